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
    point is a frontier until the robot has seen it, and it is looked at from the nearest cell that
    has a line of sight to it (:meth:`frontier`)."""

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
        self.seen = np.zeros(len(self.lattice), dtype=bool)
        self._tree = cKDTree(self.lattice) if len(self.lattice) else None

    def observe(self, agent: Agent, detections: Sequence[Detection]) -> None:
        """Mark the lattice points the robot sees now: only those within the sensor's range (found by a tree, a
        hair wider than the range) are asked (a 410 m map's 2.7 million points each look took 0.3 s)."""
        if self._tree is None:
            return
        pose = agent.world.robot.pose
        near = np.asarray(self._tree.query_ball_point(pose[:2], agent.world.sensor.range * (1 + 1e-9) + 1e-9),
                          dtype=np.intp)
        todo = np.sort(near[~self.seen[near]])
        if len(todo):
            self.seen[todo] = agent.world.sensor.visible(pose, self.lattice[todo])

    def next_view(self, agent: Agent, binding: Binding, target: str) -> View | None:
        field_ = agent.distances()
        cells = agent.grid.free_cells
        costs = field_[cells[:, 0], cells[:, 1]]
        options = container_views(agent, field_, closed_unopened(agent))
        frontier = self.frontier(agent, costs)
        if frontier is not None:
            cost, k, u = frontier
            goal = self.lattice[u]
            options.append((cost, View((int(cells[k, 0]), int(cells[k, 1])), (float(goal[0]), float(goal[1])),
                                       why="the nearest frontier")))
        if not options:
            return None
        return min(options, key=lambda o: o[0])[1]

    def frontier(self, agent: Agent, costs: np.ndarray) -> tuple[float, int, int] | None:
        """The cheapest unseen lattice point to see: (drive in metres, the free cell to see it from,
        the point). Seeing a point costs the drive to the nearest free cell within range of it
        (0.8 of the sensor's) that has a line of sight to it; among equals, the first point by
        index, seen from the first such cell by index. The robot's own cell is never a view: what
        it could see from there it has seen.

        The search runs over candidate cells in order of their drive, asking a tree of the unseen
        points how many lie within range, and the sensor's line of sight only for cells that have
        some; the first cell that sees one settles the cost. So the work grows with the cells
        nearer than the frontier, never with cells × points in range. On a fine grid the candidate
        cells are thinned to about one per 0.25 m (every cell where the grid is that coarse)."""
        from scipy.spatial import cKDTree

        unseen = np.flatnonzero(~self.seen)
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
        tree = cKDTree(self.lattice[unseen])

        def seen_from(cell: int) -> np.ndarray:
            """Indices (into ``unseen``) of the unseen points within range of a cell it can see."""
            near = np.asarray(sorted(tree.query_ball_point(points[cell], reach)), dtype=np.intp)
            if len(near):
                near = near[sensor.line_of_sight(points[cell], self.lattice[unseen[near]])]
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
