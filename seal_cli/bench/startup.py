"""What ``seal bench startup`` measures: the CPU a command line costs before it does anything.

Each figure is the median, over ``runs`` fresh interpreters, of the user + system CPU seconds the
child process used (``getrusage(RUSAGE_CHILDREN)``), so other work on the machine does not count.
The yardstick is a bare ``python -c pass``; the targets are ``seal --version`` ≤ 6× and
``seal parse TEXT`` ≤ 10× of it, in the usual, *warm* case: seal's cache (:mod:`seal_cli.cache`)
holds the read frame library and the word tables, as it does after the first command. Before
timing, each command runs once untimed, with Python allowed to write bytecode (as ``pip install``
compiles it), so that a checkout run with ``PYTHONDONTWRITEBYTECODE`` is not timed compiling
itself. The *cold* figure is ``seal parse TEXT`` with an empty cache of its own at every run (the
library read and checked, the tables sorted, both written). The *stages* are what a warm
``seal parse`` pays for, in order: the frame library, parsing one command with it (the language's
modules, the grammar, the tagger's tables, the parse), and the terminal library that prints the
tree; each is what it adds to the stages before it.
"""

from __future__ import annotations

import os
import resource
import statistics
import subprocess
import sys
import tempfile
from collections.abc import Callable, Mapping, Sequence
from typing import Any

__all__ = ["COMMAND", "TARGETS", "child_cpu", "measure"]

COMMAND = "bring me a cup from the kitchen"

TARGETS = {"version": 6.0, "parse": 10.0}
"""The largest ratio to a bare interpreter each command may cost."""

ENTRY = "from seal_cli.__main__ import main; main()"
"""What the ``seal`` console script runs."""


def child_cpu(argv: Sequence[str], runs: int, env: Mapping[str, str] | None = None) -> float:
    """The median user + system CPU seconds of ``runs`` runs of ``argv`` (output discarded)."""
    times = []
    for _ in range(runs):
        before = resource.getrusage(resource.RUSAGE_CHILDREN)
        subprocess.run(list(argv), stdin=subprocess.DEVNULL, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL,
                       check=True, env=None if env is None else dict(env))
        after = resource.getrusage(resource.RUSAGE_CHILDREN)
        times.append(after.ru_utime - before.ru_utime + after.ru_stime - before.ru_stime)
    return statistics.median(times)


def _python(code: str, *args: str) -> list[str]:
    return [sys.executable, "-c", code, *args]


def cold_cpu(argv: Sequence[str], runs: int) -> float:
    """The median CPU seconds of ``runs`` runs of ``argv``, each with an empty seal cache of its own."""
    times = []
    for _ in range(runs):
        with tempfile.TemporaryDirectory(prefix="seal-cold-") as empty:
            times.append(child_cpu(argv, 1, {**os.environ, "SEAL_CACHE_DIR": empty}))
    return statistics.median(times)


def warm_up(argv: Sequence[str]) -> None:
    """Run ``argv`` once, untimed, allowed to write bytecode: what the timed runs find is an installed
    seal's (compiled modules, a filled cache)."""
    env = {k: v for k, v in os.environ.items() if k != "PYTHONDONTWRITEBYTECODE"}
    subprocess.run(list(argv), stdin=subprocess.DEVNULL, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL,
                   check=True, env=env)


STAGES = {
    "frame library (from the cache)": "from seal_cli.frames.reading import load_library; load_library()",
    "parser: modules, grammar, tagger tables, one parse": f"from seal_cli.language.parser import parse_command; "
                                                          f"parse_command({COMMAND!r}, load_library())",
    "rich: console and tree": "import rich.console, rich.tree",
}
"""What a warm ``seal parse`` pays for, in the order it pays; each stage is measured with the ones
before it, and its figure is what it adds."""


def measure(runs: int = 20, progress: Callable[[str], None] | None = None) -> dict[str, Any]:
    """CPU seconds of a bare interpreter, ``seal --version`` and ``seal parse TEXT``, their ratios, and the stages."""
    say = progress or (lambda text: None)
    say("a bare interpreter")
    bare = child_cpu(_python("pass"), runs)
    say("seal --version")
    warm_up(_python(ENTRY, "--version"))
    commands = {"version": child_cpu(_python(ENTRY, "--version"), runs)}
    say("seal parse TEXT")
    warm_up(_python(ENTRY, "parse", COMMAND))
    commands["parse"] = child_cpu(_python(ENTRY, "parse", COMMAND), runs)
    say("seal parse TEXT, cold (an empty cache at every run)")
    cold = cold_cpu(_python(ENTRY, "parse", COMMAND), runs)
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
            "cold": {"parse": {"cpu_s": cold, "ratio": cold / bare}},
            "stages_s": stages}
