"""Errors are part of seal's interface.

Every failure a user can cause (a broken frame file, an unparsable command, an impossible
plan, a bad map) is a :class:`SealError` carrying where it happened: a file, a line and a
column (1-based), and optionally the source line so that a caret can be drawn under the
column. The CLI prints ``str(error)`` and exits with code 1; it never shows a traceback.

A check that finds several problems at once (``seal validate``) raises or returns a
:class:`SealErrors`, which holds them all in source order.
"""

from __future__ import annotations

import re
from collections.abc import Iterable, Sequence
from dataclasses import dataclass

__all__ = ["CONTROL", "SealError", "SealErrors", "Where", "at_line", "at_words", "caret", "escaped", "readable"]


@dataclass(frozen=True, order=True)
class Where:
    """A position in a source: file (or None for text given on the command line), line, column.

    Printed ``file:line:col`` as compilers do, or ``column N`` for a command given as text."""

    file: str | None = None
    line: int | None = None
    column: int | None = None

    def __str__(self) -> str:
        if self.file is None:  # a command given on the command line: where in it
            if self.column is None:
                return "<input>" if self.line is None else f"line {self.line}"
            return f"column {self.column}" if self.line in (None, 1) else f"line {self.line}, column {self.column}"
        parts = [self.file]
        if self.line is not None:
            parts.append(str(self.line))
            if self.column is not None:
                parts.append(str(self.column))
        return ":".join(parts)


EXCERPT = 100
"""The most characters of a source line a message shows: a longer line (a minified file, 20,000 brackets)
is cut to this many around the column, with "…" where it was cut."""


CONTROL = re.compile(r"[\x00-\x08\x0b-\x1f\x7f-\x9f]")
"""Control characters but a line break and a tab: printed as they are, a NUL, an escape sequence (``\\x1b[2J``) or a
carriage return acts on the terminal instead of being shown."""


def escaped(text: str) -> str:
    """``text`` with each control character (:data:`CONTROL`) written as its escape, ``\\x00``, ``\\x1b``."""
    return CONTROL.sub(lambda m: m[0].encode("unicode_escape").decode("ascii"), text)


def caret(source_line: str, column: int) -> str:
    """The source line (cut to :data:`EXCERPT` characters around the column, its control characters
    :func:`escaped`) with a caret under the 1-based column."""
    line = source_line.rstrip("\n")
    before = max(column - 1, 0)
    if len(line) > EXCERPT:
        start = max(0, min(before - EXCERPT // 2, len(line) - EXCERPT))
        head, tail = ("…" if start else ""), ("…" if start + EXCERPT < len(line) else "")
        line, before = head + line[start:start + EXCERPT] + tail, before - start + len(head)
    pad = "".join("\t" if ch == "\t" else " " * len(escaped(ch)) for ch in line[:before])
    return f"{escaped(line)}\n{pad}^"


WORD = 200
"""The most characters of one word (a name, a number, a path) a printed message shows: a room called with
20,000 letters, or an integer of 5,000 digits, is cut to this many, with "…"."""
MESSAGE = 3000
"""The most characters of a printed message (a list of 10,000 names is cut, with "…")."""


def readable(message: str) -> str:
    """``message`` with each word longer than :data:`WORD` characters, and the whole past :data:`MESSAGE`, cut
    with "…", its control characters :func:`escaped` (what is printed; the JSON of an error keeps the message
    whole)."""

    def cut(word: str) -> str:  # the punctuation that ends a long word stays: "xxx…: File name too long"
        end = min(len(word) - len(word.rstrip(":;,.)]}'\"")), 3)
        return word[:WORD - 1 - end] + "…" + word[len(word) - end:]

    message = re.sub(rf"\S{{{WORD + 1},}}", lambda m: cut(m.group()), escaped(message))
    return message if len(message) <= MESSAGE else message[:MESSAGE - 1] + "…"


class SealError(Exception):
    """One problem a user can fix, with where it is."""

    def __init__(self, message: str, where: Where | None = None, *, source_line: str | None = None,
                 hint: str | None = None) -> None:
        super().__init__(message)
        self.message = message
        self.where = where or Where()
        self.source_line = source_line
        self.hint = hint

    @property
    def file(self) -> str | None:
        return self.where.file

    @property
    def line(self) -> int | None:
        return self.where.line

    @property
    def column(self) -> int | None:
        return self.where.column

    def located(self) -> str:
        """``file:line:col: message`` (the part a tool or an editor reads); the message :func:`readable`."""
        if self.where == Where():
            return readable(self.message)
        return f"{escaped(str(self.where))}: {readable(self.message)}"

    def __str__(self) -> str:
        text = self.located()
        if self.source_line is not None and self.column is not None:
            text += "\n" + caret(self.source_line, self.column)
        if self.hint:
            text += f"\n{self.hint}"
        return text

    def to_json(self) -> dict[str, object]:
        return {"file": self.file, "line": self.line, "column": self.column, "message": self.message}


def at_words(message: str, span: tuple[int, int] | None, text: str) -> SealError:
    """An error about some words of a command (``span``, their characters in ``text``), with a caret under them when
    their place is known; the message alone when it is not."""
    if span is None:
        return SealError(message)
    return SealError(message, Where(None, 1, span[0] + 1), source_line=text)


def at_line(error: SealError, file: str, line: int, source_line: str) -> SealError:
    """A command's error (placed by its column alone: the command was given as text, ``source_line`` stripped)
    as one at ``line`` of the ``file`` the command was read from, with its column in the line and a caret
    under it; an error of another file (the map, the library) stays as it is."""
    if error.file is not None or isinstance(error, SealErrors):
        return error
    indent = len(source_line) - len(source_line.lstrip())
    column = error.column + indent if error.column is not None else None
    return SealError(error.message, Where(file, line, column),
                     source_line=source_line.rstrip("\r\n") if column is not None else None, hint=error.hint)


def _sort_key(error: SealError) -> tuple[str, int, int]:
    return (error.file or "", error.line or 0, error.column or 0)


class SealErrors(SealError):
    """Several problems found together, sorted by file, line and column."""

    def __init__(self, problems: Iterable[SealError]) -> None:
        self.problems: Sequence[SealError] = sorted(problems, key=_sort_key)
        count = len(self.problems)
        first = self.problems[0] if self.problems else None
        super().__init__(f"{count} problem{'s' if count != 1 else ''}",
                         first.where if first else None)

    def __str__(self) -> str:
        return "\n".join(str(p) for p in self.problems)

    def to_json(self) -> dict[str, object]:
        return {"problems": [p.to_json() for p in self.problems]}
