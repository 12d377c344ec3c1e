"""The baselines on the tiny kitchen and on real ALFRED-2D episodes: same machinery, different searches."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from seal_cli.bench.alfred2d import Task, judge
from seal_cli.bench.tasks import run_suite, summarise
from seal_cli.frames.library import Library
from seal_cli.sim.agent import Agent
from seal_cli.sim.policies import DEFAULT_POLICIES, POLICIES, make_policy
from seal_cli.sim.policies.coverage import CoveragePolicy
from seal_cli.sim.policies.oracle import OraclePolicy
from tests.scenes import kitchen

HEAT = Task("pick_heat_then_place_in_recep", "Apple", "DiningTable")


def solve(library: Library, policy: str, apple_in: str = "fridge_1"):  # type: ignore[no-untyped-def]
    s = kitchen(library, apple_in=apple_in)
    agent = Agent(s, library, make_policy(policy, particles=100), rng=np.random.default_rng(3))
    result = agent.run([library.frame("Heat").bind({"theme": "apple"}),
                        library.frame("Place").bind({"theme": "apple", "goal": "dining_table"})])
    return s, agent, result


@pytest.mark.parametrize("policy", [p for p in POLICIES if p != "saycan"])  # saycan: no frames (test_saycan)
def test_every_policy_solves_the_heat_task(library: Library, policy: str) -> None:
    s, _, result = solve(library, policy)
    assert result.completed, result.reason
    assert judge(HEAT, s.world).success


def test_oracle_is_shortest_and_goes_straight_to_the_apple(library: Library) -> None:
    paths = {p: solve(library, p, "cabinet_1")[2].path_m for p in DEFAULT_POLICIES}
    assert paths["oracle"] == min(paths.values())
    _, agent, _ = solve(library, "oracle", "cabinet_1")
    assert not [r for r in agent.records if r.kind == "search"]  # it never had to look


def test_coverage_opens_receptacles_it_has_not_looked_into(library: Library) -> None:
    _, agent, result = solve(library, "coverage", "cabinet_1")
    opened = [r.text for r in agent.records if r.kind == "act" and r.text.startswith("opened")]
    assert any("cabinet_1" in t for t in opened)
    assert isinstance(agent.policy, CoveragePolicy) and agent.policy.seen.any()


def test_oracle_knows_what_is_hidden(library: Library) -> None:
    s = kitchen(library, apple_in="cabinet_1")
    agent = Agent(s, library, OraclePolicy(), rng=np.random.default_rng(0))
    assert "apple_1" in agent.known
    assert "apple_1" not in Agent(kitchen(library), library, CoveragePolicy(), rng=np.random.default_rng(0)).known


def test_suite_on_real_episodes_is_reproducible_and_spec_shaped(shared_data: Path) -> None:
    args = dict(goal="gold", limit=1, types=["pick_and_place_simple", "look_at_obj_in_light"], seed=5, jobs=1,
                particles=100)
    first = list(run_suite(shared_data / "alfred2d", "valid_seen", ["sefm", "coverage", "oracle"], **args))
    again = list(run_suite(shared_data / "alfred2d", "valid_seen", ["sefm", "coverage", "oracle"], **args))
    assert [(o.task_id, o.policy, o.path_m, o.success) for o in first] == \
        [(o.task_id, o.policy, o.path_m, o.success) for o in again]
    report = summarise(first, ["sefm", "coverage", "oracle"])
    group = report["groups"]["pick_and_place_simple"]
    assert group["n"] == 1 and set(group["success"]) == set(group["path_m"]) == {"sefm", "coverage", "oracle"}
    assert all(0.0 <= v <= 1.0 for v in group["success"].values())
    oracle = [o for o in first if o.policy == "oracle"]
    assert all(o.success for o in oracle)
    for o in first:
        if o.policy != "oracle" and o.success:
            twin = next(x for x in oracle if x.task_id == o.task_id)
            assert o.path_m >= twin.path_m - 1.0  # the oracle is (nearly) a lower bound


def test_coverage_looks_from_a_cell_with_a_line_of_sight_never_from_where_it_stands(library: Library) -> None:
    """In a house with walls, a frontier point behind a wall is looked at from a cell that sees it:
    coverage finishes "stir the cup" on the apartment (it used to crawl 5 cm a step towards points
    it could never see, and before that needed gigabytes for its neighbour lists)."""
    from seal_cli.maps.formats.map_server import load_map
    from seal_cli.pipeline import run_on_map
    from seal_cli.resources import map_path

    apartment = load_map(map_path("apartment"))
    policy = CoveragePolicy()
    views: list[tuple[tuple[int, int], tuple[int, int], tuple[float, float]]] = []
    original = policy.next_view

    def spy(agent, binding, target):  # type: ignore[no-untyped-def]
        view = original(agent, binding, target)
        if view is not None and view.open is None:
            views.append((agent.robot_cell(), view.cell, view.look_at))
        return view

    policy.next_view = spy  # type: ignore[method-assign]
    agent, result = run_on_map(apartment, "stir the cup", library, policy, rng=np.random.default_rng(0))
    assert result.completed, result.reason
    assert views and all(here != cell for here, cell, _ in views)
    for _, cell, at in views:
        assert apartment.line_of_sight(agent.grid.point(cell), np.array([at]))[0]


def test_the_oracle_never_stands_behind_a_wall_from_its_thing(library: Library) -> None:
    # a mug on the kitchen side of the wall the dining room shares with it: cells of the dining room lie
    # within reach of it, but the hand cannot go through the wall (the apartment, context-suite layout)
    import dataclasses

    from seal_cli.maps.formats.map_server import load_map
    from seal_cli.maps.model import ObjectTruth, Robot
    from seal_cli.pipeline import run_on_map
    from seal_cli.resources import map_path
    from seal_cli.sim.policies import make_policy

    m = load_map(map_path("apartment"))
    where = {"spoon": (-8.0, 2.9), "cup": (-8.8, 1.0), "mug": (5.26, -0.45), "kettle": (4.84, 2.18)}
    priors = {**{c: {"kitchen": 1.0} for c in where if c not in m.priors}, **m.priors}
    world = dataclasses.replace(m, priors=priors, robot=Robot((6.0, 4.5, 0.0)),
                                objects=tuple(ObjectTruth(c, at) for c, at in where.items()))
    _, result = run_on_map(world, "pour the kettle into the mug", library, make_policy("oracle"),
                           rng=np.random.default_rng(0))
    assert result.completed, result.reason
