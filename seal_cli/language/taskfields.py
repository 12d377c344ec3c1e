"""The task a whole sentence describes, read as ALFRED's fields by a model of its words, learned on a train split,
and combined with the parser's own reading.

ALFRED's people wrote one sentence for each task they watched; the task is five fields (its type, the object, the
receptacle, the movable receptacle, whether the object is sliced). The parser reads the fields off its frames
(:func:`read_fields`, as ALFRED parses are scored), and its statistics weigh one decision at a time (which class a
phrase means, whether a step is unsaid). A :class:`FieldModel` weighs the whole sentence at once: for each of the
first four fields a multinomial logistic regression over the sentence's word unigrams and bigrams
(:func:`sentence_grams`), the chooser's model (:func:`~seal_cli.language.chooser.posterior`), every label of the
field a candidate:

    P(value | sentence) ∝ prior(value) · exp(Σ_g weight[g][value])

"a *cold* apple", "*chill*", "*rinse*" say the step; "the *butter* knife", "*bread* knife" which knife; "put the
remote *on the table* by the couch" which table. It is fitted by ``scripts/build_task_fields.py`` on ALFRED's train
goals (the label each trial's task gives) and shipped as ``task_fields/alfred_train.json``.

**The combination** (:func:`combine`): each field's value is the most probable by the model once the parser's own
reading is given :attr:`FieldModel.trust` (a log-odds bonus per field, chosen on train trials held out from the fit:
``build_task_fields.py --dev 0.2 --trust ...``), in order and consistently: the type first; the object (a class, never
none); the receptacle (none for a look, else a class); the movable receptacle only for a stack. A stack whose
movable receptacle would be the object's own class is no stack (no train task repeats a class across its fields): the
parser's type stands, or else the next best. Only classes of the
vocabulary are candidates (in a room, its classes).

The bonus is one weight of a few features of each candidate value (:func:`candidates`, :func:`score`); they can be
learned on parses of held-out train sentences (:func:`fit_trust`, ``build_task_fields.py --dev 0.2 --learn``), but
learned so they were no better than the hand-set bonuses (``docs/language.md``, alfred21), which stay shipped.

**The fifth field, sliced**, is read last, once the type and object are chosen: P(sliced | the sentence's grams, the
type, the object, the two together) (:func:`slice_grams`, :func:`sliced_probability`), fitted on train's tasks whose
object is of a class train sliced (:attr:`FieldModel.sliceable`). A parse that says no cutting (and to which the
unsaid-slice model, :mod:`~seal_cli.language.slicing`, added none) gets a Slice of the object, marked inferred, when
the sliced value is the more probable (:data:`SLICE_ADD`): "put a bowl with an apple in it in the fridge" reads as the
stack it is, and an apple moved in a container was sliced in 128 of train's 164 such stacks. A Slice said or
inferred is never taken away.

**What changes in the parse** (:func:`reread`): when the combined type is the parser's, only the classes of the
phrases the parser read the fields from (the root of a pronoun's chain), when they differ; when it is another type
(or a field has no phrase), the frames are written anew from the fields, the parser's phrases reused where they
said the thing (its words kept, its class the field's), each written frame marked ``Evoked.inferred`` with the
type's probability. A sliced object keeps the parser's Slice. A look whose thing is only found or carried to the
lamp gets an inferred LookAt of it, every said frame kept (:func:`_looked_at`). Guards: a parse with a frame no task
field holds (:data:`TASK_FRAMES`: "... and find the clock"), or whose object was said beside a thing of another class
("the knife and the apple", :func:`_coordinated`), is never written anew, only its classes may change; and a said
phrase takes only a class people meant by its head often enough (:data:`MIN_SHARE`, :data:`FILL_SHARE`: "the table"
by the couch is never the sofa; a "back" nothing places is no phrase of a class).

**Scoped** as the unsaid step is (:attr:`~seal_cli.language.grounding.Vocabulary.field_model`): only with the
statistics seal ships, where every class of the vocabulary is one they know (ALFRED's, or an ALFRED scene's), never
in a house's vocabulary; ``parse_command(..., infer_steps=False)`` turns it off.
"""

from __future__ import annotations

import json
import math
import re
from collections import Counter
from collections.abc import Iterable, Mapping, Sequence
from dataclasses import dataclass, field, replace
from functools import cache
from pathlib import Path
from types import MappingProxyType
from typing import TYPE_CHECKING

from seal_cli.frames.taxonomy import class_key, class_words
from seal_cli.language.chooser import Instance, fit, posterior, room_weights
from seal_cli.language.reference import back_unplaced
from seal_cli.language.slicing import slice_before, uncut
from seal_cli.language.values import Evoked, Parse, Phrase

if TYPE_CHECKING:
    from seal_cli.frames.library import Library
    from seal_cli.language.grounding import Vocabulary

__all__ = ["FIELDS", "NOTHING", "SHIPPED", "TRUST", "FieldModel", "Reading", "candidates", "combine",
           "field_classes", "fit_fields", "fit_trust", "fit_trust_count", "label", "load_field_model", "read_fields",
           "reread", "score", "sentence_grams", "shipped_field_model", "slice_grams", "sliced_probability", "wanted"]

SHIPPED = Path(__file__).parent / "task_fields" / "alfred_train.json"
FIELDS = ("type", "object", "receptacle", "mrecep")
"""The fields the model reads and combines with the parser's reading (sliced: :data:`SLICED`)."""
SLICED = "sliced"
"""The fifth field, read after the others (:func:`slice_grams`): only ever a Slice added the parser left unsaid."""
SLICE_VALUES = ("sliced", "whole")
SLICE_ADD = 0.5
"""The least probability of :data:`SLICED` at which a Slice the parse does not say is added: the more probable value,
as every other field is decided (not tuned; 0.6 and 0.7 measured no better on held-out train floor plans:
``build_task_fields.py --dev 0.2 --hold-out floor-plans --slice-add ...``)."""
NOTHING = "none"
"""The value of a field the task has not (a look's receptacle, a movable receptacle of all but a stack)."""
LOOK = "look_at_obj_in_light"
SIMPLE = "pick_and_place_simple"
STACK = "pick_and_place_with_movable_recep"
TWO = "pick_two_obj_and_place"
STEP_OF = MappingProxyType({"pick_heat_then_place_in_recep": "Heat", "pick_cool_then_place_in_recep": "Cool",
                            "pick_clean_then_place_in_recep": "Clean"})
MANIPULATE = ("Pick", "Heat", "Cool", "Clean", "LookAt", "Place")
"""The frames whose theme is the object, the first of them read (as the scorer reads a parse)."""
TRUST = MappingProxyType({"type": 2.0, "object": 3.0, "receptacle": 2.0, "mrecep": 1.5})
"""The parser's reading's log-odds bonus per field (chosen on held-out train: ``build_task_fields.py --dev 0.2``)."""
TASK_FRAMES = frozenset(("Pick", "Place", "Heat", "Cool", "Clean", "Slice", "LookAt", "ToggleOn", "ToggleOff"))
"""The frames an ALFRED task's fields hold: a parse with any other ("and find the clock") is never written anew."""
MIN_MEANT = 2
MIN_SHARE = 0.01
"""A said phrase the rules grounded may be given another class only when people meant that class by its head at least
:data:`MIN_MEANT` times and this share of its phrases (a label's slip, a table labelled the sofa beside it, is no
meaning of "table": 2 of 2,793)."""
FILL_MEANT = 5
FILL_SHARE = 0.05
"""A said phrase the rules grounded to nothing may be given a class only when people meant it by its head at least
:data:`FILL_MEANT` times and this share of its phrases (the thresholds of ``scripts/alfred_goal_errors.py``'s "one
word, two classes"): with nothing said for the parser's class, a glass is not the butter knife labelled beside it
7 times in 319."""
MIN_COUNT = 2
"""A word or bigram is a feature when said in at least this many train sentences with the value (both ways)."""
L2 = 1.0
"""The fit's L2 penalty."""
UNSEEN = 1e-3
"""The model's probability of a value it never saw a train task take (the parser's reading of a rare class)."""
TRUST_L2 = 1.0
"""The L2 penalty of :func:`fit_trust` (towards the unlearned combination)."""


def sentence_grams(text: str) -> tuple[str, ...]:
    """The sentence's features: ``u:`` each word (lower case, letters only), ``b:`` each pair of adjacent words,
    ``<s>`` and ``</s>`` marking its ends ("Chill an apple." → ``u:chill``, ``b:<s>_chill``, ``b:chill_an``, ...)."""
    words = re.findall(r"[a-z]+", text.lower())
    grams = {f"u:{w}" for w in words}
    grams.update(f"b:{a}_{b}" for a, b in zip(["<s>", *words], [*words, "</s>"], strict=True))
    return tuple(sorted(grams))


def slice_grams(grams: Iterable[str], kind: str, thing: str) -> tuple[str, ...]:
    """The features of the sliced field: the sentence's ``grams`` (:func:`sentence_grams`) and the task read, its
    type ``t:``, its object's class key ``o:`` and the two together ``to:`` ("put a bowl with an apple in it in the
    fridge": an apple moved in a container was sliced in most of train's stacks, a cooled one in half)."""
    return (*grams, f"t:{kind}", f"o:{thing}", f"to:{kind}|{thing}")


@dataclass(frozen=True)
class FieldModel:
    """For each field of :data:`FIELDS`, ``priors[field][value]`` (how often train tasks had it; a class key, a task
    type or :data:`NOTHING`) and ``weights[field][gram][value]``; ``trust``: the parser's bonus per field. Empty:
    nothing is reread. The sliced field (:data:`SLICED`, its values :data:`SLICE_VALUES`), when fitted, has its priors
    and weights too, and ``sliceable``: the class keys of the objects train tasks sliced (no other is ever cut);
    ``slice_add``: the least probability at which an unsaid Slice is added (:data:`SLICE_ADD`)."""

    priors: Mapping[str, Mapping[str, int]] = field(default_factory=dict)
    weights: Mapping[str, Mapping[str, Mapping[str, float]]] = field(default_factory=dict)
    trust: Mapping[str, float] = field(default_factory=lambda: dict(TRUST))
    sliceable: frozenset[str] = frozenset()
    slice_add: float = SLICE_ADD

    def __bool__(self) -> bool:
        return all(self.priors.get(f) for f in FIELDS)

    def probabilities(self, name: str, grams: Iterable[str], allowed: Iterable[str] | None = None) -> dict[str, float]:
        """P(value | grams) for the field ``name`` over its values (those of ``allowed`` only, when given)."""
        prior = self.priors.get(name, {})
        keep = None if allowed is None else set(allowed)
        keys = [k for k, n in prior.items() if n and (keep is None or k in keep)]
        return posterior(prior, self.weights.get(name, {}), keys, grams) if keys else {}


def sliced_probability(model: FieldModel, grams: Iterable[str], kind: str, thing: str) -> float:
    """P(the object is sliced | the sentence's grams, the task's type ``kind`` and object ``thing``): 0.0 when the
    model has no sliced field."""
    return model.probabilities(SLICED, slice_grams(grams, kind, thing)).get(SLICE_VALUES[0], 0.0)


@dataclass(frozen=True)
class Reading:
    """A parse read as ALFRED's fields: the type, the class key of each of object, receptacle and movable receptacle
    (:data:`NOTHING`: none read) and where its phrase is (frame index, element: the root of a pronoun's chain;
    None: no phrase), and whether the object is sliced."""

    type: str | None
    values: Mapping[str, str]
    at: Mapping[str, tuple[int, str] | None]
    sliced: bool
    unsaid: frozenset[str] = frozenset()


def _root(parse: Parse, at: tuple[int, str]) -> tuple[int, str]:
    seen = set()
    while at not in seen:
        seen.add(at)
        phrase = parse.frames[at[0]].elements.get(at[1])
        if phrase is None or phrase.refers_to is None or phrase.refers_to[0] >= len(parse.frames) \
                or phrase.refers_to[1] not in parse.frames[phrase.refers_to[0]].elements:
            return at
        at = phrase.refers_to
    return at


def _plural(phrase: Phrase) -> bool:
    text = (phrase.text or "").lower().split()
    return phrase.quantity == 2 or "two" in text or "both" in text or phrase.plural


def _carried_to(frame: Evoked) -> bool:
    """A Bring to a place said (a goal, no recipient: "take the box *to the shelf*"), which ends as a Place does
    (the library's Bring: ``in(theme, goal)``)."""
    goal = frame.elements.get("goal")
    return frame.frame == "Bring" and goal is not None and not goal.default and "recipient" not in frame.elements


def read_fields(parse: Parse) -> Reading:
    """The fields a parse says, read as ALFRED parses are scored (``../shared/eval/score_alfred_goals.py``): a step
    frame gives its type, a LookAt or a lamp switched on a look, two Places of two things a stack, a Place of a
    plural thing two things, else a simple placing; the object is the theme of the Slice when sliced, else of the
    first manipulating frame; the receptacle the goal of the last Place; the movable receptacle the goal of the
    first Place of a stack. Unlike the scorer, a Bring to a place said counts as a Place (:func:`_carried_to`:
    "put a remote into a box, take the box to the chair" is a stack whose receptacle is the chair)."""
    frames = parse.frames
    names = [f.frame for f in frames]
    places = [i for i, f in enumerate(frames) if f.frame == "Place" or _carried_to(f)]
    slices = [i for i, f in enumerate(frames) if f.frame == "Slice"]

    def at(i: int, role: str) -> tuple[int, str] | None:
        return _root(parse, (i, role)) if role in frames[i].elements else None

    def phrase(where: tuple[int, str] | None) -> Phrase | None:
        return None if where is None else frames[where[0]].elements[where[1]]

    sliced = bool(slices) or any((parse.resolve(f.elements["theme"]).head or "").lower() in ("slice", "slices")
                                 for f in frames if "theme" in f.elements)
    lamp = any(f.frame == "ToggleOn" and "theme" in f.elements and "lamp" in class_key(
        parse.resolve(f.elements["theme"]).cls or "") for f in frames)
    themes = {class_key(parse.resolve(frames[i].elements["theme"]).cls or "") if "theme" in frames[i].elements
              else "" for i in places}
    kind: str | None
    if not frames:
        kind = None
    elif "Heat" in names:
        kind = "pick_heat_then_place_in_recep"
    elif "Cool" in names:
        kind = "pick_cool_then_place_in_recep"
    elif "Clean" in names:
        kind = "pick_clean_then_place_in_recep"
    elif "LookAt" in names or lamp:
        kind = LOOK
    elif len(places) >= 2 and len(themes) >= 2:
        kind = STACK
    elif places and (p := phrase(at(places[-1], "theme"))) is not None and _plural(p):
        kind = TWO
    else:
        kind = SIMPLE
    first = slices[0] if sliced and slices else next((i for i, f in enumerate(frames)
                                                      if f.frame in MANIPULATE or _carried_to(f)), None)
    where = {"object": at(first, "theme") if first is not None else None,
             "receptacle": at(places[-1], "goal") if places and kind != LOOK else None,
             "mrecep": at(places[0], "goal") if kind == STACK else None}
    values = {}
    unsaid = set()
    for name, w in where.items():
        p = phrase(w)
        values[name] = class_key(p.cls) if p is not None and p.cls else NOTHING
        if p is not None and p.default:
            unsaid.add(name)
    return Reading(kind, values, where, sliced, frozenset(unsaid))


def _lp(p: Mapping[str, float], value: str) -> float:
    return math.log(max(p.get(value, UNSEEN), 1e-12))


def candidates(model: FieldModel, name: str, grams: Sequence[str], reading: Reading, classes: Iterable[str] | None,
               present: Iterable[str] = (), type_p: Mapping[str, float] | None = None) -> dict[str, dict[str, float]]:
    """The values the field ``name`` may take and each one's features, those :func:`combine` weighs by
    :attr:`FieldModel.trust` (a value the model never saw has probability :data:`UNSEEN`):

    * ``scale:F``: the model's log-probability of the value (weight 1 unless learned otherwise);
    * ``F``: the value is the parser's reading (the parser's bonus); ``type:T``: the parser read the type T and the
      value is T (a bonus of its own per type the parser read: a step it reads is surer than a plain placing it
      reads when the sentence says no step); ``F:unsaid``: the value is the parser's and its phrase was no one's
      words (a default, an inferred goal);
    * ``read:T:U``: the parser read the type T, the value is another type U (which readings the words overrule);
      ``F:other``: a class the parser read for another field (a stack's two goals the wrong way round);
    * ``bias:type:T``: the value is the type T; ``sliced:T``: the value is T and the parser read the thing sliced;
    * ``joint:mrecep``, ``joint:receptacle`` (the type's values only): the log-probability, by the movable
      receptacle's and the receptacle's models among ``present`` and none, that the field exists as the type says
      (a stack has a movable receptacle, a look no receptacle): the fields decoded jointly, softly.

    ``classes``: the classes a class field may take (None for the type); ``type_p``: the type's
    ``model.probabilities("type", grams)``, when the caller has them already (:func:`combine`)."""
    if name == "type":
        p = model.probabilities("type", grams) if type_p is None else type_p
        said = reading.type
    else:
        keep = set(classes or ())
        p = model.probabilities(name, grams, keep)
        said = reading.values[name] if reading.values[name] in keep else None
    values = set(p) | ({said} if said is not None else set())
    other = {v for n, v in reading.values.items() if n != name and v != NOTHING}
    joint: dict[str, float] = {}
    if name == "type" and values:
        room = {*present, NOTHING}
        for field_name in ("mrecep", "receptacle"):
            q = model.probabilities(field_name, grams, room)
            joint[field_name] = min(max(q.get(NOTHING, 0.0), 1e-6), 1 - 1e-6) if q else 0.5
    out: dict[str, dict[str, float]] = {}
    for value in sorted(values):
        x = {f"scale:{name}": _lp(p, value)}
        if value == said:
            x[name] = 1.0
            if name == "type":
                x[f"type:{value}"] = 1.0
            elif name in reading.unsaid:
                x[f"{name}:unsaid"] = 1.0
        elif name == "type" and said is not None:
            x[f"read:{said}:{value}"] = 1.0
        elif name != "type" and value in other:
            x[f"{name}:other"] = 1.0
        if name == "type":
            x[f"bias:type:{value}"] = 1.0
            if reading.sliced:
                x[f"sliced:{value}"] = 1.0
            if joint:
                x["joint:mrecep"] = math.log(1 - joint["mrecep"] if value == STACK else joint["mrecep"])
                x["joint:receptacle"] = math.log(joint["receptacle"] if value == LOOK else 1 - joint["receptacle"])
        out[value] = x
    return out


def score(trust: Mapping[str, float], features: Mapping[str, float]) -> float:
    """A value's score: its features weighed by ``trust`` (``scale:*`` weighs 1 unless given)."""
    return sum(v * trust.get(k, 1.0 if k.startswith("scale:") else 0.0) for k, v in features.items())


def _best(options: Mapping[str, Mapping[str, float]], said: str | None, trust: Mapping[str, float],
          p: Mapping[str, float]) -> tuple[str, float] | None:
    """The value of the highest :func:`score`, with its probability by the model (ties: the parser's, then by
    name)."""
    if not options:
        return None
    scores = {k: score(trust, x) for k, x in options.items()}
    best = max(scores, key=lambda k: (scores[k], k == said, k))
    return best, p.get(best, 0.0)


def combine(model: FieldModel, grams: Sequence[str], reading: Reading, present: Iterable[str],
            meant: Mapping[str, frozenset[str]] | None = None) -> tuple[dict[str, str], float]:
    """The fields the sentence most likely says (type, object, receptacle, mrecep: a task type, class keys or
    :data:`NOTHING`), the model's probabilities combined with the parser's ``reading`` (see the module and
    :func:`candidates`), among the ``present`` class keys (and for a field of ``meant``, among its classes only:
    those its phrase's words can mean); and the type's probability."""
    present = set(present)
    trust = model.trust
    p = model.probabilities("type", grams)
    options = candidates(model, "type", grams, reading, None, present, p)
    kind = _best(options, reading.type, trust, p)
    out = _fields(model, grams, reading, present, meant, kind[0] if kind else (reading.type or SIMPLE))
    if kind and out["type"] == STACK and out["mrecep"] == out["object"] and len(options) > 1:
        # a stack whose container is the thing itself is no stack: the parser's type, or else the next
        rest = {k: x for k, x in options.items() if k != STACK}
        kind = (reading.type, p.get(reading.type, 0.0)) if reading.type in rest else _best(rest, reading.type, trust, p)
        if kind:
            out = _fields(model, grams, reading, present, meant, kind[0])
    chance = kind[1] if kind else 1.0
    return out, chance


def _fields(model: FieldModel, grams: Sequence[str], reading: Reading, present: set[str],
            meant: Mapping[str, frozenset[str]] | None, kind: str) -> dict[str, str]:
    """The type ``kind`` and the class fields it has, each the highest-scored of its candidates (:func:`combine`)."""
    out = {"type": kind}
    for name in ("object", "receptacle", "mrecep"):
        if not wanted(name, kind):
            out[name] = NOTHING
            continue
        classes = present & meant[name] if meant and name in meant else present
        said = reading.values[name] if reading.values[name] in classes else None
        best = _best(candidates(model, name, grams, reading, classes), said, model.trust, {})
        out[name] = best[0] if best else (said or NOTHING)
    return out

def wanted(name: str, kind: str) -> bool:
    """Whether a task of type ``kind`` has the field ``name`` (an object always; a receptacle unless a look; a
    movable receptacle only for a stack)."""
    return name == "object" or (name == "receptacle" and kind != LOOK) or (name == "mrecep" and kind == STACK)


def fit_trust(instances: Sequence[tuple[Mapping[str, Mapping[str, float]], str]], l2: float = TRUST_L2,
              digits: int = 2) -> dict[str, float]:
    """The weights of :func:`score` that maximise the likelihood of the right value among each instance's
    :func:`candidates` (a conditional logit: P(value) ∝ exp(score)), minus ``l2 / 2`` times the squared distance
    from the unlearned combination (``scale:*`` 1, the rest 0); an instance whose right value is no candidate, or
    with one candidate, teaches nothing. Fitted on parses of sentences neither the model nor the word-class table
    was fitted on (``build_task_fields.py --dev``); deterministic (L-BFGS from the start)."""
    import numpy as np
    from scipy.optimize import minimize

    usable = [(c, g) for c, g in instances if g in c and len(c) >= 2]
    names = sorted({k for c, _ in usable for x in c.values() for k in x})
    if not names:
        return {}
    index = {k: i for i, k in enumerate(names)}
    start = np.array([1.0 if k.startswith("scale:") else 0.0 for k in names])
    blocks = []
    for c, gold in usable:
        values = sorted(c)
        m = np.zeros((len(values), len(names)))
        for r, v in enumerate(values):
            for k, x in c[v].items():
                m[r, index[k]] = x
        blocks.append((m, values.index(gold)))

    def loss(w: np.ndarray) -> tuple[float, np.ndarray]:
        total = 0.5 * l2 * float((w - start) @ (w - start))
        grad = l2 * (w - start)
        for m, g in blocks:
            z = m @ w
            top = z.max()
            e = np.exp(z - top)
            q = e / e.sum()
            total += float(np.log(e.sum()) + top - z[g])
            grad = grad + m.T @ q - m[g]
        return total, grad

    result = minimize(loss, start, jac=True, method="L-BFGS-B", options={"maxiter": 500, "gtol": 1e-6})
    return {k: round(float(w), digits) for k, w in zip(names, result.x, strict=True)
            if round(float(w), digits) != (1.0 if k.startswith("scale:") else 0.0)}


PERCEPTRON_EPOCHS = 10
PERCEPTRON_RATE = 0.1
"""The passes and step of :func:`fit_trust_count`."""


def fit_trust_count(instances: Sequence[tuple[Mapping[str, Mapping[str, float]], str]],
                    start: Mapping[str, float] = TRUST, epochs: int = PERCEPTRON_EPOCHS,
                    rate: float = PERCEPTRON_RATE, digits: int = 2) -> dict[str, float]:
    """The weights of :func:`score` learned for the count of right values, not their likelihood: an averaged
    perceptron over each instance's :func:`candidates` (whenever the highest-scored value is not the right one, the
    weights move ``rate`` times the right value's features minus the chosen one's), from ``start`` (``scale:*`` 1
    unless given), ``epochs`` passes in one fixed shuffled order; the average of the weights after every instance is
    returned (the values that differ from the unlearned combination's). An instance whose right value is no
    candidate, or with one candidate, teaches nothing. Deterministic."""
    import random

    usable = [(c, g) for c, g in instances if g in c and len(c) >= 2]
    names = sorted({k for c, _ in usable for x in c.values() for k in x} | set(start))
    if not usable:
        return {}

    def unlearned(k: str) -> float:
        return 1.0 if k.startswith("scale:") else 0.0

    w = {k: float(start.get(k, unlearned(k))) for k in names}
    total = dict.fromkeys(names, 0.0)
    order = list(range(len(usable)))
    random.Random(0).shuffle(order)
    steps = 0
    for _ in range(epochs):
        for i in order:
            options, gold = usable[i]
            chosen = max(sorted(options), key=lambda v: score(w, options[v]))
            if chosen != gold:
                for k, x in options[gold].items():
                    w[k] += rate * x
                for k, x in options[chosen].items():
                    w[k] -= rate * x
            for k in names:
                total[k] += w[k]
            steps += 1
    return {k: round(total[k] / steps, digits) for k in names if round(total[k] / steps, digits) != unlearned(k)}


def reread(parse: Parse, library: Library, vocabulary: Vocabulary, model: FieldModel, text: str) -> Parse:
    """The parse with the fields :func:`combine` chooses (see the module); unchanged when the model is empty, the
    parse has no frames, or the fields are the parser's."""
    if not model or not parse.frames:
        return parse
    reading = read_fields(parse)
    present = vocabulary.by_key
    grams = sentence_grams(text)
    fields, chance = combine(model, grams, reading, present, field_classes(parse, reading, vocabulary))
    if fields["type"] == LOOK == reading.type and not any(f.frame in MANIPULATE for f in parse.frames):
        looked = _looked_at(parse, library, fields, chance)    # the thing only found or carried to the lamp
        if looked is not None:
            return looked
    if fields["type"] == reading.type and all(reading.at[n] is not None or fields[n] == NOTHING
                                              for n in ("object", "receptacle", "mrecep")):
        out = _reclassed(parse, reading, fields, present)
    elif not all(f.frame in TASK_FRAMES for f in parse.frames) or _coordinated(parse, reading):
        out = _reclassed(parse, reading, fields, present)   # never drop a frame no field holds ("find the clock"),
    else:                                                   # nor a thing said beside another
        out = _written(parse, library, vocabulary, reading, fields, present, chance)
    return _cut(out, library, vocabulary, model, grams, fields)


def _cut(parse: Parse, library: Library, vocabulary: Vocabulary, model: FieldModel, grams: Sequence[str],
         fields: Mapping[str, str]) -> Parse:
    """The parse with a Slice of the object added before the first frame that handles it, marked inferred, when the
    parse says none (nor inferred one: :func:`~seal_cli.language.slicing.uncut`), its object is the fields' and of a
    class train tasks sliced, and :func:`sliced_probability` given the fields' type and object is at least
    :attr:`FieldModel.slice_add`; else the parse unchanged. A Slice said or inferred before is never taken away."""
    if fields["object"] not in model.sliceable or "Slice" not in library or not model.priors.get(SLICED):
        return parse
    at = uncut(parse, model.sliceable)
    if at is None or class_key(parse.resolve(parse.frames[at].elements["theme"]).cls or "") != fields["object"]:
        return parse
    p = sliced_probability(model, grams, fields["type"], fields["object"])
    return slice_before(parse, at, library, vocabulary, p) if p >= model.slice_add else parse


def _coordinated(parse: Parse, reading: Reading) -> bool:
    """Whether the object was said in a coordination of things of two classes or more ("put the knife and the apple
    on the table"): frames written anew from the fields hold one object, so the other would be dropped."""
    at = reading.at["object"]
    phrase = None if at is None else parse.frames[at[0]].elements[at[1]]
    return phrase is not None and len({c.cls for c in phrase.conjuncts}) >= 2


def field_classes(parse: Parse, reading: Reading, vocabulary: Vocabulary) -> dict[str, frozenset[str]]:
    """For each field whose phrase was said, the classes its head can mean: those people meant by it often enough
    (:data:`MIN_SHARE`, :data:`FILL_SHARE`; :meth:`~seal_cli.language.grounding.Vocabulary.meanings`) and the
    parser's, if it grounded one ("the table": a dining, side or coffee table, never the sofa beside it). A phrase
    the rules ground to nothing takes a class only when people meant it by that word often (never "the glass" a
    butter knife where no cup is). A "back" nothing said places ("wash a spatula from the counter to put it back") is
    no phrase of a class: any class may be the words' guess of where the thing was."""
    out: dict[str, frozenset[str]] = {}
    for name, where in reading.at.items():
        phrase = None if where is None else parse.frames[where[0]].elements[where[1]]
        if phrase is None or phrase.default or back_unplaced(phrase):
            continue                # "put it back" where nothing said places it: its class is the words' guess
        meant = vocabulary.meanings(phrase.head)
        total = sum(meant.values())
        least = max(MIN_MEANT, MIN_SHARE * total) if phrase.cls else max(FILL_MEANT, FILL_SHARE * total)
        out[name] = frozenset(k for k, n in meant.items() if n >= least) | ({reading.values[name]} - {NOTHING})
    return out


def _reclassed(parse: Parse, reading: Reading, fields: Mapping[str, str], present: Mapping[str, str]) -> Parse:
    """The parse with the class of each field's phrase made the field's, where they differ."""
    frames = [dict(f.elements) for f in parse.frames]
    changed = False
    for name in ("object", "receptacle", "mrecep"):
        where, value = reading.at[name], fields[name]
        if where is None or value == NOTHING or value == reading.values[name] or value not in present:
            continue
        frames[where[0]][where[1]] = replace(frames[where[0]][where[1]], cls=present[value])
        changed = True
    if not changed:
        return parse
    return replace(parse, frames=tuple(replace(f, elements=e) for f, e in zip(parse.frames, frames, strict=True)))


def _thing(parse: Parse, where: tuple[int, str] | None, value: str, present: Mapping[str, str]) -> Phrase:
    """The phrase that says a field's class: the parser's (its words, the class the field's), else the class's name,
    a default (nobody said it)."""
    cls = present[value]
    if where is not None:
        said = parse.frames[where[0]].elements[where[1]]
        return replace(said, cls=cls, refers_to=None, quantity=None, plural=False, conjuncts=())
    return Phrase(None, class_words(cls)[-1] if class_words(cls) else cls, cls, default=True)


def _looked_at(parse: Parse, library: Library, fields: Mapping[str, str], chance: float) -> Parse | None:
    """A look whose thing is only found or carried ("find the racket and turn on the lamp", "carry a candle to the
    lamp and turn it on"): the parse with a LookAt of that thing in the light of the lamp switched on added last,
    marked inferred with the type's probability (its precondition, holding the thing, is the planner's). The thing is
    the first theme of a frame other than the switching whose class is the object field's; None when no frame's is,
    or no lamp is switched on."""
    if "LookAt" not in library:
        return None
    lamps = [i for i, f in enumerate(parse.frames) if f.frame == "ToggleOn" and "theme" in f.elements
             and "lamp" in class_key(parse.resolve(f.elements["theme"]).cls or "")]
    things = [i for i, f in enumerate(parse.frames) if f.frame != "ToggleOn" and "theme" in f.elements
              and class_key(parse.resolve(f.elements["theme"]).cls or "") == fields["object"]]
    if not lamps or not things:
        return None
    thing, lamp = _root(parse, (things[0], "theme")), _root(parse, (lamps[0], "theme"))

    def it(at: tuple[int, str]) -> Phrase:
        said = parse.frames[at[0]].elements[at[1]]
        return Phrase("", said.head, said.cls, refers_to=at)

    unit = library.frame("LookAt").lexical_units
    look = Evoked("LookAt", unit[0].text if unit else "look at", parse.frames[-1].span,
                  {"theme": it(thing), "instrument": it(lamp)}, inferred=round(chance, 3))
    return replace(parse, frames=(*parse.frames, look))


def _written(parse: Parse, library: Library, vocabulary: Vocabulary, reading: Reading, fields: Mapping[str, str],
             present: Mapping[str, str], chance: float) -> Parse:
    """The frames written anew from the fields: a Slice of the object when the parser read it sliced, then the
    task's frames, each marked inferred with the type's probability; the parse unchanged when the library lacks a
    frame the task needs or a field has no class."""
    kind = fields["type"]
    needed = {"Place", "Pick", *([STEP_OF[kind]] if kind in STEP_OF else []), *(["LookAt"] if kind == LOOK else [])}
    if any(n not in library for n in needed) or fields["object"] not in present \
            or (kind != LOOK and fields["receptacle"] not in present) \
            or (kind == STACK and fields["mrecep"] not in present):
        return parse
    p = round(chance, 3)
    span = parse.frames[0].span
    out: list[Evoked] = []
    obj = _thing(parse, reading.at["object"], fields["object"], present)
    slices = [f for f in parse.frames if f.frame == "Slice"]
    if reading.sliced and slices:
        out.append(replace(slices[0], elements={**{r: e for r, e in slices[0].elements.items() if r != "theme"
                                                    and e.refers_to is None}, "theme": obj}))
        obj = Phrase("", obj.head, obj.cls, refers_to=(0, "theme"))

    def frame(name: str, elements: dict[str, Phrase]) -> Evoked:
        spec = library.frame(name)
        for e in spec.elements:
            if e.default is not None and e.role not in elements:
                cls = vocabulary.ground_name(e.default) or e.default
                elements[e.role] = Phrase(None, e.default, cls, default=True)
        unit = spec.lexical_units[0].text if spec.lexical_units else name.lower()
        return Evoked(name, unit, span, elements, inferred=p)

    def same(phrase: Phrase, index: int, role: str) -> Phrase:
        return Phrase("", phrase.head, phrase.cls, refers_to=(index, role)) if phrase.refers_to is None else phrase

    if kind == TWO:
        out.append(frame("Place", {"theme": replace(obj, quantity=2),
                                   "goal": _thing(parse, reading.at["receptacle"], fields["receptacle"], present)}))
        return replace(parse, frames=tuple(out))
    at = len(out)
    out.append(frame("Pick", {"theme": obj}))
    it = same(obj, at, "theme")
    if kind == LOOK:
        out.append(frame("LookAt", {"theme": it}))
        return replace(parse, frames=tuple(out))
    if kind in STEP_OF:
        out.append(frame(STEP_OF[kind], {"theme": it}))
    if kind == STACK:
        holder = _thing(parse, reading.at["mrecep"], fields["mrecep"], present)
        out.append(frame("Place", {"theme": it, "goal": holder}))
        it = same(holder, len(out) - 1, "goal")
    out.append(frame("Place", {"theme": it, "goal": _thing(parse, reading.at["receptacle"], fields["receptacle"],
                                                          present)}))
    return replace(parse, frames=tuple(out))


def fit_fields(rows: Sequence[Mapping[str, str]], l2: float = L2, trust: Mapping[str, float] = TRUST,
               min_rooms: int = 0, spread: float | None = None) -> FieldModel:
    """The model fitted on ALFRED goal rows (``goal_sentence``, ``task_type``, ``object``, ``receptacle``,
    ``mrecep``): each field's values counted as the prior, its weights by :func:`~seal_cli.language.chooser.fit`
    (every value a candidate; a gram weighs a value it was said with in at least :data:`MIN_COUNT` sentences, and
    in at least ``min_rooms`` floor plans, the rows' ``floor_plan``: 0 ships, as 2 and 3 moved nothing on held-out
    floor plans, ``docs/language.md`` alfred28). ``spread``: each sentence weighed by how often its floor plan
    had the field's value (:func:`~seal_cli.language.chooser.room_weights`: a room that used its dining table in forty
    tasks counts as fewer; None: each sentence 1, as shipped)."""
    grams = [sentence_grams(" ".join(r["goal_sentence"].split())) for r in rows]
    priors: dict[str, dict[str, int]] = {}
    weights: dict[str, dict[str, dict[str, float]]] = {}
    for name in FIELDS:
        labels = [label(r, name) for r in rows]
        counts = Counter(labels)
        values = tuple(sorted(counts))
        offsets = tuple(math.log(counts[v]) for v in values)
        instances = [Instance(values, offsets, values.index(v), g) for v, g in zip(labels, grams, strict=True)]
        priors[name] = dict(sorted(counts.items()))
        rooms = [r.get("floor_plan", "") for r in rows]
        weights[name] = fit(instances, l2=l2, min_count=MIN_COUNT, digits=2, min_label=MIN_COUNT,
                            groups=rooms, min_groups=min_rooms,
                            weights=None if spread is None else room_weights(list(zip(rooms, labels, strict=True)),
                                                                             spread))
    sliceable = _sliceable(rows)
    cut = [(r, g) for r, g in zip(rows, grams, strict=True) if class_key(r.get("object") or "") in sliceable]
    said = [SLICE_VALUES[0] if _is_sliced(r) else SLICE_VALUES[1] for r, _ in cut]
    counts = Counter(said)
    if all(counts[v] for v in SLICE_VALUES):
        offsets = tuple(math.log(counts[v]) for v in SLICE_VALUES)
        priors[SLICED] = {v: counts[v] for v in SLICE_VALUES}
        weights[SLICED] = fit([Instance(SLICE_VALUES, offsets, SLICE_VALUES.index(v),
                                        slice_grams(g, r["task_type"], class_key(r["object"])))
                               for v, (r, g) in zip(said, cut, strict=True)],
                              l2=l2, min_count=MIN_COUNT, digits=2, min_label=MIN_COUNT)
    return FieldModel(priors, weights, trust, sliceable if SLICED in priors else frozenset())


def _is_sliced(row: Mapping[str, str]) -> bool:
    return row.get("sliced") in ("1", "True", "true")


def _sliceable(rows: Sequence[Mapping[str, str]]) -> frozenset[str]:
    """The class keys of the objects the rows' tasks sliced."""
    return frozenset(class_key(r["object"]) for r in rows if _is_sliced(r) and r.get("object"))


def label(row: Mapping[str, str], name: str) -> str:
    if name == "type":
        return row["task_type"]
    if name == "receptacle" and row["task_type"] == LOOK:
        return NOTHING
    return class_key(row[name]) if row.get(name) else NOTHING


def model_json(model: FieldModel, source: str) -> str:
    """The model as the shipped file's text (one line per field's section, sorted)."""
    data = {"format": "seal-task-fields-1", "source": source, "trust": dict(model.trust),
            "priors": {n: dict(model.priors[n]) for n in (*FIELDS, SLICED) if n in model.priors},
            "weights": {n: model.weights[n] for n in (*FIELDS, SLICED) if n in model.weights},
            **({"sliceable": sorted(model.sliceable)} if model.sliceable else {})}
    return json.dumps(data, sort_keys=True, separators=(",", ":")) + "\n"


def load_field_model(path: Path) -> FieldModel:
    """The model in this file (a :func:`model_json` text). Raises SealError naming the file when it is not one."""
    from seal_cli.errors import SealError, Where
    from seal_cli.fileio import json_value, read_text

    try:
        data = json_value(read_text(path), path)
    except json.JSONDecodeError as err:
        raise SealError(f"not JSON: {err.msg}", Where(str(path), err.lineno, err.colno)) from None
    if not isinstance(data, dict) or data.get("format") != "seal-task-fields-1" or not all(
            isinstance(data.get(k), dict) and all(isinstance(data[k].get(n), dict) for n in FIELDS)
            for k in ("priors", "weights")):
        raise SealError("not a task-field model (format seal-task-fields-1: priors and weights of type, object, "
                        "receptacle, mrecep)", Where(str(path)))
    sliceable = data.get("sliceable", [])
    if not all(isinstance(data[k].get(SLICED, {}), dict) for k in ("priors", "weights")) \
            or not isinstance(sliceable, list) or not all(isinstance(k, str) for k in sliceable):
        raise SealError(f"{SLICED}: expected its priors and weights as objects, and sliceable as a list of class keys",
                        Where(str(path)))
    said = data.get("trust")
    trust: Mapping[str, float] = said if isinstance(said, dict) else TRUST
    if not all(isinstance(v, int | float) and not isinstance(v, bool) for v in trust.values()):
        raise SealError("trust: expected a number for each weight (" + ", ".join(FIELDS) + ", ...)",
                        Where(str(path)))
    return FieldModel(data["priors"], data["weights"],
                      {**{n: float(TRUST.get(n, 0.0)) for n in FIELDS}, **{k: float(v) for k, v in trust.items()}},
                      frozenset(sliceable))


@cache
def shipped_field_model() -> FieldModel:
    """The model shipped with seal (:data:`SHIPPED`), read once; empty when absent."""
    return load_field_model(SHIPPED) if SHIPPED.is_file() else FieldModel()
