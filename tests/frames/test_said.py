"""What is said, as words: a plan's message names shown to a user (``seal_cli.frames.said``)."""

from __future__ import annotations

import pytest
from typer.testing import CliRunner

from seal_cli.cli import app
from seal_cli.frames.model import Fact
from seal_cli.frames.said import is_question, said_names, said_words, shown, shown_fact


@pytest.mark.parametrize(("name", "words"), [
    ("what_s_in_the_fridge", "what's in the fridge"),
    ("don_t_wait_for_me", "don't wait for me"),
    ("we_ll_be_late", "we'll be late"),
    ("i_m_home", "I'm home"),
    ("they_ve_gone", "they've gone"),
    ("dinner_is_ready", "dinner is ready"),
    ("do_you_want_tea", "do you want tea"),
    ("time", "time"),
    ("_", "_"),
])
def test_a_said_name_is_its_words_with_the_apostrophes_english_writes(name: str, words: str) -> None:
    assert said_words(name) == words


@pytest.mark.parametrize(("words", "asks"), [
    ("what's in the fridge", True), ("do you want tea", True), ("isn't it late", True), ("how many cups", True),
    ("dinner is ready", False), ("the doctor is waiting", False), ("", False),
])
def test_a_question_opens_with_a_wh_word_or_an_auxiliary(words: str, asks: bool) -> None:
    assert is_question(words) is asks


def test_a_step_shows_what_is_said_quoted_and_the_names_stay_in_str(library) -> None:
    """The plan line a user reads quotes the question; ``str`` (``--json``, the suites) keeps the name."""
    tell = library.frame("Tell").bind({"message": "what_s_in_the_fridge", "recipient": "anna"})
    assert shown(tell) == 'Tell(message="what\'s in the fridge?", recipient=anna)'
    assert str(tell) == "Tell(message=what_s_in_the_fridge, recipient=anna)"
    pick = library.frame("Pick").bind({"theme": "cup", "source": "coffee_table_1"})
    assert shown(pick) == str(pick)


def test_seal_plan_prints_the_question_as_words() -> None:
    result = CliRunner().invoke(app, ["plan", "--map", "apartment", "ask Anna what's in the fridge"])
    assert result.exit_code == 0, result.output
    assert 'message="what\'s in the fridge?", recipient=anna' in result.stdout
    goal = next(line for line in result.stdout.splitlines() if line.startswith("goal:"))
    assert goal.split(None, 1)[1] == 'told("what\'s in the fridge?")'   # the goal as words too (e2e23)
    assert "what_s_in_the_fridge" not in result.stdout
    as_json = CliRunner().invoke(app, ["plan", "--map", "apartment", "ask Anna what's in the fridge", "--json"])
    assert '"message": "what_s_in_the_fridge"' in as_json.stdout
    assert '"told(what_s_in_the_fridge)"' in as_json.stdout   # names stay in --json


def test_a_fact_shows_only_what_a_step_says_as_words(library) -> None:
    """An argument is quoted only when a step says it: a thing that happens to be a name of words stays a name."""
    tell = library.frame("Tell").bind({"message": "dinner_is_ready", "recipient": "anna"})
    said = said_names([tell, library.frame("Pick").bind({"theme": "cup"})])
    assert said == {"dinner_is_ready"}
    assert shown_fact(Fact("told", ("dinner_is_ready",)), said) == 'told("dinner is ready")'
    assert shown_fact(Fact("told", ("dinner_is_ready",), negated=True), said) == 'not told("dinner is ready")'
    assert shown_fact(Fact("in", ("paper_towel", "cupboard_1")), said) == "in(paper_towel, cupboard_1)"
