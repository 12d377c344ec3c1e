"""A command's repeat said for another place or thing: "open the wardrobe in the twin room, then *the same for the
bedroom*", "dust the shelf and *do the same with* the desk".

English says again what was just said with "the same" and what changes ("for the bedroom", "with the desk", "in the
kitchen"). The parser reads no such ellipsis: its words came out as an unknown verb ("the"), or were lost. A robot
must not guess which element the new words replace (the wardrobe's room? the thing?), and must never drop the
repeat: it is refused where it is said, with the command to say instead (:func:`refuse_the_same`).

A person said after what to tell with an additive ("tell Ben that breakfast is ready *and Anna as well*") is the
same message told to them too; the parser had kept "and Anna as well" inside the message, so Ben heard it and Anna
nothing (:func:`told_too`: when the person is one of the map's people).
"""

from __future__ import annotations

import re
from collections.abc import Collection
from dataclasses import replace

from seal_cli.errors import at_words
from seal_cli.language.values import Parse

__all__ = ["ALSO", "SAME", "refuse_the_same", "told_too"]

SAME = re.compile(r"\b(?:(?:do|does|did)\s+)?(?:the\s+)?same\s+(?:thing\s+)?(?:for|with|in|to|on)\s+[^,.;!?]+",
                  re.IGNORECASE)
"""'the same' and what it is said for, up to the end of its clause."""


def refuse_the_same(text: str) -> None:
    """Refuse a command that repeats itself with "the same for ..." (the module docstring); nothing otherwise."""
    said = SAME.search(text)
    if said is None or not text[:said.start()].strip():
        return
    repeat = said.group(0).strip()
    raise at_words(f"{repeat!r} repeats an instruction said before it for something else, and the robot cannot "
                   "tell which part of it that replaces: say the instruction again in full, naming what changes",
                   said.span(), text)


ALSO = re.compile(r"^(?P<message>.*\S)\s*,?\s+and\s+(?P<who>[\w'-]+(?:\s[\w'-]+)?)\s+(?:as\s+well|too|also)\W*$",
                  re.IGNORECASE)
"""A message that ends with "and", a person and an additive."""


def told_too(parse: Parse, people: Collection[str]) -> Parse:
    """The parse with each message told to someone that ends with "and <one of ``people``> as well" (or "too",
    "also") told to that person too, in a frame of its own after it; unchanged when none does. ``people``: the
    map's people, by their names in lower case."""
    frames = []
    for evoked in parse.frames:
        message, to = evoked.elements.get("message"), evoked.elements.get("recipient")
        said = ALSO.match(message.text or "") if message is not None and to is not None else None
        if said is None or message is None or to is None or said.group("who").lower() not in people:
            frames.append(evoked)
            continue
        text, who = said.group("message"), said.group("who")
        span = None if message.span is None else (message.span[0], message.span[0] + len(text))
        first = replace(evoked, elements={**evoked.elements, "message": replace(message, text=text, head=text,
                                                                                span=span)})
        other = replace(to, text=who, head=who, refers_to=None, conjuncts=(), span=None)
        frames += [first, replace(first, elements={**first.elements, "recipient": other})]
    return parse if len(frames) == len(parse.frames) else replace(parse, frames=tuple(frames))
