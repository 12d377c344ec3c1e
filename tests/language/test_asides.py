"""language/asides.py: what is said in brackets or between two dashes, set aside as a remark (words35)."""

from __future__ import annotations

import pytest

from seal_cli.frames.library import Library
from seal_cli.language.asides import set_aside
from seal_cli.language.parser import lexicon_of
from seal_cli.language.tokens import tokenize


def _aside(text: str, library: Library) -> tuple[list[str], list[str]]:
    lexicon, _ = lexicon_of(library)
    kept, remarks = set_aside(lexicon, tokenize(text))
    return [w.lower for w in kept], [text[a:b] for a, b in remarks]


@pytest.mark.parametrize(("text", "kept", "remarks"), [
    ("fetch a towel (a dry one) from the shed", ["fetch", "a", "towel", "from", "the", "shed"], ["a dry one"]),
    ("follow Ada - she's in red - to the porch", ["follow", "ada", "to", "the", "porch"], ["she's in red"]),
    ("lift the vase \u2014 mind, it's heavy \u2014 and dust it",
     ["lift", "the", "vase", "and", "dust", "it"], ["mind, it's heavy"]),
])
def test_an_aside_is_taken_out_as_a_remark(text: str, kept: list[str], remarks: list[str], library: Library) -> None:
    assert _aside(text, library) == (kept, remarks)


@pytest.mark.parametrize(("text", "kept"), [
    ("open the shed (and then close it)", ["open", "the", "shed", "and", "then", "close", "it"]),
    ("open the gate - then find the rake - and bring it", ["open", "the", "gate", ";", "then", "find", "the", "rake",
                                                           ";", "and", "bring", "it"]),
    ("open the gate - now", ["open", "the", "gate", ";", "now"]),                  # one dash: a stop
    ("open the gate (now", ["open", "the", "gate", "now"]),                        # a bracket alone: nothing
])
def test_a_clause_or_a_lone_mark_is_no_aside(text: str, kept: list[str], library: Library) -> None:
    assert _aside(text, library) == (kept, [])


def test_dashes_before_any_verb_set_nothing_aside(library: Library) -> None:
    assert _aside("mugs - the shelf - put them there", library) == (
        ["mugs", ";", "the", "shelf", ";", "put", "them", "there"], [])


@pytest.mark.parametrize(("text", "kept", "remarks"), [
    ("find out for me how many jars are in the shed",
     ["find", "out", "how", "many", "jars", "are", "in", "the", "shed"], ["for me"]),
    ("check for us which vase is the tallest", ["check", "which", "vase", "is", "the", "tallest"], ["for us"]),
    ("figure out for me who is at the gate (quickly)", ["figure", "out", "who", "is", "at", "the", "gate"],
     ["for me", "quickly"]),
])
def test_for_me_between_a_verb_and_its_question_is_set_aside(text: str, kept: list[str], remarks: list[str],
                                                            library: Library) -> None:
    """words41: "for me" cut "find out" from its question (refused, or a LookAt of the question)."""
    assert _aside(text, library) == (kept, remarks)


@pytest.mark.parametrize("text", ["bring a cup for me", "look for me", "get the cup for me if you can"])
def test_for_me_elsewhere_stays(text: str, library: Library) -> None:
    assert _aside(text, library)[1] == []
