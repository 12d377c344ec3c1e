"""A take verb said alone that means go, get the thing and bring it back: "fetch the remote" is Bring it to
the speaker, not Pick it up and stop there; and a bringing said with no one and nowhere to bring to ("bring the
remote", "bring the remote from the kitchen") brings it to the speaker too, not down beside where it lay.

Which units mean so is data (``fetching.tsv`` beside this module, written by ``scripts/build_fetching_units.py``
from PropBank's links to FrameNet: ``fetch.01`` "bring (back)" links Bringing alone, where ``take.01``,
``get.01`` and ``carry.01`` link other frames too). A frame the parser evoked with such a unit, as the frame
that only picks its theme up (Pick), becomes the unit's bringing frame (Bring) with the speaker as its
recipient — unless a later frame of the command does anything with the thing ("fetch a bowl and fill it",
"fetch the apple and give it to Raj": the later frame says where it goes). The parse itself is unchanged.
"""

from __future__ import annotations

import functools
from collections.abc import Sequence
from dataclasses import replace
from pathlib import Path

from seal_cli.frames.library import Library
from seal_cli.language.values import Evoked, Phrase

__all__ = ["SHIPPED", "brought", "fetching_units"]

SHIPPED = Path(__file__).resolve().parent / "fetching.tsv"
SPEAKER = Phrase("me", "me", None, "person")
"""The recipient a fetch said alone brings the thing to, as "bring *me* the jam" says it."""


@functools.cache
def fetching_units(path: Path = SHIPPED) -> dict[tuple[str, str], str]:
    """(unit, the frame the parser reads it as) → the frame it means said alone: ``("fetch", "Pick"): "Bring"``."""
    rows = [line.split("\t") for line in path.read_text().splitlines() if line and not line.startswith("#")]
    return {(row[0], row[1]): row[2] for row in rows[1:] if len(row) >= 3}


def _phrases(evoked: Evoked) -> list[Phrase]:
    return [q for p in evoked.elements.values() for q in (p, *p.conjuncts)]


def _used_later(index: int, theme: Phrase, later: Sequence[Evoked]) -> bool:
    """Whether a later frame does anything with the thing: refers to this frame's theme, or names the same thing."""
    return any((p.refers_to is not None and p.refers_to[0] == index) or (p.head == theme.head and not p.default)
               for e in later for p in _phrases(e))


def _said_where_to(evoked: Evoked) -> bool:
    """Whether a frame says whom or where the thing goes to (its recipient or goal, said, not a default)."""
    return any(r in ("recipient", "goal") and not p.default for r, p in evoked.elements.items())


def brought(frames: Sequence[Evoked], library: Library) -> tuple[Evoked, ...]:
    """The frames with each fetch said alone made a bringing to the speaker."""
    names = {f.name for f in library.frames}
    bringing = set(fetching_units().values())
    out = list(frames)
    for i, evoked in enumerate(frames):
        means = fetching_units().get((evoked.lexical_unit, evoked.frame))
        if means is None and evoked.frame in bringing and not _said_where_to(evoked):
            means = evoked.frame        # "bring the remote": a bringing said with no one and nowhere to bring to
        theme = evoked.elements.get("theme")
        if means is None or means not in names or theme is None or theme.default or evoked.inferred is not None \
                or _used_later(i, theme, frames[i + 1:]):
            continue
        roles = {e.role for e in library.frame(means).elements}
        if "recipient" not in roles or not {r for r, p in evoked.elements.items() if not p.default} <= roles:
            continue
        elements = {r: p for r, p in evoked.elements.items() if not p.default}
        out[i] = replace(evoked, frame=means, elements={**elements, "recipient": SPEAKER})
    return tuple(out)
