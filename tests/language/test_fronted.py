"""The fronted "with": a thing held before the clause done with it, and what it must not read as held."""

from __future__ import annotations

import pytest

from seal_cli.frames.library import Library
from seal_cli.language.grounding import Vocabulary
from seal_cli.language.parser import CommandError, parse_command

VOCABULARY = Vocabulary.of(["book", "lamp", "door", "light", "kitchen"])


@pytest.mark.parametrize("text", ["With a book, turn on the lamp", "with a book turn on the lamp",
                                  "With the red book, turn on the lamp"])
def test_the_thing_is_held_then_the_clause_is_done(library: Library, text: str) -> None:
    parse = parse_command(text, library, VOCABULARY)
    assert [(f.frame, f.lexical_unit) for f in parse.frames] == [("Pick", "hold"), ("ToggleOn", "turn on")]
    assert parse.frames[0].elements["theme"].cls == "book" and parse.frames[1].elements["theme"].cls == "lamp"


@pytest.mark.parametrize("text", ["with the lights off, open the door", "go to the kitchen with a book"])
def test_a_state_or_a_with_inside_a_clause_holds_nothing(library: Library, text: str) -> None:
    try:
        parse = parse_command(text, library, VOCABULARY)
    except CommandError:
        return
    assert all(f.lexical_unit != "hold" for f in parse.frames)


def test_wet_and_soak_are_washing(library: Library) -> None:
    kitchen = Vocabulary.of(["sponge", "counter", "towel", "drawer"])
    wet = parse_command("put a wet sponge on the counter", library, kitchen)
    assert [f.frame for f in wet.frames] == ["Clean", "Place"] and wet.frames[0].inferred is None
    soak = parse_command("soak the towel and put it in the drawer", library, kitchen)
    assert [f.frame for f in soak.frames] == ["Clean", "Place"]


def test_attempt_to_leads_in(library: Library) -> None:
    parse = parse_command("attempt to put the book on the lamp", library, VOCABULARY)
    assert [f.frame for f in parse.frames] == ["Place"]
