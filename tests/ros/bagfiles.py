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
from seal_cli.ros.writing import (
    Message,
    detection_array,
    is_ros1,
    occupancy_grid,
    odometry,
    pose_stamped,
    tf_message,
    write_bag,
)

__all__ = ["detections", "occupancy_grid", "run_messages", "store_for", "tf_message", "write_run"]

detections = detection_array


def store_for(path: str | Path) -> Any:
    return typestore(is_ros1(path))


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
