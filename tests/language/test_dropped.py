"""``seal_cli.language.dropped``: a word of state ending a sentence that no part of the parse holds."""

from __future__ import annotations

from dataclasses import replace

import pytest

from seal_cli.frames.library import Library
from seal_cli.language.dropped import Dropped, dropped_states
from seal_cli.language.parser import parse_command
from seal_cli.language.tokens import tokenize


@pytest.mark.parametrize("text", [
    "is the light in the office on?",            # the state asked
    "turn the heater off",                       # the unit's particle
    "make sure the lamp is on",                  # the state brought about: the unit "turn on"
    "if the lamp in the hall is on, turn it off",   # the condition
    "the lamp by the bed, is it on?",            # a phrase said first, then the question
    "bring me the cup",                          # no word of state at all
])
def test_a_state_the_parse_holds_is_not_dropped(text: str, library: Library) -> None:
    assert dropped_states(parse_command(text, library), tokenize(text)) == ()


def test_a_state_asked_and_lost_is_found(library: Library) -> None:
    """The parse "is the light in the office on?" had before words26: the question asked, its state lost."""
    text = "is the light in the office on?"
    parse = parse_command(text, library)
    lost = replace(parse, frames=tuple(replace(f, asked=None) for f in parse.frames))
    assert dropped_states(lost, tokenize(text)) == (Dropped("on", 27),)
    assert Dropped("on", 27).to_json() == {"word": "on", "start": 27}


def test_only_a_state_ending_its_sentence_counts(library: Library) -> None:
    text = "put the lid on the pot"
    assert dropped_states(parse_command(text, library), tokenize(text)) == ()
