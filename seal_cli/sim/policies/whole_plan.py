"""The robot's side of :mod:`~seal_cli.sim.policies.completion`: regions of its map, the remaining plan
as targets, and the view that minimises the expected drive to finish.

:class:`WholePlanSearch` is shared by the policies that search for the whole remaining plan: SeFM
(its beliefs) and ``prior_optimal`` (the map's priors with exact negative evidence). Each gives a
weight per free cell of the map for each class sought; the rest — regions, distances, the plan's
targets, the narration — is here.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass, field

import numpy as np

from seal_cli.frames.model import Binding
from seal_cli.frames.taxonomy import class_key
from seal_cli.maps.priors import target_cells
from seal_cli.sim.agent import Agent, View
from seal_cli.sim.navigation import Cell
from seal_cli.sim.policies.completion import MAX_REGIONS, Choice, Target, solve

__all__ = ["CANDIDATES", "SAMPLE", "Region", "WholePlanSearch"]

CANDIDATES = 80
"""Free cells of a room tried as its view (a fixed sample when the room has more)."""
SAMPLE = 200
"""Points of a region's belief on which a candidate view is scored (drawn by their weight)."""


@dataclass(frozen=True, eq=False)
class Region:
    """Somewhere one view reveals: a place (``place`` set; opened first if shut) or a room's free space."""

    name: str
    view: Cell
    look_at: tuple[float, float]
    cells: np.ndarray = field(repr=False)
    """Indices into the map's free cells."""
    place: str | None = None
    views: tuple[Cell, ...] = ()
    """Cells that see about as much of the region as :attr:`view` does (a room's); the robot looks
    from the one it can reach soonest."""

    def nearest_view(self, field_: np.ndarray) -> Cell:
        """The view the robot reaches soonest, by the shortest-path field from where it is."""
        options = (self.view, *self.views)
        return min(options, key=lambda c: float(field_[c]))


def _room_views(agent: Agent, inside: np.ndarray, room_cells: np.ndarray) -> list[Cell]:
    """Cells of a room (rows of the agent's grid ``inside`` it) that each see at least 0.9 of what the
    best of them sees of the room's free cells within sensor range and line of sight (on a sample
    of both), the best first."""
    if not len(inside):
        return []
    m = agent.scene.map
    points = agent.grid.free_points[inside]
    targets = m.free_centres[room_cells]
    rng = np.random.default_rng(0)
    if len(targets) > 200:
        targets = targets[rng.choice(len(targets), 200, replace=False)]
    candidates = np.arange(len(points))
    if len(candidates) > 80:
        candidates = rng.choice(len(candidates), 80, replace=False)
    reach = m.sensor.range
    counts = []
    for c in candidates:
        x, y = points[c]
        near = np.hypot(targets[:, 0] - x, targets[:, 1] - y) <= reach
        counts.append(int(m.line_of_sight((x, y), targets[near]).sum()) if near.any() else 0)
    order = np.argsort(-np.asarray(counts), kind="stable")
    best = counts[int(order[0])]
    cells = agent.grid.free_cells[inside[candidates[order]]]
    return [(int(i), int(j)) for (i, j), n in zip(cells, np.asarray(counts)[order], strict=True) if n >= 0.9 * best]


def _place_region(agent: Agent, name: str, cells: np.ndarray) -> Region | None:
    """A place as a region of its own, seen from its stand cell nearest to it (None: nowhere to stand)."""
    stands = agent.stand_cells(agent.known[name]) if len(cells) else np.zeros((0, 2), dtype=int)
    if not len(stands):
        return None
    at = agent.known[name].at
    pts = np.asarray([agent.grid.point((int(i), int(j))) for i, j in stands])
    k = int(np.argmin(np.hypot(pts[:, 0] - at[0], pts[:, 1] - at[1])))
    return Region(name, (int(stands[k, 0]), int(stands[k, 1])), at, cells, name)


def regions_of(agent: Agent, places_only: bool = False) -> list[Region]:
    """The rooms of the map, each seen from the cell that sees most of it, with the open places its
    view sees (within sensor range and line of sight) merged in; every other place — shut ones,
    which must be opened, and those no room's view sees — a region of its own, seen from its
    stand cell nearest to it. ``places_only``: every place a region of its own, and no room (a
    single open room whose things all lie in or on its places, as in ALFRED)."""
    m = agent.scene.map
    if places_only:
        return [g for place in m.places if place.name in agent.known
                and (g := _place_region(agent, place.name, target_cells(m, place.name))) is not None]
    out: list[Region] = []
    place_cells = {p.name: target_cells(m, p.name) for p in m.places if p.name in agent.known}
    in_room: dict[int, list[str]] = {}
    views: dict[int, list[Cell]] = {}
    for r, room in enumerate(m.rooms):
        cells = np.flatnonzero(m.free_cell_room == r)
        inside = np.flatnonzero(room.contains(agent.grid.free_points))
        seen_from = _room_views(agent, inside, cells) if len(cells) else []
        if not seen_from:
            continue
        views[r] = seen_from
        at = agent.grid.point(seen_from[0])
        for place in m.places:
            known = agent.known.get(place.name)
            if known is None or known.openable or not room.contains([place.at])[0]:
                continue
            if np.hypot(place.at[0] - at[0], place.at[1] - at[1]) <= m.sensor.range and \
                    bool(m.line_of_sight(at, np.asarray([place.at]))[0]):
                in_room.setdefault(r, []).append(place.name)
    merged = {name for names in in_room.values() for name in names}
    taken = np.zeros(len(m.free_centres), dtype=bool)
    for place in m.places:
        own = place_cells.get(place.name)
        if own is None or not len(own) or place.name in merged:
            continue
        region = _place_region(agent, place.name, own)
        if region is None:
            continue
        out.append(region)
        taken[own] = True
    for r, seen_from in views.items():
        cells = np.flatnonzero((m.free_cell_room == r) & ~taken)
        for name in in_room.get(r, []):
            cells = np.union1d(cells, place_cells[name][~taken[place_cells[name]]])
        out.append(Region(m.rooms[r].name, seen_from[0], agent.grid.point(seen_from[0]), cells,
                          views=tuple(seen_from[1:])))
    return out


@dataclass(frozen=True)
class Decision:
    """A view chosen for the whole remaining plan, and why."""

    view: View
    region: Region
    expected_m: float


class WholePlanSearch:
    """The regions of one run's map, and the choice of the next one to look at."""

    def __init__(self, agent: Agent, places_only: bool = False) -> None:
        self.regions = regions_of(agent, places_only)
        self.map = agent.scene.map
        self.used: set[tuple[str, Cell]] = set()
        """Views looked from, per region (never chosen again for it)."""
        self.pending: tuple[str, Cell] | None = None
        """The region chosen last and its view, until the robot looks from there (a drive that stops
        short, the thing sought seen on the way, leaves it unused)."""
        self.scored: dict[str, tuple[tuple[int, float], list[Cell], list[float]]] = {}
        """Per region, its candidate views' scores, kept while its belief is unchanged."""

        self.seen = np.zeros(len(self.map.free_centres), dtype=bool)
        """Free cells the sensor has seen (in range and in line of sight, up to its fan of rays)."""

    def observe(self, agent: Agent) -> np.ndarray:
        """The robot has looked: the free cells it saw (indices, returned, and added to :attr:`seen`);
        the view chosen last is used once the robot has looked from it."""
        if self.pending is not None and agent.robot_cell() == self.pending[1]:
            self.used.add(self.pending)
            self.pending = None
        return self.see(agent, agent.world.robot.pose)

    def see(self, agent: Agent, pose: tuple[float, float, float]) -> np.ndarray:
        """The free cells the sensor sees from ``pose`` (indices), added to :attr:`seen`."""
        centres = self.map.free_centres
        near = np.flatnonzero(np.hypot(centres[:, 0] - pose[0], centres[:, 1] - pose[1]) <= agent.world.sensor.range)
        if len(near):
            near = near[np.asarray(agent.world.sensor.region(pose).contains(centres[near]), dtype=bool)]
        self.seen[near] = True
        return near

    def targets(self, agent: Agent, binding: Binding, target: str) -> list[tuple[str, str | None, list[Cell]]]:
        """The remaining plan's stops from the thing sought now: (class, None, []) for an unknown
        thing, (class, value, cells to stand at) for a known one. The horizon ends before a second
        thing of a class already sought (the model has one thing per class)."""
        out: list[tuple[str, str | None, list[Cell]]] = []
        first = agent.class_of(target)
        names: dict[str, str] = {first: class_key(target)}
        out.append((first, None, []))
        held = agent.held()
        values: list[str] = []
        started = False
        for step in agent.remaining:
            for action in step.actions:
                if action.name not in ("navigate", "search"):
                    continue
                if not started:
                    if step is binding and class_key(action.args[0]) == class_key(target):
                        started = True
                    continue
                values.append(action.args[0])
        for value in values:
            cls = agent.class_of(value)
            if cls in names and names[cls] != class_key(value):
                break
            if cls in names and names[cls] == class_key(value):
                continue
            names[cls] = class_key(value)
            if held is not None and held.key == cls:
                continue
            room = agent.room(value)
            if room is not None and not agent.instances(cls):
                region = next((g for g in self.regions if g.place is None and g.name == room.name), None)
                if region is not None:
                    out.append((cls, value, [region.view]))
                continue
            usable = [k for k in agent.instances(cls) if not agent.spent(k.id, value)]
            if usable:
                cells = [c for k in usable[:4] if (c := agent.stand_cell(k)) is not None]
                if cells:
                    out.append((cls, value, cells))
                continue
            out.append((cls, None, []))
        return out

    def choose(self, agent: Agent, binding: Binding, target: str,
               weights: Callable[[str], np.ndarray]) -> Decision | None:
        """The region whose view starts the shortest expected completion; ``weights(cls)`` is the
        belief of a class per free cell of the map. Each region is looked at from its view as
        :meth:`fresh_view` finds it now; a region no view would reveal more of is left out."""
        stops = self.targets(agent, binding, target)
        sought = list(dict.fromkeys(c for c, v, _ in stops if v is None))
        belief = {c: weights(c) for c in sought}
        candidates = self.regions
        mass = {c: np.array([float(belief[c][g.cells].sum()) for g in candidates]) for c in sought}
        total = {c: float(belief[c].sum()) for c in sought}
        keep = [i for i in range(len(candidates))
                if any(total[c] > 0 and mass[c][i] / total[c] >= 0.01 for c in sought)]
        here = agent.distances()
        keep = [i for i in keep if np.isfinite(here[candidates[i].nearest_view(here)])]
        keep.sort(key=lambda i: -max(mass[c][i] / total[c] if total[c] > 0 else 0.0 for c in sought))
        unseen = sum((belief[c] / total[c] for c in sought if total[c] > 0), np.zeros(len(self.map.free_centres)))
        views: dict[int, View] = {}
        for i in keep:
            if len(views) == MAX_REGIONS:
                break
            if (view := self.fresh_view(agent, candidates[i], unseen, here)) is not None:
                views[i] = view
        keep = list(views)
        if not keep:
            return None
        regions = [candidates[i] for i in keep]
        cells: list[Cell] = [views[i].cell for i in keep] + [agent.robot_cell()]
        plan: list[Target] = []
        for c, value, at in stops:
            if value is None:
                plan.append(Target(cls=c))
            else:
                plan.append(Target(at=tuple(range(len(cells), len(cells) + len(at)))))
                cells.extend(at)
        distance = np.array([agent.grid.distances(a)[[b[0] for b in cells], [b[1] for b in cells]] for a in cells])
        distance = np.minimum(distance, distance.T)
        choice: Choice | None = solve(distance, {c: mass[c][keep] for c in sought}, plan, start=len(regions),
                                      regions=len(regions))
        if choice is None:
            return None
        region = regions[choice.region]
        view = views[keep[choice.region]]
        shares = {c: float(mass[c][keep][choice.region] / mass[c][keep].sum()) for c in sought
                  if mass[c][keep].sum() > 0}
        there = " and ".join(f"{c} {p:.2f}" for c, p in shares.items() if p >= 0.005) or "little of anything"
        why = (f"{region.name}: {there} there, {here[view.cell]:.1f} m "
               f"(expected {choice.expected_m:.1f} m to finish the plan)")
        self.pending = (region.name, view.cell)
        return Decision(View(view.cell, view.look_at, view.open, why), region, choice.expected_m)

    def fresh_view(self, agent: Agent, region: Region, belief: np.ndarray, field_: np.ndarray) -> View | None:
        """Where to look at a region from now, given ``belief`` (the sought things' beliefs, each
        normalised, summed per free cell): a place not yet looked into, from its nearest stand cell
        (opening it if shut); otherwise the view not yet used for it that sees most of its belief on
        cells not seen yet (on a sample), the nearest by path of those that see at least 0.9 of that;
        None when no view would reveal any of it. So a region stays a candidate while it has belief
        where the robot has not looked, and a room its first view saw only part of is looked at again
        from where the rest is seen. A region whose belief lies only where the robot has looked (a
        detector that may miss) has no fresh view and drops out; that is left to the policy's fallback."""
        if region.place is not None and region.place not in agent.inspected:
            view = self.view_of(agent, region, field_)
            return None if (region.name, view.cell) in self.used else view
        cells = region.cells[(belief[region.cells] > 0) & ~self.seen[region.cells]]
        if not len(cells):
            return None
        w = belief[cells]
        key = (len(cells), round(float(w.sum()), 9))
        cached = self.scored.get(region.name)
        if cached is None or cached[0] != key:
            cached = (key, *self._score(agent, region, cells, w))
            self.scored[region.name] = cached
        _, options, scores = cached
        fresh = [(c, s) for c, s in zip(options, scores, strict=True)
                 if np.isfinite(field_[c]) and (region.name, c) not in self.used]
        best = max((s for _, s in fresh), default=0.0)
        if best <= 0:
            return None
        cell = min((c for c, s in fresh if s >= 0.9 * best), key=lambda c: float(field_[c]))
        return View(cell, region.look_at if region.place is not None else agent.grid.point(cell))

    def _score(self, agent: Agent, region: Region, cells: np.ndarray, w: np.ndarray) -> tuple[list[Cell], list[float]]:
        """Each candidate view of a region and the belief (``w`` on ``cells``) it would see, on a sample
        of :data:`SAMPLE` points drawn by their weight."""
        rng = np.random.default_rng(len(cells))
        targets = self.map.free_centres[cells if len(cells) <= SAMPLE else rng.choice(cells, SAMPLE, p=w / w.sum())]
        weight = w if len(cells) <= SAMPLE else np.full(len(targets), w.sum() / len(targets))
        options = self._candidates(agent, region)
        reach = agent.world.sensor.range
        scores = []
        for c in options:
            x, y = agent.grid.point(c)
            near = np.flatnonzero(np.hypot(targets[:, 0] - x, targets[:, 1] - y) <= reach)
            if len(near):
                near = near[np.asarray(agent.world.sensor.visible((x, y, 0.0), targets[near]), dtype=bool)]
            scores.append(float(weight[near].sum()))
        return options, scores

    def _candidates(self, agent: Agent, region: Region) -> list[Cell]:
        """The cells a region may be looked at from: a place's stand cells; a room's views and a fixed
        sample of :data:`CANDIDATES` of its free cells."""
        if region.place is not None:
            return [(int(i), int(j)) for i, j in agent.stand_cells(agent.known[region.place])]
        room = next(r for r in self.map.rooms if r.name == region.name)
        inside = np.flatnonzero(room.contains(agent.grid.free_points))
        if len(inside) > CANDIDATES:
            inside = np.random.default_rng(0).choice(inside, CANDIDATES, replace=False)
        return [region.view, *region.views, *((int(i), int(j)) for i, j in agent.grid.free_cells[inside])]

    def view_of(self, agent: Agent, region: Region, field_: np.ndarray) -> View:
        """Where to stand for a region: a place from its nearest stand cell (opening it if shut), a room
        from its view."""
        if region.place is not None:
            known = agent.known[region.place]
            cell = agent.stand_cell(known, field_) or region.view
            shut = known.openable and known.id not in agent.opened and not agent.world.items[known.id].is_open
            return View(cell, known.at, open=known.id if shut else None)
        return View(region.nearest_view(field_), region.look_at)
