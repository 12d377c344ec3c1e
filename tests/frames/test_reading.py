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
    assert files == [single, tmp_path / "b.yaml", single, tmp_path / "sub" / "a.frame"]   # the folder's, sorted


def test_frame_files_names_what_is_missing_or_empty(tmp_path: Path) -> None:
    (tmp_path / "empty").mkdir()
    files, problems = frame_files([tmp_path / "nope.yaml", tmp_path / "empty"])
    assert files == []
    assert [p.message for p in problems] == [f"no such file or folder: {tmp_path / 'nope.yaml'}",
                                             f"no frame files (*.yaml, *.frame) in folder {tmp_path / 'empty'}"]
    assert problems[0].file == str(tmp_path / "nope.yaml")


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
