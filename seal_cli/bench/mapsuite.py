"""The map suite: every policy on commands on one seal map, over layouts drawn from its priors.

ALFRED-2D's rooms are single and open; a building has walls, and there a search that knows which
room to try first matters most. This suite runs on any seal map (the shipped apartment by
default): for each layout, every ground-truth object of the map is moved to a point drawn from
its class's prior (:func:`sample_layout`), so the placements are as varied as the priors say
and the priors are right on average — the paper's setting. Each command then runs with every
policy on a fresh world of that layout, from the map's start pose. A run succeeds when the world
at the end is what the command asked for (:func:`seal_cli.bench.endstate.judge_end`: the
commanded frames' effects hold, read from the world), for every policy alike — those that run
seal's plan and ``saycan``, which drives itself from the text.

Outcomes are :class:`~seal_cli.bench.tasks.Outcome` rows grouped by command, and
:func:`~seal_cli.bench.tasks.summarise` folds them into the same JSON as ALFRED-2D's.
"""

from __future__ import annotations

import dataclasses
import os
import time
import zlib
from collections.abc import Callable, Iterator, Sequence
from typing import Any

import numpy as np

from seal_cli.bench.tasks import Outcome, in_order
from seal_cli.errors import SealError, SealErrors
from seal_cli.frames.library import Library
from seal_cli.frames.reading import load_library
from seal_cli.maps.formats.map_server import load_map
from seal_cli.maps.model import Map, ObjectTruth

__all__ = ["COMMANDS", "commanded_frames", "run_judged", "run_map_suite", "sample_layout"]

COMMANDS = ("stir the cup", "bring the apple to the bedroom", "put the spoon in the sink",
            "pick up the cup and put it on the dining table", "heat the apple")
"""The commands run by default (on the apartment: every frame of the library's kitchen and
manipulation sets that needs an object found)."""


def sample_layout(m: Map, rng: np.random.Generator) -> Map:
    """The map with each ground-truth object at a point drawn from its class's prior.

    An object drawn within reach of a place the prior names (by name or class: "apple: {fridge:
    0.4}") is in or on that place — the nearest such — so a closed one hides it; otherwise it
    stands on its own on the free space. Classes without a prior are drawn from the prior's floor
    (uniform over free space)."""
    objects = []
    for obj in m.objects:
        prior = m.prior(obj.cls)
        (x, y), = prior.sample(1, rng)
        named = {k for k in prior.masses if k != "_rest"}
        inside = None
        best = np.inf
        for place in m.places:
            if place.name in named or place.cls in named:
                d = float(np.hypot(place.at[0] - x, place.at[1] - y))
                if d <= place.reach and d < best:
                    inside, best = place.name, d
        objects.append(ObjectTruth(obj.cls, (float(x), float(y)), inside))
    return dataclasses.replace(m, objects=tuple(objects))


def layout_seed(seed: int, layout: int, map_name: str) -> int:
    """The generator seed of one layout, the same whatever process draws it."""
    return (seed * 1_000_003 + layout * 7_919 + zlib.crc32(map_name.encode())) % (2 ** 32)


def run_layout(m: Map, layout: int, commands: Sequence[str], library: Library, policies: Sequence[str], *,
               seed: int = 0, particles: int = 200) -> list[Outcome]:
    """Every command with every policy on one layout of the map."""
    base = layout_seed(seed, layout, m.name)
    world = sample_layout(m, np.random.default_rng(base))
    outcomes = []
    for c, text in enumerate(commands):
        asked = commanded_frames(world, text, library)
        for name in policies:
            start = time.perf_counter()
            rng = np.random.default_rng(base + 1 + c)
            success, path, steps, reason, plan = run_judged(world, text, library, name, rng=rng, particles=particles,
                                                            asked=asked)
            outcomes.append(Outcome(f"{m.name}-layout{layout}-{c}", text, name, success, round(path, 3), steps,
                                    reason, float("nan"), round(time.perf_counter() - start, 3), plan))
    return outcomes


def run_judged(m: Map, text: str, library: Library, name: str, *, rng: np.random.Generator, particles: int = 200,
               asked: tuple[list[Any], dict[str, str]] | None = None) -> tuple[bool, float, int, str, tuple[str, ...]]:
    """One policy on one command on a map whose objects are the world, judged by the end state
    (:func:`~seal_cli.bench.endstate.judge_end`): success, path, steps, reason, and the plan run (the
    skills chosen, for ``saycan``). ``asked``: :func:`commanded_frames` of the command, if known."""
    from seal_cli.bench.endstate import judge_end
    from seal_cli.pipeline import run_on_map
    from seal_cli.sim.agent import Budget, scene_from_map
    from seal_cli.sim.policies import make_policy
    from seal_cli.sim.skills import failure_kinds

    commanded, classes = asked or commanded_frames(m, text, library)
    policy = make_policy(name, particles)
    if getattr(policy, "drives_itself", False):  # saycan: from the text alone
        scene = scene_from_map(m, library)
        said = policy.run(scene, library, text, rng=rng, budget=Budget())  # type: ignore[attr-defined]
        verdict = judge_end(scene.world, m, commanded, classes, said.known)
        kinds = failure_kinds(said, verdict.success)
        reason = "success" if verdict.success else f"{'; '.join(kinds)}: {verdict.reason}"
        return verdict.success, said.path_m, said.steps, reason, tuple(said.history)
    # every thing sought is in the layout (drawn from the priors): the search is measured to the end,
    # as prior_optimal and the oracle assume, not cut off where seal run would give up (--search-end)
    agent, result = run_on_map(m, text, library, policy, rng=rng, search_end=None)
    verdict = judge_end(agent.world, m, commanded, classes, agent.known)
    reason = "success" if verdict.success else (result.reason if not result.completed else verdict.reason)
    return verdict.success, result.path_m, result.steps, reason, tuple(result.plan)


def commanded_frames(m: Map, text: str, library: Library) -> tuple[list[Any], dict[str, str]]:
    """The command's frames as ``seal run`` reads them on the map, and the class of each name
    they use: what the end-state judge holds every policy's world to."""
    from seal_cli.language.grounding import vocabulary_of_map
    from seal_cli.planning.problem import build_problem, parse_to_plan

    vocabulary = vocabulary_of_map(m)
    problem = build_problem(parse_to_plan(text, library, vocabulary), library, map=m.known(),
                            vocabulary=vocabulary)
    return list(problem.commanded), dict(problem.state.classes)


_WORKER: dict[str, Any] = {}


def _init_worker(map_path: str, framelib: Sequence[str] | None) -> None:
    _WORKER["map"] = load_map(map_path)
    _WORKER["library"] = load_library(framelib)


def _work(args: tuple[int, tuple[str, ...], tuple[str, ...], int, int]) -> tuple[int, list[Outcome]]:
    layout, commands, policies, seed, particles = args
    return layout, run_layout(_WORKER["map"], layout, commands, _WORKER["library"], policies, seed=seed,
                              particles=particles)


def run_map_suite(map_path: str, commands: Sequence[str], policies: Sequence[str], *, layouts: int = 10,
                  seed: int = 0, jobs: int | None = None, particles: int = 200,
                  framelib: Sequence[str] | None = None,
                  progress: Callable[[int, int], None] | None = None) -> Iterator[Outcome]:
    """Run the policies on the commands over ``layouts`` layouts, in ``jobs`` processes; yields the
    outcomes in layout order. The map and every command are checked (parsed and planned) first,
    so a bad one is an error before any run."""
    from seal_cli.language.grounding import vocabulary_of_map
    from seal_cli.pipeline import plan as plan_text
    from seal_cli.sim.policies import make_policy

    for name in policies:  # a missing extra (saycan's language model) fails here, before any worker starts
        policy = make_policy(name, 1)
        if getattr(policy, "drives_itself", False):
            getattr(policy, "scorer", None)
    m = load_map(map_path)
    library = load_library(framelib)
    vocabulary = vocabulary_of_map(m)
    for text in commands:     # a command that cannot be parsed or planned fails here, cleanly, naming itself
        try:
            plan_text(text, library, vocabulary=vocabulary)
            commanded_frames(m, text, library)  # grounded on this map, as each layout grounds it
        except SealError as error:
            if isinstance(error, SealErrors):
                raise
            given = "one of the suite's default commands; give the map's own with --command" if text in COMMANDS \
                else "--command"
            raise SealError(f"{error.message} (in {text!r}, {given})", error.where,
                            source_line=error.source_line, hint=error.hint) from None
    work = [(i, tuple(commands), tuple(policies), seed, particles) for i in range(layouts)]
    jobs = max(1, min(jobs or os.cpu_count() or 1, layouts or 1))
    if jobs == 1:
        _WORKER.update(map=m, library=library)
        yield from in_order(map(_work, work), layouts, progress)
        return
    from seal_cli.bench.workers import unordered

    yield from in_order(unordered(_work, work, jobs, initializer=_init_worker, initargs=(map_path, framelib)),
                        layouts, progress)
