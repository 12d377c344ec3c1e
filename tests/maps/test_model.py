"""Maps: reading map_server images exactly, the apartment, rooms, priors, maps built in code, broken maps.

Each file in ``tests/data/maps_bad`` starts with ``# expect: LINE: text`` lines; checking it must
report exactly those problems, each on its line and containing its text.
"""

from __future__ import annotations

import json
import re
from pathlib import Path

import numpy as np
import pytest
import yaml
from hypothesis import HealthCheck, example, given, settings
from hypothesis import strategies as st
from typer.testing import CliRunner

from seal_cli.cli import app
from seal_cli.errors import SealError, SealErrors
from seal_cli.maps.formats.map_server import check_map_file, load_map, read_pgm
from seal_cli.maps.geometry import FREE, OCCUPIED, UNKNOWN, OccupancyGrid
from seal_cli.maps.model import (
    OUTSIDE,
    Map,
    MapWarning,
    ObjectTruth,
    Person,
    Place,
    Robot,
    Room,
    Sensor,
    prior_density,
    sample_prior,
)
from seal_cli.maps.priors import FLOOR
from seal_cli.resources import map_path
from seal_cli.validate import validate_paths
from tests.conftest import module_from_file

ROOT = Path(__file__).resolve().parents[2]
APARTMENT = ROOT / "maps" / "apartment.yaml"
BAD = Path(__file__).parents[1] / "data" / "maps_bad"
CASES = sorted(BAD.glob("*.yaml"))
EXPECT = re.compile(r"^# expect: (\d+): (.+)$", re.M)


@pytest.fixture(scope="module")
def apartment() -> Map:
    return load_map(APARTMENT)


def write_map(folder: Path, text: str, image: bytes | None = None, image_name: str = "tiny.pgm") -> Path:
    if image is not None:
        (folder / image_name).write_bytes(image)
    path = folder / "map.yaml"
    path.write_text(text)
    return path


# -- map_server conventions ------------------------------------------------------------------------
TINY = (b"P5\n# a comment in the header\n3 2\n255\n"
        + bytes([0, 254, 205,      # row 0: the TOP row of the picture (highest y)
                 100, 40, 250]))   # row 1: the bottom row (lowest y, at the origin)
SERVER = "image: {image}\nresolution: 0.5\norigin: [1.0, 2.0, 0.0]\nnegate: {negate}\n" \
         "occupied_thresh: 0.65\nfree_thresh: 0.196\n"


def cell_centre(col: int, row_from_bottom: int) -> list[float]:
    return [1.0 + 0.5 * (col + 0.5), 2.0 + 0.5 * (row_from_bottom + 0.5)]


def test_origin_is_the_lower_left_pixel_and_row_0_the_highest_y(tmp_path: Path) -> None:
    m = load_map(write_map(tmp_path, SERVER.format(image="tiny.pgm", negate=0), TINY))
    assert m.bounds == (1.0, 2.0, 2.5, 3.0)
    assert m.name == tmp_path.name  # map.yaml takes its folder's name
    # p = (255 - v) / 255: 0 → 1.0 occupied; 254 → 0.004 free; 205 → 0.196 unknown (not < 0.196)
    # 100 → 0.608 unknown; 40 → 0.843 occupied; 250 → 0.0196 free
    top = m.grid.values([cell_centre(c, 1) for c in range(3)])
    bottom = m.grid.values([cell_centre(c, 0) for c in range(3)])
    assert top.tolist() == [OCCUPIED, FREE, UNKNOWN]
    assert bottom.tolist() == [UNKNOWN, OCCUPIED, FREE]
    assert m.is_free([cell_centre(1, 1), cell_centre(2, 0), cell_centre(0, 0)]).tolist() == [True, True, False]


def test_negate_flips_the_picture(tmp_path: Path) -> None:
    m = load_map(write_map(tmp_path, SERVER.format(image="tiny.pgm", negate=1), TINY))
    # negate: p = v / 255: 0 free, 254 occupied, 205 (0.804) occupied, 100 (0.39) unknown, 40 (0.157) free
    assert m.grid.values([cell_centre(c, 1) for c in range(3)]).tolist() == [FREE, OCCUPIED, OCCUPIED]
    assert m.grid.values([cell_centre(c, 0) for c in range(3)]).tolist() == [UNKNOWN, FREE, OCCUPIED]


def test_thresholds_are_strict_as_in_map_server(tmp_path: Path) -> None:
    # with free_thresh = 0.2 and occupied_thresh = 0.6: v = 204 gives p = 0.2 (not < 0.2: unknown),
    # v = 205 gives 0.196 (free), v = 102 gives p = 0.6 (not > 0.6: unknown), v = 101 gives 0.604 (occupied)
    image = b"P5\n4 1\n255\n" + bytes([204, 205, 102, 101])
    text = "image: t.pgm\nresolution: 1\norigin: [0, 0, 0]\nnegate: 0\noccupied_thresh: 0.6\nfree_thresh: 0.2\n"
    m = load_map(write_map(tmp_path, text, image, "t.pgm"))
    assert m.grid.values([[0.5, 0.5], [1.5, 0.5], [2.5, 0.5], [3.5, 0.5]]).tolist() == \
        [UNKNOWN, FREE, UNKNOWN, OCCUPIED]


def test_text_pgm_and_16_bit_pgm_read_like_the_binary_one(tmp_path: Path) -> None:
    p2 = b"P2\n# text\n3 2\n255\n0 254 205\n100 40 250\n"
    assert np.array_equal(read_pgm(p2), read_pgm(TINY))
    wide = b"P5\n3 2\n65535\n" + np.array([0, 254, 205, 100, 40, 250], dtype=">u2").tobytes()
    assert np.allclose(read_pgm(wide), read_pgm(TINY) * 255 / 65535)
    m = load_map(write_map(tmp_path, SERVER.format(image="tiny.pgm", negate=0), p2))
    assert m.grid.values([cell_centre(0, 1)]).tolist() == [OCCUPIED]


def test_png_reads_like_pgm(tmp_path: Path) -> None:
    import matplotlib.image

    grey = np.array([[0, 254, 205], [100, 40, 250]], dtype=np.uint8)
    rgb = np.repeat(grey[:, :, None], 3, axis=2)
    matplotlib.image.imsave(tmp_path / "tiny.png", rgb)
    (tmp_path / "tiny.pgm").write_bytes(TINY)
    png = load_map(write_map(tmp_path, SERVER.format(image="tiny.png", negate=0)))
    pgm = load_map(write_map(tmp_path, SERVER.format(image="tiny.pgm", negate=0)))
    assert np.array_equal(png.grid.cells, pgm.grid.cells)


def test_the_real_aws_house_reads_as_map_server_reads_it(shared_data: Path) -> None:
    folder = shared_data / "maps" / "aws_small_house"
    m = load_map(folder / "map.yaml")
    assert m.name == "aws_small_house"
    assert m.grid.shape == (500, 500)
    assert m.bounds == (-12.5, -12.5, 12.5, 12.5)
    raw = (folder / "map.pgm").read_bytes()
    pixels = np.frombuffer(raw[-250000:], dtype=np.uint8).reshape(500, 500)
    # every pixel: row r, column c is the cell whose centre is at origin + (c + 0.5, 499 - r + 0.5) * res
    rows, cols = np.mgrid[0:500:7, 0:500:7]
    centres = np.column_stack([-12.5 + (cols.ravel() + 0.5) * 0.05, -12.5 + (499 - rows.ravel() + 0.5) * 0.05])
    expected = np.select([pixels[rows, cols].ravel() == 0, pixels[rows, cols].ravel() == 254], [OCCUPIED, FREE],
                         UNKNOWN)
    assert np.array_equal(m.grid.values(centres), expected)
    # known cells: the first wall pixel of the picture, the house's middle, outside the house
    assert m.is_occupied([[0.675, 5.525]]).all()
    assert m.is_free([[0.725, 5.475], [0.0, 0.0], [6.55, 0.95]]).all()  # a wall's inner side, the hall, kitchen table
    assert not m.is_free([[-12.0, -12.0], [12.0, 12.0]]).any()
    assert m.free_area == pytest.approx(63021 * 0.05 ** 2)
    free_rows, free_cols = np.nonzero(m.grid.free_mask)
    assert -12.5 + free_cols.min() * 0.05 == pytest.approx(-9.3)  # the house spans about 18.75 m × 11.2 m
    assert -12.5 + (free_cols.max() + 1) * 0.05 == pytest.approx(9.45)
    models = {d["type"]: d for d in json.loads((folder / "world_models.json").read_text())["models"]}
    # the kitchen table stands in free space (a laser sees its legs only); the bed is a blob the laser never entered
    assert m.is_free([[models["KitchenTable_01"]["x"], models["KitchenTable_01"]["y"]]]).all()
    assert m.grid.values([[models["Bed_01"]["x"], models["Bed_01"]["y"]]]).tolist() == [UNKNOWN]


def test_the_aws_house_validates_as_a_plain_ros_map(shared_data: Path) -> None:
    path = shared_data / "maps" / "aws_small_house" / "map.yaml"
    assert check_map_file(path) == []
    result = CliRunner().invoke(app, ["validate", str(path)])
    assert result.exit_code == 0, result.output


def test_the_aws_house_takes_rooms_and_priors(shared_data: Path, tmp_path: Path) -> None:
    image = shared_data / "maps" / "aws_small_house" / "map.pgm"
    text = (f"image: {image}\nresolution: 0.05\norigin: [-12.5, -12.5, 0.0]\nnegate: 0\noccupied_thresh: 0.65\n"
            "free_thresh: 0.196\nbounds: [-9.5, -6, 9.6, 5.7]\nrooms:\n"
            "  - {name: bedroom, box: [-9.5, 0.0, -2.6, 3.4]}\n  - {name: kitchen, box: [4.8, -5.8, 9.6, 3.4]}\n"
            "priors:\n  cup: {bedroom: 0.5, kitchen: 0.5}\nobjects:\n  - {class: cup, at: [6.5, 1.0]}\n"
            "robot: {pose: [0.0, 0.0, 0.0]}\n")
    m = load_map(write_map(tmp_path, text))
    masses = m.prior("cup").room_masses()
    assert masses["bedroom"] == pytest.approx(0.5 * (1 - FLOOR) + FLOOR * m.room_free_area()["bedroom"] / m.free_area)


# -- the apartment ----------------------------------------------------------------------------------
def test_the_apartment(apartment: Map) -> None:
    m = apartment
    assert m.name == "apartment"
    assert m.room_names == ("bedroom", "family_room", "dining_room", "kitchen", "living_room")
    assert m.bounds == (-9.0, -6.0, 9.0, 6.0)
    assert m.grid.resolution == 0.05 and m.grid.shape == (280, 400)
    assert m.priors["cup"] == {"family_room": 0.5, "bedroom": 0.5}
    assert m.priors["spoon"] == {"kitchen": 0.5, "bedroom": 0.5}
    assert {p.name for p in m.places} >= {"fridge_1", "counter_1", "sink_1", "microwave_1", "bed_1", "sofa_1"}
    fridge = m.place("fridge_1")
    assert fridge is not None and fridge.openable and fridge.closed and fridge.room == "kitchen"
    assert [o.cls for o in m.objects] == ["spoon", "cup", "apple"]
    assert m.objects[2].at == fridge.at and m.objects[2].inside == "fridge_1"  # at defaults to the place's
    assert m.sensor == Sensor(range=5.0, fov_deg=360.0)
    assert m.robot.pose == (-6.0, -3.0, 0.0) and m.robot.holding is None
    assert 190 < m.free_area < 216  # 18 m × 12 m less walls, island, wardrobe and pillar
    assert map_path("apartment").resolve() == APARTMENT.resolve()


def test_the_apartment_image_is_what_the_script_draws(tmp_path: Path) -> None:
    drawn = module_from_file("make_apartment", ROOT / "maps" / "make_apartment.py").draw()
    assert np.array_equal(read_pgm((ROOT / "maps" / "apartment.pgm").read_bytes()), drawn.astype(float))


def test_the_apartment_validates_clean() -> None:
    assert check_map_file(APARTMENT) == []
    result = CliRunner().invoke(app, ["validate", str(APARTMENT)])
    assert result.exit_code == 0, result.output
    assert "1 map in 1 file" in result.output


def test_walls_doors_and_rooms_of_the_apartment(apartment: Map) -> None:
    m = apartment
    walls = [[-3.0, 2.0], [0.0, -6.0], [-9.0, 0.0], [5.0, -3.0]]  # a wall, the south wall, the west wall, the island
    assert m.is_occupied(walls).all() and not m.is_free(walls).any()
    doors = [[-3.0, 4.7], [-5.0, 0.5], [0.0, 1.0], [3.0, 4.5], [7.0, 0.0], [2.0, -2.0], [3.0, 0.5]]
    assert m.is_free(doors).all()
    inside = {"bedroom": [-6, 3], "family_room": [0, 3], "dining_room": [6, 3], "kitchen": [6, -4],
              "living_room": [-6, -3]}
    assert m.room_of(list(inside.values())) == list(inside)
    assert m.room_of([[2.5, 0.5], [20.0, 0.0]]) == ["living_room", OUTSIDE]  # the living room's nook; off the map
    assert m.room_index([[20.0, 0.0]]).tolist() == [-1]
    # adjacent rooms share walls: points on the boundary belong to exactly one room
    on_walls = np.array([[x, 0.0] for x in np.linspace(3.1, 8.9, 30)] + [[-3.0, y] for y in np.linspace(1.1, 5.9, 30)])
    assert (m.room_index(on_walls) >= 0).all()
    assert m.line_of_sight((-6.0, -3.0), [[-6.0, 3.0], [-5.0, 3.0], [-1.0, -3.0]]).tolist() == [False, True, True]


def test_no_object_is_visible_from_the_apartment_start(apartment: Map) -> None:
    from seal_cli.sensing.sensor import visible

    x, y, _ = apartment.robot.pose
    points = np.array([o.at for o in apartment.objects])
    assert np.all(np.hypot(points[:, 0] - x, points[:, 1] - y) > apartment.sensor.range)
    assert not visible(apartment, apartment.robot.pose, points).any()


# -- free space and sampling -------------------------------------------------------------------------
def test_sampling_free_space(apartment: Map) -> None:
    rng = np.random.default_rng(3)
    points = apartment.sample_free(rng, 5000)
    assert points.shape == (5000, 2) and apartment.is_free(points).all()
    kitchen = apartment.sample_free(rng, 2000, region="kitchen")
    assert apartment.is_free(kitchen).all()
    assert (np.array(apartment.room_of(kitchen)) == "kitchen").mean() > 0.99  # cells straddling the wall line
    again = apartment.sample_free(np.random.default_rng(3), 5000)
    assert np.array_equal(points, again)
    with pytest.raises(SealError, match="no room 'garage'"):
        apartment.sample_free(rng, 3, region="garage")


# -- priors ---------------------------------------------------------------------------------------------
@pytest.mark.parametrize("cls", ["cup", "spoon"])
def test_sampled_room_masses_match_the_prior(apartment: Map, cls: str) -> None:
    areas = apartment.room_free_area()
    expected = {room: (1 - FLOOR) * apartment.priors[cls].get(room, 0.0) + FLOOR * areas[room] / apartment.free_area
                for room in apartment.room_names}
    assert apartment.prior(cls).room_masses() == pytest.approx({**expected, OUTSIDE: 0.0}, abs=1e-9)
    points = sample_prior(apartment, cls, 40_000, np.random.default_rng(0))
    counts = np.bincount(apartment.room_index(points) + 1, minlength=6) / len(points)
    for i, room in enumerate(apartment.room_names):
        assert counts[i + 1] == pytest.approx(expected[room], abs=0.012), room
    assert apartment.is_free(points).all()


def test_prior_density_is_a_density_over_free_space(apartment: Map) -> None:
    density = prior_density(apartment, "cup", apartment.free_centres)
    assert density.sum() * apartment.cell_area == pytest.approx(1.0)
    assert prior_density(apartment, "cup", [[-3.0, 2.0], [50.0, 50.0]]).tolist() == [0.0, 0.0]  # a wall; off the map
    bedroom, dining = prior_density(apartment, "cup", [[-6.0, 3.0], [6.0, 3.0]])
    assert bedroom / dining > 50
    uniform = prior_density(apartment, "unicorn", apartment.free_centres)
    assert np.allclose(uniform, 1.0 / apartment.free_area)


def test_place_priors_spread_within_reach(apartment: Map) -> None:
    prior = apartment.prior("apple")  # fridge 0.4, counter 0.4 (place classes), kitchen 0.2
    centres = apartment.free_centres
    fridge, counter = np.array(apartment.place("fridge_1").at), np.array(apartment.place("counter_1").at)
    near = np.zeros(len(centres), dtype=bool)
    for place in (fridge, counter):
        disc = np.flatnonzero(np.hypot(*(centres - place).T) <= 1.0)
        near[disc[apartment.line_of_sight(place, centres[disc])]] = True
    kitchen = apartment.free_cell_room == apartment.room_id("kitchen")
    exact = prior.weights[near].sum()
    assert exact == pytest.approx((1 - FLOOR) * (0.8 + 0.2 * near[kitchen].sum() / kitchen.sum())
                                  + FLOOR * near.mean())
    points = prior.sample(20_000, np.random.default_rng(1))
    assert near[apartment.free_index(points)].mean() == pytest.approx(exact, abs=0.015)
    assert prior.room_masses()["kitchen"] == pytest.approx(
        1 - FLOOR + FLOOR * apartment.room_free_area()["kitchen"] / apartment.free_area)  # not through the wall


# -- maps built in code -----------------------------------------------------------------------------------
def test_a_map_from_bounds_alone_is_all_free() -> None:
    m = Map("box", (0.0, 0.0, 4.0, 3.0), rooms=(Room.box("a", 0, 0, 2, 3), Room.box("b", 2, 0, 4, 3)),
            priors={"Cup": {"A": 1.0}})
    assert m.free_area == pytest.approx(12.0)
    assert m.robot.pose == pytest.approx((2.025, 1.525, 0.0), abs=0.05)  # the free cell nearest the middle
    assert m.is_free([[0.01, 0.01], [3.99, 2.99]]).all() and not m.is_free([[4.01, 1.0]]).any()
    assert m.prior("cup").room_masses()["a"] == pytest.approx(1 - FLOOR + FLOOR / 2)
    assert m.line_of_sight((0.5, 0.5), [[3.5, 2.5]]).all()


def test_a_map_from_a_reachability_grid() -> None:
    lattice = np.array([[x, z] for x in np.arange(-1.0, 1.01, 0.25) for z in np.arange(0.0, 1.51, 0.25)])
    grid = OccupancyGrid.from_cells(lattice, 0.25)
    m = Map("FloorPlan1", grid=grid, places=(Place("Fridge_1", "Fridge", (1.5, 0.5), openable=True),),
            priors={"apple": {"fridge": 1.0}}, objects=(ObjectTruth("Apple", (1.5, 0.5), "Fridge_1"),),
            robot=Robot((0.0, 0.0, 0.0)))
    assert m.bounds == (grid.bounds[0], grid.bounds[1], 1.5, grid.bounds[3])  # the fridge is just off the grid
    assert m.free_area == pytest.approx(len(lattice) * 0.0625)
    assert m.place("fridge_1").cls == "fridge" and m.objects[0].cls == "apple"
    near = sample_prior(m, "apple", 1000, np.random.default_rng(0))
    assert (np.hypot(near[:, 0] - 1.5, near[:, 1] - 0.5) < 1.2).mean() > 0.95
    assert m.line_of_sight((0.0, 0.0), [[1.5, 0.5]]).all()  # unknown cells (counters) do not block sight


def test_a_bad_map_in_code_raises_every_problem() -> None:
    with pytest.raises(SealErrors) as caught:
        Map("bad", (0.0, 0.0, 10.0, 10.0), rooms=(Room.box("a", 0, 0, 5, 5), Room.box("b", 4, 4, 8, 8)),
            priors={"cup": {"garage": 0.5, "a": -1.0}, "mug": {"b": 0.7, "a": 0.6}},
            objects=(ObjectTruth("cup", (11.0, 1.0)),))
    messages = [p.message for p in caught.value.problems]
    assert len(messages) == 4  # the overlap is a warning; the object off the map an error
    assert any("garage" in m for m in messages) and any("-1" in m for m in messages)
    assert any("sum to 1.3" in m for m in messages) and any("outside the map's bounds" in m for m in messages)
    odd = Map("odd", (0.0, 0.0, 10.0, 10.0), rooms=(Room.box("a", 0, 0, 5, 5), Room.box("b", 4, 4, 8, 8)),
              objects=(ObjectTruth("cup", (5.0, 1.0)),))
    assert [type(w) for w in odd.warnings] == [MapWarning]
    assert odd.room_of([[4.5, 4.5]]) == ["a"]  # the room listed first wins where they overlap
    with pytest.raises(SealError, match="bounds"):
        Map("nothing")
    with pytest.raises(SealError, match="at least 3 points"):
        Room("r", ((0.0, 0.0), (1.0, 1.0)))
    with pytest.raises(SealError, match="fov"):
        Sensor(fov_deg=0)


@pytest.mark.parametrize("fov", [0.999, 1e-9, 0.5])
def test_a_sensor_narrower_than_a_degree_is_refused(fov: float) -> None:
    """A look all round is 360 / fov looks: ``fov: 0.001`` made ``seal run`` go on without end (hostile31)."""
    from seal_cli.maps.model import MIN_FOV

    with pytest.raises(SealError, match=r"sensor fov must be degrees in \[1, 360\]"):
        Sensor(fov_deg=fov)
    assert Sensor(fov_deg=MIN_FOV).fov_deg == 1.0


# -- broken map files -------------------------------------------------------------------------------------
def expectations(path: Path) -> list[tuple[int, str]]:
    return [(int(line), text.strip()) for line, text in EXPECT.findall(path.read_text())]


def test_corpus_is_large_enough() -> None:
    assert len(CASES) >= 35
    assert all(expectations(p) for p in CASES)


@pytest.mark.parametrize("path", CASES, ids=[p.stem for p in CASES])
def test_each_broken_map_reports_its_problems(path: Path) -> None:
    problems = check_map_file(path)
    got = [(p.line, p.message) for p in problems]
    want = expectations(path)
    assert len(got) == len(want), got
    for (line, message), (want_line, want_text) in zip(got, want, strict=True):
        assert line == want_line, (message, want_text)
        assert want_text in message
    assert all(p.file == str(path) and p.column for p in problems)
    if all(isinstance(p, MapWarning) for p in problems):  # odd but usable: it loads, warnings noted
        assert [w.message for w in load_map(path).warnings] == [p.message for p in problems]
    else:
        with pytest.raises(SealError):
            load_map(path)


@pytest.mark.parametrize("path", CASES, ids=[p.stem for p in CASES])
def test_seal_validate_lists_file_line_column_and_exits_1(path: Path) -> None:
    result = CliRunner().invoke(app, ["validate", str(path)])
    assert result.exit_code == 1
    assert "Traceback" not in result.output
    for line, _ in expectations(path):
        assert re.search(rf"^(error: )?{re.escape(str(path))}:{line}:\d+: ", result.output, re.M), result.output


def test_objects_on_furniture_may_stand_on_occupied_cells(tmp_path: Path) -> None:
    walls = (BAD / "walls.pgm").read_bytes()
    head = "image: walls.pgm\nresolution: 1.0\norigin: [0, 0, 0]\n"
    shelf = "places:\n  - {name: shelf_1, class: shelf, at: [5.5, 2.0]}\n"
    on_it = write_map(tmp_path, head + shelf + "objects:\n  - {class: cup, at: [5.5, 3], in: shelf_1}\n", walls,
                      "walls.pgm")
    assert check_map_file(on_it) == []
    loose = write_map(tmp_path, head + "objects:\n  - {class: cup, at: [5.5, 3]}\n")
    (warning,) = check_map_file(loose)
    assert isinstance(warning, MapWarning) and "say which place it is in" in warning.message
    m = load_map(loose)
    assert m.warnings and m.objects[0].at == (5.5, 3.0)
    from seal_cli.sensing.sensor import visible

    assert visible(m, (7.5, 3.0, 0.0), [m.objects[0].at]).all()  # seen on its obstacle's surface


def test_validate_checks_maps_and_frames_together(tmp_path: Path) -> None:
    report = validate_paths([APARTMENT, BAD / "28_many_problems.yaml"])
    assert report.maps == 2 and len(report.problems) == 4


def test_odd_files_are_problems_not_crashes(tmp_path: Path) -> None:
    for text, message in [("", "empty"), ("- 1\n- 2\n", "must be a mapping"), ("bounds: [0, 0, 1, 1]\nrooms: 3\n",
                                                                              "rooms must be a list")]:
        path = tmp_path / "odd.yaml"
        path.write_text(text)
        problems = check_map_file(path)
        assert problems and message in problems[0].message
    assert "no such file" in check_map_file(tmp_path / "missing.yaml")[0].message



def test_numbers_in_scientific_notation_and_absurd_sizes(tmp_path: Path) -> None:
    # YAML 1.1 reads 5e-2 (no dot) as a string; a map file means the number
    path = write_map(tmp_path, SERVER.format(image="tiny.pgm", negate=0).replace("0.5", "5e-1"), TINY)
    assert load_map(path).grid.resolution == 0.5
    assert "'5'" in check_map_file(write_map(tmp_path, "bounds: [0, 0, 9, 9]\nsensor: {range: '5'}\n"))[0].message
    huge = check_map_file(write_map(tmp_path, "bounds: [0, 0, 1e308, 1e308]\n"))  # each number at its column
    assert [(p.line, p.column) for p in huge] == [(1, 16), (1, 23)]
    assert all("from -10,000,000 to 10,000,000, not '1e308'" in p.message for p in huge)
    (tiny,) = check_map_file(write_map(tmp_path, "bounds: [0, 0, 1e-300, 1e-300]\n"))
    assert "no free space" in tiny.message


yaml_values = st.recursive(
    st.none() | st.booleans() | st.integers(-5, 5) | st.floats(allow_nan=True) | st.text(max_size=4),
    lambda inner: st.lists(inner, max_size=4) | st.dictionaries(st.sampled_from(
        ["name", "box", "polygon", "class", "at", "in", "pose", "range", "fov", "kitchen", "cup", "open"]), inner,
        max_size=4), max_leaves=12)


@settings(max_examples=150, deadline=None, suppress_health_check=[HealthCheck.function_scoped_fixture])
@given(st.dictionaries(st.sampled_from(["bounds", "rooms", "places", "priors", "objects", "robot", "sensor", "name",
                                        "image", "resolution", "origin", "negate"]), yaml_values, max_size=6))
def test_any_map_file_gives_problems_or_a_map_never_a_crash(tmp_path: Path, data: dict) -> None:
    data.setdefault("bounds", [0, 0, 10, 10])
    path = tmp_path / "fuzz.yaml"
    path.write_text(yaml.safe_dump(data))
    problems = check_map_file(path)
    assert all(isinstance(p, SealError) for p in problems)
    if not problems:
        assert isinstance(load_map(path), Map)


# -- seal map and seal bench maps ------------------------------------------------------------------------
def test_seal_map_shows_rooms_priors_places_and_objects() -> None:
    result = CliRunner().invoke(app, ["map", "apartment"])
    assert result.exit_code == 0, result.output
    for text in ("apartment", "family_room", "fridge_1", "closed", "spoon", "counter_1", "p_detect 0.9"):
        assert text in result.output


def test_seal_map_json_and_png_read_back(tmp_path: Path, apartment: Map) -> None:
    import matplotlib.image

    png = tmp_path / "apartment.png"
    result = CliRunner().invoke(app, ["map", str(APARTMENT), "--json", "--png", str(png)])
    assert result.exit_code == 0, result.output
    data = json.loads(result.stdout)
    assert data["name"] == "apartment" and [r["name"] for r in data["rooms"]] == list(apartment.room_names)
    assert data["priors"]["cup"]["masses"] == {"family_room": 0.5, "bedroom": 0.5}
    assert data["priors"]["cup"]["rooms"]["bedroom"] == pytest.approx(apartment.prior("cup").room_masses()["bedroom"],
                                                                      abs=1e-4)
    assert data["objects"][0] == {"class": "spoon", "at": [8.3, -4.1], "in": "counter_1", "room": "kitchen"}
    assert data["robot"]["room"] == "living_room"
    picture = matplotlib.image.imread(png)
    assert picture.shape[1] == 9 * 120 and picture.shape[2] in (3, 4)
    assert len(np.unique(picture.reshape(-1, picture.shape[2])[:, :3], axis=0)) > 20  # walls, rooms, markers


def test_seal_map_errors_are_clean(tmp_path: Path) -> None:
    bad = BAD / "10_prior_sum_above_one.yaml"
    result = CliRunner().invoke(app, ["map", str(bad), "--png", str(tmp_path / "x.png")])
    assert result.exit_code == 1 and "sum to 1.3" in result.output and "Traceback" not in result.output
    assert not (tmp_path / "x.png").exists()
    odd = CliRunner().invoke(app, ["map", str(BAD / "07_overlapping_rooms.yaml"), "--json"])
    assert odd.exit_code == 0 and "warning: " in odd.stderr and "overlaps" in odd.stderr
    assert json.loads(odd.stdout)["rooms"][0]["name"] == "hall"
    result = CliRunner().invoke(app, ["map", "apartment", "--png", str(tmp_path / "no" / "x.png")])
    assert result.exit_code == 1 and "does not exist" in result.output


def test_seal_bench_maps_reports_every_query() -> None:
    result = CliRunner().invoke(app, ["bench", "maps", "--repeats", "1", "--points", "300", "--points", "700",
                                      "--json"])
    assert result.exit_code == 0, result.output
    data = json.loads(result.stdout)
    assert data["map"] == "apartment" and data["rays"] > 1000
    queries = {(q["query"], q["points"]) for q in data["queries"]}
    assert ("visible region contains", 700) in queries and ("is_free", 300) in queries and len(queries) == 16
    assert all(q["ms"] >= 0 for q in data["queries"])


def test_the_code_example_in_the_docs_runs(monkeypatch: pytest.MonkeyPatch) -> None:
    text = (ROOT / "docs" / "maps.md").read_text()
    code = re.search(r"```python\n(.*?)```", text, re.S)
    assert code is not None
    monkeypatch.chdir(ROOT)
    scope: dict = {}
    exec(compile(code.group(1), "docs/maps.md", "exec"), scope)
    assert scope["x"].shape == (1000, 2) and scope["inside"].dtype == bool
    assert (scope["inside"] == scope["exact"]).mean() > 0.99
    assert {d.cls for d in scope["detections"]} == {"spoon", "apple"}
    assert scope["scene"].free_area == pytest.approx(63 * 0.0625)


# -- properties over random maps ---------------------------------------------------------------------------
@st.composite
def random_maps(draw: st.DrawFn) -> Map:
    """A rectangle cut into rooms by vertical walls (some with doors), places, and priors on rooms and places."""
    width, height = draw(st.floats(3, 12)), draw(st.floats(2, 8))
    cuts = sorted(draw(st.lists(st.floats(0.15, 0.85), min_size=0, max_size=3, unique=True)))
    xs = [0.0]
    for x in [c * width for c in cuts]:
        if x - xs[-1] > 0.3 and width - x > 0.3:  # rooms at least 0.3 m wide
            xs.append(x)
    xs.append(width)
    res = 0.1
    cols = int(np.ceil(width / res))
    rows = int(np.ceil(height / res))
    free = np.ones((rows, cols), dtype=bool)
    occupied = np.zeros_like(free)
    for x in xs[1:-1]:
        col = min(int(x / res), cols - 1)
        occupied[:, col] = True
        if draw(st.booleans()):
            occupied[rows // 3: rows // 3 + 8, col] = False  # a door
    free &= ~occupied
    grid = OccupancyGrid.from_masks(free, res, (0.0, 0.0), occupied)
    rooms = tuple(Room.box(f"room_{i}", a, 0.0, b, height) for i, (a, b) in enumerate(zip(xs, xs[1:], strict=False)))
    n_places = draw(st.integers(0, 3))
    places = tuple(Place(f"thing_{i}", draw(st.sampled_from(["table", "shelf"])),
                         (draw(st.floats(0.05, width - 0.05)), draw(st.floats(0.05, height - 0.05))),
                         reach=draw(st.floats(0.2, 1.5))) for i in range(n_places))
    targets = [r.name for r in rooms] + [p.name for p in places] + sorted({p.cls for p in places})
    priors = {}
    for cls in ("cup", "spoon"):
        chosen = draw(st.lists(st.sampled_from(targets), max_size=3, unique=True))
        raw = np.array(draw(st.lists(st.floats(0.0, 1.0), min_size=len(chosen), max_size=len(chosen))))
        scale = draw(st.floats(0.0, 1.0)) / max(raw.sum(), 1e-9)
        priors[cls] = {t: float(m * scale) for t, m in zip(chosen, raw, strict=True)}
    return Map("random", (0.0, 0.0, width, height), rooms=rooms, places=places, priors=priors, grid=grid)


@settings(max_examples=40, deadline=None)
@given(random_maps(), st.sampled_from(["cup", "spoon", "unicorn"]), st.integers(0, 2**31 - 1))
def test_priors_on_random_maps_are_normalised_and_match_their_masses(m: Map, cls: str, seed: int) -> None:
    prior = m.prior(cls)
    assert np.all(np.isfinite(prior.weights)) and np.all(prior.weights > 0)
    assert prior.weights.sum() == pytest.approx(1.0)
    assert prior_density(m, cls, m.free_centres).sum() * m.cell_area == pytest.approx(1.0)
    masses = m.priors.get(cls, {})
    areas = m.room_free_area()
    if not m.places:  # room priors alone: each room's mass is exactly its share
        rest = 1 - sum(masses.values())
        for room in m.room_names:
            expected = (1 - FLOOR) * (masses.get(room, 0.0) + rest * areas[room] / m.free_area) \
                + FLOOR * areas[room] / m.free_area
            assert prior.room_masses()[room] == pytest.approx(expected, abs=1e-9)
    points = prior.sample(4000, np.random.default_rng(seed))
    assert m.is_free(points).all()
    sampled = np.bincount(m.free_cell_room[m.free_index(points)] + 1, minlength=len(m.rooms) + 1) / len(points)
    exact = np.array([prior.room_masses()[OUTSIDE]] + [prior.room_masses()[r] for r in m.room_names])
    assert np.abs(sampled - exact).max() < 0.04


def test_a_rotated_grid_is_read_in_the_world_frame() -> None:
    cells = np.zeros((2, 4), dtype=np.int8)  # 4 cells along the grid's x, 2 along its y
    cells[0, 3] = OCCUPIED
    grid = OccupancyGrid(cells, 1.0, (10.0, 0.0, np.pi / 2))  # the grid's x axis points along world +y
    m = Map("turned", grid=grid)
    assert m.bounds == pytest.approx((8.0, 0.0, 10.0, 4.0))
    assert m.is_occupied([[9.5, 3.5]]).all() and m.is_free([[9.5, 0.5], [8.5, 3.5]]).all()
    points = m.sample_free(np.random.default_rng(0), 500)
    assert m.is_free(points).all() and m.in_bounds(points).all()
    assert m.free_area == pytest.approx(7.0)


@settings(max_examples=30, deadline=None)
@example(specs=[(0.0, 0.0, 1.0, 1.0, 4, 0), (2.15625, 0.375, 2.0, 1.5, 6, 437795897)], resolution=0.05, seed=0)
@given(st.lists(st.tuples(st.floats(-4, 4), st.floats(-3, 3), st.floats(0.3, 3), st.floats(0.3, 3),
                          st.integers(4, 9), st.integers(0, 2**31 - 1)), min_size=1, max_size=4),
       st.sampled_from([0.05, 0.1, 0.25, 0.5]), st.integers(0, 2**31 - 1))
def test_room_index_is_exact(specs: list, resolution: float, seed: int) -> None:
    rooms = []
    for i, (cx, cy, rx, ry, n, s) in enumerate(specs):
        r = np.random.default_rng(s)  # a star-shaped room: evenly spread angles, jittered, random radii
        angles = (np.arange(n) + r.uniform(-0.3, 0.3, n)) * 2 * np.pi / n
        radius = r.uniform(0.4, 1.0, n)
        vertices = np.column_stack([cx + rx * radius * np.cos(angles), cy + ry * radius * np.sin(angles)])
        if i % 2:  # every other room drawn on grid lines, where rounding would bite
            vertices = np.round(vertices / resolution) * resolution
        rooms.append(Room(f"r{i}", tuple((float(x), float(y)) for x, y in vertices)))
    try:
        m = Map("rooms", (-8.0, -7.0, 8.0, 7.0), rooms=tuple(rooms), grid=OccupancyGrid.filled((-8, -7, 8, 7),
                                                                                                resolution))
    except SealError:
        return  # a room that rounding to the grid made degenerate
    rng = np.random.default_rng(seed)
    vertices = np.vstack([r.vertices for r in m.rooms])
    on_edges = np.vstack([a + rng.uniform(0, 1, (20, 1)) * (b - a) for r in m.rooms
                          for a, b in zip(r.vertices, np.roll(r.vertices, -1, axis=0), strict=True)])
    lattice = np.round(rng.uniform(-8, 8, (3000, 2)) / resolution) * resolution
    points = np.vstack([rng.uniform(-9, 9, (5000, 2)), vertices, on_edges, lattice])
    assert np.array_equal(m.room_index(points), m._room_index_exact(points))


def _edited_apartment(tmp_path: Path, name: str, old: str, new: str) -> Path:
    """A copy of the shipped apartment in ``tmp_path`` (with its image) where ``old`` reads ``new``."""
    text = APARTMENT.read_text()
    assert old in text
    bad = tmp_path / name
    bad.write_text(text.replace(old, new, 1))
    (tmp_path / "apartment.pgm").write_bytes((APARTMENT.parent / "apartment.pgm").read_bytes())
    return bad


def test_a_number_too_large_for_a_float_is_a_located_error(tmp_path: Path) -> None:
    bad = _edited_apartment(tmp_path, "huge.yaml", "resolution: 0.05", "resolution: " + "1" * 400)
    result = CliRunner().invoke(app, ["map", str(bad), "--png", str(tmp_path / "x.png")])
    assert result.exit_code == 1, result.output
    assert f"{bad}:7:13: resolution must be a number of metres per pixel of at least 0.001" in result.stderr
    assert "Traceback" not in result.stderr and not (tmp_path / "x.png").exists()


@pytest.mark.parametrize(("old", "new", "where", "message"), [
    ("sensor: {range: 5.0, fov: 360}", "sensor: {range: 1e300, fov: 360}", ":45:17:", "sensor range must be"),
    ("at: [8.5, -4.0]}", "at: [8.5, -4.0], reach: 1.0e+300}", ":24:63:", "reach must be"),
])
def test_a_range_or_reach_beyond_any_building_is_refused(tmp_path: Path, old: str, new: str, where: str,
                                                         message: str) -> None:
    bad = _edited_apartment(tmp_path, "far.yaml", old, new)
    for args in (["map", str(bad)], ["localize", "--map", str(bad), "--steps", "1", "--particles", "10",
                                     "--png", str(tmp_path / "x.png")]):
        result = CliRunner().invoke(app, args)
        assert result.exit_code == 1, result.output
        assert f"{bad}{where} {message}" in result.stderr and "at most 1000" in result.stderr
        assert "Traceback" not in result.stderr and not (tmp_path / "x.png").exists()


@pytest.mark.parametrize(("old", "new", "where", "message"), [
    ("holding: null}", "holding: 7}", ":44:8:", "holding '7' is not a class name"),
    ("{class: apple, in: fridge_1}", "{class: '@@', in: fridge_1}", ":43:5:", "object class '@@' is not a class name"),
])
def test_a_class_a_plan_cannot_name_is_refused_where_it_is(tmp_path: Path, old: str, new: str, where: str,
                                                           message: str) -> None:
    bad = _edited_apartment(tmp_path, "odd.yaml", old, new)
    for args in (["map", str(bad)], ["plan", "--map", str(bad), "bring the apple to the bed"]):
        result = CliRunner().invoke(app, args)
        assert result.exit_code == 1, result.output
        assert f"{bad}{where} {message}" in result.stderr
        assert "Traceback" not in result.stderr


# -- many rooms: the room lookup and the overlap check scale with rooms plus points ----------------
def _rooms_by_brute_force(m: Map, points: np.ndarray) -> np.ndarray:
    out = np.full(len(points), -1)
    for index, room in enumerate(m.rooms):
        todo = out < 0
        out[np.flatnonzero(todo)[room.contains(points[todo])]] = index
    return out


@pytest.mark.parametrize("points", [50, 30_000])  # all against all, and the bucket grid
def test_room_lookup_by_buckets_is_the_brute_force_answer(points: int) -> None:
    rng = np.random.default_rng(3)
    rooms = []
    for i in range(300):  # overlapping boxes and triangles of every size: the first room listed wins
        x, y = rng.uniform(0, 50, 2)
        w, h = rng.uniform(0.5, 15, 2)
        triangle = ((x, y), (x + w, y), (x, y + h))
        rooms.append(Room.box(f"r{i}", x, y, x + w, y + h) if i % 2 else Room(f"r{i}", triangle))
    m = Map("many", (0.0, 0.0, 70.0, 70.0), rooms=tuple(rooms), check=False)
    p = np.vstack([rng.uniform(-5, 75, (points, 2)), [[np.nan, 1.0], [np.inf, 2.0]],
                   [r.polygon[0] for r in rooms]])  # vertices: on the edges, where half-open rules decide
    assert np.array_equal(m._room_index_exact(p), _rooms_by_brute_force(m, p))


def test_overlapping_rooms_are_found_by_a_sweep_not_all_pairs() -> None:
    from seal_cli.maps.model import _box_pairs

    rng = np.random.default_rng(4)
    lo = rng.uniform(0, 100, (400, 2))
    boxes = np.hstack([lo, lo + rng.uniform(0.1, 10, (400, 2))])
    brute = [(i, j) for i in range(400) for j in range(i + 1, 400)
             if boxes[i, 0] < boxes[j, 2] and boxes[j, 0] < boxes[i, 2]
             and boxes[i, 1] < boxes[j, 3] and boxes[j, 1] < boxes[i, 3]]
    assert sorted(_box_pairs(boxes)) == brute and brute


def test_thousands_of_rooms_validate(tmp_path: Path) -> None:  # 10,000: `seal bench reliability`
    rows = ["bounds: [0, 0, 100, 20]", "rooms:"]
    rows += [f"  - {{name: r{i}, box: [{i % 100}, {i // 100}, {i % 100 + 1}, {i // 100 + 1}]}}" for i in range(2_000)]
    rows += ["  - {name: extra, box: [0.5, 0.5, 1.5, 1.5]}"]  # overlaps four rooms
    path = tmp_path / "many.yaml"
    path.write_text("\n".join(rows) + "\n")
    problems = check_map_file(path)
    assert [p.line for p in problems] == [2_003] * 4 and all("overlaps" in p.message for p in problems)
    assert load_map(path).room_of([[99.5, 19.5], [1.2, 1.2]]) == ["r1999", "r101"]


def test_a_place_in_no_room_is_a_located_warning_and_the_map_still_loads(tmp_path: Path) -> None:
    path = _edited_apartment(tmp_path, "roomless.yaml", "  - {name: kitchen, box: [2.0, -6.0, 9.0, 0.0]}\n", "")
    text = path.read_text().replace("kitchen: 0.5, ", "").replace(", kitchen: 0.2", "")
    path.write_text(text.replace("room: kitchen", "room: bedroom"))
    problems = check_map_file(path)
    assert [p.message.split(" at ")[0] for p in problems] == [f"place {name}" for name in
                                                              ("fridge_1", "counter_1", "stove_1", "sink_1",
                                                               "microwave_1")]
    assert all(isinstance(p, MapWarning) and "in no room of this map" in p.message for p in problems)
    assert (problems[0].line, problems[0].column) == (text.split("\n").index(
        "  - {name: fridge_1, class: fridge, at: [8.5, -0.8], openable: true}") + 1, 37)
    assert len(load_map(path).warnings) == 5
    result = CliRunner().invoke(app, ["localize", "--map", str(path), "--steps", "0", "--particles", "10"])
    assert result.exit_code == 0
    assert f"warning: {path}:{problems[0].line}:37: place fridge_1" in result.stderr


def test_people_have_roles_and_the_speaker_too(tmp_path: Path) -> None:
    """``role:`` is a noun or a list of nouns, kept as class keys; ``seal map --json`` lists them."""
    path = write_map(tmp_path, "bounds: [0, 0, 10, 5]\nrooms:\n  - {name: ward, box: [0, 0, 5, 5]}\n"
                     "people:\n  - {name: Nora, room: ward, role: nurse}\n"
                     "  - {name: Ida, at: [6, 2], role: [Nurse, head nurse]}\n  - {name: Ben, at: [7, 2]}\n"
                     "speaker: {role: doctor}\n")
    m = load_map(path)
    assert [p.roles for p in m.people] == [("nurse",), ("nurse", "head_nurse"), ()]
    assert m.speaker is None and m.speaker_roles == ("doctor",) and m.speaker_at == m.robot.xy
    assert m.with_role("nurse") == ("nora", "ida") and m.with_role("Doctor") == ("me",) and m.with_role("cook") == ()
    result = CliRunner().invoke(app, ["map", str(path), "--json"])
    data = json.loads(result.stdout)
    assert data["people"][1] == {"name": "Ida", "at": [6.0, 2.0], "room": "_outside", "roles": ["nurse", "head_nurse"]}
    assert data["speaker"]["roles"] == ["doctor"]
    with pytest.raises(SealError, match="person Eve: role must be a noun or a list of nouns"):
        Map("m", bounds=(0, 0, 5, 5), people=(Person("Eve", (1.0, 1.0), roles=(3,)),))  # type: ignore[arg-type]


def test_a_room_of_more_points_than_seal_reads_is_refused_by_name() -> None:
    from seal_cli.maps.model import MAX_ROOM_VERTICES, Room

    t = np.linspace(0, 2 * np.pi, MAX_ROOM_VERTICES + 1, endpoint=False)
    with pytest.raises(SealError, match=r"room den: its polygon has 10,001 points; .* simplify the outline"):
        Room("den", tuple(zip(np.cos(t), np.sin(t), strict=True)))
    assert len(Room("den", tuple(zip(np.cos(t[1:]), np.sin(t[1:]), strict=True))).polygon) == MAX_ROOM_VERTICES


def test_rooms_at_names_every_area_that_holds_a_point() -> None:
    """Where areas overlap, ``room_of`` gives the first; ``rooms_at`` every one, in the map's order (hostile25)."""
    m = Map(name="m", bounds=(0, 0, 10, 10), rooms=(Room("west", ((0, 0), (6, 0), (6, 10), (0, 10))),
                                                    Room("east", ((4, 0), (10, 0), (10, 10), (4, 10)))))
    assert m.rooms_at((5, 5)) == ("west", "east") and m.room_of([(5, 5)]) == ["west"]
    assert m.rooms_at((8, 5)) == ("east",) and m.rooms_at((11, 5)) == ()


def test_a_kind_the_map_spells_like_an_unknown_one_is_named() -> None:
    """What a refusal of a thing the map lacks adds when the map names a kind spelt like it (hostile26: a map's
    ``{class: mgu}``, and "bring me the mug" refused without a word of it)."""
    m = Map("m", (0.0, 0.0, 10.0, 10.0), priors={"mgu": {"kitchen": 1.0}},
            rooms=(Room.box("kitchen", 0, 0, 10, 10),))
    assert m.spelt_like("mug") == "; the map names a mgu, spelt like it (a typo in the map?)"
    assert m.spelt_like("mgu") == "" and m.spelt_like("sofa") == ""
    assert "coffee table" in m.spelt_like("coffee_tabel", ["coffee_table"])
    beds = Map("m", (0.0, 0.0, 10.0, 10.0), priors={"bed": {"kitchen": 1.0}},
               rooms=(Room.box("kitchen", 0, 0, 10, 10),))
    assert "a bed, spelt like it" in beds.spelt_like("bread")
    assert beds.spelt_like("bread", words={"bed", "bread"}) == ""       # a word the library knows is no typo
    beans = Map("m", (0.0, 0.0, 10.0, 10.0), priors={"coffee_beans": {"kitchen": 1.0}},
                rooms=(Room.box("kitchen", 0, 0, 10, 10),))
    assert beans.spelt_like("coffee") == ("; the map names 'coffee beans', a kind of its own: say that if it is what "
                                          "is meant")          # a compound of the word, no typo (e2e33)


def test_rooms_drawn_one_over_another_are_said_up_to_a_bound(tmp_path: Path) -> None:
    """hostile30: 10,000 identical rooms (within the bound of a list) were 50 million pairs, checked for hours."""
    from seal_cli.maps.model import MAX_OVERLAPS

    rooms = "".join(f"  - {{name: r{i}, box: [0, 0, 1, 1]}}\n" for i in range(5_000))
    path = tmp_path / "m.yaml"
    path.write_text(f"name: m\nbounds: [0, 0, 10, 10]\nrooms:\n{rooms}", encoding="utf-8")
    found = [p.message for p in check_map_file(path) if "overlap" in p.message]
    assert len(found) == MAX_OVERLAPS + 1 and found[-1].startswith(f"more rooms overlap than the {MAX_OVERLAPS} pairs")
