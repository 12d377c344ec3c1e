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
    yield from _labels_verbs_and_numbers_cases()


def _sensor_and_name_cases() -> Iterator[Case]:  # noqa: PLR0915 - one list of cases, read top to bottom
    """Round hostile31's second batch: a sensor's field of view of a sliver (``--fov 1e-300``, a map's ``fov:
    0.001``: a look all round is 360 / fov looks); a file's name ending in ``/`` (a folder's name, given where a file
    goes: written or read as the file without it); ``--goals -``; a map image that is a dangling link or a link loop;
    control characters in names inside files and in names given (an image's name through YAML's ``\\e``, a missing
    file's name, a scorer's relayed output)."""
    from seal_cli.bench.reliability_inputs import alfred2d_data, robot_map
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
    context = ("bench", "tasks", "--suite", "context", "--layouts", "1", "--policies", "oracle", "--jobs",
               "1")
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
                "--policies", "oracle", "--jobs", "1", "--episodes", "e.jsonl/"), codes=(1,),
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


def _labels_verbs_and_numbers_cases() -> Iterator[Case]:  # noqa: PLR0915 - one list of cases, read top to bottom
    """Round hostile31's third batch: a bag's labels file whose label is a number or holds a control character (passed
    on as a class, into the observations written); a bag of only its magic bytes (Python's own words, "ord()
    expected a character"); a verb a frame library adds that English reads as a noun too, said alone ("unknown verb
    'zap' ... the robot can ... or zap"); an end-to-end suite whose case holds a number where a class goes (scored
    as a plan missed, not said at its line); numbers at the edges of what options take (seeds past 2**64, a clock of
    fullwidth digits or with a time zone, a time that is none)."""
    from seal_cli.bench.reliability_inputs import sample_bag as _sample_bag

    # -- end-to-end suites --------------------------------------------------------------------------------------------
    def suite(name: str, case: bytes, codes: tuple[int, ...], says: str) -> Case:
        head = b'cases:\n  - {map: studio, text: "go to the sofa", plan: ["Go(goal=sofa_1)"]'
        return Case(f"A bench e2e --file whose case {name}", ("bench", "e2e", "--file", "e.yaml", "--jobs", "1",
                                                                "--particles", "20"),
                    (("e.yaml", head + case + b"}\n"),), codes=codes, keep=("e.yaml",), says=says, timeout=120)
    yield suite("holds a number where the robot's hand's class goes", b", holding: 5", (1,),
                r"e\.yaml:2:\d+: .*holding '5' is not a class name")
    yield suite("holds a class of punctuation in the robot's hand", b", holding: '!!'", (1,),
                r"e\.yaml:2:\d+: .*holding")
    yield suite("holds a class with an escape sequence in the robot's hand", b', holding: "cu\\e[2Jp"', (1,),
                r"e\.yaml:2:\d+: .*holding")
    yield suite("holds a well-formed class in the robot's hand", b", holding: cup, run: done", (0, 1), r"sofa")
    # -- a verb a library adds that English reads as a noun too ------------------------------------------------------
    zap = b'frame Zap "zap" {\n  theme: object\n  do navigate(theme)\n}\n'
    for said in ("zap", "zap now", "Zap!"):
        yield Case(f"A parse of '{said}' with a library that adds the verb zap", ("parse", said, "--framelib",
                                                                                 "+z.frame"),
                   (("z.frame", zap),), codes=(1,), keep=("z.frame",), says=r"'zap' is read here as a thing",
                   unsaid=r"unknown verb 'zap'")
    yield Case("A plan of 'zap the cup' with a library that adds the verb zap",
               ("plan", "zap the cup", "--framelib", "+z.frame", "--map", "apartment"), (("z.frame", zap),),
               codes=(0,), keep=("z.frame",), says=r"Zap")
    yield Case("A parse of 'blorf' with a library that adds the verb blorf",
               ("parse", "blorf", "--framelib", "+z.frame"), (("z.frame", zap.replace(b'"zap"', b'"blorf"')),),
               codes=(0,), keep=("z.frame",), says=r"(?s).")
    # -- numbers at the edges of options -------------------------------------------------------------------------
    sofa = ("run", "go to the sofa", "--map", "studio", "--particles", "20")
    yield Case("A run --seed past 2**64", (*sofa, "--seed", str(2**64 + 1)), codes=(0,), says=r"done: Go")
    yield Case("A run --seed of 200 digits", (*sofa, "--seed", "9" * 200), codes=(0, 1, 2), says=r"seed|done: Go")
    yield Case("A run --seed of -1", (*sofa, "--seed", "-1"), codes=(2,), says=r"--seed")
    yield Case("A run --clock of fullwidth digits", (*sofa, "--clock", "\uff11\uff12:\uff10\uff10"), codes=(0, 1),
               says=r"--clock|done: Go")
    yield Case("A run --clock of 24:00", (*sofa, "--clock", "24:00"), codes=(1,), says=r"--clock: '24:00' is no time")
    yield Case("A run --clock of February 30th", (*sofa, "--clock", "2026-02-30T10:00"), codes=(1,),
               says=r"--clock: '2026-02-30T10:00' is no time")
    yield Case("A run --clock with an escape sequence", (*sofa, "--clock", "12:00\x1b[2J"), codes=(1,),
               says=r"--clock: '12:00\\x1b\[2J' is no time", unsaid=RAW)
    yield Case("A bench tasks --seed past 2**64", ("bench", "tasks", "--suite", "map", "--map", "studio", "--command",
                                                  "go to the sofa", "--layouts", "1", "--policies", "oracle",
                                                  "--jobs", "1", "--seed", str(2**64 + 1)),
               codes=(0,), says=r"(?s).", timeout=120)
    yield Case("A localize --seed of 2**128 + 1", ("localize", "--map", "apartment", "--task", "go to the kitchen",
                                                   "--steps", "1", "--particles", "20", "--seed", str(2**128 + 1)),
               codes=(0,), says=r"(?s).")
    yield Case("A bench maps --points 0", ("bench", "maps", "--points", "0"), codes=(2,), says=r"--points")
    yield Case("A run --search-end of nan", (*sofa, "--search-end", "nan"), codes=(1, 2), says=r"--search-end")
    yield Case("A run --max-metres of -inf", (*sofa, "--max-metres", "-inf"), codes=(1, 2), says=r"--max-metres")
    # -- a bag's labels and a bag of its magic alone ------------------------------------------------------------------
    bag = _sample_bag()
    if bag is None:
        return
    def labelled(name: str, labels: bytes, says: str) -> Case:
        return Case(f"A import-bag --labels whose {name}", ("import-bag", "run.mcap", "-o", "o.yaml", "--labels",
                                                            "l.yaml"),
                    (("run.mcap", bag), ("l.yaml", labels)), codes=(1,), keep=("run.mcap", "l.yaml"),
                    absent=("o.yaml",), says=says, unsaid=RAW)
    yield labelled("label is a number", b"cup: 1\n", r"l\.yaml:1:6: .*label of cup")
    yield labelled("label in a list is a number", b"[background, 7]\n", r"l\.yaml:1:\d+: .*label 1")
    yield labelled("label holds an escape sequence", b'1: "cu\\e[2Jp"\n', r"l\.yaml:1:4: .*label of 1")
    yield labelled("label holds a NUL", b'1: "cu\\0p"\n', r"l\.yaml:1:4: .*label of 1")
    yield Case("A localize --bag --labels whose label is a number",
               ("localize", "--map", "apartment", "--task", "go to the kitchen", "--particles", "20", "--bag",
                "run.mcap", "--labels", "l.yaml"), (("run.mcap", bag), ("l.yaml", b"[background, 7]\n")), codes=(1,),
               keep=("run.mcap", "l.yaml"), says=r"l\.yaml:1:\d+: .*label 1")
    yield Case("A import-bag of an .mcap of its magic alone", ("import-bag", "h.mcap", "-o", "o.yaml"),
               (("h.mcap", bag[:8]),), codes=(1,), keep=("h.mcap",), absent=("o.yaml",),
               says=r"h\.mcap: .*(cut short|ends)", unsaid=r"ord\(\)")
    yield Case("A import-bag of an .mcap of its magic and a byte", ("import-bag", "h.mcap", "-o", "o.yaml"),
               (("h.mcap", bag[:9]),), codes=(1,), keep=("h.mcap",), absent=("o.yaml",),
               says=r"h\.mcap: ", unsaid=r"ord\(\)")
