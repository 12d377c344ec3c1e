#!/usr/bin/env python3
"""Rebuild ``seal_cli/language/word_classes/alfred_train.json``: which ALFRED class people mean by
a word, counted on ALFRED's *train* goals only.

Each train goal sentence ("Put the knife in the sink.") comes with its task's labels (object
``ButterKnife``, receptacle ``SinkBasin``, movable receptacle, toggle target). The sentence is
parsed by seal with the rules alone (no statistics), the phrase that fills each labelled field is
found the way ALFRED parses are read back (the object: the theme of the first manipulating frame,
of Slice when the object is sliced; the receptacle: the goal of the last Place; the movable
receptacle: the goal of the first Place of two; the toggle target: the theme of ToggleOn), and the
label is counted under the phrase's wording: its head lemma, and its last modifier with the head.
Also counted: the sentence's other words by wording and labelled class (``context``) and by class
(``class_context``), which grounding weighs; and, for a plural object phrase with no number said,
whether the task meant one thing or several (``number``: several when it picks two). The chooser's weights
(``weights``) and, fitted on the phrases said in a known room among the classes it held, what the room's other
classes add (``scene_weights``); the unsaid step, stack, slice and goal, and the task kind a sentence describes
(``task_prior``, ``task_weights``: :mod:`seal_cli.language.tasks`).

    python scripts/build_word_classes.py                 # rewrite the shipped table
    python scripts/build_word_classes.py --check         # exit 1 if the shipped table differs
    python scripts/build_word_classes.py --dev 0.2       # fit on 80 % of train trials, score the rest

``--data`` is the shared data folder (default ``../shared/data`` beside the project). ``--dev F``
holds out a fraction F of the train trials (by a hash of the trial id), builds the table on the
others and prints the five ALFRED fields on the held-out part with the rules alone and with the
table, for each ``--min-support`` / ``--min-ratio`` / ``--context-weight`` given: the settings
were chosen there, never on valid_seen.
"""

from __future__ import annotations

import argparse
import csv
import importlib.util
import itertools
import json
import math
import sys
import tempfile
import zlib
from collections import Counter
from collections.abc import Callable, Collection, Iterable, Iterator, Sequence
from dataclasses import replace
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT))
sys.path.insert(0, str(Path(__file__).resolve().parent))

from rebuilt import write_or_check  # noqa: E402  scripts/rebuilt.py, beside this script

from seal_cli.frames.library import Library  # noqa: E402
from seal_cli.frames.reading import load_library  # noqa: E402
from seal_cli.frames.taxonomy import class_key  # noqa: E402
from seal_cli.language.chooser import Instance, features, fit, logits, room_weights, scene_features  # noqa: E402
from seal_cli.language.goals import NOWHERE, goal_features, goalless  # noqa: E402
from seal_cli.language.goals import THRESHOLD as GOAL_THRESHOLD  # noqa: E402
from seal_cli.language.grounding import PORTIONS, Vocabulary  # noqa: E402
from seal_cli.language.lexicon import noun_lemma  # noqa: E402
from seal_cli.language.parser import CommandError, Parse, Phrase, parse_command  # noqa: E402
from seal_cli.language.slicing import SLICED, WHOLE, said_bare, slice_features, uncut  # noqa: E402
from seal_cli.language.slicing import THRESHOLD as SLICE_THRESHOLD  # noqa: E402
from seal_cli.language.stacking import THRESHOLD as STACK_THRESHOLD  # noqa: E402
from seal_cli.language.stacking import coordinated  # noqa: E402
from seal_cli.language.steps import NONE, STEPS, eligible, ends_at_steps, step_features  # noqa: E402
from seal_cli.language.steps import THRESHOLD as STEP_THRESHOLD  # noqa: E402
from seal_cli.language.tasks import STACK, TASKS, carried_features, task_features, uncarried  # noqa: E402
from seal_cli.language.tasks import THRESHOLD as TASK_THRESHOLD  # noqa: E402
from seal_cli.language.wordusage import (  # noqa: E402
    CONTEXT_WEIGHT,
    FORMAT,
    MIN_RATIO,
    MIN_SUPPORT,
    SHIPPED,
    WordUsage,
    context_words,
    load_word_usage,
    unsaid_wording,
)

OUT = SHIPPED / "alfred_train.json"
MANIPULATE = ("Pick", "Heat", "Cool", "Clean", "LookAt", "Place")
LABELS = ("object", "receptacle", "mrecep", "toggle")
KEEP = 2
"""A wording seen fewer times than this is left out of the file (it could never reach MIN_SUPPORT alone)."""
SECTIONS = ("words", "seen", "context", "class_context", "number", "weights", "scene_weights", "step_prior",
            "step_weights", "stacks", "step_left", "slice_prior", "slice_weights", "goal_prior", "goal_weights",
            "task_prior", "task_weights", "stack_goal_prior", "stack_goal_weights")
STEP_OF = {"pick_heat_then_place_in_recep": "Heat", "pick_cool_then_place_in_recep": "Cool",
           "pick_clean_then_place_in_recep": "Clean"}
"""The step each ALFRED task type has (the others: none)."""
L2 = 1.0
"""The chooser's L2 penalty (chosen on train trials held out from the fit, ``--dev 0.2 --l2 ...``)."""
ROOM_SPREAD: float | None = None
"""How many phrases of one wording a floor plan may count as in the chooser's fit (``chooser.room_weights``: a room
that said "island" forty times is one room's meaning); None: every phrase counts 1. Measured on train's held-out
floor plans with spread 8 (``build_task_fields.py --dev 0.2 --hold-out floor-plans --chooser-rooms 8``): the object
0.899 → 0.901, the receptacle 0.884 → 0.881, all five 1,005 → 1,009 wrong (docs/language.md, alfred31), so not
shipped."""
SCENE_L2 = 10.0
"""The scene weights' L2 penalty (chosen on train's held-out floor plans, ``--dev 0.2 --hold-out floor-plans --scenes
--scene-l2 ...``: 1.0 memorises the rooms, better on held-out trials of seen rooms and worse on unseen ones)."""


def wording(phrase: Phrase) -> tuple[str, ...] | None:
    """The lemmas grounding would look up for this phrase (None: a phrase the statistics skip, as
    grounding does: a default, a person, a portion's head, an "of" phrase)."""
    if phrase.default or phrase.kind != "thing" or not phrase.head or " of " in f" {phrase.text or ''} ".lower():
        return None
    lemmas = tuple(noun_lemma(w) for w in (*phrase.modifiers, phrase.head) if w)
    if not lemmas or lemmas[-1] in PORTIONS:
        return None
    return lemmas


def fields(parse: Parse, row: dict[str, str]) -> Iterable[tuple[Phrase, str]]:
    """(phrase, labelled class) for each labelled field the parse has a phrase for."""
    frames = parse.frames

    def el(frame: object, role: str) -> Phrase | None:
        phrase = getattr(frame, "elements", {}).get(role)
        return None if phrase is None else parse.resolve(phrase)

    places = [f for f in frames if f.frame == "Place"]
    slices = [f for f in frames if f.frame == "Slice"]
    sliced = row["sliced"] in ("1", "True", "true")
    first = slices[0] if sliced and slices else next((f for f in frames if f.frame in MANIPULATE), None)
    found = [(el(first, "theme") if first else None, row["object"])]
    if row["task_type"] != "look_at_obj_in_light" and places:
        found.append((el(places[-1], "goal"), row["receptacle"]))
    if row["mrecep"] and len(places) >= 2:
        found.append((el(places[0], "goal"), row["mrecep"]))
    toggles = [f for f in frames if f.frame == "ToggleOn"]
    if row["toggle"] and toggles:
        found.append((el(toggles[0], "theme"), row["toggle"]))
    for phrase, label in found:
        if phrase is not None and phrase.conjuncts:
            phrase = labelled_conjunct(phrase, label)
        if phrase is not None and label:
            yield phrase, label


def labelled_conjunct(phrase: Phrase, label: str) -> Phrase | None:
    """The conjunct of a coordination the label names: the one the rules ground as the labelled class.
    A coordination stands for its first conjunct, but "move a pen and mug to the dresser" labels the pen
    as the object and "move a mug and pen" too: the first conjunct would teach that a mug said beside
    "and" is a Pen. The coordination itself (its first conjunct) when no one conjunct is the label's."""
    named = [c for c in phrase.conjuncts if c.cls is not None and class_key(c.cls) == class_key(label)]
    return named[0] if len(named) == 1 else phrase


Counts = dict[str, Counter[str]]
Context = dict[str, dict[str, Counter[str]]]
Said = tuple[tuple[str, ...], str, frozenset[str], frozenset[str], str]
"""A labelled phrase as the chooser learns from it: its lemmas, the class meant, the sentence's words, the
class keys of its room (the floor plan's classes and the task's labelled ones; empty when the plan is unknown) and
the floor plan's name."""


def count(rows: Sequence[dict[str, str]], vocabulary: Vocabulary,
          scenes: dict[str, frozenset[str]]) -> tuple[Counts, Counts, Context, Counts, Counts, list[Said]]:
    """(wording → labelled classes, wording → the classes of the scenes it was said in, wording →
    labelled class → the sentence's other words, labelled class → the same over its head wordings,
    plural wording of the object → "one" or "several" things meant: the task picks two or not,
    and every labelled phrase for the chooser)."""
    library = load_library()
    rules = vocabulary.with_usage(WordUsage())
    counts: Counts = {}
    seen: Counts = {}
    context: Context = {}
    class_context: Counts = {}
    number: Counts = {}
    said_phrases: list[Said] = []
    for row, text, parse in parsed(rows, library, rules):
        words = context_words(text)
        plan = scenes.get(row["floor_plan"], frozenset())
        room = frozenset(class_key(c) for c in (*plan, *(row[k] for k in LABELS)) if c) if plan else frozenset()
        places = [f for f in parse.frames if f.frame == "Place"]
        if row["task_type"] != "look_at_obj_in_light" and row["receptacle"] and places \
                and "goal" not in places[-1].elements:   # "throw away the towel": the goal it leaves unsaid
            said = unsaid_wording("Place", "goal", places[-1].lexical_unit)
            counts.setdefault(said, Counter())[row["receptacle"]] += 1
            seen.setdefault(said, Counter()).update(scenes.get(row["floor_plan"], ()))
        for phrase, label in fields(parse, row):
            if label == row["object"] and phrase.plural and phrase.quantity is None and not phrase.conjuncts \
                    and not {"two", "both"} & set((phrase.text or "").lower().split()):
                lemmas = wording(phrase)        # a plural object: one thing meant, or several?
                for size in (2, 1):
                    if lemmas is not None and len(lemmas) >= size:
                        meant = "several" if row["task_type"] == "pick_two_obj_and_place" else "one"
                        number.setdefault(" ".join(lemmas[-size:]), Counter())[meant] += 1
            lemmas = wording(phrase)
            if lemmas is None:
                continue
            others = words - set(lemmas)             # the sentence's other words, as grounding reads them
            said_phrases.append((lemmas, label, words, room, row.get("floor_plan", "")))
            class_context.setdefault(label, Counter()).update(others)
            for size in (2, 1):
                if len(lemmas) >= size:
                    said = " ".join(lemmas[-size:])
                    counts.setdefault(said, Counter())[label] += 1
                    seen.setdefault(said, Counter()).update(scenes.get(row["floor_plan"], ()))
                    context.setdefault(said, {}).setdefault(label, Counter()).update(others)
    return counts, seen, context, class_context, number, said_phrases


def instances(said: Iterable[Said], counts: Counts, support: int = MIN_SUPPORT,
              spread: float | None = None) -> tuple[list[Instance], list[float] | None]:
    """The chooser's train instances: each labelled phrase whose wording (the longest with support,
    as grounding picks it; the phrase itself left out of the counts) meant two classes or more; and how much each
    counts (``chooser.room_weights`` by its floor plan and wording, ``spread``: :data:`ROOM_SPREAD`; None: each 1)."""
    out = []
    rooms: list[tuple[str, str]] = []
    for lemmas, label, words, _, plan in said:
        for size in (2, 1):
            if len(lemmas) < size:
                continue
            by_class = counts.get(" ".join(lemmas[-size:]))
            if not by_class or sum(by_class.values()) - 1 < support:
                continue
            left = {c: n - (c == label) for c, n in by_class.items() if n - (c == label) > 0}
            if len(left) >= 2 and label in left:
                keys = sorted(left)
                candidates = tuple(class_key(k) for k in keys)
                out.append(Instance(candidates, tuple(math.log(left[k]) for k in keys), keys.index(label),
                                    features(lemmas, words, candidates)))
                rooms.append((plan, " ".join(lemmas[-size:])))
            break
    return out, None if spread is None else room_weights(rooms, spread)


def scene_instances(said: Iterable[Said], counts: Counts, seen: Counts, weights: dict[str, dict[str, float]],
                    support: int = MIN_SUPPORT) -> list[Instance]:
    """The scene weights' train instances: each labelled phrase said in a known room whose wording (the longest
    with support among the room's classes, as grounding in a scene picks it) meant two or more of the room's
    classes, the phrase itself left out of the counts. Each candidate's offset is what grounding in a scene
    weighs before the scene's weights: the log of its rate where present
    (:meth:`~seal_cli.language.wordusage.WordUsage.choose`) plus the chooser's logit (``weights``, by class
    key); the features are the room's classes (:func:`~seal_cli.language.chooser.scene_features`)."""
    out = []
    for lemmas, label, words, room, _ in said:
        if not room:
            continue
        for size in (2, 1):
            if len(lemmas) < size:
                continue
            wording = " ".join(lemmas[-size:])
            by_class = {class_key(c): n - (c == label) for c, n in counts.get(wording, {}).items()}
            left = {k: n for k, n in by_class.items() if n > 0 and k in room}
            if sum(left.values()) < support:
                continue
            gold = class_key(label)
            if len(left) >= 2 and gold in left:
                keys = sorted(left)
                times = {class_key(c): n - 1 for c, n in seen.get(wording, {}).items()}
                total = sum(left.values())
                rates = [left[k] / times[k] if times.get(k, 0) > 0 else left[k] / total for k in keys]
                z = logits(weights, keys, features(lemmas, words, keys))
                out.append(Instance(tuple(keys), tuple(math.log(r) + z[k] for r, k in zip(rates, keys, strict=True)),
                                    keys.index(gold), scene_features(room)))
            break
    return out


def scene_classes(data: Path, classes: Sequence[str]) -> dict[str, frozenset[str]]:
    """Each floor plan's classes (its THOR object types and receptacles), spelled as ``classes``."""
    path = data / "alfred2d" / "floorplans.json"
    if not path.is_file():
        return {}
    spelling = {class_key(c): c for c in classes}
    plans = json.loads(path.read_text())["floor_plans"]
    return {name: frozenset(spelling[class_key(c)] for c in [*plan["object_types"],
                                                             *(r["class"] for r in plan["receptacles"])]
                            if class_key(c) in spelling)
            for name, plan in plans.items()}


def scenery(data: Path, classes: Sequence[str], floor_plans: Collection[str] | None = None) -> list[str]:
    """The classes of ALFRED's floor plans that are none of ``classes`` (THOR's ``Faucet``, ``ShowerHead``):
    parts of a scene no sentence names as a task's thing, listed so that a scene's vocabulary is still
    one the statistics know (:attr:`~seal_cli.language.wordusage.WordUsage.scenery`). ``floor_plans``: only
    these floor plans' classes (a fit on some of them); None: every floor plan's."""
    path = data / "alfred2d" / "floorplans.json"
    if not path.is_file():
        return []
    known = {class_key(c) for c in classes}
    plans = json.loads(path.read_text())["floor_plans"]
    found = {c for name, plan in plans.items() if floor_plans is None or name in floor_plans
             for c in [*plan["object_types"], *(r["class"] for r in plan["receptacles"])]}
    return sorted(c for c in found if class_key(c) not in known)


def table(counts: Counts, seen: Counts, context: Context, class_context: Counts, number: Counts,
          said: list[Said], classes: Sequence[str], source: str, l2: float | None = L2,
          scene_l2: float | None = SCENE_L2, spread: float | None = ROOM_SPREAD) -> dict[str, object]:
    """The table's sections; ``l2``: the chooser's penalty (None: no chooser, the naive Bayes context);
    ``scene_l2``: the scene weights' (None: none); ``spread``: how the chooser's phrases count by their room
    (:data:`ROOM_SPREAD`; None: each 1)."""
    spelling = {class_key(c): c for c in classes}
    chosen, counted = instances(said, counts, spread=spread)
    fitted = {} if l2 is None else fit(chosen, l2, weights=counted)
    weights = {f: {spelling[k]: w for k, w in by.items()} for f, by in fitted.items()}
    in_scene = {} if l2 is None or scene_l2 is None else fit(scene_instances(said, counts, seen, fitted), scene_l2)
    scene_weights = {f: {spelling[k]: w for k, w in by.items()} for f, by in in_scene.items()}
    words = {w: dict(sorted(c.items(), key=lambda kv: (-kv[1], kv[0])))
             for w, c in sorted(counts.items()) if sum(c.values()) >= KEEP}
    where = {w: {c: seen[w][c] for c in by_class if seen.get(w, {}).get(c)} for w, by_class in words.items()}
    return {"format": FORMAT, "source": source, "built_by": "scripts/build_word_classes.py",
            "classes": list(classes), "words": words, "seen": {w: c for w, c in where.items() if c},
            "context": {} if weights else pruned(context, words),        # the chooser weighs the sentence
            "class_context": {} if weights else {c: ordered(Counter({w: n for w, n in by.items() if n >= KEEP}))
                                                 for c, by in sorted(class_context.items())},
            "number": {w: ordered(by) for w, by in sorted(number.items()) if sum(by.values()) >= KEEP},
            "weights": weights, "scene_weights": scene_weights}


def usage_of(data: dict[str, object]) -> WordUsage:
    """A table's statistics, read back as they are read when shipped."""
    with tempfile.TemporaryDirectory() as folder:
        path = Path(folder) / "table.json"
        path.write_text(dump(data))
        return load_word_usage([path])


def with_steps(data: dict[str, object], rows: Sequence[dict[str, str]], vocabulary: Vocabulary,
               l2: float = L2) -> dict[str, object]:
    """The table with its unsaid-step and unsaid-stack models: each row's sentence parsed with the
    table's grounding (nothing inferred); where the parse places one thing and says no step
    (:func:`~seal_cli.language.steps.eligible`), the task's step (or none) learned from the
    sentence's words and the classes put and where (:func:`~seal_cli.language.steps.step_features`);
    where it places two things of different classes together (:func:`~seal_cli.language.stacking.coordinated`),
    each conjunct's class counted as said, and as holding when the task carried the other in it; where
    it ends at two steps (:func:`~seal_cli.language.steps.ends_at_steps`), the last step counted as
    ended, and as left when the task left the thing in that step's instrument; where it says no cutting
    of a thing of a class train tasks sliced (:func:`~seal_cli.language.slicing.uncut`), whether the task
    sliced it, learned from the sentence's words, the thing's class and the frames evoked
    (:func:`~seal_cli.language.slicing.slice_features`); and, for every sentence parsed, its task's kind, learned
    from its words, the frames said, the classes handled and put and how many Places
    (:func:`~seal_cli.language.tasks.task_features`); and the classes train tasks put a thing in or on
    (``receptacles``: a goal said beside none of them is unsaid, :func:`~seal_cli.language.goals.said_beside`)."""
    library = load_library()
    grounded = vocabulary.with_usage(usage_of(data))
    said: list[tuple[str, tuple[str, ...]]] = []
    stacks: dict[str, Counter[str]] = {}
    ended: dict[str, Counter[str]] = {}
    sliceable = sorted({class_key(r["object"]) for r in rows if r["sliced"] in ("1", "True", "true")})
    cut: list[tuple[str, tuple[str, ...]]] = []
    put: list[tuple[str, tuple[str, ...]]] = []
    told: list[tuple[str, tuple[str, ...]]] = []
    spelling = {class_key(c): c for c in data["classes"]}  # type: ignore[union-attr]
    for row, text, parse in parsed(rows, library, grounded, infer_steps=False):
        if row["task_type"] in TASKS:
            told.append((row["task_type"], task_features(context_words(text), parse)))
        pair = coordinated(parse)
        for phrase in pair[1:] if pair else ():
            by = stacks.setdefault(phrase.cls or "", Counter())
            by["said"] += 1
            if row["task_type"] == "pick_and_place_with_movable_recep" and \
                    class_key(row["mrecep"]) == class_key(phrase.cls or ""):
                by["holds"] += 1
        last = ends_at_steps(parse)
        if last is not None:
            step = parse.frames[last]
            by = ended.setdefault(step.frame, Counter())
            by["ended"] += 1
            if class_key(parse.resolve(step.elements["instrument"]).cls or "") == class_key(row["receptacle"]):
                by["left"] += 1
        first = uncut(parse, sliceable)
        if first is not None:
            thing_said = parse.resolve(parse.frames[first].elements["theme"])
            cut.append((SLICED if row["sliced"] in ("1", "True", "true") else WHOLE,
                        slice_features(context_words(text), thing_said.cls, (f.frame for f in parse.frames),
                                       said_bare(thing_said))))
        handled = goalless(parse)
        if handled is not None and (row["task_type"] == "look_at_obj_in_light" or row["receptacle"]):
            goal = NOWHERE if row["task_type"] == "look_at_obj_in_light" else spelling[class_key(row["receptacle"])]
            thing = parse.resolve(parse.frames[handled].elements["theme"]).cls
            put.append((goal, goal_features(context_words(text), thing, (f.frame for f in parse.frames))))
        at = eligible(parse)
        if at is None:
            continue
        place = parse.frames[at]
        feats = step_features(context_words(text), parse.resolve(place.elements["theme"]).cls,
                              parse.resolve(place.elements["goal"]).cls)
        said.append((STEP_OF.get(row["task_type"], NONE), feats))
    prior = Counter(step for step, _ in said)
    keys = tuple(k for k in (*STEPS, NONE) if prior[k])
    offsets = tuple(math.log(prior[k]) for k in keys)
    weights = fit([Instance(keys, offsets, keys.index(step), feats) for step, feats in said], l2)
    kinds = Counter(kind for kind, _ in cut)
    cuts = (SLICED, WHOLE)
    cut_offsets = tuple(math.log(max(kinds[k], 1)) for k in cuts)
    cut_weights = fit([Instance(cuts, cut_offsets, cuts.index(kind), feats) for kind, feats in cut], l2)
    goals = Counter(goal for goal, _ in put)
    goal_keys = tuple(sorted(goals))
    goal_weights = fit([Instance(goal_keys, tuple(math.log(goals[k]) for k in goal_keys), goal_keys.index(goal), feats)
                        for goal, feats in put], l2)
    kinds_told = Counter(kind for kind, _ in told)
    task_keys = tuple(k for k in TASKS if kinds_told[k])
    task_weights = fit([Instance(task_keys, tuple(math.log(kinds_told[k]) for k in task_keys), task_keys.index(kind),
                                 feats) for kind, feats in told], l2)
    holders = sorted({spelling[class_key(r[k])] for r in rows for k in ("receptacle", "mrecep")
                      if r[k] and class_key(r[k]) in spelling})     # what train tasks put a thing in or on
    return {**data, "receptacles": holders, "slice_classes": [spelling[k] for k in sliceable if k in spelling],
            "slice_prior": {k: kinds[k] for k in cuts if kinds[k]}, "slice_weights": cut_weights,
            "step_prior": {k: prior[k] for k in keys}, "step_weights": weights,
            "stacks": {c: dict(sorted(by.items(), reverse=True)) for c, by in sorted(stacks.items())
                       if by["said"] >= KEEP},
            "step_left": {s: dict(sorted(by.items())) for s, by in sorted(ended.items()) if by["ended"] >= KEEP},
            "goal_prior": {k: goals[k] for k in goal_keys}, "goal_weights": goal_weights,
            "task_prior": {k: kinds_told[k] for k in task_keys}, "task_weights": task_weights}


def with_stack_goals(data: dict[str, object], rows: Sequence[dict[str, str]], vocabulary: Vocabulary,
                     l2: float = L2) -> dict[str, object]:
    """The table with where a stack's container goes when the sentence says nowhere
    (:attr:`~seal_cli.language.tasks.TaskModel.carried`): each stack's sentence parsed with the table's grounding
    (nothing inferred); where the parse puts one thing in a container and nothing more
    (:func:`~seal_cli.language.tasks.uncarried`), the task's receptacle learned from the sentence's words, the
    container's class and the frames said (:func:`~seal_cli.language.tasks.carried_features`)."""
    library = load_library()
    grounded = vocabulary.with_usage(usage_of(data))
    spelling = {class_key(c): c for c in data["classes"]}  # type: ignore[union-attr]
    went: list[tuple[str, tuple[str, ...]]] = []
    stacks = [r for r in rows if r["task_type"] == STACK and class_key(r["receptacle"]) in spelling]
    for row, text, parse in parsed(stacks, library, grounded, infer_steps=False):
        at = uncarried(parse, library)
        if at is None:
            continue
        container = parse.resolve(parse.frames[at].elements["goal"]).cls
        went.append((spelling[class_key(row["receptacle"])], carried_features(context_words(text), parse, container)))
    prior = Counter(goal for goal, _ in went)
    keys = tuple(sorted(prior))
    weights = fit([Instance(keys, tuple(math.log(prior[k]) for k in keys), keys.index(goal), feats)
                   for goal, feats in went], l2) if len(keys) >= 2 else {}
    return {**data, "stack_goal_prior": {k: prior[k] for k in keys}, "stack_goal_weights": weights}


def ordered(words: Counter[str]) -> dict[str, int]:
    return dict(sorted(words.items(), key=lambda kv: (-kv[1], kv[0])))


def pruned(context: Context, words: dict[str, dict[str, int]]) -> dict[str, dict[str, dict[str, int]]]:
    """The context counts that can matter: of wordings kept that meant two classes or more, the
    words said with the wording at least ``KEEP`` times."""
    out: dict[str, dict[str, dict[str, int]]] = {}
    for wording in words:
        by_class = context.get(wording, {})
        if len(words[wording]) < 2:
            continue
        together: Counter[str] = Counter()
        for said in by_class.values():
            together.update(said)
        row = {c: ordered(Counter({w: n for w, n in said.items() if together[w] >= KEEP}))
               for c, said in sorted(by_class.items(), key=lambda kv: (-words[wording].get(kv[0], 0), kv[0]))
               if c in words[wording]}
        row = {c: said for c, said in row.items() if said}
        if row:
            out[wording] = row
    return out


FITTED_TOLERANCE = 0.005
"""How far a fitted weight may differ from the shipped one in ``--check``: L-BFGS stops at a
gradient tolerance, so another scipy or BLAS moves the third decimal of a few weights (and drops or
adds a weight that rounds to zero). Every count must be the same."""


def differences(shipped: object, built: object, path: str = "") -> list[str]:
    """Where two tables differ: any count, word or key, or a fitted number by more than
    :data:`FITTED_TOLERANCE` (a number missing on one side counts as zero)."""
    def small(value: object) -> bool:
        return isinstance(value, float) and abs(value) <= FITTED_TOLERANCE

    if isinstance(shipped, dict) and isinstance(built, dict):
        out: list[str] = []
        for key in sorted(set(shipped) | set(built)):
            if key not in shipped or key not in built:
                if not small(shipped.get(key, built.get(key))):
                    out.append(f"{path}/{key} only in the {'new' if key not in shipped else 'shipped'} table")
                continue
            out += differences(shipped[key], built[key], f"{path}/{key}")
        return out
    if isinstance(shipped, list) and isinstance(built, list):
        if len(shipped) != len(built):
            return [f"{path}: {len(shipped)} entries shipped, {len(built)} built"]
        pairs = enumerate(zip(shipped, built, strict=True))
        return [d for k, (a, b) in pairs for d in differences(a, b, f"{path}[{k}]")]
    if isinstance(shipped, float) and isinstance(built, float):
        return [] if abs(shipped - built) <= FITTED_TOLERANCE else [f"{path}: {shipped} shipped, {built} built"]
    same = shipped == built and type(shipped) is type(built)
    return [] if same else [f"{path}: {shipped!r} shipped, {built!r} built"]


def dump(data: dict[str, object]) -> str:
    """JSON with one wording a line, so that a rebuild's diff reads."""
    head = {k: v for k, v in data.items() if k not in SECTIONS}
    text = json.dumps(head, indent=1)[:-2]
    for name in SECTIONS:
        rows = data.get(name, {})
        assert isinstance(rows, dict)
        text += f',\n "{name}": {{\n' + ",\n".join(f"  {json.dumps(w)}: {json.dumps(c)}" for w, c in rows.items())
        text += "\n }"
    return text + "\n}\n"


def parsed(rows: Iterable[dict[str, str]], library: Library, vocabulary: Vocabulary,
           infer_steps: bool = True) -> Iterator[tuple[dict[str, str], str, Parse]]:
    """Each row whose goal sentence parses: (the row, its sentence on one line, its parse); a sentence the parser
    refuses is left out."""
    for row in rows:
        text = " ".join(row["goal_sentence"].split())
        try:
            parse = parse_command(text, library, vocabulary, infer_steps=infer_steps)
        except CommandError:
            continue
        yield row, text, parse


def held_out(rows: Sequence[dict[str, str]], fraction: float, unit: str = "trials") -> set[str]:
    """The task ids held out for ``--dev``: a ``fraction`` of the trials, or of the floor plans (``unit``
    "floor-plans": every trial of a held-out floor plan, so that no room of theirs was fitted on, as on the
    unseen split), chosen by a hash of the trial id or the floor plan's name."""
    key = "task_id" if unit == "trials" else "floor_plan"
    return {r["task_id"] for r in rows if zlib.crc32(r[key].encode()) % 1000 < fraction * 1000}


def read_rows(path: Path) -> list[dict[str, str]]:
    with path.open(newline="") as handle:
        return list(csv.DictReader(handle, delimiter="\t"))


def scorer(data: Path):  # type: ignore[no-untyped-def]
    path = data.parent / "eval" / "score_alfred_goals.py"
    spec = importlib.util.spec_from_file_location("score_alfred_goals", path)
    if spec is None or spec.loader is None:
        raise SystemExit(f"error: {path}: cannot load the ALFRED scorer")
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def score(rows: Sequence[dict[str, str]], vocabulary: Callable[[dict[str, str]], Vocabulary],
          module, errors: list[str] | None = None,  # type: ignore[no-untyped-def]
          bring_goal: bool = False) -> dict[str, float | int]:
    """The scorer's five fields on these rows, each parsed with ``vocabulary(row)``, and how many
    parses had a frame inferred (``inferred``) and were then of the task's type (``inferred_right``);
    each row scored wrong is added to ``errors`` (a TSV line: the fields wrong, the sentence, what was
    read, the gold). ``bring_goal``: read a Bring to a place (a goal, no recipient) as the scorer reads
    a Place (the scorer itself reads Place only)."""
    library = load_library()
    hits: Counter[str] = Counter()
    for row in rows:
        try:
            parse = parse_command(" ".join(row["goal_sentence"].split()), library, vocabulary(row)).to_json()
        except CommandError:
            parse = {}
        if bring_goal:
            parse = {**parse, "frames": [{**f, "frame": "Place"} if f["frame"] == "Bring" and "goal" in f["elements"]
                                         and "recipient" not in f["elements"] else f
                                         for f in parse.get("frames", [])]}
        want = module.gold(row)
        got = module.read_back(parse) if parse.get("frames") else {f: None for f in module.FIELDS}
        ok = {f: got[f] == want[f] for f in module.FIELDS}
        hits.update(f for f, good in ok.items() if good)
        hits["all"] += all(ok.values())
        if any(f.get("inferred") for f in parse.get("frames", [])):
            hits["inferred"] += 1
            hits["inferred_right"] += ok["type"]
        if errors is not None and not all(ok.values()):
            wrong = ",".join(f for f, good in ok.items() if not good)
            errors.append("\t".join([wrong, row["goal_sentence"].strip(), json.dumps(got), json.dumps(want)]))
    n = max(len(rows), 1)
    return {**{f: hits[f] / n for f in ("all", *module.FIELDS)},
            "inferred": hits["inferred"], "inferred_right": hits["inferred_right"]}


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--data", type=Path, default=ROOT.parent / "shared" / "data")
    ap.add_argument("--out", type=Path, default=OUT)
    ap.add_argument("--check", action="store_true", help="compare with the shipped table instead of writing it")
    ap.add_argument("--dev", type=float, default=0.0, help="hold out this fraction of train trials and score it")
    ap.add_argument("--hold-out", choices=("trials", "floor-plans"), default="trials",
                    help="with --dev: hold out trials (of floor plans the fit also saw, as valid_seen) or whole floor "
                         "plans (none of whose rooms the fit saw, as the unseen split)")
    ap.add_argument("--min-support", type=int, nargs="*", default=[MIN_SUPPORT])
    ap.add_argument("--min-ratio", type=float, nargs="*", default=[MIN_RATIO])
    ap.add_argument("--context-weight", type=float, nargs="*", default=[CONTEXT_WEIGHT])
    ap.add_argument("--l2", type=float, nargs="*", default=[L2], help="the chooser's L2 penalties to try")
    ap.add_argument("--scene-l2", type=float, default=SCENE_L2,
                    help="with --dev: the scene weights' L2 penalty (0: no scene weights)")
    ap.add_argument("--step-threshold", type=float, nargs="*", default=[STEP_THRESHOLD],
                    help="the least probability at which an unsaid step is added (2: never); those to try")
    ap.add_argument("--stack-threshold", type=float, nargs="*", default=[STACK_THRESHOLD],
                    help="the least rate at which a coordination is read as a stack (2: never); those to try")
    ap.add_argument("--slice-threshold", type=float, nargs="*", default=[SLICE_THRESHOLD],
                    help="the least probability at which an unsaid slice is added (2: never); those to try")
    ap.add_argument("--goal-threshold", type=float, nargs="*", default=[GOAL_THRESHOLD],
                    help="the least probability at which an unsaid goal is added (2: never); those to try")
    ap.add_argument("--task-threshold", type=float, nargs="*", default=[TASK_THRESHOLD],
                    help="the least probability at which a task's frame is added (2: never); those to try")
    ap.add_argument("--bring-goal", action="store_true", help="with --dev: score a Bring to a place (goal, "
                    "no recipient) as the scorer scores a Place")
    ap.add_argument("--errors", type=Path, help="with --dev: write the held-out sentences scored wrong here (TSV)")
    ap.add_argument("--errors-of", default=None, help="with --dev: the table whose errors --errors writes "
                    "('naive Bayes', 'chooser l2 1.0'; default: the first chooser)")
    ap.add_argument("--scenes", action="store_true", help="with --dev: also score in each sentence's scene")
    ap.add_argument("--scene-errors", type=Path, help="with --dev --scenes: write the held-out sentences scored wrong "
                    "in their scenes (rates where present) here (TSV)")
    args = ap.parse_args()

    goals = args.data / "alfred" / "goals_train.tsv"
    constants = args.data / "alfred" / "alfred_constants.json"
    for path in (goals, constants):
        if not path.is_file():
            print(f"error: {path}: no such file (the shared data folder is --data)", file=sys.stderr)
            return 1
    classes = json.loads(constants.read_text())["OBJECTS"]
    vocabulary = Vocabulary.of(classes)
    rows = [r for r in read_rows(goals) if r.get("split", "train") == "train"]
    scenes = scene_classes(args.data, classes)

    if args.dev:
        args.errors_of = args.errors_of or f"chooser l2 {args.l2[0]}"
        errors: list[str] = []
        held = held_out(rows, args.dev, args.hold_out)
        fit_rows = [r for r in rows if r["task_id"] not in held]
        dev = [r for r in rows if r["task_id"] in held]
        module = scorer(args.data)
        counted = count(fit_rows, vocabulary, scenes)
        print(f"fit {len(fit_rows)} sentences, dev {len(dev)} sentences ({len(held)} trials)")

        def fitted(l2: float | None) -> WordUsage:
            data = table(*counted, classes, "dev", l2, args.scene_l2 or None)  # as it would ship, read as it is
            return usage_of(with_stack_goals(with_steps(data, fit_rows, vocabulary), fit_rows, vocabulary)
                            if l2 is not None else data)

        def show(name: str, figures: dict[str, float | int]) -> None:
            print(f"{name:<34}" + " ".join(f"{k} {v:.3f}" if isinstance(v, float) else f"{k} {v}"
                                           for k, v in figures.items()), flush=True)

        show("rules alone", score(dev, lambda row: vocabulary.with_usage(WordUsage()), module))
        tables = {"naive Bayes": fitted(None), **{f"chooser l2 {l2}": fitted(l2) for l2 in args.l2}}
        for name, table_ in tables.items():
            for support in args.min_support:
                for ratio in args.min_ratio:
                    for weight in args.context_weight:
                        tries = itertools.product(args.step_threshold, args.stack_threshold, args.slice_threshold,
                                                  args.goal_threshold, args.task_threshold) \
                            if table_.steps else [(args.step_threshold[0], args.stack_threshold[0],
                                                   args.slice_threshold[0], args.goal_threshold[0],
                                                   args.task_threshold[0])]
                        for threshold, stacking, slicing, putting, telling in tries:
                            tried = vocabulary.with_usage(replace(
                                table_, min_support=support, min_ratio=ratio, context_weight=weight,
                                steps=replace(table_.steps, threshold=threshold),
                                stacks=replace(table_.stacks, threshold=stacking),
                                slices=replace(table_.slices, threshold=slicing),
                                goals=replace(table_.goals, threshold=putting),
                                tasks=replace(table_.tasks, threshold=telling)))
                            first = (threshold, stacking, slicing, putting, telling) == (
                                args.step_threshold[0], args.stack_threshold[0], args.slice_threshold[0],
                                args.goal_threshold[0], args.task_threshold[0])
                            show(f"{name}, support {support} ratio {ratio}" + ("" if table_.weights else
                                                                             f" context {weight}")
                                 + (f" step {threshold}" if table_.steps else "")
                                 + (f" stack {stacking}" if table_.stacks else "")
                                 + (f" slice {slicing}" if table_.slices else "")
                                 + (f" goal {putting}" if table_.goals else "")
                                 + (f" task {telling}" if table_.tasks else ""),
                                 score(dev, lambda row, v=tried: v, module,
                                       errors if name == args.errors_of and first else None, args.bring_goal))
        if args.errors is not None:
            args.errors.write_text("".join(line + "\n" for line in errors))
            print(f"wrote {args.errors} ({len(errors)} sentences of {args.errors_of} scored wrong)")
        if not args.scenes:
            return 0
        usage = replace(tables[args.errors_of or "naive Bayes"], min_support=args.min_support[0],
                        min_ratio=args.min_ratio[0], context_weight=args.context_weight[0])

        def in_scene(row: dict[str, str], *, rates: bool, learned: bool = True) -> Vocabulary:
            present = scenes.get(row["floor_plan"], frozenset()) | {row[k] for k in LABELS if row[k]}
            scene = vocabulary.restricted_to(present)
            scene = scene.with_usage(usage if learned else WordUsage())
            return scene if rates else Vocabulary.of(scene.classes, usage=scene.usage)

        print("in the scene's classes:")
        show("  rules alone", score(dev, lambda row: in_scene(row, rates=True, learned=False), module))
        show("  counts", score(dev, lambda row: in_scene(row, rates=False), module))
        wrong: list[str] = []
        show("  rates where present", score(dev, lambda row: in_scene(row, rates=True), module, wrong))
        if args.scene_errors is not None:
            args.scene_errors.write_text("".join(line + "\n" for line in wrong))
            print(f"wrote {args.scene_errors} ({len(wrong)} sentences scored wrong in their scenes)")
        return 0

    source = (f"ALFRED train goals ({goals.name}: {len(rows)} human goal sentences with their task labels), "
              "parsed by seal's rules; counts of the labelled class by the wording of the phrase that fills its field, "
              "and of the sentence's other words by wording and class")
    text = dump({**with_stack_goals(with_steps(table(*count(rows, vocabulary, scenes), classes, source), rows,
                                               vocabulary), rows, vocabulary),
                 "scenery": scenery(args.data, classes)})
    return write_or_check(args.out, text, check=args.check, made_from="the train split", compare=differences,
                          summary=f"{len(json.loads(text)['words'])} wordings")


if __name__ == "__main__":
    raise SystemExit(main())
