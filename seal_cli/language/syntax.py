"""The tree of a command as typed values: a lark :class:`~lark.Transformer` with one method per rule
of ``grammars/command.lark`` turns it into :class:`Clause` values holding :class:`NP` and :class:`PP`.

The grammar reads tags, not words, and its trees are shared by commands of one tag sequence; a
tree's tokens point at the tagger's words by index (``start_pos``), so :class:`Syntax` is made for
one command's words and reads them through the tokens. Nothing here knows the frames: which
element a phrase fills is decided later (:mod:`seal_cli.language.roles`), and the clause-to-clause
passes (:mod:`seal_cli.language.clauses`) take the clauses from here.
"""

from __future__ import annotations

from collections.abc import Iterator, Sequence
from dataclasses import dataclass, field, replace
from typing import TYPE_CHECKING, Any

from lark import Token, Transformer, Tree

from seal_cli.language.element_types import Types
from seal_cli.language.english import DIRECTIONS, LOCATED, LOCATIVE, PERSON_PRONOUNS, PRONOUNS, SUBORDINATORS
from seal_cli.language.lexicon import Word, is_plural, noun_lemma

if TYPE_CHECKING:
    from seal_cli.language.grounding import Vocabulary

__all__ = ["NP", "PP", "Clause", "Command", "Item", "Syntax", "end_of"]


@dataclass
class NP:
    """A noun phrase as the grammar found it, before it fills an element."""

    start: int
    end: int
    head: Word | None
    kind: str = "thing"               # person | thing | place | message | pronoun
    pronoun: str | None = None
    quantity: int | None = None
    plural: bool = False
    mods: list[Word] = field(default_factory=list)
    results: list[Word] = field(default_factory=list)
    of: NP | None = None
    contents: list[NP] = field(default_factory=list)      # "the cup with a fork (in it)"
    inner: list[NP] = field(default_factory=list)         # noun phrases inside (for result words)
    conjuncts: list[NP] = field(default_factory=list)
    relative: str | None = None                          # "that I was drinking from"
    relative_start: int = -1
    relative_end: int = -1
    determined: bool = False                             # begins with a determiner ("the", "his", "two")
    possessor: NP | None = None                          # "*the visitor*'s question", "*Jorge*'s question"
    there: bool = False                                  # a bare "there" ending its clause: a place said before
    borrowed: bool = False                               # an earlier clause's object ("to open [it]"): said there
    located: NP | None = None                            # "a person standing *in the corridor*": where it is
    cut: tuple[int, int] | None = None                   # "the light *on* in the hall": a split particle inside
    question: str | None = None                          # a message as the person asked hears it: "do you want tea?"

    @property
    def head_text(self) -> str:
        if self.head is None:
            return ""
        if self.kind == "person" and self.head.tag == "NAME":
            return self.head.text
        return noun_lemma(self.head.text) if self.head.tag in ("WORD", "RESULT") else self.head.lower

    def ground(self, vocabulary: Vocabulary) -> str | None:
        """The class this noun phrase denotes in ``vocabulary`` (conjunctions: the first one)."""
        if self.head is None or self.kind == "message":
            return None
        words = [w.text for w in self.mods] + [self.head.text]
        of = []
        if self.of is not None and self.of.head is not None:
            of = [w.text for w in self.of.mods] + [self.of.head.text]
        return vocabulary.grounded(words, of)

    def all_nps(self) -> Iterator[NP]:
        yield self
        for np in (*self.inner, *self.contents, *self.conjuncts):
            yield from np.all_nps()


@dataclass
class PP:
    """A prepositional phrase: its preposition (the tagger's lemma: "out of"), its noun phrase."""

    prep: str
    np: NP
    start: int
    lead: bool = False         # said before the verb ("with X in hand, ...", "use X to ...")
    describes: bool = False    # after "that is": says where the noun before it is
    after_relative: bool = False   # right after a relative clause: the frame's, or the relative clause's


Item = NP | PP | Word
"""What follows a verb: a noun phrase, a prepositional phrase, or a word of its own (a particle,
"is", a wh-word, "and" between noun phrases, a relative clause kept whole, ...)."""


@dataclass
class Clause:
    """A verb and what was said with it: its objects, the phrases after them, what it says."""

    verb: Word
    objects: list[NP]
    items: list[Item]                # after the objects
    message: NP | None
    start: int
    end: int
    held: list[NP] = field(default_factory=list)     # "with X in hand": held while the clause is done
    sub: str | None = None                           # "before"/"after"/"when"... said before the verb
    conditions: list[str] = field(default_factory=list)   # "when the water boils"
    gap: Clause | None = None                        # "... and the glasses next to them": the verb again
    result: list[PP] = field(default_factory=list)   # "cut the cake *into slices*"
    unit: str | None = None                          # the lexical unit when not the verb's ("give it a *stir*")
    asked: str | None = None                         # the state a yes/no question asks ("is the fridge *open*?")


@dataclass(frozen=True)
class Command:
    """The clauses of a command as said, each with the separator before it ("", "and", "then", ...)."""

    clauses: tuple[Clause, ...]
    joins: tuple[str, ...]


def end_of(item: Item) -> int:
    """Where an item ends (a prepositional phrase: where its noun phrase does)."""
    if isinstance(item, NP):
        return item.end
    if isinstance(item, PP):
        return item.np.end
    return int(item.end)


@dataclass
class _Postmod:
    first: Word                      # "of", or the participle
    items: list[Item]


@dataclass
class _Polite:
    words: list[Word]


@dataclass
class _Lead:
    pps: list[PP]


class Syntax(Transformer[Token, Command]):
    """One command's tree → :class:`Command` (its clauses are raw: every phrase after the verb is
    in ``items``, in order; :class:`seal_cli.language.clauses.Clauses` reads the objects out)."""

    def __init__(self, text: str, words: Sequence[Word], types: Types) -> None:
        super().__init__()
        self.text = text
        self.words = words
        self.types = types

    def transform(self, tree: Tree[Token]) -> Command:
        """The command of the tree: each rule's method on its children's values, bottom up. (Lark's
        own walk, with its exception wrapping and a lookup per node, costs a sixth of a parse; this one
        calls the same methods.)"""
        return self._value(tree)

    def _value(self, tree: Tree[Token]) -> Any:
        words, value = self.words, self._value
        children: list[Any] = []
        for child in tree.children:
            if type(child) is Tree:
                children.append(value(child))
            elif child.type == "HERE":        # type: ignore[union-attr]
                children.append(self.HERE(child))   # type: ignore[arg-type]
            else:
                children.append(words[child.start_pos])   # type: ignore[union-attr,index]
        return _RULES[tree.data](self, children)

    # -- tokens --------------------------------------------------------------------------------
    def __default_token__(self, token: Token) -> Word:
        return self.words[token.start_pos]   # type: ignore[index]

    def HERE(self, token: Token) -> PP | Word:   # noqa: N802 (the tag's name)
        """"come here": a place said by pointing; a bare "there" ending its clause ("... and count the
        bikes there", "... there too") is a place said before."""
        word = self.words[token.start_pos]   # type: ignore[index]
        nxt = token.start_pos + 1            # type: ignore[operator]
        while nxt < len(self.words) and self.words[nxt].info == "time":
            nxt += 1                          # "... there too", "... there right away"
        there = word.lower == "there" and (nxt == len(self.words) or self.words[nxt].tag in ("SEP", "END"))
        prep = "toward" if word.lower in DIRECTIONS or word.info == "toward" else \
            "from" if word.info == "from" else "at"       # "carry the box *upstairs*"; "get a cup *from there*"
        return PP(prep, NP(word.start, word.end, word, "place", there=there), word.start)

    # -- the command and its clauses -----------------------------------------------------------
    def start(self, children: list[Any]) -> Command:
        clauses: list[Clause] = []
        joins: list[str] = []                     # the separator before each clause
        sep = ""
        for child in children:
            if isinstance(child, Clause):
                clauses.append(child)
                joins.append(sep)
                sep = ""
            elif isinstance(child, Word) and child.tag == "SEP":
                sep = child.info if isinstance(child.info, str) else child.text.lower()
        return Command(tuple(clauses), tuple(joins))

    def clause(self, children: list[Any]) -> Clause:
        verb, items = next(c for c in children if isinstance(c, tuple))
        sub: str | None = None
        conditions: list[str] = []
        asked: str | None = None
        for child in children:
            if isinstance(child, _Lead):         # "with a clock in hand, turn on the lamp": as if said after
                items.extend(replace(pp, lead=True) for pp in child.pps)
            elif isinstance(child, _Polite):
                for word in child.words:
                    if isinstance(word.info, str) and word.info in SUBORDINATORS:
                        sub = word.info          # "before you go to the garage, ..."
                    elif word.info == "time":    # "in five minutes, turn off the oven": the frame's time
                        text = word.text.rstrip(",;: ")
                        items.append(Word(text, word.start, word.start + len(text), "PARTICLE", "time"))
            elif isinstance(child, Word) and child.tag == "COND" and child.info == "asked":
                asked = child.text           # "is the fridge *open*?": the state asked, no condition
            elif isinstance(child, Word) and child.tag == "COND":
                conditions.append(child.text.rstrip(",;: "))
        return Clause(verb, [], items, None, verb.start, verb.end, [], sub, conditions, asked=asked)

    def verb_phrase(self, children: list[Any]) -> tuple[Word, list[Item]]:
        items: list[Item] = []
        for child in children[1:]:
            items.extend(child if isinstance(child, list) else [child])   # a predicate and where (below)
        return children[0], items

    def polite(self, children: list[Word]) -> _Polite:
        return _Polite(children)

    def cond(self, children: list[Word]) -> Word:
        return children[0]

    def lead(self, children: list[Any]) -> _Lead:
        return _Lead([c for c in children if isinstance(c, PP)])

    def pp(self, children: list[Any]) -> PP:
        prep, np, *described = children
        if described:                        # "for someone *sitting (on the sofa)*": the pronoun's description
            np = replace(np, end=max(end_of(x) for x in (described[0] if isinstance(described[0], list)
                                                         else described)))
        return PP(str(prep.info), np, prep.start)

    def predicate(self, children: list[Any]) -> Word | list[Any]:
        """A participle that describes a noun away from it ("are *wearing hats*"): one word. Said with a place
        ("how many people are *sitting on the sofa*"), the place is a phrase of the clause (where they are:
        Count's ground), after the participle's word."""
        first = children[0]
        if first.tag == "VBG_P" and len(children) == 2 and isinstance(children[1], PP) and \
                children[1].prep in LOCATIVE:
            return [Word(first.text, first.start, first.end, "PREDICATE", first.info), children[1]]
        end = first.end
        for child in children[1:]:
            end = max(end, end_of(child))
        return Word(self.text[first.start:end], first.start, end, "PREDICATE", first.info)

    # -- noun phrases --------------------------------------------------------------------------
    def pron_np(self, children: list[Word]) -> NP:
        w = children[0]
        said = w.lower.split()         # "one of them": the pronoun is "them" (its quantifier, the word's info);
        low = said[-1] if said[-1] in PRONOUNS else said[0]     # "them both": "them"
        pron_kind = "person" if low in PERSON_PRONOUNS else "thing" if low in (
            "it", "this", "that", "these", "those", "something", "everything", "anything", "nothing", "itself") \
            else "pronoun"      # "take *these* to the kitchen": pointing at things (people are "them", "these people")
        return NP(w.start, w.end, w, pron_kind, pronoun=low, plural=low in ("them", "they", "ones", "these",
                                                                            "those") and w.info != "one")

    def name_np(self, children: list[Word]) -> NP:
        w = children[0]
        if len(children) > 1:                # "Gate 5": a numbered place or thing, no person
            return NP(w.start, children[1].end, w, "thing")
        return NP(w.start, w.end, w, "person")

    def det_np(self, children: list[Any]) -> NP:
        return self._np(children, determined=True)

    def bare_np(self, children: list[Any]) -> NP:
        return self._np(children, determined=False)

    def nominal(self, children: list[Word]) -> list[Word]:
        return children

    def postmod(self, children: list[Any]) -> _Postmod:
        return _Postmod(children[0], children[1:])

    def _np(self, children: list[Any], determined: bool) -> NP:
        np = NP(-1, -1, None, determined=determined)
        for child in children:
            if isinstance(child, list):
                words = list(child)
                if words[-1].tag == "LABEL":    # "room 214": the noun is the head, its number in the text
                    np.end = words.pop().end
                np.head = words[-1]
                np.mods = [w for w in words[:-1] if w.tag == "WORD"]
                np.results = [w for w in words[:-1] if w.tag == "RESULT"]
                np.start = words[0].start if np.start < 0 else np.start
                np.end = max(np.end, words[-1].end)
            elif isinstance(child, _Postmod):
                self._postmod(np, child)
            else:
                w = child
                np.start = w.start if np.start < 0 else np.start
                if w.tag == "NUM":
                    np.quantity = int(w.info) if isinstance(w.info, int) else None
                elif w.tag == "POSS" and isinstance(w.info, str):     # "the visitor's": whose it is
                    name = w.info[:1].isupper() and any(c.islower() for c in w.info[1:])
                    owner = Word(w.info, w.start, w.start + len(w.info), "NAME" if name else "WORD")
                    person = name or self.types.is_a(noun_lemma(w.info), "person") is True
                    np.possessor = NP(np.start, owner.end, owner, "person" if person else "thing")
        assert np.head is not None
        np.plural = is_plural(np.head.text) or (np.quantity or 0) > 1
        np.kind = "person" if self.types.is_a(np.head_text, "person") is True and \
            not self.types.is_open("person") else "thing"
        return np

    def _postmod(self, np: NP, postmod: _Postmod) -> None:
        first = postmod.first
        if first.tag == "OF":
            inner = postmod.items[0]
            assert isinstance(inner, NP)
            np.of = inner
            np.inner.append(inner)
            np.end = inner.end
            return
        end = first.end
        for item in postmod.items:
            if isinstance(item, Word) and item.tag in ("VBG_T", "VBG_P", "VBG_I"):
                first = item                   # "sitting and *wearing* red shirts": the next participle's
            if isinstance(item, NP):
                np.inner.append(item)
                if first.info in ("contain", "hold", "have", "carry"):
                    np.contents.append(item)
            elif isinstance(item, PP):
                np.inner.append(item.np)
                verb_of_its_own = self.types.evoked_by(f"{first.info} {item.prep}")   # "turning on a lamp"
                if first.tag == "VBG_P" and item.prep in LOCATED and not verb_of_its_own:
                    np.located = item.np           # "the kids playing *in the yard*": where they are
            end = max(end, end_of(item))
        np.end = end


_RULES = {name: getattr(Syntax, name) for name in ("start", "clause", "verb_phrase", "polite", "cond", "lead", "pp",
                                                   "predicate", "pron_np", "name_np", "det_np", "bare_np", "nominal",
                                                   "postmod")}
"""The grammar's rules (``grammars/command.lark``) and the methods that read them."""
