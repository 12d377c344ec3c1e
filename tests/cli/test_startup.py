"""``seal bench startup`` and the entry point that answers ``seal --version`` before typer loads."""

from __future__ import annotations

import json
import subprocess
import sys

import pytest
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


def test_bench_startup_prints_the_ratios(monkeypatch: pytest.MonkeyPatch) -> None:
    import seal_cli.bench.startup as startup

    result = runner.invoke(app, ["bench", "startup", "--runs", "1", "--json"])
    assert result.exit_code == 0, result.output
    data = json.loads(result.stdout)
    assert set(data["commands"]) == {"version", "parse"} and data["python_s"] > 0
    for figures in data["commands"].values():
        assert figures["ratio"] == figures["cpu_s"] / data["python_s"] and figures["ok"] == (
            figures["ratio"] <= figures["target"])
    monkeypatch.setattr(startup, "measure", lambda runs, say: data)   # the table of that measurement, not another
    table = runner.invoke(app, ["bench", "startup", "--runs", "1"])
    assert table.exit_code == 0 and "seal --version" in table.stdout and "× python" in table.stdout
    assert f"{data['commands']['version']['cpu_s'] * 1000:.1f}" in table.stdout


def test_bench_startup_refuses_zero_runs() -> None:
    result = runner.invoke(app, ["bench", "startup", "--runs", "0"])
    assert result.exit_code == 2


# -- seal parse TEXT without typer, and one command module per command line ------------------------
def _seal(*argv: str, env: dict[str, str] | None = None) -> subprocess.CompletedProcess[str]:
    code = ("import sys\nfrom seal_cli.__main__ import main\ntry:\n    main()\nfinally:\n    print(sorted(m for m in "
            "sys.modules if m == 'typer' or m.endswith('_cmd')), file=sys.stderr)")
    return subprocess.run([sys.executable, "-c", code, *argv], capture_output=True, text=True, env=env)


def _by_typer(*argv: str) -> tuple[int, str, str]:
    result = CliRunner().invoke(app, list(argv))
    return result.exit_code, result.stdout, result.stderr


@pytest.mark.parametrize("argv", [["parse", "bring me a cup from the kitchen"], ["parse", "--json", "stir the cup"],
                                  ["parse", "stir the cup", "--json"], ["parse", "juggle the cup"],
                                  ["parse", "--json", "juggle the cup"], ["parse", ""], ["parse", "x [bold]y[/bold]"]])
def test_plain_parse_is_answered_without_typer_as_typer_answers_it(argv: list[str]) -> None:
    from seal_cli.cli import plain_parse

    assert plain_parse(argv) is not None
    run = _seal(*argv)
    *printed, modules = run.stderr.splitlines() or [""]
    code, stdout, stderr = _by_typer(*argv)
    assert (run.returncode, run.stdout, "\n".join(printed) + ("\n" if printed else "")) == (code, stdout, stderr)
    assert "Traceback" not in run.stderr


def test_anything_but_plain_parse_goes_to_typer_with_its_command_module_only() -> None:
    from seal_cli.cli import plain_parse

    for argv in (["parse"], ["parse", "-f", "x"], ["parse", "--help"], ["parse", "a", "b"], ["parse", "--json"],
                 ["parse", "--json", "--json", "a"], ["plan", "a"], ["--help"]):
        assert plain_parse(argv) is None, argv
    run = _seal("parse", "--json", "--vocabulary", "missing.yaml", "stir the cup")
    assert run.returncode == 1 and run.stderr.splitlines()[-1] == "['seal_cli.cli.parse_cmd', 'typer']"
    assert run.stderr.startswith("error: ")


def test_the_plain_parse_imports_neither_typer_nor_any_command_module() -> None:
    run = _seal("parse", "--json", "stir the cup")
    assert run.returncode == 0 and run.stderr.splitlines()[-1] == "[]"
    assert json.loads(run.stdout)["frames"][0]["frame"] == "Stir"


def test_each_command_is_found_in_the_module_the_table_names() -> None:
    from seal_cli.cli import BENCH_HOMES, HOMES, command_modules, register
    from seal_cli.cli.framework import bench_app

    whole = register()
    top = {c.name or c.callback.__name__: c.callback.__module__ for c in whole.registered_commands}  # type: ignore
    bench = {c.name or c.callback.__name__: c.callback.__module__ for c in bench_app.registered_commands}  # type: ignore
    assert {name: f"seal_cli.cli.{module}" for name, module in HOMES.items()} == top
    assert {name: f"seal_cli.cli.{module}" for name, module in BENCH_HOMES.items()} == bench
    assert command_modules(["bench", "perf", "--scale", "large"]) == ["perf_cmd"]
    assert command_modules(["parse", "x"]) == ["parse_cmd"]
    assert set(command_modules(["--help"])) == set(command_modules(["bench"])) == set(command_modules(["pars"])) \
        == set(HOMES.values()) | set(BENCH_HOMES.values())


def _rich_tree(text: str) -> str:
    """What rich prints for the parse of ``text`` on a console of the pipe's width and no colours."""
    import io

    from rich.console import Console

    from seal_cli.cli.parse_view import tree
    from seal_cli.frames.reading import load_library
    from seal_cli.language.parser import parse_command

    console = Console(file=io.StringIO(), soft_wrap=True, highlight=False, width=200)
    console.print(tree(parse_command(text, load_library(), None)))
    return console.file.getvalue()  # type: ignore[attr-defined]


def _seal_rich(*argv: str, env: dict[str, str] | None = None) -> tuple[subprocess.CompletedProcess[str], bool]:
    """Run ``seal ARGV`` into a pipe; the run and whether it imported rich."""
    code = ("import sys\nfrom seal_cli.__main__ import main\ntry:\n    main()\nfinally:\n"
            "    print('rich' in sys.modules, file=sys.stderr)")
    run = subprocess.run([sys.executable, "-c", code, *argv], capture_output=True, text=True, env=env)
    return run, run.stderr.splitlines()[-1] == "True"


def _env(**extra: str) -> dict[str, str]:
    import os

    env = {k: v for k, v in os.environ.items() if k not in ("FORCE_COLOR", "TTY_COMPATIBLE", "COLUMNS")}
    return {**env, "PYTHONIOENCODING": "utf-8", **extra}


@pytest.mark.parametrize("text", ["bring me a cup from the kitchen", "stir the cup and put it on the table",
                                  "bring Roger a coffee from the kitchen"])
def test_a_tree_into_a_pipe_is_what_rich_prints_without_rich(text: str) -> None:
    run, imported_rich = _seal_rich("parse", text, env=_env())
    assert run.returncode == 0 and not imported_rich
    assert run.stdout == _rich_tree(text)


@pytest.mark.parametrize(("text", "extra"), [
    ("bring me a cup at 5:30 from the kitchen", {}),  # ':' may start an emoji code
    ("bring me a cup from the kitchen " + "very " * 40 + "big", {}),  # rich crops at the width
    ("bring me a 杯 from the kitchen", {}),  # beyond Latin: rich decides how many columns it takes
    ("bring me a cup from the kitchen", {"COLUMNS": "200"}),
])
def test_a_tree_rich_may_print_otherwise_is_printed_by_rich(text: str, extra: dict[str, str]) -> None:
    run, imported_rich = _seal_rich("parse", text, env=_env(**extra))
    assert run.returncode == 0 and imported_rich
    assert run.stdout == _rich_tree(text)


def test_forced_colours_are_rich_s() -> None:
    run, imported_rich = _seal_rich("parse", "bring me a cup from the kitchen", env=_env(FORCE_COLOR="1"))
    assert run.returncode == 0 and imported_rich and "\x1b[" in run.stdout
