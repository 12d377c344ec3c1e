"""PDDL export: the files read back, solved by an independent planner (unified-planning's pyperplan)
to a plan as long as seal's, and that plan replayed with seal's own semantics."""

from __future__ import annotations

import re
from pathlib import Path
from typing import Any

import pytest
from typer.testing import CliRunner

from seal_cli.cli import app
from seal_cli.errors import SealError
from seal_cli.frames.library import Library
from seal_cli.frames.model import Binding, Fact
from seal_cli.maps.formats.map_server import load_map
from seal_cli.pipeline import plan as plan_text
from seal_cli.planning.pddl import domain_pddl, problem_pddl, reading_name, readings, write_pddl
from seal_cli.planning.plan import Plan, plan
from seal_cli.planning.state import State, robot_facts
from seal_cli.resources import map_path
from tests.planning.test_plan import alfred_command, alfred_tasks

runner = CliRunner()


@pytest.fixture(scope="module")
def up() -> Any:
    """unified-planning, quiet, with the pyperplan engine."""
    pytest.importorskip("up_pyperplan")
    shortcuts = pytest.importorskip("unified_planning.shortcuts")
    shortcuts.get_environment().credits_stream = None
    return shortcuts


def solve(up: Any, folder: Path) -> list[tuple[str, list[str]]]:
    """Read domain.pddl and problem.pddl with unified-planning and solve them optimally with pyperplan."""
    from unified_planning.io import PDDLReader

    problem = PDDLReader().parse_problem(str(folder / "domain.pddl"), str(folder / "problem.pddl"))
    with up.OneshotPlanner(name="pyperplan", params={"search": "astar", "heuristic": "lmcut"}) as planner:
        result = planner.solve(problem)
    assert result.plan is not None, f"pyperplan found no plan: {result.status}"
    return [(a.action.name, [str(p) for p in a.actual_parameters]) for a in result.plan.actions]


def replay(actions: list[tuple[str, list[str]]], library: Library, result: Plan) -> State:
    """Run a PDDL plan with seal's semantics: each action a frame, ``unspecified_*`` left unfilled."""
    frames = {f"do_{frame.name}".lower(): frame for frame in library}
    frames |= {reading_name(frame).lower(): frame for frame in readings(library, result)}   # "put it on ..."
    state = result.initial
    for name, args in actions:
        frame = frames[name.lower()]
        binding = frame.bind({e.role: a for e, a in zip(frame.elements, args, strict=True)
                              if not a.startswith("unspecified_")})
        assert state.applicable(binding), f"{binding} cannot run in {state}"
        state = state.apply(binding)
    return state


def round_trip(up: Any, library: Library, result: Plan, folder: Path) -> list[tuple[str, list[str]]]:
    write_pddl(folder, library, result)
    actions = solve(up, folder)
    assert len(actions) == len(result.steps), (result.text, actions, [str(s) for s in result.steps])
    final = replay(actions, library, result)
    assert all(final.holds(f) for f in result.goal), (result.text, str(final))
    return actions


# -- the round trip ---------------------------------------------------------------------------------

EXTRA = ["stir the cup", "slice the apple and put it in the fridge", "put two apples in the fridge",
         "bring Roger a coffee from the kitchen", "slice the apple and examine it under the desk lamp",
         "go to the kitchen, pick up the cup and bring it to me"]


def test_round_trip_on_alfred_tasks(up: Any, library: Library, shared_data: Path, tmp_path: Path) -> None:
    import json

    from seal_cli.language.grounding import Vocabulary

    classes = json.loads((shared_data / "alfred" / "alfred_constants.json").read_text(encoding="utf-8"))["OBJECTS"]
    vocabulary = Vocabulary.of(classes)
    tasks = alfred_tasks(shared_data)
    assert len(tasks) >= 20 and len({t["task_type"] for t in tasks}) == 7
    for i, row in enumerate(tasks):
        folder = tmp_path / str(i)
        folder.mkdir()
        round_trip(up, library, plan_text(alfred_command(row), library, vocabulary=vocabulary), folder)


@pytest.mark.parametrize("text", EXTRA)
def test_round_trip_on_other_commands(up: Any, library: Library, tmp_path: Path, text: str) -> None:
    round_trip(up, library, plan_text(text, library), tmp_path)


def test_the_goal_does_not_fix_the_order(up: Any, library: Library, tmp_path: Path) -> None:
    """The problem's goal is what the command leaves behind: a PDDL planner may put the egg away
    before it cools the apple, which the command's order forbids seal to do."""
    result = plan_text("heat the egg, cool the apple and put the egg in the fridge", library)
    write_pddl(tmp_path, library, result)
    actions = solve(up, tmp_path)
    assert len(actions) < len(result.steps)
    assert all(replay(actions, library, result).holds(f) for f in result.goal)


def test_round_trip_on_a_map(up: Any, library: Library, tmp_path: Path) -> None:
    apartment = load_map(map_path("apartment"))
    result = plan_text("heat the apple and put it on the counter", library, map=apartment)
    actions = round_trip(up, library, result, tmp_path)
    assert ("do_open", ["fridge_1"]) in actions             # the apple is in the closed fridge
    problem = (tmp_path / "problem.pddl").read_text(encoding="utf-8")
    assert "(in apple fridge_1)" in problem and "(open fridge_1)" not in problem and "(open counter_1)" in problem


# -- what the files say -----------------------------------------------------------------------------

def _action(domain: str, name: str) -> str:
    return domain.split(f"(:action {name}\n")[1].split("(:action")[0]


def test_domain_has_one_typed_action_per_frame(library: Library) -> None:
    result = plan_text("bring Roger a coffee from the kitchen", library)
    domain = domain_pddl(library, result)
    assert domain.count("(:action ") == len(library)
    assert ":requirements :strips :typing)" in domain                  # no negative preconditions needed
    params = re.search(r":parameters \((.*)\)", _action(domain, "do_Give")).group(1)
    types = dict(re.findall(r"\?(\w+) - (\w+)", params))
    assert types["theme"] != types["recipient"] == "person_kind"      # nobody is handed to themselves
    pick = _action(domain, "do_Pick")
    assert "(hand_empty)" in pick and "(not (in ?theme ?source))" in pick
    assert "(in ?theme ?source)" in pick.split(":effect")[0]           # Pick takes the thing from where it is


def test_problem_lists_things_facts_and_goal(library: Library) -> None:
    result = plan_text("slice the apple and put it in the fridge", library)
    problem = problem_pddl(library, result)
    objects = re.search(r"\(:objects\n(.*?)\n  \)", problem, re.S).group(1)
    assert re.search(r"\bfridge\b.* - location_kind", objects) and "unspecified_location" in objects
    assert "(in apple unspecified_location)" in problem and "(in knife unspecified_location)" in problem
    assert "(is_cutter knife)" in problem and "(is_cutter apple)" not in problem   # no slicing apples with apples
    assert "(open fridge)" not in problem.split("(:goal")[0] and "(open apple)" in problem
    goal = problem.split("(:goal")[1]
    assert [line.strip() for line in goal.splitlines()[1:4]] == ["(sliced apple)", "(in apple fridge)", "(hand_empty)"]


def test_a_negative_goal_asks_for_negative_preconditions(library: Library) -> None:
    state = State.of([Fact("hand_empty"), Fact("open", ("fridge",))], library.taxonomy, {"fridge"})
    result = plan([library.frame("Close").bind({"theme": "fridge"})], library, state, text="close the fridge")
    assert ":negative-preconditions" in domain_pddl(library, result)
    assert "(not (open fridge))" in problem_pddl(library, result)


def test_clashing_names_are_refused(library: Library) -> None:
    state = State.of(robot_facts(None), library.taxonomy, set())
    result = plan([library.frame("Pick").bind({"theme": "hand_empty"})], library, state)
    with pytest.raises(SealError, match="'hand_empty' would name both a predicate and an object"):
        domain_pddl(library, result)


def test_two_frames_whose_names_differ_only_in_case_are_refused(tmp_path: Path) -> None:
    """Frames ``Zap`` and ``ZAP`` were written as the actions ``do_Zap`` and ``do_ZAP``: one action defined twice to a
    planner, which reads PDDL names without case (hostile21). The command line says so and writes neither file."""
    from typer.testing import CliRunner

    from seal_cli.cli import app

    frames = "".join(f"  - frame: {name}\n    lexical_units: [{unit}]\n    elements:\n      theme: {{type: object}}\n"
                     f"    actions: [navigate(theme)]\n    postconditions: [{fact}(theme)]\n"
                     for name, unit, fact in (("Zap", "zapple", "hot"), ("ZAP", "zopple", "cold")))
    (tmp_path / "f.yaml").write_text("frames:\n" + frames)
    (tmp_path / "out").mkdir()
    result = CliRunner().invoke(app, ["plan", "zapple the cup", "--framelib", f"+{tmp_path / 'f.yaml'}", "--pddl",
                                      str(tmp_path / "out")])
    assert result.exit_code == 1 and list((tmp_path / "out").iterdir()) == []
    assert "cannot export PDDL: the actions 'do_Zap' and 'do_ZAP' differ only in case" in result.stderr


# -- writing ----------------------------------------------------------------------------------------

def test_write_pddl_into_a_folder_whole(library: Library, tmp_path: Path) -> None:
    result = plan_text("stir the cup", library)
    (tmp_path / "domain.pddl").write_text("old", encoding="utf-8")
    paths = write_pddl(tmp_path, library, result)
    assert [p.name for p in paths] == ["domain.pddl", "problem.pddl"]
    assert paths[0].read_text(encoding="utf-8") == domain_pddl(library, result)
    assert sorted(p.name for p in tmp_path.iterdir()) == ["domain.pddl", "problem.pddl"]   # no temporary left


def test_a_bad_folder_is_a_clean_error(library: Library, tmp_path: Path) -> None:
    result = plan_text("stir the cup", library)
    with pytest.raises(SealError, match="does not exist"):
        write_pddl(tmp_path / "missing", library, result)
    (tmp_path / "file").write_text("", encoding="utf-8")
    with pytest.raises(SealError, match="is a file, not a folder"):
        write_pddl(tmp_path / "file", library, result)
    assert not (tmp_path / "missing").exists()


def test_cli_writes_pddl_that_reads_back(up: Any, library: Library, tmp_path: Path) -> None:
    result = runner.invoke(app, ["plan", "--json", "--pddl", str(tmp_path), "heat the egg and put it in the fridge"])
    assert result.exit_code == 0, result.output
    actions = solve(up, tmp_path)
    assert [name for name, _ in actions] == ["do_pick", "do_heat", "do_open", "do_place"]


def test_export_does_not_change_the_plan(library: Library) -> None:
    result = plan_text("slice the apple and put it in the fridge", library)
    before = [str(s) for s in result.steps]
    domain_pddl(library, result)
    problem_pddl(library, result)
    assert [str(s) for s in result.steps] == before and isinstance(result.steps[0].binding, Binding)


def test_a_goal_said_on_is_put_on_top_without_opening_it(up: Any, library: Library, tmp_path: Path) -> None:
    """"On" the bungalow's sideboard (it opens): no Open, in seal's plan and in the exported domain, whose
    own action for that reading needs no ``open``; "in" it still opens it, and writes no such action."""
    bungalow = load_map(map_path("bungalow"))
    on = plan_text("put the mug on the sideboard", library, map=bungalow)
    assert [str(s.binding) for s in on.steps] == ["Pick(theme=mug, source=coffee_table_1)",
                                                  "Place(theme=mug, goal=sideboard_1)"]
    assert Fact("open", ("goal",)) not in on.steps[-1].binding.frame.preconditions
    assert [a.name for a in on.steps[-1].binding.actions] == ["navigate", "place_on"]
    actions = round_trip(up, library, on, tmp_path)
    assert [name.lower() for name, _ in actions] == ["do_pick", "do_place_on_top"]
    domain = (tmp_path / "domain.pddl").read_text(encoding="utf-8")
    reading = domain[domain.index("(:action do_Place_on_top"):]
    assert "(holding ?theme)" in reading and "(open ?goal)" not in reading
    into = plan_text("put the mug in the sideboard", library, map=bungalow)
    assert [s.frame for s in into.steps] == ["Pick", "Open", "Place"]
    assert [a.name for a in into.steps[-1].binding.actions] == ["navigate", "place"]
    assert "do_Place_on_top" not in domain_pddl(library, into)


@pytest.mark.parametrize("text", ["stir the cup\nthen open the fridge", "stir the cup\u2028then open the fridge",
                                  "stir the cup\u2029 \t then open the fridge"])
def test_a_command_of_several_lines_stays_in_the_comment(library: Library, text: str) -> None:
    # its second line stood outside the ';' comment: neither file was PDDL (hostile16)
    result = plan_text(text, library)
    for pddl in (domain_pddl(library, result), problem_pddl(library, result)):
        first, second = pddl.splitlines()[:2]
        assert first.startswith("; ") and first.endswith("stir the cup then open the fridge")
        assert second.startswith("(define")
