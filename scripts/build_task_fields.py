#!/usr/bin/env python3
"""Rebuild ``seal_cli/language/task_fields/alfred_train.json``: the task fields (type, object, receptacle, movable
receptacle; and sliced, given the type and object) ALFRED's *train* goal sentences say by their words
(:mod:`seal_cli.language.taskfields`).

    python scripts/build_task_fields.py                  # rewrite the shipped model (fitted on all train trials)
    python scripts/build_task_fields.py --check          # exit 1 if the shipped model differs
    python scripts/build_task_fields.py --dev 0.2        # fit on 80 % of train trials, score the rest

``--data`` is the shared data folder (default ``../shared/data`` beside the project). ``--dev F`` holds out a
fraction F of the train trials (or of the floor plans, ``--hold-out floor-plans``) as
``build_word_classes.py --dev`` does (the same hash), fits the word-class table and this model on the others, parses
the held-out sentences and prints the five fields as the scorer reads them, the parser alone and reread with each
``--trust`` tried (the parser's bonus, one number for every field, or ``type,object,receptacle,mrecep``): the shipped
trust was chosen there, never on a valid split. With ``--learn`` the combination's weights are learned there too
(``taskfields.fit_trust`` on one half of the held-out sentences, scored on the other half, and the other way
round; then the weights learned on all of them are printed), by the likelihood (``taskfields.fit_trust``) and by the
count of right values (``taskfields.fit_trust_count``). ``--l2`` and ``--min-rooms`` fit the words' model otherwise
too (its L2 penalty; the least number of floor plans a word must have been said in with a value to weigh it), and
``--rooms S`` with each sentence weighed by how often its floor plan had the field's value (``chooser.room_weights``),
and score each with the first trust (``--chooser-rooms S``: the word-class chooser fitted so too); ``--slice-add P
...`` rereads with an unsaid Slice added at each probability P (``taskfields.SLICE_ADD`` ships). Each row also gives
the 95 % interval of its all-five figure when the held-out floor plans (or trials) are drawn again (:func:`resampled`),
and each row after the first reread the interval of its count of wrong sentences against that reread's: on 23
floor plans a change of a few sentences is within it.
"""

from __future__ import annotations

import argparse
import importlib.util
import json
import sys
import zlib
from collections import Counter
from collections.abc import Callable, Sequence
from pathlib import Path
from types import ModuleType

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT))
sys.path.insert(0, str(Path(__file__).resolve().parent))

from rebuilt import write_or_check  # noqa: E402  scripts/rebuilt.py, beside this script

from seal_cli.language.grounding import Vocabulary  # noqa: E402
from seal_cli.language.taskfields import (  # noqa: E402
    FIELDS,
    L2,
    SHIPPED,
    SLICE_ADD,
    TRUST,
    FieldModel,
    candidates,
    field_classes,
    fit_fields,
    fit_trust,
    fit_trust_count,
    label,
    model_json,
    read_fields,
    reread,
    sentence_grams,
    wanted,
)
from seal_cli.language.values import Parse  # noqa: E402

TOLERANCE = 0.011
"""How far a fitted weight may move (a last decimal rounded the other way) before the shipped model is stale."""


def word_classes() -> ModuleType:
    """``build_word_classes.py``, for its train rows, hold-out hash, table fit and scorer."""
    path = ROOT / "scripts" / "build_word_classes.py"
    spec = importlib.util.spec_from_file_location("build_word_classes", path)
    assert spec is not None and spec.loader is not None
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def bwc_spread() -> float | None:
    """The chooser's room spread as ``build_word_classes.py`` ships it (:data:`build_word_classes.ROOM_SPREAD`)."""
    spread: float | None = word_classes().ROOM_SPREAD
    return spread


def differences(shipped: object, built: object, path: str = "") -> list[str]:
    """Where the shipped model differs from the one built: any count, any value, or a weight by more than
    :data:`TOLERANCE` (a weight missing on one side counts as 0)."""
    if isinstance(shipped, dict) and isinstance(built, dict):
        out = []
        for key in sorted(set(shipped) | set(built), key=str):
            a, b = shipped.get(key), built.get(key)
            if isinstance(a, float | None) and isinstance(b, float | None) and path.startswith("/weights"):
                if abs((a or 0.0) - (b or 0.0)) > TOLERANCE:
                    out.append(f"{path}/{key}: {a} shipped, {b} built")
            elif key not in shipped or key not in built:
                out.append(f"{path}/{key} only in the {'built' if key not in shipped else 'shipped'} model")
            else:
                out += differences(a, b, f"{path}/{key}")
        return out
    return [] if shipped == built else [f"{path}: {shipped} shipped, {built} built"]


def trusts(said: list[str]) -> list[dict[str, float]]:
    out = []
    for text in said:
        if text == "shipped":
            out.append(dict(TRUST))
            continue
        try:
            numbers = [float(x) for x in text.split(",")]
        except ValueError:
            raise SystemExit(f"error: --trust {text}: expected a number, or four comma-separated") from None
        if len(numbers) == 1:
            numbers *= len(FIELDS)
        if len(numbers) != len(FIELDS):
            raise SystemExit(f"error: --trust {text}: expected a number or four ({', '.join(FIELDS)})")
        out.append(dict(zip(FIELDS, numbers, strict=True)))
    return out


def dev(args: argparse.Namespace, bwc: ModuleType, rows: list[dict[str, str]]) -> int:
    from dataclasses import replace

    from seal_cli.language.parser import CommandError, parse_command

    data = args.data
    classes = json.loads((data / "alfred" / "alfred_constants.json").read_text())["OBJECTS"]
    vocabulary = bwc.Vocabulary.of(classes)
    held = bwc.held_out(rows, args.dev, args.hold_out)
    fit_rows = [r for r in rows if r["task_id"] not in held]
    dev_rows = [r for r in rows if r["task_id"] in held]
    print(f"fit {len(fit_rows)} sentences, dev {len(dev_rows)} sentences ({len(held)} {args.hold_out})", flush=True)
    table = bwc.table(*bwc.count(fit_rows, vocabulary, bwc.scene_classes(data, classes)), classes, "dev", bwc.L2,
                      bwc.SCENE_L2, spread=args.chooser_rooms)
    usage = bwc.usage_of(bwc.with_stack_goals(bwc.with_steps(table, fit_rows, vocabulary), fit_rows, vocabulary))
    tried = vocabulary.with_usage(usage)
    settings = [(l2, rooms, None) for l2 in args.l2 for rooms in args.min_rooms]
    settings += [(args.l2[0], args.min_rooms[0], spread) for spread in args.rooms]
    models = {setting: fit_fields(fit_rows, l2=setting[0], min_rooms=setting[1], spread=setting[2])
              for setting in settings}
    model = models[settings[0]]
    scorer = bwc.scorer(data)
    library = bwc.load_library()
    parsed = []
    for row in dev_rows:
        text = " ".join(row["goal_sentence"].split())
        try:
            parsed.append((row, text, parse_command(text, library, tried)))
        except CommandError:
            parsed.append((row, text, None))
    errors: list[str] = []

    unit = "task_id" if args.hold_out == "trials" else "floor_plan"       # what was held out, resampled by it
    rights: dict[str, list[bool]] = {}

    def show(name: str, model_of: Callable[[dict[str, str]], FieldModel | None], keep: bool = False) -> None:
        hits: Counter[str] = Counter()
        right = rights.setdefault(name, [])
        for row, text, parse in parsed:
            model = model_of(row)
            if parse is not None and model is not None:
                parse = reread(parse, library, tried, model, text)
            got_json = parse.to_json() if parse is not None else {}
            want = scorer.gold(row)
            got = scorer.read_back(got_json) if got_json.get("frames") else {f: None for f in scorer.FIELDS}
            ok = {f: got[f] == want[f] for f in scorer.FIELDS}
            hits.update(f for f, good in ok.items() if good)
            hits["all"] += all(ok.values())
            right.append(all(ok.values()))
            if keep and not all(ok.values()):
                wrong = ",".join(f for f, good in ok.items() if not good)
                errors.append("\t".join([wrong, row["goal_sentence"].strip(), json.dumps(got), json.dumps(want)]))
        n = max(len(parsed), 1)
        units = [row[unit] for row, _, _ in parsed]
        low, high = resampled(units, right)
        against = next((k for k in rights if k.startswith("reread") and k != name), None)
        paired = "" if against is None else "; {:+.0f} to {:+.0f} wrong against the first reread".format(
            *(-x * n for x in reversed(resampled(units, right, rights[against]))))
        print(f"{name:<48}" + " ".join(f"{k} {hits[k] / n:.3f}" for k in ("all", *scorer.FIELDS))
              + f" ({n - hits['all']} wrong; all five {low:.3f}-{high:.3f} over the held-out {args.hold_out}{paired})",
              flush=True)

    show("parser", lambda row: None)
    for i, trust in enumerate(args.trusts):
        shown = "shipped" if trust == dict(TRUST) else ",".join(f"{trust[f]:g}" for f in FIELDS)
        show("reread, trust " + shown, lambda row, t=trust: replace(model, trust=t), keep=i == 0)
    for least in args.slice_add:                   # the unsaid slice added at another probability
        show(f"reread, slice added at {least:g}", lambda row, x=least: replace(model, trust=args.trusts[0],
                                                                                 slice_add=x))
    for l2, rooms, spread in settings[1:]:         # the words' model fitted otherwise, with the first trust
        show(f"reread, l2 {l2:g}, min rooms {rooms}" + ("" if spread is None else f", rooms weighed {spread:g}"),
             lambda row, m=models[(l2, rooms, spread)]: replace(m, trust=args.trusts[0]))
    if args.learn:
        # the combination learned on the held-out parses: scored on each half by the weights learned on the other
        examples = {id(row): trust_examples(model, row, text, parse, tried) for row, text, parse in parsed}
        unit = "task_id" if args.hold_out == "trials" else "floor_plan"        # halves as the held-out part is
        half = {id(row): zlib.crc32(row[unit].encode()) % 2 for row, _, _ in parsed}
        learned = [fit_trust([e for row, _, _ in parsed if half[id(row)] != k for e in examples[id(row)]])
                   for k in (0, 1)]
        show("reread, learned on the other half", lambda row: replace(model, trust=learned[half[id(row)]]))
        every = fit_trust([e for row, _, _ in parsed for e in examples[id(row)]])
        print("learned on all the held-out sentences (TRUST):", json.dumps(every, sort_keys=True))
        # the same, learned for the count of right values (an averaged perceptron from the shipped combination)
        counted = [fit_trust_count([e for row, _, _ in parsed if half[id(row)] != k for e in examples[id(row)]])
                   for k in (0, 1)]
        show("reread, learned for the count on the other half",
             lambda row: replace(model, trust=counted[half[id(row)]]))
        every = fit_trust_count([e for row, _, _ in parsed for e in examples[id(row)]])
        print("learned for the count on all the held-out sentences (TRUST):", json.dumps(every, sort_keys=True))
    if args.errors is not None:
        args.errors.write_text("".join(line + "\n" for line in errors))
        print(f"wrote {args.errors} ({len(errors)} sentences of the first trust scored wrong)")
    return 0


DRAWS = 1000
"""How many times :func:`resampled` draws the held-out units."""


def resampled(units: Sequence[str], right: Sequence[bool], other: Sequence[bool] | None = None,
              draws: int = DRAWS, seed: int = 0) -> tuple[float, float]:
    """The 95 % interval of the share of sentences right (``right``, one per sentence), or of its difference from
    ``other``'s on the same sentences, when the held-out units (``units``: each sentence's floor plan or trial) are
    drawn again with replacement, as many as there are (a bootstrap over what was held out: 23 floor plans decide
    what "table" means in most of their sentences, so the sentences are not independent). Deterministic."""
    import random

    by: dict[str, list[int]] = {}
    for key, good, base in zip(units, right, other if other is not None else [False] * len(right), strict=True):
        total = by.setdefault(key, [0, 0])
        total[0] += int(good) - int(base)
        total[1] += 1
    keys = sorted(by)
    if not keys:
        return 0.0, 0.0
    rng = random.Random(seed)
    shares = []
    for _ in range(draws):
        picked = [by[rng.choice(keys)] for _ in keys]
        shares.append(sum(p[0] for p in picked) / max(sum(p[1] for p in picked), 1))
    shares.sort()
    return shares[int(0.025 * draws)], shares[min(int(0.975 * draws), draws - 1)]


def trust_examples(model: FieldModel, row: dict[str, str], text: str, parse: Parse | None,
                   vocabulary: Vocabulary) -> list[tuple[dict[str, dict[str, float]], str]]:
    """The held-out sentence's instances for :func:`fit_trust`: each field its task has, its candidates as
    :func:`combine` weighs them, the label's value the right one."""
    if parse is None or not parse.frames:
        return []
    reading = read_fields(parse)
    present = set(vocabulary.by_key)
    meant = field_classes(parse, reading, vocabulary)
    grams = sentence_grams(text)
    kind = label(row, "type")
    out = [(candidates(model, "type", grams, reading, None, present), kind)]
    for name in ("object", "receptacle", "mrecep"):
        if wanted(name, kind):
            classes = present & meant[name] if name in meant else present
            out.append((candidates(model, name, grams, reading, classes), label(row, name)))
    return out


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--data", type=Path, default=ROOT.parent / "shared" / "data")
    ap.add_argument("--out", type=Path, default=SHIPPED)
    ap.add_argument("--check", action="store_true", help="compare with the shipped model instead of writing it")
    ap.add_argument("--dev", type=float, default=0.0, help="hold out this fraction of train and score it")
    ap.add_argument("--hold-out", choices=("trials", "floor-plans"), default="trials")
    ap.add_argument("--trust", nargs="*", default=["shipped"],
                    help="with --dev: the parser's bonus to try (one number, four: type,object,receptacle,mrecep, "
                         "or 'shipped': the shipped combination)")
    ap.add_argument("--learn", action="store_true",
                    help="with --dev: learn the combination on the held-out parses (each half scored by the other's) "
                         "and print the weights learned on all of them")
    ap.add_argument("--errors", type=Path, help="with --dev: write the held-out sentences scored wrong here (TSV)")
    ap.add_argument("--slice-add", type=float, nargs="*", default=[],
                    help="with --dev: also reread with an unsaid Slice added at each of these probabilities "
                         f"(taskfields.SLICE_ADD: {SLICE_ADD:g} shipped; above 1: never)")
    ap.add_argument("--l2", type=float, nargs="+", default=[L2],
                    help="with --dev: the words' model's L2 penalties to try (the first with every --trust)")
    ap.add_argument("--min-rooms", type=int, nargs="+", default=[0],
                    help="with --dev: the least number of floor plans a word must have been said in with a value "
                         "to weigh it (taskfields.fit_fields' min_rooms), those to try")
    ap.add_argument("--rooms", type=float, nargs="*", default=[],
                    help="with --dev: also fit the words' model with each sentence weighed by how often its floor plan "
                         "had the field's value (chooser.room_weights), with each of these spreads")
    ap.add_argument("--chooser-rooms", type=float, default=bwc_spread(),
                    help="with --dev: fit the word-class chooser with each phrase weighed by its floor plan "
                         "(chooser.room_weights) with this spread (default: build_word_classes.ROOM_SPREAD: shipped)")
    args = ap.parse_args()

    goals = args.data / "alfred" / "goals_train.tsv"
    constants = args.data / "alfred" / "alfred_constants.json"
    for path in (goals, constants):
        if not path.is_file():
            print(f"error: {path}: no such file (the shared data folder is --data)", file=sys.stderr)
            return 1
    args.trusts = trusts(args.trust)
    for x in args.l2:
        if not x > 0:
            print(f"error: --l2 {x:g}: expected a penalty above 0", file=sys.stderr)
            return 1
    for spread in [*args.rooms, *([] if args.chooser_rooms is None else [args.chooser_rooms])]:
        if not spread > 0:
            print(f"error: --rooms {spread:g}: expected a spread above 0", file=sys.stderr)
            return 1
    for k in args.min_rooms:
        if k < 0:
            print(f"error: --min-rooms {k}: expected a count of floor plans, 0 or more", file=sys.stderr)
            return 1
    bwc = word_classes()
    rows = [r for r in bwc.read_rows(goals) if r.get("split", "train") == "train"]
    if args.dev:
        if not 0 < args.dev < 1:
            print(f"error: --dev {args.dev}: expected a fraction between 0 and 1", file=sys.stderr)
            return 1
        return dev(args, bwc, rows)
    source = f"ALFRED train goals ({goals.name}: {len(rows)} human goal sentences with their task labels)"
    text = model_json(fit_fields(rows), source)
    return write_or_check(args.out, text, check=args.check, made_from="the train split", compare=differences,
                          summary=f"{len(text)} bytes")


if __name__ == "__main__":
    raise SystemExit(main())
