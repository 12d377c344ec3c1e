"""A thing held, said before the clause that is done with it: "*With a book,* turn on the lamp",
"with a cup turn on the light". The fronted "with" phrase names what the robot holds while
it does the clause: it is read as holding it first (the library's ``hold``, a unit of Pick), then the
clause, as "while holding a book, turn on the lamp" is. Only where a command starts, and only when a
verb follows the noun phrase (after a comma or not): "with" inside a clause stays a preposition, and
"with the lights off, ...", "with the door open, ..." (a state said of the thing) hold nothing.
"""

from __future__ import annotations

from seal_cli.language.english import DETERMINERS, END_MARKS, PARTICLES
from seal_cli.language.rule import Example, Match, Rule
from seal_cli.language.state import State
from seal_cli.language.tags import Tag
from seal_cli.language.tokens import Word

HOLD = "hold"
"""The lexical unit the fronted "with" is read as (holding the thing)."""
_LONGEST = 6
"""The most words the held thing's noun phrase may have."""


def _fronted_with(s: State, i: int) -> Match | None:
    words = s.words
    if s.out and s.prev_tag() != Tag.SEP or HOLD not in s.lexicon.units or not s.np_starts(i + 1):
        return None
    for k in range(i + 2, min(len(words), i + 2 + _LONGEST)):
        low = words[k].lower
        if low in (",", ";", ":"):
            if not s.verb_after(k + 1):
                return None
            break
        if low in END_MARKS or low in ("and", "then"):
            return None
        if s.verb_at(k) is not None and words[k - 1].lower not in DETERMINERS:   # "the lights": a noun
            if k + 1 >= len(words) or words[k + 1].lower in (",", ";", ":") or words[k + 1].lower in END_MARKS:
                return None     # "with the door open, go ...": the thing's state, not a clause
            break
    else:
        return None
    if words[k - 1].lower in PARTICLES:
        return None             # "with the lights off, open the door": a state, nothing held
    w = words[i]
    return Match(1, (Word(w.text, w.start, w.end, Tag.VERB, HOLD),), expect=False, verb=HOLD, using=False)


FRONTED_WITH = Rule("with a thing held, first", _fronted_with, (
    Example("With a book, turn on the lamp", "With", Tag.VERB),
    Example("with a cup turn on the light", "with", Tag.VERB),
), frozenset(["with"]), "'with X, V ...' opening the command: hold X, then V")
