"""The ``seal`` command line: option parsing and output formatting only.

Each command lives in a module of this package and registers itself on :data:`app`. Commands
call plain engine functions, print results on stdout (JSON with ``--json``) and diagnostics on
stderr. A :class:`~seal_cli.errors.SealError` becomes one clear message and exit code 1; usage
errors are typer's own (exit 2); nothing else may escape as a traceback.
"""

from __future__ import annotations

import functools
import json
import sys
from collections.abc import Callable
from pathlib import Path
from typing import Any, TypeVar

import typer
from rich.console import Console

from seal_cli import __version__
from seal_cli.errors import SealError, SealErrors

__all__ = ["app", "bench_app", "command", "emit_json", "err", "main", "out"]

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

out = Console(soft_wrap=True, highlight=False)
err = Console(stderr=True, soft_wrap=True, highlight=False)

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

        (on or app).command(*args, **kwargs)(run)
        return function

    return decorate


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


def _version(value: bool) -> None:
    if value:
        out.print(f"seal {__version__}")
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
