"""The contents construction with the theme's noun said again instead of "it"."""

from __future__ import annotations

from seal_cli.frames.library import Library
from seal_cli.language.grounding import Vocabulary
from seal_cli.language.parser import parse_command

VOCABULARY = Vocabulary.of(["pan", "apple", "table", "knife", "bowl"])


def _places(text: str, library: Library) -> list[tuple[str | None, str | None]]:
    parse = parse_command(text, library, VOCABULARY)
    return [(parse.resolve(f.elements["theme"]).cls, parse.resolve(f.elements["goal"]).cls)
            for f in parse.frames if f.frame == "Place"]


def test_the_noun_said_again_is_the_theme_s_contents(library: Library) -> None:
    assert _places("put a pan on the table with an apple on the pan", library) == [("apple", "pan"),
                                                                                   ("pan", "table")]
    assert _places("put the bowl on the table with a knife in the bowl", library) == [("knife", "bowl"),
                                                                                      ("bowl", "table")]
    parse = parse_command("put a pan on the table with an apple on the pan", library, VOCABULARY)
    assert parse.frames[-1].elements["goal"].text == "the table"


def test_another_noun_keeps_the_contents_where_they_were_said(library: Library) -> None:
    assert ("apple", "pan") not in _places("put a pan on the table with an apple on the table", library)
    assert _places("put a pan with an apple on it on the table", library) == [("apple", "pan"), ("pan", "table")]
