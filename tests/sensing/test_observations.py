"""sensing.observations: trajectory and observation files, every problem at file:line:column."""

from __future__ import annotations

import math
from pathlib import Path
from typing import Any

import pytest

from seal_cli.errors import SealError, Where
from seal_cli.sensing.observations import Observation, check_inside, read_observations, read_trajectory, split_known


def write(tmp_path: Path, text: str, name: str = "f.yaml") -> Path:
    path = tmp_path / name
    path.write_text(text)
    return path


def test_a_trajectory_is_poses_with_yaw_zero_unless_given(tmp_path: Path) -> None:
    path = write(tmp_path, "poses:\n  - [-6.0, -3.0]\n  - [5.0, -4.5, 1.57]\n")
    first, second = read_trajectory(path)
    assert first == Observation((-6.0, -3.0, 0.0)) and second.pose == (5.0, -4.5, 1.57)
    assert first.detections is None and first.where == Where(str(path), 2, 5)


def test_observations_carry_their_detections(tmp_path: Path) -> None:
    path = write(tmp_path, "observations:\n  - pose: [5.0, -4.5, 0.0]\n    detections:\n"
                           "      - {class: spoon, at: [8.3, -4.1]}\n  - pose: [0.5, 2.5]\n    detections: []\n"
                           "  - pose: [1, 1]\n")
    seen, empty, bare = read_observations(path)
    assert seen.detections == (("spoon", (8.3, -4.1)),) and empty.detections == () == bare.detections
    assert read_observations(write(tmp_path, "- pose: [1, 2]\n", "list.yaml"))[0].pose == (1.0, 2.0, 0.0)


@pytest.mark.parametrize(("text", "line", "says"), [
    ("", 1, "holds no poses"),
    ("poses: 3\n", 1, "poses must be a list"),
    ("poses: []\n", 1, "poses is empty"),
    ("poses:\n  - [1]\n", 2, "pose 1"),
    ("poses:\n  - [1, nan]\n", 2, "pose 1"),
    ("where: []\n", 1, "where"),
])
def test_a_bad_trajectory_says_where(tmp_path: Path, text: str, line: int, says: str) -> None:
    path = write(tmp_path, text)
    with pytest.raises(SealError) as caught:
        read_trajectory(path)
    assert caught.value.file == str(path) and caught.value.line == line and says in caught.value.message


@pytest.mark.parametrize(("text", "line", "says"), [
    ("", 1, "holds no observations"),
    ("[]\n", 1, "empty"),
    ("- pose: [1, 2]\n  detections: 5\n", 2, "detections must be a list"),
    ("- pose: [1, 2]\n  detections:\n    - {class: 3, at: [1, 1]}\n", 3, "class must be a name"),
    ("- pose: [1, 2]\n  detections:\n    - {class: cup}\n", 3, "at"),
    # hostile30: printed as it is in the warning that set it aside (a NUL, an escape sequence on the terminal)
    ('- pose: [1, 2]\n  detections:\n    - {class: "cu\\0p", at: [1, 1]}\n', 3, "a control character"),
    ('- pose: [1, 2]\n  detections:\n    - {class: "\\e[31mcup", at: [1, 1]}\n', 3, "a control character"),
    ("- detections: []\n", 1, "pose"),
])
def test_bad_observations_say_where(tmp_path: Path, text: str, line: int, says: str) -> None:
    path = write(tmp_path, text)
    with pytest.raises(SealError) as caught:
        read_observations(path)
    assert caught.value.file == str(path) and caught.value.line == line and says in caught.value.message


def test_poses_and_detections_off_the_map_are_refused_where_they_are(tmp_path: Path) -> None:
    path = write(tmp_path, "- pose: [1, 2]\n- pose: [20, 2]\n")
    with pytest.raises(SealError, match=r"pose \[20, 2\] is outside map flat's bounds \[0, 0, 10, 10\]") as caught:
        check_inside(read_observations(path), (0, 0, 10, 10), "flat")
    assert caught.value.line == 2
    far = [Observation((1.0, 1.0, 0.0), (("cup", (1.0, 11.0)),))]
    with pytest.raises(SealError, match="a detection of cup at"):
        check_inside(far, (0, 0, 10, 10), "flat")
    check_inside([Observation((0.0, 10.0, math.pi))], (0, 0, 10, 10), "flat")   # the edge is inside


def block_map() -> Any:
    """A 6 m × 4 m room at 0.05 m, walled round, with a solid 2 m × 2 m block in its middle ([2, 4] × [1, 3])."""
    import numpy as np

    from seal_cli.maps.geometry import OccupancyGrid
    from seal_cli.maps.model import Map

    rows, cols = np.mgrid[0:80, 0:120]
    x, y = (cols + 0.5) * 0.05, (rows + 0.5) * 0.05
    occupied = (rows < 2) | (rows >= 78) | (cols < 2) | (cols >= 118) | ((x > 2) & (x < 4) & (y > 1) & (y < 3))
    return Map("block", grid=OccupancyGrid.from_masks(~occupied, 0.05, (0.0, 0.0, 0.0), occupied))


def test_a_measured_pose_on_an_occupied_cell_near_free_space_is_taken_with_a_warning() -> None:
    """robot5: a real robot's localised pose lands on the map's occupied cells (a chair mapped where it no longer
    stands, a localiser a few centimetres off by a wall); the whole bag was refused for one such pose."""
    m = block_map()
    looks = [Observation((1.0, 2.0, 0.0), (), Where("run.yaml", 1, 3)),
             Observation((2.1, 2.0, 0.0), (), Where("run.yaml", 2, 3)),   # 0.1 m into the block's edge
             Observation((0.05, 2.0, 0.0), (), Where("run.yaml", 3, 3))]  # in the outer wall
    said = check_inside(looks, m.bounds, m.name, m.is_occupied, m.is_free, 0.05)
    assert len(said) == 1 and said[0].startswith("2 of 3 poses lie on occupied cells of map block, each within 0.3 m")
    assert "[2.1, 2]" in said[0] and "run.yaml:2:3" in said[0]
    assert check_inside(looks[:1], m.bounds, m.name, m.is_occupied, m.is_free, 0.05) == []
    deep = [*looks, Observation((3.0, 2.0, 0.0), (), Where("run.yaml", 4, 3))]  # the block's middle: 0.95 m in
    with pytest.raises(SealError, match=r"pose \[3, 2\] is inside a wall or an obstacle of map block, more than 0.3 m "
                                        r"from any free cell.*in the map's frame") as caught:
        check_inside(deep, m.bounds, m.name, m.is_occupied, m.is_free, 0.05)
    assert caught.value.line == 4
    with pytest.raises(SealError, match=r"pose \[2.1, 2\] is inside a wall"):  # without is_free: every one refused
        check_inside(looks, m.bounds, m.name, m.is_occupied)


def test_detections_of_classes_no_belief_is_kept_for_are_set_aside_and_counted() -> None:
    looks = [Observation((1.0, 1.0, 0.0), (("Cup", (2.0, 2.0)), ("chair", (3.0, 3.0)), ("Chair", (3.0, 3.1)))),
             Observation((1.0, 1.0, 0.0), (("person", (2.0, 2.0)),), Where("o.yaml", 3, 3)),
             Observation((1.0, 1.0, 0.0)),                      # simulated: nothing to set aside
             Observation((1.0, 1.0, 0.0), (("spoon", (2.0, 2.0)),))]
    kept, dropped = split_known(looks, {"cup", "spoon"})
    assert dropped == {"chair": 2, "person": 1}
    assert kept[0].detections == (("Cup", (2.0, 2.0)),) and kept[1].detections == ()
    assert kept[1].where == Where("o.yaml", 3, 3) and kept[2] is looks[2] and kept[3] is looks[3]


def test_a_number_is_read_as_a_maps_numbers_are(tmp_path: Path) -> None:
    # a plain 1e-1 is text to YAML 1.1: the map read it as a number and observations refused it (hostile21)
    path = write(tmp_path, "- {pose: [1e-1, -3, 2E0], detections: []}\n")
    assert read_observations(path)[0].pose == (0.1, -3.0, 2.0)
    for value, said in (("010", r"f\.yaml:1:18: observation 1's pose's yaw cannot be read: '010' has a leading zero"),
                        ("10:00", r"f\.yaml:1:18: .* cannot be read: '10:00' is a number in base 60"),
                        (".nan", r"f\.yaml:1:18: .* must be a finite number, not '\.nan'")):
        path = write(tmp_path, f"- {{pose: [1, -3, {value}], detections: []}}\n")
        with pytest.raises(SealError, match=said):
            read_observations(path)
