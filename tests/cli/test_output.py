"""cli/output: the failures every command shares become one message and an exit code."""

from __future__ import annotations

import errno
import subprocess
import sys

import pytest

from seal_cli.cli.output import run_command


def _raise(error: BaseException) -> int:
    raise error


def test_an_os_error_naming_a_file_is_one_message(capsys: pytest.CaptureFixture[str]) -> None:
    error = OSError(errno.ENAMETOOLONG, "File name too long", "x" * 300)
    assert run_command(lambda: _raise(error)) == 1
    assert capsys.readouterr().err.strip() == f"error: {'x' * 300}: File name too long"


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
