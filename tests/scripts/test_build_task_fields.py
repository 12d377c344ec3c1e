"""The shipped task-field model is what ``scripts/build_task_fields.py`` gives on ALFRED's train split, and the
script names what is wrong with its arguments."""

from __future__ import annotations

import subprocess
import sys
from pathlib import Path
from types import ModuleType
from typing import Any

import pytest

from seal_cli.language.taskfields import SHIPPED, TRUST
from tests.conftest import check_on_a_sample, module_from_file

ROOT = Path(__file__).resolve().parents[2]
SCRIPT = ROOT / "scripts" / "build_task_fields.py"


def builder() -> ModuleType:
    return module_from_file("build_task_fields", SCRIPT)


def test_a_weight_may_move_in_its_last_decimal_but_no_prior_may_change() -> None:
    diff = builder().differences
    assert diff({"weights": {"type": {"u:a": {"x": 0.21}}}}, {"weights": {"type": {"u:a": {"x": 0.22}}}}) == []
    assert diff({"weights": {"type": {"u:a": {"x": 0.21}}}}, {"weights": {"type": {"u:a": {"x": 0.25}}}}) != []
    assert diff({"weights": {"type": {"u:a": {"x": 0.01}}}}, {"weights": {"type": {"u:a": {}}}}) == []
    assert diff({"priors": {"type": {"x": 3}}}, {"priors": {"type": {"x": 4}}}) == [
        "/priors/type/x: 3 shipped, 4 built"]
    assert builder().trusts(["2", "1,2,3,4"]) == [{"type": 2.0, "object": 2.0, "receptacle": 2.0, "mrecep": 2.0},
                                                  {"type": 1.0, "object": 2.0, "receptacle": 3.0, "mrecep": 4.0}]
    assert builder().trusts(["shipped"]) == [dict(TRUST)]


def test_a_missing_data_folder_or_a_bad_fraction_is_named(tmp_path: Path, shared_data: Path) -> None:
    done = subprocess.run([sys.executable, str(SCRIPT), "--check", "--data", str(tmp_path)],
                          capture_output=True, text=True, timeout=60)
    assert done.returncode == 1
    assert str(tmp_path / "alfred" / "goals_train.tsv") in done.stderr and "Traceback" not in done.stderr
    for args in (["--dev", "2"], ["--dev", "0.2", "--trust", "1,2"], ["--dev", "0.2", "--l2", "1", "0"],
                 ["--dev", "0.2", "--min-rooms", "-1"], ["--dev", "0.2", "--rooms", "0"],
                 ["--dev", "0.2", "--chooser-rooms", "-3"]):
        done = subprocess.run([sys.executable, str(SCRIPT), "--data", str(shared_data), *args],
                              capture_output=True, text=True, timeout=120)
        assert done.returncode == 1 and "Traceback" not in done.stderr, done.stderr
        assert args[-1] in done.stderr


def test_the_shipped_model_is_what_the_train_split_gives(shared_data: Path, tmp_path: Path) -> None:
    if not (shared_data / "alfred" / "goals_train.tsv").is_file():
        pytest.skip("no ALFRED train goals")
    out = tmp_path / "alfred_train.json"
    out.write_text(SHIPPED.read_text())
    check = subprocess.run([sys.executable, str(SCRIPT), "--check", "--data", str(shared_data), "--out", str(out)],
                           capture_output=True, text=True, timeout=900)
    assert check.returncode == 0, check.stdout + check.stderr


def test_check_names_a_model_the_data_no_longer_gives_and_writes_nothing(shared_data: Path, tmp_path: Path) -> None:
    def stale(model: dict[str, Any]) -> str:
        model["priors"]["type"]["pick_and_place_simple"] += 1
        return "/priors/type/pick_and_place_simple: "
    check_on_a_sample(SCRIPT, shared_data, tmp_path, stale)


def test_the_interval_resamples_the_held_out_floor_plans_not_the_sentences() -> None:
    resampled = builder().resampled
    # four floor plans of ten sentences: two all right, two all wrong; a share of 0.5 that the rooms decide
    units = [f"plan{k // 10}" for k in range(40)]
    right = [k < 20 for k in range(40)]
    low, high = resampled(units, right)
    assert low <= 0.5 <= high and high - low >= 0.5                       # four rooms: a wide interval
    spread = resampled([f"s{k}" for k in range(40)], right)                 # forty independent sentences: narrower
    assert spread[1] - spread[0] < high - low
    assert resampled(units, right) == (low, high)                           # deterministic
    assert resampled(units, right, right) == (0.0, 0.0)                     # a reading against itself: no difference
    better = [True] * 40
    assert resampled(units, better, right)[0] >= 0.0
    assert resampled([], []) == (0.0, 0.0)
