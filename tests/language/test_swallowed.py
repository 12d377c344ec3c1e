"""A verb inside an element's text is refused at the verb, never dropped silently."""

from __future__ import annotations

import json

import pytest

from seal_cli.frames.library import Library
from seal_cli.language.lexicon import CommandError, tokenize
from seal_cli.language.parser import CommandParser, parse_command
from seal_cli.language.swallowed import swallowed


@pytest.mark.parametrize(("text", "verb"), [
    ("go to the door to greet Maria", "greet"),          # an infinitive after the goal
    ("walk to the bench to find Omar", "find"),
    ("take the box to the hall to open", "open"),         # a purpose whose object is left unsaid
    ("meet Ken by the desk escort him out", "escort"),    # a second imperative with no separator
    ("grab the mug from the shelf bring it to me", "bring"),
])
def test_a_verb_inside_an_element_is_an_error_at_the_verb(library: Library, text: str, verb: str) -> None:
    with pytest.raises(CommandError) as caught:
        parse_command(text, library)
    error = caught.value
    assert error.column == text.index(verb) + 1
    assert verb in error.message and error.expected == ["a clause of its own"]


@pytest.mark.parametrize("text", [
    "put the hand soap on the sink",                 # a noun after a determiner, however verb-like
    "put a tray holding two cups on the table",      # a participle saying what the tray holds
    "put the keys back where you found them",        # a verb with a subject says where
    "bring me a washed sliced pear",                 # results said before the noun
    "go to the bedroom and find Ana",                # a clause of its own
    "tell Ken to open the door",                     # a message is said, not done here
])
def test_nouns_participles_and_messages_are_no_swallowed_verbs(library: Library, text: str) -> None:
    parse = parse_command(text, library)
    assert parse.frames and swallowed(parse, tokenize(text), CommandParser.of(library).lexicon) == ()


def test_no_gpsr_command_swallows_a_clause(library: Library, shared_data) -> None:
    texts = [json.loads(line)["text"] for line in (shared_data / "gpsr" / "dev.jsonl").open()][:600]
    lexicon = CommandParser.of(library).lexicon
    assert all(swallowed(parse_command(t, library), tokenize(t), lexicon) == () for t in texts)


def test_the_command_line_reports_it_as_an_error_object(library: Library) -> None:
    from typer.testing import CliRunner

    from seal_cli.cli import app

    result = CliRunner().invoke(app, ["parse", "go to the door to greet Maria", "--json"])
    assert result.exit_code == 1
    error = json.loads(result.stdout)["error"]
    assert error["column"] == 19 and "greet" in error["message"]
