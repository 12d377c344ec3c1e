"""What the robot sees from a pose: range, field of view, line of sight, and simulated detections.

A point is *visible* from a pose ``(x, y, yaw)`` when it is within the sensor's ``range``,
within ``fov_deg / 2`` of the heading ``yaw`` (a 360° sensor sees all round), and nothing
occupied lies between (:meth:`Map.line_of_sight <seal_cli.maps.model.Map.line_of_sight>`). Objects
inside a closed place (``in: fridge_1`` while the fridge is shut) are never visible.

Two ways to ask, with the same rule:

- :func:`visible` follows every segment through the grid exactly — the reference, for a few
  points (objects);
- :func:`visible_region` casts a fan of rays once per pose (spaced so that neighbouring rays are
  at most half a cell apart at full range) and answers :meth:`VisibleRegion.contains` for any
  number of points by one lookup each — what a particle filter uses for negative information.
  It agrees with :func:`visible` except within about a quarter cell of an obstacle's edge.

Simulated detections (:func:`seal_cli.sensing.model.simulate_detections`, through the sensor model)
come from the map's ground-truth objects: without a random generator,
every visible object is detected exactly where it is; with one, each is detected with
probability ``p_detect`` and displaced by Gaussian noise of ``sensor.noise`` metres (the same
generator state gives the same detections). There are no false positives.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np
from numpy.typing import ArrayLike, NDArray

from seal_cli.maps.geometry import as_points, cast_rays
from seal_cli.maps.model import Map, Sensor

__all__ = ["Detection", "VisibleRegion", "as_pose", "fan_angles", "in_view", "visible", "visible_mask",
           "visible_region"]

Pose = tuple[float, float, float]


def as_pose(pose: ArrayLike) -> Pose:
    """``(x, y, yaw)`` from ``[x, y]`` or ``[x, y, yaw]`` (yaw in radians; 0 when missing)."""
    values = [float(v) for v in np.asarray(pose, dtype=float).ravel()]
    if len(values) == 2:
        values.append(0.0)
    if len(values) != 3:
        raise ValueError(f"a pose is [x, y] or [x, y, yaw], not {pose!r}")
    return (values[0], values[1], values[2])


def _wrap(angle: NDArray[np.float64]) -> NDArray[np.float64]:
    """Angles wrapped into [-pi, pi)."""
    return np.asarray((angle + np.pi) % (2 * np.pi) - np.pi)


def in_view(sensor: Sensor, pose: ArrayLike, points: ArrayLike) -> NDArray[np.bool_]:
    """Within range and field of view of the pose (ignoring walls)."""
    x, y, yaw = as_pose(pose)
    d = as_points(points) - np.array([x, y])
    near = np.einsum("ij,ij->i", d, d) <= sensor.range ** 2
    if sensor.fov_deg >= 360:
        return np.asarray(near)
    bearing = _wrap(np.arctan2(d[:, 1], d[:, 0]) - yaw)
    return np.asarray(near & (np.abs(bearing) <= math.radians(sensor.fov_deg) / 2 + 1e-12))


def visible(m: Map, pose: ArrayLike, points: ArrayLike, sensor: Sensor | None = None) -> NDArray[np.bool_]:
    """Whether each point is visible from the pose (range, field of view and exact line of sight)."""
    p = as_points(points)
    out = in_view(sensor or m.sensor, pose, p)
    if out.any():
        out[out] = m.line_of_sight(as_pose(pose)[:2], p[out])
    return out


@dataclass(frozen=True, eq=False)
class VisibleRegion:
    """The region a sensor sees from one pose, as a fan of rays and how far each one reaches."""

    pose: Pose
    range: float
    fov_deg: float
    angles: NDArray[np.float64] = field(repr=False)
    """Ray directions relative to the heading, increasing, spanning the field of view."""
    reach: NDArray[np.float64] = field(repr=False)
    """How far each ray sees, in metres (``range`` where nothing blocks it)."""

    @property
    def full_circle(self) -> bool:
        return self.fov_deg >= 360

    def contains(self, points: ArrayLike) -> NDArray[np.bool_]:
        """Whether each point is in the visible region: within the reach of the ray nearest its bearing."""
        p = as_points(points)
        x, y, yaw = self.pose
        d = p - np.array([x, y])
        dist = np.hypot(d[:, 0], d[:, 1])
        bearing = _wrap(np.arctan2(d[:, 1], d[:, 0]) - yaw)
        n = len(self.angles)
        if self.full_circle:
            step = 2 * np.pi / n
            ray = np.rint((bearing - self.angles[0]) / step).astype(np.intp) % n
            inside = np.ones(len(p), dtype=bool)
        else:
            half = math.radians(self.fov_deg) / 2
            step = (2 * half / (n - 1)) if n > 1 else 1.0
            ray = np.clip(np.rint((bearing + half) / step).astype(np.intp), 0, n - 1)
            inside = np.abs(bearing) <= half + 1e-12
        return np.asarray(inside & (dist <= self.reach[ray]))

    def polygon(self) -> NDArray[np.float64]:
        """The outline of the region (the sensor's position first unless it sees all round), shape (K, 2)."""
        x, y, yaw = self.pose
        theta = yaw + self.angles
        rim = np.column_stack([x + self.reach * np.cos(theta), y + self.reach * np.sin(theta)])
        return rim if self.full_circle else np.vstack([[x, y], rim])

    @property
    def area(self) -> float:
        """Square metres of the fan (each ray a sector of its reach); not clipped to the map or to free space."""
        n = len(self.angles)
        step = 2 * np.pi / n if self.full_circle else math.radians(self.fov_deg) / max(n - 1, 1)
        weights = np.full(n, step)
        if not self.full_circle and n > 1:
            weights[[0, -1]] = step / 2
        return float(0.5 * np.sum(self.reach ** 2 * weights))


def fan_angles(fov_deg: float, rays: int) -> NDArray[np.float64]:
    """The directions of a sensor's ``rays`` relative to its heading: evenly round a full circle, or
    spanning the field of view edge to edge (at least two)."""
    if fov_deg >= 360:
        return np.asarray(-np.pi + np.arange(rays) * (2 * np.pi / rays), dtype=np.float64)
    span = math.radians(fov_deg)
    return np.asarray(np.linspace(-span / 2, span / 2, max(rays, 2)), dtype=np.float64)


def visible_region(m: Map, pose: ArrayLike, sensor: Sensor | None = None, rays: int | None = None) -> VisibleRegion:
    """Cast the sensor's rays from ``pose`` through the map's grid once.

    ``rays`` defaults to enough that neighbouring rays are at most half a grid cell apart at
    full range.
    """
    s = sensor or m.sensor
    x, y, yaw = as_pose(pose)
    span = math.radians(s.fov_deg)
    if rays is None:
        rays = max(8, math.ceil(span * s.range / (m.grid.resolution / 2)))
    angles = fan_angles(s.fov_deg, rays)
    reach = cast_rays(m.grid, (x, y), yaw + angles, s.range)
    return VisibleRegion((x, y, yaw), s.range, s.fov_deg, angles, reach)


def visible_mask(m: Map, pose: ArrayLike, points: ArrayLike, sensor: Sensor | None = None) -> NDArray[np.bool_]:
    """Whether each point is in the region visible from ``pose`` (ray-fan version of :func:`visible`).

    For many points at one pose; to test several sets of points, build :func:`visible_region` once.
    """
    return visible_region(m, pose, sensor).contains(points)


@dataclass(frozen=True)
class Detection:
    """An object of class ``cls`` seen at ``at``."""

    cls: str
    at: tuple[float, float]

    def to_json(self) -> dict[str, object]:
        return {"class": self.cls, "at": [round(self.at[0], 4), round(self.at[1], 4)]}
