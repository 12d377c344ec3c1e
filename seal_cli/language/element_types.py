"""The library's element types, asked the same few questions many times by the builder: memoised."""

from __future__ import annotations

from typing import Any

from seal_cli.frames.library import Library
from seal_cli.frames.model import Frame

__all__ = ["Types"]


class Types:
    """The library's taxonomy, asked the same few questions many times: memoised."""

    def __init__(self, library: Library) -> None:
        self.taxonomy = library.taxonomy
        self._is_a: dict[tuple[str, str], bool | None] = {}
        self._open: dict[str, bool] = {}
        self._roles: dict[str, frozenset[str]] = {}
        self._relations: dict[str, Any] = {}
        self._states: dict[str, bool] = {}
        self._evoked: dict[str, tuple[Frame, ...]] = {}
        self._objects: dict[str, str | None] = {}
        self._opening: dict[str, bool] = {}
        self._cutting: dict[str, tuple[Frame, str] | None] = {}
        self._person: dict[str, bool] = {}
        self._library = library

    def object_role(self, unit: str) -> str | None:
        """The element the unit's direct object fills in every frame it evokes, when its entry names one
        (``object: goal`` of "fill"), else None: the frame's first element, as for every other verb."""
        if unit not in self._objects:
            said = {u.object for f in self.evoked_by(unit) for u in f.lexical_units if u.text == unit}
            self._objects[unit] = next(iter(said)) if len(said) == 1 else None
        return self._objects[unit]

    def opening_only(self, unit: str) -> bool:
        """Whether every entry of the unit is ``opening`` (a word that is mostly a noun: "trash", "dust"), read as
        the verb only opening a clause before its object, so a noun in a bare phrase ("to *trash* can")."""
        if unit not in self._opening:
            said = [u.opening for f in self.evoked_by(unit) for u in f.lexical_units if u.text == unit]
            self._opening[unit] = bool(said) and all(said)
        return self._opening[unit]

    def evoked_by(self, unit: str) -> tuple[Frame, ...]:
        """The frames a lexical unit evokes (:meth:`Library.evoked_by`, memoised by unit)."""
        found = self._evoked.get(unit)
        if found is None:
            found = self._evoked[unit] = self._library.evoked_by(unit)
        return found

    def roles(self, frame: Frame) -> frozenset[str]:
        """The frame's element roles (asked for every phrase of every clause: memoised by name)."""
        found = self._roles.get(frame.name)
        if found is None:
            found = self._roles[frame.name] = frozenset(e.role for e in frame.elements)
        return found

    def makes_state(self, frame: Frame) -> bool:
        """Whether the frame's result is a state of its first element and it puts it nowhere (Slice:
        ``sliced(theme)``, no goal); memoised by name."""
        found = self._states.get(frame.name)
        if found is None:
            first = frame.elements[0].role if frame.elements else None
            found = self._states[frame.name] = "goal" not in self.roles(frame) and any(
                not p.negated and p.args == (first,) for p in frame.postconditions)
        return found

    def relation(self, frame: Frame) -> Any:
        """The frame's positive postcondition relating its first element to another
        (``in(theme, goal)``), or None; memoised by name."""
        if frame.name not in self._relations:
            first = frame.elements[0].role if frame.elements else None
            self._relations[frame.name] = next((p for p in frame.postconditions if not p.negated
                                                and len(p.args) == 2 and p.args[0] == first), None)
        return self._relations[frame.name]

    def cutting(self, noun: str) -> tuple[Frame, str] | None:
        """The frame that cuts a thing into pieces, and its lexical unit: the one the piece's noun
        names ("slice"), else the one of "cut", whose result is a state of its theme (``sliced``);
        memoised by noun."""
        if noun in self._cutting:
            return self._cutting[noun]
        found: tuple[Frame, str] | None = None
        for unit in (noun, "cut"):
            for frame in self.evoked_by(unit):
                first = frame.elements[0].role if frame.elements else None
                if any(not p.negated and p.args == (first,) for p in frame.postconditions):
                    found = (frame, unit)
                    break
            if found is not None:
                break
        if len(self._cutting) >= 4096:
            self._cutting.clear()
        self._cutting[noun] = found
        return found

    def is_a(self, cls: str, type_: str) -> bool | None:
        key = (cls, type_)
        if key not in self._is_a:
            self._is_a[key] = self.taxonomy.is_a(cls, type_)
        return self._is_a[key]

    def is_open(self, type_: str) -> bool:
        if type_ not in self._open:
            self._open[type_] = self.taxonomy.is_open(type_)
        return self._open[type_]

    def is_person(self, type_: str) -> bool:
        """A type only people belong to (``person``); memoised by type."""
        found = self._person.get(type_)
        if found is None:
            found = self._person[type_] = self.is_a("person", type_) is True and not self.is_open(type_)
        return found

    def is_location(self, type_: str) -> bool:
        """A type rooms belong to (``location``): where things are, not what they are."""
        return not self.is_open(type_) and self.is_a("room", type_) is True
