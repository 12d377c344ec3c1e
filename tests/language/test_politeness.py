"""``rules/politeness.py``: helping a person move is leading them, the person described (words48)."""

from __future__ import annotations

import pytest

from seal_cli.frames.library import Library
from seal_cli.language.parser import parse_command


def frames(text: str, library: Library) -> list[tuple[str, dict[str, str]]]:
    return [(f.frame, {role: e.head for role, e in f.elements.items() if not e.default})
            for f in parse_command(text, library).frames]


@pytest.mark.parametrize(("text", "want"), [
    ("help the man in the grey coat go to the lounge", [("Guide", {"theme": "man", "goal": "lounge"})]),
    ("help the lady at the front door to get to the car", [("Guide", {"theme": "lady", "goal": "car"})]),
    ("help the boy by the stairs with the red cap get back to his room",
     [("Guide", {"theme": "boy", "goal": "room"})]),
])
def test_a_person_described_and_helped_to_move_is_led(
        text: str, want: list[tuple[str, dict[str, str]]], library: Library) -> None:
    """"help the person in the kitchen get to the exit" was refused ("help" an unknown verb): only a pronoun, a name
    or a bare noun of people could come between "help" and the moving."""
    assert frames(text, library) == want


def test_a_person_described_and_helped_to_do_something_else_is_as_before(library: Library) -> None:
    assert frames("help the man in the hall find his keys", library) == [("Find", {"theme": "key"})]


@pytest.mark.parametrize(("text", "want"), [
    ("the lady at the gate wants you to fetch her a chair", [("Bring", {"theme": "chair", "recipient": "lady"})]),
    ("the boy in the green jumper asked you to take him to the garden",
     [("Guide", {"theme": "boy", "goal": "garden"})]),
    ("Noor, who's in the study, wants you to bring her the post", [("Bring", {"theme": "post", "recipient": "Noor"})]),
])
def test_a_request_passed_on_by_a_person_described_is_the_command(
        text: str, want: list[tuple[str, dict[str, str]]], library: Library) -> None:
    """words48: "the person at the door wants you to bring them a cup" was refused as a statement, and "Jane, who's at
    the sofa, wants you to follow her" a Tell of the relative clause: what describes the one who passes the request on
    (a phrase of place or of clothes, a relative clause between commas) is theirs."""
    parse = parse_command(text, library)
    assert frames(text, library) == want
    assert len(parse.remarks) == 1
