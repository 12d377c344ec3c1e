"""A thing asked for a person, described by its state: "bring *her* a *clean* towel", "get me a *cold* drink".

A frame's result adjective before a noun ("put a *clean* plate in the cabinet", ALFRED's goals) asks for that
result first: clean the plate, then put it (:data:`~seal_cli.language.rules.open_words.RESULT`). Asked for a person,
right after the verb's first object ("bring her a clean towel": a towel she can use), the adjective picks which
thing, one already in that state, as "a red towel" does: no Clean, no washing a towel the robot is to hand over
(words49: "Mia's in the bathroom, bring her a clean towel" was a Clean and a Bring). A participle ("a *sliced*
apple", "a *washed* cup") still says what was done to it, and stays the result."""

from __future__ import annotations

from seal_cli.language.english import OBJECT_PRONOUNS
from seal_cli.language.morphology import is_adjective, verb_lemma
from seal_cli.language.rule import Example, Match, Rule
from seal_cli.language.state import State
from seal_cli.language.tags import Tag

__all__ = ["STATE_OF_A_GIFT"]

_PEOPLE = OBJECT_PRONOUNS - {"it", "this", "that"}


def _state_of_a_gift(s: State, i: int) -> Match | None:
    """A result adjective (no participle) opening the second object of a verb whose first is a person."""
    low = s.words[i].lower
    if low not in s.lexicon.results or not is_adjective(low) or (verb_lemma(low) or low) != low or \
            not s.noun_follows(i + 1) or s.verb_index < 0:
        return None
    after = s.out[s.verb_index + 1:]
    if len(after) < 2 or not (after[0].tag == Tag.NAME or after[0].tag == Tag.PRON and after[0].lower in _PEOPLE) or \
            any(w.tag not in (Tag.DET, Tag.NUM) for w in after[1:]):
        return None
    return s.emit(i, 1, Tag.WORD)


STATE_OF_A_GIFT = Rule("a thing for a person, by its state", _state_of_a_gift, (
    Example("bring her a clean towel", "clean", Tag.WORD),
    Example("get me a cold drink from the fridge", "cold", Tag.WORD),
    Example("bring Sam a clean shirt", "clean", Tag.WORD),
), None, "'bring her a clean towel': which towel (one clean already), no cleaning")
