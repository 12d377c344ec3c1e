"""Shortest paths on free grids: A* against Dijkstra, lengths in metres, walls, corners, bad input."""

from __future__ import annotations

import math

import numpy as np
import pytest

from seal_cli.errors import SealError
from seal_cli.maps.navigation import Grid, astar, path_length


def wall_grid(connectivity: int = 8) -> Grid:
    """A 7 x 7 room (0.5 m cells) split by a wall with a gap at the top."""
    free = np.ones((7, 7), dtype=bool)
    free[0:6, 3] = False
    return Grid(free, (0.0, 0.0), 0.5, connectivity)


def test_straight_line_length_in_metres() -> None:
    grid = Grid(np.ones((1, 5), dtype=bool), (0.0, 0.0), 0.25, 4)
    path = astar(grid, (0, 0), (0, 4))
    assert path == [(0, 0), (0, 1), (0, 2), (0, 3), (0, 4)]
    assert path_length(grid, path) == pytest.approx(1.0)


@pytest.mark.parametrize("connectivity", [4, 8])
def test_path_goes_round_the_wall_and_matches_dijkstra(connectivity: int) -> None:
    grid = wall_grid(connectivity)
    path = grid.path((0, 0), (0, 6))
    assert all(grid.is_free(c) for c in path)
    assert all(c[1] != 3 or c[0] == 6 for c in path)  # crosses the wall only through the gap
    field = grid.distances((0, 0))
    assert path_length(grid, path) == pytest.approx(field[0, 6])
    assert path_length(grid, astar(grid, (0, 0), (0, 6))) == pytest.approx(field[0, 6])  # the reference agrees
    steps = [max(abs(a[0] - b[0]), abs(a[1] - b[1])) for a, b in zip(path, path[1:], strict=False)]
    assert steps and max(steps) == 1


def test_four_connected_length_is_manhattan_in_open_space() -> None:
    grid = Grid(np.ones((5, 5), dtype=bool), (0.0, 0.0), 0.25, 4)
    assert grid.distances((0, 0))[4, 4] == pytest.approx(8 * 0.25)
    grid8 = Grid(np.ones((5, 5), dtype=bool), (0.0, 0.0), 0.25, 8)
    assert grid8.distances((0, 0))[4, 4] == pytest.approx(4 * math.sqrt(2) * 0.25)


def test_diagonals_do_not_cut_corners() -> None:
    free = np.array([[True, False], [False, True]])
    grid = Grid(free, (0.0, 0.0), 1.0, 8)
    with pytest.raises(SealError, match="no path"):
        grid.path((0, 0), (1, 1))
    assert math.isinf(grid.distances((0, 0))[1, 1])


def test_from_points_round_trips_cells_and_points() -> None:
    pts = [(0.25, 1.0), (0.5, 1.0), (0.75, 1.0), (0.75, 1.25)]
    grid = Grid.from_points(pts, 0.25)
    for p in pts:
        cell = grid.cell(p)
        assert grid.is_free(cell)
        assert grid.point(cell) == pytest.approx(p)
    assert grid.free.sum() == 4
    assert grid.nearest_free((5.0, 5.0)) == grid.cell((0.75, 1.25))
    assert path_length(grid, grid.path(grid.cell(pts[0]), grid.cell(pts[-1]))) == pytest.approx(0.75)


def test_bad_input_is_a_clear_error() -> None:
    grid = wall_grid()
    with pytest.raises(SealError, match="not free"):
        grid.path((0, 3), (0, 0))
    with pytest.raises(SealError, match="not free"):
        astar(grid, (0, 0), (0, 3))
    with pytest.raises(SealError, match="not free"):
        grid.distances((99, 99))
    with pytest.raises(SealError, match="boolean"):
        Grid(np.ones((3, 3)), (0.0, 0.0), 1.0)
    with pytest.raises(SealError, match="connectivity"):
        Grid(np.ones((3, 3), dtype=bool), (0.0, 0.0), 1.0, 6)
    with pytest.raises(SealError, match="at least one"):
        Grid.from_points([], 0.25)


def test_the_path_cache_keeps_a_bounded_number_of_bytes(monkeypatch: pytest.MonkeyPatch) -> None:
    """256 fields of a million-cell grid were 3 GB: the cache holds at most CACHE_BYTES (and at least 4 fields)."""
    from seal_cli.maps import navigation

    grid = Grid(np.ones((40, 40), dtype=bool), (0.0, 0.0), 0.5)
    entry = 40 * 40 * 8 + 40 * 40 * 4
    monkeypatch.setattr(navigation, "CACHE_BYTES", 6 * entry)
    for k in range(20):
        grid.distances((k, k))
        assert len(grid._cache) <= 6
    assert np.isclose(grid.distances((0, 0))[0, 3], 1.5)  # cleared entries are computed again, the same


@pytest.mark.parametrize("connectivity", [4, 8])
def test_distances_from_several_cells_is_the_least_of_their_costs_plus_the_path(connectivity: int) -> None:
    grid = wall_grid(connectivity)
    a, b = (0, 0), (0, 6)   # either side of the wall
    assert np.array_equal(grid.distances_from(np.array([a]), np.array([0.0])), grid.distances(a))
    got = grid.distances_from(np.array([a, b]), np.array([1.0, 2.5]))
    want = np.minimum(grid.distances(a) + 1.0, grid.distances(b) + 2.5)
    assert np.allclose(got[grid.free], want[grid.free]) and np.isinf(got[~grid.free]).all()
    assert np.isinf(grid.distances_from(np.zeros((0, 2), dtype=int), np.zeros(0))).all()
    with pytest.raises(SealError, match="not free"):
        grid.distances_from(np.array([(0, 3)]), np.array([0.0]))
