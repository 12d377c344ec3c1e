"""``frame_dp``: the commanded frame's two stops searched for jointly by the exact dynamic programme over regions.

It knows what ``prior_optimal`` knows (the places, the priors, the plan) and updates the priors
exactly as it does (:class:`~seal_cli.sim.policies.prior_optimal.PriorOptimalPolicy`: the prior with
every point it would have seen removed). Where ``prior_optimal`` rolls out a greedy tour one step
ahead for the thing sought now and values the rest of the plan by approximations, this policy
chooses the region to look at next by the optimal adaptive search for the thing sought now *and*
the plan's next stop together (:mod:`~seal_cli.sim.policies.frame_dp`): every look may find either
unknown thing, and the order adapts to what was found. It chooses again after every look with the
exact posterior; when the model has nothing left (the thing sought lies in no region it may still
look at), it searches as ``prior_optimal`` does.

The regions are the whole-plan search's (:func:`~seal_cli.sim.policies.whole_plan.regions_of`: each
room from its best-seeing cell, shut places and places no room's view sees from their stand cells);
the metres between views are the lattice's; a region whose view the robot has looked from is not
looked at again by this model (what that look missed — behind furniture, out of range — is left to
the fallback). It is a reference, like ``prior_optimal``: which of the two searches shorter on a
suite says which approximation costs more there (docs/benchmarks.md, "This round (search18)").
"""

from __future__ import annotations

from collections.abc import Callable, Collection, Sequence

import numpy as np

from seal_cli.frames.model import Binding
from seal_cli.sim.agent import Agent, View
from seal_cli.sim.policies.frame_dp import Problem, solve
from seal_cli.sim.policies.prior_optimal import PriorOptimalPolicy
from seal_cli.sim.policies.whole_plan import Region
from seal_cli.sim.world import Detection

__all__ = ["FrameDPPolicy"]

MAX_REGIONS = 10
"""The most regions the programme weighs (those holding most of the two beliefs): its states grow as 2^regions."""


class FrameDPPolicy(PriorOptimalPolicy):
    """The exact joint search for the plan's first two stops over regions, with ``prior_optimal``'s posterior."""

    name = "frame_dp"

    def begin(self, agent: Agent) -> None:
        super().begin(agent)
        self.looked: set[str] = set()
        """Regions whose view the robot has looked from."""
        self.chosen: Region | None = None

    def observe(self, agent: Agent, detections: Sequence[Detection]) -> None:
        super().observe(agent, detections)
        if self.chosen is not None and agent.robot_cell() == self.chosen.view:
            self.looked.add(self.chosen.name)
            self.chosen = None

    def _belief(self, cls: str, regions: list[Region],
                weights: Callable[[str], np.ndarray] | None = None) -> np.ndarray:
        w = (weights or self.weights)(cls)
        total = float(w.sum())
        return np.array([float(w[g.cells].sum()) / total if total > 0 else 0.0 for g in regions])

    def _reach(self, cls: str, regions: list[Region], nodes: np.ndarray,
               weights: Callable[[str], np.ndarray] | None = None) -> np.ndarray:
        """Per region, the expected lattice metres from its view to the thing of ``cls`` if it is there."""
        w = (weights or self.weights)(cls)
        lattice = self.search.lattice
        out = np.zeros(len(regions))
        for k, g in enumerate(regions):
            mass = w[g.cells]
            if mass.sum() > 0:
                d = lattice.distance[nodes[k], self.search.belief_node[g.cells]]
                ok = np.isfinite(d)
                out[k] = float((mass[ok] * d[ok]).sum() / max(mass[ok].sum(), 1e-12))
        return out

    def next_view(self, agent: Agent, binding: Binding, target: str) -> View | None:
        view = self._dp_view(agent, binding, target)
        return view if view is not None else super().next_view(agent, binding, target)

    def problem_of(self, agent: Agent, binding: Binding, target: str,
                   weights: Callable[[str], np.ndarray] | None = None,
                   looked: Collection[str] | None = None) -> tuple[Problem, list[Region], str, str | None] | None:
        """The programme's problem from where the robot stands: the regions it weighs (at most
        :data:`MAX_REGIONS`, those holding most of the two beliefs), the first thing's class and the second
        stop's (None: none). ``weights``: the belief of a class per free cell (default: the exact posterior);
        ``looked``: the regions already looked at (default: those this run looked from). None: no region holds
        anything of either."""
        stops = self.search.targets(agent, binding, target)
        first = stops[0][0]
        second = stops[1] if len(stops) > 1 else None
        here = agent.robot_cell()
        done = self.looked if looked is None else looked
        regions = [g for g in self.search.regions if g.name not in done and g.view != here]
        p1 = self._belief(first, regions, weights)
        p2 = self._belief(second[0], regions, weights) if second is not None and second[1] is None else None
        keep = np.argsort(-(p1 + (p2 if p2 is not None else 0.0)), kind="stable")[:MAX_REGIONS]
        keep = keep[(p1[keep] > 0) | ((p2[keep] > 0) if p2 is not None else False)]
        if not len(keep):
            return None
        regions = [regions[k] for k in keep]
        lattice = self.search.lattice
        points = np.asarray([agent.grid.point(g.view) for g in regions] + [agent.grid.point(here)])
        nodes = lattice.node_of(points)
        distance = lattice.distance[np.ix_(nodes, nodes)]
        after = None
        if second is not None and second[1] is not None and second[2]:
            at = lattice.node_of(np.asarray([agent.grid.point(c) for c in second[2]]))
            after = lattice.distance[np.ix_(nodes[:-1], at)].min(axis=1)
        problem = Problem(distance, p1[keep], self._reach(first, regions, nodes, weights),
                          None if p2 is None else p2[keep],
                          None if p2 is None else self._reach(second[0], regions, nodes, weights) if second else None,
                          after)
        return problem, regions, first, None if second is None else second[0]

    def _dp_view(self, agent: Agent, binding: Binding, target: str) -> View | None:
        made = self.problem_of(agent, binding, target)
        if made is None:
            return None
        problem, regions, first, second_cls = made
        p1, p2 = problem.first, problem.second
        solution = solve(problem)
        if solution.region is None:
            return None
        g = regions[solution.region]
        self.chosen = g
        shares = f"{first} {p1[solution.region]:.2f}"
        if p2 is not None and second_cls is not None:
            shares += f" and {second_cls} {p2[solution.region]:.2f}"
        field_ = agent.distances()
        why = (f"{g.name}: {shares} there, {field_[g.view]:.1f} m "
               f"(expected {solution.expected_m:.1f} m to reach both, by the exact programme over regions)")
        opens = g.place if g.place is not None and self._shut(agent, g.place) else None
        return View(g.view, g.look_at, opens, why)

    @staticmethod
    def _shut(agent: Agent, place: str) -> bool:
        known = agent.known.get(place)
        return known is not None and known.openable and place not in agent.opened and \
            not agent.world.items[place].is_open
