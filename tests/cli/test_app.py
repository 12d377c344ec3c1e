"""The command line as a user meets it: frames, validate, errors, exit codes."""

from __future__ import annotations

import json
import subprocess
import sys
from pathlib import Path

import pytest
from typer.testing import CliRunner

from seal_cli.cli import app
from seal_cli.errors import SealError
from tests.frames.test_library import PROJECT_FRAMES, SPEC_FRAMES

runner = CliRunner()


def test_version() -> None:
    result = runner.invoke(app, ["--version"])
    assert result.exit_code == 0 and result.stdout.startswith("seal ")


def test_frames_json_lists_the_spec_frames_with_their_roles() -> None:
    result = runner.invoke(app, ["frames", "--json"])
    assert result.exit_code == 0
    frames = json.loads(result.stdout)["frames"]
    assert {f["frame"]: set(f["elements"]) for f in frames} == SPEC_FRAMES | PROJECT_FRAMES
    stir = next(f for f in frames if f["frame"] == "Stir")
    assert stir["elements"]["instrument"] == {"type": "utensil", "default": "spoon"}
    assert stir["preconditions"] == ["holding(instrument)"]
    assert stir["actions"] == ["navigate(theme)", "stir(instrument, theme)"]


def test_frames_table_and_one_frame_in_full() -> None:
    table = runner.invoke(app, ["frames"])
    assert table.exit_code == 0 and "25 frames" in table.stdout and "LookAt" in table.stdout
    one = runner.invoke(app, ["frames", "Stir"])
    assert one.exit_code == 0
    assert "holding(instrument)" in one.stdout and "stir(instrument, theme)" in one.stdout
    assert json.loads(runner.invoke(app, ["frames", "pick", "--json"]).stdout)["frame"] == "Pick"


def test_unknown_frame_is_a_clean_error() -> None:
    result = runner.invoke(app, ["frames", "Juggle"])
    assert result.exit_code == 1
    assert "unknown frame 'Juggle'" in result.stderr and "Traceback" not in result.output


def test_validate_ok_and_json() -> None:
    result = runner.invoke(app, ["validate", "framelib"])
    assert result.exit_code == 0 and result.stdout.startswith("ok: 25 frames")
    report = json.loads(runner.invoke(app, ["validate", "framelib", "--json"]).stdout)
    assert report["ok"] is True and report["frames"] == 25 and report["problems"] == []


def test_validate_json_lists_problems(tmp_path: Path) -> None:
    bad = tmp_path / "bad.frame"
    bad.write_text('frame Whisk "whisk" {\n  theme: bowlful\n}\n')
    result = runner.invoke(app, ["validate", "--stdlib", "--json", str(bad)])
    assert result.exit_code == 1
    (problem,) = json.loads(result.stdout)["problems"]
    assert problem == {"file": str(bad), "line": 2, "column": 3, "message": problem["message"]}
    assert "unknown category 'bowlful'" in problem["message"]


def test_a_broken_framelib_option_stops_other_commands(tmp_path: Path) -> None:
    bad = tmp_path / "bad.yaml"
    bad.write_text("frame: Whisk\nelements: {theme: {type: bowlful}}\n")
    result = runner.invoke(app, ["frames", "--framelib", str(bad)])
    assert result.exit_code == 1
    assert f"error: {bad}:2:" in result.stderr


def test_usage_errors_are_exit_2() -> None:
    assert runner.invoke(app, ["validate"]).exit_code == 2
    assert runner.invoke(app, ["frames", "--bogus"]).exit_code == 2


def test_a_usage_error_prints_a_huge_value_cut() -> None:
    """typer echoed a value whole: 5,000 digits of --seed were a box of 65 lines, 100,000 letters 107 KB."""
    for argv, named in ((["localize", "--seed", "1" * 5_000], "--seed"), (["x" * 100_000], "No such command"),
                        (["plan", "stir", *["w"] * 30_000], "unexpected extra")):
        result = runner.invoke(app, argv)
        assert result.exit_code == 2 and named in result.stderr and len(result.stderr) < 4_000
        assert "…" in result.stderr


def test_the_console_script_runs_without_a_traceback(tmp_path: Path) -> None:
    missing = tmp_path / "missing.yaml"
    run = subprocess.run([sys.executable, "-m", "seal_cli", "validate", str(missing)],
                         capture_output=True, text=True)
    assert run.returncode == 1
    assert f"{missing}: no such file or folder" in run.stdout
    assert "Traceback" not in run.stderr


def test_the_processes_the_tests_start_run_this_trees_code(tmp_path: Path) -> None:
    """The venv's seal may be installed from another checkout: ``python -m seal_cli`` from any folder runs the
    seal_cli of the tree these tests are in (``tests/conftest.py`` puts it first on PYTHONPATH)."""
    run = subprocess.run([sys.executable, "-c", "import seal_cli; print(seal_cli.__file__)"], cwd=tmp_path,
                         capture_output=True, text=True, check=True)
    assert Path(run.stdout.strip()) == Path(__file__).resolve().parents[2] / "seal_cli" / "__init__.py"


def test_tables_are_not_cut_when_the_output_is_not_a_terminal() -> None:
    """A redirected table once truncated at rich's 80 columns ('holding(instru|ment)', 'particl…')."""
    import os
    import subprocess
    import sys

    env = {k: v for k, v in os.environ.items() if k != "COLUMNS"}
    result = subprocess.run([sys.executable, "-m", "seal_cli", "frames"], capture_output=True, text=True, env=env,
                            timeout=120, check=False)
    assert result.returncode == 0, result.stderr
    assert "holding(instrument)" in result.stdout and "…" not in result.stdout


def test_an_empty_file_or_folder_name_is_refused_naming_the_option(tmp_path: Path) -> None:
    """typer reads '' as '.': `plan --pddl ''` wrote domain.pddl and problem.pddl into the current folder."""
    for argv, says in ((["plan", "--pddl", "", "stir the cup"], "--pddl is empty"),
                       (["plan", "--pddl=", "stir the cup"], "--pddl is empty"),
                       (["parse", "--vocabulary", "", "stir the cup"], "--vocabulary is empty"),
                       (["validate", ""], "an empty PATH")):
        done = subprocess.run([sys.executable, "-m", "seal_cli", *argv], cwd=tmp_path, capture_output=True, text=True)
        assert done.returncode == 1 and says in done.stderr and "Traceback" not in done.stderr, (argv, done.stderr)
        assert list(tmp_path.iterdir()) == []
    done = subprocess.run([sys.executable, "-m", "seal_cli", "plan", "--done", "", "stir the cup"], cwd=tmp_path,
                          capture_output=True, text=True)
    assert "--done is empty (an empty command says nothing)" in done.stderr  # a text's problem, not a path's


def test_an_empty_value_of_any_option_is_refused_naming_it_as_typed(tmp_path: Path) -> None:
    """hostile27: `plan --holding ''` planned with the map's robot's hand and `run --holding ''` with an empty one;
    `--task ''` was "column 1: empty command"; `run --vocabulary ''` said "an empty VOCABULARY_FILE" (its parameter's
    name); `bench perf --scale ''` "unknown scale ;". Each now names the option as typed; an empty --map still lists
    the shipped maps."""
    for argv, says in ((["plan", "stir the cup", "--holding", ""],
                        "--holding is empty: give a value (the class of what the robot holds"),
                       (["plan", "stir the cup", "--holding="], "--holding is empty"),
                       (["localize", "--map", "studio", "--task", ""], "--task is empty (an empty command"),
                       (["run", "go to the sofa", "--map", "studio", "--vocabulary", ""], "--vocabulary is empty"),
                       (["parse", "-f", ""], "-f is empty"),
                       (["bench", "perf", "--scale", ""], "--scale is empty: give a value (paper, building or large"),
                       (["plan", "stir the cup", "--map", ""], "the map's name is empty: give a map file")):
        done = subprocess.run([sys.executable, "-m", "seal_cli", *argv], cwd=tmp_path, capture_output=True, text=True)
        assert done.returncode == 1 and says in done.stderr and "Traceback" not in done.stderr, (argv, done.stderr)
        assert list(tmp_path.iterdir()) == []


def test_framelib_plus_alone_is_refused_not_read_as_the_current_folder(tmp_path: Path) -> None:
    from seal_cli.cli import framelib_paths

    with pytest.raises(SealError, match=r"--framelib \+: give a file or folder after the '\+'"):
        framelib_paths([Path("+")])
    assert framelib_paths([Path("+x")])[1:] == [Path("x")]
    result = runner.invoke(app, ["frames", "--framelib", "+"])
    assert result.exit_code == 1 and "give a file or folder after" in result.output


def test_an_option_listing_names_refuses_none_unknown_and_twice() -> None:
    from seal_cli.cli import choices

    assert choices("--policies", ["sefm, coverage"], ("sefm", "coverage"), "policy") == ["sefm", "coverage"]
    assert choices("--format", ["mcap", "ros1"], ("mcap", "ros1"), "format") == ["mcap", "ros1"]
    for given, said in ((["sefm,sefm"], "names 'sefm' twice"), ([","], "names nothing"), ([""], "names nothing"),
                        (["sefm,zz"], "unknown policy 'zz'; known: sefm, coverage")):
        with pytest.raises(SealError, match=said):
            choices("--policies", given, ("sefm", "coverage"), "policy")
    result = runner.invoke(app, ["bench", "tasks", "--suite", "map", "--map", "apartment", "--policies", "sefm,sefm"])
    assert result.exit_code == 1 and "--policies 'sefm,sefm' names 'sefm' twice" in result.output


def test_a_reliability_match_that_matches_nothing_is_refused() -> None:
    result = runner.invoke(app, ["bench", "reliability", "--match", "no such case zzz", "--count", "0"])
    assert result.exit_code == 1 and "--match 'no such case zzz': no case's name holds this text" in result.output


def test_plan_says_what_is_odd_about_its_map(tmp_path: Path) -> None:
    """Areas that overlap are a warning ``run``, ``localize`` and ``map`` said and ``plan`` kept quiet about
    (hostile25): it is said before the plan, at the map's line and column, and the plan goes on."""
    (tmp_path / "m.yaml").write_text("name: m\nbounds: [0, 0, 10, 10]\nrooms:\n  - {name: west, box: [0, 0, 6, 10]}\n"
                                     "  - {name: east, box: [4, 0, 10, 10]}\n")
    result = runner.invoke(app, ["plan", "go to the west", "--map", str(tmp_path / "m.yaml")])
    assert result.exit_code == 0 and "Go" in result.stdout
    assert result.stderr.startswith(f"warning: {tmp_path / 'm.yaml'}:5:5: room east overlaps room west (line 4)")
