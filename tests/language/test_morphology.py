"""language.morphology: lemmas, plurals and forms from lemminflect's tables, looked up by bisection."""

from __future__ import annotations

from seal_cli.language.morphology import (
    gerund_lemma,
    is_adjective,
    is_adverb,
    is_gradable,
    is_plural,
    noun_lemma,
    participles,
    verb_lemma,
)


def test_singulars_of_regular_and_irregular_nouns() -> None:
    assert [noun_lemma(w) for w in ("apples", "knives", "people", "Glasses", "cheezits")] == \
        ["apple", "knife", "person", "glass", "cheezits"]        # a word the tables lack stays as written
    assert is_plural("apples") and is_plural("people") and not is_plural("apple")


def test_verbs_and_their_forms() -> None:
    assert verb_lemma("heated") == "heat" and verb_lemma("took") == "take" and verb_lemma("xyzzy") is None
    assert gerund_lemma("wearing") == "wear" and gerund_lemma("morning") != "morn"
    assert participles("light") >= {"lit", "lighted"} and participles("cut") == frozenset({"cut"})


def test_adjectives_adverbs_and_gradable_words() -> None:
    assert is_adjective("hot") and is_adjective("clean") and not is_adjective("fridge")
    assert is_adverb("together") and not is_adverb("hot")
    assert is_gradable("warm") and not is_gradable("wooden")
