"""Statements said beside the command: a sentence with no verb of the library ("Good morning!"),
words of address and statements after the request ("..., dear, I'm cold"), a clause after
"because" or a subject contraction, and what is told without "that" ("tell mom *I'm late*")."""

from __future__ import annotations

from seal_cli.language.english import (
    BECAUSE,
    END_MARKS,
    FINITE,
    FOUND_STATED,
    LET_KNOW,
    LOCATIVE,
    NOMINATIVE,
    NP_OPENERS,
    PREPOSITIONS,
    RELATIVES,
    SUBJECTS,
    WH_WORDS,
)
from seal_cli.language.morphology import verb_lemma
from seal_cli.language.rule import START, Example, Match, Rule
from seal_cli.language.state import CLOSED, State, first_words, longest_phrase, merge, subject_contracted, subject_word
from seal_cli.language.tags import Tag
from seal_cli.language.tokens import Word, capitalised


def _aside(s: State, i: int) -> Match | None:
    return s.aside(i)


def _found_stated(s: State, i: int) -> Match | None:
    """"*You'll find Axel by the bookshelf,* lead him to the kitchen" (``FOUND_STATED``): at a sentence's start, the
    words of coming upon, a phrase, a preposition of where it is and its phrase, then a comma and a command (no "then"
    or "and": "you'll find Sam in the hall, then bring him a tea" is two steps) — a remark the command's pronoun
    names, as "Axel is by the bookshelf, ..." is."""
    words = s.words
    if s.out and not (s.out[-1].tag == Tag.SEP and s.out[-1].lower in END_MARKS):
        return None
    j = _place_before_found(s, i)
    n = longest_phrase(words, j, FOUND_STATED)
    if not n or not s.np_starts(j + n):
        return None
    comma = next((k for k in range(j + n + 1, len(words)) if words[k].lower in (",", ";") or
                  words[k].lower in END_MARKS or words[k].lower in ("and", "then")), len(words))
    if comma + 1 >= len(words) or words[comma].lower not in (",", ";") or \
            words[comma + 1].lower in ("and", "then") or not s.verb_after(comma + 1):
        return None
    if not (j > i or any(PREPOSITIONS.get(w.lower) in LOCATIVE for w in words[j + n + 1:comma])) or \
            any(s.verb_at(k) is not None and words[k - 1].lower not in NP_OPENERS for k in range(j + n, comma)):
        return None
    return Match(comma + 1 - i, (merge(words, i, comma + 1 - i, Tag.POLITE),),
                 remarks=((words[i].start, words[comma - 1].end),))


def _place_before_found(s: State, i: int) -> int:
    """Where the words of coming upon start after a phrase of place said first ("*in the bathroom* you'll find Morgan,
    ..."), else ``i``: a preposition of where a thing is and a few words with no comma or verb."""
    words = s.words
    if PREPOSITIONS.get(words[i].lower) not in LOCATIVE or not s.np_starts(i + 1):
        return i
    for k in range(i + 2, min(len(words), i + 8)):
        if longest_phrase(words, k, FOUND_STATED):
            return k
        if not words[k].lower.isalpha() or s.verb_at(k) is not None and words[k - 1].lower not in NP_OPENERS:
            return i                              # "in the *shed*": a noun after its determiner
    return i


def _her_told(s: State, i: int) -> Match | None:
    out = s.out
    if not (s.speech and out and out[-1].lower == "her" and s.prev_tag() == Tag.POSS):
        return None
    if subject_word(s.words[i]) and s.told_at(i) or _bare_noun_is(s, i):
        return Match(0, last=out[-1].tagged(Tag.PRON))            # "tell *her* we're moving": her is the person told
    return None


_ASKED_THINGS = frozenset(["question", "questions", "quiz", "riddle", "riddles", "query", "queries", "whatever"])
"""What a person asks, as a verb of saying's object ("answer *whatever* she asks you", "answer the *question* the man
asks")."""
_ASKING = frozenset(["ask", "asks", "asked", "has", "have", "poses", "pose", "posed"])
_ASKED_OF = frozenset(["you", "me", "us"])


def _asking_end(s: State, i: int) -> int:
    """Where "asks (you)" ends the clause after its subject at ``i`` ("whatever *the man by the door* asks you"; 0:
    none): a form of asking, maybe the one asked, then the clause's end; a subject of a few words before it."""
    words = s.words
    end = s.clause_end(i + 1)
    for k in range(i + 1, min(end, i + 10)):
        if words[k].lower in _ASKING:
            n = 1 + (k + 1 < end and words[k + 1].lower in _ASKED_OF)
            return k + n if k + n == end else 0
    return 0


def _question_asker(s: State, i: int) -> Match | None:
    """"answer *whatever* the person raising their arm asks you", "answer the question *she asks*": what a person asks
    is their question, as "the question *of* the person ..." is — an unsaid "of" before the asker (whose question,
    the recipient); "asks you" is dropped by :data:`ASKING_DROPPED` (words46: "she asks you" was what is said, the
    question the person answered, and "whatever the person ... asks you" was refused)."""
    words = s.words
    if not s.speech or s.prev_tag() != Tag.WORD or s.out[-1].lower not in _ASKED_THINGS:
        return None
    relative = words[i].lower in RELATIVES
    k = i + relative
    if k >= len(words) or not (words[k].lower in NOMINATIVE or words[k].lower in NP_OPENERS or
                               capitalised(words[k])) or not _asking_end(s, k):
        return None
    at = words[k].start
    return Match(int(relative), (Word("", at, at, Tag.OF, None, "of"),))


def _asking_dropped(s: State, i: int) -> Match | None:
    words = s.words
    if s.verb_index < 0 or not any(w.text == "" and w.tag == Tag.OF for w in s.out[s.verb_index + 1:-1]):
        return None
    n = 1 + (i + 1 < len(words) and words[i + 1].lower in _ASKED_OF)
    return Match(n) if s.clause_end(i + 1) == i + n else None


def _bare_noun_is(s: State, i: int) -> bool:
    """Whether a bare noun and a finite verb start at ``i`` ("tell her *dinner's* ready", "tell her *lunch is*
    served"): a statement, so the "her" before it is the person told, not whose dinner."""
    words = s.words
    low = words[i].lower
    return i + 1 < len(words) and low.isalpha() and low not in CLOSED and not capitalised(words[i]) and \
        low not in s.lexicon.units and words[i + 1].lower in FINITE


def _before_know(s: State, i: int) -> bool:
    """Whether the clause's verb is the "let" of "let X know" and its "know" is still to come ("let mum *and* dad
    know ...": what is told begins after it)."""
    return s.verb_index >= 0 and s.out[s.verb_index].lower == LET_KNOW[0] and \
        any(w.lower == LET_KNOW[1] for w in s.words[i:i + 12])


def _told(s: State, i: int) -> Match | None:
    if s.speech and s.prev_tag() in (Tag.WORD, Tag.NAME, Tag.PRON, Tag.LABEL) and s.told_at(i) and \
            not _before_know(s, i):
        end = s.speech_end(i)
        return s.emit(i, end - i, Tag.SAID)                       # "tell him we need a cart": kept whole
    return None


def _told_after_colon(s: State, i: int) -> Match | None:
    """"tell jane*:* dinner is ready", "say to the man at the door: come in" (words48): a colon after the one a verb
    of saying tells opens what is said, as "that" does; the colon was read as a word of the person ("jane:", head
    ":"). What follows it, up to where the command goes on, is said whole; the colon itself is dropped."""
    words = s.words
    if words[i].lower != ":" or not s.speech or s.prev_tag() not in (Tag.WORD, Tag.NAME, Tag.PRON, Tag.LABEL) or \
            i + 1 >= len(words) or words[i + 1].lower in END_MARKS:
        return None
    end = s.speech_end(i + 1)
    said = s.emit(i + 1, end - i - 1, Tag.SAID).words[0]
    return Match(end - i, (said,))


def _remark_unmarked(s: State, i: int) -> Match | None:
    low = s.words[i].lower
    if s.expect_verb or s.prev_tag() not in (Tag.WORD, Tag.NAME, Tag.PRON, Tag.PARTICLE, Tag.LABEL, Tag.HERE) or \
            not (low in BECAUSE or "'" in low or subject_contracted(s.words, i) or
                 low == "so" and i + 1 < len(s.words) and (s.words[i + 1].lower in SUBJECTS or
                                                           s.words[i + 1].lower in NP_OPENERS)):
        return None
    n, spans = s.remark_unmarked(i)
    return Match(n, remarks=spans) if n else None                 # "give the ball to Lily cos she wants it"


def _remark_after(s: State, i: int) -> Match | None:
    if s.expect_verb:
        return None
    n, spans = s.remark_after(i)
    return Match(n, remarks=spans) if n else None   # "close the door, dear, I'm cold": address and statements dropped


def _told_how_to(s: State, i: int) -> Match | None:
    words = s.words
    if not s.speech or s.prev_tag() not in (Tag.WORD, Tag.NAME, Tag.PRON, Tag.LABEL, Tag.VERB) or \
            i + 2 >= len(words) or words[i + 1].lower != "to" or verb_lemma(words[i + 2].lower) != words[i + 2].lower:
        return None
    end = s.speech_end(i)                                         # "explain to Robin *how to get to the kitchen*"
    return s.emit(i, end - i, Tag.SAID)


def _dislocated(s: State, i: int) -> Match | None:
    return s.dislocated(i)


DISLOCATED = Rule("phrase said first, taken up by a pronoun", _dislocated, (
    Example("The sponge on the cabinet, bring it to me.", "The sponge on the cabinet,", Tag.POLITE),
    Example("That dice on the sofa, could you bring it to me?", "That dice on the sofa,", Tag.POLITE),
    Example("whoever's at the door, greet them", "whoever's at the door,", Tag.POLITE),    # a free relative
), None, "a noun phrase and a comma before a command whose pronoun takes it up: a remark it names")
ASIDE = Rule("sentence beside the command", _aside, (
    Example("Morning! Could you open the window?", "Morning!", Tag.POLITE),
    Example("Bogdan has a question; answer it for him", "Bogdan has a question;", Tag.POLITE),
    Example("see the man by the window? greet him", "see the man by the window?", Tag.POLITE),
    Example("on the sofa there's a blanket, bring it to me", "on the sofa there's a blanket,", Tag.POLITE),
    Example("someone waving in the hall wants a towel, take them one", "someone waving in the hall wants a towel,",
            Tag.POLITE),                                          # words48: described by what they do
    Example("the gate is open close it", "the gate is open", Tag.POLITE),   # words48: the command said on, no mark
), None, "a greeting, a statement with no verb of the library, or 'see X?', where a command should start")
QUESTION_ASKER = Rule("whose question, asked", _question_asker, (
    Example("answer whatever the man at the door asks you", "", Tag.OF),
    Example("answer the question she asks", "", Tag.OF),
), None, "'answer whatever X asks (you)': X's question, as 'the question of X'", after=frozenset([Tag.WORD]),
   needs=_ASKING)
ASKING_DROPPED = Rule("whose question, asked: the asking", _asking_dropped, (
    Example("answer whatever the man at the door asks you", "asks you", ""),
), _ASKING, "the 'asks you' after the asker of 'answer whatever X asks you': dropped, X is whose question it is")
FOUND_STATED_RULE = Rule("where you will find it", _found_stated, (
    Example("you'll find Noor by the piano, take her to the garden", "you'll find Noor by the piano,", Tag.POLITE),
    Example("you will find the keys in the drawer, bring them to me", "you will find the keys in the drawer,",
            Tag.POLITE),
    Example("in the shed you'll find a rake, bring it to me", "in the shed you'll find a rake,", Tag.POLITE),
), first_words(FOUND_STATED) | frozenset(p for p, canonical in PREPOSITIONS.items() if canonical in LOCATIVE),
    "'you'll find X in Y, V it': where X is, a remark the command's pronoun names",
    after=frozenset([START, Tag.SEP]))
HER_TOLD = Rule("her told", _her_told, (
    Example("tell her we're moving", "her", Tag.PRON),
    Example("tell her dinner's ready", "her", Tag.PRON),
), None, "'her' before a subject is the person a verb of saying tells, not a possessive", after=frozenset([Tag.POSS]))
TOLD = Rule("told without that", _told, (
    Example("tell mom I'm late", "I'm late", Tag.SAID),
    Example("tell the kids dinner is ready", "dinner is ready", Tag.SAID),
    Example("tell grandma lunch is ready", "lunch is ready", Tag.SAID),
), None, "what is told without 'that', right after the person told",
   after=frozenset([Tag.WORD, Tag.NAME, Tag.PRON, Tag.LABEL]))
TOLD_AFTER_COLON = Rule("told after a colon", _told_after_colon, (
    Example("tell grandpa: the taxi is here", "the taxi is here", Tag.SAID),
    Example("say to the man at the gate: come in", "come in", Tag.SAID),
), frozenset([":"]), "a colon after the person told: what follows is what is said",
   after=frozenset([Tag.WORD, Tag.NAME, Tag.PRON, Tag.LABEL]))
TOLD_HOW_TO = Rule("how to, told", _told_how_to, (
    Example("Explain to Robin how to get to the kitchen.", "how to get to the kitchen", Tag.SAID),
    Example("tell me where to put the plates", "where to put the plates", Tag.SAID),
), WH_WORDS, "'how to V', 'where to V' after a verb of saying: what is said, not a clause of purpose")
REMARK_UNMARKED = Rule("remark without a comma", _remark_unmarked, (
    Example("give the ball to Lily cos she wants it", "cos", ""),
    Example("stir the soup so it doesn't stick", "so", ""),             # words31: purpose, "so" and a subject
    Example("stir the custard so that it doesn't go lumpy", "so", ""),   # words32: "so that" and a subject
    Example("warm up my tea it's gone cold", "it", ""),                 # words36: "it" and "'s" written apart
    Example("shut the gate so the dog can't get out", "so", ""),       # words38: "so" and a noun phrase subject
), lambda low: low in BECAUSE or "'" in low or low == "so" or low in SUBJECTS,
    "'because', a subject contraction, or 'so' and a subject (a pronoun or a noun phrase) after the request starts a "
    "statement")
REMARK_AFTER = Rule("remark after a comma", _remark_after, (
    Example("close the door, dear, I'm cold", "dear", ""),
), frozenset([",", ";"]), "words of address and statements after a comma ending the request")
