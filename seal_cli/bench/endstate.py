"""The end-state judge: whether the world at the end of a run is what the command asked for.

A map-suite run used to succeed when "every frame of its plan was executed", which only a policy
that runs seal's plan can do; a planner that drives itself from the text (``saycan``) has no plan
to execute. This judge reads the *world* instead, for every policy alike: the command is read by
seal (the same parse and grounding as ``seal run``), and its commanded frames' effects — what each
frame's postconditions leave true once the later frames have run (:func:`effects`: "pick up the cup
and put it on the table" leaves ``in(cup, dining_table_1)`` and ``hand_empty``, not
``holding(cup)``) — must hold in the world at the end, for some choice of the things the command
names by kind ("the cup": any cup).

How a fact is read from the world (:func:`holds`):

- ``in(x, p)``: x is in or on the place p (or in something there), not in the hand; ``in(x, room)``:
  x stands in the room, not in the hand; ``has(person, x)``: x was handed to the person;
- ``holding(x)``, ``hand_empty``: the robot's hand; ``open(x)``: x is open (a thing that does not
  open always is); ``toggled_on(x)``: x is on; ``hot``, ``cold``, ``clean``, ``sliced``, ``stirred``:
  the thing's state;
- ``found(x)``: the robot knows where x is (it saw it, or the map says); ``at(x)`` / ``visited(x)``:
  the robot (or, led, the person) is in the room x at the end / was there at some point;
- anything else the world keeps no state for (``answered``, ``told``, ``greeted``, ``met``,
  ``followed``, ``counted``, ``looked_at``, ``poured``): the world's log has a successful action of
  the frame that asserts it, on the same things.
"""

from __future__ import annotations

import itertools
import math
from collections.abc import Iterable, Mapping, Sequence
from dataclasses import dataclass

from seal_cli.frames.model import Binding, Fact
from seal_cli.maps.model import Map
from seal_cli.sim.world import World

__all__ = ["Verdict", "effects", "holds", "judge_end"]

MAX_CHOICES = 10_000
"""Assignments of things to the command's kinds tried before the judge gives up (it says so)."""


@dataclass(frozen=True)
class Verdict:
    success: bool
    reason: str
    satisfied: tuple[str, ...] = ()


def effects(commanded: Sequence[Binding]) -> list[tuple[Fact, Binding]]:
    """What the commanded frames leave true, in order, each with the frame that made it so."""
    left: dict[Fact, Binding] = {}
    for binding in commanded:
        for fact in binding.postconditions:
            if fact.negated:
                left.pop(fact.positive, None)
            else:
                left.pop(fact, None)
                left[fact] = binding
    return list(left.items())


def judge_end(world: World, m: Map, commanded: Sequence[Binding], classes: Mapping[str, str],
              known: Iterable[str] = ()) -> Verdict:
    """Whether the world satisfies every effect of the commanded frames (see the module docstring).

    ``classes``: the class of each name the frames use (the problem's ``state.classes``); a name
    that is an item of the world or a room of the map is that item or room, any other stands for
    some thing of its class, the same one in every fact. ``known``: the items the robot knew at the
    end (for ``found``)."""
    wanted = effects(commanded)
    if not wanted:
        return Verdict(True, "the command asks for nothing the world shows")
    names = sorted({a for fact, _ in wanted for a in fact.args if _free(a, world, m)})
    choices = [[i.id for i in world.of_class(classes.get(n, n))] for n in names]
    seen = set(known)
    best: list[str] = []
    for count, pick in enumerate(itertools.product(*choices)):
        if count >= MAX_CHOICES:
            return Verdict(False, f"gave up after {MAX_CHOICES} choices of things; best had "
                                  f"{', '.join(best) or 'nothing'}", tuple(best))
        if len(set(pick)) < len(pick):
            continue
        chosen = dict(zip(names, pick, strict=True))
        met = [str(f) for f, b in wanted if holds(_ground(f, chosen), world, m, seen, _actions(b, chosen))]
        if len(met) == len(wanted):
            return Verdict(True, "the world at the end is what the command asked for", tuple(met))
        if len(met) > len(best):
            best = met
    missing = [str(f) for f, _ in wanted if str(f) not in best]
    return Verdict(False, f"not done: needs {', '.join(missing)}; had {', '.join(best) or 'nothing'}", tuple(best))


def _free(name: str, world: World, m: Map) -> bool:
    return name not in world.items and m.room_id(name) is None


def _ground(fact: Fact, chosen: Mapping[str, str]) -> Fact:
    return Fact(fact.predicate, tuple(chosen.get(a, a) for a in fact.args), fact.negated)


def _actions(binding: Binding, chosen: Mapping[str, str]) -> list[tuple[str, tuple[str, ...]]]:
    return [(a.name, tuple(chosen.get(x, x) for x in a.args)) for a in binding.actions]


def holds(fact: Fact, world: World, m: Map, known: frozenset[str] | set[str] = frozenset(),
          actions: Sequence[tuple[str, tuple[str, ...]]] = ()) -> bool:
    """Whether a ground fact is true of the world now (see the module docstring); ``actions``: the
    asserting frame's actions, for the facts the world keeps no state of."""
    p, args = fact.predicate, fact.args
    if p == "hand_empty":
        return world.robot.holding is None
    if any(a not in world.items and m.room_id(a) is None for a in args):
        return False
    if p == "holding":
        return world.robot.holding == args[0]
    if p == "in":
        thing, where = args
        if world.held_chain(thing):
            return False
        if where in world.items:
            return any(a.id == where for a in world.ancestors(thing))
        room = m.rooms[m.room_id(where)]  # type: ignore[index]
        return bool(room.contains([world.position(thing)])[0])
    if p == "has":
        return world.items[args[1]].parent == args[0]
    if p == "open":
        return world.items[args[0]].is_open
    if p == "toggled_on":
        return world.has(args[0], "on")
    if p in ("hot", "cold", "clean", "sliced", "stirred"):
        return world.has(args[0], p)
    if p == "found":
        return args[0] in known
    if p in ("at", "visited") and m.room_id(args[0]) is not None:
        room = m.rooms[m.room_id(args[0])]  # type: ignore[index]
        points = [world.robot.pose[:2]] if p == "at" else list(world.robot.trajectory)
        return bool(room.contains(points).any())
    if p == "at":
        return math.dist(world.robot.pose[:2], world.position(args[0])) <= world.reach_of(args[0]) + 1e-9
    logged = {(e.action, e.args) for e in world.log if e.ok}
    return bool(actions) and all(a in logged or a[0] == "navigate" for a in actions)

