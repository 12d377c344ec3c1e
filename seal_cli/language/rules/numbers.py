"""Numbers and quantities: "two apples", "the two books", "room 214", "cut it into eight", "both of
the cups", and the possessive "'s"."""

from __future__ import annotations

from seal_cli.language.english import ADDITIVES, NP_OPENERS, NUMBERS, PREPOSITIONS, QUANTIFIERS, VAGUE_NUMBERS
from seal_cli.language.rule import Example, Match, Rule
from seal_cli.language.state import State, first_words, match_phrase
from seal_cli.language.tags import Tag
from seal_cli.language.tokens import Word, capitalised

_NUMBER_FIRST = first_words(NUMBERS)
PARTED = frozenset(["them", "these", "those", "it", "this", "that", "us"])
"""Pronouns after a quantifier's "of" ("one of *them*", "some of *it*"): the whole is one pronoun."""


def _digits_or_number(low: str) -> bool:
    return low.isdigit() or low in NUMBERS


def _number(s: State, i: int) -> tuple[int, object]:
    n = match_phrase(s.words, i, NUMBERS)
    return n, NUMBERS[" ".join(x.lower for x in s.words[i:i + n])] if n else None


def _label(s: State, i: int) -> Match | None:
    if s.prev_tag() in (Tag.WORD, Tag.NAME) and (s.label_at(i) or _before_state_asked(s, i)):
        return s.emit(i, 1, Tag.LABEL, s.words[i].lower)          # "room 214", "table 9": no count
    return None


def _before_state_asked(s: State, i: int) -> bool:
    """Whether the number at ``i`` ends a thing's name right before the state a yes/no question asks ("is locker 2
    *open*?": the state is no noun it counts; e2e33)."""
    from seal_cli.language.rules.requests import state_asked_at  # requests reads numbers' tags: imported late

    low = s.words[i].lower
    return (low.isascii() and low.isdigit() or low in NUMBERS and low not in VAGUE_NUMBERS) and \
        state_asked_at(s, i + 1)


def _number_as_noun(s: State, i: int) -> Match | None:
    n, _ = _number(s, i)
    if n and s.prev_tag() == Tag.PREP and not s.noun_follows(i + n) and s.words[i].lower not in ("one", "a", "an"):
        return s.emit(i, n, Tag.WORD)                             # "cut it into eight": so many pieces, a noun
    return None


def _count(s: State, i: int) -> Match | None:
    low, nxt = s.words[i].lower, s.next_lower(i)
    n, value = _number(s, i)
    if n == 1 and nxt == "of" and _quantifier_of(s, i) is not None:
        return None                               # "two *of* them", "two of the chairs": a part of a whole
    if n and not s.in_np() and (low != "one" or s.np_starts(i + 1) and nxt not in PREPOSITIONS and
                                not match_phrase(s.words, i + 1, ADDITIVES)) and \
            (n > 1 or low != "one" or s.noun_follows(i + 1)):     # "the blue one *too*": no noun counted (words31)
        return s.emit(i, n, Tag.NUM, value)
    return None


def _count_after_article(s: State, i: int) -> Match | None:
    n, value = _number(s, i)
    if n and s.in_np() and s.words[i].lower != "one" and s.prev_tag() == Tag.DET and s.noun_follows(i + n):
        return s.emit(i, n, Tag.NUM, value)                       # "the two books"
    return None


MULTIPLIERS = {"dozen": 12, "hundred": 100, "thousand": 1_000, "million": 1_000_000, "billion": 1_000_000_000,
               "trillion": 1_000_000_000_000}
"""Words that multiply the count before them ("two *hundred* apples", "a *dozen* eggs"). Read as letters, "bring me
one million apples" brought one apple and "2 thousand" two, the count cut by the multiplier in silence (hostile21);
a count past the planner's bound is then refused, as "1000 apples" is."""
_MULTIPLES = {f"{word}s": 2 * value for word, value in MULTIPLIERS.items()}
""""*hundreds* of apples": at least two hundred (it read as a thing called "hundred")."""


def _multiplied(s: State, i: int) -> Match | None:
    words, low = s.words, s.words[i].lower
    if low in _MULTIPLES:
        return s.emit(i, 2, Tag.NUM, _MULTIPLES[low]) if s.next_lower(i) == "of" else None
    n, value = _number(s, i)
    if not n:
        if low.isascii() and low.isdigit():
            n, value = 1, int(low)
        elif low in ("a", "an"):
            n, value = 1, 1
        else:
            return None
    if not isinstance(value, int) or i + n + 1 >= len(words) or words[i + n].lower not in MULTIPLIERS:
        return None
    added, m = _added(s, i + n + 1)
    if m and s.noun_follows(i + n + 1 + m):     # "a hundred and one apples", "two hundred fifty cups"
        return s.emit(i, n + 1 + m, Tag.NUM, value * MULTIPLIERS[words[i + n].lower] + added)
    after = words[i + n + 1].lower
    if after == "of":                       # "a dozen of the eggs", "two hundred of them": the "of" is the count's
        n += 1
    elif not s.noun_follows(i + n + 1):
        return None
    return s.emit(i, n + 1, Tag.NUM, value * MULTIPLIERS[words[i + n - (after == "of")].lower])


def _added(s: State, k: int) -> tuple[int, int]:
    """The number added after a multiplier at ``k``, maybe after "and" ("a hundred *and one*", "two hundred *and
    fifty*", "a thousand *twenty-two*"): its value and how many words it takes ((0, 0): none)."""
    words = s.words
    j = k + (1 if k < len(words) and words[k].lower == "and" else 0)
    if j >= len(words):
        return 0, 0
    low = words[j].lower
    value = _past_twelve_value(low)
    if value is not None:
        if low in TENS and j + 1 < len(words) and words[j + 1].lower in UNITS:
            return value + UNITS[words[j + 1].lower], j + 2 - k     # "and twenty three"
        return value, j + 1 - k
    if low.isascii() and low.isdigit():
        return int(low), j + 1 - k
    if low in NUMBERS and low not in VAGUE_NUMBERS or low == "one":
        number = NUMBERS[low]
        return (number, j + 1 - k) if isinstance(number, int) else (0, 0)
    return 0, 0


HALF = "half"
"""A predeterminer: "*half* the cookies", "*half* of the cake", "*half* a cup of water": the thing is what follows
("cut it in half" ends on it: a result, as before)."""


def _half(s: State, i: int) -> Match | None:
    words = s.words
    k = i + 1 + (1 if s.next_lower(i) == "of" else 0)
    if s.in_np() or k >= len(words) or words[k].lower not in NP_OPENERS or words[k].lower in PARTED:
        return None                              # "half of it": a pronoun, as before
    return s.emit(i, k - i, Tag.DET, HALF)


TEENS = {"thirteen": 13, "fourteen": 14, "fifteen": 15, "sixteen": 16, "seventeen": 17, "eighteen": 18,
         "nineteen": 19}
TENS = {"twenty": 20, "thirty": 30, "forty": 40, "fifty": 50, "sixty": 60, "seventy": 70, "eighty": 80, "ninety": 90}
UNITS = {"one": 1, "two": 2, "three": 3, "four": 4, "five": 5, "six": 6, "seven": 7, "eight": 8, "nine": 9}
"""The number words past twelve (``NUMBERS`` counts to twelve): "bring me twenty apples" brought one apple, the
number read as a word of the phrase (hostile21)."""


def _past_twelve_value(low: str) -> int | None:
    """The value of "fifteen", "forty", "forty-two"; None for any other word."""
    if low in TEENS or low in TENS:
        return TEENS.get(low) or TENS[low]
    tens, dash, unit = low.partition("-")
    return TENS[tens] + UNITS[unit] if dash and tens in TENS and unit in UNITS else None


def _past_twelve(s: State, i: int) -> Match | None:
    words, low = s.words, s.words[i].lower
    value = _past_twelve_value(low)
    if value is None or s.prev_tag() in (Tag.WORD, Tag.NAME):    # "room twenty": a numbered thing, as it was
        return None
    n = 1
    if low in TENS and s.next_lower(i) in UNITS:                    # "twenty three"
        value, n = value + UNITS[s.next_lower(i)], 2
    if i + n + 1 < len(words) and words[i + n].lower in MULTIPLIERS and s.noun_follows(i + n + 1):
        value, n = value * MULTIPLIERS[words[i + n].lower], n + 1   # "twenty thousand cups"
    if not s.noun_follows(i + n):
        return None
    return s.emit(i, n, Tag.NUM, value)


def _digits(s: State, i: int) -> Match | None:
    low = s.words[i].lower
    if not (low.isascii() and low.isdigit()):
        return None
    if s.prev_tag() == Tag.PREP and not s.noun_follows(i + 1):
        return s.emit(i, 1, Tag.WORD)                             # "the guests in 305": a place named by its number
    return s.emit(i, 1, Tag.NUM, int(low))


def _apostrophe_s(s: State, i: int) -> Match | None:
    words, nxt = s.words, s.next_lower(i)
    last = s.out[-1] if s.out else None
    if last is not None and last.tag in (Tag.NAME, Tag.WORD, Tag.PRON) and s.np_starts(i + 1) and \
            nxt not in ("a", "an", "the"):
        n = 1
        while last.tag == Tag.WORD and not capitalised(last) and n < len(s.out) and s.out[-n - 1].tag == Tag.WORD \
                and not capitalised(s.out[-n - 1]):
            n += 1                                # "the *coffee maker's* spout": the compound is whose
        if n > 1 and (n == len(s.out) or s.out[-n - 1].tag not in (Tag.DET, Tag.NUM, Tag.POSS)):
            n = 1                                 # "tell sophie *dinner's* ready": no determiner, no compound
        owner = " ".join(w.text for w in s.out[len(s.out) - n:])
        return Match(1, last=Word(f"{owner}'s", s.out[-n].start, words[i].end, Tag.POSS, owner), replaces=n)
    return s.emit(i, 1, Tag.BE)


def _quantifier_of(s: State, i: int) -> Match | None:
    words, low = s.words, s.words[i].lower
    if not s.in_np() and s.next_lower(i) == "of" and i + 2 < len(words) and words[i + 2].lower in PARTED and \
            not (words[i + 2].lower in NP_OPENERS and s.noun_follows(i + 3)):
        return s.emit(i, 3, Tag.PRON, low)   # "slice one of them": a pronoun, the part of what "them" is
    if not s.in_np() and s.next_lower(i) == "of" and i + 2 < len(words) and \
            (words[i + 2].lower in NP_OPENERS):
        number = NUMBERS.get(low)            # "both of the cups", "one of the books"
        return s.emit(i, 2, Tag.DET if number is None else Tag.NUM, number)
    return None


MULTIPLIED = Rule("number times a multiplier", _multiplied, (
    Example("bring me a dozen eggs", "a dozen", Tag.NUM),
    Example("bring me a hundred and one apples", "a hundred and one", Tag.NUM),
    Example("put two hundred fifty cups in the sink", "two hundred fifty", Tag.NUM),
    Example("bring me two hundred apples", "two hundred", Tag.NUM),
    Example("put 3 thousand cups in the sink", "3 thousand", Tag.NUM),
    Example("bring me hundreds of apples", "hundreds of", Tag.NUM),
), lambda low: low.isdigit() or low in _NUMBER_FIRST or low in ("a", "an") or low in _MULTIPLES,
    "a count and a multiplier after it ('dozen', 'hundred', 'million'): their product",
    needs=frozenset(MULTIPLIERS) | frozenset(_MULTIPLES))
PAST_TWELVE = Rule("number word past twelve", _past_twelve, (
    Example("bring me twenty apples", "twenty", Tag.NUM),
    Example("put forty-two cups in the sink", "forty-two", Tag.NUM),
    Example("bring me twenty three apples", "twenty three", Tag.NUM),
), lambda low: _past_twelve_value(low) is not None, "a number word from thirteen to ninety-nine counting the noun "
   "after it (and a multiplier after it: 'twenty thousand')")
LABEL = Rule("number naming a thing", _label, (
    Example("go to room 214", "214", Tag.LABEL),
    Example("clean meeting room three", "three", Tag.LABEL),
    Example("carry the tray to table one", "one", Tag.LABEL),         # words42: a bare noun after a preposition
    Example("is locker 2 open?", "2", Tag.LABEL),                    # e2e33: the state asked is no noun counted
), _digits_or_number, "a number after a noun names a numbered thing, unless a noun follows it (the state a "
   "question asks is none)",
   after=frozenset([Tag.WORD, Tag.NAME]))
NUMBER_AS_NOUN = Rule("number as a noun", _number_as_noun, (
    Example("cut it into eight", "eight", Tag.WORD),
), _NUMBER_FIRST, "a number word after a preposition with no noun: so many pieces")
COUNT = Rule("number", _count, (
    Example("bring me two apples", "two", Tag.NUM),
    Example("grab a couple of cups", "a couple of", Tag.NUM),
), _NUMBER_FIRST, "a number word counting the noun after it")
COUNT_AFTER_ARTICLE = Rule("number after an article", _count_after_article, (
    Example("bring me the two books", "two", Tag.NUM),
), _NUMBER_FIRST, "a number after 'the'")
DIGITS = Rule("digits", _digits, (
    Example("bring me 3 apples", "3", Tag.NUM),
    Example("find the guests in 305", "305", Tag.WORD),
), str.isdigit, "digits: a count, or a place named by its number after a preposition")
APOSTROPHE_S = Rule("'s", _apostrophe_s, (
    Example("bring me Roger's coat", "Roger's", Tag.POSS),
    Example("put the mug under the coffee maker's spout", "coffee maker's", Tag.POSS),
), frozenset(["'s"]), "'s: a possessive before a noun phrase, else 'is'")
QUANTIFIER_OF = Rule("quantifier of", _quantifier_of, (
    Example("bring me both of the cups", "both of", Tag.DET),
    Example("bring me one of the books", "one of", Tag.NUM),
    Example("put potatoes in the basket, slice one of them", "one of them", Tag.PRON),
    Example("take both of them to the sink", "both of them", Tag.PRON),
), QUANTIFIERS, "'both of the', 'one of the': a determiner or a number; 'one of them': a pronoun")
HALF_OF = Rule("half the", _half, (
    Example("put half the cookies in the jar", "half", Tag.DET),
    Example("eat half of the cake", "half of", Tag.DET),
), frozenset([HALF]), "'half' before a determiner (or 'of' and one): a predeterminer, the thing follows")
