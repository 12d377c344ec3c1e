"""Goals out: for each frame, the pose from which to act on its best mode, for a navigation stack.

A frame's belief says where it can be executed; a navigator needs a pose. The goal of frame i
is its best point (the densest mode, :mod:`seal_cli.sefm.modes`), moved to the nearest free cell
centre if it is not in free space, facing the way the robot would arrive: from the robot's last
pose straight towards the goal (the robot's own heading when it is already there). Goals are in
the map's frame (``frame``, ``map`` by default), one per frame in plan order.

Written by the file's name (:func:`write_goals`): ``.yaml`` / ``.yml`` a YAML list; otherwise a
bag (``.bag`` ROS 1, ``.mcap`` or a folder named without a suffix ROS 2, :mod:`seal_cli.ros.writing`; another
suffix is refused) with one
``geometry_msgs/PoseStamped`` per frame on ``/goal_pose`` — the message RViz's *2D Goal Pose*
tool publishes and Nav2's ``NavigateToPose`` action takes — stamped 1 s apart from ``stamp``.
"""

from __future__ import annotations

import math
import os
from collections.abc import Mapping, Sequence
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import numpy as np
import yaml

from seal_cli.errors import SealError
from seal_cli.fileio import atomic_write_text, shown_path
from seal_cli.maps.model import Map

__all__ = ["GOAL_TOPIC", "Goal", "check_goals_path", "goals_for", "write_goals"]

GOAL_TOPIC = "/goal_pose"
YAML_SUFFIXES = (".yaml", ".yml")
BAG_SUFFIXES = (".bag", ".mcap")
"""A goals file's name says its format; any other suffix (``goals.txt``, ``goals.json``) is refused: it was written
as a ROS 2 bag folder of that name (hostile19)."""


@dataclass(frozen=True)
class Goal:
    """Where to stand, and which way to face, to carry out one frame."""

    frame: str
    """The frame's id (``stir_cup_spoon``)."""
    name: str
    elements: Mapping[str, str]
    pose: tuple[float, float, float]
    room: str
    weight: float
    """The best mode's share of the frame's belief."""

    def to_json(self) -> dict[str, Any]:
        return {"frame": self.frame, "name": self.name, "elements": dict(self.elements),
                "pose": [round(v, 3) for v in self.pose], "room": self.room, "weight": round(self.weight, 3)}


def _free_point(m: Map, point: tuple[float, float]) -> tuple[float, float]:
    if bool(m.is_free(np.array([point]))[0]) or len(m.free_centres) == 0:
        return point
    nearest = m.free_centres[np.argmin(((m.free_centres - point) ** 2).sum(axis=1))]
    return float(nearest[0]), float(nearest[1])


def goals_for(m: Map, frame_ids: Sequence[str], frames: Sequence[Mapping[str, Any]],
              robot: tuple[float, float, float]) -> list[Goal]:
    """One goal per frame, from the frames' JSON summaries (``best``, ``modes``) and the robot's last pose."""
    out = []
    for fid, summary in zip(frame_ids, frames, strict=True):
        x, y = _free_point(m, (float(summary["best"][0]), float(summary["best"][1])))
        dx, dy = x - robot[0], y - robot[1]
        yaw = math.atan2(dy, dx) if math.hypot(dx, dy) > 1e-6 else robot[2]
        mode = min(summary["modes"], key=lambda mo: math.dist(mo["mean"], summary["best"]), default=None)
        room = mode["room"] if mode else m.room_of(np.array([[x, y]]))[0] or "_outside"
        out.append(Goal(fid, summary["frame"], summary["elements"], (x, y, yaw), room,
                        float(mode["weight"]) if mode else 0.0))
    return out


def check_goals_path(path: str | Path, inputs: Sequence[str | Path | None] = ()) -> None:
    """Refuse, before anything runs, a goals file that cannot be written or is one of ``inputs`` (the run's
    inputs and its other outputs), by path or by file (a hard link: hostile27, ``--goals g.bag`` hard-linked to the
    map was replaced by the bag). A name without a suffix is a ROS 2 bag's folder, made new: one that names a file or
    a device is refused too (hostile27: ``--goals /dev/full`` ran the whole filter, then said "Not a directory")."""
    target = Path(path)
    shown = shown_path(target)
    if str(path) == "-":    # as every other output refuses it (fileio.Outputs): it made a bag folder called "-"
        raise SealError("--goals '-': seal writes this output into a file, not to standard output; give a file name")
    for given in inputs:
        if given is not None and (os.path.realpath(given) == os.path.realpath(target) or _same_file(given, target)):
            raise SealError(f"--goals {shown} is an input or another output of the run ({shown_path(given)}): give "
                            "another file")
    if target.suffix and target.suffix not in (*YAML_SUFFIXES, *BAG_SUFFIXES):
        raise SealError(f"--goals {shown}: seal writes goals as YAML (.yaml, .yml), a ROS 1 bag (.bag), an MCAP bag "
                        f"(.mcap) or a ROS 2 bag folder (a name without a suffix), not {target.suffix}")
    folder = target.parent if str(target.parent) else Path(".")
    if not folder.is_dir():
        raise SealError(f"cannot write --goals {shown}: folder {shown_path(folder)} does not exist")
    if target.is_dir():
        raise SealError(f"cannot write --goals {shown}: a folder of that name exists")
    if not target.suffix and (target.exists() or target.is_symlink()):
        raise SealError(f"cannot write --goals {shown}: a name without a suffix is written as a ROS 2 bag's folder, "
                        f"and {shown} is {'a file' if target.is_file() else 'no folder (a device or a link)'}; give a "
                        "new name, or one ending .yaml, .bag or .mcap")


def _same_file(one: str | Path, other: Path) -> bool:
    try:
        return os.path.samefile(one, other)
    except OSError:
        return False


def write_goals(path: str | Path, goals: Sequence[Goal], frame: str = "map", stamp: float = 0.0) -> None:
    """YAML or a bag of PoseStamped, by the file's name (see the module docstring)."""
    target = Path(path)
    if target.suffix in YAML_SUFFIXES:
        document = {"frame_id": frame, "goals": [g.to_json() for g in goals]}
        text = yaml.safe_dump(document, sort_keys=False, default_flow_style=None)
        atomic_write_text(target, f"# seal localize --goals: per frame, the pose to act from (x, y, yaw in {frame}; "
                                  f"metres, radians)\n{text}")
        return
    from seal_cli.ros.messages import typestore
    from seal_cli.ros.writing import is_ros1, pose_stamped, write_bag

    ros1 = is_ros1(target)
    store = typestore(ros1)
    messages = [(GOAL_TOPIC, "geometry_msgs/msg/PoseStamped", stamp + i,
                 pose_stamped(store, stamp + i, frame, *g.pose, ros1)) for i, g in enumerate(goals)]
    write_bag(target, messages, store)
