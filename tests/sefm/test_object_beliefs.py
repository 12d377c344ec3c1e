"""sefm.object_beliefs: SLiM-style particle sets per object class, negative information and detections."""

from __future__ import annotations

import math
from collections.abc import Callable

import numpy as np
import pytest

from seal_cli.maps.formats.map_server import load_map
from seal_cli.maps.model import Map
from seal_cli.sefm.object_beliefs import ObjectBeliefs, ObjectModel, Source, Views, source_for


@pytest.fixture(scope="module")
def apartment() -> Map:
    return load_map("apartment")


def test_a_value_is_a_place_a_room_or_an_object_class(apartment: Map) -> None:
    fridge = source_for(apartment, "fridge_1")
    assert fridge.kind == "place" and fridge.points == (apartment.place("fridge_1").at,) and fridge.static
    assert source_for(apartment, "sofa").kind == "place" and len(source_for(apartment, "sofa").points) == 2
    kitchen = source_for(apartment, "kitchen")
    assert kitchen.kind == "room" and kitchen.room == apartment.room_id("kitchen")
    cup = source_for(apartment, "Cup")
    assert cup == Source("cup", "object") and not cup.static


def test_a_view_counts_once_until_the_robot_moves_turns_or_a_place_opens() -> None:
    views = Views(step=0.5, turn=math.radians(30))
    assert views.first_look((0.0, 0.0, 0.0), ())
    assert not views.first_look((0.3, 0.0, 0.1), ())           # near, same heading
    assert views.first_look((0.3, 0.0, 1.0), ())               # turned
    assert views.first_look((2.0, 0.0, 0.0), ())               # moved
    assert views.first_look((0.0, 0.0, 0.0), ((1.0, 1.0, 0.5),))  # a place shut that was not
    all_round = Views(step=0.5, turn=None)
    assert all_round.first_look((0.0, 0.0, 0.0), ()) and not all_round.first_look((0.0, 0.0, 3.0), ())


def test_a_narrow_sensor_turned_by_its_field_of_view_takes_a_new_view(apartment: Map) -> None:
    """A 1° sensor turning round on the spot (the agent at a view) sees a new sliver at each turn: each look is a
    new view, not one of twelve (search16: a turn counted only past 30°, so a 1° look round gave the misses of 12
    slivers of 360)."""
    import dataclasses

    narrow = dataclasses.replace(apartment, sensor=dataclasses.replace(apartment.sensor, fov_deg=1.0))
    beliefs = ObjectBeliefs.from_prior(narrow, [source_for(narrow, "cup")], 50, np.random.default_rng(0))
    assert beliefs.views.turn is not None and abs(beliefs.views.turn - math.radians(1.0)) < 1e-12
    assert all(beliefs.views.first_look((0.0, 0.0, math.radians(k)), ()) for k in range(360))
    assert not beliefs.views.first_look((0.0, 0.0, math.radians(0.5)), ())   # half a degree: the same sliver
    wide = ObjectBeliefs.from_prior(apartment, [source_for(apartment, "cup")], 50, np.random.default_rng(0))
    assert wide.views.turn is None


def test_beliefs_start_from_the_prior_on_free_space(apartment: Map) -> None:
    sources = [source_for(apartment, "cup"), source_for(apartment, "fridge_1")]
    beliefs = ObjectBeliefs.from_prior(apartment, sources, 300, np.random.default_rng(0))
    assert beliefs.X.shape == (2, 300, 2) and beliefs.particles == 300
    assert np.allclose(beliefs.W.sum(axis=1), 1.0) and np.allclose(beliefs.ess(), 300)
    assert beliefs.row("Cup") == 0 and beliefs.row("fridge_1") == 1
    with pytest.raises(KeyError):
        beliefs.row("teapot")
    assert beliefs.model == ObjectModel.for_map(apartment)
    again = ObjectBeliefs.from_prior(apartment, sources, 300, np.random.default_rng(0))
    assert np.array_equal(again.X, beliefs.X)


def test_seeing_nothing_moves_mass_out_of_view_and_a_detection_pulls_it_in(apartment: Map) -> None:
    rng = np.random.default_rng(1)
    beliefs = ObjectBeliefs.from_prior(apartment, [source_for(apartment, "cup")], 400, rng)
    centre = np.array([0.0, 3.0])

    def near(points: np.ndarray) -> np.ndarray:
        return np.linalg.norm(np.asarray(points) - centre, axis=-1) < 2.5

    def mass_near(b: ObjectBeliefs) -> float:
        return float(b.W[0][near(b.X[0])].sum())

    before = mass_near(beliefs)
    assert before > 0
    beliefs.update((0.0, 3.0, 0.0), near, [], [], [], rng)
    assert mass_near(beliefs) < before / 2
    beliefs.update((0.0, 3.0, 0.0), near, [("cup", (0.5, 3.5))], [], [], rng)
    close = np.linalg.norm(beliefs.X[0] - np.array([0.5, 3.5]), axis=1) < 0.6
    assert float(beliefs.W[0][close].sum()) > 0.5
    assert np.isclose(beliefs.W.sum(), 1.0)


def test_missed_is_the_log_chance_under_the_belief_that_every_new_look_missed(apartment: Map) -> None:
    """``missed``: each new view with nothing seen adds log(1 − p × the belief's share in view); a view used
    already adds nothing (its misses count once); a detection of the class starts it again (search20)."""
    rng = np.random.default_rng(2)
    beliefs = ObjectBeliefs.from_prior(apartment, [source_for(apartment, "cup")], 400, rng)
    p = min(beliefs.model.p_detect, beliefs.model.max_p_detect)

    def region(centre: tuple[float, float]) -> Callable[[np.ndarray], np.ndarray]:
        return lambda points: np.linalg.norm(np.asarray(points) - np.asarray(centre), axis=-1) < 2.5

    expected = 0.0
    far = beliefs.X[0][np.linalg.norm(beliefs.X[0] - (0.0, 3.0), axis=1) > 6.0][0]   # a second view, away
    for centre in ((0.0, 3.0), (float(far[0]), float(far[1]))):
        share = float(beliefs.W[0][region(centre)(beliefs.X[0])].sum())
        assert share > 0.01
        expected += math.log(1.0 - p * share)
        beliefs.update((*centre, 0.0), region(centre), [], [], [], rng)
        assert beliefs.missed is not None and math.isclose(beliefs.missed[0], expected, rel_tol=1e-9)
    beliefs.update((0.1, 3.0, 0.0), region((0.1, 3.0)), [], [], [], rng)     # within view_step: not a new view
    assert math.isclose(beliefs.missed[0], expected, rel_tol=1e-9) and expected < math.log(0.7)
    beliefs.update((0.0, 3.0, 0.0), region((0.0, 3.0)), [("cup", (0.5, 3.5))], [], [], rng)
    assert beliefs.missed[0] == 0.0
