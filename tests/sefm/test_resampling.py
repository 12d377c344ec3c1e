"""Resampling of stacks of particle sets: systematic draws, grouped draws, weights."""

from __future__ import annotations

import numpy as np
import pytest

from seal_cli.sefm.resampling import ess, grouped_systematic, normalise, stratified, systematic


def by_search(weights: np.ndarray, u: np.ndarray, count: int) -> np.ndarray:
    """The textbook systematic resampling: for each point (u + k)/count, the first particle whose
    normalised cumulative weight exceeds it."""
    out = []
    for row, start in zip(weights, u[:, 0], strict=True):
        cumulative = np.cumsum(row) / row.sum()
        out.append(np.minimum(np.searchsorted(cumulative, (start + np.arange(count)) / count, side="right"),
                              len(row) - 1))
    return np.array(out)


@pytest.mark.parametrize("seed", range(30))
def test_systematic_draws_what_the_textbook_search_draws(seed: int) -> None:
    rng = np.random.default_rng(seed)
    rows, size, count = int(rng.integers(1, 6)), int(rng.integers(1, 40)), int(rng.integers(1, 80))
    W = rng.random((rows, size)) ** 3 * (rng.random((rows, size)) > 0.3)
    W[:, -1] += 1e-3
    W /= W.sum(axis=1, keepdims=True)
    u = np.random.default_rng(seed).random((rows, 1))
    np.testing.assert_array_equal(systematic(W, np.random.default_rng(seed), count), by_search(W, u, count))


def test_systematic_gives_each_run_its_share_within_one() -> None:
    rng = np.random.default_rng(0)
    W = normalise(rng.random((4, 500)) ** 2)
    ancestors = systematic(W, rng, 300)
    assert ancestors.shape == (4, 300) and np.all(np.diff(ancestors, axis=1) >= 0)
    for row in range(4):
        for start in range(0, 500, 37):
            run = slice(start, start + 37)
            drawn = np.sum((ancestors[row] >= start) & (ancestors[row] < start + 37))
            assert abs(drawn - 300 * W[row, run].sum()) < 1.0 + 1e-9


def test_systematic_never_draws_more_or_fewer_than_asked() -> None:
    W = np.full((3, 7), 1 / 7)  # sums that round above 1
    for seed in range(50):
        assert systematic(W, np.random.default_rng(seed), 1000).shape == (3, 1000)
    bad = np.array([[0.0, 0.0, 0.0], [np.nan, 1.0, 1.0]])
    assert systematic(bad, np.random.default_rng(0), 6).tolist()[0] == [0, 0, 1, 1, 2, 2]


def test_weights_and_ess() -> None:
    W = normalise(np.array([[1.0, 1.0, 2.0], [0.0, 0.0, 0.0]]))
    np.testing.assert_allclose(W, [[0.25, 0.25, 0.5], [1 / 3, 1 / 3, 1 / 3]])
    np.testing.assert_allclose(ess(W), [1 / (0.0625 * 2 + 0.25), 3.0])


def test_grouped_draws_stay_in_their_group_and_stratified_keeps_shares() -> None:
    rng = np.random.default_rng(1)
    group = np.array([0, 0, 0, 1, 1, 2])
    index = grouped_systematic(np.array([1.0, 2.0, 1.0, 1.0, 3.0, 5.0]), group, np.array([8, 4, 2]), rng)
    assert list(group[index]) == [0] * 8 + [1] * 4 + [2] * 2
    assert np.bincount(index[:8], minlength=3).tolist() == [2, 4, 2]
    draws = stratified(np.array([0.5, 0.25, 0.25]), 8, rng)
    assert sorted(np.bincount(draws, minlength=3).tolist()) == [2, 2, 4]
