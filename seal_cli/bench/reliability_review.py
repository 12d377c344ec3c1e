"""The reviewer's hostile inputs of ``seal bench reliability``: what a hostile reviewer runs on
every subcommand and option, unlike the issue's cases and the generated mutations.

Each case says what the command must answer: its exit codes, and for a refusal the shape of its
message (``says``: a pattern stderr must hold, naming the file, line and column or the option).
The kinds, in order: encodings (UTF-16 big-endian, NUL bytes, a lone CR, Latin-1 in every file a
command reads and on standard input), numbers (NaN, infinity, 1e309, negatives, hexadecimal,
booleans) in priors, poses, sensors, map fields, observations and every numeric option of the
benchmarks not tried before, YAML made hostile (nesting 10,000 deep, billion-laughs aliases,
merge keys, tags, a stream of documents, tab indentation), occupancy images made hostile
(wrong magic, truncated, 16 bits, P2 ASCII, 0 by 0, 100,000 by 100,000 declared, a PNG named
``.pgm``, a folder, itself, a link to itself), paths (Unicode, a leading dash, 300 characters,
a trailing slash, ``.``), outputs (missing folders, links and hard links to inputs for every
writing option, concurrent writers, SIGINT while writing), standard streams (stdin closed,
stdout closed, stdout ``/dev/full``), sizes (10,000 frames, a command of 100,000 characters, a
file of 5,000 commands), maps whose rooms do not hold their places, unknown map names,
detections of classes nobody knows, and bags (if the ``ros`` extra is installed).

:func:`cases` is the whole suite: the issue's cases, the hostile inputs written by hand, these,
then the generated ones.
"""

from __future__ import annotations

import signal
from collections.abc import Iterator

from seal_cli.bench.reliability import (
    FRAME,
    FRAME_YAML,
    OBSERVATIONS,
    Case,
    generated_cases,
    hostile_cases,
    hostile_setting,
    issue_cases,
)

__all__ = ["cases", "review_cases"]

WHERE = r"(?m)^(error: )?{}:\d+:\d+: "
"""A refusal naming ``file:line:col`` (the file's name filled in, escaped)."""

WARNS = r"(?m)^warning: m\.yaml:\d+:\d+: "
"""A warning about ``m.yaml`` at its line and column."""


def _at(name: str) -> str:
    import re

    return WHERE.format(re.escape(name))


def _named(name: str) -> str:
    """A refusal naming a file or an argument (anywhere in stderr)."""
    import re

    return re.escape(name)


def _nested(depth: int) -> bytes:
    return ("[" * depth + "]" * depth + "\n").encode()


def _laughs(levels: int = 9) -> str:
    rows = ['a0: &a0 ["lol", "lol", "lol", "lol", "lol", "lol", "lol", "lol", "lol", "lol"]']
    rows += [f"a{i}: &a{i} [" + ", ".join([f"*a{i - 1}"] * 10) + "]" for i in range(1, levels)]
    return "\n".join(rows) + "\n"


def _word(i: int) -> str:
    """The i-th word of four letters (aaaa, baaa, ...)."""
    return "".join(chr(97 + (i // 26 ** k) % 26) for k in range(4))


def _frames(n: int) -> bytes:
    out = ["category thing = cup, bowl, spoon", "world holding"]
    for i in range(n):
        word = _word(i)
        out.append(f'frame F{i} "verb{word}" {{\n  x: thing\n  do navigate(x)\n  ensures done{i}(x)\n}}')
    return ("\n".join(out) + "\n").encode()


def _pgm(width: int, height: int, maxval: int = 255, magic: bytes = b"P5", data: bytes | None = None) -> bytes:
    head = magic + f"\n{width} {height}\n{maxval}\n".encode()
    if data is None:
        data = bytes([254]) * (width * height * (2 if maxval > 255 else 1))
    return head + data


def _bag_cases(both: tuple[tuple[str, bytes], ...]) -> Iterator[Case]:
    """Bags: garbage under every bag suffix, truncated real bags, labels made hostile."""
    try:
        import rosbags  # noqa: F401
    except ImportError:
        return
    import tempfile
    from pathlib import Path

    import numpy as np

    from seal_cli.bench.ros import write_run
    from seal_cli.maps.formats.map_server import load_map
    from seal_cli.resources import map_path

    good: dict[str, bytes] = {}
    with tempfile.TemporaryDirectory() as folder:
        for name in ("run.bag", "run.mcap"):
            write_run(Path(folder) / name, load_map(map_path("apartment")), 20, 5, np.random.default_rng(0))
            good[name] = (Path(folder) / name).read_bytes()
    for k, (suffix, data) in enumerate(((".bag", b"#ROSBAG V2.0\n"), (".bag", b"\x00" * 4096),
                                        (".mcap", b"\x89MCAP0\r\n"),
                                        (".mcap", good["run.mcap"][: len(good["run.mcap"]) // 2]),
                                        (".bag", good["run.bag"][: len(good["run.bag"]) // 3]),
                                        (".db3", b"SQLite format 3\x00"), (".db3", b""),
                                        (".bag", "ünïcode ☃".encode()))):
        name = f"b{suffix}"
        yield Case(f"R bag {k} ({suffix}, {len(data)} bytes): import-bag", ("import-bag", name, "-o", "o.yaml"),
                   ((name, data),), codes=(1,), keep=(name,), absent=("o.yaml",), says=_named(name))
        yield Case(f"R bag {k} ({suffix}, {len(data)} bytes): localize --bag",
                   ("localize", "--map", "m.yaml", "--bag", name, "--steps", "0", "--particles", "10"),
                   (*both, (name, data)), codes=(1,), keep=(name,), says=_named(name))
    bag = ("run.mcap", good["run.mcap"])
    yield Case("R a ROS 2 folder whose metadata.yaml is garbage", ("import-bag", "b2", "-o", "o.yaml"),
               (("b2/metadata.yaml", b"rosbag2_bagfile_information: [[[\n"), ("b2/b2_0.db3", b"")), codes=(1,),
               absent=("o.yaml",), says=_named("b2"))
    yield Case("R import-bag -o onto the bag through a link", ("import-bag", "run.mcap", "-o", "l.yaml"),
               (bag, ("l.yaml", "link:run.mcap")), codes=(1,), keep=("run.mcap",), says=_named("-o"))
    yield Case("R import-bag -o onto its --labels", ("import-bag", "run.mcap", "--labels", "lab.yaml", "-o",
                                                    "lab.yaml"),
               (bag, ("lab.yaml", b"0: cup\n")), codes=(1,), keep=("run.mcap", "lab.yaml"), says=_named("lab.yaml"))
    yield Case("R import-bag -o into a missing folder", ("import-bag", "run.mcap", "-o", "no/o.yaml"), (bag,),
               codes=(1,), keep=("run.mcap",), says=_named("no"))
    yield Case("R import-bag -o with the wrong suffix", ("import-bag", "run.mcap", "-o", "o.json"), (bag,),
               codes=(1,), absent=("o.json",), says=_named("o.json"))
    yield Case("R import-bag of a good bag writes whole YAML", ("import-bag", "run.mcap", "-o", "ok.yaml"), (bag,),
               codes=(0,), keep=("run.mcap",), whole=("ok.yaml",))
    for label, data in (("NaN ids", b".nan: cup\n"), ("a nested labels file", _nested(10_000)),
                        ("labels in UTF-16", "0: cup\n".encode("utf-16")), ("a list for labels", b"- cup\n"),
                        ("an alias bomb", _laughs().encode()), ("an empty class", b"0: ''\n")):
        yield Case(f"R --labels {label}", ("import-bag", "run.mcap", "--labels", "lab.yaml", "-o", "o.yaml"),
                   (bag, ("lab.yaml", data)), codes=(0, 1), keep=("lab.yaml", "run.mcap"))
    for option, value in (("--pose-topic", "/nope"), ("--detections-topic", "/nope"), ("--frame", ""),
                          ("--base-frame", "\x01"), ("--pose-topic", "x" * 5000)):
        yield Case(f"R import-bag {option} {value[:10]!r}", ("import-bag", "run.mcap", option, value, "-o", "o.yaml"),
                   (bag,), codes=(1, 2), absent=("o.yaml",))
    yield Case("R SIGINT during import-bag -o", ("import-bag", "run.mcap", "-o", "o.yaml"), (bag,),
               codes=(0, 130, -int(signal.SIGINT)), keep=("run.mcap",), signal=(int(signal.SIGINT), 0.8))
    yield Case("R two import-bag -o at once onto one file", ("import-bag", "run.mcap", "-o", "o.yaml"), (bag,),
               codes=(0,), parallel=2, whole=("o.yaml",), keep=("run.mcap",))


def review_cases() -> Iterator[Case]:  # noqa: PLR0915 - one list of cases, read top to bottom
    """The reviewer's cases, kind by kind (see the module's description)."""
    m, image, text, both, inputs, loc, frame = hostile_setting()
    argv: tuple[str, ...]
    data: bytes | str
    files: tuple[tuple[str, bytes | str], ...]

    # -- encodings -----------------------------------------------------------------------------------
    yield Case("R UTF-16 BE with a BOM: validate a .frame", ("validate", "f.frame"),
               (("f.frame", FRAME.encode("utf-16-be").join([b"\xfe\xff", b""])),), codes=(1,), keep=("f.frame",),
               says=_at("f.frame"))
    yield Case("R UTF-16 with a BOM: frame YAML", ("validate", "f.yaml"), (("f.yaml", FRAME_YAML.encode("utf-16")),),
               codes=(1,), keep=("f.yaml",), says=_at("f.yaml"))
    yield Case("R UTF-16 with a BOM: trajectory", (*loc, "--trajectory", "t.yaml"),
               (*both, ("t.yaml", "poses:\n  - [-6.0, -3.0]\n".encode("utf-16"))), codes=(1,), keep=("t.yaml",),
               says=_at("t.yaml"))
    yield Case("R UTF-16 with a BOM: --vocabulary", ("parse", "--vocabulary", "v.yaml", "stir the cup"),
               (("v.yaml", "- cup\n- spoon\n".encode("utf-16")),), codes=(1,), keep=("v.yaml",), says=_at("v.yaml"))
    yield Case("R UTF-16 with a BOM: bench plan --file", ("bench", "plan", "--file", "c.txt", "--repeat", "1"),
               (("c.txt", "stir the cup\n".encode("utf-16")),), codes=(1,), keep=("c.txt",), says=_at("c.txt"))
    yield Case("R UTF-16 with a BOM on stdin", ("parse", "--file", "-"), codes=(1,),
               stdin="stir the cup\n".encode("utf-16"), says=r"(?m)^(error: )?(-|<stdin>|standard input):\d+:\d+")
    yield Case("R UTF-16 with a BOM: bench e2e --file", ("bench", "e2e", "--file", "e.yaml", "--limit", "1"),
               (("e.yaml", "- {map: apartment, command: stir the cup}\n".encode("utf-16")),), codes=(1,),
               keep=("e.yaml",), says=_at("e.yaml"))
    nul = {"map": ("m.yaml", text.replace("name: apartment", "name: apart\x00ment").encode()),
           "frame YAML": ("f.yaml", FRAME_YAML.replace("Whisk", "Wh\x00isk").encode()),
           "observations": ("o.yaml", OBSERVATIONS.replace("cup", "c\x00up").encode()),
           "trajectory": ("t.yaml", b"poses:\n  - [-6.0,\x00 -3.0]\n"),
           "vocabulary": ("v.yaml", b"- cup\n- sp\x00oon\n")}
    runs = {"map": ("validate", "m.yaml"), "frame YAML": ("validate", "f.yaml"),
            "observations": (*loc, "--observations", "o.yaml"), "trajectory": (*loc, "--trajectory", "t.yaml"),
            "vocabulary": ("parse", "--vocabulary", "v.yaml", "stir the cup")}
    for what, (name, data) in nul.items():
        files = (*both, (name, data)) if name != "m.yaml" else ((name, data), image)
        yield Case(f"R a NUL byte in the {what}", runs[what], files, codes=(1,), keep=(name,), says=_at(name))
    yield Case("R a lone CR ends every line of a map", ("validate", "m.yaml"), (("m.yaml", text.replace("\n", "\r")
                                                                               .encode()), image), keep=inputs)
    yield Case("R a lone CR ends every line of observations", (*loc, "--observations", "o.yaml"),
               (*both, ("o.yaml", OBSERVATIONS.replace("\n", "\r").encode())), keep=("o.yaml",))
    yield Case("R CRLF observations", (*loc, "--observations", "o.yaml"),
               (*both, ("o.yaml", OBSERVATIONS.replace("\n", "\r\n").encode())), codes=(0,), keep=("o.yaml",))
    yield Case("R CRLF frame YAML", ("validate", "f.yaml"), (("f.yaml", FRAME_YAML.replace("\n", "\r\n").encode()),),
               codes=(0,), keep=("f.yaml",))
    yield Case("R CRLF and a lone CR on stdin", ("parse", "--file", "-", "--json"), codes=(0,),
               stdin=b"stir the cup\r\npick up the cup\rstir\n", twice=True)
    yield Case("R Latin-1 in the map's image name", ("validate", "m.yaml"),
               (("m.yaml", text.replace("image: apartment.pgm", "image: caf\xe9.pgm").encode("latin-1")), image),
               codes=(1,), keep=("m.yaml",), says=_at("m.yaml"))
    yield Case("R Latin-1 in a command file of bench plan", ("bench", "plan", "--file", "c.txt", "--repeat", "1"),
               (("c.txt", b"stir the caf\xe9\n"),), codes=(1,), keep=("c.txt",), says=_at("c.txt"))
    yield Case("R a BOM then CRLF: map", ("validate", "m.yaml"),
               (("m.yaml", b"\xef\xbb\xbf" + text.replace("\n", "\r\n").encode()), image), codes=(0,), keep=inputs)

    # -- numbers ---------------------------------------------------------------------------------------
    priors = {"NaN": ".nan", "infinite": ".inf", "negative": "-0.5", "1e309": "1e309", "a string": "lots",
              "a boolean": "true", "zero everywhere": "0"}
    for what, value in priors.items():
        new = text.replace("cup: {family_room: 0.5, bedroom: 0.5}", f"cup: {{family_room: {value}, bedroom: "
                           f"{'0' if what == 'zero everywhere' else '0.5'}}}")
        yield Case(f"R a prior mass {what}", ("validate", "m.yaml"), (("m.yaml", new.encode()), image),
                   codes=(0, 1) if what == "zero everywhere" else (1,), keep=inputs, says=_at("m.yaml"))
        if what in ("NaN", "negative"):
            yield Case(f"R a prior mass {what}: run", ("run", "stir the cup", "--map", "m.yaml", "--particles", "20"),
                       (("m.yaml", new.encode()), image), codes=(1,), keep=inputs, says=_at("m.yaml"))
    for spot, old, values in (("resolution", "resolution: 0.05", ("0", "-0.05", "1e309", ".nan", "1e-300", "0x10")),
                              ("origin y", "origin: [-10.0, -7.0, 0.0]", (".inf", "1e309", "-1e308")),
                              ("origin yaw", "origin: [-10.0, -7.0, 0.0]", (".nan",)),
                              ("negate", "negate: 0", ("2", "-1", ".nan", "yes")),
                              ("free_thresh", "free_thresh: 0.196", ("0.9", "-1", ".nan")),
                              ("sensor fov", "fov: 360", ("0", "-90", "1e309", ".nan", "720")),
                              ("robot x", "pose: [-6.0, -3.0, 0.0]", (".nan", "1e309", "-1e400")),
                              ("a place's reach", "at: [8.5, -0.8], openable: true", ("-1", ".inf", "0"))):
        for value in values:
            if spot == "origin y":
                new = text.replace(old, f"origin: [-10.0, {value}, 0.0]")
            elif spot == "origin yaw":
                new = text.replace(old, f"origin: [-10.0, -7.0, {value}]")
            elif spot == "robot x":
                new = text.replace(old, f"pose: [{value}, -3.0, 0.0]")
            elif spot == "a place's reach":
                new = text.replace(old, f"at: [8.5, -0.8], openable: true, reach: {value}")
            else:
                new = text.replace(old, f"{old.split(':')[0]}: {value}")
            yield Case(f"R {spot} {value}", ("map", "m.yaml", "--json"), (("m.yaml", new.encode()), image),
                       keep=inputs, says=_at("m.yaml"))
    for what, data in (("theta 1e309", b"- pose: [-6, -3, 1e309]\n"), ("a pose of four numbers",
                                                                        b"- pose: [-6, -3, 0, 1]\n"),
                       ("a boolean x", b"- pose: [true, -3]\n"), ("a hexadecimal x", b"- pose: [0x10, -3]\n"),
                       ("a detection of NaN", b"- pose: [-6, -3]\n  detections: [{class: cup, at: [.nan, .nan]}]\n"),
                       ("a detection far off", b"- pose: [-6, -3]\n  detections: [{class: cup, at: [1e300, 0]}]\n"),
                       ("a number for a class", b"- pose: [-6, -3]\n  detections: [{class: 5, at: [-5, -3]}]\n"),
                       ("1,001 detections", ("- pose: [-6, -3]\n  detections:\n" + "    - {class: cup, at: [-5, -3]}\n"
                                             * 1001).encode())):
        yield Case(f"R observations: {what}", (*loc, "--observations", "o.yaml"), (*both, ("o.yaml", data)),
                   codes=(1,), keep=("o.yaml", *inputs), says=_at("o.yaml"))
    yield Case("R a trajectory of 100,001 poses", (*loc, "--trajectory", "t.yaml"),
               (*both, ("t.yaml", b"poses:\n" + b"  - [-6.0, -3.0]\n" * 100_001)), codes=(1,), keep=("t.yaml",),
               says=_at("t.yaml"), timeout=90)
    for argv, value in ((("bench", "tasks", "--suite", "map", "--sample"), "nan"),
                        (("bench", "tasks", "--suite", "map", "--particles"), "1e309"),
                        (("bench", "tasks", "--suite", "map", "--seed"), "-1"),
                        (("bench", "tasks", "--suite", "map", "--jobs"), "65"),
                        (("bench", "e2e", "--limit"), "-1"), (("bench", "e2e", "--seed"), "nan"),
                        (("bench", "e2e", "--jobs"), "1e309"), (("bench", "ros", "--messages"), "0"),
                        (("bench", "ros", "--poses"), "1"), (("bench", "ros", "--seed"), "inf"),
                        (("bench", "perf", "--seed"), "-1"), (("bench", "maps", "--points"), "0"),
                        (("bench", "maps", "--repeats"), "1001"), (("bench", "startup", "--runs"), "0"),
                        (("bench", "reliability", "--seed"), "nan"), (("bench", "reliability", "--count"), "1e309"),
                        (("localize", "--map", "apartment", "--particles"), "+5e0"),
                        (("localize", "--map", "apartment", "--steps"), "0x10"),
                        (("localize", "--map", "apartment", "--seed"), "1e309"),
                        (("run", "stir the cup", "--map", "apartment", "--max-metres"), "1e309"),
                        (("run", "stir the cup", "--map", "apartment", "--max-metres"), "-0.0"),
                        (("run", "stir the cup", "--map", "apartment", "--max-steps"), "0"),
                        (("plan", "stir the cup", "--max-nodes"), "0"),
                        (("plan", "stir the cup", "--max-nodes"), "-1")):
        yield Case(f"R option {' '.join(argv[:2])} {argv[-1]} {value}", (*argv, value), codes=(1, 2),
                   says=_named(argv[-1]))

    dsl_numbers = {"a category of numbers": FRAME.replace("cup, bowl", "1e309, nan, -5"),
                   "an element typed by a number": FRAME.replace("theme: container", "theme: 1e309"),
                   "a default that is a number": FRAME.replace("= spoon", "= -.inf"),
                   "a fact of a number": FRAME.replace("whisked(theme)", "whisked(1e309)"),
                   "a frame named by a number": FRAME.replace("frame Whisk", "frame 1e309"),
                   "a world predicate of a number": FRAME.replace("world holding", "world 99999999999999999999")}
    for what, source in dsl_numbers.items():
        yield Case(f"R DSL: {what}", ("validate", "f.frame"), (("f.frame", source.encode()),), codes=(1,),
                   keep=("f.frame",), says=_at("f.frame"))
    yaml_numbers = {"a lexical unit of 1e309": FRAME_YAML.replace("[whisk, beat]", "[whisk, 1e309]"),
                    "a type of NaN": FRAME_YAML.replace("{type: container}", "{type: .nan}"),
                    "a default of -inf": FRAME_YAML.replace("default: spoon", "default: -.inf"),
                    "a category member of 0x10": FRAME_YAML.replace("[cup, bowl]", "[cup, 0x10]")}
    for what, source in yaml_numbers.items():
        yield Case(f"R frame YAML: {what}", ("validate", "f.yaml"), (("f.yaml", source.encode()),), codes=(1,),
                   keep=("f.yaml",), says=_at("f.yaml"))
    for amount in ("1e309", "-5", "nan", "0", "1e400", "two hundred"):
        yield Case(f"R a command asking for {amount} cups", ("plan", f"put {amount} cups in the sink"), codes=(0, 1))

    # -- YAML made hostile -----------------------------------------------------------------------------
    for name, argv, data in (("m.yaml", ("validate", "m.yaml"), _nested(10_000)),
                             ("o.yaml", (*loc, "--observations", "o.yaml"), _nested(10_000)),
                             ("t.yaml", (*loc, "--trajectory", "t.yaml"), b"poses: " + _nested(10_000)),
                             ("f.yaml", ("validate", "f.yaml"), b"frames: " + _nested(10_000)),
                             ("v.yaml", ("parse", "--vocabulary", "v.yaml", "stir"), _nested(10_000)),
                             ("d.yaml", ("map", "d.yaml"), ("{a: " * 5000 + "1" + "}" * 5000).encode())):
        yield Case(f"R YAML nested 10,000 deep: {' '.join(argv[:1])} {name}", argv,
                   (*both, (name, data)) if name != "m.yaml" else ((name, data),), codes=(1,), keep=(name,),
                   says=_named(name))
    laughs = _laughs()
    for name, argv, source in (("m.yaml", ("validate", "m.yaml"), text + laughs),
                             ("f.yaml", ("validate", "f.yaml"), FRAME_YAML + laughs),
                             ("v.yaml", ("parse", "--vocabulary", "v.yaml", "stir the cup"), laughs),
                             ("e.yaml", ("bench", "e2e", "--file", "e.yaml"), laughs)):
        yield Case(f"R a billion laughs: {name}", argv, ((name, source.encode()), image), codes=(1,), keep=(name,),
                   says=_named(name))
    yield Case("R an alias of itself in a map", ("validate", "m.yaml"), (("m.yaml", b"rooms: &r [*r]\n"),), codes=(1,),
               keep=("m.yaml",), says=_named("m.yaml"))
    yield Case("R a merge key in a room", ("validate", "m.yaml"),
               (("m.yaml", text.replace("  - {name: bedroom, box: [-9.0, 0.5, -3.0, 6.0]}",
                                        "  - &bed {name: bedroom, box: [-9.0, 0.5, -3.0, 6.0]}\n"
                                        "  - {<<: *bed, name: bedroom2}").encode()), image), keep=inputs)
    for tag in ("!!python/object/apply:os.system ['true']", "!!binary aGVsbG8=", "!!set {a, b}", "!custom x",
                "!!timestamp 2001-12-14"):
        yield Case(f"R a tag in a map's name: {tag[:16]}", ("map", "m.yaml"),
                   (("m.yaml", text.replace("name: apartment", f"name: {tag}").encode()), image),
                   codes=(1,) if "python" in tag else (0, 1), keep=inputs, says=_at("m.yaml"))
    yield Case("R a stream of two YAML documents", ("validate", "m.yaml"), (("m.yaml", (text + "---\n" + text)
                                                                              .encode()), image), codes=(1,),
               keep=inputs, says=_at("m.yaml"))
    yield Case("R tabs indent a map", ("validate", "m.yaml"), (("m.yaml", text.replace("  - {", "\t- {").encode()),
                                                               image), codes=(1,), keep=inputs, says=_at("m.yaml"))
    yield Case("R a map that is one number", ("map", "m.yaml"), (("m.yaml", b"1e309\n"),), codes=(1,),
               says=_at("m.yaml"))
    yield Case("R a map that is a list", ("validate", "m.yaml"), (("m.yaml", b"- rooms\n- places\n"),), codes=(1,),
               says=_at("m.yaml"))
    yield Case("R a repeated key in a map", ("validate", "m.yaml"), (("m.yaml", (text + "name: again\n").encode()),
                                                                     image), codes=(1,), says=_at("m.yaml"))
    yield Case("R a room name of 100,000 characters", ("map", "m.yaml", "--json"),
               (("m.yaml", text.replace("name: bedroom", "name: " + "b" * 100_000).encode()), image), keep=inputs)
    yield Case("R a frame YAML whose frames is a number", ("validate", "f.yaml"),
               (("f.yaml", FRAME_YAML.split("frames:")[0].encode() + b"frames: 5\n"),), codes=(1,),
               says=_at("f.yaml"))
    yield Case("R a frame YAML whose frames is a mapping", ("validate", "f.yaml"),
               (("f.yaml", FRAME_YAML.split("frames:")[0].encode() + b"frames: {a: 1}\n"),), codes=(1,),
               says=_at("f.yaml"))
    yield Case("R a frame YAML with a default of NaN", ("validate", "f.yaml"),
               (("f.yaml", FRAME_YAML.replace("default: spoon", "default: .nan").encode()),), codes=(1,),
               says=_at("f.yaml"))

    # -- occupancy images made hostile -----------------------------------------------------------------
    small = text.replace("image: apartment.pgm", "image: i.pgm")
    images: dict[str, bytes | str] = {
        "a wrong magic": b"P7\n4 4\n255\n" + bytes(16), "a truncated raster": _pgm(360, 240)[:2000],
        "16 bits": _pgm(360, 240, 65535), "P2 ASCII": b"P2\n2 2\n255\n0 255\n255 0\n",
        "0 by 0": _pgm(0, 0), "100,000 by 100,000 declared": _pgm(100_000, 100_000, data=bytes(64)),
        "a negative width": b"P5\n-4 4\n255\n" + bytes(16), "maxval 0": _pgm(4, 4, 0),
        "maxval 70000": _pgm(4, 4, 70000), "a header of comments only": b"P5\n# nothing\n# more\n",
        "a PNG named .pgm": b"\x89PNG\r\n\x1a\n" + bytes(40), "an empty file": b"",
        "a width of 10^30": b"P5\n" + b"9" * 30 + b" 4\n255\n" + bytes(16),
        "a link to itself": "link:i.pgm", "a dangling link": "link:gone.pgm"}
    for what, data in images.items():
        yield Case(f"R map image: {what}", ("map", "m.yaml"), (("m.yaml", small.encode()), ("i.pgm", data)),
                   keep=("m.yaml",), says=_named("i.pgm") if what != "P2 ASCII" else None,
                   codes=(0, 1) if what in ("16 bits", "P2 ASCII") else (1,))
    yield Case("R map image: the image line empty", ("map", "m.yaml"),
               (("m.yaml", text.replace("image: apartment.pgm", "image: ''").encode()),), codes=(1,),
               says=_at("m.yaml"))
    yield Case("R map image: the folder holding the map", ("map", "m.yaml"),
               (("m.yaml", text.replace("image: apartment.pgm", "image: .").encode()),), codes=(1,),
               says=_named("m.yaml"))
    yield Case("R map image: /etc/passwd", ("map", "m.yaml"),
               (("m.yaml", text.replace("image: apartment.pgm", "image: /etc/passwd").encode()),), codes=(1,),
               says=_named("passwd"))
    yield Case("R map image: a Unicode name", ("map", "m.yaml"),
               (("m.yaml", text.replace("image: apartment.pgm", "image: карта 地图.pgm").encode()),
                ("карта 地图.pgm", image[1])), codes=(0,), keep=("m.yaml",))

    # -- paths -----------------------------------------------------------------------------------------
    yield Case("R a Unicode map path", ("map", "карта.yaml"), (("карта.yaml", m[1]), image), codes=(0,))
    yield Case("R a Unicode frame path", ("validate", "frâme 😀.frame"), (("frâme 😀.frame", frame),), codes=(0,))
    yield Case("R a map path starting with a dash", ("map", "--", "-m.yaml"), (("-m.yaml", m[1]), image), codes=(0,))
    yield Case("R a path of 300 characters", ("map", "x" * 300 + ".yaml"), codes=(1,), says=r"x{20}")
    yield Case("R a map path with a trailing slash", ("map", "m.yaml/"), both, says=_named("m.yaml"))
    yield Case("R the map is '.'", ("map", "."), both, codes=(1,), says=r"\.")
    yield Case("R the map is '-'", ("map", "-"), both, codes=(1,), says=r"-")
    yield Case("R the map is /dev/stdin", ("map", "/dev/stdin"), codes=(1,), stdin=m[1], says=_named("/dev/stdin"))
    yield Case("R --framelib a map", ("validate", "m.yaml", "--stdlib"), both, keep=inputs)
    yield Case("R --framelib '+'", ("plan", "--framelib", "+", "stir the cup"), codes=(0, 1))
    yield Case("R --framelib '+nope'", ("plan", "--framelib", "+nope.frame", "stir the cup"), codes=(1,),
               says=_named("nope.frame"))
    yield Case("R --framelib /dev/null", ("plan", "--framelib", "/dev/null", "stir the cup"), codes=(1,),
               says=_named("/dev/null"))
    yield Case("R --framelib an empty folder", ("frames", "--framelib", "lib"), (("lib", "dir"),), codes=(0, 1))
    yield Case("R a frame folder with a .frame folder inside", ("validate", "lib"),
               (("lib/a.frame", frame), ("lib/b.frame", "dir")), codes=(0, 1))

    # -- outputs ---------------------------------------------------------------------------------------
    run = ("run", "stir the cup", "--map", "m.yaml", "--particles", "20")
    tasks = ("bench", "tasks", "--suite", "map", "--map", "m.yaml", "--layouts", "1", "--policies", "sefm")
    goals = (*loc, "--task", "stir the cup")
    for what, argv, files, name in (
            ("map --png a link to the image", ("map", "m.yaml", "--png", "l.png"), (("l.png", "link:apartment.pgm"),),
             "l.png"),
            ("run --rrd a link to the map", (*run, "--rrd", "l.rrd"), (("l.rrd", "link:m.yaml"),), "l.rrd"),
            ("run --png a link to a link to the map", (*run, "--png", "l.png"),
             (("k.png", "link:m.yaml"), ("l.png", "link:k.png")), "l.png"),
            ("--goals a link to the observations", (*goals, "--observations", "o.yaml", "--goals", "g.yaml"),
             (("o.yaml", OBSERVATIONS.encode()), ("g.yaml", "link:o.yaml")), "g.yaml"),
            ("--goals onto --trajectory", (*goals, "--trajectory", "t.yaml", "--goals", "t.yaml"),
             (("t.yaml", b"poses:\n  - [-6.0, -3.0]\n"),), "t.yaml"),
            ("--episodes hard-linked to the map", (*tasks, "--episodes", "h.jsonl"), (("h.jsonl", "hard:m.yaml"),),
             "h.jsonl"),
            ("--episodes onto --framelib", (*tasks, "--framelib", "f.frame", "--episodes", "f.json"),
             (("f.frame", frame), ("f.json", "hard:f.frame")), "f.json"),
            ("--pddl into a link to the folder of the map", ("plan", "--map", "m.yaml", "--pddl", "l", "stir the cup"),
             (("l", "link:."), ("domain.pddl", "hard:m.yaml")), "l"),
            ("map --png through the folder's own path", ("map", "m.yaml", "--png", "./sub/../apartment.pgm"),
             (("sub", "dir"),), "apartment.pgm")):
        yield Case(f"R an output onto an input: {what}", argv, (*both, *files), codes=(1,),
                   keep=(*inputs, *(f for f, c in files if isinstance(c, bytes))), says=_named(name))
    for what, argv, name in (("--goals", (*goals, "--goals", "no/g.yaml"), "no"),
                             ("--episodes", (*tasks, "--episodes", "no/e.jsonl"), "no"),
                             ("run --rrd", (*run, "--rrd", "no/r.rrd"), "no"),
                             ("--pddl", ("plan", "--pddl", "no/deeper", "stir the cup"), "no"),
                             ("map --png under a file", ("map", "m.yaml", "--png", "m.yaml/o.png"), "m.yaml"),
                             ("--rrd a folder", (*run, "--rrd", "sub"), "sub"),
                             ("--png the root folder", ("map", "m.yaml", "--png", "/"), "/"),
                             ("--png '..'", ("map", "m.yaml", "--png", ".."), "..")):
        yield Case(f"R an output nowhere: {what}", argv, (*both, ("sub", "dir")), codes=(1,), keep=inputs,
                   says=_named(name))
    yield Case("R an output in a read-only folder", ("map", "m.yaml", "--png", "ro/o.png"), (*both, ("ro", "ro-dir")),
               keep=inputs, absent=("ro/o.png",) if _enforced() else (), codes=(1,) if _enforced() else (0, 1))
    yield Case("R two --goals at once onto one file", (*goals, "--goals", "g.yaml"), both, codes=(0,), parallel=2,
               whole=("g.yaml",), keep=inputs)
    yield Case("R two bench tasks --episodes at once", (*tasks, "--episodes", "e.jsonl"), both, codes=(0,),
               parallel=2, whole=("e.jsonl",), keep=inputs, timeout=180)
    long_goals = tuple(a for k, a in enumerate(goals) if "--steps" not in goals[k - 1:k + 1])  # --steps once
    yield Case("R SIGINT during localize --goals", (*long_goals, "--steps", "100000", "--goals", "g.yaml"), both,
               codes=(130, -int(signal.SIGINT)), keep=inputs, absent=("g.yaml",), signal=(int(signal.SIGINT), 5.0))
    yield Case("R SIGINT while parse waits on standard input", ("parse", "--file", "-"), codes=(130, 0, 1),
               stream="open-stdin", signal=(int(signal.SIGINT), 2.0))
    yield Case("R SIGINT twice during map --png", ("map", "m.yaml", "--png", "o.png"), both,
               codes=(0, 130, -int(signal.SIGINT)), keep=inputs, signal=(int(signal.SIGINT), 0.9), twice=False)

    # -- standard streams -------------------------------------------------------------------------------
    yield Case("R stdin closed: parse --file -", ("parse", "--file", "-"), codes=(1,), stream="closed-stdin",
               says=r"(input|stdin)")
    yield Case("R stdin closed: plan", ("plan", "stir the cup"), codes=(0,), stream="closed-stdin")
    yield Case("R stdout closed: frames", ("frames",), codes=(0, 1, 120), stream="closed-stdout")
    yield Case("R stdout closed: parse --json", ("parse", "--json", "stir the cup"), codes=(0, 1, 120),
               stream="closed-stdout")
    yield Case("R stdout /dev/full: map --json", ("map", "apartment", "--json"), codes=(1,), stream="full-stdout",
               says=r"(output|space)")
    yield Case("R stdout /dev/full: validate", ("validate", "f.frame"), (("f.frame", frame),), codes=(1,),
               stream="full-stdout", says=r"(output|space)")
    yield Case("R stdout /dev/full: parse TEXT", ("parse", "stir the cup"), codes=(1,), stream="full-stdout",
               says=r"(output|space)")
    yield Case("R stderr closed: a bad map", ("map", "nope.yaml"), codes=(1,), stream="closed-stderr")

    # -- sizes -----------------------------------------------------------------------------------------
    thousands = _frames(10_000)
    yield Case("R a library of 10,000 frames: validate", ("validate", "big.frame"), (("big.frame", thousands),),
               codes=(0,), timeout=120)
    yield Case("R a library of 10,000 frames: plan", ("plan", "--framelib", "big.frame", "verbaaaa the cup"),
               (("big.frame", thousands),), codes=(0, 1), timeout=120)
    yield Case("R a library of 10,000 frames: frames --json", ("frames", "--framelib", "big.frame", "--json"),
               (("big.frame", thousands),), codes=(0,), timeout=120)
    yield Case("R a frame of 10,000 lexical units", ("validate", "lu.frame"),
               (("lu.frame", FRAME.replace('"beat"', " ".join(f'"beat{_word(i)}"' for i in range(10_000))).encode()),),
               codes=(0,), timeout=90)
    long_command = ("stir the cup " * 7700)[:100_000]
    for argv in (("parse", long_command), ("plan", long_command), ("run", long_command, "--map", "apartment")):
        yield Case(f"R a command of 100,000 characters: {argv[0]}", argv, codes=(0, 1), timeout=90)
    yield Case("R a command of 100,000 'and's", ("plan", "stir the cup" + " and" * 25_000), codes=(1,), timeout=90)
    yield Case("R a command of 10,000 combining marks", ("parse", "stir the c" + "\u0301" * 10_000 + "up"),
               codes=(0, 1))
    yield Case("R a command with ANSI escapes and markup", ("parse", "stir the \x1b[31mcup\x1b[0m [bold]x[/bold]"),
               codes=(0, 1))
    yield Case("R a command with bidi overrides", ("plan", "stir the \u202ecup\u202c"), codes=(0, 1))
    yield Case("R a --file of 5,000 commands", ("parse", "--file", "c.txt", "--json"),
               (("c.txt", b"stir the cup\npick up the spoon\n" * 2500),), codes=(0,), timeout=120)
    yield Case("R a --file of one line of 1 MB", ("parse", "--file", "c.txt"), (("c.txt", b"stir " * 200_000),),
               codes=(0, 1), timeout=90)
    yield Case("R a --file of 17 MiB", ("parse", "--file", "c.txt"), (("c.txt", b"stir the cup\n" * 1_400_000),),
               codes=(1,), says=_named("c.txt"))
    yield Case("R --done given 200 times", ("plan", *(["--done", "pick up the cup"] * 200), "stir the cup"),
               codes=(0, 1), timeout=90)

    # -- maps, names, classes --------------------------------------------------------------------------
    uncovered = "\n".join(line for line in text.split("\n") if "name: kitchen" not in line)
    uncovered = uncovered.replace("kitchen: 0.5, ", "").replace(", kitchen: 0.2", "").replace("room: kitchen",
                                                                                               "room: bedroom")
    yield Case("R a map whose rooms do not hold its places: validate", ("validate", "m.yaml"),
               (("m.yaml", uncovered.encode()), image), codes=(1,), keep=inputs, says=_at("m.yaml"))
    yield Case("R a map whose rooms do not hold its places: run warns",
               ("run", "put the spoon in the fridge", "--map", "m.yaml", "--particles", "20"),
               (("m.yaml", uncovered.encode()), image), codes=(0,), keep=inputs, says=WARNS)
    yield Case("R a map whose rooms do not hold its places: localize warns", loc,
               (("m.yaml", uncovered.encode()), image), codes=(0,), keep=inputs, says=WARNS)
    yield Case("R an object outside every room", ("validate", "m.yaml"),
               (("m.yaml", text.replace("{class: cup, at: [0.3, 3.6], in: coffee_table_1}",
                                        "{class: cup, at: [8.95, -5.95]}").encode()), image), keep=inputs)
    for name in ("apartmnt", "APARTMENT", "apartment.yml", "../maps/apartment", ""):
        yield Case(f"R seal run --map {name!r}", ("run", "stir the cup", "--map", name), codes=(1,),
                   says=r"(--map|apartment|map)")
    yield Case("R seal plan --map a frame file", ("plan", "--map", "f.frame", "stir the cup"), (("f.frame", frame),),
               codes=(1,), says=_named("f.frame"))
    yield Case("R detections of a class nobody knows", (*loc, "--observations", "o.yaml"),  # robot5: set aside, said
               (*both, ("o.yaml", b"- pose: [-6, -3]\n  detections: [{class: unicorn, at: [-5, -3]}]\n")),
               codes=(0,), keep=("o.yaml",), says=r"set aside: unicorn \(1\)")
    yield Case("R detections of a class the given library lacks", (*loc, "--framelib", "f.frame", "--task",
                                                                  "whisk the cup", "--observations", "o.yaml"),
               (*both, ("f.frame", frame), ("o.yaml", b"- pose: [-6, -3]\n  detections: [{class: knife, at: [-5, -3]}]"
                                                     b"\n")), keep=("o.yaml",))
    yield Case("R --task a frame the given library lacks", (*loc, "--framelib", "f.frame", "--task", "open the fridge"),
               (*both, ("f.frame", frame)), codes=(1,), says=r"(open|fridge|frame)")
    yield Case("R --holding a class of no map", ("run", "stir the cup", "--map", "apartment", "--holding", "unicorn"),
               says=r"unicorn")
    yield Case("R --policy with a control character", ("run", "stir the cup", "--map", "apartment", "--policy",
                                                       "sefm\x01"), codes=(1, 2), says=r"policy")
    yield Case("R --particles in Arabic-Indic digits", ("run", "stir the cup", "--map", "apartment", "--particles",
                                                        "٣"), codes=(0, 1, 2))

    yield from _bag_cases(both)


def _enforced() -> bool:
    """Whether a read-only folder refuses this user (not for root)."""
    import os

    return hasattr(os, "geteuid") and os.geteuid() != 0


def cases(seed: int = 0, count: int = 320) -> list[Case]:
    """The issue's cases, the hostile inputs written by hand, the reviewer's, a new user's, an outsider's and an
    attacker's (each with the shape of its message), then ``count`` generated ones."""
    from seal_cli.bench.reliability_attacker import attacker_cases
    from seal_cli.bench.reliability_outsider import outsider_cases
    from seal_cli.bench.reliability_users import user_cases

    return [*issue_cases(), *hostile_cases(), *review_cases(), *user_cases(), *outsider_cases(), *attacker_cases(),
            *generated_cases(seed, count)]
