"""A thing asked for a person by its state (``rules.for_a_person``): which thing, no making it so."""

from __future__ import annotations

from seal_cli.frames.library import Library
from seal_cli.language.parser import parse_command


def test_a_clean_towel_for_her_is_no_washing(library: Library) -> None:
    parse = parse_command("Mia's in the bathroom, bring her a clean towel", library)
    assert [f.frame for f in parse.frames] == ["Bring"]
    bring = parse.frames[0]
    assert bring.elements["theme"].text == "a clean towel" and bring.elements["recipient"].head == "Mia"


def test_a_result_for_no_person_is_still_made(library: Library) -> None:
    """ALFRED's "put a clean plate in the cabinet": clean it, then put it."""
    assert [f.frame for f in parse_command("put a clean plate in the cabinet", library).frames] == ["Clean", "Place"]
