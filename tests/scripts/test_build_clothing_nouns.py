"""``scripts/build_clothing_nouns.py``: the nouns of what people wear it takes from WordNet's noun hierarchy, on a
tiny WordNet, and the shipped ``framelib/wordnet_clothing.yaml`` being what WordNet gives."""

from __future__ import annotations

import subprocess
from pathlib import Path

import pytest
import yaml

from tests.conftest import run_script, tiny_wordnet

ROOT = Path(__file__).resolve().parents[2]
SCRIPT = ROOT / "scripts" / "build_clothing_nouns.py"
WORDNET_DICT = Path("/usr/share/wordnet")          # Debian's wordnet-base

DATA = """\
  1 This is a licence line, skipped.
03051540 06 n 01 clothing 0 000 | a covering designed to be worn on a person's body
03419014 06 n 01 garment 0 001 @ 03051540 n 0000 | an article of clothing
03589791 06 n 01 jacket 0 001 @ 03419014 n 0000 | a short coat
07000001 13 n 01 jacket 1 000 | the outer skin of a potato
03380867 06 n 01 footwear 0 000 | covering for a person's feet
04199027 06 n 01 shoe 0 001 @ 03380867 n 0000 | footwear shaped to fit the foot
03000002 06 n 01 cardigan 0 001 @ 03419014 n 0000 | knitted jacket
01000003 05 n 01 cardigan 1 000 | a dog of a Welsh breed
03000004 06 n 01 tunic 0 001 @ 03419014 n 0000 | a long garment
04000005 06 n 01 table 0 000 | a piece of furniture
"""
INDEX = """\
  1 This is a licence line, skipped.
jacket n 2 1 @ 2 1 03589791 07000001
shoe n 1 1 @ 1 1 04199027
cardigan n 2 1 @ 2 0 03000002 01000003
tunic n 1 1 @ 1 0 03000004
table n 1 0 1 1 04000005
"""
COUNTS = """\
jacket%1:06:00:: 1 4
shoe%1:06:00:: 1 9
table%1:06:00:: 1 30
"""


def run(*args: str) -> subprocess.CompletedProcess[str]:
    return run_script(SCRIPT, *args)


def test_a_noun_whose_first_tagged_sense_or_every_sense_is_worn(tmp_path: Path) -> None:
    wordnet = tiny_wordnet(tmp_path / "dict", "", DATA, "", INDEX, COUNTS)
    out = tmp_path / "clothing.yaml"
    done = run("--wordnet", str(wordnet), "--out", str(out))
    assert done.returncode == 0, done.stderr
    # jacket: its first (tagged) sense is a garment, the potato skin no matter; tunic: never tagged, every
    # sense worn; cardigan: never tagged, one sense a dog; table: no clothing
    assert yaml.safe_load(out.read_text())["categories"]["clothing"] == ["jacket", "shoe", "tunic"]


def test_a_folder_without_wordnet_is_one_clear_error(tmp_path: Path) -> None:
    done = run("--wordnet", str(tmp_path))
    assert done.returncode == 1 and "data.noun: no such file" in done.stderr and "Traceback" not in done.stderr


@pytest.mark.skipif(not (WORDNET_DICT / "data.noun").is_file(), reason="WordNet 3.0 not installed")
def test_the_shipped_file_is_what_wordnet_gives() -> None:
    done = run("--wordnet", str(WORDNET_DICT), "--check")
    assert done.returncode == 0, done.stdout + done.stderr
