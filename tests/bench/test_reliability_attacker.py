"""An attacker's hostile cases of ``seal bench reliability``: new, named once, each saying what its message
names; a pick of them ends cleanly (each failed on main before this round)."""

from __future__ import annotations

import functools
from pathlib import Path

import pytest

from seal_cli.bench.reliability import Case, hostile_cases, issue_cases, run_case
from seal_cli.bench.reliability_attacker import (
    alfred2d_data,
    attacker_cases,
    hostile15_cases,
    hostile16_cases,
    hostile17_cases,
    hostile18_cases,
    hostile19_cases,
    hostile20_cases,
    hostile21_cases,
    hostile22_cases,
    hostile23_cases,
    hostile24_cases,
    hostile25_cases,
    hostile26_cases,
    hostile27_cases,
    hostile28_cases,
    hostile29_bag_cases,
    hostile29_cases,
    hostile29_environment_cases,
    hostile30_cases,
    hostile30_leftover_cases,
    hostile30_output_cases,
    sparse_pgm,
)
from seal_cli.bench.reliability_outsider import outsider_cases
from seal_cli.bench.reliability_review import cases, review_cases
from seal_cli.bench.reliability_users import user_cases


@functools.cache
def _attacker() -> tuple[Case, ...]:
    """:func:`attacker_cases`, made once for this module's tests that read them (about 2 CPU-seconds a making)."""
    return tuple(attacker_cases())

def test_the_cases_are_new_named_once_and_say_what_the_message_names() -> None:
    attacker = list(_attacker())
    assert len(attacker) >= 80 and len({c.name for c in attacker}) == len(attacker)
    others = {c.name for c in [*issue_cases(), *hostile_cases(), *review_cases(), *user_cases(), *outsider_cases()]}
    assert {c.name for c in attacker}.isdisjoint(others)
    # a command a signal ends (exit 128 + n) says nothing, as any Unix tool; every other non-zero ending says why
    assert all(c.says is not None for c in attacker if c.codes != (0,) and not (c.signal and 1 not in c.codes))
    assert {c.name for c in attacker} <= {c.name for c in cases(0, 0)}


def test_a_sparse_image_holds_its_patch_in_the_lower_left_corner() -> None:
    data = sparse_pgm(5, 4, b"\x00\x01\x02\x03", 2, 2)
    pixels = data[len(b"P5\n5 4\n255\n"):]
    assert data.startswith(b"P5\n5 4\n255\n") and len(pixels) == 20
    assert pixels[10:12] == b"\x00\x01" and pixels[15:17] == b"\x02\x03" and pixels[:10] == b"\xcd" * 10


@pytest.mark.parametrize("name", ["A 5,000 digits in resolution: validate", "A 5,000 digits in an observation's pose",
                                  "A 5,000 digits in a vocabulary", "A a room of 62,831 vertices",
                                  "A a vocabulary of 300,000 words"])
def test_picked_cases_end_cleanly(name: str) -> None:
    outcome = run_case(next(c for c in _attacker() if c.name == name))
    assert outcome.problems == []


def test_the_small_alfred2d_data_runs_as_it_is_so_each_case_fails_on_its_own_change(tmp_path: Path) -> None:
    """The hostile15 cases change one value of :func:`alfred2d_data`: unchanged, it is data a run succeeds on."""
    import json
    import subprocess
    import sys

    for name, content in alfred2d_data():
        (tmp_path / name).parent.mkdir(exist_ok=True)
        (tmp_path / name).write_bytes(content)
    run = subprocess.run([sys.executable, "-m", "seal_cli", "bench", "tasks", "--data", "d", "--policies", "sefm",
                          "--jobs", "1", "--particles", "20", "--json"], cwd=tmp_path, capture_output=True, text=True,
                         timeout=300)
    assert run.returncode == 0, run.stderr
    assert json.loads(run.stdout)["groups"]["all"]["success"]["sefm"] == 1.0


@pytest.mark.parametrize("name", ["A ALFRED-2D data: an expert step that is a number",
                                  "A ALFRED-2D data: a start 10^308 m away", "A bench e2e --file: plan: 5",
                                  "A bench plan --file: a line that cannot be planned, at its line and column",
                                  "A --framelib + alone", "A --framelib /dev/zero: refused by its kind",
                                  "A a vocabulary with synonyms of 5"])
def test_picked_hostile15_cases_end_cleanly(name: str) -> None:
    """Each failed on main: a traceback (the ALFRED-2D step, ``plan: 5``), a message without its file or line (the
    start, the command, the vocabulary), the current folder read as frames, /dev/zero called missing."""
    outcome = run_case(next(c for c in hostile15_cases() if c.name == name))
    assert outcome.problems == []


@pytest.mark.parametrize("name", ["A a map called '[/]bed[bold]x' (rich markup): map",
                                  "A a map called '$x^$' (mathematics to matplotlib): map --png",
                                  "A a frame file named twice: validate", "A TERMINAL_WIDTH=abc: a usage error",
                                  "A plan --pddl of a command of two lines: both files PDDL",
                                  "A bench tasks --episodes onto its data: d/floorplans.json"])
def test_picked_hostile16_cases_end_cleanly(name: str, monkeypatch: pytest.MonkeyPatch) -> None:
    """Each failed on main: tracebacks (rich markup, matplotlib mathematics, typer's ``int(TERMINAL_WIDTH)``), a
    frame file named twice reported as every frame defined twice, PDDL files with a line outside their comment,
    the ALFRED-2D data replaced by the episodes. The commands run this tree's code (not an installed seal's)."""
    from pathlib import Path

    monkeypatch.setenv("PYTHONPATH", str(Path(__file__).resolve().parents[2]))
    outcome = run_case(next(c for c in hostile16_cases() if c.name == name))
    assert outcome.problems == []


@pytest.mark.parametrize("name", ["A seven million values in a trajectory: localize",
                                  "A a frame library whose needs chain 3,000 frames deep: plan",
                                  "A a FIFO at the library's cache entry: parse", "A import-bag of a link loop",
                                  "A localize --goals with --rrd a link loop"])
def test_picked_hostile17_cases_end_cleanly(name: str, monkeypatch: pytest.MonkeyPatch) -> None:
    """Each failed on main: a trajectory composed for over a minute, "nested too deeply" naming nothing, a FIFO in
    the cache waited on for ever, two RuntimeError tracebacks of ``Path.resolve``. The commands run this tree's
    code."""
    monkeypatch.setenv("PYTHONPATH", str(Path(__file__).resolve().parents[2]))
    outcome = run_case(next(c for c in hostile17_cases() if c.name == name))
    assert outcome.problems == []


@pytest.mark.parametrize("name", ["A a person that is an alias of the robot: said at the alias's line",
                                  "A a room merging another (<<: *room): map",
                                  "A observations whose second look sees a class nobody knows: set aside, said",
                                  "A bench tasks --policies sefm,sefm", "A import-bag of a NaN pose"])
def test_picked_hostile18_cases_end_cleanly(name: str, monkeypatch: pytest.MonkeyPatch) -> None:
    """Each failed on main: a problem said at the alias's anchor, a merge key refused, a bad look said without its
    line, a policy run twice, a bag's NaN pose written into observations seal then refused. This tree's code."""
    if "import-bag" in name:
        pytest.importorskip("rosbags")
    monkeypatch.setenv("PYTHONPATH", str(Path(__file__).resolve().parents[2]))
    outcome = run_case(next(c for c in hostile18_cases() if c.name == name))
    assert outcome.problems == []


def test_the_judge_reads_yaml_and_pddl_outputs_whole() -> None:
    from pathlib import Path
    from tempfile import TemporaryDirectory

    from seal_cli.bench.reliability import _complete

    with TemporaryDirectory() as folder:
        for name, data, whole in (("o.yaml", b"observations: []\n", True), ("o.yaml", b"a: [\n", False),
                                  ("d.pddl", b"; x\n(define (domain seal))\n", True),
                                  ("d.pddl", b"; x\nthen y\n(define (domain seal))\n", False),
                                  ("p.pddl", b"(define (problem c) (:domain seal)\n", False)):
            (Path(folder) / name).write_bytes(data)
            assert _complete(Path(folder) / name) is whole, (name, data)


@pytest.mark.parametrize("name", ["A a room name of 5,000 letters: at its line", "A a map in UTF-32",
                                  "A plan --framelib of frames: []", "A a map image at resolution 1e300: map --png",
                                  "A localize --goals goals.txt", "A bench e2e --file of no cases",
                                  "A import-bag of a pose rotated by (0, 0, 0, 0)"])
def test_picked_hostile19_cases_end_cleanly(name: str, monkeypatch: pytest.MonkeyPatch) -> None:
    """Each failed on main: a name of any length validated, UTF-32 said as a byte, a library of no frames said as an
    unknown verb, a traceback with a PNG left behind, goals written as a bag folder, a suite of nothing passed, a
    pose's zero rotation imported. This tree's code."""
    if "import-bag" in name:
        pytest.importorskip("rosbags")
    monkeypatch.setenv("PYTHONPATH", str(Path(__file__).resolve().parents[2]))
    outcome = run_case(next(c for c in hostile19_cases() if c.name == name))
    assert outcome.problems == []


def test_the_hostile19_cases_are_named_once_and_say_what_they_must() -> None:
    found = list(hostile19_cases())
    assert len({c.name for c in found}) == len(found) >= 21
    assert all(c.says for c in found if c.codes != (0,))


@pytest.mark.parametrize("name", ["A frames --json into a file past ulimit -f of 2 KiB (PYTHONUNBUFFERED=1)",
                                  "A parse --file --json into a non-blocking pipe (buffered)",
                                  "A map --png past ulimit -f of 4 KiB"])
def test_picked_hostile20_cases_end_cleanly(name: str, monkeypatch: pytest.MonkeyPatch) -> None:
    """Each failed on main: stdout cut at the file size limit with exit 0, a non-blocking pipe failing the command at 64
    KiB, a PNG past the limit said as "the output". This tree's code."""
    monkeypatch.setenv("PYTHONPATH", str(Path(__file__).resolve().parents[2]))
    outcome = run_case(next(c for c in hostile20_cases() if c.name == name))
    assert outcome.problems == []


def test_the_hostile20_cases_are_named_once_and_say_what_they_must() -> None:
    found = list(hostile20_cases())
    assert len({c.name for c in found}) == len(found) >= 14
    assert all(c.says for c in found)
    assert {c.stream for c in found} >= {"file-stdout", "nonblocking-stdout"}


@pytest.mark.parametrize("name", ["A map --help onto /dev/full", "A bench tasks --help into a reader that has gone",
                                  "A --version with standard output closed",
                                  "A parse --json of a command with a Latin-1 byte", "A plan with a full-width digit",
                                  "A plan of vulgar fraction one half apples", "A run of one million apples"])
def test_picked_hostile21_cases_end_cleanly(name: str, monkeypatch: pytest.MonkeyPatch) -> None:
    """Each failed on main: a traceback of the help onto a full disk, exit 1 of a help whose reader had gone, a
    traceback of --version with no stdout, a Latin-1 byte said as an "unexpected character '\\udce9'", a full-width
    digit refused, "3½ apples" read as three and "one million apples" as one. This tree's code."""
    monkeypatch.setenv("PYTHONPATH", str(Path(__file__).resolve().parents[2]))
    outcome = run_case(next(c for c in hostile21_cases() if c.name == name))
    assert outcome.problems == []


def test_the_hostile21_cases_are_named_once_and_say_what_they_must() -> None:
    found = list(hostile21_cases())
    assert len({c.name for c in found}) == len(found) >= 24
    assert all(c.says for c in found if c.codes != (0,))
    assert {c.stream for c in found} >= {"full-stdout", "closed-stdout", "gone-stdout"}



@pytest.mark.parametrize("name", ["A run of a room called \"kid's room\"", "A plan of 'bring me zero apples'",
                                  "A plan with a .frame file of CR lines",
                                  "A bench tasks --suite map --jobs 2 interrupted"])
def test_picked_hostile22_cases_end_cleanly(name: str, monkeypatch: pytest.MonkeyPatch) -> None:
    """Each failed on main: a room "kid's room" validated, then its plan failed at a line of seal's motion.yaml;
    "zero apples" planned one; a .frame file of CR lines held no frames, silently. The pool's case outlived its SIGINT
    by 60 s under load when the interrupt landed while a worker was forked (hostile23). This tree's code."""
    monkeypatch.setenv("PYTHONPATH", str(Path(__file__).resolve().parents[2]))
    outcome = run_case(next(c for c in hostile22_cases() if c.name == name))
    assert outcome.problems == []


def test_the_hostile22_cases_are_named_once_and_say_what_they_must() -> None:
    found = list(hostile22_cases())
    assert len({c.name for c in found}) == len(found) >= 19
    assert all(c.says for c in found)

@pytest.mark.parametrize("name", ["A bench tasks --suite map --jobs 2: a worker killed (SIGKILL)",
                                  "A run to a room called кухня",
                                  "A validate of a room name no plan can name: said at the name",
                                  "A validate of a person name no plan can name: said at the name"])
def test_picked_hostile23_cases_end_cleanly(name: str, monkeypatch: pytest.MonkeyPatch) -> None:
    """The worker's case passed before this round too (kept: the judge now signals a worker itself); the others
    failed: "the m has no кухня ... its rooms are кухня", a name's problem said at the room's box or the person's
    first key. This tree's code."""
    monkeypatch.setenv("PYTHONPATH", str(Path(__file__).resolve().parents[2]))
    outcome = run_case(next(c for c in hostile23_cases() if c.name == name))
    assert outcome.problems == []


def test_the_hostile23_cases_are_named_once_and_say_what_they_must() -> None:
    found = list(hostile23_cases())
    assert len({c.name for c in found}) == len(found) >= 14
    assert all(c.says for c in found if c.codes in ((0,), (1,)))
    assert any(c.to_worker for c in found)


@pytest.mark.parametrize("name", ["A run to a bed on the other island", "A plan to the bed when no bed can be reached",
                                  "A validate of a room called ha\\tll",
                                  "A run to a room called \\u0e04\\u0e23\\u0e31\\u0e27",
                                  "A validate of a fridge whose open is a list",
                                  "A signal 15 while run --png --rrd writes its temporary"])
def test_picked_hostile24_cases_end_cleanly(name: str, monkeypatch: pytest.MonkeyPatch) -> None:
    """Each but the last failed before this round: a bed beyond a wall searched for 14 m, none of several beds in
    reach said "inf m", a room "ha<tab>ll" validated, "go to the ครัว" refused at its vowel sign, an ``open`` list
    said as YAML nodes. This tree's code."""
    monkeypatch.setenv("PYTHONPATH", str(Path(__file__).resolve().parents[2]))
    outcome = run_case(next(c for c in hostile24_cases() if c.name == name))
    assert outcome.problems == []


def test_the_hostile24_cases_are_named_once_and_say_what_they_must() -> None:
    found = list(hostile24_cases())
    assert len({c.name for c in found}) == len(found) >= 29
    assert all(c.says for c in found if c.codes in ((0,), (1,)))
    assert any(c.signal_on for c in found) and any(c.file_blocks for c in found) and any(c.parallel > 1 for c in found)


def test_a_signal_waits_for_its_file() -> None:
    """``Case.signal_on``: the signal goes once the file is there, and not at all when the command ends first."""
    import sys

    import seal_cli.bench.reliability as judge

    waits = ("import pathlib, time\nt = time.time()\nwhile time.time() - t < 0.3: pass\n"  # busy: judge waits for CPU
             "pathlib.Path('.x.seal1-0123abcd.tmp').write_text('')\nwhile time.time() - t < 30: pass\n")
    with pytest.MonkeyPatch.context() as patch:
        patch.setattr(judge, "_seal", lambda: [sys.executable, "-c", waits])
        stopped = run_case(judge.Case("stopped once its temporary is there", (), codes=(143, -15), signal=(15, 0.0),
                                      signal_on=r"\.seal\d+-[0-9a-f]{8}\.tmp"))
        patch.setattr(judge, "_seal", lambda: [sys.executable, "-c", "pass"])
        unsent = run_case(judge.Case("ends before any file", (), codes=(0,), signal=(15, 0.0), signal_on=r"never"))
    assert stopped.code == -15 and 0.3 <= stopped.seconds < 10
    assert unsent.code == 0 and unsent.problems == []


def test_the_judge_sees_a_command_whose_reader_has_gone_fail(monkeypatch: pytest.MonkeyPatch) -> None:
    """The ``gone-stdout`` stream really is a pipe without a reader: a program that does not expect it fails there."""
    import sys

    import seal_cli.bench.reliability as judge

    monkeypatch.setattr(judge, "_seal", lambda: [sys.executable, "-c", "print('x' * 100000)"])
    failed = run_case(judge.Case("print into no reader", ("--version",), codes=(0,), stream="gone-stdout"))
    assert failed.code == 1 and {"exit", "traceback"} <= failed.kinds    # BrokenPipeError


@pytest.mark.parametrize("name", ["A plan on areas that overlap says so",
                                  "A plan to a place in two areas, by the second", "A run --png --rrd onto /dev/full",
                                  "A run --png under nohup, sent SIGHUP",
                                  "A localize --rrd past ulimit -f of 4 KiB says the file is too large"])
def test_picked_hostile25_cases_end_cleanly(name: str, monkeypatch: pytest.MonkeyPatch) -> None:
    """Each failed before this round: plan kept quiet about areas that overlap, a sofa where two areas overlap was
    "not in" the second, --rrd was left in place when --png /dev/full failed, nohup's SIGHUP ended the run 129, and
    rerun's "File too large" was "rerun's writer stopped". This tree's code."""
    monkeypatch.setenv("PYTHONPATH", str(Path(__file__).resolve().parents[2]))
    outcome = run_case(next(c for c in hostile25_cases() if c.name == name))
    assert outcome.problems == []


def test_the_hostile25_cases_are_named_once_and_say_what_they_must() -> None:
    found = list(hostile25_cases())
    assert len({c.name for c in found}) == len(found) >= 33
    assert all(c.says for c in found if c.codes in ((0,), (1,)))
    assert any(c.ignored for c in found) and any(c.cwd for c in found)


@pytest.mark.parametrize("name", ["A plan to put the milk back when each fridge holds one",
                                  "A run --rrd whose folder vanishes while it writes",
                                  "A run on a map whose rooms are a billion laughs",
                                  "A plan on a frame file with a category of 10 MB on one line",
                                  "A localize with a --done of control characters",
                                  "A run --rrd with a newline in a wrong suffix"])
def test_picked_hostile26_cases_end_cleanly(name: str, monkeypatch: pytest.MonkeyPatch) -> None:
    """Each failed before this round: the corner shop's milk moved from one fridge to the other, a vanished folder
    was said of a temporary's name, a billion laughs was said of the file alone, a 10 MB category line ran past a
    minute, a --done of control characters was not named, a file name's newline broke the message. This tree's
    code."""
    monkeypatch.setenv("PYTHONPATH", str(Path(__file__).resolve().parents[2]))
    outcome = run_case(next(c for c in hostile26_cases() if c.name == name))
    assert outcome.problems == []


def test_the_hostile26_cases_are_named_once_and_say_what_they_must() -> None:
    found = list(hostile26_cases())
    assert len({c.name for c in found}) == len(found) >= 31
    assert all(c.says for c in found if c.codes in ((0,), (1,)))
    assert sum(bool(c.vanish) for c in found) == 3 and any(c.parallel > 1 for c in found)
    assert {c.name for c in found} <= {c.name for c in _attacker()}


@pytest.mark.parametrize("name", ["A plan with --holding ''", "A run with --vocabulary ''",
                                  "A validate of a map named with a NUL",
                                  "A localize --goals onto a file where a bag folder goes",
                                  "A killed localize's bag temporary is swept", "A import-bag with --pose-topic ''"])
def test_picked_hostile27_cases_end_cleanly(name: str, monkeypatch: pytest.MonkeyPatch) -> None:
    """Each failed before this round: --holding '' planned with the map's hand, --vocabulary '' was named by its
    parameter, a map's NUL name validated, --goals onto a file ran the filter and said "Not a directory", a killed
    bag writer's folder stayed, --pose-topic '' said "no topic  in the bag". This tree's code."""
    monkeypatch.setenv("PYTHONPATH", str(Path(__file__).resolve().parents[2]))
    case = next((c for c in hostile27_cases() if c.name == name), None)
    if case is None:
        pytest.skip("the ros extra is not installed: no bag to read")
    assert run_case(case).problems == []


def test_the_hostile27_cases_are_named_once_and_say_what_they_must() -> None:
    found = list(hostile27_cases())
    assert len({c.name for c in found}) == len(found) >= 28
    assert all(c.says for c in found if c.codes == (1,))
    assert any(c.parallel > 1 for c in found) and any(c.signal for c in found)
    assert {c.name for c in found} <= {c.name for c in _attacker()}


@pytest.mark.parametrize("name", ["A bench parse --corpus of a GPSR command without its fills",
                                  "A bench parse --corpus whose text holds a lone surrogate",
                                  "A bench parse --corpus of an ALFRED row short of columns",
                                  "A map --png in a deleted working folder",
                                  "A parse --file in a deleted working folder",
                                  "A frames --json of a description holding an escape sequence"])
def test_picked_hostile28_cases_end_cleanly(name: str, monkeypatch: pytest.MonkeyPatch) -> None:
    """Each failed before this round: a GPSR line without fills and a lone surrogate were the scorer's KeyError and
    UnicodeEncodeError, an ALFRED row short of columns said "holds no commands" naming no line, a deleted working
    folder said "cannot write the output: No such file or directory" or "no such file" alone, a frame's description
    holding an escape sequence was accepted. This tree's code; none needs ../shared."""
    monkeypatch.setenv("PYTHONPATH", str(Path(__file__).resolve().parents[2]))
    case = next(c for c in hostile28_cases() if c.name == name)
    assert run_case(case).problems == []


def test_the_hostile28_cases_are_named_once_and_say_what_they_must() -> None:
    found = list(hostile28_cases())
    assert len({c.name for c in found}) == len(found) >= 25
    assert all(c.says for c in found if c.codes in ((0,), (1,)))
    assert sum(c.remove_cwd for c in found) >= 5 and sum(bool(c.unsaid) for c in found) == 2
    assert {c.name for c in found} <= {c.name for c in _attacker()}


@pytest.mark.parametrize("name", ["A bench tasks --suite context_held_out --data /dev/null",
                                  "A bench parse --corpus whose element is 5,000 digits",
                                  "A validate of a ROS map whose name is tagged !!binary",
                                  "A validate of a ROS map whose PGM has a width of 5,000 digits",
                                  "A validate of a ROS map whose PGM (text) holds a negative pixel",
                                  "A plan on a YAML frame file whose frame name has a local tag",
                                  "A validate of a ROS map saved with CRLF line ends"])
def test_picked_hostile29_cases_end_cleanly(name: str, monkeypatch: pytest.MonkeyPatch) -> None:
    """Each but the last failed before this round: --data to the held-out suite ran it whole (60 s, a hang), 5,000
    digits in a corpus and a PGM header were ValueError tracebacks, a YAML tag was passed over, a text PGM's -2 was
    read as a pixel. The last, a researcher's map saved on Windows, is read as it comes. This tree's code; none
    needs ../shared but the corpus, which fails at its line before the scorer is run."""
    monkeypatch.setenv("PYTHONPATH", str(Path(__file__).resolve().parents[2]))
    case = next(c for c in hostile29_cases() if c.name == name)
    assert run_case(case).problems == []


def test_the_hostile29_cases_are_named_once_and_say_what_they_must() -> None:
    found = list(hostile29_cases())
    assert len({c.name for c in found}) == len(found) >= 70
    assert all(c.says for c in found if c.codes in ((0,), (1,)))
    assert sum("ROS map" in c.name for c in found) >= 30
    assert {c.name for c in found} <= {c.name for c in _attacker()}


@pytest.mark.parametrize("name", ["A import-bag -o onto its bag folder's metadata.yaml",
                                  "A import-bag of a bag folder whose metadata.yaml counts in 5,000 digits",
                                  "A import-bag of a bag folder whose metadata.yaml starts with a BOM"])
def test_picked_hostile29_bag_cases_end_cleanly(name: str, monkeypatch: pytest.MonkeyPatch) -> None:
    """The first replaced the bag's metadata, the second said a Python limit naming no line; the third is read."""
    pytest.importorskip("rosbags")
    monkeypatch.setenv("PYTHONPATH", str(Path(__file__).resolve().parents[2]))
    case = next(c for c in hostile29_bag_cases() if c.name == name)
    assert run_case(case).problems == []


def test_the_hostile29_environment_cases_are_named_once_and_say_what_they_must() -> None:
    found = list(hostile29_environment_cases())
    assert len({c.name for c in found}) == len(found) >= 19 and all(c.env for c in found if "--jobs" not in c.name)
    assert all(c.says for c in found if c.codes in ((0,), (1,)))
    assert {c.name for c in found} <= {c.name for c in _attacker()}


@pytest.mark.parametrize(("batch", "name"), [
    (hostile30_leftover_cases, "A validate of a ROS map whose negate is tagged !!bool on a 0"),
    (hostile30_leftover_cases, "A bench parse --corpus whose line says text twice"),
    (hostile30_leftover_cases, "A validate of a ROS map whose PGM has bytes after its pixels"),
    (hostile30_leftover_cases, "A plan whose --done is a question (where is the cup?)"),
    (hostile30_leftover_cases, "A bench tasks --episodes into /proc"),
    (hostile30_cases, "A validate of a map whose resolution is a word and has no image"),
    (hostile30_cases, "A plan --framelib of a folder holding a FIFO named .frame"),
    (hostile30_cases, "A localize --observations whose detection's class holds a NUL"),
    (hostile30_cases, "A localize --task of a zero-width joiner alone"),
    (hostile30_output_cases, "A import-bag of a FIFO named .mcap"),
])
def test_picked_hostile30_cases_end_cleanly(batch: object, name: str, monkeypatch: pytest.MonkeyPatch) -> None:
    """Each failed before this round: !!bool 0 was a KeyError traceback, a key said twice was taken silently, bytes
    after a P5's pixels were passed over, /proc was "No such file or directory", resolution: abc passed unread, a
    FIFO in a frame folder was passed over, a NUL class was printed raw, --task was not named, import-bag of a FIFO
    hung; the question as --done is read as the question answered (found(cup)), as documented. This tree's code."""
    if "bag" in name:
        pytest.importorskip("rosbags")
    monkeypatch.setenv("PYTHONPATH", str(Path(__file__).resolve().parents[2]))
    case = next(c for c in batch() if c.name == name)  # type: ignore[operator]
    assert run_case(case).problems == []


def test_the_hostile30_cases_are_named_once_and_say_what_they_must() -> None:
    found = [*hostile30_leftover_cases(), *hostile30_cases(), *hostile30_output_cases()]
    assert len({c.name for c in found}) == len(found) >= 80
    assert all(c.says for c in found if c.codes in ((0,), (1,)))
    assert sum("tagged" in c.name for c in found) >= 10 and sum("twice" in c.name for c in found) >= 6
    assert {c.name for c in found} <= {c.name for c in _attacker()}
