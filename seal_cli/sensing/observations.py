"""Trajectory and observation files for ``seal localize``, read with the position of every problem.

A **trajectory** file lists the robot's poses; SeFM makes one belief update at each, with
detections simulated from the map's ground-truth objects::

    poses:
      - [-6.0, -3.0]            # x, y (yaw 0)
      - [5.0, -4.5, 1.57]       # x, y, yaw in radians

An **observations** file lists what a real robot saw, one update each; a visible region with no
detection of a class is negative evidence for it::

    - pose: [5.0, -4.5, 0.0]
      detections:
        - {class: spoon, at: [8.3, -4.1]}
    - pose: [0.5, 2.5]
      detections: []

(the list may also sit under a key ``observations:``). Every problem is a
:class:`~seal_cli.errors.SealError` at ``file:line:column``; :func:`check_inside` refuses poses off
the map (and deep in its walls), :func:`split_known` sets aside detections of classes no belief is kept for.
"""

from __future__ import annotations

import contextlib
import difflib
import math
from collections import Counter
from collections.abc import Callable, Collection, Sequence
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import numpy as np
import yaml

from seal_cli.errors import SealError, Where
from seal_cli.fileio import compose_yaml, read_text
from seal_cli.frames.taxonomy import class_key
from seal_cli.names import check_shown
from seal_cli.yamlnodes import clipped

MAX_OBSERVATIONS = 100_000
"""The most poses a trajectory, or observations an observations file, may hold (one update each)."""

MAX_DETECTIONS = 1_000
"""The most detections one observation may hold."""

NEAR_FREE = 0.3
"""How far (m) from a free cell a measured pose on an occupied cell may be and still be taken, with a warning: about
a robot's radius. A real robot's localised pose lands on the map's occupied cells where the map marks what has
moved since mapping (a chair) or the localiser is a few centimetres off by a wall; one farther in is in the wrong
frame, or a typo."""

__all__ = ["MAX_DETECTIONS", "MAX_OBSERVATIONS", "NEAR_FREE", "Observation", "check_inside", "read_observations",
           "read_trajectory", "split_known"]


@dataclass(frozen=True)
class Observation:
    """A pose ``(x, y, yaw)`` and what was detected there (None: simulate from the map)."""

    pose: tuple[float, float, float]
    detections: tuple[tuple[str, tuple[float, float]], ...] | None = None
    where: Where | None = field(default=None, compare=False)


class _Reader:
    def __init__(self, path: str | Path) -> None:
        self.file = str(path)
        self.text = read_text(path)
        self.lines = self.text.splitlines()

    def where(self, node: yaml.Node) -> Where:
        return Where(self.file, node.start_mark.line + 1, node.start_mark.column + 1)

    def error(self, message: str, node: yaml.Node) -> SealError:
        line = node.start_mark.line
        return SealError(message, self.where(node), source_line=self.lines[line] if line < len(self.lines) else None)

    def root(self) -> yaml.Node | None:
        root: yaml.Node | None = compose_yaml(self.text, self.file)
        return root

    def number(self, node: yaml.Node, what: str) -> float:
        """A finite number, read as a map's are: a plain ``1e-3`` (text to YAML 1.1, a number to YAML 1.2 and to
        seal's maps) is a number here too (hostile21: observations refused it), and a number YAML 1.1 and 1.2 read
        otherwise (``010``, ``10:00``) is refused saying so."""
        value: object = None
        if isinstance(node, yaml.ScalarNode) and node.tag in ("tag:yaml.org,2002:int", "tag:yaml.org,2002:float"):
            try:
                value = yaml.safe_load(node.value)
            except yaml.YAMLError as exc:  # an integer of more digits than seal reads, an octal 010, a 10:00
                raise self.error(f"{what} cannot be read: {getattr(exc, 'problem', None) or exc}", node) from None
        elif isinstance(node, yaml.ScalarNode) and node.tag == "tag:yaml.org,2002:str" and not node.style:
            with contextlib.suppress(ValueError):
                value = float(node.value)
        if isinstance(value, int | float) and not isinstance(value, bool) and abs(value) < 1e300 \
                and math.isfinite(value):
            return float(value)
        raise self.error(f"{what} must be a finite number, not {_shape(node)}", node)

    def pose(self, node: yaml.Node, what: str = "a pose") -> tuple[float, float, float]:
        if not isinstance(node, yaml.SequenceNode) or len(node.value) not in (2, 3):
            raise self.error(f"{what} must be [x, y] or [x, y, yaw] (metres, radians), not {_shape(node)}", node)
        values = [self.number(item, f"{what}'s {name}") for item, name in zip(node.value, ("x", "y", "yaw"),
                                                                              strict=False)]
        return (values[0], values[1], values[2] if len(values) == 3 else 0.0)

    def point(self, node: yaml.Node, what: str) -> tuple[float, float]:
        if not isinstance(node, yaml.SequenceNode) or len(node.value) != 2:
            raise self.error(f"{what} must be [x, y] (metres), not {_shape(node)}", node)
        return (self.number(node.value[0], f"{what}'s x"), self.number(node.value[1], f"{what}'s y"))

    def mapping(self, node: yaml.Node, what: str, keys: Sequence[str], required: Sequence[str]) -> dict[str, yaml.Node]:
        if not isinstance(node, yaml.MappingNode):
            raise self.error(f"{what} must be a mapping with {', '.join(keys)}, not {_shape(node)}", node)
        out: dict[str, yaml.Node] = {}
        for key_node, value in node.value:
            key = key_node.value if isinstance(key_node, yaml.ScalarNode) else None
            if key in out:
                raise self.error(f"{what} repeats the key {key!r}: give it once", key_node)
            if key not in keys:
                close = difflib.get_close_matches(str(key), list(keys), n=1)
                hint = f" (did you mean {close[0]!r}?)" if close else ""
                raise self.error(f"unknown key {key!r} in {what}{hint}; expected {', '.join(keys)}", key_node)
            out[str(key)] = value
        for key in required:
            if key not in out:
                raise self.error(f"{what} has no {key!r}", node)
        return out


def _shape(node: yaml.Node) -> str:
    if isinstance(node, yaml.ScalarNode):
        return "nothing" if node.tag.endswith(":null") else clipped(repr(node.value))
    if isinstance(node, yaml.SequenceNode):
        return f"a list of {len(node.value)}"
    return "a mapping"


def _empty(reader: _Reader, root: yaml.Node | None, what: str) -> SealError:
    return SealError(f"{reader.file} holds no {what}", Where(reader.file, 1, 1))


def _bound(reader: _Reader, node: yaml.SequenceNode, limit: int, what: str) -> None:
    if len(node.value) > limit:
        raise reader.error(f"{len(node.value):,} {what}: seal takes at most {limit:,}", node)


def read_trajectory(path: str | Path) -> list[Observation]:
    """The poses of a trajectory file (``poses: [[x, y], [x, y, yaw], ...]``), at least one."""
    reader = _Reader(path)
    root = reader.root()
    if root is None:
        raise _empty(reader, root, "poses")
    poses = reader.mapping(root, "a trajectory", ("poses",), ("poses",))["poses"]
    if not isinstance(poses, yaml.SequenceNode):
        raise reader.error(f"poses must be a list of [x, y] or [x, y, yaw], not {_shape(poses)}", poses)
    if not poses.value:
        raise reader.error("poses is empty: give at least one pose", poses)
    _bound(reader, poses, MAX_OBSERVATIONS, "poses")
    return [Observation(reader.pose(item, f"pose {i + 1}"), None, reader.where(item))
            for i, item in enumerate(poses.value)]


def read_observations(path: str | Path) -> list[Observation]:
    """The observations of a file: a list of ``{pose, detections: [{class, at}]}``, at least one."""
    reader = _Reader(path)
    root = reader.root()
    if root is None:
        raise _empty(reader, root, "observations")
    if isinstance(root, yaml.MappingNode):
        root = reader.mapping(root, "an observations file", ("observations",), ("observations",))["observations"]
    if not isinstance(root, yaml.SequenceNode):
        raise reader.error(f"observations must be a list of {{pose, detections}}, not {_shape(root)}", root)
    if not root.value:
        raise reader.error("the list of observations is empty: give at least one", root)
    _bound(reader, root, MAX_OBSERVATIONS, "observations")
    out = []
    for i, item in enumerate(root.value):
        what = f"observation {i + 1}"
        fields = reader.mapping(item, what, ("pose", "detections"), ("pose",))
        pose = reader.pose(fields["pose"], f"{what}'s pose")
        seen = fields.get("detections")
        detections: list[tuple[str, tuple[float, float]]] = []
        if seen is not None and not (isinstance(seen, yaml.ScalarNode) and seen.tag.endswith(":null")):
            if not isinstance(seen, yaml.SequenceNode):
                raise reader.error(f"{what}'s detections must be a list of {{class, at}}, not {_shape(seen)}", seen)
            _bound(reader, seen, MAX_DETECTIONS, f"detections in {what}")
            for j, node in enumerate(seen.value):
                label = f"detection {j + 1} of {what}"
                parts = reader.mapping(node, label, ("class", "at"), ("class", "at"))
                cls = parts["class"]
                if not isinstance(cls, yaml.ScalarNode) or cls.tag != "tag:yaml.org,2002:str" or not cls.value.strip():
                    raise reader.error(f"{label}'s class must be a name, not {_shape(cls)}", cls)
                try:  # a NUL or an escape through YAML's escapes was printed in the warning as it is (hostile30)
                    check_shown(cls.value.strip(), f"{label}'s class")
                except SealError as exc:
                    raise reader.error(exc.message, cls) from None
                detections.append((cls.value.strip(), reader.point(parts["at"], f"{label}'s at")))
        out.append(Observation(pose, tuple(detections), reader.where(item)))
    return out


def check_inside(observations: Sequence[Observation], bounds: Sequence[float], name: str,
                 is_occupied: Callable[[list[tuple[float, float]]], Any] | None = None,
                 is_free: Callable[[Any], Any] | None = None, step: float = 0.05) -> list[str]:
    """Refuse a pose or a detection outside the map's bounds, and (given the map's ``is_occupied``)
    a pose inside a wall, at its position in the file. Given ``is_free`` too, a pose on an occupied cell within
    :data:`NEAR_FREE` of a free point (looked for every ``step`` m, the map's cell) is taken, and said in the
    warning returned; only one deeper in is refused."""
    xmin, ymin, xmax, ymax = bounds

    def inside(x: float, y: float) -> bool:
        return xmin <= x <= xmax and ymin <= y <= ymax

    for obs in observations:
        if not inside(*obs.pose[:2]):
            raise SealError(f"pose [{obs.pose[0]:g}, {obs.pose[1]:g}] is outside map {name}'s bounds "
                            f"[{xmin:g}, {ymin:g}, {xmax:g}, {ymax:g}]", obs.where)
        for cls, (x, y) in obs.detections or ():
            if not inside(x, y):
                raise SealError(f"a detection of {cls} at [{x:g}, {y:g}] is outside map {name}'s bounds "
                                f"[{xmin:g}, {ymin:g}, {xmax:g}, {ymax:g}]", obs.where)
    if is_occupied is None or not observations:
        return []
    walled = [obs for obs, wall in zip(observations, is_occupied([obs.pose[:2] for obs in observations]),
                                       strict=True) if wall]
    near = _near_free([obs.pose[:2] for obs in walled], is_free, step) if is_free is not None and walled else []
    for obs, close in zip(walled, near or [False] * len(walled), strict=True):
        if not close:
            deep = f", more than {NEAR_FREE:g} m from any free cell" if is_free is not None else ""
            raise SealError(f"pose [{obs.pose[0]:g}, {obs.pose[1]:g}] is inside a wall or an obstacle of map "
                            f"{name}{deep}: the robot cannot stand there"
                            + (" (are the poses in the map's frame, and is the map's origin right?)" if deep else ""),
                            obs.where)
    if not walled:
        return []
    first = walled[0]
    return [f"{len(walled)} of {len(observations)} poses {'lies' if len(walled) == 1 else 'lie'} on occupied cells of "
            f"map {name}, {'' if len(walled) == 1 else 'each '}within "
            f"{NEAR_FREE:g} m of free space (the first, [{first.pose[0]:g}, {first.pose[1]:g}], at {first.where}): "
            f"the map marks something there that the robot drove through (moved since mapping?), or the localiser "
            f"is a few centimetres off; they are used as they are"]


def _near_free(points: Sequence[tuple[float, float]], is_free: Callable[[Any], Any], step: float) -> list[bool]:
    """Whether each point has a free point within :data:`NEAR_FREE`, looked for on a lattice of ``step`` m."""
    n = max(1, math.ceil(NEAR_FREE / max(step, 1e-3)))
    grid = np.arange(-n, n + 1) * (NEAR_FREE / n)
    dx, dy = np.meshgrid(grid, grid)
    disc = np.stack([dx.ravel(), dy.ravel()], axis=1)
    disc = disc[np.hypot(disc[:, 0], disc[:, 1]) <= NEAR_FREE + 1e-9]
    pts = np.asarray(points, float).reshape(-1, 2)
    out = np.zeros(len(pts), bool)
    chunk = max(1, 1_000_000 // len(disc))  # bounded temporaries: 100,000 poses in a wall are 16 M points
    for i in range(0, len(pts), chunk):
        block = (pts[i:i + chunk, None, :] + disc[None]).reshape(-1, 2)
        out[i:i + chunk] = np.asarray(is_free(block)).reshape(-1, len(disc)).any(axis=1)
    return [bool(v) for v in out]


def split_known(observations: Sequence[Observation],
                known: Collection[str]) -> tuple[list[Observation], dict[str, int]]:
    """The observations with only the detections of classes in ``known`` (class keys: ``Cup``, ``cup`` and ``CUP``
    are one class), and how many detections of each other class were set aside (by the class as written first).

    A real detector reports every class it was trained on (COCO's person, chair, dining table ...); seal keeps
    beliefs only of the map's and the plan's classes, and the others say nothing about them."""
    dropped: Counter[str] = Counter()
    spelled: dict[str, str] = {}
    kept = []
    for obs in observations:
        if obs.detections is None:
            kept.append(obs)
            continue
        mine = []
        for cls, at in obs.detections:
            key = class_key(cls)
            if key in known:
                mine.append((cls, at))
            else:
                dropped[spelled.setdefault(key, cls)] += 1
        kept.append(obs if len(mine) == len(obs.detections) else
                    Observation(obs.pose, tuple(mine), obs.where))
    return kept, dict(dropped.most_common())
