"""PDDL export: a planned command as ``domain.pddl`` and ``problem.pddl`` (STRIPS with typing).

The files let any PDDL planner check or redo seal's plan:

- **domain**: one action per frame of the library, named ``do_<Frame>`` (PDDL names are
  case-insensitive, and ``Open`` would clash with the predicate ``open``). Its parameters are the
  frame's elements; its precondition and effect are the frame's, ``not f`` becoming a delete.
  Requirements are ``:strips :typing``, plus ``:negative-preconditions`` only when a frame or
  the goal needs one.
- **types**: PDDL gives an object one type, but a class may belong to several categories (a
  microwave is a heater, openable and toggleable). So the types are *kinds*: the element
  categories joined wherever one thing of the problem belongs to both (by the taxonomy, or
  because it fills both kinds of element in seal's plan), and categories nested in the taxonomy.
  A parameter has its category's kind; a narrower closed category is also a precondition
  ``(is_<category> ?x)``, true of the objects not known to be outside it. Kinds that share no
  thing stay apart, so a person cannot be handed to themselves.
- **problem**: the things the plan, its initial state and its goal name; the initial state's
  facts, with ``open(x)`` spelled out for each thing that cannot close; the goal (:class:`Plan`
  ``goal``). An element seal leaves unfilled is the object ``unspecified_<kind>``, of which the
  preconditions the unfilled element dropped hold (Pick from an unspecified source: the source is
  open).

The goal is what the command leaves behind, not the order of its frames: a PDDL planner is free to
drop a commanded frame whose effects a later one undoes.
"""

from __future__ import annotations

from collections.abc import Iterable
from dataclasses import dataclass, field
from pathlib import Path

from seal_cli.errors import SealError
from seal_cli.fileio import Outputs
from seal_cli.frames.library import Library
from seal_cli.frames.model import Binding, Fact, Frame
from seal_cli.frames.taxonomy import Taxonomy, class_key
from seal_cli.planning.plan import OPENABLE, Plan

__all__ = ["Kinds", "action_name", "domain_pddl", "problem_pddl", "write_pddl"]

FALLBACK = "entity"
"""The kind of a thing that fills no element in the plan and belongs to no closed category."""


def action_name(frame: Frame) -> str:
    return f"do_{frame.name}"


def type_name(kind: str) -> str:
    return f"{kind}_kind"


def test_name(category: str) -> str:
    return f"is_{category}"


def placeholder(kind: str) -> str:
    return f"unspecified_{kind}"


def _element_types(library: Library) -> list[str]:
    return sorted({class_key(e.type) for frame in library for e in frame.elements})


@dataclass
class Kinds:
    """Element categories joined into disjoint kinds, and the kind of each object of a problem."""

    taxonomy: Taxonomy
    categories: list[str]
    parent: dict[str, str] = field(default_factory=dict)
    objects: dict[str, str] = field(default_factory=dict)
    """Object → a category it belongs to (its kind is that category's)."""
    placeholders: set[str] = field(default_factory=set)

    def find(self, category: str) -> str:
        while self.parent.setdefault(category, category) != category:
            category = self.parent[category]
        return category

    def union(self, a: str, b: str) -> None:
        ra, rb = self.find(a), self.find(b)
        if ra != rb:
            self.parent[max(ra, rb)] = min(ra, rb)

    def kind(self, category: str) -> str:
        """The kind's name: its first open category alphabetically, else its largest closed one."""
        root = self.find(category)
        group = [c for c in [*self.categories, FALLBACK] if self.find(c) == root]
        return min(group, key=lambda c: (not self.taxonomy.is_open(c), -len(self.taxonomy.members(c)), c))

    def of(self, obj: str) -> str:
        return self.kind(self.objects[obj])

    def names(self) -> list[str]:
        return sorted({self.kind(c) for c in [*self.categories, FALLBACK]})

    def narrower(self, category: str) -> bool:
        """Whether a parameter of this category needs a type test beyond its kind."""
        return not self.taxonomy.is_open(category) and any(
            self.find(c) == self.find(category) and c != category for c in [*self.categories, FALLBACK])

    @classmethod
    def of_plan(cls, library: Library, plan: Plan, objects: Iterable[str]) -> Kinds:
        taxonomy = library.taxonomy
        kinds = cls(taxonomy, _element_types(library))
        for category in kinds.categories:
            for member in (taxonomy.by_name[category].members or ()) if category in taxonomy else ():
                if member in kinds.categories:
                    kinds.union(category, member)
        uses: dict[str, set[str]] = {}
        for binding in plan.bindings:
            for role, value in binding.values:
                uses.setdefault(value, set()).add(class_key(binding.frame.element(role).type))
        for obj in objects:
            cls_ = plan.initial.class_of(obj)
            belongs = uses.get(obj, set()) | {c for c in kinds.categories
                                             if not taxonomy.is_open(c) and taxonomy.is_a(cls_, c) is True}
            belongs = belongs or {FALLBACK}
            first = min(belongs)
            for category in belongs:
                kinds.union(first, category)
            kinds.objects[obj] = first
        return kinds


# -- the problem's things ------------------------------------------------------------------------

def _unfilled(binding: Binding) -> list[tuple[str, str]]:
    """(role, category) of each element the binding leaves unfilled."""
    values = binding.elements
    return [(e.role, class_key(e.type)) for e in binding.frame.elements if e.role not in values]


def _filling(binding: Binding) -> list[tuple[str | None, str]]:
    """(value or None when unfilled, category) of each element of the binding."""
    values = binding.elements
    return [(values.get(e.role), class_key(e.type)) for e in binding.frame.elements]


def _taken_from(frame: Frame, fact: Fact) -> list[str]:
    """The roles of a where-from fact that only deletions name (Pick's source)."""
    kept = {a for f in frame.postconditions if not f.negated for a in f.args}
    return [a for a in fact.args if a not in kept]


def _dropped(binding: Binding, kinds: Kinds) -> list[Fact]:
    """The preconditions an unfilled element dropped, about the placeholders instead."""
    values = binding.elements
    stand_in = {role: placeholder(kinds.kind(category)) for role, category in _unfilled(binding)}
    return [fact.bind({**values, **stand_in}) for fact in binding.frame.preconditions
            if any(a in stand_in for a in fact.args) and not fact.negated]


def where_from(frame: Frame) -> list[Fact]:
    """Deletions naming an element that no positive postcondition names (Pick's ``in(theme, source)``,
    Close's ``open(theme)``): the frame takes the thing as it is, so in PDDL the fact must hold first.
    (seal's planner grounds such an element from the state, which is the same rule.)"""
    kept = {a for f in frame.postconditions if not f.negated for a in f.args}
    return [f.positive for f in frame.postconditions
            if f.negated and any(a not in kept for a in f.args) and f.positive not in frame.preconditions]


def _objects(plan: Plan) -> list[str]:
    names: dict[str, None] = {}
    for binding in plan.bindings:
        names.update(dict.fromkeys(value for _, value in binding.values))
    for fact in [*plan.initial.facts, *plan.goal]:
        names.update(dict.fromkeys(fact.args))
    return list(names)


@dataclass
class _Problem:
    """Everything both files need: objects and their kinds, static and initial facts."""

    library: Library
    plan: Plan
    kinds: Kinds
    objects: list[str]
    init: list[Fact]

    @classmethod
    def of(cls, library: Library, plan: Plan) -> _Problem:
        objects = _objects(plan)
        holders: dict[str, str] = {}
        for binding in plan.bindings:
            for _, category in _unfilled(binding):
                holders.setdefault(category, "")
        for frame in library:
            for fact in where_from(frame):
                for role in _taken_from(frame, fact):
                    holders.setdefault(class_key(frame.element(role).type), "")
        kinds = Kinds.of_plan(library, plan, objects)
        for category in holders:
            name = placeholder(kinds.kind(category))
            if name not in kinds.objects:
                kinds.objects[name] = category
                kinds.placeholders.add(name)
                objects.append(name)
        problem = cls(library, plan, kinds, objects, [])
        problem.init = problem._init()
        return problem

    def _init(self) -> list[Fact]:
        initial = self.plan.initial
        facts: dict[Fact, None] = dict.fromkeys(sorted(initial.facts, key=str))
        if initial.closable is not None and "open" in self._predicates():
            facts.update(dict.fromkeys(Fact("open", (o,)) for o in self.objects if o not in initial.closable))
        for binding in self.plan.bindings:
            facts.update(dict.fromkeys(_dropped(binding, self.kinds)))
            facts.update(dict.fromkeys(Fact(test_name(class_key(f.predicate)), f.args)
                                       for f in binding.preconditions if self._is_test(f)))
        for frame in self.library:
            for fact in where_from(frame):
                facts.update(dict.fromkeys(self._somewhere(frame, fact, facts)))
        for category in self._tests():
            for obj in self.objects:
                if self.kinds.find(self.kinds.objects[obj]) == self.kinds.find(category) and \
                        self._belongs(obj, category):
                    facts.setdefault(Fact(test_name(category), (obj,)), None)
        return list(facts)

    def _somewhere(self, frame: Frame, fact: Fact, known: Iterable[Fact]) -> list[Fact]:
        """For a thing nobody says where it is, ``in(thing, unspecified_location)``: Pick may take it
        from the unspecified place, as seal's Pick with no source does."""
        taken = _taken_from(frame, fact)
        given = [a for a in fact.args if a not in taken]
        if not taken or len(given) != 1:
            return []
        position, role = fact.args.index(given[0]), given[0]
        kind = self.kinds.kind(class_key(frame.element(role).type))
        placed = {f.args[position] for f in known if f.predicate == fact.predicate and len(f.args) == len(fact.args)}
        stand_in = {a: placeholder(self.kinds.kind(class_key(frame.element(a).type))) for a in taken}
        return [fact.bind({**stand_in, role: obj}) for obj in self.objects
                if obj not in placed and obj not in self.kinds.placeholders and self.kinds.of(obj) == kind]

    def _belongs(self, obj: str, category: str) -> bool:
        """Known to belong, or filling an element of that category in seal's plan (an unknown class
        the command used): a PDDL planner may not slice an apple with an apple."""
        initial = self.plan.initial
        if self.library.taxonomy.is_a(initial.class_of(obj), category) is True:
            return True
        if category == OPENABLE and initial.closable is not None and obj in initial.closable:
            return True
        kinds = self.kinds
        return any((value if value is not None else placeholder(kinds.kind(c))) == obj and c == category
                   for b in self.plan.bindings for value, c in _filling(b))

    def _is_test(self, fact: Fact) -> bool:
        return len(fact.args) == 1 and fact.predicate in self.library.taxonomy

    def _tests(self) -> list[str]:
        """Categories checked by a precondition: narrower element types and type tests in frames."""
        tests = {c for c in self.kinds.categories if self.kinds.narrower(c)}
        tests |= {class_key(f.predicate) for frame in self.library for f in frame.preconditions if self._is_test(f)}
        return sorted(tests)

    def _predicates(self) -> dict[str, int]:
        found: dict[str, int] = {}
        for frame in self.library:
            for fact in (*frame.preconditions, *frame.postconditions):
                if not self._is_test(fact):
                    found.setdefault(fact.predicate, len(fact.args))
        for fact in (*self.plan.initial.facts, *self.plan.goal):
            found.setdefault(fact.predicate, len(fact.args))
        return found


# -- writing ------------------------------------------------------------------------------------

def _atom(fact: Fact, args: Iterable[str], taxonomy: Taxonomy) -> str:
    name = test_name(class_key(fact.predicate)) if len(fact.args) == 1 and fact.predicate in taxonomy \
        else fact.predicate
    inner = " ".join([name, *args])
    return f"(not ({inner}))" if fact.negated else f"({inner})"


def _conjunction(atoms: list[str], indent: str) -> str:
    if not atoms:
        return "(and)"
    return "(and\n" + "".join(f"{indent}  {a}\n" for a in atoms) + f"{indent})"


def readings(library: Library, plan: Plan) -> list[Frame]:
    """The frames of the plan's steps read otherwise than the library writes them, each once: a goal
    said "on" (:func:`seal_cli.planning.problem.on_top`) needs no ``open(goal)``. The domain writes each
    as an action of its own beside the library's (:func:`reading_name`)."""
    found: list[Frame] = []
    for binding in plan.bindings:
        frame = binding.frame
        if frame.name in library and frame != library.frame(frame.name) and frame not in found:
            found.append(frame)
    return found


def reading_name(frame: Frame) -> str:
    """``do_Place_on_top``: the action of a reading whose thing goes on top of its goal."""
    return f"{action_name(frame)}_on_top"


def _action(frame: Frame, problem: _Problem, name: str | None = None) -> str:
    kinds, taxonomy = problem.kinds, problem.library.taxonomy
    params = " ".join(f"?{e.role} - {type_name(kinds.kind(class_key(e.type)))}" for e in frame.elements)
    pre = [f"({test_name(class_key(e.type))} ?{e.role})" for e in frame.elements if kinds.narrower(class_key(e.type))]
    pre += [_atom(f, (f"?{a}" for a in f.args), taxonomy) for f in (*frame.preconditions, *where_from(frame))]
    effect = [_atom(f, (f"?{a}" for a in f.args), taxonomy) for f in frame.postconditions]
    return (f"  (:action {name or action_name(frame)}\n"
            f"    :parameters ({params})\n"
            f"    :precondition {_conjunction(pre, '    ')}\n"
            f"    :effect {_conjunction(effect, '    ')})\n")


def _negative(problem: _Problem) -> bool:
    return any(f.negated for frame in problem.library for f in frame.preconditions) or \
        any(f.negated for f in problem.plan.goal)


def _check_names(problem: _Problem) -> None:
    """PDDL names are case-insensitive and share one namespace in many readers: two names that differ only in case
    are one name to a planner, two of a kind too (frames ``Zap`` and ``ZAP`` were written as two actions, ``do_Zap``
    and ``do_ZAP``, which a planner reads as one defined twice: hostile21)."""
    used: dict[str, tuple[str, str]] = {}
    names = [("type", type_name(k)) for k in problem.kinds.names()]
    names += [("predicate", p) for p in problem._predicates()] + [("predicate", test_name(c)) for c in problem._tests()]
    names += [("action", action_name(f)) for f in problem.library] + [("object", o) for o in problem.objects]
    names += [("action", reading_name(f)) for f in readings(problem.library, problem.plan)]
    for what, name in names:
        other, spelt = used.setdefault(name.lower(), (what, name))
        if other == what and spelt != name:
            raise SealError(f"cannot export PDDL: the {what}s {spelt!r} and {name!r} differ only in case, and PDDL "
                            f"reads names without case: rename one of them")
        if other != what:
            raise SealError(f"cannot export PDDL: {name!r} would name both a {other} and an {what}"
                            if what[0] in "aeiou" else
                            f"cannot export PDDL: {name!r} would name both a {other} and a {what}")


def domain_pddl(library: Library, plan: Plan, *, name: str = "seal") -> str:
    """The library's frames as a PDDL domain, typed by the kinds of ``plan``'s problem."""
    problem = _Problem.of(library, plan)
    _check_names(problem)
    requirements = ":strips :typing" + (" :negative-preconditions" if _negative(problem) else "")
    predicates = [f"({p}{''.join(f' ?x{i}' for i in range(n))})" for p, n in problem._predicates().items()]
    predicates += [f"({test_name(c)} ?x0)" for c in problem._tests()]
    types = " ".join(type_name(k) for k in problem.kinds.names())
    lines = [f"; the frame library as a PDDL domain, written by seal for: {_one_line(plan.text or 'a plan')}",
             f"(define (domain {name})",
             f"  (:requirements {requirements})",
             f"  (:types {types} - object)",
             "  (:predicates\n" + "".join(f"    {p}\n" for p in predicates) + "  )"]
    return "\n".join(lines) + "\n" + "".join(_action(frame, problem) for frame in library) + \
        "".join(_action(frame, problem, reading_name(frame)) for frame in readings(library, plan)) + ")\n"


def _one_line(text: str) -> str:
    """The command as the text of a ``;`` comment, which ends at the line's end: its line breaks (and every other
    run of white space) one space, anything else unprintable an escape. "stir the cup\\nthen open the fridge"
    left its second line outside the comment, and both files were PDDL no planner reads."""
    return "".join(c if c.isprintable() else c.encode("unicode_escape").decode("ascii") for c in " ".join(text.split()))


def problem_pddl(library: Library, plan: Plan, *, name: str = "command", domain: str = "seal") -> str:
    """The plan's things, initial state and goal as a PDDL problem."""
    problem = _Problem.of(library, plan)
    _check_names(problem)
    taxonomy = library.taxonomy
    by_kind: dict[str, list[str]] = {}
    for obj in problem.objects:
        by_kind.setdefault(problem.kinds.of(obj), []).append(obj)
    objects = "".join(f"    {' '.join(names)} - {type_name(kind)}\n" for kind, names in sorted(by_kind.items()))
    init = "".join(f"    {_atom(f, f.args, taxonomy)}\n" for f in problem.init)
    goal = _conjunction([_atom(f, f.args, taxonomy) for f in plan.goal], "  ")
    return (f"; {_one_line(plan.text or 'a plan')}\n(define (problem {name}) (:domain {domain})\n"
            f"  (:objects\n{objects}  )\n  (:init\n{init}  )\n  (:goal {goal})\n)\n")


PDDL_FILES = ("domain.pddl", "problem.pddl")
"""The files ``write_pddl`` writes into its folder."""


def write_pddl(directory: str | Path, library: Library, plan: Plan, files: Outputs | None = None) -> tuple[Path, Path]:
    """Write ``domain.pddl`` and ``problem.pddl`` into an existing folder, both or neither: into the
    ``--pddl`` temporaries of ``files`` when given (whose owner moves them), else on their own."""
    if files is None:
        with Outputs({"--pddl": directory}, folders={"--pddl": PDDL_FILES}) as own:
            return write_pddl(directory, library, plan, own)
    for name, text in zip(PDDL_FILES, (domain_pddl(library, plan), problem_pddl(library, plan)), strict=True):
        files.file("--pddl", name).write_text(text, encoding="utf-8")
    folder = Path(directory)
    return folder / PDDL_FILES[0], folder / PDDL_FILES[1]

