"""``scripts/build_lexical_units.py --wordnet``, rules 15 and 16 (alfred29), read from a tiny WordNet ``dict`` folder
written here, in WordNet's own file formats: a verb that is mostly a noun takes frame F when its first sense is a kind
of a synset two library verbs of F alone name ("trash" < discard, throw away); a verb whose first sense takes no object
takes F through a sense that *causes* it and is a kind of F's own verb ("stand the vase on the shelf")."""

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
  - frame: Place
    lexical_units: [put, discard, throw away, get rid of]
    elements: {theme: {type: object}, goal: {type: location}}
  - frame: Pick
    lexical_units: [pick up, remove]
    elements: {theme: {type: object}}
"""

# put.v.01; discard.v.01 (discard, throw away: two units of Place alone) and its kind trash (mostly a noun);
# get_rid_of.v.01 (get rid of: Place, remove: Pick) and its kind ditch (mostly a noun); stand: first "be upright",
# then "place upright", a kind of put.v.01 that causes it (">"); lean: "incline", then "cause to lean", a kind of
# put.v.01 with no cause pointer
DATA_VERB = """\
00000100 35 v 01 put 0 003 ~ 00000300 v 0000 ~ 00000600 v 0000 ~ 00000400 v 0000 | put into a certain place
00000200 40 v 02 discard 0 throw_away 0 001 ~ 00000250 v 0000 | throw or cast away
00000250 40 v 01 trash 0 001 @ 00000200 v 0000 | dispose of something useless
00000300 35 v 02 stand 0 stand_up 0 002 @ 00000100 v 0000 > 00000400 v 0000 | put into an upright position
00000400 35 v 01 stand 0 000 | be upright
00000500 38 v 01 lean 0 000 | incline or bend from a vertical position
00000600 35 v 01 lean 0 001 @ 00000100 v 0000 | cause to lean or incline
00000700 40 v 02 get_rid_of 0 remove 0 001 ~ 00000800 v 0000 | dispose of
00000800 40 v 01 ditch 0 001 @ 00000700 v 0000 | throw away
"""
DATA_NOUN = """\
03563967 06 n 01 implement 0 000 | an instrumentality
"""
INDEX_VERB = "".join(sorted(f"{lemma} v {len(offsets)} 1 @ {len(offsets)} {tagged} {' '.join(offsets)}\n"
                            for lemma, tagged, offsets in [
    ("put", 1, ["00000100"]), ("discard", 1, ["00000200"]), ("throw_away", 1, ["00000200"]),
    ("trash", 0, ["00000250"]), ("stand", 2, ["00000400", "00000300"]), ("stand_up", 1, ["00000300"]),
    ("lean", 2, ["00000500", "00000600"]), ("get_rid_of", 1, ["00000700"]), ("remove", 1, ["00000700"]),
    ("ditch", 0, ["00000800"])]))
INDEX_NOUN = "ditch n 1 0 1 1 00009100\ntrash n 1 0 1 1 00009200\n"
CNTLIST = "".join(f"{key} 1 {n}\n" for key, n in [
    ("put%2:35:00::", 9), ("discard%2:40:00::", 3), ("stand%2:35:00::", 8), ("lean%2:38:00::", 4),
    ("remove%2:40:00::", 5), ("trash%1:27:00::", 4), ("ditch%1:17:00::", 3)])


def wordnet(tmp_path: Path) -> build.WordNet:
    return build.WordNet(tiny_wordnet(tmp_path / "dict", DATA_VERB, DATA_NOUN, INDEX_VERB, INDEX_NOUN, CNTLIST))


def library(tmp_path: Path) -> Library:
    return tiny_library(tmp_path / "lib.yaml", LIBRARY)


def found(tmp_path: Path) -> dict[tuple[str, str], list[object]]:
    return {(unit, frame): [source, *rest] for frame, unit, source, *rest in
            build.derive_wordnet(wordnet(tmp_path), library(tmp_path))}


def test_a_kind_of_a_synset_two_verbs_of_one_frame_name_is_that_frame(tmp_path: Path) -> None:
    units = found(tmp_path)
    assert units[("trash", "Place")][0] == "wordnet:trash.v.01 < discard.v.01 (discard); mostly a noun"
    assert units[("trash", "Place")][-1] is True                      # opening: read only before its object
    assert not any(unit == "ditch" for unit, _ in units)             # get rid of (Place), remove (Pick): two frames


def test_a_sense_that_causes_the_first_and_is_a_way_of_putting_is_a_place(tmp_path: Path) -> None:
    units = found(tmp_path)
    assert units[("stand", "Place")][0] == "wordnet:stand.v.02 < put.v.01 (put), causing stand.v.01"
    assert units[("stand", "Place")][-1] is True
    assert not any(unit == "lean" for unit, _ in units)               # no cause pointer: its first sense only


def test_python_s_builtins_are_no_closed_class_words() -> None:
    closed = build.closed_class_words()
    assert "near" in closed and "back" in closed
    assert not {"bin", "hash", "list", "quit", "float"} & closed      # names of __builtins__, not English
    assert "stand" in closed and "stand" not in build.closed_class_words(phrases=False)   # "where does it stand"
