"""The house the commands already done (``--done``) left: what ``seal run`` acts in, as ``seal plan`` plans on it.

:meth:`Things.carry_out <seal_cli.planning.problem.Things.carry_out>` applies the done commands' frames to what a map
says (a thing in one place at a time). :func:`world_after` reads that back onto the map: each of its objects a done
command moved lies where it was left (on the place it was put on, in the middle of the room it was taken to, by the
person it was handed to), the robot holds what it was left holding, and the places opened or closed are so. Before
(e2e30), ``seal run --done 'bring the cup to the table' 'put it back'`` acted in the map as drawn: the cup still on
the coffee table, where "back" already was. :func:`handled` is what the robot knows of the objects it handled: they
lie where the map drew them until the done commands, which it replays on them, move them. The robot starts where the
map puts it (a done command does not say where the robot ended).
"""

from __future__ import annotations

from dataclasses import replace
from typing import TYPE_CHECKING

import numpy as np

from seal_cli.frames.model import Fact
from seal_cli.frames.taxonomy import class_key
from seal_cli.maps.model import SPEAKER, Map, ObjectTruth, Robot

if TYPE_CHECKING:
    from seal_cli.planning.problem import Things

__all__ = ["handled", "world_after"]


def world_after(m: Map, things: Things) -> Map:
    """The map with its objects, its places' doors and the robot's hand as the done commands carried out on
    ``things`` (built on ``m``) left them."""
    objects: list[ObjectTruth] = []
    holding = m.robot.holding
    for obj, name in zip(m.objects, things.object_names, strict=True):
        if name == things.held:
            holding = obj.cls
            continue
        if obj.inside is not None and Fact("in", (name, class_key(obj.inside))) in things.facts:
            objects.append(obj)
            continue
        objects.append(_left_at(m, obj, name, things))
    places = tuple(replace(p, open=Fact("open", (class_key(p.name),)) in things.facts) if p.openable else p
                   for p in m.places)
    return replace(m, objects=tuple(objects), places=places, robot=Robot(m.robot.pose, holding))


def _left_at(m: Map, obj: ObjectTruth, name: str, things: Things) -> ObjectTruth:
    """Where a done command left one of the map's objects (as drawn, when none moved it)."""
    where = next((f.args[1] for f in sorted(things.facts, key=str) if f.predicate == "in" and f.args[0] == name),
                 None)
    given = next((f.args[0] for f in sorted(things.facts, key=str) if f.predicate == "has" and f.args[1:] == (name,)),
                 None)
    place = m.place(where) if where is not None else None
    if place is not None:
        return ObjectTruth(obj.cls, place.at, place.name)
    if where is not None and m.room_id(where) is not None:
        return ObjectTruth(obj.cls, _spot_in(m, where))
    person = given or where
    if person == SPEAKER:
        return ObjectTruth(obj.cls, m.speaker_at)
    if person is not None and (someone := m.person(person)) is not None:
        return ObjectTruth(obj.cls, m.person_at(someone))
    return obj


def _spot_in(m: Map, room: str) -> tuple[float, float]:
    """The free cell of a room nearest its middle."""
    the_room = m.room(room)
    free = m.free_centres[the_room.contains(m.free_centres)]
    if len(free) == 0:
        return the_room.centroid
    middle = np.asarray(the_room.centroid)
    nearest = free[np.argmin(((free - middle) ** 2).sum(axis=1))]
    return (float(nearest[0]), float(nearest[1]))


def handled(m: Map, things: Things) -> tuple[ObjectTruth, ...]:
    """The map's objects the done commands acted on or moved, as the map drew them: what the robot knew of them
    before it did those commands."""
    touched = {*things.handled_before, *things.taken_from, *([things.held] if things.held else [])}
    return tuple(obj for obj, name in zip(m.objects, things.object_names, strict=True) if name in touched)
