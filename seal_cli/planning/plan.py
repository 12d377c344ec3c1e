"""Planning: the ordered, grounded frames that carry out a command from the robot's state.

A plan runs the **commanded** frames b₁ … bₙ in the commanded order, each once its
preconditions hold. Before bₖ the planner **inserts** frames whose postconditions make bₖ's
unmet preconditions true and, when such a frame cannot run yet, frames for its preconditions in
turn: "stir the cup" is Pick(spoon), Stir(cup). What a frame needs and does is
:class:`~seal_cli.planning.state.State` (``unmet`` and ``apply``), the semantics SeFM and the simulator use.

**Search.** A* over nodes (facts, k), k being the number of commanded frames already run. From a
node, bₖ₊₁ runs if it is applicable (and then nothing else is tried: a commanded frame runs as soon
as it can); otherwise one of the *achievers* of its unmet preconditions is inserted. A commanded
frame that is :func:`already_so` at its turn (once the one before it has run) is passed over, wherever
it stands, and noted. Every frame costs 1, and h = 1 + (commanded frames after bₖ₊₁ not already so)
+ [bₖ₊₁ is not applicable] never overestimates (but where earlier frames' results make a later
one pointless: counted once too many, alike on every path through them), so the plan found has the
fewest frames. Paths are compared, after their cost, as sequences of successor
ranks, so among the shortest plans the search returns the first in the order successors are
generated: achievers of a frame come right before it, in the order of its preconditions, and the
same inputs always give the same plan. The search gives up after ``max_nodes`` expansions.

**Achievers** of an unmet fact p that a frame N needs, in a state s (inserted frames are grounded
from the fact they achieve):

1. a frame with a postcondition of p's predicate, sign and arity, whose roles take p's arguments
   (holding(spoon) → Pick(theme=spoon));
2. a role still open that one of the frame's deletions names takes what s says, since a frame
   undoes what is there: Pick's source is where the theme is (``not in(theme, source)`` against
   ``in(apple, fridge_1)``), Place's theme is what the hand holds (``not holding(theme)``);
3. a role still open takes the value of N's element of the same name, if it fits the type
   (Bring(cup, source=kitchen) needs holding(cup) → Pick(cup, source=kitchen)); and a role rule 2
   filled takes it too when the state knows (its ``rooms``, from a map) that rule 2's place does
   not lie in N's: with in(cup, coffee_table_1) in the family room, Bring(cup, source=kitchen)
   still gives Pick(cup, source=kitchen) — the robot looks for a cup there — while with
   in(apple, fridge_1) and fridge_1 in the kitchen it gives the precise Pick(apple, source=fridge_1);
4. then the frame's defaults (the thing of that class the state knows, else the class);
5. any other role stays unfilled, and the facts and actions naming it drop out
   (the knife is put down with Place(theme=knife) and no goal).

A grounding whose values do not fit their element types, or that would not make p true, is not an
achiever. Achievers are tried with fewer unfilled roles first, then in library order.

**Explanation.** An inserted step is explained by the first later step whose precondition it made
true and which still held when that step ran: ``because="holding(spoon) for Stir"``.

**Goal.** What the command leaves behind: each commanded frame's postconditions that hold at the
end of the plan; a deletion counts when the frame removed a fact that was true and was not one of
its own preconditions (closing an open fridge; not the "holding" that Place consumes).
"""

from __future__ import annotations

import heapq
from collections.abc import Iterator, Mapping, Sequence
from dataclasses import dataclass, field
from typing import TYPE_CHECKING, Any

from seal_cli.errors import SealError
from seal_cli.frames.library import Library
from seal_cli.frames.model import Binding, Fact, Frame
from seal_cli.frames.taxonomy import Taxonomy
from seal_cli.planning.state import State

if TYPE_CHECKING:
    from seal_cli.planning.conditions import Condition

__all__ = ["MAX_CHAIN", "MAX_NODES", "Plan", "Step", "already_so", "explain", "open_already", "plan"]

MAX_NODES = 20_000
"""Default bound on the nodes the search expands before it gives up."""

MAX_CHAIN = 100
"""The most frames a chain of needs may hold (a frame needing a fact only a frame needing another fact gives, and so
on): the standard library's longest is a handful; a library whose chain is 3,000 long ran Python out of stack
("nested too deeply", naming nothing) and one 792 long took 44 s to plan (each node walks the chain again)."""


@dataclass(frozen=True)
class Step:
    """One frame of a plan: commanded, or inserted ``because`` it achieves another's precondition."""

    binding: Binding
    commanded: bool
    because: str | None = None

    @property
    def frame(self) -> str:
        return self.binding.frame.name

    @property
    def elements(self) -> dict[str, str]:
        """The filled elements, in the frame's role order."""
        values = self.binding.elements
        return {role: values[role] for role in self.binding.frame.roles if role in values}

    def to_json(self) -> dict[str, Any]:
        data: dict[str, Any] = {"frame": self.frame, "elements": self.elements}
        if self.because is not None:
            data["because"] = self.because
        return data

    def __str__(self) -> str:
        return str(self.binding)


@dataclass(frozen=True)
class Plan:
    """The steps that carry out a command, the state they start from and the facts they leave."""

    steps: tuple[Step, ...]
    initial: State
    goal: tuple[Fact, ...]
    text: str | None = None
    expanded: int = field(default=0, compare=False)
    """Search nodes expanded to find the plan."""
    warnings: tuple[str, ...] = field(default=(), compare=False)
    """What the map does not know of the command (``Problem.warnings``)."""
    check: Condition | None = field(default=None, compare=False)
    """The command's condition when the robot checks it first ("if Tom is in the garage": a look, then the steps
    only if it holds; :mod:`seal_cli.planning.conditions`), with the steps that check it."""

    @property
    def bindings(self) -> tuple[Binding, ...]:
        return tuple(step.binding for step in self.steps)

    def states(self) -> tuple[State, ...]:
        """The state before each step, then the state after the last."""
        states = [self.initial]
        for step in self.steps:
            states.append(states[-1].apply(step.binding))
        return tuple(states)

    @property
    def final(self) -> State:
        return self.states()[-1]

    def to_json(self) -> dict[str, Any]:
        """The document ``seal plan --json`` prints (SPEC, "``seal plan --json``")."""
        data: dict[str, Any] = {"text": self.text, "plan": [step.to_json() for step in self.steps],
                                "state": [str(f) for f in self.initial], "goal": [str(f) for f in self.goal]}
        if self.warnings:
            data["warnings"] = list(self.warnings)
        if self.check is not None:
            data["check"] = self.check.to_json()
        return data

    def __len__(self) -> int:
        return len(self.steps)


# -- achievers -------------------------------------------------------------------------------------

def _key(binding: Binding) -> tuple[str, tuple[tuple[str, str], ...]]:
    """What tells grounded frames apart, cheaper to hash than the binding (which hashes its frame)."""
    return binding.frame.name, binding.values


def _unify(roles: Sequence[str], args: Sequence[str], values: Mapping[str, str]) -> dict[str, str] | None:
    """``values`` extended so that each role names its argument; None if a role would take two."""
    bound = dict(values)
    for role, arg in zip(roles, args, strict=True):
        if bound.setdefault(role, arg) != arg:
            return None
    return bound


def _from_deletions(frame: Frame, values: dict[str, str], state: State) -> list[dict[str, str]]:
    """``values`` completed from the stored facts that the frame's deletions would remove."""
    partials = [values]
    for deletion in (p for p in frame.postconditions if p.negated and p.args):
        extended: list[dict[str, str]] = []
        for partial in partials:
            if all(a in partial for a in deletion.args):
                extended.append(partial)
                continue
            matches = [m for f in sorted(state.facts, key=str)
                       if f.predicate == deletion.predicate and len(f.args) == len(deletion.args)
                       and (m := _unify(deletion.args, f.args, partial)) is not None]
            extended.extend(matches or [partial])
        partials = extended
    return partials


OPENABLE = "openable"
"""The category of things that open and close; a map may say so of one place, whatever its class."""


def fits(value: str, category: str, state: State, taxonomy: Taxonomy) -> bool:
    """Whether a thing may fill an element of this type: it is not known *not* to belong (a thing
    the state says opens and closes is openable)."""
    if category == OPENABLE and state.closable is not None and value in state.closable:
        return True
    return taxonomy.is_a(state.class_of(value), category) is not False


def resolve(cls: str, state: State) -> str:
    """The thing the state knows by this name, else the first it knows of this class
    (``fridge`` → ``fridge_1``), else the class itself."""
    if cls in state.classes:
        return cls
    return next((name for name, c in state.classes.items() if c == cls), cls)


class Achievers:
    """The grounded frames that would make a fact true (see the module's docstring)."""

    def __init__(self, library: Library) -> None:
        self.taxonomy = library.taxonomy
        self.index: dict[tuple[str, bool, int], list[tuple[int, Frame, int]]] = {}
        for order, frame in enumerate(library.frames):
            for n, post in enumerate(frame.postconditions):
                key = (post.predicate, post.negated, len(post.args))
                self.index.setdefault(key, []).append((order, frame, n))

    def __call__(self, fact: Fact, needer: Binding, state: State) -> list[Binding]:
        found: dict[tuple[str, tuple[tuple[str, str], ...]], tuple[tuple[int, ...], Binding]] = {}
        for order, frame, n in self.index.get((fact.predicate, fact.negated, len(fact.args)), ()):
            values = _unify(frame.postconditions[n].args, fact.args, {})
            if values is None:
                continue
            for m, partial in enumerate(_from_deletions(frame, values, state)):
                self._as_said(frame, values, partial, needer, state)
                binding = frame.bind(self._complete(frame, partial, needer, state))
                key = _key(binding)
                if key == _key(needer) or key in found or not self.well_typed(binding, state) \
                        or not state.apply(binding).holds(fact):
                    continue
                found[key] = ((len(frame.elements) - len(binding.values), order, n, m), binding)
        return [binding for _, binding in sorted(found.values(), key=lambda rank_binding: rank_binding[0])]

    def _as_said(self, frame: Frame, values: Mapping[str, str], partial: dict[str, str], needer: Binding,
                 state: State) -> None:
        """Rule 2 yields to rule 3 where they disagree: a role a stored fact filled takes the needing
        frame's same-named element instead when that fact's place does not lie in it (the cup the
        state knows is on the coffee table, and the command says from the kitchen)."""
        said = needer.elements
        for element in frame.elements:
            role = element.role
            if role in values or role not in partial or role not in said or partial[role] == said[role]:
                continue
            if state.within(partial[role], said[role]) is False and fits(said[role], element.type, state,
                                                                         self.taxonomy):
                partial[role] = said[role]

    def _complete(self, frame: Frame, values: dict[str, str], needer: Binding, state: State) -> dict[str, str]:
        """Open roles: from the needing frame's same-named element, then from the default."""
        inherited = needer.elements
        for element in frame.elements:
            if element.role in values:
                continue
            if element.role in inherited and fits(inherited[element.role], element.type, state, self.taxonomy):
                values[element.role] = inherited[element.role]
            elif element.default is not None:
                values[element.role] = resolve(element.default, state)
        return values

    def well_typed(self, binding: Binding, state: State) -> bool:
        return all(fits(value, binding.frame.element(role).type, state, self.taxonomy)
                   for role, value in binding.values)


# -- search ----------------------------------------------------------------------------------------

Node = tuple[frozenset[Fact], int]


@dataclass
class _Trace:
    """What the search learnt on its way, for the message when it fails."""

    deepest: int = 0
    stuck: State | None = None
    dead: dict[int, list[tuple[Fact, Binding]]] = field(default_factory=dict)


class _Search:
    """A* over (facts, commanded frames run); see the module's docstring."""

    def __init__(self, commanded: tuple[Binding, ...], library: Library, max_nodes: int) -> None:
        self.commanded = commanded
        self.achievers = Achievers(library)
        self.max_nodes = max_nodes
        self.trace = _Trace()

    def h(self, state: State, k: int) -> int:
        """Frames still to run: the next commanded one and those after it not pointless here (:meth:`skip`),
        plus one if the next cannot run yet."""
        if k == len(self.commanded):
            return 0
        later = sum(1 for b in self.commanded[k + 1:] if already_so(b, state) is None)
        return 1 + later + (1 if state.unmet(self.commanded[k]) else 0)

    def skip(self, state: State, k: int) -> int:
        """The first commanded frame from the ``k``-th on that is not :func:`already_so` in ``state``:
        a frame whose results hold at its turn (once the frame before it has run, before any frame
        inserted for it: the fridge opened to take the apple out does not make "bring the apple to the
        kitchen" pointless), and whose needs do not, is passed over there."""
        while k < len(self.commanded) and already_so(self.commanded[k], state) is not None:
            k += 1
        return k

    def successors(self, state: State, k: int) -> list[tuple[Binding, bool]]:
        """The next commanded frame if it can run, else the achievers that can run now, in order."""
        goal = self.commanded[k]
        if state.applicable(goal):
            return [(goal, True)]
        return [(b, False) for b in self._relevant(goal, state, k)]

    def _relevant(self, goal: Binding, state: State, k: int) -> list[Binding]:
        """Depth first through the unmet preconditions: achievers that can run are successors. The walk
        keeps its own stack of frames still needing something, at most :data:`MAX_CHAIN` deep."""
        found: list[Binding] = []
        facts: set[Fact] = set()
        tried = {_key(goal)}
        chain = [goal]
        stack = [self._options(goal, state, k, facts)]
        while stack:
            option = next(stack[-1], None)
            if option is None:
                stack.pop()
                chain.pop()
                continue
            if _key(option) in tried:
                continue
            tried.add(_key(option))
            if state.applicable(option):
                found.append(option)
            elif len(stack) == MAX_CHAIN:
                raise self._too_deep(chain + [option])
            else:
                chain.append(option)
                stack.append(self._options(option, state, k, facts))
        return found

    def _options(self, needer: Binding, state: State, k: int, facts: set[Fact]) -> Iterator[Binding]:
        """The achievers of each of ``needer``'s unmet preconditions not met with before, in order."""
        for fact in state.unmet(needer):
            if fact in facts:
                continue
            facts.add(fact)
            options = self.achievers(fact, needer, state)
            if not options:
                self.trace.dead.setdefault(k, []).append((fact, needer))
            yield from options

    @staticmethod
    def _too_deep(chain: Sequence[Binding]) -> SealError:
        shown = [b.frame.name for b in chain]
        if len(shown) > 6:
            shown = [*shown[:3], f"... ({len(shown) - 6:,} more)", *shown[-3:]]
        return SealError(f"{chain[0].frame.name} needs a chain of more than {MAX_CHAIN} frames, each needing "
                         f"the next ({', '.join(shown)}); seal plans chains of at most {MAX_CHAIN}",
                         chain[-1].frame.where,
                         hint="each frame there needs what only the next one gives: a chain this long is most likely "
                              "a mistake in the frame library")

    def run(self, initial: State) -> tuple[list[tuple[Binding, bool]], tuple[Binding, ...], int]:
        """The path (frames, whether commanded), the commanded frames passed over on it (in order), and
        the nodes expanded."""
        start: Node = (initial.facts, self.skip(initial, 0))
        best: dict[Node, tuple[int, tuple[int, ...]]] = {start: (0, ())}
        parent: dict[Node, tuple[Node, Binding, bool]] = {}
        heap: list[tuple[int, tuple[int, ...], int, Node, State]] = [
            (self.h(initial, start[1]), (), 0, start, initial)]
        closed: set[Node] = set()
        expanded = 0
        while heap:
            _, ranks, g, node, state = heapq.heappop(heap)
            if node in closed:
                continue
            closed.add(node)
            k = node[1]
            if k > self.trace.deepest or self.trace.stuck is None:
                self.trace.deepest, self.trace.stuck = k, state
            if k == len(self.commanded):
                path = self._path(parent, node)
                return path, self._skipped(parent, node, start), expanded
            expanded += 1
            if expanded > self.max_nodes:
                raise self._gave_up(state, k)
            for rank, (binding, is_commanded) in enumerate(self.successors(state, k)):
                after = state.apply(binding)
                child: Node = (after.facts, self.skip(after, k + 1) if is_commanded else k)   # at its turn only
                cost = (g + 1, ranks + (rank,))
                if child in closed or (child in best and best[child] <= cost):
                    continue
                best[child], parent[child] = cost, (node, binding, is_commanded)
                heapq.heappush(heap, (g + 1 + self.h(after, child[1]), cost[1], g + 1, child, after))
        raise self._no_plan()

    def _skipped(self, parent: Mapping[Node, tuple[Node, Binding, bool]], node: Node, start: Node) -> tuple[
            Binding, ...]:
        """The commanded frames the path from ``start`` to ``node`` passed over: those between where
        each step left the count of commanded frames run and where the node after it stands."""
        passed: list[Binding] = []
        while node in parent:
            before, _, is_commanded = parent[node]
            passed[:0] = self.commanded[before[1] + is_commanded:node[1]]
            node = before
        return tuple(self.commanded[:start[1]]) + tuple(passed)

    @staticmethod
    def _path(parent: Mapping[Node, tuple[Node, Binding, bool]], node: Node) -> list[tuple[Binding, bool]]:
        path: list[tuple[Binding, bool]] = []
        while node in parent:
            node, binding, is_commanded = parent[node]
            path.append((binding, is_commanded))
        return path[::-1]

    def _gave_up(self, state: State, k: int) -> SealError:
        goal = self.commanded[k]
        unmet = ", ".join(map(str, state.unmet(goal)))
        # its needs all met, the search stopped just before it: "still needs nothing" read as a contradiction
        # (hostile20)
        where = f"still needs {unmet}" if unmet else "was next, its preconditions met, when the search stopped"
        nodes = f"{self.max_nodes:,} search node{'' if self.max_nodes == 1 else 's'}"
        return SealError(f"no plan found within {nodes}: {goal} (commanded frame {k + 1}) "
                         f"{where}", hint="raise the bound (--max-nodes) or shorten the command")

    def _no_plan(self) -> SealError:
        k = self.trace.deepest
        goal = self.commanded[k]
        dead = self.trace.dead.get(k)
        if dead:
            fact, needer = dead[0]
            via = "" if needer == goal else f" (on the way to {goal})"
            return SealError(f"no frame achieves {fact}, which {needer} needs{via}")
        state = self.trace.stuck or State()
        unmet = state.unmet(goal)
        return SealError(f"conflicting goals: no sequence of frames makes {' and '.join(map(str, unmet))} hold "
                         f"together for {goal} (commanded frame {k + 1}); making one true undoes another")


# -- the plan ----------------------------------------------------------------------------------------

def _check_types(commanded: Sequence[Binding], state: State, taxonomy: Taxonomy) -> None:
    for binding in commanded:
        for role, value in binding.values:
            element = binding.frame.element(role)
            if not fits(value, element.type, state, taxonomy):
                raise SealError(f"{binding.frame.name} needs its {role} to be {element.type}, "
                                f"and {value} is not (a {state.class_of(value)})")


def _because(index: int, bindings: Sequence[Binding], states: Sequence[State]) -> str | None:
    """The first later precondition step ``index`` made true that still held when it was needed."""
    before, after = states[index], states[index + 1]
    for j in range(index + 1, len(bindings)):
        for fact in bindings[j].preconditions:
            if not before.holds(fact) and after.holds(fact) and all(s.holds(fact) for s in states[index + 1:j + 1]):
                return f"{fact} for {bindings[j].frame.name}"
    return None


def _goal(steps: Sequence[Step], states: Sequence[State]) -> tuple[Fact, ...]:
    final = states[-1]
    goal: dict[Fact, None] = {}
    for step, before in zip(steps, states, strict=False):
        if not step.commanded:
            continue
        pre = set(step.binding.preconditions)
        for fact in step.binding.postconditions:
            removed = fact.negated and before.holds(fact.positive) and fact.positive not in pre
            if (removed or not fact.negated) and final.holds(fact):
                goal.setdefault(fact, None)
    return tuple(goal)


def plan(commanded: Sequence[Binding], library: Library, state: State, *, max_nodes: int = MAX_NODES,
         text: str | None = None) -> Plan:
    """The shortest plan that runs the commanded frames in order from ``state``.

    Raises SealError when an element's value is of the wrong type, when a precondition is achieved
    by no frame, when preconditions conflict, or when the search expands more than ``max_nodes``.
    """
    if max_nodes < 1:
        raise SealError(f"the search bound must be at least 1 node, not {max_nodes}")
    commanded = tuple(commanded)
    _check_types(commanded, state, library.taxonomy)
    path, already, expanded = _Search(commanded, library, max_nodes).run(state) if commanded else ([], (), 0)
    bindings = [binding for binding, _ in path]
    states = [state]
    for binding in bindings:
        states.append(states[-1].apply(binding))
    steps = tuple(Step(b, c, None if c else _because(i, bindings, states)) for i, (b, c) in enumerate(path))
    notes = tuple(f"{b} is not done: {', '.join(str(f) for f in b.postconditions if not f.negated)} "
                  "holds already" for b in already)
    notes += tuple(f"{step.binding}: {made.args[0]} is already {'closed' if made.negated else 'open'} on the map; "
                   "seal run says so without moving" for step, before in zip(steps, states, strict=False)
                   if step.commanded and (made := open_already(step.binding, before)) is not None)
    return Plan(steps, state, _goal(steps, states), text, expanded, notes)


def already_so(binding: Binding, state: State) -> Fact | None:
    """The result that makes a frame pointless here: its ``in(thing, where)`` — where a room or a place
    of the map (one the state knows the room of) —, when that and all its other results hold already
    while what it needs does not ("take the umbrella to the hallway" with the umbrella on the hallway's
    coat rack, or lying on its floor; "put the cup back on the coffee table" with the cup on it: picking
    it up to put it back would change nothing); None otherwise. ``seal plan`` asks it of the map's
    state, ``seal run`` of what the robot has seen (:meth:`seal_cli.sim.agent.Agent.already_so`): one
    rule for both."""
    results = [f for f in binding.postconditions if not f.negated]
    known = set(state.rooms.values()) | set(state.rooms)
    into = [f for f in results if f.predicate == "in" and len(f.args) == 2 and f.args[1] in known]
    if not into or not state.unmet(binding) or not all(state.holds(f) for f in results):
        return None
    return into[0]


def open_already(binding: Binding, state: State) -> Fact | None:
    """The result that makes an Open or a Close pointless here: its ``open(x)`` or ``not open(x)``, of a thing
    the state knows opens and shuts (its ``closable``: a map's openable places), when every result of the frame
    is of that kind and holds already ("close the fridge" with the fridge shut, e2e23); None otherwise.
    ``seal run`` skips such a frame at once, saying so (the robot's state starts from the map's ``open:``, as
    its plans do: no Open before taking from a dishwasher left open); ``seal plan`` keeps it, noted."""
    results = binding.postconditions
    if not results or state.closable is None:
        return None
    if not all(f.predicate == "open" and len(f.args) == 1 and f.args[0] in state.closable for f in results):
        return None
    return results[0] if all(state.holds(f) for f in results) else None


def explain(plan: Plan) -> Iterator[str]:
    """One line per step, numbered, as ``seal plan`` prints it without ``--json``."""
    for i, step in enumerate(plan.steps, 1):
        yield f"{i}. {step}" + (f"  ← {step.because}" if step.because else "")
