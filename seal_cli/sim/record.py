"""Pictures and recordings of a robot's run (``seal run --png`` / ``--rrd``).

Both are written from what the run left behind: the agent's records (poses, path, what it saw
and did), the world, and — for a SeFM policy that kept them — the particle clouds after every
belief update. Rerun and matplotlib are imported only here, inside the functions.
"""

from __future__ import annotations

import math
import re
from collections.abc import Callable, Sequence
from pathlib import Path
from typing import Any

import numpy as np

from seal_cli.fileio import atomic_output
from seal_cli.maps.drawing import cut, text_as_written
from seal_cli.sim.agent import Agent, Record

__all__ = ["write_png", "write_rrd"]


ROBOT = (31, 119, 180)
SEEN = (44, 160, 44)


def write_rrd(path: str | Path, agent: Agent) -> None:
    """A Rerun recording over the timeline ``step``, laid out as ``seal localize``'s
    (:mod:`seal_cli.sefm.observers.rerun`, whose helpers it uses): the map image, rooms and places;
    the robot's pose, path (a point every 0.25 m) and narration (``robot/log``); what it saw
    (``observations``: one entity, class ids); and — when the policy kept them — the particle clouds
    of every object (``objects/particles``) and of the frame at hand with the commanded frame it
    serves (``frames/particles``), each point with its class's id, radius by weight, logged when a
    belief changed. The metrics — the path length (``metrics/path_m``), the room masses of each frame
    while at hand (``metrics/rooms/<frame>``) and the objects' effective sample sizes
    (``metrics/ess``) — are sent at the end, one chunk each with all steps in columns. No footer."""
    import rerun as rr

    from seal_cli.sefm.modes import room_masses
    from seal_cli.sefm.observers.rerun import (
        CHANGE,
        TRAIL_STEP,
        cell_masses,
        log_clouds,
        log_detections,
        radii,
        total_variation,
    )
    from seal_cli.sefm.observers.rerun_scene import (
        DRAW,
        Classes,
        batching,
        blueprint,
        flush,
        log_map,
        save,
        send_series,
        series_colour,
        writing,
    )
    from seal_cli.sefm.resampling import ess

    m = agent.scene.map
    clouds: list[dict[str, Any]] = agent.policy.clouds
    at_hand = [c["frame"] for c in clouds if c["frame_particles"] is not None and c["frame"]]
    commanded = [c["commanded"] for c in clouds if c.get("commanded_particles") is not None and c["commanded"]]
    frames = list(dict.fromkeys([*at_hand, *commanded]))
    objects = list(dict.fromkeys(cls for c in clouds for cls in c["objects"]))
    classes = Classes(objects, frames)
    panels = [("series", "path (m)", "/metrics/path_m"), ("log", "what the robot did", "/robot/log")]
    if at_hand:
        panels.insert(1, ("series", "room mass of the frame at hand", "/metrics/rooms"))
    if objects:
        panels.insert(2, ("series", "effective sample size", "/metrics/ess"))
    stream = rr.RecordingStream("seal_run", recording_id=f"{m.name}-seal-run",
                                batcher_config=batching(), send_properties=False)
    rooms = [*m.room_names, "_outside"]
    with atomic_output(path) as tmp, writing(tmp, stream):  # rerun's failure said of ``path``, the file asked for,
        # once writing has looked at the disk that holds the temporary (still there: a full disk is said as one)
        save(stream, tmp)  # without rerun's footer, as seal localize's
        stream.set_log_time_enabled(False)
        stream.set_log_tick_enabled(False)
        stream.send_blueprint(blueprint(m, frames, panels))
        classes.log(stream)
        log_map(stream, m, [(i.id, i.at) for i in agent.world.items.values() if not i.movable])
        stream.set_time("step", sequence=0)
        trail: list[tuple[float, float]] = []
        pose: tuple[float, float, float] | None = None
        seen = 0
        for record in agent.records:
            stream.set_time("step", sequence=record.step)
            x, y, yaw = record.pose
            if record.pose != pose:
                pose = record.pose
                stream.log("robot/pose", rr.Points2D([[x, y]], radii=0.12, colors=[ROBOT], draw_order=DRAW["robot"]),
                           rr.Arrows2D(origins=[[x, y]], vectors=[[0.5 * np.cos(yaw), 0.5 * np.sin(yaw)]],
                                       colors=[ROBOT], draw_order=DRAW["robot"]))
            far = not trail or np.hypot(x - trail[-1][0], y - trail[-1][1]) >= TRAIL_STEP
            if far or (record is agent.records[-1] and trail[-1] != (x, y)):  # and where it ended
                trail.append((x, y))
                if len(trail) > 1:
                    stream.log("robot/path", rr.LineStrips2D([trail], colors=[ROBOT], draw_order=DRAW["robot"]))
            stream.log("robot/log", rr.TextLog(f"{record.kind}: {record.text}"))
            things = [agent.world.items[item] for item in record.data.get("seen", [])]
            if things or seen:
                seen = len(things)
                log_detections(stream, [(thing.key, thing.at) for thing in things], classes, SEEN)
        shown: dict[str, dict[int, float]] = {}  # what each cloud's masses were when it was last logged

        def changed(key: str, X: np.ndarray, W: np.ndarray, last: bool) -> bool:
            masses = cell_masses(X, W, m.bounds)
            if last or key not in shown or total_variation(masses, shown[key]) > CHANGE:
                shown[key] = masses
                return True
            return False

        masses: dict[str, list[tuple[int, list[float]]]] = {}  # frame: (step, its room masses) while at hand
        sizes: list[tuple[int, list[float]]] = []  # (step, every object's ESS)
        for k, cloud in enumerate(clouds):
            stream.set_time("step", sequence=cloud["step"])
            last = k == len(clouds) - 1
            beliefs = []  # the frame at hand, and the commanded frame it serves
            if cloud["frame_particles"] is not None and cloud["frame"]:
                X, W = cloud["frame_particles"]
                masses.setdefault(cloud["frame"], []).append((cloud["step"], list(room_masses(m, X, W).values())))
                beliefs.append((cloud["frame"], X, W))
            if cloud.get("commanded_particles") is not None and cloud["commanded"] not in ("", cloud["frame"]):
                beliefs.append((cloud["commanded"], *cloud["commanded_particles"]))
            if any([changed(f"frames/{fid}", X, W, last) for fid, X, W in beliefs]):
                log_clouds(stream, "frames/particles", [X for _, X, _ in beliefs], [radii(W) for _, _, W in beliefs],
                           [classes.ids[fid] for fid, _, _ in beliefs], DRAW["frames"])
            if cloud["objects"]:
                sizes.append((cloud["step"], [float(ess(cloud["objects"][c][1])) if c in cloud["objects"] else 0.0
                                              for c in objects]))
                if any([changed(f"objects/{c}", X, W, last) for c, (X, W) in cloud["objects"].items()]):
                    log_clouds(stream, "objects/particles", [X for X, _ in cloud["objects"].values()],
                               [radii(W) for _, W in cloud["objects"].values()],
                               [classes.ids[c] for c in cloud["objects"]], DRAW["objects"])

        def series(entity: str, found: list[tuple[int, list[float]]], names: list[str],
                   colours: list[tuple[int, int, int]]) -> None:
            if found:
                send_series(stream, entity, [rr.TimeColumn("step", sequence=[step for step, _ in found])],
                            np.array([values for _, values in found], float), names, colours)

        series("metrics/path_m", [(r.step, [r.path_m]) for r in agent.records], ["path (m)"], [ROBOT])
        for fid, found in masses.items():
            series(f"metrics/rooms/{fid}", found, [f"{fid}: {room}" for room in rooms],
                   [series_colour(i) for i in range(len(rooms))])
        series("metrics/ess", sizes, objects, [classes.colour(c) for c in objects])
        flush(stream, tmp)
        stream.disconnect()


@text_as_written
def write_png(path: str | Path, agent: Agent, title: str = "") -> None:
    """The map, the robot's path and where it acted; when the policy kept belief clouds, two panels:
    the belief of a step after its last look (the last step that served another frame, such as
    Pick(spoon) for Stir(cup), else the last step), and beside it the belief of the commanded frame
    that step serves (the whole task's)."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    from seal_cli.maps.drawing import cut_title, declutter, draw_map, legend_below, shown_extent

    m = agent.scene.map
    xmin, ymin, xmax, ymax = shown_extent(m)
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
            legend_below(ax, columns=4 if panels == 1 else 3)  # under the map: no cloud covers it
        axes[0][0].set_title(cut_title(title or m.name))
        if panels == 2:
            axes[0][1].set_title("the commanded frame's belief")
        fig.tight_layout()
        declutter(fig)
        with atomic_output(path) as tmp:
            fig.savefig(tmp, dpi=120, format="png", bbox_inches="tight")
    finally:
        plt.close(fig)


LABEL_CHARS = 48
"""An action's label on the picture is cut to this many characters (the narration has it whole)."""


def _short(text: str) -> str:
    return text if len(text) <= LABEL_CHARS else text[:LABEL_CHARS - 1] + "…"


def _acts(records: Sequence[Record]) -> list[tuple[tuple[float, float, float], str]]:
    """What the robot did, to label where it did it: each action and answer, and where a frame that only
    drives (Go) ended, with the drive's line ("goes to the bedroom (by desk_1)", its distance left off). A place
    opened to look in and closed again where it stood is one label ("looked into fridge_1; inside: milk_1"); one
    closed again after something was taken out of it there says so on that label ("picked up jam_1 from larder_1,
    closed larder_1")."""
    out: list[tuple[tuple[float, float, float], str]] = []
    drive: Record | None = None
    acted = False
    for record in records:
        if record.kind == "frame":
            drive, acted = None, False
        elif record.kind in ("act", "answer"):     # what it did, and what it found out there
            said = record.text.split(": ", 1)[-1]      # "answer: 1 cup ..." and "counted: 1 cup ...": once
            shut = record.text.removeprefix("closed ")
            if out and shut != record.text and out[-1][0] == record.pose and \
                    re.match(rf"opened {re.escape(shut)}(;|$)", out[-1][1]):   # opened, looked in, closed: one label
                out[-1] = (record.pose, "looked into " + out[-1][1].removeprefix("opened "))
            elif out and shut != record.text and out[-1][0] == record.pose and any(
                    re.match(rf"opened {re.escape(shut)}(;|$)", text) for pose, text in out if pose == record.pose):
                out[-1] = (record.pose, f"{out[-1][1]}, closed {shut}")   # took out of it, closed it: no new card
            elif not (out and out[-1][1].split(": ", 1)[-1] == said and ": " in record.text):
                out.append((record.pose, record.text))
            acted = True
        elif record.kind == "go":
            drive = record
        elif record.kind == "done" and drive is not None and not acted:
            out.append((record.pose, re.sub(r" \([\d.]+ m\)$", "", drive.text)))
    return out


LEG_COLOURS = ("#1f77b4", "#17becf", "#8c564b", "#e377c2", "#7f7f7f", "#bcbd22", "#9467bd", "#2ca02c")
"""The colours of a multi-step run's legs, step by step (blue first, as a one-step run's path; none is the orange
of the belief clouds or the red of the moved things)."""

ONE_CARD_M = 0.5
"""Actions done within this distance of each other are said on one card (e2e24: "picked up watering_can_1" 0.15 m
from "handed watering_can_1 to Walter" drew two cards over each other at the end)."""


def _legs(trail: np.ndarray, records: Sequence[Record],
          said: Callable[[Record], str] = lambda r: r.text) -> list[tuple[str, np.ndarray]]:
    """The path cut into the legs of the frames the robot executed, in order (each frame's line as ``said`` says it,
    and the points driven from its start to the next frame's start, by the distance driven when each began); one leg
    or none when the run had fewer than two frames that drove. A frame that drove nothing has no leg."""
    starts = [(r.path_m, said(r)) for r in records if r.kind == "frame"]
    if len(trail) < 2 or not starts:
        return []
    along = np.concatenate([[0.0], np.cumsum(np.hypot(*np.diff(trail, axis=0).T))])
    legs: list[tuple[str, np.ndarray]] = []
    for k, (begun, text) in enumerate(starts):
        end = starts[k + 1][0] if k + 1 < len(starts) else np.inf
        if end - begun <= 1e-6:
            continue
        first = max(int(np.searchsorted(along, begun + 1e-6)) - 1, 0)    # the last point at or before its start
        last = min(int(np.searchsorted(along, end - 1e-6)), len(trail) - 1)   # the first at or after its end
        if last > first:
            legs.append((text, trail[first:last + 1]))
    return legs


def _draw_run(ax: Any, agent: Agent) -> None:
    """The path, where the robot acted, and where the things are."""
    from seal_cli.maps.drawing import _HALO, LABEL, LABEL_Z

    trail = np.asarray(agent.world.robot.trajectory)
    legs = _legs(trail, agent.records, agent.said_at_end)   # each step naming what the robot handled in it
    if len(legs) < 2:
        ax.plot(trail[:, 0], trail[:, 1], "-", color="#1f77b4", linewidth=2, zorder=4, label="path")
    for k, (frame, points) in enumerate(legs if len(legs) > 1 else []):   # each step's leg in its own colour
        ax.plot(points[:, 0], points[:, 1], "-", color=LEG_COLOURS[k % len(LEG_COLOURS)], linewidth=2, zorder=4,
                label=_short(f"step {k + 1}: {frame}"))
    looks = np.asarray([r.pose[:2] for r in agent.records if r.kind == "go" and r.text.startswith("goes to look")])
    if len(looks):       # each "goes to look" of the narration, where it ended: the views the search chose
        ax.plot(looks[:, 0], looks[:, 1], "o", markersize=7, markerfacecolor="white", markeredgecolor="#1f77b4",
                markeredgewidth=1.5, zorder=5, label="where it stopped to look")
    ends = {"markeredgecolor": "white", "markeredgewidth": 1.2, "zorder": LABEL_Z + 1}   # over labels and acts
    ax.plot(*trail[0], "o", color="#1f77b4", markersize=9, label="start", **ends)
    stood: dict[tuple[float, float], list[str]] = {}      # where the robot stood for each action, numbered
    for n, (pose, text) in enumerate(_acts(agent.records), 1):
        near = next((at for at in stood if math.dist(at, pose[:2]) <= ONE_CARD_M), None)   # one card a spot
        stood.setdefault(near or (round(pose[0], 2), round(pose[1], 2)), []).append(f"{n}. {text}")
    xmin, _, xmax, _ = agent.scene.map.bounds
    for k, (at, texts) in enumerate(stood.items()):
        ax.plot(at[0], at[1], "D", color="#2ca02c", markeredgecolor="black", markersize=7, zorder=7,
                **({"label": "where it acted (numbered)"} if k == 0 else {}))
        left = at[0] > (xmin + xmax) / 2           # labels point into the map, on a white card over it
        ax.annotate("\n".join(_short(t) for t in texts), at, xytext=(-11 if left else 11, 6),
                    textcoords="offset points", fontsize=7, color="#1a6e1a", zorder=LABEL_Z, gid=LABEL,
                    ha="right" if left else "left", va="bottom",
                    bbox={"boxstyle": "round,pad=0.25", "fc": "white", "ec": "#2ca02c", "alpha": 0.9, "lw": 0.6},
                    arrowprops={"arrowstyle": "-", "color": "#2ca02c", "lw": 0.6})
    ax.plot(*trail[-1], "s", markersize=13, markerfacecolor="none", markeredgecolor="#1f77b4", markeredgewidth=2,
            zorder=LABEL_Z + 1, label="end")            # hollow: the last action's diamond shows inside it
    legend: set[str] = set()

    def once(what: str) -> dict[str, str]:          # each kind of mark named once in the legend
        first = what not in legend
        legend.add(what)
        return {"label": what} if first else {}

    for item in agent.world.items.values():
        if item.key == "person" and not item.movable:     # the people, and the speaker ("me"), where they are now
            start = agent.started.get(item.id)
            if start is not None and math.dist(start, item.at) > 0.05:    # led somewhere: from where they stood
                ax.plot(*start, "^", markersize=7, markerfacecolor="none", markeredgecolor="#9467bd", zorder=5,
                        **once("a person led, where they stood at the start"))
                ax.plot([start[0], item.at[0]], [start[1], item.at[1]], ":", color="#9467bd", linewidth=1, zorder=3)
            ax.plot(*item.at, "^", markersize=7, color="#9467bd", zorder=LABEL_Z + 2, **once("people"))
            ax.annotate(cut(agent.named(item.id)), item.at, xytext=(4, -8), textcoords="offset points", fontsize=6,
                        color="#9467bd", zorder=LABEL_Z, gid=LABEL, bbox=_HALO)
        elif item.movable:
            end = agent.world.position(item.id)
            start = agent.started.get(item.id)
            if start is not None and math.dist(start, end) > 0.05:     # moved: from where it was, dotted
                ax.plot(*start, "*", markersize=7, markerfacecolor="none", markeredgecolor="#d62728", zorder=3,
                        **once("a moved thing, where it was at the start"))
                ax.plot([start[0], end[0]], [start[1], end[1]], ":", color="#d62728", linewidth=1, zorder=3)
            ax.plot(*end, "*", markersize=7, color="#d62728", markeredgecolor="black", markeredgewidth=0.4,
                    zorder=LABEL_Z + 2, **once("things, where they are at the end"))
