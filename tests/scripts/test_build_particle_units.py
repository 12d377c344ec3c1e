"""``scripts/build_lexical_units.py --wordnet``, rules 8 and 9 (words16): a particle verb sharing a library particle
unit's first sense ("turn out" as "turn off"), and a particle that names a state after a verb that causes one ("put
the kettle *on*"), on a tiny WordNet and library of their own."""

from __future__ import annotations

import sys
from collections import defaultdict
from pathlib import Path

from seal_cli.frames.library import Library
from seal_cli.frames.reading import read_library

ROOT = Path(__file__).resolve().parents[2]
sys.path.insert(0, str(ROOT / "scripts"))

import build_lexical_units as build  # noqa: E402

LIBRARY = """\
categories: {toggleable: [lamp], object: ~, location: ~}
frames:
  - frame: ToggleOn
    lexical_units: [turn on]
    elements: {theme: {type: toggleable}}
    postconditions: [toggled_on(theme)]
  - frame: ToggleOff
    lexical_units: [turn off]
    elements: {theme: {type: toggleable}}
    postconditions: [not toggled_on(theme)]
  - frame: Place
    lexical_units: [put, stack]
    elements: {theme: {type: object}, goal: {type: location}}
    postconditions: [in(theme, goal)]
"""


class TinyWordNet:
    """What the two rules read of WordNet: senses in order, synsets' lemmas, hypernyms, antonyms."""

    def __init__(self) -> None:
        self.lemmas = {"on1": ["turn on", "switch on"], "off1": ["turn off", "switch off", "turn out"],
                       "put1": ["put", "place"], "put2": ["put"], "change1": ["change"], "stack1": ["stack"],
                       "out1": ["turn out", "produce"]}
        self.senses = {"turn on": (1, ["on1"]), "turn off": (1, ["off1"]), "turn out": (1, ["out1", "off1"]),
                       "put": (1, ["put1", "put2"]), "stack": (1, ["stack1"]), "change": (1, ["change1"])}
        self.up: dict[str, list[str]] = defaultdict(list, {"put2": ["change1"]})
        self.opposite: dict[str, set[str]] = defaultdict(set, {"on1": {"off1"}, "off1": {"on1"}})
        self.adjective_opposites = {("on", "off"), ("off", "on")}

    def name(self, lemma: str, offset: str) -> str:
        return f"{lemma.replace(' ', '_')}.v.{self.senses[lemma][1].index(offset) + 1:02d}"


def library(tmp_path: Path) -> Library:
    (tmp_path / "lib.yaml").write_text(LIBRARY)
    found, problems = read_library([tmp_path])
    assert problems == []
    return found


def test_a_particle_verb_in_the_first_sense_of_the_same_verb_s_unit_takes_its_frame(tmp_path: Path) -> None:
    lib = library(tmp_path)
    found = build.particle_verbs(TinyWordNet(), lib, lib)   # type: ignore[arg-type]
    assert found == [("ToggleOff", "turn out", "wordnet:turn_out.v.02 = turn_off.v.01 (turn off)")]


def test_a_state_particle_after_a_verb_that_causes_a_state_is_the_state_s_unit(tmp_path: Path) -> None:
    lib = library(tmp_path)
    found = build.state_particles(TinyWordNet(), lib, lib)   # type: ignore[arg-type]
    assert [(frame, unit, split) for frame, unit, _, _, _, split in found] == [
        ("ToggleOff", "put off", True), ("ToggleOn", "put on", True)]   # "stack" causes no state: none of its own
    assert "put.v.02 < change.v.01" in found[1][2]


def test_without_antonymous_adjectives_no_particle_names_a_state(tmp_path: Path) -> None:
    wordnet = TinyWordNet()
    wordnet.adjective_opposites = set()
    assert build.state_particles(wordnet, library(tmp_path), library(tmp_path)) == []   # type: ignore[arg-type]
