"""The context suite: commands whose frames need two or more things with overlapping priors.

This is where the paper's claim should show: "Stir Mug is more likely to be in a room that has
both spoons and mugs". Each command needs two things the robot must find, and the two classes'
priors share a room (spoons and cups both in the bedroom; spoons and mugs both in the kitchen;
mugs and kettles both in the dining room), so a searcher that thinks about the whole plan can look
where both may be, and one that looks for one thing at a time cannot.

Houses (:func:`houses`): the shipped apartment (its own cup and spoon priors, and mugs and
kettles added in code), the AWS RoboMaker small house's real occupancy map (the "wings" reading
of :data:`~seal_cli.bench.houses.AWS_LAYOUTS`, with furniture and priors from
:mod:`seal_cli.bench.houses`), and :func:`~seal_cli.bench.houses.cottage`, drawn for this suite.
Each has several start poses. For each layout, every thing is drawn from its class's prior
(:func:`~seal_cli.bench.mapsuite.sample_layout`); every command runs from every start with every
policy on a fresh world of that layout, with the same generator seed for every policy.

Groups are ``house · command · start``; ``all`` is everything; the JSON also has ``by_command``
and ``by_house`` (the same figures folded another way).

Which cases (:func:`selected_houses`): ``seal bench tasks --suite context`` runs the cases that fit the issue's
definition by :mod:`~seal_cli.bench.headroom`'s criterion (frame context changes the best first look, by at least
:data:`~seal_cli.bench.headroom.FITS_SHARE` of the expected path), chosen from priors and map alone among many drawn
starts and commands and written with their criterion values to :data:`CASES_FILE` before any policy ran on them;
a case's start keeps its number among the drawn starts. ``--suite context_all`` runs every command from every one of
the houses' own starts (:func:`houses`: the suite as it was before search26, 36 cases).
"""

from __future__ import annotations

import dataclasses
import json
import os
import tempfile
import time
import zlib
from collections.abc import Callable, Iterator, Sequence
from pathlib import Path
from typing import Any

import numpy as np

from seal_cli.bench.houses import (
    AWS_CONTEXT_PLACES,
    AWS_CONTEXT_STARTS,
    BUNGALOW_STARTS,
    CONTEXT_OBJECTS,
    CONTEXT_PRIORS,
    COTTAGE_STARTS,
    FARMHOUSE_STARTS,
    GALLERY_STARTS,
    HELD_OUT_SEEDS,
    LONGHOUSE_STARTS,
    MEWS_STARTS,
    RANCH_STARTS,
    TERRACE_STARTS,
    aws_house,
    bungalow,
    cottage,
    drawn_house,
    gallery,
    longhouse,
    mews,
    ranch,
)
from seal_cli.bench.mapsuite import sample_layout
from seal_cli.bench.tasks import Outcome, in_order, summarise
from seal_cli.errors import SealError
from seal_cli.frames.library import Library
from seal_cli.frames.reading import load_library
from seal_cli.maps.formats.map_server import load_map
from seal_cli.maps.model import Map, ObjectTruth, Robot

__all__ = ["CASES_FILE", "COMMANDS", "HELD_OUT_CASES_FILE", "HOUSE_SETS", "START_CLEARANCE", "House",
           "candidate_houses", "drawn_starts", "held_out_houses", "house_set", "houses",
           "paired", "regroup", "run_context_suite", "selected_houses", "unseen_houses", "with_fov"]

COMMANDS = ("stir the cup", "put the spoon in the cup", "stir the mug", "pour the kettle into the mug")
"""Spoon and cup (both likely in the bedroom), twice with different frames; spoon and mug (the
kitchen); kettle and mug (the dining room)."""

APARTMENT_STARTS = ((-6.0, -3.0, 0.0), (0.0, -3.0, 0.0), (6.0, 4.5, 0.0))
"""The apartment's own start (the living room's west end), the living room by the kitchen door, the dining room."""


@dataclasses.dataclass(frozen=True)
class House:
    """A map and the robot's start poses on it."""

    map: Map
    starts: tuple[tuple[float, float, float], ...]
    commands: tuple[tuple[str, ...], ...] | None = None
    """Per start, the commands run from it (None: every command the suite is given, from every start)."""
    labels: tuple[int, ...] | None = None
    """Per start, its number in the groups' names (None: 1, 2, ... in order)."""


def houses(data: Path) -> list[House]:
    """The suite's three houses (``data``: the shared data folder, for the AWS house's image)."""
    from seal_cli.resources import map_path

    apartment = load_map(map_path("apartment"))
    extra = {c: m for c, m in CONTEXT_PRIORS.items() if c not in apartment.priors}
    have = {o.cls for o in apartment.objects}
    apartment = dataclasses.replace(
        apartment, priors={**apartment.priors, **extra},
        objects=apartment.objects + tuple(ObjectTruth(str(o["class"]), (0.0, 0.0)) for o in CONTEXT_OBJECTS
                                          if o["class"] not in have))
    image = data / "maps" / "aws_small_house" / "map.pgm"
    if not image.is_file():
        raise SealError(f"{image}: the AWS small house's map is not there (--data names the shared data folder)")
    with tempfile.TemporaryDirectory() as folder:
        aws = load_map(aws_house(Path(folder), data, "wings", AWS_CONTEXT_STARTS[0], priors=CONTEXT_PRIORS,
                                 objects=CONTEXT_OBJECTS, places=AWS_CONTEXT_PLACES, name="aws_small_house"))
    return [House(apartment, APARTMENT_STARTS), House(aws, AWS_CONTEXT_STARTS), House(cottage(), COTTAGE_STARTS)]


def candidate_houses(data: Path) -> list[House]:
    """The houses the context suite's cases are chosen on: :func:`houses`' three and
    :func:`~seal_cli.bench.houses.mews`, drawn by search26 when the three gave few cases that fit."""
    return [*houses(data), House(mews(), MEWS_STARTS)]


def unseen_houses() -> list[House]:
    """Houses the suite's policies were not developed on, to check that its figures hold
    (:func:`~seal_cli.bench.houses.bungalow`, drawn after the suite's figures were taken, the shipped
    ``farmhouse`` and ``terrace`` maps, drawn later still, and :func:`~seal_cli.bench.houses.ranch`, drawn
    for search13's held-out check, :func:`~seal_cli.bench.houses.longhouse`, drawn for search16's, and
    :func:`~seal_cli.bench.houses.gallery`, drawn for search21's; nothing tuned on them)."""
    from seal_cli.resources import map_path

    return [House(bungalow(), BUNGALOW_STARTS), House(load_map(map_path("farmhouse")), FARMHOUSE_STARTS),
            House(load_map(map_path("terrace")), TERRACE_STARTS), House(ranch(), RANCH_STARTS),
            House(longhouse(), LONGHOUSE_STARTS), House(gallery(), GALLERY_STARTS)]


def held_out_houses() -> list[House]:
    """Houses no policy was developed or measured on, drawn by search27 from
    :data:`~seal_cli.bench.houses.HELD_OUT_SEEDS` alone (:func:`~seal_cli.bench.houses.drawn_house`: no one chose
    their plans); their cases are chosen by the same criterion as the suite's (``--suite context_held_out``).
    No starts of their own: the cases' starts are drawn."""
    return [House(drawn_house(seed), ()) for seed in HELD_OUT_SEEDS]


CASES_FILE = Path(__file__).parent / "suites" / "context_cases.json"
"""The context suite's cases, with the values of the criterion that chose them (``scripts/context_cases.py``)."""

HELD_OUT_CASES_FILE = Path(__file__).parent / "suites" / "context_held_out_cases.json"
"""The held-out houses' cases (:func:`held_out_houses`), chosen by the same criterion
(``scripts/context_cases.py --held-out``)."""


def selected_houses(data: Path, commands: Sequence[str] | None = None, cases_file: Path = CASES_FILE,
                    among: Sequence[House] | None = None) -> list[House]:
    """The context suite's selected cases (:data:`CASES_FILE`) as houses: each house with the starts a case was
    chosen from (numbered as drawn) and, per start, the commands chosen from it; ``commands``: only these
    commands' cases (refused when none is one). The houses are ``among``'s maps (default :func:`candidate_houses`'),
    in their order."""
    try:
        cases = json.loads(cases_file.read_text(encoding="utf-8"))["cases"]
    except (OSError, ValueError, KeyError, TypeError) as error:
        raise SealError(f"{cases_file}: the context suite's cases cannot be read ({error})") from None
    if commands is not None:
        unknown = [c for c in commands if c not in {case["command"] for case in cases}]
        if unknown:
            raise SealError(f"--command {unknown[0]!r}: no case of the context suite has it; its commands are "
                            + ", ".join(sorted({case["command"] for case in cases})))
        cases = [case for case in cases if case["command"] in commands]
    built = []
    for house in (candidate_houses(data) if among is None else among):
        mine = [case for case in cases if case["house"] == house.map.name]
        labels = sorted({int(case["start"]) for case in mine})
        if not labels:
            continue
        poses = tuple(next((float(case["pose"][0]), float(case["pose"][1]), float(case["pose"][2]))
                           for case in mine if case["start"] == k) for k in labels)
        said = tuple(tuple(case["command"] for case in mine if case["start"] == k) for k in labels)
        built.append(House(house.map, poses, said, tuple(labels)))
    return built


HOUSE_SETS = ("suite", "unseen")
"""``suite``: the three houses the policies were developed on (:func:`houses`); ``unseen``: the held-out
ones (:func:`unseen_houses`)."""


def house_set(name: str, data: Path) -> list[House]:
    """One of :data:`HOUSE_SETS` by name."""
    if name not in HOUSE_SETS:
        raise SealError(f"--houses {name!r}: one of {', '.join(HOUSE_SETS)}")
    return houses(data) if name == "suite" else unseen_houses()


def with_fov(built: Sequence[House], fov: float | None) -> list[House]:
    """The houses with every map's sensor seeing ``fov`` degrees (None: as drawn); refused outside
    :data:`~seal_cli.maps.model.FOV_RANGE`."""
    from seal_cli.maps.model import FOV_RANGE, fov_ok

    if fov is None:
        return list(built)
    if not fov_ok(fov):
        raise SealError(f"--fov {fov:g}: {FOV_RANGE}")
    return [dataclasses.replace(h, map=dataclasses.replace(h.map, sensor=dataclasses.replace(h.map.sensor,
                                                                                           fov_deg=float(fov))))
            for h in built]


START_CLEARANCE = 0.5
"""Metres from the nearest wall or piece of furniture a drawn start keeps (:func:`drawn_starts`)."""


def drawn_starts(m: Map, n: int, seed: int) -> tuple[tuple[float, float, float], ...]:
    """``n`` start poses drawn uniformly over the free space of ``m``'s rooms that is :data:`START_CLEARANCE`
    from anything occupied and joined to the largest such stretch (so every start reaches every other), with a
    generator from ``seed`` and the house's name: starts no one chose, the same for every policy and run."""
    from scipy.ndimage import distance_transform_edt, label

    grid = m.grid
    free = np.asarray(grid.free_mask, dtype=bool)
    clear = distance_transform_edt(free) * grid.resolution >= START_CLEARANCE
    parts, count = label(clear)
    if count == 0:
        raise SealError(f"map {m.name} has no free space {START_CLEARANCE} m from its walls to start from")
    sizes = np.bincount(parts.ravel())[1:]
    main = parts == int(np.argmax(sizes)) + 1
    centres = m.free_centres
    rows, cols, _ = grid.cell_index(centres)
    ok = np.flatnonzero(main[rows, cols] & (m.free_cell_room >= 0))
    if not len(ok):
        raise SealError(f"map {m.name}'s rooms have no free space {START_CLEARANCE} m from its walls to start from")
    rng = np.random.default_rng((seed * 1_000_003 + 104_729 + zlib.crc32(m.name.encode())) % (2 ** 32))
    picked = centres[rng.choice(ok, size=n, replace=len(ok) < n)]
    return tuple((round(float(x), 2), round(float(y), 2), 0.0) for x, y in picked)


def layout_seed(seed: int, layout: int, name: str) -> int:
    """The generator seed of one layout of one house, the same whatever process draws it."""
    return (seed * 1_000_003 + layout * 7_919 + zlib.crc32(name.encode())) % (2 ** 32)


def run_house_layout(house: House, layout: int, commands: Sequence[str], library: Library,
                     policies: Sequence[str], *, seed: int = 0, particles: int = 200) -> list[Outcome]:
    """Every command from every start with every policy on one layout of one house."""
    from seal_cli.bench.mapsuite import commanded_frames, run_judged

    m = house.map
    base = layout_seed(seed, layout, m.name)
    world = sample_layout(m, np.random.default_rng(base))
    outcomes = []
    for s, pose in enumerate(house.starts):
        start = dataclasses.replace(world, robot=Robot(pose))
        label = house.labels[s] if house.labels is not None else s + 1
        for c, text in enumerate(house.commands[s] if house.commands is not None else commands):
            group = f"{m.name} · {text} · start {label}"
            asked = commanded_frames(start, text, library)
            for name in policies:   # judged by the end state, as the map suite (saycan too)
                began = time.perf_counter()
                rng = np.random.default_rng(base + 1 + 97 * s + c)
                ok, path, steps, reason, plan = run_judged(start, text, library, name, rng=rng, particles=particles,
                                                           asked=asked)
                outcomes.append(Outcome(f"{m.name}-layout{layout}-start{label}-{c}", group, name, ok, round(path, 3),
                                        steps, reason, float("nan"), round(time.perf_counter() - began, 3), plan))
    return outcomes


_WORKER: dict[str, Any] = {}


def _work(args: tuple[int, int, tuple[str, ...], tuple[str, ...], int, int]) -> tuple[int, list[Outcome]]:
    index, layout, commands, policies, seed, particles = args
    house = _WORKER["houses"][index % len(_WORKER["houses"])]
    return index, run_house_layout(house, layout, commands, _WORKER["library"], policies, seed=seed,
                                   particles=particles)


def run_context_suite(data: Path, policies: Sequence[str], *, commands: Sequence[str] = COMMANDS,
                      layouts: int = 3, seed: int = 0, jobs: int | None = None, particles: int = 200,
                      framelib: Sequence[str] | None = None,
                      progress: Callable[[int, int], None] | None = None,
                      on: Sequence[House] | None = None, starts: int | None = None) -> Iterator[Outcome]:
    """Run the policies on the commands on every house, start and layout; yields the outcomes in
    (layout, house) order. Every command is checked (parsed and planned) on every house first.
    ``on``: these houses instead of the suite's (:func:`unseen_houses`); ``starts``: this many starts per
    house drawn with ``seed`` (:func:`drawn_starts`) instead of the house's own."""
    from seal_cli.language.grounding import vocabulary_of_map
    from seal_cli.pipeline import plan as plan_text

    library = load_library(framelib)
    built = list(on) if on is not None else houses(Path(data))
    if starts is not None:
        built = [House(h.map, drawn_starts(h.map, starts, seed)) for h in built]
    for house in built:
        for text in sorted({t for said in house.commands for t in said} if house.commands is not None else commands):
            plan_text(text, library, vocabulary=vocabulary_of_map(house.map))
    work = [(layout * len(built) + h, layout, tuple(commands), tuple(policies), seed, particles)
            for layout in range(layouts) for h in range(len(built))]
    _WORKER.update(houses=built, library=library)
    jobs = max(1, min(jobs or os.cpu_count() or 1, len(work) or 1))
    import multiprocessing

    if jobs == 1 or "fork" not in multiprocessing.get_all_start_methods():
        yield from in_order(map(_work, work), len(work), progress)
        return
    from seal_cli.bench.workers import unordered

    yield from in_order(unordered(_work, work, jobs, method="fork"), len(work), progress)  # they inherit the houses


def regroup(outcomes: Sequence[Outcome], policies: Sequence[str], part: int) -> dict[str, Any]:
    """The figures by one part of the group name (0: house, 1: command)."""
    return summarise([dataclasses.replace(o, group=o.group.split(" · ")[part]) for o in outcomes], policies)["groups"]


def paired(outcomes: Sequence[Outcome], policies: Sequence[str], reference: str = "prior_optimal",
           part: int = 1) -> dict[str, dict[str, dict[str, float]]]:
    """Each policy's path minus the reference's on the same episode, folded by one part of the group
    name (0: house, 1: command; ``all`` too): ``{group: {policy: {"n", "mean_m", "se_m"}}}``, over the
    episodes both completed. A policy without full knowledge whose mean is below the reference's by
    more than about two standard errors beats the prior optimum: a bug in one of them."""
    if reference not in policies:
        return {}
    ref = {o.task_id: o for o in outcomes if o.policy == reference}
    diffs: dict[str, dict[str, list[float]]] = {}
    for o in outcomes:
        r = ref.get(o.task_id)
        if o.policy == reference or r is None or not (o.success and r.success):
            continue
        for group in (o.group.split(" · ")[part], "all"):
            diffs.setdefault(group, {}).setdefault(o.policy, []).append(o.path_m - r.path_m)
    out: dict[str, dict[str, dict[str, float]]] = {}
    for group, by_policy in sorted(diffs.items()):
        for name, d in by_policy.items():
            a = np.asarray(d, dtype=float)
            se = float(a.std(ddof=1) / np.sqrt(len(a))) if len(a) > 1 else float("nan")
            out.setdefault(group, {})[name] = {"n": len(a), "mean_m": round(float(a.mean()), 3),
                                               "se_m": round(se, 3)}
    return out
