"""language.morphology: lemmas, plurals and forms from lemminflect's tables, looked up by bisection."""

from __future__ import annotations

from pathlib import Path

import pytest

from seal_cli.language.morphology import (
    _Table,
    gerund_lemma,
    is_adjective,
    is_adverb,
    is_gradable,
    is_plural,
    noun_lemma,
    participles,
    plural_only,
    verb_lemma,
)


def test_singulars_of_regular_and_irregular_nouns() -> None:
    assert [noun_lemma(w) for w in ("apples", "knives", "people", "Glasses", "cheezits")] == \
        ["apple", "knife", "person", "glass", "cheezits"]        # a word the tables lack stays as written
    assert is_plural("apples") and is_plural("people") and not is_plural("apple")


def test_verbs_and_their_forms() -> None:
    assert verb_lemma("heated") == "heat" and verb_lemma("took") == "take" and verb_lemma("xyzzy") is None
    assert gerund_lemma("wearing") == "wear" and gerund_lemma("morning") != "morn"
    assert participles("light") >= {"lit", "lighted"} and participles("cut") == frozenset({"cut"})


def test_adjectives_adverbs_and_gradable_words() -> None:
    assert is_adjective("hot") and is_adjective("clean") and not is_adjective("fridge")
    assert is_adverb("together") and not is_adverb("hot")
    assert is_gradable("warm") and not is_gradable("wooden")


def test_tables_looked_up_in_the_cache_find_what_the_sorted_lines_do(tmp_path: Path,
                                                                    monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setenv("SEAL_CACHE_DIR", str(tmp_path))
    monkeypatch.delenv("SEAL_NO_CACHE", raising=False)
    for name in ("lemma_lu.csv.gz", "infl_lu.csv.gz"):
        cached, memory = _Table(name), _Table(name)
        lines = memory.lines
        words = [line.split(",")[0] for line in lines[::97]] + ["", "a", "zzzz", "knive", "café", "\uffff", "a\nb"]
        assert [cached.entries(w) for w in words] == [memory._entries_in_memory(w) for w in words]
        assert cached._mapped is not None and cached._lines is None   # looked up in the entry, not in memory
        assert any(cached.entries(w) for w in words)


def test_a_corrupt_or_unwritable_table_cache_falls_back_to_the_sorted_lines(tmp_path: Path,
                                                                           monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setenv("SEAL_CACHE_DIR", str(tmp_path))
    monkeypatch.delenv("SEAL_NO_CACHE", raising=False)
    _Table("lemma_lu.csv.gz").entries("knives")
    (entry,) = tmp_path.glob("words-lemma_lu-*.txt")
    entry.write_bytes(entry.read_bytes()[:-10])            # cut short
    table = _Table("lemma_lu.csv.gz")
    assert table.entries("knives") == [["noun", "knife"]]   # made again
    assert table._mapped is not None
    blocked = tmp_path / "a file"
    blocked.write_text("")
    monkeypatch.setenv("SEAL_CACHE_DIR", str(blocked))
    table = _Table("lemma_lu.csv.gz")
    assert table.entries("knives") == [["noun", "knife"]] and table._mapped is None


@pytest.mark.parametrize(("word", "only"), [
    ("scissors", True), ("jeans", True), ("pliers", True), ("tweezers", True),
    ("glass", False), ("cup", False), ("bus", False), ("cups", False), ("sheep", False), ("knife", False),
])
def test_a_noun_with_a_plural_only(word: str, only: bool) -> None:
    assert plural_only(word) is only


@pytest.mark.parametrize(("noun", "plural"), [
    ("box", "boxes"), ("shelf", "shelves"), ("cup", "cups"), ("ice cream", "ice creams"), ("glass", "glasses"),
    ("scissors", "scissors"), ("dish", "dishes"),
])
def test_the_plural_of_a_noun(noun: str, plural: str) -> None:
    from seal_cli.language.morphology import plural_of

    assert plural_of(noun) == plural


def test_a_number_and_its_noun() -> None:
    from seal_cli.language.morphology import counted

    assert [counted(1, "box"), counted(2, "box"), counted(0, "ice cream")] == ["1 box", "2 boxes", "0 ice creams"]
