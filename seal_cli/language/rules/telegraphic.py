"""A command said in bare phrases, telegraphically, with no verb at all: "kitchen, now", "towel. bathroom. quick",
"shoes. now. from the porch", "coffee, black, no sugar".

Such a command says what is wanted, not what to do with it; English leaves the verb to the hearer, who takes it
from the phrase. **Decided** (words27): when the only phrase names a room or a part of a building one goes to
(``premises.is_premises``, from WordNet: "kitchen", "bathroom", "hall", "garage") or is a word of place
("upstairs"), the robot is asked to go there (``PATH_MEANS``); otherwise the first phrase is the thing asked for,
brought to the speaker (``REQUEST_MEANS``, as "the remote, please" is), with its "from"/"to" phrase. The other bare
phrases ("bathroom" after "towel", "black", "no sugar") say more of where or how; the robot keeps them as remarks,
visible beside the command, never silently dropped. Words of haste ("now", "quick", ``URGENT``) ask nothing more.
"""

from __future__ import annotations

from seal_cli.language.english import (
    BE_WORDS,
    DETERMINERS,
    END_MARKS,
    HERE_WORDS,
    PATH_MEANS,
    POSSESSIVES,
    PREPOSITIONS,
    PRONOUNS,
    QUESTION_WORDS,
    REQUEST_MEANS,
    URGENT,
    WH_WORDS,
)
from seal_cli.language.morphology import is_adverb, noun_lemma, parts_of_speech, verb_lemma
from seal_cli.language.premises import is_premises
from seal_cli.language.rule import START, Example, Match, Rule
from seal_cli.language.state import State, match_phrase
from seal_cli.language.tags import Tag
from seal_cli.language.tokens import Word

_SEGMENT_ENDS = frozenset([",", ";", ":"]) | END_MARKS
_PHRASE_WORDS = 4
"""The longest bare phrase read ("the red kitchen towel")."""
_WHERE = frozenset(["from", "to", "into", "in", "on"])
_SPEAKER = "me"


def _unsaid(at: int, tag: str, info: object = None, lower: str = "") -> Word:
    return Word("", at, at, tag, info, lower)


def _segments(s: State, i: int) -> list[tuple[int, int]] | None:
    """The phrases of the command from ``i`` to its end, between commas, dashes and end marks; None when any word
    there could make it more than bare phrases (a verb of the library, a question, "be", a pronoun)."""
    words = s.words
    found, start = [], i
    for k in range(i, len(words) + 1):
        if k == len(words) or words[k].lower in _SEGMENT_ENDS:
            if k < len(words) and words[k].lower == "?":
                return None
            if k > start:
                found.append((start, k))
            start = k + 1
            continue
        low = words[k].lower
        if low in BE_WORDS or low in PRONOUNS or low in QUESTION_WORDS or low in WH_WORDS or \
                low in ("and", "then", "or") or s.verb_at(k) is not None and \
                (k == 0 or words[k - 1].lower not in DETERMINERS | POSSESSIVES):
            return None
    return found


def _kind(s: State, a: int, b: int) -> str:
    """What a phrase is: "urgent" (haste or please), "path" (a preposition of where and a phrase), "np" (a bare noun
    phrase: a determiner or possessive maybe, then words of letters), else "other"."""
    words = s.words
    said = " ".join(w.lower for w in words[a:b])
    if said in URGENT:
        return "urgent"
    n = match_phrase(words, a, PREPOSITIONS)
    if n and words[a].lower in _WHERE and b - a - n >= 1 and _np(s, a + n, b):
        return "path"
    return "np" if _np(s, a, b) else "other"


def _np(s: State, a: int, b: int) -> bool:
    """Whether words ``a`` to ``b`` are a bare noun phrase: maybe a determiner or possessive, then up to four words of
    letters, no adverb ("Sadly, the door" asks nothing), the last a noun (lemminflect lists it as one, or the
    taxonomy knows it)."""
    words = s.words
    k = a + (words[a].lower in DETERMINERS or words[a].lower in POSSESSIVES)
    if not 0 < b - k <= _PHRASE_WORDS or not all(
            w.lower.isalpha() and w.lower not in DETERMINERS and w.lower not in PREPOSITIONS and
            w.lower not in URGENT and not is_adverb(w.lower) for w in words[k:b]):
        return False
    head = words[b - 1].lower
    return "noun" in parts_of_speech(head) or head in s.lexicon.things or \
        (noun_lemma(head) or head) in s.lexicon.things


def _np_words(s: State, a: int, b: int) -> tuple[Word, ...]:
    words = s.words
    return tuple(w.tagged(Tag.DET if w.lower in DETERMINERS else Tag.POSS if w.lower in POSSESSIVES else Tag.WORD)
                 for w in words[a:b])


def _telegraphic(s: State, i: int) -> Match | None:
    words = s.words
    if s.verb_at(i) is not None or any(t.tag != Tag.POLITE for t in s.out) or REQUEST_MEANS not in s.lexicon.units or \
            PATH_MEANS not in s.lexicon.units:
        return None
    segments = _segments(s, i)
    if not segments or len(segments) < 2:
        return None                                  # one phrase alone: "the remote please" is another rule's
    kinds = [_kind(s, a, b) for a, b in segments]
    if kinds[0] != "np":
        return None
    first_a, first_b = segments[0]
    lemma = noun_lemma(words[first_b - 1].lower) or words[first_b - 1].lower
    if verb_lemma(words[first_a].lower) == words[first_a].lower and first_b - first_a > 1 and \
            words[first_a + 1].lower in DETERMINERS | POSSESSIVES:
        return None                                  # "tidy the room, now": an imperative, its verb unknown
    nps = kinds.count("np")
    place = is_premises(lemma) or " ".join(w.lower for w in words[first_a:first_b]) in HERE_WORDS
    remarks: list[tuple[int, int]] = []
    at = words[first_a].start
    if nps == 1 and "path" not in kinds and place:
        out: list[Word] = [_unsaid(at, Tag.VERB, PATH_MEANS), *_np_words(s, first_a, first_b)]
        verb = PATH_MEANS
    else:
        out = [_unsaid(at, Tag.VERB, REQUEST_MEANS), _unsaid(at, Tag.PRON, None, _SPEAKER),
               *_np_words(s, first_a, first_b)]
        verb = REQUEST_MEANS
    path_said = False
    for (a, b), kind in zip(segments[1:], kinds[1:], strict=True):
        if kind == "path" and not path_said and verb == REQUEST_MEANS:
            n = match_phrase(words, a, PREPOSITIONS)
            out += [words[a].tagged(Tag.PREP, PREPOSITIONS[" ".join(w.lower for w in words[a:a + n])]),
                    *_np_words(s, a + n, b)]
            path_said = True
        elif kind == "np" and not path_said and verb == REQUEST_MEANS and words[a - 1].text.endswith(">"):
            out += [_unsaid(words[a].start, Tag.PREP, PREPOSITIONS["to"], "to"), *_np_words(s, a, b)]
            path_said = True                         # "bowl -> dishwasher": an arrow says where to (words39)
        elif kind != "urgent":
            remarks.append((words[a].start, words[b - 1].end))
    return Match(len(words) - i, tuple(out), remarks=tuple(remarks), expect=False, verb=verb, using=False)


TELEGRAPHIC = Rule("a command in bare phrases", _telegraphic, (
    Example("garage, now", "garage", Tag.WORD),
    Example("blanket. lounge. quick", "blanket", Tag.WORD),
    Example("boots. now. from the hall", "from", Tag.PREP),
    Example("tea, milk, two sugars", "tea", Tag.WORD),
    Example("mug -> sink", "sink", Tag.WORD),
), None, "bare phrases and no verb: go to the one place named, else bring the first thing asked for",
    after=frozenset([START, Tag.POLITE]))
