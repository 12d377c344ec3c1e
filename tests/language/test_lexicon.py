"""Tagging: verbs from the library, function words, open-class words, result words; morphology."""

from __future__ import annotations

import pytest

from seal_cli.frames.library import Library
from seal_cli.language.lexicon import MAX_LENGTH, CommandError, tag, tokenize
from seal_cli.language.morphology import gerund_lemma, is_adjective, is_plural, noun_lemma, participles, verb_lemma
from seal_cli.language.parser import lexicon_of


def tags(text: str, library: Library) -> list[tuple[str, str]]:
    lexicon, _ = lexicon_of(library)
    return [(w.text, w.tag) for w in tag(lexicon, text)]


def test_multiword_and_split_verbs(library: Library) -> None:
    assert tags("tell me how many cups", library)[0] == ("tell me how many", "VERB")
    assert tags("pick the cup up", library) == [("pick", "VERB"), ("the", "DET"), ("cup", "WORD"),
                                                 ("up", "PARTICLE")]
    lexicon, _ = lexicon_of(library)
    assert tag(lexicon, "pick the cup up")[0].info == "pick up"
    assert tag(lexicon, "pick the cup on the table")[0].info == "pick"      # "on" has an object: a preposition


def test_a_verb_is_only_a_verb_where_a_clause_starts(library: Library) -> None:
    assert tags("light the candle", library)[0] == ("light", "VERB")
    assert ("light", "WORD") in tags("look at the book by the light of the lamp", library)
    assert ("microwave", "WORD") in tags("put the egg in the microwave", library)
    assert tags("put it in the sink and microwave the egg", library)[6] == ("microwave", "VERB")


def test_and_joins_clauses_or_noun_phrases(library: Library) -> None:
    assert ("and", "AND_NP") in tags("put the cup and the plate on the table", library)
    assert ("and", "SEP") in tags("take the cup and put it on the table", library)


def test_names_are_capitalised_words_where_a_noun_phrase_starts(library: Library) -> None:
    assert ("Mary Ann", "NAME") in tags("greet Mary Ann", library)
    assert ("Apple", "WORD") in tags("take the Apple", library)
    assert ("TV", "WORD") in tags("find TV", library)       # an acronym is no name


def test_result_words_come_from_the_library(library: Library) -> None:
    lexicon, _ = lexicon_of(library)
    assert lexicon.results["heated"] == ("Heat", "heat")
    assert lexicon.results["lit"] == ("ToggleOn", "light")
    assert lexicon.results["hot"][0] == "Heat"                 # hot(theme) is Heat's result
    assert lexicon.results["clean"][0] == "Clean"
    assert "left" not in lexicon.results                       # Place has no one-place result
    assert "moved" not in lexicon.results                      # Go's element is a goal, not a theme
    assert ("heated", "RESULT") in tags("put a heated egg in the fridge", library)
    assert lexicon.results["warm"] == ("Heat", "warm")         # a gradable adjective among Heat's units
    assert lexicon.results["cool"] == ("Cool", "cool")
    assert "wash" not in lexicon.results and "light" not in lexicon.results   # no state ("wash" has no "washer")
    assert ("heated up", "RESULT") in tags("put the heated up egg in the fridge", library)
    assert ("rinsed off", "RESULT") in tags("put the rinsed off apple on the table", library)


def test_participles_after_nouns(library: Library) -> None:
    got = tags("find the person wearing a hat and the person pointing to the left and the person sitting", library)
    assert ("wearing", "VBG_T") in got and ("pointing", "VBG_P") in got and ("sitting", "VBG_I") in got
    assert ("waving", "WORD") in tags("follow the waving person", library)


def test_tokenize_keeps_character_offsets() -> None:
    words = tokenize("Bring Roger's cup, please!")
    assert [(w.text, w.start, w.end) for w in words] == [
        ("Bring", 0, 5), ("Roger", 6, 11), ("'s", 11, 13), ("cup", 14, 17), (",", 17, 18), ("please", 19, 25),
        ("!", 25, 26)]
    assert [w.text for w in tokenize("don't put the t-shirt & the cup")] == \
        ["don't", "put", "the", "t-shirt", "and", "the", "cup"]


def test_a_dash_between_clauses_reads_as_a_semicolon_and_hyphens_join_digits() -> None:
    """An em or en dash, a double hyphen or a hyphen between spaces breaks clauses like ";"; a
    hyphen inside a word joins letters and digits ("under-12s", "covid-19", "12-pack")."""
    for dash in ("—", "–", "--", " - "):
        words = tokenize(f"turn on the oven{dash}we open at noon")
        assert [w.lower for w in words] == ["turn", "on", "the", "oven", ";", "we", "open", "at", "noon"]
    assert [w.text for w in tokenize("the under-12s want a 12-pack of covid-19 tests")] == \
        ["the", "under-12s", "want", "a", "12-pack", "of", "covid-19", "tests"]


def test_a_remark_after_a_dash_is_set_aside(library: Library) -> None:
    from seal_cli.language.parser import parse_command

    parse = parse_command("Switch the kettle on — the guests are here.", library)
    assert [e.frame for e in parse.frames] == ["ToggleOn"] and parse.remarks == ("the guests are here",)


@pytest.mark.parametrize(("text", "column"), [("go\x00", 3), ("go to the kitchen → now", 19)])
def test_tokenize_refuses_what_is_not_text(text: str, column: int) -> None:
    with pytest.raises(CommandError) as caught:
        tokenize(text)
    assert caught.value.column == column


def test_tokenize_refuses_very_long_commands() -> None:
    with pytest.raises(CommandError, match="too long"):
        tokenize("a" * (MAX_LENGTH + 1))


def test_morphology_from_lemminflect() -> None:
    assert [noun_lemma(w) for w in ("knives", "people", "persons", "glasses", "tomatoes", "cups", "Sofa")] == \
        ["knife", "person", "person", "glass", "tomato", "cup", "sofa"]
    assert noun_lemma("cheezits") == "cheezits"                # a word the dictionary lacks stays as written
    assert noun_lemma("bars") == "bar" and is_plural("bars")   # listed only as a verb form
    from seal_cli.language.morphology import is_adverb, is_gradable

    assert is_adverb("together") and is_adverb("carefully") and not is_adverb("upright") and not is_adverb("cup")
    assert is_gradable("warm") and not is_gradable("wash") and not is_gradable("cup")
    assert is_plural("apples") and is_plural("people") and not is_plural("glass") and not is_plural("cup")
    assert verb_lemma("heated") == "heat" and verb_lemma("lit") == "light" and verb_lemma("sofa") is None
    assert gerund_lemma("wearing") == "wear" and gerund_lemma("ceiling") is None
    assert {"lit", "lighted"} <= participles("light") and participles("cut") == {"cut"}
    assert is_adjective("hot") and not is_adjective("cup")


def test_subordinate_clauses_are_separators_or_conditions(library: Library) -> None:
    assert tags("put the dishes away after you wash them", library)[4:6] == [("after you", "SEP"), ("wash", "VERB")]
    assert tags("Before you go to the garage, turn off the lights", library)[:2] == [("Before you", "POLITE"),
                                                                                   ("go", "VERB")]
    assert ("when the water is boiling", "COND") in tags("turn off the stove when the water is boiling", library)
    assert tags("If the door is open, close it", library)[:2] == [("If the door is open,", "COND"),
                                                                  ("close", "VERB")]
    lexicon, _ = lexicon_of(library)
    once = tag(lexicon, "wash the dishes and once you're done, put them away")
    assert [(w.tag, w.info) for w in once if w.tag in ("SEP", "POLITE")] == [("SEP", None), ("POLITE", "then")]
    assert ("when", "WH") in tags("tell me when dinner is ready", library)   # what is said, not a condition


def test_relative_clauses(library: Library) -> None:
    assert ("that is", "REL") in tags("bring me the cup that is on the table", library)
    assert ("I left", "REL") in tags("bring me the book I left on the sofa", library)
    assert ("that have gone bad", "REL") in tags("throw away the bananas that have gone bad", library)
    assert ("where it belongs", "HERE") in tags("put the book on the shelf where it belongs", library)
    assert [t for t in tags("find the person who is waving", library)][-1] == ("waving", "VBG_I")
    assert ("that", "WH") in tags("tell the guest that dinner is ready", library)
    assert ("where", "WH") in tags("find out where my umbrella is", library)   # no object yet: a question


def test_adverbs_of_time_place_and_manner(library: Library) -> None:
    assert tags("gently place the eggs in the basket", library)[:2] == [("gently", "POLITE"), ("place", "VERB")]
    assert ("right away", "PARTICLE") in tags("put it in the fridge right away", library)
    assert ("for three minutes", "PARTICLE") in tags("microwave the popcorn for three minutes", library)
    assert ("upstairs", "HERE") in tags("bring it upstairs", library)
    assert tags("take a look at the sink", library)[0] == ("take a look at", "VERB")
    assert tags("start by opening the window", library)[:2] == [("start by", "POLITE"), ("opening", "VERB")]
    assert ("one", "WORD") in tags("bring me the red one", library)
    assert ("one", "NUM") in tags("bring me one apple", library)


@pytest.mark.parametrize(("text", "verb", "words"), [
    ("re arranging clocks in a room", "arrange", "re arranging"),    # the prefix said apart
    ("re-arrange the clocks on the desk", "arrange", "re-arrange"),
    ("rearrange the pillows on the sofa", "arrange", "rearrange"),
    ("relight the lamp", "light", "relight"),
])
def test_a_verb_said_again_with_re_is_the_verb(text: str, verb: str, words: str, library: Library) -> None:
    lexicon, _ = lexicon_of(library)
    first = tag(lexicon, text)[0]
    assert (first.text, first.tag, first.info) == (words, "VERB", verb)


@pytest.mark.parametrize("text", ["reset the alarm", "re the cup"])
def test_re_before_a_short_or_no_verb_stays_unknown(text: str, library: Library) -> None:
    lexicon, _ = lexicon_of(library)
    assert tag(lexicon, text)[0].tag != "VERB" or tag(lexicon, text)[0].info not in ("set", "cup")
