"""The tagger's rules: each rule's worked examples (the examples are the tests), the tables, the tags."""

from __future__ import annotations

import dataclasses

import pytest

from seal_cli.frames.library import Library
from seal_cli.language.lexicon import Tagger, tag
from seal_cli.language.parser import lexicon_of
from seal_cli.language.rule import Example, Rule
from seal_cli.language.rules import TABLES
from seal_cli.language.tags import Tag, declared_tags
from seal_cli.language.tokens import Word, tokenize

RULES = [rule for table in TABLES.values() for rule in table]
EXAMPLES = [pytest.param(rule, example, id=f"{rule.name}: {example.text}") for rule in RULES
            for example in rule.examples]


@pytest.mark.parametrize(("rule", "example"), EXAMPLES)
def test_each_rule_does_what_its_examples_say(rule: Rule, example: Example, library: Library) -> None:
    lexicon, _ = lexicon_of(library)
    fired: list[str] = []
    words = Tagger(lexicon, tokenize(example.text), example.text, trace=fired).run()
    assert rule.name in fired, f"{rule.name!r} did not match in {example.text!r} (matched: {fired})"
    tagged = [(w.text, str(w.tag)) for w in words]
    if example.tag:
        assert (example.word, example.tag) in tagged, tagged
    else:
        assert all(text != example.word for text, _ in tagged), tagged     # dropped


def test_every_rule_has_a_name_of_its_own_and_examples() -> None:
    names = [rule.name for rule in RULES]
    assert len(names) == len(set(names))
    assert all(rule.examples for rule in RULES)
    assert TABLES["words"][-1].first is None      # the last rule of the word table matches any word


def test_the_tags_are_the_terminals_the_grammar_declares() -> None:
    assert {t.value for t in Tag} == declared_tags()


def test_every_tag_the_tagger_emits_is_a_member_of_the_enum(library: Library) -> None:
    lexicon, _ = lexicon_of(library)
    words = tag(lexicon, "Robin, when you get a chance, could you take the two heated apples from room 214 to "
                         "Mary's kitchen and tell her that dinner is ready?")
    assert all(isinstance(w.tag, Tag) for w in words)


def test_words_are_frozen_values() -> None:
    word = tokenize("bring it")[0]
    with pytest.raises(dataclasses.FrozenInstanceError):
        word.tag = "VERB"          # type: ignore[misc]
    assert word.tagged(Tag.VERB, "bring").tag == Tag.VERB and word.tag == ""
    assert Word("Pls", 0, 3).lower == "please"
