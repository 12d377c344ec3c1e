"""``scripts/parse_diff.py``: two trees' ``seal parse --file - --json`` compared line by line on each corpus; the
trees here are tiny stand-ins whose ``python -m seal_cli`` writes one JSON line per command."""

from __future__ import annotations

import json
import subprocess
import sys
from pathlib import Path

from tests.conftest import module_from_file

ROOT = Path(__file__).resolve().parents[2]
SCRIPT = ROOT / "scripts" / "parse_diff.py"

MAIN = """import json, sys
assert sys.argv[1:5] == ["parse", "--file", "-", "--json"], sys.argv
vocabulary = sys.argv[6] if len(sys.argv) > 6 else None
for line in sys.stdin:
    text = line.rstrip("\\n")
    print(json.dumps({"text": {TRANSFORM}, "vocabulary": bool(vocabulary)}))
"""


def tree(root: Path, transform: str) -> Path:
    """A stand-in tree: its seal_cli writes ``{"text": <transform of the command>}`` for each command."""
    package = root / "seal_cli"
    package.mkdir(parents=True)
    (package / "__init__.py").write_text("", encoding="utf-8")
    (package / "__main__.py").write_text(MAIN.replace("{TRANSFORM}", transform), encoding="utf-8")
    return root


def corpus(path: Path, texts: list[str]) -> Path:
    path.write_text("".join(json.dumps({"text": t}) + "\n" for t in texts), encoding="utf-8")
    return path


def run(*args: object) -> subprocess.CompletedProcess[str]:
    return subprocess.run([sys.executable, str(SCRIPT), *map(str, args)], capture_output=True, text=True,
                          check=False)


def test_two_trees_that_parse_alike_differ_nowhere(tmp_path: Path) -> None:
    old, new = tree(tmp_path / "old", "text"), tree(tmp_path / "new", "text")
    texts = corpus(tmp_path / "dev.jsonl", ["bring me a cup", "go to the kitchen"])
    done = run(old, new, "--data", tmp_path, "--corpus", texts, "--keep", tmp_path / "kept")
    assert done.returncode == 0, done.stderr
    assert f"{texts}: 0 of 2 parses differ" in done.stdout
    assert (tmp_path / "kept" / "old" / f"{tmp_path.name}_dev.jsonl").read_text(encoding="utf-8").count("\n") == 2


def test_a_parse_that_moved_is_shown_with_its_line_and_both_outputs(tmp_path: Path) -> None:
    old = tree(tmp_path / "old", "text")
    new = tree(tmp_path / "new", "text.upper() if 'cup' in text else text")
    texts = corpus(tmp_path / "dev.jsonl", ["go to the kitchen", "bring me a cup"])
    done = run(old, new, "--data", tmp_path, "--corpus", texts)
    assert done.returncode == 1
    assert "1 of 2 parses differ" in done.stdout and "line 2: 'bring me a cup'" in done.stdout
    assert '"BRING ME A CUP"' in done.stdout and "1 parses differ in all" in done.stdout


def test_the_old_trees_output_is_kept_and_read_back(tmp_path: Path) -> None:
    old, new = tree(tmp_path / "old", "text"), tree(tmp_path / "new", "text")
    texts = corpus(tmp_path / "dev.jsonl", ["bring me a cup"])
    assert run(old, new, "--data", tmp_path, "--corpus", texts, "--keep", tmp_path / "kept").returncode == 0
    (old / "seal_cli" / "__main__.py").write_text("raise SystemExit(3)\n", encoding="utf-8")   # not run again
    assert run(old, new, "--data", tmp_path, "--corpus", texts, "--keep", tmp_path / "kept").returncode == 0


def test_alfred_goals_are_read_as_the_scorer_reads_them(tmp_path: Path) -> None:
    goals = tmp_path / "goals.tsv"
    goals.write_text("goal_sentence\tother\nPut  a\tcup away.\tx\n", encoding="utf-8")
    assert module_from_file("parse_diff", SCRIPT).commands(goals) == ["Put a"]


def test_bad_input_is_named_with_exit_code_2(tmp_path: Path) -> None:
    new = tree(tmp_path / "new", "text")
    done = run(tmp_path / "nowhere", new, "--data", tmp_path)
    assert done.returncode == 2 and "nowhere: no seal_cli here" in done.stderr and "Traceback" not in done.stderr
    done = run(new, new, "--data", tmp_path, "--corpus", tmp_path / "missing.jsonl")
    assert done.returncode == 2 and "missing.jsonl: no such file" in done.stderr
    broken = tmp_path / "broken.jsonl"
    broken.write_text('{"text": "go"}\n{"text": \n', encoding="utf-8")
    done = run(new, new, "--data", tmp_path, "--corpus", broken)
    assert done.returncode == 2 and "broken.jsonl:2:" in done.stderr and "Traceback" not in done.stderr
