"""SeFM's greedy search (``SeFMPolicy.greedy_view``): what a look reveals, the short tour, where to stand."""

from __future__ import annotations

import numpy as np
import pytest

from seal_cli.frames.library import Library
from seal_cli.maps.geometry import OccupancyGrid
from seal_cli.maps.model import Map, ObjectTruth, Place, Robot, Room, Sensor
from seal_cli.maps.navigation import Grid
from seal_cli.sensing.model import RangeSensor
from seal_cli.sim.agent import Agent, Scene, View
from seal_cli.sim.policies.object_only import ObjectOnlyPolicy
from seal_cli.sim.policies.sefm import Look, SeFMPolicy, above_floor
from seal_cli.sim.world import Item, World
from seal_cli.sim.world import Robot as WorldRobot

PLACES = [("shelf_1", "shelf", (1.0, 1.4), False), ("shelf_2", "shelf", (2.0, 1.4), False),
          ("microwave_1", "microwave", (4.0, 1.4), True), ("cabinet_1", "cabinet", (4.0, 1.3), True),
          ("cabinet_2", "cabinet", (7.0, 1.4), True), ("table_1", "dining_table", (7.5, 1.4), False)]


def corridor(library: Library, priors: dict[str, dict[str, float]], start: float = 0.0,
             apple_on: str = "cabinet_2", extra: tuple[Item, ...] = ()) -> Scene:
    """A corridor of free cells 8 m x 1 m (0.25 m), its places along the north side, the robot at the west."""
    pts = [(x, y) for x in np.arange(0.0, 8.01, 0.25) for y in np.arange(0.0, 1.01, 0.25)]
    items = [Item(n, c, at, movable=False, receptacle=True, openable=o) for n, c, at, o in PLACES]
    where = dict((n, at) for n, _, at, _ in PLACES)[apple_on]
    items.append(Item("apple_1", "apple", (where[0], where[1] - 0.1), parent=apple_on))
    items.extend(extra)
    world = World(items, WorldRobot(pose=(start, 0.5, 0.0)), taxonomy=library.taxonomy, reach=1.5,
                  sensor=RangeSensor(Sensor(range=1.5)))
    m = Map("corridor", (-0.5, -0.5, 8.5, 2.0), rooms=(Room.box("kitchen", -0.5, -0.5, 8.5, 2.0),),
            places=tuple(Place(n, c, at, openable=o, reach=0.75) for n, c, at, o in PLACES), priors=priors,
            objects=tuple(ObjectTruth(i.key, i.at, i.parent) for i in items if i.movable and i not in extra),
            robot=Robot((start, 0.5, 0.0)), sensor=Sensor(range=0.75), grid=OccupancyGrid.from_cells(pts, 0.25))
    return Scene(world, m, Grid.from_points(pts, 0.25, connectivity=4), tuple(sorted({i.key for i in items})),
                 "corridor")


def ready(library: Library, scene: Scene, policy: SeFMPolicy, frames: list[tuple[str, dict[str, str]]]) -> Agent:
    """An agent with its plan made and its first look taken, as the run leaves it before searching."""
    agent = Agent(scene, library, policy, rng=np.random.default_rng(0))
    agent.state = agent.initial_state()
    policy.begin(agent)
    agent.look()
    commanded = [library.frame(f).bind(v) for f, v in frames]
    agent.todo, agent.steps, agent.index = list(commanded), agent.planner(commanded, library, agent.state), 0
    return agent


def shares(policy: SeFMPolicy, agent: Agent) -> dict[str, float]:
    X, W, _ = policy.cloud(agent, "apple")
    places = policy._places(agent)
    return dict(zip([p.id for p in places], policy._shares(agent, places, X, above_floor(W), "apple"),
                    strict=True))


def test_a_belief_point_that_serves_several_places_is_shared_as_the_prior_shares_it(library: Library) -> None:
    """The microwave and a cabinet stand together: the microwave's 0.4 on its own cells outweighs the
    cabinets' 0.4, spread over two cabinets, where both claim the same cells."""
    scene = corridor(library, {"apple": {"microwave": 0.4, "cabinet": 0.4, "dining_table": 0.1}})
    policy = SeFMPolicy(particles=300)
    got = shares(policy, ready(library, scene, policy, [("Pick", {"theme": "apple"})]))
    # nearly the same cells: the microwave's density there is 0.4 / its cells, the cabinets' 0.4 / twice as many
    assert got["microwave_1"] / got["cabinet_1"] == pytest.approx(2.0, rel=0.15)
    assert got["microwave_1"] + got["cabinet_1"] + got["cabinet_2"] + got["table_1"] <= 1.0 + 1e-9
    assert got["shelf_1"] == pytest.approx(0.0, abs=0.02)   # the prior puts nothing there


def test_a_look_reveals_every_open_place_within_reach_of_its_cell(library: Library) -> None:
    scene = corridor(library, {"apple": {"shelf": 0.8}}, start=5.0)
    policy = SeFMPolicy(particles=300)
    agent = ready(library, scene, policy, [("Pick", {"theme": "apple"})])
    X, W, _ = policy.cloud(agent, "apple")
    looks = policy._looks(agent, "apple", X, above_floor(W), agent.distances())
    ids = [p.id for p in policy._places(agent)]
    both = [o for o in looks if o.reveals is not None and o.reveals[ids.index("shelf_1")] > 0
            and o.reveals[ids.index("shelf_2")] > 0]
    one = [o for o in looks if o.reveals is not None and o.reveals[ids.index("shelf_2")] == 0]
    assert both and one
    assert max(o.mass for o in both) == pytest.approx(sum(shares(policy, agent)[s] for s in ("shelf_1", "shelf_2")))
    assert max(o.mass for o in both) > max(o.mass for o in one) + 0.2
    assert all(o.view.open is None for o in both)            # shelves do not open


def test_a_shut_place_in_reach_is_opened_by_the_look(library: Library) -> None:
    scene = corridor(library, {"apple": {"microwave": 0.9}}, start=4.0)
    policy = SeFMPolicy(particles=300)
    agent = ready(library, scene, policy, [("Pick", {"theme": "apple"})])
    view = policy.greedy_view(agent, agent.steps[0], "apple")
    assert view is not None and view.open == "microwave_1"
    assert view.cell == agent.robot_cell()                    # it is in reach already: no drive
    assert "opens microwave_1" in view.why


def test_a_look_reveals_every_shut_place_within_reach_not_only_the_heaviest(library: Library) -> None:
    """The microwave and a cabinet stand together: a look from beside them opens both, one after the
    other, with no drive between, so it is worth both shares; with ``open_all`` off, the heavier alone."""
    priors = {"apple": {"microwave": 0.45, "cabinet": 0.45}}
    masses = {}
    for open_all in (True, False):
        policy = SeFMPolicy(particles=300)
        policy.open_all = open_all
        agent = ready(library, corridor(library, priors, start=4.0), policy, [("Pick", {"theme": "apple"})])
        X, W, _ = policy.cloud(agent, "apple")
        here = [o for o in policy._looks(agent, "apple", X, above_floor(W), agent.distances())
                if o.view.cell == agent.robot_cell()]
        assert len(here) == 1 and here[0].view.open == "microwave_1"   # the heavier is opened first
        got = shares(policy, agent)
        masses[open_all] = (here[0].mass, got["microwave_1"], got["cabinet_1"])
    mass, microwave, cabinet = masses[True]
    assert cabinet > 0.05 and mass == pytest.approx(microwave + cabinet)
    mass, microwave, cabinet = masses[False]
    assert mass == pytest.approx(max(microwave, cabinet))


def test_the_tour_goes_to_a_near_likely_place_before_a_better_one_that_leads_away(library: Library) -> None:
    """Greedy by belief per metre goes east to the 0.3 first and leaves the 0.15 at the robot's back,
    to be driven back to; the expected cost of the whole order says take the near one on the way."""
    scene = corridor(library, {"apple": {"shelf": 0.8}}, start=3.0)
    policy = SeFMPolicy(particles=50)
    agent = ready(library, scene, policy, [("Pick", {"theme": "apple"})])
    places = policy._places(agent)
    ids = [p.id for p in places]

    def look(x: float, mass: float, place: str) -> Look:
        reveals = np.zeros(len(places))
        reveals[ids.index(place)] = mass
        cell = agent.grid.cell((x, 0.5))
        return Look(mass, float(agent.distances()[cell]), View(cell, (x, 1.4)), reveals)

    near, east, far = look(2.0, 0.15, "shelf_2"), look(4.5, 0.3, "microwave_1"), look(6.0, 0.3, "cabinet_2")
    greedy = max([near, east, far], key=lambda o: o.mass / (o.metres + policy.distance_scale))
    assert greedy is east
    assert policy._first_of_tour(agent, [near, east, far], "apple") == near.view
    policy.tour_views = 1
    assert policy._first_of_tour(agent, [near, east, far], "apple") == east.view


def test_the_stand_cell_is_the_one_nearest_the_next_known_stop(library: Library) -> None:
    """The apple is known (seen from afar); the table it goes on is known: of the cells within reach of
    the apple, the one that makes the drive there and on to the table shortest."""
    scene = corridor(library, {"apple": {"shelf": 0.9}}, start=5.0, apple_on="shelf_1")
    policy = SeFMPolicy(particles=50)
    agent = ready(library, scene, policy, [("Place", {"theme": "apple", "goal": "dining_table"})])
    agent.known["apple_1"] = agent._known(scene.world.items["apple_1"])
    apple = agent.known["apple_1"]
    cell = policy.stand(agent, apple)
    here, table = agent.distances(), agent.stand_cells(agent.known["table_1"])
    cells = agent.stand_cells(apple)
    total = [here[tuple(c)] + agent.grid.distances((int(c[0]), int(c[1])))[table[:, 0], table[:, 1]].min()
             for c in cells]
    assert cell is not None and here[cell] + agent.grid.distances(cell)[table[:, 0], table[:, 1]].min() == \
        pytest.approx(min(total))
    policy.stand_ahead = 0
    assert policy.stand(agent, apple) == agent.stand_cell(apple)


def test_once_every_place_is_looked_at_it_searches_the_frontier_not_the_spent_modes(library: Library) -> None:
    scene = corridor(library, {"apple": {"shelf": 0.8}})
    policy = SeFMPolicy(particles=100)
    agent = ready(library, scene, policy, [("Pick", {"theme": "apple"})])
    agent.inspected |= {p.id for p in policy._places(agent)}
    view = policy.greedy_view(agent, agent.steps[0], "apple")
    assert view is not None and view.why.endswith("(the belief is spent)")


def test_with_no_context_sefm_and_object_only_look_the_same(library: Library) -> None:
    """The first Pick's frame belief is its object's belief plus the frame potential's floor: with the
    floor off, the two searches see the same numbers and choose the same look."""
    priors = {"apple": {"microwave": 0.4, "cabinet": 0.4, "shelf": 0.1}}
    views = []
    for policy in (SeFMPolicy(particles=200), ObjectOnlyPolicy(particles=200)):
        agent = ready(library, corridor(library, priors), policy, [("Pick", {"theme": "apple"})])
        X, W, _ = policy.cloud(agent, "apple")
        views.append((policy.greedy_view(agent, agent.steps[0], "apple"), above_floor(W)))
    assert views[0][0] == views[1][0]
    assert np.abs(views[0][1] - views[1][1]).max() < 1e-6


def test_above_floor_takes_off_the_least_value_and_renormalises() -> None:
    assert above_floor(np.array([0.1, 0.3, 0.5])) == pytest.approx([0.0, 1 / 3, 2 / 3])
    assert above_floor(np.full(4, 0.25)) == pytest.approx([0.25] * 4)    # nothing above the floor: as it was


def test_once_every_place_is_looked_at_a_room_level_prior_still_leads_to_its_modes(library: Library) -> None:
    """In a house the prior names rooms: the thing may stand anywhere in the room, not at a place, so
    the belief's modes stay the places to look (the frontier there is blind to the prior)."""
    scene = corridor(library, {"apple": {"kitchen": 0.8}})
    policy = SeFMPolicy(particles=100)
    agent = ready(library, scene, policy, [("Pick", {"theme": "apple"})])
    agent.inspected |= {p.id for p in policy._places(agent)}
    view = policy.greedy_view(agent, agent.steps[0], "apple")
    assert view is not None and view.why == "goes to the belief's best mode"


def test_the_drive_on_is_metres_to_the_nearest_cell_to_act_on_the_next_stop_from(library: Library) -> None:
    scene = corridor(library, {"apple": {"shelf": 0.9}}, start=3.0)
    policy = SeFMPolicy(particles=100)
    agent = ready(library, scene, policy, [("Place", {"theme": "apple", "goal": "dining_table"})])
    field_ = policy._onward_field(agent, agent.known["table_1"])
    along = [float(field_[agent.grid.cell((x, 0.5))]) for x in (0.0, 2.0, 4.0, 6.0, 7.5)]
    assert along == sorted(along, reverse=True) and along[-1] == 0.0   # the table is acted on from 7.5
    assert along[0] - along[2] == pytest.approx(4.0)                    # 4 m of corridor, 0.25 m steps
    assert policy._onward_field(agent, agent.known["table_1"]) is field_   # kept for the run


def test_an_unknown_next_stop_is_expected_where_its_belief_is(library: Library) -> None:
    """Place(apple, bowl) with no bowl seen: the drive on from a cell is its expected drive to the bowl's
    belief (by the prior, at the cabinets at 4 m and 7 m), shortest between them, longest at the far west."""
    scene = corridor(library, {"apple": {"shelf": 0.9}, "bowl": {"cabinet": 0.9}}, start=3.0)
    policy = SeFMPolicy(particles=300)
    agent = ready(library, scene, policy, [("Place", {"theme": "apple", "goal": "bowl"})])
    policy._beliefs(agent)
    field_ = policy._onward_belief(agent, "apple")
    assert field_ is not None
    on = {x: float(field_[agent.grid.cell((x, 0.5))]) for x in (0.0, 2.0, 5.0, 8.0)}
    assert on[5.0] < on[8.0] < on[2.0] < on[0.0]
    assert on[0.0] - on[2.0] == pytest.approx(2.0, abs=0.05)           # every point of the belief is east of both
    alone = SeFMPolicy(particles=100)
    picking = ready(library, scene, alone, [("Pick", {"theme": "apple"})])
    alone._beliefs(picking)
    assert alone._onward_belief(picking, "apple") is None                # nothing comes after the apple


def test_sefm_finds_the_thing_from_the_look_nearer_the_next_stop(library: Library) -> None:
    """Two cells see the same cabinet, the west one nearer the robot, the east one nearer the table the
    apple goes to. Object-only takes the nearer; SeFM, whose expected cost adds the drive on from where
    the apple would be found, takes the one that leaves less to drive on; with ``onward = 0`` it is
    object-only again."""
    scene = corridor(library, {"apple": {"cabinet": 0.8}}, start=3.75)
    frames = [("Place", {"theme": "apple", "goal": "dining_table"})]

    def first(policy: SeFMPolicy) -> tuple[float, float]:
        agent = ready(library, scene, policy, frames)
        places = policy._places(agent)
        reveals = np.zeros(len(places))
        reveals[[p.id for p in places].index("cabinet_1")] = 0.6

        def look(x: float) -> Look:
            cell = agent.grid.cell((x, 0.5))
            return Look(0.6, float(agent.distances()[cell]), View(cell, (4.0, 1.3), open="cabinet_1"), reveals)

        return agent.grid.point(policy._first_of_tour(agent, [look(3.25), look(4.75)], "apple").cell)

    plain = SeFMPolicy(particles=50)
    plain.onward = 0.0
    assert first(ObjectOnlyPolicy(particles=50)) == first(plain) == (3.25, 0.5)
    assert first(SeFMPolicy(particles=50)) == (4.75, 0.5)   # 0.6 of the belief, 1.5 m less on: 0.4 m expected
    deferring = SeFMPolicy(particles=50)
    deferring.defer_m = 0.5    # more than SeFM's expected saving: object-only's look
    assert first(deferring) == (3.25, 0.5)


def test_the_floor_share_is_bayes_over_what_is_still_unseen(library: Library) -> None:
    """f on the floor, 1 - f on the places: unseen, the floor keeps f·u (u: the floor not yet in sight) and
    the places (1 - f)·r (r: the prior share of the places not looked at); below floor_min, nothing."""
    from dataclasses import replace

    scene = replace(corridor(library, {"apple": {"shelf": 0.5, "cabinet": 0.5}}), open_floor={"apple": 0.4})
    policy = SeFMPolicy(particles=100)
    agent = ready(library, scene, policy, [("Pick", {"theme": "apple"})])
    X = policy.map.free_centres
    agent.inspected.clear()   # no place looked at yet: r = 1
    u = float(np.mean(~policy.fallback.seen))
    assert 0.0 < u < 1.0
    assert policy.floor_share(agent, "apple", X) == pytest.approx(0.4 * u / (0.4 * u + 0.6))
    agent.inspected |= {p.id for p in policy._places(agent)}
    assert policy.floor_share(agent, "apple", X) == pytest.approx(1.0)
    policy.floor_min = 0.5
    assert policy.floor_share(agent, "apple", X) == 0.0


def test_with_the_places_spent_a_thing_often_on_the_floor_is_looked_for_over_the_floor(library: Library) -> None:
    from dataclasses import replace

    scene = replace(corridor(library, {"apple": {"shelf": 0.8}}), open_floor={"apple": 0.4})
    policy = SeFMPolicy(particles=100)
    agent = ready(library, scene, policy, [("Pick", {"theme": "apple"})])
    agent.inspected |= {p.id for p in policy._places(agent)}
    view = policy.greedy_view(agent, agent.steps[0], "apple")
    assert view is not None and "open floor (1.00 of the belief" in view.why
    x, y = agent.grid.point(view.cell)
    assert policy.fallback.seen.size and not policy.fallback.seen[
        np.hypot(policy.fallback.lattice[:, 0] - x, policy.fallback.lattice[:, 1] - y) <= 1.5].all()


def test_the_drive_stops_to_choose_again_when_what_it_saw_makes_another_view_better(library: Library) -> None:
    # the cottage, layout 0, from the hall's north end, "stir the mug": the drive to the dining room (for the
    # spoon) sees the mug a metre in; with the mug known the bedroom (spoons) is better than the dining room
    # by more than rethink_m, so the drive stops and turns there; driving on costs 1.6 m more
    import dataclasses

    from seal_cli.bench.houses import cottage
    from seal_cli.bench.mapsuite import sample_layout
    from seal_cli.pipeline import run_on_map
    from seal_cli.sim.policies import make_policy

    world = dataclasses.replace(sample_layout(cottage(), np.random.default_rng(0)), robot=Robot((7.5, 9.0, 0.0)))
    paths = {}
    for rethink in (1.0, float("inf")):
        policy = make_policy("sefm", 100)
        policy.rethink_m = rethink  # type: ignore[attr-defined]
        # as traced, with the filter expecting a miss in ten; with the world's detector (search23) the first
        # choice is the turn's already, and the run is 24.70 m with no stop
        policy.world_detector = False  # type: ignore[attr-defined]
        agent, result = run_on_map(world, "stir the mug", library, policy, rng=np.random.default_rng(1))
        assert result.completed, result.reason
        stops = [r.text for r in agent.records if r.kind == "go" and "what it saw makes" in r.text]
        assert bool(stops) == (rethink == 1.0), stops
        paths[rethink] = agent.world.robot.path_m
        if stops:
            later = [r.text for r in agent.records if r.kind == "search"]
            # the new choice lies west, towards the bedroom: the bedroom's view (before search20) or, with the looks
            # SeFM will not count worth nothing, the hall's view on the way there (the same path)
            assert any(f"makes {room} better" in stops[0] for room in ("bedroom", "living_room")), stops
            assert any(t.startswith("looks for spoon: bedroom") for t in later)
    assert paths[1.0] < paths[float("inf")] - 1.0, paths


def test_driving_on_is_worth_the_best_look_on_the_way_not_only_the_view(library: Library) -> None:
    # the held-out farmhouse, layout 1, from the family room's east end, "stir the cup": the drive to the bedroom's
    # view sees the cup 4 m in; with the cup known, the kitchen (the spoon's other room) beats driving on to the
    # bedroom's view by 1.4 m, but not stopping at the next look on the way (0.8 m, under rethink_m), which is
    # where the spoon lies in sight: the drive goes on and finds it; valued by the view alone it turned back
    import dataclasses

    from seal_cli.bench import context
    from seal_cli.bench.mapsuite import sample_layout
    from seal_cli.pipeline import run_on_map
    from seal_cli.sim.policies import make_policy

    house = next(h for h in context.unseen_houses() if h.map.name == "farmhouse")
    drawn = sample_layout(house.map, np.random.default_rng(context.layout_seed(0, 1, "farmhouse")))
    world = dataclasses.replace(drawn, robot=Robot(house.starts[2]))
    paths = {}
    for on_way in (True, False):
        policy = make_policy("sefm", 200)
        policy.on_the_way = on_way  # type: ignore[attr-defined]
        policy.world_detector = False  # type: ignore[attr-defined]   # the filter expecting a miss in ten, as traced
        agent, result = run_on_map(world, "stir the cup", library, policy, rng=np.random.default_rng(1),
                                   search_end=None)
        assert result.completed, result.reason
        turned = [r.text for r in agent.records if r.kind == "go" and "what it saw makes kitchen better" in r.text]
        assert bool(turned) == (not on_way), turned
        paths[on_way] = agent.world.robot.path_m
    assert paths[True] < 10.0 < 30.0 < paths[False], paths


def test_the_looks_ahead_are_the_rest_of_the_drive_s_looks_added_among_the_candidates(library: Library) -> None:
    from seal_cli.sim.policies.whole_plan import WholePlanSearch

    scene = corridor(library, {"apple": {"kitchen": 1.0}})
    agent = ready(library, scene, SeFMPolicy(particles=50), [("Pick", {"theme": "apple"})])
    search = WholePlanSearch(agent)
    before = len(search.candidates)
    view = View(agent.grid.cell((7.0, 0.5)), (7.0, 0.5))
    cells = search.ahead(agent, view)
    xs = [agent.grid.point(c)[0] for c in cells]
    assert len(cells) >= 5 and xs == sorted(xs) and 0.5 <= xs[0] <= 1.5 and xs[-1] < 7.0, xs   # a look a metre
    assert view.cell not in cells and len(search.candidates) == before + len(cells)
    assert search.ahead(agent, view) == cells and len(search.candidates) == before + len(cells)   # added once


def test_a_further_instance_is_looked_for_by_the_prior_not_by_the_found_ones_belief(library: Library) -> None:
    """The first apple seen on the table and put in place: the filter's one belief of the class is where
    that apple was (the shelves keep under 0.05 of it), and cutting it out cut the cabinet beside the
    table too. A second apple is looked for by the prior over the places not looked at: the shelves and
    cabinets a quarter each, so the first look opens the cabinet half a metre off."""
    scene = corridor(library, {"apple": {"shelf": 0.5, "cabinet": 0.5}}, start=6.5, apple_on="table_1")
    views = {}
    for further in (True, False):
        policy = SeFMPolicy(particles=200)
        policy.further_prior = further
        agent = Agent(scene, library, policy, rng=np.random.default_rng(0), classes={"apple_2": "apple"})
        agent.state = agent.initial_state()
        policy.begin(agent)
        agent.look()
        assert "apple_1" in agent.known
        agent.placed.add("apple_1")
        commanded = [library.frame("Pick").bind({"theme": "apple_2"})]
        agent.todo, agent.steps, agent.index = list(commanded), agent.planner(commanded, library, agent.state), 0
        assert policy.further(agent, "apple_2")
        X, W, _ = policy.cloud(agent, "apple_2")
        places = policy._places(agent)
        ids = [p.id for p in places]
        filtered = policy._shares(agent, places, X, above_floor(W), "apple")
        assert filtered[ids.index("shelf_1")] + filtered[ids.index("shelf_2")] < 0.05
        prior = dict(zip(ids, policy._shares(agent, places, X, policy.further_belief(agent, X, "apple"), "apple"),
                         strict=True))
        assert prior["shelf_1"] == pytest.approx(0.25, abs=0.02) and prior["shelf_2"] == pytest.approx(0.25, abs=0.02)
        assert prior["cabinet_1"] + prior["cabinet_2"] == pytest.approx(0.5, abs=0.02)
        views[further] = policy.greedy_view(agent, agent.steps[0], "apple_2")
    assert views[True] is not None and views[True].open == "cabinet_2"
    assert views[False] is not None and views[False].open != "cabinet_2"


def test_a_known_stop_beside_unlikely_looks_does_not_draw_sefm_away_from_the_likelier_look(
        library: Library) -> None:
    """Nine looks, each revealing a place of its own, the table the apple goes to known at the east end,
    two unlikely looks beside it (0.1 and 0.02). Whichever look finds the apple, the drive on is paid once
    from there, so it adds the same to every order: SeFM's looks are object-only's and so is its first
    look (3.5 m, 0.1 of the belief half a metre off, on the way to the 0.47). The rule of earlier rounds
    (looks drawn by belief per metre there *and on*, the best first look whatever the margin) put the
    looks beside the table into the tour and led the robot off towards them."""
    scene = corridor(library, {"apple": {"shelf": 0.8}}, start=3.0)
    frames = [("Place", {"theme": "apple", "goal": "dining_table"})]
    spots = [(0.25, 0.15), (1.25, 0.02), (2.75, 0.01), (3.0, 0.01), (3.25, 0.01), (3.5, 0.1), (5.0, 0.47),
             (6.0, 0.1), (6.75, 0.02)]

    def first(policy: SeFMPolicy) -> tuple[float, float]:
        agent = ready(library, scene, policy, frames)
        width = len(policy._places(agent))
        looks = []
        for k, (x, mass) in enumerate(spots):
            reveals = np.zeros(width + len(spots))
            reveals[width + k] = mass
            cell = agent.grid.cell((x, 0.5))
            looks.append(Look(mass, float(agent.distances()[cell]), View(cell, (x, 1.4)), reveals))
        return agent.grid.point(policy._first_of_tour(agent, looks, "apple").cell)

    assert first(SeFMPolicy(particles=50)) == first(ObjectOnlyPolicy(particles=50)) == (3.5, 0.5)
    earlier = SeFMPolicy(particles=50)
    earlier.onward_pool, earlier.defer_m = True, None
    assert first(earlier) != (3.5, 0.5)


def test_sefm_leaves_object_only_s_look_only_for_what_the_frame_s_context_adds(library: Library) -> None:
    """Three shelves' looks west and east of the robot (3 m): object-only takes the one a metre west. Counting what
    the drive sees on the way, the look 2.5 m west is better (the drive passes the first shelf): a gap in the
    thing's own search, which object-only's rule does not weigh. With the drive on the same from every cell (a
    stop the frame gives no reason to prefer a side for), the frame's share of that gap is nil, so SeFM keeps
    object-only's look; the rule off (earlier rounds), the whole gap made it depart."""

    class Flat(SeFMPolicy):
        def _onward_field(self, agent: Agent, *stops: object) -> np.ndarray:
            return np.full(agent.grid.shape, 2.0)

    scene = corridor(library, {"apple": {"shelf": 0.4, "cabinet": 0.4}}, start=3.0)

    def first(policy: SeFMPolicy) -> tuple[float, float]:
        agent = ready(library, scene, policy, [("Place", {"theme": "apple", "goal": "dining_table"})])
        places = policy._places(agent)
        ids = [p.id for p in places]

        def look(x: float, place: str) -> Look:
            reveals = np.zeros(len(places))
            reveals[ids.index(place)] = 0.3
            cell = agent.grid.cell((x, 0.5))
            return Look(0.3, float(agent.distances()[cell]), View(cell, (x, 1.4)), reveals)

        looks = [look(2.0, "shelf_2"), look(0.5, "shelf_1"), look(7.0, "cabinet_2")]
        return agent.grid.point(policy._first_of_tour(agent, looks, "apple").cell)

    flat = Flat(particles=50)
    assert first(ObjectOnlyPolicy(particles=50)) == first(flat) == (2.0, 0.5)
    assert flat.departures[-1]["gap"] > flat.defer_m and flat.departures[-1]["context"] == pytest.approx(0.0)
    whole_gap = Flat(particles=50)
    whole_gap.by_context_in_room = False
    assert first(whole_gap) == (0.5, 0.5)


def test_a_look_chosen_with_the_next_stop_unseen_is_chosen_again_when_the_drive_sees_it(library: Library) -> None:
    """Place(apple, bowl): a look for the apple chosen while no bowl was seen (its drive on counted from the bowl's
    belief) is weighed again once the drive brings a bowl into sight: SeFM's expected cost of finishing from here
    with another first look against driving on to that one; the drive stops when the other is better by more than
    ``defer_m``. A look still as good is driven on to; object-only, and the rule switched off, drive on."""
    priors = {"apple": {"shelf": 0.45, "dining_table": 0.45}, "bowl": {"dining_table": 0.9}}
    frames = [("Place", {"theme": "apple", "goal": "bowl"})]

    def stops(policy: SeFMPolicy, x: float | None) -> str | None:
        scene = corridor(library, priors, start=3.0, apple_on="shelf_1", extra=(Item("bowl_1", "bowl", (5.25, 1.0)),))
        agent = ready(library, scene, policy, frames)
        assert "bowl_1" not in agent.known
        policy.greedy_view(agent, agent.steps[0], "apple")       # chosen with the bowl unseen
        agent.world.robot.pose = (4.0, 0.5, 0.0)                 # a metre into the drive the bowl comes into sight
        agent.look()
        assert "bowl_1" in agent.known
        if x is None:   # driving to the look SeFM would choose from here anyway
            view = policy._first_of_tour(agent, policy._fresh(agent, "apple"), "apple")
        else:
            view = View(agent.grid.cell((x, 0.5)), (1.0, 1.4), why="the look driven to")
        return policy.reconsider(agent, agent.steps[0], "apple", view)

    assert (why := stops(SeFMPolicy(particles=300), 0.0)) is not None and "next stop" in why   # 4 m west: not now
    assert stops(SeFMPolicy(particles=300), None) is None
    off = SeFMPolicy(particles=300)
    off.reconsider_in_room = False
    assert stops(off, 0.0) is None
    assert stops(ObjectOnlyPolicy(particles=300), 0.0) is None


def test_the_tour_model_s_outcomes_average_to_its_expected_cost() -> None:
    """Per column, the mass a look first reveals and the metres the order costs if the thing is there (the
    drives to that look, a look's cost each, and the drive on); what no look reveals costs the whole tour. Their
    mean is the model's E."""
    from seal_cli.sim.policies.sefm import _TourModel

    R = np.array([[0.3, 0.2, 0.0], [0.0, 0.2, 0.4]])
    model = _TourModel(np.array([1.0, 3.0]), np.array([[0.0, 2.5], [2.5, 0.0]]), R, np.array([1.0, 2.0]), 0.1)
    for order in ([0, 1], [1, 0]):
        mass, metres = model.outcomes(order)
        assert mass.sum() == pytest.approx(1.0)
        assert float(mass @ metres) == pytest.approx(model.cost(order))
    mass, metres = model.outcomes([0, 1])
    assert metres.tolist() == pytest.approx([1.1 + 1.0, 1.1 + 1.0, 1.1 + 2.6 + 2.0, 3.7])


def test_a_drive_that_passes_a_place_within_reach_reveals_it_on_the_way(library: Library) -> None:
    """The robot looks every metre of a drive and sees onto every open place within reach: the drive from the
    west end to the cabinet at the east passes both shelves, and a thing on the first is found 1 m into it, not
    after the 7 m the model of earlier rounds charged (the look at the end). So the tour that drives east first is
    cheaper with the looks on the way counted, and a tour's order is weighed with them."""
    from dataclasses import replace

    scene = corridor(library, {"apple": {"shelf": 0.4, "cabinet": 0.4}})
    policy = SeFMPolicy(particles=50)
    agent = ready(library, scene, policy, [("Place", {"theme": "apple", "goal": "dining_table"})])
    places = policy._places(agent)
    ids = [p.id for p in places]

    def look(x: float, place: str, mass: float) -> Look:
        reveals = np.zeros(len(places))
        reveals[ids.index(place)] = mass
        cell = agent.grid.cell((x, 0.5))
        return Look(mass, float(agent.distances()[cell]), View(cell, (x, 1.4)), reveals)

    best = [look(1.0, "shelf_1", 0.4), look(7.0, "cabinet_2", 0.4)]
    fields = {o.view.cell: agent.grid.distances(o.view.cell) for o in best}
    then = policy._onward_field(agent, agent.known["table_1"])
    plain = policy._tour_model(best, fields, then)
    seeing = policy._on_the_way(agent, best, plain, then)
    assert seeing.way is not None and (-1, 1) in seeing.way
    at, cols, _ = seeing.way[(-1, 1)][0]
    assert at == pytest.approx(1.0) and cols[ids.index("shelf_1")]
    mass, metres = seeing.outcomes([1, 0])
    assert metres[ids.index("shelf_1")] < 7.0 < replace(seeing, way=None).outcomes([1, 0])[1][ids.index("shelf_1")]
    assert seeing.cost([1, 0]) < plain.cost([1, 0])


def test_the_beliefs_take_only_the_looks_the_robot_made(library: Library) -> None:
    # brought up to the robot's state before a choice, the beliefs must not count a look from where the robot
    # has driven without looking (to a thing it had seen): what is in view there was never looked for
    scene = corridor(library, {"apple": {"shelf": 0.5, "dining_table": 0.5}})
    policy = SeFMPolicy()
    agent = ready(library, scene, policy, [("Pick", {"theme": "apple"})])
    sefm = policy._beliefs(agent)
    row = sefm.objects.row("apple")
    X, W = sefm.objects.X[row].copy(), sefm.objects.W[row].copy()
    agent.world.robot.pose = (7.5, 0.5, 0.0)   # beside the dining table, not looked from
    policy._restate(agent)
    assert np.array_equal(sefm.objects.X[row], X) and np.allclose(sefm.objects.W[row], W, rtol=1e-9, atol=0)
    near = np.hypot(X[:, 0] - 7.5, X[:, 1] - 0.5) <= 0.75
    assert W[near].sum() > 0.2
    sefm.update(agent.world.robot.pose, (), policy._state(agent))   # what a look there with nothing seen does
    after = np.hypot(sefm.objects.X[row][:, 0] - 7.5, sefm.objects.X[row][:, 1] - 0.5) <= 0.75
    assert sefm.objects.W[row][after].sum() < 0.7 * W[near].sum()


def table_room(library: Library) -> Scene:
    """A corridor 8 m x 1 m (0.25 m cells) with a long dining table north of its west end (pivot 1.2 m from the
    nearest free cell, so a look from its near side does not reach its far end), a small shelf by the table's
    east corner and a cabinet at the east end; an apple on the table, the robot in the middle."""
    pts = [(x, y) for x in np.arange(0.0, 8.01, 0.25) for y in np.arange(0.0, 1.01, 0.25)]
    places = [("table_1", "dining_table", (1.5, 2.2), False), ("shelf_1", "shelf", (2.5, 1.3), False),
              ("cabinet_1", "cabinet", (7.5, 1.4), True)]
    items = [Item(n, c, at, movable=False, receptacle=True, openable=o) for n, c, at, o in places]
    items.append(Item("apple_1", "apple", (0.6, 2.4), parent="table_1"))
    world = World(items, WorldRobot(pose=(4.0, 0.5, 0.0)), taxonomy=library.taxonomy, reach=1.5,
                  sensor=RangeSensor(Sensor(range=1.5)))
    m = Map("table room", (-0.5, -0.5, 8.5, 3.5), rooms=(Room.box("kitchen", -0.5, -0.5, 8.5, 3.5),),
            places=tuple(Place(n, c, at, openable=o, reach=1.5) for n, c, at, o in places),
            priors={"apple": {"dining_table": 0.45, "shelf": 0.45}},
            objects=(ObjectTruth("apple", (0.6, 2.4), "table_1"),), robot=Robot((4.0, 0.5, 0.0)),
            sensor=Sensor(range=1.5), grid=OccupancyGrid.from_cells(pts, 0.25))
    return Scene(world, m, Grid.from_points(pts, 0.25, connectivity=4), tuple(sorted({i.key for i in items})),
                 "table room")


def test_the_drive_on_is_counted_from_where_the_thing_found_is_acted_on(library: Library) -> None:
    """A look at the long table from its east end (nearer the cabinet the apple goes to) does not reach the
    table's west end: an apple found there is picked up from a cell further west, and the drive on starts
    there. The model counts, per place a look reveals, the mean over where on it the thing may lie of the drive
    to the cell that reaches it and on from there; a place the look reaches all of (the shelf) keeps the drive on
    from the look; from the look that reaches all the table, too. Off (``acted_on``), the drive on from the look."""
    policy = SeFMPolicy(particles=50)
    agent = ready(library, table_room(library), policy, [("Place", {"theme": "apple", "goal": "cabinet"})])
    ids = [p.id for p in policy._places(agent)]
    then = policy._onward_field(agent, agent.known["cabinet_1"])
    east, west = agent.grid.cell((2.25, 1.0)), agent.grid.cell((1.0, 1.0))
    assert then[west] - then[east] == pytest.approx(1.25)   # the east end is 1.25 m nearer the cabinet

    def look(cell: tuple[int, int], masses: dict[str, float]) -> Look:
        reveals = np.zeros(len(ids))
        for place, mass in masses.items():
            reveals[ids.index(place)] = mass
        return Look(float(reveals.sum()), float(agent.distances()[cell]), View(cell, (1.5, 2.2)), reveals)

    best = [look(east, {"table_1": 0.45, "shelf_1": 0.45}), look(west, {"table_1": 0.45})]
    fields = {o.view.cell: agent.grid.distances(o.view.cell) for o in best}
    model = policy._tour_model(best, fields, then, agent)
    table, shelf = ids.index("table_1"), ids.index("shelf_1")
    assert model.acted is not None
    assert model.acted[0, shelf] == pytest.approx(then[east])            # the look reaches all the shelf
    # the table's west end is out of reach from the east look: some of the points are picked up further west
    assert model.acted[0, table] > then[east] + 0.2
    # by the geometry: the far points need a drive west and the same drive back
    assert model.acted[0, table] - then[east] < then[west] - then[east] + 1.0
    # each point's cost is the drive to a cell that reaches it and on from there: never below the look's own
    assert model.acted[1, table] >= then[west] - 1e-9
    # the expected cost of finding it at the table from the east look now counts that drive
    from dataclasses import replace

    plain = replace(model, acted=None)
    assert model.cost([0, 1]) > plain.cost([0, 1])
    off = SeFMPolicy(particles=50)
    off.acted_on = False
    agent_off = ready(library, table_room(library), off, [("Place", {"theme": "apple", "goal": "cabinet"})])
    assert off._tour_model(best, fields, then, agent_off).acted is None


def test_the_drive_on_runs_through_the_next_known_stops(library: Library) -> None:
    """With two known stops ahead, the drive on from a cell is the shortest drive through a cell to act on the
    first and then one for the second (as ``stand`` chooses them), never less than to the first alone."""
    policy = SeFMPolicy(particles=50)
    agent = ready(library, table_room(library), policy, [("Place", {"theme": "apple", "goal": "cabinet"})])
    cabinet, shelf = agent.known["cabinet_1"], agent.known["shelf_1"]
    one = policy._onward_field(agent, cabinet)
    two = policy._onward_field(agent, cabinet, shelf)
    here = agent.grid.cell((0.0, 0.0))
    # to the cabinet's nearest cell to act from (x = 6.25 at the least), then back to the shelf's (x <= 3.75)
    assert two[here] > one[here] + 2.0
    shelf_cells = agent.stand_cells(shelf)
    from_here = agent.grid.distances(here)
    brute = min(float(from_here[int(i), int(j)])
                + float(agent.grid.distances((int(i), int(j)))[shelf_cells[:, 0], shelf_cells[:, 1]].min())
                for i, j in agent.stand_cells(cabinet))
    assert two[here] == pytest.approx(brute)
    assert policy._onward_field(agent, cabinet, shelf) is two   # kept for the run


def test_the_house_view_looks_where_the_belief_lies_off_every_place_before_calling_it_spent(library: Library) -> None:
    """The longhouse's spoon on the bedroom floor (its prior names the kitchen and the bedroom; the bed, the bedroom's
    one place, is reached from nowhere): once the kitchen's counter and the study's desk are looked at, no place
    holds belief worth a look, and object-only's house view goes to the belief's mode in the bedroom. Before
    search17 it called the belief spent there (half of it on the bedroom floor) and swept the nearest frontier 0.2 m
    at a time: 87.9 m and 151 steps on this run, 60.0 m and 61 steps now."""
    import dataclasses

    from seal_cli.bench.context import layout_seed
    from seal_cli.bench.houses import LONGHOUSE_STARTS, longhouse
    from seal_cli.bench.mapsuite import sample_layout
    from seal_cli.maps.model import Robot as MapRobot
    from seal_cli.pipeline import run_on_map
    from seal_cli.sim.policies import make_policy

    m = longhouse()
    base = layout_seed(0, 0, m.name)
    world = dataclasses.replace(sample_layout(m, np.random.default_rng(base)), robot=MapRobot(LONGHOUSE_STARTS[0]))
    spoon = next(o.at for o in world.objects if o.cls == "spoon")
    assert world.rooms[[r.name for r in world.rooms].index("bedroom")].contains([spoon])[0]
    agent, result = run_on_map(world, "stir the cup", library, make_policy("object_only"),
                               rng=np.random.default_rng(base + 1), search_end=None)
    assert result.completed
    said = [r.text for r in agent.records if r.kind == "search"]
    assert any("the belief's best mode" in t for t in said)
    assert not any("the belief is spent" in t for t in said)
    assert result.path_m < 70.0 and result.steps < 100


def test_a_belief_its_looks_refute_hands_the_search_to_the_sweep(library: Library) -> None:
    """search20: the cup in the cottage's kitchen, where its prior (bedroom, family room) puts next to nothing.
    Looked for from views a metre apart everywhere it is out of sight, SeFM's belief gave the misses a chance
    below ``refute_below``: the
    belief says where the cup is not, wrongly, and choosing views by it went round the same rooms (the held-out
    ranch: 200 m); the next view is the frontier sweep's, which assumes nothing. Before the looks it is not."""
    policy, agent = cottage_agent(library, (13.5, 9.0))
    assert policy.next_view(agent, agent.steps[0], "cup") is not None
    assert policy.refuted(agent, "cup") is None
    for x in np.arange(0.5, 14.0, 1.0):        # the house looked at from views a metre apart, wherever the cup
        for y in np.arange(0.5, 10.0, 1.0):     # is out of sight
            if agent.grid.is_free(agent.grid.cell((x, y))) and not agent.world.observe((x, y, 0.0)):
                agent.world.robot.pose = (float(x), float(y), 0.0)
                assert not agent.look(quiet=True)
    why = policy.refuted(agent, "cup")
    assert why is not None and "refuted" in why
    view = policy.next_view(agent, agent.steps[0], "cup")
    assert view is not None and "frontier" in view.why and "refuted" in view.why
    policy.refute_below = 0.0
    assert policy.refuted(agent, "cup") is None
    view = policy.next_view(agent, agent.steps[0], "cup")
    assert view is not None and "frontier" not in view.why


def cottage_agent(library: Library, cup_at: tuple[float, float]) -> tuple[SeFMPolicy, Agent]:
    """The cottage with only its cup (at ``cup_at``), SeFM with its plan to pick the cup up and its first look taken."""
    import dataclasses

    from seal_cli.bench.houses import cottage
    from seal_cli.sim.agent import scene_from_map

    m = cottage()
    m = dataclasses.replace(m, objects=tuple(dataclasses.replace(o, at=cup_at) for o in m.objects if o.cls == "cup"))
    policy = SeFMPolicy(particles=100)
    agent = Agent(scene_from_map(m, library), library, policy, rng=np.random.default_rng(0))
    agent.state = agent.initial_state()
    policy.begin(agent)
    agent.look()
    commanded = [library.frame("Pick").bind({"theme": "cup"})]
    agent.todo, agent.steps, agent.index = list(commanded), agent.planner(commanded, library, agent.state), 0
    return policy, agent


def test_the_cell_belief_is_the_prior_with_a_miss_for_every_new_view_that_saw_a_cell(library: Library) -> None:
    """search22: SeFM's object belief on the map's cells: the prior, times 1 − p for each new view that saw a cell
    (negative information once per view, as the object filter counts it); a look from within the view step adds
    nothing, a look from elsewhere counts again."""
    policy, agent = cottage_agent(library, (13.5, 9.0))
    m = agent.scene.map
    prior = np.asarray(m.prior("cup").weights, dtype=float)
    seen_once = policy.looked == 1
    assert seen_once.any() and (policy.looked <= 1).all()     # the first look, from the hall
    b = policy.cell_belief("cup")
    assert np.allclose(b[~seen_once], prior[~seen_once])
    assert np.allclose(b[seen_once], prior[seen_once] * (1 - policy.p_detect))
    before = policy.looked.copy()
    x, y, _ = agent.world.robot.pose
    agent.world.robot.pose = (x + 0.2, y, 0.0)                # the same view
    agent.look(quiet=True)
    assert (policy.looked == before).all()
    agent.world.robot.pose = (3.0, 2.5, 0.0)                  # the bedroom: a new view
    agent.look(quiet=True)
    centres = m.free_centres
    sees = np.asarray(agent.world.sensor.region((3.0, 2.5, 0.0)).contains(centres), dtype=bool) & \
        (np.hypot(centres[:, 0] - 3.0, centres[:, 1] - 2.5) <= agent.world.sensor.range)
    assert sees.sum() > 1000
    assert (policy.looked - before == sees).all()


def test_with_the_priors_rooms_looked_at_the_search_turns_to_the_rooms_they_do_not_name(library: Library) -> None:
    """search22: the cup in the kitchen, where its prior (bedroom, family room) puts only the floor. With every cell of
    both named rooms seen from two views or more, SeFM's belief on the cells keeps less than a third of what is left
    there (1 − p per new view), and the whole-plan search looks elsewhere."""
    policy, agent = cottage_agent(library, (13.0, 9.0))
    m = agent.scene.map
    for pose in ((4.5, 1.0), (0.5, 4.5), (0.5, 0.5), (5.5, 4.5), (1.5, 6.5), (4.5, 8.5), (0.5, 9.5), (5.5, 5.5)):
        agent.world.robot.pose = (*pose, 0.0)
        assert not agent.look(quiet=True)
    rooms = [r.name for r in m.rooms]
    named = np.isin(m.free_cell_room, [rooms.index("bedroom"), rooms.index("family_room")])
    assert policy.looked[named].min() >= 2
    b = policy.cell_belief("cup")
    assert b[named].sum() < 0.3 * b.sum()
    view = policy.next_view(agent, agent.steps[0], "cup")
    assert view is not None
    assert m.room_of([agent.grid.point(view.cell)])[0] not in ("bedroom", "family_room")


def test_the_house_wide_look_is_at_a_place_never_at_a_person(library: Library) -> None:
    """e2e31: the guesthouse's search for a second book "looks at Carla, where the belief is": people are known to the
    robot as items that do not move, and the house-wide choice weighed each as a place, by the belief within reach of
    where they stand. A person is not where a thing lies: with the shelves looked at, the belief beside Carla (who
    stands by them) is no reason to drive to her."""
    from seal_cli.sim.world import PERSON

    carla = Item("carla", PERSON, (1.5, 0.9), movable=False)
    scene = corridor(library, {"apple": {"shelf": 0.9}}, extra=(carla,))
    policy = SeFMPolicy(particles=100)
    agent = ready(library, scene, policy, [("Pick", {"theme": "apple"})])
    assert "carla" in agent.known and not agent.known["carla"].movable
    agent.inspected |= {"shelf_1", "shelf_2"}
    X, W, modes = policy.cloud(agent, "apple")
    view = policy._house_best(agent, "apple", X, W / W.sum(), modes)
    assert view is None or "carla" not in view.why
    agent.inspected.discard("shelf_2")              # a place still holds belief: that is the look, not the person
    view = policy._house_best(agent, "apple", X, W / W.sum(), modes)
    assert view is not None and view.why == "looks at shelf_2, where the belief is"
