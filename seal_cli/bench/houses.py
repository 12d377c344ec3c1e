"""Houses for the SeFM tests and benchmarks, drawn in code: walls around box rooms with doorways, the paper's priors.

:func:`second_house` is set up like the paper's Gazebo study (five rooms; cups half in the family
room, half in the bedroom; spoons half in the kitchen, half in the bedroom) but drawn differently
from ``maps/apartment.yaml``: another size, another layout, and a bedroom much larger than the
kitchen (where a bare product of two room-uniform beliefs would put "Stir cup" in the kitchen).

:func:`aws_house` annotates the real occupancy map of the paper's house (AWS RoboMaker small house,
in the shared data) with one of :data:`AWS_LAYOUTS`, the paper's priors and a robot pose.
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from pathlib import Path

import numpy as np
import yaml

from seal_cli.errors import SealError
from seal_cli.fileio import MAX_IMAGE_BYTES, read_bytes
from seal_cli.maps.geometry import OccupancyGrid
from seal_cli.maps.model import Map, ObjectTruth, Place, Robot, Room, Sensor

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


# -- the paper's own house: the AWS RoboMaker small house's occupancy map, annotated here ------------------
AWS_LAYOUTS: dict[str, dict[str, tuple[float, float, float, float]]] = {
    # the bedroom (the bed) top left; the room below it the family room; the gym top middle is in no room
    "wings": {"bedroom": (-9.4, -1.5, -2.45, 3.1), "family_room": (-9.4, -5.7, -2.45, -1.5),
              "living_room": (-2.45, -5.7, 4.8, 2.4), "dining_room": (4.8, -0.3, 9.5, 3.1),
              "kitchen": (4.8, -5.8, 9.5, -0.3)},
    # the whole left wing a bedroom (50 m², the kitchen 20 m²); the gym top middle the family room
    "north_family": {"bedroom": (-9.4, -5.7, -2.45, 3.1), "family_room": (-2.45, 2.4, 4.8, 5.7),
                     "living_room": (-2.45, -5.7, 4.8, 2.4), "dining_room": (4.8, -0.3, 9.5, 3.1),
                     "kitchen": (4.8, -5.8, 9.5, -0.3)},
    # the right wing one kitchen; dining top middle; family room the middle; living room bottom left
    "kitchen_diner": {"bedroom": (-9.4, -1.5, -2.45, 3.1), "living_room": (-9.4, -5.7, -2.45, -1.5),
                      "family_room": (-2.45, -5.7, 4.8, 2.4), "dining_room": (-2.45, 2.4, 4.8, 5.7),
                      "kitchen": (4.8, -5.8, 9.5, 3.1)},
}
"""Room boxes for the AWS house (walls from the map: the left wing x < −2.45, the right wing x > 4.8, a
partial wall at y = −1.5 in the left wing, a gym north of the middle): three plausible readings."""

AWS_OBJECTS = ({"class": "spoon", "at": [8.6, -3.4]}, {"class": "cup", "at": [-7.5, 2.5]})
"""The spoon by the cooking bench (kitchen), the cup by the nightstand (bedroom)."""

AWS_TRAJECTORY = [(1.5, -4.0), (4.0, -3.0), (6.5, -2.5), (7.5, -3.5), (6.5, -2.0), (3.0, -0.5), (0.0, 0.5),
                  (-3.5, 0.5), (-5.5, 0.0), (-7.5, 0.0), (-8.0, 0.8), (-7.2, 0.6)]
"""Through the kitchen (four looks at the spoon), across the living room into the bedroom (three at the cup)."""


AWS_PLACES = (
    {"name": "bed_1", "class": "bed", "at": [-6.17, 2.03], "reach": 1.5},
    {"name": "nightstand_1", "class": "nightstand", "at": [-7.73, 2.86]},
    {"name": "nightstand_2", "class": "nightstand", "at": [-4.41, 2.86]},
    {"name": "desk_1", "class": "desk", "at": [-8.99, 2.06]},
    {"name": "wardrobe_1", "class": "wardrobe", "at": [-3.15, 2.48], "openable": True},
    {"name": "coffee_table_1", "class": "coffee_table", "at": [1.51, -1.73]},
    {"name": "sofa_1", "class": "sofa", "at": [0.33, -1.9], "reach": 1.2},
    {"name": "tv_stand_1", "class": "tv_stand", "at": [0.63, -5.18]},
    {"name": "tv_stand_2", "class": "tv_stand", "at": [-6.2, -1.39]},
    {"name": "dining_table_1", "class": "dining_table", "at": [6.55, 0.95], "reach": 1.2},
    {"name": "fridge_1", "class": "fridge", "at": [8.7, -1.03], "openable": True},
    {"name": "counter_1", "class": "counter", "at": [9.04, -3.35]},
    {"name": "cabinet_1", "class": "cabinet", "at": [8.0, -3.84], "openable": True},
    {"name": "trash_can_1", "class": "trash_can", "at": [2.36, -0.8]},
)
"""The furniture of the AWS house's world file (``world_models.json``: Bed_01, NightStand_01, ReadingDesk_01,
Wardrobe_01, CoffeeTable_01, SofaC_01, TVCabinet_01, KitchenTable_01, Refrigerator_01, CookingBench_01,
KitchenCabinet_01, Trash_01) at the positions given there."""

AWS_PEOPLE = ({"name": "Carla", "room": "kitchen"}, {"name": "Dev", "at": [-5.0, 0.0]})
"""Two people: Carla somewhere in the kitchen, Dev in the left wing (the bedroom of ``wings``)."""

AWS_ITEMS = ({"class": "apple", "in": "fridge_1"}, {"class": "book", "at": [-8.6, 2.0], "in": "desk_1"})
"""Two more things for the end-to-end commands: an apple in the (closed) fridge, a book on the desk."""


def aws_house(folder: Path, data: Path, layout: str, robot: tuple[float, float, float], *,
              priors: Mapping[str, Mapping[str, float]] = PAPER_PRIORS,
              objects: Sequence[Mapping[str, object]] = AWS_OBJECTS,
              places: Sequence[Mapping[str, object]] = (), name: str | None = None,
              people: Sequence[Mapping[str, object]] = ()) -> Path:
    """Write an annotated map of the AWS house into ``folder`` (the image stays where the shared data is:
    ``data`` is the shared data folder, ``../shared/data`` from a checkout); by default the paper's
    priors and objects and no places (the context suite gives :data:`AWS_CONTEXT_PRIORS`,
    :data:`AWS_CONTEXT_PLACES` and :data:`CONTEXT_OBJECTS`; the end-to-end suite :data:`AWS_PLACES`,
    :data:`AWS_PEOPLE` and :data:`AWS_ITEMS`)."""
    name = name or f"aws_{layout}"
    image = data / "maps" / "aws_small_house" / "map.pgm"
    if not image.exists():
        raise SealError(f"{image}: the AWS small house's map is not there (--data names the shared data folder)")
    read_bytes(image, MAX_IMAGE_BYTES, "map image")  # refused here, by its own name, not in a map written for it
    doc = {"image": str(image.resolve()), "resolution": 0.05,
           "origin": [-12.5, -12.5, 0.0], "negate": 0, "occupied_thresh": 0.65, "free_thresh": 0.196,
           "name": name, "rooms": [{"name": n, "box": list(b)} for n, b in AWS_LAYOUTS[layout].items()],
           "places": [dict(p) for p in places], "priors": {c: dict(m) for c, m in priors.items()},
           "objects": [dict(o) for o in objects], "robot": {"pose": list(robot)},
           "sensor": {"range": 5.0, "fov": 360}}
    if people:
        doc["people"] = [dict(p) for p in people]
    path = folder / f"{name}.yaml"
    path.write_text(yaml.safe_dump(doc, sort_keys=False))
    return path


# -- the context suite's things: two or more a command needs, whose priors overlap ---------------------------
CONTEXT_PRIORS = {**PAPER_PRIORS, "mug": {"kitchen": 0.4, "dining_room": 0.3, "family_room": 0.3},
                  "kettle": {"kitchen": 0.5, "dining_room": 0.5}}
"""The paper's cup and spoon (the bedroom holds both) and two more: mugs in the kitchen (with the spoons),
the dining room or the family room (with the cups); kettles in the kitchen or the dining room (with the mugs)."""

CONTEXT_OBJECTS = ({"class": "spoon", "at": [0.0, 0.0]}, {"class": "cup", "at": [0.0, 0.0]},
                   {"class": "mug", "at": [0.0, 0.0]}, {"class": "kettle", "at": [0.0, 0.0]})
"""One thing of each class; the suite draws where each is from its prior, so the points here are placeholders."""

AWS_CONTEXT_PLACES = ({"name": "dining_table_1", "class": "dining_table", "at": [7.0, 1.4]},
                      {"name": "bed_1", "class": "bed", "at": [-7.6, 1.5]},
                      {"name": "sofa_1", "class": "sofa", "at": [-6.0, -3.6]},
                      {"name": "counter_1", "class": "counter", "at": [8.6, -3.4]})
"""Furniture for the AWS house's "wings" reading: the dining table, the bed, a sofa in the family room,
the cooking bench."""

AWS_CONTEXT_STARTS = ((1.5, -4.0, 0.0), (0.0, 1.5, 0.0), (-3.5, 0.5, 0.0))
"""The living room's south and north ends, and the door of the bedroom wing."""


def cottage() -> Map:
    """14 m × 10 m drawn for the context suite: a hall down the middle (the living room) with two rooms
    on each side — bedroom and family room to the west, dining room and kitchen to the east, the
    kitchen and the dining room joined by a door too. The robot starts in the hall."""
    rooms = {"bedroom": (0.0, 0.0, 6.0, 5.0), "family_room": (0.0, 5.0, 6.0, 10.0),
             "living_room": (6.0, 0.0, 9.0, 10.0), "dining_room": (9.0, 0.0, 14.0, 5.0),
             "kitchen": (9.0, 5.0, 14.0, 10.0)}
    doors = [(6.0, 2.5), (6.0, 7.5), (9.0, 2.5), (9.0, 7.5), (11.5, 5.0)]
    places = (Place("dining_table_1", "dining_table", (11.5, 2.5)), Place("sink_1", "sink", (13.4, 9.4)),
              Place("bed_1", "bed", (2.0, 2.5)), Place("sofa_1", "sofa", (2.0, 8.5)))
    objects = tuple(ObjectTruth(str(o["class"]), (7.5, 5.0)) for o in CONTEXT_OBJECTS)
    return walled_house("cottage", (14.0, 10.0), rooms, doors, objects=objects, places=places,
                        robot=(7.5, 1.0, 0.0), priors=CONTEXT_PRIORS,
                        furniture=((1.0, 1.8, 3.0, 3.2), (12.0, 1.8, 13.0, 3.2)))


COTTAGE_STARTS = ((7.5, 1.0, 0.0), (7.5, 9.0, 0.0), (12.0, 7.0, 0.0))
"""The hall's south and north ends, and the kitchen."""


def mews() -> Map:
    """16 m × 10 m, drawn by search26 for the context suite after the three houses gave few cases where frame context
    changes the first look (docs/benchmarks.md, "search26"), before any policy was run on it: a through-lounge (the
    living room) along the south with the kitchen at its west end and the family room at its east end, the bedroom
    off its middle to the north, a dining room behind the kitchen and a study (no thing's prior names it) behind the
    family room. The priors are the context suite's (:data:`CONTEXT_PRIORS`: the paper's spoons and cups, mugs and
    kettles), as on every house drawn for it."""
    rooms = {"kitchen": (0.0, 0.0, 5.0, 6.0), "living_room": (5.0, 0.0, 11.0, 6.0),
             "family_room": (11.0, 0.0, 16.0, 6.0), "dining_room": (0.0, 6.0, 4.0, 10.0),
             "bedroom": (4.0, 6.0, 12.0, 10.0), "study": (12.0, 6.0, 16.0, 10.0)}
    doors = [(5.0, 3.0), (11.0, 3.0), (8.0, 6.0), (2.0, 6.0), (14.0, 6.0)]
    places = (Place("counter_1", "counter", (0.6, 3.0)), Place("coffee_table_1", "coffee_table", (8.0, 2.0)),
              Place("sofa_1", "sofa", (15.3, 3.0)), Place("dining_table_1", "dining_table", (2.0, 8.0)),
              Place("bed_1", "bed", (6.0, 8.5)), Place("desk_1", "desk", (15.3, 9.3)))
    objects = tuple(ObjectTruth(str(o["class"]), (8.0, 3.0)) for o in CONTEXT_OBJECTS)
    return walled_house("mews", (16.0, 10.0), rooms, doors, objects=objects, places=places,
                        robot=(8.0, 3.0, 0.0), priors=CONTEXT_PRIORS,
                        furniture=((5.0, 7.5, 7.0, 9.9), (1.3, 7.4, 2.7, 8.6)))


MEWS_STARTS = ((8.0, 3.0, 0.0), (2.5, 1.5, 0.0), (13.5, 1.5, 0.0))
"""The lounge's middle, the kitchen, the family room (the suite's cases start from drawn starts)."""


def bungalow() -> Map:
    """16 m × 11 m, drawn to check the context suite's figures on a house its policies were never run on
    before: three rooms in a row along the south wall (living room, dining room, kitchen), the bedroom
    and a wide family room along the north; the kitchen and the family room are reached only through
    the dining room, the bedroom only from the living room."""
    rooms = {"living_room": (0.0, 0.0, 6.0, 5.0), "dining_room": (6.0, 0.0, 10.0, 5.0),
             "kitchen": (10.0, 0.0, 16.0, 5.0), "bedroom": (0.0, 5.0, 7.0, 11.0),
             "family_room": (7.0, 5.0, 16.0, 11.0)}
    doors = [(6.0, 2.5), (10.0, 2.0), (2.0, 5.0), (8.5, 5.0)]
    places = (Place("coffee_table_1", "coffee_table", (3.0, 2.0)), Place("dining_table_1", "dining_table", (8.0, 2.5)),
              Place("counter_1", "counter", (15.3, 2.5)), Place("bed_1", "bed", (2.0, 9.0)),
              Place("sofa_1", "sofa", (11.5, 8.5)))
    objects = tuple(ObjectTruth(str(o["class"]), (3.0, 3.0)) for o in CONTEXT_OBJECTS)
    return walled_house("bungalow", (16.0, 11.0), rooms, doors, objects=objects, places=places,
                        robot=(3.0, 3.5, 0.0), priors=CONTEXT_PRIORS, furniture=((1.0, 9.5, 3.0, 10.8),))


BUNGALOW_STARTS = ((3.0, 3.5, 0.0), (8.0, 1.0, 0.0), (13.0, 9.0, 0.0))
"""The living room, the dining room's south side, the family room's east end."""


def ranch() -> Map:
    """18 m × 10 m, drawn for search13's held-out check before any policy was run on it: a living room in the
    south-west, a galley kitchen and a short hallway between it and the dining room (the kitchen opens
    wide onto the dining room, two doors side by side), the bedroom north of the living room, the family
    room north of the hallway and a bathroom (no thing's prior names it) beyond the family room."""
    rooms = {"living_room": (0.0, 0.0, 7.0, 6.0), "kitchen": (7.0, 0.0, 12.0, 4.0), "hallway": (7.0, 4.0, 12.0, 6.0),
             "dining_room": (12.0, 0.0, 18.0, 6.0), "bedroom": (0.0, 6.0, 6.0, 10.0),
             "family_room": (6.0, 6.0, 13.0, 10.0), "bathroom": (13.0, 6.0, 18.0, 10.0)}
    doors = [(7.0, 2.0), (7.0, 5.0), (12.0, 1.0), (12.0, 3.0), (12.0, 5.0), (3.0, 6.0), (9.5, 6.0), (13.0, 8.0)]
    places = (Place("coffee_table_1", "coffee_table", (3.5, 2.5)), Place("counter_1", "counter", (9.5, 0.5)),
              Place("dining_table_1", "dining_table", (15.0, 3.0)), Place("bed_1", "bed", (3.0, 8.5)),
              Place("sofa_1", "sofa", (9.5, 9.3)))
    objects = tuple(ObjectTruth(str(o["class"]), (3.0, 3.0)) for o in CONTEXT_OBJECTS)
    return walled_house("ranch", (18.0, 10.0), rooms, doors, objects=objects, places=places,
                        robot=(1.5, 1.5, 0.0), priors=CONTEXT_PRIORS,
                        furniture=((2.0, 9.0, 4.0, 9.9), (14.0, 2.3, 16.0, 3.7)))


RANCH_STARTS = ((1.5, 1.5, 0.0), (9.5, 5.0, 0.0), (16.5, 8.0, 0.0))
"""The living room's south-west corner, the hallway, the bathroom."""


def longhouse() -> Map:
    """20 m × 12 m, drawn by search16 for a held-out check before any policy was run on it: a hallway the whole
    length of the house, three rooms south of it (kitchen, dining room, living room, west to east; the kitchen
    and the dining room joined by a door too) and three north (bedroom, family room and a study no thing's prior
    names). The bedroom, where both cups and spoons may be, is the far west end of the north side; the
    kitchen, with the spoons and mugs, the far west of the south."""
    rooms = {"kitchen": (0.0, 0.0, 6.0, 5.0), "dining_room": (6.0, 0.0, 11.0, 5.0),
             "living_room": (11.0, 0.0, 20.0, 5.0), "hallway": (0.0, 5.0, 20.0, 7.0),
             "bedroom": (0.0, 7.0, 8.0, 12.0), "family_room": (8.0, 7.0, 14.0, 12.0),
             "study": (14.0, 7.0, 20.0, 12.0)}
    doors = [(3.0, 5.0), (6.0, 2.5), (8.5, 5.0), (15.0, 5.0), (4.0, 7.0), (11.0, 7.0), (17.0, 7.0)]
    places = (Place("counter_1", "counter", (0.6, 2.5)), Place("dining_table_1", "dining_table", (8.5, 2.5)),
              Place("coffee_table_1", "coffee_table", (15.5, 2.5)), Place("bed_1", "bed", (2.0, 10.5)),
              Place("sofa_1", "sofa", (11.0, 11.3)), Place("desk_1", "desk", (18.5, 11.3)))
    objects = tuple(ObjectTruth(str(o["class"]), (10.0, 6.0)) for o in CONTEXT_OBJECTS)
    return walled_house("longhouse", (20.0, 12.0), rooms, doors, objects=objects, places=places,
                        robot=(18.0, 2.5, 0.0), priors=CONTEXT_PRIORS,
                        furniture=((1.0, 9.5, 3.0, 11.8), (7.8, 2.0, 9.2, 3.0), (9.5, 11.0, 12.5, 11.8)))


LONGHOUSE_STARTS = ((18.0, 2.5, 0.0), (10.0, 6.0, 0.0), (17.0, 10.0, 0.0))
"""The living room's east end, the middle of the hallway, the study."""


def gallery() -> Map:
    """18 m × 10 m, drawn by search21 for a held-out check before any policy was run on it: a gallery the whole
    depth of the house along its west side, and four rooms east of it in two rows — the kitchen and the dining
    room to the south, the bedroom and the family room to the north. The gallery opens into the kitchen and the
    bedroom; the kitchen into the dining room; the family room only from the dining room (the bedroom and the
    family room share a wall and no door), so the bedroom's cups and the family room's are far apart by path."""
    rooms = {"gallery": (0.0, 0.0, 3.0, 10.0), "kitchen": (3.0, 0.0, 10.0, 5.0), "dining_room": (10.0, 0.0, 18.0, 5.0),
             "bedroom": (3.0, 5.0, 9.0, 10.0), "family_room": (9.0, 5.0, 18.0, 10.0)}
    doors = [(3.0, 2.5), (3.0, 7.5), (10.0, 2.5), (14.0, 5.0)]
    places = (Place("counter_1", "counter", (9.4, 0.6)), Place("dining_table_1", "dining_table", (14.0, 2.5)),
              Place("bed_1", "bed", (5.0, 9.0)), Place("sofa_1", "sofa", (13.5, 9.4)))
    objects = tuple(ObjectTruth(str(o["class"]), (1.5, 5.0)) for o in CONTEXT_OBJECTS)
    return walled_house("gallery", (18.0, 10.0), rooms, doors, objects=objects, places=places,
                        robot=(1.5, 1.5, 0.0), priors=CONTEXT_PRIORS,
                        furniture=((4.0, 8.2, 6.0, 9.8), (13.3, 2.0, 14.7, 3.0), (12.0, 9.2, 15.0, 9.8)))


GALLERY_STARTS = ((1.5, 1.5, 0.0), (1.5, 8.5, 0.0), (16.5, 8.0, 0.0))
"""The gallery's south and north ends, the family room's east end."""


FARMHOUSE_STARTS = ((4.0, 2.0, 0.0), (3.0, 9.0, 0.0), (15.0, 9.0, 0.0))
"""``maps/farmhouse.yaml`` (drawn by ``maps/make_houses.py``, an unseen house): the kitchen, the living room,
the family room's east end."""

TERRACE_STARTS = ((0.75, 1.0, 0.0), (5.0, 2.5, 0.0), (5.0, 15.0, 0.0))
"""``maps/terrace.yaml`` (an unseen house): the passage by the front door, the living room, the kitchen."""


# -- houses no one drew: a seeded plan, for held-out checks no policy was developed on -------------------------
DRAWN_ROOMS = ("kitchen", "living_room", "family_room", "dining_room", "bedroom", "study")
"""The rooms of a :func:`drawn_house`: the four the context priors name, the living room and a study (no prior)."""

DRAWN_PLACES = {"kitchen": "counter", "living_room": "coffee_table", "family_room": "sofa",
                "dining_room": "dining_table", "bedroom": "bed", "study": "desk"}
"""The piece of furniture each room of a :func:`drawn_house` has (a place, not an obstacle)."""

HELD_OUT_SEEDS = (2701, 2702)
"""The seeds of the held-out houses search27 drew (:func:`held_out_houses`), set before either was drawn."""


def _cuts(rng: np.random.Generator, width: float, least: float = 4.0) -> tuple[float, float]:
    """Two cuts splitting ``width`` into three rooms at least ``least`` wide, on a 0.5 m step."""
    a = float(np.round(rng.uniform(least, width - 2 * least) * 2) / 2)
    b = float(np.round(rng.uniform(a + least, width - least) * 2) / 2)
    return a, b


def drawn_house(seed: int, priors: Mapping[str, Mapping[str, float]] | None = None,
                objects: Sequence[Mapping[str, object]] | None = None) -> Map:
    """A house drawn from ``seed`` alone (no one chose its plan): 14–20 m × 9–12 m, two rows of three box rooms
    (each at least 4 m wide, the rows split at 40–60 % of the depth), the six :data:`DRAWN_ROOMS` in a shuffled
    order, doors on a random spanning tree of the rooms that share a wall (so every room is reached) and each other
    shared wall a door with probability 0.3, each door at its wall's shared middle; one piece of furniture a room
    (:data:`DRAWN_PLACES`). Named ``drawn<seed>``; priors and things: the context suite's by default."""
    rng = np.random.default_rng(seed)
    width = float(np.round(rng.uniform(14.0, 20.0) * 2) / 2)
    height = float(np.round(rng.uniform(9.0, 12.0) * 2) / 2)
    split = float(np.round(height * rng.uniform(0.4, 0.6) * 2) / 2)
    boxes: list[tuple[float, float, float, float]] = []
    for ymin, ymax in ((0.0, split), (split, height)):
        a, b = _cuts(rng, width)
        boxes += [(0.0, ymin, a, ymax), (a, ymin, b, ymax), (b, ymin, width, ymax)]
    names = [DRAWN_ROOMS[i] for i in rng.permutation(len(DRAWN_ROOMS))]
    walls: list[tuple[int, int, tuple[float, float]]] = []
    for row in (0, 3):
        for i in (row, row + 1):
            walls.append((i, i + 1, (boxes[i][2], (boxes[i][1] + boxes[i][3]) / 2)))
    for i in range(3):
        for j in range(3, 6):
            lo, hi = max(boxes[i][0], boxes[j][0]), min(boxes[i][2], boxes[j][2])
            if hi - lo >= 2.0:
                walls.append((i, j, ((lo + hi) / 2, split)))
    order = rng.permutation(len(walls))
    group = list(range(6))

    def root(k: int) -> int:
        while group[k] != k:
            k = group[k]
        return k

    doors = []
    for w in order:
        i, j, at = walls[int(w)]
        if root(i) != root(j):
            group[root(i)] = root(j)
            doors.append(at)
        elif rng.random() < 0.3:
            doors.append(at)
    rooms = dict(zip(names, boxes, strict=True))
    places = []
    for n, (xmin, ymin, xmax, ymax) in rooms.items():
        at = ((xmin + xmax) / 2, ymax - 0.6) if DRAWN_PLACES[n] in ("counter", "bed", "sofa", "desk") else \
            ((xmin + xmax) / 2, (ymin + ymax) / 2)
        places.append(Place(f"{DRAWN_PLACES[n]}_1", DRAWN_PLACES[n], (round(at[0], 2), round(at[1], 2))))
    first = boxes[0]
    robot = ((first[0] + first[2]) / 2, (first[1] + first[3]) / 2, 0.0)
    things = CONTEXT_OBJECTS if objects is None else objects
    return walled_house(f"drawn{seed}", (width, height), rooms, doors,
                        objects=tuple(ObjectTruth(str(o["class"]), robot[:2]) for o in things), places=tuple(places),
                        robot=robot, priors=CONTEXT_PRIORS if priors is None else priors)
