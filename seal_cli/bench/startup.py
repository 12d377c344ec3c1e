"""What ``seal bench startup`` measures: the CPU a command line costs before it does anything.

Each figure is the median, over ``runs`` fresh interpreters, of the user + system CPU seconds the
child process used (``getrusage(RUSAGE_CHILDREN)``), so other work on the machine does not count.
The yardstick is a bare ``python -c pass``; the targets are ``seal --version`` ≤ 6× and
``seal parse TEXT`` ≤ 10× of it. The *stages* are what a ``seal parse`` pays for, in order: the command-line
framework, the terminal library, reading the frame library, and parsing one command with it (the
tagger's tables, the grammar, the parse); each is what it adds to the stages before it.
"""

from __future__ import annotations

import resource
import statistics
import subprocess
import sys
from collections.abc import Callable, Sequence
from typing import Any

__all__ = ["COMMAND", "TARGETS", "child_cpu", "measure"]

COMMAND = "bring me a cup from the kitchen"

TARGETS = {"version": 6.0, "parse": 10.0}
"""The largest ratio to a bare interpreter each command may cost."""

ENTRY = "from seal_cli.__main__ import main; main()"
"""What the ``seal`` console script runs."""


def child_cpu(argv: Sequence[str], runs: int) -> float:
    """The median user + system CPU seconds of ``runs`` runs of ``argv`` (output discarded)."""
    times = []
    for _ in range(runs):
        before = resource.getrusage(resource.RUSAGE_CHILDREN)
        subprocess.run(list(argv), stdin=subprocess.DEVNULL, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL,
                       check=True)
        after = resource.getrusage(resource.RUSAGE_CHILDREN)
        times.append(after.ru_utime - before.ru_utime + after.ru_stime - before.ru_stime)
    return statistics.median(times)


def _python(code: str, *args: str) -> list[str]:
    return [sys.executable, "-c", code, *args]


STAGES = {
    "typer": "import typer",
    "rich": "import rich.console, rich.tree",
    "frame library": "from seal_cli.frames.reading import load_library; load_library()",
    "parser: tagger tables, grammar, one parse": f"from seal_cli.language.parser import parse_command; "
                                                 f"parse_command({COMMAND!r}, load_library())",
}
"""What ``seal parse`` pays for, in the order it pays; each stage is measured with the ones before it,
and its figure is what it adds."""


def measure(runs: int = 20, progress: Callable[[str], None] | None = None) -> dict[str, Any]:
    """CPU seconds of a bare interpreter, ``seal --version`` and ``seal parse TEXT``, their ratios, and the stages."""
    say = progress or (lambda text: None)
    say("a bare interpreter")
    bare = child_cpu(_python("pass"), runs)
    say("seal --version")
    commands = {"version": child_cpu(_python(ENTRY, "--version"), runs)}
    say("seal parse TEXT")
    commands["parse"] = child_cpu(_python(ENTRY, "parse", COMMAND), runs)
    stages, before, code = {}, bare, ""
    for name, step in STAGES.items():
        say(f"stage: {name}")
        code = f"{code}; {step}" if code else step
        total = child_cpu(_python(code), runs)
        stages[name] = max(0.0, total - before)
        before = total
    return {"runs": runs, "python_s": bare,
            "commands": {name: {"cpu_s": cpu, "ratio": cpu / bare, "target": TARGETS[name],
                                "ok": cpu / bare <= TARGETS[name]} for name, cpu in commands.items()},
            "stages_s": stages}
