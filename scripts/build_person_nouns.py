#!/usr/bin/env python3
"""Rebuild ``framelib/wordnet_people.yaml``: the nouns that name people, from WordNet 3.0's noun
hierarchy, added to the library's ``person`` category (``framelib/types.yaml`` lists the household
ones by hand: guest, son, nurse, ...).

A phrase whose head is a person noun is a person to the parser ("go with *the plumber*" is Follow,
as "go with Sam" is; "go with the cart" stays a Go). A noun is written when, conservatively:

1. it is one word of letters, written in lower case (no proper name, no "Floridian"), and WordNet's
   corpus tagged at least one of its senses (a noun nobody was seen using is left out);
2. *every* sense of it is a hyponym of ``person.n.01``: "pitcher" (a ballplayer and a jug),
   "cleaner" (a worker and a substance), "batter" (a ballplayer and a mixture), "controller" (an
   accountant and a device), "maker" are out, since a thing the robot handles must never be read
   as a person (requiring only the *tagged* senses to be people let "batter", "controller" and
   "maker" in: WordNet's corpus tagged few senses of things);
3. no sense of it carries a usage label (WordNet's ``;u`` pointer: ethnic slur, slang,
   disparagement) or a gloss saying it is offensive, derogatory, slang or informal.

Rules 2 and 3 leave out the everyday informal ways of naming a man, a woman or a child: "guy" (also a
rope, and "an informal term"), "fellow" ("one of a pair"), "chap" (a crack in the lip), "dude", "kid"
(a goat). So a noun is also written when (4) its *first* sense, the one WordNet's corpus met most, is a
person named by sex or age alone (``SEX_OR_AGE``: man, woman, male, female, child, boy, girl, adult,
juvenile, young person) or directly below one; its corpus uses are more often that person than
anything else (or, none tagged, every sense is a person: "dude"); and none of its *person* senses is
uncivil: a gloss that is offensive, derogatory or slang, or a usage label other than colloquialism
("informal" and "colloquial" are a register, not an insult). "tart" (first a woman, also a pastry,
neither tagged), "host" (11 tags a person, 13 a thing) and "boy" (a sense that is a slur) stay out of
this rule; "pitcher" and "batter" stay out, their first sense a ballplayer, not a man.

Each noun is written once, sorted, with the header naming the source; the data itself (WordNet's
files) is read only here, never by the parser. ``--check`` exits 1 when the shipped file differs.

    python scripts/build_person_nouns.py --wordnet /usr/share/wordnet [--check]

(Debian's ``wordnet-base`` installs WordNet 3.0 at ``/usr/share/wordnet``.)
"""

from __future__ import annotations

import re
from collections import defaultdict
from collections.abc import Callable
from pathlib import Path

from rebuilt import wordnet_arguments, write_or_check  # scripts/rebuilt.py, beside this script

ROOT = Path(__file__).resolve().parent.parent
OUT = ROOT / "framelib" / "wordnet_people.yaml"
PERSON = "00007846"                      # person.n.01: a human being
RUDE = re.compile(r"offensive|derogatory|disparag|slang|vulgar|contempt|obscen|insult|abusive|informal")
SEX_OR_AGE = ("10287213", "10787470", "09624168", "09619168",  # man.n.01, woman.n.01, male.n.02, female.n.02
              "09917593", "10285313", "10129825", "10084295",  # child.n.01, male_child.n.01, girl.n.01,
              "09605289", "09622049", "10804406")              # female_child.n.01, adult.n.01, juvenile.n.01,
#                                                                 young_person.n.01
UNCIVIL = re.compile(r"offensive|derogatory|disparag|slang|vulgar|contempt|obscen|insult|abusive")
REGISTER = "colloquialism"               # the one usage label that is a register, not an insult
HEADER = """\
# Nouns that name people, derived from WordNet 3.0's noun hierarchy (Princeton University, WordNet 3.0
# license): every sense of each is a kind of person.n.01.
# Written by scripts/build_person_nouns.py --wordnet DIR: rebuild it, do not edit it by hand.
# The category merges with `person` of types.yaml (a category declared twice takes the union).
"""


class Nouns:
    """WordNet's noun synsets: each one's hypernyms, whether it is labelled rude, and each noun's
    senses in WordNet's order with how often each was tagged."""

    def __init__(self, folder: Path) -> None:
        self.up: dict[str, list[str]] = defaultdict(list)
        self.rude: set[str] = set()
        self.lower: set[str] = set()                       # nouns WordNet writes in lower case somewhere
        self.uncivil: set[str] = set()                     # an insult: not only a register (``REGISTER``)
        labels: dict[str, list[str]] = defaultdict(list)   # synset -> the synsets of its usage labels
        first_word: dict[str, str] = {}
        for line in (folder / "data.noun").read_text(encoding="latin-1").splitlines():
            if line.startswith(" "):
                continue                                   # the licence, at the top
            fields, _, gloss = line.partition(" | ")
            head = fields.split()
            offset, at = head[0], 4 + 2 * int(head[3], 16)
            self.lower.update(word for word in head[4:at:2] if word.islower())
            first_word[offset] = head[4]
            for j in range(int(head[at])):
                symbol, target, pos = head[at + 1 + 4 * j: at + 4 + 4 * j]
                if pos == "n" and symbol == "@":
                    self.up[offset].append(target)
                elif symbol == ";u":
                    self.rude.add(offset)                  # a usage label: slur, slang, disparagement
                    labels[offset].append(target)
            if RUDE.search(gloss):
                self.rude.add(offset)
            if UNCIVIL.search(gloss):
                self.uncivil.add(offset)
        self.uncivil.update(offset for offset, of in labels.items()
                            if any(first_word.get(label) != REGISTER for label in of))
        self.senses: dict[str, list[str]] = {}
        for line in (folder / "index.noun").read_text(encoding="latin-1").splitlines():
            if line.startswith(" "):
                continue
            parts = line.split()
            count, pointers = int(parts[2]), int(parts[3])
            self.senses[parts[0]] = parts[6 + pointers: 6 + pointers + count]
        self.tagged: set[tuple[str, int]] = set()          # (noun, sense number) tagged at least once
        self.count: dict[tuple[str, int], int] = {}         # (noun, sense number) -> times tagged
        for line in (folder / "cntlist.rev").read_text(encoding="latin-1").splitlines():
            key, number, count = line.split()
            lemma, _, kind = key.partition("%")
            if kind.startswith("1:") and int(count) > 0:
                self.tagged.add((lemma, int(number)))
                self.count[lemma, int(number)] = self.count.get((lemma, int(number)), 0) + int(count)

    def kind_of(self, roots: tuple[str, ...]) -> Callable[[str], bool]:
        """Whether a synset is one of ``roots`` or a hyponym of one (through its hypernyms), remembered."""
        known: dict[str, bool] = dict.fromkeys(roots, True)

        def below(offset: str) -> bool:
            if offset not in known:
                known[offset] = False                      # cut cycles while the answer is open
                known[offset] = any(below(up) for up in self.up[offset])
            return known[offset]
        return below

    def was_tagged(self, noun: str) -> bool:
        """Whether WordNet's corpus tagged any sense of the noun."""
        return any((noun, n) in self.tagged for n in range(1, len(self.senses[noun]) + 1))


def person_nouns(nouns: Nouns) -> list[str]:
    """The nouns the module's rules keep, sorted."""
    is_person = nouns.kind_of((PERSON,))
    found = []
    for noun, offsets in nouns.senses.items():
        if not (noun.isalpha() and noun in nouns.lower):
            continue
        every_sense = nouns.was_tagged(noun) and all(map(is_person, offsets)) and \
            not any(o in nouns.rude for o in offsets)
        if every_sense or names_by_sex_or_age(nouns, noun, is_person):
            found.append(noun)
    return sorted(found)


def names_by_sex_or_age(nouns: Nouns, noun: str, is_person: Callable[[str], bool]) -> bool:
    """Rule 4: the noun's first sense is a man, woman or child named informally (at or just below
    ``SEX_OR_AGE``), its tagged uses are mostly people, and none of its person senses is uncivil."""
    offsets = nouns.senses[noun]
    first = offsets[0]
    if first not in SEX_OR_AGE and not any(up in SEX_OR_AGE for up in nouns.up[first]):
        return False
    if any(is_person(o) and o in nouns.uncivil for o in offsets):
        return False
    people = sum(nouns.count.get((noun, n), 0) for n, o in enumerate(offsets, 1) if is_person(o))
    things = sum(nouns.count.get((noun, n), 0) for n, o in enumerate(offsets, 1) if not is_person(o))
    return people > things or (people == things == 0 and all(map(is_person, offsets)))


def render(header: str, category: str, found: list[str]) -> str:
    """The data file: ``header``, then the nouns ``found`` as the library's category ``category``."""
    lines = [header, "categories:", f"  {category}:"]
    lines += [f"    - {noun}" for noun in found]
    return "\n".join(lines) + "\n"


def main() -> int:
    args = wordnet_arguments(__doc__.splitlines()[0], OUT, ("data.noun", "index.noun", "cntlist.rev"))
    if args is None:
        return 1
    text = render(HEADER, "person", person_nouns(Nouns(args.wordnet)))
    return write_or_check(args.out, text, check=args.check, made_from="WordNet",
                          summary=f"{text.count(chr(10) + '    - ')} nouns")


if __name__ == "__main__":
    raise SystemExit(main())
