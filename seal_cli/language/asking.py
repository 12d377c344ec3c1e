"""A yes/no question asked of a person, as the person is asked it: "ask Raj *if he wants tea*" is putting
"do you want tea?" to Raj, not saying "if he wants tea".

An indirect question ("if"/"whether" and a clause) after a verb of asking (:data:`ASKING`) turns into the
direct question by English's rules, with worked examples of our own:

- the person asked becomes "you": the subject pronoun ("*he* wants tea", "*she* can come") or the person's own
  name or noun ("find out if *anna* wants coffee"); "him"/"her" after it become "you", "his"/"her" before a noun
  "your", "himself"/"herself" "yourself";
- the subject and its verb are inverted: a form of "be" or a modal goes first ("he *is* hungry": "*are* you
  hungry?", "she *can* come": "*can* you come?"; "was" with "you" is "were"); "has"/"have"/"had" before a past
  participle too ("has he seen it": "*have* you seen it?"); any other verb takes "do" ("he *wants* tea": "*do* you
  *want* tea?", "he *wanted*": "*did* you *want*");
- a subject that is not the person asked stays ("ask Raj if *the tea* is ready": "is the tea ready?"); a "his"/"her"/
  "him" in its question is the person asked when it names no one else ("ask Sam if I can borrow *his* book": "can I
  borrow *your* book?").

:func:`direct_question` does it on words; :func:`person_subject` says how many words at the start of a clause name
a person (the one asked when a command names nobody else: "find out if *anna* wants coffee").
"""

from __future__ import annotations

from collections.abc import Collection, Sequence

from seal_cli.language.english import (
    BE_WORDS,
    DETERMINERS,
    MODALS,
    NP_OPENERS,
    POSSESSIVES,
    PREPOSITIONS,
    PRONOUNS,
    WH_WORDS,
)
from seal_cli.language.morphology import in_dictionary, participles, verb_lemma

__all__ = ["ASKING", "IFS", "WH_ASKED", "contracted_wh", "direct_question", "person_subject"]

ASKING = frozenset(["ask", "inquire", "enquire", "query"])
"""Verbs of asking: after the person asked, "if"/"whether" and a clause is the question put to them ("*ask* Raj if
he wants tea", "*inquire* of the guest whether she is staying"). English, not any corpus's."""

IFS = frozenset(["if", "whether"])
"""The words that start an indirect yes/no question."""

_FUNCTION_WORDS = NP_OPENERS | PRONOUNS | WH_WORDS | BE_WORDS | frozenset(PREPOSITIONS) | {"i", "there", "here"}
_BE_FOR_YOU = {"is": "are", "am": "are", "are": "are", "was": "were", "were": "were", "'s": "are"}
_BE = frozenset(_BE_FOR_YOU)
_PERFECT = {"has": "have", "have": "have", "had": "had"}
_DO = {"does": "do", "do": "do", "did": "did"}
_SUBJECT_PRONOUNS = frozenset(["he", "she", "they"])
_OBJECT_SHIFT = {"him": "you", "himself": "yourself", "herself": "yourself", "themselves": "yourselves",
                 "his": "your", "their": "your", "them": "you"}


def person_subject(words: Sequence[str], people: Collection[str], things: Collection[str]) -> int:
    """How many of ``words`` (a clause after "if"/"whether") name a person as its subject: a name (capitalised, or a
    word no dictionary lists that is no thing the library knows), or a noun of people with its determiner ("the
    guest", "my mother"); 0 when the subject is none of these ("the soup", "there", a pronoun)."""
    if len(words) < 2:
        return 0
    first = words[0]
    low = first.lower()
    if low in _FUNCTION_WORDS or verb_lemma(words[1]) is None:
        pass                                                    # "the ...", "it ...": no name; a name has a verb after
    elif first[:1].isupper() or not in_dictionary(low) and low not in things and low.isalpha():
        return 1                                                # "Anna", "anna" (no dictionary lists it)
    if low in DETERMINERS | POSSESSIVES and len(words) > 2 and words[1].lower() in people:
        return 2                                                # "the guest", "my mother"
    return 0


def direct_question(words: Sequence[str], asked: Sequence[str] = ()) -> str | None:
    """The direct question an indirect one asks (``words``: "if", "he", "wants", "tea"), put to the person asked
    (``asked``: the words that name them, "Raj"), ending in "?"; None when the words are no indirect yes/no
    question (no "if"/"whether" first, or no verb after a subject). A question word first asks a wh-question
    (:func:`_wh_question`: "where the stapler is": "where is the stapler?")."""
    if words and contracted_wh(words[0]):   # "what's in the fridge": the verb already follows the question word
        return " ".join(words).rstrip(" ?.!") + "?"
    if words and words[0].lower() in WH_ASKED:
        return _wh_question(words, asked)
    if len(words) < 3 or words[0].lower() not in IFS:
        return None
    rest = list(words[1:])
    named = [w.lower() for w in asked]
    you = False
    if rest[0].lower() in _SUBJECT_PRONOUNS:
        size, you = 1, True
    elif named and [w.lower() for w in rest[:len(named)]] == named:
        size, you = len(named), True
    else:
        size = _subject_size(rest)
    if size == 0 or size >= len(rest):
        return None
    subject = ["you"] if you else rest[:size]
    verb, after = rest[size], rest[size + 1:]
    low = verb.lower()
    negated = _negated(low)
    if negated is not None:         # "he doesn't want tea": "don't you want tea?", the negation fronted with its verb
        turned = direct_question([words[0], *rest[:size], negated, *after], asked)
        if turned is None:
            return None
        first, _, others = turned.partition(" ")
        return f"{_not_contracted(first)} {others}"
    if low in _BE:
        front, tail = (_BE_FOR_YOU[low] if you else low), after
    elif low in MODALS:
        front, tail = low, after
    elif low in _PERFECT and after and after[0].lower() in participles(verb_lemma(after[0]) or after[0]):
        front, tail = (_PERFECT[low] if you else low), after
    elif low in _DO:
        front, tail = ("do" if you and low == "does" else low), after
    else:
        lemma = verb_lemma(low)
        if lemma is None:
            return None
        past = low != lemma and low in participles(lemma) and not low.endswith("s")
        front = "did" if past else ("do" if you or not low.endswith("s") else "does")
        tail = [lemma, *after]
    if you:
        tail = _shifted(tail, _SAME_PERSON.get(rest[0].lower(), _ANY_PERSON))
    elif asked and not any(w[:1].isupper() and w != "I" for w in rest):
        subject, tail = _shifted(subject, _ANY_PERSON), _shifted(tail, _ANY_PERSON)
        # "ask Sam if I can borrow *his* book": "can I borrow your book?"; "whether *her* brother is home": "is your
        # brother home?" — another's subject, the one asked the only person the question's pronouns can be (words49)
    said = [front, *subject, *tail]
    return " ".join(said).rstrip(" ?.!") + "?"


WH_ASKED = frozenset(["what", "which", "who", "whom", "whose", "where", "when", "why", "how"])
"""Question words that start an indirect wh-question ("ask Maria *where* the stapler is")."""
_WH_NOUN = frozenset(["which", "whose", "what"])
"""Question words that may take a noun after them ("*which* mug is hers", "*what* time it is")."""


def contracted_wh(word: str) -> bool:
    """Whether a word is a question word with its verb contracted onto it ("what's", "who's", "where're",
    "how'd"): an indirect question so opened is in the direct question's order already ("ask Kenji *what's in the
    fridge*": "what's in the fridge?", e2e22), as one whose question word is its subject is."""
    head, mark, clitic = word.lower().replace("\u2019", "'").partition("'")
    return bool(mark) and head in WH_ASKED and clitic in ("s", "re", "ve", "d", "ll")


def _wh_question(words: Sequence[str], asked: Sequence[str] = ()) -> str | None:
    """The direct question an indirect wh-question asks, by English's rules: the question word (with "many"/"much"
    and its noun after "how", or a noun after "which"/"whose"/"what") stays first, then the subject and its verb
    are inverted as in a yes/no question ("where *the stapler is*": "where is the stapler?", "what *he wants*":
    "what do you want?", "how many cups *she needs*": "how many cups do you need?"); a question word that is itself
    the subject keeps the order ("who *is* at the door?", "what happened?"). None when no clause follows."""
    k = 1
    low = [w.lower() for w in words]
    if low[0] == "how" and len(words) > 2 and low[1] in ("many", "much"):
        k = 2 + _noun_size(low[2:])
    elif low[0] in _WH_NOUN and len(words) > 2 and _noun_size(low[1:]) and not _verb_first(low[1:]):
        k = 1 + _noun_size(low[1:])
    front, rest = list(words[:k]), list(words[k:])
    if not rest:
        return None
    if _verb_first([w.lower() for w in rest]):      # the question word is the subject: the order stays
        said = [*front, *rest]
        return " ".join(said).rstrip(" ?.!") + "?"
    inverted = direct_question(["if", *rest], asked)
    return None if inverted is None else f"{' '.join(front)} {inverted}"


def _verb_first(words: Sequence[str]) -> bool:
    """Whether a clause starts with its verb (no subject before it): a form of "be", "do", "have", a modal, or a
    verb form no dictionary lists as anything else the subject could be ("happened")."""
    if not words:
        return False
    w = words[0]
    if w in _BE or w in MODALS or w in _PERFECT or w in _DO:
        return True
    return w not in _FUNCTION_WORDS and verb_lemma(w) not in (None, w) and w.endswith(("ed", "s"))


def _noun_size(words: Sequence[str]) -> int:
    """How many words a noun after a question word takes ("cups", "red mug"): up to the first function word or
    verb form of a clause (a subject pronoun, a determiner, "be", a modal)."""
    k = 0
    while k < len(words) and words[k] not in _FUNCTION_WORDS and words[k] not in MODALS and words[k] not in _DO \
            and words[k] not in _PERFECT:
        k += 1
    return k if k < len(words) else max(0, k - 1)


_NOT_FORMS = {"can't": "can", "won't": "will", "shan't": "shall", "ain't": "is"}
"""Verbs with "n't" whose own part is not the verb with "n't" taken off ("can't" is "can" + "not")."""
_NOT_CONTRACTED = {"can": "can't", "will": "won't", "shall": "shan't", "am": "aren't"}
"""The forms with "n't" that are not the verb and "n't" ("will": "won't"; "am I not", contracted, is "aren't I")."""


def _negated(word: str) -> str | None:
    """The verb of a form contracted with "not" ("doesn't": "does", "isn't": "is", "won't": "will", "can't": "can"),
    or None when the word is none ("want", "not")."""
    low = word.lower().replace("\u2019", "'")
    if not low.endswith("n't") or len(low) < 5:
        return None
    verb = _NOT_FORMS.get(low, low[:-3])
    return verb if verb in _BE or verb in MODALS or verb in _PERFECT or verb in _DO else None


def _not_contracted(verb: str) -> str:
    """A verb put first in a question, contracted with "not": "do" "don't", "are" "aren't", "will" "won't"."""
    return _NOT_CONTRACTED.get(verb, f"{verb}n't")


def _subject_size(words: Sequence[str]) -> int:
    """How many words a subject that is not the person asked takes: a determiner and the words up to the first
    verb form ("the tea", "the red car", "the yoga class": a verb's -s form is not its lemma); a single word ("dinner",
    "Edith")."""
    if words[0].lower() in DETERMINERS | POSSESSIVES:
        for k in range(1, len(words)):
            low = _negated(words[k]) or words[k].lower()
            if low in _BE or low in MODALS or low in _PERFECT or low in _DO or \
                    k > 1 and verb_lemma(low) not in (None, low) and low.endswith("s"):
                return k                # "the yoga *class* is full": a noun ending in s is no verb's -s (e2e33)
        return 0
    return 1


_SAME_PERSON = {"he": frozenset(["he", "him", "his", "himself"]), "she": frozenset(["she", "her", "herself"]),
                "they": frozenset(["they", "them", "their", "themselves"])}
_ANY_PERSON = _SAME_PERSON["he"] | _SAME_PERSON["she"]
"""The pronouns that can stand for the person asked, by the subject pronoun the question used ("if *he* has seen
*her* keys": "her" is someone else); after a name, "he" or "she"."""


def _shifted(words: Sequence[str], same: frozenset[str]) -> list[str]:
    """The person asked, said of in the third person (``same``: the pronouns that can stand for them), as "you"
    ("him" → "you", "his" → "your"); "her" is "your" before a word that is no preposition's and no end, else
    "you"."""
    out = []
    for k, word in enumerate(words):
        low = word.lower()
        if low not in same:
            out.append(word)
        elif low == "her":
            nxt = words[k + 1].lower() if k + 1 < len(words) else ""
            out.append("your" if nxt and nxt.isalpha() and nxt not in _AFTER_OBJECT else "you")
        elif low in ("he", "she"):
            out.append("you")
        else:
            out.append(_OBJECT_SHIFT.get(low, word))
    return out


_AFTER_OBJECT = frozenset(["to", "with", "for", "in", "on", "at", "from", "and", "or", "if", "when", "now", "today",
                           "tonight", "later", "too", "again", "please"])
"""Words after which a "her" was the object ("help *her* to the car", "ask *her* now"): not a possessive."""
