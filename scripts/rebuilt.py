"""What the build scripts share: the arguments of one built from WordNet, and writing a rebuilt data file
whole, or checking that the shipped one is it."""

from __future__ import annotations

import argparse
import sys
from collections.abc import Iterable
from pathlib import Path


def wordnet_arguments(description: str, out: Path, needs: Iterable[str]) -> argparse.Namespace | None:
    """``--wordnet DIR``, ``--out`` (default ``out``) and ``--check`` from the command line; None, having said
    which, if a file of ``needs`` is not in the WordNet folder."""
    ap = argparse.ArgumentParser(description=description)
    ap.add_argument("--wordnet", type=Path, required=True, help="a WordNet 3.0 dict folder")
    ap.add_argument("--out", type=Path, default=out)
    ap.add_argument("--check", action="store_true", help="compare with the shipped file instead of writing it")
    args = ap.parse_args()
    missing = [args.wordnet / name for name in needs if not (args.wordnet / name).is_file()]
    if missing:
        print(f"error: {missing[0]}: no such file (--wordnet is a WordNet 3.0 dict folder)", file=sys.stderr)
        return None
    return args


def write_or_check(out: Path, text: str, *, check: bool, made_from: str, summary: str) -> int:
    """With ``check``: exit status 1, and say so, if ``out`` is not ``text`` (``made_from`` names what
    rebuilds it); else write ``text`` to ``out`` through a temporary file (never half a file) and say
    ``summary``. Returns the exit status."""
    if check:
        if not out.is_file() or out.read_text() != text:
            print(f"{out}: differs from what {made_from} gives (rebuild it)", file=sys.stderr)
            return 1
        print(f"{out}: up to date")
        return 0
    tmp = out.with_suffix(out.suffix + ".tmp")
    tmp.write_text(text)
    tmp.replace(out)
    print(f"wrote {out} ({summary})")
    return 0
