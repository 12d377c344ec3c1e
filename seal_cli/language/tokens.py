"""The words of a command: :class:`Word` (a frozen value) and :func:`tokenize`.

A word is a span of the command with the part it plays (its :class:`~seal_cli.language.tags.Tag`,
empty until tagged) and what the tag needs (``info``: the lexical unit of a verb, the number of a
number, the preposition of a preposition). Words are values: the tagger makes new words rather
than changing old ones.
"""

from __future__ import annotations

import re
from collections.abc import Sequence
from dataclasses import dataclass

from seal_cli.errors import SealError, Where
from seal_cli.language.english import (
    DETERMINERS,
    END_MARKS,
    READ_AS_ONE,
    RUN_TOGETHER,
    SPELLINGS,
    TITLES,
    TITLES_ONLY,
)
from seal_cli.language.slips import function_word

__all__ = ["MAX_LENGTH", "CommandError", "Word", "capitalised", "printable", "tokenize"]

MAX_LENGTH = 1000
"""The longest command accepted, in characters (a spoken command is far shorter)."""


class CommandError(SealError):
    """A command that cannot be parsed: where (column) and what was expected."""

    def __init__(self, message: str, column: int, text: str, expected: Sequence[str] = ()) -> None:
        super().__init__(message, Where(None, None, column), source_line=text)
        self.expected = list(expected)
        self.text = text

    def to_json(self) -> dict[str, object]:
        return {"message": self.message, "column": self.column, "expected": self.expected}


@dataclass(frozen=True, slots=True, eq=False, init=False, repr=False)
class Word:
    """A word (or a merged multiword phrase) of the command, with its tag.

    ``start``/``end`` are character offsets into the command. ``lower`` is the word as read: lower
    case, the typographic apostrophe plain, a known spelling normalised ("pls": "please"); the
    tagger may read a word otherwise ("its" as "it's") by passing ``lower``. Frozen, compared by
    identity (two words of one command are two places in it).
    """

    text: str
    start: int
    end: int
    tag: str
    info: object
    lower: str

    def __init__(self, text: str, start: int, end: int, tag: str = "", info: object = None,
                 lower: str | None = None) -> None:
        _text(self, text)          # the slots' own setters: a frozen value, made ~80,000 times a second
        _start(self, start)
        _end(self, end)
        _tag(self, tag)
        _info(self, info)
        _lower(self, read_word(text) if lower is None else lower)

    def tagged(self, tag: str, info: object = None) -> Word:
        """The same span with another tag (its text read afresh)."""
        return Word(self.text, self.start, self.end, tag, info)

    def __repr__(self) -> str:
        return f"Word({self.text!r}, {self.start}, {self.end}, {str(self.tag)!r})"


def read_word(text: str) -> str:
    """A word's text as read: lower case, the typographic apostrophe plain, a known spelling normalised ("pls":
    "please"). Remembered by text (:data:`READ_KEPT` of them): every word is made again when it is tagged, and a
    command's words are mostly the few hundred every command says."""
    lower = _READ.get(text)
    if lower is None:
        lower = text.lower()
        lower = lower.replace("’", "'") if "’" in lower else lower
        lower = SPELLINGS.get(lower, lower)
        if len(_READ) >= READ_KEPT:
            _READ.clear()
        _READ[text] = lower
    return lower


READ_KEPT = 65536
"""How many texts :func:`read_word` remembers before it starts again."""
_READ: dict[str, str] = {}


_text, _start, _end, _tag, _info, _lower = (getattr(Word, name).__set__ for name in
                                                  ("text", "start", "end", "tag", "info", "lower"))
"""The setters of :class:`Word`'s slots (``object.__setattr__`` looks each up by name: three times slower)."""


_TOKEN = re.compile(r"""
    (?P<word>[^\W\d_]+(?:['’](?![sS]\b)[^\W\d_]+|-[^\W_]+)*|[0-9]+(?:-[^\W_]+)*)   # letters, inner ' and -
                                                           # ("t-shirt", "under-12s", "covid-19"); numbers
  | (?P<poss>['’]s\b)                                      # possessive 's (and is)
  | (?P<amp>&)
  | (?P<dash>[—–]|-+>|=>|-{2,}|(?<=\s)-(?=\s))            # a dash (or "->") between clauses reads as ";"
  | (?P<punct>[,;:.!?]+)
  | (?P<quote>["“”'‘’`()\[\]])                             # quotes and brackets are ignored
""", re.VERBOSE)
"""A token; what lies between two is white space, else no token of the command (:func:`_refuse_between`)."""
_CONTROL = re.compile(r"[\x00-\x08\x0b-\x1f\x7f-\x9f]")
_SURROGATE = re.compile("[\ud800-\udfff]")
"""What Python makes of a byte of the command line that is not UTF-8 (U+DC80 to U+DCFF: ``surrogateescape``), or any
other lone surrogate: no character of any text."""
_NAME_AFTER = re.compile(r"\s+[^\W\d_]")


def tokenize(text: str) -> list[Word]:
    """The words and punctuation of ``text``; anything else is a SealError at its column."""
    if len(text) > MAX_LENGTH:
        raise CommandError(f"command too long ({len(text)} characters; the limit is {MAX_LENGTH})", MAX_LENGTH + 1,
                           text[:MAX_LENGTH + 20], ["a shorter command"])
    undecoded = _SURROGATE.search(text)
    if undecoded:
        raise CommandError(_not_utf8(undecoded.group()), undecoded.start() + 1, text, ["UTF-8 text"])
    bad = _CONTROL.search(text)
    if bad:
        raise CommandError(f"control character U+{ord(bad.group()):04X} in the command", bad.start() + 1,
                           printable(text), ["a word"])
    said = text
    read = text
    if not text.isascii():
        text = _digits_of_any_script(text)
        read = _marks_as_letters(text)
    read = _list_markers_read(read)
    paired = _bracket_pairs(read)
    words: list[Word] = []
    pos = 0
    for match in _TOKEN.finditer(read):
        start, end = match.span()
        if start != pos and not read[pos:start].isspace():
            _refuse_between(read, pos, start, said)
        pos = end
        kind = match.lastgroup
        if kind == "quote" and start not in paired:
            continue
        if kind == "quote":             # a bracket of a pair: the aside it holds (``statements.BRACKETED``)
            words.append(Word(read[start], start, pos))
            continue
        if kind == "word":
            typed = text[start:end]
            if not typed.isascii():
                _check_whole_numbers(typed, start, said)
                _check_one_alphabet(typed, start, said)
            low = typed.lower()
            two = RUN_TOGETHER.get(low) if len(typed) == 5 else None     # all five letters
            if two is not None:                                  # "gimme": "give" and "me", each its letters
                cut = start + len(two[2])
                words.append(Word(text[start:cut], start, cut, lower=two[0]))
                words.append(Word(text[cut:end], cut, end, lower=two[1]))
                continue
            one = READ_AS_ONE.get(f"{words[-1].lower} {low}") if low in _READ_AS_ONE_LAST and words and \
                words[-1].end < start else None
            if one is not None:                                  # "prior to": "before", one word of both
                first = words.pop()
                words.append(Word(text[first.start:pos], first.start, pos, lower=one))
                continue
            slip = function_word(low) if typed.isalpha() and (typed.islower() or typed[1:].islower() and (
                not words or words[-1].lower in END_MARKS)) else None
            words.append(Word(typed, start, pos, lower=slip))    # "wher": "where" (slips.function_word)
        elif kind == "punct" and match.group() == "." and words and words[-1].end == start and \
                words[-1].lower in TITLES and (capitalised(words[-1]) or words[-1].lower in TITLES_ONLY) and \
                _title_before_name(text, pos, capitalised(words[-1])) and \
                (len(words) < 2 or words[-2].lower not in DETERMINERS):     # "the Dr. Then ..." ends a sentence
            title = words[-1]
            words[-1] = Word(text[title.start:pos], title.start, pos)    # "Mr. Patel": the stop is the title's
        elif kind == "punct":           # "..." and "?!" are one mark
            words.append(Word(match.group()[0], start, pos))
        elif kind == "amp":
            words.append(Word("and", start, pos))
        elif kind == "dash":
            words.append(Word(read[start:pos], start, pos, lower=";"))   # its text the dash said
        elif kind == "poss":
            words.append(Word("'s", start, pos))
    if pos != len(text) and not read[pos:].isspace():
        _refuse_between(read, pos, len(text), said)
    return words


_READ_AS_ONE_LAST = frozenset(two.split()[-1] for two in READ_AS_ONE)
"""The last words of :data:`~seal_cli.language.english.READ_AS_ONE`: only at one of them is the pair looked up."""


def _refuse_between(read: str, start: int, end: int, said: str) -> None:
    """Refuse the first character of ``read[start:end]`` (the text between two tokens) that is no white space, at
    its column (``said``: the command as typed, for the message)."""
    for k in range(start, end):
        if not read[k].isspace():
            raise CommandError(_unexpected(said[k]), k + 1, said, ["a word"])


_MARKER = re.compile(r"""
    (?:(?<=^)|(?<=[\s.;:!?,]))                                # at the start, or after a space or a stop
    (?:(?:step|part)\s+)?                                      # "Step 1:"
    (?P<mark>\(\s*(?:[0-9]{1,2}|[a-z])\s*\)                   # "(1)", "(a)"
      |(?:[0-9]{1,2}|[a-z])\s*\)                             # "1)", "a)"
      |[0-9]{1,2}\s*(?:[.:](?!\d)|-(?=\s))                    # "1.", "1:", "1 -"
      |(?<=step\s|part\s)(?:one|two|three|four|five|six|seven|eight|nine|ten)\s*[.:])   # "Step one:" (words39)
    (?=\s)""", re.VERBOSE | re.IGNORECASE)
"""A mark that numbers a step of a list: "1)", "(2)", "3.", "a)", "1 -", "Step 1:", "Step one:"."""

_STEP_WORDS = {word: str(k) for k, word in enumerate(
    ["one", "two", "three", "four", "five", "six", "seven", "eight", "nine", "ten"], start=1)}
"""The number words of "Step one:", "Step two:" as the digits they count (words39)."""


def _list_markers_read(read: str) -> str:
    """``read`` with the marks that number the steps of a list read as stops between clauses, one character for one
    (columns stay): "1) go to the kitchen 2) find the apple 3) bring it to me" (words35). The marks count a list only
    when the first opens the command and each next one counts on from it (1, 2, 3 or a, b, c): "put 2. then ..." and
    "bring me 3) apples" number nothing. The first mark is read as nothing, each next one as ";" (or nothing after a
    stop already said)."""
    first = _MARKER.match(read, len(read) - len(read.lstrip()))
    if first is None:
        return read
    marks = [first]
    label = _label(first["mark"])
    for found in _MARKER.finditer(read, first.end()):
        if _label(found["mark"]) == _next_label(label):
            marks.append(found)
            label = _next_label(label)
    if len(marks) < 2:
        return read
    out = list(read)
    for k, mark in enumerate(marks):
        start, end = mark.span()
        before = read[:start].rstrip()
        stop = k > 0 and not (before and before[-1] in ".;:!?")
        for j in range(start, end):
            out[j] = " "
        if stop:
            out[start] = ";"
            if start > 0 and read[start - 1] not in " \t":
                return read          # a mark stuck to a word: no list
    return "".join(out)


def _bracket_pairs(read: str) -> frozenset[int]:
    """The offsets of the round brackets that pair up ("bring me a drink *(*any drink is fine*)*"), not nested: a
    bracket alone, or a pair inside a pair, is ignored as before (words35)."""
    if "(" not in read:
        return frozenset()
    found: set[int] = set()
    opened = -1
    for k, character in enumerate(read):
        if character == "(":
            opened = k if opened < 0 else -2        # a second "(" before ")": nested, no pair of the first
        elif character == ")":
            if opened >= 0:
                found.update((opened, k))
            opened = -1
    return frozenset(found)


def _label(mark: str) -> str:
    label = mark.strip("()- .:\t").strip().lower()
    return _STEP_WORDS.get(label, label)


def _next_label(label: str) -> str:
    return str(int(label) + 1) if label.isdigit() else chr(ord(label) + 1)


_OTHER_DIGIT = re.compile(r"(?![0-9])\d")
"""A decimal digit of another script than ASCII's: full-width "３" (typed with an East Asian input method),
Arabic-Indic "٣", Devanagari "३"."""


def _digits_of_any_script(text: str) -> str:
    """``text`` with each decimal digit of another script as its ASCII digit, one character for one (columns stay):
    "put ３ apples" was "unexpected character '３'" (hostile21); Unicode's decimal digits are digits whatever their
    script (Python's ``int`` reads them so)."""
    import unicodedata

    return _OTHER_DIGIT.sub(lambda m: str(unicodedata.digit(m[0])), text)


def _marks_as_letters(text: str) -> str:
    """``text`` with each combining mark that follows a letter (or another such mark) as the letter "a", one
    character for one, for the word pattern to match: it takes letters only (Python's ``\\w`` holds no mark), so the
    vowel signs of Devanagari or Thai ("रसोई", "ครัว": kitchen) and a decomposed accent were "unexpected character"
    (hostile24). The words keep their own characters."""
    import unicodedata

    out = list(text)
    for i in range(1, len(out)):
        if unicodedata.category(out[i]).startswith("M") and out[i - 1].isalpha():
            out[i] = "a"
    return "".join(out)


def _check_whole_numbers(word: str, start: int, text: str) -> None:
    """Refuse a word holding a number that is no decimal digit: a superscript ("²"), a fraction ("½", "⅓"), a
    circled or Roman numeral. Read as letters, "bring me ² apples" brought one apple and "3½ apples" three, the
    number dropped in silence (hostile21)."""
    import unicodedata

    for i, character in enumerate(word):
        if unicodedata.category(character) == "No":
            raise CommandError(f"{character!r} ({unicodedata.name(character, 'a number sign').lower()}) is no "
                               "whole number written in digits or words: seal counts things in whole numbers ('put 3 "
                               "apples', 'two cups')", start + i + 1, text, ["a whole number"])


def _unexpected(character: str) -> str:
    """The message for a character no word holds, its Unicode name said when it is not ASCII: the invisible ones
    (U+200D ZERO WIDTH JOINER, U+200F RIGHT-TO-LEFT MARK, pasted with a word) show as nothing on a screen."""
    if character.isascii():
        return f"unexpected character {character!r}"
    import unicodedata

    name = unicodedata.name(character, "")
    return f"unexpected character {character!r} (U+{ord(character):04X}{' ' + name if name else ''})"


def _not_utf8(character: str) -> str:
    """Why a lone surrogate is in a command: a command-line argument typed in another encoding than the locale's
    (``seal parse`` in a Latin-1 terminal, its "é" the byte 0xe9) reaches Python as U+DCE9, which the parser called
    an "unexpected character '\\udce9'" (hostile21)."""
    code = ord(character)
    if 0xDC80 <= code <= 0xDCFF:
        return (f"byte 0x{code - 0xDC00:02x} is not UTF-8: seal reads a command as UTF-8 text (was it typed in a "
                "terminal set to another encoding, such as Latin-1? set it, and LANG, to UTF-8)")
    return f"a lone surrogate U+{code:04X} is no character: seal reads a command as UTF-8 text"


_ALPHABETS = ("LATIN", "CYRILLIC", "GREEK")
"""The alphabets whose letters look alike ("с" and "c", "ο" and "o", "і" and "i": Unicode's confusables)."""


def _alphabet(letter: str) -> str | None:
    import unicodedata

    name = unicodedata.name(letter, "")
    return next((a for a in _ALPHABETS if name.startswith(a + " ")), None)


def _check_one_alphabet(word: str, start: int, text: str) -> None:
    """Refuse a word whose letters, between its hyphens and apostrophes, mix Latin, Cyrillic and Greek: "сup" with a
    Cyrillic "с" reads as a cup to a person and as a word of no class to seal (``run "find the сup"`` searched the
    whole house for it). A part wholly in one alphabet ("чашка", "β-carotene") is read as written. The letter that
    differs from most of its part is named, at its column."""
    import unicodedata

    offset = 0
    for part in re.split(r"(['’-])", word):
        found = [(i, a) for i, ch in enumerate(part) if (a := _alphabet(ch)) is not None]
        kinds = {a for _, a in found}
        if len(kinds) > 1:
            most = max(sorted(kinds), key=lambda k: sum(a == k for _, a in found))
            i, odd = next((i, a) for i, a in found if a != most)
            letter = part[i]
            raise CommandError(f"the word {word!r} mixes {odd.title()} and {most.title()} letters ({letter!r} is "
                               f"{unicodedata.name(letter)}): type it in one alphabet", start + offset + i + 1, text,
                               ["a word in one alphabet"])
        offset += len(part)


def _title_before_name(text: str, pos: int, written: bool = True) -> bool:
    """Whether a capitalised word follows the title's stop at ``pos`` ("Mr. *Patel*"), not the end of the text; after
    a title in lower case (``written`` False: "mr. smith"), a word in lower case too."""
    after = _NAME_AFTER.match(text, pos)
    return after is not None and (text[after.end() - 1].isupper() or not written)


def capitalised(word: Word) -> bool:
    """Whether a word is written with a capital and then lower case ("Robin"; not "TV")."""
    text = word.text
    return text[:1].isupper() and (text[1:2].islower() or any(c.islower() for c in text[2:]))


def printable(text: str) -> str:
    """The text with control characters as spaces (for a message's caret line)."""
    return _CONTROL.sub(" ", text)
