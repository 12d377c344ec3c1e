"""Words of a command (``language.tokens``): a word mixing look-alike alphabets is refused at the odd letter."""

from __future__ import annotations

import re

import pytest

from seal_cli.language.tokens import CommandError, tokenize


@pytest.mark.parametrize(("text", "column", "said"), [
    ("find the \u0441up", 10, "'\u0441up' mixes Cyrillic and Latin letters ('\u0441' is CYRILLIC SMALL LETTER ES)"),
    ("find the c\u03c5p", 11, "'c\u03c5p' mixes Greek and Latin letters ('\u03c5' is GREEK SMALL LETTER UPSILON)"),
    ("st\u0456r the cup", 3, "'st\u0456r' mixes Cyrillic and Latin letters"),
    ("\u0447\u0430\u0448\u043a\u0430 of t\u0435a", 11, "'t\u0435a' mixes Cyrillic and Latin"),
])
def test_a_word_mixing_latin_cyrillic_or_greek_is_refused_at_the_odd_letter(text: str, column: int,
                                                                           said: str) -> None:
    # run "find the сup" (a Cyrillic с) searched the whole house for an "сup" (hostile17)
    with pytest.raises(CommandError, match=re.escape(said)) as caught:
        tokenize(text)
    assert caught.value.column == column


@pytest.mark.parametrize("text", ["find the \u0447\u0430\u0448\u043a\u0430", "heat the \u03b2-carotene",
                                  "bring Zo\u00eb the na\u00efve caf\u00e9 cup", "find the \u00b5-scope"])
def test_a_word_in_one_alphabet_each_part_is_read_as_written(text: str) -> None:
    assert [w.text for w in tokenize(text)] == text.split()


@pytest.mark.parametrize(("text", "counted"), [("put \uff13 apples in the sink", "3"),      # full-width (an IME's)
                                              ("bring me \u0663 apples", "3"),             # Arabic-Indic
                                              ("go to room \uff12\uff11\uff14", "214")])
def test_a_decimal_digit_of_any_script_is_read_as_its_ascii_digit_in_its_column(text: str, counted: str) -> None:
    # "put ３ apples" was "unexpected character '３'" (hostile21)
    words = tokenize(text)
    number = next(w for w in words if w.text[0].isdigit())
    assert (number.text, number.lower) == (counted, counted)
    assert text[number.start:number.end] != counted and len(text[number.start:number.end]) == len(counted)


@pytest.mark.parametrize(("text", "column", "said"), [
    ("bring me \u00b2 apples", 10, "'\u00b2' (superscript two) is no whole number"),
    ("bring me 3\u00bd apples", 11, "'\u00bd' (vulgar fraction one half) is no whole number"),
    ("bring me \u2462 cups", 10, "(circled digit three) is no whole number"),
])
def test_a_number_that_is_no_decimal_digit_is_refused_at_its_column(text: str, column: int, said: str) -> None:
    # read as a letter, "bring me ² apples" brought one apple and "3½ apples" three, in silence (hostile21)
    with pytest.raises(CommandError, match=re.escape(said)) as caught:
        tokenize(text)
    assert caught.value.column == column


@pytest.mark.parametrize(("text", "column", "said"), [
    ("stir the cu\u200dp", 12, "unexpected character '\\u200d' (U+200D ZERO WIDTH JOINER)"),
    ("go to the kitchen\u200e", 18, "(U+200E LEFT-TO-RIGHT MARK)"),
    ("stir the caf\udce9", 13, "byte 0xe9 is not UTF-8: seal reads a command as UTF-8 text"),
    ("stir the \ud83d", 10, "a lone surrogate U+D83D is no character"),
])
def test_an_invisible_or_undecoded_character_is_named(text: str, column: int, said: str) -> None:
    # an invisible mark was "unexpected character '\u200d'", a Latin-1 byte of the command line "'\udce9'" (hostile21)
    with pytest.raises(CommandError, match=re.escape(said)) as caught:
        tokenize(text)
    assert caught.value.column == column


@pytest.mark.parametrize("word", ["\u0930\u0938\u094b\u0908", "\u0e04\u0e23\u0e31\u0e27", "ha\u0336l\u0336l",
                                  "\u0130stanbul"])
def test_a_word_whose_letters_take_combining_marks_is_one_word(word: str) -> None:
    # Devanagari's and Thai's vowel signs are combining marks, which Python's \w holds not: "go to the रसोई" was
    # "unexpected character 'ो' (U+094B DEVANAGARI VOWEL SIGN O)" (hostile24)
    assert [w.text for w in tokenize(f"go to the {word} now")] == ["go", "to", "the", word, "now"]


def test_a_mark_on_no_letter_is_still_refused_at_its_column() -> None:
    with pytest.raises(CommandError, match=r"unexpected character .*U\+0301") as caught:
        tokenize("go to the \u0301hall")
    assert caught.value.column == 11


@pytest.mark.parametrize(("text", "read"), [
    ("1) water the ferns 2) feed the cat", ["water", "the", "ferns", ";", "feed", "the", "cat"]),
    ("(a) open the gate (b) close it", ["open", "the", "gate", ";", "close", "it"]),
    ("1. sweep the porch. 2. wipe the bench", ["sweep", "the", "porch", ".", "wipe", "the", "bench"]),
    ("Step 1: rinse the jug Step 2: dry it", ["rinse", "the", "jug", ";", "dry", "it"]),
    ("1 - lock the shed, 2 - feed the hens", ["lock", "the", "shed", ",", ";", "feed", "the", "hens"]),
])
def test_the_marks_that_number_a_list_are_stops_between_its_steps(text: str, read: list[str]) -> None:
    """A list numbered 1, 2, ... or a, b, ... (words35): each mark after the first reads as a stop, columns kept."""
    words = tokenize(text)
    assert [w.lower for w in words] == read
    assert all(text[w.start:w.end].lower() == w.lower for w in words if w.lower.isalpha())


@pytest.mark.parametrize(("text", "read"), [
    ("bring me 2. then sit", ["bring", "me", "2", ".", "then", "sit"]),          # no list opens the command
    ("1) feed the cat", ["1", "feed", "the", "cat"]),                             # one mark: no list
    ("1) feed the cat 3) water it", ["1", "feed", "the", "cat", "3", "water", "it"]),   # 3 does not follow 1
])
def test_a_number_that_counts_no_list_is_read_as_said(text: str, read: list[str]) -> None:
    assert [w.lower for w in tokenize(text)] == read


@pytest.mark.parametrize(("text", "read"), [
    ("gimme the ladle", ["give", "me", "the", "ladle"]),
    ("lemme know", ["let", "me", "know"]),
    ("you gotta feed it", ["you", "got", "to", "feed", "it"]),
])
def test_two_words_run_together_are_read_as_both(text: str, read: list[str]) -> None:
    words = tokenize(text)
    assert [w.lower for w in words] == read
    assert "".join(w.text for w in words) == text.replace(" ", "")


@pytest.mark.parametrize(("text", "said", "read"), [
    ("pick up the mug prior to turning on the lamp", "prior to", "before"),
    ("Subsequent to that wash it", "Subsequent to", "after"),
])
def test_two_words_of_one_preposition_are_one_word_read_as_it(text: str, said: str, read: str) -> None:
    words = tokenize(text)
    one = next(w for w in words if w.lower == read)
    assert one.text == said and text[one.start:one.end] == said
    assert len(words) == len(text.split()) - 1


def test_prior_alone_is_a_word_of_its_own() -> None:
    assert [w.lower for w in tokenize("the prior owner to")] == ["the", "prior", "owner", "to"]


@pytest.mark.parametrize("text", ["bring me\u00a0the cup", "bring\tme  the cup ", " \u2003bring me the cup\n"])
def test_white_space_of_any_kind_between_words_is_no_word(text: str) -> None:
    assert [w.text for w in tokenize(text)] == ["bring", "me", "the", "cup"]


@pytest.mark.parametrize(("text", "column"), [("bring me   # the cup", 12), ("bring me the cup  ~", 19),
                                              ("bring me\u00a0\u00a0§ cup", 11), ("~ bring it", 1)])
def test_a_character_of_no_word_is_refused_at_its_own_column_after_white_space(text: str, column: int) -> None:
    with pytest.raises(CommandError, match="unexpected character") as caught:
        tokenize(text)
    assert caught.value.column == column


def test_a_word_is_read_alike_however_often_it_is_made() -> None:
    from seal_cli.language import tokens

    first = [(w.text, w.lower) for w in tokenize("Pls bring Me the Cup’s lid")]
    tokens._READ.clear()
    assert [(w.text, w.lower) for w in tokenize("Pls bring Me the Cup’s lid")] == first
    assert first[0] == ("Pls", "please") and tokens.read_word("Pls") == "please" and tokens.read_word("ME") == "me"
