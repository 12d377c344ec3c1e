"""Geometry: polygons, occupancy grids and line of sight, each checked against an independent reference."""

from __future__ import annotations

import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from matplotlib.path import Path as MplPath

from seal_cli.maps.geometry import (
    FREE,
    OCCUPIED,
    UNKNOWN,
    OccupancyGrid,
    as_points,
    box_polygon,
    cast_rays,
    line_of_sight,
    lines_of_sight,
    overlap_area,
    point_in_polygon,
    polygon_area,
    segment_cells,
    segments_intersect,
    self_intersections,
)

coord = st.floats(-20, 20, allow_nan=False, allow_infinity=False)


@st.composite
def star_polygons(draw: st.DrawFn) -> np.ndarray:
    """A simple polygon: vertices at increasing angles around a centre, no angular gap reaching pi
    (so the centre is inside and the polygon is star-shaped, never self-crossing)."""
    n = draw(st.integers(4, 12))
    cx, cy = draw(coord), draw(coord)
    gaps = np.array(draw(st.lists(st.floats(0.5, 1.0), min_size=n, max_size=n)))
    angles = np.cumsum(gaps) / gaps.sum() * 2 * np.pi
    radii = np.array(draw(st.lists(st.floats(0.5, 5.0), min_size=n, max_size=n)))
    return np.column_stack([cx + radii * np.cos(angles), cy + radii * np.sin(angles)])


@st.composite
def boxes(draw: st.DrawFn) -> tuple[float, float, float, float]:
    x, y = draw(st.floats(-5, 5)), draw(st.floats(-5, 5))
    return (x, y, x + draw(st.floats(0.1, 4)), y + draw(st.floats(0.1, 4)))


# -- points and polygons -------------------------------------------------------------------------
def test_as_points_shapes() -> None:
    assert as_points([1, 2]).shape == (1, 2)
    assert as_points([[1, 2], [3, 4]]).shape == (2, 2)
    assert as_points([]).shape == (0, 2)
    with pytest.raises(ValueError):
        as_points([[1, 2, 3]])


def test_area_and_orientation() -> None:
    square = box_polygon(0, 0, 2, 3)
    assert polygon_area(square) == pytest.approx(6.0)
    assert polygon_area(square[::-1]) == pytest.approx(-6.0)


def test_point_in_polygon_on_a_non_convex_room() -> None:
    ell = [[0, 0], [4, 0], [4, 1], [1, 1], [1, 3], [0, 3]]
    got = point_in_polygon([[0.5, 2.5], [2, 0.5], [2, 2], [5, 0.5], [0.5, -0.1]], ell)
    assert got.tolist() == [True, True, False, False, False]


@settings(max_examples=60, deadline=None)
@given(star_polygons(), st.integers(0, 2**31 - 1))
def test_point_in_polygon_matches_matplotlib_away_from_the_boundary(polygon: np.ndarray, seed: int) -> None:
    rng = np.random.default_rng(seed)
    lo, hi = polygon.min(axis=0) - 1, polygon.max(axis=0) + 1
    points = rng.uniform(lo, hi, size=(400, 2))
    path = MplPath(polygon, closed=False)
    inner = path.contains_points(points, radius=-1e-6)
    outer = path.contains_points(points, radius=1e-6)
    sure = inner == outer  # matplotlib's sign of radius depends on orientation; keep points both agree on
    ours = point_in_polygon(points, polygon)
    assert np.array_equal(ours[sure], inner[sure])
    assert np.array_equal(point_in_polygon(points, polygon[::-1]), ours)  # orientation does not matter


@settings(max_examples=60, deadline=None)
@given(boxes(), st.floats(0.05, 0.95), st.booleans(), st.integers(0, 2**31 - 1))
def test_rooms_sharing_an_edge_partition_the_plane(box: tuple[float, float, float, float], split: float,
                                                   vertical: bool, seed: int) -> None:
    x0, y0, x1, y1 = box
    if vertical:
        cut = x0 + split * (x1 - x0)
        a, b = box_polygon(x0, y0, cut, y1), box_polygon(cut, y0, x1, y1)
        edge = np.column_stack([np.full(50, cut), np.linspace(y0 + 1e-3, y1 - 1e-3, 50)])
    else:
        cut = y0 + split * (y1 - y0)
        a, b = box_polygon(x0, y0, x1, cut), box_polygon(x0, cut, x1, y1)
        edge = np.column_stack([np.linspace(x0 + 1e-3, x1 - 1e-3, 50), np.full(50, cut)])
    rng = np.random.default_rng(seed)
    inside = np.vstack([edge, rng.uniform((x0, y0), (x1, y1), size=(200, 2))])
    count = point_in_polygon(inside, a).astype(int) + point_in_polygon(inside, b).astype(int)
    assert np.all(count == 1)
    assert overlap_area(a, b) == 0.0


# -- self-intersection and overlap ------------------------------------------------------------------
def test_self_intersections() -> None:
    assert self_intersections([[0, 0], [1, 1], [1, 0], [0, 1]]) == [(0, 2)]  # bow tie
    assert self_intersections(box_polygon(0, 0, 1, 1)) == []
    assert self_intersections([[0, 0], [2, 0], [1, 0], [1, 1]])  # folds back over itself
    assert self_intersections([[0, 0], [4, 0], [4, 4], [2, 0.0], [0, 4]])  # touches an edge at a vertex


@settings(max_examples=80, deadline=None)
@given(star_polygons())
def test_simple_polygons_do_not_intersect_themselves(polygon: np.ndarray) -> None:
    assert self_intersections(polygon) == []


@settings(max_examples=80, deadline=None)
@given(coord, coord, st.floats(0, 2 * math.pi), st.floats(0.1, 3.0), st.floats(0.1, 3), st.floats(0.1, 3),
       st.floats(0.1, 3), st.floats(0.3, 2.8))
def test_segments_through_a_common_point_intersect(x: float, y: float, turn: float, a1: float, a2: float,
                                                   b1: float, b2: float, phi: float) -> None:
    d = np.array([math.cos(turn), math.sin(turn)])
    e = np.array([math.cos(turn + phi), math.sin(turn + phi)])
    p = np.array([x, y])
    assert segments_intersect(p - a1 * d, p + a2 * d, p - b1 * e, p + b2 * e)
    # shifted apart across the first segment's line, they no longer meet
    normal = np.array([-d[1], d[0]])
    shift = normal * (b1 + b2 + 1) * (1 if np.dot(e, normal) >= 0 else -1)
    assert not segments_intersect(p - a1 * d, p + a2 * d, p + shift + 0.01 * e, p + shift + b2 * e)


@settings(max_examples=60, deadline=None)
@given(boxes(), boxes())
def test_overlap_area_of_boxes_matches_the_formula(a: tuple[float, float, float, float],
                                                   b: tuple[float, float, float, float]) -> None:
    w = max(0.0, min(a[2], b[2]) - max(a[0], b[0]))
    h = max(0.0, min(a[3], b[3]) - max(a[1], b[1]))
    step = 0.02
    got = overlap_area(box_polygon(*a), box_polygon(*b), step=step)
    # a lattice measure: off by at most one lattice row/column along each side
    assert abs(got - w * h) <= step * (w + h) + 2 * step * step


# -- occupancy grids ----------------------------------------------------------------------------------
def test_grid_conventions_follow_ros() -> None:
    cells = np.array([[FREE, OCCUPIED, UNKNOWN],
                      [OCCUPIED, FREE, FREE]])  # row 0 is the LOWEST y
    grid = OccupancyGrid(cells, 0.5, (1.0, 2.0, 0.0))
    assert grid.shape == (2, 3)
    assert grid.bounds == (1.0, 2.0, 2.5, 3.0)
    assert grid.extent == (1.0, 2.5, 2.0, 3.0)
    # cell (0, 0) spans x [1, 1.5), y [2, 2.5)
    assert grid.values([[1.1, 2.1], [1.6, 2.1], [2.4, 2.1], [1.1, 2.9], [1.6, 2.9]]).tolist() == \
        [FREE, OCCUPIED, UNKNOWN, OCCUPIED, FREE]
    # a point on a cell edge belongs to the cell above / to the right
    rows, cols, inside = grid.cell_index([[1.5, 2.5]])
    assert (rows[0], cols[0], inside[0]) == (1, 1, True)
    assert grid.values([[0.9, 2.1], [1.1, 3.1], [3.0, 2.1]]).tolist() == [UNKNOWN] * 3  # off the grid
    assert grid.cell_centres([0, 1], [0, 2]).tolist() == [[1.25, 2.25], [2.25, 2.75]]


def test_grid_rejects_nonsense() -> None:
    with pytest.raises(ValueError):
        OccupancyGrid(np.zeros((0, 3)), 0.1)
    with pytest.raises(ValueError):
        OccupancyGrid(np.zeros((2, 2)), -1.0)
    with pytest.raises(ValueError):
        OccupancyGrid(np.full((2, 2), 7), 0.1)


def test_grids_from_masks_and_from_cell_centres() -> None:
    free = np.array([[True, False], [False, False]])
    occupied = np.array([[False, True], [False, False]])
    grid = OccupancyGrid.from_masks(free, 1.0, (0, 0), occupied)
    assert grid.cells.tolist() == [[FREE, OCCUPIED], [UNKNOWN, UNKNOWN]]
    # ALFRED-style reachable positions on a 0.25 m lattice
    centres = np.array([[0.0, 0.0], [0.25, 0.0], [0.5, 0.25], [-1.0, 1.5]])
    lattice = OccupancyGrid.from_cells(centres, 0.25, occupied=[[0.5, 0.0]])
    assert lattice.is_free(centres).all()
    assert lattice.is_free(centres + 0.1).all()  # within the cells
    assert not lattice.is_free([[0.0, 0.25], [0.125 + 0.01, 0.0 + 0.13]]).any()
    assert lattice.is_occupied([[0.5, 0.0]]).all()
    assert int(lattice.free_mask.sum()) == 4


@settings(max_examples=60, deadline=None)
@given(coord, coord, st.floats(-math.pi, math.pi), st.lists(st.tuples(coord, coord), min_size=1, max_size=20))
def test_rotated_grids_round_trip(ox: float, oy: float, yaw: float, points: list[tuple[float, float]]) -> None:
    grid = OccupancyGrid(np.zeros((4, 4), dtype=np.int8), 0.1, (ox, oy, yaw))
    p = np.array(points)
    assert np.allclose(grid.grid_to_world(grid.world_to_grid(p)), p, atol=1e-9)
    # the grid's +x axis points along yaw in the world
    assert np.allclose(grid.grid_to_world([[1.0, 0.0]]) - [ox, oy], [[math.cos(yaw), math.sin(yaw)]])


# -- segments and line of sight --------------------------------------------------------------------------
def _dense_cells(grid: OccupancyGrid, a: np.ndarray, b: np.ndarray) -> set[tuple[int, int]]:
    """Reference: the cells of points sampled densely along a-b, skipping points near grid lines."""
    t = np.linspace(0, 1, 20001)
    pts = a + t[:, None] * (b - a)
    local = grid.world_to_grid(pts) / grid.resolution
    clear = np.all(np.abs(local - np.rint(local)) > 1e-3, axis=1)
    return {(int(r), int(c)) for c, r in np.floor(local[clear]).astype(int)}


@settings(max_examples=60, deadline=None)
@given(st.tuples(st.floats(0.01, 3.99), st.floats(0.01, 2.99)), st.tuples(st.floats(0.01, 3.99), st.floats(0.01, 2.99)))
def test_segment_cells_are_exactly_the_cells_the_segment_crosses(a: tuple[float, float],
                                                                 b: tuple[float, float]) -> None:
    grid = OccupancyGrid(np.zeros((6, 8), dtype=np.int8), 0.5, (0.0, 0.0, 0.0))
    rows, cols, t_exit, valid = segment_cells(grid, a, [b])
    got = [(int(r), int(c)) for r, c in zip(rows[0][valid[0]], cols[0][valid[0]], strict=True)]
    assert len(got) == len(set(got))
    assert set(got) >= _dense_cells(grid, np.array(a), np.array(b))
    start_rows, start_cols, _ = grid.cell_index([a])
    if np.all(np.abs(np.array(a) / 0.5 - np.rint(np.array(a) / 0.5)) > 1e-9):  # (a start on a grid line and
        assert got[0] == (int(start_rows[0]), int(start_cols[0]))          # heading down only touches its cell)
    assert np.all(np.diff(t_exit[0][valid[0]]) > 0) and t_exit[0][valid[0]][-1] == 1.0


def _random_grid(seed: int, shape: tuple[int, int] = (20, 30), density: float = 0.15) -> OccupancyGrid:
    rng = np.random.default_rng(seed)
    cells = np.where(rng.random(shape) < density, OCCUPIED, FREE).astype(np.int8)
    cells[rng.random(shape) < 0.05] = UNKNOWN
    return OccupancyGrid(cells, 0.1, (-1.0, -0.5, 0.0))


def _reference_los(grid: OccupancyGrid, a: np.ndarray, points: np.ndarray) -> np.ndarray:
    """Reference: walk the ordered cells of each segment and look for an occupied one between the ends."""
    rows, cols, _, valid = segment_cells(grid, a, points)
    t_rows, t_cols, _ = grid.cell_index(points)
    o_row, o_col, _ = grid.cell_index(a)
    out = []
    h, w = grid.shape
    for i in range(len(points)):
        blocked = False
        for r, c in zip(rows[i][valid[i]], cols[i][valid[i]], strict=True):
            if (r, c) in ((o_row[0], o_col[0]), (t_rows[i], t_cols[i])) or not (0 <= r < h and 0 <= c < w):
                continue
            blocked |= bool(grid.cells[r, c] == OCCUPIED)
        out.append(not blocked)
    return np.array(out)


@settings(max_examples=40, deadline=None)
@given(st.integers(0, 10_000), st.integers(0, 10_000))
def test_line_of_sight_matches_the_ordered_walk_and_is_symmetric(grid_seed: int, seed: int) -> None:
    grid = _random_grid(grid_seed)
    rng = np.random.default_rng(seed)
    a = rng.uniform((-1.2, -0.7), (2.2, 1.7))
    points = rng.uniform((-1.2, -0.7), (2.2, 1.7), size=(40, 2))
    got = line_of_sight(grid, a, points)
    assert np.array_equal(got, _reference_los(grid, a, points))
    back = np.array([line_of_sight(grid, p, a)[0] for p in points])
    assert np.array_equal(got, back)


def test_walls_block_and_end_cells_do_not() -> None:
    cells = np.zeros((10, 10), dtype=np.int8)
    cells[:, 5] = OCCUPIED  # a wall at x in [5, 6)
    grid = OccupancyGrid(cells, 1.0)
    los = line_of_sight(grid, (0.5, 0.5), [[4.9, 9.0], [5.5, 0.6], [6.5, 0.5], [9.0, 9.0]])
    assert los.tolist() == [True, True, False, False]
    assert line_of_sight(grid, (5.5, 5.5), [[9.5, 5.5]]).tolist() == [True]  # standing in the wall's cell
    empty = OccupancyGrid(np.zeros((3, 3), dtype=np.int8), 1.0)
    assert line_of_sight(empty, (0, 0), [[2.9, 2.9], [10, 10]]).all()


@settings(max_examples=30, deadline=None)
@given(st.integers(0, 10_000), st.integers(0, 10_000))
def test_rays_reach_exactly_as_far_as_line_of_sight(grid_seed: int, seed: int) -> None:
    grid = _random_grid(grid_seed)
    rng = np.random.default_rng(seed)
    origin = rng.uniform((-0.9, -0.4), (1.9, 1.4))
    angles = rng.uniform(-np.pi, np.pi, 50)
    reach = cast_rays(grid, origin, angles, 2.0)
    assert np.all((reach > 0) & (reach <= 2.0))
    direction = np.column_stack([np.cos(angles), np.sin(angles)])
    before = origin + (reach - 1e-6)[:, None] * direction
    assert line_of_sight(grid, origin, before).all()
    stopped = reach < 2.0
    after = origin + (reach + 1e-6)[:, None] * direction
    assert not line_of_sight(grid, origin, after[stopped]).any()


def _crossings_by_every_pair(v: np.ndarray) -> list[tuple[int, int]]:
    from seal_cli.maps.geometry import _folds_back

    n, a, b = len(v), v, np.roll(v, -1, axis=0)
    out = []
    for i in range(n):
        for j in range(i + 1, n):
            neighbours = j == i + 1 or (i == 0 and j == n - 1)
            hit = bool(segments_intersect(a[i], b[i], a[j], b[j]))
            if (hit and not neighbours) or (neighbours and _folds_back(a[i:i + 1], b[i:i + 1], a[j:j + 1],
                                                                       b[j:j + 1])[0]):
                out.append((i, j))
    return out


def test_the_swept_crossing_test_finds_what_testing_every_pair_finds() -> None:
    rng = np.random.default_rng(7)
    for _ in range(200):  # small integer lattices: many touches, shared vertices and collinear overlaps
        v = rng.integers(0, 5, size=(int(rng.integers(3, 12)), 2)).astype(float)
        assert self_intersections(v) == _crossings_by_every_pair(v)


def test_a_fine_outline_is_checked_in_time_and_memory_near_its_size() -> None:
    import time

    t = np.linspace(0, 2 * np.pi, 62_831, endpoint=False)
    ring = np.c_[5 + 2 * np.cos(t), 5 + 2 * np.sin(t)]
    start = time.perf_counter()
    assert self_intersections(ring) == []  # every pair: 2 billion, 15 GB
    assert time.perf_counter() - start < 5
    ring[[10, 20_000]] = ring[[20_000, 10]]  # two far points swapped: their edges cut across the ring
    assert self_intersections(ring) == [(9, 20_000), (10, 19_999)]


def test_cells_are_coarsened_walls_first_then_free_space() -> None:
    from seal_cli.maps.geometry import FREE, OCCUPIED, UNKNOWN, coarsened, shrink_factor

    cells = np.full((5, 5), UNKNOWN, dtype=np.int8)
    cells[0, 0], cells[0, 1], cells[1, 1] = FREE, OCCUPIED, FREE
    cells[2, 3] = FREE
    out = coarsened(cells, 2)
    assert out.shape == (3, 3) and out[0, 0] == OCCUPIED and out[1, 1] == FREE and out[2, 2] == UNKNOWN
    assert coarsened(cells, 1) is cells
    assert shrink_factor(8_200, 8_200, 4096 * 4096) == 3 and shrink_factor(10, 10, 100) == 1
    assert shrink_factor(4_097, 4_097, 4096 * 4096) == 2


def test_a_grid_too_large_is_cropped_to_what_it_knows_then_coarsened() -> None:
    from seal_cli.maps.geometry import FREE, OCCUPIED, UNKNOWN, OccupancyGrid, fit_cells

    cells = np.full((100, 100), UNKNOWN, dtype=np.int8)
    cells[10:20, 30:45] = FREE
    cells[15, 40] = OCCUPIED
    kept, corner, factor = fit_cells(cells, 1_000)
    assert corner == (30, 10) and factor == 1 and np.array_equal(kept, cells[10:20, 30:45])
    assert fit_cells(cells, 100_000)[0] is cells  # within the bound: untouched
    small, corner, factor = fit_cells(cells, 50)
    assert factor == 2 and small.shape == (5, 8) and small[2, 5] == OCCUPIED
    grid = OccupancyGrid.placed(kept, 0.5, (1.0, 2.0, math.pi / 2), corner)
    assert np.allclose(grid.origin, (1.0 - 10 * 0.5, 2.0 + 30 * 0.5, math.pi / 2))  # the corner, turned with the yaw


def test_lines_of_sight_answers_as_line_of_sight_on_every_held_out_house() -> None:
    """The fan's shortcut settles most points but changes no answer: the same as following every segment exactly,
    from 12 origins a house, for every free cell within 6 m moved up to half a cell (points off the centres, on the
    cells' edges, and grazing the corners of walls and furniture), and from an origin beside a wall's corner."""
    from seal_cli.bench.context import unseen_houses

    rng = np.random.default_rng(21)
    settled = 0
    for house in unseen_houses():
        m = house.map
        grid, free = m.grid, m.free_centres
        for k in range(12):
            o = free[rng.integers(len(free))]
            near = free[np.hypot(*(free - o).T) <= 6.0]
            pts = near + rng.uniform(-grid.resolution / 2, grid.resolution / 2, near.shape)
            exact = line_of_sight(grid, o, pts)
            assert np.array_equal(lines_of_sight(grid, o, pts), exact), (m.name, k)
            settled += int(exact.sum())
    assert settled > 10_000     # the comparison is not vacuous: many points in sight, many not


def test_lines_of_sight_falls_back_to_the_exact_rule_for_few_points_and_an_empty_grid() -> None:
    cells = np.zeros((20, 20), dtype=np.int8)
    cells[5:15, 10] = OCCUPIED
    grid = OccupancyGrid(cells, 0.1)
    pts = np.asarray([[1.5, 1.0], [0.5, 1.0], [1.5, 0.2]])
    assert lines_of_sight(grid, (0.5, 1.0), pts).tolist() == line_of_sight(grid, (0.5, 1.0), pts).tolist() \
        == [False, True, False]
    many = np.column_stack([np.linspace(0.05, 1.95, 80), np.full(80, 1.0)])
    assert lines_of_sight(grid, (0.5, 1.0), many).tolist() == line_of_sight(grid, (0.5, 1.0), many).tolist()
    assert lines_of_sight(OccupancyGrid(np.zeros((4, 4), dtype=np.int8), 0.1), (0.1, 0.1), many).all()
