"""Nothing lost, nothing hangs, every problem listed (issue 14): outputs never destroy inputs,
readers refuse what would hang them, and a few hostile cases of ``seal bench reliability`` run
for real. The whole hostile suite (hundreds of cases) is ``seal bench reliability``."""

from __future__ import annotations

import os
import signal
import stat
from pathlib import Path

import pytest
import yaml
from typer.testing import CliRunner

from seal_cli.bench.reliability import Case, generated_cases, hostile_cases, issue_cases, run_case, summarise
from seal_cli.bench.reliability_review import cases, review_cases
from seal_cli.cli import app
from seal_cli.errors import SealError
from seal_cli.fileio import LOADER, Outputs, read_bytes, read_text, split_lines
from seal_cli.frames.formats import dsl
from seal_cli.yamlnodes import check_size

runner = CliRunner()


# -- outputs ------------------------------------------------------------------------------------
def test_an_output_that_is_an_input_is_refused_by_path_link_and_inode(tmp_path: Path) -> None:
    source = tmp_path / "m.yaml"
    source.write_text("kept")
    (tmp_path / "link.png").symlink_to(source)
    os.link(source, tmp_path / "hard.png")
    for target in (source, tmp_path / "link.png", tmp_path / "hard.png", tmp_path / "sub" / ".." / "m.yaml"):
        (tmp_path / "sub").mkdir(exist_ok=True)
        with pytest.raises(SealError, match="would overwrite the input"):
            Outputs({"--png": target}, [source])
    assert source.read_text() == "kept"
    assert sorted(p.name for p in tmp_path.iterdir()) == ["hard.png", "link.png", "m.yaml", "sub"]


def test_a_file_read_earlier_counts_as_an_input(tmp_path: Path) -> None:
    source = tmp_path / "notes.png"
    source.write_text("read")
    read_text(source)
    with pytest.raises(SealError, match=f"would overwrite the input {source}"):
        Outputs({"--png": source})


def test_two_outputs_may_not_be_one_file(tmp_path: Path) -> None:
    with pytest.raises(SealError, match="--rrd and --png name the same file"):
        Outputs({"--png": tmp_path / "o", "--rrd": tmp_path / "o"})
    assert list(tmp_path.iterdir()) == []


@pytest.mark.parametrize(("target", "message"), [("o.jpg", "give a name ending in .png, not .jpg"),
                                                 ("missing/o.png", "folder .* does not exist"),
                                                 (".", "it is a folder")])
def test_wrong_targets_are_refused_before_any_work(tmp_path: Path, target: str, message: str) -> None:
    with pytest.raises(SealError, match=message):
        Outputs({"--png": tmp_path / target}, suffixes={"--png": (".png",)})
    assert list(tmp_path.iterdir()) == []


def test_all_outputs_or_none(tmp_path: Path) -> None:
    with pytest.raises(RuntimeError), Outputs({"--png": tmp_path / "a.png", "--rrd": tmp_path / "a.rrd"}) as plan:
        plan["--png"].write_bytes(b"png")
        assert len(list(tmp_path.iterdir())) == 2  # the temporaries, reserved at once
        raise RuntimeError("the run failed")
    assert list(tmp_path.iterdir()) == []
    with Outputs({"--png": tmp_path / "a.png", "--rrd": tmp_path / "a.rrd"}) as plan:
        plan["--png"].write_bytes(b"png")
        plan["--rrd"].write_bytes(b"rrd")
    assert sorted(p.name for p in tmp_path.iterdir()) == ["a.png", "a.rrd"]
    assert (tmp_path / "a.rrd").read_bytes() == b"rrd"


def test_a_device_is_written_in_place_not_replaced() -> None:
    with Outputs({"--png": "/dev/null", "--rrd": "/dev/null"}, suffixes={"--png": (".png",)}) as plan:
        plan["--png"].write_bytes(b"x" * 1000)
    assert stat.S_ISCHR(os.stat("/dev/null").st_mode)


def test_a_named_pipe_nobody_reads_is_refused_not_waited_on(tmp_path: Path) -> None:
    os.mkfifo(tmp_path / "p.png")
    with pytest.raises(SealError, match="named pipe that no process reads"):
        Outputs({"--png": tmp_path / "p.png"})


def test_stale_temporaries_of_dead_runs_are_swept_live_ones_kept(tmp_path: Path) -> None:
    dead = tmp_path / ".o.png.seal999999999-0123abcd.tmp.png"
    live = tmp_path / f".o.png.seal{os.getppid()}-0123abcd.tmp.png"
    dead.write_bytes(b"half")
    live.write_bytes(b"being written")
    with Outputs({"--png": tmp_path / "o.png"}) as plan:
        plan["--png"].write_bytes(b"whole")
    assert not dead.exists() and live.exists() and (tmp_path / "o.png").read_bytes() == b"whole"


def test_plan_pddl_writes_both_files_or_neither(tmp_path: Path) -> None:
    (tmp_path / "problem.pddl").mkdir()
    result = runner.invoke(app, ["plan", "--pddl", str(tmp_path), "stir the cup"])
    assert result.exit_code == 1 and "problem.pddl" in result.stderr and "it is a folder" in result.stderr
    assert sorted(p.name for p in tmp_path.iterdir()) == ["problem.pddl"]


# -- readers ------------------------------------------------------------------------------------
def test_special_files_are_refused_by_kind_before_opening(tmp_path: Path) -> None:
    os.mkfifo(tmp_path / "pipe.yaml")
    with pytest.raises(SealError, match="it is a FIFO"):
        read_text(tmp_path / "pipe.yaml")
    with pytest.raises(SealError, match="it is a character device"):
        read_bytes("/dev/zero")


def test_files_over_the_bound_are_refused(tmp_path: Path) -> None:
    big = tmp_path / "big.txt"
    big.write_bytes(b"x" * 2000)
    with pytest.raises(SealError, match="seal reads files of at most 1000 bytes"):
        read_text(big, limit=1000)


def test_lines_are_split_on_newlines_only() -> None:
    text = "a\u2028b\x0bc\rd\x1ce\x85f\nsecond\r\nthird"
    assert split_lines(text) == ["a\u2028b\x0bc\rd\x1ce\x85f", "second", "third"]


def test_a_bom_is_dropped_and_bad_utf8_is_located(tmp_path: Path) -> None:
    path = tmp_path / "c.txt"
    path.write_bytes(b"\xef\xbb\xbfstir\nok\nbad \xff\n")
    with pytest.raises(SealError) as caught:
        read_text(path)
    assert (caught.value.line, caught.value.column) == (3, 5)
    path.write_bytes(b"\xef\xbb\xbfstir\n")
    assert read_text(path) == "stir\n"


def test_yaml_aliases_are_bounded_and_may_not_hold_themselves() -> None:
    bomb = "a: &a [1, 2, 3, 4, 5, 6, 7, 8, 9, 10]\n" + "".join(
        f"{chr(98 + i)}: &{chr(98 + i)} [{', '.join([f'*{chr(97 + i)}'] * 10)}]\n" for i in range(6))
    with pytest.raises(SealError, match="more than 1,000,000 values"):
        check_size(yaml.compose(bomb, Loader=LOADER), "bomb.yaml")
    with pytest.raises(SealError, match="refers to a value that holds it"):
        check_size(yaml.compose("&a [*a]", Loader=LOADER), "self.yaml")
    check_size(yaml.compose("a: &a [1]\nb: [*a, *a]", Loader=LOADER), "fine.yaml")


# -- every problem, in words ----------------------------------------------------------------------
def test_one_syntax_error_hides_no_other_problem() -> None:
    text = ('category thing = *\nframe A "a" {\n  x: thing\n  requires p(x) q(x)\n}\n'
            'frame B "b" {\n  x thingy\n}\nframe C "c" {\n  x: thingy\n}\nworld 5\n')
    problems = dsl.read(text, "f.frame").problems
    assert [(p.line, p.message.split(" (")[0]) for p in problems] == [
        (4, "syntax error: a comma is missing between two facts or actions"),
        (7, "syntax error: an element is written 'role: category'"),
        (12, "syntax error: unexpected '5'; expected a name")]
    assert [f.name for f in dsl.read(text, "f.frame").frames] == ["C"]


@pytest.mark.parametrize(("bad", "says"), [
    ("\t", "a quoted string may not hold"),
    ("\x00", "a frame file may not hold the control character '\\x00'"),     # anywhere in the file (hostile31)
    ("\\q", "a quoted string may not hold"),
])
def test_a_bad_character_in_a_quoted_string_is_a_located_problem(bad: str, says: str) -> None:
    problems = dsl.read(f'frame A "wh{bad}isk" {{\n}}\n', "f.frame").problems
    assert len(problems) == 1 and problems[0].line == 1 and problems[0].column == 12
    assert says in problems[0].message


# -- the hostile suite, a few cases for real --------------------------------------------------------
def test_the_suite_holds_the_issue_and_at_least_300_generated_cases() -> None:
    generated = list(generated_cases(0, 320))
    assert len(generated) == 320 and len({c.name for c in generated}) == 320
    assert len(list(issue_cases())) >= 40
    assert [c.argv for c in generated_cases(5, 20)] == [c.argv for c in generated_cases(5, 20)]
    written = list(hostile_cases())
    assert len(written) >= 100 and len({c.name for c in written}) == len(written)
    assert {c.name for c in written}.isdisjoint(c.name for c in issue_cases())
    reviewed = list(review_cases())
    assert len(reviewed) >= 120 and len({c.name for c in reviewed}) == len(reviewed)
    assert {c.name for c in reviewed}.isdisjoint(c.name for c in [*written, *issue_cases()])
    assert sum(c.says is not None for c in reviewed) >= 100  # most say what the message must name


PICKED = ("1 localize --png onto the map", "1 an output hard-linked to the image", "3 put 99999999999 apples",
          f"5 {signal.SIGTERM.name} during localize --png --rrd", "5 a stale temporary of a killed run is swept",
          "H three map --png at once onto one file", "H map through a link loop", "H map path with a newline",
          "H option run apartment --max-metres nan", "H option bench map --layouts 99999999999999999999",
          "H encoding utf-16: validate", "H a folder for a file: map map d.yaml",
          "R a NUL byte in the observations", "R stdin closed: parse --file -", "R stdout /dev/full: validate",
          "R a path of 300 characters", "R seal run --map 'apartmnt'", "R map image: 100,000 by 100,000 declared",
          "R frame YAML: a category member of 0x10", "R an output onto an input: --episodes hard-linked to the map")


@pytest.mark.parametrize("name", PICKED)
def test_hostile_cases_end_cleanly(name: str) -> None:
    case = next(c for c in cases(0, 0) if c.name == name)
    outcome = run_case(case)
    assert outcome.problems == []
    assert summarise([outcome])["tried"] == 1


def test_the_judge_sees_a_partial_output_and_a_wrong_code(tmp_path: Path) -> None:
    """The suite's own checks can fail: a whole file is required, a wrong exit code is counted."""
    broken = Case("judge", ("validate", "f.frame"), (("f.frame", b"frame {"), ("o.png", b"\x89PNG\r\n\x1a\nhalf")),
                  codes=(0,), whole=("o.png",))
    outcome = run_case(broken)
    assert outcome.kinds == {"exit", "partial"}


def test_the_judge_limits_files_and_makes_stdout_a_full_non_blocking_pipe(monkeypatch: pytest.MonkeyPatch) -> None:
    """hostile20's settings: ``file_blocks`` limits what the command may write (a file or its stdout), and a
    non-blocking stdout is read whole once the command waits on it; what the command printed is what was read."""
    monkeypatch.setenv("PYTHONPATH", str(Path(__file__).resolve().parents[1]))  # this tree's code
    capped = Case("judge", ("frames", "--json"), (("stdout.out", b""),), codes=(0,), stream="file-stdout",
                  file_blocks=4)
    assert run_case(capped).kinds == {"exit"}  # 2 KiB of 18 KiB: the command fails (exit code 1), as it must
    lines = "".join(f"stir the cup number {i}\n" for i in range(2_500)) + "put the apple on the table\n"
    piped = Case("judge", ("parse", "--file", "c.txt"), (("c.txt", lines.encode()),), codes=(0,),
                 stream="nonblocking-stdout", says=r"\n2501: Place\(theme=apple, goal=table\)\n$")
    assert run_case(piped).problems == []
    missing = Case("judge", piped.argv, piped.files, codes=(0,), stream="nonblocking-stdout", says=r"\n2502: ")
    assert run_case(missing).kinds == {"message"}


def test_the_judge_sees_an_unclear_message() -> None:
    """A refusal must say what the case says it must (``says``), and say something."""
    vague = Case("judge", ("validate", "f.frame"), (("f.frame", b"frame {"),), codes=(1,), says=r"nowhere\.txt:\d+")
    assert run_case(vague).kinds == {"message"}
    silent = Case("judge", ("map", "nope.yaml"), codes=(1,), stream="closed-stderr")
    assert run_case(silent).problems == []  # stderr closed: nothing can be said, nothing is asked


def test_a_case_starts_with_the_signals_its_judge_was_started_ignoring(monkeypatch: pytest.MonkeyPatch) -> None:
    """Started in a shell's background (``nohup ... &``), the judge ignores SIGINT and SIGHUP and passed them ignored
    to every case: "a signal 2 while run --png --rrd writes its temporary" ran to its end, 10 times in 10
    (hostile25). A case now starts with them at their default, unless it asks for them ignored (``Case.ignored``);
    the judge itself still ignores them."""
    import sys

    import seal_cli.bench.reliability as judge

    shows = ("import signal; print('SIGINT', signal.getsignal(signal.SIGINT) is signal.default_int_handler, "
             "'SIGHUP ignored', signal.getsignal(signal.SIGHUP) == signal.SIG_IGN)")
    monkeypatch.setattr(judge, "_seal", lambda: [sys.executable, "-c", shows])
    before = {n: signal.signal(n, signal.SIG_IGN) for n in (signal.SIGINT, signal.SIGHUP)}
    try:
        plain = judge.run_cases([Case("defaults", (), codes=(0,), says=r"SIGINT True SIGHUP ignored False")])
        nohup = judge.run_case(Case("nohup", (), codes=(0,), ignored=(1,),
                                    says=r"SIGINT True SIGHUP ignored True"))
        assert signal.getsignal(signal.SIGINT) == signal.SIG_IGN == signal.getsignal(signal.SIGHUP)
    finally:
        for number, handler in before.items():
            signal.signal(number, handler)
    assert plain[0].problems == [] and nohup.problems == []


def test_a_case_s_folder_vanishes_once_the_command_writes_into_it(monkeypatch: pytest.MonkeyPatch) -> None:
    """``Case.vanish``: the folder is removed, with what it holds, once a file matching the pattern is in it, while
    the command runs (a folder deleted under ``run --png d/o.png``, hostile26); a command that never writes there
    keeps it."""
    import sys

    import seal_cli.bench.reliability as judge

    script = ("import os, sys, time; open('d/.o.seal1-0123abcd.tmp', 'w').close(); deadline = time.time() + 5\n"
              "while os.path.isdir('d') and time.time() < deadline: time.sleep(0.01)\n"
              "sys.exit(1 if os.path.isdir('d') else 0)")
    monkeypatch.setattr(judge, "_seal", lambda: [sys.executable, "-c", script])
    gone = judge.run_case(judge.Case("a folder removed", (), (("d", "dir"),), codes=(0,),
                                     vanish=("d", r"\.seal\d+-[0-9a-f]{8}\.tmp")))
    assert gone.code == 0 and gone.problems == []
    kept = judge.run_case(judge.Case("a folder never written into", (), (("d", "dir"),), codes=(0,),
                                     vanish=("d", r"never"), timeout=30))
    assert kept.code == 1


def test_the_judge_counts_what_a_case_must_not_say(tmp_path: Path) -> None:
    # Case.unsaid (hostile28): a Python warning naming seal's source, on a run that succeeded
    said = Case("said", ("parse", "go to the kitchen"), codes=(0,), says=r"Go", unsaid=r"Go")
    assert [p.split(":")[0] for p in run_case(said).problems] == ["message"]
    assert run_case(Case("quiet", ("parse", "go to the kitchen"), codes=(0,), says=r"Go", unsaid=r"Warning: ")
                    ).problems == []


def test_the_judge_can_run_a_command_in_a_deleted_working_folder() -> None:
    # Case.remove_cwd (hostile28): `cd d; rm -r ../d; seal ...`
    case = Case("gone", ("parse", "--file", "c.txt"), (("d", "dir"),), codes=(1,), cwd="d", remove_cwd=True,
                says=r"working folder has been deleted")
    assert run_case(case).problems == []
