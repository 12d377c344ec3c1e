"""The context suite: its houses, a layout run by every policy, and the command line's JSON."""

from __future__ import annotations

import dataclasses
import json
from pathlib import Path

import pytest
from typer.testing import CliRunner

from seal_cli.bench.context import (
    COMMANDS,
    START_CLEARANCE,
    House,
    drawn_starts,
    house_set,
    houses,
    regroup,
    run_house_layout,
    unseen_houses,
    with_fov,
)
from seal_cli.bench.houses import CONTEXT_PRIORS, COTTAGE_STARTS, cottage
from seal_cli.bench.tasks import summarise
from seal_cli.cli import app
from seal_cli.errors import SealError
from seal_cli.frames.library import Library
from seal_cli.language.grounding import vocabulary_of_map
from seal_cli.maps.model import Robot
from seal_cli.pipeline import plan as plan_text

runner = CliRunner()


def test_every_house_has_the_things_priors_and_starts_and_plans_every_command(shared_data: Path,
                                                                               library: Library) -> None:
    built = houses(shared_data)
    assert [h.map.name for h in built] == ["apartment", "aws_small_house", "cottage"]
    for house in built:
        assert {"spoon", "cup", "mug", "kettle"} <= {o.cls for o in house.map.objects}
        assert all(house.map.priors[c] for c in CONTEXT_PRIORS)
        assert len(house.starts) >= 3
        assert all(house.map.free_index([pose[:2]])[0] >= 0 for pose in house.starts)  # every start is free
        for text in COMMANDS:
            assert len(plan_text(text, library, vocabulary=vocabulary_of_map(house.map)).steps) == 2


# where each unseen house's rooms are reached only through another (a point in it, and the least metres
# from the house's first start): the bungalow's kitchen and family room through the dining room, the
# farmhouse's bedroom through the family room, the terrace's family room through the kitchen, the ranch's
# kitchen (from its hallway, the second start) through the living room or the dining room, the longhouse's
# bedroom (from the study, the third start) through the hallway: out, 13 m west along it and in, not across; the
# gallery's family room (from the gallery's south end) through the kitchen and the dining room, not the bedroom
ONLY_THROUGH = {"bungalow": [((13.0, 2.5), 9.0), ((11.5, 8.0), 9.0)], "farmhouse": [((15.5, 3.0), 14.0)],
                "terrace": [((4.5, 18.5), 15.0)], "ranch": [((9.5, 2.0), 6.5)], "longhouse": [((2.0, 8.5), 17.5)],
                "gallery": [((12.0, 8.0), 15.0)]}
THROUGH_FROM = {"ranch": 1, "longhouse": 2}


def test_the_unseen_houses_are_room_graphs_with_free_starts_and_plan_every_command(library: Library) -> None:
    import numpy as np

    from seal_cli.sim.agent import Agent, scene_from_map
    from seal_cli.sim.policies import make_policy

    unseen = unseen_houses()
    assert [h.map.name for h in unseen] == ["bungalow", "farmhouse", "terrace", "ranch", "longhouse",
                                                "gallery"]
    for house in unseen:
        m = house.map
        assert {r.name for r in m.rooms} >= {room for prior in CONTEXT_PRIORS.values() for room in prior}
        assert {c: dict(p) for c, p in m.priors.items()} == {c: dict(p) for c, p in CONTEXT_PRIORS.items()}
        assert {"spoon", "cup", "mug", "kettle"} <= {o.cls for o in m.objects}
        origin = house.starts[THROUGH_FROM.get(m.name, 0)]
        agent = Agent(scene_from_map(dataclasses.replace(m, robot=Robot(origin)), library),
                      library, make_policy("oracle"), rng=np.random.default_rng(0))
        field_ = agent.distances()
        free = agent.grid.free_cells
        assert np.isfinite(field_[free[:, 0], free[:, 1]]).all(), m.name    # every room reachable through its doors
        for point, metres in ONLY_THROUGH[m.name]:
            assert field_[agent.grid.cell(point)] > metres, (m.name, point, float(field_[agent.grid.cell(point)]))
        assert all(m.free_index([pose[:2]])[0] >= 0 for pose in house.starts)
        for text in COMMANDS:
            assert len(plan_text(text, library, vocabulary=vocabulary_of_map(m)).steps) == 2


def test_the_aws_house_needs_the_shared_data(tmp_path: Path) -> None:
    with pytest.raises(SealError, match="AWS small house"):
        houses(tmp_path)


def test_a_layout_runs_every_policy_on_the_same_worlds(library: Library) -> None:
    house = House(cottage(), COTTAGE_STARTS[:2])
    outcomes = run_house_layout(house, 0, ["stir the cup"], library, ["sefm", "prior_optimal", "oracle"],
                                particles=100)
    assert [o.policy for o in outcomes] == ["sefm", "prior_optimal", "oracle"] * 2
    assert all(o.success for o in outcomes)
    for start in (0, 3):
        oracle = outcomes[start + 2].path_m
        assert oracle <= outcomes[start].path_m and oracle <= outcomes[start + 1].path_m
    report = summarise(outcomes, ["sefm", "prior_optimal", "oracle"])
    assert set(report["groups"]) == {"cottage · stir the cup · start 1", "cottage · stir the cup · start 2", "all"}
    assert regroup(outcomes, ["sefm"], 1)["stir the cup"]["n"] == 2
    again = run_house_layout(house, 0, ["stir the cup"], library, ["sefm", "prior_optimal", "oracle"], particles=100)
    assert [o.path_m for o in again] == [o.path_m for o in outcomes]


def test_bench_tasks_context_refuses_an_unknown_policy_and_a_bad_command(shared_data: Path) -> None:
    bad = runner.invoke(app, ["bench", "tasks", "--suite", "context", "--policies", "sefm,psychic"])
    assert bad.exit_code == 1 and "unknown policy 'psychic'; known: sefm" in bad.stderr
    unplannable = runner.invoke(app, ["bench", "tasks", "--suite", "context_all", "--command", "launch the rocket",
                                      "--data", str(shared_data), "--jobs", "1"])
    assert unplannable.exit_code == 1 and "unknown verb 'launch'" in unplannable.stderr
    assert "Traceback" not in unplannable.output


def test_bench_tasks_context_all_json(shared_data: Path) -> None:
    # the suite as it was before search26: every command from every own start of the three houses
    result = runner.invoke(app, ["bench", "tasks", "--suite", "context_all", "--command", "stir the cup", "--layouts",
                                 "1", "--policies", "oracle", "--jobs", "1", "--data", str(shared_data), "--json"])
    assert result.exit_code == 0, result.output
    data = json.loads(result.stdout)
    assert data["suite"] == "context_all" and data["houses"] == "suite" and "all" in data["groups"]
    assert data["groups"]["all"]["n"] == 9 and set(data["by_house"]) == {"apartment", "aws_small_house", "cottage",
                                                                          "all"}


def test_paired_differences_against_prior_optimal_are_per_episode_and_fold_by_command() -> None:
    from seal_cli.bench.context import paired
    from seal_cli.bench.tasks import Outcome

    def o(task: str, command: str, policy: str, path: float, ok: bool = True) -> Outcome:
        return Outcome(task, f"cottage · {command} · start 1", policy, ok, path, 1, "", float("nan"), 0.0)

    runs = [o("a", "stir the cup", "prior_optimal", 10.0), o("a", "stir the cup", "sefm", 12.0),
            o("b", "stir the cup", "prior_optimal", 10.0), o("b", "stir the cup", "sefm", 8.0),
            o("c", "stir the mug", "prior_optimal", 5.0), o("c", "stir the mug", "sefm", 9.0),
            o("d", "stir the mug", "prior_optimal", 5.0), o("d", "stir the mug", "sefm", 1.0, ok=False)]
    got = paired(runs, ["sefm", "prior_optimal"])
    assert got["stir the cup"]["sefm"] == {"n": 2, "mean_m": 0.0, "se_m": 2.0}
    assert got["stir the mug"]["sefm"]["n"] == 1 and got["stir the mug"]["sefm"]["mean_m"] == 4.0  # d failed
    assert got["all"]["sefm"]["n"] == 3 and got["all"]["sefm"]["mean_m"] == pytest.approx(4 / 3, abs=1e-3)
    assert paired(runs, ["sefm"]) == {}


def test_drawn_starts_are_clear_of_walls_in_rooms_and_the_same_for_a_seed() -> None:
    from scipy.ndimage import distance_transform_edt

    for house in unseen_houses():
        m = house.map
        starts = drawn_starts(m, 5, seed=3)
        assert len(starts) == 5 and starts == drawn_starts(m, 5, seed=3)
        assert starts != drawn_starts(m, 5, seed=4)
        clearance = distance_transform_edt(m.grid.free_mask) * m.grid.resolution
        for x, y, _ in starts:
            index = m.free_index([(x, y)])[0]
            assert index >= 0 and m.free_cell_room[index] >= 0     # free, in a room
            rows, cols, _ = m.grid.cell_index([(x, y)])
            assert clearance[rows[0], cols[0]] >= START_CLEARANCE - 1e-9


def test_the_house_sets_by_name(shared_data: Path) -> None:
    assert [h.map.name for h in house_set("unseen", shared_data)] == ["bungalow", "farmhouse", "terrace", "ranch",
                                                                     "longhouse", "gallery"]
    assert [h.map.name for h in house_set("suite", shared_data)] == ["apartment", "aws_small_house", "cottage"]
    with pytest.raises(SealError, match="--houses 'mine': one of suite, unseen"):
        house_set("mine", shared_data)


def test_bench_tasks_context_on_the_unseen_houses_from_drawn_starts(shared_data: Path) -> None:
    result = runner.invoke(app, ["bench", "tasks", "--suite", "context_all", "--houses", "unseen", "--starts", "1",
                                 "--seed", "2", "--command", "stir the cup", "--layouts", "1", "--policies", "oracle",
                                 "--jobs", "1", "--data", str(shared_data), "--json"])
    assert result.exit_code == 0, result.output
    data = json.loads(result.stdout)
    assert data["houses"] == "unseen" and data["starts"] == 1 and data["seed"] == 2
    assert set(data["by_house"]) == {"bungalow", "farmhouse", "terrace", "ranch", "longhouse", "gallery",
                                     "all"}
    assert data["groups"]["all"]["n"] == 6 and data["groups"]["all"]["success"]["oracle"] == 1.0


def test_bench_tasks_refuses_an_unknown_house_set_and_starts_off_the_context_suite(shared_data: Path) -> None:
    bad = runner.invoke(app, ["bench", "tasks", "--suite", "context_all", "--houses", "mine", "--data",
                              str(shared_data)])
    assert bad.exit_code == 1 and "--houses 'mine': one of suite, unseen" in bad.stderr
    off = runner.invoke(app, ["bench", "tasks", "--suite", "map", "--starts", "2"])
    assert (off.exit_code, off.stderr) == (1, "error: --suite map does not read --starts: --starts goes with --suite "
                                              "context_all\n")
    assert "Traceback" not in bad.output + off.output


def test_bench_tasks_context_fov_gives_every_house_that_sensor_and_refuses_a_senseless_one(shared_data: Path) -> None:
    narrow = with_fov([House(cottage(), COTTAGE_STARTS)], 90.0)
    assert narrow[0].map.sensor.fov_deg == 90.0 and narrow[0].map.sensor.range == cottage().sensor.range
    assert narrow[0].starts == COTTAGE_STARTS and with_fov(narrow, None) == narrow
    for bad in ("0", "-90", "361", "nan", "0.5", "1e-300"):  # a sliver was 360 / fov looks at each stop (hostile31)
        out = runner.invoke(app, ["bench", "tasks", "--suite", "context", "--fov", bad, "--data", str(shared_data)])
        assert out.exit_code == 1 and "degrees in [1, 360]" in out.stderr and "Traceback" not in out.output, bad
    off = runner.invoke(app, ["bench", "tasks", "--suite", "map", "--fov", "90"])
    assert off.exit_code == 1 and "--suite map does not read --fov: --fov goes with --suite context" in off.stderr
    result = runner.invoke(app, ["bench", "tasks", "--suite", "context_all", "--houses", "unseen", "--starts", "1",
                                 "--command", "stir the cup", "--layouts", "1", "--policies", "oracle", "--fov", "90",
                                 "--jobs", "1", "--data", str(shared_data), "--json"])
    assert result.exit_code == 0, result.output
    data = json.loads(result.stdout)
    assert data["fov"] == 90 and data["groups"]["all"]["success"]["oracle"] == 1.0


def test_the_context_suite_is_the_chosen_cases_from_their_own_starts(shared_data: Path, tmp_path: Path) -> None:
    from seal_cli.bench.context import CASES_FILE, selected_houses

    cases = json.loads(CASES_FILE.read_text(encoding="utf-8"))["cases"]
    built = selected_houses(shared_data)
    runs = {(h.map.name, label, text, pose) for h in built
            for label, said, pose in zip(h.labels or (), h.commands or (), h.starts, strict=True) for text in said}
    assert runs == {(c["house"], c["start"], c["command"], tuple(c["pose"])) for c in cases}
    assert len(cases) >= 30 and {"apartment", "aws_small_house"} < {h.map.name for h in built}
    only = selected_houses(shared_data, ["stir the cup"])
    assert {t for h in only for said in h.commands or () for t in said} == {"stir the cup"}
    with pytest.raises(SealError, match="--command 'launch the rocket': no case of the context suite has it"):
        selected_houses(shared_data, ["launch the rocket"])
    broken = tmp_path / "cases.json"
    broken.write_text("{", encoding="utf-8")
    with pytest.raises(SealError, match="cases.json: the context suite's cases cannot be read"):
        selected_houses(shared_data, cases_file=broken)


def _run_fewest_cased_command(suite: str, cases_file: Path, data: Path | None) -> dict:
    """`bench tasks --suite SUITE` on the command of the cases file with the fewest cases (one layout, the oracle;
    ``--data`` when given): its JSON, after checking it ran exactly that command's cases, each a success."""
    cases = json.loads(cases_file.read_text(encoding="utf-8"))["cases"]
    text = min({c["command"] for c in cases}, key=lambda t: sum(c["command"] == t for c in cases))
    mine = [c for c in cases if c["command"] == text]
    result = runner.invoke(app, ["bench", "tasks", "--suite", suite, "--command", text, "--layouts", "1",
                                 "--policies", "oracle", "--jobs", "1", "--json",
                                 *(["--data", str(data)] if data is not None else [])])
    assert result.exit_code == 0, result.output
    found: dict = json.loads(result.stdout)
    assert found["suite"] == suite
    assert set(found["groups"]) - {"all"} == {f"{c['house']} · {text} · start {c['start']}" for c in mine}
    assert found["groups"]["all"]["n"] == len(mine) and found["groups"]["all"]["success"]["oracle"] == 1.0
    return found


def test_bench_tasks_context_runs_the_chosen_cases(shared_data: Path) -> None:
    from seal_cli.bench.context import CASES_FILE

    assert _run_fewest_cased_command("context", CASES_FILE, shared_data)["houses"] == "selected"


def test_a_drawn_house_is_its_seed_alone_every_room_reached_and_every_command_planned(library: Library) -> None:
    import numpy as np

    from seal_cli.bench.context import held_out_houses
    from seal_cli.bench.houses import DRAWN_PLACES, DRAWN_ROOMS, HELD_OUT_SEEDS, drawn_house
    from seal_cli.sim.agent import Agent, scene_from_map
    from seal_cli.sim.policies import make_policy

    one, again, other = drawn_house(11), drawn_house(11), drawn_house(12)
    assert one.rooms == again.rooms and (one.grid.free_mask == again.grid.free_mask).all()
    assert one.rooms != other.rooms and one.name == "drawn11"
    assert [h.map.name for h in held_out_houses()] == [f"drawn{s}" for s in HELD_OUT_SEEDS]
    for m in (one, other, *(h.map for h in held_out_houses())):
        assert sorted(r.name for r in m.rooms) == sorted(DRAWN_ROOMS)
        assert {p.cls for p in m.places} == set(DRAWN_PLACES.values())
        assert all(DRAWN_PLACES[room] == p.cls for p, room in zip(m.places, m.room_of([p.at for p in m.places]),
                                                                  strict=True)), m.name   # each in its own room
        assert {c: dict(p) for c, p in m.priors.items()} == {c: dict(p) for c, p in CONTEXT_PRIORS.items()}
        assert 14 <= m.bounds[2] <= 20 and 9 <= m.bounds[3] <= 12
        for room in m.rooms:   # each at least 4 m wide
            xs = [v[0] for v in room.polygon]
            assert max(xs) - min(xs) >= 4.0, (m.name, room.name)
        agent = Agent(scene_from_map(m, library), library, make_policy("oracle"), rng=np.random.default_rng(0))
        field_ = agent.distances()
        free = agent.grid.free_cells
        assert np.isfinite(field_[free[:, 0], free[:, 1]]).all(), m.name    # every room reached through its doors
        for text in COMMANDS:
            assert len(plan_text(text, library, vocabulary=vocabulary_of_map(m)).steps) == 2


def test_bench_tasks_context_held_out_runs_the_cases_chosen_on_the_drawn_houses() -> None:
    from seal_cli.bench.context import HELD_OUT_CASES_FILE

    # drawn in code: no shared data read, none needed (hostile29: --data is refused for this suite)
    assert _run_fewest_cased_command("context_held_out", HELD_OUT_CASES_FILE, None)["houses"] == "held_out"
    refused = runner.invoke(app, ["bench", "tasks", "--suite", "context_held_out", "--houses", "unseen"])
    assert refused.exit_code == 1 and "--houses" in refused.output
