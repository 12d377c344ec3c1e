#!/usr/bin/env python3
"""Rebuild ``seal_cli/language/verb_usage.tsv``: for each word form WordNet 3.0 knows as a verb, how likely it is
used as a verb, P(verb | form), estimated from the SemCor sense tag counts WordNet ships (``cntlist.rev``).

The parser reads it to tell a verb from a noun where nothing else does: after "and", a bare word is a noun of a
list ("bring the cup and *plate*", "the salt and *pepper*") or the verb of a clause of its own ("go to the kitchen
and *wait* there", "take the cup and *dance*"). People use "wait" as a verb 184 times in SemCor and as a noun 4
times; "plate" 17 times as a noun and never as a verb.

For a form, each part of speech's lemmas are found as WordNet's morphy finds them: the form itself when WordNet
lists it, its entry in ``<pos>.exc`` ("found" → find, "knives" → knife), and the regular endings taken off
(nouns: -s, -ses, -xes, -zes, -ches, -shes, -men, -ies; verbs: -s, -ies, -es, -ed, -ing; adjectives: -er, -est).
Then, with ``t`` the tag counts of the lemmas' senses and ``n`` their numbers of senses (``index.<pos>``),

    P(verb | form) = (t_verb + ALPHA * n_verb) / (t_all + ALPHA * n_all)

where ``all`` sums nouns, verbs, adjectives and adverbs: each sense counts ALPHA times as if tagged, so a form
whose senses were never tagged ("pepper" the noun: four senses, none tagged; the verb two tags) is judged by
how many senses it has of each kind rather than by one or two tags. A form is written when it is one word of
lower-case letters and has a verb sense, with the probability to three places and the two tag counts; the data
itself (WordNet's files) is read only here, never by the parser. ``--check`` exits 1 when the shipped file
differs.

    python scripts/build_verb_usage.py --wordnet /usr/share/wordnet [--check]
"""

from __future__ import annotations

from collections import defaultdict
from pathlib import Path

from rebuilt import wordnet_arguments, write_or_check  # scripts/rebuilt.py, beside this script

ROOT = Path(__file__).resolve().parent.parent
OUT = ROOT / "seal_cli" / "language" / "verb_usage.tsv"
ALPHA = 1.0
"""How many tags each sense counts as, before the real ones (see the module's docstring)."""
POS = ("noun", "verb", "adj", "adv")
SS_TYPE = {"1": "noun", "2": "verb", "3": "adj", "4": "adv", "5": "adj"}
ENDINGS = {
    "noun": (("s", ""), ("ses", "s"), ("xes", "x"), ("zes", "z"), ("ches", "ch"), ("shes", "sh"), ("men", "man"),
             ("ies", "y")),
    "verb": (("s", ""), ("ies", "y"), ("es", "e"), ("es", ""), ("ed", "e"), ("ed", ""), ("ing", "e"), ("ing", "")),
    "adj": (("er", ""), ("est", ""), ("er", "e"), ("est", "e")),
    "adv": (),
}
HEADER = """\
# P(verb | word form): how likely each form WordNet 3.0 knows as a verb is used as one, from WordNet's SemCor
# sense tag counts (Princeton University, WordNet 3.0 license); each sense counts as {alpha} tag besides.
# Columns: form, P(verb | form), tags as a verb, tags of every part of speech.
# Written by scripts/build_verb_usage.py --wordnet DIR: rebuild it, do not edit it by hand.
"""


class WordNet:
    """Each part of speech's lemmas with their numbers of senses, exceptions and tag counts."""

    def __init__(self, folder: Path) -> None:
        self.senses: dict[str, dict[str, int]] = {}
        self.exc: dict[str, dict[str, list[str]]] = {}
        for pos in POS:
            senses: dict[str, int] = {}
            for line in (folder / f"index.{pos}").read_text(encoding="latin-1").splitlines():
                if line.startswith(" "):
                    continue                                   # the licence, at the top
                fields = line.split()
                senses[fields[0]] = int(fields[2])
            self.senses[pos] = senses
            exc: dict[str, list[str]] = defaultdict(list)
            path = folder / f"{pos}.exc"
            for line in path.read_text(encoding="latin-1").splitlines() if path.is_file() else ():
                form, *lemmas = line.split()
                exc[form] += lemmas
            self.exc[pos] = exc
        self.tags: dict[tuple[str, str], int] = defaultdict(int)
        for line in (folder / "cntlist.rev").read_text(encoding="latin-1").splitlines():
            key, _, count = line.split()
            lemma, _, rest = key.partition("%")
            self.tags[(SS_TYPE[rest[0]], lemma)] += int(count)

    def lemmas(self, form: str, pos: str) -> set[str]:
        """The lemmas of ``pos`` a form may be, as WordNet's morphy finds them."""
        known = self.senses[pos]
        found = {form} if form in known else set()
        found.update(lemma for lemma in self.exc[pos].get(form, ()) if lemma in known)
        for ending, base in ENDINGS[pos]:
            if form.endswith(ending) and len(form) > len(ending) + 1:
                lemma = form[: len(form) - len(ending)] + base
                if lemma in known:
                    found.add(lemma)
        return found

    def counts(self, form: str, pos: str) -> tuple[int, int]:
        """Tags and senses of a form's lemmas of ``pos``."""
        lemmas = self.lemmas(form, pos)
        return sum(self.tags[(pos, lemma)] for lemma in lemmas), sum(self.senses[pos][lemma] for lemma in lemmas)


def verb_usage(wordnet: WordNet, alpha: float = ALPHA) -> list[tuple[str, float, int, int]]:
    """Each form with a verb sense: (form, P(verb | form), verb tags, tags of every part of speech), sorted."""
    rows = []
    for form in sorted(wordnet.senses["verb"]):
        if not (form.isascii() and form.isalpha() and form.islower()):
            continue
        counts = {pos: wordnet.counts(form, pos) for pos in POS}
        tags = sum(t for t, _ in counts.values())
        senses = sum(n for _, n in counts.values())
        verb_tags, verb_senses = counts["verb"]
        rows.append((form, (verb_tags + alpha * verb_senses) / (tags + alpha * senses), verb_tags, tags))
    return rows


def render(rows: list[tuple[str, float, int, int]]) -> str:
    return HEADER.format(alpha=f"{ALPHA:g}") + "".join(f"{form}\t{p:.3f}\t{v}\t{t}\n" for form, p, v, t in rows)


def main() -> int:
    args = wordnet_arguments(__doc__.splitlines()[0], OUT, [f"index.{pos}" for pos in POS] + ["cntlist.rev"])
    if args is None:
        return 1
    rows = verb_usage(WordNet(args.wordnet))
    return write_or_check(args.out, render(rows), check=args.check, made_from="WordNet", summary=f"{len(rows)} forms")


if __name__ == "__main__":
    raise SystemExit(main())
