"""The household simulator: physical preconditions, hidden contents, states, sight, the log."""

from __future__ import annotations

import pytest

from seal_cli.errors import SealError
from seal_cli.frames.library import Library
from seal_cli.maps.model import Sensor
from seal_cli.sensing.model import RangeSensor
from seal_cli.sim.world import HAND, Item, Robot, World


def kitchen(library: Library, **robot: object) -> World:
    items = [
        Item("fridge_1", "fridge", (3.0, 0.0), movable=False, openable=True, access=((2.0, 0.0),)),
        Item("counter_1", "counter_top", (0.0, 1.0), movable=False, receptacle=True),
        Item("microwave_1", "microwave", (0.0, -1.0), movable=False, openable=True, toggleable=True),
        Item("sink_1", "sink_basin", (-1.0, 0.0), movable=False, receptacle=True),
        Item("lamp_1", "desk_lamp", (6.0, 0.0), movable=False, toggleable=True),
        Item("apple_1", "apple", (3.0, 0.1), parent="fridge_1"),
        Item("knife_1", "knife", (0.2, 1.0), parent="counter_1"),
        Item("pan_1", "pan", (-0.2, 1.0), receptacle=True, parent="counter_1"),
    ]
    return World(items, Robot(pose=(0.0, 0.0, 0.0), **robot), taxonomy=library.taxonomy,  # type: ignore[arg-type]
                 reach=1.5, sensor=RangeSensor(Sensor(range=3.0)))


def goto(world: World, x: float, y: float) -> None:
    world.drive([(x, y)])


def test_closed_fridge_hides_and_blocks_until_opened(library: Library) -> None:
    world = kitchen(library)
    goto(world, 2.0, 0.0)
    assert "apple_1" not in {d.id for d in world.observe()}
    failed = world.act("pick", "apple_1")
    assert not failed and "closed" in failed.message and world.robot.holding is None
    assert world.act("open", "fridge_1")
    assert "apple_1" in {d.id for d in world.observe()}
    assert world.act("pick", "apple_1") and world.robot.holding == "apple_1"
    assert world.items["apple_1"].parent == HAND


def test_reach_hand_and_receptacles(library: Library) -> None:
    world = kitchen(library)
    goto(world, 5.0, 0.0)
    far = world.act("pick", "knife_1")
    assert not far and "out of reach" in far.message
    goto(world, 0.0, 0.5)
    assert world.act("pick", "knife_1")
    busy = world.act("pick", "pan_1")
    assert not busy and "not empty" in busy.message
    closed = world.act("place", "knife_1", "microwave_1")
    assert not closed and "closed" in closed.message
    assert not world.act("place", "knife_1", "knife_1")
    assert world.act("place", "knife_1", "pan_1")
    assert world.items["knife_1"].parent == "pan_1" and world.robot.holding is None
    assert world.act("pick", "pan_1")
    assert world.held_chain("knife_1")  # the knife rides in the pan
    assert world.position("knife_1") == world.robot.pose[:2]


def test_slice_needs_a_held_knife_and_states_change(library: Library) -> None:
    world = kitchen(library)
    goto(world, 2.0, 0.0)
    world.act("open", "fridge_1")
    world.act("pick", "apple_1")
    assert not world.act("slice", "apple_1", "knife_1")
    goto(world, 0.0, 0.5)
    assert world.act("place", "apple_1", "counter_1")
    no_knife = world.act("slice", "apple_1", "knife_1")
    assert not no_knife and "hold" in no_knife.message
    world.act("pick", "knife_1")
    assert not world.act("slice", "apple_1", "pan_1")
    assert world.act("slice", "apple_1", "knife_1") and world.has("apple_1", "sliced")
    world.act("place", "knife_1", "counter_1")
    world.act("pick", "apple_1")
    assert not world.act("heat", "apple_1", "sink_1")  # a sink is not a heater
    assert world.act("heat", "apple_1", "microwave_1") and world.has("apple_1", "hot")
    t_hot = world.since("apple_1", "hot")
    goto(world, 2.0, 0.0)
    assert world.act("cool", "apple_1", "fridge_1")
    assert world.has("apple_1", "cold") and not world.has("apple_1", "hot")
    assert world.since("apple_1", "cold") > t_hot > world.since("apple_1", "sliced")


def test_toggles_and_lamps(library: Library) -> None:
    world = kitchen(library)
    goto(world, 5.0, 0.0)
    assert not world.act("toggle_on", "fridge_1")
    assert world.act("toggle_on", "lamp_1") and world.has("lamp_1", "on")
    assert world.act("toggle_off", "lamp_1") and not world.has("lamp_1", "on")
    again = world.act("toggle_off", "lamp_1")       # as Open and Close say (e2e23): nothing switched
    assert again and again.message == "lamp_1 is already off" and not world.has("lamp_1", "on")
    assert world.act("toggle_on", "lamp_1").message == "switched lamp_1 on"
    assert world.act("toggle_on", "lamp_1").message == "lamp_1 is already on"


def test_drive_counts_metres_and_log_keeps_order(library: Library) -> None:
    world = kitchen(library)
    assert world.drive([(1.0, 0.0), (1.0, 2.0)]) == pytest.approx(3.0)
    assert world.robot.path_m == pytest.approx(3.0)
    world.act("open", "fridge_1")
    world.act("pick", "knife_1")
    assert [e.action for e in world.log] == ["open", "pick"]
    assert world.log[0].step < world.log[1].step


def test_bad_worlds_and_actions(library: Library) -> None:
    with pytest.raises(SealError, match="two items"):
        World([Item("a", "apple", (0, 0)), Item("a", "pear", (1, 1))])
    with pytest.raises(SealError, match="not in the world"):
        World([Item("a", "apple", (0, 0), parent="nowhere")])
    world = kitchen(library)
    with pytest.raises(SealError, match="unknown primitive"):
        world.act("teleport", "apple_1")
    with pytest.raises(SealError, match="takes 1"):
        world.act("pick", "apple_1", "knife_1")
    assert not world.act("pick", "unicorn_1")
    assert not world.act("approach", "roger")  # no people in this world


def test_robot_may_start_holding(library: Library) -> None:
    world = kitchen(library, holding="knife_1")
    assert world.items["knife_1"].parent == HAND
    assert not world.act("pick", "pan_1")


def test_a_thing_is_put_in_what_is_hollow_and_on_what_is_not(library: Library) -> None:
    """The receptacle's kind decides the preposition: in a sink, a pan, an opened fridge or a wicker
    basket (a compound, by its head); on a counter."""
    world = kitchen(library)
    world.items["basket_1"] = Item("basket_1", "wicker_basket", (0.5, 0.5), movable=False, receptacle=True)
    goto(world, 0.0, 0.5)
    assert world.act("pick", "knife_1")
    said = []
    for target in ("sink_1", "counter_1", "pan_1", "basket_1"):
        said.append(world.act("place", "knife_1", target).message)
        assert world.act("pick", "knife_1")
    assert said == ["put knife_1 in sink_1", "put knife_1 on counter_1", "put knife_1 in pan_1",
                    "put knife_1 in basket_1"]
    goto(world, 2.0, 0.0)
    assert world.act("open", "fridge_1")
    assert world.act("place", "knife_1", "fridge_1").message == "put knife_1 in fridge_1"


def test_search_for_a_place_by_its_class_succeeds_at_the_place(library: Library) -> None:
    world = kitchen(library)
    goto(world, 6.0, 3.0)                       # far from the fridge and out of its reach
    far = world.act("search", "fridge")
    assert not far and "sees no fridge" in far.message
    goto(world, 2.0, 0.0)                       # at the fridge's stand cell
    found = world.act("search", "fridge")
    assert found and "fridge_1" in found.message
    assert world.act("search", "fridge_1")      # by its id, too


def test_a_thing_put_on_top_of_a_closed_place_stays_in_sight_and_reach(library: Library) -> None:
    """``place_on`` ("put the apple on the fridge"): a closed fridge takes it on its top, where the closing
    does not hide it; ``place`` (into it) is still refused while it is closed."""
    world = kitchen(library)
    world.items["pear_1"] = Item("pear_1", "pear", (2.1, 0.3))
    goto(world, 2.0, 0.0)
    assert world.act("pick", "pear_1")
    refused = world.act("place", "pear_1", "fridge_1")
    assert not refused and refused.message == "fridge_1 is closed" and world.robot.holding == "pear_1"
    put = world.act("place_on", "pear_1", "fridge_1")
    assert put and put.message == "put pear_1 on fridge_1" and not world.items["fridge_1"].is_open
    assert world.items["pear_1"].parent == "fridge_1" and world.items["pear_1"].on_top
    assert world.enclosure("pear_1") is None and world.enclosure("apple_1") == world.items["fridge_1"]
    assert "pear_1" in {d.id for d in world.observe()} and "apple_1" not in {d.id for d in world.observe()}
    assert world.act("pick", "pear_1") and not world.items["pear_1"].on_top     # taken off the top again
    assert world.act("open", "fridge_1")
    assert world.act("place", "pear_1", "fridge_1").message == "put pear_1 in fridge_1"
    assert not world.items["pear_1"].on_top and world.act("close", "fridge_1") and world.enclosure("pear_1")
