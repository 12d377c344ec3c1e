"""Bags written with rosbags: the format follows the name, and nothing is left half-written.

``run.bag`` is a ROS 1 bag; ``run.mcap`` a single MCAP file (ROS 2; ``ros2 bag play run.mcap``);
any other name a ROS 2 bag folder in sqlite3 storage. The bag is written beside the target
under a temporary name and renamed onto it only when complete. A file is replaced; an existing
folder is refused (a bag folder is not overwritten).
"""

from __future__ import annotations

import contextlib
import os
import shutil
import tempfile
from collections.abc import Sequence
from pathlib import Path
from typing import Any

from seal_cli.errors import SealError, Where
from seal_cli.ros.messages import require_rosbags, typestore
from seal_cli.ros.transforms import yaw_quaternion

__all__ = ["Message", "is_ros1", "pose_stamped", "write_bag"]

Message = tuple[str, str, float, Any]
"""``(topic, message type, stamp s, message)``."""


def is_ros1(path: str | Path) -> bool:
    return Path(path).suffix == ".bag"


def header(store: Any, stamp: float, frame: str, ros1: bool) -> Any:
    """A ``std_msgs/Header`` at ``stamp`` seconds."""
    sec = int(stamp // 1)
    time = store.types["builtin_interfaces/msg/Time"](sec=sec, nanosec=int(round((stamp - sec) * 1e9)) % 1_000_000_000)
    fields = {"seq": 0} if ros1 else {}
    return store.types["std_msgs/msg/Header"](**fields, stamp=time, frame_id=frame)


def pose(store: Any, x: float, y: float, yaw: float, z: float = 0.0) -> Any:
    """A ``geometry_msgs/Pose`` on the floor, turned by ``yaw`` about z."""
    qx, qy, qz, qw = yaw_quaternion(yaw)
    return store.types["geometry_msgs/msg/Pose"](
        position=store.types["geometry_msgs/msg/Point"](x=float(x), y=float(y), z=float(z)),
        orientation=store.types["geometry_msgs/msg/Quaternion"](x=qx, y=qy, z=qz, w=qw))


def pose_stamped(store: Any, stamp: float, frame: str, x: float, y: float, yaw: float, ros1: bool) -> Any:
    """A ``geometry_msgs/PoseStamped``: what Nav2's NavigateToPose takes as its goal."""
    return store.types["geometry_msgs/msg/PoseStamped"](header=header(store, stamp, frame, ros1),
                                                        pose=pose(store, x, y, yaw))


def write_bag(path: str | Path, messages: Sequence[Message], store: Any | None = None) -> None:
    """Write the messages (in stamp order within each topic) to a bag whose format follows the name."""
    require_rosbags()
    target = Path(path)
    folder = target.parent if str(target.parent) else Path(".")
    if not folder.is_dir():
        raise SealError(f"cannot write {target}: folder {folder} does not exist", Where(str(target)))
    if target.is_dir():
        raise SealError(f"cannot write {target}: a folder of that name exists (a bag folder is not overwritten)",
                        Where(str(target)))
    ros1 = is_ros1(target)
    store = store or typestore(ros1)
    work = Path(tempfile.mkdtemp(prefix=f".{target.name}.", dir=folder))
    try:
        inner = work / ("out.bag" if ros1 else "out")
        _write(inner, messages, store, ros1, mcap=target.suffix == ".mcap")
        if target.suffix == ".mcap":
            inner = next(inner.glob("*.mcap"))
        os.replace(inner, target)
    except OSError as exc:
        raise SealError(f"cannot write {target}: {exc.strerror or exc}", Where(str(target))) from None
    finally:
        with contextlib.suppress(OSError):
            shutil.rmtree(work)


def _write(path: Path, messages: Sequence[Message], store: Any, ros1: bool, mcap: bool) -> None:
    if ros1:
        from rosbags.rosbag1 import Writer as Writer1

        with Writer1(path) as bag1:
            connections = {}
            for topic, msgtype, _, _ in messages:
                if topic not in connections:
                    connections[topic] = bag1.add_connection(topic, msgtype, typestore=store)
            for topic, msgtype, stamp, message in messages:
                bag1.write(connections[topic], int(round(stamp * 1e9)), store.serialize_ros1(message, msgtype))
        return
    from rosbags.rosbag2 import StoragePlugin, Writer

    with Writer(path, version=8, storage_plugin=StoragePlugin.MCAP if mcap else StoragePlugin.SQLITE3) as bag2:
        conns = {}
        for topic, msgtype, _, _ in messages:
            if topic not in conns:
                conns[topic] = bag2.add_connection(topic, msgtype, typestore=store)
        for topic, msgtype, stamp, message in messages:
            bag2.write(conns[topic], int(round(stamp * 1e9)), store.serialize_cdr(message, msgtype))
