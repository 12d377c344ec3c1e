"""SeFM, Semantic Frame Mapping: where each frame of a plan can be executed, and where each object is.

:class:`SeFM` joins the object filter (:mod:`seal_cli.sefm.object_beliefs`, after SLiM) and the frame
filter (:mod:`seal_cli.sefm.frame_beliefs`, the paper's Algorithm 1) over one map. Built from a map,
the grounded frames of a plan (:class:`~seal_cli.frames.model.Binding`), the robot's state
(:class:`~seal_cli.planning.state.State`) and a ``numpy.random.Generator``, it is advanced by
:meth:`SeFM.update` with the robot's pose, what it detected there, and its state now::

    sefm = SeFM(m, plan_bindings, state, np.random.default_rng(0))
    for pose in poses:
        sefm.update(pose, simulate_detections(m, pose), state)
    sefm.frame_summary(2).rooms        # {"kitchen": 0.31, "bedroom": 0.52, ...}

One update (:meth:`SeFM.update`): the object beliefs take the observation (negative information
once per view) and the kernel sums of the sources that changed follow; the relation beliefs are
recomputed when the state's facts changed; every frame is reweighted by measurement × context,
reinvigorated, resampled and its copies moved; the context fields take the frames' new beliefs.
The context uses the frames' beliefs of the previous update (every frame is updated once per
update, all at once). Every random draw comes from the one generator, so the same seed and
inputs give the same beliefs.

What is observed about a run — a Rerun recording, a picture, metrics — is gathered by
*observers* passed in (``SeFM(..., observers=[RerunRecorder(path)])``), never by code inside the
update.
"""

from __future__ import annotations

import math
from collections.abc import Iterable, Mapping, Sequence
from dataclasses import dataclass, field, replace
from typing import Any, Protocol

import numpy as np
from numpy.typing import ArrayLike, NDArray

from seal_cli.errors import SealError
from seal_cli.frames.model import Binding
from seal_cli.frames.taxonomy import class_key
from seal_cli.maps.model import SPEAKER, Map
from seal_cli.planning.state import State
from seal_cli.sefm import compiled
from seal_cli.sefm.frame_beliefs import FrameBeliefs, FrameModel, Terms
from seal_cli.sefm.modes import Summary, summarise
from seal_cli.sefm.object_beliefs import ObjectBeliefs, ObjectModel, Region, Source, source_for
from seal_cli.sefm.potentials import KernelSums, make_kernel_sums
from seal_cli.sefm.relations import OTHER, held, relations, spatial_roles
from seal_cli.sensing.model import RangeSensor, SensorModel
from seal_cli.sensing.sensor import VisibleRegion, as_pose

__all__ = ["Observer", "SeFM", "SeFMConfig", "Step", "frame_id", "memory_needed"]

Array = NDArray[np.float64]

REGIONS = 64
"""How many visible regions (one per pose) SeFM keeps."""


BYTES_PER_PARTICLE = 160
"""Bytes one particle of one belief takes at the peak of an update (its position, weight, kernel sums and the
update's temporaries): measured with ``/usr/bin/time -f %M seal localize --steps 1`` at 1,000 and 100,000
particles, 136 bytes on the school's 29 object classes, 152 on the apartment's 9 frames and 3 classes (rel33)."""
BASE_BYTES = 300 * 2**20
"""What a ``seal localize`` takes besides its particles (the interpreter, numpy, the map, the kernels' grids)."""


def memory_needed(beliefs: int, particles: int) -> int:
    """Bytes SeFM takes, about, for ``beliefs`` particle sets (object classes and frames) of ``particles`` each."""
    return BASE_BYTES + BYTES_PER_PARTICLE * beliefs * particles


@dataclass(frozen=True)
class SeFMConfig:
    """Everything that shapes SeFM's numbers (defaults: the paper's and the SPEC's)."""

    particles: int = 200
    """Per object and per frame."""
    sigma: float = 0.3
    """The potentials' Gaussian, Σ = σ²I (m)."""
    other: float = OTHER
    """B of an Other relation."""
    kernel: str = "grid"
    """``grid`` (the engine) or ``exact`` (the O(P²) reference)."""
    objects: ObjectModel | None = None
    """None: from the map's sensor."""
    frames: FrameModel = field(default_factory=FrameModel)
    bandwidth: float = 1.0
    """Mean-shift bandwidth of the summaries (m)."""
    ray_spacing: float = 0.1
    """Gap between neighbouring sensor rays at full range (m) when casting the visible region."""
    memory: int | None = None
    """The most bytes the beliefs may take (:func:`memory_needed`; ``seal localize`` gives what the machine has
    available): more is refused before anything is drawn. None: no bound."""

    def __post_init__(self) -> None:
        if self.particles < 1:
            raise ValueError("particles must be at least 1")
        if self.sigma <= 0:
            raise ValueError("sigma must be positive")


@dataclass(frozen=True)
class Step:
    """One update, as observers see it."""

    index: int
    pose: tuple[float, float, float]
    detections: tuple[tuple[str, tuple[float, float]], ...]
    region: VisibleRegion


class Observer(Protocol):
    """Something that watches SeFM run: called once at the start, after every update, and at the end."""

    def start(self, sefm: SeFM) -> None: ...

    def update(self, sefm: SeFM, step: Step) -> None: ...

    def finish(self, sefm: SeFM) -> None: ...


def frame_id(binding: Binding) -> str:
    """A name for a grounded frame usable in paths: ``stir_cup_spoon``."""
    return "_".join([class_key(binding.frame.name), *(class_key(v) for v in _in_role_order(binding).values())])


def _in_role_order(binding: Binding) -> dict[str, str]:
    """The binding's element values, in the order of the frame's roles."""
    return dict(sorted(binding.values, key=lambda kv: binding.frame.roles.index(kv[0])))


def _places_in_space(binding: Binding) -> list[str]:
    """The values of the binding's spatial elements (what can be located: not words to say)."""
    return [binding.elements[role] for role in spatial_roles(binding)]


def _detections(detections: Iterable[Any]) -> tuple[tuple[str, tuple[float, float]], ...]:
    """Detections as ``(class, (x, y))`` from :class:`~seal_cli.sensing.sensor.Detection` objects or pairs."""
    out = []
    for d in detections:
        cls, at = (d.cls, d.at) if hasattr(d, "cls") else d
        out.append((class_key(str(cls)), (float(at[0]), float(at[1]))))
    return tuple(out)


class SeFM:
    """Object and frame beliefs over one map for one plan (see the module docstring)."""

    def __init__(self, m: Map, bindings: Sequence[Binding], state: State, rng: np.random.Generator,
                 config: SeFMConfig | None = None, observers: Sequence[Observer] = (),
                 classes: Iterable[str] = (), sensor: SensorModel | None = None,
                 said: Mapping[str, Sequence[str]] | None = None) -> None:
        """``classes``: object classes to believe in besides those the frames name; ``sensor``: what sees
        (default: the map's sensor, its view cut by the map's walls); ``said``: where the command's words
        say things are, by class (:func:`~seal_cli.sefm.relations.said_where` of the commanded frames: "the
        milk from the larder"), evidence each such class's prior is conditioned on."""
        self.map = m
        self.said = {class_key(k): tuple(v) for k, v in (said or {}).items()}
        self.sensor: SensorModel = sensor or RangeSensor.on_map(m)
        self.bindings = tuple(bindings)
        self.state = state
        self.extra_classes = tuple(class_key(c) for c in classes)
        self.rng = rng
        self.config = config or SeFMConfig()
        self.observers = list(observers)
        self.step = 0
        self._regions: dict[tuple[float, float, float], VisibleRegion] = {}
        self.sources = self._sources()
        P = self.config.particles
        self._check_memory(len(self.sources), len(self.bindings))
        self.objects = ObjectBeliefs.from_prior(m, self.sources, P, rng,
                                                self.config.objects or ObjectModel.for_sensor(self.sensor.spec))
        self.kernel: KernelSums = make_kernel_sums(self.config.kernel, len(self.sources) + len(self.bindings), P,
                                                   m.bounds, self.config.sigma, split=len(self.sources))
        self.kernel.set(range(len(self.sources)), self.objects.X, self.objects.W)
        self.relations = relations(self.bindings, state, self.config.other)
        self._related = state.facts
        self._context_rows = np.zeros(0, np.intp)
        """The kernel rows the context was last refreshed in."""
        terms = self._terms = self.terms()
        self.frames = FrameBeliefs.start(m, self._noise(), P, terms, self.kernel, (self.objects.X, self.objects.W),
                                         rng, self.config.frames)
        self._refresh_context(terms)
        for observer in self.observers:
            observer.start(self)

    # -- construction ---------------------------------------------------------------------------
    def _check_memory(self, objects: int, frames: int) -> None:
        """Refuse beliefs that would not fit in :attr:`SeFMConfig.memory`, saying how many particles would."""
        limit, P = self.config.memory, self.config.particles
        if limit is None or memory_needed(objects + frames, P) <= limit:
            return
        fits = max(0, (limit - BASE_BYTES) // (BYTES_PER_PARTICLE * max(1, objects + frames)))
        kinds = f"{objects:,} object {'class' if objects == 1 else 'classes'} and {frames:,} frame{'s' * (frames != 1)}"
        raise SealError(f"{P:,} particles for each of {objects + frames:,} beliefs ({kinds}) need about "
                        f"{memory_needed(objects + frames, P) / 2**30:.1f} GiB of memory, and {limit / 2**30:.1f} GiB "
                        "is available: " + (f"give --particles {fits:,} or fewer" if fits
                                            else "give fewer tasks, or a map of fewer classes"))

    def _sources(self) -> tuple[Source, ...]:
        """What the frames' elements name; an object class with where the command says it is (the rooms,
        places and place classes of this map among :attr:`said`)."""
        seen: dict[str, Source] = {}
        values = [v for b in self.bindings for v in _places_in_space(b)] + list(self.extra_classes)
        for value in values:
            source = self._source(value)
            seen.setdefault(source.key, source)
        for thing, where in self.said.items():
            believed = seen.get(thing)
            said = tuple(w for w in where if self.map.prior_target(w) is not None)
            if believed is not None and believed.kind == "object" and said:
                seen[thing] = replace(believed, said=said)
        return tuple(seen.values())

    def _source(self, value: str) -> Source:
        """A value names a place, room or person of the map by name, else a thing whose class the state knows
        (``cup_2`` is a cup), else a class."""
        if self.map.place(value) is not None or self.map.room_id(value) is not None or self._someone(value):
            return source_for(self.map, value)
        return source_for(self.map, self.state.class_of(value))

    def _someone(self, value: str) -> bool:
        """Whether a value is a person the map places, or the speaker ("me"): known where they stand."""
        return self.map.person(value) is not None or class_key(value) == SPEAKER

    @property
    def frame_ids(self) -> tuple[str, ...]:
        """A distinct name per frame, for paths and tables (``stir_cup_spoon``, ``pick_cup``, ``pick_cup_2``)."""
        out: list[str] = []
        for binding in self.bindings:
            base = frame_id(binding)
            name, k = base, 1
            while name in out:
                k += 1
                name = f"{base}_{k}"
            out.append(name)
        return tuple(out)

    def _noise(self) -> list[float]:
        model = self.config.frames
        out = []
        for binding in self.bindings:
            kinds = {self.sources[self.source_row(v)].kind for v in _places_in_space(binding)}
            out.append(model.movable_noise if "object" in kinds else model.static_noise)
        return out

    def source_row(self, value: str) -> int:
        """The row of the source a value names (an object class, place or room)."""
        return self.objects.row(self._source(value).key)

    # -- the state's relations ------------------------------------------------------------------
    def terms(self) -> Terms:
        """The potentials of every frame under the current relation beliefs."""
        C = len(self.sources)
        measurement = [[(self.source_row(v), b) for _, v, b in r.elements] for r in self.relations]
        context = [[(C + j, b) for j, b in r.context] for r in self.relations]
        return Terms.build(len(self.bindings), measurement, context)

    def _refresh_context(self, terms: Terms) -> None:
        """The kernel rows of the frames that are some frame's context now hold their new beliefs."""
        rows = np.unique(terms.ctx_source)
        if len(rows):
            C = len(self.sources)
            frames = rows - C
            X, W = np.take(self.frames.X, frames, axis=0), np.take(self.frames.W, frames, axis=0)
            changed = self.frames.changed()
            change = None
            if changed is not None and np.array_equal(rows, self._context_rows) and \
                    self.kernel.takes_moves(list(rows), int(changed[frames].sum())):
                change = self.frames.change
            if change is None:
                self.kernel.set(list(rows), X, W)
            else:  # the same rows as at the last update: what changed in them is enough
                P = self.frames.particles
                context = np.zeros(len(self.bindings), bool)
                context[frames] = True
                moved = []
                for f, where in ((change[0], change[1]), (change[2], change[3])):
                    keep = np.flatnonzero(context[f])
                    moved.append((f[keep] + C, np.take(where, keep, axis=0), np.full(len(keep), 1.0 / P)))
                self.kernel.move(list(rows), X, W, moved[0], moved[1])
        self._context_rows = rows

    # -- one update -----------------------------------------------------------------------------
    def update(self, pose: ArrayLike, detections: Iterable[Any] = (), state: State | None = None) -> None:
        """One belief update from the robot's pose ``(x, y[, yaw])``, what it detected there, and its state."""
        robot, seen = self._checked(pose, detections)
        if state is not None:
            self.state = state
        region = self._region(robot)
        self._observe(robot, region, seen)
        terms = self._relate()
        self.frames.update(terms, self.kernel, (self.objects.X, self.objects.W), self.rng)
        self._refresh_context(terms)
        self.step += 1
        record = Step(self.step, robot, seen, region)
        for observer in self.observers:
            observer.update(self, record)

    @property
    def known_classes(self) -> frozenset[str]:
        """The class keys a detection may name: the map's and the plan's (the others are refused by :meth:`update`)."""
        return frozenset(self.map.classes) | {source.key for source in self.sources}

    def _checked(self, pose: ArrayLike, detections: Iterable[Any]
                 ) -> tuple[tuple[float, float, float], tuple[tuple[str, tuple[float, float]], ...]]:
        """The pose and detections, refused (a SealError) when not finite, off the map, or of a class
        that neither the map nor the beliefs know: the filter never takes NaN or nonsense."""
        try:
            robot, seen = as_pose(pose), _detections(detections)
        except (TypeError, ValueError, IndexError) as exc:
            raise SealError(f"a pose is (x, y[, yaw]) and a detection (class, (x, y)): {exc}") from None
        xmin, ymin, xmax, ymax = self.map.bounds
        if not all(math.isfinite(v) for v in robot) or not (xmin <= robot[0] <= xmax and ymin <= robot[1] <= ymax):
            raise SealError(f"pose {robot} is not a finite point inside the {self.map.said}'s bounds "
                            f"[{xmin:g}, {ymin:g}, {xmax:g}, {ymax:g}]")
        known = self.known_classes
        for cls, (x, y) in seen:
            if not (math.isfinite(x) and math.isfinite(y) and xmin <= x <= xmax and ymin <= y <= ymax):
                raise SealError(f"a detection of {cls or '(no class)'} at ({x:g}, {y:g}) is not a finite point "
                                f"inside the {self.map.said}'s bounds [{xmin:g}, {ymin:g}, {xmax:g}, {ymax:g}]")
            if cls not in known:
                raise SealError(f"a detection of {cls!r}: the {self.map.said} and the plan know no such class "
                                f"(they know {', '.join(sorted(known)) or 'none'})")
        return robot, seen

    def _observe(self, robot: tuple[float, float, float], region: VisibleRegion,
                 seen: tuple[tuple[str, tuple[float, float]], ...]) -> None:
        """The object beliefs take the observation; the kernel rows of the sources that changed follow."""
        change = self.objects.update(robot, _within_range(region, self.sensor, robot), seen, self.hidden_places(),
                                     held(self.state), self.rng)
        if change.redrawn:
            rows = list(change.redrawn)
            self.kernel.set(rows, self.objects.X[rows], self.objects.W[rows])
        self.kernel.reweight([(row, index, self.objects.X[row, index], delta, total)
                              for row, index, delta, total in change.reweighted])

    def _relate(self) -> Terms:
        """The frames' potentials under the relation beliefs of the current state (recomputed when its facts change)."""
        if self.state.facts != self._related:
            self.relations = relations(self.bindings, self.state, self.config.other)
            self._related = self.state.facts
            self._terms = self.terms()
        return self._terms

    def _region(self, pose: tuple[float, float, float]) -> VisibleRegion:
        """The region visible from a pose: cast once per pose, the last ``REGIONS`` kept (a robot comes
        back to where it was; the map does not change)."""
        region = self._regions.pop(pose, None)
        if region is None:
            spec = self.sensor.spec
            span = min(spec.fov_deg, 360.0) * np.pi / 180
            rays = max(16, int(np.ceil(span * spec.range / self.config.ray_spacing)))
            region = self.sensor.region(pose, rays)
            if len(self._regions) >= REGIONS:
                del self._regions[next(iter(self._regions))]
        self._regions[pose] = region  # most recently used last
        return region

    def follow(self, looks: Sequence[Any] = (), steps: int = 0) -> None:
        """One update per look (an :class:`~seal_cli.sensing.observations.Observation`: a pose and what was
        detected there, or None to simulate it from the map's ground-truth objects), then ``steps``
        more where the last look was (the map's robot pose when there is none): the paper's 20
        updates at a fixed pose. A look the filter would refuse is refused before the first update, at the
        look's place in its file when it has one."""
        from seal_cli.sensing.model import simulate_detections
        from seal_cli.sensing.observations import Observation

        for look in looks:  # every look checked first, a refusal at its place in its file: not after minutes of updates
            if look.detections is not None:
                try:
                    self._checked(look.pose, look.detections)
                except SealError as exc:
                    if look.where is None or exc.where.file is not None:
                        raise
                    raise SealError(exc.message, look.where, hint=exc.hint) from None
        last = looks[-1] if looks else Observation(self.map.robot.pose)
        for look in [*looks, *[last] * steps]:
            seen = look.detections
            if seen is None:
                seen = tuple((d.cls, d.at) for d in simulate_detections(self.map, look.pose, self.open_places(),
                                                                         self.rng, self.sensor))
            self.update(look.pose, seen)

    def close(self) -> None:
        """Tell the observers the run is over."""
        for observer in self.observers:
            observer.finish(self)

    def open_places(self) -> list[str]:
        """The names of the map's places that are open now (what the sensor can see into)."""
        return [p.name for p in self.map.places if not p.openable or self._is_open(p)]

    def hidden_places(self) -> list[tuple[float, float, float]]:
        """Closed places as ``(x, y, reach)``: what is within reach of them may be inside, unseen."""
        return [(p.at[0], p.at[1], p.reach) for p in self.map.places if p.openable and not self._is_open(p)]

    def _is_open(self, place: Any) -> bool:
        """Open by the state's ``open(name)`` or ``open(class)``; without such a fact, closed if the state
        knows what closes, else as the map says."""
        names = {class_key(place.name), place.cls}
        if any(f.predicate == "open" and len(f.args) == 1 and class_key(f.args[0]) in names for f in self.state.facts):
            return True
        return False if self.state.closable is not None else bool(place.open)

    # -- what it believes -----------------------------------------------------------------------
    def frame_particles(self, i: int) -> tuple[Array, Array]:
        """Frame ``i``'s particles and their weights (copies)."""
        return self.frames.X[i].copy(), self.frames.W[i].copy()

    def object_particles(self, cls: str) -> tuple[Array, Array]:
        """An object class's particles and their weights (copies)."""
        row = self.objects.row(cls)
        return self.objects.X[row].copy(), self.objects.W[row].copy()

    def frame_density(self, i: int, points: ArrayLike) -> Array:
        """Frame ``i``'s target density γ (measurement × context) at the points: what its particles
        track, without their sampling noise (unnormalised)."""
        points = np.asarray(points, dtype=float)
        terms = self.terms()
        grid = np.broadcast_to(points, (len(self.bindings), len(points), 2))
        return np.asarray(self.frames.gamma_of(terms, *self.frames.potentials(terms, self.kernel, grid))[i])

    def object_density(self, cls: str, points: ArrayLike) -> Array:
        """An object class's particles smoothed by the potentials' kernel, at the points (unnormalised)."""
        points = np.asarray(points, dtype=float)
        return np.asarray(self.kernel.sample(np.array([self.objects.row(cls)]), points[None])[0])

    def frame_summary(self, i: int) -> Summary:
        return summarise(self.map, self.frames.X[i], self.frames.W[i], self.config.bandwidth)

    def object_summary(self, cls: str) -> Summary:
        row = self.objects.row(cls)
        return summarise(self.map, self.objects.X[row], self.objects.W[row], self.config.bandwidth)

    @property
    def object_classes(self) -> tuple[str, ...]:
        """The sources that are object classes (places and rooms are known, not believed)."""
        return tuple(s.key for s in self.sources if s.kind == "object")

    def frame_json(self, i: int) -> dict[str, Any]:
        binding = self.bindings[i]
        summary = self.frame_summary(i).to_json()
        summary["ess"] = round(float(self.frames.ess()[i]), 1)  # of the last reweighting: the particles weigh 1/P now
        return {"frame": binding.frame.name, "elements": _in_role_order(binding), **summary}

    def object_json(self, cls: str) -> dict[str, Any]:
        summary = self.object_summary(cls).to_json()
        summary.pop("ess")
        return {"class": cls, **summary}

    def to_json(self) -> dict[str, Any]:
        return {"frames": [self.frame_json(i) for i in range(len(self.bindings))],
                "objects": [self.object_json(c) for c in self.object_classes]}


def _within_range(region: VisibleRegion, sensor: SensorModel, pose: tuple[float, float, float]) -> Region:
    """What a look from ``pose`` sees, asked only about the points within the sensor's range: the sensor's exact rule
    (:meth:`~seal_cli.sensing.model.SensorModel.visible`: range, field of view and the segment's line of sight, the
    rule the simulator detects by and the whole-plan search's view model uses), not the ray fan of ``region`` (kept
    for drawing). The fan answers by the ray nearest a point's bearing, so a point a few centimetres behind an
    occluder's corner lies on a ray that passes the corner and was counted seen: the belief there was lowered by a
    look that could never have seen the thing (a cup beside a bed's end on the held-out ranch, docs/benchmarks.md,
    "This round (search20)" and "This round (search21)")."""
    x, y, _ = region.pose

    def contains(points: Array) -> NDArray[np.bool_]:
        jit = compiled.kernels()
        if jit is not None and points.dtype == np.float64:  # the same points, in one pass
            near = np.empty(len(points), np.intp)
            near = near[:jit.within(np.ascontiguousarray(points), x, y, region.range ** 2, near)]
        else:
            d = points - (x, y)
            near = np.flatnonzero(np.einsum("ij,ij->i", d, d) <= region.range ** 2)
        out = np.zeros(len(points), bool)
        if len(near):
            out[near] = np.asarray(sensor.visible(pose, np.take(points, near, axis=0)), dtype=bool)   # np.take: faster
        return out

    return contains
