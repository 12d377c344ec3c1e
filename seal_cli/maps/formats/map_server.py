"""Map files: a ROS map_server YAML plus seal's semantic keys, read with the position of every value.

::

    image: apartment.pgm        # optional; the map_server keys keep their ROS meaning
    resolution: 0.05
    origin: [-10.0, -7.0, 0.0]  # pose of the lower-left pixel (yaw radians)
    negate: 0
    occupied_thresh: 0.65
    free_thresh: 0.196
    mode: trinary               # optional: trinary (default), scale or raw
    name: apartment
    bounds: [-9, -6, 9, 6]      # xmin, ymin, xmax, ymax; default: the image's extent
    rooms: [{name: kitchen, polygon: [[x, y], ...]}, {name: bedroom, box: [xmin, ymin, xmax, ymax]},
            {name: sun_trap, box: [...], preposition: on}]   # optional: in, on or at (default: English's)
    places: [{name: fridge_1, class: fridge, at: [x, y], openable: true, open: false, reach: 1.0}]
    priors: {cup: {family_room: 0.5, bedroom: 0.5}}
    objects: [{class: cup, at: [x, y], in: fridge_1}]   # ``at`` defaults to the place's position
    robot: {pose: [x, y, yaw], holding: null}
    sensor: {range: 5.0, fov: 360, p_detect: 0.9, sigma: 0.3, noise: 0.05}

The image is read exactly as ROS map_server reads it: image row 0 is the highest y; for each
pixel the colour channels are averaged, ``negate`` flips the value, ``p = (255 − value) / 255``
is the occupancy probability, and the cell is occupied if ``p > occupied_thresh``, free if
``p < free_thresh``, unknown otherwise (``mode: scale`` reads the same; ``mode: raw`` takes the
value as an occupancy percentage, 255 unknown). PGM (P5 binary and P2 text, 8 or 16 bits; other
maximum values are scaled to 255) is read with numpy alone; PNG through matplotlib.

One deliberate difference, for PNG only: ROS 1's map_server averages an alpha channel *into*
the grey value in trinary mode, which turns unknown grey (205) into free space on an opaque RGBA
PNG. seal does what ROS 2's nav2_map_server does: it averages the colour channels only, and a
fully transparent pixel is unknown. Reading never raises anything but SealError.
"""

from __future__ import annotations

import contextlib
import functools
import math
import os
import re
from collections.abc import Callable, Iterator
from dataclasses import dataclass, replace
from pathlib import Path
from typing import Any, TypeVar

import numpy as np
import yaml
from numpy.typing import NDArray

from seal_cli.errors import SealError, SealErrors, Where
from seal_cli.fileio import MAX_IMAGE_BYTES, compose_yaml, composed, read_bytes, read_text, shown_path
from seal_cli.frames.taxonomy import check_class_name, class_key
from seal_cli.maps.geometry import (
    FREE,
    MAX_GRID_CELLS,
    MAX_IMAGE_CELLS,
    OCCUPIED,
    UNKNOWN,
    OccupancyGrid,
    coarsened,
    fit_cells,
    shrink_factor,
)
from seal_cli.maps.model import (
    FOV_RANGE,
    MAX_LISTED,
    MAX_PRIOR_CLASSES,
    Map,
    MapWarning,
    ObjectTruth,
    Person,
    Place,
    Robot,
    Room,
    Sensor,
    fov_ok,
)
from seal_cli.maps.prepositions import ROOM_PREPOSITIONS
from seal_cli.names import check_name_length, check_sayable, check_shown
from seal_cli.resources import map_path
from seal_cli.yamlnodes import NodeReader
from seal_cli.yamlnodes import is_null as _is_null
from seal_cli.yamlnodes import shape as _shape

__all__ = ["KEYS", "MAX_IMAGE_PIXELS", "ImageCells", "check_map_file", "load_map", "read_image", "read_image_cells",
           "read_map", "read_pgm"]

MAP_SERVER_KEYS = ("image", "resolution", "origin", "negate", "occupied_thresh", "free_thresh", "mode")
SEMANTIC_KEYS = ("name", "bounds", "rooms", "places", "priors", "objects", "robot", "sensor", "people", "speaker")
KEYS = MAP_SERVER_KEYS + ("occupancy",) + SEMANTIC_KEYS  # occupancy: a grid from a bag (formats/occupancy_bag)
ROOM_KEYS = ("name", "polygon", "box", "preposition")
PLACE_KEYS = ("name", "class", "at", "openable", "open", "reach")
OBJECT_KEYS = ("class", "at", "in")
ROBOT_KEYS = ("pose", "holding")
PERSON_KEYS = ("name", "at", "room", "role")
SPEAKER_KEYS = ("at", "role")
SENSOR_KEYS = ("range", "fov", "p_detect", "sigma", "noise")
MAX_METRES = 1000.0
"""The largest sensor range and place reach a map may give: beyond it squared distances overflow
(1e200 m) or the search's lattices cannot be built, and no robot acts a kilometre away."""
MAX_COORDINATE = 1e7
"""The largest coordinate (and angle) a map may give, in metres: 10,000 km takes in UTM's northings; a
point at 1e300 m overflows the geometry's products and no map is that large."""
MODES = ("trinary", "scale", "raw")
MIN_RESOLUTION = 1e-3
"""The finest resolution of a map image, in metres per pixel: a millimetre, finer than any robot's range sensor; a
resolution of 1e-300 gave a map of no area, and 1e300 a traceback (hostile19)."""

T = TypeVar("T")
Path_ = tuple[str | int, ...]


# -- images ---------------------------------------------------------------------------------------
MAX_IMAGE_PIXELS = 16_384 * 16_384
"""The most pixels a binary PGM (P5) map image may have, checked from its header: 256 MiB at 8 bits, the file
bound. Such an image is read a band of rows at a time, cropped to what it knows and, if still larger than
:data:`~seal_cli.maps.geometry.MAX_GRID_CELLS`, coarsened to fit: a real ROS map (8,000 × 8,000 at 5 cm, most
of it unknown) is read in a few hundred megabytes, never as floats."""

BAND = 4 * 2**20
"""Pixels classified at a time when a large image is read (bounded temporaries)."""


MAX_HEADER_DIGITS = 12
"""The most digits a number of a PGM header may have (a width of 10**12 pixels is already no image seal reads)."""

P2_TOKEN = re.compile(rb"[^\s0-9]")
"""What a text PGM's pixels may not hold: netpbm's values are whole numbers from 0 to the maximum, written in
ASCII digits (a sign, a decimal point, ``nan`` or ``1e3`` is no pixel value)."""


def _pgm_header(data: bytes) -> tuple[int, int, int, int]:
    """Width, height, maximum value and where the pixels start, of a PGM (P5 or P2)."""
    if data[:2] not in (b"P5", b"P2"):
        raise SealError(f"not a PGM image (it starts with {data[:2]!r}, not P5 or P2)")
    fields: list[int] = []
    pos = 2
    while len(fields) < 3:
        while pos < len(data) and data[pos:pos + 1].isspace():
            pos += 1
        if pos < len(data) and data[pos:pos + 1] == b"#":
            end = data.find(b"\n", pos)
            pos = len(data) if end < 0 else end + 1
            continue
        start = pos
        while pos < len(data) and data[pos:pos + 1].isdigit():
            pos += 1
        if start == pos:
            raise SealError("PGM header is cut short or malformed (expected width, height and maximum value)")
        if pos - start > MAX_HEADER_DIGITS:  # int() of 4,300 digits and more raises, and no image is that large
            raise SealError(f"PGM header's {('width', 'height', 'maximum value')[len(fields)]} has {pos - start:,} "
                            f"digits ({data[start:start + 12].decode()}…): no image is that large")
        fields.append(int(data[start:pos]))
    width, height, maxval = fields
    if width <= 0 or height <= 0 or not 0 < maxval < 65536:
        raise SealError(f"PGM header has impossible values: width {width}, height {height}, maximum {maxval}")
    return width, height, maxval, pos


def _p5_levels(data: bytes, width: int, height: int, maxval: int, pos: int) -> NDArray[Any]:
    """The raw levels of a binary PGM, ``height`` × ``width`` (row 0 the top row), a view of ``data``."""
    pos += 1  # exactly one whitespace byte separates the header from the pixels
    dtype = np.dtype(">u2") if maxval > 255 else np.dtype(np.uint8)
    need = width * height * dtype.itemsize
    if len(data) - pos < need:
        raise SealError(f"PGM image is truncated: {width}×{height} pixels need {need} bytes, "
                        f"the file has {max(len(data) - pos, 0)}")
    _check_after(data[pos + need:], f"{width}×{height} pixels", need)
    levels = np.frombuffer(data, dtype=dtype, count=width * height, offset=pos).reshape(height, width)
    top = max((int(levels[r:r + max(1, BAND // width)].max()) for r in range(0, height, max(1, BAND // width))),
              default=0)
    if top > maxval:
        raise SealError(f"PGM pixel value {top} exceeds the maximum {maxval} in its header")
    return levels


NEXT_IMAGE = re.compile(rb"\s*P[1-7]\s")
"""The start of another netpbm image: netpbm writes several images one after another in one file."""


def _check_after(rest: bytes, pixels: str, need: int) -> None:
    """Refuse what a PGM holds after its pixels unless it is whitespace (a line end an editor added) or another
    netpbm image (of which the first is the map's, as netpbm reads such a file; hostile30: any bytes after the pixels
    were passed over, so a header whose size was wrong still made a map)."""
    if not rest or rest.isspace() or NEXT_IMAGE.match(rest):
        return
    same = (" (as many again as its pixels: is it a 16-bit image? Its header's maximum must then be above 255)"
            if len(rest) == need else "")
    raise SealError(f"PGM image has {len(rest):,} bytes after its {pixels}, neither whitespace nor another image: "
                    f"its header's width, height or maximum is likely wrong{same}")


def read_pgm(data: bytes) -> NDArray[np.float64]:
    """A PGM image (P5 or P2) as grey values scaled to 0..255, row 0 the top row of the picture."""
    width, height, maxval, pos = _pgm_header(data)
    _check_cells(width, height)
    count = width * height
    if data[:2] == b"P5":
        pixels = _p5_levels(data, width, height, maxval, pos).astype(float).ravel()
    else:
        bad = P2_TOKEN.search(data, pos)
        if bad is not None:
            start = max(data.rfind(space, pos, bad.start()) for space in (b" ", b"\n", b"\t", b"\r")) + 1
            token = data[start:].split(maxsplit=1)[0][:12].decode("ascii", "backslashreplace")
            raise SealError(f"PGM (P2) pixel values must be whole numbers from 0 to {maxval} in ASCII digits, "
                            f"not {token!r} (byte {start + 1:,} of the file)")
        tokens = data[pos:].split()
        if len(tokens) < count:
            raise SealError(f"PGM image is truncated: {width}×{height} pixels, only {len(tokens)} values")
        if len(tokens) > count:
            raise SealError(f"PGM image has {len(tokens) - count:,} values after its {width}×{height} pixels: its "
                            "header's width or height is likely wrong")
        if max(map(len, tokens), default=0) > MAX_HEADER_DIGITS:  # beyond any maximum (and int() of 4,300 raises)
            longest = max(tokens, key=len)
            raise SealError(f"PGM pixel value {longest[:12].decode()}… ({len(longest):,} digits) exceeds the "
                            f"maximum {maxval} in its header")
        pixels = np.array(tokens, dtype=np.int64).astype(float)
        if pixels.max(initial=0) > maxval:
            raise SealError(f"PGM pixel value {int(pixels.max())} exceeds the maximum {maxval} in its header")
    return (pixels * (255.0 / maxval)).reshape(height, width)


def _check_cells(width: int, height: int, advice: str = "save it as a binary PGM (P5), which seal reads up to "
                 f"{MAX_IMAGE_PIXELS:,} pixels, cropping and coarsening it to fit") -> None:
    """Refuse an image of more than :data:`MAX_IMAGE_CELLS` pixels before its pixels are read."""
    if width * height > MAX_IMAGE_CELLS:
        raise SealError(f"the image is {width:,}×{height:,} pixels ({width * height:,} cells); seal reads such "
                        f"images (PNG, text PGM) of at most {MAX_IMAGE_CELLS:,} cells (4096×4096): {advice}")


def _png_cells(path: Path, negate: bool, occupied_thresh: float, free_thresh: float, mode: str) -> NDArray[np.int8]:
    """The cells of a PNG (grey: colour channels averaged, 0..255; a transparent pixel unknown), through matplotlib,
    classified a band of rows at a time: the decoded image stays in matplotlib's float32 (a 4096 × 4096 RGBA image,
    75 KB on disk, took 1.6 GB as float64 arrays)."""
    import matplotlib.image

    try:
        image = matplotlib.image.imread(str(path))
    except Exception as exc:  # matplotlib/Pillow raise many kinds; all mean "cannot read"
        raise SealError(f"cannot read image {path.name}: {exc}") from None
    unit = image.max(initial=0) <= 1.0
    cells = np.empty(image.shape[:2], dtype=np.int8)
    rows = max(1, BAND // max(1, image.shape[1] * (image.shape[2] if image.ndim == 3 else 1)))
    for r in range(0, image.shape[0], rows):
        band = np.asarray(image[r:r + rows], dtype=float)
        if unit:
            band = np.round(band * 255.0)
        if band.ndim == 2:
            cells[r:r + rows] = _classify(band, negate, occupied_thresh, free_thresh, mode)
            continue
        channels = band.shape[2]
        has_alpha = channels in (2, 4)
        part = _classify(band[..., :channels - 1 if has_alpha else channels].mean(axis=2), negate, occupied_thresh,
                         free_thresh, mode)
        if has_alpha:
            part[band[..., -1] < 1.0] = UNKNOWN  # a transparent pixel says nothing
        cells[r:r + rows] = part
    return cells


def _classify(grey: NDArray[np.float64], negate: bool, occupied_thresh: float, free_thresh: float,
              mode: str) -> NDArray[np.int8]:
    """Cells (FREE / OCCUPIED / UNKNOWN) of grey values 0..255, as ROS map_server reads them."""
    if negate:
        grey = 255.0 - grey
    cells = np.full(grey.shape, UNKNOWN, dtype=np.int8)
    if mode == "raw":
        value = np.round(grey)
        cells[value / 100.0 > occupied_thresh] = OCCUPIED
        cells[value / 100.0 < free_thresh] = FREE
        cells[value > 100] = UNKNOWN
    else:
        occ = (255.0 - grey) / 255.0
        cells[occ > occupied_thresh] = OCCUPIED
        cells[occ < free_thresh] = FREE
    return cells


@dataclass(frozen=True)
class ImageCells:
    """A map image's cells (row 0 at the lowest y), and how they sit in the image: ``offset`` (column, row from
    the bottom, in pixels) of their lower-left corner and the ``factor`` of pixels per cell along a side."""

    cells: NDArray[np.int8]
    offset: tuple[int, int] = (0, 0)
    factor: int = 1
    size: tuple[int, int] = (0, 0)
    """The whole image's width and height, in pixels."""

    def grid(self, resolution: float, origin: tuple[float, float, float]) -> OccupancyGrid:
        """The occupancy grid: the origin moved to the cells' corner, the resolution times the factor."""
        return OccupancyGrid.placed(self.cells, resolution, origin, self.offset, self.factor)


def _large_p5(levels: NDArray[Any], table: NDArray[np.int8]) -> ImageCells:
    """The cells of a P5 image larger than :data:`MAX_GRID_CELLS`, a band of rows at a time: cropped to the
    rows and columns holding a known cell, then coarsened if still too large."""
    height, width = levels.shape
    rows = max(1, BAND // width)
    known_rows = np.zeros(height, dtype=bool)
    known_cols = np.zeros(width, dtype=bool)
    for r in range(0, height, rows):
        known = table[levels[r:r + rows]] != UNKNOWN
        known_rows[r:r + rows] = known.any(axis=1)
        known_cols |= known.any(axis=0)
    if known_rows.any():
        top, bottom = int(np.argmax(known_rows)), height - int(np.argmax(known_rows[::-1]))
        left, right = int(np.argmax(known_cols)), width - int(np.argmax(known_cols[::-1]))
    else:
        top, bottom, left, right = 0, height, 0, width
    window = levels[top:bottom, left:right][::-1]  # row 0 at the lowest y
    factor = shrink_factor(window.shape[0], window.shape[1], MAX_GRID_CELLS)
    step = rows - rows % factor or factor
    parts = [coarsened(table[window[r:r + step]], factor) for r in range(0, window.shape[0], step)]
    return ImageCells(np.ascontiguousarray(np.concatenate(parts)), (left, height - bottom), factor, (width, height))


def _missing_image(path: Path) -> str:
    """Why an image that does not exist is missing: a link to nothing, or a loop of links, was "does not exist
    (looked for map.pgm)", of a file there is (hostile31)."""
    import errno

    if not path.is_symlink():
        return f"image {shown_path(path.name)} does not exist (looked for {shown_path(path)})"
    try:
        path.stat()
    except OSError as exc:
        if exc.errno == errno.ELOOP:
            return f"image {shown_path(path)} is a loop of symbolic links (each links to another of them): link it " \
                   "to the image file"
    return f"image {shown_path(path)} is a symbolic link to {shown_path(os.readlink(path))}, which does not exist"


def read_image_cells(path: Path, negate: bool = False, occupied_thresh: float = 0.65, free_thresh: float = 0.196,
                     mode: str = "trinary") -> ImageCells:
    """The cells of a map_server image (:class:`ImageCells`); an image of more than :data:`MAX_GRID_CELLS` pixels
    comes cropped to what it knows and coarsened to fit (a binary PGM a band of rows at a time; a PNG or a text
    PGM, decoded whole, only up to :data:`MAX_IMAGE_CELLS` pixels)."""
    if not path.exists():
        raise SealError(_missing_image(path))
    data = read_bytes(path, MAX_IMAGE_BYTES, "map image")
    if data[:2] == b"P5":
        width, height, maxval, pos = _pgm_header(data)
        if width * height > MAX_IMAGE_PIXELS:
            raise SealError(f"the image is {width:,}×{height:,} pixels ({width * height:,}); seal reads binary PGM "
                            f"images of at most {MAX_IMAGE_PIXELS:,} pixels (16384×16384): crop it to the building")
        levels = _p5_levels(data, width, height, maxval, pos)
        span = 65536 if maxval > 255 else 256
        table = _classify(np.arange(span, dtype=np.float64) * (255.0 / maxval), negate, occupied_thresh, free_thresh,
                          mode)
        if width * height > MAX_GRID_CELLS:
            return _large_p5(levels, table)
        return ImageCells(np.ascontiguousarray(table[levels][::-1]), size=(width, height))
    if data[:2] == b"P2":
        cells = _classify(read_pgm(data), negate, occupied_thresh, free_thresh, mode)
    elif data[:8] == b"\x89PNG\r\n\x1a\n":
        if data[12:16] == b"IHDR":  # the size, before a decoder unpacks a small file into gigabytes
            _check_cells(int.from_bytes(data[16:20], "big"), int.from_bytes(data[20:24], "big"))
        cells = _png_cells(path, negate, occupied_thresh, free_thresh, mode)
    else:
        raise SealError(f"image {path.name} is neither PGM (P5/P2) nor PNG")
    kept, corner, factor = fit_cells(cells[::-1].copy(), MAX_GRID_CELLS)
    return ImageCells(kept, corner, factor, size=(cells.shape[1], cells.shape[0]))


def read_image(path: Path, negate: bool = False, occupied_thresh: float = 0.65, free_thresh: float = 0.196,
               mode: str = "trinary") -> NDArray[np.int8]:
    """Cells (FREE / OCCUPIED / UNKNOWN) of a map_server image, row 0 at the lowest y (flipped); a large binary
    PGM's cropped and coarsened (see :func:`read_image_cells`)."""
    return read_image_cells(path, negate, occupied_thresh, free_thresh, mode).cells


# -- the YAML reader --------------------------------------------------------------------------------
class _Reader(NodeReader):
    """Turns a composed YAML map into a Map, collecting every problem with its position."""

    def __init__(self, text: str, path: Path) -> None:
        super().__init__(text, str(path))
        self.path = path
        self.positions: dict[Path_, Where] = {}
        self.broken: set[str] = set()
        self._construct = yaml.constructor.SafeConstructor()

    # -- values -------------------------------------------------------------------------------
    def value(self, node: yaml.Node) -> Any:
        try:
            return self._construct.construct_object(node, deep=True)
        except yaml.YAMLError as exc:
            self.problem(f"cannot read this value: {getattr(exc, 'problem', None) or exc}", node)
            return None

    def number(self, node: yaml.Node, what: str, ok: Callable[[float], bool] = math.isfinite,
               need: str = "a number") -> float | None:
        known = len(self.problems)
        value = self.value(node) if isinstance(node, yaml.ScalarNode) else None
        if len(self.problems) > known:  # it could not be read at all: said once
            return None
        if isinstance(value, str) and not getattr(node, "style", "x"):  # YAML 1.1: plain 1e-9 is a string
            with contextlib.suppress(ValueError):
                value = float(value)
        if isinstance(value, int) and not isinstance(value, bool) and abs(value) > 1e300:
            value = math.inf  # too large for a float: math.isfinite would raise OverflowError
        if isinstance(value, bool) or not isinstance(value, int | float) or not math.isfinite(value) \
                or not ok(float(value)):
            self.problem(f"{what} must be {need}, not {_shape(node)}", node)
            return None
        return float(value)

    def numbers(self, node: yaml.Node, what: str, counts: tuple[int, ...]) -> list[float] | None:
        shape = " or ".join(f"{n}" for n in counts)
        if not isinstance(node, yaml.SequenceNode):
            self.problem(f"{what} must be a list of {shape} numbers, not {_shape(node)}", node)
            return None
        if len(node.value) not in counts:
            self.problem(f"{what} must have {shape} numbers, not {len(node.value)}", node)
            return None
        values = [self.number(item, f"each number of {what}", lambda v: abs(v) <= MAX_COORDINATE,
                              f"a number of metres from {-MAX_COORDINATE:,.0f} to {MAX_COORDINATE:,.0f}")
                  for item in node.value]
        return None if any(v is None for v in values) else values  # type: ignore[return-value]

    def xy(self, node: yaml.Node, what: str) -> tuple[float, float] | None:
        values = self.numbers(node, what, (2,))
        return (values[0], values[1]) if values else None

    def name(self, node: yaml.Node, what: str) -> str | None:
        """A room's, place's or person's name, composed (NFC) as a command is: a YAML escape ("cafe\\u0301") can
        still spell it decomposed after the file's text was composed, and "go to the café" missed it."""
        text = self.string(node, what)
        return composed(text) if text else text

    def boolean(self, node: yaml.Node, what: str) -> bool | None:
        value = self.value(node) if isinstance(node, yaml.ScalarNode) else None
        if isinstance(value, bool) or value in (0, 1):
            return bool(value)
        shown = repr(node.value) if isinstance(node, yaml.ScalarNode) else _shape(node)     # not a list's nodes
        self.problem(f"{what} must be true or false, not {shown}", node)
        return None

    def pairs_at(self, node: yaml.Node, what: str, path: Path_, allowed: tuple[str, ...] | None = None
                 ) -> Iterator[tuple[str, yaml.Node, yaml.Node]]:
        """:meth:`NodeReader.pairs` (nothing is an empty mapping), recording each key's position under
        ``path + (key,)`` for the map's own checks."""
        for key, key_node, value_node in self.pairs(node, what, allowed, empty=True):
            self.positions[path + (key,)] = self.where(key_node)
            yield key, key_node, value_node

    def renumber(self, kind: str, kept: list[int]) -> None:
        """Positions of the items of ``kind`` (rooms, places, ...) under their index in the map: an item
        that could not be built is left out of it, so the items after it move up (the map's own checks
        would put a problem of the room after a broken one at the broken one's line)."""
        index = {old: new for new, old in enumerate(kept)}
        moved: dict[Path_, Where] = {}
        for path in [p for p in self.positions if len(p) > 1 and p[0] == kind and isinstance(p[1], int)]:
            where = self.positions.pop(path)
            if path[1] in index:
                moved[(kind, index[path[1]], *path[2:])] = where
        self.positions.update(moved)

    # -- the document ----------------------------------------------------------------------------
    def read(self, root: yaml.Node) -> Map | None:
        if not isinstance(root, yaml.MappingNode):
            self.problem(f"a map file must be a mapping of keys (image, rooms, ...), not {_shape(root)}", root)
            return None
        fields: dict[str, Any] = {}
        nodes: dict[str, yaml.Node] = {}
        for key, _, value in self.pairs_at(root, "a map file", (), KEYS):
            nodes[key] = value
        server = self.map_server(nodes, root)
        name = self.string(nodes["name"], "name") if "name" in nodes else None
        if name is not None:
            name = self.build(functools.partial(_map_name, name), nodes["name"])
        fields["name"] = name or _default_name(self.path)
        if "bounds" in nodes:
            fields["bounds"] = self.bounds(nodes["bounds"])
        if "rooms" in nodes:
            fields["rooms"] = self.rooms(nodes["rooms"])
        places = self.places(nodes["places"]) if "places" in nodes else ()
        fields["places"] = places
        if "priors" in nodes:
            fields["priors"] = self.priors(nodes["priors"])
        if "objects" in nodes:
            fields["objects"] = self.objects(nodes["objects"], places)
        if "robot" in nodes:
            fields["robot"] = self.robot(nodes["robot"])
        if "sensor" in nodes:
            fields["sensor"] = self.sensor(nodes["sensor"])
        if "people" in nodes:
            fields["people"] = self.people(nodes["people"])
        if "speaker" in nodes:
            fields["speaker"], fields["speaker_roles"] = self.speaker(nodes["speaker"])
        if server is not None:
            fields["grid"] = server
            if "bounds" not in nodes:
                fields["bounds"] = server.bounds  # the image's extent: it never grows to take in a stray place
        elif "bounds" not in nodes and "image" not in nodes and "occupancy" not in nodes:
            self.problem("a map needs bounds: [xmin, ymin, xmax, ymax] or an occupancy image", root)
            return None
        if fields.get("bounds", "") is None or (("image" in nodes or "occupancy" in nodes) and server is None):
            return None  # the bounds or the image are broken, already reported: nothing to check against
        try:
            built = Map(file=self.file, positions=self.positions, check=False,
                        **{k: v for k, v in fields.items() if v is not None})
        except SealError as exc:
            for problem in getattr(exc, "problems", None) or [exc]:
                self.problems.append(problem)
            return None
        found = built.problems(self.broken)
        self.problems.extend(found)
        return built.noting(p for p in self.problems if isinstance(p, MapWarning))  # the reader's own too

    def map_server(self, nodes: dict[str, yaml.Node], root: yaml.Node) -> OccupancyGrid | None:
        if "occupancy" in nodes:
            from seal_cli.maps.formats.occupancy_bag import grid_from_bag

            return grid_from_bag(self, nodes)
        if "image" not in nodes:  # resolution and origin too: passed over unread, "resolution: abc" was ok (hostile30)
            for key in MAP_SERVER_KEYS[1:]:
                if key in nodes:
                    self.problem(f"{key} only means something with an image; add image: or remove {key}"
                                 + (" (a map of bounds alone gets cells of its own size)" if key == "resolution"
                                    else ""), nodes[key])
            return None
        image = self.string(nodes["image"], "image")
        missing = [k for k in ("resolution", "origin") if k not in nodes]
        if missing:
            self.problem(f"a map with an image needs {' and '.join(missing)} (map_server keys)", nodes["image"])
        resolution = self.number(nodes["resolution"], "resolution", lambda v: v >= MIN_RESOLUTION,
                                 f"a number of metres per pixel of at least {MIN_RESOLUTION:g} (a millimetre, finer "
                                 "than any robot's range sensor)") if "resolution" in nodes else None
        origin = self.numbers(nodes["origin"], "origin", (2, 3)) if "origin" in nodes else None
        negate = self.boolean(nodes["negate"], "negate") if "negate" in nodes else False
        occ = self.number(nodes["occupied_thresh"], "occupied_thresh", lambda v: 0 <= v <= 1,
                          "a probability in [0, 1]") if "occupied_thresh" in nodes else 0.65
        free = self.number(nodes["free_thresh"], "free_thresh", lambda v: 0 <= v <= 1,
                           "a probability in [0, 1]") if "free_thresh" in nodes else 0.196
        mode = self.string(nodes["mode"], "mode") if "mode" in nodes else "trinary"
        if mode is not None and mode not in MODES:
            self.problem(f"mode must be one of {', '.join(MODES)}, not {mode!r}", nodes["mode"])
            mode = None
        if occ is not None and free is not None and free > occ:
            self.problem(f"free_thresh {free:g} is above occupied_thresh {occ:g}", nodes["free_thresh"])
            return None
        if None in (image, resolution, origin, negate, occ, free, mode):
            return None
        assert image is not None and resolution is not None and origin is not None and mode is not None
        try:
            read = read_image_cells(self.path.parent / image, bool(negate), float(occ or 0), float(free or 0), mode)
        except SealError as exc:
            self.problem(exc.message, nodes["image"])
            return None
        width, height = read.size
        corner = [origin[0] + width * resolution, origin[1] + height * resolution]
        if max(abs(c) for c in corner) > MAX_COORDINATE:
            self.problem(f"resolution {resolution:g} m of an image of {width:,}×{height:,} pixels from origin "
                         f"[{origin[0]:g}, {origin[1]:g}] reaches [{corner[0]:g}, {corner[1]:g}] m; a map's "
                         f"coordinates are at most {MAX_COORDINATE:,.0f} m (is the resolution in metres per pixel?)",
                         nodes["resolution"])
            return None
        if read.factor > 1:
            rows, cols = read.cells.shape
            self.problems.append(MapWarning(
                f"the image is {width:,}×{height:,} pixels; its known part is more than {MAX_GRID_CELLS:,} cells "
                f"(1024×1024), so seal merges {read.factor}×{read.factor} pixels into one cell: {cols:,}×{rows:,} "
                f"cells of {resolution * read.factor:g} m (a wall anywhere in a cell keeps it occupied); crop the "
                "image to the building to keep every pixel", self.where(nodes["image"])))
        return read.grid(resolution, tuple(origin + [0.0] * (3 - len(origin))))  # type: ignore[arg-type]

    def bounds(self, node: yaml.Node) -> tuple[float, ...] | None:
        values = self.numbers(node, "bounds", (4,))
        if values is None:
            return None
        if not (values[0] < values[2] and values[1] < values[3]):
            self.problem(f"bounds must be [xmin, ymin, xmax, ymax] with xmin < xmax and ymin < ymax, not "
                         f"{[float(v) for v in values]}", node)
            return None
        return tuple(values)

    def rooms(self, node: yaml.Node) -> tuple[Room, ...]:
        rooms, kept = [], []
        for i, item in enumerate(self.listed(node, "rooms")):
            self.positions[("rooms", i)] = self.where(item)
            fields = {key: value for key, _, value in self.pairs_at(item, "a room", ("rooms", i), ROOM_KEYS)}
            if not isinstance(item, yaml.MappingNode):
                continue
            name = self.name(fields["name"], "a room's name") if "name" in fields else None
            if "name" not in fields:
                self.problem("a room needs a name", item)
            if name and self.build(functools.partial(_checked_name, name, "room name"), fields["name"]) is None:
                self.broken.add(name)  # said once, at its name: priors naming it are not said again
                continue
            shapes = [k for k in ("polygon", "box") if k in fields]
            misspelt = any(isinstance(k, yaml.ScalarNode) and k.value not in ROOM_KEYS for k, _ in item.value)
            if len(shapes) != 1 and not (misspelt and not shapes):
                self.problem("a room needs exactly one of polygon: [[x, y], ...] or box: [xmin, ymin, xmax, ymax]"
                             + (" (it has both)" if len(shapes) == 2 else ""), item)
            said = self.room_preposition(name, fields["preposition"]) if "preposition" in fields else None
            room = self.room_shape(name, fields, shapes[0]) if name and len(shapes) == 1 else None
            if room is not None and said:
                room = replace(room, preposition=said)
            if room is not None:
                rooms.append(room)
                kept.append(i)
            elif name:
                self.broken.add(name)
        self.renumber("rooms", kept)
        return tuple(rooms)

    def room_preposition(self, name: str | None, node: yaml.Node) -> str | None:
        """A room's ``preposition:`` (in, on or at), or None said as a problem at it."""
        plain = ("tag:yaml.org,2002:str", "tag:yaml.org,2002:bool")      # YAML 1.1 reads a plain "on" as true
        if isinstance(node, yaml.ScalarNode) and node.tag in plain and node.value in ROOM_PREPOSITIONS:
            return str(node.value)
        shown = repr(node.value) if isinstance(node, yaml.ScalarNode) else _shape(node)
        self.problem(f"room {name or '?'}: preposition must be one of {', '.join(ROOM_PREPOSITIONS)}, not {shown}",
                     node)
        return None

    def room_shape(self, name: str, fields: dict[str, yaml.Node], shape: str) -> Room | None:
        node = fields[shape]
        where = self.where(node)
        if shape == "box":
            values = self.numbers(node, f"room {name}: box", (4,))
            if values is None:
                return None
            xmin, ymin, xmax, ymax = values
            return self.build(functools.partial(Room.box, name, xmin, ymin, xmax, ymax, where), node)
        if not isinstance(node, yaml.SequenceNode):
            self.problem(f"room {name}: polygon must be a list of [x, y] points, not {_shape(node)}", node)
            return None
        points = [self.xy(p, f"each point of room {name}'s polygon") for p in node.value]
        if any(p is None for p in points):
            return None
        if len(points) > 1 and points[0] == points[-1]:
            points = points[:-1]
        repeated = [i for i in range(len(points)) if points[i] == points[i - 1]] if len(points) > 1 else []
        if repeated:
            self.problem(f"room {name}: polygon repeats the point {list(points[repeated[0]])} "  # type: ignore[arg-type]
                         "twice in a row", node.value[repeated[0]])
            return None
        return self.build(lambda: Room(name, tuple(points), where), node)  # type: ignore[arg-type]

    def listed(self, node: yaml.Node, what: str) -> list[yaml.Node]:
        """The items of the map's list ``what`` (rooms, places, ...), at most :data:`MAX_LISTED`: a longer list is a
        problem at its first item past the bound, and only those before it are read (hostile26)."""
        items = self.items(node, what)
        if len(items) > MAX_LISTED:
            self.problem(f"this map lists more than {MAX_LISTED:,} {what}; seal reads at most that many (a building "
                         f"has tens or hundreds): split the map, or merge {what} of one kind", items[MAX_LISTED])
            return items[:MAX_LISTED]
        return items

    def places(self, node: yaml.Node) -> tuple[Place, ...]:
        places, kept = [], []
        for i, item in enumerate(self.listed(node, "places")):
            self.positions[("places", i)] = self.where(item)
            fields = {key: value for key, _, value in self.pairs_at(item, "a place", ("places", i), PLACE_KEYS)}
            if not isinstance(item, yaml.MappingNode):
                continue
            missing = [k for k in ("name", "class", "at") if k not in fields]
            if missing:
                self.problem(f"a place needs {', '.join(missing)}", item)
            name = self.name(fields["name"], "a place's name") if "name" in fields else None
            cls = self.string(fields["class"], "a place's class") if "class" in fields else None
            at = self.xy(fields["at"], f"place {name}: at") if "at" in fields else None
            openable = self.boolean(fields["openable"], "openable") if "openable" in fields else False
            is_open = self.boolean(fields["open"], "open") if "open" in fields else None
            reach = self.number(fields["reach"], "reach", lambda v: 0 < v <= MAX_METRES,
                                f"a positive number of metres, at most {MAX_METRES:g}") \
                if "reach" in fields else 1.0
            bad = (openable is None or reach is None or ("open" in fields and is_open is None))
            place = None
            if name and cls and at and not bad:
                place = self.build(functools.partial(Place, name, cls, at, bool(openable), is_open, None,
                                                     float(reach or 1.0), self.where(item)), item)
            if place is not None:
                places.append(place)
                kept.append(i)
            elif name:
                self.broken.add(name)
                if cls:
                    self.broken.add(cls)
        self.renumber("places", kept)
        return tuple(places)

    def priors(self, node: yaml.Node) -> dict[str, dict[str, float]]:
        priors: dict[str, dict[str, float]] = {}
        first: dict[str, str] = {}
        for cls, key_node, value in self.pairs_at(node, "priors", ("priors_raw",)):
            if len(first) == MAX_PRIOR_CLASSES:   # rel33: 100,000 classes ran localize past 300 s and 6 GB
                self.problem(f"this map's priors name more than {MAX_PRIOR_CLASSES:,} classes; seal reads at most that "
                             "many (a building's things are of tens or hundreds of classes, and each is a belief of "
                             "its own): keep the classes the tasks need, or merge kinds into one class", key_node)
                break
            try:  # a class a place or an object could not have ("cu\0p" validated, hostile28)
                key = check_class_name(cls, "the prior's class", self.where(key_node))
            except SealError as problem:
                self.problem(problem.message, key_node)
                continue
            if key in first:
                self.problem(f"priors name the class {cls!r} twice (as {first[key]!r} too)", key_node)
                continue
            first[key] = cls
            self.positions[("priors", key)] = self.where(key_node)
            masses: dict[str, float] = {}
            if _is_null(value):  # "cup:" with nothing after it: a prior left unwritten, not "anywhere"
                self.problem(f"the prior of {cls} is empty; give a mass per room, place or place class "
                             f"({cls}: {{kitchen: 0.5}}), or {{}} for anywhere in the free space", value)
                continue
            for target, target_node, mass_node in self.pairs(value, f"the prior of {cls}"):
                self.positions[("priors_raw", cls, target)] = self.where(target_node)
                self.positions[("priors", key, target)] = self.where(target_node)
                mass = self.number(mass_node, f"the mass of {target} in the prior of {cls}")
                if mass is not None:
                    masses[target] = mass
            priors[key] = masses
        return priors

    def objects(self, node: yaml.Node, places: tuple[Place, ...]) -> tuple[ObjectTruth, ...]:
        by_name = {class_key(p.name): p for p in places}
        objects, kept = [], []
        for i, item in enumerate(self.listed(node, "objects")):
            self.positions[("objects", i)] = self.where(item)
            fields = {key: value for key, _, value in self.pairs_at(item, "an object", ("objects", i), OBJECT_KEYS)}
            if not isinstance(item, yaml.MappingNode):
                continue
            if "class" not in fields:
                self.problem("an object needs a class", item)
            cls = self.string(fields["class"], "an object's class") if "class" in fields else None
            inside = self.string(fields["in"], "in") if "in" in fields else None
            if "at" in fields:
                at = self.xy(fields["at"], f"object {cls}: at")
            elif inside is not None and class_key(inside) in by_name:
                at = by_name[class_key(inside)].at
            else:
                if inside is None or class_key(inside) not in self.broken:
                    self.problem(f"object {cls or ''} needs at: [x, y]"
                                 + (f" (or in: a place of this map; {inside!r} is none)" if inside else ""), item)
                at = None
            if cls and at and ("in" not in fields or inside):
                built = self.build(functools.partial(ObjectTruth, cls, at, inside, self.where(item)), item)
                if built is not None:
                    objects.append(built)
                    kept.append(i)
        self.renumber("objects", kept)
        return tuple(objects)

    def robot(self, node: yaml.Node) -> Robot | None:
        fields = {key: value for key, _, value in self.pairs_at(node, "robot", ("robot",), ROBOT_KEYS)}
        pose = self.numbers(fields["pose"], "robot pose", (2, 3)) if "pose" in fields else []
        holding = None
        if "holding" in fields and not _is_null(fields["holding"]):
            holding = self.string(fields["holding"], "holding")
        if pose is None or not isinstance(node, yaml.MappingNode):
            return None
        return self.build(lambda: Robot(tuple(pose) or None, holding, self.where(node)),  # type: ignore[arg-type]
                          node)

    def people(self, node: yaml.Node) -> tuple[Person, ...]:
        people, kept = [], []
        for i, item in enumerate(self.listed(node, "people")):
            self.positions[("people", i)] = self.where(item)
            fields = {key: value for key, _, value in self.pairs_at(item, "a person", ("people", i), PERSON_KEYS)}
            if not isinstance(item, yaml.MappingNode):
                continue
            if "name" not in fields:
                self.problem("a person needs a name", item)
                continue
            name = self.name(fields["name"], "a person's name")
            if name and self.build(functools.partial(_checked_name, name, "person name"), fields["name"]) is None:
                continue    # said at its name, not at the person's first key
            at = self.xy(fields["at"], f"person {name}: at") if "at" in fields else None
            room = self.string(fields["room"], f"person {name}: room") if "room" in fields else None
            roles = self.roles(fields["role"], f"person {name}: role") if "role" in fields else ()
            if name and ("at" not in fields or at) and ("room" not in fields or room):
                built = self.build(functools.partial(Person, name, at, room, self.where(item), roles or ()), item)
                if built is not None:
                    people.append(built)
                    kept.append(i)
        self.renumber("people", kept)
        return tuple(people)

    def speaker(self, node: yaml.Node) -> tuple[tuple[float, float] | None, tuple[str, ...]]:
        """Where the speaker stands (None: where the robot starts) and the roles they are called by."""
        fields = {key: value for key, _, value in self.pairs_at(node, "speaker", ("speaker",), SPEAKER_KEYS)}
        if not isinstance(node, yaml.MappingNode):
            return None, ()
        roles = (self.roles(fields["role"], "speaker: role") or ()) if "role" in fields else ()
        if "at" not in fields:
            if not roles:
                self.problem("speaker needs at: [x, y] (or a role: without it, the speaker stands where the "
                             "robot starts)", node)
            return None, roles
        return self.xy(fields["at"], "speaker: at"), roles

    def roles(self, node: yaml.Node, what: str) -> tuple[str, ...] | None:
        """A role, or a list of roles: each a noun (``nurse``, ``head nurse``); None when it is not."""
        items = self.items(node, what, single=True) if isinstance(node, yaml.SequenceNode | yaml.ScalarNode) \
            else None
        if items is None or not items:
            self.problem(f"{what} must be a noun or a list of nouns, not {_shape(node)}", node)
            return None
        roles = []
        for item in items:
            value = self.value(item) if isinstance(item, yaml.ScalarNode) else None
            if not isinstance(value, str) or not class_key(value) or not re.fullmatch(r"[^\W\d_][\w '-]*", value):
                shown = repr(item.value) if isinstance(item, yaml.ScalarNode) else _shape(item)
                self.problem(f"{what} must be a noun or a list of nouns, not {shown}", item)
                return None
            roles.append(value)
        return tuple(roles)

    def sensor(self, node: yaml.Node) -> Sensor | None:
        fields = {key: value for key, _, value in self.pairs_at(node, "sensor", ("sensor",), SENSOR_KEYS)}
        checks: dict[str, tuple[Callable[[float], bool], str]] = {
            "range": (lambda v: 0 < v <= MAX_METRES, f"a positive number of metres, at most {MAX_METRES:g}"),
            "fov": (fov_ok, FOV_RANGE),
            "p_detect": (lambda v: 0 <= v <= 1, "a probability in [0, 1]"),
            "sigma": (lambda v: v > 0, "a positive number of metres"),
            "noise": (lambda v: v >= 0, "a number of metres, 0 or more")}
        values: dict[str, float | None] = {key: self.number(value, f"sensor {key}", *checks[key])
                                           for key, value in fields.items()}
        if any(v is None for v in values.values()) or not isinstance(node, yaml.MappingNode):
            return None
        args = {("fov_deg" if k == "fov" else k): v for k, v in values.items()}
        return self.build(lambda: Sensor(**args, where=self.where(node)), node)  # type: ignore[arg-type]


def _checked_name(name: str, what: str) -> str:
    """A room's or a person's name, checked where it is written (its length, then whether a command can say it):
    a problem of the name is said at the name, not at the room's box or the person's first key."""
    return check_sayable(check_name_length(name, what), what)


def _map_name(name: str) -> str:
    """A map's own name, checked: not too long to show whole, nothing in it a terminal or a picture cannot show."""
    return check_shown(check_name_length(name, "map name"), "map name")


def _default_name(path: Path) -> str:
    """A map's name when it has no ``name:``: the file's stem, or its folder's name for ``map.yaml``."""
    stem = path.stem
    return path.resolve().parent.name if stem == "map" and path.resolve().parent.name else stem


# -- entry points -------------------------------------------------------------------------------------
def read_map(path: str | Path) -> tuple[Map | None, list[SealError]]:
    """The map in a file (None if it cannot be built) and every problem found, sorted by position.

    Problems that are :class:`~seal_cli.maps.model.MapWarning` do not stop the map from being used."""
    path = Path(path)
    try:
        text = read_text(path)
        root = compose_yaml(text, str(path))
    except SealError as exc:
        return None, [exc]
    if root is None:
        return None, [SealError("the map file is empty", Where(str(path)))]
    reader = _Reader(text, path)
    built = reader.read(root)
    problems = sorted(reader.problems, key=lambda p: (p.line or 0, p.column or 0))
    for problem in problems:
        if problem.source_line is None and problem.line and problem.line <= len(reader.lines):
            problem.source_line = reader.lines[problem.line - 1]
    return built, problems


def load_map(path: str | Path) -> Map:
    """The map in a file — or shipped with seal, by name (``"apartment"``, see
    :func:`seal_cli.resources.map_path`) — or SealError(s) listing every problem with its file, line
    and column. A file of that name, when there is one, comes first.

    A map whose only problems are warnings (:class:`~seal_cli.maps.model.MapWarning`) loads, with them in
    ``Map.warnings``."""
    built, problems = read_map(map_path(str(path)))
    fatal = [p for p in problems if not isinstance(p, MapWarning)]
    if fatal or built is None:
        raise fatal[0] if len(fatal) == 1 else SealErrors(fatal or problems)
    return built


def check_map_file(path: str | Path) -> list[SealError]:
    """Every problem of a map file, warnings included (what ``seal validate`` reports); empty when the
    map is good."""
    return read_map(path)[1]
