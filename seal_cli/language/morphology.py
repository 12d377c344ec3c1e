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
import mmap
from functools import lru_cache
from pathlib import Path

__all__ = ["adverb_no_noun", "counted", "gerund_lemma", "is_adjective", "is_adverb", "is_gradable", "is_plural",
           "inflected", "noun_lemma", "participles", "parts_of_speech", "plural_of", "verb_lemma"]


class _Table:
    """A lemminflect table as sorted lines, looked up by word by bisection.

    The sorted lines are kept in seal's cache (:mod:`seal_cli.cache`) and looked up there in place,
    mapped into memory: a new process opens them in microseconds instead of decompressing and
    sorting the table (~30 ms). Without a usable cache they are sorted in memory, as they are to
    make the entry; the lines found are the same either way."""

    def __init__(self, name: str) -> None:
        self.name = name
        self._lines: list[str] | None = None
        self._mapped: tuple[mmap.mmap, int] | None = None
        self._tried = False

    def _source(self) -> Path:
        spec = importlib.util.find_spec("lemminflect")
        folder = Path(next(iter(spec.submodule_search_locations or ()))) if spec else Path()
        return folder / "resources" / self.name

    @property
    def lines(self) -> list[str]:
        """The table's lines, sorted (read from lemminflect's file)."""
        if self._lines is None:
            with gzip.open(self._source(), "rt", encoding="utf-8") as handle:
                lines = handle.read().split("\n")
            lines.sort()
            self._lines = lines
        return self._lines

    def _sorted(self) -> tuple[mmap.mmap, int] | None:
        """The sorted lines as one buffer (each line ending in a newline) and where they start: the
        cache's entry, made when missing or stale; None when the cache cannot be used."""
        if not self._tried:
            self._tried = True
            from seal_cli import __version__, cache

            source = self._source()
            try:
                info = source.stat()
            except OSError:
                return None
            stamp = cache.digest(__version__.encode(), str(source).encode(), str(info.st_size).encode(),
                                 str(info.st_mtime_ns).encode(), _FORMAT)
            name = f"words-{self.name.split('.')[0]}-{cache.digest(str(source).encode())[:16]}.txt"
            found = cache.read_mapped(name, stamp)
            if found is None:
                cache.write(name, stamp, "".join(line + "\n" for line in self.lines).encode("utf-8"))
                found = cache.read_mapped(name, stamp)
            self._mapped = found
            if found is not None:
                self._lines = None  # looked up in the entry from now on
        return self._mapped

    def entries(self, word: str) -> list[list[str]]:
        """``[category, field, ...]`` for each line of ``word``."""
        mapped = self._sorted()
        if mapped is None:
            return self._entries_in_memory(word)
        data, lo = mapped
        if "\n" in word:  # no line holds one (in memory, none would be found either)
            return []
        key = (word + ",").encode("utf-8")
        hi = len(data)
        while lo < hi:  # the first line >= key: lines wholly before lo are < key, lines from hi on are >= key
            mid = (lo + hi) // 2
            start = data.rfind(b"\n", lo, mid) + 1 or lo
            end = data.find(b"\n", start)
            if data[start:end] < key:
                lo = end + 1
            else:
                hi = start
        found = []
        while data[lo:lo + len(key)] == key:
            end = data.find(b"\n", lo)
            found.append(data[lo + len(key):end].decode("utf-8").split(","))
            lo = end + 1
        return found

    def _entries_in_memory(self, word: str) -> list[list[str]]:
        lines = self.lines
        key = word + ","
        found = []
        i = bisect.bisect_left(lines, key)
        while i < len(lines) and lines[i].startswith(key):
            found.append(lines[i][len(key):].split(","))
            i += 1
        return found


_FORMAT = b"sorted lines 1"
"""The layout of the cached tables (part of their stamp: a new layout makes new entries)."""


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


@lru_cache(maxsize=4096)
def plural_only(word: str) -> bool:
    """Whether a noun has a plural form only ("scissors", "jeans", "pliers", "pyjamas"): lemminflect's tables give
    the word itself as both its singular and its plural, and it ends in "s" as a plural does (not "glass", whose
    plural is "glasses"; nor "sheep", whose form ends in no "s"). It is taken up by "them" as a plural is ("the
    scissors are on the table, bring them to me", words26)."""
    import lemminflect

    lower = word.lower()
    forms = lemminflect.getAllInflections(lower, upos="NOUN")
    return lower.endswith("s") and not lower.endswith("ss") and forms.get("NN") == (lower,) and \
        forms.get("NNS") == (lower,)


@lru_cache(maxsize=65536)
def verb_lemma(word: str) -> str | None:
    """The verb a word is a form of (``"heated"`` → ``"heat"``), or None."""
    lemmas = _lemmas(word.lower(), "verb")
    return lemmas[0] if lemmas else None


def inflected(low: str) -> bool:
    """Whether a word is a verb's third-person or past form ("likes", "left", "locked"), not its base or -ing form."""
    lemma = verb_lemma(low) if low.isalpha() else None
    return bool(lemma) and lemma != low and not low.endswith("ing")


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
    return "adj" in parts_of_speech(word)


@lru_cache(maxsize=65536)
def is_adverb(word: str) -> bool:
    """Whether lemminflect lists the word as an adverb and as nothing else ("together",
    "carefully"; not "upright", also an adjective and a noun)."""
    return parts_of_speech(word) == {"adv"}


@lru_cache(maxsize=65536)
def parts_of_speech(word: str) -> frozenset[str]:
    """The parts of speech lemminflect lists the word as ("adj", "adv", "noun", "verb", ...)."""
    return frozenset(entry[0] for entry in _WORDS.entries(word.lower()))


@lru_cache(maxsize=65536)
def adverb_no_noun(word: str) -> bool:
    """Whether lemminflect lists the word as an adverb and never as a noun, whatever else ("just",
    "directly"; not "right" or "supply", nouns too)."""
    kinds = parts_of_speech(word)
    return "adv" in kinds and "noun" not in kinds


@lru_cache(maxsize=4096)
def is_gradable(word: str) -> bool:
    """Whether the word is an adjective with comparative forms ("warm": warmer, warmest), i.e. it
    names a state a thing can be more or less in ("wash" is listed as an adjective, but not so)."""
    return any(entry[0] == "adj" and len(entry) > 1 and entry[1] for entry in _LEMMAS.entries(word.lower()))


@lru_cache(maxsize=65536)
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


@lru_cache(maxsize=4096)
def plural_of(noun: str) -> str:
    """The plural of a noun said in words, its last word inflected by lemminflect's tables ("box": "boxes", "ice
    cream": "ice creams", "shelf": "shelves"); a word the tables do not know takes an "s" (e2e27: a count said "2
    boxs")."""
    import lemminflect

    *first, last = noun.split(" ")
    forms = lemminflect.getInflection(last, tag="NNS", inflect_oov=True) if last else ()
    return " ".join([*first, forms[0] if forms else last + "s"])


def counted(n: int, noun: str) -> str:
    """A number and its noun, plural unless one ("1 cup", "2 boxes", "0 ice creams")."""
    return f"{n} {noun if n == 1 else plural_of(noun)}"
