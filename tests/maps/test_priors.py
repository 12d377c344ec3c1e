"""maps.priors: a prior as masses on targets' free cells and a uniform rest; weights, samples, densities."""

from __future__ import annotations

import numpy as np
import pytest

from seal_cli.maps.formats.map_server import load_map
from seal_cli.maps.model import Map
from seal_cli.maps.priors import FLOOR, build_prior, target_cells


@pytest.fixture(scope="module")
def apartment() -> Map:
    return load_map("apartment")


def test_targets_are_a_rooms_cells_a_places_reach_or_every_place_of_a_class(apartment: Map) -> None:
    kitchen = target_cells(apartment, "kitchen")
    assert len(kitchen) and set(apartment.room_of(apartment.free_centres[kitchen])) == {"kitchen"}
    fridge = target_cells(apartment, "fridge_1")
    reach = apartment.place("fridge_1").reach
    assert len(fridge) and np.all(np.linalg.norm(apartment.free_centres[fridge] - apartment.place("fridge_1").at,
                                                 axis=1) <= reach + 1e-9)
    sofas = target_cells(apartment, "sofa")
    assert set(sofas) == set(target_cells(apartment, "sofa_1")) | set(target_cells(apartment, "sofa_2"))
    assert len(target_cells(apartment, "nowhere")) == 0
    assert np.all(np.diff(kitchen) > 0) and np.all(np.diff(sofas) > 0)       # sorted, no repeats


def test_the_weights_are_the_masses_with_the_floor(apartment: Map) -> None:
    prior = build_prior(apartment, "apple")
    assert prior.masses == pytest.approx({"fridge": 0.4, "counter": 0.4, "kitchen": 0.2, "_rest": 0.0})
    weights = prior.weights
    assert weights.sum() == pytest.approx(1.0) and np.all(weights > 0)        # no free cell is impossible
    fridge = target_cells(apartment, "fridge")
    alone = weights.min()
    assert alone == pytest.approx(FLOOR / prior.free_cells)                    # where no target reaches
    assert weights[fridge].sum() >= (1 - FLOOR) * 0.4
    some = np.array([0, 5, int(fridge[0])])
    assert prior.cell_weights(some) == pytest.approx(weights[some])


def test_a_class_without_a_prior_is_uniform(apartment: Map) -> None:
    prior = build_prior(apartment, "unicorn")
    assert prior.components == () and prior.masses == {"_rest": 1.0}
    assert prior.weights == pytest.approx(np.full(prior.free_cells, 1 / prior.free_cells))


def test_samples_follow_the_weights_and_the_seed(apartment: Map) -> None:
    prior = build_prior(apartment, "apple")
    points = prior.sample(20_000, np.random.default_rng(4))
    assert points.shape == (20_000, 2)
    assert np.array_equal(points, prior.sample(20_000, np.random.default_rng(4)))
    in_kitchen = np.mean(np.array(apartment.room_of(points)) == "kitchen")
    assert in_kitchen == pytest.approx(prior.room_masses()["kitchen"], abs=0.01)
    assert np.all(apartment.free_index(points) >= 0)                           # every draw on free space


def test_the_density_integrates_to_one_over_free_space(apartment: Map) -> None:
    prior = build_prior(apartment, "cup")
    density = prior.density(apartment.free_centres)
    assert density.sum() * apartment.cell_area == pytest.approx(1.0)
    assert prior.density([[500.0, 500.0]]).tolist() == [0.0]
    assert sum(prior.room_masses().values()) == pytest.approx(1.0)


def test_a_place_said_takes_the_said_share_and_the_map_keeps_the_rest(apartment: Map) -> None:
    from seal_cli.maps.priors import SAID, said_masses

    assert said_masses({"fridge": 0.4, "counter": 0.4}, ("counter_1",), 0.9) == pytest.approx(
        {"fridge": 0.04, "counter": 0.04, "counter_1": 0.9})
    prior = apartment.prior("apple", ("counter_1",))
    assert prior.masses["counter_1"] == pytest.approx(SAID)
    assert prior.masses["fridge"] == pytest.approx(0.4 * (1 - SAID))
    counter = target_cells(apartment, "counter_1")
    assert prior.weights[counter].sum() > prior.weights[target_cells(apartment, "fridge")].sum()
    assert apartment.prior("apple", ("counter_1",)) is prior and apartment.prior("apple") is not prior   # cached apart
    unknown = apartment.prior("beer", ("fridge_1",))          # a class the map has no prior of: the word alone
    assert unknown.masses == pytest.approx({"fridge_1": SAID, "_rest": 1 - SAID})
    assert apartment.prior("apple", ("nowhere",)).masses == apartment.prior("apple").masses   # not on the map
