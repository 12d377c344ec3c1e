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

Mean shift runs on the particles binned to cells of ``h/4`` (same answer, far fewer points for a
concentrated belief), all points at once (no Python loop over particles).
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

import numpy as np
from numpy.typing import NDArray

from .maps import OUTSIDE, Map

__all__ = ["Mode", "Summary", "mean_shift", "room_masses", "summarise"]

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


def mean_shift(X: Array, W: Array, bandwidth: float, iterations: int = 100,
               tolerance: float = 1e-4) -> tuple[Array, NDArray[np.intp], Array]:
    """Weighted Gaussian mean shift of points X (N, 2) with weights W (N,).

    Returns the peaks (M, 2), the peak of each point (N,) and the kernel density at each peak.
    """
    Y = X.copy()
    scale = -0.5 / bandwidth ** 2
    moving = np.ones(len(Y), bool)
    for _ in range(iterations):
        if not moving.any():
            break
        K = np.exp(scale * np.square(Y[moving][:, None, :] - X[None, :, :]).sum(axis=2)) * W
        shifted = (K @ X) / np.maximum(K.sum(axis=1, keepdims=True), 1e-300)
        step = np.sqrt(np.square(shifted - Y[moving]).sum(axis=1))
        Y[moving] = shifted
        still = np.flatnonzero(moving)[step < tolerance * bandwidth]
        moving[still] = False
    from scipy.sparse import csr_matrix
    from scipy.sparse.csgraph import connected_components

    near = np.square(Y[:, None, :] - Y[None, :, :]).sum(axis=2) < (bandwidth / 2) ** 2
    count, labels = connected_components(csr_matrix(near), directed=False)
    density = np.exp(scale * np.square(Y[:, None, :] - X[None, :, :]).sum(axis=2)) @ W
    top = np.full(count, -1.0)
    np.maximum.at(top, labels, density)
    peak_of = np.full(count, -1, np.intp)
    peak_of[labels[density == top[labels]]] = np.flatnonzero(density == top[labels])
    return Y[peak_of], np.asarray(labels, np.intp), top


def _binned(X: Array, W: Array, cell: float) -> tuple[Array, Array, NDArray[np.intp]]:
    """Weighted centroids of the occupied cells, their weights, and each point's cell."""
    keys = np.floor(X / cell).astype(np.int64)
    _, cell_of, = np.unique(keys, axis=0, return_inverse=True)
    cell_of = cell_of.ravel()
    mass = np.asarray(np.bincount(cell_of, weights=W), float)
    safe = np.where(mass > 0, mass, 1.0)
    centre = np.column_stack([np.bincount(cell_of, weights=W * X[:, 0]) / safe,
                              np.bincount(cell_of, weights=W * X[:, 1]) / safe])
    return centre, mass, cell_of


def summarise(m: Map, X: Array, W: Array, bandwidth: float = 1.0, min_weight: float = 0.05,
              max_modes: int = 5) -> Summary:
    """The summary of a weighted particle set on a map (see the module docstring)."""
    W = np.asarray(W, float) / np.sum(W)
    centre, mass, cell_of = _binned(X, W, bandwidth / 4)
    keep = mass > 0
    peaks, labels, density = mean_shift(centre[keep], mass[keep], bandwidth)
    label_of_cell = np.full(len(centre), -1, np.intp)
    label_of_cell[keep] = labels
    basin = label_of_cell[cell_of]
    weights = np.bincount(basin[basin >= 0], weights=W[basin >= 0], minlength=len(peaks))
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
