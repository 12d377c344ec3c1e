"""validate: frame files and maps checked together; a YAML file is a map by its keys."""

from __future__ import annotations

from pathlib import Path

from seal_cli.maps.formats.map_server import KEYS
from seal_cli.resources import framelib_dir, maps_dir
from seal_cli.validate import FRAME_FILE_KEYS, Report, is_map_file, validate_paths


def test_a_map_is_told_from_frames_by_its_top_level_keys(tmp_path: Path) -> None:
    cases = {"map.yaml": "bounds: [0, 0, 4, 3]\nrooms: []\n", "frames.yaml": "frames: []\ncategories: {}\n",
             "both.yaml": "frame: Stir\nrooms: []\n", "named.yaml": "name: kitchen\n", "list.yaml": "- 1\n",
             "broken.yaml": "rooms: [\n", "map.frame": "bounds: [0, 0, 4, 3]\n"}
    for name, text in cases.items():
        (tmp_path / name).write_text(text)
    assert {n for n in cases if is_map_file(tmp_path / n)} == {"map.yaml"}
    assert is_map_file(maps_dir() / "apartment.yaml") and not is_map_file(framelib_dir() / "kitchen.yaml")
    assert not FRAME_FILE_KEYS & set(KEYS)          # the map's keys are map_server's, listed there once


def test_a_good_library_and_map_report_what_they_hold() -> None:
    report = validate_paths([framelib_dir(), maps_dir() / "apartment.yaml"])
    assert report.problems == [] and report.maps == 1 and report.frames > 20 and report.categories > 5
    assert report.summary().startswith(f"ok: {report.frames} frames, {report.categories} categories, 1 map in ")
    data = report.to_json()
    assert data["ok"] is True and data["maps"] == 1 and str(maps_dir() / "apartment.yaml") in data["files"]


def test_problems_of_frames_and_maps_come_sorted_by_file_and_line(tmp_path: Path) -> None:
    (tmp_path / "a_map.yaml").write_text("bounds: [0, 0, 4, 3]\nsensor: {range: -1}\n")
    (tmp_path / "b_frames.yaml").write_text("frame: stir\n")
    report = validate_paths([tmp_path])
    assert report.maps == 1 and len(report.problems) >= 2
    files = [p.file for p in report.problems]
    assert files == sorted(files) and files[0] == str(tmp_path / "a_map.yaml")
    assert report.summary().startswith(f"{len(report.problems)} problems in ")
    assert report.to_json()["ok"] is False


def test_with_the_standard_library_only_the_given_frames_are_counted(tmp_path: Path) -> None:
    (tmp_path / "wave.yaml").write_text("frame: Wave\nlexical_units: [wave]\nelements:\n  theme: {type: person}\n"
                                        "actions: [navigate(theme), greet(theme)]\npostconditions: [greeted(theme)]\n")
    report = validate_paths([tmp_path / "wave.yaml"], with_stdlib=True)
    assert report.problems == [] and report.frames == 1


def test_an_empty_report_says_so() -> None:
    assert Report().summary() == "ok: 0 frames, 0 categories, 0 maps in 0 files"


def test_a_map_is_a_map_whatever_its_name_says(tmp_path: Path) -> None:
    # 'seal validate my_map' listed every key of a good map as "unknown key in a frame file" (hostile16)
    text = (maps_dir() / "apartment.yaml").read_text(encoding="utf-8")
    (tmp_path / "apartment.pgm").write_bytes((maps_dir() / "apartment.pgm").read_bytes())
    for name in ("my_map", "map.txt"):
        (tmp_path / name).write_text(text, encoding="utf-8")
        assert is_map_file(tmp_path / name)
        report = validate_paths([tmp_path / name])
        assert report.problems == [] and report.maps == 1
    (tmp_path / "m.frame").write_text(text, encoding="utf-8")
    assert not is_map_file(tmp_path / "m.frame")   # the DSL's suffix: a frame file, whatever it holds


def test_the_top_level_keys_are_read_without_composing_the_file() -> None:
    from seal_cli.validate import top_level_keys

    text = "name: m\nbounds: [0, 0, 1, 1]\nrooms:\n  - {name: a, box: [0, 0, 1, 1]}\npriors: {cup: {a: 1}}\n"
    text += "? [k]\n: 3\n"
    assert top_level_keys(text) == {"name", "bounds", "rooms", "priors"}
    assert top_level_keys("- a\n") is None and top_level_keys("a\n") is None and top_level_keys("") == set()
    assert top_level_keys("frames: []\nx: {frame: 1}\n---\nrooms: []\n") == {"frames", "x"}   # the first document


def test_a_lexical_unit_that_is_a_function_word_is_a_problem_at_its_line(tmp_path: Path) -> None:
    """The frame readers took "the" as a unit, and "the cup" then parsed as its frame (hostile32)."""
    (tmp_path / "z.frame").write_text('category object = cup\nframe Zap "zap" "of" {\n  theme: object\n'
                                      "  do navigate(theme)\n}\n")
    report = validate_paths([tmp_path / "z.frame"])
    assert [(p.line, p.column) for p in report.problems] == [(2, 17)]
    assert "lexical unit 'of' of Zap is a preposition" in report.problems[0].message
