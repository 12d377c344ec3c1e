"""The exact joint search over regions: checked against a plain enumeration of worlds, and on small worked cases."""

from __future__ import annotations

import itertools
from functools import cache

import numpy as np
import pytest

from seal_cli.sim.policies.frame_dp import Problem, one_at_a_time, solve


def _by_worlds(problem: Problem) -> float:
    """The same optimum computed the long way: the worlds (where each thing is, ``None``: in no region) with
    their probabilities, and the Bellman recursion over the worlds still consistent with what was seen."""
    k = len(problem.first)
    d = problem.distance
    rest1 = 1 - float(problem.first.sum())
    firsts = [(r, float(problem.first[r])) for r in range(k)] + [(None, rest1)]
    if problem.second is not None:
        rest2 = 1 - float(problem.second.sum())
        seconds = [(r, float(problem.second[r])) for r in range(k)] + [(None, rest2)]
    else:
        seconds = [(None, 1.0)]
    worlds = tuple((a, b, pa * pb) for (a, pa), (b, pb) in itertools.product(firsts, seconds) if pa * pb > 0)

    def finish(at: int, looked: frozenset[int], alive: tuple[int, ...]) -> float:
        """The first thing found in region ``at``: on to the second stop, searching for it alone if unknown."""
        w = [worlds[i] for i in alive]
        total = sum(p for *_, p in w)
        if problem.second is None:
            return 0.0 if problem.after is None else float(problem.after[at])
        assert problem.reach_second is not None
        known = {b for _, b, _ in w if b is not None and b in looked}
        if known:
            (b,) = known
            return float(d[at, b] + problem.reach_second[b])
        return alone(at, looked, alive) / total if total > 0 else 0.0

    @cache
    def alone(at: int, looked: frozenset[int], alive: tuple[int, ...]) -> float:
        """Unnormalised: the sum over the worlds ``alive`` of probability times metres to find the second thing."""
        assert problem.reach_second is not None
        left = [i for i in alive if worlds[i][1] is not None and worlds[i][1] not in looked]
        if sum(worlds[i][2] for i in left) < 1e-3 * sum(worlds[i][2] for i in alive):
            return 0.0
        best = np.inf
        total = sum(worlds[i][2] for i in alive)
        for u in range(k):
            if u in looked or not any(worlds[i][1] == u for i in left):
                continue
            here = tuple(i for i in alive if worlds[i][1] == u)
            elsewhere = tuple(i for i in alive if worlds[i][1] != u)
            cost = d[at, u] * total + sum(worlds[i][2] for i in here) * problem.reach_second[u]
            cost += alone(u, looked | {u}, elsewhere)
            best = min(best, cost)
        return float(best) if np.isfinite(best) else 0.0

    @cache
    def value(at: int, looked: frozenset[int], alive: tuple[int, ...]) -> float:
        """Unnormalised: probability times metres to finish over the worlds ``alive``."""
        total = sum(worlds[i][2] for i in alive)
        left = sum(worlds[i][2] for i in alive if worlds[i][0] is not None)
        if left < 1e-3 * total:
            return 0.0
        best = np.inf
        for u in range(k):
            if u in looked:
                continue
            if not any(worlds[i][0] == u or worlds[i][1] == u for i in alive):
                continue
            seen = looked | {u}
            cost = d[at, u] * total
            outcomes = {(worlds[i][0] == u, worlds[i][1] == u) for i in alive}
            for here, also in outcomes:                 # what the look at u sees: the first thing? the second?
                group = tuple(i for i in alive if (worlds[i][0] == u, worlds[i][1] == u) == (here, also))
                if here:
                    mass = sum(worlds[i][2] for i in group)
                    cost += mass * (problem.reach_first[u] + finish(u, seen, group))
                else:
                    cost += value(u, seen, group)
            best = min(best, cost)
        return float(best) if np.isfinite(best) else 0.0

    return value(k, frozenset(), tuple(range(len(worlds))))


def _random_problem(rng: np.random.Generator, k: int, second: str) -> Problem:
    pts = rng.uniform(0, 10, size=(k + 1, 2))
    d = np.hypot(*(pts[:, None, :] - pts[None, :, :]).transpose(2, 0, 1))
    p1 = rng.dirichlet(np.ones(k + 1))[:k]
    reach1 = rng.uniform(0, 2, size=k)
    if second == "unknown":
        return Problem(d, p1, reach1, rng.dirichlet(np.ones(k + 1))[:k], rng.uniform(0, 2, size=k))
    if second == "known":
        return Problem(d, p1, reach1, after=rng.uniform(0, 8, size=k))
    return Problem(d, p1, reach1)


@pytest.mark.parametrize("second", ["unknown", "known", "none"])
def test_the_programme_is_the_optimum_computed_over_the_worlds(second: str) -> None:
    rng = np.random.default_rng(7)
    for _ in range(6):
        problem = _random_problem(rng, 4, second)
        assert solve(problem).expected_m == pytest.approx(_by_worlds(problem), rel=1e-9, abs=1e-9)


def test_one_thing_alone_is_searched_in_the_best_fixed_order() -> None:
    # for a single thing nothing is learnt until it is found, so the optimum is the best order of the regions
    rng = np.random.default_rng(3)
    problem = _random_problem(rng, 5, "none")
    p, d, e = problem.first, problem.distance, problem.reach_first
    best = np.inf
    for order in itertools.permutations(range(5)):
        cost, at, left = 0.0, 5, 1.0
        for u in order:
            if left < 1e-3:
                break
            cost += left * d[at, u] + p[u] * e[u]
            left -= p[u]
            at = u
        best = min(best, cost)
    assert solve(problem).expected_m == pytest.approx(best)


def test_the_region_that_may_hold_both_things_comes_first_though_the_first_thing_alone_says_otherwise() -> None:
    # the robot is 2 m from each region, the regions 4 m apart; the spoon is in region 0 with 0.6, region 1 with
    # 0.4; the cup in region 1 with 0.5 (the rest of its belief is beyond the regions, where the model stops)
    d = np.array([[0.0, 4.0, 2.0],
                  [4.0, 0.0, 2.0],
                  [2.0, 2.0, 0.0]])
    spoon = np.array([0.6, 0.4])
    reach = np.zeros(2)
    alone = solve(Problem(d, spoon, reach))
    assert alone.region == 0 and alone.expected_m == pytest.approx(2 + 0.4 * 4)
    both = solve(Problem(d, spoon, reach, np.array([0.0, 0.5]), reach))
    # region 0 first: 2 + 0.6 * 4 (then to region 1 for the cup) + 0.4 * 4 (the spoon in region 1) = 6.0;
    # region 1 first: 2 + 0.6 * (4 to the spoon in region 0, and back 4 only if the look saw the cup) = 5.6
    assert both.region == 1 and both.expected_m == pytest.approx(2 + 0.6 * (4 + 0.5 * 4))


def test_one_thing_at_a_time_follows_the_first_things_order_and_pays_for_it() -> None:
    # the case above: the spoon alone says region 0 first; searched that way the pair costs 6.0, not 5.6
    d = np.array([[0.0, 4.0, 2.0],
                  [4.0, 0.0, 2.0],
                  [2.0, 2.0, 0.0]])
    reach = np.zeros(2)
    problem = Problem(d, np.array([0.6, 0.4]), reach, np.array([0.0, 0.5]), reach)
    greedy = one_at_a_time(problem)
    assert greedy.region == 0 and greedy.expected_m == pytest.approx(2 + 0.6 * 4 + 0.4 * 4)
    assert solve(problem).expected_m == pytest.approx(5.6)


@pytest.mark.parametrize("second", ["unknown", "known", "none"])
def test_one_thing_at_a_time_is_never_shorter_than_the_programme(second: str) -> None:
    rng = np.random.default_rng(11)
    for _ in range(6):
        problem = _random_problem(rng, 4, second)
        best, greedy = solve(problem).expected_m, one_at_a_time(problem).expected_m
        assert greedy >= best - 1e-9
        if second == "none":   # nothing after the first thing: the first thing's own order is the optimum
            assert greedy == pytest.approx(best)


def test_a_thing_beyond_every_region_ends_the_model() -> None:
    d = np.zeros((3, 3))
    assert solve(Problem(d, np.zeros(2), np.zeros(2))).region is None


def test_a_problem_of_mismatched_shapes_is_refused() -> None:
    with pytest.raises(ValueError, match="2 regions"):
        Problem(np.zeros((2, 2)), np.zeros(2), np.zeros(2))
    with pytest.raises(ValueError, match="both its belief and its reaches"):
        Problem(np.zeros((3, 3)), np.zeros(2), np.zeros(2), np.zeros(2))
