from __future__ import annotations

import pytest

from seal_cli.errors import SealError
from seal_cli.maps.model import Room
from seal_cli.maps.prepositions import located, preposition


@pytest.mark.parametrize(("name", "said"), [
    ("balcony", "on"), ("back_deck", "on"), ("Front Deck", "on"), ("patio", "on"), ("roof_terrace", "on"),
    ("porch", "on"), ("landing", "on"), ("balconies", "on"), ("porches", "on"),
    ("kitchen", "in"), ("living_room", "in"), ("deck_room", "in"), ("hall", "in"), ("bus", "in"), ("", "in"),
])
def test_an_open_platform_is_on_and_a_room_in(name: str, said: str) -> None:
    """English says *on* a balcony or deck (its head noun, the name's last word) and *in* a room: "the deck
    room" is a room."""
    assert preposition(name) == said


def test_located_says_the_maps_preposition_else_englishs() -> None:
    from seal_cli.maps.formats.map_server import load_map

    boat = load_map("houseboat")
    assert located("back_deck", boat) == "on the back deck"
    assert located("saloon", boat) == "in the saloon"
    assert located("loft") == "in the loft"


def test_a_room_takes_only_in_on_or_at() -> None:
    assert Room.box("nook", 0, 0, 1, 1, preposition="at").preposition == "at"
    with pytest.raises(SealError, match="room nook: preposition must be one of in, on, at, not 'under'"):
        Room.box("nook", 0, 0, 1, 1, preposition="under")
