"""How likely a verb is said with a direct object: P(object | verb), from WordNet's verb frames.

The shipped table (``verb_objects.tsv`` beside this module) is derived from WordNet 3.0's sentence frames and SemCor
tag counts by ``scripts/build_verb_objects.py``, which rebuilds it; the parser never reads WordNet itself. Where a
participle could take the noun phrase after it or leave it to the clause's verb ("bring the kid who's *crying* his
teddy": the teddy is what is brought), the tagger asks :func:`takes_object`: "cry" 0.327, "wait" 0.447, "wear" 0.992.
"""

from __future__ import annotations

from functools import cache
from pathlib import Path

__all__ = ["OBJECT_SHARE", "SHIPPED", "object_share", "takes_object"]

SHIPPED = Path(__file__).resolve().parent / "verb_objects.tsv"
OBJECT_SHARE = 0.5
"""How likely a verb must be said with an object to take the noun phrase after its participle where the clause's
verb could take it too (:func:`takes_object`): "wear" 0.992, "hold" 0.969 do; "wait" 0.447, "cry" 0.327 do not."""


@cache
def _table() -> dict[str, float]:
    table: dict[str, float] = {}
    for line in SHIPPED.read_text(encoding="utf-8").splitlines():
        if line and not line.startswith("#"):
            verb, share, _ = line.split("\t")
            table[verb] = float(share)
    return table


def object_share(verb: str) -> float | None:
    """P(object | verb) for a lower-case verb lemma; None for a verb WordNet does not list."""
    return _table().get(verb)


def takes_object(verb: str) -> bool:
    """Whether a verb lemma is mostly said with a direct object (a verb WordNet does not list: yes, as before)."""
    share = object_share(verb)
    return share is None or share >= OBJECT_SHARE
