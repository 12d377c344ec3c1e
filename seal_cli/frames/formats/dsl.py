"""Frame libraries written in the ``.frame`` DSL (``grammars/frames.lark``).

The DSL states exactly the YAML model; a file in one form and its translation into the other
load to equal frames. Reading never raises: problems are collected with their position.
"""

from __future__ import annotations

import json
import re
from collections.abc import Iterator
from functools import cache
from typing import Any

from lark import Lark, Token, Tree, UnexpectedCharacters, UnexpectedEOF, UnexpectedInput, UnexpectedToken

from seal_cli.errors import SealError, Where
from seal_cli.frames.formats import Contents
from seal_cli.frames.model import Action, Element, Fact, Frame, LexicalUnit
from seal_cli.frames.taxonomy import Category, Synonyms, Taxonomy
from seal_cli.resources import grammar_path

__all__ = ["dump", "parser", "read"]

# What a person calls the grammar's terminals in a message.
_TERMINALS = {"NAME": "a name (letters, digits and '_', not starting with a digit)",
              "STRING": 'a "quoted" lexical unit', "LBRACE": "'{'", "RBRACE": "'}'",
              "LPAR": "'('", "RPAR": "')'", "COMMA": "','", "COLON": "':'", "EQUAL": "'='", "NOT": "'not'",
              "OPEN": "'*'", "$END": "the end of the file"}


@cache
def parser(strict: bool = False) -> Lark:
    """The DSL's LALR parser (``strict=True`` also proves the grammar free of conflicts)."""
    return Lark(grammar_path("frames.lark").read_text(encoding="utf-8"), parser="lalr", strict=strict,
                propagate_positions=True, maybe_placeholders=False,
                cache=not strict)  # Lark's cache of the parse table: ~0.15 s less at every start


def _describe(names: set[str] | frozenset[str]) -> str:
    words = sorted({_TERMINALS.get(n, repr(n.lower())) for n in names})
    return ", ".join(words[:-1]) + (" or " if len(words) > 1 else "") + words[-1] if words else "nothing"


# Worked examples of each mistake, for lark's ``match_examples``: the error's parser state is
# compared with theirs, and the label of the matching one says in words what to write.
MISTAKES: dict[str, list[str]] = {
    "an action cannot be negated: only facts take 'not' (write the undoing in 'ensures not ...')": [
        'frame A { x: t\n do not a(x) }', 'frame A { x: t\n do a(x), not b(x) }'],
    "a comma is missing between two facts or actions (write 'requires a(x), b(x)')": [
        'frame A { x: t\n requires a(x) b(x) }', 'frame A { x: t\n ensures a(x) b(x) }',
        'frame A { x: t\n do a(x) b(x) }', 'frame A { x: t\n requires a b(x) }'],
    "an element is written 'role: category' (a colon between them)": [
        'frame A { x t }', 'frame A { x: t\n y t }'],
    "after '=' comes the default, a class name ('instrument: utensil = spoon')": [
        'frame A { x: t = }', 'frame A { x: t = "s" }'],
    "after ',' in an argument list comes another name ('stir(instrument, theme)')": [
        'frame A { x: t\n requires a(x,) }', 'frame A { x: t\n do a(x,) }'],
    "an action takes its arguments in parentheses ('navigate(theme)')": [
        'frame A { x: t\n do a }', 'frame A { x: t\n do a, b(x) }'],
    "the frame is not closed: add '}' after its last member": [
        'frame A { x: t', 'frame A { x: t\n requires a(x)', 'frame A {'],
    "a frame is 'frame Name \"unit\" ... {': a name, then quoted lexical units, then '{'": [
        'frame "stir" { }', 'frame A stir { }', 'frame A "a" }', 'frame { }'],
    "a lexical unit is written in double quotes ('\"pick up\"')": [
        "frame A 'stir' { }"],
}


def _syntax_problem(exc: UnexpectedInput, text: str, file: str) -> SealError:
    lines = text.split("\n")
    line = getattr(exc, "line", None)
    column = getattr(exc, "column", None)
    if isinstance(exc, UnexpectedEOF) or line is None or line < 1:
        line, column = max(len(lines), 1), len(lines[-1]) + 1 if lines else 1
    source = lines[line - 1] if 0 < line <= len(lines) else ""
    if isinstance(exc, UnexpectedCharacters):
        found = repr(source[column - 1]) if column and column - 1 < len(source) else "this character"
        message = f"unexpected {found}"
    elif isinstance(exc, UnexpectedToken):
        token = exc.token
        found = "end of file" if token.type == "$END" else repr(str(token))
        message = f"unexpected {found}"
    else:
        message = "unexpected end of file"
    expected = getattr(exc, "expected", None) or getattr(exc, "allowed", None)
    if expected:
        message += f"; expected {_describe(set(expected))}"
    label = _mistake(exc)
    if label:
        message = f"{label} (found {found if isinstance(exc, UnexpectedCharacters | UnexpectedToken) else 'the end'})"
    odd = source[column - 1] if isinstance(exc, UnexpectedCharacters) and column and column <= len(source) else ""
    if odd.isalpha() and not odd.isascii():   # 'thème' was "a comma is missing between two facts (found 'è')"
        message = (f"a name in a .frame file is written in the letters A-Z and a-z, digits and '_' (found {odd!r}); "
                   "a YAML frame file takes element, category and class names in any letters")
    return SealError(f"syntax error: {message}", Where(file, line, column), source_line=source)


def _mistake(exc: UnexpectedInput) -> str | None:
    """The mistake whose worked examples fail in the parser state where ``exc`` failed (and on the
    same kind of token, when one does), if any. Lark's own ``match_examples`` compares whole
    parser stacks, which differ with every statement before the mistake; the state on top is
    what says where in a frame the parse stopped."""
    key = _failure(exc)
    if key is None:
        return None
    table = _mistake_table()
    return table.get(key) or table.get((key[0], None))


def _failure(exc: UnexpectedInput) -> tuple[int, str | None] | None:
    state = getattr(exc, "state", None)
    position = getattr(state, "position", None)
    if not isinstance(position, int):
        return None
    token = getattr(exc, "token", None)
    return (position, getattr(token, "type", None))


@cache
def _mistake_table() -> dict[tuple[int, str | None], str]:
    table: dict[tuple[int, str | None], str] = {}
    for label, examples in MISTAKES.items():
        for example in examples:
            try:
                parser().parse(example)
            except UnexpectedInput as exc:
                key = _failure(exc)
                if key is not None:
                    table.setdefault(key, label)
                    table.setdefault((key[0], None), label)
    return table


class _Builder:
    """Walks the parse tree into model objects, recording problems."""

    def __init__(self, text: str, file: str) -> None:
        self.file = file
        self.lines = text.split("\n")
        self.contents = Contents()

    def where(self, item: Tree | Token) -> Where:
        if isinstance(item, Token):
            return Where(self.file, item.line, item.column)
        return Where(self.file, item.meta.line, item.meta.column)

    def problem(self, exc: SealError, at: Tree | Token) -> None:
        for problem in getattr(exc, "problems", None) or [exc]:
            where = problem.where if problem.where.line else self.where(at)
            if where.file is None:
                where = Where(self.file, where.line, where.column)
            line = self.lines[where.line - 1] if where.line and where.line <= len(self.lines) else None
            self.contents.problems.append(SealError(problem.message, where, source_line=line))

    def build(self, tree: Tree) -> None:
        for statement in tree.children:
            assert isinstance(statement, Tree)
            try:
                getattr(self, str(statement.data))(statement)
            except SealError as exc:
                self.problem(exc, statement)

    def frame(self, tree: Tree) -> None:
        name, *rest = tree.children
        fields: dict[str, Any] = {"lexical_units": [], "elements": [], "preconditions": [], "actions": [],
                                  "postconditions": []}
        for child in rest:
            assert isinstance(child, Tree)
            kind = str(child.data)
            try:
                if kind == "unit":
                    fields["lexical_units"].append(LexicalUnit(_string(child.children[0]), self.where(child)))
                elif kind == "element":
                    role, type_, *default = child.children
                    value = str(default[0].children[0]) if default else None
                    fields["elements"].append(Element(str(role), str(type_), value, self.where(child)))
                elif kind in ("requires", "ensures"):
                    key = "preconditions" if kind == "requires" else "postconditions"
                    fields[key].extend(self.fact(f) for f in child.children)
                elif kind == "does":
                    fields["actions"].extend(self.action(a) for a in child.children)
                elif kind == "description":
                    fields["description"] = _string(child.children[0])
                elif kind == "framenet":
                    fields["framenet"] = str(child.children[0])
            except SealError as exc:
                self.problem(exc, child)
        frozen: dict[str, Any] = {k: tuple(v) if isinstance(v, list) else v for k, v in fields.items()}
        try:
            frame = Frame(str(name), where=self.where(name), **frozen)
        except SealError as exc:  # still checked with the others, without the parts refused
            self.problem(exc, tree)
            salvaged = Frame.salvage(str(name), where=self.where(name), **frozen)
            if salvaged is not None:
                self.contents.frames.append(salvaged)
            return
        self.contents.frames.append(frame)

    def fact(self, tree: Tree) -> Fact:
        negated = bool(tree.children) and isinstance(tree.children[0], Token) and tree.children[0].type == "NOT"
        parts = tree.children[1:] if negated else tree.children
        name = str(parts[0])
        args = tuple(str(a) for a in parts[1].children) if len(parts) > 1 else ()
        return Fact(name, args, negated, self.where(tree))

    def action(self, tree: Tree) -> Action:
        name, arguments = tree.children
        return Action(str(name), tuple(str(a) for a in arguments.children), self.where(tree))

    def category(self, tree: Tree) -> None:
        name, members = tree.children
        listed = None if isinstance(members, Token) else tuple(str(m) for m in members.children)
        category = Category(str(name), listed, self.where(tree))
        self.contents.taxonomy = self.contents.taxonomy.merged(Taxonomy((category,)))

    def synonyms(self, tree: Tree) -> None:
        name, members = tree.children
        entry = Synonyms(str(name), tuple(str(m) for m in members.children), self.where(tree))
        self.contents.taxonomy = self.contents.taxonomy.merged(Taxonomy(synonyms=(entry,)))

    def world(self, tree: Tree) -> None:
        self.contents.taxonomy = self.contents.taxonomy.merged(
            Taxonomy((), tuple(str(w) for w in tree.children)))


def _string(token: Any) -> str:
    """A quoted string's text, with JSON's escapes (``\\"``, ``\\\\``, ``\\n``, ``\\u00e9``)."""
    try:
        return str(json.loads(str(token)))
    except json.JSONDecodeError as exc:
        bad = str(token)[exc.pos:exc.pos + 2] if exc.msg.startswith("Invalid \\escape") else str(token)[exc.pos]
        line, column = getattr(token, "line", None), getattr(token, "column", None)
        where = Where(None, line, column + exc.pos) if line is not None and column is not None else None
        raise SealError(f"a quoted string may not hold {bad!r}: write a tab or a newline as \\t or \\n, a "
                        "quote as \\\", a backslash as \\\\, any other character as itself or \\uXXXX",
                        where) from None


def read(text: str, file: str = "<frame>") -> Contents:
    """The frames, categories and problems in a ``.frame`` file's text. After a syntax error each
    statement is parsed on its own, so that one mistake hides none of the file's other problems.

    A line ends at LF, CRLF or a lone CR (an old Mac editor's, as YAML reads it): a file saved with CR alone was
    one line to the grammar, whose first ``//`` comment took the whole file, so it validated "ok: 0 frames"
    and ``--framelib +f.frame`` added nothing, silently (hostile22). Only those end a line: the lines of
    messages are the grammar's (``str.splitlines`` also split at U+2028 or a form feed, so a caret could be
    drawn under another line than the one named)."""
    text = text.replace("\r\n", "\n").replace("\r", "\n")
    builder = _Builder(text, file)
    past = _control(text, file, builder.lines) or _past_bound(text, file, builder.lines)
    if past is not None:
        builder.contents.problems.append(past)
        return builder.contents
    try:
        tree = parser().parse(text)
    except UnexpectedInput:
        for offset, chunk in _statements(text):
            try:
                tree = parser().parse(chunk)
            except UnexpectedInput as exc:
                builder.contents.problems.append(_shifted(_syntax_problem(exc, chunk, file), offset, builder.lines))
                continue
            _shift(tree, offset)
            builder.build(tree)
        return builder.contents
    builder.build(tree)
    return builder.contents


_CONTROL = re.compile(r"[\x00-\x08\x0b\x0e-\x1f\x7f-\x9f]")
"""The control characters a ``.frame`` file may not hold anywhere (all but a tab, a line break and a form feed)."""


def _control(text: str, file: str, lines: list[str]) -> SealError | None:
    """The refusal of a file holding a control character, at the first: in a comment it was read with the comment,
    silently (a NUL, hostile31), as YAML refuses it anywhere in a file; in a name it was "the frame is not closed"."""
    found = _CONTROL.search(text)
    if found is None:
        return None
    line = text.count("\n", 0, found.start()) + 1
    column = found.start() - (text.rfind("\n", 0, found.start()) + 1) + 1
    code = ord(found.group())
    return SealError(f"a frame file may not hold the control character {found.group()!r} (U+{code:04X}), not even in "
                     "a comment: remove it (a tab, a line break and a form feed are the only ones a frame file takes)",
                     Where(file, line, column), source_line=lines[line - 1])


MAX_WORDS = 150_000
"""The most names and quoted units a ``.frame`` file may hold (the shipped library has about 10,000): parsing grows
with them, and a category of 1,100,000 members on one line of 10 MB ran past a minute (hostile26); a file holding
more is refused at the first word past the bound, before it is parsed."""

_WORD = re.compile(r'//[^\n]*|"(?:[^"\\\n]|\\.)*"|[^\W\d]\w*')


def _past_bound(text: str, file: str, lines: list[str]) -> SealError | None:
    """The refusal of a file of more than :data:`MAX_WORDS` words (comments not counted), at the first past it."""
    count = 0
    for found in _WORD.finditer(text):
        if found.group().startswith("//"):
            continue
        count += 1
        if count > MAX_WORDS:
            line = text.count("\n", 0, found.start()) + 1
            column = found.start() - (text.rfind("\n", 0, found.start()) + 1) + 1
            return SealError(f"this frame file holds more than {MAX_WORDS:,} names and units; seal reads at most "
                             "that many (split it into several files)", Where(file, line, column),
                             source_line=lines[line - 1])
    return None


_STATEMENT = re.compile(r"[ \t]*(frame|category|world|synonyms)[ \t]+[^:=\s]")


def _statements(text: str) -> Iterator[tuple[int, str]]:
    """(lines before it, text) of each top-level statement: a chunk starts at a line that opens
    with a statement's keyword."""
    lines = text.split("\n")
    starts = [i for i, line in enumerate(lines) if _STATEMENT.match(line)]
    if not starts or starts[0] != 0:
        starts.insert(0, 0)
    for start, end in zip(starts, [*starts[1:], len(lines)], strict=True):
        chunk = "\n".join(lines[start:end])
        if chunk.strip():
            yield start, chunk


def _shift(tree: Tree, lines: int) -> None:
    """Move a chunk's positions down by the lines before it."""
    for node in tree.iter_subtrees():
        meta = node.meta
        if not meta.empty:
            meta.line += lines
            meta.end_line += lines
        for child in node.children:
            if isinstance(child, Token) and child.line is not None:
                child.line += lines
                if child.end_line is not None:
                    child.end_line += lines


def _shifted(problem: SealError, lines: int, source: list[str]) -> SealError:
    where = problem.where
    line = (where.line or 1) + lines
    return SealError(problem.message, Where(where.file, line, where.column),
                     source_line=source[line - 1] if line <= len(source) else None)


# -- writing --------------------------------------------------------------------------------
def _quote(text: str) -> str:
    return json.dumps(text, ensure_ascii=False)


def dump_frame(frame: Frame) -> str:
    head = " ".join(["frame", frame.name, *(_quote(u.text) for u in frame.lexical_units)])
    lines = [head + " {"]
    if frame.description:
        lines.append(f"  description {_quote(frame.description)}")
    if frame.framenet:
        lines.append(f"  framenet {frame.framenet}")
    for e in frame.elements:
        lines.append(f"  {e.role}: {e.type}" + (f" = {e.default}" if e.default is not None else ""))
    for keyword, items in (("requires", frame.preconditions), ("do", frame.actions),
                           ("ensures", frame.postconditions)):
        if items:
            lines.append(f"  {keyword} " + ", ".join(str(i) for i in items))
    return "\n".join(lines) + "\n}\n"


def dump(frames: tuple[Frame, ...] | list[Frame], taxonomy: Taxonomy | None = None) -> str:
    """Frames (and categories) as ``.frame`` text."""
    parts = [dump_frame(f) for f in frames]
    if taxonomy:
        for c in taxonomy.categories:
            parts.append(f"category {c.name} = {'*' if c.members is None else ', '.join(c.members)}\n")
        if taxonomy.world:
            parts.append(f"world {', '.join(taxonomy.world)}\n")
        for entry in taxonomy.synonyms:
            parts.append(f"synonyms {entry.name} = {', '.join(entry.names)}\n")
    return "\n".join(parts)
