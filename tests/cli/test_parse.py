"""``seal parse`` and ``seal bench parse`` as a user meets them: JSON, JSON Lines, trees, errors."""

from __future__ import annotations

import json
from pathlib import Path

import pytest
from typer.testing import CliRunner

from seal_cli.cli import app

runner = CliRunner()


def test_parse_json_prints_the_frames() -> None:
    result = runner.invoke(app, ["parse", "bring Roger a coffee from the kitchen", "--json"])
    assert result.exit_code == 0, result.output
    data = json.loads(result.stdout)
    assert data["text"] == "bring Roger a coffee from the kitchen"
    assert [f["frame"] for f in data["frames"]] == ["Bring"]
    assert data["frames"][0]["elements"]["recipient"] == {"text": "Roger", "head": "Roger", "class": None,
                                                          "kind": "person"}


def test_parse_prints_a_tree_without_json() -> None:
    result = runner.invoke(app, ["parse", "stir the cup and put it on the table"])
    assert result.exit_code == 0, result.output
    for words in ("0. Stir", "1. Place", "theme", "instrument", "default", "→ frame 0 theme"):
        assert words in result.stdout


def test_the_tree_shows_a_condition_on_the_world() -> None:
    result = runner.invoke(app, ["parse", "when the water boils, turn off the stove"])
    assert result.exit_code == 0, result.output
    assert result.stdout.splitlines()[-1] == "    └── condition: when the water boils"


def test_the_tree_and_the_json_show_the_state_a_question_asks() -> None:
    result = runner.invoke(app, ["parse", "is the garage door still open?"])
    assert result.exit_code == 0, result.output
    assert result.stdout.splitlines()[-1] == "    └── asked: still open"
    data = json.loads(runner.invoke(app, ["parse", "is the garage door still open?", "--json"]).stdout)
    assert data["frames"][0]["frame"] == "LookAt" and data["frames"][0]["asked"] == "still open"


def test_an_unparsable_command_is_a_message_with_a_caret_and_exit_1() -> None:
    result = runner.invoke(app, ["parse", "launch the rocket"])
    assert result.exit_code == 1
    assert "unknown verb 'launch'" in result.stderr and "the robot can" in result.stderr
    assert "launch the rocket\n^" in result.stderr
    assert "Traceback" not in result.output


def test_an_unparsable_command_with_json_is_an_error_object() -> None:
    result = runner.invoke(app, ["parse", "bring me the", "--json"])
    assert result.exit_code == 1
    data = json.loads(result.stdout)
    assert data["text"] == "bring me the"
    assert set(data["error"]) == {"message", "column", "expected"} and data["error"]["column"] == 13


def test_file_mode_writes_one_json_line_per_input_line(tmp_path: Path) -> None:
    commands = tmp_path / "commands.txt"
    commands.write_text("go to the kitchen\n\nlaunch the rocket\nfind Robin and follow them\n", encoding="utf-8")
    result = runner.invoke(app, ["parse", "--file", str(commands), "--json"])
    assert result.exit_code == 0                      # lines that fail are error objects, not a failure
    lines = [json.loads(line) for line in result.stdout.splitlines()]
    assert len(lines) == 4
    assert [("frames" in x, "error" in x) for x in lines] == [(True, False), (False, True), (False, True),
                                                              (True, False)]
    assert lines[3]["frames"][1]["elements"]["theme"]["refers_to"] == [0, "theme"]


def test_file_mode_reads_standard_input() -> None:
    result = runner.invoke(app, ["parse", "--file", "-", "--json"], input="go to the kitchen\nfind the cup\n")
    assert result.exit_code == 0
    assert [json.loads(x)["frames"][0]["frame"] for x in result.stdout.splitlines()] == ["Go", "Find"]


def test_file_mode_without_json_prints_a_line_per_command(tmp_path: Path) -> None:
    result = runner.invoke(app, ["parse", "--file", "-"], input="go to the kitchen\nlaunch it\n")
    assert result.exit_code == 0
    assert "1: Go(goal=kitchen)" in result.stdout and "2: error unknown verb 'launch'" in result.stdout


def test_a_missing_file_is_exit_1(tmp_path: Path) -> None:
    result = runner.invoke(app, ["parse", "--file", str(tmp_path / "nope.txt"), "--json"])
    assert result.exit_code == 1 and "no such file" in result.stderr and not result.stdout


def test_text_or_file_not_both_nor_neither_is_a_usage_error() -> None:
    for args in (["parse"], ["parse", "go home", "--file", "-"]):
        result = runner.invoke(app, args, input="")
        assert result.exit_code == 2 and "give either a command or --file" in result.stderr


def test_vocabulary_grounds_elements(tmp_path: Path) -> None:
    vocab = tmp_path / "vocab.yaml"
    vocab.write_text("- AlarmClock\n- {class: Fridge, synonyms: [refrigerator]}\n", encoding="utf-8")
    result = runner.invoke(app, ["parse", "put the clock in the refrigerator", "--json", "--vocabulary", str(vocab)])
    assert result.exit_code == 0, result.output
    elements = json.loads(result.stdout)["frames"][0]["elements"]
    assert (elements["theme"]["class"], elements["goal"]["class"]) == ("AlarmClock", "Fridge")


def test_a_bad_vocabulary_is_exit_1(tmp_path: Path) -> None:
    vocab = tmp_path / "vocab.yaml"
    vocab.write_text("cup: 1\n", encoding="utf-8")
    result = runner.invoke(app, ["parse", "find the cup", "--vocabulary", str(vocab)])
    assert result.exit_code == 1 and "YAML list" in result.stderr


def test_map_classes_ground_elements() -> None:
    pytest.importorskip("seal_cli.maps.model")
    result = runner.invoke(app, ["parse", "take the spoon from the fridge", "--json", "--map", "apartment"])
    assert result.exit_code == 0, result.output
    elements = json.loads(result.stdout)["frames"][0]["elements"]
    assert (elements["theme"]["class"], elements["source"]["class"]) == ("spoon", "fridge")


def test_bench_parse_runs_the_scorer(shared_data: Path, tmp_path: Path) -> None:
    scorers = shared_data.parent / "eval"
    if not (scorers / "score_parse.py").is_file():
        pytest.skip("the shared scorers are not here")
    corpus = tmp_path / "tiny.jsonl"
    corpus.write_text("\n".join(json.dumps(x) for x in [
        {"text": "bring me the cup", "expect": [{"frame": "Bring|Give", "elements": {"recipient": "me"}}]},
        {"text": "go to the kitchen", "expect": [{"frame": "Go", "elements": {"goal": "kitchen"}}]},
    ]) + "\n", encoding="utf-8")
    result = runner.invoke(app, ["bench", "parse", "--corpus", str(corpus), "--json"])
    assert result.exit_code == 0, result.output
    figures = json.loads(result.stdout)["corpora"][str(corpus)]
    assert figures["n"] == 2 and figures["frames"] == 1.0 and figures["roles"] == 1.0
    in_process = figures["in_process"]
    assert (in_process["commands"], in_process["parsed"], in_process["silent_swallowed"]) == (2, 2, 0)
    assert in_process["commands_per_cpu_s"] > 0


@pytest.mark.parametrize(("content", "expected"), [
    (b"\x84\x00binary", "is not UTF-8 text"),
    (b"- a\n- b\n", ":1:1: not JSON"),
    (b'{"text": "stir the cup", "expect": []}\n{"text": oops}\n', ":2:10: not JSON"),
    (b'{"text": "stir the cup", "expect": []}\n[1, 2]\n', ":2:1: this line is a list, not a JSON object"),
    (b"", "this corpus holds no commands"),  # hostile19: the scorer divided by zero
    (b"\n\n", "this corpus holds no commands"),
    (b'{"frames": []}\n', ":1:1: this command has no 'text'"),  # hostile28: the scorer's KeyError
])
def test_bench_parse_refuses_a_corpus_that_is_not_json_lines(tmp_path: Path, content: bytes, expected: str) -> None:
    corpus = tmp_path / "bad.jsonl"
    corpus.write_bytes(content)
    (tmp_path / "score_parse.py").write_text("raise SystemExit('never run')\n")  # a scorer found: the corpus is judged
    for extra in ([], ["--json"]):
        result = runner.invoke(app, ["bench", "parse", "--corpus", str(corpus), "--scorers", str(tmp_path), *extra])
        assert result.exit_code == 1, result.output
        assert f"error: {corpus}" in result.stderr and expected in result.stderr
        assert "Traceback" not in result.output + result.stderr


def test_bench_parse_refuses_constants_no_corpus_reads(tmp_path: Path) -> None:
    # --constants with only JSON Lines corpora was passed over (hostile20): they are read for .tsv goals only
    corpus = tmp_path / "c.jsonl"
    corpus.write_text('{"text": "stir the cup"}\n')
    result = runner.invoke(app, ["bench", "parse", "--corpus", str(corpus), "--constants", "k.json"])
    said = "error: --constants k.json: the ALFRED constants are read for ALFRED goals (a .tsv --corpus), and no "
    assert (result.exit_code, result.stderr) == (1, said + "--corpus given is one\n")


def test_bench_parse_reports_a_crashing_scorer_as_an_error(tmp_path: Path) -> None:
    corpus = tmp_path / "odd.jsonl"
    corpus.write_text('{"text": "go to the kitchen", "expect": [{"frame": "Go"}]}\n', encoding="utf-8")
    (tmp_path / "score_parse.py").write_text("raise RuntimeError('the scorer broke')\n")
    result = runner.invoke(app, ["bench", "parse", "--corpus", str(corpus), "--scorers", str(tmp_path)])
    assert result.exit_code == 1, result.output
    assert f"the scorer failed on {corpus}: RuntimeError: the scorer broke" in result.stderr
    assert "Traceback" not in result.output + result.stderr



@pytest.mark.parametrize(("make", "said"), [("fifo", "is a FIFO (named pipe), not a scorer"),
                                            ("dir", "is a folder, not a scorer"), ("none", "not found")])
def test_bench_parse_says_what_stands_where_the_scorer_goes(tmp_path: Path, make: str, said: str) -> None:
    """hostile30: a FIFO or a folder named score_parse.py was "scorer not found"."""
    import os

    corpus = tmp_path / "c.jsonl"
    corpus.write_text('{"text": "go to the kitchen", "expect": [{"frame": "Go"}]}\n', encoding="utf-8")
    scorer = tmp_path / "s" / "score_parse.py"
    scorer.parent.mkdir()
    if make == "fifo":
        os.mkfifo(scorer)
    elif make == "dir":
        scorer.mkdir()
    result = runner.invoke(app, ["bench", "parse", "--corpus", str(corpus), "--scorers", str(scorer.parent)])
    assert result.exit_code == 1 and f"scorer {scorer} {said} (give --scorers DIR" in result.stderr


GO = '"text": "go to the kitchen"'


@pytest.mark.parametrize(("line", "expected"), [
    ("{" + GO + '}', ":1:1: this command says nothing to score it by: give 'expect'"),
    ("{" + GO + ', "command_types": ["goToLoc"]}', ":1:1: this GPSR command has no 'fills'"),
    ("{" + GO + ', "command_types": [], "fills": []}', ":1:31: its 'command_types' is an empty list"),
    ("{" + GO + ', "command_types": ["goToLoc"], "fills": [{"placeholder": "loc"}]}', ":1:61: fill 1 has no 'value'"),
    ("{" + GO + ', "expect": "Go"}', ":1:31: its 'expect' is a string, not a list of frames"),
    ("{" + GO + ', "expect": [{"elements": {}}]}', ":1:31: frame 1 of its 'expect' has no 'frame'"),
    ("{" + GO + ', "expect": [{"frame": "Go", "elements": {"goal": 1e999}}]}',
     ":1:71: element 'goal' of frame 1 of its 'expect' is the number inf, not a string"),
    ('{"text": NaN, "expect": []}', ":1:2: its 'text' is the number nan, not a string"),
    ('{"text": "go\\udc80", "expect": []}', ":1:13: \\udc80 is half a character"),
])
def test_bench_parse_names_the_line_and_the_field_the_scorer_would_miss(tmp_path: Path, line: str,
                                                                         expected: str) -> None:
    # hostile28: each was a KeyError, AttributeError or UnicodeEncodeError inside the shared scorer, "the scorer
    # failed on c.jsonl: KeyError: 'command_types'", naming no line; the scorer is never run on them now
    corpus = tmp_path / "c.jsonl"
    corpus.write_text(line + "\n", encoding="utf-8")
    (tmp_path / "score_parse.py").write_text("raise SystemExit('never run')\n")
    result = runner.invoke(app, ["bench", "parse", "--corpus", str(corpus), "--scorers", str(tmp_path)])
    assert result.exit_code == 1, result.output
    assert f"error: {corpus}{expected}" in result.stderr and "Traceback" not in result.output + result.stderr


ALFRED = "task_type\tobject\treceptacle\tmrecep\tsliced\tgoal_sentence\n"


@pytest.mark.parametrize(("table", "expected"), [
    ("goal_sentence\nput an apple in the fridge\n", ":1:1: this ALFRED goals table has no columns 'task_type', "),
    (ALFRED + "pick_and_place_simple\tApple\n", ":2:1: this row has no 'receptacle', 'mrecep', 'sliced', "
                                                 "'goal_sentence': it has 2 of the header's 6 columns"),
])
def test_bench_parse_names_what_an_alfred_table_lacks(tmp_path: Path, table: str, expected: str) -> None:
    corpus = tmp_path / "g.tsv"
    corpus.write_text(table, encoding="utf-8")
    result = runner.invoke(app, ["bench", "parse", "--corpus", str(corpus), "--scorers", str(tmp_path)])
    assert result.exit_code == 1, result.output
    assert f"error: {corpus}{expected}" in result.stderr


def test_bench_parse_refuses_constants_whose_classes_are_not_names(tmp_path: Path) -> None:
    corpus = tmp_path / "g.tsv"
    corpus.write_text(ALFRED + "pick_and_place_simple\tApple\tFridge\t\t0\tput an apple in the fridge\n")
    constants = tmp_path / "k.json"
    constants.write_text('{"OBJECTS": ["Apple", 5]}')
    result = runner.invoke(app, ["bench", "parse", "--corpus", str(corpus), "--constants", str(constants)])
    assert result.exit_code == 1, result.output
    assert f"error: {constants}: the ALFRED constants' OBJECTS holds 5, not a class name" in result.stderr


def test_bench_parse_scores_a_corpus_with_a_bom_and_crlf(shared_data: Path, tmp_path: Path) -> None:
    # the scorer reads seal's plain copy: on the file itself it failed on the BOM ("Unexpected UTF-8 BOM")
    if not (shared_data.parent / "eval" / "score_parse.py").is_file():
        pytest.skip("the shared scorers are not here")
    corpus = tmp_path / "c.jsonl"
    line = "{" + GO + ', "expect": [{"frame": "Go", "elements": {"goal": "kitchen"}}]}'
    corpus.write_bytes(("\ufeff" + line + "\r\n").encode())
    result = runner.invoke(app, ["bench", "parse", "--corpus", str(corpus), "--json"])
    assert result.exit_code == 0, result.output
    figures = json.loads(result.stdout)["corpora"][str(corpus)]
    assert (figures["n"], figures["frames"], figures["roles"]) == (1, 1.0, 1.0)
