"""What every command prints through: rich consoles on stdout and stderr made when first used, JSON
on stdout, progress bars, and the failures every command shares turned into a message and an exit code.

Imports no command-line framework (typer): ``seal parse TEXT`` prints through it without one
(:func:`seal_cli.cli.main`).
"""

from __future__ import annotations

import contextlib
import functools
import io
import os
import re
import sys
from collections.abc import Callable, Iterator, MutableMapping
from typing import TYPE_CHECKING, Any

from seal_cli.errors import SealError, SealErrors, readable

if TYPE_CHECKING:
    from rich.console import Console

__all__ = ["PIPE_WIDTH", "LazyConsole", "dump_json", "emit_json", "err", "out", "plain", "plot_cache",
           "printable_streams", "progress_bar", "report", "run_command", "run_framework", "sane_sizes", "styled",
           "whole_writes"]

PIPE_WIDTH = 200
"""Columns of the output when it is not a terminal (a file, a pipe) and ``COLUMNS`` is not set."""


def reader_gone(stream: Any) -> None:
    """The program reading ``stream`` has gone (``seal validate F | head -1``): what is still to print there is
    dropped (the stream's file becomes ``/dev/null``) and the command goes on to its own end and exit code."""
    with contextlib.suppress(OSError, ValueError, AttributeError):
        os.dup2(os.open(os.devnull, os.O_WRONLY), stream.fileno())


def _console_reader_gone(console: Console) -> None:
    """rich's ``on_broken_pipe`` for seal's consoles: :func:`reader_gone`. rich's own raised ``SystemExit(1)``, so a
    command whose reader had gone exited 1 ("the input is wrong") with no message, and under ``--json`` 0: ``seal
    validate`` of a file with problems, piped into ``head -1``, exited 0 or 1 by its output format (hostile19)."""
    console.quiet = True
    reader_gone(console.file)


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
            console.on_broken_pipe = functools.partial(_console_reader_gone, console)  # type: ignore[method-assign]
            self._console = console
        return self._console

    def plain(self) -> bool:
        """Whether the console, not yet made, would print text as it is: no colours or styles (its file
        not a terminal, nor made one by ``FORCE_COLOR`` or ``TTY_COMPATIBLE``), UTF-8 (rich's tree
        guides) and :data:`PIPE_WIDTH` columns wide (no ``COLUMNS``).
        What prints then may skip importing rich (``seal parse TEXT`` into a pipe or a file)."""
        if self._console is not None or self._options.get("stderr") or any(
                name in os.environ for name in ("FORCE_COLOR", "TTY_COMPATIBLE", "COLUMNS")):
            return False
        stream = sys.stdout
        try:
            if stream.isatty():
                return False
        except (AttributeError, ValueError):
            return False
        return (getattr(stream, "encoding", None) or "utf-8").lower().startswith("utf")

    def __getattr__(self, name: str) -> Any:
        return getattr(self.console, name)


# emoji=False: rich turns ':pile_of_poo:' into 💩, and a room so called was shown as one (hostile16)
out = LazyConsole(soft_wrap=True, highlight=False, emoji=False)
err = LazyConsole(stderr=True, soft_wrap=True, highlight=False, emoji=False)

_TAG = re.compile(r"(\\*)(\[[a-z#/@][^[]*?])")
"""What rich's markup reads as a tag (``rich.markup.RE_TAGS``), with the backslashes before it."""


_CONTROL = re.compile(r"[\x00-\x08\x0b-\x1f\x7f-\x9f]")
"""Control characters but newline and tab: a name holding ESC (YAML's ``"\\e[31m"``) reached the terminal as an
escape sequence of its own."""


def _shown(text: object) -> str:
    return _CONTROL.sub(lambda m: m[0].encode("unicode_escape").decode("ascii"), str(text))


def plain(text: object) -> str:
    """``text`` as rich markup that prints as it is written. Names come from files (a room called ``[/]``, a
    frame described ``[bold]``): put into a table or a styled line unescaped, rich read them as styles, printed
    them wrong or failed with a ``MarkupError`` traceback (hostile16). Unlike ``rich.markup.escape``, a
    trailing backslash is left single: nothing follows it (:func:`styled` for text a tag follows). Control
    characters (ESC, CR) are written as escapes (``\\x1b``), never sent to the terminal."""
    return _TAG.sub(lambda m: f"{m[1]}{m[1]}\\{m[2]}", _shown(text))


def styled(style: str, text: object) -> str:
    """``text`` in ``style``, as rich markup that prints the text as it is written."""
    from rich.markup import escape

    return f"[{style}]{escape(_shown(text))}[/{style}]"


def report(error: SealError) -> None:
    """Print a SealError (or each of several) on stderr, plainly."""
    problems = error.problems if isinstance(error, SealErrors) else [error]
    for problem in problems:
        err.print(f"error: {problem}", markup=False)


FINISHED: int | None = None
"""The exit code of the command once it has finished (its outputs renamed into place), else None: an
interrupt (SIGINT) that arrives after it, while the process ends, leaves that code as it is."""

STARTED = False
"""Whether a command's body has started (:func:`run_command`): what typer prints before one (its help, a usage
error) is answered by :func:`run_framework`."""

STOPPED: list[BaseException] = []
"""The interrupt that stopped the command, kept: its traceback holds the frames it unwound, whose objects are then
never freed. One was numba's half-built llvmlite module, which segfaulted when freed (exit -11 instead of 130,
hostile24); the process then ends without freeing them (``seal_cli.__main__``)."""

READER_GONE = False
"""Whether a write to standard output or error found its reader gone (``EPIPE``: ``seal --help | head -1``)."""


def run_command(function: Callable[[], int | None]) -> int:
    """Run a command's body; its exit code. The failures every command shares become one message on
    stderr and an exit code: a SealError 1, an interrupt 130, a closed pipe 0 (the reader has what it
    wanted), memory or nesting that runs out 1; our temporaries of outputs never written are removed."""
    from seal_cli.fileio import clean_up_on_signals, committed, forget_commits, note_interrupts, remove_temporaries

    global FINISHED, STARTED

    STARTED = True
    forget_commits()
    clean_up_on_signals()
    note_interrupts()
    _closed_streams_to_null()
    _quiet_arithmetic()
    FINISHED = None
    try:
        code = function()
        FINISHED = code = code if isinstance(code, int) else 0  # its outputs are in place: the work is done
        if code == 0:
            sys.stdout.flush()  # a full disk must fail the command, not the interpreter's exit
        return code
    except SealError as error:
        report(error)
        return 1
    except KeyboardInterrupt as stop:
        STOPPED.append(stop)
        if FINISHED is not None:  # an interrupt after the command finished changes nothing it did
            return FINISHED
        if committed():  # its outputs are in place, whole: what is left (a summary printed) is not worth a failure
            return 0
        err.print("interrupted")
        return 130
    except BrokenPipeError:
        return 0
    except MemoryError:
        err.print("error: out of memory: ask for less (fewer particles, steps, episodes or a smaller "
                  "map)", markup=False)
        return 1
    except RecursionError:
        err.print("error: the input is nested too deeply for seal to handle", markup=False)
        return 1
    except OSError as error:  # what the system refuses: a name too long, a full disk under stdout, ...
        if error.filename is None:  # writing standard output failed (a full disk, a broken device)
            return output_failed(error)
        else:
            err.print(readable(f"error: {error.filename}: {error.strerror or error}"), markup=False)  # a long name cut
        return 1
    except Exception:
        from seal_cli.fileio import interrupted

        if interrupted():  # the interrupt landed in an extension's import: ImportError "initialization failed"
            err.print("interrupted")
            return FINISHED if FINISHED is not None else 130
        raise
    finally:
        remove_temporaries()  # of outputs planned but never written: the command failed first


def output_failed(error: OSError) -> int:
    """Writing standard output failed (a full disk, a broken device): what is still buffered there is dropped, the
    reason said on stderr (if it can be), exit code 1."""
    _stdout_to_null()
    with contextlib.suppress(OSError, ValueError):
        err.print(f"error: cannot write the output: {error.strerror or error}", markup=False)
    return 1


def run_framework(app: Callable[[], Any]) -> None:
    """Run typer's ``app``, which prints on its own what comes before any command (``--help``, a usage error), as a
    command prints: its help onto a full disk (``seal map --help > /dev/full``) was an ``OSError`` traceback, now
    ``error: cannot write the output: No space left on device``, exit code 1; its help into a reader that has gone
    (``seal --help | head -c1``) exited 1 with no message (rich's ``SystemExit(1)``, or click's own for ``EPIPE``),
    now the help's own 0, as a command ends with its own code when its reader has gone (hostile19). A command's body
    answers for itself (:func:`run_command`); typer's usage errors keep their exit code (2)."""
    try:
        app()
    except OSError as error:
        if error.filename is not None or STARTED:
            raise
        sys.exit(0 if isinstance(error, BrokenPipeError) else output_failed(error))
    except SystemExit as ended:
        if ended.code == 1 and READER_GONE and not STARTED:  # the help's reader left: rich's or click's exit 1
            raise SystemExit(_help_code()) from None
        raise


def _help_code() -> int:
    """The exit code of the help typer prints before any command: 0 when asked for (``--help``, ``-h``, or the
    version), 2 when shown for a command missing (``seal``, ``seal bench``: typer's usage error)."""
    asked = {"--help", "-h", "--version"}
    return 0 if any(a in asked for a in sys.argv[1:]) else 2


def _quiet_arithmetic() -> None:
    """numpy's RuntimeWarnings (an overflow in a product of coordinates of 1e300) are no message for a
    user: the checks that follow say what is wrong with the input, at its line and column. Kept when
    the user asked for warnings (``-W``, ``PYTHONWARNINGS``)."""
    import warnings

    if not sys.warnoptions:
        warnings.simplefilter("ignore", RuntimeWarning)


def _closed_streams_to_null() -> None:
    """A standard output or error the command was started without (``>&-``) reads as ``/dev/null``:
    what is printed there is lost, as the caller asked, instead of failing the command."""
    for name in ("stdout", "stderr"):
        if getattr(sys, name) is None:
            setattr(sys, name, open(os.devnull, "w", encoding="utf-8"))  # noqa: SIM115 - lives as long as seal


def _stdout_to_null() -> None:
    """After a write to standard output failed: drop what is still buffered, so that the interpreter's
    exit does not fail again (and print a traceback) flushing it."""
    with contextlib.suppress(OSError, ValueError):
        os.dup2(os.open(os.devnull, os.O_WRONLY), sys.stdout.fileno())


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

    if not err.is_terminal:      # a log (a pipe, a file, CI): a line now and then once a run is long (rel33)
        yield Heartbeat(what)
        return
    with Progress(TextColumn(what), BarColumn(), MofNCompleteColumn(), TimeElapsedColumn(), TextColumn("left"),
                  TimeRemainingColumn(), console=err.console, transient=True) as progress:
        bar = progress.add_task(what, total=total)
        yield lambda done, total: progress.update(bar, completed=done, total=total)


HEARTBEAT_S = 60.0
"""Seconds between two progress lines of a long run whose stderr is no terminal (the first after as long)."""


class Heartbeat:
    """``advance(done, total)`` that says, on a stderr that is no terminal, how far a long run is, at most once
    every :data:`HEARTBEAT_S` seconds: ``updates: 1,200 of 100,020 after 1 min 0 s, about 83 h 20 min left
    (Ctrl-C stops it and writes nothing)``. A run shorter than that says nothing (tests and scripts see no
    line); ``seal localize --steps 100000`` in a log said nothing for hours (rel33)."""

    def __init__(self, what: str, every: float = HEARTBEAT_S, clock: Callable[[], float] | None = None) -> None:
        import time

        self.what, self.every, self.clock = what, every, clock or time.monotonic
        self.start = self.last = self.clock()

    def __call__(self, done: int, total: int) -> None:
        now = self.clock()
        if now - self.last < self.every or done <= 0:
            return
        self.last = now
        spent = now - self.start
        left = f", about {_duration(spent * (total - done) / done)} left" if total and done < total else ""
        err.print(f"{self.what}: {done:,} of {total:,} after {_duration(spent)}{left} (Ctrl-C stops it and writes "
                  "nothing)", markup=False, highlight=False)


def _duration(seconds: float) -> str:
    """``3 h 20 min``, ``1 min 5 s``, ``42 s``."""
    whole = int(round(seconds))
    hours, rest = divmod(whole, 3600)
    minutes, secs = divmod(rest, 60)
    if hours:
        return f"{hours:,} h {minutes} min"
    return f"{minutes} min {secs} s" if minutes else f"{secs} s"


def _unicode(stream: Any) -> bool:
    """Whether a stream's encoding holds every character (UTF-8, -16 or -32)."""
    encoding = (getattr(stream, "encoding", None) or "utf-8").lower().replace("-", "").replace("_", "")
    return encoding.startswith("utf")


MAX_COLUMNS = 1_000
"""The widest (and tallest) screen seal draws for. rich and typer take ``COLUMNS``, ``LINES`` and typer's
``TERMINAL_WIDTH`` as they come: ``COLUMNS=1000000000 seal --help`` drew its boxes a billion characters wide
(8.8 GB before it was killed), a usage error under ``COLUMNS=10000000`` was 70 MB of stderr."""

MIN_COLUMNS = 40
"""The narrowest screen seal draws for (a phone's terminal): under ``COLUMNS=1`` rich drew the tables and the help
as their borders alone (``││││││``), not a letter of what they hold (hostile19). A narrower width is taken as this."""
SIZE_VARIABLES = ("COLUMNS", "LINES", "TERMINAL_WIDTH")


def sane_sizes(environ: MutableMapping[str, str] = os.environ) -> None:
    """The screen's size as the environment gives it, made one seal can draw: a size past :data:`MAX_COLUMNS` is
    taken as that, a width under :data:`MIN_COLUMNS` as that; one that is no positive integer is dropped, as rich
    drops ``COLUMNS=abc`` (typer's own ``int(TERMINAL_WIDTH)`` of ``abc``, and rich's of ``COLUMNS`` or ``LINES``
    of 5,000 digits, were ``ValueError`` tracebacks before any command ran)."""
    for name in SIZE_VARIABLES:
        value = environ.get(name)
        if value is None:
            continue
        text = value.strip()
        if not (text.isascii() and text.isdigit()) or not text.strip("0"):
            del environ[name]
        elif len(text.lstrip("0")) > len(str(MAX_COLUMNS)) or int(text) > MAX_COLUMNS:
            environ[name] = str(MAX_COLUMNS)
        elif name != "LINES" and int(text) < MIN_COLUMNS:
            environ[name] = str(MIN_COLUMNS)


def plot_cache(environ: MutableMapping[str, str] = os.environ) -> str | None:
    """matplotlib's cache folder made one it can write: a ``MPLCONFIGDIR`` that is a file or a device (or a folder
    that cannot be written) made matplotlib rebuild its font cache in a new temporary folder on every run (30 s of a
    ``run --png``) and say so in two lines of its own (hostile29); it is then kept in seal's own cache folder
    (:func:`seal_cli.cache.folder`), and the warning to say is returned. A name that does not exist yet is left to
    matplotlib, which makes it; with seal's cache off, nothing changes."""
    given = environ.get("MPLCONFIGDIR")
    if not given or not os.path.lexists(given):
        return None
    if os.path.isdir(given) and os.access(given, os.W_OK | os.X_OK):
        return None
    from seal_cli import cache

    folder = cache.folder(environ)
    if folder is None:
        return None
    instead = folder / "matplotlib"
    environ["MPLCONFIGDIR"] = str(instead)
    return f"MPLCONFIGDIR {given} is not a folder seal can write: matplotlib's cache is kept in {instead} instead"


def own_renderers(environ: MutableMapping[str, str] = os.environ) -> None:
    """The environment's switches of the libraries seal writes its files with, set for files (rel33): matplotlib
    draws with Agg, whatever ``MPLBACKEND`` says (``MPLBACKEND=junk`` was a ``ValueError`` traceback on every
    ``--png``; seal shows no window), and Rerun records what ``--rrd`` asks, whatever ``RERUN`` says (``RERUN=off``,
    its switch for programs that log by default, made every ``--rrd`` a ``ValueError`` traceback: "No application
    id found")."""
    environ["MPLBACKEND"] = "agg"
    environ.pop("RERUN", None)


def printable_streams() -> None:
    """Standard output and error whose encoding cannot hold every character (``PYTHONIOENCODING=ascii``,
    a Latin-1 locale) write what they cannot hold as ``\\xe9`` escapes instead of failing the command
    with a UnicodeEncodeError; JSON on such an output escapes it as JSON does (:func:`dump_json`)."""
    for stream in (sys.stdout, sys.stderr):
        if stream is not None and not _unicode(stream):
            with contextlib.suppress(AttributeError, ValueError, OSError):
                stream.reconfigure(errors="backslashreplace")  # type: ignore[union-attr]


def _reader_left() -> None:
    global READER_GONE

    READER_GONE = True


class _WholeWrites(io.FileIO):
    """A standard stream's file descriptor whose ``write`` writes all it is given or raises: a short write (the
    disk fills, ``ulimit -f`` is reached, a pipe takes part) is followed by another for the rest, which then fails
    with the system's reason, and a stream left non-blocking by whoever started seal (``EAGAIN``) waits until it
    takes more, as a blocking one does. Python's own unbuffered text stream (``PYTHONUNBUFFERED=1``, ``python -u``)
    drops what a short write left and goes on (hostile20)."""

    def write(self, data: Any) -> int:
        view = memoryview(data).cast("B")
        done = 0
        while done < len(view):
            try:
                written = super().write(view[done:])
            except BrokenPipeError:
                _reader_left()
                raise
            if written is None:  # non-blocking and full: wait until it takes more
                import select  # only here: every line seal prints comes through this write

                select.select([], [self.fileno()], [])
                continue
            done += written
        return done


def whole_writes() -> None:
    """Standard output and error write everything a command prints, or fail the command with the system's reason
    (:class:`_WholeWrites`): under ``PYTHONUNBUFFERED=1`` (set by many containers and CI images) ``seal frames --json
    > out.json`` on a nearly full disk left 4,096 bytes of it and exited 0, and into a pipe its parent had made
    non-blocking ``seal parse --file F --json`` stopped at 64 KiB and exited 0 (buffered: exit 1, the output cut)."""
    for name in ("stdout", "stderr"):
        stream = getattr(sys, name)
        if type(stream) is not io.TextIOWrapper:  # not the interpreter's own (a test's capture, /dev/null)
            continue
        buffer = stream.buffer
        raw = buffer if isinstance(buffer, io.FileIO) else getattr(buffer, "raw", None)
        if type(raw) is not io.FileIO or isinstance(raw, _WholeWrites):
            continue
        with contextlib.suppress(OSError, ValueError):
            stream.flush()
            whole = _WholeWrites(raw.fileno(), "w", closefd=False)
            unbuffered = buffer is raw
            replaced = io.TextIOWrapper(whole if unbuffered else io.BufferedWriter(whole),
                                        encoding=stream.encoding, errors=stream.errors,
                                        line_buffering=stream.line_buffering, write_through=unbuffered)
            setattr(sys, name, replaced)


def dump_json(data: Any) -> str:
    """One JSON document as text for stdout: characters as they are on a UTF-8 output, ``\\u00e9``
    escapes on an output whose encoding cannot hold them (still the same JSON)."""
    import json

    if _unicode(sys.stdout):
        text = json.dumps(data, ensure_ascii=False)
        try:
            text.encode("utf-8")
        except UnicodeEncodeError:  # a lone surrogate: a command-line byte that is not UTF-8, echoed (hostile21)
            return json.dumps(data)   # written as \udce9, not as the raw byte (which made the JSON invalid UTF-8)
        return text
    return json.dumps(data, ensure_ascii=True)


def emit_json(data: Any) -> None:
    """One JSON document on stdout (nothing, when its reader has gone: :func:`reader_gone`)."""
    try:
        sys.stdout.write(dump_json(data) + "\n")
        sys.stdout.flush()
    except BrokenPipeError:
        reader_gone(sys.stdout)
