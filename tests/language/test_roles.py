"""Which element a phrase fills (``seal_cli.language.roles``): a place said after where a thing goes."""

from __future__ import annotations

import pytest

from seal_cli.frames.library import Library
from seal_cli.language.parser import parse_command


@pytest.mark.parametrize(("text", "goal"), [
    ("put the cup on the table by the sink", "the table by the sink"),   # where the goal is, no source
    ("put a spray bottle into a cabinet under the sink", "a cabinet under the sink"),
    ("take the cup to the table by the sink", "the table by the sink"),  # Bring too: after its goal
])
def test_a_locative_phrase_after_the_goal_describes_it(library: Library, text: str, goal: str) -> None:
    frame = parse_command(text, library).frames[-1]
    assert frame.elements["goal"].text == goal and "source" not in frame.elements
