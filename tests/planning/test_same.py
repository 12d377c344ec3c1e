"""A command's repeat said for another place or thing ("..., then the same for the hall"): refused where it is said,
never lost (seal_cli/planning/same.py)."""

from __future__ import annotations

import pytest

from seal_cli.errors import SealError
from seal_cli.frames.library import Library
from seal_cli.planning.problem import parse_to_plan
from seal_cli.planning.same import refuse_the_same


@pytest.mark.parametrize(("text", "said"), [
    ("switch off the lamp in the study and the same for the hall", "the same for the hall"),
    ("wipe the table, then do the same with the counter", "do the same with the counter"),
    ("shut the window in the bedroom. Same in the bathroom!", "Same in the bathroom"),
])
def test_the_same_for_something_else_is_refused_where_it_is_said(library: Library, text: str, said: str) -> None:
    with pytest.raises(SealError, match="repeats an instruction said before it for something else") as refused:
        parse_to_plan(text, library)
    assert refused.value.column == text.index(said) + 1 and f"'{said}'" in refused.value.message


@pytest.mark.parametrize("text", ["bring me the same cup", "put the cups in the same box", "the same for me"])
def test_same_that_repeats_nothing_before_it_is_left_to_the_parser(text: str) -> None:
    refuse_the_same(text)      # no repeat of an instruction said before it: nothing refused here


@pytest.mark.parametrize(("text", "told"), [
    ("tell Carla that the taxi is here and Ben as well", [("the_taxi_is_here", "carla"), ("the_taxi_is_here", "ben")]),
    ("tell Anna dinner is at seven, and Carla too", [("dinner_is_at_seven", "anna"), ("dinner_is_at_seven", "carla")]),
    ("tell Ben that the tea and the cake are ready", [("the_tea_and_the_cake_are_ready", "ben")]),    # no person
    ("tell Ben that the rain stopped and Bob too", [("the_rain_stopped_and_bob_too", "ben")]),   # Bob: not on the map
])
def test_a_message_for_another_person_too_is_told_to_them(library: Library, text: str,
                                                          told: list[tuple[str, str]]) -> None:
    """e2e25: "tell Ben that breakfast is ready and Anna as well" told Ben "breakfast is ready and Anna as well"."""
    from pathlib import Path

    from seal_cli.maps.formats.map_server import load_map
    from seal_cli.planning.problem import build_problem

    m = load_map(Path(__file__).resolve().parents[2] / "maps" / "guesthouse.yaml")
    commanded = build_problem(parse_to_plan(text, library), library, map=m).commanded
    assert [(b.elements["message"], b.elements["recipient"]) for b in commanded] == told
