"""The order in which SeFM lists particles: room by room, and within a room along a Hilbert curve.

Systematic resampling and stratified draws give every contiguous run of a list its share of the
draws to within one (:mod:`seal_cli.sefm.resampling`). So the order particles are listed in decides
which parts of the map keep their share of a belief exactly:

- listed **room by room**, each room keeps its share (200 particles do not misstate a 50/50 prior
  as 57/43);
- listed, within a room, **along a Hilbert curve** over the map's cells, each compact patch of the
  room keeps its share too: a run of consecutive cells on the curve is a blob, not a strip. The
  part of a room the robot has looked at then holds its share of the particles to within a few,
  and so does what negative information leaves of the room. Gerber and Chopin's sequential
  quasi-Monte Carlo orders particles by the same curve for the same reason.

``rank`` is each free cell's position in that order (cached per map); particles off free space
(objects may stand on furniture) come first.
"""

from __future__ import annotations

from functools import lru_cache

import numpy as np
from numpy.typing import NDArray

from seal_cli.maps.model import Map
from seal_cli.sefm import compiled

__all__ = ["by_room", "hilbert_index", "order_of_cells", "order_of_points", "rank"]

Index = NDArray[np.intp]


def hilbert_index(i: NDArray[np.integer], j: NDArray[np.integer], bits: int) -> NDArray[np.int64]:
    """The position of cell (i, j) on the Hilbert curve through a 2^bits × 2^bits grid."""
    x, y = np.asarray(i, np.int64).copy(), np.asarray(j, np.int64).copy()
    d = np.zeros(x.shape, np.int64)
    s = 1 << (bits - 1)
    while s > 0:
        rx, ry = (x & s) > 0, (y & s) > 0
        d += s * s * ((3 * rx.astype(np.int64)) ^ ry.astype(np.int64))
        flip = ~ry & rx
        x = np.where(flip, s - 1 - x, x)
        y = np.where(flip, s - 1 - y, y)
        x, y = np.where(~ry, y, x), np.where(~ry, x, y)
        s >>= 1
    return d


@lru_cache(maxsize=8)
def rank(m: Map) -> Index:
    """Each free cell's position when the free cells are listed room by room (no room first), and
    within a room along the Hilbert curve through the map's grid."""
    rows, cols = m.grid.cell_index(m.free_centres)[:2]
    bits = max(1, int(np.ceil(np.log2(max(m.grid.shape)))))
    key = (m.free_cell_room.astype(np.int64) + 1) << (2 * bits)
    key += hilbert_index(rows, cols, bits)
    out = np.empty(len(key), np.intp)
    out[np.argsort(key, kind="stable")] = np.arange(len(key))
    out.setflags(write=False)
    return out


def order_of_cells(m: Map, cells: Index) -> Index:
    """A permutation of each row of free cell indices (-1: off free space) that lists them in order.

    The stable sort of each row's ranks, done as a plain sort of ``(rank + 1) · width + position``:
    the keys are then distinct and the ties of a rank fall in position order, so the positions come
    out exactly as a stable argsort lists them, about six times faster (a sort of 32-bit integers
    when they fit, vectorised; an argsort is neither)."""
    cells = np.asarray(cells)
    ranks = rank(m)
    width = cells.shape[-1] if cells.ndim else 1
    dtype = np.int32 if (len(ranks) + 1) * max(width, 1) + width < 2**31 else np.int64
    jit = compiled.kernels()
    if jit is not None and cells.ndim and width and cells.dtype.kind == "i":  # the same keys, in one pass each way
        rows = cells.reshape(-1, width)
        unique = np.empty(rows.shape, dtype)
        jit.order_keys(_keys(m, dtype), rows, unique)
        unique.sort(axis=-1)
        out = np.empty(rows.shape, np.intp)
        jit.positions_of(unique, out)
        return out.reshape(cells.shape)
    key = _keys(m, dtype)[cells + 1]  # rank + 1, and 0 off free space (-1)
    step = np.asarray(width, dtype)
    unique = np.add(np.multiply(key, step), np.arange(width, dtype=dtype))
    return np.asarray(np.remainder(np.sort(unique, axis=-1), step), np.intp)


@lru_cache(maxsize=8)
def _keys(m: Map, dtype: type) -> NDArray[np.integer]:
    """0, then each free cell's rank + 1: the sort key of a free cell index + 1 (-1, off free space, gives 0)."""
    out: NDArray[np.integer] = np.concatenate([[0], rank(m) + 1]).astype(dtype)
    out.setflags(write=False)
    return out


def order_of_points(m: Map, X: NDArray[np.float64]) -> Index:
    """A permutation of each row of points X (R, P, 2) that lists them in order."""
    cells = m.free_index(X.reshape(-1, 2)).reshape(X.shape[:-1]).astype(np.intp)
    return order_of_cells(m, cells)


@lru_cache(maxsize=8)
def by_room(m: Map) -> tuple[Index, Index]:
    """The free cells in order, and where each room's run starts (``-1``, no room, first): room r's
    cells are ``cells[starts[r + 1]:starts[r + 2]]``."""
    cells = np.argsort(rank(m), kind="stable")
    rooms = m.free_cell_room[cells] + 1
    return cells, np.searchsorted(rooms, np.arange(len(m.rooms) + 2))
