"""prior_optimal and SeFM's whole-plan search on a drawn house: where they look first, and why they say so."""

from __future__ import annotations

import dataclasses
import re

import numpy as np
import pytest

from seal_cli.bench.houses import cottage
from seal_cli.frames.library import Library
from seal_cli.maps.model import ObjectTruth, Robot
from seal_cli.pipeline import run_on_map
from seal_cli.sim.policies import make_policy

NARRATION = re.compile(r"looks for spoon: (\w+): spoon (0\.\d\d)(?: and cup (0\.\d\d))? there, ([\d.]+) m "
                       r"\(expected ([\d.]+) m to finish the plan\)")


def _house(spoon: tuple[float, float], cup: tuple[float, float], at: tuple[float, float] = (7.5, 5.0)):  # type: ignore[no-untyped-def]
    m = cottage()
    objects = (ObjectTruth("spoon", spoon), ObjectTruth("cup", cup))
    return dataclasses.replace(m, objects=objects, robot=Robot((*at, 0.0)))


def test_both_look_first_where_spoon_and_cup_may_both_be_and_say_why(library: Library) -> None:
    # in the hall, half a metre nearer the bedroom's door than the kitchen's: for the spoon alone a look
    # down the hall comes first, for "stir the cup" the bedroom (spoons and cups), not the kitchen (spoons)
    world = _house(spoon=(3.0, 1.0), cup=(4.0, 1.5), at=(7.5, 4.5))
    for name in ("prior_optimal", "sefm"):
        agent, result = run_on_map(world, "stir the cup", library, make_policy(name, 100), rng=np.random.default_rng(0))
        assert result.completed, result.reason
        said = [NARRATION.search(r.text) for r in agent.records if r.kind == "search"]
        assert said and all(said), [r.text for r in agent.records if r.kind == "search"]
        first = said[0]
        assert first is not None and first.group(1) == "bedroom", [r.text for r in agent.records if r.kind == "search"]
        assert first.group(3) is not None and float(first.group(3)) > 0.3
    agent, result = run_on_map(world, "pick up the spoon", library, make_policy("prior_optimal"),
                               rng=np.random.default_rng(0))
    first_alone = next(r.text for r in agent.records if r.kind == "search")
    assert result.completed and ": bedroom:" not in first_alone, first_alone


def test_prior_optimal_removes_what_it_has_seen_and_finds_a_thing_off_every_prior(library: Library) -> None:
    world = _house(spoon=(7.5, 9.0), cup=(12.0, 7.0))      # the spoon in the hall, where no prior puts it
    agent, result = run_on_map(world, "stir the cup", library, make_policy("prior_optimal"),
                               rng=np.random.default_rng(0))
    assert result.completed, result.reason
    policy = agent.policy
    w = policy.weights("spoon")
    cleared = policy.cleared["spoon"]
    assert cleared.any() and not w[cleared].any()
    assert w[~cleared].any()          # what it has not seen keeps its prior


@pytest.mark.parametrize("name", ["prior_optimal", "sefm"])
def test_the_whole_plan_search_looks_again_at_a_room_its_view_saw_only_part_of(library: Library, name: str) -> None:
    # with a 2 m sensor no cell sees a whole 6 x 5 m room: the bedroom stays a region while any of its
    # belief is where the robot has not looked, looked at from a new view each time, so the beliefs
    # (not the frontier) find the cup
    m = _house(spoon=(3.0, 1.0), cup=(0.6, 4.4))
    world = dataclasses.replace(m, sensor=dataclasses.replace(m.sensor, range=2.0))
    agent, result = run_on_map(world, "stir the cup", library, make_policy(name, 100),
                               rng=np.random.default_rng(0))
    assert result.completed, result.reason
    searches = [r.text for r in agent.records if r.kind == "search"]
    assert not any("are spent" in t or "is spent" in t for t in searches), searches
    if name == "prior_optimal":       # the cup's corner, from a view added for it
        assert any(": bedroom: cup" in t for t in searches), searches
    # SeFM plans the cup's search given what the spoon's saw: into the bedroom for the spoon, where the
    # cup is seen on the way (it took the kitchen twice and the family room three times, 47 m, before)
    assert agent.world.robot.path_m < 30.0, searches
    looked_from = [r.data["to"] for r in agent.records if r.kind == "go" and r.text.startswith("goes to look")
                   and "stops" not in r.text]
    assert len(set(map(tuple, looked_from))) == len(looked_from), looked_from     # never from one cell twice


def test_prior_optimal_counts_a_shut_receptacle_unseen_until_it_is_opened() -> None:
    from seal_cli.maps.model import Place
    from seal_cli.sim.policies.prior_optimal import PriorOptimalPolicy

    m = _house(spoon=(3.0, 1.0), cup=(4.0, 1.5))
    box = Place("cupboard_1", "cupboard", (12.0, 8.0), openable=True)
    world = dataclasses.replace(m, places=m.places + (box,), priors={**m.priors, "cup": {"cupboard_1": 1.0}})
    policy = PriorOptimalPolicy()
    policy.map, policy.openable, policy.cleared, policy.parents = world, [p.openable for p in world.places], {}, {}
    policy.looks = [(np.arange(len(world.free_centres)), frozenset(), frozenset())]   # everything seen, the box shut
    inside = policy.parent_of("cup") == len(world.places) - 1
    assert inside.any() and not inside.all()
    w = policy.weights("cup")
    assert not w[~inside].any() and w[inside].any()                  # only the shut cupboard may still hold it
    policy.cleared = {}
    policy.looks.append((np.zeros(0, dtype=int), frozenset({"cupboard_1"}), frozenset({"cupboard_1"})))
    assert not policy.weights("cup").any()                           # looked into from within reach: nothing left


def test_a_search_drive_stops_at_the_look_that_finds_the_thing(library: Library) -> None:
    from seal_cli.bench.houses import CONTEXT_OBJECTS, CONTEXT_PRIORS
    from seal_cli.maps.formats.map_server import load_map
    from seal_cli.resources import map_path

    m = load_map(map_path("apartment"))
    where = {"spoon": (-8.0, 2.9), "cup": (-8.8, 1.0), "mug": (5.26, -0.45), "kettle": (4.84, 2.18)}
    world = dataclasses.replace(
        m, priors={**{c: p for c, p in CONTEXT_PRIORS.items() if c not in m.priors}, **m.priors},
        objects=tuple(ObjectTruth(str(o["class"]), where[str(o["class"])]) for o in CONTEXT_OBJECTS),
        robot=Robot((0.0, -3.0, 0.0)))
    agent, result = run_on_map(world, "pour the kettle into the mug", library, make_policy("prior_optimal"),
                               rng=np.random.default_rng(0))
    assert result.completed, result.reason
    texts = [r.text for r in agent.records]
    stops = [i for i, t in enumerate(texts) if "stops, what it looks for is in sight" in t]
    assert stops, texts
    k = stops[0]
    assert texts[k - 1].startswith("sees ") and texts[k + 1].startswith("goes to ")
    assert texts[k + 1].split()[2].split("_")[0] in texts[k - 1]     # straight to what it saw
