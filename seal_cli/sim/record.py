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
            if cloud.get("commanded_particles") is not None:
                X, W = cloud["commanded_particles"]
                stream.log(f"commanded/{cloud['commanded']}/particles",
                           rr.Points2D(X, radii=0.03, colors=_weights_colours(W)))
            for cls, (X, W) in cloud["objects"].items():
                stream.log(f"objects/{cls}/particles", rr.Points2D(X, radii=0.03, colors=_weights_colours(W)))
        stream.flush()
        del stream


def write_png(path: str | Path, agent: Agent, title: str = "") -> None:
    """The map, the robot's path and where it acted; when the policy kept belief clouds, two panels:
    the belief of a step after its last look (the last step that served another frame, such as
    Pick(spoon) for Stir(cup), else the last step), and beside it the belief of the commanded frame
    that step serves (the whole task's)."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    from seal_cli.maps.drawing import draw_map

    m = agent.scene.map
    xmin, ymin, xmax, ymax = m.bounds
    clouds: list[dict[str, Any]] = agent.policy.clouds
    kept = [c for c in clouds if c["frame_particles"] is not None]
    serving = [c for c in kept if c.get("commanded") and c["commanded"] != c["frame"]]
    last = (serving or kept)[-1] if kept else None   # the last look for a step that serves another frame
    panels = 2 if last is not None and last.get("commanded_particles") is not None else 1
    width = 9.0 * panels
    fig, axes = plt.subplots(1, panels, figsize=(width, max(3.0, 9.0 * (ymax - ymin) / (xmax - xmin) + 0.6)),
                             squeeze=False)
    try:
        beliefs = [("frame_particles", "frame", "step"), ("commanded_particles", "commanded", "commanded")][:panels]
        for ax, (key, name, label) in zip(axes[0], beliefs, strict=True):
            draw_map(ax, m, objects=False, robot=False)
            if last is not None and last.get(key) is not None:
                X, W = last[key]
                ax.scatter(X[:, 0], X[:, 1], s=4 + 40 * W / max(W.max(), 1e-12), c="#ff7f0e", alpha=0.6, zorder=2,
                           label=f"{label} belief: {last[name]}")
            _draw_run(ax, agent)
            ax.legend(loc="upper right", fontsize=7)
        axes[0][0].set_title(title or m.name)
        if panels == 2:
            axes[0][1].set_title("the commanded frame's belief")
        with atomic_output(path) as tmp:
            fig.savefig(tmp, dpi=120, format="png", bbox_inches="tight")
    finally:
        plt.close(fig)


def _draw_run(ax: Any, agent: Agent) -> None:
    """The path, where the robot acted, and where the things are."""
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
