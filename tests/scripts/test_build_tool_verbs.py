"""``scripts/build_lexical_units.py --wordnet``, rule 11 (words20): a verb named for a tool keeps a frame with an
instrument only when the tool is of the instrument's type ("mow the lawn" is no slicing with a knife), read from a
tiny WordNet ``dict`` folder written here, in WordNet's own file formats."""

from __future__ import annotations

import sys
from pathlib import Path

from seal_cli.frames.library import Library
from tests.conftest import tiny_library, tiny_wordnet

ROOT = Path(__file__).resolve().parents[2]
sys.path.insert(0, str(ROOT / "scripts"))

import build_lexical_units as build  # noqa: E402

LIBRARY = """\
categories: {cutter: [knife], object: ~}
frames:
  - frame: Slice
    lexical_units: [cut, slice]
    elements: {theme: {type: object}, instrument: {type: cutter, default: knife}}
    postconditions: [sliced(theme)]
"""

# implement.n.01 at its WordNet 3.0 offset (the rule looks for it there); cut.v.01 and its kinds: slice (a unit),
# mow (named for a mower), hack (for no tool), saw (for a saw that the word names first), tap (for a tool that "tap"
# names only in its second sense; first, a faucet)
DATA_VERB = """\
00000100 35 v 01 cut 0 005 ~ 00000200 v 0000 ~ 00000300 v 0000 ~ 00000400 v 0000 ~ 00000500 v 0000 \
~ 00000600 v 0000 | cut
00000200 35 v 01 slice 0 001 @ 00000100 v 0000 | cut into slices
00000300 35 v 01 mow 0 002 @ 00000100 v 0000 + 00001200 n 0101 | cut with a blade or mower
00000400 35 v 01 hack 0 001 @ 00000100 v 0000 | cut with a heavy blow
00000500 35 v 01 saw 0 002 @ 00000100 v 0000 + 00001300 n 0101 | cut with a saw
00000600 35 v 01 tap 0 002 @ 00000100 v 0000 + 00001500 n 0101 | cut a thread
"""
DATA_NOUN = """\
03563967 06 n 01 implement 0 000 | an instrumentality
00001100 06 n 01 device 0 000 | a device
00001200 06 n 02 lawn_mower 0 mower 0 001 @ 03563967 n 0000 | garden tool
00001300 06 n 01 saw 0 001 @ 03563967 n 0000 | hand tool
00001400 06 n 02 faucet 0 tap 0 001 @ 00001100 n 0000 | a regulator
00001500 06 n 01 tap 0 001 @ 03563967 n 0000 | a tool for cutting a thread
"""
INDEX_VERB = "".join(f"{lemma} v 1 1 @ 1 1 {offset}\n" for lemma, offset in [
    ("cut", "00000100"), ("hack", "00000400"), ("mow", "00000300"), ("saw", "00000500"), ("slice", "00000200"),
    ("tap", "00000600")])
INDEX_NOUN = """\
implement n 1 0 1 0 03563967
lawn_mower n 1 0 1 0 00001200
mower n 1 0 1 0 00001200
saw n 1 0 1 0 00001300
tap n 2 0 2 0 00001400 00001500
"""
CNTLIST = "".join(f"{lemma}%2:35:00:: 1 {n}\n" for lemma, n in [("cut", 9), ("mow", 2), ("hack", 2), ("saw", 2),
                                                                  ("tap", 2), ("slice", 3)])


def wordnet(tmp_path: Path) -> build.WordNet:
    return build.WordNet(tiny_wordnet(tmp_path / "dict", DATA_VERB, DATA_NOUN, INDEX_VERB, INDEX_NOUN, CNTLIST))


def library(tmp_path: Path) -> Library:
    return tiny_library(tmp_path / "lib.yaml", LIBRARY)


def test_the_tools_a_verb_is_named_for_are_implements_its_word_names_first(tmp_path: Path) -> None:
    net = wordnet(tmp_path)
    assert net.tools("mow", "00000300") == ["lawn_mower", "mower"]
    assert net.tools("saw", "00000500") == ["saw"]
    assert net.tools("hack", "00000400") == []
    assert net.tools("tap", "00000600") == []      # "tap" is first a faucet


def test_a_verb_named_for_a_tool_of_another_type_takes_no_frame_with_an_instrument(tmp_path: Path) -> None:
    found = {unit for frame, unit, _ in build.derive_wordnet(wordnet(tmp_path), library(tmp_path))}
    assert found == {"hack", "tap"}                # mow, saw: a mower, a saw are no cutters of the library
