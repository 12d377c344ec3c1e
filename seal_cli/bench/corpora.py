"""A parsing corpus as the shared scorers read it: checked line by line, then copied plain for them.

The scorers of ``../shared/eval`` (``score_parse.py`` for JSON Lines, ``score_alfred_goals.py`` for
ALFRED goal tables) are shared with other systems and trust their corpus: a line without a field they
index was a ``KeyError`` inside the scorer, which ``seal bench parse`` could only pass on as "the scorer
failed on c.jsonl: KeyError: 'command_types'", naming no line (hostile28). :func:`read_corpus` reads a
corpus with seal's readers (its size bound, its encoding checks, lines split at ``\\n`` alone) and
refuses, at its line (and the field's column where the line shows it), every field a scorer indexes that
is missing or of the wrong type. :func:`write_plain` then writes what was read into a folder of seal's,
one plain JSON line (or TSV row) per command: that copy is what the scorer reads, so a byte-order mark,
a carriage return between two fields (the scorer's ``open`` ends a line there) or a named pipe in the
user's file never reaches it.

What a scorer needs of each JSON line (``score_parse.expected_frames`` and its main loop):

* ``text``: a string;
* either ``expect``: a list of ``{"frame": STRING, "elements": {ROLE: STRING}}`` (``elements`` optional),
* or ``command_types``: a non-empty list of strings, and ``fills``: a list of objects, each with a string
  ``value`` and ``placeholder`` unless it is a verb's (``verb_class``).

Of each row of an ALFRED goals table (``score_alfred_goals.gold``): the columns :data:`ALFRED_COLUMNS`,
every one present in the header and in the row.
"""

from __future__ import annotations

import csv
import io
import json
from dataclasses import dataclass
from pathlib import Path
from typing import Any

from seal_cli.errors import SealError, Where
from seal_cli.fileio import json_value, read_text, split_lines

__all__ = ["ALFRED_COLUMNS", "Corpus", "read_corpus", "write_plain"]

ALFRED_COLUMNS = ("task_type", "object", "receptacle", "mrecep", "sliced", "goal_sentence")
"""The columns of an ALFRED goals table the scorer reads from every row."""


@dataclass(frozen=True)
class Corpus:
    """A corpus as read: its JSON objects (``rows`` empty) or its table's rows (``items`` empty)."""

    path: Path
    items: tuple[dict[str, Any], ...] = ()
    rows: tuple[dict[str, str], ...] = ()

    @property
    def table(self) -> bool:
        return self.path.suffix == ".tsv"

    @property
    def expects(self) -> bool:
        """Whether a line says its frames itself (``expect``): the scorer scores such a line whatever
        templates it knows."""
        return any("expect" in item for item in self.items)


def read_corpus(path: Path) -> Corpus:
    """The corpus at ``path`` (a ``.tsv`` ALFRED goals table, else JSON Lines), every field the scorer
    reads checked; the first problem is a SealError at its line."""
    return _read_table(path) if path.suffix == ".tsv" else _read_lines(path)


def write_plain(corpus: Corpus, folder: Path) -> Path:
    """The corpus written into ``folder`` as the scorer reads it best: one JSON object a line, or a
    tab-separated table of :data:`ALFRED_COLUMNS`, UTF-8, ``\\n`` line ends; its path."""
    target = folder / f"corpus{len(list(folder.iterdir()))}{'.tsv' if corpus.table else '.jsonl'}"
    with target.open("w", encoding="utf-8", newline="") as handle:
        if corpus.table:
            writer = csv.writer(handle, delimiter="\t", lineterminator="\n")
            writer.writerow(ALFRED_COLUMNS)
            writer.writerows([row[column] for column in ALFRED_COLUMNS] for row in corpus.rows)
        else:
            handle.writelines(json.dumps(item, ensure_ascii=True) + "\n" for item in corpus.items)
    return target


# -- JSON Lines ---------------------------------------------------------------------------------------------------

def _read_lines(path: Path) -> Corpus:
    items = []
    for number, line in enumerate(split_lines(read_text(path)), 1):
        if not line.strip():
            continue
        try:
            item = json_value(line, path, number)
        except json.JSONDecodeError as exc:
            raise SealError(f"not JSON: {exc.msg}", Where(str(path), number, exc.colno), source_line=line) from None
        if not isinstance(item, dict):
            raise SealError(f"this line is {_kind(item)}, not a JSON object: each line of a corpus is one command, "
                            '{"text": ..., "expect": [...]} or a GPSR command with its command_types and fills',
                            Where(str(path), number, 1), source_line=line)
        _check_item(item, _Line(path, number, line))
        items.append(item)
    return Corpus(path, items=tuple(items))


@dataclass(frozen=True)
class _Line:
    """One line of a corpus, to say where a field of it is."""

    path: Path
    number: int
    text: str

    def at(self, needle: str) -> Where:
        column = self.text.find(needle)
        return Where(str(self.path), self.number, column + 1 if column >= 0 else 1)

    def problem(self, message: str, field: str | None = None) -> SealError:
        where = self.at(json.dumps(field)) if field else Where(str(self.path), self.number, 1)
        return SealError(message, where, source_line=self.text)


def _check_item(item: dict[str, Any], line: _Line) -> None:
    text = item.get("text")
    if not isinstance(text, str):
        raise line.problem("this command has no 'text' (the command, a string)" if "text" not in item else
                           f"its 'text' is {_kind(text)}, not a string (the command)", "text" if "text" in item
                           else None)
    if "command_types" in item:
        _check_gpsr(item, line)
    if "expect" in item:
        _check_expect(item["expect"], line)
    elif "command_types" not in item:
        raise line.problem("this command says nothing to score it by: give 'expect' (a list of frames, each "
                           "{\"frame\": NAME, \"elements\": {ROLE: TEXT}}), or a GPSR command's 'command_types' "
                           "and 'fills'")


def _check_expect(expect: Any, line: _Line) -> None:
    if not isinstance(expect, list):
        raise line.problem(f"its 'expect' is {_kind(expect)}, not a list of frames", "expect")
    for number, frame in enumerate(expect, 1):
        where = f"frame {number} of its 'expect'"
        if not isinstance(frame, dict):
            raise line.problem(f"{where} is {_kind(frame)}, not an object {{\"frame\": NAME, ...}}", "expect")
        if not isinstance(frame.get("frame"), str):
            raise line.problem(f"{where} has no 'frame' (the frame's name, a string)" if "frame" not in frame
                               else f"{where}'s 'frame' is {_kind(frame['frame'])}, not a string",
                               "expect" if "frame" not in frame else "frame")
        elements = frame.get("elements", {})
        if not isinstance(elements, dict):
            raise line.problem(f"{where}'s 'elements' is {_kind(elements)}, not an object {{ROLE: TEXT}}",
                               "elements")
        for role, value in elements.items():
            if not isinstance(value, str):
                raise line.problem(f"element {role!r} of {where} is {_kind(value)}, not a string (the text "
                                   "the element must hold)", role)


def _check_gpsr(item: dict[str, Any], line: _Line) -> None:
    types = item["command_types"]
    if not isinstance(types, list) or not types or not all(isinstance(t, str) for t in types):
        raise line.problem(f"its 'command_types' is {_kind(types)}, not a non-empty list of template names "
                           "(strings)", "command_types")
    if "expect" in item:
        return  # the scorer reads the frames from 'expect' then, and the types only to count per type
    if "fills" not in item:
        raise line.problem("this GPSR command has no 'fills' (the words the generator filled in, each "
                           "{\"placeholder\": ..., \"value\": ...}): the scorer reads its frames' elements from them")
    fills = item["fills"]
    if not isinstance(fills, list):
        raise line.problem(f"its 'fills' is {_kind(fills)}, not a list", "fills")
    for number, fill in enumerate(fills, 1):
        if not isinstance(fill, dict):
            raise line.problem(f"fill {number} is {_kind(fill)}, not an object {{\"placeholder\": ..., "
                               "\"value\": ...}", "fills")
        if "verb_class" in fill:
            continue  # a verb starts a clause; the scorer reads nothing else of it
        for key in ("placeholder", "value"):
            if not isinstance(fill.get(key), str):
                raise line.problem(f"fill {number} has no '{key}' (a string)" if key not in fill else
                                   f"fill {number}'s '{key}' is {_kind(fill[key])}, not a string",
                                   "fills" if key not in fill else key)


def _kind(value: Any) -> str:
    """What a JSON value is, in words."""
    if value is None:
        return "null"
    if isinstance(value, bool):
        return "a boolean"
    if isinstance(value, int | float):
        return f"the number {value}"
    if isinstance(value, str):
        return "a string"
    if isinstance(value, list):
        return "an empty list" if not value else "a list"
    return "an object"


# -- ALFRED goal tables ---------------------------------------------------------------------------------------

def _read_table(path: Path) -> Corpus:
    text = read_text(path)
    reader = csv.DictReader(io.StringIO(text, newline=""), delimiter="\t")
    try:
        header = reader.fieldnames or []
        missing = [column for column in ALFRED_COLUMNS if column not in header]
        if missing:
            first = split_lines(text)[0] if text else ""
            raise SealError(f"this ALFRED goals table has no column{'s' * (len(missing) > 1)} "
                            f"{', '.join(repr(m) for m in missing)} in its "
                            f"header (the scorer reads {', '.join(ALFRED_COLUMNS)} of every row, tab-separated)",
                            Where(str(path), 1, 1), source_line=first)
        rows = []
        for row in reader:
            absent = [column for column in ALFRED_COLUMNS if row.get(column) is None]
            if absent:
                raise SealError(f"this row has no {', '.join(repr(a) for a in absent)}: it has "
                                f"{sum(row.get(c) is not None for c in header)} of the header's {len(header)} columns "
                                "(tab-separated)",
                                Where(str(path), reader.line_num, 1))
            rows.append({column: row[column] for column in ALFRED_COLUMNS})
    except csv.Error as error:
        raise SealError(f"cannot read this table: {error}", Where(str(path), reader.line_num)) from None
    return Corpus(path, rows=tuple(rows))
