"""Where a thing is put: "put away the cup" where the map keeps cups, "take the cup to the kitchen" on the
kitchen's counter, not in its sink (seal_cli/planning/keeping.py, and its use by the planner and the robot)."""

from __future__ import annotations

import tempfile
from pathlib import Path

import numpy as np
import pytest

from seal_cli.errors import SealError
from seal_cli.frames.library import Library
from seal_cli.maps.formats.map_server import load_map
from seal_cli.maps.model import Map
from seal_cli.pipeline import plan as plan_text
from seal_cli.pipeline import run_on_map
from seal_cli.planning.keeping import Spot, kept_place, put_in_room, tier
from seal_cli.sim.policies import make_policy

MAPS = Path(__file__).resolve().parents[2] / "maps"


def steps(text: str, library: Library, house: str = "apartment") -> list[str]:
    return [str(s) for s in plan_text(text, library, map=load_map(MAPS / f"{house}.yaml")).steps]


def test_tiers_put_a_prior_first_then_tables_then_storage_then_seats_then_appliances(library: Library) -> None:
    taxonomy, prior = library.taxonomy, {"fridge": 0.4}
    kinds = {c: tier(taxonomy, prior, Spot(f"{c}_1", c, None, (0.0, 0.0)))
             for c in ("fridge", "counter", "kitchen_table", "medicine_cabinet", "sofa", "bunk_bed", "sink",
                       "bathroom_sink", "stove", "bathtub")}
    assert kinds == {"fridge": 0, "counter": 1, "kitchen_table": 1, "medicine_cabinet": 2, "sofa": 3, "bunk_bed": 3,
                     "sink": 4, "bathroom_sink": 4, "stove": 4, "bathtub": 4}


def test_put_away_never_puts_the_thing_back_where_it_lies_nor_in_an_appliance(library: Library) -> None:
    spots = [Spot("table_1", "table", "den", (0.0, 0.0)), Spot("sink_1", "sink", "kitchen", (1.0, 0.0)),
             Spot("shelf_1", "shelf", "den", (9.0, 0.0)), Spot("sofa_1", "sofa", "den", (0.5, 0.0)),
             Spot("cupboard_1", "cupboard", "kitchen", (12.0, 0.0))]
    priors = {"cup": {"den": 0.4, "kitchen": 0.6}}
    found = kept_place(library.taxonomy, priors, "cup", spots, lies="table_1", near=(0.0, 0.0))
    assert found is not None and found.name == "cupboard_1"    # more mass before a better tier; never the sink
    found = kept_place(library.taxonomy, priors, "cup", spots[:4], lies="table_1", near=(0.0, 0.0))
    assert found is not None and found.name == "table_1"       # the den is as likely as any room with storage
    assert kept_place(library.taxonomy, priors, "cup", spots[:4], lies="sofa_1", near=(0.0, 0.0)) == spots[0]
    assert kept_place(library.taxonomy, priors, "book", spots, lies=None, near=(0.0, 0.0)) is None   # no prior
    kept_there = {"cup": {"table_1": 1.0}}     # lies where the prior keeps it: put away already
    assert kept_place(library.taxonomy, kept_there, "cup", spots, lies="table_1", near=(0.0, 0.0)) == spots[0]
    seats = {"cup": {"den": 1.0}}               # the den has a sofa besides the table: never onto a seat
    assert kept_place(library.taxonomy, seats, "cup", spots[:2] + spots[3:4], lies="sofa_1", near=(0.0, 0.0)) == \
        spots[0]
    assert kept_place(library.taxonomy, seats, "cup", spots[1:2] + spots[3:4], lies="sofa_1", near=(0.0, 0.0)) is None


def test_a_room_goal_takes_the_rooms_place_for_such_a_thing_then_the_nearest(library: Library) -> None:
    spots = [Spot("sink_1", "sink", "kitchen", (0.0, 0.0)), Spot("counter_1", "counter", "kitchen", (3.0, 0.0)),
             Spot("fridge_1", "fridge", "kitchen", (5.0, 0.0))]
    near = {"sink_1": 1.0, "counter_1": 4.0, "fridge_1": 6.0}
    assert put_in_room(library.taxonomy, {}, "cup", spots, near).name == "counter_1"            # type: ignore[union-attr]
    apple = {"apple": {"fridge": 0.5}}
    assert put_in_room(library.taxonomy, apple, "apple", spots, near).name == "fridge_1"        # type: ignore[union-attr]
    assert put_in_room(library.taxonomy, {}, "cup", spots, {"sink_1": 1.0}).name == "sink_1"   # type: ignore[union-attr]
    assert put_in_room(library.taxonomy, {}, "cup", spots, {}) is None


def test_put_away_plans_a_goal_from_the_maps_priors_other_than_where_the_thing_lies(library: Library) -> None:
    # the apartment keeps cups in the family room or the bedroom, spoons in the kitchen or the bedroom: the cup on
    # the family room's coffee table and the spoon on the kitchen counter are put away already
    assert steps("put away the cup", library) == []
    assert steps("put the apple away", library) == []      # in the fridge, where apples are kept: put away already
    assert steps("store the spoon", library) == []
    assert steps("put down the cup", library)[-1] == "Place(theme=cup)"      # down, here: no goal to choose
    assert steps("put away the towel", library, "townhouse")[-1] == "Place(theme=towel, goal=medicine_cabinet_1)"
    tv = _moved(library, "{class: cup, at: [0.3, 3.6], in: coffee_table_1}", "{class: cup, at: [-4.9, -0.9], in: "
                "tv_stand_1}")
    assert [str(s) for s in plan_text("put away the cup", library, map=tv).steps] == \
        ["Pick(theme=cup, source=tv_stand_1)", "Place(theme=cup, goal=desk_1)"]   # the nearest of the likeliest
    with pytest.raises(SealError, match=r"cannot tell where to put away 'the book' \(book\): the apartment has no "
                                        r"prior of where a book is kept \(it knows where to keep apple, cup, spoon\)"):
        steps("put away the book", library)
    # the farmhouse keeps cups in the family room (a sofa) and the bedroom (the bed the cup is on): no table there,
    # so the parser's learned guess of where "put away" puts things stands
    assert steps("put away the cup", library, "farmhouse")[-1] == "Place(theme=cup, goal=dining_table_1)"


def test_there_with_no_place_before_it_is_refused_and_one_said_before_is_taken(library: Library) -> None:
    with pytest.raises(SealError, match=r"column 13: cannot tell where 'in there' is: no place before it in the "
                                        r"command says; name the place \(the apartment's places are fridge_1"):
        steps("put the cup in there", library)
    assert steps("go to the bedroom and put the cup in there", library)[-1] == "Place(theme=cup, goal=bedroom)"


@pytest.mark.parametrize(("house", "text", "put"), [
    ("apartment", "take the cup to the kitchen", "put cup_1 on counter_1"),
    ("townhouse", "take the towel to the bathroom", "put towel_1 in medicine_cabinet_1"),
])
def test_the_robot_puts_a_thing_brought_to_a_room_where_such_a_thing_goes(library: Library, house: str, text: str,
                                                                          put: str) -> None:
    agent, result = run_on_map(load_map(MAPS / f"{house}.yaml"), text, library, make_policy("oracle"),
                               rng=np.random.default_rng(0))
    assert result.completed and any(r.text == put for r in agent.records)


def test_put_away_leaves_a_thing_where_its_prior_keeps_it_in_the_plan_and_the_run(library: Library) -> None:
    office = load_map(MAPS / "office_floor.yaml")
    found = plan_text("put the stapler away", library, map=office)      # staplers are kept on desks: desk_1 is one
    assert found.steps == () and any("Place(theme=stapler, goal=desk_1) is not done" in w for w in found.warnings)
    agent, result = run_on_map(office, "put the stapler away", library, make_policy("sefm", 50),
                               rng=np.random.default_rng(0))
    assert result.completed and any("stapler_1 is on desk_1 already" in r.text for r in agent.records)
    assert result.executed == []


def _moved(library: Library, was: str, now: str, tmp: Path | None = None) -> Map:
    """The apartment with one of its things lying elsewhere."""
    text = (MAPS / "apartment.yaml").read_text().replace("image: apartment.pgm", f"image: {MAPS / 'apartment.pgm'}")
    moved = text.replace(was, now)
    assert moved != text
    folder = Path(tempfile.mkdtemp()) if tmp is None else tmp
    (folder / "moved.yaml").write_text(moved)
    return load_map(folder / "moved.yaml")


def test_the_robot_chooses_again_once_it_knows_where_the_thing_lay(library: Library, tmp_path: Path) -> None:
    """The run grounds "put away the cup" before the robot has seen it, on the likeliest place overall; once the
    robot knows where the cup lay it chooses again: a cup lying on the bedroom's desk (a room as likely as any)
    is put away already, in the plan and in the run; one on the living room's TV stand is put on the desk."""
    house = _moved(library, "{class: cup, at: [0.3, 3.6], in: coffee_table_1}",
                   "{class: cup, at: [-8.3, 1.4], in: desk_1}", tmp_path)
    assert plan_text("put away the cup", library, map=house).steps == ()
    agent, result = run_on_map(house, "put away the cup", library, make_policy("sefm", 50),
                               rng=np.random.default_rng(0))
    assert result.completed and any("cup_1 is on desk_1 already" in r.text for r in agent.records)
    assert agent.world.items["cup_1"].parent == "desk_1" and result.executed == []
    tv = _moved(library, "{class: cup, at: [0.3, 3.6], in: coffee_table_1}", "{class: cup, at: [-4.9, -0.9], in: "
                "tv_stand_1}")
    agent, result = run_on_map(tv, "put away the cup", library, make_policy("sefm", 50),
                               rng=np.random.default_rng(0))
    assert result.completed and agent.world.items["cup_1"].parent == "desk_1"
