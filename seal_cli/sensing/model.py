"""The sensor model: one interface for what a robot sees, used by SeFM, the simulated world and every policy.

A :class:`SensorModel` answers three questions about a pose ``(x, y, yaw)``:

- :meth:`~SensorModel.visible` — is each point seen (range, field of view, line of sight)? Exact,
  for a few points (the things in a world, a lattice of frontier points).
- :meth:`~SensorModel.region` — the visible region as a fan of rays, cast once and then asked about
  any number of points (:meth:`VisibleRegion.contains <seal_cli.sensing.sensor.VisibleRegion.contains>`):
  what the particle filter uses for negative information.
- :meth:`~SensorModel.detect` — simulated detections of the things given (each visible one seen with
  probability ``p_detect``, displaced by Gaussian noise of ``noise`` metres; none missed or moved
  without a random generator).

Its parameters are a map's :class:`~seal_cli.maps.model.Sensor` (``range``, ``fov_deg``, ``p_detect``,
``sigma``, ``noise``): the observation likelihood of the object filter reads ``p_detect`` and ``sigma``
from the same object. :class:`RangeSensor` is the one implementation shipped: a range-and-bearing sensor
whose line of sight is cut by the occupied cells of an occupancy grid (a map's), or by nothing (ALFRED's
rooms, whose scenes carry no walls). A new sensor (a camera frustum, a detector whose ``p_detect`` falls
with distance) is one class with these methods, registered in :data:`SENSORS`.
"""

from __future__ import annotations

from collections.abc import Callable, Iterable, Sequence
from dataclasses import dataclass, field
from typing import Protocol, runtime_checkable

import numpy as np
from numpy.typing import ArrayLike, NDArray

from seal_cli.frames.taxonomy import class_key
from seal_cli.maps.geometry import as_points, lines_of_sight
from seal_cli.maps.model import Map, ObjectTruth, Sensor
from seal_cli.sensing.sensor import Detection, VisibleRegion, as_pose, fan_angles, in_view, visible_region

__all__ = ["SENSORS", "RangeSensor", "SensorModel", "closed_places", "sensor_for", "simulate_detections",
           "visible_objects"]

Pose = Sequence[float]


@runtime_checkable
class SensorModel(Protocol):
    """What a robot sees from a pose; see the module docstring."""

    @property
    def spec(self) -> Sensor:
        """The parameters: range, field of view, detection probability, spread and noise."""

    @property
    def range(self) -> float: ...

    def visible(self, pose: Pose, points: ArrayLike) -> NDArray[np.bool_]: ...

    def line_of_sight(self, origin: Sequence[float], points: ArrayLike) -> NDArray[np.bool_]: ...

    def region(self, pose: Pose, rays: int | None = None) -> VisibleRegion: ...

    def detect(self, pose: Pose, things: Iterable[tuple[str, tuple[float, float]]],
               rng: np.random.Generator | None = None) -> list[Detection]: ...


@dataclass(frozen=True, eq=False)
class RangeSensor:
    """A sensor that sees within ``spec.range`` metres and ``spec.fov_deg`` degrees of its heading, its line
    of sight cut by the occupied cells of ``occupancy`` (nothing cuts it when that is None)."""

    spec: Sensor = field(default_factory=Sensor)
    occupancy: Map | None = field(default=None, repr=False)
    """The map whose occupied cells block the view (its grid and bounds), or None."""

    @classmethod
    def on_map(cls, m: Map, spec: Sensor | None = None) -> RangeSensor:
        """The map's sensor (or ``spec``), its view cut by the map's walls."""
        return cls(spec or m.sensor, m)

    @property
    def range(self) -> float:
        return self.spec.range

    @property
    def fov_deg(self) -> float:
        return self.spec.fov_deg

    def line_of_sight(self, origin: Sequence[float], points: ArrayLike) -> NDArray[np.bool_]:
        """Whether nothing occupied lies between ``origin`` and each point (the map's exact rule, many points at once:
        :func:`~seal_cli.maps.geometry.lines_of_sight`)."""
        p = as_points(points)
        if self.occupancy is None:
            return np.ones(len(p), dtype=bool)
        return np.asarray(lines_of_sight(self.occupancy.grid, (float(origin[0]), float(origin[1])), p), dtype=bool)

    def visible(self, pose: Pose, points: ArrayLike) -> NDArray[np.bool_]:
        """Within range and field of view, and in line of sight (exact)."""
        p = as_points(points)
        out = in_view(self.spec, as_pose(pose), p)
        if out.any():
            out[out] = self.line_of_sight(pose[:2], p[out])
        return out

    def region(self, pose: Pose, rays: int | None = None) -> VisibleRegion:
        """The visible region as a fan of rays (``rays`` of them; by default half a cell apart at full range)."""
        if self.occupancy is None:
            return _open_region(self.spec, as_pose(pose), rays)
        return visible_region(self.occupancy, pose, self.spec, rays)

    def detect(self, pose: Pose, things: Iterable[tuple[str, tuple[float, float]]],
               rng: np.random.Generator | None = None) -> list[Detection]:
        """Detections of the visible ones among ``things`` (``(class, (x, y))``); see the module docstring."""
        listed = list(things)
        if not listed:
            return []
        seen = [t for t, ok in zip(listed, self.visible(pose, np.array([at for _, at in listed], dtype=float)),
                                   strict=True) if ok]
        if rng is None or not seen:
            return [Detection(cls, at) for cls, at in seen]
        hit = rng.random(len(seen)) < self.spec.p_detect
        noise = self.spec.noise
        offsets = rng.normal(0.0, noise, size=(len(seen), 2)) if noise > 0 else np.zeros((len(seen), 2))
        return [Detection(cls, self._on_map(at[0] + float(dx), at[1] + float(dy)))
                for (cls, at), ok, (dx, dy) in zip(seen, hit, offsets, strict=True) if ok]

    def _on_map(self, x: float, y: float) -> tuple[float, float]:
        """A noisy position kept within the map's bounds: the apartment's fridge stands 0.5 m from its edge, so one
        detection in a few thousand (σ 0.3 m) fell outside, and SeFM rightly refused it: ``bench ros --messages
        3000`` and a long ``localize --trajectory`` failed on their own simulated sensor (hostile19)."""
        if self.occupancy is None:
            return x, y
        xmin, ymin, xmax, ymax = self.occupancy.bounds
        return min(max(x, xmin), xmax), min(max(y, ymin), ymax)


def _open_region(spec: Sensor, pose: tuple[float, float, float], rays: int | None) -> VisibleRegion:
    """The fan of a sensor that nothing occludes: every ray reaches its full range."""
    angles = fan_angles(spec.fov_deg, max(8, rays or 64))
    return VisibleRegion(pose, spec.range, spec.fov_deg, angles, np.full(len(angles), spec.range))


SENSORS: dict[str, Callable[[Map, Sensor | None], SensorModel]] = {"range": RangeSensor.on_map}
"""Sensor models by name: each builds the model for a map from its parameters (default: the map's ``sensor``)."""


def sensor_for(m: Map, kind: str = "range", spec: Sensor | None = None) -> SensorModel:
    """The sensor model ``kind`` on map ``m``; an unknown kind lists the known ones."""
    from seal_cli.errors import SealError

    if kind not in SENSORS:
        raise SealError(f"unknown sensor model {kind!r}; the models are {', '.join(sorted(SENSORS))}")
    return SENSORS[kind](m, spec)


def closed_places(m: Map, open_places: Iterable[str] | None = None) -> frozenset[str]:
    """Class keys of the names of the places that are shut: openable and not open.

    ``open_places`` names the places open now; None means as the map says (``open:``).
    """
    if open_places is None:
        return frozenset(class_key(p.name) for p in m.places if p.openable and not p.open)
    opened = {class_key(name) for name in open_places}
    return frozenset(class_key(p.name) for p in m.places if p.openable and class_key(p.name) not in opened)


def visible_objects(m: Map, pose: ArrayLike, open_places: Iterable[str] | None = None,
                    sensor: Sensor | None = None) -> list[ObjectTruth]:
    """The ground-truth objects visible from the pose (not hidden in a closed place)."""
    candidates = _unhidden(m, open_places)
    if not candidates:
        return []
    seen = RangeSensor.on_map(m, sensor).visible(as_pose(pose), np.array([o.at for o in candidates]))
    return [o for o, ok in zip(candidates, seen, strict=True) if ok]


def _unhidden(m: Map, open_places: Iterable[str] | None) -> list[ObjectTruth]:
    shut = closed_places(m, open_places)
    return [o for o in m.objects if o.inside is None or class_key(o.inside) not in shut]


def simulate_detections(m: Map, pose: ArrayLike, open_places: Iterable[str] | None = None,
                        rng: np.random.Generator | None = None,
                        sensor: Sensor | SensorModel | None = None) -> list[Detection]:
    """What a sensor reports from ``pose`` about the map's ground-truth objects that no closed place hides:
    :meth:`SensorModel.detect` of ``sensor`` — a model, or parameters for the map's :class:`RangeSensor`
    (default: the map's own ``sensor``)."""
    model = sensor if sensor is not None and not isinstance(sensor, Sensor) else RangeSensor.on_map(m, sensor)
    things = [(o.cls, o.at) for o in _unhidden(m, open_places)]
    return model.detect(as_pose(pose), things, rng)
