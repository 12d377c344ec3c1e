"""The task a sentence describes, learned on a train split, and the frame a task adds when the parse lacks it.

ALFRED's people wrote one sentence for each task they watched, of seven kinds (look at a thing in a lamp's
light, put a thing somewhere, two things, a thing in a container, a thing heated, cooled or cleaned first).
What kind of task a sentence describes is carried by its words and by what the parse made of them, not
only by its frames: "take a clock from a desk with a *lit* lamp", "turn *off* the floor lamp while holding a
credit card", "hold a watch up under the lamp light" all describe looking at the thing under a lamp, yet no
LookAt is said and no lamp is switched on. A :class:`TaskModel` holds a conditional logistic regression (the
chooser's, :mod:`seal_cli.language.chooser`) over the task kinds:

    P(task | sentence) ∝ prior(task) · exp(Σ_f weight[f][task])

with the features of :func:`task_features` (the sentence's words, the frames the parse says, the class of
the thing it handles and of where it puts it, how many Places it says). It is fitted by
``scripts/build_word_classes.py`` on ALFRED's train goals (each sentence parsed with nothing inferred, the
label its task's type) and shipped in the word-class table (``task_prior``, ``task_weights``).

**What a task adds** is a table, :data:`ADDERS` (task → the function that adds its frame), used when the kind's
probability is at least :data:`THRESHOLD`, the frame marked ``Evoked.inferred`` with it. A look task: a parse that
handles one grounded thing and says no look, no lamp switched on and no step (:func:`unlooked`) gets a LookAt of
that thing after its last frame, its instrument the light the sentence names, else the room's lamp
(:func:`add_look`). A heating, cooling or cleaning task: a parse that places one thing and says no step gets the
step before its Place (:func:`~seal_cli.language.steps.add_step`, as the step model adds one). A stack with a
movable receptacle: a parse that puts one thing in a container ("place a slice of tomato in a pan") and says
nowhere the container goes gets the container put where such a container most likely went
(:func:`add_carried`: :attr:`TaskModel.carried`, P(receptacle | sentence, container), fitted on train's stacks).
The other kinds were measured and have no adder (``docs/language.md``, "This round (alfred15)"): a container or
a second thing the sentence does not name cannot be added, and a step the parse already says is never dropped.

**Scoped and marked** as the unsaid step is (:mod:`seal_cli.language.steps`): only where every class of the
vocabulary is one the statistics know (``Vocabulary.task_model``); ``parse_command(..., infer_steps=False)``
turns it off.
"""

from __future__ import annotations

from collections.abc import Callable, Iterable, Mapping
from dataclasses import dataclass, field, replace
from functools import partial
from types import MappingProxyType
from typing import TYPE_CHECKING

from seal_cli.frames.taxonomy import class_key, class_words
from seal_cli.language.chooser import posterior, sentence_features
from seal_cli.language.goals import GoalModel
from seal_cli.language.steps import add_step
from seal_cli.language.values import Evoked, Parse, Phrase

if TYPE_CHECKING:
    from seal_cli.frames.library import Library
    from seal_cli.language.grounding import Vocabulary

__all__ = ["ADDERS", "CONTAINER", "LOOK", "STACK", "TASKS", "THRESHOLD", "TaskModel", "add_carried", "add_look",
           "carried_features", "infer_task", "task_features", "uncarried", "unlooked"]

LOOK = "look_at_obj_in_light"
STACK = "pick_and_place_with_movable_recep"
TASKS = ("look_at_obj_in_light", "pick_and_place_simple", "pick_and_place_with_movable_recep",
         "pick_clean_then_place_in_recep", "pick_cool_then_place_in_recep", "pick_heat_then_place_in_recep",
         "pick_two_obj_and_place")
"""ALFRED's task kinds, the model's classes."""
THRESHOLD = 0.7
"""The least probability at which a task's frame is added (chosen on held-out train, ``scripts/build_word_classes.py
--dev 0.2 --task-threshold ...``)."""
HANDLING = ("Pick", "Place", "Bring", "Give")
"""Frames whose theme is a thing the sentence handles."""
BLOCKING = frozenset(("LookAt", "Heat", "Cool", "Clean", "Slice"))
"""Frames whose presence means the sentence said what is done to the thing (or that it looks)."""
LIGHT = "light"
"""The taxonomy's category of the things a LookAt's light is (its ``instrument``)."""
LAMP = "lamp"
"""The class name a look's light is grounded by when the sentence names no light (the LookAt frame's "in the
light of a lamp"), as a frame's default is (:meth:`~seal_cli.language.grounding.Vocabulary.ground_name`): in a
room, its lamp."""
CONTAINER = "container"
"""The taxonomy's category of the things carried with another in them (a pan, a bowl, a mug; not a fridge)."""


def task_features(words: Iterable[str], parse: Parse) -> tuple[str, ...]:
    """The features of a parsed sentence: ``w:`` each of its words
    (:func:`~seal_cli.language.wordusage.context_words`), ``f:`` each frame it says (none inferred), ``o:`` the class
    key of the first thing it handles, ``r:`` of the goal of its last Place, ``or:`` the two together (what is put
    where), ``p:`` how many Places it says (0, 1, 2 or more)."""
    out = {f"w:{w}" for w in words}
    said = [f for f in parse.frames if f.inferred is None]
    out.update(f"f:{f.frame}" for f in said)
    things = [parse.resolve(f.elements["theme"]).cls for f in said if "theme" in f.elements]
    thing = next((c for c in things if c), None)
    if thing:
        out.add(f"o:{class_key(thing)}")
    places = [f for f in said if f.frame == "Place"]
    goal = parse.resolve(places[-1].elements["goal"]).cls if places and "goal" in places[-1].elements else None
    if goal:
        out.add(f"r:{class_key(goal)}")
    if thing and goal:
        out.add(f"or:{class_key(thing)}|{class_key(goal)}")
    out.add(f"p:{min(len(places), 2)}")
    return tuple(sorted(out))


@dataclass(frozen=True)
class TaskModel:
    """``prior[task]``: how often each task kind was a train sentence's; ``weights[feature][task]``: the fitted
    weights; ``threshold``: the least probability at which a task's frame is added; ``carried``: where a stack's
    container goes. Empty: none is added."""

    prior: Mapping[str, int] = field(default_factory=dict)
    weights: Mapping[str, Mapping[str, float]] = field(default_factory=dict)
    threshold: float = THRESHOLD
    carried: GoalModel = field(default_factory=GoalModel)
    """Where a stack's container went when the sentence says nowhere (P(receptacle | :func:`carried_features`),
    fitted on train's stacks; ``stack_goal_prior``, ``stack_goal_weights`` in the table). Empty: a stack adds
    nothing."""

    def __post_init__(self) -> None:
        object.__setattr__(self, "prior", MappingProxyType(dict(self.prior)))
        object.__setattr__(self, "weights", MappingProxyType({f: MappingProxyType(dict(by))
                                                              for f, by in self.weights.items()}))

    def __bool__(self) -> bool:
        return any(self.prior.get(t) for t in ADDERS)

    def probabilities(self, features: Iterable[str]) -> dict[str, float]:
        """P(task | features) for each task kind the prior knows."""
        keys = [k for k in TASKS if self.prior.get(k)]
        return posterior(self.prior, self.weights, keys, features)


def _light(library: Library, phrase: Phrase | None) -> bool:
    return phrase is not None and phrase.cls is not None and library.taxonomy.is_a(phrase.cls, LIGHT) is True


def unlooked(parse: Parse, library: Library) -> Phrase | None:
    """The thing a parse handles when a look could be what it leaves unsaid: it handles one grounded thing (the
    themes of Pick, Place, Bring, Give; no coordination), and says no look, no step, no cutting and no light
    switched on; else None."""
    frames = parse.frames
    if any(f.frame in BLOCKING for f in frames):
        return None
    if any(f.frame == "ToggleOn" and _light(library, parse.resolve(f.elements.get("theme") or Phrase(None, "")))
           for f in frames):
        return None
    handled = [f.elements["theme"] for f in frames if f.frame in HANDLING and "theme" in f.elements]
    classes = {parse.resolve(p).cls for p in handled}
    if len(classes) != 1 or None in classes or any(parse.resolve(p).conjuncts for p in handled):
        return None
    return handled[0]


def add_look(parse: Parse, library: Library, vocabulary: Vocabulary, probability: float) -> Parse:
    """The parse with a LookAt of the thing it handles after its last frame (:func:`unlooked`), its instrument the
    first light the sentence names (a lamp switched off, "a *lit lamp*"), else the vocabulary's lamp (:data:`LAMP`,
    a default: nobody said it), marked inferred; else unchanged."""
    thing = unlooked(parse, library)
    if thing is None or "LookAt" not in library:
        return parse
    elements = {"theme": thing}
    lights = [p for f in parse.frames for p in f.elements.values() if _light(library, parse.resolve(p))]
    lamp = vocabulary.ground_name(LAMP)
    if lights:
        elements["instrument"] = lights[0]
    elif lamp is not None:
        elements["instrument"] = Phrase(None, LAMP, lamp, default=True)
    unit = library.frame("LookAt").lexical_units[0].text
    look = Evoked("LookAt", unit, parse.frames[-1].span, elements, inferred=round(probability, 3))
    return replace(parse, frames=(*parse.frames, look))


def _stepped(step: str, parse: Parse, library: Library, vocabulary: Vocabulary, probability: float) -> Parse:
    """The parse with ``step`` added before the Place of the one thing it places, when it says no step
    (:func:`~seal_cli.language.steps.add_step`)."""
    return add_step(parse, library, vocabulary, step, probability)


def carried_features(words: Iterable[str], parse: Parse, container: str | None) -> tuple[str, ...]:
    """The features of a stack whose container's place is unsaid: the sentence's words, ``o:`` the container's
    class, ``f:`` the frames said (:func:`~seal_cli.language.chooser.sentence_features`)."""
    return sentence_features(words, container, (f.frame for f in parse.frames if f.inferred is None))


def uncarried(parse: Parse, library: Library) -> int | None:
    """The index of the Place that puts one thing in a container (:data:`CONTAINER`: a pan, a bowl; grounded)
    when it is the parse's only Place and the thing is another class and no coordination ("place a slice of
    tomato in a pan"): a stack that says nowhere the container goes; else None."""
    places = [i for i, f in enumerate(parse.frames) if f.frame == "Place"]
    if len(places) != 1 or any(f.frame in ("Bring", "Give") for f in parse.frames):
        return None
    place = parse.frames[places[0]]
    if "theme" not in place.elements or "goal" not in place.elements:
        return None
    theme, goal = parse.resolve(place.elements["theme"]), parse.resolve(place.elements["goal"])
    if theme.cls is None or goal.cls is None or theme.conjuncts or goal.conjuncts or goal.kind != "thing" \
            or class_key(theme.cls) == class_key(goal.cls) or library.taxonomy.is_a(goal.cls, CONTAINER) is not True:
        return None
    return places[0]


def add_carried(parse: Parse, library: Library, vocabulary: Vocabulary, probability: float) -> Parse:
    """The parse with its container put where it most likely went (:func:`uncarried`), after its last frame: the
    most probable receptacle the vocabulary holds by :attr:`TaskModel.carried` (a default: nobody said it), marked
    inferred with the task's probability; else unchanged, and unchanged on a house's vocabulary
    (:attr:`~seal_cli.language.grounding.Vocabulary.house`), where nobody asked for that placing."""
    if vocabulary.house:
        return parse
    at = uncarried(parse, library)
    model = vocabulary.task_model.carried
    if at is None or not model:
        return parse
    goal = parse.frames[at].elements["goal"]
    target = goal.refers_to or (at, "goal")
    root = parse.frames[target[0]].elements[target[1]]
    present = vocabulary.by_key
    p = model.probabilities(carried_features(vocabulary.context, parse, root.cls), present)
    p.pop(class_key(root.cls or ""), None)
    if not p:
        return parse
    cls = present[max(p, key=lambda k: p[k])]
    container = Phrase("", root.head, root.cls, root.kind, target, root.quantity, root.plural)
    where = Phrase(None, " ".join(class_words(cls)) or cls, cls, default=True)
    unit = library.frame("Place").lexical_units[0].text
    put = Evoked("Place", unit, parse.frames[-1].span, {"theme": container, "goal": where},
                 inferred=round(probability, 3))
    return replace(parse, frames=(*parse.frames, put))


STEP_OF = MappingProxyType({"pick_heat_then_place_in_recep": "Heat", "pick_cool_then_place_in_recep": "Cool",
                            "pick_clean_then_place_in_recep": "Clean"})
"""The step frame of each task kind that has one."""
ADDERS: Mapping[str, Callable[[Parse, Library, Vocabulary, float], Parse]] = MappingProxyType(
    {LOOK: add_look, STACK: add_carried, **{kind: partial(_stepped, step) for kind, step in STEP_OF.items()}})
"""Task kind → what adds its frame to a parse that lacks it (the kinds with none add nothing)."""


def infer_task(parse: Parse, library: Library, vocabulary: Vocabulary, model: TaskModel,
               words: Iterable[str]) -> Parse:
    """The parse with its most probable task's frame added when the model is sure enough and the task has an adder
    (:data:`ADDERS`); else the parse unchanged."""
    if not model or not parse.frames:
        return parse
    p = model.probabilities(task_features(words, parse))
    best = max(p, key=lambda k: p[k])
    adder = ADDERS.get(best)
    if adder is None or p[best] < model.threshold:
        return parse
    return adder(parse, library, vocabulary, p[best])
