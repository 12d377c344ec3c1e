"""A search the speaker says they failed at, or are making: "*I can't find* my glasses", "*we're looking for* the
cat", "*I couldn't find* the remote anywhere".

Said to a home robot, the speaker's own fruitless search asks the robot to search: a Find of the thing (words49: it
was refused as "a statement, no command"). Only the speaker ("I", "we") and a verb of searching of the library's
Find; "I can't open the jar" stays a statement (no search; what the robot should do with the jar is not said)."""

from __future__ import annotations

from seal_cli.language.english import WHERE_MEANS
from seal_cli.language.morphology import verb_lemma
from seal_cli.language.rule import Example, Match, Rule
from seal_cli.language.state import State
from seal_cli.language.tags import Tag
from seal_cli.language.tokens import Word

__all__ = ["SEARCH_FAILED", "TRACKED_DOWN"]

SPEAKERS = frozenset(["i", "we"])
FAILED = frozenset(["can't", "cannot", "couldn't", "can't seem to", "don't seem to be able to"])
"""What says the speaker's search came to nothing, after "I"/"we" ("I *can't* find ...")."""
SEARCHING = frozenset(["i'm", "we're"])
"""The speaker, with "be": "*I'm* looking for ..."."""
SEARCH_VERBS = frozenset(["find", "locate", "spot", "see"])
SEARCH_GERUNDS = frozenset(["looking for", "searching for", "trying to find", "hunting for"])


def _phrase(s: State, i: int, table: frozenset[str]) -> int:
    """How many words at ``i`` say a phrase of ``table`` (the longest), else 0."""
    words = s.words
    for n in (6, 5, 4, 3, 2, 1):
        if i + n <= len(words) and " ".join(w.lower for w in words[i:i + n]) in table:
            return n
    return 0


_GOES_ON = frozenset([",", ";", ".", "!", "?", "and", "but", "so"])


def _goes_on(s: State, k: int) -> bool:
    """Whether another clause follows the search said at ``k``: then that clause is the request, the search its
    context ("I'm looking for my phone, *have you seen it?*": one Find, words46's remark)."""
    words = s.words
    return any(w.lower in _GOES_ON and any(v.lower.isalpha() for v in words[j + 1:])
               for j, w in enumerate(words[k:], k))


def _search_failed(s: State, i: int) -> Match | None:
    """"I can't find X", "we couldn't locate X", "I'm looking for X", "I am searching for X": the speaker, a search
    and a phrase right after it: the words up to the search are the clause's verb, Find's."""
    if WHERE_MEANS not in s.lexicon.units:
        return None
    words = s.words
    low = words[i].lower
    if low in SPEAKERS:
        k = i + 1
        n = _phrase(s, k, FAILED)
        if n and k + n < len(words) and (verb_lemma(words[k + n].lower) or words[k + n].lower) in SEARCH_VERBS:
            k += n + 1
        elif k < len(words) and words[k].lower in ("am", "are") and _phrase(s, k + 1, SEARCH_GERUNDS):
            k += 1 + _phrase(s, k + 1, SEARCH_GERUNDS)
        else:
            return None
    elif low in SEARCHING and _phrase(s, i + 1, SEARCH_GERUNDS):
        k = i + 1 + _phrase(s, i + 1, SEARCH_GERUNDS)
    else:
        return None
    if not s.np_starts(k) or _goes_on(s, k):
        return None
    end = words[k - 1].end
    return Match(k - i, (Word(s.text_of(words[i].start, end), words[i].start, end, Tag.VERB, WHERE_MEANS),),
                 expect=False, verb=WHERE_MEANS, using=False)


SEARCH_FAILED = Rule("a search the speaker failed at", _search_failed, (
    Example("I can't find my glasses", "I can't find", Tag.VERB),
    Example("we couldn't locate the cat anywhere", "we couldn't locate", Tag.VERB),
    Example("I'm looking for the remote", "I'm looking for", Tag.VERB),
    Example("I am searching for my wallet", "I am searching for", Tag.VERB),
    Example("I can't seem to find the scissors", "I can't seem to find", Tag.VERB),
), SPEAKERS | SEARCHING, "'I can't find X', 'I'm looking for X': find X")


PURSUING = frozenset(["track", "hunt"])
"""Verbs of pursuit that, with "down", are finding what was pursued ("*track down* the keys", "hunt the remote down":
the dictionaries' "to find after a search"). WordNet files "track down" and "hunt down" only under hunting animals
(hunt.v.01), so as units of Find the verb data would make every way of hunting ("falcon", "poach") a search: they are
read here, as English's phrasal verbs (words49), not listed in the library."""


def _tracked_down(s: State, i: int) -> Match | None:
    """A verb of pursuit (``PURSUING``, any form) and "down", right after it or after its object ending the clause
    ("track the dog down"), is Find's: the words of the verb are its verb, the particle split off."""
    if WHERE_MEANS not in s.lexicon.units:
        return None
    words = s.words
    if (verb_lemma(words[i].lower) or words[i].lower) not in PURSUING or i + 2 >= len(words):
        return None
    if words[i + 1].lower == "down" and s.np_starts(i + 2):
        end = words[i + 1].end
        return Match(2, (Word(s.text_of(words[i].start, end), words[i].start, end, Tag.VERB, WHERE_MEANS),),
                     expect=False, verb=WHERE_MEANS, using=False)
    if not s.np_starts(i + 1):
        return None
    q = next((k for k in range(i + 2, len(words)) if words[k].lower in _GOES_ON or words[k].lower == "down"), None)
    if q is None or words[q].lower != "down" or q + 1 < len(words) and words[q + 1].lower not in _GOES_ON:
        return None
    return Match(1, (words[i].tagged(Tag.VERB, WHERE_MEANS),), expect=False, verb=WHERE_MEANS, using=False,
                 particle=(q, WHERE_MEANS))


TRACKED_DOWN = Rule("a thing tracked down", _tracked_down, (
    Example("track down the keys", "track down", Tag.VERB),
    Example("could you hunt down the tv remote", "hunt down", Tag.VERB),
    Example("track the dog down", "track", Tag.VERB),
), lambda low: low.isalpha() and (verb_lemma(low) or low) in PURSUING, "'track down X', 'hunt X down': find X")
