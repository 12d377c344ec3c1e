"""The end-state judge: the world at the end against the commanded frames' effects, for every policy."""

from __future__ import annotations

import numpy as np
import pytest

from seal_cli.bench.endstate import effects, holds, judge_end
from seal_cli.bench.mapsuite import commanded_frames, run_map_suite
from seal_cli.frames.library import Library
from seal_cli.frames.model import Fact
from seal_cli.frames.reading import load_library
from seal_cli.maps.formats.map_server import load_map
from seal_cli.resources import map_path
from seal_cli.sim.agent import scene_from_map
from seal_cli.sim.policies import make_policy
from seal_cli.sim.policies.saycan import SayCanPolicy
from seal_cli.sim.scorers import BagOfWordsScorer, ExampleScorer, load_examples
from seal_cli.sim.world import HAND


@pytest.fixture(scope="module")
def library() -> Library:
    return load_library(None)


@pytest.fixture(scope="module")
def apartment():  # type: ignore[no-untyped-def]
    return load_map(map_path("apartment"))


def test_effects_keep_what_the_later_frames_leave_true(library: Library, apartment) -> None:  # type: ignore[no-untyped-def]
    commanded, classes = commanded_frames(apartment, "pick up the cup and put it on the dining table", library)
    assert [str(f) for f, _ in effects(commanded)] == ["in(cup, dining_table_1)", "hand_empty"]
    assert classes["cup"] == "cup"


def test_the_judge_reads_places_rooms_the_hand_and_states_from_the_world(library: Library, apartment) -> None:  # type: ignore[no-untyped-def]
    scene = scene_from_map(apartment, library)
    world = scene.world
    cup = world.of_class("cup")[0].id
    commanded, classes = commanded_frames(apartment, "pick up the cup and put it on the dining table", library)
    before = judge_end(world, apartment, commanded, classes)
    assert not before.success and "in(cup, dining_table_1)" in before.reason
    world.items[cup].parent = "dining_table_1"
    world.items[cup].at = world.items["dining_table_1"].at
    assert judge_end(world, apartment, commanded, classes).success
    world.items[cup].parent, world.robot.holding = HAND, cup     # in the hand is not on the table
    assert not judge_end(world, apartment, commanded, classes).success
    assert holds(Fact("holding", (cup,)), world, apartment) and not holds(Fact("hand_empty"), world, apartment)
    bedroom, = commanded_frames(apartment, "bring the apple to the bedroom", library)[0]
    assert [str(f) for f, _ in effects([bedroom])] == ["in(apple, bedroom)", "hand_empty"]
    apple = world.of_class("apple")[0].id
    inside = apartment.rooms[apartment.room_id("bedroom")]   # type: ignore[index]
    world.items[apple].at = tuple(np.mean(np.asarray(inside.polygon), axis=0))
    world.items[apple].parent = None
    world.robot.holding = None
    world.items[cup].parent = "dining_table_1"
    assert holds(Fact("in", (apple, "bedroom")), world, apartment)
    assert not holds(Fact("in", (apple, "kitchen")), world, apartment)
    assert not holds(Fact("stirred", (cup,)), world, apartment)
    assert holds(Fact("found", (cup,)), world, apartment, {cup}) and not holds(Fact("found", (cup,)), world, apartment)


def test_saycan_runs_on_the_map_suite_judged_like_every_policy(monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setattr("seal_cli.sim.policies.make_policy",
                        lambda name, particles=200: SayCanPolicy(ExampleScorer(BagOfWordsScorer()), load_examples())
                        if name == "saycan" else make_policy(name, particles))
    outcomes = list(run_map_suite(str(map_path("apartment")), ["put the spoon in the sink"], ["oracle", "saycan"],
                                  layouts=1, jobs=1, particles=50))
    oracle, saycan = outcomes
    assert oracle.policy == "oracle" and oracle.success and oracle.reason == "success"
    assert saycan.policy == "saycan" and saycan.commanded[:2] == ("find the spoon", "pick up the spoon")
    assert saycan.success == (saycan.reason == "success")
    assert saycan.success or "not done: needs in(spoon, sink_1)" in saycan.reason

