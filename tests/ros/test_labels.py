"""Labels files name numeric class ids: a mapping or a list, every problem at its line and column."""

from __future__ import annotations

from pathlib import Path

import pytest

from seal_cli.errors import SealError
from seal_cli.ros.labels import read_labels


def write(tmp_path: Path, text: str) -> Path:
    path = tmp_path / "labels.yaml"
    path.write_text(text)
    return path


def test_a_mapping_and_a_list_name_the_same_ids(tmp_path: Path) -> None:
    assert read_labels(write(tmp_path, "{0: background, 1: spoon, 2: cup}\n")) == \
        read_labels(write(tmp_path, "[background, spoon, cup]\n")) == {"0": "background", "1": "spoon", "2": "cup"}


@pytest.mark.parametrize(("text", "message"), [
    ("", "labels.yaml: a labels file is a mapping {id: class} or a list of classes, not nothing"),
    ("spoon\n", "labels.yaml:1:1: a labels file is a mapping {id: class} or a list of classes, not 'spoon'"),
    ("[spoon, [cup]]\n", "labels.yaml:1:9: label 1 must be a single value, not a list"),
    ("{1: spoon, 1: cup}\n", "labels.yaml:1:12: the labels repeats the key '1'"),
    ("{1: spoon\n", "labels.yaml:2:1: YAML syntax error"),
    ("{cup: 1}\n", "labels.yaml:1:7: the label of cup must be a class's name, not '1' (YAML reads it as int)"),
    ("[spoon, true]\n", "labels.yaml:1:9: label 1 must be a class's name, not 'true' (YAML reads it as bool)"),
    ('[spoon, "cu\\0p"]\n', "labels.yaml:1:9: label 1 'cu\\x00p' holds '\\x00' (U+0000"),   # hostile31
])
def test_bad_labels_files(tmp_path: Path, text: str, message: str) -> None:
    with pytest.raises(SealError) as caught:
        read_labels(write(tmp_path, text))
    assert str(caught.value).splitlines()[0].startswith(f"{tmp_path}/{message}")
