"""``scripts/build_verb_objects.py``: P(object | verb) from WordNet's verb frames and sense tag counts, on a tiny
WordNet, and the shipped ``seal_cli/language/verb_objects.tsv`` being what WordNet gives."""

from __future__ import annotations

import subprocess
from pathlib import Path

import pytest

from seal_cli.language.verb_objects import object_share, takes_object
from tests.conftest import run_script

ROOT = Path(__file__).resolve().parents[2]
SCRIPT = ROOT / "scripts" / "build_verb_objects.py"
WORDNET_DICT = Path("/usr/share/wordnet")          # Debian's wordnet-base

# offset lexfile pos word-count words... pointer-count frames | gloss; frames: "+ frame word" (word 00: every word)
DATA = """\
  1 licence line, skipped.
00000001 29 v 02 sob 0 weep 0 000 01 + 02 00 | shed tears
00000002 29 v 01 sob 1 000 02 + 02 00 + 08 00 | utter with sobs
00000003 35 v 02 hug 0 squeeze 2 000 02 + 09 01 + 02 02 | hold close
"""
COUNTS = """\
sob%2:29:00:: 1 9
sob%2:29:01:: 1 1
hug%2:35:00:: 1 4
"""


def run(*args: str) -> subprocess.CompletedProcess[str]:
    return run_script(SCRIPT, *args)


def test_the_share_of_tagged_senses_said_with_an_object(tmp_path: Path) -> None:
    (tmp_path / "data.verb").write_text(DATA)
    (tmp_path / "cntlist.rev").write_text(COUNTS)
    out = tmp_path / "verb_objects.tsv"
    done = run("--wordnet", str(tmp_path), "--out", str(out))
    assert done.returncode == 0, done.stderr
    rows = {line.split("\t")[0]: line.split("\t")[1:] for line in out.read_text().splitlines()
            if not line.startswith("#")}
    # sob: the weeping sense (9 + 1) has no object, the uttering one (1 + 1) has: 2 / 12; hug: frame 9 is its own
    # (word 01), frame 2 squeeze's; weep and squeeze: never tagged, one sense each
    assert rows == {"sob": ["0.167", "10"], "weep": ["0.000", "0"], "hug": ["1.000", "4"], "squeeze": ["0.000", "0"]}


def test_a_folder_without_wordnet_is_one_clear_error(tmp_path: Path) -> None:
    done = run("--wordnet", str(tmp_path))
    assert done.returncode == 1 and "data.verb: no such file" in done.stderr and "Traceback" not in done.stderr


def test_the_shipped_table_tells_verbs_said_with_an_object() -> None:
    assert all(takes_object(v) for v in ("wear", "hold", "carry", "read"))
    assert not any(takes_object(v) for v in ("cry", "wait", "sit", "stand", "smile", "sleep"))
    assert object_share("zzzz") is None and takes_object("zzzz")


@pytest.mark.skipif(not (WORDNET_DICT / "data.verb").is_file(), reason="WordNet 3.0 not installed")
def test_the_shipped_file_is_what_wordnet_gives() -> None:
    done = run("--wordnet", str(WORDNET_DICT), "--check")
    assert done.returncode == 0, done.stdout + done.stderr
