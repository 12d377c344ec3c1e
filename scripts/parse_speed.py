"""How fast two trees of seal parse one corpus in process, measured side by side on a shared, noisy machine.

    python scripts/parse_speed.py OLD_TREE NEW_TREE --corpus FILE [--constants FILE] [--rounds 5] [--chunk 100]

Each tree parses in a worker process of its own (``PYTHONPATH`` its tree), as ``seal bench parse`` does in process:
its parser, then 200 commands to warm up. The corpus is then parsed ``--rounds`` times by both, ``--chunk`` commands
at a time, the two workers taking turns (which one goes first alternates), and the CPU time (``time.process_time``)
of each chunk summed per round: what the other processes of the machine take from one tree they take from the other
within a fraction of a second, where two ``seal bench parse`` runs a minute apart see different loads. Prints each
round's commands per CPU-second and the ratio NEW / OLD, then the medians. An ALFRED goals table (``.tsv``) is parsed
with ALFRED's classes as the vocabulary (``--constants``, the ``OBJECTS`` of ``alfred_constants.json``). Exit 2 on
bad input.
"""

from __future__ import annotations

import argparse
import os
import statistics
import subprocess
import sys
from pathlib import Path

WORKER = """
import contextlib, json, sys, time
from pathlib import Path
from seal_cli.bench.parsing import commands_of
from seal_cli.errors import SealError
from seal_cli.frames.reading import load_library
from seal_cli.language.parser import CommandParser
corpus, constants = Path(sys.argv[1]), sys.argv[2]
texts = commands_of(corpus)
vocabulary = None
if corpus.suffix == ".tsv":
    from seal_cli.language.grounding import Vocabulary
    classes = json.loads(Path(constants).read_text(encoding="utf-8"))["OBJECTS"]
    vocabulary = Vocabulary.of([str(c) for c in classes])
parser = CommandParser.of(load_library())
for text in texts[:200]:
    with contextlib.suppress(SealError):
        parser.parse(text, vocabulary)
print(len(texts), flush=True)
for line in sys.stdin:
    start, end = map(int, line.split())
    begun = time.process_time()
    for text in texts[start:end]:
        with contextlib.suppress(SealError):
            parser.parse(text, vocabulary)
    print(time.process_time() - begun, flush=True)
"""
"""The worker each tree runs: its commands' count once warmed up, then the CPU seconds of each chunk it is asked."""


def worker(tree: Path, corpus: Path, constants: Path) -> subprocess.Popen[str]:
    return subprocess.Popen([sys.executable, "-c", WORKER, str(corpus.resolve()), str(constants.resolve())],
                            cwd=tree, env={**os.environ, "PYTHONPATH": str(tree)}, text=True,
                            stdin=subprocess.PIPE, stdout=subprocess.PIPE)


def ask(process: subprocess.Popen[str], line: str | None = None) -> float:
    """Send ``line`` (a chunk "start end") and read the answer (a count or CPU seconds)."""
    assert process.stdin is not None and process.stdout is not None
    if line is not None:
        process.stdin.write(line + "\n")
        process.stdin.flush()
    answer = process.stdout.readline()
    if not answer:
        raise SystemExit(f"a worker stopped (exit {process.wait()})")
    return float(answer)


def measure(processes: list[subprocess.Popen[str]], size: int, rounds: int, chunk: int) -> list[list[float]]:
    """Commands per CPU-second of each tree in each round (see the module docstring)."""
    figures: list[list[float]] = [[], []]
    for round_ in range(rounds):
        spent = [0.0, 0.0]
        for number, start in enumerate(range(0, size, chunk)):
            for k in (0, 1) if (number + round_) % 2 == 0 else (1, 0):
                spent[k] += ask(processes[k], f"{start} {min(size, start + chunk)}")
        for k in (0, 1):
            figures[k].append(size / spent[k] if spent[k] > 0 else float("inf"))
        print(f"round {round_ + 1}: old {figures[0][-1]:,.0f}  new {figures[1][-1]:,.0f} commands/CPU-s  "
              f"ratio {figures[1][-1] / figures[0][-1]:.3f}", flush=True)
    return figures


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("old", type=Path, help="a tree (a checkout: PYTHONPATH for its seal_cli)")
    parser.add_argument("new", type=Path)
    parser.add_argument("--corpus", type=Path, required=True, help="JSON Lines with 'text', or an ALFRED goals .tsv")
    parser.add_argument("--constants", type=Path, help="ALFRED's alfred_constants.json (for a .tsv corpus)")
    parser.add_argument("--rounds", type=int, default=5)
    parser.add_argument("--chunk", type=int, default=100, help="commands per turn")
    args = parser.parse_args(argv)
    for tree in (args.old, args.new):
        if not (tree / "seal_cli" / "__init__.py").is_file():
            parser.error(f"{tree}: no seal_cli package in this tree")
    if not args.corpus.is_file():
        parser.error(f"--corpus {args.corpus}: no such file")
    if args.corpus.suffix == ".tsv" and (args.constants is None or not args.constants.is_file()):
        parser.error("an ALFRED goals table is parsed with ALFRED's classes: give --constants alfred_constants.json")
    if args.rounds < 1 or args.chunk < 1:
        parser.error("--rounds and --chunk are counts of at least 1")
    processes = [worker(tree.resolve(), args.corpus, args.constants or args.corpus) for tree in (args.old, args.new)]
    try:
        sizes = [int(ask(p)) for p in processes]
        if sizes[0] != sizes[1] or not sizes[0]:
            raise SystemExit(f"the trees read {sizes[0]} and {sizes[1]} commands from the corpus")
        old, new = measure(processes, sizes[0], args.rounds, args.chunk)
    finally:
        for process in processes:
            if process.stdin is not None:
                process.stdin.close()
            process.wait()
    ratios = [b / a for a, b in zip(old, new, strict=True)]
    print(f"median: old {statistics.median(old):,.0f}  new {statistics.median(new):,.0f} commands/CPU-s; ratio of the "
          f"medians {statistics.median(new) / statistics.median(old):.3f}, median of the rounds' ratios "
          f"{statistics.median(ratios):.3f} (n={sizes[0]}, {args.rounds} rounds of chunks of {args.chunk})")
    return 0


if __name__ == "__main__":
    sys.exit(main())
