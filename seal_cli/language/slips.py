"""Function words typed with one slip of the fingers: "*wher* is anna", "*cna* you bring me some water",
"*plese* close the door", "*waht*'s in the fridge?".

Questions and requests open with a question word, a modal or "please"; typed with a slip, the whole command
was an unknown verb. :func:`function_word` reads a typed word as the one function word of
:data:`SLIP_TARGETS` it is one slip from: two neighbouring letters swapped ("waht", "cna"), or, when both the
typed word and the word meant have at least :data:`SLIP_LONGER` letters, one letter left out ("wher",
"plese", "coud") or one typed too many ("wheere"). Never a word the dictionary lists ("were", "wen", "hoe"
stay themselves) nor a function word itself ("many" is no slip of "may"), never a word of fewer than three
letters, and only when exactly one target is that near ("hwo" is a swap of both "who" and "how": left
unread); a name such as "cora", "maya" or "wes" is no slip of any of them. The tokenizer allows a capital
only on the first word of a sentence (a capitalised word inside it is a name). The verbs' own slips are
:meth:`seal_cli.language.lexicon.Lexicon.mistyped`'s.
"""

from __future__ import annotations

from functools import lru_cache

from seal_cli.language import english
from seal_cli.language.english import MODALS, WH_WORDS
from seal_cli.language.morphology import in_dictionary

__all__ = ["SLIP_LONGER", "SLIP_TARGETS", "function_word", "one_slip"]

_PHRASE_WORDS = ("the", "and", "from", "with", "into", "onto", "them", "this", "that", "there")
"""The determiners, pronouns, conjunction and prepositions of place said most in commands, whose slips people type
("*teh* cup", "*adn* then", "*fomr* the shelf", "give *tehm* to me")."""
SLIP_TARGETS = frozenset(w for w in (*WH_WORDS, *MODALS, "please", "you", *_PHRASE_WORDS) if len(w) >= 3)
"""The function words a slip is read back to: the question words, the modals, "please" (the words that
open a request or a question) and "you", the subject a request put as a question names ("can *yuo* open the
door", words25; three letters: only two swapped); and the commonest words inside a command's phrases
(``_PHRASE_WORDS``: "bring me *teh* cup *fomr* the kitchen", words33)."""

SLIP_LONGER = 4
"""The fewest letters of a typed word, and of the word it is read as, when a letter was left out or typed too
many: in three letters too many words lie one letter apart ("maya" and "mary", names, are "may" and a letter;
"wat" might be a name)."""

_LETTERS = "abcdefghijklmnopqrstuvwxyz"
_FUNCTION_WORDS = frozenset(word for table in vars(english).values() if isinstance(table, (frozenset, set, dict))
                            for word in table if isinstance(word, str) and word.isalpha())
"""Every one-word entry of :mod:`english`'s closed classes: the dictionary lists open-class words only, so
"many" (one slip from "may") is known here."""


def one_slip(low: str, letters: bool = True) -> set[str]:
    """The words ``low`` (lower case, as typed) is one slip from, itself left out: two neighbouring letters
    swapped, and with ``letters`` one letter typed too many or one left out. The function words' slips here and
    the verbs' (:meth:`seal_cli.language.lexicon.Lexicon.mistyped`) are both read back through it."""
    near = {low[:j] + low[j + 1] + low[j] + low[j + 2:] for j in range(len(low) - 1)}      # swapped
    if letters:
        near |= {low[:j] + low[j + 1:] for j in range(len(low))}                            # one too many
        near |= {low[:j] + c + low[j:] for j in range(len(low) + 1) for c in _LETTERS}      # one left out
    near.discard(low)
    return near


@lru_cache(maxsize=16384)
def function_word(low: str) -> str | None:
    """The function word ``low`` (a lower-case word as typed) is one slip from, or None."""
    if len(low) < 3 or not low.isalpha() or low in _FUNCTION_WORDS or in_dictionary(low):
        return None
    near = one_slip(low, letters=len(low) >= SLIP_LONGER)
    found = {w for w in near & SLIP_TARGETS if len(w) == len(low) or min(len(w), len(low)) >= SLIP_LONGER}
    return found.pop() if len(found) == 1 else None
