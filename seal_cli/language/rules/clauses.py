"""Clauses and their joints: sentence ends, separators ("and", "then", ","), subordinate clauses
inside a clause, relative clauses, "until the corner", "something to drink"."""

from __future__ import annotations

from seal_cli.language.english import (
    BE_WORDS,
    DONE_BEFORE,
    END_MARKS,
    HERE_WORDS,
    NP_OPENERS,
    PARTICLES,
    PERSON_PRONOUNS,
    POLITE,
    PREPOSITIONS,
    PRONOUNS,
    RELATIVES,
    SEPARATOR_WORDS,
    VERB_JOINTS,
    VERB_TAKES,
)
from seal_cli.language.morphology import (
    in_verb_tables,
    is_adjective,
    noun_lemma,
    participles,
    parts_of_speech,
    verb_lemma,
)
from seal_cli.language.rule import AFTER_SEP, Example, Match, Rule
from seal_cli.language.state import (
    CLOSED,
    INDEFINITE,
    REL_FIRST,
    SEP_FIRST,
    SUB_FIRST,
    State,
    first_words,
    longest_phrase,
    match_phrase,
    merge,
)
from seal_cli.language.tags import Tag
from seal_cli.language.tokens import Word, capitalised
from seal_cli.language.verb_usage import mostly_verb


def _end_mark(s: State, i: int) -> Match | None:
    w = s.words[i]
    if all(r.lower in END_MARKS or r.lower == "please" for r in s.words[i + 1:]):
        return Match(1, (w.tagged(Tag.END),))
    return Match(1, (w.tagged(Tag.SEP),), expect=True)            # "Go to the kitchen. Find Robin."


def _something_to(s: State, i: int) -> Match | None:
    out, words = s.out, s.words
    if out and (out[-1].lower in INDEFINITE or len(out) > 1 and out[-1].tag == Tag.WORD and
                out[-2].lower in INDEFINITE) and i + 1 < len(words) and \
            verb_lemma(words[i + 1].lower) == words[i + 1].lower:
        end = s.relative_end(i + 1)                               # "something to drink"
        return s.emit(i, end - i, Tag.REL)
    return None


def _until_arrival(s: State, i: int) -> Match | None:
    n = s.until_arrival(i)
    return s.emit(i, n, Tag.PREP, "to") if n else None        # "follow him until you reach the patio"


def _for_subject_to(s: State, i: int) -> Match | None:
    """"wait for Alex *to arrive*", "hold the door for the guest to come in": "for" (or a unit ending in it: "wait
    for"), a noun phrase, then "to" and a
    verb is a clause whose subject is the phrase (what they are to do, no clause of the robot's purpose): kept as
    one ``COND`` word, as "until the guest arrives" is. Of a person only ("a plate for an egg to rest on" is
    left as it was)."""
    words, out = s.words, s.out
    if s.verb_index < 0 or i + 1 >= len(words) or not in_verb_tables(words[i + 1].lower) or \
            verb_lemma(words[i + 1].lower) != words[i + 1].lower:
        return None
    k = len(out) - 1
    while k > s.verb_index and out[k].tag in (Tag.DET, Tag.POSS, Tag.NUM, Tag.WORD, Tag.NAME, Tag.PRON):
        k -= 1
    said_for = out[k].tag == Tag.PREP and out[k].info == "for" or k == s.verb_index and out[k].lower.endswith(" for")
    last = out[-1]
    person = last.tag == Tag.NAME or last.tag == Tag.PRON and last.lower in PERSON_PRONOUNS or \
        last.tag == Tag.WORD and noun_lemma(last.lower) in s.lexicon.people
    if k == len(out) - 1 or k < s.verb_index or not said_for or not person or \
            out[k + 1].tag == Tag.PRON and out[k + 1].lower in ("me", "us"):
        return None                       # "fetch a knife for me to cut the bread": what the robot brings it for
    end = s.cond_end(i + 1)
    if words[end - 1].lower in ("and", "but") and end - 1 > i + 1:
        end -= 1                          # "... to come in *and* then greet them": the joint is the clauses'
    return Match(end - i, (merge(words, i, end - i, Tag.COND, "until"),))


def _until_place(s: State, i: int) -> Match | None:
    if s.until_place(i):
        return Match(1, (s.words[i].tagged(Tag.PREP, "to"),))     # "follow me until the gate"
    return None


def _inner(s: State) -> bool:
    return s.prev_tag() not in (Tag.DET, Tag.POSS, Tag.NUM, Tag.PREP)


def _subordinate(s: State, i: int) -> Match | None:
    if s.words[i].lower not in SUB_FIRST or not _inner(s):
        return None
    m = s.subordinate(i, start=False)
    return Match(m.consumed, m.words, expect=AFTER_SEP) if m else None


def _relative(s: State, i: int) -> Match | None:
    if not _inner(s):
        return None
    m = s.relative(i)
    return Match(m.consumed, m.words, expect=AFTER_SEP) if m else None


def _contact_relative(s: State, i: int) -> Match | None:
    """A relative clause with no "that" whose subject is a name ("the book *Tom lent you*", "the question *Ella
    asked*", "the cup *Sam put on the shelf*"): after a common noun, a capitalised word that is no word of the
    library's things, then a verb in its past form (none is the base form of an imperative, so no clause starts
    there). Kept whole as one ``REL`` word the noun keeps, as "the book *I left on the sofa*" is; it used to be
    read as the noun "lent", the rest dropped."""
    words, w = s.words, s.words[i]
    if s.prev_tag() != Tag.WORD or not capitalised(w) or i + 1 >= len(words) or w.lower in s.lexicon.things:
        return None
    verb = words[i + 1].lower
    lemma = verb_lemma(verb)
    if not lemma or verb.endswith("ing") or verb not in participles(lemma):
        return None
    end = s.relative_end(i + 1)
    return s.emit(i, end - i, Tag.REL) if end > i + 1 else None


def _stranded_relative(s: State, i: int) -> Match | None:
    """A relative clause with no "that" whose subject is "it" or "they" and whose preposition is left at its end
    ("the sink *it came from*", "the table *it was on*", "the shelf *they sat on*"): after a common noun, "it" and a
    past form or "was"/"is", up to a preposition ending the clause — kept whole as one ``REL`` word the noun keeps,
    as "the shelf *I took it from*" is (words31: "it" was a phrase no element took, dropped silently)."""
    words = s.words
    if s.prev_tag() != Tag.WORD or i + 2 >= len(words):
        return None
    verb = words[i + 1].lower
    lemma = verb_lemma(verb)
    if verb not in BE_WORDS and (not lemma or verb.endswith("ing") or verb not in participles(lemma)):
        return None
    end = s.relative_end(i + 1)
    if end <= i + 2 or words[end - 1].lower not in PREPOSITIONS or \
            end < len(words) and words[end].lower not in END_MARKS and words[end].lower not in (",", "and", "then"):
        return None                          # only a preposition left over at the clause's end
    return s.emit(i, end - i, Tag.REL)


def _partitive_of(s: State, i: int) -> Match | None:
    out = s.out
    if not out or s.verb_index != len(out) - 1 or out[-1].tag != Tag.VERB or \
            str(out[-1].info).split()[-1] not in ("many", "much"):
        return None
    return Match(1)                   # "how many *of* the people in the hall ...": of them, the people counted


def _particle_between_objects(s: State, i: int) -> Match | None:
    """"bring me *back* the book", "give him back the keys": a particle between the person and the thing of a
    verb that may have a recipient says only the direction; it is dropped (it was read as "bring back" a
    person, Guide). Not a word that may be a preposition ("bring Cell Phones *on* the bed")."""
    if s.words[i].lower in PREPOSITIONS or s.verb_index < 0 or len(s.out) != s.verb_index + 2 or \
            str(s.out[s.verb_index].info) not in s.lexicon.recipients or not s.np_starts(i + 1):
        return None
    person = s.out[-1]
    if not (person.tag == Tag.PRON and person.lower in PERSON_PRONOUNS or person.tag == Tag.NAME):
        return None
    return Match(1)


PARTITIVE_OF = Rule("of after how many", _partitive_of, (
    Example("How many of the people in the bedroom are wearing white jackets?", "of", ""),
), frozenset(["of"]), "'of' right after 'how many' (a unit of counting): the part counted is the phrase after it")


_COMMA_RELATIVES = frozenset(["who", "whom", "whose", "which"])


def _the_one_described(s: State, i: int) -> Match | None:
    """"bring me the mug on the shelf*, the one* that's chipped", "find the man in the hall*, the one* who is
    waving": "the one" set off by a comma after a noun, then a relative clause, names the noun again to describe it
    (words35): the comma and "the one" are dropped, the relative clause describes the noun. After a noun of a
    place phrase ("the man in the hall, the one who is waving") it describes the thing before, not the place: the
    whole of it is a remark then, never the place's."""
    words = s.words
    if i + 3 >= len(words) or words[i + 1].lower != "the" or words[i + 2].lower not in ("one", "ones") or \
            words[i + 3].lower not in RELATIVES or s.verb_index < 0 or s.prev_tag() not in (Tag.NAME, Tag.WORD):
        return None
    if any(w.tag == Tag.PREP for w in s.out[s.verb_index + 1:]):
        end = s.cond_end(i + 1)
        return Match(end - i, remarks=((words[i + 1].start, words[end - 1].end),))
    return Match(3)


def _comma_relative(s: State, i: int) -> Match | None:
    """A relative clause set off by a comma after a name or a noun ("take it to Adel*, who's in the bathroom*"):
    it describes the noun as one without the comma does, and asks nothing (no question to tell)."""
    words = s.words
    if i + 2 >= len(words) or words[i + 1].lower not in _COMMA_RELATIVES or s.verb_index < 0 or \
            s.prev_tag() not in (Tag.NAME, Tag.WORD):
        return None
    m = s.relative(i + 1, described=s.speech and _said_before_person(s))
    return Match(1 + m.consumed, m.words, expect=AFTER_SEP) if m else None


def _relative_closed(s: State, i: int) -> Match | None:
    """"give Adel*, who's in the office,* a plum": the comma that closes a relative clause set off by commas after
    the person, before the thing given, is no joint: it is dropped, and the thing is the second object, as in "give
    Adel who's in the office a plum" (words42: the comma joined "the office" and "a plum" as one list, the
    recipient's). Only in a clause whose verb gives to someone (not a verb of saying), with nothing but the relative
    clause and its phrases after the person, and a noun phrase with a determiner next."""
    if s.verb_index < 0:
        return None
    unit = str(s.out[s.verb_index].info)
    if unit not in s.lexicon.recipients or unit in s.lexicon.speech or s.next_lower(i) not in NP_OPENERS:
        return None
    after = s.out[s.verb_index + 1:]
    rel = next((k for k, w in enumerate(after) if w.tag == Tag.REL), -1)
    if rel < 1 or after[rel - 1].tag not in (Tag.NAME, Tag.WORD) or \
            "," not in s.text_of(after[rel - 1].end, after[rel].start) or \
            any(w.tag not in (Tag.PREP, Tag.DET, Tag.POSS, Tag.WORD, Tag.NAME, Tag.NUM) for w in after[rel + 1:]):
        return None
    return Match(1)


def _said_before_person(s: State) -> bool:
    """Whether a verb of speech has its message (or question) before the person ("answer *a question* for Morgan",
    "tell *the time* to Jo"): a comma's "who ..." after the person then describes them (words35), nothing more said."""
    after = s.out[s.verb_index + 1:]
    first = next((k for k, w in enumerate(after) if w.tag == Tag.PREP), -1)
    return first > 0 and after[-1].tag in (Tag.NAME, Tag.WORD) and any(w.tag == Tag.WORD for w in after[:first])


def _separator(s: State, i: int) -> Match | None:
    n = match_phrase(s.words, i, SEPARATOR_WORDS)
    m = s.separator(i, n) if n else None
    return Match(m.consumed, m.words, expect=AFTER_SEP) if m else None


END_MARK = Rule("sentence end", _end_mark, (
    Example("Go to the kitchen. Find Robin.", ".", Tag.SEP),
    Example("close the door!", "!", Tag.END),
), END_MARKS, "'.', '!', '?': the end of the command, or between two sentences of it")
PARTICLE_BETWEEN_OBJECTS = Rule("particle between the objects", _particle_between_objects, (
    Example("bring me back the book", "back", ""),
), PARTICLES, "'bring me back X': the particle between the person and the thing, dropped")
SOMETHING_TO = Rule("something to V", _something_to, (
    Example("bring me something to drink", "to drink", Tag.REL),
), frozenset(["to"]), "'to' and a verb after an indefinite pronoun: what it is for, kept whole")
UNTIL_ARRIVAL = Rule("until you reach a place", _until_arrival, (
    Example("follow the man in blue until you reach the patio", "until you reach", Tag.PREP),
    Example("lead Jo till we get to the exit", "till we get to", Tag.PREP),
), frozenset(["until", "till"]), "'until you reach/get to/arrive at' a noun phrase after a verb of motion: how far")
FOR_SUBJECT_TO = Rule("for X to V", _for_subject_to, (
    Example("go to the kitchen and wait for alex to arrive", "to arrive", Tag.COND),
    Example("wait at the door for the guest to come in", "to come in", Tag.COND),
), frozenset(["to"]), "'for X to V': X is to do V (kept as a condition), no clause of the robot's purpose")
UNTIL_PLACE = Rule("until a place", _until_place, (
    Example("follow me until the gate", "until", Tag.PREP),
), frozenset(["until", "till"]), "'until' a noun phrase after a verb of motion: how far")
SUBORDINATE_INSIDE = Rule("subordinate clause", _subordinate, (
    Example("turn off the stove when the water boils", "when the water boils", Tag.COND),
    Example("turn off the stove before you leave", "before you leave", Tag.COND),
    Example("turn off the stove when you leave the kitchen", "when you leave the kitchen", Tag.COND),
), SUB_FIRST | REL_FIRST, "a subordinate clause inside a clause: a condition, or a clause of the robot's own")
RELATIVE = Rule("relative clause", _relative, (
    Example("bring me the glass that I was drinking from", "that I was drinking from", Tag.REL),
    Example("put the cup you just washed on the shelf", "you just washed", Tag.REL),        # words38: an adverb
    Example("put the cup where it belongs", "where it belongs", Tag.HERE),
    Example("put the box that has a candle in it on the shelf", "that has", Tag.PREP),       # "with" (alfred23)
    Example("set down the tray which holds two cups on it", "which holds", Tag.PREP),
    Example("move the crate that contains the lemons to the porch", "that contains", Tag.VBG_T),  # "containing"
    Example("bring me the cup that has a chip", "that has a chip", Tag.REL),
), SUB_FIRST | REL_FIRST, "a relative clause after a noun, kept whole (or 'that is' dropped; 'that has X in it': "
   "'with X in it')")
CONTACT_RELATIVE = Rule("relative clause of a name, no that", _contact_relative, (
    Example("give me the book Tom lent you", "Tom lent you", Tag.REL),
    Example("bring me the note Ella wrote", "Ella wrote", Tag.REL),     # words46: "the question Ella asked": hers
    Example("bring me the mug Sam left on the sofa", "Sam left", Tag.REL),
), lambda low: low.isalpha() and low not in CLOSED, "a name and a past verb after a noun: a relative clause "
   "without 'that'", after=frozenset([Tag.WORD]))
STRANDED_RELATIVE = Rule("relative clause of it, its preposition last", _stranded_relative, (
    Example("put the mug back on the shelf it came from", "it came from", Tag.REL),
    Example("leave the jar on the table it was on", "it was on", Tag.REL),
), frozenset(["it", "they"]), "'it' and a past verb after a noun, its preposition ending the clause: a relative "
   "clause without 'that'")
THE_ONE_DESCRIBED = Rule("', the one' and a relative clause after a noun", _the_one_described, (
    Example("bring me the mug, the one that is chipped", "that is chipped", Tag.REL),
    Example("find the man, the one who is waving", "waving", Tag.VBG_I),
    Example("find the man in the hall, the one who is waving. then greet him", "greet", Tag.VERB),
), frozenset([","]), "', the one that ...' after a noun: the noun described again, 'the one' dropped")
COMMA_RELATIVE = Rule("relative clause after a comma", _comma_relative, (
    Example("take it to Adel, who's in the bathroom.", "who's", Tag.REL),
    Example("give the cup to the man, who is sitting on the sofa", "sitting", Tag.VBG_P),
    Example("tell the joke to Priya, who is in the den", "who is", Tag.REL),
), frozenset([","]), "', who is ...' after a name or a noun: a relative clause describing it, not a question")
RELATIVE_CLOSED = Rule("a relative clause's closing comma", _relative_closed, (
    Example("give Adel, who's in the office, a plum", ",", ""),
), frozenset([","]), "', who is in X,' between the person given to and the thing: the closing comma, dropped",
   after=frozenset([Tag.WORD, Tag.NAME, Tag.NUM]))
SEPARATOR = Rule("separator", _separator, (
    Example("take the cup and put it on the table", "and", Tag.SEP),
    Example("put the cup and the plate on the table", "and", Tag.AND_NP),
), SEP_FIRST, "'and', ',', 'then', ... joining clauses or noun phrases")


_OBJECT_STARTS = frozenset(["it", "them", "him", "her", "me", "us", "everyone", "everybody", "someone", "somebody",
                            "anyone", "anybody", "everything", "something"])
"""Pronouns that open the object of a verb said without a joint ("... in the hall *greet everyone* there": words42
added the indefinite ones)."""


_FREE_PLACES = frozenset(["wherever", "anywhere", "everywhere"])
"""Words that open a free relative of place ("follow him *wherever* he goes")."""
_FREE_SUBJECTS = frozenset(["he", "she", "they", "it", "i", "we"])


def _wherever(s: State, i: int) -> Match | None:
    """"follow him *wherever he goes*", "follow Jo everywhere she walks": a free relative of place, a subject and its
    verb, after a clause with its object says where the robot follows, which the frame says already: a remark
    (words42: "he" was a pronoun no element took). Only up to the clause's end, with no verb of the library's base
    form in it after the subject's own ("wherever he goes, bring a cup" keeps its command)."""
    words = s.words
    if s.verb_index < 0 or s.prev_tag() not in (Tag.WORD, Tag.NAME, Tag.PRON) or i + 2 >= len(words) or \
            words[i + 1].lower not in _FREE_SUBJECTS:
        return None
    end = s.cond_end(i + 1)
    if end < i + 3 or any(s.verb_at(k) is not None and verb_lemma(words[k].lower) == words[k].lower and
                          not _wished_by_subject(words, k) for k in range(i + 3, end)):
        return None
    return Match(end - i, remarks=((words[i].start, words[end - 1].end),))


_WISHING = frozenset(["want", "need", "like", "wish", "have", "plan", "choose", "decide"])
"""Lemmas of the verbs whose "to" and base form say what the free relative's subject wishes ("wherever she *wants to
go*"): the subject's verb, not the robot's."""


def _wished_by_subject(words: list[Word], k: int) -> bool:
    """Whether the base form at ``k`` follows "to" after a verb of wishing ("wherever he wants *to go*", words46: it
    was read as a command of its own and the free relative refused)."""
    return k >= 2 and words[k - 1].lower == "to" and verb_lemma(words[k - 2].lower) in _WISHING


def _unjoined(s: State, i: int) -> Match | None:
    """A verb of the library in its base form right after a phrase, before its own object ("meet Jo at the
    counter *escort her* back", "pick up the cup *bring it* to me"): a new clause said without "and"."""
    words = s.words
    if s.verb_index < 0 or s.prev_tag() not in (Tag.WORD, Tag.NAME, Tag.PRON, Tag.LABEL, Tag.PARTICLE, Tag.HERE):
        return None
    if words[i].lower not in s.lexicon.units:
        return None                       # only a verb's base form starts a command
    found = s.verb_at(i)
    if found is None or found[2] is not None or words[i].lower != found[0].split()[0]:
        return None
    unit = found[0]
    after = i + found[1]
    if after >= len(words):
        return None
    nxt = words[after]
    n = match_phrase(words, after, PREPOSITIONS)
    path = n > 0 and unit in s.lexicon.goals and words[i].lower not in s.lexicon.things and \
        not is_adjective(s.out[-1].lower) and s.np_starts(after + n)   # not "a different *place* on the counter"
    if not (nxt.lower in _OBJECT_STARTS or nxt.lower in NP_OPENERS or
            capitalised(nxt) and nxt.lower not in CLOSED or path):
        return None                       # "put it in the fridge *go to* the kitchen": a verb of motion and its path
    if nxt.lower in ("that", "this", "these", "those") and not s.noun_follows(after + 1):
        return None                       # "a potato slice *that is* on a plate": a relative clause
    w = words[i]
    return Match(found[1], (Word("", w.start, w.start, Tag.SEP), merge(words, i, found[1], Tag.VERB, unit)),
                 expect=False, verb=unit, using=False)


def _done_before(s: State, i: int) -> Match | None:
    """A joint that says the clauses after it come first ("give me the cereal; *before that*, go to the table",
    "bring me the cup, *but first* rinse it"): one ``SEP`` word whose info is the phrase (``english.DONE_BEFORE``),
    replacing a separator said just before it; ``Clauses.order`` moves its clauses before the one said before."""
    words = s.words
    n = longest_phrase(words, i, DONE_BEFORE)
    if not n or s.verb_index < 0:
        return None
    j = i + n + int(i + n < len(words) and words[i + n].lower == ",")
    k = j if j >= len(words) or s.verb_at(j) is not None else j + match_phrase(words, j, POLITE)
    if k >= len(words) or s.verb_at(k) is None or verb_lemma(words[k].lower) != words[k].lower:
        return None                       # "put it away before that gets cold": a condition, no joint
    if s.prev_tag() not in (Tag.SEP, Tag.AND_NP) and words[i].lower != "but" and words[j - 1].lower != ",":
        return None                       # "before that" said bare inside a clause: left to the other rules
    phrase = " ".join(w.lower for w in words[i:i + n])
    prev = s.out[-1] if s.out else None
    joined = prev is not None and prev.tag in (Tag.SEP, Tag.AND_NP)     # "..., but first": the comma is the joint
    start = prev.start if prev is not None and joined else words[i].start
    joint = Word(s.text_of(start, words[j - 1].end) or phrase, start, words[j - 1].end, Tag.SEP, phrase)
    if joined:
        return Match(j - i, (), last=joint, expect=True)
    return Match(j - i, (joint,), expect=True)


_NAME_ENDS = frozenset(["and", ",", ".", "!", "?", ";", "then"])


def _person_verb_unjoined(s: State, i: int) -> Match | None:
    """A verb whose first element only a person fills ("meet", "greet", "follow": ``Lexicon.people_only``), in
    its base form right after a phrase, then one lower-case word that names nothing the library knows, that
    English's word tables list as no part of speech (``morphology.parts_of_speech``: a name), and ends the
    clause ("go to the bathtub *meet tracy* and guide her", "wait by the door greet jo."): the word is the
    person's name said in lower case, and the verb a clause of its own said without "and" (it was read as
    part of the place, "the bathtub meet tracy", and Meet was lost). A word the library knows ("follow the
    *guest*") or a closed-class word is left to ``UNJOINED``."""
    words = s.words
    if s.verb_index < 0 or s.prev_tag() not in (Tag.WORD, Tag.NAME, Tag.LABEL, Tag.HERE):
        return None
    low = words[i].lower
    if low not in s.lexicon.people_only or low not in s.lexicon.units:
        return None
    found = s.verb_at(i)
    if found is None or found[2] is not None or found[1] != 1 or found[0] != low:
        return None
    after = i + 1
    if after >= len(words):
        return None
    nxt = words[after].lower
    if capitalised(words[after]) or not nxt.isalpha() or nxt in CLOSED or nxt in s.lexicon.things or \
            nxt in s.lexicon.units or is_adjective(nxt) or parts_of_speech(nxt):
        return None                       # "the swim meet *area*": a word of English's tables, no name
    if after + 1 < len(words) and words[after + 1].lower not in _NAME_ENDS and \
            not match_phrase(words, after + 1, PREPOSITIONS):
        return None                       # "the swim meet schedule": a noun goes on
    w = words[i]
    return Match(1, (Word("", w.start, w.start, Tag.SEP), merge(words, i, 1, Tag.VERB, low)),
                 expect=False, verb=low, using=False)


_NO_NOUN_AFTER = frozenset(["it", "them", "him", "her"])
"""Object pronouns, which never go on a noun phrase: a verb's object ("grab the towel *fold it* on the rack")."""


_SPEAKER_OBJECTS = frozenset(["me", "us"])
_VERB_OR_NOUN = frozenset(["verb", "noun"])
"""Who speaks, as an object: after a verb of going and a verb's base form, that verb's ("come *help* me")."""


def _going_only(s: State, unit: str) -> bool:
    """Whether a unit is of going only: its frames have a goal, and none has a recipient or puts a thing ("go",
    "come", "head"; not "take", "bring", "put")."""
    return unit in s.lexicon.goals and unit not in s.lexicon.recipients and unit not in s.lexicon.puts


def _unknown_unjoined(s: State, i: int) -> Match | None:
    """A verb's base form that no frame lists, right after a phrase and before an object pronoun ("grab the towel
    *fold it* on the rack"), or after "to" and before its object ("head to the bedroom *to wake up* Jonas"): a clause
    of its own, so its unknown verb is reported, not read as a noun of the phrase (the verb was lost)."""
    words = s.words
    to = words[i].lower == "to"
    if s.verb_index >= 0 and not to and i + 1 < len(words) and s.prev_tag() == Tag.VERB and \
            words[i + 1].lower in PREPOSITIONS and _going_only(s, str(s.out[s.verb_index].info)):
        if capitalised(words[i]):
            return None                 # "guide *Jack* to the kitchen": a capital inside the sentence is a name (e2e33)
        low = words[i].lower            # "go *chat* with the person": a verb no frame lists, then its preposition
        if verb_lemma(low) == low and s.verb_at(i) is None and low not in CLOSED and low not in s.lexicon.things and \
                "verb" in parts_of_speech(low) and parts_of_speech(low) <= _VERB_OR_NOUN:
            return Match(0, (Word("", words[i].start, words[i].start, Tag.SEP),), expect=True)   # words42: it was
        return None                     # Go's goal ("chat with the person"), the verb lost silently
    if s.verb_index < 0 or not to and (i + 1 >= len(words) or words[i + 1].lower not in _NO_NOUN_AFTER and
                                       words[i + 1].lower not in _SPEAKER_OBJECTS and
                                       words[i + 1].lower not in NP_OPENERS):
        return None
    if not to and s.prev_tag() == Tag.VERB and _going_only(s, str(s.out[s.verb_index].info)):
        if capitalised(words[i]):
            return None                 # "show *Jack* the way to ...": a name, as after "to" (e2e33)
        low = words[i].lower            # "go *see* them": a verb of going, then another verb's own clause
        if verb_lemma(low) == low and s.verb_at(i) is None and low not in CLOSED and low not in s.lexicon.things and \
                (words[i + 1].lower not in NP_OPENERS or parts_of_speech(low) <= _VERB_OR_NOUN):
            return Match(0, (Word("", words[i].start, words[i].start, Tag.SEP),), expect=True)
        return None             # "go *round* the corner": an adverb or adjective too, a path
    if s.prev_tag() not in (Tag.WORD, Tag.NAME, Tag.PRON, Tag.LABEL, Tag.PARTICLE, Tag.HERE) or \
            not to and not _unknown_before_object(words[i].lower, words[i + 1].lower):
        return None
    k = i + 1 if to else i
    if k + 1 >= len(words):
        return None
    verb, nxt = words[k].lower, words[k + 1]
    if verb_lemma(verb) != verb or verb in s.lexicon.units or verb in CLOSED or verb in s.lexicon.things or \
            to and capitalised(words[k]):
        return None                       # "a blanket to *Grace* in the lounge": a capital after "to" is a name
    if to and not (nxt.lower in PARTICLES or nxt.lower in NP_OPENERS or nxt.lower in _SPEAKER_OBJECTS or
                   nxt.lower in _NO_NOUN_AFTER or capitalised(nxt) and nxt.lower not in CLOSED):
        return None                       # "come to the kitchen *to help me*" (words30: the goal was "the kitchen
        #                                   to help", "me" dropped)
    if to:
        return Match(1, (words[i].tagged(Tag.SEP),), expect=True)
    return Match(0, (Word("", words[i].start, words[i].start, Tag.SEP),), expect=True)


def _unknown_before_object(verb: str, nxt: str) -> bool:
    """Whether a word no frame lists, after a phrase, is a verb before its object: an object pronoun follows ("grab
    the towel *fold it*"), or a determiner follows a word English uses as a verb only or mostly (``parts_of_speech``,
    ``mostly_verb``: "open the door *let the* cat out" was Open of "the door let", the clause dropped; words30).
    "the door *handle the* ..." would take a noun that is mostly one."""
    if nxt in _NO_NOUN_AFTER:
        return True
    return nxt in NP_OPENERS and (parts_of_speech(verb) == _VERB_ONLY or mostly_verb(verb))


_VERB_ONLY = frozenset(["verb"])


def _particle_verb(s: State, j: int) -> bool:
    """Whether the word at ``j`` is a verb of English said with a particle that ends the clause or comes before an
    object ("and *tidy up*", "and tidy up the toys"): a phrasal verb, though the word is mostly an adjective."""
    words = s.words
    k = j + 1
    if k >= len(words) or words[k].lower not in PARTICLES or not in_verb_tables(words[j].lower):
        return False
    if k + 1 >= len(words) or words[k + 1].lower in END_MARKS or match_phrase(words, k + 1, SEPARATOR_WORDS):
        return True
    return words[k].lower in _OBJECT_PARTICLES and (words[k + 1].lower in NP_OPENERS or words[k + 1].lower in PRONOUNS)


_OBJECT_PARTICLES = frozenset(["up", "out", "away", "aside"])
"""Particles said before a verb's object that are no preposition of a place the object is at ("tidy *up* the toys";
"put a cup and pen *on* the desk": where the pen goes)."""


def _verb_after_joint(s: State, i: int) -> Match | None:
    """After "and", "then" or "," inside a clause, a bare word (no determiner) that is mostly used as a verb, in its
    base form, and names no thing the library knows, before what a verb takes (a determiner, a pronoun, "here" or
    "there", "please", a preposition or a particle, or the end of the command): a clause of its own ("go to the
    kitchen and *sleep* there", "take the cup and *dance*"), so its verb is a frame's or reported as unknown, never
    read as a noun of a list ("bring the cup and *plate*", "the salt and *pepper*"). A verb said with a particle
    ending the clause is one though mostly an adjective ("head back to the kitchen and *tidy up*")."""
    words = s.words
    n = match_phrase(words, i, SEPARATOR_WORDS)
    if not n or s.verb_index < 0 or s.prev_tag() not in (Tag.WORD, Tag.NAME, Tag.PRON, Tag.HERE, Tag.PARTICLE):
        return None
    j = i + n
    while j < len(words) and match_phrase(words, j, SEPARATOR_WORDS):
        j += match_phrase(words, j, SEPARATOR_WORDS)
    if j >= len(words) or not all(w.lower in VERB_JOINTS for w in words[i:j]):
        return None
    w = words[j]
    low = w.lower
    if not low.isalpha() or capitalised(w) or low in CLOSED or low in s.lexicon.things or verb_lemma(low) != low or \
            not (mostly_verb(low) or _particle_verb(s, j)) or s.verb_after(j):
        return None                       # a verb of the library: the separator's ("and *put* it on the table")
    k = j + 1
    if not (k >= len(words) or words[k].lower in VERB_TAKES or match_phrase(words, k, HERE_WORDS) or
            match_phrase(words, k, PREPOSITIONS)):
        return None
    return Match(j - i, (merge(words, i, j - i, Tag.SEP),), expect=True)


VERB_AFTER_JOINT = Rule("verb after a joint", _verb_after_joint, (
    Example("go to the kitchen and sleep there", "sleep", Tag.WORD),
    Example("take the cup and dance", "dance", Tag.WORD),
    Example("grab the towel, and kneel down", "kneel", Tag.WORD),
    Example("go to the sofa and sit", "sit", Tag.WORD),
    Example("grab the mug then sit down", "sit", Tag.WORD),
    Example("head back to the kitchen and tidy up", "tidy", Tag.WORD),
), frozenset(VERB_JOINTS), "a bare word mostly used as a verb after 'and', 'then' or ',', before what a verb takes: "
   "a clause of its own, not a noun of a list", after=frozenset([Tag.WORD, Tag.NAME, Tag.PRON, Tag.HERE, Tag.PARTICLE]))
WHEREVER = Rule("wherever they go", _wherever, (
    Example("follow him wherever he goes", "wherever", ""),
    Example("stay with Jo everywhere she walks", "everywhere", ""),
    Example("follow Noor wherever she wants to go", "wherever", ""),
), _FREE_PLACES, "'wherever he goes' after a clause: a free relative of place, a remark",
   after=frozenset([Tag.WORD, Tag.NAME, Tag.PRON]))
UNJOINED = Rule("clause without a joint", _unjoined, (
    Example("meet Jo at the counter escort her back", "escort", Tag.VERB),
    Example("pick up the cup bring it to me", "bring", Tag.VERB),
    Example("put the milk in the fridge go to the kitchen", "go", Tag.VERB),
), None, "a verb of the library and its object right after a phrase: a clause of its own, not a noun",
   after=frozenset([Tag.WORD, Tag.NAME, Tag.PRON, Tag.LABEL, Tag.PARTICLE, Tag.HERE]))
DONE_BEFORE_JOINT = Rule("a joint that puts what follows first", _done_before, (
    Example("hand me the towel, but first wash it", ", but first", Tag.SEP),
    Example("give me the plate, but before that go to the sink", ", but before that", Tag.SEP),
), first_words(DONE_BEFORE), "'before that', 'but first' between clauses: what follows is done first")
DONE_BEFORE_START = Rule("a joint that puts what follows first, a clause expected", _done_before, (
    Example("bring me the cup. Before that, rinse it", ". Before that,", Tag.SEP),
    Example("bring me the cup; before that, rinse it", "; before that,", Tag.SEP),
), first_words(DONE_BEFORE), "'before that' where a clause starts, after a sentence: what follows is done first")
PERSON_VERB_UNJOINED = Rule("a person's verb and a lower-case name without a joint", _person_verb_unjoined, (
    Example("go to the bathtub meet tracy and guide her", "meet", Tag.VERB),
    Example("wait by the front door greet jo.", "greet", Tag.VERB),
    Example("walk to the porch follow sam to the car", "follow", Tag.VERB),
), None, "'meet/greet/follow' and one lower-case word ending the clause after a phrase: a clause, the word a name",
   after=frozenset([Tag.WORD, Tag.NAME, Tag.LABEL, Tag.HERE]))
def _unknown_verb_first(low: str) -> bool:
    """Where an unknown verb without a joint can start (its rule's gate): "to", or a verb's base form."""
    return low == "to" or low not in CLOSED and verb_lemma(low) == low


UNKNOWN_UNJOINED = Rule("unknown verb without a joint", _unknown_unjoined, (
    Example("grab the towel fold it on the rack", "fold", Tag.WORD),
    Example("head to the bedroom to wake up Jonas", "to", Tag.SEP),
    Example("the person in the hall needs help, go see them", "see", Tag.WORD),
    Example("come help me", "help", Tag.WORD),
    Example("go feed the cat", "feed", Tag.WORD),
    Example("go chat with the guard", "chat", Tag.WORD),                  # words42: a preposition after it
    Example("open the door let the cat out", "let", Tag.WORD),
    Example("come to the kitchen to help me", "to", Tag.SEP),
), _unknown_verb_first, "a verb no frame lists before its object, after a phrase: a clause of its own",
   after=frozenset([Tag.VERB, Tag.WORD, Tag.NAME, Tag.PRON, Tag.LABEL, Tag.PARTICLE, Tag.HERE]))
