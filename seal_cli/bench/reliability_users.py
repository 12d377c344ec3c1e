"""A new user's hostile inputs of ``seal bench reliability`` (round e2e9): kinds the issue's, the hand-written,
the reviewer's and the generated cases did not hold, each found by trying seal as a user and fixed in one place.

- a source line of 20,000 characters (minified YAML, a nesting bomb): the message shows a window of it around
  the column (:func:`seal_cli.errors.caret`), not the whole line;
- ``-`` (or a blank) for an output: refused (:class:`seal_cli.fileio.Outputs`), not written as a file called ``-``;
- a refusal inside a ``--done`` command names that option (:func:`seal_cli.planning.problem.naming_done`);
- the robot holding what cannot be held (a place, a room, a person, a place's class), in the map (located at
  ``robot.holding``) or by ``--holding`` (named): refused (:meth:`seal_cli.maps.model.Map.unholdable`); the run
  had put the fridge on the sofa;
- an object whose name in a run (``fridge_1``) is a place's: refused at its line, not "two items in the world";
- "something", "anything" as the thing of a frame on a map; "upstairs" as a room: refused at their column, no
  sweep of the whole house for a "something".
"""

from __future__ import annotations

from collections.abc import Iterator

from seal_cli.bench.reliability import Case, hostile_setting

__all__ = ["user_cases"]

NO_LONG_LINE = r"\A(?![\s\S]*[^\n]{300})[\s\S]*"
"""A pattern's start: no line of the message is 300 characters or longer (then what it must say)."""


def user_cases() -> Iterator[Case]:
    """The cases, each with the shape of its message (``says``)."""
    _, image, text, both, inputs, loc, _ = hostile_setting()
    deep = ("deep.yaml", ("[" * 20_000 + "]" * 20_000 + "\n").encode())
    yield Case("U a line of 40,000 brackets: a window of it in the message", ("map", "deep.yaml"), (deep,),
               codes=(1,), keep=("deep.yaml",), says=NO_LONG_LINE + r"deep\.yaml:1:\d+: YAML syntax error")
    long = ("long.yaml", text.replace("name: apartment", "name: apartment  # " + "x" * 5_000 + "\n  bad: [").encode())
    yield Case("U a 5,000-character comment before a syntax error", ("validate", "long.yaml"), (long, image),
               codes=(1,), says=NO_LONG_LINE + r"long\.yaml:\d+:\d+:")
    too_long = "go to the kitchen and " * 100
    yield Case("U a command of 2,200 characters: a window of it", ("plan", too_long), codes=(1,),
               says=NO_LONG_LINE + r"column 1001: command too long")
    # -- "-" for an output
    for argv in (("map", "m.yaml", "--png", "-"), (*loc, "--rrd", "-"),
                 ("run", "go to the kitchen", "--map", "m.yaml", "--particles", "20", "--png", "-"),
                 ("plan", "--pddl", "-", "go to the kitchen"), ("map", "m.yaml", "--png", " ")):
        option = next(a for a in argv if a in ("--png", "--rrd", "--pddl"))
        value = argv[argv.index(option) + 1]
        yield Case(f"U {argv[0]} {option} {value!r}", argv, both, codes=(1,), keep=inputs, absent=("-", " "),
                   says=rf"{option} '{value}': seal writes this output into a (file|folder), not to standard output")
    # -- --done and --holding
    yield Case("U a refusal inside --done names it", ("plan", "--map", "m.yaml", "--done", "go to the garage",
                                                     "go to the kitchen"), both, codes=(1,), keep=inputs,
               says=r"column 7: in --done 'go to the garage': the apartment has no garage")
    yield Case("U --done too long names it", ("run", "go to the kitchen", "--map", "m.yaml", "--done", "x" * 3000),
               both, codes=(1,), keep=inputs, says=NO_LONG_LINE + r"in --done 'x+\.\.\.': command too long")
    for held, why in (("fridge_1", "a place of this map"), ("Anna", "a person of this map"),
                      ("kitchen", "a room of this map"), ("sofa", "the class of the place sofa_1")):
        yield Case(f"U run --holding {held}", ("run", "put it on the bed", "--map", "m.yaml", "--holding", held), both,
                   codes=(1,), keep=inputs, says=rf"--holding '{held}' is {why}")
    yield Case("U plan --holding a place", ("plan", "put it on the bed", "--map", "m.yaml", "--holding", "fridge_1"),
               both, codes=(1,), keep=inputs, says=r"--holding 'fridge_1' is a place of this map")
    holds = ("h.yaml", text.replace("holding: null", "holding: fridge_1").encode())
    yield Case("U the map's robot holds its fridge", ("run", "go to the kitchen", "--map", "h.yaml"), (holds, image),
               codes=(1,), keep=("h.yaml",), says=r"h\.yaml:\d+:\d+: the robot holds 'fridge_1', which is a place")
    clash = ("c.yaml", text.replace("  - {class: apple, in: fridge_1}",
                                    "  - {class: apple, in: fridge_1}\n  - {class: fridge, in: fridge_1}").encode())
    yield Case("U an object called as a place in a run", ("run", "open the fridge", "--map", "c.yaml"),
               (clash, image), codes=(1,), keep=("c.yaml",),
               says=r"c\.yaml:\d+:\d+: object fridge is called fridge_1 in a run, which is already the name of a place")
    # -- words a map has no thing for
    for said, word, column in (("bring me something", "something", 10), ("find anything in the fridge",
                                                                          "anything", 6)):
        yield Case(f"U run {said!r}", ("run", said, "--map", "m.yaml"), both, codes=(1,), keep=inputs, timeout=30,
                   says=rf"column {column}: '{word}' does not say what kind of thing")
    yield Case("U run 'go upstairs' on a one-floor map", ("run", "go upstairs", "--map", "m.yaml"), both, codes=(1,),
               keep=inputs, timeout=30, says=r"column 4: the apartment has no upstairs")
