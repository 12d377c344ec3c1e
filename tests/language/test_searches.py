"""A search asked, then said again as a command: one search (seal_cli.language.searches)."""

from __future__ import annotations

from seal_cli.frames.library import Library
from seal_cli.language.parser import parse_command


def frames(text: str, library: Library) -> list[tuple[str, dict[str, str]]]:
    parse = parse_command(text, library)
    return [(f.frame, {role: e.head for role, e in f.elements.items() if not e.default}) for f in parse.frames]


def test_a_question_of_where_then_where_to_look_is_one_search(library: Library) -> None:
    assert frames("Where's the remote? Look in the lounge", library) == [
        ("Find", {"theme": "remote", "ground": "lounge"})]


def test_a_question_of_a_person_then_find_them_is_one_search(library: Library) -> None:
    parse = parse_command("is anybody in the garage? find them and greet them", library)
    assert [f.frame for f in parse.frames] == ["Find", "Greet"]
    assert parse.frames[1].elements["theme"].refers_to == (0, "theme")


def test_two_commands_or_another_thing_stay_two_searches(library: Library) -> None:
    assert [f for f, _ in frames("find the cup, then look in the kitchen", library)] == ["Find", "Find"]
    assert [f for f, _ in frames("where is the cup? find the plate", library)] == ["Find", "Find"]
    assert [f for f, _ in frames("where is the cup in the kitchen? look in the garage", library)] == ["Find", "Find"]
