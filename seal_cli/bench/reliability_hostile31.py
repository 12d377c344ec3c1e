"""Round hostile31's hostile inputs of ``seal bench reliability`` (an attacker's, as
:mod:`seal_cli.bench.reliability_attacker`'s, kept apart from that long list): what hostile30 left (a NUL or another
control character in a ``.frame`` file's comment was read as part of the comment, silently), then the kinds older
rounds held fewest of."""

from __future__ import annotations

from collections.abc import Iterator

from seal_cli.bench.reliability import Case

__all__ = ["hostile31_cases", "hostile31_leftover_cases"]

WHISK = b'category object = cup, bowl\nframe Whisk "whisk" {\n  theme: object\n  do navigate(theme)\n}\n'
"""A frame file of one category and one frame that validates alone."""

RAW = r"[\x00-\x08\x0b-\x1f\x7f]"
"""A control character other than a tab or a line break: what must never reach the terminal as it is."""


def hostile31_leftover_cases() -> Iterator[Case]:
    """Round hostile31's first batch, what hostile30 left: a ``.frame`` file holding a NUL (or an escape, a
    backspace, a DEL) in a comment was read, the character passed over with the comment; one in a name or between
    two facts was "the frame is not closed", its line printed with the character as it is."""
    def frame_case(name: str, data: bytes, says: str, argv: tuple[str, ...] = ("validate", "f.frame")) -> Case:
        return Case(f"A {argv[0]} of a .frame file {name}", argv, (("f.frame", data),), codes=(1,),
                    keep=("f.frame",), says=says, unsaid=RAW)
    yield frame_case("with a NUL in a '#' comment", WHISK.replace(b"{\n", b"{\n  # a NUL \x00 here\n"),
                     r"f\.frame:3:11: .*U\+0000")
    yield frame_case("with a NUL in a '//' comment", WHISK.replace(b"{\n", b"{\n  // \x00\n"),
                     r"f\.frame:3:6: .*U\+0000", ("plan", "whisk the cup", "--framelib", "+f.frame"))
    yield frame_case("with an escape sequence in a comment", b"# \x1b[2J\x1b[31mred\n" + WHISK,
                     r"f\.frame:1:3: .*U\+001B")
    yield frame_case("with a NUL inside a name", WHISK.replace(b"theme: object", b"theme: obj\x00ect"),
                     r"f\.frame:3:13: .*U\+0000")
    yield frame_case("with a backspace between two frames", WHISK + b"\x08\n" + WHISK.replace(b"Whisk", b"Beat"),
                     r"f\.frame:6:1: .*U\+0008")
    yield frame_case("with a DEL at the end of a comment at the end", WHISK + b"// end\x7f",
                     r"f\.frame:6:7: .*U\+007F")


def hostile31_cases() -> Iterator[Case]:
    """Round hostile31's later batches."""
    yield from _sensor_and_name_cases()


def _sensor_and_name_cases() -> Iterator[Case]:  # noqa: PLR0915 - one list of cases, read top to bottom
    """Round hostile31's second batch: a sensor's field of view of a sliver (``--fov 1e-300``, a map's ``fov:
    0.001``: a look all round is 360 / fov looks); a file's name ending in ``/`` (a folder's name, given where a file
    goes: written or read as the file without it); ``--goals -``; a map image that is a dangling link or a link loop;
    control characters in names inside files and in names given (an image's name through YAML's ``\\e``, a missing
    file's name, a scorer's relayed output)."""
    from seal_cli.bench.reliability_attacker import alfred2d_data, robot_map
    from seal_cli.resources import map_path

    (_, head), (_, image) = robot_map()
    ros = (("m.yaml", head), ("map.pgm", image))
    apartment = map_path("apartment").read_bytes()
    apartment_image = map_path("apartment").with_suffix(".pgm").read_bytes()
    assert b"sensor: {range: 5.0, fov: 360}" in apartment, "the apartment's sensor changed: update hostile31's cases"
    def narrow(fov: str) -> tuple[tuple[str, bytes], ...]:
        return (("a.yaml", apartment.replace(b"fov: 360}", f"fov: {fov}}}".encode())),
                ("apartment.pgm", apartment_image))
    # -- a sensor's field of view of a sliver ----------------------------------------------------------------------
    context = ("bench", "tasks", "--suite", "context", "--layouts", "1", "--policies", "oracle", "--particles", "20",
               "--jobs", "1")
    yield Case("A bench tasks --suite context --fov 1e-300", (*context, "--fov", "1e-300"), codes=(1,),
               says=r"--fov 1e-300: degrees", timeout=60)
    yield Case("A bench tasks --suite context --fov 0.01", (*context, "--fov", "0.01"), codes=(1,),
               says=r"--fov 0\.01: degrees", timeout=60)
    yield Case("A validate of a map whose sensor sees 0.001 degrees", ("validate", "a.yaml"), narrow("0.001"),
               codes=(1,), keep=("a.yaml",), says=r"a\.yaml:45:\d+: .*fov")
    yield Case("A run on a map whose sensor sees 0.001 degrees", ("run", "find the spoon", "--map", "a.yaml",
                                                                  "--particles", "20"), narrow("0.001"),
               codes=(1,), keep=("a.yaml",), says=r"a\.yaml:45:\d+: .*fov", timeout=60)
    yield Case("A localize on a map whose sensor sees 1e-9 degrees", ("localize", "--map", "a.yaml", "--task",
                                                                      "find the spoon", "--steps", "2", "--particles",
                                                                      "20"), narrow("1e-9"),
               codes=(1,), keep=("a.yaml",), says=r"a\.yaml:45:\d+: .*fov", timeout=60)
    yield Case("A run on a ROS map whose sensor sees half a degree", ("run", "go to the kitchen", "--map", "m.yaml",
                                                                      "--particles", "20"),
               (("m.yaml", head + b"sensor: {range: 5.0, fov: 0.5}\n"), ros[1]), codes=(1,),
               keep=("m.yaml", "map.pgm"), says=r"m\.yaml:16:\d+: .*fov", timeout=60)
    yield Case("A validate of a map whose sensor sees 1 degree", ("validate", "a.yaml"), narrow("1"), codes=(0,),
               keep=("a.yaml",), says=r"ok: ")
    # -- a file's name ending in '/' ----------------------------------------------------------------------------------
    sofa = ("run", "go to the sofa", "--map", "studio", "--particles", "20")
    loc = ("localize", "--map", "apartment", "--task", "go to the kitchen", "--steps", "1", "--particles", "20")
    obs = b"- pose: [-6, -3]\n  detections: []\n"
    yield Case("A run --rrd whose name ends in /", (*sofa, "--rrd", "o.rrd/"), codes=(1,), absent=("o.rrd",),
               says=r"--rrd o\.rrd/")
    yield Case("A map --png whose name ends in /.", ("map", "studio", "--png", "o.png/."), codes=(1,),
               absent=("o.png",), says=r"--png o\.png/\.")
    yield Case("A localize --goals whose name ends in /", (*loc, "--goals", "g.yaml/"), codes=(1,),
               absent=("g.yaml",), says=r"--goals g\.yaml/")
    yield Case("A bench tasks --episodes whose name ends in /",
               ("bench", "tasks", "--suite", "map", "--map", "studio", "--command", "go to the sofa", "--layouts", "1",
                "--policies", "oracle", "--particles", "20", "--jobs", "1", "--episodes", "e.jsonl/"), codes=(1,),
               absent=("e.jsonl",), says=r"--episodes e\.jsonl/", timeout=120)
    yield Case("A localize --observations of a file named with a / after it", (*loc, "--observations", "o.yaml/"),
               (("o.yaml", obs),), codes=(1,), keep=("o.yaml",), says=r"--observations o\.yaml/")
    yield Case("A validate of a map file named with a / after it", ("validate", "m.yaml/"), ros, codes=(1,),
               keep=("m.yaml",), says=r"m\.yaml/")
    yield Case("A run --map of a file named with a / after it", ("run", "go to the kitchen", "--map", "m.yaml/",
                                                                "--particles", "20"), ros, codes=(1,),
               keep=("m.yaml",), says=r"--map m\.yaml/")
    yield Case("A plan --framelib +FILE/ of a frame file", ("plan", "whisk the cup", "--framelib", "+f.frame/",
                                                           "--map", "apartment"),
               (("f.frame", WHISK.replace(b"category object = cup, bowl\n", b"")),), codes=(1,), keep=("f.frame",),
               says=r"--framelib \+?f\.frame/")
    yield Case("A plan --pddl of a folder named with a / after it", ("plan", "go to the kitchen", "--map", "apartment",
                                                                    "--pddl", "d/"), (("d", "dir"),), codes=(0,),
               whole=("d/domain.pddl", "d/problem.pddl"), says=r"(?s).")
    yield Case("A bench tasks --data of a folder named with a / after it",
               ("bench", "tasks", "--data", "d/", "--policies", "sefm", "--jobs", "1", "--particles", "20"),
               alfred2d_data(), codes=(0,), says=r"(?s).", timeout=120)
    yield Case("A localize --goals of '-'", (*loc, "--goals", "-"), codes=(1,), absent=("-",),
               says=r"--goals '-': seal writes this output into a file")
    # -- a map image that is a dangling link or a link loop -------------------------------------------------------
    yield Case("A validate of a ROS map whose image is a dangling link", ("validate", "m.yaml"),
               (ros[0], ("map.pgm", "link:gone.pgm")), codes=(1,), keep=("m.yaml",),
               says=r"m\.yaml:1:8: .*link.*gone\.pgm")
    yield Case("A validate of a ROS map whose image is a link loop", ("validate", "m.yaml"),
               (ros[0], ("map.pgm", "link:loop.pgm"), ("loop.pgm", "link:map.pgm")), codes=(1,), keep=("m.yaml",),
               says=r"m\.yaml:1:8: .*loop")
    # -- control characters in names: never raw on the terminal -----------------------------------------------------
    yield Case("A validate of a ROS map whose image's name holds an escape sequence", ("validate", "m.yaml"),
               (("m.yaml", head.replace(b"image: map.pgm", b'image: "map\\e[2J.pgm"')), ros[1]), codes=(1,),
               keep=("m.yaml",), says=r"m\.yaml:1:8: ", unsaid=RAW)
    yield Case("A run on a ROS map whose image's name holds a NUL", ("run", "go to the kitchen", "--map", "m.yaml",
                                                                    "--particles", "20"),
               (("m.yaml", head.replace(b"image: map.pgm", b'image: "map\\0.pgm"')), ros[1]), codes=(1,),
               keep=("m.yaml",), says=r"m\.yaml:1:8: ", unsaid=RAW)
    yield Case("A validate of a missing file whose name holds an escape sequence", ("validate", "m\x1b[2J.yaml"),
               codes=(1,), says=r"m\\x1b\[2J\.yaml", unsaid=RAW)
    yield Case("A run --map of a missing map whose name holds a carriage return",
               ("run", "go to the kitchen", "--map", "apart\rment", "--particles", "20"), codes=(1,),
               says=r"apart\\rment", unsaid=RAW)
    yield Case("A parse --vocabulary of a missing file whose name holds a backspace",
               ("parse", "--vocabulary", "v\x08.yaml", "stir the cup"), codes=(1,), says=r"v\\x08\.yaml",
               unsaid=RAW)
    yield Case("A plan --holding holding an escape sequence", ("plan", "put it on the table", "--map", "apartment",
                                                              "--holding", "cu\x1b[2Jp"), codes=(1,),
               says=r"--holding", unsaid=RAW)
    yield Case("A bench parse --corpus whose text holds an escape sequence", ("bench", "parse", "--corpus", "c.jsonl"),
               (("c.jsonl", b'{"text": "go to the kitchen\\u001b[2J", "expect": [{"frame": "Go"}]}\n'),),
               codes=(0, 1), keep=("c.jsonl",), says=r"c\.jsonl", unsaid=RAW, timeout=120)
    yield Case("A bench e2e --file whose case's text holds an escape sequence",
               ("bench", "e2e", "--file", "e.yaml", "--jobs", "1", "--particles", "20"),
               (("e.yaml", b'cases:\n  - {map: studio, text: "go to the sofa\\e[2J", plan: ["Go(goal=sofa_1)"], '
                           b'run: done}\n'),), codes=(0, 1), keep=("e.yaml",), says=r"sofa", unsaid=RAW, timeout=120)
    yield Case("A parse --file whose line holds an escape sequence", ("parse", "--file", "c.txt"),
               (("c.txt", b"go to the kitchen\n\x1b[2Jopen the fridge\n"),), codes=(0, 1), keep=("c.txt",),
               says=r"2|U\+001B", unsaid=RAW)
