"""A verb of getting said of a state, not of a thing: "help her *get dressed*", "get ready", "get changed".

"get" with a past participle or an adjective that is no noun, ending its clause with no determiner before it, is
becoming: "get dressed" is dressing oneself, "get ready" making ready. No thing is picked up, and no frame of the
library does it; read as Pick it took "dressed" for a thing (words49). :func:`becoming` finds the words; the parser
refuses the command at the verb, saying what it read."""

from __future__ import annotations

from collections.abc import Sequence

from seal_cli.language.morphology import inflected, parts_of_speech
from seal_cli.language.tags import Tag
from seal_cli.language.tokens import Word

__all__ = ["becoming"]

GETTING = frozenset(["get", "gets", "got", "getting", "gotten"])
_ENDS = frozenset([Tag.SEP, Tag.END, Tag.VERB, Tag.POLITE])


def becoming(words: Sequence[Word]) -> tuple[Word, Word] | None:
    """The first verb of getting (a tagged ``VERB``) whose object is one word of state ending its clause, with that
    word; None when there is none."""
    for i, verb in enumerate(words[:-1]):
        state = words[i + 1]
        if verb.tag != Tag.VERB or verb.lower not in GETTING or state.tag not in (Tag.WORD, Tag.RESULT) or \
                i + 2 < len(words) and words[i + 2].tag not in _ENDS:
            continue
        if _a_state(state.lower):
            return verb, state
    return None


def _a_state(low: str) -> bool:
    """A past participle ("dressed", "changed", "lost") or an adjective English lists as no noun ("ready")."""
    pos = parts_of_speech(low)
    if "noun" in pos or not low.isalpha():
        return False
    return "adj" in pos or inflected(low)
