"""The unsaid stack: which of two things placed together a sentence most likely means to carry the
other in, learned on a train split.

"Move a knife and a glass to the sink" says two things go to the sink; most of ALFRED's people who
wrote it were describing a task that put the knife in the glass and took the glass to the sink (a
stack with a movable receptacle). Whether a coordination is a stack, and which conjunct holds the
other, depends on what the conjuncts are: a glass, a pan or a box is a thing other things are
carried in, a knife is none. A :class:`StackModel` holds, for each class, how often it was a conjunct
of such a coordination (``said``) and how often the task then carried the other conjunct in it
(``holds``), counted by ``scripts/build_word_classes.py`` on ALFRED's train goals and shipped in the
word-class table (``stacks``). Of the two conjuncts the one with the higher rate ``holds / said``
(at least ``min_support`` observations) is the container, and the stack is read when that rate is at
least :data:`THRESHOLD`.

**Scoped and marked**, as the unsaid step is (:mod:`seal_cli.language.steps`): only where every class
of the vocabulary is one the statistics were counted over (ALFRED's, or one ALFRED scene's), only for
a parse with one Place whose theme is a coordination of two things of different grounded classes put
in a grounded goal, and with no step, look or switching said; the Place added (the thing put in its
container) is marked ``Evoked.inferred`` with the rate. ``parse_command(..., infer_steps=False)``
turns it off with the step.
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass, field, replace
from types import MappingProxyType

from seal_cli.frames.taxonomy import class_key
from seal_cli.language.steps import BLOCKING, shifted
from seal_cli.language.values import Evoked, Parse, Phrase

__all__ = ["MIN_SUPPORT", "THRESHOLD", "StackModel", "coordinated", "infer_stack"]

THRESHOLD = 0.5
"""The least rate ``holds / said`` of the container at which the stack is read (chosen on train
trials held out from the counts, ``scripts/build_word_classes.py --dev 0.2 --stack-threshold ...``)."""
MIN_SUPPORT = 5
"""Coordinations of a class below which its rate is not trusted (the class never holds)."""


@dataclass(frozen=True)
class StackModel:
    """``said[class key]``: train coordinations of two things (:func:`coordinated`) the class was one
    of; ``holds[class key]``: of those, how many were a task that carried the other in it. Empty: no
    stack is ever read."""

    said: Mapping[str, int] = field(default_factory=dict)
    holds: Mapping[str, int] = field(default_factory=dict)
    threshold: float = THRESHOLD
    min_support: int = MIN_SUPPORT

    def __post_init__(self) -> None:
        object.__setattr__(self, "said", MappingProxyType({class_key(c): n for c, n in self.said.items()}))
        object.__setattr__(self, "holds", MappingProxyType({class_key(c): n for c, n in self.holds.items()}))

    def __bool__(self) -> bool:
        return any(self.holds.values())

    def rate(self, cls: str) -> float:
        """How often a coordination with this class was a stack with it as the container (0: too
        few observations)."""
        key = class_key(cls)
        said = self.said.get(key, 0)
        return self.holds.get(key, 0) / said if said >= self.min_support else 0.0

    def container(self, a: str, b: str) -> tuple[int, float] | None:
        """Which of two classes (0 or 1) holds the other, and its rate; None when neither is sure enough."""
        rates = (self.rate(a), self.rate(b))
        best = 1 if rates[1] > rates[0] else 0
        return (best, rates[best]) if rates[best] >= self.threshold else None


def coordinated(parse: Parse) -> tuple[int, Phrase, Phrase] | None:
    """(the index of the Place, its two conjuncts) when the parse places a coordination of two things
    of different grounded classes in a grounded goal, with one Place and no step, look or switch; else
    None."""
    frames = parse.frames
    if any(f.frame in BLOCKING for f in frames):
        return None
    places = [i for i, f in enumerate(frames) if f.frame == "Place"]
    if len(places) != 1:
        return None
    theme, goal = (frames[places[0]].elements.get(r) for r in ("theme", "goal"))
    if theme is None or goal is None or parse.resolve(goal).cls is None:
        return None
    said = parse.resolve(theme)
    if len(said.conjuncts) != 2:
        return None
    a, b = said.conjuncts
    if a.cls is None or b.cls is None or class_key(a.cls) == class_key(b.cls):
        return None
    return places[0], a, b


def infer_stack(parse: Parse, model: StackModel) -> Parse:
    """The parse with its coordination read as a stack when the model is sure enough: the thing put in
    the container first (a Place marked inferred), then the container put where the sentence said;
    else the parse unchanged."""
    found = coordinated(parse) if model else None
    if found is None:
        return parse
    at, *pair = found
    chosen = model.container(pair[0].cls or "", pair[1].cls or "")
    if chosen is None:
        return parse
    which, rate = chosen
    container, thing = pair[which], pair[1 - which]
    frames = [shifted(f, at) for f in parse.frames]
    place = frames[at]
    inner = Evoked("Place", place.lexical_unit, place.span, {"theme": thing, "goal": container},
                   inferred=round(rate, 3))
    outer = replace(place, elements={**place.elements, "theme": container})
    return replace(parse, frames=(*frames[:at], inner, outer, *frames[at + 1:]))
