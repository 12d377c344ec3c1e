from __future__ import annotations

import pytest

from seal_cli.sim.relaying import SENDER, asked_for, relayed


@pytest.mark.parametrize(("words", "passed_on"), [
    ("I'm ready", "the person who sent me says they're ready"),
    ("I am on my way", "the person who sent me says they are on their way"),
    ("I was right and my tea is cold", "the person who sent me says they were right and their tea is cold"),
    ("I wasn't there", "the person who sent me says they weren't there"),
    ("I will be late", "the person who sent me says they will be late"),
    ("I've left the keys with myself", "the person who sent me says they've left the keys with themselves"),
    ("the blue mug is mine", "the person who sent me says the blue mug is theirs"),
    ("it's me", "the person who sent me says it's them"),
    ("call me", "the person who sent me asks you to call them"),
    ("please call me back", "the person who sent me asks you to call them back"),
    ("don't forget my keys", "the person who sent me asks you not to forget their keys"),
    ("dinner is ready", "dinner is ready"),
    ("we are leaving", "we are leaving"),
])
def test_the_senders_first_person_is_passed_on_in_the_third(words: str, passed_on: str) -> None:
    """"tell Nora I'm ready" gave Nora the robot's "I'm ready" (words45); "am" and "was" agree with "they"."""
    assert relayed(words) == passed_on


def test_the_sender_is_named_when_known() -> None:
    assert relayed("I'm running late", "the doctor") == "the doctor says they're running late"
    assert SENDER == "the person who sent me"


@pytest.mark.parametrize(("question", "asked"), [
    ("can I borrow his book", "can the person who sent me borrow his book"),
    ("do I need my umbrella", "does the person who sent me need their umbrella"),
    ("am I late", "is the person who sent me late"),
    ("do you want tea", "do you want tea"),
])
def test_a_question_asked_for_the_sender_names_them_where_it_said_i(question: str, asked: str) -> None:
    """"ask Sam if I can borrow his book" asked Sam "can I borrow his book?", the robot's "I" (words45)."""
    assert asked_for(question) == asked


@pytest.mark.parametrize(("words", "passed_on"), [
    ("I will meet him", "the person who sent me says they will meet you"),
    ("I'll see her at the station", "the person who sent me says they'll see you at the station"),
    ("I found her glasses", "the person who sent me says they found your glasses"),
    ("I will ring her tomorrow", "the person who sent me says they will ring you tomorrow"),
    ("she is late and her bus has gone", "you are late and your bus has gone"),
    ("he needs his coat", "you need your coat"),
    ("Bea is waiting for him", "Bea is waiting for him"),          # someone else is named: "him" may be anyone
    ("dinner is ready", "dinner is ready"),
])
def test_a_he_or_she_in_a_relayed_message_is_the_hearer(words: str, passed_on: str) -> None:
    """words47: "tell Sam I will meet him" gave Sam "... they will meet him"; to the one it is passed on to, a he or
    she no one else in the message can be is "you", the verb agreeing."""
    assert relayed(words, hearer=True) == passed_on


def test_without_a_hearer_the_third_person_is_kept() -> None:
    assert relayed("I will meet him") == "the person who sent me says they will meet him"
