"""sensing.observations: trajectory and observation files, every problem at file:line:column."""

from __future__ import annotations

import math
from pathlib import Path

import pytest

from seal_cli.errors import SealError, Where
from seal_cli.sensing.observations import Observation, check_inside, read_observations, read_trajectory


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
