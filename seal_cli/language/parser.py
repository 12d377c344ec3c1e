"""The command language: text → the frames it evokes, with their elements filled.

A :class:`CommandParser` (one per frame library) runs the stages, one module each:

1. :mod:`~seal_cli.language.lexicon` tags the words;
2. the LALR grammar ``grammars/command.lark`` parses the tags (trees are shared by commands of one
   tag sequence), and :mod:`~seal_cli.language.syntax` turns the tree into clauses of typed noun
   phrases (:class:`~seal_cli.language.syntax.NP`) and prepositional phrases;
3. :mod:`~seal_cli.language.clauses` runs the clause-to-clause passes (relatives, gapping,
   coordination, subordinate clauses, order words, light verbs);
4. :mod:`~seal_cli.language.evoking` turns each clause into frames: which frame of the verb, the
   elements its phrases fill (:mod:`~seal_cli.language.roles`, a preposition → roles table), what
   pronouns refer to (:mod:`~seal_cli.language.reference`), the frames result words, contents and
   pieces imply, defaults, and grounding in a vocabulary (:mod:`~seal_cli.language.grounding`).

:func:`parse_command` is the public function; it asks the parser of the library it is given.
"""

from __future__ import annotations

import re
from collections.abc import Iterable, Iterator, Sequence
from dataclasses import replace
from typing import TYPE_CHECKING, Any

from lark import Tree

from seal_cli.errors import SealError, SealErrors
from seal_cli.frames.library import Library
from seal_cli.language.asked import thing_asked
from seal_cli.language.becoming import becoming
from seal_cli.language.clauses import Clauses
from seal_cli.language.element_types import Types
from seal_cli.language.english import BE_WORDS, NP_OPENERS, NUMBERS, SPEECH_ACTS, WH_WORDS
from seal_cli.language.evoking import Evoker
from seal_cli.language.goals import infer_goal
from seal_cli.language.lexicon import CommandError, Lexicon, Tagger, Word, tokenize
from seal_cli.language.morphology import in_verb_tables, parts_of_speech
from seal_cli.language.phrasal import phrasal_verb
from seal_cli.language.reported import merge_reported
from seal_cli.language.rules.negatives import opens_prohibition
from seal_cli.language.searches import drop_found_again, merge_searches
from seal_cli.language.slicing import infer_slice
from seal_cli.language.stacking import infer_stack
from seal_cli.language.state import CLOSED, State
from seal_cli.language.steps import infer_left_in, infer_step
from seal_cli.language.swallowed import Swallowed, swallowed
from seal_cli.language.syntax import NP, Syntax
from seal_cli.language.tags import Tag
from seal_cli.language.taskfields import reread
from seal_cli.language.tasks import infer_task
from seal_cli.language.units import unit_problems
from seal_cli.language.unmade import unmade_state
from seal_cli.language.unplaced import unplaced_error
from seal_cli.language.values import Evoked, Parse, Phrase

if TYPE_CHECKING:
    from lark import Lark

    from seal_cli.language.grounding import Vocabulary

__all__ = ["NP", "CommandError", "CommandParser", "Evoked", "Parse", "Phrase", "parse_command", "parse_lines"]


class CommandParser:
    """Parses commands for one frame library: owns its lexicon, its memoised types, the parse trees
    seen (by tag sequence) and the vocabularies merged with the library's synonyms."""

    TREES = 4096
    """How many parse trees are kept (by tag sequence) before the cache starts again."""

    def __init__(self, library: Library) -> None:
        problems = unit_problems(library)      # a unit "the" read "the cup" as its frame (hostile32)
        if problems:
            raise problems[0] if len(problems) == 1 else SealErrors(problems)
        self.library = library
        self.lexicon = Lexicon.of(library)
        self.types = Types(library)
        self.trees: dict[tuple[str, ...], Tree] = {}
        """Parse trees by tag sequence. The grammar reads tags, not words, and a tree's tokens point at
        words by their index, so commands of one shape ("take the X from the Y") share one parse."""
        self._merged: dict[int, tuple[Vocabulary, Vocabulary]] = {}

    @classmethod
    def of(cls, library: Library) -> CommandParser:
        """The parser of a library (made once per library object)."""
        found = _PARSERS.get(id(library))
        if found is not None and found.library is library:
            return found
        parser = _PARSERS[id(library)] = cls(library)
        return parser

    def parse(self, text: str, vocabulary: Vocabulary | None = None, infer_steps: bool = True) -> Parse:
        """The frames a command evokes. Raises :class:`CommandError` (a SealError with a column and
        what was expected) when it cannot be parsed. ``infer_steps``: add the step a sentence most
        likely leaves unsaid, where the vocabulary's statistics know it (:mod:`~seal_cli.language.steps`)."""
        lexicon = self.lexicon
        if not text.strip():
            raise CommandError("empty command: expected a verb, such as " + _some_verbs(lexicon), 1, text,
                               ["a verb"])
        tokens = tokenize(text)
        if vocabulary is not None and vocabulary.people:
            tokens = [_as_name(w) if w.lower in vocabulary.people else w for w in tokens]
        tagger = Tagger(lexicon, tokens, text)
        words = tagger.run()
        if not words:
            raise CommandError("no words in the command: expected a verb, such as " + _some_verbs(lexicon),
                               _first_column(text), text, ["a verb"])
        phrasal = phrasal_verb(words, lexicon)
        if phrasal is not None:
            raise _phrasal_error(text, lexicon, *phrasal)
        unmade = unmade_state(tokens, lexicon)
        if unmade is not None:
            raise _unmade_error(text, lexicon, *unmade)
        became = becoming(words)
        if became is not None:
            raise _becoming_error(text, lexicon, *became)
        tree = self.tree(text, words)
        if vocabulary is not None:
            vocabulary = self.with_library_synonyms(vocabulary).in_context(text)   # the sentence weighs
        command = Syntax(text, words, self.types).transform(tree)
        clauses = Clauses(text, self.library, self.types, lexicon.speech).passes(command)
        evoker = Evoker(text, self.library, self.types, vocabulary, words, tagger.remarks)
        parse = merge_reported(drop_found_again(merge_searches(evoker.command(clauses))), self.library)
        lost = swallowed(parse, words, lexicon, self.library.taxonomy.known_classes)
        if lost:
            raise _swallowed_error(parse, lost[0])
        if evoker.unplaced:               # a phrase no element took: refused at it, never dropped silently
            raise unplaced_error(text, *evoker.unplaced[0])
        thing = thing_asked(parse, self.library, lexicon)
        if thing is not None:
            raise _thing_asked_error(text, lexicon, *thing)
        if infer_steps and vocabulary is not None:
            parse = infer_task(parse, self.library, vocabulary, vocabulary.task_model, vocabulary.context)
            parse = infer_slice(parse, self.library, vocabulary, vocabulary.slice_model, vocabulary.context)
            parse = infer_stack(parse, vocabulary.stack_model)
            parse = infer_left_in(parse, self.library, vocabulary.step_model)
            parse = infer_step(parse, self.library, vocabulary, vocabulary.step_model, vocabulary.context)
            parse = infer_goal(parse, self.library, vocabulary.by_key, vocabulary.goal_model, vocabulary.context,
                               vocabulary.house)
            parse = reread(parse, self.library, vocabulary, vocabulary.field_model, text)
        remarks = sorted([*tagger.remarks, *evoker.beside])
        if remarks:
            parse = replace(parse, remarks=tuple(text[a:b] for a, b in remarks))
        return parse

    def tree(self, text: str, words: Sequence[Word]) -> Tree:
        """The grammar's tree of the tagged words (shared by commands of the same tags)."""
        from lark.exceptions import UnexpectedInput

        tags = tuple(w.tag for w in words)
        tree = self.trees.get(tags)
        if tree is None:
            try:
                tree = command_parser().parse(words)
            except UnexpectedInput as error:
                raise _explain(error, text, words, self.lexicon) from None
            if len(self.trees) >= self.TREES:
                self.trees.clear()
            self.trees[tags] = tree
        return tree

    def with_library_synonyms(self, vocabulary: Vocabulary) -> Vocabulary:
        """The vocabulary with the library's synonyms of its classes (``framelib/synonyms.yaml``:
        a map's ``Fridge`` is also called "refrigerator"); made once per vocabulary."""
        found = self._merged.get(id(vocabulary))
        if found is not None and found[0] is vocabulary:
            return found[1]
        merged = vocabulary.with_synonyms(self.library.taxonomy.names)
        if len(self._merged) > 64:
            self._merged.clear()
        self._merged[id(vocabulary)] = (vocabulary, merged)
        return merged


_PARSERS: dict[int, CommandParser] = {}
"""The parser of each library object (by identity: a library is a value, costly to hash)."""


def parse_command(text: str, library: Library, vocabulary: Vocabulary | None = None,
                  infer_steps: bool = True) -> Parse:
    """The frames a command evokes. Raises :class:`CommandError` (a SealError with a column and
    what was expected) when it cannot be parsed. ``infer_steps=False``: never add an unsaid step
    (:mod:`~seal_cli.language.steps`), even where the statistics know one."""
    return CommandParser.of(library).parse(text, vocabulary, infer_steps)


def lexicon_of(library: Library) -> tuple[Lexicon, Types]:
    """The library's lexicon and memoised types (its parser's)."""
    parser = CommandParser.of(library)
    return parser.lexicon, parser.types


# ---------------------------------------------------------------------------------------------
# The grammar (built once: it does not depend on the library)

_GRAMMAR: Lark | None = None


def command_parser(strict: bool = False) -> Lark:
    """The LALR parser of ``grammars/command.lark`` over tagged words (Lark caches its tables
    on disk, so a new process builds it in milliseconds)."""
    global _GRAMMAR
    if _GRAMMAR is not None and not strict:
        return _GRAMMAR
    from lark import Lark

    from seal_cli.resources import grammar_path

    grammar = grammar_path("command.lark").read_text(encoding="utf-8")
    parser = Lark(grammar, parser="lalr", lexer=_tag_lexer(), strict=strict, maybe_placeholders=False,
                  cache=not strict)
    if not strict:
        _GRAMMAR = parser
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

# ---------------------------------------------------------------------------------------------
# Lines, and errors a person can act on




def parse_lines(lines: Iterable[str], library: Library,
                vocabulary: Vocabulary | None = None) -> Iterator[dict[str, Any]]:
    """One JSON object per line: the parse, or ``{"text", "error"}`` for a line that cannot be parsed."""
    for line in lines:
        text = line.rstrip("\r\n")
        try:
            yield parse_command(text, library, vocabulary).to_json()
        except SealError as error:
            yield {"text": text, "error": _error_json(error)}


def _as_name(word: Word) -> Word:
    """A word that names a person of the world, written as a name ("take *sam*": Sam) for the tagger; the
    command's text, which the elements quote, is unchanged."""
    return Word(word.text[:1].upper() + word.text[1:], word.start, word.end, word.tag, word.info, word.lower)


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


def _swallowed_error(parse: Parse, lost: Swallowed) -> CommandError:
    """A verb said inside an element's text is an instruction the frames would drop: refused, never
    lost silently ("go to the sink to meet Alex")."""
    evoked = parse.frames[lost.frame]
    phrase = evoked.elements[lost.element]
    return CommandError(f"{lost.verb!r} is a verb inside the {lost.element} {phrase.text!r} of {evoked.frame}: "
                        f"say it as an instruction of its own (\"..., then {lost.verb} ...\")", lost.start + 1,
                        parse.text, ["a clause of its own"])


def _some_verbs(lexicon: Lexicon, near: str | None = None) -> str:
    verbs, known = lexicon.verbs, lexicon.verb_set  # 'in' the 667 verbs for each: 2 ms a refusal, hours for a
    # --file of blank lines (16 MiB of them: 16 million refusals)
    import difflib

    close = difflib.get_close_matches(near, verbs, n=3, cutoff=0.6) if near else []
    shown = close + [v for v in ("bring", "find", "go", "pick up", "put", "follow", "tell") if v in known
                     and v not in close]
    for verb in (*lexicon.can, *verbs):  # the frames' own first verbs ("open", "heat"), not the alphabet's first
        if len(shown) >= 8:               # ("abandon"); only as many as are shown (each refusal went through all)
            break
        if verb in known and verb not in shown:
            shown.append(verb)
    return ", ".join(shown[:8]) + (f" ({len(verbs)} in all; `seal frames` lists them)" if len(verbs) > 8 else "")


def _phrasal_error(text: str, lexicon: Lexicon, verb: Word, particle: Word) -> CommandError:
    """A verb made another by its particle ("hang up the phone"): refused at the verb, with what the robot can do, and,
    for a verb that puts a thing somewhere, how to say the verb's own sense: with where the thing goes ("hang up my
    jacket on the coat rack" is a Place; e2e32: "hang up my jacket" said only what the robot can do)."""
    said = f"{verb.text.lower()} {particle.lower}"
    unit = str(verb.info)
    thing = _object_said(text, verb, particle)
    example = f"{said} {thing}" if thing else f"{verb.text.lower()} it {particle.lower}"
    hint = f"; to {unit} a thing somewhere, say where it goes (\"{example} on the ...\")" \
        if unit in lexicon.puts else ""
    return CommandError(f"{said!r} is a verb of its own, not {unit!r}: no frame of the library does it{hint}; "
                        f"the robot can {_either(list(lexicon.can))}", verb.start + 1, text, ["a verb"])


def _unmade_error(text: str, lexicon: Lexicon, state: Word, verb: str) -> CommandError:
    """"I want the door *locked*": a state no frame brings about (:mod:`~seal_cli.language.unmade`); refused there."""
    return CommandError(f"{state.text.lower()!r}: the robot cannot {verb} things (no frame of the library does it), "
                        f"so it cannot make a thing {state.text.lower()}; it can {_either(list(lexicon.can))}",
                        state.start + 1, text, ["a state the robot brings about"])


def _becoming_error(text: str, lexicon: Lexicon, verb: Word, state: Word) -> CommandError:
    """"get dressed": becoming so, no thing got (:mod:`~seal_cli.language.becoming`); refused at the verb."""
    said = f"{verb.text.lower()} {state.text.lower()}"
    return CommandError(f"{said!r} is becoming {state.text.lower()}, not getting a thing: no frame of the library "
                        f"does it; the robot can {_either(list(lexicon.can))}", verb.start + 1, text, ["a verb"])


def _object_said(text: str, verb: Word, particle: Word) -> str:
    """The words of the thing a phrasal verb's clause names ("my jacket" of "hang up my jacket", "the kids" of "tuck
    the kids in"), up to four words before the clause goes on; "" when there are none or more."""
    between = text[verb.end:particle.start].strip()
    after = re.split(r"[,;.!?]| and | then ", text[particle.end:], maxsplit=1)[0].strip()
    words = (between or after).split()
    return " ".join(words) if len(words) <= 4 else ""


def _thing_asked_error(text: str, lexicon: Lexicon, evoked: Evoked, role: str) -> CommandError:
    """A thing where words are asked ("answer the door"): refused at the verb, with what the robot can do."""
    phrase = evoked.elements[role]
    return CommandError(f"{phrase.text!r} is a thing, not a question to {evoked.lexical_unit}: "
                        f"'{evoked.lexical_unit} {phrase.text}' is no frame of the library; "
                        f"the robot can {_either(list(lexicon.can))}", evoked.span[0] + 1, text, ["a question"])


def _no_verb(word: str) -> bool:
    """Whether a command's first word opens a phrase and is no verb (words32): a determiner or number ("*two* sugars
    in my tea", "*another* cushion"), or a noun English has no verb of ("*tea* for two"); a misspelt verb ("brin")
    is neither, and keeps the message that names the verbs spelt like it."""
    return word in NP_OPENERS or word in NUMBERS or word.isascii() and word.isdigit() or \
        not in_verb_tables(word) and "noun" in parts_of_speech(word)


def _verbless(words: Sequence[Word]) -> bool:
    """Whether the tagged command is phrases only: no verb found, no "is", no question, no "to" ("where is being my
    bag?", "kids breakfast is ready, tell Tom ...": not said as a thing alone)."""
    return not any(w.tag == "VERB" or w.lower in BE_WORDS or w.lower in WH_WORDS or w.lower in ("?", "to")
                   for w in words)             # "keys need *to* end up on the chair": a verb after all


def _unknown_verb(lexicon: Lexicon, word: str) -> str:
    """The message for a verb no frame lists: the known verbs spelt like it first, when it is no verb of English
    ("brin": bring), else what the robot can do, one verb for each frame of the library ("tidy", "wait", "make":
    none of them)."""
    import difflib

    if word in lexicon.verbs:  # a library's verb English reads as a noun too ("zap"): "unknown verb 'zap' ... or zap"
        return (f"{word!r} is read here as a thing, not as the library's verb {word!r}: say what to {word} "
                f"('{word} the ...', '{word} it')")
    english = in_verb_tables(word) and word not in CLOSED                   # "this", "it": no verbs here
    close = [] if english else difflib.get_close_matches(word, lexicon.verbs, n=3, cutoff=0.75)
    if close or not lexicon.can:                 # "make" is a verb of English, no misspelt "take"
        meant = [verb for verb in close if _one_letter_replaced(word, verb)]
        asked = f": did you mean {meant[0]!r}? (one letter differs)" if len(meant) == 1 else ""
        return f"unknown verb {word!r}{asked}; known verbs include {_some_verbs(lexicon, word)}"
    return (f"unknown verb {word!r}: no frame of the library does it; the robot can {_either(list(lexicon.can))} "
            f"({len(lexicon.verbs)} verbs in all; `seal frames` lists them)")


def _one_letter_replaced(word: str, verb: str) -> bool:
    """Whether ``word`` is ``verb`` with one letter typed for another, past the first ("cound": count, "brimg": bring;
    words39). Such a slip is not read as the verb ("cound" is as near "could", "found", "round"): the refusal asks."""
    return len(word) == len(verb) and word[0] == verb[0] and sum(a != b for a, b in zip(word, verb, strict=True)) == 1


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
        if opens_prohibition(words, token.start_pos):
            return CommandError(f"{_said_from(text, words, token.start_pos)!r} asks the robot not to do something: "
                                f"no frame of the library does that; say what it should do (it can "
                                f"{_either(list(lexicon.can))})", column, text, ["a verb"])
        if _asks(words, token.start_pos):
            return CommandError(f"{_said_from(text, words, token.start_pos)!r} is a question the robot cannot answer:"
                                f" it tells what is where, how many there are, which thing is the biggest, lightest "
                                f"..., who a person is and what they wear or do; else say what it should do (it can "
                                f"{_either(list(lexicon.can))})", column, text, ["a verb"])
        if _states(lexicon, text, words[token.start_pos].start):
            return CommandError(f"{_said_from(text, words, token.start_pos)!r} is a statement, no command: "
                                f"say what the robot should do (it can "
                                f"{_either(list(lexicon.can))})", column, text, ["a verb"])
        if token.start_pos == 0 and _no_verb(word) and _verbless(words):
            return CommandError(f"{_said_from(text, words, token.start_pos)!r} says no verb: a thing said alone is "
                                f"asked for with 'please' ('the keys, please') or 'for' and a person ('coffee for "
                                f"Ruth'); else say what to do with it (the robot can {_either(list(lexicon.can))})",
                                column, text, ["a verb"])
        return CommandError(_unknown_verb(lexicon, word), column, text, ["a verb"])
    before = _word_before(words, words[token.start_pos].start if not at_end else len(text))
    after = f" after {before!r}" if before else ""
    if wants_verb and at_end and all(w.tag in (Tag.POLITE, Tag.SEP, Tag.END) for w in words) and \
            any(part in SPEECH_ACTS for w in words for part in w.lower.split()):
        return CommandError(f"{text.strip()!r} asks nothing: a greeting, thanks or politeness alone is no "
                            f"instruction; say what the robot should do (it can {_either(list(lexicon.can))})",
                            _first_column(text), text, ["a verb"])
    if wants_verb:
        return CommandError(f"expected a verb{after}, such as {_some_verbs(lexicon)}", column, text, ["a verb"])
    if at_end:
        return CommandError(f"the command ends too early{after}: expected {_either(expected)}", column, text,
                            expected)
    return CommandError(f"unexpected {str(token)!r}{after}: expected {_either(expected)}", column, text, expected)


_ASKING_NEXT = frozenset(["is", "are", "was", "were", "'s", "do", "does", "did", "can", "could", "will", "would",
                          "should", "has", "have", "old", "heavy", "big", "long", "far", "much", "tall", "often"])
"""Words after a question word that make it a question ("*why is* the fridge open?", "*how old* is ...")."""


def _asks(words: Sequence[Word], k: int) -> bool:
    """Whether the words from ``k`` are a question no rule read as one the robot answers ("why is the fridge
    open?", "how heavy is the box?"; words41: they were refused as statements): a question word where the clause
    starts, then an auxiliary or "how"'s adjective, or a question mark ending its sentence."""
    low = words[k].lower
    if low not in WH_WORDS or low in ("if", "whether"):
        return False
    nxt = words[k + 1].lower if k + 1 < len(words) else ""
    end = next((w.lower for w in words[k + 1:] if w.lower in (".", "!", "?", ";")), "")
    return nxt in _ASKING_NEXT or end == "?"


def _states(lexicon: Lexicon, text: str, start: int) -> bool:
    """Whether a statement opens at character ``start`` of ``text`` ("*rose wants to go to bed*", "*the door is
    open*": a subject and a finite verb, :meth:`State.statement_at`): no verb the robot lacks."""
    raw = tokenize(text)
    k = next((j for j, w in enumerate(raw) if w.start == start), None)
    return k is not None and State(lexicon, raw, text).statement_at(k) > 0


def _said_from(text: str, words: Sequence[Word], k: int) -> str:
    """The words of the clause from word ``k`` to the end of its sentence, as said."""
    end = next((w.start for w in words[k + 1:] if w.lower in (".", "!", "?", ";")), len(text))
    return text[words[k].start:end].strip()


def _word_before(words: Sequence[Word], position: int) -> str | None:
    before = [w for w in words if w.end <= position]
    return before[-1].text if before else None


def _either(options: Sequence[str]) -> str:
    if not options:
        return "something else"
    return options[0] if len(options) == 1 else ", ".join(options[:-1]) + " or " + options[-1]

