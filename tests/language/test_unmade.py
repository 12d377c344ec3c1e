"""A state asked for that no frame brings about (``seal_cli.language.unmade``): refused at the state."""

from __future__ import annotations

import pytest

from seal_cli.frames.library import Library
from seal_cli.language.lexicon import CommandError
from seal_cli.language.parser import parse_command


@pytest.mark.parametrize(("text", "column", "verb"), [
    ("I want the door locked, please", 17, "lock"),
    ("keep the gate locked", 15, "lock"),
    ("make sure the back door is locked", 28, "lock"),
    ("I'd like the windows painted", 22, "paint"),
])
def test_a_state_no_frame_makes_is_refused_there(library: Library, text: str, column: int, verb: str) -> None:
    with pytest.raises(CommandError) as caught:
        parse_command(text, library)
    assert caught.value.column == column
    assert f"the robot cannot {verb} things" in caught.value.message


@pytest.mark.parametrize(("text", "frame"), [
    ("I want the door closed", "Close"),
    ("I want the apple sliced", "Slice"),
    ("keep the fan running", "ToggleOn"),           # a machine in operation is one switched on
    ("keep the lamp on in the hallway", "ToggleOn"),
    ("leave the dishwasher going", "ToggleOn"),
])
def test_a_state_a_frame_makes_is_that_frame(library: Library, text: str, frame: str) -> None:
    assert [f.frame for f in parse_command(text, library).frames] == [frame]
