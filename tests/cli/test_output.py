"""cli/output: the failures every command shares become one message and an exit code."""

from __future__ import annotations

import errno
import os
import subprocess
import sys
from pathlib import Path

import pytest

from seal_cli.cli.output import plain, run_command, styled


def _raise(error: BaseException) -> int:
    raise error


def test_an_os_error_naming_a_file_is_one_message(capsys: pytest.CaptureFixture[str]) -> None:
    error = OSError(errno.ENAMETOOLONG, "File name too long", "x" * 300)
    assert run_command(lambda: _raise(error)) == 1
    assert capsys.readouterr().err.strip() == f"error: {'x' * 198}…: File name too long"  # a long name cut (hostile14)


def test_a_full_disk_under_stdout_is_one_message_and_exit_1() -> None:
    with open("/dev/full", "w") as full:
        done = subprocess.run([sys.executable, "-m", "seal_cli", "map", "apartment", "--json"], stdout=full,
                              stderr=subprocess.PIPE, text=True, check=False)
    assert done.returncode == 1
    assert done.stderr == "error: cannot write the output: No space left on device\n"


@pytest.mark.parametrize(("argv", "code", "said"), [
    (["frames"], 0, ""),                      # stdout closed: what it prints is lost, as asked
    (["parse", "--json", "stir the cup"], 0, ""),
])
def test_a_closed_stdout_is_no_traceback(argv: list[str], code: int, said: str) -> None:
    done = subprocess.run(["/bin/sh", "-c", 'exec "$@" >&-', "sh", sys.executable, "-m", "seal_cli", *argv],
                          stderr=subprocess.PIPE, text=True, check=False)
    assert (done.returncode, done.stderr) == (code, said)


def test_a_closed_stdin_is_a_message_for_parse_file_dash() -> None:
    done = subprocess.run(["/bin/sh", "-c", 'exec "$@" <&-', "sh", sys.executable, "-m", "seal_cli", "parse",
                           "--file", "-"], capture_output=True, text=True, check=False)
    assert done.returncode == 1
    assert done.stderr == "error: --file -: standard input is closed; pipe the commands in, or give a file\n"


class _Interrupting:
    """A stdout whose flush is interrupted (SIGINT just after the command's work)."""

    encoding = "utf-8"

    def write(self, text: str) -> int:
        return len(text)

    def flush(self) -> None:
        raise KeyboardInterrupt


def test_an_interrupt_after_the_command_finished_keeps_its_code(monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setattr(sys, "stdout", _Interrupting())
    assert run_command(lambda: 0) == 0  # its outputs were in place: not 130 with a file written
    assert run_command(lambda: _raise(KeyboardInterrupt())) == 130


def test_sigint_while_seal_imports_is_no_traceback() -> None:
    code = ("import sys, seal_cli.__main__ as m, seal_cli.cli as c\n"
            "def stop(): raise KeyboardInterrupt\n"
            "c.main = stop\nsys.argv = ['seal', 'frames']\nm.main()\n")
    done = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=False)
    assert (done.returncode, done.stderr) == (130, "interrupted\n")


@pytest.mark.parametrize("encoding", ["ascii", "latin-1"])
def test_an_output_that_cannot_hold_a_character_escapes_it(encoding: str) -> None:
    import json
    import os

    env = {**os.environ, "PYTHONIOENCODING": encoding}
    for argv in (["parse", "stir the café 😀"], ["plan", "stir the cup"], ["map", "apartment"], ["frames", "Stir"]):
        done = subprocess.run([sys.executable, "-m", "seal_cli", *argv], capture_output=True, env=env, check=False)
        assert b"Traceback" not in done.stderr and done.returncode in (0, 1), argv
    done = subprocess.run([sys.executable, "-m", "seal_cli", "parse", "--json", "bring Zoë a café"],
                          capture_output=True, env=env, check=False)
    assert done.returncode == 0 and done.stdout.isascii()
    assert json.loads(done.stdout)["text"] == "bring Zoë a café"  # escaped as JSON escapes: the same JSON


def test_an_import_failing_under_an_interrupt_is_the_interrupt(monkeypatch: pytest.MonkeyPatch) -> None:
    from seal_cli import fileio

    failed = ImportError("initialization failed")  # what SIGINT inside matplotlib's ft2font import raises
    monkeypatch.setattr(fileio, "_INTERRUPTED", [False])
    with pytest.raises(ImportError):
        run_command(lambda: _raise(failed))  # a real failure stays one

    def interrupted_import() -> None:
        fileio._INTERRUPTED[0] = True  # SIGINT arrived during the command (a flag left by an earlier one is reset)
        _raise(failed)

    assert run_command(interrupted_import) == 130


def test_an_interrupt_while_the_outputs_move_ends_with_them_in_place_and_success(
        tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    """SIGINT between an output's rename and the command's return was exit 130 with the file written
    ("R SIGINT during import-bag -o", now and then): the signal waits while the outputs move."""
    import os
    import signal

    from seal_cli import fileio
    from seal_cli.cli.output import run_command

    moved = fileio._move

    def move_then_interrupt(output: object) -> None:
        moved(output)  # type: ignore[arg-type]
        os.kill(os.getpid(), signal.SIGINT)  # held: it arrives once the commit is recorded

    monkeypatch.setattr(fileio, "_move", move_then_interrupt)
    monkeypatch.setattr(fileio, "_INTERRUPTED", [False])
    # SIGINT as a terminal's: a shell without job control starts `cmd &` with SIGINT ignored (a CI run in the
    # background), and then no interrupt would arrive at all
    before = signal.signal(signal.SIGINT, signal.default_int_handler)
    target = tmp_path / "o.yaml"

    def command() -> int:
        with fileio.Outputs({"-o": target}) as plan:
            plan["-o"].write_text("poses: []\n")
        raise AssertionError("the interrupt arrives before the command goes on")

    try:
        assert run_command(command) == 0
        assert target.read_text() == "poses: []\n" and fileio.committed()
        assert run_command(lambda: 0) == 0 and not fileio.committed()  # the next command starts afresh
    finally:
        signal.signal(signal.SIGINT, before)


def test_plain_text_prints_as_written() -> None:
    from rich.console import Console

    console = Console(record=True, width=200, color_system=None)
    for name in ("[/]bed[bold]x", "a\\[/]", "x\\", "[red]", "$x^$"):
        console.print(plain(name))
        assert console.export_text().rstrip("\n") == name
    for name, shown in (("bed\x1b[31mroom\r", "bed\\x1b[31mroom\\r"), ("\x1b[bold]x\x9b", "\\x1b[bold]x\\x9b")):
        console.print(plain(name))   # an escape sequence from a file never reaches the terminal
        assert console.export_text().rstrip("\n") == shown
        console.print(styled("bold", name))
        assert console.export_text().rstrip("\n") == shown


MARKUP_ROOM = "[/]bed[bold]x"
"""A room name rich read as markup: ``seal map`` failed with a MarkupError traceback (hostile16)."""


def _map_with(tmp_path: Path, old: str, new: str) -> Path:
    from seal_cli.resources import map_path

    text = map_path("apartment").read_text(encoding="utf-8")
    assert old in text
    (tmp_path / "apartment.pgm").write_bytes(map_path("apartment").with_suffix(".pgm").read_bytes())
    path = tmp_path / "m.yaml"
    path.write_text(text.replace(old, new), encoding="utf-8")
    return path


@pytest.mark.parametrize("argv", [
    ["map", "{map}"],
    ["localize", "--map", "{map}", "--task", "find the spoon", "--steps", "1", "--particles", "20"],
    ["run", "--map", "{map}", "find the spoon", "--max-steps", "60", "--particles", "50"],   # the names, not the search
])
@pytest.mark.parametrize("room", [MARKUP_ROOM, ":pile_of_poo:"])   # rich's markup; rich's emoji code (shown as 💩)
def test_names_from_a_map_are_printed_as_written(tmp_path: Path, argv: list[str], room: str) -> None:
    # the map's own name: a room's can hold no '[' or ':' since hostile22 (no plan could name such a room)
    m = _map_with(tmp_path, "name: apartment", f"name: '{room}'")
    done = subprocess.run([sys.executable, "-m", "seal_cli", *(a.format(map=m) for a in argv)], capture_output=True,
                          text=True, check=False, env={**os.environ, "NO_COLOR": "1", "COLUMNS": "250"})
    assert "Traceback" not in done.stderr
    assert done.returncode in (0, 1), done.stderr
    if argv[0] != "run":    # run narrates rooms and places, not the map's name
        assert room in done.stdout


def test_a_frame_described_in_markup_is_shown_as_written(tmp_path: Path) -> None:
    library = tmp_path / "zap.yaml"
    library.write_text("frame: Zap\ndescription: '[/] zap [bold]'\nlexical_units: [zap]\n"
                       "elements: {theme: {type: object}}\nactions: [navigate(theme)]\n"
                       "postconditions: [looked_at(theme)]\n", encoding="utf-8")
    done = subprocess.run([sys.executable, "-m", "seal_cli", "frames", "--framelib", f"+{library}", "Zap"],
                          capture_output=True, text=True, check=False)
    assert done.returncode == 0, done.stderr
    assert "[/] zap [bold]" in done.stdout


@pytest.mark.parametrize(("environ", "after"), [
    ({"COLUMNS": "1000000000"}, {"COLUMNS": "1000"}),
    ({"COLUMNS": "1" * 5_000, "LINES": "9" * 5_000}, {"COLUMNS": "1000", "LINES": "1000"}),
    ({"TERMINAL_WIDTH": "abc", "COLUMNS": "0", "LINES": "-3"}, {}),
    ({"COLUMNS": " 120 ", "LINES": "40", "TERMINAL_WIDTH": "1000"}, {"COLUMNS": " 120 ", "LINES": "40",
                                                                     "TERMINAL_WIDTH": "1000"}),
    ({"COLUMNS": "1", "LINES": "1", "TERMINAL_WIDTH": "39"}, {"COLUMNS": "40", "LINES": "1", "TERMINAL_WIDTH": "40"}),
])
def test_screen_sizes_no_one_can_draw_are_bounded_or_dropped(environ: dict[str, str], after: dict[str, str]) -> None:
    from seal_cli.cli.output import sane_sizes

    sane_sizes(environ)
    assert environ == after


@pytest.mark.parametrize(("name", "value"), [("COLUMNS", "1000000000"), ("TERMINAL_WIDTH", "abc"),
                                             ("COLUMNS", "1" * 5_000), ("LINES", "1" * 5_000)])
def test_help_and_usage_errors_under_a_hostile_screen_size(name: str, value: str) -> None:
    # a billion columns: 8.8 GB and no end; 'abc' (typer's int()) and 5,000 digits (rich's): tracebacks (hostile16)
    env = {**os.environ, name: value}
    for argv in (["--help"], ["localize", "--steps", "x"], ["map", "apartment"]):
        done = subprocess.run([sys.executable, "-m", "seal_cli", *argv], capture_output=True, text=True,
                              check=False, env=env, timeout=60)
        assert "Traceback" not in done.stderr and done.returncode in (0, 2), done.stderr[-500:]
        assert len(done.stdout) + len(done.stderr) < 100_000


def test_a_table_under_columns_1_shows_its_words() -> None:
    """hostile19: `COLUMNS=1 seal frames` drew the table's borders alone, not one letter of what it holds."""
    import os
    import subprocess
    import sys

    environ = {k: v for k, v in os.environ.items() if k not in ("TERMINAL_WIDTH", "NO_COLOR")} | {"COLUMNS": "1"}
    shown = subprocess.run([sys.executable, "-m", "seal_cli", "frames"], capture_output=True, text=True, env=environ,
                           timeout=120, check=True).stdout
    assert "Heat" in shown and "Stir" in shown


@pytest.mark.parametrize(("args", "code"), [
    (["validate", "tests/data/maps_bad"], 1), (["validate", "tests/data/maps_bad", "--json"], 1),
    (["validate", "maps"], 0), (["frames"], 0), (["frames", "--json"], 0),
])
def test_a_reader_gone_leaves_the_commands_own_exit_code(args: list[str], code: int) -> None:
    """hostile19: `seal validate BAD | head -1` exited 1 with no message as a table (rich's SystemExit(1)) and 0 as
    JSON; a command whose reader has gone now drops the rest of its output and ends as it would have."""
    import os
    import subprocess
    import sys

    read, write = os.pipe()
    os.close(read)  # the reader has gone before the first byte
    try:
        done = subprocess.run([sys.executable, "-m", "seal_cli", *args], stdout=write, stderr=subprocess.PIPE,
                              timeout=300, check=False)
    finally:
        os.close(write)
    assert done.returncode == code, done.stderr
    assert b"Traceback" not in done.stderr and b"Exception ignored" not in done.stderr


_SEAL = Path(__file__).resolve().parents[2]


@pytest.mark.parametrize("unbuffered", ["1", None])
@pytest.mark.parametrize("argv", [["frames", "--json"], ["frames"]])
def test_stdout_past_ulimit_f_fails_the_command(tmp_path: Path, unbuffered: str | None, argv: list[str]) -> None:
    # under PYTHONUNBUFFERED=1 Python's stream dropped what a short write left: 2 KiB of the output, exit 0 (hostile20)
    env = {**os.environ, "PYTHONPATH": str(_SEAL)}
    env.pop("PYTHONUNBUFFERED", None)
    if unbuffered:
        env["PYTHONUNBUFFERED"] = unbuffered
    with open(tmp_path / "out", "wb") as out:
        done = subprocess.run(["/bin/sh", "-c", 'ulimit -f 4; exec "$@"', "sh",  # POSIX sh: 512-byte blocks
                               sys.executable, "-m", "seal_cli", *argv], stdout=out, stderr=subprocess.PIPE,
                              text=True, env=env, check=False)
    assert (done.returncode, done.stderr) == (1, "error: cannot write the output: File too large\n")
    assert (tmp_path / "out").stat().st_size == 2048


def test_whole_writes_writes_everything_into_a_full_non_blocking_pipe() -> None:
    # into a pipe its parent had made non-blocking, a write stopped at 64 KiB (a short write, then EAGAIN): exit 0 with
    # the rest dropped (PYTHONUNBUFFERED=1) or exit 1 (hostile20); now it waits until the reader takes more
    import io
    import threading
    import time

    from seal_cli.cli import output

    reader, writer = os.pipe()
    os.set_blocking(writer, False)
    received = bytearray()

    def read_late() -> None:
        time.sleep(0.2)  # the pipe is full by then
        while chunk := os.read(reader, 1 << 16):
            received.extend(chunk)

    thread = threading.Thread(target=read_late)
    thread.start()
    try:
        raw = output._WholeWrites(writer, "w", closefd=False)
        assert raw.write(b"0123456789" * 30_000) == 300_000
        text = io.TextIOWrapper(raw, encoding="utf-8", write_through=True)  # type: ignore[arg-type]
        text.write("café\n" * 20_000)
        text.flush()
    finally:
        os.close(writer)
        thread.join()
        os.close(reader)
    assert bytes(received) == b"0123456789" * 30_000 + "café\n".encode() * 20_000


def test_whole_writes_replaces_only_the_interpreters_own_streams(monkeypatch: pytest.MonkeyPatch) -> None:
    import io

    from seal_cli.cli import output

    captured = io.StringIO()
    monkeypatch.setattr(sys, "stdout", captured)
    output.whole_writes()
    assert sys.stdout is captured  # a test's capture (or any stream not on a file descriptor) is left alone


def _seal_into(stdout: int | str, *argv: str) -> subprocess.CompletedProcess[str]:
    """seal's ``argv`` with standard output onto ``stdout``: a file descriptor, ``"closed"`` or ``"gone"`` (a pipe
    whose reader has gone before the first byte)."""
    if stdout == "closed":
        return subprocess.run(["/bin/sh", "-c", 'exec "$@" >&-', "sh", sys.executable, "-m", "seal_cli", *argv],
                              stderr=subprocess.PIPE, text=True, timeout=120, check=False)
    write = stdout if isinstance(stdout, int) else os.pipe()
    if isinstance(write, tuple):
        os.close(write[0])
        write = write[1]
    try:
        return subprocess.run([sys.executable, "-m", "seal_cli", *argv], stdout=write, stderr=subprocess.PIPE,
                              text=True, timeout=120, check=False)
    finally:
        if not isinstance(stdout, int):
            os.close(write)


@pytest.mark.parametrize("argv", [["--help"], ["-h"], ["map", "--help"], ["bench", "tasks", "--help"], ["--version"]])
def test_help_and_version_onto_a_full_disk_closed_or_gone_output(argv: list[str]) -> None:
    """hostile21: typer's help (every command's) onto /dev/full was an OSError traceback out of rich, and into a reader
    that had gone exit 1 with no message; ``--version`` with its stdout closed an AttributeError traceback, onto a full
    disk an OSError one. Now: the message of a command's full disk (exit 1), the help's own exit 0 otherwise."""
    with open("/dev/full", "w") as full:
        done = _seal_into(full.fileno(), *argv)
    assert (done.returncode, done.stderr) == (1, "error: cannot write the output: No space left on device\n")
    for stdout in ("closed", "gone"):
        done = _seal_into(stdout, *argv)
        assert (done.returncode, done.stderr) == (0, ""), (stdout, done.stderr[-500:])


def test_the_framework_still_fails_on_an_error_naming_a_file_and_keeps_a_usage_errors_code() -> None:
    from seal_cli.cli import output

    def named() -> None:
        raise FileNotFoundError(2, "No such file or directory", "x.yaml")

    with pytest.raises(FileNotFoundError):
        output.run_framework(named)

    def usage() -> None:
        raise SystemExit(2)

    with pytest.raises(SystemExit) as ended:
        output.run_framework(usage)
    assert ended.value.code == 2


def test_json_never_echoes_a_byte_of_the_command_line_that_is_not_utf8(monkeypatch: pytest.MonkeyPatch) -> None:
    """hostile21: `parse $'caf\\xe9' --json` echoed the byte back raw (Python's surrogateescape): the JSON was not
    UTF-8. It is now written as the escape \\udce9, and text that is UTF-8 is written as it is."""
    import io
    import json

    from seal_cli.cli.output import dump_json

    monkeypatch.setattr(sys, "stdout", io.TextIOWrapper(io.BytesIO(), encoding="utf-8"))
    text = dump_json({"text": "stir the caf\udce9"})
    assert text == '{"text": "stir the caf\\udce9"}' and json.loads(text)["text"] == "stir the caf\udce9"
    text.encode("utf-8")
    assert dump_json({"text": "café"}) == '{"text": "café"}'


@pytest.mark.parametrize(("argv", "code"), [([], 2), (["bench"], 2), (["bench", "-h"], 0)])
def test_help_shown_for_a_missing_command_keeps_its_code_when_its_reader_has_gone(argv: list[str], code: int) -> None:
    # `seal` alone prints the help and exits 2 (typer's usage error); its reader gone, it is still 2, not 0 (hostile21)
    done = _seal_into("gone", *argv)
    assert (done.returncode, done.stderr) == (code, "")


def test_an_interrupt_ends_the_process_without_freeing_what_it_left_half_built() -> None:
    """SIGINT inside numba's compiling left an llvmlite object half built; freeing it (when the interrupt's traceback
    went) was a segmentation fault, exit -11 (hostile24). Here an object whose freeing crashes the same way."""
    code = ("import ctypes, os, signal, sys, time\n"
            "import seal_cli.__main__ as m, seal_cli.cli as c\n"
            "from seal_cli.cli.output import run_command\n"
            "class HalfBuilt:\n"
            "    def __del__(self): ctypes.string_at(0)\n"
            "def body():\n"
            "    kept = HalfBuilt()\n"
            "    os.kill(os.getpid(), signal.SIGINT)\n"
            "    time.sleep(30)\n"
            "def command(): sys.exit(run_command(body))\n"
            "c.main = command\nsys.argv = ['seal', 'frames']\nm.main()\n")
    done = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=False, timeout=60)
    assert (done.returncode, done.stderr) == (130, "interrupted\n")


def test_a_matplotlib_cache_folder_that_is_none_is_replaced_by_seals(tmp_path: Path) -> None:
    """``MPLCONFIGDIR=/dev/null`` or a file: matplotlib rebuilt its font cache in a new temporary folder on every run,
    saying so in two lines of its own (hostile29). A writable folder, or a name not made yet, is left as given."""
    from seal_cli.cli.output import plot_cache

    (tmp_path / "f").write_text("x", encoding="utf-8")
    for given in ("/dev/null", str(tmp_path / "f")):
        environ = {"MPLCONFIGDIR": given, "SEAL_CACHE_DIR": str(tmp_path / "c")}
        assert plot_cache(environ) == (f"MPLCONFIGDIR {given} is not a folder seal can write: matplotlib's cache is "
                                       f"kept in {tmp_path / 'c' / 'matplotlib'} instead")
        assert environ["MPLCONFIGDIR"] == str(tmp_path / "c" / "matplotlib")
    for given in (str(tmp_path), str(tmp_path / "new")):
        environ = {"MPLCONFIGDIR": given}
        assert plot_cache(environ) is None and environ["MPLCONFIGDIR"] == given
    environ = {"MPLCONFIGDIR": "/dev/null", "SEAL_NO_CACHE": "1"}  # no cache of seal's: matplotlib's own way
    assert plot_cache(environ) is None and environ["MPLCONFIGDIR"] == "/dev/null"
    assert plot_cache({}) is None
