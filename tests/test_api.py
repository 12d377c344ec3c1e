"""The public API (``seal_cli/__init__.py``) and its guide, docs/api.md, whose examples are tests."""

from __future__ import annotations

import importlib
import re
import subprocess
import sys
from pathlib import Path

import pytest

import seal_cli
from seal_cli.maps.model import Map
from seal_cli.resources import maps_dir

ROOT = Path(__file__).resolve().parents[1]


def code_blocks() -> list[str]:
    return re.findall(r"```python\n(.*?)```", (ROOT / "docs" / "api.md").read_text(encoding="utf-8"), re.S)


def test_the_guide_runs_as_written(tmp_path: Path, monkeypatch: pytest.MonkeyPatch,
                                   capsys: pytest.CaptureFixture[str]) -> None:
    monkeypatch.chdir(tmp_path)  # shipped maps by name, from anywhere
    blocks = code_blocks()
    assert len(blocks) >= 3
    scope: dict = {}
    for i, code in enumerate(blocks):
        exec(compile(code, f"docs/api.md (block {i + 1})", "exec"), scope)
    node = scope["node"]
    assert node.sefm.step == 4 and len(node.beliefs.published) == 4
    printed = capsys.readouterr().out.splitlines()
    assert printed[0] == "['Pick', 'Stir']" and printed[1].split()[0] in node.sefm.map.room_names


def test_every_public_name_is_its_home_modules_object() -> None:
    assert len(set(seal_cli.__all__)) == len(seal_cli.__all__)
    for module, names in seal_cli._HOMES.items():
        home = importlib.import_module(module)
        for name in names:
            assert name in seal_cli.__all__
            assert getattr(seal_cli, name) is getattr(home, name), name
    eager = {"SealError", "SealErrors", "Where", "__version__"}
    assert set(seal_cli.__all__) == eager | {n for names in seal_cli._HOMES.values() for n in names}
    assert set(seal_cli.__all__) <= set(dir(seal_cli))


def test_an_unknown_name_is_an_attribute_error() -> None:
    with pytest.raises(AttributeError, match="no attribute 'SeFm'"):
        seal_cli.SeFm  # noqa: B018
    assert not hasattr(seal_cli, "nothing_here")


def test_importing_the_package_loads_no_subpackage() -> None:
    code = "import sys, seal_cli; print(sorted(m for m in sys.modules if m.startswith('seal_cli')))"
    loaded = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True).stdout
    assert loaded.strip() == "['seal_cli', 'seal_cli.errors']"


def test_load_map_takes_a_path_or_a_shipped_name(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.chdir(tmp_path)
    by_name = seal_cli.load_map("apartment")
    by_path = seal_cli.load_map(maps_dir() / "apartment.yaml")
    assert isinstance(by_name, Map) and by_name.name == by_path.name == "apartment"
    assert by_name.room_names == by_path.room_names
    local = tmp_path / "apartment.yaml"      # a file of that name comes first
    local.write_text("name: mine\nbounds: [0, 0, 4, 3]\n")
    assert seal_cli.load_map("apartment.yaml").name == "mine"
    assert seal_cli.load_map("apartment").name == "apartment"
    with pytest.raises(seal_cli.SealError, match="nowhere.yaml"):
        seal_cli.load_map("nowhere.yaml")


def test_the_package_is_typed() -> None:
    assert (Path(seal_cli.__file__).parent / "py.typed").is_file()
    pyproject = (ROOT / "pyproject.toml").read_text(encoding="utf-8")
    assert 'packages = ["seal_cli"]' in pyproject   # hatch ships every file of the package, py.typed too
