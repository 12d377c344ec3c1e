"""A yes/no question put to a person (``seal_cli.language.asking``): the indirect question as the person hears it."""

from __future__ import annotations

import pytest

from seal_cli.frames.library import Library
from seal_cli.language.asking import direct_question, person_subject
from seal_cli.language.parser import parse_command


@pytest.mark.parametrize(("said", "asked", "question"), [
    ("if he wants tea", "", "do you want tea?"),
    ("whether he is hungry", "", "are you hungry?"),
    ("if anna wants coffee", "anna", "do you want coffee?"),
    ("if she can come to the garage", "", "can you come to the garage?"),
    ("if she wanted her coffee hot", "", "did you want your coffee hot?"),
    ("if he has seen the keys", "", "have you seen the keys?"),
    ("whether he has a pen", "", "do you have a pen?"),
    ("if they are coming", "", "are you coming?"),
    ("if the tea is ready", "Raj", "is the tea ready?"),                 # not the person asked: the subject stays
    ("if Edith needs help", "Raj", "does Edith need help?"),
    ("if he has seen her keys", "", "have you seen her keys?"),          # "her" is someone else after "he"
    ("whether the yoga class is full", "Rosa", "is the yoga class full?"),  # e2e33: "class" is no verb's -s form
    ("if the red glass breaks", "Rosa", "does the red glass break?"),
])
def test_an_indirect_question_is_put_as_the_person_hears_it(said: str, asked: str, question: str) -> None:
    assert direct_question(said.split(), asked.split()) == question


@pytest.mark.parametrize(("said", "asked", "question"), [
    ("if he doesn't want tea", "", "don't you want tea?"),              # the negation goes first with its verb
    ("if he does not want tea", "", "do you not want tea?"),            # said in full, it stays after the subject
    ("whether she isn't hungry", "", "aren't you hungry?"),
    ("if he can't come", "", "can't you come?"),
    ("if they won't stay for lunch", "", "won't you stay for lunch?"),
    ("if he hasn't seen his keys", "", "haven't you seen your keys?"),
    ("if Anna wasn't there", "Anna", "weren't you there?"),
    ("if the tea isn't ready", "Raj", "isn't the tea ready?"),           # another subject stays
    ("if he doesn\u2019t want tea", "", "don't you want tea?"),          # a typographic apostrophe
])
def test_a_negated_indirect_question_is_put_as_the_person_hears_it(said: str, asked: str, question: str) -> None:
    """e2e23: "ask Ben if he doesn't want tea" put "if he doesn't want tea" to Ben as said."""
    assert direct_question(said.split(), asked.split()) == question


def test_ask_a_negated_question_puts_it_to_the_person(library: Library) -> None:
    (tell,) = parse_command("ask Ben if he doesn't want tea", library).frames
    assert (tell.frame, tell.elements["message"].head, tell.elements["recipient"].head) == \
        ("Tell", "don't you want tea?", "Ben")


@pytest.mark.parametrize("said", ["he wants tea", "if", "if he", "that he wants tea"])
def test_words_that_are_no_indirect_yes_no_question_give_none(said: str) -> None:
    assert direct_question(said.split()) is None


@pytest.mark.parametrize(("words", "size"), [
    ("anna wants coffee", 1), ("Ben is hungry", 1), ("the guest is staying", 2), ("my mother needs help", 2),
    ("the soup needs salt", 0), ("it is raining", 0), ("there is milk", 0), ("milk is left", 0),
])
def test_a_person_as_the_subject_of_a_question(words: str, size: int) -> None:
    assert person_subject(words.split(), {"guest", "mother"}, {"milk", "soup"}) == size


def test_ask_puts_the_question_to_the_person_told(library: Library) -> None:
    (tell,) = parse_command("ask Raj if he wants tea", library).frames
    message = tell.elements["message"]
    assert (tell.frame, message.text, message.head, tell.elements["recipient"].head) == \
        ("Tell", "if he wants tea", "do you want tea?", "Raj")


def test_a_question_with_a_verb_inside_is_one_message_not_a_clause_of_its_own(library: Library) -> None:
    """"ask Priya if she can come to the garage" was Tell("if she can") and Go(garage): the robot went itself."""
    (tell,) = parse_command("ask Priya if she can come to the garage", library).frames
    assert tell.elements["message"].head == "can you come to the garage?"


def test_find_out_whether_a_person_wants_something_is_asking_them(library: Library) -> None:
    (tell,) = parse_command("find out if anna wants coffee", library).frames
    assert (tell.frame, tell.lexical_unit, tell.elements["recipient"].head, tell.elements["recipient"].kind,
            tell.elements["message"].head) == ("Tell", "ask", "anna", "person", "do you want coffee?")
    (tell,) = parse_command("check whether the guest is staying for dinner", library).frames
    assert tell.elements["recipient"].text == "the guest" and tell.elements["message"].head == \
        "are you staying for dinner?"


@pytest.mark.parametrize(("text", "frame"), [
    ("check if the door is closed", "LookAt"),           # a thing's state: looked at
    ("could you see if the baby is asleep", "LookAt"),   # a state said with "be": looked at, not asked
    ("see if Ben is in the kitchen", "Find"),            # where a person is: looked for
    ("tell Raj that dinner is ready", "Tell"),
])
def test_questions_of_things_and_places_are_not_asked_of_anyone(library: Library, text: str, frame: str) -> None:
    frames = parse_command(text, library).frames
    assert frames[0].frame == frame
    assert all(not f.elements.get("message") or not f.elements["message"].head.endswith("?") for f in frames)


@pytest.mark.parametrize(("said", "question"), [
    ("where the stapler is", "where is the stapler?"),
    ("what he wants", "what do you want?"),
    ("what she wants for dinner", "what do you want for dinner?"),
    ("when she is coming", "when are you coming?"),
    ("why the door is open", "why is the door open?"),
    ("how many cups she needs", "how many cups do you need?"),
    ("who is at the door", "who is at the door?"),          # the question word is the subject: the order stays
    ("which mug is hers", "which mug is hers?"),
    ("where is the stapler", "where is the stapler?"),      # already direct
])
def test_a_wh_question_is_put_as_the_person_hears_it(said: str, question: str) -> None:
    assert direct_question(said.split(), ["Maria"]) == question


def test_ask_a_person_a_wh_question_puts_it_to_them(library: Library) -> None:
    """"ask Maria where the stapler is" was Find(stapler), then Tell of "where the stapler is": the robot looked
    for the stapler itself instead of asking Maria."""
    (tell,) = parse_command("ask Maria where the stapler is", library).frames
    assert (tell.frame, tell.elements["message"].head, tell.elements["recipient"].head) == \
        ("Tell", "where is the stapler?", "Maria")


@pytest.mark.parametrize(("command", "question"), [
    ("ask Kenji what's in the mini fridge", "what's in the mini fridge?"),
    ("ask Omar who's at the door", "who's at the door?"),
    ("ask Maria where the stapler is", "where is the stapler?"),
])
def test_a_question_word_with_its_verb_contracted_is_asked_as_said(library: Library, command: str,
                                                                   question: str) -> None:
    """"ask Kenji what's in the mini fridge" (e2e22): the contraction puts the verb after the question word already,
    so the question is put to Kenji as said (was left a message the robot answered itself, looking in the fridge);
    "tell Kenji what's in the mini fridge" is still the robot's to find out."""
    message = parse_command(command, library).frames[0].elements["message"]
    assert message.head == question
    told = parse_command("tell Kenji what's in the mini fridge", library).frames[0].elements["message"]
    assert told.head == told.text == "what's in the mini fridge"


@pytest.mark.parametrize(("said", "asked", "question"), [
    ("if I can borrow his book", "Sam", "can I borrow your book?"),       # the one asked: no one else is named
    ("whether her brother is home", "Mia", "is your brother home?"),
    ("if Anna can borrow his book", "Raj", "can Anna borrow his book?"),  # another named: "his" may be hers
])
def test_a_pronoun_of_the_person_asked_is_turned_to_them(said: str, asked: str, question: str) -> None:
    """"ask Sam if I can borrow his book" kept "his" (words49): to Sam, it is "your book"."""
    assert direct_question(said.split(), asked.split()) == question
