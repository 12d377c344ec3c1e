"""Pictures and recordings of a robot's run (``seal run --png`` / ``--rrd``).

Both are written from what the run left behind: the agent's records (poses, path, what it saw
and did), the world, and — for a SeFM policy that kept them — the particle clouds after every
belief update. Rerun and matplotlib are imported only here, inside the functions.
"""

from __future__ import annotations

from pathlib import Path
from typing import Any

import numpy as np

from seal_cli.fileio import atomic_output
from seal_cli.sim.agent import Agent

__all__ = ["write_png", "write_rrd"]


def _weights_colours(W: np.ndarray) -> np.ndarray:
    """RGBA per particle: light for small weights, deep red for the heaviest."""
    w = W / W.max() if len(W) and W.max() > 0 else np.zeros(len(W))
    colours = np.zeros((len(W), 4), dtype=np.uint8)
    colours[:, 0] = 200
    colours[:, 1] = (200 * (1 - w)).astype(np.uint8)
    colours[:, 2] = (60 * (1 - w)).astype(np.uint8)
    colours[:, 3] = 255
    return colours


def write_rrd(path: str | Path, agent: Agent) -> None:
    """A Rerun recording over the timeline ``step``: the map, the robot's pose and path, what it saw,
    and the particle clouds of the frame at hand and of every object (when the policy kept them)."""
    import rerun as rr

    scene = agent.scene
    m = scene.map
    stream = rr.RecordingStream("seal_run")
    with atomic_output(path) as tmp:
        stream.save(str(tmp))
        stream.set_time("step", sequence=0)
        free = scene.grid.free_points
        stream.log("map/occupancy", rr.Points2D(free, radii=scene.grid.resolution / 2, colors=[230, 230, 230]),
                   static=True)
        if m.rooms:
            stream.log("map/rooms", rr.LineStrips2D([list(r.polygon) + [r.polygon[0]] for r in m.rooms],
                                                    labels=[r.name for r in m.rooms]), static=True)
        places = [i for i in agent.world.items.values() if not i.movable]
        if places:
            stream.log("map/places", rr.Points2D([p.at for p in places], labels=[p.id for p in places],
                                                 radii=0.08, colors=[90, 90, 90]), static=True)
        trail: list[tuple[float, float]] = []
        for record in agent.records:
            stream.set_time("step", sequence=record.step)
            trail.append((record.pose[0], record.pose[1]))
            stream.log("robot/pose", rr.Points2D([record.pose[:2]], radii=0.12, colors=[31, 119, 180]))
            if len(trail) > 1:
                stream.log("robot/path", rr.LineStrips2D([trail], colors=[31, 119, 180]))
            stream.log("robot/log", rr.TextLog(f"{record.kind}: {record.text}"))
            stream.log("metrics/path_m", rr.Scalars(record.path_m))
            for item in record.data.get("seen", []):
                at = agent.world.items[item].at
                stream.log(f"observations/{agent.world.items[item].key}", rr.Points2D([at], radii=0.1,
                                                                                   colors=[44, 160, 44]))
        for cloud in agent.policy.clouds:
            stream.set_time("step", sequence=cloud["step"])
            if cloud["frame_particles"] is not None:
                X, W = cloud["frame_particles"]
                stream.log(f"frames/{cloud['frame']}/particles", rr.Points2D(X, radii=0.03,
                                                                             colors=_weights_colours(W)))
            for cls, (X, W) in cloud["objects"].items():
                stream.log(f"objects/{cls}/particles", rr.Points2D(X, radii=0.03, colors=_weights_colours(W)))
        stream.flush()
        del stream


def write_png(path: str | Path, agent: Agent, title: str = "") -> None:
    """The map, the robot's path and where it acted, and the last belief clouds (if kept)."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    from seal_cli.maps.drawing import draw_map

    m = agent.scene.map
    xmin, ymin, xmax, ymax = m.bounds
    fig, ax = plt.subplots(figsize=(9.0, max(3.0, 9.0 * (ymax - ymin) / (xmax - xmin) + 0.6)))
    try:
        draw_map(ax, m, objects=False, robot=False)
        clouds: list[dict[str, Any]] = agent.policy.clouds
        if clouds and clouds[-1]["frame_particles"] is not None:
            X, W = clouds[-1]["frame_particles"]
            ax.scatter(X[:, 0], X[:, 1], s=4 + 40 * W / max(W.max(), 1e-12), c="#ff7f0e", alpha=0.6, zorder=2,
                       label=f"belief: {clouds[-1]['frame']}")
        trail = np.asarray(agent.world.robot.trajectory)
        ax.plot(trail[:, 0], trail[:, 1], "-", color="#1f77b4", linewidth=2, zorder=4, label="path")
        ax.plot(*trail[0], "o", color="#1f77b4", markersize=8, zorder=5)
        for record in agent.records:
            if record.kind == "act":
                ax.plot(record.pose[0], record.pose[1], "D", color="#2ca02c", markersize=6, zorder=6)
                ax.annotate(record.text, record.pose[:2], xytext=(4, 4), textcoords="offset points", fontsize=6,
                            color="#2ca02c", zorder=6)
        for item in agent.world.items.values():
            if item.movable:
                ax.plot(*agent.world.position(item.id), "*", markersize=6, color="#d62728", zorder=3)
        ax.set_title(title or m.name)
        ax.legend(loc="upper right", fontsize=7)
        with atomic_output(path) as tmp:
            fig.savefig(tmp, dpi=120, format="png", bbox_inches="tight")
    finally:
        plt.close(fig)
