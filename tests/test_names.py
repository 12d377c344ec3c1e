"""names: a name longer than a terminal line, a PNG label or a Rerun path shows whole is refused at its place."""

from __future__ import annotations

import re
from pathlib import Path

import pytest

from seal_cli.errors import SealError
from seal_cli.frames.formats import dsl
from seal_cli.frames.taxonomy import Category, Synonyms
from seal_cli.maps.formats.map_server import load_map
from seal_cli.names import MAX_NAME, check_name_length, check_shown, name_too_long

SMALL = "name: {map}\nbounds: [0, 0, 10, 10]\nrooms:\n  - name: {room}\n    box: [0, 0, 5, 10]\n" \
        "people:\n  - {{name: {person}, at: [1, 1], role: {role}}}\n"


def test_a_name_of_the_bound_passes_and_one_more_is_refused() -> None:
    assert check_name_length("r" * MAX_NAME, "room name") == "r" * MAX_NAME
    assert name_too_long("r" * MAX_NAME, "room name") is None
    problem = name_too_long("r" * (MAX_NAME + 1), "room name")
    assert problem is not None and "room name 'rrrr" in problem.message and "is 101 characters long" in problem.message


@pytest.mark.parametrize(("field", "said", "where"), [
    ("map", "map name", (1, 7)),
    ("room", "room name", (4, 11)),
    ("person", "person name", (7, 12)),   # at the name itself, not at the person
    ("role", "person Sam: role", (7, 5)),
])
def test_a_map_names_the_long_name_at_its_line(tmp_path: Path, field: str, said: str, where: tuple[int, int]) -> None:
    names = {"map": "m", "room": "hall", "person": "Sam", "role": "nurse"} | {field: "x" * 5000}
    (tmp_path / "m.yaml").write_text(SMALL.format(**names))
    with pytest.raises(SealError) as caught:
        load_map(tmp_path / "m.yaml")
    problems = getattr(caught.value, "problems", None) or [caught.value]
    assert len(problems) == 1, [str(p) for p in problems]  # said once: nothing said again of what names it
    assert problems[0].message.startswith(f"{said} 'xxxx") and "5,000 characters long" in problems[0].message
    assert (problems[0].where.line, problems[0].where.column) == where


def test_names_of_the_bound_read(tmp_path: Path) -> None:
    names = {"map": "m" * MAX_NAME, "room": "h" * MAX_NAME, "person": "S" * MAX_NAME, "role": "n" * MAX_NAME}
    (tmp_path / "m.yaml").write_text(SMALL.format(**names))
    m = load_map(tmp_path / "m.yaml")
    assert m.name == "m" * MAX_NAME and m.rooms[0].name == "h" * MAX_NAME and m.people[0].name == "S" * MAX_NAME


@pytest.mark.parametrize(("text", "said"), [
    ('frame Z{long} "zap" {{\n  theme: thing\n  do navigate(theme)\n}}\n', "frame name"),
    ('frame Zap "zap" {{\n  t{long}: thing\n  do navigate(theme)\n}}\n', "element"),
    ('frame Zap "zap" {{\n  theme: t{long}\n  do navigate(theme)\n}}\n', "type"),
    ('frame Zap "zap" {{\n  theme: thing\n  do navigate(theme)\n  ensures p{long}(theme)\n}}\n', "predicate"),
    ('frame Zap "zap" {{\n  theme: thing\n  do a{long}(theme)\n}}\n', "action"),
])
def test_a_frame_names_the_long_name(text: str, said: str) -> None:
    problems = dsl.read(text.format(long="z" * 3000), "f.frame").problems
    assert any(p.message.startswith(f"{said} '") and "3,001 characters long" in p.message for p in problems), \
        [str(p) for p in problems]


def test_categories_and_synonyms_refuse_long_names() -> None:
    with pytest.raises(SealError, match=r"^category name 'uuu.*3,000 characters long"):
        Category("u" * 3000, ("spoon",))
    with pytest.raises(SealError, match=r"category utensil: member 'sss.*3,000 characters long"):
        Category("utensil", ("s" * 3000,))
    with pytest.raises(SealError, match=r"synonyms of fridge: name 'iii.*3,000 characters long"):
        Synonyms("fridge", ("i" * 3000,))


@pytest.mark.parametrize(("name", "said"), [
    ("\U0001f6cf", "room name '\U0001f6cf' holds '\U0001f6cf' (U+1F6CF BED), a symbol no command can say"),
    ("hall\u200d", "(U+200D ZERO WIDTH JOINER), an invisible character no command can say"),
    ("\u200fden", "(U+200F RIGHT-TO-LEFT MARK), an invisible character"),
])
def test_a_room_or_person_name_no_command_can_say_is_refused(name: str, said: str) -> None:
    # a room called "🛏" or "hall" + U+200D validated; no command could reach it (hostile21)
    from seal_cli.maps.model import Person, Room

    with pytest.raises(SealError, match=re.escape(said)):
        Room(name, ((0, 0), (1, 0), (1, 1)))
    with pytest.raises(SealError, match=re.escape(said.replace("room name", "person name"))):
        Person(name, at=(0.5, 0.5))


@pytest.mark.parametrize("name", ["café", "Zoë", "kids room", "RD lab", "room 2-b", "Ахмед", "living_room",
                                  "floor 2", "Anne-Marie", "Nai\u0308ve"])
def test_names_of_letters_digits_and_word_parts_are_sayable(name: str) -> None:
    from seal_cli.names import check_sayable

    assert check_sayable(name, "room name") == name


@pytest.mark.parametrize(("name", "said"), [
    ("kid's room", "room name \"kid's room\" holds \"'\", which a plan cannot name"),
    ("R&D lab", "room name 'R&D lab' holds '&', which a plan cannot name"),
    ("Dr. Smith", "holds '.', which a plan cannot name"),
    ("hall: 2", "holds ':', which a plan cannot name"),
    ("hall (west)", "holds '(', which a plan cannot name"),
    ("hall#2", "holds '#'"),
    ("hall|2", "holds '|'"),
    ("2nd floor", "room name '2nd floor' starts with a digit, which a plan cannot name"),
])
def test_a_room_or_person_name_no_plan_can_name_is_refused(name: str, said: str) -> None:
    # each validated, then every plan going there failed at a line of seal's own motion.yaml (hostile22)
    from seal_cli.maps.model import Person, Room

    with pytest.raises(SealError, match=re.escape(said)):
        Room(name, ((0, 0), (1, 0), (1, 1)))
    with pytest.raises(SealError, match=re.escape(said.replace("room name", "person name"))):
        Person(name, at=(0.5, 0.5))


@pytest.mark.parametrize(("name", "said"), [
    ("ha\tll", "room name 'ha\\tll' holds '\\t', which a plan cannot name"),
    ("hall\x85", "holds '\\x85', which a plan cannot name"),
    ("hall\u2028", "holds '\\u2028', which a plan cannot name"),
    ("\u0301\u0301", "holds no letter or digit, so no command can say it"),
])
def test_a_name_with_a_tab_a_line_end_or_no_letter_is_refused(name: str, said: str) -> None:
    # each validated (a tab and U+0085 are spaces to str.isspace, a name of accents alone had no letter to fail on)
    # (hostile24)
    from seal_cli.maps.model import Room

    with pytest.raises(SealError, match=re.escape(said)):
        Room(name, ((0, 0), (1, 0), (1, 1)))


def test_a_name_with_a_no_break_space_is_sayable() -> None:
    from seal_cli.names import check_sayable

    assert check_sayable("living\u00a0room", "room name") == "living\u00a0room"


@pytest.mark.parametrize(("name", "said"), [("m\x00x", "a control character"), ("m\x1b[2J", "a control character"),
                                            ("m\u202eeman", "reorders the line"), ("a\u2028b", "a line separator")])
def test_a_name_a_terminal_cannot_show_is_refused(name: str, said: str) -> None:
    """hostile27: a map named with a NUL drew a missing glyph; a right-to-left override turned the terminal's line."""
    with pytest.raises(SealError, match=re.escape(said)):
        check_shown(name, "map name")


@pytest.mark.parametrize("name", ["Café ☕ №5 — R&D", "خانه\u200cما", "👨\u200d👩\u200d👧 home", "2nd floor"])
def test_a_name_of_symbols_punctuation_and_joiners_is_shown(name: str) -> None:
    """A zero-width non-joiner belongs in Persian words, a zero-width joiner in emoji: only what reorders stays out."""
    assert check_shown(name, "map name") == name


@pytest.mark.parametrize(("escaped", "character"), [("\\0", "\\x00"), ("\\u202E", "\\u202e")])
def test_a_map_named_with_what_cannot_be_shown_is_refused_at_its_name(tmp_path: Path, escaped: str,
                                                                      character: str) -> None:
    (tmp_path / "m.yaml").write_text(f'name: "m{escaped}x"\nbounds: [0, 0, 10, 10]\nrooms:\n'
                                     "  - {name: hall, box: [0, 0, 10, 10]}\n")
    with pytest.raises(SealError) as caught:
        load_map(tmp_path / "m.yaml")
    problems = getattr(caught.value, "problems", None) or [caught.value]
    assert [(p.line, p.column) for p in problems] == [(1, 7)]
    assert problems[0].message.startswith(f"map name 'm{character}x' holds '{character}'")


def test_a_longer_text_may_keep_the_characters_it_allows() -> None:
    # a frame's description keeps its line breaks and tabs; an escape sequence stays refused in it (hostile28)
    assert check_shown("one\n\ttwo", "description", allowed="\n\t") == "one\n\ttwo"
    with pytest.raises(SealError, match=r"holds '\\x1b' \(U\+001B\), a control character"):
        check_shown("a \x1b[31m red", "description", allowed="\n\t")
    with pytest.raises(SealError, match=r"holds '\\n'"):
        check_shown("one\ntwo", "map name")
