"""A state asked for that no frame of the library brings about: "I want the door *locked*", "keep the gate
*locked*", "make sure the windows are *painted*".

A wish for a thing's state ("I'd like the blinds closed") or a verb that keeps it so ("keep the door shut") asks for
the verb whose result the state is (``requests.WISHED_STATE``, ``requests.RESULTATIVE``). When the state is the past
participle of a verb no frame lists ("locked": no frame locks), nothing can bring it about: the command is refused at
the participle, saying which verb the robot lacks (words49: it was refused as "'the door locked': no element of
Bring takes it", a thing asked for)."""

from __future__ import annotations

from collections.abc import Sequence

from seal_cli.language.english import BE_WORDS, DETERMINERS, END_MARKS, KEEPING, POSSESSIVES, WISHED_PLACED
from seal_cli.language.lexicon import Lexicon
from seal_cli.language.morphology import in_verb_tables, inflected, parts_of_speech, verb_lemma
from seal_cli.language.state import longest_phrase
from seal_cli.language.tokens import Word

__all__ = ["unmade_state"]

ASKING = WISHED_PLACED | KEEPING | frozenset(["i need", "we need", "i'd prefer", "i would prefer", "make sure",
                                              "ensure", "leave", "please keep", "please make sure"])
"""What asks for a thing to be, or stay, in a state, opening the sentence."""
_THING_WORDS = 4
"""The most words of the thing's phrase after its determiner ("the back garden door")."""
_ENDING = frozenset([",", "please", "thanks", "now", "tonight", "today"])


def unmade_state(words: Sequence[Word], lexicon: Lexicon) -> tuple[Word, str] | None:
    """The participle ending a wish for a state that no unit of the library brings about, with its verb; None
    otherwise."""
    n = longest_phrase(words, 0, ASKING)
    if not n:
        return None
    k = n + (n < len(words) and (words[n].lower in DETERMINERS or words[n].lower in POSSESSIVES))
    start = k
    while k < len(words) and k - start < _THING_WORDS and words[k].lower.isalpha() and not _participle(words[k].lower):
        k += 1
    if k == start or k >= len(words):
        return None
    k += words[k].lower in BE_WORDS                    # "make sure the door *is* locked"
    if k >= len(words) or not _participle(words[k].lower):
        return None
    if k + 1 < len(words) and words[k + 1].lower not in END_MARKS and words[k + 1].lower not in _ENDING:
        return None
    lemma = verb_lemma(words[k].lower) or ""
    if lemma in lexicon.units or words[k].lower in lexicon.results:
        return None
    return words[k], lemma


def _participle(low: str) -> bool:
    """A past participle of a verb English's tables list, no adjective ("locked", "painted"; not "closed", "open")."""
    pos = parts_of_speech(low)
    return inflected(low) and "adj" not in pos and "noun" not in pos and in_verb_tables(verb_lemma(low) or "")
