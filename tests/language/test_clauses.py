"""The clause passes: a clause of purpose read as a "to" phrase becomes a clause of its own."""

from __future__ import annotations

import pytest

from seal_cli.frames.library import Library
from seal_cli.language.parser import parse_command


def _frames(text: str, library: Library) -> list[tuple[str, dict[str, str | None]]]:
    return [(f.frame, {role: p.text for role, p in f.elements.items()}) for f in parse_command(text, library).frames]


@pytest.mark.parametrize(("text", "expected"), [
    ("carry the box to the porch to open", [("Bring", {"theme": "the box", "goal": "the porch"}),
                                            ("Open", {"theme": "the box"})]),        # its object: the box
    ("bring the jar to the counter to put spoon beside it",
     [("Bring", {"theme": "the jar", "goal": "the counter"}), ("Place", {"theme": "spoon", "goal": "it"})]),
    ("take a pear to the sink to rinse", [("Bring", {"theme": "a pear", "goal": "the sink"}),   # in hand: the
                                          ("Clean", {"theme": "", "instrument": None})]),       # pear, unsaid
])
def test_a_purpose_read_as_a_to_phrase_is_a_clause(library: Library, text: str, expected: list[object]) -> None:
    assert _frames(text, library) == expected


def test_a_purpose_takes_the_object_only_when_it_is_known_to_fit(library: Library) -> None:
    assert _frames("carry the crate to the porch to open", library)[1] == ("Open", {})   # a crate: not known
    frames = _frames("carry the box to the porch to open it", library)                  # said: its own
    assert frames[1][0] == "Open" and frames[1][1]["theme"] == "it"


def test_a_purpose_of_going_takes_no_object(library: Library) -> None:
    frames = _frames("grab the torch to go check the shed", library)
    assert frames[0] == ("Pick", {"theme": "the torch"}) and ("Go", {"theme": "the torch"}) not in frames
    assert all(elements.get("goal") != "the torch" for _, elements in frames)


@pytest.mark.parametrize(("text", "frames"), [
    ("move the mug to microwave", ["Place"]),                     # a thing the taxonomy knows: a place
])
def test_no_purpose_where_the_word_is_a_thing(library: Library, text: str, frames: list[str]) -> None:
    parse = parse_command(text, library)
    assert [f.frame for f in parse.frames if f.frame != "Cool"] == frames


@pytest.mark.parametrize(("text", "goal"), [
    ("move the jug from the shelf to trash can", "trash can"),     # "trash": a verb only before its object
    ("move the brush to dust pan", "dust pan"),
])
def test_no_purpose_where_the_verb_is_mostly_a_noun(library: Library, text: str, goal: str) -> None:
    """A word the library reads as a verb only opening a clause before its object (``opening``: "trash", "dust")
    is the noun it mostly is in a bare "to" phrase (alfred29)."""
    assert [(name, elements.get("goal")) for name, elements in _frames(text, library)] == [("Place", goal)]
    assert _frames("carry the jug to the hall to trash the wrapper", library)[-1] == ("Place", {"theme": "the wrapper"})


def test_a_purpose_read_as_a_to_phrase_keeps_what_follows_its_verb(library: Library) -> None:
    from seal_cli.language.clauses import Clauses
    from seal_cli.language.lexicon import Tagger, tokenize
    from seal_cli.language.parser import CommandParser
    from seal_cli.language.syntax import PP, Syntax

    text = "carry the jar to the counter to fold cups beside it"
    parser = CommandParser.of(library)
    words = Tagger(parser.lexicon, tokenize(text), text).run()
    command = Syntax(text, words, parser.types).transform(parser.tree(text, words))
    clauses = Clauses(text, library, parser.types, parser.lexicon.speech).passes(command)
    assert [c.verb.lower for c in clauses][0] == "carry"
    if len(clauses) == 2 and clauses[1].verb.lower == "fold":       # read by the tagger or by this pass
        assert [np.head_text for np in clauses[1].objects] == ["cup"]
        assert [x.prep for x in clauses[1].items if isinstance(x, PP)] == ["beside"]


@pytest.mark.parametrize(("text", "goals"), [
    ("put the pan in the fridge, then on the stove", ["the fridge", "the stove"]),       # the verb left out
    ("put a cup in the fridge and in the microwave", ["the fridge", "the microwave"]),
    ("put the bowl in fridge and then in cabinet", ["fridge", "cabinet"]),
    ("put a cup in fridge and in microwave", ["fridge", "microwave"]),                  # a thing, no verb
])
def test_a_second_place_said_without_the_verb_puts_the_same_thing(library: Library, text: str,
                                                                   goals: list[str]) -> None:
    parse = parse_command(text, library)
    places = [f for f in parse.frames if f.frame == "Place" and not f.inferred]
    assert [p.elements["goal"].text for p in places] == goals
    assert {parse.resolve(p.elements["theme"]).text for p in places} == {places[0].elements["theme"].text}



@pytest.mark.parametrize(("text", "expected"), [
    ("drop the pan on the table with a knife in it", [("Place", {"theme": "a knife", "goal": "the pan"}),
                                                      ("Place", {"theme": "the pan", "goal": "the table"})]),
    ("put a wine glass on the table with a spoon in it",
     [("Place", {"theme": "a spoon", "goal": "a wine glass"}),
      ("Place", {"theme": "a wine glass", "goal": "the table"})]),
    ("place a pan down on the table with a potato inside of it",   # a particle between: the verb's
     [("Place", {"theme": "a potato", "goal": "a pan"}), ("Place", {"theme": "a pan", "goal": "the table"})]),
    ("put a pan with a knife in it on the counter",                 # said before the place: as before
     [("Place", {"theme": "a knife", "goal": "a pan with a knife in it"}),
      ("Place", {"theme": "a pan with a knife in it", "goal": "the counter"})]),
])
def test_contents_said_after_the_place_are_the_carried_thing_s(library: Library, text: str,
                                                                 expected: list[object]) -> None:
    assert _frames(text, library) == expected


@pytest.mark.parametrize(("text", "expected"), [
    ("put the crate that has a melon in it on the porch",       # "that has X in it": "with X in it" (alfred23)
     [("Place", {"theme": "a melon", "goal": "the crate that has a melon in it"}),
      ("Place", {"theme": "the crate that has a melon in it", "goal": "the porch"})]),
    ("set the tray which holds a teapot on it on the bench",
     [("Place", {"theme": "a teapot", "goal": "the tray which holds a teapot on it"}),
      ("Place", {"theme": "the tray which holds a teapot on it", "goal": "the bench"})]),
    ("move the basket that contains the lemons to the porch",   # "that contains X": "containing X"
     [("Place", {"theme": "the lemons", "goal": "the basket that contains the lemons"}),
      ("Place", {"theme": "the basket that contains the lemons", "goal": "the porch"})]),
])
def test_what_a_relative_clause_says_a_thing_holds_is_its_contents(library: Library, text: str,
                                                                     expected: list[object]) -> None:
    assert _frames(text, library) == expected


def test_having_with_nothing_in_it_stays_a_relative_clause(library: Library) -> None:
    assert _frames("bring me the cup that has a chip", library) == [
        ("Bring", {"theme": "the cup", "recipient": "me"})]      # no contents, no second frame


@pytest.mark.parametrize("text", [
    "bring the newspaper to the table with the lamp on it",     # a newspaper holds nothing: the table's lamp
    "put the apple on the plate with a fork on it",             # the plate holds things: its fork
])
def test_contents_after_a_place_stay_the_place_s_otherwise(library: Library, text: str) -> None:
    frames = _frames(text, library)
    assert len(frames) == 1 and frames[0][1]["goal"].endswith("on it")


def test_a_quantifier_floated_after_a_pronoun_is_part_of_it(library: Library) -> None:
    assert _frames("put the apple in the bowl and put them both on the table", library)[1] == (
        "Place", {"theme": "them both", "goal": "the table"})                  # the place was lost
    assert _frames("put a spoon in a cup and move them both to the sink", library)[1] == (
        "Place", {"theme": "them both", "goal": "the sink"})                   # was Go to "them"
    parse = parse_command("put the apple in the bowl and put them both on the table", library)
    assert parse.resolve(parse.frames[1].elements["theme"]).head == "bowl"    # the bowl, carried with the apple
    assert _frames("give them all the apples", library) == [("Give", {"theme": "all the apples",
                                                                       "recipient": "them"})]


@pytest.mark.parametrize(("text", "expected"), [
    ("bring me the spoon from the kitchen and the cup from the family room",
     [("Bring", {"theme": "the spoon", "recipient": "me", "source": "the kitchen"}),
      ("Bring", {"theme": "the cup", "recipient": "me", "source": "the family room"})]),
    ("bring Anna the spoon from the kitchen and the cup from the bedroom",       # the person told: both times
     [("Bring", {"theme": "the spoon", "recipient": "Anna", "source": "the kitchen"}),
      ("Bring", {"theme": "the cup", "recipient": "Anna", "source": "the bedroom"})]),
    ("take the cup from the bedroom and the kettle from the kitchen to the table",   # a goal said once: both's
     [("Bring", {"theme": "the cup", "goal": "the table", "source": "the bedroom"}),
      ("Bring", {"theme": "the kettle", "goal": "the table", "source": "the kitchen"})]),
])
def test_each_thing_said_with_its_own_source_is_fetched_from_there(library: Library, text: str,
                                                                   expected: list[object]) -> None:
    """A source per conjunct (e2e19): "the kitchen and the cup from the family room" was one source of one Bring,
    and the plan brought the spoon twice, the second time from the cup."""
    assert _frames(text, library) == expected


def test_a_place_joined_to_a_source_without_a_source_of_its_own_stays_one_source(library: Library) -> None:
    (bring,) = parse_command("take the cup from the table and the shelf to the sink", library).frames
    assert [c.head for c in bring.elements["source"].conjuncts] == ["table", "shelf"]

@pytest.mark.parametrize(("text", "theme", "goal"), [
    ("put the bottle on the second from the bottom shelf", "the bottle", "the second from the bottom shelf"),
    ("put the plate in the cabinet closest to the stove", "the plate", "the cabinet closest to the stove"),
    ("put the mug on the shelf nearest to the door", "the mug", "the shelf nearest to the door"),
])
def test_which_of_a_row_or_the_one_nearest_something_describes_the_place(library: Library, text: str, theme: str,
                                                                          goal: str) -> None:
    assert _frames(text, library) == [("Place", {"theme": theme, "goal": goal})]


@pytest.mark.parametrize(("text", "expected"), [
    ("slice the apple in the pan", [("Slice", {"theme": "the apple in the pan", "instrument": None}),
                                    ("Place", {"theme": "the apple in the pan", "goal": "the pan"})]),
    ("cut a tomato inside a bowl with a knife",
     [("Slice", {"theme": "a tomato inside a bowl", "instrument": "a knife"}),
      ("Place", {"theme": "a tomato inside a bowl", "goal": "a bowl"})]),
])
def test_a_thing_cut_where_it_lies_in_a_container_leaves_its_pieces_there(library: Library, text: str,
                                                                           expected: list[object]) -> None:
    assert _frames(text, library) == expected


@pytest.mark.parametrize("text", [
    "slice the bread on the counter",       # a counter is no container: where it is cut, nothing more
    "slice the apple in the fridge",        # nor is a fridge (an appliance the taxonomy does not call one)
    "put the apple in the pan",             # no cut
])
def test_no_pieces_are_put_where_nothing_is_cut_in_a_container(library: Library, text: str) -> None:
    assert len(_frames(text, library)) == 1


@pytest.mark.parametrize(("text", "pairs"), [
    ("bring Anna the cup and Ben the spoon", [("cup", "Anna"), ("spoon", "Ben")]),
    ("give Tom the hammer and Priya the book", [("hammer", "Tom"), ("book", "Priya")]),
    ("bring Anna the cup and the spoon", [("cup", "Anna")]),          # one person: one frame, the things joined
])
def test_each_thing_to_its_own_person(library: Library, text: str, pairs: list[tuple[str, str]]) -> None:
    """"bring Anna the cup and Ben the spoon": a person and a thing, "and", another person and thing is a second
    clause with its verb left out (it was one Bring of "the cup and Ben", the spoon lost)."""
    frames = parse_command(text, library).frames
    assert [(f.elements["theme"].head, f.elements["recipient"].head) for f in frames] == pairs
