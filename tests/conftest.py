"""Shared fixtures: the standard library, and where the shared real data lives."""

from __future__ import annotations

from pathlib import Path

import pytest

from seal_cli.frames.library import Library
from seal_cli.frames.reading import load_library

ROOT = Path(__file__).resolve().parents[1]
DATA = ROOT.parent / "shared" / "data"


@pytest.fixture(scope="session")
def library() -> Library:
    return load_library()


@pytest.fixture(scope="session")
def shared_data() -> Path:
    if not DATA.is_dir():
        pytest.skip(f"shared data not found at {DATA}")
    return DATA
