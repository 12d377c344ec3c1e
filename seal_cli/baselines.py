"""The searchers SeFM is measured against, on the same episodes and the same execution machinery.

- :class:`ObjectOnlyPolicy` (SLiM-style, after Zeng et al.): one belief per object class, from
  the same priors and observations, searched for one at a time in plan order: it looks where the
  *object* the current frame needs is believed to be, with no frame relations and no
  precondition context.
- :class:`CoveragePolicy`: knows nothing of where things usually are; it goes to the nearest
  frontier of what it has seen (or the nearest receptacle it has not looked into) until what it
  needs is in view.
- :class:`OraclePolicy`: knows where everything is, including what closed receptacles hold, and
  chooses the instances that make the whole remaining plan shortest: a lower bound on the path.
- ``uniform``: SeFM without priors (:class:`~seal_cli.agent.SeFMPolicy` with ``priors=False``).

Every policy answers one question, :meth:`next_view`: from where to look next for what the
current frame needs (see :class:`seal_cli.agent.Policy`).
"""

from __future__ import annotations

import itertools
import math
from collections.abc import Sequence

import numpy as np

from .agent import Agent, Known, SeFMPolicy, View
from .frames import Binding
from .taxonomy import class_key
from .world import Detection

__all__ = ["POLICIES", "CoveragePolicy", "ObjectOnlyPolicy", "OraclePolicy", "make_policy"]


def closed_unopened(agent: Agent) -> list[Known]:
    """Receptacles that are shut and that the robot has not looked into."""
    return [k for k in agent.known.values() if not k.movable and k.openable and k.id not in agent.opened
            and not agent.world.items[k.id].is_open]


def container_views(agent: Agent, field_: np.ndarray, containers: Sequence[Known]) -> list[tuple[float, View]]:
    """(path cost, view) for opening each container from its nearest stand cell."""
    views = []
    for k in containers:
        cell = agent.stand_cell(k, field_)
        if cell is not None and np.isfinite(field_[cell]):
            views.append((float(field_[cell]), View(cell, k.at, open=k.id, why=f"opens {k.id} to look inside")))
    return views


class CoveragePolicy:
    """Go to the nearest frontier of the seen area, or the nearest unopened receptacle.

    What is to be seen is every point of the map within sensor range of free space (things stand
    on furniture, off the free space), on a lattice of half the sensor range at most 0.25 m."""

    name = "coverage"

    def begin(self, agent: Agent) -> None:
        grid = agent.grid
        step = min(0.25, grid.resolution * max(1, round(0.25 / grid.resolution)))
        rng = agent.world.sensor.range
        x0, y0 = grid.free_points.min(axis=0) - rng
        x1, y1 = grid.free_points.max(axis=0) + rng
        xs, ys = np.meshgrid(np.arange(x0, x1 + 1e-9, step), np.arange(y0, y1 + 1e-9, step))
        lattice = np.column_stack([xs.ravel(), ys.ravel()])
        from scipy.spatial import cKDTree

        near, _ = cKDTree(grid.free_points).query(lattice, distance_upper_bound=0.8 * rng)
        self.lattice = lattice[np.isfinite(near)]
        self.tree = cKDTree(grid.free_points)
        self.seen = np.zeros(len(self.lattice), dtype=bool)

    def observe(self, agent: Agent, detections: Sequence[Detection]) -> None:
        todo = np.flatnonzero(~self.seen)
        if len(todo):
            self.seen[todo] = agent.world.sensor.visible(agent.world.robot.pose, self.lattice[todo])

    def next_view(self, agent: Agent, binding: Binding, target: str) -> View | None:
        field_ = agent.distances()
        cells = agent.grid.free_cells
        costs = field_[cells[:, 0], cells[:, 1]]
        options = container_views(agent, field_, closed_unopened(agent))
        here = agent.robot_cell()
        while len(unseen := np.flatnonzero(~self.seen)):
            rng = 0.8 * agent.world.sensor.range
            # the cost of seeing a lattice point: the drive to the nearest cell within range of it
            groups = self.tree.query_ball_point(self.lattice[unseen], rng)
            best: tuple[float, int, int] | None = None
            for u, group in zip(unseen, groups, strict=True):
                if not group:
                    continue
                g = np.asarray(group)
                k = int(g[int(np.argmin(costs[g]))])
                if np.isfinite(costs[k]) and (best is None or costs[k] < best[0]):
                    best = (float(costs[k]), int(u), int(k))
            if best is not None:
                cost, ui, ki = best
                cell = (int(cells[ki, 0]), int(cells[ki, 1]))
                goal = self.lattice[ui]
                if cell == here:
                    self.seen[ui] = True  # in view from here yet unseen: never to be seen
                    continue
                options.append((cost, View(cell, (float(goal[0]), float(goal[1])), why="the nearest frontier")))
            break
        if not options:
            return None
        return min(options, key=lambda o: o[0])[1]


class OraclePolicy:
    """Knows the world; picks the instances that make the remaining plan shortest."""

    name = "oracle"
    oracle = True
    max_assignments = 2000
    per_class = 6

    def begin(self, agent: Agent) -> None:
        pass

    def observe(self, agent: Agent, detections: Sequence[Detection]) -> None:
        pass

    def next_view(self, agent: Agent, binding: Binding, target: str) -> View | None:
        return None  # it knows every instance there is; if none will do, there is none

    def choose(self, agent: Agent, cls: str, candidates: Sequence[Known]) -> str | None:
        targets = _navigation_targets(agent)
        if not targets or targets[0] != cls:
            targets = [cls, *targets]
        held = agent.held()
        options: dict[str, list[Known]] = {}
        field_ = agent.distances()
        for t in dict.fromkeys(targets):
            if held is not None and held.key == t and t != cls:
                continue
            pool = list(candidates) if t == cls else [k for k in agent.instances(t) if k.id not in agent.unreachable]
            costed = [(float(field_[c]), k) for k in pool if (c := agent.stand_cell(k, field_)) is not None]
            costed.sort(key=lambda ck: ck[0])
            if costed:
                options[t] = [k for _, k in costed[: self.per_class]]
        if cls not in options:
            return None
        classes = list(options)
        best: tuple[float, str] | None = None
        for n, combo in enumerate(itertools.product(*(options[c] for c in classes))):
            if n >= self.max_assignments:
                break
            chosen = dict(zip(classes, combo, strict=True))
            cost = _tour(agent, [chosen[t] for t in targets if t in chosen])
            if best is None or cost < best[0]:
                best = (cost, chosen[cls].id)
        return best[1] if best else None


def _navigation_targets(agent: Agent) -> list[str]:
    """The classes the remaining plan will drive to, in order."""
    out: list[str] = []
    for binding in getattr(agent, "remaining", []):
        for action in binding.actions:
            if action.name == "navigate":
                out.append(class_key(action.args[0]))
    return out


def _tour(agent: Agent, stops: Sequence[Known]) -> float:
    """Metres to visit the stops in order, each at its stand cell nearest the previous one."""
    cell = agent.robot_cell()
    total = 0.0
    for k in stops:
        cells = agent.stand_cells(k)
        if not len(cells):
            return math.inf
        field_ = agent.grid.distances(cell)
        costs = field_[cells[:, 0], cells[:, 1]]
        i = int(np.argmin(costs))
        if not np.isfinite(costs[i]):
            return math.inf
        total += float(costs[i])
        cell = (int(cells[i, 0]), int(cells[i, 1]))
    return total


class ObjectOnlyPolicy(SeFMPolicy):
    """SLiM-style search: the belief of the object the current frame needs, and nothing else."""

    name = "object_only"
    use_frames = False


POLICIES = ("sefm", "object_only", "coverage", "oracle")


def make_policy(name: str, particles: int = 200) -> SeFMPolicy | CoveragePolicy | OraclePolicy:
    """A fresh policy by name: sefm, object_only, coverage, oracle or uniform."""
    if name == "sefm":
        return SeFMPolicy(particles=particles)
    if name == "uniform":
        policy = SeFMPolicy(particles=particles, priors=False)
        policy.name = "uniform"
        return policy
    if name == "object_only":
        return ObjectOnlyPolicy(particles=particles)
    if name == "coverage":
        return CoveragePolicy()
    if name == "oracle":
        return OraclePolicy()
    from .errors import SealError

    raise SealError(f"unknown policy {name!r}; known: {', '.join((*POLICIES, 'uniform'))}")
