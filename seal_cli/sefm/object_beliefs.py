"""Object beliefs (after SLiM, Zeng et al. 2020): a weighted particle set per object class.

Notation (after the ``particles`` library): ``X`` (C, P, 2) are the particles of C sources, one
row each, ``W`` (C, P) their normalised weights, ``L`` the likelihood of one observation.

A *source* is anything a frame element can name:

- an **object** class (``cup``): particles drawn from the map's prior of the class (its rooms'
  and places' masses spread uniformly, plus a small floor over all free space; a class without
  a prior is uniform), conditioned on where the command says the thing is, if it says (``said``)
  — systematically over the rooms, so that each room gets its share of the
  particles to within one, and stratified along a Hilbert curve within a room, so that each patch
  of it does too (:mod:`seal_cli.sefm.cell_order`) — and updated by what the robot sees;
- a **place** (``fridge_1``) or a place class (``fridge``): particles at the places, fixed;
- a **room** (``kitchen``): particles uniform over the room's free space, fixed.

One update of the object rows, from a pose's visible region and the detections there:

1. **reweight** by the observation likelihood (``p`` = the sensor's ``p_detect``, ``σ`` its spread,
   ``λ`` the clutter density)::

       L(x) = 1 − p·v(x) + p · Σ_d N(z_d; x, σ²) / λ

   where ``v(x)`` is 1 inside the visible region and 0 outside or within reach of a closed
   place (what is inside a shut fridge cannot be seen), and the sum runs over the detections
   ``z_d`` of the class. With no detection a visible particle falls to ``1 − p``: negative
   information. ``p`` is capped below 1 so that no weight becomes zero by one miss.

   **Negative information counts once per view.** A detector's misses from one viewpoint are
   not independent (what hid the object from it, or made it miss, is still there at the next
   look), so the ``−p·v`` term is applied only at a *new* view: one farther than ``view_step``
   from, or (for a sensor that does not see all round) turned ``view_turn`` or more (at most the field
   of view) away from,
   every view already used with the same places shut. From a view already used, ``v = 0``:
   standing still adds nothing to what the first look said. Detections always count;
2. when the effective sample size falls under half the particles: **resample** (systematic),
   **jitter** by a small Gaussian, and **reinvigorate**: a share of the particles (5 %) is redrawn
   from the prior and given together a small weight (1 %, the chance that the object was moved
   where nobody saw), so that a belief never collapses for good on a wrong spot and never dies.
   Otherwise the particles stay where they are and only their weights change (so the kernel sums
   of a class whose particles were barely touched are updated in a window, not recomputed).

Before reweighting, a detected class also gets a share of its particles (its lightest 30 %) put
on the fresh detections, as the authors did: the likelihood then weighs them, so a detection
far from everything the belief expected is represented at once.

Classes the robot holds are not updated: they are in its hand, not in the scene.
"""

from __future__ import annotations

import math
from collections.abc import Callable, Iterable, Sequence
from dataclasses import dataclass, field

import numpy as np
from numpy.typing import NDArray

from seal_cli.frames.taxonomy import class_key
from seal_cli.maps.model import OUTSIDE, SPEAKER, Map, Sensor
from seal_cli.sefm import cell_order
from seal_cli.sefm.resampling import ess, normalise, stratified, systematic

__all__ = ["ObjectBeliefs", "ObjectModel", "Source", "Update", "Views", "source_for"]

Array = NDArray[np.float64]
Region = Callable[[Array], NDArray[np.bool_]]
"""A visible region: whether each point (N, 2) is seen."""
Hidden = Sequence[tuple[float, float, float]]
"""Closed places as ``(x, y, reach)``: what is within reach of them may be inside, unseen."""


@dataclass(frozen=True)
class Source:
    """What a frame element's value is on this map: ``kind`` is "object", "place" or "room"."""

    key: str
    kind: str
    points: tuple[tuple[float, float], ...] = ()
    """For a place: where its places are."""
    room: int | None = None
    said: tuple[str, ...] = ()
    """For an object class: the rooms, places or place classes the command says it is in ("the milk from
    the larder"): evidence its prior is conditioned on (:meth:`Map.prior <seal_cli.maps.model.Map.prior>`)."""

    @property
    def static(self) -> bool:
        return self.kind != "object"


def source_for(m: Map, value: str) -> Source:
    """What a value names: a place (by name, then by class), a room, a person the map places (known
    where they stand, as a place is: "me" is the speaker), or else an object class."""
    key = class_key(value)
    person = m.person(value)
    if person is not None or key == SPEAKER:
        return Source(key, "place", (m.person_at(person) if person is not None else m.speaker_at,))
    place = m.place(value)
    places = (place,) if place is not None else m.places_of_class(value)
    if places:
        return Source(key, "place", tuple(p.at for p in places))
    room = m.room_id(value)
    if room is not None:
        return Source(key, "room", room=room)
    return Source(key, "object")


@dataclass(frozen=True)
class ObjectModel:
    """Parameters of the object filter (defaults: the sensor's detection model, the authors' jitter)."""

    p_detect: float = 0.9
    sigma: float = 0.3
    clutter: float = 1e-3
    """False detections per m² of view (λ): how much a detection outweighs chance."""
    jitter: float = 0.02
    prior_share: float = 0.05
    """Share of the particles redrawn from the prior at each resampling..."""
    relocate: float = 0.01
    """...and the weight they carry together: the chance the object was moved unseen."""
    detection_share: float = 0.3
    """Share of a detected class's particles put on its fresh detections."""
    resample_below: float = 0.5
    max_p_detect: float = 0.99
    view_step: float = 0.5
    """How far (m) the robot must move for a look to be a new view (its misses to count again)..."""
    view_turn: float = math.radians(30)
    """...or how far (rad) it must turn, for a sensor that does not see all round (at most its field of view: a
    sensor narrower than this sees, turned by its field, a wedge it had not seen, as the robot does looking round)."""

    @classmethod
    def for_sensor(cls, spec: Sensor, **overrides: float) -> ObjectModel:
        """The observation model of a sensor's detections (its ``p_detect`` and ``sigma``, unless ``overrides`` says
        otherwise)."""
        return cls(**{"p_detect": spec.p_detect, "sigma": spec.sigma, **overrides})

    @classmethod
    def for_map(cls, m: Map, **overrides: float) -> ObjectModel:
        return cls.for_sensor(m.sensor, **overrides)


@dataclass
class Views:
    """The views whose negative information the beliefs already hold (see the module docstring)."""

    step: float
    turn: float | None
    """None: the heading does not matter (the sensor sees all round)."""
    used: list[tuple[float, float, float, frozenset[tuple[float, float, float]]]] = field(default_factory=list)

    def first_look(self, pose: tuple[float, float, float], hidden: Hidden) -> bool:
        """Whether no view like this one (near, same heading, same places shut) was used; it is now."""
        x, y, yaw = pose
        shut = frozenset(hidden)
        for u, v, heading, closed in self.used:
            turned = self.turn is not None and \
                abs((yaw - heading + math.pi) % (2 * math.pi) - math.pi) >= self.turn - 1e-9
            if closed == shut and math.hypot(x - u, y - v) <= self.step and not turned:
                return False
        self.used.append((x, y, yaw, shut))
        return True


@dataclass(frozen=True)
class Update:
    """What changed in the object rows: rows redrawn, and rows whose weights changed at some particles."""

    redrawn: tuple[int, ...] = ()
    reweighted: tuple[tuple[int, NDArray[np.intp], Array, float], ...] = ()
    """``(row, particle indices, weight increments before normalising, the normaliser)``."""


@dataclass
class ObjectBeliefs:
    """The particle sets of every source; rows in the order of ``sources``."""

    map: Map
    sources: tuple[Source, ...]
    X: Array
    W: Array
    model: ObjectModel = field(default_factory=ObjectModel)
    views: Views = field(default_factory=lambda: Views(ObjectModel.view_step, None))
    missed: Array | None = None
    """Per row, the log-probability under the row's belief of every look since its class was last detected (or
    since the start) having missed it: the sum of the log-normalisers of its reweightings (the model's evidence
    for what it has not seen; 0 for a row never looked for). Read by a searcher to tell a belief its looks have
    refuted (:attr:`seal_cli.sim.policies.sefm.SeFMPolicy.refuted`); it changes nothing in the filter."""

    @classmethod
    def from_prior(cls, m: Map, sources: Sequence[Source], particles: int, rng: np.random.Generator,
                   model: ObjectModel | None = None) -> ObjectBeliefs:
        X = np.stack([_initial(m, s, particles, rng) for s in sources]) if sources else np.zeros((0, particles, 2))
        X = np.take_along_axis(X, cell_order.order_of_points(m, X)[..., None], axis=1)
        W = np.full((len(sources), particles), 1.0 / particles)
        model = model or ObjectModel.for_map(m)
        views = Views(model.view_step, None if m.sensor.fov_deg >= 360 else
                      min(model.view_turn, math.radians(m.sensor.fov_deg)))
        return cls(m, tuple(sources), X, W, model, views)

    @property
    def particles(self) -> int:
        return int(self.X.shape[1])

    def row(self, key: str) -> int:
        wanted = class_key(key)
        for i, source in enumerate(self.sources):
            if source.key == wanted:
                return i
        raise KeyError(key)

    def ess(self) -> Array:
        return ess(self.W)

    # -- one update ---------------------------------------------------------------------------
    def update(self, pose: tuple[float, float, float], contains: Region,
               detections: Iterable[tuple[str, tuple[float, float]]], hidden: Hidden, held: Iterable[str],
               rng: np.random.Generator) -> Update:
        """Reweight by one observation, then resample and reinvigorate the rows that need it.

        ``contains(points) -> bool[N]`` tells the region visible from ``pose``; ``hidden`` lists
        closed places; ``detections`` are ``(class, (x, y))``.
        """
        rows = self._believed(held)
        if len(rows) == 0:
            return Update()
        seen = _by_class(detections)
        detected = [int(r) for r in rows if self.sources[r].key in seen]
        self._place_on_detections(detected, seen, rng)
        new_view = self.views.first_look(pose, hidden)
        L = self._likelihood(rows, contains if new_view else None, seen, hidden)
        raw = np.take(self.W, rows, axis=0) * L
        total = raw.sum(axis=1)
        if self.missed is None or len(self.missed) != len(self.sources):
            self.missed = np.zeros(len(self.sources))
        self.missed[rows] += np.log(np.maximum(total, 1e-300))
        self.missed[detected] = 0.0
        W = normalise(raw)
        low = ess(W) < self.model.resample_below * self.particles
        is_detected = np.zeros(len(self.sources), bool)
        is_detected[detected] = True
        windowed = ~low & ~is_detected[rows]  # the rows whose particles stay where they are
        kept = np.flatnonzero(windowed)
        reweighted = _changes(rows[kept], np.take(self.W, rows[kept], axis=0), np.take(L, kept, axis=0), total[kept])
        self.W[rows] = W
        self._resample(rows[low], rng)
        return Update(tuple(sorted({*detected, *(int(r) for r in rows[low])})), reweighted)

    def _believed(self, held: Iterable[str]) -> NDArray[np.intp]:
        """The rows an observation updates: the object classes, but for those the robot holds."""
        hand = {class_key(h) for h in held}
        return np.array([i for i, s in enumerate(self.sources) if not s.static and s.key not in hand], dtype=np.intp)

    def _place_on_detections(self, rows: Sequence[int], seen: dict[str, Array], rng: np.random.Generator) -> None:
        """Put a share of each detected class's particles (its lightest) on the fresh detections, at the mean weight."""
        P = self.particles
        n = min(int(round(self.model.detection_share * P)), P)
        if n == 0 or not rows:
            return
        for row in rows:
            z = seen[self.sources[row].key]
            lightest = np.argsort(self.W[row], kind="stable")[:n]
            picks = z[rng.integers(0, len(z), n)]
            self.X[row, lightest] = self._inside(picks + rng.normal(0.0, self.model.sigma, picks.shape))
            self.W[row, lightest] = 1.0 / P
            self.W[row] /= self.W[row].sum()
        self._sort(np.asarray(rows, np.intp))

    def _likelihood(self, rows: NDArray[np.intp], contains: Region | None, seen: dict[str, Array],
                    hidden: Hidden) -> Array:
        """L of the module docstring at the rows' particles; ``contains`` None: a view already used (v = 0)."""
        X = np.take(self.X, rows, axis=0)
        p = min(self.model.p_detect, self.model.max_p_detect)
        L = np.ones(X.shape[:2])
        if contains is not None:
            flat = X.reshape(-1, 2)
            v = np.asarray(contains(flat), dtype=bool)
            for x, y, reach in hidden:
                v &= np.square(flat - (x, y)).sum(axis=1) > reach ** 2
            L -= p * v.reshape(X.shape[:2])
        s2 = self.model.sigma ** 2
        norm = p / (2 * np.pi * s2 * self.model.clutter)
        for k, row in enumerate(rows):
            z = seen.get(self.sources[row].key)
            if z is not None:
                d2 = np.square(X[k][:, None, :] - z[None, :, :]).sum(axis=2)
                L[k] += norm * np.exp(-0.5 * d2 / s2).sum(axis=1)
        return L

    def _resample(self, rows: NDArray[np.intp], rng: np.random.Generator) -> None:
        """Systematic resampling with jitter, plus a share of fresh draws from the prior that together
        carry the weight ``relocate`` (the chance that the object was moved where nobody saw)."""
        if len(rows) == 0:
            return
        P = self.particles
        n = min(int(round(self.model.prior_share * P)), P - 1)
        ancestors = systematic(self.W[rows], rng, P - n)  # the rows are kept in cell order
        X = np.take_along_axis(self.X[rows], ancestors[..., None], axis=1)
        X = self._inside(X + rng.normal(0.0, self.model.jitter, X.shape))
        W = np.full((len(rows), P), (1.0 - (self.model.relocate if n else 0.0)) / (P - n))
        if n:
            X = np.concatenate([X, np.stack([_initial(self.map, self.sources[r], n, rng) for r in rows])], axis=1)
            W[:, P - n:] = self.model.relocate / n
        self.X[rows], self.W[rows] = X, W
        self._sort(rows)

    def _sort(self, rows: NDArray[np.intp]) -> None:
        """Keep the rows in cell order (:mod:`seal_cli.sefm.cell_order`), so that systematic resampling keeps each
        room's share, and each patch's."""
        P = self.particles
        order = (cell_order.order_of_points(self.map, np.take(self.X, rows, axis=0)) + (rows * P)[:, None]).ravel()
        self.X[rows] = np.take(self.X.reshape(-1, 2), order, axis=0).reshape(len(rows), P, 2)
        self.W[rows] = np.take(self.W, order).reshape(len(rows), P)

    def _inside(self, X: Array) -> Array:
        xmin, ymin, xmax, ymax = self.map.bounds
        return np.stack([np.clip(X[..., 0], xmin, xmax), np.clip(X[..., 1], ymin, ymax)], axis=-1)


def _changes(rows: NDArray[np.intp], W: Array, L: Array,
             total: Array) -> tuple[tuple[int, NDArray[np.intp], Array, float], ...]:
    """Each row's reweighting as :attr:`Update.reweighted`: the particles whose weight changed (L ≠ 1),
    their increments W·(L − 1) before normalising, and the normaliser."""
    k, index = np.nonzero(L != 1.0)  # row by row, each row's particles in order
    delta = W[k, index] * (L[k, index] - 1.0)
    start = np.searchsorted(k, np.arange(len(rows) + 1))
    return tuple((int(rows[r]), index[a:b], delta[a:b], float(total[r]))
                 for r, (a, b) in enumerate(zip(start[:-1].tolist(), start[1:].tolist(), strict=True)) if b > a)


def _by_class(detections: Iterable[tuple[str, tuple[float, float]]]) -> dict[str, Array]:
    seen: dict[str, list[tuple[float, float]]] = {}
    for cls, at in detections:
        seen.setdefault(class_key(cls), []).append((float(at[0]), float(at[1])))
    return {k: np.array(v, dtype=float) for k, v in seen.items()}


def _initial(m: Map, source: Source, n: int, rng: np.random.Generator) -> Array:
    """Particles of a source before anything is seen."""
    if source.kind == "place":
        points = np.array(source.points, dtype=float)
        return points[np.arange(n) % len(points)]
    if source.kind == "room":
        return m.sample_free(rng, n, region=source.room)
    return m.jitter_in_cells(rng, rng.permutation(_by_room(m, source.key, n, rng, source.said)))


def _by_room(m: Map, cls: str, n: int, rng: np.random.Generator, said: tuple[str, ...] = ()) -> NDArray[np.intp]:
    """``n`` free cells drawn by the prior of ``cls``: each room gets its share of the draws to within
    one (systematic over rooms), and within a room the draws are stratified along the cells' order
    (:mod:`seal_cli.sefm.cell_order`): one independent draw in each of ``count`` runs of equal weight, so
    each patch of the room gets its share without the particles falling on a lattice. In a room that no
    target of the prior touches the weights are equal, and a draw is a position along the room's run; in
    the others the prior's cumulative weight over the run is read (the prior keeps it per room)."""
    cells, starts = cell_order.by_room(m)
    prior = m.prior(cls, said)
    by_name = prior.room_masses()
    masses = np.array([by_name[OUTSIDE]] + [by_name[name] for name in m.room_names])  # runs: no room first
    counts = np.bincount(stratified(masses, n, rng), minlength=len(masses))
    rank = np.arange(n) - np.repeat(np.cumsum(counts) - counts, counts)
    u = (rank + rng.random(n)) / np.maximum(np.repeat(counts, counts), 1)
    out = np.empty(n, dtype=np.intp)
    done = 0
    for run in np.flatnonzero(counts):
        members = cells[starts[run]:starts[run + 1]]
        k = int(counts[run])
        share = u[done:done + k]
        if run - 1 in prior.rooms_touched:
            cdf = prior.room_cdf(int(run) - 1, members)
            index = np.searchsorted(cdf, share * cdf[-1], side="right")
        else:
            index = (share * len(members)).astype(np.intp)
        out[done:done + k] = members[np.minimum(index, len(members) - 1)]
        done += k
    return out
