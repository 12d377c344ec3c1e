"""A command's repeat said for another place or thing: "open the wardrobe in the twin room, then *the same for the
bedroom*", "dust the shelf and *do the same with* the desk".

English says again what was just said with "the same" and what changes ("for the bedroom", "with the desk", "in the
kitchen"). The parser reads no such ellipsis: its words came out as an unknown verb ("the"), or were lost. A robot
must not guess which element the new words replace (the wardrobe's room? the thing?), and must never drop the
repeat: it is refused where it is said, with the command to say instead (:func:`refuse_the_same`).
"""

from __future__ import annotations

import re

from seal_cli.errors import SealError, Where

__all__ = ["SAME", "refuse_the_same"]

SAME = re.compile(r"\b(?:(?:do|does|did)\s+)?(?:the\s+)?same\s+(?:thing\s+)?(?:for|with|in|to|on)\s+[^,.;!?]+",
                  re.IGNORECASE)
"""'the same' and what it is said for, up to the end of its clause."""


def refuse_the_same(text: str) -> None:
    """Refuse a command that repeats itself with "the same for ..." (the module docstring); nothing otherwise."""
    said = SAME.search(text)
    if said is None or not text[:said.start()].strip():
        return
    repeat = said.group(0).strip()
    raise SealError(f"{repeat!r} repeats an instruction said before it for something else, and the robot cannot "
                    "tell which part of it that replaces: say the instruction again in full, naming what changes",
                    Where(None, 1, said.start() + 1), source_line=text)
