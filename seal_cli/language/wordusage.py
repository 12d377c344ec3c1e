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

**The rest of the sentence.** The same word means different classes in different sentences: a
"cup" put in the coffee machine is more often a ``Mug``, the "table" where a lamp is turned on a
``SideTable``. A table may also count, for each wording and class, the other words of the
sentences that meant it (:attr:`WordUsage.context`, the words of :func:`context_words`, and over
all wordings of a class: :attr:`WordUsage.class_context`); each class's count (or rate) is then
weighed by how much more often than the wording's other classes its sentences held the words of
this one, a naive Bayes factor damped by ``CONTEXT_WEIGHT`` (:meth:`WordUsage.context_factor`),
before the same thresholds decide. A table with ``weights`` (the shipped one) weighs the sentence by
the discriminative chooser of :mod:`seal_cli.language.chooser` instead (:meth:`WordUsage.sentence_factor`).
In a scene, a table with ``scene_weights`` also weighs each candidate by the other classes the room holds
(:meth:`WordUsage.scene_factor`: "the table" of a room with a bed leans to its side table).

Tables are JSON files (``format: seal-word-classes/1``) in the folder ``word_classes/`` beside
this module; every file there is read and their counts are added.
"""

from __future__ import annotations

import math
import re
from collections.abc import Callable, Iterable, Mapping
from dataclasses import dataclass, field
from functools import cache, cached_property
from pathlib import Path
from types import MappingProxyType
from typing import Any

from seal_cli.errors import SealError, Where
from seal_cli.frames.taxonomy import class_key
from seal_cli.language.chooser import features, logits, scene_features
from seal_cli.language.goals import NOWHERE, GoalModel
from seal_cli.language.morphology import noun_lemma
from seal_cli.language.slicing import KINDS, SliceModel
from seal_cli.language.stacking import StackModel
from seal_cli.language.steps import NONE, STEPS, StepModel
from seal_cli.language.tasks import TASKS, TaskModel

__all__ = ["CONTEXT_PRIOR", "CONTEXT_WEIGHT", "FORMAT", "MIN_RATIO", "MIN_SUPPORT", "SHIPPED", "WordUsage",
           "context_words", "load_word_usage", "shipped_word_usage", "unsaid_wording"]

FORMAT = "seal-word-classes/1"
SHIPPED = Path(__file__).resolve().parent / "word_classes"
MIN_SUPPORT = 2
"""Observations of a wording (among the present classes) below which the rules decide alone (chosen on
train trials held out from the counts: with the chooser, 2 scored 0.701, 3 0.698, 5 0.693; the table
keeps no wording said fewer than twice)."""
MIN_RATIO = 1.2
"""How many times as often the learned class must be meant as the rules' class to replace it
(chosen on train trials held out from the counts: 1.0–1.2 scored best, 1.5–3 about 0.6 points lower)."""
CONTEXT_WEIGHT = 0.3
"""How much the sentence's other words weigh (the exponent of the naive Bayes factor: 0 ignores
them, 1 is plain naive Bayes, which trusts the words' independence far too much; chosen on train
trials held out from the counts, see docs/language.md)."""
CONTEXT_PRIOR = 5.0
"""How many phrases' worth of the class's rate over all its wordings a wording's own rate of a
context word is smoothed with (a wording said few times borrows from its class)."""

SPELLING = 0.85
"""How similar (``difflib``'s ratio) a word no class names must be to a wording people said to be read as
its misspelling ("stovve" → stove 0.91, "cabinst" → cabinet 0.86; "pencil" for "parcel" is 0.67)."""

_WORD = re.compile(r"[a-z]+")


def context_words(text: str) -> frozenset[str]:
    """The words of a sentence as :attr:`WordUsage.context` counts them: lower-case letters only,
    each as its noun lemma ("Put two mugs in the coffee machine" → put, two, mug, in, the, ...)."""
    return frozenset(noun_lemma(w) for w in _WORD.findall(text.lower()))


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
    context: Mapping[str, Mapping[str, Mapping[str, int]]] = field(default_factory=dict)
    """``context[wording][class key][word]``: of the phrases with this wording that meant the class,
    how many were said in a sentence with the word (:func:`context_words`, the phrase's own words
    left out). Empty: the sentence is not weighed."""
    class_context: Mapping[str, Mapping[str, int]] = field(default_factory=dict)
    """``class_context[class key][word]``: the same over every head wording of the class, which a
    wording's own counts are smoothed towards (:data:`CONTEXT_PRIOR`)."""
    context_weight: float = CONTEXT_WEIGHT
    number: Mapping[str, Mapping[str, int]] = field(default_factory=dict)
    """``number[wording]["one" | "several"]``: of the plural phrases with this wording that named the
    task's object (no number said), how many meant one thing ("put the keys on the table": one key
    chain) and how many several (:meth:`names_one`)."""
    weights: Mapping[str, Mapping[str, float]] = field(default_factory=dict)
    """``weights[feature][class key]``: the discriminative chooser's weights
    (:mod:`~seal_cli.language.chooser`), which weigh the sentence in place of :meth:`context_factor`
    when a table has them."""
    steps: StepModel = field(default_factory=StepModel)
    """Which step a sentence that places a thing and says none most likely means
    (:mod:`~seal_cli.language.steps`); empty: none is inferred."""
    stacks: StackModel = field(default_factory=StackModel)
    """Which of two things placed together holds the other (:mod:`~seal_cli.language.stacking`);
    empty: no stack is read."""
    slices: SliceModel = field(default_factory=SliceModel)
    """Whether a sentence that says no cutting most likely means the thing sliced
    (:mod:`~seal_cli.language.slicing`); empty: no slice is inferred."""
    goals: GoalModel = field(default_factory=GoalModel)
    """Where a sentence that handles a thing and puts it nowhere most likely means it put
    (:mod:`~seal_cli.language.goals`); empty: no goal is inferred."""
    tasks: TaskModel = field(default_factory=TaskModel)
    """Which task kind a sentence describes, and the frame a kind adds when the parse lacks it
    (:mod:`~seal_cli.language.tasks`); empty: none is added."""
    scenery: frozenset[str] = frozenset()
    """Class keys of the scenes the statistics were counted in that no count is of (ALFRED's ``faucet``):
    a vocabulary of these and :attr:`universe` is one the unsaid step and stack may be inferred in."""
    scene_weights: Mapping[str, Mapping[str, float]] = field(default_factory=dict)
    """``scene_weights["s:<class key>"][class key]``: what the scene adds to the chooser where a phrase is
    grounded in one (:meth:`choose` with ``scene``): each class the room holds
    (:func:`~seal_cli.language.chooser.scene_features`) weighs each candidate, fitted on train phrases among
    the candidates their room held. Empty: the room's classes decide only which candidates compete."""

    def __post_init__(self) -> None:
        for name in ("counts", "seen", "class_context", "number", "weights", "scene_weights"):
            table = getattr(self, name)
            object.__setattr__(self, name, MappingProxyType({w: MappingProxyType(dict(c)) for w, c in table.items()}))
        object.__setattr__(self, "context", MappingProxyType(
            {w: MappingProxyType({c: MappingProxyType(dict(t)) for c, t in by.items()})
             for w, by in self.context.items()}))

    def __bool__(self) -> bool:
        return bool(self.counts)

    def merged(self, other: WordUsage) -> WordUsage:
        """The two tables' counts added."""
        def add(mine: Mapping[str, Mapping[str, Any]], theirs: Mapping[str, Mapping[str, Any]]) -> dict:
            out: dict[str, dict[str, Any]] = {w: dict(c) for w, c in mine.items()}
            for key, by in theirs.items():
                row = out.setdefault(key, {})
                for name, n in by.items():
                    row[name] = row.get(name, 0) + n
            return out

        context: dict[str, dict[str, dict[str, int]]] = {}
        for table in (self.context, other.context):
            for wording, by_class in table.items():
                row = context.setdefault(wording, {})
                for key, words in add(row, by_class).items():
                    row[key] = words
        return WordUsage(add(self.counts, other.counts), self.universe | other.universe,
                         self.sources + other.sources, self.min_support, self.min_ratio,
                         add(self.seen, other.seen), context, add(self.class_context, other.class_context),
                         self.context_weight, add(self.number, other.number),
                         add(self.weights, other.weights),
                         StepModel(add({"": self.steps.prior}, {"": other.steps.prior}).get("", {}),
                                   add(self.steps.weights, other.steps.weights), self.steps.threshold,
                                   add({"": self.steps.ended}, {"": other.steps.ended}).get("", {}),
                                   add({"": self.steps.left}, {"": other.steps.left}).get("", {})),
                         StackModel(add({"": self.stacks.said}, {"": other.stacks.said}).get("", {}),
                                    add({"": self.stacks.holds}, {"": other.stacks.holds}).get("", {}),
                                    self.stacks.threshold, self.stacks.min_support),
                         SliceModel(add({"": self.slices.prior}, {"": other.slices.prior}).get("", {}),
                                    add(self.slices.weights, other.slices.weights),
                                    self.slices.classes | other.slices.classes, self.slices.threshold),
                         GoalModel(add({"": self.goals.prior}, {"": other.goals.prior}).get("", {}),
                                   add(self.goals.weights, other.goals.weights), self.goals.threshold,
                                   self.goals.holders | other.goals.holders),
                         TaskModel(add({"": self.tasks.prior}, {"": other.tasks.prior}).get("", {}),
                                   add(self.tasks.weights, other.tasks.weights), self.tasks.threshold,
                                   GoalModel(add({"": self.tasks.carried.prior}, {"": other.tasks.carried.prior})
                                             .get("", {}),
                                             add(self.tasks.carried.weights, other.tasks.carried.weights))),
                         self.scenery | other.scenery, add(self.scene_weights, other.scene_weights))

    def names_one(self, lemmas: tuple[str, ...]) -> bool:
        """Whether a plural phrase whose words up to the head are ``lemmas`` names one thing, as
        people meant it: "the keys" are one key chain, "the pencils" several pencils. The longest
        wording with at least ``min_support`` observations decides: one, when at least
        ``min_support`` people meant one thing and ``min_ratio`` times as many as meant several."""
        for size in (2, 1):
            if len(lemmas) < size:
                continue
            said = self.number.get(" ".join(lemmas[-size:]))
            if not said or sum(said.values()) < self.min_support:
                continue
            one, several = said.get("one", 0), said.get("several", 0)
            return one >= self.min_support and one >= self.min_ratio * several
        return False

    def without_context(self) -> WordUsage:
        """These counts with the sentence not weighed (the wording alone decides)."""
        return WordUsage(self.counts, self.universe, self.sources, self.min_support, self.min_ratio, self.seen,
                         number=self.number, steps=self.steps, stacks=self.stacks, slices=self.slices,
                         goals=self.goals, tasks=self.tasks, scenery=self.scenery)

    def scene_factor(self, keys: Iterable[str], present: Iterable[str]) -> dict[str, float]:
        """For each class key, how much a scene holding the class keys ``present`` favours it:
        ``exp(Σ scene_weights)`` over :func:`~seal_cli.language.chooser.scene_features` (1.0 without them)."""
        keys = list(keys)
        if not self.scene_weights or len(keys) < 2:
            return {key: 1.0 for key in keys}
        z = logits(self.scene_weights, keys, scene_features(present))
        return {key: math.exp(v) for key, v in z.items()}

    def sentence_factor(self, wording: str, lemmas: tuple[str, ...], keys: Iterable[str],
                        words: Iterable[str]) -> dict[str, float]:
        """For each class key, how much the sentence favours it as the meaning of ``wording``: the
        chooser's ``exp(Σ weights)`` over the phrase's :func:`~seal_cli.language.chooser.features` when
        the table has weights, else the naive Bayes :meth:`context_factor`."""
        keys = list(keys)
        if self.weights:
            if len(keys) < 2:
                return {key: 1.0 for key in keys}
            z = logits(self.weights, keys, features(lemmas, words, keys))
            return {key: math.exp(v) for key, v in z.items()}
        return self.context_factor(wording, keys, set(words) - set(lemmas))

    @cached_property
    def _class_phrases(self) -> dict[str, int]:
        """How many phrases meant each class: its counts over the one-word (head) wordings."""
        total: dict[str, int] = {}
        for wording, by_class in self.counts.items():
            if " " not in wording:
                for key, n in by_class.items():
                    total[key] = total.get(key, 0) + n
        return total

    def context_factor(self, wording: str, keys: Iterable[str], words: Iterable[str]) -> dict[str, float]:
        """For each class key, how much the sentence's other ``words`` favour it as the meaning of
        ``wording`` over the wording's other classes: the product over the words of
        P(word | class, wording) / P(word | wording), smoothed towards P(word | class) over all the
        class's wordings, raised to ``context_weight``. 1.0 for every class when nothing is known.
        The head word of a class's own name is left out: "pot" in "put a knife and a pot ..." names
        the other phrase, and counting it would make a knife a pot wherever a label mixed the two up
        (a modifier stays: the "desk" of "the lamp on the desk" is evidence for a ``DeskLamp``)."""
        keys = list(keys)
        by_class = self.context.get(wording)
        counts = self.counts.get(wording, {})
        if not by_class or not self.context_weight or len(keys) < 2:
            return {key: 1.0 for key in keys}
        said = sum(counts.values())
        logs = dict.fromkeys(keys, 0.0)
        named = {key.split("_")[-1] for key in keys}
        for word in words:
            if word in named:
                continue       # "a knife and a pot": a word naming a class there is another phrase's, no evidence
            together = sum(c.get(word, 0) for c in by_class.values())
            if not together:
                continue                                  # a word never said with this wording
            p_word = (together + CONTEXT_PRIOR * 0.01) / (said + CONTEXT_PRIOR)
            for key in keys:
                n = counts.get(key, 0)
                overall = (self.class_context.get(key, {}).get(word, 0) + 0.1) / (self._class_phrases.get(key, 0) + 1)
                p = (by_class.get(key, {}).get(word, 0) + CONTEXT_PRIOR * overall) / (n + CONTEXT_PRIOR)
                logs[key] += math.log(p) - math.log(p_word)
        return {key: math.exp(self.context_weight * v) for key, v in logs.items()}

    @cached_property
    def _heads(self) -> tuple[str, ...]:
        """The one-word wordings people said at least ``min_support`` times, which a misspelling is matched against."""
        return tuple(w for w, by in self.counts.items() if " " not in w and "<-" not in w and w.isalpha()
                     and sum(by.values()) >= self.min_support)

    @cached_property
    def _spelled(self) -> dict[str, str | None]:
        return {}

    def respelled(self, word: str, least: int = 5) -> str | None:
        """The word people said that ``word`` most likely misspells ("stovve": stove, "cabinst":
        cabinet), or None: the one wording of the table within :data:`SPELLING` similarity
        (``difflib``'s ratio) of a word of at least ``least`` letters (5: a shorter typo is too often another
        word; 4 where the phrase is evidence that a thing's name is said, the whole of "a slice of *bred*"),
        closer than any other."""
        if len(word) < least or not word.isalpha() or word in self.counts:
            return None
        cache = self._spelled
        if word not in cache:
            import difflib

            close = difflib.get_close_matches(word, self._heads, n=2, cutoff=SPELLING)
            ratios = [difflib.SequenceMatcher(None, word, c).ratio() for c in close]
            cache[word] = close[0] if close and (len(close) == 1 or ratios[0] > ratios[1]) else None
        return cache[word]

    @cached_property
    def _compounds(self) -> dict[str, tuple[str, ...]]:
        """Modifier → the heads it was said with in a two-word wording people said at least ``min_support`` times."""
        heads: dict[str, list[str]] = {}
        for wording, by in self.counts.items():
            words = wording.split(" ")
            if len(words) == 2 and all(w.isalpha() for w in words) and sum(by.values()) >= self.min_support:
                heads.setdefault(words[0], []).append(words[1])
        return {m: tuple(h) for m, h in heads.items()}

    def respelled_after(self, modifier: str, word: str) -> str | None:
        """The head that ``word`` most likely misspells after ``modifier``, or None: the one head people said
        after that modifier (a two-word wording of the table, "end table") within :data:`SPELLING` of ``word``,
        closer than any other, when ``modifier word`` itself is no wording ("the end tale": table). A typo
        that is a word ("tale", "bred") or short is read so only where the modifier's compound names it: the
        compound is the evidence :meth:`respelled` lacks for words under 5 letters."""
        if len(word) < 3 or not word.isalpha() or f"{modifier} {word}" in self.counts or word in self.counts:
            return None
        import difflib

        heads = self._compounds.get(modifier, ())
        close = difflib.get_close_matches(word, heads, n=2, cutoff=SPELLING)
        ratios = [difflib.SequenceMatcher(None, word, c).ratio() for c in close]
        return close[0] if close and (len(close) == 1 or ratios[0] > ratios[1]) else None

    @cached_property
    def _meant(self) -> frozenset[str]:
        return frozenset(key for by_class in self.counts.values() for key in by_class)

    def meant(self, cls: str | None) -> bool:
        """Whether anybody in the counts meant this class (by any wording): a class nobody meant (THOR's
        ``ToiletPaperRoll``, beside the ``ToiletPaper`` people call a roll) is no evidence against the data."""
        return cls is not None and class_key(cls) in self._meant

    def choose(self, lemmas: tuple[str, ...], present: Mapping[str, str], rule: str | None,
               scene: bool = False, context: Iterable[str] = ()) -> str | None:
        """The class meant by a phrase whose words up to the head are ``lemmas``, among ``present``
        (class key → the vocabulary's spelling), given what the rules found (``rule``, or None).
        ``scene``: the present classes are those of one scene (compare rates, see :attr:`seen`);
        otherwise any (compare counts: how often each is meant, wherever). ``context``: the other
        words of the sentence (:func:`context_words`), which weigh each class by
        :meth:`sentence_factor`.

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
            if rule_key is not None and _named_by_more(rule_key, lemmas, size):
                return rule                               # the rules matched more of the phrase
            wording = " ".join(lemmas[-size:])
            scored = self._scored(wording, seen) if scene else [(float(n), key) for n, key in seen]
            if context and (self.weights or self.context):
                factor = self.sentence_factor(wording, lemmas, (key for _, key in scored), context)
                scored = [(s * factor[key], key) for s, key in scored]
            if scene and self.scene_weights:
                factor = self.scene_factor((key for _, key in scored), present)
                scored = [(s * factor[key], key) for s, key in scored]
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


def _named_by_more(key: str, lemmas: tuple[str, ...], size: int) -> bool:
    """Whether the class name ``key`` (a class key) spans more than the last ``size`` of a phrase's ``lemmas``:
    its words are all the phrase's and more than ``size`` ("coffee table" → ``coffee_table``), or the phrase's
    last words written together spell it ("glass bottle" → THOR's ``Glassbottle``, one word)."""
    name = key.split("_")
    if size < len(name) and set(name) <= set(lemmas):
        return True
    return any("".join(lemmas[-n:]) == "".join(name) for n in range(size + 1, len(lemmas) + 1))


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
    context: dict[str, dict[str, dict[str, int]]] = {}
    raw = data.get("context", {})
    if not isinstance(raw, dict):
        raise SealError("\"context\" must map each wording to {class: {word: count}}", where)
    for wording, by_class in raw.items():
        if not isinstance(by_class, dict) or not all(
                isinstance(c, str) and class_key(c) in universe and _word_counts(t) for c, t in by_class.items()):
            raise SealError(f"context {wording!r}: expected {{class of \"classes\": {{word: positive count}}}}",
                            where)
        context[" ".join(str(wording).lower().split())] = {class_key(c): dict(t) for c, t in by_class.items()}
    class_context: dict[str, dict[str, int]] = {}
    raw = data.get("class_context", {})
    if not isinstance(raw, dict) or not all(
            isinstance(c, str) and class_key(c) in universe and _word_counts(t) for c, t in raw.items()):
        raise SealError("\"class_context\" must map each class of \"classes\" to {word: positive count}", where)
    class_context = {class_key(c): dict(t) for c, t in raw.items()}
    raw = data.get("number", {})
    if not isinstance(raw, dict) or not all(
            _word_counts(by) and set(by) <= {"one", "several"} for by in raw.values()):
        raise SealError("\"number\" must map each wording to {\"one\": count, \"several\": count}", where)
    number = {" ".join(str(w).lower().split()): dict(by) for w, by in raw.items()}
    raw = data.get("weights", {})
    if not _weight_table(raw, lambda c: isinstance(c, str) and class_key(c) in universe):
        raise SealError("\"weights\" must map each feature to {class of \"classes\": finite number}", where)
    weights = {str(f): {class_key(c): float(v) for c, v in by.items()} for f, by in raw.items()}
    raw = data.get("scene_weights", {})
    if not _weight_table(raw, lambda c: isinstance(c, str) and class_key(c) in universe) or \
            not all(str(f).startswith("s:") for f in raw):
        raise SealError("\"scene_weights\" must map each feature \"s:<class>\" to {class of \"classes\": finite "
                        "number}", where)
    scene_weights = {str(f): {class_key(c): float(v) for c, v in by.items()} for f, by in raw.items()}
    return WordUsage(counts, universe, (str(data.get("source", where.file)),), seen=seen, context=context,
                     class_context=class_context, number=number, weights=weights, steps=_steps(data, where),
                     stacks=_stacks(data, universe, where), slices=_slices(data, universe, where),
                     goals=_goals(data, universe, where), tasks=_tasks(data, universe, where),
                     scenery=_scenery(data, where), scene_weights=scene_weights)


def _steps(data: dict[str, Any], where: Where) -> StepModel:
    """The unsaid-step model of a table (``step_prior``: {step: count}, ``step_weights``: {feature: {step: w}})."""
    names = {*STEPS, NONE}
    prior = data.get("step_prior", {})
    if not _word_counts(prior) or not set(prior) <= names:
        raise SealError(f"\"step_prior\" must map each of {', '.join(sorted(names))} to a positive count", where)
    raw = data.get("step_weights", {})
    if not _weight_table(raw, lambda c: c in names):
        raise SealError("\"step_weights\" must map each feature to {step: finite number}", where)
    weights = {str(f): {c: float(v) for c, v in by.items()} for f, by in raw.items()}
    raw = data.get("step_left", {})
    if not isinstance(raw, dict) or not all(
            c in STEPS and _word_counts(by) and set(by) <= {"ended", "left"} and by.get("left", 0) <= by.get("ended", 0)
            for c, by in raw.items()):
        raise SealError(f"\"step_left\" must map each of {', '.join(STEPS)} to {{\"ended\": count, \"left\": count "
                        "no greater}", where)
    return StepModel(prior, weights, ended={c: by.get("ended", 0) for c, by in raw.items()},
                     left={c: by.get("left", 0) for c, by in raw.items()})


def _scenery(data: dict[str, Any], where: Where) -> frozenset[str]:
    raw = data.get("scenery", [])
    if not isinstance(raw, list) or not all(isinstance(c, str) and c for c in raw):
        raise SealError("\"scenery\" must be a list of class names", where)
    return frozenset(class_key(c) for c in raw)


def _stacks(data: dict[str, Any], universe: frozenset[str], where: Where) -> StackModel:
    """The unsaid-stack model of a table (``stacks``: {class: {"said": count, "holds": count}})."""
    raw = data.get("stacks", {})
    if not isinstance(raw, dict) or not all(
            isinstance(c, str) and class_key(c) in universe and _word_counts(by) and set(by) <= {"said", "holds"}
            and by.get("holds", 0) <= by.get("said", 0) for c, by in raw.items()):
        raise SealError("\"stacks\" must map each class of \"classes\" to {\"said\": count, \"holds\": count "
                        "no greater}", where)
    return StackModel({c: by.get("said", 0) for c, by in raw.items()}, {c: by.get("holds", 0) for c, by in raw.items()})


def _slices(data: dict[str, Any], universe: frozenset[str], where: Where) -> SliceModel:
    """The unsaid-slice model of a table (``slice_prior``: {"sliced" | "whole": count}, ``slice_weights``:
    {feature: {kind: w}}, ``slice_classes``: [class of "classes"])."""
    prior = data.get("slice_prior", {})
    if not _word_counts(prior) or not set(prior) <= set(KINDS):
        raise SealError(f"\"slice_prior\" must map each of {', '.join(KINDS)} to a positive count", where)
    raw = data.get("slice_weights", {})
    if not _weight_table(raw, lambda k: k in KINDS):
        raise SealError(f"\"slice_weights\" must map each feature to {{{' | '.join(KINDS)}: finite number}}", where)
    classes = data.get("slice_classes", [])
    if not isinstance(classes, list) or not all(isinstance(c, str) and class_key(c) in universe for c in classes):
        raise SealError("\"slice_classes\" must be a list of classes of \"classes\"", where)
    return SliceModel(prior, {str(f): {k: float(v) for k, v in by.items()} for f, by in raw.items()},
                      frozenset(classes))


def _goals(data: dict[str, Any], universe: frozenset[str], where: Where, name: str = "goal") -> GoalModel:
    """The unsaid-goal model of a table (``goal_prior``: {class of "classes" | "none": count}, ``goal_weights``:
    {feature: {class | "none": w}}; ``receptacles``: [class of "classes"], what holds things,
    :attr:`~seal_cli.language.goals.GoalModel.holders`); ``name``: the sections' prefix (``stack_goal``: where a
    stack's container goes, :attr:`~seal_cli.language.tasks.TaskModel.carried`)."""
    def known(c: Any) -> bool:
        return isinstance(c, str) and (c == NOWHERE or class_key(c) in universe)

    prior = data.get(f"{name}_prior", {})
    if not _word_counts(prior) or not all(known(c) for c in prior):
        raise SealError(f"\"{name}_prior\" must map each class of \"classes\" or \"{NOWHERE}\" to a positive count",
                        where)
    raw = data.get(f"{name}_weights", {})
    if not _weight_table(raw, known):
        raise SealError(f"\"{name}_weights\" must map each feature to {{class of \"classes\" | \"{NOWHERE}\": finite "
                        "number}", where)
    holders = data.get("receptacles", []) if name == "goal" else []
    if not isinstance(holders, list) or not all(isinstance(c, str) and class_key(c) in universe for c in holders):
        raise SealError("\"receptacles\" must be a list of classes of \"classes\"", where)
    return GoalModel(prior, {str(f): {(c if c == NOWHERE else class_key(c)): float(v) for c, v in by.items()}
                             for f, by in raw.items()}, holders=frozenset(holders))


def _tasks(data: dict[str, Any], universe: frozenset[str], where: Where) -> TaskModel:
    """The task model of a table (``task_prior``: {task kind: count}, ``task_weights``: {feature: {task kind: w}};
    ``stack_goal_prior``, ``stack_goal_weights``: where a stack's container goes, as :func:`_goals` reads them)."""
    prior = data.get("task_prior", {})
    if not _word_counts(prior) or not set(prior) <= set(TASKS):
        raise SealError(f"\"task_prior\" must map each of {', '.join(TASKS)} to a positive count", where)
    raw = data.get("task_weights", {})
    if not _weight_table(raw, lambda k: k in TASKS):
        raise SealError("\"task_weights\" must map each feature to {task kind: finite number}", where)
    return TaskModel(prior, {str(f): {k: float(v) for k, v in by.items()} for f, by in raw.items()},
                     carried=_goals(data, universe, where, "stack_goal"))


def _weight_table(table: Any, known: Callable[[Any], bool]) -> bool:
    """Whether a fitted model's weights are {feature: {class the model knows: finite number}}."""
    return isinstance(table, dict) and all(
        isinstance(by, dict) and all(known(c) and isinstance(v, int | float) and not isinstance(v, bool)
                                     and math.isfinite(v) for c, v in by.items()) for by in table.values())


def _word_counts(table: Any) -> bool:
    return isinstance(table, dict) and all(
        isinstance(w, str) and isinstance(n, int) and not isinstance(n, bool) and n > 0 for w, n in table.items())


def load_word_usage(paths: Iterable[str | Path]) -> WordUsage:
    """The word-class tables in these files (or folders of ``*.json``), their counts added."""
    import json

    from seal_cli.fileio import json_value, read_text

    usage = WordUsage()
    for path in paths:
        path = Path(path)
        for file in sorted(path.glob("*.json")) if path.is_dir() else [path]:
            where = Where(str(file))
            try:
                data = json_value(read_text(file), file)
            except json.JSONDecodeError as err:
                raise SealError(f"not JSON: {err.msg}", Where(str(file), err.lineno, err.colno)) from None
            usage = usage.merged(_table(data, where))
    return usage


@cache
def shipped_word_usage() -> WordUsage:
    """The tables shipped with seal (``seal_cli/language/word_classes/``), read once."""
    return load_word_usage([SHIPPED]) if SHIPPED.is_dir() else WordUsage()
