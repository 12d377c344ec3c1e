"""The robot's and the world's state as a set of grounded facts, and how frames change it.

This is the one place where the semantics of executing a frame live; the planner, the
localisation engine (which needs to know which preconditions are met) and the simulator all
use it. It is STRIPS:

- a grounded frame is *applicable* when each of its preconditions holds;
- applying it removes its negated postconditions and adds its positive ones:
  ``(state - deletes) | adds``.

A unary fact whose predicate names a category of the library (``openable(fridge)``) is a
type test, decided by the taxonomy rather than stored: it holds unless the class is known
not to belong.

``open(x)`` of a thing that cannot be closed always holds (a table is always open; see
docs/design.md, "Open things"). A state that knows which things open and close (``closable``)
decides this itself, so that only the openable things' ``open`` facts are stored.
"""

from __future__ import annotations

from collections.abc import Iterable, Iterator, Mapping
from dataclasses import dataclass, field

from seal_cli.frames.model import Binding, Fact
from seal_cli.frames.taxonomy import Taxonomy

__all__ = ["State", "robot_facts"]

HAND_EMPTY = Fact("hand_empty")


@dataclass(frozen=True)
class State:
    """A set of grounded positive facts; whatever is not in it is false (closed world)."""

    facts: frozenset[Fact] = frozenset()
    taxonomy: Taxonomy | None = field(default=None, compare=False, repr=False)
    closable: frozenset[str] | None = field(default=None, compare=False, repr=False)
    """The things that open and close. When given, ``open(x)`` of any other thing always holds;
    when None, ``open`` is an ordinary stored fact."""
    classes: Mapping[str, str] = field(default_factory=dict, compare=False, repr=False)
    """The class of each thing whose name is not its class (``fridge_1`` → ``fridge``, ``apple_2`` → ``apple``)."""
    rooms: Mapping[str, str] = field(default_factory=dict, compare=False, repr=False)
    """The room each place lies in (``fridge_1`` → ``kitchen``), as a map says, and each thing that
    lies on no place (a towel on the restroom's floor → ``restroom``); empty without a map."""

    @classmethod
    def of(cls, facts: Iterable[Fact], taxonomy: Taxonomy | None = None,
           closable: Iterable[str] | None = None, classes: Mapping[str, str] | None = None,
           rooms: Mapping[str, str] | None = None) -> State:
        return cls(frozenset(f.positive for f in facts if not f.negated), taxonomy,
                   None if closable is None else frozenset(closable), dict(classes or {}), dict(rooms or {}))

    def class_of(self, name: str) -> str:
        """The class of a thing: its entry in ``classes``, else its own name."""
        return self.classes.get(name, name)

    def within(self, place: str, where: str) -> bool | None:
        """Whether a place is ``where`` or lies in it (``fridge_1`` in ``kitchen``); None when the
        state knows the room of neither (no map)."""
        if place == where or self.rooms.get(place) == where:
            return True
        return False if place in self.rooms or where in self.rooms else None

    def holds(self, fact: Fact) -> bool:
        """Whether a grounded fact is true here (a negated fact: whether its positive is false)."""
        taxonomy = self.taxonomy
        if taxonomy is not None and len(fact.args) == 1 and fact.predicate in taxonomy:
            truth = taxonomy.is_a(self.class_of(fact.args[0]), fact.predicate) is not False
        elif self.closable is not None and fact.predicate == "open" and len(fact.args) == 1 \
                and fact.args[0] not in self.closable:
            truth = True
        else:
            truth = fact.positive in self.facts or self._in_room(fact.positive)
        return truth != fact.negated

    def _in_room(self, fact: Fact) -> bool:
        """Whether ``in(x, room)`` holds because x is in or on a place that lies in the room and is
        not shut (an umbrella on the hallway's coat rack is in the hallway; an apple in the closed
        fridge is still to be brought out), or lies there on no place: ``rooms`` says so, nobody
        holds it and no fact puts it in or on anything (once moved, the facts say where it is)."""
        if fact.predicate != "in" or len(fact.args) != 2 or fact.args[1] not in self.rooms.values():
            return False
        thing, room = fact.args
        put = [f for f in self.facts if f.predicate in ("in", "on") and len(f.args) == 2 and f.args[0] == thing]
        if not put:
            return self.rooms.get(thing) == room and Fact("holding", (thing,)) not in self.facts
        return any(self.rooms.get(f.args[1]) == room and self.holds(Fact("open", (f.args[1],))) for f in put)

    def unmet(self, binding: Binding) -> tuple[Fact, ...]:
        """The grounded frame's preconditions that do not hold, in the frame's order."""
        return tuple(f for f in binding.preconditions if not self.holds(f))

    def applicable(self, binding: Binding) -> bool:
        return not self.unmet(binding)

    def apply(self, binding: Binding) -> State:
        """The state after the grounded frame has run: ``(state - deletes) | adds``."""
        post = binding.postconditions
        deletes = {f.positive for f in post if f.negated}
        adds = {f for f in post if not f.negated}
        return State((self.facts - deletes) | adds, self.taxonomy, self.closable, self.classes, self.rooms)

    def achieves(self, binding: Binding, fact: Fact) -> bool:
        """Whether running the grounded frame here makes ``fact`` hold."""
        return self.apply(binding).holds(fact)

    def __contains__(self, fact: object) -> bool:
        return isinstance(fact, Fact) and self.holds(fact)

    def __iter__(self) -> Iterator[Fact]:
        return iter(sorted(self.facts, key=str))

    def __str__(self) -> str:
        return "{" + ", ".join(str(f) for f in self) + "}"


def robot_facts(holding: str | None = None) -> frozenset[Fact]:
    """What the robot's hand says: ``holding(x)``, or ``hand_empty``."""
    return frozenset({Fact("holding", (holding,))} if holding else {HAND_EMPTY})
