"""Politeness and address: what asks nicely and says no task ("could you", "please", "Robin, ...",
"when you get a chance")."""

from __future__ import annotations

from seal_cli.language.english import (
    AS_ABLE,
    AS_ABLE_NOT_MANNER,
    ASKED_AGAIN,
    END_MARKS,
    FREQUENCY_ADVERBS,
    GREETINGS,
    HELPED_MOVING,
    KNOW_WISHES,
    NP_OPENERS,
    NUMBER_MEANS,
    OBJECT_PRONOUNS,
    POLITE,
    QUESTION_MEANS,
    QUESTION_WORDS,
    RELAYED_OBLIGATION,
    RELAYING,
    SUBJECTS,
    TAG_QUESTIONS,
    WHERE_MEANS,
)
from seal_cli.language.morphology import (
    gerund_lemma,
    in_verb_tables,
    is_adjective,
    is_adverb,
    noun_lemma,
    parts_of_speech,
    verb_lemma,
)
from seal_cli.language.rule import START, Example, Match, Rule
from seal_cli.language.state import CLOSED, FORMULA_FIRST, State, first_words, longest_phrase, match_phrase, merge
from seal_cli.language.tags import Tag
from seal_cli.language.tokens import capitalised

_ASKING = frozenset([QUESTION_MEANS, WHERE_MEANS, NUMBER_MEANS, "how many"])
_DO_YOU = frozenset(["do you", "would you", "does anyone"])


def _said(s: State, i: int, table: frozenset[str]) -> int:
    """How many words of the longest phrase of ``table`` start at ``i`` (0: none)."""
    return max((len(parts) for parts in map(str.split, table) if i + len(parts) <= len(s.words) and
                all(s.words[i + k].lower == part for k, part in enumerate(parts))), default=0)


_ASKED_NICELY = frozenset(["please", "kindly"])
"""Politeness before the question asked again ("what's in the box, *kindly* tell me": words37)."""
_OPINION_ASKED = frozenset(["say", "think", "guess", "reckon"])
"""The hearer's opinion asked after a question ("how many are in the hall, would you *say*?", "who's at the door, do
you *think*?": words37): the question asked again, no clause of its own. Not a table of :mod:`english` ("say" is a
verb of the library's)."""


def _asked_again(s: State, i: int) -> Match | None:
    """"Which drink is the heaviest, *can you tell me*?": the question asked again after its comma, nothing after
    it: politeness ending the command (``ASKED_AGAIN``), not a clause that tells nothing."""
    words = s.words
    if not s.out or s.out[-1].tag != Tag.SEP or s.out[-1].lower != "," or \
            not any(w.tag == Tag.VERB and w.info in _ASKING for w in s.out):
        return None
    n = asked_again_at(s, i)
    return Match(n, (merge(words, i, n, Tag.POLITE),)) if n else None


def asked_again_at(s: State, i: int) -> int:
    """How many words from ``i`` ask the question before them again and end the command (", *do you think*?",
    ", *can you tell me*", ", *kindly tell me*"); 0: none (words37, shared with the question's own end: words39)."""
    words = s.words
    n = _said(s, i, TAG_QUESTIONS | _DO_YOU) or _said(s, i, _ASKED_NICELY)
    m = _said(s, i + n, ASKED_AGAIN) or (_said(s, i + n, _OPINION_ASKED) if n and words[i].lower not in
                                         _ASKED_NICELY else 0)
    if not m or not all(w.lower in END_MARKS for w in words[i + n + m:]):
        return 0
    return n + m


def _formula(s: State, i: int) -> Match | None:
    n = s.formula(i)
    if not n:
        return None
    if s.expect_verb:
        return Match(n, (merge(s.words, i, n, Tag.POLITE),))     # "When you get a chance, could you ..."
    return Match(n)                                               # "bring it to me when you can"


def _while_holding(s: State, i: int) -> Match | None:
    if not s.out and s.words[i].lower in ("while", "after", "having") and s.verb_after(i + 1):
        return s.emit(i, 1, Tag.POLITE)                           # "While holding a cup, ...", "Having grabbed"
    return None


def _adverb_comma(s: State, i: int) -> Match | None:
    words, low = s.words, s.words[i].lower
    if i + 2 < len(words) and words[i + 1].lower == "," and is_adverb(low) and \
            (s.verb_after(i + 2) or words[i + 2].lower == "please"):
        return Match(2, (merge(words, i, 2, Tag.POLITE),))        # "*Quietly,* please: turn off ..."
    return None


_ANNOUNCING = frozenset(["is", "need", "want", "do", "job", "task", "mission"])
"""Last words of a phrase that announces the task ("the task is", "here's what I need", "what I want you to do
is": words33): a verb must follow (after a colon or comma), else they are no politeness ("the task is done")."""

_ANNOUNCED = frozenset(["job", "task", "mission"])
"""Nouns of "your job: ..." (words35), an announcement only with its colon or comma."""

_ORDINALS = frozenset(["second", "third", "fourth"])
"""Ordinals that say which step comes ("*second,* fill it": words33) only before a comma or a verb."""

_VERB_NEXT = frozenset(["to", "about", "mind"])
"""Last words of politeness that only a verb may follow ("help me *to* ...", "how *about* closing ...", "do you
*mind* switching ..."): with none after, the words are no politeness."""


_WANT_YOU_BARE = frozenset(["i want you", "i need you", "i would like you", "i'd like you", "we want you",
                            "we need you"])
"""A wish that the robot do something said without its "to", as learners of English say it ("*I want you* bring me the
book": words39): politeness only when a verb of the library follows ("I need you here" stays a statement)."""


def _politeness(s: State, i: int) -> Match | None:
    words, low = s.words, s.words[i].lower
    n = match_phrase(words, i, POLITE)
    bare = longest_phrase(words, i, _WANT_YOU_BARE) if low in ("i", "we", "i'd") else 0
    if bare > n and s.verb_after(i + bare):
        return Match(bare, (merge(words, i, bare, Tag.POLITE),))
    if low == "to" and n == 1 and _goal_said_first(s, i):
        return None                                   # "*To the dining room,* follow Jane": where, said first
    if low in _ORDINALS and not (i + 1 < len(words) and words[i + 1].lower in (",", ";", ":") or s.verb_after(i + 1)):
        return None                                   # "*second* cup, please": a thing's order, no step's
    wish = longest_phrase(words, i, KNOW_WISHES)
    if n and wish > n and i + wish < len(words) and words[i + wish].lower != "where":
        return None                                   # "*would you know* how many ...": a wish to know (words37)
    k = i + n
    while k < len(words) and words[k].lower != "to" and is_adverb(words[k].lower):
        k += 1                                        # "would you mind *terribly* switching off ..."
    if n > 1 and words[i + n - 1].lower in _ANNOUNCING and k < len(words) and words[k].lower in (":", ","):
        k += 1                                        # "the task is*:* bring me ...", "here's what I need*:* go ..."
    elif n == 2 and words[i + 1].lower in _ANNOUNCED:
        return None                                   # "your job" with no colon: no announcement ("your job is done")
    if n > 1 and words[i + n - 1].lower in _VERB_NEXT | _ANNOUNCING and not s.verb_after(k) and \
            not _unknown_verb_wished(s, i, n):
        return None                                   # "help me to the bathroom": "help" is the verb said (words27);
        #   "what about the dishes?": a question, no suggestion of a deed ("what about closing it": words30)
    if n and not (n == 1 and low in ("and", "then") and not s.out and not s.verb_after(i + 1) and
                  not _question_next(s, i + 1)) and (
            low in ("to", "and", "then") or s.verb_after(i + n) or not s.verb_at(i) or
            i + n >= len(words) and n > 1):
        return Match(n, (merge(words, i, n, Tag.POLITE),))
    return None                                       # "bring one. then *go*": a verb said last is no politeness


def _unknown_verb_wished(s: State, i: int, n: int) -> bool:
    """Whether the formula of ``n`` words at ``i`` wishes the robot do something ("I want *you to*", "we need you to")
    and a verb's base form no frame lists follows: the formula is politeness, so the command is refused at that verb
    ("I want you to polish it": "unknown verb 'polish'", not "'i'"; after a comma it was dropped as a remark,
    words46)."""
    words = s.words
    k = i + n
    return n > 2 and words[k - 2].lower == "you" and words[k - 1].lower == "to" and k < len(words) and \
        words[k].lower.isalpha() and verb_lemma(words[k].lower) == words[k].lower and in_verb_tables(words[k].lower)


_QUESTION_FIRST = QUESTION_WORDS | {"where", "where's", "whereabouts", "how"}
"""Words that open a question the robot answers, after which a first "and" or "then" only joins it to what was
said before ("*And* who is in the kitchen?", "*then* where is the cup?": words33)."""


def _question_next(s: State, k: int) -> bool:
    """Whether a question the robot answers starts at ``k``."""
    return k < len(s.words) and s.words[k].lower in _QUESTION_FIRST


def _helping(s: State, i: int) -> Match | None:
    """"*Help Jane* find her keys", "help him carry the box to the car", "help the guest to find a seat": helping a
    person do something is doing it (words33), as "help me find my keys" is. "help her to the car" has no verb after
    the person: "help" is the verb said there."""
    k = s.helped_verb(i)
    return Match(k - i, (merge(s.words, i, k - i, Tag.POLITE),)) if k else None


def _moving_helped(s: State, k: int) -> bool:
    """Whether a verb of moving of ``HELPED_MOVING`` at ``k`` is followed by where to ("get *to* the kitchen", "go
    *back*", "get *there*")."""
    _, moving, where = HELPED_MOVING
    words = s.words
    return k + 1 < len(words) and verb_lemma(words[k].lower) in moving and words[k + 1].lower in where


def _helped_moving(s: State, i: int) -> Match | None:
    unit = HELPED_MOVING[0]
    k = s.helped_verb(i)
    if not k or unit not in s.lexicon.units or not _moving_helped(s, k):
        return None
    verb = merge(s.words, i, 1, Tag.VERB, unit)
    if k == i + 2 and s.words[i + 1].lower in OBJECT_PRONOUNS:     # "help *her* get there": the person, no "her X"
        return Match(2, (verb, s.emit(i + 1, 1, Tag.PRON).words[0]), expect=False, verb=unit, using=False)
    return Match(1, (verb,), expect=False, verb=unit, using=False)


def _helped_moving_dropped(s: State, i: int) -> Match | None:
    if s.verb_index < 0 or s.out[s.verb_index].lower != "help" or s.out[s.verb_index].info != HELPED_MOVING[0] or \
            any(w.tag in (Tag.SEP, Tag.VERB) for w in s.out[s.verb_index + 1:]):
        return None
    start = s.out[s.verb_index].start
    helped = next((s.helped_verb(j) for j, w in enumerate(s.words) if w.start == start), 0)
    n = s.words[i].lower == "to"
    if i + n != helped:
        return None                     # the verb "help" read as leading comes after the person and what describes them
    return Match(n + 1) if _moving_helped(s, i + n) else None     # "help him *get* to the kitchen": the leading's


def _goal_said_first(s: State, i: int) -> bool:
    """Whether "to" at ``i`` opens a phrase of where, said first and ended by a comma before a clause ("*To the
    dining room,* follow Jane": words33), not the "to" of an infinitive ("to open the door, turn the key"); the
    verb after it has a goal ("to the lamp, turn on the light" is none: refused as before, never the goal dropped),
    or one to whom it is done ("*to the person waving in the kitchen,* tell a joke": the person told, words41; a
    participle inside the phrase describes its person, no verb of a clause)."""
    words = s.words
    if not s.np_starts(i + 1) or s.verb_at(i + 1) is not None:
        return False
    for k in range(i + 2, min(len(words), i + _SAID_FIRST_WORDS)):
        low = words[k].lower
        if low == ",":
            return s.verb_after(k + 1) and (s.goal_verb_after(k + 1) or _recipient_verb_after(s, k + 1))
        if low in END_MARKS or s.verb_at(k) is not None and words[k - 1].lower not in NP_OPENERS and \
                gerund_lemma(low) in (None, low):
            return False
    return False


_SAID_FIRST_WORDS = 12
"""How many words a phrase of "to" said first may have, with its comma ("to the woman wearing a red shirt in the
kitchen,")."""


def _recipient_verb_after(s: State, k: int) -> bool:
    """Whether the first verb of the library after ``k`` is done to someone (a recipient: "tell", "bring")."""
    for m in range(k, min(k + 8, len(s.words))):
        found = s.verb_at(m)
        if found is not None:
            return found[0] in s.lexicon.recipients
        if s.words[m].lower in END_MARKS:
            return False
    return False


_ATTENTION = frozenset(["look", "listen", "go on", "come on", "look here"])
"""Verbs said to catch the hearer's attention before what follows ("*Look,* the window is open. Close it."), or to
urge them on ("*Go on,* take the bowl to the sink": words42, it was refused as "go on", no verb of the library)."""


def _attention(s: State, i: int) -> Match | None:
    """"*Look,* the window is open. Close it.", "*listen,* can you fetch the mail?": a verb of attention and a comma
    before a statement or a command asks for attention, no search and no looking (words33: "Look," was Find with
    nothing sought)."""
    words = s.words
    n = longest_phrase(words, i, _ATTENTION)
    if not n or i + n + 1 >= len(words) or words[i + n].lower != "," or \
            not (s.statement_at(i + n + 1) or s.verb_after(i + n + 1)):
        return None
    return Match(n + 1, (merge(words, i, n + 1, Tag.POLITE),))


def _emphatic_do(s: State, i: int) -> Match | None:
    words = s.words
    if i + 1 < len(words) and "do" not in s.lexicon.units and \
            verb_lemma(words[i + 1].lower) == words[i + 1].lower and s.verb_at(i + 1):
        return s.emit(i, 1, Tag.POLITE)                           # emphatic "*Do* take his coat"
    return None


def _you_imperative(s: State, i: int) -> Match | None:
    words = s.words
    if i + 1 < len(words) and verb_lemma(words[i + 1].lower) == words[i + 1].lower and s.verb_at(i + 1):
        return s.emit(i, 1, Tag.POLITE)                           # "You go to the hall", "please you bring ..."
    return None


def _vocative_name(s: State, i: int) -> Match | None:
    words = s.words
    if capitalised(words[i]) and i + 1 < len(words) and words[i + 1].lower == "," and s.verb_after(i + 2):
        return Match(2, (merge(words, i, 2, Tag.POLITE),))        # "Robin, bring me a cup"
    return None


def _addressable(s: State, k: int) -> bool:
    """Whether the word at ``k`` may be one addressed: a lower-case word of no closed class and no verb of the
    library, that names no thing of the taxonomy unless a person ("mum", "man"), and has no reading as a verb of
    English unless a person ("alexa", "dude", "bro", "young"; never "towel", "water", "stop")."""
    word = s.words[k]
    low = word.lower
    if not low.isalpha() or low in CLOSED or low in SUBJECTS or s.verb_at(k) is not None or is_adverb(low):
        return False
    person = low in s.lexicon.people or (noun_lemma(low) or low) in s.lexicon.people
    return person or low not in s.lexicon.things and (noun_lemma(low) or low) not in s.lexicon.things and \
        not in_verb_tables(low)


def _addressed(s: State, i: int) -> Match | None:
    words = s.words
    if s.verb_at(i) is not None or not all(w.tag == Tag.POLITE for w in s.out):
        return None                                   # only before the command
    greeted = bool(s.out) and s.out[-1].lower.split()[-1] in GREETINGS
    n = 0
    while n < 2 and i + n < len(words) and (_addressable(s, i + n) or greeted and n == 0 and
                                             words[i + n].lower.isalpha() and s.verb_at(i + n) is None and
                                             words[i + n].lower not in CLOSED):
        n += 1
    if not n:
        return None
    k = i + n
    if k < len(words) and words[k].lower == "," and (s.verb_after(k + 1) or s.asks_at(k + 1) or
                                                     greeted and s.statement_at(k + 1)) if k + 1 < len(words) \
            else False:
        return Match(n + 1, (merge(words, i, n + 1, Tag.POLITE),))   # "alexa, switch off the tv", "young man, ..."
    m = i + 1
    while m + 1 < len(words) and s.verb_at(m) is None and words[m].lower.isalpha() and \
            (is_adverb(words[m].lower) or words[m].lower in FREQUENCY_ADVERBS):
        m += 1                                        # "Morgan *just* arrived": an adverb before the verb (words39)
    nxt = words[m].lower if m < len(words) else ""
    if nxt and s.verb_at(m) is not None and verb_lemma(nxt) != nxt:
        return None                                   # "Priya went to the garage": a subject and its finite verb
    if (greeted or words[i].lower in GREETINGS or not parts_of_speech(words[i].lower) - {"noun"}) and \
            s.verb_after(i + 1):
        return Match(1, (merge(words, i, 1, Tag.POLITE),))         # "dude just open the door", "ok google turn ..."
    return None


_RELAY_SUBJECT_WORDS = 3
_RELAYING_PRONOUNS = frozenset(["he", "she", "they", "we", "i"])


def _relayed(s: State, i: int) -> Match | None:
    """"mummy says you have to turn off the telly", "Anna asked you to bring her a towel", "dad says you should bring
    him his glasses": a subject, a verb passing a request on (``RELAYING``), maybe "that", then "you" and what obliges
    (``RELAYED_OBLIGATION``) before a verb: the request is the command (it was read as Tell, "say"/"ask" with the
    clause as its message, or as an unknown verb "mummy"); the subject and its verb are a remark, which a pronoun
    of the command may take up ("bring *him* his glasses": dad)."""
    words = s.words
    if not any(w.lower == "you" for w in words[i + 1:i + _RELAY_SUBJECT_WORDS + _RELAY_DESCRIBED + 5]) or \
            not all(w.tag == Tag.POLITE for w in s.out):
        return None                                   # no "you" near (the common case)
    low = words[i].lower
    if low in _RELAYING_PRONOUNS:
        j = i + 1
    else:
        k = i + (low in NP_OPENERS)
        j = k
        while j < len(words) and j - k < _RELAY_SUBJECT_WORDS and words[j].lower.isalpha() and \
                words[j].lower not in CLOSED and not longest_phrase(words, j, RELAYING) and s.verb_at(j) is None:
            j += 1
        if j == k:
            return None
        j = _relayer_described(s, j)
    n = longest_phrase(words, j, RELAYING)
    if not n:
        return None
    k = j + n + (j + n < len(words) and words[j + n].lower == "that")
    if k >= len(words) or words[k].lower != "you":
        return None
    m = longest_phrase(words, k + 1, RELAYED_OBLIGATION)
    if not m or not s.verb_after(k + 1 + m):
        return None
    end = k + 1 + m
    return Match(end - i, (merge(words, i, end - i, Tag.POLITE),), remarks=((words[i].start, words[j + n - 1].end),))


_RELAY_DESCRIBED = 8
"""The most words of what describes the one who passes a request on ("the man *at the door* wants you to ...")."""


def _relayer_described(s: State, j: int) -> int:
    """Where what describes the one passing a request on ends, from ``j`` (words48): phrases of where they are or what
    they wear ("the person *at the door* wants you to ...", :meth:`State.described_at`), or a relative clause set off
    by commas ("Jane*, who's at the sofa,* wants you to follow her"); ``j`` when none."""
    words = s.words
    if j + 2 < len(words) and words[j].lower == "," and (words[j + 1].lower in ("who", "who's", "whose") or
                                                         words[j + 1].lower == "that"):
        close = next((k for k in range(j + 2, min(len(words), j + _RELAY_DESCRIBED)) if words[k].lower == ","), None)
        return close + 1 if close is not None else j
    return s.described_at(j)


def _like_filler(s: State, i: int) -> Match | None:
    words = s.words
    if s.out and (s.out[-1].tag == Tag.POLITE or s.out[-1].tag == Tag.SEP and s.out[-1].lower != ",") and \
            i + 1 < len(words) and \
            (s.verb_after(i + 1) or words[i + 1].lower == "," and s.verb_after(i + 2)):
        return Match(1 + (words[i + 1].lower == ","))             # "can you *like* grab my bag": a filler
    return None


_SPOKEN_FILLERS = frozenset(["you know", "i mean", "like", "basically", "so basically", "you see"])
"""Words a speaker fills a pause with, said between commas where a clause starts ("go to the office and, *you know*,
find Morgan"; words39): they ask nothing."""


def _spoken_filler(s: State, i: int) -> Match | None:
    words = s.words
    if not s.expect_verb or s.out and s.out[-1].tag not in (Tag.SEP, Tag.POLITE):
        return None
    n = _said(s, i, _SPOKEN_FILLERS)
    if not n or i + n + 1 >= len(words) or words[i + n].lower != ",":
        return None
    after = words[i + n + 1].lower
    if not s.verb_after(i + n + 1) and not (in_verb_tables(after) and verb_lemma(after) == after and
                                            after not in CLOSED and after not in SUBJECTS):
        return None             # a clause's verb follows ("I mean, *see* if Jane is there"), known or not
    return Match(n + 1)


def _filler_inside(s: State, i: int) -> Match | None:
    """", like," / ", you know," / ", I mean," between commas inside a clause ("find*, like,* the biggest box";
    words39): a pause filled, nothing said; the clause goes on after it."""
    words = s.words
    if s.expect_verb or i + 3 >= len(words):
        return None
    n = _said(s, i + 1, _SPOKEN_FILLERS)
    if not n or i + n + 2 >= len(words) or words[i + n + 1].lower != "," or words[i + n + 2].lower in END_MARKS:
        return None
    return Match(n + 2)


def _please_inside(s: State, i: int) -> Match | None:
    words = s.words
    if s.expect_verb or i + 1 >= len(words) or words[i + 1].lower in END_MARKS:
        return None
    n, spans = s.remark_after(i + 1) if words[i + 1].lower == "," else (0, ())
    if n:
        return Match(1 + n, remarks=spans)      # "turn the heater on please, *I'm shivering*"
    return Match(2 if i + 2 < len(words) and words[i + 1].lower == "," else 1)
    # "bring me, please, a glass of juice": politeness inside the clause


def _as_able(s: State, i: int) -> Match | None:
    """"get to the kitchen *as fast as you can*", "close it *as gently as possible*": "as", one adverb or adjective of
    manner, "as" and what the robot can (``english.AS_ABLE``), ending the clause: how, no thing and no clause (it was
    "as you" read as a joint and "can" an unknown verb). One adverb, as "quickly" is (``PARTICLE``)."""
    words = s.words
    if s.expect_verb or i + 3 >= len(words) or words[i + 2].lower != "as":
        return None
    low = words[i + 1].lower
    if low in AS_ABLE_NOT_MANNER or not low.isalpha() or not (is_adverb(low) or is_adjective(low)):
        return None
    n = _said(s, i + 3, AS_ABLE)
    k = i + 3 + n
    if not n or k < len(words) and words[k].lower not in END_MARKS and words[k].lower not in (",", ";", "and",
                                                                                                "then", "please"):
        return None
    return s.emit(i, k - i, Tag.PARTICLE)


def _thanks(s: State, i: int) -> Match | None:
    """"please", "thanks", "thank you" ending the command: politeness, unless a verb of saying says them ("tell
    him to say thank you": what is said, not the speaker's thanks; the message was "say")."""
    words = s.words
    if i > 0 and verb_lemma(words[i - 1].lower) == "say":
        return None
    k = i + 1
    while k < len(words) and words[k].lower in ("you", "please", "thanks"):
        k += 1
    if all(r.lower in END_MARKS for r in words[k:]):
        return Match(k - i, (merge(words, i, k - i, Tag.POLITE),))   # "... please", "..., thank you."
    return None


def _tag_question(s: State, i: int) -> Match | None:
    words = s.words
    n = 0 if s.expect_verb else match_phrase(words, i, TAG_QUESTIONS)
    if n and all(w.lower in END_MARKS for w in words[i + n:]):
        return Match(n, (merge(words, i, n, Tag.POLITE),))        # "fetch me a spoon from the cabinet *would you*"
    return None


ASKED_AGAIN_RULE = Rule("the question asked again", _asked_again, (
    Example("What's the largest snack in the pantry, can you tell me?", "can you tell me", Tag.POLITE),
    Example("how many cups are on the table, could you tell me", "could you tell me", Tag.POLITE),
    Example("how many jars are in the pantry, would you say?", "would you say", Tag.POLITE),
    Example("what's in the shed, kindly tell me", "kindly tell me", Tag.POLITE),
), None, "'..., can you tell me?' after a question: politeness, nothing more asked", after=frozenset([Tag.SEP]))
FORMULA = Rule("politeness formula", _formula, (
    Example("When you get a chance, could you close the window?", "When you get a chance,", Tag.POLITE),
    Example("Hey, when you get a sec, could you grab me a soda?", "when you get a sec,", Tag.POLITE),
    Example("once you've got a minute, fold the towels", "once you've got a minute,", Tag.POLITE),   # words42
    Example("bring it to me when you can", "when", ""),
), FORMULA_FIRST, "politeness said as a clause of its own: before the command, politeness; after it, dropped")
WHILE_HOLDING = Rule("while or after first", _while_holding, (
    Example("While holding a cup, turn on the lamp", "While", Tag.POLITE),
    Example("Having grabbed the cup, put it on the table.", "Having", Tag.POLITE),
), frozenset(["while", "after", "having"]), "'while'/'after'/'having' opening the command before a verb")
ADVERB_COMMA = Rule("adverb and comma", _adverb_comma, (
    Example("Quietly, please: turn off the radio", "Quietly,", Tag.POLITE),
), is_adverb, "a manner adverb and its comma before a request")
_POLITE_FIRST = first_words(POLITE)
"""Where politeness can start (its rule's gate)."""
POLITENESS = Rule("politeness", _politeness, (
    Example("could you please bring me a cup", "could you please", Tag.POLITE),
    Example("once you're upstairs, see if you can find my glasses", "see if you can", Tag.POLITE),      # words42
    Example("go to the garage and try and find the pump", "try and", Tag.POLITE),
    Example("robot, go to the kitchen", "robot,", Tag.POLITE),
    Example("how about closing the window", "how about", Tag.POLITE),
    Example("do you mind switching the fan on", "do you mind", Tag.POLITE),
    Example("And who is in the kitchen?", "And", Tag.POLITE),
    Example("would you close the gate", "would you", Tag.POLITE),
    Example("I want you open the gate", "I want you", Tag.POLITE),
), _POLITE_FIRST, "politeness words and phrases before the verb (english.POLITE)")
ATTENTION = Rule("look, listen", _attention, (
    Example("Look, the window is open. Close it.", "Look,", Tag.POLITE),
    Example("listen, can you fetch the mail?", "listen,", Tag.POLITE),
    Example("go on, take the bowl to the sink", "go on,", Tag.POLITE),                  # words42
), first_words(_ATTENTION), "'Look, ...', 'listen, ...' before a statement or a command: attention asked, no frame")
HELPING = Rule("help a person do", _helping, (
    Example("Help Jane find her keys", "Help Jane", Tag.POLITE),
    Example("help the guest to find a seat", "help the guest to", Tag.POLITE),
), frozenset(["help"]), "'help Jane find X': find X (the robot does what it helps with)")
HELPED_MOVING_RULE = Rule("help a person move", _helped_moving, (
    Example("help grandpa get to the garden", "help", Tag.VERB),
    Example("help him go back to his room", "help", Tag.VERB),
    Example("help the man in the red shirt go to the bathroom", "help", Tag.VERB),   # words48: described
), frozenset(["help"]), "'help X get/go to Y': guide X to Y (the robot leads the person it helps move)")
HELPED_MOVING_DROPPED = Rule("help a person move: the moving", _helped_moving_dropped, (
    Example("help grandpa get to the garden", "get", ""),
    Example("help the guest to go upstairs", "to go", ""),
), frozenset(["to", *(f for lemma in HELPED_MOVING[1] for f in (lemma, "got", "went", "came"))]),
    "the verb of moving after 'help X' read as guiding: dropped, the verb is the leading")
EMPHATIC_DO = Rule("emphatic do", _emphatic_do, (
    Example("Do take his coat", "Do", Tag.POLITE),
), frozenset(["do"]), "'do' before a verb's base form")
YOU_IMPERATIVE = Rule("you before the verb", _you_imperative, (
    Example("You go to the hall", "You", Tag.POLITE),
), frozenset(["you"]), "'you' before a verb's base form: still a request")
VOCATIVE_NAME = Rule("name addressed", _vocative_name, (
    Example("Robin, bring me a cup", "Robin,", Tag.POLITE),
), None, "a capitalised name and a comma before the command: the robot addressed")
ADDRESSED = Rule("one addressed in lower case", _addressed, (
    Example("alexa, turn off the radio", "alexa,", Tag.POLITE),
    Example("hey siri, where is my wallet", "siri,", Tag.POLITE),
    Example("young lady, bring me the paper", "young lady,", Tag.POLITE),
    Example("yo, grab me a coke", "yo,", Tag.POLITE),
    Example("dude just shut the door", "dude", Tag.POLITE),
), None, "a word that names no thing and is no verb (or a person), before a comma and the command: whom is addressed",
   after=frozenset([START, Tag.POLITE]))
RELAYED = Rule("a request passed on", _relayed, (
    Example("granny says you have to shut the window", "granny says you have to", Tag.POLITE),
    Example("Omar asked you to fetch him a towel", "Omar asked you to", Tag.POLITE),
    Example("my brother wants you to open the garage", "my brother wants you to", Tag.POLITE),
    Example("the lady at the gate wants you to fetch her a chair", "the lady at the gate wants you to", Tag.POLITE),
), None, "'X says you have to V', 'X asked you to V': the request passed on is the command, X's words a remark",
   after=frozenset([START, Tag.POLITE]), needs=frozenset(["you"]))
LIKE_FILLER = Rule("like as a filler", _like_filler, (
    Example("could you like pass me the salt", "like", ""),
    Example("go to the shed and then like grab the rake", "like", ""),     # words48: after a joint
), frozenset(["like"]), "'like' after politeness or a joint and before the verb: a filler")
SPOKEN_FILLER = Rule("a spoken filler before its comma", _spoken_filler, (
    Example("open the shed and, you know, shut it", "you", ""),
    Example("I mean, grab the mop", "mean", ""),
), frozenset(["you", "i", "like", "basically", "so"]), "'you know,' / 'I mean,' where a clause starts: a filler")
FILLER_INSIDE = Rule("a spoken filler between commas inside a clause", _filler_inside, (
    Example("fetch, like, the biggest box from the shed", "like", ""),
    Example("put the mug, you know, in the sink", "know", ""),
), frozenset([","]), "', like,' / ', you know,' inside a clause: a filler")
PLEASE_INSIDE = Rule("please inside a clause", _please_inside, (
    Example("bring me, please, a glass of juice", "please", ""),
    Example("turn the heater on please, I'm shivering", "please", ""),
), frozenset(["please"]), "politeness inside a clause, and a remark after it")
AS_ABLE_RULE = Rule("as fast as you can", _as_able, (
    Example("get to the kitchen as fast as you can", "as fast as you can", Tag.PARTICLE),
    Example("close the lid as gently as possible, please", "as gently as possible", Tag.PARTICLE),
), frozenset(["as"]), "'as fast as you can', 'as gently as possible': a manner, said as one adverb")
TAG_QUESTION = Rule("tag question", _tag_question, (
    Example("fetch me a spoon from the cabinet would you", "would you", Tag.POLITE),
    Example("close the door will you?", "will you", Tag.POLITE),
), frozenset(w.split()[0] for w in TAG_QUESTIONS), "'..., would you?' ending a request: politeness")
THANKS = Rule("thanks at the end", _thanks, (
    Example("bring me the cup thank you.", "thank you", Tag.POLITE),
), frozenset(["please", "thanks", "thank"]), "'please', 'thanks', 'thank you' ending the command")
