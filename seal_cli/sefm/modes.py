"""What a weighted particle set says, in words a person (or a planner) can use.

A :class:`Summary` of a belief gives

- ``rooms``: the probability mass in each room of the map, and in ``"_outside"`` (no room);
- ``modes``: the peaks of the belief — found by weighted mean shift with a Gaussian kernel of
  bandwidth ``h`` (each particle climbs the kernel density estimate to a peak; the particles
  that reach the same peak are its *basin*) — each with the weighted mean and covariance of
  its basin, its weight, and the room holding most of it; basins lighter than ``min_weight``
  are left out, the rest sorted heaviest first;
- ``best``: the highest peak among the basins that count as modes — the densest place, where a
  robot should look first;
- ``ess``: the effective sample size, 1 / Σ W².

:func:`mean_shift` is the textbook algorithm (every particle climbs, O(N²) per iteration);
:func:`grid_modes`, which the summaries use, finds the same peaks by hill climbing on the density
estimate computed on a grid, in time linear in the particles and cells. No Python loop runs
over particles in either.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

import numpy as np
from numpy.typing import NDArray

from seal_cli.maps.model import OUTSIDE, Map

__all__ = ["Mode", "Summary", "grid_modes", "mean_shift", "room_masses", "summarise"]

Array = NDArray[np.float64]


@dataclass(frozen=True)
class Mode:
    mean: tuple[float, float]
    cov: tuple[tuple[float, float], tuple[float, float]]
    weight: float
    room: str

    def to_json(self, digits: int = 3) -> dict[str, Any]:
        return {"mean": [round(v, digits) for v in self.mean],
                "cov": [[round(v, digits) for v in row] for row in self.cov],
                "weight": round(self.weight, digits), "room": self.room}


@dataclass(frozen=True)
class Summary:
    rooms: dict[str, float]
    modes: tuple[Mode, ...]
    best: tuple[float, float]
    ess: float

    @property
    def top_room(self) -> str:
        return max(self.rooms, key=lambda r: self.rooms[r])

    def to_json(self, digits: int = 3) -> dict[str, Any]:
        return {"rooms": {r: round(m, digits) for r, m in self.rooms.items()},
                "modes": [m.to_json(digits) for m in self.modes],
                "best": [round(v, digits) for v in self.best], "ess": round(self.ess, 1)}


def room_masses(m: Map, X: Array, W: Array) -> dict[str, float]:
    """Probability mass per room name, and ``"_outside"``."""
    sums = np.bincount(m.room_index(X) + 1, weights=W, minlength=len(m.rooms) + 1)
    out = {name: float(sums[i + 1]) for i, name in enumerate(m.room_names)}
    out[OUTSIDE] = float(sums[0])
    return out


def mean_shift(X: Array, W: Array, bandwidth: float, iterations: int = 50,
               tolerance: float = 1e-3) -> tuple[Array, NDArray[np.intp], Array]:
    """Weighted Gaussian mean shift of points X (N, 2) with weights W (N,).

    Returns the peaks (M, 2), the peak of each point (N,) and the kernel density at each peak.
    """
    Y = X.copy()
    scale = -0.5 / bandwidth ** 2
    moving = np.ones(len(Y), bool)
    for _ in range(iterations):
        if not moving.any():
            break
        K = np.exp(scale * _sq_distances(Y[moving], X)) * W
        shifted = (K @ X) / np.maximum(K.sum(axis=1, keepdims=True), 1e-300)
        step = np.sqrt(np.square(shifted - Y[moving]).sum(axis=1))
        Y[moving] = shifted
        still = np.flatnonzero(moving)[step < tolerance * bandwidth]
        moving[still] = False
    return _merge(Y, X, W, bandwidth)


def _merge(points: Array, X: Array, W: Array, bandwidth: float) -> tuple[Array, NDArray[np.intp], Array]:
    """Points closer than ``bandwidth / 2`` (by chains of such neighbours) are one peak, placed at the
    densest of them: the peaks (M, 2), the peak of each point, and the density at each peak."""
    from scipy.sparse import csr_matrix
    from scipy.sparse.csgraph import connected_components

    count, group = connected_components(csr_matrix(_sq_distances(points, points) < (bandwidth / 2) ** 2),
                                        directed=False)
    density = np.exp(-0.5 / bandwidth ** 2 * _sq_distances(points, X)) @ W
    top = np.full(count, -1.0)
    np.maximum.at(top, group, density)
    densest = np.full(count, -1, np.intp)
    densest[group[density == top[group]]] = np.flatnonzero(density == top[group])
    return points[densest], np.asarray(group, np.intp), top


def _sq_distances(A: Array, B: Array) -> Array:
    """Squared distances between every row of A and every row of B."""
    dx = np.subtract.outer(A[:, 0], B[:, 0])
    dy = np.subtract.outer(A[:, 1], B[:, 1])
    return np.asarray(dx * dx + dy * dy)


def grid_modes(X: Array, W: Array, bandwidth: float) -> tuple[Array, NDArray[np.intp], Array]:
    """The same peaks as :func:`mean_shift`, found on a grid: O(cells), for summaries at every step.

    The weighted Gaussian kernel density estimate is computed on cells of ``bandwidth / 3`` (binned
    particles smoothed by the kernel), every cell points to its highest neighbour, and following
    the pointers leads each cell to a peak (a discretised mean shift). Each peak is then refined by
    exact mean-shift steps on the particles, and peaks closer than ``bandwidth / 2`` are merged.
    Returns the peaks (M, 2), the peak of each particle (N,) and the density at each peak.
    """
    from scipy import ndimage

    cell = bandwidth / 3
    low = X.min(axis=0) - 3 * bandwidth
    shape = tuple(int(v) for v in np.ceil((X.max(axis=0) + 3 * bandwidth - low) / cell).astype(int) + 1)
    index = np.floor((X - low) / cell).astype(np.intp)
    flat = index[:, 0] * shape[1] + index[:, 1]
    mass = np.bincount(flat, weights=W, minlength=shape[0] * shape[1]).reshape(shape)
    density = ndimage.gaussian_filter(mass, bandwidth / cell, mode="constant", truncate=3.0)
    padded = np.pad(density, 1, constant_values=-1.0)
    offsets = [(di, dj) for di in (-1, 0, 1) for dj in (-1, 0, 1)]
    around = np.stack([padded[1 + di:1 + di + shape[0], 1 + dj:1 + dj + shape[1]] for di, dj in offsets])
    step = np.array(offsets)[np.argmax(around, axis=0)]  # ties go to the first offset: a plateau flows one way
    rows, cols = np.indices(shape)
    target = np.clip(rows + step[..., 0], 0, shape[0] - 1) * shape[1] + np.clip(cols + step[..., 1], 0, shape[1] - 1)
    target = target.ravel()
    still = target == np.arange(target.size)
    target[still & (density.ravel() <= 0)] = np.flatnonzero(still & (density.ravel() <= 0))
    for _ in range(int(np.ceil(np.log2(max(target.size, 2)))) + 2):
        target = target[target]
    tops, peak_of = np.unique(target[flat], return_inverse=True)
    peaks = low + (np.column_stack(np.unravel_index(tops, shape)) + 0.5) * cell
    scale = -0.5 / bandwidth ** 2
    for _ in range(5):  # refine each peak by exact mean shift on the particles
        K = np.exp(scale * _sq_distances(peaks, X)) * W
        peaks = (K @ X) / np.maximum(K.sum(axis=1, keepdims=True), 1e-300)
    merged, group, top = _merge(peaks, X, W, bandwidth)
    return merged, np.asarray(group[peak_of.ravel()], np.intp), top


def summarise(m: Map, X: Array, W: Array, bandwidth: float = 1.0, min_weight: float = 0.05,
              max_modes: int = 5) -> Summary:
    """The summary of a weighted particle set on a map (see the module docstring)."""
    W = np.asarray(W, float) / np.sum(W)
    peaks, basin, density = grid_modes(X, W, bandwidth)
    weights = np.bincount(basin, weights=W, minlength=len(peaks))
    rooms = m.room_index(X)
    modes: list[Mode] = []
    for k in np.argsort(-weights, kind="stable"):
        if weights[k] < min_weight or len(modes) >= max_modes:
            break
        inside = basin == k
        w = W[inside] / weights[k]
        mean = w @ X[inside]
        d = X[inside] - mean
        cov = (d * w[:, None]).T @ d
        room_mass = np.bincount(rooms[inside] + 1, weights=W[inside], minlength=len(m.rooms) + 1)
        top = int(np.argmax(room_mass)) - 1
        modes.append(Mode((float(mean[0]), float(mean[1])),
                          ((float(cov[0, 0]), float(cov[0, 1])), (float(cov[1, 0]), float(cov[1, 1]))),
                          float(weights[k]), m.rooms[top].name if top >= 0 else OUTSIDE))
    heavy = weights >= min(min_weight, float(weights.max()))
    best = peaks[int(np.argmax(np.where(heavy, density, -1.0)))]
    return Summary(room_masses(m, X, W), tuple(modes), (float(best[0]), float(best[1])),
                   float(1.0 / np.square(W).sum()))
