"""``seal_cli.language.reference``: what a pronoun said in the command stands for (words48)."""

from __future__ import annotations

import pytest

from seal_cli.frames.library import Library
from seal_cli.language.parser import parse_command


@pytest.mark.parametrize(("text", "head"), [
    ("the lady by the window wants a scone, bring her one", "scone"),
    ("Theo would like a blanket, could you take him one", "blanket"),
])
def test_a_bare_one_after_a_wish_stands_for_the_thing_wished_for(library: Library, text: str, head: str) -> None:
    """"X wants a cola, bring him one" had the theme "one", a person: the kind of thing the statement names."""
    theme = parse_command(text, library).frames[0].elements["theme"]
    assert (theme.text, theme.head, theme.kind) == ("one", head, "thing")

