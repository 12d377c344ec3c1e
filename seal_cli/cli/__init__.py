"""The ``seal`` command line: option parsing and output formatting only.

Each command lives in a module of this package and registers itself on :data:`app`. Commands
call plain engine functions, print results on stdout (JSON with ``--json``) and diagnostics on
stderr. A :class:`~seal_cli.errors.SealError` becomes one clear message and exit code 1; usage
errors are typer's own (exit 2); nothing else may escape as a traceback.

May import anything; nothing imports it (but ``python -m seal_cli``).
"""

from __future__ import annotations

import contextlib
import functools
import json
import os
import sys
from collections.abc import Callable, Iterator
from pathlib import Path
from typing import TYPE_CHECKING, Any, TypeVar

import typer

from seal_cli import __version__
from seal_cli.errors import SealError, SealErrors

if TYPE_CHECKING:
    from rich.console import Console

__all__ = ["MAX_COUNT", "MAX_PARTICLES", "MAX_RUN_METRES", "MAX_RUN_STEPS", "MAX_STEPS", "OUTPUT_SUFFIXES",
           "a_number", "app", "bench_app", "command", "emit_json", "err", "main", "out", "progress_bar"]

app = typer.Typer(
    name="seal",
    help="SEAL: parse robot commands into semantic frames, plan them, and localise where each can be executed.",
    add_completion=False,
    no_args_is_help=True,
    pretty_exceptions_enable=False,
    context_settings={"help_option_names": ["-h", "--help"]},
)

bench_app = typer.Typer(help="Benchmarks: parsing corpora, the task suite with baselines, belief-update speed.",
                        no_args_is_help=True)
app.add_typer(bench_app, name="bench")



PIPE_WIDTH = 200
"""Columns of the output when it is not a terminal (a file, a pipe) and ``COLUMNS`` is not set."""


class LazyConsole:
    """A rich ``Console``, made when first used: importing rich costs more than ``seal --version`` and
    ``seal parse --json`` do in all, and they never print through it."""

    def __init__(self, **options: Any) -> None:
        self._options = options
        self._console: Console | None = None

    @property
    def console(self) -> Console:
        """The console itself (for what wants one: a ``rich.progress.Progress``)."""
        if self._console is None:
            from rich.console import Console

            console = Console(**self._options)
            if not console.is_terminal and "COLUMNS" not in os.environ:
                console.width = PIPE_WIDTH  # rich's 80 columns would cut the tables of a redirected run
            self._console = console
        return self._console

    def __getattr__(self, name: str) -> Any:
        return getattr(self.console, name)


out = LazyConsole(soft_wrap=True, highlight=False)
err = LazyConsole(stderr=True, soft_wrap=True, highlight=False)

F = TypeVar("F", bound=Callable[..., Any])


def report(error: SealError) -> None:
    """Print a SealError (or each of several) on stderr, plainly."""
    problems = error.problems if isinstance(error, SealErrors) else [error]
    for problem in problems:
        err.print(f"error: {problem}", markup=False)


def command(*args: Any, on: typer.Typer | None = None, **kwargs: Any) -> Callable[[F], F]:
    """``@app.command`` (or a command of the sub-app ``on``, e.g. ``bench_app``) that turns
    SealError into a message on stderr and exit code 1."""

    def decorate(function: F) -> F:
        @functools.wraps(function)
        def run(*a: Any, **kw: Any) -> Any:
            from seal_cli.fileio import clean_up_on_signals, remove_temporaries

            clean_up_on_signals()
            try:
                return function(*a, **kw)
            except SealError as error:
                report(error)
                raise typer.Exit(1) from None
            except KeyboardInterrupt:
                err.print("interrupted")
                raise typer.Exit(130) from None
            except BrokenPipeError:
                raise typer.Exit(0) from None
            except MemoryError:
                err.print("error: out of memory: ask for less (fewer particles, steps, episodes or a smaller "
                          "map)", markup=False)
                raise typer.Exit(1) from None
            except RecursionError:
                err.print("error: the input is nested too deeply for seal to handle", markup=False)
                raise typer.Exit(1) from None
            finally:
                remove_temporaries()  # of outputs planned but never written: the command failed first

        (on or app).command(*args, **kwargs)(run)
        return function

    return decorate


@contextlib.contextmanager
def progress_bar(what: str, total: int | None = None) -> Iterator[Callable[[int, int], None]]:
    """``advance(done, total)`` for a bar with the count, the time taken and an estimate of the time
    left: on stderr, and only when stderr is a terminal (nothing in a pipe, a file or a test)."""
    from rich.progress import (
        BarColumn,
        MofNCompleteColumn,
        Progress,
        TextColumn,
        TimeElapsedColumn,
        TimeRemainingColumn,
    )

    with Progress(TextColumn(what), BarColumn(), MofNCompleteColumn(), TimeElapsedColumn(), TextColumn("left"),
                  TimeRemainingColumn(), console=err.console, transient=True,
                  disable=not err.is_terminal) as progress:
        bar = progress.add_task(what, total=total)
        yield lambda done, total: progress.update(bar, completed=done, total=total)


def emit_json(data: Any) -> None:
    """One JSON document on stdout."""
    sys.stdout.write(json.dumps(data, ensure_ascii=False) + "\n")
    sys.stdout.flush()


def framelib_paths(paths: list[Path] | None) -> list[Path] | None:
    """The library's files: as given, or the standard library and then each ``+PATH`` (which adds to
    it instead of replacing it)."""
    if not paths:
        return None
    added = [str(p).startswith("+") for p in paths]
    if not any(added):
        return list(paths)
    from seal_cli.resources import framelib_dir

    return [framelib_dir(), *(Path(str(p)[1:]) if plus else p for p, plus in zip(paths, added, strict=True))]


FramelibOption = typer.Option(None, "--framelib", help="Frame library file or folder (repeatable); "
                              "default: the shipped standard library. +PATH adds to the standard library.",
                              show_default=False)
JsonOption = typer.Option(False, "--json", help="Machine-readable output on stdout.")

MAX_PARTICLES = 100_000
"""The most particles per object and per frame a command takes (a million per belief fills memory)."""

MAX_STEPS = 100_000
"""The most belief updates ``seal localize --steps`` takes (about ten minutes at 200 particles)."""

MAX_RUN_STEPS = 100_000
"""The most steps ``seal run --max-steps`` allows (a run ends sooner when its task is done)."""

MAX_RUN_METRES = 100_000.0
"""The farthest ``seal run --max-metres`` lets the robot drive (100 km; NaN and infinity are refused)."""

MAX_COUNT = 1_000
"""The most layouts, repeats and runs a benchmark option takes (each is a whole run of its own)."""


def a_number(value: float | None) -> float | None:
    """An option's callback that refuses NaN (click's ranges let it through: no comparison holds)."""
    if value is not None and value != value:
        raise typer.BadParameter("must be a number, not nan")
    return value


OUTPUT_SUFFIXES = {"--png": (".png",), "--rrd": (".rrd",), "--episodes": (".jsonl", ".json"),
                   "--goals": (".yaml", ".yml"), "--output": (".yaml", ".yml")}
"""The suffixes each output option's format may carry (``--png out.jpg`` is refused, not mislabelled)."""


def _version(value: bool) -> None:
    if value:
        typer.echo(f"seal {__version__}")
        raise typer.Exit()


@app.callback()
def _root(version: bool = typer.Option(False, "--version", callback=_version, is_eager=True,
                                       help="Print the version and exit.")) -> None:
    """SEAL: Semantic Frame Execution And Localization."""


def _register() -> None:
    """Import the command modules so that they register on ``app``."""
    import importlib
    import pkgutil

    found = {m.name for m in pkgutil.iter_modules(__path__) if m.name.endswith("_cmd")}
    order = [m for m in COMMAND_ORDER if m in found] + sorted(found - set(COMMAND_ORDER))
    for module in order:
        importlib.import_module(f"{__name__}.{module}")


COMMAND_ORDER = ("parse_cmd", "plan_cmd", "localize_cmd", "run_cmd", "library_cmd", "map_cmd")
"""The order commands appear in ``seal --help``: the pipeline first, then the tools."""


_register()


def main() -> None:
    """Entry point of the ``seal`` console script."""
    app()
