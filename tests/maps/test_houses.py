"""The example houses a user would draw (maps/townhouse.yaml, maps/office_floor.yaml): their images
are what make_houses.py draws, and they are clean, sensible maps."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from seal_cli.maps.formats.map_server import load_map, read_pgm
from tests.conftest import module_from_file

MAPS = Path(__file__).resolve().parents[2] / "maps"
HOUSES = ["townhouse", "office_floor", "cafe", "clinic", "farmhouse", "terrace", "bungalow", "lodge", "flat",
          "carehome", "student_house", "guesthouse", "studio", "corner_shop", "houseboat", "library", "bakery",
          "workshop", "school", "fitness_club"]


def make_houses():  # type: ignore[no-untyped-def]
    return module_from_file("make_houses", MAPS / "make_houses.py", register=True)  # its dataclass looks itself up


@pytest.mark.parametrize("name", HOUSES)
def test_the_committed_image_is_what_the_script_draws(name: str) -> None:
    module = make_houses()
    house = next(h for h in module.HOUSES if h.name == name)
    drawn = module.draw(house)
    assert np.array_equal(read_pgm((MAPS / f"{name}.pgm").read_bytes()), drawn.astype(float))


@pytest.mark.parametrize("name", HOUSES)
def test_a_house_is_a_clean_map_whose_rooms_are_joined_by_doors(name: str) -> None:
    from seal_cli.frames.reading import standard_library
    from seal_cli.sim.agent import scene_from_map

    m = load_map(MAPS / f"{name}.yaml")
    assert m.problems() == [] and m.warnings == ()
    scene = scene_from_map(m, standard_library())
    reach = scene.grid.distances(scene.grid.cell(m.robot.xy))
    for room in m.rooms:          # every room can be driven into from where the robot starts
        inside = room.contains(scene.grid.free_points)
        cells = scene.grid.free_cells[inside]
        assert np.isfinite(reach[cells[:, 0], cells[:, 1]]).any(), room.name
    for place in m.places:        # and every place is in a room, with the robot able to stand by it
        assert place.room is not None, place.name
    assert len({p.name for p in m.people}) >= 2 and any(len(r.name.split("_")) > 1 for r in m.rooms)


def test_an_l_shaped_house_leaves_its_missing_corner_unknown() -> None:
    """The bungalow's yard (x > 9, y > 6) is no part of the house: unknown, walled off from the kitchen and the
    study, and nothing of it can be driven on."""
    m = load_map(MAPS / "bungalow.yaml")
    assert not m.grid.is_free((12.5, 9.0)) and m.grid.is_free((7.0, 9.0)) and m.grid.is_free((12.5, 4.5))
    module = make_houses()
    image = module.draw(next(h for h in module.HOUSES if h.name == "bungalow"))
    row = image.shape[0] - 1 - round((9.0 + 1.0) / module.RESOLUTION)      # y = 9 m, from the top
    col = round((12.5 + 1.0) / module.RESOLUTION)
    assert image[row, col] == module.UNKNOWN


def test_a_maps_name_is_said_as_words() -> None:
    """Messages name a map as words (e2e28: the simulator said "had the corner_shop one")."""
    assert load_map(MAPS / "corner_shop.yaml").said == "corner shop"
    assert load_map(MAPS / "houseboat.yaml").said == "houseboat"
