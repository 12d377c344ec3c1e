"""The unsaid goal: a Place added after a sentence that handles a thing and puts it nowhere, only where the
statistics know the vocabulary and the model is sure enough among the classes present, marked inferred."""

from __future__ import annotations

import json
import math
from pathlib import Path

import pytest

from seal_cli.errors import SealError
from seal_cli.frames.library import Library
from seal_cli.frames.taxonomy import class_key
from seal_cli.language.goals import NOWHERE, GoalModel, goal_features, goalless, infer_goal, said_beside
from seal_cli.language.grounding import Vocabulary
from seal_cli.language.parser import parse_command
from seal_cli.language.wordusage import WordUsage, load_word_usage, shipped_word_usage

KITCHEN = ("Kettle", "Mug", "StoveBurner", "CoffeeMachine", "CounterTop", "Fridge", "Sink", "DeskLamp", "Knife",
           "Laptop")
MODEL = GoalModel({"StoveBurner": 10, "CounterTop": 30, "CoffeeMachine": 10, NOWHERE: 50},
                  {"w:stove": {"stove_burner": 5.0}, "o:mug": {"coffee_machine": 4.0}},
                  holders=frozenset({"StoveBurner", "CounterTop", "CoffeeMachine", "Fridge", "Sink", "Mug"}))


def kitchen(model: GoalModel = MODEL, classes: tuple[str, ...] = KITCHEN) -> Vocabulary:
    return Vocabulary.of(classes, usage=WordUsage({}, frozenset(class_key(c) for c in KITCHEN), goals=model))


def frames(text: str, library: Library, vocabulary: Vocabulary) -> list[tuple[str, str | None, str | None]]:
    parse = parse_command(text, library, vocabulary)
    return [(f.frame, parse.resolve(f.elements["theme"]).cls if "theme" in f.elements else None,
             parse.resolve(f.elements["goal"]).cls if "goal" in f.elements else None) for f in parse.frames]


def test_the_model_weighs_its_prior_by_the_sentence_among_the_classes_present() -> None:
    assert MODEL.probabilities((), {"stove_burner", "counter_top", "coffee_machine"})[NOWHERE] == pytest.approx(0.5)
    p = MODEL.probabilities(goal_features(["wash", "stove"], "Kettle", ["Clean"]), {"stove_burner", "counter_top"})
    assert set(p) == {"stove_burner", "counter_top", NOWHERE}        # no coffee machine in this room
    assert p["stove_burner"] == pytest.approx(10 * math.exp(5) / (10 * math.exp(5) + 30 + 50))
    assert goal_features(["wash", "stove", "wash"], "Kettle", ["Clean", "Pick"]) == (
        "w:stove", "w:wash", "o:kettle", "f:Clean", "f:Pick")
    assert not GoalModel() and not GoalModel({NOWHERE: 4})


def test_a_place_is_added_after_the_last_frame_and_marked(library: Library) -> None:
    assert frames("wash the kettle on the stove", library, kitchen()) == [
        ("Clean", "Kettle", None), ("Place", "Kettle", "StoveBurner")]
    parse = parse_command("heat a mug and put it back", library, kitchen())
    assert [f.frame for f in parse.frames] == ["Heat", "Place", "Place"]     # "put it back" stays as said
    put = parse.to_json()["frames"][-1]
    assert put["inferred"] is True and 0.5 <= put["probability"] < 1.0
    assert put["elements"]["goal"] == {"text": None, "head": "coffee machine", "class": "CoffeeMachine",
                                       "default": True}
    assert parse.resolve(parse.frames[-1].elements["theme"]).cls == "Mug"


def test_no_goal_when_said_unsure_looking_or_off(library: Library) -> None:
    assert frames("wash the kettle", library, kitchen()) == [("Clean", "Kettle", None)]        # none: 0.5 of 1
    assert frames("wash the kettle and put it in the fridge", library, kitchen())[-1] == ("Place", "Kettle", "Fridge")
    assert len(frames("pick up the mug and turn on the lamp", library, kitchen())) == 2
    assert len(frames("take the mug to the counter", library, kitchen())) == 1                  # Bring says where
    off = parse_command("wash the kettle on the stove", library, kitchen(), infer_steps=False)
    assert [f.frame for f in off.frames] == ["Clean"] and goalless(off) == 0
    assert infer_goal(off, library, kitchen().by_key, GoalModel(), ["stove"]) is off
    no_stove = tuple(c for c in KITCHEN if c != "StoveBurner")
    assert len(frames("wash the kettle on the stove", library, kitchen(classes=no_stove))) == 1


def test_a_vocabulary_the_statistics_do_not_know_gets_no_goal(library: Library) -> None:
    arena = Vocabulary.of([*KITCHEN, "person"], usage=kitchen().usage)
    assert not arena.goal_model
    assert len(frames("wash the kettle on the stove", library, arena)) == 1


@pytest.mark.parametrize(("section", "value"), [
    ("goal_prior", {"Banana": 3}), ("goal_prior", {NOWHERE: 0}), ("goal_weights", {"w:stove": {"Banana": 1.0}}),
    ("goal_weights", {"w:stove": {NOWHERE: "big"}}), ("goal_weights", [])])
def test_bad_goal_sections_are_clear_errors(tmp_path: Path, section: str, value: object) -> None:
    path = tmp_path / "bad.json"
    path.write_text(json.dumps({"format": "seal-word-classes/1", "classes": ["Apple"], "words": {}, section: value}))
    with pytest.raises(SealError, match=f'"{section}" must') as err:
        load_word_usage([path])
    assert err.value.file == str(path)


def test_a_table_s_goal_model_is_read_and_merged(tmp_path: Path) -> None:
    path = tmp_path / "t.json"
    path.write_text(json.dumps({"format": "seal-word-classes/1", "classes": ["Fridge"], "words": {},
                                "goal_prior": {"Fridge": 2, NOWHERE: 6}, "goal_weights": {"w:cold": {"Fridge": 1.5}}}))
    usage = load_word_usage([path])
    assert usage.goals.probabilities((), {"fridge"})["fridge"] == pytest.approx(0.25)
    assert usage.goals.weights["w:cold"] == {"fridge": 1.5}
    assert usage.merged(usage).goals.prior == {"fridge": 4, NOWHERE: 12}


def test_seal_run_says_where_it_puts_the_thing(library: Library) -> None:
    from seal_cli.pipeline import inferred_steps

    parse = parse_command("wash the kettle on the stove", library, kitchen())
    assert inferred_steps(parse)[0].startswith("(inferred: put the kettle on the stove in the stove burner, 0.")


def test_the_shipped_table_puts_a_mug_back_under_the_coffee_machine_only_for_alfred(library: Library) -> None:
    assert shipped_word_usage().goals
    alfred = Vocabulary.of(["Mug", "CoffeeMachine", "Microwave", "Cabinet", "CounterTop", "SinkBasin", "Fridge"])
    assert frames("heat up the coffee cup", library, alfred)[-1] == ("Place", "Mug", "CoffeeMachine")
    assert len(frames("heat up the coffee cup and put it in the cabinet", library, alfred)) == 2
    gpsr = Vocabulary.of(["mug", "coffee machine", "microwave", "cabinet", "person"])
    assert len(frames("heat up the coffee cup", library, gpsr)) == 1


def test_a_goal_said_beside_a_thing_that_holds_nothing_is_unsaid(library: Library) -> None:
    # a knife holds nothing: the kettle goes on what holds the knife, which the sentence leaves unsaid; no threshold,
    # since the knife itself is sure to be wrong (the counter: 30 of the 50 placings, none left out)
    assert frames("put the kettle next to the knife", library, kitchen()) == [("Place", "Kettle", "CounterTop")]
    parse = parse_command("set the kettle in front of the laptop", library, kitchen())
    goal = parse.to_json()["frames"][-1]["elements"]["goal"]
    assert goal == {"text": None, "head": "counter top", "class": "CounterTop", "default": True}
    assert "inferred" not in parse.to_json()["frames"][-1]                  # the Place was said; its goal was not
    assert frames("put the kettle by the knife near the stove", library, kitchen())[-1][2] == "StoveBurner"


def test_a_goal_said_beside_a_thing_the_room_does_not_hold_is_unsaid(library: Library) -> None:
    # no class of this kitchen is a television: nothing known holds it, so what holds the kettle is left unsaid too
    assert frames("put the kettle in front of the television", library, kitchen()) == \
        [("Place", "Kettle", "CounterTop")]
    off = parse_command("put the kettle in front of the television", library, kitchen(), infer_steps=False)
    assert off.frames[-1].elements["goal"].cls is None and said_beside(off, MODEL.holders) == 0
    # said on it, it stays what was said (the robot cannot put it there, and says so)
    on = parse_command("put the kettle on the television", library, kitchen())
    assert on.frames[-1].elements["goal"].cls is None and not on.frames[-1].elements["goal"].default


def test_a_goal_beside_a_holder_said_on_or_in_or_in_a_house_stays(library: Library) -> None:
    assert frames("put the kettle next to the mug", library, kitchen()) == [("Place", "Kettle", "Mug")]  # holds things
    assert frames("put the kettle on the knife", library, kitchen()) == [("Place", "Kettle", "Knife")]   # said on it
    assert frames("put the kettle next to the knife on the stove", library, kitchen())[-1][2] == "StoveBurner"
    off = parse_command("put the kettle next to the knife", library, kitchen(), infer_steps=False)
    assert said_beside(off, MODEL.holders) == 0 and said_beside(off, frozenset()) is None
    assert infer_goal(off, library, kitchen().by_key, MODEL, [], house=True) is off
    unknown = GoalModel(MODEL.prior, MODEL.weights)                          # a table with no "receptacles"
    assert infer_goal(off, library, kitchen().by_key, unknown, []) is off


def test_a_table_s_receptacles_are_read_and_a_bad_list_is_an_error(tmp_path: Path) -> None:
    path = tmp_path / "t.json"
    table = {"format": "seal-word-classes/1", "classes": ["Fridge", "Knife"], "words": {}, "goal_prior": {"Fridge": 2},
             "receptacles": ["Fridge"]}
    path.write_text(json.dumps(table))
    assert load_word_usage([path]).goals.holders == {"fridge"}
    path.write_text(json.dumps({**table, "receptacles": ["Banana"]}))
    with pytest.raises(SealError, match='"receptacles" must') as err:
        load_word_usage([path])
    assert err.value.file == str(path)
