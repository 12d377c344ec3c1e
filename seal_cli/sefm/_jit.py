"""The grid engine's innermost loops as numba-compiled functions (imported only through
:mod:`seal_cli.sefm.compiled`, which falls back to numpy when numba is not installed).

Each one computes what its numpy counterpart computes, in the same order and the same precision —
the same numbers, bit for bit (tests/sefm/test_compiled.py) — in one pass over the particles instead
of a dozen whole-array passes with their temporaries.
"""

from __future__ import annotations

import numba  # type: ignore[import-untyped, unused-ignore]
import numpy as np


@numba.njit(cache=True, nogil=True)  # type: ignore[untyped-decorator, unused-ignore]
def read(grids, origin_x, origin_y, inverse_cell, top_u, top_v, sources, coef, points, out):
    """``out[r, q] = Σ_s coef[r, s] · bilinear(grids[sources[r, s]], points[r, q])`` (sources −1: no term),
    for float32 grids, coef and out: the numpy reads of ``GridKernelSums.combine``."""
    R, Q = points.shape[0], points.shape[1]
    S = sources.shape[1]
    for r in range(R):
        for q in range(Q):
            u = (points[r, q, 0] - origin_x) * inverse_cell
            v = (points[r, q, 1] - origin_y) * inverse_cell
            u = min(max(u, 0.0), top_u)
            v = min(max(v, 0.0), top_v)
            i = int(u)
            j = int(v)
            fu32 = np.float32(u - i)  # the offsets in float64, then as the float32 grids
            fv32 = np.float32(v - j)
            acc = np.float32(0.0)
            for s in range(S):
                source = sources[r, s]
                if source < 0:
                    continue
                a = grids[source, i, j]
                b = grids[source, i + 1, j]
                c = grids[source, i, j + 1]
                d = grids[source, i + 1, j + 1]
                a = a + (b - a) * fu32
                c = c + (d - c) * fu32
                a = a + (c - a) * fv32
                acc += a * coef[r, s]
            out[r, q] = acc


@numba.njit(cache=True, nogil=True)  # type: ignore[untyped-decorator, unused-ignore]
def bin_corners(base, ny, fu, fv, weights, mass):
    """Linear binning into ``mass`` (flat, zeros): the four corners' shares added corner after corner,
    as ``np.bincount`` adds them from the index ``GridKernelSums._bin`` builds."""
    n = base.shape[0]
    for corner in range(4):
        offset = (ny if corner == 1 or corner == 3 else 0) + (1 if corner >= 2 else 0)
        for p in range(n):
            a = fu[p] if corner == 1 or corner == 3 else 1 - fu[p]
            b = fv[p] if corner >= 2 else 1 - fv[p]
            mass[base[p] + offset] += a * b * weights[p]


@numba.njit(cache=True, nogil=True)  # type: ignore[untyped-decorator, unused-ignore]
def systematic(weights, u, count, ancestors):
    """:func:`seal_cli.sefm.resampling.systematic` for rows whose sums are positive and finite; False
    (``ancestors`` not filled) when some row's is not."""
    rows, size = weights.shape
    for r in range(rows):
        total = _row_total(weights, r)  # the row's cumulative sum at its end, added in the same order
        if not (total > 0 and total < np.inf):
            return False
    for r in range(rows):
        scale = count / _row_total(weights, r)
        running = 0.0
        below = 0
        filled = 0
        for k in range(size):
            running += weights[r, k]
            edge = running * scale if k < size - 1 else float(count)
            drawn = int(np.ceil(edge - u[r]))
            for _ in range(drawn - below):
                ancestors[r, filled] = k
                filled += 1
            below = drawn
    return True


@numba.njit(cache=True, nogil=True)  # type: ignore[untyped-decorator, unused-ignore]
def _row_total(weights, r):
    total = 0.0
    for k in range(weights.shape[1]):
        total += weights[r, k]
    return total


@numba.njit(cache=True, nogil=True)  # type: ignore[untyped-decorator, unused-ignore]
def bin_points(positions, origin_x, origin_y, inverse_cell, top_u, top_v, weights, ny, mass):
    """``GridKernelSums._cells`` then ``_bin`` of rows of points (R, P, 2) with weights (R, P) into the stack
    ``mass`` (flat, zeros; row r's grid starts at ``r · nx · ny``): the same numbers, with no array between."""
    rows, P = weights.shape
    cells = mass.shape[0] // rows
    for corner in range(4):
        offset = (ny if corner == 1 or corner == 3 else 0) + (1 if corner >= 2 else 0)
        for r in range(rows):
            for p in range(P):
                u = min(max((positions[r, p, 0] - origin_x) * inverse_cell, 0.0), top_u)
                v = min(max((positions[r, p, 1] - origin_y) * inverse_cell, 0.0), top_v)
                i = int(u)
                j = int(v)
                fu = u - i
                fv = v - j
                a = fu if corner == 1 or corner == 3 else 1 - fu
                b = fv if corner >= 2 else 1 - fv
                mass[r * cells + i * ny + j + offset] += a * b * weights[r, p]


@numba.njit(cache=True, nogil=True)  # type: ignore[untyped-decorator, unused-ignore]
def order_keys(table, cells, out):
    """``table[cells + 1] · width + position`` for rows of cells (R, width): ``cell_order.order_of_cells``'s keys."""
    rows, width = cells.shape
    for r in range(rows):
        for k in range(width):
            out[r, k] = table[cells[r, k] + 1] * width + k


@numba.njit(cache=True, nogil=True)  # type: ignore[untyped-decorator, unused-ignore]
def positions_of(keys, out):
    """The positions the sorted keys (R, width) carry (each key modulo the width)."""
    rows, width = keys.shape
    for r in range(rows):
        for k in range(width):
            out[r, k] = keys[r, k] % width


@numba.njit(cache=True, nogil=True)  # type: ignore[untyped-decorator, unused-ignore]
def gather_rows(values, order, out):
    """``out[r, k] = values[r, order[r, k]]``."""
    rows, width = order.shape
    for r in range(rows):
        for k in range(width):
            out[r, k] = values[r, order[r, k]]


@numba.njit(cache=True, nogil=True)  # type: ignore[untyped-decorator, unused-ignore]
def gather_resampled(order, chosen, X, cells, gamma, X_out, cells_out, gamma_out, ancestors, copies):
    """What resampling keeps: draw k of row r is particle ``order[r, chosen[r, k]]`` of the row, with its
    position, free cell and γ; a draw equal to the one before it is a copy."""
    rows, count = chosen.shape
    for r in range(rows):
        for k in range(count):
            a = order[r, chosen[r, k]]
            ancestors[r, k] = a
            X_out[r, k, 0] = X[r, a, 0]
            X_out[r, k, 1] = X[r, a, 1]
            cells_out[r, k] = cells[r, a]
            gamma_out[r, k] = gamma[r, a]
            copies[r, k] = k > 0 and chosen[r, k] == chosen[r, k - 1]


@numba.njit(cache=True, nogil=True)  # type: ignore[untyped-decorator, unused-ignore]
def draw_in_rows(weights, row, points, particle):
    """For each query n, the particle of row ``row[n]`` whose cumulative share (plus the row's number) first
    exceeds ``points[n]`` — ``np.searchsorted`` over ``FrameBeliefs._near_elements``' flat cdf of every row,
    clipped into the row — with only the rows asked about summed."""
    S, P = weights.shape
    used = np.zeros(S, np.bool_)
    for n in range(row.shape[0]):
        used[row[n]] = True
    cdf = np.empty((S, P))
    for r in range(S):
        if used[r]:
            total = _row_total(weights, r)
            running = 0.0
            for k in range(P):
                running += weights[r, k]
                cdf[r, k] = running / total + r
    for n in range(row.shape[0]):
        k = np.searchsorted(cdf[row[n]], points[n], side="right")
        particle[n] = min(max(k, 0), P - 1)


@numba.njit(cache=True, nogil=True)  # type: ignore[untyped-decorator, unused-ignore]
def assemble(X, fresh_X, cells, fresh_cells, gamma, last_gamma, fresh_gamma, Z, W, P, fresh_weights,
             X_out, cells_out, gamma_out, weights_out):
    """The carried particles then the fresh draws of each row, with their γ and weights: the carried ones
    weigh ``Ẑ · W · P · γ / γ_last`` (0 where γ_last is not positive), as ``FrameBeliefs.update`` forms them."""
    rows, carried = W.shape
    fresh = fresh_weights.shape[1]
    for r in range(rows):
        for k in range(carried):
            X_out[r, k, 0] = X[r, k, 0]
            X_out[r, k, 1] = X[r, k, 1]
            cells_out[r, k] = cells[r, k]
            gamma_out[r, k] = gamma[r, k]
            ratio = gamma[r, k] / last_gamma[r, k] if last_gamma[r, k] > 0 else 0.0
            weights_out[r, k] = Z[r] * W[r, k] * P * ratio
        for k in range(fresh):
            X_out[r, carried + k, 0] = fresh_X[r, k, 0]
            X_out[r, carried + k, 1] = fresh_X[r, k, 1]
            cells_out[r, carried + k] = fresh_cells[r, k]
            gamma_out[r, carried + k] = fresh_gamma[r, k]
            weights_out[r, carried + k] = fresh_weights[r, k]


@numba.njit(cache=True, nogil=True)  # type: ignore[untyped-decorator, unused-ignore]
def within(points, x, y, reach2, out):
    """The indices of the points (N, 2) within ``√reach2`` of (x, y), in order, into ``out``; how many."""
    n = 0
    for k in range(points.shape[0]):
        dx = points[k, 0] - x
        dy = points[k, 1] - y
        if dx * dx + dy * dy <= reach2:
            out[n] = k
            n += 1
    return n


@numba.njit(cache=True, nogil=True)  # type: ignore[untyped-decorator, unused-ignore]
def gamma(measurement, context, floor, positive, has, c0, free, out):
    """``FrameBeliefs.gamma_of`` then zero off free space, for float32 potentials: the measurement (as
    float64) plus the row's floor, 1 where the row has no element; times ``c0 + context`` (in float32)
    where the row has context."""
    rows, Q = measurement.shape
    for r in range(rows):
        for q in range(Q):
            if not free[r, q]:
                out[r, q] = 0.0
                continue
            value = np.float64(measurement[r, q]) + floor[r] if positive[r] else 1.0
            if has[r]:
                value *= np.float64(c0 + context[r, q])
            out[r, q] = value


def warm() -> None:
    """Call every loop once on tiny arrays of the types the engine passes, so that each is compiled (or read
    from numba's cache on disk) now, when the kernels are first asked for, not inside a timed update."""
    f8, f4, ip = np.float64, np.float32, np.intp

    def frozen(a: np.ndarray) -> np.ndarray:  # read-only arrays are a type of their own to numba
        a.setflags(write=False)
        return a

    grids = np.zeros((1, 3, 3), f4)
    read(grids, 0.0, 0.0, 1.0, 1.0, 1.0, np.zeros((1, 1), ip), np.ones((1, 1), f4), np.zeros((1, 1, 2)),
         np.empty((1, 1), f4))
    for spread in (np.ones(1), frozen(np.ones(1))):  # (broadcast weights are read-only)
        bin_corners(np.zeros(1, ip), 3, np.zeros(1), np.zeros(1), spread, np.zeros(9))
    bin_points(np.zeros((1, 1, 2)), 0.0, 0.0, 1.0, 1.0, 1.0, np.ones((1, 1)), 3, np.zeros(9))
    systematic(np.ones((1, 2)), np.zeros((1, 1))[:, 0], 2, np.empty((1, 2), ip))
    for key in (np.int32, np.int64):
        keys = np.empty((1, 1), key)
        order_keys(frozen(np.zeros(2, key)), np.zeros((1, 1), ip), keys)  # (the cached table is read-only)
        positions_of(keys, np.empty((1, 1), ip))
    gather_rows(np.zeros((1, 1)), np.zeros((1, 1), ip), np.empty((1, 1)))
    gather_resampled(np.zeros((1, 1), ip), np.zeros((1, 1), ip), np.zeros((1, 1, 2)), np.zeros((1, 1), ip),
                     np.zeros((1, 1)), np.empty((1, 1, 2)), np.empty((1, 1), ip), np.empty((1, 1)),
                     np.empty((1, 1), ip),
                     np.empty((1, 1), np.bool_))
    draw_in_rows(np.ones((1, 1)), np.zeros(1, ip), np.zeros(1), np.empty(1, ip))
    assemble(np.zeros((1, 1, 2)), np.zeros((1, 1, 2)), np.zeros((1, 1), ip), np.zeros((1, 1), ip), np.zeros((1, 1)),
             np.zeros((1, 1)), np.zeros((1, 1)), np.ones(1), np.ones((1, 1)), 1, np.zeros((1, 1)),
             np.empty((1, 2, 2)), np.empty((1, 2), ip), np.empty((1, 2)), np.empty((1, 2)))
    within(np.zeros((1, 2)), 0.0, 0.0, 1.0, np.empty(1, ip))
    for free in (np.ones((1, 1), np.bool_), frozen(np.ones((1, 1), np.bool_))):  # (a broadcast mask is read-only)
        gamma(np.zeros((1, 1), f4), np.zeros((1, 1), f4), np.zeros(1), np.ones(1, np.bool_), np.ones(1, np.bool_),
              f4(1.0), free, np.empty((1, 1), f8))
