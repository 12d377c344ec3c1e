"""The house the commands already done left (e2e30): what ``seal run`` acts in after ``--done``."""

from __future__ import annotations

from pathlib import Path

import pytest

from seal_cli.frames.library import Library
from seal_cli.maps.formats.map_server import load_map
from seal_cli.maps.model import Map
from seal_cli.planning.aftermath import handled, world_after
from seal_cli.planning.problem import Things, carry_out_done, parse_to_plan

MAPS = Path(__file__).resolve().parents[2] / "maps"


def _after(m: Map, library: Library, *done: str) -> tuple[Map, Things]:
    things = Things(library.taxonomy, m)
    things.hold(None)
    carry_out_done([parse_to_plan(t, library) for t in done], library, things)
    return world_after(m, things), things


@pytest.fixture(scope="module")
def apartment() -> Map:
    return load_map(MAPS / "apartment.yaml")


def test_a_thing_put_somewhere_lies_there_and_nowhere_else(apartment: Map, library: Library) -> None:
    world, things = _after(apartment, library, "bring the cup to the table")
    cups = world.objects_of_class("cup")
    assert [c.inside for c in cups] == ["dining_table_1"] and cups[0].at == apartment.place("dining_table_1").at
    assert [o.cls for o in handled(apartment, things)] == ["cup"]
    assert handled(apartment, things)[0].inside == "coffee_table_1"     # what the robot knew before it moved it


def test_a_thing_picked_up_is_in_the_robots_hand_not_on_the_map(apartment: Map, library: Library) -> None:
    world, _ = _after(apartment, library, "pick up the cup")
    assert world.objects_of_class("cup") == () and world.robot.holding == "cup"


def test_a_thing_handed_over_lies_by_whom_it_was_handed_to(apartment: Map, library: Library) -> None:
    world, _ = _after(apartment, library, "bring me the cup")
    (cup,) = world.objects_of_class("cup")
    assert cup.inside is None and cup.at == apartment.speaker_at


def test_a_thing_taken_to_a_room_lies_on_its_free_floor(library: Library) -> None:
    library_map = load_map(MAPS / "library.yaml")
    world, _ = _after(library_map, library, "take the newspaper to the study room")
    (paper,) = world.objects_of_class("newspaper")
    assert paper.inside is None and world._room_name(paper.at) == "study_room" and world.is_free([paper.at])[0]


def test_a_place_opened_is_open_and_the_rest_as_drawn(apartment: Map, library: Library) -> None:
    world, _ = _after(apartment, library, "open the fridge")
    assert world.place("fridge_1").open is True
    assert world.objects == apartment.objects and world.robot == apartment.robot
