"""docs/frames.md's DSL example is a library of its own, as the guide says: it validates alone and evokes its frame."""

from __future__ import annotations

import re
from pathlib import Path

from seal_cli.frames.reading import load_library
from seal_cli.pipeline import parse
from seal_cli.validate import validate_paths

ROOT = Path(__file__).resolve().parents[1]


def test_the_dsl_example_validates_alone_and_parses(tmp_path: Path) -> None:
    text = (ROOT / "docs" / "frames.md").read_text(encoding="utf-8")
    block = re.search(r"## The DSL\s+```\n(.*?)```", text, re.S)
    assert block, "docs/frames.md has a DSL example"
    example = tmp_path / "stir.frame"
    example.write_text(block.group(1), encoding="utf-8")
    report = validate_paths([example])
    assert report.problems == [] and report.summary() == "ok: 1 frame, 3 categories, 0 maps in 1 file"
    assert report.summary() in " ".join(text.split())  # the guide quotes what seal validate says of it
    evoked = parse("mix the bowl", load_library([example])).frames
    assert [f.frame for f in evoked] == ["Stir"] and evoked[0].elements["instrument"].head == "spoon"
