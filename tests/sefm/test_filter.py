"""SeFM's object and frame beliefs: priors, negative information, detections, closed places, relations,
the paper's Fig. 3 on a house drawn here, convergence, determinism, and weights that never break."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from seal_cli.bench.houses import SECOND_HOUSE_TRAJECTORY, aws_house, second_house
from seal_cli.frames.library import Library
from seal_cli.frames.model import Binding, Fact
from seal_cli.maps.model import Map, ObjectTruth, Place, Robot, Room, Sensor
from seal_cli.pipeline import plan as plan_text
from seal_cli.planning.state import State, robot_facts
from seal_cli.sefm.filter import SeFM, SeFMConfig, frame_id
from seal_cli.sefm.modes import room_masses
from seal_cli.sensing.model import simulate_detections

SEEDS = range(5)


@pytest.fixture(scope="module")
def house() -> Map:
    return second_house()


def paper_frames(library: Library, m: Map, holding: str | None = None) -> tuple[list[Binding], State]:
    """The frames of the paper's Fig. 3 as ``seal localize`` plans them (grasp the cup, grasp the spoon, stir it)."""
    bindings: list[Binding] = []
    state = None
    for text in ("grasp the cup", "grasp the spoon", "stir the cup"):
        plan = plan_text(text, library, holding=holding, map=m)
        state = state or plan.initial
        bindings += [b for b in plan.bindings if b not in bindings]
    assert state is not None
    return bindings, state


def stir_index(bindings: list[Binding]) -> int:
    return next(i for i, b in enumerate(bindings) if b.frame.name == "Stir")


def run(m: Map, bindings: list[Binding], state: State, seed: int, poses: list[tuple[float, float]] | None = None,
        steps: int = 20, **config: object) -> SeFM:
    rng = np.random.default_rng(seed)
    sefm = SeFM(m, bindings, state, rng, SeFMConfig(**config))  # type: ignore[arg-type]
    poses = poses or [m.robot.pose[:2]]
    for pose in [*poses, *[poses[-1]] * steps]:
        sefm.update(pose, simulate_detections(m, (*pose, 0.0), sefm.open_places(), rng), state)
    return sefm


# -- the paper's Fig. 3, on a house these tests draw -------------------------------------------------------
@pytest.mark.parametrize("seed", SEEDS)
def test_fig3a_stir_sits_where_spoons_are_and_densest_where_cups_are_too(library: Library, house: Map,
                                                                         seed: int) -> None:
    bindings, state = paper_frames(library, house)
    sefm = run(house, bindings, state, seed)
    rooms = sefm.frame_summary(stir_index(bindings)).rooms
    assert rooms["kitchen"] + rooms["bedroom"] >= 0.7
    assert max(rooms, key=rooms.__getitem__) == "bedroom"


@pytest.mark.parametrize("seed", SEEDS)
def test_fig3b_holding_the_spoon_moves_stir_to_the_cup_rooms(library: Library, house: Map, seed: int) -> None:
    bindings, state = paper_frames(library, house, holding="spoon")
    sefm = run(house, bindings, state, seed)
    rooms = sefm.frame_summary(stir_index(bindings)).rooms
    assert rooms["family_room"] + rooms["bedroom"] >= 0.7
    assert rooms["kitchen"] < 0.1


@pytest.mark.parametrize("holding", [None, "spoon"])
@pytest.mark.parametrize("seed", range(3))
def test_fig3cd_beliefs_converge_on_the_objects_seen_along_a_path(library: Library, house: Map, seed: int,
                                                                  holding: str | None) -> None:
    bindings, state = paper_frames(library, house, holding)
    sefm = run(house, bindings, state, seed, SECOND_HOUSE_TRAJECTORY)
    truth = {o.cls: np.array(o.at) for o in house.objects}
    for cls, at in truth.items():
        if cls == holding:
            continue
        summary = sefm.object_summary(cls)
        assert np.hypot(*(np.array(summary.best) - at)) < 1.0
        row = sefm.objects.row(cls)
        assert sefm.objects.W[row][np.hypot(*(sefm.objects.X[row] - at).T) < 1.0].sum() > 0.8
    stir = stir_index(bindings)
    target = truth["cup"] if holding else truth["spoon"]
    assert np.hypot(*(np.array(sefm.frame_summary(stir).best) - target)) < 1.0
    X, W = sefm.frames.X[stir], sefm.frames.W[stir]
    near = np.minimum(np.hypot(*(X - truth["cup"]).T), np.hypot(*(X - truth["spoon"]).T)) < 1.0
    assert W[near].sum() > 0.8
    for i, binding in enumerate(bindings):
        if binding.frame.name == "Pick" and binding.elements["theme"] != holding:
            best = np.array(sefm.frame_summary(i).best)
            assert np.hypot(*(best - truth[binding.elements["theme"]])) < 1.0, binding


def test_on_the_aws_house_a_look_into_the_bedroom_lowers_it_once_then_it_stays(library: Library, shared_data: Path,
                                                                               tmp_path: Path) -> None:
    """The map's middle sees a sixth of the (50 m²) bedroom: the spoon's bedroom mass drops at the first
    look and stays there for the other 19 updates at that pose; Stir keeps the bedroom on top."""
    from seal_cli.maps.formats.map_server import load_map

    m = load_map(aws_house(tmp_path, shared_data, "north_family", (0.0, 0.0, 0.0)))
    bindings, state = paper_frames(library, m)
    stir = stir_index(bindings)
    rng = np.random.default_rng(0)
    sefm = SeFM(m, bindings, state, rng)
    spoon = sefm.objects.row("spoon")

    def bedroom(X: np.ndarray, W: np.ndarray) -> float:
        return room_masses(m, X, W)["bedroom"]

    prior = bedroom(sefm.objects.X[spoon], sefm.objects.W[spoon])
    masses, stirs = [], []
    for _ in range(20):
        sefm.update(m.robot.pose, simulate_detections(m, m.robot.pose, sefm.open_places(), rng), state)
        masses.append(bedroom(sefm.objects.X[spoon], sefm.objects.W[spoon]))
        stirs.append(sefm.frame_summary(stir).rooms)
    assert masses[0] < prior - 0.02
    assert masses[1:] == pytest.approx([masses[0]] * 19, abs=1e-9)
    assert all(max(rooms, key=rooms.__getitem__) == "bedroom" for rooms in stirs[1:])
    assert max(r["bedroom"] for r in stirs[1:]) - min(r["bedroom"] for r in stirs[1:]) < 0.08


def test_the_bare_product_context_would_put_stir_in_the_small_kitchen(library: Library, house: Map) -> None:
    """Why the context has a floor of 1 (docs/sefm.md): two room-uniform beliefs multiplied favour small rooms."""
    from seal_cli.sefm.frame_beliefs import FrameModel

    bindings, state = paper_frames(library, house)
    bare = run(house, bindings, state, 0, frames=FrameModel(context_floor=0.0))
    rooms = bare.frame_summary(stir_index(bindings)).rooms
    assert rooms["kitchen"] > rooms["bedroom"]


def test_stir_does_not_collapse_with_more_updates(library: Library, house: Map) -> None:
    """The frame filter tracks the target: 60 updates at a pose give the 20-update masses, not one room."""
    bindings, state = paper_frames(library, house)
    stir = stir_index(bindings)
    long = run(house, bindings, state, 1, steps=60).frame_summary(stir).rooms
    assert 0.3 < long["kitchen"] < 0.45 and 0.4 < long["bedroom"] < 0.56


# -- object beliefs -------------------------------------------------------------------------------------
def box_map(**kw: object) -> Map:
    rooms = (Room.box("left", 0, 0, 5, 4), Room.box("right", 5, 0, 10, 4))
    places = (Place("fridge_1", "fridge", (9.0, 2.0), openable=True),)
    defaults: dict[str, object] = {"priors": {"cup": {"left": 0.5, "right": 0.5}, "apple": {"fridge": 1.0}},
                                   "objects": (ObjectTruth("cup", (8.0, 1.0)), ObjectTruth("apple", (9.0, 2.2),
                                                                                           "fridge_1")),
                                   "robot": Robot((2.5, 2.0, 0.0)), "sensor": Sensor(range=3.0)}
    defaults.update(kw)
    return Map("boxes", (0.0, 0.0, 10.0, 4.0), rooms, places, **defaults)  # type: ignore[arg-type]


def cup_state(library: Library, *facts: Fact) -> State:
    return State.of(robot_facts(None) | set(facts), library.taxonomy, closable=["fridge_1"])


def test_prior_gives_each_room_its_share(library: Library) -> None:
    m = box_map()
    sefm = SeFM(m, [], cup_state(library), np.random.default_rng(0), SeFMConfig(particles=201), classes=["cup"])
    masses = room_masses(m, sefm.objects.X[0], sefm.objects.W[0])
    prior = m.prior("cup").room_masses()
    assert masses == pytest.approx(prior, abs=1 / 201 + 1e-9)


def test_where_the_command_says_a_thing_is_weighs_in_its_prior(library: Library) -> None:
    """"The cup from the fridge": the cup's belief starts with SAID of it at the fridge, the map's halves share
    the rest; a class the command says nothing of, or a place not on the map, keeps the map's prior."""
    from seal_cli.maps.priors import SAID

    m = box_map()
    said = SeFM(m, [], cup_state(library), np.random.default_rng(0), SeFMConfig(particles=400), classes=["cup"],
                said={"cup": ["fridge_1"]})
    masses = room_masses(m, said.objects.X[0], said.objects.W[0])
    assert masses["right"] == pytest.approx(SAID + (1 - SAID) * 0.5, abs=0.02)
    near = np.hypot(*(said.objects.X[0] - (9.0, 2.0)).T) <= 1.0 + 1e-9
    assert said.objects.W[0][near].sum() >= SAID - 0.05    # less the floor spread over free space
    for other in ({"apple": ["fridge_1"]}, {"cup": ["attic"]}):
        plain = SeFM(m, [], cup_state(library), np.random.default_rng(0), SeFMConfig(particles=400), classes=["cup"],
                     said=other)
        assert room_masses(m, plain.objects.X[0], plain.objects.W[0])["right"] == pytest.approx(0.5, abs=0.01)


def test_seeing_nothing_lowers_what_is_in_view_by_one_minus_p_detect(library: Library) -> None:
    m = box_map(objects=())
    sefm = SeFM(m, [], cup_state(library), np.random.default_rng(0), SeFMConfig(particles=400), classes=["cup"])
    sefm.update((2.5, 2.0), [])
    left = room_masses(m, sefm.objects.X[0], sefm.objects.W[0])["left"]
    # nearly all of the left room is in view: 0.5·0.1 against 0.5 (the p_detect of the filter is the sensor's 0.9)
    assert left == pytest.approx(0.05 / 0.55, abs=0.03)


def test_a_view_counts_once_standing_still_adds_nothing(library: Library) -> None:
    """A detector's misses from one view are not independent: the first look lowers what it sees, the
    next 19 from the same pose leave the belief as it was; a look from a new place counts again."""
    m = box_map(objects=(), sensor=Sensor(range=2.0))
    sefm = SeFM(m, [], cup_state(library), np.random.default_rng(0), SeFMConfig(particles=400), classes=["cup"])

    def left() -> float:
        return room_masses(m, sefm.objects.X[0], sefm.objects.W[0])["left"]

    before = left()
    sefm.update((2.5, 2.0), [])
    once = left()
    assert once < before - 0.1  # the 2 m disc is about half the left room
    for _ in range(19):
        sefm.update((2.5, 2.0), [])
    assert left() == pytest.approx(once, abs=1e-9)
    sefm.update((2.6, 2.1), [])  # 0.14 m away: the same view
    assert left() == pytest.approx(once, abs=1e-9)
    sefm.update((1.0, 2.0), [])  # 1.5 m away: a new view
    assert left() < once - 0.02


def test_views_are_new_by_place_heading_and_what_is_shut() -> None:
    from seal_cli.sefm.object_beliefs import Views

    round_ = Views(0.5, None)
    assert round_.first_look((0.0, 0.0, 0.0), [])
    assert not round_.first_look((0.3, 0.3, 3.0), [])      # near, and a 360° sensor does not care where it faces
    assert round_.first_look((0.0, 0.6, 0.0), [])          # moved
    assert round_.first_look((0.0, 0.0, 0.0), [(1.0, 1.0, 0.5)])  # a place shut now that was open: another view
    ahead = Views(0.5, np.radians(30))
    assert ahead.first_look((0.0, 0.0, 0.0), [])
    assert not ahead.first_look((0.0, 0.0, 0.4), [])       # turned 23°
    assert ahead.first_look((0.0, 0.0, 0.6), [])           # turned 34°
    assert not ahead.first_look((0.0, 0.0, 2 * np.pi), [])  # a full turn is the same heading


def test_detections_from_a_view_already_used_still_count(library: Library) -> None:
    m = box_map()
    sefm = SeFM(m, [], cup_state(library), np.random.default_rng(0), SeFMConfig(), classes=["cup"])
    sefm.update((6.5, 2.0), [])  # missed it
    sefm.update((6.5, 2.0), [("cup", (8.0, 1.0))])  # the same view, and now it is seen
    s = sefm.object_summary("cup")
    assert np.hypot(s.best[0] - 8.0, s.best[1] - 1.0) < 0.3


def test_visible_regions_are_cast_once_per_pose_and_the_last_ones_kept(library: Library,
                                                                       monkeypatch: pytest.MonkeyPatch) -> None:
    import seal_cli.sefm.filter as beliefs

    monkeypatch.setattr(beliefs, "REGIONS", 2)
    sefm = SeFM(box_map(), [], cup_state(library), np.random.default_rng(0), classes=["cup"])
    first = sefm._region((1.0, 1.0, 0.0))
    assert sefm._region((1.0, 1.0, 0.0)) is first
    sefm._region((2.0, 1.0, 0.0))
    assert sefm._region((1.0, 1.0, 0.0)) is first  # used again: now the most recent
    sefm._region((3.0, 1.0, 0.0))                  # evicts (2, 1)
    assert set(sefm._regions) == {(1.0, 1.0, 0.0), (3.0, 1.0, 0.0)}


def test_a_detection_pulls_the_belief_onto_it(library: Library) -> None:
    m = box_map()
    sefm = SeFM(m, [], cup_state(library), np.random.default_rng(0), SeFMConfig(), classes=["cup"])
    sefm.update((6.5, 2.0), [("cup", (8.0, 1.0))])
    s = sefm.object_summary("cup")
    assert np.hypot(s.best[0] - 8.0, s.best[1] - 1.0) < 0.3
    assert s.modes[0].weight > 0.9


def test_what_is_in_a_closed_place_cannot_be_seen_missing(library: Library) -> None:
    m = box_map()
    closed = SeFM(m, [], cup_state(library), np.random.default_rng(0), SeFMConfig(), classes=["apple"])
    opened = SeFM(m, [], cup_state(library, Fact("open", ("fridge_1",))), np.random.default_rng(0), SeFMConfig(),
                  classes=["apple"])
    for sefm in (closed, opened):
        for pose in ((7.0, 2.0), (7.0, 1.0), (7.5, 3.0)):  # three views (one view counts once)
            sefm.update(pose, [])
    near = [s.objects.W[0][np.hypot(*(s.objects.X[0] - (9.0, 2.0)).T) < 1.0].sum() for s in (closed, opened)]
    assert near[0] > 0.9  # shut: no evidence against the apple being inside
    assert near[1] < 0.5  # open and empty-looking: the apple is probably not there


def test_a_held_object_is_not_updated(library: Library) -> None:
    m = box_map()
    state = State.of(robot_facts("cup"), library.taxonomy)
    sefm = SeFM(m, [], state, np.random.default_rng(0), SeFMConfig(), classes=["cup"])
    before = sefm.objects.W.copy(), sefm.objects.X.copy()
    sefm.update((2.5, 2.0), [])
    np.testing.assert_array_equal(sefm.objects.W, before[0])
    np.testing.assert_array_equal(sefm.objects.X, before[1])


def test_a_perfect_detector_still_leaves_weights_alive(library: Library) -> None:
    m = box_map(sensor=Sensor(range=50.0, p_detect=1.0), objects=())
    sefm = SeFM(m, [library.frame("Pick").bind({"theme": "cup"})], cup_state(library), np.random.default_rng(0))
    for _ in range(30):
        sefm.update((5.0, 2.0), [])  # sees everything, never the cup
    for W in (sefm.objects.W, sefm.frames.W):
        assert np.all(np.isfinite(W)) and np.allclose(W.sum(axis=1), 1.0) and np.all(W.max(axis=1) > 0)


# -- frame beliefs --------------------------------------------------------------------------------------
def test_an_all_disjoint_frame_is_uniform_over_free_space(library: Library) -> None:
    m = box_map()
    pick = library.frame("Pick").bind({"theme": "cup"})
    state = State.of(robot_facts("cup"), library.taxonomy)
    sefm = SeFM(m, [pick], state, np.random.default_rng(0), SeFMConfig(particles=1000))
    sefm.update((2.5, 2.0), [], state)
    rooms = sefm.frame_summary(0).rooms
    assert rooms["left"] == pytest.approx(0.5, abs=0.06)


def test_relations_follow_the_state_given_to_update(library: Library, house: Map) -> None:
    bindings, empty = paper_frames(library, house)
    stir = stir_index(bindings)
    holding = State.of((empty.facts - {Fact("hand_empty")}) | {Fact("holding", ("spoon",))}, empty.taxonomy,
                       empty.closable, empty.classes)
    sefm = SeFM(house, bindings, empty, np.random.default_rng(0))
    assert sefm.relations[stir].element("instrument") == 1.0
    for _ in range(15):
        sefm.update(house.robot.pose, [], holding)
    assert sefm.relations[stir].element("instrument") == 0.0
    rooms = sefm.frame_summary(stir).rooms
    assert rooms["kitchen"] < 0.1 and rooms["family_room"] + rooms["bedroom"] > 0.7


def test_same_seed_same_beliefs_other_seed_other_beliefs(library: Library, house: Map) -> None:
    bindings, state = paper_frames(library, house)
    a, b, c = (run(house, bindings, state, s, SECOND_HOUSE_TRAJECTORY[:4], steps=2) for s in (7, 7, 8))
    np.testing.assert_array_equal(a.frames.X, b.frames.X)
    np.testing.assert_array_equal(a.objects.W, b.objects.W)
    assert not np.array_equal(a.frames.X, c.frames.X)


def test_exact_and_grid_kernels_give_the_same_beliefs(library: Library, house: Map) -> None:
    bindings, state = paper_frames(library, house)
    stir = stir_index(bindings)
    grid = run(house, bindings, state, 3, steps=5).frame_summary(stir).rooms
    exact = run(house, bindings, state, 3, steps=5, kernel="exact").frame_summary(stir).rooms
    for room in grid:
        assert grid[room] == pytest.approx(exact[room], abs=0.05)


def test_frame_ids_are_distinct(library: Library) -> None:
    pick = library.frame("Pick").bind({"theme": "cup"})
    sefm = SeFM(box_map(), [pick, pick], cup_state(library), np.random.default_rng(0))
    assert frame_id(pick) == "pick_cup"
    assert sefm.frame_ids == ("pick_cup", "pick_cup_2")


def test_places_and_rooms_are_known_not_believed(library: Library) -> None:
    m = box_map()
    place = library.frame("Place").bind({"theme": "cup", "goal": "fridge_1"})
    go = library.frame("Go").bind({"goal": "right"})
    state = State.of(robot_facts("cup") | {Fact("open", ("fridge_1",))}, library.taxonomy, closable=["fridge_1"])
    sefm = SeFM(m, [place, go], state, np.random.default_rng(0))
    assert sefm.object_classes == ("cup",)
    for _ in range(5):
        sefm.update((2.5, 2.0), [], state)
    assert np.hypot(*(np.array(sefm.frame_summary(0).best) - (9.0, 2.0))) < 0.8
    assert sefm.frame_summary(1).rooms["right"] > 0.9


# -- weights never break --------------------------------------------------------------------------------
@st.composite
def scenarios(draw: st.DrawFn) -> tuple[Map, list[tuple[tuple[float, float, float], list[tuple[str, tuple]]]]]:
    width = draw(st.floats(3.0, 12.0))
    height = draw(st.floats(3.0, 8.0))
    cut = draw(st.floats(0.3, 0.7)) * width
    rooms = (Room.box("a", 0, 0, cut, height), Room.box("b", cut, 0, width, height))
    masses = draw(st.lists(st.floats(0.0, 0.5), min_size=2, max_size=2))
    sensor = Sensor(range=draw(st.floats(0.5, 6.0)), fov_deg=draw(st.sampled_from([60.0, 180.0, 360.0])),
                    p_detect=draw(st.floats(0.0, 1.0)), sigma=draw(st.floats(0.05, 1.0)))
    m = Map("random", (0.0, 0.0, width, height), rooms, priors={"cup": {"a": masses[0], "b": masses[1]}},
            sensor=sensor)
    point = st.tuples(st.floats(0.0, width), st.floats(0.0, height))
    steps = draw(st.lists(st.tuples(st.tuples(st.floats(0.0, width), st.floats(0.0, height), st.floats(-3.2, 3.2)),
                                    st.lists(st.tuples(st.sampled_from(["cup", "spoon"]), point), max_size=3)),
                          min_size=1, max_size=6))
    return m, steps


@settings(max_examples=25, deadline=None, suppress_health_check=[HealthCheck.too_slow,
                                                                 HealthCheck.function_scoped_fixture])
@given(scenario=scenarios(), seed=st.integers(0, 2 ** 16), holding=st.sampled_from([None, "spoon"]),
       particles=st.sampled_from([1, 2, 7, 50]))
def test_weights_are_always_finite_and_normalised(library: Library, scenario: tuple, seed: int,
                                                   holding: str | None, particles: int) -> None:
    m, steps = scenario
    frames = [library.frame("Pick").bind({"theme": "spoon"}), library.frame("Stir").bind({"theme": "cup"})]
    state = State.of(robot_facts(holding), library.taxonomy)
    sefm = SeFM(m, frames, state, np.random.default_rng(seed), SeFMConfig(particles=particles))
    for pose, detections in steps:
        sefm.update(pose, detections, state)
        for W in (sefm.objects.W, sefm.frames.W):
            assert np.all(np.isfinite(W)) and np.all(W >= 0)
            np.testing.assert_allclose(W.sum(axis=1), 1.0)
        assert np.all(np.isfinite(sefm.frames.X)) and np.all(np.isfinite(sefm.objects.X))
        assert np.all(np.isfinite(sefm.frames.Z)) and np.all(sefm.frames.Z > 0)
    for i in range(len(frames)):
        summary = sefm.frame_summary(i)
        assert sum(summary.rooms.values()) == pytest.approx(1.0)
        assert all(np.isfinite(summary.best))


@st.composite
def bad_updates(draw: st.DrawFn) -> tuple[tuple[float, ...], list[tuple[str, tuple[float, float]]], str]:
    """A pose and detections of which exactly one thing is wrong, and what: NaN or infinity, off
    the map (the scenario maps lie in [0, 12] × [0, 8]), or a class nobody knows."""
    wrong = draw(st.sampled_from(["nan pose", "off-map pose", "nan detection", "off-map detection", "class"]))
    bad_number = draw(st.sampled_from([float("nan"), float("inf"), -float("inf")]))
    off = draw(st.one_of(st.floats(-1e12, -0.01), st.floats(12.01, 1e12)))
    pose: tuple[float, ...] = (1.0, 1.0, 0.0)
    seen = [("cup", (1.0, 1.0))]
    if wrong == "nan pose":
        pose = (bad_number, 1.0, 0.0) if draw(st.booleans()) else (1.0, 1.0, bad_number)
    elif wrong == "off-map pose":
        pose = (off, 1.0) if draw(st.booleans()) else (1.0, off)
    elif wrong == "nan detection":
        seen.append(("spoon", (bad_number, 1.0)))
    elif wrong == "off-map detection":
        seen.append(("cup", (1.0, off)))
    else:
        seen.append((draw(st.sampled_from(["zebra", "", "cupp"])), (1.0, 1.0)))
    return pose, seen, wrong


@settings(max_examples=40, deadline=None, suppress_health_check=[HealthCheck.too_slow,
                                                                 HealthCheck.function_scoped_fixture])
@given(scenario=scenarios(), bad=bad_updates(), seed=st.integers(0, 2 ** 16))
def test_nan_off_map_and_unknown_class_are_refused_and_change_nothing(library: Library, scenario: tuple,
                                                                       bad: tuple, seed: int) -> None:
    from seal_cli.errors import SealError

    m, steps = scenario
    frames = [library.frame("Pick").bind({"theme": "spoon"}), library.frame("Stir").bind({"theme": "cup"})]
    state = State.of(robot_facts(None), library.taxonomy)
    sefm = SeFM(m, frames, state, np.random.default_rng(seed), SeFMConfig(particles=7))
    pose, seen, wrong = bad
    before = (sefm.objects.X.copy(), sefm.frames.W.copy(), sefm.step)
    with pytest.raises(SealError):
        sefm.update(pose, seen, state)
    np.testing.assert_array_equal(sefm.objects.X, before[0])
    np.testing.assert_array_equal(sefm.frames.W, before[1])
    assert sefm.step == before[2]
    sefm.update(steps[0][0], steps[0][1], state)  # and it goes on as if the bad update never came
    assert np.all(np.isfinite(sefm.frames.W)) and np.all(np.isfinite(sefm.objects.X))


def test_public_queries_agree_with_the_summaries() -> None:
    """What a searcher asks SeFM: particles, densities at points, closed places."""
    from seal_cli.frames.reading import load_library
    from seal_cli.maps.formats.map_server import load_map
    from seal_cli.pipeline import plan as plan_text
    from seal_cli.resources import map_path
    from seal_cli.sefm.filter import SeFM

    m = load_map(map_path("apartment")).known()
    plan = plan_text("stir the cup", load_library(), map=m)
    sefm = SeFM(m, plan.bindings, plan.initial, np.random.default_rng(0))
    sefm.update(m.robot.pose)
    X, W = sefm.frame_particles(1)
    assert X.shape == (200, 2) and np.isclose(W.sum(), 1.0)
    X[:] = 0.0                                   # a copy: the belief is untouched
    assert not np.allclose(sefm.frame_particles(1)[0], 0.0)
    points = m.free_centres
    density = sefm.frame_density(1, points)
    assert density.shape == (len(points),) and np.all(np.isfinite(density)) and density.max() > 0
    rooms = m.room_index(points)
    names = m.room_names
    mass = {names[r]: density[rooms == r].sum() / density.sum() for r in range(len(names))}
    assert max(mass, key=mass.get) == "bedroom"           # where spoons and cups both are likely
    cups = sefm.object_density("cup", points)
    assert cups[rooms == names.index("kitchen")].sum() < 0.05 * cups.sum()
    assert [(x, y) for x, y, _ in sefm.hidden_places()] == [tuple(p.at) for p in m.places if p.openable]


def test_on_a_large_floor_the_context_follows_the_frames_by_their_changes(library: Library) -> None:
    """On a 60 m × 40 m floor the context rows are stamped with what each update changed rather than
    smoothed over the whole grid again: after some updates they hold what setting them afresh gives."""
    from seal_cli.bench.perf import building
    from seal_cli.sefm.potentials import GridKernelSums, SplitKernelSums

    m = building(np.random.default_rng(1), classes=4, columns=12, rows=8)
    things = sorted(m.priors)
    bindings = [library.frame("Pick").bind({"theme": things[0]}),
                library.frame("Stir").bind({"theme": things[1], "instrument": things[0]})]
    state = State.of(robot_facts(None), library.taxonomy)
    rng = np.random.default_rng(2)
    sefm = SeFM(m, bindings, state, rng, SeFMConfig(particles=200))
    for pose in [(2.5, 2.5, 0.0), (5.0, 2.5, 0.0), (7.5, 2.5, 0.0)]:
        sefm.update(pose, simulate_detections(m, pose, sefm.open_places(), rng), state)
    assert isinstance(sefm.kernel, SplitKernelSums) and isinstance(sefm.kernel.high, GridKernelSums)
    high, row = sefm.kernel.high, 0                    # Pick's row among the frames: Stir's context
    assert high.moves[row] == 3
    fresh = GridKernelSums(2, m.bounds, sefm.config.sigma, cell=sefm.config.sigma)
    fresh.set([row], sefm.frames.X[[row]], sefm.frames.W[[row]])
    np.testing.assert_allclose(high.grids[row], fresh.grids[row], atol=1e-6 * fresh.grids[row].max())


def test_a_person_the_map_places_is_a_known_position_not_a_class_spread_over_the_house(library: Library) -> None:
    """Tell(recipient=anna) sits where Anna is (the map puts her in the kitchen), and Bring to "me" has
    the speaker as a second mode: neither believes in a class "person" spread over the whole house."""
    from seal_cli.maps.formats.map_server import load_map

    m = load_map("apartment")
    for text, room in (("tell Anna the time", "kitchen"), ("tell Ben the time", "bedroom")):
        found = plan_text(text, library, map=m.known())
        sefm = run(m, list(found.bindings), found.initial, 0, steps=3)
        assert "person" not in sefm.object_classes
        masses = room_masses(m, *sefm.frame_particles(0))
        assert masses[room] > 0.9, (text, masses)
    found = plan_text("bring me the cup", library, map=m.known())
    sefm = run(m, list(found.bindings), found.initial, 0, steps=3)
    assert "person" not in sefm.object_classes
    X, W = sefm.frame_particles(len(found.bindings) - 1)
    near_speaker = np.linalg.norm(X - np.asarray(m.speaker_at), axis=1) < 1.0
    assert W[near_speaker].sum() > 0.1


def test_a_bad_look_is_refused_at_its_place_before_any_update(library: Library) -> None:
    """hostile18: a detection of a class nobody knows, the 2nd look of an observations file, was refused with no
    file or line, after the looks before it had been filtered."""
    from seal_cli.errors import SealError, Where
    from seal_cli.maps.formats.map_server import load_map
    from seal_cli.resources import map_path
    from seal_cli.sensing.observations import Observation

    m = load_map(map_path("apartment"))
    state = State.of(robot_facts(None), library.taxonomy)
    sefm = SeFM(m, [library.frame("Stir").bind({"theme": "cup"})], state, np.random.default_rng(0),
                SeFMConfig(particles=7))
    looks = [Observation((-6.0, -3.0, 0.0), (("cup", (1.0, 1.0)),), Where("o.yaml", 2, 5)),
             Observation((-6.0, -3.0, 0.0), (("zzz", (1.0, 1.0)),), Where("o.yaml", 4, 5))]
    with pytest.raises(SealError) as caught:
        sefm.follow(looks)
    assert caught.value.where == Where("o.yaml", 4, 5) and "'zzz'" in caught.value.message
    assert sefm.step == 0


def test_a_spot_behind_a_beds_corner_is_not_counted_seen_by_a_look_whose_ray_fan_grazes_the_corner(
        library: Library) -> None:
    """The cottage's bed (1.0–3.0 × 1.8–3.2 m): from (5.0, 2.5) the segment to (1.05, 1.15) cuts the bed's
    south-east corner, but the ray of the filter's fan nearest its bearing passes the corner. Half the cup's
    particles there, half at (4.0, 1.0) in plain view: a look with nothing seen lowers only the second half, as the
    exact rule (and the simulator) has it; by the fan both halves fell alike (search21)."""
    from seal_cli.bench.houses import cottage
    from seal_cli.sensing.model import RangeSensor

    m = cottage()
    pose, hidden, plain = (5.0, 2.5, 0.0), (1.05, 1.15), (4.0, 1.0)
    sensor = RangeSensor.on_map(m)
    rays = max(16, int(np.ceil(2 * np.pi * m.sensor.range / SeFMConfig().ray_spacing)))
    assert sensor.region(pose, rays).contains(np.asarray([hidden])).tolist() == [True]    # the fan: in view
    assert sensor.visible(pose, np.asarray([hidden, plain])).tolist() == [False, True]     # the exact rule: hidden
    sefm = SeFM(m, [], cup_state(library), np.random.default_rng(0), SeFMConfig(particles=200), classes=["cup"])
    row = sefm.objects.row("cup")
    X = sefm.objects.X[row]
    X[:100], X[100:] = hidden, plain
    sefm.objects.W[row] = 1.0 / 200
    sefm.update(pose, [])
    at = np.hypot(*(sefm.objects.X[row] - hidden).T) < 0.1
    share = float(sefm.objects.W[row][at].sum() / sefm.objects.W[row].sum())
    p = m.sensor.p_detect
    assert share == pytest.approx(1 / (1 + (1 - p)), abs=0.03)      # only the spot in view fell, by 1 − p


def test_beliefs_past_the_memory_given_are_refused_saying_how_many_particles_fit(library: Library) -> None:
    """``SeFMConfig.memory``: beliefs that would not fit are refused before anything is drawn (rel33: ``seal
    localize`` gives the machine's available memory; 10,000 classes of 100,000 particles would take 150 GiB)."""
    from seal_cli.errors import SealError
    from seal_cli.sefm.filter import BASE_BYTES, BYTES_PER_PARTICLE, memory_needed

    m = box_map()
    assert memory_needed(2, 1000) == BASE_BYTES + 2 * 1000 * BYTES_PER_PARTICLE
    limit = BASE_BYTES + 2 * 500 * BYTES_PER_PARTICLE          # room for 500 particles of the two classes
    with pytest.raises(SealError, match=r"1,000 particles for each of 2 beliefs \(2 object classes and 0 frames\) "
                                        r"need about .* GiB of memory, .* give --particles 500 or fewer"):
        SeFM(m, [], cup_state(library), np.random.default_rng(0), SeFMConfig(particles=1000, memory=limit),
             classes=["cup", "apple"])
    fits = SeFM(m, [], cup_state(library), np.random.default_rng(0), SeFMConfig(particles=500, memory=limit),
                classes=["cup", "apple"])
    assert len(fits.object_classes) == 2
