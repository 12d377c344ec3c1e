"""The ``seal`` command line: option parsing and output formatting only.

Each command lives in a module of this package and registers itself on :data:`app`
(:mod:`~seal_cli.cli.framework`: typer). Commands call plain engine functions, print results on stdout
(JSON with ``--json``) and diagnostics on stderr (:mod:`~seal_cli.cli.output`). A
:class:`~seal_cli.errors.SealError` becomes one clear message and exit code 1; usage errors are typer's
own (exit 2); nothing else may escape as a traceback.

A command line imports only the module of the command it names (:func:`command_modules`), and the
commonest one, ``seal parse TEXT`` (``--json``), is answered without typer at all (:func:`main`):
the same function prints the same parse, through the same failure handling.

May import anything; nothing imports it (but ``python -m seal_cli``).
"""

from __future__ import annotations

import os
import sys
from pathlib import Path
from typing import TYPE_CHECKING, Any

from seal_cli.cli.output import PIPE_WIDTH, LazyConsole, emit_json, err, out, progress_bar, report

if TYPE_CHECKING:
    import typer

    from seal_cli.cli.framework import FramelibOption, JsonOption, bench_app, command

    app: typer.Typer
    """The whole command line, every command registered (made when first asked for, see ``__getattr__``)."""

__all__ = ["DETECTIONS_TOPIC_HELP", "MAX_COUNT", "MAX_PARTICLES", "MAX_RUN_METRES", "MAX_RUN_STEPS", "MAX_STEPS",
           "OUTPUT_SUFFIXES", "PIPE_WIDTH", "POSE_TOPIC_HELP", "FramelibOption", "JsonOption", "LazyConsole",
           "a_number", "app", "bench_app", "choices", "command", "emit_json", "err", "main", "one_held", "out",
           "progress_bar", "report"]


def framelib_paths(paths: list[Path] | None) -> list[Path] | None:
    """The library's files: as given, or the standard library and then each ``+PATH`` (which adds to
    it instead of replacing it)."""
    if not paths:
        return None
    added = [str(p).startswith("+") for p in paths]
    if not any(added):
        return list(paths)
    from seal_cli.resources import framelib_dir

    if any(str(p).strip() == "+" for p in paths):  # Path("") is ".": the current folder would be read as frames
        from seal_cli.errors import SealError

        raise SealError("--framelib +: give a file or folder after the '+' (--framelib +PATH adds PATH to the "
                        "standard library)")
    return [framelib_dir(), *(Path(str(p)[1:]) if plus else p for p, plus in zip(paths, added, strict=True))]


def choices(option: str, given: list[str], known: tuple[str, ...] | list[str], what: str) -> list[str]:
    """The names an option lists (``--policies sefm,greedy``, or ``--format`` given again and again), each checked:
    none at all, one unknown (the known listed) or one named twice (``sefm,sefm`` ran the same policy twice, as
    two identical columns at twice the time) is a SealError naming the option and the value as given; ``what``: the
    kind of name ("policy"), for the message."""
    from seal_cli.errors import SealError

    names = [name.strip() for value in given for name in value.split(",") if name.strip()]
    shown = ",".join(given)
    if not names:
        raise SealError(f"{option} {shown!r} names nothing; give one or more of {', '.join(known)}")
    for name in names:
        if name not in known:
            raise SealError(f"{option} {shown!r}: unknown {what} {name!r}; known: {', '.join(known)}")
    twice = next((name for i, name in enumerate(names) if name in names[:i]), None)
    if twice is not None:
        raise SealError(f"{option} {shown!r} names {twice!r} twice; name each once")
    return names


def one_held(holding: list[str] | None) -> str | None:
    """What ``--holding`` says the robot holds: the option given once, or None. The robot has one hand, so the
    option given twice or more (``--holding spoon --holding cup``) is refused, naming each value, rather than
    keeping the last silently (typer's way with a single-valued option)."""
    from seal_cli.errors import SealError

    if not holding:
        return None
    if len(holding) > 1:
        raise SealError(f"--holding is given {len(holding)} times ({', '.join(map(repr, holding))}); the robot holds "
                        "one thing at a time: give it once")
    return holding[0]


MAX_PARTICLES = 100_000
"""The most particles per object and per frame a command takes (a million per belief fills memory)."""

MAX_STEPS = 100_000
"""The most belief updates ``seal localize --steps`` takes (about ten minutes at 200 particles)."""

POSE_TOPIC_HELP = ("the robot's pose (PoseStamped, PoseWithCovarianceStamped, Odometry, or /tf); default: /tf if it "
                   "links --frame to --base-frame, else the bag's only pose topic.")
"""``--pose-topic``'s help, shared by ``seal localize --bag`` and ``seal import-bag``."""

DETECTIONS_TOPIC_HELP = "the vision_msgs Detection2DArray/3DArray topic; default: the bag's only one."
"""``--detections-topic``'s help, shared likewise."""

MAX_RUN_STEPS = 100_000
"""The most steps ``seal run --max-steps`` allows (a run ends sooner when its task is done)."""

MAX_RUN_METRES = 100_000.0
"""The farthest ``seal run --max-metres`` lets the robot drive (100 km; NaN and infinity are refused)."""

MAX_COUNT = 1_000
"""The most layouts, repeats and runs a benchmark option takes (each is a whole run of its own)."""


def a_number(value: float | None) -> float | None:
    """An option's callback that refuses NaN (click's ranges let it through: no comparison holds)."""
    if value is not None and value != value:
        import typer

        raise typer.BadParameter("must be a number, not nan")
    return value


OUTPUT_SUFFIXES = {"--png": (".png",), "--rrd": (".rrd",), "--episodes": (".jsonl", ".json"),
                   "--goals": (".yaml", ".yml", ".bag", ".mcap"), "--output": (".yaml", ".yml")}
"""The suffixes each output option's format may carry (``--png out.jpg`` is refused, not mislabelled)."""


COMMAND_ORDER = ("parse_cmd", "plan_cmd", "localize_cmd", "run_cmd", "library_cmd", "map_cmd")
"""The order commands appear in ``seal --help``: the pipeline first, then the tools."""

HOMES = {"parse": "parse_cmd", "plan": "plan_cmd", "localize": "localize_cmd", "run": "run_cmd",
         "frames": "library_cmd", "validate": "library_cmd", "map": "map_cmd", "import-bag": "ros_cmd"}
"""The module of each command (``tests/cli`` checks this against what the modules register)."""

BENCH_HOMES = {"parse": "parse_cmd", "plan": "plan_cmd", "maps": "map_cmd", "perf": "perf_cmd",
               "reliability": "reliability_cmd", "ros": "ros_cmd", "tasks": "run_cmd", "e2e": "run_cmd",
               "startup": "startup_cmd"}
"""The module of each ``seal bench`` command."""


def command_modules(argv: list[str] | None = None) -> list[str]:
    """The command modules a command line needs: only its command's module when it names one
    (``seal parse ...`` needs ``parse_cmd``, ``seal bench perf ...`` ``perf_cmd``), every module
    otherwise (``seal --help``, a misspelt command: its message lists them all). Importing one module
    instead of eleven, and typer making one command instead of twenty, is a fifth of ``seal parse``'s
    start (``seal bench startup``)."""
    import pkgutil

    found = {m.name for m in pkgutil.iter_modules(__path__) if m.name.endswith("_cmd")}
    every = [m for m in COMMAND_ORDER if m in found] + sorted(found - set(COMMAND_ORDER))
    argv = argv or []
    home = HOMES.get(argv[0]) if argv else None
    if argv[:1] == ["bench"] and len(argv) > 1:
        home = BENCH_HOMES.get(argv[1])
    return [home] if home in found else every


_registered: set[str] = set()


def register(modules: list[str] | None = None) -> typer.Typer:
    """Import command modules (default: all) so that they register on the app; the app."""
    import importlib

    from seal_cli.cli import framework

    for module in command_modules() if modules is None else modules:
        if module not in _registered:
            importlib.import_module(f"{__name__}.{module}")
            _registered.add(module)
    return framework.app


_FRAMEWORK = ("FramelibOption", "JsonOption", "bench_app", "command")


def __getattr__(name: str) -> Any:
    """``app``, the whole command line with every command registered (what tests and ``--help`` see),
    and the framework's names the command modules use: typer is imported when first asked for."""
    if name == "app":
        return register()
    if name in _FRAMEWORK:
        from seal_cli.cli import framework

        return getattr(framework, name)
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")


def plain_parse(argv: list[str]) -> tuple[str, bool] | None:
    """``(TEXT, as_json)`` when the command line is ``parse TEXT`` with at most ``--json`` beside it
    (TEXT not starting with '-'), which :func:`main` answers without typer; None for anything else
    (other options, ``--help``, shell completion), which typer answers."""
    if argv[:1] != ["parse"] or "_SEAL_COMPLETE" in os.environ:
        return None
    rest = argv[1:]
    words = [a for a in rest if a != "--json"]
    if len(words) != 1 or words[0].startswith("-") or len(rest) - len(words) > 1:
        return None
    return words[0], len(rest) > 1


def main() -> None:
    """Entry point of the ``seal`` console script: the app with the commands this command line needs;
    ``seal parse TEXT`` without typer (the same function prints the same parse, see
    :func:`seal_cli.cli.parse_view.print_parse`)."""
    plain = plain_parse(sys.argv[1:])
    if plain is not None:
        from seal_cli.cli.output import run_command
        from seal_cli.cli.parse_view import print_parse
        from seal_cli.fileio import typed

        text, as_json = plain   # as the typer path takes it (cli.framework): composed, its bytes read as UTF-8
        sys.exit(run_command(lambda: print_parse(typed(text), None, None, as_json)))  # the standard library
    from seal_cli.cli.output import run_framework

    run_framework(register(command_modules(sys.argv[1:])))
