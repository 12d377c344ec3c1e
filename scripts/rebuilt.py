"""What the build scripts share: the arguments of one built from WordNet, and writing a rebuilt data file
whole, or checking that the shipped one is it."""

from __future__ import annotations

import argparse
import json
import os
import sys
import tempfile
from collections.abc import Callable, Iterable
from pathlib import Path
from typing import Any


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


Compare = Callable[[Any, Any], list[str]]
"""``compare(shipped, built)``: where a shipped JSON data file differs from the one just built (empty: the same)."""

SHOWN = 5
"""How many differences ``--check`` names before it says how many more there are."""


def stale(out: Path, text: str, made_from: str, compare: Compare | None = None) -> str | None:
    """Why ``out`` is not what ``made_from`` gives (``text``, just built), or None if it is: missing, unreadable,
    not JSON (at its line and column) or differing. Without ``compare`` the texts must be the same; with it both
    are read as JSON and ``compare`` lists their differences (a fitted number may move in a last decimal)."""
    if not out.exists():
        return f"{out}: no such file (build it from {made_from})"
    try:
        shipped = out.read_text(encoding="utf-8")
    except (OSError, UnicodeDecodeError) as error:
        reason = error.strerror if isinstance(error, OSError) else "not UTF-8"
        return f"{out}: cannot be read: {reason} (rebuild it)"
    if compare is None:
        return None if shipped == text else f"{out}: differs from what {made_from} gives (rebuild it)"
    try:
        old = json.loads(shipped)
    except json.JSONDecodeError as error:
        return f"{out}:{error.lineno}:{error.colno}: not JSON: {error.msg} (rebuild it)"
    problems = compare(old, json.loads(text))
    if not problems:
        return None
    more = f" ... ({len(problems) - SHOWN} more)" if len(problems) > SHOWN else ""
    return f"{out}: differs from what {made_from} gives (rebuild it): {'; '.join(problems[:SHOWN])}{more}"


def write_whole(out: Path, text: str) -> None:
    """``text`` written to ``out`` through a temporary file of its own beside it, renamed onto it: never half a
    file, and two writers never share a temporary. Its folder is made if need be."""
    out.parent.mkdir(parents=True, exist_ok=True)
    handle, tmp = tempfile.mkstemp(prefix=f".{out.name}.", suffix=".tmp", dir=out.parent)
    try:
        with os.fdopen(handle, "w", encoding="utf-8") as file:
            file.write(text)
        os.replace(tmp, out)
    except BaseException:
        Path(tmp).unlink(missing_ok=True)
        raise


def write_or_check(out: Path, text: str, *, check: bool, made_from: str, summary: str,
                   compare: Compare | None = None) -> int:
    """With ``check``: exit status 1, and say why on stderr (:func:`stale`), if ``out`` is not ``text``, and
    write nothing. Else write ``text`` to ``out`` whole (:func:`write_whole`) and say ``summary``. Returns the
    exit status."""
    if check:
        problem = stale(out, text, made_from, compare)
        if problem is not None:
            print(problem, file=sys.stderr)
            return 1
        print(f"{out}: up to date")
        return 0
    try:
        write_whole(out, text)
    except OSError as error:
        print(f"error: {out}: cannot be written: {error.strerror or error}", file=sys.stderr)
        return 1
    print(f"wrote {out} ({summary})")
    return 0
