"""``seal run`` on the shipped apartment and ``seal bench tasks`` on a few real episodes, through the CLI."""

from __future__ import annotations

import json
from pathlib import Path

import pytest
from typer.testing import CliRunner

from seal_cli.cli import app
from seal_cli.sim.policies import DEFAULT_POLICIES

runner = CliRunner()


def test_run_stir_the_cup_narrates_and_finishes(tmp_path: Path) -> None:
    png, rrd = tmp_path / "run.png", tmp_path / "run.rrd"
    result = runner.invoke(app, ["run", "--map", "apartment", "stir the cup", "--png", str(png), "--rrd", str(rrd),
                                 "--particles", "100"])
    assert result.exit_code == 0, result.output
    assert "plan: Pick(theme=spoon), Stir(theme=cup, instrument=spoon)" in result.output
    assert "picked up spoon_1" in result.output and "stirred cup_1 with spoon_1" in result.output
    assert png.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
    import rerun as rr

    summary = str(rr.chunk.RrdReader(str(rrd)).stream().collect().summary())
    for entity in ("/robot/path", "/robot/pose", "/map/places", "/objects/particles", "/observations",
                   "/frames/particles", "/metrics/path_m"):
        assert entity in summary, entity


def test_run_json_is_reproducible_and_holding_skips_the_pick() -> None:
    args = ["run", "--map", "apartment", "stir the cup", "--json", "--seed", "3", "--particles", "100"]
    first = json.loads(runner.invoke(app, args).stdout)
    again = json.loads(runner.invoke(app, args).stdout)
    assert first == again and first["completed"] and first["path_m"] > 0
    held = json.loads(runner.invoke(app, [*args, "--holding", "spoon"]).stdout)
    assert held["plan"] == ["Stir(theme=cup, instrument=spoon)"] and held["path_m"] < first["path_m"]


def test_run_refuses_what_cannot_be_done() -> None:
    result = runner.invoke(app, ["run", "--map", "apartment", "pick up the unicorn", "--max-steps", "30",
                                 "--particles", "50"])      # (e2e27: refused before the run, where it is said)
    assert result.exit_code == 1 and "column 9: the apartment knows no unicorn" in result.output
    assert "Traceback" not in result.output
    json_run = runner.invoke(app, ["run", "--map", "bungalow", "find the unicorn", "--json"])
    assert json_run.exit_code == 1 and not json.loads(json_run.stdout)["completed"]      # SPEC: exit 1, why on stderr
    assert json_run.stderr.startswith("not done: no unicorn found")
    plain_run = runner.invoke(app, ["run", "--map", "bungalow", "find the unicorn"])
    assert plain_run.exit_code == 1 and "not done" not in plain_run.stdout and "not done" in plain_run.stderr
    bad = runner.invoke(app, ["run", "--map", "no_such_map.yaml", "stir the cup"])
    assert bad.exit_code == 1 and "Traceback" not in bad.output
    unknown = runner.invoke(app, ["run", "--map", "apartment", "stir the cup", "--policy", "psychic"])
    assert unknown.exit_code == 1 and "unknown policy" in unknown.output


def test_bench_tasks_json_has_every_group(shared_data: Path) -> None:
    result = runner.invoke(app, ["bench", "tasks", "--suite", "alfred2d", "--data", str(shared_data / "alfred2d"),
                                 "--split", "valid_seen", "--goal", "gold", "--limit", "1", "--jobs", "1",
                                 "--type", "pick_heat_then_place_in_recep", "--type", "look_at_obj_in_light",
                                 "--particles", "100", "--json"])
    assert result.exit_code == 0, result.output
    report = json.loads(result.stdout)
    assert list(report["groups"]) == ["look_at_obj_in_light", "pick_heat_then_place_in_recep", "all"]
    for figures in report["groups"].values():
        assert set(figures["success"]) == set(DEFAULT_POLICIES)
        assert set(figures["path_m"]) == set(DEFAULT_POLICIES)


def test_bench_tasks_table_and_bad_options(shared_data: Path) -> None:
    ok = runner.invoke(app, ["bench", "tasks", "--data", str(shared_data / "alfred2d"), "--limit", "1",
                             "--type", "pick_and_place_simple", "--policies", "oracle", "--jobs", "1"])
    assert ok.exit_code == 0 and "pick_and_place_simple" in ok.stdout and "oracle" in ok.stdout
    bad_goal = runner.invoke(app, ["bench", "tasks", "--data", str(shared_data / "alfred2d"), "--goal", "mind"])
    assert bad_goal.exit_code == 1 and "unknown goal source" in bad_goal.output
    bad_suite = runner.invoke(app, ["bench", "tasks", "--suite", "thor"])
    assert bad_suite.exit_code == 1 and "unknown suite" in bad_suite.output


def test_run_grounds_words_in_the_map_and_a_vocabulary_file(tmp_path: Path) -> None:
    words = tmp_path / "words.yaml"
    words.write_text("- {class: cup, synonyms: [beaker]}\n- {class: pineapple, synonyms: [ananas]}\n", encoding="utf-8")
    args = ["run", "--map", "apartment", "stir the beaker", "--json", "--particles", "50", "--max-steps", "5"]
    plain = runner.invoke(app, args)          # no such class: refused before anything moves (lead, stop 39)
    assert plain.exit_code == 1 and "the apartment knows no beaker" in plain.output
    named = json.loads(runner.invoke(app, [*args, "--vocabulary", str(words)]).stdout)
    assert named["plan"] == ["Pick(theme=spoon)", "Stir(theme=cup, instrument=spoon)"]
    missing = runner.invoke(app, [*args, "--vocabulary", str(tmp_path / "none.yaml")])
    assert missing.exit_code == 1 and "Traceback" not in missing.output


def test_the_budgets_are_kept_inside_a_leg() -> None:
    """--max-metres 0.1 once drove 6.17 m and --max-steps 1 took 7: a leg is cut where the budget ends."""
    runner = CliRunner()
    for metres in ("0.1", "5"):
        result = runner.invoke(app, ["run", "--map", "apartment", "stir the cup", "--max-metres", metres, "--json"])
        data = json.loads(result.stdout)
        assert result.exit_code == 1 and not data["completed"]
        assert data["path_m"] <= float(metres) + 1e-6 and data["reason"] == f"out of path budget ({metres} m)"
    result = runner.invoke(app, ["run", "--map", "apartment", "stir the cup", "--max-steps", "1", "--json"])
    data = json.loads(result.stdout)
    assert data["steps"] == 1 and data["reason"] == "out of steps (1)"


def test_particles_are_bounded_like_localize() -> None:
    runner = CliRunner()
    for args in (["run", "--map", "apartment", "stir the cup"], ["bench", "tasks"]):
        result = runner.invoke(app, [*args, "--particles", "1000000000"])
        assert result.exit_code == 2 and "1<=x<=100000" in result.output



@pytest.mark.parametrize("command", [["run", "--map", "apartment", "stir the cup"],
                                     ["plan", "--map", "apartment", "stir the cup"],
                                     ["localize", "--map", "apartment", "--task", "stir the cup"]])
def test_holding_given_twice_is_refused_naming_both(command: list[str], tmp_path: Path) -> None:
    """`--holding spoon --holding cup` kept the cup silently (typer's last value): the robot holds one thing."""
    png = tmp_path / "out.png"
    extra = [] if command[0] == "plan" else ["--png", str(png)]
    result = runner.invoke(app, [*command, "--holding", "spoon", "--holding", "cup", *extra])
    assert result.exit_code == 1
    assert "--holding is given 2 times ('spoon', 'cup')" in result.stderr and "one thing" in result.stderr
    assert result.stdout == "" and not png.exists()


def test_holding_given_once_is_what_the_robot_holds() -> None:
    result = runner.invoke(app, ["plan", "--map", "apartment", "stir the cup", "--holding", "spoon", "--json"])
    assert result.exit_code == 0
    assert [s["frame"] for s in json.loads(result.stdout)["plan"]] == ["Stir"]


@pytest.mark.parametrize(("args", "said"), [
    (["--suite", "map", "--type", "x"], "error: --suite map does not read --type: --type goes with --suite alfred2d\n"),
    (["--suite", "map", "--limit", "1", "--split", "train"],
     "error: --suite map does not read --split, --limit: --split goes with --suite alfred2d; --limit goes with --suite "
     "alfred2d\n"),
    (["--map", "townhouse"], "error: --suite alfred2d does not read --map: --map goes with --suite map\n"),
    (["--suite", "context", "--goal", "human", "--layouts", "1"],
     "error: --suite context does not read --goal: --goal goes with --suite alfred2d\n"),
    (["--suite", "map", "--data", "."], "error: --suite map does not read --data: --data goes with --suite alfred2d or "
                                        "context or context_all\n"),
    # the held-out houses are drawn in code: a --data given them was passed over (hostile29)
    (["--suite", "context_held_out", "--data", "/dev/null"],
     "error: --suite context_held_out does not read --data: --data goes with --suite alfred2d or context or "
     "context_all\n"),
    # the context suite's own options are in the same table, with the same message (hostile21: they had a check of
    # their own, by value, so '--houses suite' to another suite passed)
    (["--houses", "suite", "--fov", "90"],
     "error: --suite alfred2d does not read --houses, --fov: --houses goes with --suite context_all; --fov goes with "
     "--suite context or context_all or context_held_out\n"),
    # the chosen cases have their own starts: --houses and --starts go with the whole suite (search26)
    (["--suite", "context", "--houses", "unseen", "--starts", "2"],
     "error: --suite context does not read --houses, --starts: --houses goes with --suite context_all; --starts goes "
     "with --suite context_all\n"),
    (["--suite", "map", "--starts", "2", "--type", "x"],
     "error: --suite map does not read --type, --starts: --type goes with --suite alfred2d; --starts goes with --suite "
     "context_all\n"),
])
def test_bench_tasks_refuses_an_option_its_suite_does_not_read(args: list[str], said: str) -> None:
    # given to a suite that does not read it, an option was passed over: '--suite map --type x' ran the whole suite for
    # minutes (hostile20); refused before any work, even when given its default's value ('--split valid_seen' too)
    result = runner.invoke(app, ["bench", "tasks", *args])
    assert (result.exit_code, result.stderr) == (1, said)
    again = runner.invoke(app, ["bench", "tasks", "--suite", "map", "--split", "valid_seen", "--goal", "gold"])
    assert again.exit_code == 1 and "--suite map does not read --split, --goal" in again.stderr


def test_run_refuses_a_png_onto_its_own_standard_output(tmp_path: Path) -> None:
    """``--png`` naming the file standard output goes to (``/dev/stdout``; here a file stdout is redirected to) is
    refused before the robot moves, exit 1 with the option named on stderr: the picture would be mixed with the
    run's lines (e2e22). The same picture to another file is written."""
    import os
    import subprocess
    import sys

    root = Path(__file__).resolve().parents[2]
    env = {**os.environ, "PYTHONPATH": str(root)}
    shared = tmp_path / "out.png"
    args = [sys.executable, "-m", "seal_cli", "run", "--map", "apartment", "go to the kitchen", "--particles", "50"]
    with shared.open("wb") as stdout:
        refused = subprocess.run([*args, "--png", str(shared)], stdout=stdout, stderr=subprocess.PIPE, env=env,
                                 cwd=tmp_path, text=False, check=False)
    said = refused.stderr.decode()
    assert refused.returncode == 1 and "--png" in said and "standard output" in said and "Traceback" not in said
    assert shared.read_bytes() == b""        # nothing written onto the stream, the robot never moved
    apart = tmp_path / "apart.png"
    with (tmp_path / "lines.txt").open("wb") as stdout:
        written = subprocess.run([*args, "--png", str(apart)], stdout=stdout, stderr=subprocess.PIPE, env=env,
                                 cwd=tmp_path, check=False)
    assert written.returncode == 0, written.stderr.decode()
    assert apart.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n" and b"done" in (tmp_path / "lines.txt").read_bytes()


def test_a_run_not_done_draws_its_whole_picture_and_says_so(tmp_path: Path) -> None:
    """A run that ends not done (exit 1) writes its --png and --rrd whole, the picture of where it searched, and
    says so under its "not done" line, so that a script reading the exit code knows they are a failure's
    (hostile25); a run refused before it starts writes neither."""
    png, rrd = tmp_path / "o.png", tmp_path / "o.rrd"
    args = ["run", "--map", "bungalow", "find the unicorn", "--particles", "20", "--png", str(png), "--rrd",
            str(rrd)]    # a Find is still searched (a thing to fetch the house knows nothing of is refused, e2e27)
    result = runner.invoke(app, args)
    assert result.exit_code == 1 and result.stderr.startswith("not done: no unicorn found"), result.output
    assert result.stderr.splitlines()[1] == (f"written all the same, to show where the robot searched: its picture "
                                             f"{png} and its recording {rrd}")
    assert png.read_bytes().endswith(b"IEND\xaeB`\x82") and rrd.stat().st_size > 0
    png.unlink()
    rrd.unlink()
    refused = runner.invoke(app, [*args[:3], "put the unicorn in the spaceship", *args[4:]])
    assert refused.exit_code == 1 and "not done" not in refused.output and list(tmp_path.iterdir()) == []


def test_run_says_on_the_balcony_and_passes_a_message_on_in_the_third_person() -> None:
    """words45: "Sam is in the balcony" and Nora told the robot's "I'm ready"."""
    where = runner.invoke(app, ["run", "--map", "studio", "where is Sam", "--particles", "100"])
    assert where.exit_code == 0, where.output
    assert "answer: Sam is on the balcony at (7.00, 7.00)" in where.output and "in the balcony" not in where.output
    told = runner.invoke(app, ["run", "--map", "studio", "tell Nora I'm ready", "--particles", "100"])
    assert told.exit_code == 0, told.output
    assert 'said "the person who sent me says they\'re ready"' in told.output


@pytest.mark.parametrize(("policy", "options", "says"), [
    ("oracle", ["--search-end", "0.5"], "--search-end is not read by --policy oracle, which knows where everything is "
                                        "and never searches: leave it out"),
    ("oracle", ["--search-end", "0.05"], "--search-end is not read by --policy oracle"),        # its default, given
    ("coverage", ["--particles", "50"], "--particles is not read by --policy coverage, which keeps no particle beliefs "
                                        "(--particles goes with sefm, object_only, uniform): leave it out"),
    ("prior_optimal", ["--particles", "50", "--search-end", "0.5"], "--particles is not read by --policy "
                                                                     "prior_optimal"),
    ("saycan", ["--clock", "10:00", "--vocabulary", "v.yaml"], "--clock and --vocabulary are not read by --policy "
                                                               "saycan, which runs from the instruction text alone"),
])
def test_an_option_the_policy_never_reads_is_refused_before_any_work(policy: str, options: list[str],
                                                                     says: str) -> None:
    """``--policy oracle --search-end 0.5`` was taken and nothing done with it: the oracle never searches
    (hostile32)."""
    result = runner.invoke(app, ["run", "go to the sofa", "--map", "studio", "--policy", policy, *options])
    assert result.exit_code == 1 and f"error: {says}" in result.output, result.output


def test_the_options_a_policy_reads_stay() -> None:
    from seal_cli.sim.policies import POLICIES

    assert {n for n, e in POLICIES.items() if e.load().keeps_particles} == {"sefm", "object_only", "uniform"}
    for policy, options in (("object_only", ["--particles", "30", "--search-end", "0.5"]),
                            ("coverage", ["--search-end", "0.5"]), ("oracle", ["--clock", "10:00"])):
        result = runner.invoke(app, ["run", "go to the sofa", "--map", "studio", "--policy", policy, *options])
        assert result.exit_code == 0 and "done: Go(goal=sofa_1)" in result.output, (policy, result.output)


@pytest.mark.parametrize(("policies", "says"), [
    ("oracle", "--particles is not read by --policies oracle, which keeps no particle beliefs (--particles goes with "
               "sefm, object_only, uniform): leave it out"),
    ("oracle,coverage,prior_optimal", "--particles is not read by --policies oracle,coverage,prior_optimal: oracle "
                                      "and coverage and prior_optimal keep no particle beliefs"),
])
def test_bench_tasks_refuses_particles_no_listed_policy_reads(policies: str, says: str, tmp_path: Path) -> None:
    """``bench tasks --policies oracle --particles 20`` was taken though no policy listed keeps particles (rel33):
    refused by the rule ``seal run``'s ``--policy`` has, before any work (no ``--episodes`` written)."""
    episodes = tmp_path / "e.jsonl"
    result = runner.invoke(app, ["bench", "tasks", "--suite", "map", "--map", "studio", "--command", "go to the sofa",
                                 "--layouts", "1", "--policies", policies, "--particles", "20", "--jobs", "1",
                                 "--episodes", str(episodes)])
    assert result.exit_code == 1 and f"error: {says}" in result.output, result.output
    assert not episodes.exists()


def test_bench_tasks_keeps_particles_when_one_listed_policy_reads_them() -> None:
    """A list may mix policies: ``--particles`` one of them reads stays (the others pass it over)."""
    from seal_cli.cli.run_cmd import unread_by_policies
    from seal_cli.errors import SealError

    given = {"particles"}.__contains__
    unread_by_policies("--policies", ["oracle", "object_only"], given)          # object_only reads it: no refusal
    unread_by_policies("--policies", ["oracle"], lambda _: False)                # not given: nothing to refuse
    with pytest.raises(SealError, match=r"--particles is not read by --policies oracle,coverage"):
        unread_by_policies("--policies", ["oracle", "coverage"], given)
