"""frames.reading: files and folders of frame files → a Library, every problem collected or raised."""

from __future__ import annotations

from pathlib import Path

import pytest

from seal_cli.errors import SealError, SealErrors
from seal_cli.frames.formats import dsl, yamlfile
from seal_cli.frames.library import Library
from seal_cli.frames.reading import (
    FRAME_SUFFIXES,
    READERS,
    frame_files,
    load_library,
    read_files,
    read_library,
    standard_library,
)
from seal_cli.resources import framelib_dir

STIR_YAML = """\
frame: Stir
lexical_units: [stir]
elements:
  theme: {type: container}
  instrument: {type: utensil, default: spoon}
preconditions: [holding(instrument)]
actions: [navigate(theme), stir(instrument, theme)]
postconditions: [stirred(theme)]
"""

WAVE_DSL = """\
frame Wave "wave" {
  theme: person
  do navigate(theme), greet(theme)
  ensures greeted(theme)
}
"""


def test_readers_by_suffix_are_the_two_formats() -> None:
    assert {".yaml": yamlfile.read, ".yml": yamlfile.read, ".frame": dsl.read} == READERS
    assert FRAME_SUFFIXES == (".yaml", ".yml", ".frame")


def test_frame_files_sorts_each_folder_and_keeps_the_order_of_the_arguments(tmp_path: Path) -> None:
    (tmp_path / "b.yaml").write_text("")
    (tmp_path / "sub").mkdir()
    (tmp_path / "sub" / "a.frame").write_text("")
    (tmp_path / "notes.txt").write_text("")
    single = tmp_path / "single.yml"
    single.write_text("")
    files, problems = frame_files([single, tmp_path])
    assert problems == []
    assert files == [single, tmp_path / "b.yaml", tmp_path / "sub" / "a.frame"]   # the folder's, sorted; single once


def test_frame_files_names_what_is_missing_or_empty(tmp_path: Path) -> None:
    (tmp_path / "empty").mkdir()
    files, problems = frame_files([tmp_path / "nope.yaml", tmp_path / "empty"])
    assert files == []
    assert [p.message for p in problems] == [f"no such file or folder: {tmp_path / 'nope.yaml'}",
                                             f"no frame files (*.yaml, *.frame) in folder {tmp_path / 'empty'}"]
    assert problems[0].file == str(tmp_path / "nope.yaml")


def test_a_device_or_a_pipe_given_as_a_frame_file_is_refused_by_its_kind_not_called_missing(tmp_path: Path) -> None:
    import os

    os.mkfifo(tmp_path / "pipe")
    files, problems = frame_files(["/dev/null", tmp_path / "pipe"])
    assert problems == [] and files == [Path("/dev/null"), tmp_path / "pipe"]   # it said "no such file or folder"
    contents = read_files(files)
    assert [p.message for p in contents.problems] == [
        "cannot read this file: it is a character device, not a regular file",
        "cannot read this file: it is a FIFO (named pipe), not a regular file"]


def test_read_files_reads_both_formats_and_collects_unreadable_files(tmp_path: Path) -> None:
    (tmp_path / "stir.yaml").write_text(STIR_YAML)
    (tmp_path / "wave.frame").write_text(WAVE_DSL)
    (tmp_path / "bad.yaml").write_bytes(b"\xff\xfe not utf-8")
    contents = read_files([tmp_path / "stir.yaml", tmp_path / "wave.frame", tmp_path / "bad.yaml"])
    assert [f.name for f in contents.frames] == ["Stir", "Wave"]
    (problem,) = contents.problems
    assert problem.file == str(tmp_path / "bad.yaml") and "not UTF-8" in problem.message


def test_read_library_keeps_the_first_of_two_frames_of_one_name_and_reports_the_second(tmp_path: Path) -> None:
    (tmp_path / "a.yaml").write_text(STIR_YAML)
    (tmp_path / "b.yaml").write_text(STIR_YAML.replace("[stir]", "[mix]"))
    library, problems = read_library([framelib_dir(), tmp_path])
    stir = library.frame("Stir")
    assert [u.text for u in stir.lexical_units] == [u.text for u in standard_library().frame("Stir").lexical_units]
    assert any("duplicate frame name 'Stir'" in p.message for p in problems)


def test_load_library_raises_every_problem(tmp_path: Path) -> None:
    (tmp_path / "a.yaml").write_text("frame: stir\n")
    with pytest.raises(SealError) as caught:
        load_library([tmp_path, tmp_path / "missing"])
    assert isinstance(caught.value, SealErrors) and len(caught.value.problems) >= 2
    assert {p.file for p in caught.value.problems} >= {str(tmp_path / "a.yaml"), str(tmp_path / "missing")}


def test_the_standard_library_is_read_once_and_is_the_default() -> None:
    assert standard_library() is standard_library()
    assert isinstance(standard_library(), Library)
    assert load_library() == standard_library() == load_library([framelib_dir()])
    assert {"Pick", "Place", "Stir", "Bring"} <= set(standard_library().by_name)


# -- the cross-process cache of read libraries ---------------------------------------------------
@pytest.fixture
def own_cache(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> Path:
    folder = tmp_path / "cache"
    monkeypatch.setenv("SEAL_CACHE_DIR", str(folder))
    monkeypatch.delenv("SEAL_NO_CACHE", raising=False)
    return folder


def _reads(monkeypatch: pytest.MonkeyPatch) -> list[int]:
    """Count the times the files are really read (not served from the cache)."""
    import seal_cli.frames.reading as reading

    counted: list[int] = []
    real = reading._read

    def counting(*args: object) -> object:
        counted.append(1)
        return real(*args)  # type: ignore[arg-type]

    monkeypatch.setattr(reading, "_read", counting)
    return counted


def test_a_library_is_read_once_and_then_served_from_the_cache(own_cache: Path, monkeypatch: pytest.MonkeyPatch,
                                                               tmp_path: Path) -> None:
    reads = _reads(monkeypatch)
    first = load_library()
    assert len(reads) == 1 and [p.name for p in own_cache.glob("library-*.pickle")]
    again = load_library()
    assert len(reads) == 1
    assert again == first == read_library([framelib_dir()])[0]
    assert [u.where for f in again for u in f.lexical_units] == [u.where for f in first for u in f.lexical_units]


WHISK_YAML = STIR_YAML.replace("Stir", "Whisk").replace("[stir]", "[whisk]") \
    .replace("stirred", "whisked")
"""A frame the standard library lacks, typed in its categories."""


def test_a_changed_frame_file_is_read_again(own_cache: Path, monkeypatch: pytest.MonkeyPatch, tmp_path: Path) -> None:
    folder = tmp_path / "lib"
    folder.mkdir()
    (folder / "whisk.yaml").write_text(WHISK_YAML)
    reads = _reads(monkeypatch)
    assert load_library([framelib_dir(), folder]).frame("Whisk").lexical_units[0].text == "whisk"
    # the same size and, on a coarse clock, the same modification time: only the contents tell
    (folder / "whisk.yaml").write_text(WHISK_YAML.replace("[whisk]", "[froth]"))
    assert load_library([framelib_dir(), folder]).frame("Whisk").lexical_units[0].text == "froth"
    assert len(reads) == 2
    assert load_library([framelib_dir(), folder]).frame("Whisk").lexical_units[0].text == "froth"
    assert len(reads) == 2


def test_a_file_added_to_or_removed_from_a_folder_is_seen(own_cache: Path, tmp_path: Path) -> None:
    folder = tmp_path / "lib"
    folder.mkdir()
    (folder / "whisk.yaml").write_text(WHISK_YAML)
    standard = len(load_library())
    assert len(load_library([framelib_dir(), folder])) == standard + 1
    (folder / "wave.frame").write_text(WAVE_DSL.replace("greet(theme)", "navigate(theme)")
                                       .replace("greeted(theme)", "waved(theme)"))
    assert {"Whisk", "Wave"} <= set(load_library([framelib_dir(), folder]).by_name)
    (folder / "whisk.yaml").unlink()
    assert "Whisk" not in load_library([framelib_dir(), folder])


def test_framelib_libraries_are_cached_apart_and_name_their_files_as_given(own_cache: Path, tmp_path: Path,
                                                                         monkeypatch: pytest.MonkeyPatch) -> None:
    (tmp_path / "a").mkdir()
    (tmp_path / "b").mkdir()
    (tmp_path / "a" / "lib.yaml").write_text(WHISK_YAML)
    (tmp_path / "b" / "lib.yaml").write_text(WHISK_YAML.replace("[whisk]", "[froth]"))
    standard = framelib_dir()
    monkeypatch.chdir(tmp_path / "a")
    assert load_library([standard, "lib.yaml"]).frame("Whisk").lexical_units[0].text == "whisk"
    monkeypatch.chdir(tmp_path / "b")
    assert load_library([standard, "lib.yaml"]).frame("Whisk").lexical_units[0].text == "froth"  # another file
    monkeypatch.chdir(tmp_path)
    whisk = load_library([standard, "a"]).frame("Whisk")
    assert whisk.lexical_units[0].where.file == str(Path("a") / "lib.yaml")  # named as in this run
    assert load_library([standard, tmp_path / "a"]).frame("Whisk").lexical_units[0].where.file == \
        str(tmp_path / "a" / "lib.yaml")
    assert len(list(own_cache.glob("library-*.pickle"))) == 4


def test_a_corrupt_cached_library_is_ignored_and_made_again(own_cache: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    first = load_library()
    (entry,) = own_cache.glob("library-*.pickle")
    header, _, payload = entry.read_bytes().partition(b"\n")
    entry.write_bytes(header + b"\n" + bytes(len(payload)))  # whole, of the right length, but not a pickle
    reads = _reads(monkeypatch)
    assert load_library() == first
    assert len(reads) == 1
    assert load_library() == first
    assert len(reads) == 1  # made again, and whole


def test_a_library_with_problems_is_not_cached(own_cache: Path, tmp_path: Path) -> None:
    (tmp_path / "bad.yaml").write_text("frame: Stir\nlexical_units: [stir]\nelements: {theme: {type: nope}}\n")
    for _ in range(2):
        with pytest.raises((SealError, SealErrors)):
            load_library([tmp_path / "bad.yaml"])
    assert not list(own_cache.glob("library-*"))


def test_a_read_only_or_missing_cache_changes_nothing(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    blocked = tmp_path / "a file"
    blocked.write_text("")
    monkeypatch.setenv("SEAL_CACHE_DIR", str(blocked / "seal"))
    assert load_library() == read_library([framelib_dir()])[0]
    monkeypatch.setenv("SEAL_NO_CACHE", "1")
    assert load_library() == read_library([framelib_dir()])[0]


def test_a_folder_walk_passes_over_what_vanishes_and_does_not_follow_folder_links(tmp_path: Path) -> None:
    from seal_cli.frames.reading import frame_files

    (tmp_path / "lib" / "sub").mkdir(parents=True)
    (tmp_path / "other").mkdir()
    (tmp_path / "lib" / "sub" / "b.frame").write_text("")
    (tmp_path / "lib" / "a.yaml").write_text("")
    (tmp_path / "other" / "c.frame").write_text("")
    (tmp_path / "lib" / "linked").symlink_to(tmp_path / "other")   # a link to a folder: not walked
    (tmp_path / "lib" / "loop").symlink_to(".")
    (tmp_path / "lib" / "gone.frame").symlink_to(tmp_path / "nowhere.frame")  # dangling: kept, for reading to refuse
    files, problems = frame_files([tmp_path / "lib"])
    assert [p.relative_to(tmp_path).as_posix() for p in files] == ["lib/a.yaml", "lib/gone.frame", "lib/sub/b.frame"]
    assert not problems
    files, problems = frame_files(["/proc"])  # processes end while it is walked: never "No such file"
    assert files == [] and [p.message for p in problems] == ["no frame files (*.yaml, *.frame) in folder /proc"]


def test_a_file_named_twice_is_read_once(tmp_path: Path) -> None:
    # the standard library given twice was 526 problems: every frame and category "defined twice" (hostile16)
    (tmp_path / "link.yaml").symlink_to(framelib_dir() / "kitchen.yaml")
    (tmp_path / "hard.yaml").hardlink_to(tmp_path / "link.yaml")
    given = [framelib_dir(), framelib_dir(), framelib_dir() / "kitchen.yaml", tmp_path / "link.yaml",
             tmp_path / "hard.yaml"]
    files, problems = frame_files(given)
    assert problems == [] and files == frame_files([framelib_dir()])[0]
    library, problems = read_library(given)
    assert problems == [] and len(library) == len(read_library([framelib_dir()])[0])


@pytest.mark.parametrize(("text", "says"), [("", r"this file holds nothing: no frame, category"),
                                           ("frames: []\n", r"this file holds nothing"),
                                           ("categories:\n  utensil: [spoon]\n",
                                            r"this frame library holds no frames \(1 file read\)")])
def test_a_library_of_no_frames_is_refused(tmp_path: Path, text: str, says: str) -> None:
    """hostile19: `plan --framelib empty.yaml` said "unknown verb 'stir'; known verbs include " and nothing more;
    hostile30: a file of nothing is said so of itself, also beside others (``--framelib +empty.frame``)."""
    from seal_cli.frames.reading import load_library

    (tmp_path / "f.yaml").write_text(text)
    with pytest.raises(SealError, match=says) as caught:
        load_library([tmp_path / "f.yaml"])
    assert caught.value.file == str(tmp_path / "f.yaml")


@pytest.mark.parametrize(("name", "text"), [("e.frame", ""), ("c.frame", "// only a comment\r\n"),
                                            ("b.yaml", "\ufeff# a comment\n")])
def test_a_frame_file_of_nothing_is_a_problem_of_its_own(tmp_path: Path, name: str, text: str) -> None:
    """``seal validate`` said "ok: 0 frames" of an empty file, and ``--framelib +empty.frame`` passed it over."""
    (tmp_path / name).write_text(text, encoding="utf-8")
    _, problems = read_library([framelib_dir(), tmp_path / name])
    assert [(p.file, p.message.split(":")[0]) for p in problems] == [(str(tmp_path / name),
                                                                      "this file holds nothing")]
