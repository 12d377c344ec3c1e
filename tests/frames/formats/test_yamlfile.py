"""frames.formats.yamlfile: frames in YAML, one or many documents; problems collected with positions."""

from __future__ import annotations

from seal_cli.frames.formats.yamlfile import dump, read
from seal_cli.frames.reading import standard_library

A = "frame: A\nlexical_units: [a]\nelements: {theme: {type: object}}\n"


def test_a_file_may_hold_several_documents() -> None:
    contents = read(A + "---\n" + A.replace("A", "B").replace("[a]", "[b]"), "x.yaml")
    assert [f.name for f in contents.frames] == ["A", "B"] and contents.problems == []
    assert contents.frames[1].where is not None and contents.frames[1].where.line == 5


def test_an_empty_file_holds_nothing_and_is_no_error() -> None:
    contents = read("", "x.yaml")
    assert contents.frames == [] and contents.problems == []


def test_a_yaml_syntax_error_is_located() -> None:
    (problem,) = read("frame: A\n  bad: [\n", "x.yaml").problems
    assert (problem.file, problem.line, problem.column) == ("x.yaml", 2, 6)
    assert problem.message.startswith("YAML syntax error")


def test_dump_reads_back_to_the_same_frames() -> None:
    library = standard_library()
    again = read(dump(list(library.frames), library.taxonomy), "dumped.yaml")
    assert again.problems == [] and tuple(again.frames) == library.frames
