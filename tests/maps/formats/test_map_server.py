"""maps.formats.map_server: map files read as ROS map_server reads them; every bad image one clear error."""

from __future__ import annotations

import re
from pathlib import Path

import numpy as np
import pytest

from seal_cli.errors import SealError
from seal_cli.maps.formats.map_server import KEYS, MAP_SERVER_KEYS, SEMANTIC_KEYS, load_map, read_image, read_pgm
from seal_cli.maps.geometry import FREE, OCCUPIED, UNKNOWN
from seal_cli.resources import maps_dir


def test_the_keys_are_map_servers_then_seals() -> None:
    assert KEYS == MAP_SERVER_KEYS + ("occupancy",) + SEMANTIC_KEYS  # occupancy: a grid from a ROS bag
    assert {"image", "resolution", "origin", "negate", "occupied_thresh", "free_thresh"} <= set(MAP_SERVER_KEYS)
    assert {"rooms", "places", "priors", "objects", "robot", "sensor"} <= set(SEMANTIC_KEYS)


@pytest.mark.parametrize(("data", "says"), [
    (b"P6\n1 1\n255\n\x00", "not a PGM image"),
    (b"P5\n3\n", "cut short"),
    (b"P5\n0 2\n255\n", "impossible values"),
    (b"P5\n2 2\n70000\n", "impossible values"),
    (b"P5\n2 2\n255\n\x00\x00", "truncated"),
    (b"P2\n2 1\n255\n1 x\n", "whole numbers"),
    (b"P2\n2 1\n255\n1\n", "only 1 values"),
    (b"P2\n2 1\n100\n1 200\n", "exceeds the maximum 100"),
])
def test_a_broken_pgm_is_one_clear_error(data: bytes, says: str) -> None:
    with pytest.raises(SealError, match=says):
        read_pgm(data)


@pytest.mark.parametrize(("data", "says"), [
    # a text PGM's values are ASCII digits: a sign, a fraction, NaN or an exponent was read by float() (hostile29)
    (b"P2\n2 2\n255\n1 -2 3 4\n", r"not '-2' \(byte 14 of the file\)"),
    (b"P2\n2 2\n255\n1 2.5 3 4\n", r"not '2\.5' \(byte 14 of the file\)"),
    (b"P2\n2 2\n255\n1 nan 3 4\n", "not 'nan'"),
    (b"P2\n2 2\n255\n1\t+2 3 4\n", "not '\\+2'"),
    (b"P2\n2 2\n255\n1 1e3 3 4\n", "not '1e3'"),
    # 5,000 digits: int() raised ValueError in the header, and a pixel became inf, int(inf) an OverflowError
    (b"P5\n" + b"9" * 5000 + b" 10\n255\n", "width has 5,000 digits"),
    (b"P5\n10 10\n" + b"9" * 13 + b"\n", "maximum value has 13 digits"),
    (b"P2\n2 2\n255\n1 " + b"9" * 5000 + b" 3 4\n", r"999999999999… \(5,000 digits\) exceeds the maximum 255"),
])
def test_a_pgm_holding_what_no_pgm_holds_is_refused_saying_what(data: bytes, says: str) -> None:
    with pytest.raises(SealError, match=says):
        read_pgm(data)


def test_a_text_pgm_of_digits_reads_as_before() -> None:
    assert read_pgm(b"P2\n3 1\n255\n0\t254\r\n205\n").tolist() == [[0.0, 254.0, 205.0]]


def test_a_pgm_is_scaled_to_255_with_row_zero_on_top() -> None:
    grey = read_pgm(b"P2\n2 2\n# max 10\n10\n0 10\n5 10\n")
    assert grey.tolist() == [[0.0, 255.0], [127.5, 255.0]]


def test_cells_follow_the_thresholds_and_the_image_is_flipped(tmp_path: Path) -> None:
    path = tmp_path / "t.pgm"
    path.write_bytes(b"P5\n3 2\n255\n" + bytes([0, 254, 205, 255, 0, 0]))
    cells = read_image(path)
    # image row 0 (the top) is the highest y: it becomes the last row of the grid
    assert cells[1].tolist() == [OCCUPIED, FREE, UNKNOWN] and cells[0].tolist() == [FREE, OCCUPIED, OCCUPIED]
    assert read_image(path, negate=True)[1].tolist() == [FREE, OCCUPIED, OCCUPIED]


@pytest.mark.parametrize(("name", "data", "says"), [
    ("missing.pgm", None, "does not exist"),
    ("t.jpg", b"\xff\xd8\xff\xe0", "neither PGM"),
    ("t.png", b"\x89PNG\r\n\x1a\nnot really", "cannot read image t.png"),
])
def test_an_unreadable_image_is_named(tmp_path: Path, name: str, data: bytes | None, says: str) -> None:
    if data is not None:
        (tmp_path / name).write_bytes(data)
    with pytest.raises(SealError, match=says):
        read_image(tmp_path / name)


def test_a_map_file_naming_a_bad_image_says_where(tmp_path: Path) -> None:
    (tmp_path / "m.yaml").write_text("image: gone.pgm\nresolution: 0.5\norigin: [0, 0, 0]\n")
    with pytest.raises(SealError) as caught:
        load_map(tmp_path / "m.yaml")
    assert "gone.pgm" in str(caught.value) and caught.value.file == str(tmp_path / "m.yaml")


def test_the_shipped_apartment_loads_by_name_and_path_alike() -> None:
    by_name, by_path = load_map("apartment"), load_map(maps_dir() / "apartment.yaml")
    assert by_name.name == by_path.name == "apartment"
    assert np.array_equal(by_name.grid.cells, by_path.grid.cells)


def test_an_image_of_more_cells_than_the_bound_is_refused_before_its_pixels(tmp_path: Path) -> None:
    import struct
    import zlib

    from seal_cli.maps.geometry import MAX_IMAGE_CELLS

    assert MAX_IMAGE_CELLS == 4096 * 4096
    with pytest.raises(SealError, match=r"4,097×4,096 pixels .* at most 16,777,216 cells"):
        read_pgm(b"P5\n4097 4096\n255\n")  # refused from the header: no pixels needed
    body = b"IHDR" + struct.pack(">IIBBBBB", 20_000, 20_000, 8, 0, 0, 0, 0)
    png = tmp_path / "bomb.png"  # a PNG's header alone: the decoder would unpack it into gigabytes
    png.write_bytes(b"\x89PNG\r\n\x1a\n" + struct.pack(">I", 13) + body + struct.pack(">I", zlib.crc32(body)))
    with pytest.raises(SealError, match=r"20,000×20,000 pixels"):
        read_image(png)


def _problems(tmp_path: Path, text: str) -> list[tuple[int | None, str]]:
    from seal_cli.maps.formats.map_server import check_map_file

    path = tmp_path / "x.yaml"
    path.write_text("name: a\nbounds: [0, 0, 10, 10]\n" + text)
    return [(p.line, p.message) for p in check_map_file(path)]


def test_a_problem_after_an_item_that_could_not_be_built_is_at_its_own_line(tmp_path: Path) -> None:
    rooms = ("rooms:\n  - {name: kitchen, polygon: [[0, 0], [1, 1]]}\n  - {name: den, box: [0, 0, 1, 1]}\n"
             "  - {name: hall, polygon: [[2, 2], [9, 9], [9, 2], [2, 9]]}\n")
    lines = {message.split(":")[0]: line for line, message in _problems(tmp_path, rooms)}
    assert lines["room hall intersects itself"] == 6  # was 5, den's line: the broken kitchen moved them up
    places = "places:\n  - {name: sink_1, class: sink}\n  - {name: bed_1, class: bed, at: [50, 5]}\n"
    assert (5, "place bed_1 at [50, 5] is outside the map's bounds [0, 0]–[10, 10]") in _problems(tmp_path, places)
    objects = "objects:\n  - {class: cup, at: [1]}\n  - {class: mug, at: [50, 5]}\n"
    assert any(line == 5 and "object mug" in message for line, message in _problems(tmp_path, objects))


def test_a_room_called_outside_or_wholly_off_the_map_and_absurd_coordinates_are_refused(tmp_path: Path) -> None:
    said = _problems(tmp_path, "rooms:\n  - {name: _Outside, box: [0, 0, 5, 5]}\n")
    assert said == [(4, "a room cannot be called '_Outside': seal's outputs give that name to the mass in no room; "
                        "call the room another name")]
    assert _problems(tmp_path, "rooms:\n  - {name: outside, box: [0, 0, 5, 5]}\n") == []  # a garden may be
    said = _problems(tmp_path, "rooms:\n  - {name: a, box: [0, 0, 5, 5]}\n  - {name: b, box: [20, 0, 30, 5]}\n")
    assert said == [(5, "room b ([20, 0]–[30, 5]) is wholly outside the map's bounds [0, 0]–[10, 10]: nothing in "
                        "it can be reached or seen")]
    said = _problems(tmp_path, "robot: {pose: [1, 1, 1e300]}\n")
    assert said == [(3, "each number of robot pose must be a number of metres from -10,000,000 to 10,000,000, "
                        "not '1e300'")]
    assert _problems(tmp_path, "robot: {pose: [1, 1, 0]}\nspeaker: {at: [9.9, 1e1]}\n") == []


def _apartment_in(tmp_path: Path, image: bytes) -> Path:
    text = (maps_dir() / "apartment.yaml").read_text().replace("image: apartment.pgm", "image: big.pgm")
    (tmp_path / "big.pgm").write_bytes(image)
    (tmp_path / "m.yaml").write_text(text)
    return tmp_path / "m.yaml"


def test_a_large_mostly_unknown_image_is_cropped_to_what_it_knows(tmp_path: Path,
                                                                   monkeypatch: pytest.MonkeyPatch) -> None:
    """A real ROS map: the building in a large unknown sheet. Read by rows, cropped: the same cells, at the
    same places of the world, as the building's own image."""
    from seal_cli.bench.reliability_attacker import _pgm_pixels, sparse_pgm
    from seal_cli.maps.formats import map_server

    monkeypatch.setattr(map_server, "MAX_GRID_CELLS", 200_000)  # the apartment's 112,000 pixels fit; 1,000² not
    monkeypatch.setattr(map_server, "BAND", 10_000)  # many bands
    pixels, width, height = _pgm_pixels((maps_dir() / "apartment.pgm").read_bytes())
    small, large = load_map("apartment"), load_map(_apartment_in(tmp_path, sparse_pgm(1_000, 1_000, pixels, width,
                                                                                      height)))
    assert large.warnings == small.warnings == ()
    known = small.grid.cells != UNKNOWN
    rows, cols = np.flatnonzero(known.any(axis=1)), np.flatnonzero(known.any(axis=0))
    assert np.array_equal(large.grid.cells, small.grid.cells[rows[0]:rows[-1] + 1, cols[0]:cols[-1] + 1])
    corner = small.grid.grid_to_world(np.array([[cols[0], rows[0]]]) * small.grid.resolution)[0]
    assert np.allclose(large.grid.origin[:2], corner) and large.grid.resolution == small.grid.resolution


def test_a_large_known_image_is_coarsened_with_a_warning_and_its_walls_kept(tmp_path: Path,
                                                                           monkeypatch: pytest.MonkeyPatch) -> None:
    from seal_cli.maps.formats import map_server

    monkeypatch.setattr(map_server, "MAX_GRID_CELLS", 250_000)
    picture = np.full((1_000, 1_000), 254, dtype=np.uint8)  # free everywhere ...
    picture[:, 501] = 0  # ... but one wall a pixel thin, at an odd column
    image = b"P5\n1000 1000\n255\n" + picture.tobytes()
    (tmp_path / "x.pgm").write_bytes(image)
    found = map_server.read_image_cells(tmp_path / "x.pgm")
    assert found.factor == 2 and found.cells.shape == (500, 500)
    assert (found.cells[:, 250] == OCCUPIED).all() and (found.cells[:, 249] == FREE).all()  # the wall stays closed
    text = "image: x.pgm\nresolution: 0.05\norigin: [0, 0, 0]\nname: a\n"
    (tmp_path / "x.yaml").write_text(text)
    warnings = load_map(tmp_path / "x.yaml").warnings
    assert [w.message for w in warnings if "merges 2×2 pixels" in w.message and "0.1 m" in w.message]
    assert warnings[0].line == 1


def test_a_large_text_pgm_or_png_says_what_to_do(tmp_path: Path) -> None:
    with pytest.raises(SealError, match=r"6,000×6,000 pixels .* save it as a binary PGM \(P5\)"):
        read_pgm(b"P2\n6000 6000\n255\n205 205\n")
    with pytest.raises(SealError, match=r"binary PGM images of at most 268,435,456 pixels"):
        (tmp_path / "x.pgm").write_bytes(b"P5\n20000 20000\n255\n")
        read_image(tmp_path / "x.pgm")


def test_every_grid_of_a_map_has_at_most_max_grid_cells(tmp_path: Path) -> None:
    """A fully known 8,200 x 8,200 image was 2,734 x 2,734 cells (64 s and 3.9 GB to run), bounds of 100 m x 100 m
    4 million cells (2.3 GB): an image, PNG or PGM, is cropped and coarsened to MAX_GRID_CELLS, with a warning; bounds
    alone get coarser cells."""
    import matplotlib.image

    from seal_cli.maps.formats import map_server
    from seal_cli.maps.geometry import MAX_GRID_CELLS

    assert MAX_GRID_CELLS == 1024 * 1024
    picture = np.full((1_500, 1_500), 254, dtype=np.uint8)
    picture[:, 700] = 0
    (tmp_path / "x.pgm").write_bytes(b"P5\n1500 1500\n255\n" + picture.tobytes())
    matplotlib.image.imsave(tmp_path / "x.png", picture, cmap="gray", vmin=0, vmax=255)
    for name in ("x.pgm", "x.png"):
        found = map_server.read_image_cells(tmp_path / name)
        assert found.factor == 2 and found.cells.size <= MAX_GRID_CELLS and (found.cells[:, 350] == OCCUPIED).all()
        (tmp_path / "x.yaml").write_text(f"image: {name}\nresolution: 0.05\norigin: [0, 0, 0]\nname: a\n")
        m = load_map(tmp_path / "x.yaml")
        assert m.grid.resolution == 0.1 and [w for w in m.warnings if "merges 2×2 pixels" in w.message]
    (tmp_path / "b.yaml").write_text("name: b\nbounds: [0, 0, 100, 100]\nrooms:\n"
                                     "  - {name: a, box: [0, 0, 100, 100]}\n")
    m = load_map(tmp_path / "b.yaml")
    assert m.grid.cells.size <= MAX_GRID_CELLS and m.grid.resolution > 0.05


def test_a_png_is_classified_by_bands_as_whole(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    """A 4,096² RGBA PNG of 76 KB took 1.6 GB as float64 arrays: it is classified a band of rows at a time, the same
    cells (grey the mean of the colours, a transparent pixel unknown)."""
    from PIL import Image

    from seal_cli.bench.reliability_attacker import rgba_png
    from seal_cli.maps.formats import map_server

    rng = np.random.default_rng(0)
    Image.fromarray(rng.integers(0, 256, (300, 200, 4), dtype=np.uint8)).save(tmp_path / "x.png")
    whole = map_server.read_image(tmp_path / "x.png")
    monkeypatch.setattr(map_server, "BAND", 1_000)
    assert np.array_equal(map_server.read_image(tmp_path / "x.png"), whole)
    assert (whole == UNKNOWN).any() and (whole == FREE).any() and (whole == OCCUPIED).any()
    (tmp_path / "w.png").write_bytes(rgba_png(64))
    cells = map_server.read_image(tmp_path / "w.png")
    assert (cells[:, 32] == OCCUPIED).all() and (cells[:, 31] == FREE).all()


def test_a_place_whose_name_or_class_no_plan_can_use_is_refused_at_its_line(tmp_path: Path) -> None:
    # 'fridge[/]' validated, then every plan on the map failed: "argument 'fridge[/]' is not a name", unplaced
    said = _problems(tmp_path, "places:\n  - {name: 'fridge[/]', class: fridge, at: [1, 1]}\n"
                               "  - {name: sink_1, class: 'si|nk', at: [2, 2]}\n"
                               "  - {name: Bed 1, class: bed, at: [3, 3]}\n")
    assert said == [(4, "place name 'fridge[/]' is not a class name (letters, digits, '_' or spaces, not starting "
                        "with a digit)"),
                    (5, "place sink_1: class 'si|nk' is not a class name (letters, digits, '_' or spaces, not "
                        "starting with a digit)")]


def test_a_map_of_more_values_than_the_bound_is_refused_at_the_value_past_it(tmp_path: Path,
                                                                              monkeypatch: pytest.MonkeyPatch) -> None:
    from seal_cli import yamlnodes
    from seal_cli.maps.formats.map_server import read_map

    monkeypatch.setattr(yamlnodes, "MAX_VALUES", 50)
    path = tmp_path / "m.yaml"
    path.write_text("name: m\nbounds: [0, 0, 4, 4]\nnoise: [" + ", ".join("0" * 60) + "]\n")
    built, problems = read_map(path)
    assert built is None and [(p.where.line, p.message) for p in problems] == [
        (3, "this file holds more than 50 values; seal reads at most that many")]


@pytest.mark.parametrize(("resolution", "says"), [
    ("1e-300", "resolution must be a number of metres per pixel of at least 0.001"),
    ("0.0009", "resolution must be a number of metres per pixel of at least 0.001"),
    ("1e300", "resolution 1e+300 m of an image of 2×2 pixels from origin [0, 0] reaches [2e+300, 2e+300] m"),
    ("6e6", "reaches [1.2e+07, 1.2e+07] m; a map's coordinates are at most 10,000,000 m"),
])
def test_a_resolution_no_map_can_have_is_refused_at_its_line(tmp_path: Path, resolution: str, says: str) -> None:
    """hostile19: resolution 1e300 of a small PNG was an OverflowError traceback; 1e-300 a map of no area."""
    (tmp_path / "i.pgm").write_bytes(b"P5\n2 2\n255\n" + bytes([254] * 4))
    (tmp_path / "m.yaml").write_text(f"image: i.pgm\nresolution: {resolution}\norigin: [0, 0, 0]\n")
    with pytest.raises(SealError, match=re.escape(says)) as caught:
        load_map(tmp_path / "m.yaml")
    assert (caught.value.where.line, caught.value.where.column) == (2, 13)
    (tmp_path / "m.yaml").write_text("image: i.pgm\nresolution: 0.001\norigin: [0, 0, 0]\n")
    assert load_map(tmp_path / "m.yaml").grid.resolution == 0.001


def test_a_room_mostly_outside_the_bounds_is_a_warning_naming_how_much(tmp_path: Path) -> None:
    # a 50 m room on an image of 0.1 m (a resolution ten times too fine) validated without a word (hostile21)
    said = _problems(tmp_path, "rooms:\n  - {name: a, box: [0, 0, 5, 5]}\n  - {name: b, box: [5, 0, 30, 5]}\n")
    assert said == [(5, "room b ([5, 0]–[30, 5]) lies 80% outside the map's bounds [0, 0]–[10, 10]: what is there "
                        "can be neither reached nor seen (do the image's resolution and origin match the rooms?)")]
    assert _problems(tmp_path, "rooms:\n  - {name: a, box: [-1, 0, 10, 10]}\n") == []  # a wall's width past: read
    path = tmp_path / "m.yaml"
    path.write_text("name: m\nbounds: [0, 0, 10, 10]\nrooms:\n  - {name: b, polygon: [[5, 0], [30, 0], [30, 5]]}\n")
    from seal_cli.maps.formats.map_server import check_map_file

    problems = check_map_file(path)      # a triangle of 62.5 m², 2.5 m² of it inside
    assert [type(p).__name__ for p in problems] == ["MapWarning"] and "lies 96% outside" in problems[0].message


def test_the_area_of_a_polygon_inside_a_box() -> None:
    from seal_cli.maps.geometry import box_polygon, clipped_area

    assert clipped_area(box_polygon(0, 0, 10, 10), (0, 0, 5, 5)) == 25.0
    assert clipped_area(box_polygon(0, 0, 10, 10)[::-1], (2, 2, 20, 20)) == 64.0      # clockwise too
    assert clipped_area([[0, 0], [4, 0], [0, 4]], (1, -1, 10, 10)) == pytest.approx(4.5)
    assert clipped_area(box_polygon(0, 0, 1, 1), (5, 5, 6, 6)) == 0.0
    concave = [[0, 0], [6, 0], [6, 6], [4, 6], [4, 2], [2, 2], [2, 6], [0, 6]]     # a U: 28 m²
    assert clipped_area(concave, (0, 0, 6, 3)) == pytest.approx(16.0)               # its lower 3 m: 12 + 2 × 2


@pytest.mark.parametrize(("value", "shown"), [("[true]", "a list"), ("{a: 1}", "a mapping"), ('"yes"', "'yes'")])
def test_an_open_of_another_type_is_said_as_its_shape(tmp_path: Path, value: str, shown: str) -> None:
    # a list was said as "not [ScalarNode(tag='tag:yaml.org,2002:bool', value='true')]" (hostile24)
    (tmp_path / "m.yaml").write_text("name: m\nbounds: [0, 0, 10, 10]\nplaces:\n  - {name: fridge_1, class: fridge, "
                                     f"at: [5, 5], openable: true, open: {value}}}\n")
    with pytest.raises(SealError) as caught:
        load_map(tmp_path / "m.yaml")
    assert (caught.value.message, caught.value.line, caught.value.column) == (
        f"open must be true or false, not {shown}", 4, 71)


def test_a_name_spelt_decomposed_by_a_yaml_escape_is_read_composed(tmp_path: Path) -> None:
    # "cafe\u0301" in a double-quoted scalar is decomposed after the file's text was composed: "go to the café" was
    # "the m has no café ...; its rooms are café, lounge" (hostile24)
    (tmp_path / "m.yaml").write_text('name: m\nbounds: [0, 0, 10, 10]\nrooms:\n  - {name: "cafe\\u0301", box: '
                                     '[0, 0, 5, 10]}\nplaces:\n  - {name: "pe\\u0301tanque_1", class: table, '
                                     'at: [2, 2]}\npeople:\n  - {name: "Zoe\\u0308", at: [1, 1]}\n')
    m = load_map(tmp_path / "m.yaml")
    assert [r.name for r in m.rooms] == ["caf\u00e9"]
    assert [p.name for p in m.places] == ["p\u00e9tanque_1"] and [p.name for p in m.people] == ["Zo\u00eb"]


def test_a_map_listing_more_than_the_bound_is_refused_at_the_first_past_it(tmp_path: Path,
                                                                           monkeypatch: pytest.MonkeyPatch) -> None:
    """40,000 rooms took over a minute to validate, 100,000 places two minutes to run (hostile26): a list of rooms,
    places, objects or people longer than :data:`MAX_LISTED` is refused at its first item past the bound."""
    import seal_cli.maps.formats.map_server as server

    monkeypatch.setattr(server, "MAX_LISTED", 2)
    rooms = "".join(f"  - {{name: r{i}, box: [{i}, 0, {i + 1}, 1]}}\n" for i in range(3))
    assert (6, "this map lists more than 2 rooms") in [(line, message[:32]) for line, message in
                                                        _problems(tmp_path, f"rooms:\n{rooms}")]


@pytest.mark.parametrize(("data", "says"), [
    (b"P5\n2 2\n255\n\x00\x01\x02\x03GARBAGE", r"7 bytes after its 2×2 pixels, neither whitespace nor another image"),
    (b"P5\n2 2\n255\n\x00\x01\x02\x03\x04\x05\x06\x07", r"4 bytes after .*\(as many again as its pixels: is it a "
                                                        r"16-bit image"),
    (b"P5\n1 1\n65535\n\x00\x01\x00", r"1 bytes after its 1×1 pixels"),
    (b"P2\n2 1\n255\n1 2 3\n", r"1 values after its 2×1 pixels"),
])
def test_what_a_pgm_holds_after_its_pixels_is_refused(data: bytes, says: str) -> None:
    """hostile30: it was passed over, so a header whose size was wrong still made a map."""
    with pytest.raises(SealError, match=says):
        read_pgm(data)


@pytest.mark.parametrize("after", [b"\n", b" \r\n\t\n", b"P5\n1 1\n255\n\x07", b"\nP2\n1 1\n255\n7\n"])
def test_whitespace_or_another_image_after_a_p5s_pixels_is_read(after: bytes) -> None:
    """A line end an editor added; netpbm's several images in one file (the first is the map's)."""
    assert read_pgm(b"P5\n2 1\n255\n\x00\xfe" + after).tolist() == [[0.0, 254.0]]


@pytest.mark.parametrize(("line", "key"), [("resolution: abc", "resolution"), ("origin: {x: 1}", "origin"),
                                           ("resolution: 0.05", "resolution")])
def test_image_keys_without_an_image_are_refused(tmp_path: Path, line: str, key: str) -> None:
    """hostile30: resolution and origin were passed over unread without an image ("resolution: abc" was ok)."""
    from seal_cli.maps.formats.map_server import check_map_file

    path = tmp_path / "m.yaml"
    path.write_text(f"name: m\nbounds: [0, 0, 10, 10]\nrooms:\n  - {{name: hall, box: [0, 0, 10, 10]}}\n{line}\n")
    found = [(p.line, p.message) for p in check_map_file(path)]
    assert found and found[0][0] == 5 and found[0][1].startswith(f"{key} only means something with an image")


def test_a_rooms_preposition_is_read_and_a_bad_one_refused_at_its_column(tmp_path: Path) -> None:
    from seal_cli.maps.prepositions import located

    path = tmp_path / "x.yaml"
    path.write_text("name: a\nbounds: [0, 0, 10, 10]\nrooms:\n"
                    "  - {name: sun_trap, box: [0, 0, 5, 5], preposition: on}\n"
                    "  - {name: balcony, box: [5, 0, 10, 5]}\n")
    m = load_map(path)
    assert [r.preposition for r in m.rooms] == ["on", None]
    assert (located("sun_trap", m), located("balcony", m)) == ("on the sun trap", "on the balcony")
    said = _problems(tmp_path, "rooms:\n  - {name: hall, box: [0, 0, 5, 5], preposition: under}\n")
    assert said == [(4, "room hall: preposition must be one of in, on, at, not 'under'")]
    path.write_text("name: a\nbounds: [0, 0, 10, 10]\nrooms:\n  - {name: hall, box: [0, 0, 5, 5], preposition: [on]}\n")
    with pytest.raises(SealError) as caught:
        load_map(path)
    assert "preposition must be one of in, on, at, not a list" in str(caught.value)
    assert (caught.value.line, caught.value.column) == (4, 50)      # at the list


def test_an_image_that_is_a_link_to_nothing_or_a_loop_says_so(tmp_path: Path) -> None:
    """Both were "image map.pgm does not exist (looked for map.pgm)", of a file that is there (hostile31)."""
    from seal_cli.maps.formats.map_server import read_image_cells

    (tmp_path / "dangling.pgm").symlink_to("gone.pgm")
    (tmp_path / "a.pgm").symlink_to("b.pgm")
    (tmp_path / "b.pgm").symlink_to("a.pgm")
    with pytest.raises(SealError, match=r"dangling\.pgm is a symbolic link to gone\.pgm, which does not exist"):
        read_image_cells(tmp_path / "dangling.pgm")
    with pytest.raises(SealError, match=r"a\.pgm is a loop of symbolic links"):
        read_image_cells(tmp_path / "a.pgm")
    with pytest.raises(SealError, match=r"image none\.pgm does not exist"):
        read_image_cells(tmp_path / "none.pgm")


def test_priors_of_more_classes_than_the_bound_are_refused(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    """rel33: 100,000 prior classes ran ``seal localize`` past 300 s and 6 GB; refused at the first class past
    ``MAX_PRIOR_CLASSES`` (3 here), at its line and column."""
    import seal_cli.maps.formats.map_server as map_server

    monkeypatch.setattr(map_server, "MAX_PRIOR_CLASSES", 3)
    path = tmp_path / "m.yaml"
    path.write_text("name: m\nbounds: [0, 0, 10, 10]\nrooms: [{name: kitchen, box: [0, 0, 10, 10]}]\npriors:\n"
                    + "".join(f"  c{i}: {{kitchen: 1}}\n" for i in range(5)), encoding="utf-8")
    with pytest.raises(SealError, match=r"m\.yaml:8:3: this map's priors name more than 3 classes"):
        load_map(path)
    path.write_text(path.read_text(encoding="utf-8").replace("  c3: {kitchen: 1}\n  c4: {kitchen: 1}\n", ""),
                    encoding="utf-8")
    assert len(load_map(path).priors) == 3
