"""A tiny hand-made household for the agent, baseline and run tests: one room of 6 m x 4 m."""

from __future__ import annotations

import numpy as np

from seal_cli.frames.library import Library
from seal_cli.maps.geometry import OccupancyGrid
from seal_cli.maps.model import Map, ObjectTruth, Place, Robot, Room, Sensor
from seal_cli.maps.navigation import Grid
from seal_cli.sensing.model import RangeSensor
from seal_cli.sim.agent import Scene
from seal_cli.sim.world import Item, World
from seal_cli.sim.world import Robot as WorldRobot


def kitchen(library: Library, *, apple_in: str = "fridge_1", priors: bool = True) -> Scene:
    """Free cells on a 0.25 m lattice over [0, 6] x [0, 4]; a fridge at the east end, a counter at
    the west end, a table in the middle of the north wall, a cabinet by the counter."""
    pts = [(x, y) for x in np.arange(0.5, 5.51, 0.25) for y in np.arange(0.5, 3.01, 0.25)]
    grid = Grid.from_points(pts, 0.25, connectivity=4)
    places = [("fridge_1", "fridge", (5.9, 1.0), True), ("counter_1", "counter_top", (0.1, 1.0), False),
              ("table_1", "dining_table", (3.0, 3.9), False), ("cabinet_1", "cabinet", (0.1, 2.5), True),
              ("microwave_1", "microwave", (0.1, 3.5), True)]
    items = [Item(n, c, at, movable=False, receptacle=True, openable=o, toggleable=c == "microwave")
             for n, c, at, o in places]
    spot = {"fridge_1": (5.8, 1.1), "counter_1": (0.2, 1.1), "table_1": (3.0, 3.8), "cabinet_1": (0.2, 2.5)}
    items += [Item("apple_1", "apple", spot[apple_in], parent=apple_in),
              Item("knife_1", "knife", (0.2, 0.9), parent="counter_1"),
              Item("mug_1", "mug", (3.2, 3.8), parent="table_1", receptacle=True)]
    world = World(items, WorldRobot(pose=(3.0, 1.0, 0.0)), taxonomy=library.taxonomy, reach=1.5,
                  sensor=RangeSensor(Sensor(range=1.5)))
    occupancy = OccupancyGrid.from_cells(pts, 0.25)
    m = Map("tiny_kitchen", (-0.5, -0.5, 6.5, 4.5), rooms=(Room.box("kitchen", -0.5, -0.5, 6.5, 4.5),),
            places=tuple(Place(n, c, at, openable=o, reach=0.75) for n, c, at, o in places),
            priors={"apple": {"fridge": 0.6, "counter_top": 0.3}, "knife": {"counter_top": 0.8},
                    "mug": {"dining_table": 0.7}} if priors else {},
            objects=tuple(ObjectTruth(i.key, i.at, i.parent) for i in items if i.movable),
            robot=Robot((3.0, 1.0, 0.0)), sensor=Sensor(range=0.75), grid=occupancy)
    return Scene(world, m, grid, tuple(sorted({i.key for i in items})), "tiny kitchen")
