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

A prior is stored as what it really is: a mass per target, each target a set of free cells (shared by
every class that names it and cached on the map, :meth:`Map.target_cells <seal_cli.maps.model.Map.target_cells>`),
plus the mass spread over all free space. Nothing dense per class is kept: :meth:`Prior.cell_weights`
gives the probability of any free cells on demand, :meth:`Prior.sample` draws a target by mass, a cell
uniformly in it and a point uniformly in the cell, and :meth:`Prior.density` is a cell's weight divided by
its area — a density in 1/m² that integrates to 1 over free space and is 0 elsewhere. Memory is one index
array per target of the map, whatever the number of classes.
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass, field
from functools import cached_property
from typing import TYPE_CHECKING

import numpy as np
from numpy.typing import ArrayLike, NDArray

from seal_cli.frames.taxonomy import class_key
from seal_cli.maps.geometry import OUTSIDE, as_points

if TYPE_CHECKING:
    from seal_cli.maps.model import Map

__all__ = ["FLOOR", "SAID", "Prior", "build_prior", "prior_of", "said_masses", "target_cells"]

FLOOR = 0.02
"""The share of every prior spread uniformly over all free space."""

SAID = 0.9
"""How much a command's word for where a thing is ("the milk from the larder") is believed: the share of
the thing's prior put on the targets the command names, the map's prior keeping the rest. The speaker is
mostly right, not always: what they name is looked at first unless something else is much nearer, and the
search goes on where the map's prior says once it is not there (docs/planning.md, "This round (e2e15)")."""


@dataclass(frozen=True, eq=False)
class Prior:
    """The prior of one class on one map: masses on sets of free cells, and a uniform rest."""

    map: Map = field(repr=False)
    cls: str
    components: tuple[tuple[NDArray[np.intp], float], ...] = field(repr=False)
    """``(sorted free-cell indices, probability)`` per target with mass; the probabilities and
    :attr:`uniform` sum to 1."""
    uniform: float
    """The probability spread uniformly over all free cells (the rest and the floor)."""
    masses: Mapping[str, float] = field(default_factory=dict)
    """The resolved masses per target (``"_rest"`` for what is spread over all free space)."""

    @property
    def free_cells(self) -> int:
        return len(self.map.free_centres)

    def cell_weights(self, cells: ArrayLike) -> NDArray[np.float64]:
        """The probability of each given free cell (indices into the map's ``free_centres``)."""
        cells = np.asarray(cells, dtype=np.intp)
        out = np.full(len(cells), self.uniform / max(self.free_cells, 1))
        for members, mass in self.components:
            at = np.searchsorted(members, cells)
            hit = members[np.minimum(at, len(members) - 1)] == cells
            out[hit] += mass / len(members)
        return out

    @property
    def weights(self) -> NDArray[np.float64]:
        """The probability of every free cell, as a dense array (computed, not kept: for small maps and tests)."""
        return self.cell_weights(np.arange(self.free_cells))

    def sample(self, n: int, rng: np.random.Generator) -> NDArray[np.float64]:
        """``n`` points drawn from the prior, shape (n, 2): a target by mass, a cell uniform in it, a point
        uniform in the cell. One uniform number per point picks both the target (by the cumulative masses)
        and the cell within it (by where the number falls inside the target's share)."""
        blocks = [(members, mass) for members, mass in self.components]
        if self.free_cells:
            blocks.append((np.arange(self.free_cells), self.uniform))
        edges = np.cumsum([0.0] + [mass for _, mass in blocks])
        u = rng.random(n) * edges[-1]
        which = np.clip(np.searchsorted(edges, u, side="right") - 1, 0, len(blocks) - 1)
        cells = np.empty(n, dtype=np.intp)
        for k, (members, mass) in enumerate(blocks):
            chosen = which == k
            at = ((u[chosen] - edges[k]) / mass * len(members)).astype(np.intp)
            cells[chosen] = members[np.clip(at, 0, len(members) - 1)]
        return self.map.jitter_in_cells(rng, cells)

    def density(self, points: ArrayLike) -> NDArray[np.float64]:
        """Density per m² at each point: its free cell's probability over the cell's area; 0 off free space."""
        index = self.map.free_index(as_points(points))
        out = np.zeros(len(index))
        on = index >= 0
        out[on] = self.cell_weights(index[on]) / self.map.cell_area
        return out

    def room_masses(self) -> dict[str, float]:
        """The prior's mass per room name (and ``"_outside"``), exactly."""
        sums = self._room_sums
        masses = {name: float(sums[i + 1]) for i, name in enumerate(self.map.room_names)}
        masses[OUTSIDE] = float(sums[0])
        return masses

    @cached_property
    def _room_sums(self) -> NDArray[np.float64]:
        """Mass per room index + 1 (0: outside every room)."""
        rooms = self.map.free_cell_room + 1
        size = len(self.map.rooms) + 1
        sums = np.bincount(rooms, minlength=size) * (self.uniform / max(self.free_cells, 1))
        for members, mass in self.components:
            sums = sums + np.bincount(rooms[members], minlength=size) * (mass / len(members))
        return np.asarray(sums, dtype=np.float64)

    @cached_property
    def rooms_touched(self) -> frozenset[int]:
        """The room indices (-1: outside every room) holding cells of some target: elsewhere the prior is
        uniform over the cells."""
        rooms = self.map.free_cell_room
        return frozenset(int(r) for members, _ in self.components for r in np.unique(rooms[members]))

    def room_cdf(self, room: int, cells: NDArray[np.intp]) -> NDArray[np.float64]:
        """The cumulative weights over ``cells`` — room ``room``'s free cells, in the caller's order —,
        cached per room (the map does not change): what draws stratified within a room read."""
        cache = self._room_cdfs
        if room not in cache:
            cdf = np.cumsum(self.cell_weights(cells))
            cdf.setflags(write=False)
            cache[room] = cdf
        return cache[room]

    @cached_property
    def _room_cdfs(self) -> dict[int, NDArray[np.float64]]:
        return {}


def target_cells(m: Map, target: str) -> NDArray[np.intp]:
    """The free cells (sorted indices into ``m.free_centres``) a prior target spreads its mass over."""
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


def said_masses(masses: Mapping[str, float], said: tuple[str, ...], weight: float = SAID) -> dict[str, float]:
    """A class's prior masses per target conditioned on a command that says where the thing is: ``weight``
    shared equally among the targets said, the masses the map gives (and the rest they leave) scaled by
    ``1 − weight``. A target the map already names keeps its share besides."""
    out = {target: (1.0 - weight) * mass for target, mass in masses.items()}
    for target in said:
        out[target] = out.get(target, 0.0) + weight / len(said)
    return out


def build_prior(m: Map, cls: str, floor: float = FLOOR, said: tuple[str, ...] = ()) -> Prior:
    """The prior of ``cls`` (a class key) on ``m``; see the module docstring. ``said``: the targets a command
    names as where the thing is (:func:`said_masses`)."""
    parts: dict[str, tuple[NDArray[np.intp], float]] = {}
    masses: dict[str, float] = {}
    given = m.priors.get(cls, {})
    said = tuple(t for t in said if len(m.target_cells(t)))
    for target, mass in (said_masses(given, said) if said else given).items():
        cells = m.target_cells(target)
        if mass <= 0 or len(cells) == 0:
            continue
        parts[target] = (cells, mass)
        masses[target] = mass
    rest = max(0.0, 1.0 - sum(masses.values()))
    masses["_rest"] = rest
    total = (1 - floor) * (sum(masses.values())) + floor if len(m.free_centres) else 1.0
    components = tuple((cells, (1 - floor) * mass / total) for cells, mass in parts.values())
    uniform = ((1 - floor) * rest + floor) / total
    return Prior(m, cls, components, uniform, masses)


def prior_of(priors: Mapping[str, Mapping[str, float]], cls: str) -> dict[str, float]:
    """A class's prior masses by class key (empty for a class the map has no prior of)."""
    key = class_key(cls)
    for name, masses in priors.items():
        if class_key(name) == key:
            return {class_key(t): float(m) for t, m in masses.items()}
    return {}
