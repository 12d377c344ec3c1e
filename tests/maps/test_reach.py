"""How far the robot drives to a place (seal_cli/maps/reach.py): around walls, through doors, or not at all."""

from __future__ import annotations

import math
from dataclasses import replace
from pathlib import Path

import numpy as np

from seal_cli.maps.formats.map_server import load_map
from seal_cli.maps.geometry import OCCUPIED, OccupancyGrid
from seal_cli.maps.reach import drive_lengths

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
