"""The standard library: the SPEC's frames, roles and lexical units, indexed for the parser."""

from __future__ import annotations

import pytest

from seal_cli.errors import SealError
from seal_cli.frames.library import Library
from seal_cli.frames.reading import load_library
from seal_cli.planning.state import State, robot_facts

# The SPEC's table: frame -> element roles (part of the contract).
SPEC_FRAMES = {
    "Go": {"goal"}, "Find": {"theme", "ground"}, "Pick": {"theme", "source"}, "Place": {"theme", "goal"},
    "Bring": {"theme", "recipient", "goal", "source"}, "Give": {"theme", "recipient"},
    "Open": {"theme"}, "Close": {"theme"}, "ToggleOn": {"theme"}, "ToggleOff": {"theme"},
    "Heat": {"theme", "instrument"}, "Cool": {"theme", "instrument"}, "Clean": {"theme", "instrument"},
    "Slice": {"theme", "instrument"}, "LookAt": {"theme", "instrument"}, "Stir": {"theme", "instrument"},
    "Pour": {"theme", "goal"}, "Follow": {"theme", "source", "goal"}, "Guide": {"theme", "source", "goal"},
    "Meet": {"theme", "ground"}, "Greet": {"theme", "ground"}, "Tell": {"message", "recipient"},
    "Answer": {"theme", "recipient"}, "Count": {"theme", "ground"},
}

# Frames the project adds beyond the SPEC's table (its roles kept as the SPEC names them elsewhere).
PROJECT_FRAMES = {"Wait": {"theme", "ground"}}

# Lexical units the SPEC's table names for each frame.
SPEC_UNITS = {
    "Go": "go navigate move walk head", "Find": "find|locate|look for|search for|spot",
    "Pick": "pick up|take|grab|grasp|get|fetch", "Place": "put|place|set|leave|drop off",
    "Bring": "bring|deliver|fetch|carry|take", "Give": "give|hand|pass", "Open": "open", "Close": "close|shut",
    "ToggleOn": "turn on|switch on", "ToggleOff": "turn off|switch off", "Heat": "heat|warm|microwave",
    "Cool": "cool|chill", "Clean": "clean|wash|rinse", "Slice": "slice|cut|chop",
    "LookAt": "look at|examine|inspect", "Stir": "stir|mix", "Pour": "pour", "Follow": "follow",
    "Guide": "guide|escort|lead|take", "Meet": "meet", "Greet": "greet|salute|say hello to|introduce yourself to",
    "Tell": "tell|say", "Answer": "answer", "Count": "count|tell me how many",
}


def test_the_standard_library_has_the_spec_frames_and_roles(library: Library) -> None:
    assert {f.name: set(f.roles) for f in library} == SPEC_FRAMES | PROJECT_FRAMES


def test_wait_stays_where_it_is_told_and_does_nothing_there(library: Library) -> None:
    """"go to the kitchen and wait there", "wait for me in the hall": Wait drives to its ground if one is
    said and waits; who it waits for (the theme) is acted on by no primitive, so "here" stays a where."""
    wait = library.frame("Wait")
    assert tuple(library.evoked_by("wait")) == (wait,) and wait in library.evoked_by("wait for")
    assert {e.role: e.type for e in wait.elements} == {"theme": "person", "ground": "location"}
    assert [(a.name, a.args) for a in wait.actions] == [("navigate", ("ground",)), ("wait", ())]
    assert [a.name for a in wait.bind({}).actions] == ["wait"]         # "wait": nowhere to go first


@pytest.mark.parametrize("name", sorted(SPEC_UNITS))
def test_the_spec_lexical_units_evoke_their_frames(library: Library, name: str) -> None:
    units = SPEC_UNITS[name].replace(" ", "|") if name == "Go" else SPEC_UNITS[name]
    for unit in units.split("|"):
        assert library.frame(name) in library.evoked_by(unit), unit


def test_multiword_units_come_first(library: Library) -> None:
    units = library.units
    assert units.index("tell me how many") < units.index("tell")
    assert units.index("pick up") < units.index("pick")
    assert {f.name for f in library.evoked_by("take")} == {"Pick", "Bring", "Guide"}


def test_unknown_frame_lists_the_known_ones(library: Library) -> None:
    with pytest.raises(SealError, match=r"unknown frame 'Stirr' \(did you mean 'Stir'\?\); the library has .*Stir"):
        library.frame("Stirr")
    assert library.frame("stir").name == "Stir"


def test_loading_a_broken_library_raises_every_problem(tmp_path) -> None:
    bad = tmp_path / "bad.yaml"
    bad.write_text("frame: Whisk\nelements:\n  theme: {type: nothing_declared}\nactions: [fly(theme)]\n")
    with pytest.raises(SealError) as caught:
        load_library([bad])
    assert "nothing_declared" in str(caught.value) and "fly" in str(caught.value)


def test_frames_really_chain(library: Library) -> None:
    """Pick gives what Place, Stir and Heat need; Place gives back the empty hand Pick needs."""
    state = State.of(robot_facts(None), library.taxonomy)
    pick_spoon = library.frame("Pick").bind({"theme": "spoon"})
    stir = library.frame("Stir").bind({"theme": "cup"})
    assert state.unmet(stir) == (stir.preconditions[0],)
    holding = state.apply(pick_spoon)
    assert holding.applicable(stir)
    place = library.frame("Place").bind({"theme": "spoon", "goal": "table"})
    assert not holding.applicable(library.frame("Pick").bind({"theme": "cup"}))
    freed = holding.apply(place)
    assert freed.applicable(library.frame("Pick").bind({"theme": "cup"}))
    assert str(freed) == "{hand_empty, in(spoon, table)}"


def test_achievers_are_found_by_predicate(library: Library) -> None:
    assert {f.name for f in library.achievers("holding")} == {"Pick"}
    assert {f.name for f in library.achievers("hand_empty")} == {"Place", "Bring", "Give"}
    assert {f.name for f in library.achievers("open")} == {"Open"}
