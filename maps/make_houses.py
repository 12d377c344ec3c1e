"""Draw the occupancy images of the example houses ``townhouse.yaml``, ``office_floor.yaml``,
``cafe.yaml`` and ``clinic.yaml``, and of the context suite's unseen houses ``farmhouse.yaml`` and
``terrace.yaml``, the L-shaped ``bungalow.yaml``, ``lodge.yaml``, e2e21's held-out holiday lodge, and
``flat.yaml``, e2e22's held-out long flat, and ``carehome.yaml``, e2e23's held-out care home, and
``student_house.yaml``, e2e24's held-out student house, and ``guesthouse.yaml``, e2e25's held-out bed and
breakfast, and ``studio.yaml``, e2e26's held-out open-plan studio flat, and ``corner_shop.yaml``, e2e27's held-out
corner shop with its back rooms, and ``houseboat.yaml``, e2e28's held-out wide-beam houseboat, and ``library.yaml``, e2e29's held-out
branch library, and ``bakery.yaml``, e2e30's held-out bakery with its bakehouse and back rooms, and ``workshop.yaml``, e2e31's held-out
joinery workshop with its showroom, finishing room and back rooms, and ``school.yaml``, e2e32's held-out primary school
block along one corridor, and ``fitness_club.yaml``, e2e33's held-out fitness club with its sun deck (run once; the PGMs are committed next to this script).

    python maps/make_houses.py          # rewrites maps/<house>.pgm for each of HOUSES

Each house is a plan on paper, as a user would draw their own: the outer walls, the inner walls
(centre lines, each with its doors as gaps), and the solid blocks a laser sees (a car, a server
rack, a bookcase). Walls are 0.15 m thick. Furniture that things stand on (desks, tables, beds,
benches) is left free: the robot sees over it. Pixel values follow ROS map_server: 0 occupied,
254 free, 205 unknown (outside the house); row 0 is the highest y, the lower-left pixel sits at
the house's ``origin``.
"""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path

import numpy as np

RESOLUTION = 0.05
WALL = 0.15
MARGIN = 1.0
FREE, UNKNOWN, OCCUPIED = 254, 205, 0

Segment = tuple[float, float, float, float]


@dataclass(frozen=True)
class House:
    """A house on paper: its outline (xmin, ymin, xmax, ymax), its inner walls (each a centre line
    with its door gaps along it) and its solid blocks (boxes)."""

    name: str
    outline: Segment
    walls: tuple[tuple[Segment, tuple[tuple[float, float], ...]], ...]
    blocks: tuple[Segment, ...] = ()
    cutouts: tuple[Segment, ...] = ()
    """Boxes of the outline that are not the house (an L-shaped plan): left unknown, walled by ``walls``."""

    @property
    def origin(self) -> tuple[float, float]:
        return self.outline[0] - MARGIN, self.outline[1] - MARGIN


COTTAGE = House(
    "townhouse", (0.0, 0.0, 14.0, 10.0),
    walls=(
        ((5.0, 0.0, 5.0, 10.0), ((2.0, 3.0), (7.0, 8.0))),     # garage | hallway, laundry room | hallway
        ((0.0, 5.0, 5.0, 5.0), ()),                            # garage | laundry room
        ((7.0, 0.0, 7.0, 10.0), ((2.0, 3.0), (6.5, 7.5))),     # hallway | bathroom, hallway | study
        ((7.0, 5.0, 14.0, 5.0), ((12.0, 13.0),)),              # bathroom, guest room | study
        ((10.0, 0.0, 10.0, 5.0), ()),                          # bathroom | guest room
    ),
    blocks=(
        (1.0, 1.0, 2.8, 4.0),      # the car in the garage
        (8.0, 9.6, 10.0, 9.925),   # the bookcase against the study's north wall
    ),
)

OFFICE_FLOOR = House(
    "office_floor", (0.0, 0.0, 16.0, 8.0),
    walls=(
        ((4.0, 0.0, 4.0, 8.0), ((3.4, 4.6),)),                  # reception | corridor
        ((4.0, 3.0, 16.0, 3.0), ((6.0, 7.0), (10.0, 11.0), (13.5, 14.5))),  # corridor | break, server room, office
        ((4.0, 5.0, 16.0, 5.0), ((5.0, 6.5), (13.0, 14.0))),   # corridor | open office, meeting room
        ((11.0, 5.0, 11.0, 8.0), ()),                          # open office | meeting room
        ((9.0, 0.0, 9.0, 3.0), ()),                            # break room | server room
        ((12.0, 0.0, 12.0, 3.0), ()),                          # server room | office
    ),
    blocks=(
        (9.3, 0.1, 10.0, 2.2),     # the server rack
        (11.5, 0.1, 11.925, 1.5),  # a cupboard of the server room
    ),
)

CAFE = House(
    "cafe", (0.0, 0.0, 16.0, 10.0),
    walls=(
        ((10.0, 0.0, 10.0, 6.0), ((2.0, 5.0),)),               # seating area | bar: a wide opening
        ((0.0, 6.0, 16.0, 6.0), ((1.0, 2.0), (11.0, 12.0), (14.5, 15.5))),  # restroom; kitchen, office from the bar
        ((3.0, 6.0, 3.0, 10.0), ()),                           # restroom | storeroom
        ((8.0, 6.0, 8.0, 10.0), ((7.0, 8.0),)),                # storeroom | kitchen
        ((13.0, 6.0, 13.0, 10.0), ()),                         # kitchen | office
    ),
    blocks=(
        (5.0, 2.8, 5.4, 3.2),      # a pillar in the seating area
        (3.1, 9.55, 7.9, 9.925),   # the storeroom's shelving rack along its north wall
    ),
)

CLINIC = House(
    "clinic", (0.0, 0.0, 16.0, 10.0),
    walls=(
        ((0.0, 5.0, 16.0, 5.0), ((5.0, 6.0), (8.0, 9.5), (13.0, 14.0))),  # waiting, reception, staff | corridor
        ((7.0, 0.0, 7.0, 5.0), ((1.0, 4.0),)),                 # waiting room | reception: a wide opening
        ((11.0, 0.0, 11.0, 5.0), ()),                          # reception | staff room
        ((0.0, 6.5, 16.0, 6.5), ((1.0, 2.0), (4.5, 5.5), (9.0, 10.0), (13.5, 14.5))),  # corridor | the back rooms
        ((3.0, 6.5, 3.0, 10.0), ()),                           # restroom | exam room
        ((7.5, 6.5, 7.5, 10.0), ()),                           # exam room | treatment room
        ((12.0, 6.5, 12.0, 10.0), ()),                         # treatment room | supply room
    ),
    blocks=(
        (12.1, 9.55, 15.0, 9.925),  # the supply room's shelving rack along its north wall
        (0.1, 0.1, 0.5, 0.5),       # a pot plant in the waiting room's corner
    ),
)

FARMHOUSE = House(
    "farmhouse", (0.0, 0.0, 18.0, 12.0),
    walls=(
        ((8.0, 0.0, 8.0, 6.0), ((2.0, 3.0),)),                 # kitchen | dining room
        ((13.0, 0.0, 13.0, 6.0), ()),                          # dining room | bedroom
        ((0.0, 6.0, 18.0, 6.0), ((2.0, 3.0), (10.0, 11.0), (15.0, 16.0))),  # kitchen, dining, bedroom | north
        ((6.0, 6.0, 6.0, 12.0), ((9.0, 10.0),)),               # living room | family room
    ),
    blocks=(
        (0.1, 4.4, 1.4, 5.9),      # the range cooker in the kitchen's corner
        (17.5, 0.1, 17.925, 2.0),  # the bedroom's wardrobe
    ),
)

TERRACE = House(
    "terrace", (0.0, 0.0, 8.0, 20.0),
    walls=(
        ((1.5, 0.0, 1.5, 20.0), ((2.0, 3.0), (6.5, 7.5), (10.5, 11.5), (14.0, 15.0))),  # passage | the rooms
        ((1.5, 5.0, 8.0, 5.0), ()),                            # living room | bedroom
        ((1.5, 9.0, 8.0, 9.0), ()),                            # bedroom | dining room
        ((1.5, 13.0, 8.0, 13.0), ((5.0, 6.0),)),               # dining room | kitchen
        ((1.5, 16.5, 8.0, 16.5), ((4.0, 5.5),)),               # kitchen | family room (the back extension)
    ),
    blocks=(
        (7.5, 5.1, 7.925, 6.8),    # the bedroom's wardrobe
    ),
)

BUNGALOW = House(
    "bungalow", (0.0, 0.0, 16.0, 12.0),
    walls=(
        ((9.0, 6.0, 9.0, 12.0), ()),                           # the L's inner corner: kitchen | outside
        ((9.0, 6.0, 16.0, 6.0), ()),                           # study, garage | outside
        ((3.0, 0.0, 3.0, 6.0), ((2.5, 3.5),)),                 # hall | corridor
        ((0.0, 6.0, 9.0, 6.0), ((1.0, 2.0), (7.0, 8.0))),      # hall | living room, dining room | kitchen
        ((5.0, 6.0, 5.0, 12.0), ((8.0, 9.0),)),                # living room | kitchen
        ((3.0, 2.4, 12.0, 2.4), ((4.0, 5.0), (7.0, 8.0), (10.0, 11.0))),  # corridor | utility, bathroom, bedroom
        ((3.0, 3.6, 12.0, 3.6), ((4.0, 5.5), (10.0, 11.0))),   # corridor | dining room, study
        ((6.5, 0.0, 6.5, 2.4), ()),                            # utility room | bathroom
        ((9.0, 0.0, 9.0, 2.4), ()),                            # bathroom | bedroom
        ((9.0, 3.6, 9.0, 6.0), ()),                            # dining room | study
        ((12.0, 0.0, 12.0, 6.0), ((2.5, 3.5),)),               # corridor | garage
    ),
    blocks=(
        (13.2, 1.0, 15.2, 5.0),    # the car in the garage
        (0.1, 11.4, 1.2, 11.925),  # the chimney breast in the living room
    ),
    cutouts=((9.0, 6.0, 16.0, 12.0),),
)

LODGE = House(
    "lodge", (0.0, 0.0, 15.0, 9.0),
    walls=(
        ((3.0, 0.0, 3.0, 4.0), ((0.5, 1.5),)),                 # porch | corridor, porch | utility room
        ((0.0, 4.0, 6.0, 4.0), ((1.0, 2.0),)),                 # porch | lounge, utility room | lounge
        ((3.0, 2.0, 15.0, 2.0), ((4.0, 5.0), (7.0, 8.0), (10.5, 11.5), (13.0, 14.0))),  # corridor | the rest
        ((6.0, 2.0, 6.0, 9.0), ((6.0, 7.0),)),                 # utility room | kitchen, lounge | kitchen
        ((10.0, 2.0, 10.0, 9.0), ((7.0, 8.0),)),               # kitchen | bathroom, kitchen | office
        ((10.0, 5.0, 12.5, 5.0), ()),                          # bathroom | office
        ((12.5, 2.0, 12.5, 9.0), ()),                          # bathroom, office | bedroom
    ),
    blocks=(
        (14.5, 6.5, 14.925, 8.8),  # the bedroom's wardrobe against the east wall
    ),
)

FLAT = House(
    "flat", (0.0, 0.0, 20.0, 8.0),
    walls=(
        ((3.0, 0.0, 3.0, 8.0), ((3.7, 4.8),)),                 # hall | corridor (the hall is the whole west end)
        ((3.0, 5.0, 20.0, 5.0), ((5.0, 6.0), (16.0, 17.0))),   # corridor | living room, corridor | kitchen
        ((9.0, 5.0, 9.0, 8.0), ((6.0, 7.0),)),                 # living room | dining room
        ((13.0, 5.0, 13.0, 8.0), ((6.0, 7.0),)),               # dining room | kitchen
        ((3.0, 3.5, 20.0, 3.5), ((4.0, 5.0), (7.5, 8.5), (12.0, 13.0), (17.0, 18.0))),  # corridor | the south rooms
        ((6.0, 0.0, 6.0, 3.5), ()),                            # bathroom | nursery
        ((10.0, 0.0, 10.0, 3.5), ()),                          # nursery | bedroom
        ((15.0, 0.0, 15.0, 3.5), ()),                          # bedroom | study
    ),
    blocks=(
        (3.2, 7.6, 5.0, 7.925),    # the piano against the living room's north wall
        (13.1, 0.1, 14.9, 0.5),    # the bedroom's wardrobe against the south wall
    ),
)

CAREHOME = House(
    "carehome", (0.0, 0.0, 16.0, 10.0),
    walls=(
        ((4.0, 0.0, 4.0, 10.0), ((1.0, 2.0), (4.6, 5.6), (8.0, 9.0))),  # reception | lounge, kitchen | lounge, dining
        ((0.0, 4.0, 4.0, 4.0), ()),                            # reception | kitchen
        ((4.0, 6.0, 10.0, 6.0), ((5.0, 8.0),)),                # lounge | dining room: a 3 m archway
        ((10.0, 0.0, 10.0, 10.0), ((1.5, 3.0), (8.0, 9.0))),   # lounge | garden (the garden door), dining | rose room
        ((10.0, 5.0, 16.0, 5.0), ()),                          # garden | rose room, bathroom (the garden's fence)
        ((13.0, 5.0, 13.0, 10.0), ((8.0, 9.0),)),              # rose room | its en-suite bathroom
    ),
    blocks=(
        (6.5, 0.1, 8.0, 0.5),      # the fireplace against the lounge's south wall
        (1.5, 6.5, 2.5, 8.0),      # the kitchen island
        (14.5, 3.5, 15.9, 4.9),    # the garden shed
    ),
)

STUDENT_HOUSE = House(
    "student_house", (0.0, 0.0, 14.0, 10.0),
    walls=(
        ((3.0, 0.0, 3.0, 5.0), ((3.5, 4.5),)),                 # hall | blue room, hall | corridor
        ((0.0, 5.0, 14.0, 5.0), ((1.0, 2.0), (4.5, 5.5), (8.0, 9.0), (12.0, 13.0))),  # hall, corridor | the north
        ((3.0, 3.0, 14.0, 3.0), ((3.5, 4.3), (6.4, 7.2), (9.2, 10.0), (11.9, 12.7))),  # corridor | four bedrooms
        ((5.75, 0.0, 5.75, 3.0), ()),                          # blue room | green room
        ((8.5, 0.0, 8.5, 3.0), ()),                            # green room | red room
        ((11.25, 0.0, 11.25, 3.0), ()),                        # red room | yellow room
        ((7.0, 5.0, 7.0, 10.0), ((7.5, 8.5),)),                # kitchen | living room
        ((11.0, 5.0, 11.0, 10.0), ()),                         # living room | bathroom
    ),
    blocks=(
        (0.1, 4.2, 0.9, 4.9),      # the boiler cupboard in the hall's north-west corner
        (12.6, 8.0, 13.9, 9.9),    # the bath against the bathroom's east wall
    ),
)

GUESTHOUSE = House(
    "guesthouse", (0.0, 0.0, 16.0, 10.0),
    walls=(
        ((4.0, 0.0, 4.0, 5.0), ((3.3, 4.7),)),                 # reception | twin room, reception | corridor
        ((0.0, 5.0, 16.0, 5.0), ((1.5, 2.5), (4.5, 5.5), (8.0, 9.0), (11.0, 12.0))),  # to dining, kitchen, lounge
        ((4.0, 3.0, 16.0, 3.0), ((5.5, 6.5), (9.5, 10.5), (13.5, 14.5))),  # corridor | twin, double room, bathroom
        ((8.0, 0.0, 8.0, 3.0), ()),                            # twin room | double room
        ((12.0, 0.0, 12.0, 3.0), ()),                          # double room | bathroom
        ((6.0, 5.0, 6.0, 10.0), ((7.0, 8.0),)),                # dining room | kitchen
        ((10.0, 5.0, 10.0, 10.0), ()),                         # kitchen | lounge
        ((13.0, 5.0, 13.0, 10.0), ((8.0, 9.0),)),              # lounge | the owner's bedroom
    ),
    blocks=(
        (3.0, 0.1, 3.9, 1.0),      # the luggage cupboard in the reception's south-east corner
        (14.6, 0.1, 15.9, 2.0),    # the bath against the bathroom's east wall
    ),
)

STUDIO = House(
    "studio", (0.0, 0.0, 12.0, 8.0),
    walls=(
        ((3.0, 0.0, 3.0, 8.0), ((1.0, 2.0),)),                 # hall | the open-plan room; bathroom | it, balcony
        ((0.0, 3.0, 3.0, 3.0), ((1.0, 2.0),)),                 # hall | bathroom
        ((3.0, 6.0, 12.0, 6.0), ((9.0, 10.0),)),               # the open-plan room | balcony (the balcony door)
    ),
    blocks=(
        (7.5, 2.9, 9.5, 3.1),      # the low shelf that half parts the living area from the sleeping area
        (0.1, 7.0, 2.0, 7.9),      # the bath against the bathroom's north wall
    ),
)

CORNER_SHOP = House(
    "corner_shop", (0.0, 0.0, 14.0, 12.0),
    walls=(
        ((0.0, 10.0, 14.0, 10.0), ((5.0, 6.0),)),              # the back rooms | the back yard (the kitchen's door)
        ((8.0, 0.0, 8.0, 10.0), ((2.0, 3.0), (8.0, 9.0))),     # shop | stockroom, kitchen | office
        ((8.0, 5.0, 14.0, 5.0), ((10.0, 11.0),)),              # stockroom | office
        ((0.0, 6.0, 8.0, 6.0), ((5.0, 6.0),)),                 # shop | bathroom, kitchen (the door behind the till)
        ((3.0, 6.0, 3.0, 10.0), ((7.0, 8.0),)),                # bathroom | kitchen
    ),
    blocks=(
        (1.0, 2.0, 1.4, 4.5),      # the shop's west aisle of shelving
        (3.6, 2.0, 4.0, 4.5),      # the shop's east aisle of shelving
        (13.5, 0.1, 13.9, 4.0),    # the stockroom's racking against its east wall
    ),
)

HOUSEBOAT = House(
    "houseboat", (0.0, 0.0, 21.0, 6.0),
    walls=(
        ((3.0, 0.0, 3.0, 6.0), ((2.5, 3.5),)),                 # front deck | saloon (the front doors)
        ((9.0, 0.0, 9.0, 6.0), ((2.5, 3.5),)),                 # saloon | galley
        ((13.0, 0.0, 13.0, 6.0), ((0.5, 1.5),)),               # galley | corridor, bathroom
        ((13.0, 2.0, 18.0, 2.0), ((13.8, 14.8), (16.2, 17.2))),  # corridor | bathroom, cabin
        ((15.5, 2.0, 15.5, 6.0), ()),                          # bathroom | cabin
        ((18.0, 0.0, 18.0, 6.0), ((0.5, 1.5),)),               # corridor, cabin | back deck (the back doors)
    ),
    blocks=(
        (13.1, 4.9, 14.3, 5.9),    # the shower cubicle in the bathroom's north-west corner
        (3.1, 0.1, 4.6, 0.5),      # the saloon's bookshelf along the south side
    ),
)

LIBRARY = House(
    "library", (0.0, 0.0, 16.0, 10.0),
    walls=(
        ((3.0, 0.0, 3.0, 10.0), ((1.5, 3.0),)),                # foyer | reading room (the inner doors)
        ((11.0, 0.0, 11.0, 6.0), ((2.0, 3.5),)),               # reading room | study room
        ((3.0, 6.0, 16.0, 6.0), ((5.0, 6.0), (8.5, 9.5), (11.5, 12.5), (14.0, 15.0))),  # the north row's doors
        ((7.0, 6.0, 7.0, 10.0), ()),                           # office | staff room
        ((11.0, 6.0, 11.0, 10.0), ()),                         # staff room | toilet
        ((13.0, 6.0, 13.0, 10.0), ()),                         # toilet | storeroom
    ),
    blocks=(
        (4.0, 0.1, 6.0, 0.5),      # the reading room's bookshelves along the south wall
        (7.0, 0.1, 9.0, 0.5),
    ),
)

BAKERY = House(
    "bakery", (0.0, 0.0, 14.0, 10.0),
    walls=(
        ((7.0, 0.0, 7.0, 10.0), ((2.0, 3.0),)),                 # shop | bakehouse (the door behind the counter)
        ((0.0, 6.0, 7.0, 6.0), ((1.0, 5.0),)),                  # shop | seating area (a wide archway)
        ((7.0, 6.0, 14.0, 6.0), ((8.0, 9.0), (10.5, 11.5), (12.5, 13.5))),  # the back rooms' doors
        ((10.0, 6.0, 10.0, 10.0), ()),                          # storeroom | office
        ((12.0, 6.0, 12.0, 10.0), ()),                          # office | toilet
    ),
    blocks=(
        (0.1, 0.5, 0.45, 3.5),     # the bread shelves along the shop's west wall
    ),
)

WORKSHOP = House(
    "workshop", (0.0, 0.0, 16.0, 10.0),
    walls=(
        ((5.0, 0.0, 5.0, 10.0), ((2.0, 3.0),)),                 # showroom | workshop (the only door off the showroom)
        ((0.0, 5.0, 5.0, 5.0), ((3.5, 4.5),)),                  # showroom | office
        ((12.0, 0.0, 12.0, 6.0), ((2.0, 3.5),)),                # workshop | finishing room (a wide door)
        ((5.0, 6.0, 16.0, 6.0), ((7.0, 8.0), (11.0, 12.0), (14.0, 15.0))),  # the back rooms' doors
        ((10.0, 6.0, 10.0, 10.0), ()),                          # kitchen | storeroom
        ((13.0, 6.0, 13.0, 10.0), ()),                          # storeroom | toilet
    ),
    blocks=(
        (8.0, 3.3, 9.2, 4.3),      # the table saw in the middle of the workshop floor
        (5.1, 0.1, 6.2, 0.5),      # the timber rack along the workshop's south wall
    ),
)

SCHOOL = House(
    "school", (0.0, 0.0, 18.0, 10.0),
    walls=(
        ((3.0, 0.0, 3.0, 10.0), ((4.6, 5.9), (7.5, 8.5))),     # entrance | corridor, entrance | office
        ((3.0, 4.5, 18.0, 4.5), ((5.0, 6.0), (10.5, 11.5), (14.5, 15.3), (16.6, 17.4))),  # the south rooms' doors
        ((3.0, 6.0, 18.0, 6.0), ((4.0, 5.0), (7.5, 8.5), (12.0, 14.0))),  # office, staff room, hall (double doors)
        ((9.0, 0.0, 9.0, 4.5), ()),                             # classroom | art room
        ((14.0, 0.0, 14.0, 4.5), ()),                           # art room | toilets
        ((16.0, 0.0, 16.0, 4.5), ()),                           # toilets | storeroom
        ((6.0, 6.0, 6.0, 10.0), ()),                            # office | staff room
        ((10.0, 6.0, 10.0, 10.0), ()),                          # staff room | hall
    ),
    blocks=(
        (10.6, 9.3, 11.8, 9.85),   # the piano against the hall's north wall
    ),
)

FITNESS_CLUB = House(
    "fitness_club", (0.0, 0.0, 16.0, 10.0),
    walls=(
        ((4.0, 0.0, 4.0, 10.0), ((2.0, 3.2),)),                 # reception | gym (the changing room only off the reception)
        ((0.0, 5.0, 4.0, 5.0), ((1.5, 2.5),)),                  # reception | changing room
        ((12.0, 0.0, 12.0, 6.0), ((2.0, 3.5),)),                # gym | studio
        ((4.0, 6.0, 16.0, 6.0), ((5.5, 6.7), (9.0, 10.0), (13.5, 15.0))),  # juice bar, office; the studio's deck door
        ((8.0, 6.0, 8.0, 10.0), ()),                            # juice bar | office
        ((11.0, 6.0, 11.0, 10.0), ()),                          # office | sun deck
    ),
    blocks=(
        (5.0, 0.2, 5.8, 2.0),      # the treadmills along the gym's south wall
        (6.2, 0.2, 7.0, 2.0),
    ),
)

HOUSES = (COTTAGE, OFFICE_FLOOR, CAFE, CLINIC, FARMHOUSE, TERRACE, BUNGALOW, LODGE, FLAT, CAREHOME, STUDENT_HOUSE,
          GUESTHOUSE, STUDIO, CORNER_SHOP, HOUSEBOAT, LIBRARY, BAKERY, WORKSHOP, SCHOOL, FITNESS_CLUB)


def draw(house: House) -> np.ndarray:
    """The image as rows of pixels, row 0 the highest y."""
    x0, y0, x1, y1 = house.outline
    width = round((x1 - x0 + 2 * MARGIN) / RESOLUTION)
    height = round((y1 - y0 + 2 * MARGIN) / RESOLUTION)
    ox, oy = house.origin
    xs = ox + (np.arange(width) + 0.5) * RESOLUTION
    ys = oy + (np.arange(height)[::-1] + 0.5) * RESOLUTION  # row 0 at the top
    x, y = np.meshgrid(xs, ys)
    image = np.full((height, width), UNKNOWN, dtype=np.uint8)

    def box(a: float, b: float, c: float, d: float) -> np.ndarray:
        return (x >= min(a, c)) & (x <= max(a, c)) & (y >= min(b, d)) & (y <= max(b, d))

    image[box(*house.outline)] = FREE
    outer = ((x0, y0, x1, y0), ()), ((x0, y1, x1, y1), ()), ((x0, y0, x0, y1), ()), ((x1, y0, x1, y1), ())
    half = WALL / 2
    for (a, b, c, d), doors in (*outer, *house.walls):
        solid = box(a - half, b - half, c + half, d + half)
        along = x if b == d else y
        for start, end in doors:
            solid &= ~((along > start) & (along < end))
        image[solid] = OCCUPIED
    for block in house.blocks:
        image[box(*block)] = OCCUPIED
    for a, b, c, d in house.cutouts:  # outside, and the outline's walls along it: the walls that bound it stay
        image[(x > a + half) & (x <= c + half) & (y > b + half) & (y <= d + half)] = UNKNOWN
    return image


def write_pgm(path: Path, image: np.ndarray) -> None:
    height, width = image.shape
    header = f"P5\n# {path.name}: drawn by make_houses.py, {RESOLUTION:.3f} m/pix\n{width} {height}\n255\n"
    path.write_bytes(header.encode("ascii") + image.tobytes())


if __name__ == "__main__":
    for house in HOUSES:
        write_pgm(Path(__file__).with_name(f"{house.name}.pgm"), draw(house))
