"""``State.separator``: a joint of clauses, or of noun phrases (words48)."""

from __future__ import annotations

from seal_cli.frames.library import Library
from seal_cli.language.parser import parse_command


def test_and_also_before_a_noun_phrase_joins_noun_phrases(library: Library) -> None:
    """"bring me an apple from the table and also a cola from the fridge" was refused at "a" ("and also" read as a
    joint of clauses); before a determiner it joins the things, each with its source as after "and"."""
    parse = parse_command("fetch me a plum from the bowl and also a pear from the shelf", library)
    assert [(f.frame, f.elements["theme"].head, f.elements["source"].head) for f in parse.frames] == [
        ("Bring", "plum", "bowl"), ("Bring", "pear", "shelf")]


def test_and_also_before_a_verb_still_joins_clauses(library: Library) -> None:
    parse = parse_command("go to the porch and also find the dog", library)
    assert [f.frame for f in parse.frames] == ["Go", "Find"]
