"""``scripts/parse_speed.py``: two trees' parsers timed side by side, chunk by chunk, on one corpus."""

from __future__ import annotations

import json
import re
import subprocess
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
SCRIPT = ROOT / "scripts" / "parse_speed.py"


def run(*args: object) -> subprocess.CompletedProcess[str]:
    return subprocess.run([sys.executable, str(SCRIPT), *map(str, args)], capture_output=True, text=True,
                          timeout=300)


def test_one_tree_against_itself_gives_a_figure_per_round_and_the_medians(tmp_path: Path) -> None:
    corpus = tmp_path / "c.jsonl"
    corpus.write_text("".join(json.dumps({"text": t}) + "\n" for t in
                              ["bring me the apple", "go to the kitchen", "find Anna", "brin me a cup"]),
                      encoding="utf-8")                                 # the last refused: still timed
    done = run(ROOT, ROOT, "--corpus", corpus, "--rounds", "2", "--chunk", "3")
    assert done.returncode == 0, done.stderr
    rounds = re.findall(r"^round (\d): old ([\d,]+)  new ([\d,]+) commands/CPU-s  ratio ([\d.]+)$", done.stdout, re.M)
    assert [r[0] for r in rounds] == ["1", "2"]
    assert all(int(r[1].replace(",", "")) > 0 and float(r[3]) > 0 for r in rounds)
    assert "(n=4, 2 rounds of chunks of 3)" in done.stdout


def test_bad_input_is_refused_before_any_worker_starts(tmp_path: Path) -> None:
    missing = run(ROOT, ROOT, "--corpus", tmp_path / "none.jsonl")
    assert missing.returncode == 2 and "no such file" in missing.stderr
    no_tree = run(tmp_path, ROOT, "--corpus", SCRIPT)
    assert no_tree.returncode == 2 and "no seal_cli package" in no_tree.stderr
    goals = tmp_path / "g.tsv"
    goals.write_text("goal_sentence\nput a cup in the sink\n", encoding="utf-8")
    assert "--constants" in run(ROOT, ROOT, "--corpus", goals).stderr
