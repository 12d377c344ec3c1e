"""Small bags written with rosbags for the tests: a robot's poses, its transforms, detections, a map.

Everything is built from plain values (``x, y, yaw``; ``(class, x, y, z)``) so that a test reads
like the run it describes; :func:`run_messages` lays out a whole run. ``ros1`` builds ROS 1
messages (headers with ``seq``, vision_msgs 1 with integer ids); the writer picks the bag format
from the file name (``.bag``, ``.mcap``, else a sqlite3 folder).
"""

from __future__ import annotations

from collections.abc import Sequence
from pathlib import Path
from typing import Any

import numpy as np

from seal_cli.ros.messages import DETECTION_2D, DETECTION_3D, ODOMETRY, POSE_STAMPED, TF, typestore
from seal_cli.ros.writing import Message, header, is_ros1, pose, pose_stamped, write_bag


def store_for(path: str | Path) -> Any:
    return typestore(is_ros1(path))


def _vector(store: Any, x: float, y: float, z: float) -> Any:
    return store.types["geometry_msgs/msg/Vector3"](x=float(x), y=float(y), z=float(z))


def odometry(store: Any, stamp: float, frame: str, child: str, x: float, y: float, yaw: float, ros1: bool) -> Any:
    T = store.types
    twist = T["geometry_msgs/msg/TwistWithCovariance"](twist=T["geometry_msgs/msg/Twist"](
        linear=_vector(store, 0, 0, 0), angular=_vector(store, 0, 0, 0)), covariance=np.zeros(36))
    return T[ODOMETRY](header=header(store, stamp, frame, ros1), child_frame_id=child,
                       pose=T["geometry_msgs/msg/PoseWithCovariance"](pose=pose(store, x, y, yaw),
                                                                      covariance=np.zeros(36)), twist=twist)


def tf_message(store: Any, stamp: float, edges: Sequence[tuple[str, str, float, float, float]], ros1: bool) -> Any:
    """``edges``: (parent, child, x, y, yaw)."""
    T = store.types
    transforms = []
    for parent, child, x, y, yaw in edges:
        p = pose(store, x, y, yaw)
        transforms.append(T["geometry_msgs/msg/TransformStamped"](
            header=header(store, stamp, parent, ros1), child_frame_id=child,
            transform=T["geometry_msgs/msg/Transform"](translation=_vector(store, x, y, 0), rotation=p.orientation)))
    return T[TF](transforms=transforms)


def detections(store: Any, stamp: float, frame: str, seen: Sequence[tuple[str | int, float, float, float]],
               ros1: bool, three_d: bool = True) -> Any:
    """A Detection3DArray (or 2D) of ``(class, x, y, z)`` in ``frame``, each with one hypothesis of score 0.9."""
    T = store.types
    out = []
    for cls, x, y, z in seen:
        where = T["geometry_msgs/msg/PoseWithCovariance"](pose=pose(store, x, y, 0.0, z), covariance=np.zeros(36))
        if ros1:
            hyp = T["vision_msgs/msg/ObjectHypothesisWithPose"](id=int(cls), score=0.9, pose=where)
        else:
            hyp = T["vision_msgs/msg/ObjectHypothesisWithPose"](
                hypothesis=T["vision_msgs/msg/ObjectHypothesis"](class_id=str(cls), score=0.9), pose=where)
        if three_d:
            box = T["vision_msgs/msg/BoundingBox3D"](center=pose(store, x, y, 0.0, z), size=_vector(store, .1, .1, .1))
            extra = ({"source_cloud": _empty_cloud(store, stamp, frame)} if ros1 else {"id": ""})
            out.append(T["vision_msgs/msg/Detection3D"](header=header(store, stamp, frame, ros1), results=[hyp],
                                                        bbox=box, **extra))
        else:
            centre = (T["geometry_msgs/msg/Pose2D"](x=320.0, y=240.0, theta=0.0) if ros1 else
                      T["vision_msgs/msg/Pose2D"](position=T["vision_msgs/msg/Point2D"](x=320.0, y=240.0), theta=0.0))
            box = T["vision_msgs/msg/BoundingBox2D"](center=centre, size_x=40.0, size_y=30.0)
            extra = ({"source_img": _empty_image(store, stamp, frame)} if ros1 else {"id": ""})
            out.append(T["vision_msgs/msg/Detection2D"](header=header(store, stamp, frame, ros1), results=[hyp],
                                                        bbox=box, **extra))
    kind = DETECTION_3D if three_d else DETECTION_2D
    return T[kind](header=header(store, stamp, frame, ros1), detections=out)


def _empty_image(store: Any, stamp: float, frame: str) -> Any:
    return store.types["sensor_msgs/msg/Image"](header=header(store, stamp, frame, True), height=0, width=0,
                                                encoding="", is_bigendian=0, step=0, data=np.zeros(0, np.uint8))


def _empty_cloud(store: Any, stamp: float, frame: str) -> Any:
    return store.types["sensor_msgs/msg/PointCloud2"](header=header(store, stamp, frame, True), height=0, width=0,
                                                      fields=[], is_bigendian=False, point_step=0, row_step=0,
                                                      data=np.zeros(0, np.uint8), is_dense=True)


def occupancy_grid(store: Any, stamp: float, values: np.ndarray, resolution: float,
                   origin: tuple[float, float, float], ros1: bool, frame: str = "map") -> Any:
    """``values[row, col]`` (−1 or 0..100), row 0 at the lowest y."""
    T = store.types
    height, width = values.shape
    time = header(store, stamp, frame, ros1).stamp
    info = T["nav_msgs/msg/MapMetaData"](map_load_time=time, resolution=float(resolution), width=width, height=height,
                                         origin=pose(store, *origin))
    return T["nav_msgs/msg/OccupancyGrid"](header=header(store, stamp, frame, ros1), info=info,
                                           data=np.asarray(values, np.int8).ravel())


def run_messages(path: str | Path, poses: Sequence[tuple[float, float, float, float]],
                 looks: Sequence[tuple[float, str, Sequence[tuple[str | int, float, float, float]]]],
                 pose_source: str = "pose", detections_topic: str = "/detections", three_d: bool = True,
                 odom: tuple[float, float, float] = (0.0, 0.0, 0.0)) -> list[Message]:
    """A run: ``poses`` (t, x, y, yaw) of base_link in map, and ``looks`` (t, frame, detections).

    ``pose_source``: ``pose`` (PoseStamped on /robot_pose), ``odom`` (Odometry on /odom in frame
    odom, with a static map → odom of ``odom``) or ``tf`` (map → odom static, odom → base_link on /tf).
    """
    ros1 = is_ros1(path)
    store = store_for(path)
    out: list[Message] = []
    ox, oy, oyaw = odom
    c, s = np.cos(oyaw), np.sin(oyaw)

    def in_odom(x: float, y: float, yaw: float) -> tuple[float, float, float]:
        dx, dy = x - ox, y - oy
        return c * dx + s * dy, -s * dx + c * dy, yaw - oyaw

    if pose_source in ("odom", "tf"):
        out.append(("/tf_static", TF, poses[0][0], tf_message(store, poses[0][0], [("map", "odom", *odom)], ros1)))
    for t, x, y, yaw in poses:
        if pose_source == "pose":
            out.append(("/robot_pose", POSE_STAMPED, t, pose_stamped(store, t, "map", x, y, yaw, ros1)))
        elif pose_source == "odom":
            out.append(("/odom", ODOMETRY, t, odometry(store, t, "odom", "base_link", *in_odom(x, y, yaw), ros1)))
        else:
            out.append(("/tf", TF, t, tf_message(store, t, [("odom", "base_link", *in_odom(x, y, yaw))], ros1)))
    kind = DETECTION_3D if three_d else DETECTION_2D
    for t, frame, seen in looks:
        out.append((detections_topic, kind, t, detections(store, t, frame, seen, ros1, three_d)))
    out.sort(key=lambda m: m[2])
    return out


def write_run(path: str | Path, *args: Any, **kwargs: Any) -> Path:
    write_bag(path, run_messages(path, *args, **kwargs), store_for(path))
    return Path(path)
