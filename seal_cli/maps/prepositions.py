"""How a room is said after "is": *in* the kitchen, *on* the balcony.

English puts a person or a thing *in* an enclosed room and *on* an open platform: a balcony, a deck, a
patio, a terrace, a porch, a landing, a veranda, a roof. A room's preposition is the one its map gives
(``preposition: on`` in the room's YAML, for names English cannot tell, "the sun_trap") or, by default, the
one English gives its head noun (the last word of the name: ``back_deck`` is a deck). :func:`located` says
"on the back deck" for every sentence of ``seal run`` and ``seal plan`` that says where something is.
"""

from __future__ import annotations

from typing import TYPE_CHECKING

from seal_cli.frames.taxonomy import class_key

if TYPE_CHECKING:
    from seal_cli.maps.model import Map

__all__ = ["OPEN_PLATFORMS", "ROOM_PREPOSITIONS", "located", "preposition", "room_preposition"]

ROOM_PREPOSITIONS = ("in", "on", "at")
"""The prepositions a map may give a room."""

OPEN_PLATFORMS = frozenset(["balcony", "deck", "patio", "terrace", "porch", "landing", "veranda", "verandah",
                            "roof", "rooftop", "platform", "stage", "decking", "pier", "jetty", "dock", "lawn",
                            "sundeck", "mezzanine", "stoop"])
"""Head nouns of open platforms, which English says *on* ("on the balcony", "on the landing"): a closed list
of the language, not read off any command."""


def preposition(name: str) -> str:
    """The preposition English gives a room of that name: "on" for an open platform (its last word one of
    :data:`OPEN_PLATFORMS`, singular or plural), "in" otherwise."""
    words = class_key(name).split("_")
    head = words[-1] if words else ""
    singular = head[:-3] + "y" if head.endswith("ies") else head[:-2] if head.endswith("hes") else \
        head[:-1] if head.endswith("s") else head
    return "on" if head in OPEN_PLATFORMS or singular in OPEN_PLATFORMS else "in"


def room_preposition(room: str, m: Map | None = None) -> str:
    """The preposition a room is said with: the map's for the room when it gives one, else English's
    (:func:`preposition`). ``seal map --json`` lists it per room."""
    if m is not None:
        index = m.room_id(room)
        given = m.rooms[index].preposition if index is not None else None
        if given:
            return given
    return preposition(room)


def located(room: str, m: Map | None = None) -> str:
    """Where something is, said: "in the kitchen", "on the balcony" (:func:`room_preposition`), the map's spelling
    said as words."""
    return f"{room_preposition(room, m)} the {room.replace('_', ' ')}"
