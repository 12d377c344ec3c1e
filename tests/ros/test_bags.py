"""Reading a robot's run out of bags that the tests write with rosbags: every format, every pose source,
transforms chained and interpolated, and each kind of bad bag refused with one clear message."""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest

pytest.importorskip("rosbags")

from seal_cli.errors import SealError  # noqa: E402
from seal_cli.ros.bags import read_run  # noqa: E402
from seal_cli.ros.grids import read_occupancy_grid  # noqa: E402
from seal_cli.ros.messages import POSE_STAMPED  # noqa: E402
from seal_cli.ros.writing import pose_stamped, write_bag  # noqa: E402
from tests.ros.bagfiles import occupancy_grid, run_messages, store_for, write_run  # noqa: E402

POSES = [(10.0 + 0.5 * i, -6.0 + 0.1 * i, -3.0, 0.1 * i) for i in range(20)]
"""(t, x, y, yaw): base_link in map, along the living room, turning."""
LOOKS = [(10.25 + i, "map", [("spoon", 7.0, -5.0, 0.8)]) for i in range(5)] + [(15.3, "base_link", [("cup", 1.0, 0.0,
                                                                                                        0.5)])]
NAMES = ["run.mcap", "run_db3", "run.bag"]
"""A single MCAP file, a ROS 2 sqlite3 folder, a ROS 1 bag."""


def expected_pose(t: float) -> tuple[float, float, float]:
    f = (t - 10.0) / 0.5
    return (-6.0 + 0.1 * f, -3.0, 0.1 * f)


def looks_for(name: str) -> list:
    """ROS 1's vision_msgs carry integer class ids: 1 stands for spoon, 2 for cup."""
    if not name.endswith(".bag"):
        return LOOKS
    return [(t, frame, [({"spoon": 1, "cup": 2}[c], x, y, z) for c, x, y, z in seen]) for t, frame, seen in LOOKS]


@pytest.mark.parametrize("source", ["pose", "odom", "tf"])
@pytest.mark.parametrize("name", NAMES)
def test_every_format_and_pose_source_gives_the_same_run(tmp_path: Path, name: str, source: str) -> None:
    bag = write_run(tmp_path / name, POSES, looks_for(name), pose_source=source, odom=(1.0, 2.0, 0.5))
    run = read_run(bag)
    assert run.pose_source == {"pose": "/robot_pose", "odom": "/odom", "tf": "/tf"}[source]
    assert run.detections_topic == "/detections" and run.skipped == 0
    assert run.stamps == pytest.approx([t for t, _, _ in LOOKS])
    for obs, (t, _, _) in zip(run.observations, LOOKS, strict=True):
        assert obs.pose == pytest.approx(expected_pose(t), abs=1e-5)  # interpolated (nlerp) between two poses
    spoon = "1" if name.endswith(".bag") else "spoon"
    assert run.observations[0].detections == ((spoon, pytest.approx((7.0, -5.0))),)
    # the cup was seen 1 m ahead of the robot: carried into the map through the pose at 15.3 s
    x, y, yaw = expected_pose(15.3)
    cls, at = run.observations[-1].detections[0]
    assert cls == ("2" if name.endswith(".bag") else "cup")
    assert at == pytest.approx((x + math.cos(yaw), y + math.sin(yaw)), abs=1e-5)


def test_detection_2d_positions_come_from_the_hypothesis_pose(tmp_path: Path) -> None:
    bag = write_run(tmp_path / "run.mcap", POSES, LOOKS, three_d=False)
    run = read_run(bag)
    assert run.observations[0].detections == (("spoon", pytest.approx((7.0, -5.0))),)


def test_detections_in_a_camera_frame_are_chained_through_tf(tmp_path: Path) -> None:
    """base_link → camera is static, 0.2 m ahead and turned left by 90°; odom → base_link moves."""
    from seal_cli.ros.messages import TF
    from tests.ros.bagfiles import tf_message

    path = tmp_path / "run.mcap"
    messages = run_messages(path, POSES, [(12.0, "camera", [("cup", 1.0, 0.0, 0.0)])], pose_source="tf")
    store = store_for(path)
    messages.insert(0, ("/tf_static", TF, 10.0, tf_message(store, 10.0, [("base_link", "camera", 0.2, 0.0,
                                                                           math.pi / 2)], False)))
    write_bag(path, messages, store)
    run = read_run(path)
    x, y, yaw = expected_pose(12.0)
    ahead = (x + 0.2 * math.cos(yaw), y + 0.2 * math.sin(yaw))
    assert run.observations[0].detections[0][1] == pytest.approx((ahead[0] - math.sin(yaw), ahead[1] + math.cos(yaw)))


def test_an_empty_detection_array_is_a_look_that_saw_nothing(tmp_path: Path) -> None:
    bag = write_run(tmp_path / "run.mcap", POSES, [(11.0, "map", [])])
    assert read_run(bag).observations[0].detections == ()


def test_detections_outside_the_poses_time_are_skipped(tmp_path: Path) -> None:
    bag = write_run(tmp_path / "run.mcap", POSES, [(10.5, "map", []), (10.0 - 0.3, "map", []), (40.0, "map", [])])
    run = read_run(bag)
    assert run.skipped == 1 and run.stamps == pytest.approx([9.7, 10.5])  # within 0.5 s: held at the first pose
    assert run.observations[0].pose == pytest.approx(expected_pose(10.0))


def test_a_topic_named_explicitly_is_used(tmp_path: Path) -> None:
    path = tmp_path / "run.mcap"
    messages = run_messages(path, POSES, LOOKS)
    store = store_for(path)
    messages += [("/other_pose", POSE_STAMPED, t, pose_stamped(store, t, "map", 0.0, 0.0, 0.0, False))
                 for t, *_ in POSES]
    write_bag(path, sorted(messages, key=lambda m: m[2]), store)
    with pytest.raises(SealError, match="several robot pose topics .*/other_pose, /robot_pose.*--pose-topic"):
        read_run(path)
    assert read_run(path, pose_topic="/other_pose").observations[0].pose == (0.0, 0.0, 0.0)


# -- bad bags ----------------------------------------------------------------------------------------
def message_of(path: Path, **kwargs: object) -> str:
    with pytest.raises(SealError) as caught:
        read_run(path, **kwargs)  # type: ignore[arg-type]
    return str(caught.value)


def test_not_a_bag(tmp_path: Path) -> None:
    (tmp_path / "notes.bag").write_text("not a bag\n")
    assert "cannot read this as a ROS bag" in message_of(tmp_path / "notes.bag")
    (tmp_path / "cut.mcap").write_bytes(b"\x89MCAP0\r\n" + b"\x00" * 10)
    assert "cannot read this as a ROS bag" in message_of(tmp_path / "cut.mcap")
    assert message_of(tmp_path / "absent.mcap").endswith("no such bag")


@pytest.mark.parametrize("name", NAMES)
def test_a_bag_named_as_another_format_is_told_to_be_renamed(tmp_path: Path, name: str) -> None:
    # an MCAP saved as run.bag said "utf-8 b'\\x89MCAP0\\r\\n' 0 1 invalid start byte" (hostile17)
    import shutil

    bag = write_run(tmp_path / name, POSES, looks_for(name))
    if bag.is_dir():
        bag = next(bag.glob("*.db3"))
    right = {".mcap": ".mcap", ".db3": ".db3", ".bag": ".bag"}[bag.suffix]
    for wrong in (".bag", ".mcap", ".db3", ""):
        if wrong != right:
            moved = shutil.copy(bag, tmp_path / f"moved{wrong}")
            said = message_of(Path(moved))
            assert said.endswith(f"seal reads a bag by its name's suffix; rename it to end in {right}")
    assert read_run(bag).observations


def test_a_link_loop_and_a_folder_without_metadata_are_said_as_they_are(tmp_path: Path) -> None:
    # a link loop was "no such bag" here and a RuntimeError traceback in import-bag (hostile17)
    (tmp_path / "loop.mcap").symlink_to("loop.mcap")
    assert message_of(tmp_path / "loop.mcap").endswith("cannot read this bag: Too many levels of symbolic links")
    (tmp_path / "empty").mkdir()
    assert "this folder is no ROS 2 bag: it has no metadata.yaml" in message_of(tmp_path / "empty")


def test_missing_topics(tmp_path: Path) -> None:
    bag = write_run(tmp_path / "run.mcap", POSES, LOOKS)
    assert "no topic /camera/detections in the bag (its topics: /detections (vision_msgs/msg/Detection3DArray)" \
        in message_of(bag, detections_topic="/camera/detections")
    assert "/detections holds vision_msgs/msg/Detection3DArray, not robot pose" in message_of(bag,
                                                                                               pose_topic="/detections")
    only_poses = tmp_path / "poses.mcap"
    write_bag(only_poses, [m for m in run_messages(only_poses, POSES, LOOKS) if m[0] != "/detections"])
    assert "the bag has no detection topic" in message_of(only_poses)


def test_unknown_frames(tmp_path: Path) -> None:
    bag = write_run(tmp_path / "run.mcap", POSES, [(11.0, "camera", [("cup", 1.0, 0.0, 0.0)])], pose_source="tf")
    assert "cannot carry the detections on frame 'camera' into 'map': frame 'camera' is not in the transforms " \
           "(known frames: base_link, map, odom)" in message_of(bag)
    assert "the transforms do not place 'base_link' in 'world'" in message_of(bag, frame="world")


def test_clock_jumps(tmp_path: Path) -> None:
    """The third detection message is logged at 14 s, but its header says 2 s."""
    from seal_cli.ros.messages import DETECTION_3D
    from tests.ros.bagfiles import detections

    bag = tmp_path / "run.mcap"
    store = store_for(bag)
    messages = run_messages(bag, POSES, [(12.0, "map", []), (13.0, "map", [])])
    messages.append(("/detections", DETECTION_3D, 14.0, detections(store, 2.0, "map", [], False)))
    write_bag(bag, sorted(messages, key=lambda m: m[2]), store)
    assert "the clock of /detections jumps back 11.000 s at message 3" in message_of(bag)


def test_poses_and_detections_on_different_clocks(tmp_path: Path) -> None:
    bag = write_run(tmp_path / "run.mcap", POSES, [(1.7e9 + t, "map", []) for t, _, _ in LOOKS])
    assert "no message on /detections falls within the poses' time span [10.000, 19.500] s" in message_of(bag)
    assert "different clocks" in message_of(bag)


def test_a_grid_is_read_with_its_origin_and_rows(tmp_path: Path) -> None:
    path = tmp_path / "map.mcap"
    values = np.zeros((4, 6), np.int8)
    values[0, :] = 100  # the lowest row is a wall
    values[3, 5] = -1
    store = store_for(path)
    write_bag(path, [("/map", "nav_msgs/msg/OccupancyGrid", 1.0,
                      occupancy_grid(store, 1.0, values, 0.5, (-1.0, -2.0, 0.0), False))], store)
    grid = read_occupancy_grid(path)
    assert grid.values.tolist() == values.tolist() and grid.resolution == 0.5 and grid.origin == (-1.0, -2.0, 0.0)
    with pytest.raises(SealError, match="no topic /costmap in the bag \\(its occupancy grids: /map\\)"):
        read_occupancy_grid(path, "/costmap")


def test_a_single_moving_pose_places_only_what_is_near_its_stamp(tmp_path: Path) -> None:
    """One message on /tf is not a static transform: detections far from its stamp are not placed at it."""
    bag = write_run(tmp_path / "run.mcap", POSES[:1], [(10.2, "map", []), (30.0, "map", [])], pose_source="tf")
    run = read_run(bag)
    assert run.stamps == pytest.approx([10.2]) and run.skipped == 1


def test_a_localiser_pose_over_odometry_transforms_carries_robot_frame_detections(tmp_path: Path) -> None:
    """/robot_pose in map (a localiser), /tf only odom → base_link (drifted 1 m off): a detection in base_link
    reaches map through the localiser's pose, not through the drifted odometry."""
    from seal_cli.ros.messages import TF
    from tests.ros.bagfiles import tf_message

    path = tmp_path / "run.mcap"
    store = store_for(path)
    messages = run_messages(path, POSES, [(12.0, "base_link", [("cup", 1.0, 0.0, 0.0)])], pose_source="pose")
    messages += [("/tf", TF, t, tf_message(store, t, [("odom", "base_link", x + 1.0, y, yaw)], False))
                 for t, x, y, yaw in POSES]
    write_bag(path, sorted(messages, key=lambda m: m[2]), store)
    run = read_run(path)
    assert run.pose_source == "/robot_pose"
    x, y, yaw = expected_pose(12.0)
    assert run.observations[0].pose == pytest.approx((x, y, yaw), abs=1e-5)
    assert run.observations[0].detections[0][1] == pytest.approx((x + math.cos(yaw), y + math.sin(yaw)), abs=1e-5)


def test_values_seal_would_refuse_are_refused_at_their_message(tmp_path: Path) -> None:
    """hostile18: a NaN pose, a detection at infinity or 10³⁰⁰ m, 5,000 detections in one message were imported into
    an observations file that seal itself then refused."""
    poses = [(1.0, -6.0, -3.0, 0.0), (2.0, math.nan, -3.0, 0.0), (3.0, -5.0, -3.0, 0.0)]
    write_run(tmp_path / "nan.mcap", poses, [(2.5, "map", [("cup", 1.0, 1.0, 0.0)])])
    said = message_of(tmp_path / "nan.mcap")
    assert "the pose of message 2 on /robot_pose" in said and "(nan, -3, 0, 0, 0, 0, 1)" in said
    good = [(1.0, -6.0, -3.0, 0.0), (3.0, -5.0, -3.0, 0.0)]
    for x in (math.inf, 1e300):
        write_run(tmp_path / "far.mcap", good, [(2.0, "map", [("cup", 1.0, 1.0, 0.0), ("cup", x, 1.0, 0.0)])])
        assert "the position of detection 2 of message 1 on /detections" in message_of(tmp_path / "far.mcap")
    write_run(tmp_path / "many.mcap", good, [(2.0, "map", [("cup", 1.0, 1.0, 0.0)] * 1001)])
    assert "message 1 on /detections holds 1,001 detections: seal takes at most 1,000" in message_of(
        tmp_path / "many.mcap")
    write_run(tmp_path / "ok.mcap", good, [(2.0, "map", [("cup", 1.0, 1.0, 0.0)] * 1000)])
    assert len(read_run(tmp_path / "ok.mcap").observations[0].detections or ()) == 1000


def test_more_messages_than_observations_seal_takes_are_refused(tmp_path: Path,
                                                                monkeypatch: pytest.MonkeyPatch) -> None:
    from seal_cli.ros import bags

    monkeypatch.setattr(bags, "MAX_OBSERVATIONS", 3)
    good = [(1.0, -6.0, -3.0, 0.0), (3.0, -5.0, -3.0, 0.0)]
    write_run(tmp_path / "b.mcap", good, [(1.5 + 0.1 * i, "map", []) for i in range(3)])
    assert len(read_run(tmp_path / "b.mcap").observations) == 3
    write_run(tmp_path / "b.mcap", good, [(1.5 + 0.1 * i, "map", []) for i in range(4)])
    assert "/detections holds more than 3 messages" in message_of(tmp_path / "b.mcap")


@pytest.mark.parametrize("source", ["pose", "tf"])
@pytest.mark.parametrize("rotation", [(0.0, 0.0, 0.0, 0.0), (0.0, 0.0, 3.5, 0.5), (0.0, 0.0, 0.1, 0.9)])
def test_a_rotation_that_is_no_unit_quaternion_is_refused(tmp_path: Path, source: str,
                                                          rotation: tuple[float, ...]) -> None:
    """hostile19: a ROS 1 pose left at its default orientation (0, 0, 0, 0), or a damaged byte in it, scaled every
    detection it carried (seal's rotations assume a unit quaternion), and was imported."""
    path = tmp_path / f"b{source}.mcap"
    messages = run_messages(path, [(1.0, -6.0, -3.0, 0.0), (3.0, -5.0, -3.0, 0.0)],
                            [(2.0, "base_link", [("cup", 1.0, 1.0, 0.0)])], pose_source=source)
    topic = "/robot_pose" if source == "pose" else "/tf"
    last = [m for m in messages if m[0] == topic][-1][3]
    q = last.pose.orientation if source == "pose" else last.transforms[0].transform.rotation
    q.x, q.y, q.z, q.w = rotation
    write_bag(path, messages, store_for(path))
    said = message_of(path)
    assert f"of message 2 on {topic} (qx, qy, qz, qw) is (" in said and "a rotation is a unit quaternion" in said
    q.x, q.y, q.z, q.w = (0.0, 0.0, 0.6, 0.8)  # a unit quaternion: read
    write_bag(path, messages, store_for(path))
    assert len(read_run(path).observations) == 1


def test_a_damaged_index_is_said_as_damage() -> None:
    """hostile19: a ROS 1 bag with a flipped byte in its index said 'cannot read /tf from the bag: 60673' (a
    KeyError) or nothing at all (an AssertionError inside rosbags)."""
    from seal_cli.ros.reader import damage

    assert damage(KeyError(60673)).startswith("the bag is damaged: a record or its index does not hold what its "
                                              "header says (KeyError: 60673)")
    assert "(AssertionError)" in damage(AssertionError())
    assert damage(ValueError("Truncated record at offset 43")) == "Truncated record at offset 43"


def test_messages_stamped_zero_among_stamped_ones_are_left_out_with_a_note(tmp_path: Path) -> None:
    """robot5: under use_sim_time, nodes stamp 0 until Gazebo's /clock arrives; the bag logs them at wall time. Two
    such transforms on /tf and a detection message stamped 0 were placed at their log time (1.7e9 s) and the whole
    bag was refused as a clock jump of 1.7e9 s."""
    from seal_cli.ros.messages import DETECTION_3D, TF
    from tests.ros.bagfiles import detections, tf_message

    path = tmp_path / "run.mcap"
    store = store_for(path)
    wall = 1.7e9
    messages = run_messages(path, POSES, [(11.0, "map", [("cup", 1.0, 1.0, 0.0)])], pose_source="tf")
    messages = [(topic, kind, wall + t, m) for topic, kind, t, m in messages]  # logged at wall time
    early = [("/tf", TF, wall + 9.0 + 0.1 * k, tf_message(store, 0.0, [("odom", "base_link", 5.0, 5.0, 0.0)], False))
             for k in range(2)]
    early.append(("/detections", DETECTION_3D, wall + 9.5, detections(store, 0.0, "map", [("cup", 2.0, 2.0, 0.0)],
                                                                       False)))
    write_bag(path, early + messages, store)
    run = read_run(path)
    assert run.stamps == pytest.approx([11.0])  # the detection stamped 0 is left out, the one at 11 s kept
    assert run.observations[0].pose == pytest.approx(expected_pose(11.0), abs=1e-5)  # not pulled to (5, 5)
    assert run.observations[0].where is not None and "message 2" in str(run.observations[0].where)
    assert any("2 of 22 transforms on /tf (odom → base_link) are stamped 0" in note for note in run.notes)
    assert any("1 of 2 messages on /detections are stamped 0" in note and "use_sim_time" in note
               for note in run.notes)


def test_a_topic_never_stamped_is_placed_at_the_times_the_bag_logged_it(tmp_path: Path) -> None:
    from seal_cli.ros.messages import DETECTION_3D
    from tests.ros.bagfiles import detections

    path = tmp_path / "run.mcap"
    store = store_for(path)
    messages = run_messages(path, POSES, [])
    messages += [("/detections", DETECTION_3D, t, detections(store, 0.0, "map", [], False)) for t in (11.0, 12.5)]
    write_bag(path, sorted(messages, key=lambda m: m[2]), store)
    run = read_run(path)
    assert run.stamps == pytest.approx([11.0, 12.5]) and run.notes == ()


@pytest.mark.parametrize("three_d", [False, True])
def test_a_detection_with_no_position_is_refused_not_put_at_the_camera(tmp_path: Path, three_d: bool) -> None:
    """robot5: a 2-D detector (boxes in the image, no depth) publishes Detection2DArray with the hypothesis's pose
    left at (0, 0, 0); every detection was read as an object at the camera's own origin."""
    bag = write_run(tmp_path / "run.mcap", POSES, [(12.0, "camera_optical", [("cup", 0.0, 0.0, 0.0)])],
                    pose_source="tf", three_d=three_d)
    said = message_of(bag)
    assert "detection 1 (cup) of message 1 on /detections is at (0, 0, 0) in frame 'camera_optical'" in said
    assert ("bbox.center" if three_d else "results[].pose.pose") in said and "without depth" in said
    # at the origin of the map frame itself is a place like any other
    write_run(tmp_path / "origin.mcap", POSES, [(12.0, "map", [("cup", 0.0, 0.0, 0.0)])], three_d=three_d)
    assert read_run(tmp_path / "origin.mcap").observations[0].detections == (("cup", (0.0, 0.0)),)


@pytest.mark.parametrize(("quaternion", "yaw"), [((0.0, 0.0, 1.0, 0.0), math.pi), ((0.0, 0.0, 0.0, 0.0), 0.0),
                                                 ((0.0, 0.0, math.sin(0.25), math.cos(0.25)), 0.5)])
def test_a_grids_origin_turn_is_read_from_its_quaternion(tmp_path: Path, quaternion: tuple[float, ...],
                                                         yaw: float) -> None:
    """robot5: an origin turned by half a turn, (0, 0, 1, 0), was read as a quarter turn (its w = 0 taken for ROS 1's
    default orientation (0, 0, 0, 0) and replaced by 1)."""
    path = tmp_path / "map.mcap"
    store = store_for(path)
    grid = occupancy_grid(store, 1.0, np.zeros((2, 3), np.int8), 0.5, (1.0, 2.0, 0.0), False)
    o = grid.info.origin.orientation
    o.x, o.y, o.z, o.w = quaternion
    write_bag(path, [("/map", "nav_msgs/msg/OccupancyGrid", 1.0, grid)], store)
    assert read_occupancy_grid(path).origin == pytest.approx((1.0, 2.0, yaw))


@pytest.mark.parametrize("source", ["tf", "odom"])
def test_a_run_without_a_localiser_is_told_how_to_go_on(tmp_path: Path, source: str) -> None:
    """robot5: a bag of odometry alone (no localiser running: no map → odom, no /amcl_pose) was refused with `frame
    'map' is not in the transforms`, and nothing said what to record or which --frame to give."""
    path = tmp_path / "run.mcap"
    messages = [m for m in run_messages(path, POSES, [(11.0, "base_link", [("cup", 1.0, 0.0, 0.0)])],
                                        pose_source=source) if m[0] != "/tf_static"]  # the static map → odom
    write_bag(path, messages, store_for(path))
    said = message_of(path)
    assert "frame 'map' is not in the transforms" in said and "give --frame odom" in said and "/amcl_pose" in said
    run = read_run(path, frame="odom")
    assert run.observations[0].pose == pytest.approx(expected_pose(11.0), abs=1e-5)  # odom is map here: (0, 0, 0)


def test_a_map_built_while_recording_is_read_from_its_last_message(tmp_path: Path) -> None:
    """robot5: slam_toolbox and gmapping republish /map as it grows; the first message, which seal read, is the few
    cells seen at the start. The last is the whole map."""
    path = tmp_path / "slam.mcap"
    store = store_for(path)
    small, whole = np.full((2, 2), -1, np.int8), np.zeros((4, 6), np.int8)
    small[0, 0] = 0
    write_bag(path, [("/map", "nav_msgs/msg/OccupancyGrid", t, occupancy_grid(store, t, grid, 0.5, (-1.0, -1.0, 0.0),
                                                                             False))
                     for t, grid in ((1.0, small), (2.0, np.zeros((3, 4), np.int8)), (3.0, whole))], store)
    assert read_occupancy_grid(path).values.shape == (4, 6)
    empty = tmp_path / "empty.mcap"
    write_bag(empty, run_messages(empty, POSES, LOOKS), store)
    with pytest.raises(SealError, match="no topic /map in the bag \\(it holds no occupancy grid\\)"):
        read_occupancy_grid(empty)


def test_a_transform_never_stamped_beside_stamped_ones_takes_the_log_times(tmp_path: Path) -> None:
    """A robot on wall time whose one publisher never stamps its transform (map → odom at stamp 0, every time): that
    edge is placed at the times the bag logged it, as before robot5, not left out."""
    from seal_cli.ros.messages import TF
    from tests.ros.bagfiles import tf_message

    path = tmp_path / "run.mcap"
    store = store_for(path)
    messages = [m for m in run_messages(path, POSES, [(11.0, "map", [])], pose_source="tf") if m[0] != "/tf_static"]
    messages += [("/tf", TF, t, tf_message(store, 0.0, [("map", "odom", 0.0, 0.0, 0.0)], False)) for t, *_ in POSES]
    write_bag(path, sorted(messages, key=lambda m: m[2]), store)
    run = read_run(path)
    assert run.observations[0].pose == pytest.approx(expected_pose(11.0), abs=1e-5) and run.notes == ()
