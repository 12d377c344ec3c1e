"""A thing "returned" with no one and nowhere to return it to goes back where it was taken from.

Transitive "return" is WordNet's ``return.v`` 02078312 "bring back to the point of departure" ("return the
book", "return it"): said with a theme and neither a recipient nor a goal, it is the library's put-back
(:func:`put_back_unit`: the storing unit that says "back", ``put back``), so the planner puts the thing back
where the robot took it from, or where such a thing is kept when the command did not take it
(:func:`seal_cli.planning.problem._back_to`). Said with a place or a person ("return the book to the shelf",
"return it to Nora") it stays a bringing; said with no thing ("go to the kitchen and return") it stays
motion back to the speaker. The parse itself is unchanged.

"Take it back" and "bring it back" (e2e27) are the same synset's other lemmas, and English tells them apart by the
verb's deixis: *bring* moves a thing toward the speaker, *take* away from them. So "bring the cup back", "bring back
the cup" stay a bringing to the speaker (the library's ``bring back``, as before); "take the cup back", "take back the
cup" (a "take" whose words hold a bare "back", in no element: the parse reads it as a taking up, ``Pick``, and drops
the particle) is a put-back: where the command took the cup from, or where a cup is kept when it did not take it. Said
with a place or a person ("take the cup back to the kitchen", "take it back to Nora") it stays what the parse says.
"""

from __future__ import annotations

import re
from collections.abc import Sequence
from dataclasses import replace

from seal_cli.frames.library import Library
from seal_cli.language.values import Evoked

__all__ = ["RETURNING_THINGS", "TAKING_AWAY", "put_back_unit", "returned", "says_back"]

RETURNING_THINGS = frozenset({"return"})
"""Verbs whose transitive sense is "bring back to the point of departure" (WordNet 02078312, whose other
lemmas, "bring back" and "take back", English also reads as bringing to the speaker: left as bringing)."""


TAKING_AWAY = frozenset({"take"})
"""Verbs that move a thing away from the speaker (deixis: "take" there, "bring" here): with a bare "back" and no
one and nowhere said, the thing goes back where it came from."""


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


def _takes_back(evoked: Evoked, text: str) -> bool:
    """Whether the frame is a "take" of a thing with a bare "back" in its words and no recipient or goal said ("take
    the cup back", "take back the cup"): the word "back" within the frame's span, in no element's span."""
    unit = evoked.lexical_unit.split()
    said = {role for role, phrase in evoked.elements.items() if not phrase.default}
    if (unit != [*unit[:1]] or unit[0] not in TAKING_AWAY or "theme" not in said or said & {"recipient", "goal"}
            or evoked.elements["theme"].kind == "person"):      # "take Tom back": a person is led, not put back
        return False
    return says_back(evoked, text)


def says_back(evoked: Evoked, text: str) -> bool:
    """Whether the frame's words hold a bare "back", in no element's span ("put the book *back* on the shelf", "take
    the cup *back*"), or its unit ends in it ("put back"): the thing is to return where it belongs, so it is not there
    now (e2e30, :func:`seal_cli.planning.problem.the_ones_not_there`)."""
    if evoked.lexical_unit.split()[-1:] == ["back"]:
        return True
    spans = [p.span for p in evoked.elements.values() if p.span is not None]
    start, end = evoked.span
    return any(word.group(0).lower() == "back" and not any(a <= start + word.start() < b for a, b in spans)
               for word in re.finditer(r"[A-Za-z]+", text[start:end]))


def returned(frames: Sequence[Evoked], library: Library, text: str = "") -> tuple[Evoked, ...]:
    """The frames with each thing returned (or taken back) to nowhere said made a put-back of it; ``text``: the
    command the frames' spans index."""
    back = put_back_unit(library)
    if back is None:
        return tuple(frames)
    frame, unit = back
    roles = set(library.frame(frame).roles)
    return tuple(replace(e, frame=frame, lexical_unit=unit,
                         elements={r: p for r, p in e.elements.items() if r in roles and not p.default})
                 if _returns_a_thing(e) or _takes_back(e, text) else e for e in frames)
