"""``seal plan``: the ordered, grounded frames that carry out a command from the robot's state."""

from __future__ import annotations

from dataclasses import asdict, dataclass
from pathlib import Path

import typer
from rich.table import Table

from ..planning import MAX_NODES, Plan
from . import FramelibOption, JsonOption, bench_app, command, emit_json, framelib_paths, out
from .parse_cmd import VocabularyOption, vocabulary_from

MapOption = typer.Option(None, "--map", help="The world: its places (openable ones closed unless open: true), "
                         "where its objects are, the robot's hand; also grounds the words in its classes. "
                         "A path or a shipped map's name.", show_default=False)


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


@dataclass(frozen=True)
class Timing:
    """One command's plan: commanded and total frames, search nodes expanded, median milliseconds
    for parse + ground + plan, and for the plan alone."""

    text: str
    commanded: int
    steps: int
    nodes: int
    ms: float
    plan_ms: float
    """Of ``ms``, the search alone (the rest is parsing and grounding)."""


BENCH_COMMANDS = (
    "stir the cup",
    "heat the egg and put it in the fridge",
    "slice the apple and put it in the fridge",
    "put two apples in the fridge, put three eggs in the microwave and put two cups on the table",
    "go to the kitchen, pick up the cup, bring it to me",
    "find the cup, bring it to me, find the spoon, give it to Roger, open the fridge and put the apple in the fridge",
    "pick up the cup, put it in the fridge, pick up the apple, put it in the microwave, pick up the spoon "
    "and stir the cup",
    "look at the clock under the lamp, turn off the lamp, slice the bread, heat it, put it on the table "
    "and close the microwave",
    "heat the egg, cool the apple, clean the plate, put the egg on the plate, put the apple in the microwave "
    "and stir the cup",
    "stir the cup, slice the apple, put the apple in the cup, heat the cup, put the cup in the fridge "
    "and close the fridge",
    "slice the apple, slice the bread, slice the tomato, put the apple in the fridge, put the bread in the fridge "
    "and put the tomato in the fridge",
)
"""Commands of one to six clauses that ``seal bench plan`` times by default."""


@command("plan", on=bench_app)
def bench_plan(
    file: Path | None = typer.Option(None, "--file", "-f", help="Time these commands (one per line) instead of "
                                     "the built-in ones.", show_default=False),
    map_name: str | None = MapOption,
    repeat: int = typer.Option(5, "--repeat", min=1, help="Runs per command; the median is reported."),
    framelib: list[Path] | None = FramelibOption,
    as_json: bool = JsonOption,
) -> None:
    """Time parse + ground + plan for commands of up to six clauses; report the slowest."""
    import statistics
    import time

    from ..library import load_library
    from ..planning import plan as search
    from ..problem import problem_of_text

    library = load_library(framelib_paths(framelib))
    world = None
    if map_name is not None:
        from ..maps import load_map
        from ..resources import map_path

        world = load_map(map_path(map_name))
    vocabulary = vocabulary_from(None, map_name)
    if file is not None:
        from ..fileio import read_text

        texts = [line.strip() for line in read_text(file).splitlines() if line.strip()]
    else:
        texts = list(BENCH_COMMANDS)
    problem_of_text(texts[0], library, map=world, vocabulary=vocabulary)      # warm up: grammar and lexicon
    rows = []
    for text in texts:
        times, searches = [], []
        for _ in range(repeat):
            begin = time.perf_counter()
            problem = problem_of_text(text, library, map=world, vocabulary=vocabulary)
            middle = time.perf_counter()
            result = search(problem.commanded, library, problem.state, text=text)
            times.append(time.perf_counter() - begin)
            searches.append(time.perf_counter() - middle)
        rows.append(Timing(text, sum(s.commanded for s in result.steps), len(result.steps), result.expanded,
                           round(1000 * statistics.median(times), 2), round(1000 * statistics.median(searches), 2)))
    slowest = max(rows, key=lambda r: r.ms)
    if as_json:
        emit_json({"map": world.name if world else None, "repeat": repeat,
                   "commands": [asdict(r) for r in rows], "slowest": asdict(slowest)})
        return
    table = Table(title=f"parse + ground + plan, median of {repeat}" + (f", map {world.name}" if world else ""),
                  title_justify="left")
    for column in ("ms", "plan ms", "nodes", "steps", "commanded", "command"):
        table.add_column(column, justify="left" if column == "command" else "right", overflow="fold")
    for row in rows:
        table.add_row(f"{row.ms:.2f}", f"{row.plan_ms:.2f}", str(row.nodes), str(row.steps), str(row.commanded),
                      row.text)
    out.print(table)
    out.print(f"slowest: {slowest.ms:.2f} ms — {slowest.text}", markup=False)
