"""A robot's run out of a ROS bag: where it was, and what it detected, one observation per detection message.

:func:`read_run` opens a ROS 1 ``.bag``, a ROS 2 bag folder (sqlite3 or MCAP), or a bare ``.db3`` /
``.mcap`` file, and returns one :class:`~seal_cli.sensing.observations.Observation` per
``vision_msgs/Detection2DArray`` or ``Detection3DArray`` message:

- **the robot's pose** at the message's stamp, interpolated (:mod:`seal_cli.ros.transforms`) from
  ``geometry_msgs/PoseStamped``, ``PoseWithCovarianceStamped`` (what amcl publishes) or
  ``nav_msgs/Odometry`` messages, or from ``/tf`` (``map → odom → base_link`` chained, with
  ``/tf_static``), expressed in ``frame`` (``map``);
- **what it detected**: each detection's best-scoring hypothesis gives the class (``class_id``
  in vision_msgs 4, the integer ``id`` in vision_msgs 1, as text), and its position is the
  centre of its 3-D box (Detection3D) or its hypothesis's pose (Detection2D, where a detector
  with depth writes the object's position), carried from the header's frame into ``frame``
  through the transforms at the stamp; its height is dropped. An empty array is a look that saw
  nothing: negative evidence.

Stamps are the headers'. A topic whose stamps are all zero (a publisher that never stamps) is placed at the
times the bag logged its messages; on a topic with stamps, a message stamped zero (published under
``use_sim_time`` before the simulator's ``/clock`` arrived) has no time on the topic's clock and is left
out, counted in :attr:`Run.notes`. A
detection message more than ``TOLERANCE`` seconds outside the span of the poses (or of the
transforms it needs) cannot be placed and is skipped (:attr:`Run.skipped` counts them); if
none can be placed, the two streams are on different clocks and that is an error. A topic whose
stamps run backwards by more than ``JUMP`` seconds is a clock jump (a bag recorded across a
restart, or sim and wall time mixed), an error naming the message. Every problem is one
:class:`~seal_cli.errors.SealError` naming the bag.
"""

from __future__ import annotations

import math
from collections.abc import Mapping, Sequence
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import numpy as np
from numpy.typing import NDArray

from seal_cli.errors import SealError, Where
from seal_cli.ros.messages import DETECTION_TYPES, POSE_TYPES, TF
from seal_cli.ros.reader import Bag, open_bag
from seal_cli.ros.transforms import TfTree, Track, apply, compose, invert, quaternion_yaw
from seal_cli.sensing.observations import MAX_DETECTIONS, MAX_OBSERVATIONS, Observation

__all__ = ["JUMP", "TOLERANCE", "Run", "read_run"]

Array = NDArray[np.float64]
Look = list[tuple[str, str, tuple[float, float, float]]]
"""One message's detections: (class, frame, position in that frame)."""

TOLERANCE = 0.5
"""How far (s) outside the poses' span a detection may be and still be placed (at the nearest pose)."""
JUMP = 1.0
"""How far (s) a topic's stamps may run backwards before it is a clock jump (jitter below is sorted out)."""
TF_TOPICS = ("/tf", "/tf_static")
MAX_COORDINATE = 1e7
"""The largest coordinate a pose, transform or detection may give, in metres (a map's bound,
:data:`seal_cli.maps.formats.map_server.MAX_COORDINATE`)."""


@dataclass(frozen=True)
class Run:
    """What :func:`read_run` found: one observation (and its stamp, s) per detection message placed."""

    observations: tuple[Observation, ...]
    stamps: tuple[float, ...]
    pose_source: str
    detections_topic: str
    skipped: int = 0
    notes: tuple[str, ...] = ()
    """What was left out of the bag and why, for the user (messages stamped zero among stamped ones)."""


# -- stamps and poses --------------------------------------------------------------------------------
def _stamp(header: Any) -> float:
    """A header's stamp in seconds (0: the message was not stamped)."""
    stamp = header.stamp
    return float(stamp.sec) + float(stamp.nanosec) * 1e-9


def _clocked(bag: Bag, topic: str, stamped: Sequence[float], logged: Sequence[float],
             what: str = "messages") -> tuple[list[float], NDArray[np.bool_]]:
    """The stamps of a topic's messages (or transforms) and which of them to keep.

    All stamped zero: a publisher that never stamps; the times the bag logged them stand in (all kept). Some
    stamped zero among stamped ones: published before the clock started (a node under ``use_sim_time`` before
    Gazebo's ``/clock`` arrived stamps 0); they have no time on the topic's clock and are left out, with a note.
    Taking the log time for those (wall time, 1.7e9 s) against the others' sim time (35 s) was refused as a
    clock jump of the whole bag."""
    s = np.asarray(stamped, float)
    if not (s > 0).any():
        return [float(v) for v in logged], np.ones(len(s), bool)
    keep = s > 0
    if not keep.all():
        first = int(np.argmin(keep)) + 1
        bag.notes.append(f"{int((~keep).sum())} of {len(s)} {what} on {topic} are stamped 0 among stamped ones (the "
                         f"first: {what.rstrip('s')} {first}) and were left out: published before the clock started "
                         f"(under use_sim_time, before /clock)?")
    return [float(v) for v in s], keep


def _frame(name: str) -> str:
    return name.lstrip("/")


def _check_values(bag: Bag, values: Sequence[float], what: str) -> None:
    """Refuse a value that is not a finite number within :data:`MAX_COORDINATE`: observations that seal itself
    would refuse (``pose: [nan, ...]``) are never written or used."""
    if all(math.isfinite(v) and abs(v) <= MAX_COORDINATE for v in values):
        return
    shown = ", ".join(f"{v:g}" for v in values)
    raise bag.error(f"{what} is ({shown}): seal takes finite numbers of at most {MAX_COORDINATE:g} m "
                    "(a localiser or detector that lost track publishes NaN; drop those messages from the bag)")


ROTATION_TOLERANCE = 0.01
"""How far a rotation's squared length may be from 1 (tf2's own test for a denormalised quaternion)."""


def _check_rotation(bag: Bag, q: Sequence[float], what: str) -> None:
    """Refuse a rotation that is no unit quaternion: seal, like tf2, rotates by unit quaternions only, and one of
    another length scales what it carries (a ROS 1 pose left at its default (0, 0, 0, 0), a damaged byte)."""
    squared = sum(v * v for v in q)
    if abs(squared - 1) <= ROTATION_TOLERANCE:
        return
    shown = ", ".join(f"{v:g}" for v in q)
    raise bag.error(f"{what} is ({shown}), of length {math.sqrt(squared):.3g}: a rotation is a unit quaternion "
                    "(length 1; tf2 refuses the others too). A pose with no rotation is (0, 0, 0, 1), not (0, 0, 0, 0)")


def _check_clock(bag: Bag, topic: str, stamps: Sequence[float]) -> None:
    """Refuse stamps that run backwards by more than JUMP seconds."""
    s = np.asarray(stamps, float)
    if len(s) < 2:
        return
    back = np.maximum.accumulate(s)[:-1] - s[1:]
    if (back > JUMP).any():
        k = int(np.argmax(back > JUMP)) + 1
        raise bag.error(f"the clock of {topic} jumps back {back[k - 1]:.3f} s at message {k + 1} "
                        f"(stamp {s[k]:.3f} s after {s[:k].max():.3f} s): was the bag recorded across a restart, "
                        f"or with sim and wall time mixed?")


def _pose_of(message: Any, msgtype: str) -> Any:
    return message.pose if msgtype.endswith("/PoseStamped") else message.pose.pose


def _pose_track(bag: Bag, topic: str, base_frame: str) -> Track:
    """The robot's pose messages on a topic as a track (parent: their frame; child: the base frame)."""
    msgtype = bag.topics[topic]
    stamps: list[float] = []
    logs: list[float] = []
    t: list[tuple[float, float, float]] = []
    q: list[tuple[float, float, float, float]] = []
    frames: list[str] = []
    child = base_frame
    for i, logged, message in bag.messages(topic):
        pose = _pose_of(message, msgtype)
        frame = _frame(message.header.frame_id)
        if frames and frame != frames[0]:
            raise bag.error(f"the frame of {topic} changes from {frames[0]!r} to {frame!r} at message {i + 1}")
        frames.append(frame)
        if msgtype.endswith("/Odometry") and message.child_frame_id:
            child = _frame(message.child_frame_id)
        stamps.append(_stamp(message.header))
        logs.append(logged)
        t.append((pose.position.x, pose.position.y, pose.position.z))
        q.append((pose.orientation.x, pose.orientation.y, pose.orientation.z, pose.orientation.w))
        _check_values(bag, (*t[-1], *q[-1]), f"the pose of message {i + 1} on {topic} (x, y, z, qx, qy, qz, qw)")
        _check_rotation(bag, q[-1], f"the rotation of message {i + 1} on {topic} (qx, qy, qz, qw)")
    if not stamps:
        raise bag.error(f"{topic} holds no messages: no poses to place the detections at")
    if not frames[0]:
        raise bag.error(f"the poses on {topic} name no frame (header.frame_id is empty)")
    stamps, keep = _clocked(bag, topic, stamps, logs)
    kept = [int(k) for k in np.nonzero(keep)[0]]
    stamps, t, q = [stamps[k] for k in kept], [t[k] for k in kept], [q[k] for k in kept]
    _check_clock(bag, topic, stamps)
    return _track(frames[0], child, stamps, t, q)


def _track(parent: str, child: str, stamps: Sequence[float], t: Sequence[Any], q: Sequence[Any]) -> Track:
    order = np.argsort(np.asarray(stamps, float), kind="stable")
    s = np.asarray(stamps, float)[order]
    T, Q = np.asarray(t, float)[order], np.asarray(q, float)[order]
    keep = np.r_[True, np.diff(s) > 0]  # one pose per stamp: the first
    return Track(parent, child, s[keep], T[keep], Q[keep])


def _tf_tree(bag: Bag) -> TfTree:
    """Every transform on /tf and /tf_static, one track per child frame."""
    samples: dict[tuple[str, str], tuple[list[float], list[Any], list[Any]]] = {}
    static: set[tuple[str, str]] = set()
    for topic in TF_TOPICS:
        if topic not in bag.topics:
            continue
        if bag.topics[topic] != TF:
            raise bag.error(f"{topic} holds {bag.topics[topic]}, not {TF}")
        read: list[tuple[tuple[str, str], float, float, Any, Any]] = []  # (edge, stamp, logged, t, q)
        for i, logged, message in bag.messages(topic):
            for tr in message.transforms:
                key = (_frame(tr.header.frame_id), _frame(tr.child_frame_id))
                v, r = tr.transform.translation, tr.transform.rotation
                read.append((key, _stamp(tr.header), logged, (v.x, v.y, v.z), (r.x, r.y, r.z, r.w)))
                _check_values(bag, (*read[-1][3], *read[-1][4]), f"the transform {key[0]} → {key[1]} of message "
                                                                 f"{i + 1} on {topic} (x, y, z, qx, qy, qz, qw)")
                _check_rotation(bag, read[-1][4], f"the rotation of the transform {key[0]} → {key[1]} of message "
                                                  f"{i + 1} on {topic} (qx, qy, qz, qw)")
        stamps, keep = [r[1] for r in read], np.ones(len(read), bool)  # /tf_static: stamps never used
        if topic == "/tf":  # edge by edge: one publisher may never stamp (log times), another start before /clock
            edges: dict[tuple[str, str], list[int]] = {}
            for k, r in enumerate(read):
                edges.setdefault(r[0], []).append(k)
            for key, rows in edges.items():
                mine, kept_ = _clocked(bag, f"{topic} ({key[0]} → {key[1]})", [read[k][1] for k in rows],
                                       [read[k][2] for k in rows], "transforms")
                for k, stamp, ok in zip(rows, mine, kept_, strict=True):
                    stamps[k], keep[k] = stamp, ok
        for (key, _, _, t, q), stamp, kept in zip(read, stamps, keep, strict=True):
            if topic != "/tf":
                static.add(key)
            if kept:
                s_, t_, q_ = samples.setdefault(key, ([], [], []))
                s_.append(stamp)
                t_.append(t)
                q_.append(q)
        if topic == "/tf":
            _check_clock(bag, topic, [s for s, k in zip(stamps, keep, strict=True) if k])
    tree = TfTree()
    parents: dict[str, str] = {}
    for (parent, child), (s, t, q) in samples.items():
        if child in parents:
            raise bag.error(f"frame {child!r} has two parents in the transforms: {parents[child]!r} and {parent!r}")
        parents[child] = parent
        if (parent, child) in static:
            tree.add(Track(parent, child, np.zeros(1), np.asarray(t[-1:], float), np.asarray(q[-1:], float), True))
        else:
            tree.add(_track(parent, child, s, t, q))
    return tree


# -- detections ----------------------------------------------------------------------------------------
def _best(results: Sequence[Any]) -> Any:
    return max(results, key=lambda r: float(getattr(getattr(r, "hypothesis", r), "score", 0.0)))


def _class_of(hypothesis: Any) -> str:
    inner = getattr(hypothesis, "hypothesis", None)
    return str(inner.class_id if inner is not None else hypothesis.id).strip()


def _detections(bag: Bag, topic: str, labels: Mapping[str, str],
                map_frame: str) -> tuple[list[float], list[Look], list[int]]:
    """Per message kept: its stamp, its detections as (class, frame, position in that frame), and its number on the
    topic (from 1). A detection at exactly (0, 0, 0) of a frame other than the map's is refused: it has no position
    (see :func:`_no_position`)."""
    three_d = bag.topics[topic].endswith("3DArray")
    stamps: list[float] = []
    logs: list[float] = []
    looks: list[Look] = []
    for i, logged, message in bag.messages(topic):
        if i >= MAX_OBSERVATIONS:
            raise bag.error(f"{topic} holds more than {MAX_OBSERVATIONS:,} messages: each is an observation, and seal "
                            f"takes at most {MAX_OBSERVATIONS:,}; cut the bag (ros2 bag convert, rosbag filter)")
        if len(message.detections) > MAX_DETECTIONS:
            raise bag.error(f"message {i + 1} on {topic} holds {len(message.detections):,} detections: seal takes at "
                            f"most {MAX_DETECTIONS:,} in one observation")
        stamps.append(_stamp(message.header))
        logs.append(logged)
        seen = []
        for j, det in enumerate(message.detections):
            if not det.results:
                continue  # a box with no hypothesis names no class
            best = _best(det.results)
            cls = _class_of(best)
            cls = labels.get(cls, cls)
            frame = _frame(det.header.frame_id or message.header.frame_id)
            if not cls:
                raise bag.error(f"detection {j + 1} of message {i + 1} on {topic} has an empty class id")
            if not frame:
                raise bag.error(f"message {i + 1} on {topic} names no frame (header.frame_id is empty)")
            p = det.bbox.center.position if three_d else best.pose.pose.position
            seen.append((cls, frame, (float(p.x), float(p.y), float(p.z))))
            _check_values(bag, seen[-1][2], f"the position of detection {j + 1} of message {i + 1} on {topic}")
            if seen[-1][2] == (0.0, 0.0, 0.0) and frame != map_frame:
                raise bag.error(_no_position(f"detection {j + 1} ({cls}) of message {i + 1} on {topic}", frame,
                                             three_d))
        looks.append(seen)
    if not stamps:
        raise bag.error(f"{topic} holds no messages: nothing was detected")
    stamps, keep = _clocked(bag, topic, stamps, logs)
    numbers = [int(k) + 1 for k in np.nonzero(keep)[0]]
    stamps, looks = [stamps[n - 1] for n in numbers], [looks[n - 1] for n in numbers]
    _check_clock(bag, topic, stamps)
    return stamps, looks, numbers


def _no_position(what: str, frame: str, three_d: bool) -> str:
    """Why a detection at (0, 0, 0) of a sensor's frame is refused: that is the sensor itself, where no object can
    be; it is what a detector that finds boxes in the image but no depth leaves in a message's position (most 2-D
    detectors' Detection2DArray), and every such detection would be put at the camera."""
    field = "its bounding box's centre (bbox.center)" if three_d else "its hypothesis's pose (results[].pose.pose)"
    return (f"{what} is at (0, 0, 0) in frame {frame!r}, the sensor's own origin: {field} gives no position. A "
            f"detector that finds boxes in the image without depth leaves it empty; seal needs where each object is "
            f"(a depth camera or a 3-D detector fills it), in the frame of the header")


def _choose(bag: Bag, given: str | None, types: Sequence[str], what: str, option: str,
            extra: Sequence[str] = ()) -> str:
    """The topic given (checked), or the only topic of the right types in the bag."""
    topics = bag.topics
    listing = ", ".join(f"{t} ({m})" for t, m in sorted(topics.items())) or "none"
    if given is not None:
        if given not in topics:
            raise bag.error(f"no topic {given} in the bag (its topics: {listing})")
        if topics[given] not in types and given not in extra:
            raise bag.error(f"{given} holds {topics[given]}, not {what} ({', '.join(types)})")
        return given
    found = sorted(t for t, m in topics.items() if m in types)
    if len(found) == 1:
        return found[0]
    if not found:
        raise bag.error(f"the bag has no {what} topic ({', '.join(types)}); its topics: {listing}")
    raise bag.error(f"the bag has several {what} topics ({', '.join(found)}): choose one with {option}")


def read_run(path: str | Path, *, pose_topic: str | None = None, detections_topic: str | None = None,
             frame: str = "map", base_frame: str = "base_link", labels: Mapping[str, str] | None = None) -> Run:
    """The run in a bag, as observations in ``frame`` (see the module docstring).

    ``pose_topic``: a pose topic, or ``/tf`` for the transforms; by default ``/tf`` when it links
    ``frame`` to ``base_frame``, else the bag's only pose topic. ``detections_topic``: by default
    the bag's only vision_msgs detection array topic. ``labels``: class id → class name
    (:mod:`seal_cli.ros.labels`), for detectors that name classes by number.
    """
    frame = _frame(frame)
    with open_bag(path) as bag:
        tree = _tf_tree(bag)
        source = pose_topic
        if source in (None, "/tf") and any(t in bag.topics for t in TF_TOPICS):
            try:
                tree.path(frame, base_frame)
                source = "/tf"
            except SealError as exc:
                if source == "/tf" or not any(m in POSE_TYPES for m in bag.topics.values()):
                    raise bag.error(f"the transforms do not place {base_frame!r} in {frame!r}: {exc.message}"
                                    f"{_no_map_frame(tree, frame)}") from None
        if source != "/tf":
            source = _choose(bag, source, POSE_TYPES, "robot pose", "--pose-topic")
        topic = _choose(bag, detections_topic, DETECTION_TYPES, "detection", "--detections-topic")
        robot = None if source == "/tf" else _pose_track(bag, source, base_frame)
        stamps, looks, numbers = _detections(bag, topic, labels or {}, frame)
        return _place(bag, tree, robot, source, topic, frame, base_frame, stamps, looks, numbers)


def _place(bag: Bag, tree: TfTree, robot: Track | None, source: str, topic: str, frame: str, base_frame: str,
           stamps: list[float], looks: list[Look], numbers: list[int]) -> Run:
    """Each detection message at the robot's pose at its stamp, its detections carried into ``frame``."""
    s = np.asarray(stamps, float)
    try:
        if robot is None:
            span, (t, q) = tree.span(frame, base_frame), tree.lookup(frame, base_frame, s)
        else:
            _link(tree, robot)
            above = tree.span(frame, robot.parent)
            span = (max(robot.span[0], above[0]), min(robot.span[1], above[1]))
            t, q = compose(tree.lookup(frame, robot.parent, s), robot.at(s))
    except SealError as exc:
        raise bag.error(f"cannot place the robot in frame {frame!r}: {exc.message}{_no_map_frame(tree, frame)}") \
            from None
    placed = (s >= span[0] - TOLERANCE) & (s <= span[1] + TOLERANCE)
    if not placed.any():
        raise bag.error(f"no message on {topic} falls within the poses' time span [{span[0]:.3f}, {span[1]:.3f}] s "
                        f"(its stamps run [{s.min():.3f}, {s.max():.3f}] s): are they on different clocks?")
    yaw = quaternion_yaw(q)
    order = [int(k) for k in np.argsort(s, kind="stable") if placed[k]]  # jitter within JUMP is sorted out
    points = _in_frame(bag, tree, frame, s, looks, placed)
    observations = [Observation((float(t[k, 0]), float(t[k, 1]), float(yaw[k])), points[int(k)],
                                Where(f"{bag.path} {topic} message {numbers[k]}")) for k in order]
    for k, look in zip(order, observations, strict=True):  # what the transforms made of them, bounded alike
        _check_values(bag, look.pose, f"the robot's pose at message {numbers[k]} on {topic}, in frame {frame!r} "
                                      f"(x, y, yaw)")
        for cls, at in look.detections or ():
            _check_values(bag, at, f"a detection of {cls} in message {numbers[k]} on {topic}, in frame {frame!r} "
                                   f"(x, y)")
    return Run(tuple(observations), tuple(float(s[k]) for k in order), source, topic, int((~placed).sum()),
               tuple(bag.notes))


def _no_map_frame(tree: TfTree, frame: str) -> str:
    """How to go on when the map frame is nowhere in the bag (robot5): a run recorded without a localiser has only
    odometry, and its top frame (``odom``) is what its poses and detections can be given in."""
    if frame in tree.frames:
        return ""
    roots = sorted({tree.root(f) for f in tree.frames})
    top = f"--frame {roots[0]}" if len(roots) == 1 else f"--frame with one of {', '.join(roots)}"
    return (f". No localiser's pose or {frame} → odom transform was recorded: record /tf with the localiser running "
            f"(amcl, slam_toolbox) or its pose topic (/amcl_pose), or, if the map is drawn in the odometry's frame "
            f"(a short run from where the map was started), give {top}")


def _link(tree: TfTree, robot: Track) -> None:
    """Join the pose topic to the transforms: as the robot frame's parent when /tf gives it none; else, when
    /tf does not reach the topic's frame (a localiser's ``map`` over ``odom → base_link``), as the link
    from that frame to the robot frame's root at the topic's stamps — ``map → odom``, as a localiser
    publishes it — so that detections in the robot's frames reach ``map`` too."""
    if robot.child not in tree.tracks:
        tree.add(robot)
        return
    if tree.connected(robot.parent, robot.child):
        return
    root = tree.root(robot.child)
    below = tree.lookup(root, robot.child, robot.stamps)
    t, q = compose((robot.t, robot.q), invert(below))
    tree.add(Track(robot.parent, root, robot.stamps, t, q))


def _in_frame(bag: Bag, tree: TfTree, frame: str, stamps: Array,
              looks: list[Look],
              placed: NDArray[np.bool_]) -> dict[int, tuple[tuple[str, tuple[float, float]], ...]]:
    """Every placed message's detections as (class, (x, y)) in ``frame``: one lookup per detection frame."""
    rows = [(k, cls, source, p) for k, look in enumerate(looks) if placed[k] for cls, source, p in look]
    out: dict[int, list[tuple[str, tuple[float, float]]]] = {int(k): [] for k in np.nonzero(placed)[0]}
    for source in sorted({r[2] for r in rows}):
        mine = [r for r in rows if r[2] == source]
        at = np.array([stamps[r[0]] for r in mine])
        points = np.array([r[3] for r in mine], float)
        if source != frame:
            try:
                lo, hi = tree.span(frame, source)
                if at.min() < lo - TOLERANCE or at.max() > hi + TOLERANCE:
                    raise SealError(f"the transforms from {source!r} to {frame!r} cover [{lo:.3f}, {hi:.3f}] s, "
                                    f"not the detections' stamps [{at.min():.3f}, {at.max():.3f}] s")
                points = apply(tree.lookup(frame, source, at), points)
            except SealError as exc:
                raise bag.error(f"cannot carry the detections on frame {source!r} into {frame!r}: "
                                f"{exc.message}") from None
        for (k, cls, _, _), p in zip(mine, points, strict=True):
            out[k].append((cls, (float(p[0]), float(p[1]))))
    return {k: tuple(v) for k, v in out.items()}
