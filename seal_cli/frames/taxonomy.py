"""Object classes and the categories that frame elements are typed with.

A library declares categories in a types file (``utensil: [spoon, fork, ladle]``); a member
may itself be a category (``tableware: [utensil, plate]``). A category declared without
members (``thing: ~``) is *open*: every class belongs to it.

Class names compare case-insensitively with ``_``, ``-``, spaces and CamelCase humps equal:
``SinkBasin``, ``sink_basin`` and ``sink basin`` are one class (:func:`class_key`).

A library may also say what else a class is called (``fridge: [refrigerator, icebox]``): each
entry is a set of English names for one kind of thing (:class:`Synonyms`), merged into every
vocabulary that grounds commands (a class called by any name of a set is called by all of them).
"""

from __future__ import annotations

import re
from collections.abc import Iterable, Mapping
from dataclasses import dataclass, field
from functools import cached_property, lru_cache

from seal_cli.errors import SealError, Where
from seal_cli.names import MAX_NAME, check_name_length

__all__ = ["Category", "Synonyms", "Taxonomy", "check_class_name", "class_key", "class_words"]

_NAME = re.compile(r"^[a-z0-9]+(?:_[a-z0-9]+)*$")
_CLASS = re.compile(r"[^\W\d]\w*\Z")  # Unicode letters too: a café is a class
_HUMP = re.compile(r"(?<=[a-z0-9])(?=[A-Z])|(?<=[A-Z])(?=[A-Z][a-z])")


def class_words(name: str) -> tuple[str, ...]:
    """The lower-case words of a class name: ``"SinkBasin"`` and ``"sink_basin"`` give ``("sink", "basin")``."""
    return tuple(w for w in re.split(r"[\s_\-]+", _HUMP.sub(" ", name).lower()) if w)


MAX_CLASS_NAME = MAX_NAME
"""The longest class name (as a key, words joined by '_') a plan may use: ``--holding`` of 3,000 letters was
held, and printed whole in every state."""


def check_class_name(name: str, what: str, where: Where | None = None) -> str:
    """``class_key(name)``, or a SealError when that is no name a plan can use (letters, digits
    and '_', not starting with a digit): ``what`` says which value it is."""
    key = class_key(name)
    if len(key) > MAX_CLASS_NAME:
        raise SealError(f"{what} {name[:40]!r}… is {len(key):,} characters long; a class name has at most "
                        f"{MAX_CLASS_NAME}", where)
    if not _CLASS.match(key):
        raise SealError(f"{what} {name!r} is not a class name (letters, digits, '_' or spaces, not starting "
                        "with a digit)", where)
    return key


@lru_cache(maxsize=8192)
def class_key(name: str) -> str:
    """The key under which class names compare equal (``"sink_basin"``); cached, as planners and
    state checks ask for the same few names again and again."""
    return "_".join(class_words(name))


@dataclass(frozen=True)
class Category:
    """A named set of classes and categories; ``members is None`` means open (everything)."""

    name: str
    members: tuple[str, ...] | None
    where: Where | None = field(default=None, compare=False, repr=False)

    def __post_init__(self) -> None:
        if not class_key(self.name):
            raise SealError("a category needs a name", self.where)
        object.__setattr__(self, "name", check_name_length(class_key(self.name), "category name", self.where))
        if self.members is not None:
            object.__setattr__(self, "members", tuple(check_name_length(class_key(m), f"category {self.name}: member",
                                                                        self.where) for m in self.members))
        odd = [n for n in (self.name, *(self.members or ())) if not _CLASS.match(n)]
        if odd:  # a number ("0x10", "1e309") is no class
            raise SealError(f"category {self.name}: {odd[0]!r} is not a class name (letters, digits and '_', not "
                            "starting with a digit)", self.where)

    @property
    def is_open(self) -> bool:
        return self.members is None


@dataclass(frozen=True)
class Synonyms:
    """Names of one kind of thing: the class ``name`` is also called each of ``names``
    (``fridge``: refrigerator, icebox). Names compare like class names (:func:`class_key`)."""

    name: str
    names: tuple[str, ...]
    where: Where | None = field(default=None, compare=False, repr=False)

    def __post_init__(self) -> None:
        if not class_key(self.name):
            raise SealError("a synonyms entry needs a class name", self.where)
        name = check_name_length(class_key(self.name), "a synonyms entry's class", self.where)
        names = tuple(check_name_length(class_key(n), f"synonyms of {name}: name", self.where) for n in self.names)
        if not names:
            raise SealError(f"synonyms of {name} list no other name", self.where)
        if any(not n for n in names):
            raise SealError(f"synonyms of {name} include an empty name", self.where)
        odd = [n for n in (name, *names) if not _NAME.match(n)]
        if odd:
            raise SealError(f"synonyms of {name}: {odd[0]!r} is not a name (letters, digits and spaces only)",
                            self.where)
        if name in names:
            raise SealError(f"{name} is listed among its own synonyms", self.where)
        repeated = sorted({n for n in names if names.count(n) > 1})
        if repeated:
            raise SealError(f"synonyms of {name} repeat {', '.join(repeated)}", self.where)
        object.__setattr__(self, "name", name)
        object.__setattr__(self, "names", names)

    @property
    def all_names(self) -> tuple[str, ...]:
        return (self.name, *self.names)


@dataclass(frozen=True)
class Taxonomy:
    """The categories of a library, with membership that follows nested categories."""

    categories: tuple[Category, ...] = ()
    world: tuple[str, ...] = ()
    """Predicates the world or the robot's state may make true without any frame (``hand_empty``)."""
    synonyms: tuple[Synonyms, ...] = ()
    """Other English names of classes (``fridge``: refrigerator), in the order declared."""

    @cached_property
    def names(self) -> Mapping[str, tuple[str, ...]]:
        """Each name (class key) of a synonyms entry → the other names of its entry; entries
        with the same class name are one set. (Validation refuses a name in two sets.)"""
        sets: dict[str, dict[str, None]] = {}
        for entry in self.synonyms:
            sets.setdefault(entry.name, {}).update(dict.fromkeys(entry.all_names))
        names: dict[str, tuple[str, ...]] = {}
        for members in sets.values():
            for name in members:
                names.setdefault(name, tuple(n for n in members if n != name))
        return names

    @cached_property
    def by_name(self) -> Mapping[str, Category]:
        return {c.name: c for c in self.categories}

    def __contains__(self, name: object) -> bool:
        return isinstance(name, str) and class_key(name) in self.by_name

    @cached_property
    def _closure(self) -> Mapping[str, frozenset[str]]:
        """Each closed category's members, following nested categories (cycles are cut)."""
        closure: dict[str, frozenset[str]] = {}
        for name in self.by_name:
            seen: set[str] = set()
            stack = [name]
            while stack:
                category = self.by_name.get(stack.pop())
                for member in (category.members or ()) if category else ():
                    if member not in seen:
                        seen.add(member)
                        stack.append(member)
            closure[name] = frozenset(seen)
        return closure

    @cached_property
    def known_classes(self) -> frozenset[str]:
        """Every class named as a member somewhere (categories excluded)."""
        return frozenset(m for ms in self._closure.values() for m in ms if m not in self.by_name)

    def members(self, category: str) -> frozenset[str]:
        """The classes (not categories) of a closed category."""
        return frozenset(m for m in self._closure.get(class_key(category), ()) if m not in self.by_name)

    def is_open(self, category: str) -> bool:
        found = self.by_name.get(class_key(category))
        # the closure already follows nested categories, so no recursion (a category may list itself)
        return bool(found and (found.is_open or any(self.by_name[m].is_open for m in self._closure[found.name]
                                                     if m in self.by_name)))

    def is_a(self, cls: str, category: str) -> bool | None:
        """Whether ``cls`` belongs to ``category``: True, False, or None when nobody can tell.

        A class belongs to itself and to every open category. A class nobody has listed (the
        vocabulary is open) is None for closed categories: not known to be a member, nor known
        not to be one.
        """
        cls, category = class_key(cls), class_key(category)
        if cls == category or cls in self._closure.get(category, ()):
            return True
        if self.is_open(category):
            return True
        if cls in self.known_classes or cls in self.by_name:
            return False
        return None

    def kin(self, cls: str) -> tuple[str, frozenset[str]] | None:
        """The smallest closed category that lists ``cls`` (directly or through a nested one) and another class,
        and those other classes: the kind of thing it is, and what else is of that kind ("cup": container, with
        mug, glass, bowl, ...); None for a class no closed category lists. Of two the same size, the first
        declared."""
        cls = class_key(cls)
        best: tuple[str, frozenset[str]] | None = None
        for name in self.by_name:
            members = self.members(name)
            if cls not in members or self.is_open(name) or len(members) < 2:
                continue
            if best is None or len(members) < len(best[1]) + 1:
                best = (name, members - {cls})
        return best

    def merged(self, other: Taxonomy) -> Taxonomy:
        """Both taxonomies; a category declared in both takes the union of members."""
        merged: dict[str, Category] = dict(self.by_name)
        for category in other.categories:
            mine = merged.get(category.name)
            if mine is None:
                merged[category.name] = category
            elif mine.members is not None and category.members is not None:
                members = tuple(dict.fromkeys(mine.members + category.members))
                merged[category.name] = Category(category.name, members, mine.where)
            else:
                merged[category.name] = Category(category.name, None, mine.where)
        return Taxonomy(tuple(merged.values()), tuple(dict.fromkeys(self.world + other.world)),
                        self.synonyms + other.synonyms)

    @classmethod
    def of(cls, categories: Mapping[str, Iterable[str] | None], world: Iterable[str] = ()) -> Taxonomy:
        """Build from a plain mapping, as in tests: ``Taxonomy.of({"utensil": ["spoon"]})``."""
        return cls(tuple(Category(n, None if m is None else tuple(m)) for n, m in categories.items()),
                   tuple(world))
