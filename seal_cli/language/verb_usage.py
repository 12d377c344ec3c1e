"""How likely a word form is used as a verb: P(verb | form), from WordNet's sense tag counts.

The shipped table (``verb_usage.tsv`` beside this module) is derived from WordNet 3.0's SemCor tag counts by
``scripts/build_verb_usage.py``, which rebuilds it; the parser never reads WordNet itself. Where nothing else tells
a verb from a noun — a bare word after "and": "go to the kitchen and *wait* there" against "bring the cup and
*plate*" — the tagger asks :func:`verb_share`: "wait" 0.969, "plate" 0.030, "pepper" 0.500.
"""

from __future__ import annotations

from functools import cache, lru_cache
from pathlib import Path

__all__ = ["MIN_VERB_TAGS", "SHIPPED", "VERB_SHARE", "mostly_verb", "verb_share", "verb_tags"]

SHIPPED = Path(__file__).resolve().parent / "verb_usage.tsv"
VERB_SHARE = 0.6
"""How likely a form must be used as a verb to be read as one where nothing else tells (:func:`mostly_verb`):
"wait" 0.969, "dance" 0.610 are; "pepper" 0.500, "fork" 0.235, "plate" 0.030 are not. Chosen on every corpus we
have (docs/language.md, words14): 0.5 to 0.8 change the same parses there; 0.6 keeps "pepper" (0.500) a noun and
"dance" (0.610) a verb."""
MIN_VERB_TAGS = 1
"""How often the form must have been seen used as a verb (:func:`verb_tags`): a form never tagged has a share
from its numbers of senses only ("the toilet paper and *spool*": 0.667, never tagged)."""


@cache
def _table() -> dict[str, tuple[float, int]]:
    table: dict[str, tuple[float, int]] = {}
    for line in SHIPPED.read_text(encoding="utf-8").splitlines():
        if line and not line.startswith("#"):
            form, share, verb_tags, _ = line.split("\t")
            table[form] = (float(share), int(verb_tags))
    return table


def verb_share(form: str) -> float:
    """P(verb | form) for a lower-case word form: 0.0 for a form WordNet knows no verb sense of."""
    return _table().get(form, (0.0, 0))[0]


def verb_tags(form: str) -> int:
    """How often SemCor's taggers saw a lower-case word form used as a verb (0: never, or no verb sense): how much
    evidence :func:`verb_share` rests on ("spool": two verb senses and one noun sense, never tagged)."""
    return _table().get(form, (0.0, 0))[1]


@lru_cache(maxsize=65536)
def mostly_verb(form: str) -> bool:
    """Whether a lower-case word form is used mostly as a verb, on evidence: a share of at least
    :data:`VERB_SHARE`, from at least :data:`MIN_VERB_TAGS` tags as a verb."""
    return verb_share(form) >= VERB_SHARE and verb_tags(form) >= MIN_VERB_TAGS
