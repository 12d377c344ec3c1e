"""Where a robot can drive, and how far it is: shortest paths on a grid of free cells.

A :class:`Grid` is a boolean mask of free cells laid on the plane: cell ``(i, j)`` (row ``i``
along +y, column ``j`` along +x) has its centre at ``origin + (j, i) * resolution``. ALFRED's
scenes give such a grid directly (the agent's 0.25 m reachable positions); a seal map gives it
from its occupancy image, with the robot's radius taken off the free space (:meth:`Grid.from_map`).
It is the one model of where the robot drives: the simulator drives on it, and planning ranks
places by it (:mod:`seal_cli.maps.reach`), so the place planning calls nearest is the one the
robot reaches soonest.

Moves go to the 4 or 8 neighbouring free cells (a diagonal costs √2 cells, and may not cut a
corner). :func:`astar` finds one shortest path; :meth:`Grid.distances` gives the length of the
shortest path from one cell to every cell at once (Dijkstra, in C through scipy), which is what
choosing among many viewpoints needs. Lengths are in metres.
"""

from __future__ import annotations

import heapq
import math
from collections.abc import Iterable, Sequence
from dataclasses import dataclass, field
from functools import cached_property
from typing import TYPE_CHECKING

import numpy as np

from seal_cli.errors import SealError

if TYPE_CHECKING:
    from seal_cli.maps.model import Map

ROBOT_RADIUS = 0.2
"""Metres the robot's body reaches from its centre: the free space it drives on keeps this far from walls."""

CACHE_BYTES = 64 * 2**20
"""The most bytes of shortest-path fields a grid keeps (at most 256 of them): about 50 on the apartment, 5 on a
grid of a million cells (256 of 12 MB each took the memory of a run past 1 GB there)."""

__all__ = ["ROBOT_RADIUS", "Cell", "Grid", "astar", "path_length"]

Cell = tuple[int, int]

_STEPS4: tuple[tuple[int, int, float], ...] = ((1, 0, 1.0), (-1, 0, 1.0), (0, 1, 1.0), (0, -1, 1.0))
_STEPS8: tuple[tuple[int, int, float], ...] = _STEPS4 + tuple((di, dj, math.sqrt(2.0))
                                                             for di in (1, -1) for dj in (1, -1))


@dataclass(frozen=True, eq=False)
class Grid:
    """Free cells on the plane, and the moves between them."""

    free: np.ndarray
    origin: tuple[float, float]
    resolution: float
    connectivity: int = 8
    _cache: dict[Cell, tuple[np.ndarray, np.ndarray]] = field(default_factory=dict, repr=False)

    def __post_init__(self) -> None:
        if self.free.ndim != 2 or self.free.dtype != bool:
            raise SealError("a navigation grid needs a 2-D boolean mask of free cells")
        if self.resolution <= 0:
            raise SealError(f"grid resolution must be positive, not {self.resolution}")
        if self.connectivity not in (4, 8):
            raise SealError(f"grid connectivity must be 4 or 8, not {self.connectivity}")

    @classmethod
    def from_points(cls, points: Iterable[Sequence[float]], resolution: float, connectivity: int = 4,
                    margin: int = 1) -> Grid:
        """The grid whose free cells are the given points (ALFRED's reachable positions)."""
        pts = np.asarray([(float(p[0]), float(p[1])) for p in points], dtype=float)
        if not len(pts):
            raise SealError("a navigation grid needs at least one free point")
        low = pts.min(axis=0) - margin * resolution
        idx = np.rint((pts - low) / resolution).astype(int)
        shape = (int(idx[:, 1].max()) + 1 + margin, int(idx[:, 0].max()) + 1 + margin)
        free = np.zeros(shape, dtype=bool)
        free[idx[:, 1], idx[:, 0]] = True
        return cls(free, (float(low[0]), float(low[1])), resolution, connectivity)

    @classmethod
    def from_map(cls, m: Map, robot_radius: float = ROBOT_RADIUS) -> Grid:
        """The cells of a map's grid the robot's centre may stand on: its free cells, less those within
        ``robot_radius`` of an obstacle (all of them when that would leave none), centred on the map's cells."""
        from scipy.ndimage import binary_erosion

        free = np.asarray(m.grid.free_mask, dtype=bool)
        cells = max(0, int(math.ceil(robot_radius / m.grid.resolution)) - 1)
        kept = binary_erosion(free, iterations=cells) if cells else free
        res = m.grid.resolution
        centre = (m.grid.origin[0] + res / 2, m.grid.origin[1] + res / 2)
        return cls((kept if kept.any() else free).astype(bool), centre, res, 8)

    @property
    def shape(self) -> tuple[int, int]:
        return (int(self.free.shape[0]), int(self.free.shape[1]))

    # -- cells and points -------------------------------------------------------------------

    def cell(self, point: Sequence[float]) -> Cell:
        """The cell whose square holds the point (it may be outside the grid or occupied)."""
        return (int(round((point[1] - self.origin[1]) / self.resolution)),
                int(round((point[0] - self.origin[0]) / self.resolution)))

    def point(self, cell: Cell) -> tuple[float, float]:
        """The centre of a cell."""
        return (self.origin[0] + cell[1] * self.resolution, self.origin[1] + cell[0] * self.resolution)

    def inside(self, cell: Cell) -> bool:
        return 0 <= cell[0] < self.free.shape[0] and 0 <= cell[1] < self.free.shape[1]

    def is_free(self, cell: Cell) -> bool:
        return self.inside(cell) and bool(self.free[cell])

    @cached_property
    def free_cells(self) -> np.ndarray:
        """Every free cell as rows of ``(i, j)``."""
        return np.argwhere(self.free)

    @cached_property
    def free_points(self) -> np.ndarray:
        """The centres of the free cells, rows of ``(x, y)``, in the order of :attr:`free_cells`."""
        cells = self.free_cells
        return np.column_stack([self.origin[0] + cells[:, 1] * self.resolution,
                                self.origin[1] + cells[:, 0] * self.resolution])

    def nearest_free(self, point: Sequence[float]) -> Cell:
        """The free cell whose centre is nearest the point."""
        pts = self.free_points
        k = int(np.argmin(np.hypot(pts[:, 0] - point[0], pts[:, 1] - point[1])))
        i, j = self.free_cells[k]
        return (int(i), int(j))

    def neighbours(self, cell: Cell) -> Iterable[tuple[Cell, float]]:
        """Free cells one move away, with the move's length in cells."""
        steps = _STEPS4 if self.connectivity == 4 else _STEPS8
        i, j = cell
        for di, dj, cost in steps:
            nxt = (i + di, j + dj)
            if not self.is_free(nxt):
                continue
            if di and dj and not (self.is_free((i + di, j)) and self.is_free((i, j + dj))):
                continue  # no cutting corners
            yield nxt, cost

    # -- distances ---------------------------------------------------------------------------

    @cached_property
    def _graph(self) -> tuple[object, np.ndarray]:
        """The free cells as a sparse graph (scipy), and each cell's node index (-1 if occupied)."""
        from scipy.sparse import coo_matrix

        index = -np.ones(self.free.shape, dtype=np.int32)  # int32: a grid has at most a few million cells
        cells = self.free_cells
        index[cells[:, 0], cells[:, 1]] = np.arange(len(cells))
        rows, cols, costs = [], [], []
        steps = _STEPS4 if self.connectivity == 4 else _STEPS8
        h, w = self.free.shape
        for di, dj, cost in steps:
            ni, nj = cells[:, 0] + di, cells[:, 1] + dj
            ok = (ni >= 0) & (ni < h) & (nj >= 0) & (nj < w)
            ok[ok] &= self.free[ni[ok], nj[ok]]
            if di and dj:
                ok[ok] &= self.free[cells[ok, 0] + di, cells[ok, 1]] & self.free[cells[ok, 0], cells[ok, 1] + dj]
            rows.append(index[cells[ok, 0], cells[ok, 1]])
            cols.append(index[ni[ok], nj[ok]])
            costs.append(np.full(int(ok.sum()), cost))
        n = len(cells)
        graph = coo_matrix((np.concatenate(costs), (np.concatenate(rows), np.concatenate(cols))), shape=(n, n))
        del rows, cols, costs
        return graph.tocsr(), index

    def _dijkstra(self, start: Cell) -> tuple[np.ndarray, np.ndarray]:
        """Distances (metres, per cell) and predecessors (per node) of every shortest path from ``start``."""
        if start in self._cache:
            return self._cache[start]
        from scipy.sparse.csgraph import dijkstra

        if not self.is_free(start):
            raise SealError(f"cell {start} is not free")
        graph, index = self._graph
        along, previous = dijkstra(graph, directed=True, indices=int(index[start]), return_predecessors=True)
        field_ = np.full(self.free.shape, np.inf)
        cells = self.free_cells
        field_[cells[:, 0], cells[:, 1]] = along * self.resolution
        if len(self._cache) >= min(256, max(4, CACHE_BYTES // (field_.nbytes + previous.nbytes))):
            self._cache.clear()
        self._cache[start] = (field_, previous)
        return field_, previous

    def distances(self, start: Cell) -> np.ndarray:
        """Metres of the shortest path from ``start`` to every cell (``inf`` where none, or occupied)."""
        return self._dijkstra(start)[0]

    def distances_from(self, cells: np.ndarray, costs: np.ndarray) -> np.ndarray:
        """Per cell, min over the free ``cells`` (rows of i, j) of each one's ``costs`` plus the metres of the
        shortest path between it and the cell (``inf`` where none, or occupied; everywhere without ``cells``):
        one Dijkstra from a source joined to each of them at its cost (a move costs the same both ways)."""
        from scipy.sparse import csr_matrix, vstack
        from scipy.sparse.csgraph import dijkstra

        field_ = np.full(self.free.shape, np.inf)
        cells = np.asarray(cells, dtype=int).reshape(-1, 2)
        costs = np.asarray(costs, dtype=float).reshape(-1)
        keep = np.isfinite(costs)
        cells, costs = cells[keep], costs[keep]
        if not len(cells):
            return field_
        graph, index = self._graph
        n = graph.shape[0]   # type: ignore[attr-defined]
        nodes = index[cells[:, 0], cells[:, 1]]
        if (nodes < 0).any():
            raise SealError("a source cell is not free")
        source = csr_matrix((costs / self.resolution, (np.zeros(len(nodes), dtype=int), nodes)), shape=(1, n))
        joined = vstack([graph, source]).tocsr()
        joined.resize((n + 1, n + 1))
        along = dijkstra(joined, directed=True, indices=n)[:n]
        free = self.free_cells
        field_[free[:, 0], free[:, 1]] = along * self.resolution
        return field_

    def path(self, start: Cell, goal: Cell) -> list[Cell]:
        """One shortest path, both ends included (from the Dijkstra tree of ``start``; :func:`astar` is
        the reference); an unreachable goal is a SealError."""
        field_, previous = self._dijkstra(start)
        if not self.is_free(goal):
            raise SealError(f"the goal cell {goal} is not free")
        if not np.isfinite(field_[goal]):
            raise SealError(f"no path from {self.point(start)} to {self.point(goal)}")
        _, index = self._graph
        cells = self.free_cells
        node = int(index[goal])
        path = [goal]
        while node != int(index[start]):
            node = int(previous[node])
            path.append((int(cells[node, 0]), int(cells[node, 1])))
        return path[::-1]


def _heuristic(a: Cell, b: Cell, connectivity: int) -> float:
    di, dj = abs(a[0] - b[0]), abs(a[1] - b[1])
    if connectivity == 4:
        return float(di + dj)
    return float(max(di, dj) + (math.sqrt(2.0) - 1.0) * min(di, dj))


def astar(grid: Grid, start: Cell, goal: Cell) -> list[Cell]:
    """A* with the Manhattan (4-connected) or octile (8-connected) distance, which never overestimates."""
    for name, cell in (("start", start), ("goal", goal)):
        if not grid.is_free(cell):
            raise SealError(f"the {name} cell {cell} is not free")
    frontier: list[tuple[float, float, Cell]] = [(_heuristic(start, goal, grid.connectivity), 0.0, start)]
    came: dict[Cell, Cell | None] = {start: None}
    cost: dict[Cell, float] = {start: 0.0}
    while frontier:
        _, g, cell = heapq.heappop(frontier)
        if cell == goal:
            break
        if g > cost[cell]:
            continue
        for nxt, step in grid.neighbours(cell):
            new = g + step
            if new < cost.get(nxt, math.inf) - 1e-12:
                cost[nxt] = new
                came[nxt] = cell
                heapq.heappush(frontier, (new + _heuristic(nxt, goal, grid.connectivity), new, nxt))
    if goal not in came:
        raise SealError(f"no path from {grid.point(start)} to {grid.point(goal)}")
    path = [goal]
    while (prev := came[path[-1]]) is not None:
        path.append(prev)
    return path[::-1]


def path_length(grid: Grid, path: Sequence[Cell]) -> float:
    """Metres along a path of cells."""
    return sum(math.hypot(a[0] - b[0], a[1] - b[1]) for a, b in zip(path, path[1:], strict=False)) * grid.resolution
