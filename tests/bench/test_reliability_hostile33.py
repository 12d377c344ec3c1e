"""Round rel33's hostile cases of ``seal bench reliability``: new, named once, each saying what its message names,
part of the attacker's; a pick of them ends cleanly (each failed before this round)."""

from __future__ import annotations

from pathlib import Path

import pytest

from seal_cli.bench.reliability import run_case
from seal_cli.bench.reliability_attacker import attacker_cases
from seal_cli.bench.reliability_hostile33 import hostile33_cases


def test_the_hostile33_cases_are_named_once_and_say_what_they_must() -> None:
    found = list(hostile33_cases())
    assert len({c.name for c in found}) == len(found) >= 50
    assert all(c.says for c in found)
    everyone = [c.name for c in attacker_cases()]
    assert {c.name for c in found} <= set(everyone)
    assert len(everyone) == len(set(everyone))


@pytest.mark.parametrize("name", [
    "A bench tasks --policies oracle --particles 20",
    "A map --png with MPLBACKEND='junk'",
    "A map --png beside a matplotlibrc of text.usetex: True",
    "A localize --rrd with RERUN=off",
    "A localize with NUMBA_NUM_THREADS=0",
])
def test_picked_hostile33_cases_end_cleanly(name: str, monkeypatch: pytest.MonkeyPatch) -> None:
    """Each failed before this round: ``--particles`` was taken though no policy listed reads it; ``MPLBACKEND=junk``,
    a ``matplotlibrc`` asking for LaTeX, ``RERUN=off`` and ``NUMBA_NUM_THREADS=0`` were tracebacks. This tree's code."""
    monkeypatch.setenv("PYTHONPATH", str(Path(__file__).resolve().parents[2]))
    case = next(c for c in hostile33_cases() if c.name == name)
    assert run_case(case).problems == []
