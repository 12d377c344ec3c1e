#!/usr/bin/env python3
"""Fold the ``--episodes`` files of several ``seal bench tasks`` runs (seeds, or policies run
apart) into one table: per group and policy, the success rate and the mean path over every
episode of every file, and, for ``saycan``, the failure kinds counted.

    python scripts/summarise_episodes.py base_valid_gold_*.jsonl saycan_valid_gold_*.jsonl

Each file's rows are :class:`seal_cli.bench.tasks.Outcome` JSON; a (task, policy) seen in several
files counts once per file (one seed each). ``--markdown`` prints a Markdown table.
"""

from __future__ import annotations

import argparse
import json
import sys
from collections import Counter, defaultdict
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT))

from seal_cli.bench.alfred2d import TASK_TYPES  # noqa: E402

KINDS = ("unafforded action proposed", "object never found", "done too early", "out of budget")


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("files", nargs="+", type=Path)
    parser.add_argument("--markdown", action="store_true")
    args = parser.parse_args()
    rows: dict[tuple[str, str], list[dict]] = defaultdict(list)
    policies: list[str] = []
    for path in args.files:
        for line in path.read_text(encoding="utf-8").splitlines():
            o = json.loads(line)
            rows[(o["group"], o["policy"])].append(o)
            if o["policy"] not in policies:
                policies.append(o["policy"])
    groups = sorted({g for g, _ in rows}, key=lambda g: (TASK_TYPES.index(g) if g in TASK_TYPES else 99, g))
    table = [["group", "n", *policies]]
    for group in [*groups, "all"]:
        cells, n = [], 0
        for p in policies:
            runs = [o for (g, q), os_ in rows.items() if q == p and (group == "all" or g == group) for o in os_]
            n = max(n, len(runs))
            if not runs:
                cells.append("-")
                continue
            success = sum(o["success"] for o in runs) / len(runs)
            path = sum(o["path_m"] for o in runs) / len(runs)
            cells.append(f"{success:.3f} / {path:.2f}")
        table.append([group, str(n), *cells])
    print_table(table, args.markdown)
    saycan = [o for (_, q), os_ in rows.items() if q == "saycan" for o in os_]
    if saycan:
        failed = [o for o in saycan if not o["success"]]
        kinds = Counter(k for o in failed for k in KINDS if o["reason"].startswith(k) or f"; {k}" in
                        o["reason"].split(":")[0])
        print()
        print_table([["saycan", "episodes", "failed", *KINDS],
                     ["", str(len(saycan)), str(len(failed)), *(str(kinds[k]) for k in KINDS)]], args.markdown)
    return 0


def print_table(table: list[list[str]], markdown: bool) -> None:
    if markdown:
        print("| " + " | ".join(table[0]) + " |")
        print("|" + "---|" * len(table[0]))
        for row in table[1:]:
            print("| " + " | ".join(row) + " |")
        return
    widths = [max(len(r[i]) for r in table) for i in range(len(table[0]))]
    for row in table:
        print("  ".join(c.ljust(w) for c, w in zip(row, widths, strict=True)))


if __name__ == "__main__":
    raise SystemExit(main())
