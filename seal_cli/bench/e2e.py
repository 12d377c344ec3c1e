"""The end-to-end suite: plain commands on a map, each with the plan it must ground to and how its run must end.

A :class:`Case` is a command on one of the suite's maps (``apartment``: ``maps/apartment.yaml``;
``aws``: the AWS small house annotated with rooms, places, people and things by
:func:`seal_cli.bench.houses.aws_house`; any other map shipped in ``maps/``, such as ``townhouse``; or a
map file, by its path from the cases file, inside its folder's tree or seal's maps, or by an absolute path:
:func:`_map_file`), and what must come of it:

- ``plan``: the steps ``seal plan --map`` must print (frames and their map ids, in order); or
  ``refused``: words the refusal must contain (a room the map lacks, a fixed thing to pick up);
- ``run``: how ``seal run`` must end: ``done`` (every frame executed) or ``not_found`` (the
  robot searched and the thing is not in the house); ``answer``: words the answer must contain;
  ``says``: words a line the run prints must contain ("put spoon_1 in sink_1");
- ``holding``: the class of what the robot holds at the start (as ``seal run --holding``), for a command
  to a robot that already has something in hand;
- ``done``: the commands already carried out, in order (as ``seal plan --done`` / ``seal run --done``): the
  command is planned and run in the house they left (e2e30).

A case is **plan-right** when the plan is exactly the expected one (or the refusal says what
it must), and **run-completed** when the run ends as expected. The cases are data
(``seal_cli/bench/suites/e2e.yaml``), written from the maps, never from an evaluation set.
"""

from __future__ import annotations

import tempfile
from collections.abc import Callable, Iterable, Sequence
from dataclasses import asdict, dataclass, replace
from pathlib import Path
from typing import Any

from seal_cli.bench.workers import ordered
from seal_cli.errors import SealError, Where

__all__ = ["AWS_ROBOT", "Case", "Verdict", "load_cases", "run_cases", "summarise"]

AWS_ROBOT = (1.5, -4.0, 0.0)
"""Where the robot starts in the AWS house: the living room, south of the sofa."""

RUN_ENDS = ("done", "not_found")


@dataclass(frozen=True)
class Case:
    """One command on one map and what must come of it (see the module docstring)."""

    map: str
    text: str
    plan: tuple[str, ...] | None = None
    refused: str | None = None
    run: str | None = None
    answer: str | None = None
    file: str | None = None
    """The map file, for a map that is not one of :data:`MAPS` (a shipped map, or a user's own)."""
    says: str | None = None
    holding: str | None = None
    """The class of what the robot holds at the start (None: what the map's robot holds)."""
    done: tuple[str, ...] = ()
    """The commands already carried out, in order (``--done``)."""

    def __post_init__(self) -> None:
        if (self.plan is None) == (self.refused is None):
            raise SealError(f"case {self.text!r}: give exactly one of plan and refused")
        if self.run is not None and self.run not in RUN_ENDS:
            raise SealError(f"case {self.text!r}: run is one of {', '.join(RUN_ENDS)}, not {self.run!r}")


@dataclass(frozen=True)
class Verdict:
    """What came of one case."""

    map: str
    text: str
    plan_right: bool
    got: str
    run_ran: bool = False
    run_completed: bool = False
    run_reason: str = ""
    answer: str | None = None
    path_m: float = 0.0


SHIPPED = ("e2e.yaml", "e2e_houses.yaml", "e2e_cafe.yaml", "e2e_clinic.yaml", "e2e_users9.yaml", "e2e_users10.yaml",
           "e2e_e2e11.yaml", "e2e_users11.yaml", "e2e_users12.yaml", "e2e_users13.yaml", "e2e_users14.yaml",
           "e2e_users15.yaml", "e2e_users16.yaml", "e2e_users17.yaml", "e2e_users18.yaml", "e2e_users19.yaml",
           "e2e_users20.yaml", "e2e_users21.yaml", "e2e_users22.yaml", "e2e_users23.yaml", "e2e_users24.yaml",
           "e2e_users25.yaml", "e2e_users26.yaml", "e2e_users28.yaml", "e2e_users30.yaml", "e2e_users31.yaml")
"""The shipped suite's files in ``suites/``: the apartment and the AWS house; the example houses; the cafe;
the clinic (and the users' trials on every house, e2e_users18 also on the held-out lodge, e2e_users19 on the
held-out flat, e2e_users20 on the held-out care home, e2e_users21 on the held-out student house,
e2e_users22 on the held-out guesthouse, e2e_users23 on the held-out studio flat, e2e_users24 on the held-out corner
shop, e2e_users25 on the held-out houseboat, e2e_users26 on the held-out library, e2e_users28 on the held-out
workshop, e2e_users30 on the held-out fitness club, e2e_users31 on the houses the others use least: the lodge, the
flat, the care home and the terrace; e2e_users27, on the held-out bakery, is not shipped: three of
its plans are not what its user expected; nor is e2e_users29, on the held-out school, for two: docs/planning.md,
"e2e32")."""


def load_cases(path: str | Path | None = None) -> list[Case]:
    """The cases of a suite file (default: the shipped suite, every file of :data:`SHIPPED`)."""
    if path is None:
        return [c for name in SHIPPED for c in load_cases(Path(__file__).parent / "suites" / name)]
    return _load(Path(path))


KEYS = ("map", "text", "plan", "refused", "run", "answer", "says", "holding", "done")
"""The keys of a case in a suite file."""


def _load(path: Path) -> list[Case]:
    """The cases of one suite file; every problem of every case at its line and column (a value of the wrong
    type, an unknown or repeated key, a case with both or neither of plan and refused)."""
    import yaml

    from seal_cli.errors import SealErrors
    from seal_cli.fileio import compose_yaml, read_text
    from seal_cli.frames.taxonomy import check_class_name
    from seal_cli.yamlnodes import NodeReader

    text = read_text(path)
    reader = NodeReader(text, str(path))
    root = compose_yaml(text, str(path))
    entries = None
    if isinstance(root, yaml.MappingNode):
        entries = next((value for key, _, value in reader.pairs(root, "the suite", ("cases",)) if key == "cases"),
                       None)
    if not isinstance(entries, yaml.SequenceNode):
        reader.problem("an end-to-end suite is a mapping with cases: [...]",
                       entries if entries is not None else root)
        entries = yaml.SequenceNode("tag:yaml.org,2002:seq", [])
    cases = []
    for number, entry in enumerate(entries.value, 1):
        fields = {key: (key_node, value) for key, key_node, value in reader.pairs(entry, f"case {number}", KEYS)}
        if not isinstance(entry, yaml.MappingNode):
            continue  # said by pairs
        values: dict[str, Any] = {}
        for key, (_, value) in fields.items():
            if key in ("plan", "done"):
                what = "a step of case {}'s plan" if key == "plan" else "a command of case {}'s done"
                values[key] = tuple(v for v in (reader.string(item, what.format(number))
                                                for item in reader.items(value, f"case {number}'s {key}")) if v)
            else:
                values[key] = reader.string(value, f"case {number}'s {key}")
        text_node = fields["text"][1] if "text" in fields else None
        if values.get("text") is not None and text_node is not None and not text_node.tag.endswith(":str"):
            kind = text_node.tag.rsplit(":", 1)[-1]         # rel33: `text: 5` was scored as a plan missed
            reader.problem(f"case {number}'s text {values['text']!r} is read by YAML as {kind}, not as a command: "
                           "quote it if it is the command meant", text_node)
            values["text"] = None
        if values.get("holding") is not None:  # a number there was a plan missed, not a problem of the file (hostile31)
            try:
                check_class_name(values["holding"], f"case {number}'s holding")
            except SealError as error:
                reader.problem(error.message, fields["holding"][1])
        missing = [k for k in ("text", "map") if k not in fields]
        if missing:
            reader.problem(f"case {number} has no {' and no '.join(missing)} (its map: one of {', '.join(MAPS)}, a "
                           "shipped map or a map file)", entry)
            continue
        if ("plan" in fields) == ("refused" in fields):
            reader.problem(f"case {number}: give exactly one of plan and refused", entry)
            continue
        if "run" in fields and values["run"] is not None and values["run"] not in RUN_ENDS:
            reader.problem(f"case {number}'s run is one of {', '.join(RUN_ENDS)}, not {values['run']!r}",
                           fields["run"][1])
            continue
        if any(v is None for v in values.values()):
            continue  # said above
        try:
            where = _map_file(values["map"], path.parent, number, path)
        except SealError as error:
            reader.problem(error.message, fields["map"][1])
            continue
        cases.append(Case(values["map"], values["text"], values.get("plan"), values.get("refused"),
                          values.get("run"), values.get("answer"), where, values.get("says"),
                          values.get("holding"), values.get("done", ())))
    if not entries.value and not reader.problems:  # a run of nothing reported "all 0" and exited 0, as if it passed
        reader.problem("the suite holds no cases: list at least one under cases: (text, map, and plan or refused)",
                       entries)
    if reader.problems:
        raise reader.problems[0] if len(reader.problems) == 1 else SealErrors(reader.problems)
    return cases


def _map_file(name: str, base: Path, number: int, suite: Path) -> str | None:
    """Where a case's map is: None for one of :data:`MAPS`; else, for a relative name, a map file found from the
    cases file's folder (``base``), never from the working folder, or a shipped map by its name (``townhouse``); for
    an absolute name, that file, as given.

    A relative name must stay inside the cases file's folder or the folder of seal's shipped maps once its ``..``
    are taken (hostile32: ``map: ../../etc/passwd`` was read as a map, and refused only as one; a name not beside
    the suite was looked for from where seal was started). The names are compared as written, ``..`` taken away
    but links not followed: a link put in the suite's folder is the suite's own. A map elsewhere is named by its
    absolute path, which says where it is whatever folder the suite is in or is run from."""
    if name in MAPS:
        return None
    import os

    from seal_cli.resources import maps_dir

    given = Path(name)
    folder = Path(os.path.normpath(base.absolute()))
    shipped = Path(os.path.normpath(maps_dir().absolute()))
    found = given if given.is_absolute() else Path(os.path.normpath(folder / given))
    if not given.is_absolute() and not found.is_file() and os.sep not in name:       # a shipped map, by its name
        found = shipped / (name if name.endswith((".yaml", ".yml")) else f"{name}.yaml")
    elif not given.is_absolute() and not (found.is_relative_to(folder) or found.is_relative_to(shipped)):
        raise SealError(f"case {number}'s map {name!r} is outside the suite's folder {folder} and seal's maps: a "
                        "case names a map file in its suite's folder or below it, or a shipped map; give a map "
                        "elsewhere by its absolute path", Where(str(suite)))
    if not found.is_file():
        raise SealError(f"case {number}: no map {name!r} (the suite's maps are {', '.join(MAPS)}; a shipped map "
                        "or a map file, relative to the cases file, also works)", Where(str(suite)))
    return str(found.resolve())


MAPS: dict[str, Callable[[Path, Path], Path]] = {
    "apartment": lambda folder, data: _shipped("apartment"),
    "aws": lambda folder, data: _aws(folder, data),
}
"""The suite's maps by name: each writes (or finds) its map file, given a scratch folder and the shared data."""


def _shipped(name: str) -> Path:
    from seal_cli.resources import map_path

    return map_path(name)


def _aws(folder: Path, data: Path) -> Path:
    from seal_cli.bench.houses import AWS_ITEMS, AWS_OBJECTS, AWS_PEOPLE, AWS_PLACES, PAPER_PRIORS, aws_house

    priors = {**PAPER_PRIORS, "apple": {"fridge": 0.5, "kitchen": 0.3}, "book": {"desk": 0.5, "bedroom": 0.3}}
    return aws_house(folder, data, "wings", AWS_ROBOT, priors=priors, objects=[*AWS_OBJECTS, *AWS_ITEMS],
                     places=AWS_PLACES, people=AWS_PEOPLE)


def held(the_map: Any, holding: str) -> Any:
    """The map with its robot holding a thing of the class ``holding`` (refused, as ``seal run --holding`` is,
    when the robot cannot hold one)."""
    from seal_cli.maps.model import Robot

    the_map.check_holding(holding)
    return replace(the_map, robot=Robot(the_map.robot.pose, holding))


def plan_steps(case: Case, the_map: Any, library: Any) -> tuple[bool, str]:
    """Whether the case plans right, and what it planned (or the refusal); with the robot holding what the case says
    it holds."""
    from seal_cli.pipeline import plan as plan_text

    try:
        if case.holding is not None:
            the_map = held(the_map, case.holding)
        found = plan_text(case.text, library, map=the_map, done=case.done)
    except SealError as error:
        return case.refused is not None and case.refused in error.message, f"refused: {error.message}"
    steps = tuple(str(step) for step in found.steps)
    return case.plan == steps, "; ".join(steps)


def _judge(args: tuple[Case, str, int, int, Sequence[str] | None]) -> Verdict:
    return judge(*args)


def judge(case: Case, map_file: str, seed: int, particles: int, framelib: Sequence[str] | None) -> Verdict:
    """Plan the case, then run it if it says how the run must end (one worker's job)."""
    import numpy as np

    from seal_cli.frames.reading import load_library
    from seal_cli.maps.formats.map_server import load_map
    from seal_cli.pipeline import run_on_map
    from seal_cli.sim.agent import Budget
    from seal_cli.sim.policies import make_policy

    library = load_library(framelib)
    the_map = load_map(map_file)
    if case.holding is not None:
        try:
            the_map = held(the_map, case.holding)
        except SealError as error:
            return Verdict(case.map, case.text, False, f"refused: {error.message}")
    right, got = plan_steps(case, the_map, library)
    if case.run is None or case.refused is not None:
        return Verdict(case.map, case.text, right, got)
    try:
        agent, result = run_on_map(the_map, case.text, library, make_policy("sefm", particles),
                                   rng=np.random.default_rng(seed), budget=Budget(steps=400, metres=300.0),
                                   done=case.done)
    except SealError as error:
        return Verdict(case.map, case.text, right, got, True, False, f"refused: {error.message}")
    ended = result.completed if case.run == "done" else (not result.completed and result.why.value == "not_found")
    answered = case.answer is None or (result.answer is not None and case.answer in result.answer)
    answered = answered and (case.says is None or any(case.says in r.text for r in agent.records))
    return Verdict(case.map, case.text, right, got, True, ended and answered, result.reason, result.answer,
                   round(result.path_m, 2))


def run_cases(cases: Iterable[Case], data: Path, *, seed: int = 0, particles: int = 100, jobs: int = 1,
              framelib: Sequence[str] | None = None,
              progress: Callable[[int, int], None] | None = None) -> list[Verdict]:
    """Every case's verdict, in order; ``jobs`` worker processes."""
    cases = list(cases)
    with tempfile.TemporaryDirectory(prefix="seal-e2e-") as scratch:
        files = {c.map: c.file or str(MAPS[c.map](Path(scratch), data)) for c in cases}
        args = [(c, files[c.map], seed, particles, framelib) for c in cases]
        verdicts: list[Verdict] = []
        if jobs <= 1:
            for i, a in enumerate(args, 1):
                verdicts.append(judge(*a))
                if progress:
                    progress(i, len(args))
            return verdicts
        for i, verdict in enumerate(ordered(_judge, args, jobs), 1):
            verdicts.append(verdict)
            if progress:
                progress(i, len(args))
    return verdicts


def summarise(verdicts: Sequence[Verdict]) -> dict[str, Any]:
    """Plan-right and run-completed counts and rates per map and for ``all``, and the misses."""
    groups: dict[str, list[Verdict]] = {"all": list(verdicts)}
    for v in verdicts:
        groups.setdefault(v.map, []).append(v)
    report: dict[str, Any] = {"groups": {}}
    for name, members in groups.items():
        ran = [v for v in members if v.run_ran]
        report["groups"][name] = {
            "n": len(members), "plan_right": sum(v.plan_right for v in members),
            "plan_rate": round(sum(v.plan_right for v in members) / len(members), 3) if members else None,
            "runs": len(ran), "run_completed": sum(v.run_completed for v in ran),
            "run_rate": round(sum(v.run_completed for v in ran) / len(ran), 3) if ran else None}
    report["misses"] = [asdict(v) for v in verdicts if not v.plan_right or (v.run_ran and not v.run_completed)]
    return report
