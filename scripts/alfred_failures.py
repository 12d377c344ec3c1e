#!/usr/bin/env python3
"""Why ALFRED-2D episodes run from the human goal sentences failed: each failed episode of a
``seal bench tasks --suite alfred2d --goal human --episodes FILE`` run, classified by its first cause.

Each failed episode's first goal sentence is parsed again as the runner parses it (grounded in the
classes of the episode's room, ``alfred2d.scene_vocabulary``) and read back into ALFRED's five fields
the way ``../shared/eval/score_alfred_goals.py`` reads a parse; the first field that differs from the
trial's labels names the cause, in this order:

- ``parse error``: the sentence did not parse (the runner's "cannot read the command");
- ``task type``, ``object class``, ``receptacle``, ``movable receptacle``, ``sliced``: the field read wrong;
- ``budget``: the parse read right and the run ran out of its budget;
- ``execution``: the parse read right and the run ended without the goal (the search never found a
  thing, an action failed, or the world was not as the task wants at the end).

With ``--gold FILE`` (the ``--episodes`` file of a ``--goal gold`` run of the same split), an
``execution`` or ``budget`` episode the gold frames also failed is counted apart (``... (gold failed
too)``). Classes are compared without case or underscores.

    python scripts/alfred_failures.py /tmp/human.jsonl [--gold /tmp/gold.jsonl] [--split valid_seen] [--list]
"""

from __future__ import annotations

import argparse
import importlib.util
import json
import sys
from collections import Counter
from pathlib import Path
from typing import Any

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT))

from seal_cli.bench.alfred2d import TASK_TYPES, Task, build_scene, load_suite, scene_vocabulary  # noqa: E402
from seal_cli.errors import SealError  # noqa: E402
from seal_cli.frames.reading import load_library  # noqa: E402
from seal_cli.language.parser import parse_command  # noqa: E402

CAUSES = ("parse error", "task type", "object class", "receptacle", "movable receptacle", "sliced", "budget",
          "execution", "budget (gold failed too)", "execution (gold failed too)")
FIELD_CAUSE = {"type": "task type", "object": "object class", "receptacle": "receptacle",
               "mrecep": "movable receptacle", "sliced": "sliced"}


def scorer(path: Path) -> Any:
    """The shared ALFRED goal scorer, loaded as a module (its ``read_back`` and ``gold``)."""
    spec = importlib.util.spec_from_file_location("score_alfred_goals", path)
    if spec is None or spec.loader is None or not path.is_file():
        raise SystemExit(f"error: {path}: cannot load the ALFRED goal scorer")
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def labels(task: Task) -> dict[str, str]:
    """The trial's labels as a row of the goal scorer's TSV."""
    return {"task_type": task.type, "object": task.object, "receptacle": task.receptacle or "",
            "mrecep": task.mrecep or "", "sliced": "1" if task.sliced else "0"}


def same(a: object, b: object) -> bool:
    """Two read-back values alike: classes compared without case or underscores (the scene grounds to class
    keys, ``spray_bottle``; the labels are THOR's names, ``SprayBottle``)."""
    if isinstance(a, str) and isinstance(b, str):
        return a.replace("_", "").lower() == b.replace("_", "").lower()
    return a == b


def classify(outcome: dict[str, Any], got: dict[str, Any] | None, want: dict[str, Any],
             gold_failed: bool) -> tuple[str, list[str]]:
    """The first cause of one failed episode, and every field read wrong (``got`` None: no parse)."""
    if got is None:
        return "parse error", []
    wrong = [f for f in ("type", "object", "receptacle", "mrecep", "sliced") if not same(got[f], want[f])]
    if wrong:
        return FIELD_CAUSE[wrong[0]], wrong
    cause = "budget" if "budget" in outcome["reason"] else "execution"
    return (f"{cause} (gold failed too)" if gold_failed else cause), []


def read_outcomes(path: Path, policy: str) -> dict[str, dict[str, Any]]:
    rows: dict[str, dict[str, Any]] = {}
    try:
        text = path.read_text(encoding="utf-8")
    except OSError as error:
        raise SystemExit(f"error: {path}: {error.strerror}") from None
    for number, line in enumerate(text.splitlines(), 1):
        if not line.strip():
            continue
        try:
            row = json.loads(line)
            if row["policy"] == policy:
                rows[row["task_id"]] = row
        except (json.JSONDecodeError, KeyError, TypeError):
            raise SystemExit(f"error: {path}:{number}: not an episode outcome (JSON with task_id, policy)") from None
    return rows


def report(outcomes: dict[str, dict[str, Any]], suite: Any, module: Any, gold: dict[str, dict[str, Any]], *,
           markdown: bool, listing: bool) -> None:
    """Print each failed episode's first cause by task type (a table; with ``listing`` every failure too).
    ``module`` is the goal scorer (:func:`scorer`), ``gold`` the outcomes of a gold run of the same episodes (an
    episode that failed there too is counted as execution's)."""
    library = load_library()
    by_type: dict[str, Counter[str]] = {}
    total: Counter[str] = Counter()
    listed = []
    for episode in suite.episodes:
        outcome = outcomes.get(episode.task_id)
        if outcome is None:
            continue
        counts = by_type.setdefault(episode.group, Counter())
        counts["n"] += 1
        total["n"] += 1
        if outcome["success"]:
            continue
        scene = build_scene(episode, suite.floor_plans[episode.floor_plan], library, suite.priors)
        sentence = " ".join(episode.goals[0].split())
        try:
            parse = parse_command(sentence, library, scene_vocabulary(scene.vocabulary)).to_json()
            got = module.read_back(parse) if parse.get("frames") else None
        except SealError:
            got = None
        want = module.gold(labels(episode.task))
        gold_failed = episode.task_id in gold and not gold[episode.task_id]["success"]
        cause, wrong = classify(outcome, got, want, gold_failed)
        counts[cause] += 1
        total[cause] += 1
        listed.append((cause, episode.group, sentence, wrong, got, want, outcome["reason"]))
    groups = sorted(by_type, key=lambda g: TASK_TYPES.index(g) if g in TASK_TYPES else 99)
    causes = [c for c in CAUSES if total[c]]
    header = ["type", "n", "failed", *causes]
    table = [header]
    for group, counts in [*((g, by_type[g]) for g in groups), ("all", total)]:
        failed = sum(counts[c] for c in causes)
        table.append([group, str(counts["n"]), str(failed), *(str(counts[c]) for c in causes)])
    if markdown:
        print("| " + " | ".join(header) + " |")
        print("|" + "---|" * len(header))
        for row in table[1:]:
            print("| " + " | ".join(row) + " |")
    else:
        widths = [max(len(r[i]) for r in table) for i in range(len(header))]
        for row in table:
            print("  ".join(cell.ljust(w) for cell, w in zip(row, widths, strict=True)))
    if listing:
        for cause, group, sentence, wrong, got, want, reason in sorted(listed, key=lambda x: CAUSES.index(x[0])):
            detail = ", ".join(f"{f}: {got[f] if got else None} want {want[f]}" for f in wrong) or reason
            print(f"[{cause}] {group}: {sentence!r} -- {detail}")


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("episodes", type=Path, help="the --episodes file of a --goal human run")
    ap.add_argument("--gold", type=Path, help="the --episodes file of a --goal gold run of the same split")
    ap.add_argument("--data", type=Path, default=ROOT.parent / "shared" / "data")
    ap.add_argument("--split", default="valid_seen")
    ap.add_argument("--policy", default="sefm")
    ap.add_argument("--list", action="store_true", help="print every failed episode with its cause")
    ap.add_argument("--markdown", action="store_true")
    args = ap.parse_args()

    outcomes = read_outcomes(args.episodes, args.policy)
    gold = read_outcomes(args.gold, args.policy) if args.gold else {}
    module = scorer(args.data.parent / "eval" / "score_alfred_goals.py")
    try:
        suite = load_suite(args.data / "alfred2d", args.split)
    except SealError as error:
        raise SystemExit(f"error: {error}") from None
    report(outcomes, suite, module, gold, markdown=args.markdown, listing=args.list)
    return 0


if __name__ == "__main__":
    sys.exit(main())
