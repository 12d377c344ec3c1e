"""Grounding: which object class a noun phrase denotes, in a given vocabulary of classes.

A :class:`Vocabulary` is a list of classes (``AlarmClock``, ``tomato soup``), each with optional
synonyms. A phrase is matched on its words' lemmas (so plurals match), best first:

1. an exact name: the phrase's last words spell a class's own name, or else a synonym ("the red
   *alarm clock*"), also written together ("the *lap top*" → ``Laptop``, "a *bath tub*" →
   ``Bathtub``); or the words after "of" do ("a roll *of toilet paper*");
2. the head word: the phrase's head is the head of a class name ("clock" → ``AlarmClock``),
   helped by every other word they share ("a bottle of *wine*" → ``WineBottle``), then another
   word of a class name ("counter" → ``CounterTop``);
3. the words after "of" ("the middle *of the table*").

A phrase whose head names a portion, region, part or group of something (``PORTIONS``: "an
apple *slice*", "the table *top*", "the toilet *tank*", "a *set* of keys") denotes what its
modifiers or its "of" phrase name, when they name a class. A modifier of any other head names
something else: a "chair cushion" is a cushion, not a chair, and no class when the vocabulary
calls nothing a cushion.

Within a step, the class sharing the most words with the phrase wins; a class's own name beats
another class's synonym; a remaining tie (``DiningTable``, ``SideTable``, ``CoffeeTable`` for
"table") goes to the class listed first, so a vocabulary lists the usual class first, and a map's
vocabulary lists only the tables the building has. No match gives None: the vocabulary of a
building is open and an unknown noun is not an error.

Vocabulary files are YAML lists: ``- cup`` or ``- {class: Fridge, synonyms: [refrigerator]}``
(a mapping ``classes: [...]`` is read too).
"""

from __future__ import annotations

from collections.abc import Iterable, Mapping, Sequence
from dataclasses import dataclass, field, replace
from functools import cached_property
from pathlib import Path
from types import MappingProxyType
from typing import Any

from seal_cli.errors import SealError, Where
from seal_cli.frames.taxonomy import class_key, class_words
from seal_cli.language.english import PARTS
from seal_cli.language.goals import GoalModel
from seal_cli.language.lexicon import noun_lemma
from seal_cli.language.slicing import SliceModel
from seal_cli.language.stacking import StackModel
from seal_cli.language.steps import StepModel
from seal_cli.language.taskfields import FieldModel, shipped_field_model
from seal_cli.language.tasks import TaskModel
from seal_cli.language.wordusage import WordUsage, context_words, shipped_word_usage, unsaid_wording
from seal_cli.names import check_shown, name_too_long

__all__ = ["PARTS", "PIECES", "PORTIONS", "Vocabulary", "load_vocabulary", "vocabulary_of_map"]


PORTIONS = frozenset(" ".join((
    "slice piece bit chunk half part portion wedge segment section sliver strip lump cube quarter crumb",
    "top side edge corner middle centre center end bottom surface back front",
    " ".join(sorted(PARTS)),
    "set bunch pair pack group collection stack pile handful roll")).split())
"""English nouns that name a portion, a region, a part or a group of something else ("an apple
*slice*", "the table *top*", "the fridge *door*", "a *set* of keys"): with one of these as its
head, a phrase denotes what its modifiers or its "of" phrase name."""


PIECES = frozenset({"slice", "piece", "chunk", "wedge", "section", "segment", "sliver", "half", "quarter", "bit"})
"""The portions that are pieces cut from a whole ("an apple *slice*", "a *piece* of bread"): a
piece exists once its whole has been cut, so naming one asks for the cutting (see
:mod:`seal_cli.language.parser`)."""


_RULES = WordUsage()
_NO_STEPS = StepModel()
_NO_STACKS = StackModel()
_NO_SLICES = SliceModel()
_NO_GOALS = GoalModel()
_NO_TASKS = TaskModel()
_NO_FIELDS = FieldModel()
_INDEXES = ("_usage", "_present", "_names", "_own", "_exact", "_spelled", "_by_word", "_rules_alone", "_in_scope")
"""The cached indexes a vocabulary builds from its classes and usage, which do not depend on the sentence."""


def _lemmas(words: Iterable[str]) -> tuple[str, ...]:
    return tuple(noun_lemma(w) for w in words)


def _head(name: tuple[str, ...]) -> str:
    """The head word of a name: the last, or the one before "of" ("head of lettuce": head)."""
    return name[name.index("of") - 1] if "of" in name[1:] else name[-1]


@dataclass(frozen=True)
class Vocabulary:
    """Object classes, each with the names (class name and synonyms) it may be called by."""

    classes: tuple[str, ...]
    synonyms: tuple[tuple[str, ...], ...] = ()
    where: Where | None = field(default=None, compare=False)
    usage: WordUsage | None = field(default=None, compare=False)
    """Which class people mean by a word (:mod:`~seal_cli.language.wordusage`); None: the shipped tables."""
    scene: bool = field(default=False, compare=False)
    """Whether the classes are those of one scene (:meth:`restricted_to`): the statistics then ask
    which class people mean by a word where it is present, not which one is meant most often."""
    context: frozenset[str] = field(default=frozenset(), compare=False)
    """The words of the sentence being grounded (:meth:`in_context`), which the statistics weigh
    (:meth:`~seal_cli.language.wordusage.WordUsage.context_factor`); empty: the phrase alone."""
    people: frozenset[str] = field(default=frozenset(), compare=False)
    """The names of the people of this world, lower case (a map's ``people``, a vocabulary file's
    ``people:``): the parser reads them as names however they are written ("take *sam*")."""
    house: bool = field(default=False, compare=False)
    """Whether these are the classes of a building a robot acts in (a map's: :func:`vocabulary_of_map`): there a
    command is what its speaker said, not one of ALFRED's seven tasks, so the task statistics add no placing
    nobody said (:func:`~seal_cli.language.tasks.add_carried`: "put the spoon in the cup" is two steps there)."""

    def __post_init__(self) -> None:
        if not self.synonyms:
            object.__setattr__(self, "synonyms", tuple(() for _ in self.classes))
        if len(self.synonyms) != len(self.classes):
            raise SealError("a vocabulary needs one list of synonyms per class", self.where)

    @classmethod
    def of(cls, names: Iterable[str], synonyms: Mapping[str, Sequence[str]] | None = None,
           usage: WordUsage | None = None) -> Vocabulary:
        """A vocabulary from class names (and optionally synonyms by class), duplicates dropped."""
        unique = tuple(dict.fromkeys(n for n in names if class_words(n)))
        extra = synonyms or {}
        return cls(unique, tuple(tuple(extra.get(n, ())) for n in unique), usage=usage)

    def with_usage(self, usage: WordUsage) -> Vocabulary:
        """This vocabulary grounding with these word statistics (``WordUsage()``: the rules alone)."""
        return Vocabulary(self.classes, self.synonyms, self.where, usage, self.scene, people=self.people,
                          house=self.house)

    def in_context(self, text: str) -> Vocabulary:
        """This vocabulary grounding the phrases of the sentence ``text``: the statistics weigh its
        other words ("the cup" in "put the cup in the coffee machine"). Made once per sentence, so
        it shares this vocabulary's indexes of names instead of building them again."""
        words = context_words(text)
        if words == self.context:
            return self
        made = Vocabulary(self.classes, self.synonyms, self.where, self.usage, self.scene, words, self.people,
                          self.house)
        for name in _INDEXES:      # built here once, on this vocabulary: built on each copy, every sentence built them
            made.__dict__[name] = getattr(self, name)
        return made

    @cached_property
    def _usage(self) -> WordUsage:
        return shipped_word_usage() if self.usage is None else self.usage

    @cached_property
    def _present(self) -> dict[str, str]:
        """Class key → class, for the statistics (which count by class key)."""
        present: dict[str, str] = {}
        for name in self.classes:
            present.setdefault(class_key(name), name)
        return present

    @cached_property
    def _names(self) -> tuple[tuple[int, tuple[str, ...]], ...]:
        """(class index, lemmatised words) for every name of every class: the classes' own names
        first, then their synonyms (so that an own name wins over another class's synonym)."""
        names = []
        for index, name in enumerate(self.classes):
            names.append((index, _lemmas(class_words(name))))
        for index, synonyms in enumerate(self.synonyms):
            names.extend((index, _lemmas(class_words(spelled))) for spelled in synonyms)
        return tuple((index, words) for index, words in names if words)

    @cached_property
    def _own(self) -> frozenset[tuple[str, ...]]:
        """The classes' own names (lemmatised words), which win ties over synonyms."""
        return frozenset(_lemmas(class_words(name)) for name in self.classes)

    @cached_property
    def _exact(self) -> dict[tuple[str, ...], int]:
        exact: dict[tuple[str, ...], int] = {}
        for index, words in self._names:
            exact.setdefault(words, index)
        for index, words in self._names:
            exact.setdefault(("".join(words),), index)     # "glassbottle", "tvstand"
        return exact

    @cached_property
    def _spelled(self) -> dict[tuple[str, ...], int]:
        """The own names, as spelled, of classes whose names are one word by their lemmas (e2e22: a house's
        ``glass`` and its ``glasses``, whose lemma is "glass" too): there the form said tells them apart, "a glass"
        the one, "my glasses" the other, before any statistic of what people mean by the lemma."""
        by_lemma: dict[tuple[str, ...], list[int]] = {}
        for index, name in enumerate(self.classes):
            by_lemma.setdefault(_lemmas(class_words(name)), []).append(index)
        return {class_words(self.classes[i]): i for same in by_lemma.values() if len(set(
            class_words(self.classes[j]) for j in same)) > 1 for i in same}

    @cached_property
    def _by_word(self) -> dict[str, list[tuple[int, tuple[str, ...]]]]:
        """Word → (class index, name) of every name with the word, own names first ("bin" is the
        head of the trash can's "trash bin", as "clock" is of AlarmClock)."""
        index: dict[str, list[tuple[int, tuple[str, ...]]]] = {}
        for cls_index, words in self._names:
            for word in dict.fromkeys(words):
                index.setdefault(word, []).append((cls_index, words))
        return index

    def with_synonyms(self, synonyms: Mapping[str, Sequence[str]]) -> Vocabulary:
        """This vocabulary with more synonyms, by class key (``class_key``): each class gets the
        names listed under its own name. A class with none added keeps what it had.

        A class named for a part or region of something (its last word is in :data:`PORTIONS`:
        ``SinkBasin``, ``BathtubBasin``, ``CounterTop``) is also called by the name of the whole
        and the whole's synonyms ("sink", "tub", "counter"), unless the vocabulary has a class for
        the whole itself: in a room whose only sink is its basin, "the sink" is the basin."""
        if not synonyms:
            return self
        keys = {class_key(name) for name in self.classes}
        added = []
        for name, own in zip(self.classes, self.synonyms, strict=True):
            names = [*own, *synonyms.get(class_key(name), ())]
            words = class_words(name)
            whole = "_".join(words[:-1])
            if len(words) > 1 and noun_lemma(words[-1]) in PORTIONS and whole not in keys:
                names += [whole.replace("_", " "), *synonyms.get(whole, ())]
            added.append(tuple(dict.fromkeys(n for n in names if class_key(n) != class_key(name))))
        return Vocabulary(self.classes, tuple(added), self.where, self.usage, self.scene, people=self.people,
                          house=self.house)

    def restricted_to(self, classes: Iterable[str]) -> Vocabulary:
        """The vocabulary of a scene: only the given classes (those present), each with the names
        this vocabulary gives it, in this vocabulary's order (which settles ties), then the present
        classes this vocabulary does not list. Classes keep the spelling they are given."""
        present: dict[str, str] = {}
        for cls in classes:
            present.setdefault(class_key(cls), cls)
        names: dict[str, list[str]] = {}
        for name, synonyms in zip(self.classes, self.synonyms, strict=True):
            key = class_key(name)
            if key in present:
                names.setdefault(present[key], []).extend(synonyms)
        for cls in present.values():
            names.setdefault(cls, [])
        scene = Vocabulary.of(list(names), names, self.usage)
        return Vocabulary(scene.classes, scene.synonyms, scene.where, scene.usage, True, people=self.people,
                          house=self.house)

    def __len__(self) -> int:
        return len(self.classes)

    def ground_words(self, words: Sequence[str], head: int = -1, of: Sequence[str] = ()) -> str | None:
        """The class that words denote (``head`` indexes the head word), or None."""
        if self._spelled and head in (-1, len(words) - 1):
            # "a glass" where glasses are a class too: the form said, the phrase's own words first ("a glass of
            # water" the glass), then its "of" phrase's ("a pair of glasses" the glasses)
            for phrase in (words, of):
                spelled = tuple(w.lower() for w in phrase if w)
                for start in range(len(spelled)):
                    index = self._spelled.get(spelled[start:])
                    if index is not None:
                        return self.classes[index]
        words = _lemmas(w for w in words if w)
        of = _lemmas(w for w in of if w)
        if not words and not of:
            return None
        end = len(words) + head + 1 if head < 0 else head + 1
        found = self._ground(words, end, of)
        if found is None and words and words[end - 1].endswith("s"):     # a plural the dictionary lacks
            for cut in (1, 2):
                stem = words[end - 1][:-cut]
                found = self._ground((*words[:end - 1], stem, *words[end:]), end, of) if len(stem) > 1 else None
                if found is not None:
                    break
        if words and not of and end == len(words) and words[-1] not in PORTIONS:
            found = self._usage.choose(words, self._present, found, self.scene, self.context)
            if found is None:                # "the stovve": a word nobody's class names, misspelling one people say
                said = self._usage.respelled(words[-1])
                if said is not None:
                    found = self._usage.choose((said,), self._present, None, self.scene, self.context)
                elif len(words) > 1:         # "the end tale": a word, yet after "end" a misspelt "table"
                    said = self._usage.respelled_after(words[-2], words[-1])
                    if said is not None:
                        found = self._usage.choose((words[-2], said), self._present, None, self.scene,
                                                   self.context)
        elif end == len(words) and words and words[-1] in PORTIONS:   # "the left side of the sink",
            whole = of or words[:-1]                                     # "a chair seat": the whole decides
            if whole and whole[-1] not in PORTIONS and (
                    found == self._ground(whole, len(whole), ()) or not self._usage.meant(found)):
                found = self._usage.choose(whole, self._present, found, self.scene, self.context)
                said = self._usage.respelled(whole[-1], 4) if found is None else None
                if said is not None:         # "a slice of bred": the whole misspelt, as "the stovve" is; a portion
                    #                          is of a thing, so a 4-letter word no wording is may be its typo
                    found = self._usage.choose((said,), self._present, None, self.scene, self.context)
        elif of and end == len(words) and found is not None and of[-1] not in PORTIONS and \
                words[-1] != noun_lemma(class_words(found)[-1]) and \
                found == self._ground(words, end, ()) == self._ground(of, len(of), ()):
            # "the light of a tall lamp": the head alone names what the whole alone names (a lamp's light is the
            # lamp) by another word than the class's own head, so the whole's words decide ("a bar of soap", "a
            # box of tissues" are the class's own names, SoapBar and TissueBox: they stay)
            found = self._usage.choose(of, self._present, found, self.scene, self.context)
        return found

    def _ground(self, words: tuple[str, ...], end: int, of: tuple[str, ...]) -> str | None:
        if of and end == len(words):                      # "a chest of drawers", "a bar of soap"
            for start in range(end):
                index = self._exact.get((*words[start:], "of", *of))
                if index is not None:
                    return self.classes[index]
        for phrase in (words[:end], of):
            for start in range(len(phrase)):             # longest exact name ending at the head
                index = self._exact.get(phrase[start:])
                if index is None and len(phrase) - start > 1:
                    index = self._exact.get(("".join(phrase[start:]),))     # "lap top": Laptop
                if index is not None:
                    return self.classes[index]
        head_word = words[end - 1] if words else of[-1]
        if head_word in PORTIONS:            # "an apple slice", "the table top", "a set of keys": the apple, ...
            found = self._ground(words, end - 1, of) if end > 1 else None
            if found is None and of:
                found = self._ground(of, len(of), ())
            if found is not None:
                return found
        best: tuple[float, int] | None = None
        context = set(words) | set(of)
        for key, weight in ((head_word, 4.0), *((w, 1.0) for w in reversed(of))):
            for cls_index, name in self._by_word.get(key, ()):
                if key != _head(name) and name not in self._own:
                    continue      # a "table lamp" is a lamp: a synonym names a table only by its head
                score = weight + (2.0 if name[-1] == key else 0.0) + sum(0.5 for w in name if w in context) \
                    - 0.25 * sum(1 for w in name if w not in context) + (0.125 if name in self._own else 0.0)
                if best is None or (score, -cls_index) > (best[0], -best[1]):
                    best = (score, cls_index)
            if best is not None and weight >= 4.0:
                break
        return None if best is None else self.classes[best[1]]

    def names_one(self, words: Sequence[str]) -> bool:
        """Whether a plural noun phrase with these words (modifiers, head) names one thing, as people
        mean it: "the keys" are one key chain (:meth:`~seal_cli.language.wordusage.WordUsage.names_one`,
        learned from a train split; the rules alone know no such plural)."""
        return self._usage.names_one(_lemmas(w for w in words if w))

    def ground_unsaid(self, frame: str, role: str, unit: str) -> str | None:
        """The class people most likely mean as ``frame``'s ``role`` when they use the lexical unit
        ``unit`` and leave the element unsaid ("throw away the towel": the goal of Place by "throw
        away"), by the statistics alone (:func:`~seal_cli.language.wordusage.unsaid_wording`): a
        clear majority among the present classes, or None (the rules know no unsaid elements)."""
        return self._usage.choose((unsaid_wording(frame, role, unit),), self._present, None, self.scene)

    @property
    def step_model(self) -> StepModel:
        """Which step a sentence leaves unsaid (:mod:`~seal_cli.language.steps`), from the statistics:
        only when every class of this vocabulary is one they were counted over (ALFRED's classes, or
        a scene's of them, with its scenery: :attr:`~seal_cli.language.wordusage.WordUsage.scenery`),
        else an empty model (a GPSR arena, a shipped map: no step is inferred)."""
        usage = self._usage
        return usage.steps if usage.steps and self._in_scope else _NO_STEPS

    @property
    def stack_model(self) -> StackModel:
        """Which of two things placed together holds the other (:mod:`~seal_cli.language.stacking`),
        scoped as :attr:`step_model` is: empty unless every class of this vocabulary is one the
        statistics were counted over."""
        usage = self._usage
        return usage.stacks if usage.stacks and self._in_scope else _NO_STACKS

    @property
    def slice_model(self) -> SliceModel:
        """Whether a sentence means its thing sliced though it says no cutting
        (:mod:`~seal_cli.language.slicing`), scoped as :attr:`step_model` is."""
        usage = self._usage
        return usage.slices if usage.slices and self._in_scope else _NO_SLICES

    @property
    def goal_model(self) -> GoalModel:
        """Where a sentence that puts its thing nowhere means it put (:mod:`~seal_cli.language.goals`),
        scoped as :attr:`step_model` is."""
        usage = self._usage
        return usage.goals if usage.goals and self._in_scope else _NO_GOALS

    @property
    def task_model(self) -> TaskModel:
        """Which task a sentence describes, and the frame it adds when the parse lacks it
        (:mod:`~seal_cli.language.tasks`), scoped as :attr:`step_model` is."""
        usage = self._usage
        return usage.tasks if usage.tasks and self._in_scope else _NO_TASKS

    def meanings(self, wording: str) -> Mapping[str, int]:
        """How often people meant each class (class key → count) by this wording (lemmas joined by spaces: "table",
        "butter knife"), by the statistics; empty when they never saw it."""
        return self._usage.counts.get(wording, MappingProxyType({}))

    @property
    def field_model(self) -> FieldModel:
        """What task fields the whole sentence says (:mod:`~seal_cli.language.taskfields`), combined with the
        parser's reading: only with the statistics seal ships (no ``usage`` given), scoped as :attr:`step_model` is,
        and never in a house's vocabulary; else an empty model."""
        if self.usage is not None or self.house or not self._usage.tasks or not self._in_scope:
            return _NO_FIELDS
        return shipped_field_model()

    @property
    def by_key(self) -> Mapping[str, str]:
        """Class key → this vocabulary's spelling of the class, for each of its classes."""
        return MappingProxyType(self._present)

    @cached_property
    def _in_scope(self) -> bool:
        """Whether every class of this vocabulary is one the statistics were counted over, or part of
        their scenes' scenery: where the unsaid step, stack, slice and goal may be inferred (asked once
        per vocabulary, shared by its copies for each sentence)."""
        usage = self._usage
        return set(self._present) <= usage.universe | usage.scenery

    def ground_name(self, name: str) -> str | None:
        """The class a class name of the frame library denotes (a default: Slice's ``knife``): by
        the rules alone, since nobody said it, the statistics of what people mean do not apply."""
        return self._rules_alone.ground_words(class_words(name))

    @cached_property
    def _rules_alone(self) -> Vocabulary:
        return self if self.usage is not None and not self.usage else self.with_usage(_RULES)

    def grounded(self, words: Sequence[str], of: Sequence[str] = ()) -> str | None:
        """:meth:`ground_words` of a phrase's words (its head last) and of its "of" phrase's, remembered by
        this vocabulary: a sentence asks for the same phrase several times (for each frame and role that
        may take it), and the answer depends only on the words and this vocabulary (which holds the
        sentence's context, :meth:`in_context`: each sentence's copy remembers its own)."""
        key = (tuple(words), tuple(of))
        memo = self._grounded
        if key in memo:
            return memo[key]
        if len(memo) >= GROUNDED:
            memo.clear()
        found = memo[key] = self.ground_words(key[0], -1, key[1])
        return found

    @cached_property
    def _grounded(self) -> dict[tuple[tuple[str, ...], tuple[str, ...]], str | None]:
        return {}


GROUNDED = 4096
"""How many phrases a vocabulary remembers grounding (:meth:`Vocabulary.grounded`) before it starts again."""


def _entries(data: Any, where: Where) -> tuple[list[str], dict[str, list[str]]]:
    if isinstance(data, dict) and "classes" in data:
        data = data["classes"]
    if not isinstance(data, list):
        raise _problem("a vocabulary is a YAML list of classes (each a name or {class: NAME, synonyms: [...]})",
                       where)
    names: list[str] = []
    synonyms: dict[str, list[str]] = {}
    for number, entry in enumerate(data, 1):
        if isinstance(entry, str | int | float) and str(entry).strip():
            names.append(str(entry))
        elif isinstance(entry, dict) and isinstance(entry.get("class"), str) and entry["class"].strip():
            extra = entry.get("synonyms") or []
            if not isinstance(extra, list) or not all(isinstance(s, str) for s in extra):
                raise _problem(f"entry {number}: synonyms must be a list of names", where, number, "synonyms")
            names.append(entry["class"])
            synonyms.setdefault(entry["class"], []).extend(extra)
        else:
            raise _problem(f"entry {number} is neither a class name nor {{class: NAME, synonyms: [...]}}", where,
                           number)
    if not names:
        raise _problem("the vocabulary lists no class", where)
    for number, entry in enumerate(data, 1):  # a class or synonym no message, table or picture shows whole
        for name in [entry] if not isinstance(entry, dict) else [entry["class"], *(entry.get("synonyms") or [])]:
            long = name_too_long(str(name), f"entry {number}: name")
            if long is not None:
                raise _problem(long.message, where, number)
            try:  # an escape sequence or an override in a class or synonym (hostile28)
                check_shown(str(name), f"entry {number}: name")
            except SealError as problem:
                raise _problem(problem.message, where, number) from None
    return names, synonyms


def _problem(message: str, where: Where, entry: int | None = None, key: str | None = None) -> SealError:
    """A vocabulary's problem at the line and column of its ``entry`` (1-based; its ``key``'s value), else of the
    list of classes, found by reading the file's nodes again (only when there is a problem to say)."""
    import yaml

    from seal_cli.fileio import LOADER, read_text

    if where.file is None:
        return SealError(message, where)
    try:
        text = read_text(where.file)
        node: yaml.Node | None = yaml.compose(text, Loader=LOADER)
    except (SealError, yaml.YAMLError):
        return SealError(message, where)

    def value(of: yaml.Node | None, name: str) -> yaml.Node | None:
        if not isinstance(of, yaml.MappingNode):
            return None
        return next((v for k, v in of.value if isinstance(k, yaml.ScalarNode) and k.value == name), None)

    if key == "people":
        node = value(node, "people") or node
    else:
        node = value(node, "classes") or node
        if entry is not None and isinstance(node, yaml.SequenceNode) and entry <= len(node.value):
            node = node.value[entry - 1]
            node = (value(node, key) or node) if key is not None else node
    if node is None:
        return SealError(message, where)
    line = node.start_mark.line
    lines = text.splitlines()
    return SealError(message, Where(where.file, line + 1, node.start_mark.column + 1),
                     source_line=lines[line] if line < len(lines) else None)


ARENA_CLASSES = ("objects", "locations", "placement_locations", "rooms")
"""The keys of a RoboCup@Home arena's vocabulary (its ``names`` are people) that hold classes."""


def _arena(data: dict[str, Any]) -> dict[str, Any]:
    """A RoboCup@Home arena's vocabulary (``names``, ``objects``, ``locations``, ``rooms``: the
    competition's own JSON) as a vocabulary mapping: its classes, and its names as ``people``."""
    classes = [c for key in ARENA_CLASSES for c in data.get(key) or () if isinstance(c, str)]
    return {"classes": list(dict.fromkeys(classes)), "people": data.get("names", [])}


MAX_VOCABULARY_VALUES = 50_000
"""The most values (class names, synonyms, people) a vocabulary file may hold: parsing a command looks at
every class (50,000 take about 3 s; 300,000 took 25 s), and no robot's world names more; a larger file is
refused as it is read, at the value past the bound."""


def load_vocabulary(path: str | Path) -> Vocabulary:
    """Read a vocabulary file: a YAML list of classes, each a name or ``{class, synonyms}``; or a
    mapping of ``classes`` and ``people``; or a RoboCup@Home arena's vocabulary (``names``, ``objects``,
    ``locations``, ``rooms``)."""
    from seal_cli.fileio import read_yaml

    where = Where(str(path))
    data = read_yaml(path, MAX_VOCABULARY_VALUES, "vocabulary")
    if isinstance(data, dict) and "classes" not in data and "names" in data:
        data = _arena(data)
    names, synonyms = _entries(data, where)
    people = data.get("people", []) if isinstance(data, dict) else []
    if not isinstance(people, list) or not all(isinstance(p, str) and p.strip() for p in people):
        raise _problem("people: must be a list of names", where, key="people")
    return replace(Vocabulary.of(names, synonyms), people=frozenset(p.strip().lower() for p in people))


def vocabulary_of_map(map_: Any) -> Vocabulary:
    """The classes a map knows: its places', its objects' and its priors' classes."""
    names = [p.cls for p in getattr(map_, "places", ())]
    names += [o.cls for o in getattr(map_, "objects", ())]
    names += list(getattr(map_, "priors", {}) or {})
    people = frozenset(p.name.lower() for p in getattr(map_, "people", ()) if getattr(p, "name", None))
    return replace(Vocabulary.of(names), people=people, house=True)
