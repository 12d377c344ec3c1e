"""A discriminative chooser of the class a phrase means among the classes its word can mean.

The counts of :mod:`seal_cli.language.wordusage` say how often people meant each class by a wording
("knife": ButterKnife 418, Knife 269); the rest of the sentence says which of them this person meant.
This module weighs it with a conditional (multinomial) logistic regression: for a phrase whose
wording meant the candidate classes ``c``, the probability of class ``c`` is

    P(c | phrase) ∝ prior(c) · exp(Σ_f weight[f][c])

over the phrase's features ``f`` (:func:`features`: the sentence's other words and the phrase's
modifiers). ``prior`` is the wording's count of the class
(or its rate where present, in a scene), so the weights learn only what the sentence adds to the
wording. The weights are fitted by L-BFGS on a train split with an L2 penalty (:func:`fit`),
deterministically, and shipped as a table of ``{feature: {class: weight}}``; at parse time a class's
score is a few dictionary lookups (:func:`logits`), with no numerical library.
"""

from __future__ import annotations

import math
from collections import Counter
from collections.abc import Iterable, Mapping, Sequence
from dataclasses import dataclass

__all__ = ["Instance", "features", "fit", "logits", "posterior", "room_weights", "scene_features", "sentence_features"]


def features(lemmas: Sequence[str], context: Iterable[str], candidates: Iterable[str] = ()) -> tuple[str, ...]:
    """The features of a phrase whose words up to the head are ``lemmas``, said in a sentence whose
    words are ``context`` (:func:`~seal_cli.language.wordusage.context_words`), when it may mean the
    class keys ``candidates``: ``w:`` each other word of the sentence (its verbs, the other phrases'
    words), ``m:`` each modifier. Every word of a candidate's own name is left out: "pot" in "put
    a pot containing a knife" names the other phrase, and the few labels that mix the two up would
    teach that a knife said beside a pot is a pot (so would "counter" of ``CounterTop`` make "the
    glass" of "put the glass on the counter" a counter top).

    Not a feature: the frame element the phrase fills. Tried on held-out train, it made the same
    words ground to two classes in one sentence ("put a sponge in a *pan*, put the *pan* in the
    cabinet": the goal and the theme), so the second Place no longer moved the same thing (all five
    fields 0.680 against 0.694 without it)."""
    own = set(lemmas) | {w for key in candidates for w in key.split("_")}
    out = [f"w:{w}" for w in sorted(set(context) - own)]
    out += [f"m:{m}" for m in dict.fromkeys(lemmas[:-1])]
    return tuple(out)


def scene_features(present: Iterable[str]) -> tuple[str, ...]:
    """The features of the scene a phrase is grounded in, for the scene's weights
    (:attr:`~seal_cli.language.wordusage.WordUsage.scene_weights`): ``s:`` the class key of each class the
    scene holds. With the weights ``s:bed`` → ``SideTable`` a bedroom's "table" leans to its side table, a
    class present beside the candidates (``s:coffee_table`` for ``DiningTable``) says which of two is the one
    people mean where both are."""
    return tuple(f"s:{key}" for key in sorted(set(present)))


def sentence_features(words: Iterable[str], thing: str | None, frames: Iterable[str]) -> tuple[str, ...]:
    """The features of a whole sentence for the unsaid slice and the unsaid goal: ``w:`` each of its words
    (:func:`~seal_cli.language.wordusage.context_words`), ``o:`` the class key of the thing it handles,
    ``f:`` each frame the parse evokes (said ones, for the goal)."""
    from seal_cli.frames.taxonomy import class_key

    out = [f"w:{w}" for w in sorted(set(words))]
    if thing:
        out.append(f"o:{class_key(thing)}")
    out += [f"f:{name}" for name in sorted(set(frames))]
    return tuple(out)


def logits(weights: Mapping[str, Mapping[str, float]], keys: Iterable[str], feats: Iterable[str]) -> dict[str, float]:
    """Each class key's sum of the weights of ``feats`` (0.0 for a class no feature weighs), added in the order of
    ``feats``. The rows of the features said are looked up once, then each key's sum is taken over them (a parse
    asks this of a few keys and a dozen rows several times per sentence: key by key is the quicker walk, and the sums
    are the same additions in the same order)."""
    rows = [row for row in map(weights.get, feats) if row]
    out: dict[str, float] = {}
    for key in keys:
        total = 0.0
        for row in rows:
            total += row.get(key, 0.0)
        out[key] = total
    return out


def posterior(prior: Mapping[str, int], weights: Mapping[str, Mapping[str, float]], keys: Iterable[str],
              feats: Iterable[str]) -> dict[str, float]:
    """P(key | feats) ∝ prior[key] · exp(logit[key]) over ``keys`` (each with a prior count above 0)."""
    keys = list(keys)
    z = logits(weights, keys, feats)
    scores = {k: math.log(prior[k]) + z[k] for k in keys}
    top = max(scores.values(), default=0.0)
    shares = {k: math.exp(v - top) for k, v in scores.items()}
    total = sum(shares.values())
    return {k: share / total for k, share in shares.items()}


def room_weights(said: Sequence[tuple[str, str]], spread: float) -> list[float]:
    """How much each instance counts when ``said`` gives each one's room and wording: a room that said a
    wording ``n`` times counts as ``(1 + spread) · n / (n + spread)`` instances of it, each ``(1 + spread) /
    (n + spread)`` (one said once counts 1). What a word means is partly the room's (one floor plan's "island" is
    its dining table, the next one's its counter top), and a room that said it forty times is still one room: the
    estimate of a room not seen is the rooms' mean, shrunk to the phrases' pooled count by ``spread`` (the
    strength of a Dirichlet prior over the rooms' meanings; large: every phrase counts 1, as pooled; near 0: every
    room counts 1)."""
    if not spread > 0:
        raise ValueError(f"spread {spread}: expected a number above 0")
    times = Counter(said)
    return [(1.0 + spread) / (times[key] + spread) for key in said]


@dataclass(frozen=True)
class Instance:
    """One phrase of a train split: the classes its wording can mean (``candidates``), the log of each
    one's prior (``offsets``: the wording's count of it, the phrase itself left out), which one was
    meant (``label``, an index into ``candidates``) and the phrase's :func:`features`."""

    candidates: tuple[str, ...]
    offsets: tuple[float, ...]
    label: int
    features: tuple[str, ...]


def fit(instances: Sequence[Instance], l2: float = 1.0, min_count: int = 2,
        digits: int = 3, min_label: int = 0, groups: Sequence[str] | None = None,
        min_groups: int = 0, weights: Sequence[float] | None = None) -> dict[str, dict[str, float]]:
    """The weights ``{feature: {class key: weight}}`` maximising the instances' log-likelihood minus
    ``l2 / 2`` times the squared weights. A (feature, class) pair gets a weight when the feature was
    said with the class among the candidates in at least ``min_count`` instances, and with the class
    meant in at least ``min_label`` (a model over many classes, every one a candidate, keeps only the
    pairs seen together: its table stays small) and in at least ``min_groups`` of the instances'
    ``groups`` (one per instance, such as the room it was said in: a word that went with a class in one
    room only says more of that room than of the word); weights are rounded to ``digits`` decimals and
    those that round to zero left out. ``weights``: how much each instance counts in the likelihood (one per
    instance, above 0; None: 1 each), so that a room that said one word many times counts as one room
    (:func:`room_weights`). Deterministic (L-BFGS from zero)."""
    import numpy as np
    from scipy.optimize import minimize
    from scipy.sparse import csr_matrix

    if groups is not None and len(groups) != len(instances):
        raise ValueError(f"{len(instances)} instances have {len(groups)} groups")
    if weights is not None and (len(weights) != len(instances) or not all(w > 0 for w in weights)):
        raise ValueError(f"{len(instances)} instances need as many weights, each above 0")
    each = weights if weights is not None else [1.0] * len(instances)
    kept = [(i, g, w) for i, g, w in zip(instances, groups if groups is not None else [""] * len(instances), each,
                                         strict=True) if len(i.candidates) >= 2]
    usable = [i for i, _, _ in kept]
    seen: Counter[tuple[str, str]] = Counter()
    meant: Counter[tuple[str, str]] = Counter()
    meant_in: dict[tuple[str, str], set[str]] = {}
    for inst, where, _ in kept:
        for f in set(inst.features):
            meant[(f, inst.candidates[inst.label])] += 1
            meant_in.setdefault((f, inst.candidates[inst.label]), set()).add(where)
            for c in inst.candidates:
                seen[(f, c)] += 1
    pairs = sorted(p for p, n in seen.items() if n >= min_count and meant[p] >= min_label
                   and len(meant_in.get(p, ())) >= min_groups)
    index = {p: k for k, p in enumerate(pairs)}
    rows: list[int] = []
    cols: list[int] = []
    offsets: list[float] = []
    starts: list[int] = []
    gold: list[int] = []
    by_feature: dict[str, list[tuple[str, int]]] = {}   # each feature's weighted classes: a model over many
    for (f, c), k in index.items():                    # classes looks up only the pairs it keeps, not every class
        by_feature.setdefault(f, []).append((c, k))
    for inst in usable:
        first_row = len(offsets)
        starts.append(first_row)
        gold.append(first_row + inst.label)
        if len(inst.offsets) != len(inst.candidates):
            raise ValueError(f"an instance of {len(inst.candidates)} candidates has {len(inst.offsets)} offsets")
        offsets.extend(inst.offsets)
        at: dict[str, list[int]] = {}
        for j, c in enumerate(inst.candidates):
            at.setdefault(c, []).append(first_row + j)
        for f in set(inst.features):
            for c, k in by_feature.get(f, ()):
                for row in at.get(c, ()):
                    rows.append(row)
                    cols.append(k)
    if not pairs or not usable:
        return {}
    design = csr_matrix((np.ones(len(rows)), (rows, cols)), shape=(len(offsets), len(pairs)))
    design.sort_indices()                              # the same sums in the same order, whatever the set's order
    base = np.asarray(offsets)
    first = np.asarray(starts)
    group = np.repeat(np.arange(len(starts)), np.diff(np.append(first, len(offsets))))
    target = np.zeros(len(offsets))
    target[np.asarray(gold)] = 1.0
    counted = None if weights is None else np.asarray([w for _, _, w in kept], dtype=float)
    by_row = None if counted is None else counted[group]          # each instance's weight, and each row's

    def loss(w: np.ndarray) -> tuple[float, np.ndarray]:
        z = design @ w + base
        top = np.maximum.reduceat(z, first)
        e = np.exp(z - top[group])
        total = np.add.reduceat(e, first)
        log_norm = np.log(total) + top
        p = e / total[group]
        if counted is None or by_row is None:
            nll = float(np.sum(log_norm) - np.sum(z[target > 0]))
            grad = design.T @ (p - target) + l2 * w
        else:
            nll = float(counted @ log_norm - counted @ z[target > 0])
            grad = design.T @ ((p - target) * by_row) + l2 * w
        return nll + 0.5 * l2 * float(w @ w), grad

    result = minimize(loss, np.zeros(len(pairs)), jac=True, method="L-BFGS-B",
                      options={"maxiter": 500, "gtol": 1e-6})
    out: dict[str, dict[str, float]] = {}
    for (f, c), w in zip(pairs, result.x, strict=True):
        value = round(float(w), digits)
        if value and math.isfinite(value):
            out.setdefault(f, {})[c] = value
    return {f: dict(sorted(by.items())) for f, by in sorted(out.items())}
