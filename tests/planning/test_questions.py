"""What a command asks: the kind of answer each Find, Count or Tell wants, from the words that evoked it."""

from __future__ import annotations

import pytest

from seal_cli.errors import SealError
from seal_cli.frames.library import Library
from seal_cli.language.grounding import vocabulary_of_map
from seal_cli.language.parser import parse_command
from seal_cli.maps.formats.map_server import load_map
from seal_cli.planning.grounding import MapNames
from seal_cli.planning.problem import build_problem, parse_to_plan
from seal_cli.planning.questions import Question, fact_asked, name_asked, read_questions, reports, told_first


def asked(text: str, library: Library) -> list[tuple[str, Question]]:
    m = load_map("apartment")
    parse = parse_command(text, library, vocabulary_of_map(m))
    commanded = build_problem(parse, library, map=m.known()).commanded
    return [(str(b), q) for b, q in read_questions(parse, commanded, MapNames(m, library.taxonomy)).items()]


@pytest.mark.parametrize(("text", "frame", "question"), [
    ("is there a cup in the kitchen?", "Find(theme=cup, ground=kitchen)", Question("whether")),
    ("are there any spoons in the bedroom?", "Find(theme=spoon, ground=bedroom)", Question("whether")),
    ("is Ben in the kitchen?", "Find(theme=ben, ground=kitchen)", Question("whether")),
    ("is the apple in the fridge?", "Find(theme=apple, ground=fridge_1)", Question("whether")),
    ("anyone in the bedroom?", "Find(theme=person, ground=bedroom)", Question("whether")),
    ("any apples in the fridge?", "Find(theme=apple, ground=fridge_1)", Question("whether")),
    ("where is the cup?", "Find(theme=cup)", Question("where")),
    ("find the cup in the kitchen", "Find(theme=cup, ground=kitchen)", Question("where")),
    ("how many cups are in the family room?", "Count(theme=cup, ground=family_room)", Question("how_many")),
    ("what is on the dining table?", "Tell(message=what_is_on_the_dining_table)",
     Question("what", "dining_table_1", "on")),
    ("what's in the fridge?", "Tell(message=what_s_in_the_fridge)", Question("what", "fridge_1", "in")),
    ("who is in the kitchen?", "Tell(message=who_is_in_the_kitchen)", Question("what", "kitchen", "in", "person")),
])
def test_each_question_is_read_from_its_words(text: str, frame: str, question: Question, library: Library) -> None:
    assert asked(text, library) == [(frame, question)]


@pytest.mark.parametrize(("text", "frame", "question"), [
    ("who is in the kitchen right now?", "Tell(message=who_is_in_the_kitchen_right_now)",
     Question("what", "kitchen", "in", "person")),
    ("what's on the dining table at the moment", "Tell(message=what_s_on_the_dining_table_at_the_moment)",
     Question("what", "dining_table_1", "on")),
])
def test_words_after_the_place_a_question_asks_about_leave_it_that_place(text: str, frame: str, question: Question,
                                                                        library: Library) -> None:
    """"who is in the kitchen right now?" was said back as it was asked: "the kitchen right now" named no room."""
    assert asked(text, library) == [(frame, question)]


@pytest.mark.parametrize("text", ["who is in the garage?", "what's in the dishwasher right now?"])
def test_a_question_about_a_room_or_fixed_thing_the_map_lacks_is_refused_at_the_question(text: str,
                                                                                      library: Library) -> None:
    with pytest.raises(SealError) as refused:
        asked(text, library)
    assert "the apartment has no" in refused.value.message
    assert refused.value.where.column == 1


@pytest.mark.parametrize(("text", "question"), [
    ("tell me the name of the person in the kitchen", Question("what", "kitchen", "in", "person")),
    ("give me the names of the people in the bedroom", Question("what", "bedroom", "in", "person")),
    ("tell me the name of the woman at the dining table", Question("what", "dining_table_1", "at", "person")),
])
def test_the_name_of_someone_somewhere_asks_who_is_there(text: str, question: Question, library: Library) -> None:
    """The run said "name" to the speaker (the message's head) and drove nowhere (lead, stop 42)."""
    got = [q for _, q in asked(text, library)]
    assert got and all(q == question for q in got)


def test_the_name_of_a_thing_somewhere_asks_what_is_there(library: Library) -> None:
    """words43: the run said "name" to the speaker; the question is what (such a thing) is there."""
    assert asked("tell me the name of the book on the coffee table", library) == [
        ("Tell(message=what_book_is_on_the_coffee_table, recipient=me)",
         Question("what", "coffee_table_1", "on", "thing"))]
    assert asked("tell me the names of the things in the fridge", library) == [
        ("Tell(message=what_things_are_in_the_fridge, recipient=me)", Question("what", "fridge_1", "in", "thing"))]
    with pytest.raises(SealError, match="the apartment has no garden"):
        asked("tell me the name of the person in the garden", library)


@pytest.mark.parametrize(("text", "frame"), [
    ("tell me the names of the people in the kitchen", "Tell(message=who_is_in_the_kitchen, recipient=me)"),
    ("tell Ben the name of the man at the desk", "Tell(message=who_is_at_the_desk, recipient=ben)"),
    ("tell me the names", "Tell(message=name, recipient=me)"),          # a message is said once, plural or not
])
def test_a_message_asking_for_names_is_the_question_it_asks_and_said_once(text: str, frame: str,
                                                                          library: Library) -> None:
    """The plan's message was "name" ("names": a Tell of "name" and another of "another name")."""
    assert [str(b) for b in _commanded(text, library)] == [frame]


def _commanded(text: str, library: Library) -> list[object]:
    m = load_map("apartment")
    return list(build_problem(parse_command(text, library, vocabulary_of_map(m)), library, map=m.known()).commanded)


@pytest.mark.parametrize(("message", "question"), [
    ("the name of the person in the office", "who is in the office"),
    ("the names of the people at the door", "who is at the door"),
    ("name of the woman by the window", None),                     # "by" names no place a question looks at
    ("the name of the biggest book on the shelf", "what biggest book is on the shelf"),
    ("the names of the toys in the box", "what toys are in the box"),
    ("the name of the person", None),                               # no place: no question of what is there
    ("the name of in the box", None),
    ("the gesture of the person in the office", None),              # not a name
])
def test_the_question_a_message_asking_for_names_asks(message: str, question: str | None, library: Library) -> None:
    assert name_asked(message, library.taxonomy) == question


def test_a_message_that_asks_nothing_of_the_map_is_no_question(library: Library) -> None:
    assert asked("tell me a joke", library) == []
    assert asked("what is on the moon?", library) == []            # a place the map lacks: nothing to look at
    assert asked("go to the kitchen", library) == []


def test_the_time_or_the_date_asked_for_is_a_fact_the_robot_tells(library: Library) -> None:
    time = Question("fact", relation="time")
    assert asked("what is the time?", library) == [("Tell(message=what_is_the_time)", time)]
    assert asked("tell Anna the time", library) == [("Tell(message=time, recipient=anna)", time)]
    assert [q for _, q in asked("tell Ben what day it is", library)] == [Question("fact", relation="day")]
    assert [q for _, q in asked("tell me the date", library)] == [Question("fact", relation="date")]
    assert fact_asked("the time of the meeting") is None             # more than the time: no fact of the clock
    assert fact_asked("time") == "time" and fact_asked("what time is it right now") == "time"


def test_a_fact_asked_of_today_is_told_however_the_possessive_is_written(library: Library) -> None:
    date = Question("fact", relation="date")
    assert [q for _, q in asked("tell me today's date", library)] == [date]     # "today" was read as when
    assert [q for _, q in asked("what's today's date?", library)] == [date]
    assert fact_asked("what’s the time") == "time"
    assert fact_asked("tomorrow's date") is None                     # not the clock's date: nothing made up


def test_a_question_kind_is_checked() -> None:
    with pytest.raises(ValueError, match="one of where, whether, how_many, what"):
        Question("why")


def test_looking_somewhere_for_nothing_in_particular_asks_what_is_there(library: Library) -> None:
    assert asked("look in the fridge", library) == [("Find(ground=fridge_1)", Question("what", "fridge_1", "in"))]
    assert asked("look around the kitchen", library) == [("Find(ground=kitchen)", Question("what", "kitchen", "in"))]


def test_seeing_whether_asks_whether(library: Library) -> None:
    from seal_cli.planning.questions import asks_whether

    for text, whether in (("see if anyone is in the kitchen", True),
                          ("check whether there is milk in the fridge", True),
                          ("find Anna if she is in the kitchen", False), ("find the cup", False)):
        (find,) = parse_command(text, library).frames
        assert asks_whether(text, find) is whether, text


def test_a_state_question_keeps_where_the_thing_is(library: Library) -> None:
    assert asked("is the window open in the bedroom?", library) == [
        ("LookAt(theme=window)", Question("state", "bedroom", "open"))]
    assert asked("is the stove still on in the kitchen?", library) == [
        ("LookAt(theme=stove_1)", Question("state", "kitchen", "still on"))]
    assert asked("is the stove still on?", library) == [("LookAt(theme=stove_1)", Question("state", None, "still on"))]
    negated = Question("state", None, "not open")
    assert asked("is the fridge not open?", library) == [("LookAt(theme=fridge_1)", negated)]


def test_a_message_asking_for_what_an_earlier_frame_found_reports_it(library: Library) -> None:
    """"find the cup and tell me where it is": the Tell reports the Find's answer; a message that asks
    nothing ("hello") or a Tell with no question before it is said as it is."""
    report = Question("report")
    assert [q for _, q in asked("find the cup and tell me where it is", library)] == [Question("where"), report]
    assert [q for _, q in asked("look for the spoon and tell me what you found", library)][-1] == report
    assert [q for _, q in asked("find the apple and report its location to me", library)][-1] == report
    assert [q for _, q in asked("find the cup and tell Ben where it is", library)][-1] == report
    assert [q for _, q in asked("find the cup and tell me hello", library)] == [Question("where")]
    assert asked("go to the kitchen and tell me where you are", library) == []   # nothing asked before it
    assert reports("where it is") and reports("its location") and not reports("hello")
    assert not reports("that you are here")     # a pronoun of the speaker or the robot points at nothing sought


def test_what_is_seen_after_going_somewhere_asks_what_is_there(library: Library) -> None:
    """"go to the bedroom and tell me what you see": the message names no place, so it asks what is where the
    Go took the robot; a message that asks something else, or names its own place, keeps its reading."""
    assert [q for _, q in asked("go to the bedroom and tell me what you see", library)] == [
        Question("what", "bedroom", "in")]
    assert [q for _, q in asked("go to the kitchen and tell me who is there", library)] == [
        Question("what", "kitchen", "in", "person")]
    assert [q for _, q in asked("go to the dining table and tell me what you can see", library)] == [
        Question("what", "dining_table_1", "on")]
    assert [q for _, q in asked("go to the kitchen and tell me what you see in the fridge", library)] == [
        Question("what", "fridge_1", "in")]
    assert asked("go to the kitchen and tell me what you think", library) == []     # asks no looking
    assert asked("tell me what you see", library) == []                             # nowhere gone: nothing to name


def told(text: str, library: Library) -> list[tuple[str, Question | None]]:
    """Each commanded frame of ``text`` as the planner reads it on the apartment, with its question."""
    m = load_map("apartment")
    parse = parse_to_plan(text, library, vocabulary_of_map(m))
    commanded = build_problem(parse, library, map=m.known()).commanded
    questions = read_questions(parse, commanded, MapNames(m, library.taxonomy))
    return [(str(b), questions.get(b)) for b in commanded]


@pytest.mark.parametrize(("text", "first", "question"), [
    ("tell Ben where the spoon is", "Find(theme=spoon)", Question("where")),
    ("tell Anna where Ben is", "Find(theme=ben)", Question("where")),
    ("tell Anna how many cups are in the family room", "Count(theme=cup, ground=family_room)",
     Question("how_many")),
    ("tell Ben whether the fridge is open", "LookAt(theme=fridge_1)", Question("state", None, "open")),
])
def test_a_question_told_to_someone_is_found_out_first_and_then_reported(
        text: str, first: str, question: Question, library: Library) -> None:
    """"tell Ben where the spoon is": the robot finds the spoon (as for "do you know where the spoon is?"),
    then tells Ben what it found, not the words "where the spoon is"."""
    steps = told(text, library)
    assert steps[0] == (first, question)
    assert steps[-1][0].startswith("Tell(") and steps[-1][1] == Question("report")


@pytest.mark.parametrize("text", ["tell Ben hello", "tell Anna the time", "tell Ben what is on the dining table",
                                  "tell Ben who is in the kitchen", "find the cup and tell Ben where it is",
                                  "tell Ben where you are going"])
def test_a_message_that_the_tell_answers_itself_or_that_asks_nothing_findable_gets_no_frame_first(
        text: str, library: Library) -> None:
    """Said as it is, a fact of the clock, what or who is somewhere (the Tell looks), a question already
    answered by an earlier frame, or one whose words the robot cannot ask of itself."""
    m = load_map("apartment")
    parse = parse_command(text, library, vocabulary_of_map(m))
    assert parse_to_plan(text, library, vocabulary_of_map(m)) == parse


def test_the_frames_found_out_first_lie_on_the_message_words(library: Library) -> None:
    m = load_map("apartment")
    text = "please tell Ben where the spoon is"
    parse = told_first(parse_command(text, library, vocabulary_of_map(m)),
                       lambda said: parse_command(said, library, vocabulary_of_map(m)))
    find, tell = parse.frames
    assert find.frame == "Find" and tell.frame == "Tell"
    assert text[find.span[0]:find.span[1]] in ("where the spoon", "where the spoon is")   # the parser drops "is"
    theme = find.elements["theme"]
    assert theme.span is None or text[theme.span[0]:theme.span[1]] == "the spoon"


@pytest.mark.parametrize(("text", "step"), [
    ("ask ben whether he is hungry", "Tell(message=are_you_hungry, recipient=ben)"),
    ("ask Anna if she wants coffee", "Tell(message=do_you_want_coffee, recipient=anna)"),
    ("find out if anna wants coffee", "Tell(message=do_you_want_coffee, recipient=anna)"),
])
def test_a_question_put_to_a_person_is_asked_not_found_out_first(text: str, step: str, library: Library) -> None:
    """"ask ben whether he is hungry" was LookAt(he), a whole-house search for "He", then the words said (e2e19): the
    question is the person's to answer, asked of them as they hear it."""
    assert told(text, library) == [(step, Question("asked"))]


@pytest.mark.parametrize(("text", "frame", "question"), [
    ("is there anything in the fridge?", "Find(ground=fridge_1)", Question("what", "fridge_1", "in")),
    ("is there something on the dining table", "Find(ground=dining_table_1)", Question("what", "dining_table_1", "on")),
    ("are there anything in the kitchen", "Find(ground=kitchen)", Question("what", "kitchen", "in")),
])
def test_whether_any_thing_at_all_is_somewhere_asks_what_is_there(text: str, frame: str, question: Question,
                                                                  library: Library) -> None:
    m = load_map("apartment")
    parse = parse_to_plan(text, library, vocabulary_of_map(m))
    commanded = build_problem(parse, library, map=m.known()).commanded
    assert [(str(b), q) for b, q in read_questions(parse, commanded, MapNames(m, library.taxonomy)).items()] == \
        [(frame, question)]


def test_a_kind_or_a_person_asked_of_somewhere_is_still_whether(library: Library) -> None:
    m = load_map("apartment")
    for text, frame in (("is there a cup in the kitchen?", "Find(theme=cup, ground=kitchen)"),
                        ("is there anyone in the kitchen?", "Find(theme=person, ground=kitchen)"),
                        ("is there anything and a cup in the kitchen?", None)):
        try:
            parse = parse_to_plan(text, library, vocabulary_of_map(m))
            commanded = build_problem(parse, library, map=m.known()).commanded
        except SealError:
            assert frame is None            # "anything and a cup": a kind of nothing still refused, not dropped
            continue
        assert [str(b) for b in commanded] == [frame]
        assert set(read_questions(parse, commanded, MapNames(m, library.taxonomy)).values()) == {Question("whether")}


@pytest.mark.parametrize(("text", "every"), [
    ("where are the cups?", True),
    ("where can I find cups?", True),
    ("where did you see the cups?", True),
    ("where is the cup?", False),
    ("where are my glasses?", False),        # a pair: one thing
    ("where are my keys?", False),           # a person's keys: one bunch
    ("where are the two cups?", False),      # those two
    ("find the cups", False),                # a command, not a question of where
])
def test_a_where_question_of_a_kind_in_the_plural_asks_for_every_one(text: str, every: bool,
                                                                      library: Library) -> None:
    """e2e34: "where are the towels?" planned one Find per towel; it is one question whose answer says where each
    one is."""
    got = asked(text, library)
    assert [q.every for _, q in got][:1] == [every]
    if every:
        assert got == [("Find(theme=cup)", Question("where", every=True))]
