#!/usr/bin/env python3
"""The context suite's cases: every candidate (``seal_cli.bench.headroom.candidates``: the candidate commands from
drawn starts on each house, priors and map alone, no layout, no policy) with its criterion values, and the ones that
fit (``headroom.selected``), written to ``seal_cli/bench/suites/context_cases.json``; ``--check``: refuse if the
file is not what the criterion gives now.

    python scripts/context_cases.py                 # rebuild (about 15 min)
    python scripts/context_cases.py --check         # the same, compared with the file
    python scripts/context_cases.py --house mews --out part.json   # one house's part
    python scripts/context_cases.py --held-out      # the held-out houses' cases (context_held_out_cases.json)
"""

from __future__ import annotations

import argparse
import json
import sys
from pathlib import Path
from typing import Any

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT))

from seal_cli.bench import context, headroom  # noqa: E402
from seal_cli.errors import SealError  # noqa: E402
from seal_cli.frames.reading import load_library  # noqa: E402


def document(cases: list[headroom.Headroom], houses: list[str]) -> dict[str, Any]:
    """The file's contents: how the candidates were made, the criterion, every candidate and the selected ones."""
    return {"criterion": f"the joint programme's first region differs from one thing at a time's and the expected "
                         f"saving is at least {headroom.FITS_SHARE} of the one-at-a-time path (bench/headroom.py)",
            "fits_share": headroom.FITS_SHARE, "houses": houses, "starts": headroom.CANDIDATE_STARTS,
            "seed": headroom.CANDIDATE_SEED, "commands": list(headroom.CANDIDATE_COMMANDS),
            "cases": [c.to_json() for c in headroom.selected(cases)],
            "candidates": [c.to_json() for c in cases]}


def written(doc: dict[str, Any]) -> str:
    """The file's text: the head's fields one a line, then each case and each candidate on a line of its own."""
    lines = [f" {json.dumps(k)}: {json.dumps(v)}," for k, v in doc.items() if k not in ("cases", "candidates")]
    for key in ("cases", "candidates"):
        rows = ",\n".join(f"  {json.dumps(c)}" for c in doc[key])
        lines.append(f" {json.dumps(key)}: [\n{rows}\n ]" + ("," if key == "cases" else ""))
    return "{\n" + "\n".join(lines) + "\n}\n"


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--data", type=Path, default=ROOT / ".." / "shared" / "data",
                        help="the shared data folder (default: beside the checkout), for the AWS house")
    parser.add_argument("--house", action="append", default=[], help="only this house (repeatable; default: all)")
    parser.add_argument("--held-out", action="store_true",
                        help="the held-out houses (context.held_out_houses) instead of the suite's; default --out: "
                             "context_held_out_cases.json")
    parser.add_argument("--out", type=Path, help="where to write (default: the suite's cases file)")
    parser.add_argument("--check", action="store_true", help="write nothing; exit 1 if --out differs")
    args = parser.parse_args()
    if args.out is None:
        args.out = context.HELD_OUT_CASES_FILE if args.held_out else context.CASES_FILE
    try:
        built = context.held_out_houses() if args.held_out else context.candidate_houses(args.data)
    except SealError as error:
        print(f"error: {error.message}", file=sys.stderr)
        return 1
    names = [h.map.name for h in built]
    unknown = [h for h in args.house if h not in names]
    if unknown:
        print(f"error: --house {unknown[0]!r}: one of {', '.join(names)}", file=sys.stderr)
        return 1
    built = [h for h in built if not args.house or h.map.name in args.house]
    cases = list(headroom.candidates(built, load_library(None)))
    text = written(document(cases, [h.map.name for h in built]))
    if args.check:
        try:
            same = args.out.read_text(encoding="utf-8") == text
        except OSError as error:
            print(f"error: {args.out}: {error.strerror}", file=sys.stderr)
            return 1
        if not same:
            print(f"error: {args.out} is not what the criterion gives now: rebuild it", file=sys.stderr)
            return 1
        print(f"{args.out}: up to date ({len(headroom.selected(cases))} cases)")
        return 0
    args.out.write_text(text, encoding="utf-8")
    print(f"{args.out}: {len(cases)} candidates, {len(headroom.selected(cases))} cases", file=sys.stderr)
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
