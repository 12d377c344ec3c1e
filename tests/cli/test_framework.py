"""The help a user reads: every command's line in its group's list, and every option's help, as written."""

from __future__ import annotations

import re
from typing import Any

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
