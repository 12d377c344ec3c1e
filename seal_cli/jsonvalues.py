"""Parsed JSON read with checks: every value knows its path in the document (``objects[3].position``) and
where the document is (a file, and the line of a JSON Lines record), so a value of the wrong type, a
missing key or a number that is not finite is one :class:`~seal_cli.errors.SealError` naming both —
never a ``KeyError`` or ``AttributeError`` from deep inside a reader.

    trial = Value(json.loads(line), "trial", Where("trials.jsonl", 12))
    x, y, z = trial["objects"][0]["position"].numbers(3)
    # trials.jsonl:12: trial.objects[0].position must be a list of 3 finite numbers, not [1, "a"]
"""

from __future__ import annotations

import math
from collections.abc import Iterator
from typing import Any

from seal_cli.errors import SealError, Where

__all__ = ["Value", "kind"]


def kind(value: Any) -> str:
    """What a JSON value is, in words, with a short excerpt: ``a string ('abc')``, ``a list of 2``."""
    if value is None:
        return "null"
    if isinstance(value, bool):
        return f"a boolean ({str(value).lower()})"
    if isinstance(value, (int, float)):
        return f"the number {value!r}"
    if isinstance(value, str):
        shown = value if len(value) <= 40 else value[:39] + "…"
        return f"a string ({shown!r})"
    if isinstance(value, list):
        return f"a list of {len(value)}"
    if isinstance(value, dict):
        return f"an object of {len(value)} key{'s' if len(value) != 1 else ''}"
    return type(value).__name__


class Value:
    """One value of a parsed JSON document, its path in it, and where the document is."""

    def __init__(self, value: Any, path: str, where: Where) -> None:
        self.raw = value
        self.path = path
        self.where = where

    def problem(self, message: str) -> SealError:
        """A SealError about this value: ``file:line: path message`` (the document itself when its path is
        empty: ``file: the file must be ...``)."""
        return SealError(f"{self.path or 'the file'} {message}", self.where)

    def _child(self, key: str | int) -> str:
        if isinstance(key, int):
            return f"{self.path}[{key}]"
        return f"{self.path}.{key}" if self.path else key

    def _must(self, what: str) -> SealError:
        return self.problem(f"must be {what}, not {kind(self.raw)}")

    # -- containers ---------------------------------------------------------------------------------
    def _mapping(self) -> dict[str, Any]:
        if not isinstance(self.raw, dict):
            raise self._must("an object ({...})")
        return self.raw

    def __getitem__(self, key: str) -> Value:
        """The value at ``key`` of an object; a missing key is a problem."""
        mapping = self._mapping()
        if key not in mapping:
            raise self.problem(f"has no {key!r}")
        return Value(mapping[key], self._child(key), self.where)

    def get(self, key: str) -> Value | None:
        """The value at ``key`` of an object, or None where it is missing or null."""
        mapping = self._mapping()
        if mapping.get(key) is None:
            return None
        return Value(mapping[key], self._child(key), self.where)

    def items(self) -> Iterator[tuple[str, Value]]:
        """The keys and values of an object."""
        for key, value in self._mapping().items():
            yield key, Value(value, self._child(key), self.where)

    def list(self) -> list[Value]:
        """The items of a list."""
        if not isinstance(self.raw, list):
            raise self._must("a list")
        return [Value(v, self._child(k), self.where) for k, v in enumerate(self.raw)]

    # -- scalars ------------------------------------------------------------------------------------
    def text(self) -> str:
        """A string."""
        if not isinstance(self.raw, str):
            raise self._must("a string")
        return self.raw

    def texts(self) -> tuple[str, ...]:
        """A list of strings."""
        return tuple(v.text() for v in self.list())

    def number(self) -> float:
        """A finite number (not a boolean)."""
        if isinstance(self.raw, bool) or not isinstance(self.raw, (int, float)):
            raise self._must("a number")
        number = float(self.raw)
        if not math.isfinite(number):
            raise self._must("a finite number")
        return number

    def numbers(self, count: int | None = None) -> tuple[float, ...]:
        """A list of ``count`` finite numbers (any number of them if None)."""
        what = f"a list of {count} finite numbers" if count is not None else "a list of finite numbers"
        if not isinstance(self.raw, list) or (count is not None and len(self.raw) != count):
            raise self._must(what)
        return tuple(v.number() for v in self.list())

    def integer(self) -> int:
        """An integer (not a boolean; 3.0 is not one)."""
        if isinstance(self.raw, bool) or not isinstance(self.raw, int):
            raise self._must("an integer")
        return self.raw

    def flag(self) -> bool:
        """A boolean."""
        if not isinstance(self.raw, bool):
            raise self._must("true or false")
        return self.raw
