"""``scripts/build_lexical_units.py --wordnet``, rule 13 (words26): a verb named for a tool whose kind WordNet names
by a gerund ("cleaning_implement") does what the kind is named for, when the gerund is a frame's own first verb; rule
11 still holds (a frame with an instrument keeps it only for a tool of the instrument's type). Read from a tiny
WordNet ``dict`` folder written here, in WordNet's own file formats."""

from __future__ import annotations

import sys
from pathlib import Path

from seal_cli.frames.library import Library
from tests.conftest import tiny_library, tiny_wordnet

ROOT = Path(__file__).resolve().parents[2]
sys.path.insert(0, str(ROOT / "scripts"))

import build_lexical_units as build  # noqa: E402

# Clean done with any cleaning tool (a swab is one), or only at a sink (a washer): the library's own Clean
LIBRARY = """\
categories: {{tool: [swab], washer: [sink], object: ~}}
frames:
  - frame: Clean
    lexical_units: [clean]
    elements: {{theme: {{type: object}}, instrument: {{type: {instrument}, default: {default}}}}}
    postconditions: [clean(theme)]
  - frame: Slice
    lexical_units: [slice]
    elements: {{theme: {{type: object}}}}
    postconditions: [sliced(theme)]
"""

# clean.v.01 and slice.v.01; swab (named for a swab, a cleaning_implement), shave (named for a razor, a
# cutting_implement: "cutting" is no frame's own verb), paint (named for a brush, an implement of no kind by a
# gerund); absorb, a verb of no frame, is swab's hypernym (as WordNet's mop.v.01 < absorb.v.04)
DATA_VERB = """\
00000100 35 v 01 clean 0 000 | make clean
00000200 35 v 01 slice 0 000 | cut into slices
00000300 35 v 01 absorb 0 001 ~ 00000400 v 0000 | take in
00000400 35 v 01 swab 0 002 @ 00000300 v 0000 + 00001200 n 0101 | wipe up with a swab
00000500 35 v 01 shave 0 001 + 00001400 n 0101 | remove hair with a razor
00000600 35 v 01 paint 0 001 + 00001500 n 0101 | make a picture with a brush
"""
DATA_NOUN = """\
03563967 06 n 01 implement 0 000 | an instrumentality
00001100 06 n 01 cleaning_implement 0 001 @ 03563967 n 0000 | an implement used in cleaning
00001200 06 n 01 swab 0 001 @ 00001100 n 0000 | cleaning implement of absorbent material
00001300 06 n 01 cutting_implement 0 001 @ 03563967 n 0000 | a tool used for cutting
00001400 06 n 01 razor 0 001 @ 00001300 n 0000 | edge tool used in shaving
00001500 06 n 01 brush 0 001 @ 03563967 n 0000 | an implement with bristles
"""
INDEX_VERB = "".join(f"{lemma} v 1 1 @ 1 1 {offset}\n" for lemma, offset in [
    ("absorb", "00000300"), ("clean", "00000100"), ("paint", "00000600"), ("shave", "00000500"),
    ("slice", "00000200"), ("swab", "00000400")])
INDEX_NOUN = "".join(f"{lemma} n 1 0 1 0 {offset}\n" for lemma, offset in [
    ("brush", "00001500"), ("cleaning_implement", "00001100"), ("cutting_implement", "00001300"),
    ("implement", "03563967"), ("razor", "00001400"), ("swab", "00001200")])
CNTLIST = "".join(f"{lemma}%2:35:00:: 1 {n}\n" for lemma, n in [("clean", 9), ("slice", 3), ("absorb", 4),
                                                                  ("swab", 2), ("shave", 2), ("paint", 2)])


def wordnet(tmp_path: Path) -> build.WordNet:
    return build.WordNet(tiny_wordnet(tmp_path / "dict", DATA_VERB, DATA_NOUN, INDEX_VERB, INDEX_NOUN, CNTLIST))


def library(tmp_path: Path, instrument: str, default: str) -> Library:
    return tiny_library(tmp_path / f"lib-{instrument}.yaml", LIBRARY.format(instrument=instrument, default=default))


def test_the_kinds_of_a_verbs_tool_are_its_implements_hypernyms(tmp_path: Path) -> None:
    net = wordnet(tmp_path)
    assert net.tool_kinds("swab", "00000400") == [("swab", "swab"), ("swab", "cleaning_implement"),
                                                  ("swab", "implement")]
    assert ("razor", "cutting_implement") in net.tool_kinds("shave", "00000500")


def test_a_verb_named_for_a_cleaning_tool_cleans_when_the_frame_takes_that_tool(tmp_path: Path) -> None:
    found = {(frame, unit): rest for frame, unit, *rest in
             build.derive_wordnet(wordnet(tmp_path), library(tmp_path, "tool", "swab"))}
    # shave: "cutting" is no frame's own verb (Slice's is "slice"); paint: a brush is of no kind named by a gerund
    assert set(found) == {("Clean", "swab")}
    source, *said = found[("Clean", "swab")]
    assert source == "wordnet:swab.v.01 named for swab (cleaning_implement: clean)"
    assert said[-1] is True                                # opening: read only opening an imperative


def test_the_tool_must_be_of_the_instruments_type(tmp_path: Path) -> None:
    """The library's Clean washes a held thing at a sink (its instrument a washer): a swab is none, so rule 11
    refuses the unit, as it refuses "mow" for Slice; "mop the floor" stays an unknown verb."""
    found = build.derive_wordnet(wordnet(tmp_path), library(tmp_path, "washer", "sink"))
    assert not [unit for unit in found if unit[1] == "swab"]
