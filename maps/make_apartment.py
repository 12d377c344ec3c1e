"""Draw ``apartment.pgm``, the occupancy image of ``apartment.yaml`` (run once; the PGM is committed).

    python maps/make_apartment.py          # rewrites maps/apartment.pgm next to this script

The house is 18 m × 12 m (x from -9 to 9, y from -6 to 6), laid out like the SEAL paper's
Gazebo study: a bedroom and a family room along the north side, a dining room in the
north-east, the kitchen in the south-east and an L-shaped living room in the south-west.
Walls are 0.15 m thick, centred on the room boundaries of ``apartment.yaml``, with doors as
gaps; a kitchen island, a wardrobe and a pillar are solid too (a laser sees them). Furniture
that objects stand on (tables, counters, beds) is left free: the robot sees over it.

Pixel values follow ROS map_server: 0 occupied, 254 free, 205 unknown (outside the house).
The image's row 0 is the highest y; its lower-left pixel sits at ``ORIGIN``.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np

RESOLUTION = 0.05
ORIGIN = (-10.0, -7.0)
SIZE = (20.0, 14.0)  # metres: width, height
HOUSE = (-9.0, -6.0, 9.0, 6.0)
WALL = 0.15
FREE, UNKNOWN, OCCUPIED = 254, 205, 0

# wall centre lines (x0, y0, x1, y1), each with its door gaps (from, to) along the wall
WALLS: list[tuple[tuple[float, float, float, float], list[tuple[float, float]]]] = [
    ((-9.0, -6.0, 9.0, -6.0), []),             # south
    ((-9.0, 6.0, 9.0, 6.0), []),               # north
    ((-9.0, -6.0, -9.0, 6.0), []),             # west
    ((9.0, -6.0, 9.0, 6.0), []),               # east
    ((-3.0, 0.5, -3.0, 6.0), [(4.2, 5.2)]),    # bedroom | family room (and living room below y=1)
    ((-9.0, 0.5, -3.0, 0.5), [(-5.5, -4.5)]),  # bedroom | living room
    ((-3.0, 1.0, 3.0, 1.0), [(-1.0, 1.0)]),    # family room | living room: a wide opening
    ((3.0, 1.0, 3.0, 6.0), [(4.0, 5.0)]),      # family room | dining room
    ((3.0, 0.0, 9.0, 0.0), [(6.5, 7.5)]),      # dining room | kitchen
    ((2.0, 0.0, 3.0, 0.0), []),                # living room's nook | kitchen
    ((2.0, -6.0, 2.0, 0.0), [(-2.5, -1.5)]),   # living room | kitchen
]                                              # (x = 3 between the nook and the dining room is open)
BLOCKS = [
    (4.5, -3.5, 5.5, -2.5),    # kitchen island
    (-3.6, 2.0, -3.075, 3.5),  # wardrobe against the bedroom's east wall
    (-0.2, -2.2, 0.2, -1.8),   # a pillar in the living room
]


def draw() -> np.ndarray:
    """The image as rows of pixels, row 0 the highest y."""
    width, height = round(SIZE[0] / RESOLUTION), round(SIZE[1] / RESOLUTION)
    xs = ORIGIN[0] + (np.arange(width) + 0.5) * RESOLUTION
    ys = ORIGIN[1] + (np.arange(height)[::-1] + 0.5) * RESOLUTION  # row 0 at the top
    x, y = np.meshgrid(xs, ys)
    image = np.full((height, width), UNKNOWN, dtype=np.uint8)

    def box(x0: float, y0: float, x1: float, y1: float) -> np.ndarray:
        return (x >= min(x0, x1)) & (x <= max(x0, x1)) & (y >= min(y0, y1)) & (y <= max(y0, y1))

    image[box(*HOUSE)] = FREE
    half = WALL / 2
    for (x0, y0, x1, y1), doors in WALLS:
        solid = box(x0 - half, y0 - half, x1 + half, y1 + half)
        for a, b in doors:
            along = x if y0 == y1 else y
            solid &= ~((along > a) & (along < b))
        image[solid] = OCCUPIED
    for block in BLOCKS:
        image[box(*block)] = OCCUPIED
    return image


def write_pgm(path: Path, image: np.ndarray) -> None:
    height, width = image.shape
    header = f"P5\n# apartment.pgm: drawn by make_apartment.py, {RESOLUTION:.3f} m/pix\n{width} {height}\n255\n"
    path.write_bytes(header.encode("ascii") + image.tobytes())


if __name__ == "__main__":
    write_pgm(Path(__file__).with_name("apartment.pgm"), draw())
