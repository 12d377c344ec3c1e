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

Each unit is written with its source (``propbank:give_out.06 -> FrameNet Giving``); the data
itself is never copied. ``--check`` exits 1 when the shipped file differs from what the data gives.

    python scripts/build_lexical_units.py [--data ../shared/data] [--check]
"""

from __future__ import annotations

import argparse
import json
import sys
from collections import defaultdict
from pathlib import Path
from typing import Any

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT))

from seal_cli.frames.library import Library  # noqa: E402
from seal_cli.frames.reading import load_library  # noqa: E402

OUT = ROOT / "framelib" / "derived_units.yaml"
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


def render(found: list[tuple[str, str, str]]) -> str:
    lines = [HEADER, "lexical_units:"]
    lines += [f"  - {{frame: {frame}, unit: {unit}, source: {json.dumps(source)}}}" for frame, unit, source in found]
    return "\n".join(lines) + "\n"


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--data", type=Path, default=ROOT.parent / "shared" / "data")
    ap.add_argument("--out", type=Path, default=OUT)
    ap.add_argument("--check", action="store_true", help="compare with the shipped file instead of writing it")
    args = ap.parse_args()
    path = args.data / "lexicon" / "propbank_rolesets.json"
    if not path.is_file():
        print(f"error: {path}: no such file (the shared data folder is --data)", file=sys.stderr)
        return 1
    rolesets = json.loads(path.read_text())
    # the library without the file being rebuilt: its units must not count as listed already
    framelib = ROOT / "framelib"
    library = load_library([p for p in sorted(framelib.iterdir()) if p != args.out.resolve()
                            and p.suffix in (".yaml", ".yml", ".frame")])
    text = render(derive(rolesets, library))
    if args.check:
        if not args.out.is_file() or args.out.read_text() != text:
            print(f"{args.out}: differs from what the verb data gives (rebuild it)", file=sys.stderr)
            return 1
        print(f"{args.out}: up to date")
        return 0
    tmp = args.out.with_suffix(".yaml.tmp")
    tmp.write_text(text)
    tmp.replace(args.out)
    print(f"wrote {args.out} ({text.count('frame:')} units)")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
