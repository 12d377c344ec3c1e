"""bench/corpora: a parsing corpus checked as the shared scorers read it, and its plain copy."""

from __future__ import annotations

import csv
import json
from pathlib import Path

import pytest

from seal_cli.bench.corpora import ALFRED_COLUMNS, read_corpus, write_plain
from seal_cli.errors import SealError


def test_a_corpus_read_and_written_plain_holds_the_same_commands(tmp_path: Path) -> None:
    lines = [{"text": "go to the kitchen", "expect": [{"frame": "Go", "elements": {"goal": "kitchen"}}]},
             {"text": "find the café", "command_types": ["findObj"],
              "fills": [{"placeholder": "findVerb", "value": "find", "verb_class": "find"},
                        {"placeholder": "obj", "value": "café"}]}]
    path = tmp_path / "c.jsonl"
    # a BOM, CRLF, a blank line and a carriage return between two fields: the scorer's open() ends a line there
    path.write_bytes(("\ufeff" + json.dumps(lines[0]).replace(", ", ",\r ", 1) + "\r\n\r\n" + json.dumps(lines[1])
                      + "\n").encode())
    corpus = read_corpus(path)
    assert corpus.items == tuple(lines) and corpus.expects and not corpus.table
    (tmp_path / "work").mkdir()
    plain = write_plain(corpus, tmp_path / "work")
    raw = plain.read_bytes()
    assert raw.isascii() and b"\r" not in raw
    assert [json.loads(line) for line in open(plain, encoding="utf-8")] == lines  # noqa: SIM115 - as the scorer reads


def test_an_alfred_table_is_copied_with_the_columns_the_scorer_reads(tmp_path: Path) -> None:
    path = tmp_path / "g.tsv"
    header = "split\t" + "\t".join(ALFRED_COLUMNS) + "\textra\n"
    path.write_text(header + 'valid\tpick_and_place_simple\tApple\tFridge\t\t0\tput "an" apple in the fridge\tx\n',
                    encoding="utf-8")
    corpus = read_corpus(path)
    assert corpus.table and corpus.rows[0]["goal_sentence"] == 'put "an" apple in the fridge'
    (tmp_path / "work").mkdir()
    plain = write_plain(corpus, tmp_path / "work")
    rows = list(csv.DictReader(open(plain), delimiter="\t"))  # noqa: SIM115 - as the scorer reads
    assert rows == [dict(corpus.rows[0])]


@pytest.mark.parametrize(("line", "where", "said"), [
    ('{"text": "go", "expect": [{"frame": "Go", "elements": []}]}', (1, 43), "'elements' is an empty list"),
    ('{"text": "go", "command_types": ["goToLoc", 3], "fills": []}', (1, 16), "not a non-empty list"),
    ('{"text": "go", "command_types": ["goToLoc"], "fills": [7]}', (1, 46), "fill 1 is the number 7"),
    ('{"text": "go", "command_types": ["goToLoc"], "fills": [{"value": "x"}]}', (1, 46), "no 'placeholder'"),
    ('"go to the kitchen"', (1, 1), "this line is a string, not a JSON object"),
])
def test_what_the_scorer_would_miss_is_said_at_its_line(tmp_path: Path, line: str, where: tuple[int, int],
                                                        said: str) -> None:
    path = tmp_path / "c.jsonl"
    path.write_text('{"text": "go", "expect": []}\n' + line + "\n", encoding="utf-8")
    with pytest.raises(SealError, match=said) as caught:
        read_corpus(path)
    assert (caught.value.where.line, caught.value.where.column) == (where[0] + 1, where[1])


def test_a_verb_fill_needs_no_value(tmp_path: Path) -> None:
    path = tmp_path / "c.jsonl"
    path.write_text('{"text": "go", "command_types": ["goToLoc"], "fills": [{"verb_class": "go"}]}\n')
    assert len(read_corpus(path).items) == 1


@pytest.mark.parametrize(("line", "column", "says"), [
    ('{"text": "go", "expect": [{"frame": "Go", "elements": {"goal": ' + "9" * 5000 + "}}]}", 64,
     "an integer of 5,000 digits"),
    ('{"text": "go", "expect": ' + "[" * 100_000 + "]" * 100_000 + "}", 26 + 498, "nested too deeply"),
])
def test_a_corpus_line_python_cannot_read_is_refused_at_its_column(tmp_path: Path, line: str, column: int,
                                                                   says: str) -> None:
    """5,000 digits were a ValueError's traceback; nesting was refused at the line alone (hostile29)."""
    path = tmp_path / "c.jsonl"
    path.write_text(line + "\n", encoding="utf-8")
    with pytest.raises(SealError) as caught:
        read_corpus(path)
    assert (caught.value.where.line, caught.value.where.column) == (1, column)
    assert says in caught.value.message
