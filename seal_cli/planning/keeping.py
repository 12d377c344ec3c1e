"""Where a thing is put: a map's places ranked for receiving a thing of a class.

Two commands leave the place to the robot. "Put away the cup" says no goal at all: the cup goes where
the map believes cups are kept (:func:`kept_place`). "Take the cup to the kitchen" says a room: the cup
goes on the place in that room where such a thing is put (:func:`put_in_room`), not on the room's
nearest place, which may be its sink. Both rank the candidate places the same way, by
:func:`rank`:

1. **tier** — 0: the map's prior of the class names the place or its class ("apple: {fridge: 0.4,
   counter: 0.4}"); 1: furniture that is no seat (a table, a counter, a desk, a shelf, a
   nightstand); 2: any other place that is no appliance (a cabinet, a basket, a coat rack, a
   class the library does not know); 3: a seat or a bed (the library's ``seat`` category); 4: an
   appliance or a fixture for doing something to a thing (a sink, a bathtub, a stove, a fridge: the
   ``washer``, ``heater``, ``cooler`` and ``toggleable`` categories);
2. **mass** — then more prior mass first: what the prior gives the place, its class and its room;
3. then the caller's distance (from the thing for "put away", from the robot in a room).

A class is read as the library reads a compound it does not list: by its head (a ``bathroom_sink`` is
a sink, a ``reception_desk`` a desk: :func:`~seal_cli.planning.grounding.kind_of`).

**Put away** takes only places some prior mass points at (the place, its class or its room) and that
are no appliance (tiers 0 to 3), other than the place the thing lies on now, ranked a little
differently: a place the prior names first, seats last, and between them more mass before a better
tier (a towel believed to be kept in the bathroom goes into its cabinet, not onto a table of the
laundry room where it is less likely kept); then tier and nearness to the thing. Never the place
it lies on now: "put away" says the thing
is out of place, so it is never put straight back. With no such place (the map has no prior of the
class, or the prior names nothing but where the thing is) there is no answer, and the planner refuses,
naming the classes the map does know where to keep.
"""

from __future__ import annotations

import math
from collections.abc import Iterable, Mapping, Sequence
from dataclasses import dataclass

from seal_cli.frames.taxonomy import Taxonomy, class_key, class_words
from seal_cli.planning.grounding import kind_of

__all__ = ["APPLIANCES", "STORING_UNITS", "Spot", "kept_place", "put_in_room", "rank"]

APPLIANCES = ("washer", "heater", "cooler", "toggleable")
"""The library's categories of places for doing something to a thing, not for leaving it."""

STORING_UNITS = frozenset({"put away", "store", "stow", "stow away", "tidy away", "clear away"})
"""Lexical units of Place that, said without a goal, mean "where it is kept" rather than "down here"."""


@dataclass(frozen=True)
class Spot:
    """A candidate place: its name, class, room and where it stands."""

    name: str
    cls: str
    room: str | None
    at: tuple[float, float]


def tier(taxonomy: Taxonomy, prior: Mapping[str, float], spot: Spot) -> int:
    """The spot's tier for a class whose prior is ``prior`` (see the module docstring)."""
    if _named_mass(prior, spot) > 0:
        return 0
    if any(kind_of(taxonomy, spot.cls, kind) is True for kind in APPLIANCES):
        return 4
    if kind_of(taxonomy, spot.cls, "seat") is True:
        return 3
    if kind_of(taxonomy, spot.cls, "furniture") is True:
        return 1
    return 2


def _named_mass(prior: Mapping[str, float], spot: Spot) -> float:
    keys = {class_key(spot.name), class_key(spot.cls), class_words(spot.cls)[-1] if spot.cls else ""}
    return sum(prior.get(k, 0.0) for k in keys if k)


def mass(prior: Mapping[str, float], spot: Spot) -> float:
    """The prior mass pointing at a spot: its own, its class's and its room's."""
    return _named_mass(prior, spot) + (prior.get(class_key(spot.room), 0.0) if spot.room else 0.0)


def rank(taxonomy: Taxonomy, prior: Mapping[str, float], spot: Spot) -> tuple[int, float]:
    """The sort key of a spot, best first: its tier, then more prior mass."""
    return tier(taxonomy, prior, spot), -round(mass(prior, spot), 9)


def prior_of(priors: Mapping[str, Mapping[str, float]], cls: str) -> dict[str, float]:
    """A class's prior masses by class key (empty for a class the map has no prior of)."""
    key = class_key(cls)
    for name, masses in priors.items():
        if class_key(name) == key:
            return {class_key(t): float(m) for t, m in masses.items()}
    return {}


def kept_place(taxonomy: Taxonomy, priors: Mapping[str, Mapping[str, float]], cls: str, spots: Sequence[Spot],
               *, lies: str | None = None, near: tuple[float, float] | None = None) -> Spot | None:
    """Where "put away" puts a thing of ``cls``: the best spot some prior mass points at that is no
    appliance, other than ``lies`` (where the thing is now); nearest ``near`` among equals; None if none."""
    prior = prior_of(priors, cls)
    fits = [s for s in spots if s.name != lies and mass(prior, s) > 0 and tier(taxonomy, prior, s) < 4]
    if not fits:
        return None

    def key(s: Spot) -> tuple[int, float, int, float, str]:
        level = tier(taxonomy, prior, s)
        return ({0: 0, 3: 2}.get(level, 1), -round(mass(prior, s), 9), level, math.dist(s.at, near) if near else 0.0,
                s.name)

    return min(fits, key=key)


def put_in_room(taxonomy: Taxonomy, priors: Mapping[str, Mapping[str, float]], cls: str | None,
                spots: Iterable[Spot], distance: Mapping[str, float]) -> Spot | None:
    """Where a thing of ``cls`` goes when a room is its goal: the best of the room's ``spots``, the
    nearest by ``distance`` (the robot's drive to each; a spot missing from it cannot be reached)
    among equals."""
    prior = prior_of(priors, cls) if cls else {}
    reachable = [s for s in spots if s.name in distance]
    if not reachable:
        return None
    return min(reachable, key=lambda s: (rank(taxonomy, prior, s), distance[s.name], s.name))

