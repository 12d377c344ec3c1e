"""yamlnodes: positions of YAML values, and the problems of their shapes, collected, never raised."""

from __future__ import annotations

import yaml

from seal_cli.errors import SealError, Where
from seal_cli.fileio import LOADER
from seal_cli.yamlnodes import NodeReader, is_null, shape, suggest

TEXT = "name: kitchen\nitems: [a, b]\nempty:\nbox: {x: 1, x: 2, colour: red}\n"


def node(text: str = TEXT) -> yaml.MappingNode:
    root = yaml.compose(text, Loader=LOADER)
    assert isinstance(root, yaml.MappingNode)
    return root


def value(key: str) -> yaml.Node:
    return next(v for k, v in node().value if k.value == key)


def test_positions_are_one_based_lines_and_columns() -> None:
    reader = NodeReader(TEXT, "map.yaml")
    assert reader.where(value("items")) == Where("map.yaml", 2, 8)


def test_shapes_and_nulls() -> None:
    assert is_null(value("empty")) and not is_null(value("name"))
    assert "list" in shape(value("items")) and "mapping" in shape(value("box"))
    assert suggest("colr", ["colour", "size"]) == " (did you mean 'colour'?)" and suggest("zzz", ["colour"]) == ""


def test_reading_values_collects_problems_with_source_lines() -> None:
    reader = NodeReader(TEXT, "map.yaml")
    assert reader.string(value("name"), "a name") == "kitchen"
    assert [n.value for n in reader.items(value("items"), "items")] == ["a", "b"]
    assert reader.items(value("empty"), "items") == []
    assert reader.string(value("items"), "a name") is None
    pairs = [key for key, _, _ in reader.pairs(value("box"), "the box", allowed=("x", "size"))]
    assert pairs == ["x"]
    messages = [p.message for p in reader.problems]
    assert messages[0].startswith("a name must be a single value")
    assert "the box repeats the key 'x'" in messages
    assert any(m.startswith("unknown key 'colour' in the box") and "known keys are x, size" in m for m in messages)
    assert all(p.source_line == TEXT.splitlines()[p.line - 1] for p in reader.problems)


def test_build_turns_a_value_objects_error_into_a_problem() -> None:
    reader = NodeReader(TEXT, "map.yaml")

    def bad() -> int:
        raise SealError("a room needs three corners")

    assert reader.build(bad, value("box")) is None and reader.build(lambda: 7, value("box")) == 7
    (problem,) = reader.problems
    assert problem.message == "a room needs three corners" and problem.where == Where("map.yaml", 4, 6)
