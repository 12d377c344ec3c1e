"""The planning problem: the commanded frames, the things that fill their elements, and the state
they start from — what :func:`seal_cli.planning.plan.plan` takes, built from a parsed command, the
robot's state and a map.

**Values.** An element's value is the phrase's grounded class (``Phrase.cls``, known when a
vocabulary or a map is), else its head noun as a class key ("the alarm clock" without a vocabulary
is ``clock``). A pronoun takes the value of its antecedent (``refers_to``); one with no antecedent
("put it in the fridge" alone) is an error. An element the command leaves out takes its default.

**Things.** Values name things. Without a map a thing is named by its class. A map names its
places and rooms (``fridge_1``), and a value that is the class of a place becomes the first place
of that class in the map's order ("the fridge" → ``fridge_1``). Several things of one class are
``<class>``, ``<class>_2``, ``<class>_3``, …: the map's objects of a class in the map's order, and
the things a counted phrase ("two apples") asks for, so that on a map "two apples" are its first
two apples. A frame whose element is counted is commanded once per thing, in order, and so is a
frame whose pronoun refers to them ("find two apples and put them in the fridge").

**State.** The robot holds ``holding`` (else the map's ``robot.holding``), else its hand is empty.
The map's objects are ``in`` their places. A thing that opens and closes (a map place with
``openable: true``, else a class of the ``openable`` category) is closed unless the map says
``open: true``; every other thing is always open (:attr:`State.closable <seal_cli.planning.state.State.closable>`).
Then the frames of each ``done`` command, grounded the same way, are applied in order: they ran.
"""

from __future__ import annotations

import itertools
import math
from collections.abc import Iterable, Mapping, Sequence
from dataclasses import dataclass
from typing import TYPE_CHECKING, Any

from seal_cli.errors import SealError, Where
from seal_cli.frames.library import Library
from seal_cli.frames.model import Binding, Fact, Frame
from seal_cli.frames.taxonomy import Taxonomy, check_class_name, class_key, class_words
from seal_cli.planning.state import State, robot_facts

OPENABLE = "openable"
OBJECT = "object"
"""The category of what a robot handles; a map's rooms and places (fixed furniture and receptacles,
as the SPEC says) are never one."""

if TYPE_CHECKING:
    from seal_cli.language.parser import Parse, Phrase
    from seal_cli.maps.model import Map

__all__ = ["MAX_COMMANDED", "MAX_COUNT", "Problem", "Things", "build_problem", "commanded_frames", "instance_names",
           "problem_of_text"]

INDEFINITE = frozenset({"something", "anything", "everything", "nothing"})
"""Pronouns that name a thing of their own rather than an antecedent."""


def instance_names(cls: str, n: int) -> tuple[str, ...]:
    """The names of ``n`` things of a class when nothing else is named: ``apple``, ``apple_2``, …"""
    key = class_key(cls)
    return tuple(key if i == 1 else f"{key}_{i}" for i in range(1, n + 1))


@dataclass(frozen=True)
class Problem:
    """A command ready to plan: its frames in the commanded order and the state they start from."""

    text: str
    commanded: tuple[Binding, ...]
    state: State


class Things:
    """The things a command and a map talk about: their names and classes, which ones open and
    close, and what the map says about them (``in`` and ``open`` facts)."""

    def __init__(self, taxonomy: Taxonomy, map: Map | None = None) -> None:
        self.taxonomy = taxonomy
        self.classes: dict[str, str] = {}
        self.closable: set[str] = set()
        self.fixed: set[str] = set()
        """The map's rooms and places: they stay where they are."""
        self.facts: set[Fact] = set()
        self.robot_holding: str | None = None
        if map is not None:
            self._read_map(map)

    def _read_map(self, map: Map) -> None:
        for room in map.rooms:
            self.classes.setdefault(class_key(room.name), class_key(room.name))
            self.fixed.add(class_key(room.name))
        for place in map.places:
            name = class_key(place.name)
            self.classes[name] = place.cls
            self.fixed.add(name)
            if place.openable:
                self.closable.add(name)
                if place.open:
                    self.facts.add(Fact("open", (name,)))
        counts: dict[str, int] = {}
        for obj in map.objects:
            counts[obj.cls] = counts.get(obj.cls, 0) + 1
            name = self._fresh(obj.cls, counts[obj.cls])
            if obj.inside is not None:
                self.facts.add(Fact("in", (name, class_key(obj.inside))))
        self.robot_holding = map.robot.holding

    def _fresh(self, cls: str, n: int) -> str:
        """Register a new thing of a class, the n-th if that name is free (else the next free one)."""
        name = cls if n == 1 else f"{cls}_{n}"
        while name in self.classes:
            n += 1
            name = f"{cls}_{n}"
        self._add(name, cls)
        return name

    def _add(self, name: str, cls: str) -> None:
        if name not in self.classes:
            self.classes[name] = cls
            if self.taxonomy.is_a(cls, OPENABLE) is True:
                self.closable.add(name)

    def class_of(self, name: str) -> str:
        return self.classes.get(name, name)

    def name(self, value: str) -> str:
        """The thing a value names: the thing of that name, else the first of that class, else a new one."""
        key = class_key(value)
        if key in self.classes:
            return key
        for name, cls in self.classes.items():
            if cls == key:
                return name
        self._add(key, key)
        return key

    def instances(self, value: str, n: int) -> tuple[str, ...]:
        """``n`` distinct things of the class a value names, the known ones first (in map order)."""
        first = self.name(value)
        cls = self.classes[first]
        known = [first] + [name for name, c in self.classes.items() if c == cls and name != first]
        while len(known) < n:
            known.append(self._fresh(cls, len(known) + 1))
        return tuple(known[:n])

    def state(self, holding: str | None = None) -> State:
        """The world's facts and the robot's hand; ``holding`` (a class) overrides the map's robot."""
        if holding:
            check_class_name(holding, "holding")
        held = holding or self.robot_holding
        name = self.name(held) if held else None
        facts = {f for f in self.facts if not (f.predicate == "in" and f.args[0] == name)}
        return State.of(facts | robot_facts(name), self.taxonomy, self.closable, self.classes)


MAX_COUNT = 100
"""The most things one phrase may ask for ("put 100 apples in the fridge"); more is refused."""

MAX_COMMANDED = 200
"""The most grounded frames one command may command (counts and conjunctions multiply)."""


def _located(message: str, phrase: Phrase | None, text: str) -> SealError:
    """An error about a phrase, with a caret under it when its place in the text is known."""
    if phrase is None or phrase.span is None:
        return SealError(message)
    return SealError(message, Where(None, 1, phrase.span[0] + 1), source_line=text)


def _said(phrase: Phrase | None, name: str) -> str:
    return f"{phrase.text!r} ({name})" if phrase is not None and phrase.text else name


def _values(phrase: Phrase, earlier: Sequence[Mapping[str, tuple[str, ...]]], things: Things,
            text: str) -> tuple[str, ...]:
    """The things a phrase names: its antecedent's for a pronoun, else its class (counted if asked);
    every conjunct's for a coordination."""
    from seal_cli.language.english import PERSON_PRONOUNS, PRONOUNS

    if phrase.conjuncts:        # "the apple and the pear": both
        return tuple(dict.fromkeys(v for c in phrase.conjuncts for v in _values(c, earlier, things, text)))
    if phrase.refers_to is not None:
        index, role = phrase.refers_to
        if 0 <= index < len(earlier) and role in earlier[index]:
            return earlier[index][role]
        raise _located(f"{phrase.text!r} refers to the {role} of frame {index + 1}, which the command lacks",
                       phrase, text)
    word = phrase.head.lower()
    if word in PRONOUNS and word not in PERSON_PRONOUNS and word not in INDEFINITE:
        raise _located(f"cannot tell what {phrase.text!r} refers to: nothing before it in the command fits",
                       phrase, text)
    value = phrase.cls or phrase.head
    if not class_key(value):
        raise _located(f"{phrase.text!r} names no thing", phrase, text)
    count = _count(phrase, value)
    if count > MAX_COUNT:
        raise _located(f"{phrase.text!r} asks for {count:,} things; seal plans for at most {MAX_COUNT} "
                       "of a kind", phrase, text)
    return things.instances(value, count)


def _count(phrase: Phrase, value: str) -> int:
    """How many things a phrase asks for: the number said ("two apples"); at least two for a plural
    that names the class by its head ("the books", "both books"; not "the keys" of a key chain);
    one whole for pieces cut from it ("two slices of apple": one apple, sliced; but "two sets of
    keys" are two key chains)."""
    from seal_cli.language.grounding import PIECES

    named = class_words(value)[-1:] == (phrase.head,)
    if phrase.head in PIECES and not named:
        return 1
    if phrase.quantity is not None:
        return max(1, phrase.quantity)
    return 2 if phrase.plural and named else 1


def _check_types(frame: Frame, values: Mapping[str, tuple[str, ...]], phrases: Mapping[str, Phrase],
                 things: Things, text: str) -> None:
    """A value known not to belong to its element's category is an error ("open the table"); so is
    a map's room or place where the element is an object the robot handles ("pick up the sofa")."""
    for role, names in values.items():
        element = frame.element(role)
        for name in names:
            if element.type == OPENABLE and name in things.closable:
                continue
            if element.type == OBJECT and name in things.fixed:
                phrase = phrases.get(role)
                raise _located(f"{frame.name} needs its {role} to be an object the robot can handle, and "
                               f"{_said(phrase, name)} is fixed in the map", phrase, text)
            if things.taxonomy.is_a(things.class_of(name), element.type) is False:
                phrase = phrases.get(role)
                raise _located(f"{frame.name} needs its {role} to be {element.type}, and "
                               f"{_said(phrase, name)} is not", phrase, text)


def commanded_frames(parse: Parse, library: Library, things: Things) -> list[Binding]:
    """The grounded frames a parse commands, in order; a counted element repeats its frame."""
    earlier: list[dict[str, tuple[str, ...]]] = []
    bindings: list[Binding] = []
    for evoked in parse.frames:
        frame = library.frame(evoked.frame)
        values = {role: _values(phrase, earlier, things, parse.text) for role, phrase in evoked.elements.items()}
        for element in frame.elements:
            if element.role not in values and element.default is not None:
                values[element.role] = (things.name(element.default),)
        _check_types(frame, values, evoked.elements, things, parse.text)
        earlier.append(values)
        roles = [r for r in frame.roles if r in values]
        if len(bindings) + math.prod(len(values[r]) for r in roles) > MAX_COMMANDED:
            raise SealError(f"the command asks for more than {MAX_COMMANDED} frames (counted and joined things "
                            f"multiply: {evoked.frame} alone is {math.prod(len(values[r]) for r in roles):,}); "
                            "split it into smaller commands")
        for combination in itertools.product(*(values[r] for r in roles)):
            bindings.append(frame.bind(dict(zip(roles, combination, strict=True))))
    return bindings


def build_problem(parse: Parse, library: Library, *, holding: str | None = None, done: Iterable[Parse] = (),
                  map: Map | None = None) -> Problem:
    """The commanded frames of a parse and the state they start from (see the module's docstring)."""
    things = Things(library.taxonomy, map)
    for frame in library:
        for element in frame.elements:
            if element.default is not None:
                things.name(element.default)
    executed = [(p.text, b) for p in done for b in commanded_frames(p, library, things)]
    commanded = commanded_frames(parse, library, things)
    state = things.state(holding)
    changed: dict[Fact, str] = {}  # a fact an earlier done command made true or false → that command
    for text, binding in executed:
        for fact in state.unmet(binding):
            if fact.positive in changed:
                raise SealError(f"--done {text!r} cannot follow --done {changed[fact.positive]!r}: "
                                f"{binding.frame.name} needs {fact}, which that command undid; say what happened "
                                "in between (another --done) or drop one of them")
        state = state.apply(binding)
        changed.update((f.positive, text) for f in binding.postconditions)
    return Problem(parse.text, tuple(commanded), state)


def problem_of_text(text: str, library: Library, *, holding: str | None = None, done: Sequence[str] = (),
                    map: Map | None = None, vocabulary: Any = None) -> Problem:
    """Parse the command and the ``done`` commands (with the map's vocabulary unless one is
    given), then :func:`build_problem`."""
    from seal_cli.language.parser import parse_command

    if vocabulary is None and map is not None:
        from seal_cli.language.grounding import vocabulary_of_map

        vocabulary = vocabulary_of_map(map)
    parses = [parse_command(t, library, vocabulary) for t in (*done, text)]
    return build_problem(parses[-1], library, holding=holding, done=parses[:-1], map=map)
