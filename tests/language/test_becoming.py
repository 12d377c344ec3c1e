"""A verb of getting said of a state (``seal_cli.language.becoming``): "get dressed" is becoming, refused."""

from __future__ import annotations

import pytest

from seal_cli.frames.library import Library
from seal_cli.language.lexicon import CommandError
from seal_cli.language.parser import parse_command


@pytest.mark.parametrize(("text", "column", "said"), [
    ("help her get dressed", 10, "'get dressed'"),
    ("Sam needs help getting dressed", 16, "'getting dressed'"),
    ("get ready, please", 1, "'get ready'"),
])
def test_getting_a_state_is_refused_at_the_verb(library: Library, text: str, column: int, said: str) -> None:
    with pytest.raises(CommandError) as caught:
        parse_command(text, library)
    assert caught.value.column == column
    assert said in caught.value.message and "no frame of the library does it" in caught.value.message


@pytest.mark.parametrize(("text", "frame"), [
    ("get milk", "Pick"),                          # a noun: the thing got
    ("get me the milk", "Bring"),
    ("get cold water from the fridge", "Pick"),    # an adjective before its noun
])
def test_getting_a_thing_stays_a_getting(library: Library, text: str, frame: str) -> None:
    assert [f.frame for f in parse_command(text, library).frames][-1] == frame
