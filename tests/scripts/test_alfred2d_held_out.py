"""scripts/alfred2d_held_out.py: its arguments and data checked before anything is fitted or written."""

from __future__ import annotations

from pathlib import Path

import pytest

from tests.conftest import run_script

SCRIPT = Path(__file__).resolve().parents[2] / "scripts" / "alfred2d_held_out.py"


@pytest.mark.parametrize(("args", "said"), [
    (["--dev", "1.5"], "--dev 1.5: a fraction in (0, 1)"),
    (["--dev", "0"], "--dev 0.0: a fraction in (0, 1)"),
    (["--sample", "0"], "--sample and --particles: at least 1"),
])
def test_a_bad_argument_is_said_with_exit_code_1(tmp_path: Path, args: list[str], said: str) -> None:
    done = run_script(SCRIPT, "--data", str(tmp_path), *args)
    assert done.returncode == 1 and said in done.stderr and "Traceback" not in done.stderr


def test_a_data_folder_without_alfred_s_files_is_named(tmp_path: Path) -> None:
    done = run_script(SCRIPT, "--data", str(tmp_path), "--episodes", str(tmp_path / "out.jsonl"))
    assert done.returncode == 1 and "goals_train.tsv: no such file" in done.stderr
    assert not (tmp_path / "out.jsonl").exists()


def test_episodes_written_into_the_data_folder_are_refused(tmp_path: Path) -> None:
    for name in ("alfred/goals_train.tsv", "alfred/alfred_constants.json", "alfred2d/floorplans.json"):
        (tmp_path / name).parent.mkdir(parents=True, exist_ok=True)
        (tmp_path / name).write_text("")
    done = run_script(SCRIPT, "--data", str(tmp_path), "--episodes", str(tmp_path / "alfred" / "goals_train.tsv"))
    assert done.returncode == 1 and "inside the data folder" in done.stderr
    assert (tmp_path / "alfred" / "goals_train.tsv").read_text() == ""
    done = run_script(SCRIPT, "--data", str(tmp_path), "--policies", "sefm,nope")
    assert done.returncode == 1 and "--policies sefm,nope: the policies are" in done.stderr


def test_a_trial_not_in_the_held_out_sample_is_named(shared_data: Path, tmp_path: Path) -> None:
    done = run_script(SCRIPT, "--data", str(shared_data), "--goal", "gold", "--sample", "1", "--trial", "trial_nope",
                      "--episodes", str(tmp_path / "out.jsonl"))
    assert done.returncode == 1 and "--trial trial_nope: not a trial of the held-out sample" in done.stderr
    assert "Traceback" not in done.stderr and not (tmp_path / "out.jsonl").exists()


def test_one_trial_is_run_alone(shared_data: Path, tmp_path: Path) -> None:
    """The episode heating's context-share fix was traced on (docs/benchmarks.md, "search25"): run by itself, gold,
    it is one episode of its group, SeFM's path object-only's."""
    import json

    out = tmp_path / "out.jsonl"
    done = run_script(SCRIPT, "--data", str(shared_data), "--goal", "gold", "--policies", "sefm,object_only",
                      "--trial", "trial_T20190911_135649_366423", "--episodes", str(out))
    assert done.returncode == 0, done.stderr
    rows = [json.loads(line) for line in out.read_text().splitlines()]
    assert [r["policy"] for r in rows] == ["sefm", "object_only"]
    assert {r["task_id"] for r in rows} == {"trial_T20190911_135649_366423"} and rows[0]["success"]
    assert rows[0]["path_m"] == rows[1]["path_m"]
