"""``seal_cli.bench.plan``: the timings ``seal bench plan`` prints."""

from __future__ import annotations

from seal_cli.bench.plan import BENCH_COMMANDS, time_plans
from seal_cli.frames.library import Library
from seal_cli.maps.formats.map_server import load_map
from seal_cli.resources import map_path


def test_each_command_gets_its_plan_and_times(library: Library) -> None:
    rows = time_plans(["stir the cup", "heat the egg and put it in the fridge"], library, repeat=2)
    assert [(r.text, r.commanded, r.steps) for r in rows] == [
        ("stir the cup", 1, 2), ("heat the egg and put it in the fridge", 2, 4)]
    assert all(0 < r.plan_ms <= r.ms and r.nodes >= r.steps for r in rows)


def test_a_map_grounds_the_commands_in_its_world(library: Library) -> None:
    world = load_map(map_path("apartment"))
    (row,) = time_plans(["put the apple on the counter"], library, map=world, repeat=1)
    assert row.commanded == 1 and row.steps >= 2          # the fridge opened and the apple picked up first
    (there,) = time_plans(["put the apple in the fridge"], library, map=world, repeat=1)
    assert there.commanded == 0      # it is in the fridge already: nothing to do (planning.plan.already_so)


def test_no_commands_no_timings(library: Library) -> None:
    assert time_plans([], library) == []


def test_the_built_in_commands_run_from_one_clause_to_six(library: Library) -> None:
    rows = time_plans(BENCH_COMMANDS, library, repeat=1)
    assert min(r.commanded for r in rows) == 1 and max(r.commanded for r in rows) >= 6
    assert all(r.steps >= r.commanded for r in rows)


def test_a_command_of_a_file_that_cannot_be_planned_is_refused_at_its_line_before_any_is_timed(
        library: Library) -> None:
    import pytest

    from seal_cli.errors import SealError

    lines = [(1, "stir the cup"), (4, "  flibber the garage")]
    with pytest.raises(SealError) as caught:
        time_plans([t.strip() for _, t in lines], library, repeat=1, source=("c.txt", lines))
    assert str(caught.value).startswith("c.txt:4:3: unknown verb 'flibber'")   # was "column 1: ..." alone
