"""A thing where words are asked: "answer *the door*", "answer *the phone*" are no answering of a question.

A frame element of type ``question`` (what is asked: Answer's theme) is said in words ("answer *the
question* of the person at the door", "answer *Sam's question*"). Filled by a plain noun phrase whose
head is a thing the library names (a class of its taxonomy or a synonym of one: "door", "phone"), the
verb is another verb (WordNet's "answer: react to a signal", as one answers a door or a telephone),
which no frame of the library has: the parser refuses the command at the verb instead of asking the
door a question.
"""

from __future__ import annotations

from seal_cli.frames.library import Library
from seal_cli.language.lexicon import Lexicon
from seal_cli.language.values import Evoked, Parse

__all__ = ["ASKED_TYPES", "thing_asked"]

ASKED_TYPES = frozenset(["question"])
"""Element types whose fillers are words asked, never things."""


def thing_asked(parse: Parse, library: Library, lexicon: Lexicon) -> tuple[Evoked, str] | None:
    """The first frame whose element of what is asked is filled by a thing the library names, with the element's
    role; None when there is none."""
    for evoked in parse.frames:
        frame = library.by_name.get(evoked.frame)
        if frame is None:
            continue
        for element in frame.elements:
            phrase = evoked.elements.get(element.role)
            if element.type in ASKED_TYPES and phrase is not None and not phrase.default and \
                    phrase.refers_to is None and phrase.relative is None and phrase.kind == "thing" and \
                    phrase.head.lower() in lexicon.things and \
                    (phrase.text or "").lower().split()[-1:] == [phrase.head.lower()]:
                return evoked, element.role
    return None
