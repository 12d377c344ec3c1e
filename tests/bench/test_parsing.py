"""``seal bench parse`` in process: counts of commands, errors and swallowed clauses."""

from __future__ import annotations

import json
from pathlib import Path

import pytest

from seal_cli.bench.parsing import commands_of, measure
from seal_cli.errors import SealError
from seal_cli.frames.library import Library
from seal_cli.language.lexicon import CommandError
from seal_cli.language.parser import parse_command


def test_a_swallowed_clause_is_counted_as_refused(library: Library) -> None:
    texts = ["take the lamp from the box handing it to Ana", "bring me the cup", "launch the rocket",
             "go to the kitchen"]
    try:                                 # refused today; a clause of its own once the tagger reads the participle
        parse_command(texts[0], library)
        refused = 0
    except CommandError as error:
        refused = int(error.expected == ["a clause of its own"])
    figures = measure(texts, library, warmup=0)
    assert (figures.commands, figures.parsed, figures.errors) == (4, 3 - refused, 1 + refused)
    assert (figures.refused_swallowed, figures.silent_swallowed) == (refused, 0)
    assert figures.commands_per_cpu_s > 0


def test_a_state_asked_is_never_dropped_silently(library: Library) -> None:
    figures = measure(["is the light in the office on?", "is the lamp on the desk off?", "turn the fan off"],
                      library, warmup=0)
    assert (figures.parsed, figures.silent_swallowed, figures.silent_dropped) == (3, 0, 0)
    assert figures.to_json()["silent_dropped"] == 0


def test_the_commands_of_a_corpus(tmp_path: Path) -> None:
    lines = tmp_path / "c.jsonl"
    lines.write_text(json.dumps({"text": "go home"}) + "\n\n" + json.dumps({"other": 1}) + "\n", encoding="utf-8")
    assert commands_of(lines) == ["go home"]
    goals = tmp_path / "g.tsv"
    goals.write_text("split\tgoal_sentence\nvalid\tput  the cup \tx\n", encoding="utf-8")
    assert commands_of(goals) == ["put the cup"]
    bad = tmp_path / "bad.jsonl"
    bad.write_text('{"text": oops}\n', encoding="utf-8")
    with pytest.raises(SealError, match="not JSON"):
        commands_of(bad)


def test_a_phrase_no_element_takes_is_counted_as_refused(library: Library) -> None:
    """words31: a phrase of a clause no frame element takes is refused at it, never left silently."""
    figures = measure(["put the jar on the shelf the teapot", "open the window a little",
                       "bring to the hall the chairs"], library, warmup=0)
    assert (figures.parsed, figures.errors, figures.refused_unplaced, figures.silent_unplaced) == (2, 1, 1, 0)
    assert figures.to_json()["refused_unplaced"] == 1
