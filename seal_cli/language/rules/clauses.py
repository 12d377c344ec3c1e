"""Clauses and their joints: sentence ends, separators ("and", "then", ","), subordinate clauses
inside a clause, relative clauses, "until the corner", "something to drink"."""

from __future__ import annotations

from seal_cli.language.english import END_MARKS, SEPARATOR_WORDS
from seal_cli.language.morphology import verb_lemma
from seal_cli.language.rule import AFTER_SEP, Example, Match, Rule
from seal_cli.language.state import INDEFINITE, REL_FIRST, SEP_FIRST, SUB_FIRST, State, match_phrase
from seal_cli.language.tags import Tag


def _end_mark(s: State, i: int) -> Match | None:
    w = s.words[i]
    if all(r.lower in END_MARKS or r.lower == "please" for r in s.words[i + 1:]):
        return Match(1, (w.tagged(Tag.END),))
    return Match(1, (w.tagged(Tag.SEP),), expect=True)            # "Go to the kitchen. Find Robin."


def _something_to(s: State, i: int) -> Match | None:
    out, words = s.out, s.words
    if out and (out[-1].lower in INDEFINITE or len(out) > 1 and out[-1].tag == Tag.WORD and
                out[-2].lower in INDEFINITE) and i + 1 < len(words) and \
            verb_lemma(words[i + 1].lower) == words[i + 1].lower:
        end = s.relative_end(i + 1)                               # "something to drink"
        return s.emit(i, end - i, Tag.REL)
    return None


def _until_place(s: State, i: int) -> Match | None:
    if s.until_place(i):
        return Match(1, (s.words[i].tagged(Tag.PREP, "to"),))     # "follow me until the gate"
    return None


def _inner(s: State) -> bool:
    return s.prev_tag() not in (Tag.DET, Tag.POSS, Tag.NUM, Tag.PREP)


def _subordinate(s: State, i: int) -> Match | None:
    if s.words[i].lower not in SUB_FIRST or not _inner(s):
        return None
    m = s.subordinate(i, start=False)
    return Match(m.consumed, m.words, expect=AFTER_SEP) if m else None


def _relative(s: State, i: int) -> Match | None:
    if not _inner(s):
        return None
    m = s.relative(i)
    return Match(m.consumed, m.words, expect=AFTER_SEP) if m else None


def _separator(s: State, i: int) -> Match | None:
    n = match_phrase(s.words, i, SEPARATOR_WORDS)
    m = s.separator(i, n) if n else None
    return Match(m.consumed, m.words, expect=AFTER_SEP) if m else None


END_MARK = Rule("sentence end", _end_mark, (
    Example("Go to the kitchen. Find Robin.", ".", Tag.SEP),
    Example("close the door!", "!", Tag.END),
), END_MARKS, "'.', '!', '?': the end of the command, or between two sentences of it")
SOMETHING_TO = Rule("something to V", _something_to, (
    Example("bring me something to drink", "to drink", Tag.REL),
), frozenset(["to"]), "'to' and a verb after an indefinite pronoun: what it is for, kept whole")
UNTIL_PLACE = Rule("until a place", _until_place, (
    Example("follow me until the gate", "until", Tag.PREP),
), frozenset(["until", "till"]), "'until' a noun phrase after a verb of motion: how far")
SUBORDINATE_INSIDE = Rule("subordinate clause", _subordinate, (
    Example("turn off the stove when the water boils", "when the water boils", Tag.COND),
), SUB_FIRST | REL_FIRST, "a subordinate clause inside a clause: a condition, or a clause of the robot's own")
RELATIVE = Rule("relative clause", _relative, (
    Example("bring me the glass that I was drinking from", "that I was drinking from", Tag.REL),
    Example("put the cup where it belongs", "where it belongs", Tag.HERE),
), SUB_FIRST | REL_FIRST, "a relative clause after a noun, kept whole (or 'that is' dropped)")
SEPARATOR = Rule("separator", _separator, (
    Example("take the cup and put it on the table", "and", Tag.SEP),
    Example("put the cup and the plate on the table", "and", Tag.AND_NP),
), SEP_FIRST, "'and', ',', 'then', ... joining clauses or noun phrases")
