"""Object priors: where an object of a class is believed to be before anything is seen.

A map's ``priors`` give, per object class, probability mass per *target*: a room, a place
(``fridge_1``) or a place class (``counter``: every counter). The prior of a class is the
mixture, over the map's free space,

    p(x) = (1 − ε) · [ Σ_t m_t · U_t(x) + (1 − Σ_t m_t) · U(x) ] + ε · U(x)

where ``U`` is uniform over all free space, ``U_t`` uniform over the target's free space and
``ε`` = :data:`FLOOR` a small floor so that no free point is impossible. A room's free space is
the free cells whose centres are in the room; a place's (or a place class's) is the free space
within the place's ``reach`` (1 m by default) and in its line of sight — where a robot stands
to take something from it, not behind a wall — and, if there is none, the free cell nearest to
it. A class without a prior is uniform.

Everything is resolved to the map's free cells: :attr:`Prior.weights` is the probability of
each free cell, sampling draws a cell by weight and a point uniformly inside it, and
:meth:`Prior.density` is the cell's weight divided by its area — a density in 1/m² that
integrates to 1 over free space and is 0 elsewhere.
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass, field
from functools import cached_property
from typing import TYPE_CHECKING

import numpy as np
from numpy.typing import ArrayLike, NDArray

from seal_cli.maps.geometry import OUTSIDE, as_points

if TYPE_CHECKING:
    from seal_cli.maps.model import Map

__all__ = ["FLOOR", "Prior", "build_prior", "target_cells"]

FLOOR = 0.02
"""The share of every prior spread uniformly over all free space."""


@dataclass(frozen=True, eq=False)
class Prior:
    """The prior of one class on one map, as a probability per free cell."""

    map: Map = field(repr=False)
    cls: str
    weights: NDArray[np.float64] = field(repr=False)
    masses: Mapping[str, float] = field(default_factory=dict)
    """The resolved masses per target (``"_rest"`` for what is spread over all free space)."""

    @cached_property
    def _cdf(self) -> NDArray[np.float64]:
        return np.cumsum(self.weights)

    def sample(self, n: int, rng: np.random.Generator) -> NDArray[np.float64]:
        """``n`` points drawn from the prior, shape (n, 2): a cell by weight, a point uniform in it."""
        cdf = self._cdf
        cells = np.minimum(np.searchsorted(cdf, rng.random(n) * cdf[-1], side="right"), len(cdf) - 1)
        return self.map.jitter_in_cells(rng, cells)

    def density(self, points: ArrayLike) -> NDArray[np.float64]:
        """Density per m² at each point: its free cell's probability over the cell's area; 0 off free space."""
        index = self.map.free_index(as_points(points))
        out = np.zeros(len(index))
        on = index >= 0
        out[on] = self.weights[index[on]] / self.map.cell_area
        return out

    def room_masses(self) -> dict[str, float]:
        """The prior's mass per room name (and ``"_outside"``), exactly, from the cell weights."""
        sums = np.bincount(self.map.free_cell_room + 1, weights=self.weights, minlength=len(self.map.rooms) + 1)
        masses = {name: float(sums[i + 1]) for i, name in enumerate(self.map.room_names)}
        masses[OUTSIDE] = float(sums[0])
        return masses


def target_cells(m: Map, target: str) -> NDArray[np.intp]:
    """The free cells (indices into ``m.free_centres``) a prior target spreads its mass over."""
    resolved = m.prior_target(target)
    if resolved is None:
        return np.zeros(0, dtype=np.intp)
    kind, indices = resolved
    if kind == "room":
        return np.flatnonzero(m.free_cell_room == indices[0])
    centres = m.free_centres
    near = np.zeros(len(centres), dtype=bool)
    for i in indices:
        place = m.places[i]
        d2 = ((centres - np.array(place.at)) ** 2).sum(axis=1)
        within = d2 <= place.reach ** 2
        within[within] = m.line_of_sight(place.at, centres[within])  # not through a wall
        if not within.any() and len(d2):
            within[np.argmin(d2)] = True
        near |= within
    return np.flatnonzero(near)


def build_prior(m: Map, cls: str, floor: float = FLOOR) -> Prior:
    """The prior of ``cls`` (a class key) on ``m``; see the module docstring."""
    count = len(m.free_centres)
    uniform = np.full(count, 1.0 / count) if count else np.zeros(0)
    mixture = np.zeros(count)
    masses: dict[str, float] = {}
    for target, mass in m.priors.get(cls, {}).items():
        cells = target_cells(m, target)
        if mass <= 0 or len(cells) == 0:
            continue
        mixture[cells] += mass / len(cells)
        masses[target] = masses.get(target, 0.0) + mass
    rest = max(0.0, 1.0 - sum(masses.values()))
    masses["_rest"] = rest
    weights = (1 - floor) * (mixture + rest * uniform) + floor * uniform
    total = weights.sum()
    if total > 0:
        weights = weights / total
    weights.setflags(write=False)
    return Prior(m, cls, weights, masses)
