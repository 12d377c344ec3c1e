"""ROS messages built from plain values, and bags written with rosbags (the format follows the name).

The builders take ``x, y, yaw`` and ``(class, x, y, z)`` and give rosbags message objects of the
typestore passed (``ros1``: headers with ``seq``, vision_msgs 1 with integer ids); they serve the
goals (:mod:`seal_cli.ros.goals`), the benchmark (:mod:`seal_cli.bench.ros`) and the tests.

``run.bag`` is a ROS 1 bag; ``run.mcap`` a single MCAP file (ROS 2; ``ros2 bag play run.mcap``);
any other name a ROS 2 bag folder in sqlite3 storage. The bag is written beside the target
under a temporary name and renamed onto it only when complete. A file is replaced; an existing
folder is refused (a bag folder is not overwritten).
"""

from __future__ import annotations

import contextlib
import os
import shutil
from collections.abc import Sequence
from pathlib import Path
from typing import Any

import numpy as np

from seal_cli.errors import SealError, Where
from seal_cli.fileio import work_folder
from seal_cli.ros.messages import DETECTION_2D, DETECTION_3D, ODOMETRY, TF, require_rosbags, typestore
from seal_cli.ros.transforms import yaw_quaternion

__all__ = ["Message", "detection_array", "header", "is_ros1", "occupancy_grid", "odometry", "pose", "pose_stamped",
           "tf_message", "write_bag"]

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


def detection_array(store: Any, stamp: float, frame: str, seen: Sequence[tuple[str | int, float, float, float]],
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
    if target.exists() and not target.is_file():    # a device: a bag is built beside it and renamed into place
        raise SealError(f"cannot write {target}: it is no file nor folder (a device?); give a file name",
                        Where(str(target)))
    ros1 = is_ros1(target)
    store = store or typestore(ros1)
    try:
        work = work_folder(target)
    except OSError as exc:
        raise _failed(target, exc) from None
    try:
        inner = work / ("out.bag" if ros1 else "out")
        _write(inner, messages, store, ros1, mcap=target.suffix == ".mcap")
        if target.suffix == ".mcap":
            inner = next(inner.glob("*.mcap"))
        os.replace(inner, target)
    except OSError as exc:
        raise _failed(target, exc) from None
    finally:
        with contextlib.suppress(OSError):
            shutil.rmtree(work)


def _failed(target: Path, error: OSError) -> Exception:
    """Why writing the bag ``target`` failed: said of ``target``, or, when it is the temporary of an output seal
    plans (``localize --goals g.mcap``), the system's error of it, for that output to name its option (hostile30:
    past ``ulimit -f`` it said "cannot write .g.mcap.seal…tmp.mcap: File too large")."""
    from seal_cli.fileio import is_live_temporary

    if is_live_temporary(target):
        return OSError(error.errno, error.strerror, str(target))
    return SealError(f"cannot write {target}: {error.strerror or error}", Where(str(target)))


def _write(path: Path, messages: Sequence[Message], store: Any, ros1: bool, mcap: bool) -> None:
    if ros1:
        from rosbags.rosbag1 import Writer as Writer1

        with Writer1(path) as bag1:
            _fill(bag1, messages, store, store.serialize_ros1)
        return
    from rosbags.rosbag2 import StoragePlugin, Writer

    with Writer(path, version=8, storage_plugin=StoragePlugin.MCAP if mcap else StoragePlugin.SQLITE3) as bag2:
        _fill(bag2, messages, store, store.serialize_cdr)


def _fill(bag: Any, messages: Sequence[Message], store: Any, serialize: Any) -> None:
    """One connection per topic, in the order topics first come, then every message at its stamp."""
    connections = {}
    for topic, msgtype, _, _ in messages:
        if topic not in connections:
            connections[topic] = bag.add_connection(topic, msgtype, typestore=store)
    for topic, msgtype, stamp, message in messages:
        bag.write(connections[topic], int(round(stamp * 1e9)), serialize(message, msgtype))
