"""The end-to-end suite's cases file (``bench/e2e.py``: ``load_cases``): every problem at its line and column."""

from __future__ import annotations

from pathlib import Path

import pytest

from seal_cli.bench.e2e import load_cases
from seal_cli.errors import SealError, SealErrors

GOOD = '{map: apartment, text: "go to the kitchen", plan: [Go(goal=kitchen)], run: done}'


def test_the_shipped_suite_and_a_good_file_load(tmp_path: Path) -> None:
    assert len(load_cases()) > 100
    (tmp_path / "e.yaml").write_text(f"cases:\n  - {GOOD}\n")
    [case] = load_cases(tmp_path / "e.yaml")
    assert (case.text, case.plan, case.run, case.file) == ("go to the kitchen", ("Go(goal=kitchen)",), "done", None)


@pytest.mark.parametrize(("entry", "message"), [
    (GOOD.replace("[Go(goal=kitchen)]", "5"), r"e\.yaml:2:\d+: case 1's plan must be a list, not '5'"),
    (GOOD.replace("[Go(goal=kitchen)]", "Go(goal=kitchen)"), r"e\.yaml:2:\d+: case 1's plan must be a list"),
    (GOOD.replace("[Go(goal=kitchen)]", "[{a: 1}]"), r"e\.yaml:2:\d+: a step of case 1's plan must be a single value"),
    (GOOD.replace("done", "[done]"), r"e\.yaml:2:\d+: case 1's run must be a single value, not a list"),
    (GOOD.replace("done", "finished"), r"e\.yaml:2:\d+: case 1's run is one of done, not_found, not 'finished'"),
    (GOOD.replace("run: done", "refused: nope"), r"e\.yaml:2:\d+: case 1: give exactly one of plan and refused"),
    (GOOD.replace("}", ", answer: [1]}"), r"e\.yaml:2:\d+: case 1's answer must be a single value, not a list"),
    (GOOD.replace("}", ", bogus: 1}"), r"e\.yaml:2:\d+: unknown key 'bogus' in case 1"),
    (GOOD.replace("}", ", run: done}"), r"e\.yaml:2:\d+: case 1 repeats the key 'run'"),
    (GOOD.replace('text: "go to the kitchen", ', ""), r"e\.yaml:2:\d+: case 1 has no text"),
    (GOOD.replace("apartment", "garage"), r"e\.yaml:2:\d+: case 1: no map 'garage'"),
    (GOOD.replace("}", ", done: 5}"), r"e\.yaml:2:\d+: case 1's done must be a list, not '5'"),
    (GOOD.replace("}", ", done: [[a]]}"), r"e\.yaml:2:\d+: a command of case 1's done must be a single value"),
    (GOOD.replace("}", ", holding: 5}"), r"e\.yaml:2:\d+: case 1's holding '5' is not a class name"),   # hostile31
    (GOOD.replace("}", ", holding: '!!'}"), r"e\.yaml:2:\d+: case 1's holding '!!' is not a class name"),
])
def test_a_case_of_the_wrong_shape_is_said_at_its_line_and_column(tmp_path: Path, entry: str, message: str) -> None:
    """Each was a TypeError traceback (``plan: 5``) or taken as it was (a plan of one string read letter by
    letter, an unknown key, an answer that is a list)."""
    (tmp_path / "e.yaml").write_text(f"cases:\n  - {entry}\n")
    with pytest.raises(SealError, match=message):
        load_cases(tmp_path / "e.yaml")


def test_every_case_is_checked_and_the_file_must_hold_a_list_of_cases(tmp_path: Path) -> None:
    (tmp_path / "e.yaml").write_text(f"cases:\n  - {GOOD.replace('done', 'x')}\n  - {GOOD}\n  - 5\n")
    with pytest.raises(SealErrors) as caught:
        load_cases(tmp_path / "e.yaml")
    assert [(p.line, p.message.split(" ")[0]) for p in caught.value.problems] == [(2, "case"), (4, "case")]
    for text in ("cases: 5\n", "[1]\n", "", "other: []\n"):
        (tmp_path / "e.yaml").write_text(text)
        with pytest.raises(SealError, match=r"e\.yaml(:\d+:\d+)?: (an end-to-end suite|unknown key)"):
            load_cases(tmp_path / "e.yaml")


def test_a_case_may_say_what_the_robot_holds_at_the_start(tmp_path: Path) -> None:
    """``holding``: the class in the robot's hand at the start, as ``seal run --holding``; a class it cannot hold
    is the case's refusal, not a crash."""
    from seal_cli.bench.e2e import judge
    from seal_cli.resources import map_path

    suite = tmp_path / "suite.yaml"
    suite.write_text('cases:\n'
                     '  - {map: apartment, holding: cup, text: "put it on the dining table", '
                     'plan: ["Place(theme=cup, goal=dining_table_1)"]}\n'
                     '  - {map: apartment, holding: fridge, text: "put it on the dining table", '
                     'plan: ["Place(theme=fridge, goal=dining_table_1)"]}\n')
    held, fixed = load_cases(suite)
    assert held.holding == "cup"
    verdict = judge(held, str(map_path("apartment")), 0, 50, None)
    assert verdict.plan_right, verdict.got
    refused = judge(fixed, str(map_path("apartment")), 0, 50, None)
    assert not refused.plan_right and refused.got.startswith("refused: --holding 'fridge'")


def test_a_case_may_say_the_commands_already_carried_out(tmp_path: Path) -> None:
    """``done`` (e2e30): the commands already carried out, as ``seal plan --done``; the plan starts from the house they
    left (the cup on the dining table, so back is the coffee table)."""
    from seal_cli.bench.e2e import judge
    from seal_cli.resources import map_path

    suite = tmp_path / "suite.yaml"
    suite.write_text('cases:\n'
                     '  - {map: apartment, done: ["bring the cup to the table"], text: "put it back", '
                     'plan: ["Pick(theme=cup, source=dining_table_1)", "Place(theme=cup, goal=coffee_table_1)"]}\n')
    [case] = load_cases(suite)
    assert case.done == ("bring the cup to the table",)
    verdict = judge(case, str(map_path("apartment")), 0, 50, None)
    assert verdict.plan_right, verdict.got


def test_a_suite_of_no_cases_is_refused(tmp_path: Path) -> None:
    """hostile19: `bench e2e --file` of `cases: []` ran nothing, reported "all 0" and exited 0, as if it passed."""
    (tmp_path / "e.yaml").write_text("cases: []\n")
    with pytest.raises(SealError, match=r"e\.yaml:1:8: the suite holds no cases"):
        load_cases(tmp_path / "e.yaml")


def test_a_cases_map_is_found_from_the_suite_inside_its_folder_or_seals_maps(tmp_path: Path,
                                                                            monkeypatch: pytest.MonkeyPatch) -> None:
    """``map: ../../etc/passwd`` was read as a map, and a name not beside the suite was looked for from the working
    folder (hostile32). Relative names stay in the suite's folder's tree or seal's maps; an absolute one is as
    given."""
    import os

    from seal_cli.resources import map_path, maps_dir

    suite, outside = tmp_path / "s", tmp_path / "elsewhere"
    (suite / "maps").mkdir(parents=True)
    outside.mkdir()
    studio = map_path("studio").read_text()
    for where in (suite / "maps" / "m.yaml", tmp_path / "m.yaml", outside / "o.yaml"):
        where.write_text(studio)
    monkeypatch.chdir(tmp_path)                      # m.yaml is in the working folder, not beside the suite

    def load(map_name: str) -> str | None:
        (suite / "e.yaml").write_text(f"cases:\n  - {GOOD.replace('apartment', repr(map_name))}\n")
        return load_cases(suite / "e.yaml")[0].file

    assert load("maps/m.yaml") == str((suite / "maps" / "m.yaml").resolve())
    assert load("maps/../maps/m.yaml") == str((suite / "maps" / "m.yaml").resolve())
    assert load("studio") == str(map_path("studio").resolve())                          # a shipped map by its name
    to_shipped = os.path.relpath(maps_dir() / "studio.yaml", suite)                     # seal's maps, by a path
    assert load(to_shipped) == str(map_path("studio").resolve())
    assert load(str(outside / "o.yaml")) == str((outside / "o.yaml").resolve())         # absolute: as given
    for name in ("../m.yaml", "../elsewhere/o.yaml", "../" * 20 + "etc/passwd", "maps/../../m.yaml"):
        with pytest.raises(SealError, match=rf"e\.yaml:2:\d+: case 1's map '{name}' is outside the suite's folder "
                                            rf".* give a map elsewhere by its absolute path"):
            load(name)
    with pytest.raises(SealError, match=r"e\.yaml:2:\d+: case 1: no map 'm\.yaml'"):
        load("m.yaml")


def test_a_case_text_yaml_reads_as_a_number_is_refused_at_it(tmp_path: Path) -> None:
    """``text: 5`` was scored as a plan missed (rel33); a quoted "5" is a command (which the parser then refuses)."""
    suite = tmp_path / "e.yaml"
    suite.write_text("cases:\n  - {map: studio, text: 5, plan: [Go(goal=sofa_1)]}\n", encoding="utf-8")
    with pytest.raises((SealError, SealErrors), match=r"e\.yaml:2:25: case 1's text '5' is read by YAML as int"):
        load_cases(suite)
    suite.write_text("cases:\n  - {map: studio, text: '5', refused: command}\n", encoding="utf-8")
    assert [c.text for c in load_cases(suite)] == ["5"]
