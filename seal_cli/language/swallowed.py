"""Clauses swallowed into an element: a verb of the library inside the text of a phrase that fills a
frame element ("go to the sink *to meet* Alex" → goal "the sink to meet Alex", Meet lost). A robot
must never drop an instruction silently, so the parser refuses them (a
:class:`~seal_cli.language.lexicon.CommandError` at the verb) and `seal bench parse` counts them on
every corpus.

A word of an element's text (not its first) is a swallowed verb when it is a form of a word that
begins one of the library's lexical units and, in the command, it is said as a verb is, not as a noun:

* in its base form (an imperative's) after "to": an infinitive ("the sink *to meet* Alex");
* in its base form right before what begins a noun phrase and is no noun itself (an object pronoun,
  a determiner, a name): "the counter *escort her* back", "a loaf of bread *put the* slice ...";
* a participle before an object pronoun: "a fireplace *taking it* to the table" (but "a plate
  *holding a candle*" says what the plate holds);

or, whether the library lists it or not, a bare word used mostly as a verb
(:func:`~seal_cli.language.verb_usage.mostly_verb`, from WordNet's tag counts) in its base form right after "and",
"then" or "," and before what a verb takes or the end ("the kitchen and *wait there*": a verb read as a noun of
a list; "the cup and *plate*" is a list);

and never after a determiner or a possessive ("the *hand* soap": a noun) or a subject ("where *you
found* them" says where, it asks nothing).

Messages are said, not done (their verbs are no instructions), and a relative clause is kept
apart from the text, so neither is looked at.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass

from seal_cli.language.english import DETERMINERS, NP_OPENERS, OBJECT_PRONOUNS, SUBJECTS, VERB_JOINTS, VERB_TAKES
from seal_cli.language.lexicon import Lexicon, Word
from seal_cli.language.morphology import verb_lemma
from seal_cli.language.state import CLOSED
from seal_cli.language.values import Parse
from seal_cli.language.verb_usage import mostly_verb

__all__ = ["Swallowed", "swallowed", "verb_at"]


@dataclass(frozen=True)
class Swallowed:
    """A verb said inside the text of a frame's element: the frame's index, the element, the verb."""

    frame: int
    element: str
    verb: str
    start: int                 # where the verb is, in characters of the command

    def to_json(self) -> dict[str, object]:
        return {"frame": self.frame, "element": self.element, "verb": self.verb, "start": self.start}


def swallowed(parse: Parse, words: Sequence[Word], lexicon: Lexicon,
              things: frozenset[str] = frozenset()) -> tuple[Swallowed, ...]:
    """The verbs said inside the elements' texts of a parse (empty when none: the usual case), given
    the command's words (the tagger's, or :func:`~seal_cli.language.lexicon.tokenize`'s) and the
    classes the library knows (``Taxonomy.known_classes``: a word naming one is a noun, "next to
    *microwave*")."""
    said = [(index, role, phrase.span) for index, evoked in enumerate(parse.frames)
            for role, phrase in evoked.elements.items()
            if phrase.span is not None and not phrase.default and phrase.kind != "message"
            and phrase.refers_to is None]
    found: list[Swallowed] = []
    for index, role, (start, end) in said:
        for k, word in enumerate(words):     # not the phrase's first word: what the grammar began it with
            if start < word.start and word.end <= end and verb_at(words, k, lexicon, things):
                found.append(Swallowed(index, role, word.text, word.start))
                break
    return tuple(found)


_NOUN_PHRASE_STARTS = (OBJECT_PRONOUNS | DETERMINERS) - {"that", "this"}
"""Words that begin a noun phrase and are no noun: after a verb, its object ("this", "that" may be
relative pronouns or demonstratives: left out)."""
_NO_VERB_AFTER = NP_OPENERS | SUBJECTS | {"you"}
"""Words after which a verb's form is no imperative: a noun ("the *hand* soap") or a subject's verb."""


def verb_at(words: Sequence[Word], k: int, lexicon: Lexicon, things: frozenset[str] = frozenset()) -> bool:
    """Whether word ``k`` of a command is said as a verb of the library (the module docstring)."""
    before = words[k - 1].lower if k > 0 else ""
    after = words[k + 1] if k + 1 < len(words) else None
    then = after.lower if after is not None else ""
    if before in VERB_JOINTS and (after is None or then in VERB_TAKES) and \
            _verb_after_joint(words[k], things, lexicon):
        return True                      # "go to the kitchen and *wait* there"
    starts_np = then in _NOUN_PHRASE_STARTS or after is not None and after.text[:1].isupper()
    if before != "to" and not starts_np and then not in OBJECT_PRONOUNS or before in _NO_VERB_AFTER:
        return False                     # no sign of a verb (the cheap tests first: most words stop here)
    low = words[k].lower.split(" ", 1)[0]   # a word the tagger joined: its first ("warm up")
    lemma = verb_lemma(low)
    if lemma is None or lemma not in lexicon.units or low in things:
        return False
    if low != lemma:                     # "a fireplace *taking it* to the table" does something; "a plate
        return low.endswith("ing") and then in OBJECT_PRONOUNS   # *holding a* candle" says what it has;
    return before == "to" or starts_np   # "washed *sliced* Apple" is a result said before its noun


def _verb_after_joint(word: Word, things: frozenset[str], lexicon: Lexicon) -> bool:
    """Whether a word after "and", "then" or "," is a bare verb's base form (mostly used as one, no thing the
    library knows, no closed-class word), said as the tagger's rule ``verb after a joint`` reads it."""
    low = word.lower
    return low.isalpha() and not word.text[:1].isupper() and low not in CLOSED and low not in things and \
        low not in lexicon.things and verb_lemma(low) == low and mostly_verb(low)
