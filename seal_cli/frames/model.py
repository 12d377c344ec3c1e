"""The typed frame model: semantic frames, their elements, facts and actions.

A **frame** (after FrameNet and RoboFrameNet) is what a verb phrase evokes: ``Stir`` with the
**elements** ``theme`` (what is stirred) and ``instrument`` (what it is stirred with). Its
**preconditions** are ordered facts that must hold before its **actions** (primitive robot
actions) run; its **postconditions** are the facts that hold afterwards, ``not f(x)`` deleting
``f(x)``. Facts and actions name the frame's elements as arguments; a frame is *grounded* by
binding each element to an object class (see :meth:`Frame.bind`).

All of these are frozen value objects that check themselves when built. Where an object was
written (file, line, column) rides along in ``where`` and never takes part in equality, so the
same frame written in YAML and in the DSL compares equal.
"""

from __future__ import annotations

import re
from collections.abc import Iterable, Mapping
from dataclasses import dataclass, field
from functools import cached_property
from typing import Any

from seal_cli.errors import SealError, SealErrors, Where
from seal_cli.names import check_name_length, check_shown, name_too_long

__all__ = ["Action", "Element", "Fact", "Frame", "LexicalUnit", "parse_atom"]

IDENTIFIER = re.compile(r"[^\W\d]\w*\Z")  # Unicode letters too: "café" and "Zoë" are names
FRAME_NAME = re.compile(r"[A-Z][A-Za-z0-9_]*\Z")
_ATOM = re.compile(r"\s*(?P<neg>not\s+)?(?P<name>[^\W\d]\w*)\s*(?:\((?P<args>[^()]*)\))?\s*\Z")


def _check_identifier(kind: str, text: str, where: Where | None) -> None:
    check_name_length(text, kind, where)
    if not (IDENTIFIER.match(text) or text.isidentifier()):    # a mark after a letter too: "i̇stanbul", "रसोई"
        raise SealError(f"{kind} {text!r} is not a name (letters, digits and '_', not starting with a digit)",
                        where)


def parse_atom(text: str, where: Where | None = None) -> tuple[bool, str, tuple[str, ...]]:
    """Split ``"not in(theme, goal)"`` into ``(True, "in", ("theme", "goal"))``.

    >>> parse_atom("hand_empty")
    (False, 'hand_empty', ())
    """
    match = _ATOM.match(text)
    if not match:
        raise SealError(f"cannot read {text!r}: expected name or name(arg, ...), optionally after 'not'",
                        where)
    raw = match["args"]
    args = tuple(a.strip() for a in raw.split(",")) if raw is not None and raw.strip() else ()
    for arg in args:
        _check_identifier("argument", arg, where)
    return bool(match["neg"]), match["name"], args


@dataclass(frozen=True)
class Fact:
    """A predicate over element names (in a frame) or object classes (once grounded).

    ``negated`` facts appear in postconditions (they delete) and, rarely, in preconditions
    (they must not hold).
    """

    predicate: str
    args: tuple[str, ...] = ()
    negated: bool = False
    where: Where | None = field(default=None, compare=False, repr=False)

    def __post_init__(self) -> None:
        _check_identifier("predicate", self.predicate, self.where)
        if self.predicate == "not":
            raise SealError("'not' negates a fact and cannot be a predicate: write 'not name(args)'", self.where)
        for arg in self.args:
            _check_identifier("argument", arg, self.where)

    @classmethod
    def parse(cls, text: str, where: Where | None = None) -> Fact:
        negated, name, args = parse_atom(text, where)
        return cls(name, args, negated, where)

    @cached_property
    def positive(self) -> Fact:
        """The fact without its negation (itself when it is not negated)."""
        return Fact(self.predicate, self.args, False, self.where) if self.negated else self

    def bind(self, values: Mapping[str, str]) -> Fact:
        """The fact with each argument replaced by its value (arguments without one stay)."""
        return Fact(self.predicate, tuple(values.get(a, a) for a in self.args), self.negated, self.where)

    def __str__(self) -> str:
        atom = f"{self.predicate}({', '.join(self.args)})" if self.args else self.predicate
        return f"not {atom}" if self.negated else atom


@dataclass(frozen=True)
class Action:
    """A primitive robot action, such as ``navigate(theme)`` or ``stir(instrument, theme)``."""

    name: str
    args: tuple[str, ...] = ()
    where: Where | None = field(default=None, compare=False, repr=False)

    def __post_init__(self) -> None:
        _check_identifier("action", self.name, self.where)
        for arg in self.args:
            _check_identifier("argument", arg, self.where)

    @classmethod
    def parse(cls, text: str, where: Where | None = None) -> Action:
        negated, name, args = parse_atom(text, where)
        if negated:
            raise SealError(f"an action cannot be negated: {text!r}", where)
        return cls(name, args, where)

    def bind(self, values: Mapping[str, str]) -> Action:
        return Action(self.name, tuple(values.get(a, a) for a in self.args), self.where)

    def __str__(self) -> str:
        return f"{self.name}({', '.join(self.args)})"


@dataclass(frozen=True)
class Element:
    """A frame element: its role (``theme``), its type (a category) and an optional default class."""

    role: str
    type: str
    default: str | None = None
    where: Where | None = field(default=None, compare=False, repr=False)

    def __post_init__(self) -> None:
        _check_identifier("element", self.role, self.where)
        _check_identifier("type", self.type, self.where)
        if self.default is not None:
            _check_identifier("default", self.default, self.where)


def normalize_unit(text: str) -> str:
    """A lexical unit's canonical spelling: lower case, single spaces."""
    return " ".join(text.lower().split())


MAX_UNIT_LENGTH = 1000
"""The longest lexical unit, in characters: the longest command seal takes
(:data:`seal_cli.language.tokens.MAX_LENGTH`), so a longer unit could never be said."""


@dataclass(frozen=True)
class LexicalUnit:
    """A verb lemma, possibly of several words ("pick up", "look for"), that evokes a frame. ``object``:
    the element its direct object fills when that is not the frame's first ("fill the glass with water":
    the glass is where the water goes, FrameNet's Filling), its theme then said with "with". ``apart``: the
    particles with which the verb is a verb of its own that the frame is not ("hang *up*": end a phone call,
    PropBank's ``hang_up.03``), unless a place is said ("hang up the coat *on the hook*"). ``stores``: said
    with no goal, the unit means "where such a thing is kept" ("put away", "store"), not "down here"
    (:func:`seal_cli.planning.problem.commanded_frames`). ``split``: said only with its particle alone after the
    object ("put the kettle *on*": the state it is put in, ToggleOn); joined ("put on the table", "put on your coat")
    it is no such unit. ``opening``: a verb that is mostly a noun ("dust", "vacuum", "ladle"), read as the unit only
    opening an imperative clause before its object, where a noun cannot stand ("dust the shelf", not "put the dust
    in the bin")."""

    text: str
    where: Where | None = field(default=None, compare=False, repr=False)
    object: str | None = field(default=None, compare=False)   # only added units say it: dumps leave it out
    apart: tuple[str, ...] = field(default=(), compare=False)
    stores: bool = field(default=False, compare=False)
    split: bool = field(default=False, compare=False)
    opening: bool = field(default=False, compare=False)

    def __post_init__(self) -> None:
        object.__setattr__(self, "text", normalize_unit(self.text))
        if len(self.text) > MAX_UNIT_LENGTH:
            raise SealError(f"lexical unit '{self.text[:40]}…' is {len(self.text):,} characters long, longer than any "
                            f"command seal takes ({MAX_UNIT_LENGTH:,} characters): it could never be said", self.where)
        if not self.text or not all(re.fullmatch(r"[a-z][a-z'-]*", w) for w in self.words):
            raise SealError(f"lexical unit {self.text!r} must be one or more words of letters a-z (with ' or - "
                            "inside)", self.where)
        if self.object is not None:
            _check_identifier("object", self.object, self.where)
        if not all(re.fullmatch(r"[a-z]+", p) for p in self.apart):
            raise SealError(f"lexical unit {self.text!r}: apart must be particles, words of letters "
                            f"({' '.join(self.apart)!r})", self.where)
        if self.split and len(self.words) != 2:
            raise SealError(f"lexical unit {self.text!r}: a split unit is a verb and its particle, two words",
                            self.where)

    @property
    def words(self) -> tuple[str, ...]:
        return tuple(self.text.split())

    def __str__(self) -> str:
        return self.text


@dataclass(frozen=True)
class Frame:
    """A semantic frame ``f = (O, P, A)``: elements, pre- and postconditions, actions."""

    name: str
    lexical_units: tuple[LexicalUnit, ...] = ()
    elements: tuple[Element, ...] = ()
    preconditions: tuple[Fact, ...] = ()
    actions: tuple[Action, ...] = ()
    postconditions: tuple[Fact, ...] = ()
    description: str = ""
    framenet: str | None = None
    where: Where | None = field(default=None, compare=False, repr=False)

    def __post_init__(self) -> None:
        problems = list(self.problems())
        if problems:
            raise problems[0] if len(problems) == 1 else SealErrors(problems)

    def problems(self) -> Iterable[SealError]:
        """What is wrong inside this frame alone (the library checks the rest)."""
        too_long = name_too_long(self.name, "frame name", self.where)
        if too_long is not None:
            yield too_long
        elif not FRAME_NAME.match(self.name):
            yield SealError(f"frame name {self.name!r} must start with a capital letter "
                            "and hold only letters, digits and '_'", self.where)
        for what, text in (("description", self.description), ("FrameNet name", self.framenet or "")):
            try:  # printed by `seal frames` and its JSON (hostile28: a lone surrogate, an escape sequence passed)
                check_shown(text, f"{self.name}'s {what}", self.where, allowed="\n\t" if what == "description" else "")
            except SealError as problem:
                yield problem
        seen: dict[str, Element] = {}
        for element in self.elements:
            if element.role in seen:
                yield SealError(f"{self.name} has two elements named {element.role!r}", element.where)
            seen[element.role] = element
        units: set[str] = set()
        for unit in self.lexical_units:
            if unit.text in units:
                yield SealError(f"{self.name} lists the lexical unit {unit.text!r} twice", unit.where)
            units.add(unit.text)
        for section, items in (("precondition", self.preconditions), ("action", self.actions),
                               ("postcondition", self.postconditions)):
            for item in items:
                for arg in item.args:
                    if arg not in seen:
                        yield SealError(f"{section} {item} names {arg!r}, which {self.name} lacks"
                                        f"{_suggest(arg, seen)}; its elements are {_listing(seen)}", item.where)

    def needs_held(self, role: str | None = None) -> bool:
        """Whether the frame needs the robot to hold its ``role`` (by default its first element) first:
        a ``holding(role)`` precondition (Place, Heat; Stir for its instrument)."""
        return _holds(self.preconditions, role or self.first_role)

    def gets_held(self, role: str | None = None) -> bool:
        """Whether the frame leaves the robot holding its ``role`` (by default its first element): a
        ``holding(role)`` postcondition (Pick)."""
        return _holds(self.postconditions, role or self.first_role)

    @property
    def first_role(self) -> str | None:
        """The role of the frame's first element (what its verb acts on), None for a frame without any."""
        return self.elements[0].role if self.elements else None

    @classmethod
    def salvage(cls, name: str, **fields: Any) -> Frame | None:
        """The frame without what its own checks refuse (a second element or lexical unit of one
        name, a fact or action naming an element it lacks), so that a library's checks across
        frames still look at the rest of it; None when its name itself is wrong."""
        if not FRAME_NAME.match(name):
            return None
        elements = tuple({e.role: e for e in reversed(fields.get("elements", ()))}.values())[::-1]
        roles = {e.role for e in elements}
        units = tuple({u.text: u for u in reversed(fields.get("lexical_units", ()))}.values())[::-1]
        kept = {key: tuple(i for i in fields.get(key, ()) if set(i.args) <= roles)
                for key in ("preconditions", "actions", "postconditions")}
        try:
            return cls(name, **{**fields, "elements": elements, "lexical_units": units, **kept})  # type: ignore[arg-type]
        except SealError:
            return None

    @cached_property
    def roles(self) -> tuple[str, ...]:
        """The roles of the elements, in order (made once: the parser asks a frame for them at every clause)."""
        return tuple(e.role for e in self.elements)

    def element(self, role: str) -> Element:
        for element in self.elements:
            if element.role == role:
                return element
        raise KeyError(f"{self.name} has no element {role!r}; its elements are {', '.join(self.roles)}")

    def bind(self, values: Mapping[str, str | None]) -> Binding:
        """Ground the frame: each element takes its value, else its default.

        Facts and actions that name an element left without a value are dropped: "pick up the
        cup" says nothing about where from, so ``open(source)`` does not apply.
        """
        unknown = set(values) - set(self.roles)
        if unknown:
            raise SealError(f"{self.name} has no element {', '.join(sorted(unknown))}; "
                            f"its elements are {', '.join(self.roles)}")
        bound: dict[str, str] = {}
        for element in self.elements:
            value = values.get(element.role) or element.default
            if value is not None:
                bound[element.role] = value
        return Binding(self, tuple(sorted(bound.items())))


@dataclass(frozen=True)
class Binding:
    """A grounded frame: a frame and the value (an object class or place) of each filled element.

    Its grounded facts and actions are computed once (planners ask for them at every state)."""

    frame: Frame
    values: tuple[tuple[str, str], ...]

    @property
    def elements(self) -> dict[str, str]:
        return dict(self.values)

    def _ground(self, facts: Iterable[Fact]) -> tuple[Fact, ...]:
        values = self.elements
        return tuple(f.bind(values) for f in facts if all(a in values for a in f.args))

    @cached_property
    def preconditions(self) -> tuple[Fact, ...]:
        return self._ground(self.frame.preconditions)

    @cached_property
    def postconditions(self) -> tuple[Fact, ...]:
        return self._ground(self.frame.postconditions)

    @cached_property
    def actions(self) -> tuple[Action, ...]:
        values = self.elements
        return tuple(a.bind(values) for a in self.frame.actions if all(x in values for x in a.args))

    def __str__(self) -> str:
        inner = ", ".join(f"{role}={value}" for role, value in
                          sorted(self.values, key=lambda kv: self.frame.roles.index(kv[0])))
        return f"{self.frame.name}({inner})"


def _listing(elements: Mapping[str, Element]) -> str:
    return ", ".join(elements) if elements else "none"


def _suggest(name: str, choices: Iterable[str]) -> str:
    import difflib

    close = difflib.get_close_matches(name, [c for c in choices if c != name], n=1)
    return f" (did you mean {close[0]!r}?)" if close else ""


def _holds(facts: Iterable[Fact], role: str | None) -> bool:
    """Whether ``facts`` assert ``holding(role)`` (not its negation)."""
    return role is not None and any(f.predicate == "holding" and f.args == (role,) and not f.negated for f in facts)
