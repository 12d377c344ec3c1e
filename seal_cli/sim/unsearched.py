"""When a search ends: how likely a thing of a kind is still where the robot has not searched.

A map's prior of a class (:mod:`seal_cli.maps.priors`) says where a thing of it would be *if the house has
one*. :class:`Unsearched` keeps that prior's mass as the robot searches: every free cell its sensor sees
at a look keeps (1 − p_detect) of its mass, and the mass the prior puts on a place that is shut (a closed
fridge: the prior names it, or its class) stays whole until the robot opens the place and looks into it
from within reach, which sees all it holds (as :attr:`Agent.inspected <seal_cli.sim.agent.Agent.inspected>`
says) and leaves none. What is left,

    r = Σ_cells m_c · (1 − p)^(looks that saw c) + Σ_shut places not looked into m_P,

is the probability that such a thing, if there is one, has not been seen yet: P(unseen | in the house).
The search ends when r falls below :data:`SEARCH_END` (0.05): had the house a thing of the kind, the
robot would have seen it with probability at least 0.95. With even odds that the house has one at all,
the posterior that it has one, given that none was seen, is r / (1 + r) < 0.048.

The robot's perception is the map's sensor (range, field of view, walls), and p_detect is the sensor's
(0.9 by default), the same model the filter's negative information uses. The simulated world detects
what is in view every time, so the rule is conservative there.
"""

from __future__ import annotations

from collections.abc import Iterable
from dataclasses import dataclass, field

import numpy as np
from numpy.typing import NDArray

from seal_cli.maps.model import Map
from seal_cli.maps.priors import FLOOR

__all__ = ["SEARCH_END", "Unsearched"]

SEARCH_END = 0.05
"""The unsearched share of a prior below which a search for a thing of that kind ends, not found."""


@dataclass
class Unsearched:
    """The prior mass of one class not yet searched: per free cell of the map, and per shut place."""

    map: Map = field(repr=False)
    cls: str
    cells: NDArray[np.float64] = field(repr=False)
    """Per free cell (``map.free_centres``), the mass still unsearched there."""
    inside: dict[str, float]
    """Per place shut at the start (by name), the mass the prior puts in it, still unsearched."""
    p_detect: float

    @classmethod
    def of(cls, m: Map, key: str, shut: Iterable[str] = ()) -> Unsearched:
        """The prior of class ``key`` on ``m``, with the mass of its place targets that are among ``shut``
        (place names) put inside those places instead of around them."""
        shut = {p for p in shut}
        prior = m.prior(key)
        total = sum(prior.masses.values())
        scale = (1 - FLOOR) / total if total > 0 else 1.0
        cells = np.full(len(m.free_centres), prior.uniform / max(len(m.free_centres), 1))
        inside: dict[str, float] = {}
        for target, mass in prior.masses.items():
            if target == "_rest":
                continue
            share = mass * scale
            places = _places_of(m, target)
            closed = [p for p in places if p in shut]
            for place in closed:
                inside[place] = inside.get(place, 0.0) + share / len(places)
            around = share * (1 - len(closed) / len(places)) if places else share   # a room: all of it
            members = m.target_cells(target)
            if around > 0 and len(members):
                cells[members] += around / len(members)
        return cls(m, key, cells, inside, m.sensor.p_detect)

    @property
    def left(self) -> float:
        """r: the probability that a thing of the class, if the house has one, has not been seen yet."""
        return float(self.cells.sum()) + sum(self.inside.values())

    def saw(self, visible: NDArray[np.bool_], looked_into: Iterable[str] = ()) -> None:
        """One look: the free cells seen (a mask over ``map.free_centres``) and the shut places looked into
        from within reach (all they hold is seen)."""
        self.cells[visible] *= 1.0 - self.p_detect
        for place in looked_into:
            if place in self.inside:
                self.inside[place] = 0.0

    def left_at(self, targets: Iterable[str]) -> float:
        """The mass still unsearched at some of the prior's targets (rooms, places, place classes, by name): on
        their cells and inside their shut places."""
        targets = list(targets)
        mask = np.zeros(len(self.cells), dtype=bool)
        places: set[str] = set()
        for target in targets:
            mask[self.map.target_cells(target)] = True
            places.update(_places_of(self.map, target))
        return float(self.cells[mask].sum()) + sum(m for p, m in self.inside.items() if p in places)

    def searched_rooms(self, share: float = 0.5) -> list[str]:
        """The rooms of which at least ``share`` of the prior's mass there has been searched, in the map's
        order (by how the cells compare with an unsearched copy)."""
        fresh = Unsearched.of(self.map, self.cls, self.inside)
        rooms = self.map.free_cell_room
        done = []
        for i, room in enumerate(self.map.rooms):
            there = rooms == i
            before = float(fresh.cells[there].sum())
            if before > 0 and float(self.cells[there].sum()) <= (1 - share) * before:
                done.append(room.name)
        return done


def _places_of(m: Map, target: str) -> list[str]:
    """The names of the places a prior target names (a place, or every place of a class); none for a room."""
    resolved = m.prior_target(target)
    if resolved is None or resolved[0] == "room":
        return []
    return [m.places[i].name for i in resolved[1]]
