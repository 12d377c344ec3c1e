"""Which element a phrase fills (``seal_cli.language.roles``): where a moved thing comes from, and where it goes."""

from __future__ import annotations

import pytest

from seal_cli.frames.library import Library
from seal_cli.language.parser import parse_command


def _frames(text: str, library: Library) -> list[tuple[str, dict[str, str | None]]]:
    return [(f.frame, {role: p.text for role, p in f.elements.items()}) for f in parse_command(text, library).frames]


@pytest.mark.parametrize(("text", "expected"), [
    ("move the sugar from the pantry to the kitchen table",
     [("Place", {"theme": "the sugar", "source": "the pantry", "goal": "the kitchen table"})]),
    ("shift the vase from the table to the windowsill",
     [("Place", {"theme": "the vase", "source": "the table", "goal": "the windowsill"})]),
    ("put two knives from the dining table in the drawer",          # a locative after the source: the goal
     [("Place", {"theme": "two knives", "source": "the dining table", "goal": "the drawer"})]),
])
def test_a_place_said_with_from_is_where_a_placed_thing_comes_from(library: Library, text: str,
                                                                    expected: list[object]) -> None:
    assert _frames(text, library) == expected


@pytest.mark.parametrize(("text", "goal"), [
    ("put the cup on the table by the sink", "the table by the sink"),   # where the goal is, no source
    ("put a spray bottle into a cabinet under the sink", "a cabinet under the sink"),
    ("take the cup to the table by the sink", "the table by the sink"),  # Bring too: after its goal
])
def test_a_locative_phrase_after_the_goal_describes_it(library: Library, text: str, goal: str) -> None:
    frame = parse_command(text, library).frames[-1]
    assert frame.elements["goal"].text == goal and "source" not in frame.elements


def test_a_thing_in_hand_has_no_source_to_say(library: Library) -> None:
    """"move [it] to the cabinet" after heating the mug is a Place still, its source unsaid (not Go)."""
    frames = _frames("heat the mug and move to the cabinet", library)
    assert [name for name, _ in frames] == ["Heat", "Place"]
    assert frames[1][1]["goal"] == "the cabinet"
