"""A statement said before the command (``rules.statements``, ``State.statement_at``): a remark, and what its
phrases give the command's pronouns."""

from __future__ import annotations

import pytest

from seal_cli.frames.library import Library
from seal_cli.language.lexicon import CommandError
from seal_cli.language.parser import parse_command


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
