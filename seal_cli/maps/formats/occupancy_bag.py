"""A map's occupancy from a ``nav_msgs/OccupancyGrid`` in a ROS bag, instead of an image.

A robot that mapped a building with slam_toolbox or gmapping has the map as a message; the
annotated map can take it directly (the path relative to the map file, like ``image:``)::

    occupancy: {bag: mapping_run.mcap, topic: /map}   # topic defaults to /map; or just
    occupancy: mapping_run.mcap
    occupied_thresh: 0.65                              # optional, as for an image
    free_thresh: 0.196

The last message on the topic is used (a SLAM node republishes the map as it grows, the last the
most complete; map_server publishes it once). Its cells keep the conventions map_server follows for
images: a value v in 0..100 is the occupancy probability p = v / 100, occupied if
``p > occupied_thresh``, free if ``p < free_thresh``, unknown otherwise, and −1 is unknown; row
0 is the lowest y and ``info.origin`` the pose of cell (0, 0)'s lower-left corner, so
``resolution`` and ``origin`` come from the message (giving them too is refused, as are the
image-only keys ``negate`` and ``mode``). Reading the bag needs the ``ros`` extra.
"""

from __future__ import annotations

from typing import Any

import numpy as np
import yaml

from seal_cli.errors import SealError
from seal_cli.maps.geometry import FREE, MAX_GRID_CELLS, OCCUPIED, UNKNOWN, OccupancyGrid, fit_cells
from seal_cli.maps.model import MapWarning

__all__ = ["KEY", "grid_from_bag"]

KEY = "occupancy"
FIELDS = ("bag", "topic")
FROM_MESSAGE = ("resolution", "origin")
IMAGE_ONLY = ("image", "negate", "mode")


def cells(values: np.ndarray, occupied_thresh: float, free_thresh: float) -> np.ndarray:
    """FREE / OCCUPIED / UNKNOWN from OccupancyGrid values (−1, 0..100), as map_server thresholds them."""
    v = np.asarray(values, dtype=np.int16)
    p = v / 100.0
    out = np.full(v.shape, UNKNOWN, np.int8)
    known = (v >= 0) & (v <= 100)
    out[known & (p > occupied_thresh)] = OCCUPIED
    out[known & (p < free_thresh)] = FREE
    return out


def grid_from_bag(reader: Any, nodes: dict[str, yaml.Node]) -> OccupancyGrid | None:
    """The occupancy grid the ``occupancy:`` key names (None, with problems recorded, if it cannot be read).

    ``reader`` is the map file's reader (:mod:`seal_cli.maps.formats.map_server`): its ``problem``,
    ``string``, ``number``, ``pairs`` and ``path``."""
    node = nodes[KEY]
    for key in (*FROM_MESSAGE, *IMAGE_ONLY):
        if key in nodes:
            reader.problem(f"{key} cannot be given with occupancy: "
                           + ("the grid's resolution and origin come from its message" if key in FROM_MESSAGE
                              else "give an image or an occupancy grid from a bag, not both" if key == "image"
                              else f"{key} is for images"), nodes[key])
    fields: dict[str, yaml.Node] = {"bag": node} if isinstance(node, yaml.ScalarNode) else \
        {k: v for k, _, v in reader.pairs(node, "occupancy", FIELDS)}
    if "bag" not in fields:
        reader.problem("occupancy needs a bag: {bag: FILE, topic: /map}", node)
        return None
    bag = reader.string(fields["bag"], "occupancy's bag")
    topic = reader.string(fields["topic"], "occupancy's topic") if "topic" in fields else "/map"
    occ = reader.number(nodes["occupied_thresh"], "occupied_thresh", lambda v: 0 <= v <= 1,
                        "a probability in [0, 1]") if "occupied_thresh" in nodes else 0.65
    free = reader.number(nodes["free_thresh"], "free_thresh", lambda v: 0 <= v <= 1,
                         "a probability in [0, 1]") if "free_thresh" in nodes else 0.196
    if bag is None or topic is None or occ is None or free is None or any(k in nodes for k in (*FROM_MESSAGE,
                                                                                             *IMAGE_ONLY)):
        return None
    if free > occ:
        reader.problem(f"free_thresh {free:g} is above occupied_thresh {occ:g}", nodes["free_thresh"])
        return None
    from seal_cli.ros.grids import read_occupancy_grid

    try:
        grid = read_occupancy_grid(reader.path.parent / bag, topic)
    except SealError as exc:
        reader.problem(f"{reader.path.parent / bag}: {exc.message}", fields["bag"])
        return None
    kept, corner, factor = fit_cells(cells(grid.values, occ, free), MAX_GRID_CELLS)
    if factor > 1:
        reader.problems.append(MapWarning(
            f"{reader.path.parent / bag}: the grid on {topic} has {grid.values.size:,} cells, its known part more "
            f"than {MAX_GRID_CELLS:,} (1024×1024), so seal merges {factor}×{factor} cells into one: "
            f"{kept.shape[1]:,}×{kept.shape[0]:,} cells of {grid.resolution * factor:g} m",
            reader.where(fields["bag"])))
    return OccupancyGrid.placed(kept, grid.resolution, grid.origin, corner, factor)
