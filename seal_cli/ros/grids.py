"""Occupancy grids out of a bag: the first ``nav_msgs/OccupancyGrid`` on a topic (``/map``).

Imports only :mod:`seal_cli.ros.reader` and :mod:`seal_cli.ros.transforms`, so that a map file format
(:mod:`seal_cli.maps.formats.occupancy_bag`) can read one without importing what sits above maps.
"""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path

import numpy as np
from numpy.typing import NDArray

from seal_cli.ros.messages import OCCUPANCY_GRID
from seal_cli.ros.reader import open_bag
from seal_cli.ros.transforms import quaternion_yaw

__all__ = ["Grid", "read_occupancy_grid"]


@dataclass(frozen=True)
class Grid:
    """A ``nav_msgs/OccupancyGrid``: ``values[row, col]`` in −1 (unknown) or 0..100, row 0 at the lowest y."""

    values: NDArray[np.int8]
    resolution: float
    origin: tuple[float, float, float]
    frame: str


def read_occupancy_grid(path: str | Path, topic: str = "/map") -> Grid:
    """The last ``nav_msgs/OccupancyGrid`` on ``topic``: map_server publishes one; a SLAM node (slam_toolbox,
    gmapping, cartographer) republishes the map as it grows, and its last is the most complete (the first, which
    was read before robot5, is the few square metres seen at the start)."""
    with open_bag(path) as bag:
        if topic not in bag.topics:
            grids = sorted(t for t, m in bag.topics.items() if m == OCCUPANCY_GRID)
            hint = f" (its occupancy grids: {', '.join(grids)})" if grids else " (it holds no occupancy grid)"
            raise bag.error(f"no topic {topic} in the bag{hint}")
        if bag.topics[topic] != OCCUPANCY_GRID:
            raise bag.error(f"{topic} holds {bag.topics[topic]}, not {OCCUPANCY_GRID}")
        found = bag.last(topic)
        if found is None:
            raise bag.error(f"{topic} holds no messages")
        message = found[2]
        info = message.info
        width, height = int(info.width), int(info.height)
        data = np.asarray(message.data, dtype=np.int8)
        if width <= 0 or height <= 0 or len(data) != width * height:
            raise bag.error(f"the occupancy grid on {topic} is {width}×{height} cells but holds {len(data)} values")
        if not (np.isfinite(info.resolution) and info.resolution > 0):
            raise bag.error(f"the occupancy grid on {topic} has resolution {info.resolution}, not a positive "
                            f"number of metres per cell")
        o = info.origin
        q = [o.orientation.x, o.orientation.y, o.orientation.z, o.orientation.w]
        # ROS 1's default orientation is (0, 0, 0, 0): no turn. A half turn is (0, 0, 1, 0), and w = 0 alone is
        # no default (read as w = 1, it was a quarter turn)
        yaw = float(quaternion_yaw(np.array([q if any(q) else [0.0, 0.0, 0.0, 1.0]]))[0])
        # resolution is a float32: 0.05 arrives as 0.0500000007; take the shortest decimal that is that float32
        resolution = float(np.format_float_positional(np.float32(info.resolution), unique=True))
        return Grid(data.reshape(height, width), resolution,
                    (float(o.position.x), float(o.position.y), yaw), message.header.frame_id.lstrip("/"))
