"""Frame libraries written in the ``.frame`` DSL (``grammars/frames.lark``).

The DSL states exactly the YAML model; a file in one form and its translation into the other
load to equal frames. Reading never raises: problems are collected with their position.
"""

from __future__ import annotations

import json
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
_TERMINALS = {"NAME": "a name", "STRING": 'a "quoted" lexical unit', "LBRACE": "'{'", "RBRACE": "'}'",
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


def _syntax_problem(exc: UnexpectedInput, text: str, file: str) -> SealError:
    lines = text.splitlines()
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
    return SealError(f"syntax error: {message}", Where(file, line, column), source_line=source)


class _Builder:
    """Walks the parse tree into model objects, recording problems."""

    def __init__(self, text: str, file: str) -> None:
        self.file = file
        self.lines = text.splitlines()
        self.contents = Contents()

    def where(self, item: Tree | Token) -> Where:
        if isinstance(item, Token):
            return Where(self.file, item.line, item.column)
        return Where(self.file, item.meta.line, item.meta.column)

    def problem(self, exc: SealError, at: Tree | Token) -> None:
        for problem in getattr(exc, "problems", None) or [exc]:
            where = problem.where if problem.where.line else self.where(at)
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
        frame = Frame(str(name), where=self.where(name), **frozen)
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
    return str(json.loads(str(token)))


def read(text: str, file: str = "<frame>") -> Contents:
    """The frames, categories and problems in a ``.frame`` file's text."""
    builder = _Builder(text, file)
    try:
        tree = parser().parse(text)
    except UnexpectedInput as exc:
        builder.contents.problems.append(_syntax_problem(exc, text, file))
        return builder.contents
    builder.build(tree)
    return builder.contents


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
