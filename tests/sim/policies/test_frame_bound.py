"""frame_dp on a drawn house: where the exact programme over regions looks first, and why it says so."""

from __future__ import annotations

import dataclasses
import re

import numpy as np

from seal_cli.bench.houses import cottage
from seal_cli.frames.library import Library
from seal_cli.maps.model import ObjectTruth, Robot
from seal_cli.pipeline import run_on_map
from seal_cli.sim.policies import make_policy

SAID = re.compile(r"looks for (\w+): (\w[\w ]*): \w+ (0\.\d\d|1\.00)(?: and (\w+) (0\.\d\d|1\.00))? there, ([\d.]+) m "
                  r"\(expected ([\d.]+) m to reach both, by the exact programme over regions\)")


def _house(spoon: tuple[float, float], cup: tuple[float, float], at: tuple[float, float]):  # type: ignore[no-untyped-def]
    m = cottage()
    objects = (ObjectTruth("spoon", spoon), ObjectTruth("cup", cup))
    return dataclasses.replace(m, objects=objects, robot=Robot((*at, 0.0)))


def test_the_programme_weighs_both_things_and_says_so(library: Library) -> None:
    # the cottage's hall, nearer the bedroom's door: spoons are in the kitchen or the bedroom, cups in the
    # family room or the bedroom; for "stir the cup" the bedroom, where both may be, is looked at first
    world = _house(spoon=(3.0, 1.0), cup=(4.0, 1.5), at=(7.5, 4.5))
    agent, result = run_on_map(world, "stir the cup", library, make_policy("frame_dp"), rng=np.random.default_rng(0))
    assert result.completed, result.reason
    said = [SAID.search(r.text) for r in agent.records if r.kind == "search"]
    assert said and said[0] is not None, [r.text for r in agent.records if r.kind == "search"]
    first = said[0]
    assert first.group(1) == "spoon" and first.group(2) == "bedroom" and first.group(4) == "cup"
    assert float(first.group(3)) > 0.3 and float(first.group(5)) > 0.3


def test_a_region_looked_from_is_not_chosen_again_and_a_thing_off_every_region_is_still_found(library: Library) -> None:
    world = _house(spoon=(7.5, 9.0), cup=(12.0, 7.0), at=(7.5, 1.0))   # the spoon in the hall: no prior puts it there
    agent, result = run_on_map(world, "stir the cup", library, make_policy("frame_dp"), rng=np.random.default_rng(0),
                               search_end=None)
    assert result.completed, result.reason
    policy = agent.policy
    rooms = [m.group(2) for r in agent.records if r.kind == "search" and (m := SAID.search(r.text)) is not None]
    assert len(rooms) == len(set(rooms)) and policy.looked   # each region once, by this model
