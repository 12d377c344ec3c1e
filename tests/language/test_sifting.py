"""The tagger's third gate, ``Rule.needs`` (perf47): a rule that can match only in a command saying one of some
words is not asked in a command that says none of them (``lexicon.Gates.unsaid``). It only spares asking: on a
sample of every corpus, the rules that fire, in order, are the same with the gate as without it."""

from __future__ import annotations

import contextlib
from pathlib import Path

from seal_cli.errors import SealError
from seal_cli.frames.library import Library
from seal_cli.language import lexicon
from seal_cli.language.lexicon import Match, Tagger
from seal_cli.language.parser import _as_name, lexicon_of
from seal_cli.language.rule import START, Rule
from seal_cli.language.rules import TABLES
from seal_cli.language.tokens import Word, tokenize
from tests.language.test_parse_caches import corpora


def _trace(lex: lexicon.Lexicon, text: str, people: frozenset[str], sift: bool) -> tuple[list[str], object]:
    """The rules fired tagging ``text`` as the parser does (people of the world written as names), and the words
    tagged (or the error)."""
    fired: list[str] = []
    try:
        tokens = tokenize(text)
    except SealError as error:
        return fired, str(error)
    tokens = [_as_name(w) if w.lower in people else w for w in tokens]
    try:
        words = Tagger(lex, tokens, text, trace=fired, sift=sift).run()
    except SealError as error:
        return fired, str(error)
    return fired, [(w.text, w.tag, w.info, w.start, w.end) for w in words]


def test_every_corpus_fires_the_same_rules_with_the_gate_by_words_said(library: Library, shared_data: Path) -> None:
    lex, _ = lexicon_of(library)
    sifted = 0
    for name, texts, vocabulary in corpora(shared_data):
        people = frozenset(vocabulary.people) if vocabulary is not None and vocabulary.people else frozenset()
        for text in texts:
            assert _trace(lex, text, people, True) == _trace(lex, text, people, False), (name, text)
            with contextlib.suppress(SealError):
                sifted += lexicon._GATES.unsaid(tokenize(text)) != 0
    assert sifted > 1000                # the gate leaves rules out of most commands


def test_every_rule_needing_words_still_fires_in_its_examples(library: Library) -> None:
    lex, _ = lexicon_of(library)
    needing = [rule for table in TABLES.values() for rule in table if rule.needs is not None]
    assert len(needing) >= 10
    for rule in needing:
        for example in rule.examples:
            fired: list[str] = []
            Tagger(lex, tokenize(example.text), example.text, trace=fired).run()
            assert rule.name in fired, (rule.name, example.text)
            assert not rule.needs.isdisjoint(w.lower for w in tokenize(example.text))


def test_a_rule_whose_words_are_unsaid_is_left_out_of_the_index() -> None:
    def anything(_state: object, _i: int) -> Match:
        return Match(1)

    needing = Rule("needs many", anything, (), needs=frozenset(["many"]))
    anywhere = Rule("anywhere", anything, ())
    gates = lexicon.Gates(((needing, anywhere),))
    said = gates.unsaid(tokenize("how many cups"))
    unsaid = gates.unsaid(tokenize("bring the cups"))
    assert said == 0 and unsaid != 0
    assert gates.rules("cup", START, said) == ((needing, anywhere),)
    assert gates.rules("cup", START, unsaid) == ((anywhere,),)
    assert gates.rest(0, "cup", START, needing, unsaid) == (anywhere,)
    assert gates.unsaid([Word("Many", 0, 4)]) == 0           # the word's lower-case form, as the rules read it
