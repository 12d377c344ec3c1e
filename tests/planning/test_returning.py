"""A thing "returned" with no one and nowhere said goes back where it was taken from (planning/returning.py)."""

from __future__ import annotations

from pathlib import Path

import pytest

from seal_cli.frames.library import Library
from seal_cli.language.values import Evoked, Phrase
from seal_cli.planning.returning import put_back_unit, returned

MAPS = Path(__file__).resolve().parents[2] / "maps"


def _plan(text: str, library: Library, holding: str | None = None) -> list[str]:
    from seal_cli.maps.formats.map_server import load_map
    from seal_cli.pipeline import plan

    return [str(step) for step in plan(text, library, holding=holding, map=load_map(MAPS / "studio.yaml")).steps]


def test_the_library_says_which_unit_puts_back(library: Library) -> None:
    assert put_back_unit(library) == ("Place", "put back")


def test_a_return_of_a_thing_with_nowhere_said_is_a_put_back(library: Library) -> None:
    thing = Phrase("the hammer", "hammer", "hammer", "thing")
    said = Evoked("Bring", "return", (0, 17), {"theme": thing})
    assert [(e.frame, e.lexical_unit, set(e.elements)) for e in returned([said], library)] == [
        ("Place", "put back", {"theme"})]
    to_someone = Evoked("Bring", "return", (0, 24), {"theme": thing, "recipient": Phrase("Raj", "raj", None, "person")})
    fetched = Evoked("Bring", "bring", (0, 16), {"theme": thing})      # another verb: still a bringing
    assert returned([to_someone, fetched], library) == (to_someone, fetched)


@pytest.mark.parametrize(("text", "holding", "steps"), [
    ("return it", "umbrella", ["Place(theme=umbrella, goal=coat_rack_1)"]),         # held: where such a thing is kept
    ("return the book", "book", ["Place(theme=book, goal=bookshelf_1)"]),
    ("take the key to the hall and then return it", None,                          # taken: back where it lay
     ["Pick(theme=key, source=dining_table_1)", "Bring(theme=key, goal=hall)", "Pick(theme=key, source=hall)",
      "Place(theme=key, goal=dining_table_1)"]),
])
def test_return_puts_the_thing_back_where_it_was_taken_from(library: Library, text: str, holding: str | None,
                                                            steps: list[str]) -> None:
    """e2e25: "return it" while holding the umbrella planned a Bring to the speaker."""
    assert _plan(text, library, holding) == steps


@pytest.mark.parametrize(("text", "last"), [
    ("return the remote to Nora", "Bring(theme=remote, recipient=nora)"),     # someone said: a bringing
    ("go to the balcony and return", "Go(goal=me)"),                           # nothing returned: back to the speaker
])
def test_return_with_someone_or_nothing_said_is_as_before(library: Library, text: str, last: str) -> None:
    assert _plan(text, library)[-1] == last
