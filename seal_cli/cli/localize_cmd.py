"""``seal localize``: SeFM's belief over where each frame of the plan can be executed, and where each object is."""

from __future__ import annotations

import contextlib
from pathlib import Path
from typing import TYPE_CHECKING, Any

import typer

from seal_cli.cli import FramelibOption, JsonOption, command, emit_json, framelib_paths, out

if TYPE_CHECKING:
    from seal_cli.sensing.observations import Observation


def _rooms(rooms: dict[str, float], top: int = 3) -> str:
    best = sorted(rooms.items(), key=lambda kv: -kv[1])[:top]
    return ", ".join(f"{name} {mass:.2f}" for name, mass in best if mass >= 0.005) or "—"


def _point(p: list[float]) -> str:
    return f"({p[0]:.2f}, {p[1]:.2f})"


def show(result: dict[str, Any]) -> None:
    """The frames and objects as two tables: top rooms, modes, best point."""
    from rich.table import Table

    frames = Table(title=f"frames on {result['map']} after {result['updates']} updates "
                         f"({result['particles']} particles, seed {result['seed']})", title_justify="left")
    for column in ("frame", "rooms", "modes (weight room)", "best", "ess"):
        frames.add_column(column, overflow="fold")
    for f in result["frames"]:
        name = f"{f['frame']}({', '.join(f'{r}={v}' for r, v in f['elements'].items())})"
        modes = ", ".join(f"{m['weight']:.2f} {m['room']}" for m in f["modes"][:3]) or "—"
        frames.add_row(name, _rooms(f["rooms"]), modes, _point(f["best"]), f"{f['ess']:.0f}")
    if result["frames"]:
        out.print(frames)
    objects = Table(title="objects", title_justify="left")
    for column in ("class", "rooms", "modes (weight room)", "best"):
        objects.add_column(column, overflow="fold")
    for o in result["objects"]:
        modes = ", ".join(f"{m['weight']:.2f} {m['room']}" for m in o["modes"][:3]) or "—"
        objects.add_row(o["class"], _rooms(o["rooms"]), modes, _point(o["best"]))
    if result["objects"]:
        out.print(objects)


@command("localize")
def localize(
    map_name: str = typer.Option(..., "--map", help="The annotated map (a path or a shipped map's name)."),
    tasks: list[str] | None = typer.Option(None, "--task", help="A command (repeatable): it is parsed, planned, "
                                           "and every frame of its plan is localised.", show_default=False),
    holding: str | None = typer.Option(None, "--holding", help="The class of what the robot holds (overrides the "
                                       "map's robot).", show_default=False),
    done: list[str] | None = typer.Option(None, "--done", help="A command already carried out (repeatable, in "
                                          "order): its frames' postconditions hold.", show_default=False),
    trajectory: Path | None = typer.Option(None, "--trajectory", help="YAML poses: [[x, y], [x, y, yaw], ...]; one "
                                           "update per pose, detections simulated from the map's objects.",
                                           show_default=False),
    observations: Path | None = typer.Option(None, "--observations", help="YAML list of {pose, detections: "
                                             "[{class, at}]}: real detections, one update each.",
                                             show_default=False),
    steps: int = typer.Option(20, "--steps", min=0, help="Updates at the final pose (the paper uses 20)."),
    particles: int = typer.Option(200, "--particles", min=1, help="Particles per object and per frame."),
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

    from seal_cli.errors import SealError
    from seal_cli.fileio import atomic_output
    from seal_cli.frames.reading import load_library
    from seal_cli.maps.formats.map_server import load_map
    from seal_cli.pipeline import frames_to_localise
    from seal_cli.resources import map_path
    from seal_cli.sefm.filter import SeFM, SeFMConfig
    from seal_cli.sensing.observations import check_inside, read_observations, read_trajectory

    if trajectory is not None and observations is not None:
        raise SealError("give --trajectory (simulated detections) or --observations (real ones), not both")
    library = load_library(framelib_paths(framelib))
    the_map = load_map(map_path(map_name))
    runs: list[Observation] = []
    if trajectory is not None:
        runs = read_trajectory(trajectory)
    elif observations is not None:
        runs = read_observations(observations)
    check_inside(runs, the_map.bounds, the_map.name)
    bindings, state = frames_to_localise(tasks or [], library, the_map, holding=holding, done=done or [])
    rng = np.random.default_rng(seed)
    with contextlib.ExitStack() as files:
        observers: list[Any] = []
        if rrd is not None:
            from seal_cli.sefm.observers.rerun import RerunRecorder

            observers.append(RerunRecorder(files.enter_context(atomic_output(rrd))))
        if png is not None:
            from seal_cli.sefm.observers.png import PngDrawer

            observers.append(PngDrawer(files.enter_context(atomic_output(png))))
        classes = () if bindings else the_map.classes
        sefm = SeFM(the_map, bindings, state, rng, SeFMConfig(particles=particles), observers, classes=classes)
        sefm.follow(runs, steps)
        sefm.close()
    result = {"map": the_map.name, "seed": seed, "steps": steps, "particles": particles,
              "updates": sefm.step, **sefm.to_json()}
    if as_json:
        emit_json(result)
    else:
        show(result)
