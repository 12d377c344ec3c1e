"""Round hostile32's hostile inputs of ``seal bench reliability`` (an attacker's, as
:mod:`seal_cli.bench.reliability_attacker`'s, kept apart from that long list): what hostile31 noticed and left — a
frame library whose lexical unit is a function word, a precondition cycle said as one frame's, an option given twice,
options a policy never reads, an end-to-end suite's map named anywhere."""

from __future__ import annotations

from collections.abc import Iterator

from seal_cli.bench.reliability import Case

__all__ = ["hostile32_cases"]

CATEGORY = b"category object = cup, bowl\n"


def _frame(name: bytes, unit: bytes, requires: bytes = b"", ensures: bytes = b"") -> bytes:
    """A ``.frame`` frame of one element that validates alone (with :data:`CATEGORY`)."""
    return (b"frame " + name + b' "' + unit + b'" {\n  theme: object\n' + (b"  requires " + requires + b"\n" if requires
                                                                          else b"")
            + b"  do navigate(theme)\n" + (b"  ensures " + ensures + b"\n" if ensures else b"") + b"}\n")


def hostile32_cases() -> Iterator[Case]:
    """Round hostile32's batches, each recorded before its fix."""
    yield from _function_word_cases()
    yield from _cycle_cases()
    yield from _repeated_option_cases()
    yield from _policy_option_cases()
    yield from _suite_map_cases()


def _function_word_cases() -> Iterator[Case]:
    """A lexical unit that is a function word of English ("the", "a", "of", "and", "it", "with", "must"): accepted,
    and then "the cup" parsed as that frame, "bring it" as another. Refused at the unit's line and column."""
    for word in ("the", "a", "of", "and", "it", "with", "must", "them", "which"):
        data = CATEGORY + _frame(b"Zap", word.encode())
        yield Case(f"A validate of a .frame whose lexical unit is the function word '{word}'", ("validate", "f.frame"),
                   (("f.frame", data),), codes=(1,), keep=("f.frame",),
                   says=rf"f\.frame:2:11: lexical unit '{word}' of Zap is .*function word")
    yield Case("A parse of 'the cup' with a library whose unit is 'the'",
               ("parse", "the cup", "--framelib", "+f.frame"), (("f.frame", CATEGORY + _frame(b"Zap", b"the")),),
               codes=(1,), keep=("f.frame",), says=r"f\.frame:2:11: lexical unit 'the' of Zap", unsaid=r"Zap  'the'")
    yield Case("A plan of 'bring it to the kitchen' with a library whose unit is 'it'",
               ("plan", "bring the cup to the kitchen", "--map", "apartment", "--framelib", "+f.frame"),
               (("f.frame", CATEGORY + _frame(b"Zap", b"it")),), codes=(1,), keep=("f.frame",),
               says=r"f\.frame:2:11: lexical unit 'it' of Zap")
    yield Case("A validate of a .frame whose unit opens with a determiner ('the cup')", ("validate", "f.frame"),
               (("f.frame", CATEGORY + _frame(b"Zap", b"the cup")),), codes=(1,), keep=("f.frame",),
               says=r"f\.frame:2:11: lexical unit 'the cup' of Zap")
    yield Case("A validate of a .frame whose second unit is 'of'", ("validate", "f.frame"),
               (("f.frame", CATEGORY + _frame(b"Zap", b'zap" "of')),), codes=(1,), keep=("f.frame",),
               says=r"f\.frame:2:17: lexical unit 'of' of Zap")
    yield Case("A validate of a YAML frame whose lexical unit is 'of'", ("validate", "f.yaml"),
               (("f.yaml", b"categories:\n  object: [cup, bowl]\nframes:\n  - {frame: Zap, lexical_units: [zap, of], "
                 b"elements: {theme: object}, actions: [navigate(theme)]}\n"),), codes=(1,), keep=("f.yaml",),
               says=r"f\.yaml:4:39: lexical unit 'of' of Zap")
    yield Case("A validate of a YAML file adding the unit 'and' to a frame", ("validate", "f.frame", "u.yaml"),
               (("f.frame", CATEGORY + _frame(b"Zap", b"zap")),
                ("u.yaml", b"lexical_units:\n  - {frame: Zap, unit: and, source: me}\n")), codes=(1,),
               keep=("f.frame", "u.yaml"), says=r"u\.yaml:2:\d+: lexical unit 'and' of Zap")
    # guards: a unit with function words after its verb, and a question's unit ("how many", the standard Count's)
    yield Case("A validate of a .frame whose unit is 'zap the way to'", ("validate", "f.frame"),
               (("f.frame", CATEGORY + _frame(b"Zap", b"zap the way to")),), codes=(0,), keep=("f.frame",),
               says=r"ok: 1 frame")
    yield Case("A validate of a .frame whose unit is 'how much'", ("validate", "f.frame"),
               (("f.frame", CATEGORY + _frame(b"Zap", b"how much")),), codes=(0,), keep=("f.frame",),
               says=r"ok: 1 frame")


def _cycle_cases() -> Iterator[Case]:
    """A precondition cycle of three frames, one of which also needs what it achieves itself: said "Zap → Zap",
    naming one frame of the three. The whole cycle is said, at the first frame's line and column."""
    three = (CATEGORY + _frame(b"Zap", b"zap", b"a(theme), c(theme)", b"b(theme), c(theme)")
             + _frame(b"Bop", b"bop", b"b(theme)", b"d(theme)") + _frame(b"Cop", b"cop", b"d(theme)", b"a(theme)"))
    yield Case("A validate of a precondition cycle of three frames, one needing what it achieves",
               ("validate", "f.frame"), (("f.frame", three),), codes=(1,), keep=("f.frame",),
               says=r"f\.frame:2:7: precondition cycle: Zap → Cop → Bop → Zap", unsaid=r"Zap → Zap")
    yield Case("A plan with a library of a precondition cycle of three frames, one needing what it achieves",
               ("plan", "zap the cup", "--map", "apartment", "--framelib", "+f.frame"), (("f.frame", three),),
               codes=(1,), keep=("f.frame",), says=r"f\.frame:2:7: precondition cycle: Zap → Cop → Bop → Zap")
    # two loops through one frame (Zap needs Bop's and Cop's, each needs Zap's): every frame named, Zap twice
    forked = (CATEGORY + _frame(b"Zap", b"zap", b"a(theme), c(theme)", b"b(theme), d(theme)")
              + _frame(b"Bop", b"bop", b"b(theme)", b"a(theme)") + _frame(b"Cop", b"cop", b"d(theme)", b"c(theme)"))
    yield Case("A validate of two precondition loops through one frame", ("validate", "f.frame"),
               (("f.frame", forked),), codes=(1,), keep=("f.frame",),
               says=r"f\.frame:2:7: precondition cycle: Zap → Bop → Zap → Cop → Zap")
    yield Case("A validate of a YAML precondition cycle of three frames, one needing what it achieves",
               ("validate", "f.yaml"),
               (("f.yaml", b"categories:\n  object: [cup]\nframes:\n"
                 b"  - {frame: Zap, lexical_units: [zap], elements: {theme: object}, preconditions: [a(theme), "
                 b"c(theme)], actions: [navigate(theme)], postconditions: [b(theme), c(theme)]}\n"
                 b"  - {frame: Bop, lexical_units: [bop], elements: {theme: object}, preconditions: [b(theme)], "
                 b"actions: [navigate(theme)], postconditions: [d(theme)]}\n"
                 b"  - {frame: Cop, lexical_units: [cop], elements: {theme: object}, preconditions: [d(theme)], "
                 b"actions: [navigate(theme)], postconditions: [a(theme)]}\n"),), codes=(1,), keep=("f.yaml",),
               says=r"f\.yaml:4:\d+: precondition cycle: Zap → Cop → Bop → Zap")
    # guards: a plain cycle of three, and a frame alone needing what only it achieves
    plain = (CATEGORY + _frame(b"Zap", b"zap", b"a(theme)", b"b(theme)")
             + _frame(b"Bop", b"bop", b"b(theme)", b"d(theme)") + _frame(b"Cop", b"cop", b"d(theme)", b"a(theme)"))
    yield Case("A validate of a plain precondition cycle of three frames", ("validate", "f.frame"),
               (("f.frame", plain),), codes=(1,), keep=("f.frame",),
               says=r"f\.frame:2:7: precondition cycle: Zap → Cop → Bop → Zap")
    yield Case("A validate of a frame needing what only it achieves", ("validate", "f.frame"),
               (("f.frame", CATEGORY + _frame(b"Zap", b"zap", b"a(theme)", b"a(theme)")),), codes=(1,),
               keep=("f.frame",), says=r"f\.frame:2:7: precondition cycle: Zap → Zap")


def _repeated_option_cases() -> Iterator[Case]:
    """An option that takes one value given twice (``--clock 10:00 --clock 11:00``): the last was taken, silently,
    as click does. Refused naming the option, for every command; repeatable options and flags given twice stay."""
    sofa = ("run", "go to the sofa", "--map", "studio", "--particles", "20")
    yield Case("A run --clock given twice", (*sofa, "--clock", "10:00", "--clock", "11:00"), codes=(1,),
               says=r"--clock is given twice \('10:00', '11:00'\)")
    yield Case("A run --clock given twice, once with '='", (*sofa, "--clock=10:00", "--clock", "11:00"), codes=(1,),
               says=r"--clock is given twice")
    yield Case("A run --map given twice", ("run", "go to the sofa", "--map", "studio", "--map", "apartment"),
               codes=(1,), says=r"--map is given twice \('studio', 'apartment'\)")
    yield Case("A run --seed given three times", (*sofa, "--seed", "1", "--seed", "2", "--seed", "3"), codes=(1,),
               says=r"--seed is given 3 times \('1', '2', '3'\)")
    yield Case("A run --png given twice", (*sofa, "--png", "a.png", "--png", "b.png"), codes=(1,),
               absent=("a.png", "b.png"), says=r"--png is given twice")
    yield Case("A localize --steps given twice", ("localize", "--map", "apartment", "--task", "go to the kitchen",
                                                  "--particles", "20", "--steps", "1", "--steps", "2"), codes=(1,),
               says=r"--steps is given twice")
    yield Case("A plan --map given twice", ("plan", "go to the sofa", "--map", "apartment", "--map", "studio"),
               codes=(1,), says=r"--map is given twice")
    yield Case("A parse --vocabulary given twice", ("parse", "go to the sofa", "--vocabulary", "v.yaml",
                                                    "--vocabulary", "v.yaml"),
               (("v.yaml", b"- {class: sofa, synonyms: [couch]}\n"),), codes=(1,), keep=("v.yaml",),
               says=r"--vocabulary is given twice")
    yield Case("A bench tasks --seed given twice", ("bench", "tasks", "--suite", "map", "--map", "studio", "--command",
                                                   "go to the sofa", "--layouts", "1", "--policies", "oracle",
                                                   "--jobs", "1", "--seed", "1", "--seed", "2"), codes=(1,),
               says=r"--seed is given twice", timeout=120)
    yield Case("A bench e2e --jobs given twice", ("bench", "e2e", "--jobs", "1", "--jobs", "2"), codes=(1,),
               says=r"--jobs is given twice")
    # guards: repeatable options and a flag given twice
    yield Case("A run --done given twice", (*sofa, "--done", "go to the hall", "--done", "go to the balcony"),
               codes=(0,), says=r"done: Go")
    yield Case("A localize --task given twice", ("localize", "--map", "apartment", "--task", "go to the kitchen",
                                                 "--task", "go to the bedroom", "--particles", "20", "--steps", "1"),
               codes=(0,), says=r"(?s).")
    yield Case("A plan --json given twice", ("plan", "go to the kitchen", "--map", "apartment", "--json", "--json"),
               codes=(0,), says=r"(?s).")
    yield Case("A parse with --framelib given twice",
               ("parse", "zap the cup", "--framelib", "+f.frame", "--framelib", "+g.frame"),
               (("f.frame", CATEGORY + _frame(b"Zap", b"zap")),
                ("g.frame", b"category dish = plate\n" + _frame(b"Bop", b"bop"))), codes=(0,),
               keep=("f.frame", "g.frame"), says=r"(?s).")


def _policy_option_cases() -> Iterator[Case]:
    """``run --policy oracle --search-end 0.5``: the oracle never searches, yet the option was taken and nothing
    done with it; so ``--particles`` of a policy that keeps no particles, and ``--clock``, ``--vocabulary`` and
    ``--search-end`` of saycan, which runs from the text alone."""
    sofa = ("run", "go to the sofa", "--map", "studio")
    yield Case("A run --policy oracle --search-end 0.5", (*sofa, "--policy", "oracle", "--search-end", "0.5"),
               codes=(1,), says=r"--search-end.*--policy oracle")
    yield Case("A run --policy oracle --search-end at its default", (*sofa, "--policy", "oracle", "--search-end",
                                                                     "0.05"), codes=(1,), says=r"--search-end")
    yield Case("A run --policy oracle --particles 50", (*sofa, "--policy", "oracle", "--particles", "50"),
               codes=(1,), says=r"--particles.*--policy oracle")
    yield Case("A run --policy coverage --particles 50", (*sofa, "--policy", "coverage", "--particles", "50"),
               codes=(1,), says=r"--particles.*--policy coverage")
    yield Case("A run --policy prior_optimal --particles 50", (*sofa, "--policy", "prior_optimal", "--particles",
                                                               "50"), codes=(1,), says=r"--particles")
    yield Case("A run --policy saycan --clock 10:00", (*sofa, "--policy", "saycan", "--clock", "10:00"),
               codes=(1,), says=r"--clock.*--policy saycan")
    yield Case("A run --policy saycan --search-end 0.5", (*sofa, "--policy", "saycan", "--search-end", "0.5"),
               codes=(1,), says=r"--search-end.*--policy saycan")
    yield Case("A run --policy saycan --vocabulary", (*sofa, "--policy", "saycan", "--vocabulary", "v.yaml"),
               (("v.yaml", b"- {class: sofa, synonyms: [couch]}\n"),), codes=(1,), keep=("v.yaml",),
               says=r"--vocabulary.*--policy saycan")
    # guards: what a policy reads
    yield Case("A run --policy object_only --particles 30 --search-end 0.5",
               (*sofa, "--policy", "object_only", "--particles", "30", "--search-end", "0.5"), codes=(0,),
               says=r"done: Go")
    yield Case("A run --policy coverage --search-end 0.5", (*sofa, "--policy", "coverage", "--search-end", "0.5"),
               codes=(0,), says=r"done: Go")
    yield Case("A run --policy oracle --clock 10:00", (*sofa, "--policy", "oracle", "--clock", "10:00"), codes=(0,),
               says=r"done: Go")


def _suite_map_cases() -> Iterator[Case]:
    """An end-to-end suite's ``map:`` named any file: ``../../etc/passwd`` was read as a map (and refused as one), a
    name not beside the suite was looked for from the working folder. A map's path is the suite's: relative to its
    file, inside its folder's tree or seal's maps; an absolute path is taken as given."""
    from seal_cli.resources import map_path

    studio = map_path("studio").read_bytes()
    studio_image = map_path("studio").with_suffix(".pgm").read_bytes()
    def suite(name: str, map_name: bytes, files: tuple[tuple[str, bytes | str], ...], codes: tuple[int, ...],
              says: str, at: str = "e.yaml", cwd: str = "") -> Case:
        case = (b'cases:\n  - {map: "' + map_name + b'", text: "go to the sofa", plan: ["Go(goal=sofa_1)"]}\n')
        given = at.removeprefix(f"{cwd}/") if cwd else at
        return Case(f"A bench e2e --file whose map {name}", ("bench", "e2e", "--file", given, "--jobs", "1",
                                                           "--particles", "20"),
                    ((at, case), *files), codes=codes, keep=(at,), says=says, timeout=120, cwd=cwd)
    yield suite("climbs out to /etc/passwd", b"../" * 12 + b"etc/passwd", (), (1,),
                r"e\.yaml:2:\d+: .*outside")
    yield suite("is a map file above the suite's folder", b"../m.yaml",
                (("m.yaml", studio), ("studio.pgm", studio_image)), (1,), r"e\.yaml:2:\d+: .*outside", "s/e.yaml", "s")
    yield suite("is a map file in the working folder, not beside the suite", b"m.yaml",
                (("m.yaml", studio), ("studio.pgm", studio_image)), (1,), r"e\.yaml:2:\d+: .*no map",
                "s/e.yaml")
    # guards: a map beside the suite, below it, and a shipped map by name
    yield suite("is a map file below the suite's folder", b"maps/m.yaml",
                (("maps/m.yaml", studio), ("maps/studio.pgm", studio_image)), (0,), r"1/1")
    yield suite("is a shipped map by its name", b"studio", (), (0,), r"1/1")
