"""The parts a word plays in a command: the terminals of ``grammars/command.lark``.

One enum, listed once; a test checks it against the grammar's ``%declare`` line, so a tag the
tagger emits is a terminal the grammar knows and the other way round. Members are strings
(``Tag.VERB == "VERB"``), so a tag sequence keys the parser's cache of trees as before.
"""

from __future__ import annotations

import re
from collections.abc import Iterator
from pathlib import Path

from seal_cli.resources import grammar_path

__all__ = ["NP_START", "Tag", "declared_tags"]


class _Tags(type):
    """The type of :class:`Tag`: iterating the class gives its members, in the order they are listed."""

    _members: tuple[Tag, ...]

    def __iter__(cls) -> Iterator[Tag]:
        return iter(cls._members)

    def __len__(cls) -> int:
        return len(cls._members)


class Tag(str, metaclass=_Tags):
    """What a word is to the grammar (see the comment at the top of ``grammars/command.lark``).

    Each member is an instance of this ``str`` subclass, so ``Tag.VERB == "VERB"`` and ``isinstance(w.tag, Tag)``
    hold as they did for the ``enum.StrEnum`` it was, and ``.value`` is the plain string. Not an enum: in Python
    3.11 every ``Tag.VERB`` read through an enum's class costs five times a plain class attribute (its metaclass's
    ``__getattr__`` hook), and the tagger's rules read a tag a few hundred thousand times a second."""

    __slots__ = ()

    VERB = "VERB"            # a lexical unit ("bring", "pick up", "tell me how many")
    PARTICLE = "PARTICLE"    # the split particle of a verb, a preposition without object, a time adverbial
    SEP = "SEP"              # what joins clauses: "," "and" "then" "." ...
    POLITE = "POLITE"        # "please", "could you", "robot", a remark said before the command
    END = "END"              # a final "." "!" "?"
    DET = "DET"
    NUM = "NUM"
    POSS = "POSS"            # "their", "Roger's"
    PRON = "PRON"
    NAME = "NAME"            # a capitalised word where a noun phrase starts
    WORD = "WORD"            # every other word: a noun or an adjective
    RESULT = "RESULT"        # a word naming a frame's result before a noun ("heated", "clean")
    OF = "OF"
    PREP = "PREP"
    VBG_T = "VBG_T"          # a participle after a noun, with an object
    VBG_P = "VBG_P"          # ... with a prepositional phrase
    VBG_I = "VBG_I"          # ... bare
    WH = "WH"
    BE = "BE"
    THERE = "THERE"          # existential "there"
    HERE = "HERE"            # locative "here", "there", "where it belongs"
    AND_NP = "AND_NP"        # "and" between noun phrases
    AND_VBG = "AND_VBG"      # "and" between two participles of one noun ("sitting *and* wearing a hat")
    COND = "COND"            # a condition on the world, kept whole
    REL = "REL"              # a relative clause kept whole
    SAID = "SAID"            # what is said after a verb of saying, kept whole
    LABEL = "LABEL"          # a number naming a numbered thing ("room 214")

    @property
    def value(self) -> str:
        """The tag as a plain string."""
        return str.__str__(self)

    def __repr__(self) -> str:
        return f"<Tag.{self.value}>"


Tag._members = tuple(Tag(value) for name, value in vars(Tag).items() if name.isupper() and isinstance(value, str))
for _member in Tag._members:
    setattr(Tag, _member.value, _member)


NP_START = frozenset({Tag.DET, Tag.NUM, Tag.POSS, Tag.PRON, Tag.NAME, Tag.WORD, Tag.RESULT})
"""Tags that can begin a noun phrase."""

_DECLARE = re.compile(r"^%declare\s+(.+)$", re.MULTILINE)


def declared_tags(grammar: Path | None = None) -> frozenset[str]:
    """The terminals a grammar declares (its ``%declare`` lines; the shipped ``command.lark`` by default)."""
    grammar = grammar or grammar_path("command.lark")
    return frozenset(name for line in _DECLARE.findall(grammar.read_text(encoding="utf-8")) for name in line.split())
