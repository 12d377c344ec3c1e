"""A question and the telling of its answer said beside it: one frame (seal_cli.language.reported)."""

from __future__ import annotations

import pytest

from seal_cli.frames.library import Library
from seal_cli.language.parser import parse_command


def frames(text: str, library: Library) -> list[str]:
    return [f.frame for f in parse_command(text, library).frames]


@pytest.mark.parametrize(("text", "frame"), [
    ("find out who is in the garage and tell me", "Tell"),
    ("check who is at the gate and let me know", "Tell"),
    ("see what's on the workbench and report back to me", "Tell"),
    ("What's the heaviest box in the attic? Tell me, please.", "Tell"),
    ("count the mugs on the shelf and let me know", "Count"),
    ("Is the oven on? Let me know.", "LookAt"),
    ("check whether there is bread in the box and tell me", "Find"),
    ("Tell me, who is on the porch?", "Tell"),
    ("let us know, how many mugs are on the shelf?", "Count"),
])
def test_a_question_and_its_telling_are_one_frame(text: str, frame: str, library: Library) -> None:
    assert frames(text, library) == [frame]


def test_the_question_keeps_its_words_and_takes_the_person_told(library: Library) -> None:
    (told,) = parse_command("find out who is in the garage and tell Maya", library).frames
    assert told.elements["message"].text == "who is in the garage"
    assert told.elements["recipient"].text == "Maya"
    (told,) = parse_command("check who is at the gate and let me know", library).frames
    assert told.elements["message"].text == "who is at the gate"          # "and let me know" is no part of it
    assert told.elements["recipient"].head == "me"


@pytest.mark.parametrize(("text", "want"), [
    ("find the dog and tell me", ["Find", "Tell"]),                        # a search commanded, then a report
    ("count the mugs and tell me the total", ["Count", "Tell"]),           # the telling says a message
    ("count the mugs and tell Maya", ["Count", "Tell"]),                   # another person, a count tells no one
    ("tell him that lunch is ready and let me know", ["Tell", "Tell"]),    # no question: two tellings
    ("who is in the garage? greet them", ["Tell", "Greet"]),
    ("count the mugs and tell it to Maya", ["Count", "Tell"]),            # a count tells no one
    ("tell me what is in the box and tell it to Maya", ["Tell", "Tell"]),  # two people told
])
def test_other_tellings_stay_frames_of_their_own(text: str, want: list[str], library: Library) -> None:
    assert frames(text, library) == want


def test_the_answer_told_again_as_it_is_the_question_told(library: Library) -> None:
    (told,) = parse_command("find out the name of the man in the shed and tell it to Maya", library).frames
    assert (told.frame, told.elements["message"].text) == ("Tell", "the name of the man in the shed")
    assert told.elements["recipient"].text == "Maya"


def test_later_pronouns_still_name_their_antecedent(library: Library) -> None:
    parse = parse_command("Is anyone in the den? Let me know, then greet them.", library)
    assert [f.frame for f in parse.frames] == ["Find", "Greet"]
    assert parse.frames[1].elements["theme"].refers_to == (0, "theme")


@pytest.mark.parametrize(("text", "frame", "question"), [
    ("look for the scissors and let me know", "Find", "where"),
    ("count the spoons and tell Nadia", "Count", "how many"),
])
def test_a_telling_that_stays_its_own_frame_tells_the_answer(text: str, frame: str, question: str,
                                                             library: Library) -> None:
    """The same pass that merges a question and its telling (words34: it was the evoker's answer_told before)."""
    before, told = parse_command(text, library).frames
    assert (before.frame, told.frame) == (frame, "Tell")
    assert (told.elements["message"].text, told.elements["message"].head) == ("", question)


def test_the_answer_is_told_only_after_a_frame_that_answers_one(library: Library) -> None:
    from seal_cli.language.reported import answer_of, told_answers
    assert answer_of(library, "Count") == "how many" and answer_of(library, "Find") == "where"
    assert answer_of(library, "Open") is None
    parse = parse_command("open the box and tell Nadia", library)
    assert told_answers(parse, library) is parse and "message" not in parse.frames[1].elements
