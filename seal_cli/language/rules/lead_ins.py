"""Words before a clause's verb that are no verb and no politeness phrase: a comma after
politeness ("First, open ..."), a sequencing word ("After that, ..."), a subordinate clause ("When
you reach the kitchen, ..."), a manner adverb ("Gently place ..."), "be careful and", "start by
opening", a light verb with a noun that is a lexical unit ("take a look at"), a polite frame
ending in "you could" ("I was wondering if you could ...").

Each rule applies only where the word is no verb, unless it is one of ``LEAD_FIRST`` (a verb of
the library that also leads in: "start by", "take a look").
"""

from __future__ import annotations

from seal_cli.language.english import (
    BE_WORDS,
    BECAUSE,
    BEING_AT,
    BEING_MEANS,
    CLOCK_PREPOSITIONS,
    END_MARKS,
    FREQUENCY_LEADS,
    HAVING_FIRST,
    HAVING_MEANS,
    NOMINATIVE,
    NP_OPENERS,
    NUMBERS,
    PARTICLES,
    PARTS_OF_DAY,
    PREPOSITIONS,
    PRONOUNS,
    QUESTION_WORDS,
    RATE_WORDS,
    SEPARATOR_WORDS,
    TIME_FIRST_LEAD,
    TIME_MEASURE,
    TIME_UNITS,
    TIME_WORDS,
    TIMES_SAID,
    is_room_word,
)
from seal_cli.language.morphology import gerund_lemma, is_adverb, noun_lemma, participles, parts_of_speech, verb_lemma
from seal_cli.language.premises import is_premises
from seal_cli.language.rule import START, Example, Match, Rule
from seal_cli.language.rules.numbers import TEENS, TENS
from seal_cli.language.state import (
    CLOSED,
    LEAD_FIRST,
    LIGHT_VERBS,
    SEP_FIRST,
    SUB_FIRST,
    TIME_FIRST,
    State,
    first_words,
    match_phrase,
    merge,
)
from seal_cli.language.tags import Tag
from seal_cli.language.tokens import Word, capitalised


def _not_a_verb(s: State, i: int) -> bool:
    return s.words[i].lower in LEAD_FIRST or s.verb_at(i) is None


def _comma_after_politeness(s: State, i: int) -> Match | None:
    if s.prev_tag() in (Tag.POLITE, Tag.COND, Tag.SEP) and _not_a_verb(s, i):
        return Match(1, last=s.extended(i, 1))
    return None


def _sequencing(s: State, i: int) -> Match | None:
    words, low = s.words, s.words[i].lower
    if not _not_a_verb(s, i):
        return None
    n = match_phrase(words, i, SEPARATOR_WORDS)
    if n and low not in ("and", "or", "while", "before", "after", "as") or n > 1 and low in ("and", "after"):
        k = i + n + (1 if i + n < len(words) and words[i + n].lower == "," else 0)
        if s.verb_after(k):
            if s.prev_tag() == Tag.SEP:        # "Take the cup to the sink. After that, wash it."
                last = s.extended(i, k - i)
                return Match(k - i, last=Word(last.text, last.start, last.end, last.tag, "then"))
            return Match(k - i, (merge(words, i, k - i, Tag.POLITE),))
    return None


_TIME_NOT_FIRST = frozenset(["too", "as well", "again", "first"])
"""Time words that never open a clause as its time ("first" is sequencing, ``SEPARATOR_WORDS``)."""


def _time_said(s: State, i: int) -> int:
    """How many words a time said before the verb takes at ``i`` (0: none): a time adverbial ("tonight", "right
    now", "later on", "this afternoon"), a time with a number ("in five minutes", "at six"), a measure of time
    ("in a couple of minutes", "in an hour"), or "after"/"before" and a bare noun ("after lunch", "before bed")."""
    words, low = s.words, s.words[i].lower
    n = match_phrase(words, i, TIME_WORDS)
    if n and " ".join(w.lower for w in words[i:i + n]) not in _TIME_NOT_FIRST:
        if low == "later" and s.next_lower(i) == "on":
            n += 1                                                  # "later on"
        if low in ("tonight", "tomorrow") and s.next_lower(i + n - 1) in PARTS_OF_DAY:
            n += 1                                                  # "tomorrow morning"
        return n
    if low == "this" and s.next_lower(i) in PARTS_OF_DAY:
        return 2                                                    # "this afternoon"
    n = _how_often(s, i)
    if n:
        return n                                                    # "every morning", "twice a day"
    if low == "from" and s.next_lower(i) == "now" and s.next_lower(i + 1) == "on":
        return 3                                                    # "from now on"
    n = s.clock_time(i)
    if n:
        return n                                                    # "in five minutes", "at six"
    if low == "in":
        k = i + 1
        while k < len(words) and (words[k].lower in TIME_MEASURE or words[k].lower in NUMBERS or
                                  words[k].lower in TEENS or words[k].lower in TENS or words[k].lower.isdigit()):
            k += 1                                                  # "in a couple of minutes", "in twenty minutes"
        if k > i + 1 and k < len(words) and words[k].lower in TIME_UNITS:
            return k + 1 - i
    if low in TIME_FIRST_LEAD and i + 1 < len(words):
        nxt = words[i + 1].lower
        after = s.next_lower(i + 1)
        if nxt.isalpha() and nxt not in CLOSED and nxt not in PRONOUNS | NOMINATIVE and \
                not capitalised(words[i + 1]) and \
                s.verb_at(i + 1) is None and not nxt.endswith("ing") and \
                (after == "," or verb_lemma(after) == after):       # "until dad gets home": a clause, no time
            return 2                                                # "after lunch", "before bed"
    return 0


def _how_often(s: State, i: int) -> int:
    """How many words a time said as how often takes at ``i`` (0: none): "every"/"each", a few words of
    quantity and a part of the day or a unit ("*every morning*", "*every few minutes*"), or a number of times
    and its rate ("*twice a day*", "*three times a week*", "*once every hour*")."""
    words, low = s.words, s.words[i].lower
    units = TIME_UNITS | PARTS_OF_DAY
    k = i
    if low in TIMES_SAID:
        k = i + 1
    elif (low in NUMBERS or low.isdigit()) and s.next_lower(i) == "times":
        k = i + 2
    if k > i:
        if k + 1 < len(words) and words[k].lower in RATE_WORDS and words[k + 1].lower in units:
            return k + 2 - i
        return 0
    if low in FREQUENCY_LEADS:
        k = i + 1
        while k < len(words) and (words[k].lower in TIME_MEASURE or words[k].lower in NUMBERS):
            k += 1                                                  # "every few minutes", "every two hours"
        if k < len(words) and words[k].lower in units:
            return k + 1 - i
    return 0


def _time_first(s: State, i: int) -> Match | None:
    """A time said before the clause's verb ("*in five minutes* turn off the oven", "*tonight* close the
    curtains", "*after lunch*, clean the counter"): when, nothing to do; kept as the frame's time."""
    n = _time_said(s, i)
    if not n:
        return None
    words = s.words
    k = i + n + (1 if i + n < len(words) and words[i + n].lower == "," else 0)
    if k >= len(words) or not (s.verb_after(k) or s.asks_at(k) or words[k].lower == "i" and
                               s.next_lower(k) in ("need", "want", "'d", "would") or
                               k > i + n and _verb_of_english(s, k)):
        return None
    return Match(k - i, (merge(words, i, k - i, Tag.POLITE, "time"),))


def _verb_of_english(s: State, k: int) -> bool:
    """Whether the word at ``k``, after a time said first and its comma, is a verb's base form no frame has, with an
    object after it ("tomorrow morning, *wake* Priya up"): the clause's verb, refused there, not a thing asked for."""
    words = s.words
    low = words[k].lower
    if k + 1 >= len(words) or not low.isalpha() or low in CLOSED or verb_lemma(low) != low or \
            "verb" not in parts_of_speech(low):
        return False
    nxt = words[k + 1]
    return nxt.lower in NP_OPENERS or nxt.lower in PRONOUNS or capitalised(nxt)


def _subordinate(s: State, i: int) -> Match | None:
    return s.subordinate(i, start=True) if _not_a_verb(s, i) else None


def _longest(s: State, i: int, table: frozenset[str]) -> int:
    """How many words of the longest phrase of ``table`` start at ``i`` (0: none)."""
    words = s.words
    return max((len(p.split()) for p in table if i + len(p.split()) <= len(words) and
                all(words[i + k].lower == w for k, w in enumerate(p.split()))), default=0)


_REASONS = frozenset(["since", "now that", "seeing as", "seeing that", "given that", *BECAUSE])
"""Words that open a reason said before the command ("*since* you're in the kitchen anyway, grab a spoon": words39)."""


def _reason_first(s: State, i: int) -> Match | None:
    """A reason said before the command: "since", "now that", "because" and a statement, then a comma and the command
    ("*Since you're in the kitchen anyway,* grab a spoon", "*now that Sam is here,* greet him"). The reason asks
    nothing: it is kept as a remark, beside the command, and the clause starts after its comma."""
    words = s.words
    if s.out and s.out[-1].tag not in (Tag.POLITE, Tag.SEP):
        return None
    n = _longest(s, i, _REASONS)
    end = s.statement_at(i + n) if n else 0
    if not end or end >= len(words) or words[end].lower != "," or not s.verb_after(end + 1):
        return None
    return Match(end + 1 - i, remarks=((words[i].start, words[end - 1].end),), expect=True)


_HEADING_MARKS = frozenset([":", ";", ".", ","])
"""Marks after a room said as a heading before the command ("*Bedroom:* find Jane", "*Office -* count people": the
tokenizer reads a dash as ";")."""


_TASK_HEADINGS = frozenset(["task", "command", "instruction", "instructions", "request", "order", "orders", "todo",
                            "step", "next"])
"""Nouns that head what follows as the robot's task ("*Task:* bring me a cola", "*Instructions -* go to the kitchen",
words48), as a form or a list labels it."""


def _task_heading(s: State, i: int) -> Match | None:
    """A label of the task before the command, with a colon or a dash after it ("*Task:* go to the kitchen and find
    the milk", "*Command -* bring me a cola"; words48: an unknown verb "task"): nothing, as "robot:" is (the tokenizer
    reads a dash as ";"). Only where the command starts, before a verb; "task" with no mark is no label."""
    words = s.words
    if any(w.tag != Tag.POLITE for w in s.out) or words[i].lower not in _TASK_HEADINGS or i + 2 >= len(words) or \
            words[i + 1].lower not in (":", ";") or not s.verb_after(i + 2):
        return None
    return Match(2, (merge(words, i, 2, Tag.POLITE),))


def _room_heading(s: State, i: int) -> Match | None:
    """A room said alone before the command, as a heading, with a colon, a dash, a full stop or a comma after it
    ("*Bedroom:* find Jane", "*the pantry.* find the tuna", "*Office -* count the people"; words39): where the
    command is done, as "in the bedroom, find Jane" says it. Only a room (``english.is_room_word`` or a part of a
    building, ``premises``): a thing said so stays a bare phrase ("cola, fridge"); a name so is one addressed."""
    words = s.words
    if any(w.tag != Tag.POLITE for w in s.out):
        return None
    j = i + (words[i].lower == "the")
    k = j
    while k < len(words) and k < j + 2 and words[k].lower.isalpha() and s.verb_at(k) is None and \
            words[k].lower not in CLOSED:
        k += 1
    if k == j or k + 1 >= len(words) or words[k].lower not in _HEADING_MARKS or not s.verb_after(k + 1):
        return None
    nouns = [w.lower for w in words[j:k]]
    if not (is_room_word(nouns) or is_premises(noun_lemma(nouns[-1]) or nouns[-1])):
        return None
    at = words[i].start
    out = [Word("", at, at, Tag.PREP, "in", "in")]
    if j > i:
        out.append(words[i].tagged(Tag.DET))
    out.extend(w.tagged(Tag.WORD) for w in words[j:k])
    out.append(Word(words[k].text, words[k].start, words[k].end, Tag.SEP, None, ","))
    return Match(k + 1 - i, tuple(out), expect=True)


def _being_at(s: State, i: int) -> Match | None:
    """"*Once you're in* the living room, find Peyton": to be somewhere before a clause is to go there first;
    the subordinator and "you're" are read as ``BEING_MEANS`` (a verb of the library), the place as its
    path, and the comma or "then" after it joins the clause that follows."""
    words = s.words
    subordinators, subjects, places = BEING_AT
    n = _longest(s, i, subordinators)
    m = _longest(s, i + n, subjects) if n else 0
    k = _longest(s, i + n + m, places) if m else 0
    if not k or BEING_MEANS not in s.lexicon.units or not s.np_starts(i + n + m + k):
        return None
    end = s.cond_end(i + n + m + k)
    if (end >= len(words) or words[end].lower not in (",", ";") or not s.verb_after(end + 1)) and \
            _run_on_verb(s, i + n + m + k, end) is None:
        return None                     # "once you're in the kitchen the light is off": no clause follows
    last = words[i + n + m - 1].end
    return Match(n + m, (Word(s.text_of(words[i].start, last), words[i].start, last, Tag.VERB, BEING_MEANS),),
                 expect=False, verb=BEING_MEANS, using=False)


def _run_on_verb(s: State, np: int, end: int) -> int | None:
    """Where a clause said without a comma starts after the noun phrase at ``np`` ("once you're in the
    living room *look for* Skyler"): a verb of the library in its base form, after a word of the phrase
    that is no determiner, possessive or preposition; None when no such verb comes before ``end``, or a
    verb of being does first ("once you're in the garage the door *is* shut": a statement, no clause)."""
    words = s.words
    for j in range(np + 1, end):
        before = words[j - 1].lower
        if before in BE_WORDS:
            return None
        if not before.isalpha() or before in NP_OPENERS or before in PREPOSITIONS:
            continue
        found = s.verb_at(j)
        if found is not None and found[0].split()[0] == words[j].lower:
            return j
    return None


_ON_THE_WAY = (frozenset(["on", "along"]), frozenset(["your", "the", "my", "our", "its"]), frozenset(["way"]))
""""*On your way* back, ...", "on the way to the kitchen, ...": the words that open a circumstance of the trip."""
_WAY_WORDS = 8
"""The most words a circumstance of the trip runs to before its comma ("on your way back from the garage,")."""


def _on_the_way(s: State, i: int) -> Match | None:
    """"*On your way back,* pick up the post", "on the way to the kitchen, grab a cup": a circumstance of the
    trip before the clause, up to its comma, is no command of its own (the clause is what is asked; the robot
    plans its own trip): politeness before the verb, as a subordinate clause of the robot's own is."""
    words = s.words
    ons, owners, ways = _ON_THE_WAY
    if i + 3 >= len(words) or words[i].lower not in ons or words[i + 1].lower not in owners or \
            words[i + 2].lower not in ways:
        return None
    comma = next((j for j in range(i + 3, min(len(words), i + 3 + _WAY_WORDS)) if words[j].lower in (",", ";")),
                 None)
    if comma is None or not s.verb_after(comma + 1) or any(w.lower in END_MARKS for w in words[i + 3:comma]):
        return None
    return s.emit(i, comma + 1 - i, Tag.POLITE)


_BEFORE_GERUND = frozenset(["before"])
"""The subordinator whose clause of an -ing form, said before the command, is done after it ("*before going* to the
bedroom, grab the towel"; "after V-ing", "while V-ing" are read by ``politeness.WHILE_HOLDING``, in the order said)."""


def _subordinate_gerund(s: State, i: int) -> Match | None:
    """"*Before* going to the bedroom, grab the towel", "before answering her question, meet her at the door": a
    subordinator, then the -ing form of a verb of the library, opens a clause said before the command, as "before you
    go" does: the subordinator is kept (words41: "before" was read as a manner adverb, and the clause done first)."""
    low = s.words[i].lower
    nxt = s.next_lower(i)
    if low not in _BEFORE_GERUND or not nxt or gerund_lemma(nxt) in (None, nxt) or s.verb_at(i + 1) is None:
        return None
    return s.emit(i, 1, Tag.POLITE, low)


def _manner(s: State, i: int) -> Match | None:
    low = s.words[i].lower
    if low.isalpha() and low not in PARTICLES and is_adverb(low) and s.verb_after(i + 1) and _not_a_verb(s, i):
        return s.emit(i, 1, Tag.POLITE)                           # "Gently place the eggs ..."
    return None


def _be_careful(s: State, i: int) -> Match | None:
    words = s.words                                       # "Be careful and carry ...", "be a dear and hand me ..."
    nxt = s.next_lower(i)
    k = i + 1 + (1 if nxt in ("a", "an", "so", "extra", "very", "really") else 0)
    while k < min(len(words), i + 5) and words[k].lower not in CLOSED and words[k].lower.isalpha() and \
            words[k].lower not in ("and", "then"):
        k += 1
    if i + 1 < k < len(words) and words[k].lower in ("and", ",") and s.verb_after(k + 1):
        return s.emit(i, k + 1 - i, Tag.POLITE)
    return None


def _start_by(s: State, i: int) -> Match | None:
    words = s.words
    if s.next_lower(i) == "by" and i + 2 < len(words) and gerund_lemma(words[i + 2].lower) and s.verb_at(i + 2):
        return s.emit(i, 2, Tag.POLITE)                           # "Start by opening the window"
    return None


_ASPECTS = {"keep": ("on",), "continue": (), "carry": ("on",), "start": (), "begin": (), "go": ("on",), "mind": ()}
"""Verbs of aspect before another verb's -ing form or "to" ("*keep* following", "*carry on* walking", "*continue to*
follow", "*start* cleaning"), with the particle each takes ("carry" and "go" only with "on"); "mind" before an -ing
form is "would you mind" said short ("*mind* closing the window?")."""


def _aspect(s: State, i: int) -> Match | None:
    """"*keep following* Angel until you reach the garage", "carry on walking", "continue to follow her": a verb
    of aspect (``_ASPECTS``) before the -ing form of a verb of the library, or "to" and its base form, says
    when or how long that verb goes on: the verb is the clause's."""
    words, low = s.words, s.words[i].lower
    particles = _ASPECTS.get(low)
    if particles is None:
        return None
    j = i + 1
    if j < len(words) and words[j].lower in particles:
        j += 1
    elif low in ("carry", "go"):
        return None                                               # "carry the box", "go to": no aspect
    if j < len(words) and gerund_lemma(words[j].lower) and s.verb_at(j):
        return s.emit(i, j - i, Tag.POLITE)
    if j + 1 < len(words) and words[j].lower == "to" and low not in ("keep", "mind") and \
            words[j + 1].lower == ((s.verb_at(j + 1) or ("",))[0].split() or [""])[0]:   # "start to the": none
        return s.emit(i, j + 1 - i, Tag.POLITE)                   # "continue to follow her": base form only
    return None


def _light_verb(s: State, i: int) -> Match | None:
    found = s.light_verb(i)
    if found is None:
        return None
    n, text = found
    return Match(n, (merge(s.words, i, n, Tag.VERB, text),), expect=False, verb=text)


WATCHING = ("check on", frozenset(["keep an eye on", "keep an eye out for", "keep watch on", "keep watch over",
                                   "keep tabs on", "keep a check on"]))
"""Idioms of keeping watch over something ("*keep an eye on* the soup"), read as the library's unit "check on"
(LookAt: the robot goes and looks at it; it watches no longer than that)."""


def _watching(s: State, i: int) -> Match | None:
    unit, idioms = WATCHING
    n = _longest(s, i, idioms)
    if not n or unit.split()[0] not in s.lexicon.units or not s.np_starts(i + n):
        return None
    return Match(n, (merge(s.words, i, n, Tag.VERB, unit),), expect=False, verb=unit)


def _polite_frame(s: State, i: int) -> Match | None:
    words = s.words
    if not all(t.tag == Tag.POLITE for t in s.out) or s.verb_at(i) is not None or words[i].lower in QUESTION_WORDS:
        return None                     # "what's the thinnest thing *you can* find on the shelf?": a question (words41)
    for j in range(i, min(len(words) - 2, i + 12)):  # "It would be great if you could close ..."
        if words[j].lower in (",", ";") or words[j].lower in END_MARKS:
            break
        n = 1 if words[j + 1].lower in _YOU_MODALS or j > i and words[j - 1].lower == "of" and \
            words[j + 1].lower == "to" else 2 if j + 2 < len(words) and \
            (words[j + 1].lower, words[j + 2].lower) in _YOU_MODALS_TO else 0   # "it'd be kind *of you to*" (words41)
        if words[j].lower == "you" and n and s.verb_after(j + 1 + n):
            return s.emit(i, j + 1 + n - i, Tag.POLITE)
        if j > i and words[j - 1].lower == "if" and _you_would(s, j):
            return s.emit(i, j + 1 - i, Tag.POLITE)
    return None


def _you_would(s: State, j: int) -> bool:
    """Whether "if" and the subject at ``j`` end a polite frame said before it ("it'd be great if *you'd* close
    ...", "it would be nice if *you* closed the hatch": words37): "you'd", or "you" and a verb's past form (the
    past of a wish, no time), before what the verb takes. A frame said first only: "*if you* found the keys, bring
    them" is a condition (the frame needs words before its "if")."""
    words = s.words
    low = words[j].lower
    if low in ("you'd", "u'd"):
        return s.verb_after(j + 1)
    if low != "you" or j + 2 >= len(words):
        return False
    past = words[j + 1].lower
    lemma = verb_lemma(past)
    return lemma is not None and (lemma != past or past in participles(lemma)) and \
        not past.endswith(("ing", "s")) and s.verb_at(j + 1) is not None and \
        (s.np_starts(j + 2) or words[j + 2].lower in PREPOSITIONS)   # "if you *went to* the kitchen"
    # a past the same as the base ("it would help a lot if you *put* the groceries away": words43) is a past too


_IF_YOU_COULD = frozenset(["if you could", "if you would", "if you'd", "if u could", "if you could maybe"])
"""A request said as the condition of a wish left unsaid or said after it ("*if you could* wipe the table, that would
be great", "if you'd close the door"): a past modal, never "can" ("if you can find the keys, bring them": a
condition)."""


def _if_you_could(s: State, i: int) -> Match | None:
    """"*If you could* wipe the kitchen table, that would be great", "if you would close the door": "if", "you" and a
    past modal before a verb of the library, at the start of a sentence, with no clause of the library after a comma
    of its sentence (what follows the comma is a wish, kept as a remark: "that would be great"), is politeness, as
    "could you" is (words43: refused as a statement, "that would be great"). "if you could find the keys, bring
    them to me" stays a condition: a command follows."""
    words = s.words
    if s.out and s.out[-1].tag not in (Tag.POLITE, Tag.SEP):
        return None
    n = _longest(s, i, _IF_YOU_COULD)
    if not n or not s.verb_after(i + n):
        return None
    for k in range(i + n, len(words)):
        low = words[k].lower
        if low in END_MARKS:
            break
        if low in (",", ";") and s.verb_after(k + 1):
            return None                  # "if you could find the keys, *bring* them": a condition and a command
    return s.emit(i, n, Tag.POLITE)


_YOU_MODALS = frozenset(["could", "can", "would", "will", "might", "should", "must"])
"""The modals that end a polite frame after "you" ("if you *could*", "I think you *should*": words33 added
"should" and "must", the hedged advice of "I think you should follow her")."""
_YOU_MODALS_TO = frozenset([("need", "to"), ("have", "to"), ("ought", "to")])
"""Two-word modals that end a polite frame after "you" ("I guess you *need to* ...", words33)."""


COMMA_AFTER_POLITENESS = Rule("comma after politeness", _comma_after_politeness, (
    Example("First, open the fridge", "First,", Tag.POLITE),
), frozenset([",", ";", ":"]), "a comma after politeness, a condition or a separator joins it")
SEQUENCING = Rule("sequencing word", _sequencing, (
    Example("Take the cup to the sink. After that, wash it.", ". After that,", Tag.SEP),
    Example("Next, open the door", "Next,", Tag.POLITE),
), SEP_FIRST, "a sequencing word before the verb")
def _having_first(s: State, i: int) -> Match | None:
    """"*Once you have* the spoon, put it in the dishwasher": to have a thing before a clause is to get it first
    (``HAVING_MEANS``); the subordinator and "you have" are read as that verb, the phrase as its object, and the
    comma or "then" after it joins the clause that follows. "once you have washed it" is a clause of its own, and so
    is a past participle of a verb no frame has ("after you've *fed* the cat": the perfect, a condition; words36)."""
    words = s.words
    subordinators, havings = HAVING_FIRST
    n = _longest(s, i, subordinators)
    m = _longest(s, i + n, havings) if n else 0
    k = i + n + m
    if not m or HAVING_MEANS not in s.lexicon.units or not s.np_starts(k) or s.verb_at(k) is not None or \
            words[k].lower in ("to", "been", "got", "done", "finished") or _past_participle(words[k].lower) or \
            s.formula(i):
        return None                     # "once you have the time": politeness (``TIME_ASKED``)
    end = s.cond_end(k)
    if (end >= len(words) or words[end].lower not in (",", ";", "then", "and") or not s.verb_after(end + 1)) and \
            _run_on_verb(s, k, end) is None:
        return None                     # "once you have the time": no clause follows, or politeness
    last = words[k - 1].end
    return Match(k - i, (Word(s.text_of(words[i].start, last), words[i].start, last, Tag.VERB, HAVING_MEANS),),
                 expect=False, verb=HAVING_MEANS, using=False)


def _past_participle(word: str) -> bool:
    """Whether a word is only a verb's past form, no noun ("fed", "swept", "ironed"; not "left", "spoon"): after
    "you have" it makes the perfect, never the having of a thing."""
    lemma = verb_lemma(word)
    return lemma is not None and lemma != word and word in participles(lemma) and "noun" not in parts_of_speech(word)


HAVING_FIRST_RULE = Rule("having a thing first", _having_first, (
    Example("Once you have the spoon, put it in the dishwasher", "Once you have", Tag.VERB),
    Example("when you've the keys, bring them to me", "when you've", Tag.VERB),
), first_words(HAVING_FIRST[0]), "'once you have X, ...': get X, then the clause")
BEING_AT_RULE = Rule("being somewhere first", _being_at, (
    Example("Once you're in the living room, find Peyton", "Once you're", Tag.VERB),
    Example("when you are at the door, greet the visitor", "when you are", Tag.VERB),
    Example("once youre in the living room look for Skyler", "once youre", Tag.VERB),   # no comma: a run-on
), first_words(BEING_AT[0]), "'once you're in X, ...': go to X, then the clause")
TIME_SAID_FIRST = Rule("a time said first", _time_first, (
    Example("in five minutes turn off the oven", "in five minutes", Tag.POLITE),
    Example("in a couple of minutes, check on the baby", "in a couple of minutes,", Tag.POLITE),
    Example("tonight close all the curtains", "tonight", Tag.POLITE),
    Example("later on, bring me a coffee", "later on,", Tag.POLITE),
    Example("after lunch clean the kitchen counter", "after lunch", Tag.POLITE),
    Example("this afternoon open the windows", "this afternoon", Tag.POLITE),
    Example("every morning, open the curtains", "every morning,", Tag.POLITE),
    Example("three times a week, dust the shelves", "three times a week,", Tag.POLITE),
    Example("from now on, close the back door", "from now on,", Tag.POLITE),
    Example("tonight, feed the cat", "tonight,", Tag.POLITE),     # a verb no frame has: refused at "feed"
), TIME_FIRST | TIME_FIRST_LEAD | frozenset(["this", "in", "at", "from"]) | CLOCK_PREPOSITIONS | FREQUENCY_LEADS |
    TIMES_SAID | frozenset(NUMBERS) | frozenset(str(n) for n in range(2, 13)),
    "a time before the verb ('in five minutes', 'tonight', 'after lunch'): when, kept as the frame's time")
ROOM_HEADING = Rule("a room said as a heading", _room_heading, (
    Example("Garage: fetch the drill", "Garage", Tag.WORD),
    Example("the hallway - count the boxes", "hallway", Tag.WORD),
), None, "a room alone and a colon, dash or stop before the command: where it is done ('in the garage, ...')",
   needs=_HEADING_MARKS)
TASK_HEADING = Rule("the task labelled", _task_heading, (
    Example("Task: go to the porch and fetch the mat", "Task:", Tag.POLITE),
    Example("command - bring me the scissors", "command -", Tag.POLITE),
), _TASK_HEADINGS, "'Task:' or 'Command -' before the command: a label, nothing to do")
REASON_FIRST = Rule("a reason said first", _reason_first, (
    Example("Since you're in the shed anyway, grab the rake", "rake", Tag.WORD),
    Example("now that Sam is here, open the gate", "gate", Tag.WORD),
), frozenset(["since", "now", "seeing", "given", *BECAUSE]), "'since' and a statement, then a comma, before the "
   "command: a reason, kept as a remark")
SUBORDINATE = Rule("subordinate clause first", _subordinate, (
    Example("If the door is open, close it", "If the door is open,", Tag.COND),
    Example("When you reach the kitchen, open the fridge", "When you", Tag.POLITE),
    Example("Go to the kitchen and when you get there, pick up the cup.", "when you get there,", Tag.POLITE),
    Example("go to the kitchen and when you're there look for a cup", "look for", Tag.VERB),
    Example("Go to the kitchen and once there find a cup", "once there", Tag.POLITE),
    Example("when you leave the bedroom, switch off the light", "when you leave the bedroom,", Tag.COND),
    Example("before you leave, turn off the stove", "before you leave,", Tag.COND),
), SUB_FIRST,
   "a condition, or a clause of the robot's own, before the verb (arriving where it went: none; leaving: when)")
ON_THE_WAY = Rule("on the way", _on_the_way, (
    Example("on your way back, pick up the post", "on your way back,", Tag.POLITE),
    Example("on the way to the kitchen, grab a cup", "on the way to the kitchen,", Tag.POLITE),
), _ON_THE_WAY[0], "'on your way back, ...': a circumstance of the trip before the clause, no command of its own")
def _manner_first(low: str) -> bool:
    """Where a manner adverb can start (its rule's gate)."""
    return low.isalpha() and low not in PARTICLES and is_adverb(low)


SUBORDINATE_GERUND = Rule("subordinator before an -ing form", _subordinate_gerund, (
    Example("Before going to the bedroom, grab the towel", "Before", Tag.POLITE),
    Example("before answering her question, meet her at the door", "before", Tag.POLITE),
), _BEFORE_GERUND, "'before V-ing, ...': the subordinator of a clause said first")
MANNER = Rule("manner adverb", _manner, (
    Example("Gently place the eggs in the bowl", "Gently", Tag.POLITE),
), _manner_first, "a manner adverb before the verb")
BE_CAREFUL = Rule("be careful and", _be_careful, (
    Example("Be careful and carry the tray to the table", "Be careful and", Tag.POLITE),
), frozenset(["be"]), "'be careful and', 'be a dear and' before a verb")
START_BY = Rule("start by", _start_by, (
    Example("Start by opening the window", "Start by", Tag.POLITE),
), frozenset(["start", "begin", "finish", "end", "continue"]), "'start by' a gerund of the library")
ASPECT = Rule("keep doing", _aspect, (
    Example("keep following angel until you reach the garage", "keep", Tag.POLITE),
    Example("carry on walking to the end of the hall", "carry on", Tag.POLITE),
    Example("continue to follow her", "continue to", Tag.POLITE),
    Example("mind closing the window?", "mind", Tag.POLITE),
), frozenset(_ASPECTS), "'keep V-ing', 'carry on V-ing', 'continue to V': the verb V, how long it goes on")
LIGHT_VERB = Rule("take a look at", _light_verb, (
    Example("take a quick look at the painting", "take a quick look at", Tag.VERB),
    Example("have a look in the fridge for the butter", "have a look", Tag.VERB),      # the noun's unit, a place after
    Example("take a walk around the garden", "take a walk", Tag.VERB),
), LIGHT_VERBS, "a light verb and a noun that is a lexical unit (with its preposition, or a place)")
WATCHING_RULE = Rule("keep an eye on", _watching, (
    Example("keep an eye on the soup", "keep an eye on", Tag.VERB),
    Example("please keep watch over the baby", "keep watch over", Tag.VERB),
), frozenset(["keep"]), "'keep an eye on X', 'keep watch over X': check on X (LookAt)")
IF_YOU_COULD = Rule("if you could, first", _if_you_could, (
    Example("If you could wipe the kitchen table, that would be great.", "If you could", Tag.POLITE),
    Example("if you'd close the door", "if you'd", Tag.POLITE),
    Example("if you would bring me a towel, thanks", "if you would", Tag.POLITE),
), frozenset(["if"]), "'if you could V X(, that would be great)': a request, politeness before the verb",
    after=frozenset([START, Tag.POLITE, Tag.SEP]))
POLITE_FRAME = Rule("if you could", _polite_frame, (
    Example("It would be great if you could close the door", "It would be great if you could", Tag.POLITE),
    Example("it'd be great if you'd close the door", "it'd be great if you'd", Tag.POLITE),
    Example("it would be nice if you opened the gate", "it would be nice if you", Tag.POLITE),
    Example("It would help a lot if you put the groceries in the fridge", "It would help a lot if you", Tag.POLITE),
    Example("I'd love it if you went to the kitchen", "I'd love it if you", Tag.POLITE),
    Example("I think you should follow her", "I think you should", Tag.POLITE),
    Example("I suppose you need to wash the cup", "I suppose you need to", Tag.POLITE),
    Example("it would be kind of you to open the gate", "it would be kind of you to", Tag.POLITE),
), None, "a polite frame ending in 'you could' before the verb", after=frozenset([START, Tag.POLITE]),
   needs=frozenset(["you", "you'd", "u'd"]))      # the subjects it returns at (itself and _you_would)
