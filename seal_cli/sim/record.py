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


ROBOT = (31, 119, 180)
SEEN = (44, 160, 44)


def write_rrd(path: str | Path, agent: Agent) -> None:
    """A Rerun recording over the timeline ``step``, laid out as ``seal localize``'s
    (:mod:`seal_cli.sefm.observers.rerun_scene`): the map image, rooms and places; the robot's pose,
    path and narration (``robot/log``); what it saw; the path length (``metrics/path_m``); and — when
    the policy kept them — the particle clouds of the frame at hand and of every object (class ids,
    radius by weight, logged when the belief changed), the frame's room masses (``metrics/rooms/<frame>``)
    and the objects' effective sample sizes (``metrics/ess``)."""
    import rerun as rr

    from seal_cli.sefm.modes import room_masses
    from seal_cli.sefm.observers.rerun import CHANGE, cell_masses, radii, total_variation
    from seal_cli.sefm.observers.rerun_scene import DRAW, Classes, batching, blueprint, log_map, save
    from seal_cli.sefm.resampling import ess

    m = agent.scene.map
    clouds: list[dict[str, Any]] = agent.policy.clouds
    frames = list(dict.fromkeys(c["frame"] for c in clouds if c["frame_particles"] is not None and c["frame"]))
    objects = list(dict.fromkeys(cls for c in clouds for cls in c["objects"]))
    classes = Classes(objects, frames)
    panels = [("series", "path (m)", "/metrics/path_m"), ("log", "what the robot did", "/robot/log")]
    if frames:
        panels.insert(1, ("series", "room mass of the frame at hand", "/metrics/rooms"))
    if objects:
        panels.insert(2, ("series", "effective sample size", "/metrics/ess"))
    stream = rr.RecordingStream("seal_run", recording_id=f"{m.name}-seal-run",
                                batcher_config=batching(), send_properties=False)
    with atomic_output(path) as tmp:
        save(stream, tmp)  # without rerun's footer, as seal localize's
        stream.set_log_time_enabled(False)
        stream.set_log_tick_enabled(False)
        stream.send_blueprint(blueprint(m, frames, panels))
        classes.log(stream)
        log_map(stream, m, [(i.id, i.at) for i in agent.world.items.values() if not i.movable])
        stream.set_time("step", sequence=0)
        trail: list[tuple[float, float]] = []
        for record in agent.records:
            stream.set_time("step", sequence=record.step)
            x, y, yaw = record.pose
            if not trail or trail[-1] != (x, y):
                trail.append((x, y))
                stream.log("robot/pose", rr.Points2D([[x, y]], radii=0.12, colors=[ROBOT], draw_order=DRAW["robot"]),
                           rr.Arrows2D(origins=[[x, y]], vectors=[[0.5 * np.cos(yaw), 0.5 * np.sin(yaw)]],
                                       colors=[ROBOT], draw_order=DRAW["robot"]))
                if len(trail) > 1:
                    stream.log("robot/path", rr.LineStrips2D([trail], colors=[ROBOT], draw_order=DRAW["robot"]))
            stream.log("robot/log", rr.TextLog(f"{record.kind}: {record.text}"))
            stream.log("metrics/path_m", rr.Scalars(record.path_m))
            for item in record.data.get("seen", []):
                thing = agent.world.items[item]
                stream.log(f"observations/{thing.key}", rr.Points2D([thing.at], radii=0.1, colors=[SEEN],
                                                                   draw_order=DRAW["observations"]))
        shown: dict[str, dict[int, float]] = {}  # what each cloud's masses were when it was last logged

        def changed(key: str, X: np.ndarray, W: np.ndarray, last: bool) -> bool:
            masses = cell_masses(X, W, m.bounds)
            if last or key not in shown or total_variation(masses, shown[key]) > CHANGE:
                shown[key] = masses
                return True
            return False

        named: set[str] = set()  # the metrics whose series names went with their first values
        for k, cloud in enumerate(clouds):
            stream.set_time("step", sequence=cloud["step"])
            last = k == len(clouds) - 1
            if cloud["frame_particles"] is not None and cloud["frame"]:
                X, W = cloud["frame_particles"]
                fid = cloud["frame"]
                lines = [] if fid in named else [rr.SeriesLines(names=[*m.room_names, "_outside"])]
                named.add(fid)
                stream.log(f"metrics/rooms/{fid}", rr.Scalars(list(room_masses(m, X, W).values())), *lines)
                if changed(f"frames/{fid}", X, W, last):
                    stream.log(f"frames/{fid}/particles", rr.Points2D(X, radii=radii(W), class_ids=[classes.ids[fid]],
                                                                     draw_order=DRAW["frames"]))
            if cloud["objects"]:
                lines = [] if "ess" in named else [rr.SeriesLines(names=objects)]
                named.add("ess")
                stream.log("metrics/ess", rr.Scalars([float(ess(cloud["objects"][c][1])) if c in cloud["objects"]
                                                      else 0.0 for c in objects]), *lines)
            if cloud.get("commanded_particles") is not None:
                X, W = cloud["commanded_particles"]
                key = f"commanded/{cloud['commanded']}"
                if changed(key, X, W, last):
                    stream.log(f"{key}/particles", rr.Points2D(X, radii=radii(W), draw_order=DRAW["frames"]))
            for cls, (X, W) in cloud["objects"].items():
                if changed(f"objects/{cls}", X, W, last):
                    stream.log(f"objects/{cls}/particles", rr.Points2D(X, radii=radii(W),
                                                                      class_ids=[classes.ids[cls]],
                                                                      draw_order=DRAW["objects"]))
        stream.flush()
        stream.disconnect()


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
    stood: dict[tuple[float, float], list[str]] = {}      # where the robot stood for each action, numbered
    acts = [r for r in agent.records if r.kind == "act"]
    for n, record in enumerate(acts, 1):
        stood.setdefault((round(record.pose[0], 2), round(record.pose[1], 2)), []).append(f"{n}. {record.text}")
    for at, texts in stood.items():
        ax.plot(at[0], at[1], "D", color="#2ca02c", markersize=6, zorder=6)
        ax.annotate("\n".join(texts), at, xytext=(4, 4), textcoords="offset points", fontsize=6,
                    color="#2ca02c", zorder=6)
    for item in agent.world.items.values():
        if item.key == "person" and not item.movable:     # the people, and the speaker ("me")
            ax.plot(*item.at, "^", markersize=7, color="#9467bd", zorder=5)
            ax.annotate(item.id, item.at, xytext=(4, -8), textcoords="offset points", fontsize=6,
                        color="#9467bd", zorder=5)
        elif item.movable:
            ax.plot(*agent.world.position(item.id), "*", markersize=6, color="#d62728", zorder=3)
