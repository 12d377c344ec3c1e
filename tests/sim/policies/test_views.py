"""The view model's lattice and candidate views on a drawn house: paths round walls, looks through doors."""

from __future__ import annotations

import numpy as np
import pytest

from seal_cli.bench.houses import cottage
from seal_cli.frames.library import Library
from seal_cli.sim.agent import Agent, scene_from_map
from seal_cli.sim.policies import make_policy
from seal_cli.sim.policies.whole_plan import WholePlanSearch


def _search(library: Library) -> tuple[Agent, WholePlanSearch]:
    m = cottage()
    agent = Agent(scene_from_map(m, library), library, make_policy("prior_optimal"), rng=np.random.default_rng(0))
    return agent, WholePlanSearch(agent)


def test_the_lattice_drives_round_walls_and_sees_through_doors_only(library: Library) -> None:
    agent, search = _search(library)
    lattice = search.lattice
    bed, fam = (int(k) for k in lattice.node_of(np.asarray([[3.0, 4.4], [3.0, 5.6]])))
    # the wall between the bedroom and the family room: 1.2 m apart, but the drive goes out by the hall
    assert abs(np.hypot(*(lattice.points[bed] - lattice.points[fam])) - 1.2) < 0.3
    assert lattice.distance[bed, fam] > 6.0
    assert np.allclose(lattice.distance, lattice.distance.T)
    assert not lattice.visible(bed)[fam]
    hall, door_in = (int(k) for k in lattice.node_of(np.asarray([[7.5, 2.5], [4.5, 2.5]])))
    assert lattice.visible(hall)[door_in]                       # straight through the bedroom's door
    nodes, metres = lattice.looks(hall, bed)
    assert nodes[-1] == bed and all(b > a for a, b in zip(metres, metres[1:], strict=False))
    assert 0.9 <= metres[0] <= 1.5 and abs(metres[-1] - lattice.distance[hall, bed]) < 1e-3


def test_the_candidates_are_room_views_places_and_both_sides_of_every_door(library: Library) -> None:
    agent, search = _search(library)
    names = [c.name for c in search.candidates]
    for room in ("bedroom", "family_room", "living_room", "dining_room", "kitchen"):
        assert room in names
    for place in ("bed_1", "sofa_1", "dining_table_1", "sink_1"):
        assert place in names
    points = search.lattice.points[[c.node for c in search.candidates]]
    for door in [(6.0, 2.5), (6.0, 7.5), (9.0, 2.5), (9.0, 7.5), (11.5, 5.0)]:
        near = np.hypot(points[:, 0] - door[0], points[:, 1] - door[1]) <= 0.8
        assert near.sum() >= 2, door
    for c in search.candidates:
        assert agent.grid.is_free(c.cell) and c.open is None       # nothing in the cottage opens


def test_a_shut_receptacle_is_seen_into_only_from_the_view_that_opens_it(library: Library) -> None:
    from seal_cli.maps.formats.map_server import load_map
    from seal_cli.resources import map_path

    m = load_map(map_path("apartment"))
    agent = Agent(scene_from_map(m, library), library, make_policy("prior_optimal"), rng=np.random.default_rng(0))
    search = WholePlanSearch(agent)
    shut = search._shut(agent)
    assert "fridge_1" in shut and shut["fridge_1"].any()
    k = next(i for i, c in enumerate(search.candidates) if c.open == "fridge_1")
    hidden = np.zeros(search.lattice.size, dtype=bool)
    for mask in shut.values():
        hidden |= mask
    reveals = [shut.get(c.open) if c.open is not None else None for c in search.candidates]
    start = int(search.lattice.node_of(np.asarray([agent.grid.point(agent.robot_cell())]))[0])
    table = search.lattice.drive_table(start, search.nodes, reveals, hidden)
    inside = shut["fridge_1"]
    assert np.isfinite(table.seen_at[k, inside]).all()
    assert np.allclose(table.seen_at[k, inside], table.length[k])     # at the end, when it is opened
    others = [i for i in range(len(search.candidates)) if i != k and search.candidates[i].open is None]
    assert not np.isfinite(table.seen_at[np.ix_(others, np.flatnonzero(inside))]).any()


def test_a_view_of_another_rule_is_weighed_on_the_same_footing_and_the_tables_grow_to_it(library: Library) -> None:
    from seal_cli.pipeline import run_on_map
    from seal_cli.sim.agent import View

    agent, _ = run_on_map(cottage(), "pick up the spoon", library, make_policy("prior_optimal"),
                          rng=np.random.default_rng(0))
    weights = agent.policy.weights  # type: ignore[attr-defined]
    search = WholePlanSearch(agent)
    first = search.choose(agent, agent.steps[0], "spoon", weights)
    assert first is not None
    grown = dict(search._tables)
    # a cell no candidate stands on, in the hall: weighed among the candidates, the model's cost no worse
    cell = agent.grid.cell((7.5, 3.0))
    assert all(c.cell != cell for c in search.candidates)
    n = len(search.candidates)
    with_it = search.choose(agent, agent.steps[0], "spoon", weights, also=View(cell, (7.5, 3.0)))
    assert with_it is not None and len(search.candidates) == n + 1 and search.candidates[-1].cell == cell
    assert with_it.expected_m <= first.expected_m + 1e-9
    # the tables kept from the first choice grew by the added candidate's row: the tables drawn afresh
    shut = search._shut(agent)
    hidden = np.zeros(search.lattice.size, dtype=bool)
    for mask in shut.values():
        hidden |= mask
    reveals = [shut.get(c.open) if c.open is not None else None for c in search.candidates]
    assert grown and all(len(t.length) == n for t in grown.values())
    for origin, _ in list(grown)[:5]:
        table = search._tables[(origin, (frozenset(shut), None))]
        whole = search.lattice.drive_table(origin, search.nodes, reveals, hidden)
        assert len(table.length) == n + 1
        assert np.array_equal(table.seen_at, whole.seen_at) and np.array_equal(table.length, whole.length)


def test_a_lattice_on_a_large_free_space_has_at_most_max_nodes() -> None:
    """An empty 50 m x 50 m floor at 0.25 m was 40,000 nodes, their all-pairs tables more than 19 GB: the blocks grow
    until the nodes fit, and paths and looks still work on them."""
    from seal_cli.maps.navigation import Grid
    from seal_cli.sim.policies.views import MAX_NODES, lattice_of

    grid = Grid(np.ones((400, 400), dtype=bool), (0.0, 0.0), 0.125)  # 50 m x 50 m
    lattice = lattice_of(grid, lambda p, pts: np.ones(len(pts), dtype=bool), "test-large", 5.0)
    assert 1_000 < lattice.size <= MAX_NODES
    a, b = (int(k) for k in lattice.node_of(np.asarray([[1.0, 1.0], [49.0, 49.0]])))
    assert abs(lattice.distance[a, b] - 48 * np.sqrt(2)) < 2.0 and lattice.path(a, b)[-1] == b


def test_the_lattice_is_built_a_band_of_sources_at_a_time_with_the_same_paths(monkeypatch: pytest.MonkeyPatch) -> None:
    """Its all-pairs shortest paths are computed :data:`ROWS_AT_ONCE` sources at a time (scipy's float64 rows for
    all 4,096 sources were 201 MB on top of the 134 MB kept): the same distances and predecessors as at once."""
    from scipy.sparse.csgraph import dijkstra

    import seal_cli.sim.policies.views as views
    from seal_cli.maps.navigation import Grid

    free = np.ones((60, 90), dtype=bool)
    free[30, 5:85] = False                                       # a wall with a gap at each end
    grid = Grid(free, (0.0, 0.0), 0.1)
    monkeypatch.setattr(views, "ROWS_AT_ONCE", 7)
    lattice = views.lattice_of(grid, lambda p, pts: np.ones(len(pts), dtype=bool), "test-bands", 3.0)
    assert lattice.size > 7 * 3 and lattice.distance.dtype == np.float32 and lattice.previous.dtype == np.int32
    n = lattice.size
    coarse = np.zeros((n, n))
    for a in range(n):   # the lattice's own edges: neighbours one hop apart on their shortest paths
        for b in range(n):
            if lattice.previous[a, b] == a:
                coarse[a, b] = coarse[b, a] = np.hypot(*(lattice.points[a] - lattice.points[b]))
    whole, previous = dijkstra(coarse, directed=False, return_predecessors=True)
    assert np.allclose(lattice.distance, whole.astype(np.float32), atol=1e-4)
    assert (lattice.previous == previous).mean() > 0.99             # ties may break either way, lengths agree


def test_the_drive_tables_kept_are_bounded_the_oldest_dropped_and_made_again(monkeypatch: pytest.MonkeyPatch,
                                                                            library: Library) -> None:
    """A search keeps one drive table per node it plans from (116 MB each on a 4,096-node lattice with 3,500
    candidates, never dropped): now at most :data:`TABLE_BYTES`, those used longest ago dropped; the choices are
    the same."""
    import seal_cli.sim.policies.whole_plan as whole_plan
    from seal_cli.pipeline import run_on_map

    agent, _ = run_on_map(cottage(), "pick up the spoon", library, make_policy("prior_optimal"),
                          rng=np.random.default_rng(0))
    weights = agent.policy.weights  # type: ignore[attr-defined]
    free = WholePlanSearch(agent)
    unbounded = free.choose(agent, agent.steps[0], "spoon", weights)
    one = next(iter(free._tables.values()))
    size = one.seen_at.nbytes + one.look.nbytes
    assert len(free._tables) > 3
    monkeypatch.setattr(whole_plan, "TABLE_BYTES", 3 * size)
    bounded = WholePlanSearch(agent)
    chosen = bounded.choose(agent, agent.steps[0], "spoon", weights)
    held = sum(t.seen_at.nbytes + t.look.nbytes for t in bounded._tables.values())
    assert held <= 3 * size and 1 <= len(bounded._tables) <= 3
    assert unbounded is not None and chosen is not None
    assert (chosen.view.cell, chosen.expected_m) == (unbounded.view.cell, unbounded.expected_m)


def test_a_narrow_sensor_adds_a_bounded_number_of_views_and_none_that_sees_next_to_nothing(library: Library) -> None:
    """A sensor with a 1° field of view sees a sliver from each node: the candidates never covered the belief, and
    every choice added MORE_VIEWS views (50 → 65 candidates in nine choices of "stir the cup" on the apartment, each
    a row of every drive table and a term of every greedy tour's step; one run took over ten minutes). Views that see
    less than UNCOVERED of the belief left are not added, and never more than ADDED_VIEWS over a run."""
    import dataclasses

    from seal_cli.sim.policies.whole_plan import ADDED_VIEWS, MORE_VIEWS

    def grown(fov: float, choices: int) -> tuple[int, int]:
        m = cottage()
        m = dataclasses.replace(m, sensor=dataclasses.replace(m.sensor, fov_deg=fov))
        agent = Agent(scene_from_map(m, library), library, make_policy("prior_optimal"), rng=np.random.default_rng(0))
        search = WholePlanSearch(agent)
        before = len(search.candidates)
        rng = np.random.default_rng(1)
        for _ in range(choices):          # beliefs spread over the house, as a search left at a loss has them
            search._cover(agent, {"spoon": rng.random(search.lattice.size), "cup": rng.random(search.lattice.size)})
        return before, len(search.candidates) - before

    _, wide = grown(360.0, 12)
    _, narrow = grown(1.0, 12)
    assert wide <= ADDED_VIEWS
    assert narrow <= ADDED_VIEWS < 12 * MORE_VIEWS


def test_a_narrow_sensor_s_run_weighs_a_bounded_number_of_views(monkeypatch: pytest.MonkeyPatch,
                                                                library: Library) -> None:
    """End to end on the cottage with a 1° sensor: the candidates never grow past ADDED_VIEWS (set to MORE_VIEWS here)
    but for the one view another rule asks to weigh at each choice, and each greedy tour takes at most MAX_TOUR views
    (search16: three views more at every choice, with no end). Since search17 a view looks all round (the robot
    turns there), so the map's own views cover the belief and a 1° sensor adds none."""
    import dataclasses

    import seal_cli.sim.policies.completion as completion
    import seal_cli.sim.policies.whole_plan as whole_plan
    from seal_cli.bench.mapsuite import sample_layout
    from seal_cli.pipeline import run_on_map
    from seal_cli.sim.agent import Budget

    counts: list[tuple[int, int]] = []
    tours = [0]
    real_tour, real_choose = completion.greedy_tour, whole_plan.WholePlanSearch.choose

    def tour(*a, **k):  # type: ignore[no-untyped-def]
        t = real_tour(*a, **k)
        tours[0] += len(t.views)
        assert len(t.views) <= completion.MAX_TOUR
        return t

    def choose(self, *a, **k):  # type: ignore[no-untyped-def]
        out = real_choose(self, *a, **k)
        counts.append((len(self.candidates), self.added))
        return out

    monkeypatch.setattr(completion, "greedy_tour", tour)
    monkeypatch.setattr(whole_plan.WholePlanSearch, "choose", choose)
    monkeypatch.setattr(whole_plan, "ADDED_VIEWS", whole_plan.MORE_VIEWS)     # the cap reached at the first choice
    m = cottage()
    m = dataclasses.replace(m, sensor=dataclasses.replace(m.sensor, fov_deg=1.0))
    m = sample_layout(m, np.random.default_rng(3))     # the cottage's own things stand in the hall, seen at the start
    run_on_map(m, "stir the cup", library, make_policy("sefm"), rng=np.random.default_rng(0), budget=Budget(steps=10))
    assert len(counts) >= 2 and all(added <= whole_plan.ADDED_VIEWS for _, added in counts)
    first = counts[0][0] - counts[0][1]                         # the map's own views, and the one asked to weigh
    assert all(n - added <= first + len(counts) for n, added in counts)
    assert counts[-1][1] < whole_plan.ADDED_VIEWS               # all-round views: the cap is not even reached
    assert tours[0] > 0


def test_a_look_on_the_way_sees_what_it_faces_and_a_view_sees_all_round() -> None:
    """A 90° sensor on an open corridor (nothing blocks the view): a look on the drive east sees the nodes ahead of
    it within 45° of east, not those behind; the look at the drive's end (the view, where the robot turns round)
    sees all round; with a 360° sensor a look on the way sees all round too."""
    from seal_cli.maps.navigation import Grid
    from seal_cli.sim.policies.views import lattice_of

    free = np.ones((8, 80), dtype=bool)        # 0.4 m × 4 m of 5 cm cells, rows along y, columns along x
    grid = Grid(free, (0.0, 0.0), 0.05)
    narrow = lattice_of(grid, lambda p, pts: np.ones(len(pts), dtype=bool), "test-fov90", 10.0, 1.0, np.radians(90))
    wide = lattice_of(grid, lambda p, pts: np.ones(len(pts), dtype=bool), "test-fov360", 10.0, 1.0)
    west, east = (int(k) for k in narrow.node_of(np.asarray([[0.1, 0.1], [3.9, 0.1]])))
    nodes, metres, headings = narrow.looks_facing(west, east)
    assert len(nodes) >= 3 and all(abs(h) < np.radians(46) for h in headings)      # driving east
    u = nodes[1]
    ahead = narrow.points[:, 0] > narrow.points[u, 0] + 0.5
    behind = narrow.points[:, 0] < narrow.points[u, 0] - 0.5
    along = narrow.visible_along(u, headings[1])
    assert along[ahead].all() and not along[behind].any()
    assert wide.visible_along(u, headings[1])[behind].all()
    table = narrow.drive_table(west, [east], [None], np.zeros(narrow.size, dtype=bool))
    assert np.isfinite(table.seen_at[0]).all()                  # the far end's look sees back over the whole way
    first = narrow.drive_table(west, [nodes[1]], [None], np.zeros(narrow.size, dtype=bool))
    behind_start = narrow.points[:, 0] < narrow.points[west, 0] + 0.01
    assert np.isfinite(first.seen_at[0][behind_start]).all()    # the view at its end looks round, back west too
    away = narrow.drive_table(west, [east], [None], np.zeros(narrow.size, dtype=bool))
    mid = np.flatnonzero((narrow.points[:, 0] > 1.5) & (narrow.points[:, 0] < 2.0))
    assert (away.seen_at[0][mid] < metres[-1]).all()            # seen ahead on the way, before the end


def test_a_look_from_a_stale_node_reveals_nothing_and_the_choice_goes_where_a_look_counts(library: Library) -> None:
    """search20: SeFM counts a miss once per view, so a look from where it has looked already lowers none of its
    belief. The model must expect the same (a stale node's look reveals nothing), or it chooses that look again and
    again — the ranch's 200 m runs. A look that opens a receptacle is a new view and still sees."""
    from seal_cli.pipeline import run_on_map

    agent, _ = run_on_map(cottage(), "pick up the spoon", library, make_policy("prior_optimal"),
                          rng=np.random.default_rng(0))
    m = agent.scene.map
    bedroom = np.asarray(m.rooms[m.room_id("bedroom")].contains(m.free_centres), dtype=bool).astype(float)

    def weights(cls: str) -> np.ndarray:
        return bedroom

    search = WholePlanSearch(agent)
    lattice = search.lattice
    first = search.choose(agent, agent.steps[0], "spoon", weights)
    assert first is not None and first.candidate.name == "bedroom"
    node = first.candidate.node
    stale = np.hypot(*(lattice.points - lattice.points[node]).T) <= 0.5
    hidden = np.zeros(lattice.size, dtype=bool)
    start = int(lattice.node_of(np.asarray([agent.grid.point(agent.robot_cell())]))[0])
    fresh = lattice.drive_table(start, [node], [None], hidden)
    old = lattice.drive_table(start, [node], [None], hidden, stale)
    looks, _ = lattice.looks(start, node)
    assert np.isfinite(fresh.seen_at[0, lattice.visible(node)]).all()
    everywhere = np.ones(lattice.size, dtype=bool)
    assert not np.isfinite(lattice.drive_table(start, [node], [None], hidden, everywhere).seen_at).any()
    on_the_way = np.zeros(lattice.size, dtype=bool)
    for u in looks[:-1]:
        if not stale[u]:
            on_the_way |= lattice.visible(u)
    assert np.array_equal(np.isfinite(old.seen_at[0]), on_the_way)           # the end's look: nothing
    opened = np.zeros(lattice.size, dtype=bool)
    opened[node] = True
    opening = lattice.drive_table(start, [node], [opened], hidden, stale)
    assert np.isfinite(opening.seen_at[0, lattice.visible(node)]).all()
    again = search.choose(agent, agent.steps[0], "spoon", weights, stale=stale)
    assert again is not None and not stale[again.candidate.node]
    assert again.candidate.cell != first.candidate.cell and "spoon" in again.view.why
    assert again.costs[(first.candidate.cell, None)] > first.expected_m     # its own look is worth nothing now
