"""The validator: a corpus of broken frame files, each with the problems it must report.

Each file in ``tests/data/frames_bad`` starts with ``# expect: LINE: text`` (or ``// expect:``
in the DSL) lines; validating the file together with the standard library must report exactly
those problems, each on its line and containing its text.
"""

from __future__ import annotations

import re
from pathlib import Path

import pytest
from typer.testing import CliRunner

from seal_cli.cli import app
from seal_cli.frames.model import Element, Fact, Frame
from seal_cli.frames.taxonomy import Taxonomy
from seal_cli.frames.validation import check_library
from seal_cli.validate import validate_paths

BAD = Path(__file__).parents[1] / "data" / "frames_bad"
CASES = sorted(BAD.iterdir())
EXPECT = re.compile(r"^(?:#|//) expect: (\d+): (.+)$", re.M)


def expectations(path: Path) -> list[tuple[int, str]]:
    return [(int(line), text.strip()) for line, text in EXPECT.findall(path.read_text())]


def test_corpus_is_large_enough() -> None:
    assert len(CASES) >= 30
    assert all(expectations(p) for p in CASES)


@pytest.mark.parametrize("path", CASES, ids=[p.stem for p in CASES])
def test_each_broken_file_reports_its_problems(path: Path) -> None:
    report = validate_paths([path], with_stdlib=True)
    got = [(p.line, p.message) for p in report.problems]
    want = expectations(path)
    assert len(got) == len(want), got
    for (line, message), (want_line, want_text) in zip(got, want, strict=True):
        assert line == want_line, (message, want_text)
        assert want_text in message
    assert all(p.file == str(path) for p in report.problems)


@pytest.mark.parametrize("path", CASES, ids=[p.stem for p in CASES])
def test_cli_prints_file_line_column_and_exits_1(path: Path) -> None:
    result = CliRunner().invoke(app, ["validate", "--stdlib", str(path)])
    assert result.exit_code == 1
    assert result.exception is None or isinstance(result.exception, SystemExit)
    line = expectations(path)[0][0]
    assert re.search(rf"^{re.escape(str(path))}:{line}:\d+: ", result.stdout, re.M), result.stdout
    assert "Traceback" not in result.output


def test_syntax_errors_show_the_line_with_a_caret() -> None:
    result = CliRunner().invoke(app, ["validate", "--stdlib", str(BAD / "34_dsl_bad_character.frame")])
    lines = result.stdout.splitlines()
    index = next(i for i, text in enumerate(lines) if "unexpected '@'" in text)
    assert lines[index + 1] == "  theme: @container"
    assert lines[index + 2] == "         ^"


def test_every_problem_is_listed_not_only_the_first(tmp_path: Path) -> None:
    mixed = tmp_path / "mixed.yaml"
    mixed.write_text("frame: Beat\nlexical_units: [beat]\nelements:\n  theme: {type: containr}\n"
                     "actions: [stirr(theme)]\npreconditions: [stired(theme)]\n")
    report = validate_paths([mixed, BAD / "12_unknown_category.yaml"], with_stdlib=True)
    assert sorted((p.file, p.line) for p in report.problems) == sorted([
        (str(BAD / "12_unknown_category.yaml"), 5), (str(mixed), 4), (str(mixed), 5), (str(mixed), 6)])


def test_the_standard_library_is_clean(library) -> None:
    from seal_cli.resources import framelib_dir

    report = validate_paths([framelib_dir()])
    assert report.problems == []
    assert report.frames == 25


def test_missing_path_is_a_problem(tmp_path: Path) -> None:
    report = validate_paths([tmp_path / "nope.yaml"])
    assert "no such file or folder" in report.problems[0].message


def test_empty_folder_is_a_problem(tmp_path: Path) -> None:
    report = validate_paths([tmp_path])
    assert "no frame files" in report.problems[0].message


def test_cycle_needs_every_achiever_inside_it() -> None:
    taxonomy = Taxonomy.of({"thing": None})

    def frame(name: str, needs: str, gives: str) -> Frame:
        return Frame(name, elements=(Element("theme", "thing"),), preconditions=(Fact(needs, ("theme",)),),
                     postconditions=(Fact(gives, ("theme",)),))

    looped = [frame("Boil", "filled", "boiling"), frame("Fill", "boiling", "filled")]
    assert any("cycle" in p.message for p in check_library(looped, taxonomy))
    # A third frame that achieves `filled` without needing anything breaks the cycle.
    escape = Frame("Pour", elements=(Element("theme", "thing"),), postconditions=(Fact("filled", ("theme",)),))
    assert not any("cycle" in p.message for p in check_library([*looped, escape], taxonomy))


def test_a_negated_precondition_needs_no_achiever_and_makes_no_cycle(tmp_path: Path) -> None:
    """``requires not zapped(theme)`` (a "do it once" frame) holds in the closed world until something makes
    ``zapped`` true, so it is no unachieved precondition, and a pair toggling it (Zap, Unzap) no cycle (e2e22);
    a positive precondition nothing achieves is still refused."""
    taxonomy = Taxonomy.of({"thing": None})
    theme = (Element("theme", "thing"),)
    zap = Frame("Zap", elements=theme, preconditions=(Fact("zapped", ("theme",), negated=True),),
                postconditions=(Fact("zapped", ("theme",)),))
    unzap = Frame("Unzap", elements=theme, preconditions=(Fact("zapped", ("theme",)),),
                  postconditions=(Fact("zapped", ("theme",), negated=True),))
    assert check_library([zap], taxonomy) == [] and check_library([zap, unzap], taxonomy) == []
    blessed = Frame("Bless", elements=theme, preconditions=(Fact("holy", ("theme",)),))
    assert any("achieved by no frame" in p.message for p in check_library([zap, blessed], taxonomy))
    dsl = tmp_path / "zap.frame"
    dsl.write_text('frame Zap "zap" {\n  theme: object\n  requires not zapped(theme)\n  do navigate(theme)\n'
                   '  ensures zapped(theme)\n}\n')
    assert validate_paths([dsl], with_stdlib=True).problems == []


def test_a_cycle_is_said_whole_through_every_frame_of_it() -> None:
    """A frame of a cycle of three that also needs what it achieves itself made the cycle "Zap → Zap", naming one
    frame (hostile32); frames on two loops through one are each named, that one twice."""
    taxonomy = Taxonomy.of({"thing": None})

    def frame(name: str, needs: tuple[str, ...], gives: tuple[str, ...]) -> Frame:
        return Frame(name, elements=(Element("theme", "thing"),),
                     preconditions=tuple(Fact(n, ("theme",)) for n in needs),
                     postconditions=tuple(Fact(g, ("theme",)) for g in gives))

    def said(frames: list[Frame]) -> list[str]:
        return [p.message.split(";")[0] for p in check_library(frames, taxonomy)]

    three = [frame("Zap", ("a", "c"), ("b", "c")), frame("Bop", ("b",), ("d",)), frame("Cop", ("d",), ("a",))]
    assert said(three) == ["precondition cycle: Zap → Cop → Bop → Zap"]
    forked = [frame("Zap", ("a", "c"), ("b", "d")), frame("Bop", ("b",), ("a",)), frame("Cop", ("d",), ("c",))]
    assert said(forked) == ["precondition cycle: Zap → Bop → Zap → Cop → Zap"]
    assert said([frame("Zap", ("a",), ("a",))]) == ["precondition cycle: Zap → Zap"]
    four = [frame("A", ("a",), ("d",)), frame("B", ("b",), ("a",)), frame("C", ("c",), ("b",)),
            frame("D", ("d",), ("c",))]
    assert said(four) == ["precondition cycle: A → B → C → D → A"]


def test_a_category_cycle_is_said_whole() -> None:
    taxonomy = Taxonomy.of({"a": ["b", "c", "x"], "b": ["a"], "c": ["a"]})
    found = [p.message for p in check_library([], taxonomy) if "category cycle" in p.message]
    assert found and found[0].startswith("category cycle: a → b → a → c → a")


def test_a_knot_of_thousands_is_said_by_one_loop_and_a_count_at_once() -> None:
    """A way round every frame of a knot of 5,000 took 10 s (a star: each frame needs the hub's, the hub each's)."""
    import time

    from seal_cli.frames.validation import WHOLE

    taxonomy = Taxonomy.of({"thing": None})
    n = 5000
    hub = Frame("Hub", elements=(Element("x", "thing"),), preconditions=tuple(Fact(f"p{i}", ("x",)) for i in range(n)),
                postconditions=(Fact("c", ("x",)),))
    leaves = [Frame(f"L{i}", elements=(Element("x", "thing"),), preconditions=(Fact("c", ("x",)),),
                    postconditions=(Fact(f"p{i}", ("x",)),)) for i in range(n)]
    started = time.perf_counter()
    found = check_library([hub, *leaves], taxonomy)
    assert time.perf_counter() - started < 3 and len(found) == 1
    assert found[0].message.startswith("precondition cycle: Hub → L0 → Hub (and 4,999 more of the same knot: L1, L2, "
                                       "L3, …); none")
    small = check_library([hub.__class__(hub.name, elements=hub.elements, preconditions=hub.preconditions[:WHOLE - 1],
                                         postconditions=hub.postconditions), *leaves[:WHOLE - 1]], taxonomy)
    cycle = small[0].message.split(";")[0].removeprefix("precondition cycle: ").split(" → ")
    assert cycle[:4] == ["Hub", "L0", "Hub", "L1"] and set(cycle) == {"Hub", *(f"L{i}" for i in range(WHOLE - 1))}
