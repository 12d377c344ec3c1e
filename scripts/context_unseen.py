#!/usr/bin/env python3
"""The old context suite (``--suite context_all``) on houses its policies were not developed on
(``seal_cli.bench.context.unseen_houses``; the same as ``seal bench tasks --suite context_all --houses unseen``, which
also takes ``--starts N``): the same commands, layouts drawn from the same priors, starts fixed with the house; the
same JSON as ``seal bench tasks --suite context_all --json``.

    python scripts/context_unseen.py --layouts 3 --jobs 2 --policies sefm,object_only,prior_optimal > unseen.json
"""

from __future__ import annotations

import argparse
import json
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT))

from seal_cli.bench import context  # noqa: E402
from seal_cli.bench.tasks import summarise  # noqa: E402


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--layouts", type=int, default=3)
    parser.add_argument("--jobs", type=int, default=2)
    parser.add_argument("--seed", type=int, default=0)
    parser.add_argument("--policies", default="sefm,object_only,prior_optimal")
    parser.add_argument("--episodes", type=Path, help="also write every outcome here as JSON Lines")
    parser.add_argument("--data", type=Path, default=ROOT / ".." / "shared" / "data",
                        help="the shared data folder (default: beside the checkout)")
    parser.add_argument("--house", action="append", default=[],
                        help="only this held-out house, by its map's name (repeatable; default: all of them)")
    parser.add_argument("--fov", type=float, help="every house's sensor sees this many degrees (default: 360)")
    args = parser.parse_args()
    names = [n.strip() for n in args.policies.split(",") if n.strip()]
    on = context.unseen_houses()
    unknown = [h for h in args.house if h not in {house.map.name for house in on}]
    if unknown:
        print(f"error: --house {unknown[0]!r}: one of {', '.join(house.map.name for house in on)}", file=sys.stderr)
        return 1
    if args.house:
        on = [house for house in on if house.map.name in args.house]
    if args.fov is not None and not 0 < args.fov <= 360:
        print(f"error: --fov {args.fov:g}: degrees in (0, 360]", file=sys.stderr)
        return 1
    on = context.with_fov(on, args.fov)
    outcomes = list(context.run_context_suite(args.data, names, layouts=args.layouts,
                                              seed=args.seed, jobs=args.jobs, on=on))
    if args.episodes is not None:
        args.episodes.write_text("".join(json.dumps(o.to_json()) + "\n" for o in outcomes), encoding="utf-8")
    report = summarise(outcomes, names)
    report.update({"suite": "context (unseen houses)", "layouts": args.layouts, "seed": args.seed, "fov": args.fov,
                   "by_command": context.regroup(outcomes, names, 1), "by_house": context.regroup(outcomes, names, 0),
                   "against_prior_optimal": context.paired(outcomes, names)})
    json.dump(report, sys.stdout, indent=1)
    print()
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
