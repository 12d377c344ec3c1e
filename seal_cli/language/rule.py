"""A construction of the tagger as a value: :class:`Rule`, what it finds (:class:`Match`), and its
worked examples (:class:`Example`).

A rule looks at the tagger's state at word ``i`` and either declines (``None``) or says what the
words there are: how many it consumes, the tagged words it emits, the last tagged word it
replaces (a name going on: "Mary *Ann*"), the statements it drops beside the command (remarks),
and what the tagger expects next (a verb, or not). It changes nothing itself: the tagger applies
the match. The rules of a table are tried in order, so precedence is the order of a visible list
(:mod:`seal_cli.language.rules`).
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass
from typing import TYPE_CHECKING, NamedTuple

from seal_cli.language.tags import Tag
from seal_cli.language.tokens import Word

if TYPE_CHECKING:
    from seal_cli.language.state import State

__all__ = ["AFTER_SEP", "START", "Example", "Match", "Rule", "after_all_but"]

AFTER_SEP = "after-sep"
"""``Match.expect``: expect a verb when the last tagged word, the match applied, is a separator."""


class Match(NamedTuple):
    """What a rule found at a word (an immutable value: a named tuple, made several times per word, costs a
    third of a frozen dataclass).

    ``consumed``: how many input words it takes (0: it only retags the last word, and the next rule
    of the table is tried). ``words``: the tagged words it emits, in order. ``last``: a word that
    replaces the last tagged word (the last ``replaces`` of them), before ``words``. ``remarks``:
    character spans of statements dropped beside the command. ``expect``: whether a verb is expected
    next (``None``: unchanged, ``AFTER_SEP``: when the last tag is then ``SEP``). ``verb``: the
    lexical unit of a clause's verb it emitted (the last of ``words``); ``particle``: (word index,
    unit) of a split particle to come; ``using``: after "use X", "to" starts the clause of what X is used for.
    """

    consumed: int
    words: tuple[Word, ...] = ()
    last: Word | None = None
    replaces: int = 1
    remarks: tuple[tuple[int, int], ...] = ()
    expect: bool | str | None = None
    verb: str | None = None
    particle: tuple[int, str] | None = None
    using: bool | None = None


@dataclass(frozen=True, slots=True)
class Example:
    """A worked example: tagging ``text`` fires the rule and yields a word ``word`` tagged ``tag``
    (``tag`` empty: the words are dropped, and no tagged word has that text)."""

    text: str
    word: str
    tag: str


@dataclass(frozen=True, slots=True)
class Rule:
    """A named construction: ``match(state, i)`` is pure (see :class:`Match`). Two gates say where it can match at
    all, so that the tagger asks it only there (:class:`~seal_cli.language.lexicon.Gates` indexes the tables by
    them): ``first``, when given, the word's lower-case form is one of these, or satisfies this predicate; ``after``,
    when given, the tag of the last tagged word is one of these (:data:`START`: no word tagged yet). A gate must
    never turn away a word where ``match`` would have matched (``tests/language/test_rules.py`` asks every rule at
    every word of every example, gated or not); ``examples`` are run by a test."""

    name: str
    match: Callable[[State, int], Match | None]
    examples: tuple[Example, ...]
    first: frozenset[str] | Callable[[str], bool] | None = None
    doc: str = ""
    after: frozenset[str] | None = None
    needs: frozenset[str] | None = None

    def admits(self, low: str) -> bool:
        """Whether the rule may match a word read as ``low`` (its gate; asked once per word form)."""
        first = self.first
        return first is None or (low in first if isinstance(first, frozenset) else first(low))

    def follows(self, tag: str) -> bool:
        """Whether the rule may match after a last tagged word tagged ``tag`` (:data:`START`: none)."""
        return self.after is None or tag in self.after


START = ""
"""``Rule.after``: the tag of the last tagged word when none is tagged yet (``State.prev_tag`` at the first word)."""


def after_all_but(*tags: str) -> frozenset[str]:
    """A gate ``after`` that admits every tag, and :data:`START`, but ``tags``."""
    return frozenset([START, *Tag]) - frozenset(tags)
