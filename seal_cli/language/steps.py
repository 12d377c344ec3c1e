"""The unsaid step: which step (heat, cool, clean, or none) a sentence that places a thing most likely
means when it says none, learned on a train split.

"Put an apple in the fridge" says no step, yet most of ALFRED's people who wrote it were describing a
task that cooled the apple first: the words a person chooses ("chilled" aside) still carry it, in the
sentence's other words and in what is put where. A :class:`StepModel` holds a conditional logistic
regression (the chooser's, :mod:`seal_cli.language.chooser`) over the steps ``Heat``, ``Cool``,
``Clean`` and ``none``:

    P(step | sentence) ∝ prior(step) · exp(Σ_f weight[f][step])

with the features of :func:`step_features` (the sentence's words, the placed thing's class, the goal's
class). It is fitted by ``scripts/build_word_classes.py`` on ALFRED's train goals and shipped in the
word-class table (``step_prior``, ``step_weights``).

**Scoped and marked.** What it learns is in part how ALFRED's tasks were generated, not how people
talk, so the step is added (:func:`infer_step`) only

* where the vocabulary is the one the statistics were learned on: every class of the vocabulary is a
  class the table knows (ALFRED's, or one ALFRED scene's); a GPSR arena or a shipped map, whose
  classes ALFRED never had, is never given a step;
* when the parse places one thing (one theme, not two, not a stack) in a grounded goal and says no
  step, no look and no switching on;
* when the step's probability is at least :data:`THRESHOLD` (chosen on train trials held out from the
  fit for near-zero breakage);

and the frame added is marked: ``Evoked.inferred`` is its probability (``"inferred": true,
"probability": 0.84`` in the JSON). ``parse_command(..., infer_steps=False)`` or a vocabulary with
other statistics (``Vocabulary.with_usage(WordUsage())``) turns it off.
"""

from __future__ import annotations

from collections.abc import Iterable, Mapping
from dataclasses import dataclass, field, replace
from types import MappingProxyType
from typing import TYPE_CHECKING

from seal_cli.frames.taxonomy import class_key
from seal_cli.language.chooser import posterior
from seal_cli.language.english import NP_OPENERS, NUMBERS
from seal_cli.language.values import Evoked, Parse, Phrase

if TYPE_CHECKING:
    from seal_cli.frames.library import Library
    from seal_cli.language.grounding import Vocabulary

__all__ = ["BLOCKING", "LEFT_SUPPORT", "LEFT_THRESHOLD", "NONE", "STEPS", "THRESHOLD", "StepModel", "add_step",
           "done_by_step", "eligible", "ends_at_steps", "filling", "in_place_of_filling", "infer_left_in", "infer_step",
           "moved_phrase", "shifted", "step_at", "step_features"]

STEPS = ("Clean", "Cool", "Heat")
"""The steps a sentence may leave unsaid (frames of the library), in the model's order."""
NONE = "none"
"""The model's class for "no step"."""
THRESHOLD = 0.6
"""The least probability at which the step is added, chosen on held-out train (``scripts/build_word_classes.py
--dev 0.2 --step-threshold 0.8 0.7 0.6 0.5``, steps and stacks together): of the parses given a frame
inferred, 52 of 54 were then of the task's type at 0.8, 63 of 68 at 0.7, 75 of 84 at 0.6, 86 of 104 at
0.5; the steps 0.7 adds beyond 0.8 are right 11 times in 14, those below it 12 in 16, then 11 in 20.
Measured again at alfred10 (with the later models: slice, goal, filling), everything inferred: 149 of 176
right at 0.7, 161 of 193 at 0.6, 169 of 208 at 0.5; held-out sentences all five fields right +10 / −2 from
0.7 to 0.6, so 0.6 (what 0.5 adds beyond it is right 8 times in 15, a coin toss)."""
LEFT_THRESHOLD = 0.5
"""The least rate at which a sentence that ends at two steps is given the Place it leaves unsaid."""
LEFT_SUPPORT = 5
"""Train sentences below which that rate is not trusted."""
BLOCKING = frozenset((*STEPS, "LookAt", "ToggleOn", "ToggleOff"))
"""Frames whose presence means the sentence said what it does to the thing (or is about looking)."""


def step_features(words: Iterable[str], thing: str | None, goal: str | None) -> tuple[str, ...]:
    """The features of a sentence: ``w:`` each of its words (:func:`~seal_cli.language.wordusage.context_words`),
    ``o:`` the class key of the thing placed, ``r:`` of its goal, and ``or:`` the two together (what is put where:
    a mug into a cabinet is a task of its own, not the sum of a mug and a cabinet)."""
    out = [f"w:{w}" for w in sorted(set(words))]
    if thing:
        out.append(f"o:{class_key(thing)}")
    if goal:
        out.append(f"r:{class_key(goal)}")
    if thing and goal:
        out.append(f"or:{class_key(thing)}|{class_key(goal)}")
    return tuple(out)


@dataclass(frozen=True)
class StepModel:
    """``prior[step]``: how often each step (or ``none``) was meant by an eligible train sentence;
    ``weights[feature][step]``: the fitted weights; ``threshold``: the least probability at which a
    step is added. Empty: no step is ever inferred."""

    prior: Mapping[str, int] = field(default_factory=dict)
    weights: Mapping[str, Mapping[str, float]] = field(default_factory=dict)
    threshold: float = THRESHOLD
    ended: Mapping[str, int] = field(default_factory=dict)
    """``ended[step]``: train parses that said two different steps, this one last, and put the thing
    nowhere (:func:`ends_at_steps`)."""
    left: Mapping[str, int] = field(default_factory=dict)
    """``left[step]``: of those, how many were a task that left the thing in the step's instrument."""

    def __post_init__(self) -> None:
        for name in ("prior", "ended", "left"):
            object.__setattr__(self, name, MappingProxyType(dict(getattr(self, name))))
        object.__setattr__(self, "weights", MappingProxyType({f: MappingProxyType(dict(by))
                                                              for f, by in self.weights.items()}))

    def __bool__(self) -> bool:
        return bool(self.prior) and any(self.prior.get(s) for s in STEPS)

    def probabilities(self, features: Iterable[str]) -> dict[str, float]:
        """P(step | features) for each step and ``none`` the prior knows."""
        keys = [k for k in (*STEPS, NONE) if self.prior.get(k)]
        return posterior(self.prior, self.weights, keys, features)

    def left_rate(self, step: str) -> float:
        """How often a sentence that ended at two steps, ``step`` last, meant the thing left in that
        step's instrument (0: fewer than :data:`LEFT_SUPPORT` such sentences)."""
        ended = self.ended.get(step, 0)
        return self.left.get(step, 0) / ended if ended >= LEFT_SUPPORT else 0.0


def filling(frame: Evoked) -> bool:
    """Whether a Place puts a substance into a thing said before it: "fill *the bowl* with *water*", "a bowl
    *with water in it*", "a bowl *filled with water*". Its theme is a mass noun (singular, said with no
    determiner, possessive or number: "water", "cold water"; "fill the bowl with *apples*" or "*an apple*"
    puts things) and its goal's words come first. The thing it fills is its goal; no second thing is put."""
    if frame.frame != "Place":
        return False
    theme, goal = frame.elements.get("theme"), frame.elements.get("goal")
    if theme is None or goal is None or theme.refers_to is not None or theme.span is None or goal.span is None \
            or theme.plural or theme.quantity is not None or theme.conjuncts or not theme.text:
        return False
    first = theme.text.lower().split()[0]
    return goal.span[0] < theme.span[0] and first not in NP_OPENERS and \
        first not in NUMBERS


def eligible(parse: Parse) -> int | None:
    """The index of the Place an unsaid step would come before, or None: the parse places one thing
    (its Places' themes are one class, not plural, not two) in a goal with a class, and evokes no
    step, look or switch. A Place that fills the thing with a substance (:func:`filling`) puts no
    second thing."""
    frames = parse.frames
    if any(f.frame in BLOCKING for f in frames):
        return None
    places = [i for i, f in enumerate(frames) if f.frame == "Place" and not filling(f)]
    if not places:
        return None
    themes = {_cls(parse, frames[i].elements.get("theme")) for i in places}
    last = frames[places[-1]]
    theme = last.elements.get("theme")
    goal = last.elements.get("goal")
    if len(themes) != 1 or None in themes or goal is None or parse.resolve(goal).cls is None:
        return None
    said = parse.resolve(theme) if theme is not None else None
    if said is None or said.plural or said.quantity not in (None, 1) or \
            {"two", "both"} & set((said.text or "").lower().split()):
        return None
    return places[-1]


def step_at(parse: Parse, at: int) -> int:
    """Where the unsaid step goes for the Place at ``at``: before it, or before the first Place that fills
    the thing it places with a substance ("*fill a bowl with water* and put it in the fridge": washed, then
    filled, then put)."""
    thing = _cls(parse, parse.frames[at].elements.get("theme"))
    for i, f in enumerate(parse.frames[:at]):
        if filling(f) and _cls(parse, f.elements.get("goal")) == thing:
            return i
    return at


def ends_at_steps(parse: Parse) -> int | None:
    """The index of the last step when the parse says two different steps ("heat and chill an apple")
    and puts the thing nowhere (no Place, Bring or Give), its last step having an instrument with a
    class; else None."""
    frames = parse.frames
    if any(f.frame in ("Place", "Bring", "Give") for f in frames):
        return None
    steps = [i for i, f in enumerate(frames) if f.frame in STEPS]
    if len({frames[i].frame for i in steps}) < 2:
        return None
    last = frames[steps[-1]]
    tool, theme = last.elements.get("instrument"), last.elements.get("theme")
    if tool is None or theme is None or _cls(parse, tool) is None:
        return None
    return steps[-1]


def infer_left_in(parse: Parse, library: Library, model: StepModel) -> Parse:
    """The parse with the Place it most likely leaves unsaid when it ends at two steps: the thing left
    in the last step's instrument ("heat and chill an apple": in the fridge), marked inferred with the
    rate learned on train (:meth:`StepModel.left_rate`) when that is at least :data:`LEFT_THRESHOLD`;
    else the parse unchanged."""
    at = ends_at_steps(parse) if model else None
    if at is None or "Place" not in library:
        return parse
    step = parse.frames[at]
    rate = model.left_rate(step.frame)
    if rate < LEFT_THRESHOLD:
        return parse
    unit = library.frame("Place").lexical_units[0].text
    elements = {"theme": step.elements["theme"], "goal": step.elements["instrument"]}
    return replace(parse, frames=(*parse.frames, Evoked("Place", unit, step.span, elements,
                                                        inferred=round(rate, 3))))


def _cls(parse: Parse, phrase: Phrase | None) -> str | None:
    return None if phrase is None else parse.resolve(phrase).cls


def infer_step(parse: Parse, library: Library, vocabulary: Vocabulary, model: StepModel,
               words: Iterable[str]) -> Parse:
    """The parse with the step it most likely leaves unsaid added before its Place, marked inferred,
    when the model is sure enough (see the module's scope); else the parse unchanged."""
    at = eligible(parse)
    if at is None or not model:
        return parse
    place = parse.frames[at]
    theme = place.elements["theme"]
    thing = parse.resolve(theme).cls
    goal = parse.resolve(place.elements["goal"]).cls
    p = model.probabilities(step_features(words, thing, goal))
    best = max(p, key=lambda k: p[k])
    if best == NONE or p[best] < model.threshold:
        return parse
    return add_step(parse, library, vocabulary, best, p[best])


def add_step(parse: Parse, library: Library, vocabulary: Vocabulary, step: str, probability: float) -> Parse:
    """The parse with the frame ``step`` (Heat, Cool, Clean) of the thing it places added before its Place
    (:func:`eligible`, :func:`step_at`), marked inferred with ``probability``; unchanged when the parse is not
    eligible or the library lacks the frame."""
    at = eligible(parse)
    if at is None or step not in library:
        return parse
    place = parse.frames[at]
    theme = place.elements["theme"]
    best = step
    frame = library.frame(best)
    role = next((e.role for e in frame.elements if e.role == "theme"), None)
    if role is None:
        return parse
    elements: dict[str, Phrase] = {role: moved_phrase(theme, at)}
    for e in frame.elements:
        if e.default is not None and e.role not in elements:
            cls = vocabulary.ground_name(e.default) or e.default
            elements[e.role] = Phrase(None, e.default, cls, default=True)
    unit = frame.lexical_units[0].text if frame.lexical_units else best.lower()
    before = step_at(parse, at)
    if before != at and done_by_step(parse, before):
        elements[role] = parse.frames[before].elements["goal"]
        added = Evoked(best, unit, parse.frames[before].span, elements, inferred=round(probability, 3))
        return in_place_of_filling(parse, before, added, role)
    if before != at:
        elements[role] = moved_phrase(parse.frames[before].elements["goal"], before)
    added = Evoked(best, unit, parse.frames[before].span, elements, inferred=round(probability, 3))
    frames = [shifted(f, before) for f in parse.frames]
    return replace(parse, frames=(*frames[:before], added, *frames[before:]))


def done_by_step(parse: Parse, at: int) -> bool:
    """Whether the filling at ``at`` (:func:`filling`) is what the unsaid step added before it does, so that it
    is read as that step and not kept as a Place of its own: its substance is no thing of the vocabulary ("fill
    a bowl with *water*" in a kitchen whose classes hold no water: the bowl is filled at the sink as it is rinsed
    there, and no thing "water" can be fetched and put in it) or the thing it fills itself (the substance
    grounded to its container's class). Nothing refers to the substance (a later "it" is the thing filled)."""
    frame = parse.frames[at]
    theme, goal = frame.elements["theme"], frame.elements["goal"]
    if theme.cls is not None and theme.cls != parse.resolve(goal).cls:
        return False
    return not any(ref == (at, r) for f in parse.frames for p in f.elements.values() for ref in _refs(p)
                   for r in frame.elements if r != "goal")


def in_place_of_filling(parse: Parse, at: int, step: Evoked, role: str) -> Parse:
    """The parse with the filling at ``at`` replaced by ``step``, whose ``role`` is the thing filled: what
    referred to the filling's goal ("fill a bowl with water and put *it* in the fridge") refers to the step's
    thing."""
    frames = [step if i == at else _retargeted(f, (at, "goal"), (at, role)) for i, f in enumerate(parse.frames)]
    return replace(parse, frames=tuple(frames))


def _refs(phrase: Phrase) -> list[tuple[int, str]]:
    refs = [] if phrase.refers_to is None else [phrase.refers_to]
    return refs + [r for c in phrase.conjuncts for r in _refs(c)]


def _retargeted(frame: Evoked, old: tuple[int, str], new: tuple[int, str]) -> Evoked:
    def moved(phrase: Phrase) -> Phrase:
        conjuncts = tuple(moved(c) for c in phrase.conjuncts)
        ref = new if phrase.refers_to == old else phrase.refers_to
        if ref == phrase.refers_to and all(a is b for a, b in zip(conjuncts, phrase.conjuncts, strict=True)):
            return phrase
        return replace(phrase, refers_to=ref, conjuncts=conjuncts)

    elements = {r: moved(p) for r, p in frame.elements.items()}
    return frame if all(elements[r] is frame.elements[r] for r in elements) else replace(frame, elements=elements)


def shifted(frame: Evoked, at: int) -> Evoked:
    """The frame with its references to frames from index ``at`` on moved one later."""
    moved = {role: moved_phrase(p, at) for role, p in frame.elements.items()}
    return frame if all(moved[r] is frame.elements[r] for r in moved) else replace(frame, elements=moved)


def moved_phrase(phrase: Phrase, at: int) -> Phrase:
    """The phrase with its references (and its conjuncts') to frames from index ``at`` on moved one later."""
    conjuncts = tuple(moved_phrase(c, at) for c in phrase.conjuncts)
    ref = phrase.refers_to
    if ref is not None and ref[0] >= at:
        ref = (ref[0] + 1, ref[1])
    if ref == phrase.refers_to and all(a is b for a, b in zip(conjuncts, phrase.conjuncts, strict=True)):
        return phrase
    return replace(phrase, refers_to=ref, conjuncts=conjuncts)
