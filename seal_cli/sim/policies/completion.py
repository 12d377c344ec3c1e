"""The expected cost to complete the remaining plan, and the next view that minimises it.

A plan drives to its targets in order (Pick(spoon), then Stir(cup): the spoon, then the cup).
Some targets are known — a place of the map, a thing already seen — and are positions; the others
are unknown and are beliefs. This module answers, for a robot at a node of a
:class:`~seal_cli.sim.policies.views.Lattice`: *from which candidate view should it look next, so
that the whole remaining plan is done by the shortest expected drive?*

The model (the approximation, stated once):

- **Views and looks.** The robot drives shortest paths between nodes and looks every metre on the
  way and at the end (as the agent does); a look sees the nodes the sensor sees from it, except
  those in a shut receptacle, which the look at a view that opens it sees. A search drive stops at
  the first look that sees the thing sought, and the robot drives to it (the lattice's distance).
- **Beliefs.** Each unknown thing is at one node, with probability proportional to its belief's
  mass there; different things are independent (the commanded frame's belief over its unknown
  elements in factorised form; the frame's relation — the things near each other — enters through
  the path costs between them). The detector does not miss.
- **Costs.** Metres driven; acting and turning cost nothing.

For one thing, the optimal search is an ordering of views (nothing is learnt until it is found), and
its expected cost follows from when each node is first seen. For the whole plan the exact
optimum is out of reach (a look can reveal any subset of the things), so :func:`choose` is a
**one-step rollout**: for each candidate first view ``u`` it evaluates, exactly under the model,
the policy "drive to ``u``, then search on by the greedy tour" — the tour that takes next the view
revealing the most of the thing's belief per metre on its drive and look — and the rest of the plan
once the thing is found. It picks the best ``u`` and is run again after every look with the new
beliefs (receding horizon). A rollout is never worse, under the model, than the tour it rolls
out. The rest of the plan after the thing sought now is valued as:

- a known target: the distance to the nearest of its positions;
- the next unknown thing: if it was seen on the drive before the thing sought now was found, the
  distance to it; otherwise its own greedy tour from the candidate view nearest to where the first
  was found, planned with its belief *given what the first search saw*: the nodes the first tour's
  looks saw up to the look that found the first thing hold none of it (that belief renormalised; a
  tour per look that can find the first thing, :data:`LEVELS` of them at most, the rest grouped
  with the look before them);
- any unknown thing after that: its greedy tour from the candidate view nearest to the thing before,
  with no credit for having been seen on the way; past :data:`HORIZON` such things, the drive from the thing
  before to where its belief puts it (no search: a lower bound). None of these terms depends on the first view,
  so they change the expected metres, never the choice.
"""

from __future__ import annotations

import dataclasses
from collections.abc import Callable, Mapping, Sequence
from dataclasses import dataclass

import numpy as np

from seal_cli.sim.policies.views import DriveTable

__all__ = ["MAX_TOUR", "Choice", "Target", "Tour", "choose", "greedy_tour", "quantiles"]

MAX_TOUR = 12
"""The most views of a greedy tour (it also ends when its belief is spent)."""
SPENT = 1e-3
"""A tour ends when less than this share of its belief is left unseen."""
SAMPLES = 300
"""Nodes at which a belief is represented for the rest of the plan: at its mass's quantiles (see :func:`quantiles`)."""
SCALE = 1.0
"""Metres added to every drive in the greedy tour's mass-per-metre rule (a view at the robot's feet is not free)."""
SLIGHT = 0.01
"""The share of the next thing's belief the first search's looks must see for its tour to be planned anew without
it (:meth:`_Later._tour`): looks that see less (a narrow sensor's, which see a sliver each) leave it the tour
planned with the whole belief, one for all the candidates weighed, not one per candidate and look."""
HORIZON = 3
"""The unknown things after the next one whose greedy tours the rollout weighs; a thing further on is valued as
the drive to where its belief puts it, with no search (a lower bound of its search). The terms after the next
unknown thing are the same for every candidate, so the horizon changes no choice, only the expected metres said;
a plan of 30 things to fetch (a command of 30 "bring" clauses) made every choice weigh 28 tours from about a
hundred starts each: 18 s a look on the school (rel33)."""
LEVELS = 16
"""The most looks of the first search after which the next thing's tour is planned anew (each with the
nodes seen up to that look taken out of its belief); a look beyond them shares the tour of the one before."""


@dataclass(frozen=True)
class Target:
    """One stop of the remaining plan: an unknown thing (``cls``), or known positions (``at``: nodes, the
    robot goes to the nearest)."""

    cls: str | None = None
    at: tuple[int, ...] = ()


@dataclass(frozen=True)
class Choice:
    """The candidate view to look from next (an index into the candidates), the expected metres to finish
    the plan from here, and the share of each sought class's belief the drive there and its look reveal."""

    view: int
    expected_m: float
    shares: Mapping[str, float]
    costs: Mapping[int, float] = dataclasses.field(default_factory=dict)
    """Every candidate weighed and its expected metres to finish the plan (what :func:`choose` compared)."""
    search: Mapping[int, float] = dataclasses.field(default_factory=dict)
    """Of :attr:`costs`, the expected metres until the thing sought now is reached (the rest is the plan after it)."""
    then: int | None = None
    """The view the chosen one's tour looks from next if the thing is not found (None: the tour ends there): what a
    look that reveals little is worth, when it is on the way to more."""


@dataclass(frozen=True)
class Tour:
    """A search's drives: per node, the metres from the tour's start when it is first seen (inf: never),
    the node it is seen from; the views in order, where the tour ends and its length."""

    seen_at: np.ndarray
    look: np.ndarray
    views: tuple[int, ...]
    end: int
    length: float

    def cost(self, distance: np.ndarray) -> np.ndarray:
        """Per node, the metres until a thing there is reached: seen, then driven to; a node the tour
        never sees is driven to after it."""
        out = np.empty(len(self.seen_at))
        seen = np.isfinite(self.seen_at)
        idx = np.flatnonzero(seen)
        out[idx] = self.seen_at[idx] + distance[self.look[idx], idx]
        rest = np.flatnonzero(~seen)
        out[rest] = self.length + distance[self.end, rest]
        return out


Tables = Callable[[int], DriveTable]
"""The drives from a node to every candidate view (:meth:`~seal_cli.sim.policies.views.Lattice.drive_table`)."""


def greedy_tour(tables: Tables, nodes: Sequence[int], belief: np.ndarray, start: int, *,
                first: int | None = None) -> Tour:
    """The greedy search for one thing from node ``start``: each next view (an index into the candidate
    ``nodes``) the one whose drive and look reveal the most of ``belief`` not yet seen per metre;
    ``first``: the view to start with, whatever the rule says. The rule never takes the view it is at."""
    n = len(belief)
    seen_at = np.full(n, np.inf)
    look = np.full(n, -1, dtype=np.int64)
    total = float(belief.sum())
    left = total
    at, elapsed = start, 0.0
    views: list[int] = []
    seen = np.zeros(n, dtype=bool)
    while len(views) < MAX_TOUR and total > 0 and left > SPENT * total:
        table = tables(at)
        if first is not None and not views:
            v = first
        else:
            mass = table.reveals @ np.where(seen, 0.0, belief)
            score = np.where(np.isfinite(table.length), mass / (table.per_metre + SCALE), -1.0)
            for k in (i for i, node in enumerate(nodes) if node == at):
                score[k] = -1.0
            v = int(np.argmax(score))
            if score[v] <= 0 or mass[v] <= 0:
                break
        row = np.isfinite(table.seen_at[v]) & ~seen
        seen_at[row] = elapsed + table.seen_at[v, row]
        look[row] = table.look[v, row]
        seen |= row
        left -= float(belief[row].sum())
        elapsed += float(table.length[v])
        at = int(nodes[v])
        views.append(v)
    return Tour(seen_at, look, tuple(views), at, elapsed)


def choose(tables: Tables, nodes: Sequence[int], distance: np.ndarray, beliefs: Mapping[str, np.ndarray],
           targets: Sequence[Target], *, start: int, allowed: Sequence[int], prefer: int | None = None,
           tie: float = 0.0, by_context: bool = False) -> Choice | None:
    """The one-step rollout of the module's model: the candidate view (of ``allowed``, indices into
    ``nodes``) to look from next. ``beliefs[cls]``: per node, the belief that the thing of class ``cls``
    is there (unnormalised). ``targets``: the remaining plan's stops in order, the first unknown (the
    thing sought now). ``prefer``: a candidate taken if its expected cost is within ``tie`` metres of the
    best (what the model cannot tell apart: its paths run on a lattice). None when it has no belief
    left, or no candidate reveals any of it."""
    if not targets or targets[0].cls is None:
        return None
    sought = targets[0].cls
    reachable = np.isfinite(distance[start])     # belief where the robot cannot go is no use to it
    q = {c: np.where(np.isfinite(b) & (b > 0) & reachable, b, 0.0) for c, b in beliefs.items()}
    q = {c: b / b.sum() for c, b in q.items() if b.sum() > 0}
    if sought not in q:
        return None
    here = tables(start)
    reveal = np.isfinite(here.seen_at)
    share = {c: reveal.astype(float) @ b for c, b in q.items()}
    options = [v for v in allowed if np.isfinite(here.length[v]) and share[sought][v] > 0]
    if not options:
        return None
    q1 = q[sought]
    rest = targets[1:]
    later = _Later(tables, nodes, distance, q, rest)
    sample = quantiles(q1, SAMPLES)
    support = np.flatnonzero(q1 > 0)
    best: tuple[float, int] | None = None
    costs: dict[int, float] = {}
    search: dict[int, float] = {}
    for v in options:
        tour = greedy_tour(tables, nodes, q1, start, first=v)
        expected = search[v] = float(q1[support] @ tour.cost(distance)[support])
        if rest:
            expected += float(later.after(tour, sample).mean())
        costs[v] = expected
        if best is None or expected < best[0]:
            best = (expected, v)
    assert best is not None
    if prefer is not None and prefer in costs:
        if costs[prefer] <= best[0] + tie:
            best = (costs[prefer], prefer)
        elif by_context:
            after = {k: costs[k] - search[k] for k in costs}
            better = [(costs[k], k) for k in costs
                      if costs[k] < costs[prefer] - tie and after[k] < after[prefer] - tie]
            best = min(better) if better else (costs[prefer], prefer)
    expected, v = best
    views = greedy_tour(tables, nodes, q1, start, first=v).views
    return Choice(v, expected, {c: float(share[c][v]) for c in q}, costs, search,
                  views[1] if len(views) > 1 else None)


def quantiles(belief: np.ndarray, k: int) -> np.ndarray:
    """``k`` nodes standing for a belief, each with weight 1/k: the nodes at the quantiles (i + 1/2)/k of its
    cumulative mass, in node order (systematic sampling, with no random draw; a node may come twice)."""
    cumulative = np.cumsum(belief / belief.sum())
    index = np.searchsorted(cumulative, (np.arange(k) + 0.5) / k)
    return np.asarray(np.minimum(index, len(belief) - 1), dtype=np.intp)


class _Later:
    """The expected cost of the plan's stops after the thing sought now (see the module docstring)."""

    def __init__(self, tables: Tables, nodes: Sequence[int], distance: np.ndarray, q: Mapping[str, np.ndarray],
                 stops: Sequence[Target]) -> None:
        self.tables, self.nodes, self.distance, self.q, self.stops = tables, nodes, distance, q, list(stops)
        self.tours: dict[tuple[str, int, tuple[tuple[int, ...], float] | None], np.ndarray] = {}
        views = np.asarray(nodes)
        self.anchor = views[np.argmin(distance[:, views], axis=1)]
        """Per node, the candidate view nearest to it, where a search from there starts."""
        self.samples = {c: quantiles(b, SAMPLES) for c, b in q.items()}
        self._heads: dict[bytes, tuple[list[np.ndarray], np.ndarray, int | None]] = {}
        self._tail: list[float] | None = None

    def _tour(self, cls: str, anchor: int, seen: tuple[Tour, float] | None = None) -> np.ndarray:
        """Per node, the metres to reach a thing of ``cls`` there by its greedy tour from view node ``anchor``;
        ``seen``: a first tour and the metres of it driven, whose looks so far saw none of it (the tour is
        planned with the belief without the nodes they saw)."""
        belief = self.q[cls]
        if seen is not None:
            kept = np.where(seen[0].seen_at <= seen[1], 0.0, belief)
            if kept.sum() > 0 and belief.sum() - kept.sum() >= SLIGHT * belief.sum():
                belief = kept
            else:          # the looks saw (next to) none of it: the tour planned without them, shared
                seen = None
        key = (cls, anchor, None if seen is None else (seen[0].views, seen[1]))
        if key not in self.tours:
            self.tours[key] = greedy_tour(self.tables, self.nodes, belief, anchor).cost(self.distance)
        return self.tours[key]

    def _search(self, cls: str, starts: np.ndarray, w: np.ndarray, tour: Tour | None = None,
                levels: np.ndarray | None = None) -> np.ndarray:
        """(len(starts), len(w)): the metres from each start to reach a thing of ``cls`` at each node of ``w``:
        to the start's nearest view, then that view's greedy tour (``levels``: per start, the metres of the
        first ``tour`` driven when it found the first thing, whose looks so far are taken out of the belief)."""
        anchors = self.anchor[starts]
        out = np.empty((len(starts), len(w)))
        keys = np.zeros(len(starts)) if levels is None else levels
        for a, level in {(int(a), float(k)) for a, k in zip(anchors, keys, strict=True)}:
            rows = np.flatnonzero((anchors == a) & (keys == level))
            seen = None if tour is None else (tour, level)
            out[rows] = self.distance[starts[rows], a][:, None] + self._tour(cls, a, seen)[w][None, :]
        return out

    @staticmethod
    def _levels(tour: Tour, found_at: np.ndarray) -> np.ndarray:
        """Per node of ``found_at``, the metres of ``tour`` driven at the look that finds it (the looks
        beyond the first :data:`LEVELS` grouped with the one before them; never seen: the whole tour)."""
        at = np.where(np.isfinite(tour.seen_at[found_at]), tour.seen_at[found_at], tour.length)
        marks = np.unique(at)
        if len(marks) > LEVELS:
            keep = marks[np.linspace(0, len(marks) - 1, LEVELS).round().astype(int)]
            at = keep[np.searchsorted(keep, at, side="right") - 1]
        return np.asarray(at, dtype=float)

    def after(self, tour: Tour, found_at: np.ndarray) -> np.ndarray:
        """For the thing sought now found at each node of ``found_at`` by ``tour``: the expected metres of
        the rest of the plan from there. Only the next unknown thing's term depends on ``tour``: the known stops
        before it (:meth:`_head`) and every stop after it (:meth:`_tail`) are the same for every candidate
        weighed, so they are reckoned once per choice and added in the same order (the same sums to the last bit)."""
        head, rows, first = self._head(found_at)
        cost = np.zeros(len(found_at))
        for term in head:
            cost += term
        if first is None:
            return cost
        stop = self.stops[first]
        assert stop.cls is not None
        w = self.samples[stop.cls]
        # the next unknown thing: seen on the drive before the first was found, or searched for from there
        before = tour.seen_at[w][None, :] <= tour.seen_at[found_at][:, None]
        direct = self.distance[np.ix_(rows, w)]
        search = self._search(stop.cls, rows, w, tour, self._levels(tour, found_at))
        cost += np.where(before, direct, search).mean(axis=1)
        for value in self._tail_terms(first):
            cost += value
        return cost

    def _head(self, found_at: np.ndarray) -> tuple[list[np.ndarray], np.ndarray, int | None]:
        """The known stops before the next unknown thing: each one's metres per node of ``found_at``, where each
        row then stands, and the index of that unknown stop (None: no unknown thing is left)."""
        key = found_at.tobytes()
        if key not in self._heads:
            terms: list[np.ndarray] = []
            rows = found_at.copy()   # each row's own position, until an unknown thing is reached
            first = None
            for index, stop in enumerate(self.stops):
                if stop.cls is None:
                    at = np.asarray(stop.at, dtype=np.intp)
                    if len(at):
                        gap = self.distance[np.ix_(rows, at)]
                        terms.append(gap.min(axis=1))
                        rows = at[np.argmin(gap, axis=1)]
                elif stop.cls in self.q:
                    first = index
                    break
            self._heads[key] = (terms, rows, first)
        return self._heads[key]

    def _tail_terms(self, first: int) -> list[float]:
        """The expected metres of each stop after the unknown one at ``first``, from a spread over where that thing
        was (its belief's samples): the same for every row and every candidate."""
        if self._tail is None:
            terms: list[float] = []
            cls = self.stops[first].cls
            assert cls is not None
            spread: np.ndarray = np.bincount(self.samples[cls], minlength=len(self.distance)) / len(self.samples[cls])
            searched = 0
            for stop in self.stops[first + 1:]:
                if stop.cls is None:
                    at = np.asarray(stop.at, dtype=np.intp)
                    if not len(at):
                        continue
                    gap = self.distance[:, at]
                    terms.append(float(spread @ gap.min(axis=1)))
                    spread = np.bincount(at[np.argmin(gap, axis=1)], weights=spread, minlength=len(spread))
                    continue
                if stop.cls not in self.q:
                    continue
                w = self.samples[stop.cls]
                starts = np.flatnonzero(spread > 0)
                if searched < HORIZON:
                    terms.append(float(spread[starts] @ self._search(stop.cls, starts, w).mean(axis=1)))
                    searched += 1
                else:     # past the horizon: the drive to where it is, no search (a lower bound of its cost)
                    terms.append(float(spread[starts] @ self.distance[np.ix_(starts, w)].mean(axis=1)))
                spread = np.bincount(w, minlength=len(self.distance)) / len(w)
            self._tail = terms
        return self._tail
