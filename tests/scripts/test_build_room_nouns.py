"""``scripts/build_room_nouns.py``: the nouns of rooms and parts of buildings it takes from WordNet's noun hierarchy,
on a tiny WordNet, and the shipped ``seal_cli/language/premises.txt`` being what WordNet gives."""

from __future__ import annotations

import subprocess
from pathlib import Path

import pytest

from tests.conftest import run_script, tiny_wordnet

ROOT = Path(__file__).resolve().parents[2]
SCRIPT = ROOT / "scripts" / "build_room_nouns.py"
WORDNET_DICT = Path("/usr/share/wordnet")          # Debian's wordnet-base

DATA = """\
  1 This is a licence line, skipped.
02735688 06 n 01 area 0 000 | a part of a structure having some specific function
04105893 06 n 01 room 0 001 @ 02735688 n 0000 | an area within a building enclosed by walls
03619890 06 n 01 scullery 0 001 @ 04105893 n 0000 | a room for washing dishes
03112099 06 n 01 corridor 0 000 | an enclosed passageway
03479952 06 n 01 hallway 0 001 @ 03112099 n 0000 | an interior passage
05000001 09 n 01 study 0 000 | a piece of research
03000002 06 n 01 study 1 001 @ 04105893 n 0000 | a room used for reading and writing
04000005 06 n 01 towel 0 000 | a rectangular piece of cloth
03000006 06 n 01 snug 0 001 @ 04105893 n 0000 | a small cosy room
09000007 06 n 01 snug 1 000 | a comfortable feeling
"""
INDEX = """\
  1 This is a licence line, skipped.
scullery n 1 1 @ 1 1 03619890
hallway n 1 1 @ 1 1 03479952
study n 2 1 @ 2 1 05000001 03000002
towel n 1 0 1 1 04000005
snug n 2 1 @ 2 0 03000006 09000007
"""
COUNTS = """\
scullery%1:06:00:: 1 2
hallway%1:06:00:: 1 9
study%1:09:00:: 1 30
study%1:06:00:: 2 5
towel%1:06:00:: 1 8
"""


def run(*args: str) -> subprocess.CompletedProcess[str]:
    return run_script(SCRIPT, *args)


def premises(tmp_path: Path, data: str, index: str, counts: str) -> list[str]:
    """The nouns the script writes from a tiny WordNet of these noun files (it must succeed)."""
    wordnet = tiny_wordnet(tmp_path / "dict", "", data, "", index, counts)
    out = tmp_path / "premises.txt"
    done = run("--wordnet", str(wordnet), "--out", str(out))
    assert done.returncode == 0, done.stderr
    return [line for line in out.read_text().splitlines() if line and not line.startswith("#")]


def test_a_noun_whose_first_tagged_sense_or_every_sense_is_part_of_a_building(tmp_path: Path) -> None:
    nouns = premises(tmp_path, DATA, INDEX, COUNTS)
    # scullery: a room; hallway: a corridor; study: its first (most tagged) sense is research; towel: cloth;
    # snug: never tagged, one sense a feeling
    assert nouns == ["hallway", "scullery"]


STORES_DATA = """\
  1 This is a licence line, skipped.
02735688 06 n 01 area 0 000 | a part of a structure having some specific function
04105893 06 n 01 room 0 001 @ 02735688 n 0000 | an area within a building enclosed by walls
04328946 06 n 01 storage_space 0 001 @ 02735688 n 0000 | the area in any structure that provides space for storage
03094503 06 n 01 container 0 000 | any object that can be used to hold things
03000011 06 n 01 hutch 0 001 @ 04328946 n 0000 | a recess or cabinet for storing dishes
03000012 06 n 01 tray 0 002 @ 03094503 n 0000 @ 04328946 n 0000 | a sliding box in a piece of furniture
03000013 06 n 01 stockroom 0 002 @ 04105893 n 0000 @ 04328946 n 0000 | a room where goods are kept
03000014 06 n 01 parlour 0 001 @ 04105893 n 0000 | a room for receiving guests
"""
STORES_INDEX = """\
  1 This is a licence line, skipped.
hutch n 1 1 @ 1 1 03000011
tray n 1 1 @ 1 1 03000012
stockroom n 1 1 @ 1 1 03000013
parlour n 1 1 @ 1 1 03000014
"""
STORES_COUNTS = """\
hutch%1:06:00:: 1 3
tray%1:06:00:: 1 4
stockroom%1:06:00:: 1 2
parlour%1:06:00:: 1 5
"""


def test_a_place_things_are_kept_in_is_no_premises_unless_it_is_a_room(tmp_path: Path) -> None:
    nouns = premises(tmp_path, STORES_DATA, STORES_INDEX, STORES_COUNTS)
    # hutch: storage space (an area) and no room, as WordNet files "cupboard"; tray: a container and storage space,
    # as "drawer"; stockroom: storage space and a room, as "pantry"/"storeroom"; parlour: a room
    assert nouns == ["parlour", "stockroom"]


def test_a_folder_without_wordnet_is_one_clear_error(tmp_path: Path) -> None:
    done = run("--wordnet", str(tmp_path))
    assert done.returncode == 1 and "data.noun: no such file" in done.stderr and "Traceback" not in done.stderr


@pytest.mark.skipif(not (WORDNET_DICT / "data.noun").is_file(), reason="WordNet 3.0 not installed")
def test_the_shipped_file_is_what_wordnet_gives() -> None:
    done = run("--wordnet", str(WORDNET_DICT), "--check")
    assert done.returncode == 0, done.stdout + done.stderr
