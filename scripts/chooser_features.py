#!/usr/bin/env python3
"""Which features would help the chooser: each candidate feature set fitted on train's fitted part and scored on
its held-out part, at the level of the phrase (no parse is rebuilt).

Each train goal sentence is parsed by the rules alone, as ``scripts/build_word_classes.py`` counts it; every labelled
phrase whose wording (its last modifier and head, else its head, said at least twice on the fitted part) meant two
classes or more is a chooser instance (:class:`~seal_cli.language.chooser.Instance`: the wording's counts as the
prior, the phrase itself left out of them on the fitted part). For each feature set the chooser is fitted with L2 1.0
on the fitted part and its most probable class compared with the label on the held-out part, by the field the phrase
fills (object, receptacle, other: the movable receptacle, the lamp). ``ceiling`` fits the shipped features on the
held-out phrases themselves: how much the sentence's words could tell at best.

    python scripts/chooser_features.py                               # held-out trials (--dev 0.2)
    python scripts/chooser_features.py --hold-out floor-plans --sets shipped near
    python scripts/chooser_features.py --hold-out floor-plans --sets shipped --rooms 8 3

``--rooms S ...`` also fits each set with its phrases weighed by their floor plan (``chooser.room_weights``, spread
S: a room that said a wording many times counts as fewer phrases; ``build_word_classes.ROOM_SPREAD``). The set
``room`` adds the sentence's scene type (kitchen, living room, bedroom, bathroom: its floor plan's), which the goal
scorer never gives a parser: a ceiling of what knowing the kind of room would add.
"""

from __future__ import annotations

import argparse
import json
import math
import re
import sys
from collections import Counter
from collections.abc import Callable, Sequence
from pathlib import Path
from typing import Any

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT))
sys.path.insert(0, str(ROOT / "scripts"))

from build_word_classes import fields, held_out, parsed, read_rows, wording  # noqa: E402

from seal_cli.frames.reading import load_library  # noqa: E402
from seal_cli.frames.taxonomy import class_key  # noqa: E402
from seal_cli.language.chooser import Instance, features, fit, logits, room_weights  # noqa: E402
from seal_cli.language.grounding import Vocabulary  # noqa: E402
from seal_cli.language.morphology import noun_lemma  # noqa: E402
from seal_cli.language.wordusage import WordUsage, context_words  # noqa: E402

Said = dict[str, Any]
_WORD = re.compile(r"[a-z]+")


def phrases(rows: Sequence[dict[str, str]], held: set[str]) -> list[Said]:
    """Every labelled phrase of the rows, parsed by the rules alone, with what the feature sets read."""
    classes = json.loads((ROOT.parent / "shared" / "data" / "alfred" / "alfred_constants.json").read_text())["OBJECTS"]
    rules = Vocabulary.of(classes).with_usage(WordUsage())
    library = load_library()
    out: list[Said] = []
    for row, text, parse in parsed(rows, library, rules):
        others = [p for f in parse.frames for p in f.elements.values()]
        for phrase, label in fields(parse, row):
            lemmas = wording(phrase)
            if lemmas is None:
                continue
            field = "object" if label == row["object"] else "receptacle" if label == row["receptacle"] else "other"
            out.append({"lemmas": lemmas, "label": label, "words": context_words(text), "text": text,
                        "phrase": phrase.text or "", "field": field, "dev": row["task_id"] in held,
                        "plan": row.get("floor_plan", ""), "scene": row.get("scene_type", ""),
                        "frames": sorted({f.frame for f in parse.frames}),
                        "classes": sorted({q.cls for q in others if q.cls and q is not phrase})})
    return out


def _lemmas(text: str) -> list[str]:
    return [noun_lemma(w) for w in _WORD.findall(text.lower())]


def near(said: Said, width: int = 3) -> list[str]:
    """``n:`` the words within ``width`` of the phrase in its sentence."""
    words, own = _lemmas(said["text"]), _lemmas(said["phrase"])
    for i in range(len(words) - len(own) + 1):
        if own and words[i:i + len(own)] == own:
            around = words[max(0, i - width):i] + words[i + len(own):i + len(own) + width]
            return [f"n:{w}" for w in dict.fromkeys(around)]
    return []


SETS: dict[str, Callable[[Said, tuple[str, ...]], tuple[str, ...]]] = {
    "shipped": lambda s, c: features(s["lemmas"], s["words"], c),
    "near": lambda s, c: features(s["lemmas"], s["words"], c) + tuple(near(s)),
    "pairs": lambda s, c: features(s["lemmas"], s["words"], c) + tuple(
        f"b:{a}_{b}" for a, b in dict.fromkeys(zip(_lemmas(s["text"]), _lemmas(s["text"])[1:], strict=False))),
    "classes": lambda s, c: features(s["lemmas"], s["words"], c) + tuple(
        f"c:{class_key(k)}" for k in s["classes"] if class_key(k) not in c),
    "frames": lambda s, c: features(s["lemmas"], s["words"], c) + tuple(f"f:{f}" for f in s["frames"]),
    "field": lambda s, c: features(s["lemmas"], s["words"], c) + (f"e:{s['field']}",),
    "room": lambda s, c: features(s["lemmas"], s["words"], c) + (f"r:{s.get('scene', '')}",),
}
"""The feature sets tried: the shipped one (``w:`` the sentence's other words, ``m:`` the phrase's modifiers) and it
with the words near the phrase, the sentence's word pairs, the rules' classes of the sentence's other phrases, the
frames the parse evokes, or the field the phrase fills (which a parser could only guess), or the kind of room
(which the goal scorer does not give)."""


def instances(said: Sequence[Said], counts: dict[str, Counter[str]], feats: Callable[..., tuple[str, ...]],
              leave_out: bool) -> list[tuple[Said, Instance]]:
    out = []
    for s in said:
        lemmas = s["lemmas"]
        for size in (2, 1):
            by = counts.get(" ".join(lemmas[-size:])) if len(lemmas) >= size else None
            if not by or sum(by.values()) - leave_out < 2:
                continue
            left = {c: n - (leave_out and c == s["label"]) for c, n in by.items()}
            left = {c: n for c, n in left.items() if n > 0}
            if len(left) >= 2 and s["label"] in left:
                keys = sorted(left)
                candidates = tuple(class_key(k) for k in keys)
                out.append(({**s, "wording": " ".join(lemmas[-size:])},
                            Instance(candidates, tuple(math.log(left[k]) for k in keys), keys.index(s["label"]),
                                     feats(s, candidates))))
            break
    return out


def scored(weights: dict[str, dict[str, float]], held: Sequence[tuple[Said, Instance]]) -> Counter[str]:
    right: Counter[str] = Counter()
    for s, inst in held:
        z = logits(weights, inst.candidates, inst.features)
        score = [o + z[c] for o, c in zip(inst.offsets, inst.candidates, strict=True)]
        right[s["field"]] += max(range(len(score)), key=score.__getitem__) == inst.label
    return right


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--dev", type=float, default=0.2)
    ap.add_argument("--hold-out", choices=("trials", "floor-plans"), default="trials")
    ap.add_argument("--sets", nargs="*", default=[*SETS, "ceiling"], choices=[*SETS, "ceiling"])
    ap.add_argument("--l2", type=float, default=1.0)
    ap.add_argument("--rooms", type=float, nargs="*", default=[],
                    help="also fit each set with its phrases weighed by floor plan, with each of these spreads")
    args = ap.parse_args()
    for spread in args.rooms:
        if not spread > 0:
            print(f"error: --rooms {spread:g}: expected a spread above 0", file=sys.stderr)
            return 1
    rows = [r for r in read_rows(ROOT.parent / "shared" / "data" / "alfred" / "goals_train.tsv")
            if r.get("split", "train") == "train"]
    said = phrases(rows, held_out(rows, args.dev, args.hold_out))
    fitted = [s for s in said if not s["dev"]]
    counts: dict[str, Counter[str]] = {}
    for s in fitted:
        for size in (2, 1):
            if len(s["lemmas"]) >= size:
                counts.setdefault(" ".join(s["lemmas"][-size:]), Counter())[s["label"]] += 1
    dev = [s for s in said if s["dev"]]
    for name in args.sets:
        feats = SETS["shipped" if name == "ceiling" else name]
        held = instances(dev, counts, feats, False)
        train = held if name == "ceiling" else instances(fitted, counts, feats, True)
        for spread in [None, *([] if name == "ceiling" else args.rooms)]:
            weights = fit([i for _, i in train], args.l2,
                          weights=None if spread is None else room_weights(rooms(train), spread))
            right, total = scored(weights, held), Counter(s["field"] for s, _ in held)
            prior = scored({}, held)
            shown = name if spread is None else f"{name}, rooms {spread:g}"
            print(f"{shown:<9} " + "  ".join(f"{f} {right[f]} / {total[f]} (prior {prior[f]})"
                                             for f in ("object", "receptacle", "other")),
                  f" weights {sum(len(w) for w in weights.values())}", flush=True)
    return 0


def rooms(made: Sequence[tuple[Said, Instance]]) -> list[tuple[str, str]]:
    """Each instance's floor plan and the wording its prior was counted under (the longest with support, as
    :func:`instances` picks it), for ``chooser.room_weights``."""
    return [(s.get("plan", ""), s["wording"]) for s, _ in made]


if __name__ == "__main__":
    raise SystemExit(main())
