"""The cell order: room by room, and along a Hilbert curve within a room."""

from __future__ import annotations

import numpy as np
import pytest

from seal_cli.maps.model import Map, Room
from seal_cli.sefm import cell_order
from seal_cli.sefm.object_beliefs import Source, _initial


@pytest.fixture(scope="module")
def rooms() -> Map:
    return Map("two_rooms", (0.0, 0.0, 10.0, 4.0), (Room.box("west", 0, 0, 4, 4), Room.box("east", 4, 0, 9, 4)),
               priors={"cup": {"west": 0.5, "east": 0.5}})


@pytest.mark.parametrize("bits", [1, 2, 3, 6])
def test_the_hilbert_curve_visits_every_cell_once_in_unit_steps(bits: int) -> None:
    n = 1 << bits
    i, j = (a.ravel() for a in np.meshgrid(np.arange(n), np.arange(n), indexing="ij"))
    d = cell_order.hilbert_index(i, j, bits)
    assert sorted(d) == list(range(n * n))
    path = np.argsort(d)
    assert np.all(np.abs(np.diff(i[path])) + np.abs(np.diff(j[path])) == 1)


def test_cells_are_ranked_room_by_room(rooms: Map) -> None:
    rank = cell_order.rank(rooms)
    assert sorted(rank) == list(range(len(rooms.free_centres)))
    room_in_order = rooms.free_cell_room[np.argsort(rank)]
    assert np.all(np.diff(room_in_order) >= 0)  # no room (-1) first, then west, then east
    cells, starts = cell_order.by_room(rooms)
    assert set(rooms.free_cell_room[cells[starts[1]:starts[2]]]) == {0}
    assert set(rooms.free_cell_room[cells[starts[2]:starts[3]]]) == {1}


def test_a_run_of_the_order_is_a_blob_not_a_strip(rooms: Map) -> None:
    cells, starts = cell_order.by_room(rooms)
    west = rooms.free_centres[cells[starts[1]:starts[2]]]
    for run in np.array_split(west, 16):  # 1 m² each
        extent = run.max(axis=0) - run.min(axis=0)
        assert extent.max() <= 2.0  # a row-by-row order would give 4 m × 0.25 m strips


def test_points_off_free_space_come_first(rooms: Map) -> None:
    X = np.array([[[5.0, 1.0], [20.0, 20.0], [1.0, 1.0]]])
    order = cell_order.order_of_points(rooms, X)[0]
    assert list(order) == [1, 2, 0]


def test_prior_draws_give_every_part_of_a_room_its_share(rooms: Map) -> None:
    """Stratified along the curve, the south-west quarter of the west room gets its 1/4 of the room's
    50 particles to within a couple, seed after seed (independent draws would be off by ±3)."""
    counts = []
    for seed in range(20):
        X = _initial(rooms, Source("cup", "object"), 100, np.random.default_rng(seed))
        west = X[X[:, 0] < 4]
        counts.append(int(np.sum((west[:, 0] < 2) & (west[:, 1] < 2))))
    assert all(abs(c - 12.5) <= 2.6 for c in counts), counts


@pytest.mark.parametrize("shape", [(5, 300), (1, 7), (3, 1), (40, 1100), (2, 0), (9,)])
def test_the_order_is_exactly_a_stable_sort_of_the_ranks(rooms: Map, shape: tuple[int, ...]) -> None:
    rng = np.random.default_rng(3)
    ranks = cell_order.rank(rooms)
    cells = rng.integers(-1, len(ranks), shape)
    cells[..., : shape[-1] // 3] = cells[..., :1]           # many ties, of a cell and of off free space
    key = np.where(cells >= 0, ranks[np.maximum(cells, 0)], -1)
    order = cell_order.order_of_cells(rooms, cells)
    assert order.dtype == np.intp
    assert np.array_equal(order, np.argsort(key, axis=-1, kind="stable"))
