"""Gaussian kernel sums of weighted particle sets: the numbers inside SeFM's potentials.

The measurement and context potentials of a frame particle at ``x`` are sums, over the
particles ``y_s`` (weights ``w_s``) of an object's or a frame's belief, of a Gaussian kernel
of constant covariance ``Σ = σ² I``::

    K(x) = Σ_s w_s · exp(−|x − y_s|² / 2σ²)

The kernel's peak is 1, so for normalised weights ``K`` lies in [0, 1] and reads as "how much
of the belief lies within about σ of x"; it is ``2πσ²`` times the belief smoothed by the
normal density N(0, Σ).

A :class:`KernelSums` holds a numbered set of *sources* (rows: one per object class and one per
frame) and answers *queries*: weighted sums ``Σ_s w_rs · K_{source_rs}(x)`` of a few sources at
each of many points (:meth:`KernelSums.combine`: a frame's potential is one such sum at each of
its particles), or ``K`` of one source (:meth:`KernelSums.sample`). Two implementations give the
same answer:

:class:`ExactKernelSums`
    the reference: every pair, O(P·Q) per query, formed in chunks so that memory holds at most
    ``chunk`` pairs at a time (it grows with the particles, never with their square).
:class:`GridKernelSums`
    the engine: a source is spread onto a grid of cell ``h`` by linear binning, smoothed with a
    separable Gaussian filter (truncated at 4 standard deviations, zero outside the grid: what
    ``scipy.ndimage.gaussian_filter`` computes, done as two products with banded matrices on one
    BLAS thread) and read back at the queries by bilinear interpolation. Binning and
    interpolation each widen the kernel by a variance of ``h²/6`` per axis, so the filter uses
    ``σ² − h²/3``; at ``h = σ/2`` the normalised weights it gives
    are within a total variation of about 0.005 of the exact ones (``seal bench perf`` measures
    it). Work is O(cells) per changed source and O(1) per query point. A source whose weights
    change at a few particles (negative information in the robot's view) is updated in a
    window around them only: K is linear in the weights.
"""

from __future__ import annotations

import math
from abc import ABC, abstractmethod
from collections.abc import Sequence
from functools import lru_cache
from typing import Any

import numpy as np
from numpy.typing import NDArray

from seal_cli.sefm import compiled

__all__ = ["ExactKernelSums", "GridKernelSums", "KernelSums", "SplitKernelSums", "exact_kernel_sum",
           "make_kernel_sums"]

Array = NDArray[np.float64]
Index = NDArray[np.intp]
Change = tuple[int, Index, Array, Array, float]
"""``(row, particle indices, their positions, weight increments before normalising, the normaliser)``."""
Moved = tuple[Index, Array, Array]
"""Particles put in or taken out of rows: ``(row of each, positions (m, 2), weights (m,))``."""


class KernelSums(ABC):
    """Numbered weighted particle sets and weighted sums of their ``K`` at any points."""

    sigma: float

    @abstractmethod
    def set(self, rows: Sequence[int], positions: Array, weights: Array) -> None:
        """Rows ``rows`` now hold these particle sets: ``positions`` (R, P, 2), normalised ``weights`` (R, P)."""

    def move(self, rows: Sequence[int], positions: Array, weights: Array, gone: Moved, come: Moved) -> None:
        """Rows ``rows`` now hold these particle sets, which differ from what they held by the particles
        ``gone`` and ``come`` (each ``(row, positions (m, 2), weights (m,))``). By default: :meth:`set`."""
        self.set(rows, positions, weights)

    def takes_moves(self, rows: Sequence[int], changed: int) -> bool:
        """Whether :meth:`move` would use the particles that changed (``changed`` of them in all) rather
        than set the rows afresh: if not, there is no need to list them."""
        return False

    @abstractmethod
    def reweight(self, changes: Sequence[Change]) -> None:
        """For each change ``(row, index, positions, delta, total)``: the weights of particles ``index``
        (at ``positions``, (m, 2)) of ``row`` grew by ``delta``; then all were divided by ``total``."""

    @abstractmethod
    def combine(self, sources: Index, weights: Array, points: Array) -> Array:
        """``out[r, q] = Σ_s weights[r, s] · K_{sources[r, s]}(points[r, q])`` for points (R, Q, 2) and
        sources, weights (R, S); a source of −1 is no term. Shape (R, Q)."""

    def versions(self) -> Index | None:
        """A number per row that changes whenever the row's K does (None: not kept, so any row may have)."""
        return None

    def sample(self, which: Index, points: Array, rows: Index | None = None) -> Array:
        """``out[t, q] = K_{which[t]}(points[t, q])`` for points (T, Q, 2): shape (T, Q). With ``rows``
        (T,), points are (R, Q, 2) and query t is at ``points[rows[t]]``."""
        which = np.asarray(which, np.intp)
        at = points if rows is None else points[np.asarray(rows, np.intp)]
        return self.combine(which[:, None], np.ones((len(which), 1)), at)


def exact_kernel_sum(points: Array, positions: Array, weights: Array, sigma: float, chunk: int = 1 << 18) -> Array:
    """``K(x) = Σ_s w_s exp(−|x − y_s|²/2σ²)`` for each point, by every pair (the reference).

    At most ``chunk`` pairs are formed at once.
    """
    out = np.empty(len(points))
    rows = max(1, chunk // max(len(positions), 1))
    scale = -0.5 / sigma ** 2
    for start in range(0, len(points), rows):
        block = points[start:start + rows]
        dx = np.subtract.outer(block[:, 0], positions[:, 0])
        dy = np.subtract.outer(block[:, 1], positions[:, 1])
        # einsum, not ``@``: a multithreaded BLAS would spin on the one core the benchmark measures
        out[start:start + rows] = np.einsum("ij,j->i", np.exp((dx * dx + dy * dy) * scale), weights)
    return out


class ExactKernelSums(KernelSums):
    """Every pair: O(P·Q) work per query and O(chunk) memory. The reference the engine is tested against."""

    def __init__(self, count: int, particles: int, sigma: float, chunk: int = 1 << 18) -> None:
        self.sigma = float(sigma)
        self.chunk = chunk
        self.positions = np.zeros((count, particles, 2))
        self.weights = np.zeros((count, particles))

    def set(self, rows: Sequence[int], positions: Array, weights: Array) -> None:
        self.positions[list(rows)] = positions
        self.weights[list(rows)] = weights

    def reweight(self, changes: Sequence[Change]) -> None:
        for row, index, _, delta, total in changes:
            self.weights[row, index] += delta
            self.weights[row] /= total

    def combine(self, sources: Index, weights: Array, points: Array) -> Array:
        out = np.zeros(points.shape[:2])
        for r, s in zip(*np.nonzero(np.asarray(sources) >= 0), strict=True):
            row = sources[r, s]
            out[r] += weights[r, s] * exact_kernel_sum(points[r], self.positions[row], self.weights[row], self.sigma,
                                                       self.chunk)
        return out


SET_CHUNK = 16
"""Rows binned and smoothed together when a grid engine's rows are set."""
STAMP_COST = 3.0
"""What adding one cell of a particle's stamp costs, in cells of a whole-grid smoothing (measured)."""
RESET_AFTER = 16
"""Moves a row takes by stamps before it is set afresh (float32 sums drift, if only by ~1e-7 a move)."""


class GridKernelSums(KernelSums):
    """Binned Gaussian smoothing on a grid over ``bounds`` (see the module docstring).

    ``cell`` defaults to σ/2, coarsened only if the grid would exceed ``max_cells`` cells.
    """

    def __init__(self, count: int, bounds: Sequence[float], sigma: float, cell: float | None = None,
                 max_cells: int = 250_000, truncate: float = 4.0, dtype: type = np.float32) -> None:
        if sigma <= 0:
            raise ValueError("sigma must be positive")
        xmin, ymin, xmax, ymax = (float(v) for v in bounds)
        pad = truncate * sigma
        width, height = xmax - xmin + 2 * pad, ymax - ymin + 2 * pad
        if cell is None:
            cell = min(sigma, max(sigma / 2, math.sqrt(width * height / max_cells)))
        self.sigma = float(sigma)
        self.cell = float(cell)
        self.truncate = float(truncate)
        self.origin = np.array([xmin - pad, ymin - pad])
        self.shape = (int(math.ceil(width / cell)) + 2, int(math.ceil(height / cell)) + 2)
        self._top = (self.shape[0] - 1.0001, self.shape[1] - 1.0001)
        """The largest cell coordinates a point is clamped to (a corner's neighbours stay in the grid)."""
        self.filter_sigma = math.sqrt(max((sigma / cell) ** 2 - 1 / 3, 0.25))
        self.halo = int(math.ceil(truncate * self.filter_sigma)) + 1
        self.scale = 2 * math.pi * sigma ** 2 / cell ** 2
        self.grids: NDArray[np.floating[Any]] = np.zeros((count, *self.shape), dtype=dtype)
        self._band = _band(max(self.shape), self.filter_sigma, truncate, dtype) if max(self.shape) <= MAX_BAND else None
        """The filter along an axis as a matrix (any window's is its leading block: entries depend on i − j)."""
        self.radius = int(truncate * self.filter_sigma + 0.5)
        """How far (cells) the filter reaches."""
        self.factor = np.ones(count)
        """Each row's grid times its factor is its K (a reweighting divides the factor, not the grid)."""
        self.moves = np.zeros(count, np.intp)
        """Moves by stamps each row has taken since it was last set."""
        self._versions = np.zeros(count, np.intp)

    def _cells(self, xy: Array) -> tuple[Index, Index, Array, Array]:
        """Lower-left cell indices and fractional offsets of points (clamped into the grid)."""
        u = (xy[..., 0] - self.origin[0]) * (1 / self.cell)
        v = (xy[..., 1] - self.origin[1]) * (1 / self.cell)
        for w, top in ((u, self._top[0]), (v, self._top[1])):  # np.clip, without its wrapper
            np.maximum(w, 0, out=w)
            np.minimum(w, top, out=w)
        i, j = u.astype(np.intp), v.astype(np.intp)  # truncation is floor: u, v >= 0
        return i, j, u - i, v - j

    def _bin(self, shape: tuple[int, int, int], i: Index, j: Index, fu: Array, fv: Array, weights: Array,
             flat: bool = False) -> Array:
        """Linear binning of weighted points with cell indices (i, j): of stack layer k when the arrays are
        (count, P); with ``flat``, ``i`` already counts rows across the layers (``layer * nx + i``)."""
        count, nx, ny = shape
        layers = 0 if flat else np.arange(count).reshape(-1, *([1] * (i.ndim - 1))) * nx
        base = ((layers + i) * ny + j).ravel()
        jit = compiled.kernels()
        if jit is not None:  # the same sums, added in the same order, in one loop
            binned = np.zeros(count * nx * ny)
            spread = np.broadcast_to(weights, i.shape)
            jit.bin_corners(base, ny, *(np.ascontiguousarray(a, float).ravel() for a in (fu, fv, spread)), binned)
            return np.asarray(binned, dtype=self.grids.dtype).reshape(shape)
        n = len(base)
        index = np.empty(4 * n, base.dtype)  # the four corners' cells and shares, one after the other
        np.add(base, ny, out=index[n:2 * n])
        np.add(base, 1, out=index[2 * n:3 * n])
        np.add(base, ny + 1, out=index[3 * n:])
        index[:n] = base
        gu, gv = 1 - fu, 1 - fv
        share = np.empty(4 * n, np.result_type(fu, fv, weights))
        spread = np.broadcast_to(weights, gu.shape).ravel()
        for k, (a, b) in enumerate(((gu, gv), (fu, gv), (gu, fv), (fu, fv))):
            np.multiply(np.multiply(a, b).ravel(), spread, out=share[k * n:(k + 1) * n])
        mass = np.bincount(index, share, minlength=count * nx * ny)
        return np.asarray(mass, dtype=self.grids.dtype).reshape(shape)

    def _bin_points(self, positions: Array, weights: Array) -> Array:
        """:meth:`_bin` of rows of points (R, P, 2) with weights (R, P), from their positions."""
        jit = compiled.kernels()
        if jit is None or positions.dtype != np.float64:
            return self._bin((len(positions), *self.shape), *self._cells(positions), weights)
        binned = np.zeros(len(positions) * self.shape[0] * self.shape[1])
        jit.bin_points(np.ascontiguousarray(positions), float(self.origin[0]), float(self.origin[1]), 1 / self.cell,
                       float(self._top[0]), float(self._top[1]), np.ascontiguousarray(weights, float),
                       self.shape[1], binned)
        return np.asarray(binned, dtype=self.grids.dtype).reshape(len(positions), *self.shape)

    def _smooth(self, mass: Array) -> Array:
        """The binned masses (R, nx', ny') smoothed along both grid axes by the Gaussian filter, as two
        products with banded matrices (each entry a tap of the filter's kernel, as ``scipy.ndimage``'s
        ``gaussian_filter`` with zeros outside would use), block by block: BLAS does the zeros near the
        band faster than a filter loop does the taps alone. (A grid more than ``MAX_BAND`` cells long
        takes the filter.)"""
        _, nx, ny = mass.shape
        if self._band is None:
            from scipy import ndimage

            s = self.filter_sigma
            smooth = ndimage.gaussian_filter(mass, (0, s, s), mode="constant", truncate=self.truncate)
        else:
            with _one_thread():
                smooth = _banded(_banded(mass, self._band, self.radius, 2), self._band, self.radius, 1)
        smooth *= self.scale
        return np.asarray(smooth)

    def set(self, rows: Sequence[int], positions: Array, weights: Array) -> None:
        """Bin and smooth the rows' particles, ``SET_CHUNK`` rows at a time (the binned masses and the
        smoothing's intermediates are several times a grid: in chunks they stay small whatever the count)."""
        rows = list(rows)
        for start in range(0, len(rows), SET_CHUNK):
            part = slice(start, start + SET_CHUNK)
            chunk = rows[part]
            self.grids[chunk] = self._smooth(self._bin_points(positions[part], weights[part]))
            self.factor[chunk] = 1.0
            self.moves[chunk] = 0
            self._versions[chunk] += 1

    def versions(self) -> Index:
        return self._versions.copy()

    def move(self, rows: Sequence[int], positions: Array, weights: Array, gone: Moved, come: Moved) -> None:
        """When the particles that changed are few against the grid's cells (a large map), each one's
        smoothed mass — its *stamp*, the filter's taps around its four binning corners: ``2·radius + 2``
        cells a side — is taken out of (gone) or added to (come) its row's grid; otherwise, and every
        ``RESET_AFTER`` moves, the rows are set afresh. K is linear in the particles, so both give the same
        grids (to float32 rounding)."""
        rows = list(rows)
        if not self.takes_moves(rows, len(gone[0]) + len(come[0])):
            self.set(rows, positions, weights)
            return
        self._stamp(np.concatenate([gone[0], come[0]]), np.concatenate([gone[1], come[1]]),
                    np.concatenate([-np.asarray(gone[2], float), np.asarray(come[2], float)]))
        self.moves[rows] += 1
        self._versions[rows] += 1

    def takes_moves(self, rows: Sequence[int], changed: int) -> bool:
        side = 2 * self.radius + 2
        rows = list(rows)
        return bool(rows) and changed * side * side * STAMP_COST <= len(rows) * self.shape[0] * self.shape[1] \
            and int(self.moves[rows].max()) < RESET_AFTER

    def _stamp(self, rows: Index, positions: Array, weights: Array) -> None:
        """Add each particle's smoothed mass (weight ``weights[n]`` at ``positions[n]``) to row ``rows[n]``:
        what binning it and smoothing the grid would add there."""
        nx, ny = self.shape
        r = self.radius
        taps = _band(2 * r + 1, self.filter_sigma, self.truncate, self.grids.dtype.type)[r]  # k(t), t = −r … r
        low, high = np.append(taps, 0), np.insert(taps, 0, 0)  # k(m − r) and k(m − r − 1), m = 0 … 2r + 1
        i, j, fu, fv = self._cells(positions)
        along_i = (1 - fu)[:, None] * low + fu[:, None] * high  # the corners i and i + 1 (shares 1 − fu, fu) filtered
        along_j = (1 - fv)[:, None] * low + fv[:, None] * high
        scale = self.scale * np.asarray(weights, float) / self.factor[rows]
        stamp = (scale[:, None, None] * along_i[:, :, None] * along_j[:, None, :]).astype(self.grids.dtype)
        offset = np.arange(2 * r + 2) - r
        ci, cj = i[:, None] + offset, j[:, None] + offset
        inside = ((ci >= 0) & (ci < nx))[:, :, None] & ((cj >= 0) & (cj < ny))[:, None, :]
        cell = ((rows[:, None, None] * nx + ci[:, :, None]) * ny + cj[:, None, :])
        if inside.all():
            np.add.at(self.grids.reshape(-1), cell.ravel(), stamp.ravel())
        else:
            np.add.at(self.grids.reshape(-1), cell[inside], stamp[inside])

    def reweight(self, changes: Sequence[Change]) -> None:
        """All the changes' particles are binned into windows of one size around them (one filter for all);
        the division by each total is kept as a factor of the row, applied when sampling."""
        moved = [c for c in changes if len(c[1])]
        if moved:
            sizes = [len(c[1]) for c in moved]
            i, j, fu, fv = self._cells(np.concatenate([c[2] for c in moved]))
            start = np.cumsum([0, *sizes[:-1]])
            low_i, high_i = np.minimum.reduceat(i, start), np.maximum.reduceat(i, start)
            low_j, high_j = np.minimum.reduceat(j, start), np.maximum.reduceat(j, start)
            span_i = min(int((high_i - low_i).max()) + 2 * self.halo + 2, self.shape[0])
            span_j = min(int((high_j - low_j).max()) + 2 * self.halo + 2, self.shape[1])
            corner_i = np.clip(low_i - self.halo, 0, self.shape[0] - span_i)
            corner_j = np.clip(low_j - self.halo, 0, self.shape[1] - span_j)
            layer = np.repeat(np.arange(len(moved)), sizes)
            rows = np.array([c[0] for c in moved])
            delta = np.concatenate([c[3] for c in moved]) / self.factor[rows][layer]
            mass = self._bin((len(moved), span_i, span_j), layer * span_i + i - corner_i[layer], j - corner_j[layer],
                             fu, fv, delta, flat=True)
            smooth = self._smooth(mass)
            for k, row in enumerate(rows):
                self.grids[row, corner_i[k]:corner_i[k] + span_i, corner_j[k]:corner_j[k] + span_j] += smooth[k]
        if changes:
            rows = np.array([c[0] for c in changes], np.intp)
            self.factor[rows] /= np.array([c[4] for c in changes], float)
            self._versions[rows] += 1

    def combine(self, sources: Index, weights: Array, points: Array) -> Array:
        """Bilinear reads of the sources' grids at the points, one term (a column of ``sources``) at a time
        (compiled: every term of a point at once, :mod:`seal_cli.sefm.compiled`)."""
        dtype = self.grids.dtype
        sources = np.asarray(sources, np.intp)
        jit = compiled.kernels()
        if jit is not None and dtype == np.float32 and points.dtype == np.float64:
            coef = (np.asarray(weights) * self.factor[np.maximum(sources, 0)] * (sources >= 0)).astype(dtype)
            out = np.empty(points.shape[:2], dtype)
            jit.read(self.grids, float(self.origin[0]), float(self.origin[1]), 1 / self.cell, float(self._top[0]),
                     float(self._top[1]), np.ascontiguousarray(sources), coef, np.ascontiguousarray(points), out)
            return out
        i, j, fu, fv = self._cells(points)
        nx, ny = self.shape
        base = i * ny + j
        fu, fv = fu.astype(dtype), fv.astype(dtype)
        coef = (np.asarray(weights) * self.factor[np.maximum(sources, 0)] * (sources >= 0)).astype(dtype)
        flat = self.grids.reshape(-1)
        right, up, both = flat[ny:], flat[1:], flat[ny + 1:]  # a corner's neighbours at the same index
        out = np.zeros(base.shape, dtype)
        for s in range(sources.shape[1]):
            live = np.flatnonzero(sources[:, s] >= 0)
            if len(live) == 0:
                continue
            # the rows holding a term: a run of rows (a slice, no copies) when they are consecutive
            at: slice | Index = slice(live[0], live[-1] + 1) if live[-1] - live[0] + 1 == len(live) else live
            corner = base[at] + (sources[at, s] * (nx * ny))[:, None]
            a, b = np.take(flat, corner), np.take(right, corner)
            c, d = np.take(up, corner), np.take(both, corner)
            u, v = fu[at], fv[at]
            a += (b - a) * u                    # along x at the lower row of cells
            c += (d - c) * u                    # ... and at the upper row
            a += (c - a) * v                    # along y
            a *= coef[at, s, None]
            out[at] += a
        return out


class SplitKernelSums(KernelSums):
    """Rows below ``split`` answered by ``low``, the others (renumbered from 0) by ``high``.

    SeFM keeps object beliefs (the measurement's sources) on a grid of σ/2 and frame beliefs (the
    context's sources) on a grid of σ: the context only ever scales a frame's weight by
    ``1 + Σ C·K``, so an error in K there moves the weights by less than half as much, while
    the frames' grids, rebuilt at every update, cost four times less.
    """

    def __init__(self, low: KernelSums, high: KernelSums, split: int) -> None:
        self.low, self.high, self.split = low, high, split
        self.sigma = low.sigma

    def set(self, rows: Sequence[int], positions: Array, weights: Array) -> None:
        index = np.asarray(list(rows), np.intp)
        below = index < self.split
        if below.any():
            self.low.set([int(r) for r in index[below]], positions[below], weights[below])
        if (~below).any():
            self.high.set([int(r) - self.split for r in index[~below]], positions[~below], weights[~below])

    def takes_moves(self, rows: Sequence[int], changed: int) -> bool:
        index = np.asarray(list(rows), np.intp)
        return not (index < self.split).any() and self.high.takes_moves([int(r) - self.split for r in index], changed)

    def move(self, rows: Sequence[int], positions: Array, weights: Array, gone: Moved, come: Moved) -> None:
        index = np.asarray(list(rows), np.intp)
        if (index < self.split).any() or (gone[0] < self.split).any() or (come[0] < self.split).any():
            self.set(rows, positions, weights)  # the low rows take no moves: set them all
            return
        self.high.move([int(r) - self.split for r in index], positions, weights,
                       (gone[0] - self.split, gone[1], gone[2]), (come[0] - self.split, come[1], come[2]))

    def versions(self) -> Index | None:
        low, high = self.low.versions(), self.high.versions()
        return None if low is None or high is None else np.concatenate([low, high])

    def reweight(self, changes: Sequence[Change]) -> None:
        self.low.reweight([c for c in changes if c[0] < self.split])
        self.high.reweight([(c[0] - self.split, *c[1:]) for c in changes if c[0] >= self.split])

    def combine(self, sources: Index, weights: Array, points: Array) -> Array:
        sources = np.asarray(sources, np.intp)
        below, above = (sources >= 0) & (sources < self.split), sources >= self.split
        parts = [kernel.combine(np.where(part, sources - offset, -1), weights, points)
                 for part, kernel, offset in ((below, self.low, 0), (above, self.high, self.split)) if part.any()]
        if not parts:
            return np.zeros(points.shape[:2])
        return parts[0] if len(parts) == 1 else parts[0] + parts[1]


MAX_BAND = 1024
"""The longest grid side whose filter is a banded matrix product (the matrix holds side² numbers)."""


def _band(n: int, sd: float, truncate: float, dtype: type) -> Array:
    """The n × n matrix of a Gaussian filter of ``sd`` cells along one axis, cut at ``truncate`` sd
    (the taps ``scipy.ndimage.gaussian_filter1d`` uses, normalised over the cut kernel)."""
    radius = int(truncate * sd + 0.5)
    total = np.exp(-0.5 * (np.arange(-radius, radius + 1) / sd) ** 2).sum()
    d = np.subtract.outer(np.arange(n), np.arange(n))
    return np.where(np.abs(d) <= radius, np.exp(-0.5 * (d / sd) ** 2) / total, 0.0).astype(dtype)


def _banded(mass: Array, band: Array, radius: int, axis: int, block: int = 32) -> Array:
    """``mass`` times the symmetric band matrix along ``axis`` (1 or 2), a block of ``block`` outputs at a
    time from the inputs within ``radius`` of it (the rest of the band is zeros)."""
    n = mass.shape[axis]
    out = np.empty_like(mass)
    for start in range(0, n, block):
        stop = min(start + block, n)
        low, high = max(0, start - radius), min(n, stop + radius)
        if axis == 2:
            out[:, :, start:stop] = mass[:, :, low:high] @ band[low:high, start:stop]
        else:
            out[:, start:stop, :] = np.matmul(band[start:stop, low:high], mass[:, low:high, :])
    return out


@lru_cache(maxsize=1)
def _blas() -> Any:
    from threadpoolctl import ThreadpoolController

    return ThreadpoolController()


def _one_thread() -> Any:
    """A context in which BLAS runs on one thread: OpenBLAS would spread even these small products over
    every core and keep them spinning (the benchmark counts the process's CPU time: that is twice the work)."""
    return _blas().limit(limits=1, user_api="blas")


def make_kernel_sums(kind: str, count: int, particles: int, bounds: Sequence[float], sigma: float,
                     split: int | None = None) -> KernelSums:
    """``"grid"`` (the engine) or ``"exact"`` (the O(P²) reference) for ``count`` sources.

    With ``split``, the grid engine keeps rows from ``split`` on (SeFM's frames) on a grid of σ
    (:class:`SplitKernelSums`)."""
    if kind == "grid":
        if split is None or split >= count:
            return GridKernelSums(count, bounds, sigma)
        return SplitKernelSums(GridKernelSums(split, bounds, sigma), GridKernelSums(count - split, bounds, sigma,
                                                                                     cell=sigma), split)
    if kind == "exact":
        return ExactKernelSums(count, particles, sigma)
    raise ValueError(f"unknown kernel {kind!r}; use 'grid' or 'exact'")
