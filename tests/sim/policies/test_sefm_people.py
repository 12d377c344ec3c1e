"""SeFM's belief over a person the robot led (``sefm.people_now``): it moves with them (e2e26)."""

from __future__ import annotations

import math

import numpy as np

from seal_cli.frames.library import Library


def test_the_commanded_belief_about_a_led_person_is_where_they_were_led(library: Library) -> None:
    """"guide Anna to the kitchen and then bring her the milk": the Bring's particles held a cluster where Anna sat at
    breakfast (2, 8) after she was led to the kitchen; now none lies there, and they gather by her and the fridge."""
    from seal_cli import pipeline
    from seal_cli.maps.formats.map_server import load_map
    from seal_cli.sim.policies.sefm import SeFMPolicy, people_now

    house = load_map("guesthouse")
    policy = SeFMPolicy(particles=100)
    policy.keep_clouds = True
    agent, result = pipeline.run_on_map(house, "guide Anna to the kitchen and then bring her the milk", library,
                                        policy, rng=np.random.default_rng(0))
    assert result.completed, result.reason
    anna = agent.world.items["anna"].at
    assert house.room_of([anna]) == ["kitchen"]
    moved = {p.key: p for p in people_now(house, agent)}
    assert moved["anna"].at == anna and moved["ben"] == house.person("ben")       # only the one led has moved
    bring = [c for c in policy.clouds if c["commanded"].startswith("bring")]
    assert bring, [c["commanded"] for c in policy.clouds]
    X, W = bring[-1]["commanded_particles"]
    where = X.reshape(-1, X.shape[-1])[:, :2]
    near_start = np.hypot(where[:, 0] - 2.0, where[:, 1] - 8.0) < 1.5
    assert not near_start.any()
    assert min(math.dist(tuple(x), anna) for x in where) < 1.0
