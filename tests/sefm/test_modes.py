"""Summaries of weighted particle sets: room masses, modes by weighted mean shift, the best point."""

from __future__ import annotations

import numpy as np
import pytest

from seal_cli.maps.model import Map, Room
from seal_cli.sefm.modes import grid_modes, mean_shift, room_masses, summarise


@pytest.fixture(scope="module")
def two_rooms() -> Map:
    return Map("two_rooms", (0.0, 0.0, 10.0, 5.0), (Room.box("west", 0, 0, 5, 5), Room.box("east", 5, 0, 10, 5)))


def blobs(rng: np.random.Generator) -> tuple[np.ndarray, np.ndarray]:
    """300 particles around (2, 2) with weight 0.7 in all, 100 around (8, 3) with 0.3."""
    X = np.concatenate([rng.normal((2, 2), 0.2, (300, 2)), rng.normal((8, 3), 0.3, (100, 2))])
    W = np.concatenate([np.full(300, 0.7 / 300), np.full(100, 0.3 / 100)])
    return X, W


def test_room_masses_count_weights_per_room(two_rooms: Map) -> None:
    X = np.array([[1.0, 1.0], [6.0, 1.0], [7.0, 4.0], [20.0, 20.0]])
    W = np.array([0.1, 0.2, 0.3, 0.4])
    assert room_masses(two_rooms, X, W) == pytest.approx({"west": 0.1, "east": 0.5, "_outside": 0.4})


def test_mean_shift_finds_both_peaks() -> None:
    X, W = blobs(np.random.default_rng(0))
    peaks, labels, density = mean_shift(X, W, bandwidth=0.5)
    assert len(peaks) == 2
    order = np.argsort(-density)
    np.testing.assert_allclose(peaks[order[0]], (2, 2), atol=0.1)
    np.testing.assert_allclose(peaks[order[1]], (8, 3), atol=0.15)
    assert set(labels[:300]) == {order[0]} and set(labels[300:]) == {order[1]}


def test_summary_modes_weights_means_covariances_rooms(two_rooms: Map) -> None:
    X, W = blobs(np.random.default_rng(1))
    s = summarise(two_rooms, X, W, bandwidth=0.5)
    assert [m.room for m in s.modes] == ["west", "east"]
    assert [m.weight for m in s.modes] == pytest.approx([0.7, 0.3])
    np.testing.assert_allclose(s.modes[0].mean, (2, 2), atol=0.05)
    np.testing.assert_allclose(np.array(s.modes[0].cov), np.eye(2) * 0.04, atol=0.015)
    np.testing.assert_allclose(s.best, (2, 2), atol=0.1)
    assert s.rooms == pytest.approx({"west": 0.7, "east": 0.3, "_outside": 0.0})
    assert s.top_room == "west"
    assert s.ess == pytest.approx(1 / np.sum(W ** 2))


def test_best_is_the_densest_peak_not_the_heaviest_basin(two_rooms: Map) -> None:
    rng = np.random.default_rng(2)
    spread = rng.uniform((0.2, 0.2), (4.8, 4.8), (600, 2))   # 0.6 of the mass over a whole room
    tight = rng.normal((8, 2.5), 0.15, (400, 2))             # 0.4 in one spot
    X = np.concatenate([spread, tight])
    W = np.concatenate([np.full(600, 0.6 / 600), np.full(400, 0.4 / 400)])
    s = summarise(two_rooms, X, W)
    np.testing.assert_allclose(s.best, (8, 2.5), atol=0.1)


def test_light_basins_are_not_modes(two_rooms: Map) -> None:
    X, W = blobs(np.random.default_rng(3))
    W = np.where(np.arange(400) < 300, 0.98 / 300, 0.02 / 100)
    s = summarise(two_rooms, X, W, bandwidth=0.5, min_weight=0.05)
    assert len(s.modes) == 1 and s.modes[0].room == "west"


def test_json_has_the_spec_keys(two_rooms: Map) -> None:
    X, W = blobs(np.random.default_rng(4))
    data = summarise(two_rooms, X, W).to_json()
    assert set(data) == {"rooms", "modes", "best", "ess"}
    assert set(data["modes"][0]) == {"mean", "cov", "weight", "room"}
    assert len(data["modes"][0]["cov"]) == 2 and len(data["best"]) == 2


@pytest.mark.parametrize("seed", range(3))
def test_grid_modes_find_the_peaks_mean_shift_finds(seed: int) -> None:
    rng = np.random.default_rng(seed)
    X = np.concatenate([rng.normal((2, 2), 0.3, (150, 2)), rng.normal((6, 2.5), 0.5, (150, 2)),
                        rng.uniform((0, 0), (10, 5), (100, 2))])
    W = rng.random(400)
    W /= W.sum()
    exact, exact_labels, exact_density = mean_shift(X, W, 0.8)
    grid, grid_labels, grid_density = grid_modes(X, W, 0.8)
    strong = exact[exact_density > 0.2 * exact_density.max()]
    for peak in strong:
        assert np.min(np.hypot(*(grid - peak).T)) < 0.1
    heavy = np.argmax(np.bincount(exact_labels, W))
    assert np.mean(grid_labels[exact_labels == heavy] == np.argmax(np.bincount(grid_labels, W))) > 0.95
