"""The unsaid slice: a Slice added before the first frame that handles a food the sentence does not say
to cut, only where the statistics know the vocabulary and the model is sure enough, marked inferred."""

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
from seal_cli.language.slicing import SLICED, WHOLE, SliceModel, infer_slice, said_bare, slice_features, uncut
from seal_cli.language.wordusage import WordUsage, load_word_usage, shipped_word_usage

KITCHEN = ("ButterKnife", "Apple", "Mug", "Fridge", "CounterTop", "Pan", "Microwave")
MODEL = SliceModel({SLICED: 10, WHOLE: 90}, {"w:knife": {SLICED: 4.0, WHOLE: -1.0}, "f:Heat": {SLICED: 0.5}},
                   frozenset(["Apple"]))


def kitchen(model: SliceModel = MODEL) -> Vocabulary:
    return Vocabulary.of(KITCHEN, usage=WordUsage({}, frozenset(class_key(c) for c in KITCHEN), slices=model))


def frames(text: str, library: Library, vocabulary: Vocabulary) -> list[tuple[str, str | None]]:
    parse = parse_command(text, library, vocabulary)
    return [(f.frame, parse.resolve(f.elements["theme"]).cls if "theme" in f.elements else None)
            for f in parse.frames]


def test_the_model_weighs_its_prior_by_the_sentence() -> None:
    assert MODEL.probability(()) == pytest.approx(0.1)
    with_knife = MODEL.probability(slice_features(["knife", "put"], "Apple", ["Place"]))
    assert with_knife == pytest.approx(1 / (1 + 9 * math.exp(-5)))
    assert slice_features(["put", "knife", "put"], "Apple", ["Place", "Heat"]) == (
        "w:knife", "w:put", "o:apple", "f:Heat", "f:Place")
    assert not SliceModel() and not SliceModel({SLICED: 3, WHOLE: 5}) and not SliceModel({SLICED: 3}, {}, {"Apple"})


def test_a_food_said_bare_is_a_feature_of_its_own(library: Library) -> None:
    def thing(text: str) -> bool:
        parse = parse_command(text, library, kitchen(SliceModel()))
        return said_bare(parse.resolve(parse.frames[-1].elements["theme"]))

    assert thing("put cooked apple in the fridge") and thing("put cold apple on the counter")
    assert not thing("put a cooked apple in the fridge") and not thing("put the apple in the fridge")
    assert not thing("put apples in the fridge") and not thing("put two apples in the fridge")
    assert not thing("pick up the apple and put it in the fridge")       # "it" is the apple said with "the"
    assert slice_features(["put"], "Apple", ["Place"], bare=True) == ("w:put", "o:apple", "f:Place", "d:bare")
    bare = SliceModel({SLICED: 10, WHOLE: 90}, {"d:bare": {SLICED: 4.0}}, frozenset(["Apple"]))
    assert frames("put cooked apple in the fridge", library, kitchen(bare))[0] == ("Slice", "Apple")
    assert frames("put a cooked apple in the fridge", library, kitchen(bare))[0] == ("Heat", "Apple")


def test_a_slice_is_added_before_the_first_frame_that_handles_the_thing_and_marked(library: Library) -> None:
    assert frames("put an apple in the fridge and put the knife down", library, kitchen()) == [
        ("Slice", "Apple"), ("Place", "Apple"), ("Place", "ButterKnife")]
    assert frames("put the knife down and put an apple in the fridge", library, kitchen()) == [
        ("Place", "ButterKnife"), ("Place", "Apple")]       # the thing handled first is the knife
    parse = parse_command("put an apple in the fridge with the knife", library, kitchen())
    cut = parse.to_json()["frames"][0]
    assert cut["frame"] == "Slice" and cut["inferred"] is True and cut["probability"] > 0.7
    assert cut["elements"]["instrument"]["default"] is True


def test_pronouns_still_find_their_frames_after_the_slice(library: Library) -> None:
    parse = parse_command("pick up an apple and the knife, then heat it in the microwave", library, kitchen())
    assert [f.frame for f in parse.frames] == ["Slice", "Pick", "Heat"]
    assert parse.resolve(parse.frames[2].elements["theme"]).cls == "Apple"


def test_no_slice_when_unsure_said_not_a_class_sliced_or_off(library: Library) -> None:
    assert frames("put an apple in the fridge", library, kitchen()) == [("Place", "Apple")]    # 0.1
    assert [f for f, _ in frames("slice an apple and put it in the fridge", library, kitchen())] == ["Slice", "Place"]
    assert frames("put a mug in the fridge with the knife", library, kitchen())[0][0] == "Place"
    off = parse_command("put an apple in the fridge with the knife", library, kitchen(), infer_steps=False)
    assert [f.frame for f in off.frames] == ["Place"] and uncut(off, {"apple"}) == 0
    assert infer_slice(off, library, kitchen(), SliceModel(), ["knife"]) is off


def test_a_vocabulary_the_statistics_do_not_know_gets_no_slice(library: Library) -> None:
    arena = Vocabulary.of([*KITCHEN, "person"], usage=kitchen().usage)
    assert not arena.slice_model
    assert frames("put an apple in the fridge with the knife", library, arena)[0][0] == "Place"


@pytest.mark.parametrize(("section", "value"), [
    ("slice_prior", {"cut": 3}), ("slice_prior", {SLICED: 0}), ("slice_weights", {"w:knife": {"cut": 1.0}}),
    ("slice_weights", {"w:knife": {SLICED: "big"}}), ("slice_classes", ["Banana"]), ("slice_classes", "Apple")])
def test_bad_slice_sections_are_clear_errors(tmp_path: Path, section: str, value: object) -> None:
    path = tmp_path / "bad.json"
    path.write_text(json.dumps({"format": "seal-word-classes/1", "classes": ["Apple"], "words": {}, section: value}))
    with pytest.raises(SealError, match=f'"{section}" must') as err:
        load_word_usage([path])
    assert err.value.file == str(path)


def test_a_table_s_slice_model_is_read_and_merged(tmp_path: Path) -> None:
    path = tmp_path / "t.json"
    path.write_text(json.dumps({"format": "seal-word-classes/1", "classes": ["Apple"], "words": {},
                                "slice_prior": {SLICED: 2, WHOLE: 6}, "slice_weights": {"w:knife": {SLICED: 1.5}},
                                "slice_classes": ["Apple"]}))
    usage = load_word_usage([path])
    assert usage.slices.classes == {"apple"} and usage.slices.probability(()) == pytest.approx(0.25)
    assert usage.merged(usage).slices.prior == {SLICED: 4, WHOLE: 12}


def test_seal_run_says_it_slices_first(library: Library) -> None:
    from seal_cli.pipeline import inferred_steps

    parse = parse_command("put an apple in the fridge with the knife", library, kitchen())
    assert inferred_steps(parse)[0].startswith("(inferred: slice it first, 0.")


def test_the_shipped_table_slices_a_food_moved_with_a_knife_only_for_alfred(library: Library) -> None:
    shipped = shipped_word_usage()
    assert shipped.slices and {"apple", "bread", "lettuce", "potato", "tomato"} <= shipped.slices.classes
    alfred = Vocabulary.of(["ButterKnife", "Apple", "Potato", "Fridge", "Sink", "Microwave"])
    assert frames("put a knife and a cooked apple in the fridge", library, alfred)[:2] == [
        ("Slice", "Apple"), ("Heat", "Apple")]
    assert frames("put the chilled slice potato in the sink", library, alfred)[0] == ("Slice", "Potato")
    assert frames("put an apple in the fridge", library, alfred) == [("Place", "Apple")]
    gpsr = Vocabulary.of(["knife", "apple", "fridge", "microwave", "person"])
    assert frames("put a knife and a cooked apple in the fridge", library, gpsr)[0][0] != "Slice"
