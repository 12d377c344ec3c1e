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


def test_take_back_is_a_put_back_and_bring_back_a_bringing_here(library: Library) -> None:
    """e2e27: "take" moves a thing away from the speaker, "bring" toward them; with a bare "back" and no one and
    nowhere said, "take it back" puts it back, "bring it back" brings it here."""
    thing = Phrase("the hammer", "hammer", "hammer", "thing", span=(5, 15))
    taken = Evoked("Pick", "take", (0, 20), {"theme": thing})            # "take the hammer back"
    before = Evoked("Pick", "take", (0, 20), {"theme": replace_span(thing, 10)})   # "take back the hammer"
    plain = Evoked("Pick", "take", (0, 15), {"theme": thing})            # "take the hammer": a taking up
    assert [e.lexical_unit for e in returned([taken], library, "take the hammer back")] == ["put back"]
    assert [e.lexical_unit for e in returned([before], library, "take back the hammer")] == ["put back"]
    assert returned([plain], library, "take the hammer") == (plain,)
    backpack = Evoked("Pick", "take", (0, 16), {"theme": Phrase("the backpack", "backpack", None, span=(5, 17))})
    assert returned([backpack], library, "take the backpack") == (backpack,)     # "back" only as a word of its own
    tom = Evoked("Pick", "take", (0, 13), {"theme": Phrase("Tom", "tom", None, "person", span=(5, 8))})
    assert returned([tom], library, "take Tom back") == (tom,)                  # a person: not put back


def replace_span(phrase: Phrase, start: int) -> Phrase:
    from dataclasses import replace

    assert phrase.span is not None
    return replace(phrase, span=(start, start + phrase.span[1] - phrase.span[0]))


@pytest.mark.parametrize(("text", "holding", "steps"), [
    ("take the mug back", "mug", ["Open(theme=cupboard_1)", "Place(theme=mug, goal=cupboard_1)"]),   # held: kept
    ("take back the mug", "mug", ["Open(theme=cupboard_1)", "Place(theme=mug, goal=cupboard_1)"]),
    ("bring the mug back", "mug", ["Bring(theme=mug, recipient=me)"]),          # toward the speaker
    ("bring back the mug", "mug", ["Bring(theme=mug, recipient=me)"]),
    ("take the mug back to the balcony", "mug", ["Bring(theme=mug, goal=balcony)"]),    # a place said: as said
    ("take the remote to the kitchenette, then take it back", None,             # taken: back where it lay
     ["Pick(theme=remote, source=sofa_1)", "Bring(theme=remote, goal=kitchenette)",
      "Pick(theme=remote, source=kitchenette)", "Place(theme=remote, goal=sofa_1)"]),
])
def test_taking_back_and_bringing_back_on_a_map(library: Library, text: str, holding: str | None,
                                                steps: list[str]) -> None:
    assert _plan(text, library, holding) == steps


@pytest.mark.parametrize(("text", "back"), [
    ("put the vase back on the mantelpiece", True),
    ("set the vase back down on the mantelpiece", True),
    ("put the vase on the mantelpiece", False),
    ("put the vase on the back porch", False),      # "back" inside an element: a porch, not a return
])
def test_a_bare_back_in_a_frame_says_the_thing_returns(library: Library, text: str, back: bool) -> None:
    from seal_cli.language.parser import parse_command
    from seal_cli.planning.returning import says_back

    parse = parse_command(text, library)
    assert says_back(parse.frames[0], text) is back
