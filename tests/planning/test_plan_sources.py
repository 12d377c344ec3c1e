"""Where a thing is taken from: the state's precise place when it lies in what the command names,
else what the command names (issue #11: "bring me a cup from the kitchen")."""

from __future__ import annotations

import json

import pytest
from typer.testing import CliRunner

from seal_cli.cli import app
from seal_cli.frames.model import Fact
from seal_cli.frames.reading import standard_library
from seal_cli.planning.plan import plan
from seal_cli.planning.state import State, robot_facts

runner = CliRunner()


def planned(text: str) -> list[str]:
    result = runner.invoke(app, ["plan", "--map", "apartment", text, "--json"])
    assert result.exit_code == 0, result.output
    return [f"{s['frame']}({', '.join(f'{k}={v}' for k, v in s['elements'].items())})"
            for s in json.loads(result.stdout)["plan"]]


@pytest.mark.parametrize(("text", "expected"), [
    # the cup the map knows is on the coffee table, in the family room: the command's kitchen stands
    ("bring me a cup from the kitchen",
     ["Pick(theme=cup, source=kitchen)", "Bring(theme=cup, recipient=me, source=kitchen)"]),
    # the apple is in fridge_1, which is in the kitchen: the precise source, opened first
    ("bring me the apple from the kitchen",
     ["Open(theme=fridge_1)", "Pick(theme=apple, source=fridge_1)",
      "Bring(theme=apple, recipient=me, source=kitchen)"]),
    # the place named is the one the state knows
    ("take the cup from the coffee table to the kitchen",
     ["Pick(theme=cup, source=coffee_table_1)", "Bring(theme=cup, goal=kitchen, source=coffee_table_1)"]),
    # the room named holds the place the state knows
    ("bring me the cup from the family room",
     ["Pick(theme=cup, source=coffee_table_1)", "Bring(theme=cup, recipient=me, source=family_room)"]),
])
def test_the_source_is_the_commands_unless_the_known_place_lies_in_it(text: str, expected: list[str]) -> None:
    assert planned(text) == expected


def test_another_place_than_the_known_one_stands_as_said() -> None:
    library = standard_library()
    state = State.of({Fact("in", ("cup", "coffee_table_1")), *robot_facts(None)}, library.taxonomy, closable=(),
                     rooms={"coffee_table_1": "family_room", "counter_1": "kitchen"})
    bring = library.frame("Bring").bind({"theme": "cup", "recipient": "me", "source": "counter_1"})
    assert [str(b) for b in plan([bring], library, state).bindings][0] == "Pick(theme=cup, source=counter_1)"


def test_without_rooms_the_known_place_is_kept() -> None:
    """No map says where the places lie: nothing contradicts the stored fact, rule 2 stands."""
    library = standard_library()
    state = State.of({Fact("in", ("cup", "coffee_table")), *robot_facts(None)}, library.taxonomy, closable=())
    assert state.within("coffee_table", "kitchen") is None
    bring = library.frame("Bring").bind({"theme": "cup", "recipient": "me", "source": "kitchen"})
    assert str(plan([bring], library, state).bindings[0]) == "Pick(theme=cup, source=coffee_table)"


def test_within_reads_the_rooms() -> None:
    state = State.of((), rooms={"fridge_1": "kitchen", "sofa_1": "family_room"})
    assert state.within("fridge_1", "kitchen") is True and state.within("kitchen", "kitchen") is True
    assert state.within("sofa_1", "kitchen") is False and state.within("fridge_1", "sofa_1") is False
    assert state.apply(standard_library().frame("Open").bind({"theme": "fridge_1"})).rooms == state.rooms
