"""When a search ends: the unsearched share of a kind's prior, and seal run stopping on it."""

from __future__ import annotations

import json
from pathlib import Path

import numpy as np
import pytest
from typer.testing import CliRunner

from seal_cli.cli import app
from seal_cli.maps.model import Map, Place, Room
from seal_cli.maps.priors import FLOOR
from seal_cli.sim.unsearched import SEARCH_END, Unsearched

CLINIC = Path(__file__).resolve().parents[2] / "maps" / "clinic.yaml"


def two_rooms() -> Map:
    return Map("two", bounds=(0.0, 0.0, 4.0, 2.0),
               rooms=(Room("a", ((0, 0), (2, 0), (2, 2), (0, 2))), Room("b", ((2, 0), (4, 0), (4, 2), (2, 2)))),
               places=(Place("fridge_1", "fridge", (3.5, 1.0), openable=True),),
               priors={"cup": {"a": 0.6}, "milk": {"fridge": 0.8}})


def test_the_unsearched_mass_is_the_prior_until_looked_at_then_keeps_one_minus_p_detect() -> None:
    m = two_rooms()
    cup = Unsearched.of(m, "cup")
    assert cup.left == pytest.approx(1.0) and cup.inside == {}
    in_a = m.free_cell_room == 0
    assert cup.cells[in_a].sum() == pytest.approx((1 - FLOOR) * 0.6 + (FLOOR + (1 - FLOOR) * 0.4) * in_a.mean())
    cup.saw(in_a)
    expected = cup.cells[~in_a].sum() + 0.1 * Unsearched.of(m, "cup").cells[in_a].sum()
    assert cup.left == pytest.approx(expected) and cup.searched_rooms() == ["a"]
    cup.saw(np.ones(len(m.free_centres), bool))
    assert cup.left == pytest.approx(0.1 * expected)


def test_the_mass_left_at_some_targets_is_theirs_alone() -> None:
    """e2e28: the search for another one counts only where the prior keeps such things (its targets), not its floor
    share spread everywhere."""
    m = two_rooms()
    milk = Unsearched.of(m, "milk", ["fridge_1"])
    near = float(milk.cells[m.target_cells("fridge")].sum())     # the floor share on the cells by it
    assert milk.left_at(["fridge"]) == pytest.approx(milk.inside["fridge_1"] + near) and milk.left_at([]) == 0.0
    assert milk.left_at(["fridge"]) < milk.left                  # the floor share is not the fridge's
    cup = Unsearched.of(m, "cup")
    in_a = m.free_cell_room == 0
    assert cup.left_at(["a"]) == pytest.approx(float(cup.cells[in_a].sum()))
    cup.saw(in_a)
    assert cup.left_at(["a"]) == pytest.approx(0.1 * float(Unsearched.of(m, "cup").cells[in_a].sum()))
    milk.saw(np.zeros(len(m.free_centres), bool), ["fridge_1"])
    assert milk.left_at(["fridge"]) == pytest.approx(near)


def test_the_mass_in_a_shut_place_waits_until_the_robot_looks_into_it() -> None:
    m = two_rooms()
    milk = Unsearched.of(m, "milk", shut=["fridge_1"])
    assert milk.inside == {"fridge_1": pytest.approx((1 - FLOOR) * 0.8)}
    milk.saw(np.ones(len(m.free_centres), bool))           # seen all round, the fridge shut
    assert milk.left == pytest.approx(0.1 * (1 - (1 - FLOOR) * 0.8) + (1 - FLOOR) * 0.8)
    milk.saw(np.zeros(len(m.free_centres), bool), looked_into=["fridge_1"])
    assert milk.inside == {"fridge_1": 0.0} and milk.left < SEARCH_END
    open_fridge = Unsearched.of(m, "milk")                  # not shut: its mass lies around it, to be seen
    assert open_fridge.inside == {} and open_fridge.left == pytest.approx(1.0)


def test_a_kind_the_map_has_a_prior_of_but_not_in_the_house_ends_its_search_short_of_a_sweep() -> None:
    """The clinic's priors name a sandwich (in the fridge 0.7, on the table 0.2) and it has none: the robot
    looks where sandwiches are likely and stops, rather than searching until its budget is spent."""
    runner = CliRunner()
    result = runner.invoke(app, ["run", "--map", str(CLINIC), "bring me the sandwich", "--particles", "50", "--json"])
    assert result.exit_code == 1
    report = json.loads(result.stdout)
    assert report["why"] == "not_found" and report["reason"].startswith("no sandwich found: searched the ")
    assert "looked into fridge_1" in report["reason"]
    assert "it would have been seen with probability 0.9" in report["reason"]
    assert report["path_m"] < 30.0
    swept = runner.invoke(app, ["run", "--map", str(CLINIC), "bring me the sandwich", "--particles", "50", "--json",
                                "--search-end", "0", "--max-metres", "80"])
    assert swept.exit_code == 1 and json.loads(swept.stdout)["reason"] == "out of path budget (80 m)"   # no end but it
