"""Houses for the SeFM tests, drawn in code: walls around box rooms with doorways, the paper's priors.

:func:`second_house` is set up like the paper's Gazebo study (five rooms; cups half in the family
room, half in the bedroom; spoons half in the kitchen, half in the bedroom) but drawn differently
from ``maps/apartment.yaml``: another size, another layout, and a bedroom much larger than the
kitchen (where a bare product of two room-uniform beliefs would put "Stir cup" in the kitchen).
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence

import numpy as np

from seal_cli.geometry import OccupancyGrid
from seal_cli.maps import Map, ObjectTruth, Place, Robot, Room, Sensor

PAPER_PRIORS = {"cup": {"family_room": 0.5, "bedroom": 0.5}, "spoon": {"kitchen": 0.5, "bedroom": 0.5}}


def walled_house(name: str, size: tuple[float, float], rooms: Mapping[str, tuple[float, float, float, float]],
                 doors: Sequence[tuple[float, float]], *, objects: Sequence[ObjectTruth] = (),
                 places: Sequence[Place] = (), robot: tuple[float, float, float] = (0.0, 0.0, 0.0),
                 priors: Mapping[str, Mapping[str, float]] = PAPER_PRIORS, resolution: float = 0.1,
                 furniture: Sequence[tuple[float, float, float, float]] = ()) -> Map:
    """A house of ``size`` (metres, from the origin) whose rooms are boxes with 0.1 m walls on their
    edges, cut by 1 m doorways centred on ``doors``; ``furniture`` boxes are occupied too."""
    width, height = size
    cols, rows = int(round(width / resolution)), int(round(height / resolution))
    ys, xs = (np.mgrid[0:rows, 0:cols] + 0.5) * resolution
    occupied = (xs < resolution) | (ys < resolution) | (xs > width - resolution) | (ys > height - resolution)
    for xmin, ymin, xmax, ymax in rooms.values():
        inside = (xs >= xmin - 0.06) & (xs <= xmax + 0.06) & (ys >= ymin - 0.06) & (ys <= ymax + 0.06)
        edge = (np.abs(xs - xmin) < 0.06) | (np.abs(xs - xmax) < 0.06) | (np.abs(ys - ymin) < 0.06) | (
            np.abs(ys - ymax) < 0.06)
        occupied |= inside & edge
    for x, y in doors:
        occupied &= ~((np.abs(xs - x) < 0.5) & (np.abs(ys - y) < 0.5))
    for xmin, ymin, xmax, ymax in furniture:
        occupied |= (xs >= xmin) & (xs <= xmax) & (ys >= ymin) & (ys <= ymax)
    grid = OccupancyGrid.from_masks(~occupied, resolution, (0.0, 0.0, 0.0), occupied)
    return Map(name, (0.0, 0.0, width, height), tuple(Room.box(n, *box) for n, box in rooms.items()),
               tuple(places), dict(priors), tuple(objects), Robot(robot), Sensor(), grid)


def second_house() -> Map:
    """16 m × 12 m: a small kitchen top left, a large bedroom bottom right, the robot in the hall."""
    rooms = {"kitchen": (0.0, 8.0, 5.0, 12.0),        # 20 m²
             "dining_room": (5.0, 8.0, 10.0, 12.0),
             "family_room": (10.0, 7.0, 16.0, 12.0),
             "living_room": (0.0, 0.0, 6.0, 8.0),
             "bedroom": (9.0, 0.0, 16.0, 7.0)}        # 49 m²
    doors = [(2.5, 8.0), (5.0, 10.0), (7.5, 8.0), (10.0, 9.5), (15.0, 7.0), (6.0, 4.0)]
    places = (Place("counter_1", "counter", (4.5, 11.5)), Place("coffee_table_1", "coffee_table", (12.0, 9.0)),
              Place("fridge_1", "fridge", (0.5, 11.5), openable=True))
    objects = (ObjectTruth("spoon", (4.3, 11.3), "counter_1"), ObjectTruth("cup", (12.3, 9.2), "coffee_table_1"))
    return walled_house("second_house", (16.0, 12.0), rooms, doors, objects=objects, places=places,
                        robot=(7.5, 2.0, 0.0), furniture=((12.5, 1.0, 14.5, 3.0),))


SECOND_HOUSE_TRAJECTORY = [(7.5, 2.0), (7.5, 6.0), (7.5, 9.5), (3.0, 10.0), (2.0, 9.0), (4.0, 9.5), (7.5, 9.5),
                           (11.0, 9.5), (12.0, 8.0)]
"""From the hall through the dining room into the kitchen (three looks at the spoon: a detector that misses one
look in ten will not miss them all), then into the family room (the cup)."""
