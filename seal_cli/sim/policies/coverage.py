"""``coverage``: the searcher that knows nothing of where things usually are.

It goes to the nearest frontier of what it has seen (or the nearest receptacle it has not looked
into) until what it needs is in view. The helpers for opening receptacles and thinning candidate
cells are shared with the other policies.
"""

from __future__ import annotations

from collections.abc import Sequence

import numpy as np

from seal_cli.frames.model import Binding
from seal_cli.sim.agent import Agent, Known, View
from seal_cli.sim.policies.base import Policy
from seal_cli.sim.world import Detection

__all__ = ["CoveragePolicy", "closed_unopened", "container_views", "one_per_quarter_metre"]


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


def one_per_quarter_metre(cells: np.ndarray, resolution: float) -> np.ndarray:
    """Which of the cells (rows of i, j) lie on a lattice of about 0.25 m: all of them on a grid that
    coarse or coarser, one in ``stride²`` on a finer one. The searchers that pay a shortest-path
    field or a line-of-sight query per candidate cell thin their candidates with it."""
    stride = max(1, round(0.25 / resolution))
    if stride == 1:
        return np.ones(len(cells), dtype=bool)
    return (cells[:, 0] % stride == 0) & (cells[:, 1] % stride == 0)


class CoveragePolicy(Policy):
    """Go to the nearest frontier of the seen area, or the nearest unopened receptacle.

    What is to be seen is every point of the map within sensor range of free space (things stand
    on furniture, off the free space), on a lattice of half the sensor range at most 0.25 m; a
    lattice point is a frontier until the robot has seen the square it stands for, and it is looked
    at from the nearest cell that has a line of sight to what of it is unseen (:meth:`frontier`).

    A square counts as seen when every *sample* of it has been seen, by one look or several: the
    centres of the map's free cells nearest to the lattice point (where a thing on the floor lies:
    the layouts draw a point in a free cell), and the lattice point itself where no free cell holds it
    (a table's top, where a thing on it stands). The sweep of earlier rounds marked a square seen when
    its centre was seen, and on the AWS house at 90° the point 0.08 m from a cup beside the bed was
    seen from 3.6-4.7 m past the bed's corner while the cup was not: the square counted as seen, the
    sweep ended and the run failed (docs/benchmarks.md, "This round (search19)")."""

    name = "coverage"

    def begin(self, agent: Agent) -> None:
        from scipy.spatial import cKDTree

        grid = agent.grid
        step = min(0.25, grid.resolution * max(1, round(0.25 / grid.resolution)))
        rng = agent.world.sensor.range
        x0, y0 = grid.free_points.min(axis=0) - rng
        x1, y1 = grid.free_points.max(axis=0) + rng
        xs, ys = np.meshgrid(np.arange(x0, x1 + 1e-9, step), np.arange(y0, y1 + 1e-9, step))
        lattice = np.column_stack([xs.ravel(), ys.ravel()])
        near, _ = cKDTree(grid.free_points).query(lattice, distance_upper_bound=0.8 * rng)
        self.lattice = lattice[np.isfinite(near)]
        self.seen = np.zeros(len(self.lattice), dtype=bool)
        self._tree = cKDTree(self.lattice) if len(self.lattice) else None
        floor = np.asarray(agent.scene.map.free_centres, dtype=float)
        if self._tree is None:
            self.samples, self.owner = np.zeros((0, 2)), np.zeros(0, dtype=np.intp)
        else:
            _, floor_owner = self._tree.query(floor)
            on_floor = agent.scene.map.free_index(self.lattice) >= 0
            bare = np.flatnonzero(~on_floor)
            self.samples = np.concatenate([floor, self.lattice[bare]])
            self.owner = np.concatenate([np.asarray(floor_owner, dtype=np.intp), bare])
        """Every sample (rows of x, y) and the lattice point whose square it is in."""
        self.sample_seen = np.zeros(len(self.samples), dtype=bool)
        self._left = np.bincount(self.owner, minlength=len(self.lattice))
        """Per lattice point, how many of its samples are not seen yet."""
        self._sample_tree = cKDTree(self.samples) if len(self.samples) else None

    def observe(self, agent: Agent, detections: Sequence[Detection]) -> None:
        """Mark the samples the robot sees now, and the lattice points whose every sample is seen: only the samples
        within the sensor's range (found by a tree, a hair wider than the range) are asked (a 410 m map's 2.7
        million points each look took 0.3 s)."""
        if self._sample_tree is None:
            return
        pose = agent.world.robot.pose
        near = np.asarray(self._sample_tree.query_ball_point(pose[:2], agent.world.sensor.range * (1 + 1e-9) + 1e-9),
                          dtype=np.intp)
        todo = np.sort(near[~self.sample_seen[near]])
        if len(todo):
            fresh = todo[agent.world.sensor.visible(pose, self.samples[todo])]
            self.sample_seen[fresh] = True
            if len(fresh):
                self._left -= np.bincount(self.owner[fresh], minlength=len(self.lattice))
                self.seen = self._left == 0

    def next_view(self, agent: Agent, binding: Binding, target: str) -> View | None:
        field_ = agent.distances()
        cells = agent.grid.free_cells
        costs = field_[cells[:, 0], cells[:, 1]]
        options = container_views(agent, field_, closed_unopened(agent))
        frontier = self.frontier(agent, costs)
        if frontier is not None:
            cost, k, u = frontier
            goal = self.samples[u]
            options.append((cost, View((int(cells[k, 0]), int(cells[k, 1])), (float(goal[0]), float(goal[1])),
                                       why="the nearest frontier")))
        if not options:
            return None
        return min(options, key=lambda o: o[0])[1]

    def frontier(self, agent: Agent, costs: np.ndarray) -> tuple[float, int, int] | None:
        """The cheapest unseen sample to see: (drive in metres, the free cell to see it from, the
        sample, an index into :attr:`samples`). Seeing a sample costs the drive to the nearest free cell
        within range of it (0.8 of the sensor's) that has a line of sight to it; among equals, the first
        sample by index, seen from the first such cell by index. The robot's own cell is never a view:
        what it could see from there it has seen.

        The search runs over candidate cells in order of their drive, asking a tree of the unseen
        samples how many lie within range, and the sensor's line of sight only for cells that have
        some; the first cell that sees one settles the cost. So the work grows with the cells
        nearer than the frontier, never with cells × samples in range. On a fine grid the candidate
        cells are thinned to about one per 0.25 m (every cell where the grid is that coarse)."""
        from scipy.spatial import cKDTree

        unseen = np.flatnonzero(~self.sample_seen)
        if not len(unseen):
            return None
        reach = 0.8 * agent.world.sensor.range
        sensor = agent.world.sensor
        grid = agent.grid
        points, cells = grid.free_points, grid.free_cells
        here = agent.robot_cell()
        candidate = np.isfinite(costs) & ~((cells[:, 0] == here[0]) & (cells[:, 1] == here[1]))
        candidate &= one_per_quarter_metre(cells, grid.resolution)
        order = np.flatnonzero(candidate)
        order = order[np.argsort(costs[order], kind="stable")]
        tree = cKDTree(self.samples[unseen])

        def seen_from(cell: int) -> np.ndarray:
            """Indices (into ``unseen``) of the unseen samples within range of a cell it can see."""
            near = np.asarray(sorted(tree.query_ball_point(points[cell], reach)), dtype=np.intp)
            if len(near):
                near = near[sensor.line_of_sight(points[cell], self.samples[unseen[near]])]
            return near

        first: int | None = None
        for chunk in np.array_split(order, max(1, len(order) // 2048)) if len(order) else []:
            counts = tree.query_ball_point(points[chunk], reach, return_length=True)
            for cell in chunk[np.flatnonzero(counts)]:
                if len(seen_from(int(cell))):
                    first = int(cell)
                    break
            if first is not None:
                break
        if first is None:
            return None
        cost = float(costs[first])
        tied = order[costs[order] == cost]
        views = {int(c): seen_from(int(c)) for c in tied}
        u = min(int(v.min()) for v in views.values() if len(v))
        k = min(c for c, v in views.items() if u in set(v.tolist()))
        return cost, k, int(unseen[u])
