"""Relation beliefs B(R | x_t): how much each element and each precondition frame matters *now*.

SEAL's measurement and context potentials are sums over relations weighted by a belief that
comes from the robot's state (paper, Method; SPEC, "SeFM: what the numbers mean"):

- an element the robot **holds**, or whose preconditions are all **met** (and that the frame
  does not have to go to), is **Disjoint** — weight 0: it no longer says where the frame is;
- the element(s) of the **next unmet step** are **Core** — weight 1. The steps of a grounded
  frame are its unmet preconditions, in order, then its actions, in order; the next step is
  the first that names an element that is not Disjoint ("Stir(cup, spoon)" with an empty hand:
  ``holding(spoon)`` → the spoon is Core; holding the spoon: ``navigate(cup)`` → the cup);
- every other element is **Other** — weight :data:`OTHER` (0.3 by default).

The context of a frame is the same over the frames that achieve its unmet preconditions: the
achiever of the first unmet precondition that has one is Core, achievers of later ones are
Other, and achievers of preconditions already met are Disjoint (left out).

A potential whose relations are all Disjoint is a factor of 1, never a zero; that rule lives
with the potentials (:mod:`seal_cli.sefm.frame_beliefs`). Elements that are not places in space (a
message to say, a question to answer) take no part: they are never located.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass

from seal_cli.frames.model import Action, Binding, Fact
from seal_cli.frames.taxonomy import class_key
from seal_cli.planning.state import State

__all__ = ["CORE", "DISJOINT", "LOCATING_ACTIONS", "OTHER", "Relations", "achievers", "context_relations",
           "element_relations", "held", "relations", "said_where", "spatial_roles"]

CORE = 1.0
OTHER = 0.3
DISJOINT = 0.0

LOCATING_ACTIONS = frozenset({"navigate", "approach", "search"})
"""Primitive actions that take the robot to their argument: an element they name is never Disjoint
because a precondition of it is met (only because the robot holds it)."""

NON_SPATIAL = {"say": {0}, "answer": {0}}
"""Argument positions of primitives that are words, not things in space."""


@dataclass(frozen=True)
class Relations:
    """The relation beliefs of one grounded frame: per element role, and per achieving frame."""

    elements: tuple[tuple[str, str, float], ...]
    """``(role, value, belief)`` for each spatial element, in the frame's order."""
    context: tuple[tuple[int, float], ...]
    """``(index of the achieving binding, belief)`` for each frame achieving an unmet precondition."""

    @property
    def all_disjoint(self) -> bool:
        return not any(b > 0 for _, _, b in self.elements)

    def element(self, role: str) -> float:
        for r, _, belief in self.elements:
            if r == role:
                return belief
        raise KeyError(role)


def spatial_roles(binding: Binding) -> tuple[str, ...]:
    """The filled elements that are things in space: named by a precondition, or by an action
    argument that is not a word (``say(message)``), or by nothing at all (then assumed spatial)."""
    values = binding.elements
    spoken: set[str] = set()
    used: set[str] = set()
    for action in binding.frame.actions:
        for position, arg in enumerate(action.args):
            (spoken if position in NON_SPATIAL.get(action.name, ()) else used).add(arg)
    for fact in binding.frame.preconditions:
        used.update(fact.args)
    return tuple(r for r in binding.frame.roles if r in values and (r in used or r not in spoken))


def held(state: State) -> frozenset[str]:
    """The class keys of what the robot holds: its ``holding(x)`` facts."""
    return frozenset(class_key(f.args[0]) for f in state.facts if f.predicate == "holding" and len(f.args) == 1)


def _disjoint(binding: Binding, role: str, state: State) -> bool:
    value = binding.elements[role]
    if class_key(value) in held(state):
        return True
    mine = [f for f in binding.frame.preconditions if role in f.args]
    if not mine or any(a.name in LOCATING_ACTIONS and role in a.args for a in binding.frame.actions):
        return False
    return all(state.holds(f.bind(binding.elements)) for f in mine if all(a in binding.elements for a in f.args))


def _steps(binding: Binding, state: State) -> list[Fact | Action]:
    """The frame's remaining steps in the role names of the frame: unmet preconditions, then actions."""
    values = binding.elements
    unmet = [f for f in binding.frame.preconditions
             if all(a in values for a in f.args) and not state.holds(f.bind(values))]
    actions = [a for a in binding.frame.actions if all(x in values for x in a.args)]
    return [*unmet, *actions]


def element_relations(binding: Binding, state: State, other: float = OTHER) -> dict[str, float]:
    """B(R_k | x_t) for each spatial element role of the grounded frame."""
    roles = spatial_roles(binding)
    disjoint = {r for r in roles if _disjoint(binding, r, state)}
    live = [r for r in roles if r not in disjoint]
    core: set[str] = set()
    for step in _steps(binding, state):
        named = [a for a in step.args if a in live]
        if named:
            core = set(named)
            break
    return {r: DISJOINT if r in disjoint else CORE if r in core else other for r in roles}


def _key(fact: Fact) -> tuple[str, tuple[str, ...]]:
    return fact.predicate, tuple(class_key(a) for a in fact.args)


def achievers(bindings: Sequence[Binding]) -> dict[tuple[str, tuple[str, ...]], list[int]]:
    """Which bindings (indices) make each fact true: their positive postconditions, by class key."""
    out: dict[tuple[str, tuple[str, ...]], list[int]] = {}
    for j, binding in enumerate(bindings):
        for fact in binding.postconditions:
            if not fact.negated and j not in out.setdefault(_key(fact), []):
                out[_key(fact)].append(j)
    return out


def context_relations(index: int, bindings: Sequence[Binding], state: State, other: float = OTHER,
                      made_by: dict[tuple[str, tuple[str, ...]], list[int]] | None = None) -> dict[int, float]:
    """B(R_ij | x_t) for the frames j (indices into ``bindings``) that achieve frame i's unmet preconditions.

    Among several achievers of one fact, the nearest one planned before frame i is taken (else
    the nearest after it): the plan's own order says which step provides the fact. ``made_by``
    is :func:`achievers` of the bindings, if already known.
    """
    made_by = achievers(bindings) if made_by is None else made_by
    beliefs: dict[int, float] = {}
    first = True
    for fact in state.unmet(bindings[index]):
        candidates = [j for j in made_by.get(_key(fact), []) if j != index]
        if not candidates:
            continue
        before = [j for j in candidates if j < index]
        j = max(before) if before else min(candidates)
        beliefs[j] = max(beliefs.get(j, 0.0), CORE if first else other)
        first = False
    return beliefs


def relations(bindings: Sequence[Binding], state: State, other: float = OTHER) -> list[Relations]:
    """The relation beliefs of every grounded frame of a plan in one state."""
    out = []
    made_by = achievers(bindings)
    for i, binding in enumerate(bindings):
        elements = element_relations(binding, state, other)
        values = binding.elements
        out.append(Relations(tuple((r, values[r], b) for r, b in elements.items()),
                             tuple(sorted(context_relations(i, bindings, state, other, made_by).items()))))
    return out


def said_where(bindings: Sequence[Binding]) -> dict[str, tuple[str, ...]]:
    """Where the command says each thing is, by class key: a frame that takes a thing out of somewhere
    (a postcondition ``not in(theme, source)``, Pick's) presumes ``in(theme, source)`` as it was said
    ("the milk from the larder": milk → larder_1). Evidence for the thing's belief, not a fact: the
    speaker may be wrong. A place an earlier frame of the plan puts the thing in is where it *will* be, not
    where it is ("take the peas to the kitchen and put them in the fridge": the second Pick's source, the
    kitchen, is the Bring's goal)."""
    out: dict[str, list[str]] = {}
    put: set[tuple[str, str]] = set()
    for binding in bindings:
        for fact in binding.postconditions:
            if fact.predicate != "in" or len(fact.args) != 2 or fact.args[0] == fact.args[1]:
                continue
            thing, where = (class_key(a) for a in fact.args)
            if not fact.negated:
                put.add((thing, where))
            elif (thing, where) not in put and where not in out.setdefault(thing, []):
                out[thing].append(where)
    return {k: tuple(v) for k, v in out.items() if v}
