"""How far a robot drives from a point to each of some places, on the free space the simulator drives on.

It ranks places the command does not tell apart ("put the guitar on the bed" in a house with four beds: the
nearest the robot can drive to, :mod:`seal_cli.planning.grounding`). The paths are the simulator's own
(:meth:`Grid.from_map <seal_cli.maps.navigation.Grid.from_map>`: the map's free cells less the robot's radius, 8
moves that cut no corner), so the place ranked nearest is the one the robot reaches soonest. A place is reached at
any free cell within its ``reach`` of it, those in a clear line of sight of it when there are any (where the robot
stands to act on it: ``Agent.stand_cell``); the start is its own cell, or the nearest free one. A place no such
cell joins to the start is ``inf`` away.
"""

from __future__ import annotations

import math
from collections.abc import Sequence

import numpy as np

from seal_cli.maps.geometry import lines_of_sight
from seal_cli.maps.model import Map
from seal_cli.maps.navigation import Grid

__all__ = ["drive_lengths", "grid_of"]

_GRIDS: list[tuple[Map, Grid]] = []
"""The last map's grid (building its graph is most of the cost: a planner asks for one map many times)."""


def grid_of(m: Map) -> Grid:
    """The simulator's free-space grid of a map, built once for the last map asked about."""
    if not _GRIDS or _GRIDS[0][0] is not m:
        _GRIDS[:] = [(m, Grid.from_map(m))]
    return _GRIDS[0][1]


def drive_lengths(m: Map, start: Sequence[float], places: Sequence[str]) -> list[float]:
    """The length (m) of the shortest drive from ``start`` (x, y) to within reach of each named place of ``m``;
    inf if none."""
    grid = grid_of(m)
    if not grid.free.any():
        return [math.inf] * len(places)
    cell = grid.cell(start)
    field = grid.distances(cell if grid.is_free(cell) else grid.nearest_free(start))
    return [_to_place(m, grid, name, field) for name in places]


def _to_place(m: Map, grid: Grid, name: str, field: np.ndarray) -> float:
    place = m.place(name)
    if place is None:
        return math.inf
    points = grid.free_points
    near = np.flatnonzero(np.hypot(*(points - np.asarray(place.at, dtype=float)).T) <= place.reach - 1e-6)
    if not len(near):
        return math.inf
    clear = np.asarray(lines_of_sight(m.grid, place.at, points[near]), dtype=bool)
    cells = grid.free_cells[near[clear] if clear.any() else near]
    return float(field[cells[:, 0], cells[:, 1]].min())
