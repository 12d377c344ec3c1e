"""A thing "returned" with no one and nowhere to return it to goes back where it was taken from.

Transitive "return" is WordNet's ``return.v`` 02078312 "bring back to the point of departure" ("return the
book", "return it"): said with a theme and neither a recipient nor a goal, it is the library's put-back
(:func:`put_back_unit`: the storing unit that says "back", ``put back``), so the planner puts the thing back
where the robot took it from, or where such a thing is kept when the command did not take it
(:func:`seal_cli.planning.problem._back_to`). Said with a place or a person ("return the book to the shelf",
"return it to Nora") it stays a bringing; said with no thing ("go to the kitchen and return") it stays
motion back to the speaker. The parse itself is unchanged.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import replace

from seal_cli.frames.library import Library
from seal_cli.language.values import Evoked

__all__ = ["RETURNING_THINGS", "put_back_unit", "returned"]

RETURNING_THINGS = frozenset({"return"})
"""Verbs whose transitive sense is "bring back to the point of departure" (WordNet 02078312, whose other
lemmas, "bring back" and "take back", English also reads as bringing to the speaker: left as bringing)."""


def put_back_unit(library: Library) -> tuple[str, str] | None:
    """The library's frame and unit that put a thing back where it was taken from (a storing unit ending in
    "back"), or None when the library has none."""
    return next(((f.name, u.text) for f in library.frames for u in f.lexical_units
                 if u.stores and u.text.split()[-1:] == ["back"]), None)


def _returns_a_thing(evoked: Evoked) -> bool:
    """Whether the frame is a "return" of a thing said with no recipient and no goal."""
    unit = evoked.lexical_unit.split()
    said = {role for role, phrase in evoked.elements.items() if not phrase.default}
    return unit == [*unit[:1]] and unit[0] in RETURNING_THINGS and "theme" in said and not said & {"recipient", "goal"}


def returned(frames: Sequence[Evoked], library: Library) -> tuple[Evoked, ...]:
    """The frames with each thing returned to nowhere said made a put-back of it."""
    back = put_back_unit(library)
    if back is None:
        return tuple(frames)
    frame, unit = back
    roles = set(library.frame(frame).roles)
    return tuple(replace(e, frame=frame, lexical_unit=unit,
                         elements={r: p for r, p in e.elements.items() if r in roles and not p.default})
                 if _returns_a_thing(e) else e for e in frames)
