"""The sensor model: one interface (visible, region, detect) for SeFM, the world and the policies."""

from __future__ import annotations

import numpy as np
import pytest

from seal_cli.errors import SealError
from seal_cli.maps.geometry import OccupancyGrid
from seal_cli.maps.model import Map, ObjectTruth, Robot, Room, Sensor
from seal_cli.sensing.model import SENSORS, RangeSensor, SensorModel, sensor_for, simulate_detections
from seal_cli.sim.world import Item, World
from seal_cli.sim.world import Robot as WorldRobot


def walled(x_wall: float = 2.0) -> Map:
    """A 6 m × 2 m strip with a wall across it at ``x_wall``."""
    res = 0.1
    ys, xs = (np.mgrid[0:20, 0:60] + 0.5) * res
    wall = np.abs(xs - x_wall) < 0.06
    grid = OccupancyGrid.from_masks(~wall, res, (0.0, 0.0, 0.0), wall)
    return Map("strip", (0.0, 0.0, 6.0, 2.0), (Room.box("strip", 0.0, 0.0, 6.0, 2.0),), (), {},
               (ObjectTruth("cup", (1.0, 1.0)), ObjectTruth("cup", (3.0, 1.0))), Robot((0.5, 1.0, 0.0)),
               Sensor(range=5.0, p_detect=0.5), grid)


def test_range_and_field_of_view_without_walls() -> None:
    sensor = RangeSensor(Sensor(range=2.0, fov_deg=90.0))
    points = np.array([[1.0, 0.0], [3.0, 0.0], [-1.0, 0.0], [1.0, 0.9]])
    assert sensor.visible((0.0, 0.0, 0.0), points).tolist() == [True, False, False, True]
    assert sensor.line_of_sight((0.0, 0.0), points).all()
    assert sensor.region((0.0, 0.0, 0.0)).contains(points).tolist() == [True, False, False, True]


def test_walls_cut_the_view_and_the_region_agrees_with_the_exact_answer() -> None:
    m = walled()
    sensor = RangeSensor.on_map(m)
    assert isinstance(sensor, SensorModel)
    points = np.array([[1.0, 1.0], [3.0, 1.0], [1.9, 0.5]])
    assert sensor.visible((0.5, 1.0, 0.0), points).tolist() == [True, False, True]
    assert sensor.region((0.5, 1.0, 0.0)).contains(points).tolist() == [True, False, True]


def test_detections_follow_the_detection_probability_and_never_see_through_walls() -> None:
    m = walled()
    sensor = RangeSensor.on_map(m)
    assert [d.at for d in sensor.detect((0.5, 1.0, 0.0), [("cup", (1.0, 1.0)), ("cup", (3.0, 1.0))])] == [(1.0, 1.0)]
    rng = np.random.default_rng(0)
    hits = sum(len(simulate_detections(m, (0.5, 1.0, 0.0), rng=rng)) for _ in range(400))
    assert 160 < hits < 240  # p_detect 0.5 of the one visible cup; the cup behind the wall never


def test_the_registry_builds_a_sensor_and_refuses_an_unknown_one() -> None:
    m = walled()
    assert isinstance(sensor_for(m), RangeSensor) and "range" in SENSORS
    with pytest.raises(SealError, match="unknown sensor model 'lidar'; the models are range"):
        sensor_for(m, "lidar")


class Blinkered:
    """A sensor of one's own: it sees only ahead along +x, within 1 m (a new model is one class)."""

    spec = Sensor(range=1.0)
    range = 1.0

    def visible(self, pose, points):  # type: ignore[no-untyped-def]
        p = np.asarray(points, dtype=float).reshape(-1, 2)
        return (p[:, 0] >= pose[0]) & (np.hypot(*(p - np.asarray(pose[:2])).T) <= 1.0)

    def line_of_sight(self, origin, points):  # type: ignore[no-untyped-def]
        return np.ones(len(points), dtype=bool)

    def region(self, pose, rays=None):  # type: ignore[no-untyped-def]
        return RangeSensor(self.spec).region(pose, rays)

    def detect(self, pose, things, rng=None):  # type: ignore[no-untyped-def]
        return []


def test_the_world_sees_through_any_sensor_model() -> None:
    items = [Item("cup_1", "cup", (0.8, 0.0), movable=True), Item("cup_2", "cup", (-0.8, 0.0), movable=True)]
    world = World(items, WorldRobot(pose=(0.0, 0.0, 0.0)), sensor=Blinkered())
    assert [d.id for d in world.observe()] == ["cup_1"]


def test_a_simulated_detection_near_the_edge_stays_on_the_map() -> None:
    """hostile19: a noisy detection of the apartment's apple (0.5 m from the map's edge) fell outside its bounds
    once in a few thousand, and SeFM refused its own simulator's report (``bench ros --messages 3000`` failed)."""
    m = Map("edge", bounds=(0.0, 0.0, 10.0, 10.0), objects=(ObjectTruth("apple", (9.9, 9.9)),))
    sensor = RangeSensor.on_map(m, Sensor(range=5.0, p_detect=1.0, noise=1.0))
    rng = np.random.default_rng(0)
    seen = [d.at for _ in range(50) for d in sensor.detect((8.0, 8.0, 0.0), [("apple", (9.9, 9.9))], rng)]
    assert len(seen) == 50 and all(0.0 <= x <= 10.0 and 0.0 <= y <= 10.0 for x, y in seen)
    assert any(x == 10.0 or y == 10.0 for x, y in seen)  # some would have fallen outside
