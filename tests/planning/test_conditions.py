"""A condition seal run checks by looking (``seal_cli.planning.conditions``), and the run that checks it."""

from __future__ import annotations

import numpy as np
import pytest

from seal_cli.frames.library import Library
from seal_cli.language.parser import parse_command
from seal_cli.maps.formats.map_server import load_map
from seal_cli.pipeline import run_on_map
from seal_cli.planning.conditions import as_question, checked_condition
from seal_cli.sim.policies import make_policy


@pytest.mark.parametrize(("said", "question"), [
    ("if Tom is in the garage", "is Tom in the garage?"),
    ("if the mug is on the table", "is the mug on the table?"),
    ("if there is milk in the fridge", "is there milk in the fridge?"),
    ("if there's a cup on the desk", "is there a cup on the desk?"),
    ("when the water boils", None),          # waits for it to come true: not a question of now
    ("if it rains", None),                   # nothing the robot sees
    ("if the tea is ready", None),           # a state the robot does not see
    ("if there are two cups", None),         # no place said
    ("if the fridge is open", "is the fridge open?"),                # a state the robot sees (e2e21)
    ("if the coffee machine is still on", "is the coffee machine still on?"),
    ("if the dishwasher is not empty", "is the dishwasher not empty?"),
    ("if the fridge is open and cold", None),                         # more than one state word
    ("if the light in the office is on", "is the light on in the office?"),   # the place after the state
    ("if the mug is on the table", "is the mug on the table?"),       # "on" and a place: where it is
])
def test_a_condition_about_where_something_is_is_a_question(said: str, question: str | None) -> None:
    assert as_question(said) == question


def test_the_command_is_checked_only_under_one_condition_for_every_frame(library: Library) -> None:
    frames = parse_command("if Tom is in the garage, give him the hammer", library).frames
    assert checked_condition(frames) is not None and checked_condition(frames).question == "is Tom in the garage?"
    assert checked_condition(parse_command("give Tom the hammer", library).frames) is None


@pytest.mark.parametrize(("text", "acted", "said"), [
    ("if Tom is in the garage, give him the hammer", True, "handed hammer_1 to Tom"),
    ("if Priya is in the garage, give her the hammer", False, "'if Priya is in the garage' does not hold (no: "
                                                              "Priya is in the study"),
])
def test_the_run_checks_the_condition_first_and_acts_only_when_it_holds(library: Library, text: str, acted: bool,
                                                                         said: str) -> None:
    """The townhouse: Tom is in the garage, Priya in the study. The frames are done when the condition holds and
    not otherwise, which the run says (no warning that the condition is not checked)."""
    agent, result = run_on_map(load_map("townhouse"), text, library, make_policy("oracle"),
                               rng=np.random.default_rng(0))
    lines = [r.text for r in agent.records]
    assert result.completed and result.warnings == []
    assert any(line.startswith("checks first whether") for line in lines)
    assert any(said in line for line in lines)
    assert any(e.startswith("Give") for e in result.executed) == acted


@pytest.mark.parametrize(("text", "acted", "said"), [
    ("if the dishwasher is open, close it", True, "closed dishwasher_1"),
    ("if the fridge is open, close it", False,
     "'if the fridge is open' does not hold (no: fridge_1 is closed (as the map has it))"),
])
def test_a_state_condition_is_checked_by_looking_at_the_thing(library: Library, text: str, acted: bool,
                                                            said: str) -> None:
    """The lodge (e2e21): its dishwasher was left open, its fridge is shut. The robot looks at the thing first, as
    for "is the fridge open?", and closes it only if it is open."""
    agent, result = run_on_map(load_map("lodge"), text, library, make_policy("oracle"), rng=np.random.default_rng(0))
    lines = [r.text for r in agent.records]
    assert result.completed and result.warnings == []
    assert any(line.startswith("checks first whether") for line in lines) and any(said in line for line in lines)
    assert any(e.startswith("Close") for e in result.executed) == acted


def test_seal_plan_shows_the_check_before_the_steps(library: Library) -> None:
    """``seal plan`` on a map says what the run looks at first; with no condition, or none the robot checks, none."""
    from seal_cli.pipeline import plan

    found = plan("if Tom is in the garage, give him the hammer", library, map=load_map("townhouse"))
    assert found.check is not None and found.check.looks == ("Find(theme=tom, ground=garage)",)
    assert found.to_json()["check"] == {"condition": "if Tom is in the garage", "question": "is Tom in the garage?",
                                        "plan": ["Find(theme=tom, ground=garage)"]}
    assert [str(s) for s in found.steps] == ["Pick(theme=hammer, source=workbench_1)",
                                             "Give(theme=hammer, recipient=tom)"]
    state = plan("if the coffee machine is on, turn it off", library, map=load_map("office_floor"))
    assert state.check is not None and state.check.looks == ("LookAt(theme=coffee_machine_1)",)
    assert [str(s) for s in state.steps] == ["ToggleOff(theme=coffee_machine_1)"]
    assert plan("give Tom the hammer", library, map=load_map("townhouse")).check is None
    assert plan("when the water boils, turn off the stove", library, map=load_map("apartment")).check is None


@pytest.mark.parametrize(("text", "step"), [
    ("turn off the light in the office", "ToggleOff(theme=desk_lamp_1)"),      # "light": a lamp, by the room said
    ("is the light on in the office?", "LookAt(theme=desk_lamp_1)"),           # the place after the state
    ("if the light in the office is on, switch it off", "ToggleOff(theme=desk_lamp_1)"),  # "it": what was said
    ("if the coffee machine is on, turn it off", None),
])
def test_a_thing_named_in_a_condition_or_a_question_is_the_one_in_the_place_said(library: Library, text: str,
                                                                                  step: str | None) -> None:
    """The lodge has a floor lamp in the lounge (first on the map) and a desk lamp in the office (e2e21)."""
    from seal_cli.pipeline import plan

    if step is None:      # the office floor's coffee machine, by all the words the condition said
        assert [str(s) for s in plan(text, library, map=load_map("office_floor")).steps] == \
            ["ToggleOff(theme=coffee_machine_1)"]
        return
    assert [str(s) for s in plan(text, library, map=load_map("lodge")).steps] == [step]
