"""The frontier sweep's notion of "seen": a lattice square counts only once every sample of it (the free cells a
thing on the floor may lie in) has been seen, by one look or several."""

from __future__ import annotations

from types import SimpleNamespace

import numpy as np

from seal_cli.maps.geometry import OccupancyGrid
from seal_cli.maps.model import Map, Robot, Sensor
from seal_cli.maps.navigation import Grid
from seal_cli.sensing.model import RangeSensor
from seal_cli.sim.policies.coverage import CoveragePolicy

RES = 0.05


def room_with_a_post() -> SimpleNamespace:
    """A 3 m x 2 m floor at 0.05 m with a post (0.3 m square) in its middle; the robot in the west, seeing 2.5 m all
    round. Stands in for the agent: what :class:`CoveragePolicy` reads of it."""
    xs = np.arange(RES / 2, 3.0, RES)
    ys = np.arange(RES / 2, 2.0, RES)
    every = np.array([(x, y) for x in xs for y in ys])
    post = (np.abs(every[:, 0] - 1.5) < 0.15) & (np.abs(every[:, 1] - 1.0) < 0.15)
    free = every[~post]
    occupancy = OccupancyGrid.from_cells(free, RES, occupied=every[post])
    m = Map("post", (0.0, 0.0, 3.0, 2.0), robot=Robot((0.3, 1.0, 0.0)), sensor=Sensor(range=2.5), grid=occupancy)
    sensor = RangeSensor.on_map(m)
    world = SimpleNamespace(robot=SimpleNamespace(pose=(0.3, 1.0, 0.0)), sensor=sensor)
    grid = Grid.from_points(free, RES, connectivity=8)
    return SimpleNamespace(grid=grid, world=world, scene=SimpleNamespace(map=m),
                           robot_cell=lambda: grid.cell(world.robot.pose))


def test_a_square_whose_centre_is_seen_is_not_seen_while_a_floor_cell_of_it_is_hidden() -> None:
    agent = room_with_a_post()
    sweep = CoveragePolicy()
    sweep.begin(agent)
    sweep.observe(agent, [])
    pose = agent.world.robot.pose
    floor = agent.scene.map.free_centres
    visible = agent.world.sensor.visible(pose, floor)
    _, owner = sweep._tree.query(floor)
    for u in np.flatnonzero(sweep.seen):   # every square marked seen: all its floor is in sight
        assert visible[owner == u].all()
    centre_seen = agent.world.sensor.visible(pose, sweep.lattice)
    edge = [u for u in np.flatnonzero(centre_seen & ~sweep.seen) if (owner == u).any() and visible[owner == u].any()]
    assert edge, "the post's shadow crosses some square whose centre the look sees"
    # the old rule marked those squares seen; from the far side of the post the rest of them comes into sight
    agent.world.robot.pose = (2.7, 1.0, 0.0)
    sweep.observe(agent, [])
    assert sweep.seen[edge].all()
    inside = (np.abs(sweep.lattice[:, 0] - 1.5) > 0.3) | (np.abs(sweep.lattice[:, 1] - 1.0) > 0.3)
    on_floor = np.isin(np.arange(len(sweep.lattice)), owner) & inside
    assert sweep.seen[on_floor & (np.hypot(sweep.lattice[:, 0] - 1.5, sweep.lattice[:, 1] - 1.0) < 1.0)].all()


def test_the_frontier_aims_at_what_is_left_unseen_and_never_from_where_the_robot_stands() -> None:
    agent = room_with_a_post()
    sweep = CoveragePolicy()
    sweep.begin(agent)
    sweep.observe(agent, [])
    field_ = agent.grid.distances(agent.grid.cell(agent.world.robot.pose))
    cells = agent.grid.free_cells
    costs = field_[cells[:, 0], cells[:, 1]]
    cost, k, u = sweep.frontier(agent, costs)   # type: ignore[misc]
    assert not sweep.sample_seen[u]
    here = agent.grid.cell(agent.world.robot.pose)
    assert (int(cells[k, 0]), int(cells[k, 1])) != here
    at = agent.grid.free_points[k]
    assert agent.world.sensor.line_of_sight(at, sweep.samples[u:u + 1])[0]
    assert np.hypot(*(sweep.samples[u] - at)) <= 0.8 * agent.world.sensor.range
    assert cost == float(costs[k]) > 0
