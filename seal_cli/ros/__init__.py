"""ROS in and out: bags read and written with ``rosbags`` (the ``ros`` extra; no ROS install needed).

Imports maps and sensing; never language, planning, sefm, sim, bench or cli.

- :mod:`~seal_cli.ros.messages`: the typestores, with vision_msgs registered from its ``.msg`` text;
- :mod:`~seal_cli.ros.reader`: an open bag, its topics and messages, every failure a SealError;
- :mod:`~seal_cli.ros.transforms`: a TF tree read from a bag, looked up at any stamp (interpolated);
- :mod:`~seal_cli.ros.bags`: a robot's run (poses and detections) out of a bag, as observations;
- :mod:`~seal_cli.ros.grids`: occupancy grids out of a bag (read by the map format
  :mod:`seal_cli.maps.formats.occupancy_bag`; it imports only reader, messages and transforms);
- :mod:`~seal_cli.ros.labels`: class names for numeric class ids;
- :mod:`~seal_cli.ros.importing`: a run as an observations file (``seal import-bag``);
- :mod:`~seal_cli.ros.goals`: the poses to act from, written as ``geometry_msgs/PoseStamped`` or YAML;
- :mod:`~seal_cli.ros.writing`: messages built from plain values, and bags written by file name.

``rosbags`` is imported only inside the functions, and its absence is one clear
:class:`~seal_cli.errors.SealError`.
"""
