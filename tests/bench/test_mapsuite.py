"""The map suite: layouts drawn from a map's priors, every policy on the same layouts."""

from __future__ import annotations

import json
from pathlib import Path

import numpy as np
import pytest
from typer.testing import CliRunner

from seal_cli.bench.mapsuite import run_map_suite, sample_layout
from seal_cli.bench.tasks import summarise
from seal_cli.cli import app
from seal_cli.errors import SealError
from seal_cli.maps.formats.map_server import load_map
from seal_cli.resources import map_path

runner = CliRunner()


def test_a_layout_moves_every_object_to_where_its_prior_puts_mass() -> None:
    apartment = load_map(map_path("apartment"))
    rooms_of = {"cup": {"family_room", "bedroom"}, "spoon": {"kitchen", "bedroom"}}
    seen_inside = set()
    for seed in range(20):
        layout = sample_layout(apartment, np.random.default_rng(seed))
        assert [o.cls for o in layout.objects] == [o.cls for o in apartment.objects]
        for obj in layout.objects:
            assert layout.is_free(np.array([obj.at]))[0]
            (room,) = layout.room_of(np.array([obj.at]))
            if obj.cls in rooms_of:
                assert room in rooms_of[obj.cls]
            if obj.inside is not None:
                seen_inside.add((obj.cls, obj.inside))
                place = layout.place(obj.inside)
                assert place is not None and np.hypot(place.at[0] - obj.at[0], place.at[1] - obj.at[1]) <= place.reach
    assert ("apple", "fridge_1") in seen_inside and ("apple", "counter_1") in seen_inside
    again = sample_layout(apartment, np.random.default_rng(3))
    assert again.objects == sample_layout(apartment, np.random.default_rng(3)).objects


def test_every_policy_runs_on_the_same_layouts_and_the_oracle_is_shortest() -> None:
    outcomes = list(run_map_suite(str(map_path("apartment")), ["stir the cup"], ["sefm", "oracle"], layouts=2,
                                  jobs=1, particles=100))
    assert [(o.task_id, o.policy) for o in outcomes] == [
        ("apartment-layout0-0", "sefm"), ("apartment-layout0-0", "oracle"),
        ("apartment-layout1-0", "sefm"), ("apartment-layout1-0", "oracle")]
    assert all(o.success and o.group == "stir the cup" for o in outcomes)
    by = {(o.task_id, o.policy): o.path_m for o in outcomes}
    for layout in ("apartment-layout0-0", "apartment-layout1-0"):
        assert by[(layout, "oracle")] <= by[(layout, "sefm")] + 1e-9
    report = summarise(outcomes, ["sefm", "oracle"])
    assert report["groups"]["stir the cup"]["n"] == 2 and report["groups"]["all"]["success"]["sefm"] == 1.0


def test_a_command_that_cannot_be_planned_fails_before_any_run() -> None:
    with pytest.raises(SealError, match="unknown verb 'launch'"):
        list(run_map_suite(str(map_path("apartment")), ["launch the rocket"], ["sefm"], layouts=1, jobs=1))


def test_bench_tasks_map_suite_json() -> None:
    result = runner.invoke(app, ["bench", "tasks", "--suite", "map", "--command", "heat the apple", "--layouts", "1",
                                 "--policies", "oracle,coverage", "--jobs", "1", "--json"])
    assert result.exit_code == 0, result.output
    data = json.loads(result.stdout)
    assert data["suite"] == "map" and data["map"] == "apartment" and data["layouts"] == 1
    group = data["groups"]["heat the apple"]
    assert group["n"] == 1 and set(group["success"]) == {"oracle", "coverage"}
    assert group["path_m"]["oracle"] <= group["path_m"]["coverage"]
    assert 50 < data["peak_rss_mb"] < 4_000      # the largest process running episodes (hostile15: a figure)
    bad = runner.invoke(app, ["bench", "tasks", "--suite", "nope"])
    assert bad.exit_code == 1 and "the suites are alfred2d, map, context" in bad.stderr


def test_a_thing_where_its_prior_is_small_is_searched_for_to_the_end() -> None:
    """A layout drawn from the priors may put the cup in the dining room (prior 0.01): the suite measures
    the search to the end, where seal run's search end (--search-end) gives up on it."""
    from dataclasses import replace

    from seal_cli.bench.mapsuite import run_judged
    from seal_cli.frames.reading import load_library
    from seal_cli.pipeline import run_on_map
    from seal_cli.sim.policies import make_policy

    library = load_library()
    apartment = load_map(map_path("apartment"))
    at = (5.0, 3.5)
    assert apartment.is_free(np.array([at]))[0] and apartment.room_of(np.array([at]))[0] == "dining_room"
    m = replace(apartment, objects=tuple(replace(o, at=at, inside=None) if o.cls == "cup" else o
                                         for o in apartment.objects))
    success, path, _, reason, _ = run_judged(m, "find the cup", library, "sefm", rng=np.random.default_rng(0),
                                             particles=100)
    assert success and reason == "success" and path > 0
    _, given_up = run_on_map(m, "find the cup", library, make_policy("sefm", 100), rng=np.random.default_rng(0))
    assert not given_up.completed and given_up.reason.startswith("no cup found: searched ")


def test_a_default_command_the_map_cannot_ground_is_named_before_any_run(tmp_path: Path) -> None:
    """hostile19: on a map without a bedroom the default "bring the apple to the bedroom" failed inside the first
    layout's run, saying only 'column 20: the m has no bedroom'."""


    folder = tmp_path
    (folder / "m.yaml").write_text("name: m\nbounds: [0, 0, 10, 10]\nrooms:\n  - {name: hall, box: [0, 0, 10, 10]}\n")
    with pytest.raises(SealError, match=r"the m has no bedroom.*\(in 'bring the apple to the bedroom', one of the "
                                        r"suite's default commands; give the map's own with --command\)"):
        list(run_map_suite(str(folder / "m.yaml"), ["bring the apple to the bedroom"], ["sefm"], layouts=1, jobs=1))
