"""Places that restrict nothing: "have you seen my keys *anywhere*?", "I've looked *everywhere* for the remote".

"anywhere" and "everywhere" said after what a clause is about name no place where the thing is sought or put: they
say the search is not bounded. Read as a manner (an adverb, as "quickly" is), never an element a planner would
have to ground ("anywhere" was Find's ground, a place no map holds; words49)."""

from __future__ import annotations

from seal_cli.language.english import END_MARKS, PREPOSITIONS
from seal_cli.language.rule import Example, Match, Rule
from seal_cli.language.state import State
from seal_cli.language.tags import Tag

__all__ = ["UNBOUNDED_PLACE"]

UNBOUNDED = frozenset(["anywhere", "everywhere"])
"""Adverbs of place that bound nothing (not "somewhere", which may go on: "somewhere safe")."""

_AFTER = frozenset([Tag.WORD, Tag.NAME, Tag.PRON, Tag.VERB])
_ENDING = frozenset([",", ";", "and", "then", "please", "at", "yet", "already"])


def _unbounded_place(s: State, i: int) -> Match | None:
    """"anywhere"/"everywhere" after the clause's verb or its object, ending the clause or before a place said
    ("have you seen it anywhere in the kitchen": the kitchen is the ground): a manner of the search."""
    if s.in_np() or s.verb_index < 0 or s.prev_tag() not in _AFTER:
        return None
    nxt = s.next_lower(i)
    if nxt and nxt not in END_MARKS and nxt not in _ENDING and nxt not in PREPOSITIONS:
        return None
    return s.emit(i, 1, Tag.PARTICLE)


UNBOUNDED_PLACE = Rule("a place that bounds nothing", _unbounded_place, (
    Example("have you seen my keys anywhere", "anywhere", Tag.PARTICLE),
    Example("search everywhere for my glasses", "everywhere", Tag.PARTICLE),
    Example("look everywhere for the cat", "everywhere", Tag.PARTICLE),
    Example("have you seen it anywhere in the kitchen?", "anywhere", Tag.PARTICLE),
), UNBOUNDED, "'anywhere', 'everywhere': the search is not bounded, no place to ground")
