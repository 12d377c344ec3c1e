"""How fast the map queries are: what ``seal bench maps`` measures.

Each query runs on ``n`` points drawn uniformly over the map's free space (``seal bench maps``
uses 1,000 — one belief — and 60,000 — sixty beliefs, the building scale of the SPEC), from the
robot's pose, several times; the figure reported is the median wall-clock time of one call.
"""

from __future__ import annotations

import statistics
import time
from collections.abc import Callable, Sequence
from functools import partial
from pathlib import Path
from typing import Any

import numpy as np

from seal_cli.maps.formats.map_server import load_map
from seal_cli.maps.model import Map
from seal_cli.sensing.sensor import visible, visible_region

__all__ = ["bench_map"]


def _median_ms(run: Callable[[], Any], repeats: int) -> float:
    times = []
    for _ in range(repeats):
        start = time.perf_counter()
        run()
        times.append(time.perf_counter() - start)
    return 1000.0 * statistics.median(times)


def bench_map(path: str | Path, sizes: Sequence[int] = (1_000, 60_000), repeats: int = 5, seed: int = 0
              ) -> dict[str, Any]:
    """Median milliseconds per call of each map query, per number of points."""
    load_ms = _median_ms(lambda: load_map(path), max(1, repeats // 2))
    m: Map = load_map(path)
    rng = np.random.default_rng(seed)
    pose = m.robot.pose
    cls = next(iter(m.priors), "thing")
    prior = m.prior(cls)
    region = visible_region(m, pose)
    rows: list[dict[str, Any]] = []
    for n in sizes:
        points = m.sample_free(rng, n)
        queries: dict[str, Callable[[], Any]] = {
            "is_free": partial(m.is_free, points),
            "room_index": partial(m.room_index, points),
            "line_of_sight": partial(m.line_of_sight, pose[:2], points),
            "visible (exact)": partial(visible, m, pose, points),
            "visible region contains": partial(region.contains, points),
            f"prior density ({cls})": partial(prior.density, points),
            f"prior sample ({cls})": partial(prior.sample, n, rng),
            "sample_free": partial(m.sample_free, rng, n),
        }
        for name, run in queries.items():
            rows.append({"query": name, "points": n, "ms": round(_median_ms(run, repeats), 3)})
    region_ms = _median_ms(lambda: visible_region(m, pose), repeats)
    return {"map": m.name, "grid": list(m.grid.shape), "resolution": m.grid.resolution,
            "rooms": len(m.rooms), "free_area_m2": round(m.free_area, 2), "load_ms": round(load_ms, 2),
            "visible_region_ms": round(region_ms, 3), "rays": len(region.angles), "queries": rows}
