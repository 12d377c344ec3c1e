"""Help a person is said to need (``rules.help_needed``, ``requests.PERSON_NEEDING``): the deed, or leading them."""

from __future__ import annotations

import pytest

from seal_cli.frames.library import Library
from seal_cli.language.parser import parse_command


def _frames(text: str, library: Library) -> list[tuple[str, dict[str, str | None]]]:
    return [(f.frame, {role: p.text for role, p in f.elements.items()}) for f in parse_command(text, library).frames]


@pytest.mark.parametrize(("text", "expected"), [
    ("robin needs some help getting to the exit", [("Guide", {"theme": "robin", "goal": "the exit"})]),
    ("the old man needs a hand to get back to his room", [("Guide", {"theme": "the old man", "goal": "his room"})]),
    ("Sam needs help finding his keys", [("Find", {"theme": "his keys"})]),
    ("grandma needs a hand carrying the shopping to the kitchen",
     [("Bring", {"theme": "the shopping", "goal": "the kitchen"})]),
])
def test_help_needed_is_the_deed_or_leading_the_person(library: Library, text: str, expected: list[object]) -> None:
    assert _frames(text, library) == expected


def test_a_need_of_a_thing_is_still_bringing_it(library: Library) -> None:
    assert _frames("dad needs his glasses", library) == [("Bring", {"theme": "his glasses", "recipient": "dad"})]
