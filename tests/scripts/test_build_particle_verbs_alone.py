"""``scripts/build_lexical_units.py --wordnet`` (words32): rule 14, a particle verb whose verb is no unit ("clear
away") takes a frame from its own first sense when the verb alone has a tagged sense there too; and rule 1's tie (as
many tagged senses as a verb as a noun) broken by how often the word was used as a verb ("chuck"). Read from a tiny
WordNet ``dict`` folder written here, in WordNet's own file formats; its synsets made up."""

from __future__ import annotations

import sys
from pathlib import Path

from seal_cli.frames.library import Library
from tests.conftest import tiny_library, tiny_wordnet

ROOT = Path(__file__).resolve().parents[2]
sys.path.insert(0, str(ROOT / "scripts"))

import build_lexical_units as build  # noqa: E402

LIBRARY = """\
categories: {location: [room], object: ~}
frames:
  - frame: Pick
    lexical_units: [remove, withdraw]
    elements: {theme: {type: object}, source: {type: location}}
  - frame: Place
    lexical_units: [put, throw, toss]
    elements: {theme: {type: object}, goal: {type: location}}
"""

# remove.v.01 (remove, withdraw: Pick) and its kinds: "clear away" and clear.v.02 (the verb alone, tagged), "sell out"
# (sell has no sense under remove.v.01); clear.v.01, the first sense of "clear", is no frame's. throw.v.01 (Place)
# and its kind chuck.v.01 = toss.v.03 ("chuck": one tagged sense as a verb, one as a noun, used more as a verb) and
# fling.v.01 ("fling": the same tie, used more as a noun)
DATA_VERB = """\
00000100 35 v 02 remove 0 withdraw 0 003 ~ 00000300 v 0000 ~ 00000400 v 0000 ~ 00000500 v 0000 | take away
00000200 30 v 01 clear 0 000 | rid of obstructions
00000300 35 v 01 clear_away 0 001 @ 00000100 v 0000 | remove from sight
00000400 35 v 01 clear 0 001 @ 00000100 v 0000 | remove
00000500 40 v 01 sell_out 0 001 @ 00000100 v 0000 | give up
00000600 40 v 01 sell 0 000 | exchange for money
00000700 35 v 01 put 0 000 | put into a certain place
00000800 35 v 01 throw 0 002 ~ 00000900 v 0000 ~ 00001000 v 0000 | propel through the air
00000900 35 v 02 chuck 0 toss 0 001 @ 00000800 v 0000 | throw carelessly
00001000 35 v 01 fling 0 001 @ 00000800 v 0000 | throw with force
"""
DATA_NOUN = """\
03563967 06 n 01 implement 0 000 | an instrumentality
"""
INDEX_VERB = """\
clear v 2 1 @ 2 2 00000200 00000400
clear_away v 1 1 @ 1 0 00000300
chuck v 1 1 @ 1 1 00000900
fling v 1 1 @ 1 1 00001000
put v 1 1 @ 1 1 00000700
remove v 1 1 @ 1 1 00000100
sell v 1 1 @ 1 1 00000600
sell_out v 1 1 @ 1 0 00000500
throw v 1 1 @ 1 1 00000800
toss v 3 1 @ 3 1 00002000 00002100 00000900
withdraw v 1 1 @ 1 1 00000100
"""
INDEX_NOUN = """\
chuck n 1 0 1 1 00003000
fling n 1 0 1 1 00003100
"""
CNTLIST = "".join(f"{key} {n} {count}\n" for key, n, count in [
    ("clear%2:30:00::", 1, 9), ("clear%2:35:00::", 2, 2), ("remove%2:35:00::", 1, 9), ("sell%2:40:00::", 1, 9),
    ("throw%2:35:00::", 1, 9), ("put%2:35:00::", 1, 9), ("chuck%2:35:00::", 1, 2), ("chuck%1:06:00::", 1, 1),
    ("fling%2:35:00::", 1, 1), ("fling%1:06:00::", 1, 3)])


def wordnet(tmp_path: Path) -> build.WordNet:
    return build.WordNet(tiny_wordnet(tmp_path / "dict", DATA_VERB, DATA_NOUN, INDEX_VERB, INDEX_NOUN, CNTLIST))


def library(tmp_path: Path) -> Library:
    return tiny_library(tmp_path / "lib.yaml", LIBRARY)


def test_a_particle_verb_of_a_verb_no_frame_lists_takes_the_frame_its_verb_has_a_sense_of(tmp_path: Path) -> None:
    found = {unit: (frame, source) for frame, unit, source, *_ in build.derive_wordnet(wordnet(tmp_path),
                                                                                       library(tmp_path))}
    frame, source = found["clear away"]
    assert frame == "Pick" and "< remove.v.01" in source and "as clear.v.02" in source and "particle verb" in source
    assert "sell out" not in found           # "sell" alone means no removing: the particle makes another verb
    assert "clear" not in found              # its first sense reaches no frame: "clear the table" stays unknown


def test_a_tie_of_tagged_senses_goes_to_how_often_the_word_was_used_as_a_verb(tmp_path: Path) -> None:
    net = wordnet(tmp_path)
    assert net.mostly_verb("chuck") and not net.mostly_verb("fling")
    found = {unit: frame for frame, unit, *_ in build.derive_wordnet(net, library(tmp_path))}
    assert found.get("chuck") == "Place"     # chuck.v.01 < throw.v.01, with "toss" (Place alone) in it
