"""ROS message types: rosbags' typestores plus vision_msgs, registered from its ``.msg`` text.

rosbags ships the core ROS 1 and ROS 2 messages (std_msgs, geometry_msgs, nav_msgs, tf2_msgs)
but not vision_msgs. Its definitions are given here as the ``.msg`` files of vision_msgs 4
(ROS 2 Humble and later: the class is ``results[i].hypothesis.class_id``, a string) and of
vision_msgs 1 (ROS 1 Noetic: ``results[i].id``, an integer; with tf2_msgs/TFMessage, missing from
rosbags' Noetic store). A bag that embeds its own
definitions (every ROS 1 bag, every MCAP file) is read with those instead; these are used for a
ROS 2 sqlite3 bag that carries none, and for writing bags.
"""

from __future__ import annotations

from typing import Any

from seal_cli.errors import SealError

__all__ = ["DETECTION_TYPES", "ODOMETRY", "OCCUPANCY_GRID", "POSE_TYPES", "POSE_STAMPED", "TF", "typestore"]

POSE_STAMPED = "geometry_msgs/msg/PoseStamped"
POSE_COVARIANCE = "geometry_msgs/msg/PoseWithCovarianceStamped"
ODOMETRY = "nav_msgs/msg/Odometry"
TF = "tf2_msgs/msg/TFMessage"
OCCUPANCY_GRID = "nav_msgs/msg/OccupancyGrid"
DETECTION_2D = "vision_msgs/msg/Detection2DArray"
DETECTION_3D = "vision_msgs/msg/Detection3DArray"
POSE_TYPES = (POSE_STAMPED, POSE_COVARIANCE, ODOMETRY)
DETECTION_TYPES = (DETECTION_2D, DETECTION_3D)

VISION_MSGS_ROS2 = {
    "vision_msgs/msg/Point2D": "float64 x\nfloat64 y\n",
    "vision_msgs/msg/Pose2D": "vision_msgs/Point2D position\nfloat64 theta\n",
    "vision_msgs/msg/BoundingBox2D": "vision_msgs/Pose2D center\nfloat64 size_x\nfloat64 size_y\n",
    "vision_msgs/msg/BoundingBox3D": "geometry_msgs/Pose center\ngeometry_msgs/Vector3 size\n",
    "vision_msgs/msg/ObjectHypothesis": "string class_id\nfloat64 score\n",
    "vision_msgs/msg/ObjectHypothesisWithPose": "vision_msgs/ObjectHypothesis hypothesis\n"
                                                "geometry_msgs/PoseWithCovariance pose\n",
    "vision_msgs/msg/Detection2D": "std_msgs/Header header\nvision_msgs/ObjectHypothesisWithPose[] results\n"
                                   "vision_msgs/BoundingBox2D bbox\nstring id\n",
    "vision_msgs/msg/Detection3D": "std_msgs/Header header\nvision_msgs/ObjectHypothesisWithPose[] results\n"
                                   "vision_msgs/BoundingBox3D bbox\nstring id\n",
    DETECTION_2D: "std_msgs/Header header\nvision_msgs/Detection2D[] detections\n",
    DETECTION_3D: "std_msgs/Header header\nvision_msgs/Detection3D[] detections\n",
}
"""vision_msgs 4.x (ROS 2 Humble, Iron, Jazzy)."""

VISION_MSGS_ROS1 = {
    "vision_msgs/msg/BoundingBox2D": "geometry_msgs/Pose2D center\nfloat64 size_x\nfloat64 size_y\n",
    "vision_msgs/msg/BoundingBox3D": "geometry_msgs/Pose center\ngeometry_msgs/Vector3 size\n",
    "vision_msgs/msg/ObjectHypothesisWithPose": "int64 id\nfloat64 score\ngeometry_msgs/PoseWithCovariance pose\n",
    "vision_msgs/msg/Detection2D": "Header header\nvision_msgs/ObjectHypothesisWithPose[] results\n"
                                   "vision_msgs/BoundingBox2D bbox\nsensor_msgs/Image source_img\n",
    "vision_msgs/msg/Detection3D": "Header header\nvision_msgs/ObjectHypothesisWithPose[] results\n"
                                   "vision_msgs/BoundingBox3D bbox\nsensor_msgs/PointCloud2 source_cloud\n",
    DETECTION_2D: "Header header\nvision_msgs/Detection2D[] detections\n",
    DETECTION_3D: "Header header\nvision_msgs/Detection3D[] detections\n",
}
"""vision_msgs 1.x (ROS 1 Noetic); rosbags' Noetic store also lacks tf2_msgs/TFMessage."""
VISION_MSGS_ROS1[TF] = "geometry_msgs/TransformStamped[] transforms\n"


def require_rosbags() -> None:
    """Refuse, with the way out, when the ``ros`` extra is not installed."""
    try:
        import rosbags  # noqa: F401
    except ImportError:
        raise SealError("reading and writing ROS bags needs rosbags: pip install 'seal[ros]'") from None


def typestore(ros1: bool = False) -> Any:
    """rosbags' Humble (or Noetic) typestore with vision_msgs registered."""
    require_rosbags()
    from rosbags.typesys import Stores, get_types_from_msg, get_typestore

    store = get_typestore(Stores.ROS1_NOETIC if ros1 else Stores.ROS2_HUMBLE)
    types: dict[str, Any] = {}
    for name, text in (VISION_MSGS_ROS1 if ros1 else VISION_MSGS_ROS2).items():
        types.update(get_types_from_msg(text, name))
    store.register(types)
    return store
