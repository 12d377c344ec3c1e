"""``seal frames`` and ``seal validate``: look at a frame library and check it."""

from __future__ import annotations

from pathlib import Path
from typing import TYPE_CHECKING, Any

import typer

from seal_cli.cli import FramelibOption, JsonOption, command, emit_json, err, framelib_paths, out
from seal_cli.cli.output import plain

if TYPE_CHECKING:
    from seal_cli.frames.model import Frame


def frame_json(frame: Frame) -> dict[str, Any]:
    """A frame as the JSON that ``seal frames --json`` prints."""
    return {
        "frame": frame.name,
        "description": frame.description,
        "framenet": frame.framenet,
        "lexical_units": [u.text for u in frame.lexical_units],
        "elements": {e.role: {"type": e.type, "default": e.default} for e in frame.elements},
        "preconditions": [str(f) for f in frame.preconditions],
        "actions": [str(a) for a in frame.actions],
        "postconditions": [str(f) for f in frame.postconditions],
        "source": str(frame.where) if frame.where else None,
    }


def _elements(frame: Frame) -> str:
    return ", ".join(f"{e.role}: {e.type}" + (f" = {e.default}" if e.default else "") for e in frame.elements)


@command("frames")
def frames(
    name: str | None = typer.Argument(None, help="Show this frame in full."),
    framelib: list[Path] | None = FramelibOption,
    as_json: bool = JsonOption,
) -> None:
    """The library's frames as a table, or one frame in full."""
    from rich.table import Table

    from seal_cli.frames.reading import load_library

    library = load_library(framelib_paths(framelib))
    from seal_cli.errors import SealErrors
    from seal_cli.language.units import unit_problems

    if problems := unit_problems(library):   # what any command with this library refuses (hostile32)
        raise problems[0] if len(problems) == 1 else SealErrors(problems)
    if name is not None:
        frame = library.frame(name)
        if as_json:
            emit_json(frame_json(frame))
            return
        table = Table.grid(padding=(0, 2))
        table.add_column(style="bold")
        table.add_column()
        data = frame_json(frame)
        table.add_row("frame", plain(frame.name))
        for key in ("description", "framenet", "source"):
            if data[key]:
                table.add_row(key, plain(data[key]))
        table.add_row("lexical units", plain(", ".join(data["lexical_units"])))
        table.add_row("elements", plain("\n".join(
            f"{e.role}: {e.type}" + (f" (default {e.default})" if e.default else "") for e in frame.elements)))
        for key in ("preconditions", "actions", "postconditions"):
            table.add_row(key, plain("\n".join(f"{i + 1}. {x}" for i, x in enumerate(data[key]))) or "—")
        out.print(table)
        return
    if as_json:
        emit_json({"frames": [frame_json(f) for f in library]})
        return
    table = Table(title=f"{len(library)} frame{'' if len(library) == 1 else 's'}", title_justify="left")
    for column in ("frame", "lexical units", "elements", "preconditions", "postconditions"):
        table.add_column(column, overflow="fold")
    for frame in library:
        table.add_row(plain(frame.name), plain(", ".join(u.text for u in frame.lexical_units)), plain(_elements(frame)),
                      plain(", ".join(map(str, frame.preconditions))) or "—",
                      plain(", ".join(map(str, frame.postconditions))) or "—")
    out.print(table)


@command("validate")
def validate(
    paths: list[Path] = typer.Argument(..., help="Frame files (*.yaml, *.frame), folders of them, and map files."),
    stdlib: bool = typer.Option(False, "--stdlib", help="Check the frames together with the standard library "
                                "(for files that extend it)."),
    as_json: bool = JsonOption,
) -> None:
    """Check frame files, frame folders and maps; list every problem as file:line:col: message."""
    from seal_cli.validate import validate_paths

    report = validate_paths(paths, with_stdlib=stdlib)
    if as_json:
        emit_json(report.to_json())
    else:
        for problem in report.problems:
            out.print(str(problem), markup=False)
        summary = report.summary()
        (err if report.problems else out).print(summary, markup=False)
    if report.problems:
        raise typer.Exit(1)
