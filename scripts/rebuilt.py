"""What the build scripts share: write a rebuilt data file whole, or check that the shipped one is it."""

from __future__ import annotations

import sys
from pathlib import Path


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
