"""How far the robot drives to a place (seal_cli/maps/reach.py): around walls, through doors, or not at all, on the
simulator's own free space."""

from __future__ import annotations

import math
from dataclasses import replace
from pathlib import Path

import numpy as np
import pytest

from seal_cli.frames.library import Library
from seal_cli.maps.formats.map_server import load_map
from seal_cli.maps.geometry import OCCUPIED, OccupancyGrid
from seal_cli.maps.navigation import ROBOT_RADIUS, Grid
from seal_cli.maps.reach import drive_lengths, grid_of

GUESTHOUSE = Path(__file__).resolve().parents[2] / "maps" / "guesthouse.yaml"
START = (15.0, 4.0)      # the corridor's east end


def test_a_drive_goes_round_the_walls_through_the_doors() -> None:
    m = load_map(GUESTHOUSE)
    bed_3, bed_4, nope = drive_lengths(m, START, ["bed_3", "bed_4", "no_such_place"])
    # bed_4 (the owner's bedroom) is 5 m away as the crow flies but only through the lounge; bed_3 is 5.7 m away
    assert math.dist(START, m.place("bed_4").at) < math.dist(START, m.place("bed_3").at)
    assert bed_3 < bed_4 and 5.0 < bed_3 < 7.5 and bed_4 > 8.0 and nope == math.inf


def test_a_place_behind_a_closed_wall_is_out_of_reach() -> None:
    m = load_map(GUESTHOUSE)
    cells = np.array(m.grid.cells)
    (low, high), (col, _), _ = m.grid.cell_index(np.array([[13.0, 7.9], [13.0, 9.1]]))
    cells[low:high + 1, col - 2:col + 3] = OCCUPIED     # the lounge's door to the bedroom walled up
    shut = replace(m, grid=OccupancyGrid(cells, m.grid.resolution, m.grid.origin))
    assert drive_lengths(shut, START, ["bed_4"]) == [math.inf]
    assert drive_lengths(shut, START, ["bed_3"]) == drive_lengths(m, START, ["bed_3"])


def test_a_place_is_as_far_as_the_simulator_drives_to_it(library: Library) -> None:
    # the owner's wardrobe stands just behind the corridor's end wall: within arm's reach of the start through the
    # wall, 10 m by the lounge; the ranking and the simulator measure on one grid (Grid.from_map)
    from seal_cli.sim.agent import Agent, scene_from_map
    from seal_cli.sim.policies import make_policy

    m = load_map(GUESTHOUSE)
    agent = Agent(scene_from_map(m, library), library, make_policy("oracle"), rng=np.random.default_rng(0))
    names = [p.name for p in m.places]
    for name, length in zip(names, drive_lengths(m, m.robot.pose, names), strict=True):
        cell = agent.stand_cell(agent.known[name])
        assert cell is not None and length == pytest.approx(float(agent.distances()[cell]), abs=1e-9), name
    near, far = drive_lengths(m, START, ["wardrobe_2", "wardrobe_3"])
    assert math.dist(START, m.place("wardrobe_3").at) < 1.8 and far > 9.5 > 6.0 > near


def test_the_ranking_drives_on_the_free_space_less_the_robots_radius() -> None:
    m = load_map(GUESTHOUSE)
    grid = grid_of(m)
    assert grid is grid_of(m)            # built once for a map asked about again
    assert grid.free.sum() < np.asarray(m.grid.free_mask).sum()
    assert np.array_equal(grid.free, Grid.from_map(m, ROBOT_RADIUS).free)
