"""STRIPS semantics of grounded frames: what holds, what is unmet, what applying a frame does."""

from __future__ import annotations

from seal_cli.frames.library import Library
from seal_cli.frames.model import Element, Fact, Frame
from seal_cli.frames.taxonomy import Taxonomy
from seal_cli.planning.state import State, robot_facts


def test_robot_facts() -> None:
    assert robot_facts(None) == {Fact("hand_empty")}
    assert robot_facts("spoon") == {Fact("holding", ("spoon",))}


def test_negated_facts_hold_when_their_positive_does_not() -> None:
    state = State.of([Fact("open", ("fridge",))])
    assert state.holds(Fact("open", ("fridge",)))
    assert state.holds(Fact("open", ("oven",), negated=True))
    assert Fact("open", ("fridge",)) in state


def test_category_tests_are_decided_by_the_taxonomy() -> None:
    taxonomy = Taxonomy.of({"openable": ["fridge"], "place": ["table"]})
    state = State.of([], taxonomy)
    assert state.holds(Fact("openable", ("fridge",)))
    assert not state.holds(Fact("openable", ("table",)))      # known not to be openable
    assert state.holds(Fact("openable", ("hatch",)))          # nobody knows: benefit of the doubt


def test_unmet_keeps_the_frames_order(library: Library) -> None:
    look = library.frame("LookAt").bind({"theme": "clock", "instrument": "lamp"})
    state = State.of(robot_facts(None))
    assert [str(f) for f in state.unmet(look)] == ["holding(clock)", "toggled_on(lamp)"]
    assert [str(f) for f in State.of(robot_facts("clock")).unmet(look)] == ["toggled_on(lamp)"]


def test_apply_deletes_then_adds(library: Library) -> None:
    state = State.of([Fact("hand_empty"), Fact("in", ("egg", "fridge")), Fact("cold", ("egg",))])
    state = state.apply(library.frame("Pick").bind({"theme": "egg", "source": "fridge"}))
    assert str(state) == "{cold(egg), holding(egg)}"
    state = state.apply(library.frame("Heat").bind({"theme": "egg"}))
    assert str(state) == "{holding(egg), hot(egg)}"
    assert state.achieves(library.frame("Place").bind({"theme": "egg", "goal": "table"}), Fact("hand_empty"))


def test_frames_without_preconditions_are_always_applicable() -> None:
    wave = Frame("Wave", elements=(Element("theme", "person"),))
    assert State().applicable(wave.bind({"theme": "Roger"}))


def test_open_of_a_thing_that_cannot_close_always_holds(library: Library) -> None:
    state = State.of([Fact("hand_empty")], library.taxonomy, closable={"fridge"})
    assert state.holds(Fact("open", ("table",)))                  # a table is always open
    assert not state.holds(Fact("open", ("fridge",)))             # the fridge starts closed
    opened = state.apply(library.frame("Open").bind({"theme": "fridge"}))
    assert opened.holds(Fact("open", ("fridge",))) and opened.closable == frozenset({"fridge"})
    assert opened.apply(library.frame("Close").bind({"theme": "fridge"})).holds(Fact("open", ("fridge",), True))
    assert not State.of([]).holds(Fact("open", ("table",)))       # without closable, open is stored


def test_type_tests_use_the_class_of_a_named_thing(library: Library) -> None:
    state = State.of([], library.taxonomy, classes={"fridge_1": "fridge", "table_1": "table"})
    assert state.class_of("fridge_1") == "fridge" and state.class_of("cup") == "cup"
    assert state.holds(Fact("openable", ("fridge_1",)))
    assert not state.holds(Fact("openable", ("table_1",)))
    assert state.apply(library.frame("Open").bind({"theme": "fridge_1"})).class_of("table_1") == "table"
