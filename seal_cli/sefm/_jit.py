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
