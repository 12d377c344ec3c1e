#!/usr/bin/env python3
"""Rebuild ``seal_cli/language/premises.txt``: the nouns that name a part of a home or a building one goes to (a
room, a hallway, a floor, a garage, a porch, a garden), from WordNet 3.0's noun hierarchy, one a line
(read by ``seal_cli/language/premises.py``).

A command said as a bare phrase ("kitchen, now", "bathroom, quick") asks the robot to go there when the phrase names
such a place, and asks for the thing otherwise ("towel. bathroom. quick", "keys, now": bring it; words27). The
category ``room`` of ``types.yaml`` is open (a map names its rooms), so it cannot say which words are places; this
list is closed, and no category of the library (it adds no class the taxonomy would then know). A noun is written
when it is one word of letters, written in lower case, and either its first sense (WordNet orders senses by how
often they were tagged; at least one was) or, for a noun never tagged, every sense of it is a hyponym of one of
:data:`PREMISES` — area.n.05 ("kitchen", "bedroom", "patio": rooms are areas of a structure), corridor.n.01
("hallway", "hall"), building.n.01 ("garage", "shed"), floor.n.02 ("attic", "cellar"), porch.n.01 or garden.n.01.
The first sense decides for tagged nouns: "study" (first a piece of research) and "lounge" (first a sofa) stay out,
"kitchen" and "hall" (first a hallway) are in. A sense that is also a kind of :data:`STORES` -- container.n.01 or
storage_space.n.01, what things are kept in -- is out unless it is a room as well: "drawer" and "cupboard" (areas of
storage space) are things one opens, not places one goes to ("drawer, now" asks for the drawer), "pantry" (a
storeroom, a room) stays in (words29). The data itself (WordNet's files) is read only here, never by the
parser. ``--check`` exits 1 when the shipped file differs.

    python scripts/build_room_nouns.py --wordnet /usr/share/wordnet [--check]
"""

from __future__ import annotations

from pathlib import Path

from build_clothing_nouns import nouns_whose_senses  # scripts/build_clothing_nouns.py, beside this script
from build_person_nouns import Nouns  # scripts/build_person_nouns.py, beside this script
from rebuilt import wordnet_arguments, write_or_check  # scripts/rebuilt.py, beside this script

ROOT = Path(__file__).resolve().parent.parent
OUT = ROOT / "seal_cli" / "language" / "premises.txt"
PREMISES = ("02735688", "03112099", "02913152", "03365991", "03984381", "03417345")
# area.n.05, corridor.n.01, building.n.01, floor.n.02, porch.n.01, garden.n.01
STORES = ("03094503", "04328946")
# container.n.01, storage_space.n.01: what things are kept in ("drawer", "cupboard": WordNet files both under storage
# space, an area); such a sense is no place one goes to unless it is also a room ("pantry", "storeroom"; words29)
ROOM = "04105893"
# room.n.01
HEADER = """\
# Nouns that name a part of a home or a building one goes to, derived from WordNet 3.0's noun hierarchy
# (Princeton University, WordNet 3.0 license): the first sense of each (every sense, for a noun never tagged)
# is a kind of area.n.05, corridor.n.01, building.n.01, floor.n.02, porch.n.01 or garden.n.01, and no kind of
# container.n.01 or storage_space.n.01 unless also of room.n.01.
# Written by scripts/build_room_nouns.py --wordnet DIR: rebuild it, do not edit it by hand.
"""


def render(found: list[str]) -> str:
    """The data file: the header, then one noun a line."""
    return HEADER + "".join(f"{noun}\n" for noun in found)


def room_nouns(nouns: Nouns) -> list[str]:
    """The nouns the module's rules keep, sorted (the rule of ``build_clothing_nouns``, other roots), less the
    places things are kept in that are no room (:data:`STORES`)."""
    is_place, is_store, is_room = nouns.kind_of(PREMISES), nouns.kind_of(STORES), nouns.kind_of((ROOM,))
    return nouns_whose_senses(nouns, lambda o: is_place(o) and not (is_store(o) and not is_room(o)))


def main() -> int:
    args = wordnet_arguments(__doc__.splitlines()[0], OUT, ("data.noun", "index.noun", "cntlist.rev"))
    if args is None:
        return 1
    found = room_nouns(Nouns(args.wordnet))
    return write_or_check(args.out, render(found), check=args.check, made_from="WordNet",
                          summary=f"{len(found)} nouns")


if __name__ == "__main__":
    raise SystemExit(main())
