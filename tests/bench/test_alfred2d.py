"""ALFRED-2D: loading real trials, building their worlds and maps, priors from train, gold frames, judging."""

from __future__ import annotations

import json
import os
from pathlib import Path
from typing import Any

import pytest

from seal_cli.bench.alfred2d import (
    FOUR,
    TASK_TYPES,
    Task,
    build_scene,
    estimate_priors,
    goal_conditions,
    gold_classes,
    gold_commands,
    judge,
    load_suite,
    open_floor,
    read_floorplans,
    read_trials,
    scene_priors,
    scene_vocabulary,
    suite_vocabulary,
    thor_yaw,
)
from seal_cli.errors import SealError
from seal_cli.frames.library import Library
from seal_cli.frames.taxonomy import class_key
from seal_cli.sim.world import HAND


@pytest.fixture(scope="module")
def suite(shared_data: Path):  # type: ignore[no-untyped-def]
    return load_suite(shared_data / "alfred2d", "valid_seen", limit=2)


def test_suite_has_every_task_type_and_the_papers_four_first(suite) -> None:  # type: ignore[no-untyped-def]
    groups = [e.group for e in suite.episodes]
    assert set(groups) == set(TASK_TYPES) and all(groups.count(t) == 2 for t in TASK_TYPES)
    assert FOUR == ("look_at_obj_in_light", "pick_and_place_simple", "pick_and_place_with_movable_recep",
                    "pick_heat_then_place_in_recep")


def test_priors_come_from_train_and_put_apples_in_fridges(suite) -> None:  # type: ignore[no-untyped-def]
    apple = suite.priors["apple"]
    assert sum(apple.values()) == pytest.approx(1.0)
    assert max(apple, key=lambda k: apple[k]) == "fridge"
    kitchen = next(e for e in suite.episodes if e.scene_type == "kitchen")
    plan = suite.floor_plans[kitchen.floor_plan]
    local = scene_priors(suite.priors, plan, ["apple", "never_seen_thing"])
    assert set(local["apple"]) == {class_key(r.cls) for r in plan.receptacles if r.receptacle}
    for masses in local.values():
        assert sum(masses.values()) == pytest.approx(1.0) and min(masses.values()) > 0


def test_the_open_floor_share_is_the_none_share_against_the_rooms_receptacle_classes(suite) -> None:  # type: ignore[no-untyped-def]
    plan = suite.floor_plans[suite.episodes[0].floor_plan]
    present = {class_key(r.cls) for r in plan.receptacles if r.receptacle}
    priors = {"bat": {"_none": 0.6, sorted(present)[0]: 0.4}, "apple": {sorted(present)[0]: 1.0}}
    got = open_floor(priors, plan, ["bat", "apple"])
    assert set(got) == {"bat"}   # never on the floor: left out
    assert got["bat"] == pytest.approx(0.6 / (0.6 + 0.4 + 0.02 * (len(present) - 1)))


def test_estimate_priors_counts_parents(suite) -> None:  # type: ignore[no-untyped-def]
    priors = estimate_priors(suite.episodes[:3], suite.floor_plans)
    for masses in priors.values():
        assert sum(masses.values()) == pytest.approx(1.0)


def test_scene_world_and_map_agree(suite, library: Library) -> None:  # type: ignore[no-untyped-def]
    episode = suite.episodes[0]
    plan = suite.floor_plans[episode.floor_plan]
    scene = build_scene(episode, plan, library, suite.priors)
    world, m = scene.world, scene.map
    assert {p.name for p in m.places} == {i.id for i in world.items.values() if not i.movable}
    assert len(m.objects) == len(episode.objects)
    assert all(i.openable is False or "open" not in i.states for i in world.items.values())  # all shut
    start = scene.grid.cell(episode.start)
    assert scene.grid.is_free(start)
    assert world.robot.holding is None and world.robot.pose == episode.start
    assert m.is_free([episode.start[:2]])[0]


def test_thor_rotation_convention() -> None:
    import math

    assert thor_yaw(0) == pytest.approx(math.pi / 2)  # faces +z
    assert thor_yaw(90) == pytest.approx(0.0)  # faces +x


def test_gold_frames_per_task_type(library: Library) -> None:
    heat = gold_commands(Task("pick_heat_then_place_in_recep", "Egg", "Fridge"), library)
    assert [str(b) for b in heat] == ["Heat(theme=egg, instrument=microwave)", "Place(theme=egg, goal=fridge)"]
    sliced = gold_commands(Task("pick_cool_then_place_in_recep", "Apple", "CounterTop", sliced=True), library,
                           ["butter_knife", "apple"])
    assert str(sliced[0]) == "Slice(theme=apple, instrument=butter_knife)"
    stack = gold_commands(Task("pick_and_place_with_movable_recep", "Apple", "CounterTop", mrecep="Pan"), library)
    assert [str(b) for b in stack] == ["Place(theme=apple, goal=pan)", "Place(theme=pan, goal=counter_top)"]
    two = Task("pick_two_obj_and_place", "Book", "Desk")
    assert [b.elements["theme"] for b in gold_commands(two, library)] == ["book", "book_2"]
    assert gold_classes(two) == {"book_2": "book"}
    look = gold_commands(Task("look_at_obj_in_light", "AlarmClock", toggle="DeskLamp"), library)
    assert str(look[0]) == "LookAt(theme=alarm_clock, instrument=desk_lamp)"
    with pytest.raises(SealError, match="no receptacle"):
        gold_commands(Task("pick_and_place_simple", "Book"), library)


def test_goal_conditions_are_ordered() -> None:
    assert goal_conditions(Task("pick_heat_then_place_in_recep", "Apple", "CounterTop", sliced=True)) == [
        ("sliced", ("apple",)), ("hot", ("apple",)), ("in", ("apple", "counter_top"))]
    with pytest.raises(SealError, match="unknown task type"):
        goal_conditions(Task("juggle", "Apple", "CounterTop"))


def test_judge_needs_every_condition_in_order(suite, library: Library) -> None:  # type: ignore[no-untyped-def]
    task = Task("pick_heat_then_place_in_recep", "Apple", "CounterTop")
    episode = next(e for e in suite.episodes if e.scene_type == "kitchen")
    scene = build_scene(episode, suite.floor_plans[episode.floor_plan], library, suite.priors)
    world = scene.world
    apple = world.of_class("apple")[0]
    counter = world.of_class("counter_top")[0]
    assert not judge(task, world).success
    # placed first, heated after (teleporting for the test): the order is wrong
    world._move(apple, counter.id, counter.at)
    world.step += 1
    world._set(apple, "hot")
    world.step += 1
    verdict = judge(task, world)
    assert not verdict.success and "out of order" in verdict.reason
    # take it again, and put it back after it is hot: now right
    world._move(apple, HAND)
    world.step += 1
    world._move(apple, counter.id, counter.at)
    assert judge(task, world).success


def _one_plan(data: Path, **changes: object) -> dict[str, object]:
    """The shared data's first floor plan alone, with ``changes``; and one of its trials."""
    plans = json.loads((data / "alfred2d" / "floorplans.json").read_text())
    name = next(iter(plans["floor_plans"]))
    plan = {**plans["floor_plans"][name], **changes}
    return {"movable_classes": plans["movable_classes"], "floor_plans": {name: plan}}


def _a_trial(data: Path, name: str) -> dict[str, Any]:
    for line in (data / "alfred2d" / "trials_train.jsonl").open():
        if f'"{name}"' in line:
            return dict(json.loads(line))
    raise AssertionError(f"no trial of {name}")


@pytest.mark.parametrize(("plan", "trial", "message"), [
    ({"floor_plans": [1, 2]}, None, r"floorplans\.json: floor_plans must be an object \(\{\.\.\.\}\), not a list of 2"),
    ({"receptacles": [[1, 2]]}, None, r"floorplans\.json: floor_plans\.\w+\.receptacles\[0\] must be an object"),
    ({"bounds": [float("nan"), 0, 1, 1]}, None, r"\.bounds\[0\] must be a finite number, not the number nan"),
    ({"reachable": [[0, "a"]]}, None, r"\.reachable\[0\]\[1\] must be a number, not a string \('a'\)"),
    ({}, {"expert": {"high_pddl": [5]}}, r"valid_seen\.jsonl:1: trial\.expert\.high_pddl\[0\] must be an"),
    ({}, {"task": {"type": "look_at_obj_in_light", "object": None}}, r":1: trial\.task\.object must be a string, not "
                                                                     "null"),
    ({}, {"agent_start": [0, 0]}, r":1: trial\.agent_start must be a list of 3 finite numbers, not a list of 2"),
    ({}, {"goals": "abc"}, r":1: trial\.goals must be a list, not a string \('abc'\)"),
    ({}, {"objects": [{"id": "a", "class": "Mug", "position": [0, 0, 0], "parent_guess": -1}]},
     r":1: trial\.objects\[0\]\.parent_guess must be the index of one of the floor plan's \d+ receptacles"),
    ({}, {"floor_plan": "Nowhere"}, r":1: trial\.floor_plan names no floor plan"),
    ({}, [1, 2], r":1: trial must be an object"),
])
def test_data_of_the_wrong_type_is_said_at_its_path(tmp_path: Path, shared_data: Path, plan: dict[str, Any],
                                                    trial: Any, message: str) -> None:
    """A value of the wrong type anywhere in the floor plans or a trial is one SealError naming the file (and the
    trial's line) and the value's path; it was a KeyError, AttributeError or TypeError traceback, or taken."""
    plans = plan if "floor_plans" in plan else _one_plan(shared_data, **plan)
    name = next(iter(_one_plan(shared_data)["floor_plans"]))
    (tmp_path / "floorplans.json").write_text(json.dumps(plans))
    base = _a_trial(shared_data, name)
    changed = {**base, **trial} if isinstance(trial, dict) else (trial if trial is not None else base)
    (tmp_path / "trials_valid_seen.jsonl").write_text(json.dumps(changed) + "\n")
    with pytest.raises(SealError, match=message):
        read_trials(tmp_path, "valid_seen", read_floorplans(tmp_path)[0]).__next__()


def test_bad_data_is_a_clear_error(tmp_path: Path, shared_data: Path) -> None:
    with pytest.raises(SealError, match="no ALFRED-2D data"):
        read_floorplans(tmp_path)
    (tmp_path / "floorplans.json").write_text("{not json")
    with pytest.raises(SealError, match=r"floorplans\.json:1:2: this floor plans file is not JSON"):
        read_floorplans(tmp_path)
    (tmp_path / "floorplans.json").unlink()
    os.mkfifo(tmp_path / "floorplans.json")  # a pipe nobody writes to: refused, not waited on
    with pytest.raises(SealError, match="FIFO"):
        read_floorplans(tmp_path)
    (tmp_path / "floorplans.json").unlink()
    (tmp_path / "trials_x.jsonl").write_bytes(b"\n{\"task_id\": \"caf\xe9\"}\n")
    with pytest.raises(SealError, match=r"trials_x\.jsonl:2:17: this trials file is not UTF-8"):
        list(read_trials(tmp_path, "x", {}))
    (tmp_path / "trials_x.jsonl").write_text('{"task_id": 1,}\n')
    with pytest.raises(SealError, match=r"trials_x\.jsonl:1:15: trial is not JSON"):
        list(read_trials(tmp_path, "x", {}))
    (tmp_path / "trials_x.jsonl").write_text('\n{"task_id": "t\\ud800"}\n')  # hostile28: half a character
    with pytest.raises(SealError, match=r"trials_x\.jsonl:2:15: \\ud800 is half a character"):
        list(read_trials(tmp_path, "x", {}))
    (tmp_path / "floorplans.json").write_text('{"floor_plans": {"F\\udc80": {}}}')
    with pytest.raises(SealError, match=r"floorplans\.json:1:20: \\udc80 is half a character"):
        read_floorplans(tmp_path)
    (tmp_path / "floorplans.json").write_text(json.dumps({"floor_plans": {"F": {"receptacles": [{}]}}}))
    with pytest.raises(SealError, match=r"floorplans\.json: floor_plans\.F\.receptacles\[0\] has no 'position'"):
        read_floorplans(tmp_path)
    with pytest.raises(SealError, match="no split 'test'"):
        load_suite(shared_data / "alfred2d", "test")
    with pytest.raises(SealError, match="unknown task type"):
        load_suite(shared_data / "alfred2d", "valid_seen", types=["juggling"])


def test_the_suite_vocabulary_is_a_shipped_file_with_every_class_of_the_data(shared_data: Path) -> None:
    from seal_cli.bench.alfred2d import VOCABULARY
    from seal_cli.language.grounding import load_vocabulary

    assert VOCABULARY.is_file() and VOCABULARY.parents[2].name == "seal_cli"   # inside the package: shipped
    vocab = suite_vocabulary()
    assert vocab == load_vocabulary(VOCABULARY)
    plans, movable = read_floorplans(shared_data / "alfred2d")
    classes = {r.cls for p in plans.values() for r in p.receptacles} | set(movable)
    assert classes <= set(vocab.classes)
    conventions = {"chair": "ArmChair", "table": "DiningTable", "sink": "SinkBasin", "glass": "Cup", "lamp": "DeskLamp"}
    for cls, names in zip(vocab.classes, vocab.synonyms, strict=True):   # ALFRED's conventions are the scene's
        assert not any(conventions.get(n) == cls for n in names), (cls, names)


def test_an_episode_grounds_its_sentence_in_the_classes_its_room_has(library: Library) -> None:
    from seal_cli.language.parser import parse_command

    def goal(text: str, present: list[str]) -> tuple[str | None, str | None]:
        place = parse_command(text, library, scene_vocabulary(present)).frames[-1].elements
        return place["theme"].cls, place["goal"].cls

    bedroom = ["side_table", "desk_lamp", "arm_chair", "pillow", "cell_phone", "laptop"]
    assert goal("put the phone on the table", bedroom) == ("cell_phone", "side_table")
    assert goal("put the cushion on the chair", bedroom) == ("pillow", "arm_chair")
    assert goal("put the computer on the table", bedroom) == ("laptop", "side_table")   # the suite's own names
    bathroom = ["sink_basin", "bathtub_basin", "hand_towel", "hand_towel_holder", "toilet"]
    assert goal("put the towel in the sink", bathroom) == ("hand_towel", "sink_basin")
    assert goal("put the towel on the towel rack", bathroom) == ("hand_towel", "hand_towel_holder")
    assert goal("put the towel in the tub", bathroom) == ("hand_towel", "bathtub_basin")
    kitchen = ["dining_table", "side_table", "counter_top", "butter_knife", "kettle", "sink_basin"]
    assert goal("put the knife on the table", kitchen) == ("butter_knife", "dining_table")  # the suite's order
    assert goal("put the teapot on the counter", kitchen) == ("kettle", "counter_top")
    assert goal("put the glass on the counter", kitchen)[0] is None      # no glass here, and no convention


def test_human_goals_are_grounded_in_the_episodes_room(shared_data: Path, library: Library) -> None:
    from seal_cli.bench.tasks import commands_for

    full = load_suite(shared_data / "alfred2d", "valid_seen", with_priors=False)
    episode = next(e for e in full.episodes if e.goals[0] == "Put a cooked slice of tomato on a kitchen counter.")
    plan = full.floor_plans[episode.floor_plan]
    scene = build_scene(episode, plan, library, {})
    commanded, _ = commands_for(episode, library, scene.vocabulary, "human")
    assert [str(b) for b in commanded] == ["Slice(theme=tomato, instrument=knife)",
                                           "Heat(theme=tomato, instrument=microwave)",
                                           "Place(theme=tomato, goal=counter_top)"]
    assert all(v in scene.vocabulary for b in commanded for _, v in b.values)   # every value a class of the room


def test_place_spread_is_the_share_of_the_pivot_s_clearance_a_thing_lies_at(suite) -> None:  # type: ignore[no-untyped-def]
    from seal_cli.bench.alfred2d import place_spread

    got = place_spread(suite.episodes, suite.floor_plans, (0.0, 0.5, 1.0))
    assert got[0] <= got[1] <= got[2] and got[0] >= 0.0
    assert 0.0 < got[1] < 2.0   # a thing lies on its receptacle, about as far from the pivot as the pivot's clearance
    with pytest.raises(SealError, match="no thing starts"):
        place_spread([], suite.floor_plans)


def test_a_limit_reads_the_trials_only_until_each_type_has_its_first(tmp_path: Path, shared_data: Path) -> None:
    """``limit``: the first trials of each type, in file order; once every type asked for has them the rest of the
    file is not read (the train split is 35 MB): a bad line after them is never met, one before them is."""
    (tmp_path / "floorplans.json").write_text(json.dumps(_one_plan(shared_data)))
    trial = _a_trial(shared_data, next(iter(_one_plan(shared_data)["floor_plans"])))
    kind = trial["task"]["type"]
    lines = [json.dumps({**trial, "task_id": f"t{k}"}) for k in range(3)]
    (tmp_path / "trials_x.jsonl").write_text("\n".join([*lines, "{not json"]) + "\n")
    suite = load_suite(tmp_path, "x", limit=2, types=[kind], with_priors=False)
    assert [e.task_id for e in suite.episodes] == ["t0", "t1"]
    with pytest.raises(SealError, match=r"trials_x\.jsonl:4:2: trial is not JSON"):
        load_suite(tmp_path, "x", limit=4, types=[kind], with_priors=False)
