"""``seal plan``: the ordered, grounded frames that carry out a command from the robot's state."""

from __future__ import annotations

from dataclasses import asdict
from pathlib import Path
from typing import TYPE_CHECKING

import typer

from seal_cli.cli import (
    MAX_COUNT,
    FramelibOption,
    JsonOption,
    bench_app,
    command,
    emit_json,
    err,
    framelib_paths,
    one_held,
    out,
)
from seal_cli.cli.output import plain, styled
from seal_cli.cli.parse_cmd import VocabularyOption, vocabulary_from
from seal_cli.planning.plan import MAX_NODES, Plan

MAX_MAX_NODES = 10_000_000
"""The most search nodes ``--max-nodes`` allows (each holds a state: about 2 GB at this bound)."""

if TYPE_CHECKING:
    from seal_cli.maps.model import Map

MapOption = typer.Option(None, "--map", help="The world: its places (openable ones closed unless open: true), "
                         "where its objects are, the robot's hand; also grounds the words in its classes. "
                         "A path or a shipped map's name.", show_default=False)


def _load_world(map_name: str | None) -> Map | None:
    """The ``--map`` world, or None."""
    if map_name is None:
        return None
    from seal_cli.maps.formats.map_server import load_map
    from seal_cli.resources import map_path

    return load_map(map_path(map_name))


def show(plan: Plan) -> None:
    """The plan as a numbered list: commanded frames in bold, inserted ones with their reason; first the look that
    checks the command's condition, when the run checks one ("if Tom is in the garage")."""
    from rich.table import Table

    from seal_cli.frames.said import said_names, shown_elements, shown_fact

    if plan.check is not None:     # what the run looks at first; the steps below only if the condition holds
        out.print(f"[dim]checks first:[/dim] {plain(plan.check.question)} "
                  f"({plain(', '.join(plan.check.looks))}); then, only if {plain(plan.check.said.split(None, 1)[1])}:")
    table = Table.grid(padding=(0, 2))
    for column in ("number", "frame", "elements", "because"):
        table.add_column(justify="right" if column == "number" else "left")
    for i, step in enumerate(plan.steps, 1):
        elements = plain(", ".join(f"{role}={value}" for role, value in shown_elements(step.binding)))
        frame = styled("bold", step.frame) if step.commanded else plain(step.frame)
        because = styled("dim", f"← {step.because}") if step.because else ""
        table.add_row(f"{i}.", frame, elements, because)
    out.print(table)
    said = said_names(step.binding for step in plan.steps)  # told(x): the message as words, as the steps show it
    out.print(f"[dim]state:[/dim] {plain(', '.join(shown_fact(f, said) for f in plan.initial)) or '—'}")
    out.print(f"[dim]goal:[/dim]  {plain(', '.join(shown_fact(f, said) for f in plan.goal)) or '—'}")


@command("plan")
def plan(
    text: str = typer.Argument(..., help="The command, e.g. \"heat the egg and put it in the fridge\"."),
    holding: list[str] | None = typer.Option(None, "--holding", help="The class of what the robot holds (overrides "
                                             "the map's robot).", show_default=False),
    done: list[str] | None = typer.Option(None, "--done", help="A command already carried out (repeatable, in "
                                          "order): its frames' postconditions hold.", show_default=False),
    map_name: str | None = MapOption,
    vocabulary: Path | None = VocabularyOption,
    pddl: Path | None = typer.Option(None, "--pddl", help="Also write domain.pddl and problem.pddl into this "
                                     "existing folder.", show_default=False),
    max_nodes: int = typer.Option(MAX_NODES, "--max-nodes", min=1, max=MAX_MAX_NODES,
                                  help="Give up after expanding this many "
                                  "search nodes."),
    framelib: list[Path] | None = FramelibOption,
    as_json: bool = JsonOption,
) -> None:
    """Plan a command: the frames it commands, in order, with the frames their preconditions need."""
    from seal_cli.fileio import Outputs
    from seal_cli.frames.reading import load_library
    from seal_cli.pipeline import plan as plan_text
    from seal_cli.planning.pddl import PDDL_FILES

    held = one_held(holding)
    library = load_library(framelib_paths(framelib))
    world = _load_world(map_name)
    for odd in world.warnings if world is not None else ():  # odd but usable (rooms that overlap): said, as run,
        err.print(f"warning: {odd}", markup=False)            # localize and map say it (hostile25)
    outputs = Outputs({"--pddl": pddl}, [vocabulary, *(framelib or [])], folders={"--pddl": PDDL_FILES})
    result = plan_text(text, library, holding=held, done=tuple(done or ()), map=world,
                       vocabulary=vocabulary_from(vocabulary, map_name), max_nodes=max_nodes)
    with outputs:  # both files or neither; a failure above leaves no temporary (they are removed at exit)
        if pddl is not None:
            from seal_cli.planning.pddl import write_pddl

            write_pddl(pddl, library, result, files=outputs)
    for warning in result.warnings:
        err.print(f"[yellow]warning:[/yellow] {plain(warning)}", markup=True)
    if as_json:
        emit_json(result.to_json())
    else:
        show(result)


@command("plan", on=bench_app)
def bench_plan(
    file: Path | None = typer.Option(None, "--file", "-f", help="Time these commands (one per line) instead of "
                                     "the built-in ones.", show_default=False),
    map_name: str | None = MapOption,
    repeat: int = typer.Option(5, "--repeat", min=1, max=MAX_COUNT, help="Runs per command; the median is reported."),
    framelib: list[Path] | None = FramelibOption,
    as_json: bool = JsonOption,
) -> None:
    """Time parse + ground + plan for commands of up to six clauses; report the slowest."""
    from rich.table import Table

    from seal_cli.bench.plan import BENCH_COMMANDS, time_plans
    from seal_cli.frames.reading import load_library

    library = load_library(framelib_paths(framelib))
    world = _load_world(map_name)
    if file is not None:
        from seal_cli.fileio import read_text, split_lines

        numbered = [(k, line) for k, line in enumerate(split_lines(read_text(file)), 1) if line.strip()]
        texts = [line.strip() for _, line in numbered]
        source: tuple[str, list[tuple[int, str]]] | None = (str(file), numbered)
        if not texts:
            from seal_cli.errors import SealError, Where

            raise SealError("no commands to time: the file has no non-blank line", Where(str(file)))
    else:
        texts, source = list(BENCH_COMMANDS), None
    rows = time_plans(texts, library, map=world, vocabulary=vocabulary_from(None, map_name), repeat=repeat,
                      source=source)
    slowest = max(rows, key=lambda r: r.ms)
    if as_json:
        emit_json({"map": world.name if world else None, "repeat": repeat,
                   "commands": [asdict(r) for r in rows], "slowest": asdict(slowest)})
        return
    table = Table(title=f"parse + ground + plan, median of {repeat}" + (f", map {plain(world.name)}" if world else ""),
                  title_justify="left")
    for column in ("ms", "plan ms", "nodes", "steps", "commanded", "command"):
        table.add_column(column, justify="left" if column == "command" else "right", overflow="fold")
    for row in rows:
        table.add_row(f"{row.ms:.2f}", f"{row.plan_ms:.2f}", str(row.nodes), str(row.steps), str(row.commanded),
                      plain(row.text))
    out.print(table)
    out.print(f"slowest: {slowest.ms:.2f} ms — {slowest.text}", markup=False)
