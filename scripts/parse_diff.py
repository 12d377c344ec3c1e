"""Whether two trees of seal parse every corpus alike: ``seal parse --file - --json`` run by each tree on each
corpus, the JSON output compared line by line (a change that should move no parse, such as a speed-up, must leave
every byte as it was).

    python scripts/parse_diff.py OLD_TREE NEW_TREE --data /work/shared/data [--keep DIR] [--corpus FILE ...]

The corpora (default): GPSR dev, every ``tests/data/wording*.jsonl`` of NEW_TREE, ALFRED train and valid_seen goals
(``.tsv``, parsed with ALFRED's classes as the vocabulary, as ``score_alfred_goals.py`` parses them). ``--keep DIR``
keeps each tree's output in ``DIR/old`` and ``DIR/new``, and reuses OLD_TREE's from there when it is present (the
old tree is parsed once). Prints, per corpus, how many lines differ and the first few; exit 1 if any differ, 2 on
bad input.
"""

from __future__ import annotations

import argparse
import csv
import json
import os
import subprocess
import sys
import tempfile
from pathlib import Path

SHOWN = 3
"""How many differing lines are shown per corpus."""


def commands(path: Path) -> list[str]:
    """The commands of a corpus: each JSON line's ``text``, or each ``goal_sentence`` of an ALFRED goals table with
    its runs of white space made single (as the scorers read them)."""
    if path.suffix == ".tsv":
        with path.open(encoding="utf-8", newline="") as rows:
            return [" ".join(str(row.get("goal_sentence") or "").split())
                    for row in csv.DictReader(rows, delimiter="\t")]
    found = []
    for number, line in enumerate(path.read_text(encoding="utf-8").splitlines(), 1):
        if line.strip():
            try:
                item = json.loads(line)
            except json.JSONDecodeError as error:
                raise ValueError(f"{path}:{number}:{error.colno}: not JSON ({error.msg})") from None
            if isinstance(item, dict) and isinstance(item.get("text"), str):
                found.append(item["text"])
    return found


def corpora(data: Path, tree: Path) -> list[Path]:
    """The default corpora (see the module docstring)."""
    return [data / "gpsr" / "dev.jsonl", *sorted((tree / "tests" / "data").glob("wording*.jsonl")),
            data / "alfred" / "goals_train.tsv", data / "alfred" / "goals_valid_seen.tsv"]


def parsed(tree: Path, texts: list[str], vocabulary: Path | None) -> list[str]:
    """The lines ``seal parse --file - --json`` of ``tree`` writes for ``texts``."""
    argv = [sys.executable, "-m", "seal_cli", "parse", "--file", "-", "--json"]
    if vocabulary is not None:
        argv += ["--vocabulary", str(vocabulary)]
    env = {**os.environ, "PYTHONPATH": str(tree)}
    run = subprocess.run(argv, input="".join(text.replace("\n", " ") + "\n" for text in texts), capture_output=True,
                         text=True, cwd=tree, env=env, check=False)
    lines = run.stdout.splitlines()
    if len(lines) != len(texts):
        raise RuntimeError(f"{tree}: {len(lines)} lines for {len(texts)} commands (exit {run.returncode}): "
                           f"{run.stderr[-500:]}")
    return lines


def output(tree: Path, corpus: Path, texts: list[str], vocabulary: Path | None, keep: Path | None,
           reuse: bool) -> list[str]:
    """The tree's output on a corpus, kept in (and, with ``reuse``, read back from) ``keep``."""
    kept = keep / f"{corpus.parent.name}_{corpus.stem}.jsonl" if keep is not None else None
    if reuse and kept is not None and kept.is_file():
        return kept.read_text(encoding="utf-8").splitlines()
    lines = parsed(tree, texts, vocabulary if corpus.suffix == ".tsv" else None)
    if kept is not None:
        kept.parent.mkdir(parents=True, exist_ok=True)
        kept.write_text("".join(line + "\n" for line in lines), encoding="utf-8")
    return lines


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("old", type=Path, help="the tree parsed first (a checkout, PYTHONPATH for its seal_cli)")
    ap.add_argument("new", type=Path)
    ap.add_argument("--data", type=Path, required=True, help="the shared data folder (gpsr/, alfred/)")
    ap.add_argument("--corpus", type=Path, action="append", help="a corpus to compare (repeatable; default: all)")
    ap.add_argument("--keep", type=Path, help="keep the outputs here; reuse the old tree's")
    args = ap.parse_args()
    for tree in (args.old, args.new):
        if not (tree / "seal_cli" / "__init__.py").is_file():
            print(f"error: {tree}: no seal_cli here (a tree is a checkout of the project)", file=sys.stderr)
            return 2
    chosen = args.corpus or corpora(args.data, args.new)
    missing = [path for path in chosen if not path.is_file()]
    if missing:
        print(f"error: {missing[0]}: no such file", file=sys.stderr)
        return 2
    constants = args.data / "alfred" / "alfred_constants.json"
    differ = 0
    with tempfile.TemporaryDirectory() as scratch:
        vocabulary = None
        if any(path.suffix == ".tsv" for path in chosen):
            vocabulary = Path(scratch) / "alfred_classes.yaml"
            classes = json.loads(constants.read_text(encoding="utf-8"))["OBJECTS"]
            vocabulary.write_text("".join(f"- {c}\n" for c in classes), encoding="utf-8")
        for corpus in chosen:
            try:
                texts = commands(corpus)
            except (ValueError, UnicodeDecodeError, csv.Error) as error:
                print(f"error: {error}", file=sys.stderr)
                return 2
            old = output(args.old.resolve(), corpus, texts, vocabulary, args.keep and args.keep / "old", True)
            new = output(args.new.resolve(), corpus, texts, vocabulary, args.keep and args.keep / "new", False)
            changed = [k for k, (a, b) in enumerate(zip(old, new, strict=True)) if a != b]
            differ += len(changed)
            print(f"{corpus}: {len(changed)} of {len(texts)} parses differ")
            for k in changed[:SHOWN]:
                print(f"  line {k + 1}: {texts[k]!r}\n    old {old[k][:300]}\n    new {new[k][:300]}")
    print(f"{differ} parses differ in all")
    return 1 if differ else 0


if __name__ == "__main__":
    sys.exit(main())
