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

**Put away** leaves a thing where it is when it lies on a place the prior names (or whose class it
names), or on a table, a shelf or storage with as much prior mass as any such place (the spoon on the
kitchen counter, where spoons are kept as likely as anywhere): it is put away already, and the planner
says so rather than moving it. Otherwise it takes a place other than where the thing lies, that some
prior mass points at (the place, its class or its room) and that is a table, a shelf or storage (tiers 0
to 2: never a seat or a bed, never an appliance), ranked a little differently from a room's: a place the
prior names first, then more mass before a better tier (a towel believed kept in the bathroom goes into
its cabinet, not onto a table of a room where it is less likely kept), then tier and nearness to the
robot. With no such place (the map has no prior of the class, or its rooms hold no table, shelf or
cupboard but where the thing lies) there is no answer, and the planner refuses, saying what it knows.

``seal run`` grounds the command before the robot has seen the thing, so it cannot exclude where the
thing lies: it takes the best place overall, and when the robot finds the thing there, the thing
needs no moving: a thing lying on the place the ranking chooses without knowing where it lies has as
much prior mass as any, so it is put away already, and the plan and the run agree.
"""

from __future__ import annotations

import math
from collections.abc import Callable, Iterable, Mapping, Sequence
from dataclasses import dataclass
from typing import TYPE_CHECKING

from seal_cli.frames.taxonomy import Taxonomy, class_key, class_words
from seal_cli.maps.priors import prior_of
from seal_cli.planning.grounding import kind_of

if TYPE_CHECKING:
    from seal_cli.maps.model import Map

__all__ = ["APPLIANCES", "Spot", "back_where_taken", "kept_place", "put_in_room", "rank", "spots_of", "where_kept"]

APPLIANCES = ("washer", "heater", "cooler", "toggleable")
"""The library's categories of places for doing something to a thing, not for leaving it."""


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


def kept_place(taxonomy: Taxonomy, priors: Mapping[str, Mapping[str, float]], cls: str, spots: Sequence[Spot],
               *, lies: str | None = None, near: tuple[float, float] | None = None) -> Spot | None:
    """Where "put away" puts a thing of ``cls`` that lies on ``lies`` (None: not known): that place itself
    when the prior names it or its class (the thing is put away already); else the best other spot some
    prior mass points at that is a table, a shelf or storage (no seat, no appliance), nearest ``near``
    among equals; None if there is none."""
    prior = prior_of(priors, cls)
    here = next((s for s in spots if s.name == lies), None)
    if here is not None and _kept_already(taxonomy, prior, here, spots):
        return here
    fits = [s for s in spots if s.name != lies and mass(prior, s) > 0 and tier(taxonomy, prior, s) < 3]
    if not fits:
        return None

    def key(s: Spot) -> tuple[int, float, int, float, str]:
        level = tier(taxonomy, prior, s)
        return (min(level, 1), -round(mass(prior, s), 9), level, math.dist(s.at, near) if near else 0.0, s.name)

    return min(fits, key=key)


def _kept_already(taxonomy: Taxonomy, prior: Mapping[str, float], here: Spot, spots: Sequence[Spot]) -> bool:
    """Whether a thing lying on ``here`` is put away already: the prior names the place or its class, or the
    place is a table, a shelf or storage (no seat, no appliance) with as much prior mass as any such place
    (the spoon on the counter of the kitchen, where spoons are most likely kept)."""
    level = tier(taxonomy, prior, here)
    if level == 0:
        return True
    if level >= 3 or mass(prior, here) <= 0:
        return False
    best = max(mass(prior, s) for s in spots if tier(taxonomy, prior, s) < 3)
    return mass(prior, here) >= best - 1e-9


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



def spots_of(m: Map) -> list[Spot]:
    """A map's places as spots (named by class key, with their rooms: the map fills in a place's room)."""
    return [Spot(class_key(p.name), p.cls, p.room, p.at) for p in m.places]


def where_kept(taxonomy: Taxonomy, m: Map, cls: str) -> Callable[[str | None], str | None]:
    """"Put away" a thing of ``cls`` on ``m`` as a function of where it lies: :func:`kept_place`'s name, or
    None when no place fits (what ``seal run``'s robot asks once it knows where the thing lay)."""
    spots = spots_of(m)

    def choose(lies: str | None) -> str | None:
        spot = kept_place(taxonomy, m.priors, cls, spots, lies=class_key(lies) if lies else None, near=m.robot.xy)
        return spot.name if spot is not None else None

    return choose


def back_where_taken(lies: str | None) -> str | None:
    """Put "back": where the thing lay when the robot took it (None: not known, the goal stands)."""
    return class_key(lies) if lies else None
