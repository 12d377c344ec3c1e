"""Question tags and what they turn into a question (words25): "the back door is locked, *isn't it*?", "you've
turned off the oven, *haven't you*?", "you couldn't pass me the salt, *could you*?".

A tag — a comma, an auxiliary or modal (positive or negative) and a pronoun, ending the sentence — asks the
hearer to confirm what the clause before it says. It adds no task of its own, so it is dropped
(:data:`QUESTION_TAG`); what it does to the clause before it is read by the clause's own rule:

- a thing said to be in a state ("the back door is locked, isn't it?") is the yes/no question of that state
  ("is the back door locked?"): check the thing, the state kept (:data:`STATE_TAGGED`);
- something the robot is said to have done, or asked whether it did ("you've turned off the oven, haven't you?",
  "did you close the garage door?") asks whether the thing is now in the state the deed leaves it in: check the
  thing (:data:`DONE_ASKED`) — a verb of the library with a result (``Lexicon.results``: closed, turned off,
  washed); other deeds ("did you see my keys?", "have you found the cat?") are searches asked, as before;
- a modal said of "you" with a tag ("you couldn't pass me the salt, could you?", "you'll close the door, won't
  you?") is a polite request, as "could you pass me the salt?" is (:data:`YOU_MODAL_TAGGED`).
"""

from __future__ import annotations

from seal_cli.language.english import (
    BE_WORDS,
    END_MARKS,
    NEGATED_AUXILIARIES,
    NP_OPENERS,
    SEEN_ASKED,
    STATE_MEANS,
    WHERE_MEANS,
)
from seal_cli.language.morphology import participles, verb_lemma
from seal_cli.language.rule import Example, Match, Rule
from seal_cli.language.rules.requests import seen_asked_from, state_said
from seal_cli.language.state import State, merge
from seal_cli.language.tags import Tag
from seal_cli.language.tokens import Word

__all__ = ["DONE_ASKED", "QUESTION_TAG", "SEEN_TAGGED", "STATE_TAGGED", "YOU_MODAL_TAGGED", "tag_at"]

TAG_AUXILIARIES = frozenset([*NEGATED_AUXILIARIES, *NEGATED_AUXILIARIES.values(), "am", "aren't", "shall", "might",
                             "must"])
"""The auxiliaries and modals that open a question tag, positive and negative ("is it", "isn't it")."""
TAG_SUBJECTS = frozenset(["it", "they", "you", "he", "she", "we", "i", "there", "this", "that"])
"""The pronouns that close a question tag."""
_STATE_BE = frozenset(["is", "are", "'s", "'re"])
"""The verbs of being a state said of a thing takes, in the present (the question is about now), said joined to
the phrase too ("the oven*'s* off, isn't it?", words26)."""
_DONE_AUXILIARIES = frozenset(["did", "have", "has", "didn't", "haven't", "hasn't"])
_DONE_SAID = frozenset(["you've", "you'd"])
""""*You've* closed the door, haven't you?": a subject and its auxiliary in one word."""
_YOU_MODALS = frozenset(["can", "could", "will", "would", "can't", "couldn't", "won't", "wouldn't"])
_YOU_MODAL_SAID = frozenset(["you'll", "you'd"])


def tag_at(s: State, i: int) -> int | None:
    """The index of the comma that opens a question tag ending the sentence that word ``i`` is in, else None:
    ", isn't it?", ", haven't you", ", could you?" (the sentence's end mark, or the command's end, right after)."""
    words = s.words
    end = next((k for k in range(i, len(words)) if words[k].lower in END_MARKS), len(words))
    c = end - 3
    if c <= i or words[c].lower != "," or words[c + 1].lower not in TAG_AUXILIARIES or \
            words[c + 2].lower not in TAG_SUBJECTS:
        return None
    return c


_VOICED_SUBJECTS = frozenset(["it", "they"])
"""Pronouns a state said as a question may be said of ("the lamp, *it* is on or off?": the phrase said first)."""


def asked_by_voice(s: State, i: int) -> int | None:
    """The index of the "?" that ends the sentence word ``i`` is in, when the sentence is a statement asked as a
    question, by its mark alone ("the back door is locked?", "the lamp, it is on or off?": words26), else None."""
    words = s.words
    end = next((k for k in range(i, len(words)) if words[k].lower in END_MARKS), len(words))
    return end if end < len(words) and words[end].lower == "?" else None


def _question_tag(s: State, i: int) -> Match | None:
    words = s.words
    if not s.out or i + 2 >= len(words) or words[i + 1].lower not in TAG_AUXILIARIES or \
            words[i + 2].lower not in TAG_SUBJECTS or i + 3 < len(words) and words[i + 3].lower not in END_MARKS:
        return None
    return Match(3)                               # "..., isn't it?": asks only for agreement; dropped


def _state_tagged(s: State, i: int) -> Match | None:
    """At the phrase that opens "the back door is locked, isn't it?": the state said of it, then a tag, is the
    yes/no question "is the back door locked?" — check the thing (``STATE_MEANS``, unsaid before the phrase); the
    state is kept by ``STATE_ASKED`` at the "is", as in the question."""
    words = s.words
    if STATE_MEANS not in s.lexicon.units or not s.np_starts(i) or words[i].lower in BE_WORDS:
        return None
    c = tag_at(s, i)
    if c is None:
        c = asked_by_voice(s, i)
        if c is None or words[i].lower not in NP_OPENERS and words[i].lower not in _VOICED_SUBJECTS:
            return None                           # "can you *check* whether ...?", "make sure ...?": no phrase
    elif words[i].lower in TAG_SUBJECTS:
        return None
    be = next((k for k in range(i + 1, c) if words[k].lower in _STATE_BE), None)
    if be is None or be + 1 >= c or any(w.lower == "," for w in words[i + 1:be]) or \
            any(s.verb_at(k) is not None and not s.np_starts(k - 1) for k in range(i + 1, be)):
        return None
    if not state_said(s, be + 1, c):
        return None
    return Match(0, (Word("", words[i].start, words[i].start, Tag.VERB, STATE_MEANS, "if"),), expect=False,
                 verb=STATE_MEANS, using=False)


def _done_verb(s: State, v: int, base: bool) -> int | None:
    """How many words the verb of the library at ``v`` takes when it is said in the form a deed asked takes (its
    base form after "did", else its participle), it is a unit whose frame leaves its theme in a state another
    frame undoes (``Lexicon.undoable``: close, turn off, heat), said joined and a phrase after it; else None."""
    words = s.words
    found = s.verb_at(v) if v < len(words) else None
    if found is None or found[2] is not None or found[0] not in s.lexicon.undoable:
        return None
    n = found[1]
    low = words[v].lower
    lemma = verb_lemma(low) or low
    if low != lemma if base else low not in participles(lemma):
        return None
    return n if s.np_starts(v + n) else None


def _done_asked(s: State, i: int) -> Match | None:
    """"*Did you close* the garage door?", "*you've turned off* the oven, haven't you?": whether the robot did a
    deed that leaves a thing in a state is whether the thing is in it: check the thing (``STATE_MEANS``). Said
    without the auxiliary first ("you've ...", "you closed ..."), only with a tag ending the sentence (else it is a
    statement)."""
    words = s.words
    low = words[i].lower
    if STATE_MEANS not in s.lexicon.units or i + 2 >= len(words):
        return None
    if low in _DONE_AUXILIARIES and words[i + 1].lower == "you":
        v, base = i + 2, low in ("did", "didn't")
    elif low in _DONE_SAID and tag_at(s, i) is not None:
        v, base = i + 1, False
    elif low == "you" and tag_at(s, i) is not None:
        v, base = (i + 2, False) if words[i + 1].lower in ("have", "'ve") else \
            (i + 2, True) if words[i + 1].lower == "did" else (i + 1, False)    # "you *did* lock it, didn't you?"
    else:
        return None
    n = _done_verb(s, v, base)
    if n is None:
        return None
    end = words[v + n - 1].end
    return Match(v + n - i, (Word(s.text_of(words[i].start, end), words[i].start, end, Tag.VERB, STATE_MEANS),),
                 expect=False, verb=STATE_MEANS, using=False)


def _seen_tagged(s: State, i: int) -> Match | None:
    """"*You haven't seen* my keys, have you?", "*you've seen* the cat, haven't you?": whether the thing was seen,
    said with the subject first and a tag ending the sentence, asks what "have you seen my keys?" asks: find the
    thing (``WHERE_MEANS``; ``SEEN_ASKED``'s auxiliaries, subjects and verbs of perceiving). Without the tag it is
    a statement, no command."""
    words = s.words
    auxiliaries, subjects, _ = SEEN_ASKED
    if WHERE_MEANS not in s.lexicon.units or tag_at(s, i) is None:
        return None
    low = words[i].lower
    if low in _DONE_SAID:
        v = i + 1
    elif low in subjects and i + 1 < len(words) and words[i + 1].lower in auxiliaries:
        v = i + 2
    else:
        return None
    return seen_asked_from(s, i, v)


def _you_modal_tagged(s: State, i: int) -> Match | None:
    """"*You couldn't* pass me the salt, could you?", "*you'll* close the door, won't you?": "you" and a modal (or
    its negative) before a verb's base form, the sentence ended by a tag: a polite request, as "could you pass me
    the salt?" is; the words before the verb are politeness."""
    words = s.words
    low = words[i].lower
    n = 1 if low in _YOU_MODAL_SAID else 2 if low == "you" and i + 1 < len(words) and \
        words[i + 1].lower in _YOU_MODALS else 0
    if not n or i + n >= len(words) or tag_at(s, i) is None:
        return None
    verb = words[i + n].lower
    if verb_lemma(verb) != verb or s.verb_at(i + n) is None:
        return None
    return Match(n, (merge(words, i, n, Tag.POLITE),))


QUESTION_TAG = Rule("question tag", _question_tag, (
    Example("the back door is locked, isn't it?", "isn't", ""),
    Example("close the window, won't you?", "won't", ""),
    Example("you couldn't pass me the salt, could you?", "could", ""),
), frozenset([","]), "', isn't it?' ending a sentence: asks for agreement only, dropped")
STATE_TAGGED = Rule("a state said, then its tag", _state_tagged, (
    Example("the back door is locked, isn't it?", "", Tag.VERB),
    Example("the back door is locked, isn't it?", "locked", Tag.COND),
    Example("the lights in the hall are still on, aren't they?", "still on", Tag.COND),
    Example("the heater's off, isn't it?", "off", Tag.COND),
    Example("the garage door is shut?", "shut", Tag.COND),
    Example("the radio, it is on or off?", "on or off", Tag.COND),
), None, "'X is locked, isn't it?', 'X is locked?': the question 'is X locked?' (LookAt, the state asked kept)",
   needs=_STATE_BE)
DONE_ASKED = Rule("whether the robot did it", _done_asked, (
    Example("did you close the garage door?", "did you close", Tag.VERB),
    Example("you've turned off the oven, haven't you?", "you've turned off", Tag.VERB),
    Example("have you heated the soup?", "have you heated", Tag.VERB),
    Example("you did switch off the iron, didn't you?", "you did switch off", Tag.VERB),
), _DONE_AUXILIARIES | _DONE_SAID | frozenset(["you"]),
    "'did you close X?', 'you've closed X, haven't you?': check X (LookAt)")
SEEN_TAGGED = Rule("seen, said first, then a tag", _seen_tagged, (
    Example("you haven't seen my keys, have you?", "you haven't seen", Tag.VERB),
    Example("you've seen the cat, haven't you?", "you've seen", Tag.VERB),
), _DONE_SAID | SEEN_ASKED[1], "'you haven't seen X, have you?': find X, as 'have you seen X?'")
YOU_MODAL_TAGGED = Rule("you and a modal, then a tag", _you_modal_tagged, (
    Example("you couldn't pass me the salt, could you?", "you couldn't", Tag.POLITE),
    Example("you'll close the door, won't you?", "you'll", Tag.POLITE),
), _YOU_MODAL_SAID | frozenset(["you"]), "'you couldn't X, could you?': a polite request to X")
