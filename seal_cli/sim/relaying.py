"""A message passed on to someone else, said as a person passes it on: the sender's "I" becomes the sender.

"tell Nora I'm ready" gave Nora the robot's "I'm ready": the robot is not ready, the person who sent it is. A
person relaying a message says whose it is and turns its first person singular into the third (words45):

- a statement: "I'm ready" → *the person who sent me says they're ready*; "I was right and my tea is cold" →
  *... says they were right and their tea is cold*; "it's me" → *... says it's them*;
- a question asked for the sender ("ask Sam if I can borrow his book": "can I borrow his book?") →
  *can the person who sent me borrow his book?* (:func:`asked_for`: the sender is the subject after the auxiliary,
  which agrees with it, :data:`INVERTED`: "do I" *does the person who sent me*, "am I" *is ...*);
- a request (the message opens with a verb: "tell Nora to call me", the message "call me") → *the person who
  sent me asks you to call them*; "don't forget my keys" → *... asks you not to forget their keys*.

*They* stands for the sender (singular "they": the simulator knows no one's gender) and takes the verb forms "I"
takes, but for "be": *am*, *'m* and *was* become *are*, *'re* and *were* (:data:`AGREEMENT`). "me", "my", "mine",
"myself" become "them", "their", "theirs", "themselves". A message with no first person singular ("dinner is ready")
is passed on as it was said. "we" and "us" are left: they may include the hearer or the robot. The sender is "the
person who sent me", or what the map calls the speaker (the clinic's speaker is "the doctor").
"""

from __future__ import annotations

import re

from seal_cli.language.english import NP_OPENERS, SUBJECTS
from seal_cli.language.morphology import verb_lemma

__all__ = ["SENDER", "asked_for", "relayed"]

SENDER = "the person who sent me"
"""Who a relayed message is from, when the map gives the speaker no other name."""

THIRD_PERSON = {"i": "they", "me": "them", "my": "their", "mine": "theirs", "myself": "themselves",
                "i'm": "they're", "i've": "they've", "i'll": "they'll", "i'd": "they'd"}
"""The first person singular and its third (singular "they")."""

AGREEMENT = {"am": "are", "was": "were", "wasn't": "weren't", "'m": "'re"}
"""A verb after "I" that changes after "they"; every other form of every verb is the same after both."""

INVERTED = {"am": "is", "do": "does", "have": "has", "don't": "doesn't", "haven't": "hasn't", "aren't": "isn't"}
"""An auxiliary before "I" in a question, agreeing with the sender named in its place (a singular noun phrase);
every other auxiliary ("can", "should", "was", "will") is the same before both."""

_WORD = re.compile(r"[A-Za-z]+(?:['’][A-Za-z]+)*")


def _third(match: re.Match[str], after_i: list[bool]) -> str:
    word = match.group(0)
    low = word.lower().replace("’", "'")
    if after_i[0] and low in AGREEMENT:
        after_i[0] = False
        return AGREEMENT[low]
    after_i[0] = low == "i"
    return THIRD_PERSON.get(low, word)


def _first_person(text: str) -> bool:
    """Whether ``text`` holds a first person singular word (:data:`THIRD_PERSON`'s keys)."""
    return any(w.lower().replace("’", "'") in THIRD_PERSON for w in _WORD.findall(text))


def relayed(words: str, sender: str = SENDER) -> str:
    """The message's words as the robot passes them on from ``sender`` (the module docstring): unchanged when they
    hold no first person singular."""
    if not _first_person(words):
        return words
    after_i = [False]
    third = _WORD.sub(lambda m: _third(m, after_i), words)
    first = third.split(maxsplit=1)[0].lower() if third.split() else ""
    if first in ("please", "kindly") and len(third.split()) > 1:        # "please call me": the request is "call me"
        third = third.split(maxsplit=1)[1]
        first = third.split(maxsplit=1)[0].lower()
    if first in ("don't", "don’t") and len(third.split()) > 1:
        return f"{sender} asks you not to {third.split(maxsplit=1)[1]}"
    if first not in SUBJECTS and first not in NP_OPENERS and first not in THIRD_PERSON.values() \
            and first.isalpha() and verb_lemma(first) == first:
        return f"{sender} asks you to {third}"
    return f"{sender} says {third}"


def asked_for(question: str, sender: str = SENDER) -> str:
    """A question the robot asks someone for ``sender`` (the module docstring): the "I" after its auxiliary is the
    sender, any other first person singular the third; unchanged when it holds none."""
    words = question.split()
    if not _first_person(question):
        return question
    for k in range(len(words) - 1):
        if words[k + 1] == "I":
            aux = words[k].lower().replace("’", "'")
            words[k] = INVERTED.get(aux, words[k])
            words[k + 1] = sender
            break
    after_i = [False]
    return " ".join(w if w == sender else _WORD.sub(lambda m: _third(m, after_i), w) for w in words)
