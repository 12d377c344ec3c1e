"""The simulator is physical: reach is cut by walls; people take what is handed to them and follow when led."""

from __future__ import annotations

import numpy as np

from seal_cli.sim.world import PERSON, Item, Reason, Robot, World


class WallAtOne:
    """A sensor whose sight is cut by a wall along x = 1."""

    range = 5.0

    def line_of_sight(self, origin: object, points: object) -> np.ndarray:
        p = np.asarray(points, dtype=float).reshape(-1, 2)
        x0 = float(origin[0])                                            # type: ignore[index]
        return ~((np.minimum(x0, p[:, 0]) < 1.0) & (np.maximum(x0, p[:, 0]) > 1.0))

    def visible(self, pose: object, points: object) -> np.ndarray:
        return self.line_of_sight(pose, points)


def walled_world(robot_at: tuple[float, float]) -> World:
    """A wall along x = 1; an apple on a table at x = 1.6 (its reach 1 m); Anna at (0, 1)."""
    items = [Item("table_1", "table", (1.6, 0.0), movable=False, receptacle=True, reach=1.0),
             Item("apple_1", "apple", (1.6, 0.0), parent="table_1"),
             Item("anna", PERSON, (0.0, 1.0), movable=False)]
    return World(items, Robot(pose=(*robot_at, 0.0)), sensor=WallAtOne())  # type: ignore[arg-type]


def test_reach_is_cut_by_a_wall_and_refused_with_the_reason() -> None:
    world = walled_world((0.8, 0.0))                  # 0.8 m away, but behind the wall
    outcome = world.act("pick", "apple_1")
    assert not outcome.ok and outcome.reason is Reason.BEHIND_WALL and "behind a wall" in outcome.message
    assert world.robot.holding is None
    world = walled_world((2.3, 0.0))                  # 0.7 m away on the table's side
    assert world.act("pick", "apple_1").ok


def test_a_place_reach_is_its_own() -> None:
    world = walled_world((2.75, 0.0))                 # 1.15 m: beyond the table's 1 m, within the world's 1.5 m
    outcome = world.act("pick", "apple_1")
    assert outcome.reason is Reason.OUT_OF_REACH and "(1 m)" in outcome.message


def test_a_person_takes_what_is_handed_over_and_walks_along_when_led() -> None:
    world = walled_world((0.0, 0.5))
    world.items["cup_1"] = Item("cup_1", "cup", (0.0, 0.5), parent="@hand")
    world.robot.holding = "cup_1"
    assert world.act("hand_over", "cup_1", "anna").ok
    assert world.items["cup_1"].parent == "anna" and world.robot.holding is None
    assert world.act("hand_over", "cup_1", "anna").reason is Reason.NOT_HELD
    assert world.act("greet", "table_1").reason is Reason.WRONG_KIND
    assert world.act("lead", "anna", "kitchen").ok
    world.drive([(0.0, -3.0)])
    assert world.items["anna"].at == (0.0, -3.0)


def test_a_thing_handed_to_a_person_is_taken_back_within_reach_of_them() -> None:
    """"Bring me the mug and put it in the sink": what was handed over is taken back, and said so (e2e18)."""
    world = walled_world((0.0, 0.5))
    world.items["cup_1"] = Item("cup_1", "cup", (0.0, 0.5), parent="@hand")
    world.robot.holding = "cup_1"
    assert world.act("hand_over", "cup_1", "anna").ok
    taken = world.act("pick", "cup_1")
    assert taken.ok and taken.message == "took cup_1 back from anna" and world.robot.holding == "cup_1"
