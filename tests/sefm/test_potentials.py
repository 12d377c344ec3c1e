"""Kernel sums: the exact O(P²) reference and the binned grid engine give the same answer."""

from __future__ import annotations

import numpy as np
import pytest

from seal_cli.sefm.potentials import ExactKernelSums, GridKernelSums, exact_kernel_sum, make_kernel_sums

BOUNDS = (0.0, 0.0, 12.0, 8.0)


def clouds(rng: np.random.Generator, sources: int, particles: int) -> tuple[np.ndarray, np.ndarray]:
    """Particle sets like beliefs: a tight cluster, a room-sized spread, and a thin floor everywhere."""
    centres = rng.uniform((1, 1), (11, 7), (sources, 3, 2))
    X = np.concatenate([centres[:, :1] + rng.normal(0, 0.3, (sources, particles // 3, 2)),
                        centres[:, 1:2] + rng.uniform(-2, 2, (sources, particles // 3, 2)),
                        rng.uniform(BOUNDS[:2], BOUNDS[2:], (sources, particles - 2 * (particles // 3), 2))], axis=1)
    X = np.clip(X, BOUNDS[:2], BOUNDS[2:])
    W = rng.random((sources, particles))
    return X, W / W.sum(axis=1, keepdims=True)


def tv(a: np.ndarray, b: np.ndarray) -> float:
    return float(0.5 * np.abs(a / a.sum() - b / b.sum()).sum())


def test_exact_sum_by_hand() -> None:
    points = np.array([[0.0, 0.0], [1.0, 0.0]])
    positions = np.array([[0.0, 0.0], [0.0, 2.0]])
    weights = np.array([0.25, 0.75])
    got = exact_kernel_sum(points, positions, weights, sigma=1.0)
    want = [0.25 + 0.75 * np.exp(-2.0), 0.25 * np.exp(-0.5) + 0.75 * np.exp(-2.5)]
    np.testing.assert_allclose(got, want)


def test_exact_chunks_do_not_change_the_answer() -> None:
    rng = np.random.default_rng(0)
    X, W = clouds(rng, 1, 300)
    points = rng.uniform(BOUNDS[:2], BOUNDS[2:], (257, 2))
    whole = exact_kernel_sum(points, X[0], W[0], 0.3, chunk=1 << 30)
    np.testing.assert_allclose(exact_kernel_sum(points, X[0], W[0], 0.3, chunk=300), whole)
    np.testing.assert_allclose(exact_kernel_sum(points, X[0], W[0], 0.3, chunk=1), whole)


@pytest.mark.parametrize("seed", range(3))
def test_grid_matches_exact_within_the_tv_bound(seed: int) -> None:
    rng = np.random.default_rng(seed)
    X, W = clouds(rng, 4, 600)
    exact, grid = ExactKernelSums(4, 600, 0.3), GridKernelSums(4, BOUNDS, 0.3)
    for kernel in (exact, grid):
        kernel.set(range(4), X, W)
    which = np.array([0, 1, 2, 3, 0])
    queries = np.clip(X[[1, 2, 3, 0, 0]] + rng.normal(0, 0.4, (5, 600, 2)), BOUNDS[:2], BOUNDS[2:])
    a, b = exact.sample(which, queries), grid.sample(which, queries)
    floor = 1e-3  # the frame filter never weighs a particle by K alone: it adds a floor
    assert max(tv(a[t] + floor, b[t] + floor) for t in range(5)) < 0.01
    np.testing.assert_allclose(b, a, atol=0.02 * a.max())


def test_a_single_particle_gives_the_gaussian_itself() -> None:
    grid = GridKernelSums(1, BOUNDS, 0.3)
    grid.set([0], np.array([[[6.0, 4.0]]]), np.array([[1.0]]))
    d = np.linspace(0, 1.2, 13)
    got = grid.sample(np.array([0]), np.column_stack([6.0 + d, np.full_like(d, 4.0)])[None])[0]
    # one particle is the worst case (binning and interpolation errors do not average out): 4 % of the peak
    np.testing.assert_allclose(got, np.exp(-d ** 2 / (2 * 0.09)), atol=0.04)


@pytest.mark.parametrize("kind", ["grid", "exact"])
def test_reweighting_a_few_particles_equals_setting_again(kind: str) -> None:
    rng = np.random.default_rng(4)
    X, W = clouds(rng, 2, 300)
    kernel = make_kernel_sums(kind, 2, 300, BOUNDS, 0.3)
    kernel.set([0, 1], X, W)
    index = np.flatnonzero(np.hypot(*(X[1] - X[1, 0]).T) < 1.5)
    L = np.ones(300)
    L[index] = 0.1  # negative information around one spot
    raw = W[1] * L
    kernel.reweight([(1, index, X[1, index], W[1, index] * (L[index] - 1), float(raw.sum()))])
    fresh = make_kernel_sums(kind, 2, 300, BOUNDS, 0.3)
    fresh.set([0, 1], X, np.stack([W[0], raw / raw.sum()]))
    points = rng.uniform(BOUNDS[:2], BOUNDS[2:], (2, 400, 2))
    np.testing.assert_allclose(kernel.sample(np.array([0, 1]), points), fresh.sample(np.array([0, 1]), points),
                               atol=1e-6)


def test_grid_memory_grows_with_the_map_not_with_particles_squared() -> None:
    grid = GridKernelSums(3, BOUNDS, 0.3)
    assert grid.cell == pytest.approx(0.15)
    assert grid.grids.shape[0] == 3 and grid.grids[0].size < 10_000
    exact = ExactKernelSums(1, 5000, 0.3, chunk=1 << 16)
    exact.set([0], np.zeros((1, 5000, 2)), np.full((1, 5000), 1 / 5000))
    out = exact.sample(np.array([0]), np.zeros((1, 5000, 2)))
    np.testing.assert_allclose(out, 1.0)


def test_unknown_kernel_is_refused() -> None:
    with pytest.raises(ValueError, match="grid"):
        make_kernel_sums("fft", 1, 1, BOUNDS, 0.3)


@pytest.mark.parametrize("kind", ["grid", "exact"])
def test_combine_is_the_weighted_sum_of_samples(kind: str) -> None:
    """A frame's potential: Σ_s w_rs K_{source_rs} at each of row r's points; −1 is no term; rows of a split
    kernel are answered by the part that holds them."""
    rng = np.random.default_rng(5)
    X, W = clouds(rng, 4, 300)
    kernel = make_kernel_sums(kind, 4, 300, BOUNDS, 0.3, split=2)
    kernel.set(range(4), X, W)
    sources = np.array([[0, 3], [1, -1], [-1, -1]])
    weights = np.array([[1.0, 0.3], [0.5, 7.0], [2.0, 2.0]])
    points = rng.uniform(BOUNDS[:2], BOUNDS[2:], (3, 50, 2))
    got = kernel.combine(sources, weights, points)
    K = lambda s, r: kernel.sample(np.array([s]), points[r][None])[0]  # noqa: E731
    np.testing.assert_allclose(got[0], K(0, 0) + 0.3 * K(3, 0), rtol=1e-5, atol=1e-7)
    np.testing.assert_allclose(got[1], 0.5 * K(1, 1), rtol=1e-5, atol=1e-7)
    np.testing.assert_array_equal(got[2], 0.0)


@pytest.mark.parametrize("banded", [True, False])
def test_the_grid_smoothing_is_the_gaussian_filter(banded: bool, monkeypatch: pytest.MonkeyPatch) -> None:
    """The banded matrix products compute what scipy.ndimage's Gaussian filter does (zeros outside); a grid
    too long for a band matrix uses the filter itself."""
    from scipy import ndimage

    import seal_cli.sefm.potentials as potentials

    if not banded:
        monkeypatch.setattr(potentials, "MAX_BAND", 10)
    grid = GridKernelSums(2, BOUNDS, 0.3)
    assert (grid._band is not None) == banded
    mass = np.random.default_rng(7).random((2, 40, 31)).astype(np.float32)
    want = ndimage.gaussian_filter(mass.astype(float), (0, grid.filter_sigma, grid.filter_sigma), mode="constant",
                                   truncate=grid.truncate) * grid.scale
    np.testing.assert_allclose(grid._smooth(mass), want, rtol=1e-5, atol=1e-5 * want.max())


def test_moving_particles_by_stamps_equals_setting_again() -> None:
    """On a large map, a few particles taken out and put in are stamped into the grid, not smoothed over
    the whole of it; the grid is what setting the rows afresh gives (particles at the grid's very edges
    too), and after ``RESET_AFTER`` moves the rows are set afresh."""
    import seal_cli.sefm.potentials as potentials

    rng = np.random.default_rng(8)
    bounds, P = (0.0, 0.0, 60.0, 40.0), 400
    X = rng.uniform(bounds[:2], bounds[2:], (2, P, 2))
    X[0, :3] = [[0.0, 0.0], [60.0, 40.0], [-3.0, 45.0]]  # at the corners, and off the map (clamped)
    W = np.full((2, P), 1.0 / P)
    grid = GridKernelSums(2, bounds, 0.3, cell=0.3)
    grid.set([0, 1], X, W)
    for step in range(3):
        k = rng.choice(P, 30, replace=False)
        rows = np.repeat([0, 1], 30)
        gone = X[rows, np.tile(k, 2)].copy()
        X[rows, np.tile(k, 2)] = rng.uniform(bounds[:2], bounds[2:], (60, 2))
        come = X[rows, np.tile(k, 2)]
        grid.move([0, 1], X, W, (rows, gone, np.full(60, 1.0 / P)), (rows, come, np.full(60, 1.0 / P)))
        assert grid.moves.tolist() == [step + 1] * 2
    fresh = GridKernelSums(2, bounds, 0.3, cell=0.3)
    fresh.set([0, 1], X, W)
    np.testing.assert_allclose(grid.grids, fresh.grids, atol=1e-6 * fresh.grids.max())
    grid.moves[:] = potentials.RESET_AFTER
    grid.move([0, 1], X, W, (np.zeros(0, np.intp), np.zeros((0, 2)), np.zeros(0)),
              (np.zeros(0, np.intp), np.zeros((0, 2)), np.zeros(0)))
    assert grid.moves.tolist() == [0, 0] and np.array_equal(grid.grids, fresh.grids)


def test_on_a_small_map_moving_particles_sets_the_rows_afresh() -> None:
    """Where smoothing the whole grid costs less than the stamps, a move is a set: the same numbers, bit for bit."""
    rng = np.random.default_rng(9)
    X, W = clouds(rng, 1, 300)
    grid, fresh = GridKernelSums(1, BOUNDS, 0.3, cell=0.3), GridKernelSums(1, BOUNDS, 0.3, cell=0.3)
    grid.set([0], X, W)
    moved = X.copy()
    moved[0, :200] = rng.uniform(BOUNDS[:2], BOUNDS[2:], (200, 2))
    rows = np.zeros(200, np.intp)
    grid.move([0], moved, W, (rows, X[0, :200], W[0, :200]), (rows, moved[0, :200], W[0, :200]))
    fresh.set([0], moved, W)
    assert grid.moves.tolist() == [0] and np.array_equal(grid.grids, fresh.grids)
