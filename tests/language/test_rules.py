"""The tagger's rules: each rule's worked examples (the examples are the tests), the tables, the tags."""

from __future__ import annotations

import dataclasses

import pytest

from seal_cli.frames.library import Library
from seal_cli.language import lexicon
from seal_cli.language.lexicon import Match, Tagger, tag
from seal_cli.language.parser import lexicon_of
from seal_cli.language.rule import START, Example, Rule, after_all_but
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


class UnindexedTagger(Tagger):
    """The tagger's loop before the index by last tag: every rule of the table that its ``first`` gate admits is
    asked, in order, whatever the last tag; a rule its ``after`` gate turns away must decline (``refused`` lists
    those that did not)."""

    def __init__(self, *args: object, **kwargs: object) -> None:
        super().__init__(*args, **kwargs)  # type: ignore[arg-type]
        self.refused: list[str] = []
        self.asked = 0

    def first_match(self, table: int, low: str, i: int) -> Match | None:
        rules = [rule for rule in lexicon._GATES.tables[table] if rule.admits(low)]
        self.asked += len(rules)
        for rule in rules:
            after = self.out[-1].tag if self.out else START
            found = rule.match(self, i)
            if found is None:
                continue
            if not rule.follows(after):
                self.refused.append(f"{rule.name} after {after!r}")
            self.apply(found, i)
            if self.trace is not None:
                self.trace.append(rule.name)
            if found.consumed:
                return found
        return None


def test_no_rule_is_kept_by_the_index_from_a_word_the_loop_would_match(library: Library) -> None:
    """Every rule's examples, tagged through the index (each rule's ``first`` and ``after`` gates) and by the loop
    that asks every rule: the same words and the same rules fired, and no rule matched where its gate turns it
    away; the index lists far fewer rules to ask at the same words."""
    lex, _ = lexicon_of(library)
    gated = [rule.name for rule in RULES if rule.after is not None]
    assert len(gated) >= 20
    asked = indexed = 0
    for rule in RULES:
        for example in rule.examples:
            fired: list[str] = []
            words = Tagger(lex, tokenize(example.text), example.text, trace=fired).run()
            plain_fired: list[str] = []
            plain = UnindexedTagger(lex, tokenize(example.text), example.text, trace=plain_fired)
            plain_words = plain.run()
            assert plain.refused == [], (example.text, plain.refused)
            assert fired == plain_fired, example.text
            assert [(w.text, w.tag, w.info) for w in words] == [(w.text, w.tag, w.info) for w in plain_words]
            asked += plain.asked
            indexed += _asked(lex, example.text)
    assert indexed < asked * 0.8, (indexed, asked)


def _asked(lex: lexicon.Lexicon, text: str) -> int:
    """How many rules the index lists for the tagger to ask, tagging ``text``."""
    counted = 0

    class Counting(Tagger):
        def first_match(self, table: int, low: str, i: int) -> Match | None:
            nonlocal counted
            counted += len(lexicon._GATES.rules(low, self.out[-1].tag if self.out else START)[table])
            return super().first_match(table, low, i)

    Counting(lex, tokenize(text), text).run()
    return counted


GATED_FOR_SPEED = ("politeness", "adverb and comma", "sequencing word", "manner adverb",
                   "a wish said of a person's phrase", "asked where", "unknown verb without a joint",
                   "subordinate clause first")
"""Rules whose ``first`` gate only spares the tagger asking them (perf30), not a condition their match leaves to it:
where the gate turns them away, they decline anyway."""


def test_a_first_word_gate_added_for_speed_turns_away_only_words_where_the_rule_declines(library: Library) -> None:
    lex, _ = lexicon_of(library)
    gated = [rule for rule in RULES if rule.name in GATED_FOR_SPEED]
    assert len(gated) == len(GATED_FOR_SPEED) and all(rule.first is not None for rule in gated)
    matched: list[tuple[str, str]] = []
    asked = 0

    class Asking(Tagger):
        def first_match(self, table: int, low: str, i: int) -> Match | None:
            nonlocal asked
            for rule in gated:
                if rule in lexicon._GATES.tables[table] and not rule.admits(low):
                    asked += 1
                    if rule.match(self, i) is not None:
                        matched.append((rule.name, self.text))
            return super().first_match(table, low, i)

    for rule in RULES:
        for example in rule.examples:
            Asking(lex, tokenize(example.text), example.text).run()
    assert matched == []
    assert asked > 5000


def test_a_gate_by_last_tag_turns_a_rule_away_only_there() -> None:
    def anything(_state: object, _i: int) -> Match:
        return Match(1)

    after_a_noun = Rule("after a noun", anything, (), None, "", frozenset(["WORD"]))
    anywhere = Rule("anywhere", anything, ())
    gates = lexicon.Gates(((after_a_noun, anywhere),))
    assert gates.rules("cup", "WORD") == ((after_a_noun, anywhere),)
    assert gates.rules("cup", "DET") == ((anywhere,),)
    assert gates.rules("cup", START) == ((anywhere,),)
    assert gates.rest(0, "cup", "WORD", after_a_noun) == (anywhere,)
    assert START in after_all_but("WORD") and "WORD" not in after_all_but("WORD") and "DET" in after_all_but("WORD")


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
