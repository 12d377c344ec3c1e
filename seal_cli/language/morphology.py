"""Lemmas, singulars and inflections of English words, from lemminflect's dictionaries.

lemminflect ships two lookup tables (``lemma_lu.csv.gz``: word → lemmas by part of speech;
``infl_lu.csv.gz``: lemma → inflected forms) and a learned model for words they lack. Its own
loader turns each table into Python dictionaries, which takes most of a second; ``seal parse``
starts many times a minute from scripts, so this module reads the same tables as sorted lines
and looks words up by bisection (a few milliseconds to open). A noun the tables lack ("cheezits")
is kept as written (grounding then also tries it without a plural ending); a verb they lack gets
its forms from lemminflect's model, imported only then.

    word table line:  ``knives,noun,knife``            (word, category, lemmas separated by /)
    lemma table line: ``light,verb,lit/lighted,lit,lighting,lights``   (VBD, VBN, VBG, VBZ)
"""

from __future__ import annotations

import bisect
import gzip
import importlib.util
from functools import lru_cache
from pathlib import Path

__all__ = ["gerund_lemma", "is_adjective", "is_adverb", "is_gradable", "is_plural", "noun_lemma", "participles",
           "verb_lemma"]


class _Table:
    """A lemminflect table as sorted lines, looked up by word."""

    def __init__(self, name: str) -> None:
        self.name = name
        self._lines: list[str] | None = None

    @property
    def lines(self) -> list[str]:
        if self._lines is None:
            spec = importlib.util.find_spec("lemminflect")
            folder = Path(next(iter(spec.submodule_search_locations or ()))) if spec else Path()
            with gzip.open(folder / "resources" / self.name, "rt", encoding="utf-8") as handle:
                lines = handle.read().split("\n")
            lines.sort()
            self._lines = lines
        return self._lines

    def entries(self, word: str) -> list[list[str]]:
        """``[category, field, ...]`` for each line of ``word``."""
        lines = self.lines
        key = word + ","
        found = []
        i = bisect.bisect_left(lines, key)
        while i < len(lines) and lines[i].startswith(key):
            found.append(lines[i][len(key):].split(","))
            i += 1
        return found


_WORDS = _Table("lemma_lu.csv.gz")
_LEMMAS = _Table("infl_lu.csv.gz")


def _lemmas(word: str, category: str) -> tuple[str, ...]:
    for entry in _WORDS.entries(word):
        if entry[0] == category and len(entry) > 1:
            return tuple(entry[1].split("/"))
    return ()


_SUPPLETIVE = {"people": "person"}
"""English's suppletive plural, which lemminflect's table lists only as a noun of its own ("peoples")."""


@lru_cache(maxsize=65536)
def noun_lemma(word: str) -> str:
    """The singular of a noun (``"knives"`` → ``"knife"``, ``"people"`` → ``"person"``); lower case."""
    lower = word.lower()
    if len(lower) <= 2 or not lower.isalpha():
        return lower
    if lower in _SUPPLETIVE:
        return _SUPPLETIVE[lower]
    lemmas = _lemmas(lower, "noun")
    if not lemmas:
        verb = _lemmas(lower, "verb")       # "bars": listed only as a verb form; its noun is "bar"
        if verb and lower.endswith("s") and verb[0] in (lower[:-1], lower[:-2]):
            return verb[0]
        return lower        # a word the dictionary lacks ("cheezits") stays as it is
    if lower in lemmas and (not lower.endswith("s") or lower.endswith("ss") or len(lemmas) == 1):
        return lower                            # "people", "glass"; but "glasses" → "glass"
    return lemmas[0]


@lru_cache(maxsize=65536)
def is_plural(word: str) -> bool:
    """Whether a noun is plural ("apples", "people", "knives")."""
    lower = word.lower()
    if lower in ("people", "persons", "children", "men", "women"):
        return True
    return noun_lemma(lower) != lower


@lru_cache(maxsize=65536)
def verb_lemma(word: str) -> str | None:
    """The verb a word is a form of (``"heated"`` → ``"heat"``), or None."""
    lemmas = _lemmas(word.lower(), "verb")
    return lemmas[0] if lemmas else None


@lru_cache(maxsize=65536)
def gerund_lemma(word: str) -> str | None:
    """The verb of an -ing form (``"wearing"`` → ``"wear"``), or None."""
    lower = word.lower()
    if not lower.endswith("ing") or len(lower) < 5:
        return None
    return verb_lemma(lower)


@lru_cache(maxsize=65536)
def in_dictionary(word: str) -> bool:
    """Whether lemminflect lists the word at all (as a noun, verb, adjective or adverb): a person's
    name mostly is not ("jamie", "priya"; "robin" is a bird too)."""
    return bool(_WORDS.entries(word.lower()))


@lru_cache(maxsize=65536)
def is_adjective(word: str) -> bool:
    """Whether lemminflect lists the word as an adjective ("hot", "clean")."""
    return any(entry[0] == "adj" for entry in _WORDS.entries(word.lower()))


@lru_cache(maxsize=65536)
def is_adverb(word: str) -> bool:
    """Whether lemminflect lists the word as an adverb and as nothing else ("together",
    "carefully"; not "upright", also an adjective and a noun)."""
    entries = _WORDS.entries(word.lower())
    return bool(entries) and all(entry[0] == "adv" for entry in entries)


@lru_cache(maxsize=4096)
def is_gradable(word: str) -> bool:
    """Whether the word is an adjective with comparative forms ("warm": warmer, warmest), i.e. it
    names a state a thing can be more or less in ("wash" is listed as an adjective, but not so)."""
    return any(entry[0] == "adj" and len(entry) > 1 and entry[1] for entry in _LEMMAS.entries(word.lower()))


def in_verb_tables(word: str) -> bool:
    """Whether lemminflect's shipped tables list the word as a verb with its past forms (so its
    participles need no model: :func:`participles` reads them there)."""
    return any(entry[0] == "verb" and len(entry) >= 3 for entry in _LEMMAS.entries(word.lower()))


@lru_cache(maxsize=4096)
def participles(verb: str) -> frozenset[str]:
    """Past forms and past participles of a verb: ``light`` → {lit, lighted}, ``cut`` → {cut}."""
    for entry in _LEMMAS.entries(verb.lower()):
        if entry[0] == "verb" and len(entry) >= 3:
            return frozenset(f for field in entry[1:3] for f in field.split("/") if f)
    import lemminflect

    forms = lemminflect.getAllInflectionsOOV(verb, upos="VERB")
    return frozenset(f.lower() for tag in ("VBN", "VBD") for f in forms.get(tag, ()))
