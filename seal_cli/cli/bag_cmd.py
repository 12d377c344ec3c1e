"""``seal import-bag``: a ROS bag's poses and detections as an observations file for ``seal localize``."""

from __future__ import annotations

from pathlib import Path

import typer

from seal_cli.cli import command, err


@command("import-bag")
def import_bag(
    bag: Path = typer.Argument(..., help="A ROS bag: ROS 1 .bag, ROS 2 folder, .db3 or .mcap.", show_default=False),
    output: Path = typer.Option(..., "-o", "--output", help="The observations YAML to write.", show_default=False),
    pose_topic: str | None = typer.Option(None, "--pose-topic", help="The robot's pose (PoseStamped, "
                                          "PoseWithCovarianceStamped, Odometry, or /tf); default: /tf if it links "
                                          "--frame to base_link, else the bag's only pose topic.",
                                          show_default=False),
    detections_topic: str | None = typer.Option(None, "--detections-topic", help="The vision_msgs "
                                                "Detection2DArray/3DArray topic; default: the bag's only one.",
                                                show_default=False),
    frame: str = typer.Option("map", "--frame", help="The map's TF frame: poses and detections are carried into it."),
    base_frame: str = typer.Option("base_link", "--base-frame", help="The robot's TF frame."),
    labels: Path | None = typer.Option(None, "--labels", help="YAML {id: class} or [class, ...] naming numeric "
                                       "class ids (ROS 1 vision_msgs, COCO ids).", show_default=False),
) -> None:
    """Read a bag's robot poses and detections into observations YAML (one entry per detection message)."""
    from seal_cli.errors import SealError, Where
    from seal_cli.fileio import atomic_write_text
    from seal_cli.ros.bags import read_run
    from seal_cli.ros.importing import observations_text

    if output.resolve() == bag.resolve():
        raise SealError(f"-o {output} is the bag itself: give another file", Where(str(output)))
    from seal_cli.ros.labels import read_labels

    names = read_labels(labels) if labels is not None else None
    run = read_run(bag, pose_topic=pose_topic, detections_topic=detections_topic, frame=frame, base_frame=base_frame,
                   labels=names)
    atomic_write_text(output, observations_text(run, str(bag), frame))
    skipped = f" ({run.skipped} outside the poses' time span skipped)" if run.skipped else ""
    err.print(f"wrote {output}: {len(run.observations)} observations from {run.detections_topic}{skipped}, poses "
              f"from {run.pose_source}", markup=False)
