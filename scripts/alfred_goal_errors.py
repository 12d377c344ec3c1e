#!/usr/bin/env python3
"""Why held-out ALFRED goal sentences were read wrong: the sentences of a ``build_word_classes.py --dev F
--errors FILE`` run (train trials held out from the fit; never a valid split), each classified by its first
wrong field and the cause the read-back and the labels show.

Each line of ``FILE`` is what ``--errors`` writes: the fields wrong (comma-separated), the sentence, what the
parse was read back as and what the labels are (JSON, as ``../shared/eval/score_alfred_goals.py`` reads them).
The first wrong field, in the scorer's order (type, object, receptacle, mrecep, sliced), names the field; the
cause is read from the two dicts and the word-class table (which classes people called by one word on train):

- ``no parse``: the parse has no frames (every field empty);
- type: ``step not read`` (a heating, cooling or cleaning task read as one without a step), ``another step read``,
  ``container not read`` (a stack read as one Place), ``stack read as two things`` (a stack said as a coordination,
  "move a pan and a knife to the sink"), ``second thing not read`` (two things read as one), ``look not read``,
  ``more read than the label`` (a step, a stack, two things or a look the simple task lacks), ``other``;
- object, receptacle, mrecep: ``nothing read`` (no phrase, or one that grounds to no class: "the fruit", a
  sentence that stops at its step), ``one word, two classes`` (the two classes share a wording of the table:
  "knife" for Knife and ButterKnife), ``another class``;
- sliced: ``slice not read``, ``slice read``.

    python scripts/alfred_goal_errors.py /tmp/e.tsv [--table FILE] [--markdown] [--examples 2]
"""

from __future__ import annotations

import argparse
import json
import sys
from collections import Counter
from collections.abc import Mapping
from pathlib import Path
from typing import Any

ROOT = Path(__file__).resolve().parent.parent
TABLE = ROOT / "seal_cli" / "language" / "word_classes" / "alfred_train.json"
FIELDS = ("type", "object", "receptacle", "mrecep", "sliced")
STEP_TASKS = {"pick_heat_then_place_in_recep", "pick_cool_then_place_in_recep", "pick_clean_then_place_in_recep"}
SIMPLE = "pick_and_place_simple"
STACK = "pick_and_place_with_movable_recep"
TWO = "pick_two_obj_and_place"
LOOK = "look_at_obj_in_light"


def key(cls: object) -> str:
    """A class compared without case or underscores."""
    return str(cls or "").replace("_", "").lower()


SHARED_LEAST = 5
"""People who meant each of two classes by one wording before the pair counts as that wording's ..."""
SHARED_SHARE = 0.05
"""... and the least share of the wording's phrases each must have (a label's slip, a book labelled the alarm clock
beside it, is no second meaning of "book")."""


def shared_words(words: Mapping[str, Mapping[str, int]]) -> dict[frozenset[str], str]:
    """Each pair of classes one wording of the table meant both of (each at least :data:`SHARED_LEAST` times and
    :data:`SHARED_SHARE` of the wording's phrases) → the wording said most often for both."""
    out: dict[frozenset[str], tuple[int, str]] = {}
    for wording, by_class in words.items():
        classes = sorted(by_class)
        total = sum(by_class.values())
        for i, a in enumerate(classes):
            for b in classes[i + 1:]:
                pair = frozenset((key(a), key(b)))
                said = min(by_class[a], by_class[b])
                if said < max(SHARED_LEAST, SHARED_SHARE * total):
                    continue
                if pair not in out or said > out[pair][0]:
                    out[pair] = (said, wording)
    return {pair: wording for pair, (_, wording) in out.items()}


def type_cause(got: str | None, want: str) -> str:
    if want in STEP_TASKS:
        return "another step read" if got in STEP_TASKS else "step not read"
    if want == STACK:
        return "stack read as two things" if got == TWO else "container not read"
    if want == TWO:
        return "second thing not read" if got == SIMPLE else "other"
    if want == LOOK:
        return "look not read"
    if want == SIMPLE:
        return "more read than the label"
    return "other"


def classify(wrong: list[str], got: Mapping[str, Any], want: Mapping[str, Any],
             shared: Mapping[frozenset[str], str]) -> tuple[str, str, str]:
    """(the first wrong field, its cause, a detail: the classes or types confused)."""
    if not any(got.get(f) for f in FIELDS):
        return "any", "no parse", ""
    field = next(f for f in FIELDS if f in wrong)
    if field == "type":
        return field, type_cause(got.get("type"), str(want["type"])), f"{got.get('type')} for {want['type']}"
    if field == "sliced":
        return field, "slice read" if got.get("sliced") else "slice not read", ""
    if not got.get(field):
        return field, "nothing read", str(want[field])
    pair = frozenset((key(got[field]), key(want[field])))
    detail = f"{got[field]} for {want[field]}"
    if pair in shared:
        return field, "one word, two classes", f"{detail} ('{shared[pair]}')"
    return field, "another class", detail


def read_errors(path: Path) -> list[tuple[list[str], str, dict[str, Any], dict[str, Any]]]:
    try:
        text = path.read_text(encoding="utf-8")
    except OSError as error:
        raise SystemExit(f"error: {path}: {error.strerror}") from None
    out = []
    for number, line in enumerate(text.splitlines(), 1):
        if not line.strip():
            continue
        cells = line.split("\t")
        try:
            if len(cells) != 4:
                raise ValueError
            got, want = json.loads(cells[2]), json.loads(cells[3])
            if not isinstance(got, dict) or not isinstance(want, dict) or not cells[0]:
                raise ValueError
        except ValueError:
            raise SystemExit(f"error: {path}:{number}: not a line of --errors (fields, sentence, read back, "
                             "labels: four tab-separated cells)") from None
        out.append((cells[0].split(","), cells[1], got, want))
    return out


def read_table(path: Path) -> dict[str, dict[str, int]]:
    try:
        data = json.loads(path.read_text(encoding="utf-8"))
    except OSError as error:
        raise SystemExit(f"error: {path}: {error.strerror}") from None
    except json.JSONDecodeError as error:
        raise SystemExit(f"error: {path}:{error.lineno}:{error.colno}: not JSON") from None
    words = data.get("words") if isinstance(data, dict) else None
    if not isinstance(words, dict):
        raise SystemExit(f"error: {path}: no 'words' section (a word-class table)")
    return words


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("errors", type=Path, help="the --errors file of a build_word_classes.py --dev run")
    ap.add_argument("--table", type=Path, default=TABLE, help="the word-class table whose wordings are shared")
    ap.add_argument("--examples", type=int, default=1, help="sentences shown for each cause")
    ap.add_argument("--details", type=int, default=3, help="most frequent confusions shown for each cause")
    ap.add_argument("--markdown", action="store_true")
    args = ap.parse_args()

    rows = read_errors(args.errors)
    shared = shared_words(read_table(args.table))
    causes: Counter[tuple[str, str]] = Counter()
    details: dict[tuple[str, str], Counter[str]] = {}
    examples: dict[tuple[str, str], list[str]] = {}
    for wrong, sentence, got, want in rows:
        field, cause, detail = classify(wrong, got, want, shared)
        causes[field, cause] += 1
        if detail:
            details.setdefault((field, cause), Counter())[detail] += 1
        examples.setdefault((field, cause), []).append(sentence)
    header = ["field", "cause", "sentences", "most often", "e.g."]
    lines = [header]
    for (field, cause), n in causes.most_common():
        top = "; ".join(f"{d} {k}" for d, k in details.get((field, cause), Counter()).most_common(args.details))
        said = " / ".join(f'"{s}"' for s in examples[field, cause][:args.examples])
        lines.append([field, cause, str(n), top, said])
    lines.append(["all", "", str(len(rows)), "", ""])
    if args.markdown:
        print("| " + " | ".join(header) + " |")
        print("|" + "---|" * len(header))
        for line in lines[1:]:
            print("| " + " | ".join(cell.replace("|", "/") for cell in line) + " |")
    else:
        for line in lines:
            print("\t".join(line))
    return 0


if __name__ == "__main__":
    sys.exit(main())
