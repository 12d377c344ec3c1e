"""Where the user says a thing is, in a statement beside the command (seal_cli/planning/told.py)."""

from __future__ import annotations

from pathlib import Path

import pytest

from seal_cli.frames.library import Library
from seal_cli.maps.formats.map_server import load_map
from seal_cli.pipeline import plan
from seal_cli.planning.problem import parse_to_plan

GUESTHOUSE = Path(__file__).resolve().parents[2] / "maps" / "guesthouse.yaml"


@pytest.mark.parametrize(("text", "step"), [
    ("find the soap, it's in the bathroom", "Find(theme=soap, ground=bathroom)"),
    ("look for the glasses. They are probably in the lounge", "Find(theme=glasses, ground=lounge)"),
    ("find Ben, he's in the kitchen", "Find(theme=ben, ground=kitchen)"),
    ("grab the teapot, the teapot is on the dining table", "Pick(theme=teapot, source=dining_table_1)"),
])
def test_a_statement_of_where_the_thing_is_says_where_to_look(library: Library, text: str, step: str) -> None:
    """e2e25: "Locate the towel, it's in the dining room" dropped the place and found the bathroom's towel."""
    assert str(plan(text, library, map=load_map(GUESTHOUSE)).steps[0]) == step


@pytest.mark.parametrize("text", [
    "find the soap, the key is in the bathroom",          # about another thing: a remark, kept
    "find the soap in the kitchen, it's in the bathroom",  # where is said already
    "find the soap, it's lovely",                          # no place
])
def test_other_statements_stay_remarks(library: Library, text: str) -> None:
    parse = parse_to_plan(text, library)
    assert parse.remarks and "ground" not in parse.frames[0].elements or \
        parse.frames[0].elements["ground"].text == "the kitchen"
