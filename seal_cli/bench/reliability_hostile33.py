"""Round rel33's hostile inputs of ``seal bench reliability`` (an attacker's, as
:mod:`seal_cli.bench.reliability_attacker`'s, kept apart from that long list): what hostile32 left (options no listed
policy reads, requests past the machine's memory, a command of 30 "bring" clauses), then the environment a command
runs in (the switches of the libraries seal writes its files with: matplotlib's backend and ``matplotlibrc``, Rerun's
``RERUN``, numba's threads), and values of the wrong type in every kind of file seal reads."""

from __future__ import annotations

from collections.abc import Iterator

from seal_cli.bench.reliability import Case

__all__ = ["hostile33_cases"]

SMALL = b"""name: m
bounds: [0, 0, 10, 10]
rooms:
  - {name: kitchen, box: [0, 0, 5, 10]}
  - {name: hall, box: [5, 0, 10, 10]}
places:
  - {name: fridge_1, class: fridge, at: [1, 1], openable: true}
priors: {cup: {kitchen: 0.5, hall: 0.5}}
objects: [{class: cup, at: [7, 7]}]
robot: {pose: [2, 2, 0]}
"""
"""A map of bounds alone that validates and runs ("bring me a cup")."""

THINGS = ("laptop", "book", "scissors", "glue", "paint", "brush", "apron", "paper", "stapler", "key", "phone",
          "tissues", "kettle", "mug", "milk", "sandwich", "apple", "ball", "whistle", "tambourine", "coat", "jumper",
          "soap", "mop", "bucket", "box", "calculator", "register")
BRINGS = ", ".join(f"bring the {thing} to {who}" for thing, who in zip(THINGS, ["Priya", "Helen", "Dan", "Lily", "me"]
                                                                       * 6, strict=False))
"""A command of 28 "bring" clauses, each of another thing the school has a prior of (709 characters)."""


def hostile33_cases() -> Iterator[Case]:
    """Round rel33's batches, recorded before their fixes."""
    yield from _leftover_cases()
    yield from _environment_cases()
    yield from _map_type_cases()
    yield from _other_file_cases()


def _leftover_cases() -> Iterator[Case]:
    """What hostile32 left: ``bench tasks --policies oracle --particles 20`` taken though no policy listed keeps
    particles; ``localize --particles 100000`` of a map of thousands of classes (160 GiB) ran until the machine
    killed it; a command of 30 "bring" clauses."""
    tiny = ("bench", "tasks", "--suite", "map", "--map", "studio", "--command", "go to the sofa", "--layouts", "1",
            "--jobs", "1")
    yield Case("A bench tasks --policies oracle --particles 20", (*tiny, "--policies", "oracle", "--particles", "20",
                                                                    "--episodes", "e.jsonl"),
               codes=(1,), absent=("e.jsonl",), says=r"--particles is not read by --policies oracle, which keeps no")
    yield Case("A bench tasks --policies oracle,coverage --particles 20",
               (*tiny, "--policies", "oracle,coverage", "--particles", "20"), codes=(1,),
               says=r"--particles is not read by --policies oracle,coverage: oracle and coverage keep no")
    yield Case("A bench tasks --policies oracle,object_only --particles 20 (one reads it)",
               (*tiny, "--policies", "oracle,object_only", "--particles", "20"), codes=(0,), says=r"(?s).",
               timeout=180)
    def classes(n: int) -> bytes:
        return SMALL.replace(b"priors: {cup: {kitchen: 0.5, hall: 0.5}}",
                             b"priors:\n" + b"".join(b"  c%d: {kitchen: 1}\n" % i for i in range(n)))
    # 2,000 classes (the most a map's priors may name) of 100,000 particles: 32 GiB, more than a machine of 24 GB has
    yield Case("A localize --particles 100000 of a map of 2,000 classes (32 GiB)",
               ("localize", "--map", "m.yaml", "--particles", "100000", "--steps", "1", "--png", "o.png"),
               (("m.yaml", classes(2000)),), codes=(1,), keep=("m.yaml",), absent=("o.png",),
               says=r"100,000 particles for each of 2,\d+ beliefs .* GiB of memory, and .* GiB is available: give "
                    r"--particles [\d,]+ or fewer", timeout=180)
    # found while fixing: 100,000 prior classes (2.3 MB) took `seal map` 30 s of CPU, `seal localize` past 300 s, 6 GB
    yield Case("A localize of a map whose priors name 100,000 classes", ("localize", "--map", "m.yaml", "--steps", "1"),
               (("m.yaml", classes(100_000)),), codes=(1,), keep=("m.yaml",),
               says=r"m\.yaml:\d+:3: this map's priors name more than 2,000 classes", timeout=180)
    yield Case("A SIGINT during localize --particles 100000 --steps 100000 --png", (
        "localize", "--map", "apartment", "--task", "stir the cup", "--particles", "100000", "--steps", "100000",
        "--png", "o.png", "--rrd", "o.rrd"), codes=(130,), signal=(2, 6.0), absent=("o.png", "o.rrd"),
        says=r"interrupted")
    yield Case("A parse of 28 'bring' clauses", ("parse", BRINGS, "--json"), codes=(0,), says=r"(?s).")
    yield Case("A plan of 28 'bring' clauses on the school", ("plan", BRINGS, "--map", "school"), codes=(0,),
               says=r"(?s).")
    yield Case("A run of 28 'bring' clauses on the school, 15 steps", ("run", BRINGS, "--map", "school",
                                                                         "--max-steps", "15"),
               codes=(1,), says=r"not done: out of steps \(15\)", timeout=180)


def _environment_cases() -> Iterator[Case]:
    """The environment's switches of the libraries seal writes with: ``MPLBACKEND=junk`` (a ``ValueError`` traceback on
    every ``--png``), a ``matplotlibrc`` in the working folder (``text.usetex: True``: a ``RuntimeError`` traceback
    without LaTeX; ``savefig.dpi: 100000``: out of memory), ``RERUN=off`` (every ``--rrd`` a traceback),
    ``NUMBA_NUM_THREADS=0`` (every SeFM a ``ValueError`` traceback)."""
    picture = ("map", "apartment", "--png", "o.png")
    run = ("run", "go to the sofa", "--map", "studio", "--particles", "20")
    localize = ("localize", "--map", "apartment", "--task", "stir the cup", "--particles", "50", "--steps", "2")
    for value in ("junk", "module://nope", "tkagg", "qtagg", ""):
        yield Case(f"A map --png with MPLBACKEND={value!r}", picture, codes=(0,), env=(("MPLBACKEND", value),),
                   whole=("o.png",), says=r"(?s).")
    yield Case("A run --png with MPLBACKEND=junk", (*run, "--png", "o.png"), codes=(0,),
               env=(("MPLBACKEND", "junk"),), whole=("o.png",), says=r"done: Go")
    yield Case("A localize --png with MPLBACKEND=junk", (*localize, "--png", "o.png"), codes=(0,),
               env=(("MPLBACKEND", "junk"),), whole=("o.png",), says=r"(?s).")
    for name, rc in (("text.usetex: True", b"text.usetex: True\n"),
                     ("savefig.dpi: 100000", b"savefig.dpi: 100000\nfigure.dpi: 100000\n"),
                     ("figure.figsize: 1000, 1000", b"figure.figsize: 1000, 1000\n"),
                     ("font.size: 0.0001", b"font.size: 0.0001\n"),
                     ("savefig.format: jpg and savefig.transparent",
                      b"savefig.format: jpg\nsavefig.transparent: True\n"),
                     ("axes.prop_cycle of one colour", b"axes.prop_cycle: cycler('color', ['w'])\n")):
        yield Case(f"A map --png beside a matplotlibrc of {name}", picture, (("matplotlibrc", rc),), codes=(0,),
                   keep=("matplotlibrc",), whole=("o.png",), says=r"(?s).", timeout=120)
    yield Case("A run --png beside a matplotlibrc of text.usetex: True", (*run, "--png", "o.png"),
               (("matplotlibrc", b"text.usetex: True\n"),), codes=(0,), keep=("matplotlibrc",), whole=("o.png",),
               says=r"done: Go")
    yield Case("A localize --png with MATPLOTLIBRC of text.usetex: True", (*localize, "--png", "o.png"),
               (("rc/matplotlibrc", b"text.usetex: True\n"),), codes=(0,), env=(("MATPLOTLIBRC", "rc"),),
               keep=("rc/matplotlibrc",), whole=("o.png",), says=r"(?s).")
    for value in ("off", "0", "false"):
        yield Case(f"A localize --rrd with RERUN={value}", (*localize, "--rrd", "o.rrd"), codes=(0,),
                   env=(("RERUN", value),), whole=("o.rrd",), says=r"(?s).")
    yield Case("A run --rrd with RERUN=off", (*run, "--rrd", "o.rrd"), codes=(0,), env=(("RERUN", "off"),),
               whole=("o.rrd",), says=r"done: Go")
    for value in ("0", "-3", "abc", "100000"):
        yield Case(f"A localize with NUMBA_NUM_THREADS={value}", localize, codes=(0,),
                   env=(("NUMBA_NUM_THREADS", value),), says=r"(?s).")
    yield Case("A run with NUMBA_NUM_THREADS=0", run, codes=(0,), env=(("NUMBA_NUM_THREADS", "0"),),
               says=r"done: Go")
    yield Case("A localize with SEAL_NUMPY_ONLY=junk", localize, codes=(0,), env=(("SEAL_NUMPY_ONLY", "junk"),),
               says=r"(?s).")


def _map_type_cases() -> Iterator[Case]:
    """Values of the wrong type where a map wants another: a room's polygon of text, rooms as a mapping, a place's
    ``openable`` written as text, the robot's hand holding a list, YAML's own directives, a key that is a list."""
    def bad(name: str, old: bytes, new: bytes, says: str = r"m\.yaml:\d+:\d+: ") -> Case:
        assert old in SMALL, old
        return Case(f"A validate of a map whose {name}", ("validate", "m.yaml"), (("m.yaml", SMALL.replace(old, new)),),
                    codes=(1,), keep=("m.yaml",), says=says)
    yield bad("room is a polygon of two points", b"box: [0, 0, 5, 10]", b"polygon: [[0, 0], [5, 10]]")
    yield bad("room's polygon is of text", b"box: [0, 0, 5, 10]", b"polygon: [['0', '0'], ['5', '0'], ['5', '10']]")
    yield bad("room's polygon is one point thrice", b"box: [0, 0, 5, 10]", b"polygon: [[1, 1], [1, 1], [1, 1]]")
    yield bad("rooms are a mapping", b"rooms:\n  - {name: kitchen, box: [0, 0, 5, 10]}\n  - {name: hall, box: "
              b"[5, 0, 10, 10]}", b"rooms: {kitchen: [0, 0, 5, 10]}")
    yield bad("place's openable is the text 'yes'", b"openable: true", b"openable: 'yes'")
    yield bad("robot holds a list", b"robot: {pose: [2, 2, 0]}", b"robot: {pose: [2, 2, 0], holding: [cup]}")
    yield bad("room holds a key that is a list", b"{name: hall, box: [5, 0, 10, 10]}",
              b"{name: hall, box: [5, 0, 10, 10], ? [a, b] : 1}")
    yield bad("name is !!binary", b"name: m", b"name: !!binary aGVsbG8=")
    yield bad("bounds have no width", b"bounds: [0, 0, 10, 10]", b"bounds: [0, 0, 0, 10]")
    yield bad("prior is a list", b"priors: {cup: {kitchen: 0.5, hall: 0.5}}", b"priors: {cup: []}")
    yield Case("A validate of a map with a %YAML 1.2 directive", ("validate", "m.yaml"),
               (("m.yaml", b"%YAML 1.2\n---\n" + SMALL),), codes=(0,), keep=("m.yaml",), says=r"ok: ")
    yield Case("A validate of a map with a document end and garbage after it", ("validate", "m.yaml"),
               (("m.yaml", SMALL + b"...\n@@@ garbage\n"),), codes=(1,), keep=("m.yaml",), says=r"m\.yaml:\d+:\d+: ")


def _other_file_cases() -> Iterator[Case]:
    """Values of the wrong type in observations, vocabularies, frame YAML and end-to-end suites; clocks and seeds
    at the edge."""
    obs = ("localize", "--map", "apartment", "--particles", "20", "--observations", "o.yaml")
    for name, data in (("detections as a mapping", b"- {pose: [0, 0, 0], detections: {class: cup, at: [1, 1]}}\n"),
                       ("a detection at one number", b"- {pose: [0, 0, 0], detections: [{class: cup, at: [1]}]}\n"),
                       ("a pose of four numbers", b"- {pose: [0, 0, 0, 0], detections: []}\n"),
                       ("a class that is a list", b"- {pose: [0, 0, 0], detections: [{class: [cup], at: [1, 1]}]}\n")):
        yield Case(f"A localize --observations of {name}", obs, (("o.yaml", data),), codes=(1,), keep=("o.yaml",),
                   says=r"o\.yaml:\d+:\d+: ")
    yield Case("A localize --trajectory of a yaw as text", ("localize", "--map", "apartment", "--particles", "20",
                                                              "--trajectory", "t.yaml"),
               (("t.yaml", b"poses: [[0, 0, east]]\n"),), codes=(1,), keep=("t.yaml",), says=r"t\.yaml:1:\d+: ")
    voc = ("parse", "bring me a mug", "--vocabulary", "v.yaml")
    for name, data in (("synonyms as text", b"- {class: cup, synonyms: mug}\n"),
                       ("a class that is a mapping", b"- {class: {cup: 1}}\n")):
        yield Case(f"A parse --vocabulary of {name}", voc, (("v.yaml", data),), codes=(0, 1),
                   keep=("v.yaml",), says=r"v\.yaml:\d+:\d+: |Bring")
    frame = (b"frames:\n  - {frame: Zap, lexical_units: [zap], elements: {theme: {type: cup}}, "
             b"actions: [navigate(theme)]")
    for name, old, new in (("elements as a list", b"elements: {theme: {type: cup}}", b"elements: [theme]"),
                           ("preconditions as text", b"actions:", b"preconditions: holding(theme), actions:"),
                           ("lexical units as text", b"lexical_units: [zap]", b"lexical_units: zap")):
        yield Case(f"A validate of a YAML frame with {name}", ("validate", "f.yaml"),
                   (("f.yaml", frame.replace(old, new) + b"}\n"),), codes=(0, 1), keep=("f.yaml",),
                   says=r"f\.yaml:\d+:\d+: |ok: 1 frame")
    e2e = ("bench", "e2e", "--file", "e.yaml", "--jobs", "1", "--particles", "20")
    for name, data in (("cases as a mapping", b"cases: {a: 1}\n"),
                       ("a text that is a number", b"cases:\n  - {map: studio, text: 5, plan: ['Go(goal=sofa_1)']}\n"),
                       ("a plan that is text", b"cases:\n  - {map: studio, text: go to the sofa, plan: 'Go'}\n")):
        yield Case(f"A bench e2e --file of {name}", e2e, (("e.yaml", data),), codes=(1,), keep=("e.yaml",),
                   says=r"e\.yaml:\d+:\d+: ", timeout=120)
    sofa = ("run", "go to the sofa", "--map", "studio", "--particles", "20")
    for clock, codes, says in (("2026-02-29T10:00", (1,), r"--clock"), ("0000-01-01T00:00", (1,), r"--clock"),
                               ("10:00:00", (1,), r"--clock"), ("9999-12-31T23:59", (0,), r"done: Go")):
        yield Case(f"A run --clock {clock}", (*sofa, "--clock", clock), codes=codes, says=says)
    yield Case("A run --seed 1e3", (*sofa, "--seed", "1e3"), codes=(2,), says=r"--seed")
