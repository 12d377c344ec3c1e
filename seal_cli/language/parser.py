"""The command language: text → the frames it evokes, with their elements filled.

:func:`parse_command` tags the words (:mod:`seal_cli.language.lexicon`), parses the tags with the LALR
grammar ``grammars/command.lark``, and turns each clause into an :class:`Evoked` frame:

1. **Which frame.** A verb's lexical unit may evoke several frames ("take": Pick, Bring,
   Guide). Each is tried: the direct object fills the frame's first element, an indirect object
   its recipient, and each prepositional phrase the role its preposition names (FrameNet's
   names: *to* → goal or recipient, *from* → source, *with* → instrument, *in/on/at* → ground,
   goal or instrument). A realised role the frame lacks excludes it; the others are scored by
   how well each phrase fits its element's type (a person where a person is wanted), and the
   frame with the fewest unfilled elements wins a tie.
2. **Which phrase a preposition describes.** A prepositional phrase the frame has no role for
   describes the noun before it ("the person *at the sofa*").
3. **Pronouns** ("it", "them", "one") refer to an element of an earlier frame that fits
   (``refers_to``); an omitted object of a frame that needs its object in hand refers to the
   object of the frame before ("pick up the apple and put [it] in the fridge").
4. **Result words** evoke frames of their own before the clause's frame: "put a *heated* egg
   in the fridge" is Heat(egg), Place(egg, fridge); and "put the cup *with the fork* on the
   table" puts the fork in the cup first.
5. **Defaults**: an element the command omits takes the frame's default, marked ``default``.
6. **Grounding**: with a :class:`~seal_cli.language.grounding.Vocabulary`, each element gets the class
   it denotes (``cls``), else None.
"""

from __future__ import annotations

import difflib
from collections.abc import Iterable, Iterator, Mapping, Sequence
from dataclasses import dataclass, field, replace
from typing import TYPE_CHECKING, Any

from lark import Tree

from seal_cli.errors import SealError
from seal_cli.frames.library import Library
from seal_cli.frames.model import Frame
from seal_cli.language.english import FIRST_LATER, PERSON_PRONOUNS, PRONOUNS, SUBORDINATORS
from seal_cli.language.grounding import PIECES, PORTIONS
from seal_cli.language.lexicon import (
    CommandError,
    Lexicon,
    Mention,
    Tagger,
    Word,
    is_plural,
    mentions,
    noun_lemma,
    tokenize,
)
from seal_cli.language.morphology import is_gradable

if TYPE_CHECKING:
    from lark import Lark

    from seal_cli.language.grounding import Vocabulary

__all__ = ["CommandError", "Evoked", "Parse", "Phrase", "parse_command", "parse_lines"]


# ---------------------------------------------------------------------------------------------
# Values


@dataclass(frozen=True)
class Phrase:
    """What fills a frame element: the words, their head (lemma), the class they denote.

    ``kind`` is "person", "thing", "place" (here, there) or "message"; ``refers_to`` names the
    antecedent of a pronoun as (frame index, element); ``quantity`` a number said ("two
    apples"); ``default`` marks an element filled from the frame's default, not said;
    ``conjuncts`` are the phrases of a coordination ("the apple and the pear"), each grounded
    (the phrase itself stands for the first).
    """

    text: str | None
    head: str
    cls: str | None = None
    kind: str = "thing"
    refers_to: tuple[int, str] | None = None
    quantity: int | None = None
    plural: bool = False
    modifiers: tuple[str, ...] = ()
    default: bool = False
    span: tuple[int, int] | None = field(default=None, compare=False)
    conjuncts: tuple[Phrase, ...] = ()
    relative: str | None = None

    def to_json(self) -> dict[str, Any]:
        data: dict[str, Any] = {"text": self.text, "head": self.head, "class": self.cls}
        if self.kind != "thing":
            data["kind"] = self.kind
        if self.refers_to is not None:
            data["refers_to"] = list(self.refers_to)
        if self.quantity is not None:
            data["quantity"] = self.quantity
        if self.plural:
            data["number"] = "plural"
        if self.modifiers:
            data["modifiers"] = list(self.modifiers)
        if self.default:
            data["default"] = True
        if self.conjuncts:
            data["conjuncts"] = [c.to_json() for c in self.conjuncts]
        if self.relative:
            data["relative"] = self.relative
        return data


@dataclass(frozen=True)
class Evoked:
    """A frame evoked by a verb phrase (or by a result word), with its elements."""

    frame: str
    lexical_unit: str
    span: tuple[int, int]
    elements: Mapping[str, Phrase]
    condition: str | None = None
    result: str | None = None
    time: str | None = None

    def to_json(self) -> dict[str, Any]:
        data = {"frame": self.frame, "lexical_unit": self.lexical_unit, "span": list(self.span),
                "elements": {role: p.to_json() for role, p in self.elements.items()}}
        for key in ("condition", "result", "time"):
            if getattr(self, key):
                data[key] = getattr(self, key)
        return data


@dataclass(frozen=True)
class Parse:
    """A parsed command: the frames it evokes, in the order they are to be done."""

    text: str
    frames: tuple[Evoked, ...]
    remarks: tuple[str, ...] = ()
    """What was said beside the command and dropped: statements, greetings ("*The grandchildren are
    here.*", "..., *she's been waiting a while*")."""

    def to_json(self) -> dict[str, Any]:
        data: dict[str, Any] = {"text": self.text, "frames": [f.to_json() for f in self.frames]}
        if self.remarks:
            data["remarks"] = list(self.remarks)
        return data

    def resolve(self, phrase: Phrase) -> Phrase:
        """The phrase a pronoun stands for (the phrase itself when it is not one)."""
        seen = 0
        while phrase.refers_to is not None and seen < len(self.frames):
            index, role = phrase.refers_to
            phrase = self.frames[index].elements[role]
            seen += 1
        return phrase


# ---------------------------------------------------------------------------------------------
# The parser (grammar built once) and the lexicon of each library (cached)

_PARSER: Lark | None = None
_LEXICONS: dict[int, tuple[Library, Lexicon, Types]] = {}


class Types:
    """The library's taxonomy, asked the same few questions many times: memoised."""

    def __init__(self, library: Library) -> None:
        self.taxonomy = library.taxonomy
        self._is_a: dict[tuple[str, str], bool | None] = {}
        self._open: dict[str, bool] = {}
        self._roles: dict[str, frozenset[str]] = {}
        self._relations: dict[str, Any] = {}
        self._states: dict[str, bool] = {}

    def roles(self, frame: Frame) -> frozenset[str]:
        """The frame's element roles (asked for every phrase of every clause: memoised by name)."""
        found = self._roles.get(frame.name)
        if found is None:
            found = self._roles[frame.name] = frozenset(e.role for e in frame.elements)
        return found

    def makes_state(self, frame: Frame) -> bool:
        """See :meth:`Builder.makes_state` (memoised by name)."""
        found = self._states.get(frame.name)
        if found is None:
            first = frame.elements[0].role if frame.elements else None
            found = self._states[frame.name] = "goal" not in self.roles(frame) and any(
                not p.negated and p.args == (first,) for p in frame.postconditions)
        return found

    def relation(self, frame: Frame) -> Any:
        """The frame's positive postcondition relating its first element to another
        (``in(theme, goal)``), or None; memoised by name."""
        if frame.name not in self._relations:
            first = frame.elements[0].role if frame.elements else None
            self._relations[frame.name] = next((p for p in frame.postconditions if not p.negated
                                                and len(p.args) == 2 and p.args[0] == first), None)
        return self._relations[frame.name]

    def is_a(self, cls: str, type_: str) -> bool | None:
        key = (cls, type_)
        if key not in self._is_a:
            self._is_a[key] = self.taxonomy.is_a(cls, type_)
        return self._is_a[key]

    def is_open(self, type_: str) -> bool:
        if type_ not in self._open:
            self._open[type_] = self.taxonomy.is_open(type_)
        return self._open[type_]

    def is_person(self, type_: str) -> bool:
        """A type only people belong to (``person``)."""
        return self.is_a("person", type_) is True and not self.is_open(type_)

    def is_location(self, type_: str) -> bool:
        """A type rooms belong to (``location``): where things are, not what they are."""
        return not self.is_open(type_) and self.is_a("room", type_) is True


def command_parser(strict: bool = False) -> Lark:
    """The LALR parser of ``grammars/command.lark`` over tagged words (Lark caches its tables
    on disk, so a new process builds it in milliseconds)."""
    global _PARSER
    if _PARSER is not None and not strict:
        return _PARSER
    from lark import Lark

    from seal_cli.resources import grammar_path

    grammar = grammar_path("command.lark").read_text(encoding="utf-8")
    parser = Lark(grammar, parser="lalr", lexer=_tag_lexer(), strict=strict, maybe_placeholders=False,
                  cache=not strict)
    if not strict:
        _PARSER = parser
    return parser


def _tag_lexer() -> type:
    """The lexer that hands the tagger's words to Lark as tokens (made once, importable by name
    so that Lark's cache can refer to it)."""
    global TagLexer
    if TagLexer is None:
        from lark import Token
        from lark.lexer import Lexer

        class _TagLexer(Lexer):
            def __init__(self, lexer_conf: Any) -> None:
                pass

            def lex(self, data: Any) -> Iterator[Token]:   # type: ignore[override]
                for i, w in enumerate(data):   # start_pos is the word's index: trees are shared by shape
                    yield Token(w.tag, w.text, i, 1, w.start + 1, 1, w.end + 1, w.end)

        _TagLexer.__name__ = _TagLexer.__qualname__ = "TagLexer"
        TagLexer = _TagLexer
    return TagLexer


TagLexer: type | None = None


def lexicon_of(library: Library) -> tuple[Lexicon, Types]:
    """The library's lexicon and memoised types (made once per library)."""
    found = _LEXICONS.get(id(library))
    if found is not None and found[0] is library:
        return found[1], found[2]
    lexicon, types = Lexicon.of(library), Types(library)
    _LEXICONS[id(library)] = (library, lexicon, types)
    return lexicon, types


# ---------------------------------------------------------------------------------------------
# Entry points


def parse_command(text: str, library: Library, vocabulary: Vocabulary | None = None) -> Parse:
    """The frames a command evokes. Raises :class:`CommandError` (a SealError with a column and
    what was expected) when it cannot be parsed."""
    from lark.exceptions import UnexpectedInput

    lexicon, types = lexicon_of(library)
    if not text.strip():
        raise CommandError("empty command: expected a verb, such as " + _some_verbs(lexicon), 1, text,
                           ["a verb"])
    tagger = Tagger(lexicon, tokenize(text), text)
    words = tagger.run()
    if not words:
        raise CommandError("no words in the command: expected a verb, such as " + _some_verbs(lexicon),
                           _first_column(text), text, ["a verb"])
    tags = tuple(w.tag for w in words)
    tree = _TREES.get(tags)
    if tree is None:
        try:
            tree = command_parser().parse(words)
        except UnexpectedInput as error:
            raise _explain(error, text, words, lexicon) from None
        if len(_TREES) >= 4096:
            _TREES.clear()
        _TREES[tags] = tree
    if vocabulary is not None:
        vocabulary = with_library_synonyms(vocabulary, library)
    parse = Builder(text, library, types, vocabulary, words, tagger.remarks).command(tree)
    if tagger.remarks:
        parse = replace(parse, remarks=tuple(text[a:b] for a, b in tagger.remarks))
    return parse


_TREES: dict[tuple[str, ...], Tree] = {}
"""Parse trees by tag sequence. The grammar reads tags, not words, and a tree's tokens point at
words by their index, so commands of one shape ("take the X from the Y") share one parse."""


_MERGED: dict[tuple[int, int], tuple[Vocabulary, Library, Vocabulary]] = {}


def with_library_synonyms(vocabulary: Vocabulary, library: Library) -> Vocabulary:
    """The vocabulary with the library's synonyms of its classes (``framelib/synonyms.yaml``:
    a map's ``Fridge`` is also called "refrigerator"); made once per vocabulary and library."""
    key = (id(vocabulary), id(library))
    found = _MERGED.get(key)
    if found is not None and found[0] is vocabulary and found[1] is library:
        return found[2]
    merged = vocabulary.with_synonyms(library.taxonomy.names)
    if len(_MERGED) > 64:
        _MERGED.clear()
    _MERGED[key] = (vocabulary, library, merged)
    return merged


def parse_lines(lines: Iterable[str], library: Library,
                vocabulary: Vocabulary | None = None) -> Iterator[dict[str, Any]]:
    """One JSON object per line: the parse, or ``{"text", "error"}`` for a line that cannot be parsed."""
    for line in lines:
        text = line.rstrip("\r\n")
        try:
            yield parse_command(text, library, vocabulary).to_json()
        except SealError as error:
            yield {"text": text, "error": _error_json(error)}


def _error_json(error: SealError) -> dict[str, object]:
    if isinstance(error, CommandError):
        return error.to_json()
    return {"message": error.message, "column": error.column, "expected": []}


# ---------------------------------------------------------------------------------------------
# Errors a person can act on

_DESCRIBE = {"VERB": "a verb", "DET": "a noun phrase", "WORD": "a noun phrase", "NAME": "a noun phrase",
             "PRON": "a noun phrase", "NUM": "a noun phrase", "POSS": "a noun phrase", "RESULT": "a noun phrase",
             "PREP": "a preposition", "SEP": "'and' or ','", "END": "the end of the command",
             "$END": "the end of the command", "POLITE": "a verb", "OF": "'of'", "PARTICLE": "a particle",
             "VBG_T": "a participle", "VBG_P": "a participle", "VBG_I": "a participle", "WH": "a question",
             "BE": "'is' or 'are'", "THERE": "'there'", "HERE": "'here'", "AND_NP": "'and'",
             "SAID": "what is said"}


def _some_verbs(lexicon: Lexicon, near: str | None = None) -> str:
    verbs = [v for v in lexicon.verbs]
    close = difflib.get_close_matches(near, verbs, n=3, cutoff=0.6) if near else []
    shown = close + [v for v in ("bring", "find", "go", "pick up", "put", "follow", "tell") if v in verbs
                     and v not in close]
    shown += [v for v in verbs if v not in shown][: max(0, 8 - len(shown))]
    return ", ".join(shown[:8]) + (f" ({len(verbs)} in all; `seal frames` lists them)" if len(verbs) > 8 else "")


def _first_column(text: str) -> int:
    stripped = len(text) - len(text.lstrip())
    return stripped + 1


def _explain(error: Any, text: str, words: Sequence[Word], lexicon: Lexicon) -> CommandError:
    from lark.exceptions import UnexpectedToken

    expected = sorted({_DESCRIBE.get(t, t.lower()) for t in getattr(error, "expected", ()) or ()})
    if not isinstance(error, UnexpectedToken):
        return CommandError("cannot parse the command", 1, text, expected)
    token = error.token
    at_end = token.type == "$END"
    column = len(text.rstrip()) + 1 if at_end else words[token.start_pos].start + 1
    wants_verb = "VERB" in (error.expected or ())
    if wants_verb and not at_end and token.type not in ("END", "SEP"):
        word = str(token).split()[0].lower()
        return CommandError(f"unknown verb {word!r}; known verbs include {_some_verbs(lexicon, word)}",
                            column, text, ["a verb"])
    before = _word_before(words, words[token.start_pos].start if not at_end else len(text))
    after = f" after {before!r}" if before else ""
    if wants_verb:
        return CommandError(f"expected a verb{after}, such as {_some_verbs(lexicon)}", column, text, ["a verb"])
    if at_end:
        return CommandError(f"the command ends too early{after}: expected {_either(expected)}", column, text,
                            expected)
    return CommandError(f"unexpected {str(token)!r}{after}: expected {_either(expected)}", column, text, expected)


def _word_before(words: Sequence[Word], position: int) -> str | None:
    before = [w for w in words if w.end <= position]
    return before[-1].text if before else None


def _either(options: Sequence[str]) -> str:
    if not options:
        return "something else"
    return options[0] if len(options) == 1 else ", ".join(options[:-1]) + " or " + options[-1]


# ---------------------------------------------------------------------------------------------
# Noun phrases as read from the tree


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

    @property
    def head_text(self) -> str:
        if self.head is None:
            return ""
        if self.kind == "person" and self.head.tag == "NAME":
            return self.head.text
        return noun_lemma(self.head.text) if self.head.tag in ("WORD", "RESULT") else self.head.lower

    def all_nps(self) -> Iterator[NP]:
        yield self
        for np in (*self.inner, *self.contents, *self.conjuncts):
            yield from np.all_nps()


@dataclass
class PP:
    prep: str
    np: NP
    start: int
    lead: bool = False         # said before the verb ("with X in hand, ...", "use X to ...")
    describes: bool = False    # after "that is": says where the noun before it is
    after_relative: bool = False   # right after a relative clause: the frame's, or the relative clause's


@dataclass
class Clause:
    verb: Word
    objects: list[NP]
    items: list[Any]                 # NP | PP | Word (PARTICLE, BE, WH, ...) after the objects
    message: NP | None
    start: int
    end: int
    held: list[NP] = field(default_factory=list)     # "with X in hand": held while the clause is done
    sub: str | None = None                           # "before"/"after"/"when"... said before the verb
    conditions: list[str] = field(default_factory=list)   # "when the water boils"
    gap: Clause | None = None                        # "... and the glasses next to them": the verb again
    result: list[PP] = field(default_factory=list)   # "cut the cake *into slices*"


_PLACES = ("goal", "ground", "source")
"""The roles that say where (FrameNet's names)."""
LIGHT_VERBS = ("give",)
"""Verbs that lend their clause to an action noun: "give the sauce a stir" is stirring it."""
_TO = ("to", "into", "onto")
_FROM = ("from", "out of", "off")
_LOCATIVE = ("in", "on", "at", "near", "under", "by", "inside", "behind", "above", "over", "in front of",
             "between", "around", "across", "through", "along", "beyond", "against", "outside", "past")
_ATTACHABLE = _LOCATIVE + ("with", "without", "about", "for", "via", "of")
_PUT_IN = ("in", "on", "inside", "into", "onto")


class Builder:
    """Turns the tree of one command into frames (see the module docstring)."""

    def __init__(self, text: str, library: Library, types: Types, vocabulary: Vocabulary | None,
                 words: Sequence[Word], remarks: Sequence[tuple[int, int]] = ()) -> None:
        self.text = text
        self.remarks = remarks
        self._mentions: list[Mention] | None = None
        self.library = library
        self.taxonomy = types
        self.vocabulary = vocabulary
        self.words = words
        self.frames: list[Evoked] = []
        self.kinds: list[dict[str, str]] = []          # kind of each frame's elements, for pronouns
        self.cut: set[int] = set()                     # noun phrases of pieces already seen to (cut_for)
        self.clause_frames = 0                         # frames of the clauses before the one being built

    # -- the tree ------------------------------------------------------------------------------
    def word(self, token: Any) -> Word:
        return self.words[token.start_pos]

    def command(self, tree: Tree) -> Parse:
        clauses: list[Clause] = []
        joins: list[str] = []                     # the separator before each clause
        sep = ""
        for child in tree.children:
            if str(getattr(child, "data", "")) == "clause":
                clauses.append(self.read_clause(child))
                joins.append(sep)
                sep = ""
                if clauses[-1].gap is not None:   # "put the plates on the table and the glasses next to them"
                    clauses.append(clauses[-1].gap)
                    joins.append("and")
            elif not isinstance(child, Tree) and child.type == "SEP":
                word = self.word(child)           # the word, not the token: trees are shared
                sep = word.info if isinstance(word.info, str) else word.text.lower()
        self.subordinate(clauses)
        for k in range(len(clauses) - 1):         # "slice and chill an apple": both the apple
            bare, nxt = clauses[k], clauses[k + 1]
            if not (bare.objects or bare.items or bare.message or bare.held) and nxt.objects and \
                    not set(joins[k + 1].split()) - {"and", "then", ",", "plus", "as", "well"}:
                bare.objects = [nxt.objects[0]]
        ordered: list[Clause] = []
        for clause, join in zip(clauses, joins, strict=True):
            # "turn on the lamp while holding a clock": hold it first; but "carry a clock while turning
            # on a lamp" is already holding it (the one that takes a thing in hand comes first)
            together = "while" in join.split() or join.split()[:1] == ["as"] and join != "as well as"
            if together and ordered and not (self.takes(ordered[-1]) and not self.takes(clause)) \
                    or (join in ("when done", "once done") or join in FIRST_LATER) and ordered:  # "A after B": B first
                if not (clause.objects or clause.message) and ordered[-1].objects:
                    clause.objects = [ordered[-1].objects[0]]     # "put it away when done heating": it
                elif clause.objects and clause.objects[0].pronoun in ("it", "them") and ordered[-1].objects and \
                        not ordered[-1].objects[0].pronoun:
                    clause.objects[0] = ordered[-1].objects[0]    # "put the dishes away after you wash them"
                ordered.insert(len(ordered) - 1, clause)
            else:
                ordered.append(clause)
        for clause in ordered:
            self.clause(clause)
        return Parse(self.text, tuple(self.frames))

    @staticmethod
    def subordinate(clauses: list[Clause]) -> None:
        """Order the clauses of subordinate clauses said with a subordinator before their verb: one
        that a clause follows is subordinate to it ("*before you go* to the garage, turn off the
        lights": the lights first; "*when you reach* the kitchen, open the fridge": in order); the
        last one is subordinate to the clause before it ("put them away, *after you wash* them")."""
        k = 0
        while k < len(clauses):
            sub = clauses[k].sub
            if sub is not None and k + 1 < len(clauses) and sub == "before":
                clauses[k], clauses[k + 1] = clauses[k + 1], clauses[k]
                k += 2
                continue
            if sub is not None and k + 1 == len(clauses) and k > 0 and sub in FIRST_LATER:
                clauses[k - 1], clauses[k] = clauses[k], clauses[k - 1]
            k += 1

    def takes(self, clause: Clause) -> bool:
        """Whether the clause's verb takes a thing in hand (a frame of it has ``holding(theme)`` as a
        result: "hold", "carry", "pick up")."""
        return any(frame.elements and any(p.predicate == "holding" and not p.negated and
                                          p.args == (frame.elements[0].role,) for p in frame.postconditions)
                   for frame in self.library.evoked_by(str(clause.verb.info)))

    def read_clause(self, tree: Tree) -> Clause:
        phrase = next(c for c in tree.children if str(getattr(c, "data", "")) == "verb_phrase")
        verb = self.word(phrase.children[0])
        items: list[Any] = [self.item(child) for child in phrase.children[1:]]
        sub: str | None = None
        conditions: list[str] = []
        for child in tree.children:
            data = str(getattr(child, "data", ""))
            if data == "lead":                  # "with a clock in hand, turn on the lamp": as if said after
                items.extend(replace(self.pp(pp), lead=True) for pp in child.children if isinstance(pp, Tree))
            elif data == "polite":
                for token in child.children:
                    info = self.word(token).info
                    if isinstance(info, str) and info in SUBORDINATORS:
                        sub = info              # "before you go to the garage, ..."
            elif data == "cond":
                conditions.append(self.word(child.children[0]).text.rstrip(",;: "))
        items = self.relatives(items)
        gap: Clause | None = None
        split = self.gapping(items)
        if split is not None:
            gap = self.make_clause(verb, items[split + 1:], [], None, [])
            gap.start = items[split + 1].start
            items = items[:split]
        clause = self.make_clause(verb, items, conditions, sub, [])
        clause.gap = gap
        return clause

    def make_clause(self, verb: Word, items: list[Any], conditions: list[str], sub: str | None,
                    held: list[NP]) -> Clause:
        """A clause from its verb and the phrases after it."""
        held = held + self.in_hand(items)
        items = self.coordinate(items)
        items = self.containing(items)
        objects: list[NP] = []
        if len(items) > 1 and isinstance(items[0], Word) and items[0].lower == "how" and \
                isinstance(items[1], NP) and items[1].quantity is not None:
            counted = items[1]
            assert isinstance(counted, NP)
            counted.quantity = None             # "count how many books are on the shelf": the books
            items.pop(0)
        while items and (isinstance(items[0], NP) or isinstance(items[0], Word) and items[0].tag == "PARTICLE"
                         and objects == [] and len(items) > 1 and isinstance(items[1], NP)):
            first = items.pop(0)
            if isinstance(first, NP):
                objects.append(first)
        self.recipient_first(verb, objects, items)
        self.second_object(verb, objects, items)
        message = self.message(items) or self.said(verb, objects, items)
        end = max([verb.end] + [self.end_of(x) for x in (*objects, *items)] + ([message.end] if message else []))
        return Clause(verb, objects, items, message, verb.start, end, held, sub, conditions)

    def recipient_first(self, verb: Word, objects: list[NP], items: list[Any]) -> None:
        """"give *to me* the remote", "bring to my son his coat": a "to" phrase naming a person right
        after a verb whose frames have someone to receive, and then a noun phrase: that noun phrase is
        the object (the order of many other languages)."""
        if objects or len(items) < 2 or not isinstance(items[0], PP) or items[0].prep != "to" or \
                items[0].np.kind != "person" or not isinstance(items[1], NP) or items[1].kind == "person" or \
                not any("recipient" in self.taxonomy.roles(f) for f in self.library.evoked_by(str(verb.info))):
            return
        objects.append(items.pop(1))

    def second_object(self, verb: Word, objects: list[NP], items: list[Any]) -> None:
        """"give the man *in the gray suit* his coat": after a person and the phrases that describe them
        (where they are, what they have), a noun phrase with a determiner is the second object of a verb
        whose frames have someone to receive; the phrases join the person's noun phrase."""
        if len(objects) != 1 or objects[0].kind != "person" or objects[0].pronoun is not None or \
                not items or not isinstance(items[0], PP):
            return
        k = 0
        while k < len(items) and isinstance(items[k], PP) and items[k].prep in _LOCATIVE + ("with",) and \
                not items[k].lead:
            k += 1
        if k == len(items) or not isinstance(items[k], NP) or not items[k].determined or \
                items[k].kind == "person" or \
                not any("recipient" in self.taxonomy.roles(f) for f in self.library.evoked_by(str(verb.info))):
            return
        person = objects[0]
        for pp in items[:k]:
            person.inner.append(pp.np)
            person.end = max(person.end, pp.np.end)
        objects.append(items[k])
        del items[:k + 1]

    def relatives(self, items: list[Any]) -> list[Any]:
        """A relative clause (``REL``) belongs to the noun before it: kept whole as its ``relative``,
        with the frames its result words evoke ("a lamp that is turned on"); "that is" before a
        prepositional phrase makes the phrase describe the noun ("the pan that is on the stove"),
        never fill an element of the frame."""
        if not any(isinstance(item, Word) and item.tag == "REL" for item in items):
            return items
        out: list[Any] = []
        describe = False
        for item in items:
            if isinstance(item, Word) and item.tag == "REL" and out and isinstance(out[-1], NP | PP):
                host = out[-1].np if isinstance(out[-1], PP) else out[-1]
                if item.info == "be":
                    describe = True
                    continue
                host.relative = self.text[item.start:item.end]
                host.relative_start, host.relative_end = item.start, item.end
                for frame_unit in item.info if isinstance(item.info, tuple) else ():
                    host.results.append(Word(item.text, item.start, item.end, "RESULT", frame_unit))
                continue
            if describe and isinstance(item, PP):
                item.describes = True
            elif out and isinstance(item, PP) and isinstance(out[-1], NP | PP) and \
                    (out[-1].np if isinstance(out[-1], PP) else out[-1]).relative_end == item.start - 1:
                item.after_relative = True
            describe = False
            out.append(item)
        return out

    @staticmethod
    def gapping(items: list[Any]) -> int | None:
        """Where a second clause with the verb left out starts: "put the plates *on the table* and the
        glasses *next to them*" (an object and a place, "and", another object and place); None."""
        if len(items) < 5 or not isinstance(items[0], NP):
            return None
        for k in range(2, len(items) - 2):
            if isinstance(items[k], Word) and items[k].tag == "AND_NP" and items[k].lower == "and" and \
                    isinstance(items[k - 1], PP) and isinstance(items[k + 1], NP) and \
                    all(isinstance(x, PP) for x in items[k + 2:]) and not items[k - 1].lead and \
                    items[k - 1].prep not in ("with", "without", "of", "for", "about", "between") + _FROM and \
                    items[k - 1].np.pronoun is None:     # "a bowl with a spoon in it and a knife ...": contents
                return k
        return None

    def said(self, verb: Word, objects: list[NP], items: list[Any]) -> NP | None:
        """What a verb of saying says when it is a clause without a wh-word: "tell him *dinner is
        ready*" (a noun phrase, then "is"), from the object after the person told."""
        if not objects or not items or not (isinstance(items[0], Word) and items[0].tag == "BE") or \
                str(verb.info) not in lexicon_of(self.library)[0].speech:
            return None
        first = objects[1] if len(objects) >= 2 else objects[0]
        stop = next((j for j in range(len(items)) if isinstance(items[j], PP) and items[j].prep in ("to", "for")
                     and items[j].np.kind in ("person", "pronoun")), len(items))
        end = max(self.end_of(x) for x in items[:stop])
        del objects[objects.index(first):]
        del items[:stop]
        head = Word(self.text[first.start:end], first.start, end, "WORD")
        return NP(first.start, end, head, "message")

    @staticmethod
    def in_hand(items: list[Any]) -> list[NP]:
        """Take out "with X in hand" ("in his hands"): X is held while the clause is done."""
        held = []
        k = 0
        while k + 1 < len(items):
            first, second = items[k], items[k + 1]
            if isinstance(first, PP) and first.prep == "with" and isinstance(second, PP) and second.prep == "in" \
                    and second.np.head is not None and second.np.head_text == "hand" and not second.np.of:
                held.append(first.np)
                del items[k:k + 2]
                continue
            k += 1
        return held

    @staticmethod
    def end_of(item: Any) -> int:
        if isinstance(item, NP):
            return item.end
        if isinstance(item, PP):
            return item.np.end
        return int(item.end)

    def item(self, node: Any) -> Any:
        if not isinstance(node, Tree):
            word = self.word(node)
            if word.tag == "HERE":              # "come here": a place said by pointing
                nxt = node.start_pos + 1        # a bare "there" ending its clause ("... and count the bikes there")
                while nxt < len(self.words) and self.words[nxt].info == "time":
                    nxt += 1                     # "... there too", "... there right away"
                there = word.lower == "there" and (nxt == len(self.words) or self.words[nxt].tag in ("SEP", "END"))
                return PP("at", NP(word.start, word.end, word, "place", there=there), word.start)
            return word
        data = str(node.data)           # a lark Token: compare it as a plain str (faster)
        if data == "pp":
            return self.pp(node)
        if data == "predicate":
            return self.predicate(node)
        return self.np(node)

    def pp(self, node: Tree) -> PP:
        prep = self.word(node.children[0])
        return PP(str(prep.info), self.np(node.children[1]), prep.start)

    def predicate(self, node: Tree) -> Word:
        first = self.word(node.children[0])
        end = first.end
        for child in node.children[1:]:
            end = max(end, self.end_of(self.item(child)))
        return Word(self.text[first.start:end], first.start, end, "PREDICATE", first.info)

    def np(self, node: Any) -> NP:
        kind = str(node.data)
        if kind == "pron_np":
            w = self.word(node.children[0])
            low = w.lower
            pron_kind = "person" if low in PERSON_PRONOUNS else "thing" if low in (
                "it", "this", "that", "something", "everything", "anything", "nothing", "itself") else "pronoun"
            return NP(w.start, w.end, w, pron_kind, pronoun=low, plural=low in ("them", "they", "ones", "these",
                                                                                "those"))
        if kind == "name_np":
            w = self.word(node.children[0])
            if len(node.children) > 1:          # "Gate 5": a numbered place or thing, no person
                return NP(w.start, self.word(node.children[1]).end, w, "thing")
            return NP(w.start, w.end, w, "person")
        # det_np / bare_np
        np = NP(-1, -1, None, determined=kind == "det_np")
        for child in node.children:
            data = str(child.data) if isinstance(child, Tree) else None
            if data == "nominal":
                words = [self.word(t) for t in child.children]
                if words[-1].tag == "LABEL":    # "room 214": the noun is the head, its number in the text
                    np.end = words.pop().end
                np.head = words[-1]
                np.mods = [w for w in words[:-1] if w.tag == "WORD"]
                np.results = [w for w in words[:-1] if w.tag == "RESULT"]
                np.start = words[0].start if np.start < 0 else np.start
                np.end = max(np.end, words[-1].end)
            elif data == "postmod":
                self.postmod(np, child)
            else:
                w = self.word(child)
                np.start = w.start if np.start < 0 else np.start
                if w.tag == "NUM":
                    np.quantity = int(w.info) if isinstance(w.info, int) else None
                elif w.tag == "POSS" and isinstance(w.info, str):     # "the visitor's": whose it is
                    name = w.info[:1].isupper() and any(c.islower() for c in w.info[1:])
                    owner = Word(w.info, w.start, w.start + len(w.info), "NAME" if name else "WORD")
                    person = name or self.taxonomy.is_a(noun_lemma(w.info), "person") is True
                    np.possessor = NP(np.start, owner.end, owner, "person" if person else "thing")
        assert np.head is not None
        np.plural = is_plural(np.head.text) or (np.quantity or 0) > 1
        np.kind = "person" if self.taxonomy.is_a(np.head_text, "person") is True and \
            not self.taxonomy.is_open("person") else "thing"
        return np

    def postmod(self, np: NP, node: Tree) -> None:
        first = self.word(node.children[0])
        if first.tag == "OF":
            inner = self.np(node.children[1])
            np.of = inner
            np.inner.append(inner)
            np.end = inner.end
            return
        end = first.end
        for child in node.children[1:]:
            item = self.item(child)
            if isinstance(item, NP):
                np.inner.append(item)
                if first.info in ("contain", "hold", "have", "carry"):
                    np.contents.append(item)
            elif isinstance(item, PP):
                np.inner.append(item.np)
            end = max(end, self.end_of(item))
        np.end = end

    def coordinate(self, items: list[Any]) -> list[Any]:
        """Join "NP and NP" into one phrase with conjuncts."""
        out: list[Any] = []
        i = 0
        while i < len(items):
            item = items[i]
            if (isinstance(item, Word) and item.tag == "AND_NP" and item.lower == "or" and out
                    and isinstance(out[-1], PP) and i + 1 < len(items) and isinstance(items[i + 1], PP)):
                items = [*items[:i + 1], items[i + 1].np, *items[i + 2:]]   # "on the desk or in the bedroom"
            if (isinstance(item, Word) and item.tag == "AND_NP" and out and isinstance(out[-1], NP | PP)
                    and i + 1 < len(items) and isinstance(items[i + 1], NP)):
                host = out[-1].np if isinstance(out[-1], PP) else out[-1]
                other = items[i + 1]
                if item.lower == "or":               # "an apple or a pear": either will do, the first
                    host.end = other.end
                    i += 2
                    continue
                if host.contents and host.contents[-1].end == host.end:   # "a pot containing a knife and
                    content = host.contents[-1]                             # a slice": both in the pot
                    if not content.conjuncts:
                        content.conjuncts.append(replace(content, conjuncts=[]))
                    content.conjuncts.append(other)
                    content.end = host.end = other.end
                    content.plural = True
                    i += 2
                    continue
                if not host.conjuncts:
                    host.conjuncts.append(replace(host, conjuncts=[]))
                host.conjuncts.append(other)
                host.end = other.end
                host.plural = True
                i += 2
                continue
            out.append(item)
            i += 1
        return out

    def containing(self, items: list[Any]) -> list[Any]:
        """Read "a pan with a spoon in it": the spoon is a content of the pan (and "in it" no goal)."""
        out: list[Any] = []
        i = 0
        while i < len(items):
            item = items[i]
            nxt = items[i + 1] if i + 1 < len(items) else None
            host = out[-1].np if out and isinstance(out[-1], PP) else out[-1] if out and isinstance(out[-1], NP) \
                else None
            if (host is not None and isinstance(item, PP) and item.prep == "with" and isinstance(nxt, PP)
                    and nxt.prep in ("in", "on", "inside") and nxt.np.pronoun in ("it", "them")):
                host.contents.append(item.np)
                host.end = max(host.end, nxt.np.end)
                i += 2
                continue
            out.append(item)
            i += 1
        return out

    def message(self, items: list[Any]) -> NP | None:
        """A question said as the message ("tell me *what day is today*"): from the wh-word on,
        up to a final "to <person>" phrase. "how many" is no message (it asks to count)."""
        for k, item in enumerate(items):
            if isinstance(item, Word) and item.tag == "SAID":   # "tell him we need a cart": said without "that"
                del items[k]
                return NP(item.start, item.end, Word(item.text, item.start, item.end, "WORD"), "message")
            if isinstance(item, Word) and item.tag == "WH":
                nxt = items[k + 1] if k + 1 < len(items) else None
                if item.lower == "how" and isinstance(nxt, NP) and nxt.quantity is not None:
                    items.pop(k)
                    return None
                stop = next((j for j in range(k + 1, len(items)) if isinstance(items[j], PP)
                             and items[j].prep in ("to", "for") and items[j].np.kind in ("person", "pronoun")),
                            len(items))
                end = max(self.end_of(x) for x in items[k:stop]) if stop > k else item.end
                start = item.start
                if item.lower in ("that", "to") and stop > k + 1:   # "tell him that ...", "tell her to ..."
                    start = items[k + 1].start
                head = Word(self.text[start:end], start, end, "WORD")
                del items[k:stop]
                return NP(start, end, head, "message")
        return None

    # -- one clause → frames -----------------------------------------------------------------
    def clause(self, clause: Clause) -> None:
        self.clause_frames = len(self.frames)
        unit = self.light_verb(clause) or str(clause.verb.info)
        frames = self.library.evoked_by(unit)
        used = [x for x in clause.items if isinstance(x, PP) and x.lead and x.prep == "with"]
        if used and not any("instrument" in self.taxonomy.roles(f) for f in frames):
            clause.held += [x.np for x in used]             # "use a card to turn on the lamp": hold it
            clause.items = [x for x in clause.items if not any(x is u for u in used)]
        for np in clause.held:
            self.hold(np)
        if frames and all(self.makes_state(f) for f in frames):
            clause.result = [x for x in clause.items if isinstance(x, PP) and self.is_form(x)]
            clause.items = [x for x in clause.items if not any(x is r for r in clause.result)]
        best = self.best_fit(frames, clause)
        head = unit.split()[0]
        if best is None and head != unit and self.library.evoked_by(head):
            # "take the trash out to the garage": no frame of "take out" has a goal, one of "take" has
            best = self.best_fit(self.library.evoked_by(head), clause)
            if best is not None:
                unit, frames = head, self.library.evoked_by(head)
        if (best is None or "recipient" not in self.taxonomy.roles(best[1])) and self.recipient_said(clause):
            brings = self.bringing(frames)   # "grab me a beer", "grab a beer from the fridge for me": Bring
            found = self.best_fit(brings, clause) if brings else None
            if found is not None:
                best = found
        if best is None:                     # no frame takes every phrase: the best that takes the most
            for order, frame in enumerate(frames):
                assigned = self.assign(frame, clause, strict=False)
                assert assigned is not None
                roles, attached, score = assigned
                key = (score - 5 * len(clause.items), -self.unfilled(frame, roles), -order)
                if best is None or key > best[0]:
                    best = (key, frame, roles, attached)
        assert best is not None
        _, frame, roles, attached = best
        self.first_into(frame, roles, attached)
        self.emit(frame, unit, clause, roles, attached)

    def light_verb(self, clause: Clause) -> str | None:
        """"give the sauce *a quick stir*": "give" with a thing and "a" (adjectives) and a noun that is a lexical
        unit of the library is that unit's frame, done to the thing (the construction of "take a look at").
        The lexical unit, or None. A person keeps "give" ("give me a hand")."""
        if str(clause.verb.info) not in LIGHT_VERBS or len(clause.objects) != 2:
            return None
        thing, act = clause.objects
        if thing.kind == "person" or act.head is None or act.head.tag != "WORD" or act.of is not None or \
                act.plural or act.quantity is not None or act.relative or \
                self.text[act.start:act.end].split(None, 1)[0].lower() not in ("a", "an", "another"):
            return None
        unit = act.head.lower
        frames = self.library.evoked_by(unit)
        if not frames or not all(f.elements and not self.is_person_type(f.elements[0].type) for f in frames):
            return None
        clause.objects = [thing]
        return unit

    def makes_state(self, frame: Frame) -> bool:
        """Whether the frame's result is a state of its first element and it puts it nowhere (Slice:
        ``sliced(theme)``, no goal)."""
        return self.taxonomy.makes_state(frame)

    @staticmethod
    def is_form(pp: PP) -> bool:
        """Whether a phrase says the form the action leaves its theme in: "*into slices*", "into eight
        pieces", "into cubes", "*in half*" (a portion, a number of things, or things said bare)."""
        np = pp.np
        if np.head is None or np.kind != "thing" or np.pronoun is not None or pp.prep not in ("into", "in"):
            return False
        head = noun_lemma(np.head.text)
        if head in PORTIONS or head == "half":
            return True
        first = np.mods[0] if np.mods else np.head
        bare_plural = np.plural and first.start == np.start and not np.of
        return pp.prep == "into" and (np.quantity is not None or bare_plural)

    def recipient_said(self, clause: Clause) -> bool:
        """Whether the clause names someone to receive: an indirect object, or "for"/"to" a person."""
        return len(clause.objects) >= 2 and self.kind(clause.objects[0], None, None) == "person" or any(
            isinstance(x, PP) and x.prep in ("for", "to") and self.kind(x.np, None, None) == "person"
            for x in clause.items)

    def bringing(self, frames: Sequence[Frame]) -> list[Frame]:
        """For a verb of taking (a frame of it gets its theme in hand: Pick), the frames that take a
        thing in hand to someone (a recipient, and ``holding(theme)`` before): taking a thing for a
        person is bringing it to them, so those that also say where it is taken from (a source) when
        any does. Empty for any other verb."""
        if not any(self.achieves_holding(f) for f in frames):
            return []
        handing = [f for f in self.library.frames if f not in frames and "recipient" in self.taxonomy.roles(f)
                   and f.elements and any(p.predicate == "holding" and p.args == (f.elements[0].role,)
                                          and not p.negated for p in f.preconditions)]
        fetching = [f for f in handing if "source" in self.taxonomy.roles(f)]
        return fetching or handing       # "grab me two eggs": taken from where they are, so Bring, not Give

    @staticmethod
    def achieves_holding(frame: Frame) -> bool:
        first = frame.elements[0].role if frame.elements else None
        return first is not None and any(p.predicate == "holding" and p.args == (first,) and not p.negated
                                          for p in frame.postconditions)

    def best_fit(self, frames: Sequence[Frame], clause: Clause
                 ) -> tuple[tuple[float, ...], Frame, dict[str, Any], list[tuple[NP, PP]]] | None:
        """The frame that takes every phrase of the clause best (fewest elements left empty, then
        library order), or None when none takes them all."""
        best: tuple[tuple[float, ...], Frame, dict[str, Any], list[tuple[NP, PP]]] | None = None
        for order, frame in enumerate(frames):
            assigned = self.assign(frame, clause, strict=True)
            if assigned is None:
                continue
            roles, attached, score = assigned
            key = (score, -self.unfilled(frame, roles), -order)
            if best is None or key > best[0]:
                best = (key, frame, roles, attached)
        return best

    def first_into(self, frame: Frame, roles: dict[str, Any], attached: list[tuple[NP, PP]]) -> None:
        """"Put a spoon *in a bowl* into the sink": the spoon goes into the bowl, and the bowl (a
        container) into the sink (:meth:`carry_on`)."""
        relation = self.relation(frame)
        if relation is None or not isinstance(roles.get(relation.args[1]), NP):
            return
        theme, goal = roles.get(relation.args[0]), roles[relation.args[1]]
        for k, (host, pp) in enumerate(attached):
            if host is theme and pp.prep in _PUT_IN and pp.np.kind == "thing" and not pp.np.pronoun and \
                    not pp.describes and \
                    self.taxonomy.is_a(self.class_or_head(pp.np), "container") is True:
                roles[relation.args[1]] = pp.np
                attached[k] = (pp.np, PP("into", goal, goal.start))
                return

    def unfilled(self, frame: Frame, roles: Mapping[str, Any]) -> int:
        """Elements the clause leaves empty; an object left unsaid that the frame before has in hand
        is not empty ("heat the mug, move [it] to the cabinet": Place, not Go)."""
        first = frame.elements[0].role if frame.elements else None
        held = first is not None and first not in roles and bool(self.frames) and any(
            p.predicate == "holding" and p.args == (first,) for p in frame.preconditions) and \
            self.implicit(frame, first) is not None
        return sum(1 for e in frame.elements if e.role not in roles) - int(held)

    def assign(self, frame: Frame, clause: Clause,
               strict: bool) -> tuple[dict[str, Any], list[tuple[NP, PP]], float] | None:
        """Fill the frame's elements from the clause; None when a realised role does not fit."""
        roles: dict[str, Any] = {}
        attached: list[tuple[NP, PP]] = []
        first = frame.elements[0].role if frame.elements else None
        have = self.taxonomy.roles(frame)
        objects = list(clause.objects)
        seek = first == "theme" and "ground" in have and self.searches(frame, str(clause.verb.info)) and \
            any(isinstance(x, PP) and x.prep == "for" for x in clause.items)
        if seek and objects:                 # "search the kitchen for a can opener": the kitchen is searched
            roles["ground"] = objects.pop(0)
        if clause.message is not None and first is not None:
            roles[first] = clause.message
            if objects and "recipient" in have:
                roles["recipient"] = objects.pop(0)
        elif len(objects) >= 2:
            if "recipient" in have:
                roles["recipient"] = objects.pop(0)
            elif strict:
                return None
        if objects and first is not None and first not in roles:
            only = objects.pop(0)
            if ("recipient" in have and only.kind == "person"
                    and not self.is_person_type(frame.elements[0].type) and frame.elements[0].role != "goal"
                    and not any(isinstance(x, PP) and x.prep == "to" for x in clause.items)):
                roles["recipient"] = only            # "tell Robin", "give Maria": the person receives
            else:
                roles[first] = only
        if objects and strict:
            return None
        previous: NP | None = clause.objects[-1] if clause.objects else None
        has_to = any(isinstance(x, PP) and x.prep in _TO for x in clause.items)
        for item in clause.items:
            if isinstance(item, NP):
                if strict:
                    return None
                previous = item
                continue
            if not isinstance(item, PP):
                continue
            if seek and item.prep == "for" and "theme" not in roles:
                roles["theme"] = item.np          # "... for a can opener", "look in the closet for my scarf"
                previous = item.np
                continue
            role = None if item.describes else self.role_for(frame, item, previous, roles, has_to)
            if item.after_relative and "recipient" in roles:
                role = None                       # "bring me the book I left on the sofa": where it was left
            if role is None and previous is None and first == "theme" and first not in roles and \
                    item.prep in ("on", "at") and not item.lead and not item.describes and \
                    not (self.frames and self.needs_in_hand(frame)):
                role = first                      # "check on the baby": the verb's object after its preposition
            if role is None and item.prep == "for" and item.np.pronoun in PERSON_PRONOUNS and not item.describes:
                continue                          # "chop the carrots *for me* with the knife": for whom, no element
            if role is not None:
                roles[role] = item.np
            elif previous is not None and (item.prep in _ATTACHABLE or not strict or item.describes):
                attached.append((previous, item))
            elif strict:
                return None
            previous = item.np
        score = sum(self.fit(frame, role, np) for role, np in roles.items())
        return roles, attached, score

    @staticmethod
    def needs_in_hand(frame: Frame) -> bool:
        """Whether the frame needs its first element in hand (``holding(theme)`` before it)."""
        first = frame.elements[0].role if frame.elements else None
        return any(p.predicate == "holding" and p.args == (first,) for p in frame.preconditions)

    @staticmethod
    def searches(frame: Frame, unit: str) -> bool:
        """Whether the unit's object is the place searched: the frame also has the unit with "for"
        ("search" beside "search for", "look" beside "look for"), so "search X for Y" is "search for Y
        in X"."""
        wanted = unit + " for"
        return any(u.text == wanted for u in frame.lexical_units)

    def role_for(self, frame: Frame, pp: PP, previous: NP | None, roles: Mapping[str, Any],
                 has_to: bool = False) -> str | None:
        """The element a prepositional phrase fills in this frame, or None (it describes a noun).
        A locative phrase is no goal when a *to* phrase says the goal ("the book on the bed to the desk")."""
        have = self.taxonomy.roles(frame)
        np = pp.np
        person = self.kind(np, frame, "recipient" if "recipient" in have else None) == "person"
        if pp.prep in _TO or pp.prep == "for":
            options = ["recipient", "goal"] if person else ["goal"] if pp.prep != "for" else []
            if pp.prep == "to" and not person and "goal" not in have and np.kind == "thing":
                options = ["recipient"]      # "give the newspaper to grandpa": Give has no goal, only someone
        elif pp.prep in _FROM:
            options = ["source"]
        elif pp.prep == "with":
            if previous is not None and previous.kind == "person" and previous.pronoun is None and not (
                    "instrument" in have and
                    self.taxonomy.is_a(self.class_or_head(np), frame.element("instrument").type) is True):
                return None              # "follow the woman *with the umbrella*": it describes her
            options = ["instrument"]
        elif pp.prep in _LOCATIVE:
            person_before = previous is not None and (previous.kind == "person" or (
                frame.elements and roles.get(frame.elements[0].role) is previous
                and self.is_person_type(frame.elements[0].type)))
            if person_before and "ground" not in have:
                return None
            if previous is not None and previous.contents and np.pronoun in ("it", "them"):
                return None                              # "a pan with a spoon in it"
            options = ["ground"]
            theme_type = frame.elements[0].type if frame.elements else None
            if (theme_type is None or not self.is_person_type(theme_type) or frame.elements[0].role == "goal") \
                    and not has_to:
                options.append("goal")
            options += ["instrument", "source"]
        else:
            return None
        for role in options:
            if role in have and role not in roles:
                if role == "instrument" and pp.prep != "with" and not self.made_for(np, frame) and \
                        self.taxonomy.is_a(self.class_or_head(np), frame.element(role).type) is not True:
                    continue
                return role
        return None

    def made_for(self, np: NP, frame: Frame) -> bool:
        """Whether the noun names a thing made for doing the frame: its head is the agent noun of one of
        the frame's verbs and the library knows no class of it ("in the blanket *warmer*": warm, Heat)."""
        if np.head is None or np.kind != "thing" or "instrument" not in frame.roles or \
                self.taxonomy.is_a(self.class_or_head(np), frame.element("instrument").type) is not None:
            return False
        head = noun_lemma(np.head.text.split()[-1].lower())
        if not head.endswith("er") or len(head) < 5:
            return False
        stems = {head[:-2], head[:-1], head[:-3]}     # warmer, cooler: warm, cool; freezer: freeze; cutter: cut
        return any(u.text in stems for u in frame.lexical_units)

    def is_location(self, type_: str) -> bool:
        return self.taxonomy.is_location(type_)

    def is_person_type(self, type_: str) -> bool:
        return self.taxonomy.is_person(type_)

    def class_or_head(self, np: NP) -> str:
        if self.vocabulary is not None:
            found = self.vocabulary.ground_np(np)
            if found:
                return found
        return np.head_text

    def kind(self, np: NP, frame: Frame | None, role: str | None) -> str:
        if np.kind != "pronoun":
            return np.kind
        antecedent = self.antecedent(np, frame, role)
        return antecedent[2] if antecedent else "pronoun"

    def fit(self, frame: Frame, role: str, np: NP) -> float:
        """How well a phrase fits an element: +2 a person where a person is wanted, +1 a class of
        the element's type, 0 unknown, -2 what cannot be (a thing where a person is wanted)."""
        type_ = frame.element(role).type
        kind = self.kind(np, frame, role)
        person_type = self.is_person_type(type_)
        if kind == "person":     # a person is somewhere too: "bring her to me" (Guide's goal)
            return 2.0 if person_type else 0.0 if self.taxonomy.is_open(type_) or self.is_location(type_) else -2.0
        if kind == "pronoun":
            return 0.0
        if person_type:          # a noun nobody called a thing may receive ("give the newspaper to grandpa"),
            return 1.0 if role == "recipient" and kind == "thing" and \
                self.taxonomy.is_a(self.class_or_head(np), type_) is None else -2.0   # as any noun may be a place
        if kind in ("message", "place"):
            return 0.5
        found = self.taxonomy.is_a(self.class_or_head(np), type_)
        return 1.0 if found else -2.0 if found is False else 0.0

    # -- pronouns ------------------------------------------------------------------------------
    def antecedent(self, np: NP, frame: Frame | None, role: str | None) -> tuple[int, str, str] | None:
        """(frame index, element, kind) of what a pronoun refers to: the latest element of an
        earlier frame that can be it (a person for "him", a thing for "it"), fitting the role."""
        wanted_person: bool | None = None
        if frame is not None and role is not None:
            type_ = frame.element(role).type
            wanted_person = True if self.is_person_type(type_) else None if self.taxonomy.is_open(type_) else \
                bool(self.taxonomy.is_a("person", type_))
        carried = self.carried(frame, role) if np.pronoun in ("it", "them", "they", "both") else None
        if carried is not None:
            return carried
        best: tuple[float, int, str, str] | None = None
        for index in range(len(self.frames) - 1, -1, -1):
            evoked = self.frames[index]
            for rank, (name, phrase) in enumerate(evoked.elements.items()):
                if phrase.default:
                    continue
                target = (index, name)
                if phrase.refers_to is not None:     # "put it in the fridge, take it out": the apple again
                    target = phrase.refers_to
                    if not (0 <= target[0] < len(self.frames)) or target[1] not in self.frames[target[0]].elements:
                        continue
                    phrase = self.frames[target[0]].elements[target[1]]
                kind = phrase.kind
                if kind in ("message", "place"):
                    continue
                if kind == "thing" and np.pronoun in ("him", "her", "he", "she") and \
                        self.person_by_role(target, phrase):
                    kind = "person"                  # "meet the plumber ... and take him": a person there
                if np.pronoun in ("it", "one", "this", "that") and kind == "person":
                    continue
                if np.pronoun in ("him", "her") and kind != "person":
                    continue
                if np.pronoun in ("them", "they", "ones") and kind != "person" and not phrase.plural \
                        and wanted_person is not False:
                    pass
                score = -(len(self.frames) - index) * 2 - rank * 0.5
                if self.is_location(self.library.frame(evoked.frame).element(name).type):
                    score -= 1
                if wanted_person is True:
                    score += 3 if kind == "person" else -3
                elif wanted_person is False and kind == "person":
                    score -= 3
                if np.pronoun in ("them", "they") and (kind == "person" or phrase.plural):
                    score += 1
                if wanted_person is False and kind == "thing" and frame is not None and role is not None:
                    fits = self.taxonomy.is_a(phrase.cls or phrase.head, frame.element(role).type)
                    score += 3.0 if fits else -3.0 if fits is False else 0.0   # "close it": the fridge
                if frame is not None and role is not None and self.undoes(frame, role, evoked.frame, name):
                    score += 3.0       # "open the shed, grab the trowel, then close it": the shed opened
                if best is None or score > best[0]:
                    best = (score, target[0], target[1], kind)
        return None if best is None else best[1:]

    def undoes(self, frame: Frame, role: str, earlier: str, name: str) -> bool:
        """Whether ``frame`` ends, on its element ``role``, a state the ``earlier`` frame gave its element
        ``name`` (Close's ``not open(theme)`` undoes Open's ``open(theme)``)."""
        ended = {p.predicate for p in frame.postconditions if p.negated and p.args == (role,)}
        return bool(ended) and any(not p.negated and p.args == (name,) and p.predicate in ended
                                   for p in self.library.frame(earlier).postconditions)

    def mentioned(self, np: NP, frame: Frame, role: str) -> Mention | None:
        """What a pronoun no frame's element can be stands for in a statement or condition said before it
        ("*My son Declan* arrives at six; meet him", "*When Ana* arrives, ...", "*The printer*'s jammed, fix
        it"): him/her the latest person named, it the latest thing (one of the element's type first)."""
        if self._mentions is None:
            spans = [*self.remarks, *((w.start, w.end) for w in self.words if w.tag == "COND")]
            self._mentions = sorted((m for a, b in spans for m in mentions(self.text, a, b)), key=lambda m: m.start)
        pronoun = np.pronoun or ""
        if pronoun not in ("him", "her", "he", "she", "it", "this", "that"):
            return None
        person = pronoun not in ("it", "this", "that")
        said = [m for m in self._mentions if m.end <= np.start and
                (m.name or self.taxonomy.is_a(noun_lemma(m.head), "person") is True) == person]
        if not person:
            type_ = frame.element(role).type
            fitting = [m for m in said if noun_lemma(m.head) == type_ or not self.taxonomy.is_open(type_)
                       and self.taxonomy.is_a(noun_lemma(m.head), type_) is True]
            said = fitting or [m for m in said if m.determined and not m.oblique] or [m for m in said if m.determined]
        return said[-1] if said else None

    def person_by_role(self, target: tuple[int, str], phrase: Phrase) -> bool:
        """Whether a noun the library does not know as a person is one by the element it fills: an
        element typed person ("meet *the plumber*", Meet's theme), unless its class is known to be no
        person; or a noun the taxonomy does not know at all that fills the first element, one a person may
        fill ("find *the bellhop*": Find's theme is any thing; not "in the kitchen", where it is)."""
        evoked = self.library.frame(self.frames[target[0]].frame)
        type_ = evoked.element(target[1]).type
        known = self.taxonomy.is_a(phrase.cls or phrase.head, "person")
        if known is None and phrase.head.lower() not in PRONOUNS and target[1] == evoked.elements[0].role and \
                self.taxonomy.is_a("person", type_) is True:
            return True                               # "find the bellhop and tell him ...": one that may be a person
        return self.is_person_type(type_) and known is not False

    def carried(self, frame: Frame | None, role: str | None) -> tuple[int, str, str] | None:
        """After "put the pen in a cup", the object of "and move it (them) to the desk" is the cup
        with the pen in it: moving the pen again would undo what was just done. (Only when both
        frames put their first element somewhere, and the place was a container.)"""
        if frame is None or not self.frames or role != (frame.elements[0].role if frame.elements else None):
            return None
        if self.relation(frame) is None:
            return None
        last = self.frames[-1]
        relation = self.relation(self.library.frame(last.frame))
        if relation is None or relation.args[1] not in last.elements:
            return None
        goal = last.elements[relation.args[1]]
        if goal.default or goal.kind != "thing" or goal.refers_to is not None or \
                self.taxonomy.is_a(goal.cls or goal.head, "container") is not True:
            return None
        return len(self.frames) - 1, relation.args[1], "thing"

    def relation(self, frame: Frame) -> Any:
        return self.taxonomy.relation(frame)

    # -- frames out ----------------------------------------------------------------------------
    def emit(self, frame: Frame, unit: str, clause: Clause, roles: dict[str, Any],
             attached: list[tuple[NP, PP]]) -> None:
        theme = frame.elements[0].role if frame.elements else ""
        holds_nothing = "instrument" not in frame.roles and not any(
            not p.negated and len(p.args) == 2 and p.args[0] == theme for p in frame.postconditions)
        for host, pp in attached:
            if pp.after_relative and host.relative is not None:
                host.relative = self.text[host.relative_start:pp.np.end]
                continue
            host.end = max(host.end, pp.np.end)
            if pp.prep == "with" and pp.np.kind != "person" and (host.kind != "person" or host.pronoun):
                if holds_nothing and host is roles.get(theme) and pp.np.kind == "thing" and not pp.np.pronoun:
                    self.hold(pp.np)     # "turn on the lamp with the remote": held while it is done
                else:
                    host.contents.append(pp.np)
        self.asker(frame, roles)
        # frames evoked by result words and contents, in the order of the words
        for role in frame.roles:
            np = roles.get(role)
            if isinstance(np, NP):
                self.prepare(np, frame, role, roles)
        elements: dict[str, Phrase] = {}
        for element in frame.elements:
            np = roles.get(element.role)
            if np is not None:
                elements[element.role] = self.phrase(np, frame, element.role)
        first = frame.elements[0] if frame.elements else None
        if first is not None and first.role not in elements and self.frames and \
                any(p.predicate == "holding" and p.args == (first.role,) for p in frame.preconditions):
            implicit = self.implicit(frame, first.role)
            if implicit is not None:
                elements = {first.role: implicit, **elements}
        for element in frame.elements:
            if element.role not in elements and element.default is not None:
                elements[element.role] = Phrase(None, element.default, self.ground_name(element.default),
                                                default=True)
        ordered = {e.role: elements[e.role] for e in frame.elements if e.role in elements}
        self.frames.append(Evoked(frame.name, unit, (clause.start, clause.end), ordered,
                                  "; ".join(clause.conditions) or None,
                                  " ".join(self.text[r.start:r.np.end] for r in clause.result) or None,
                                  " ".join(w.text for w in clause.items if isinstance(w, Word) and w.info == "time")
                                  or None))
        self.carry_on(frame, roles, attached)

    @staticmethod
    def asker(frame: Frame, roles: dict[str, Any]) -> None:
        """Whose question is answered gets the answer: "answer *Jorge*'s question", "answer the question *of
        the girl in the kitchen*" (the possessor, or the person of an "of" phrase with what describes them,
        is the recipient when none is said)."""
        first = frame.elements[0] if frame.elements else None
        theme = roles.get(first.role) if first is not None and first.type == "question" else None
        if not isinstance(theme, NP) or "recipient" not in frame.roles or "recipient" in roles:
            return
        if theme.possessor is not None and theme.possessor.kind == "person":
            roles["recipient"] = theme.possessor
        elif theme.of is not None and theme.of.kind == "person" and theme.of.pronoun is None:
            roles["recipient"] = replace(theme.of, end=max(theme.of.end, theme.end))

    def carry_on(self, frame: Frame, roles: Mapping[str, Any], attached: list[tuple[NP, PP]]) -> None:
        """"Put an apple in a pan *on the table*": a container the theme goes into, said to be in
        or on a place, is put there too, after (a pan already there stays: the planner skips it).
        Only when the frame's goal may be a place (a room is one): "pour water into the bowl *in
        kennel 2*" says where the bowl is (Pour's goal is a container; the water is poured, not put)."""
        first = frame.elements[0].role if frame.elements else None
        relation = next((p for p in frame.postconditions if not p.negated and len(p.args) == 2
                         and p.args[0] == first and isinstance(roles.get(p.args[1]), NP)), None)
        if relation is None or self.taxonomy.is_a("room", frame.element(relation.args[1]).type) is not True:
            return                                   # the goal may be no place: a container only
        goal = roles[relation.args[1]]
        for host, pp in attached:
            if host is goal and pp.prep in _PUT_IN and not pp.np.pronoun and goal.kind == "thing" and not pp.describes \
                    and \
                    self.taxonomy.is_a(self.class_or_head(goal), "container") is True:
                self.put(goal, pp.np, relation.predicate)
                return

    def prepare(self, np: NP, frame: Frame, role: str, roles: Mapping[str, Any]) -> None:
        """Frames that must come first: result words ("heated") and contents ("with a fork")."""
        cutting = self.cutting(noun_lemma(np.head.text)) if np.head is not None else None
        if cutting is not None and cutting[0].name == frame.name and frame.elements and \
                role == frame.elements[0].role:
            self.cut.update(id(c) for c in (np, *np.conjuncts))   # "cut a tomato slice": this frame cuts it
        for inner in np.inner:
            self.results_of(inner)
        if np.results and role == "instrument":
            np.results = []              # "wipe the table with a clean cloth": the tool as it is, no Clean first
        if np.results and frame.elements and role == frame.elements[0].role:
            if "source" in roles:
                np.results = []          # "take the clean mugs out of the dishwasher": the thing as it is
            undone = {p.predicate for p in frame.postconditions if p.negated and p.args == (role,)}
            np.results = [w for w in np.results if not undone & self.result_states(w)]   # "heat the frozen peas"
        self.results_of(np)
        if np.contents and role == (frame.elements[0].role if frame.elements else None):
            relation = next((p for p in frame.postconditions if not p.negated and len(p.args) == 2
                             and p.args[0] == role and p.args[1] in roles), None)
            if relation is not None:
                for content in np.contents:
                    self.results_of(content)
                    self.put(content, np, relation.predicate)

    def result_states(self, word: Word) -> set[str]:
        """The states a result word's frame gives its theme (``cold`` for "frozen")."""
        frame = self.library.frame(word.info[0])  # type: ignore[index]
        first = frame.elements[0].role if frame.elements else None
        return {p.predicate for p in frame.postconditions if not p.negated and p.args == (first,)}

    def results_of(self, np: NP) -> None:
        if np.conjuncts:                 # "a heated apple and a chilled pear": each its own
            for conjunct in np.conjuncts:
                self.results_of(conjunct)
            np.results = []
            return
        self.cut_for(np)
        for word in np.results:
            info: tuple[str, str] = word.info  # type: ignore[assignment]
            frame_name, unit = info
            frame = self.library.frame(frame_name)
            first = frame.elements[0].role
            theme = self.phrase(np, frame, first)
            if any(e.frame == frame.name and first in e.elements and self.same_thing(e.elements[first], theme)
                   for e in self.frames):
                continue                 # "a chilled, cut slice": cut once
            self.frames.append(Evoked(frame.name, unit, (word.start, word.end),
                                      {first: theme} | self.defaults(frame, {first})))
        np.results = []

    def cutting(self, noun: str) -> tuple[Frame, str] | None:
        """The frame that cuts a thing into pieces, and its lexical unit: the one the piece's noun
        names ("slice"), else the one of "cut", whose result is a state of its theme (``sliced``)."""
        for unit in (noun, "cut"):
            for frame in self.library.evoked_by(unit):
                first = frame.elements[0].role if frame.elements else None
                if any(not p.negated and p.args == (first,) for p in frame.postconditions):
                    return frame, unit
        return None

    def cut_for(self, np: NP) -> None:
        """A piece cut from a whole ("an apple *slice*", "a *piece* of bread", ``grounding.PIECES``)
        exists once the whole has been cut: the cutting frame comes first, on the whole, unless the
        command has cut it already ("slice the bread and take a slice")."""
        if np.head is None or np.head.tag != "WORD" or np.kind != "thing" or noun_lemma(np.head.text) not in PIECES \
                or id(np) in self.cut:
            return
        self.cut.add(id(np))
        found = self.cutting(noun_lemma(np.head.text))
        if found is None:
            return
        frame, unit = found
        first = frame.elements[0].role
        whole = self.phrase(np, frame, first)
        if whole.refers_to is not None or whole.cls is None and not (_whole_named(np) or np.of):
            return                                         # no whole named: "take a (little) slice" (see phrase)
        if any(e.frame == frame.name and first in e.elements and self.same_thing(e.elements[first], whole)
               for e in self.frames):
            return
        self.frames.append(Evoked(frame.name, unit, (np.start, np.end), {first: whole} | self.defaults(frame, {first})))

    def cut_from(self, np: NP) -> tuple[int, str] | None:
        """For a piece that names no whole ("take *a slice*"), the theme of the latest frame that cut
        something in this command: what the piece was cut from."""
        if np.head is None or np.head.tag != "WORD" or _whole_named(np) or np.of is not None or \
                noun_lemma(np.head.text) not in PIECES:
            return None
        found = self.cutting(noun_lemma(np.head.text))
        if found is None:
            return None
        frame = found[0]
        first = frame.elements[0].role
        for index in range(len(self.frames) - 1, -1, -1):
            if self.frames[index].frame == frame.name and first in self.frames[index].elements:
                return index, first
        return None

    def same_thing(self, a: Phrase, b: Phrase) -> bool:
        if a.refers_to is not None or b.refers_to is not None:
            ra = a.refers_to or ()
            rb = b.refers_to or ()
            return bool(ra and ra == rb)
        return (a.cls or a.head) == (b.cls or b.head)

    def hold(self, np: NP) -> None:
        """The frame that gets ``np`` in hand (``holding(theme)``: Pick), before the clause."""
        for frame in sorted(self.library.achievers("holding"), key=lambda f: len(f.elements)):
            first = frame.elements[0].role if frame.elements else None
            if first is not None and any(p.predicate == "holding" and p.args == (first,) and not p.negated
                                         for p in frame.postconditions):
                self.results_of(np)
                elements = {first: self.phrase(np, frame, first)}
                last = (len(self.frames) - 1, first)
                if self.frames and elements[first].refers_to == last and self.frames[-1].frame == frame.name:
                    return                           # "pick up a card and use it to ...": in hand already
                self.frames.append(Evoked(frame.name, frame.lexical_units[0].text if frame.lexical_units else "",
                                          (np.start, np.end), elements | self.defaults(frame, elements)))
                return

    def put(self, content: NP, container: NP, predicate: str) -> None:
        """The frame that makes ``predicate(content, container)`` true (Place for ``in``)."""
        for frame in sorted(self.library.achievers(predicate), key=lambda f: len(f.elements)):
            fact = next(p for p in frame.postconditions if p.predicate == predicate and not p.negated)
            if len(fact.args) == 2 and fact.args[0] == frame.elements[0].role:
                elements = {fact.args[0]: self.phrase(content, frame, fact.args[0]),
                            fact.args[1]: self.phrase(container, frame, fact.args[1])}
                self.frames.append(Evoked(frame.name, frame.lexical_units[0].text if frame.lexical_units else "",
                                          (content.start, content.end), elements | self.defaults(frame, elements)))
                return

    def defaults(self, frame: Frame, have: Iterable[str]) -> dict[str, Phrase]:
        have = set(have)
        return {e.role: Phrase(None, e.default, self.ground_name(e.default), default=True)
                for e in frame.elements if e.default is not None and e.role not in have}

    def implicit(self, frame: Frame, role: str) -> Phrase | None:
        """An object left unsaid refers to the object of the frame before ("and put [it] away"),
        or to the container it was just put in (:meth:`carried`)."""
        carried = self.carried(frame, role)
        if carried is not None:
            index, name, _ = carried
            root = self.frames[index].elements[name]
            return Phrase("", root.head, root.cls, root.kind, (index, name), root.quantity, root.plural)
        for index in range(len(self.frames) - 1, -1, -1):
            evoked = self.frames[index]
            if not evoked.elements:
                continue
            name, phrase = next(iter(evoked.elements.items()))
            if phrase.kind != "thing" or phrase.default:
                continue
            target = phrase.refers_to or (index, name)
            root = self.frames[target[0]].elements[target[1]]
            return Phrase("", root.head, root.cls, root.kind, target, root.quantity, root.plural)
        return None

    def phrase(self, np: NP, frame: Frame, role: str) -> Phrase:
        if np.pronoun is not None and (np.kind in ("pronoun", "thing") or np.pronoun in ("him", "her", "he", "she")) \
                and np.pronoun not in ("something", "everything", "anything", "nothing"):
            found = self.antecedent(np, frame, role)
            if found is not None:
                index, name, _ = found
                target = self.frames[index].elements[name]
                ref = target.refers_to or (index, name)
                root = self.frames[ref[0]].elements[ref[1]]
                return Phrase(self.text[np.start:np.end], root.head, root.cls, found[2], ref, root.quantity,
                              root.plural, span=(np.start, np.end))
            said = self.mentioned(np, frame, role)
            if said is not None:                    # "Bogdan has a question; answer it for him"
                person = said.name or self.taxonomy.is_a(noun_lemma(said.head), "person") is True
                return Phrase(self.text[np.start:np.end], said.head if said.name else noun_lemma(said.head),
                              None, "person" if person else "thing", span=(np.start, np.end))
            return Phrase(self.text[np.start:np.end], np.head_text, None,
                          "thing" if np.kind == "pronoun" and np.pronoun == "it" else
                          "person" if np.kind == "pronoun" else np.kind, span=(np.start, np.end))
        if np.there:
            place = self.place_before()
            if place is not None:                   # "go to the garage and count the bikes there"
                root = self.frames[place[0]].elements[place[1]]
                return Phrase(self.text[np.start:np.end], root.head, root.cls, root.kind, place, root.quantity,
                              root.plural, span=(np.start, np.end))
        text = self.text[np.start:np.end]
        cls = None
        if self.vocabulary is not None and np.kind != "message":
            cls = self.vocabulary.ground_np(np)
        whole = self.cut_from(np) if cls is None else None
        if whole is not None:                   # "slice the bread, take a slice": a slice of the bread
            index, name = whole
            root = self.frames[index].elements[name]
            ref = root.refers_to or (index, name)
            root = self.frames[ref[0]].elements[ref[1]]
            return Phrase(text, root.head, root.cls, root.kind, ref, None, np.plural, span=(np.start, np.end))
        modifiers = tuple(noun_lemma(w.text) if w.tag == "WORD" else w.lower for w in np.mods)
        conjuncts = tuple(self.phrase(c, frame, role) for c in np.conjuncts) if len(np.conjuncts) > 1 else ()
        return Phrase(text, np.head_text if np.kind != "message" else text, cls, np.kind, None, np.quantity,
                      np.plural and np.kind != "message", modifiers, span=(np.start, np.end), conjuncts=conjuncts,
                      relative=np.relative)

    def place_before(self) -> tuple[int, str] | None:
        """The place named last in an earlier clause (a goal, ground or source said, not a default, and no
        person; through a "there" or pronoun that stood for one), as (frame index, element); None."""
        best: tuple[int, tuple[int, str]] | None = None
        for index in range(self.clause_frames):
            for role, phrase in self.frames[index].elements.items():
                if phrase.default or phrase.span is None or role not in _PLACES:
                    continue
                target = phrase.refers_to or (index, role)
                if self.frames[target[0]].elements[target[1]].kind != "thing":
                    continue                                  # a person, "here": no place named
                if best is None or phrase.span[0] >= best[0]:
                    best = (phrase.span[0], target)
        return None if best is None else best[1]

    def ground_name(self, name: str) -> str | None:
        if self.vocabulary is None:
            return name
        return self.vocabulary.ground_name(name) or name


def _whole_named(np: NP) -> bool:
    """Whether a piece's modifiers name what it is cut from ("an *apple* slice"): a modifier that is no
    gradable adjective ("the *little* piece", "a *thin* slice" say how it is, not of what)."""
    return any(not is_gradable(m.lower) for m in np.mods)
