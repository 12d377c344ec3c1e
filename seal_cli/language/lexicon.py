"""Words of a command and the part each plays: the lexicon behind ``grammars/command.lark``.

The command grammar is written over *tags*, not words. This module splits a command into
words and tags each one, so that the grammar never lists a verb or a noun:

- **verbs** are the lexical units of the frame library (``Library.by_unit``), multiword ones
  included ("pick up", "tell me how many"); a particle verb may be split around its object
  ("pick the cup up", "turn the lamp on"). A frame with new lexical units makes new verbs;
- **function words** (determiners, prepositions, pronouns, conjunctions, politeness) are the
  closed classes of English, listed in :mod:`seal_cli.language.english`;
- **every other word is open-class**: a noun, an adjective or a name (``NAME``: a capitalised
  word where a noun phrase starts). A word nobody has listed is never an error;
- **result words** (``RESULT``): a participle of a lexical unit, or an adjective equal to the
  predicate of a frame's result (``hot``, ``clean``), before a noun: "a *heated* egg" evokes
  Heat. Which words these are is derived from the library's postconditions;
- **participles after a noun** (``VBG_T``, ``VBG_P``, ``VBG_I``: transitive, with a
  prepositional complement, bare) describe people and things: "the person *wearing* a hat".

Lemmas and singulars come from lemminflect, which ships its data. The tagger decides what the
grammar cannot: whether "and" joins clauses or noun phrases, whether "light" is a verb or a
noun, by looking one or two words ahead.
"""

from __future__ import annotations

import re
from collections.abc import Iterable, Mapping, Sequence
from dataclasses import dataclass

from seal_cli.errors import SealError, Where
from seal_cli.frames.library import Library
from seal_cli.language.english import (
    AND_WORDS,
    BASE_FORM_SUBJECTS,
    BE_WORDS,
    BECAUSE,
    CLOCK_PREPOSITIONS,
    CLOCK_WORDS,
    CONTRACTED,
    DETERMINERS,
    END_MARKS,
    FILLERS,
    FINITE,
    FREQUENCY_ADVERBS,
    HERE_WORDS,
    LINKING_VERBS,
    NOMINATIVE,
    NUMBERS,
    OBJECT_PRONOUNS,
    PARTICLES,
    PARTITIVES,
    PATH_PREPOSITIONS,
    POLITE,
    POLITE_FORMULAE,
    POSSESSIVES,
    PREPOSITIONS,
    PRONOUNS,
    QUANTIFIERS,
    RELATIVES,
    SEPARATOR_WORDS,
    SPELLINGS,
    STATEMENT_LINKS,
    STATES_DONE,
    SUBJECTS,
    SUBORDINATORS,
    THIRD_PERSON_SUBJECTS,
    TIME_MEASURE,
    TIME_UNITS,
    TIME_WORDS,
    TITLES,
    VAGUE_NUMBERS,
    VOCATIVES,
    WH_WORDS,
)
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

__all__ = ["MAX_LENGTH", "CommandError", "Lexicon", "Mention", "Tagger", "Word", "is_plural", "mentions",
           "noun_lemma", "tokenize", "verb_lemma"]

MAX_LENGTH = 1000
"""The longest command accepted, in characters (a spoken command is far shorter)."""

class CommandError(SealError):
    """A command that cannot be parsed: where (column) and what was expected there."""

    def __init__(self, message: str, column: int, text: str, expected: Sequence[str] = ()) -> None:
        super().__init__(message, Where(None, None, column), source_line=text)
        self.expected = list(expected)
        self.text = text

    def to_json(self) -> dict[str, object]:
        return {"message": self.message, "column": self.column, "expected": self.expected}


# ---------------------------------------------------------------------------------------------
# Phrases of closed-class words, and the first words of what the tagger looks at specially

_PHRASES: dict[str, tuple[str, ...]] = {}
for _table in (PREPOSITIONS, POLITE, POLITE_FORMULAE, SEPARATOR_WORDS, NUMBERS, HERE_WORDS, TIME_WORDS, SUBORDINATORS,
               VOCATIVES):
    for _phrase in _table:
        words = tuple(_phrase.split())
        if len(words) > 1:
            _PHRASES.setdefault(words[0], ())
            _PHRASES[words[0]] = (*_PHRASES[words[0]], _phrase)
_LONGEST_FUNCTION_PHRASE = max(len(p.split()) for ps in _PHRASES.values() for p in ps)

_SUB_FIRST = frozenset(p.split()[0] for p in SUBORDINATORS)
_FORMULA_FIRST = frozenset(p.split()[0] for p in POLITE_FORMULAE)
_TIME_FIRST = frozenset(p.split()[0] for p in TIME_WORDS)
_FUNCTION_SPECIAL = _TIME_FIRST | {"for", "every", "each", "one", "ones", "that", "at", "by", "until", "till",
                                   "around", "in", "before"}
"""First words of what :meth:`Tagger._special_function_word` tags (checked before calling it)."""
_SEP_FIRST = frozenset(p.split()[0] for p in SEPARATOR_WORDS)
_LEAD_FIRST = _SUB_FIRST | _SEP_FIRST | {",", ";", ":", "start", "begin", "finish", "end", "continue", "take", "have",
                                         "be"}
"""Words that may begin what :meth:`Tagger.lead_in` tags before a verb (besides adverbs and polite frames)."""
_REL_FIRST = RELATIVES | NOMINATIVE | {"where", "you"}
_INDEFINITE = frozenset(["something", "anything", "nothing", "everything", "someone", "somebody", "anyone",
                         "anybody"])

NP_START = frozenset({"DET", "NUM", "POSS", "PRON", "NAME", "WORD", "RESULT"})
"""Tags that can begin a noun phrase."""

# ---------------------------------------------------------------------------------------------
# Tokens


class Word:
    """A word (or a merged multiword function phrase) of the command, with its tag.

    ``start``/``end`` are character offsets into the command. ``info`` carries what the tag
    needs: the lexical unit of a VERB, the (frame, unit) of a RESULT, the number of a NUM,
    the preposition of a PREP. (A plain slotted class: the tagger makes tens of thousands.)
    """

    __slots__ = ("end", "info", "lower", "start", "tag", "text")

    def __init__(self, text: str, start: int, end: int, tag: str = "", info: object = None) -> None:
        self.text = text
        self.start = start
        self.end = end
        self.tag = tag
        self.info = info
        lower = text.lower()
        lower = lower.replace("’", "'") if "’" in lower else lower
        self.lower = SPELLINGS.get(lower, lower)         # "pls": "please"

    def __repr__(self) -> str:
        return f"Word({self.text!r}, {self.start}, {self.end}, {self.tag!r})"


_TOKEN = re.compile(r"""
    (?P<word>[^\W\d_]+(?:['’](?![sS]\b)[^\W\d_]+|-[^\W_]+)*|[0-9]+(?:-[^\W_]+)*)   # letters, inner ' and -
                                                           # ("t-shirt", "under-12s", "covid-19"); numbers
  | (?P<poss>['’]s\b)                                      # possessive 's (and is)
  | (?P<amp>&)
  | (?P<dash>[—–]|-{2,}|(?<=\s)-(?=\s))                   # a dash between clauses reads as ";"
  | (?P<punct>[,;:.!?]+)
  | (?P<quote>["“”'‘’`()\[\]])                             # quotes and brackets are ignored
  | (?P<space>\s+)
""", re.VERBOSE)
_CONTROL = re.compile(r"[\x00-\x08\x0b-\x1f\x7f-\x9f]")
_NAME_AFTER = re.compile(r"\s+[^\W\d_]")


def tokenize(text: str) -> list[Word]:
    """The words and punctuation of ``text``; anything else is a SealError at its column."""
    if len(text) > MAX_LENGTH:
        raise CommandError(f"command too long ({len(text)} characters; the limit is {MAX_LENGTH})", MAX_LENGTH + 1,
                           text[:MAX_LENGTH + 20], ["a shorter command"])
    bad = _CONTROL.search(text)
    if bad:
        raise CommandError(f"control character U+{ord(bad.group()):04X} in the command", bad.start() + 1,
                           _printable(text), ["a word"])
    words: list[Word] = []
    pos = 0
    for match in _TOKEN.finditer(text):
        if match.start() != pos:
            raise CommandError(f"unexpected character {text[pos]!r}", pos + 1, text, ["a word"])
        pos = match.end()
        kind = match.lastgroup
        if kind == "word":
            words.append(Word(match.group(), match.start(), pos))
        elif kind == "punct" and match.group() == "." and words and words[-1].end == match.start() and \
                words[-1].lower in TITLES and _capitalised(words[-1]) and _title_before_name(text, pos) and \
                (len(words) < 2 or words[-2].lower not in DETERMINERS):     # "the Dr. Then ..." ends a sentence
            title = words[-1]
            words[-1] = Word(text[title.start:pos], title.start, pos)    # "Mr. Patel": the stop is the title's
        elif kind == "punct":           # "..." and "?!" are one mark
            words.append(Word(match.group()[0], match.start(), pos))
        elif kind == "amp":
            words.append(Word("and", match.start(), pos))
        elif kind == "dash":
            words.append(Word(";", match.start(), pos))
        elif kind == "poss":
            words.append(Word("'s", match.start(), pos))
    if pos != len(text):
        raise CommandError(f"unexpected character {text[pos]!r}", pos + 1, text, ["a word"])
    return words


def _title_before_name(text: str, pos: int) -> bool:
    """Whether a capitalised word follows the title's stop at ``pos`` ("Mr. *Patel*"), not the end of the text."""
    after = _NAME_AFTER.match(text, pos)
    return after is not None and text[after.end() - 1].isupper()


def _awaits_name(word: Word) -> bool:
    """Whether a tagged word is a title whose name follows ("*Mr.* Hughes"): no noun phrase yet."""
    return word.text.endswith(".") and word.lower.rstrip(".") in TITLES


def _subject_word(word: Word) -> bool:
    """Whether a word may only start a clause: a subject pronoun or its contraction ("we're", "I'll")."""
    low = word.lower
    return low in SUBJECTS and low not in OBJECT_PRONOUNS or \
        "'" in low and low.split("'")[0] in SUBJECTS and "'" + low.split("'", 1)[1] in CONTRACTED


def _statement_lead(word: Word, nxt: Word) -> bool:
    """Whether a word may lead a statement said beside the command: a sentence adverb ("*apparently*
    they're staying"), or "and"/"then"/"quick" before a comma, an adverb or a subject ("*and* quick, it's
    the next shot", "and then *it* goes ...")."""
    low, after = word.lower, nxt.lower
    if is_adverb(low) and low.endswith("ly"):
        return True
    return low in ("and", "then", "quick") and (after in (",", "quick", "then") or is_adverb(after) or
                                                after in SUBJECTS or _subject_word(nxt))


def _inflected(low: str) -> bool:
    """Whether a word is a verb's third-person or past form ("likes", "left"), not its base or -ing form."""
    lemma = verb_lemma(low) if low.isalpha() else None
    return bool(lemma) and lemma != low and not low.endswith("ing")


def _printable(text: str) -> str:
    return _CONTROL.sub(" ", text)


# ---------------------------------------------------------------------------------------------
# The lexicon of one library


@dataclass(frozen=True)
class Lexicon:
    """Verbs and result words of a library, indexed for the tagger.

    ``units``: first word → the library's lexical units starting with it, longest first.
    ``results``: a participle or result adjective → (frame name, lexical unit).
    ``speech``: units of frames whose first element is a ``message`` or a ``question`` ("tell", "say",
    "answer"): after them a clause is what is said ("tell him *that dinner is ready*"), not a relative
    clause or a condition. ``goals``: units of frames with a ``goal`` element ("follow", "go").
    """

    units: Mapping[str, tuple[tuple[str, ...], ...]]
    results: Mapping[str, tuple[str, str]]
    verbs: tuple[str, ...]
    speech: frozenset[str] = frozenset()
    goals: frozenset[str] = frozenset()

    @classmethod
    def of(cls, library: Library) -> Lexicon:
        units: dict[str, list[tuple[str, ...]]] = {}
        for unit in library.units:           # longest first
            words = tuple(unit.split())
            units.setdefault(words[0], []).append(words)
        speech = frozenset(unit.text for frame in library.frames if frame.elements
                           and frame.elements[0].type in ("message", "question") for unit in frame.lexical_units)
        goals = frozenset(unit.text for frame in library.frames if any(e.role == "goal" for e in frame.elements)
                          for unit in frame.lexical_units)
        return cls({w: tuple(us) for w, us in units.items()}, _result_words(library),
                   tuple(sorted(library.by_unit)), speech, goals)

    def verb_at(self, words: Sequence[Word], i: int, stop: int) -> tuple[str, int, int | None] | None:
        """The lexical unit that starts at word ``i``: (unit, words it covers contiguously,
        index of a split particle or None). Contiguous matches are preferred, longest first;
        "pick the cup up" splits "pick up" when "up" stands alone before the clause ends."""
        first = words[i].lower
        candidates = self.units.get(first)
        if not candidates:                       # "putting", "placed": a form of a lexical unit
            base = verb_lemma(first) if first.isalpha() else None
            candidates = self.units.get(base) if base and base != first else None
            if not candidates:
                return None
        for unit in candidates:
            n = len(unit)
            if i + n <= len(words) and all(words[i + k].lower == unit[k] for k in range(1, n)):
                if i + n < len(words) and words[i + n].lower in ("of", "'s"):
                    return None                  # "slice of apple", "the light's": a noun
                if n > 1 or not self._split(words, i, stop, candidates):
                    return " ".join(unit), n, None
                break
        split = self._split(words, i, stop, candidates)
        if split:
            return split
        return None

    def _split(self, words: Sequence[Word], i: int, stop: int,
               candidates: Iterable[tuple[str, ...]]) -> tuple[str, int, int] | None:
        for unit in candidates:
            if len(unit) != 2 or unit[1] not in PARTICLES:
                continue
            for j in range(i + 2, stop):
                if words[j].lower == unit[1] and _stands_alone(words, j) and \
                        _match_phrase(words, j - 1, TIME_WORDS) < 2:      # not "right away"
                    return " ".join(unit), 1, j
        return None


def _stands_alone(words: Sequence[Word], j: int) -> bool:
    """A particle stands alone when no noun phrase follows it (it is not a preposition there)."""
    if j + 1 >= len(words):
        return True
    after = words[j + 1].lower
    return after in (",", ".", "!", "?", ";", "please") or after in PREPOSITIONS or after in SEPARATOR_WORDS or \
        after in BECAUSE or "'" in after and after.split("'")[0] in SUBJECTS     # "turn it off *it's* too loud"


def _result_words(library: Library) -> dict[str, tuple[str, str]]:
    """Words before a noun that name a frame's result: participles of its lexical units and the
    predicate of a positive one-place postcondition on its first element (``hot(theme)``)."""
    results: dict[str, tuple[str, str]] = {}
    for frame in library.frames:
        if not frame.elements or not frame.lexical_units:
            continue
        first = frame.elements[0]
        if first.role != "theme" or library.taxonomy.is_a("person", first.type) and \
                not library.taxonomy.is_open(first.type):
            continue    # only a theme's state is a result ("the moved cup" does not mean Go)
        effects = [f for f in frame.postconditions if not f.negated and f.args == (first.role,)]
        if not effects:
            continue
        for fact in effects:
            if fact.predicate.isalpha() and is_adjective(fact.predicate):
                results.setdefault(fact.predicate, (frame.name, frame.lexical_units[0].text))
                for unit in frame.lexical_units:     # "a warm apple", "a cool tomato": the same state
                    if len(unit.words) == 1 and is_gradable(unit.text):
                        results.setdefault(unit.text, (frame.name, unit.text))
        for unit in frame.lexical_units:
            words = unit.words
            if len(words) == 1 or all(w in PARTICLES for w in words[1:]):
                for form in participles(words[0]):
                    if form not in _CLOSED:
                        results.setdefault(form, (frame.name, unit.text))
                        if len(words) > 1:          # "turned off": ToggleOff, whatever "turned" alone is
                            results.setdefault(" ".join((form, *words[1:])), (frame.name, unit.text))
    return results


_CLOSED = (DETERMINERS | POSSESSIVES | PRONOUNS | WH_WORDS | BE_WORDS | PARTICLES
           | frozenset(p for p in PREPOSITIONS if " " not in p) | frozenset(NUMBERS))


# ---------------------------------------------------------------------------------------------
# The tagger


def _match_phrase(words: Sequence[Word], i: int, table: Iterable[str] | Mapping[str, object]) -> int:
    """How many words of a multiword (or one-word) phrase of ``table`` start at ``i`` (0: none)."""
    first = words[i].lower
    if first not in _PHRASES:
        return 1 if first in table else 0
    best = 0
    for phrase in _PHRASES.get(first, ()):
        if phrase in table:
            parts = phrase.split()
            n = len(parts)
            if n > best and i + n <= len(words) and all(words[i + k].lower == parts[k] for k in range(n)):
                best = n
    if best == 0 and first in table:
        best = 1
    return best


def _merge(words: list[Word], i: int, n: int, tag: str, info: object = None) -> Word:
    text = " ".join(w.text for w in words[i:i + n])
    merged = Word(text, words[i].start, words[i + n - 1].end, tag, info)
    return merged


def _capitalised(word: Word) -> bool:
    text = word.text
    return text[:1].isupper() and any(c.islower() for c in text[1:])


def _its_is_it_is(words: Sequence[Word], k: int) -> bool:
    """Whether "its" written without its apostrophe is "it's" ("*its* too loud", "*its* getting cold",
    "*its* a mess"): a determiner, an adverb, a participle, or an adjective that ends the phrase follow it,
    no noun ("its lid", "its red lid")."""
    nxt = words[k + 1].lower if k + 1 < len(words) else ""
    if not nxt.isalpha():
        return False
    if nxt in DETERMINERS or nxt in ("not", "been", "going", "gonna", "got") or gerund_lemma(nxt) or \
            nxt not in _CLOSED and is_adverb(nxt):
        return True
    after = words[k + 2].lower if k + 2 < len(words) else ""
    return is_adjective(nxt) and (not after.isalpha() or after in _CLOSED or after in SEPARATOR_WORDS)


def _without_fillers(words: list[Word]) -> list[Word]:
    """The words without hesitations ("um", "uh", ...) and the comma after one ("and, *um,* put it on the
    bed"): they say nothing, so "and then, um, chill it" is "and then, chill it"."""
    if not any(w.lower in FILLERS for w in words):
        return words
    kept: list[Word] = []
    skip_comma = False
    for w in words:
        if w.lower in FILLERS:
            skip_comma = True
            continue
        if not (skip_comma and w.lower == ","):
            kept.append(w)
        skip_comma = False
    return kept


class Tagger:
    """Tags the words of one command (see the module docstring). Not thread-safe; cheap to make."""

    def __init__(self, lexicon: Lexicon, words: list[Word], text: str = "") -> None:
        self.text = text
        self.lexicon = lexicon
        self.words = _without_fillers(words)
        for k, w in enumerate(self.words):
            if w.lower == "its" and _its_is_it_is(self.words, k):
                w.lower = "it's"                        # "turn the radio off *its* too loud"
        self.out: list[Word] = []
        self._verbs: dict[int, tuple[str, int, int | None] | None] = {}
        self.using = False                  # after "use X": "to" starts the clause of what X is used for
        self.speech = False                 # the clause's verb says something ("tell"): a clause after it is said
        self.verb_index = -1                # where in ``out`` the clause's verb is
        self.remarks: list[tuple[int, int]] = []   # character spans of statements dropped beside the command

    def verb_at(self, i: int) -> tuple[str, int, int | None] | None:
        """The lexical unit starting at word ``i`` (memoised: the tagger asks more than once)."""
        if i not in self._verbs:
            self._verbs[i] = self.lexicon.verb_at(self.words, i, self.clause_end(i + 1))
        return self._verbs[i]

    # -- helpers -----------------------------------------------------------------------------
    def text_of(self, start: int, end: int) -> str:
        return self.text[start:end] if self.text else ""

    def clause_end(self, i: int) -> int:
        """Index of the first word at or after ``i`` that may end the clause."""
        for j in range(i, len(self.words)):
            if self.words[j].lower in (",", ";", ".", "!", "?", "then", "and"):
                return j
        return len(self.words)

    def verb_after(self, i: int) -> bool:
        """Whether a verb (a lexical unit) starts at ``i``, after any politeness words; or at ``i`` itself,
        a verb that is politeness only before another ("and *go* to the hall", not "go and get")."""
        start = i
        while i < len(self.words):
            n = _match_phrase(self.words, i, POLITE)
            if n and self.words[i].lower not in ("to", "and", "then"):
                i += n
                continue
            break
        if i < len(self.words) and (self.verb_at(i) is not None or self.use_at(i)):
            return True
        return start < i and start < len(self.words) and self.verb_at(start) is not None

    def formula(self, i: int) -> int:
        """How many words a politeness formula said as a whole clause takes at ``i`` (0: none): it
        ends the command or is followed by punctuation, "and"/"then" or more politeness."""
        words = self.words
        if words[i].lower not in _FORMULA_FIRST:
            return 0
        n = _match_phrase(words, i, POLITE_FORMULAE)
        if not n or i + n == len(words):
            return n
        nxt = words[i + n].lower
        if nxt in END_MARKS or nxt in (",", ";", ":", "and", "then"):
            return n
        m = _match_phrase(words, i + n, POLITE)
        return n if m and nxt != "to" and self.verb_after(i + n) else 0

    def statement_at(self, i: int) -> int:
        """Whether a statement starts at ``i`` and where its clause ends (0: none): a subject (a pronoun,
        a contraction "it's", "we're", "i'll"; or a noun phrase: "the bus", "my son Declan", "Bogdan") and
        then a finite verb ("is", "has", "can't", "keeps", "arrives on"); a command starts with a verb's
        base form instead. The clause ends at punctuation."""
        words = self.words
        if i >= len(words):
            return 0
        end = i
        while end < len(words) and words[end].lower not in END_MARKS and words[end].lower not in (",", ";", ":"):
            end += 1
        first = words[i].lower
        nxt = words[i + 1].lower if i + 1 < end else ""
        if i + 1 < len(words) and _statement_lead(words[i], words[i + 1]):
            k = i + 1 + (words[i + 1].lower == ",")          # "..., *apparently* they're staying", "and quick, it's"
            return self.statement_at(k) if k < len(words) and not (_capitalised(words[i]) and k == i + 1) else 0
        if nxt.isascii() and nxt.isdigit() and i + 2 < end and words[i + 2].lower in FINITE and \
                first not in self.lexicon.units:
            return end                                        # "Table 4 is ready", "room 12 has no towels"
        if verb_lemma(first) == first and first not in SUBJECTS:
            return 0                                          # "Grab the cup": a command, maybe an unknown verb
        if first in BASE_FORM_SUBJECTS and nxt.isalpha() and nxt not in PREPOSITIONS:
            return end                                        # "we open at six", "I need a hand": no command
        if "'" in first and first.split("'")[0] in SUBJECTS | {"you", "who", "what", "here"} and \
                "'" + first.split("'", 1)[1] in CONTRACTED:
            return end                                        # "we're eating in ten", "i'll be right there"
        if first in SUBJECTS or first == "you" and nxt not in ("can", "could", "will", "would", "should", "must"):
            return end if nxt in FINITE or nxt in CONTRACTED or self.finite_form(i + 1, end) or \
                first in THIRD_PERSON_SUBJECTS and _inflected(nxt) else 0     # "he *likes* company", "it *smells* like"
        partitive = first in QUANTIFIERS and nxt == "of"       # "one of its wheels squeaks"
        if not (first in DETERMINERS or first in POSSESSIVES or _capitalised(words[i]) or partitive):
            return 0
        for k in range(i + 1, end):
            if words[k - 1].lower in DETERMINERS or words[k - 1].lower in POSSESSIVES:
                continue                                      # "the plates": a noun
            if words[k].lower in FINITE or self.finite_form(k, end) or \
                    verb_lemma(words[k].lower) in LINKING_VERBS and _inflected(words[k].lower):
                return end                                    # "the fridge door's open", "the door *seems* loose"
            if k == end - 1 and k > i + 1 and self.final_verb(k, partitive):
                return end                                    # "the timer just went", "one of them squeaks"
        return 0

    def final_verb(self, k: int, partitive: bool) -> bool:
        """Whether the word at ``k``, ending its clause after the subject, is a finite verb with nothing
        after it: a past form ("the kettle *boiled*"), or a present form after an adverb ("the bell
        *always rings*") or after a partitive subject ("one of its wheels *squeaks*"); a word ending in
        s after a noun alone may be a plural noun ("the kitchen plates")."""
        low = self.words[k].lower
        lemma = verb_lemma(low) if low.isalpha() else None
        if not lemma or lemma == low or low.endswith("ing"):
            return False
        before = self.words[k - 1].lower
        return not low.endswith("s") or partitive or is_adverb(before) or before in FREQUENCY_ADVERBS



    def told_at(self, i: int) -> bool:
        """Whether a clause said without "that" starts at ``i``, right after the person a verb of saying
        tells ("tell mom *I'm late*", "tell the waiter *table 4 is ready*"): a statement, and only one
        noun phrase between the verb and it."""
        if self.verb_index < 0 or _awaits_name(self.out[-1]):
            return False                                      # "tell Mr. | Hughes that ...": the title's name
        if not self.statement_at(i) and not self.bare_subject(i):
            return False
        between = self.out[self.verb_index + 1:]
        return all(t.tag in ("DET", "POSS", "WORD", "NAME", "PRON", "LABEL", "RESULT") for t in between) and \
            sum(t.tag in ("PRON", "NAME") for t in between) <= 1

    def bare_subject(self, i: int) -> bool:
        """Whether a statement whose subject is a bare noun starts at ``i`` after a plural person noun
        ("tell the kids *dinner is ready*"): one or two lowercase open words, then "is"/"has"/..."""
        words, out = self.words, self.out
        if len(out) < 2 or out[-1].tag != "WORD" or not is_plural(out[-1].lower) or \
                out[-2].tag not in ("DET", "POSS", "NUM", "WORD"):
            return False
        for k in range(i, min(i + 2, len(words) - 1)):
            low = words[k].lower
            if not low.isalpha() or _capitalised(words[k]) or low in DETERMINERS or low in PRONOUNS or \
                    low in PREPOSITIONS or low in POSSESSIVES or low in self.lexicon.units:
                return False
            if words[k + 1].lower in FINITE:
                return True
        return False

    def finite_form(self, k: int, end: int) -> bool:
        """Whether the word at ``k`` is a verb's third-person or past form followed by what a verb takes
        ("she *arrives on* the bus", "the light *keeps flashing*"), not a plural noun."""
        low = self.words[k].lower if k < end else ""
        lemma = verb_lemma(low) if low.isalpha() else None
        if not lemma or lemma == low or low.endswith("ing"):
            return False                                      # irregular pasts too: "left", "brought"
        nxt = self.words[k + 1].lower if k + 1 < end else ""
        return bool(nxt) and (nxt in PREPOSITIONS or nxt in DETERMINERS or nxt in POSSESSIVES or nxt == "to"
                              or nxt in OBJECT_PRONOUNS or bool(gerund_lemma(nxt)))   # "a guest *left* it"

    def vocatives_end(self, i: int) -> int:
        """Where words of address and tag questions starting at ``i`` end, commas between ("..., *dear*",
        "..., *would you*?"); ``i`` when none."""
        words, k = self.words, i
        while k < len(words):
            n = _match_phrase(words, k, VOCATIVES)
            if n:
                k += n
            elif words[k].lower == "," and k > i:
                k += 1
            else:
                break
        return k

    def remark_unmarked(self, i: int) -> int:
        """A statement after the request with no comma before it, started by "because"/"cos"/... or a subject
        contraction ("give the ball to Lily *cos she wants it*", "turn the radio off *it's too loud*"): how
        many words to drop (0: none). A bare "she"/"I" after a noun may start a relative clause ("the book *I
        left* on the sofa"), so only these."""
        low = self.words[i].lower
        if low not in BECAUSE and not ("'" in low and low.split("'")[0] in SUBJECTS and
                                        "'" + low.split("'", 1)[1] in CONTRACTED):
            return 0
        n = self.remark_after(i - 1)
        return n - 1 if n else 0

    def remark_after(self, i: int) -> int:
        """After a comma that ends a request: words of address, tag questions and statements up to the end
        of the sentence ("..., *dear*? ...", "..., *she's been waiting a while*.", "..., *we're eating in
        ten*"), also after "or", "because", "so" ("..., *or it will melt*"); how many words to drop (0: none).
        Only when nothing else follows in the sentence."""
        words = self.words
        k, spans = i + 1, []
        while True:
            k = self.vocatives_end(k)
            link = 1 if k < len(words) and words[k].lower in STATEMENT_LINKS and k + 1 < len(words) else 0
            end = self.statement_at(k + link)
            if not end:
                break
            spans.append((words[k].start, words[end - 1].end))
            k = end
            while k < len(words) and words[k].lower in (",", ";"):
                k += 1
            if spans and k < len(words) and (k + 1 == len(words) or words[k + 1].lower in END_MARKS) and \
                    words[k].lower not in self.lexicon.units and \
                    (is_adjective(words[k].lower) or words[k].lower.endswith("ing") and gerund_lemma(words[k].lower)):
                spans.append((words[k].start, words[k].end))     # "..., someone left it open, *shocking*."
                k += 1
        if k < len(words) and words[k].lower not in END_MARKS or k == i + 1:
            return 0
        self.remarks.extend(spans)
        return k - i

    def aside(self, i: int) -> int:
        """A sentence said beside the command, with no verb of the library, at the start of a sentence
        ("*Good morning!* Could you ...", "*Priya needs her laptop,* could you bring it to her?"): how many
        words it takes, with its end mark (0: none). A greeting or a statement asks nothing of the
        robot when another sentence holds the command; before a comma, only when a polite request
        follows ("..., could you", "..., please"). Only a verb's base form makes a command: "my
        brother is *freezing*" states."""
        words = self.words
        k = len(self.out) - 1
        while k >= 0 and self.out[k].tag == "POLITE":
            k -= 1                                       # "... Sorry, *gross*": interjections start it
        if k >= 0 and not (self.out[k].tag == "SEP" and self.out[k].lower in END_MARKS):
            return 0                                     # inside a sentence
        stated = self.statement_at(i)
        if stated and stated < len(words) and words[stated].lower in (",", ";") and self.verb_after(stated + 1):
            self.remarks.append((words[i].start, words[stated - 1].end))
            return stated + 1 - i                        # "Bogdan has a question; answer it for him"
        said = any(t.tag == "VERB" for t in self.out)
        alone = i + 1 == len(words) or words[i + 1].lower in END_MARKS      # "... *Gross.*": an adjective alone
        if verb_lemma(words[i].lower) == words[i].lower and not stated and not self.timed_noun(i) and \
                not (said and alone and is_adjective(words[i].lower)):
            return 0                                     # "Grab the cup.": a verb the library lacks, an error
        end, comma = i, -1
        while end < len(words) and words[end].lower not in END_MARKS:
            if not stated and (words[end].lower in self.lexicon.units and self.verb_at(end) is not None
                               or self.use_at(end)):
                return comma + 1 - i if comma > i and self.request_at(comma + 1) else 0
            if words[end].lower in (",", ";") and comma < 0:
                comma = end
            end += 1
        if end >= len(words):
            if not said or stated:
                return 0
            self.remarks.append((words[i].start, words[-1].end))
            return end - i                               # "pour it into the cup... *the blue one*": a fragment after
        while end + 1 < len(words) and words[end + 1].lower in END_MARKS:
            end += 1
        if not any(t.tag == "VERB" for t in self.out) and \
                not any(self.verb_at(k) is not None for k in range(end + 1, len(words))):
            return 0                                     # no sentence holds a command: the error says so
        self.remarks.append((words[i].start, words[end].end))
        return end + 1 - i

    def until_place(self, i: int) -> bool:
        """Whether "until"/"till" at ``i`` says how far a motion goes: after a verb of a frame with a goal,
        a noun phrase with no verb and no time ("walk with her *until the corner*"); "until the bus
        stops" (a noun then an -s form) stays a condition."""
        words = self.words
        if self.verb_index < 0 or str(self.out[self.verb_index].info) not in self.lexicon.goals or \
                self.clock_time(i) or not self.np_starts(i + 1):
            return False
        end = self.cond_end(i + 1)
        span = [w.lower for w in words[i + 1:end]]
        if not span or any(x in FINITE or x in CONTRACTED or x in SUBJECTS or x in TIME_UNITS
                           or x in ("you", "i") or x in STATES_DONE for x in span) or \
                any(gerund_lemma(x) and (k == 0 or span[k - 1] not in DETERMINERS) for k, x in enumerate(span)):
            return False
        return not (len(span) > 1 and span[-1].endswith("s") and span[-2] not in DETERMINERS
                    and span[-2] not in POSSESSIVES)

    def timed_noun(self, i: int) -> bool:
        """Whether the sentence at ``i`` is a word that is no verb of the library and a time, and nothing
        else ("*Dinner at eight.*", "*Checkout in ten minutes!*"): a statement without a verb."""
        words = self.words
        if words[i].lower in self.lexicon.units or i + 1 >= len(words) or \
                words[i + 1].lower not in CLOCK_PREPOSITIONS:
            return False
        n = self.clock_time(i + 1) or _match_phrase(words, i + 1, TIME_WORDS)
        return bool(n) and i + 1 + n < len(words) and words[i + 1 + n].lower in END_MARKS

    def request_at(self, i: int) -> bool:
        """Whether a polite request starts at ``i``: politeness ("could you", "please", "robot", commas
        between) and then a verb."""
        words, polite = self.words, False
        while i < len(words):
            n = _match_phrase(words, i, POLITE)
            if n and words[i].lower not in ("to", "and", "then", "go", "come", "now", "first", "just"):
                polite, i = True, i + n
            elif words[i].lower == ",":
                i += 1
            else:
                break
        return polite and i < len(words) and self.verb_at(i) is not None

    def use_at(self, i: int) -> bool:
        """Whether "use X to V ..." starts at ``i`` ("use a knife to slice the apple"): X is what V
        is done with, so "use" is tagged as the preposition "with" before the clause of V."""
        if self.words[i].lower not in ("use", "using") or not self.np_starts(i + 1):
            return False
        for j in range(i + 2, min(len(self.words) - 1, i + 9)):
            low = self.words[j].lower
            if low == "to":
                return self.verb_at(j + 1) is not None
            if low in (",", ";", ".", "!", "?", "and", "then"):
                return False
        return False

    def purpose(self, i: int) -> bool:
        """Whether "to" at ``i`` starts a clause of purpose ("... to put it in the sink")."""
        if i + 1 < len(self.words) and self.using and self.verb_at(i + 1):
            return True                    # "use a knife to slice apples"
        if i + 2 >= len(self.words) or not self.out or self.out[-1].tag in ("VERB", "PREP"):
            return False
        found = self.verb_at(i + 1)
        if not found:
            return False
        after = i + 1 + found[1]
        if after >= len(self.words):
            return False
        nxt = self.words[after].lower
        return nxt in DETERMINERS or nxt in POSSESSIVES or nxt in PRONOUNS or (
            nxt in PREPOSITIONS and self.np_starts(after + _match_phrase(self.words, after, PREPOSITIONS)))

    def np_starts(self, i: int) -> bool:
        if i >= len(self.words):
            return False
        w = self.words[i]
        low = w.lower
        if low in END_MARKS or low in (",", ";", ":") or low in WH_WORDS or low in BE_WORDS:
            return False
        if low in PREPOSITIONS and low not in ("one",):
            return False
        return low not in ("and", "then", "please", "here", "there", "until", "till")

    def prev_tag(self) -> str:
        return self.out[-1].tag if self.out else ""

    # -- the pass ----------------------------------------------------------------------------
    def run(self) -> list[Word]:
        words = self.words
        i = 0
        expect_verb = True
        particles: dict[int, str] = {}
        while i < len(words):
            w = words[i]
            low = w.lower
            if i in particles:
                w.tag, w.info = "PARTICLE", particles.pop(i)
                self.out.append(w)
                i += 1
                continue
            if low in _FORMULA_FIRST:
                n = self.formula(i)
                if n and expect_verb:
                    self.out.append(_merge(words, i, n, "POLITE"))    # "When you get a chance, could you ..."
                    i += n
                    continue
                if n:
                    i += n                                             # "bring it to me when you can"
                    continue
            if expect_verb:
                if not self.out and low in ("while", "after") and self.verb_after(i + 1):
                    self.out.append(Word(w.text, w.start, w.end, "POLITE"))   # "While holding a cup, ..."
                    i += 1
                    continue
                if i + 2 < len(words) and words[i + 1].lower == "," and is_adverb(low) and \
                        (self.verb_after(i + 2) or words[i + 2].lower == "please"):
                    self.out.append(_merge(words, i, 2, "POLITE"))      # "*Quietly,* please: turn off ..."
                    i += 2
                    continue
                n = _match_phrase(words, i, POLITE)
                if n and not (n == 1 and low in ("and", "then") and not self.out and not self.verb_after(i + 1)) and (
                        low in ("to", "and", "then") or self.verb_after(i + n) or i + n >= len(words)
                        or not self.verb_at(i)):
                        self.out.append(_merge(words, i, n, "POLITE"))
                        i += n
                        continue
                if low == "do" and i + 1 < len(words) and "do" not in self.lexicon.units and \
                        verb_lemma(words[i + 1].lower) == words[i + 1].lower and self.verb_at(i + 1):
                    self.out.append(Word(w.text, w.start, w.end, "POLITE"))   # emphatic "*Do* take his coat"
                    i += 1
                    continue
                if low == "you" and i + 1 < len(words) and verb_lemma(words[i + 1].lower) == words[i + 1].lower and \
                        self.verb_at(i + 1):
                    self.out.append(Word(w.text, w.start, w.end, "POLITE"))   # "You go to the hall", "please
                    i += 1                                                     # you bring ...": still a request
                    continue
                n = self.lead_in(i)
                if n:
                    i += n
                    if self.prev_tag() == "VERB":
                        expect_verb = False
                    continue
                if _capitalised(w) and i + 1 < len(words) and words[i + 1].lower == "," and self.verb_after(i + 2):
                    self.out.append(_merge(words, i, 2, "POLITE"))      # "Robin, bring me a cup"
                    i += 2
                    continue
                if self.use_at(i):
                    self.out.append(Word(w.text, w.start, w.end, "PREP", "with"))
                    self.using = True
                    expect_verb = False
                    i += 1
                    continue
                found = self.verb_at(i)
                if found:
                    self.using = False
                    unit, n, split = found
                    self.out.append(_merge(words, i, n, "VERB", unit))
                    self.clause_verb(unit)
                    if split is not None:
                        particles[split] = unit
                    i += n
                    expect_verb = False
                    continue
                n = self.aside(i)
                if n:
                    self.out.append(_merge(words, i, n, "POLITE"))     # "Good morning! Could you ..."
                    i += n
                    continue
                expect_verb = False
                # not a verb: tag it as what it is; the grammar reports the missing verb
            if low in END_MARKS:
                rest = words[i + 1:]
                if all(r.lower in END_MARKS or r.lower == "please" for r in rest):
                    self.out.append(Word(w.text, w.start, w.end, "END"))
                    i += 1
                    continue
                self.out.append(Word(w.text, w.start, w.end, "SEP"))    # "Go to the kitchen. Find Robin."
                expect_verb = True
                i += 1
                continue
            if self.speech and self.out and self.out[-1].lower == "her" and self.prev_tag() == "POSS" and \
                    _subject_word(w) and self.told_at(i):
                self.out[-1].tag = "PRON"                    # "tell *her* we're moving": her is the person told
            if self.speech and self.prev_tag() in ("WORD", "NAME", "PRON", "LABEL") and self.told_at(i):
                end = self.speech_end(i)
                i += self._emit(i, end - i, "SAID")          # "tell him we need a cart": what is said, kept whole
                continue
            if low == "please" and not expect_verb and i + 1 < len(words) and words[i + 1].lower not in END_MARKS:
                n = self.remark_after(i + 1) if words[i + 1].lower == "," else 0
                if n:
                    i += 1 + n       # "turn the heater on please, *I'm shivering*"
                    continue
                i += 2 if i + 2 < len(words) and words[i + 1].lower == "," else 1
                continue                 # "bring me, please, a glass of juice": politeness inside the clause
            if low == "to" and self.out and (self.out[-1].lower in _INDEFINITE or len(self.out) > 1 and
                                             self.out[-1].tag == "WORD" and self.out[-2].lower in _INDEFINITE) \
                    and i + 1 < len(words) and verb_lemma(words[i + 1].lower) == words[i + 1].lower:
                end = self.relative_end(i + 1)                          # "something to drink"
                i += self._emit(i, end - i, "REL")
                continue
            if low == "to" and self.speech and self.prev_tag() in ("WORD", "NAME", "PRON") and \
                    i + 1 < len(words) and self.verb_at(i + 1):
                self.out.append(Word(w.text, w.start, w.end, "WH"))      # "tell Maria *to* come downstairs"
                i += 1
                continue
            if low == "to" and self.purpose(i):
                self.out.append(Word(w.text, w.start, w.end, "SEP"))     # "take the remote to turn on the lamp"
                expect_verb = True
                i += 1
                continue
            if low in ("until", "till") and self.until_place(i):
                self.out.append(Word(w.text, w.start, w.end, "PREP", "to"))   # "follow me until the gate"
                i += 1
                continue
            if (low in _SUB_FIRST or low in _REL_FIRST) and self.prev_tag() not in ("DET", "POSS", "NUM", "PREP"):
                n = self.subordinate(i, start=False) or self.relative(i)
                if n:
                    i += n
                    expect_verb = self.prev_tag() == "SEP"
                    continue
            if not expect_verb and self.prev_tag() in ("WORD", "NAME", "PRON", "PARTICLE", "LABEL", "HERE") and \
                    (low in BECAUSE or "'" in low):
                n = self.remark_unmarked(i)
                if n:
                    i += n                   # "give the ball to Lily cos she wants it"
                    continue
            if low in (",", ";") and not expect_verb:
                n = self.remark_after(i)
                if n:
                    i += n                   # "close the door, dear, I'm cold": address and statements dropped
                    continue
            n = _match_phrase(words, i, SEPARATOR_WORDS)
            if n:
                step = self.separator(i, n)
                if step:
                    i += step
                    expect_verb = self.prev_tag() == "SEP"
                    continue
            if low in ("please", "thanks", "thank"):
                k = i + 1
                while k < len(words) and words[k].lower in ("you", "please", "thanks"):
                    k += 1
                if all(r.lower in END_MARKS for r in words[k:]):
                    self.out.append(_merge(words, i, k - i, "POLITE"))    # "... please", "..., thank you."
                    i = k
                    continue
            i += self.tag_word(i)
            if self.out[-1].lower in ("hand", "hands") and len(self.out) > 1 and \
                    self.out[-2].tag in ("PREP", "POSS") and self.verb_after(i):
                expect_verb = True           # "with a clock in hand turn the lamp on"
        return self.out

    # -- clauses inside clauses ---------------------------------------------------------------
    def clause_verb(self, unit: str) -> None:
        """A clause's verb was tagged: remember where, and whether it says something."""
        self.speech = unit in self.lexicon.speech
        self.verb_index = len(self.out) - 1

    def has_object(self) -> bool:
        """Whether the clause has a noun phrase after its verb yet."""
        return self.verb_index >= 0 and any(t.tag in ("DET", "NUM", "POSS", "PRON", "NAME", "WORD")
                                            for t in self.out[self.verb_index + 1:])

    def _extend(self, i: int, n: int) -> None:
        """The last tagged word takes in words ``i .. i+n`` ("First" + "," before a verb)."""
        last = self.out[-1]
        self.out[-1] = Word(self.text_of(last.start, self.words[i + n - 1].end) or last.text, last.start,
                            self.words[i + n - 1].end, last.tag, last.info)

    def cond_end(self, j: int) -> int:
        """Where a clause said inside another ends: at punctuation, or at "and"/"then" before a verb."""
        words = self.words
        k = j
        while k < len(words):
            low = words[k].lower
            if low in (",", ";", ":") or low in END_MARKS:
                break
            if low in ("and", "then", "but") and self.verb_after(k + 1):
                break
            k += 1
        return k

    def speech_end(self, j: int) -> int:
        """Where reported speech that starts at ``j`` ends: at the end of the sentence, or where a
        clause of the command's own follows ("tell him that, if it rains, the party is off | and
        bring ..."); its own commas are inside it."""
        words = self.words
        k = j
        while k < len(words):
            low = words[k].lower
            if low in END_MARKS and k > j:
                break
            if low in (",", ";") and k > j and k + 1 < len(words) and \
                    words[k + 1].lower.split("'")[0] == "i" and self.statement_at(k + 1):
                break                # "tell Sam that the dog needs a walk, *I can't do it today*": the speaker's
            if low in (",", ";", ":", "and", "then", "but") and k > j:
                n = _match_phrase(words, k, SEPARATOR_WORDS) or 1
                m = k + n
                while m < len(words) and _match_phrase(words, m, SEPARATOR_WORDS):
                    m += _match_phrase(words, m, SEPARATOR_WORDS)
                if m < len(words) and (self.verb_at(m) is not None or self.verb_after(m)):
                    break
            k += 1
        while k > j and words[k - 1].lower in (",", ";", ":"):
            k -= 1                                           # a comma before the next clause is no speech
        return k

    def lead_in(self, i: int) -> int:
        """Words before a clause's verb that are no verb and no politeness phrase; returns how many
        were tagged (0: none here). A comma after politeness ("First, open ..."), a sequencing word
        after a sentence ("After that, ..."), a subordinate clause ("When you reach the kitchen, ...",
        "If the door is open, ..."), a manner adverb ("Gently place ..."), "be careful and", "start by
        opening", a polite frame ending in "you could" ("I was wondering if you could ..."), and a
        light verb with a noun that is a lexical unit ("take a look at" is "look at")."""
        words, low = self.words, self.words[i].lower
        if low not in _LEAD_FIRST and self.verb_at(i) is not None:
            return 0                                        # the verb itself (most clauses)
        prev = self.prev_tag()
        nxt = words[i + 1].lower if i + 1 < len(words) else ""
        if low in (",", ";", ":") and prev in ("POLITE", "COND", "SEP"):
            self._extend(i, 1)
            return 1
        n = _match_phrase(words, i, SEPARATOR_WORDS)
        if n and low not in ("and", "or", "while", "before", "after", "as") or n > 1 and low in ("and", "after"):
            k = i + n + (1 if i + n < len(words) and words[i + n].lower == "," else 0)
            if self.verb_after(k):
                if prev == "SEP":
                    self._extend(i, k - i)                  # "Take the cup to the sink. After that, wash it."
                    self.out[-1].info = "then"
                else:
                    self.out.append(_merge(words, i, k - i, "POLITE"))
                return k - i
        n = self.subordinate(i, start=True)
        if n:
            return n
        if low.isalpha() and low not in PARTICLES and is_adverb(low) and self.verb_after(i + 1):
            return self._emit(i, 1, "POLITE")               # "Gently place the eggs ..."
        if low == "be":                                     # "Be careful and carry ...", "be a dear and hand me ..."
            k = i + 1 + (1 if nxt in ("a", "an", "so", "extra", "very", "really") else 0)
            while k < min(len(words), i + 5) and words[k].lower not in _CLOSED and words[k].lower.isalpha() and \
                    words[k].lower not in ("and", "then"):
                k += 1
            if i + 1 < k < len(words) and words[k].lower in ("and", ",") and self.verb_after(k + 1):
                return self._emit(i, k + 1 - i, "POLITE")
        if nxt == "by" and low in ("start", "begin", "finish", "end", "continue") and i + 2 < len(words) and \
                gerund_lemma(words[i + 2].lower) and self.verb_at(i + 2):
            return self._emit(i, 2, "POLITE")               # "Start by opening the window"
        if low in ("take", "have") and nxt in ("a", "another"):
            for k in (i + 2, i + 3):                        # "take a (quick) look at"
                for unit in self.lexicon.units.get(words[k].lower if k < len(words) else "", ()):
                    if len(unit) > 1 and unit[1] in PREPOSITIONS and \
                            all(k + m < len(words) and words[k + m].lower == unit[m] for m in range(len(unit))):
                        self.out.append(_merge(words, i, k + len(unit) - i, "VERB", " ".join(unit)))
                        self.clause_verb(" ".join(unit))
                        return k + len(unit) - i
        if all(t.tag == "POLITE" for t in self.out) and self.verb_at(i) is None:
            for j in range(i, min(len(words) - 2, i + 12)):  # "It would be great if you could close ..."
                if words[j].lower in (",", ";") or words[j].lower in END_MARKS:
                    break
                if words[j].lower == "you" and words[j + 1].lower in ("could", "can", "would", "will", "might") \
                        and self.verb_after(j + 2):
                    return self._emit(i, j + 2 - i, "POLITE")
        return 0

    def _subordinate_at(self, i: int) -> tuple[str, int, str] | None:
        """A subordinate clause at ``i``: ("clause", end, subordinator) for one of the robot's own
        ("after you wash them": the verb's clause follows), ("then", end, "then") for "once you're
        done (with X)", ("cond", end, subordinator) for a condition on the world ("when the water
        boils"); None when none starts here."""
        words = self.words
        n = _match_phrase(words, i, SUBORDINATORS)
        if not n or _match_phrase(words, i, TIME_WORDS) > n or i + n >= len(words) or self.formula(i):
            return None
        sub = " ".join(w.lower for w in words[i:i + n])
        j = i + n
        subject = words[j].lower
        if subject in ("you", "you've"):           # "before *we* open": the people's doing, a condition
            k = j + 1
            if subject == "you" and k < len(words) and words[k].lower in ("have", "had"):
                k += 1
            if k < len(words) and (self.verb_at(k) is not None or self.verb_after(k)):
                return "clause", k, sub
        state = j + 1 if subject in ("you're", "we're", "you've", "we've") else \
            j + 2 if subject in ("you", "we") and j + 1 < len(words) and words[j + 1].lower in ("are", "have") \
            else -1
        if 0 <= state < len(words) and words[state].lower in STATES_DONE:
            return "then", self.cond_end(state + 1), "then"
        end = self.cond_end(j)
        return ("cond", end, sub) if end > j else None

    def subordinate(self, i: int, start: bool) -> int:
        """Tag a subordinate clause (see :meth:`_subordinate_at`); returns how many words it took.
        At a clause's start the subordinator is politeness before the verb (the grammar's ``pre``),
        inside a clause a separator; a condition is one ``COND`` word."""
        low = self.words[i].lower
        if self.verb_after(i + 1) or not start and (self.speech and low in WH_WORDS or
                                                    _match_phrase(self.words, i, SEPARATOR_WORDS) > 1):
            return 0            # "tell me when ..." is what is said; "after heating it", "when done": separators
        found = self._subordinate_at(i)
        if found is None:
            return 0
        kind, end, sub = found
        tag = "COND" if kind == "cond" else "POLITE" if start else "SEP"
        self.out.append(_merge(self.words, i, end - i, tag, sub))
        return end - i

    def relative(self, i: int) -> int:
        """A relative clause after a noun; returns how many words it took. "the cup *that is* on the
        table" and "the person *who is* waving" drop "that is" (the rest describes the noun as
        usual); any other ("the glass *that I was drinking from*", "the book *I left on the sofa*",
        "the bananas *that have gone bad*") is one ``REL`` word the noun keeps; "*where it belongs*"
        names a place (``HERE``)."""
        words, low, prev = self.words, self.words[i].lower, self.prev_tag()
        nxt = words[i + 1].lower if i + 1 < len(words) else ""
        if low == "where":
            if self.speech or prev not in ("WORD", "NAME", "PRON", "PARTICLE", "HERE") or not self.has_object():
                return 0
            end = self.cond_end(i + 1)
            return self._emit(i, end - i, "HERE", "where") if end > i + 1 else 0
        if prev not in ("WORD", "NAME") and not (prev == "PRON" and low == "who" and self.out[-1].lower in (
                "someone", "somebody", "anyone", "anybody", "everyone", "everybody", "those", "one")):
            return 0
        if self.speech:
            return 0             # "tell the man (that) ...": what is said
        if low in NOMINATIVE or low == "you" and verb_lemma(nxt):
            end = self.relative_end(i + 1)
            return self._emit(i, end - i, "REL") if end > i + 1 else 0
        if low not in RELATIVES or self.speech and low == "that" or not nxt or nxt in END_MARKS:
            return 0
        if nxt in BE_WORDS and i + 2 < len(words):
            after = words[i + 2].lower
            n = _match_phrase(words, i + 2, PREPOSITIONS)
            if n and self.np_starts(i + 2 + n):
                return self._emit(i, 2, "REL", "be")     # "the cup that is on the table": the PP describes it
            if gerund_lemma(after):
                return 2         # "the person who is waving": "the person waving"
            end = i + 2
            results: list[tuple[str, str]] = []
            while end < len(words) and (words[end].lower not in _CLOSED or words[end].lower == "not") and \
                    words[end].lower not in END_MARKS and words[end].lower not in (",", ";", ":", "then") and \
                    not (words[end].lower in ("and", "or") and (end + 1 >= len(words) or words[end + 1].lower in
                                                                _CLOSED or self.verb_after(end + 1))):
                low = words[end].lower                   # "that are black and white"
                particle = words[end + 1].lower if end + 1 < len(words) else ""
                found = self.lexicon.results.get(f"{low} {particle}") if particle in PARTICLES else None
                if found:
                    end += 1                         # "turned on", "turned off": the unit's own frame
                found = found or self.lexicon.results.get(low)
                if found:
                    results.append(found)            # "a lamp that is turned on": a result, as "a lit lamp"
                end += 1
            if i + 2 < end < len(words) and words[end].lower in PARTICLES and verb_lemma(words[end - 1].lower) and (
                    end + 1 == len(words) or words[end + 1].lower in END_MARKS or words[end + 1].lower in (",", ";")
                    or _match_phrase(words, end + 1, PREPOSITIONS)):
                end += 1                             # "the charger that's plugged in | next to my bed"
            return self._emit(i, max(end, i + 2) - i, "REL", tuple(results))
        end = self.relative_end(i + 1)
        return self._emit(i, end - i, "REL") if end > i + 1 else 0

    def relative_end(self, j: int) -> int:
        """Where a relative clause with a verb of its own ends: where a clause would end, or before a
        prepositional phrase, which the frame may take ("put the cup you used | in the sink") or give back
        to the relative clause ("bring me the book I left | on the sofa")."""
        words = self.words
        end = self.cond_end(j)
        for k in range(j + 1, end):
            n = _match_phrase(words, k, PREPOSITIONS)
            if not n or not self.np_starts(k + n) or self.verb_at(k + n) is not None:
                continue
            if k + n < len(words) and words[k + n].lower in ("it", "them", "him", "her") and k + n + 1 < end:
                continue         # "a box that has a candle in it | on the table"
            return k             # "the book I left | on the sofa": the frame decides whose phrase it is
        return end

    def separator(self, i: int, n: int) -> int:
        """Tag a separator ("and", ",", "then", ", and then") as SEP, AND_NP or nothing;
        returns how many words it took (0: not a separator here)."""
        words = self.words
        j = i + n
        while j < len(words) and _match_phrase(words, j, SEPARATOR_WORDS) and words[j].lower not in ("before",):
            j += _match_phrase(words, j, SEPARATOR_WORDS)
        phrase = " ".join(w.lower for w in words[i:i + n])
        low, span = ("and", j - i - n + 1) if phrase in AND_WORDS else (words[i].lower, j - i)
        sub = self._subordinate_at(j) if j < len(words) and words[j].lower in _SUB_FIRST and \
            not (self.speech and words[j].lower in WH_WORDS) and not self.verb_after(j + 1) else None
        if sub is not None and low in ("and", "then", ",", ";", "or", "and then"):
            kind, end = sub[0], sub[1]
            ends_clause = end < len(self.words) and self.words[end].lower == "," and self.verb_after(end + 1)
            if low in (",", ";") and kind == "cond" and not ends_clause:
                return j - i      # "turn off the stove, when the water boils": the condition of this clause
            self.out.append(_merge(words, i, j - i, "SEP"))
            return j - i          # "..., and once you're done, put them away"; "...; when it is warm, bring it"
        if self.verb_after(j):
            self.out.append(_merge(words, i, j - i, "SEP"))
            return j - i
        if phrase == "followed by":
            return 0                 # "the cup followed by the plate": no clause follows
        if j >= len(words) or words[j].lower in END_MARKS:
            if low in (",", ";", ":"):
                return j - i        # a trailing comma is nothing
            self.out.append(_merge(words, i, j - i, "SEP"))
            return j - i
        nxt = words[j].lower
        if low == "," and gerund_lemma(nxt) and self.prev_tag() in ("WORD", "NAME"):
            return 1                # "a pan, containing a knife, in the fridge"
        if low in (",", ";", ":") and (nxt in PREPOSITIONS or nxt == "please"):
            return 1                # "Put a pan with a spoon in it, in the sink"
        if low in ("then", "after that", "afterwards", "finally", "after", "before", "while", "once done",
                   "when done") or span > 1 and low != ",":
            self.out.append(_merge(words, i, j - i, "SEP"))
            return j - i
        if low in ("and", ",", "or") and self.np_starts(j) and self.prev_tag() in ("WORD", "NAME", "PRON"):
            after = words[j + 1].lower if j + 1 < len(words) else ""
            unknown_verb = (nxt not in DETERMINERS and nxt not in POSSESSIVES and nxt not in PRONOUNS
                            and not _capitalised(words[j]) and nxt not in NUMBERS
                            and (after in DETERMINERS or after in POSSESSIVES or after in ("it", "them", "me")))
            if not unknown_verb:
                self.out.append(_merge(words, i, n, "AND_NP"))
                return n
        m = _match_phrase(words, j, PREPOSITIONS) if low == "and" and n == 1 else 0
        if m and self.prev_tag() in ("WORD", "NAME", "PRON") and self.np_starts(j + m) and \
                PREPOSITIONS[" ".join(w.lower for w in words[j:j + m])] in PATH_PREPOSITIONS and \
                not any(self.verb_at(k) for k in range(j, self.cond_end(j))):
            return n                 # "down from the shelf *and* over to my chair": one path, phrases in a row
        if low == "or" and self.prev_tag() in ("WORD", "NAME", "PRON") and _match_phrase(words, j, PREPOSITIONS):
            k = j + _match_phrase(words, j, PREPOSITIONS)
            end = self.cond_end(k)
            if self.np_starts(k) and not any(self.verb_at(m) for m in range(k, end)):
                self.out.append(_merge(words, i, n, "AND_NP"))
                return n             # "on the desk or in the bedroom"
        if low in ("and", "then", ",", ";", "or"):
            self.out.append(_merge(words, i, j - i, "SEP"))
            return j - i
        return 0

    def tag_word(self, i: int) -> int:
        """Tag the word at ``i`` (not a verb, not a separator); returns how many words it took."""
        in_np = self.prev_tag() in ("DET", "NUM", "POSS", "RESULT")   # inside a noun phrase, before its head
        return self._quantity(i, in_np) or self._function_word(i, in_np) or self._open_word(i, in_np)

    def _emit(self, i: int, n: int, tag: str, info: object = None) -> int:
        word = self.words[i]
        self.out.append(Word(word.text, word.start, word.end, tag, info) if n == 1 else
                        _merge(self.words, i, n, tag, info))
        return n

    def _quantity(self, i: int, in_np: bool) -> int:
        """Numbers ("two", "a couple of", "3"), quantifiers before "of" ("both of the"), "'s"."""
        words, low, nxt = self.words, self.words[i].lower, self._next(i)
        if self.prev_tag() in ("WORD", "NAME") and self.label_at(i):
            return self._emit(i, 1, "LABEL", low)              # "room 214", "table 9": no count
        n = _match_phrase(words, i, NUMBERS)
        if n and self.prev_tag() == "PREP" and not self._noun_follows(i + n) and low not in ("one", "a", "an"):
            return self._emit(i, n, "WORD")                    # "cut it into eight": so many pieces, a noun
        if n and not in_np and (low != "one" or self.np_starts(i + 1) and nxt not in PREPOSITIONS) and \
                (n > 1 or low != "one" or self._noun_follows(i + 1)):
            return self._emit(i, n, "NUM", NUMBERS[" ".join(x.lower for x in words[i:i + n])])
        if n and in_np and low != "one" and self.prev_tag() == "DET" and self._noun_follows(i + n):
            return self._emit(i, n, "NUM", NUMBERS[" ".join(x.lower for x in words[i:i + n])])   # "the two books"
        if low.isascii() and low.isdigit():
            if self.prev_tag() == "PREP" and not self._noun_follows(i + 1):
                return self._emit(i, 1, "WORD")                # "the guests in 305": a place named by its number
            return self._emit(i, 1, "NUM", int(low))
        if low == "'s":
            last = self.out[-1] if self.out else None
            if last is not None and last.tag in ("NAME", "WORD", "PRON") and self.np_starts(i + 1) and \
                    nxt not in ("a", "an", "the"):
                self.out[-1] = Word(f"{last.text}'s", last.start, words[i].end, "POSS", last.text)
                return 1
            return self._emit(i, 1, "BE")
        if not in_np and low in QUANTIFIERS and nxt == "of" and i + 2 < len(words) and \
                (words[i + 2].lower in DETERMINERS or words[i + 2].lower in POSSESSIVES):
            number = NUMBERS.get(low)            # "both of the cups", "one of the books"
            return self._emit(i, 2, "DET" if number is None else "NUM", number)
        return 0

    def clock_time(self, i: int) -> int:
        """How many words a time said with a number take at ``i`` (0: none): "at three", "by 5 pm",
        "at half past six", "until 4 o'clock", "in ten minutes", "in ten" (a number word; "in 305"
        is a numbered place). Nothing noun-like may follow: "at three tables" counts tables."""
        words, low = self.words, self.words[i].lower
        k = i + 1
        if k < len(words) and low != "in" and words[k].lower in ("half", "quarter") and k + 1 < len(words) and \
                words[k + 1].lower in ("past", "to"):
            k += 2                                              # "at half past six"
        if k >= len(words) or not (words[k].lower in NUMBERS and words[k].lower not in VAGUE_NUMBERS
                                   or words[k].lower.isascii() and words[k].lower.isdigit()):
            return 0
        digits = words[k].lower.isdigit()
        k += 1
        if k < len(words) and words[k].lower in TIME_UNITS:
            return k + 1 - i                                    # "in ten minutes", "by 5 hours"
        if low == "in" and digits:
            return 0                                            # "the guests in 305": a place
        while k < len(words) and words[k].lower in CLOCK_WORDS:
            k += 1                                              # "at 5 pm", "at three thirty", "at 4 o'clock"
        if k < len(words) and self._noun_follows(k) and words[k].lower not in NUMBERS:
            return 0
        return k - i

    def label_at(self, i: int) -> bool:
        """Whether the number at ``i`` names a numbered thing with the noun before it ("room *214*",
        "meeting room *three*", "table *9*"): one number (digits, or a number word other than "one"),
        with no noun after it to count ("give the kids *two* apples" counts)."""
        low = self.words[i].lower
        if not (low.isascii() and low.isdigit() or low in NUMBERS and low not in VAGUE_NUMBERS):
            return False
        if i + 1 < len(self.words) and self.words[i + 1].lower in TIME_UNITS:
            return False                                        # "wait ten minutes"
        return i + 1 >= len(self.words) or not self._noun_follows(i + 1) or self.words[i + 1].lower in NUMBERS

    def _special_function_word(self, i: int) -> int:
        """Time adverbials ("right away", "for three minutes"), "one" after adjectives ("the red one")
        and "that" opening reported speech ("tell the guest *that* dinner is ready"); 0 if none."""
        words, low = self.words, self.words[i].lower
        n = _match_phrase(words, i, TIME_WORDS)
        if n and (low != "first" or self.prev_tag() not in ("VERB", "PREP")):
            return self._emit(i, n, "PARTICLE", "time")        # "put it in the fridge right away"
        if low in ("for", "every", "each") and self.prev_tag() not in ("VERB", "PREP"):
            k = i + 1                                          # "for three minutes", "every few minutes"
            while k < len(words) and (words[k].lower in TIME_MEASURE or words[k].lower in NUMBERS
                                      or words[k].lower.isdigit()):
                k += 1
            if k < len(words) and words[k].lower in TIME_UNITS:
                return self._emit(i, k + 1 - i, "PARTICLE", "time")
        if low in CLOCK_PREPOSITIONS and self.prev_tag() != "PREP":
            n = self.clock_time(i)
            if n:
                return self._emit(i, n, "PARTICLE", "time")        # "meet her at three", "in ten minutes"
        prev = self.prev_tag()
        if low in ("one", "ones") and prev in ("WORD", "RESULT"):
            k = len(self.out) - 1
            while k >= 0 and self.out[k].tag in ("WORD", "RESULT"):
                k -= 1
            if k >= 0 and self.out[k].tag in ("DET", "POSS", "NUM"):
                return self._emit(i, 1, "WORD")                  # "the red one"
        if low == "that" and self.speech and prev in ("WORD", "NAME", "PRON", "LABEL") and \
                (self.np_starts(i + 1) or self._next(i) == ","):
            self._emit(i, 1, "WH")                               # "tell the guest *that* dinner is ready":
            start = i + 1                                        # what is said is any clause, kept whole
            while start < len(words) and words[start].lower == ",":
                start += 1                                       # "tell her that, if it rains, ..."
            end = self.speech_end(start)
            return start - i + (self._emit(start, end - start, "SAID") if end > start else 0)
        return 0

    def _function_word(self, i: int, in_np: bool) -> int:
        """Prepositions, particles, "of", wh-words, "is", possessives, determiners, pronouns."""
        words, low, nxt = self.words, self.words[i].lower, self._next(i)
        if low in PARTICLES and nxt == "of" and _match_phrase(words, i, PREPOSITIONS) < 2:
            return self._emit(i, 1, "WORD")       # "the back of the toilet"
        if low == "of":
            return self._emit(i, 1, "OF")
        if in_np:
            if (low in DETERMINERS or low in POSSESSIVES) and self._noun_follows(i + 1):
                return self._emit(i, 1, "DET" if low in DETERMINERS else "POSS")
            return 0
        if low in _FUNCTION_SPECIAL:
            n = self._special_function_word(i)
            if n:
                return n
        n = _match_phrase(words, i, HERE_WORDS)
        after_be = bool(self.out) and self.out[-1].tag == "BE"  # "how many cups are there in the kitchen"
        if n and not (low == "there" and (nxt in BE_WORDS or after_be)):
            return self._emit(i, n, "HERE")
        if low == "there":
            return self._emit(i, 1, "THERE")
        n = _match_phrase(words, i, PREPOSITIONS)
        if n:
            prep = PREPOSITIONS[" ".join(x.lower for x in words[i:i + n])]
            has_object = self.np_starts(i + n) or i + n < len(words) and words[i + n].lower in ("here", "there")
            if not has_object and prep == "outside":
                return self._emit(i, n, "HERE")                  # "take the trash bag outside"
            return self._emit(i, n, "PREP" if has_object else "PARTICLE", prep)   # "pick it up", "... from"
        if low in PARTICLES:
            return self._emit(i, 1, "PARTICLE", low)
        if low in WH_WORDS and self.prev_tag() != "DET":
            return self._emit(i, 1, "WH")
        if low in BE_WORDS:
            return self._emit(i, 1, "BE")
        if low in POSSESSIVES and (low != "her" or self._noun_follows(i + 1)):
            return self._emit(i, 1, "POSS")
        if low in PARTITIVES and self.prev_tag() == "VERB" and not self._noun_follows(i + 1) and \
                nxt not in DETERMINERS and nxt not in POSSESSIVES and nxt not in NUMBERS and nxt != "of":
            return self._emit(i, 1, "PRON")                    # "pour *some* into the cup": some of it
        if low in DETERMINERS and (low not in ("that", "this", "these", "those") or self._noun_follows(i + 1)):
            return self._emit(i, 1, "DET")
        if low in PRONOUNS:
            return self._emit(i, 1, "PRON")
        return 0

    def _open_word(self, i: int, in_np: bool) -> int:
        """Participles after a noun, result words, names, and every other word (a noun or adjective)."""
        w, low, nxt, prev = self.words[i], self.words[i].lower, self._next(i), self.prev_tag()
        gerund = gerund_lemma(low)
        if gerund and prev in ("WORD", "NAME", "PRON", "BE"):
            tag = "VBG_T" if self.np_starts(i + 1) and nxt not in PARTICLES else \
                "VBG_P" if nxt in PREPOSITIONS and self.np_starts(i + 2) else "VBG_I"
            return self._emit(i, 1, tag, gerund)
        result = self.lexicon.results.get(low)
        if result and self._noun_follows(i + 1):
            return self._emit(i, 1, "RESULT", result)
        if result and nxt in PARTICLES and self._noun_follows(i + 2):
            return self._emit(i, 2, "RESULT", self.lexicon.results.get(f"{low} {nxt}", result))  # "a heated up potato"
        if result and nxt == "," and i + 2 < len(self.words) and self.words[i + 2].lower in self.lexicon.results \
                and self._noun_follows(i + 3):
            self._emit(i, 1, "RESULT", result)                  # "a cooked, rinsed egg"
            return 2
        if not in_np and low.isalpha() and is_adverb(low) and prev != "DET":
            return self._emit(i, 1, "PARTICLE")                # "gather together", "put it carefully on ..."
        if _capitalised(w) and not in_np and prev != "WORD" and low not in _CLOSED:
            if prev == "PREP" and low.endswith("s") and len(low) > 2 and self._noun_follows(i + 1) and \
                    not _capitalised(self.words[i + 1]) and not gerund_lemma(nxt):
                return self._emit(i, 1, "POSS", w.text[:-1])    # "in *Emmas* room": a possessive lacking its '
            if prev == "NAME":          # "Mary Ann": one name
                last = self.out[-1]
                self.out[-1] = Word(self.text_of(last.start, w.end), last.start, w.end, "NAME")
                return 1
            return self._emit(i, 1, "NAME")
        return self._emit(i, 1, "WORD")

    def _next(self, i: int) -> str:
        return self.words[i + 1].lower if i + 1 < len(self.words) else ""

    def _noun_follows(self, i: int) -> bool:
        """Whether an open-class word (a noun or adjective) starts at ``i``."""
        if i >= len(self.words):
            return False
        low = self.words[i].lower
        if low in _CLOSED or low in END_MARKS or low in (",", ";", ":", "and", "then", "of", "please") or \
                low in _SUB_FIRST:                              # "on pallet 6 *before* they ship"
            return low in NUMBERS and low != "one"
        return low not in PREPOSITIONS


@dataclass(frozen=True)
class Mention:
    """A noun phrase said in a statement or condition beside the command ("*my son Declan* arrives"):
    what a pronoun of the command may stand for. ``head`` is its last word (a name as written)."""

    start: int
    end: int
    head: str
    name: bool
    determined: bool
    oblique: bool = False            # the object of a preposition ("a question about *the computer*")


def mentions(text: str, start: int, end: int) -> list[Mention]:
    """The noun phrases of ``text[start:end]``, a statement or condition that is no command: a determiner, a
    possessive or a capitalised word, then open-class words; a name ends its phrase ("my friend *Ana* arrives")."""
    try:
        words = tokenize(text[start:end])
    except CommandError:
        return []
    found: list[Mention] = []
    k = 0
    while k < len(words):
        low = words[k].lower
        determined = low in DETERMINERS or low in POSSESSIVES
        if not (determined or _capitalised(words[k]) and low not in _CLOSED and low not in NOMINATIVE):
            k += 1
            continue
        first, k = k, k + 1 if determined else k
        while k < len(words) and words[k].lower.isalpha() and words[k].lower not in _CLOSED and \
                words[k].lower not in FINITE and words[k].lower not in SEPARATOR_WORDS and \
                words[k].lower not in _SUB_FIRST and not gerund_lemma(words[k].lower):
            k += 1
            if _capitalised(words[k - 1]) and not (k < len(words) and _capitalised(words[k])):
                break                                         # "my son Declan | arrives"
        if k > first + int(determined):
            head = words[k - 1]
            oblique = first > 0 and words[first - 1].lower in PREPOSITIONS
            found.append(Mention(start + words[first].start, start + head.end, head.text, _capitalised(head),
                                 determined, oblique))
        else:
            k = max(k, first + 1)
    return found


def tag(lexicon: Lexicon, text: str) -> list[Word]:
    """The tagged words of a command."""
    return Tagger(lexicon, tokenize(text), text).run()
