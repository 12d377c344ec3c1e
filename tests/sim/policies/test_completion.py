"""The exact expected-drive search: against brute force, and on the cases it is for."""

from __future__ import annotations

import itertools

import numpy as np

from seal_cli.sim.policies.completion import Target, solve


def _line(points: list[float]) -> np.ndarray:
    """Distances between points on a line."""
    p = np.asarray(points)
    return np.abs(p[:, None] - p[None, :])


def test_one_thing_matches_the_best_visit_order_by_brute_force() -> None:
    rng = np.random.default_rng(4)
    for _ in range(5):
        xy = rng.uniform(0, 10, (6, 2))            # five regions and the start
        distance = np.hypot(*(xy[:, None, :] - xy[None, :, :]).transpose(2, 0, 1))
        mass = rng.uniform(0.05, 1, 5)
        best = np.inf
        for order in itertools.permutations(range(5)):
            here, walked, expected = 5, 0.0, 0.0
            for r in order:
                walked += distance[here, r]
                here = r
                expected += mass[r] / mass.sum() * walked
            best = min(best, expected)
        choice = solve(distance, {"spoon": mass}, [Target("spoon")], start=5, regions=5)
        assert choice is not None and abs(choice.expected_m - best) < 1e-9


def test_two_things_go_first_where_both_may_be() -> None:
    # kitchen 0 (spoon), bedroom 1 (spoon and cup), family room 2 (cup); the start 3 is nearer the kitchen
    xy = np.array([[0.0, 0.0], [6.0, 3.0], [12.0, 0.0], [1.5, 4.0]])
    distance = np.hypot(*(xy[:, None, :] - xy[None, :, :]).transpose(2, 0, 1))
    masses = {"spoon": np.array([0.5, 0.5, 0.0]), "cup": np.array([0.0, 0.5, 0.5])}
    choice = solve(distance, masses, [Target("spoon"), Target("cup")], start=3, regions=3)
    assert choice is not None and choice.region == 1
    alone = solve(distance, {"spoon": masses["spoon"]}, [Target("spoon")], start=3, regions=3)
    assert alone is not None and alone.region == 0      # for the spoon alone the kitchen is first


def test_a_known_goal_is_a_cost_not_a_place_to_search() -> None:
    # the spoon is surely in region 1; the sink (location 3) is beside region 0, where no spoon is
    distance = _line([0.0, 10.0, 5.0, 0.5])
    choice = solve(distance, {"spoon": np.array([0.0, 1.0])}, [Target("spoon"), Target(at=(3,))], start=2,
                   regions=2)
    assert choice is not None and choice.region == 1
    assert abs(choice.expected_m - (5.0 + 9.5)) < 1e-9


def test_what_was_seen_is_not_searched_again_and_nothing_left_is_none() -> None:
    distance = _line([0.0, 4.0, 1.0])
    masses = {"cup": np.array([0.6, 0.4])}
    choice = solve(distance, masses, [Target("cup")], start=2, regions=2, seen=frozenset({0}))
    assert choice is not None and choice.region == 1 and abs(choice.expected_m - 3.0) < 1e-9
    assert solve(distance, masses, [Target("cup")], start=2, regions=2, seen=frozenset({0, 1})) is None
