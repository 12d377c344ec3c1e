#!/usr/bin/env python3
"""How much frame context can save in each context-suite case, from the priors and the map alone
(``seal_cli.bench.headroom``: the exact programme over regions against one thing at a time; no layout, no run).

    python scripts/context_headroom.py --houses suite --houses unseen > headroom.json
"""

from __future__ import annotations

import argparse
import json
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT))

from seal_cli.bench import context, headroom  # noqa: E402
from seal_cli.errors import SealError  # noqa: E402
from seal_cli.frames.reading import load_library  # noqa: E402


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--houses", action="append", default=[],
                        help=f"a set of houses, one of {', '.join(context.HOUSE_SETS)} (repeatable; default: suite)")
    parser.add_argument("--data", type=Path, default=ROOT / ".." / "shared" / "data",
                        help="the shared data folder (default: beside the checkout)")
    parser.add_argument("--starts", type=int,
                        help="this many starts per house drawn with --seed (context.drawn_starts), not the house's own")
    parser.add_argument("--seed", type=int, default=0, help="the seed of the drawn starts")
    args = parser.parse_args()
    if args.starts is not None and args.starts < 1:
        print(f"error: --starts {args.starts}: at least 1", file=sys.stderr)
        return 1
    try:
        built = [h for name in (args.houses or ["suite"]) for h in context.house_set(name, args.data)]
    except SealError as error:
        print(f"error: {error.message}", file=sys.stderr)
        return 1
    if args.starts is not None:
        built = [context.House(h.map, context.drawn_starts(h.map, args.starts, args.seed)) for h in built]
    cases = [{**c.to_json(), "pose": list(built_pose)} for c, built_pose in
             ((c, next(h for h in built if h.map.name == c.house).starts[c.start - 1])
              for c in headroom.headrooms(built, load_library(None)))]
    by_house: dict[str, dict[str, float]] = {}
    for c in cases:
        h = by_house.setdefault(c["house"], {"joint_m": 0.0, "one_at_a_time_m": 0.0, "n": 0, "fits": 0})
        h["joint_m"] += c["joint_m"]
        h["one_at_a_time_m"] += c["one_at_a_time_m"]
        h["n"] += 1
        h["fits"] += int(c["fits"])
    for h in by_house.values():
        h["saving"] = round(1 - h["joint_m"] / h["one_at_a_time_m"], 4) if h["one_at_a_time_m"] else 0.0
        h["joint_m"] = round(h["joint_m"] / h["n"], 3)
        h["one_at_a_time_m"] = round(h["one_at_a_time_m"] / h["n"], 3)
    json.dump({"fits_share": headroom.FITS_SHARE, "starts": args.starts, "seed": args.seed, "by_house": by_house,
               "cases": cases}, sys.stdout, indent=1)
    print()
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
