"""An attacker's hostile inputs of ``seal bench reliability`` (round hostile13): kinds none of the issue's, the
hand-written, the reviewer's, the new user's, the outsider's or the generated cases held.

- integers of 5,000 digits wherever a number goes (Python refuses to convert more than 4,300 digits: a
  ``ValueError`` traceback from PyYAML's constructor in maps, priors, observations, trajectories, frame files);
- YAML tags for other types (``!!binary``, ``!!set``, ``!!timestamp``), keys that are lists or mappings, flow
  nesting 100,000 deep on one line;
- sensor and prior numbers outside their sense (a detection probability of 1.5, a negative prior mass, a prior
  whose masses sum to zero), degenerate rooms (collinear, one point, zero width, inverted boxes);
- occupancy images: missing, a JPEG, an empty or numeric ``image:``, a header comment of a megabyte, a real
  map's size (6,000 × 6,000 cells, mostly unknown: read by rows, cropped to what is known), a P2 text image of
  that size;
- the frame DSL: a fact nested 10,000 deep, a category of 100,000 members on one line, 20,000 broken frames,
  category cycles, NUL and bidi characters in names, CRLF with an error on a known line;
- command texts of punctuation, emoji, right-to-left scripts, zero-width and homoglyph letters only;
- outputs onto an input reached through a folder link or ``/proc/self/cwd``, onto ``--vocabulary``, onto
  ``/dev/full``; folders and empty files where a vocabulary, observations or a trajectory go;
- sizes: a vocabulary of 300,000 words, a map of 2,000 km at 1 cm, a resolution of a micrometre.
"""

from __future__ import annotations

import math
from collections.abc import Iterator

import numpy as np

from seal_cli.bench.reliability import FRAME, FRAME_YAML, Case, hostile_setting
from seal_cli.bench.reliability_inputs import alfred2d_data, robot_map
from seal_cli.bench.reliability_inputs import sample_bag as _sample_bag
from seal_cli.bench.reliability_outsider import ALFRED_ROW

__all__ = ["alfred2d_data", "attacker_cases", "chain_library", "hostile14_cases", "hostile15_cases", "hostile16_cases",
           "hostile17_cases", "hostile18_cases", "hostile19_cases", "hostile20_cases", "hostile21_cases",
           "hostile22_cases", "hostile23_cases", "hostile24_cases", "hostile25_cases", "hostile26_cases",
           "hostile27_cases", "hostile28_cases", "hostile29_bag_cases", "hostile29_cases",
           "hostile29_environment_cases", "hostile30_cases", "hostile30_leftover_cases", "hostile30_output_cases",
           "rgba_png", "robot_map",
           "sparse_pgm", "split_house"]

DIGITS = "1" * 5_000
"""An integer longer than Python converts from text (4,300 digits)."""


def sparse_pgm(width: int, height: int, patch: bytes, patch_width: int, patch_height: int) -> bytes:
    """A binary PGM of ``width`` × ``height`` unknown (205) pixels with the P5 ``patch`` in its lower-left
    corner: a real ROS map's shape (a building in a large unknown sheet)."""
    rows = bytearray(b"\xcd" * (width * height))
    for r in range(patch_height):
        start = (height - patch_height + r) * width
        rows[start:start + patch_width] = patch[r * patch_width:(r + 1) * patch_width]
    return f"P5\n{width} {height}\n255\n".encode() + bytes(rows)


def rgba_png(side: int) -> bytes:
    """A ``side`` × ``side`` RGBA PNG, white and opaque but for a black wall down the middle: small on disk, large
    once decoded."""
    import struct
    import zlib

    def chunk(kind: bytes, body: bytes) -> bytes:
        return struct.pack(">I", len(body)) + kind + body + struct.pack(">I", zlib.crc32(kind + body))

    row = bytearray(b"\xff" * (4 * side))
    row[4 * (side // 2):4 * (side // 2) + 3] = b"\x00\x00\x00"
    packer = zlib.compressobj(9)
    pixels = b"".join(packer.compress(b"\x00" + bytes(row)) for _ in range(side)) + packer.flush()
    header = struct.pack(">IIBBBBB", side, side, 8, 6, 0, 0, 0)
    return b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", header) + chunk(b"IDAT", pixels) + chunk(b"IEND", b"")


def _pgm_pixels(data: bytes) -> tuple[bytes, int, int]:
    """The pixels, width and height of an 8-bit P5 whose header has at most one comment line."""
    lines = data.split(b"\n", 4)
    if lines[1].startswith(b"#"):
        lines = [lines[0], *data.split(b"\n", 4)[2:]]
        lines = [*lines[:3], b"\n".join(lines[3:])]
    width, height = lines[1].split()
    assert lines[0] == b"P5" and lines[2] == b"255", "the apartment's image changed: update the attacker's cases"
    return lines[3], int(width), int(height)


def attacker_cases() -> Iterator[Case]:  # noqa: PLR0915 - one list of cases, read top to bottom
    """The cases, each with the shape of its message (``says``)."""
    m, image, text, both, inputs, loc, frame = hostile_setting()
    located = r"{}:\d+:\d+:"

    def replaced(old: str, new: str) -> bytes:
        assert old in text, f"the apartment changed: update the attacker's case for {old!r}"
        return text.replace(old, new).encode()

    # -- integers of 5,000 digits ------------------------------------------------------------------------
    spots = {"resolution": ("resolution: 0.05", f"resolution: {DIGITS}", ("validate", "h.yaml")),
             "a prior's mass": ("cup: {family_room: 0.5", f"cup: {{family_room: {DIGITS}", ("validate", "h.yaml")),
             "the origin": ("origin: [-10.0, -7.0, 0.0]", f"origin: [-{DIGITS}, -7.0, 0.0]",
                            ("run", "go to the kitchen", "--map", "h.yaml")),
             "the robot's pose": ("pose: [-6.0, -3.0, 0.0]", f"pose: [-6.0, {DIGITS}, 0.0]",
                                  ("localize", "--map", "h.yaml", "--steps", "1", "--particles", "20")),
             "the sensor's range": ("range: 5.0", f"range: {DIGITS}", ("map", "h.yaml")),
             "the bounds": ("bounds: [-9.0, -6.0, 9.0, 6.0]", f"bounds: [-9.0, -6.0, {DIGITS}, 6.0]",
                            ("validate", "h.yaml"))}
    for label, (old, new, argv) in spots.items():
        yield Case(f"A 5,000 digits in {label}: {argv[0]}", argv, (("h.yaml", replaced(old, new)), image),
                   codes=(1,), keep=("h.yaml", "apartment.pgm"), says=located.format(r"h\.yaml"))
    yield Case("A 5,000 digits in an observation's pose", (*loc, "--observations", "o.yaml"),
               (*both, ("o.yaml", f"- pose: [{DIGITS}, -3.0]\n  detections: []\n".encode())), codes=(1,),
               keep=("o.yaml", *inputs), says=r"o\.yaml:1:\d+:")
    yield Case("A 5,000 digits in a detection", (*loc, "--observations", "o.yaml"),
               (*both, ("o.yaml", f"- pose: [-6, -3]\n  detections: [{{class: cup, at: [1, {DIGITS}]}}]\n"
                        .encode())), codes=(1,), keep=("o.yaml", *inputs), says=r"o\.yaml:2:\d+:")
    yield Case("A 5,000 digits in a trajectory", (*loc, "--trajectory", "t.yaml"),
               (*both, ("t.yaml", f"poses:\n  - [-6.0, {DIGITS}]\n".encode())), codes=(1,),
               keep=("t.yaml", *inputs), says=r"t\.yaml:2:\d+:")
    yield Case("A 5,000 digits as a frame YAML lexical unit", ("validate", "f.yaml"),
               (("f.yaml", f"frames:\n  - frame: Whisk\n    lexical_units: [{DIGITS}]\n".encode()),), codes=(1,),
               keep=("f.yaml",), says=r"f\.yaml:3:\d+:")
    yield Case("A 5,000 digits in a vocabulary", ("parse", "--vocabulary", "v.yaml", "stir the cup"),
               (("v.yaml", f"- cup\n- {DIGITS}\n".encode()),), codes=(1,), keep=("v.yaml",), says=r"v\.yaml:2:\d+:")
    yield Case("A 5,000 digits in the sensor's field of view", ("validate", "h.yaml"),
               (("h.yaml", replaced("fov: 360", f"fov: {DIGITS}")), image), codes=(1,), keep=("h.yaml",),
               says=located.format(r"h\.yaml"))
    # -- YAML tags and keys of other types ---------------------------------------------------------------
    tagged = {"!!binary resolution": ("resolution: 0.05", "resolution: !!binary aGVsbG8="),
              "!!set prior": ("cup: {family_room: 0.5, bedroom: 0.5}", "cup: !!set {family_room, bedroom}"),
              "!!timestamp origin": ("origin: [-10.0, -7.0, 0.0]", "origin: [2001-12-14, -7.0, 0.0]"),
              "a list as a room's key": ("- {name: bedroom, box:", "- {[name]: bedroom, box:"),
              "a mapping as a prior's key": ("cup: {family_room: 0.5", "{a: 1}: {family_room: 0.5")}
    for label, (old, new) in tagged.items():
        yield Case(f"A map with {label}", ("validate", "h.yaml"), (("h.yaml", replaced(old, new)), image),
                   codes=(1,), keep=("h.yaml",), says=located.format(r"h\.yaml"))
    yield Case("A a vocabulary keyed by a list", ("parse", "--vocabulary", "v.yaml", "stir the cup"),
               (("v.yaml", b"? [cup, mug]\n: x\n"),), codes=(1,), keep=("v.yaml",), says=r"v\.yaml")
    yield Case("A an observation keyed by a mapping", (*loc, "--observations", "o.yaml"),
               (*both, ("o.yaml", b"- {pose: [-6, -3], {a: 1}: 2}\n")), codes=(1,), keep=("o.yaml", *inputs),
               says=r"o\.yaml:1:\d+:")
    flow = ("[" * 100_000 + "]" * 100_000 + "\n").encode()
    for kind, argv in (("map", ("validate", "x.yaml")), ("observations", (*loc, "--observations", "x.yaml")),
                       ("frame YAML", ("plan", "--framelib", "x.yaml", "stir the cup"))):
        yield Case(f"A {kind} nested 100,000 deep on one line", argv, (*both, ("x.yaml", flow)), codes=(1,),
                   keep=("x.yaml", *inputs), says=r"x\.yaml(:\d+:\d+)?:")
    # -- numbers outside their sense ----------------------------------------------------------------------
    senseless = {"a detection probability of 1.5": ("fov: 360", "fov: 360, p_detect: 1.5"),
                 "a detection probability below 0": ("fov: 360", "fov: 360, p_detect: -0.1"),
                 "a negative noise": ("fov: 360", "fov: 360, noise: -1"),
                 "a sensor sigma of 0": ("fov: 360", "fov: 360, sigma: 0"),
                 "a sensor range of 0": ("range: 5.0", "range: 0"),
                 "a negative prior mass": ("cup: {family_room: 0.5, bedroom: 0.5}",
                                           "cup: {family_room: -0.5, bedroom: 0.5}"),
                 "a prior whose masses sum to 0": ("cup: {family_room: 0.5, bedroom: 0.5}",
                                                   "cup: {family_room: 0.5, bedroom: -0.5}")}
    for label, (old, new) in senseless.items():
        yield Case(f"A map with {label}: run", ("run", "bring me a cup", "--map", "h.yaml", "--particles", "20"),
                   (("h.yaml", replaced(old, new)), image), codes=(1,), keep=("h.yaml",),
                   says=located.format(r"h\.yaml"))
    # -- degenerate rooms --------------------------------------------------------------------------------
    head = "name: a\nbounds: [0, 0, 10, 10]\nrooms:\n  - {name: kitchen, box: [5, 0, 10, 10]}\n"
    rooms = {"collinear": "  - {name: den, polygon: [[0, 0], [1, 1], [2, 2]]}\n",
             "one point thrice": "  - {name: den, polygon: [[1, 1], [1, 1], [1, 1]]}\n",
             "of zero width": "  - {name: den, box: [1, 1, 1, 5]}\n",
             "inverted": "  - {name: den, box: [4, 4, 1, 1]}\n",
             "touching itself at a vertex": "  - {name: den, polygon: [[0, 0], [2, 2], [4, 0], [2, 2], [0, 4]]}\n"}
    for label, row in rooms.items():
        yield Case(f"A a room {label}", ("validate", "x.yaml"), (("x.yaml", (head + row).encode()),), codes=(1,),
                   keep=("x.yaml",), says=r"x\.yaml:5:\d+:")
    circle = ", ".join(f"[{5 + 2 * math.cos(k / 1e4):.6f}, {5 + 2 * math.sin(k / 1e4):.6f}]" for k in range(62_831))
    ringed = head.replace("[5, 0, 10, 10]", "[8, 0, 10, 2]") + f"  - {{name: den, polygon: [{circle}]}}\n"
    yield Case("A a room of 62,831 vertices", ("validate", "x.yaml"), (("x.yaml", ringed.encode()),), codes=(1,),
               keep=("x.yaml",), says=r"x\.yaml:5:\d+:.*62,831")
    fine = ", ".join(f"[{5 + 2 * math.cos(k * math.tau / 9_000):.6f}, {5 + 2 * math.sin(k * math.tau / 9_000):.6f}]"
                     for k in range(9_000))
    outlined = head.replace("[5, 0, 10, 10]", "[8, 0, 10, 2]") + f"  - {{name: den, polygon: [{fine}]}}\n"
    yield Case("A a room of 9,000 vertices: run", ("run", "go to the den", "--map", "x.yaml", "--particles", "20"),
               (("x.yaml", outlined.encode()),), codes=(0,), keep=("x.yaml",))
    yield Case("A a room named with 20,000 letters: the message cuts the name", ("validate", "h.yaml"),
               (("h.yaml", replaced("name: bedroom", "name: b" + "e" * 20_000 + "droom")), image), codes=(1,),
               keep=("h.yaml",), says=r"\A(?![\s\S]*[^\n]{3001})[\s\S]*h\.yaml:\d+:\d+: .*beee+…")
    objects = "".join(f"  - {{class: cup, at: [{-8.5 + (k % 100) * 0.05:.2f}, {-5.5 + (k // 100) * 0.005:.3f}]}}\n"
                      for k in range(50_000))
    yield Case("A 50,000 objects in the apartment", ("validate", "h.yaml"),
               (("h.yaml", replaced("objects:\n", "objects:\n" + objects)), image), codes=(0, 1), keep=("h.yaml",),
               says=r"h\.yaml")
    # -- occupancy images --------------------------------------------------------------------------------
    images = {"missing": ("image: apartment.pgm", "image: nowhere.pgm", ()),
              "a JPEG": ("image: apartment.pgm", "image: photo.pgm", (("photo.pgm", b"\xff\xd8\xff\xe0" + bytes(64)),)),
              "empty": ("image: apartment.pgm", "image: ''", ()),
              "a number": ("image: apartment.pgm", "image: 5", ()),
              "a list": ("image: apartment.pgm", "image: [a.pgm]", ())}
    for label, (old, new, extra) in images.items():
        yield Case(f"A map image {label}", ("map", "h.yaml"), (("h.yaml", replaced(old, new)), image, *extra),
                   codes=(1,), keep=("h.yaml",), says=located.format(r"h\.yaml"))
    pixels, width, height = _pgm_pixels(image[1])
    commented = f"P5\n# {'x' * 1_000_000}\n{width} {height}\n255\n".encode() + pixels
    yield Case("A map image with a header comment of 1 MB", ("map", "m.yaml"), (m, ("apartment.pgm", commented)),
               codes=(0,), keep=inputs)
    big = sparse_pgm(6_000, 6_000, pixels, width, height)
    yield Case("A a real map's image: 6,000 × 6,000, mostly unknown (validate)", ("validate", "m.yaml"),
               (m, ("apartment.pgm", big)), codes=(0,), keep=inputs, timeout=120)
    yield Case("A a real map's image: 6,000 × 6,000, mostly unknown (run)", ("run", "go to the kitchen", "--map",
                                                                           "m.yaml", "--particles", "50"),
               (m, ("apartment.pgm", big)), codes=(0,), keep=inputs, timeout=180)
    yield Case("A a P2 text image of 6,000 × 6,000", ("validate", "m.yaml"),
               (m, ("apartment.pgm", b"P2\n6000 6000\n255\n" + b"205 " * 100_000)), codes=(1,), keep=inputs,
               says=r"m\.yaml:\d+:\d+: .*(P5|binary)")
    # -- the frame DSL -----------------------------------------------------------------------------------
    dsl = {"a fact nested 10,000 deep": ("requires holding(instrument)",
                                         "requires holding(" + "f(" * 10_000 + "x" + ")" * 10_001, (1,), 8),
           "a category of 100,000 members on one line": ("category container = cup, bowl",
                                                         "category container = cup, bowl, "
                                                         + ", ".join(f"c{k}" for k in range(100_000)), (0, 1), 1),
           "a NUL inside a frame's name": ("frame Whisk", "frame Wh\x00isk", (1,), 4),
           "a right-to-left override in a frame's name": ("frame Whisk", "frame Wh\u202eisk", (0, 1), 4)}
    for label, (old, new, codes, line) in dsl.items():
        data = frame.decode().replace(old, new).encode()
        yield Case(f"A DSL: {label}", ("validate", "f.frame"), (("f.frame", data),), codes=codes, keep=("f.frame",),
                   says=rf"f\.frame:{line}:\d+:" if codes == (1,) else r"f\.frame")
    broken = "".join(f"frame F{k} {{\n  do navigate(\n}}\n" for k in range(20_000)).encode()
    yield Case("A DSL: 20,000 broken frames", ("validate", "f.frame"), (("f.frame", broken),), codes=(1,),
               keep=("f.frame",), says=r"f\.frame:\d+:\d+:")
    cycle = b"category a = b\ncategory b = a\nframe Go \"go\" {\n  theme: a\n  do navigate(theme)\n}\n"
    yield Case("A DSL: two categories of each other", ("validate", "f.frame"), (("f.frame", cycle),), codes=(1,),
               keep=("f.frame",), says=r"f\.frame:\d+:\d+:")
    crlf = frame.decode().replace("do navigate(theme), stir", "do navigate(theme) stir").replace("\n", "\r\n")
    yield Case("A DSL: CRLF lines and a missing comma on line 9", ("validate", "f.frame"),
               (("f.frame", crlf.encode()),), codes=(1,), keep=("f.frame",), says=r"f\.frame:9:26:")
    # -- command texts -----------------------------------------------------------------------------------
    texts = {"only punctuation": "?!.,;:…—", "only emoji": "😀🤖🍕", "Arabic, right to left": "اذهب إلى المطبخ",
             "Hebrew with bidi marks": "\u200fלך למטבח\u200f", "zero-width spaces in a word": "st\u200bir the cup",
             "a Cyrillic homoglyph": "st\u0456r the cup", "100,000 exclamation marks": "!" * 100_000,
             "only whitespace": " \t \u3000 "}
    for label, command in texts.items():
        for verb in ("parse", "plan"):
            yield Case(f"A a command of {label}: {verb}", (verb, command), codes=(0, 1), says=r"column \d+|error")
    yield Case("A run a command of only emoji", ("run", "😀🤖🍕", "--map", "m.yaml", "--particles", "20"), both,
               codes=(1,), keep=inputs, says=r"column \d+")
    # -- outputs onto inputs, by other roads --------------------------------------------------------------
    plain = (("mapfile", m[1]), image)
    yield Case("A --png onto the map through a folder link", ("map", "mapfile", "--png", "d/mapfile"),
               (*plain, ("d", "link:.")), codes=(1,), keep=("mapfile", "apartment.pgm"), says=r"d/mapfile")
    yield Case("A --rrd onto the map through /proc/self/cwd", ("localize", "--map", "mapfile", "--steps", "1",
                                                               "--particles", "20", "--rrd", "/proc/self/cwd/mapfile"),
               plain, codes=(1,), keep=("mapfile", "apartment.pgm"), says=r"/proc/self/cwd/mapfile")
    yield Case("A run --png onto its --vocabulary", ("run", "bring me a cup", "--map", "m.yaml", "--particles", "20",
                                                     "--vocabulary", "vocab", "--png", "vocab"),
               (*both, ("vocab", b"- cup\n- spoon\n")), codes=(1,), keep=(*inputs, "vocab"), says=r"vocab")
    yield Case("A run --rrd /dev/full", ("run", "go to the kitchen", "--map", "m.yaml", "--particles", "20", "--rrd",
                                         "/dev/full"), both, codes=(1,), keep=inputs, says=r"--rrd /dev/full")
    yield Case("A plan --pddl /dev/full", ("plan", "--pddl", "/dev/full", "stir the cup"), codes=(1,),
               says=r"--pddl")
    yield Case("A bench tasks --episodes /dev/full", ("bench", "tasks", "--suite", "map", "--layouts", "1",
                                                      "--policies", "sefm", "--command", "go to the kitchen",
                                                      "--particles", "50", "--episodes", "/dev/full"),
               codes=(1,), says=r"--episodes")
    # -- empty names and overlong values for options ------------------------------------------------------
    empties = {"plan --pddl ''": ("plan", "--pddl", "", "stir the cup"),
               "plan --pddl=": ("plan", "--pddl=", "stir the cup"),
               "map --png ''": ("map", "m.yaml", "--png", ""),
               "localize --goals ''": (*loc, "--task", "stir the cup", "--goals", ""),
               "parse --vocabulary ''": ("parse", "--vocabulary", "", "stir the cup"), "validate ''": ("validate", "")}
    for label, argv in empties.items():
        yield Case(f"A an empty name: {label}", argv, both, codes=(1,), keep=inputs,
                   absent=("domain.pddl", "problem.pddl"), says=r"(--[a-z]+ is empty|an empty PATH)")
    yield Case("A --holding of 3,000 letters: run", ("run", "bring me a cup", "--map", "m.yaml", "--particles", "20",
                                                      "--holding", "x" * 3_000), both, codes=(1,), keep=inputs,
               says=r"holding 'x+'… is 3,000 characters long")
    yield Case("A --holding of 100,000 letters: plan", ("plan", "--holding", "y" * 100_000, "stir the cup"),
               codes=(1,), says=r"holding 'y+'… is 100,000 characters long")
    # -- folders and empty files where files go ------------------------------------------------------------
    for option, argv in (("--vocabulary", ("parse", "--vocabulary", "x", "stir the cup")),
                         ("--observations", (*loc, "--observations", "x")),
                         ("--trajectory", (*loc, "--trajectory", "x"))):
        yield Case(f"A {option} a folder", argv, (*both, ("x", "dir")), codes=(1,), keep=inputs,
                   says=r"x: this is a folder")
        yield Case(f"A {option} an empty file", argv, (*both, ("x", b"")), codes=(0, 1), keep=inputs,
                   says=r"(?m)^(error: )?x")
    yield Case("A a map of comments only", ("map", "x.yaml"), (("x.yaml", b"# nothing\n# here\n"),), codes=(1,),
               keep=("x.yaml",), says=r"x\.yaml")
    # -- sizes -------------------------------------------------------------------------------------------
    words = "".join(f"- w{k}\n" for k in range(300_000)).encode()
    yield Case("A a vocabulary of 300,000 words", ("parse", "--vocabulary", "v.yaml", "stir the cup"),
               (("v.yaml", words),), codes=(1,), keep=("v.yaml",), says=r"v\.yaml:\d+:\d+: .*300,000|v\.yaml:.*most",
               timeout=20)
    yield Case("A a map of 2,000 km at 1 cm", ("validate", "x.yaml"),
               (("x.yaml", b"name: a\nresolution: 0.01\nbounds: [-1000000, -1000000, 1000000, 1000000]\n"
                 b"rooms:\n  - {name: hall, box: [0, 0, 10, 10]}\n"),), codes=(0, 1), keep=("x.yaml",),
               says=r"x\.yaml")
    yield Case("A a map of 10 m at a micrometre, no image: run",
               ("run", "go to the hall", "--map", "x.yaml", "--particles", "20"),
               (("x.yaml", b"name: a\nresolution: 0.000001\nbounds: [0, 0, 10, 10]\n"
                 b"rooms:\n  - {name: hall, box: [0, 0, 10, 10]}\n"),), codes=(0, 1), keep=("x.yaml",),
               says=r"x\.yaml")
    yield from hostile14_cases()
    yield from hostile15_cases()
    yield from hostile16_cases()
    yield from hostile17_cases()
    yield from hostile18_cases()
    yield from hostile19_cases()
    yield from hostile20_cases()
    yield from hostile21_cases()
    yield from hostile22_cases()
    yield from hostile23_cases()
    yield from hostile24_cases()
    yield from hostile25_cases()
    yield from hostile26_cases()
    yield from hostile27_cases()
    yield from hostile28_cases()
    yield from hostile29_cases()
    yield from hostile29_bag_cases()
    yield from hostile29_environment_cases()
    yield from hostile30_leftover_cases()
    yield from hostile30_cases()
    yield from hostile30_output_cases()
    from seal_cli.bench.reliability_hostile31 import hostile31_cases, hostile31_leftover_cases

    yield from hostile31_leftover_cases()
    yield from hostile31_cases()
    from seal_cli.bench.reliability_hostile32 import hostile32_cases

    yield from hostile32_cases()
    from seal_cli.bench.reliability_hostile33 import hostile33_cases

    yield from hostile33_cases()


def hostile14_cases() -> Iterator[Case]:
    """Round hostile14: usage errors that echoed a value whole, grids and searches that grew past a gigabyte, and a
    map name too long for the file system reported at seal's own folder."""
    _, _, _, both, inputs, _, _ = hostile_setting()
    cut = r"\A(?=[\s\S]*{})[\s\S]{{1,4000}}\Z"  # what is named, in a message of 4,000 characters at most
    usage = {"an integer of 5,000 digits for --seed": (("localize", "--seed", "1" * 5_000), "--seed"),
             "an integer of 5,000 digits for --jobs": (("bench", "tasks", "--jobs", "9" * 5_000), "--jobs"),
             "a command of 100,000 letters": (("x" * 100_000,), "No such command"),
             "a bench command of 100,000 letters": (("bench", "y" * 100_000), "No such command"),
             "an extra argument of 100,000 letters": (("plan", "stir", "b" * 100_000), "unexpected extra"),
             "an option of 10,000 letters": (("run", "--bogus" + "z" * 10_000), "No such option"),
             "30,000 extra words": (("plan", *["w"] * 30_000), "unexpected extra")}
    for label, (argv, named) in usage.items():
        yield Case(f"A usage error cut: {label}", argv, codes=(2,), says=cut.format(named))
    yield Case("A a map name of 5,000 letters: the argument, not seal's folder", ("run", "go", "--map", "q" * 5_000),
               codes=(1,), says=r"\A(?![\s\S]*(maps/|q{300}))[\s\S]*q+…")
    yield Case("A --episodes with another suffix says JSONL or JSON", (
        "bench", "tasks", "--suite", "map", "--map", "m.yaml", "--layouts", "1", "--policies", "sefm", "--episodes",
        "m.yaml"), both, codes=(1,), keep=inputs, says=r"writes JSONL or JSON files")
    yield Case("A bench parse: a second corpus's constants nested too deeply, before any is scored",
               ("bench", "parse", "--corpus", "g.jsonl", "--corpus", "c.tsv", "--constants", "k.json"),
               (("g.jsonl", b'{"text": "stir the cup", "expect": [{"frame": "Stir"}]}\n'), ("c.tsv", ALFRED_ROW),
                ("k.json", b"[" * 100_000 + b"]" * 100_000)), codes=(1,),
               says=r"\A(?![\s\S]*scoring)[\s\S]*k\.json(:1:\d+)?: .*nested too deeply")
    known = np.full((5_000, 5_000), 254, dtype=np.uint8)  # a fully known image: free, walls round it and across
    known[[0, -1], :] = known[:, [0, -1]] = known[:, 2_500] = 0
    known[2_400:2_600, 2_500] = 254
    rooms = ("name: big\nbounds: [0, 0, 250, 250]\nrooms:\n  - {name: kitchen, box: [0, 0, 125, 250]}\n"
             "  - {name: hall, box: [125, 0, 250, 250]}\nrobot: {pose: [200, 125, 0]}\n")
    yield Case("A a fully known image of 5,000 × 5,000 pixels: run", ("run", "go to the kitchen", "--map", "b.yaml"),
               (("b.yaml", ("image: b.pgm\nresolution: 0.05\norigin: [0, 0, 0]\n" + rooms).encode()),
                ("b.pgm", b"P5\n5000 5000\n255\n" + known.tobytes())), codes=(0,), keep=("b.yaml", "b.pgm"),
               says=r"b\.yaml:1:8: .*merges 5×5 pixels")
    yield Case("A a 4,096 × 4,096 RGBA PNG of 86 KB: validate", ("validate", "p.yaml"),
               (("p.yaml", b"image: p.png\nresolution: 0.05\norigin: [0, 0, 0]\nname: p\n"),
                ("p.png", rgba_png(4_096))),
               codes=(1,), keep=("p.yaml", "p.png"), says=r"p\.yaml:1:8: .*merges 4×4 pixels")
    yield Case("A bounds of 100 m × 100 m, no image: run", ("run", "go to the kitchen", "--map", "b.yaml"),
               (("b.yaml", rooms.replace("250", "100").replace("125", "50").replace("200", "80").encode()),),
               codes=(0,), keep=("b.yaml",))
    empty = ("name: e\nbounds: [0, 0, 30, 30]\nrooms:\n  - {name: kitchen, box: [0, 0, 15, 30]}\n"
             "  - {name: hall, box: [15, 0, 30, 30]}\nrobot: {pose: [25, 15, 0]}\npriors:\n"
             "  cup: {kitchen: 0.5, hall: 0.5}\nobjects:\n  - {class: cup, at: [3, 3]}\n")
    yield Case("A search an empty 30 m × 30 m floor: run", ("run", "bring me a cup", "--map", "e.yaml"),
               (("e.yaml", empty.encode()),), codes=(0,), keep=("e.yaml",), timeout=120)


def hostile15_cases() -> Iterator[Case]:
    """Round hostile15: data files read without checks of their values' types (ALFRED-2D's floor plans and trials,
    the end-to-end suite's cases), refusals of a command read from a file or of a vocabulary's entry said without
    their line, ``--framelib +`` read as the current folder, a device given as a frame file called missing."""
    tasks = ("bench", "tasks", "--data", "d", "--policies", "sefm", "--jobs", "1", "--particles", "20")
    trials = r"d/trials_valid_seen\.jsonl:1: trial"
    data: dict[str, tuple[dict[str, object] | None, dict[str, object] | list[object] | None, str]] = {
        "receptacles that are a mapping": ({"receptacles": {"a": 1}}, None,
                                           r"d/floorplans\.json: floor_plans\.FloorPlan1\.receptacles must be a list"),
        "a receptacle that is a list": ({"receptacles": [[1, 2]]}, None,
                                        r"d/floorplans\.json: floor_plans\.FloorPlan1\.receptacles\[0\] must be an "
                                        r"object"),
        "NaN bounds": ({"bounds": [float("nan"), 0, 1, 1]}, None, r"\.bounds\[0\] must be a finite number"),
        "an expert step that is a number": (None, {"expert": {"high_pddl": [5]}},
                                            trials + r"\.expert\.high_pddl\[0\] must be an object"),
        "a NaN position": (None, {"objects": [{"id": "a", "class": "Apple", "position": [float("nan"), 0, 0]}]},
                           trials + r"\.objects\[0\]\.position\[0\] must be a finite number"),
        "a task object of null": (None, {"task": {"type": "pick_and_place_simple", "object": None}},
                                  trials + r"\.task\.object must be a string, not null"),
        "a parent_guess of -1": (None, {"objects": [{"id": "a", "class": "Apple", "position": [1.2, 0.9, 0],
                                                     "parent_guess": -1}]},
                                 trials + r"\.objects\[0\]\.parent_guess must be the index of one of the floor "
                                          r"plan's 2 receptacles"),
        "goals that are a string": (None, {"goals": "put the apple in the fridge"},
                                    trials + r"\.goals must be a list, not a string"),
        "a start 10^308 m away": (None, {"agent_start": [1e308, 1e308, 90]},
                                  trials + r" trial_1: robot pose .* is outside the map's bounds"),
        "a trial that is a list": (None, [1, 2], trials + r" must be an object"),
    }
    for label, (plan, trial, says) in data.items():
        files = alfred2d_data(plan, trial)
        yield Case(f"A ALFRED-2D data: {label}", tasks, files, codes=(1,), keep=tuple(n for n, _ in files),
                   says=says, timeout=120)
    cases = {"plan: 5": ("plan: [Go(goal=kitchen)]", "plan: 5", r"e\.yaml:2:\d+: case 1's plan must be a list"),
             "a plan of one string": ("plan: [Go(goal=kitchen)]", "plan: Go(goal=kitchen)",
                                      r"e\.yaml:2:\d+: case 1's plan must be a list"),
             "an unknown key": ("run: done", "run: done, bogus: 1", r"e\.yaml:2:\d+: unknown key 'bogus' in case 1"),
             "run as a list": ("run: done", "run: [done]", r"e\.yaml:2:\d+: case 1's run must be a single value")}
    good = '{map: apartment, text: "go to the kitchen", plan: [Go(goal=kitchen)], run: done}'
    for label, (old, new, says) in cases.items():
        yield Case(f"A bench e2e --file: {label}", ("bench", "e2e", "--file", "e.yaml", "--jobs", "1"),
                   (("e.yaml", f"cases:\n  - {good.replace(old, new)}\n".encode()),), codes=(1,), keep=("e.yaml",),
                   says=says)
    yield Case("A bench plan --file: a line that cannot be planned, at its line and column",
               ("bench", "plan", "--file", "c.txt", "--repeat", "1"),
               (("c.txt", b"stir the cup\n\n  flibber the garage\n"),), codes=(1,), keep=("c.txt",),
               says=r"c\.txt:3:3: unknown verb 'flibber'")
    yield Case("A bench plan --file: a NUL, at its line and column", ("bench", "plan", "--file", "c.txt", "--repeat",
                                                                      "1"),
               (("c.txt", b"stir the cup\r\nstir\x00 the cup\r\n"),), codes=(1,), keep=("c.txt",),
               says=r"c\.txt:2:5: control character U\+0000")
    yield Case("A --framelib + alone", ("frames", "--framelib", "+"), (("x.yaml", b"name: not a frame file\n"),),
               codes=(1,), keep=("x.yaml",), says=r"--framelib \+: give a file or folder after")
    for device, kind in (("/dev/zero", "character device"), ("pipe", "FIFO")):
        yield Case(f"A --framelib {device}: refused by its kind", ("plan", "--framelib", device, "stir the cup"),
                   (("pipe", "fifo"),), codes=(1,), says=rf"{device}: cannot read this file: it is a {kind}")
    vocabularies = {"synonyms of 5": (b"- cup\n- {class: mug, synonyms: 5}\n", r"v\.yaml:2:26: entry 2: synonyms"),
                    "an entry that is a list": (b"classes:\n  - cup\n  - [x]\n", r"v\.yaml:3:5: entry 2 is neither"),
                    "people of a number": (b"classes: [cup]\npeople: [5]\n", r"v\.yaml:2:9: people: must be")}
    for label, (content, says) in vocabularies.items():
        yield Case(f"A a vocabulary with {label}", ("parse", "--vocabulary", "v.yaml", "stir the cup"),
                   (("v.yaml", content),), codes=(1,), keep=("v.yaml",), says=says)
    _, image, text, _, _, _, _ = hostile_setting()
    cafe = ("m.yaml", text.replace("kitchen", "caf\u00e9").encode())
    decomposed = ("m.yaml", text.replace("kitchen", "cafe\u0301").encode())
    yield Case("A a command typed decomposed (e + U+0301) reaches the room named composed",
               ("plan", "--map", "m.yaml", "go to the cafe\u0301"), (cafe, image), codes=(0,),
               keep=("m.yaml", "apartment.pgm"))
    yield Case("A a map written decomposed (e + U+0301) names the room a composed command reaches",
               ("plan", "--map", "m.yaml", "go to the caf\u00e9"), (decomposed, image), codes=(0,),
               keep=("m.yaml", "apartment.pgm"))


def hostile16_cases() -> Iterator[Case]:
    """Round hostile16: names from files read as rich markup or matplotlib mathematics, a place no plan can name, a
    file named twice read twice, screen sizes no one can draw, comments of a written file broken by a name's line
    break, and an output over a suite's data read after the outputs were planned."""
    _, image, text, _, _, _, _ = hostile_setting()
    kept = ("m.yaml", "apartment.pgm")

    def named(old: str, new: str) -> tuple[tuple[str, bytes], tuple[str, bytes]]:
        assert old in text, f"the apartment changed: update the hostile16 case for {old!r}"
        return ("m.yaml", text.replace(old, new).encode()), image

    # the map's own name: a room's or a person's can hold no '[', '$' or '\\' since hostile22 (no plan could name it)
    markup = named("name: apartment", "name: '[/]bed[bold]x'")
    for argv in (("map", "m.yaml"), ("localize", "--map", "m.yaml", "--task", "find the spoon", "--steps", "1",
                                     "--particles", "20"),
                 ("run", "--map", "m.yaml", "find the spoon", "--particles", "20")):
        yield Case(f"A a map called '[/]bed[bold]x' (rich markup): {argv[0]}", argv, markup, codes=(0,), keep=kept)
    yield Case("A an answer naming a place 'fridge[/]': refused at the place's line",
               ("run", "--map", "m.yaml", "what is in the fridge"), named("fridge_1", "'fridge[/]'"), codes=(1,),
               keep=kept, says=r"m\.yaml:\d+:\d+: place name 'fridge\[/\]' is not")
    yield Case("A a place class 'si|nk': validate", ("validate", "m.yaml"), named("class: sink", "class: 'si|nk'"),
               codes=(1,), keep=kept, says=r"m\.yaml:\d+:\d+: place sink_1: class 'si\|nk' is not")
    zap = ("z.yaml", b"frame: Zap\ndescription: '[/] zap [bold]'\nlexical_units: [zap]\n"
                     b"elements: {theme: {type: object}}\nactions: [navigate(theme)]\n"
                     b"postconditions: [looked_at(theme)]\n")
    for shown in ("Zap", ""):
        yield Case(f"A a frame described in rich markup: {shown or 'the table'}",
                   ("frames", "--framelib", "+z.yaml", *([shown] if shown else [])), (zap,), codes=(0,),
                   keep=("z.yaml",))
    dollars = named("name: apartment", "name: '$x^$'")
    yield Case("A a map called '$x^$' (mathematics to matplotlib): map --png", ("map", "m.yaml", "--png", "o.png"),
               dollars, codes=(0,), keep=kept, whole=("o.png",))
    yield Case("A a map called '$x^$': localize --png", ("localize", "--map", "m.yaml", "--task", "find the spoon",
                                                         "--steps", "1", "--particles", "20", "--png", "o.png"),
               dollars, codes=(0,), keep=kept, whole=("o.png",))
    yield Case("A a map called '$\\frac{$': run --png", ("run", "--map", "m.yaml", "find the spoon", "--particles",
                                                          "20", "--png", "o.png"),
               named("name: apartment", "name: '$\\frac{$'"), codes=(0,), keep=kept, whole=("o.png",))
    stir = ("s.frame", FRAME.encode())
    yield Case("A a frame file named twice: validate", ("validate", "s.frame", "s.frame", "l.frame"),
               (stir, ("l.frame", "link:s.frame")), codes=(0,), keep=("s.frame",))
    yield Case("A a frame file named twice: --framelib", ("frames", "--framelib", "s.frame", "--framelib", "."),
               (stir,), codes=(0,), keep=("s.frame",))
    digits = "1" * 5_000
    for name, value in (("COLUMNS", "1000000000"), ("TERMINAL_WIDTH", "abc"), ("COLUMNS", digits),
                        ("LINES", digits), ("TERMINAL_WIDTH", "1000000000")):
        shown = value if len(value) < 20 else f"{len(value):,} digits"
        yield Case(f"A {name}={shown}: --help", ("--help",), codes=(0,), env=((name, value),))
        yield Case(f"A {name}={shown}: a usage error", ("localize", "--map", "apartment", "--steps", "x"), codes=(2,),
                   env=((name, value),), says="--steps")
    yield Case("A plan --pddl of a command of two lines: both files PDDL",
               ("plan", "stir the cup\nthen open the fridge", "--pddl", "out"), (("out", "dir"),), codes=(0,),
               whole=("out/domain.pddl", "out/problem.pddl"))
    data = alfred2d_data(None, None)
    tasks = ("bench", "tasks", "--data", "d", "--policies", "sefm", "--jobs", "1", "--particles", "20", "--episodes")
    for target, extra in (("d/floorplans.json", ()), ("d/trials_train.jsonl", ()),
                          ("d/t.json", (("d/t.json", "link:trials_valid_seen.jsonl"),))):
        yield Case(f"A bench tasks --episodes onto its data: {target}", (*tasks, target), (*data, *extra), codes=(1,),
                   keep=tuple(n for n, _ in data), says=r"--episodes d/\S+ would overwrite the input d/", timeout=120)
    yield Case("A a DSL element named in other letters ('thème')", ("validate", "k.frame"),
               (("k.frame", "category cup = cup\nframe Zap \"zap\" { thème: cup do navigate(thème) }\n".encode()),),
               codes=(1,), keep=("k.frame",), says=r"k\.frame:2:21: syntax error: a name in a \.frame file is written")
    yield Case("A a lexical unit in other letters ('zäp')", ("validate", "k.frame"),
               (("k.frame", "frame Zap \"zäp\" { }\n".encode()),), codes=(1,), keep=("k.frame",),
               says=r"k\.frame:1:11: lexical unit 'zäp' must be one or more words of letters a-z")
    yield Case("A a room whose name holds ESC and CR: map", ("map", "m.yaml"),        # refused since hostile22
               named("bedroom", '"bed\\e[31mroom\\r"'), codes=(1,), keep=kept,
               says=r"m\.yaml:\d+:\d+: room name .* which a plan cannot name")
    yield Case("A validate a map whose name has no .yaml (my_map)", ("validate", "my_map"),
               (("my_map", text.encode()), image), codes=(0,), keep=("my_map", "apartment.pgm"))
    yield Case("A parse --file of 100,000 blank lines (each refused)", ("parse", "--file", "c.txt", "--json"),
               (("c.txt", b"\n" * 100_000),), codes=(0,), keep=("c.txt",))
    yield from _bag_names()


def _bag_names() -> Iterator[Case]:
    """import-bag of a bag whose name holds a line break or a byte that is not UTF-8: the file reads back."""
    bag = _sample_bag()
    if bag is None:
        return
    for name in ("r\nx: [.mcap", "r\u2028x.mcap", "r\udcffz.mcap"):
        yield Case(f"A import-bag of a bag called {name!r}: the file reads back", ("import-bag", name, "-o", "o.yaml"),
                   ((name, bag),), codes=(0,), keep=(name,), whole=("o.yaml",))


def chain_library(length: int) -> tuple[bytes, str]:
    """A YAML frame file of ``length`` frames Z0 … Z{length-1}, each needing what only the one before it gives,
    and a command evoking the last (its lexical unit: "zap" and three letters)."""
    def unit(i: int) -> str:
        return "zap" + "".join(chr(97 + (i // 26 ** d) % 26) for d in range(3))

    frames = [f"  - frame: Z{i}\n    lexical_units: [{unit(i)}]\n    elements:\n      theme: {{type: object}}\n"
              f"    preconditions: [{f'done{i - 1}(theme)' if i else ''}]\n    actions: [navigate(theme)]\n"
              f"    postconditions: [done{i}(theme)]\n" for i in range(length)]
    return ("frames:\n" + "".join(frames)).encode(), f"{unit(length - 1)} the cup"


def hostile17_cases() -> Iterator[Case]:
    """Round hostile17: YAML of millions of values composed before anything bounded it (maps, frame files,
    observations, trajectories), a frame library whose needs chain 3,000 deep, what is no file at a cache entry's
    name, and a file just past the size bound said to be of the bound's size."""
    millions = b"[" + b"0," * 7_000_000 + b"0]\n"  # 14 MB: seven million values, within the 16 MiB of a file
    said = r"{}:\d+:\d+: this file holds more than 1,000,000 values"
    for name, argv, data in (
            ("a map: validate", ("validate", "m.yaml"), b"name: m\nbounds: [0, 0, 4, 4]\nnoise: " + millions),
            ("a map: map", ("map", "m.yaml"), b"name: m\nbounds: [0, 0, 4, 4]\nnoise: " + millions),
            ("a frame file: frames", ("frames", "--framelib", "+m.yaml"), b"frame: Zap\nnoise: " + millions),
            ("observations: localize", ("localize", "--map", "apartment", "--particles", "20", "--observations",
                                        "m.yaml"), b"- {pose: [0, 0], detections: " + millions + b"}\n"),
            ("a trajectory: localize", ("localize", "--map", "apartment", "--particles", "20", "--trajectory",
                                        "m.yaml"), b"poses: " + millions)):
        yield Case(f"A seven million values in {name}", argv, (("m.yaml", data),), codes=(1,), keep=("m.yaml",),
                   says=said.format(r"m\.yaml"), timeout=40)
    chain, command = chain_library(3000)
    yield Case("A a frame library whose needs chain 3,000 frames deep: plan",
               ("plan", "--framelib", "+z.yaml", command), (("z.yaml", chain),), codes=(1,), keep=("z.yaml",),
               says=r"z\.yaml:\d+:\d+: Z2999 needs a chain of more than 100 frames")
    from seal_cli.frames.reading import cache_entry_name

    entry = cache_entry_name()
    if entry is not None:
        for kind in ("fifo", "dir"):
            yield Case(f"A a {'FIFO' if kind == 'fifo' else 'folder'} at the library's cache entry: parse",
                       ("parse", "stir the cup"), ((f"c/{entry}", kind),), codes=(0,), env=(("SEAL_CACHE_DIR", "c"),),
                       timeout=30)
    yield Case("A import-bag of a link loop", ("import-bag", "loop", "-o", "o.yaml"), (("loop", "link:loop"),),
               codes=(1,), absent=("o.yaml",), says=r"loop: cannot read this bag: Too many levels of symbolic links")
    yield Case("A localize --goals with --rrd a link loop",
               ("localize", "--map", "apartment", "--task", "find the cup", "--steps", "1", "--particles", "20",
                "--goals", "g.yaml", "--rrd", "loop"), (("loop", "link:loop"),), codes=(1,), absent=("g.yaml",),
               says=r"cannot write --rrd loop")
    yield Case("A import-bag of a folder without metadata.yaml", ("import-bag", "b", "-o", "o.yaml"), (("b", "dir"),),
               codes=(1,), absent=("o.yaml",), says=r"b: this folder is no ROS 2 bag: it has no metadata\.yaml")
    yield from _misnamed_bags()
    yield Case("A run a word whose 'c' is Cyrillic ('\u0441up')", ("run", "find the \u0441up", "--map", "apartment",
                                                                 "--particles", "20"), codes=(1,),
               says=r"column 10: the word '\u0441up' mixes Cyrillic and Latin letters")
    yield Case("A observations 100 bytes past 16 MiB: the sizes in bytes",
               ("localize", "--map", "apartment", "--observations", "o.yaml"),
               (("o.yaml", b"#" * (16 * 2**20 + 100) + b"\n"),), codes=(1,), keep=("o.yaml",),
               says=r"o\.yaml: this file is 16,777,317 bytes; seal reads files of at most 16,777,216 bytes")


def _misnamed_bags() -> Iterator[Case]:
    """import-bag of an MCAP bag named ``.bag``, ``.db3`` or with no suffix: told to rename it."""
    bag = _sample_bag()
    if bag is None:
        return
    for name in ("run.bag", "run.db3", "run"):
        yield Case(f"A import-bag of an MCAP bag named {name}", ("import-bag", name, "-o", "o.yaml"), ((name, bag),),
                   codes=(1,), keep=(name,), absent=("o.yaml",),
                   says=rf"{name.replace('.', chr(92) + '.')}: this file is an MCAP bag, but .*rename it to end in "
                        r"\.mcap")


SMALL_MAP = ("name: m\nbounds: [0, 0, 10, 10]\nrobot: &r {pose: [1, 1, 0]}\n"
             "rooms:\n  - &room {name: kitchen, box: [0, 0, 5, 10]}\n"
             "  - {<<: *room, name: hall, box: [5, 0, 10, 10]}\n")
"""A map of two rooms, the second merging the first (``<<``), the robot's pose anchored."""


def _hostile_bag(poses: list[tuple[float, float, float, float]],
                 looks: list[tuple[float, list[tuple[str, float, float, float]]]],
                 rotation: tuple[int, tuple[float, float, float, float]] | None = None) -> bytes | None:
    """The bytes of an MCAP bag: PoseStamped ``poses`` (t, x, y, yaw) on /robot_pose and a Detection3DArray per look
    (t, detections in map) on /detections; ``rotation``: (index of a pose, the quaternion x y z w it holds instead of
    its yaw's); None without the ros extra."""
    try:
        import rosbags  # noqa: F401
    except ImportError:
        return None
    import tempfile
    from pathlib import Path

    from seal_cli.ros.messages import DETECTION_3D, POSE_STAMPED, typestore
    from seal_cli.ros.writing import detection_array, pose_stamped, write_bag

    store = typestore(False)
    messages = [("/robot_pose", POSE_STAMPED, t, pose_stamped(store, t, "map", x, y, yaw, False))
                for t, x, y, yaw in poses]
    if rotation is not None:
        q = messages[rotation[0]][3].pose.orientation
        q.x, q.y, q.z, q.w = rotation[1]
    messages += [("/detections", DETECTION_3D, t, detection_array(store, t, "map", seen, False)) for t, seen in looks]
    messages.sort(key=lambda m: m[2])
    with tempfile.TemporaryDirectory() as folder:
        write_bag(Path(folder) / "b.mcap", messages, store)
        return (Path(folder) / "b.mcap").read_bytes()


def hostile18_cases() -> Iterator[Case]:
    """Round hostile18: a problem with an alias's value said at the anchor, merge keys refused, bags imported into
    observations seal then refused, a bad look said without its line after the looks before it were filtered, a
    lexical unit no command can hold, an option naming one policy twice, a --match of no case."""
    yield Case("A a person that is an alias of the robot: said at the alias's line", ("validate", "m.yaml"),
               (("m.yaml", (SMALL_MAP + "people: [*r]\n").encode()),), codes=(1,), keep=("m.yaml",),
               says=r"m\.yaml:7:10: a person needs a name")
    yield Case("A a room merging another (<<: *room): map", ("map", "m.yaml", "--json"),
               (("m.yaml", SMALL_MAP.encode()),), codes=(0,), keep=("m.yaml",), twice=True)
    yield Case("A a merge key of a number", ("validate", "m.yaml"),
               (("m.yaml", SMALL_MAP.replace("<<: *room", "<<: 5").encode()),), codes=(1,), keep=("m.yaml",),
               says=r"m\.yaml:6:10: a merge key \(<<\) takes a mapping")
    frames = ("frames:\n  - &base\n    frame: Zap\n    lexical_units: [zapp]\n    elements:\n"
              "      theme: {type: object}\n    actions: [navigate(theme)]\n    postconditions: [zapped(theme)]\n"
              "  - <<: *base\n"
              "    lexical_units: [zopp]\n")
    yield Case("A a frame merging another's name (<<: *base): said at the merge", ("validate", "f.yaml"),
               (("f.yaml", frames.encode()),), codes=(1,), keep=("f.yaml",),
               says=r"f\.yaml:9:9: duplicate frame name 'Zap': already defined \(at f\.yaml:3:12\)")
    laughs = "".join(f"l{i}: &l{i} [{', '.join([f'*l{i - 1}'] * 9)}]\n" for i in range(1, 9))
    yield Case("A a billion laughs merged (<<: *l0 beside *l8)", ("validate", "m.yaml"),
               (("m.yaml", (SMALL_MAP + "l0: &l0 {a: 1, b: 2, c: 3, d: 4, e: 5, f: 6, g: 7, h: 8, i: 9}\n" + laughs
                            + "z: {<<: *l0, y: *l8}\n").encode()),), codes=(1,), keep=("m.yaml",),
               says=r"m\.yaml(:\d+:\d+)?: this file holds more than 1,000,000 values once its aliases")
    # robot5: a detector reports every class it knows (a chair, a person); they are set aside with a warning
    yield Case("A observations whose second look sees a class nobody knows: set aside, said",
               ("localize", "--map", "apartment", "--particles", "20", "--observations", "o.yaml"),
               (("o.yaml", b"- {pose: [-6, -3, 0], detections: [{class: cup, at: [1, 1]}]}\n"
                           b"- {pose: [-6, -3, 0], detections: [{class: zzz, at: [1, 1]}]}\n"),), codes=(0,),
               keep=("o.yaml",), says=r"1 detection of a class neither map apartment nor the plan knows was set "
                                       r"aside: zzz \(1\)")
    unit = " ".join(["zap"] * 20_000)
    yield Case("A a lexical unit of 80,000 characters: validate", ("validate", "f.frame"),
               (("f.frame", f'frame Zap "{unit}" {{\n  theme: object\n  do navigate(theme)\n}}\n'.encode()),),
               codes=(1,), keep=("f.frame",), says=r"f\.frame:1:11: lexical unit .* longer than any command")
    yield Case("A bench tasks --policies sefm,sefm",
               ("bench", "tasks", "--suite", "map", "--map", "apartment", "--policies", "sefm,sefm"), codes=(1,),
               says=r"--policies 'sefm,sefm' names 'sefm' twice")
    yield Case("A bench ros --format ''", ("bench", "ros", "--format", ""), codes=(1,),
               says=r"--format( is empty|'' names nothing)[^\n]*mcap")
    yield Case("A bench reliability --match of no case", ("bench", "reliability", "--match", "zzz no case"),
               codes=(1,), says=r"--match 'zzz no case': no case's name holds this text")
    good = [(1.0, -6.0, -3.0, 0.0), (3.0, -5.0, -3.0, 0.0)]
    for name, poses, looks, said in (
            ("a NaN pose", [(1.0, -6.0, -3.0, 0.0), (2.0, math.nan, -3.0, 0.0), (3.0, -5.0, -3.0, 0.0)],
             [(2.5, [("cup", 1.0, 1.0, 0.0)])], r"the pose of message 2 on /robot_pose .* is \(nan, "),
            ("a detection at infinity", good, [(2.0, [("cup", math.inf, 1.0, 0.0)])],
             r"the position of detection 1 of message 1 on /detections is \(inf, "),
            ("a detection 1e300 m away", good, [(2.0, [("cup", 1e300, 1.0, 0.0)])],
             r"the position of detection 1 of message 1 on /detections is \(1e\+300, "),
            ("1,001 detections in one message", good, [(2.0, [("cup", 1.0, 1.0, 0.0)] * 1001)],
             r"message 1 on /detections holds 1,001 detections")):
        bag = _hostile_bag(poses, looks)
        if bag is None:
            return
        yield Case(f"A import-bag of {name}", ("import-bag", "b.mcap", "-o", "o.yaml"), (("b.mcap", bag),),
                   codes=(1,), keep=("b.mcap",), absent=("o.yaml",), says=rf"b\.mcap: {said}")
        yield Case(f"A localize --bag of {name}", ("localize", "--map", "apartment", "--particles", "20", "--bag",
                                                   "b.mcap"), (("b.mcap", bag),), codes=(1,), keep=("b.mcap",),
                   says=rf"b\.mcap: {said}")


def hostile19_cases() -> Iterator[Case]:  # noqa: PLR0915 - one list of cases, read top to bottom
    """Round hostile19: names of any length, a rotation that is no unit quaternion, UTF-16 and UTF-32 said as bytes,
    a library of no frames, a resolution no map can have, COLUMNS=1, goals written as a bag folder by a wrong suffix,
    benchmarks of nothing that reported success, a default command the map cannot ground, a handed stream."""
    long = "k" * 5000
    room = f"name: m\nbounds: [0, 0, 10, 10]\nrooms:\n  - name: {long}\n    box: [0, 0, 5, 10]\n"
    yield Case("A a room name of 5,000 letters: at its line", ("validate", "m.yaml"), (("m.yaml", room.encode()),),
               codes=(1,), keep=("m.yaml",), says=r"m\.yaml:4:11: room name 'k+…' is 5,000 characters long")
    person = f"name: m\nbounds: [0, 0, 10, 10]\npeople:\n  - {{name: {long}, at: [1, 1]}}\n"
    # said at the name itself since hostile23 (4:12), not at the person's first key (4:5)
    yield Case("A a person name of 5,000 letters: map", ("map", "m.yaml"), (("m.yaml", person.encode()),),
               codes=(1,), keep=("m.yaml",), says=r"m\.yaml:4:12: person name 'k+…' is 5,000 characters long")
    yield Case("A a map name of 5,000 letters: run", ("run", "go to the hall", "--map", "m.yaml"),
               (("m.yaml", f"name: {long}\nbounds: [0, 0, 10, 10]\n".encode()),), codes=(1,), keep=("m.yaml",),
               says=r"m\.yaml:1:7: map name 'k+…' is 5,000 characters long")
    frame = f'category thing = *\nframe Z{long} "zap" {{\n  theme: thing\n  do navigate(theme)\n}}\n'
    yield Case("A a frame name of 5,001 letters: plan", ("plan", "zap the cup", "--framelib", "+f.frame"),
               (("f.frame", frame.encode()),), codes=(1,), keep=("f.frame",),
               says=r"f\.frame:2:7: frame name 'Zk+…' is 5,001 characters long")
    element = f'category thing = *\nframe Zap "zap" {{\n  {long}: thing\n  do navigate({long})\n}}\n'
    yield Case("A an element name of 5,000 letters: validate", ("validate", "f.frame"),
               (("f.frame", element.encode()),), codes=(1,), keep=("f.frame",),
               says=r"f\.frame:3:3: element 'k+…' is 5,000 characters long")
    yield Case("A a vocabulary class of 1,000 letters", ("parse", "--vocabulary", "v.yaml", "find the cup"),
               (("v.yaml", f"- cup\n- {'c' * 1000}\n".encode()),), codes=(1,), keep=("v.yaml",),
               says=r"v\.yaml:2:3: entry 2: name 'c+…' is 1,000 characters long")
    yield Case("A bench ros --messages past its bound", ("bench", "ros", "--messages", "5001"), codes=(2,),
               says=r"--messages")
    yield Case("A bench ros --poses past its bound", ("bench", "ros", "--poses", "100001"), codes=(2,),
               says=r"--poses")
    text = "stir the cup\nfind the spoon\n"
    yield Case("A parse --file in UTF-16 without a byte-order mark", ("parse", "--file", "c.txt", "--json"),
               (("c.txt", text.encode("utf-16-le")),), codes=(1,), keep=("c.txt",),
               says=r"c\.txt:1:1: this file is UTF-16 text, not UTF-8")
    yield Case("A a map in UTF-32", ("validate", "m.yaml"),
               (("m.yaml", "name: m\nbounds: [0, 0, 10, 10]\n".encode("utf-32")),), codes=(1,), keep=("m.yaml",),
               says=r"m\.yaml:1:1: this file is UTF-32 text, not UTF-8")
    for name, content in (("an empty file", b""), ("frames: []", b"frames: []\n"),
                          ("categories alone", b"categories:\n  utensil: [spoon]\n")):
        yield Case(f"A plan --framelib of {name}", ("plan", "stir the cup", "--framelib", "f.yaml"),
                   (("f.yaml", content),), codes=(1,), keep=("f.yaml",),
                   says=r"f\.yaml: this (frame library holds no frames|file holds nothing)")  # hostile30: the file
    image = b"P5\n2 2\n255\n" + bytes([254] * 4)
    for value, said in (("1e300", r"m\.yaml:2:13: resolution 1e\+300 m of an image of 2×2 pixels"),
                        ("1e-300", r"m\.yaml:2:13: resolution must be a number of metres per pixel of at least")):
        yield Case(f"A a map image at resolution {value}: map --png", ("map", "m.yaml", "--png", "o.png"),
                   (("m.yaml", f"image: i.pgm\nresolution: {value}\norigin: [0, 0, 0]\n".encode()), ("i.pgm", image)),
                   codes=(1,), keep=("m.yaml", "i.pgm"), absent=("o.png",), says=said)
    yield Case("A COLUMNS=1 frames", ("frames",), codes=(0,), env=(("COLUMNS", "1"),))
    yield Case("A localize --goals goals.txt", ("localize", "--map", "apartment", "--task", "stir the cup", "--steps",
                                                "1", "--particles", "10", "--goals", "goals.txt"), codes=(1,),
               absent=("goals.txt",), says=r"seal writes goals as YAML \(\.yaml, \.yml\), .* not \.txt")
    yield Case("A bench e2e --file of no cases", ("bench", "e2e", "--file", "e.yaml"), (("e.yaml", b"cases: []\n"),),
               codes=(1,), keep=("e.yaml",), says=r"e\.yaml:1:8: the suite holds no cases")
    yield Case("A bench parse --corpus of no commands", ("bench", "parse", "--corpus", "c.jsonl", "--scorers", "."),
               (("c.jsonl", b"\n\n"), ("score_parse.py", b"raise SystemExit('never run')\n")), codes=(1,),
               keep=("c.jsonl",), says=r"c\.jsonl: this corpus holds no commands")
    yield Case("A bench tasks --suite map on a map without a bedroom",
               ("bench", "tasks", "--suite", "map", "--map", "m.yaml", "--layouts", "1", "--jobs", "1"),
               (("m.yaml", b"name: m\nbounds: [0, 0, 10, 10]\nrooms:\n  - {name: hall, box: [0, 0, 10, 10]}\n"),),
               codes=(1,), keep=("m.yaml",), says=r"has no bedroom.*\(in 'bring the apple to the bedroom', one of the "
                                                  r"suite's default commands")
    yield Case("A parse --file /dev/stdin", ("parse", "--file", "/dev/stdin"), codes=(1,), stdin=b"stir the cup\n",
               says=r"/dev/stdin: cannot read this file: .*a stream this command was handed")
    good = [(1.0, -6.0, -3.0, 0.0), (3.0, -5.0, -3.0, 0.0)]
    for name, q in (("(0, 0, 0, 0)", (0.0, 0.0, 0.0, 0.0)), ("of length 3.5", (0.0, 0.0, 3.5, 0.0))):
        bag = _hostile_bag(good, [(2.0, [("cup", 1.0, 1.0, 0.0)])], (1, q))
        if bag is None:
            return
        yield Case(f"A import-bag of a pose rotated by {name}", ("import-bag", "b.mcap", "-o", "o.yaml"),
                   (("b.mcap", bag),), codes=(1,), keep=("b.mcap",), absent=("o.yaml",),
                   says=r"b\.mcap: the rotation of message 2 on /robot_pose \(qx, qy, qz, qw\) is .*a rotation is a "
                        r"unit quaternion")


def hostile20_cases() -> Iterator[Case]:
    """Round hostile20: standard output and files written under a limit: a file grown past ``ulimit -f`` (the
    largest file a process may write), and a pipe whose parent made it non-blocking, with and without
    ``PYTHONUNBUFFERED=1`` (set in many containers and CI images: Python's unbuffered stream drops what a short
    write leaves)."""
    unbuffered = ("PYTHONUNBUFFERED", "1")
    buffered = ("PYTHONUNBUFFERED", "<unset>")
    for name, setting in (("PYTHONUNBUFFERED=1", unbuffered), ("buffered", buffered)):
        for printing in (("frames", "--json"), ("frames",), ("map", "apartment", "--json")):
            yield Case(f"A {' '.join(printing)} into a file past ulimit -f of 2 KiB ({name})", printing,
                       (("stdout.out", b""),), codes=(1,), stream="file-stdout", file_blocks=4, env=(setting,),
                       says=r"error: cannot write the output: File too large")
    lines = "".join(f"stir the cup number {i}\n" for i in range(2_500)) + "put the apple on the table\n"
    for name, setting in (("PYTHONUNBUFFERED=1", unbuffered), ("buffered", buffered)):
        for shape in (("--json",), ()):
            yield Case(f"A parse --file {' '.join(shape) or 'as text'} into a non-blocking pipe ({name})",
                       ("parse", "--file", "c.txt", *shape), (("c.txt", lines.encode()),), codes=(0,),
                       keep=("c.txt",), stream="nonblocking-stdout", env=(setting,),
                       says=r'"text": "put the apple on the table"' if shape
                       else r"\n2501: Place\(theme=apple, goal=table\)\n$")
    writing: tuple[str, ...]
    for what, writing, files, option in (
            ("map --png", ("map", "apartment", "--png", "o.png"), (), r"--png o\.png"),
            ("localize --png", ("localize", "--map", "apartment", "--task", "stir the cup", "--steps", "1",
                                "--particles", "10", "--png", "o.png"), (), r"--png o\.png"),
            ("plan --pddl", ("plan", "stir the cup", "--pddl", "d"), (("d", "dir"),),
             r"--pddl d/(domain|problem)\.pddl")):
        yield Case(f"A {what} past ulimit -f of 4 KiB", writing, files, codes=(1,), file_blocks=8,
                   absent=("o.png", "d/domain.pddl", "d/problem.pddl"),
                   says=rf"error: cannot write {option}: File too large")
    yield Case("A plan --max-nodes 1 stopped before a frame whose needs are met",
               ("plan", "stir the cup", "--max-nodes", "1"), codes=(1,),
               says=r"within 1 search node: Stir\(theme=cup, instrument=spoon\) \(commanded frame 1\) was next, its "
                    r"preconditions met")
    unread: tuple[str, ...]
    for unread, said in ((("--suite", "map", "--type", "x", "--layouts", "1"), r"--suite map does not read --type"),
                       (("--suite", "map", "--limit", "1"), r"--suite map does not read --limit"),
                       (("--map", "townhouse", "--data", "d"), r"--suite alfred2d does not read --map"),
                       (("--suite", "context", "--split", "train", "--data", "d"),
                        r"--suite context does not read --split")):
        yield Case(f"A bench tasks {' '.join(unread)}: an option its suite does not read",
                   ("bench", "tasks", *unread, "--jobs", "1"),
                   (("d", "dir"),), codes=(1,), says=said, timeout=30)
    for option, value in (("--frame", "odom"), ("--base-frame", "base_link")):
        yield Case(f"A localize {option} {value} without --bag", ("localize", "--map", "apartment", "--task",
                                                                  "stir the cup", "--steps", "0", option, value),
                   codes=(1,), says=rf"{option} reads a bag: give --bag too")
    yield Case("A bench parse --constants with a JSON Lines corpus only",
               ("bench", "parse", "--corpus", "c.jsonl", "--constants", "k.json"),
               (("c.jsonl", b'{"text": "stir the cup"}\n'), ("k.json", b'{"OBJECTS": ["cup"]}\n')), codes=(1,),
               keep=("c.jsonl", "k.json"), says=r"--constants k\.json: the ALFRED constants are read for ALFRED goals")


def hostile21_cases() -> Iterator[Case]:  # noqa: PLR0915 - one list of cases, read top to bottom
    """Round hostile21: what typer prints before a command (its help, ``--version``) onto a full disk, a closed
    standard output or a reader that has gone; a command-line byte that is not UTF-8; numbers written in other
    digits, as superscripts or fractions, or with a multiplier; invisible characters in a command."""
    full = r"error: cannot write the output: No space left on device"
    argv: tuple[str, ...]
    for argv in (("--help",), ("map", "--help"), ("bench", "tasks", "--help"), ("-h",)):
        yield Case(f"A {' '.join(argv)} onto /dev/full", argv, codes=(1,), stream="full-stdout", says=full)
        yield Case(f"A {' '.join(argv)} into a reader that has gone", argv, codes=(0,), stream="gone-stdout")
    yield Case("A --version onto /dev/full", ("--version",), codes=(1,), stream="full-stdout", says=full)
    yield Case("A --version with standard output closed", ("--version",), codes=(0,), stream="closed-stdout")
    yield Case("A --version into a reader that has gone", ("--version",), codes=(0,), stream="gone-stdout")
    latin1 = "stir the caf\udce9"  # the byte 0xe9 on the command line: "café" typed in a Latin-1 terminal
    for argv in (("parse", latin1), ("parse", latin1, "--json"), ("plan", latin1),
                 ("localize", "--map", "apartment", "--steps", "0", "--task", latin1)):
        yield Case(f"A {argv[0]}{' --json' if '--json' in argv else ''} of a command with a Latin-1 byte", argv,
                   codes=(1,), says=r'"text": "stir the caf\\udce9", "error": \{"message": "byte 0xe9 is not UTF-8: '
                   r'.*"column": 13' if "--json" in argv else
                   r"column 13: byte 0xe9 is not UTF-8: seal reads a command as UTF-8 text")
    yield Case("A plan with a full-width digit", ("plan", "put \uff13 apples in the sink", "--map", "apartment"),
               codes=(0,), says=r"Place\s+theme=apple_3, goal=sink_1")
    yield Case("A plan with an Arabic-Indic digit", ("plan", "bring me \u0662 apples", "--map", "apartment"),
               codes=(0,), says=r"Bring\s+theme=apple_2, recipient=me")
    for number, column, name in (("\u00b2", 10, "superscript two"), ("3\u00bd", 11, "vulgar fraction one half")):
        yield Case(f"A plan of {name} apples", ("plan", f"bring me {number} apples", "--map", "apartment"),
                   codes=(1,), says=rf"column {column}: '.' \({name}\) is no whole number")
    for count, shown in (("one million", "1,000,000"), ("2 thousand", "2,000"), ("hundreds of", "200")):
        yield Case(f"A run of {count} apples", ("run", f"bring me {count} apples", "--map", "apartment"),
                   codes=(1,), says=rf"column 10: '{count} apples' asks for {shown} things; seal plans for at most 100")
    for mark, name in (("\u200d", "ZERO WIDTH JOINER"), ("\u200f", "RIGHT-TO-LEFT MARK")):
        yield Case(f"A parse with a {name.lower()}", ("parse", f"stir the cu{mark}p"), codes=(1,),
                   says=rf"column 12: unexpected character .* \(U\+{ord(mark):04X} {name}\)")
    for value, said in (("012", r"'012' has a leading zero: YAML 1\.1, which seal reads, takes it as octal \(10\)"),
                        ("10:00", r"'10:00' is a number in base 60 to YAML 1\.1")):
        bounds = f"name: m\nbounds: [0, 0, {value}, 10]\nrooms:\n  - {{name: hall, box: [0, 0, 5, 10]}}\n"
        yield Case(f"A a map's bounds of {value}", ("validate", "m.yaml"), (("m.yaml", bounds.encode()),),
                   codes=(1,), keep=("m.yaml",), says=rf"m\.yaml:2:16: cannot read this value: {said}")
        looks = f"- {{pose: [-6, -3, {value}], detections: []}}\n"
        yield Case(f"A an observation's yaw of {value}", ("localize", "--map", "apartment", "--task", "find the cup",
                                                          "--observations", "o.yaml", "--particles", "20"),
                   (("o.yaml", looks.encode()),), codes=(1,), keep=("o.yaml",),
                   says=rf"o\.yaml:1:19: observation 1's pose's yaw cannot be read: {said}")
    yield Case("A an observation's yaw of 1e-1, as a map reads it", ("localize", "--map", "apartment", "--task",
                                                                     "find the cup", "--observations", "o.yaml",
                                                                     "--particles", "20"),
               (("o.yaml", b"- {pose: [-6, -3, 1e-1], detections: []}\n"),), codes=(0,), keep=("o.yaml",),
               says=r"frames on apartment after \d+ updates \(20 particles")
    tiny = b"P5\n2 2\n255\n" + bytes([254] * 4)    # 0.1 m of image at 0.05 m a pixel, rooms drawn for metres
    drawn = b"image: i.pgm\nresolution: 0.05\norigin: [0, 0, 0]\nrooms:\n  - {name: hall, box: [0, 0, 50, 50]}\n"
    yield Case("A a room of 50 m on an image of 0.1 m: validate", ("validate", "m.yaml"),
               (("m.yaml", drawn), ("i.pgm", tiny)), codes=(1,), keep=("m.yaml", "i.pgm"),
               says=r"m\.yaml:5:5: room hall \(\[0, 0\]–\[50, 50\]\) lies 100% outside the map's bounds")
    yield Case("A a room of 50 m on an image of 0.1 m: map", ("map", "m.yaml"), (("m.yaml", drawn), ("i.pgm", tiny)),
               codes=(0,), keep=("m.yaml", "i.pgm"), says=r"warning: m\.yaml:5:5: room hall .* lies 100% outside")
    cased = "".join(f"  - frame: {name}\n    lexical_units: [{unit}]\n    elements:\n      theme: {{type: object}}\n"
                    f"    actions: [navigate(theme)]\n    postconditions: [{fact}(theme)]\n"
                    for name, unit, fact in (("Zap", "zapple", "hot"), ("ZAP", "zopple", "cold")))
    yield Case("A plan --pddl of frames Zap and ZAP", ("plan", "zapple the cup", "--framelib", "+f.yaml", "--pddl",
                                                       "d"), (("f.yaml", f"frames:\n{cased}".encode()), ("d", "dir")),
               codes=(1,), keep=("f.yaml",), absent=("d/domain.pddl", "d/problem.pddl"),
               says=r"cannot export PDDL: the actions 'do_Zap' and 'do_ZAP' differ only in case")
    yield Case("A bench plan --file - with a command on standard input", ("bench", "plan", "--file", "-"),
               codes=(1,), stdin=b"stir the cup\n", says=r"-: no such file \('-' is standard input only to seal parse")
    for name, said in (("\U0001f6cf", r"U\+1F6CF BED\), a symbol"), ("hall\u200d", r"U\+200D ZERO WIDTH JOINER\)")):
        emoji = f'name: m\nbounds: [0, 0, 10, 10]\nrooms:\n  - {{name: "{name}", box: [0, 0, 10, 10]}}\n'
        yield Case(f"A a room called {name.encode('unicode_escape').decode()}", ("run", "go to the hall", "--map",
                                                                                   "m.yaml"),
                   (("m.yaml", emoji.encode()),), codes=(1,), keep=("m.yaml",),
                   says=rf"m\.yaml:4:\d+: room name .* \({said}.* no command can say")
    yield Case("A parse TEXT typed decomposed (NFD)", ("parse", "stir the cafe\u0301", "--json"), codes=(0,),
               says=r'"head": "caf\u00e9"')
    ascii_locale = (("LC_ALL", "C"), ("LANG", "C"), ("PYTHONUTF8", "0"), ("PYTHONCOERCECLOCALE", "0"))
    for argv in (("parse", "stir the café"), ("plan", "stir the café")):  # the apartment knows no café (e2e27)
        yield Case(f"A {argv[0]} of an accented word in an ASCII locale", argv, codes=(0,), env=ascii_locale,
                   says=r"Stir .*caf\\xe9")
    yield Case("A plan of twenty apples", ("plan", "bring me twenty apples", "--map", "apartment", "--json"),
               codes=(0,), says=r'"apple_20"(?![\s\S]*"apple_21")')


def hostile22_cases() -> Iterator[Case]:
    """Round hostile22: names of rooms and people a plan cannot name (punctuation, a leading digit), which validated
    and then failed every plan at a line of seal's own ``motion.yaml``; counts of zero and "a hundred and one"; a
    ``.frame`` file with CR line ends (one comment line: no frames, silently); a ``--jobs 2`` pool interrupted."""
    for kind, name, said in (("room", "kid's room", r"holds \"'\", which a plan cannot name"),
                             ("room", "hall: 2", r"holds ':', which a plan cannot name"),
                             ("room", "2nd floor", r"starts with a digit, which a plan cannot name"),
                             ("person", "Dr. Smith", r"holds '\.', which a plan cannot name"),
                             ("person", "R&D", r"holds '&', which a plan cannot name")):
        rooms = "  - {name: hall, box: [0, 0, 10, 10]}\n"
        entry = f'  - {{name: "{name}", ' + ("box: [0, 0, 10, 10]}\n" if kind == "room" else "at: [5, 5]}\n")
        text = (f"name: m\nbounds: [0, 0, 10, 10]\nrooms:\n{entry if kind == 'room' else rooms}" +
                ("" if kind == "room" else f"people:\n{entry}"))
        line = 4 if kind == "room" else 6
        for argv in (("validate", "m.yaml"), ("run", f"go to the {name}", "--map", "m.yaml")):
            yield Case(f"A {argv[0]} of a {kind} called {name!r}", argv, (("m.yaml", text.encode()),), codes=(1,),
                       keep=("m.yaml",), says=rf"m\.yaml:{line}:\d+: {kind} name .*{said}")
    for text, said in (("bring me a hundred and one apples", r"'a hundred and one apples' asks for 101 things"),
                       ("put two hundred and fifty cups in the sink", r"asks for 250 things"),
                       ("bring me zero apples", r"column 10: 'zero apples' asks for no things"),
                       ("put 0 cups in the sink", r"column 5: '0 cups' asks for no things")):
        yield Case(f"A plan of {text!r}", ("plan", text, "--map", "apartment"), codes=(1,), says=said)
    zap = ('// zapping\nframe Zap "zap" {\n  theme: object\n  do navigate(theme)\n  ensures zapped(theme)\n}\n')
    for end, shown in (("\r", "CR"), ("\r\n", "CRLF")):
        yield Case(f"A plan with a .frame file of {shown} lines", ("plan", "zap the cup", "--framelib", "+z.frame"),
                   (("z.frame", zap.replace("\n", end).encode()),), codes=(0,), keep=("z.frame",),
                   says=r"Zap\s+theme=cup")
        broken = zap.replace("zapped(theme)", "zapped(theme").replace("\n", end)
        yield Case(f"A validate of a broken .frame file of {shown} lines", ("validate", "z.frame"),
                   (("z.frame", broken.encode()),), codes=(1,), keep=("z.frame",),
                   says=r"z\.frame:6:1: syntax error: unexpected '\}'")
    yield Case("A bench tasks --suite map --jobs 2 interrupted", ("bench", "tasks", "--suite", "map", "--map",
                                                                  "apartment", "--layouts", "4", "--jobs", "2",
                                                                  "--policies", "sefm,coverage"),
               codes=(0, 130), signal=(2, 5.0), says=r"interrupted")
    for argv, said in ((("validate", "-"), r"-: no such file or folder: - \('-' is standard input only to seal parse"),
                       (("map", "-"), r"-: no such map file \('-' is standard input only to seal parse")):
        yield Case(f"A {argv[0]} - with a map on standard input", argv, codes=(1,), stdin=b"name: m\n", says=said)


def hostile23_cases() -> Iterator[Case]:
    """Round hostile23: ``--jobs 2`` pools ended from outside (a worker killed as the out-of-memory killer does,
    the command terminated or hung up), ``localize --goals`` stopped by each signal, rooms and people named in
    other scripts (end to end), problems of a name said at the name, outputs onto inputs through a link or by name,
    a map nested deeper than any reader's stack."""
    suite = ("bench", "tasks", "--suite", "map", "--map", "apartment", "--layouts", "4", "--jobs", "2", "--policies",
             "sefm,coverage")
    yield Case("A bench tasks --suite map --jobs 2: a worker killed (SIGKILL)", suite, codes=(1,), to_worker=True,
               signal=(9, 3.0), says=r"a worker process ended abruptly \(killed by a signal, or out of memory\?\)")
    for number, code in ((15, 143), (1, 129)):
        yield Case(f"A bench tasks --suite map --jobs 2: signal {number} to the command", suite,
                   codes=(code, -number), signal=(number, 5.0))
    rooms = ("name: m\nbounds: [0, 0, 10, 10]\nrooms:\n  - {{name: \"{room}\", box: [0, 0, 5, 10]}}\n"
             "  - {{name: hall, box: [5, 0, 10, 10]}}\npeople:\n  - {{name: Ахмед, at: [7, 5]}}\n")
    for room, said in (("кухня", "кухня"), ("σαλόνι", "Σαλόνι"), ("厨房", "厨房")):
        text = rooms.format(room=room).encode()
        yield Case(f"A run to a room called {room}", ("run", f"go to the {said}", "--map", "m.yaml", "--particles",
                                                      "20"), (("m.yaml", text),), codes=(0,), keep=("m.yaml",),
                   says=rf"done: Go\(goal={room}\)")
    yield Case("A plan of a cup for a person called Ахмед", ("plan", "bring the cup to Ахмед", "--map", "m.yaml"),
               (("m.yaml", rooms.format(room="кухня").encode()),), codes=(0,), says=r"recipient=ахмед")
    for kind, entry, line, column in (("room", '  - {name: "kid\'s room", box: [0, 0, 10, 10]}\n', 4, 12),
                                      ("person", '  - {at: [5, 5], name: "Dr. Smith"}\n', 6, 24)):
        listed = "name: m\nbounds: [0, 0, 10, 10]\nrooms:\n" + (entry if kind == "room" else
                                                             "  - {name: hall, box: [0, 0, 10, 10]}\npeople:\n" + entry)
        yield Case(f"A validate of a {kind} name no plan can name: said at the name", ("validate", "m.yaml"),
                   (("m.yaml", listed.encode()),), codes=(1,), keep=("m.yaml",),
                   says=rf"m\.yaml:{line}:{column}: {kind} name")
    small = rooms.format(room="kitchen").encode()
    goals = ("localize", "--map", "m.yaml", "--task", "go to the kitchen", "--particles", "20")
    yield Case("A localize --goals onto the map through a symbolic link", (*goals, "--goals", "l.yaml"),
               (("m.yaml", small), ("l.yaml", "link:m.yaml")), codes=(1,), keep=("m.yaml",),
               says=r"l\.yaml.*(would overwrite|is the input|input)")
    yield Case("A map --png onto the map itself", ("map", "m.yaml", "--png", "m.yaml"), (("m.yaml", small),),
               codes=(1,), keep=("m.yaml",), says=r"--png")
    for number, code in ((15, 143), (1, 129)):
        yield Case(f"A signal {number} during localize --goals", (*goals, "--steps", "100000", "--goals", "g.yaml"),
                   (("m.yaml", small),), codes=(code, -number), keep=("m.yaml",), absent=("g.yaml",),
                   signal=(number, 5.0))
    deep = b"name: m\nbounds: " + b"[" * 100_000 + b"]" * 100_000 + b"\n"
    yield Case("A a map nested 100,000 lists deep", ("validate", "m.yaml"), (("m.yaml", deep),), codes=(1,),
               keep=("m.yaml",), says=r"m\.yaml")



def split_house() -> tuple[bytes, str]:
    """A 10 m × 10 m house at 0.1 m whose free space a wall at x = 5 m splits into two islands (west, east), and the
    head of its map file (its image, rooms and the robot in the west): what hostile24's reach cases start from."""
    cells = np.full((100, 100), 254, dtype=np.uint8)
    cells[:, [0, 50, 99]] = 0
    cells[[0, 99], :] = 0
    head = ("image: s.pgm\nresolution: 0.1\norigin: [0, 0, 0]\nname: m\nrobot: {pose: [1, 1, 0]}\nrooms:\n"
            "  - {name: west, box: [0, 0, 5, 10]}\n  - {name: east, box: [5, 0, 10, 10]}\n")
    return b"P5\n100 100\n255\n" + cells.tobytes(), head


def hostile24_cases() -> Iterator[Case]:  # noqa: PLR0915 - one list of cases, read top to bottom
    """Round hostile24: the nearest of several places by path (e2e25's ``maps/reach.py``) on a house split into
    islands, places out of reach; degenerate grids (1 × 1, 20,000 × 20,000 declared, a resolution of 0 or NaN, an
    origin at infinity); room names with control characters, line separators, combining marks only, typed
    decomposed, in scripts whose letters take combining vowel signs; 1,000 ``--done`` commands; a place's ``open``
    of the wrong type; an alias bomb; outputs onto the image through a link, past ``ulimit -f``, signalled while
    their temporary is being written, written by two runs at once."""
    image, head = split_house()
    beds = head + ("places:\n  - {name: bed_1, class: bed, at: [8, 2]}\n  - {name: bed_2, class: bed, at: [3, 8]}\n"
                   "  - {name: bed_3, class: bed, at: [9, 9]}\n")
    far = head + "places:\n  - {name: bed_1, class: bed, at: [8, 2]}\n  - {name: bed_2, class: bed, at: [7, 8]}\n"
    yield Case("A plan to the bed on a house split by a wall: the nearest by path", ("plan", "go to the bed", "--map",
                                                                                   "m.yaml"),
               (("m.yaml", beds.encode()), ("s.pgm", image)), codes=(0,), keep=("m.yaml", "s.pgm"),
               says=r"chose bed_2, the nearest the robot drives to from where it starts \(\d")
    yield Case("A plan to the bed when no bed can be reached", ("plan", "go to the bed", "--map", "m.yaml"),
               (("m.yaml", far.encode()), ("s.pgm", image)), codes=(0,), keep=("m.yaml", "s.pgm"),
               says=r"^(?![\s\S]*inf m)[\s\S]*'the bed' could be bed_1 \(east\) or bed_2 \(east\): the robot can reach "
                    r"none of them from where it starts")
    yield Case("A run to a bed on the other island", ("run", "go to bed_1", "--map", "m.yaml", "--particles", "20"),
               (("m.yaml", far.encode()), ("s.pgm", image)), codes=(1,), keep=("m.yaml", "s.pgm"),
               says=r"not done: bed_1 cannot be reached from anywhere the robot can drive — 0\.00 m driven")
    yield Case("A run to a room on the other island", ("run", "go to the east", "--map", "m.yaml", "--particles", "20"),
               (("m.yaml", far.encode()), ("s.pgm", image)), codes=(1,), keep=("m.yaml", "s.pgm"),
               says=r"not done: cannot drive into east")
    # -- degenerate grids ------------------------------------------------------------------------------------------
    one = (b"image: o.pgm\nresolution: 0.05\norigin: [0, 0, 0]\nrooms:\n  - {name: hall, box: [0, 0, 0.05, 0.05]}\n"
           b"places:\n  - {name: bed_1, class: bed, at: [0.02, 0.02]}\n")
    yield Case("A run on a map of one free cell", ("run", "go to the bed", "--map", "m.yaml", "--particles", "20"),
               (("m.yaml", one), ("o.pgm", b"P5\n1 1\n255\n\xfe")), codes=(0,), keep=("m.yaml", "o.pgm"),
               says=r"done: Go\(goal=bed_1\)")
    yield Case("A run on a map of one occupied cell", ("run", "go to the bed", "--map", "m.yaml"),
               (("m.yaml", one), ("o.pgm", b"P5\n1 1\n255\n\x00")), codes=(1,), keep=("m.yaml", "o.pgm"),
               says=r"m\.yaml.*(no free space|outside|occupied)")
    grid = b"image: g.pgm\nresolution: 0.05\norigin: [0, 0, 0]\n"
    for what, text, said in (
            ("an image declared 20,000 × 20,000", grid, r"m\.yaml:1:8: the image is 20,000×20,000 pixels"),
            ("a resolution of 0", grid.replace(b"0.05", b"0"), r"m\.yaml:2:13: "),
            ("a resolution of NaN", grid.replace(b"0.05", b".nan"), r"m\.yaml:2:13: "),
            ("an origin at infinity", grid.replace(b"[0, 0", b"[.inf, 0"), r"m\.yaml:3:10: ")):
        yield Case(f"A validate of {what}", ("validate", "m.yaml"),
                   (("m.yaml", text), ("g.pgm", b"P5\n20000 20000\n255\n" + b"\xfe" * 4096)), codes=(1,),
                   keep=("m.yaml", "g.pgm"), says=said, timeout=30)
    # -- room names ------------------------------------------------------------------------------------------------
    named = 'name: m\nbounds: [0, 0, 10, 10]\nrooms:\n  - {{name: "{room}", box: [0, 0, 5, 10]}}\n' \
            '  - {{name: lounge, box: [5, 0, 10, 10]}}\nrobot: {{pose: [7, 5, 0]}}\n'
    for room, said in (("ha\\tll", r"'\\t'"), ("hall\\x85", r"'\\x85'"), ("hall\\u2028", r"'\\u2028'"),
                       ("\\u0301\\u0301", r"no letter")):
        yield Case(f"A validate of a room called {room}", ("validate", "m.yaml"),
                   (("m.yaml", named.format(room=room).encode()),), codes=(1,), keep=("m.yaml",),
                   says=rf"m\.yaml:4:12: room name .*{said}")
    for room, command, goal in (("cafe\u0301", "go to the café", "café"), ("रसोई", "go to the रसोई", "रसोई"),
                                ("ครัว", "go to the ครัว", "ครัว"), ("İstanbul", "go to the İstanbul", "i̇stanbul"),
                                ("ha\u0336l\u0336l", "go to the ha\u0336l\u0336l", "ha\u0336l\u0336l")):
        yield Case(f"A run to a room called {room.encode('unicode_escape').decode()}",
                   ("run", command, "--map", "m.yaml", "--particles", "20"),
                   (("m.yaml", named.format(room=room).encode()),), codes=(0,), keep=("m.yaml",),
                   says=rf"done: Go\(goal={goal}\)")
    # -- --done, open, aliases -------------------------------------------------------------------------------------
    done = tuple(a for _ in range(1_000) for a in ("--done", "go to the kitchen"))
    for argv in (("plan", "bring me the cup", "--map", "apartment"),
                 ("run", "bring me the cup", "--map", "apartment", "--particles", "20")):
        yield Case(f"A {argv[0]} with 1,000 --done commands", (*argv, *done), codes=(0,), says=r"Bring")
    fridge = "name: m\nbounds: [0, 0, 10, 10]\nplaces:\n  - {{name: fridge_1, class: fridge, at: [5, 5], openable: " \
             "true, open: {value}}}\n"
    for value, shown in (("[true]", "a list"), ("{a: 1}", "a mapping")):
        yield Case(f"A validate of a fridge whose open is {shown}", ("validate", "m.yaml"),
                   (("m.yaml", fridge.format(value=value).encode()),), codes=(1,), keep=("m.yaml",),
                   says=rf"m\.yaml:4:71: open must be true or false, not {shown}\n")
    laughs = ['a0: &a0 ["lol", "lol", "lol", "lol", "lol", "lol", "lol", "lol", "lol", "lol"]',
              *(f"a{i}: &a{i} [" + ", ".join([f"*a{i - 1}"] * 10) + "]" for i in range(1, 10))]
    bomb = "name: m\nbounds: [0, 0, 10, 10]\nlaughs:\n" + "".join(f"  {line}\n" for line in laughs) + "rooms: *a9\n"
    yield Case("A run on a map of a billion laughs", ("run", "go to the hall", "--map", "m.yaml"),
               (("m.yaml", bomb.encode()),), codes=(1,), keep=("m.yaml",), timeout=30,
               says=r"m\.yaml(:\d+:\d+)?: this file holds more than 1,000,000 values once its aliases")
    # -- outputs ---------------------------------------------------------------------------------------------------
    m, apartment, _, both, inputs, _, _ = hostile_setting()
    run = ("run", "go to the kitchen", "--map", "m.yaml", "--particles", "20")
    yield Case("A run --png onto the map's image through a link", (*run, "--png", "l.png"),
               (*both, ("l.png", "link:apartment.pgm")), codes=(1,), keep=inputs,
               says=r"--png l\.png would overwrite the input apartment\.pgm")
    yield Case("A run --png --rrd past ulimit -f of 4 KiB", (*run, "--png", "o.png", "--rrd", "o.rrd"), both,
               codes=(1,), keep=inputs, file_blocks=8, absent=("o.png", "o.rrd"),
               says=r"error: cannot write --(png o\.png|rrd o\.rrd)")
    for number, code in ((15, 143), (2, 130)):
        yield Case(f"A signal {number} while run --png --rrd writes its temporary",
                   (*run, "--png", "o.png", "--rrd", "o.rrd"), both, codes=(code, -number), keep=inputs,
                   absent=("o.png", "o.rrd"), signal=(number, 0.0), signal_on=r"\.seal\d+-[0-9a-f]{8}\.tmp")
    yield Case("A two run --png --rrd at once onto the same files", (*run, "--png", "o.png", "--rrd", "o.rrd"), both,
               codes=(0,), keep=inputs, parallel=2, whole=("o.png", "o.rrd"), says=r"done: Go\(goal=kitchen\)")


def _areas(rooms: str, places: str = "", robot: str = "[8, 2, 0]") -> bytes:
    """A 10 m × 10 m open-plan map without an image (all free, no walls), its areas told apart only by their outlines
    (as the studio's), each ``rooms`` line one area."""
    return (f"name: m\nbounds: [0, 0, 10, 10]\nrooms:\n{rooms}" + (f"places:\n{places}" if places else "")
            + f"robot: {{pose: {robot}}}\n").encode()


def hostile25_cases() -> Iterator[Case]:  # noqa: PLR0915 - one list of cases, read top to bottom
    """Round hostile25: areas without walls (overlapping, self-intersecting, of no area, outside the map, a place in
    two); "put it back" and pronouns with nothing before them, after 1,000 ``--done``; clock times out of range;
    goals and grounds a map does not know; outputs onto a folder, a named pipe, ``/dev/full``; map YAML with a
    repeated key, a line of 4 MB, a NUL, a BOM and CRLF; frame libraries with a precondition cycle or a unit claimed
    twice; a junk environment (no HOME, LANG=C, a read-only working folder, SIGHUP ignored as ``nohup`` leaves it);
    the picture and recording of a run that ends not done."""
    two = "  - {name: west, box: [0, 0, 6, 10]}\n  - {name: east, box: [4, 0, 10, 10]}\n"
    sofa = "  - {name: sofa_1, class: sofa, at: [5, 5]}\n"
    # -- areas without walls ---------------------------------------------------------------------------------------
    yield Case("A validate of two areas that overlap", ("validate", "m.yaml"), (("m.yaml", _areas(two)),),
               codes=(1,), keep=("m.yaml",),
               says=r"m\.yaml:5:5: room east overlaps room west \(line 4\) by about 20\.00 m²")
    yield Case("A plan on areas that overlap says so", ("plan", "go to west", "--map", "m.yaml"),
               (("m.yaml", _areas(two)),), codes=(0,), keep=("m.yaml",),
               says=r"warning: m\.yaml:5:5: room east overlaps room west")
    yield Case("A plan to a place in two areas, by the second",
               ("plan", "go to the sofa in east", "--map", "m.yaml"), (("m.yaml", _areas(two, sofa)),), codes=(0,),
               keep=("m.yaml",), says=r"Go +goal=sofa_1")
    yield Case("A run to a place in two areas, by the first", ("run", "go to the sofa in west", "--map", "m.yaml",
                                                                "--particles", "20"),
               (("m.yaml", _areas(two, sofa)),), codes=(0,), keep=("m.yaml",), says=r"done: Go\(goal=sofa_1\)")
    bow = "  - {name: a, polygon: [[0, 0], [10, 10], [10, 0], [0, 10]]}\n"
    yield Case("A run on an area drawn as a bow tie", ("run", "go to a", "--map", "m.yaml", "--particles", "20"),
               (("m.yaml", _areas(bow)),), codes=(1,), keep=("m.yaml",),
               says=r"m\.yaml:4:15: room a intersects itself: edge 1 \(\[0, 0\]–\[10, 10\]\) meets edge 3")
    flat = "  - {name: a, box: [0, 0, 10, 10]}\n  - {name: b, polygon: [[1, 1], [2, 2], [3, 3]]}\n"
    yield Case("A plan on an area of no area", ("plan", "go to b", "--map", "m.yaml"), (("m.yaml", _areas(flat)),),
               codes=(1,), keep=("m.yaml",), says=r"m\.yaml:5:15: room b (has no area|intersects itself)")
    far = "  - {name: a, box: [0, 0, 10, 10]}\n  - {name: b, box: [20, 20, 30, 30]}\n"
    yield Case("A run to an area outside the map", ("run", "go to b", "--map", "m.yaml", "--particles", "20"),
               (("m.yaml", _areas(far)),), codes=(1,), keep=("m.yaml",),
               says=r"m\.yaml:5:5: room b \(\[20, 20\]–\[30, 30\]\) is wholly outside the map's bounds")
    # -- pronouns with nothing before them -------------------------------------------------------------------------
    yield Case("A plan to put it back with nothing taken", ("plan", "put it back", "--map", "studio"), codes=(1,),
               says=r"error: column 5: cannot tell what 'it' refers to")
    done = tuple(a for _ in range(1_000) for a in ("--done", "go to the sofa"))
    yield Case("A plan to return it after 1,000 --done", ("plan", "return it", "--map", "studio", *done), codes=(1,),
               says=r"error: column 8: cannot tell what 'it' refers to")
    yield Case("A plan to give it to her after --done naming nobody",
               ("plan", "give the mug to her", "--map", "studio", "--done", "go to the sofa"), codes=(1,),
               says=r"error: column 17: cannot tell who 'her' is")
    # -- clock times -----------------------------------------------------------------------------------------------
    for time in ("99:99", "25:00", "5:60", "5:30:10", "5.5.5"):
        yield Case(f"A plan to bring a mug at {time}", ("plan", f"bring me a mug at {time}", "--map", "studio"),
                   codes=(0, 1), says=r"error: column \d+: |Bring +theme=mug")
    # -- goals and grounds the map does not know -------------------------------------------------------------------
    yield Case("A plan onto a table of a map without places", ("plan", "put the mug on the table", "--map", "m.yaml"),
               (("m.yaml", b"name: m\nbounds: [0, 0, 10, 10]\nobjects:\n  - {class: mug, at: [2, 2]}\n"),),
               codes=(1,), keep=("m.yaml",), says=r"error: column 16: the m has no table")
    yield Case("A run searching a room the studio lacks", ("run", "look for the mug in the garage", "--map",
                                                           "studio", "--particles", "20"),
               codes=(1,), says=r"error: column 21: the studio has no garage")
    # -- outputs ---------------------------------------------------------------------------------------------------
    run = ("run", "go to the sofa", "--map", "studio", "--particles", "20")
    yield Case("A run --rrd onto a folder", (*run, "--rrd", "d.rrd"), (("d.rrd", "dir"),), codes=(1,),
               says=r"--rrd d\.rrd: it is a folder")
    yield Case("A run --png onto a named pipe nobody reads", (*run, "--png", "p.png"), (("p.png", "fifo"),),
               codes=(1,), says=r"--png p\.png: it is a named pipe", timeout=30)
    yield Case("A run --png --rrd onto /dev/full", (*run, "--png", "/dev/full", "--rrd", "o.rrd"), codes=(1,),
               absent=("o.rrd",), says=r"cannot write --png /dev/full: No space left on device")
    for argv, said in ((("localize", "--map", "studio", "--steps", "3", "--particles", "20", "--rrd", "o.rrd"),
                        "localize"), ((*run, "--rrd", "o.rrd"), "run")):  # found while fixing: not in the gold
        yield Case(f"A {said} --rrd past ulimit -f of 4 KiB says the file is too large", argv, codes=(1,),
                   file_blocks=8, absent=("o.rrd",), says=r"error: cannot write --rrd o\.rrd: File too large")
    # -- map YAML --------------------------------------------------------------------------------------------------
    yield Case("A run on a map whose area repeats its name key", ("run", "go to a", "--map", "m.yaml"),
               (("m.yaml", _areas("  - {name: a, name: b, box: [0, 0, 10, 10]}\n")),), codes=(1,), keep=("m.yaml",),
               says=r"m\.yaml:4:15: .*repeats the key 'name'")
    yield Case("A validate of a map with a line of 4 MB", ("validate", "m.yaml"),
               (("m.yaml", _areas(two).replace(b"rooms:", b"# " + b"x" * 4_000_000 + b"\nrooms:")),), codes=(1,),
               keep=("m.yaml",), says=r"m\.yaml:6:5: room east overlaps", timeout=30)
    yield Case("A run on a map with a NUL in an area's name", ("run", "go to a", "--map", "m.yaml"),
               (("m.yaml", _areas("  - {name: \"a\x00\", box: [0, 0, 10, 10]}\n")),), codes=(1,), keep=("m.yaml",),
               says=r"m\.yaml:4:14: YAML does not allow the control character '\\x00'")
    yield Case("A run on a map with a BOM and CRLF", ("run", "go to the sofa", "--map", "m.yaml", "--particles", "20"),
               (("m.yaml", b"\xef\xbb\xbf" + _areas(two, sofa).replace(b"\n", b"\r\n")),), codes=(0,),
               keep=("m.yaml",), says=r"warning: m\.yaml:5:5: room east overlaps")
    # -- frame libraries -------------------------------------------------------------------------------------------
    cycle = FRAME.replace("requires holding(instrument)", "requires beaten(theme)") + '''frame Beat "batter" {
  theme: container
  instrument: utensil = spoon
  requires whisked(theme)
  do stir(instrument, theme)
  ensures beaten(theme)
}
'''
    yield Case("A plan on a library whose preconditions make a cycle",
               ("plan", "whisk the cup", "--framelib", "c.frame"), (("c.frame", cycle.encode()),),
               codes=(1,), keep=("c.frame",), says=r"c\.frame:\d+:\d+: .*cycle")
    twice = FRAME + FRAME[FRAME.index("frame Whisk"):].replace("frame Whisk", "frame Beat").replace('"beat"', '"mix"')
    yield Case("A plan on a library whose unit two frames claim", ("plan", "whisk the cup", "--framelib", "t.frame"),
               (("t.frame", twice.encode()),), codes=(1,), keep=("t.frame",),
               says=r"t\.frame:\d+:\d+: lexical unit 'whisk' of Beat is also claimed by Whisk")
    # -- the environment -------------------------------------------------------------------------------------------
    yield Case("A run --png with HOME unset", (*run, "--png", "o.png"), codes=(0,), env=(("HOME", "<unset>"),),
               whole=("o.png",), says=r"done: Go\(goal=sofa_1\)")
    yield Case("A run to the café with LANG=C", ("run", "go to the café", "--map", "m.yaml", "--particles", "20"),
               (("m.yaml", _areas("  - {name: café, box: [0, 0, 10, 10]}\n")),), codes=(0,), keep=("m.yaml",),
               env=(("LANG", "C"), ("LC_ALL", "C"), ("PYTHONUTF8", "0"), ("PYTHONIOENCODING", "<unset>")),
               says=r"done: Go\(goal=caf(é|\\xe9)\)")
    yield Case("A run in a read-only working folder", ("run", "go to the sofa", "--map", "studio", "--particles", "20"),
               (("ro", "ro-dir"),), codes=(0,), cwd="ro", says=r"done: Go\(goal=sofa_1\)")
    yield Case("A run --png under nohup, sent SIGHUP", (*run, "--png", "o.png"), codes=(0,), ignored=(1,),
               signal=(1, 0.0), signal_on=r"\.seal\d+-[0-9a-f]{8}\.tmp", whole=("o.png",),
               says=r"done: Go\(goal=sofa_1\)")
    # -- a run that ends not done ----------------------------------------------------------------------------------
    yield Case("A run not done still draws its whole picture", ("run", "find the unicorn", "--map", "bungalow",
                                                                 "--particles", "20", "--png", "o.png", "--rrd",
                                                                 "o.rrd"),    # a Find: a Bring of a thing the
               codes=(1,), whole=("o.png", "o.rrd"),                           # house lacks is refused (e2e27)
               says=r"not done: no unicorn found[^\n]*\n[^\n]*o\.png[^\n]*o\.rrd")


def _laughs(anchor: str, depth: int = 9) -> str:
    """``depth`` lines of a YAML "billion laughs" inside a sequence (``- &l0 [...]``, each line ten aliases of the
    one before): 10**depth values once expanded, from about a kilobyte."""
    lines = [f"  - &{anchor}0 [{', '.join(['lol'] * 10)}]\n"]
    lines += [f"  - &{anchor}{i} [{', '.join([f'*{anchor}{i - 1}'] * 10)}]\n" for i in range(1, depth)]
    return "".join(lines)


def _many_places(count: int) -> bytes:
    """A 100 m × 100 m map without an image holding ``count`` tables in one room (about 50 bytes a place)."""
    places = "".join(f"  - {{name: t{i}, class: table, at: [{1 + i % 98}.5, {1 + i // 98 % 98}.5]}}\n"
                     for i in range(count))
    return f"name: m\nbounds: [0, 0, 100, 100]\nrooms:\n  - {{name: hall, box: [0, 0, 100, 100]}}\nplaces:\n{places}" \
        .encode()


def _many_rooms(side: int) -> bytes:
    """A map without an image of ``side`` × ``side`` rooms of 1 m × 1 m side by side."""
    rooms = "".join(f"  - {{name: r{x}_{y}, box: [{x}, {y}, {x + 1}, {y + 1}]}}\n"
                    for x in range(side) for y in range(side))
    return f"name: m\nbounds: [0, 0, {side}, {side}]\nrooms:\n{rooms}".encode()


def hostile26_cases() -> Iterator[Case]:  # noqa: PLR0915 - one list of cases, read top to bottom
    """Round hostile26: the corner shop's two of a kind ("put the milk back" with a milk in each fridge), "take it
    back" / "bring it back" with nothing taken, things a map knows only by a prior, by a prior over a room it lacks,
    or by a misspelt class; outputs whose folder vanishes while they are written, onto the map itself or one another,
    named with spaces, a newline and emoji, through a link to the map, written by four runs at once; maps of 200,000
    places and 40,000 rooms; YAML "billion laughs" in a map and a frame library, block nesting 20,000 deep; a frame
    file with a line of 10 MB; ``--done`` texts of bytes that are not UTF-8 and of control characters."""
    run = ("run", "go to the sofa", "--map", "studio", "--particles", "20")
    shop = ("--map", "corner_shop")
    # -- the corner shop: two of a kind ----------------------------------------------------------------------------
    yield Case("A plan to put the milk back when each fridge holds one", ("plan", "put the milk back", *shop),
               codes=(0,), says=r"\A(?![\s\S]*Pick)[\s\S]*in\(milk, fridge_\d\), hand_empty holds already")
    yield Case("A plan to take the milk and put it back puts it where it was",
               ("plan", "take the milk and put it back", *shop), codes=(0,),
               says=r"Place +theme=milk, goal=(fridge_\d)[\s\S]*state: [^\n]*in\(milk, \1\)")
    yield Case("A run to put back the milk it holds, two fridges", ("run", "put it back", *shop, "--holding", "milk",
                                                                  "--particles", "20"),
               codes=(0,), says=r"done: Place\(theme=milk, goal=fridge_\d\)")
    yield Case("A plan to take it back with nothing taken", ("plan", "take it back", *shop), codes=(1,),
               says=r"error: column 6: cannot tell what 'it' refers to")
    yield Case("A plan to bring it back after --done naming a place", ("plan", "bring it back", *shop, "--done",
                                                                       "go to the counter"),
               codes=(1,), says=r"error: column 7: ")
    yield Case("A run to take it back with nothing taken writes no picture",
               ("run", "take it back", *shop, "--particles", "20", "--png", "o.png"), codes=(1,), absent=("o.png",),
               says=r"error: column 6: cannot tell what 'it' refers to")
    # -- things a map knows only by a prior, by a prior over no room, by a misspelt class --------------------------
    base = "name: m\nbounds: [0, 0, 10, 10]\nrooms:\n  - {name: kitchen, box: [0, 0, 10, 10]}\n" \
           "places:\n  - {name: table_1, class: table, at: [5, 5]}\n"
    prior_only = (base + "priors:\n  umbrella: {table: 0.9}\n").encode()
    yield Case("A plan to bring a thing the map knows only by a prior", ("plan", "bring me the umbrella", "--map",
                                                                         "m.yaml"),
               (("m.yaml", prior_only),), codes=(0,), keep=("m.yaml",), says=r"Bring +theme=umbrella")
    yield Case("A run to bring a thing the map knows only by a prior, not there",
               ("run", "bring me the umbrella", "--map", "m.yaml", "--particles", "20"), (("m.yaml", prior_only),),
               codes=(1,), keep=("m.yaml",), says=r"not done: no umbrella found")
    no_room = (base + "priors:\n  mug: {garage: 0.9}\n").encode()
    yield Case("A plan on a map whose prior names a room it lacks", ("plan", "bring me the mug", "--map", "m.yaml"),
               (("m.yaml", no_room),), codes=(1,), keep=("m.yaml",),
               says=r"m\.yaml:8:9: prior of mug names 'garage', which is no room")
    yield Case("A run --png on a map whose prior names a room it lacks",
               ("run", "find the mug", "--map", "m.yaml", "--particles", "20", "--png", "o.png"),
               (("m.yaml", no_room),), codes=(1,), keep=("m.yaml",), absent=("o.png",), says=r"m\.yaml:8:9: ")
    typo = (base + "objects:\n  - {class: mgu, at: [5, 5], in: table_1}\n").encode()
    yield Case("A plan to bring a thing whose class the map misspells", ("plan", "bring me the mug", "--map", "m.yaml"),
               (("m.yaml", typo),), codes=(1,), keep=("m.yaml",), says=r"error: column 10: [^\n]*\bmgu\b")
    typo_prior = (base + "priors:\n  mgu: {table: 0.9}\n").encode()
    yield Case("A run to find a thing whose prior the map misspells",
               ("run", "find the mug", "--map", "m.yaml", "--particles", "20"), (("m.yaml", typo_prior),),
               codes=(1,), keep=("m.yaml",), says=r"\bmgu\b")
    # -- outputs ---------------------------------------------------------------------------------------------------
    temporary = r"\.seal\d+-[0-9a-f]{8}\.tmp"
    yield Case("A localize --rrd whose folder vanishes while it writes",
               ("localize", "--map", "studio", "--steps", "20", "--particles", "200", "--rrd", "d/o.rrd"),
               (("d", "dir"),), codes=(1,), vanish=("d", temporary), absent=("d/o.rrd",),
               says=r"error: cannot write --rrd d/o\.rrd: [^\n]*(No such file or directory|folder)")
    yield Case("A run --rrd whose folder vanishes while it writes", (*run, "--rrd", "d/o.rrd"), (("d", "dir"),),
               codes=(1,), vanish=("d", temporary), absent=("d/o.rrd",),
               says=r"error: cannot write --rrd d/o\.rrd: [^\n]*(No such file or directory|folder)")
    yield Case("A run --png whose folder vanishes while it writes", (*run, "--png", "d/o.png"), (("d", "dir"),),
               codes=(1,), vanish=("d", temporary), absent=("d/o.png",),
               says=r"error: cannot write --png d/o\.png: [^\n]*(No such file or directory|folder)")
    mine = (("m.yaml", _areas("  - {name: a, box: [0, 0, 10, 10]}\n")),)
    mine_run = ("run", "go to a", "--map", "m.yaml", "--particles", "20")
    yield Case("A run --png onto its map file", (*mine_run, "--png", "m.yaml"), mine, codes=(1,), keep=("m.yaml",),
               says=r"--png m\.yaml")
    yield Case("A run --png onto a link to its map", (*mine_run, "--png", "l.png"), (*mine, ("l.png", "link:m.yaml")),
               codes=(1,), keep=("m.yaml",), says=r"--png l\.png would overwrite the input m\.yaml")
    yield Case("A run --rrd onto its --png", (*mine_run, "--png", "o.png", "--rrd", "o.png"), mine, codes=(1,),
               keep=("m.yaml",), absent=("o.png",), says=r"--rrd o\.png")
    odd = "a b\nç😀.png"
    yield Case("A run --png named with a space, a newline and emoji", (*run, "--png", odd), codes=(0,), whole=(odd,),
               says=r"done: Go\(goal=sofa_1\)")
    yield Case("A run --rrd with a newline in a wrong suffix", (*run, "--rrd", "x\ny.png"), codes=(1,),
               absent=("x\ny.png",), says=r"--rrd [^\n]*x\\ny\.png")
    yield Case("Four runs --png onto one file at once", (*run, "--png", "o.png"), codes=(0,), parallel=4,
               whole=("o.png",), says=r"done: Go\(goal=sofa_1\)")
    yield Case("Three localize --rrd onto one file at once", ("localize", "--map", "studio", "--steps", "3",
                                                              "--particles", "20", "--rrd", "o.rrd"),
               codes=(0,), parallel=3, whole=("o.rrd",), says=r"(?s).")
    # -- sizes -----------------------------------------------------------------------------------------------------
    yield Case("A run on a map of 200,000 places", ("run", "go to the hall", "--map", "m.yaml", "--particles", "20"),
               (("m.yaml", _many_places(200_000)),), codes=(0, 1), keep=("m.yaml",), says=r"m\.yaml")
    yield Case("A validate of a map of 40,000 rooms", ("validate", "m.yaml"), (("m.yaml", _many_rooms(200)),),
               codes=(0, 1), keep=("m.yaml",), says=r"m\.yaml")
    # -- YAML bombs and nesting ------------------------------------------------------------------------------------
    yield Case("A run on a map whose rooms are a billion laughs", ("run", "go to a", "--map", "m.yaml"),
               (("m.yaml", f"name: m\nbounds: [0, 0, 10, 10]\nrooms:\n{_laughs('r')}".encode()),), codes=(1,),
               keep=("m.yaml",), says=r"m\.yaml:\d+:\d+: ")
    library = FRAME_YAML.replace("  utensil: [spoon, fork]\n", "  utensil: [spoon, fork]\n  laughs:\n"
                                 + _laughs("c").replace("  - ", "    - "))
    yield Case("A plan on a frame library whose category is a billion laughs",
               ("plan", "whisk the cup", "--framelib", "l.yaml"), (("l.yaml", library.encode()),), codes=(1,),
               keep=("l.yaml",), says=r"l\.yaml:\d+:\d+: ")
    yield Case("A validate of a map nested 20,000 deep in block sequences", ("validate", "m.yaml"),
               (("m.yaml", b"name: m\nbounds: [0, 0, 10, 10]\nrooms:\n  " + b"- " * 20_000 + b"a\n"),), codes=(1,),
               keep=("m.yaml",), says=r"m\.yaml:\d+:\d+: ")
    yield Case("A plan on a frame file after a comment of 10 MB", ("plan", "whisk the cup", "--framelib", "f.frame"),
               (("f.frame", b"// " + b"x" * 10_000_000 + b"\n" + FRAME.replace("do navigate", "do do navigate")
                 .encode()),), codes=(1,), keep=("f.frame",), says=r"f\.frame:\d+:\d+: ")
    yield Case("A plan on a frame file with a category of 10 MB on one line",
               ("plan", "whisk the cup", "--framelib", "f.frame"),
               (("f.frame", FRAME.encode() + b"category many = " + ", ".join(f"m{i}" for i in range(1_100_000))
                 .encode() + b"\n"),), codes=(0, 1), keep=("f.frame",), says=r"f\.frame")
    # -- --done texts that are not text ----------------------------------------------------------------------------
    yield Case("A plan with a --done of bytes that are not UTF-8", ("plan", "go to the sofa", "--map", "studio",
                                                                    "--done", "\udcff\udcfe\udc80 the cup"),
               codes=(1,), says=r"--done")
    yield Case("A localize with a --done of control characters", ("localize", "--map", "studio", "--steps", "3",
                                                                  "--particles", "20", "--done", "\x01\x02\x7f\x1b[2J"),
               codes=(1,), says=r"--done")


def _pgm16(width: int, height: int, value: int) -> bytes:
    """A 16-bit binary PGM (maximum 65535, each pixel two bytes, most significant first) of one ``value``, its header
    with a comment between each of its numbers (as netpbm allows)."""
    return f"P5\n# a\n{width} # b\n{height}\n# c\n65535\n".encode() + value.to_bytes(2, "big") * (width * height)


def _two_cycle_files() -> tuple[tuple[str, bytes], tuple[str, bytes]]:
    """Two ``.frame`` files whose frames need each other's postcondition: Whisk (in c.frame) needs ``beaten``, which
    only Beat (in d.frame) ensures, and Beat needs ``whisked``, which only Whisk ensures."""
    whisk = ('category container = cup, bowl\nworld holding, hand_empty\nframe Whisk "whisk" {\n  theme: container\n'
             '  requires beaten(theme)\n  do navigate(theme)\n  ensures whisked(theme)\n}\n')
    beat = ('frame Beat "beat" {\n  theme: container\n  requires whisked(theme)\n  do navigate(theme)\n'
            '  ensures beaten(theme)\n}\n')
    return ("c.frame", whisk.encode()), ("d.frame", beat.encode())


def hostile27_cases() -> Iterator[Case]:  # noqa: PLR0915 - one list of cases, read top to bottom
    """Round hostile27: options given as empty strings (``--holding``, a bag's topics and frames), a map named with a
    NUL or a right-to-left override, ``--goals`` written as a bag (onto a device, onto a file where a bag folder goes,
    hard-linked to the map, through ``..``, by two runs at once, interrupted, a killed run's temporary), commands and
    ``--done`` texts of 60,000 to 100,000 words, a precondition cycle across two frame files, the houseboat's shut
    places, a 16-bit ROS map image, a seed of 2**128 + 1, clocks at the calendar's ends, priors of a thing summing to
    zero."""
    studio = ("--map", "studio")
    loc = ("localize", *studio, "--steps", "1", "--particles", "20")
    task = (*loc, "--task", "go to the sofa")
    # -- options given as empty strings ----------------------------------------------------------------------------
    yield Case("A plan with --holding ''", ("plan", "go to the sofa", *studio, "--holding", ""), codes=(1,),
               says=r"--holding")
    yield Case("A run with --holding ''", ("run", "go to the sofa", *studio, "--holding", "", "--particles", "20"),
               codes=(1,), says=r"--holding")
    yield Case("A localize with --holding ''", (*task, "--holding", ""), codes=(1,), says=r"--holding")
    yield Case("A plan with --done ''", ("plan", "go to the sofa", *studio, "--done", ""), codes=(1,), says=r"--done")
    yield Case("A localize with --task ''", (*loc, "--task", ""), codes=(1,), says=r"--task")
    yield Case("A run with --vocabulary ''", ("run", "go to the sofa", *studio, "--vocabulary", ""), codes=(1,),
               says=r"--vocabulary is empty")
    yield Case("A bench perf with --scale ''", ("bench", "perf", "--scale", ""), codes=(1,), says=r"--scale")
    bag = _sample_bag()
    if bag is not None:
        for option in ("--pose-topic", "--frame", "--base-frame"):
            yield Case(f"A import-bag with {option} ''", ("import-bag", "r.mcap", "-o", "o.yaml", option, ""),
                       (("r.mcap", bag),), codes=(1,), keep=("r.mcap",), absent=("o.yaml",), says=f"{option}\\b")
        yield Case("A localize --bag with --detections-topic ''",
                   ("localize", "--map", "apartment", "--bag", "r.mcap", "--steps", "1", "--particles", "20",
                    "--detections-topic", ""), (("r.mcap", bag),), codes=(1,), keep=("r.mcap",),
                   says=r"--detections-topic\b")
    # -- a map's own name -------------------------------------------------------------------------------------------
    named = "bounds: [0, 0, 10, 10]\nrooms:\n  - {name: hall, box: [0, 0, 10, 10]}\n"
    yield Case("A validate of a map named with a NUL", ("validate", "m.yaml"),
               (("m.yaml", ('name: "m\\0x"\n' + named).encode()),), codes=(1,), keep=("m.yaml",),
               says=r"m\.yaml:1:7: ")
    yield Case("A map --png of a map named with a right-to-left override", ("map", "m.yaml", "--png", "o.png"),
               (("m.yaml", ('name: "m\\u202Eeman"\n' + named).encode()),), codes=(1,), keep=("m.yaml",),
               absent=("o.png",), says=r"m\.yaml:1:7: ")
    # -- --goals written as a bag -----------------------------------------------------------------------------------
    yield Case("A localize --goals onto /dev/full, a bag folder's name", (*task, "--goals", "/dev/full"), codes=(1,),
               says=r"--goals /dev/full")
    yield Case("A localize --goals onto a file where a bag folder goes", (*task, "--goals", "out"),
               (("out", b"a file, not a bag folder\n"),), codes=(1,), keep=("out",), says=r"--goals out\b")
    mine = (("m.yaml", _areas("  - {name: a, box: [0, 0, 10, 10]}\n",
                              "  - {name: sofa_1, class: sofa, at: [5, 5]}\n")),)
    mine_task = ("localize", "--map", "m.yaml", "--steps", "1", "--particles", "20", "--task", "go to the sofa")
    yield Case("A localize --goals as a bag hard-linked to its map", (*mine_task, "--goals", "g.bag"),
               (*mine, ("g.bag", "hard:m.yaml")), codes=(1,), keep=("m.yaml", "g.bag"), says=r"--goals g\.bag")
    yield Case("A localize --goals through .. onto its map", (*mine_task, "--goals", "d/../m.yaml"),
               (*mine, ("d", "dir")), codes=(1,), keep=("m.yaml",), says=r"--goals d/\.\./m\.yaml")
    yield Case("Two localize --goals onto one .mcap at once", (*task, "--goals", "g.mcap"), codes=(0,), parallel=2,
               whole=("g.mcap",), says=r"(?s).")
    yield Case("A SIGINT during localize --goals .mcap", (*task, "--goals", "g.mcap"), codes=(130,),
               absent=("g.mcap",), signal=(2, 0.0), signal_on=r"^\.g\.mcap\.")
    stale = ".g.mcap.seal999999-0123abcd.tmp"
    yield Case("A killed localize's bag temporary is swept", (*task, "--goals", "g.mcap"),
               ((f"{stale}/out/half.mcap", b"half"),), codes=(0,), whole=("g.mcap",), absent=(stale,),
               says=r"(?s).")
    # -- 60,000 to 100,000 words -------------------------------------------------------------------------------------
    yield Case("A parse --file of one line of 100,000 words", ("parse", "--file", "c.txt", "--json"),
               (("c.txt", (" ".join(["cup"] * 100_000) + "\n").encode()),), codes=(0,), keep=("c.txt",), twice=True)
    yield Case("A bench plan --file of one line of 100,000 words",
               ("bench", "plan", "--file", "c.txt", "--repeat", "1"),
               (("c.txt", (" ".join(["go"] * 100_000) + "\n").encode()),), codes=(1,), keep=("c.txt",),
               says=r"c\.txt:1:\d+: command too long")
    yield Case("A run with a --done of 60,000 words", ("run", "go to the sofa", *studio, "--particles", "20",
                                                       "--done", "go to the bed " + " ".join(["a"] * 60_000)),
               codes=(1,), says=r"--done")
    # -- a precondition cycle across two files -----------------------------------------------------------------------
    yield Case("A plan on two frame files whose frames need each other",
               ("plan", "whisk the cup", "--framelib", "c.frame", "--framelib", "d.frame"), _two_cycle_files(),
               codes=(1,), keep=("c.frame", "d.frame"), says=r"[cd]\.frame:\d+:\d+: precondition cycle")
    # -- the houseboat's shut places ---------------------------------------------------------------------------------
    boat = ("--map", "houseboat")
    yield Case("A run to put the mug in the houseboat's shut locker",
               ("run", "put the mug in the locker", *boat, "--particles", "50"), codes=(0,),
               says=r"done: Place\(theme=mug(_2)?, goal=locker_1\)")
    yield Case("A plan on the houseboat: the locker opened, then shut, before taking the rope",
               ("plan", "take the rope out of the locker", *boat, "--done", "open the locker", "--done",
                "close the locker"), codes=(0,), says=r"Open +theme=locker_1")
    yield Case("A run on the houseboat: the fridge said open already, bring me the milk",
               ("run", "bring me the milk", *boat, "--done", "open the fridge", "--particles", "50"), codes=(0,),
               says=r"plan: (?![^\n]*Open\(theme=fridge_1)")
    # -- a ROS map image of 16 bits ----------------------------------------------------------------------------------
    ros = (b"image: m.pgm\nresolution: 0.05\norigin: [0.0, 0.0, 0.0]\nnegate: 0\noccupied_thresh: 0.65\n"
           b"free_thresh: 0.196\n")
    yield Case("A map whose ROS image is a 16-bit PGM with comments in its header", ("map", "m.yaml", "--json"),
               (("m.yaml", ros), ("m.pgm", _pgm16(100, 80, 65535))), codes=(0,), keep=("m.yaml", "m.pgm"))
    # -- numbers at their edges --------------------------------------------------------------------------------------
    yield Case("A run with a seed of 2**128 + 1", ("run", "go to the sofa", *studio, "--particles", "20", "--seed",
                                                   str(2 ** 128 + 1)), codes=(0,), twice=True,
               says=r"done: Go\(goal=sofa_1\)")
    yield Case("A run whose clock reads the last minute of 9999", ("run", "go to the sofa", *studio, "--particles",
                                                                   "20", "--clock", "9999-12-31T23:59"), codes=(0,),
               says=r"done: Go\(goal=sofa_1\)")
    yield Case("A run whose clock reads the year 0", ("run", "go to the sofa", *studio, "--particles", "20", "--clock",
                                                      "0000-01-01T00:00"), codes=(1,), says=r"--clock")
    zero = (b"name: m\nbounds: [0, 0, 10, 10]\nrooms:\n  - {name: kitchen, box: [0, 0, 5, 10]}\n"
            b"  - {name: hall, box: [5, 0, 10, 10]}\npriors:\n  mug: {kitchen: 0, hall: 0.0}\n"
            b"robot: {pose: [1, 1, 0]}\n")
    # masses given, the rest of 1 spread over all free space: masses all 0 are a uniform prior (maps.priors), searched
    yield Case("A run to find a thing whose priors sum to zero", ("run", "find the mug", "--map", "m.yaml",
                                                                  "--particles", "20"),
               (("m.yaml", zero),), codes=(1,), keep=("m.yaml",), says=r"not done: no mug found")


def _long_names() -> bytes:
    """A map whose rooms, places and classes have names of 96 to 100 characters (the most a name may have)."""
    room, thing, person = "w" * 99, "a" * 98, "p" * 100
    return (f"name: m\nbounds: [0, 0, 10, 10]\nrooms:\n  - {{name: {room}, box: [0, 0, 5, 10]}}\n"
            f"  - {{name: b{room}, box: [5, 0, 10, 10]}}\nplaces:\n"
            f"  - {{name: {thing}_1, class: {thing}, at: [2, 5]}}\n"
            f"  - {{name: {thing}_2, class: {thing}, at: [7, 5]}}\npeople:\n  - {{name: {person}, at: [3, 3]}}\n"
            f"priors:\n  cup: {{{room}: 1.0}}\n").encode()


def _frame_described(description: str) -> bytes:
    """A ``.frame`` file of one frame whose description is ``description`` (DSL escapes as written)."""
    return (f'frame Whisk "whisk" {{\n  description "{description}"\n  theme: object\n'
            "  do navigate(theme)\n  ensures whisked(theme)\n}\n").encode()


def hostile28_cases() -> Iterator[Case]:  # noqa: PLR0915 - one list of cases, read top to bottom
    """Round hostile28: ``bench parse`` corpora the shared scorers cannot read (fields missing or of another type,
    NaN, 1e999, a lone surrogate, a BOM and CRLF, an ALFRED table short of columns, constants that are numbers, a
    device), a map's priors naming a room it lacks under ``bench tasks``, every kind of command run in a working
    folder deleted under it, a frame description holding a lone surrogate, an escape sequence or an override, an
    unclosed frame at the end of its file, names of 100 characters drawn in a picture, a read-only ``TMPDIR``."""
    corpus = ("bench", "parse", "--corpus", "c.jsonl")
    go = '"text": "go to the kitchen"'
    expect = '"expect": [{"frame": "Go", "elements": {"goal": "kitchen"}}]'
    # -- bench parse: what the scorer reads, at its line ---------------------------------------------------------------
    yield Case("A bench parse --corpus whose line says nothing to score by", corpus,
               (("c.jsonl", f"{{{go}}}\n".encode()),), codes=(1,), keep=("c.jsonl",), says=r"c\.jsonl:1:\d+: .*expect")
    yield Case("A bench parse --corpus of a GPSR command without its fills", corpus,
               (("c.jsonl", f'{{{go}, "command_types": ["goToLoc"]}}\n'.encode()),), codes=(1,), keep=("c.jsonl",),
               says=r"c\.jsonl:1:\d+: .*'fills'")
    yield Case("A bench parse --corpus whose expected frame has no name", corpus,
               (("c.jsonl", f'{{{go}, "expect": [{{"elements": {{}}}}]}}\n'.encode()),), codes=(1,),
               keep=("c.jsonl",), says=r"c\.jsonl:1:\d+: .*'frame'")
    yield Case("A bench parse --corpus whose element is 1e999", corpus,
               (("c.jsonl", f'{{{go}, "expect": [{{"frame": "Go", "elements": {{"goal": 1e999}}}}]}}\n'.encode()),),
               codes=(1,), keep=("c.jsonl",), says=r"c\.jsonl:1:\d+: .*goal")
    yield Case("A bench parse --corpus whose second text is NaN", corpus,
               (("c.jsonl", f'{{{go}, {expect}}}\n{{"text": NaN, {expect}}}\n'.encode()),), codes=(1,),
               keep=("c.jsonl",), says=r"c\.jsonl:2:\d+: .*'text'")
    yield Case("A bench parse --corpus whose text holds a lone surrogate", corpus,
               (("c.jsonl", f'{{"text": "go to the kitchen\\ud800", {expect}}}\n'.encode()),), codes=(1,),
               keep=("c.jsonl",), says=r"c\.jsonl:1:\d+: .*surrogate")
    yield Case("A bench parse --corpus with a BOM and CRLF line ends", corpus,
               (("c.jsonl", f"\ufeff{{{go}, {expect}}}\r\n".encode()),), codes=(0,), keep=("c.jsonl",),
               says=r"frames 1\.000", timeout=120)
    yield Case("A bench parse --corpus of GPSR templates the scorer does not know", corpus,
               (("c.jsonl", f'{{{go}, "command_types": ["flyToMoon"], "fills": []}}\n'.encode()),), codes=(1,),
               keep=("c.jsonl",), says=r"c\.jsonl: .*(scored none|no command)", timeout=120)
    table = "task_type\tobject\treceptacle\tmrecep\tsliced\tgoal_sentence\n"
    yield Case("A bench parse --corpus of an ALFRED table without its task columns",
               ("bench", "parse", "--corpus", "g.tsv"), (("g.tsv", b"goal_sentence\ngo to the kitchen\n"),),
               codes=(1,), keep=("g.tsv",), says=r"g\.tsv:1:\d+: .*'task_type'")
    yield Case("A bench parse --corpus of an ALFRED row short of columns", ("bench", "parse", "--corpus", "g.tsv"),
               (("g.tsv", (table + "pick_and_place_simple\tApple\n").encode()),), codes=(1,), keep=("g.tsv",),
               says=r"g\.tsv:2:\d+: .*'goal_sentence'")
    yield Case("A bench parse --constants whose OBJECTS holds a number",
               ("bench", "parse", "--corpus", "g.tsv", "--constants", "k.json"),
               (("g.tsv", (table + "pick_and_place_simple\tApple\tFridge\t\t0\tput an apple in the fridge\n").encode()),
                ("k.json", b'{"OBJECTS": ["Apple", 5, "Fridge"]}\n')), codes=(1,), keep=("g.tsv", "k.json"),
               says=r"k\.json: .*OBJECTS")
    yield Case("A bench parse --corpus that is /dev/null", ("bench", "parse", "--corpus", "/dev/null"), codes=(1,),
               says=r"/dev/null: .*character device")
    # -- bench tasks: a map's priors naming a room it lacks -----------------------------------------------------------
    lacking = (b"name: m\nbounds: [0, 0, 10, 10]\nrooms:\n  - {name: hall, box: [0, 0, 10, 10]}\n"
               b"priors:\n  cup: {garage: 1.0}\n")
    yield Case("A bench tasks --map whose priors name a room it lacks",
               ("bench", "tasks", "--suite", "map", "--map", "m.yaml", "--command", "find the cup", "--policies",
                "sefm", "--particles", "20", "--layouts", "1"), (("m.yaml", lacking),), codes=(1,),
               keep=("m.yaml",), says=r"m\.yaml:6:\d+: ")
    # -- a working folder deleted under the command ------------------------------------------------------------------
    gone = {"files": (("d", "dir"),), "cwd": "d", "remove_cwd": True}
    yield Case("A map --png in a deleted working folder", ("map", "apartment", "--png", "o.png"), codes=(1,),
               says=r"--png o\.png.*working folder", **gone)  # type: ignore[arg-type]
    yield Case("A run --rrd in a deleted working folder", ("run", "go to the kitchen", "--map", "apartment",
                                                           "--particles", "20", "--rrd", "o.rrd"), codes=(1,),
               says=r"--rrd o\.rrd.*working folder", **gone)  # type: ignore[arg-type]
    yield Case("A localize --goals in a deleted working folder",
               ("localize", "--map", "apartment", "--steps", "1", "--particles", "20", "--task", "go to the kitchen",
                "--goals", "g.yaml"), codes=(1,), says=r"--goals g\.yaml.*working folder", **gone)  # type: ignore[arg-type]
    yield Case("A parse --file in a deleted working folder", ("parse", "--file", "c.txt"), codes=(1,),
               says=r"c\.txt: .*working folder", **gone)  # type: ignore[arg-type]
    yield Case("A validate in a deleted working folder", ("validate", "m.yaml"), codes=(1,),
               says=r"m\.yaml.*working folder", **gone)  # type: ignore[arg-type]
    yield Case("A map of a relative map file in a deleted working folder", ("map", "m.yaml"), codes=(1,),
               says=r"m\.yaml: no such map file.*working folder", **gone)  # type: ignore[arg-type]
    yield Case("A plan on a shipped map in a deleted working folder", ("plan", "go to the kitchen", "--map",
                                                                       "apartment"), codes=(0,),
               says=r"Go +goal=kitchen", **gone)  # type: ignore[arg-type]
    # -- a frame's description: what no terminal shows ----------------------------------------------------------------
    described = ("frames", "--framelib", "+d.frame", "--json")
    yield Case("A frames --json of a description holding a lone surrogate", described,
               (("d.frame", _frame_described("a \\udc80 b")),), codes=(1,), keep=("d.frame",),
               says=r"d\.frame:\d+:\d+: .*description")
    yield Case("A frames --json of a description holding an escape sequence", described,
               (("d.frame", _frame_described("a \\u001b[31m red")),), codes=(1,), keep=("d.frame",),
               says=r"d\.frame:\d+:\d+: .*description")
    yield Case("A validate of a YAML frame whose description holds a right-to-left override",
               ("validate", "d.yaml"),
               (("d.yaml", b'frames:\n  - frame: Whisk\n    description: "a \\u202e b"\n'
                           b'    lexical_units: [whisk]\n'),),
               codes=(1,), keep=("d.yaml",), says=r"d\.yaml:\d+:\d+: .*description")
    yield Case("A validate of a frame file that ends inside its last frame", ("validate", "u.frame"),
               (("u.frame", b'frame Whisk "whisk" {\n  theme: object\n  do navigate(theme)\n'),), codes=(1,),
               keep=("u.frame",), says=r"u\.frame:\d+:\d+: .*not closed")
    # -- names of 100 characters in a picture ------------------------------------------------------------------------
    loud = (("PYTHONWARNINGS", "<unset>"),)
    yield Case("A run --png on a map of 100-character names", ("run", f"go to the {'a' * 98}", "--map", "m.yaml",
                                                               "--particles", "20", "--png", "o.png"),
               (("m.yaml", _long_names()),), codes=(0,), keep=("m.yaml",), whole=("o.png",), env=loud,
               unsaid=r"Warning", says=r"done: Go")
    yield Case("A localize --png on a map of 100-character names",
               ("localize", "--map", "m.yaml", "--steps", "1", "--particles", "20", "--task", "find the cup",
                "--png", "o.png"), (("m.yaml", _long_names()),), codes=(0,), keep=("m.yaml",), whole=("o.png",),
               env=loud, unsaid=r"Warning", says=r"(?s).")
    # -- a read-only TMPDIR -------------------------------------------------------------------------------------------
    yield Case("A bench parse with a read-only TMPDIR", corpus,
               (("c.jsonl", f"{{{go}, {expect}}}\n".encode()), ("t", "ro-dir")), codes=(0,), keep=("c.jsonl",),
               env=(("TMPDIR", "t"),), says=r"frames 1\.000", timeout=120)
    # -- the second batch: class names no terminal shows, in priors and vocabularies ----------------------------------
    yield Case("A validate of priors whose class holds a NUL", ("validate", "m.yaml"),
               (("m.yaml", b'name: m\nbounds: [0, 0, 10, 10]\nrooms:\n  - {name: hall, box: [0, 0, 10, 10]}\n'
                           b'priors:\n  "cu\\0p": {hall: 1.0}\n'),), codes=(1,), keep=("m.yaml",),
               says=r"m\.yaml:6:3: .*class")
    yield Case("A parse with a vocabulary class holding an escape sequence",
               ("parse", "find the cup", "--vocabulary", "v.yaml", "--json"), (("v.yaml", b'- "cu\\e[31mp"\n- mug\n'),),
               codes=(1,), keep=("v.yaml",), says=r"v\.yaml:1:\d+: ")
    yield Case("A run with a vocabulary synonym holding a right-to-left override",
               ("run", "go to the sofa", "--map", "studio", "--particles", "20", "--vocabulary", "v.yaml"),
               (("v.yaml", b'- {class: mug, synonyms: ["be\\u202eaker"]}\n'),), codes=(1,), keep=("v.yaml",),
               says=r"v\.yaml:1:\d+: ")


def hostile29_cases() -> Iterator[Case]:  # noqa: PLR0915 - one list of cases, read top to bottom
    """Round hostile29: ``--done`` given many times, contradicting itself, unparseable, naming another map's things;
    ``bench tasks --suite context_held_out`` with options it reads and does not read, an output onto a device, a
    SIGINT; ``bench parse --corpus`` of a folder, a FIFO, a link loop, nothing, binary bytes, deep nesting, 5,000
    digits; ``run --png/--rrd`` onto a folder, a FIFO, a link loop, one path twice, a link to the map's image; a
    researcher's own ROS map (``map_saver``'s lines and a P5 image, rooms added by hand) read as it comes (CRLF, a
    BOM, an image name with a space or ``..``) and broken (tabs, Latin-1, repeated keys, thresholds crossed, 400
    digits, YAML tags, an image that is a device, a FIFO, itself, a folder, a loop, empty, a PGM lying about its size
    or holding signs, fractions and NaN); frame files with a BOM and CRLF, Latin-1, tags; odd ``--jobs``; HOME unset;
    a closed stdin; a reader gone from stdout."""
    studio = ("--map", "studio")
    sofa = ("run", "go to the sofa", *studio, "--particles", "20")
    # -- --done ------------------------------------------------------------------------------------------------------
    many = [a for _ in range(100) for a in ("--done", "go to the bed")]
    yield Case("A run with --done given 100 times", (*sofa, *many), codes=(0,), says=r"done: Go")
    yield Case("A run whose --done open then close the fridge", ("run", "open the fridge", "--map", "apartment",
                                                                 "--particles", "20", "--done", "open the fridge",
                                                                 "--done", "close the fridge"),
               codes=(0,), says=r"done: Open\(theme=fridge_1\)")
    yield Case("A run whose --done is no command", (*sofa, "--done", "qwzx blorp"), codes=(1,),
               says=r"column 1: in --done 'qwzx blorp'")
    yield Case("A run whose --done names another map's thing", (*sofa, "--done", "open the locker"), codes=(1,),
               says=r"in --done 'open the locker': the studio has no locker")
    yield Case("A run whose --done names another map's room", (*sofa, "--done", "go to the galley"), codes=(1,),
               says=r"in --done 'go to the galley'")
    yield Case("A run whose --done is a negation", (*sofa, "--done", "don't open the fridge"), codes=(1,),
               says=r"in --done")
    yield Case("A localize whose second --done is no command",
               ("localize", *studio, "--steps", "1", "--particles", "20", "--task", "go to the sofa", "--done",
                "go to the bed", "--done", "qwzx"), codes=(1,), says=r"in --done 'qwzx'")
    # -- bench tasks --suite context_held_out ------------------------------------------------------------------------
    held = ("bench", "tasks", "--suite", "context_held_out", "--policies", "oracle", "--jobs", "1")
    mug = (*held, "--command", "stir the mug", "--layouts", "1")
    yield Case("A bench tasks --suite context_held_out --data /dev/null", (*held, "--data", "/dev/null"), codes=(1,),
               says=r"--suite context_held_out does not read --data")
    yield Case("A bench tasks --suite context_held_out --fov nan", (*held, "--fov", "nan"), codes=(1,), says=r"--fov")
    yield Case("A bench tasks --suite context_held_out --starts 2", (*held, "--starts", "2"), codes=(1,),
               says=r"does not read --starts")
    yield Case("A bench tasks --suite context_held_out --command none of its cases has",
               (*held, "--command", "go to the kitchen"), codes=(1,), says=r"--command 'go to the kitchen'")
    yield Case("A bench tasks --suite context_held_out --framelib of a broken frame", (*mug, "--framelib", "b.frame"),
               (("b.frame", b"frame {\n"),), codes=(1,), keep=("b.frame",), says=r"b\.frame:1:\d+: ")
    yield Case("A bench tasks --suite context_held_out --episodes /dev/full", (*mug, "--episodes", "/dev/full"),
               codes=(1,), says=r"--episodes", timeout=120)
    yield Case("A SIGINT during bench tasks --suite context_held_out --episodes", (*mug, "--episodes", "e.jsonl"),
               codes=(130,), absent=("e.jsonl",), signal=(2, 3.0))
    # -- bench parse --corpus ------------------------------------------------------------------------------------------
    corpus = ("bench", "parse", "--corpus", "c.jsonl")
    yield Case("A bench parse --corpus that is a folder", ("bench", "parse", "--corpus", "d"), (("d", "dir"),),
               codes=(1,), says=r"\bd: ")
    yield Case("A bench parse --corpus that is a FIFO", corpus, (("c.jsonl", "fifo"),), codes=(1,),
               says=r"c\.jsonl: ", timeout=30)
    yield Case("A bench parse --corpus that is a link to itself", corpus, (("c.jsonl", "link:c.jsonl"),), codes=(1,),
               says=r"c\.jsonl: ")
    yield Case("A bench parse --corpus that is empty", corpus, (("c.jsonl", b""),), codes=(1,), keep=("c.jsonl",),
               says=r"c\.jsonl: ")
    yield Case("A bench parse --corpus of binary bytes", corpus, (("c.jsonl", b"\x00\xff\xfe" * 100),), codes=(1,),
               keep=("c.jsonl",), says=r"c\.jsonl")
    yield Case("A bench parse --corpus nested 100,000 deep", corpus,
               (("c.jsonl", b'{"text": "go", "expect": ' + b"[" * 100_000 + b"]" * 100_000 + b"}\n"),), codes=(1,),
               keep=("c.jsonl",), says=r"c\.jsonl:1:\d+: ")
    yield Case("A bench parse --corpus whose element is 5,000 digits", corpus,
               (("c.jsonl", b'{"text": "go", "expect": [{"frame": "Go", "elements": {"goal": ' + b"9" * 5000
                 + b"}}]}\n"),), codes=(1,), keep=("c.jsonl",), says=r"c\.jsonl:1:\d+: ")
    table = "task_type\tobject\treceptacle\tmrecep\tsliced\tgoal_sentence\n"
    yield Case("A bench parse --constants holding 5,000 digits",
               ("bench", "parse", "--corpus", "g.tsv", "--constants", "k.json"),
               (("g.tsv", (table + "pick_and_place_simple\tApple\tFridge\t\t0\tput an apple in the fridge\n").encode()),
                ("k.json", b'{"OBJECTS": ["Apple", "Fridge"], "n": ' + b"9" * 5000 + b"}\n")), codes=(1,),
               keep=("g.tsv", "k.json"), says=r"k\.json:1:\d+: ")
    # -- run --png / --rrd into odd places -----------------------------------------------------------------------------
    kitchen = ("run", "go to the kitchen", "--map", "m.yaml", "--particles", "20")
    ros = robot_map()
    yield Case("A run --png onto a folder", (*kitchen, "--png", "d"), (*ros, ("d", "dir")), codes=(1,),
               keep=("m.yaml", "map.pgm"), says=r"--png d\b")
    yield Case("A run --png onto a FIFO", (*kitchen, "--png", "f.png"), (*ros, ("f.png", "fifo")), codes=(1,),
               keep=("m.yaml", "map.pgm"), says=r"--png f\.png", timeout=30)
    yield Case("A run --png onto a link to itself", (*kitchen, "--png", "l.png"), (*ros, ("l.png", "link:l.png")),
               codes=(1,), keep=("m.yaml", "map.pgm"), says=r"--png l\.png")
    yield Case("A run --png and --rrd onto one path", (*kitchen, "--png", "o.png", "--rrd", "o.png"), ros, codes=(1,),
               keep=("m.yaml", "map.pgm"), absent=("o.png",), says=r"--(png|rrd) o\.png")
    yield Case("A run --png onto the map's image", (*kitchen, "--png", "map.pgm"), ros, codes=(1,),
               keep=("m.yaml", "map.pgm"), says=r"--png map\.pgm")
    yield Case("A run --png onto a hard link to the map's image", (*kitchen, "--png", "x.png"),
               (*ros, ("x.png", "hard:map.pgm")), codes=(1,), keep=("m.yaml", "map.pgm", "x.png"), says=r"--png x\.png")
    yield Case("A run --rrd onto a link to the map's image", (*kitchen, "--rrd", "x.rrd"),
               (*ros, ("x.rrd", "link:map.pgm")), codes=(1,), keep=("m.yaml", "map.pgm"), says=r"--rrd x\.rrd")
    # -- a researcher's own ROS map: good but unusual ------------------------------------------------------------------
    (_, head), (_, image) = ros
    yield Case("A run --png on a researcher's ROS map with rooms added by hand", (*kitchen, "--png", "o.png"), ros,
               codes=(0,), keep=("m.yaml", "map.pgm"), whole=("o.png",), says=r"done: Go\(goal=kitchen\)")
    yield Case("A validate of a ROS map saved with CRLF line ends", ("validate", "m.yaml"),
               (("m.yaml", head.replace(b"\n", b"\r\n")), ("map.pgm", image)), codes=(0,), keep=("m.yaml",),
               says=r"ok: ")
    yield Case("A validate of a ROS map with a BOM", ("validate", "m.yaml"),
               (("m.yaml", b"\xef\xbb\xbf" + head), ("map.pgm", image)), codes=(0,), keep=("m.yaml",), says=r"ok: ")
    yield Case("A validate of a ROS map whose image's name has a space", ("validate", "m.yaml"),
               (("m.yaml", head.replace(b"image: map.pgm", b"image: my map.pgm")), ("my map.pgm", image)),
               codes=(0,), says=r"ok: ")
    yield Case("A validate of a ROS map whose image is in the folder above", ("validate", "d/m.yaml"),
               (("d/m.yaml", head.replace(b"image: map.pgm", b"image: ../map.pgm")), ("map.pgm", image)),
               codes=(0,), says=r"ok: ")
    yield Case("A validate of a ROS map with two-number origin", ("validate", "m.yaml"),
               (("m.yaml", head.replace(b", 0.000000]", b"]")), ("map.pgm", image)), codes=(0,), says=r"ok: ")
    # -- a researcher's own ROS map: broken, each at its line and column -----------------------------------------------
    def bad(name: str, yaml_text: bytes, says: str, *more: tuple[str, bytes | str]) -> Case:
        return Case(f"A validate of a ROS map {name}", ("validate", "m.yaml"),
                    (("m.yaml", yaml_text), ("map.pgm", image), *more), codes=(1,), keep=("m.yaml", "map.pgm"),
                    says=says)
    yield bad("indented with a tab", head.replace(b"  - {name: hall", b"\t- {name: hall"), r"m\.yaml:\d+:\d+: ")
    yield bad("in Latin-1", head.replace(b"name: lab", b"name: lab\xe9"), r"m\.yaml:\d+:\d+: ")
    yield bad("whose resolution is said twice", head + b"resolution: 0.1\n", r"m\.yaml:\d+:\d+: .*resolution")
    yield bad("whose thresholds cross", head.replace(b"free_thresh: 0.25", b"free_thresh: 0.9"),
              r"m\.yaml:\d+:\d+: ")
    yield bad("whose origin has 400 digits", head.replace(b"origin: [-5.000000", b"origin: [" + b"9" * 400),
              r"m\.yaml:4:\d+: ")
    yield bad("whose negate is 2", head.replace(b"negate: 0", b"negate: 2"), r"m\.yaml:5:\d+: ")
    yield bad("of two documents", head + b"---\nname: other\n", r"m\.yaml:\d+:\d+: ")
    yield bad("whose name is tagged !!binary", head.replace(b"name: lab", b"name: !!binary bGFi"),
              r"m\.yaml:9:7: .*!!binary")
    yield bad("whose rooms are tagged !!python/object/apply",
              head.replace(b"rooms:", b"rooms: !!python/object/apply:os.system"), r"m\.yaml:10:8: .*!!python")
    yield bad("whose name has a local tag", head.replace(b"name: lab", b"name: !mine lab"), r"m\.yaml:9:7: .*!mine")
    yield bad("whose image is /dev/zero", head.replace(b"image: map.pgm", b"image: /dev/zero"), r"m\.yaml:1:8: ")
    yield bad("whose image is a FIFO", head.replace(b"image: map.pgm", b"image: f.pgm"), r"m\.yaml:1:8: ",
              ("f.pgm", "fifo"))
    yield bad("whose image is the map itself", head.replace(b"image: map.pgm", b"image: m.yaml"), r"m\.yaml:1:8: ")
    yield bad("whose image is a folder", head.replace(b"image: map.pgm", b"image: d"), r"m\.yaml:1:8: ", ("d", "dir"))
    yield bad("whose image is a link to itself", head.replace(b"image: map.pgm", b"image: l.pgm"), r"m\.yaml:1:8: ",
              ("l.pgm", "link:l.pgm"))
    yield bad("whose image is empty", head.replace(b"image: map.pgm", b"image: e.pgm"), r"m\.yaml:1:8: ",
              ("e.pgm", b""))
    def pgm(name: str, data: bytes, says: str = r"m\.yaml:1:8: ") -> Case:
        return Case(f"A validate of a ROS map whose PGM {name}", ("validate", "m.yaml"),
                    (("m.yaml", head), ("map.pgm", data)), codes=(1,), keep=("m.yaml", "map.pgm"), says=says)
    yield pgm("says 4000 x 4000 and holds 100 bytes", b"P5\n4000 4000\n255\n" + b"\xfe" * 100)
    yield pgm("says 0 x 0", b"P5\n0 0\n255\n")
    yield pgm("says 1e6 x 1e6", b"P5\n1000000 1000000\n255\n" + b"\xfe" * 100)
    yield pgm("has a maximum of 0", b"P5\n10 10\n0\n" + b"\x00" * 100)
    yield pgm("has a width of 5,000 digits", b"P5\n" + b"9" * 5000 + b" 10\n255\n", r"m\.yaml:1:8: .*digits")
    yield pgm("(text) holds a negative pixel", b"P2\n2 2\n255\n1 -2 3 4\n", r"m\.yaml:1:8: .*'-2'")
    yield pgm("(text) holds a fraction", b"P2\n2 2\n255\n1 2.5 3 4\n", r"m\.yaml:1:8: .*'2\.5'")
    yield pgm("(text) holds NaN", b"P2\n2 2\n255\n1 nan 3 4\n", r"m\.yaml:1:8: .*'nan'")
    yield pgm("(text) holds a pixel of 5,000 digits", b"P2\n2 2\n255\n1 " + b"9" * 5000 + b" 3 4\n",
              r"m\.yaml:1:8: .*exceeds the maximum 255")
    # -- frame files ---------------------------------------------------------------------------------------------------
    whisk_yaml = (b"frames:\n  - frame: Whisk\n    lexical_units: [whisk]\n    elements:\n      theme: {type: object}\n"
                  b"    actions: [navigate(theme)]\n")
    whisk_dsl = b'frame Whisk "whisk" {\n  theme: object\n  do navigate(theme)\n}\n'
    yaml_plan = ("plan", "whisk the cup", "--framelib", "+f.yaml")
    dsl_plan = ("plan", "whisk the cup", "--framelib", "+f.frame")
    yield Case("A plan on a YAML frame file with a BOM and CRLF", yaml_plan,
               (("f.yaml", b"\xef\xbb\xbf" + whisk_yaml.replace(b"\n", b"\r\n")),), codes=(0,), keep=("f.yaml",),
               says=r"Whisk")
    yield Case("A plan on a frame file with a BOM and CRLF", dsl_plan,
               (("f.frame", b"\xef\xbb\xbf" + whisk_dsl.replace(b"\n", b"\r\n")),), codes=(0,), keep=("f.frame",),
               says=r"Whisk")
    yield Case("A plan on a YAML frame file in Latin-1", yaml_plan, (("f.yaml", whisk_yaml.replace(b"[whisk]",
                                                                                                     b"[whisk\xe9]")),),
               codes=(1,), keep=("f.yaml",), says=r"f\.yaml:3:\d+: ")
    yield Case("A plan on a frame file in Latin-1", dsl_plan, (("f.frame", whisk_dsl.replace(b'"whisk"',
                                                                                           b'"whisk\xe9"')),),
               codes=(1,), keep=("f.frame",), says=r"f\.frame:1:\d+: ")
    yield Case("A plan on a YAML frame file of two documents, the second repeating the frame", yaml_plan,
               (("f.yaml", whisk_yaml + b"---\n" + whisk_yaml),), codes=(1,), keep=("f.yaml",),
               says=r"f\.yaml:\d+:\d+: ")
    yield Case("A plan on a YAML frame file whose units are tagged !!set", yaml_plan,
               (("f.yaml", whisk_yaml.replace(b"[whisk]", b"!!set {whisk}")),), codes=(1,), keep=("f.yaml",),
               says=r"f\.yaml:3:\d+: ")
    yield Case("A plan on a YAML frame file whose frame name has a local tag", yaml_plan,
               (("f.yaml", whisk_yaml.replace(b"frame: Whisk", b"frame: !x Whisk")),), codes=(1,), keep=("f.yaml",),
               says=r"f\.yaml:2:\d+: .*!x")
    # -- --jobs, the environment, the streams --------------------------------------------------------------------------
    for jobs in ("65", "-1", "9" * 30):
        yield Case(f"A bench tasks --jobs {jobs[:8]}", ("bench", "tasks", "--suite", "map", "--jobs", jobs),
                   codes=(2,), says=r"--jobs")
    yield Case("A run with HOME unset", sofa, codes=(0,), env=(("HOME", "<unset>"),), says=r"done: Go")
    yield Case("A parse --file - with stdin closed", ("parse", "--file", "-"), codes=(1,), stream="closed-stdin",
               says=r"stdin|standard input|-")
    yield Case("A frames --json to a reader that has gone", ("frames", "--json"), codes=(0, 1, 141),
               stream="gone-stdout", says=r"\A(?![\s\S]*Traceback)")


def _bag_folder() -> tuple[tuple[str, bytes], ...]:
    """A ROS 2 sqlite3 bag folder ``x/`` (``metadata.yaml`` and ``out.db3``) of a robot in the apartment, as its
    files; none without the ros extra."""
    try:
        import rosbags  # noqa: F401
    except ImportError:
        return ()
    import tempfile
    from pathlib import Path

    from seal_cli.bench.ros import write_run
    from seal_cli.maps.formats.map_server import load_map
    from seal_cli.resources import map_path

    with tempfile.TemporaryDirectory() as folder:
        bag = Path(folder) / "run_db3"
        write_run(bag, load_map(map_path("apartment")), 20, 5, np.random.default_rng(0))
        return tuple((f"x/{p.name}", p.read_bytes()) for p in sorted(bag.iterdir()))


def hostile29_bag_cases() -> Iterator[Case]:
    """Round hostile29's second batch, a researcher's own ROS 2 bag folder: an output onto its ``metadata.yaml`` or
    a hard link to its database, and its ``metadata.yaml`` edited by hand (a YAML tag, Latin-1 bytes, 5,000 digits,
    a syntax error, a file outside the folder), each refused at its line and column; given with a trailing slash,
    through a link, with CRLF or a BOM, read as it comes."""
    files = _bag_folder()
    if not files:
        return
    meta = dict(files)["x/metadata.yaml"]
    db = tuple(f for f in files if f[0] != "x/metadata.yaml")
    keep = tuple(name for name, _ in files)
    yield Case("A import-bag -o onto its bag folder's metadata.yaml", ("import-bag", "x", "-o", "x/metadata.yaml"),
               files, codes=(1,), keep=keep, says=r"--output x/metadata\.yaml would overwrite")
    yield Case("A import-bag -o onto a hard link to its bag's database", ("import-bag", "x", "-o", "h.yaml"),
               (*files, ("h.yaml", "hard:x/out.db3")), codes=(1,), keep=(*keep, "h.yaml"), says=r"--output h\.yaml")
    yield Case("A localize --bag --goals onto the bag folder's metadata.yaml",
               ("localize", "--map", "apartment", "--bag", "x", "--task", "go to the kitchen", "--steps", "1",
                "--particles", "20", "--goals", "x/metadata.yaml"), files, codes=(1,), keep=keep,
               says=r"--goals x/metadata\.yaml")
    def edited(name: str, text: bytes, says: str) -> Case:
        return Case(f"A import-bag of a bag folder whose metadata.yaml {name}", ("import-bag", "x", "-o", "o.yaml"),
                    (("x/metadata.yaml", text), *db), codes=(1,), keep=("x/metadata.yaml", "x/out.db3"),
                    absent=("o.yaml",), says=says)
    yield edited("holds a !!python tag", meta.replace(b"ros_distro: rosbags",
                                                       b'ros_distro: !!python/object/apply:os.system ["true"]'),
                 r"x/metadata\.yaml:17:15: ")
    yield edited("ends in Latin-1 bytes", meta + b"# caf\xe9\n", r"x/metadata\.yaml:\d+:\d+: ")
    yield edited("counts in 5,000 digits", meta.replace(b"  message_count: 26", b"  message_count: " + b"9" * 5000),
                 r"x/metadata\.yaml:14:18: ")
    yield edited("is cut inside a list", b"rosbag2_bagfile_information:\n  files: [\n", r"x/metadata\.yaml:\d+:\d+: ")
    yield edited("lists a file outside the folder", meta.replace(b"  - out.db3", b"  - ../run.mcap"), r"\bx: ")
    def read(name: str, argv: tuple[str, ...], more: tuple[tuple[str, bytes | str], ...] = (),
             text: bytes = meta) -> Case:
        return Case(f"A import-bag of a bag folder {name}", ("import-bag", *argv, "-o", "o.yaml"),
                    (("x/metadata.yaml", text), *db, *more), codes=(0,), keep=("x/metadata.yaml", "x/out.db3"),
                    whole=("o.yaml",), says=r"5 observations")
    yield read("given with a trailing slash", ("x/",))
    yield read("given through a link", ("y",), (("y", "link:x"),))
    yield read("whose metadata.yaml has CRLF line ends", ("x",), text=meta.replace(b"\n", b"\r\n"))
    yield read("whose metadata.yaml starts with a BOM", ("x",), text=b"\xef\xbb\xbf" + meta)


def hostile29_environment_cases() -> Iterator[Case]:
    """Round hostile29's third batch, the environment a command starts in: seal's cache folder a device, a file, a link
    loop or the map itself; ``XDG_CACHE_HOME`` a file; ``HOME`` empty or missing; matplotlib's ``MPLCONFIGDIR`` a
    file or a device (matplotlib then rebuilt its font cache in a temporary folder each run, 30 s, and said so in two
    lines of its own); ``TMPDIR`` a file or missing; ``COLUMNS`` 0, negative, a word, 1; ``PYTHONIOENCODING`` ascii
    and latin-1; ``LC_ALL=C`` with an accented map name; ``--jobs 64`` for one task."""
    parse = ("parse", "go to the café")
    for name, value, files in (("a device", "/dev/null", ()), ("a file", "f", (("f", b"x"),)),
                               ("a link to itself", "l", (("l", "link:l"),))):
        yield Case(f"A parse with SEAL_CACHE_DIR {name}", parse, files, codes=(0,), env=(("SEAL_CACHE_DIR", value),),
                   keep=tuple(n for n, c in files if isinstance(c, bytes)), says=r"Go\b")
    small = b"name: m\nbounds: [0, 0, 10, 10]\nrooms:\n  - {name: hall, box: [0, 0, 10, 10]}\n"
    yield Case("A map with SEAL_CACHE_DIR the map itself", ("map", "m.yaml"), (("m.yaml", small),), codes=(0,),
               env=(("SEAL_CACHE_DIR", "m.yaml"),), keep=("m.yaml",), says=r"(?s).")
    yield Case("A parse with XDG_CACHE_HOME a file", parse, (("f", b"x"),), codes=(0,),
               env=(("XDG_CACHE_HOME", "f"), ("SEAL_CACHE_DIR", "<unset>")), keep=("f",), says=r"Go\b")
    for name, value in (("empty", ""), ("a folder that does not exist", "/nonexistent/home")):
        yield Case(f"A parse with HOME {name}", parse, codes=(0,),
                   env=(("HOME", value), ("XDG_CACHE_HOME", "<unset>"), ("SEAL_CACHE_DIR", "<unset>")), says=r"Go\b")
    drive = ("run", "go to the kitchen", "--map", "apartment", "--particles", "20", "--png", "o.png")
    for name, value, files in (("a file", "f", (("f", b"x"),)), ("a device", "/dev/null", ())):
        yield Case(f"A run --png with MPLCONFIGDIR {name}", drive, files, codes=(0,),
                   env=(("MPLCONFIGDIR", value), ("PYTHONWARNINGS", "<unset>")), whole=("o.png",),
                   keep=tuple(n for n, c in files if isinstance(c, bytes)),
                   says=rf"warning: MPLCONFIGDIR {value} is not a folder", unsaid=r"Matplotlib created|mkdir -p")
    corpus = b'{"text": "go to the kitchen", "expect": [{"frame": "Go", "elements": {"goal": "kitchen"}}]}\n'
    yield Case("A bench parse with TMPDIR a file", ("bench", "parse", "--corpus", "c.jsonl"),
               (("c.jsonl", corpus), ("t", b"x")), codes=(0,), env=(("TMPDIR", "t"),), keep=("c.jsonl", "t"),
               says=r"frames 1\.000", timeout=120)
    yield Case("A run --png with TMPDIR missing", drive, codes=(0,), env=(("TMPDIR", "/nonexistent"),),
               whole=("o.png",), says=r"done: Go")
    for columns in ("0", "-5", "abc", "1"):
        yield Case(f"A plan with COLUMNS={columns}", ("plan", "go to the kitchen", "--map", "apartment"), codes=(0,),
                   env=(("COLUMNS", columns),), says=r"Go")
    yield Case("A parse with PYTHONIOENCODING=ascii:strict of a snowman", ("parse", "go to the \u2603 now"),
               codes=(1,), env=(("PYTHONIOENCODING", "ascii:strict"),), says=r"column 11: .*U\+2603")
    yield Case("A run with PYTHONIOENCODING=latin-1 of a word the map lacks", ("run", "go to the café", "--map",
                                                                               "apartment", "--particles", "20"),
               codes=(1,), env=(("PYTHONIOENCODING", "latin-1"),), says=r"column 7: the apartment has no caf")
    yield Case("A validate with LC_ALL=C of a map named café", ("validate", "m.yaml"),
               (("m.yaml", small.replace(b"name: m", "name: café".encode())),), codes=(0,),
               env=(("LC_ALL", "C"), ("LANG", "C"), ("PYTHONUTF8", "0")), keep=("m.yaml",), says=r"ok: ")
    yield Case("A bench tasks --jobs 64 for one task", ("bench", "tasks", "--suite", "map", "--map", "studio",
                                                          "--command", "go to the sofa", "--layouts", "1",
                                                          "--policies", "oracle", "--jobs", "64"),
               codes=(0,), says=r"(?s).", timeout=120)


def _column_of(data: bytes, key: bytes, nth: int = 2) -> int:
    """The 1-based column of the ``nth`` JSON key ``key`` (with its quotes) in ``data``'s line holding it."""
    needle, at = b'"' + key + b'"', -1
    for _ in range(nth):
        at = data.index(needle, at + 1)
    return at - data.rfind(b"\n", 0, at)


def hostile30_leftover_cases() -> Iterator[Case]:  # noqa: PLR0915 - one list of cases, read top to bottom
    """Round hostile30's first batch, what hostile29 noticed and left: YAML's own tags (``!!str`` on a number where a
    number goes was read as the number, ``!!int`` on a name as the name); JSON objects with a key twice (the last
    was taken, as Python's reader takes it); a P5 image with bytes after its pixels (read, the rest passed over) or
    too few; a question given as ``--done``; a benchmark's output into a folder root cannot write (``/proc``,
    ``/sys``: the only ones a root-run bench has)."""
    (_, head), (_, image) = robot_map()
    def tagged(name: str, old: bytes, new: bytes, codes: tuple[int, ...], says: str) -> Case:
        assert old in head, f"the researcher's map changed: update the case {name!r}"
        return Case(f"A validate of a ROS map {name}", ("validate", "m.yaml"),
                    (("m.yaml", head.replace(old, new)), ("map.pgm", image)), codes=codes, keep=("m.yaml", "map.pgm"),
                    says=says)
    # -- YAML's own tags: each read as YAML defines it -----------------------------------------------------------------
    yield tagged("whose resolution is tagged !!str", b"resolution: 0.050000", b"resolution: !!str 0.050000", (1,),
                 r"m\.yaml:3:13: .*resolution")
    yield tagged("whose name is tagged !!int", b"name: lab", b"name: !!int lab", (1,), r"m\.yaml:9:7: .*!!int")
    yield tagged("whose negate is tagged !!bool on a 0", b"negate: 0", b"negate: !!bool 0", (1,),
                 r"m\.yaml:5:9: .*!!bool")
    yield tagged("whose origin is tagged !!float on an integer", b"origin: [-5.000000", b"origin: [!!float -5", (0,),
                 r"ok: ")
    yield tagged("whose name is tagged !!str on a number", b"name: lab", b"name: !!str 5", (0,), r"ok: ")
    yield tagged("whose rooms are tagged !!map on a list", b"rooms:\n", b"rooms: !!map\n", (1,),
                 r"m\.yaml:10:8: .*!!map")
    yield tagged("whose robot is tagged !!seq on a mapping", b"robot: {pose", b"robot: !!seq {pose", (1,),
                 r"m\.yaml:\d+:8: .*!!seq")
    yield tagged("whose place is tagged !!null on a name", b"table_1, class", b"!!null table_1, class", (1,),
                 r"m\.yaml:\d+:\d+: .*!!null")
    yield tagged("whose key is tagged !!str", b"resolution: 0.05", b"!!str resolution: 0.05", (0,), r"ok: ")
    yield Case("A localize whose observation's pose is tagged !!str",
               ("localize", "--map", "apartment", "--task", "go to the kitchen", "--steps", "1", "--particles", "20",
                "--observations", "o.yaml"), (("o.yaml", b"- pose: [!!str -6, -3]\n  detections: []\n"),), codes=(1,),
               keep=("o.yaml",), says=r"o\.yaml:1:10: ")
    # -- JSON objects with a key twice: refused at the second --------------------------------------------------------
    line = b'{"text": "go to the kitchen", "text": "go to the bed", "expect": [{"frame": "Go", "elements": ' \
           b'{"goal": "kitchen"}}]}\n'
    yield Case("A bench parse --corpus whose line says text twice", ("bench", "parse", "--corpus", "c.jsonl"),
               (("c.jsonl", line),), codes=(1,), keep=("c.jsonl",),
               says=rf"c\.jsonl:1:{_column_of(line, b'text')}: .*'text'")
    nested = b'{"text": "go to the kitchen", "expect": [{"frame": "Go", "elements": {"goal": "kitchen", "goal": ' \
             b'"bed"}}]}\n'
    yield Case("A bench parse --corpus whose element says goal twice", ("bench", "parse", "--corpus", "c.jsonl"),
               (("c.jsonl", b"\n" + nested),), codes=(1,), keep=("c.jsonl",),
               says=rf"c\.jsonl:2:{_column_of(nested, b'goal')}: .*'goal'")
    table = "task_type\tobject\treceptacle\tmrecep\tsliced\tgoal_sentence\n"
    constants = b'{\n  "OBJECTS": ["Apple", "Fridge"],\n  "OBJECTS": ["Apple"]\n}\n'
    yield Case("A bench parse --constants that says OBJECTS twice",
               ("bench", "parse", "--corpus", "g.tsv", "--constants", "k.json"),
               (("g.tsv", (table + "pick_and_place_simple\tApple\tFridge\t\t0\tput an apple in the fridge\n").encode()),
                ("k.json", constants)), codes=(1,), keep=("g.tsv", "k.json"), says=r"k\.json:3:3: .*'OBJECTS'")
    tasks = ("bench", "tasks", "--data", "d", "--policies", "sefm", "--jobs", "1", "--particles", "20")
    data = dict(alfred2d_data())
    plans = data["d/floorplans.json"].replace(b'"scene_type": "kitchen"',
                                              b'"scene_type": "kitchen", "scene_type": "bathroom"', 1)
    yield Case("A bench tasks on ALFRED-2D floor plans that say scene_type twice", tasks,
               tuple({**data, "d/floorplans.json": plans}.items()), codes=(1,), keep=tuple(data),
               says=rf"d/floorplans\.json:1:{_column_of(plans, b'scene_type')}: .*'scene_type'", timeout=120)
    trial = data["d/trials_valid_seen.jsonl"].replace(b'"split": "valid_seen"',
                                                      b'"split": "valid_seen", "split": "train"')
    yield Case("A bench tasks on an ALFRED-2D trial that says split twice", tasks,
               tuple({**data, "d/trials_valid_seen.jsonl": trial}.items()), codes=(1,), keep=tuple(data),
               says=rf"d/trials_valid_seen\.jsonl:1:{_column_of(trial, b'split')}: .*'split'", timeout=120)
    yield Case("A validate of a map written as JSON that says name twice", ("validate", "m.json"),
               (("m.json", b'{"name": "a", "name": "b", "bounds": [0, 0, 10, 10],\n "rooms": [{"name": "hall", '
                           b'"box": [0, 0, 10, 10]}]}\n'),), codes=(1,), keep=("m.json",),
               says=r"m\.json:1:15: .*'name'")
    # -- a P5 image with more bytes than its pixels, or fewer ----------------------------------------------------------
    def pgm(name: str, data: bytes, codes: tuple[int, ...], says: str) -> Case:
        return Case(f"A validate of a ROS map whose PGM {name}", ("validate", "m.yaml"),
                    (("m.yaml", head), ("map.pgm", data)), codes=codes, keep=("m.yaml", "map.pgm"), says=says)
    yield pgm("has bytes after its pixels", image + b"GARBAGE" * 10, (1,), r"m\.yaml:1:8: .*70 bytes after")
    yield pgm("has its pixels twice (16-bit saved under a maximum of 255)", image + image[15:], (1,),
              r"m\.yaml:1:8: .*after")
    yield pgm("ends with a newline after its pixels", image + b"\n", (0,), r"ok: ")
    yield pgm("holds a second image after the first (netpbm's several images)", image + image, (0,), r"ok: ")
    yield pgm("is one byte short", image[:-1], (1,), r"m\.yaml:1:8: .*truncated")
    text = b"P2\n200 200\n255\n" + b" ".join(b"%d" % v for v in image[15:]) + b"\n"
    yield pgm("(text) has values after its pixels", text + b"7 7\n", (1,), r"m\.yaml:1:8: .*2 values after")
    yield pgm("(text) ends with blank lines after its pixels", text + b"  \n\n\t\n", (0,), r"ok: ")
    # -- a question given as --done: the question answered -------------------------------------------------------------
    yield Case("A plan whose --done is a question (where is the cup?)",
               ("plan", "bring me the cup", "--map", "apartment", "--done", "where is the cup?"), codes=(0,),
               says=r"found\(cup\)")
    yield Case("A run whose --done is a question (how many cups are there?)",
               ("run", "go to the sofa", "--map", "studio", "--particles", "20", "--done", "how many cups are there?"),
               codes=(0,), says=r"done: Go")
    # -- a benchmark's output where root cannot write ----------------------------------------------------------------
    tiny = ("bench", "tasks", "--suite", "map", "--map", "studio", "--command", "go to the sofa", "--layouts", "1",
            "--policies", "oracle", "--jobs", "1", "--episodes")
    yield Case("A bench tasks --episodes into /proc", (*tiny, "/proc/e.jsonl"), codes=(1,),
               says=r"--episodes /proc/e\.jsonl: folder /proc does not take new files")
    yield Case("A bench tasks --episodes into /sys", (*tiny, "/sys/e.jsonl"), codes=(1,),
               says=r"--episodes /sys/e\.jsonl: folder /sys does not take new files")
    yield Case("A bench tasks --episodes into /sys/kernel", (*tiny, "/sys/kernel/e.jsonl"), codes=(1,),
               says=r"--episodes /sys/kernel/e\.jsonl: folder /sys/kernel does not take new files")
    yield Case("A run --png into /proc/self", ("run", "go to the sofa", "--map", "studio", "--particles", "20",
                                               "--png", "/proc/self/o.png"), codes=(1,),
               says=r"--png /proc/self/o\.png: folder /proc/self does not take new files")


def _png(width: int, height: int, depth: int = 8, colour: int = 0, rows: bytes | None = None,
         crc: bool = True) -> bytes:
    """A PNG of ``width`` × ``height`` (bit ``depth``, ``colour`` type), its pixel rows ``rows`` (default: all 0xfe,
    each row with its filter byte), with right or wrong CRCs."""
    import struct
    import zlib

    def chunk(kind: bytes, body: bytes) -> bytes:
        check = zlib.crc32(kind + body) if crc else 0
        return struct.pack(">I", len(body)) + kind + body + struct.pack(">I", check)

    channels = {0: 1, 2: 3, 3: 1, 4: 2, 6: 4}[colour]
    row = b"\x00" + b"\xfe" * (width * channels * depth // 8)
    body = zlib.compress(rows if rows is not None else row * height)
    palette = chunk(b"PLTE", b"\xfe\xfe\xfe\x00\x00\x00") if colour == 3 else b""
    return (b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", width, height, depth, colour, 0, 0, 0))
            + palette + chunk(b"IDAT", body) + chunk(b"IEND", b""))


def hostile30_cases() -> Iterator[Case]:  # noqa: PLR0915 - one list of cases, read top to bottom
    """Round hostile30's second batch, every input kind: maps (keys passed over without an image, names that differ
    only by case or by Unicode's composition, names holding a NUL or an escape through YAML's escapes, a map of only
    a BOM or of only comments), map images (PNGs cut short, with a wrong CRC, 16-bit, with a palette, a GIF named
    .png, ``/proc/self/mem``), frame libraries (a folder holding a FIFO, a dangling link or a loop; a frame file of
    only a BOM; a frame name with a zero-width space; an unclosed string at the end), vocabularies, observations and
    trajectories (empty, CR-only, nested deep), command texts (zero-width, fullwidth, combining, tag characters,
    variation selectors, an ideographic space alone, a line separator), ``seal validate`` given one file twice."""
    small = b"name: m\nbounds: [0, 0, 10, 10]\nrooms:\n  - {name: kitchen, box: [0, 0, 5, 10]}\n" \
            b"  - {name: hall, box: [5, 0, 10, 10]}\n"
    def map_case(name: str, data: bytes, codes: tuple[int, ...], says: str,
                 argv: tuple[str, ...] = ("validate", "m.yaml"), *more: tuple[str, bytes | str]) -> Case:
        return Case(f"A {argv[0]} of a map {name}", argv, (("m.yaml", data), *more), codes=codes,
                    keep=("m.yaml", *(n for n, c in more if isinstance(c, bytes))), says=says)
    # -- maps ----------------------------------------------------------------------------------------------------------
    yield map_case("whose resolution is a word and has no image", small + b"resolution: abc\n", (1,),
                   r"m\.yaml:6:\d+: .*resolution")
    yield map_case("whose origin is a mapping and has no image", small + b"origin: {x: 1}\n", (1,),
                   r"m\.yaml:6:\d+: .*origin")
    yield map_case("whose rooms differ only by case", small.replace(b"name: hall", b"name: Kitchen"), (1,),
                   r"m\.yaml:5:\d+: .*[Kk]itchen")
    yield map_case("whose rooms differ only by Unicode's composition", small.replace(b"kitchen", "café".encode())
                   .replace(b"name: hall", "name: cafe\u0301".encode()), (1,), r"m\.yaml:5:\d+: .*caf")
    yield map_case("whose room's name holds a NUL through a YAML escape",
                   small.replace(b"name: hall", b'name: "ha\\0ll"'), (1,), r"m\.yaml:5:\d+: ")
    yield map_case("whose place's name holds an escape sequence through a YAML escape",
                   small + b'places:\n  - {name: "sink\\e[31m_1", class: sink, at: [1, 1]}\n', (1,),
                   r"m\.yaml:7:\d+: ")
    yield map_case("whose class holds a zero-width space", small + "places:\n  - {name: sink_1, class: \"si\u200bnk\","
                   " at: [1, 1]}\n".encode(), (1,), r"m\.yaml:7:\d+: ")
    yield map_case("of only a BOM", b"\xef\xbb\xbf", (1,), r"m\.yaml: ")
    yield map_case("of only comments and CRLF", b"# a map\r\n# more\r\n", (1,), r"m\.yaml: ")
    yield Case("A validate of a map of one flow line of 2 MB, its 60,000 rooms one over another",
               ("validate", "m.yaml"),
               (("m.yaml", b"{name: m, bounds: [0, 0, 10, 10], rooms: [" + b", ".join(
                   b"{name: r%d, box: [0, 0, 1, 1]}" % i for i in range(60_000)) + b"]}\n"),), codes=(1,),
               keep=("m.yaml",), says=r"m\.yaml:1:\d+: ", timeout=180)
    yield map_case("whose robot's pose is a string of digits", small + b"robot: {pose: '1 2 0'}\n", (1,),
                   r"m\.yaml:6:\d+: .*pose")
    yield map_case("whose bounds are nested 50,000 deep", small.replace(b"bounds: [0, 0, 10, 10]",
                                                                         b"bounds: " + b"[" * 50_000 + b"]" * 50_000),
                   (1,), r"m\.yaml:2:\d+: ")
    # -- map images ----------------------------------------------------------------------------------------------------
    (_, head), (_, pgm) = robot_map()
    png_head = head.replace(b"image: map.pgm", b"image: map.png")
    def image_case(name: str, data: bytes, codes: tuple[int, ...], says: str) -> Case:
        return Case(f"A validate of a ROS map whose image {name}", ("validate", "m.yaml"),
                    (("m.yaml", png_head), ("map.png", data)), codes=codes, keep=("m.yaml", "map.png"), says=says)
    good = _png(200, 200)
    yield image_case("is a PNG cut short in its pixels", good[:60], (1,), r"m\.yaml:1:8: ")
    yield image_case("is a PNG whose CRCs are wrong", _png(200, 200, crc=False), (1,), r"m\.yaml:1:8: ")
    yield image_case("is a 16-bit grey PNG", _png(200, 200, depth=16), (0,), r"ok: ")
    yield image_case("is a PNG with a palette", _png(200, 200, colour=3, rows=(b"\x00" + b"\x00" * 200) * 200), (0,),
                     r"ok: ")
    yield image_case("is a PNG of width 0", _png(0, 200), (1,), r"m\.yaml:1:8: ")
    yield image_case("is a GIF named .png", b"GIF89a\x01\x00\x01\x00\x00\x00\x00;", (1,), r"m\.yaml:1:8: ")
    yield image_case("is a PNG whose pixels are 10 MB of zeros once decompressed", _png(
        200, 200, rows=b"\x00" * 10_000_000), (1,), r"m\.yaml")
    yield Case("A validate of a ROS map whose image is /proc/self/mem", ("validate", "m.yaml"),
               (("m.yaml", head.replace(b"image: map.pgm", b"image: /proc/self/mem")),), codes=(1,), keep=("m.yaml",),
               says=r"m\.yaml:1:8: ")
    yield Case("A validate of a ROS map whose image is /dev/stdin, stdin closed", ("validate", "m.yaml"),
               (("m.yaml", head.replace(b"image: map.pgm", b"image: /dev/stdin")),), codes=(1,), keep=("m.yaml",),
               stream="closed-stdin", says=r"m\.yaml:1:8: ")
    yield Case("A validate of a ROS map whose PGM header has a comment with a NUL and Latin-1",
               ("validate", "m.yaml"),
               (("m.yaml", head), ("map.pgm", pgm.replace(b"P5\n", b"P5\n# caf\xe9 \x00\n", 1))), codes=(0,),
               keep=("m.yaml", "map.pgm"), says=r"ok: ")
    # -- frame libraries -----------------------------------------------------------------------------------------------
    whisk = b'frame Whisk "whisk" {\n  theme: object\n  do navigate(theme)\n}\n'
    lib = ("plan", "whisk the cup", "--framelib", "+d")
    yield Case("A plan --framelib of a folder holding a FIFO named .frame", lib,
               (("d/a.frame", whisk), ("d/b.frame", "fifo")), codes=(1,), keep=("d/a.frame",), says=r"d/b\.frame",
               timeout=30)
    yield Case("A plan --framelib of a folder holding a dangling link", lib,
               (("d/a.frame", whisk), ("d/b.yaml", "link:nowhere.yaml")), codes=(1,), keep=("d/a.frame",),
               says=r"d/b\.yaml")
    yield Case("A plan --framelib of a folder holding a link to itself", lib,
               (("d/a.frame", whisk), ("d/b.frame", "link:b.frame")), codes=(1,), keep=("d/a.frame",),
               says=r"d/b\.frame")
    yield Case("A plan --framelib of a folder holding a link to the folder", lib,
               (("d/a.frame", whisk), ("d/e", "link:.")), codes=(0,), keep=("d/a.frame",), says=r"Whisk")
    yield Case("A plan --framelib of a frame file of only a BOM", ("plan", "go to the kitchen", "--framelib",
                                                                  "+f.frame"),
               (("f.frame", b"\xef\xbb\xbf"),), codes=(0, 1), keep=("f.frame",), says=r"f\.frame|Go")
    yield Case("A validate of a frame whose name holds a zero-width space", ("validate", "f.frame"),
               (("f.frame", whisk.replace(b"frame Whisk", "frame Wh\u200bisk".encode())),), codes=(1,),
               keep=("f.frame",), says=r"f\.frame:1:\d+: ")
    yield Case("A validate of a frame file ending inside a string", ("validate", "f.frame"),
               (("f.frame", b'frame Whisk "whisk'),), codes=(1,), keep=("f.frame",), says=r"f\.frame:1:\d+: ")
    yield Case("A plan on a frame file with a NUL in a comment", ("plan", "whisk the cup", "--framelib", "+f.frame"),
               (("f.frame", b"// a \x00 comment\n" + whisk),), codes=(0,), keep=("f.frame",), says=r"Whisk")
    yield Case("A plan on a YAML frame whose unit holds a line separator", ("plan", "whisk the cup", "--framelib",
                                                                             "+f.yaml"),
               (("f.yaml", b'frames:\n  - frame: Whisk\n    lexical_units: ["whisk\\L"]\n    elements:\n'
                           b"      theme: {type: object}\n    actions: [navigate(theme)]\n"),), codes=(0,),
               keep=("f.yaml",), says=r"Whisk")
    yield Case("A validate of the same frame file given twice", ("validate", "f.frame", "./f.frame"),
               (("f.frame", whisk),), codes=(0, 1), keep=("f.frame",), says=r"(?s)f\.frame")
    yield Case("A validate of a frame file and a link to it", ("validate", "f.frame", "l.frame"),
               (("f.frame", whisk), ("l.frame", "link:f.frame")), codes=(0, 1), keep=("f.frame",),
               says=r"(?s)\.frame")
    # -- vocabularies, observations, trajectories ----------------------------------------------------------------------
    loc = ("localize", "--map", "apartment", "--task", "go to the kitchen", "--steps", "1", "--particles", "20")
    yield Case("A parse --vocabulary of only a BOM", ("parse", "--vocabulary", "v.yaml", "stir the cup"),
               (("v.yaml", b"\xef\xbb\xbf"),), codes=(0, 1), keep=("v.yaml",), says=r"v\.yaml|Stir|stir")
    yield Case("A parse --vocabulary nested 50,000 deep", ("parse", "--vocabulary", "v.yaml", "stir the cup"),
               (("v.yaml", b"cup: " + b"[" * 50_000 + b"]" * 50_000 + b"\n"),), codes=(1,), keep=("v.yaml",),
               says=r"v\.yaml:1:\d+: ")
    yield Case("A localize --observations of CR-only lines", (*loc, "--observations", "o.yaml"),
               (("o.yaml", b"- pose: [-6, -3]\r  detections: []\r- pose: [-6, -3]\r  detections: []\r"),),
               codes=(0,), keep=("o.yaml",), says=r"(?s).")
    yield Case("A localize --observations nested 50,000 deep", (*loc, "--observations", "o.yaml"),
               (("o.yaml", b"- pose: " + b"[" * 50_000 + b"]" * 50_000 + b"\n"),), codes=(1,), keep=("o.yaml",),
               says=r"o\.yaml:1:\d+: ")
    yield Case("A localize --trajectory of only a BOM and CRLF", (*loc, "--trajectory", "t.yaml"),
               (("t.yaml", b"\xef\xbb\xbf\r\n"),), codes=(1,), keep=("t.yaml",), says=r"t\.yaml")
    yield Case("A localize --observations whose detection's class holds a NUL", (*loc, "--observations", "o.yaml"),
               (("o.yaml", b'- pose: [-6, -3]\n  detections: [{class: "cu\\0p", at: [-5, -3]}]\n'),), codes=(1,),
               keep=("o.yaml",), says=r"o\.yaml:2:\d+: ")
    yield Case("A localize --labels of a mapping with a key twice", ("localize", "--map", "apartment", "--bag",
                                                                     "x.mcap", "--labels", "l.yaml", "--task",
                                                                     "go to the kitchen"),
               (("l.yaml", b"1: cup\n1: spoon\n"), ("x.mcap", b"\x89MCAP0\r\n")), codes=(1,), keep=("l.yaml",),
               says=r"l\.yaml:2:1: |x\.mcap")
    # -- command texts -------------------------------------------------------------------------------------------------
    run = ("run", "--map", "studio", "--particles", "20")
    def said(name: str, text: str, codes: tuple[int, ...], says: str, argv: tuple[str, ...] = run) -> Case:
        return Case(f"A {argv[0]} of a command {name}", (argv[0], text, *argv[1:]), codes=codes, says=says)
    yield said("with a zero-width space inside a word", "go to the so\u200bfa", (0, 1), r"column \d+|done: Go")
    yield said("with a zero-width joiner inside a word", "go to the so\u200dfa", (0, 1), r"column \d+|done: Go")
    yield said("in fullwidth letters", "ｇｏ ｔｏ ｔｈｅ ｓｏｆａ", (0, 1), r"column \d+|done: Go")
    yield said("whose every letter has a combining mark", "".join(c + "\u0308" if c.isalpha() else c
                                                                 for c in "go to the sofa"), (1,), r"column \d+")
    yield said("of Unicode tag characters", "go to the sofa\U000e0067\U000e006f", (0, 1), r"column \d+|done: Go")
    yield said("with a variation selector", "go to the sofa\ufe0f", (0, 1), r"column \d+|done: Go")
    yield said("of an ideographic space alone", "\u3000", (1, 2), r"empty|command|nothing")
    yield said("holding a line separator", "go to the sofa\u2028and open the fridge", (0, 1),
               r"column \d+|done: ")
    yield said("with a right-to-left mark between words", "go to\u200f the sofa", (0, 1), r"column \d+|done: Go")
    yield said("with a BOM inside", "go to the\ufeff sofa", (0, 1), r"column \d+|done: Go")
    yield said("of a Hangul filler", "go to the \u3164", (1,), r"column \d+")
    yield said("of emoji with skin tones and joiners", "go to the \U0001f469\U0001f3fd\u200d\U0001f373", (1,),
               r"column \d+")
    yield said("with a dotted capital I", "GO TO THE SOFA \u0130", (0, 1), r"column \d+|done: Go")
    yield Case("A plan --holding of a zero-width space", ("plan", "put it on the table", "--map", "apartment",
                                                          "--holding", "\u200b"), codes=(1,), says=r"--holding")
    yield Case("A plan --holding with a right-to-left override", ("plan", "put it on the table", "--map", "apartment",
                                                                  "--holding", "cu\u202ep"), codes=(1,),
               says=r"--holding")
    yield Case("A localize --task of a zero-width joiner alone", ("localize", "--map", "apartment", "--task",
                                                                  "\u200d", "--steps", "1", "--particles", "20"),
               codes=(1, 2), says=r"--task|empty|command")
    yield Case("A parse --file of a BOM, CRLF and a line of only a zero-width space", ("parse", "--file", "c.txt"),
               (("c.txt", "\ufeffgo to the kitchen\r\n\u200b\r\nopen the fridge\r\n".encode()),), codes=(0, 1),
               keep=("c.txt",), says=r"c\.txt:2|Go|Open")
    # found by hand after the batch's fixes: a FIFO where the scorer goes was "scorer not found"
    yield Case("A bench parse --scorers whose score_parse.py is a FIFO", ("bench", "parse", "--corpus", "c.jsonl",
                                                                          "--scorers", "s"),
               (("c.jsonl", b'{"text": "go to the kitchen", "expect": [{"frame": "Go"}]}\n'),
                ("s/score_parse.py", "fifo")), codes=(1,), keep=("c.jsonl",),
               says=r"scorer s/score_parse\.py is a FIFO", timeout=30)


def hostile30_output_cases() -> Iterator[Case]:  # noqa: PLR0915 - one list of cases, read top to bottom
    """Round hostile30's third batch, outputs and interrupted writes: an output that is an input through ``..``,
    ``./``, a link into a folder, a hard link, a shipped map's image reached by an absolute link; names that differ
    from an input only by case (another file: written); ``plan --pddl`` into the folder of an input named like its
    files; ``--goals``, ``import-bag -o`` and ``bench tasks --episodes`` past ``ulimit -f`` and stopped by SIGTERM,
    SIGHUP or SIGINT while writing; bags that are empty, garbage, a FIFO, ``/dev/zero`` by a link, cut short."""
    from seal_cli.resources import map_path

    loc = ("localize", "--map", "apartment", "--task", "go to the kitchen", "--steps", "2", "--particles", "20")
    obs = b"- pose: [-6, -3]\n  detections: []\n- pose: [-5.5, -3]\n  detections: []\n"
    # -- an output that is an input, however it is reached ---------------------------------------------------------
    yield Case("A localize --goals onto its observations through d/..", (*loc, "--observations", "o.yaml", "--goals",
                                                                         "d/../o.yaml"),
               (("o.yaml", obs), ("d", "dir")), codes=(1,), keep=("o.yaml",), says=r"--goals d/\.\./o\.yaml")
    yield Case("A localize --goals onto its observations through ./", (*loc, "--observations", "o.yaml", "--goals",
                                                                       "./o.yaml"),
               (("o.yaml", obs),), codes=(1,), keep=("o.yaml",), says=r"--goals (\./)?o\.yaml is an input")
    yield Case("A localize --goals onto its trajectory through a link to its folder",
               (*loc, "--trajectory", "d/t.yaml", "--goals", "l/t.yaml"),
               (("d/t.yaml", b"poses:\n  - [-6, -3]\n  - [-5.5, -3]\n"), ("l", "link:d")), codes=(1,),
               keep=("d/t.yaml",), says=r"--goals l/t\.yaml")
    yield Case("A localize --goals named as its observations but for case", (*loc, "--observations", "o.yaml",
                                                                             "--goals", "O.yaml"),
               (("o.yaml", obs),), codes=(0,), keep=("o.yaml",), whole=("O.yaml",), says=r"(?s).")
    image = str(map_path("apartment").with_suffix(".pgm"))
    yield Case("A run --png onto a link to the shipped map's image",
               ("run", "go to the kitchen", "--map", "apartment", "--particles", "20", "--png", "l.png"),
               (("l.png", f"link:{image}"),), codes=(1,), says=r"--png l\.png would overwrite the input")
    yield Case("A map --png onto a link to the shipped map's own YAML", ("map", "apartment", "--png", "l.png"),
               (("l.png", f"link:{map_path('apartment')}"),), codes=(1,), says=r"--png l\.png would overwrite")
    yield Case("A plan --pddl into the folder of its vocabulary named domain.pddl",
               ("plan", "stir the cup", "--vocabulary", "d/domain.pddl", "--pddl", "d"),
               (("d/domain.pddl", b"cup: [mug]\n"),), codes=(1,), keep=("d/domain.pddl",),
               says=r"--pddl .*d/domain\.pddl would overwrite")
    yield Case("A plan --pddl whose problem.pddl is a hard link to its frame file",
               ("plan", "whisk the cup", "--framelib", "+f.frame", "--pddl", "d"),
               (("f.frame", b'frame Whisk "whisk" {\n  theme: object\n  do navigate(theme)\n}\n'),
                ("d/problem.pddl", "hard:f.frame")), codes=(1,), keep=("f.frame", "d/problem.pddl"),
               says=r"--pddl .*d/problem\.pddl would overwrite")
    data = alfred2d_data()
    yield Case("A bench tasks --episodes onto its trials through d/../d", ("bench", "tasks", "--data", "d",
                                                                        "--policies", "sefm", "--jobs", "1",
                                                                        "--particles", "20", "--episodes",
                                                                        "d/../d/trials_valid_seen.jsonl"),
               data, codes=(1,), keep=tuple(n for n, _ in data), says=r"--episodes d/\.\./d/trials_valid_seen\.jsonl")
    # -- interrupted and cut-short writes --------------------------------------------------------------------------
    yield Case("A localize --goals of 235 bytes within ulimit -f of 512 bytes", (*loc, "--observations", "o.yaml",
                                                                             "--goals", "g.yaml"),
               (("o.yaml", obs),), codes=(0,), keep=("o.yaml",), whole=("g.yaml",), file_blocks=1, says=r"(?s).")
    yield Case("A localize --goals .mcap past ulimit -f of 512 bytes", (*loc, "--observations", "o.yaml", "--goals",
                                                                        "g.mcap"),
               (("o.yaml", obs),), codes=(1,), keep=("o.yaml",), absent=("g.mcap",), file_blocks=1,
               says=r"error: cannot write --goals g\.mcap: File too large")
    tiny = ("bench", "tasks", "--suite", "map", "--map", "studio", "--command", "go to the sofa", "--layouts", "3",
            "--policies", "oracle,sefm", "--particles", "20", "--episodes", "e.jsonl")
    yield Case("A bench tasks --episodes past ulimit -f of 512 bytes", (*tiny, "--jobs", "1"), codes=(1,),
               absent=("e.jsonl",), file_blocks=1, says=r"--episodes e\.jsonl: File too large|File too large",
               timeout=120)
    yield Case("A SIGTERM during bench tasks --jobs 2 --episodes", (*tiny, "--jobs", "2"), codes=(143,),
               absent=("e.jsonl",), signal=(15, 4.0), timeout=120)
    yield Case("A SIGHUP during localize --goals", ("localize", "--map", "apartment", "--task", "go to the kitchen",
                                                    "--steps", "400", "--particles", "2000", "--goals", "g.yaml"),
               codes=(129,), absent=("g.yaml",), signal=(1, 4.0), timeout=60)
    # -- bags ------------------------------------------------------------------------------------------------------
    bag = _sample_bag()
    if bag is None:
        return
    yield Case("A import-bag -o onto its bag through d/..", ("import-bag", "run.mcap", "-o", "d/../run.mcap"),
               (("run.mcap", bag), ("d", "dir")), codes=(1,), keep=("run.mcap",), says=r"-o d/\.\./run\.mcap")
    yield Case("A import-bag -o past ulimit -f of 512 bytes", ("import-bag", "run.mcap", "-o", "o.yaml"),
               (("run.mcap", bag),), codes=(1,), keep=("run.mcap",), absent=("o.yaml",), file_blocks=1,
               says=r"File too large")
    yield Case("A SIGINT during import-bag", ("import-bag", "run.mcap", "-o", "o.yaml"), (("run.mcap", bag),),
               codes=(0, 130), keep=("run.mcap",), signal=(2, 1.5))
    yield Case("A import-bag of an empty .mcap", ("import-bag", "e.mcap", "-o", "o.yaml"), (("e.mcap", b""),),
               codes=(1,), keep=("e.mcap",), absent=("o.yaml",), says=r"e\.mcap")
    yield Case("A import-bag of an MCAP cut in half", ("import-bag", "h.mcap", "-o", "o.yaml"),
               (("h.mcap", bag[:len(bag) // 2]),), codes=(0, 1), keep=("h.mcap",), says=r"h\.mcap|observations")
    yield Case("A import-bag of a .db3 of garbage", ("import-bag", "g.db3", "-o", "o.yaml"),
               (("g.db3", b"SQLite format 3\x00" + bytes(range(256)) * 40),), codes=(1,), keep=("g.db3",),
               absent=("o.yaml",), says=r"g\.db3")
    yield Case("A import-bag of a ROS 1 .bag cut after its header", ("import-bag", "r.bag", "-o", "o.yaml"),
               (("r.bag", b"#ROSBAG V2.0\n" + b"\x00" * 64),), codes=(1,), keep=("r.bag",), absent=("o.yaml",),
               says=r"r\.bag")
    yield Case("A import-bag of a FIFO named .mcap", ("import-bag", "f.mcap", "-o", "o.yaml"), (("f.mcap", "fifo"),),
               codes=(1,), absent=("o.yaml",), says=r"f\.mcap", timeout=30)
    yield Case("A import-bag of a link to /dev/zero named .mcap", ("import-bag", "z.mcap", "-o", "o.yaml"),
               (("z.mcap", "link:/dev/zero"),), codes=(1,), absent=("o.yaml",), says=r"z\.mcap", timeout=30)
    yield Case("A localize --bag of an empty .mcap", (*loc, "--bag", "e.mcap"), (("e.mcap", b""),), codes=(1,),
               keep=("e.mcap",), says=r"e\.mcap")
    folder = _bag_folder()
    meta = dict(folder)["x/metadata.yaml"]
    yield Case("A import-bag of a ROS 2 bag folder whose database is a FIFO", ("import-bag", "x", "-o", "o.yaml"),
               (("x/metadata.yaml", meta), ("x/out.db3", "fifo")), codes=(1,), keep=("x/metadata.yaml",),
               absent=("o.yaml",), says=r"x/out\.db3: .*FIFO", timeout=30)
