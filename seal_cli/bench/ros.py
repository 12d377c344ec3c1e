"""``seal bench ros``: a robot's bag read and filtered, at the paper's scale.

The bag is written first (not timed): the shipped apartment, the robot driving the paper
benchmark's loop (:mod:`seal_cli.bench.perf`) at 10 Hz for ``poses`` poses, published as ``/tf``
(``map → odom`` static, ``odom → base_link`` moving), and ``messages`` ``vision_msgs/Detection3DArray``
messages spread evenly over the run, in ``base_link``, holding what the map's sensor model sees
of the ground-truth objects from the pose then (:func:`~seal_cli.sensing.model.simulate_detections`).

Timed (CPU seconds of this process): :func:`~seal_cli.ros.bags.read_run` (open, deserialise,
chain the transforms, interpolate a pose per message, carry the detections into ``map``) and
then one SeFM update per observation with the paper's frames — Pick(cup), Pick(spoon), Stir(cup,
spoon), 2 object classes, 200 particles. ``updates_per_s`` is messages over the two together.
Then the same updates again with the Rerun recorder (``seal localize --rrd``; the extra ``rrd`` extra's
rerun-sdk): ``recorded_updates_per_s`` (reading included, the recording written and closed) and the
file's size, ``rrd_bytes`` (``None`` without rerun).
"""

from __future__ import annotations

import math
import tempfile
import time
from pathlib import Path
from typing import Any

import numpy as np

from seal_cli.frames.library import Library
from seal_cli.maps.model import Map
from seal_cli.planning.state import State, robot_facts
from seal_cli.sefm.filter import SeFM, SeFMConfig
from seal_cli.sensing.model import simulate_detections

__all__ = ["FORMATS", "measure"]

FORMATS = {"mcap": "run.mcap", "sqlite3": "run_db3", "ros1": "run.bag"}
LOOP = [(-6, -3), (-3.5, -0.2), (-1, -2.5), (1, -2.5), (2.5, -4.7), (5, -4.5), (7, -3), (5, -4.5), (2.5, -4.7),
        (1, -2), (0.5, 0.5), (0.5, 2.5)]
"""The paper benchmark's loop through the apartment (seal_cli.bench.perf)."""
RATE = 10.0
"""Poses per second (Hz)."""


def _poses(n: int) -> list[tuple[float, float, float]]:
    """``n`` poses evenly along the loop, each facing the way it goes."""
    points = np.array(LOOP, float)
    lengths = np.r_[0.0, np.cumsum(np.hypot(*np.diff(points, axis=0).T))]
    at = np.linspace(0.0, lengths[-1], n)
    x, y = np.interp(at, lengths, points[:, 0]), np.interp(at, lengths, points[:, 1])
    leg = np.clip(np.searchsorted(lengths, at, side="right") - 1, 0, len(points) - 2)
    d = points[leg + 1] - points[leg]
    return [(float(a), float(b), float(math.atan2(v, u))) for a, b, (u, v) in zip(x, y, d, strict=True)]


def write_run(path: Path, m: Map, poses: int, messages: int, rng: np.random.Generator) -> None:
    """The benchmark's bag (see the module docstring)."""
    from seal_cli.ros.messages import DETECTION_3D, TF, typestore
    from seal_cli.ros.writing import detection_array, is_ros1, tf_message, write_bag

    ros1 = is_ros1(path)
    store = typestore(ros1)
    track = _poses(poses)
    start = 1_700_000_000.0
    out: list[Any] = [("/tf_static", TF, start, tf_message(store, start, [("map", "odom", 0.0, 0.0, 0.0)], ros1))]
    for k, (x, y, yaw) in enumerate(track):
        t = start + k / RATE
        out.append(("/tf", TF, t, tf_message(store, t, [("odom", "base_link", x, y, yaw)], ros1)))
    ids = {cls: k for k, cls in enumerate(m.classes)}
    for k in range(messages):
        t = start + (k + 0.5) * (poses - 1) / RATE / messages
        f = (t - start) * RATE
        x, y, yaw = track[min(int(round(f)), len(track) - 1)]
        c, s = math.cos(yaw), math.sin(yaw)
        seen = []
        for d in simulate_detections(m, (x, y, yaw), [p.name for p in m.places], rng):
            dx, dy = d.at[0] - x, d.at[1] - y
            seen.append((ids[d.cls] if ros1 else d.cls, c * dx + s * dy, -s * dx + c * dy, 0.8))
        out.append(("/detections", DETECTION_3D, t, detection_array(store, t, "base_link", seen, ros1)))
    write_bag(path, sorted(out, key=lambda msg: msg[2]), store)


def measure(m: Map, library: Library, fmt: str = "mcap", poses: int = 1000, messages: int = 200, seed: int = 0,
            particles: int = 200) -> dict[str, Any]:
    """Write the bag, then time reading it and filtering it (see the module docstring)."""
    from seal_cli.ros.bags import read_run

    rng = np.random.default_rng(seed)
    bindings = (library.frame("Pick").bind({"theme": "cup"}), library.frame("Pick").bind({"theme": "spoon"}),
                library.frame("Stir").bind({"theme": "cup"}))
    with tempfile.TemporaryDirectory(prefix="seal-bench-ros-") as folder:
        path = Path(folder) / FORMATS[fmt]
        write_run(path, m, poses, messages, rng)
        size = sum(p.stat().st_size for p in ([path] if path.is_file() else path.rglob("*")) if p.is_file())
        labels = {str(k): cls for k, cls in enumerate(m.classes)}
        t0 = time.process_time()
        run = read_run(path, labels=labels if fmt == "ros1" else None)
        t1 = time.process_time()
    sefm = SeFM(m, bindings, State.of(robot_facts(None), library.taxonomy), np.random.default_rng(seed),
                SeFMConfig(particles=particles))
    t2 = time.process_time()
    sefm.follow(list(run.observations), 0)
    t3 = time.process_time()
    updates = len(run.observations)
    recorded = _recorded(m, bindings, library, run, seed, particles)
    return {"format": fmt, "poses": poses, "messages": messages, "bag_bytes": size, "updates": updates,
            "frames": len(bindings), "objects": len(sefm.object_classes), "particles": particles,
            "read_s": round(t1 - t0, 3), "filter_s": round(t3 - t2, 3),
            "updates_per_s": round(updates / max(t1 - t0 + t3 - t2, 1e-9), 1),
            "recorded_updates_per_s": None if recorded is None else
            round(updates / max(t1 - t0 + recorded[0], 1e-9), 1),
            "rrd_bytes": None if recorded is None else recorded[1],
            "detections": sum(len(o.detections or ()) for o in run.observations)}


def _recorded(m: Map, bindings: Any, library: Library, run: Any, seed: int,
              particles: int) -> tuple[float, int] | None:
    """The same updates with the Rerun recorder: (CPU seconds, file bytes), or None without rerun."""
    try:
        import rerun  # noqa: F401
    except ImportError:
        return None
    from seal_cli.sefm.observers.rerun import RerunRecorder

    with tempfile.TemporaryDirectory(prefix="seal-bench-rrd-") as folder:
        path = Path(folder) / "run.rrd"
        t0 = time.process_time()
        sefm = SeFM(m, bindings, State.of(robot_facts(None), library.taxonomy), np.random.default_rng(seed),
                    SeFMConfig(particles=particles), [RerunRecorder(path, stamps=run.stamps)])
        sefm.follow(list(run.observations), 0)
        sefm.close()
        return time.process_time() - t0, path.stat().st_size
