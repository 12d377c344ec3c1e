#!/usr/bin/env python3
"""Rebuild ``seal_cli/language/verb_objects.tsv``: for each verb WordNet 3.0 lists, how likely it is said with a
direct object, P(object | verb), from WordNet's verb frames weighted by the SemCor sense tag counts it ships.

The parser reads it where a participle could take the noun phrase after it or leave it to the clause's verb: "bring
the kid who's *crying* his teddy" (people cry, they do not cry teddies: the teddy is what is brought), against "bring
the man *wearing* a hat" (the hat is what he wears). WordNet gives each sense of a verb its sentence frames
("Somebody ----s", "Somebody ----s something", ...). A sense *takes an object* when one of its frames, for the
verb's word in that synset, has a noun phrase right after the verb (frames 8-11, 14-21, 24, 25, 30, 31; 5 "Something
----s something Adjective/Noun" too). Then, with ``t`` a sense's tag count (``cntlist.rev``) and each sense counted
``ALPHA`` times besides,

    P(object | verb) = sum over senses that take an object of (t + ALPHA) / sum over all senses of (t + ALPHA)

"cry" 0.14 (its weeping senses are the most tagged), "wait" 0.10, "wear" 0.99, "hold" 0.90. A verb is written when
it is one word of lower-case letters, with the probability to three places and its tag count; the data itself
(WordNet's files) is read only here, never by the parser. ``--check`` exits 1 when the shipped file differs.

    python scripts/build_verb_objects.py --wordnet /usr/share/wordnet [--check]
"""

from __future__ import annotations

from collections import defaultdict
from pathlib import Path

from rebuilt import wordnet_arguments, write_or_check  # scripts/rebuilt.py, beside this script

ROOT = Path(__file__).resolve().parent.parent
OUT = ROOT / "seal_cli" / "language" / "verb_objects.tsv"
ALPHA = 1.0
"""How many tags each sense counts as, before the real ones."""
WITH_OBJECT = frozenset([5, 8, 9, 10, 11, 14, 15, 16, 17, 18, 19, 20, 21, 24, 25, 30, 31])
"""WordNet's verb frames with a noun phrase right after the verb ("Somebody ----s something", "... somebody", ...)."""
HEADER = """\
# P(object | verb): how likely each verb WordNet 3.0 lists is said with a direct object, from its senses' sentence
# frames weighted by WordNet's SemCor sense tag counts (Princeton University, WordNet 3.0 license); each sense counts
# as {alpha} tag besides. Columns: verb, P(object | verb), tags.
# Written by scripts/build_verb_objects.py --wordnet DIR: rebuild it, do not edit it by hand.
"""


def senses(folder: Path) -> dict[str, list[tuple[int, bool]]]:
    """Each verb → its senses as (tag count, takes an object)."""
    tags: dict[str, int] = {}
    for line in (folder / "cntlist.rev").read_text(encoding="latin-1").splitlines():
        key, _, count = line.split()
        tags[key] = int(count)
    found: dict[str, list[tuple[int, bool]]] = defaultdict(list)
    for line in (folder / "data.verb").read_text(encoding="latin-1").splitlines():
        if line.startswith(" "):
            continue                                       # the licence, at the top
        fields = line.partition(" | ")[0].split()
        lexfile, count = fields[1], int(fields[3], 16)
        words = [(fields[4 + 2 * k], int(fields[5 + 2 * k], 16)) for k in range(count)]
        k = 4 + 2 * count
        k += 1 + 4 * int(fields[k])                        # the pointers
        frames: dict[int, set[int]] = defaultdict(set)     # word number (0: every word) → its frames
        for f in range(int(fields[k])):
            _, number, word = fields[k + 1 + 3 * f: k + 4 + 3 * f]
            frames[int(word, 16)].add(int(number))
        for n, (word, lex_id) in enumerate(words, start=1):
            lemma = word.lower()
            key = f"{lemma}%2:{lexfile}:{lex_id:02d}::"
            own = frames[0] | frames[n]
            found[lemma].append((tags.get(key, 0), bool(own & WITH_OBJECT)))
    return found


def verb_objects(found: dict[str, list[tuple[int, bool]]], alpha: float = ALPHA) -> list[tuple[str, float, int]]:
    """Each verb: (verb, P(object | verb), tags), sorted."""
    rows = []
    for verb in sorted(found):
        if not (verb.isascii() and verb.isalpha() and verb.islower()):
            continue
        weights = [(t + alpha, obj) for t, obj in found[verb]]
        total = sum(w for w, _ in weights)
        rows.append((verb, sum(w for w, obj in weights if obj) / total, sum(t for t, _ in found[verb])))
    return rows


def render(rows: list[tuple[str, float, int]]) -> str:
    return HEADER.format(alpha=f"{ALPHA:g}") + "".join(f"{verb}\t{p:.3f}\t{t}\n" for verb, p, t in rows)


def main() -> int:
    args = wordnet_arguments(__doc__.splitlines()[0], OUT, ["data.verb", "cntlist.rev"])
    if args is None:
        return 1
    rows = verb_objects(senses(args.wordnet))
    return write_or_check(args.out, render(rows), check=args.check, made_from="WordNet", summary=f"{len(rows)} verbs")


if __name__ == "__main__":
    raise SystemExit(main())
