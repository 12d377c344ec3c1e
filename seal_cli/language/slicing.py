"""The unsaid slice: whether a sentence that names a food it does not say to cut most likely means
a slice of it, learned on a train split.

"Put a knife and a cooked apple in the fridge" or "put the chilled slice potato in the sink" says no
cutting, yet most of ALFRED's people who wrote such a sentence were describing a task that sliced the
food first: a knife moved with it, "slice" said as a modifier, a pan "containing" it. A
:class:`SliceModel` holds a conditional logistic regression (the chooser's,
:mod:`seal_cli.language.chooser`) over ``sliced`` and ``whole``:

    P(sliced | sentence) ∝ prior(sliced) · exp(Σ_f weight[f][sliced])

with the features of :func:`slice_features` (the sentence's words, the thing's class, the frames the
parse evokes). It is fitted by ``scripts/build_word_classes.py`` on ALFRED's train goals (each sentence
parsed with the table, nothing inferred; the label is the task's ``sliced``) and shipped in the
word-class table (``slice_prior``, ``slice_weights``, ``slice_classes``).

**Scoped and marked**, as the unsaid step is (:mod:`seal_cli.language.steps`): only where every class
of the vocabulary is one the statistics were counted over; only for a parse that says no cutting (no
Slice, no theme whose head is "slice") whose thing (the theme of its first frame that handles one) is
of a class train tasks sliced (``slice_classes``: Apple, Bread, ...); only when the probability is at
least :data:`THRESHOLD`. The Slice added before that frame is marked ``Evoked.inferred`` with it.
``parse_command(..., infer_steps=False)`` turns it off with the step.
"""

from __future__ import annotations

import math
from collections.abc import Iterable, Mapping
from dataclasses import dataclass, field, replace
from types import MappingProxyType
from typing import TYPE_CHECKING

from seal_cli.frames.taxonomy import class_key
from seal_cli.language.chooser import logits, sentence_features
from seal_cli.language.english import NP_OPENERS, PRONOUNS, QUANTIFIERS
from seal_cli.language.steps import moved_phrase, shifted
from seal_cli.language.values import Evoked, Parse, Phrase

if TYPE_CHECKING:
    from seal_cli.frames.library import Library
    from seal_cli.language.grounding import Vocabulary

__all__ = ["HANDLING", "KINDS", "SLICED", "THRESHOLD", "WHOLE", "SliceModel", "infer_slice", "said_bare",
           "slice_before", "slice_features", "uncut"]

SLICED = "sliced"
WHOLE = "whole"
KINDS = (SLICED, WHOLE)
"""The model's two classes."""
THRESHOLD = 0.7
"""The least probability at which the slice is added (chosen on held-out train,
``scripts/build_word_classes.py --dev 0.2 --slice-threshold ...``)."""
HANDLING = ("Pick", "Heat", "Cool", "Clean", "LookAt", "Place")
"""Frames whose theme is the thing a task handles (the first of them names it)."""


def slice_features(words: Iterable[str], thing: str | None, frames: Iterable[str],
                   bare: bool = False) -> tuple[str, ...]:
    """The sentence's features (:func:`~seal_cli.language.chooser.sentence_features`), and ``d:bare`` when the
    thing is said as a bare singular (:func:`said_bare`): "put cooked potato in the fridge" reads the food as a
    mass, some of it, where "put a cooked potato" counts one."""
    out = sentence_features(words, thing, frames)
    return (*out, "d:bare") if bare else out


def said_bare(phrase: Phrase) -> bool:
    """Whether a phrase is a singular said with no determiner, possessive or number before it ("cooked potato",
    "cold apple"; not "a cold apple", "two apples", "apples", "it")."""
    words = (phrase.text or "").lower().split()
    return bool(words) and not phrase.plural and phrase.quantity is None and not phrase.conjuncts \
        and words[0] not in NP_OPENERS and words[0] not in QUANTIFIERS and words[0] not in PRONOUNS


@dataclass(frozen=True)
class SliceModel:
    """``prior[kind]``: how often an eligible train sentence meant the thing sliced or whole;
    ``weights[feature][kind]``: the fitted weights; ``classes``: the class keys train tasks sliced.
    Empty: no slice is ever inferred."""

    prior: Mapping[str, int] = field(default_factory=dict)
    weights: Mapping[str, Mapping[str, float]] = field(default_factory=dict)
    classes: frozenset[str] = frozenset()
    threshold: float = THRESHOLD

    def __post_init__(self) -> None:
        object.__setattr__(self, "prior", MappingProxyType(dict(self.prior)))
        object.__setattr__(self, "weights", MappingProxyType({f: MappingProxyType(dict(by))
                                                              for f, by in self.weights.items()}))
        object.__setattr__(self, "classes", frozenset(class_key(c) for c in self.classes))

    def __bool__(self) -> bool:
        return bool(self.prior.get(SLICED)) and bool(self.prior.get(WHOLE)) and bool(self.classes)

    def probability(self, features: Iterable[str]) -> float:
        """P(sliced | features)."""
        z = logits(self.weights, KINDS, features)
        a = math.log(self.prior[SLICED]) + z[SLICED]
        b = math.log(self.prior[WHOLE]) + z[WHOLE]
        return 1.0 / (1.0 + math.exp(min(b - a, 700.0)))


def uncut(parse: Parse, classes: Iterable[str]) -> int | None:
    """The index of the first frame that handles the thing when the parse says no cutting (no Slice, no
    theme whose head is "slice") and the thing is of one of ``classes`` (class keys); else None."""
    frames = parse.frames
    if any(f.frame == "Slice" for f in frames):
        return None
    if any((parse.resolve(p).head or "").lower() in ("slice", "slices")
           for f in frames for r, p in f.elements.items() if r == "theme"):
        return None
    at = next((i for i, f in enumerate(frames) if f.frame in HANDLING), None)
    theme = frames[at].elements.get("theme") if at is not None else None
    if theme is None:
        return None
    cls = parse.resolve(theme).cls
    return at if cls is not None and class_key(cls) in set(classes) else None


def infer_slice(parse: Parse, library: Library, vocabulary: Vocabulary, model: SliceModel,
                words: Iterable[str]) -> Parse:
    """The parse with the Slice it most likely leaves unsaid before its first frame that handles the
    thing, marked inferred, when the model is sure enough (see the module's scope); else unchanged."""
    at = uncut(parse, model.classes) if model else None
    if at is None or "Slice" not in library:
        return parse
    theme = parse.frames[at].elements["theme"]
    thing = parse.resolve(theme)
    p = model.probability(slice_features(words, thing.cls, (f.frame for f in parse.frames), said_bare(thing)))
    if p < model.threshold:
        return parse
    return slice_before(parse, at, library, vocabulary, p)


def slice_before(parse: Parse, at: int, library: Library, vocabulary: Vocabulary, p: float) -> Parse:
    """The parse with a Slice of the theme of its frame ``at`` added before that frame, marked inferred with
    ``p`` (the library's Slice, its defaults grounded in ``vocabulary``; the later frames' references moved)."""
    theme = parse.frames[at].elements["theme"]
    frame = library.frame("Slice")
    elements: dict[str, Phrase] = {"theme": moved_phrase(theme, at)}
    for e in frame.elements:
        if e.default is not None and e.role not in elements:
            elements[e.role] = Phrase(None, e.default, vocabulary.ground_name(e.default) or e.default, default=True)
    unit = frame.lexical_units[0].text if frame.lexical_units else "slice"
    cut = Evoked("Slice", unit, parse.frames[at].span, elements, inferred=round(p, 3))
    frames = [shifted(f, at) for f in parse.frames]
    return replace(parse, frames=(*frames[:at], cut, *frames[at:]))
