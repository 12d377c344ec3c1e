"""Shared fixtures: the standard library, and where the shared real data lives."""

from __future__ import annotations

import fcntl
import importlib.util
import json
import os
import shutil
import signal
import subprocess
import sys
import tempfile
from collections.abc import Callable
from pathlib import Path
from types import ModuleType
from typing import Any

import pytest

from seal_cli.frames.library import Library
from seal_cli.frames.reading import load_library

ROOT = Path(__file__).resolve().parents[1]
DATA = ROOT.parent / "shared" / "data"

_CACHE_MADE: list[str] = []


def pytest_configure(config: pytest.Config) -> None:
    """The tests' cache of read libraries and word tables lives in a folder of their own, never in
    the user's ``~/.cache/seal`` (subprocesses the tests start inherit it). The subprocesses run this tree's
    ``seal_cli`` (its folder first on ``PYTHONPATH``), not whichever one the venv installed: a worktree's tests
    test the worktree."""
    if "SEAL_CACHE_DIR" not in os.environ:
        folder = tempfile.mkdtemp(prefix="seal-test-cache-")
        _CACHE_MADE.append(folder)
        os.environ["SEAL_CACHE_DIR"] = folder
    paths = os.environ.get("PYTHONPATH", "").split(os.pathsep)
    if paths[0] != str(ROOT):
        os.environ["PYTHONPATH"] = os.pathsep.join([str(ROOT), *filter(None, paths)])
    _interrupts_as_at_a_terminal()


def _interrupts_as_at_a_terminal() -> None:
    """A run started in a shell's background (``nohup pytest &``, a CI step) begins with SIGINT ignored, and every
    process a test starts inherits that: the tests of Ctrl-C (a worker forked as SIGINT lands, a command interrupted
    while it holds a half-built object) then saw no interrupt at all and failed. SIGINT is acted on here as at a
    terminal (Python's own handler; a caught signal is reset to its default by ``exec``, so the commands the tests
    start begin with it too), as ``bench reliability``'s ``_signals_reach_cases`` does for its cases."""
    if signal.getsignal(signal.SIGINT) == signal.SIG_IGN:
        signal.signal(signal.SIGINT, signal.default_int_handler)


def pytest_unconfigure(config: pytest.Config) -> None:
    for folder in _CACHE_MADE:
        shutil.rmtree(folder, ignore_errors=True)


@pytest.fixture(scope="session")
def library() -> Library:
    return load_library()


@pytest.fixture(scope="session")
def shared_data() -> Path:
    if not DATA.is_dir():
        pytest.skip(f"shared data not found at {DATA}")
    return DATA


def made_once(factory: pytest.TempPathFactory, name: str, make: Callable[[Path], None]) -> Path:
    """A file ``make(path)`` writes, made once for the whole run: under pytest-xdist its workers share the run's
    temporary folder and a lock in it (the first makes the file, the others wait for it and read it)."""
    if "PYTEST_XDIST_WORKER" not in os.environ:
        path = factory.mktemp(name) / name
        make(path)
        return path
    root = factory.getbasetemp().parent
    path = root / name
    with open(root / f"{name}.lock", "w") as lock:
        fcntl.flock(lock, fcntl.LOCK_EX)
        if not path.exists():
            part = root / f"{name}.part"
            make(part)
            part.replace(path)
    return path


@pytest.fixture(scope="session")
def rebuilt_word_classes(shared_data: Path, tmp_path_factory: pytest.TempPathFactory) -> Path:
    """The word-class table ``scripts/build_word_classes.py`` builds from the whole train split (about a CPU-minute):
    built once for the tests that compare it with the shipped one."""
    if not (shared_data / "alfred" / "goals_train.tsv").is_file():
        pytest.skip("no ALFRED train goals")

    def build(out: Path) -> None:
        done = subprocess.run([sys.executable, str(ROOT / "scripts" / "build_word_classes.py"), "--data",
                               str(shared_data), "--out", str(out)], capture_output=True, text=True, timeout=900)
        assert done.returncode == 0, done.stdout + done.stderr

    return made_once(tmp_path_factory, "word_classes_train.json", build)


def alfred_sample(shared_data: Path, folder: Path, every: int) -> Path:
    """A data folder of one ALFRED train sentence in ``every`` (with the constants and floor plans): enough for a
    build script's fit to run end to end in seconds."""
    if not (shared_data / "alfred" / "goals_train.tsv").is_file():
        pytest.skip("no ALFRED train goals")
    (folder / "alfred").mkdir(parents=True)
    lines = (shared_data / "alfred" / "goals_train.tsv").read_text().splitlines(keepends=True)
    (folder / "alfred" / "goals_train.tsv").write_text("".join([lines[0], *lines[1::every]]))
    (folder / "alfred" / "alfred_constants.json").symlink_to(shared_data / "alfred" / "alfred_constants.json")
    if (shared_data / "alfred2d").is_dir():
        (folder / "alfred2d").symlink_to(shared_data / "alfred2d")
    return folder


def check_on_a_sample(script: Path, shared_data: Path, tmp_path: Path, stale: Callable[[Any], str]) -> None:
    """A build script's ``--check`` end to end on one ALFRED train sentence in 40 (the whole split is compared by
    the test of its shipped file): the file built from the sample checks up to date; moved by ``stale`` (which
    changes the read JSON in place and returns the path it changed, "/priors/type/..."), it is named there, exit 1,
    and the file is left as it was (``--check`` writes nothing)."""
    data = alfred_sample(shared_data, tmp_path / "data", every=40)
    out = tmp_path / "built.json"
    run = [sys.executable, str(script), "--data", str(data), "--out", str(out)]
    done = subprocess.run(run, capture_output=True, text=True, timeout=300)
    assert done.returncode == 0 and done.stdout.startswith(f"wrote {out} ("), done.stdout + done.stderr
    check = subprocess.run([*run, "--check"], capture_output=True, text=True, timeout=300)
    assert check.returncode == 0 and check.stdout == f"{out}: up to date\n", check.stdout + check.stderr
    built = json.loads(out.read_text())
    where = stale(built)
    out.write_text(json.dumps(built))
    check = subprocess.run([*run, "--check"], capture_output=True, text=True, timeout=300)
    assert check.returncode == 1 and f"{out}: differs from what the train split gives (rebuild it): {where}" \
        in check.stderr, check.stderr
    assert out.read_text() == json.dumps(built)


def tiny_wordnet(folder: Path, data_verb: str, data_noun: str, index_verb: str, index_noun: str, cntlist: str) -> Path:
    """A WordNet ``dict`` folder of the given file texts, for a build script's tests on a few synsets."""
    folder.mkdir()
    for name, text in [("data.verb", data_verb), ("data.noun", data_noun), ("index.verb", index_verb),
                       ("index.noun", index_noun), ("cntlist.rev", cntlist)]:
        (folder / name).write_text(text)
    return folder


def tiny_library(path: Path, text: str) -> Library:
    """A frame library of the given YAML text, written to ``path`` and read back without problems, for a build
    script's tests on a few frames."""
    from seal_cli.frames.reading import read_library

    path.write_text(text)
    found, problems = read_library([path])
    assert problems == []
    return found


def run_script(script: Path, *args: str) -> subprocess.CompletedProcess[str]:
    """``script`` (a build script of ``scripts/``) run with ``args`` by this Python, its output captured as text."""
    return subprocess.run([sys.executable, str(script), *args], capture_output=True, text=True, timeout=300)


def module_from_file(name: str, path: Path, register: bool = False) -> ModuleType:
    """The Python file at ``path`` (a script, a map's drawing, a scorer of ``../shared/eval``) run as the module
    ``name``, afresh each call; ``register`` puts it in ``sys.modules`` first (a dataclass of it looks itself up
    there)."""
    spec = importlib.util.spec_from_file_location(name, path)
    assert spec is not None and spec.loader is not None
    module = importlib.util.module_from_spec(spec)
    if register:
        sys.modules.setdefault(name, module)
    spec.loader.exec_module(module)
    return module
