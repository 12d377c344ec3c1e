"""Statements said beside the command (``rules/statements.py``, ``State.statement_at``): a remark, where it ends,
what its phrases give the command's pronouns, and the command after it (words48, words49)."""

from __future__ import annotations

import pytest

from seal_cli.frames.library import Library
from seal_cli.language.parser import CommandError, parse_command


@pytest.mark.parametrize(("text", "remark", "frame", "role", "head"), [
    ("Grace is in the lounge, bring her a towel", "Grace is in the lounge", "Bring", "recipient", "Grace"),
    ("Grace's in the lounge, bring her a towel", "Grace's in the lounge", "Bring", "recipient", "Grace"),
    ("someone left the fridge open, could you close it", "someone left the fridge open", "Close", "theme", "fridge"),
])
def test_a_statement_of_where_someone_is_then_a_command(library: Library, text: str, remark: str, frame: str,
                                                        role: str, head: str) -> None:
    """A capitalised word before "is" names someone, though English has a verb "grace" (words49: "unknown verb
    'grace'"); a state word ends the phrase a pronoun may stand for ("the fridge *open*": it is the fridge)."""
    parse = parse_command(text, library)
    assert parse.remarks == (remark,)
    assert [f.frame for f in parse.frames] == [frame] and parse.frames[0].elements[role].head == head


def test_a_statement_alone_is_still_refused(library: Library) -> None:
    with pytest.raises(CommandError, match="is a statement, no command"):
        parse_command("Grace is in the lounge.", library)


def frames(text: str, library: Library) -> list[tuple[str, dict[str, str]]]:
    """Each frame with the heads of its said elements."""
    return [(f.frame, {role: e.head for role, e in f.elements.items() if not e.default})
            for f in parse_command(text, library).frames]


@pytest.mark.parametrize(("text", "want"), [
    ("someone raising their left arm in the office wants to ask you something, please answer",
     [("Answer", {})]),
    ("somebody wearing a red hat in the garden has a question, go answer it", [("Answer", {"theme": "question"})]),
    ("anyone sitting by the fire is cold, bring them a blanket",
     [("Bring", {"theme": "blanket", "recipient": "them"})]),
])
def test_a_pronoun_of_people_described_by_what_they_do_is_a_statement(
        text: str, want: list[tuple[str, dict[str, str]]], library: Library) -> None:
    parse = parse_command(text, library)
    assert frames(text, library) == want
    assert parse.remarks and parse.remarks[0].split()[1].endswith("ing")


@pytest.mark.parametrize(("text", "want"), [
    ("angel is thirsty bring him a drink", [("Bring", {"theme": "drink", "recipient": "him"})]),
    ("the gate is open close it", [("Close", {"theme": "gate"})]),
    ("Teo is in the garage take him a torch", [("Bring", {"theme": "torch", "recipient": "Teo"})]),
    ("the guest at the door is lost guide her to the lounge", [("Guide", {"theme": "guest", "source": "door",
                                                                          "goal": "lounge"})]),
    ("the old man is waiting in the hall please lead him to the study", [("Guide", {"theme": "man", "source": "hall",
                                                                                    "goal": "study"})]),
    ("I'm freezing can you fetch me a jumper", [("Bring", {"theme": "jumper", "recipient": "me"})]),
])
def test_a_command_said_on_after_a_whole_statement_with_no_mark(
        text: str, want: list[tuple[str, dict[str, str]]], library: Library) -> None:
    assert frames(text, library) == want
    assert len(parse_command(text, library).remarks) == 1          # the statement, kept beside the command


@pytest.mark.parametrize("text", [
    "the cup is by the light switch",           # "light" before a noun: no command starts there
    "is the door open close it",               # a question first: no statement said whole
    "she wants to clean the kitchen",           # "to" before the verb: the statement's own
])
def test_no_command_starts_inside_a_statement(text: str, library: Library) -> None:
    with pytest.raises(CommandError):
        parse_command(text, library)


@pytest.mark.parametrize(("text", "want"), [
    ("robin went to the kitchen, follow him", [("Follow", {"theme": "him"})]),
    ("angel came in a minute ago, greet her", [("Greet", {"theme": "her"})]),
])
def test_a_lower_case_name_the_dictionary_lists_said_doing_something_is_a_statement(
        text: str, want: list[tuple[str, dict[str, str]]], library: Library) -> None:
    """words48: "robin went to the kitchen, follow him" was an unknown verb "robin"; a bare word before a verb's
    past form, taken up by "him"/"her" after, names someone."""
    assert frames(text, library) == want
