"""Shared fixtures: the standard library, and where the shared real data lives."""

from __future__ import annotations

import os
import shutil
import tempfile
from pathlib import Path

import pytest

from seal_cli.frames.library import Library
from seal_cli.frames.reading import load_library

ROOT = Path(__file__).resolve().parents[1]
DATA = ROOT.parent / "shared" / "data"

_CACHE_MADE: list[str] = []


def pytest_configure(config: pytest.Config) -> None:
    """The tests' cache of read libraries and word tables lives in a folder of their own, never in
    the user's ``~/.cache/seal`` (subprocesses the tests start inherit it)."""
    if "SEAL_CACHE_DIR" not in os.environ:
        folder = tempfile.mkdtemp(prefix="seal-test-cache-")
        _CACHE_MADE.append(folder)
        os.environ["SEAL_CACHE_DIR"] = folder


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
