"""ROS commands: ``seal import-bag`` (a bag's poses and detections as an observations file for
``seal localize``) and ``seal bench ros`` (a bag read and filtered: updates per second)."""

from __future__ import annotations

import os
from pathlib import Path

import typer
from rich.table import Table

from seal_cli.cli import (
    DETECTIONS_TOPIC_HELP,
    POSE_TOPIC_HELP,
    JsonOption,
    bench_app,
    choices,
    command,
    emit_json,
    err,
    out,
)

MAX_POSES = 100_000
"""The most poses of ``bench ros``'s bag: 2.8 hours of driving at 10 Hz, a 15 MB MCAP, about 6 s to write and read
per format. A million took minutes per format before a single update was timed (hostile19)."""
MAX_MESSAGES = 5_000
"""The most detection messages of ``bench ros``'s bag (each one timed update, then again with the Rerun recorder):
about 25 ms each here, so about 2 minutes per format, 6 for all three; 2,000 took 52 s, and the bound before,
100,000, would have taken 40 minutes per format (hostile19)."""


@command("import-bag")
def import_bag(
    bag: Path = typer.Argument(..., help="A ROS bag: ROS 1 .bag, ROS 2 folder, .db3 or .mcap.", show_default=False),
    output: Path = typer.Option(..., "-o", "--output", help="The observations YAML to write.", show_default=False),
    pose_topic: str | None = typer.Option(None, "--pose-topic", help=f"From the bag: {POSE_TOPIC_HELP}",
                                          show_default=False),
    detections_topic: str | None = typer.Option(None, "--detections-topic",
                                                help=f"From the bag: {DETECTIONS_TOPIC_HELP}", show_default=False),
    frame: str = typer.Option("map", "--frame", help="The map's TF frame: poses and detections are carried into it."),
    base_frame: str = typer.Option("base_link", "--base-frame", help="The robot's TF frame."),
    labels: Path | None = typer.Option(None, "--labels", help="YAML {id: class} or \\[class, ...] naming numeric "
                                       "class ids (ROS 1 vision_msgs, COCO ids).", show_default=False),
) -> None:
    """Read a bag's robot poses and detections into observations YAML (one entry per detection message)."""
    from seal_cli.errors import SealError, Where
    from seal_cli.ros.bags import read_run
    from seal_cli.ros.importing import observations_text

    if os.path.realpath(output) == os.path.realpath(bag):  # Path.resolve raises on a link loop
        raise SealError(f"-o {output} is the bag itself: give another file", Where(str(output)))
    from seal_cli.cli import OUTPUT_SUFFIXES
    from seal_cli.fileio import Outputs
    from seal_cli.ros.labels import read_labels

    names = read_labels(labels) if labels is not None else None
    outputs = Outputs({"--output": output}, [bag, labels], suffixes=OUTPUT_SUFFIXES)
    run = read_run(bag, pose_topic=pose_topic, detections_topic=detections_topic, frame=frame, base_frame=base_frame,
                   labels=names)
    with outputs:
        outputs["--output"].write_text(observations_text(run, str(bag), frame), encoding="utf-8")
    skipped = f" ({run.skipped} outside the poses' time span skipped)" if run.skipped else ""
    err.print(f"wrote {output}: {len(run.observations)} observations from {run.detections_topic}{skipped}, poses "
              f"from {run.pose_source}", markup=False)
    for note in run.notes:
        err.print(f"warning: {note}", markup=False)


@command("ros", on=bench_app)
def bench_ros(
    formats: list[str] | None = typer.Option(None, "--format", help="mcap, sqlite3 or ros1 (repeatable; default "
                                             "mcap).", show_default=False),
    poses: int = typer.Option(1000, "--poses", min=2, max=MAX_POSES, help="Robot poses in the bag (10 Hz)."),
    messages: int = typer.Option(200, "--messages", min=1, max=MAX_MESSAGES,
                                 help="Detection messages in the bag: one update each."),
    seed: int = typer.Option(0, "--seed", min=0, help="Seed of the random generators."),
    as_json: bool = JsonOption,
) -> None:
    """Read a robot's bag (poses on /tf, vision_msgs detections) and filter it at the paper's scale: updates/s."""
    from seal_cli.bench.ros import FORMATS, measure
    from seal_cli.frames.reading import load_library
    from seal_cli.maps.formats.map_server import load_map
    from seal_cli.resources import map_path

    wanted = choices("--format", formats or ["mcap"], tuple(FORMATS), "format")
    err.print("[dim]seal bench ros: writes the bag (untimed), then times reading it and one belief update per "
              "detection message (this process's CPU seconds)[/dim]")
    library, m = load_library(), load_map(map_path("apartment"))
    results = [measure(m, library, fmt, poses, messages, seed) for fmt in wanted]
    if as_json:
        emit_json({"runs": results})
        return
    table = Table(title="a bag read and filtered (paper scale: 3 frames, 2 objects, 200 particles)",
                  title_justify="left")
    for column in ("format", "poses", "messages", "bag kB", "read s", "filter s", "updates/s", "with --rrd /s",
                   "rrd kB"):
        table.add_column(column, justify="left" if column == "format" else "right")
    for r in results:
        recorded = r["recorded_updates_per_s"] is not None
        table.add_row(r["format"], str(r["poses"]), str(r["messages"]), f"{r['bag_bytes'] / 1000:.0f}",
                      f"{r['read_s']:.2f}", f"{r['filter_s']:.2f}", f"{r['updates_per_s']:.1f}",
                      f"{r['recorded_updates_per_s']:.1f}" if recorded else "-",
                      f"{r['rrd_bytes'] / 1000:.0f}" if recorded else "-")
    out.print(table)
