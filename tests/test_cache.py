"""cache: entries whole or not at all, stale and corrupt ones ignored, never required."""

from __future__ import annotations

import os
from pathlib import Path

import pytest

from seal_cli import cache


@pytest.fixture(autouse=True)
def own_cache(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> Path:
    folder = tmp_path / "cache"
    monkeypatch.setenv("SEAL_CACHE_DIR", str(folder))
    monkeypatch.delenv("SEAL_NO_CACHE", raising=False)
    return folder


def test_an_entry_reads_back_with_its_stamp_only(own_cache: Path) -> None:
    assert cache.write("thing.bin", "abc", b"payload\n\x00bytes")
    assert cache.read("thing.bin", "abc") == b"payload\n\x00bytes"
    assert cache.read("thing.bin", "abd") is None          # stale: made from something else
    assert cache.read("other.bin", "abc") is None          # none
    assert [p.name for p in own_cache.iterdir()] == ["thing.bin"]  # no temporary left beside it


def test_a_mapped_entry_starts_after_its_header() -> None:
    cache.write("table.txt", "s1", b"a,1\nb,2\n")
    mapped, start = cache.read_mapped("table.txt", "s1") or (b"", -1)
    assert mapped[start:] == b"a,1\nb,2\n"
    assert cache.read_mapped("table.txt", "s2") is None


@pytest.mark.parametrize("damage", [lambda b: b[:-1], lambda b: b + b"x", lambda b: b"", lambda b: b"garbage\n" + b,
                                    lambda b: b.replace(b"seal-cache 2", b"seal-cache 9"),
                                    lambda b: b.replace(b" 7 ", b" seven "),
                                    lambda b: b[:-3] + b"X" + b[-2:],           # a byte flipped: same length
                                    lambda b: b.replace(b"payload", b"PAYLOAD"),  # the header's digest is of payload
                                    lambda b: b.split(b" 7 ")[0] + b" 7\n" + b.split(b"\n", 1)[1]])  # no digest
def test_a_corrupt_entry_is_ignored(own_cache: Path, damage: object) -> None:
    cache.write("thing.bin", "abc", b"payload")
    entry = own_cache / "thing.bin"
    entry.write_bytes(damage(entry.read_bytes()))  # type: ignore[operator]
    assert cache.read("thing.bin", "abc") is None
    assert cache.read_mapped("thing.bin", "abc") is None


def test_a_cache_that_cannot_be_written_is_no_error(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    blocked = tmp_path / "a file"
    blocked.write_text("not a folder")
    monkeypatch.setenv("SEAL_CACHE_DIR", str(blocked / "seal"))
    assert not cache.write("thing.bin", "abc", b"payload")
    assert cache.read("thing.bin", "abc") is None
    assert blocked.read_text() == "not a folder"


def test_the_cache_can_be_turned_off(own_cache: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setenv("SEAL_NO_CACHE", "1")
    assert cache.folder() is None
    assert not cache.write("thing.bin", "abc", b"payload")
    assert not own_cache.exists()
    monkeypatch.setenv("SEAL_NO_CACHE", "0")
    assert cache.folder() == own_cache


def test_the_default_folder_follows_xdg(monkeypatch: pytest.MonkeyPatch, tmp_path: Path) -> None:
    monkeypatch.delenv("SEAL_CACHE_DIR")
    monkeypatch.setenv("XDG_CACHE_HOME", str(tmp_path))
    assert cache.folder() == tmp_path / "seal"
    monkeypatch.delenv("XDG_CACHE_HOME")
    monkeypatch.setenv("HOME", str(tmp_path / "home"))
    assert cache.folder() == tmp_path / "home" / ".cache" / "seal"


def test_digests_keep_the_parts_apart() -> None:
    assert cache.digest(b"ab", b"c") != cache.digest(b"a", b"bc")
    assert cache.digest(b"x") == cache.digest(b"x")


def test_a_corrupted_word_table_is_made_again(own_cache: Path) -> None:
    """A flipped byte in a cached word table keeps its length: the digest sees it, and the table is rebuilt."""
    from seal_cli.language.morphology import _Table

    table = _Table("lemma_lu.csv.gz")
    found = table.entries("cups")
    assert found
    entry = next(own_cache.glob("words-lemma_lu-*.txt"))
    data = bytearray(entry.read_bytes())
    at = data.index(b"\ncups,") + 1
    data[at:at + 4] = b"cupz"  # the entry of "cups" now names "cupz": the same length
    entry.write_bytes(bytes(data))
    again = _Table("lemma_lu.csv.gz")
    assert again.entries("cups") == found
    assert b"\ncups," in entry.read_bytes()  # made again


@pytest.mark.parametrize("kind", ["fifo", "zero", "folder", "large"])
def test_what_is_no_regular_file_at_an_entry_name_is_no_entry(own_cache: Path, kind: str,
                                                              monkeypatch: pytest.MonkeyPatch) -> None:
    # a FIFO at the library's entry hung `seal parse`; a link to /dev/zero read it for 100 s up to 23 GB (hostile17)
    own_cache.mkdir(parents=True, exist_ok=True)
    entry = own_cache / "e"
    if kind == "fifo":
        os.mkfifo(entry)
    elif kind == "zero":
        entry.symlink_to("/dev/zero")
    elif kind == "folder":
        entry.mkdir()
    else:
        monkeypatch.setattr(cache, "MAX_READ", 100)
        cache.write("e", "s", b"x" * 101)
    assert cache.read("e", "s") is None
    assert (cache.read_mapped("e", "s") is None) == (kind != "large")  # a large entry is mapped, never read whole
    if kind != "folder":
        assert cache.write("e", "s", b"payload") and cache.read("e", "s") == b"payload"  # made again in its place
