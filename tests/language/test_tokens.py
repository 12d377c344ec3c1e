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
