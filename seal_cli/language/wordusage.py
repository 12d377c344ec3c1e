"""Which class people mean by a word: grounding statistics learned from a train split.

The rules of :mod:`seal_cli.language.grounding` read a phrase's words against class names;
they cannot know that people who say "the sink" in an AI2-THOR kitchen mean its ``SinkBasin``,
"the chair" in a living room its ``ArmChair``, or "a knife" the ``ButterKnife`` more often than
the ``Knife``. A :class:`WordUsage` table holds, for each wording (a noun phrase's head, and its
last modifier with the head), how often people meant each class, counted on a train split
(``scripts/build_word_classes.py`` rebuilds the shipped table from ALFRED's train goals).

Grounding asks it among the classes *present* (the vocabulary: a scene's classes, or all
classes when no scene is known), so "the table" in a room with a side table and no dining table
is the side table even when dining tables are the more usual meaning. In a scene
(``Vocabulary.restricted_to``) a class is judged by how often people meant it when it was
there (:attr:`WordUsage.seen`), not by how often it was meant anywhere. The rules stay in charge
unless the data is clear (:meth:`WordUsage.choose`): at least ``MIN_SUPPORT`` observations of
the wording among the present classes, at least ``MIN_SUPPORT`` people who meant the learned
class, and that class meant at least ``MIN_RATIO`` times as often as the class the rules found
(half of the present classes' share when the rules found none). A class the statistics never
saw (no class of the split's vocabulary: a GPSR arena's "table") is never overridden.

Tables are JSON files (``format: seal-word-classes/1``) in the folder ``word_classes/`` beside
this module; every file there is read and their counts are added.
"""

from __future__ import annotations

from collections.abc import Iterable, Mapping
from dataclasses import dataclass, field
from functools import cache, cached_property
from pathlib import Path
from types import MappingProxyType
from typing import Any

from seal_cli.errors import SealError, Where
from seal_cli.frames.taxonomy import class_key

__all__ = ["FORMAT", "MIN_RATIO", "MIN_SUPPORT", "SHIPPED", "WordUsage", "load_word_usage", "shipped_word_usage",
           "unsaid_wording"]

FORMAT = "seal-word-classes/1"
SHIPPED = Path(__file__).resolve().parent / "word_classes"
MIN_SUPPORT = 5
"""Observations of a wording (among the present classes) below which the rules decide alone."""
MIN_RATIO = 1.2
"""How many times as often the learned class must be meant as the rules' class to replace it
(chosen on train trials held out from the counts: 1.0–1.2 scored best, 1.5–3 about 0.6 points lower)."""


def unsaid_wording(frame: str, role: str, unit: str) -> str:
    """The table's key for an element a clause leaves unsaid: which class people meant as the ``role``
    of ``frame`` when they used the lexical unit ``unit`` and did not say it ("throw away the towel":
    the goal of Place by "throw away"). No noun phrase's lemmas contain ``<-``, so it cannot collide;
    lower case, as the table's wordings are read."""
    return " ".join(f"{frame}.{role} <- {unit}".lower().split())


@dataclass(frozen=True)
class WordUsage:
    """Counts of the class meant, by wording (lemmas joined by spaces), over a known set of classes.

    ``counts[wording][class key]``; ``universe`` the class keys the counts were taken over (the
    split's vocabulary): only a class among them can be overridden by the statistics."""

    counts: Mapping[str, Mapping[str, int]] = field(default_factory=dict)
    universe: frozenset[str] = frozenset()
    sources: tuple[str, ...] = ()
    min_support: int = MIN_SUPPORT
    min_ratio: float = MIN_RATIO
    seen: Mapping[str, Mapping[str, int]] = field(default_factory=dict)
    """``seen[wording][class key]``: how often the wording was said in a scene that held the class.
    In a scene, a class is judged by its rate (``counts / seen``): how often people mean it when it
    is there, not how often it is there."""

    def __post_init__(self) -> None:
        for name in ("counts", "seen"):
            table = getattr(self, name)
            object.__setattr__(self, name, MappingProxyType({w: MappingProxyType(dict(c)) for w, c in table.items()}))

    def __bool__(self) -> bool:
        return bool(self.counts)

    def merged(self, other: WordUsage) -> WordUsage:
        """The two tables' counts added."""
        def add(mine: Mapping[str, Mapping[str, int]], theirs: Mapping[str, Mapping[str, int]]) -> dict:
            out: dict[str, dict[str, int]] = {w: dict(c) for w, c in mine.items()}
            for key, by in theirs.items():
                row = out.setdefault(key, {})
                for name, n in by.items():
                    row[name] = row.get(name, 0) + n
            return out

        return WordUsage(add(self.counts, other.counts), self.universe | other.universe,
                         self.sources + other.sources, self.min_support, self.min_ratio,
                         add(self.seen, other.seen))

    @cached_property
    def _meant(self) -> frozenset[str]:
        return frozenset(key for by_class in self.counts.values() for key in by_class)

    def meant(self, cls: str | None) -> bool:
        """Whether anybody in the counts meant this class (by any wording): a class nobody meant (THOR's
        ``ToiletPaperRoll``, beside the ``ToiletPaper`` people call a roll) is no evidence against the data."""
        return cls is not None and class_key(cls) in self._meant

    def choose(self, lemmas: tuple[str, ...], present: Mapping[str, str], rule: str | None,
               scene: bool = False) -> str | None:
        """The class meant by a phrase whose words up to the head are ``lemmas``, among ``present``
        (class key → the vocabulary's spelling), given what the rules found (``rule``, or None).
        ``scene``: the present classes are those of one scene (compare rates, see :attr:`seen`);
        otherwise any (compare counts: how often each is meant, wherever).

        The longest wording with support decides: the last modifier and the head, else the head. A
        wording shorter than the class name the rules matched in the phrase ("coffee table" →
        ``CoffeeTable``; "table" alone favours dining tables) keeps the rules' class."""
        if not self.counts or not lemmas:
            return rule
        rule_key = class_key(rule) if rule is not None else None
        if rule_key is not None and rule_key not in self.universe:
            return rule                                   # a class the statistics never saw
        for size in (2, 1):
            if len(lemmas) < size:
                continue
            by_class = self.counts.get(" ".join(lemmas[-size:]))
            if not by_class:
                continue
            seen = [(n, key) for key, n in by_class.items() if key in present]
            support = sum(n for n, _ in seen)
            if support < self.min_support:
                continue
            if rule_key is not None and size < len(rule_key.split("_")) \
                    and set(rule_key.split("_")) <= set(lemmas):
                return rule                               # the rules matched more of the phrase
            wording = " ".join(lemmas[-size:])
            scored = self._scored(wording, seen) if scene else [(float(n), key) for n, key in seen]
            total = sum(s for s, _ in scored)
            s_best, best = max(scored, key=lambda s: (s[0], s[1] == rule_key))
            s_rule = next((s for s, key in scored if key == rule_key), 0.0)
            if by_class[best] < self.min_support:
                return rule                               # too few people meant it to say
            if rule_key is None:                          # nothing the rules found: the clear majority
                return present[best] if 2 * s_best >= total else None
            if best != rule_key and s_best >= self.min_ratio * s_rule:
                return present[best]
            return rule
        return rule


    def _scored(self, wording: str, seen: list[tuple[int, str]]) -> list[tuple[float, str]]:
        """Each class's rate: how often the wording meant it, of the times it was said where the
        class was (a class with no record of that keeps its count's share)."""
        times = self.seen.get(wording, {})
        return [(n / times[key] if times.get(key) else float(n) / max(sum(m for m, _ in seen), 1), key)
                for n, key in seen]


def _table(data: Any, where: Where) -> WordUsage:
    if not isinstance(data, dict) or data.get("format") != FORMAT:
        raise SealError(f"not a word-class table (expected \"format\": \"{FORMAT}\")", where)
    classes, words = data.get("classes"), data.get("words")
    if not isinstance(classes, list) or not all(isinstance(c, str) and c for c in classes):
        raise SealError("\"classes\" must be a list of class names", where)
    if not isinstance(words, dict):
        raise SealError("\"words\" must map each wording to {class: count}", where)
    universe = frozenset(class_key(c) for c in classes)
    counts: dict[str, dict[str, int]] = {}
    for wording, by_class in words.items():
        if not isinstance(by_class, dict) or not all(
                isinstance(c, str) and isinstance(n, int) and not isinstance(n, bool) and n > 0
                for c, n in by_class.items()):
            raise SealError(f"wording {wording!r}: expected {{class: positive count}}", where)
        unknown = [c for c in by_class if class_key(c) not in universe]
        if unknown:
            raise SealError(f"wording {wording!r}: class {unknown[0]!r} is not in \"classes\"", where)
        counts[" ".join(str(wording).lower().split())] = {class_key(c): n for c, n in by_class.items()}
    seen: dict[str, dict[str, int]] = {}
    raw = data.get("seen", {})
    if not isinstance(raw, dict):
        raise SealError("\"seen\" must map each wording to {class: times said where the class was}", where)
    for wording, by_class in raw.items():
        if not isinstance(by_class, dict) or not all(
                isinstance(c, str) and class_key(c) in universe and isinstance(n, int) and not isinstance(n, bool)
                and n > 0 for c, n in by_class.items()):
            raise SealError(f"seen {wording!r}: expected {{class of \"classes\": positive count}}", where)
        seen[" ".join(str(wording).lower().split())] = {class_key(c): n for c, n in by_class.items()}
    return WordUsage(counts, universe, (str(data.get("source", where.file)),), seen=seen)


def load_word_usage(paths: Iterable[str | Path]) -> WordUsage:
    """The word-class tables in these files (or folders of ``*.json``), their counts added."""
    import json

    from seal_cli.fileio import read_text

    usage = WordUsage()
    for path in paths:
        path = Path(path)
        for file in sorted(path.glob("*.json")) if path.is_dir() else [path]:
            where = Where(str(file))
            try:
                data = json.loads(read_text(file))
            except json.JSONDecodeError as err:
                raise SealError(f"not JSON: {err.msg}", Where(str(file), err.lineno, err.colno)) from None
            usage = usage.merged(_table(data, where))
    return usage


@cache
def shipped_word_usage() -> WordUsage:
    """The tables shipped with seal (``seal_cli/language/word_classes/``), read once."""
    return load_word_usage([SHIPPED]) if SHIPPED.is_dir() else WordUsage()
