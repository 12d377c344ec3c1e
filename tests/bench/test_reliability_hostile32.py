"""Round hostile32's hostile cases of ``seal bench reliability``: new, named once, each saying what its message names,
part of the attacker's; a pick of them ends cleanly (each failed on main before this round)."""

from __future__ import annotations

from pathlib import Path

import pytest

from seal_cli.bench.reliability import run_case
from seal_cli.bench.reliability_attacker import attacker_cases
from seal_cli.bench.reliability_hostile32 import hostile32_cases


def test_the_hostile32_cases_are_named_once_and_say_what_they_must() -> None:
    found = list(hostile32_cases())
    assert len({c.name for c in found}) == len(found) >= 50
    assert all(c.says for c in found)
    assert {c.name for c in found} <= {c.name for c in attacker_cases()}


@pytest.mark.parametrize("name", [
    "A validate of a .frame whose lexical unit is the function word 'the'",
    "A parse of 'the cup' with a library whose unit is 'the'",
    "A validate of a YAML file adding the unit 'and' to a frame",
    "A validate of a precondition cycle of three frames, one needing what it achieves",
    "A run --clock given twice",
    "A bench e2e --jobs given twice",
    "A run --policy oracle --search-end 0.5",
    "A run --policy saycan --clock 10:00",
    "A bench e2e --file whose map climbs out to /etc/passwd",
    "A bench e2e --file whose map is a map file in the working folder, not beside the suite",
])
def test_picked_hostile32_cases_end_cleanly(name: str, monkeypatch: pytest.MonkeyPatch) -> None:
    """Each failed before this round: a unit "the" was taken and "the cup" parsed as its frame, a cycle of three
    was "Zap → Zap", ``--clock`` twice ran at the last, ``--jobs`` twice ran the whole suite, the oracle took a
    ``--search-end`` it never reads, saycan a ``--clock``, a suite's map climbed out of its folder or was found in
    the working folder. This tree's code."""
    monkeypatch.setenv("PYTHONPATH", str(Path(__file__).resolve().parents[2]))
    case = next(c for c in hostile32_cases() if c.name == name)
    assert run_case(case).problems == []
