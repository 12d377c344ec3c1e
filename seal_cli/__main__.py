"""The entry point of ``seal`` and ``python -m seal_cli``.

``seal --version`` is answered here, before the command line's framework is imported: typer alone
costs about five times a bare interpreter's start-up (measured by ``seal bench startup``), and a
version check should cost nothing. Everything else goes to :data:`seal_cli.cli.app`.

Python's cyclic garbage collector is kept out of a command's start and end, which it would only
slow: the modules, grammars and tables a command line loads live as long as its process, so the
collections their making triggers (each a pass over everything made so far) find nothing, and at
exit the interpreter's last collection passes over all of them once more, before the process's
memory is handed back whole (a quarter of ``seal parse``'s CPU, ``seal bench startup``). The
collector is off while the command line is set up; what that made is then frozen (:func:`gc.freeze`:
left out of later collections) and the collector runs as usual through the command, but for
``seal parse TEXT``, one command of bounded size, which runs without it. What is alive when the
command has finished is frozen too, so exit skips the pass.
Nothing a command writes waits on the collector: outputs are renamed into place, and temporaries
removed, before the command returns (:mod:`seal_cli.fileio`).

An interrupt (Ctrl-C, SIGINT) while the command line is still being imported, before a command runs
(a second or more on a loaded machine), ends seal as one during a command does: ``interrupted``,
exit code 130, no traceback; one after the command has finished (its outputs in place) leaves the command's
own exit code, and one while the interpreter shuts down is ignored. Standard streams whose encoding cannot
hold every character (``PYTHONIOENCODING=ascii``, a Latin-1 terminal) are set up first
(:func:`seal_cli.cli.output.printable_streams`), and a screen size no one can draw (``COLUMNS`` of a billion,
``TERMINAL_WIDTH=abc``) is bounded or dropped (:func:`seal_cli.cli.output.sane_sizes`), and a matplotlib cache
folder that is none (``MPLCONFIGDIR=/dev/null``) replaced by seal's, with a warning
(:func:`seal_cli.cli.output.plot_cache`).
"""

from __future__ import annotations

import gc
import sys


def main() -> None:
    if sys.argv[1:] == ["--version"]:
        _version()
        return
    enabled = gc.isenabled()
    gc.disable()
    try:
        from seal_cli.cli.output import own_renderers, plot_cache, printable_streams, sane_sizes, whole_writes
        from seal_cli.fileio import note_interrupts

        note_interrupts()
        whole_writes()
        printable_streams()
        sane_sizes()
        said = plot_cache()
        own_renderers()
        if said:
            sys.stderr.write(f"warning: {said}\n")
        from seal_cli.cli import main as run
        from seal_cli.cli import plain_parse

        if enabled and plain_parse(sys.argv[1:]) is None:
            gc.freeze()
            gc.enable()
        run()
    except SystemExit as end:
        _end_now_if_interrupted(end.code)
        raise
    except KeyboardInterrupt:  # before a command ran (importing): as during one; after it ended: its own code
        from seal_cli.cli import output
        from seal_cli.fileio import remove_temporaries

        if output.FINISHED is not None:
            sys.exit(output.FINISHED)
        remove_temporaries()
        sys.stderr.write("interrupted\n")
        _end_now_if_interrupted(130)
        sys.exit(130)
    except Exception:
        from seal_cli.fileio import interrupted, remove_temporaries

        if not interrupted():
            raise
        remove_temporaries()  # an interrupt inside an extension's import: ImportError "initialization failed"
        sys.stderr.write("interrupted\n")
        _end_now_if_interrupted(130)
        sys.exit(130)
    finally:
        gc.freeze()  # the command has finished: the process ends without a last pass over its objects
        _ignore_late_signals()


def _end_now_if_interrupted(code: object) -> None:
    """After SIGINT, end the process with ``code`` at once, its streams flushed, without freeing what the interrupt
    left: an interrupt inside numba's compiling leaves llvmlite objects half built, and freeing one (its ``__del__``,
    when the interrupt's traceback went, or at the interpreter's exit) was a segmentation fault: exit -11, not 130,
    once in 48 interrupted ``localize --goals`` under load with numba's cache empty (hostile24)."""
    import contextlib
    import os

    from seal_cli.fileio import interrupted

    if not interrupted():
        return
    for stream in (sys.stdout, sys.stderr):
        with contextlib.suppress(Exception):
            if stream is not None:
                stream.flush()
    os._exit(code if isinstance(code, int) else 0 if code is None else 1)


def _version() -> None:
    """``seal --version``, answered without the framework, fails as a command's output does (hostile21): with its
    standard output closed (``>&-``: ``sys.stdout`` is None) it was an ``AttributeError`` traceback, onto a full disk
    an ``OSError`` one; now the first writes nowhere (as onto ``/dev/null``), the second says ``error: cannot write
    the output: No space left on device``, exit code 1, and a reader that has gone leaves exit code 0."""
    from seal_cli import __version__

    if sys.stdout is None:
        return
    try:
        sys.stdout.write(f"seal {__version__}\n")
        sys.stdout.flush()
    except BrokenPipeError:
        from seal_cli.cli.output import reader_gone

        reader_gone(sys.stdout)
    except OSError as error:
        from seal_cli.cli.output import output_failed

        sys.exit(output_failed(error))


def _ignore_late_signals() -> None:
    """The command has ended and its exit code is chosen: SIGINT, SIGTERM and SIGHUP are ignored while the
    interpreter shuts down (one there was a traceback from ``threading._shutdown``, or ended the process as
    killed by SIGINT after it had written its output)."""
    import contextlib
    import signal

    for number in (signal.SIGINT, signal.SIGTERM, signal.SIGHUP):
        with contextlib.suppress(ValueError, OSError, AttributeError):
            signal.signal(number, signal.SIG_IGN)


if __name__ == "__main__":
    main()
