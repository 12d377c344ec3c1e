"""A frame library's lexical units as the language reads them: none opens with a function word of English."""

from __future__ import annotations

from pathlib import Path

import pytest

from seal_cli.errors import SealError
from seal_cli.frames.reading import load_library, read_library, standard_library
from seal_cli.language.english import FUNCTION_WORD_CLASSES, function_word_class
from seal_cli.language.parser import CommandParser, parse_command
from seal_cli.language.units import unit_problems

ZAP = 'category object = cup, bowl\nframe Zap "{unit}" {{\n  theme: object\n  do navigate(theme)\n}}\n'


def _library(tmp_path: Path, unit: str) -> Path:
    path = tmp_path / "z.frame"
    path.write_text(ZAP.format(unit=unit), encoding="utf-8")
    return path


@pytest.mark.parametrize(("unit", "kind"), [("the", "a determiner"), ("a", "a determiner"), ("of", "a preposition"),
                                            ("and", "a conjunction"), ("it", "a pronoun"), ("with", "a preposition"),
                                            ("must", "a modal verb"), ("is", "a form of 'be'"), ("which",
                                                                                                "a question word"),
                                            ("my", "a possessive"), ("whose", "a question word"), ("two", "a number")])
def test_a_unit_that_is_a_function_word_is_refused_at_its_line_and_column(tmp_path: Path, unit: str,
                                                                          kind: str) -> None:
    library, problems = read_library([_library(tmp_path, unit)])
    assert problems == []                              # the frame readers know no English
    found = unit_problems(library)
    assert [(p.line, p.column) for p in found] == [(2, 11)]
    assert found[0].message.startswith(f"lexical unit '{unit}' of Zap is {kind}, a function word of English")


def test_a_unit_opening_with_one_is_refused_and_words_after_its_verb_are_its_own(tmp_path: Path) -> None:
    found = unit_problems(read_library([_library(tmp_path, "the cup")])[0])
    assert len(found) == 1 and "'the cup' of Zap opens with 'the', a determiner" in found[0].message
    for good in ("zap the way to", "zap it up", "how much", "zap"):       # a question's unit: "how many" is Count's
        assert unit_problems(read_library([_library(tmp_path, good)])[0]) == [], good


def test_the_standard_library_has_none_and_the_classes_are_the_tables() -> None:
    assert unit_problems(standard_library()) == []
    assert function_word_class("of") == "a preposition" and function_word_class("zap") is None
    assert function_word_class("The") == "a determiner"
    every = set().union(*(words for _, words in FUNCTION_WORD_CLASSES))
    assert all(" " not in w and w for w in every)      # one word each: a unit's first word is one


def test_a_parser_of_such_a_library_refuses_it_so_the_cup_is_no_frame(tmp_path: Path) -> None:
    library = load_library([_library(tmp_path, "the")])
    with pytest.raises(SealError, match=r"z\.frame:2:11: lexical unit 'the' of Zap is a determiner"):
        parse_command("the cup", library)
    with pytest.raises(SealError, match="lexical unit 'the'"):
        CommandParser(library)
