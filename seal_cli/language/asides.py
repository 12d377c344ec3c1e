"""What is said beside a command in brackets or between two dashes: :func:`set_aside`.

"bring me a drink *(any drink is fine)* from the fridge", "follow Ada *- she's the one in red -* to the porch",
"take the bowl *— careful, it's fragile —* and put it away": an aside describes or comments; the command reads on
around it (words35). It is a remark of the parse (kept, never dropped in silence), unless a verb of the library opens
a clause in it ("open the shed *(and then close it)*"): then only its brackets go, and its words are read as said. A
dash alone stays what the tokenizer made it, a stop between clauses. Taken out before the tagger runs, so that no
rule reads the word after an aside's first bracket as the next word of the command.
"""

from __future__ import annotations

from collections.abc import Sequence
from typing import TYPE_CHECKING

from seal_cli.language.english import CHECK_WHETHER, END_MARKS, PARTICLES
from seal_cli.language.morphology import verb_lemma
from seal_cli.language.tokens import Word

if TYPE_CHECKING:
    from seal_cli.language.lexicon import Lexicon

__all__ = ["set_aside"]

_DASHES = frozenset("-—–")
_CLAUSE_JOINTS = frozenset([",", ";", "and", "then", "please"])
"""Words after which a verb's base form opens a clause of the aside."""


def _dash(word: Word) -> bool:
    return word.lower == ";" and word.text[:1] in _DASHES


def _aside_end(lexicon: Lexicon, words: Sequence[Word], i: int) -> int:
    """Where the aside opened at ``i`` closes (its closing bracket or dash), or -1 when none does. Two dashes set
    an aside off only inside a clause already begun ("lunchboxes - kitchen table - bring them" is three pieces)."""
    if words[i].lower == "(":
        return next((k for k in range(i + 1, len(words)) if words[k].lower == ")"), -1)
    if not _dash(words[i]) or i == 0:
        return -1
    start = next((k + 1 for k in range(i - 1, -1, -1) if words[k].lower in END_MARKS), 0)
    if not any(lexicon.verb_at(words, k, i) is not None for k in range(start, i)):
        return -1
    end = next((k for k in range(i + 1, len(words)) if words[k].lower in END_MARKS or _dash(words[k])), -1)
    if end < 0 or not _dash(words[end]) or end == i + 1 or end + 1 >= len(words) or \
            words[end + 1].lower in END_MARKS:
        return -1                                   # one dash: a stop; or a dash ending the sentence
    return end


def _clause_in(lexicon: Lexicon, words: Sequence[Word], start: int, end: int) -> bool:
    """Whether a verb of the library, in its base form, opens a clause between ``start`` and ``end``."""
    for k in range(start, end):
        low = words[k].lower
        if (k == start or words[k - 1].lower in _CLAUSE_JOINTS) and verb_lemma(low) == low and \
                lexicon.verb_at(words, k, end) is not None:
            return True
    return False


_ASKED_NEXT = frozenset(["who", "what", "which", "whose", "what's", "who's", "how", "where", "if", "whether"])
"""Words that open the question after "for me" in "find out *for me* how many ...", "check for me which ..."."""


def _for_whom_before_question(lexicon: Lexicon, words: Sequence[Word], i: int) -> bool:
    """Whether "for me" ("for us") at ``i`` stands between a verb of the library and the question it asks ("could
    you find out *for me* how many people are in the office?", "check for me which object is the heaviest"; words41:
    "for me" cut the verb from its question — refused, or a LookAt of the question): whom the answer is for, said
    beside it. Set aside as a remark, the verb and its question are read as said together."""
    if words[i].lower != "for" or i + 2 >= len(words) or words[i + 1].lower not in ("me", "us") or \
            words[i + 2].lower not in _ASKED_NEXT:
        return False
    for j in range(max(0, i - 3), i):
        if " ".join(w.lower for w in words[j:i]) in CHECK_WHETHER[0]:
            return True                             # "figure out for me": a verb of checking (english.CHECK_WHETHER)
        found = lexicon.verb_at(words, j, i)
        if found is not None and all(w.lower in PARTICLES for w in words[j + found[1]:i]):
            return True                             # "find *out* for me": the verb and its particle
    return False


def set_aside(lexicon: Lexicon, words: Sequence[Word]) -> tuple[list[Word], list[tuple[int, int]]]:
    """The words of the command with its asides taken out, and the character spans of those asides (remarks).
    A bracket of an aside that holds a clause is taken out alone."""
    said = {w.lower for w in words}
    if "for" in said and ("me" in said or "us" in said):
        found = next((i for i in range(1, len(words)) if _for_whom_before_question(lexicon, words, i)), None)
        if found is not None:                       # "find out *for me* how many ...": whom it is done for, beside
            rest, inner = set_aside(lexicon, [*words[:found], *words[found + 2:]])
            return rest, sorted([(words[found].start, words[found + 1].end), *inner])
    if "(" not in said and ")" not in said and (";" not in said or not any(_dash(w) for w in words)):
        return list(words), []                      # the commonest case: nothing to set aside, asked cheaply
    kept: list[Word] = []
    remarks: list[tuple[int, int]] = []
    i = 0
    while i < len(words):
        w = words[i]
        end = _aside_end(lexicon, words, i)
        if end < 0:
            if w.lower not in ("(", ")"):
                kept.append(w)                      # a bracket left alone is nothing, as before
            i += 1
            continue
        if _clause_in(lexicon, words, i + 1, end):
            if not _dash(w):
                i += 1                              # "(and then close it)": its brackets only
                continue
            kept.append(w)
            i += 1
            continue
        if end > i + 1:
            remarks.append((words[i + 1].start, words[end - 1].end))
        i = end + 1
    return kept, remarks
