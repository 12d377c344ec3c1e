"""``seal bench reliability``: seal run as a hostile user runs it, counting what went wrong.

Every case is one ``seal`` command run as a subprocess in a fresh folder, with a timeout. The
cases are the defects of issue 14 replayed one by one, and hostile inputs generated from a seed:
broken frame files, maps and observation files made by mutating good ones, hostile command
texts, output paths that are inputs, devices, folders or wrong suffixes, out-of-bound options,
and signals sent during a run. A case counts

- a **traceback** when ``Traceback (most recent call last)`` reaches stderr;
- a **hang** when it does not finish within its timeout;
- a **wrong exit code** when its code is not one the case allows (0 or 1 for a bad input, 2 for
  a bad option, 143 after SIGTERM, ...);
- a **lost or partial file** when an input changed, a temporary of ours was left behind, an
  output the case forbids exists, or a failed command left any new file;
- **nondeterminism** when a case marked ``twice`` gives other output on a second run;
- an **unclear message** when a refusal (exit code 1 or 2) says nothing on stderr, or not what
  the case says it must (``Case.says``: the file, line and column, or the option).

A reliable seal counts zero of each; only ``tried`` grows.
"""

from __future__ import annotations

import contextlib
import hashlib
import os
import random
import re
import select
import signal
import subprocess
import sys
import tempfile
import time
from collections.abc import Callable, Iterator
from concurrent.futures import ThreadPoolExecutor
from dataclasses import dataclass, field
from pathlib import Path

__all__ = ["Case", "Outcome", "generated_cases", "hostile_cases", "issue_cases", "run_case", "run_cases",
           "summarise"]

TIMEOUT = 60.0
"""Seconds any case may take (the bound every command must finish or refuse within)."""

TRACEBACK = "Traceback (most recent call last)"
TEMPORARY = re.compile(r"\.seal\d+-[0-9a-f]{8}\.tmp")

FRAME = '''category container = cup, bowl
category utensil = spoon, fork
world holding, hand_empty
frame Whisk "whisk" "beat" {
  description "Whisk what is in a container."
  theme: container
  instrument: utensil = spoon
  requires holding(instrument)
  do navigate(theme), stir(instrument, theme)
  ensures whisked(theme)
}
'''

FRAME_YAML = '''categories:
  container: [cup, bowl]
  utensil: [spoon, fork]
world: [holding, hand_empty]
frames:
  - frame: Whisk
    lexical_units: [whisk, beat]
    elements:
      theme: {type: container}
      instrument: {type: utensil, default: spoon}
    preconditions: [holding(instrument)]
    actions: [navigate(theme), stir(instrument, theme)]
    postconditions: [whisked(theme)]
'''

OBSERVATIONS = '''- pose: [-6.0, -3.0, 0.0]
  detections:
    - {class: cup, at: [-5.0, -3.0]}
- pose: [5.0, -4.5]
  detections: []
'''

HOSTILE_CHARS = ["\t", "\x00", "\\q", "\u2028", "\ufeff", "{", "}", "(", ")", ":", ",", "=", '"', "'", "*", "&a",
                 "*a", "!!python/object:os.system", "\r", "\x1c", "é", "-", "[", "]", "#", "%", "\\", "9" * 30,
                 "nan", ".inf", "~", "null", "@@"]
HOSTILE_WORDS = ["stir", "the", "cup", "café", "put", "99999999999", "apples", "in", "fridge", "and", "it", "\x01",
                 "\u2028", "\t", "pick", "up", "spoon", "😀", "ʼ", "not", "1e308", "-5", "two", "bring", "me", "a",
                 "(", ")", "[bold]", "\\", "NaN", "0", "sofa", "open", "table", "knife", "\r"]


@dataclass(frozen=True)
class Case:
    """One command to run in a fresh folder holding ``files``, and what it may do.

    A file's content is bytes, or ``"fifo"`` for a named pipe, ``"dir"`` for a folder, or ``"link:TARGET"`` for a
    symbolic link, or ``"hard:TARGET"`` for a hard link, or ``"ro-dir"`` for a read-only folder.
    ``keep``: files that must be unchanged after; ``absent``: files that must not exist after;
    ``signal``: send it this many seconds after the start."""

    name: str
    argv: tuple[str, ...]
    files: tuple[tuple[str, bytes | str], ...] = ()
    codes: tuple[int, ...] = (0, 1)
    keep: tuple[str, ...] = ()
    absent: tuple[str, ...] = ()
    twice: bool = False
    signal: tuple[int, float] | None = None
    stdin: bytes | None = None
    timeout: float = TIMEOUT
    parallel: int = 1
    """Run this many copies at once in the same folder (concurrent writers of one output)."""
    whole: tuple[str, ...] = ()
    """Files that must exist after and be complete (a PNG to its IEND, JSON that parses)."""
    says: str | None = None
    """A pattern the command's messages (stderr, and stdout for ``seal validate``'s listing) must
    hold: when it refuses (exit code 1 or 2), its refusal's shape (``file:line:col:``, the option's
    name); for a case that must succeed (``codes == (0,)``), its warning."""
    stream: str = ""
    """Standard streams made hostile: ``closed-stdin``, ``closed-stdout``, ``closed-stderr``,
    ``full-stdout`` (``/dev/full``: every write fails), ``open-stdin`` (a pipe nobody writes to),
    ``file-stdout`` (into the case's file ``stdout.out``, which the case makes so that it is no new file),
    ``nonblocking-stdout`` (a pipe made non-blocking, as some parents leave it, read only once it is full or the
    command has ended: a write then finds it full and must wait, not fail nor drop what it could not write),
    ``gone-stdout`` (a pipe whose reader has gone before the command writes, as ``| head -c1`` leaves it: every
    write fails with ``EPIPE``)."""
    file_blocks: int = 0
    """The largest file the command may write, in 512-byte blocks (``ulimit -f``, ``RLIMIT_FSIZE``); 0: no limit."""
    env: tuple[tuple[str, str], ...] = ()
    """Environment variables set (or, with the value ``"<unset>"``, removed) for the command, after the
    suite's own (``COLUMNS=200``, ``NO_COLOR=1``, ``PYTHONWARNINGS=ignore``)."""
    to_worker: bool = False
    """Send ``signal`` to a forked worker of the command (of a ``--jobs N`` pool, as the kernel's out-of-memory
    killer picks one), once it has one, rather than to the command itself."""
    signal_on: str = ""
    """Send ``signal`` only once a file whose name matches this pattern is in the case's folder (the command's
    temporary output, while it is being written); never, if the command ends first."""
    ignored: tuple[int, ...] = ()
    """Signals the command starts with ignored, as ``nohup`` starts it (SIGHUP) or a script's background job
    (SIGINT): a shell's ``trap '' ...`` before it runs."""
    cwd: str = ""
    """The folder of the case's files to run the command in (a ``ro-dir``: a read-only working folder); the case's
    folder itself when empty."""
    vanish: tuple[str, str] | tuple[()] = ()
    """(folder, pattern): remove that folder of the case's files, with all it holds, once a file whose name matches
    the pattern is in it (the command's temporary output, while it is being written): a folder deleted under a
    running command."""
    unsaid: str | None = None
    """A pattern the command's messages must *not* hold, whatever it ends with (a Python warning naming seal's
    source, ``UserWarning: Tight layout not applied``, where the case unsets the suite's ``PYTHONWARNINGS``)."""
    remove_cwd: bool = False
    """Remove the working folder (``cwd``, an empty folder of the case's files) just before seal starts in it:
    ``cd d; rm -r ../d; seal ...``, a relative name then names nothing (hostile28)."""


@dataclass
class Outcome:
    """What one case did."""

    case: str
    code: int | None
    seconds: float
    problems: list[str] = field(default_factory=list)

    @property
    def kinds(self) -> set[str]:
        return {p.split(":", 1)[0] for p in self.problems}


# -- running ------------------------------------------------------------------------------------
def _make(folder: Path, files: tuple[tuple[str, bytes | str], ...]) -> None:
    for name, content in files:
        path = folder / name
        path.parent.mkdir(parents=True, exist_ok=True)
        if content == "fifo":
            os.mkfifo(path)
        elif content == "dir":
            path.mkdir(parents=True, exist_ok=True)
        elif content == "ro-dir":
            path.mkdir(parents=True, exist_ok=True)
            path.chmod(0o555)
        elif isinstance(content, str) and content.startswith("link:"):
            path.symlink_to(content[5:])
        elif isinstance(content, str) and content.startswith("hard:"):
            os.link(folder / content[5:], path)
        elif isinstance(content, bytes):
            path.write_bytes(content)


def _digest(path: Path) -> str | None:
    try:
        return hashlib.sha256(path.read_bytes()).hexdigest() if path.is_file() else None
    except OSError:
        return None


def _listing(folder: Path) -> set[str]:
    return {str(p.relative_to(folder)) for p in folder.rglob("*")}


def _seal() -> list[str]:
    return [sys.executable, "-m", "seal_cli"]


def _complete(path: Path) -> bool:
    """Whether an output file is whole: a PNG ends with its IEND chunk, JSON and YAML parse, PDDL balances."""
    import json

    import yaml

    try:
        data = path.read_bytes()
    except OSError:
        return False
    if path.suffix == ".png":
        return data.startswith(b"\x89PNG\r\n\x1a\n") and data.endswith(b"IEND\xaeB`\x82")
    try:
        if path.suffix == ".json":
            json.loads(data)
        elif path.suffix == ".jsonl":
            [json.loads(line) for line in data.splitlines() if line.strip()]
        elif path.suffix == ".yaml":
            yaml.safe_load(data)
        elif path.suffix == ".pddl":
            return _pddl(data.decode("utf-8"))
    except (ValueError, yaml.YAMLError):
        return False
    return bool(data)


def _pddl(text: str) -> bool:
    """Whether a PDDL file is one ``(define ...)`` whose parentheses balance, once its ``;`` comments are cut."""
    code = "\n".join(line.split(";", 1)[0] for line in text.splitlines()).strip()
    depth = 0
    for c in code:
        depth += {"(": 1, ")": -1}.get(c, 0)
        if depth < 0:
            return False
    return code.startswith("(define") and depth == 0


def _parallel(case: Case, folder: Path) -> tuple[int | None, bytes, bytes, float]:
    """Run ``case.parallel`` copies at once; the worst exit code (None if any hung) and all stderr."""
    runs: list[tuple[int | None, bytes, bytes, float]] = []
    with ThreadPoolExecutor(case.parallel) as pool:
        for run in pool.map(lambda _: _one(case, folder), range(case.parallel)):
            runs.append(run)
    codes = [r[0] for r in runs]
    bad = [c for c in codes if c is None or c not in case.codes]
    code = None if None in codes else (bad[0] if bad else codes[0])
    return code, b"".join(r[1] for r in runs), b"".join(r[2] for r in runs), max(r[3] for r in runs)


def _once(case: Case, folder: Path) -> tuple[int | None, bytes, bytes, float]:
    return _parallel(case, folder) if case.parallel > 1 else _one(case, folder)


STREAMS = {"closed-stdin": "<&-", "closed-stdout": ">&-", "closed-stderr": "2>&-", "full-stdout": ">/dev/full",
           "file-stdout": ">stdout.out", "open-stdin": "", "nonblocking-stdout": "", "gone-stdout": "", "": ""}
"""The shell redirection of each hostile ``Case.stream``."""


def _one(case: Case, folder: Path) -> tuple[int | None, bytes, bytes, float]:
    env = {**os.environ, "COLUMNS": "200", "NO_COLOR": "1", "PYTHONWARNINGS": "ignore", **dict(case.env)}
    env = {name: value for name, value in env.items() if value != "<unset>"}
    start = time.perf_counter()
    argv = [*_seal(), *(a.replace("\x00", "\x01") for a in case.argv)]  # no shell can pass a NUL in an argument
    if STREAMS[case.stream] or case.file_blocks or case.ignored or case.remove_cwd:
        limit = f"ulimit -f {case.file_blocks}; " if case.file_blocks else ""  # POSIX sh: 512-byte blocks
        trap = f"trap '' {' '.join(str(n) for n in case.ignored)}; " if case.ignored else ""
        gone = 'rmdir "$PWD" && ' if case.remove_cwd else ""
        argv = ["/bin/sh", "-c", f'{limit}{trap}{gone}exec "$@" {STREAMS[case.stream]}', "sh", *argv]
    piped = case.stdin is not None or case.stream == "open-stdin"
    if case.stream == "nonblocking-stdout":
        return _nonblocking(case, argv, folder, env, start)
    stdout: int = subprocess.PIPE
    if case.stream == "gone-stdout":  # a pipe whose reader has gone: every write fails with EPIPE
        reader, stdout = os.pipe()
        os.close(reader)
    try:
        process = subprocess.Popen(argv, cwd=folder / case.cwd, env=env, stdout=stdout,
                                   stderr=subprocess.PIPE, stdin=subprocess.PIPE if piped
                                   else subprocess.DEVNULL, start_new_session=True)
    finally:
        if stdout != subprocess.PIPE:
            os.close(stdout)
    try:
        if case.vanish:
            _remove_when(process, folder / case.vanish[0], case.vanish[1])
        if case.signal is not None:
            number, delay = case.signal
            if _wait_to_signal(process, delay) and _wait_for_file(process, folder, case.signal_on):
                _send(process, number, case.to_worker)
        out, err = process.communicate(case.stdin, timeout=case.timeout)
    except subprocess.TimeoutExpired:
        os.killpg(process.pid, signal.SIGKILL)
        out, err = process.communicate()
        return None, out or b"", err, time.perf_counter() - start
    return process.returncode, out or b"", err, time.perf_counter() - start


def _nonblocking(case: Case, argv: list[str], folder: Path, env: dict[str, str],
                 start: float) -> tuple[int | None, bytes, bytes, float]:
    """Run a case whose standard output is a non-blocking pipe, read only once the pipe is full and the command
    has written nothing more for a quarter of a second (or it has ended), so that the command's writes find it full
    (``Case.stream`` ``nonblocking-stdout``)."""
    import fcntl
    import termios

    reader, writer = os.pipe()
    os.set_blocking(writer, False)
    with tempfile.TemporaryFile() as errors:
        process = subprocess.Popen(argv, cwd=folder, env=env, stdout=writer, stderr=errors,
                                   stdin=subprocess.DEVNULL, start_new_session=True)
        os.close(writer)
        held, last, since = bytearray(4), -1, time.perf_counter()
        while process.poll() is None and time.perf_counter() - start < case.timeout:
            fcntl.ioctl(reader, termios.FIONREAD, held)
            now, count = time.perf_counter(), int.from_bytes(held, sys.byteorder)
            if count != last:
                last, since = count, now
            elif count > PIPE_FULL - PIPE_BUF and now - since >= 0.25:  # full to the writer, and it writes no more
                break
            time.sleep(0.01)
        chunks = []
        deadline = start + case.timeout
        try:
            while time.perf_counter() < deadline:
                if not select.select([reader], [], [], 0.1)[0]:
                    continue
                chunk = os.read(reader, 1 << 16)
                if not chunk:
                    break
                chunks.append(chunk)
        finally:
            os.close(reader)
        try:
            code: int | None = process.wait(max(0.1, deadline - time.perf_counter()))
        except subprocess.TimeoutExpired:
            os.killpg(process.pid, signal.SIGKILL)
            process.wait()
            code = None
        errors.seek(0)
        return code, b"".join(chunks), errors.read(), time.perf_counter() - start


PIPE_FULL = 65_536
"""Bytes a Linux pipe holds by default."""

PIPE_BUF = 4_096
"""Bytes a write into a pipe puts in at once or not at all: a non-blocking write of that many or fewer into a pipe
with less room fails with ``EAGAIN``, so a pipe holding more than ``PIPE_FULL - PIPE_BUF`` may be full to its
writer."""

SIGNAL_CPU = 0.05
"""CPU seconds a process has used before a case's signal is sent to it (besides the case's own delay): the
interpreter's own start-up and ``import seal_cli`` (20–30 ms of CPU here) are over by then, and a signal
there ends Python with a traceback no program can catch, before any of seal's code runs; seal's command
line is still importing (until about 0.06 s), which is what the outsider's cases interrupt. Counted in
CPU time (``/proc``, 10 ms ticks), not wall-clock time, so that a loaded machine, where start-up takes
longer, moves neither edge."""


def _cpu_seconds(pid: int) -> float | None:
    """User and system CPU time of a running process (from ``/proc``), None where it cannot be read."""
    try:
        fields = Path(f"/proc/{pid}/stat").read_text().rsplit(")", 1)[1].split()
        return (int(fields[11]) + int(fields[12])) / os.sysconf("SC_CLK_TCK")
    except (OSError, ValueError, IndexError):
        return None


def _wait_to_signal(process: subprocess.Popen[bytes], delay: float) -> bool:
    """Wait ``delay`` seconds and until the process has used :data:`SIGNAL_CPU` of CPU; whether it still runs."""
    start = time.perf_counter()
    while process.poll() is None:
        cpu = _cpu_seconds(process.pid)
        if time.perf_counter() - start >= delay and (cpu is None or cpu >= SIGNAL_CPU):
            return True
        time.sleep(0.005)
    return False


def _wait_for_file(process: subprocess.Popen[bytes], folder: Path, pattern: str) -> bool:
    """Wait until a file whose name matches ``pattern`` is in ``folder`` (at once without a pattern); whether the
    process still runs."""
    found = re.compile(pattern) if pattern else None
    while process.poll() is None:
        if found is None or any(found.search(name) for name in os.listdir(folder)):
            return True
        time.sleep(0.001)
    return False


def _remove_when(process: subprocess.Popen[bytes], folder: Path, pattern: str) -> None:
    """Remove ``folder`` and all it holds once a file whose name matches ``pattern`` is in it (``Case.vanish``);
    nothing if the process ends first."""
    import shutil

    found = re.compile(pattern)
    while process.poll() is None:
        with contextlib.suppress(OSError):
            if any(found.search(name) for name in os.listdir(folder)):
                shutil.rmtree(folder, ignore_errors=True)
                return
        time.sleep(0.001)


def _workers(pid: int) -> list[int]:
    """The process ids of a running process's forked workers: its children with its own command line (from
    ``/proc``; not a helper it runs, such as ``uname`` for :mod:`platform`; none where it cannot be read)."""
    try:
        children = [int(child) for child in Path(f"/proc/{pid}/task/{pid}/children").read_text().split()]
        own = Path(f"/proc/{pid}/cmdline").read_bytes()
    except (OSError, ValueError):
        return []
    found = []
    for child in children:
        with contextlib.suppress(OSError):
            if Path(f"/proc/{child}/cmdline").read_bytes() == own:
                found.append(child)
    return found


def _send(process: subprocess.Popen[bytes], number: int, to_worker: bool) -> None:
    """Send signal ``number`` to the process, or (``to_worker``) to its first forked worker once it has one (none
    while it still runs: nothing is sent)."""
    if not to_worker:
        process.send_signal(number)
        return
    while process.poll() is None:
        workers = _workers(process.pid)
        if workers:
            with contextlib.suppress(ProcessLookupError):
                os.kill(workers[0], number)
            return
        time.sleep(0.01)


@contextlib.contextmanager
def _signals_reach_cases() -> Iterator[None]:
    """While the cases run, SIGINT, SIGHUP and SIGTERM that this process was started with ignored are caught by a
    handler that does nothing: this process still ignores them, but a command it starts begins with them at their
    default (a caught signal is reset by ``exec``, an ignored one is inherited), as at a terminal. Started in a
    shell's background (``nohup ... &``, CI's steps), the judge passed SIGINT ignored to every case: "a signal 2
    while run --png --rrd writes its temporary" then ran to its end and wrote both outputs, 10 times in 10 (the
    flaky case of hostile24), and every SIGINT case with it. A case that wants one ignored says so
    (``Case.ignored``). Nothing changes outside the main thread, where handlers cannot be set."""
    changed = {}
    with contextlib.suppress(ValueError, OSError):  # not the main thread
        for number in (signal.SIGINT, signal.SIGHUP, signal.SIGTERM):
            if signal.getsignal(number) == signal.SIG_IGN:
                changed[number] = signal.signal(number, lambda _number, _frame: None)
    try:
        yield
    finally:
        for number, handler in changed.items():
            signal.signal(number, handler)


def run_case(case: Case) -> Outcome:
    """Run one case in a fresh folder and judge what it did."""
    with _signals_reach_cases():
        return _run_case(case)


def _run_case(case: Case) -> Outcome:
    with tempfile.TemporaryDirectory(prefix="seal-reliability-") as name:
        folder = Path(name)
        _make(folder, case.files)
        before = _listing(folder)
        kept = {k: _digest(folder / k) for k in case.keep}
        code, out, err, seconds = _once(case, folder)
        outcome = Outcome(case.name, code, seconds)
        text = err.decode("utf-8", "replace")
        if code is None:
            outcome.problems.append(f"hang: no end within {case.timeout:g} s")
        elif code not in case.codes:
            outcome.problems.append(f"exit: {code}, expected {' or '.join(map(str, case.codes))}: {text[-300:]}")
        if TRACEBACK in text or TRACEBACK in out.decode("utf-8", "replace"):
            outcome.problems.append(f"traceback: {text[-500:]}")
        said = text + out.decode("utf-8", "replace")
        if code in (1, 2) and case.stream != "closed-stderr" and not said.strip():
            outcome.problems.append("message: the command failed and said nothing")
        elif case.says is not None and (code in (1, 2) or (code == 0 and case.codes == (0,))) \
                and not re.search(case.says, said):
            outcome.problems.append(f"message: what it said does not match {case.says!r}: {said[-300:]}")
        if case.unsaid is not None and re.search(case.unsaid, said):
            outcome.problems.append(f"message: what it said holds {case.unsaid!r}: {said[-300:]}")
        for key, digest in kept.items():
            if _digest(folder / key) != digest:
                outcome.problems.append(f"lost: input {key} changed or vanished")
        after = _listing(folder)
        for left in sorted(after):
            if TEMPORARY.search(left):
                outcome.problems.append(f"partial: temporary {left} left behind")
        for name_ in case.whole:
            if not _complete(folder / name_):
                outcome.problems.append(f"partial: {name_} is missing or not whole")
        for name_ in case.absent:
            if (folder / name_).exists() and name_ not in before:
                outcome.problems.append(f"partial: {name_} written though the command failed or was stopped")
        if code not in (0, None) and case.parallel == 1:
            for new in sorted(after - before):
                if not TEMPORARY.search(new) and new not in case.whole:  # a failed run's whole picture is asked for
                    outcome.problems.append(f"partial: {new} written by a failed command")
        if case.twice and code is not None:
            again = _once(case, folder)
            if again[1] != out or again[0] != code:
                outcome.problems.append("nondeterminism: a second run gave other output")
        return outcome


def run_cases(all_cases: list[Case], jobs: int = 1,
              progress: Callable[[int, int], None] | None = None) -> list[Outcome]:
    """Run every case (``jobs`` at a time), in order."""
    outcomes: list[Outcome] = []
    with _signals_reach_cases(), ThreadPoolExecutor(max(1, jobs)) as pool:
        for outcome in pool.map(run_case, all_cases):
            outcomes.append(outcome)
            if progress is not None:
                progress(len(outcomes), len(all_cases))
    return outcomes


def summarise(outcomes: list[Outcome]) -> dict[str, object]:
    """The counts the issue asks for, and every problem found."""
    def count(kind: str) -> int:
        return sum(kind in o.kinds for o in outcomes)

    return {"tried": len(outcomes), "tracebacks": count("traceback"), "hangs": count("hang"),
            "wrong_exit_codes": count("exit"), "lost_or_partial_files": count("lost") + count("partial"),
            "nondeterministic": count("nondeterminism"), "unclear_messages": count("message"),
            "slowest_s": round(max((o.seconds for o in outcomes), default=0.0), 2),
            "problems": [{"case": o.case, "problems": o.problems} for o in outcomes if o.problems]}


# -- the cases ----------------------------------------------------------------------------------
def _apartment() -> tuple[tuple[str, bytes], tuple[str, bytes]]:
    from seal_cli.resources import maps_dir

    folder = maps_dir()
    return (("m.yaml", (folder / "apartment.yaml").read_bytes()), ("apartment.pgm",
                                                                   (folder / "apartment.pgm").read_bytes()))


def issue_cases() -> Iterator[Case]:
    """Every case of issue 14, replayed."""
    m, image = _apartment()
    obs = ("obs.yaml", OBSERVATIONS.encode())
    traj = ("traj.yaml", b"poses:\n  - [-6.0, -3.0]\n  - [5.0, -4.5, 1.57]\n")
    loc = ("localize", "--map", "m.yaml", "--steps", "1", "--particles", "20")
    inputs = ("m.yaml", "apartment.pgm", "obs.yaml", "traj.yaml")
    both = (m, image, obs, traj)
    # 1. outputs destroy inputs
    yield Case("1 localize --png onto the map", (*loc, "--png", "m.yaml"), both, keep=inputs)
    yield Case("1 localize --rrd onto the map's image", (*loc, "--rrd", "apartment.pgm"), both, keep=inputs)
    yield Case("1 localize --png onto --observations", (*loc, "--observations", "obs.yaml", "--png", "obs.yaml"),
               both, keep=inputs)
    yield Case("1 localize --rrd onto --trajectory", (*loc, "--trajectory", "traj.yaml", "--rrd", "traj.yaml"),
               both, keep=inputs)
    yield Case("1 run --png onto the map", ("run", "stir the cup", "--map", "m.yaml", "--particles", "20", "--png",
                                            "m.yaml"), both, keep=inputs)
    yield Case("1 run --rrd onto the image", ("run", "stir the cup", "--map", "m.yaml", "--particles", "20",
                                              "--rrd", "apartment.pgm"), both, keep=inputs)
    yield Case("1 map --png onto its own map", ("map", "m.yaml", "--png", "m.yaml"), both, keep=inputs)
    yield Case("1 map --png onto its image", ("map", "m.yaml", "--png", "apartment.pgm"), both, keep=inputs)
    yield Case("1 --png and --rrd one path", (*loc, "--png", "out.png", "--rrd", "out.png"), both, keep=inputs,
               absent=("out.png",))
    yield Case("1 an output through a symlink to the map", (*loc, "--png", "link.png"),
               (*both, ("link.png", "link:m.yaml")), keep=inputs)
    yield Case("1 an output hard-linked to the image", (*loc, "--rrd", "hard.rrd"),
               (*both, ("hard.rrd", "hard:apartment.pgm")), keep=inputs)
    yield Case("1 /dev/null stays a device", (*loc, "--png", "/dev/null", "--rrd", "/dev/null"), both, codes=(0,),
               keep=inputs)
    # 2. tracebacks
    for command in (("map", "m.yaml", "--png", "/proc/x.png"), (*loc, "--png", "/proc/x.png"),
                    ("run", "stir the cup", "--map", "m.yaml", "--png", "/proc/x.png"),
                    ("bench", "tasks", "--suite", "map", "--layouts", "1", "--episodes", "/proc/x.jsonl")):
        yield Case(f"2 unwritable folder: {command[0]}", command, both, codes=(1,), keep=inputs)
    for bad in ("\t", "\x00", "\\q"):
        frame = FRAME.replace('"whisk"', f'"whi{bad}sk"').encode()
        yield Case(f"2 .frame string with {bad!r}: validate", ("validate", "f.frame"), (("f.frame", frame),),
                   codes=(1,), keep=("f.frame",))
        yield Case(f"2 .frame string with {bad!r}: plan", ("plan", "--framelib", "f.frame", "whisk the cup"),
                   (("f.frame", frame),), codes=(1,))
    yield Case("2 a billion particles", (*loc, "--particles", "1000000000"), both, codes=(1, 2))
    # 3. hangs
    yield Case("3 put 99999999999 apples", ("plan", "put 99999999999 apples in the fridge"), codes=(1,))
    yield Case("3 5000 apples and --max-nodes", ("plan", "--max-nodes", "100", "put 5000 apples in the fridge"),
               codes=(1,))
    yield Case("3 a 2,000-frame chain", ("validate", "chain.frame"), (("chain.frame", _chain(2000, False)),),
               codes=(0,), timeout=120)
    yield Case("3 a 2,000-frame cycle", ("validate", "cycle.frame"), (("cycle.frame", _chain(2000, True)),),
               codes=(1,), timeout=120)
    yield Case("3 map image /dev/zero", ("map", "z.yaml"), (("z.yaml", m[1].replace(b"apartment.pgm",
                                                                                   b"/dev/zero")),), codes=(1,))
    yield Case("3 map image a FIFO", ("map", "f.yaml"), (("f.yaml", m[1].replace(b"apartment.pgm", b"pipe.pgm")),
                                                        ("pipe.pgm", "fifo")), codes=(1,))
    yield Case("3 parse --file /dev/zero", ("parse", "--file", "/dev/zero"), codes=(1,))
    yield Case("3 parse --file a FIFO", ("parse", "--file", "p.txt"), (("p.txt", "fifo"),), codes=(1,))
    yield Case("3 observations with an anchor reused 1,000 times", (*loc, "--observations", "bomb.yaml"),
               (*both, ("bomb.yaml", _anchor_bomb())), codes=(1,))
    yield Case("3 --steps 100000000", (*loc, "--steps", "100000000"), both, codes=(1, 2))
    # 4. one output line per input line
    lines = "stir the cup\u2028pick up the cup\x0bstir\x0cthe cup\rstir\x1cthe cup\x1dx\x1ey\x85z\nstir the cup\n"
    yield Case("4 odd line breaks", ("parse", "--file", "l.txt", "--json"), (("l.txt", lines.encode()),),
               twice=True)
    yield Case("4 a BOM", ("parse", "--file", "b.txt"), (("b.txt", b"\xef\xbb\xbfstir the cup\n"),), codes=(0,))
    yield Case("4 invalid UTF-8 on stdin", ("parse", "--file", "-"), codes=(1,), stdin=b"stir the cup\n\xff\n")
    # 5. partial files and signals
    yield Case("5 --pddl into a missing folder", ("plan", "--pddl", "nope", "stir the cup"), codes=(1,))
    yield Case("5 --pddl both or neither", ("plan", "--pddl", "out", "stir the cup"),
               (("out/problem.pddl/x", b""),), codes=(1,), absent=("out/domain.pddl",))
    for number in (signal.SIGTERM, signal.SIGINT):
        yield Case(f"5 {signal.Signals(number).name} during localize --png --rrd",
                   ("localize", "--map", "m.yaml", "--steps", "100000", "--png", "o.png", "--rrd", "o.rrd"), both,
                   codes=(130, 143, -int(number)), keep=inputs, absent=("o.png", "o.rrd"), signal=(number, 6.0))
    stale = ".o.png.seal999999-0123abcd.tmp.png"
    yield Case("5 a stale temporary of a killed run is swept", ("map", "m.yaml", "--png", "o.png"),
               (*both, (stale, b"half")), codes=(0,), absent=(stale,))
    # 6. wrong or silent acceptance
    yield Case("6 stir the café", ("plan", "stir the café"))
    yield Case("6 contradictory --done", ("plan", "--done", "pick up the spoon", "--done", "pick up the knife",
                                          "stir the cup"))
    yield Case("6 parse without a command", ("parse",), codes=(2,))
    yield Case("6 repeated key in observations", (*loc, "--observations", "d.yaml"),
               (*both, ("d.yaml", b"- pose: [-6, -3]\n  pose: [5, -4.5]\n")), codes=(1,))
    yield Case("6 pose inside a wall", (*loc, "--observations", "w.yaml"),
               (*both, ("w.yaml", b"- pose: [-10.5, -5.5]\n")), codes=(1,))
    # 7 and 8
    yield Case("7 validate lists every problem", ("validate", "v.frame"),
               (("v.frame", FRAME.replace("theme: container", "theme container").encode() + b"\nworld 5\n"),),
               codes=(1,), twice=True)
    yield Case("8 --png out.jpg", ("map", "m.yaml", "--png", "out.jpg"), both, codes=(1,), absent=("out.jpg",))


def _rooms(n: int) -> bytes:
    rows = ["bounds: [0, 0, 1000, 1000]", "rooms:"]
    rows += [f"  - {{name: r{i}, box: [{i % 100 * 10}, {i // 100 * 10}, {i % 100 * 10 + 10}, {i // 100 * 10 + 10}]}}"
             for i in range(n)]
    return ("\n".join(rows) + "\n").encode()


Setting = tuple[tuple[str, bytes], tuple[str, bytes], str, tuple[tuple[str, bytes], ...], tuple[str, ...],
                tuple[str, ...], bytes]


def hostile_setting() -> Setting:
    """What the hand-written hostile cases start from: the apartment's map and image (as files, and
    the map's text), both files, their names (kept unchanged by every case), a one-step localize
    command on them, and the frame DSL's bytes."""
    m, image = _apartment()
    loc = ("localize", "--map", "m.yaml", "--steps", "1", "--particles", "20")
    return m, image, m[1].decode(), (m, image), ("m.yaml", "apartment.pgm"), loc, FRAME.encode()


def hostile_cases() -> Iterator[Case]:
    """Hostile inputs written one by one, of kinds the mutations do not make: other encodings,
    numbers that are huge, negative, NaN or infinite wherever a number goes, links, spaces and
    newlines in paths, empty files, folders for files, concurrent writers of one output,
    signals during each writing command, and every subcommand's options at their edges."""
    m, image, text, both, inputs, loc, frame = hostile_setting()
    # -- encodings: frames, maps, observations, commands -------------------------------------------
    latin = FRAME.replace("Whisk what", "Wh\xe9sk").encode("latin-1")
    encodings = {"utf-16": FRAME.encode("utf-16"), "utf-16-le": FRAME.encode("utf-16-le"),
                 "utf-32": FRAME.encode("utf-32"), "latin-1 é": latin,
                 "overlong NUL": frame.replace(b"Whisk what", b"Wh\xc0\x80isk"),
                 "lone surrogate": frame.replace(b"Whisk what", b"Wh\xed\xa0\x80isk"),
                 "CRLF": FRAME.replace("\n", "\r\n").encode(), "CR only": FRAME.replace("\n", "\r").encode(),
                 "two BOMs": b"\xef\xbb\xbf\xef\xbb\xbf" + frame,
                 "BOM inside": frame.replace(b"frame Whisk", b"frame \xef\xbb\xbfWhisk")}
    for name, data in encodings.items():
        yield Case(f"H encoding {name}: validate", ("validate", "f.frame"), (("f.frame", data),), keep=("f.frame",))
    for name, data in (("utf-16 map", text.encode("utf-16")), ("latin-1 map", text.replace("apartment\n", "app\xe9\n")
                                                                           .encode("latin-1")),
                       ("CRLF map", text.replace("\n", "\r\n").encode())):
        yield Case(f"H encoding {name}", ("validate", "m.yaml"), (("m.yaml", data), image), keep=inputs)
    for name, data in (("utf-16 observations", OBSERVATIONS.encode("utf-16")),
                       ("latin-1 observations", OBSERVATIONS.replace("cup", "c\xfcp").encode("latin-1"))):
        yield Case(f"H encoding {name}", (*loc, "--observations", "o.yaml"), (*both, ("o.yaml", data)), codes=(1,),
                   keep=("o.yaml", *inputs))
    for name, data in (("utf-16", "stir the cup\n".encode("utf-16")), ("latin-1", b"stir the caf\xe9\n"),
                       ("NULs", b"stir\x00the cup\n"),
                       ("a BOM per line", b"\xef\xbb\xbfstir the cup\n\xef\xbb\xbfstir\n")):
        yield Case(f"H encoding parse --file {name}", ("parse", "--file", "c.txt", "--json"), (("c.txt", data),),
                   keep=("c.txt",), twice=True)
    # -- numbers of a map: huge, negative, NaN, infinite ---------------------------------------------
    numbers = ["1e309", "-1e309", ".nan", ".inf", "-.inf", "-0.0", "1e-320", "99999999999999999999999", "0x10", "1_000"]
    spots = {"resolution": ("resolution: 0.05", "resolution: {}"),
             "origin": ("origin: [-10.0, -7.0, 0.0]", "origin: [{}, -7.0, 0.0]"),
             "bounds": ("bounds: [-9.0, -6.0, 9.0, 6.0]", "bounds: [-9.0, -6.0, {}, 6.0]"),
             "a box": ("box: [-9.0, 0.5, -3.0, 6.0]", "box: [-9.0, 0.5, {}, 6.0]"),
             "a place": ("at: [8.5, -0.8]", "at: [{}, -0.8]"),
             "the robot": ("pose: [-6.0, -3.0, 0.0]", "pose: [-6.0, -3.0, {}]"),
             "the sensor": ("range: 5.0", "range: {}"),
             "a threshold": ("occupied_thresh: 0.65", "occupied_thresh: {}")}
    for k, (spot, (old, new)) in enumerate(spots.items()):
        for value in (numbers[k % len(numbers)], numbers[(k + 3) % len(numbers)], numbers[(k + 6) % len(numbers)]):
            yield Case(f"H number {value} in {spot}", ("validate", "m.yaml"),
                       (("m.yaml", text.replace(old, new.format(value)).encode()), image), keep=inputs)
    # -- numbers of observations and trajectories --------------------------------------------------
    for value in (".nan", ".inf", "-1e309", "1e308", "-0.0", "1e400", "[1, 2]", "{x: 1}", "true", "null"):
        yield Case(f"H observation pose {value}", (*loc, "--observations", "o.yaml"),
                   (*both, ("o.yaml", f"- pose: [{value}, -3.0]\n".encode())), keep=("o.yaml", *inputs))
        yield Case(f"H detection at {value}", (*loc, "--observations", "o.yaml"),
                   (*both, ("o.yaml", f"- pose: [-6, -3]\n  detections: [{{class: cup, at: [{value}, -3]}}]\n"
                            .encode())), keep=("o.yaml", *inputs))
    for value in (".nan", "1e309", "[]", "-9.0000001"):
        yield Case(f"H trajectory pose {value}", (*loc, "--trajectory", "t.yaml"),
                   (*both, ("t.yaml", f"poses:\n  - [{value}, -3.0]\n".encode())), keep=("t.yaml", *inputs))
    # -- numbers of options ------------------------------------------------------------------------
    options = [("localize", "--map", "apartment", "--particles"), ("localize", "--map", "apartment", "--steps"),
               ("localize", "--map", "apartment", "--seed"), ("run", "stir the cup", "--map", "apartment", "--seed"),
               ("run", "stir the cup", "--map", "apartment", "--max-steps"),
               ("run", "stir the cup", "--map", "apartment", "--max-metres"),
               ("run", "stir the cup", "--map", "apartment", "--particles"),
               ("plan", "stir the cup", "--max-nodes"), ("bench", "tasks", "--suite", "map", "--layouts"),
               ("bench", "tasks", "--suite", "map", "--limit"), ("bench", "reliability", "--count"),
               ("bench", "reliability", "--jobs"), ("bench", "maps", "--points"), ("bench", "maps", "--repeats"),
               ("bench", "perf", "--scale"), ("bench", "ros", "--poses"), ("bench", "startup", "--runs"),
               ("bench", "plan", "--repeat"), ("bench", "e2e", "--particles"), ("bench", "tasks", "--jobs")]
    for argv in options:
        values = ("nan", "-inf", "1e400", "-5", "99999999999999999999")
        for value in values if argv[-1] != "--limit" else ("nan", "-5", "0"):
            huge_seed = argv[-1] in ("--seed", "--limit") and value.isdigit()  # any whole number is a seed;
            # a limit beyond the cases is all of them (a long benchmark, not a hang): only bad values there
            yield Case(f"H option {argv[0]} {argv[-2]} {argv[-1]} {value}", (*argv, value),
                       codes=(0, 1, 2) if huge_seed else (1, 2), timeout=90)
    # -- paths: links, spaces, newlines, empty files, folders ------------------------------------------
    yield Case("H map through a dangling link", ("map", "l.yaml"), (("l.yaml", "link:nowhere.yaml"),), codes=(1,))
    yield Case("H map through a link loop", ("map", "a.yaml"), (("a.yaml", "link:b.yaml"), ("b.yaml", "link:a.yaml")),
               codes=(1,))
    yield Case("H a frame folder holding a link loop", ("validate", "lib"),
               (("lib/a.frame", frame), ("lib/loop", "link:.")), codes=(0, 1))
    yield Case("H map path with spaces", ("map", "my map.yaml"), (("my map.yaml", m[1]), image), codes=(0,),
               keep=("my map.yaml",))
    yield Case("H map path with a newline", ("map", "my\nmap.yaml"), (("my\nmap.yaml", m[1]), image), codes=(0,))
    yield Case("H image path with spaces", ("map", "m.yaml"),
               (("m.yaml", m[1].replace(b"image: apartment.pgm", b"image: 'an image.pgm'")),
                ("an image.pgm", image[1])),
               codes=(0,))
    yield Case("H --png path with spaces and a newline", ("map", "m.yaml", "--png", "out put\n.png"), both, codes=(0,),
               whole=("out put\n.png",), keep=inputs)
    command: tuple[str, ...]
    for command in (("validate", "e.frame"), ("validate", "e.yaml"), ("map", "e.yaml"), ("parse", "--file", "e.txt"),
                    (*loc, "--observations", "e.yaml"), (*loc, "--trajectory", "e.yaml"),
                    ("plan", "--framelib", "e.frame", "stir the cup"), ("bench", "plan", "--file", "e.txt")):
        yield Case(f"H empty file: {' '.join(command[:1] + command[-2:])}", command,
                   (*both, ("e.frame", b""), ("e.yaml", b""), ("e.txt", b"")), codes=(0, 1), keep=inputs)
    for command in (("map", "d.yaml"), ("parse", "--file", "d.yaml"), (*loc, "--observations", "d.yaml"),
                    ("plan", "--map", "d.yaml", "stir the cup"), ("run", "stir the cup", "--map", "d.yaml"),
                    ("localize", "--map", "m.yaml", "--labels", "d.yaml", "--bag", "d.yaml"),
                    ("parse", "--vocabulary", "d.yaml", "stir the cup"), ("import-bag", "d.yaml", "-o", "o.yaml")):
        yield Case(f"H a folder for a file: {' '.join(command[:1] + command[-2:])}", command,
                   (*both, ("d.yaml", "dir")), codes=(1, 2))
    yield Case("H map image is a folder", ("map", "m.yaml"), (("m.yaml", m[1]), ("apartment.pgm", "dir")), codes=(1,))
    yield Case("H map image is the map itself", ("map", "m.yaml"),
               (("m.yaml", m[1].replace(b"image: apartment.pgm", b"image: m.yaml")),), codes=(1,), keep=("m.yaml",))
    yield Case("H --pddl onto a file", ("plan", "--pddl", "f.txt", "stir the cup"), (("f.txt", b"keep me"),),
               codes=(1,), keep=("f.txt",))
    yield Case("H --episodes onto the map", ("bench", "tasks", "--suite", "map", "--map", "m.yaml", "--layouts", "1",
                                              "--episodes", "m.yaml"), both, codes=(1,), keep=inputs)
    yield Case("H import-bag -o onto its bag", ("import-bag", "b.bag", "-o", "b.bag"), (("b.bag", b"not a bag"),),
               codes=(1,), keep=("b.bag",))
    yield Case("H --goals onto the map", (*loc, "--task", "stir the cup", "--goals", "m.yaml"), both, codes=(1,),
               keep=inputs)
    yield Case("H 10,000 rooms", ("validate", "r.yaml"), (("r.yaml", _rooms(10_000)),), codes=(0,), timeout=120)
    # -- concurrent writers of one output ----------------------------------------------------------
    yield Case("H three map --png at once onto one file", ("map", "m.yaml", "--png", "o.png"), both, codes=(0,),
               parallel=3, whole=("o.png",), keep=inputs)
    yield Case("H two localize --png --rrd at once", (*loc, "--png", "o.png", "--rrd", "o.rrd"), both, codes=(0,),
               parallel=2, whole=("o.png", "o.rrd"), keep=inputs)
    yield Case("H two plan --pddl at once", ("plan", "--pddl", "out", "stir the cup"), (("out", "dir"),), codes=(0,),
               parallel=2, whole=("out/domain.pddl", "out/problem.pddl"))
    # two runs of one short drive: "stir the cup" (a search for the cup and the spoon, 35 steps: 13.6 s of CPU each)
    # took two copies past 60 s at a load of 20 (hostile26's whole bench); the writers' race is the same (hostile27)
    yield Case("H two run --png at once", ("run", "go to the kitchen", "--map", "m.yaml", "--particles", "50", "--png",
                                           "r.png"), both, codes=(0,), parallel=2, whole=("r.png",), keep=inputs,
               says=r"done: Go\(goal=kitchen\)")
    # -- signals while writing -------------------------------------------------------------------------
    writers = {"map --png": ("map", "m.yaml", "--png", "o.png"),
               "run --png --rrd": ("run", "stir the cup", "--map", "m.yaml", "--png", "o.png", "--rrd", "o.rrd"),
               "plan --pddl": ("plan", "--pddl", "out", "stir the cup"),
               "bench tasks --episodes": ("bench", "tasks", "--suite", "map", "--map", "m.yaml", "--layouts", "3",
                                          "--episodes", "o.jsonl")}
    for k, (what, argv) in enumerate(writers.items()):
        for number in (signal.SIGINT, signal.SIGHUP, signal.SIGTERM)[k % 2:k % 2 + 2]:
            yield Case(f"H {signal.Signals(number).name} during {what}", argv, (*both, ("out", "dir")),
                       codes=(0, 129, 130, 143, -int(number)), keep=inputs, signal=(number, 1.5 + k))
    # -- where a thing is put (e2e10): "put away", a room as a goal, "there", a picture's crop -------------------
    priors = "priors:\n  cup: {family_room: 0.5, bedroom: 0.5}\n  spoon: {kitchen: 0.5, bedroom: 0.5}\n" \
             "  apple: {fridge: 0.4, counter: 0.4, kitchen: 0.2}\n"
    odd_priors = {"zero mass": "priors:\n  cup: {bedroom: 0.0}\n", "no priors": "priors: {}\n",
                  "a prior naming only where the cup lies": "priors:\n  cup: {coffee_table_1: 1.0}\n",
                  "a prior of a class named like a place": "priors:\n  cup: {sofa: 1.0}\n  sofa_1: {bedroom: 1.0}\n"}
    for what, block in odd_priors.items():
        changed = text.replace(priors, block)
        assert changed != text, "the apartment's priors changed: update the hostile put-away cases"
        for said in ("put away the cup", "store the cup and the spoon", "take the cup to the bedroom"):
            yield Case(f"H put away, {what}: {said}", ("run", said, "--map", "p.yaml", "--particles", "20",
                                                       "--max-steps", "60"),
                       (("p.yaml", changed.encode()), image), keep=("p.yaml", "apartment.pgm"))
    no_places = re.sub(r"places:\n(  - .*\n)+", "places: []\n", text).replace("in: coffee_table_1", "in: null") \
        .replace("in: counter_1", "in: null").replace("in: fridge_1", "in: null").replace("{class: apple, in: null}",
                                                                                          "{class: apple, at: [8, -3]}")
    yield Case("H put away on a map with no places", ("plan", "put away the cup", "--map", "n.yaml"),
               (("n.yaml", no_places.encode()), image), keep=("n.yaml",))
    for said in ("put away it", "put away", "store everything", "put the cup in there", "put it over there",
                 "put away the cup in there", "put the cup there and put it away", "take the cup there",
                 "put away the fridge", "put away the kitchen", "bring a coffee", "bring the coffee table a coffee",
                 "put away " + "the cup and " * 60 + "the spoon"):
        yield Case(f"H where to put: {said[:40]}", ("plan", "--map", "apartment", said), says=None)
    unknown = b"P5\n400 280\n255\n" + b"\xcd" * (400 * 280)      # every pixel unknown grey: nothing to crop to
    yield Case("H map --png of a map whose image is all unknown", ("map", "m.yaml", "--png", "o.png"),
               (m, ("apartment.pgm", unknown)), codes=(0, 1), keep=inputs)
    # -- every subcommand's options at their edges -----------------------------------------------------
    edges = [("parse", "--vocabulary", "nope.yaml", "stir the cup"), ("parse", "--map", "nope", "stir the cup"),
             ("parse", "--framelib", "nope.frame", "stir"), ("plan", "--holding", "😀", "stir the cup"),
             ("plan", "--holding", "", "stir the cup"), ("plan", "--done", "", "stir the cup"),
             ("plan", "--map", "apartment", "--done", "fly to the moon", "stir the cup"),
             ("frames", "--framelib", "nope"), ("frames", "Nonexistent"), ("frames", ""), ("frames", "--json", "Stir"),
             ("map", "apartment", "--json"), ("map", "nope"), ("map", ""), ("validate",), ("validate", "--stdlib"),
             ("validate", "--json", "nope.frame"), ("validate", "x.txt"),
             ("run", "stir the cup", "--map", "apartment", "--policy", "nope"),
             ("run", "", "--map", "apartment"), ("run", "stir the cup", "--map", "apartment", "--holding", "spoon",
                                                 "--done", "pick up the cup"),
             ("localize", "--map", "apartment", "--task", "", "--steps", "0"),
             ("localize", "--map", "apartment", "--task", "fly to the moon", "--steps", "0"),
             ("localize", "--map", "apartment", "--frame", "", "--steps", "0"),
             ("localize", "--map", "apartment", "--bag", "nope.bag"),
             ("localize", "--map", "apartment", "--observations", "o.yaml", "--trajectory", "o.yaml"),
             ("import-bag", "nope.bag", "-o", "o.yaml"), ("import-bag", "nope.bag"),
             ("bench", "tasks", "--suite", "nope"), ("bench", "tasks", "--suite", "map", "--policies", "nope"),
             ("bench", "tasks", "--suite", "map", "--backend", "nope"), ("bench", "tasks", "--split", "nope"),
             ("bench", "tasks", "--data", "nowhere"), ("bench", "parse", "--corpus", "nope"),
             ("bench", "parse", "--scorers", "nowhere"), ("bench", "e2e", "--map", "nope"),
             ("bench", "e2e", "--file", "nope.txt"), ("bench", "maps", "--map", "nope"),
             ("bench", "ros", "--format", "nope"), ("bench", "plan", "--file", "nope.txt"),
             ("bench", "plan", "--map", "nope"), ("bench", "reliability", "--limit", "-1"), ("bench", "nope"),
             ("nope",), ("--version",), ("-h",), ("parse", "-h"), ("bench", "tasks", "-h")]
    for argv in edges:
        yield Case(f"H option edge: {' '.join(argv)}", argv, codes=(0, 1, 2))


def _chain(n: int, cycle: bool) -> bytes:
    def word(i: int) -> str:
        letters = ""
        while True:
            letters += chr(97 + i % 26)
            i //= 26
            if not i:
                return letters

    out = ["category thing = *"]
    for i in range(n):
        following = (i + 1) % n if cycle else i + 1
        needs = f"  requires p{following}(x)\n" if cycle or i < n - 1 else ""
        out.append(f'frame F{i} "verb{word(i)}" {{\n  x: thing\n{needs}  ensures p{i}(x)\n}}')
    return "\n".join(out).encode()


def _anchor_bomb() -> bytes:
    head = "- &a {pose: [-6, -3], detections: [" + ", ".join(["{class: cup, at: [-5, -3]}"] * 1000) + "]}\n"
    return (head + "- *a\n" * 1000).encode()


def _mutate(text: str, rng: random.Random) -> str:
    """One hostile edit of a text: a character inserted, deleted or repeated, a line dropped or
    doubled, the text cut short."""
    kind = rng.randrange(6)
    at = rng.randrange(len(text) + 1)
    if kind == 0:
        return text[:at] + rng.choice(HOSTILE_CHARS) + text[at:]
    if kind == 1:
        return text[:at] + text[at + rng.randint(1, 8):]
    if kind == 2:
        return text[:at]
    lines = text.split("\n")
    line = rng.randrange(len(lines))
    if kind == 3:
        return "\n".join(lines[:line] + lines[line + 1:])
    if kind == 4:
        return "\n".join(lines[:line] + [lines[line]] * rng.randint(2, 4) + lines[line + 1:])
    words = re.split(r"(\W+)", text)
    spot = rng.randrange(len(words))
    words[spot] = rng.choice(["nan", "-1", "1e308", "0", "~", "[]", "{}", "x" * 300, "é", "99999999999"])
    return "".join(words)


def generated_cases(seed: int = 0, count: int = 320) -> Iterator[Case]:
    """``count`` hostile inputs drawn from ``seed``: frames, maps, observations, commands, output
    paths and options, in turn."""
    rng = random.Random(seed)
    m, image = _apartment()
    map_text = m[1].decode()
    makers: list[Callable[[int], Case]] = []

    def frame_dsl(i: int) -> Case:
        text = FRAME
        for _ in range(rng.randint(1, 3)):
            text = _mutate(text, rng)
        command = rng.choice([("validate", "f.frame"), ("plan", "--framelib", "f.frame", "whisk the cup")])
        return Case(f"frame {i}", command, (("f.frame", text.encode()),), keep=("f.frame",), twice=i % 10 == 0)

    def frame_yaml(i: int) -> Case:
        text = FRAME_YAML
        for _ in range(rng.randint(1, 3)):
            text = _mutate(text, rng)
        command = rng.choice([("validate", "f.yaml"), ("parse", "--framelib", "f.yaml", "whisk the bowl")])
        return Case(f"frame yaml {i}", command, (("f.yaml", text.encode()),), keep=("f.yaml",))

    def a_map(i: int) -> Case:
        text = _mutate(map_text, rng)
        command = rng.choice([("map", "m.yaml", "--json"), ("validate", "m.yaml"),
                              ("plan", "--map", "m.yaml", "stir the cup")])
        return Case(f"map {i}", command, (("m.yaml", text.encode()), image), keep=("m.yaml", "apartment.pgm"))

    def observations(i: int) -> Case:
        text = OBSERVATIONS
        for _ in range(rng.randint(1, 2)):
            text = _mutate(text, rng)
        return Case(f"observations {i}", ("localize", "--map", "m.yaml", "--steps", "0", "--particles", "20",
                                          "--observations", "o.yaml"), (m, image, ("o.yaml", text.encode())),
                    keep=("o.yaml", "m.yaml"))

    def command(i: int) -> Case:
        words = " ".join(rng.choice(HOSTILE_WORDS) for _ in range(rng.randint(1, 9)))
        verb = rng.choice([("parse",), ("parse", "--json"), ("plan",), ("plan", "--map", "apartment")])
        return Case(f"command {i}", (*verb, "--", words), twice=i % 7 == 0)  # "--": words may start with "-"

    def output(i: int) -> Case:
        target = rng.choice(["m.yaml", "apartment.pgm", "o.jpg", "sub", "missing/o.png", "/dev/null", "link.png",
                             "hard.png", "fifo.png", "o.png", "o.rrd", "/proc/o.png", ""])
        option = rng.choice(["--png", "--rrd"])
        command = rng.choice([("localize", "--map", "m.yaml", "--steps", "0", "--particles", "10"),
                              ("map", "m.yaml")])
        if command[0] == "map":
            option = "--png"
        files = (m, image, ("sub/x", b""), ("link.png", "link:m.yaml"), ("hard.png", "hard:m.yaml"),
                 ("fifo.png", "fifo"))
        return Case(f"output {i}: {option} {target!r}", (*command, option, target), files,
                    keep=("m.yaml", "apartment.pgm"))

    def option(i: int) -> Case:
        name, value = rng.choice([("--particles", rng.choice(["0", "-1", "1e9", "x", "1000000000000"])),
                                  ("--steps", rng.choice(["-1", "99999999999", "x"])),
                                  ("--seed", rng.choice(["-1", "x", "1.5"]))])
        return Case(f"option {i}: {name} {value}", ("localize", "--map", "apartment", name, value),
                    codes=(1, 2))

    makers = [frame_dsl, frame_yaml, a_map, observations, command, output, option]
    for i in range(count):
        yield makers[i % len(makers)](i)

