#!/usr/bin/env python3
"""Time SeFM's decisions: the five map-suite commands on the apartment's layouts 0 and 1 in one process;
per run the path, the seconds in all and the seconds spent in ``SeFMPolicy.plan_view``.

    python scripts/time_plan_view.py
"""

from __future__ import annotations

import sys
import time
from pathlib import Path
from typing import Any

import numpy as np

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT))

from seal_cli.bench.mapsuite import COMMANDS, layout_seed, sample_layout  # noqa: E402
from seal_cli.frames.reading import load_library  # noqa: E402
from seal_cli.maps.formats.map_server import load_map  # noqa: E402
from seal_cli.pipeline import run_on_map  # noqa: E402
from seal_cli.sim.policies import make_policy  # noqa: E402
from seal_cli.sim.policies.sefm import SeFMPolicy  # noqa: E402


def main() -> int:
    spent = [0.0]
    plan_view = SeFMPolicy.plan_view

    def timed(self: SeFMPolicy, *args: Any, **kwargs: Any) -> Any:
        began = time.perf_counter()
        try:
            return plan_view(self, *args, **kwargs)
        finally:
            spent[0] += time.perf_counter() - began

    SeFMPolicy.plan_view = timed  # type: ignore[method-assign]
    library, m = load_library(None), load_map("apartment")
    rows = []
    for layout in range(2):
        base = layout_seed(0, layout, m.name)
        world = sample_layout(m, np.random.default_rng(base))
        for c, text in enumerate(COMMANDS):
            spent[0], began = 0.0, time.perf_counter()
            rng = np.random.default_rng(base + 1 + c)
            _, result = run_on_map(world, text, library, make_policy("sefm", 200), rng=rng)
            rows.append((time.perf_counter() - began, spent[0]))
            print(f"layout {layout}, {text}: {result.path_m:.2f} m, {rows[-1][0]:.1f} s, plan_view {rows[-1][1]:.1f} s")
    print(f"first run: {rows[0][0]:.1f} s, plan_view {rows[0][1]:.1f} s")
    later = np.asarray(rows[1:])
    print(f"later runs: mean {later[:, 0].mean():.2f} s, plan_view {later[:, 1].mean():.2f} s")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
