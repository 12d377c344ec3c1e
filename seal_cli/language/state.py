"""The tagger's state at a word, and the questions its rules ask of it.

:class:`State` holds the words of one command, the tagged words so far (``out``), and what the
clause being tagged has shown (its verb, whether it says something, whether "use X" came before);
its methods look ahead and behind without changing anything (memoising the verbs found), so the
rules of :mod:`seal_cli.language.rules` stay pure functions of it. The tagger
(:class:`seal_cli.language.lexicon.Tagger`) applies what they match.
"""

from __future__ import annotations

from collections.abc import Iterable, Mapping, Sequence
from typing import TYPE_CHECKING

from seal_cli.language.english import (
    ADDITIVES,
    AND_WORDS,
    BASE_FORM_SUBJECTS,
    BE_WORDS,
    BECAUSE,
    CLOCK_PREPOSITIONS,
    CLOCK_WORDS,
    CONTRACTED,
    CORRECTION_MARKS,
    DEPARTING,
    DETERMINERS,
    END_MARKS,
    FILLERS,
    FINITE,
    FREE_RELATIVES,
    FREQUENCY_ADVERBS,
    HERE_WORDS,
    HOLDING_VERBS,
    LET_KNOW,
    LINKING_VERBS,
    LOCATED,
    LOCATIVE,
    MODALS,
    NOMINATIVE,
    NOT_PLACES,
    NP_OPENERS,
    NUMBERS,
    OBJECT_PRONOUNS,
    OBLIGED,
    PARTICLES,
    PATH_PREPOSITIONS,
    PERCEIVING,
    PLACE_MEANS,
    POLITE,
    POLITE_FORMULAE,
    POSSESSIVES,
    PREPOSITIONS,
    PRONOUNS,
    QUANTIFIERS,
    QUESTION_WORDS,
    RELATIVES,
    RELAYING,
    REQUESTS,
    SEEN_ASKED,
    SEEN_QUESTIONS,
    SEPARATOR_WORDS,
    SEQUENCE_ADVERBS,
    STATE_ASKERS,
    STATEMENT_LINKS,
    STATES_DONE,
    SUBJECTS,
    SUBORDINATORS,
    THANKS_AHEAD,
    THIRD_PERSON_SUBJECTS,
    TIME_ASKED,
    TIME_UNITS,
    TIME_WORDS,
    TITLES,
    VAGUE_NUMBERS,
    VOCATIVES,
    WH_WORDS,
    WHERE_QUESTIONS,
    YOU_MUST,
    is_room_word,
)
from seal_cli.language.morphology import (
    gerund_lemma,
    in_dictionary,
    in_verb_tables,
    inflected,
    is_adjective,
    is_adverb,
    is_plural,
    noun_lemma,
    participles,
    parts_of_speech,
    verb_lemma,
)
from seal_cli.language.rule import Match
from seal_cli.language.tags import Tag
from seal_cli.language.tokens import CommandError, Word, capitalised

LIGHT_VERBS = frozenset(["take", "have"])
"""Light verbs said with a noun that is a lexical unit ("*have* a look for", :meth:`State.light_verb`)."""
_PUT_IN = frozenset(["in", "on", "inside"])
"""Prepositions (canonical) of where a thing is put, besides those of a path ("into", "onto")."""
_SOURCES = frozenset(["from", "out of", "off"])
"""Prepositions (canonical) of where a path starts: where a thing is taken from."""

if TYPE_CHECKING:
    from seal_cli.language.lexicon import Lexicon

__all__ = ["CLOSED", "IN_NP", "LIGHT_VERBS", "State", "longest_phrase", "match_phrase", "merge"]

# ---------------------------------------------------------------------------------------------
# Phrases of closed-class words, and the first words of what the tagger looks at specially

_PHRASES: dict[tuple[str, str], tuple[tuple[str, tuple[str, ...]], ...]] = {}
"""First two words → (phrase, its words) of each multiword phrase of the closed-class tables, longest first (so
:func:`match_phrase` stops at the first that fits)."""
_FORMULAE = POLITE_FORMULAE | frozenset(THANKS_AHEAD)
"""The politeness formulae said as a clause of their own (``State.formula``)."""
for _table in (PREPOSITIONS, POLITE, _FORMULAE, SEPARATOR_WORDS, SEQUENCE_ADVERBS, NUMBERS, HERE_WORDS,
               TIME_WORDS, SUBORDINATORS, VOCATIVES):
    for _phrase in _table:
        _parts = tuple(_phrase.split())
        _two = (_parts[0], _parts[1]) if len(_parts) > 1 else None
        if _two is not None and (_phrase, _parts) not in _PHRASES.get(_two, ()):
            _PHRASES[_two] = (*_PHRASES.get(_two, ()), (_phrase, _parts))
_PHRASES = {first: tuple(sorted(found, key=lambda item: -len(item[1]))) for first, found in _PHRASES.items()}
_PHRASE_FIRST = frozenset(first for first, _ in _PHRASES)

_SEEING_FIRST = frozenset(p.split()[0] for p in SEEN_ASKED[2])
"""First words of the verbs of a question whether a thing was seen ("have you *seen* ...", "did anyone *come*
across")."""


def first_words(phrases: Iterable[str]) -> frozenset[str]:
    """The words the phrases start with: where a rule reading them can start (its gate)."""
    return frozenset(p.split()[0] for p in phrases)


SUB_FIRST = first_words(SUBORDINATORS)
FORMULA_FIRST = first_words(_FORMULAE) | TIME_ASKED[0]
TIME_FIRST = first_words(TIME_WORDS)
SEP_FIRST = first_words(SEPARATOR_WORDS)
LEAD_FIRST = SUB_FIRST | SEP_FIRST | {",", ";", ":", "start", "begin", "finish", "end", "continue", "take", "have",
                                     "be"}
"""Words that may begin what a lead-in rule tags before a verb (besides adverbs and polite frames)."""
REL_FIRST = RELATIVES | NOMINATIVE | {"where", "you"}
INDEFINITE = frozenset(["something", "anything", "nothing", "everything", "someone", "somebody", "anyone",
                        "anybody"])
CLOSED = (NP_OPENERS | PRONOUNS | WH_WORDS | BE_WORDS | PARTICLES
          | frozenset(p for p in PREPOSITIONS if " " not in p) | frozenset(NUMBERS))
"""Every one-word closed-class word."""


def match_phrase(words: Sequence[Word], i: int, table: Iterable[str] | Mapping[str, object]) -> int:
    """How many words of a multiword (or one-word) phrase of ``table`` start at ``i`` (0: none)."""
    first = words[i].lower
    if first in _PHRASE_FIRST and i + 1 < len(words):
        left = len(words) - i
        for phrase, parts in _PHRASES.get((first, words[i + 1].lower), ()):   # longest first: the first that fits
            n = len(parts)
            if n <= left and phrase in table and all(words[i + k].lower == parts[k] for k in range(2, n)):
                return n
    return 1 if first in table else 0


_TABLES_INDEXED = 256
_INDEXED: dict[frozenset[str], dict[str, tuple[tuple[str, ...], ...]]] = {}
"""Each table of phrases :func:`longest_phrase` was asked about (a constant of English: keyed by its value),
indexed by first word, longest first."""


def longest_phrase(words: Sequence[Word], i: int, table: Iterable[str]) -> int:
    """How many words of the longest phrase of ``table`` (one word or several) start at ``i`` (0: none)."""
    if not isinstance(table, frozenset):
        table = frozenset(table)                 # a list or a dict of phrases: its phrases, as a key
    index = _INDEXED.get(table)
    if index is None:
        if len(_INDEXED) >= _TABLES_INDEXED:     # tables made afresh by a caller: the cache starts again
            _INDEXED.clear()
        found: dict[str, list[tuple[str, ...]]] = {}
        for phrase in table:
            parts = tuple(phrase.split())
            if parts:
                found.setdefault(parts[0], []).append(parts)
        index = _INDEXED[table] = {first: tuple(sorted(set(all_parts), key=len, reverse=True))
                                   for first, all_parts in found.items()}
    if i >= len(words):
        return 0
    left = len(words) - i
    for parts in index.get(words[i].lower, ()):
        n = len(parts)
        if n <= left and all(words[i + k].lower == parts[k] for k in range(1, n)):
            return n
    return 0


IN_NP = frozenset({Tag.DET, Tag.NUM, Tag.POSS, Tag.RESULT})
"""The tags after which the next word is inside a noun phrase, before its head (:meth:`State.in_np`)."""

_DISLOCATED_WORDS = 12
"""How far a phrase said first may run before its comma ("the dice on the sofa in the living room,")."""
_DASHES = frozenset(["-", "–", "—", "--"])
"""Dashes, which the tokenizer reads as ";": between a phrase said first and the command, a comma."""


def time_asked(words: Sequence[Word], i: int) -> int:
    """How many words "when you get a sec" (``english.TIME_ASKED``) takes at ``i`` (0: none)."""
    subordinators, verbs, quantity, measures = TIME_ASKED
    if i + 3 >= len(words) or words[i].lower not in subordinators or words[i + 1].lower not in ("you", "you've") or \
            words[i + 2].lower not in verbs:          # "when you've got a sec": the perfect of having
        return 0
    k = i + 3
    while k < len(words) and words[k].lower in quantity:
        k += 1
    return k + 1 - i if k < len(words) and words[k].lower in measures else 0


def merge(words: Sequence[Word], i: int, n: int, tag: str, info: object = None) -> Word:
    """Words ``i .. i+n`` as one tagged word."""
    text = "".join((" " if k and w.start > words[i + k - 1].end else "") + w.text    # spaced as the command was:
                   for k, w in enumerate(words[i:i + n]))                            # "at 5:30"
    return Word(text, words[i].start, words[i + n - 1].end, tag, info)


def awaits_name(word: Word) -> bool:
    """Whether a tagged word is a title whose name follows ("*Mr.* Hughes"): no noun phrase yet."""
    return word.text.endswith(".") and word.lower.rstrip(".") in TITLES


def _superlative(low: str) -> bool:
    """Whether ``low`` is an adjective's superlative ("biggest", "heaviest", "most", "least")."""
    return low in ("most", "least", "best", "worst") or len(low) > 4 and low.endswith("est") and is_adjective(low)


def subject_word(word: Word) -> bool:
    """Whether a word may only start a clause: a subject pronoun or its contraction ("we're", "I'll")."""
    low = word.lower
    return low in SUBJECTS and low not in OBJECT_PRONOUNS or \
        "'" in low and low.split("'")[0] in SUBJECTS and "'" + low.split("'", 1)[1] in CONTRACTED


_HELPED = frozenset(["him", "her", "them"])
"""Pronouns of the person helped in "help *her* find ..." ("help me/us" are politeness of ``POLITE``)."""


def statement_lead(word: Word, nxt: Word) -> bool:
    """Whether a word may lead a statement said beside the command: a sentence adverb ("*apparently*
    they're staying"), or "and"/"then"/"quick" before a comma, an adverb or a subject ("*and* quick, it's
    the next shot", "and then *it* goes ...")."""
    low, after = word.lower, nxt.lower
    if is_adverb(low) and low.endswith("ly"):
        return True
    return low in ("and", "then", "quick") and (after in (",", "quick", "then") or is_adverb(after) or
                                                after in SUBJECTS or subject_word(nxt))


def _infinitive(word: Word, n: int = 1) -> bool:
    """Whether a word after "to" can start a clause: written lower case (a capital there starts a name: "give the
    letter to *Drew*", "take the tea to *Will*") and a verb's base form or -ing form ("prior to *turning* on a
    lamp"), never a past form only said alone ("to *drew*", words26: "drew" was read as "draw", a second frame, the
    letter's recipient lost); a past form with its unit's particle stays a slip of the base form ("to *rinsed off*
    in the sink", ``n`` words of the unit)."""
    low = word.lower.split(" ", 1)[0]
    lemma = verb_lemma(low)
    return not capitalised(word) and (n > 1 or lemma is None or lemma == low or in_verb_tables(low) or
                                      gerund_lemma(low) is not None)    # "prior to *turning* on a lamp"


_ASKING_MODALS = frozenset(["can", "could", "would", "will"])
"""Modals that open a request put as a question ("*can you* guide her there"): before "you" and a verb of the
library, inside a statement said without punctuation, the command begins (words47)."""


def lower_case_name(words: Sequence[Word], k: int) -> bool:
    """Whether word ``k``, in lower case, is a person's name as a subject (words24; the caller says where a subject
    stands: opening a statement, or after a condition's subordinator, "when *sam* gets home"): no dictionary lists
    it, no closed class has it, and a finite verb follows ("*ben* is in the garden", "*anna* wants to go to the
    kitchen", "*noah* has to leave"). Dictionary words ("dinner is ready") and free relatives ("whoever's at the
    door", "whatever's on the table") name no one; a capital makes a name anywhere."""
    low = words[k].lower
    if not low.isalpha() or low in CLOSED or low.endswith("ever") or in_dictionary(low) or k + 1 >= len(words):
        return False
    nxt = words[k + 1].lower
    return nxt in FINITE or nxt == "'s" or inflected(nxt)


def _its_is_it_is(words: Sequence[Word], k: int) -> bool:
    """Whether "its" written without its apostrophe is "it's" ("*its* too loud", "*its* getting cold",
    "*its* a mess"): a determiner, an adverb, a participle, or an adjective that ends the phrase follow it,
    no noun ("its lid", "its red lid")."""
    nxt = words[k + 1].lower if k + 1 < len(words) else ""
    if not nxt.isalpha():
        return False
    if nxt in DETERMINERS or nxt in ("not", "been", "going", "gonna", "got") or gerund_lemma(nxt) or \
            nxt not in CLOSED and is_adverb(nxt) or nxt in PREPOSITIONS and nxt != "one" or _past_only(nxt):
        return True                          # "*its* on the chair": no noun after a possessive (words31); "*its*
        #                                      gone cold": a verb's past form that is nothing else (words36)
    after = words[k + 2].lower if k + 2 < len(words) else ""
    return is_adjective(nxt) and (not after.isalpha() or after in CLOSED or after in SEPARATOR_WORDS)


def _past_only(word: str) -> bool:
    """Whether a word is a verb's past form and nothing else in lemminflect ("gone", "melted", "finished"; not
    "broken", an adjective too, nor "left")."""
    lemma = verb_lemma(word)
    return lemma is not None and lemma != word and word in participles(lemma) and parts_of_speech(word) == {"verb"}


def subject_contracted(words: Sequence[Word], i: int) -> bool:
    """Whether a subject pronoun and a contraction written apart start at ``i`` ("it 's", "she 's", "we 're", as the
    tokenizer splits "it's"): a statement's start; "it 's" only where no noun follows, as for "its" (":func:`
    _its_is_it_is`": "heat up my coffee *it's gone cold*", words36; "take off it's lid" is the possessive typed)."""
    if i + 1 >= len(words) or words[i].lower not in SUBJECTS or words[i + 1].lower not in CONTRACTED:
        return False
    return words[i].lower != "it" or words[i + 1].lower != "'s" or _its_is_it_is(words, i + 1)


_PLACED_SUBJECTS = frozenset(["someone", "somebody", "everyone", "everybody", "nobody", "anyone", "anybody"])
"""Pronouns of people that may be said with where they are before their verb ("*someone in the kitchen* is
waving"): the phrase of place is the subject's, so the statement's verb comes after it (words30)."""


def _without_fillers(words: list[Word]) -> list[Word]:
    """The words without hesitations ("um", "uh", ...) and the comma after one ("and, *um,* put it on the
    bed"): they say nothing, so "and then, um, chill it" is "and then, chill it". A hesitation between a phrase and
    the marks of a correction and its new phrase is the pause a comma writes ("take the bins out *er* I mean the
    recycling": ", I mean the recycling"; words30)."""
    if not any(w.lower in FILLERS for w in words):
        return words
    kept: list[Word] = []
    skip_comma = False
    for at, w in enumerate(words):
        if w.lower in FILLERS:
            n = longest_phrase(words, at + 1, CORRECTION_MARKS)
            if n and kept and kept[-1].lower != "," and at + 1 + n < len(words) and \
                    words[at + 1 + n].lower in NP_OPENERS and words[at + n].lower not in ("no", "wait", "sorry"):
                #   ("um no the mug": "no" may be the phrase's determiner, as in ", no sugar")
                kept.append(Word(",", w.start, w.end))
            skip_comma = True
            continue
        if not (skip_comma and w.lower == ","):
            kept.append(w)
        skip_comma = False
    return kept


_LEANING = (DETERMINERS | POSSESSIVES | frozenset(p for p in PREPOSITIONS if " " not in p)) - {"that", "this"}
"""Words that lean on what follows (a determiner, a possessive, a one-word preposition): said twice in a row, they
are a speaker's restart, not two words of the command."""
_OPENING = DETERMINERS | POSSESSIVES
"""The last word of a restart: one that opens a noun phrase ("the the", "to the to the"); a preposition said twice
may be a particle and its preposition ("turn the lamp on *on* the desk")."""
_RUNS = (3, 2, 1)
"""How many words a restart said again may have, longest first ("go *to the to the* kitchen")."""


def _without_restarts(words: list[Word]) -> list[Word]:
    """The words without a run of leaning words said again at once ("bring me *the the* remote", "go *to the to
    the* kitchen", "put the keys *on the on the* hook"): dictated speech restarts a phrase, so the first run is
    dropped. Only runs of words that cannot end a phrase, ending in a determiner or a possessive: "that that" (a
    pronoun, then a determiner), "turn the lamp on on the desk" (a particle, then a preposition) keep both."""
    lows = [w.lower for w in words]
    opening = [k for k, low in enumerate(lows) if low in _OPENING]
    if len({lows[k] for k in opening}) == len(opening):
        return words                            # no word opening a phrase said twice: no restart
    if not any(lows[a] == lows[b] for n, a in enumerate(opening) for b in opening[n + 1:n + 1 + _RUNS[0]]
               if b - a <= _RUNS[0]):
        return words                            # no word opening a phrase said again a run's length on: no restart
    size = len(lows)
    kept: list[Word] = []
    i = 0
    while i < size:
        for n in _RUNS:
            e = i + n                           # the first run said is words[i:e], again at words[e:e + n]
            if e + n <= size and lows[e - 1] in _OPENING and lows[i:e] == lows[e:e + n] and \
                    _LEANING.issuperset(lows[i:e]):
                i = e                           # the first run said is dropped; the second is read
                break
        else:
            kept.append(words[i])
            i += 1
    return kept if len(kept) < size else words


def read_words(words: list[Word]) -> list[Word]:
    """The words as the tagger reads them: without fillers and restarts, "its" read as "it's" where a noun cannot
    follow."""
    words = _without_restarts(_without_fillers(words))
    if any(w.lower == "its" for w in words):
        words = [Word(w.text, w.start, w.end, w.tag, w.info, "it's") if w.lower == "its" and _its_is_it_is(words, k)
                 else w for k, w in enumerate(words)]      # "turn the radio off *its* too loud"
    return words

_NEEDING = frozenset(["has", "needs", "wants"])
"""After a bare subject and before "to", a need stated ("lily *has* to get to the garage")."""
_BE_STATED = frozenset(["is", "are", "was", "were", "isn't", "aren't", "wasn't", "weren't"])
"""Forms of "be" after a bare noun that make it a subject ("dinner *is* ready"): no command says "X is"."""

_UNASKED: tuple[str, int, int | None] = ("", 0, None)
"""What :meth:`State.verb_at` has not been asked yet (no unit is found so: a unit has a word)."""

_GIVEN_TO = frozenset(["me", "him", "her", "them", "us"])
"""Object pronouns that can be the person a thing is given to ("give *him* the keys and then *her* the coat")."""


_TOWARD = ("to", "into", "onto")
"""Prepositions of where a motion ends, which a phrase said first may open ("*To the exit,* please guide her")."""


class State:
    """What the tagger knows at a word of one command (see the module docstring)."""

    def __init__(self, lexicon: Lexicon, words: list[Word], text: str = "") -> None:
        self.text = text
        self.lexicon = lexicon
        self.words = read_words(words)
        self.out: list[Word] = []
        self._verbs: dict[int, tuple[str, int, int | None] | None] = {}
        self.using = False                  # after "use X": "to" starts the clause of what X is used for
        self.speech = False                 # the clause's verb says something ("tell"): a clause after it is said
        self.verb_index = -1                # where in ``out`` the clause's verb is
        self.expect_verb = True             # a clause starts here
        self.particles: dict[int, str] = {}  # word index -> the unit of a split particle to come
        self.remarks: list[tuple[int, int]] = []   # character spans of statements dropped beside the command

    def verb_at(self, i: int) -> tuple[str, int, int | None] | None:
        """The lexical unit starting at word ``i`` (memoised: the rules ask more than once)."""
        found = self._verbs.get(i, _UNASKED)
        if found is _UNASKED:
            found = self.lexicon.verb_at(self.words, i, self.clause_end(i + 1))
            found = self._verbs[i] = None if found is not None and found[1] == 1 and self.past_subject(i) else found
        return found

    def past_subject(self, i: int) -> bool:
        """Whether the word at ``i`` is a past form only (no base form, no -ing form: "drew", "rose") said before a
        finite verb ("*Drew* is in the kitchen", "*rose* wants to go to bed"): the subject of a statement, never a
        verb said of the robot (words26: they were read as "draw", "rise"; "moved is" is no English)."""
        words = self.words
        low = words[i].lower
        lemma = verb_lemma(low)
        return i + 1 < len(words) and words[i + 1].lower in FINITE and lemma is not None and lemma != low and \
            not in_verb_tables(low) and gerund_lemma(low) is None

    # -- reading the words -------------------------------------------------------------------
    def emit(self, i: int, n: int, tag: str, info: object = None) -> Match:
        """A match that tags words ``i .. i+n`` as one word."""
        word = self.words[i]
        return Match(n, (Word(word.text, word.start, word.end, tag, info) if n == 1 else
                         merge(self.words, i, n, tag, info),))

    def text_of(self, start: int, end: int) -> str:
        return self.text[start:end] if self.text else ""

    def prev_tag(self) -> str:
        return self.out[-1].tag if self.out else ""

    def in_np(self) -> bool:
        """Whether the next word is inside a noun phrase, before its head."""
        return bool(self.out) and self.out[-1].tag in IN_NP

    def next_lower(self, i: int) -> str:
        return self.words[i + 1].lower if i + 1 < len(self.words) else ""

    def extended(self, i: int, n: int) -> Word:
        """The last tagged word taking in words ``i .. i+n`` ("First" + "," before a verb)."""
        last = self.out[-1]
        return Word(self.text_of(last.start, self.words[i + n - 1].end) or last.text, last.start,
                    self.words[i + n - 1].end, last.tag, last.info)

    def clause_end(self, i: int) -> int:
        """Index of the first word at or after ``i`` that may end the clause."""
        for j in range(i, len(self.words)):
            if self.words[j].lower in (",", ";", ".", "!", "?", "then", "and"):
                return j
        return len(self.words)

    def verb_after(self, i: int) -> bool:
        """Whether a verb (a lexical unit) starts at ``i``, after any politeness words; or at ``i`` itself,
        a verb that is politeness only before another ("and *go* to the hall", not "go and get"), also after
        politeness ("please *go* with her", words28)."""
        start = i
        said = i                        # where the last politeness skipped started: maybe a verb ("go", "come")
        while i < len(self.words):
            n = match_phrase(self.words, i, POLITE)
            if n and self.words[i].lower not in ("to", "and", "then"):
                said = i
                i += n
                continue
            low = self.words[i].lower
            if start < i and low.endswith("ly") and is_adverb(low) and self.verb_at(i) is None:
                i += 1                  # "Dear, could you *possibly* close ...": an adverb after politeness (words25)
                continue
            break
        if i < len(self.words) and (self.verb_at(i) is not None or self.use_at(i) or
                                    self.words[i].lower in LIGHT_VERBS and self.light_verb(i) is not None or
                                    self.words[i].lower == "help" and self.helped_verb(i)):
            return True                 # "go and *have a look for* the sponge": a light verb (words40)
        return start < i and (start < len(self.words) and self.verb_at(start) is not None or
                              said != start and self.verb_at(said) is not None)

    def helped_verb(self, i: int) -> int:
        """Where the verb helped with starts after "help" at ``i`` (0: none): "help", the person (a pronoun, one
        name, or a person's noun the taxonomy knows, maybe after its determiner and up to two adjectives: "help *the
        old man*"), maybe "to", then a verb of the library in its base form ("help Jane find her keys", "help the
        guest to find a seat")."""
        words = self.words
        if words[i].lower != "help" or i + 2 >= len(words):
            return 0
        k = i + 1
        if words[k].lower in DETERMINERS:
            k += 1
            while k + 1 < len(words) and k < i + 4 and is_adjective(words[k].lower) and \
                    (noun_lemma(words[k].lower) or words[k].lower) not in self.lexicon.people:
                k += 1                  # "help the *old* man get to the exit" (words46)
            if k >= len(words):
                return 0
        person = words[k].lower
        if not (person in _HELPED and k == i + 1 or capitalised(words[k]) and k == i + 1 or
                (noun_lemma(person) or person) in self.lexicon.people):
            return 0
        k = self.described_at(k + 1) if person not in _HELPED else k + 1
        k += k < len(words) and words[k].lower == "to"
        if k >= len(words) or verb_lemma(words[k].lower) != words[k].lower or self.verb_at(k) is None:
            return 0
        return k

    def _name_in_past(self, i: int, end: int) -> bool:
        """Whether a lower-case name the dictionary also lists as a noun ("robin", "paris", "angel") starts a
        statement of what they did at ``i`` (words48): said bare, first, before a verb's past form that is nothing
        else ("went", "came", "walked"; maybe after "just"), and taken up after the statement by "him"/"her"/"he"/
        "she" ("robin went to the kitchen, *follow him*": an unknown verb "robin"). A thing said so ("apple sliced,
        put it away") is taken up by "it", if at all."""
        words = self.words
        first = words[i].lower
        k = i + 1 + (i + 1 < end and words[i + 1].lower == "just")
        if capitalised(words[i]) or not first.isalpha() or first in CLOSED or first in self.lexicon.units or \
                k >= end or not _past_only(words[k].lower):
            return False
        return any(w.lower in ("him", "her", "he", "she", "his") for w in words[end:])

    def described_at(self, k: int) -> int:
        """Where what describes a person named ends, from ``k`` (words48): up to two phrases of where they are or
        what they wear ("help the man *in the red shirt* go to the bathroom", "the lady *at the door* wants you to
        ..."), each a preposition, its determiner and up to three open words; ``k`` when none."""
        words = self.words
        for _ in range(2):
            if k + 2 >= len(words) or words[k].lower not in LOCATIVE and words[k].lower != "with" or \
                    words[k + 1].lower not in DETERMINERS:
                return k
            j = k + 2
            while j < min(len(words), k + 5) and words[j].lower.isalpha() and words[j].lower not in CLOSED and \
                    words[j].lower not in FINITE and not longest_phrase(words, j, RELAYING) and \
                    not (self._base_unit(j) and j > k + 2):
                j += 1
            if j == k + 2:
                return k
            k = j
        return k

    def formula(self, i: int) -> int:
        """How many words a politeness formula said as a whole clause takes at ``i`` (0: none): it
        ends the command or is followed by punctuation, "and"/"then" or more politeness."""
        words = self.words
        if words[i].lower not in FORMULA_FIRST:
            return 0
        n = match_phrase(words, i, _FORMULAE) or time_asked(words, i)
        if not n or i + n == len(words):
            return n
        nxt = words[i + n].lower
        if nxt in END_MARKS or nxt in (",", ";", ":", "and", "then"):
            return n
        m = match_phrase(words, i + n, POLITE)
        return n if m and nxt != "to" and self.verb_after(i + n) else 0

    def possessed_at(self, k: int, end: int) -> bool:
        """Whether the word at ``k``, after "'s", is what someone has ("Anna's *cup*", "the guest's *red* coat"): a
        noun or adjectives then a noun, no word of state or verb form ending the clause ("the door's *open*",
        "the dog's *barking*")."""
        words = self.words
        if k >= end:
            return False
        low = words[k].lower
        if low in DETERMINERS or low in BE_WORDS or low in PREPOSITIONS or low in FINITE or is_adverb(low) or \
                gerund_lemma(low) is not None or verb_lemma(low) not in (None, low):
            return False
        return not is_adjective(low) or k + 1 < end and self.possessed_at(k + 1, end)

    def statement_at(self, i: int) -> int:
        """Whether a statement starts at ``i`` and where its clause ends (0: none): a subject (a pronoun,
        a contraction "it's", "we're", "i'll"; or a noun phrase: "the bus", "my son Declan", "Bogdan") and
        then a finite verb ("is", "has", "can't", "keeps", "arrives on"); a command starts with a verb's
        base form instead. The clause ends at punctuation, or where the command goes on without it
        (:meth:`command_resumes`: "look for Jo, *she's by the fence* and follow her")."""
        words = self.words
        if i >= len(words):
            return 0
        end = i
        first_word = words[i].lower                           # "*I'm* thirsty can you ...": a subject and its verb
        while end < len(words) and words[end].lower not in END_MARKS and words[end].lower not in (",", ";", ":") \
                and not (end > i + 2 and self.command_resumes(end) or
                         end == i + 2 and (self.imperative_unmarked(end) or
                                           "'" in first_word and self.command_resumes(end))):
            end += 1
        first = words[i].lower
        nxt = words[i + 1].lower if i + 1 < end else ""
        if i + 1 < len(words) and statement_lead(words[i], words[i + 1]):
            k = i + 1 + (words[i + 1].lower == ",")          # "..., *apparently* they're staying", "and quick, it's"
            return self.statement_at(k) if k < len(words) and not (capitalised(words[i]) and k == i + 1) else 0
        if nxt.isascii() and nxt.isdigit() and i + 2 < end and words[i + 2].lower in FINITE and \
                first not in self.lexicon.units:
            return end                                        # "Table 4 is ready", "room 12 has no towels"
        if first.isalpha() and not capitalised(words[i]) and first not in CLOSED and first not in self.lexicon.units \
                and not first.endswith("ever") \
                and (nxt in _BE_STATED or nxt == "'s" and not self.possessed_at(i + 2, end) or
                     nxt in _NEEDING and i + 2 < end and (words[i + 2].lower == "to" or
                                                          nxt != "has" and words[i + 2].lower in NP_OPENERS)):
            return end          # "dinner's ready", "lunch is served" (not "whatever's"); "lily has to go" (words25);
            # "grace wants a drink", "dad needs his glasses": a need of a thing stated (words27)
        if not capitalised(words[i]) and lower_case_name(words, i):
            return end                                        # "noah has to get to the garage": a name (words24)
        if capitalised(words[i]) and first.isalpha() and first not in CLOSED and first not in self.lexicon.units and \
                (nxt in _BE_STATED or nxt == "'s" and not self.possessed_at(i + 2, end)):
            return end          # "Grace is in the lounge, ...", "Rose's upstairs": no command says "X is" (words49)
        if self._name_in_past(i, end):
            return end                                        # "robin went to the kitchen, follow him" (words48)
        if verb_lemma(first) == first and first not in SUBJECTS:
            return 0                                          # "Grab the cup": a command, maybe an unknown verb
        if self.wish_of_deed(i):
            return 0                                          # "..., then *I want you to* give it to me": a request
        if first in BASE_FORM_SUBJECTS and nxt.isalpha() and nxt not in PREPOSITIONS:
            return end                                        # "we open at six", "I need a hand": no command
        if first in ("you'll", "you'd", "you") and match_phrase(words, i, YOU_MUST) and \
                self.verb_after(i + match_phrase(words, i, YOU_MUST)):
            return 0                                          # "..., you'll have to find it": the robot is told
        if "'" in first and first.split("'")[0] in SUBJECTS | {"you", "who", "what", "here"} and \
                "'" + first.split("'", 1)[1] in CONTRACTED:
            return end                                        # "we're eating in ten", "i'll be right there"
        if first in _PLACED_SUBJECTS and (nxt in LOCATIVE and self.np_starts(i + 2) or gerund_lemma(nxt)):
            k = i + 2                                         # "*someone in the kitchen is* waving, greet them"
            # "*someone raising their left arm* in the office *wants* ...": described by what they do (words48)
            while k < end and words[k].lower not in FINITE and (self.verb_at(k) is None or
                                                                words[k - 1].lower in NP_OPENERS):
                k += 1                                        # "their *left* arm": a noun's word, no verb
            return end if k < end and words[k].lower in FINITE else 0
        if first in SUBJECTS or first == "you" and nxt not in ("can", "could", "will", "would", "should", "must"):
            return end if nxt in FINITE or nxt in CONTRACTED or self.finite_form(i + 1, end) or \
                first in THIRD_PERSON_SUBJECTS and inflected(nxt) else 0     # "he *likes* company", "it *smells* like"
        partitive = first in QUANTIFIERS and nxt == "of"       # "one of its wheels squeaks"
        if not (first in NP_OPENERS or capitalised(words[i]) or partitive):
            return 0
        for k in range(i + 1, end):
            if words[k - 1].lower in NP_OPENERS:
                continue                                      # "the plates": a noun
            if words[k].lower == "'s" and self.possessed_at(k + 1, end):
                continue                                      # "the knife and Anna's *cup*": whose, not "is"
            if words[k].lower in FINITE or self.finite_form(k, end) or \
                    verb_lemma(words[k].lower) in LINKING_VERBS and inflected(words[k].lower):
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
        if self.verb_index < 0 or awaits_name(self.out[-1]):
            return False                                      # "tell Mr. | Hughes that ...": the title's name
        if not self.statement_at(i) and not self.bare_subject(i):
            return False
        between = self.out[self.verb_index + 1:]
        if len(between) == 2 and between[0].tag == "PREP" and between[0].info in ("for", "to") and \
                between[1].tag in ("PRON", "NAME"):
            between = between[1:]       # "describe *for me* everything that's in the drawer": the person told
        if self.thing_told_of():
            return False                # "list *everything* that's on the counter": a thing, no person told
        return all(t.tag in ("DET", "POSS", "WORD", "NAME", "PRON", "LABEL", "RESULT") for t in between) and \
            sum(t.tag in ("PRON", "NAME") for t in between) <= 1

    def thing_told_of(self) -> bool:
        """Whether the word before is a thing a verb of saying tells of, not the person told: "list *everything*
        that's on the counter", "describe all the *drinks* that are on the stove" (a pronoun of things, or a noun of
        the library's things that names no person, right after the verb's phrase begins), so "that" starts a
        relative clause of it, not what is said."""
        if not self.speech or self.verb_index < 0 or not self.out:
            return False
        last = self.out[-1]
        if last.tag == "PRON":
            return last.lower in ("everything", "something", "anything", "all")
        lemma = noun_lemma(last.lower)
        return last.tag == "WORD" and lemma in self.lexicon.things and lemma not in self.lexicon.people and \
            all(t.tag in ("DET", "POSS", "WORD", "NUM") for t in self.out[self.verb_index + 1:])

    def bare_subject(self, i: int) -> bool:
        """Whether a statement whose subject is a bare noun starts at ``i`` after a plural person noun
        ("tell the kids *dinner is ready*") or a person noun said alone after the verb ("tell grandma *lunch
        is ready*", a noun of kin used as a name): one or two lowercase open words, then "is"/"has"/..."""
        words, out = self.words, self.out
        alone = len(out) >= 2 and out[-1].tag == "WORD" and out[-2] is out[self.verb_index] and \
            noun_lemma(out[-1].lower) in self.lexicon.people        # "tell grandma *lunch is ready*"
        if not alone and (len(out) < 2 or out[-1].tag != "WORD" or not is_plural(out[-1].lower) or
                          out[-2].tag not in ("DET", "POSS", "NUM", "WORD")):
            return False
        for k in range(i, min(i + 2, len(words) - 1)):
            low = words[k].lower
            if not low.isalpha() or capitalised(words[k]) or low in NP_OPENERS or low in PRONOUNS or \
                    low in PREPOSITIONS or low in self.lexicon.units:
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
        return bool(nxt) and (nxt in PREPOSITIONS or nxt in NP_OPENERS or nxt == "to"
                              or nxt in OBJECT_PRONOUNS or bool(gerund_lemma(nxt)))   # "a guest *left* it"

    def wish_of_deed(self, i: int) -> bool:
        """Whether a wish that the robot do something starts at ``i`` ("*I want you to* give it to me", "we need you
        to close the gate": a polite formula of ``POLITE`` that starts with its subject, then a verb of the library):
        a request, no statement, wherever a clause starts ("get the plum, and then I want you to give it to me": it
        was dropped as a remark, words46)."""
        n = match_phrase(self.words, i, POLITE)
        if n <= 2 or i + n >= len(self.words) or self.words[i].lower.split("'")[0] not in ("i", "we"):
            return False                  # "tell mum *you have to go*": what is told, no wish of the speaker
        low = self.words[i + n].lower
        return self.verb_after(i + n) or low.isalpha() and verb_lemma(low) == low and in_verb_tables(low)
        #   a verb no frame lists is refused at it, never dropped with the remark ("..., then I want you to polish it")

    def vocatives_end(self, i: int) -> int:
        """Where words of address and tag questions starting at ``i`` end, commas between ("..., *dear*",
        "..., *would you*?"); ``i`` when none."""
        words, k = self.words, i
        while k < len(words):
            n = match_phrase(words, k, VOCATIVES)
            if n:
                k += n
            elif words[k].lower == "," and k > i:
                k += 1
            else:
                break
        return k

    def goal_verb_after(self, k: int) -> bool:
        """Whether the first verb of the library after ``k`` (politeness before it skipped) has a goal ("to the
        exit, please *guide* her"; "to the lamp, *turn on* the light" has none: the phrase is no goal of it)."""
        for m in range(k, min(k + 8, len(self.words))):
            found = self.verb_at(m)
            if found is not None:
                return found[0] in self.lexicon.goals
            if self.words[m].lower in END_MARKS:
                return False
        return False

    def command_resumes(self, m: int) -> bool:
        """Whether the command goes on at ``m``, inside a statement said without punctuation (words33): "and" or
        "then" and a verb of the library in its base form ("..., he's near the fence *and follow* him"), or such a
        verb right after "there"/"here" and before its object ("there's someone waving there *greet* them"). A
        statement's own verbs are finite ("she *wants* it", "they *can* find it"): no base form of a unit after
        "and" in a statement said to the robot but the robot's next command."""
        words = self.words
        low = words[m].lower
        if low in ("and", "then"):
            k = m + 1 + (m + 1 < len(words) and words[m + 1].lower == "then")
            return k < len(words) and self._base_unit(k)
        if low in _ASKING_MODALS and m + 2 < len(words) and words[m + 1].lower == "you" and self._base_unit(m + 2):
            return True                          # "robin is at the sofa *can you* guide her there" (words47)
        return low not in CLOSED and words[m - 1].lower in ("there", "here") and self._base_unit(m) and \
            self.np_starts(m + 1) or self.imperative_unmarked(m)

    def imperative_unmarked(self, m: int) -> bool:
        """Whether a command said without a mark starts at ``m``, right after a statement that is whole (words48):
        "angel is thirsty *bring* him a drink", "robin is in the kitchen *bring* him a coke", "the door is open
        *close* it", "I'm thirsty *please bring* me some water". The statement has a finite verb of its own (or a
        subject contracted with one: "I'm"); it ends in an open word (an adjective, a noun, a participle: never "to",
        "can" or "the"); the verb at ``m`` (or after "please") is a verb of the library in its base form, and its
        object, a pronoun or a determiner, follows. A noun the verb could be ("by the *light* switch") has no object
        after it."""
        words = self.words
        k = m + (words[m].lower == "please")
        if k + 1 >= len(words) or not self._base_unit(k) or not (
                words[k + 1].lower in OBJECT_PRONOUNS or words[k + 1].lower in DETERMINERS or
                words[k + 1].lower in POSSESSIVES):
            return False
        before = words[m - 1].lower if m > 0 else ""
        if not before.isalpha() or before in CLOSED or before in FINITE or self._base_unit(m - 1) and \
                not is_adjective(before):
            return False                         # "... *go bring* him a coke": the command starts at "go"
        for j in range(m - 2, -1, -1):
            low = words[j].lower
            if low in END_MARKS or low in (",", ";", "and", "then"):
                return False
            if low in FINITE or verb_lemma(low) in LINKING_VERBS and inflected(low) or \
                    "'" in low and "'" + low.split("'", 1)[1] in CONTRACTED:
                return j > 0 or "'" in low
        return False

    def _base_unit(self, k: int) -> bool:
        """Whether a verb of the library starts at ``k`` in its base form."""
        found = self.verb_at(k)
        return found is not None and verb_lemma(self.words[k].lower) == self.words[k].lower

    def remark_unmarked(self, i: int) -> tuple[int, tuple[tuple[int, int], ...]]:
        """A statement after the request with no comma before it, started by "because"/"cos"/... or a subject
        contraction ("give the ball to Lily *cos she wants it*", "turn the radio off *it's too loud*"): how
        many words to drop (0: none). A bare "she"/"I" after a noun may start a relative clause ("the book *I
        left* on the sofa"), so only these."""
        low = self.words[i].lower
        if low not in BECAUSE and not ("'" in low and low.split("'")[0] in SUBJECTS and
                                        "'" + low.split("'", 1)[1] in CONTRACTED) and \
                not subject_contracted(self.words, i) and \
                not (low == "so" and i + 1 < len(self.words) and (self.words[i + 1].lower in SUBJECTS | {"that"} or
                                                                  self.words[i + 1].lower in NP_OPENERS)):
            return 0, ()                 # "stir the porridge *so it doesn't burn*": a purpose, said beside (words31);
            #                              "close the gate *so the dog can't get out*": its subject a noun phrase
        n, spans = self.remark_after(i - 1)
        return (n - 1, spans) if n else (0, ())

    def remark_after(self, i: int) -> tuple[int, tuple[tuple[int, int], ...]]:
        """After a comma that ends a request: words of address, tag questions and statements up to the end
        of the sentence ("..., *dear*? ...", "..., *she's been waiting a while*.", "..., *we're eating in
        ten*"), also after "or", "because", "so" ("..., *or it will melt*"); how many words to drop (0: none).
        Only when nothing else follows in the sentence, or a clause after a comma ("find Jane, *she's in the
        bedroom*, and tell her ..."). Returns the count and the spans dropped."""
        words = self.words
        k, spans = i + 1, []
        while True:
            k = self.vocatives_end(k)
            link = 1 if k < len(words) and words[k].lower in STATEMENT_LINKS and k + 1 < len(words) else 0
            if link and words[k].lower == "so" and words[k + 1].lower == "that" and k + 2 < len(words):
                link = 2                 # "stir the porridge *so that it doesn't stick*": a purpose (words32)
            end = self.statement_at(k + link)
            purpose = link == 2 or link == 1 and words[k].lower == "so" and words[k + 1].lower in NP_OPENERS
            if not end and purpose and self.cond_end(k + link) > k + link + 1 and \
                    words[k + link].lower not in ("you", "we"):
                end = self.cond_end(k + link)    # "so that the room cools down", "so the cat can't get out": a
                #     clause, not the robot's step ("so that you can give them to Alex" is one: its own clause)
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
        if spans and k < len(words) and words[k - 1].lower in (",", ";") and \
                (words[k].lower in ("and", "then") and self.verb_after(k + 1) or self.verb_after(k)):
            return k - 1 - i, tuple(spans)  # "find Jane, *she's in the bedroom*, and tell her ...": the clause goes on
        if spans and k < len(words) and self.command_resumes(k):
            return k - i, tuple(spans)      # "look for Jo *she's by the fence* and follow her" (words33)
        if k < len(words) and words[k].lower not in END_MARKS or k == i + 1:
            return 0, ()
        return k - i, tuple(spans)

    def _place_said_first(self, i: int) -> bool:
        """Whether a phrase of place ("from", "to", or a preposition of where, and a noun phrase with no verb in it)
        starts at ``i`` and a comma ends it before a clause: a phrase said first ("*From the bookshelf,* could you get
        me the red book?", "*To the exit,* please guide her": words33), never a remark beside the command (its place
        was lost)."""
        words = self.words
        n = match_phrase(words, i, PREPOSITIONS)
        if not n or PREPOSITIONS[" ".join(w.lower for w in words[i:i + n])] not in (*LOCATIVE, "from", *_TOWARD) or \
                not self.np_starts(i + n):
            return False
        for k in range(i + n, len(words)):
            low = words[k].lower
            if low == ",":                               # its last word a place the taxonomy knows: no "meantime"
                toward = PREPOSITIONS[" ".join(w.lower for w in words[i:i + n])] in _TOWARD and \
                    self.goal_verb_after(k + 1)        # a goal: any place, before a verb that has one
                return k > i + n and (toward or noun_lemma(words[k - 1].lower) in self.lexicon.things or is_room_word(
                    [w.lower for w in words[i + n:k] if w.lower not in NP_OPENERS])) and self.verb_after(k + 1)
                #   or a room's name ("*In the bedroom,* could you look for ...", words28)
            if low in END_MARKS or low in (";", "and", "then") or low in TIME_WORDS or \
                    self.verb_at(k) is not None and words[k - 1].lower not in NP_OPENERS:
                return False
        return False

    def _there_after_place(self, i: int) -> int:
        """Where "there is/'s/are" starts right after a phrase of place at ``i`` ("*on the sofa* there's a blanket",
        "in the kitchen there are two cups"), no comma or verb between (0: none)."""
        words = self.words
        n = match_phrase(words, i, PREPOSITIONS)
        if not n or PREPOSITIONS[" ".join(w.lower for w in words[i:i + n])] not in LOCATIVE or \
                not self.np_starts(i + n):
            return 0
        for k in range(i + n + 1, len(words) - 1):
            low = words[k].lower
            if low == "there" and (words[k + 1].lower in BE_WORDS or words[k + 1].lower in MODALS and
                                   k + 2 < len(words) and words[k + 2].lower == "be"):
                return k                          # "in the kitchen there *should be* someone" (words46)
            if not low.isalpha() or low in END_MARKS or self.verb_at(k) is not None and \
                    words[k - 1].lower not in NP_OPENERS:
                return 0                          # "in the *study* there are three mugs": a noun (words26)
        return 0

    def aside(self, i: int) -> Match | None:
        """A sentence said beside the command, with no verb of the library, at the start of a sentence
        ("*Good morning!* Could you ...", "*Priya needs her laptop,* could you bring it to her?"): how many
        words it takes, with its end mark (0: none). A greeting or a statement asks nothing of the
        robot when another sentence holds the command; before a comma, only when a polite request
        follows ("..., could you", "..., please"). Only a verb's base form makes a command: "my
        brother is *freezing*" states. The match tags it as politeness and keeps it as a remark."""
        words = self.words
        k = len(self.out) - 1
        while k >= 0 and self.out[k].tag == "POLITE":
            k -= 1                                       # "... Sorry, *gross*": interjections start it
        if k >= 0 and not (self.out[k].tag == "SEP" and self.out[k].lower in END_MARKS):
            return None                                  # inside a sentence
        there = self._there_after_place(i)
        if there:
            stated = self.statement_at(there)
            if stated and stated < len(words) and words[stated].lower in (",", ";") and self.verb_after(stated + 1):
                return self._aside(i, stated + 1 - i, (words[i].start, words[stated - 1].end))
                # "on the sofa there's a blanket, bring it to me": the place said first is the statement's (words24)
        if self._place_said_first(i):
            return None                                  # "from the fridge, can you grab me a soda": where, said first
        stated = self.statement_at(i)
        if stated and stated < len(words) and words[stated].lower in (",", ";") and self._command_follows(stated + 1):
            but = stated + 1 < len(words) and words[stated + 1].lower == "but"
            return self._aside(i, stated + 1 + but - i, (words[i].start, words[stated - 1].end))
        if stated and stated < len(words) and words[stated].lower not in ("and", "then") and \
                self.command_resumes(stated):
            return self._aside(i, stated - i, (words[i].start, words[stated - 1].end))
            # "robin is at the sofa *can you* guide her there": the command said on without a mark (words47)
            # "Bogdan has a question; answer it for him"; "she needs her pills, they're upstairs, fetch them"
        seen = self._seen_question(i)
        if seen:
            return self._aside(i, seen - i, (words[i].start, words[seen - 1].end))
            # "see the man by the window? greet him": what is seen is what "him" stands for (words24)
        said = any(t.tag == "VERB" for t in self.out)
        alone = i + 1 == len(words) or words[i + 1].lower in END_MARKS      # "... *Gross.*": an adjective alone
        if verb_lemma(words[i].lower) == words[i].lower and not stated and not self.timed_noun(i) and \
                not (said and alone and is_adjective(words[i].lower)):
            return None                                  # "Grab the cup.": a verb the library lacks, an error
        end, comma = i, -1
        while end < len(words) and words[end].lower not in END_MARKS:
            if not stated and (words[end].lower in self.lexicon.units and self.verb_at(end) is not None
                               or self.use_at(end)):
                return self._aside(i, comma + 1 - i) if comma > i and self.request_at(comma + 1) else None
            if words[end].lower in (",", ";") and comma < 0:
                comma = end
            end += 1
        if end >= len(words):
            if not said or stated and any(self.verb_at(k) is not None and words[k - 1].lower not in NP_OPENERS
                                          and not self._state_in_progress(i, k) for k in range(i + 1, end)):
                return None                              # a statement with a verb of the library in it: said
            return self._aside(i, end - i, (words[i].start, words[-1].end))
            # "pour it into the cup... *the blue one*": a fragment after; "follow Adel? *He is at the entrance*"
        while end + 1 < len(words) and words[end + 1].lower in END_MARKS:
            end += 1
        if not any(t.tag == "VERB" for t in self.out) and \
                not any(self.verb_at(k) is not None or self.asks_at(k) for k in range(end + 1, len(words))):
            return None                                  # no sentence holds a command: the error says so
        return self._aside(i, end + 1 - i, (words[i].start, words[end].end))

    def _state_in_progress(self, i: int, k: int) -> bool:
        """Whether the verb at ``k``, in a statement starting at ``i``, says what someone other than the robot is
        doing right now (words42): its "-ing" form right after a form of "be", and the subject not "you" ("take
        Robin to the office. *she's waiting* at the entrance", "*Anna is waiting* in the hall": where she is, no
        task). "you're waiting ..." may tell the robot, and a base form anywhere ("Anna is waiting for you to bring
        her a cup") is a task: both stay said."""
        words = self.words
        low = words[k].lower
        return k > i and low.endswith("ing") and (words[k - 1].lower in BE_WORDS or
                                                     words[k - 1].lower.endswith(("'re", "'m", "'s"))) and \
            not any(w.lower.startswith("you") for w in words[i:k]) and \
            not any(self.verb_at(j) is not None and verb_lemma(words[j].lower) == words[j].lower
                    for j in range(k + 1, len(words)) if words[j].lower not in END_MARKS)

    def dislocated(self, i: int) -> Match | None:
        """A noun phrase said first, then a comma and a command that takes it up by a pronoun ("*The sponge
        on the cabinet,* bring it to me", "*That dice on the sofa,* could you bring it to me?"): the phrase is
        a remark, which the pronoun names (:meth:`~seal_cli.language.reference.Reference.mentioned`)."""
        words = self.words
        free = words[i].lower in FREE_RELATIVES               # "*whoever's at the door*, greet them"
        bare = self.bare_thing(i)                             # "*door* - open it" (words26)
        if self.out and not (self.out[-1].tag == "SEP" and self.out[-1].lower in END_MARKS or
                             all(t.tag == "POLITE" for t in self.out)) or \
                words[i].lower not in NP_OPENERS and not free and not bare:   # "ugh, *my jeans*, where are they"
            return None
        comma = -1
        for k in range(i + 1, min(len(words), i + _DISLOCATED_WORDS)):
            low = words[k].lower
            if low == "," or low == ";" and self.text_of(words[k].start, words[k].end).strip() in _DASHES:
                comma = k                                # "the man by the door *-* greet him": a dash as a comma
                break
            if low in END_MARKS or low in (";", ":", "and", "then"):
                return None
            if self.verb_at(k) is not None and words[k - 1].lower not in NP_OPENERS and not \
                    (free and k == i + 1 and words[k].lower in BE_WORDS) and \
                    not (k > i + 1 and gerund_lemma(low)):   # "the man *waiting* at the door, greet him"
                return None                              # a clause, not a phrase
        if comma < 0 or not (self.verb_after(comma + 1) or self._asked_of_it(comma + 1)):
            return None
        if self._asked_of_it(comma + 1):
            return self._aside(i, comma + 1 - i, (words[i].start, words[comma - 1].end))
        for k in range(comma + 1, len(words)):
            if words[k].lower in END_MARKS:
                break
            if words[k].lower in (("them", "him", "her") if free else ("it", "them") if bare else
                                  ("it", "them", "him", "her", "one")):
                return self._aside(i, comma + 1 - i, (words[i].start, words[comma - 1].end))
        return None

    def bare_thing(self, i: int) -> bool:
        """Whether the word at ``i`` opens a phrase of a thing said bare, telegraphically, before a comma or a dash
        ("*door* - open it", "*lunchboxes* - bring them"): a lower-case noun (lemminflect lists it as one), no
        verb of the library there, no closed-class word, no person of the taxonomy (a person said first and a
        comma is the one addressed: "mum, bring her the cup"); only "it"/"them" take it up."""
        words = self.words
        low = words[i].lower
        return low.isalpha() and not capitalised(words[i]) and low not in CLOSED and self.verb_at(i) is None and \
            "noun" in parts_of_speech(low) and (noun_lemma(low) or low) not in self.lexicon.people and \
            low not in self.lexicon.people

    def _command_follows(self, k: int, said: int = 0) -> bool:
        """Whether a command follows a statement at ``k``: a verb (after politeness), a request said without one
        ("could I have ...", "where is ..."), maybe after "but" ("I'm sorry to trouble you, *but* could I have a
        towel?"), or another statement and then one ("she needs her tablets, *they're on the counter*, fetch
        them": words26; up to three statements)."""
        words = self.words
        if k < len(words) and words[k].lower == "but":
            k += 1
        if k >= len(words):
            return False
        if self.verb_after(k) or self.asks_at(k):
            return True
        stated = self.statement_at(k) if said < 3 else 0
        return bool(stated) and stated < len(words) and words[stated].lower in (",", ";") and \
            self._command_follows(stated + 1, said + 1)

    def _asked_of_it(self, k: int) -> bool:
        """Whether a question of being asked of "it"/"they" starts at ``k`` ("the lamp by the bed, *is it* on?",
        "my jeans, *where are they*?", "the lamp, *it is* on or off?"): the phrase said first is what the pronoun
        names (words26), as before a command."""
        words = self.words
        be, it = ("is", "are", "isn't", "aren't"), ("it", "they")
        if k + 2 < len(words) and words[k].lower == "where":
            k += 1                                # "my jeans, *where are they*?"
        elif k + 2 < len(words) and words[k].lower in it and words[k + 1].lower in be:
            return any(w.lower == "?" for w in words[k + 2:])    # "the lamp, *it is* on or off?"
        return k + 1 < len(words) and words[k].lower in be and words[k + 1].lower in it

    def _seen_question(self, i: int) -> int:
        """Where a question of perception at ``i`` ends, its "?" included (0: none): "see" / "do you see" /
        "can you spot" (``SEEN_QUESTIONS``), a noun phrase, and "?", with a command in the next sentence ("*see the
        person by the door?* follow them"). Without a command after it, it is no remark ("see the cup?" stays an
        error naming "see")."""
        words = self.words
        n = longest_phrase(words, i, SEEN_QUESTIONS)
        if not n or not self.np_starts(i + n):
            return 0
        end = next((k for k in range(i + n, len(words)) if words[k].lower in END_MARKS), len(words))
        if end >= len(words) or words[end].lower != "?" or \
                not any(self.verb_at(k) is not None for k in range(end + 1, len(words))):
            return 0
        return end + 1

    def _aside(self, i: int, n: int, *remarks: tuple[int, int]) -> Match:
        return Match(n, (merge(self.words, i, n, Tag.POLITE),), remarks=remarks)

    def asks_at(self, k: int) -> bool:
        """Whether a request said without an imperative may start at ``k`` (a bare question, "where is",
        "I'd like"; :mod:`seal_cli.language.rules.requests` reads them)."""
        words = self.words
        if words[k].lower in QUESTION_WORDS:
            return True
        auxiliaries, subjects, seeing = SEEN_ASKED
        if words[k].lower in auxiliaries and k + 2 < len(words) and words[k + 1].lower in subjects and \
                verb_lemma(words[k + 2].lower) in _SEEING_FIRST:
            return True                 # "I'm looking for my phone, *have you seen* it anywhere?" (words46)
        return any(all(k + m < len(words) and words[k + m].lower == part for m, part in enumerate(phrase.split()))
                   for phrase in (*WHERE_QUESTIONS, *REQUESTS) if phrase.split()[0] == words[k].lower)

    def until_place(self, i: int, at: int = 0) -> bool:
        """Whether "until"/"till" at ``i`` says how far a motion goes: after a verb of a frame with a goal,
        a noun phrase (at ``at``, the next word if 0) with no verb and no time ("walk with her *until the
        corner*"); "until the bus stops" (a noun then an -s form) stays a condition."""
        words = self.words
        at = at or i + 1
        if self.verb_index < 0 or str(self.out[self.verb_index].info) not in self.lexicon.goals or \
                self.clock_time(i) or not self.np_starts(at):
            return False
        end = self.cond_end(at)
        span = [w.lower for w in words[at:end]]
        if not span or any(x in FINITE or x in CONTRACTED or x in SUBJECTS or x in TIME_UNITS
                           or x in ("you", "i") or x in STATES_DONE for x in span) or \
                any(gerund_lemma(x) and (k == 0 or span[k - 1] not in DETERMINERS) for k, x in enumerate(span)):
            return False
        return not (len(span) > 1 and span[-1].endswith("s") and span[-2] not in NP_OPENERS)

    def until_arrival(self, i: int) -> int:
        """How many words "until you reach", "till we get to", "until you arrive at" take at ``i`` when what
        follows is a place the motion goes to ("follow him *until you reach* the patio"): the subject, a verb
        of a frame with a goal and its preposition say how far, as "until the gate" does (0: none)."""
        words = self.words
        k = i + 1
        if k >= len(words) or words[k].lower not in ("you", "we"):
            return 0
        found = self.verb_at(k + 1) if k + 1 < len(words) else None
        if found is None or found[2] is not None or found[0] not in self.lexicon.goals:
            return 0
        at = k + 1 + found[1]
        if at < len(words) and words[at].lower in PREPOSITIONS and words[at].lower not in NOT_PLACES:
            at += 1
        return at - i if self.until_place(i, at) else 0

    def timed_noun(self, i: int) -> bool:
        """Whether the sentence at ``i`` is a word that is no verb of the library and a time, and nothing
        else ("*Dinner at eight.*", "*Checkout in ten minutes!*"): a statement without a verb."""
        words = self.words
        if words[i].lower in self.lexicon.units or i + 1 >= len(words) or \
                words[i + 1].lower not in CLOCK_PREPOSITIONS:
            return False
        n = self.clock_time(i + 1) or match_phrase(words, i + 1, TIME_WORDS)
        return bool(n) and i + 1 + n < len(words) and words[i + 1 + n].lower in END_MARKS

    def request_at(self, i: int) -> bool:
        """Whether a polite request starts at ``i``: politeness ("could you", "please", "robot", commas
        between) and then a verb."""
        words, polite = self.words, False
        while i < len(words):
            n = match_phrase(words, i, POLITE)
            if n and words[i].lower not in ("to", "and", "then", "go", "come", "now", "first", "just"):
                polite, i = True, i + n
            elif words[i].lower == ",":
                i += 1
            else:
                break
        return polite and i < len(words) and self.verb_at(i) is not None

    def light_verb(self, i: int) -> tuple[int, str] | None:
        """A light verb and a noun that is a lexical unit at ``i`` ("take a (quick) look at", "have a look *in the
        fridge*"): how many words it takes and the unit it says; None when there is none."""
        words = self.words
        if self.next_lower(i) not in ("a", "another"):
            return None
        for k in (i + 2, i + 3):                                      # "take a (quick) look at"
            for unit in self.lexicon.units.get(words[k].lower if k < len(words) else "", ()):
                if len(unit) > 1 and unit[1] in PREPOSITIONS and \
                        all(k + m < len(words) and words[k + m].lower == unit[m] for m in range(len(unit))):
                    return k + len(unit) - i, " ".join(unit)
        for k in (i + 2, i + 3):           # "have a look *in the fridge* for the butter", "take a walk around it"
            noun = words[k].lower if k + 1 < len(words) else ""
            if (noun,) in self.lexicon.units.get(noun, ()) and noun not in self.lexicon.things and \
                    match_phrase(words, k + 1, LOCATIVE) > 0:
                return k + 1 - i, noun
        return None

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
        """Whether "to" at ``i`` starts a clause of purpose ("... to put it in the sink"). With its object
        unsaid ("put it in the fridge *to chill*", "pick up a bowl *to hold up* over the bin") or a bare
        one ("pick up the knife *to slice bread*") only when the verb names no thing the library knows
        ("move it to *microwave*" is a place)."""
        words = self.words
        if i + 1 < len(words) and self.using and self.verb_at(i + 1):
            return True                    # "use a knife to slice apples"
        if i + 1 >= len(words) or not self.out or self.out[-1].tag in ("VERB", "PREP"):
            return False
        asker = match_phrase(words, i + 1, STATE_ASKERS)
        if asker and i + 1 + asker < len(words) and words[i + 1 + asker].lower in ("if", "whether"):
            return True                    # "go to the bedroom to see if the lamp is on": asked there
        found = self.verb_at(i + 1)
        if not found or not _infinitive(words[i + 1], found[1]):
            return False                   # "give the letter to *Drew*": a past form or a capital, no infinitive
        after = i + 1 + found[1]
        thing = words[i + 1].lower in self.lexicon.things or self.out[-1].tag not in ("WORD", "NAME", "PRON",
                                                                                       "PARTICLE", "LABEL")
        if after >= len(words) or words[after].lower in END_MARKS or words[after].lower in (",", ";", "and", "then"):
            return not thing and found[2] is None
        nxt = words[after].lower
        return nxt in NP_OPENERS or nxt in PRONOUNS or capitalised(words[after]) or (
            nxt in PREPOSITIONS and self.np_starts(after + match_phrase(words, after, PREPOSITIONS))) or \
            not thing and (nxt in PARTICLES or self.noun_follows(after) and nxt not in self.lexicon.units)

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

    def has_object(self) -> bool:
        """Whether the clause has a noun phrase after its verb yet."""
        return self.verb_index >= 0 and any(t.tag in ("DET", "NUM", "POSS", "PRON", "NAME", "WORD")
                                            for t in self.out[self.verb_index + 1:])

    def cond_end(self, j: int) -> int:
        """Where a clause said inside another ends: at punctuation, or at "and"/"then" before a verb."""
        words = self.words
        k = j
        while k < len(words):
            low = words[k].lower
            if low in (":", ".") and k >= 2 and words[k - 2].lower in CLOCK_PREPOSITIONS and self.minutes_written_on(k):
                k += 2                           # "wait until 5:30": the minutes of a time, not an end (words32)
                continue
            if low in (",", ";", ":") or low in END_MARKS:
                break
            if low in ("and", "then", "but") and self.verb_after(k + 1):
                break
            k += 1
        return k

    def minutes_written_on(self, k: int) -> bool:
        """Whether the ":" or "." at ``k`` joins a time's hours and minutes, written together ("5:30", "17.45"); a
        time no clock shows is refused here (:meth:`_check_clock`)."""
        words = self.words
        if not (0 < k < len(words) - 1 and words[k - 1].lower.isascii() and words[k - 1].lower.isdigit() and
                len(words[k + 1].lower) == 2 and words[k + 1].lower.isascii() and words[k + 1].lower.isdigit() and
                words[k - 1].end == words[k].start and words[k].end == words[k + 1].start):
            return False
        self._check_clock(words[k - 1], words[k + 1])
        return True

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
                n = match_phrase(words, k, SEPARATOR_WORDS) or 1
                m = k + n
                while m < len(words) and match_phrase(words, m, SEPARATOR_WORDS):
                    m += match_phrase(words, m, SEPARATOR_WORDS)
                if m < len(words) and (self.verb_at(m) is not None or self.verb_after(m) or self._let_know(m)):
                    break
            k += 1
        while k > j and words[k - 1].lower in (",", ";", ":"):
            k -= 1                                           # a comma before the next clause is no speech
        return self._thanked_after(j, k)

    def _thanked_after(self, j: int, k: int) -> int:
        """Where speech from ``j`` to ``k`` ends once ", please" / ", thanks" / ", thank you" closing it is left
        out: after its comma it is the speaker's politeness to the robot ("tell Priya the bus is here*, please*",
        "..., please, and bring my coat"), not part of what to tell. Without the comma it stays said ("tell Jo I
        said thanks")."""
        words = self.words
        m = k
        while m > j and words[m - 1].lower in ("please", "thanks", "thank", "you"):
            m -= 1
        if m == k or m - 1 <= j or words[m - 1].lower != "," or words[m].lower == "you" or \
                words[k - 1].lower == "thank":
            return k
        return m - 1

    def _let_know(self, m: int) -> bool:
        """Whether "let X know" starts at ``m`` ("... *and let me know*", "and let the guests know"): a clause of
        telling, which no verb of the library starts (words33)."""
        words = self.words
        return words[m].lower == LET_KNOW[0] and \
            any(words[k].lower == LET_KNOW[1] for k in range(m + 2, min(m + 5, len(words))))

    def _subordinate_at(self, i: int) -> tuple[str, int, str] | None:
        """A subordinate clause at ``i``: ("clause", end, subordinator) for one of the robot's own
        ("after you wash them": the verb's clause follows), ("then", end, "then") for "once you're
        done (with X)", ("cond", end, subordinator) for a condition on the world ("when the water
        boils"); None when none starts here."""
        words = self.words
        n = match_phrase(words, i, SUBORDINATORS)
        if not n or match_phrase(words, i, TIME_WORDS) > n or i + n >= len(words) or self.formula(i):
            return None
        sub = " ".join(w.lower for w in words[i:i + n])
        j = i + n
        subject = words[j].lower
        if subject in ("there", "here") and self._clause_follows(j + 1):
            return "then", j + 1, "then"            # "go to the kitchen and *once there* find a cup"
        if subject in ("you", "you've"):           # "before *we* open": the people's doing, a condition
            k = j + 1
            if subject == "you" and k < len(words) and words[k].lower in ("have", "had"):
                k += 1
            left = self._departure_end(k)
            if left and self._leaving(k):
                return "cond", left, sub            # "before you leave, turn off the stove": leaving is no arriving
            arrived = self._arrival_end(k)
            if arrived:
                return "then", arrived, "then"      # "when you get there", "once you arrive,": arrived where we went
            if left:
                return "cond", left, sub            # "turn off the stove *before you leave*": when, no frame
            if sub in ("if", "in case") and k < len(words) and match_phrase(words, k, PERCEIVING) and \
                    self.cond_end(k) > k + 1:               # ("if you" said last: no word after it, hypothesis)
                return "cond", self.cond_end(k), sub    # "if you spot my wallet, ...": whether it is seen, no search
            if k < len(words) and (self.verb_at(k) is not None or self.verb_after(k)):
                return "clause", k, sub
        state = j + 1 if subject in ("you're", "we're", "you've", "we've") else \
            j + 2 if subject in ("you", "we") and j + 1 < len(words) and words[j + 1].lower in ("are", "have") \
            else -1
        if 0 <= state < len(words) and words[state].lower in STATES_DONE:
            if self._clause_follows(state + 1):
                return "then", state + 1, "then"    # "when you're there look for a cup": the clause is its own
            return "then", self.cond_end(state + 1), "then"
        end = self.cond_end(j)
        if end >= len(words) or words[end].lower in END_MARKS:
            end = self.run_on_condition(j, end) or end      # "when Sam comes home *give* him his keys"
        return ("cond", end, sub) if end > j else None

    def run_on_condition(self, j: int, end: int) -> int | None:
        """Where the command starts inside a condition said first with no comma ("when Sam comes home *give* him
        his keys", "if the kettle has boiled *pour* the water"): after a finite verb of the condition (one that
        is not its own lemma: "comes", "has"; or a base form after a subject: "when guests *arrive*"; never the
        condition's first word or one after a determiner: "the *guests*" is its subject, words30), a verb of the
        library in its base form, not after a determiner,
        "to", a modal or "and", with an object, a particle or nothing after it; None when there is none (dictated
        speech drops the comma: words29)."""
        words = self.words
        finite = False
        for k in range(j, end):
            low = words[k].lower
            lemma = verb_lemma(low)
            if not finite:
                finite = lemma is not None and low not in NP_OPENERS and k > j and \
                    words[k - 1].lower not in NP_OPENERS and words[k - 1].lower not in MODALS and \
                    words[k - 1].lower != "to" or low in BE_WORDS or \
                    "'" in low[1:] and "'" + low.split("'", 1)[1] in CONTRACTED     # "if *you're* in the hall"
                continue            # "before *the guests* arrive", "when *guests* arrive": the subject (words30)
            before = words[k - 1].lower
            if before in NP_OPENERS or before in MODALS or before in BE_WORDS or \
                    before in ("to", "and", "or", "not", "'s"):     # "if the door is *open*": its state
                continue
            found = self.verb_at(k)
            if found is None or found[0].split()[0] != low:
                continue
            nxt = words[k + 1].lower if k + 1 < len(words) else ""
            if not nxt or nxt in END_MARKS or nxt in PRONOUNS or self.np_starts(k + 1) or nxt in PARTICLES:
                return k
        return None

    def _clause_follows(self, k: int) -> bool:
        """Whether a clause of the command starts at ``k``, maybe after a comma."""
        if k < len(self.words) and self.words[k].lower == ",":
            k += 1
        return k < len(self.words) and self.verb_after(k)

    def _departure_end(self, k: int) -> int:
        """Where "leave", "go" ends at ``k`` when it ends the sentence: a verb of moving (a unit of a frame with a
        goal) said of the robot with nothing after it ("turn off the stove before you *leave*"), or with only the
        room it leaves, after a unit that puts its object somewhere ("when you leave *the kitchen*": a room is no
        thing to put anywhere; "when you reach the kitchen" goes there, a clause), is its going away, the time of
        the command, no frame (0: none); so is one said first, before a comma and the command's clause ("when you
        leave the bedroom, switch off the light", words24). Not "after you put it away" (an object), "when you get
        there, ..." (:meth:`_arrival_end`)."""
        words = self.words
        found = self.verb_at(k) if k < len(words) else None
        if found is None or found[2] is not None or found[0] not in self.lexicon.goals:
            return 0
        after = k + found[1]
        if after < len(words) and words[after].lower in DEPARTING and found[0] not in self.lexicon.puts:
            after += 1                          # "before you go *out*": a particle of leaving, nothing after it
        room = after + (after < len(words) and words[after].lower in NP_OPENERS)
        stop = next((m for m in range(room, len(words)) if words[m].lower in END_MARKS or
                     words[m].lower in ("now", "please", ",")), len(words))
        if room > after and stop > room and found[0] in self.lexicon.puts and \
                is_room_word([w.lower for w in words[room:stop]]):
            after = stop                        # "... when you leave *the kitchen*": a room is put nowhere, left
        while after < len(words) and words[after].lower in ("now", "please"):
            after += 1
        if after < len(words) and words[after].lower == "," and self._clause_follows(after):
            return after                        # "when you leave the bedroom, switch off the light": said first
        return after if after == len(words) or words[after].lower in END_MARKS else 0

    def _leaving(self, k: int) -> bool:
        """Whether the verb at ``k`` is a unit that puts its object somewhere ("leave"): said of the robot with no
        object it is going away, never arriving (words24)."""
        found = self.verb_at(k) if k < len(self.words) else None
        return found is not None and found[0] in self.lexicon.puts

    def _arrival_end(self, k: int) -> int:
        """Where "get there", "arrive", "reach it" ends at ``k``: a verb of going (a unit of a frame with a
        goal) with no place but "there"/"here"/"it", then a comma or a clause (0: none). Arriving where the
        command went is no motion of its own."""
        words = self.words
        found = self.verb_at(k) if k < len(words) else None
        if found is None or found[2] is not None or found[0] not in self.lexicon.goals:
            return 0
        after = k + found[1]
        if after < len(words) and words[after].lower in ("there", "here", "it"):
            after += 1
        return after if self._clause_follows(after) else 0

    def subordinate(self, i: int, start: bool) -> Match | None:
        """Tag a subordinate clause (see :meth:`_subordinate_at`; None: none here).
        At a clause's start the subordinator is politeness before the verb (the grammar's ``pre``),
        inside a clause a separator; a condition is one ``COND`` word."""
        low = self.words[i].lower
        if self.verb_after(i + 1) or not start and (self.speech and low in WH_WORDS or
                                                    match_phrase(self.words, i, SEPARATOR_WORDS) > 1):
            return None         # "tell me when ..." is what is said; "after heating it", "when done": separators
        found = self._subordinate_at(i)
        if found is None:
            return None
        kind, end, sub = found
        tag = Tag.COND if kind == "cond" else Tag.POLITE if start else Tag.SEP
        return Match(end - i, (merge(self.words, i, end - i, tag, sub),))

    def relative(self, i: int, described: bool = False) -> Match | None:
        """A relative clause after a noun (None: none here). "the cup *that is* on the
        table" and "the person *who is* waving" drop "that is" (the rest describes the noun as
        usual); any other ("the glass *that I was drinking from*", "the book *I left on the sofa*",
        "the bananas *that have gone bad*") is one ``REL`` word the noun keeps; "*where it belongs*"
        names a place (``HERE``). ``described``: the clause is set off by a comma after a verb of speech whose
        message is said already ("tell the time to Jo*, who is in the hall*"), so it describes, nothing said."""
        words, low, prev = self.words, self.words[i].lower, self.prev_tag()
        nxt = words[i + 1].lower if i + 1 < len(words) else ""
        if low == "where":
            if self.speech or prev not in ("WORD", "NAME", "PRON", "PARTICLE", "HERE") or not self.has_object():
                return None
            end = self.cond_end(i + 1)
            return self.emit(i, end - i, "HERE", "where") if end > i + 1 else None
        if prev == "PARTICLE" and len(self.out) > 1 and self.out[-1].info != self.out[-1].lower and \
                self.out[-2].tag in ("WORD", "NAME"):
            prev = self.out[-2].tag   # "turn the lamp on *that is on the table*": a split particle, then the noun's
        told_of = self.thing_told_of()
        if prev not in ("WORD", "NAME") and not (prev == "PRON" and low == "who" and self.out[-1].lower in (
                "someone", "somebody", "anyone", "anybody", "everyone", "everybody", "those", "one")) and \
                not (told_of and low in ("that", "which")) and \
                not (prev == "PRON" and low in ("that", "which") and self.out[-1].lower in INDEFINITE):
            return None             # "take everything *that's in the sink*": an indefinite's relative clause
        if self.speech and not told_of and not described:
            return None             # "tell the man (that) ...": what is said
        if low == "you" and "adv" in parts_of_speech(nxt) and nxt not in CLOSED and i + 2 < len(words) and \
                verb_lemma(words[i + 2].lower) not in (None, words[i + 2].lower):
            nxt = words[i + 2].lower                    # "the one you *just* brought": the verb after the adverb
        if low in NOMINATIVE or low == "you" and verb_lemma(nxt):
            end = self.relative_end(i + 1)
            return self.emit(i, end - i, "REL") if end > i + 1 else None
        if low not in RELATIVES or self.speech and low == "that" and not told_of or not nxt or nxt in END_MARKS:
            return None
        holding = self.holding_relative(i)
        if holding is not None:
            return holding
        if nxt in BE_WORDS and i + 2 < len(words):
            b = i + 2                                   # "the man who's *the one* in red": "the one" says nothing
            if b + 2 < len(words) and words[b].lower == "the" and words[b + 1].lower in ("one", "ones"):
                b += 2                                  # more (words35)
            after = words[b].lower
            n = match_phrase(words, b, PREPOSITIONS)
            if n and self.np_starts(b + n):
                return self.emit(i, b - i, "REL", "be")     # "the cup that is on the table": the PP describes it
            if gerund_lemma(after) and prev == "NAME" and len(self.out) > 1 and self.out[-2].tag == "PREP":
                end = self.cond_end(b)              # "bring it to Alex(,) who is sitting at the desk": a name
                return self.emit(i, end - i, "REL")     # after a preposition takes no participle in the grammar;
                #   the clause is one REL word the name keeps, as "who's in the bathroom" is (words28)
            if gerund_lemma(after):
                return Match(b - i)  # "the person who is waving": "the person waving"
            end = b
            if end + 1 < len(words) and words[end].lower in ("the", "a") and _superlative(words[end + 1].lower) and \
                    (end + 2 >= len(words) or words[end + 2].lower in END_MARKS or
                     words[end + 2].lower in (",", ";", "and", "then")):
                end += 1        # "the cup that is *the* biggest" (words35); "the closest to the sink": no end
            results: list[tuple[str, str]] = []
            while end < len(words) and (words[end].lower not in CLOSED or words[end].lower == "not") and \
                    words[end].lower not in END_MARKS and words[end].lower not in (",", ";", ":", "then") and \
                    not (words[end].lower in ("and", "or") and (end + 1 >= len(words) or words[end + 1].lower in
                                                                CLOSED or self.verb_after(end + 1))):
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
                    or match_phrase(words, end + 1, PREPOSITIONS)):
                end += 1                             # "the charger that's plugged in | next to my bed"
            return self.emit(i, max(end, i + 2) - i, "REL", tuple(results))
        end = self.relative_end(i + 1)
        return self.emit(i, end - i, "REL") if end > i + 1 else None

    def holding_relative(self, i: int) -> Match | None:
        """A relative clause that says what a thing holds (alfred23), read as the phrase of contents it means:
        "the box *that has* a candle in it" is "the box *with* a candle in it", "a plate *which holds* a pen on
        it" "a plate *with* a pen on it" (a verb of having, its object said to be in or on "it"); "the bowl *that
        contains* an apple" is "the bowl *containing* an apple". "has" or "holds" with no "in it" ("the cup that has
        a chip", "the man that holds a cup") stay relative clauses."""
        words = self.words
        if words[i].lower not in ("that", "which") or i + 2 >= len(words) or self.prev_tag() != "WORD":
            return None
        verb = verb_lemma(words[i + 1].lower)
        if verb not in HOLDING_VERBS or words[i + 1].lower == verb or not self.np_starts(i + 2):
            return None
        end = self.cond_end(i + 2)
        said_in = any(words[k].lower in ("in", "on", "inside") and words[k + 1].lower in ("it", "them")
                      for k in range(i + 3, min(end, len(words) - 1)))
        if said_in:
            return self.emit(i, 2, Tag.PREP, "with")
        return self.emit(i, 2, Tag.VBG_T, "contain") if verb == "contain" else None

    def relative_end(self, j: int) -> int:
        """Where a relative clause with a verb of its own ends: where a clause would end, or before a
        prepositional phrase, which the frame may take ("put the cup you used | in the sink") or give back
        to the relative clause ("bring me the book I left | on the sofa")."""
        words = self.words
        end = self.cond_end(j)
        for k in range(j + 1, end):
            n = match_phrase(words, k, PREPOSITIONS)
            if not n or not self.np_starts(k + n) or self.verb_at(k + n) is not None:
                continue
            if k + n < len(words) and words[k + n].lower in ("it", "them", "him", "her") and k + n + 1 < end:
                continue         # "a box that has a candle in it | on the table"
            return k             # "the book I left | on the sofa": the frame decides whose phrase it is
        return end

    def separator(self, i: int, n: int) -> Match | None:
        """Tag a separator ("and", ",", "then", ", and then") as SEP, AND_NP or nothing;
        None when it is no separator here."""
        words = self.words
        j = i + n
        while j < len(words) and match_phrase(words, j, SEPARATOR_WORDS) and words[j].lower not in ("before",):
            if j > i and words[j].lower in SUB_FIRST and (self._subordinate_at(j) or ("",))[0] == "then":
                break               # ", and *while you're there*, greet Jo": the clause's own subordinate (words42)
            j += match_phrase(words, j, SEPARATOR_WORDS)
        later = match_phrase(words, j, SEQUENCE_ADVERBS) if j < len(words) else 0
        if later and self.verb_after(j + later + int(j + later < len(words) and words[j + later].lower == ",")):
            j += later + int(words[j + later].lower == ",")   # ", and *later on* find her": part of the joint
        phrase = " ".join(w.lower for w in words[i:i + n])
        low, span = ("and", j - i - n + 1) if phrase in AND_WORDS else (words[i].lower, j - i)
        sub = self._subordinate_at(j) if j < len(words) and words[j].lower in SUB_FIRST and \
            not (self.speech and words[j].lower in WH_WORDS) and not self.verb_after(j + 1) else None
        if sub is not None and low in ("and", "then", ",", ";", "or", "and then"):
            kind, end = sub[0], sub[1]
            ends_clause = end < len(self.words) and self.words[end].lower == "," and self.verb_after(end + 1)
            if low in (",", ";") and kind == "cond" and not ends_clause:
                return Match(j - i)  # "turn off the stove, when the water boils": the condition of this clause
            # "..., and once you're done, put them away"; "...; when it is warm, bring it"
            return Match(j - i, (merge(words, i, j - i, Tag.SEP),))
        if self.verb_after(j):
            return Match(j - i, (merge(words, i, j - i, Tag.SEP),))
        if phrase == "followed by":
            return None              # "the cup followed by the plate": no clause follows
        if j >= len(words) or words[j].lower in END_MARKS:
            if low in (",", ";", ":"):
                return Match(j - i)        # a trailing comma is nothing
            return Match(j - i, (merge(words, i, j - i, Tag.SEP),))
        nxt = words[j].lower
        if low == "," and gerund_lemma(nxt) and self.prev_tag() in ("WORD", "NAME"):
            return Match(1)                # "a pan, containing a knife, in the fridge"
        if low in (",", ";", ":") and (nxt in PREPOSITIONS or nxt == "please"):
            return Match(1)                # "Put a pan with a spoon in it, in the sink"
        joint = [w.lower for w in words[i:j]]
        then = "then" in joint or "afterwards" in joint or "next" in joint or \
            "after" in joint and "that" in joint          # "and after that Jane to the office" (words35)
        again = self._object_again(j, then, any(w.lower in (",", ";") for w in words[i:j])) \
            if low in ("and", ",", ";", "then") else None
        if again:                          # "bring the milk to the table and the cereal too": the verb again
            return Match(j - i, (merge(words, i, j - i, Tag.SEP), Word("", words[j].start, words[j].start,
                                                                        Tag.VERB, again)),
                         expect=False, verb=again, using=False)
        given = (self._given_again(j) or self._led_again(j)) if (
            then or any(w.lower in (",", ";") for w in words[i:j])) and low in ("and", ",", ";", "then") else None
        if given:                          # "hand Ben a cup and then *Anna a cup*": the verb again, to her
            return Match(j - i, (merge(words, i, j - i, Tag.SEP), Word("", words[j].start, words[j].start,
                                                                        Tag.VERB, given)),
                         expect=False, verb=given, using=False)
        if low == "and" and [w.lower for w in words[i + 1:j]] == ["also"] and self.np_starts(j) and \
                self.prev_tag() in ("WORD", "NAME") and words[j].lower in NP_OPENERS and self.verb_at(j) is None:
            return Match(j - i, (words[i].tagged(Tag.AND_NP),))   # "an apple *and also* a cola": "and" (words48)
        if low in ("then", "after that", "afterwards", "finally", "after", "before", "while", "once done",
                   "when done") or span > 1 and low != ",":
            again = self._path_again(j)
            if again:                      # "go to the kitchen and then *to the bedroom*": the verb again
                return Match(j - i, (merge(words, i, j - i, Tag.SEP), Word("", words[j].start, words[j].start,
                                                                            Tag.VERB, again)),
                             expect=False, verb=again, using=False)
            return Match(j - i, (merge(words, i, j - i, Tag.SEP),))
        if low == "," and span == 1 and self._between_adjectives(i, j):
            return Match(1)                # "a round, gold object": one noun phrase, its head "object"
        if low in ("and", ",", ";") and self._obliged_at(j) and not self.things_listed():
            return Match(j - i, (merge(words, i, j - i, Tag.SEP),), expect=True)   # "..., the cups go on the shelf"
        if low == "," and j == i + 2 and words[i + 1].lower == "and" and self.prev_tag() in ("WORD", "NAME") and \
                self.person_at(j) and match_phrase(words, j + 1, ADDITIVES):
            return Match(j - i, (merge(words, i, j - i, Tag.AND_NP),))   # "hand Ben a cup*, and* Anna too"
        if low in ("and", ",", "or") and self.np_starts(j) and self.prev_tag() in ("WORD", "NAME", "PRON"):
            unknown_verb = (nxt not in NP_OPENERS and nxt not in PRONOUNS
                            and not capitalised(words[j]) and nxt not in NUMBERS and
                            (self._object_after(j + 1) or self._verb_and_path(j)))
            if not unknown_verb:
                return Match(n, (merge(words, i, n, Tag.AND_NP),))
        m, prep = self.preposition(j) if low == "and" and n == 1 else (0, None)
        if m and self.prev_tag() in ("WORD", "NAME", "PRON") and self.np_starts(j + m) and \
                prep in PATH_PREPOSITIONS and \
                not any(self.verb_at(k) for k in range(j, self.cond_end(j))):
            return Match(n)      # "down from the shelf *and* over to my chair": one path, phrases in a row
        again = self._path_again(j) if m and self.prev_tag() in ("WORD", "NAME", "PRON") else None
        if again in self.lexicon.puts and prep in _PUT_IN and \
                not any(self.verb_at(k) and words[k].lower not in self.lexicon.things
                        for k in range(j + m, self.cond_end(j))):    # "in (the) microwave": a thing, no verb
            return Match(n, (merge(words, i, n, Tag.SEP), Word("", words[j].start, words[j].start, Tag.VERB, again)),
                         expect=False, verb=again, using=False)   # "put a cup in the fridge *and in* the microwave"
        if low == "or" and self.prev_tag() in ("WORD", "NAME", "PRON") and match_phrase(words, j, PREPOSITIONS):
            k = j + match_phrase(words, j, PREPOSITIONS)
            end = self.cond_end(k)
            if self.np_starts(k) and not any(self.verb_at(m) for m in range(k, end)):
                return Match(n, (merge(words, i, n, Tag.AND_NP),))    # "on the desk or in the bedroom"
        if low in ("and", "then", ",", ";", "or"):
            return Match(j - i, (merge(words, i, j - i, Tag.SEP),))
        return None

    def things_listed(self) -> bool:
        """Whether the clause so far is only the things of "the plate and the bowl belong on the shelf": its verb
        the unsaid "put" of a thing said to belong somewhere, and no more than noun phrases after it (words42: the
        "and" joins the things, the obligation is the list's)."""
        if self.verb_index < 0:
            return False
        verb = self.out[self.verb_index]
        return not verb.text and verb.info == PLACE_MEANS and \
            all(w.tag in (Tag.DET, Tag.WORD, Tag.POSS, Tag.NUM, Tag.AND_NP) for w in self.out[self.verb_index + 1:])

    def _obliged_at(self, j: int) -> bool:
        """Whether a noun phrase and what it should do ("the cups *go* on the shelf", ``english.OBLIGED``) start at
        ``j``: a clause of its own, said as a statement (the rule ``where a thing should go``)."""
        words = self.words
        if j >= len(words) or words[j].lower not in NP_OPENERS:
            return False
        for k in range(j + 1, min(len(words), j + 8)):
            if match_phrase(words, k, OBLIGED):
                return words[k - 1].lower not in NP_OPENERS and \
                    k + 1 < len(words)
            if not words[k].lower.isalpha() or words[k].lower in PREPOSITIONS or words[k].lower in CLOSED:
                return False
        return False

    def _between_adjectives(self, i: int, j: int) -> bool:
        """Whether the comma at ``i`` stands between two adjectives of one noun phrase ("a round, gold object",
        "the small, black shelf"): the word before it is an adjective, no noun the library names, right after
        a determiner, a number or a possessive; open-class words follow up to the phrase's end, with no "and"
        or "or" closing a list ("a red, a blue and a green cup"; "a bowl, cup and plate" stays a list)."""
        words, out = self.words, self.out
        if len(out) < 2 or out[-1].tag != Tag.WORD or out[-2].tag not in (Tag.DET, Tag.NUM, Tag.POSS):
            return False
        before = words[i - 1].lower
        if not is_adjective(before) or before in self.lexicon.things or not self.noun_follows(j):
            return False
        k = j
        while k < len(words) and self.noun_follows(k) and words[k].lower not in NUMBERS:
            k += 1
        return k > j and (k >= len(words) or words[k].lower not in ("and", "or", ","))

    def _path_again(self, j: int) -> str | None:
        """The verb of the clause before when a path without a verb follows a separator of sequence: "go to
        the kitchen and then *to the bedroom*", "walk to the door, then back to the sofa" (a verb of motion,
        a frame with a goal, and only a path phrase after: the same verb said again); None."""
        words = self.words
        if self.verb_index < 0 or str(self.out[self.verb_index].info) not in self.lexicon.goals:
            return None
        k = j + (1 if j < len(words) and words[j].lower == "back" else 0)
        n, prep = self.preposition(k)
        unit = str(self.out[self.verb_index].info)
        if prep is None or not (prep in PATH_PREPOSITIONS or unit in self.lexicon.puts and prep in _PUT_IN) or \
                not self.np_starts(k + n):
            return None              # "put the pan in the fridge, then *on the stove*": where it is put next
        return unit

    def preposition(self, k: int) -> tuple[int, str | None]:
        """The preposition that starts at word ``k``: how many words it takes and its canonical form
        (``english.PREPOSITIONS``: "inside of" is "in"); (0, None) when none starts there."""
        words = self.words
        n = match_phrase(words, k, PREPOSITIONS) if k < len(words) else 0
        return n, (PREPOSITIONS[" ".join(w.lower for w in words[k:k + n])] if n else None)

    def _object_again(self, j: int, then: bool = False, comma: bool = False) -> str | None:
        """The verb of the clause before when one more object of it follows a separator ("..., and the cereal *too*",
        "and the fork as well", ``ADDITIVES``; after "then" no additive is needed: "put the milk in the fridge and
        then the butter"): a noun phrase (a determiner or a possessive first) of open-class words, and then only
        the additive to the sentence's end or the next separator; None."""
        words = self.words
        if self.verb_index < 0 or j >= len(words) or \
                words[j].lower not in NP_OPENERS:
            return None
        k = j + 1
        while k < min(len(words), j + 8) and words[k].lower.isalpha() and (
                words[k].lower not in CLOSED or then and words[k].lower in ("one", "ones")) and \
                not match_phrase(words, k, ADDITIVES) and \
                (self.verb_at(k) is None or words[k].lower in self.lexicon.things):
            k += 1                                        # "and a *pan* too": a thing, though a verb of English
        if k == j + 1:
            return None                                   # a determiner alone
        n = match_phrase(words, k, ADDITIVES) if k < len(words) else 0
        if not n and not then:
            return self._placed_again(j) if comma else None
        if not n and then and k < len(words):
            m, prep = self.preposition(k)           # "count the cups in the den and then *the ones in the hall*":
            if prep is not None and self.np_starts(k + m):     # the verb again, with a place of its own (words35)
                end = self.cond_end(k + m)
                if any(self.verb_at(x) is not None and words[x - 1].lower not in NP_OPENERS
                       for x in range(k + m, end)):
                    return None
                k = end
        end = k + n
        if end < len(words) and words[end].lower not in END_MARKS and words[end].lower not in (",", ";", "please"):
            return None
        return str(self.out[self.verb_index].info)

    def person_at(self, j: int) -> bool:
        """Whether word ``j`` names a person a thing can be given to: a name (written with a capital, no thing
        nor verb of the library), a noun of people ("mum", "the twins" are not: one word), or an object pronoun."""
        words = self.words
        if j >= len(words):
            return False
        low = words[j].lower
        return low in _GIVEN_TO or low in self.lexicon.people or \
            capitalised(words[j]) and low not in self.lexicon.things and low not in CLOSED and self.verb_at(j) is None

    def _given_again(self, j: int) -> str | None:
        """The verb of the clause before when, after "and then" or a comma, another person and a thing follow
        with no verb: "hand Ben a cup and then *Anna a cup*", "bring Dad his glasses, then *Mum her keys*" (gapping:
        the verb is said once). The clause gave a thing to a person said first (a unit of a frame with a
        recipient, a person right after the verb); the new person is followed by a noun phrase's opener (a
        determiner, a possessive, a number); None."""
        words = self.words
        if self.verb_index < 0 or self.verb_index + 1 >= len(self.out):
            return None
        unit = str(self.out[self.verb_index].info)
        first = self.out[self.verb_index + 1]
        if unit not in self.lexicon.recipients or not (first.tag == Tag.NAME or first.lower in _GIVEN_TO or
                                                        first.lower in self.lexicon.people):
            return None
        if not self.person_at(j) or j + 1 >= len(words) or words[j + 1].lower not in NP_OPENERS or \
                self.verb_after(j):
            return None
        return unit

    def _led_again(self, j: int) -> str | None:
        """The verb of the clause before when, after "then" or a comma, another person and a path follow with no
        verb: "guide Ben to the hall, then *Ana to the porch*" (gapping, words35). The clause's verb has a goal and
        its object, said right after it, is a person; the new person is followed by a preposition of a path and its
        noun phrase, and no verb to the clause's end; None. A preposition of where the person is ("in", "at", "on")
        may follow instead, after any verb whose object is a person: "greet Ben in the hall, then *Ana in the den*",
        "find Jo at the desk and then Max in the shed" (words37)."""
        words = self.words
        if self.verb_index < 0 or self.verb_index + 1 >= len(self.out):
            return None
        unit = str(self.out[self.verb_index].info)
        first = self.out[self.verb_index + 1]
        if not (first.tag == Tag.NAME or first.lower in _GIVEN_TO or first.lower in self.lexicon.people):
            return None
        if not self.person_at(j) or j + 1 >= len(words) or self.verb_after(j):
            return None
        m, prep = self.preposition(j + 1)
        if not (prep in PATH_PREPOSITIONS and unit in self.lexicon.goals or prep in LOCATED) or \
                not self.np_starts(j + 1 + m):
            return None
        end = self.cond_end(j + 1 + m)
        if any(self.verb_at(x) is not None and words[x - 1].lower not in NP_OPENERS for x in range(j + 1 + m, end)):
            return None
        return unit

    def _placed_again(self, j: int) -> str | None:
        """The verb of the clause before when, after a comma, one more object and where it goes follow, with
        no verb ("put the fork on the table, *and a knife on the plate*", "put the cup in the sink, the plate
        in the rack", "..., and a warm slice of bread in the bin"): the verb puts a thing somewhere, its clause
        said a place already (or the new one says where it comes from: "bring me the cup, *and a knife from the
        kitchen*"), and the new noun phrase (a determiner at ``j``, open-class words, an "of" phrase)
        is followed only by a place phrase of putting or of a path to the clause's end; None."""
        words = self.words
        unit = str(self.out[self.verb_index].info)
        k = j + 1
        while k < min(len(words), j + 10) and (words[k].lower.isalpha() and words[k].lower not in CLOSED or
                                                 words[k].lower == "of" and k > j + 1):
            k += 1                                        # "a cold potato *slice*": a verb of ours inside the phrase
        if k == j + 1 or words[k - 1].lower == "of":
            return None
        m, prep = self.preposition(k)
        if prep is None or not (prep in PATH_PREPOSITIONS or prep in _PUT_IN) or unit not in self.lexicon.goals or \
                not (prep in _SOURCES or any(w.tag == Tag.PREP for w in self.out[self.verb_index + 1:])) or \
                not self.np_starts(k + m):
            return None               # a source needs no place said before: "bring me the cup, and a knife *from* ..."
        end = self.cond_end(k + m)
        if any(self.verb_at(x) and words[x].lower not in self.lexicon.things for x in range(k + m, end)) or \
                any(words[x].lower in ("and", "or") for x in range(k + m, end)):
            return None                                   # "..., and the knife on the plate and wash it": a clause
        return unit

    def _verb_and_path(self, j: int) -> bool:
        """Whether word ``j``, after "and", is a verb's base form that names no thing the library knows, with
        a preposition of no place after it (``NOT_PLACES``) or a wh-word: "go to the office and *wait for* me
        there", "wash a mug and *fill with* water", "go into the office and *see who* is there" (a clause, not
        a noun of a list; "a bowl and *pen on* the desk": where the list goes)."""
        words = self.words
        low = words[j].lower
        return j + 1 < len(words) and words[j - 1].lower == "and" and \
            (words[j + 1].lower in NOT_PLACES or words[j + 1].lower in WH_WORDS) and \
            low.isalpha() and low not in self.lexicon.things and verb_lemma(low) == low

    def _object_after(self, k: int) -> bool:
        """Whether what starts at ``k`` is the object of a verb said just before it: a determiner, a
        possessive, an object pronoun or a name ("..., and *let Kim* know"), after a particle too
        ("..., *track down the* towel"): the word before is then a verb, not a noun of a list."""
        words = self.words
        if k + 1 < len(words) and words[k].lower in PARTICLES and words[k].lower not in PREPOSITIONS and \
                verb_lemma(words[k - 1].lower) and words[k - 1].lower not in self.lexicon.things:
            k += 1                       # "track *down* the towel": the particle of a verb, not "fork *in* the"
        if k >= len(words):
            return False
        low = words[k].lower
        return low in NP_OPENERS or low in ("it", "them", "me") or \
            capitalised(words[k]) and low not in self.lexicon.things and verb_lemma(words[k - 1].lower) is not None

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
        if digits and k + 1 < len(words) and words[k].lower in (":", ".") and self.minutes_written_on(k):
            k += 2                                              # "at 5:30", "by 17.45": the minutes written on
        if k < len(words) and words[k].lower in TIME_UNITS:
            return k + 1 - i                                    # "in ten minutes", "by 5 hours"
        if low == "in" and digits:
            return 0                                            # "the guests in 305": a place
        while k < len(words) and words[k].lower in CLOCK_WORDS:
            k += 1                                              # "at 5 pm", "at three thirty", "at 4 o'clock"
        if k < len(words) and self.noun_follows(k) and words[k].lower not in NUMBERS:
            return 0
        return k - i

    def _check_clock(self, hours: Word, minutes: Word) -> None:
        """Refuse a time written with its minutes that no clock shows: "at 25:00", "by 5:60", "at 99:99" (hours up
        to 23, or 24:00, the day's end; minutes up to 59), at the column of its hours, rather than keep a time the
        robot cannot wait for."""
        h, m = int(hours.lower), int(minutes.lower)
        if h <= 23 and m <= 59 or h == 24 and m == 0:
            return
        said = self.text[hours.start:minutes.end] if self.text else f"{hours.text}:{minutes.text}"
        why = f"the minutes go up to 59, not {m}" if m > 59 else f"the hours go up to 23, not {h}"
        raise CommandError(f"{said!r} is no time of day: {why}", hours.start + 1, self.text, ["a time such as 17:45"])

    def label_at(self, i: int) -> bool:
        """Whether the number at ``i`` names a numbered thing with the noun before it ("room *214*",
        "meeting room *three*", "table *9*"): one number (digits, or a number word other than "one"),
        with no noun after it to count ("give the kids *two* apples" counts)."""
        low = self.words[i].lower
        if low == "one" and self._one_labels(i):
            return True
        if not (low.isascii() and low.isdigit() or low in NUMBERS and low not in VAGUE_NUMBERS):
            return False
        if i + 1 < len(self.words) and self.words[i + 1].lower in TIME_UNITS:
            return False                                        # "wait ten minutes"
        return i + 1 >= len(self.words) or not self.noun_follows(i + 1) or self.words[i + 1].lower in NUMBERS

    def _one_labels(self, i: int) -> bool:
        """Whether the "one" at ``i`` names a numbered place with the bare singular noun before it, right after a
        preposition, ending the phrase ("go to *table one*", "put it in box one": words42; it was the pronoun of
        "the red one", with no element to take it). Only there: "give the kids one", "bring Anna one" count."""
        out = self.out
        return len(out) >= 2 and out[-1].tag == Tag.WORD and out[-2].tag == Tag.PREP and \
            not is_plural(out[-1].lower) and not self.noun_follows(i + 1)

    def noun_follows(self, i: int) -> bool:
        """Whether an open-class word (a noun or adjective) starts at ``i``."""
        if i >= len(self.words):
            return False
        low = self.words[i].lower
        if low in CLOSED or low in END_MARKS or low in (",", ";", ":", "and", "then", "of", "please") or \
                low in SUB_FIRST:                              # "on pallet 6 *before* they ship"
            return low in NUMBERS and low != "one"
        return low not in PREPOSITIONS


