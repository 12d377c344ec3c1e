"""``prior_optimal``: the best any searcher can do with the map's priors — the reference SeFM is measured against.

It knows what SeFM knows before it starts (the places, the priors of every class, the plan) and
nothing more, and it updates the priors *exactly* with what it has seen. The world's detector
does not miss, so the posterior of a class is its prior with every point removed where a thing
of that class would have been seen: a point the sensor saw (in range and in line of sight, by the
sensor's fan of rays half a cell apart at full range, which disagrees with exact line of sight on
0.1-0.4 % of the cells in range on the apartment; ten times cheaper) unless a
thing there would lie in a receptacle that was shut at that look, and every point of a place the
robot looked into from within reach (what is in or on it is seen at hand). Where a thing "would
lie" follows the layouts' own rule (:func:`~seal_cli.bench.mapsuite.sample_layout`): a point within
reach of a place the class's prior names is in or on the nearest such place.

It looks where the view model of :mod:`~seal_cli.sim.policies.completion` says — the candidate
view whose drive, look and greedy continuation give the shortest expected drive to finish the
whole remaining plan, counting what is seen on the way (a drive is a sequence of looks, and stops at
the one that finds the thing) — and chooses again after every look with the exact posterior
(receding horizon). When nothing of what it seeks is left anywhere it can reach it sweeps the
frontier (:class:`~seal_cli.sim.policies.coverage.CoveragePolicy`), so it is complete.

**Where it is exact, and where it stops being.** The posterior is exact (for this detector). The
sensing model of the choice is exact up to the lattice: a look sees what the sensor sees from the
lattice node nearest the robot (nodes about 0.25 m apart), and the drive's looks fall on the lattice
path's nodes a metre apart. The choice itself is not the optimal adaptive search: it is one step of
policy improvement (a rollout) over the greedy mass-per-metre tour, so, under the model, it is never
worse than that tour and may be worse than the optimum; the rest of the plan is valued with the
approximations listed in :mod:`~seal_cli.sim.policies.completion` (the next thing's search planned
with its belief given what the first search saw, from the view nearest where the first was found;
the things after it with no credit for being seen on the way). It is the
reference of what search achieves with the priors, not a proven bound: a searcher without full
knowledge beating it by more than about two standard errors would point at one of those
approximations (``against_prior_optimal`` in the context suite's JSON).
"""

from __future__ import annotations

from collections.abc import Sequence

import numpy as np

from seal_cli.frames.model import Binding
from seal_cli.sim.agent import Agent, View
from seal_cli.sim.policies.base import Policy
from seal_cli.sim.policies.coverage import CoveragePolicy
from seal_cli.sim.policies.whole_plan import WholePlanSearch
from seal_cli.sim.world import Detection

__all__ = ["PriorOptimalPolicy"]

class PriorOptimalPolicy(Policy):
    """The view-model search for the whole plan under the priors, with the exact posterior (module docstring)."""

    name = "prior_optimal"

    def begin(self, agent: Agent) -> None:
        m = agent.scene.map
        self.map = m
        self.search = WholePlanSearch(agent)
        self.looks: list[tuple[np.ndarray, frozenset[str], frozenset[str]]] = []
        """Per look: the free cells seen, the places open then, the places looked into from within reach."""
        self.cleared: dict[str, np.ndarray] = {}
        self.parents: dict[str, np.ndarray] = {}
        self.openable = [p.name in agent.world.items and agent.world.items[p.name].openable for p in m.places]
        self.fallback = CoveragePolicy()
        self.fallback.begin(agent)

    def observe(self, agent: Agent, detections: Sequence[Detection]) -> None:
        self.fallback.observe(agent, detections)
        seen = self.search.observe(agent)
        pose = agent.world.robot.pose
        items = agent.world.items
        open_ = frozenset(p.name for p in self.map.places if p.name in items and items[p.name].is_open)
        at_hand = frozenset(name for name in open_ if agent.world.within_reach(name, pose))
        look = (seen, open_, at_hand)
        self.looks.append(look)
        for cls in self.cleared:
            self._clear(cls, look)

    def parent_of(self, cls: str) -> np.ndarray:
        """Per free cell, the place (an index into the map's places) a thing of ``cls`` there would be in or
        on — the nearest within reach that its prior names, by name or class — or -1."""
        if cls not in self.parents:
            m = self.map
            named = {k for k in m.prior(cls).masses if k != "_rest"}
            centres = m.free_centres
            parent = np.full(len(centres), -1, dtype=np.intp)
            best = np.full(len(centres), np.inf)
            for k, place in enumerate(m.places):
                if place.name in named or place.cls in named:
                    d = np.hypot(centres[:, 0] - place.at[0], centres[:, 1] - place.at[1])
                    closer = (d <= place.reach) & (d < best)
                    parent[closer], best[closer] = k, d[closer]
            self.parents[cls] = parent
        return self.parents[cls]

    def _clear(self, cls: str, look: tuple[np.ndarray, frozenset[str], frozenset[str]]) -> None:
        seen, open_, at_hand = look
        parent = self.parent_of(cls)
        cleared = self.cleared[cls]
        places = self.map.places
        owner = parent[seen]
        shut = np.array([k >= 0 and self.openable[k] and places[k].name not in open_ for k in owner], dtype=bool)
        cleared[seen[~shut]] = True
        for k, place in enumerate(places):
            if place.name in at_hand:
                cleared[parent == k] = True

    def weights(self, cls: str) -> np.ndarray:
        """The posterior of ``cls`` per free cell: the prior, with every cell where it would have been seen removed."""
        if cls not in self.cleared:
            self.cleared[cls] = np.zeros(len(self.map.free_centres), dtype=bool)
            for look in self.looks:
                self._clear(cls, look)
        return np.where(self.cleared[cls], 0.0, np.asarray(self.map.prior(cls).weights, dtype=float))

    def next_view(self, agent: Agent, binding: Binding, target: str) -> View | None:
        decision = self.search.choose(agent, binding, target, self.weights)
        if decision is not None:
            return decision.view
        view = self.fallback.next_view(agent, binding, target)
        return None if view is None else View(view.cell, view.look_at, view.open, f"{view.why} (the priors are spent)")
