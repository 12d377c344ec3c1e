"""The baselines on the tiny kitchen and on real ALFRED-2D episodes: same machinery, different searches."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from seal_cli.agent import Agent
from seal_cli.alfred2d import Task, judge
from seal_cli.baselines import POLICIES, CoveragePolicy, OraclePolicy, make_policy
from seal_cli.bench_tasks import run_suite, summarise
from seal_cli.errors import SealError
from seal_cli.library import Library

from .scenes import kitchen

HEAT = Task("pick_heat_then_place_in_recep", "Apple", "DiningTable")


def solve(library: Library, policy: str, apple_in: str = "fridge_1"):  # type: ignore[no-untyped-def]
    s = kitchen(library, apple_in=apple_in)
    agent = Agent(s, library, make_policy(policy, particles=100), rng=np.random.default_rng(3))
    result = agent.run([library.frame("Heat").bind({"theme": "apple"}),
                        library.frame("Place").bind({"theme": "apple", "goal": "dining_table"})])
    return s, agent, result


@pytest.mark.parametrize("policy", [*POLICIES, "uniform"])
def test_every_policy_solves_the_heat_task(library: Library, policy: str) -> None:
    s, _, result = solve(library, policy)
    assert result.completed, result.reason
    assert judge(HEAT, s.world).success


def test_oracle_is_shortest_and_goes_straight_to_the_apple(library: Library) -> None:
    paths = {p: solve(library, p, "cabinet_1")[2].path_m for p in POLICIES}
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


def test_unknown_policy_is_refused() -> None:
    with pytest.raises(SealError, match="unknown policy 'psychic'"):
        make_policy("psychic")


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


def test_coverage_drops_every_point_it_cannot_see_from_here_in_one_pass(library: Library) -> None:
    """Lattice points within reach of the robot's own cell yet unseen (behind a wall) are dropped
    together: one neighbour query per choice, not one per dropped point (a map whose belief was
    spent far from the robot made `seal run` take hours)."""
    agent = Agent(kitchen(library), library, CoveragePolicy(), rng=np.random.default_rng(0))
    policy = agent.policy
    assert isinstance(policy, CoveragePolicy)
    policy.begin(agent)
    policy.seen[:] = False  # nothing seen: every point the robot's own cell is nearest to is "unseeable"
    tree, calls = policy.tree, []

    class Counting:
        def query_ball_point(self, points, r):  # type: ignore[no-untyped-def]
            calls.append(len(points))
            return tree.query_ball_point(points, r)

    policy.tree = Counting()  # type: ignore[assignment]
    view = policy.next_view(agent, library.frame("Heat").bind({"theme": "apple"}), "apple")
    assert view is not None and view.cell != agent.robot_cell()
    assert len(calls) == 1 and policy.seen.sum() > 1
