#!/usr/bin/env python3
"""ALFRED-2D on train floor plans held out of every statistic: the measurement of the unseen floor plans we can make.

``valid_unseen`` is not in our data, and every statistic seal ships for ALFRED was fitted on all of train: the
word-class table with its step, stack, slice, goal and task models (``seal_cli/language/word_classes/``), the
words' model of the task fields (``seal_cli/language/task_fields/``) and the place priors SeFM searches with
(:func:`seal_cli.bench.alfred2d.train_priors`). This script holds out a fraction of train's floor plans by the hash
``build_word_classes.py --dev F --hold-out floor-plans`` uses, fits all three on the other floor plans' trials exactly
as their build scripts do, puts them in place of the shipped ones in this process, and runs the policies on a
stratified sample of the held-out floor plans' trials (``--sample`` per task type, as ``seal bench tasks --sample``
chooses them), from the first human goal sentence (``--goal human``) or ALFRED's labels (``--goal gold``), as ``seal
bench tasks`` runs an episode (:func:`seal_cli.bench.tasks.run_episode`). It prints the success rate and mean path
per task type (the bench's JSON with ``--json``), writes every outcome to ``--episodes`` (JSON Lines, as the bench's
``--episodes``), and with ``--causes`` classifies each failed episode by its first cause as
``scripts/alfred_failures.py`` does, its sentence parsed again with the refitted statistics.

    python scripts/alfred2d_held_out.py --sample 40 --episodes /tmp/held.jsonl --causes
    python scripts/alfred2d_held_out.py --sample 40 --goal gold --episodes /tmp/held_gold.jsonl
    python scripts/alfred2d_held_out.py --goal gold --policies sefm,object_only --trial trial_T20190908_204024_506453

Not refitted: SeFM's place spread (``SeFMPolicy.ON_PLACE``, four quantiles of where a thing lies on a surface) and the
suite's vocabulary file (THOR's names, not learned).
"""

from __future__ import annotations

import argparse
import importlib.util
import json
import sys
import tempfile
from pathlib import Path
from types import ModuleType
from typing import Any

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT))

from seal_cli.bench import alfred2d  # noqa: E402
from seal_cli.bench.tasks import GOALS, Outcome, run_episode, summarise  # noqa: E402
from seal_cli.errors import SealError  # noqa: E402
from seal_cli.frames.reading import load_library  # noqa: E402
from seal_cli.language import taskfields, wordusage  # noqa: E402


def script(name: str) -> ModuleType:
    """Another script of this folder, loaded as a module."""
    path = ROOT / "scripts" / f"{name}.py"
    spec = importlib.util.spec_from_file_location(name, path)
    assert spec is not None and spec.loader is not None
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def fit_statistics(data: Path, rows: list[dict[str, str]], folder: Path, bwc: ModuleType) -> None:
    """The word-class table and the task fields' model fitted on ``rows`` as their build scripts fit them (the
    word-class table as ``build_word_classes.py --dev`` fits it, with its scenes' weights, and with the scenery the
    shipped table lists, of ``rows``' floor plans only: without it a scene with a faucet or a shower head is out of
    the statistics' scope, and no step, goal, task or field is inferred there), written into ``folder`` and put in
    place of the shipped ones for the rest of this process."""
    classes = json.loads((data / "alfred" / "alfred_constants.json").read_text())["OBJECTS"]
    vocabulary = bwc.Vocabulary.of(classes)
    table = bwc.table(*bwc.count(rows, vocabulary, bwc.scene_classes(data, classes)), classes,
                      "held-out floor plans", bwc.L2, bwc.SCENE_L2)
    table = bwc.with_stack_goals(bwc.with_steps(table, rows, vocabulary), rows, vocabulary)
    table["scenery"] = bwc.scenery(data, classes, {r["floor_plan"] for r in rows})
    (folder / "word_classes").mkdir()
    (folder / "word_classes" / "alfred_train.json").write_text(bwc.dump(table), encoding="utf-8")
    (folder / "task_fields.json").write_text(
        taskfields.model_json(taskfields.fit_fields(rows), "held-out floor plans"), encoding="utf-8")
    wordusage.SHIPPED = folder / "word_classes"
    taskfields.SHIPPED = folder / "task_fields.json"
    wordusage.shipped_word_usage.cache_clear()
    taskfields.shipped_field_model.cache_clear()


def causes(outcomes: dict[str, dict[str, Any]], suite: alfred2d.Suite, data: Path, markdown: bool,
           listing: bool) -> None:
    """Each failed episode's first cause (``scripts/alfred_failures.py``'s classification), by task type."""
    af = script("alfred_failures")
    af.report(outcomes, suite, af.scorer(data.parent / "eval" / "score_alfred_goals.py"), {}, markdown=markdown,
              listing=listing)


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--data", type=Path, default=ROOT.parent / "shared" / "data", help="the shared data folder")
    ap.add_argument("--dev", type=float, default=0.2, help="the fraction of train's floor plans held out")
    ap.add_argument("--sample", type=int, default=40, help="episodes per task type, of the held-out floor plans")
    ap.add_argument("--goal", default="human", choices=GOALS)
    ap.add_argument("--policies", default="sefm", help="comma-separated policies")
    ap.add_argument("--seed", type=int, default=0)
    ap.add_argument("--particles", type=int, default=200)
    ap.add_argument("--episodes", type=Path, help="write every outcome here (JSON Lines)")
    ap.add_argument("--causes", action="store_true", help="classify each failed episode by its first cause")
    ap.add_argument("--list", action="store_true", help="with --causes: print every failed episode")
    ap.add_argument("--markdown", action="store_true", help="with --causes: the table in Markdown")
    ap.add_argument("--json", action="store_true", help="print the bench's JSON")
    ap.add_argument("--trial", action="append", default=[],
                    help="run only this trial of the sample (its task id; repeatable): one episode to trace")
    args = ap.parse_args()
    if not 0 < args.dev < 1:
        raise SystemExit(f"error: --dev {args.dev}: a fraction in (0, 1)")
    if args.sample < 1 or args.particles < 1:
        raise SystemExit("error: --sample and --particles: at least 1")
    goals = args.data / "alfred" / "goals_train.tsv"
    for path in (goals, args.data / "alfred" / "alfred_constants.json", args.data / "alfred2d" / "floorplans.json"):
        if not path.is_file():
            raise SystemExit(f"error: {path}: no such file (the shared data folder is --data)")
    if args.episodes is not None and args.episodes.resolve().is_relative_to(args.data.resolve()):
        raise SystemExit(f"error: --episodes {args.episodes}: inside the data folder, which this script only reads")
    if args.episodes is not None and not args.episodes.resolve().parent.is_dir():
        raise SystemExit(f"error: --episodes {args.episodes}: its folder does not exist")
    policies = [p.strip() for p in args.policies.split(",") if p.strip()]
    from seal_cli.sim.policies import POLICIES

    unknown = [p for p in policies if p not in POLICIES]
    if not policies or unknown:
        raise SystemExit(f"error: --policies {args.policies}: the policies are {', '.join(POLICIES)}")

    bwc = script("build_word_classes")
    rows = [r for r in bwc.read_rows(goals) if r.get("split", "train") == "train"]
    held = bwc.held_out(rows, args.dev, "floor-plans")
    fit_rows = [r for r in rows if r["task_id"] not in held]
    try:
        suite = alfred2d.load_suite(args.data / "alfred2d", "train", with_priors=False)
    except SealError as error:
        print(f"error: {error}", file=sys.stderr)
        return 1
    fit_ids = {r["task_id"] for r in fit_rows}
    suite.priors = alfred2d.estimate_priors((e for e in suite.episodes if e.task_id in fit_ids), suite.floor_plans)
    suite.episodes = alfred2d._stratified([e for e in suite.episodes if e.task_id in held], args.sample)
    if args.trial:
        missing = sorted(set(args.trial) - {e.task_id for e in suite.episodes})
        if missing:
            print(f"error: --trial {missing[0]}: not a trial of the held-out sample", file=sys.stderr)
            return 1
        suite.episodes = [e for e in suite.episodes if e.task_id in args.trial]
    plans = {e.floor_plan for e in suite.episodes}
    print(f"fit on {len(fit_rows)} sentences; {len(suite.episodes)} episodes of {len(plans)} held-out floor plans",
          file=sys.stderr, flush=True)
    library = load_library()
    outcomes: list[Outcome] = []
    with tempfile.TemporaryDirectory() as folder:
        if args.goal == "human" or args.causes:  # gold commands are ALFRED's labels: no sentence is read
            fit_statistics(args.data, fit_rows, Path(folder), bwc)
        for number, episode in enumerate(suite.episodes, 1):
            outcomes += run_episode(episode, suite, library, policies, goal=args.goal, seed=args.seed,
                                    particles=args.particles)
            if number % 20 == 0:
                print(f"{number} / {len(suite.episodes)} episodes", file=sys.stderr, flush=True)
        if args.episodes is not None:
            args.episodes.write_text("".join(json.dumps(o.to_json()) + "\n" for o in outcomes), encoding="utf-8")
        report = summarise(outcomes, policies)
        report.update({"split": "train, held-out floor plans", "dev": args.dev, "goal": args.goal,
                       "sample": args.sample, "seed": args.seed, "floor_plans": len(plans)})
        if args.json:
            print(json.dumps(report, indent=1))
        else:
            for group, figures in report["groups"].items():
                print(f"{group:<36} n {figures['n']:>4}  " + "  ".join(
                    f"{p} {figures['success'][p]:.3f} / {figures['path_m'][p] or 0:.2f} m" for p in policies))
        if args.causes:
            causes({o.task_id: o.to_json() for o in outcomes if o.policy == policies[0]}, suite, args.data,
                   args.markdown, args.list)
    return 0


if __name__ == "__main__":
    sys.exit(main())
