"""A function word typed with one slip (slips.function_word) and where the tokenizer reads it so."""

from __future__ import annotations

import pytest

from seal_cli.language.slips import SLIP_TARGETS, function_word
from seal_cli.language.tokens import tokenize


@pytest.mark.parametrize(("typed", "meant"), [
    ("wehn", "when"), ("whta", "what"), ("cuold", "could"), ("wolud", "would"),   # two letters swapped
    ("whch", "which"), ("shoud", "should"), ("pleae", "please"),                   # one left out
    ("whhere", "where"), ("pleasse", "please"),                                     # one too many
    ("cna", "can"),                                                                 # three letters: a swap
    ("teh", "the"), ("adn", "and"), ("frmo", "from"), ("wiht", "with"),            # words of phrases (words33)
    ("tehm", "them"), ("taht", "that"),
])
def test_one_slip_from_one_function_word(typed: str, meant: str) -> None:
    assert function_word(typed) == meant


@pytest.mark.parametrize("typed", [
    "were", "wen", "hoe", "plea",        # words of the dictionary: never read as another
    "many", "then", "whom",              # function words themselves
    "hwo",                               # one swap from "who" and from "how": which one is unknown
    "maya", "mary", "wat",               # a letter more or less than a three-letter word ("may", "what")
    "jamie", "cora", "sam", "ab",        # names, too short
    "form", "fomr", "thier",             # a word itself; two slips from "from"; "their" is no target
])
def test_no_slip_read(typed: str) -> None:
    assert function_word(typed) is None


def test_the_targets_open_requests_and_questions() -> None:
    assert {"what", "where", "how", "can", "could", "would", "please"} <= SLIP_TARGETS
    assert "if" not in SLIP_TARGETS          # two letters: every slip of it is another word


def test_the_tokenizer_reads_a_slip_but_keeps_the_text() -> None:
    words = tokenize("wher is anna")
    assert [(w.text, w.lower) for w in words] == [("wher", "where"), ("is", "is"), ("anna", "anna")]
    assert tokenize("Cna you help")[0].lower == "can"                # a capital opening the sentence
    assert tokenize("go. Cna you help")[2].lower == "can"
    assert tokenize("tell Cna the time")[1].lower == "cna"           # a capital inside it: a name
