"""``scripts/alfred_failures.py``: a failed ALFRED-2D episode classified by its first cause, the read-back fields
compared as the goal scorer's classes and the scene's class keys, and a bad episodes file named with its line."""

from __future__ import annotations

import subprocess
import sys
from pathlib import Path
from types import ModuleType

from tests.conftest import module_from_file

ROOT = Path(__file__).resolve().parents[2]
SCRIPT = ROOT / "scripts" / "alfred_failures.py"


def script() -> ModuleType:
    return module_from_file("alfred_failures", SCRIPT)


WANT = {"type": "pick_and_place_simple", "object": "spraybottle", "receptacle": "toilet", "mrecep": "", "sliced": False}


def test_the_first_field_read_wrong_is_the_cause() -> None:
    classify = script().classify
    failed = {"reason": "not done: needs in(spray_bottle, toilet)"}
    assert classify(failed, None, WANT, False) == ("parse error", [])
    got = {**WANT, "object": "spray_bottle", "receptacle": ""}                # the scene's key: the same class
    assert classify(failed, got, WANT, False) == ("receptacle", ["receptacle"])
    got = {**WANT, "type": "pick_two_obj_and_place", "receptacle": "shelf"}
    assert classify(failed, got, WANT, False) == ("task type", ["type", "receptacle"])


def test_a_right_parse_is_execution_or_budget_and_apart_when_gold_failed_too() -> None:
    classify = script().classify
    got = {**WANT, "object": "spray_bottle"}
    assert classify({"reason": "searched everywhere"}, got, WANT, False) == ("execution", [])
    assert classify({"reason": "out of budget (400 steps)"}, got, WANT, False) == ("budget", [])
    assert classify({"reason": "searched everywhere"}, got, WANT, True) == ("execution (gold failed too)", [])


def test_labels_are_a_row_of_the_goal_scorer() -> None:
    from seal_cli.bench.alfred2d import Task

    row = script().labels(Task("pick_heat_then_place_in_recep", "Apple", "Fridge", sliced=True))
    assert row == {"task_type": "pick_heat_then_place_in_recep", "object": "Apple", "receptacle": "Fridge",
                   "mrecep": "", "sliced": "1"}


def test_a_bad_episodes_file_is_named_with_its_line(tmp_path: Path) -> None:
    bad = tmp_path / "eps.jsonl"
    bad.write_text('{"task_id": "t1", "policy": "sefm", "success": true}\nnot json\n', encoding="utf-8")
    run = subprocess.run([sys.executable, str(SCRIPT), str(bad)], capture_output=True, text=True, cwd=ROOT)
    assert run.returncode == 1 and f"{bad}:2:" in run.stderr and "Traceback" not in run.stderr
    missing = subprocess.run([sys.executable, str(SCRIPT), str(tmp_path / "none.jsonl")], capture_output=True,
                             text=True, cwd=ROOT)
    assert missing.returncode == 1 and "none.jsonl" in missing.stderr and "Traceback" not in missing.stderr
