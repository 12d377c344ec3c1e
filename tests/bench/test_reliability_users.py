"""A new user's hostile cases of ``seal bench reliability``: each says what its message names; they end cleanly."""

from __future__ import annotations

import pytest

from seal_cli.bench.reliability import hostile_cases, issue_cases, run_case
from seal_cli.bench.reliability_review import cases, review_cases
from seal_cli.bench.reliability_users import user_cases


def test_the_cases_are_new_named_once_and_say_what_the_message_names() -> None:
    users = list(user_cases())
    assert len(users) >= 20 and len({c.name for c in users}) == len(users)
    assert {c.name for c in users}.isdisjoint(c.name for c in [*issue_cases(), *hostile_cases(), *review_cases()])
    assert all(c.says is not None for c in users)
    assert {c.name for c in users} <= {c.name for c in cases(0, 0)}


@pytest.mark.parametrize("name", ["U a line of 40,000 brackets: a window of it in the message", "U run --png '-'",
                                  "U a refusal inside --done names it", "U run --holding fridge_1",
                                  "U an object called as a place in a run", "U run 'bring me something'"])
def test_picked_cases_end_cleanly(name: str) -> None:
    outcome = run_case(next(c for c in user_cases() if c.name == name))
    assert outcome.problems == [] and outcome.code == 1
