"""The geometry of the view model: a coarse lattice of the free space, what each node of it sees, and
the looks a drive between two nodes takes.

The whole-plan search (:mod:`~seal_cli.sim.policies.completion`) values a view by what the robot sees
*on the way to it and from it*. That needs, for many pairs of cells, the shortest path, the looks
the agent takes along it (one every ``look_every`` metres and one at the end, as
:meth:`~seal_cli.sim.agent.Agent.drive_to` does) and what each look sees. On the robot's own grid
(5 cm cells, 50 000–80 000 of them) that is far too slow, so it is done on a :class:`Lattice`: the
grid's free cells grouped in blocks of about :data:`SPACING` metres, one node per block, linked where
the grid links their cells, with all-pairs shortest paths. A node sees another when the map's sensor
sees the other's point from its point (range and line of sight: the sensor's exact model). Beliefs,
sightings and distances of the search are all on the nodes.

Looks have headings. The look at a view's end sees all round (:meth:`Lattice.visible`): a sensor
narrower than 360° turns on the spot there and looks until it has looked all round
(:meth:`~seal_cli.sim.agent.Agent.look_round`, as the agent does at every view a policy chooses). A
look on the way faces along the drive (:meth:`Lattice.visible_along`: the nodes within half the field
of view of the heading from the path's node before it), as the robot does, which looks every
``look_every`` metres without stopping to turn.

Building a lattice costs a few seconds on the apartment (the all-pairs paths, then one sensor
query per node looked from), so lattices are kept per grid and sensor (:func:`lattice_of`): the runs
of a benchmark on one house share one.
"""

from __future__ import annotations

import hashlib
from collections.abc import Callable, Sequence
from dataclasses import dataclass, field
from functools import cached_property
from typing import Any

import numpy as np

from seal_cli.maps.navigation import Grid

__all__ = ["MAX_NODES", "SPACING", "DriveTable", "Lattice", "lattice_of"]

SPACING = 0.25
"""The lattice's block side in metres (the grid's cells are grouped into blocks of about this size)."""

MAX_NODES = 4096
"""The most nodes a lattice has: its all-pairs distances and predecessors take 8 bytes a pair (16.7 million
pairs, 134 MB, at this bound; built :data:`ROWS_AT_ONCE` sources at a time; the shipped maps have up to 3,300
nodes at :data:`SPACING`). On a larger free space the blocks grow until the nodes fit: "bring me a cup" on an
empty 50 m × 50 m map (40,000 nodes of 0.25 m) took more than 19 GB before."""

ROWS_AT_ONCE = 256
"""Sources of the lattice's all-pairs shortest paths computed at once: scipy returns float64 distances and
predecessors for each, kept as float32 and int32; computed whole, the 4,096-node lattice's transient was
4,096² × 12 bytes (201 MB) on top of the 134 MB kept."""


@dataclass(frozen=True)
class DriveTable:
    """What the drives from one node to each of a set of candidate nodes see: ``seen_at[v, z]`` the metres
    driven when node ``z`` is first seen on the drive to candidate ``v`` (inf: not seen), ``look[v, z]``
    the node it is first seen from, ``length[v]`` the drive's metres."""

    seen_at: np.ndarray
    look: np.ndarray
    length: np.ndarray

    @cached_property
    def reveals(self) -> np.ndarray:
        """``reveals[v, z]`` 1.0 where the drive to candidate ``v`` sees node ``z``, else 0.0 (kept: a greedy
        tour weighs every candidate's drive by it at each of its steps)."""
        return np.isfinite(self.seen_at).astype(float)

    @cached_property
    def per_metre(self) -> np.ndarray:
        """Each drive's metres, 0 where there is none (the greedy tour's mass-per-metre rule divides by it)."""
        return np.nan_to_num(self.length, posinf=0.0)

    @property
    def nbytes(self) -> int:
        return int(self.seen_at.nbytes + self.look.nbytes + self.length.nbytes + 2 * self.seen_at.size * 4)


ALONG_BYTES = 64 * 2**20
"""The most bytes of a lattice's kept :meth:`Lattice.visible_along` masks (a node and a heading each, one byte a
node): a sensor that does not see all round made every drive table cut each look's view to its heading again, 685,000
times in 60 steps of 28 "bring" clauses on the school, 67 s of their 200 (rel33)."""


@dataclass(eq=False)
class Lattice:
    """A coarse graph of a grid's free space (see the module docstring)."""

    points: np.ndarray
    """(N, 2) each node's point (its block's free cell nearest the block's centre)."""
    cells: np.ndarray
    """(N, 2) that cell of the grid."""
    distance: np.ndarray = field(repr=False)
    """(N, N) shortest-path metres between nodes (inf: not connected)."""
    previous: np.ndarray = field(repr=False)
    """(N, N) predecessors of the all-pairs shortest paths (scipy's convention, -9999 for none)."""
    sees: Callable[[tuple[float, float], np.ndarray], np.ndarray] = field(repr=False)
    """The sensor: which of some points a look from a point sees."""
    range: float
    look_every: float = 1.0
    fov: float = 2 * np.pi
    """The sensor's field of view (radians): what a look on the way sees (:meth:`visible_along`)."""
    _seen: dict[int, np.ndarray] = field(default_factory=dict, repr=False)
    _along: dict[tuple[int, float], np.ndarray] = field(default_factory=dict, repr=False)
    """:meth:`visible_along`'s answers, the last :data:`ALONG_BYTES` of them."""
    kept: dict[Any, Any] = field(default_factory=dict, repr=False)
    """What the users of a lattice derive from it alone and keep with it (the whole-plan search's
    regions and candidate views, by the places known)."""

    @property
    def size(self) -> int:
        return len(self.points)

    def node_of(self, points: np.ndarray) -> np.ndarray:
        """The nearest node of each point."""
        from scipy.spatial import cKDTree

        tree = getattr(self, "_tree", None)
        if tree is None:
            tree = cKDTree(self.points)
            self._tree = tree
        _, index = tree.query(np.asarray(points, dtype=float).reshape(-1, 2))
        return np.asarray(index, dtype=np.intp)

    def visible(self, node: int) -> np.ndarray:
        """The nodes a look from ``node`` sees (a bool mask, kept)."""
        out = self._seen.get(node)
        if out is None:
            x, y = self.points[node]
            near = np.flatnonzero(np.hypot(self.points[:, 0] - x, self.points[:, 1] - y) <= self.range)
            out = np.zeros(self.size, dtype=bool)
            if len(near):
                out[near[np.asarray(self.sees((float(x), float(y)), self.points[near]), dtype=bool)]] = True
            out[node] = True
            self._seen[node] = out
        return out

    def visible_along(self, node: int, heading: float) -> np.ndarray:
        """The nodes a look from ``node`` facing ``heading`` (radians) sees: those :meth:`visible` all round
        within half the field of view of the heading (all of them for a sensor that sees all round)."""
        around = self.visible(node)
        if self.fov >= 2 * np.pi - 1e-9:
            return around
        found = self._along.get((node, heading))
        if found is not None:
            return found
        out = around.copy()
        others = np.flatnonzero(around)
        others = others[others != node]
        if len(others):
            d = self.points[others] - self.points[node]
            off = np.abs((np.arctan2(d[:, 1], d[:, 0]) - heading + np.pi) % (2 * np.pi) - np.pi)
            out[others[off > self.fov / 2 + 1e-9]] = False
        if len(self._along) * self.size >= ALONG_BYTES:     # the oldest dropped: a drive's looks face few headings
            del self._along[next(iter(self._along))]
        self._along[(node, heading)] = out
        return out

    def path(self, a: int, b: int) -> list[int]:
        """The nodes of a shortest path from ``a`` to ``b``, both included ([] if none)."""
        if a == b:
            return [a]
        if not np.isfinite(self.distance[a, b]):
            return []
        out = [b]
        while out[-1] != a:
            out.append(int(self.previous[a, out[-1]]))
        return out[::-1]

    def looks(self, a: int, b: int) -> tuple[list[int], list[float]]:
        """The looks of a drive from ``a`` to ``b``: the nodes looked from (one every :attr:`look_every`
        metres and the end) and the metres driven at each."""
        nodes, metres, _ = self.looks_facing(a, b)
        return nodes, metres

    def looks_facing(self, a: int, b: int) -> tuple[list[int], list[float], list[float]]:
        """:meth:`looks`, with each look's heading (radians): the direction from the path's node before it."""
        nodes = self.path(a, b)
        if len(nodes) < 2:
            return [], [], []
        out, metres, headings = [], [], []
        along, since = 0.0, 0.0
        for u, v in zip(nodes, nodes[1:], strict=False):
            step = float(self.distance[u, v])
            along += step
            since += step
            if since >= self.look_every and v != nodes[-1]:
                out.append(v)
                metres.append(along)
                headings.append(self._heading(u, v))
                since = 0.0
        out.append(nodes[-1])
        metres.append(along)
        headings.append(self._heading(nodes[-2], nodes[-1]))
        return out, metres, headings

    def _heading(self, u: int, v: int) -> float:
        dx, dy = self.points[v] - self.points[u]
        return float(np.arctan2(dy, dx))

    def drive_table(self, origin: int, candidates: Sequence[int], reveals: Sequence[np.ndarray | None],
                    hidden: np.ndarray, stale: np.ndarray | None = None) -> DriveTable:
        """The drives from ``origin`` to each candidate (see :class:`DriveTable`). A look does not see
        ``hidden`` nodes (in a shut receptacle); a look on the way sees what it faces (:meth:`visible_along`),
        the look at the end of the drive to candidate ``v`` sees all round (the robot turns round at a view)
        and also ``reveals[v]`` (what opening a receptacle there shows). ``stale`` (a bool per node): a look
        from such a node tells the beliefs nothing (a view they have used already: SeFM counts a miss once
        per view), so it reveals nothing — unless it opens a receptacle (``reveals[v]``): with other places shut
        it is a view of its own, and sees as any other."""
        k, n = len(candidates), self.size
        seen_at = np.full((k, n), np.inf, dtype=np.float32)
        look = np.full((k, n), -1, dtype=np.int32)
        length = np.full(k, np.inf)
        for v, target in enumerate(candidates):
            masks: list[tuple[int, float, np.ndarray | None, float | None]]
            nodes, metres, headings = self.looks_facing(origin, int(target))
            if not nodes:
                if origin == target:
                    length[v] = 0.0
                    masks = [(origin, 0.0, reveals[v], None)]
                else:
                    continue
            else:
                length[v] = metres[-1]
                masks = [(u, m, None, h) for u, m, h in zip(nodes, metres, headings, strict=True)]
                masks[-1] = (masks[-1][0], masks[-1][1], reveals[v], None)
            row, at = seen_at[v], look[v]
            for u, m, extra, heading in masks:
                if stale is not None and stale[u] and extra is None:
                    continue
                fresh = (self.visible(u) if heading is None else self.visible_along(u, heading)) & ~hidden
                if extra is not None:
                    fresh = fresh | extra
                fresh &= ~np.isfinite(row)
                row[fresh] = m
                at[fresh] = u
        return DriveTable(seen_at, look, length)


_LATTICES: dict[bytes, Lattice] = {}
"""Lattices by grid and sensor (the last few), shared by the runs of one process on one house."""


def lattice_of(grid: Grid, sees: Callable[[tuple[float, float], np.ndarray], np.ndarray], sensor_key: str,
               reach: float, look_every: float = 1.0, fov: float = 2 * np.pi) -> Lattice:
    """The lattice of a grid's free space with a sensor (``sees`` all round, ``reach`` its range, ``fov`` its
    field of view in radians; ``sensor_key`` names the sensor and the map whose walls cut its view), built
    once per grid and sensor."""
    key = hashlib.blake2b(np.packbits(grid.free).tobytes() + repr((grid.shape, grid.resolution, sensor_key,
                                                                   reach, look_every, fov)).encode()).digest()
    found = _LATTICES.get(key)
    if found is not None:
        return found
    from scipy.sparse import coo_matrix
    from scipy.sparse.csgraph import dijkstra

    cells = grid.free_cells
    side = max(1, int(np.ceil(SPACING / grid.resolution - 1e-9)))
    while True:
        blocks = cells // side
        width = int(blocks[:, 1].max()) + 1
        block_id = blocks[:, 0] * width + blocks[:, 1]
        unique, node_of_cell = np.unique(block_id, return_inverse=True)
        if len(unique) <= MAX_NODES:
            break
        side = max(side + 1, int(side * np.sqrt(len(unique) / MAX_NODES)))
    centre = (np.stack([unique // width, unique % width], axis=1) + 0.5) * side - 0.5
    gap = np.hypot(*(cells - centre[node_of_cell]).T)
    order = np.lexsort((gap, node_of_cell))
    first = order[np.r_[0, np.flatnonzero(np.diff(node_of_cell[order])) + 1]]
    rep_cells = cells[first]
    points = np.asarray([grid.point((int(i), int(j))) for i, j in rep_cells], dtype=float)
    graph, _ = grid._graph
    coo = graph.tocoo()  # type: ignore[attr-defined]
    a, b = node_of_cell[coo.row], node_of_cell[coo.col]
    keep = a != b
    pairs = np.unique(np.stack([a[keep], b[keep]], axis=1), axis=0)
    weight = np.hypot(*(points[pairs[:, 0]] - points[pairs[:, 1]]).T)
    n = len(points)
    coarse = coo_matrix((weight, (pairs[:, 0], pairs[:, 1])), shape=(n, n)).tocsr()
    distance = np.empty((n, n), dtype=np.float32)
    previous = np.empty((n, n), dtype=np.int32)
    for start in range(0, n, ROWS_AT_ONCE):  # a band of sources at a time: scipy's float64 rows never all at once
        rows = np.arange(start, min(n, start + ROWS_AT_ONCE))
        distance[rows], previous[rows] = dijkstra(coarse, directed=False, indices=rows, return_predecessors=True)
    lattice = Lattice(points, rep_cells, distance, previous, sees, reach, look_every, min(float(fov), 2 * np.pi))
    if len(_LATTICES) >= 4:
        _LATTICES.pop(next(iter(_LATTICES)))
    _LATTICES[key] = lattice
    return lattice

