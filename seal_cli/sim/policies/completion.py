"""The expected cost to complete the remaining plan, and the search order that minimises it.

A plan drives to its targets in order (Pick(spoon), then Stir(cup): the spoon, then the cup).
Some targets are known — a place of the map, a thing already seen — and are positions; the others
are unknown and are beliefs. This module answers, for a robot at a point: *which region should it
look at next, so that the whole remaining plan is done by the shortest expected drive?*

The model (the approximation, stated once):

- **Regions.** The map is cut into regions a single view reveals: every place (the free space
  within its reach, where a thing on or in it is taken from; a shut one is revealed by opening it)
  and every room (its free space outside the places). Looking from a region's view reveals whether
  each sought thing is in that region, with certainty; a thing found in a region is at its view.
- **Beliefs.** Each unknown thing is in exactly one region, with probability proportional to the
  belief's mass there (what is believed to be outside every region is left out: the beliefs are
  conditioned on the regions), and different things are independent — the factorised form of the
  commanded frame's belief over its unknown elements.
- **Costs.** Driving between views, the start and the known targets costs the shortest-path
  metres on the grid; acting costs nothing.

Under that model the optimal adaptive search is a finite-horizon MDP whose state is the robot's
location, the set of regions seen, how far along the plan it is and where each thing seen so far
was found; :func:`solve` computes its value exactly by dynamic programming (memoised recursion).
When the robot finds the thing at hand it serves it and moves on, and everything it saw on the
way counts: a cup seen while looking for the spoon is a known position for Stir. It is exact for
the model; it stops being exact where the model does — a view that sees less than its whole region
(a large or L-shaped room), things that stand between regions, a detector that misses, two things
of one class, and more regions than :data:`MAX_REGIONS` (then only the heaviest are kept).
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from dataclasses import dataclass
from typing import Any

import numpy as np

__all__ = ["MAX_REGIONS", "Choice", "Target", "solve"]

MAX_REGIONS = 9
"""The most regions the exact search considers (the heaviest, by the largest mass of any thing sought)."""


@dataclass(frozen=True)
class Target:
    """One stop of the remaining plan: an unknown thing (``cls``), or known positions (``at``: indices of
    locations, the robot goes to the nearest)."""

    cls: str | None = None
    at: tuple[int, ...] = ()


@dataclass(frozen=True)
class Choice:
    """The region to look at next (an index into the regions) and the expected metres to finish from here."""

    region: int
    expected_m: float


def solve(distance: np.ndarray, masses: Mapping[str, np.ndarray], targets: Sequence[Target], *, start: int,
          regions: int, seen: frozenset[int] = frozenset()) -> Choice | None:
    """The exact adaptive search of the module's model.

    ``distance[a, b]``: metres between locations; locations ``0 .. regions-1`` are the regions'
    views, the others the start and the known targets' positions. ``masses[cls][r]``: the belief
    that the thing of class ``cls`` is in region ``r`` (unnormalised; only its ratios count).
    ``targets``: the remaining plan's stops in order; the first must be unknown. ``seen``: regions
    already looked at (nothing sought is there). None when the first target has no belief left."""
    classes = sorted({t.cls for t in targets if t.cls is not None})
    index = {c: k for k, c in enumerate(classes)}
    mass = np.zeros((len(classes), regions))
    for c, k in index.items():
        m = np.asarray(masses[c], dtype=float)[:regions].copy()
        m[list(seen)] = 0.0
        mass[k] = np.where(np.isfinite(m) & (m > 0), m, 0.0)
    plan = [(index[t.cls] if t.cls is not None else -1, t.at) for t in targets]
    seen_mask = sum(1 << r for r in seen)
    memo: dict[tuple[Any, ...], tuple[float, int]] = {}

    def left(k: int, mask: int) -> float:
        row = mass[k]
        return float(sum(row[r] for r in range(regions) if not mask >> r & 1))

    def value(loc: int, mask: int, i: int, found: tuple[int, ...]) -> tuple[float, int]:
        key = (loc, mask, i, found)
        if key in memo:
            return memo[key]
        cost = 0.0
        while i < len(plan):
            k, at = plan[i]
            if k < 0:
                nxt = min(at, key=lambda a: distance[loc, a])
            elif found[k] >= 0:
                nxt = found[k]
            else:
                break
            cost += float(distance[loc, nxt])
            loc, i = nxt, i + 1
        if i == len(plan):
            memo[key] = (cost, -1)
            return memo[key]
        k = plan[i][0]
        sought = sorted({plan[j][0] for j in range(i, len(plan)) if plan[j][0] >= 0 and found[plan[j][0]] < 0})
        remaining = {s: left(s, mask) for s in sought}
        best, choice = np.inf, -1
        for r in range(regions):
            if mask >> r & 1 or mass[k, r] <= 0:
                continue
            expected = float(distance[loc, r])
            outcomes: list[tuple[float, tuple[int, ...]]] = [(1.0, found)]
            for s in sought:
                p = mass[s, r] / remaining[s] if remaining[s] > 0 else 0.0
                p = 1.0 if p > 1 - 1e-9 else p
                split = []
                for prob, f in outcomes:
                    if p > 0:
                        split.append((prob * p, f[:s] + (r,) + f[s + 1:]))
                    if p < 1:
                        split.append((prob * (1 - p), f))
                outcomes = split
            for prob, f in outcomes:
                if prob > 1e-12:
                    expected += prob * value(r, mask | 1 << r, i, f)[0]
            if expected < best:
                best, choice = expected, r
        memo[key] = (cost + best, choice)
        return memo[key]

    if not plan or plan[0][0] < 0 or mass[plan[0][0]].sum() <= 0:
        return None
    total, region = value(start, seen_mask, 0, tuple(-1 for _ in classes))
    if region < 0 or not np.isfinite(total):
        return None
    return Choice(region, total)
