"""``scripts/build_verb_usage.py``: P(verb | form) from WordNet's sense tag counts, on a tiny WordNet, and the shipped
``seal_cli/language/verb_usage.tsv`` being what WordNet gives."""

from __future__ import annotations

import subprocess
from pathlib import Path

import pytest

from seal_cli.language.verb_usage import mostly_verb, verb_share, verb_tags
from tests.conftest import run_script

ROOT = Path(__file__).resolve().parents[2]
SCRIPT = ROOT / "scripts" / "build_verb_usage.py"
WORDNET_DICT = Path("/usr/share/wordnet")          # Debian's wordnet-base

INDEX = {
    "noun": "  1 licence line, skipped.\nwait n 2 1 @ 2 1 1 2\nplate n 1 1 @ 1 1 3\npepper n 2 1 @ 2 0 4 5\n"
            "knife n 1 1 @ 1 1 6\n",
    "verb": "  1 licence line, skipped.\nwait v 1 1 @ 1 1 7\nplate v 1 1 @ 1 0 8\npepper v 1 1 @ 1 1 9\n"
            "knife v 1 1 @ 1 0 10\nspool v 2 1 @ 2 0 11 12\n",
    "adj": "  1 licence line, skipped.\n",
    "adv": "  1 licence line, skipped.\n",
}
COUNTS = """\
wait%2:42:00:: 1 30
wait%1:28:00:: 1 2
plate%1:06:00:: 1 10
pepper%2:30:00:: 1 2
knife%1:06:00:: 1 5
"""


def run(*args: str) -> subprocess.CompletedProcess[str]:
    return run_script(SCRIPT, *args)


def test_the_share_of_verb_tags_with_each_sense_counted_once(tmp_path: Path) -> None:
    for pos, text in INDEX.items():
        (tmp_path / f"index.{pos}").write_text(text)
    (tmp_path / "cntlist.rev").write_text(COUNTS)
    (tmp_path / "noun.exc").write_text("knives knife\n")
    out = tmp_path / "verb_usage.tsv"
    done = run("--wordnet", str(tmp_path), "--out", str(out))
    assert done.returncode == 0, done.stderr
    rows = {line.split("\t")[0]: line.split("\t")[1:] for line in out.read_text().splitlines()
            if not line.startswith("#")}
    # wait: (30 + 1) / (32 + 3); plate: (0 + 1) / (10 + 2); pepper: (2 + 1) / (2 + 3); spool: never tagged, 2 / 2
    assert rows == {"wait": ["0.886", "30", "32"], "plate": ["0.083", "0", "10"], "pepper": ["0.600", "2", "2"],
                    "knife": ["0.143", "0", "5"], "spool": ["1.000", "0", "0"]}


def test_a_folder_without_wordnet_is_one_clear_error(tmp_path: Path) -> None:
    done = run("--wordnet", str(tmp_path))
    assert done.returncode == 1 and "index.noun: no such file" in done.stderr and "Traceback" not in done.stderr


def test_the_shipped_table_reads_verbs_and_nouns_apart() -> None:
    assert mostly_verb("wait") and mostly_verb("dance") and verb_tags("wait") > 100
    assert not any(mostly_verb(w) for w in ("plate", "fork", "pepper", "butter", "spool", "quickly"))
    assert verb_share("quickly") == 0.0 and verb_share("plate") < 0.1


@pytest.mark.skipif(not (WORDNET_DICT / "cntlist.rev").is_file(), reason="WordNet 3.0 not installed")
def test_the_shipped_file_is_what_wordnet_gives() -> None:
    done = run("--wordnet", str(WORDNET_DICT), "--check")
    assert done.returncode == 0, done.stdout + done.stderr
