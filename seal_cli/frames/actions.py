"""The primitive robot actions that frames are made of, with what each one means.

A frame's ``actions`` name these primitives; ``seal validate`` refuses an unknown name or a
wrong number of arguments, and the simulator (``seal run``) executes exactly these. Adding a
primitive means adding it here and teaching the simulator how to do it.
"""

from __future__ import annotations

from dataclasses import dataclass

__all__ = ["PRIMITIVES", "Primitive"]


@dataclass(frozen=True)
class Primitive:
    name: str
    params: tuple[str, ...]
    meaning: str

    @property
    def arity(self) -> int:
        return len(self.params)


def _table(*rows: tuple[str, tuple[str, ...], str]) -> dict[str, Primitive]:
    return {name: Primitive(name, params, meaning) for name, params, meaning in rows}


PRIMITIVES: dict[str, Primitive] = _table(
    ("navigate", ("target",), "drive to a pose from which the target (place, room, object or person) is within reach"),
    ("approach", ("person",), "drive up to a person"),
    ("search", ("thing",), "look around until the thing is seen"),
    ("pick", ("object",), "grasp the object (hand empty, object within reach and not inside a closed place)"),
    ("place", ("object", "receptacle"), "put the held object in or on the receptacle (open if openable)"),
    ("place_on", ("object", "receptacle"), "put the held object on top of the receptacle (closed or not)"),
    ("hand_over", ("object", "person"), "give the held object to the person"),
    ("open", ("thing",), "open an openable thing within reach"),
    ("close", ("thing",), "close an openable thing within reach"),
    ("toggle_on", ("thing",), "switch a toggleable thing on"),
    ("toggle_off", ("thing",), "switch a toggleable thing off"),
    ("heat", ("object", "appliance"), "heat the held object with the appliance (a microwave, as in ALFRED)"),
    ("cool", ("object", "appliance"), "cool the held object in the appliance (a fridge)"),
    ("clean", ("object", "appliance"), "wash the held object at the appliance (a sink)"),
    ("slice", ("object", "tool"), "slice the object with the held tool (a knife)"),
    ("look_at", ("object",), "look at the object"),
    ("stir", ("tool", "container"), "stir the container's contents with the held tool"),
    ("pour", ("object", "container"), "pour the held object's contents into the container"),
    ("follow", ("person",), "follow the person until they stop"),
    ("lead", ("person", "target"), "ask the person to follow and drive to the target"),
    ("meet", ("person",), "introduce itself to the person and learn who they are"),
    ("greet", ("person",), "greet the person"),
    ("say", ("message",), "say the message aloud"),
    ("answer", ("question",), "listen to a question and answer it"),
    ("count", ("thing",), "count the things in view"),
    ("wait", (), "stay where it is, doing nothing, until it is told more (or the person waited for comes)"),
)
