"""The help a user reads: every command's line in its group's list, and every option's help, as written."""

from __future__ import annotations

import os
import re
import subprocess
import sys
from pathlib import Path
from typing import Any

import pytest
import typer
from typer.testing import CliRunner

from seal_cli.cli import app
from seal_cli.cli.framework import short_help

runner = CliRunner()


def _commands() -> list[tuple[str, Any]]:
    """Every command of ``seal``, groups included, with its full name (``bench perf``); typer's click commands."""
    found: list[tuple[str, Any]] = []

    def walk(prefix: str, command: Any) -> None:
        found.append((prefix, command))
        if hasattr(command, "commands"):
            for name, sub in command.commands.items():
                walk(f"{prefix} {name}".strip(), sub)

    walk("", typer.main.get_command(app))
    return found


def test_short_help_is_the_first_paragraph_on_one_line() -> None:
    doc = """Updates per second of SeFM, at the paper's scale, a building's
    and a large floor's.

    More on a second paragraph."""
    assert short_help(doc) == "Updates per second of SeFM, at the paper's scale, a building's and a large floor's."


def test_every_command_is_listed_on_one_line_of_text() -> None:
    """typer keeps a docstring's line breaks in its list of commands: `seal bench --help` showed "a building's"
    and "and a large floor's" on two lines of the perf entry. Every command now says what it does in one line of
    text (wrapped only by the terminal)."""
    commands = _commands()
    assert {"parse", "plan", "localize", "run", "bench perf", "bench startup", "import-bag"} <= {n for n, _ in commands}
    for name, command in commands:
        if name and not hasattr(command, "commands"):
            assert command.short_help and "\n" not in command.short_help, name
    listing = runner.invoke(app, ["bench", "--help"], env={"COLUMNS": "400"}).stdout
    perf = next(line for line in listing.splitlines() if "│ perf " in line)
    assert "a building's and a large floor's (each in a process of its own)." in perf
    assert "reading bags, start-up cost" in listing  # the group's own help names every benchmark


def test_no_option_help_loses_a_bracket_to_rich_markup() -> None:
    """Help is rendered as rich markup, where ``[class, ...]`` is a style tag and vanished: `--labels` read "YAML
    {id: class} or  naming numeric class ids". Such a bracket must be escaped (``\\[``)."""
    for name, command in _commands():
        for param in command.params:
            text = getattr(param, "help", None) or ""
            assert not re.search(r"(?<!\\)\[[a-z#/@]", text), f"seal {name} {param.name}: {text}"
    for args in (["localize", "--help"], ["import-bag", "--help"]):
        shown = runner.invoke(app, args, env={"COLUMNS": "400"}).stdout
        assert "YAML {id: class} or [class, ...] naming" in shown, shown


def test_a_command_typed_decomposed_is_read_composed() -> None:
    """"go to the cafe" + U+0301 (an accent typed after its letter) was "unexpected character" at the accent; a
    command's text (and --task, --done, --command, --holding) is composed (NFC) before it is parsed."""
    from seal_cli.cli.framework import COMMAND_TEXTS, _composed_commands

    values = {"text": "stir the cafe\u0301", "done": ["cafe\u0301"], "map_name": "cafe\u0301.yaml"}
    assert _composed_commands(values) == {"text": "stir the caf\u00e9", "done": ["caf\u00e9"],
                                          "map_name": "cafe\u0301.yaml"}         # a file's name is left as given
    assert {"text", "tasks", "done", "commands", "holding"} <= set(COMMAND_TEXTS)
    result = CliRunner().invoke(app, ["parse", "--json", "stir the cafe\u0301"])
    assert result.exit_code == 0 and "unexpected character" not in result.output


def test_a_name_typed_with_a_slash_after_it_is_found_as_typed() -> None:
    from seal_cli.cli.framework import _typed_with_slash

    argv = ["run", "go", "--png", "o.png/", "--rrd=o.rrd/.", "m.yaml//"]
    assert _typed_with_slash("o.png", ["--png"], argv) == "o.png/"
    assert _typed_with_slash("o.rrd", ["--rrd"], argv) == "o.rrd/."
    assert _typed_with_slash("m.yaml", (), argv) == "m.yaml//"
    assert _typed_with_slash("o.png", ["--rrd"], argv) is None  # another option's value
    assert _typed_with_slash("go", (), argv) is None and _typed_with_slash("/", (), ["validate", "/"]) is None


def test_a_files_name_with_a_slash_after_it_is_refused_naming_the_option(tmp_path: Path) -> None:
    """typer's Path drops the '/': ``--rrd o.rrd/`` wrote the file o.rrd, ``--observations o.yaml/`` read o.yaml
    (hostile31). A folder's name with its '/' is read as before. This tree's code."""
    env = {**os.environ, "PYTHONPATH": str(Path(__file__).resolve().parents[2])}
    (tmp_path / "o.yaml").write_text("- pose: [-6, -3]\n  detections: []\n")
    (tmp_path / "d").mkdir()
    loc = ["localize", "--map", "apartment", "--task", "go to the kitchen", "--steps", "1", "--particles", "20"]
    for argv, says in (([*loc, "--observations", "o.yaml/"], "--observations o.yaml/: a name ending in '/' is a "
                                                             "folder's, and o.yaml is a file"),
                       (["map", "studio", "--png", "n.png/"], "--png n.png/: a name ending in '/' is a folder's, and "
                                                              "there is no folder n.png"),
                       (["validate", "o.yaml/."], "o.yaml/.: a name ending in '/' is a folder's")):
        done = subprocess.run([sys.executable, "-m", "seal_cli", *argv], cwd=tmp_path, capture_output=True, text=True,
                              env=env)
        assert done.returncode == 1 and f"error: {says}" in done.stderr and "Traceback" not in done.stderr, argv
    assert sorted(p.name for p in tmp_path.iterdir()) == ["d", "o.yaml"]
    done = subprocess.run([sys.executable, "-m", "seal_cli", "plan", "go to the kitchen", "--map", "apartment",
                           "--pddl", "d/"], cwd=tmp_path, capture_output=True, text=True, env=env)
    written = sorted(p.name for p in (tmp_path / "d").iterdir())
    assert done.returncode == 0 and written == ["domain.pddl", "problem.pddl"]


def test_an_option_of_one_value_given_twice_is_refused_for_every_command(tmp_path: Path,
                                                                         monkeypatch: pytest.MonkeyPatch) -> None:
    """click kept the last value, silently: ``--clock 10:00 --clock 11:00`` ran at 11:00 (hostile32). Every command
    is made by the framework's command class, so none keeps the last."""
    from seal_cli.cli.framework import _OnceCommand

    monkeypatch.chdir(tmp_path)
    assert all(isinstance(c, _OnceCommand) for name, c in _commands() if name and not hasattr(c, "commands"))
    for argv, says in ((["run", "go to the sofa", "--map", "studio", "--clock", "10:00", "--clock=11:00"],
                        "--clock is given twice ('10:00', '11:00'); it takes one value: give it once"),
                       (["plan", "go to the sofa", "--map", "studio", "--map", "apartment", "--map", "studio"],
                        "--map is given 3 times ('studio', 'apartment', 'studio')"),
                       (["map", "studio", "--png", "a.png", "--png", "b.png"], "--png is given twice"),
                       (["bench", "e2e", "--jobs", "1", "--jobs", "1"], "--jobs is given twice ('1', '1')"),
                       (["run", "go to the sofa", "--map", "studio", "--vocabulary", "v.yaml", "--vocabulary",
                         "x" * 100], "--vocabulary is given twice ('v.yaml', '" + "x" * 40 + "'…)")):
        result = runner.invoke(app, argv)
        assert result.exit_code == 1 and f"error: {says}" in result.output, (argv, result.output)
    assert list(tmp_path.iterdir()) == []


def test_repeatable_options_and_flags_given_twice_stay(tmp_path: Path) -> None:
    result = runner.invoke(app, ["plan", "go to the sofa", "--map", "studio", "--done", "go to the hall", "--done",
                                 "go to the balcony", "--json", "--json"])
    assert result.exit_code == 0 and '"plan"' in result.output
