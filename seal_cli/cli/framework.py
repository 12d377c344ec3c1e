"""The command line's framework: typer's app, the decorator that registers a command on it, and the
options several commands share.

Imported by the command modules (through :mod:`seal_cli.cli`), never by ``seal --version`` or
``seal parse TEXT``, which are answered without typer (:func:`seal_cli.cli.main`).
"""

from __future__ import annotations

import functools
import inspect
from collections.abc import Callable
from pathlib import Path
from typing import Any, TypeVar

import typer
from typer.core import TyperCommand

from seal_cli import __version__
from seal_cli.cli.output import run_command

__all__ = ["FramelibOption", "JsonOption", "app", "bench_app", "command", "short_help"]

app = typer.Typer(
    name="seal",
    help="SEAL: parse robot commands into semantic frames, plan them, and localise where each can be executed.",
    add_completion=False,
    no_args_is_help=True,
    pretty_exceptions_enable=False,
    context_settings={"help_option_names": ["-h", "--help"]},
)

bench_app = typer.Typer(help="Benchmarks: parsing corpora, planning time, belief-update speed, map queries, the task "
                        "suites with baselines, commands end to end, hostile inputs, reading bags, start-up cost.",
                        no_args_is_help=True)
app.add_typer(bench_app, name="bench")


F = TypeVar("F", bound=Callable[..., Any])


def _readable_usage_errors() -> None:
    """typer's usage errors (a bad option value, an unknown command, extra arguments) printed their values whole: an
    integer of 5,000 digits or an argument of 100,000 letters filled the screen. Each such message is cut as seal's own
    are (:func:`seal_cli.errors.readable`: a word past 200 characters, the whole past 3,000) where it is made, in
    click's exception (typer's own copy of click, imported with typer: nothing more is imported at start); the exit
    code (2) and the usage line stay typer's. typer has no hook for this. The help that ``seal`` alone prints goes
    through another exception, left whole."""
    from typer._click import exceptions

    from seal_cli.errors import readable

    made = exceptions.ClickException.__init__
    if getattr(made, "readable", False):
        return

    def cut(self: Any, message: str) -> None:
        made(self, message if type(self).__name__ == "NoArgsIsHelpError" else readable(message))

    cut.readable = True  # type: ignore[attr-defined]
    exceptions.ClickException.__init__ = cut  # type: ignore[method-assign]


_readable_usage_errors()


def command(*args: Any, on: typer.Typer | None = None, **kwargs: Any) -> Callable[[F], F]:
    """``@app.command`` (or a command of the sub-app ``on``, e.g. ``bench_app``) that turns
    SealError into a message on stderr and exit code 1 (and the other failures
    :func:`~seal_cli.cli.output.run_command` names into theirs)."""

    def decorate(function: F) -> F:
        @functools.wraps(function)
        def run(*a: Any, **kw: Any) -> None:
            def checked() -> int | None:
                _refuse_repeated_options()
                _refuse_empty_values(kw)
                _refuse_folder_names_of_files(kw)
                return function(*a, **_composed_commands(kw))

            code = run_command(checked)
            if code:
                raise typer.Exit(code)

        if "short_help" not in kwargs and function.__doc__:
            kwargs["short_help"] = short_help(function.__doc__)
        (on or app).command(*args, cls=_OnceCommand, **kwargs)(run)
        return function

    return decorate


_GIVEN = "seal.given"
"""The key, in a command's click context's ``meta``, of what each option taking one value was given, as typed."""


class _OnceCommand(TyperCommand):
    """typer's command, whose parser notes each value given to an option that takes one (click's ``store``
    action): given twice (``--clock 10:00 --clock 11:00``) click keeps the last, silently; the command then refuses
    it (:func:`_refuse_repeated_options`). Repeatable options (``--done``, ``--framelib``: click's ``append``) and
    flags (``--json --json`` says the same once more) are left as they are."""

    def make_parser(self, ctx: Any) -> Any:
        parser = super().make_parser(ctx)
        given: dict[str, list[str]] = ctx.meta.setdefault(_GIVEN, {})
        for option in {id(o): o for o in (*parser._long_opt.values(), *parser._short_opt.values())}.values():
            if option.action == "store" and option.obj is not None:
                option.process = functools.partial(_noted, option.process, given, option.obj)  # type: ignore[method-assign]
        return parser


def _noted(process: Callable[[Any, Any], None], given: dict[str, list[str]], option: Any, value: Any,
           state: Any) -> None:
    """An option's value, noted under its longest name as the parser meets it, then stored as click stores it."""
    given.setdefault(max(option.opts, key=len), []).append(value)
    process(value, state)


def _refuse_repeated_options() -> None:
    """Refuse an option that takes one value given more than once, naming it and the values as typed (hostile32):
    ``run --clock 10:00 --clock 11:00`` ran at 11:00, ``run --map studio --map apartment`` on the apartment, ``--seed
    1 --seed 2`` with seed 2, and nothing said so."""
    from typer._click.globals import get_current_context

    from seal_cli.errors import SealError

    context = get_current_context(silent=True)
    given: dict[str, list[str]] = context.meta.get(_GIVEN, {}) if context is not None else {}
    for option, values in given.items():
        if len(values) > 1:
            times = "twice" if len(values) == 2 else f"{len(values)} times"
            shown = ", ".join(repr(v) if len(str(v)) <= 40 else repr(str(v)[:40]) + "…" for v in values)
            raise SealError(f"{option} is given {times} ({shown}); it takes one value: give it once")


def given(parameter: str) -> bool:
    """Whether the running command's ``parameter`` (its function's argument) was given on the command line, not left
    at its default: an option that goes only with another (``--frame`` with ``--bag``) or with some suites is refused
    when given without it, even at its default's value (hostile20)."""
    from typer._click.core import ParameterSource
    from typer._click.globals import get_current_context  # typer's own copy of click, whose context runs the command

    context = get_current_context(silent=True)
    source = context.get_parameter_source(parameter) if context is not None else None
    return source not in (None, ParameterSource.DEFAULT)


def short_help(doc: str) -> str:
    """A command's line in its group's list of commands: the docstring's first paragraph on one line. typer (0.28)
    keeps the docstring's line breaks there in its rich markup mode, so a wrapped docstring was listed broken
    mid-sentence (``seal bench --help``: "... a building's" / "and a large floor's ...")."""
    return " ".join(inspect.cleandoc(doc).split("\n\n")[0].split())


COMMAND_TEXTS = ("text", "tasks", "done", "commands", "holding")
"""The parameters that hold what a user types as a command (or a class held): composed to NFC as files are
(``fileio.composed``); file and map names are left as given (a file system may hold a name decomposed)."""


def _composed_commands(values: dict[str, Any]) -> dict[str, Any]:
    """``values`` with the commands a user typed composed (NFC): "go to the cafe" + U+0301 was "unexpected
    character" at the accent."""
    from seal_cli.fileio import typed

    def one(value: Any) -> Any:
        if isinstance(value, str):
            return typed(value)
        if isinstance(value, list):
            return [typed(v) if isinstance(v, str) else v for v in value]
        return value

    return {name: one(value) if name in COMMAND_TEXTS else value for name, value in values.items()}


def _options() -> list[Any]:
    """The running command's options (click's parameters that have ``--names``), or none outside a command."""
    from typer._click.globals import get_current_context

    context = get_current_context(silent=True)
    return [p for p in context.command.params if p.param_type_name == "option"] if context is not None else []


def _given_empty(opts: list[str], argv: list[str]) -> str | None:
    """Which of an option's names ``argv`` gives an empty value (``--pddl ''``, ``--pddl=``), or None."""
    for option in opts:
        if f"{option}=" in argv or any(argv[k] == option and argv[k + 1] == "" for k in range(len(argv) - 1)):
            return option
    return None


def _refuse_empty_values(values: dict[str, Any]) -> None:
    """Refuse an option given an empty value, naming it. A file or folder option: typer reads ``''`` as ``.``, the
    current folder, and ``plan --pddl ''`` wrote its files there, ``--png ''`` was "a folder". Any other: ``''`` was
    read as if the option were left out, or as a name no one gives (hostile27: ``plan --holding ''`` planned with the
    map's robot's hand, ``run --holding ''`` with an empty one; ``import-bag --pose-topic ''`` said "no topic  in the
    bag"; ``--done ''`` and ``--task ''`` were "column 1: empty command", naming no option). The option is named as
    typed (its click names, not its parameter's: ``--vocabulary`` of ``vocabulary_file`` was "an empty
    VOCABULARY_FILE was given")."""
    import sys

    from seal_cli.errors import SealError

    argv = sys.argv[1:]
    options = {p.name: p for p in _options()}
    for name, value in values.items():
        items = value if isinstance(value, list | tuple) else [value]
        if not any(isinstance(v, Path) and str(v) == "." or v == "" for v in items):
            continue
        option = options.get(name)
        if option is None:      # an argument: `validate ''`
            if any(isinstance(v, Path) for v in items) and "" in argv and "." not in argv:
                raise SealError(f"an empty {name.upper().rstrip('S')} was given: give a file or folder name")
            continue
        if "--map" in option.opts:  # an empty map name is the map's own problem: resources.map_path lists the maps
            continue
        typed = _given_empty(option.opts, argv)
        if typed is None and "" in items and given(name):  # an empty text given, argv not this command's own
            typed = max(option.opts, key=len)
        if typed is not None:
            out = "" if option.required else ", or leave the option out"
            helped = (option.help or "").rstrip(".")      # what it takes: its choices, if any
            takes = f" ({helped[:1].lower()}{helped[1:]})" if helped else ""
            said = (f" (an empty command says nothing): give one{out}" if name in COMMAND_TEXTS[:4]
                    else ": give a file or folder name" if any(isinstance(v, Path) for v in items)
                    else f": give a value{takes}{out}")
            raise SealError(f"{typed} is empty{said}")


def _refuse_folder_names_of_files(values: dict[str, Any]) -> None:
    """Refuse a file's name given with a ``/`` after it (``--rrd o.rrd/``, ``--observations o.yaml/``, ``validate
    m.yaml/``), naming the option as typed. Such a name is a folder's (``cat o.yaml/`` says "Not a directory"), but
    typer makes it a ``Path``, which drops the ``/``: the output was written as the file ``o.rrd``, the input read as
    the file (hostile31). A name of an existing folder (``--framelib lib/``, ``--pddl out/``) or of no file and no
    suffix (``--goals bag/``, a ROS 2 bag's folder to make) is a folder's, as it says."""
    import sys

    from seal_cli.errors import SealError
    from seal_cli.fileio import shown_path

    argv = sys.argv[1:]
    options = {p.name: p for p in _options()}
    for name, value in values.items():
        items = value if isinstance(value, list | tuple) else [value]
        option = options.get(name)
        for item in items:
            a_map = isinstance(item, str) and option is not None and "--map" in option.opts
            if not (isinstance(item, Path) or a_map):
                continue
            raw = _typed_with_slash(str(item), option.opts if option is not None else (), argv)
            if raw is None:
                continue
            target = Path(raw.lstrip("+") if option is not None and "--framelib" in option.opts else raw)
            if target.is_dir() or not (target.exists() or target.is_symlink() or target.suffix):
                continue
            said = f"{max(option.opts, key=len)} {shown_path(raw)}" if option is not None else shown_path(raw)
            what = f"{shown_path(target)} is a file" if target.exists() else f"there is no folder {shown_path(target)}"
            raise SealError(f"{said}: a name ending in '/' is a folder's, and {what}: give the file's name without the "
                            "'/'")


def _typed_with_slash(value: str, opts: tuple[str, ...] | list[str], argv: list[str]) -> str | None:
    """How ``value`` (a path typer made, its trailing ``/`` dropped) was typed in ``argv``, if it was typed with a
    ``/`` (or ``/.``) after it: after one of ``opts`` (``--png x/``, ``--png=x/``), or anywhere for an argument."""
    for k, typed in enumerate(argv):
        for opt in opts:
            if typed.startswith(f"{opt}="):
                typed = typed[len(opt) + 1:]
                break
        else:
            if opts and not (k and argv[k - 1] in opts):
                continue
        if typed.rstrip("/").removesuffix("/.").rstrip("/") != typed and Path(typed) == Path(value) \
                and typed not in ("/", "+/"):
            return typed
    return None


FramelibOption = typer.Option(None, "--framelib", help="Frame library file or folder (repeatable); "
                              "default: the shipped standard library. +PATH adds to the standard library.",
                              show_default=False)
JsonOption = typer.Option(False, "--json", help="Machine-readable output on stdout.")


def _version(value: bool) -> None:
    if value:
        typer.echo(f"seal {__version__}")
        raise typer.Exit()


@app.callback()
def _root(version: bool = typer.Option(False, "--version", callback=_version, is_eager=True,
                                       help="Print the version and exit.")) -> None:
    """SEAL: Semantic Frame Execution And Localization."""
