"""A phrase of a clause that no frame element takes lands where English puts it, is kept as a remark, or the
command is refused at it: never dropped silently (words31)."""

from __future__ import annotations

import pytest

from seal_cli.frames.library import Library
from seal_cli.language.lexicon import CommandError
from seal_cli.language.parser import parse_command
from seal_cli.language.syntax import NP, PP, Clause
from seal_cli.language.tokens import Word
from seal_cli.language.unplaced import EXPECTED, unplaced, unplaced_error


def _np(start: int, end: int, pronoun: str | None = None) -> NP:
    return NP(start, end, Word("x", start, end, "WORD"), pronoun=pronoun)


def test_a_phrase_is_placed_by_an_element_or_by_describing_a_noun(library: Library) -> None:
    go = library.frame("Go")
    place = library.frame("Place")
    cup, shelf, hall = _np(4, 11), _np(15, 24), _np(28, 36)
    on, into = PP("on", shelf, 12), PP("in", hall, 25)
    clause = Clause(Word("put", 0, 3, "VERB", "put"), [cup], [on, into], None, 0, 36)
    assert unplaced(clause, place, {"theme": cup, "goal": hall}, [(cup, on)]) == []
    assert unplaced(clause, place, {"theme": cup}, [(cup, on)]) == [into]        # "in the hall": no element
    assert unplaced(clause, place, {"theme": cup, "goal": shelf}, []) == [into]
    way = NP(5, 12, Word("way", 9, 12, "WORD"))                                   # "show them the way": the path
    told = Clause(Word("show", 0, 4, "VERB", "show"), [way], [], None, 0, 12)
    assert unplaced(told, library.frame("Guide"), {}, []) == []
    assert unplaced(told, library.frame("Open"), {}, []) == [way]                # no motion: a thing left over
    assert unplaced(told, go, {}, []) == []


def test_said_for_whom_is_no_phrase_left_over(library: Library) -> None:
    me, mug = _np(5, 7, pronoun="me"), _np(8, 13)
    clause = Clause(Word("find", 0, 4, "VERB", "find"), [me, mug], [PP("for", _np(18, 21, "her"), 14)], None, 0, 21)
    assert unplaced(clause, library.frame("Find"), {"theme": mug}, []) == []


def test_the_refusal_names_the_phrase_at_its_column() -> None:
    text = "go with the trolley please"
    error = unplaced_error(text, PP("with", _np(12, 19), 3), "Go", "go")
    assert error.expected == [EXPECTED]
    assert "'with the trolley'" in str(error) and "Go" in str(error)
    assert error.column == 4


@pytest.mark.parametrize(("text", "frame", "role", "head"), [
    ("of the mugs on the rack, how many are chipped?", "Count", "theme", "mug"),     # a partitive: what is counted
    ("of the kids in the den, how many are asleep?", "Count", "theme", "kid"),
])
def test_a_fronted_partitive_is_what_is_counted(library: Library, text: str, frame: str, role: str,
                                                head: str) -> None:
    (count,) = parse_command(text, library).frames
    assert count.frame == frame and count.elements[role].head == head


def test_a_state_after_are_says_which_are_counted(library: Library) -> None:
    (count,) = parse_command("how many jars are empty in the larder?", library).frames
    assert count.elements["theme"].head == "jar" and "empty" in count.elements["theme"].modifiers
    parse = parse_command("fetch the jam and tell me how many are left", library)
    assert parse.remarks == ("left",)                     # of a thing unsaid: kept as a remark, not lost


@pytest.mark.parametrize(("text", "remark"), [
    ("open the curtains a crack", "a crack"),             # a degree
    ("push the door shut a little bit", None),             # (another reading: not this rule's)
    ("cut the cheese, not too thick", "thick"),            # how, a bare gradable adjective
    ("pop over to the shed, will you, and fetch the rake", "you"),    # the one spoken to, in a tag question
])
def test_a_degree_or_manner_is_kept_as_a_remark(library: Library, text: str, remark: str | None) -> None:
    try:
        parse = parse_command(text, library)
    except CommandError as error:
        assert remark is None and error.expected != [EXPECTED]
        return
    if remark is not None:
        assert remark in parse.remarks


def test_a_number_of_portions_after_slicing_is_the_form(library: Library) -> None:
    (cut,) = parse_command("cut the loaf um six slices", library).frames
    assert cut.frame == "Slice" and cut.result == "six slices"


def test_what_the_same_is_compared_with_describes_it(library: Library) -> None:
    (place,) = parse_command("put the mug on the same shelf as the teapot", library).frames
    assert place.elements["goal"].head == "shelf" and place.elements["goal"].text == "the same shelf as the teapot"


@pytest.mark.parametrize(("text", "at"), [
    ("put the box a jar on the table", "a jar"),
    ("put the jar on the shelf the teapot", "the teapot"),
])
def test_a_phrase_no_frame_takes_is_refused_at_it(library: Library, text: str, at: str) -> None:
    with pytest.raises(CommandError) as caught:
        parse_command(text, library)
    assert caught.value.expected == [EXPECTED]
    assert caught.value.column == text.index(at) + 1


def test_going_with_a_thing_to_a_place_takes_it_there(library: Library) -> None:
    (bring,) = parse_command("go with the laundry basket to the bedroom", library).frames
    assert bring.frame == "Bring"
    assert (bring.elements["theme"].head, bring.elements["goal"].head) == ("basket", "bedroom")
    (guide,) = parse_command("go with Sam to the kitchen", library).frames       # a person: as before
    assert guide.frame == "Guide"


def test_handing_over_said_with_only_a_place_puts_it_there(library: Library) -> None:
    frames = parse_command("grab the salad, chill it and serve on the big plate", library).frames
    assert [f.frame for f in frames] == ["Pick", "Cool", "Place"]
    assert frames[2].elements["goal"].head == "plate"
