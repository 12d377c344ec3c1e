"""Maps whose occupancy comes from a nav_msgs/OccupancyGrid in a bag: the shipped apartment's grid, saved as a
message and read back, gives the same map as its image; bad keys and bags are problems at their line."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

pytest.importorskip("rosbags")

from seal_cli.errors import SealError  # noqa: E402
from seal_cli.maps.formats.map_server import load_map, read_map  # noqa: E402
from seal_cli.maps.geometry import FREE, OCCUPIED  # noqa: E402
from seal_cli.resources import map_path  # noqa: E402
from seal_cli.ros.writing import write_bag  # noqa: E402
from tests.ros.bagfiles import occupancy_grid, store_for  # noqa: E402

MAP_SERVER_LINES = ("image:", "resolution:", "origin:", "negate:", "occupied_thresh:", "free_thresh:", "mode:")


def saved_as_message(tmp_path: Path, name: str = "mapping.mcap", topic: str = "/map") -> Path:
    """The apartment's grid as map_saver's inverse would publish it: 100 occupied, 0 free, −1 unknown."""
    grid = load_map(map_path("apartment")).grid
    values = np.where(grid.cells == OCCUPIED, 100, np.where(grid.cells == FREE, 0, -1)).astype(np.int8)
    values[grid.cells == FREE] = np.random.default_rng(0).integers(0, 19, int((grid.cells == FREE).sum()))
    bag = tmp_path / name
    store = store_for(bag)
    write_bag(bag, [(topic, "nav_msgs/msg/OccupancyGrid", 5.0,
                     occupancy_grid(store, 5.0, values, grid.resolution, grid.origin, bag.suffix == ".bag"))], store)
    return bag


def apartment_with(tmp_path: Path, *lines: str) -> Path:
    """The shipped apartment's YAML with its map_server keys replaced by ``lines``."""
    text = map_path("apartment").read_text()
    kept = [line for line in text.splitlines() if not line.startswith(MAP_SERVER_LINES)]
    path = tmp_path / "apartment.yaml"
    path.write_text("\n".join([*lines, *kept]) + "\n")
    return path


@pytest.mark.parametrize("name", ["mapping.mcap", "mapping.bag", "mapping_db3"])
def test_the_grid_from_a_bag_is_the_image_grid(tmp_path: Path, name: str) -> None:
    saved_as_message(tmp_path, name)
    from_bag = load_map(apartment_with(tmp_path, f"occupancy: {{bag: {name}, topic: /map}}"))
    shipped = load_map(map_path("apartment"))
    assert from_bag.grid.resolution == shipped.grid.resolution and from_bag.grid.origin == shipped.grid.origin
    assert np.array_equal(from_bag.grid.cells, shipped.grid.cells)  # values 0..18 are all below free_thresh
    assert from_bag.bounds == shipped.bounds and from_bag.room_names == shipped.room_names


def test_thresholds_apply_to_the_message_values(tmp_path: Path) -> None:
    saved_as_message(tmp_path)
    strict = load_map(apartment_with(tmp_path, "occupancy: mapping.mcap", "free_thresh: 0.1"))
    shipped = load_map(map_path("apartment"))
    assert (strict.grid.cells == FREE).sum() < 0.7 * (shipped.grid.cells == FREE).sum()  # 10..18 are now unknown


def problems(path: Path) -> list[str]:
    return [str(p) for p in read_map(path)[1]]


def test_bad_occupancy_keys_are_problems_at_their_line(tmp_path: Path) -> None:
    saved_as_message(tmp_path)
    found = problems(apartment_with(tmp_path, "occupancy: mapping.mcap", "resolution: 0.05"))
    assert any(":2:13: resolution cannot be given with occupancy" in p for p in found), found
    found = problems(apartment_with(tmp_path, "occupancy: {bag: mapping.mcap, topic: /costmap}"))
    assert any(":1:18: " in p and "no topic /costmap in the bag (its occupancy grids: /map)" in p for p in found), found
    found = problems(apartment_with(tmp_path, "occupancy: {bag: missing.mcap}"))
    assert any("missing.mcap: no such bag" in p for p in found), found
    found = problems(apartment_with(tmp_path, "occupancy: {bags: mapping.mcap}"))
    assert any("unknown key 'bags' in occupancy (did you mean 'bag'?)" in p for p in found), found
    with pytest.raises(SealError):
        load_map(apartment_with(tmp_path, "occupancy: {topic: /map}"))
