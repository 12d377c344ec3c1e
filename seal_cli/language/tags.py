"""The parts a word plays in a command: the terminals of ``grammars/command.lark``.

One enum, listed once; a test checks it against the grammar's ``%declare`` line, so a tag the
tagger emits is a terminal the grammar knows and the other way round. Members are strings
(``Tag.VERB == "VERB"``), so a tag sequence keys the parser's cache of trees as before.
"""

from __future__ import annotations

import enum
import re
from pathlib import Path

from seal_cli.resources import grammar_path

__all__ = ["NP_START", "Tag", "declared_tags"]


class Tag(enum.StrEnum):
    """What a word is to the grammar (see the comment at the top of ``grammars/command.lark``)."""

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
    COND = "COND"            # a condition on the world, kept whole
    REL = "REL"              # a relative clause kept whole
    SAID = "SAID"            # what is said after a verb of saying, kept whole
    LABEL = "LABEL"          # a number naming a numbered thing ("room 214")


NP_START = frozenset({Tag.DET, Tag.NUM, Tag.POSS, Tag.PRON, Tag.NAME, Tag.WORD, Tag.RESULT})
"""Tags that can begin a noun phrase."""

_DECLARE = re.compile(r"^%declare\s+(.+)$", re.MULTILINE)


def declared_tags(grammar: Path | None = None) -> frozenset[str]:
    """The terminals a grammar declares (its ``%declare`` lines; the shipped ``command.lark`` by default)."""
    grammar = grammar or grammar_path("command.lark")
    return frozenset(name for line in _DECLARE.findall(grammar.read_text(encoding="utf-8")) for name in line.split())
