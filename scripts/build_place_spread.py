#!/usr/bin/env python3
"""Rebuild ``SeFMPolicy.ON_PLACE`` (``seal_cli/sim/policies/sefm.py``): where on a receptacle that does not open a
thing lies, as a share of the receptacle pivot's distance to the nearest reachable position, at the quantiles
1/8, 3/8, 5/8 and 7/8 of ALFRED-2D's train split (:func:`seal_cli.bench.alfred2d.place_spread`). SeFM's search
in one room takes a thing found on an open place to lie at those distances from the pivot, to count the drive
to where it is picked up from (docs/benchmarks.md, "This round (search15)"). ``--check`` exits 1 when the
shipped figures differ.

    python scripts/build_place_spread.py [--data ../shared/data/alfred2d] [--check]
"""

from __future__ import annotations

import argparse
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT))

from seal_cli.bench.alfred2d import place_spread, read_floorplans, read_trials  # noqa: E402
from seal_cli.sim.policies.sefm import SeFMPolicy  # noqa: E402


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--data", type=Path, default=ROOT.parent / "shared" / "data" / "alfred2d")
    parser.add_argument("--check", action="store_true", help="exit 1 when SeFMPolicy.ON_PLACE differs")
    args = parser.parse_args()
    plans, _ = read_floorplans(args.data)
    spread = place_spread(read_trials(args.data, "train", plans), plans)
    print(f"ON_PLACE = {spread}")
    if args.check and spread != tuple(SeFMPolicy.ON_PLACE):
        print(f"shipped: {tuple(SeFMPolicy.ON_PLACE)}", file=sys.stderr)
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
