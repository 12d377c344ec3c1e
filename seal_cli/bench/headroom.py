"""How much frame context *can* save in each case of the context suite, from the priors and the map alone.

For one house, start and command, before any look: the exact programme over regions
(:func:`~seal_cli.sim.policies.frame_dp.solve`, the joint search for the plan's two unknown things) against
the searcher that looks for one thing at a time (:func:`~seal_cli.sim.policies.frame_dp.one_at_a_time`: the
first thing's own optimal order, what it sees of the second kept), both under the same model — regions, the
map's priors, the lattice's metres (:mod:`~seal_cli.sim.policies.frame_dp` states the model and where it stops
being exact). No layout is drawn and no policy is run: the beliefs are the priors, the robot has not looked.

A case *fits* the issue's definition ("frames need two or more things with overlapping priors", where context
changes the best order) when the programme's first region differs from the one-at-a-time searcher's and the
expected saving is at least :data:`FITS_SHARE` of the one-at-a-time path: the things' priors overlap in a way
that changes what to look at first, by enough to measure.

The context suite (``seal bench tasks --suite context``) is made of the cases that fit: :func:`candidates` computes
every :data:`CANDIDATE_COMMANDS` command from :data:`CANDIDATE_STARTS` starts drawn with :data:`CANDIDATE_SEED` on
each house, :func:`selected` keeps those that fit, and ``scripts/context_cases.py`` writes them, with their values,
to :data:`CASES_FILE` (``--check``: the file is what the criterion gives now).
"""

from __future__ import annotations

import dataclasses
from collections.abc import Iterator, Sequence
from typing import Any

import numpy as np

from seal_cli.bench.context import COMMANDS, House, drawn_starts
from seal_cli.frames.library import Library
from seal_cli.frames.model import Binding
from seal_cli.maps.model import Map, ObjectTruth
from seal_cli.sim.agent import Agent, View
from seal_cli.sim.policies.frame_bound import FrameDPPolicy
from seal_cli.sim.policies.frame_dp import one_at_a_time, solve

__all__ = ["CANDIDATE_COMMANDS", "CANDIDATE_SEED", "CANDIDATE_STARTS", "FITS_SHARE", "Headroom", "candidates",
           "headroom", "headrooms", "selected"]

FITS_SHARE = 0.05
"""The least expected saving, as a share of the one-at-a-time path, for a case to fit (module docstring):
set before any case was computed, about the standard error of a house's mean path over its 36 runs."""


@dataclasses.dataclass(frozen=True)
class Headroom:
    """One case: the expected metres of the joint programme and of one thing at a time, and their first regions."""

    house: str
    command: str
    start: int
    first: str
    second: str | None
    joint_m: float
    one_at_a_time_m: float
    joint_region: str | None
    one_at_a_time_region: str | None
    covered: float
    """The share of the two priors the weighed regions hold (the rest is beyond the model)."""
    pose: tuple[float, float, float] = (0.0, 0.0, 0.0)
    """The robot's start."""

    @property
    def saving(self) -> float:
        """The expected saving as a share of the one-at-a-time path."""
        return (self.one_at_a_time_m - self.joint_m) / self.one_at_a_time_m if self.one_at_a_time_m > 0 else 0.0

    @property
    def fits(self) -> bool:
        return self.joint_region != self.one_at_a_time_region and self.saving >= FITS_SHARE

    def to_json(self) -> dict[str, Any]:
        return {**dataclasses.asdict(self), "pose": list(self.pose), "joint_m": round(self.joint_m, 3),
                "one_at_a_time_m": round(self.one_at_a_time_m, 3), "covered": round(self.covered, 3),
                "saving": round(self.saving, 4), "fits": self.fits}


class _Asked(Exception):
    """The probe's answer, carried out of the agent's run at its first choice of a view."""

    def __init__(self, found: Headroom | None) -> None:
        super().__init__("probed")
        self.found = found


class _Probe(FrameDPPolicy):
    """Asked for its first view, it sets up the programme under the priors (no look counted) and stops the run."""

    name = "headroom"
    case: tuple[str, str, int] = ("", "", 0)
    pose: tuple[float, float, float] = (0.0, 0.0, 0.0)

    def next_view(self, agent: Agent, binding: Binding, target: str) -> View | None:
        m = self.map
        if any(k.movable for k in agent.known.values()):
            raise RuntimeError(f"{m.name}: the probe's first look found a thing; the corner it hides them in is seen")

        def prior(cls: str) -> np.ndarray:
            return np.asarray(m.prior(cls).weights, dtype=float)

        made = self.problem_of(agent, binding, target, weights=prior, looked=())
        if made is None:
            raise _Asked(None)
        problem, regions, first, second = made
        joint, alone = solve(problem), one_at_a_time(problem)
        covered = float(problem.first.sum()) if problem.second is None else \
            float((problem.first.sum() + problem.second.sum()) / 2)

        def name(k: int | None) -> str | None:
            return None if k is None else regions[k].name

        house, command, start = self.case
        raise _Asked(Headroom(house, command, start, first, second if problem.second is not None else None,
                              joint.expected_m, alone.expected_m, name(joint.region), name(alone.region), covered,
                              self.pose))


def _unseen_world(m: Map) -> Map:
    """The map with every thing put in a corner of its bounds (a wall or beyond the house on the maps here, where no
    look reaches; :meth:`_Probe.next_view` checks that nothing was found): the probe's first choice is made before
    anything is found, whatever a layout would hold."""
    far = (float(m.bounds[2]) - 1e-3, float(m.bounds[3]) - 1e-3)
    return dataclasses.replace(m, objects=tuple(ObjectTruth(o.cls, far) for o in m.objects))


def headroom(m: Map, pose: tuple[float, float, float], command: str, library: Library,
             start: int = 1) -> Headroom | None:
    """The case of one command from one start on one map (None: no region holds either thing)."""
    from seal_cli.maps.model import Robot
    from seal_cli.pipeline import run_on_map

    world = dataclasses.replace(_unseen_world(m), robot=Robot(pose))
    probe = _Probe()
    probe.case = (m.name, command, start)
    probe.pose = (float(pose[0]), float(pose[1]), float(pose[2]))
    try:
        run_on_map(world, command, library, probe, rng=np.random.default_rng(0), search_end=None)
    except _Asked as asked:
        return asked.found
    return None


def headrooms(built: Sequence[House], library: Library, commands: Sequence[str] = COMMANDS) -> Iterator[Headroom]:
    """Every command from every start of every house, in that order."""
    for house in built:
        for s, pose in enumerate(house.starts):
            for command in commands:
                found = headroom(house.map, pose, command, library, s + 1)
                if found is not None:
                    yield found


CANDIDATE_COMMANDS = (*COMMANDS, "put the spoon in the mug", "pour the kettle into the cup",
                      "bring me the cup and the spoon", "bring me the mug and the kettle",
                      "bring me the spoon and the mug")
"""The context suite's commands and more of the same kind (two things, each with its prior), the candidates of
:func:`candidates`; written before any case was computed, by the things' classes, not by any result."""

CANDIDATE_STARTS = 32
"""Starts drawn per house (:func:`~seal_cli.bench.context.drawn_starts`) for the candidates."""

CANDIDATE_SEED = 26
"""The seed of the candidates' drawn starts (this round's number, set before any case was computed)."""


def candidates(built: Sequence[House], library: Library, commands: Sequence[str] = CANDIDATE_COMMANDS,
               starts: int = CANDIDATE_STARTS, seed: int = CANDIDATE_SEED) -> Iterator[Headroom]:
    """Every command from ``starts`` starts drawn with ``seed`` on every house (numbered 1.. in the drawn order),
    in that order: the priors and the map alone, no layout, no policy."""
    yield from headrooms([House(h.map, drawn_starts(h.map, starts, seed)) for h in built], library, commands)


def selected(cases: Sequence[Headroom]) -> list[Headroom]:
    """The cases that fit (:attr:`Headroom.fits`), in their order: the context suite."""
    return [c for c in cases if c.fits]
