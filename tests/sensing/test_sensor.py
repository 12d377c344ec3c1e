"""The sensor: range, field of view, line of sight, closed places, and simulated detections."""

from __future__ import annotations

import functools
import math
from pathlib import Path

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from seal_cli.maps.formats.map_server import load_map
from seal_cli.maps.geometry import OCCUPIED, OccupancyGrid
from seal_cli.maps.model import Map, ObjectTruth, Place, Room, Sensor
from seal_cli.sensing.model import closed_places, simulate_detections, visible_objects
from seal_cli.sensing.sensor import Detection, as_pose, in_view, visible, visible_mask, visible_region

APARTMENT = Path(__file__).resolve().parents[2] / "maps" / "apartment.yaml"


@functools.cache
def cached_apartment() -> Map:
    return load_map(APARTMENT)


@pytest.fixture(scope="module")
def apartment() -> Map:
    return cached_apartment()


def walled_room() -> Map:
    """10 m × 10 m at 0.1 m, a wall along x in [5, 5.1) with a door at y in [4, 5); a fridge and a table."""
    cells = np.zeros((100, 100), dtype=np.int8)
    cells[:, 50] = OCCUPIED
    cells[40:50, 50] = 0
    grid = OccupancyGrid(cells, 0.1)
    return Map("walled", grid=grid, rooms=(Room.box("west", 0, 0, 5, 10), Room.box("east", 5, 0, 10, 10)),
               places=(Place("fridge_1", "fridge", (8.0, 1.0), openable=True), Place("table_1", "table", (2.0, 2.0))),
               objects=(ObjectTruth("apple", (8.0, 1.0), "fridge_1"), ObjectTruth("cup", (2.0, 2.0), "table_1"),
                        ObjectTruth("spoon", (7.0, 8.0))),
               sensor=Sensor(range=6.0, fov_deg=360.0, p_detect=0.5, noise=0.1))


def test_poses() -> None:
    assert as_pose([1, 2]) == (1.0, 2.0, 0.0)
    assert as_pose((1, 2, 3)) == (1.0, 2.0, 3.0)
    with pytest.raises(ValueError):
        as_pose([1, 2, 3, 4])


def test_range_and_field_of_view() -> None:
    sensor = Sensor(range=2.0, fov_deg=90.0)
    pose = (0.0, 0.0, math.pi / 2)  # facing +y
    points = [[0, 1.9], [0, 2.1], [1.0, 1.1], [1.1, 1.0], [0, -1], [-1.0, 1.01]]
    assert in_view(sensor, pose, points).tolist() == [True, False, True, False, False, True]
    assert in_view(Sensor(range=2.0), pose, [[0, -1.9]]).tolist() == [True]  # 360° sees behind


def test_walls_hide_and_doors_show() -> None:
    m = walled_room()
    seen = visible(m, (2.0, 4.5, 0.0), [[7.0, 4.5], [7.0, 2.0], [4.9, 2.0], [7.0, 8.0]])
    assert seen.tolist() == [True, False, True, False]  # through the door; behind the wall; same side; too far round


def test_closed_places_hide_their_contents() -> None:
    m = walled_room()
    pose = (7.0, 2.0, 0.0)
    assert closed_places(m) == {"fridge_1"}
    assert [o.cls for o in visible_objects(m, pose)] == ["spoon"]
    assert [o.cls for o in visible_objects(m, pose, open_places=["Fridge_1"])] == ["apple", "spoon"]
    assert simulate_detections(m, pose, open_places=["fridge_1"]) == [Detection("apple", (8.0, 1.0)),
                                                                     Detection("spoon", (7.0, 8.0))]
    # the cup is on a table (not openable): visible from the west side, not through the wall
    assert [d.cls for d in simulate_detections(m, (1.0, 1.0, 0.0))] == ["cup"]


def test_simulated_detections_are_reproducible_and_noisy_as_declared() -> None:
    m = walled_room()
    pose = (7.0, 2.0, 0.0)
    rng, other = np.random.default_rng(7), np.random.default_rng(7)
    first = [simulate_detections(m, pose, ["fridge_1"], rng) for _ in range(2000)]
    again = [simulate_detections(m, pose, ["fridge_1"], other) for _ in range(2000)]
    assert first == again
    counts = [len(d) for d in first]
    assert np.mean(counts) == pytest.approx(2 * 0.5, abs=0.06)  # two visible objects, p_detect 0.5
    offsets = np.array([np.subtract(d.at, (7.0, 8.0)) for ds in first for d in ds if d.cls == "spoon"])
    assert offsets.std(axis=0) == pytest.approx([0.1, 0.1], rel=0.1)
    exact = Sensor(range=6.0, p_detect=1.0, noise=0.0)
    assert simulate_detections(m, pose, ["fridge_1"], np.random.default_rng(0), exact) == \
        simulate_detections(m, pose, ["fridge_1"])
    assert simulate_detections(m, pose, rng=np.random.default_rng(0), sensor=Sensor(p_detect=0.0)) == []
    assert Detection("cup", (1.0, 2.0)).to_json() == {"class": "cup", "at": [1.0, 2.0]}


def test_the_region_agrees_with_the_exact_test(apartment: Map) -> None:
    rng = np.random.default_rng(0)
    points = apartment.sample_free(rng, 20_000)
    for pose in [(-6.0, -3.0, 0.0), (0.0, 0.0, 1.0), (7.0, -3.0, 2.0), (5.0, 3.0, -1.0), (-8.9, 5.9, 0.3)]:
        region = visible_region(apartment, pose)
        exact = visible(apartment, pose, points)
        assert (region.contains(points) == exact).mean() > 0.998, pose
        assert np.array_equal(visible_mask(apartment, pose, points), region.contains(points))


@settings(max_examples=25, deadline=None)
@given(st.floats(-8.5, 8.5), st.floats(-5.5, 5.5), st.floats(-math.pi, math.pi), st.floats(20, 360),
       st.floats(1.0, 8.0))
def test_any_pose_and_sensor_the_region_agrees_with_the_exact_test(x: float, y: float, yaw: float, fov: float,
                                                                   reach: float) -> None:
    m = cached_apartment()
    sensor = Sensor(range=reach, fov_deg=fov)
    rng = np.random.default_rng(int(abs(x * 1000)))
    points = np.array([x, y]) + rng.uniform(-reach, reach, size=(3000, 2))
    exact = visible(m, (x, y, yaw), points, sensor)
    fast = visible_region(m, (x, y, yaw), sensor).contains(points)
    assert (fast == exact).mean() > 0.99


def test_region_area_and_outline() -> None:
    open_map = Map("open", (-10.0, -10.0, 10.0, 10.0))
    full = visible_region(open_map, (0.0, 0.0, 0.0), Sensor(range=3.0))
    assert full.area == pytest.approx(math.pi * 9, rel=1e-3)
    assert np.allclose(np.hypot(*full.polygon().T), 3.0)
    cone = visible_region(open_map, (0.0, 0.0, 0.5), Sensor(range=3.0, fov_deg=60))
    assert cone.area == pytest.approx(math.pi * 9 / 6, rel=1e-3)
    assert cone.polygon()[0].tolist() == [0.0, 0.0]
    m = walled_room()
    blocked = visible_region(m, (2.0, 2.0, 0.0))
    # the wall at x = 5 (3 m east) with a door at y in [4, 5] shades most of the east: area lost is at least
    # the part of the disc beyond the wall's line less the door's cone
    segment = 36 * math.acos(3 / 6) - 3 * math.sqrt(36 - 9)
    assert math.pi * 36 - segment * 1.05 < blocked.area < math.pi * 36 - segment * 0.6
    assert blocked.contains([[4.9, 2.0], [5.2, 2.0]]).tolist() == [True, False]
