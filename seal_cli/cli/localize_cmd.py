"""``seal localize``: SeFM's belief over where each frame of the plan can be executed, and where each object is."""

from __future__ import annotations

import math
from collections.abc import Callable
from pathlib import Path
from typing import TYPE_CHECKING, Any

import typer

from seal_cli.cli import (
    DETECTIONS_TOPIC_HELP,
    MAX_PARTICLES,
    MAX_STEPS,
    POSE_TOPIC_HELP,
    FramelibOption,
    JsonOption,
    command,
    emit_json,
    err,
    framelib_paths,
    one_held,
    out,
    progress_bar,
)
from seal_cli.cli.framework import given as option_given

if TYPE_CHECKING:
    from seal_cli.sensing.observations import Observation


def show(result: dict[str, Any]) -> None:
    """The frames and objects as two tables: top rooms, modes, best point."""
    from rich.table import Table

    from seal_cli.cli.output import plain
    from seal_cli.sefm.shown import modes_text, point, rooms_text

    frames = Table(title=f"frames on {plain(result['map'])} after {result['updates']} updates "
                         f"({result['particles']} particles, seed {result['seed']})", title_justify="left")
    for column in ("frame", "rooms", "modes (weight room)", "best", "ess"):
        frames.add_column(column, overflow="fold")
    for f in result["frames"]:
        name = f"{f['frame']}({', '.join(f'{r}={v}' for r, v in f['elements'].items())})"
        frames.add_row(plain(name), plain(rooms_text(f["rooms"])) or "—", plain(modes_text(f["modes"])) or "—",
                       point(f["best"]), f"{f['ess']:.0f}")
    if result["frames"]:
        out.print(frames)
    objects = Table(title="objects", title_justify="left")
    for column in ("class", "rooms", "modes (weight room)", "best"):
        objects.add_column(column, overflow="fold")
    for o in result["objects"]:
        objects.add_row(plain(o["class"]), plain(rooms_text(o["rooms"])) or "—", plain(modes_text(o["modes"])) or "—",
                        point(o["best"]))
    if result["objects"]:
        out.print(objects)


def _read_bag(bag: Path, pose_topic: str | None, detections_topic: str | None, frame: str, base_frame: str,
              labels: Path | None) -> tuple[list[Observation], tuple[float, ...]]:
    from seal_cli.cli import err
    from seal_cli.ros.bags import TOLERANCE, read_run
    from seal_cli.ros.labels import read_labels

    names = read_labels(labels) if labels is not None else None
    run = read_run(bag, pose_topic=pose_topic, detections_topic=detections_topic, frame=frame, base_frame=base_frame,
                   labels=names)
    err.print(f"{bag}: {len(run.observations)} detection messages on {run.detections_topic}, poses from "
              f"{run.pose_source}", markup=False)
    if run.skipped:
        err.print(f"warning: {run.skipped} messages on {run.detections_topic} lie more than {TOLERANCE:g} s outside "
                  f"the poses' time span and were skipped", markup=False)
    for note in run.notes:
        err.print(f"warning: {note}", markup=False)
    return list(run.observations), run.stamps


def turned_origin(name: str, yaw: float) -> str:
    """What a map whose origin turns its image means for a robot's bag (robot5): seal turns the image, as RViz
    draws it, but amcl and Nav2's costmaps ignore an origin's yaw, so a robot localised by them has its poses in
    the frame of the image unturned, and the bag's poses and detections would miss the map's rooms by the turn."""
    return (f"the {name}'s origin turns its image by {yaw:g} rad ({math.degrees(yaw):.1f}°): seal turns it, as RViz "
            f"draws it, but amcl and Nav2's costmaps ignore an origin's yaw, so poses from them are in the frame of "
            f"the image unturned; if the robot was localised on this map by amcl or Nav2, set the yaw to 0 "
            f"(docs/maps.md)")


def _known_only(runs: list[Observation], known: frozenset[str], map_name: str) -> list[Observation]:
    """The runs without detections of classes neither the map nor the plan knows, said in a warning: a detector
    reports every class it knows (a chair, a person), and the whole run was refused for one of them."""
    from seal_cli.cli import err
    from seal_cli.frames.taxonomy import class_key
    from seal_cli.sensing.observations import split_known
    from seal_cli.yamlnodes import suggest

    kept, dropped = split_known(runs, known)
    if dropped:
        listed = ", ".join(f"{cls} ({n}{suggest(class_key(cls), known).replace(' (', ', ').rstrip(')')})"
                           for cls, n in list(dropped.items())[:10])
        more = f" and {len(dropped) - 10} more classes" if len(dropped) > 10 else ""
        n = sum(dropped.values())
        counted = f"{n} detections of classes" if n > 1 else "1 detection of a class"
        err.print(f"warning: {counted} neither map {map_name} nor the plan knows {'were' if n > 1 else 'was'} set "
                  f"aside: {listed}{more}; seal keeps beliefs of {', '.join(sorted(known)) or 'none'} "
                  f"(--labels renames a detector's classes)", markup=False)
    return kept


class Counter:
    """Observer that reports each update to a progress bar's ``advance(done, total)``."""

    def __init__(self, advance: Callable[[int, int], None], total: int) -> None:
        self.advance, self.total = advance, total

    def start(self, sefm: Any) -> None:
        self.advance(0, self.total)

    def update(self, sefm: Any, step: Any) -> None:
        self.advance(step.index, self.total)

    def finish(self, sefm: Any) -> None:
        self.advance(self.total, self.total)


@command("localize")
def localize(
    map_name: str = typer.Option(..., "--map", help="The annotated map (a path or a shipped map's name)."),
    tasks: list[str] | None = typer.Option(None, "--task", help="A command (repeatable): it is parsed, planned, "
                                           "and every frame of its plan is localised.", show_default=False),
    holding: list[str] | None = typer.Option(None, "--holding", help="The class of what the robot holds (overrides the "
                                             "map's robot).", show_default=False),
    done: list[str] | None = typer.Option(None, "--done", help="A command already carried out (repeatable, in "
                                          "order): its frames' postconditions hold.", show_default=False),
    trajectory: Path | None = typer.Option(None, "--trajectory", help="YAML poses: \\[\\[x, y], \\[x, y, "
                                           "yaw], ...]; one update per pose, detections simulated from the "
                                           "map's objects.",
                                           show_default=False),
    observations: Path | None = typer.Option(None, "--observations", help="YAML list of {pose, detections: "
                                             "[{class, at}]}: real detections, one update each.",
                                             show_default=False),
    bag: Path | None = typer.Option(None, "--bag", help="A ROS bag (ROS 1 .bag, ROS 2 folder, .db3 or .mcap): one "
                                    "update per vision_msgs detection message, at the robot's pose then.",
                                    show_default=False),
    pose_topic: str | None = typer.Option(None, "--pose-topic", help=f"With --bag: {POSE_TOPIC_HELP}",
                                          show_default=False),
    detections_topic: str | None = typer.Option(None, "--detections-topic", help=f"With --bag: {DETECTIONS_TOPIC_HELP}",
                                                show_default=False),
    frame: str = typer.Option("map", "--frame", help="With --bag: the map's TF frame (poses and detections are "
                              "carried into it); also the frame of --goals."),
    base_frame: str = typer.Option("base_link", "--base-frame", help="With --bag: the robot's TF frame."),
    labels: Path | None = typer.Option(None, "--labels", help="With --bag: YAML {id: class} or \\[class, ...] naming "
                                       "numeric class ids (ROS 1 vision_msgs, COCO ids).", show_default=False),
    goals: Path | None = typer.Option(None, "--goals", help="Write per frame the pose to act from: YAML (.yaml) or "
                                      "geometry_msgs/PoseStamped on /goal_pose in a bag (.bag, .mcap, a folder).",
                                      show_default=False),
    steps: int = typer.Option(20, "--steps", min=0, max=MAX_STEPS, help="Updates at the final pose (the paper "
                              "uses 20)."),
    particles: int = typer.Option(200, "--particles", min=1, max=MAX_PARTICLES, help="Particles per object and "
                                  "per frame."),
    seed: int = typer.Option(0, "--seed", min=0, help="Seed of the one random generator."),
    rrd: Path | None = typer.Option(None, "--rrd", help="Write a Rerun recording of the run here.",
                                    show_default=False),
    png: Path | None = typer.Option(None, "--png", help="Write a picture of the map and the beliefs here.",
                                    show_default=False),
    framelib: list[Path] | None = FramelibOption,
    as_json: bool = JsonOption,
) -> None:
    """Run SeFM: where each frame of the tasks' plans can be executed, and where each object is."""
    import numpy as np

    from seal_cli.cli import OUTPUT_SUFFIXES
    from seal_cli.errors import SealError
    from seal_cli.fileio import Outputs
    from seal_cli.frames.reading import load_library
    from seal_cli.machine import available_memory
    from seal_cli.maps.formats.map_server import load_map
    from seal_cli.pipeline import frames_to_localise
    from seal_cli.planning.problem import naming_done
    from seal_cli.resources import map_path
    from seal_cli.sefm.filter import SeFM, SeFMConfig
    from seal_cli.sensing.observations import check_inside, read_observations, read_trajectory

    given = [name for name, v in (("--trajectory", trajectory), ("--observations", observations), ("--bag", bag))
             if v is not None]
    if len(given) > 1:
        raise SealError(f"give one of --trajectory (simulated detections), --observations or --bag (real ones), "
                        f"not both {' and '.join(given)}")
    bag_options = {"pose_topic": "--pose-topic", "detections_topic": "--detections-topic", "frame": "--frame",
                   "base_frame": "--base-frame", "labels": "--labels"}
    without_bag = [option for name, option in bag_options.items() if option_given(name)] if bag is None else []
    if without_bag:  # --frame and --base-frame were passed over without a bag (hostile20)
        listed = ", ".join(without_bag[:-1]) + " and " + without_bag[-1] if len(without_bag) > 1 else without_bag[0]
        raise SealError(f"{listed} {'read' if len(without_bag) > 1 else 'reads'} a bag: give --bag too")
    if goals is not None:
        from seal_cli.ros.goals import check_goals_path

        check_goals_path(goals, [bag, observations, trajectory, labels, rrd, png, *(framelib or []),
                                 map_name if Path(map_name).exists() else None])
    held = one_held(holding)
    library = load_library(framelib_paths(framelib))
    the_map = load_map(map_path(map_name))
    for warning in the_map.warnings:  # odd but usable (a place in no room): said, not refused
        err.print(f"warning: {warning}", markup=False)
    runs: list[Observation] = []
    stamps: tuple[float, ...] = ()
    if trajectory is not None:
        runs = read_trajectory(trajectory)
    elif observations is not None:
        runs = read_observations(observations)
    elif bag is not None:
        runs, stamps = _read_bag(bag, pose_topic, detections_topic, frame, base_frame, labels)
        if the_map.grid.yaw:
            err.print(f"warning: {turned_origin(the_map.said, the_map.grid.yaw)}", markup=False)
    for said in check_inside(runs, the_map.bounds, the_map.name, the_map.is_occupied, the_map.is_free,
                             the_map.grid.resolution):
        err.print(f"warning: {said}", markup=False)
    with naming_done(tasks or [], "", "--task"):  # a refusal located in a task names it
        bindings, state = frames_to_localise(tasks or [], library, the_map, holding=held, done=done or [])
    if goals is not None and not bindings:
        raise SealError("--goals writes a pose per frame, and there are none: give --task")
    rng = np.random.default_rng(seed)
    goal_file = goals if goals is not None and goals.suffix else None  # a ROS 2 bag's folder: by its writer
    with Outputs({"--rrd": rrd, "--png": png, "--goals": goal_file},
                 [map_name, trajectory, observations, bag, labels, *(framelib or [])],
                 suffixes=OUTPUT_SUFFIXES) as files, progress_bar("updates", len(runs) + steps) as advance:
        observers: list[Any] = [Counter(advance, len(runs) + steps)]
        if rrd is not None:
            from seal_cli.sefm.observers.rerun import RerunRecorder

            observers.append(RerunRecorder(files["--rrd"], stamps=stamps))
        if png is not None:
            from seal_cli.sefm.observers.png import PngDrawer

            observers.append(PngDrawer(files["--png"]))
        classes = () if bindings else the_map.classes
        config = SeFMConfig(particles=particles, memory=available_memory())   # refused past it (rel33)
        sefm = SeFM(the_map, bindings, state, rng, config, observers, classes=classes)
        runs = _known_only(runs, sefm.known_classes, the_map.name)
        sefm.follow(runs, steps)
        sefm.close()
        result = {"map": the_map.name, "seed": seed, "steps": steps, "particles": particles,
                  "updates": sefm.step, **sefm.to_json()}
        if goals is not None:
            from seal_cli.ros.goals import goals_for, write_goals

            last = runs[-1].pose if runs else the_map.robot.pose
            write_goals(files.get("--goals") or goals, goals_for(the_map, sefm.frame_ids, result["frames"], last),
                        frame, stamps[-1] if stamps else 0.0)
    if as_json:
        emit_json(result)
    else:
        show(result)
