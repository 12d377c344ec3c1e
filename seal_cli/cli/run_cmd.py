"""``seal run``: a simulated robot carries out a command on a map; ``seal bench tasks``: the ALFRED-2D suite."""

from __future__ import annotations

import os
from collections.abc import Callable, Sequence
from datetime import datetime
from pathlib import Path
from typing import Any

import typer

from seal_cli.cli import (
    MAX_COUNT,
    MAX_PARTICLES,
    MAX_RUN_METRES,
    MAX_RUN_STEPS,
    FramelibOption,
    JsonOption,
    a_number,
    bench_app,
    choices,
    command,
    emit_json,
    err,
    framelib_paths,
    one_held,
    out,
)
from seal_cli.cli.framework import given
from seal_cli.cli.output import plain, styled
from seal_cli.sim.policies import DEFAULT_POLICIES, POLICIES
from seal_cli.sim.unsearched import SEARCH_END

SUITES = ("alfred2d", "map", "context", "context_all", "context_held_out")

CONTEXT_SUITES = ("context", "context_all", "context_held_out")
"""``context``: the cases chosen by the headroom criterion (``bench.context.selected_houses``); ``context_all``:
every command from every own start of the three houses (the suite before search26), or ``--houses unseen``;
``context_held_out``: the cases the same criterion chose on houses drawn from a seed (``context.held_out_houses``)."""

SUITE_OPTIONS = {"data": ("--data", ("alfred2d", "context", "context_all")), "split": ("--split", ("alfred2d",)),
                 "goal": ("--goal", ("alfred2d",)), "limit": ("--limit", ("alfred2d",)),
                 "sample": ("--sample", ("alfred2d",)), "types": ("--type", ("alfred2d",)),
                 "map_name": ("--map", ("map",)), "commands": ("--command", ("map", *CONTEXT_SUITES)),
                 "layouts": ("--layouts", ("map", *CONTEXT_SUITES)), "house_set": ("--houses", ("context_all",)),
                 "starts": ("--starts", ("context_all",)), "fov": ("--fov", CONTEXT_SUITES)}
"""The options of ``bench tasks`` that only some suites read (parameter: option, suites). Given to another suite,
one was passed over in silence (hostile20): ``--suite map --type x`` or ``--limit 1``, meant to make a run short,
ran the whole suite for minutes; ``--suite alfred2d --map townhouse`` ran ALFRED-2D. Now refused before any work.
``--suite context_held_out`` draws its houses in code and reads no data: its ``--data`` was passed over (hostile29:
``--data /dev/null`` ran the whole suite), and without it the default folder had to be there all the same.
One table for every suite (hostile21): ``--houses``, ``--starts`` and ``--fov`` had a check of their own beside it
("--houses, --starts and --fov go with --suite context", by value, so ``--houses suite`` passed)."""


def _unread_options(suite: str, given: Callable[[str], bool]) -> None:
    """Refuse the options of :data:`SUITE_OPTIONS` given on the command line (``given(parameter)``) that ``suite``
    does not read."""
    from seal_cli.errors import SealError

    unread = [(option, suites) for name, (option, suites) in SUITE_OPTIONS.items()
              if suite not in suites and given(name)]
    if unread:
        said = "; ".join(f"{option} goes with --suite {' or '.join(suites)}" for option, suites in unread)
        raise SealError(f"--suite {suite} does not read {', '.join(o for o, _ in unread)}: {said}")


POLICY_OPTIONS = {"particles": "--particles", "search_end": "--search-end", "clock": "--clock",
                  "vocabulary_file": "--vocabulary"}
"""The options of ``seal run`` and ``seal bench tasks`` that some policies never read (parameter: option)."""

_TEXT_ALONE = ("runs from the instruction text alone, with no clock, vocabulary or search of seal's",
               "run from the instruction text alone, with no clock, vocabulary or search of seal's")


def _why_unread(parameter: str, searcher: Any) -> tuple[str, str] | None:
    """Why a policy (its class) never reads the option of ``parameter``, said of one policy and of several; None if
    it reads it."""
    itself = getattr(searcher, "drives_itself", False)
    if parameter == "particles" and not searcher.keeps_particles:
        keeping = ", ".join(name for name, e in POLICIES.items() if e.load().keeps_particles)
        return (f"keeps no particle beliefs (--particles goes with {keeping})",
                f"keep no particle beliefs (--particles goes with {keeping})")
    if parameter == "search_end" and searcher.oracle:
        return ("knows where everything is and never searches", "know where everything is and never search")
    if parameter in ("search_end", "clock", "vocabulary_file") and itself:
        return _TEXT_ALONE
    return None


def unread_by_policies(option: str, names: Sequence[str], given: Callable[[str], bool]) -> None:
    """Refuse, before any work, each option of :data:`POLICY_OPTIONS` given on the command line (``given(parameter)``)
    that no policy of ``names`` reads (``option``: ``--policy`` of ``seal run``, ``--policies`` of ``bench tasks``,
    whose list may mix policies: an option one of them reads stays). hostile32: ``run --policy oracle --search-end
    0.5`` was taken and nothing done with it (the oracle never searches); so was ``--particles`` of a policy that keeps
    no particles (oracle, coverage, prior_optimal, frame_dp, saycan) and ``--clock``, ``--vocabulary`` and
    ``--search-end`` of saycan, which runs from the text alone (its ``--rrd``, ``--png`` and ``--done`` are refused
    where it runs). rel33: ``bench tasks --policies oracle --particles 20`` too, by the same rule."""
    from seal_cli.errors import SealError

    if not names or any(name not in POLICIES for name in names):   # make_policy / choices name the known ones
        return
    loaded = {name: POLICIES[name].load() for name in dict.fromkeys(names)}
    groups: dict[tuple[tuple[str, tuple[str, str]], ...], list[str]] = {}
    for parameter, flag in POLICY_OPTIONS.items():
        whys = {name: _why_unread(parameter, searcher) for name, searcher in loaded.items()} if given(parameter) \
            else {}
        if whys and all(whys.values()):
            groups.setdefault(tuple((n, w) for n, w in whys.items() if w), []).append(flag)
    if groups:
        said = "; ".join(f"{' and '.join(flags)} {'is' if len(flags) == 1 else 'are'} not read by "
                         f"{_policies_said(option, whys)}" for whys, flags in groups.items())
        count = sum(len(flags) for flags in groups.values())
        raise SealError(f"{said}: leave {'it' if count == 1 else 'them'} out")


def _policies_said(option: str, whys: tuple[tuple[str, tuple[str, str]], ...]) -> str:
    """`--policy oracle, which knows ...`; of several, `--policies oracle,coverage: oracle and coverage keep ...`."""
    if len(whys) == 1:
        name, (one, _) = whys[0]
        return f"{option} {name}, which {one}"
    by_why: dict[tuple[str, str], list[str]] = {}
    for name, why in whys:
        by_why.setdefault(why, []).append(name)
    return f"{option} {','.join(n for n, _ in whys)}: " + "; ".join(
        f"{' and '.join(names)} {one if len(names) == 1 else several}" for (one, several), names in by_why.items())


KIND_STYLE = {"warn": "yellow", "plan": "bold", "frame": "bold cyan", "search": "yellow", "go": "", "see": "green",
              "look": "dim", "act": "green", "fail": "red", "replan": "magenta", "done": "bold green",
              "give_up": "bold red", "answer": "bold magenta"}


def _narrate(record: Any) -> None:
    if record.data.get("detail"):      # a survey's drives and looks: in --json and the recording, not said
        return
    style = KIND_STYLE.get(record.kind, "")
    where = f"[dim]({record.pose[0]:.2f}, {record.pose[1]:.2f}) {record.path_m:6.2f} m[/dim]"
    out.print(f"{where}  {styled(style, record.text)}" if style else f"{where}  {plain(record.text)}")


def read_clock(text: str | None) -> datetime | None:
    """``--clock``: a time of today (HH:MM) or a date and time (YYYY-MM-DDTHH:MM); a bad one is refused."""
    from seal_cli.errors import SealError

    if text is None:
        return None
    try:
        if "T" in text or "-" in text:
            return datetime.fromisoformat(text)
        hours, minutes = (int(part) for part in text.split(":"))
        return datetime.now().replace(hour=hours, minute=minutes, second=0, microsecond=0)
    except ValueError:
        raise SealError(f"--clock: {text!r} is no time; give HH:MM (14:05) or YYYY-MM-DDTHH:MM") from None


@command("run")
def run(
    text: str = typer.Argument(..., help="The command, e.g. \"stir the cup\"."),
    map_name: str = typer.Option(..., "--map", help="The map (a path or a shipped map's name); its ground-truth "
                                 "objects are the world the robot acts in."),
    holding: list[str] | None = typer.Option(None, "--holding", help="The class of what the robot holds at the start.",
                                             show_default=False),
    done: list[str] | None = typer.Option(None, "--done", help="A command already carried out (repeatable): its "
                                          "frames' postconditions hold at the start.", show_default=False),
    policy: str = typer.Option("sefm", "--policy", help="Who searches: " + "; ".join(
        f"{name} ({entry.summary})" for name, entry in POLICIES.items()) + "."),
    seed: int = typer.Option(0, "--seed", min=0, help="Seed of the one random generator."),
    particles: int = typer.Option(200, "--particles", min=1, max=MAX_PARTICLES,
                                   help="Particles per object and per frame."),
    max_steps: int = typer.Option(400, "--max-steps", min=1, max=MAX_RUN_STEPS,
                                   help="Give up after this many steps."),
    max_metres: float = typer.Option(300.0, "--max-metres", min=0.1, max=MAX_RUN_METRES,
                                      callback=a_number, help="Give up after driving this far."),
    search_end: float = typer.Option(SEARCH_END, "--search-end", min=0.0, max=1.0, callback=a_number,
                                     help="End a search for a kind of thing the map has a prior of, not found, once "
                                     "less than this share of its prior is left unsearched (0: only the budget "
                                     "ends it)."),
    rrd: Path | None = typer.Option(None, "--rrd", help="Write a Rerun recording of the run here.",
                                    show_default=False),
    png: Path | None = typer.Option(None, "--png", help="Write a picture of the run here.", show_default=False),
    vocabulary_file: Path | None = typer.Option(None, "--vocabulary", help="Also call the map's classes by the "
                                                "names this vocabulary file gives them (the map's classes only).",
                                                show_default=False),
    clock: str | None = typer.Option(None, "--clock", help="What the robot's clock reads at the start (HH:MM, or "
                                     "YYYY-MM-DDTHH:MM); it tells the time from it. Default: the computer's clock.",
                                     show_default=False),
    framelib: list[Path] | None = FramelibOption,
    as_json: bool = JsonOption,
) -> None:
    """Simulate a robot that searches for what the command needs, goes there and does it, narrating each step."""
    import numpy as np

    from seal_cli.frames.reading import load_library
    from seal_cli.maps.formats.map_server import load_map
    from seal_cli.pipeline import run_on_map
    from seal_cli.resources import map_path
    from seal_cli.sim.agent import Budget
    from seal_cli.sim.policies import make_policy

    unread_by_policies("--policy", [policy], given)
    held = one_held(holding)
    start_clock = read_clock(clock)
    library = load_library(framelib_paths(framelib))
    the_map = load_map(map_path(map_name))
    for warning in the_map.warnings:  # odd but usable (a place in no room): said, not refused
        err.print(f"warning: {warning}", markup=False)
    vocabulary = None
    if vocabulary_file is not None:
        from seal_cli.language.grounding import load_vocabulary

        vocabulary = load_vocabulary(vocabulary_file)
    from seal_cli.cli import OUTPUT_SUFFIXES
    from seal_cli.fileio import Outputs

    searcher = make_policy(policy, particles)
    if getattr(searcher, "drives_itself", False):  # saycan: from the text alone, no frames to draw or record
        from seal_cli.errors import SealError
        from seal_cli.sim.skills import run_text_on_map

        if rrd is not None or png is not None or done:
            raise SealError(f"--policy {policy}: --rrd, --png and --done need seal's frames; this policy has none")
        skills = run_text_on_map(the_map, text, library, searcher, rng=np.random.default_rng(seed), holding=held,
                                 budget=Budget(steps=max_steps, metres=max_metres),
                                 observers=[] if as_json else [_narrate])
        if as_json:
            emit_json({"map": the_map.name, "text": text, "policy": policy, "seed": seed,
                       "completed": skills.completed, "reason": skills.reason, "path_m": round(skills.path_m, 3),
                       "steps": skills.steps, "skills": skills.history,
                       "proposed_unafforded": skills.proposed_unafforded, "never_seen": skills.never_seen})
        elif skills.completed:
            out.print(f"said done — {skills.path_m:.2f} m driven, {skills.steps} steps")
        if not skills.completed:   # exit 1, and why on stderr (SPEC, "Exit codes")
            why = skills.reason if skills.reason.startswith("not done") else f"not done: {skills.reason}"
            err.print(f"{plain(why)} — {skills.path_m:.2f} m driven, {skills.steps} steps", markup=False)
            raise typer.Exit(1)
        return
    searcher.keep_clouds = rrd is not None or png is not None
    with Outputs({"--rrd": rrd, "--png": png}, [map_name, vocabulary_file, *(framelib or [])],
                 suffixes=OUTPUT_SUFFIXES) as outputs:
        agent, result = run_on_map(the_map, text, library, searcher, rng=np.random.default_rng(seed),
                                   holding=held, done=done or (), vocabulary=vocabulary,
                                   budget=Budget(steps=max_steps, metres=max_metres),
                                   observers=[] if as_json else [_narrate], clock=start_clock,
                                   search_end=search_end)
        if rrd is not None:
            from seal_cli.sim.record import write_rrd

            write_rrd(outputs["--rrd"], agent)
        if png is not None:
            from seal_cli.sim.record import write_png

            ended = "done" if result.completed else result.reason.split(":")[0]     # "no sandwich found"
            write_png(outputs["--png"], agent, f"{the_map.said}: {text} ({ended}, {result.path_m:.1f} m)")
    if as_json:
        emit_json({"map": the_map.name, "text": text, "policy": policy, "seed": seed,
                   "completed": result.completed, "reason": result.reason, "path_m": round(result.path_m, 3),
                   "steps": result.steps, "plan": result.plan, "executed": result.executed,
                   "answer": result.answer, "warnings": result.warnings, "why": result.why.value,
                   "records": [{"kind": r.kind, "text": r.text, "step": r.step, "path_m": round(r.path_m, 3),
                                "pose": [round(v, 3) for v in r.pose], **({"detail": True} if r.data.get("detail")
                                                                          else {})} for r in result.records]})
    else:
        if result.answer:
            out.print(f"[bold]answer:[/bold] {plain(result.answer)}", markup=True)
        if result.completed:
            out.print(f"[bold green]done[/bold green] — {result.path_m:.2f} m driven, {result.steps} steps")
    if not result.completed:   # the job could not be done: exit 1, and why on stderr (SPEC, "Exit codes")
        err.print(f"[bold red]not done[/bold red]: {plain(result.reason)} — {result.path_m:.2f} m driven, "
                  f"{result.steps} steps", markup=True)
        if written := not_done_outputs(png, rrd):
            err.print(written, markup=False)
        raise typer.Exit(1)


def not_done_outputs(png: Path | None, rrd: Path | None) -> str:
    """What a run that ended not done says of its ``--png`` and ``--rrd`` (empty without them). They are written,
    whole, all the same: the picture of where the robot searched is what tells why it failed, and exit code 1 says
    the task was not done, not that the run broke off (a run that breaks off, or is refused, writes neither). Said,
    so that a script reading the exit code does not take them for a success's (hostile25)."""
    what = [f"its picture {png}" if png is not None else "", f"its recording {rrd}" if rrd is not None else ""]
    said = " and ".join(w for w in what if w)
    return plain(f"written all the same, to show where the robot searched: {said}") if said else ""


@command("tasks", on=bench_app)
def tasks(
    suite: str = typer.Option("alfred2d", "--suite", help="alfred2d: ALFRED-2D's episodes; map: commands on "
                              "one seal map over layouts drawn from its priors; context: commands needing two "
                              "things with overlapping priors, the cases where frame context changes the best "
                              "first look (chosen from priors and map alone); context_all: every such command "
                              "from every start of the three houses; context_held_out: the cases the same "
                              "criterion chose on two houses drawn from a seed, held out."),
    data: Path | None = typer.Option(None, "--data", help="The ALFRED-2D folder (default: ../shared/data/alfred2d "
                                     "beside the project); with --suite context or context_all the shared data "
                                     "folder (default ../shared/data), for the AWS house's map.", show_default=False),
    split: str = typer.Option("valid_seen", "--split", help="Which split's episodes to run (priors always come "
                              "from train)."),
    goal: str = typer.Option("gold", "--goal", help="gold: ALFRED's task labels; human: the first human goal "
                             "sentence, parsed."),
    limit: int | None = typer.Option(None, "--limit", min=1, help="At most this many episodes per task type.",
                                     show_default=False),
    sample: int | None = typer.Option(None, "--sample", min=1, help="A stratified sample: this many episodes "
                                      "per task type, the same whatever --seed (instead of the first --limit).",
                                      show_default=False),
    types: list[str] | None = typer.Option(None, "--type", help="Only this task type (repeatable).",
                                           show_default=False),
    map_name: str = typer.Option("apartment", "--map", help="With --suite map: the map (a path or a shipped "
                                 "map's name)."),
    commands: list[str] | None = typer.Option(None, "--command", help="With --suite map: a command to run "
                                              "(repeatable; default: five household commands).",
                                              show_default=False),
    layouts: int | None = typer.Option(None, "--layouts", min=1, max=MAX_COUNT,
                                       help="With --suite map, context or context_all: object "
                                       "layouts drawn from the priors (default 10 for map, 3 for context).",
                                       show_default=False),
    house_set: str = typer.Option("suite", "--houses", help="With --suite context_all: suite (the three houses the "
                                  "policies were developed on) or unseen (four held-out houses)."),
    starts: int | None = typer.Option(None, "--starts", min=1, max=MAX_COUNT, help="With --suite context_all: this "
                                      "many starts per house drawn with --seed from its rooms' free space "
                                      "(default: each house's own three).", show_default=False),
    fov: float | None = typer.Option(None, "--fov", help="With --suite context or context_all: every house's "
                                     "sensor sees this many degrees, in [1, 360] (default: each house's own, 360).",
                                     show_default=False),
    policies: str = typer.Option(",".join(DEFAULT_POLICIES), "--policies",
                                 help="Comma-separated policies, of: " + ", ".join(POLICIES) + "."),
    jobs: int = typer.Option(0, "--jobs", min=0, max=64, help="Worker processes (0: one per core)."),
    backend: str = typer.Option("process", "--backend", help="With --suite alfred2d: process (this machine's "
                                "pool) or ray (Ray's pool, the ray extra; a cluster via RAY_ADDRESS)."),
    seed: int = typer.Option(0, "--seed", min=0, help="Seed; each episode's generator is derived from it."),
    particles: int = typer.Option(200, "--particles", min=1, max=MAX_PARTICLES,
                                   help="Particles per object and per frame."),
    episodes: Path | None = typer.Option(None, "--episodes", help="Also write every outcome here as JSON Lines.",
                                         show_default=False),
    framelib: list[Path] | None = FramelibOption,
    as_json: bool = JsonOption,
) -> None:
    """Run every policy on the same episodes: success and path length per task type (ALFRED-2D) or
    per command (a seal map over layouts drawn from its priors)."""
    import json

    from rich.progress import BarColumn, MofNCompleteColumn, Progress, TextColumn, TimeElapsedColumn

    from seal_cli.bench.tasks import Outcome, run_suite, summarise
    from seal_cli.errors import SealError
    from seal_cli.maps.model import FOV_RANGE, fov_ok

    if suite not in SUITES:
        raise SealError(f"unknown suite {suite!r}; the suites are {', '.join(SUITES)}")
    if limit is not None and sample is not None:      # the arguments first: they need no file
        raise SealError("give --limit (the first episodes of each task type) or --sample (a stratified sample), "
                        "not both")
    names = choices("--policies", [policies], tuple(POLICIES), "policy")
    if backend not in ("process", "ray") or (backend == "ray" and suite != "alfred2d"):
        raise SealError(f"--backend {backend!r}: process, or ray with --suite alfred2d")
    _unread_options(suite, given)
    unread_by_policies("--policies", names, given)
    if fov is not None and not fov_ok(fov):      # NaN too
        raise SealError(f"--fov {fov:g}: {FOV_RANGE}")
    if suite == "context_all":
        from seal_cli.bench.context import HOUSE_SETS

        if house_set not in HOUSE_SETS:
            raise SealError(f"--houses {house_set!r}: one of {', '.join(HOUSE_SETS)}")
    shared = Path(__file__).resolve().parents[2].parent / "shared" / "data"
    if data is None:
        data = shared if suite in CONTEXT_SUITES else shared / "alfred2d"
        if suite not in ("map", "context_held_out") and not data.is_dir():
            raise SealError(f"the {suite} suite's data is not at {data}, the default beside a checkout of seal (an "
                            "installed seal has no data): give --data DIR")
    from seal_cli.bench import alfred2d
    from seal_cli.cli import OUTPUT_SUFFIXES
    from seal_cli.fileio import Outputs
    from seal_cli.resources import map_path

    the_map = map_path(map_name) if suite == "map" else None  # an input too: --episodes must not replace it
    read = alfred2d.data_files(data) if suite == "alfred2d" else []   # and the data's files (their folder is no file)
    outputs = Outputs({"--episodes": episodes}, [data, the_map, *read, *(framelib or [])], suffixes=OUTPUT_SUFFIXES)
    outcomes: list[Outcome] = []
    with Progress(TextColumn("episodes"), BarColumn(), MofNCompleteColumn(), TimeElapsedColumn(), console=err.console,
                  transient=True, disable=not err.is_terminal) as progress:
        bar = progress.add_task("episodes", total=None)

        def advance(done: int, total: int) -> None:
            progress.update(bar, completed=done, total=total)

        libs = [str(p) for p in framelib_paths(framelib) or []] or None
        if suite == "map":
            from seal_cli.bench.mapsuite import COMMANDS, run_map_suite

            layouts = layouts or 10
            runs = run_map_suite(str(the_map), list(commands or COMMANDS), names, layouts=layouts,
                                 seed=seed, jobs=jobs or os.cpu_count() or 1, particles=particles, framelib=libs,
                                 progress=advance)
        elif suite in CONTEXT_SUITES:
            from seal_cli.bench import context

            layouts = layouts or 3
            on = context.selected_houses(data, commands or None) if suite == "context" else \
                context.selected_houses(data, commands or None, context.HELD_OUT_CASES_FILE,
                                        context.held_out_houses()) if suite == "context_held_out" else \
                context.house_set(house_set, data)
            runs = context.run_context_suite(data, names, commands=list(commands or context.COMMANDS),
                                             layouts=layouts, seed=seed, jobs=jobs or os.cpu_count() or 1,
                                             particles=particles, framelib=libs, progress=advance,
                                             on=context.with_fov(on, fov), starts=starts)
        else:
            runs = run_suite(data, split, names, goal=goal, limit=limit, types=types, seed=seed,
                             jobs=jobs or os.cpu_count() or 1, particles=particles, framelib=libs,
                             progress=advance, backend=backend, sample=sample)
        outcomes.extend(runs)
    with outputs:  # a failure above leaves no temporary: they are removed at exit
        if episodes is not None:
            outputs["--episodes"].write_text("".join(json.dumps(o.to_json()) + "\n" for o in outcomes),
                                             encoding="utf-8")
    report = summarise(outcomes, names)
    if suite == "map":
        report.update({"suite": suite, "map": map_name, "layouts": layouts, "seed": seed})
    elif suite in CONTEXT_SUITES:
        from seal_cli.bench.context import paired, regroup

        which = {"context_all": house_set, "context": "selected"}.get(suite, "held_out")
        report.update({"suite": suite, "houses": which,
                       "starts": starts or ("the houses' own" if suite == "context_all" else "the cases' own"),
                       "fov": fov, "layouts": layouts, "seed": seed, "by_command": regroup(outcomes, names, 1),
                       "by_house": regroup(outcomes, names, 0), "against_prior_optimal": paired(outcomes, names)})
    else:
        report.update({"suite": suite, "split": split, "goal": goal, "seed": seed, "limit": limit, "sample": sample})
    from seal_cli.bench.perf import peak_rss_mb

    report["peak_rss_mb"] = round(peak_rss_mb(children=True), 1)  # the largest process: this one or a worker
    if as_json:
        emit_json(report)
    else:
        _table(report, names)
        err.print(f"[dim]peak memory: {report['peak_rss_mb']:,.0f} MB (the largest process running episodes)[/dim]")


def _table(report: dict[str, Any], names: list[str]) -> None:
    from rich.table import Table

    if report["suite"] == "map":
        title = f"map {plain(report['map'])}, {report['layouts']} layouts: success rate / mean path (m)"
    elif report["suite"] in CONTEXT_SUITES:
        title = (f"{report['suite']} suite ({report['houses']} houses), {report['layouts']} layouts: success rate / "
                 "mean path (m)")
    else:
        title = f"ALFRED-2D {plain(report['split'])}, goals from {report['goal']}: success rate / mean path (m)"
    table = Table(title=title)
    table.add_column("task type" if report["suite"] == "alfred2d" else "command", no_wrap=True)
    table.add_column("n", justify="right", no_wrap=True)
    for name in names:
        table.add_column(name, justify="right", no_wrap=True)
    expert_column = report["suite"] == "alfred2d"
    if expert_column:
        table.add_column("expert m", justify="right", no_wrap=True)
    for group, figures in report["groups"].items():
        cells = []
        for name in names:
            s, p = figures["success"][name], figures["path_m"][name]
            cells.append(f"{s:.2f} / {p:.2f}" if s is not None and p is not None else "—")
        if expert_column:
            expert = figures.get("expert_path_m")
            cells.append(f"{expert:.2f}" if expert is not None else "—")
        table.add_row(f"[bold]{group}[/bold]" if group == "all" else plain(group), str(figures["n"]), *cells)
    wide = 40 + 16 * len(names)
    if out.width >= wide:
        out.print(table)
    else:
        from rich.console import Console

        Console(width=wide, highlight=False, emoji=False).print(table)


@command("e2e", on=bench_app)
def e2e(
    map_name: str | None = typer.Option(None, "--map", help="Only this map's cases (apartment, aws, townhouse, ...).",
                                        show_default=False),
    limit: int | None = typer.Option(None, "--limit", min=1, help="At most this many cases per map.",
                                     show_default=False),
    file: Path | None = typer.Option(None, "--file", help="Cases from this YAML file instead of the shipped "
                                     "suite.", show_default=False),
    data: Path | None = typer.Option(None, "--data", help="The shared data folder (default: ../shared/data "
                                     "beside the project).", show_default=False),
    jobs: int = typer.Option(0, "--jobs", min=0, max=64, help="Worker processes (0: one per core)."),
    seed: int = typer.Option(0, "--seed", min=0, help="Seed of each run's generator."),
    particles: int = typer.Option(100, "--particles", min=1, max=MAX_PARTICLES,
                                  help="Particles per object and per frame."),
    framelib: list[Path] | None = FramelibOption,
    as_json: bool = JsonOption,
) -> None:
    """Plain commands on the shipped maps and the AWS house: how many ground to the expected plan, how many
    runs end as they must."""
    from rich.table import Table

    from seal_cli.bench.e2e import load_cases, run_cases, summarise
    from seal_cli.errors import SealError

    cases = load_cases(file)
    names = list(dict.fromkeys(c.map for c in cases))
    if map_name is not None and map_name not in names:
        raise SealError(f"unknown map {map_name!r} for --map; the suite's maps are {', '.join(names)}")
    cases = [c for c in cases if map_name is None or c.map == map_name]
    if limit is not None:
        by_map: dict[str, list[Any]] = {}
        for case in cases:
            by_map.setdefault(case.map, []).append(case)
        cases = [c for c in cases if by_map[c.map].index(c) < limit]
    if data is None:
        data = Path(__file__).resolve().parents[2].parent / "shared" / "data"
    libs = [str(p) for p in framelib_paths(framelib) or []] or None
    verdicts = run_cases(cases, data, seed=seed, particles=particles, jobs=jobs or os.cpu_count() or 1,
                         framelib=libs)
    report = summarise(verdicts)
    report.update({"seed": seed, "particles": particles})
    if as_json:
        emit_json(report)
        return
    table = Table(title="end-to-end commands: plan right / run ended as it must")
    for column in ("map", "n", "plan right", "runs", "run completed"):
        table.add_column(column, justify="left" if column == "map" else "right")
    for name, g in report["groups"].items():
        plan_rate = f"{g['plan_right']}/{g['n']} ({g['plan_rate']:.3f})" if g["n"] else "—"
        run_rate = f"{g['run_completed']}/{g['runs']} ({g['run_rate']:.3f})" if g["runs"] else "—"
        table.add_row(f"[bold]{name}[/bold]" if name == "all" else plain(name), str(g["n"]), plan_rate, str(g["runs"]),
                      run_rate)
    out.print(table)
    for miss in report["misses"]:
        what = "plan" if not miss["plan_right"] else "run"
        detail = miss["got"] if what == "plan" else miss["run_reason"]
        out.print(f"[red]{what} miss[/red] {plain(miss['map'])}: {plain(repr(miss['text']))} → {plain(detail)}",
                  highlight=False)
