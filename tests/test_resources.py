"""resources: the shipped grammars, frame library and maps, from a checkout or a wheel."""

from __future__ import annotations

from pathlib import Path

import pytest

from seal_cli import resources
from seal_cli.errors import SealError


def test_the_shipped_folders_are_found() -> None:
    assert (resources.grammar_path("command.lark")).is_file()
    assert any(resources.framelib_dir().glob("*.yaml")) and (resources.maps_dir() / "apartment.yaml").is_file()


def test_a_map_by_path_or_by_a_shipped_name(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.chdir(tmp_path)
    shipped = resources.maps_dir() / "apartment.yaml"
    assert resources.map_path("apartment") == shipped == resources.map_path("apartment.yaml")
    (tmp_path / "apartment.yaml").write_text("")
    assert resources.map_path("apartment.yaml") == Path("apartment.yaml")      # a file of that name first
    assert resources.map_path("sub/nowhere") == Path("sub/nowhere")            # a path: left for the reader
    assert resources.map_path("../maps/apartment") == Path("../maps/apartment")  # never a shipped map's folder


@pytest.mark.parametrize(("name", "message"), [("apartmnt", "did you mean 'apartment'.*shipped maps: apartment"),
                                               ("APARTMENT", "did you mean 'apartment'"),
                                               ("zzzz", r"nor a map shipped with seal; shipped maps: apartment"),
                                               ("", "the map's name is empty"), ("  ", "the map's name is empty")])
def test_a_name_that_is_no_file_and_no_shipped_map_lists_them(name: str, message: str, tmp_path: Path,
                                                              monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.chdir(tmp_path)
    with pytest.raises(SealError, match=message):
        resources.map_path(name)


def test_a_missing_installation_folder_is_one_clear_error(monkeypatch: pytest.MonkeyPatch, tmp_path: Path) -> None:
    monkeypatch.setattr(resources, "_PACKAGE", tmp_path / "seal_cli")
    with pytest.raises(SealError, match="the shipped folder 'maps' is missing from this installation"):
        resources.maps_dir()


def test_a_map_named_dash_says_standard_input_is_read_only_by_parse() -> None:
    # "seal map -" said "no such map file, nor a map shipped with seal" and listed the maps (hostile22)
    from seal_cli.resources import map_path

    with pytest.raises(SealError, match=r"^-: no such map file \('-' is standard input only to seal parse --file"):
        map_path("-")


def test_a_frame_file_named_dash_says_standard_input_is_read_only_by_parse() -> None:
    from seal_cli.frames.reading import frame_files

    files, (problem,) = frame_files(["-"])
    assert files == [] and problem.message.startswith("no such file or folder: - ('-' is standard input only")
    _, (other,) = frame_files(["./nothing-here"])
    assert "standard input" not in other.message
