"""The task a sentence describes: a LookAt added to a parse the model reads as a look task that says none, only
where the statistics know the vocabulary and the model is sure enough, marked inferred."""

from __future__ import annotations

import json
import math
from pathlib import Path

import pytest

from seal_cli.errors import SealError
from seal_cli.frames.library import Library
from seal_cli.frames.taxonomy import class_key
from seal_cli.language.grounding import Vocabulary
from seal_cli.language.parser import parse_command
from seal_cli.language.tasks import ADDERS, LOOK, TASKS, TaskModel, infer_task, task_features, unlooked
from seal_cli.language.wordusage import WordUsage, context_words, load_word_usage, shipped_word_usage

ROOM = ("CreditCard", "FloorLamp", "DeskLamp", "Desk", "Sofa", "Mug", "Microwave", "AlarmClock")
SIMPLE = "pick_and_place_simple"
MODEL = TaskModel({LOOK: 10, SIMPLE: 40}, {"w:off": {LOOK: 6.0}, "w:lit": {LOOK: 5.0}, "f:Place": {SIMPLE: 2.0}})


def room(model: TaskModel = MODEL, classes: tuple[str, ...] = ROOM) -> Vocabulary:
    return Vocabulary.of(classes, usage=WordUsage({}, frozenset(class_key(c) for c in ROOM), tasks=model))


def frames(text: str, library: Library, vocabulary: Vocabulary) -> list[tuple[str, str | None]]:
    parse = parse_command(text, library, vocabulary)
    return [(f.frame, parse.resolve(f.elements["theme"]).cls if "theme" in f.elements else None)
            for f in parse.frames]


def test_the_model_weighs_its_prior_by_the_sentence(library: Library) -> None:
    assert MODEL.probabilities(())[LOOK] == pytest.approx(0.2)
    assert MODEL.probabilities(("w:off",))[LOOK] == pytest.approx(10 * math.exp(6) / (10 * math.exp(6) + 40))
    assert set(MODEL.probabilities(())) == {LOOK, SIMPLE}
    parse = parse_command("put the mug in the microwave", library, room(), infer_steps=False)
    assert task_features(context_words(parse.text), parse) == (
        "f:Place", "o:mug", "p:1", "r:microwave", "w:in", "w:microwave", "w:mug", "w:put", "w:the")
    assert not TaskModel() and not TaskModel({SIMPLE: 4})       # no kind with an adder: nothing to add
    assert set(ADDERS) <= set(TASKS)


def test_a_look_is_added_after_the_last_frame_and_marked(library: Library) -> None:
    assert frames("turn off the floor lamp while holding a credit card", library, room())[-1] == (
        "LookAt", "CreditCard")
    parse = parse_command("pick up the credit card and turn off the floor lamp", library, room())
    assert [f.frame for f in parse.frames] == ["Pick", "ToggleOff", "LookAt"]     # what was said stays
    look = parse.to_json()["frames"][-1]
    assert look["inferred"] is True and 0.7 <= look["probability"] < 1.0
    assert parse.resolve(parse.frames[-1].elements["instrument"]).cls == "FloorLamp"     # the light it names
    lit = parse_command("take a clock from a desk with a lit lamp", library, room())
    assert [f.frame for f in lit.frames] == ["Pick", "LookAt"]
    assert lit.resolve(lit.frames[-1].elements["theme"]).cls == "AlarmClock"
    assert lit.resolve(lit.frames[-1].elements["instrument"]).cls == "FloorLamp"    # the lamp listed first
    held = parse_command("take the credit card from a lit desk", library, room(classes=ROOM[:2]))
    light = held.frames[-1].elements["instrument"]
    assert (light.cls, light.default) == ("FloorLamp", True)        # none said: the room's lamp, a default


def test_no_look_when_said_unsure_or_off(library: Library) -> None:
    assert frames("pick up the credit card", library, room()) == [("Pick", "CreditCard")]       # 0.2 < 0.7
    assert [f for f, _ in frames("pick up the credit card and turn on the lamp", library, room())] == [
        "Pick", "ToggleOn"]                                       # a lamp switched on: the look is said
    assert [f for f, _ in frames("look at the credit card and turn off the lamp", library, room())] == [
        "LookAt", "ToggleOff"]
    off = parse_command("turn off the lamp while holding a credit card", library, room(), infer_steps=False)
    assert "LookAt" not in [f.frame for f in off.frames]
    assert infer_task(off, library, room(), TaskModel(), ["off"]) is off
    two = parse_command("pick up the credit card and the mug and turn off the lamp", library, room(),
                        infer_steps=False)
    assert unlooked(two, library) is None                         # two things handled: which one?


def test_a_vocabulary_the_statistics_do_not_know_gets_no_task(library: Library) -> None:
    arena = Vocabulary.of([*ROOM, "person"], usage=room().usage)
    assert not arena.task_model
    assert "LookAt" not in [f for f, _ in frames("turn off the lamp while holding a credit card", library, arena)]


@pytest.mark.parametrize(("section", "value"), [
    ("task_prior", {"juggle": 3}), ("task_prior", {LOOK: 0}), ("task_weights", {"w:off": {"juggle": 1.0}}),
    ("task_weights", {"w:off": {LOOK: "big"}}), ("task_weights", [])])
def test_bad_task_sections_are_clear_errors(tmp_path: Path, section: str, value: object) -> None:
    path = tmp_path / "bad.json"
    path.write_text(json.dumps({"format": "seal-word-classes/1", "classes": ["Apple"], "words": {}, section: value}))
    with pytest.raises(SealError, match=f'"{section}" must') as err:
        load_word_usage([path])
    assert err.value.file == str(path)


def test_a_table_s_task_model_is_read_and_merged(tmp_path: Path) -> None:
    path = tmp_path / "t.json"
    path.write_text(json.dumps({"format": "seal-word-classes/1", "classes": ["Apple"], "words": {},
                                "task_prior": {LOOK: 2, SIMPLE: 6}, "task_weights": {"w:lit": {LOOK: 1.5}}}))
    usage = load_word_usage([path])
    assert usage.tasks.probabilities(())[LOOK] == pytest.approx(0.25)
    assert usage.tasks.weights["w:lit"] == {LOOK: 1.5}
    assert usage.merged(usage).tasks.prior == {LOOK: 4, SIMPLE: 12}


def test_seal_run_says_what_it_looks_at(library: Library) -> None:
    from seal_cli.pipeline import inferred_steps

    parse = parse_command("turn off the floor lamp while holding a credit card", library, room())
    assert inferred_steps(parse)[-1].startswith("(inferred: look at a credit card, 0.")


def test_the_shipped_table_reads_a_lamp_turned_off_as_a_look_only_for_alfred(library: Library) -> None:
    assert shipped_word_usage().tasks
    alfred = Vocabulary.of(["CreditCard", "FloorLamp", "Sofa", "CoffeeTable"])
    assert frames("Turn off the floor lamp while holding a credit card.", library, alfred)[-1] == (
        "LookAt", "CreditCard")
    assert "LookAt" not in [f for f, _ in frames("Put the credit card on the sofa.", library, alfred)]
    gpsr = Vocabulary.of(["credit card", "floor lamp", "sofa", "person"])
    assert "LookAt" not in [f for f, _ in frames("Turn off the floor lamp while holding a credit card.", library,
                                                  gpsr)]
