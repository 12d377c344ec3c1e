"""The robot's side of :mod:`~seal_cli.sim.policies.completion`: the candidate views of its map, the
remaining plan as targets, and the view that minimises the expected drive to finish.

:class:`WholePlanSearch` is shared by the policies that search for the whole remaining plan: SeFM
(its beliefs) and ``prior_optimal`` (the map's priors with exact negative evidence). Each gives a
weight per free cell of the map for each class sought; the rest — the lattice the search runs on
(:mod:`~seal_cli.sim.policies.views`), the candidate views, the plan's targets, the narration — is here.

The candidate views (a modest set, about ten per room): each room's cells that see most of it
(:func:`regions_of`, up to :data:`ROOM_VIEWS` of them), every place's stand cell nearest to it (a
shut one opened from there), and both sides of every doorway (the lattice's nodes of two rooms
that touch, grouped into doors :data:`DOOR_GAP` metres apart), so that a peek through a door is a
view of its own. What the drives between them see on the way is counted by the model itself.
"""

from __future__ import annotations

import hashlib
from collections.abc import Callable, Mapping
from dataclasses import dataclass, field

import numpy as np

from seal_cli.frames.model import Binding
from seal_cli.frames.taxonomy import class_key
from seal_cli.maps.navigation import Cell
from seal_cli.maps.priors import target_cells
from seal_cli.sim.agent import Agent, View
from seal_cli.sim.policies.completion import Choice, Target, choose
from seal_cli.sim.policies.views import SPACING, DriveTable, Lattice, lattice_of

__all__ = ["ADDED_VIEWS", "COVER_SAMPLE", "DOOR_GAP", "MORE_VIEWS", "ROOM_VIEWS", "UNCOVERED", "Candidate", "Region",
           "WholePlanSearch", "cells_in_sight"]

ROOM_VIEWS = 4
"""The most views of a room among the candidates (its best-seeing cells, the best first)."""
DOOR_GAP = 1.5
"""Metres between two touching stretches of a pair of rooms for them to be two doors."""
UNCOVERED = 0.01
"""The share of a belief the candidates may leave unseen before views are added (:meth:`WholePlanSearch._cover`)."""
MORE_VIEWS = 3
"""The most views added at one choice."""
ADDED_VIEWS = 4 * MORE_VIEWS
"""The most views added over a run (the candidates are then fixed: every drive table, and every step of every
greedy tour, weighs each candidate, so their number bounds the cost of a choice)."""
COVER_SAMPLE = 40
"""Nodes tried for each added view (drawn by the belief no candidate sees)."""


@dataclass(frozen=True, eq=False)
class Region:
    """A room (its free space, seen from its best-seeing cells) or a place (``place`` set), whose views
    are candidates of the search."""

    name: str
    view: Cell
    look_at: tuple[float, float]
    cells: np.ndarray = field(repr=False)
    """Indices into the map's free cells."""
    place: str | None = None
    views: tuple[Cell, ...] = ()
    """Cells that see about as much of the region as :attr:`view` does (a room's), the best first."""


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
class Candidate:
    """A view the search may take: a cell of the robot's grid, its lattice node, what to face, the
    room (or place) it is named by, and the shut place it opens (None: just looks)."""

    cell: Cell
    node: int
    look_at: tuple[float, float]
    name: str
    open: str | None = None


@dataclass(frozen=True)
class Decision:
    """A view chosen for the whole remaining plan, and why."""

    view: View
    candidate: Candidate
    expected_m: float
    costs: Mapping[tuple[Cell, str | None], float] = field(default_factory=dict)
    """Every candidate weighed (by its cell and the place it opens) and its expected metres to finish."""

    def regret(self, view: View) -> float:
        """The expected metres lost by looking from ``view`` rather than from this decision's (inf: not weighed)."""
        return self.costs.get((view.cell, view.open), float("inf")) - self.expected_m


TABLE_BYTES = 128 * 2**20
"""The most bytes of drive tables one search keeps (one per node it plans from: candidates × lattice nodes × 8
bytes, 116 MB on a 4,096-node lattice with 3,500 candidates, and as much again for the reveals a greedy tour
weighs by, counted in :attr:`DriveTable.nbytes`; about 3 MB on an empty 50 m floor, where a run plans from a
hundred nodes and kept 300 MB); past it those used longest ago are dropped."""


class WholePlanSearch:
    """The candidate views of one run's map, and the choice of the next one to look from."""

    def __init__(self, agent: Agent, places_only: bool = False) -> None:
        m = agent.scene.map
        self.map = m
        sensor = agent.world.sensor
        self.lattice: Lattice = lattice_of(agent.grid, lambda p, pts: sensor.line_of_sight(p, pts),   # all round
                                           f"{m.name}|{m.bounds}|{m.sensor!r}", sensor.range, agent.look_every,
                                           np.radians(sensor.spec.fov_deg))
        known = tuple(sorted((k.id, k.cls, k.at, k.openable) for k in agent.known.values() if not k.movable))
        kept = self.lattice.kept.get((places_only, known))
        if kept is None:   # the same for every run on one house: kept with its lattice
            self.regions = regions_of(agent, places_only)
            kept = self.lattice.kept[(places_only, known)] = (self.regions, tuple(self._candidates(agent)))
        self.regions = kept[0]
        self.candidates = list(kept[1])
        self.nodes = [c.node for c in self.candidates]
        self.belief_node = self.lattice.node_of(m.free_centres)
        """Per free cell of the map, its lattice node (beliefs are summed onto the nodes)."""
        self.used: set[Cell] = set()
        """Candidate cells looked from (never chosen again)."""
        self.pending: Cell | None = None
        """The view chosen last, until the robot looks from there (a drive that stops short leaves it unused)."""
        self._tables: dict[tuple[int, tuple[frozenset[str], bytes | None]], DriveTable] = {}
        self._covered: np.ndarray | None = None
        self.added = 0
        """Views :meth:`_cover` has added (at most :data:`ADDED_VIEWS`)."""
        self._table_bytes = 0
        """Nodes some candidate's look sees."""
        self.seen = np.zeros(len(m.free_centres), dtype=bool)
        """Free cells the sensor has seen (in range and in line of sight, up to its fan of rays)."""

    def _candidates(self, agent: Agent) -> list[Candidate]:
        m = self.map
        lattice = self.lattice
        out: dict[Cell, Candidate] = {}

        def add(cell: Cell, look_at: tuple[float, float], name: str, open_: str | None = None) -> None:
            if cell not in out or open_ is not None:
                node = int(lattice.node_of(np.asarray([agent.grid.point(cell)]))[0])
                out[cell] = Candidate(cell, node, look_at, name, open_)

        for region in self.regions:
            if region.place is None:
                for cell in (region.view, *region.views)[:ROOM_VIEWS]:
                    add(cell, agent.grid.point(cell), region.name)
        for place in m.places:
            known = agent.known.get(place.name)
            if known is None or known.movable:
                continue
            stands = agent.stand_cells(known)
            if not len(stands):
                continue
            pts = np.asarray([agent.grid.point((int(i), int(j))) for i, j in stands])
            k = int(np.argmin(np.hypot(pts[:, 0] - known.at[0], pts[:, 1] - known.at[1])))
            add((int(stands[k, 0]), int(stands[k, 1])), known.at, place.name,
                place.name if known.openable else None)
        for node in self._doorways():
            cell = (int(lattice.cells[node, 0]), int(lattice.cells[node, 1]))
            if agent.grid.is_free(cell):
                room = self._room_of(np.asarray([lattice.points[node]]))[0]
                add(cell, agent.grid.point(cell), m.rooms[room].name if room >= 0 else "the doorway")
        return list(out.values())

    def _room_of(self, points: np.ndarray) -> np.ndarray:
        out = np.full(len(points), -1, dtype=np.intp)
        for r, room in enumerate(self.map.rooms):
            inside = np.asarray(room.contains(points), dtype=bool) & (out < 0)
            out[inside] = r
        return out

    def _doorways(self) -> list[int]:
        """Both sides of every door: for each pair of rooms whose nodes touch, the touching stretches grouped
        into doors :data:`DOOR_GAP` apart, and on each side of each door the node nearest its middle."""
        from scipy.spatial import cKDTree

        lattice = self.lattice
        room = self._room_of(lattice.points)
        step = float(np.min(lattice.distance[lattice.distance > 0])) if lattice.size > 1 else 0.0
        pairs = cKDTree(lattice.points).query_pairs(step * 1.5, output_type="ndarray")
        if not len(pairs):
            return []
        a, b = pairs[:, 0], pairs[:, 1]
        touch = (room[a] >= 0) & (room[b] >= 0) & (room[a] != room[b]) & \
            np.isclose(lattice.distance[a, b], np.hypot(*(lattice.points[a] - lattice.points[b]).T), atol=1e-3)
        out: list[int] = []
        by_pair: dict[tuple[int, int], list[tuple[int, int]]] = {}
        for u, v in pairs[touch]:
            key = (int(min(room[u], room[v])), int(max(room[u], room[v])))
            by_pair.setdefault(key, []).append((int(u), int(v)))
        for links in by_pair.values():
            mids = np.asarray([(lattice.points[u] + lattice.points[v]) / 2 for u, v in links])
            door = np.full(len(links), -1)
            for k in range(len(links)):
                if door[k] < 0:
                    near = np.hypot(*(mids - mids[k]).T) <= DOOR_GAP
                    door[near & (door < 0)] = k
            for d in np.unique(door):
                members = np.flatnonzero(door == d)
                centre = mids[members].mean(axis=0)
                for side in (0, 1):
                    ends = np.asarray([links[k][side] for k in members])
                    out.append(int(ends[np.argmin(np.hypot(*(lattice.points[ends] - centre).T))]))
        return out

    def observe(self, agent: Agent, see: bool = True) -> np.ndarray:
        """The robot has looked: the free cells it saw (indices, returned, and added to :attr:`seen`; none
        when not ``see``: a searcher with beliefs of its own, SeFM, needs only the views used); the view
        chosen last is used once the robot has looked from it."""
        if self.pending is not None and agent.robot_cell() == self.pending:
            self.used.add(self.pending)
            self.pending = None
        return self.see(agent, agent.world.robot.pose) if see else np.zeros(0, dtype=np.intp)

    def see(self, agent: Agent, pose: tuple[float, float, float]) -> np.ndarray:
        """The free cells the sensor sees from ``pose`` (indices), added to :attr:`seen`."""
        near = cells_in_sight(agent, pose)
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

    def _shut(self, agent: Agent) -> dict[str, np.ndarray]:
        """The shut receptacles the robot knows of and the lattice nodes a thing in each would be at (within
        its reach, the nearest such receptacle's)."""
        points = self.lattice.points
        best = np.full(len(points), np.inf)
        owner = np.full(len(points), -1)
        names: list[str] = []
        for known in agent.known.values():
            if known.movable or not known.openable or known.id in agent.opened or agent.world.items[known.id].is_open:
                continue
            where = self.map.place(known.id)
            reach = where.reach if where is not None else agent.world.reach
            d = np.hypot(points[:, 0] - known.at[0], points[:, 1] - known.at[1])
            closer = (d <= reach + 0.25) & (d < best)
            owner[closer], best[closer] = len(names), d[closer]
            names.append(known.id)
        return {name: owner == k for k, name in enumerate(names)}

    def _cover(self, agent: Agent, beliefs: dict[str, np.ndarray], stale: np.ndarray | None = None) -> None:
        """Add views until the candidates' looks see all but :data:`UNCOVERED` of each belief (at most
        :data:`MORE_VIEWS` of them each time): each the node, of a sample of those near the belief no
        candidate sees, that sees most of it (a room its views see only part of, a short-range sensor).
        ``stale``: nodes whose looks tell the beliefs nothing (:meth:`choose`): a candidate there covers
        nothing, and no view is added there."""
        lattice = self.lattice
        if self._covered is None:
            self._covered = np.zeros(lattice.size, dtype=bool)
            for node in self.nodes:
                self._covered |= lattice.visible(node)
        covered = self._covered
        if stale is not None and stale.any():
            covered = np.zeros(lattice.size, dtype=bool)
            for node in self.nodes:
                if not stale[node]:
                    covered |= lattice.visible(node)
        for _ in range(MORE_VIEWS):
            if self.added >= ADDED_VIEWS:
                break
            left = {c: float(b[~covered].sum() / b.sum()) for c, b in beliefs.items() if b.sum() > 0}
            if not left or max(left.values()) <= UNCOVERED:
                break
            weight = sum((b / b.sum() for b in beliefs.values() if b.sum() > 0), np.zeros(lattice.size))
            weight = np.where(covered, 0.0, weight)
            near = np.flatnonzero(weight > 0)
            rng = np.random.default_rng(len(self.nodes))
            pick = near if len(near) <= COVER_SAMPLE else rng.choice(near, COVER_SAMPLE, replace=False,
                                                                     p=weight[near] / weight[near].sum())
            field_ = agent.distances()
            options = [int(k) for k in pick if np.isfinite(field_[tuple(lattice.cells[k])])
                       and (stale is None or not stale[k])]
            if not options:
                break
            gains = {k: float(weight[lattice.visible(k)].sum()) for k in options}
            best = max(options, key=gains.__getitem__)
            if gains[best] < UNCOVERED * float(weight.sum()):   # a look that sees next to nothing (a narrow sensor)
                break
            self.added += 1
            cell = (int(lattice.cells[best, 0]), int(lattice.cells[best, 1]))
            room = self._room_of(lattice.points[best:best + 1])[0]
            self.candidates.append(Candidate(cell, best, agent.grid.point(cell),
                                             self.map.rooms[room].name if room >= 0 else "the open floor"))
            self.nodes.append(best)
            self._covered |= lattice.visible(best)
            if covered is not self._covered:
                covered |= lattice.visible(best)

    def _add(self, agent: Agent, view: View) -> None:
        """A view of another rule (the greedy place view) among the candidates, kept for the run."""
        if any(c.cell == view.cell and c.open == view.open for c in self.candidates):
            return
        node = int(self.lattice.node_of(np.asarray([agent.grid.point(view.cell)]))[0])
        room = self._room_of(self.lattice.points[node:node + 1])[0]
        name = view.open or (self.map.rooms[room].name if room >= 0 else "the open floor")
        self.candidates.append(Candidate(view.cell, node, view.look_at, name, view.open))
        self.nodes.append(node)
        if self._covered is not None:
            self._covered |= self.lattice.visible(node)

    def ahead(self, agent: Agent, view: View) -> list[Cell]:
        """The looks the rest of the drive to ``view`` takes (the lattice's looks from the robot's node to the
        view's, one every ``look_every`` metres, the view's own left out), each added among the candidates for the
        run: driving on is worth at least stopping at any of them to choose again (:meth:`~seal_cli.sim.policies.
        sefm.SeFMPolicy.reconsider`). Their grid cells, in the drive's order."""
        lattice = self.lattice
        start, end = (int(k) for k in lattice.node_of(np.asarray([agent.grid.point(agent.robot_cell()),
                                                                   agent.grid.point(view.cell)])))
        nodes, _ = lattice.looks(start, end)
        out: list[Cell] = []
        for node in nodes[:-1]:
            cell = (int(lattice.cells[node, 0]), int(lattice.cells[node, 1]))
            if cell == view.cell or cell in self.used or not agent.grid.is_free(cell):
                continue
            self._add(agent, View(cell, agent.grid.point(cell)))
            out.append(cell)
        return out

    def _forget_tables(self) -> None:
        """Drop the drive tables used longest ago while they hold more than :data:`TABLE_BYTES` (the last one
        used is always kept); a table dropped is made again if it is asked for."""
        while self._table_bytes > TABLE_BYTES and len(self._tables) > 1:
            self._table_bytes -= self._tables.pop(next(iter(self._tables))).nbytes

    def choose(self, agent: Agent, binding: Binding, target: str,
               weights: Callable[[str], np.ndarray], also: View | None = None,
               by_context: bool = False, stale: np.ndarray | None = None) -> Decision | None:
        """The candidate view that starts the shortest expected completion (:func:`~seal_cli.sim.policies.
        completion.choose`); ``weights(cls)`` is the belief of a class per free cell of the map. ``also``: a
        view another rule would take now (the greedy place view), weighed among the candidates on the same
        footing, so the choice is never worse than it under the model, and taken when the model cannot tell
        it from the best (within the lattice's :data:`~seal_cli.sim.policies.views.SPACING`); ``by_context``: another
        view is taken over ``also`` only where the rest of the plan, too, makes it better (:func:`~seal_cli.sim.
        policies.completion.choose`); ``stale``: a bool per lattice node, where a look tells the beliefs nothing
        (a view they have used already), so the model's looks from there reveal nothing (:meth:`~seal_cli.sim.
        policies.views.Lattice.drive_table`)."""
        stops = self.targets(agent, binding, target)
        sought = list(dict.fromkeys(c for c, v, _ in stops if v is None))
        n = self.lattice.size
        beliefs = {c: np.bincount(self.belief_node, weights=np.where(np.isfinite(w := weights(c)) & (w > 0), w, 0.0),
                                  minlength=n) for c in sought}
        if stale is not None and not stale.any():
            stale = None
        self._cover(agent, beliefs, stale)
        if also is not None:
            self._add(agent, also)
        shut = self._shut(agent)
        hidden = np.zeros(n, dtype=bool)
        for mask in shut.values():
            hidden |= mask
        key = frozenset(shut)
        reveals = [shut.get(c.open) if c.open is not None else None for c in self.candidates]
        lattice = self.lattice

        kind = (key, None if stale is None else hashlib.blake2b(np.packbits(stale).tobytes(), digest_size=16).digest())

        def tables(origin: int) -> DriveTable:   # kept across choices; rows added for candidates added since
            table = self._tables.pop((origin, kind), None)   # taken out and put back: the dict is in order of use
            done = 0 if table is None else len(table.length)
            if done < len(self.nodes):
                more = lattice.drive_table(origin, self.nodes[done:], reveals[done:], hidden, stale)
                if table is not None:
                    self._table_bytes -= table.nbytes
                    table = DriveTable(np.concatenate([table.seen_at, more.seen_at]),
                                       np.concatenate([table.look, more.look]),
                                       np.concatenate([table.length, more.length]))
                else:
                    table = more
                self._table_bytes += table.nbytes
            assert table is not None
            self._tables[(origin, kind)] = table
            self._forget_tables()
            return table

        plan: list[Target] = []
        for c, value, at in stops:
            if value is None:
                plan.append(Target(cls=c))
            else:
                plan.append(Target(at=tuple(int(k) for k in lattice.node_of(
                    np.asarray([agent.grid.point(cell) for cell in at])))))
        here = agent.robot_cell()
        field_ = agent.distances()
        allowed = [k for k, c in enumerate(self.candidates) if c.cell not in self.used and c.cell != here
                   and np.isfinite(field_[c.cell]) and (c.open is None or c.open in shut)]
        start = int(lattice.node_of(np.asarray([agent.grid.point(here)]))[0])
        prefer = next((k for k, c in enumerate(self.candidates) if also is not None and c.cell == also.cell
                       and c.open == also.open), None)
        choice: Choice | None = choose(tables, self.nodes, lattice.distance, beliefs, plan, start=start,
                                       allowed=allowed, prefer=prefer, tie=SPACING,
                                       by_context=by_context)
        if choice is None:
            return None
        candidate = self.candidates[choice.view]
        there = " and ".join(f"{c} {p:.2f}" for c, p in choice.shares.items() if p >= 0.005) or "little of anything"
        then = None if choice.then is None else self.candidates[choice.then].name
        why = (f"{candidate.name}: {there} there, {field_[candidate.cell]:.1f} m "
               f"(expected {choice.expected_m:.1f} m to finish the plan)"
               + (f", {then} next if it is not there" if then is not None and then != candidate.name else ""))
        self.pending = candidate.cell
        costs = {(self.candidates[k].cell, self.candidates[k].open): m for k, m in choice.costs.items()}
        return Decision(View(candidate.cell, candidate.look_at, candidate.open, why), candidate, choice.expected_m,
                        costs)


def cells_in_sight(agent: Agent, pose: tuple[float, float, float]) -> np.ndarray:
    """The map's free cells (indices into ``free_centres``) the robot's sensor sees from ``pose``: within its range
    and inside its region (field of view and line of sight)."""
    centres = agent.scene.map.free_centres
    near = np.flatnonzero(np.hypot(centres[:, 0] - pose[0], centres[:, 1] - pose[1]) <= agent.world.sensor.range)
    if len(near):
        near = near[np.asarray(agent.world.sensor.region(pose).contains(centres[near]), dtype=bool)]
    return near
