#!/usr/bin/env python3
"""Rebuild ``framelib/wordnet_clothing.yaml``: the nouns that name what people wear, from WordNet 3.0's
noun hierarchy, as the library's ``clothing`` category.

After a person, "in" and such a noun say what the person wears, not where they are: "greet the man *in the
black jacket*" (the theme described, no ground), while "greet the man in the kitchen" says where. A noun is
written when it is one word of letters, written in lower case, and either its first sense (WordNet orders
senses by how often they were tagged; at least one was) or, for a noun never tagged, every sense of it is a
hyponym of one of :data:`WORN` — clothing.n.01 ("jacket", "hat", "dress"), footwear.n.02 ("shoe", "boot")
or handwear.n.01 ("glove"). The first sense decides for tagged nouns because a person "in a coat" means
the garment, not a coat of paint ("jacket", "coat" and "hat" have senses of other kinds). The data itself
(WordNet's files) is read only here, never by the parser. ``--check`` exits 1 when the shipped file differs.

    python scripts/build_clothing_nouns.py --wordnet /usr/share/wordnet [--check]
"""

from __future__ import annotations

from collections.abc import Callable
from pathlib import Path

from build_person_nouns import Nouns, render  # scripts/build_person_nouns.py, beside this script
from rebuilt import wordnet_arguments, write_or_check  # scripts/rebuilt.py, beside this script

ROOT = Path(__file__).resolve().parent.parent
OUT = ROOT / "framelib" / "wordnet_clothing.yaml"
WORN = ("03051540", "03380867", "02799897")     # clothing.n.01, footwear.n.02, handwear.n.01
HEADER = """\
# Nouns that name what people wear, derived from WordNet 3.0's noun hierarchy (Princeton University,
# WordNet 3.0 license): the first sense of each (every sense, for a noun never tagged) is a kind of
# clothing.n.01, footwear.n.02 or handwear.n.01.
# Written by scripts/build_clothing_nouns.py --wordnet DIR: rebuild it, do not edit it by hand.
"""


def clothing_nouns(nouns: Nouns, roots: tuple[str, ...] = WORN) -> list[str]:
    """The nouns the module's rules keep, sorted."""
    return nouns_whose_senses(nouns, nouns.kind_of(roots))


def nouns_whose_senses(nouns: Nouns, is_kind: Callable[[str], bool]) -> list[str]:
    """The one-word, lower-case nouns whose first sense (every sense, for a noun never tagged) ``is_kind``, sorted."""
    found = []
    for noun, offsets in nouns.senses.items():
        if not (noun.isalpha() and noun in nouns.lower and offsets):
            continue
        if is_kind(offsets[0]) if nouns.was_tagged(noun) else all(map(is_kind, offsets)):
            found.append(noun)
    return sorted(found)


def main() -> int:
    args = wordnet_arguments(__doc__.splitlines()[0], OUT, ("data.noun", "index.noun", "cntlist.rev"))
    if args is None:
        return 1
    text = render(HEADER, "clothing", clothing_nouns(Nouns(args.wordnet)))
    return write_or_check(args.out, text, check=args.check, made_from="WordNet",
                          summary=f"{text.count(chr(10) + '    - ')} nouns")


if __name__ == "__main__":
    raise SystemExit(main())
