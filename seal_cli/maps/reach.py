"""How far a robot drives from a point to each of some places: shortest paths over a map's free cells.

It ranks places the command does not tell apart ("put the guitar on the bed" in a house with four beds: the
nearest the robot can drive to, :mod:`seal_cli.planning.grounding`). The map's grid is coarsened to at most
:data:`CELLS` cells (a wall stays closed: :func:`~seal_cli.maps.geometry.coarsened`); moves go to the 8
neighbouring free cells (a diagonal costs √2 cells); a place is reached at any free cell within its ``reach`` of
it (its nearest free cell when none is); the start is its nearest free cell. Unlike the simulator's navigation
(:mod:`seal_cli.sim.navigation`) it does not take the robot's radius off the free space: it ranks places, it does
not plan a drive. A place no free cell joins to the start is ``inf`` away.
"""

from __future__ import annotations

import math
from collections.abc import Sequence

import numpy as np
from numpy.typing import NDArray

from seal_cli.maps.geometry import FREE, coarsened
from seal_cli.maps.model import Map

__all__ = ["CELLS", "drive_lengths"]

CELLS = 120_000
"""The most cells the ranking searches (a 24 m x 12 m house at 0.05 m is 115,200: it keeps its own cells)."""

MOVES = ((0, 1, 1.0), (1, 0, 1.0), (1, 1, math.sqrt(2)), (1, -1, math.sqrt(2)))
"""Half the 8 moves (the graph is undirected): (rows, columns, length in cells)."""


def drive_lengths(m: Map, start: Sequence[float], places: Sequence[str]) -> list[float]:
    """The length (m) of the shortest drive from ``start`` (x, y) to each named place of ``m``; inf if none."""
    from scipy.sparse import coo_matrix
    from scipy.sparse.csgraph import dijkstra

    free, size, origin = _free_cells(m)
    index = -np.ones(free.shape, dtype=np.intp)
    index[free] = np.arange(int(free.sum()))
    if not free.any():
        return [math.inf] * len(places)
    heads, tails, lengths = [], [], []
    for dr, dc, length in MOVES:
        a, b = _shifted(index, dr, dc)
        both = (a >= 0) & (b >= 0)
        heads.append(a[both])
        tails.append(b[both])
        lengths.append(np.full(int(both.sum()), length * size))
    n = int(free.sum())
    graph = coo_matrix((np.concatenate(lengths), (np.concatenate(heads), np.concatenate(tails))), shape=(n, n))
    centres = _centres(free, size, origin)
    first = int(np.argmin(np.hypot(*(centres - np.asarray(start[:2], dtype=float)).T)))
    field = dijkstra(graph.tocsr(), directed=False, indices=first)
    return [_to_place(m, name, centres, field) for name in places]


def _free_cells(m: Map) -> tuple[NDArray[np.bool_], float, NDArray[np.float64]]:
    """The free mask (row 0 at the lowest y), the cell size and the world point of cell (0, 0)'s corner."""
    cells = m.grid.cells
    factor = max(1, math.ceil(math.sqrt(cells.size / CELLS)))
    return coarsened(cells, factor) == FREE, m.grid.resolution * factor, np.asarray(m.grid.origin[:2], dtype=float)


def _shifted(index: NDArray[np.intp], dr: int, dc: int) -> tuple[NDArray[np.intp], NDArray[np.intp]]:
    """The cell ids of every pair (cell, cell moved by dr rows and dc columns) inside the grid."""
    h, w = index.shape
    rows = slice(0, h - dr)
    a = index[rows, max(0, -dc):w - max(0, dc)]
    b = index[dr:h, max(0, dc):w - max(0, -dc)]
    return a.ravel(), b.ravel()


def _centres(free: NDArray[np.bool_], size: float, origin: NDArray[np.float64]) -> NDArray[np.float64]:
    rows, cols = np.nonzero(free)
    return origin + (np.column_stack([cols, rows]) + 0.5) * size


def _to_place(m: Map, name: str, centres: NDArray[np.float64], field: NDArray[np.float64]) -> float:
    place = m.place(name)
    if place is None:
        return math.inf
    away = np.hypot(*(centres - np.asarray(place.at, dtype=float)).T)
    near = away <= place.reach
    return float(field[near].min() if near.any() else field[int(np.argmin(away))])
