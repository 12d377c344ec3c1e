"""prior_optimal and SeFM's whole-plan search on a drawn house: where they look first, and why they say so."""

from __future__ import annotations

import dataclasses
import re

import numpy as np

from seal_cli.bench.houses import cottage
from seal_cli.frames.library import Library
from seal_cli.maps.model import ObjectTruth, Robot
from seal_cli.pipeline import run_on_map
from seal_cli.sim.policies import make_policy

NARRATION = re.compile(r"looks for spoon: (\w+): spoon (0\.\d\d)(?: and cup (0\.\d\d))? there, ([\d.]+) m "
                       r"\(expected ([\d.]+) m to finish the plan\)")


def _house(spoon: tuple[float, float], cup: tuple[float, float]):  # type: ignore[no-untyped-def]
    m = cottage()
    objects = (ObjectTruth("spoon", spoon), ObjectTruth("cup", cup))
    return dataclasses.replace(m, objects=objects, robot=Robot((7.5, 5.0, 0.0)))


def test_both_look_first_where_spoon_and_cup_may_both_be_and_say_why(library: Library) -> None:
    # the hall's middle: the bedroom (spoons and cups) and the kitchen (spoons only) are equally near
    world = _house(spoon=(3.0, 1.0), cup=(4.0, 1.5))
    for name in ("prior_optimal", "sefm"):
        agent, result = run_on_map(world, "stir the cup", library, make_policy(name, 100), rng=np.random.default_rng(0))
        assert result.completed, result.reason
        said = [NARRATION.search(r.text) for r in agent.records if r.kind == "search"]
        assert said and all(said), [r.text for r in agent.records if r.kind == "search"]
        first = next(m for m in said if m is not None and float(m.group(2)) > 0.2)  # past the hall it stands in
        assert first.group(1) == "bedroom" and first.group(3) is not None and float(first.group(3)) > 0.3


def test_prior_optimal_removes_what_it_has_seen_and_finds_a_thing_off_every_prior(library: Library) -> None:
    world = _house(spoon=(7.5, 9.0), cup=(12.0, 7.0))      # the spoon in the hall, where no prior puts it
    agent, result = run_on_map(world, "stir the cup", library, make_policy("prior_optimal"),
                               rng=np.random.default_rng(0))
    assert result.completed, result.reason
    policy = agent.policy
    assert policy.seen.any() and not policy.weights("spoon")[policy.seen].any()
