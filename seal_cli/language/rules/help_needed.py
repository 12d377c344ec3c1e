"""Help a person is said to need with a deed: "Sam needs help *finding* his keys", "grandma needs a hand *carrying*
the shopping to the kitchen".

As "I could use some help finding my keys" asks for the finding (``requests.HELP_WISHED``), help said to be needed
by someone else asks the robot to do the deed: the person, the need and the help are politeness, the -ing form the
clause's verb (words49: "Sam needs help getting dressed" was a Bring of "help getting dressed" to Sam; the deed is
now read, and "getting dressed", no frame's, refused at it). Help to move somewhere ("robin needs help getting to the
exit") is guiding the person, ``requests.PERSON_NEEDING``'s, tried first."""

from __future__ import annotations

from seal_cli.language.english import DETERMINERS, POSSESSIVES
from seal_cli.language.morphology import gerund_lemma
from seal_cli.language.rule import Example, Match, Rule
from seal_cli.language.state import CLOSED, State, longest_phrase, merge
from seal_cli.language.tags import Tag

__all__ = ["HELP_NEEDED_WITH"]

NEEDING = frozenset(["needs", "wants", "could use", "would like", "would love"])
HELP = frozenset(["help", "some help", "a little help", "a bit of help", "a hand", "a little hand", "a helping hand",
                  "some assistance"])
_PERSON_WORDS = 4
"""The most words of the person's phrase ("my little brother", "the old man")."""


def _help_needed_with(s: State, i: int) -> Match | None:
    """A person's phrase (a word that is no verb, or a determiner and up to three words), "needs", help, maybe
    "with", and the -ing form of a verb of the library."""
    words = s.words
    first = words[i].lower
    if not first.isalpha() or s.verb_at(i) is not None or first in CLOSED and first not in DETERMINERS and \
            first not in POSSESSIVES:
        return None
    for k in range(i + 1, min(len(words), i + _PERSON_WORDS + 1)):
        n = longest_phrase(words, k, NEEDING)
        if n:
            break
        if k > i + 1 and not (first in DETERMINERS or first in POSSESSIVES) or not words[k].lower.isalpha():
            return None
    else:
        return None
    m = longest_phrase(words, k + n, HELP)
    if not m:
        return None
    j = k + n + m
    j += j < len(words) and words[j].lower == "with"
    if j >= len(words) or gerund_lemma(words[j].lower) is None or s.verb_at(j) is None:
        return None
    return Match(j - i, (merge(words, i, j - i, Tag.POLITE),), expect=True)


HELP_NEEDED_WITH = Rule("help a person needs with a deed", _help_needed_with, (
    Example("Sam needs help finding his keys", "Sam needs help", Tag.POLITE),
    Example("grandma needs a hand carrying the shopping to the kitchen", "grandma needs a hand", Tag.POLITE),
    Example("my brother needs help with finding his shoes", "my brother needs help with", Tag.POLITE),
    Example("Sam needs help getting dressed", "Sam needs help", Tag.POLITE),     # then refused: no frame's deed
), lambda low: low.isalpha(), "'Sam needs help finding his keys': find his keys (the deed helped with)")
