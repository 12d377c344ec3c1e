"""An outsider's hostile cases of ``seal bench reliability``: new, named once, each saying what its message
names; a pick of them ends cleanly; the signal of a case waits for the child's own start-up."""

from __future__ import annotations

import signal
import subprocess
import sys

import pytest

from seal_cli.bench.reliability import Case, hostile_cases, issue_cases, run_case
from seal_cli.bench.reliability_outsider import outsider_cases
from seal_cli.bench.reliability_review import cases, review_cases
from seal_cli.bench.reliability_users import user_cases


def test_the_cases_are_new_named_once_and_say_what_the_message_names() -> None:
    outsider = list(outsider_cases())
    assert len(outsider) >= 80 and len({c.name for c in outsider}) == len(outsider)
    others = {c.name for c in [*issue_cases(), *hostile_cases(), *review_cases(), *user_cases()]}
    assert {c.name for c in outsider}.isdisjoint(others)
    assert all(c.says is not None for c in outsider if c.codes != (0,) and c.signal is None)
    assert {c.name for c in outsider} <= {c.name for c in cases(0, 0)}


@pytest.mark.parametrize("name", ["O PYTHONIOENCODING=ascii: parse --json stays JSON",
                                  "O PYTHONIOENCODING=ascii: plan stir the cup", "O COLUMNS=5: frames",
                                  "O SIGINT 0.1 s into map --png (while importing)", "O map: a room called _outside",
                                  "O map: a self-crossing room after a broken one",
                                  "O map image: a PNG declaring 20,000 × 20,000", "O 1e300 m in the origin: validate",
                                  "O bench tasks: floorplans.json is a FIFO",
                                  "O bench tasks: a Latin-1 byte in the trials", "O map --png /dev/full",
                                  "O numpy's warnings stay off stderr (PYTHONWARNINGS unset)"])
def test_picked_cases_end_cleanly(name: str) -> None:
    outcome = run_case(next(c for c in outsider_cases() if c.name == name))
    assert outcome.problems == []


def test_an_environment_variable_can_be_set_and_removed() -> None:
    shown = Case("env", ("parse", "--json", "stir the café"), codes=(0,), says=r"caf\\u00e9",
                 env=(("PYTHONIOENCODING", "ascii"), ("NO_COLOR", "<unset>")))
    assert run_case(shown).problems == []
    plain = Case("env", ("parse", "--json", "stir the café"), codes=(0,), says=r"caf\\u00e9")
    assert any(p.startswith("message:") for p in run_case(plain).problems)  # UTF-8: the judge can fail


def test_a_signal_waits_for_the_interpreter_to_start() -> None:
    from seal_cli.bench.reliability import SIGNAL_CPU, _cpu_seconds, _wait_to_signal

    child = subprocess.Popen([sys.executable, "-c", "import time\nwhile True: pass"])
    try:
        assert _wait_to_signal(child, 0.0)
        cpu = _cpu_seconds(child.pid)
        assert cpu is None or cpu >= SIGNAL_CPU
    finally:
        child.send_signal(signal.SIGKILL)
        child.wait()
    ended = subprocess.Popen([sys.executable, "-c", "pass"])
    ended.wait()
    assert not _wait_to_signal(ended, 0.0)  # it ended: no signal to send
