"""``seal bench startup`` and the entry point that answers ``seal --version`` before typer loads."""

from __future__ import annotations

import json
import subprocess
import sys

from typer.testing import CliRunner

from seal_cli.cli import app

runner = CliRunner()


def test_the_fast_version_says_what_the_typer_option_says() -> None:
    fast = subprocess.run([sys.executable, "-m", "seal_cli", "--version"], capture_output=True, text=True, check=True)
    slow = runner.invoke(app, ["--version"])
    assert slow.exit_code == 0 and fast.stdout == slow.stdout == "seal 0.1.0\n"


def test_anything_else_goes_to_the_command_line() -> None:
    run = subprocess.run([sys.executable, "-m", "seal_cli", "--versio"], capture_output=True, text=True)
    assert run.returncode == 2 and "--versio" in run.stderr    # typer's usage error, not the fast path
    run = subprocess.run([sys.executable, "-m", "seal_cli", "parse", "--json", "stir the cup"], capture_output=True,
                         text=True, check=True)
    assert json.loads(run.stdout)["frames"][0]["frame"] == "Stir"


def test_bench_startup_prints_the_ratios() -> None:
    result = runner.invoke(app, ["bench", "startup", "--runs", "1", "--json"])
    assert result.exit_code == 0, result.output
    data = json.loads(result.stdout)
    assert set(data["commands"]) == {"version", "parse"} and data["python_s"] > 0
    for figures in data["commands"].values():
        assert figures["ratio"] == figures["cpu_s"] / data["python_s"] and figures["ok"] == (
            figures["ratio"] <= figures["target"])
    table = runner.invoke(app, ["bench", "startup", "--runs", "1"])
    assert table.exit_code == 0 and "seal --version" in table.stdout and "× python" in table.stdout


def test_bench_startup_refuses_zero_runs() -> None:
    result = runner.invoke(app, ["bench", "startup", "--runs", "0"])
    assert result.exit_code == 2
