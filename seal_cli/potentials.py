"""Gaussian kernel sums of weighted particle sets: the numbers inside SeFM's potentials.

The measurement and context potentials of a frame particle at ``x`` are sums, over the
particles ``y_s`` (weights ``w_s``) of an object's or a frame's belief, of a Gaussian kernel
of constant covariance ``Σ = σ² I``::

    K(x) = Σ_s w_s · exp(−|x − y_s|² / 2σ²)

The kernel's peak is 1, so for normalised weights ``K`` lies in [0, 1] and reads as "how much
of the belief lies within about σ of x"; it is ``2πσ²`` times the belief smoothed by the
normal density N(0, Σ).

A :class:`KernelSums` holds a numbered set of *sources* (rows: one per object class and one per
frame) and answers *queries*: ``K`` of a source at many points. Two implementations give the
same answer:

:class:`ExactKernelSums`
    the reference: every pair, O(P·Q) per query, formed in chunks so that memory holds at most
    ``chunk`` pairs at a time (it grows with the particles, never with their square).
:class:`GridKernelSums`
    the engine: a source is spread onto a grid of cell ``h`` by linear binning, smoothed with a
    separable Gaussian filter (``scipy.ndimage``) and read back at the queries by bilinear
    interpolation. Binning and interpolation each widen the kernel by a variance of ``h²/6``
    per axis, so the filter uses ``σ² − h²/3``; at ``h = σ/2`` the normalised weights it gives
    are within a total variation of about 0.005 of the exact ones (``seal bench perf`` measures
    it). Work is O(cells) per changed source and O(1) per query point. A source whose weights
    change at a few particles (negative information in the robot's view) is updated in a
    window around them only: K is linear in the weights.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from typing import Protocol

import numpy as np
from numpy.typing import NDArray

__all__ = ["ExactKernelSums", "GridKernelSums", "KernelSums", "exact_kernel_sum", "make_kernel_sums"]

Array = NDArray[np.float64]
Index = NDArray[np.intp]


class KernelSums(Protocol):
    """Numbered weighted particle sets and ``K`` of any of them at any points."""

    sigma: float

    def set(self, rows: Sequence[int], positions: Array, weights: Array) -> None:
        """Rows ``rows`` now hold these particle sets: ``positions`` (R, P, 2), normalised ``weights`` (R, P)."""
        ...

    def reweight(self, row: int, index: Index, positions: Array, delta: Array, total: float) -> None:
        """The weights of particles ``index`` (at ``positions``, (m, 2)) of ``row`` grew by ``delta``;
        then all were divided by ``total``."""
        ...

    def sample(self, which: Index, points: Array) -> Array:
        """``out[t, q] = K_{which[t]}(points[t, q])`` for points (T, Q, 2): shape (T, Q)."""
        ...


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
        out[start:start + rows] = np.exp((dx * dx + dy * dy) * scale) @ weights
    return out


class ExactKernelSums:
    """Every pair: O(P·Q) work per query and O(chunk) memory. The reference the engine is tested against."""

    def __init__(self, count: int, particles: int, sigma: float, chunk: int = 1 << 18) -> None:
        self.sigma = float(sigma)
        self.chunk = chunk
        self.positions = np.zeros((count, particles, 2))
        self.weights = np.zeros((count, particles))

    def set(self, rows: Sequence[int], positions: Array, weights: Array) -> None:
        self.positions[list(rows)] = positions
        self.weights[list(rows)] = weights

    def reweight(self, row: int, index: Index, positions: Array, delta: Array, total: float) -> None:
        self.weights[row, index] += delta
        self.weights[row] /= total

    def sample(self, which: Index, points: Array) -> Array:
        out = np.empty(points.shape[:2])
        for t, row in enumerate(which):
            out[t] = exact_kernel_sum(points[t], self.positions[row], self.weights[row], self.sigma, self.chunk)
        return out


class GridKernelSums:
    """Binned Gaussian smoothing on a grid over ``bounds`` (see the module docstring).

    ``cell`` defaults to σ/2, coarsened only if the grid would exceed ``max_cells`` cells.
    """

    def __init__(self, count: int, bounds: Sequence[float], sigma: float, cell: float | None = None,
                 max_cells: int = 250_000, truncate: float = 4.0) -> None:
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
        self.filter_sigma = math.sqrt(max((sigma / cell) ** 2 - 1 / 3, 0.25))
        self.halo = int(math.ceil(truncate * self.filter_sigma)) + 1
        self.scale = 2 * math.pi * sigma ** 2 / cell ** 2
        self.grids = np.zeros((count, *self.shape))

    def _cells(self, xy: Array) -> tuple[Index, Index, Array, Array]:
        """Lower-left cell indices and fractional offsets of points (clamped into the grid)."""
        u = np.clip((xy[..., 0] - self.origin[0]) / self.cell, 0, self.shape[0] - 1.000001)
        v = np.clip((xy[..., 1] - self.origin[1]) / self.cell, 0, self.shape[1] - 1.000001)
        i, j = np.floor(u).astype(np.intp), np.floor(v).astype(np.intp)
        return i, j, u - i, v - j

    def _bin(self, shape: tuple[int, int, int], i: Index, j: Index, fu: Array, fv: Array, weights: Array) -> Array:
        """Linear binning of weighted points with cell indices (i, j) of stack layer k (first axis of i)."""
        count, nx, ny = shape
        base = (np.arange(count).reshape(-1, *([1] * (i.ndim - 1))) * nx + i) * ny + j
        index = np.concatenate([base.ravel(), (base + ny).ravel(), (base + 1).ravel(), (base + ny + 1).ravel()])
        share = np.concatenate([((1 - fu) * (1 - fv) * weights).ravel(), (fu * (1 - fv) * weights).ravel(),
                                ((1 - fu) * fv * weights).ravel(), (fu * fv * weights).ravel()])
        return np.asarray(np.bincount(index, share, minlength=count * nx * ny), float).reshape(shape)

    def _smooth(self, mass: Array) -> Array:
        from scipy import ndimage

        s = self.filter_sigma
        return np.asarray(ndimage.gaussian_filter(mass, (0, s, s), mode="constant", truncate=self.truncate)
                          * self.scale)

    def set(self, rows: Sequence[int], positions: Array, weights: Array) -> None:
        if len(rows) == 0:
            return
        i, j, fu, fv = self._cells(positions)
        self.grids[list(rows)] = self._smooth(self._bin((len(rows), *self.shape), i, j, fu, fv, weights))

    def reweight(self, row: int, index: Index, positions: Array, delta: Array, total: float) -> None:
        if len(index):
            i, j, fu, fv = self._cells(positions)
            lo_i, lo_j = max(int(i.min()) - self.halo, 0), max(int(j.min()) - self.halo, 0)
            hi_i, hi_j = min(int(i.max()) + self.halo + 2, self.shape[0]), min(int(j.max()) + self.halo + 2,
                                                                                  self.shape[1])
            window = (1, hi_i - lo_i, hi_j - lo_j)
            mass = self._bin(window, (i - lo_i)[None], (j - lo_j)[None], fu[None], fv[None], delta[None])
            self.grids[row, lo_i:hi_i, lo_j:hi_j] += self._smooth(mass)[0]
        self.grids[row] /= total

    def sample(self, which: Index, points: Array) -> Array:
        i, j, fu, fv = self._cells(points)
        nx, ny = self.shape
        flat = self.grids.reshape(-1)
        corner = (np.asarray(which)[:, None] * nx + i) * ny + j
        low = flat[corner] * (1 - fu) + flat[corner + ny] * fu
        high = flat[corner + 1] * (1 - fu) + flat[corner + ny + 1] * fu
        return np.asarray(low * (1 - fv) + high * fv)


def make_kernel_sums(kind: str, count: int, particles: int, bounds: Sequence[float], sigma: float) -> KernelSums:
    """``"grid"`` (the engine) or ``"exact"`` (the O(P²) reference) for ``count`` sources."""
    if kind == "grid":
        return GridKernelSums(count, bounds, sigma)
    if kind == "exact":
        return ExactKernelSums(count, particles, sigma)
    raise ValueError(f"unknown kernel {kind!r}; use 'grid' or 'exact'")
