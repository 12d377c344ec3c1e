"""How beliefs are written for people: one formatter for the tables and the pictures.

A share (a room's mass, a mode's weight) is shown with two decimals, rounded half up from the
number as the JSON output writes it (three decimals). The table of ``seal localize`` formats the
JSON and the PNG formats the beliefs themselves; both go through :func:`share`, so 0.845 reads
0.85 in both (Python's ``f"{0.845:.2f}"`` gives 0.84: the float is just below 0.845).
"""

from __future__ import annotations

from collections.abc import Iterable, Mapping
from decimal import ROUND_HALF_UP, Decimal
from typing import Any

__all__ = ["JSON_DIGITS", "metres", "modes_text", "point", "rooms_text", "share"]

JSON_DIGITS = 3
"""Decimals of the shares in JSON output (:meth:`seal_cli.sefm.modes.Summary.to_json`)."""


def _half_up(value: float, places: int) -> str:
    written = Decimal(repr(round(float(value), JSON_DIGITS)))
    return str(written.quantize(Decimal(1).scaleb(-places), rounding=ROUND_HALF_UP))


def share(value: float) -> str:
    """A mass or weight in [0, 1], two decimals (``0.845`` → ``"0.85"``)."""
    return _half_up(value, 2)


def metres(value: float) -> str:
    """A coordinate in metres, two decimals, rounded like :func:`share`."""
    return _half_up(value, 2)


def point(p: Iterable[float]) -> str:
    """``(x, y)`` in metres."""
    x, y = list(p)[:2]
    return f"({metres(x)}, {metres(y)})"


def rooms_text(rooms: Mapping[str, float], top: int = 3) -> str:
    """The ``top`` rooms by mass, ``"kitchen 0.49, bedroom 0.47"`` (masses that show as 0.00 left out)."""
    best = sorted(rooms.items(), key=lambda kv: -kv[1])[:top]
    return ", ".join(f"{name} {share(mass)}" for name, mass in best if share(mass) != "0.00")


def modes_text(modes: Iterable[Mapping[str, Any]], top: int = 3) -> str:
    """Modes (JSON dicts with ``weight`` and ``room``), ``"0.48 bedroom, 0.29 kitchen"``."""
    return ", ".join(f"{share(m['weight'])} {m['room']}" for m in list(modes)[:top])
