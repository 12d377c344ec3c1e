"""Constructions of people's wording (issue 13): bare questions, wishes, "let me know", phrases said
first, "in there", clauses said without a joint. Each on sentences of our own."""

from __future__ import annotations

import pytest

from seal_cli.frames.library import Library
from seal_cli.language.parser import CommandError, parse_command


def frames(text: str, library: Library) -> list[tuple[str, dict[str, str]]]:
    """Each frame with the heads of its said elements (the antecedent's head for a pronoun)."""
    parse = parse_command(text, library)
    return [(f.frame, {role: e.head for role, e in f.elements.items() if not e.default})
            for f in parse.frames]


@pytest.mark.parametrize(("text", "want"), [
    ("What's the tallest plant in the greenhouse?", "What's the tallest plant in the greenhouse"),
    ("who is waiting at the door?", "who is waiting at the door"),
    ("Which book on the shelf is the thickest?", "Which book on the shelf is the thickest"),
    ("what is under the bed", "what is under the bed"),
])
def test_a_bare_question_is_told(text: str, want: str, library: Library) -> None:
    parse = parse_command(text, library)
    (tell,) = parse.frames
    assert tell.frame == "Tell" and tell.elements["message"].text == want


def test_where_and_is_there_ask_to_find(library: Library) -> None:
    assert frames("where are my glasses?", library) == [("Find", {"theme": "glass"})]
    assert frames("Where's the stapler", library) == [("Find", {"theme": "stapler"})]
    assert frames("is there any milk in the fridge?", library) == [("Find", {"theme": "milk", "ground": "fridge"})]
    assert frames("how many chairs are in the attic?", library) == [("Count", {"theme": "chair", "ground": "attic"})]


def test_a_question_after_a_phrase_said_first(library: Library) -> None:
    (tell,) = parse_command("In the garage, what is on the workbench?", library).frames
    assert tell.frame == "Tell" and tell.elements["message"].text == "what is on the workbench"
    (count,) = parse_command("Of the guests in the lounge, how many are dancing?", library).frames
    assert count.frame == "Count" and count.elements["ground"].head == "lounge"
    assert frames("From the pantry, bring me the flour", library) == [
        ("Bring", {"theme": "flour", "recipient": "me", "source": "pantry"})]


@pytest.mark.parametrize("text", ["I'd like the blue towel", "Could I have a spoon, please?", "I need the stapler.",
                                  "may I have some water", "I would like a cushion from the sofa"])
def test_a_wish_for_a_thing_is_bring_to_the_speaker(text: str, library: Library) -> None:
    (bring,) = parse_command(text, library).frames
    assert bring.frame == "Bring"
    me = bring.elements["recipient"]
    assert (me.head, me.kind, me.text) == ("me", "person", "")       # the speaker, left unsaid


def test_a_wish_beside_a_request_is_a_statement(library: Library) -> None:
    (bring,) = parse_command("I need a hand, could you bring the box to the car?", library).frames
    assert bring.frame == "Bring" and bring.elements["theme"].head == "box"
    assert parse_command("I'd like you to open the window", library).frames[0].frame == "Open"


def test_let_someone_know_is_tell(library: Library) -> None:
    (tell,) = parse_command("let me know when the oven is hot", library).frames
    assert tell.frame == "Tell" and tell.elements["recipient"].head == "me"
    assert tell.elements["message"].text == "when the oven is hot"
    (tell,) = parse_command("Let Priya know that the taxi is here", library).frames
    assert (tell.frame, tell.elements["recipient"].head, tell.elements["message"].text) == \
        ("Tell", "Priya", "the taxi is here")
    assert frames("let me know how many eggs are left in the carton", library)[0][0] == "Count"


def test_in_there_is_the_place_named_before(library: Library) -> None:
    parse = parse_command("go to the garage and find the ladder in there", library)
    find = parse.frames[1]
    assert find.frame == "Find" and find.elements["ground"].head == "garage"
    assert find.elements["ground"].refers_to == (0, "goal")


@pytest.mark.parametrize(("text", "want"), [
    ("walk to the porch to greet Lena", ["Go", "Greet"]),
    ("go to the desk to meet the new intern", ["Go", "Meet"]),
    ("find my wallet so you can bring it to me", ["Find", "Bring"]),
    ("greet Tom at the entrance guide him to the lounge", ["Greet", "Guide"]),
    ("take the mug from the shelf put it in the sink", ["Pick", "Place"]),
])
def test_a_clause_inside_a_phrase_is_a_clause_of_its_own(text: str, want: list[str], library: Library) -> None:
    assert [f for f, _ in frames(text, library)] == want


def test_a_noun_that_is_a_verb_stays_a_noun(library: Library) -> None:
    assert [f for f, _ in frames("refrigerate a potato slice that is on a plate", library)] == ["Slice", "Cool"]
    assert [f for f, _ in frames("put the cup under the light on the table", library)] == ["Place"]


def test_no_question_without_a_clause(library: Library) -> None:
    with pytest.raises(CommandError):
        parse_command("what?", library)
