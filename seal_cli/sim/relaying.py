"""A message passed on to someone else, said as a person passes it on: the sender's "I" becomes the sender.

"tell Nora I'm ready" gave Nora the robot's "I'm ready": the robot is not ready, the person who sent it is. A
person relaying a message says whose it is and turns its first person singular into the third (words45):

- a statement: "I'm ready" → *the person who sent me says they're ready*; "I was right and my tea is cold" →
  *... says they were right and their tea is cold*; "it's me" → *... says it's them*;
- a question asked for the sender ("ask Sam if I can borrow his book": the parser's "can I borrow your book?",
  :mod:`~seal_cli.language.asking`) → *can the person who sent me borrow your book?* (:func:`asked_for`: the
  sender is the subject after the auxiliary, which agrees with it, :data:`INVERTED`: "do I" *does the person who
  sent me*, "am I" *is ...*);
- a request (the message opens with a verb: "tell Nora to call me", the message "call me") → *the person who
  sent me asks you to call them*; "don't forget my keys" → *... asks you not to forget their keys*.

The one the message is passed on to is "you" in it (words47): "tell Sam I will meet *him*" → *... says they will
meet you*; a "he" or "she" (with the verb agreeing: "he *is*" → *you are*, "she *wants*" → *you want*), "his", "her",
"himself" stand for the hearer when the message names no one else (no capitalised word but "I" and a first word
of the dictionary: "tell Sam Anna misses him" is passed on as said). "her" before a noun or adjective is "your"
("her keys"), else "you".

*They* stands for the sender (singular "they": the simulator knows no one's gender) and takes the verb forms "I"
takes, but for "be": *am*, *'m* and *was* become *are*, *'re* and *were* (:data:`AGREEMENT`). "me", "my", "mine",
"myself" become "them", "their", "theirs", "themselves". A message with no first person singular ("dinner is ready")
is passed on as it was said. "we" and "us" are left: they may include the hearer or the robot. The sender is "the
person who sent me", or what the map calls the speaker (the clinic's speaker is "the doctor").
"""

from __future__ import annotations

import re

from seal_cli.language.english import NP_OPENERS, PARTICLES, SUBJECTS, TIME_WORDS
from seal_cli.language.morphology import in_dictionary, parts_of_speech, verb_lemma

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

SECOND_PERSON = {"he": "you", "she": "you", "him": "you", "his": "your", "hers": "yours", "himself": "yourself",
                 "herself": "yourself", "he's": "you're", "she's": "you're", "he'll": "you'll", "she'll": "you'll",
                 "he'd": "you'd", "she'd": "you'd"}
"""A third person singular and the second, for the hearer of a relayed message ("her": :func:`_hearer`)."""

HEARER_AGREEMENT = {"is": "are", "was": "were", "isn't": "aren't", "wasn't": "weren't", "has": "have",
                    "hasn't": "haven't", "does": "do", "doesn't": "don't"}
"""A verb after "he"/"she" that changes after "you" besides a present's "-s" ("wants": "want")."""

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


def _common(word: str) -> bool:
    """Whether a capitalised first word may be no name: a word of the dictionary or a pronoun ("Dinner", "He")."""
    low = word.lower()
    return in_dictionary(low) or low in SECOND_PERSON or low in ("her", "i")


def _hearer(words: str) -> str:
    """``words`` with the third person singular that stands for the hearer said in the second (the module
    docstring); unchanged when the message names someone else (a capitalised word but "I")."""
    found = list(_WORD.finditer(words))
    if any(m.group(0)[0].isupper() and m.group(0).split("'")[0] != "I" and (k or not _common(m.group(0)))
           for k, m in enumerate(found)) or \
            not any(m.group(0).lower() in SECOND_PERSON or m.group(0).lower() == "her" for m in found):
        return words
    out, last, subject = [], 0, False
    for k, m in enumerate(found):
        word, low = m.group(0), m.group(0).lower()
        new = word
        if subject and low in HEARER_AGREEMENT:
            new = HEARER_AGREEMENT[low]
        elif subject and low.endswith("s") and (verb_lemma(low) or low) != low and "verb" in parts_of_speech(low):
            new = verb_lemma(low) or word        # "she *wants* tea": "you want tea"
        elif low == "her":
            after = found[k + 1].group(0).lower() if k + 1 < len(found) else ""
            noun = bool(after) and words[m.end():found[k + 1].start()].strip() == "" and \
                after not in TIME_WORDS and after not in PARTICLES and bool({"noun", "adj"} & parts_of_speech(after))
            new = "your" if noun else "you"
        elif low in SECOND_PERSON:
            new = SECOND_PERSON[low]
        subject = low in ("he", "she")
        out.append(words[last:m.start()] + (new[0].upper() + new[1:] if word[0].isupper() else new))
        last = m.end()
    return "".join(out) + words[last:]


def relayed(words: str, sender: str = SENDER, *, hearer: bool = False) -> str:
    """The message's words as the robot passes them on from ``sender`` (the module docstring): unchanged when they
    hold no first person singular. ``hearer``: said to the one it was for, whom a "he"/"she" may stand for."""
    if hearer:
        words = _hearer(words)
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
