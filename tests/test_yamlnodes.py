"""yamlnodes: positions of YAML values, and the problems of their shapes, collected, never raised."""

from __future__ import annotations

import pytest
import yaml

from seal_cli.errors import SealError, Where
from seal_cli.fileio import LOADER
from seal_cli.yamlnodes import NodeReader, check_size, is_null, shape, suggest

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


def test_an_alias_is_a_node_at_its_own_line_and_column() -> None:
    from seal_cli.fileio import compose_yaml

    text = "robot: &r {pose: [1, 1, 0]}\npeople:\n  - *r\n  - [*r]\n"
    root = compose_yaml(text, "m.yaml")
    robot, people = root.value[0][1], root.value[1][1]
    first, second = people.value[0], people.value[1].value[0]
    assert (first.start_mark.line, first.start_mark.column) == (2, 4)
    assert (second.start_mark.line, second.start_mark.column) == (3, 5)
    assert first.value is robot.value and (robot.start_mark.line, robot.start_mark.column) == (0, 7)


def test_aliases_are_placed_in_the_order_written_however_deep() -> None:
    from seal_cli.fileio import compose_documents

    text = "---\na: &a [1]\nb: [[*a], *a]\n---\nc: &a 2\nd: *a\n"
    first, second = compose_documents(text, "m.yaml")
    inner, outer = first.value[1][1].value[0].value[0], first.value[1][1].value[1]
    assert (inner.start_mark.line, inner.start_mark.column) == (2, 5)
    assert (outer.start_mark.line, outer.start_mark.column) == (2, 10)
    d = second.value[1][1]
    assert d.value == "2" and (d.start_mark.line, d.start_mark.column) == (5, 3)


def test_merge_keys_merge_with_the_mappings_own_keys_first() -> None:
    from seal_cli.fileio import compose_yaml

    text = "a: &a {x: 1, y: 2}\nb: &b {y: 3, z: 4}\nc: {<<: [*a, *b], x: 9}\nc2: &c2 {<<: *a}\n"
    root = compose_yaml(text, "m.yaml")
    c = root.value[2][1]
    assert [(k.value, v.value) for k, v in c.value] == [("y", "2"), ("z", "4"), ("x", "9")]
    c2 = root.value[3][1]
    assert [(k.value, v.value) for k, v in c2.value] == [("x", "1"), ("y", "2")]
    assert yaml.load(text, Loader=LOADER)["c"] == {"x": 9, "y": 2, "z": 4}  # PyYAML's loader merges alike


def test_a_merge_of_a_merge_and_a_merge_of_no_mapping() -> None:
    from seal_cli.fileio import compose_yaml

    root = compose_yaml("a: &a {x: 1}\nb: &b {<<: *a, y: 2}\nc: {<<: *b, z: 3}\n", "m.yaml")
    assert [k.value for k, _ in root.value[2][1].value] == ["x", "y", "z"]
    for text, column in (("a: {<<: 5}\n", 9), ("a: &a [1]\nb: {<<: [*a]}\n", 10)):
        try:
            compose_yaml(text, "m.yaml")
        except SealError as exc:
            assert "a merge key (<<) takes a mapping" in exc.message and exc.where.column == column
        else:
            raise AssertionError("merged no mapping")


def test_a_merge_bomb_is_still_refused_by_its_size() -> None:
    from seal_cli.fileio import compose_yaml

    lines = ["l0: &l0 {a: 1, b: 2, c: 3, d: 4, e: 5, f: 6, g: 7, h: 8, i: 9}"]
    lines += [f"l{i}: &l{i} [*l{i - 1}, *l{i - 1}, *l{i - 1}, *l{i - 1}, *l{i - 1}, *l{i - 1}, *l{i - 1}, *l{i - 1}, "
              f"*l{i - 1}]" for i in range(1, 9)]
    lines += ["m: {<<: [*l0], z: *l8}"]
    try:
        compose_yaml("\n".join(lines) + "\n", "m.yaml")
    except SealError as exc:
        assert "once its aliases (*name) are expanded" in exc.message
    else:
        raise AssertionError("a billion laughs was read")


def test_a_merged_pair_stands_at_the_merge_that_brought_it() -> None:
    from seal_cli.fileio import compose_yaml

    root = compose_yaml("a: &a {x: {y: 1}}\nb: {<<: *a}\n", "m.yaml")
    key, value = root.value[1][1].value[0]
    assert (key.start_mark.line, key.start_mark.column) == (1, 8) == (value.start_mark.line, value.start_mark.column)
    inner = value.value[0][0]
    assert (inner.start_mark.line, inner.start_mark.column) == (0, 11)  # what is inside: where it is written


def test_a_file_too_large_once_expanded_is_refused_where_it_passes_the_bound() -> None:
    """A "billion laughs" is refused at the line whose aliases pass the bound, not at the file alone (hostile26)."""
    from seal_cli.yamlnodes import check_size

    laughs = "a: 1\nl:\n  - &l0 [x, x, x]\n  - &l1 [*l0, *l0, *l0]\n  - &l2 [*l1, *l1, *l1]\n"
    with pytest.raises(SealError, match="more than 20 values once its aliases") as caught:
        check_size(yaml.compose(laughs, Loader=LOADER), "b.yaml", 20)
    assert caught.value.where == Where("b.yaml", 4, 5)            # &l1: its 13 values bring the count to 22
    with pytest.raises(SealError) as caught:
        check_size(yaml.compose("x: [" + ", ".join("1" * 30) + "]\n", Loader=LOADER), "f.yaml", 20)
    assert caught.value.where.line == 1 and caught.value.where.column is not None


@pytest.mark.parametrize(("text", "where", "tag"), [
    ("name: !!binary bGFi\n", (1, 7), "!!binary"),
    ("rooms: !!python/object/apply:os.system\n  - a\n", (1, 8), "!!python/object/apply:os.system"),
    ("a: [1, !mine b]\n", (1, 8), "!mine"),
    ("a: !!set {x}\n", (1, 4), "!!set"),
    ("a: !!omap [{x: 1}]\n", (1, 4), "!!omap"),
    ("a: !<tag:example.com,2000:x> b\n", (1, 4), "!<tag:example.com,2000:x>"),
])
def test_a_tag_seal_does_not_read_is_refused_at_its_node(text: str, where: tuple[int, int], tag: str) -> None:
    """Each was passed over (hostile29): ``name: !!binary bGFi`` named the map ``bGFi``."""
    with pytest.raises(SealError) as caught:
        check_size(yaml.compose(text, Loader=LOADER), "f.yaml")
    assert (caught.value.where.line, caught.value.where.column) == where
    assert f"the tag {tag} asks for a value seal does not read" in caught.value.message


def test_the_tags_yaml_gives_plain_values_are_read() -> None:
    text = "a: [1, 2.5, true, ~, x, 2001-12-14, !!str 10, !!int 3]\nb: &b {c: 1}\nd:\n  <<: *b\n"
    check_size(yaml.compose(text, Loader=LOADER), "f.yaml")


def _checked(text: str) -> yaml.Node:
    root = yaml.compose(text, Loader=LOADER)
    check_size(root, "f.yaml", lines=text.split("\n"))
    return root


@pytest.mark.parametrize(("text", "where", "says"), [
    ("name: !!int lab\n", (1, 7), "the tag !!int says the value is an integer, but it is 'lab'"),
    ("negate: !!bool 0\n", (1, 9), "the tag !!bool says the value is true or false, but it is '0'"),
    ("a: [1, &x !!float abc]\n", (1, 8), "the tag !!float says the value is a number, but it is 'abc'"),
    ("a: !!null b\n", (1, 4), "the tag !!null says"),
    ("a: !!seq {b: 1}\n", (1, 4), "the tag !!seq says the value is a list, but it is a mapping"),
    ("a: !!map\n  - b\n", (1, 4), "the tag !!map says the value is a mapping, but it is a list"),
    ("a: !!int [1]\n", (1, 4), "the tag !!int says the value is an integer, but it is a list"),
])
def test_a_core_tag_that_does_not_fit_its_value_is_refused_at_it(text: str, where: tuple[int, int],
                                                                 says: str) -> None:
    """hostile30: ``!!int lab`` was read as the name "lab", and ``!!bool 0`` was a KeyError traceback."""
    with pytest.raises(SealError) as caught:
        _checked(text)
    assert (caught.value.where.line, caught.value.where.column) == where
    assert says in caught.value.message


def test_a_core_tag_that_fits_is_read_as_yaml_defines_it() -> None:
    root = _checked("a: [!!float 1, !!float 1e-3, !!int 0x10, !!bool yes, !!null ~, !!str 0.05, !!seq [1], "
                    "!!timestamp 2001-12-14]\n!!str b: !!map {c: 1}\nd: !!str 5\n")
    items = root.value[0][1].value
    assert items[5].tag == "tag:yaml.org,2002:str" and items[5].style  # read as text, as if quoted
    assert "the text '0.05'" in shape(items[5]) and shape(root.value[2][1]).startswith("the text '5'")


def test_a_tag_is_known_as_written_only_where_the_file_writes_it() -> None:
    """A plain value that YAML reads as text (``x``), a quoted number, an anchor without a tag: no tag written."""
    root = _checked("a: &n 5\nb: x\nc: '7'\nd: !!str\n")
    assert not root.value[1][1].style and shape(root.value[2][1]).startswith("the text '7'")
