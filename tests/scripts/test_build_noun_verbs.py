"""``scripts/build_lexical_units.py --wordnet``, rule 12 (words21): a verb that is mostly a noun ("dust", "vacuum")
takes the frame whose own verb's first sense it is, or a way of doing it, or a unit's first sense ("stick" =
deposit), marked ``opening: true`` (the parser reads it only opening an imperative before its object); read from a
tiny WordNet ``dict`` folder written here, in WordNet's own file formats."""

from __future__ import annotations

import sys
from pathlib import Path

from seal_cli.frames.library import Library
from seal_cli.frames.reading import read_library
from tests.conftest import tiny_library, tiny_wordnet

ROOT = Path(__file__).resolve().parents[2]
sys.path.insert(0, str(ROOT / "scripts"))

import build_lexical_units as build  # noqa: E402

LIBRARY = """\
categories: {location: [room], object: ~}
frames:
  - frame: Clean
    lexical_units: [clean, wet]
    elements: {theme: {type: object}}
    postconditions: [clean(theme)]
  - frame: Go
    lexical_units: [go]
    elements: {goal: {type: location}}
  - frame: Place
    lexical_units: [put, deposit]
    elements: {theme: {type: object}, goal: {type: location}}
"""

# clean.v.01 and its kinds: dust (mostly a noun), hoover (no verb of the parser's tables), scrub (mostly a verb: the
# older rules); wet.v.01 (Clean lists "wet", but its first unit is "clean") and its kind water; go.v.01 and its kind
# wind (Go's first element is a goal, no thing an object names); stick (mostly a noun), whose first sense is the first
# sense of "deposit", a unit of Place alone
DATA_VERB = """\
00000100 35 v 01 clean 0 003 ~ 00000200 v 0000 ~ 00000300 v 0000 ~ 00000400 v 0000 | make clean
00000200 35 v 01 dust 0 001 @ 00000100 v 0000 | remove the dust from
00000300 35 v 01 hoover 0 001 @ 00000100 v 0000 | clean with a vacuum cleaner
00000400 35 v 01 scrub 0 001 @ 00000100 v 0000 | clean by rubbing
00000500 35 v 01 wet 0 001 ~ 00000600 v 0000 | cause to become wet
00000600 35 v 01 water 0 001 @ 00000500 v 0000 | supply with water
00000700 38 v 01 go 0 001 ~ 00000800 v 0000 | move
00000800 38 v 01 wind 0 001 @ 00000700 v 0000 | to move or cause to move in a sinuous course
00000900 35 v 01 put 0 000 | put into a certain place
00001000 35 v 02 stick 0 deposit 0 000 | put, fix, force, or implant
"""
DATA_NOUN = """\
03563967 06 n 01 implement 0 000 | an instrumentality
"""
INDEX_VERB = "".join(f"{lemma} v 1 1 @ 1 {tagged} {offset}\n" for lemma, tagged, offset in [
    ("clean", 1, "00000100"), ("dust", 1, "00000200"), ("go", 1, "00000700"), ("hoover", 0, "00000300"),
    ("scrub", 1, "00000400"), ("water", 1, "00000600"), ("wet", 1, "00000500"), ("wind", 1, "00000800"),
    ("put", 1, "00000900"), ("deposit", 1, "00001000"), ("stick", 1, "00001000")])
INDEX_NOUN = "".join(f"{lemma} n 2 0 2 2 0000{n}100 0000{n}200\n" for n, lemma in enumerate(
    ["dust", "water", "wind", "stick"], start=1))
CNTLIST = "".join(f"{lemma}%2:35:00:: 1 {n}\n" for lemma, n in [("clean", 9), ("dust", 2), ("scrub", 3), ("wet", 4),
                                                                  ("water", 2), ("go", 9), ("wind", 2)])


def wordnet(tmp_path: Path) -> build.WordNet:
    return build.WordNet(tiny_wordnet(tmp_path / "dict", DATA_VERB, DATA_NOUN, INDEX_VERB, INDEX_NOUN, CNTLIST))


def library(tmp_path: Path) -> Library:
    return tiny_library(tmp_path / "lib.yaml", LIBRARY)


def test_a_verb_that_is_mostly_a_noun_takes_the_frame_of_its_first_units_sense_read_only_opening(
        tmp_path: Path) -> None:
    net = wordnet(tmp_path)
    assert not net.mostly_verb("dust") and net.mostly_verb("scrub")
    found = {(unit, frame): rest for frame, unit, _, *rest in build.derive_wordnet(net, library(tmp_path))}
    # not water (wet is no frame's first unit), wind (Go's first element is a goal), scrub (mostly a verb: rules
    # 2-4 only, and no other verb of the library supports clean.v.01, rule 4)
    assert set(found) == {("dust", "Clean"), ("hoover", "Clean"), ("stick", "Place")}   # stick = deposit.v.01
    assert found[("dust", "Clean")][-1] is True and found[("hoover", "Clean")][-1] is True   # opening: true


def test_the_opening_mark_is_written_and_read_back(tmp_path: Path) -> None:
    text = build.render(sorted(build.derive_wordnet(wordnet(tmp_path), library(tmp_path))))
    assert '{frame: Clean, unit: dust, source: "wordnet:dust.v.01 < clean.v.01 (clean); mostly a noun", ' \
           'opening: true}' in text
    (tmp_path / "units.yaml").write_text(text)
    found, problems = read_library([tmp_path / "lib.yaml", tmp_path / "units.yaml"])
    assert problems == []
    clean = found.by_name["Clean"]
    assert {u.text: u.opening for u in clean.lexical_units} == {
        "clean": False, "wet": False, "dust": True, "hoover": True}


def test_a_word_never_tagged_takes_its_first_sense_that_reaches_a_frame(tmp_path: Path) -> None:
    """Rule 12 for a word WordNet's corpus never tagged, as verb or noun (words24: "nuke", "zap"): the order of its
    senses says nothing of use, so its first sense that reaches a frame counts, as rule 2 does for such verbs. A word
    tagged as a noun keeps its first sense only."""
    folder = tmp_path / "dict"
    folder.mkdir()
    extra = ("00001100 33 v 01 zapp 0 000 | strike with a ray\n"
             "00001200 35 v 02 zapp 0 bedd 0 001 @ 00000100 v 0000 | clean with a ray\n"
             "00001300 35 v 01 bedd 0 000 | furnish with a bed\n")
    index = INDEX_VERB + "bedd v 2 1 @ 2 0 00001300 00001200\nzapp v 2 1 @ 2 0 00001100 00001200\n"
    index = "".join(sorted(index.splitlines(keepends=True)))
    for name, text in [("data.verb", DATA_VERB + extra), ("data.noun", DATA_NOUN), ("index.verb", index),
                       ("index.noun", INDEX_NOUN + "bedd n 1 0 1 1 00009100\n"),
                       ("cntlist.rev", CNTLIST + "bedd%1:06:00:: 1 5\n")]:
        (folder / name).write_text(text)
    net = build.WordNet(folder)
    found = {(unit, frame): source for frame, unit, source, *_ in build.derive_wordnet(net, library(tmp_path))}
    assert found[("zapp", "Clean")] == "wordnet:zapp.v.02 < clean.v.01 (clean); no verb's forms, never tagged"
    assert ("bedd", "Clean") not in found          # tagged as a noun: its first sense, which reaches nothing
    assert ("dust", "Clean") in found and ("stick", "Place") in found
