"""The task suite: every policy on the same ALFRED-2D episodes, success and path length per task type.

For each episode, each policy gets a fresh copy of the same world, the same start, the same
commanded frames (from ALFRED's labels with ``goal="gold"``, or parsed from the first human goal
sentence with ``goal="human"``) and its own random generator seeded from the run's seed and the
episode's id, so the figures do not depend on how episodes are spread over processes. Success is
judged on the world at the end (:func:`seal_cli.bench.alfred2d.judge`): every goal condition of the task
type holds, in the right order.

Episodes run in ``jobs`` worker processes (each loads the floor plans and the priors once); the
per-episode results come back in episode order, and :func:`summarise` folds them into the
SPEC's ``{"groups": {type: {"n", "success": {...}, "path_m": {...}}}}``.
"""

from __future__ import annotations

import math
import os
import time
import zlib
from collections.abc import Callable, Iterable, Iterator, Sequence
from dataclasses import asdict, dataclass
from pathlib import Path
from typing import Any

import numpy as np

from seal_cli.bench.alfred2d import (
    TASK_TYPES,
    Episode,
    Suite,
    build_scene,
    gold_classes,
    gold_commands,
    judge,
    load_suite,
)
from seal_cli.errors import SealError
from seal_cli.frames.library import Library
from seal_cli.frames.model import Binding
from seal_cli.frames.reading import load_library

__all__ = ["GOALS", "Outcome", "commands_for", "in_order", "run_episode", "run_suite", "summarise"]

GOALS = ("gold", "human")
BACKENDS = ("process", "ray")
"""Where episodes run: this machine's process pool, or Ray's drop-in pool (the ``ray`` extra)."""


@dataclass(frozen=True)
class Outcome:
    """One policy on one episode."""

    task_id: str
    group: str
    policy: str
    success: bool
    path_m: float
    steps: int
    reason: str
    expert_path_m: float
    seconds: float
    commanded: tuple[str, ...] = ()

    def to_json(self) -> dict[str, Any]:
        return asdict(self)


def episode_seed(seed: int, episode: Episode) -> int:
    """A seed for one episode, the same whatever process runs it."""
    return (seed * 1_000_003 + zlib.crc32(episode.task_id.encode())) % (2 ** 32)


def commands_for(episode: Episode, library: Library, vocabulary: Sequence[str],
                 goal: str) -> tuple[list[Binding], dict[str, str]]:
    """The commanded frames of an episode, and the class of each thing they name.

    ``gold``: from ALFRED's labels. ``human``: the first goal sentence, parsed and grounded
    against the scene's classes, its frames built without a map (values are classes, or
    ``apple_2`` for a second apple)."""
    if goal == "gold":
        return gold_commands(episode.task, library, vocabulary), gold_classes(episode.task)
    if goal != "human":
        raise SealError(f"unknown goal source {goal!r}; use one of {', '.join(GOALS)}")
    from seal_cli.bench.alfred2d import scene_vocabulary
    from seal_cli.language.parser import parse_command
    from seal_cli.planning.problem import build_problem

    if not episode.goals:
        raise SealError(f"episode {episode.task_id} has no goal sentence")
    parse = parse_command(episode.goals[0], library, scene_vocabulary(vocabulary))
    problem = build_problem(parse, library)
    return list(problem.commanded), dict(problem.state.classes)


def run_episode(episode: Episode, suite: Suite, library: Library, policies: Sequence[str], *, goal: str = "gold",
                seed: int = 0, particles: int = 200) -> list[Outcome]:
    """Every policy on one episode."""
    from seal_cli.sim.agent import Agent, Budget
    from seal_cli.sim.policies import make_policy

    plan = suite.floor_plans[episode.floor_plan]
    outcomes = []
    for name in policies:
        start = time.perf_counter()
        scene = build_scene(episode, plan, library, suite.priors)
        policy = make_policy(name, particles)
        if getattr(policy, "drives_itself", False):  # saycan: from the instruction text, not seal's frames
            rng = np.random.default_rng(episode_seed(seed, episode))
            outcomes.append(_run_skills(policy, episode, scene, library, goal, rng, start))
            continue
        try:
            commanded, classes = commands_for(episode, library, scene.vocabulary, goal)
        except SealError as error:
            outcomes.append(Outcome(episode.task_id, episode.group, name, False, 0.0, 0,
                                    f"cannot read the command: {error.message}", episode.expert_path_m,
                                    time.perf_counter() - start))
            continue
        rng = np.random.default_rng(episode_seed(seed, episode))
        agent = Agent(scene, library, policy, rng=rng, budget=Budget(), classes=classes)
        result = agent.run(commanded)
        verdict = judge(episode.task, scene.world)
        reason = "success" if verdict.success else (result.reason if not result.completed else verdict.reason)
        outcomes.append(Outcome(episode.task_id, episode.group, name, verdict.success, round(result.path_m, 3),
                                result.steps, reason, episode.expert_path_m, round(time.perf_counter() - start, 3),
                                tuple(str(b) for b in commanded)))
    return outcomes


def _run_skills(policy: Any, episode: Episode, scene: Any, library: Library, goal: str,
                rng: np.random.Generator, start: float) -> Outcome:
    """A policy that drives itself from the instruction text (``saycan``), judged the same way; its
    failure kinds (:func:`seal_cli.sim.skills.failure_kinds`) lead the reason."""
    from seal_cli.sim.agent import Budget
    from seal_cli.sim.skills import failure_kinds, gold_instruction

    t = episode.task
    instruction = (gold_instruction(t.type, t.object, t.receptacle, t.mrecep, t.toggle, t.sliced)
                   if goal == "gold" else (episode.goals[0] if episode.goals else ""))
    result = policy.run(scene, library, instruction, rng=rng, budget=Budget())
    verdict = judge(episode.task, scene.world)
    kinds = failure_kinds(result, verdict.success)
    reason = "success" if verdict.success else f"{'; '.join(kinds)}: {verdict.reason}"
    return Outcome(episode.task_id, episode.group, policy.name, verdict.success, round(result.path_m, 3),
                   result.steps, reason, episode.expert_path_m, round(time.perf_counter() - start, 3),
                   (instruction,))


# -- running many episodes ---------------------------------------------------------------------

_WORKER: dict[str, Any] = {}


def _init_worker(data_dir: str, split: str, limit: int | None, types: Sequence[str] | None,
                 framelib: Sequence[str] | None, sample: int | None = None) -> None:
    _WORKER["suite"] = load_suite(data_dir, split, limit=limit, types=types, sample=sample)
    _WORKER["library"] = load_library(framelib)


def _work(args: tuple[int, Sequence[str], str, int, int]) -> tuple[int, list[Outcome]]:
    index, policies, goal, seed, particles = args
    suite: Suite = _WORKER["suite"]
    return index, run_episode(suite.episodes[index], suite, _WORKER["library"], policies, goal=goal, seed=seed,
                              particles=particles)


def run_suite(data_dir: str | Path, split: str, policies: Sequence[str], *, goal: str = "gold",
              limit: int | None = None, types: Sequence[str] | None = None, seed: int = 0, jobs: int | None = None,
              particles: int = 200, framelib: Sequence[str] | None = None,
              progress: Callable[[int, int], None] | None = None, backend: str = "process",
              sample: int | None = None) -> Iterator[Outcome]:
    """Run the policies on the split's episodes (``limit`` per task type, or a stratified ``sample``
    per task type: :func:`~seal_cli.bench.alfred2d.load_suite`), in ``jobs`` processes;
    yields the outcomes in episode order, calling ``progress(done, total)`` as episodes finish.

    ``backend``: ``process`` (this machine's process pool) or ``ray`` (``ray.util.multiprocessing.Pool``,
    the ``ray`` extra: a local Ray, or the cluster ``RAY_ADDRESS`` names). Each episode's generator is
    seeded from its id, so both give the same outcomes."""
    if backend not in BACKENDS:
        raise SealError(f"unknown backend {backend!r}; use one of {', '.join(BACKENDS)}")
    if goal not in GOALS:
        raise SealError(f"unknown goal source {goal!r}; use one of {', '.join(GOALS)}")
    from seal_cli.sim.policies import make_policy

    for name in policies:  # a missing extra (saycan's language model) fails here, before any worker starts
        policy = make_policy(name, 1)
        if getattr(policy, "drives_itself", False):
            getattr(policy, "scorer", None)
    suite = load_suite(data_dir, split, limit=limit, types=types, with_priors=False, sample=sample)
    total = len(suite.episodes)
    jobs = max(1, min(jobs or os.cpu_count() or 1, total or 1))
    work = [(i, tuple(policies), goal, seed, particles) for i in range(total)]
    init = (str(data_dir), split, limit, tuple(types) if types else None, tuple(framelib) if framelib else None,
            sample)
    if backend == "ray":
        try:
            from ray.util.multiprocessing import Pool as RayPool
        except ImportError as error:
            raise SealError("--backend ray needs the ray extra: pip install 'seal[ray]'") from error
        with RayPool(jobs, initializer=_init_worker, initargs=init) as ray_pool:
            yield from in_order(ray_pool.imap_unordered(_work, work), total, progress)
        return
    if jobs == 1:
        _init_worker(*init)
        results: Iterable[tuple[int, list[Outcome]]] = map(_work, work)
        yield from in_order(results, total, progress)
        return
    from seal_cli.bench.workers import unordered

    yield from in_order(unordered(_work, work, jobs, initializer=_init_worker, initargs=init), total, progress)


def in_order(results: Iterable[tuple[int, list[Outcome]]], total: int,
             progress: Callable[[int, int], None] | None = None) -> Iterator[Outcome]:
    """The outcomes of ``(index, outcomes)`` pairs that arrive in any order, yielded in index order
    as soon as every earlier index has arrived; ``progress(done, total)`` after each arrival."""
    done: dict[int, list[Outcome]] = {}
    following = 0
    for count, (index, outcomes) in enumerate(results, 1):
        done[index] = outcomes
        if progress:
            progress(count, total)
        while following in done:
            yield from done.pop(following)
            following += 1


def summarise(outcomes: Iterable[Outcome], policies: Sequence[str]) -> dict[str, Any]:
    """The SPEC's JSON: per task type, the number of episodes, and per policy the success rate and
    the mean path in metres over all its episodes; also ``path_m_solved`` (mean over the episodes
    that every policy solved, the fair comparison of search cost) and the expert's mean path."""
    by_group: dict[str, dict[str, list[Outcome]]] = {}
    for o in outcomes:
        by_group.setdefault(o.group, {}).setdefault(o.task_id, []).append(o)
    groups: dict[str, Any] = {}
    order = [g for g in TASK_TYPES if g in by_group] + sorted(g for g in by_group if g not in TASK_TYPES)
    everything: dict[str, list[Outcome]] = {}
    for group in [*order, "all"]:
        episodes = by_group[group] if group != "all" else everything
        if group != "all":
            everything.update(episodes)
        if not episodes:
            continue
        groups[group] = _figures(episodes, policies)
    return {"groups": groups, "policies": list(policies)}


def _figures(episodes: dict[str, list[Outcome]], policies: Sequence[str]) -> dict[str, Any]:
    per: dict[str, list[Outcome]] = {p: [] for p in policies}
    for outs in episodes.values():
        for o in outs:
            per.setdefault(o.policy, []).append(o)
    solved = [tid for tid, outs in episodes.items() if all(o.success for o in outs)]
    expert = [outs[0].expert_path_m for outs in episodes.values() if math.isfinite(outs[0].expert_path_m)]
    return {
        "n": len(episodes),
        "success": {p: _mean([o.success for o in per[p]]) for p in policies},
        "path_m": {p: _mean([o.path_m for o in per[p]]) for p in policies},
        "path_m_solved": {p: _mean([o.path_m for o in per[p] if o.task_id in solved]) for p in policies},
        "n_solved_by_all": len(solved),
        "expert_path_m": _mean(expert),
    }


def _mean(values: Sequence[float | bool]) -> float | None:
    return round(float(np.mean(values)), 4) if len(values) else None
