"""The map suite: every policy on commands on one seal map, over layouts drawn from its priors.

ALFRED-2D's rooms are single and open; a building has walls, and there a search that knows which
room to try first matters most. This suite runs on any seal map (the shipped apartment by
default): for each layout, every ground-truth object of the map is moved to a point drawn from
its class's prior (:func:`sample_layout`), so the placements are as varied as the priors say
and the priors are right on average — the paper's setting. Each command then runs with every
policy on a fresh world of that layout, from the map's start pose. A run succeeds when every frame
of its plan was executed: the simulator refuses any action whose physical preconditions do not
hold, so a completed plan is a done task.

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
from seal_cli.errors import SealError
from seal_cli.frames.library import Library
from seal_cli.frames.reading import load_library
from seal_cli.maps.formats.map_server import load_map
from seal_cli.maps.model import Map, ObjectTruth

__all__ = ["COMMANDS", "run_map_suite", "sample_layout"]

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
    from seal_cli.pipeline import run_on_map
    from seal_cli.sim.policies import make_policy

    base = layout_seed(seed, layout, m.name)
    world = sample_layout(m, np.random.default_rng(base))
    outcomes = []
    for c, text in enumerate(commands):
        for name in policies:
            start = time.perf_counter()
            rng = np.random.default_rng(base + 1 + c)
            _, result = run_on_map(world, text, library, make_policy(name, particles), rng=rng)
            outcomes.append(Outcome(f"{m.name}-layout{layout}-{c}", text, name, result.completed,
                                    round(result.path_m, 3), result.steps, result.reason, float("nan"),
                                    round(time.perf_counter() - start, 3), tuple(result.plan)))
    return outcomes


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

    for name in policies:  # the map suite's success is "every frame executed": no judge for a frame-less run
        if getattr(make_policy(name, 1), "drives_itself", False):
            raise SealError(f"policy {name!r} runs from the text alone, and the map suite judges success by seal's "
                            "frames; run it on --suite alfred2d, whose judge reads the world")
    m = load_map(map_path)
    library = load_library(framelib)
    vocabulary = vocabulary_of_map(m)
    for text in commands:     # a command that cannot be parsed or planned fails here, cleanly
        plan_text(text, library, vocabulary=vocabulary)
    work = [(i, tuple(commands), tuple(policies), seed, particles) for i in range(layouts)]
    jobs = max(1, min(jobs or os.cpu_count() or 1, layouts or 1))
    if jobs == 1:
        _WORKER.update(map=m, library=library)
        yield from in_order(map(_work, work), layouts, progress)
        return
    import multiprocessing

    context = multiprocessing.get_context("fork" if "fork" in multiprocessing.get_all_start_methods() else "spawn")
    with context.Pool(jobs, initializer=_init_worker, initargs=(map_path, framelib)) as pool:
        yield from in_order(pool.imap_unordered(_work, work), layouts, progress)
