"""The README's examples are part of the test suite: every `seal ...` line of its example block runs."""

from __future__ import annotations

import os
import re
import shlex
from pathlib import Path

import pytest
from typer.testing import CliRunner

from seal_cli.cli import app

ROOT = Path(__file__).resolve().parents[1]


def examples() -> list[list[str]]:
    text = (ROOT / "README.md").read_text()
    block = re.search(r"### Examples\s+```sh\n(.*?)```", text, re.S)
    assert block, "the README has an Examples block"
    lines = block.group(1).replace("\\\n", " ").splitlines()
    return [shlex.split(line, comments=True)[1:] for line in lines if line.startswith("seal ")]


def test_the_readme_has_examples_of_the_pipeline() -> None:
    assert {args[0] for args in examples()} >= {"parse", "plan", "localize", "run"}


@pytest.mark.parametrize("args", examples(), ids=lambda a: " ".join(a[:2]))
def test_each_readme_example_runs(args: list[str], tmp_path: Path) -> None:
    cwd = os.getcwd()
    os.chdir(ROOT)  # the examples name shipped files by their path in the checkout
    try:
        args = [str(tmp_path / a) if a.endswith(".png") else a for a in args]
        result = CliRunner().invoke(app, args)
    finally:
        os.chdir(cwd)
    assert result.exit_code == 0, result.output
    assert result.stdout.strip()
    for a in args:
        if a.endswith(".png"):
            assert Path(a).read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
