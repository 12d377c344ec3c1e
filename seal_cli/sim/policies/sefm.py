"""Where the SeFM agent looks next: the search policy driven by the frame beliefs.

The :class:`~seal_cli.sim.agent.Agent` executes a plan and asks its policy for a :class:`View`
whenever what the current frame needs is not yet known. :class:`SeFMPolicy` answers from SeFM's
belief over where the frame can be executed (:class:`seal_cli.sefm.filter.SeFM`); the policies it
is measured against are registered beside it in :data:`seal_cli.sim.policies.POLICIES`.
"""

from __future__ import annotations

from collections.abc import Sequence
from typing import Any

import numpy as np

from seal_cli.frames.model import Binding, Fact
from seal_cli.planning.state import State
from seal_cli.sim.agent import Agent, View
from seal_cli.sim.navigation import Cell
from seal_cli.sim.policies.base import Policy
from seal_cli.sim.world import Detection

__all__ = ["SeFMPolicy"]


class SeFMPolicy(Policy):
    """The SeFM searcher: observe the best mode of the current frame's belief.

    The beliefs (:class:`seal_cli.sefm.filter.SeFM`) are over every frame of the plan and every object
    they name, built from the map's priors and updated with each look. To search for what the
    current frame needs, the robot takes the frame's modes, heaviest first, and goes where it
    can *observe* one: if the mode lies at a closed receptacle it has not looked into, it goes
    and opens it; otherwise it goes to the nearest pose (by path) from which the mode is in view.
    A view already taken is not taken again; when every mode has been looked at, it falls back
    to the nearest frontier (:class:`~seal_cli.sim.policies.coverage.CoveragePolicy`), so the search is
    complete. ``priors=False`` is the ``uniform`` ablation (:class:`~seal_cli.sim.policies.uniform.UniformPolicy`);
    :class:`~seal_cli.sim.policies.object_only.ObjectOnlyPolicy` looks at the object's belief instead of the frame's.
    """

    name = "sefm"
    use_frames = True

    def __init__(self, *, particles: int = 200, priors: bool = True, bandwidth: float = 0.5,
                 distance_scale: float = 1.0) -> None:
        self.particles = particles
        self.priors = priors
        self.bandwidth = bandwidth
        self.distance_scale = distance_scale
        """A view's utility is the belief mass it reveals / (metres to drive there + scale)."""
        self._clouds: list[dict[str, Any]] = []

    @classmethod
    def make(cls, *, particles: int = 200) -> Policy:
        return cls(particles=particles)

    @property
    def clouds(self) -> list[dict[str, Any]]:
        return self._clouds

    def begin(self, agent: Agent) -> None:
        from seal_cli.sim.policies.coverage import CoveragePolicy

        self.fallback = CoveragePolicy()
        self.fallback.begin(agent)
        self.history: list[tuple[tuple[float, float, float], tuple[Detection, ...]]] = []
        self.tried: set[tuple[Cell, str | None]] = set()
        self.sefm: Any = None
        self.planner: Any = None
        self.key: tuple[str, ...] = ()
        self.map = agent.scene.map
        if not self.priors:
            from dataclasses import replace

            self.map = replace(self.map, priors={})

    def _state(self, agent: Agent) -> State:
        """The robot's state for SeFM: its hand, and which receptacles *by name* it knows are open."""
        held = agent.held()
        facts = {Fact("holding", (held.key,))} if held else {Fact("hand_empty")}
        facts |= {Fact("open", (i.id,)) for i in agent.world.items.values()
                  if i.openable and i.is_open and i.id in agent.known}
        facts |= {f for f in agent.state.facts if f.predicate not in ("holding", "hand_empty", "open")}
        return State.of(facts, agent.library.taxonomy, closable={i.id for i in agent.world.items.values()
                                                                 if i.openable}, classes=agent.classes)

    def _beliefs(self, agent: Agent) -> Any:
        """SeFM over the current plan (rebuilt, and the looks replayed, when the plan changes)."""
        from seal_cli.sefm.filter import SeFM, SeFMConfig

        bindings = [b.frame.bind({r: agent.class_of(v) for r, v in b.values}) for b in agent.steps]
        key = tuple(str(b) for b in bindings)
        if self.sefm is None or key != self.key:
            state = self._state(agent)
            self.sefm = SeFM(self.map, bindings, state, agent.rng,
                             SeFMConfig(particles=self.particles, bandwidth=self.bandwidth))
            self.key = key
            for pose, seen in self.history:
                self.sefm.update(pose, seen, state)
        return self.sefm

    def observe(self, agent: Agent, detections: Sequence[Detection]) -> None:
        self.fallback.observe(agent, detections)
        if self.planner is not None:
            self.planner.observe(agent)
        pose = agent.world.robot.pose
        self.history.append((pose, tuple(detections)))
        if self.sefm is None and self.keep_clouds and agent.steps:
            self._beliefs(agent)
        elif self.sefm is not None:
            self.sefm.update(pose, detections, self._state(agent))
            if self.keep_clouds:
                self.snapshot(agent)

    def snapshot(self, agent: Agent) -> None:
        """The clouds now: the frame at hand, the commanded frame it serves, and every object believed in."""
        sefm = self.sefm
        objects = {c: sefm.object_particles(c) for c in sefm.object_classes}
        from seal_cli.sefm.filter import frame_id

        index = min(agent.index, len(sefm.bindings) - 1)
        commanded = self.commanded_index(agent)
        self._clouds.append({
            "step": agent.world.step,
            "frame": frame_id(sefm.bindings[index]) if sefm.bindings else "",
            "frame_particles": sefm.frame_particles(index) if sefm.bindings else None,
            "commanded": frame_id(sefm.bindings[commanded]) if commanded is not None else "",
            "commanded_particles": sefm.frame_particles(commanded) if commanded is not None else None,
            "objects": objects})

    def commanded_index(self, agent: Agent) -> int | None:
        """The plan step of the commanded frame the step at hand serves (itself, if it is commanded)."""
        if not self.sefm.bindings:
            return None
        for j in range(min(agent.index, len(self.sefm.bindings) - 1), len(agent.steps)):
            if agent.todo and agent.steps[j] == agent.todo[0] and j < len(self.sefm.bindings):
                return j
        return len(self.sefm.bindings) - 1

    def cloud(self, agent: Agent, target: str) -> tuple[np.ndarray, np.ndarray, list[Any]]:
        """Where the thing sought is believed to be, as a weight per free cell of the map, and the
        belief's modes. SeFM: the current frame's target density (measurement × context, the density
        its particles track, evaluated without their sampling noise); object-only: the object's
        particles smoothed by the same kernel."""
        sefm = self._beliefs(agent)
        sefm.update(agent.world.robot.pose, (), self._state(agent))
        points = self.map.free_centres
        if self.use_frames:
            i = self.frame_index(agent)
            density = sefm.frame_density(i, points)
            modes = list(sefm.frame_summary(i).modes)
        else:
            density = sefm.object_density(agent.class_of(target), points)
            modes = list(sefm.object_summary(agent.class_of(target)).modes)
        density = np.where(np.isfinite(density) & (density > 0), density, 0.0)
        total = density.sum()
        return points, (density / total if total > 0 else np.full(len(points), 1.0 / len(points))), modes

    serve_commanded = False
    """Search by the belief of the commanded frame the current step serves (Stir(cup) while picking
    the spoon for it: spoons near cups are worth more), rather than the step's own. Off: on
    ALFRED-2D it drew the robot to the static goal (a desk, a microwave) first, and searched longer
    (docs/benchmarks.md)."""

    def frame_index(self, agent: Agent) -> int:
        """The plan step whose belief guides the search: the current one, or the commanded frame it
        is a precondition of (the next commanded frame in the plan)."""
        if self.serve_commanded and agent.todo:
            for j in range(agent.index, len(agent.steps)):
                if agent.steps[j] == agent.todo[0]:
                    return j
        return agent.index

    def next_view(self, agent: Agent, binding: Binding, target: str) -> View | None:
        """With frames, the view that starts the shortest expected completion of the whole remaining
        plan (:meth:`plan_view`); where that has nothing to say, and for object-only, :meth:`greedy_view`."""
        if self.use_frames and self.whole_plan:
            decision = self.plan_view(agent, binding, target)
            if decision is not None:
                self.tried.add((decision.view.cell, decision.view.open))
                return decision.view
        return self.greedy_view(agent, binding, target)

    whole_plan = True
    """Search for the whole remaining plan (off: the step's own belief, the search of earlier rounds)."""
    min_rooms = 2
    """The whole-plan search runs on maps of this many rooms or more; on fewer (ALFRED's single open rooms,
    seen 1.5 m at a time) the greedy view rule is kept: the region model of earlier rounds was longer
    there, and the view model that replaced it has not been measured there (docs/benchmarks.md)."""

    places_in_one_room = False
    """On a map of one room, search for the whole plan over its places (each a region seen from its stand
    cell), with no region for the room itself. Off: on ALFRED-2D it was longer than the greedy rule (3.52
    against 3.14 m on 21 valid_seen episodes), since a look there sees several places at once and the
    model counts only the one it stands at (docs/benchmarks.md)."""

    def plan_view(self, agent: Agent, binding: Binding, target: str) -> Any:
        """The view to look from for the whole remaining plan (:class:`~seal_cli.sim.policies.whole_plan.
        WholePlanSearch`, the view model of :mod:`~seal_cli.sim.policies.completion`) under SeFM's beliefs
        of the things still unknown — the commanded frames' unknown elements, each SeFM's object belief
        after every look so far (its detector may miss, so a place looked at keeps some), as a mass per
        free cell."""
        from seal_cli.sim.policies.whole_plan import WholePlanSearch

        single = len(self.map.rooms) < self.min_rooms
        if single and not self.places_in_one_room:
            return None
        if self.planner is None:
            self.planner = WholePlanSearch(agent, places_only=single)
            for pose, _ in self.history:
                self.planner.see(agent, pose)
        sefm = self._beliefs(agent)
        sefm.update(agent.world.robot.pose, (), self._state(agent))
        points = self.map.free_centres

        def weights(cls: str) -> np.ndarray:
            if cls in sefm.object_classes:
                w = np.asarray(sefm.object_density(cls, points), dtype=float)
            else:
                w = np.asarray(self.map.prior(cls).weights, dtype=float)
            return np.where(np.isfinite(w) & (w > 0), w, 0.0)

        return self.planner.choose(agent, binding, target, weights)

    def greedy_view(self, agent: Agent, binding: Binding, target: str) -> View | None:
        """The view that reveals the most belief per metre: opening a shut receptacle reveals the
        mass at it; standing on a mode reveals the mass the beliefs' sensor would see there and no
        shut receptacle hides."""
        field_ = agent.distances()
        X, W, modes = self.cloud(agent, target)
        W = W.copy()
        for k in agent.instances(agent.class_of(target)):
            if agent.spent(k.id, target):  # the belief is right there, but that one will not do
                W[np.hypot(X[:, 0] - k.at[0], X[:, 1] - k.at[1]) <= agent.world.reach] = 0.0
        hidden = np.zeros(len(X), dtype=bool)
        for x, y, r in self.sefm.hidden_places():
            hidden |= np.hypot(X[:, 0] - x, X[:, 1] - y) <= r
        seeing = self.map.sensor.range
        options: list[tuple[float, float, View]] = []
        for place in agent.known.values():  # every place is somewhere to look: what is in or on it
            if place.movable or place.id in agent.inspected:
                continue
            where = self.map.place(place.id)
            reach = where.reach if where is not None else agent.world.reach
            near = np.hypot(X[:, 0] - place.at[0], X[:, 1] - place.at[1]) <= reach + 0.25
            cell = agent.stand_cell(place, field_)
            if cell is None:
                continue
            shut = place.openable and place.id not in agent.opened and not agent.world.items[place.id].is_open
            mass = float(W[near].sum() if shut else W[near & ~hidden].sum())
            why = f"opens {place.id}, where the belief is" if shut else f"looks at {place.id}, where the belief is"
            options.append((mass, float(field_[cell]), View(cell, place.at, open=place.id if shut else None,
                                                             why=why)))
        for mode in modes if self.modes_too or not options else ():  # the belief's modes, wherever they are
            view = self._view_of(agent, mode.mean, field_)
            if view is not None:
                at = agent.grid.point(view.cell)
                mass = float(W[(np.hypot(X[:, 0] - at[0], X[:, 1] - at[1]) <= seeing) & ~hidden].sum())
                options.append((mass, float(field_[view.cell]), view))
        fresh = [o for o in options if (o[2].cell, o[2].open) not in self.tried and o[0] > self.min_mass]
        if fresh:
            view = max(fresh, key=lambda o: o[0] / (o[1] + self.distance_scale))[2]
        else:
            fallback = self.fallback.next_view(agent, binding, target)
            if fallback is None:
                return None
            view = View(fallback.cell, fallback.look_at, fallback.open, f"{fallback.why} (the belief is spent)")
        self.tried.add((view.cell, view.open))
        return view

    min_mass = 1e-3
    """A view that would reveal less belief than this is not worth the drive."""
    modes_too = False
    """Also consider standing on the belief's modes when the map has places (without places, always)."""

    def _view_of(self, agent: Agent, point: tuple[float, float], field_: np.ndarray) -> View | None:
        """Where to stand to observe a point of the belief: the particles are poses from which the
        robot could act on the thing, so it stands on it (or as near as it can drive)."""
        pts = agent.grid.free_points
        cells = agent.grid.free_cells
        gap = np.hypot(pts[:, 0] - point[0], pts[:, 1] - point[1])
        costs = field_[cells[:, 0], cells[:, 1]]
        for radius in (agent.grid.resolution * 1.5, agent.world.reach / 2):
            near = np.flatnonzero((gap <= radius) & np.isfinite(costs))
            if len(near):
                k = int(near[np.argmin(costs[near])])
                return View((int(cells[k, 0]), int(cells[k, 1])), point, why="goes to the belief's best mode")
        return None
