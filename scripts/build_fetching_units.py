#!/usr/bin/env python3
"""Rebuild ``seal_cli/planning/fetching.tsv``: the lexical units that, said alone ("fetch the remote"), mean
go, get the thing and bring it back to the speaker, derived from the verb data in ``../shared/data/lexicon/``
(``verb_frame_links.tsv``: each PropBank roleset of a verb with its FrameNet frames).

A unit *u* is written for a frame T of the library when

1. *u* is a lexical unit of T and of another frame B of the library whose elements include a recipient,
   where T picks its theme up (a ``pick`` action) and has no recipient (the parser reads "fetch the remote",
   with nobody to bring it to, as T: Pick);
2. every sense of *u*'s verb that PropBank links to FrameNet links only to B's FrameNet frame (``fetch.01``
   "bring (back)": Bringing alone), and at least one does: none links to T's (``take.01`` links Taking and
   Bringing, ``get.01`` Getting, ``carry.01`` Bearing_arms and Carry_goods too: none of them is written).

Each row is ``unit, T, B, source``; the data itself is never copied. ``--check`` exits 1 when the shipped
file differs from what the data gives.
"""

from __future__ import annotations

import argparse
import csv
import sys
from collections import defaultdict
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT))
sys.path.insert(0, str(Path(__file__).resolve().parent))

from rebuilt import write_or_check  # noqa: E402  scripts/rebuilt.py, beside this script

from seal_cli.frames.library import Library  # noqa: E402
from seal_cli.frames.reading import load_library  # noqa: E402

OUT = ROOT / "seal_cli" / "planning" / "fetching.tsv"
HEADER = ("# Units that, said alone, mean bring the thing to the speaker (seal_cli/planning/fetching.py).\n"
          "# Written by scripts/build_fetching_units.py from ../shared/data/lexicon/verb_frame_links.tsv: "
          "rebuild it, do not edit it by hand.\n"
          "unit\tsaid_as\tmeans\tsource\n")


def derive(links: list[dict[str, str]], library: Library) -> list[tuple[str, str, str, str]]:
    """(unit, T, B, source) for every unit the data supports, sorted."""
    senses: dict[str, list[tuple[str, str, set[str]]]] = defaultdict(list)
    for row in links:
        lemma = row["propbank_roleset"].rsplit(".", 1)[0].replace("_", " ")
        frames = {f for f in row["framenet_frames"].split(";") if f}
        senses[lemma].append((row["propbank_roleset"], row["roleset_name"], frames))
    found = []
    for frame in library.frames:
        if not frame.framenet:
            continue
        for unit in frame.lexical_units:
            linked = [(rid, name, fns) for rid, name, fns in senses.get(unit.text, ()) if fns]
            if not linked or any(fns != {frame.framenet} for _, _, fns in linked):
                continue
            if "recipient" not in {e.role for e in frame.elements}:
                continue
            for other in library.frames:
                if other.name == frame.name or unit.text not in {u.text for u in other.lexical_units} \
                        or not any(a.name == "pick" for a in other.actions) \
                        or "recipient" in {e.role for e in other.elements}:
                    continue
                said = "; ".join(f"propbank:{rid} ({name})" for rid, name, _ in linked)
                found.append((unit.text, other.name, frame.name, f"{said} -> FrameNet {frame.framenet} only"))
    return sorted(found)


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--data", type=Path, default=ROOT.parent / "shared" / "data")
    ap.add_argument("--out", type=Path, default=OUT)
    ap.add_argument("--check", action="store_true", help="compare with the shipped file instead of writing it")
    args = ap.parse_args()
    path = args.data / "lexicon" / "verb_frame_links.tsv"
    if not path.is_file():
        print(f"error: {path}: no such file (the shared data folder is --data)", file=sys.stderr)
        return 1
    with path.open(newline="") as handle:
        links = list(csv.DictReader(handle, delimiter="\t"))
    library = load_library([p for p in sorted((ROOT / "framelib").iterdir())
                            if p.suffix in (".yaml", ".yml", ".frame")])
    found = derive(links, library)
    text = HEADER + "".join("\t".join(row) + "\n" for row in found)
    return write_or_check(args.out, text, check=args.check, made_from="the verb data", summary=f"{len(found)} units")


if __name__ == "__main__":
    raise SystemExit(main())
