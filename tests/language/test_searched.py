"""Searches the speaker tells of (``rules.searched``, ``rules.anywhere``): finding the thing, nowhere in particular."""

from __future__ import annotations

import pytest

from seal_cli.frames.library import Library
from seal_cli.language.parser import parse_command


def _frames(text: str, library: Library) -> list[tuple[str, dict[str, str | None]]]:
    return [(f.frame, {role: p.text for role, p in f.elements.items()}) for f in parse_command(text, library).frames]


@pytest.mark.parametrize(("text", "expected"), [
    ("I can't find my headphones anywhere", [("Find", {"theme": "my headphones"})]),
    ("have you seen it anywhere", [("Find", {"theme": "it"})]),                   # no ground "anywhere"
    ("have you seen my keys anywhere in the kitchen", [("Find", {"theme": "my keys", "ground": "the kitchen"})]),
    ("we couldn't locate the cat", [("Find", {"theme": "the cat"})]),
    ("track down the keys", [("Find", {"theme": "the keys"})]),
    ("hunt the remote down", [("Find", {"theme": "the remote"})]),
    ("shadow the man in the red shirt", [("Follow", {"theme": "the man in the red shirt"})]),
])
def test_a_search_told_of_is_a_find(library: Library, text: str, expected: list[object]) -> None:
    assert _frames(text, library) == expected


def test_a_search_said_before_a_question_is_its_context(library: Library) -> None:
    parse = parse_command("I'm looking for my phone, have you seen it anywhere?", library)
    assert [f.frame for f in parse.frames] == ["Find"] and parse.remarks == ("I'm looking for my phone",)
