"""``seal_cli.language.english``: the closed classes the tagger reads are well-formed word lists."""

from __future__ import annotations

from collections.abc import Iterable

import pytest

import seal_cli.language.english as english
from seal_cli.frames.library import Library
from seal_cli.language.parser import parse_command


def _tables() -> dict[str, Iterable[str]]:
    return {name: value for name, value in vars(english).items()
            if name.isupper() and isinstance(value, (frozenset, dict))}


def test_every_entry_is_lowercase_words_without_stray_space() -> None:
    tables = _tables()
    assert {"DETERMINERS", "PREPOSITIONS", "POLITE", "TITLES", "SPELLINGS", "FILLERS"} <= set(tables)
    for name, table in tables.items():
        for entry in table:
            assert entry == entry.strip() and entry == entry.lower() and "  " not in entry, (name, entry)


def test_spellings_lead_to_words_not_to_other_spellings() -> None:
    for written, meant in english.SPELLINGS.items():
        assert meant not in english.SPELLINGS, (written, meant)
        assert written != meant


def test_number_words_count() -> None:
    assert english.NUMBERS["three"] == 3 and english.NUMBERS["a couple of"] == 2
    assert all(isinstance(n, int) and n >= 0 for n in english.NUMBERS.values())


def test_texting_spellings_of_yourself_read_as_yourself(library: Library) -> None:
    """words48: "introduce urself to Jo" was a Tell of "urself"; "introduce yourself to" greets."""
    parse = parse_command("introduce urself to Jo in the hall", library)
    assert [f.frame for f in parse.frames] == ["Greet"]


@pytest.mark.parametrize(("text", "want"), [
    ("go to the hall, after which find the umbrella", ["Go", "Find"]),
    ("go to the porch and from there go to the garage", ["Go", "Go"]),
    ("walk to the shed. from there, go to the gate", ["Go", "Go"]),
    ("head on over to the study", ["Go"]),
])
def test_joints_said_with_which_or_from_there(library: Library, text: str, want: list[str]) -> None:
    """words48: "after which" was a question ("which find the milk" told), "and from there go ..." refused at
    "there", "head on over to" a ToggleOn of the head; the joint says only what comes next."""
    assert [f.frame for f in parse_command(text, library).frames] == want
