"""``seal plan``: the ordered, grounded frames that carry out a command from the robot's state."""

from __future__ import annotations

from pathlib import Path

import typer
from rich.table import Table

from ..planning import MAX_NODES, Plan
from . import FramelibOption, JsonOption, command, emit_json, framelib_paths, out
from .parse_cmd import MapOption, VocabularyOption, vocabulary_from


def show(plan: Plan) -> None:
    """The plan as a numbered list: commanded frames in bold, inserted ones with their reason."""
    table = Table.grid(padding=(0, 2))
    for column in ("number", "frame", "elements", "because"):
        table.add_column(justify="right" if column == "number" else "left")
    for i, step in enumerate(plan.steps, 1):
        elements = ", ".join(f"{role}={value}" for role, value in step.elements.items())
        frame = f"[bold]{step.frame}[/bold]" if step.commanded else step.frame
        because = f"[dim]← {step.because}[/dim]" if step.because else ""
        table.add_row(f"{i}.", frame, elements, because)
    out.print(table)
    out.print(f"[dim]state:[/dim] {', '.join(map(str, plan.initial)) or '—'}")
    out.print(f"[dim]goal:[/dim]  {', '.join(map(str, plan.goal)) or '—'}")


@command("plan")
def plan(
    text: str = typer.Argument(..., help="The command, e.g. \"heat the egg and put it in the fridge\"."),
    holding: str | None = typer.Option(None, "--holding", help="The class of what the robot holds (overrides "
                                       "the map's robot).", show_default=False),
    done: list[str] | None = typer.Option(None, "--done", help="A command already carried out (repeatable, in "
                                          "order): its frames' postconditions hold.", show_default=False),
    map_name: str | None = MapOption,
    vocabulary: Path | None = VocabularyOption,
    pddl: Path | None = typer.Option(None, "--pddl", help="Also write domain.pddl and problem.pddl into this "
                                     "existing folder.", show_default=False),
    max_nodes: int = typer.Option(MAX_NODES, "--max-nodes", min=1, help="Give up after expanding this many "
                                  "search nodes."),
    framelib: list[Path] | None = FramelibOption,
    as_json: bool = JsonOption,
) -> None:
    """Plan a command: the frames it commands, in order, with the frames their preconditions need."""
    from ..library import load_library
    from ..planning import plan_text

    library = load_library(framelib_paths(framelib))
    world = None
    if map_name is not None:
        from ..maps import load_map
        from ..resources import map_path

        world = load_map(map_path(map_name))
    result = plan_text(text, library, holding=holding, done=tuple(done or ()), map=world,
                       vocabulary=vocabulary_from(vocabulary, map_name), max_nodes=max_nodes)
    if pddl is not None:
        from ..pddl import write_pddl

        write_pddl(pddl, library, result)
    if as_json:
        emit_json(result.to_json())
    else:
        show(result)
