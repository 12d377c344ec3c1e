"""The unsaid goal: where a sentence that handles a thing and says nowhere to put it most likely means
it to end up, learned on a train split.

"Wash the kettle on the stove", "Heat a mug and put it back", "Chill the coffee cup": each says what
is done to the thing and stops there (or says "back", "away"), yet every ALFRED task it was written
for ends with the thing put somewhere, and the words often say where: the place the thing was said to
be at ("the kettle *on the stove*", "the bread *from the counter*"), what the thing is for ("a mug
*for coffee*"), or the thing itself (a mug goes back under the coffee machine). A :class:`GoalModel`
holds a conditional logistic regression (the chooser's, :mod:`seal_cli.language.chooser`) over the
receptacle classes and ``none`` (a look task: the thing is held, not put):

    P(goal | sentence) ∝ prior(goal) · exp(Σ_f weight[f][goal])

with the features of :func:`goal_features` (the sentence's words, the thing's class, the frames said).
It is fitted by ``scripts/build_word_classes.py`` on ALFRED's train goals and shipped in the
word-class table (``goal_prior``, ``goal_weights``).

**Scoped and marked**, as the unsaid step is (:mod:`seal_cli.language.steps`): only where every class
of the vocabulary is one the statistics were counted over (ALFRED's, or one ALFRED scene's); only for a
parse that handles one grounded thing (Pick, a step, Slice, or a Place with no goal) and puts nothing
anywhere (no Place with a goal, no Bring or Give, no look or switching); only among the classes the
vocabulary has, when the most probable is at least :data:`THRESHOLD`. The Place added (the thing put
in the goal, after the last frame) is marked ``Evoked.inferred`` with the probability, its goal a
``default`` element (nobody said it). ``parse_command(..., infer_steps=False)`` turns it off with the step.

**A goal said only beside a thing that holds nothing is unsaid too.** "Put the cabbage *by the knife*", "place the
bread *next to the spoon*", "set the mug *in front of the laptop*": a preposition that puts a thing beside another
(:data:`~seal_cli.language.english.BESIDE`) says where on something it goes, not what it goes on, and a knife holds
nothing; the thing ends on whatever holds the knife, which the sentence leaves unsaid (when it says it, "next to the
knife *on the counter*", the parser's ``beside_on`` reads the counter). Which classes hold things is learned, not
listed: the classes train tasks put a thing in or on (:attr:`GoalModel.holders`, the table's ``receptacles``).
When the last Place's goal is said so and its class is none of them, or it names no class of the vocabulary ("in
front of *the TV*" in a room whose classes hold none: it is no more known to hold things) (:func:`said_beside`), the
goal is chosen as
for a sentence that says none (the same model and features) and replaces the landmark, a ``default`` element: the
most probable of the classes present, with no threshold, since the landmark itself is sure to be wrong (nothing can
be put in a knife). Not in a house's vocabulary
(:attr:`~seal_cli.language.grounding.Vocabulary.house`): a home's robot can find the knife and what holds it.
"""

from __future__ import annotations

from collections.abc import Iterable, Mapping
from dataclasses import dataclass, field, replace
from types import MappingProxyType
from typing import TYPE_CHECKING

from seal_cli.frames.taxonomy import class_key, class_words
from seal_cli.language.chooser import posterior, sentence_features
from seal_cli.language.english import BESIDE
from seal_cli.language.reference import back_unplaced
from seal_cli.language.values import Evoked, Parse, Phrase

if TYPE_CHECKING:
    from seal_cli.frames.library import Library

__all__ = ["HANDLING", "NOWHERE", "THRESHOLD", "GoalModel", "goal_features", "goalless", "infer_goal", "said_beside"]

NOWHERE = "none"
"""The model's class for "put nowhere" (the thing is only held: ALFRED's look tasks)."""
THRESHOLD = 0.5
"""The least probability at which the goal is added (chosen on held-out train,
``scripts/build_word_classes.py --dev 0.2 --goal-threshold ...``)."""
HANDLING = ("Pick", "Heat", "Cool", "Clean", "Slice", "Place")
"""Frames whose theme is a thing the sentence handles (the last of them names the thing put)."""
PUTTING = frozenset(("Bring", "Give", "LookAt", "ToggleOn", "ToggleOff"))
"""Frames that say where the thing goes, or that the sentence is about looking (then nothing is added)."""


goal_features = sentence_features
"""The sentence's features (:func:`~seal_cli.language.chooser.sentence_features`)."""


@dataclass(frozen=True)
class GoalModel:
    """``prior[goal]``: how often an eligible train sentence's task put the thing in each class (class
    key, or ``none``); ``weights[feature][goal]``: the fitted weights; ``threshold``: the least
    probability at which a goal is added. Empty: no goal is ever inferred."""

    prior: Mapping[str, int] = field(default_factory=dict)
    weights: Mapping[str, Mapping[str, float]] = field(default_factory=dict)
    threshold: float = THRESHOLD
    holders: frozenset[str] = frozenset()
    """Class keys of the things train tasks put a thing in or on (their receptacles and movable receptacles): a
    goal said beside a class of none of them is a goal unsaid (:func:`said_beside`). Empty: none is."""

    def __post_init__(self) -> None:
        object.__setattr__(self, "prior", MappingProxyType({(k if k == NOWHERE else class_key(k)): n
                                                            for k, n in self.prior.items()}))
        object.__setattr__(self, "holders", frozenset(class_key(k) for k in self.holders))
        object.__setattr__(self, "weights", MappingProxyType({f: MappingProxyType(dict(by))
                                                              for f, by in self.weights.items()}))

    def __bool__(self) -> bool:
        return any(k != NOWHERE and n for k, n in self.prior.items())

    def probabilities(self, features: Iterable[str], present: Iterable[str]) -> dict[str, float]:
        """P(goal | features) over ``none`` and the goals among ``present`` (class keys)."""
        here = set(present)
        keys = [k for k in self.prior if self.prior[k] and (k == NOWHERE or k in here)]
        return posterior(self.prior, self.weights, keys, features)


def goalless(parse: Parse) -> int | None:
    """The index of the last frame that handles the thing when the parse handles one grounded thing and
    puts it nowhere: no Place with a goal, no Bring or Give, no look or switching ("wash the kettle on the
    stove", "heat a mug and put it back": a "back" no source places is nowhere said); else None."""
    frames = parse.frames
    if not frames or any(f.frame in PUTTING for f in frames):
        return None
    if any(f.frame == "Place" and "goal" in f.elements and not back_unplaced(f.elements["goal"]) for f in frames):
        return None
    handling = [i for i, f in enumerate(frames) if f.frame in HANDLING and "theme" in f.elements]
    if not handling:
        return None
    themes = {parse.resolve(frames[i].elements["theme"]).cls for i in handling}
    if len(themes) != 1 or None in themes:
        return None
    return handling[-1]


def said_beside(parse: Parse, holders: frozenset[str]) -> int | None:
    """The index of the parse's last Place when its goal was said beside a thing (a preposition of
    :data:`~seal_cli.language.english.BESIDE`: "by the knife", "in front of the laptop") whose class is none of
    ``holders`` (class keys of what holds things), or that names no class of the vocabulary at all ("in front of
    *the TV*" in a room whose classes hold no television: nothing known holds it either), said as a phrase of its
    own (no pronoun, coordination or default); else None."""
    places = [i for i, f in enumerate(parse.frames) if f.frame == "Place" and f.inferred is None]
    if not places or not holders:
        return None
    goal = parse.frames[places[-1]].elements.get("goal")
    if goal is None or goal.preposition not in BESIDE or goal.default or goal.refers_to is not None \
            or goal.conjuncts or goal.kind != "thing" or goal.cls is not None and class_key(goal.cls) in holders \
            or "theme" not in parse.frames[places[-1]].elements:
        return None
    return places[-1]


def infer_goal(parse: Parse, library: Library, present: Mapping[str, str], model: GoalModel,
               words: Iterable[str], house: bool = False) -> Parse:
    """The parse with the Place it most likely leaves unsaid after its last frame, marked inferred, when
    the model is sure enough among the ``present`` classes (class key → the vocabulary's spelling; see the
    module's scope); or, when its last Place's goal is said only beside a thing that holds nothing
    (:func:`said_beside`; never in a ``house``), that goal replaced by the most probable one; else the parse
    unchanged."""
    at = goalless(parse) if model else None
    if at is None and model and not house:
        return _beside(parse, present, model, words)
    if at is None or "Place" not in library:
        return parse
    theme = parse.frames[at].elements["theme"]
    said = [f.frame for f in parse.frames if f.inferred is None]
    p = model.probabilities(goal_features(words, parse.resolve(theme).cls, said), present)
    best = max(p, key=lambda k: (p[k], k == NOWHERE))
    if best == NOWHERE or p[best] < model.threshold:
        return parse
    cls = present[best]
    goal = Phrase(None, " ".join(class_words(cls)) or cls, cls, default=True)
    unit = library.frame("Place").lexical_units[0].text
    last = parse.frames[-1]
    place = Evoked("Place", unit, last.span, {"theme": theme, "goal": goal}, inferred=round(p[best], 3))
    return replace(parse, frames=(*parse.frames, place))


def _beside(parse: Parse, present: Mapping[str, str], model: GoalModel, words: Iterable[str]) -> Parse:
    """The parse with the goal of its last Place, said only beside a thing that holds nothing (:func:`said_beside`),
    replaced by the most probable goal among the ``present`` classes (a ``default``: nobody said it); else
    unchanged."""
    at = said_beside(parse, model.holders)
    if at is None:
        return parse
    place = parse.frames[at]
    landmark = class_key(place.elements["goal"].cls or "")
    said = [f.frame for f in parse.frames if f.inferred is None]
    p = model.probabilities(goal_features(words, parse.resolve(place.elements["theme"]).cls, said), present)
    p.pop(landmark, None)
    p.pop(NOWHERE, None)                # the sentence puts the thing somewhere
    if not p:
        return parse
    best = max(p, key=lambda k: p[k])
    cls = present[best]
    goal = Phrase(None, " ".join(class_words(cls)) or cls, cls, default=True)
    frames = list(parse.frames)
    frames[at] = replace(place, elements={**place.elements, "goal": goal})
    return replace(parse, frames=tuple(frames))
