"""Relation beliefs from the robot's state: Core, Other, Disjoint (SPEC, "SeFM: what the numbers mean")."""

from __future__ import annotations

import pytest

from seal_cli.frames.library import Library
from seal_cli.frames.model import Fact
from seal_cli.planning.state import State, robot_facts
from seal_cli.sefm.relations import (
    CORE,
    DISJOINT,
    OTHER,
    context_relations,
    element_relations,
    relations,
    spatial_roles,
)


def state(library: Library, holding: str | None = None, *extra: Fact, closable: tuple[str, ...] = ()) -> State:
    return State.of(robot_facts(holding) | set(extra), library.taxonomy, closable=closable or None)


def test_stir_with_an_empty_hand_is_near_the_spoon_first(library: Library) -> None:
    stir = library.frame("Stir").bind({"theme": "cup"})
    beliefs = element_relations(stir, state(library))
    assert beliefs == {"theme": OTHER, "instrument": CORE}


def test_holding_the_spoon_makes_it_disjoint_and_the_cup_core(library: Library) -> None:
    stir = library.frame("Stir").bind({"theme": "cup"})
    assert element_relations(stir, state(library, "spoon")) == {"theme": CORE, "instrument": DISJOINT}


def test_other_belief_is_a_parameter(library: Library) -> None:
    stir = library.frame("Stir").bind({"theme": "cup"})
    assert element_relations(stir, state(library), other=0.5)["theme"] == 0.5


def test_context_is_the_frame_achieving_the_next_unmet_precondition(library: Library) -> None:
    plan = [library.frame("Pick").bind({"theme": "cup"}), library.frame("Pick").bind({"theme": "spoon"}),
            library.frame("Stir").bind({"theme": "cup"})]
    assert context_relations(2, plan, state(library)) == {1: CORE}
    assert context_relations(2, plan, state(library, "spoon")) == {}  # met: Disjoint, left out
    assert context_relations(0, plan, state(library)) == {}


def test_later_unmet_preconditions_give_other_context(library: Library) -> None:
    look = library.frame("LookAt").bind({"theme": "book", "instrument": "lamp"})
    plan = [library.frame("Pick").bind({"theme": "book"}), library.frame("ToggleOn").bind({"theme": "lamp"}), look]
    assert context_relations(2, plan, state(library)) == {0: CORE, 1: OTHER}
    beliefs = element_relations(look, state(library))
    assert beliefs == {"theme": CORE, "instrument": OTHER}


def test_an_element_with_its_precondition_met_but_still_to_be_visited_is_not_disjoint(library: Library) -> None:
    place = library.frame("Place").bind({"theme": "apple", "goal": "fridge"})
    opened = state(library, "apple", Fact("open", ("fridge",)), closable=("fridge",))
    assert element_relations(place, opened) == {"theme": DISJOINT, "goal": CORE}
    shut = state(library, "apple", closable=("fridge",))
    assert element_relations(place, shut) == {"theme": DISJOINT, "goal": CORE}


def test_a_closed_source_is_the_next_step_of_pick(library: Library) -> None:
    pick = library.frame("Pick").bind({"theme": "cup", "source": "cabinet"})
    assert element_relations(pick, state(library, closable=("cabinet",))) == {"theme": OTHER, "source": CORE}


def test_a_step_without_elements_passes_core_to_the_next(library: Library) -> None:
    pick = library.frame("Pick").bind({"theme": "cup"})
    assert element_relations(pick, state(library, "spoon")) == {"theme": CORE}  # hand_empty names nothing


def test_words_are_not_places(library: Library) -> None:
    tell = library.frame("Tell").bind({"message": "joke", "recipient": "roger"})
    assert spatial_roles(tell) == ("recipient",)
    assert relations([tell], state(library))[0].elements == (("recipient", "roger", CORE),)


def test_all_disjoint_is_reported(library: Library) -> None:
    pick = library.frame("Pick").bind({"theme": "spoon"})
    (r,) = relations([pick], state(library, "spoon"))
    assert r.all_disjoint and r.element("theme") == DISJOINT
    with pytest.raises(KeyError):
        r.element("goal")


def test_said_where_reads_a_frame_that_takes_a_thing_out_of_a_place(library: Library) -> None:
    from seal_cli.sefm.relations import said_where

    plan = [library.frame("Pick").bind({"theme": "milk", "source": "larder_1"}),
            library.frame("Bring").bind({"theme": "milk", "recipient": "me", "source": "larder_1"}),
            library.frame("Pick").bind({"theme": "cup"}),
            library.frame("Place").bind({"theme": "cup", "goal": "sink_1"})]
    assert said_where(plan) == {"milk": ("larder_1",)}    # a goal is where it will be, not where it is


def test_said_where_skips_where_an_earlier_frame_puts_the_thing(library: Library) -> None:
    from seal_cli.sefm.relations import said_where

    plan = [library.frame("Pick").bind({"theme": "peas"}),
            library.frame("Bring").bind({"theme": "peas", "goal": "kitchen"}),
            library.frame("Pick").bind({"theme": "peas", "source": "kitchen"}),
            library.frame("Place").bind({"theme": "peas", "goal": "fridge_1"})]
    assert said_where(plan) == {}      # the kitchen is where the Bring puts the peas, not where they are
