"""Which nouns name a part of a home or a building one goes to: a room, a hallway, a floor, a garage, a porch, a
garden (:func:`is_premises`).

The shipped list (``premises.txt`` beside this module) is derived from WordNet 3.0's noun hierarchy by
``scripts/build_room_nouns.py``, which rebuilds it; the parser never reads WordNet itself. A command said as a
bare phrase asks to go there when the phrase names such a place ("kitchen, now") and for the thing otherwise
("towel. bathroom. quick"; :mod:`seal_cli.language.rules.telegraphic`).
"""

from __future__ import annotations

from functools import cache
from pathlib import Path

__all__ = ["SHIPPED", "is_premises"]

SHIPPED = Path(__file__).resolve().parent / "premises.txt"


@cache
def _nouns() -> frozenset[str]:
    return frozenset(line.strip() for line in SHIPPED.read_text(encoding="utf-8").splitlines()
                     if line.strip() and not line.startswith("#"))


def is_premises(noun: str) -> bool:
    """Whether a noun's lemma, in lower case, names a room or a part of a building ("kitchen", "hall", "garage")."""
    return noun in _nouns()
