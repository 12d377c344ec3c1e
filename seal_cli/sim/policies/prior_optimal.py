"""``prior_optimal``: the best any searcher can do with the map's priors — the reference SeFM is measured against.

It knows what SeFM knows before it starts (the places, the priors of every class, the plan) and
nothing more, and it updates the priors *exactly* with what it has seen: a cell the sensor has
seen (in range, in line of sight, not inside a shut receptacle) holds nothing it is looking for,
so the posterior is the prior with those cells removed. It looks where the exact dynamic
programme of :mod:`~seal_cli.sim.policies.completion` says — the adaptive region order that
minimises the expected drive to finish the whole remaining plan, with independent objects — and
solves it again after every look. When nothing of what it seeks is left in any region, it sweeps
the frontier (:class:`~seal_cli.sim.policies.coverage.CoveragePolicy`), so it is complete.

Where it is exact and where not is the model's business (:mod:`~seal_cli.sim.policies.completion`):
exact when a region's view sees all of it, things lie in regions, the detector does not miss, one
thing per class, at most :data:`~seal_cli.sim.policies.completion.MAX_REGIONS` regions with belief.
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
    """The exact region-level search for the whole plan under the priors (see the module docstring)."""

    name = "prior_optimal"

    def begin(self, agent: Agent) -> None:
        m = agent.scene.map
        self.map = m
        self.seen = np.zeros(len(m.free_centres), dtype=bool)
        self.search = WholePlanSearch(agent)
        self.hidden = {g.place: g.cells for g in self.search.regions if g.place is not None
                       and agent.known[g.place].openable}
        self.fallback = CoveragePolicy()
        self.fallback.begin(agent)

    def observe(self, agent: Agent, detections: Sequence[Detection]) -> None:
        self.fallback.observe(agent, detections)
        pose = agent.world.robot.pose
        centres = self.map.free_centres
        near = np.flatnonzero(np.hypot(centres[:, 0] - pose[0], centres[:, 1] - pose[1]) <= agent.world.sensor.range)
        if len(near):
            visible = np.asarray(agent.world.sensor.visible(pose, centres[near]), dtype=bool)
            shut = np.zeros(len(centres), dtype=bool)
            for place, cells in self.hidden.items():
                if not agent.world.items[place].is_open:
                    shut[cells] = True
            self.seen[near[visible & ~shut[near]]] = True

    def weights(self, cls: str) -> np.ndarray:
        """The prior of ``cls`` per free cell, with what has been seen removed."""
        return np.where(self.seen, 0.0, np.asarray(self.map.prior(cls).weights, dtype=float))

    def next_view(self, agent: Agent, binding: Binding, target: str) -> View | None:
        decision = self.search.choose(agent, binding, target, self.weights)
        if decision is not None:
            self.search.looked.add(decision.region.name)
            return decision.view
        view = self.fallback.next_view(agent, binding, target)
        return None if view is None else View(view.cell, view.look_at, view.open, f"{view.why} (the priors are spent)")
