"""The compiled inner loops (numba) give what the numpy passes give, bit for bit; without numba, numpy runs."""

from __future__ import annotations

import hashlib
from collections.abc import Callable, Iterator
from typing import TypeVar

import numpy as np
import pytest

from seal_cli.sefm import compiled
from seal_cli.sefm.potentials import GridKernelSums
from seal_cli.sefm.resampling import systematic

BOUNDS = (0.0, 0.0, 12.0, 8.0)
T = TypeVar("T")


@pytest.fixture
def numpy_only(monkeypatch: pytest.MonkeyPatch) -> Iterator[None]:
    monkeypatch.setenv("SEAL_NUMPY_ONLY", "1")
    compiled.kernels.cache_clear()
    yield
    monkeypatch.delenv("SEAL_NUMPY_ONLY")
    compiled.kernels.cache_clear()


def both(run: Callable[[], T], monkeypatch: pytest.MonkeyPatch) -> tuple[T, T]:
    """``run()`` with the compiled loops, then with numpy alone."""
    pytest.importorskip("numba")
    compiled.kernels.cache_clear()
    assert compiled.kernels() is not None
    fast = run()
    monkeypatch.setenv("SEAL_NUMPY_ONLY", "1")
    compiled.kernels.cache_clear()
    try:
        assert compiled.kernels() is None
        slow = run()
    finally:
        monkeypatch.delenv("SEAL_NUMPY_ONLY")
        compiled.kernels.cache_clear()
    return fast, slow


def grid_with_rows(rng: np.random.Generator) -> GridKernelSums:
    grid = GridKernelSums(5, BOUNDS, 0.3)
    X = rng.uniform((-1, -1), (13, 9), (5, 400, 2))  # some off the map: clamped into the grid
    W = rng.random((5, 400))
    grid.set(range(5), X, W / W.sum(axis=1, keepdims=True))
    grid.factor[:] = rng.uniform(0.5, 2, 5)
    return grid


@pytest.mark.parametrize("seed", [0, 1])
def test_reads_are_the_numpy_reads(seed: int, monkeypatch: pytest.MonkeyPatch) -> None:
    rng = np.random.default_rng(seed)
    grid = grid_with_rows(rng)
    points = rng.uniform((-3, -3), (15, 11), (7, 300, 2))
    sources = rng.integers(-1, 5, (7, 3))
    sources[2] = -1                                   # a row without terms reads 0
    weights = rng.random((7, 3))
    fast, slow = both(lambda: grid.combine(sources, weights, points), monkeypatch)
    assert fast.dtype == slow.dtype == np.float32 and fast.shape == (7, 300)
    np.testing.assert_array_equal(fast, slow)
    assert not fast[2].any() and fast.max() > 0


def test_binning_is_the_numpy_binning(monkeypatch: pytest.MonkeyPatch) -> None:
    rng = np.random.default_rng(3)
    X = rng.uniform((-1, -1), (13, 9), (4, 500, 2))
    W = rng.random((4, 500))
    W /= W.sum(axis=1, keepdims=True)
    index = rng.choice(500, 40, replace=False)

    def grids() -> np.ndarray:
        grid = GridKernelSums(4, BOUNDS, 0.3)
        grid.set(range(4), X, W)
        grid.reweight([(1, index, X[1, index], -0.5 * W[1, index], 0.9)])  # binned in a window around them
        return grid.grids.copy()

    fast, slow = both(grids, monkeypatch)
    np.testing.assert_array_equal(fast, slow)
    assert fast.sum() > 0


@pytest.mark.parametrize("count", [None, 7, 1000])
def test_systematic_draws_the_numpy_draws(count: int | None, monkeypatch: pytest.MonkeyPatch) -> None:
    rng = np.random.default_rng(5)
    W = rng.random((6, 300)) ** 4                      # uneven: many copies of a few
    W[3, 100:] = 0.0                                   # a row with empty runs

    def draw() -> np.ndarray:
        return systematic(W, np.random.default_rng(9), count)

    fast, slow = both(draw, monkeypatch)
    np.testing.assert_array_equal(fast, slow)
    assert fast.shape == (6, count or 300) and (np.diff(fast, axis=1) >= 0).all()


def test_a_row_without_weight_takes_the_numpy_way(monkeypatch: pytest.MonkeyPatch) -> None:
    W = np.ones((3, 10))
    W[1] = 0.0                                         # drawn as if uniform
    W[2, 4] = np.nan

    def draw() -> np.ndarray:
        return systematic(W, np.random.default_rng(0), 10)

    fast, slow = both(draw, monkeypatch)
    np.testing.assert_array_equal(fast, slow)
    assert fast[1].tolist() == list(range(10))


def test_a_whole_run_is_the_same_with_and_without_numba(monkeypatch: pytest.MonkeyPatch) -> None:
    """Building scale, a few updates: the beliefs hash the same either way."""
    from seal_cli.bench.perf import scale
    from seal_cli.frames.reading import load_library
    from seal_cli.maps.formats.map_server import load_map
    from seal_cli.resources import map_path
    from seal_cli.sefm.filter import SeFM, SeFMConfig
    from seal_cli.sensing.model import simulate_detections

    case = scale("building", load_library(None), lambda: load_map(map_path("apartment")))

    def run() -> str:
        rng = np.random.default_rng(0)
        sefm = SeFM(case.map, case.bindings[::6], case.state, rng, SeFMConfig(particles=200))
        for pose in case.path[:4]:
            sefm.update(pose, simulate_detections(case.map, pose, sefm.open_places(), rng), case.state)
        arrays = (sefm.frames.X, sefm.frames.gamma, sefm.objects.X, sefm.objects.W)
        return hashlib.sha1(b"".join(a.tobytes() for a in arrays)).hexdigest()

    fast, slow = both(run, monkeypatch)
    assert fast == slow


def test_without_numba_numpy_runs(numpy_only: None) -> None:
    assert compiled.kernels() is None
    rng = np.random.default_rng(0)
    grid = grid_with_rows(rng)
    out = grid.combine(np.array([[0, 1]]), np.ones((1, 2)), rng.uniform((0, 0), (12, 8), (1, 50, 2)))
    assert out.shape == (1, 50) and out.max() > 0


@pytest.mark.parametrize("shape", [(5, 300), (1, 7), (40, 1100), (9,)])
def test_the_cell_order_is_the_numpy_order(shape: tuple[int, ...], monkeypatch: pytest.MonkeyPatch) -> None:
    from seal_cli.bench.perf import building
    from seal_cli.sefm.cell_order import order_of_cells

    m = building(np.random.default_rng(0), classes=3, columns=2, rows=2)
    cells = np.random.default_rng(1).integers(-1, len(m.free_centres), shape)
    cells[..., : shape[-1] // 3] = cells[..., :1]    # ties, of a cell or of off free space
    fast, slow = both(lambda: order_of_cells(m, cells), monkeypatch)
    np.testing.assert_array_equal(fast, slow)
    assert fast.shape == shape and fast.dtype == np.intp


def test_an_interrupt_that_landed_while_numba_loaded_is_acted_on_not_run_past(monkeypatch: pytest.MonkeyPatch) -> None:
    """A SIGINT inside numba's import comes out as ImportError, one inside LLVM's callbacks is dropped ("Exception
    ignored"): either way the run went on — ``localize --steps 100000`` for minutes without its compiled loops
    (the reliability suite's "SIGINT during localize" hangs under load). Noted, it is raised here."""
    import builtins

    from seal_cli import fileio

    pytest.importorskip("numba")
    monkeypatch.setattr(fileio, "_INTERRUPTED", [True])
    compiled.kernels.cache_clear()
    with pytest.raises(KeyboardInterrupt):
        compiled.kernels()                                    # loaded, but an interrupt was noted meanwhile
    real_import = builtins.__import__

    def failing(name: str, *args: object, **kwargs: object) -> object:
        if name == "seal_cli.sefm" and args and "_jit" in (args[2] or ()):  # type: ignore[operator]
            raise ImportError("initialization failed")
        return real_import(name, *args, **kwargs)  # type: ignore[arg-type]

    monkeypatch.setattr(builtins, "__import__", failing)
    compiled.kernels.cache_clear()
    with pytest.raises(KeyboardInterrupt):
        compiled.kernels()
    monkeypatch.setattr(fileio, "_INTERRUPTED", [False])
    compiled.kernels.cache_clear()
    assert compiled.kernels() is None                        # no interrupt: numba is missing, numpy runs
    monkeypatch.undo()
    compiled.kernels.cache_clear()
    assert compiled.kernels() is not None
