"""Where the SeFM agent looks next: the search policy driven by the frame beliefs.

The :class:`~seal_cli.sim.agent.Agent` executes a plan and asks its policy for a :class:`View`
whenever what the current frame needs is not yet known. :class:`SeFMPolicy` answers from SeFM's
belief over where the frame can be executed (:class:`seal_cli.sefm.filter.SeFM`); the policies it
is measured against are registered beside it in :data:`seal_cli.sim.policies.POLICIES`.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass, replace
from typing import Any

import numpy as np

from seal_cli.frames.model import Binding, Fact
from seal_cli.frames.taxonomy import class_key
from seal_cli.maps.model import Map, Person
from seal_cli.maps.navigation import Cell
from seal_cli.planning.state import State
from seal_cli.sim.agent import Agent, Known, View
from seal_cli.sim.policies.base import Policy
from seal_cli.sim.world import PERSON, Detection

__all__ = ["THINNED", "Look", "SeFMPolicy"]

THINNED = 0.25 - 1e-9
"""Grids at least this coarse are where the oracle's tour over stand cells is exact (not thinned)."""


@dataclass(frozen=True, eq=False)
class Look:
    """A look the search may take: the belief it would reveal, the metres to drive there, the view,
    and what it reveals of each place (None: a look that no place's share describes, a belief mode)."""

    mass: float
    metres: float
    view: View
    reveals: np.ndarray | None = None


@dataclass
class _TourModel:
    """One thing searched for through a few looks (:meth:`SeFMPolicy._first_of_tour`): ``here`` the metres
    from the robot to each look, ``between`` from look to look, ``R[k, c]`` the belief look k reveals of
    column c (a place, or a look's own mass), ``on[k]`` the (weighted) drive on from look k to the plan's next
    stop; ``scale`` what a look costs beside its drive."""

    here: np.ndarray
    between: np.ndarray
    R: np.ndarray
    on: np.ndarray
    scale: float
    way: dict[tuple[int, int], list[tuple[float, np.ndarray, float | np.ndarray]]] | None = None
    """Per drive (from look a, or -1 the robot, to look b), the looks the robot takes on the way: metres
    from a, which columns that look reveals (a place within reach and open), and the drive on from there."""
    mass: np.ndarray | None = None
    """Per column, the belief a look on the way reveals of it (with :attr:`way`)."""
    acted: np.ndarray | None = None
    """Per look and column, the (weighted) metres from look k to finish the plan's next stop when the thing is
    found in that column: to where it is acted on and on from there (:meth:`SeFMPolicy._acted`); None: ``on[k]``
    for every column (the drive on counted from the look). A look on the way carries its own row in :attr:`way`."""

    def _legs(self, prev: int, k: int) -> list[tuple[float, np.ndarray, float | np.ndarray]]:
        return self.way.get((prev, k), []) if self.way is not None else []

    @staticmethod
    def _after(found: np.ndarray, on: float | np.ndarray, gain: float) -> float:
        """The drive on paid for the belief ``found`` (per column) a look reveals first, of which ``gain`` is still
        unfound: ``on`` per column (or one figure for all), weighted by where in ``found`` the thing would be."""
        if np.ndim(on) == 0:
            return gain * float(on)
        total = float(found.sum())
        return gain * float(found @ on) / total if total > 0 else 0.0

    def cost(self, order: Sequence[int]) -> float:
        """E = Σ_k (d(v_k-1, v_k) + scale) · (1 − Σ_j<k p_j) + Σ_k p_k · on_k."""
        R = self.R
        seen = np.zeros(R.shape[1], dtype=bool)
        left, total, prev = 1.0, 0.0, -1
        for k in order:
            d = self.here[k] if prev < 0 else self.between[prev, k]
            done = 0.0
            for at, cols, on in self._legs(prev, k):   # a look on the way, and the drive stops when it finds it
                total += (at - done) * left
                done = at
                first = np.where(cols & ~seen, self.mass, 0.0) if self.mass is not None else np.zeros(len(cols))
                gain = min(float(first.sum()), left)
                seen |= cols
                total += self._after(first, on, gain)
                left = max(0.0, left - gain)
            total += (d - done + self.scale) * left
            new = np.where(seen, 0.0, R[k])
            found = float(new.sum())
            gain = min(found, left)
            seen |= R[k] > 0
            total += self._after(new, self.on[k] if self.acted is None else self.acted[k], gain)
            left = max(0.0, left - gain)
            prev = k
        return round(total, 6)   # equal to rounding: the same order for SeFM and object-only

    def outcomes(self, order: Sequence[int]) -> tuple[np.ndarray, np.ndarray]:
        """Where the thing may be under the model, and the metres the order costs if it is there: per column,
        its mass as first revealed and the drives to the look that reveals it plus the drive on from there;
        last, the belief no look reveals, which costs the whole tour. The masses' mean of the costs is
        :meth:`cost` (but where the looks reveal more than the whole belief)."""
        R = self.R
        mass = np.zeros(R.shape[1] + 1)
        metres = np.zeros(R.shape[1] + 1)
        seen = np.zeros(R.shape[1], dtype=bool)
        driven, prev = 0.0, -1
        for k in order:
            for at, cols, on in self._legs(prev, k):
                new = cols & ~seen
                if self.mass is not None:
                    mass[:-1][new] = self.mass[new]
                metres[:-1][new] = driven + at + (np.asarray(on)[new] if np.ndim(on) else on)
                seen |= cols
            driven += (self.here[k] if prev < 0 else self.between[prev, k]) + self.scale
            new = (R[k] > 0) & ~seen
            mass[:-1][new] = R[k][new]
            metres[:-1][new] = driven + (self.on[k] if self.acted is None else self.acted[k][new])
            seen |= R[k] > 0
            prev = k
        mass[-1] = max(0.0, 1.0 - float(mass[:-1].sum()))
        metres[-1] = driven
        return mass, metres

    def best(self, first: int | None = None) -> tuple[list[int], float]:
        """The order of least :meth:`cost`: built greedily from where the robot is (the most new belief per
        metre), then improved by moving one look at a time to wherever E falls most (or-opt); with ``first``,
        the best that starts with that look."""
        n, R = len(self.here), self.R
        order: list[int] = [first] if first is not None else []
        todo = set(range(n)) - set(order)
        revealed = R[first] > 0 if first is not None else np.zeros(R.shape[1], dtype=bool)
        while todo:   # greedy from where the robot is: the most new belief per metre
            prev = order[-1] if order else -1

            def ratio(k: int, prev: int = prev, revealed: np.ndarray = revealed) -> float:
                gain = float(R[k][~revealed].sum())
                return gain / ((self.here[k] if prev < 0 else self.between[prev, k]) + self.scale)

            k = max(sorted(todo), key=ratio)
            order.append(k)
            todo.remove(k)
            revealed = revealed | (R[k] > 0)
        current = self.cost(order)
        fixed = 0 if first is None else 1
        for _ in range(4 * n):   # or-opt: move one look elsewhere while that shortens the expected search
            moves = [(self.cost(o), o) for i in range(fixed, n) for j in range(fixed, n) if i != j
                     for o in [order[:i] + order[i + 1:]] for o in [o[:j] + [order[i]] + o[j:]]]
            if not moves:
                break
            value, candidate = min(moves, key=lambda m: m[0])
            if value >= current - 1e-9:
                break
            current, order = value, candidate
        return order, current


def people_now(the_map: Map, agent: Agent) -> tuple[Person, ...]:
    """The map's people where the robot knows they stand now: one it led ("guide Anna to the kitchen") stands where
    it left them, not where the map put them, so a later frame about them ("then bring her the milk") is believed
    where they are."""
    people = []
    for person in the_map.people:
        known = agent.known.get(person.key)
        moved = known is not None and math.dist(known.at, the_map.person_at(person)) > MOVED_M
        people.append(replace(person, at=(known.at[0], known.at[1]), room=None) if moved and known is not None
                      else person)
    return tuple(people)


MOVED_M = 0.05
"""How far from where the map stands a person the robot must know them to stand to count them moved (a cell)."""


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
    keeps_particles = True

    def __init__(self, *, particles: int = 200, priors: bool = True, bandwidth: float = 0.5,
                 distance_scale: float = 0.1) -> None:
        self.particles = particles
        self.priors = priors
        self.bandwidth = bandwidth
        self.distance_scale = distance_scale
        """A view's utility is the belief mass it reveals / (metres to drive there + scale): what a look
        costs beside its drive (0.1 m, chosen on ALFRED-2D's train split: docs/benchmarks.md; a look costs no
        metres, and once a look opens every shut place within reach, 0.5 m overcharged the cells beside
        several of them)."""
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
        self._stands: dict[str, list[Cell]] = {}
        self._reach_ids: tuple[str, ...] = ()
        self._rows: dict[Cell, np.ndarray] = {}
        from seal_cli.sim.policies.oracle import OraclePolicy

        self._tours = OraclePolicy()
        self._tours.begin(agent)
        self._stood: dict[str, tuple[float, float]] = {}
        self._onward: dict[tuple[tuple[str, tuple[float, float]], ...], np.ndarray] = {}
        self._floor_sight: dict[Cell, np.ndarray] = {}
        self._prior_shares: dict[str, np.ndarray] = {}
        self.sefm: Any = None
        self.planner: Any = None
        self._news = False
        """A look since the last choice saw a thing it had not seen (what may make another view better)."""
        self._blind: str | None = None
        """The thing whose last look was chosen with the plan's next stop unseen (:meth:`_reconsider_in_room`)."""
        self._things: set[str] = set()
        self.departures: list[dict[str, Any]] = []
        self._ways: dict[tuple[Cell, Cell], list[tuple[float, Cell]]] = {}
        self._reach_cache: dict[tuple[Cell, str], bool] = {}
        self._places_at: dict[str, list[np.ndarray]] = {}
        self._acted_then: np.ndarray | None = None
        self._acted_cache: dict[str, list[np.ndarray]] = {}
        """Each choice in one room where SeFM's best first look was not object-only's: the gap, both orders'
        outcomes (:meth:`_TourModel.outcomes`) and whether SeFM departed (read by tracing scripts)."""
        self._chosen: tuple[Cell, str, Any] | None = None
        """A choice made on the drive (:meth:`reconsider`) that stopped it: where, for what, the decision."""
        self.key: tuple[str, ...] = ()
        self.map = agent.scene.map
        from seal_cli.sefm.object_beliefs import ObjectModel, Views

        model = ObjectModel.for_map(self.map, **self._detector(agent))
        fov = self.map.sensor.fov_deg
        self._views = Views(model.view_step, None if fov >= 360 else min(model.view_turn, math.radians(fov)))
        """The views whose misses :attr:`looked` counts (the object filter's rule: once per view)."""
        self.looked = np.zeros(len(self.map.free_centres), dtype=np.int64)
        """Per free cell of the map, the new views that saw it (in range and line of sight, not in a shut place):
        the misses of :meth:`cell_belief`."""
        self.p_detect = min(model.p_detect, model.max_p_detect)
        if not self.priors:
            from dataclasses import replace

            self.map = replace(self.map, priors={})

    world_detector = False
    """On: the object filter's detection probability is the simulated world's (:attr:`~seal_cli.sim.world.World.
    p_detect`: its detector never misses; the filter caps it at ``ObjectModel.max_p_detect``, 0.99), not the map's
    ``sensor.p_detect`` (0.9 on the shipped maps), which describes a real robot's detector. Off (kept, search23):
    measured on two held-out houses it took the gallery from 33.35 to 30.63 m (1.011 × prior_optimal) but put the
    farmhouse back above object-only (24.29 against 23.29: the 2 % draw of docs/sefm.md's trace, lost again), and
    the other seven houses were not measured (docs/sefm.md, "The detector the filter assumes")."""

    def _detector(self, agent: Agent) -> dict[str, float]:
        """The overrides of the object filter's model for the world it searches (:attr:`world_detector`)."""
        return {"p_detect": float(agent.world.p_detect)} if self.world_detector else {}

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
        from seal_cli.sefm.object_beliefs import ObjectModel

        bindings = [b.frame.bind({r: v if agent.is_person(v) else agent.class_of(v) for r, v in b.values})
                    for b in agent.steps]     # a person of the map is where they stand, not any person
        people = people_now(self.map, agent)
        unmeant = _not_meant(agent)
        key = (*(str(b) for b in bindings), *(f"{k}: {v}" for k, v in agent.told.items()),   # the word, withdrawn
               *(f"{p.key} at {p.at}" for p in people if p not in self.map.people),        # one led: moved
               *(f"not {i}" for i in sorted(unmeant)))
        if self.sefm is None or key != self.key:
            state = self._state(agent)
            the_map = self.map if people == self.map.people else replace(self.map, people=people)
            objects = ObjectModel.for_map(self.map, **self._detector(agent))
            self.sefm = SeFM(the_map, bindings, state, agent.rng,
                             SeFMConfig(particles=self.particles, bandwidth=self.bandwidth, objects=objects),
                             said=agent.told)
            self.key = key
            for pose, seen in self.history:
                self.sefm.update(pose, [d for d in seen if d.id not in unmeant], state)
        return self.sefm

    def observe(self, agent: Agent, detections: Sequence[Detection]) -> None:
        self.fallback.observe(agent, detections)
        fresh = {d.id for d in detections if agent.world.items[d.id].movable} - self._things
        if fresh:
            self._things |= fresh
            self._news = True
        if self.planner is not None:
            looked_from = self.planner.pending
            self.planner.observe(agent, see=False)
            if looked_from is not None and self.planner.pending is None:    # the look it chose, taken
                self._spent_views(agent)
        pose = agent.world.robot.pose
        self.history.append((pose, tuple(detections)))
        self._count_view(agent, pose)
        if self.sefm is None and self.keep_clouds and agent.steps:
            self._beliefs(agent)
        elif self.sefm is not None:
            unmeant = _not_meant(agent)
            self.sefm.update(pose, [d for d in detections if d.id not in unmeant], self._state(agent))
            if self.keep_clouds:
                self.snapshot(agent)

    def _count_view(self, agent: Agent, pose: tuple[float, float, float]) -> None:
        """A look from ``pose``: if it is a new view (the object filter's rule, with the places shut as they are now),
        every free cell it sees — by the sensor's exact rule, not within reach of a shut place — has one more miss."""
        items = agent.world.items
        hidden = [(p.at[0], p.at[1], p.reach) for p in self.map.places
                  if p.name in items and items[p.name].openable and not items[p.name].is_open]
        if not self._views.first_look(pose, hidden):
            return
        from seal_cli.sim.policies.whole_plan import cells_in_sight

        centres = self.map.free_centres
        near = cells_in_sight(agent, pose)
        for x, y, r in hidden:
            near = near[np.hypot(centres[near, 0] - x, centres[near, 1] - y) > r]
        self.looked[near] += 1

    cell_beliefs = True
    """The whole-plan search weighs a thing not yet seen by :meth:`cell_belief` — SeFM's object belief computed on the
    map's free cells — rather than by the object filter's particles (off: the particles' kernel density, before
    search22; see :meth:`cell_belief`)."""

    def cell_belief(self, cls: str, said: Sequence[str] = ()) -> np.ndarray:
        """The belief of a thing of ``cls`` no look has seen, per free cell of the map: its prior (the one the object
        filter draws its particles from, floor included, conditioned on where the command ``said`` it is) times
        ``1 − p`` for every new view that saw the cell (the filter's observation model, negative information once
        per view). This is the object filter's posterior, computed exactly on the cells the search weighs, without
        the filter's two approximations that matter for where to look next: a few hundred particles carry the
        prior's floor (2 % spread over the whole house) in next to no particles, so once the named rooms are looked
        at the particles' belief stays in them; and the share redrawn from the prior at each resampling (the chance
        the thing was moved unseen) puts belief back where the robot has just looked. On the held-out gallery a mug
        on such a floor kept SeFM going round the rooms the prior names for 90 m (docs/benchmarks.md, "This round
        (search22)"). The simulated world is still while the robot searches it."""
        prior = np.asarray(self.map.prior(cls, said).weights, dtype=float)
        return prior * (1.0 - self.p_detect) ** self.looked

    def _spent_views(self, agent: Agent) -> None:
        """Once the robot has taken the look the whole-plan search chose, the views within ``view_step`` of where it
        stands (all round: the heading does not matter, a narrow sensor turns round at a view) are not chosen: SeFM
        would not count a look from there as new (negative information counts once per view), so its belief does not
        fall there and the model would expect to find there what is left of the belief where it has just looked —
        the robot edged a few centimetres at a time, looking again, after a place the command named turned out
        empty. A view that opens a shut place stays; the looks on the drive are left as before (measured: excluding
        the views near them too changed three of 36 runs of the context suite, two longer by 1.5 m)."""
        from seal_cli.sefm.object_beliefs import ObjectModel

        x, y = agent.world.robot.pose[:2]
        step = ObjectModel.view_step
        for c in self.planner.candidates:
            if c.open is None and c.cell not in self.planner.used:
                px, py = agent.grid.point(c.cell)
                if math.hypot(px - x, py - y) <= step:
                    self.planner.used.add(c.cell)

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

    stand_ahead = 2
    """How many known stops after the one at hand the choice of a stand cell looks ahead to (:meth:`stand`)."""

    def stand(self, agent: Agent, known: Known) -> Cell | None:
        """The cell to act on ``known`` from that makes the drive on through the next known stops of the
        plan shortest (the sink to clean the apple at, the table to put it on: exactly, by the oracle's
        dynamic programme over stand cells, :meth:`~seal_cli.sim.policies.oracle.OraclePolicy.tour`); the
        nearest cell when the next stop is not known yet — what is unknown is never a reason to stand
        elsewhere — and on a grid finer than :data:`THINNED`, where the tour's stand cells are thinned to
        one per 0.25 m and lose more than looking ahead saves (the apartment's 5 cm grid: 0.1–0.2 m a
        command on the map suite) — and in houses (maps of :attr:`min_rooms` rooms or more), as before."""
        stops = [known, *self._ahead(agent, known.cls, known.at, known.id)]
        if len(stops) == 1 or agent.grid.resolution < THINNED or len(self.map.rooms) >= self.min_rooms:
            return agent.stand_cell(known)
        for stop in stops:   # a thing moved since (put down, carried) has other stand cells now
            if self._stood.setdefault(stop.id, stop.at) != stop.at:
                self._stood[stop.id] = stop.at
                self._tours._cells.pop(stop.id, None)
                self._tours._pairs = {k: v for k, v in self._tours._pairs.items() if stop.id not in k}
        metres, cell = self._tours.tour(agent, stops)
        return cell if np.isfinite(metres) and cell is not None else agent.stand_cell(known)

    def _ahead(self, agent: Agent, cls: str, at: tuple[float, float], skip: str | None = None) -> list[Known]:
        """The known stops of the plan after the one for ``cls`` (at most :attr:`stand_ahead`), each the
        instance nearest the stop before it; up to the first stop of which no instance is known."""
        from seal_cli.sim.policies.oracle import navigation_targets

        held = agent.held()
        targets = [agent.class_of(t) for t in navigation_targets(agent)]
        while targets and targets[0] == cls:
            targets.pop(0)
        stops: list[Known] = []
        for name in targets[: self.stand_ahead]:
            if held is not None and held.key == name:
                continue
            pool = [k for k in agent.instances(name) if k.id != skip and k.id not in agent.unreachable
                    and not agent.world.held_chain(k.id) and not agent.spent(k.id, name)]
            if not pool:
                break
            last = stops[-1].at if stops else at
            stops.append(min(pool, key=lambda k: (k.at[0] - last[0]) ** 2 + (k.at[1] - last[1]) ** 2))
        return stops

    def next_view(self, agent: Agent, binding: Binding, target: str) -> View | None:
        """With frames, the view that starts the shortest expected completion of the whole remaining
        plan (:meth:`plan_view`); where that has nothing to say, and for object-only, :meth:`greedy_view`."""
        if self.use_frames and self.whole_plan and (why := self.refuted(agent, target)) is not None:
            fallback = self.fallback.next_view(agent, binding, target)   # the sweep: complete, assumes nothing
            if fallback is not None:
                self._chosen = None
                self.tried.add((fallback.cell, fallback.open))
                return View(fallback.cell, fallback.look_at, fallback.open, f"{fallback.why} ({why})")
        if self.use_frames and self.whole_plan:
            chosen, self._chosen = self._chosen, None
            if chosen is not None and chosen[:2] == (agent.robot_cell(), target):   # on the drive, nothing seen since
                decision = chosen[2]
                self.planner.pending = decision.candidate.cell
            else:
                decision = self.plan_view(agent, binding, target)
            self._news = False
            if decision is not None:
                self.tried.add((decision.view.cell, decision.view.open))
                return decision.view
        return self.greedy_view(agent, binding, target)

    refute_below = 1e-3
    """The probability, under SeFM's belief of the thing sought, of all its looks so far having missed it, below
    which the whole-plan search hands the search for it to the frontier sweep (:meth:`refuted`). Set before
    measuring, not tuned: a calibrated belief is this unlucky once in a thousand searches."""

    def refuted(self, agent: Agent, target: str) -> str | None:
        """Why SeFM's belief of the thing sought is refuted by its own looks (None: it is not): the probability
        under that belief of every look since the thing's class was last seen having missed it
        (:attr:`~seal_cli.sefm.object_beliefs.ObjectBeliefs.missed`, the filter's evidence) is below
        :attr:`refute_below`. The belief then says where the thing is not, wrongly — it lies where the looks
        were taken to see and did not (a sliver behind a bed's corner the sensor's fan of rays counts as seen), or
        where the prior says next to nothing — and choosing views by it went round the same rooms for 200 m on
        the held-out ranch (docs/benchmarks.md, "This round (search20)"); the sweep looks at every square not yet
        seen, nearest first, and assumes nothing. Only on maps of :attr:`min_rooms` rooms or more, where the
        whole-plan search runs."""
        if self.sefm is None or len(self.map.rooms) < self.min_rooms:
            return None
        missed = self.sefm.objects.missed
        cls = agent.class_of(target)
        if missed is None or cls not in self.sefm.object_classes:
            return None
        p = float(np.exp(missed[self.sefm.objects.row(cls)]))
        if p >= self.refute_below:
            return None
        return f"the belief of {cls} is refuted: its looks all missed it, a chance of {p:.1e} by it"

    rethink_m = 1.0
    """Metres of expected drive to finish the plan by which another view must beat the one driven to, after a
    look on the way saw a thing not seen before, for the drive to stop and look from there instead
    (:meth:`reconsider`; the rollout's lattice paths differ from the robot's by a fraction of a metre)."""

    def reconsider(self, agent: Agent, binding: Binding, target: str, view: View) -> str | None:
        """The whole-plan search's drive stops when a look on the way saw something new (a thing of the plan:
        the cup while looking for the spoon) and, with it, another view finishes the plan more than
        :attr:`rethink_m` sooner than driving on to ``view``; the new choice is the next view."""
        if len(self.map.rooms) < self.min_rooms:
            return self._reconsider_in_room(agent, target, view)
        if self.planner is None or not self._news or not (self.use_frames and self.whole_plan):
            return None
        self._news = False
        pending = self.planner.pending
        on_way = self.planner.ahead(agent, view) if self.on_the_way else []
        decision = self.plan_view(agent, binding, target)
        self.planner.pending = pending
        if decision is None or decision.view.cell == view.cell:
            return None
        lost = decision.regret(view)
        if on_way:
            from seal_cli.sim.policies.whole_plan import Decision

            def cost(cell: Cell) -> float:
                return float(decision.costs.get((cell, None), np.inf))

            stop = min(on_way, key=cost)
            keep = min(cost(stop), decision.expected_m + lost)   # driving on: to the view, or a look on the way
            if decision.view.cell not in on_way and keep - decision.expected_m > self.rethink_m:
                lost = keep - decision.expected_m
            elif decision.expected_m + lost - cost(stop) > self.rethink_m:   # stop on the way and choose again there
                candidate = next(c for c in self.planner.candidates if c.cell == stop and c.open is None)
                gain = decision.expected_m + lost - cost(stop)
                why = (f"{candidate.name}: a look on the way, then choose again ({cost(stop):.1f} m expected to"
                       f" finish, {gain:.1f} m less than driving on)")
                decision = Decision(View(stop, agent.grid.point(stop), None, why), candidate, cost(stop),
                                    decision.costs)
                self._chosen = (agent.robot_cell(), target, decision)
                return f"what it saw makes a look on the way better ({gain:.1f} m less than driving on)"
            else:
                return None
        if lost <= self.rethink_m:
            return None
        self._chosen = (agent.robot_cell(), target, decision)
        return (f"what it saw makes {decision.candidate.name} better ({decision.expected_m:.1f} m expected to finish,"
                f" {lost:.1f} m less than driving on)" if np.isfinite(lost) else
                f"what it saw leaves nothing to see from there ({decision.candidate.name} now)")

    on_the_way = True
    """Driving on is valued as the best of going on to the view and stopping at any look the rest of the drive
    takes, to choose again there (:meth:`~seal_cli.sim.policies.whole_plan.WholePlanSearch.ahead`): the drive
    shows what it passes whatever is chosen next, so another view must beat the best of these by more than
    :attr:`rethink_m` (see docs/sefm.md, "Choosing again on the drive")."""

    reconsider_in_room = True
    """In one room, a look chosen while the plan's next stop was unseen (its drive on counted from the stop's
    belief) is chosen again when the drive brings an instance of that stop into sight (:meth:`_reconsider_in_room`)."""

    def _reconsider_in_room(self, agent: Agent, target: str, view: View) -> str | None:
        """The drive to ``view`` stops when the look was chosen with the plan's next stop unseen and the drive has
        now seen it, and SeFM's expected cost of finishing the plan (:meth:`_first_of_tour`) from here is lower
        by more than :attr:`defer_m` with another first look than with driving on to ``view``."""
        if not (self.reconsider_in_room and self.use_frames and self._blind == target and self._news):
            return None
        self._news = False
        if not self._ahead(agent, agent.class_of(target), agent.world.robot.pose[:2])[:1]:
            return None
        self._blind = None
        key = (view.cell, view.open)
        self.tried.discard(key)
        fresh = self._fresh(agent, target)
        driven = next((o for o in fresh if (o.view.cell, o.view.open) == key), None)
        choice = self._first_of_tour(agent, fresh, target, incumbent=driven) if driven is not None else view
        if (choice.cell, choice.open) == key:
            self.tried.add(key)
            return None
        return "what it saw of the plan's next stop makes another look better"

    whole_plan = True
    """Search for the whole remaining plan (off: the step's own belief, the search of earlier rounds)."""
    min_rooms = 2
    """The whole-plan search runs on maps of this many rooms or more; on fewer (ALFRED's single open rooms,
    seen 1.5 m at a time) the greedy view rule is kept: the region model of earlier rounds was longer
    there, and the view model that replaced it has not been measured there (docs/benchmarks.md)."""

    by_context = False
    """In the whole-plan search, leave object-only's view under the same belief (:meth:`_house_best`) for another
    only where the frame's context — the rest of the plan after the thing sought now: where the next thing may
    be, the drive on to a known stop — makes the other better too, by more than the lattice's spacing
    (:func:`~seal_cli.sim.policies.completion.choose`): the thing's own search would be object-only's, and the
    frame would move the robot only where it has something to say. Off: measured on the context suite it gives
    up most of SeFM's gain (19.34 m against 18.02, object-only 21.99), which comes as much from the rollout's
    search for each thing as from the context; the map suite's one longer command is a bet the model takes
    knowingly (docs/benchmarks.md, "This round (search14)")."""

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
        sefm = self._beliefs(agent)
        self._restate(agent)
        points = self.map.free_centres

        sought = agent.class_of(target)
        further = self.further_prior and self.further(agent, target)

        def weights(cls: str) -> np.ndarray:
            if further and cls == sought:   # e2e24: the other mug in a house, as in one room (:meth:`further_belief`)
                w = self._further_unlooked(agent, points, cls)
            elif self.cell_beliefs and cls in sefm.object_classes and not agent.instances(cls):
                w = self.cell_belief(cls, sefm.objects.sources[sefm.objects.row(cls)].said)
            elif cls in sefm.object_classes:
                w = np.asarray(sefm.object_density(cls, points), dtype=float)
            else:
                w = np.asarray(self.map.prior(cls).weights, dtype=float)
            return np.where(np.isfinite(w) & (w > 0), w, 0.0)

        greedy = None
        if sought in sefm.object_classes:   # object-only's choice now, weighed among the candidates
            w = weights(sought)
            if w.sum() > 0:
                greedy = self._house_best(agent, target, points, w / w.sum(), list(sefm.object_summary(sought).modes))
        return self.planner.choose(agent, binding, target, weights, also=greedy, by_context=self.by_context,
                                   stale=self._stale_nodes() if self.count_views_once else None)

    count_views_once = True
    """The whole-plan search values a look from where SeFM has looked already (within its ``view_step``, with the
    same places shut) as revealing nothing (:meth:`_stale_nodes`). Off (before search20): the model expected such a
    look to reveal the belief its view sees, SeFM's filter counted the look's misses as nothing new, the belief
    stayed, and the search chose the same kind of look again — on the held-out ranch, 200 m of views about a
    bedroom whose belief no look could lower (docs/benchmarks.md, "This round (search20)")."""

    def _stale_nodes(self) -> np.ndarray | None:
        """The lattice nodes from which a look would tell SeFM's beliefs nothing: within the object filter's
        ``view_step`` of a view it has used with the places shut as they are now (negative information counts
        once per view: :mod:`seal_cli.sefm.object_beliefs`). None for a sensor that does not see all round,
        whose views also differ by heading (the model's look at a view turns all round; not modelled)."""
        views = self.sefm.objects.views
        if views.turn is not None:
            return None
        shut = frozenset(self.sefm.hidden_places())
        used = np.asarray([(x, y) for x, y, _, closed in views.used if closed == shut], dtype=float)
        if not len(used):
            return None
        from scipy.spatial import cKDTree

        points = self.planner.lattice.points
        near = cKDTree(used).query(points, distance_upper_bound=views.step + 1e-9)[0]
        return np.asarray(np.isfinite(near), dtype=bool)

    def _restate(self, agent: Agent) -> None:
        """Bring the frame beliefs up to the robot's state without an observation the robot did not make: one
        update at the pose of its last look (a view already used, so it adds no negative information) with no
        detections. An update at the robot's pose, where it may not have looked (it drove to a thing it had seen
        and picked it up), would count everything in view there as missed: on the farmhouse the cup 4.9 m away
        in sight of the spoon, searched for 31 m more (docs/benchmarks.md, search13)."""
        if self.history:
            self.sefm.update(self.history[-1][0], (), self._state(agent))

    def greedy_view(self, agent: Agent, binding: Binding, target: str) -> View | None:
        """The first look of the shortest expected search through the looks that reveal the most belief
        per metre (:meth:`_looks`, :meth:`_first_of_tour`); the belief's modes where the map has no places;
        the nearest frontier when no look is worth :attr:`min_mass`. Once every place has been looked at:
        the belief's modes where the class's prior names a room (the thing may stand anywhere in it), the
        frontier where the prior names only places (ALFRED's rooms: the modes of a belief whose places
        are spent lie where it has looked already, and chasing them wandered for tens of metres)."""
        if len(self.map.rooms) >= self.min_rooms:
            return self._house_view(agent, binding, target)
        fresh = self._fresh(agent, target)
        return self._taken(agent, binding, target, self._first_of_tour(agent, fresh, target) if fresh else None)

    def _fresh(self, agent: Agent, target: str) -> list[Look]:
        """The looks :meth:`greedy_view` chooses among: not yet tried, each worth :attr:`min_mass`."""
        field_ = agent.distances()
        X, W, modes = self.cloud(agent, target)
        W = above_floor(W)
        if self.further_prior and self.further(agent, target):   # the found ones are not in it: nothing to cut
            W = self.further_belief(agent, X, agent.class_of(target))
        else:
            for k in agent.instances(agent.class_of(target)):
                if agent.spent(k.id, target):  # the belief is right there, but that one will not do
                    W[np.hypot(X[:, 0] - k.at[0], X[:, 1] - k.at[1]) <= agent.world.reach] = 0.0
        hidden = np.zeros(len(X), dtype=bool)
        for x, y, r in self.sefm.hidden_places():
            hidden |= np.hypot(X[:, 0] - x, X[:, 1] - y) <= r
        options = self._looks(agent, target, X, W, field_, self.floor_share(agent, target, X))
        seeing = self.map.sensor.range
        roomy = any((t := self.map.prior_target(name)) is not None and t[0] == "room"
                    for name in self.map.priors.get(agent.class_of(target), {}))
        for mode in modes if self.modes_too or not self._places(agent) or (not options and roomy) else ():
            view = self._view_of(agent, mode.mean, field_)
            if view is not None:
                at = agent.grid.point(view.cell)
                mass = float(W[(np.hypot(X[:, 0] - at[0], X[:, 1] - at[1]) <= seeing) & ~hidden].sum())
                options.append(Look(mass, float(field_[view.cell]), view))
        return [o for o in options if (o.view.cell, o.view.open) not in self.tried and o.mass > self.min_mass]

    further_prior = True
    """Search for a further instance of a class (the second laptop, once the first is found and put
    down) by the class's prior over the places not yet looked at (:meth:`further_belief`), not by the
    filter's belief of the class, which the first instance's detection has drawn onto it; the places
    around the found ones keep their prior (the belief there was the found one's, and it is not in this
    one). Off: the filter's belief with everything within reach of a found instance cut out (earlier
    rounds), which also cut the places beside it."""

    @staticmethod
    def further(agent: Agent, target: str) -> bool:
        """Whether ``target`` must be an instance of its class other than every one seen: some seen one
        is spent for it (put in place already, out of reach, or chosen for another name)."""
        return any(agent.spent(k.id, target) for k in agent.instances(agent.class_of(target)))

    def further_belief(self, agent: Agent, X: np.ndarray, cls: str) -> np.ndarray:
        """Where a further instance of ``cls`` may be, as a weight per point of ``X`` (the map's free
        cells): the class's prior above its floor.

        SeFM keeps one belief per class (one object, after SLiM): a detection puts its particles on the
        instance seen, and what is left elsewhere is the prior's redrawn 5 % at 1 % of the weight and
        whatever negative information has done to it — the wrong belief for *another* instance, and one
        whose residue ranks places by sampling noise (in one train episode the two armchairs by the bed,
        while the counter top the prior favours had none left above the floor). Taking the instances to
        be placed independently by the prior, with a detector that sees all a place holds once the robot
        has looked into or onto it from within reach, the posterior of a further instance is the prior
        restricted to the places not yet so looked at — which is what the search's places model does with
        this belief (:meth:`_looks` keeps only the places not inspected). The approximation: looks from
        beyond reach (a place 1.5 m off seen from across the room) and the detector's misses are not
        counted against a place."""
        w = np.asarray(self.map.prior(cls).weights, dtype=float)
        w = np.where(np.isfinite(w) & (w > 0), w, 0.0)
        if len(w) != len(X) or w.sum() <= 0:
            return np.zeros(len(X))
        return above_floor(w / w.sum())

    def _further_unlooked(self, agent: Agent, X: np.ndarray, cls: str) -> np.ndarray:
        """:meth:`further_belief` for the whole-plan search in a house (e2e24): the class's prior, less the places
        the robot has looked into or onto from within reach (the single-room search's places model drops them;
        the whole-plan model has no places, so their mass is cut here). Before, the search for a second mug on
        the student house used the class's belief, drawn onto the first mug, and wandered 170 m."""
        w = self.further_belief(agent, X, cls)
        if not len(w):
            return w
        for k in agent.known.values():
            if k.movable or k.id not in agent.inspected:
                continue
            where = self.map.place(k.id)
            reach = where.reach if where is not None else agent.world.reach
            w[np.hypot(X[:, 0] - k.at[0], X[:, 1] - k.at[1]) <= reach + 0.25] = 0.0
        return w

    tour_views = 8
    """How many of the best looks (by belief per metre) the search orders as a tour before taking the
    first (:meth:`_first_of_tour`); 1 is the greedy rule."""

    onward = 1.0
    """SeFM's frame context in one room: the search is for where the frame can be done, so the drive on to
    the plan's next stop (the fridge to put the apple in, the lamp to look at it under; where no instance
    is known yet, the stop's belief: :meth:`_onward_belief`) counts: the tour's expected cost adds, for the
    belief each look would be the first to reveal, this weight times the drive on from it, and SeFM's first
    look departs from object-only's only where that expected cost says so by more than :attr:`defer_m`
    (:meth:`_first_of_tour`). 0: the thing's search alone, as object-only searches."""

    onward_through = True
    """The drive on from where the thing is found runs through the plan's next known stops (up to
    :attr:`stand_ahead`, as :meth:`stand` chooses the cells to act on them from): in a cooling task, the fridge
    *and* the cabinet the plate goes to after it, so a look beside the fridge's far side is not valued as if the
    plan ended at the fridge (docs/benchmarks.md, "This round (search15)"). Off: to the next stop only."""

    onward_pool = False
    """Also draw the tour's looks from the best by belief per metre of the drive there *and on*, mass /
    (metres + scale + on) (earlier rounds: on). Off: SeFM's looks are object-only's, the best by belief per
    metre there, and the drive on counts only in the tour's expected cost. That ratio is not an expected
    cost: it favours looks beside a known stop (the garbage can by the fridge) whatever their mass, and the
    tour's E over a larger set of looks is not comparable with object-only's (the belief a tour leaves
    unrevealed counts nothing). Under the model the drive on is paid once, from the look that finds the
    thing, so for looks that reveal different places Σ p_k · on(v_k) is the same in every order and cannot
    choose the looks (docs/benchmarks.md, "This round (search9)")."""

    def _onward_field(self, agent: Agent, stop: Known, *later: Known) -> np.ndarray:
        """Metres from every cell to the nearest cell to act on ``stop`` from; with ``later`` stops, the shortest
        drive through a cell to act on each in turn, as :meth:`stand` chooses them (kept per stops and places)."""
        key = tuple((k.id, k.at) for k in (stop, *later))
        if key not in self._onward:
            rest = np.zeros(agent.grid.shape)
            for k in reversed((stop, *later)):   # from the last stop back: to act on it, then on through the rest
                cells = agent.stand_cells(k)
                rest = agent.grid.distances_from(cells, rest[cells[:, 0], cells[:, 1]])
            self._onward[key] = rest
        return self._onward[key]

    onward_points = 24
    """At most this many of the heaviest points of a stop's belief (:meth:`_onward_belief`)."""

    def _onward_belief(self, agent: Agent, target: str) -> np.ndarray | None:
        """The expected metres from every cell on to the plan's next stop after ``target`` when no instance
        of it is known yet (the lamp LookAt(pen, lamp) needs, not yet seen): the stop's SeFM belief above
        its floor, its heaviest points (up to 90 % of it, at most :attr:`onward_points`), each the drive
        to it weighted by its mass. None: no such stop, or no belief of it."""
        from seal_cli.sim.policies.oracle import navigation_targets

        cls = agent.class_of(target)
        targets = [agent.class_of(t) for t in navigation_targets(agent)]
        while targets and targets[0] == cls:
            targets.pop(0)
        held = agent.held()
        if not targets or (held is not None and held.key == targets[0]) or targets[0] not in self.sefm.object_classes:
            return None
        X = self.map.free_centres
        w = np.asarray(self.sefm.object_density(targets[0], X), dtype=float)
        w = np.where(np.isfinite(w) & (w > 0), w, 0.0)
        if w.sum() <= 0:
            return None
        w = above_floor(w / w.sum())
        top = np.argsort(-w, kind="stable")[: self.onward_points]
        top = top[: int(np.searchsorted(np.cumsum(w[top]), 0.9 * w[top].sum())) + 1]
        total = np.zeros(agent.grid.shape)
        for k in top:
            total += w[k] * agent.grid.distances(agent.grid.nearest_free(X[k]))
        return np.asarray(total / w[top].sum())

    def _first_of_tour(self, agent: Agent, looks: Sequence[Look], target: str, incumbent: Look | None = None) -> View:
        """The first look of the shortest expected search through the best :attr:`tour_views` looks.

        Searching for one thing, an order of looks v1, v2, ... costs, in expectation, each drive times
        the chance the thing is still unfound when it starts: E = Σ_k (d(v_k-1, v_k) + scale) · (1 − Σ_j<k
        p_j), where p_j is the belief look j reveals that the looks before it have not (a look from one
        cell sees every place within reach of it, so a place two looks reach counts once). One greedy
        step (the most belief per metre) can leave a near, fairly likely place behind, to be driven back
        to later; the order is built greedily from where the robot is and then improved by moving one
        look at a time to wherever E falls most (or-opt), and the robot goes to the first look.
        Of looks equally good (the same belief for the same drive: the cells all round a fridge), the one
        nearer the plan's next known stop — a tie-break, so a known goal never draws the
        robot away from where the thing is likelier. SeFM (:attr:`onward` > 0) adds to E, for the belief
        p_j each look reveals first, p_j times the drive on from it to the next stop: a place two looks
        see is best seen from the one nearer where the frame goes on (for looks that reveal different
        places that sum is the same in every order: the drive on is paid once). SeFM's looks are
        object-only's (with :attr:`onward_pool`, also the best by belief per metre there and on), and its
        first look is object-only's — the first of the tour of the same looks with no drive on — unless the
        best order's E beats the best order that starts with object-only's look by more than :attr:`defer_m`.
        With ``incumbent`` (the look being driven to, :meth:`_reconsider_in_room`), that look stands in for
        object-only's in the comparison, and (:attr:`see_on_the_way`) both orders' E count what their drives
        see on the way (:meth:`_on_the_way`); object-only's own order does not.
        The drive on is counted from where the thing found would be acted on (:meth:`_acted`: from the look
        where it reaches the thing, else from the cell that does, with the drive there) and through the plan's
        next known stops (:attr:`onward_through`).
        Approximations: the looks are the best few, not all; on the way, only places within reach; the
        belief the tour leaves unrevealed adds nothing to E; one instance; an open place as a disc round its
        pivot on which the thing lies at :attr:`ON_PLACE`'s distances, walls between the hand and the thing not
        counted."""

        through = self._ahead(agent, agent.class_of(target), agent.world.robot.pose[:2])
        ahead = through[:1]
        stands = agent.stand_cells(ahead[0]) if ahead else np.zeros((0, 2), dtype=int)
        then = None
        if self.use_frames and self.onward > 0:
            stops = through if self.onward_through else ahead
            then = self._onward_field(agent, *stops) if ahead else self._onward_belief(agent, target)
            self._blind = target if then is not None and not ahead else None

        def plain(o: Look) -> float:   # equal to rounding: the same looks for SeFM and object-only
            return round(o.mass / (o.metres + self.distance_scale), 6)

        def score(o: Look) -> float:
            on = self.onward * float(then[o.view.cell]) if then is not None else 0.0
            return round(o.mass / (o.metres + self.distance_scale + (on if np.isfinite(on) else 0.0)), 6)

        # object-only's looks: the best by belief per metre (ties at the last kept, then the nearer the next stop)
        ranked = sorted(looks, key=lambda o: -plain(o))
        pool = ranked[: self.tour_views]
        pool += [o for o in ranked[len(pool):] if plain(o) == plain(pool[-1])][: self.tour_views]
        extra: list[Look] = []
        if self.onward_pool and then is not None:   # and the best by belief per metre there and on
            ranked = sorted(looks, key=lambda o: -score(o))
            extra = ranked[: self.tour_views]
            extra += [o for o in ranked[len(extra):] if score(o) == score(extra[-1])][: self.tour_views]
        fields = {o.view.cell: agent.grid.distances(o.view.cell) for o in [*pool, *extra]}

        def onward(o: Look) -> float:   # metres on to the plan's next known stop
            f = fields[o.view.cell][stands[:, 0], stands[:, 1]] if len(stands) else np.zeros(1)
            return float(f.min())

        plain_best = sorted(pool, key=lambda o: (-plain(o), onward(o)))[: self.tour_views]
        if then is None:
            return self._tour(agent, plain_best, fields, None)[0].view
        best = plain_best + [o for o in sorted(extra, key=lambda o: (-score(o), onward(o))) if o not in plain_best]
        best = best[: 2 * self.tour_views]
        if self.defer_m is None:
            return self._tour(agent, best, fields, then)[0].view
        # the look object-only's rule takes under this belief (or the one driven to), and what SeFM's cost says of it
        alone = self._tour(agent, plain_best, fields, None)[0] if incumbent is None else incumbent
        if not any(o is alone for o in best):
            best = [*best, alone]
            fields.setdefault(alone.view.cell, agent.grid.distances(alone.view.cell))
        model = self._tour_model(best, fields, then, agent)
        if self.see_on_the_way and then is not None:
            model = self._on_the_way(agent, best, model, then)
        order, expected = model.best()
        if best[order[0]] is alone:
            return alone.view
        other, deferred = model.best(first=next(k for k, o in enumerate(best) if o is alone))
        departs = self._departs(model, order, other, deferred - expected)
        context = None
        if departs and self.by_context_in_room and then is not None and incumbent is None:
            context = self._context_share(agent, best, fields, then, best[order[0]], alone, deferred - expected)
            departs = context > self.defer_m if self.defer_m is not None else context > 0
        self.departures.append({"target": target, "gap": round(deferred - expected, 4),
                                "context": None if context is None else round(context, 4),
                                "outcomes": (model.outcomes(order), model.outcomes(other)), "departs": departs})
        return best[order[0]].view if departs else alone.view

    by_context_in_room = True
    """In one room, SeFM's first look departs from object-only's only for what the frame's context adds to the
    expected saving (:meth:`_context_share`), not for the rest of the gap. SeFM's expected cost differs from the
    rule object-only's look comes from in two ways: the drive on to the plan's next stops (the frame's context)
    and what the drives see on the way (:attr:`see_on_the_way`, a finer model of the *thing's own* search, which
    object-only's choice does not use). A departure the second alone earns is a bet on the search model, not on
    the frame: on ALFRED-2D's held-out floor plans it was the heating group's tomato (9.5 m against object-only's
    6.0, docs/benchmarks.md, "search25"). Against object-only's look only: a look being driven to
    (:meth:`_reconsider_in_room`) is weighed again because the drive saw the plan's next stop, news of the context
    itself, and there the whole gap counts. Off: the whole gap counts everywhere (search9 to search24)."""

    def _context_share(self, agent: Agent, best: Sequence[Look], fields: dict[Cell, np.ndarray], then: np.ndarray,
                       mine: Look, alone: Look, gap: float) -> float:
        """The part of ``gap`` — how much less SeFM's expected cost of finishing the plan is with ``mine`` first
        than with object-only's ``alone`` first — that the frame's context makes: ``gap`` less the same comparison
        under the same model with no stop after the thing (its search alone: the drives there, what they see on the
        way and the drive to where it is acted on, as in the full model; not the drive on from there). Both
        comparisons take each first look with the best order after it that the greedy build and or-opt find
        (:meth:`_TourModel.best`)."""
        alone_then = np.zeros_like(then)   # no stop after the thing: the drive to act on it stays, the drive on goes
        search = self._tour_model(best, fields, alone_then, agent)
        if self.see_on_the_way:
            search = self._on_the_way(agent, best, search, alone_then)
        i = next(k for k, o in enumerate(best) if o is mine)
        j = next(k for k, o in enumerate(best) if o is alone)
        return gap - (search.best(first=j)[1] - search.best(first=i)[1])

    def _departs(self, model: _TourModel, order: Sequence[int], other: Sequence[int], gap: float) -> bool:
        """Whether SeFM's best order ``order`` is taken over ``other``, the best that starts with object-only's look:
        the expected saving ``gap`` exceeds :attr:`defer_m`."""
        return self.defer_m is not None and gap > self.defer_m

    defer_m: float | None = 0.25
    """SeFM's first look in one room is object-only's under the same belief (the best tour by belief per metre,
    with no drive on) unless SeFM's expected cost of finishing the plan — the search, and the drive on from
    where the thing is found — is lower by more than this many metres with another first look. Where the
    frame gives no reason to differ the two drive alike, and the drive on to a known stop (the fridge, the
    sink) cannot draw the robot to a look beside it that the model values within a lattice step of
    object-only's. None: SeFM's best first look, whatever the margin (earlier rounds)."""

    def _tour(self, agent: Agent, best: Sequence[Look], fields: dict[Cell, np.ndarray], then: np.ndarray | None,
              first: int | None = None) -> tuple[Look, float]:
        """The first look of the shortest expected search through ``best``, and its expected cost (with
        ``then``, the drive on from where the thing is found to the plan's next stop, SeFM's; ``first``: the
        best order that starts with that look)."""
        if len(best) < 2:
            return best[0], 0.0
        model = self._tour_model(best, fields, then, agent)
        order, current = model.best(first)
        return best[order[0]], current

    def _tour_model(self, best: Sequence[Look], fields: dict[Cell, np.ndarray], then: np.ndarray | None,
                    agent: Agent | None = None) -> _TourModel:
        """The expected-cost model of searching through ``best`` (:class:`_TourModel`); with ``agent`` (and
        :attr:`acted_on`), the drive on counted from where the thing is acted on (:meth:`_acted`)."""
        n = len(best)
        here = np.array([o.metres for o in best])
        between = np.array([fields[o.view.cell][[b.view.cell[0] for b in best], [b.view.cell[1] for b in best]]
                            for o in best])
        width = max((len(o.reveals) for o in best if o.reveals is not None), default=0)
        R = np.zeros((n, width + n))   # what each look reveals; a look no place's share describes, its own mass
        for k, o in enumerate(best):
            if o.reveals is None:
                R[k, width + k] = o.mass
            else:
                R[k, : len(o.reveals)] = o.reveals
        on = np.array([float(then[o.view.cell]) for o in best]) if then is not None else np.zeros(n)
        on = np.where(np.isfinite(on), on, 0.0)
        acted = None
        if agent is not None and then is not None and self.acted_on:
            acted = self._acted(agent, then, [o.view.cell for o in best], np.asarray((R > 0).any(axis=0)))
        return _TourModel(here, between, R, self.onward * on, self.distance_scale, acted=acted)

    acted_on = True
    """SeFM's drive on, in one room, is counted from where the thing found is acted on, not from the look that
    finds it (:meth:`_acted`). Off: from the look (earlier rounds), which charged a look at a long table's near
    end as if the robot picked up from there a plate at the far end (docs/benchmarks.md, "This round
    (search15)")."""

    ON_PLACE = (0.124, 0.325, 0.523, 0.903)
    """Where on an open place a thing lies: its distance from the place's pivot as a share of the pivot's distance
    to the nearest free cell, at the quantiles 1/8, 3/8, 5/8 and 7/8 of ALFRED-2D's train split (120,151 things on
    receptacles that do not open; :func:`seal_cli.bench.alfred2d.place_spread`, rebuilt by
    ``scripts/build_place_spread.py``)."""

    ON_PLACE_DIRECTIONS = 8
    """Directions round the pivot at which :attr:`ON_PLACE`'s distances are taken (the place as a disc)."""

    def _acted(self, agent: Agent, then: np.ndarray, cells: Sequence[Cell], live: np.ndarray) -> np.ndarray:
        """(len(cells), len(live)): per cell a look is taken from and per column (a place, or a look's own belief),
        the (weighted) metres to finish the plan's next stop once the look finds the thing there.

        The robot acts on a thing from a cell within reach of *it* (or by its place's access points, as
        :meth:`~seal_cli.sim.agent.Agent.stand_cells`), the one that makes the drive there and on to the next stop
        shortest (:meth:`stand`): from a look within reach of the thing, the drive on from the look; from one that
        is not, the drive to such a cell and on from there. Where on an open place the thing lies is not in the
        belief (a belief point is a pose to act from), so it is taken at :attr:`ON_PLACE`'s distances from the
        pivot in :attr:`ON_PLACE_DIRECTIONS` directions, equally likely; the column's cost is the mean over those
        points of min over the cells s that reach the point of d(cell, s) + then(s), which is then(cell) where
        the cell itself reaches it. A shut place (its thing is taken from where it is opened), a floor point and
        a look's own mass keep the drive on from the look. ``live``: the columns to value (others get the look's)."""
        own = np.array([float(then[c]) for c in cells])
        out = np.repeat(np.where(np.isfinite(own), own, 0.0)[:, None], len(live), axis=1)
        places = self._places(agent)
        at = tuple(np.array(cells, dtype=int).reshape(-1, 2).T)
        for j, place in enumerate(places[: len(live)]):
            if not live[j] or place.openable:
                continue
            costs = [h[at] for h in self._acted_fields(agent, place, then)]
            if not costs:
                continue
            value = np.mean(costs, axis=0)
            out[:, j] = np.where(np.isfinite(value), value, out[:, j])
        return self.onward * out

    def _acted_fields(self, agent: Agent, place: Known, then: np.ndarray) -> list[np.ndarray]:
        """Per point the thing may lie at on ``place`` (:meth:`_acted`), per free cell u: min over the cells s that
        reach the point of d(u, s) + then(s) — one Dijkstra from a source joined to those cells at then(s)
        (kept while ``then`` is the same)."""
        if self._acted_then is not then:
            self._acted_then, self._acted_cache = then, {}
        if place.id not in self._acted_cache:
            out = []
            for stands in self._on_place(agent, place):
                cells = agent.grid.free_cells[stands]
                field_ = agent.grid.distances_from(cells, then[cells[:, 0], cells[:, 1]])
                if np.isfinite(field_).any():
                    out.append(field_)
            self._acted_cache[place.id] = out
        return self._acted_cache[place.id]

    def _on_place(self, agent: Agent, place: Known) -> list[np.ndarray]:
        """Per point a thing may lie at on ``place`` (:attr:`ON_PLACE`), the free cells (indices into the grid's
        free cells) from which the robot reaches it; kept per place."""
        if place.id not in self._places_at:
            pts = agent.grid.free_points
            rho = float(np.min(np.hypot(pts[:, 0] - place.at[0], pts[:, 1] - place.at[1]))) if len(pts) else 0.0
            reach = agent.world.reach_of(place.id) if place.id in agent.world.items else agent.world.reach
            near_access = np.zeros(len(pts), dtype=bool)
            for a in place.access:
                near_access |= np.hypot(pts[:, 0] - a[0], pts[:, 1] - a[1]) <= agent.world.access_tolerance
            out = []
            for share in self.ON_PLACE:
                for t in range(self.ON_PLACE_DIRECTIONS):
                    angle = 2 * math.pi * t / self.ON_PLACE_DIRECTIONS
                    x, y = place.at[0] + share * rho * math.cos(angle), place.at[1] + share * rho * math.sin(angle)
                    near = (np.hypot(pts[:, 0] - x, pts[:, 1] - y) <= reach - 1e-6) | near_access
                    if near.any():
                        out.append(np.flatnonzero(near))
            self._places_at[place.id] = out
        return self._places_at[place.id]

    see_on_the_way = True
    """SeFM's expected cost when it weighs its own first look against object-only's counts what the drives see
    on the way (:meth:`_on_the_way`): the robot looks every metre of a drive, sees into or onto every open
    place within reach of where it stands, and a search drive stops at the look that finds the thing. Off:
    a drive reveals only what its last look does (earlier rounds)."""

    def _on_the_way(self, agent: Agent, best: Sequence[Look], model: _TourModel, then: np.ndarray) -> _TourModel:
        """``model`` with the looks every drive between ``best``'s looks (and from the robot) takes on the way,
        and what each reveals: the places (not the floor) within the world's reach of it, open and holding
        belief — the belief of a place is what the looks of ``best`` say it holds — with the drive on from
        there. Paths are the grid's shortest ones, looks every :attr:`~seal_cli.sim.agent.Agent.look_every`
        metres as :meth:`~seal_cli.sim.agent.Agent.drive_to` takes them."""
        from dataclasses import replace

        places = self._places(agent)
        width = model.R.shape[1]
        mass = np.zeros(width)
        for o in best:
            if o.reveals is not None:
                mass[: len(places)] = np.maximum(mass[: len(places)], o.reveals[: len(places)])
        shut = np.array([self._shut(agent, p) for p in places], dtype=bool)
        mass[: len(places)][shut] = 0.0
        if not mass.any():
            return model
        live = np.flatnonzero(mass[: len(places)] > 0)
        starts = [(-1, agent.robot_cell()), *((k, o.view.cell) for k, o in enumerate(best))]
        way: dict[tuple[int, int], list[tuple[float, np.ndarray, float | np.ndarray]]] = {}
        for a, start in starts:
            for b, o in enumerate(best):
                if a == b or start == o.view.cell:
                    continue
                key = (start, o.view.cell)
                if key not in self._ways:
                    self._ways[key] = self._stops(agent, start, o.view.cell)
                legs = []
                for at, cell in self._ways[key]:
                    cols = np.zeros(width, dtype=bool)
                    cols[live] = self._reach_at(agent, places, live, cell)
                    if cols.any():
                        if model.acted is not None:   # from where the thing is acted on
                            legs.append((at, cols, self._acted(agent, then, [cell], cols)[0]))
                        else:
                            on = float(then[cell]) if np.isfinite(then[cell]) else 0.0
                            legs.append((at, cols, self.onward * on))
                if legs:
                    way[(a, b)] = legs
        return replace(model, way=way, mass=mass)

    def _stops(self, agent: Agent, start: Cell, goal: Cell) -> list[tuple[float, Cell]]:
        """Where a drive from ``start`` to ``goal`` looks on the way: (metres from ``start``, cell)."""
        from seal_cli.errors import SealError

        try:
            path = agent.grid.path(start, goal)
        except SealError:   # no path: the tour's drive tables say inf already
            return []
        out, metres, since = [], 0.0, 0.0
        prev = agent.grid.point(path[0])
        for cell in path[1:-1]:
            p = agent.grid.point(cell)
            step = math.dist(prev, p)
            prev, metres, since = p, metres + step, since + step
            if since >= agent.look_every:
                out.append((metres, cell))
                since = 0.0
        return out

    def _reach_at(self, agent: Agent, places: Sequence[Known], live: np.ndarray, cell: Cell) -> np.ndarray:
        """Which of the places ``live`` (indices into ``places``) the robot can act on from ``cell`` (kept per cell
        and place)."""
        x, y = agent.grid.point(cell)
        out = np.zeros(len(live), dtype=bool)
        for i, j in enumerate(live):
            place = places[int(j)]
            key = (cell, place.id)
            if key not in self._reach_cache:
                near = (math.dist((x, y), place.at) <= agent.world.reach_of(place.id) + 1e-9
                        or any(math.dist((x, y), a) <= agent.world.access_tolerance + 1e-9 for a in place.access))
                self._reach_cache[key] = near and agent.world.within_reach(place.id, (x, y, 0.0))
            out[i] = self._reach_cache[key]
        return out

    def _places(self, agent: Agent) -> list[Known]:
        """The places a look can reveal the contents of (not people, not things)."""
        return [k for k in agent.known.values() if not k.movable and agent.world.items[k.id].key != PERSON]

    def _shares(self, agent: Agent, places: Sequence[Known], X: np.ndarray, W: np.ndarray, cls: str) -> np.ndarray:
        """The belief mass each place holds. A belief point is a pose to act from, within a place's
        reach (+ one cell) of it, and may serve several places at once (a counter, the cabinet under
        it, the microwave on it); it is shared among them as the class's prior shares it — in
        proportion to the prior density each place's target puts there (a microwave's 0.12 on its few
        cells outweighs one of twenty cabinets' share of 0.13) — and equally where the prior names
        none of them (a room-level prior)."""
        covers = np.zeros((len(X), len(places)), dtype=bool)
        for j, place in enumerate(places):
            where = self.map.place(place.id)
            reach = where.reach if where is not None else agent.world.reach
            covers[:, j] = np.hypot(X[:, 0] - place.at[0], X[:, 1] - place.at[1]) <= reach + 0.25
        density = np.zeros((len(X), len(places)))
        column = {class_key(p.id): j for j, p in enumerate(places)}
        for name, mass in self.map.priors.get(cls, {}).items():
            resolved = self.map.prior_target(name)
            cells = self.map.target_cells(name)
            if resolved is None or resolved[0] == "room" or mass <= 0 or not len(cells):
                continue
            members = [column[k] for i in resolved[1] if (k := class_key(self.map.places[i].name)) in column]
            if members:
                shared = covers[:, members].sum(axis=1, keepdims=True)
                density[:, members] += np.where(covers[:, members], mass / len(cells) / np.maximum(shared, 1), 0.0)
        named = density.sum(axis=1, keepdims=True)
        split = np.where(named > 0, density / np.where(named > 0, named, 1.0),
                         covers / np.maximum(covers.sum(axis=1, keepdims=True), 1))
        return np.asarray(W @ split, dtype=float)

    @staticmethod
    def _shut(agent: Agent, place: Known) -> bool:
        return place.openable and place.id not in agent.opened and not agent.world.items[place.id].is_open

    def _looks(self, agent: Agent, target: str, X: np.ndarray, W: np.ndarray,
               field_: np.ndarray, floor: float = 0.0) -> list[Look]:
        """Every look worth considering: the belief it reveals, the metres to drive there, the view.

        A look from a cell reveals what is in or on *every* open place within reach of it, not only
        the one it was chosen for (in ALFRED's open rooms a stand cell is within reach of two or three
        receptacles), and what the shut place it opens holds (the heaviest one within reach); a place
        the robot has looked at from within reach while it was open holds nothing more to see. The
        cells are each place's nearest stand cell by path and, on a 0.25 m lattice, every cell within
        reach of a place, so a cell that reaches two likely places beats the nearest cell of either.
        With ``floor`` (the chance the thing lies on the open floor, :meth:`floor_share`) the places hold
        1 − ``floor`` of the belief, and every look also reveals the floor's share of the unseen floor
        points in sight of it (:meth:`_floor_looks`, which adds the looks from open floor)."""
        places = self._places(agent)
        share = self._shares(agent, places, X, W, agent.class_of(target)) * (1.0 - floor)
        live = np.array([p.id not in agent.inspected for p in places], dtype=bool) & (share > 0)
        if not live.any():
            return self._floor_looks(agent, [], len(places), floor, field_)
        shut = np.array([self._shut(agent, p) for p in places], dtype=bool)
        cells = self._lattice(agent, [p for p, ok in zip(places, live, strict=True) if ok])
        for place in (p for p, ok in zip(places, live, strict=True) if ok):
            cell = agent.stand_cell(place, field_)
            if cell is not None:
                cells.append(cell)
        cells = list(dict.fromkeys(c for c in cells if np.isfinite(field_[c])))
        if not cells:
            return []
        reach = self._reach_rows(agent, places, cells)
        opens = np.where(reach & (live & ~shut)[None, :], share[None, :], 0.0)
        boxes = np.where(reach & (live & shut)[None, :], share[None, :], 0.0)
        best_box = np.argmax(boxes, axis=1)
        options = []
        for i, cell in enumerate(cells):
            seen = opens[i].sum()
            box = places[int(best_box[i])] if boxes[i, best_box[i]] > 0 else None
            shut_mass = boxes[i].sum() if self.open_all else (boxes[i, best_box[i]] if box is not None else 0.0)
            mass = float(seen + shut_mass)
            if mass <= 0:
                continue
            shown = [places[j].id for j in np.argsort(-opens[i]) if opens[i, j] > 0][:3]
            look_at = box.at if box is not None else places[int(np.argmax(opens[i]))].at
            why = (f"opens {box.id}" + (f" and looks at {', '.join(shown)}" if shown else "") if box is not None
                   else f"looks at {', '.join(shown)}") + ", where the belief is"
            reveals = opens[i] + boxes[i] if self.open_all else opens[i].copy()
            if box is not None and not self.open_all:
                reveals[int(best_box[i])] = boxes[i, best_box[i]]
            options.append(Look(mass, float(field_[cell]), View(cell, look_at, open=box.id if box else None, why=why),
                                reveals))
        return self._floor_looks(agent, options, len(places), floor, field_)

    floor_min = 0.1
    """The least learnt open-floor share (:attr:`~seal_cli.sim.agent.Scene.open_floor`) for which the floor
    is searched as a place of its own (below it, the frontier sweep once the places are spent, as
    before). Chosen on ALFRED-2D's train split (docs/benchmarks.md)."""

    def floor_share(self, agent: Agent, target: str, X: np.ndarray) -> float:
        """The chance the thing sought lies on the open floor, given that it has not been seen yet.

        Bayes, with a perfect detector: the prior puts f (the scene's learnt :attr:`~seal_cli.sim.agent.
        Scene.open_floor` share) on the floor, uniformly over its free cells, and 1 − f on the places as
        the map's priors share it. Not having seen it leaves f·u on the floor (u: the fraction of the floor
        not yet in sight) and (1 − f)·r on the places (r: the prior share of the places not yet looked
        into or onto), so the floor's share is f·u / (f·u + (1 − f)·r). 0 below :attr:`floor_min`."""
        cls = agent.class_of(target)
        f = float(agent.scene.open_floor.get(cls, 0.0))
        if f < self.floor_min or f <= 0:
            return 0.0
        u = float(np.mean(~self.fallback.seen)) if len(self.fallback.seen) else 0.0
        places = self._places(agent)
        if cls not in self._prior_shares or len(self._prior_shares[cls]) != len(places):
            w = np.asarray(self.map.prior(cls).weights, dtype=float)
            w = np.where(np.isfinite(w) & (w > 0), w, 0.0)
            self._prior_shares[cls] = self._shares(agent, places, X, above_floor(w / w.sum()) if w.sum() > 0
                                                   else np.zeros(len(X)), cls)
        prior = self._prior_shares[cls]
        live = np.array([p.id not in agent.inspected for p in places], dtype=bool)
        r = float(prior[live].sum() / prior.sum()) if prior.sum() > 0 else 0.0
        on_floor, on_places = f * u, (1.0 - f) * r
        return on_floor / (on_floor + on_places) if on_floor > 0 else 0.0

    def _floor_looks(self, agent: Agent, looks: list[Look], width: int, floor: float,
                     field_: np.ndarray) -> list[Look]:
        """The looks with what each reveals of the open floor: ``floor`` spread evenly over the floor
        points not yet in sight (the frontier sweep's lattice, :class:`~seal_cli.sim.policies.coverage.
        CoveragePolicy`: every point within sight of free space), each point its own column after the
        ``width`` places' (so a point two looks see counts once in the tour); and looks from open floor,
        one free cell per 0.5 m, that reveal only floor. Unchanged when ``floor`` is 0."""
        unseen = ~self.fallback.seen
        if floor <= 0 or not unseen.any():
            return looks
        each = floor / float(unseen.sum())

        def floor_of(cell: Cell) -> np.ndarray:
            if cell not in self._floor_sight:
                x, y = agent.grid.point(cell)
                self._floor_sight[cell] = agent.world.sensor.visible((x, y, 0.0), self.fallback.lattice)
            return np.where(self._floor_sight[cell] & unseen, each, 0.0)

        out = []
        for o in looks:
            extra = floor_of(o.view.cell)
            reveals = np.concatenate([o.reveals if o.reveals is not None else np.zeros(width), extra])
            out.append(Look(o.mass + float(extra.sum()), o.metres, o.view, reveals))
        stride = max(1, round(0.5 / agent.grid.resolution))
        taken = {o.view.cell for o in looks}
        for i, j in agent.grid.free_cells:
            cell = (int(i), int(j))
            if i % stride or j % stride or cell in taken or not np.isfinite(field_[cell]):
                continue
            extra = floor_of(cell)
            if extra.sum() > 0:
                x, y = agent.grid.point(cell)
                why = f"looks over the open floor ({floor:.2f} of the belief is there)"
                out.append(Look(float(extra.sum()), float(field_[cell]), View(cell, (x, y), why=why),
                                np.concatenate([np.zeros(width), extra])))
        return out

    open_all = True
    """A look from a cell reveals every shut place within reach of it as well as the open ones: the robot
    opens them one after another from where it stands (the view names the heaviest; the next choice,
    with no drive, the next), and opening costs no metres. Off: only the heaviest shut one counts, and
    a cell beside five drawers is worth one drawer's share (the rule of earlier rounds)."""

    def _lattice(self, agent: Agent, places: Sequence[Known]) -> list[Cell]:
        """The free cells within reach of the places, one per 0.25 m."""
        from seal_cli.sim.policies.coverage import one_per_quarter_metre

        out: list[Cell] = []
        for place in places:
            if place.id not in self._stands:
                cells = agent.stand_cells(place)
                cells = cells[one_per_quarter_metre(cells, agent.grid.resolution)]
                self._stands[place.id] = [(int(i), int(j)) for i, j in cells]
            out.extend(self._stands[place.id])
        return out

    def _reach_rows(self, agent: Agent, places: Sequence[Known], cells: Sequence[Cell]) -> np.ndarray:
        """Which places the robot can act on (and so see into or onto) from each cell: the world's
        own rule (:meth:`~seal_cli.sim.world.World.within_reach`), kept per cell for the run."""
        ids = tuple(p.id for p in places)
        if ids != self._reach_ids:
            self._reach_ids, self._rows = ids, {}
        todo = [c for c in cells if c not in self._rows]
        for cell in todo:
            x, y = agent.grid.point(cell)
            self._rows[cell] = np.array([agent.world.within_reach(i, (x, y, 0.0)) for i in ids], dtype=bool)
        return np.array([self._rows[c] for c in cells], dtype=bool).reshape(len(cells), len(ids))

    def _house_view(self, agent: Agent, binding: Binding, target: str) -> View | None:
        """The greedy view of earlier rounds, kept for maps of :attr:`min_rooms` rooms or more: each place
        not yet looked into or onto, scored by the belief mass at it (for a shut one, all of it) per
        metre (+ :attr:`house_scale`) to its nearest stand cell; the belief's modes when no place is
        left. The single-room view (what a look reveals of every place in reach, the short tour, the
        frontier once the places are spent) was longer in houses, where a look from a place's stand
        cell reaches no other place and the prior names rooms (docs/benchmarks.md: the context suite)."""
        X, W, modes = self.cloud(agent, target)
        return self._taken(agent, binding, target, self._house_best(agent, target, X, W, modes))

    def _house_best(self, agent: Agent, target: str, X: np.ndarray, W: np.ndarray, modes: Sequence[Any]) -> View | None:
        """:meth:`_house_view`'s choice under the belief ``W`` over the points ``X`` (None: no fresh look
        is worth :attr:`min_mass`), with nothing marked tried."""
        field_ = agent.distances()
        W = W.copy()
        for k in agent.instances(agent.class_of(target)):
            if agent.spent(k.id, target):
                W[np.hypot(X[:, 0] - k.at[0], X[:, 1] - k.at[1]) <= agent.world.reach] = 0.0
        hidden = np.zeros(len(X), dtype=bool)
        for x, y, r in self.sefm.hidden_places():
            hidden |= np.hypot(X[:, 0] - x, X[:, 1] - y) <= r
        options: list[tuple[float, float, View]] = []
        for place in self._places(agent):   # not a person: the belief near Carla is the bookshelf's, not hers (e2e31)
            if place.id in agent.inspected:
                continue
            where = self.map.place(place.id)
            reach = where.reach if where is not None else agent.world.reach
            near = np.hypot(X[:, 0] - place.at[0], X[:, 1] - place.at[1]) <= reach + 0.25
            cell = agent.stand_cell(place, field_)
            if cell is None:
                continue
            shut = self._shut(agent, place)
            mass = float(W[near].sum() if shut else W[near & ~hidden].sum())
            why = f"opens {place.id}, where the belief is" if shut else f"looks at {place.id}, where the belief is"
            options.append((mass, float(field_[cell]), View(cell, place.at, open=place.id if shut else None,
                                                             why=why)))
        def worth(options: list[tuple[float, float, View]]) -> list[tuple[float, float, View]]:
            return [o for o in options if (o[2].cell, o[2].open) not in self.tried and o[0] > self.min_mass]

        fresh = worth(options)
        if self.modes_too or not fresh:     # no place holds belief worth a look: where the belief is (its modes)
            for mode in modes:
                view = self._view_of(agent, mode.mean, field_)
                if view is not None:
                    at = agent.grid.point(view.cell)
                    seen = (np.hypot(X[:, 0] - at[0], X[:, 1] - at[1]) <= self.map.sensor.range) & ~hidden
                    options.append((float(W[seen].sum()), float(field_[view.cell]), view))
            fresh = worth(options)
        return max(fresh, key=lambda o: o[0] / (o[1] + self.house_scale))[2] if fresh else None

    def _taken(self, agent: Agent, binding: Binding, target: str, view: View | None) -> View | None:
        """The view chosen (marked tried), or, when no fresh look is left, the frontier sweep's."""
        if view is None:
            fallback = self.fallback.next_view(agent, binding, target)
            if fallback is None:
                return None
            view = View(fallback.cell, fallback.look_at, fallback.open, f"{fallback.why} (the belief is spent)")
        self.tried.add((view.cell, view.open))
        return view

    house_scale = 1.0
    """The metres a look costs beside its drive in :meth:`_house_view` (earlier rounds' choice)."""

    min_mass = 1e-3
    """A view that would reveal less belief than this is not worth the drive."""
    modes_too = False
    """Also consider standing on the belief's modes when the map has places (without places, or when no place
    left holds belief worth a look, always: before search17 the modes were weighed only on a map with no
    places, so a belief lying on a room's floor away from every place — the longhouse's bedroom, its bed
    reached from nowhere — was declared spent and the robot swept the frontier 0.2 m at a time,
    docs/benchmarks.md "This round (search17)")."""

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


def above_floor(W: np.ndarray) -> np.ndarray:
    """A belief over free cells less its uniform floor (its least value), renormalised: a share that is
    the same everywhere is no reason to look anywhere, and counted per cell it would favour the places
    with the most cells around them. A frame belief with no context is its object's belief plus the
    frame potential's floor, so with the floor taken off SeFM searches for the first thing of a plan
    exactly as object-only does, and parts from it only where the frame's context says something."""
    rest = W - W.min() if len(W) else W.copy()
    total = rest.sum()
    return rest / total if total > 0 else W.copy()


def _not_meant(agent: Agent) -> frozenset[str]:
    """The things the robot saw lying where the command puts one of their kind, another being meant
    (:attr:`Agent.not_meant <seal_cli.sim.agent.Agent.not_meant>`): no evidence of where another lies. Counted as
    seen, the one on the sofa kept the belief of a blanket at the sofa, and "put the blanket on the sofa" on the
    houseboat circled the saloon for 211 m (lead, stop 39); unseen, each look there is a miss.

    So are the things chosen for a name no step left names (the book already brought for "bring me two books"): they
    are no evidence of where the next one of their kind lies. Counted as seen, the book handed over drew the second
    book's belief to the speaker, and the guesthouse's one book took 87 m to give up on (lead, e2e29)."""
    named = {class_key(v) for b in agent.remaining for _, v in b.values}
    done = {i for name, i in agent.chosen.items() if name not in named}
    return frozenset(i for ids in agent.not_meant.values() for i in ids) | done
