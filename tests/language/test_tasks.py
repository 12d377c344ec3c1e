"""The task a sentence describes: a LookAt added to a parse the model reads as a look task that says none, a stack's
container put where it most likely went, only where the statistics know the vocabulary and the model is sure enough,
marked inferred."""

from __future__ import annotations

import json
import math
from pathlib import Path

import pytest

from seal_cli.errors import SealError
from seal_cli.frames.library import Library
from seal_cli.frames.taxonomy import class_key
from seal_cli.language.goals import GoalModel
from seal_cli.language.grounding import Vocabulary
from seal_cli.language.parser import parse_command
from seal_cli.language.tasks import (
    ADDERS,
    LOOK,
    STACK,
    TASKS,
    TaskModel,
    infer_task,
    task_features,
    uncarried,
    unlooked,
)
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
        "f:Place", "o:mug", "or:mug|microwave", "p:1", "r:microwave", "w:in", "w:microwave", "w:mug", "w:put", "w:the")
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


STACK_ROOM = ("Tomato", "Pan", "CounterTop", "DiningTable", "Fridge", "Knife", "Mug", "Apple")
STACKING = TaskModel({STACK: 10, SIMPLE: 40}, {"r:pan": {STACK: 5.0}, "r:mug": {STACK: 5.0}},
                     carried=GoalModel({"CounterTop": 6, "DiningTable": 3, "Pan": 1},
                                       {"w:dinner": {class_key("DiningTable"): 4.0}}))


def stacking(classes: tuple[str, ...] = STACK_ROOM, model: TaskModel = STACKING) -> Vocabulary:
    return Vocabulary.of(classes, usage=WordUsage({}, frozenset(class_key(c) for c in STACK_ROOM), tasks=model))


def test_a_stack_s_container_is_put_where_it_most_likely_went(library: Library) -> None:
    parse = parse_command("place a slice of tomato in a pan", library, stacking())
    places = [f for f in parse.frames if f.frame == "Place"]
    assert len(places) == 2
    inner, outer = places
    assert parse.resolve(inner.elements["theme"]).cls == "Tomato"
    assert outer.elements["theme"].refers_to == (parse.frames.index(inner), "goal")     # the same pan, carried
    assert parse.resolve(outer.elements["theme"]).cls == "Pan"
    assert (outer.elements["goal"].cls, outer.elements["goal"].default) == ("CounterTop", True)
    assert outer.inferred is not None and outer.inferred >= 0.7 and inner.inferred is None
    supper = parse_command("put the apple in the pan for dinner", library, stacking())
    assert supper.frames[-1].elements["goal"].cls == "DiningTable"              # the sentence's words weigh
    bare = parse_command("put the apple in the pan", library, stacking(tuple(c for c in STACK_ROOM
                                                                              if c != "CounterTop")))
    assert bare.frames[-1].elements["goal"].cls == "DiningTable"          # only what the room holds; never the pan


def test_a_house_s_container_stays_where_the_command_puts_it(library: Library) -> None:
    """On a map's vocabulary a command is what its speaker said, not one of ALFRED's tasks: no placing is added."""
    from dataclasses import replace

    house = replace(stacking(), house=True)
    parse = parse_command("place a slice of tomato in a pan", library, house)
    assert [f.frame for f in parse.frames if f.frame == "Place"] == ["Place"]
    assert house.in_context("a pan").house and house.restricted_to(["Pan"]).house


def test_no_container_is_carried_when_said_unsure_or_no_container(library: Library) -> None:
    said = parse_command("put the apple in the pan and put the pan on the table", library, stacking())
    assert [f.inferred for f in said.frames if f.frame == "Place"] == [None, None]     # both Places said
    fridge = parse_command("put the apple in the fridge", library, stacking(
        model=TaskModel(STACKING.prior, {"f:Place": {STACK: 9.0}}, carried=STACKING.carried)))
    assert uncarried(fridge, library) is None and len(fridge.frames) == 1         # a fridge carries nothing
    unsure = parse_command("put the apple in the pan", library, stacking(
        model=TaskModel(STACKING.prior, {}, carried=STACKING.carried)))            # 0.2 < 0.7
    assert [f.frame for f in unsure.frames] == ["Place"]
    nowhere = parse_command("put the apple in the pan", library, stacking(
        model=TaskModel(STACKING.prior, STACKING.weights)))                        # no places learned
    assert [f.frame for f in nowhere.frames] == ["Place"]
    two = parse_command("put the apple and the knife in the pan", library, stacking(), infer_steps=False)
    assert uncarried(two, library) is None                                     # a coordination: the stack model's
    gpsr = Vocabulary.of([*STACK_ROOM, "person"], usage=stacking().usage)
    assert [f.frame for f in parse_command("put the apple in the pan", library, gpsr).frames] == ["Place"]


def test_a_table_s_stack_goals_are_read_checked_and_merged(tmp_path: Path) -> None:
    path = tmp_path / "t.json"
    path.write_text(json.dumps({"format": "seal-word-classes/1", "classes": ["Apple", "Pan", "CounterTop"],
                                "words": {}, "task_prior": {STACK: 2}, "stack_goal_prior": {"CounterTop": 3},
                                "stack_goal_weights": {"w:stove": {"CounterTop": 0.5}}}))
    usage = load_word_usage([path])
    top = class_key("CounterTop")
    assert usage.tasks.carried.prior == {top: 3}
    assert usage.tasks.carried.weights["w:stove"] == {top: 0.5}
    assert usage.merged(usage).tasks.carried.prior == {top: 6}
    path.write_text(json.dumps({"format": "seal-word-classes/1", "classes": ["Apple"], "words": {},
                                "stack_goal_prior": {"Sofa": 3}}))
    with pytest.raises(SealError, match='"stack_goal_prior" must') as err:
        load_word_usage([path])
    assert err.value.file == str(path)


def test_the_shipped_table_carries_a_pan_only_for_alfred(library: Library) -> None:
    assert shipped_word_usage().tasks.carried
    alfred = Vocabulary.of(["Tomato", "Pan", "CounterTop", "DiningTable", "Fridge", "Knife"])
    parse = parse_command("Place a slice of tomato in a pan.", library, alfred)
    assert [f.frame for f in parse.frames][-2:] == ["Place", "Place"] and parse.frames[-1].inferred is not None
    gpsr = Vocabulary.of(["tomato", "pan", "counter", "person"])
    assert [f.frame for f in parse_command("Place a slice of tomato in a pan.", library, gpsr).frames].count(
        "Place") == 1
