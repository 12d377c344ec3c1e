"""ROS in and out: bags read and written with ``rosbags`` (the ``ros`` extra; no ROS install needed).

- :mod:`~seal_cli.ros.messages`: the typestores, with vision_msgs registered from its ``.msg`` text;
- :mod:`~seal_cli.ros.transforms`: a TF tree read from a bag, looked up at any stamp (interpolated);
- :mod:`~seal_cli.ros.bags`: a robot's run (poses and detections) and occupancy grids out of a bag;
- :mod:`~seal_cli.ros.goals`: the poses to act from, written as ``geometry_msgs/PoseStamped`` or YAML.

This package may import :mod:`seal_cli.errors`, :mod:`seal_cli.fileio`, :mod:`seal_cli.maps` and
:mod:`seal_cli.sensing`; never sefm, sim, bench or cli. ``rosbags`` is imported only inside the
functions, and its absence is one clear :class:`~seal_cli.errors.SealError`.
"""
