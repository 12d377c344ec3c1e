"""The exact adaptive search for two things of one plan, by dynamic programming over regions.

A plan drives to the thing sought now (the *first*, unknown), then to the *second* stop: another
unknown thing, a known position, or nothing. Both unknown things are searched for *jointly*: every
look may find either, and the order in which regions are looked at adapts to what was found. This
module answers, under the model below, *which region should the robot look at next so that both
stops are reached by the shortest expected drive?* — exactly, by dynamic programming over the
robot's position (a region's view), the set of regions looked at, and where the second thing was
found (if it was).

The model (the approximation, stated once):

- **Regions.** The free space is cut into regions (a room seen from its best-seeing cell; a place
  seen from where one stands at it); a look from a region's view sees everything in it and nothing
  outside it. The robot looks only from views; what a drive sees on the way is not counted.
- **Beliefs.** Each thing is in one region with the probability ``first[r]`` or ``second[r]`` (the
  rest, ``1 - sum``, is "nowhere the regions cover"); the two are independent. A region looked at
  holds neither thing any more than it was seen to (the detector does not miss), so the belief
  that a thing is in region ``u`` given it is in none of the regions ``V`` looked at is
  ``p[u] / (1 - p[V])``.
- **Costs.** Metres: ``distance[a, b]`` between views (the last row and column: the robot's start),
  ``reach_first[u]`` / ``reach_second[u]`` from a region's view to a thing found there (its expected
  drive), the first thing then stands in for its region's view; ``after[u]``: from the first thing
  found in region ``u`` to a known second stop. Where a thing lies in none of the regions left
  (its remaining belief below :data:`SPENT`), the model stops: that costs nothing more (the policy
  falls back to a search that does not use this model).

Where it stops being exact for the real robot: a look from a view may see less than its region
(walls, furniture, range) or more (a neighbouring room through a door); things seen on the drive;
a thing's position inside its region (its expected drive from the view, not the drive from where
it really is on to the next stop); the plan's stops after the second. Under the model itself it
is exact: :func:`solve` is the Bellman recursion over every reachable state.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from functools import cache

import numpy as np

__all__ = ["SPENT", "Problem", "Solution", "one_at_a_time", "solve"]

SPENT = 1e-3
"""Below this share of its belief left in the regions not looked at, a thing is taken to be beyond the model."""
UNKNOWN = -1
"""The second thing's state: not found yet."""
ABSENT = -2
"""The second stop is no unknown thing (a known position, or nothing)."""


@dataclass(frozen=True, eq=False)
class Problem:
    """The search for the first thing, then the second stop, over ``K`` regions (see the module docstring)."""

    distance: np.ndarray = field(repr=False)
    """(K + 1, K + 1) metres between the regions' views; index K is where the robot is."""
    first: np.ndarray = field(repr=False)
    """(K,) the first thing's belief per region."""
    reach_first: np.ndarray = field(repr=False)
    """(K,) metres from a region's view to the first thing found there."""
    second: np.ndarray | None = field(default=None, repr=False)
    """(K,) the second thing's belief per region; None: the second stop is not an unknown thing."""
    reach_second: np.ndarray | None = field(default=None, repr=False)
    after: np.ndarray | None = field(default=None, repr=False)
    """(K,) metres from the first thing found in a region to a known second stop; None: no known second stop."""

    def __post_init__(self) -> None:
        k = len(self.first)
        if self.distance.shape != (k + 1, k + 1) or self.reach_first.shape != (k,):
            raise ValueError(f"a problem of {k} regions needs a {(k + 1, k + 1)} distance and {k} reaches")
        if (self.second is None) != (self.reach_second is None):
            raise ValueError("the second thing needs both its belief and its reaches")
        if self.second is not None and self.after is not None:
            raise ValueError("the second stop is either an unknown thing or a known position, not both")


@dataclass(frozen=True)
class Solution:
    """The region to look at first (None: the first thing is beyond the model) and the expected metres to finish."""

    region: int | None
    expected_m: float


def _given(p: np.ndarray, looked: int) -> np.ndarray:
    """``p`` given the thing is in none of the regions of the bitmask ``looked`` (zero where looked)."""
    mask = np.array([(looked >> r) & 1 for r in range(len(p))], dtype=bool)
    left = 1.0 - float(p[mask].sum())
    out = np.where(mask, 0.0, p)
    return out / left if left > 0 else np.zeros_like(p)


def solve(problem: Problem) -> Solution:
    """The Bellman recursion over (view, regions looked at, where the second thing is): the optimal first
    region and the expected metres of the optimal adaptive search (the module's model)."""
    return _programme(problem, one_at_a_time=False)


def one_at_a_time(problem: Problem) -> Solution:
    """The expected metres, under the same model, of the searcher that looks for one thing at a time: its
    looks for the first thing follow the optimal search for the first thing *alone* (the second stop weighs
    nothing in the order), while what those looks show of the second thing is kept, as every policy here keeps
    it; once the first is found, the second is searched for optimally from there. Against :func:`solve` it is
    what frame context can save in a problem, from its beliefs and metres alone: never less than
    :func:`solve`'s, equal where the plan's second stop changes no choice."""
    return _programme(problem, one_at_a_time=True)


def _programme(problem: Problem, *, one_at_a_time: bool) -> Solution:
    k = len(problem.first)
    d = problem.distance
    p1 = np.asarray(problem.first, dtype=float)
    p2 = None if problem.second is None else np.asarray(problem.second, dtype=float)
    e1 = np.asarray(problem.reach_first, dtype=float)
    e2 = None if problem.reach_second is None else np.asarray(problem.reach_second, dtype=float)

    @cache
    def second_alone(at: int, looked: int) -> float:
        """The second thing searched for alone, from the view ``at``, the regions ``looked`` seen."""
        assert p2 is not None and e2 is not None
        q = _given(p2, looked)
        if q.sum() < SPENT:
            return 0.0
        best = np.inf
        for u in range(k):
            if q[u] > 0 and np.isfinite(d[at, u]):
                best = min(best, d[at, u] + q[u] * e2[u] + (1 - q[u]) * second_alone(u, looked | 1 << u))
        return float(best) if np.isfinite(best) else 0.0

    def then(at: int, looked: int, second: int) -> float:
        """From the first thing, found in region ``at``, to the second stop."""
        if second == ABSENT:
            return 0.0 if problem.after is None else float(problem.after[at])
        if second >= 0:
            assert e2 is not None
            return float(d[at, second] + e2[second])
        return second_alone(at, looked)

    @cache
    def alone(at: int, looked: int) -> tuple[float, int | None]:
        """The first thing searched for alone (the second stop weighs nothing): its value and first region."""
        q1 = _given(p1, looked)
        if q1.sum() < SPENT:
            return 0.0, None
        best, choice = np.inf, None
        for u in range(k):
            if q1[u] > 0 and not (looked >> u) & 1 and np.isfinite(d[at, u]):
                cost = d[at, u] + q1[u] * e1[u] + (1 - q1[u]) * alone(u, looked | 1 << u)[0]
                if cost < best - 1e-9:
                    best, choice = cost, u
        return (float(best), choice) if choice is not None else (0.0, None)

    @cache
    def value(at: int, looked: int, second: int) -> tuple[float, int | None]:
        q1 = _given(p1, looked)
        if q1.sum() < SPENT:
            return 0.0, None
        q2 = _given(p2, looked) if p2 is not None and second == UNKNOWN else None
        best, choice = np.inf, None
        fixed = alone(at, looked)[1] if one_at_a_time else None
        for u in range(k):
            worth = q1[u] > 0 or (q2 is not None and q2[u] > 0)
            if not worth or (looked >> u) & 1 or not np.isfinite(d[at, u]) or (one_at_a_time and u != fixed):
                continue
            seen = looked | 1 << u
            a = float(q1[u])
            b = 0.0 if q2 is None else float(q2[u])
            here = u if second == UNKNOWN else second
            cost = d[at, u] + a * e1[u]
            if a > 0:
                cost += a * (b * then(u, seen, u) if b > 0 else 0.0) + a * (1 - b) * then(u, seen, second)
            if a < 1:
                cost += (1 - a) * (b * value(u, seen, here)[0] + (1 - b) * value(u, seen, second)[0])
            if cost < best - 1e-9:
                best, choice = cost, u
        return (float(best), choice) if choice is not None else (0.0, None)

    expected, region = value(k, 0, UNKNOWN if p2 is not None else ABSENT)
    return Solution(region, expected)
