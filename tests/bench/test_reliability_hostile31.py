"""Round hostile31's hostile cases of ``seal bench reliability``: new, named once, each saying what its message names,
part of the attacker's; each leftover and a pick of the later batches end cleanly (each failed on main before this
round)."""

from __future__ import annotations

from pathlib import Path

import pytest

from seal_cli.bench.reliability import run_case
from seal_cli.bench.reliability_attacker import attacker_cases
from seal_cli.bench.reliability_hostile31 import hostile31_cases, hostile31_leftover_cases


def test_the_hostile31_cases_are_named_once_and_say_what_they_must() -> None:
    found = [*hostile31_leftover_cases(), *hostile31_cases()]
    assert len({c.name for c in found}) == len(found)
    assert all(c.says for c in found if c.codes in ((0,), (1,)))
    assert {c.name for c in found} <= {c.name for c in attacker_cases()}
    assert len(found) >= 60 and sum(c.unsaid is not None for c in found) >= 20


@pytest.mark.parametrize("name", [c.name for c in hostile31_leftover_cases()])
def test_a_control_character_anywhere_in_a_frame_file_is_refused_at_it(name: str,
                                                                         monkeypatch: pytest.MonkeyPatch) -> None:
    """A NUL, an escape, a backspace or a DEL in a comment was read with the comment; in a name it was "the frame is
    not closed" and its line was printed with the character as it is. This tree's code."""
    monkeypatch.setenv("PYTHONPATH", str(Path(__file__).resolve().parents[2]))
    case = next(c for c in hostile31_leftover_cases() if c.name == name)
    assert run_case(case).problems == []


@pytest.mark.parametrize("name", [
    "A bench tasks --suite context --fov 1e-300",
    "A run on a map whose sensor sees 0.001 degrees",
    "A run --rrd whose name ends in /",
    "A localize --observations of a file named with a / after it",
    "A localize --goals of '-'",
    "A validate of a ROS map whose image is a link loop",
    "A run --map of a missing map whose name holds a carriage return",
    "A bench e2e --file whose case holds a number where the robot's hand's class goes",
    "A parse of 'zap' with a library that adds the verb zap",
    "A import-bag --labels whose label holds a NUL",
    "A import-bag of an .mcap of its magic alone",
])
def test_picked_hostile31_cases_end_cleanly(name: str, monkeypatch: pytest.MonkeyPatch) -> None:
    """Each failed before this round: a sliver of a field of view ran without end, a name ending in '/' wrote or read
    the file without it, ``--goals -`` made a folder called "-", a loop of links "does not exist", a carriage return
    in a name reached the terminal, a number as a case's holding was a plan missed, "zap" alone was an "unknown verb"
    the robot can do, a label holding a NUL was passed on as a class, a bag of its magic alone said "ord()". This
    tree's code."""
    if "bag" in name:
        pytest.importorskip("rosbags")
    monkeypatch.setenv("PYTHONPATH", str(Path(__file__).resolve().parents[2]))
    case = next(c for c in hostile31_cases() if c.name == name)
    assert run_case(case).problems == []
