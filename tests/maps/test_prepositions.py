from __future__ import annotations

from pathlib import Path

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


def test_room_preposition_is_the_maps_else_englishs() -> None:
    from seal_cli.maps.formats.map_server import load_map
    from seal_cli.maps.prepositions import room_preposition

    boat = load_map("houseboat")
    assert room_preposition("back_deck", boat) == "on" and room_preposition("saloon", boat) == "in"
    assert room_preposition("porch") == "on"


def test_seal_map_json_says_each_rooms_preposition(tmp_path: Path) -> None:
    """``seal map --json`` lists the preposition each room is said with: the map's ``preposition:`` when given
    ("at the sun trap"), else English's ("on the balcony", "in the kitchen")."""
    import json

    from typer.testing import CliRunner

    from seal_cli.cli import app

    path = tmp_path / "m.yaml"
    path.write_text("bounds: [0, 0, 9, 3]\nrooms:\n  - {name: kitchen, box: [0, 0, 3, 3]}\n"
                    "  - {name: balcony, box: [3, 0, 6, 3]}\n"
                    "  - {name: sun_trap, box: [6, 0, 9, 3], preposition: at}\n")
    result = CliRunner().invoke(app, ["map", str(path), "--json"])
    assert result.exit_code == 0, result.output
    rooms = {r["name"]: r["preposition"] for r in json.loads(result.stdout)["rooms"]}
    assert rooms == {"kitchen": "in", "balcony": "on", "sun_trap": "at"}
