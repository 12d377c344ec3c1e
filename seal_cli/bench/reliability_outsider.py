"""An outsider's hostile inputs of ``seal bench reliability`` (round hostile12): kinds none of the issue's, the
hand-written, the reviewer's, the new user's or the generated cases held, each found failing and fixed in one place.

- the environment a command runs in: a standard output that cannot encode every character
  (``PYTHONIOENCODING=ascii`` or ``latin-1``: a traceback from rich or ``json``; now escapes, and JSON stays JSON,
  :func:`seal_cli.cli.output.printable_streams`), ``COLUMNS`` of 5, 0, -4 or ``abc``, ``TERM=dumb``,
  ``FORCE_COLOR``, a cache folder that is a file, ``/dev/null``, read-only or under ``/proc``, no ``HOME``;
  numpy's RuntimeWarnings on stderr once the suite's own ``PYTHONWARNINGS=ignore`` is taken away;
- SIGINT while the command line is still importing (the first tenth of a second, a second on a loaded machine):
  a ``KeyboardInterrupt`` traceback (the reason "SIGINT during map --png" failed now and then under load);
- maps: a problem of the room, place, object or person after one that could not be built was reported at the
  line of the one before (:meth:`seal_cli.maps.formats.map_server._Reader.renumber`); a room called ``_outside``
  (the name of the mass in no room: its prior mass was reported as nowhere); a room wholly outside the bounds
  (validated, then a run "cannot drive into" it); coordinates of 1e308 m (overflows, then misleading messages);
  an occupancy image of more than 4096 × 4096 cells (10,000 × 10,000 took some 15 GB; a 438 KB PNG declaring
  20,000 × 20,000 was handed to the decoder; since hostile13 a binary PGM that large is cropped and coarsened);
- ALFRED-2D data: a ``floorplans.json`` that is a FIFO hung ``bench tasks``, a Latin-1 byte in a trials file was
  a traceback, JSON errors had no line and column (:func:`seal_cli.fileio.read_json`,
  :func:`seal_cli.fileio.stream_lines`); a FIFO for ``bench parse --constants`` hung the scorer; ``bench e2e
  --data`` without the AWS house (or with a FIFO for its image) was reported in a temporary map file; ``seal
  validate /`` ended on "error: /proc/20888: No such file or directory" (a process ended during the walk);
- outputs onto ``/dev/full``.
"""

from __future__ import annotations

import signal
from collections.abc import Iterator

from seal_cli.bench.reliability import Case, hostile_setting

__all__ = ["outsider_cases"]

NO_WARNING = r"\A(?![\s\S]*(Warning|warnings\.warn))"
"""A pattern that holds when no Python warning reached the output."""

ALFRED_ROW = (b"task_type\tobject\treceptacle\tmrecep\tsliced\tgoal_sentence\n"
              b"pick_and_place_simple\tCup\tSinkBasin\t\t0\tput the cup in the sink\n")
"""An ALFRED goals table of one row with every column the scorer reads (hostile28: a table without them is refused
at its header, before its constants are read)."""


def _png_header(width: int, height: int) -> bytes:
    """A PNG's signature and IHDR chunk declaring ``width`` × ``height`` (8-bit grey), then garbage."""
    import struct
    import zlib

    body = b"IHDR" + struct.pack(">IIBBBBB", width, height, 8, 0, 0, 0, 0)
    return (b"\x89PNG\r\n\x1a\n" + struct.pack(">I", 13) + body + struct.pack(">I", zlib.crc32(body))
            + b"\x00" * 64)


def outsider_cases() -> Iterator[Case]:  # noqa: PLR0915 - one list of cases, read top to bottom
    """The cases, each with the shape of its message (``says``)."""
    m, image, text, both, inputs, loc, _ = hostile_setting()
    env: tuple[tuple[str, str], ...]
    run = ("run", "go to the kitchen", "--map", "m.yaml", "--particles", "20", "--max-steps", "40")
    # -- standard streams that cannot encode every character -----------------------------------------------
    for encoding in ("ascii", "latin-1"):
        env = (("PYTHONIOENCODING", encoding),)
        cafe = r"caf(\\xe9|é|\ufffd)"  # escaped, or one Latin-1 byte (read back as UTF-8: a replacement)
        yield Case(f"O PYTHONIOENCODING={encoding}: parse a café", ("parse", "stir the café"), codes=(0,), env=env,
                   says=cafe)
        yield Case(f"O PYTHONIOENCODING={encoding}: parse --json stays JSON", ("parse", "--json", "bring Zoë a café"),
                   codes=(0,), env=env, says=r'"bring Zo\\u00eb a caf\\u00e9"')
        yield Case(f"O PYTHONIOENCODING={encoding}: a parse error in JSON", ("parse", "--json", "stir the 😀"),
                   codes=(1,), env=env, says=r'"stir the \\ud83d\\ude00"')
        yield Case(f"O PYTHONIOENCODING={encoding}: parse --file --json", ("parse", "--file", "c.txt", "--json"),
                   (("c.txt", "stir the café\nbring me a crème brûlée\n".encode()),), codes=(0,), env=env,
                   keep=("c.txt",), says=r'cr\\u00e8me')
        for argv in (("plan", "stir the cup"), ("map", "m.yaml"), ("frames",), ("frames", "Stir"),
                     ("localize", "--map", "m.yaml", "--steps", "1", "--particles", "20", "--task", "stir the cup"),
                     run, ("validate", "m.yaml"), ("--help",), ("run", "--help")):
            yield Case(f"O PYTHONIOENCODING={encoding}: {' '.join(argv[:2])}", argv, both, codes=(0,), env=env,
                       keep=inputs)
        yield Case(f"O PYTHONIOENCODING={encoding}: an error naming é", ("map", "apartmént"), codes=(1,), env=env,
                   says=r"apartm(\\xe9|é|\ufffd)nt: no such map file")
        yield Case(f"O PYTHONIOENCODING={encoding}: validate lists a café's problem", ("validate", "f.frame"),
                   (("f.frame", "frame Café \"café\" {\n  theme: cup\n  do navigate(theme),\n}\n".encode()),),
                   codes=(1,), env=env, keep=("f.frame",), says=r"f\.frame:\d+:\d+:")
    # -- terminals, colours, widths, caches, homes ----------------------------------------------------------
    shown = (("frames",), ("plan", "stir the cup"), ("map", "m.yaml"), ("parse", "bring me a cup from the kitchen"))
    settings: list[tuple[tuple[str, str], ...]] = [
        (("COLUMNS", "5"),), (("COLUMNS", "0"),), (("COLUMNS", "-4"),), (("COLUMNS", "abc"),),
        (("COLUMNS", "<unset>"), ("LINES", "0")), (("TERM", "dumb"), ("NO_COLOR", "<unset>")),
        (("FORCE_COLOR", "1"), ("NO_COLOR", "<unset>"), ("TERM", "xterm-256color")),
        (("LANG", "C"), ("LC_ALL", "C"), ("PYTHONUTF8", "0"))]
    for k, env in enumerate(settings):
        argv = shown[k % len(shown)]
        label = " ".join(f"{name}={value}" for name, value in env)
        yield Case(f"O {label}: {' '.join(argv[:2])}", argv, both, codes=(0,), env=env, keep=inputs)
    caches: dict[str, tuple[tuple[str, str], ...]] = {"SEAL_CACHE_DIR a file": (("SEAL_CACHE_DIR", "m.yaml"),),
              "SEAL_CACHE_DIR /dev/null": (("SEAL_CACHE_DIR", "/dev/null"),),
              "SEAL_CACHE_DIR read-only": (("SEAL_CACHE_DIR", "ro"),),
              "SEAL_CACHE_DIR under /proc": (("SEAL_CACHE_DIR", "/proc/seal-cache"),),
              "XDG_CACHE_HOME a file, HOME missing": (("SEAL_CACHE_DIR", "<unset>"), ("XDG_CACHE_HOME", "m.yaml"),
                                                      ("HOME", "/nonexistent")),
              "no HOME at all": (("SEAL_CACHE_DIR", "<unset>"), ("XDG_CACHE_HOME", "<unset>"), ("HOME", "<unset>")),
              "SEAL_NO_CACHE garbage": (("SEAL_NO_CACHE", "yes please"),)}
    for label, env in caches.items():
        yield Case(f"O {label}: parse, then plan", ("plan", "--map", "m.yaml", "stir the cup"),
                   (*both, ("ro", "ro-dir")), codes=(0,), env=env, keep=inputs)
    tiny = text.replace("resolution: 0.05", "resolution: 1e-300")
    assert tiny != text, "the apartment's resolution changed: update the outsider's warning case"
    yield Case("O numpy's warnings stay off stderr (PYTHONWARNINGS unset)", ("localize", "--map", "r.yaml", "--steps",
                                                                             "1", "--particles", "20"),
               (("r.yaml", tiny.encode()), image), codes=(1,), env=(("PYTHONWARNINGS", "<unset>"),),
               keep=("r.yaml",), says=NO_WARNING + r"[\s\S]*r\.yaml:\d+:\d+:")
    # -- SIGINT while the command line is imported -------------------------------------------------------
    for delay in (0.0, 0.1, 0.2, 0.35):  # 0.0: at reliability.SIGNAL_CPU, 0.05 s of CPU, while typer imports
        yield Case(f"O SIGINT {delay} s into map --png (while importing)", ("map", "m.yaml", "--png", "o.png"), both,
                   codes=(0, 130, -int(signal.SIGINT)), keep=inputs, signal=(signal.SIGINT, delay))
    yield Case("O SIGINT 0.0 s into parse --json", ("parse", "--json", "stir the cup"),
               codes=(0, 130, -int(signal.SIGINT)), signal=(signal.SIGINT, 0.0))
    yield Case("O SIGINT 0.0 s into validate", ("validate", "m.yaml"), both,
               codes=(0, 130, -int(signal.SIGINT)), keep=inputs, signal=(signal.SIGINT, 0.0))
    # -- maps -------------------------------------------------------------------------------------------------
    head = "name: a\nbounds: [0, 0, 10, 10]\n"
    maps = {
        "a room called _outside": (head + "rooms:\n  - {name: kitchen, box: [5, 0, 10, 10]}\n"
                                   "  - {name: _outside, box: [0, 0, 5, 10]}\n",
                                   r"x\.yaml:5:\d+: a room cannot be called '_outside'"),
        "a self-crossing room after a broken one": (head + "rooms:\n  - {name: kitchen, polygon: [[0, 0], [1, 1]]}\n"
                                                    "  - {name: den, box: [0, 0, 1, 1]}\n"
                                                    "  - {name: hall, polygon: [[2, 2], [9, 9], [9, 2], [2, 9]]}\n",
                                                    r"x\.yaml:6:\d+: room hall intersects itself"),
        "overlapping rooms after a broken one": (head + "rooms:\n  - {name: kitchen, box: [0, 0]}\n"
                                                 "  - {name: den, box: [0, 0, 5, 5]}\n"
                                                 "  - {name: hall, box: [1, 1, 6, 6]}\n",
                                                 r"x\.yaml:6:\d+: room hall overlaps room den \(line 5\)"),
        "a place off the map after a broken one": (head + "places:\n  - {name: sink_1, class: sink}\n"
                                                   "  - {name: bed_1, class: bed, at: [50, 5]}\n",
                                                   r"x\.yaml:5:\d+: place bed_1 at \[50, 5\] is outside"),
        "an object off the map after a broken one": (head + "objects:\n  - {class: cup, at: [1]}\n"
                                                     "  - {class: mug, at: [50, 5]}\n",
                                                     r"x\.yaml:5:\d+: object mug at \[50, 5\] is outside"),
        "a room wholly outside the bounds": (head + "rooms:\n  - {name: kitchen, box: [0, 0, 10, 10]}\n"
                                             "  - {name: garage, box: [100, 100, 200, 200]}\n",
                                             r"x\.yaml:5:\d+: room garage .* is wholly outside the map's bounds"),
    }
    for label, (body, says) in maps.items():
        yield Case(f"O map: {label}", ("validate", "x.yaml"), (("x.yaml", body.encode()),), codes=(1,),
                   keep=("x.yaml",), says=says)
    yield Case("O map: run into a room wholly outside the bounds", ("run", "go to the garage", "--map", "x.yaml"),
               (("x.yaml", maps["a room wholly outside the bounds"][0].encode()),), codes=(1,), keep=("x.yaml",),
               says=r"x\.yaml:5:\d+: room garage")
    huge = {"a room's box": ("box: [-9.0, 0.5, -3.0, 6.0]", "box: [-9.0, 0.5, 1e308, 6.0]"),
            "the origin": ("origin: [-10.0, -7.0, 0.0]", "origin: [-1e300, -7.0, 0.0]"),
            "a place": ("at: [8.5, -0.8]", "at: [8.5, -1e200]"),
            "the robot's yaw": ("pose: [-6.0, -3.0, 0.0]", "pose: [-6.0, -3.0, 1e300]"),
            "the speaker": ("speaker: {at: [-6.5, -4.0]}", "speaker: {at: [-6.5, 1e250]}")}
    for label, (old, new) in huge.items():
        assert old in text, f"the apartment changed: update the outsider's huge number in {label}"
        for command in (("validate", "h.yaml"), ("run", "go to the kitchen", "--map", "h.yaml")):
            yield Case(f"O 1e300 m in {label}: {command[0]}", command, (("h.yaml", text.replace(old, new).encode()),
                                                                       image),
                       codes=(1,), keep=("h.yaml",), says=r"h\.yaml:\d+:\d+: each number of .* from -10,000,000")
    big = b"P5\n4097 4097\n255\n" + b"\xfe" * (4097 * 4097)
    yield Case("O map image of 4097 × 4097 cells", ("map", "m.yaml"), (m, ("apartment.pgm", big)), codes=(0,),
               keep=("m.yaml",), says=r"warning: m\.yaml:\d+:\d+: the image is 4,097×4,097 pixels; .* merges 5×5")
    yield Case("O map image: a PNG declaring 20,000 × 20,000", ("validate", "p.yaml"),
               (("p.yaml", text.replace("image: apartment.pgm", "image: bomb.png").encode()),
                ("bomb.png", _png_header(20_000, 20_000))),
               codes=(1,), keep=("p.yaml", "bomb.png"), says=r"p\.yaml:\d+:\d+: the image is 20,000×20,000 pixels")
    yield Case("O map image: a P2 declaring 100,000 × 1,000", ("map", "m.yaml"),
               (m, ("apartment.pgm", b"P2\n100000 1000\n255\n" + b"254 " * 1000)), codes=(1,), keep=("m.yaml",),
               says=r"m\.yaml:\d+:\d+: the image is 100,000×1,000 pixels")
    # -- ALFRED-2D data -----------------------------------------------------------------------------------
    tasks = ("bench", "tasks", "--suite", "alfred2d", "--data", "d", "--split", "x", "--goal", "gold", "--policies",
             "sefm")
    plans = ("d/floorplans.json", b'{"floor_plans": {}, "movable_classes": []}\n')
    yield Case("O bench tasks: floorplans.json is a FIFO", tasks, (("d/floorplans.json", "fifo"),), codes=(1,),
               says=r"d/floorplans\.json: .*FIFO")
    yield Case("O bench tasks: the trials file is a FIFO", tasks, (plans, ("d/trials_x.jsonl", "fifo")), codes=(1,),
               says=r"d/trials_x\.jsonl: .*FIFO")
    yield Case("O bench tasks: floorplans.json is not JSON", tasks, (("d/floorplans.json", b'{"floor_plans": {\n'),),
               codes=(1,), says=r"d/floorplans\.json:2:1: this floor plans file is not JSON")
    yield Case("O bench tasks: a Latin-1 byte in the trials", tasks,
               (plans, ("d/trials_x.jsonl", b'{"task_id": "caf\xe9"}\n')), codes=(1,),
               says=r"d/trials_x\.jsonl:1:17: this trials file is not UTF-8")
    yield Case("O bench tasks: a trial that is not JSON", tasks, (plans, ("d/trials_x.jsonl", b'\n{"task_id": 1,}\n')),
               codes=(1,), says=r"d/trials_x\.jsonl:2:15: trial is not JSON")
    yield Case("O bench parse: --constants is a FIFO", ("bench", "parse", "--corpus", "c.tsv", "--constants", "k.json"),
               (("c.tsv", ALFRED_ROW), ("k.json", "fifo")), codes=(1,), says=r"k\.json")
    e2e = ("bench", "e2e", "--data", "e", "--map", "aws", "--limit", "1", "--jobs", "1")
    yield Case("O bench e2e: the AWS house's image is a FIFO", e2e, (("e/maps/aws_small_house/map.pgm", "fifo"),),
               codes=(1,), says=r"(?m)^error: e/maps/aws_small_house/map\.pgm: cannot read this map image: it is a "
                                r"FIFO")
    yield Case("O bench e2e: no AWS house in --data", e2e, (("e", "dir"),), codes=(1,),
               says=r"(?m)^error: e/maps/aws_small_house/map\.pgm: the AWS small house's map is not there")
    for walked in (("validate", "/proc"), ("frames", "--framelib", "/proc")):
        yield Case(f"O {' '.join(walked)}: processes end while it is walked", walked, codes=(1,),
                   says=r"(?m)^(error: )?/proc: no frame files \(\*\.yaml, \*\.frame\) in folder /proc$")
    # -- outputs onto a full device ---------------------------------------------------------------------------
    yield Case("O map --png /dev/full", ("map", "m.yaml", "--png", "/dev/full"), both, codes=(1,), keep=inputs,
               says=r"cannot write --png /dev/full: No space left on device")
    yield Case("O localize --rrd /dev/full", (*loc, "--rrd", "/dev/full"), both, codes=(1,), keep=inputs,
               says=r"cannot write --rrd /dev/full: No space left on device")
    yield Case("O plan --pddl with domain.pddl a link to the map", ("plan", "--map", "m.yaml", "--pddl", "out",
                                                                     "stir the cup"),
               (*both, ("out/domain.pddl", "link:../m.yaml")), codes=(1,), keep=inputs,
               says=r"would overwrite the input m\.yaml")
