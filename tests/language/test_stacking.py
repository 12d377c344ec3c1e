"""The unsaid stack: a coordination of two things put in one place read as one carried in the other
only where the statistics know the vocabulary and the container's rate is high enough, marked inferred."""

from __future__ import annotations

import json
from pathlib import Path

import pytest

from seal_cli.errors import SealError
from seal_cli.frames.library import Library
from seal_cli.frames.taxonomy import class_key
from seal_cli.language.grounding import Vocabulary
from seal_cli.language.parser import parse_command
from seal_cli.language.stacking import StackModel, coordinated, infer_stack
from seal_cli.language.wordusage import WordUsage, load_word_usage, shipped_word_usage

KITCHEN = ("ButterKnife", "Cup", "Pan", "Fork", "SinkBasin", "CounterTop", "Apple", "Fridge")
MODEL = StackModel({"Cup": 20, "Pan": 10, "ButterKnife": 30, "Fork": 8, "Apple": 3},
                   {"Cup": 15, "Pan": 4, "ButterKnife": 1, "Apple": 3})


def kitchen(model: StackModel = MODEL) -> Vocabulary:
    return Vocabulary.of(KITCHEN, usage=WordUsage({}, frozenset(class_key(c) for c in KITCHEN), stacks=model))


def frames(text: str, library: Library, vocabulary: Vocabulary) -> list[tuple[str, str | None, str | None]]:
    parse = parse_command(text, library, vocabulary)
    return [(f.frame, parse.resolve(f.elements["theme"]).cls if "theme" in f.elements else None,
             parse.resolve(f.elements["goal"]).cls if "goal" in f.elements else None) for f in parse.frames]


def test_the_container_is_the_conjunct_that_most_often_held_the_other() -> None:
    assert MODEL.rate("cup") == 0.75 and MODEL.rate("Fork") == 0.0
    assert MODEL.container("ButterKnife", "Cup") == (1, 0.75)
    assert MODEL.container("Cup", "ButterKnife") == (0, 0.75)
    assert MODEL.container("ButterKnife", "Pan") is None          # 0.4: below the threshold
    assert MODEL.rate("Apple") == 0.0                               # three coordinations: too few
    assert not StackModel() and not StackModel({"Cup": 4})


def test_a_coordination_with_a_container_is_read_as_a_stack_and_marked(library: Library) -> None:
    assert frames("move a knife and a cup to the sink", library, kitchen()) == [
        ("Place", "ButterKnife", "Cup"), ("Place", "Cup", "SinkBasin")]
    assert frames("put the cup and the knife on the counter", library, kitchen()) == [
        ("Place", "ButterKnife", "Cup"), ("Place", "Cup", "CounterTop")]
    parse = parse_command("move a knife and a cup to the sink", library, kitchen())
    inner, outer = parse.to_json()["frames"]
    assert inner["inferred"] is True and inner["probability"] == 0.75 and "inferred" not in outer
    assert inner["span"] == outer["span"]


def test_a_pronoun_for_the_coordination_is_read_through(library: Library) -> None:
    assert frames("find a cup and a knife and place them in the sink", library, kitchen()) == [
        ("Find", "Cup", None), ("Place", "ButterKnife", "Cup"), ("Place", "Cup", "SinkBasin")]
    later = parse_command("put a knife and a cup in the sink and then pick it up", library, kitchen())
    assert [f.frame for f in later.frames] == ["Place", "Place", "Pick"]
    assert later.frames[2].elements["theme"].refers_to == (1, "theme")


def test_no_stack_when_unsure_the_same_class_twice_a_step_said_or_off(library: Library) -> None:
    assert frames("move a knife and a pan to the sink", library, kitchen())[0][0] == "Place"
    assert len(frames("move a knife and a pan to the sink", library, kitchen())) == 1
    assert len(frames("move a cup and another cup to the sink", library, kitchen())) == 1
    assert len(frames("move a knife and a fork to the sink", library, kitchen())) == 1
    assert [f.frame for f in parse_command("rinse a knife and a cup and put them in the sink", library,
                                           kitchen()).frames] == ["Clean", "Place"]
    off = parse_command("move a knife and a cup to the sink", library, kitchen(), infer_steps=False)
    assert len(off.frames) == 1 and coordinated(off) is not None
    assert infer_stack(off, StackModel()) is off


def test_a_vocabulary_the_statistics_do_not_know_gets_no_stack(library: Library) -> None:
    arena = Vocabulary.of([*KITCHEN, "person"], usage=kitchen().usage)
    assert not arena.stack_model
    assert len(frames("move a knife and a cup to the sink", library, arena)) == 1


def test_the_shipped_table_reads_a_knife_and_a_pan_as_a_stack(library: Library) -> None:
    shipped = shipped_word_usage()
    assert shipped.stacks and shipped.stacks.rate("Pan") >= 0.5 > shipped.stacks.rate("ButterKnife")
    alfred = Vocabulary.of(["ButterKnife", "Pan", "SinkBasin", "CounterTop"])
    assert frames("move a knife and a pan to the sink", library, alfred) == [
        ("Place", "ButterKnife", "Pan"), ("Place", "Pan", "SinkBasin")]
    gpsr = Vocabulary.of(["knife", "pan", "sink", "person"])
    assert len(frames("move a knife and a pan to the sink", library, gpsr)) == 1


@pytest.mark.parametrize("stacks", [{"Mug": {"said": 2, "holds": 3}}, {"Bowl": {"said": 2}},
                                    {"Mug": {"said": 0}}, {"Mug": {"said": 2, "held": 1}}, ["Mug"]])
def test_bad_stack_sections_are_clear_errors(tmp_path: Path, stacks: object) -> None:
    path = tmp_path / "bad.json"
    path.write_text(json.dumps({"format": "seal-word-classes/1", "classes": ["Mug"], "words": {},
                                "stacks": stacks}))
    with pytest.raises(SealError, match='"stacks" must map') as err:
        load_word_usage([path])
    assert err.value.file == str(path)


def test_a_table_s_stack_model_is_read_and_merged(tmp_path: Path) -> None:
    path = tmp_path / "t.json"
    path.write_text(json.dumps({"format": "seal-word-classes/1", "classes": ["Mug"], "words": {},
                                "stacks": {"Mug": {"said": 6, "holds": 4}}}))
    usage = load_word_usage([path])
    assert usage.stacks.rate("Mug") == pytest.approx(4 / 6)
    assert usage.merged(usage).stacks.rate("Mug") == pytest.approx(8 / 12)


def test_seal_run_says_what_it_put_where(library: Library) -> None:
    from seal_cli.pipeline import inferred_steps

    parse = parse_command("move a knife and a cup to the sink", library, kitchen())
    assert inferred_steps(parse) == ["(inferred: move a knife in a cup, 0.75)"]
