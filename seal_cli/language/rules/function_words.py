"""Function words inside a clause: time adverbials, "one" after adjectives, "that" opening
reported speech, "of", "here"/"there", prepositions, particles, wh-words, "is", possessives,
partitives, determiners, pronouns (closed classes: :mod:`seal_cli.language.english`)."""

from __future__ import annotations

from seal_cli.language.asking import ASKING, IFS
from seal_cli.language.english import (
    BE_WORDS,
    CLOCK_PREPOSITIONS,
    DEMONSTRATIVES,
    DETERMINERS,
    END_MARKS,
    ENDS,
    HERE_WORDS,
    NP_OPENERS,
    NUMBERS,
    OBJECT_PARTICLES,
    ORDINALS,
    PARTICLES,
    PARTITIVES,
    POSSESSIVES,
    PREPOSITIONS,
    PRONOUNS,
    REGIONS,
    SIDES,
    TIME_MEASURE,
    TIME_UNITS,
    TIME_WORDS,
    WH_WORDS,
)
from seal_cli.language.morphology import noun_lemma, parts_of_speech, verb_lemma
from seal_cli.language.premises import is_premises
from seal_cli.language.rule import Example, Match, Rule
from seal_cli.language.state import CLOSED, IN_NP, TIME_FIRST, State, first_words, match_phrase, merge
from seal_cli.language.tags import Tag
from seal_cli.language.tokens import Word

HOME = "home"
"""An adverb of direction said after the thing moved, ending the clause ("bring him *home*"); a noun elsewhere ("go
home" is Go's goal either way, "the home office")."""
_HERE_FIRST = first_words(HERE_WORDS) | {HOME}
_PREP_FIRST = first_words(PREPOSITIONS)


def _time_word(s: State, i: int) -> Match | None:
    if s.in_np():
        return None
    n = match_phrase(s.words, i, TIME_WORDS)
    if n and s.next_lower(i + n - 1) == "'s":
        return None                                               # "today's date": whose, not when
    if n and (s.words[i].lower != "first" or s.prev_tag() not in (Tag.VERB, Tag.PREP)):
        return s.emit(i, n, Tag.PARTICLE, "time")                 # "put it in the fridge right away"
    return None


def _for_a_time(s: State, i: int) -> Match | None:
    words = s.words
    if s.in_np() or s.prev_tag() in (Tag.VERB, Tag.PREP):
        return None
    k = i + 1                                                     # "for three minutes", "every few minutes"
    while k < len(words) and (words[k].lower in TIME_MEASURE or words[k].lower in NUMBERS
                              or words[k].lower.isdigit()):
        k += 1
    if k < len(words) and words[k].lower in TIME_UNITS:
        return s.emit(i, k + 1 - i, Tag.PARTICLE, "time")
    return None


def _clock_time(s: State, i: int) -> Match | None:
    if s.in_np() or s.prev_tag() == Tag.PREP:
        return None
    n = s.clock_time(i)
    return s.emit(i, n, Tag.PARTICLE, "time") if n else None     # "meet her at three", "in ten minutes"


def _one(s: State, i: int) -> Match | None:
    if s.out and s.prev_tag() == Tag.PRON and s.out[-1].lower in DEMONSTRATIVES and not s.in_np():
        return Match(1, (s.words[i].tagged(Tag.WORD),), last=s.out[-1].tagged(Tag.DET))   # "bring me *this one*"
    if s.in_np() or s.prev_tag() not in (Tag.WORD, Tag.RESULT):
        return None
    k = len(s.out) - 1
    while k >= 0 and s.out[k].tag in (Tag.WORD, Tag.RESULT):
        k -= 1
    if k >= 0 and s.out[k].tag in (Tag.DET, Tag.POSS, Tag.NUM):
        return s.emit(i, 1, Tag.WORD)                             # "the red one"
    if s.words[i].lower == "ones" and k < len(s.out) - 1 and (k < 0 or s.out[k].tag in (Tag.VERB, Tag.PRON, Tag.PREP)):
        return s.emit(i, 1, Tag.WORD)                             # "bring me new ones": a bare plural (words29)
    return None


def _that_said(s: State, i: int) -> Match | None:
    words = s.words
    if s.in_np() or not s.speech or s.prev_tag() not in (Tag.WORD, Tag.NAME, Tag.PRON, Tag.LABEL) or \
            not (s.np_starts(i + 1) or s.next_lower(i) == ","):
        return None
    start = i + 1                                                 # "tell the guest *that* dinner is ready":
    while start < len(words) and words[start].lower == ",":      # what is said is any clause, kept whole
        start += 1                                                # "tell her that, if it rains, ..."
    end = s.speech_end(start)
    that = words[i].tagged(Tag.WH)
    if end > start:
        return Match(end - i, (that, s.emit(start, end - start, Tag.SAID).words[0]))
    return Match(start - i, (that,))


def _if_asked(s: State, i: int) -> Match | None:
    """"ask Raj *if* he wants tea": after the person a verb of asking asks, "if"/"whether" and the question, which
    is kept whole (as what is said after "that"): "ask Priya if she can come to the garage" is not a clause "come to
    the garage" of the command's own."""
    words = s.words
    if s.in_np() or not s.speech or s.verb_index < 0 or str(s.out[s.verb_index].info) not in ASKING or \
            s.prev_tag() not in (Tag.WORD, Tag.NAME, Tag.PRON, Tag.LABEL) or i + 1 >= len(words):
        return None
    end = s.speech_end(i + 1)
    if end <= i + 1:
        return None
    return Match(end - i, (words[i].tagged(Tag.WH), s.emit(i + 1, end - i - 1, Tag.SAID).words[0]))


def _alternatives_told(s: State, i: int) -> Match | None:
    """"tell Anna *whether* the guy is sitting or standing", "let the guest know if the taxi is here or still on its
    way": after the person a verb of saying tells (any unit that says something, not only a verb of asking), a
    reported question that offers alternatives joined by "or" is what is told, kept whole as a question put to
    a person is (:data:`IF_ASKED`); read as the command's own clause its "or" joins nothing the grammar knows.
    Without "or" the told clause is read as before ("tell Anna whether the door is open")."""
    words = s.words
    if s.in_np() or not s.speech or s.verb_index < 0 or \
            s.prev_tag() not in (Tag.WORD, Tag.NAME, Tag.PRON, Tag.LABEL) or i + 1 >= len(words):
        return None
    end = s.speech_end(i + 1)
    if end - (i + 1) < 3 or not any(w.lower == "or" for w in words[i + 2:end - 1]):
        return None
    return Match(end - i, (words[i].tagged(Tag.WH), s.emit(i + 1, end - i - 1, Tag.SAID).words[0]))


def _particle_noun(s: State, i: int) -> Match | None:
    if s.next_lower(i) == "of" and match_phrase(s.words, i, PREPOSITIONS) < 2:
        return s.emit(i, 1, Tag.WORD)                             # "the back of the toilet"
    return None


_COMPOUND_PARTICLES = frozenset(["out", "up", "down", "away", "back"])
"""Particles that make a modifier of a verb before a noun ("the pull-out drawer", "a pop-up toaster", "the fold-down
table"); the particles that are also prepositions of place ("in", "on", "off", "over") are left out: "put the pan
*in* sink" keeps its place."""


def _compound_modifier(s: State, i: int) -> Match | None:
    """"the *pull out* drawer", "a *fold down* table", "the *pop up* toaster": a verb's base form and a particle after
    a determiner, a possessive or a number, right before a noun (no adjective or adverb: "turn the heat up *high*"),
    is a modifier of that noun, written apart as it is often said ("pull-out"), not the clause's particle (words32:
    "out" ended the phrase and "drawer" was left over)."""
    words, out = s.words, s.out
    if len(out) < 2 or out[-1].tag != Tag.WORD or out[-2].tag not in (Tag.DET, Tag.POSS, Tag.NUM) or \
            words[i].lower not in _COMPOUND_PARTICLES or i + 1 >= len(words):
        return None
    verb, noun = out[-1].text.lower(), words[i + 1].lower
    kinds = parts_of_speech(noun)
    if verb_lemma(verb) != verb or "noun" not in kinds or kinds & {"adj", "adv"} or noun in CLOSED or \
            noun in TIME_WORDS:
        return None
    return s.emit(i, 1, Tag.WORD)


_BEFORE_A_NUMBER = ORDINALS | frozenset(["next", "other", "remaining", "final", "same"])
"""Words that order things and may come between a determiner and a number ("the *last* two plates", "the *other*
three cups")."""


def _ordinal_before_number(s: State, i: int) -> Match | None:
    """"the *last* two plates", "my *first* three books": an ordinal between a determiner and a number, before a
    noun, opens the counted phrase with its determiner (one noun phrase: two plates, the last of them), never a
    phrase of its own ("the last" as the theme, "two plates" lost)."""
    words = s.words
    if s.prev_tag() not in (Tag.DET, Tag.POSS) or i + 2 >= len(words) or \
            match_phrase(words, i + 1, NUMBERS) == 0 or words[i + 1].lower in ("one", "a", "an"):
        return None
    n = match_phrase(words, i + 1, NUMBERS)
    return s.emit(i, 1, Tag.DET) if s.noun_follows(i + 1 + n) else None


def _ordinal_from_an_end(s: State, i: int) -> Match | None:
    """"the *second from the bottom* shelf": an ordinal counting from an end of a row, said before the noun it counts,
    is one modifier of that noun (the phrase names a shelf, not "the second" of something taken from the bottom
    shelf). Only after a determiner and before a noun; "the second drawer from the left" needs no rule."""
    words = s.words
    if not s.out or s.out[-1].tag != Tag.DET or i + 3 >= len(words) or words[i + 1].lower != "from":
        return None
    k = i + 2 + (words[i + 2].lower in ("the", "a"))
    if k < len(words) and words[k].lower in ENDS and s.noun_follows(k + 1):
        return s.emit(i, k + 1 - i, Tag.WORD)
    return None


def _side_of_region(s: State, i: int) -> Match | None:
    if s.next_lower(i) == "of" and len(s.out) >= 2 and s.out[-1].tag == Tag.WORD and \
            s.out[-1].lower in REGIONS and s.out[-2].tag in (Tag.DET, Tag.POSS):
        return s.emit(i, 1, Tag.WORD)                             # "the front left of the stove": a region of it
    return None


def _of(s: State, i: int) -> Match | None:
    return s.emit(i, 1, Tag.OF)


def _determiner_in_np(s: State, i: int) -> Match | None:
    low = s.words[i].lower
    if s.in_np() and low in NP_OPENERS and s.noun_follows(i + 1):
        return s.emit(i, 1, Tag.DET if low in DETERMINERS else Tag.POSS)
    return None


def _here(s: State, i: int) -> Match | None:
    if s.in_np():
        return None
    low, nxt = s.words[i].lower, s.next_lower(i)
    if low == HOME:                       # "bring him *home*", "take grandma home": where the motion goes
        ends = not nxt or nxt in END_MARKS or nxt in (",", ";", "please", "and", "then", "now", "yet", "already")
        return s.emit(i, 1, Tag.HERE) if ends and s.verb_index >= 0 and s.prev_tag() in (
            Tag.WORD, Tag.NAME, Tag.PRON) else None
    n = match_phrase(s.words, i, HERE_WORDS)
    after_be = bool(s.out) and s.out[-1].tag == Tag.BE           # "how many cups are there in the kitchen"
    if n and not (low == "there" and (nxt in BE_WORDS or after_be)):
        found = s.emit(i, n, Tag.HERE)
        if n == 2 and low == "in":                                # "in there": read as "there"
            w = found.words[0]
            return Match(n, (Word(w.text, w.start, w.end, w.tag, w.info, s.words[i + 1].lower),))
        return found
    if low == "there":
        return s.emit(i, 1, Tag.THERE)
    return None


_WHENCE = frozenset(["from"])
"""Prepositions of where a motion starts: after them a place word names the place ("from *upstairs*")."""


def _place_word_after_from(s: State, i: int) -> Match | None:
    """"Get my teddy from *upstairs*", "bring the laundry from *downstairs*": a one-word place ("upstairs",
    "downstairs", "indoors") right after a preposition of where a motion starts names that place, as a
    noun does (words25): the source, not a dangling "here" the grammar refuses after a preposition."""
    words = s.words
    if not s.out or s.prev_tag() != Tag.PREP or s.out[-1].info not in _WHENCE or \
            words[i].lower not in _PLACE_WORDS:
        return None
    nxt = s.next_lower(i)
    if nxt and nxt not in END_MARKS and nxt not in (",", ";", "and", "then", "please", "to", "into", "onto"):
        return None
    return s.emit(i, 1, Tag.WORD)


_PLACE_WORDS = frozenset(w for w in HERE_WORDS if " " not in w and w not in ("here", "there"))


def _from_there(s: State, i: int) -> Match | None:
    """"go to the pantry and get a bowl *from there*", "take the cup from here": "from" and a bare "here"/"there"
    ending the clause is where the motion starts, a place pointed at or said before (words42: the grammar refused
    "there" after a preposition). One word, a place (``HERE``) whose preposition is "from": the source."""
    words = s.words
    if s.in_np() or words[i].lower not in _WHENCE or i + 1 >= len(words) or words[i + 1].lower not in ("here", "there"):
        return None
    nxt = s.next_lower(i + 1)
    if nxt and nxt not in END_MARKS and nxt not in (",", ";", "and", "then", "please", "to", "into", "onto", "too"):
        return None
    w = merge(words, i, 2, Tag.HERE, words[i].lower)
    return Match(2, (Word(w.text, w.start, w.end, w.tag, w.info, words[i + 1].lower),))


def _particle_before_object(s: State, i: int) -> Match | None:
    """"bring *in* the washing", "hand *in* the form", "bring *over* a cola to Mia" (words48): "in" or "over" right
    after a verb that hands a thing to someone (a unit of a frame with a recipient, no verb of saying) and before its
    object is the verb's particle, as "bring the washing *in*" says it (it was a Guide from the washing, "take in"
    aside; words30; "bring over a cola" brought from the cola). Only before a determiner or a possessive: "put in the
    fridge" (no such verb) keeps its place."""
    if s.prev_tag() != Tag.VERB or s.verb_index != len(s.out) - 1 or i + 1 >= len(s.words):
        return None
    unit = str(s.out[-1].info)
    if unit not in s.lexicon.recipients or unit in s.lexicon.speech or " " in unit or \
            s.words[i + 1].lower not in NP_OPENERS:
        return None
    end = s.clause_end(i + 1)
    end = next((k for k in range(i + 2, end) if s.words[k].lower in PREPOSITIONS), end)
    if any(is_premises(noun_lemma(w.lower) or w.lower) for w in s.words[i + 2:end]):
        return None                 # "bring (it) in the kitchen": a place, where it goes
    return s.emit(i, 1, Tag.PARTICLE, s.words[i].lower)


def _particle_of_no_motion(s: State, i: int) -> Match | None:
    """"dust *off* the shelf", "wipe *down* the worktop", "scrub *out* the pan": a particle right after a verb none of
    whose frames moves anything (no goal, no source: ``Lexicon.motionless``) and before a determiner or a possessive
    is the verb's, and the phrase its object: it names no place the thing comes off (words36: "dust off the shelf"
    was refused as a phrase Clean has no element for). "take off the lid" (Pick has a source) is unchanged."""
    if s.prev_tag() != Tag.VERB or s.verb_index != len(s.out) - 1 or i + 1 >= len(s.words) or \
            str(s.out[-1].info) not in s.lexicon.motionless or s.words[i + 1].lower not in NP_OPENERS:
        return None
    return s.emit(i, 1, Tag.PARTICLE, s.words[i].lower)


def _preposition(s: State, i: int) -> Match | None:
    if s.in_np():
        return None
    words = s.words
    n = match_phrase(words, i, PREPOSITIONS)
    if not n:
        return None
    if n > 1 and match_phrase(words, i + n - 1, HERE_WORDS) == 2:
        return s.emit(i, n - 1, Tag.PARTICLE, words[i].lower)    # "put them *back* in there": "in there" a place
    prep = PREPOSITIONS[" ".join(x.lower for x in words[i:i + n])]
    has_object = s.np_starts(i + n) or i + n < len(words) and words[i + n].lower in ("here", "there")
    if not has_object and prep == "outside":
        return s.emit(i, n, Tag.HERE)                             # "take the trash bag outside"
    return s.emit(i, n, Tag.PREP if has_object else Tag.PARTICLE, prep)   # "pick it up", "... from"


def _nearest(s: State, i: int) -> Match | None:
    """"the chair *nearest* the window", "the one *nearer* the door": the comparative or superlative of "near" after a
    noun and before a noun phrase's opener is a preposition, as "near" is ("nearest to" is one already; words38: the
    window was a phrase no element took). Before a noun it stays an adjective ("the *nearest* chair")."""
    if s.in_np() or s.prev_tag() not in (Tag.WORD, Tag.NAME, Tag.PRON) or s.next_lower(i) not in NP_OPENERS:
        return None
    return s.emit(i, 1, Tag.PREP, "near")


_FROM_SLIP = "form"
""""from" with two letters swapped that is also a word ("bring me the cup *form* the shelf"): the slips of function
words never read a word the dictionary lists (:mod:`seal_cli.language.slips`), so this one is read by its place."""


def _form_for_from(s: State, i: int) -> Match | None:
    """"pick up the spoon *form* the sink" (words37): "form" right after the noun phrase a verb took, before a
    determiner or a possessive that opens a phrase with no verb after it to the clause's end, is "from" typed with
    two letters swapped; "the *form*", "fill in the tax form the bank sent" stay nouns."""
    words = s.words
    if s.verb_index < 0 or s.prev_tag() not in (Tag.WORD, Tag.NAME, Tag.PRON) or i + 2 >= len(words) or \
            words[i + 1].lower not in NP_OPENERS:
        return None
    end = s.cond_end(i + 1)
    if any(s.verb_at(k) is not None and words[k - 1].lower not in NP_OPENERS for k in range(i + 2, end)):
        return None
    return s.emit(i, 1, Tag.PREP, "from")


def _back(s: State, i: int) -> Match | None:
    """"put the mug *back*": "back" after the object of a verb that puts its thing in its goal, with no
    place said in the rest of the clause, is where the thing goes: back where it was taken from (a place, as
    "here" is; what it refers to is :meth:`seal_cli.language.reference.Reference.source_before`'s)."""
    if s.in_np() or s.verb_index < 0 or str(s.out[s.verb_index].info) not in s.lexicon.puts or \
            s.prev_tag() == Tag.VERB:
        return None                                               # "carry back the mug": a particle, as before
    if s.noun_follows(i + 1) or str(s.out[s.verb_index].info) in s.lexicon.escorts:
        return None                               # "the left back burner": a noun's; "take them back": a person
    rest = s.words[i + 1:s.clause_end(i + 1)]
    if any(w.lower in _PREP_FIRST or w.lower in _HERE_FIRST or w.lower in PARTICLES for w in rest):
        return None                                               # "put it back on the shelf": the place said
    return s.emit(i, 1, Tag.HERE, "back")


def _particle(s: State, i: int) -> Match | None:
    return None if s.in_np() else s.emit(i, 1, Tag.PARTICLE, s.words[i].lower)


def _wh(s: State, i: int) -> Match | None:
    return None if s.in_np() or s.prev_tag() == Tag.DET else s.emit(i, 1, Tag.WH)


def _be(s: State, i: int) -> Match | None:
    return None if s.in_np() else s.emit(i, 1, Tag.BE)


def _possessive(s: State, i: int) -> Match | None:
    if s.in_np() or s.words[i].lower == "her" and (not s.noun_follows(i + 1) or s.next_lower(i) in HERE_WORDS):
        return None                                               # "take *her* there": the pronoun, then where
    if s.words[i].lower == "her" and _verb_and_object(s, i + 1):
        return None               # "when you find *her* tell her the time": the pronoun, then a clause (words28)
    return s.emit(i, 1, Tag.POSS)


_OBJECTS_AFTER = frozenset(["it", "them", "him", "her", "me", "us", "the"])


def _verb_and_object(s: State, j: int) -> bool:
    """Whether a library verb's base form starts at ``j``, then an object ("tell *her*", "bring *the* cup"): no
    noun a possessive goes on ("find her *tell her* the time"), but a clause said without a joint."""
    if j + 1 >= len(s.words) or s.words[j].lower not in s.lexicon.units or s.words[j + 1].lower not in _OBJECTS_AFTER:
        return False
    found = s.verb_at(j)
    return found is not None and found[2] is None and found[0].split()[0] == s.words[j].lower


_RECIPIENTS = frozenset(["me", "us", "him", "her", "them"])


def _partitive(s: State, i: int) -> Match | None:
    nxt = s.next_lower(i)
    after_verb = s.prev_tag() == Tag.VERB or s.prev_tag() == Tag.PRON and len(s.out) > 1 and \
        s.out[-2].tag == Tag.VERB and s.out[-1].lower in _RECIPIENTS    # "can you bring me *some*?" (words28)
    if not s.in_np() and after_verb and not s.noun_follows(i + 1) and \
            nxt not in NP_OPENERS and nxt not in NUMBERS and nxt != "of":
        return s.emit(i, 1, Tag.PRON)                             # "pour *some* into the cup": some of it
    return None


def _another_alone(s: State, i: int) -> Match | None:
    """"move the vase from one shelf to *another*", "put the cushions on another, then sit down": "another" with its
    noun left out, after a preposition and before no noun, is the noun phrase (of the kind said before it:
    ``Reference.noun_for_one``), never a determiner whose noun is missing."""
    if s.prev_tag() != Tag.PREP or s.noun_follows(i + 1) or s.next_lower(i) in ("one", "ones"):
        return None                                  # "to another one": the determiner of "one"
    return s.emit(i, 1, Tag.WORD)


def _next_alone(s: State, i: int) -> Match | None:
    """"move the box from one table to *the next*": "the next" after a preposition and before no noun is the noun
    phrase, its noun left out (``Reference.noun_for_one``), as "another" is (:func:`_another_alone`); never "next"
    the joint of a clause ("then")."""
    out = s.out
    if len(out) < 2 or out[-1].lower != "the" or out[-2].tag != Tag.PREP or s.noun_follows(i + 1) or \
            s.next_lower(i) in ("one", "ones", "to") or s.verb_after(i + 1):
        return None
    return s.emit(i, 1, Tag.WORD)


def _determiner(s: State, i: int) -> Match | None:
    if s.in_np() or s.words[i].lower in ("that", "this", "these", "those") and not s.noun_follows(i + 1):
        return None
    return s.emit(i, 1, Tag.DET)


_WHATEVER = frozenset(["whatever", "whichever"])


_TELLERS = frozenset(["he", "she", "they", "i", "you", "we"])
"""Subjects of a free relative said after a verb of telling ("tell me whatever *she* says")."""


def _whatever(s: State, i: int) -> Match | None:
    """"pick up *whatever is* there", "bring me whatever's on the counter", "take whatever is in the sink": a free
    relative of things is the thing, as "everything" is, and its "is" is dropped as "that is" is ("everything that
    is on the counter"): the place after it describes it. Never a name written in lower case."""
    if s.in_np():
        return None
    words = s.words
    k = i + 1
    if words[i].lower == "whatever" and s.verb_index >= 0 and str(s.out[s.verb_index].info) in s.lexicon.speech and \
            k + 1 < len(words) and words[k].lower in _TELLERS:
        return s.emit(i, 1, Tag.WH)              # "tell me *whatever* she says": what she says (words49)
    if k < len(words) and words[k].lower in BE_WORDS and k + 1 < len(words) and (
            words[k + 1].lower in PREPOSITIONS or words[k + 1].lower in HERE_WORDS):
        return Match(2, s.emit(i, 1, Tag.WORD).words)
    return s.emit(i, 1, Tag.WORD)


def _pronoun(s: State, i: int) -> Match | None:
    return None if s.in_np() else s.emit(i, 1, Tag.PRON)


def _floating_each(s: State, i: int) -> Match | None:
    """"give Ana and Bo a cup *each*", "bring the kids an apple *each*": "each" after the object, before the end, a
    comma, "and", "then" or "please", is English's floating quantifier: the people said get one each, as the
    phrase's conjuncts already say; no determiner of a noun to come (words38: "the command ends too early")."""
    nxt = s.next_lower(i)
    if s.in_np() or s.prev_tag() not in (Tag.WORD, Tag.NAME) or \
            not (i + 1 >= len(s.words) or nxt in (",", ";", "and", "then", "please") or nxt in END_MARKS):
        return None
    return Match(1)


FLOATED = frozenset(["both", "all"])
"""Quantifiers said after a pronoun of several things ("put them *both* on the table")."""


def _pronoun_quantified(s: State, i: int) -> Match | None:
    after = s.words[i + 2].lower if i + 2 < len(s.words) else ""
    if s.in_np() or s.next_lower(i) not in FLOATED or s.noun_follows(i + 2) or after in NP_OPENERS or \
            after in NUMBERS or after == "of":
        return None                      # "give them all the apples": "all" opens the thing given
    return s.emit(i, 2, Tag.PRON)


TIME_WORD = Rule("time word", _time_word, (
    Example("put it in the fridge right away", "right away", Tag.PARTICLE),
), TIME_FIRST, "a time adverbial ('now', 'right away', 'later')")
FOR_A_TIME = Rule("for a time", _for_a_time, (
    Example("stir the soup for three minutes", "for three minutes", Tag.PARTICLE),
), frozenset(["for", "every", "each"]), "'for three minutes', 'every few minutes'")
CLOCK_TIME = Rule("clock time", _clock_time, (
    Example("meet her at three", "at three", Tag.PARTICLE),
    Example("bring me a cup at 5:30 from the kitchen", "at 5:30", Tag.PARTICLE),
    Example("meet Anna at 17.45 in the hall", "at 17.45", Tag.PARTICLE),
), CLOCK_PREPOSITIONS, "a time said with a number ('at three', 'in ten minutes')")
NEAREST = Rule("nearest as a preposition", _nearest, (
    Example("bring me the chair nearest the window", "nearest", Tag.PREP),
    Example("wipe the bench nearer the gate", "nearer", Tag.PREP),
), frozenset(["nearest", "nearer"]), "'nearest'/'nearer' after a noun, before a noun phrase: a preposition, 'near'")
FLOATING_EACH = Rule("each after the object", _floating_each, (
    Example("give the twins a biscuit each", "each", ""),
    Example("hand Kim and Lou a towel each, please", "each", ""),
), frozenset(["each"]), "'each' after the object, at the clause's end: the floating quantifier, said of the people")
ONE = Rule("the red one", _one, (
    Example("bring me the red one", "one", Tag.WORD),
    Example("put that one in the drawer", "one", Tag.WORD),
    Example("put the old batteries in the bin and bring me new ones", "ones", Tag.WORD),
), frozenset(["one", "ones"]), "'one' after adjectives after a determiner: a noun")
THAT_SAID = Rule("that and what is said", _that_said, (
    Example("tell the guest that dinner is ready", "dinner is ready", Tag.SAID),
), frozenset(["that"]), "'that' after the person a verb of saying tells: what is said, kept whole")
IF_ASKED = Rule("if and what is asked", _if_asked, (
    Example("ask Raj if he wants tea", "he wants tea", Tag.SAID),
    Example("ask Priya whether she can come to the garage", "she can come to the garage", Tag.SAID),
), IFS, "'if'/'whether' after the person a verb of asking asks: the question, kept whole")
ALTERNATIVES_TOLD = Rule("whether A or B told", _alternatives_told, (
    Example("tell Anna whether the guy is sitting or standing", "the guy is sitting or standing", Tag.SAID),
    Example("tell the man at the door if the taxi is here or still on its way",
            "the taxi is here or still on its way", Tag.SAID),
), IFS, "'whether/if A or B' after the person a verb of saying tells: the question, kept whole")
COMPOUND_MODIFIER = Rule("verb and particle as a modifier", _compound_modifier, (
    Example("open the pull out drawer", "out", Tag.WORD),
    Example("put the blanket on the fold down bed", "down", Tag.WORD),
), _COMPOUND_PARTICLES, "'the pull out drawer': a verb and a particle after a determiner, before a noun, modify it")
PARTICLE_NOUN = Rule("particle as a noun", _particle_noun, (
    Example("clean the back of the toilet", "back", Tag.WORD),
), PARTICLES, "a particle before 'of' is a noun ('the back of')")
ORDINAL_BEFORE_NUMBER = Rule("ordinal before a number", _ordinal_before_number, (
    Example("put the last two plates in the sink", "last", Tag.DET),
    Example("bring me the first three cups", "first", Tag.DET),
), _BEFORE_A_NUMBER, "'the last two plates': an ordinal between a determiner and a number, part of the phrase")
ORDINAL_FROM_AN_END = Rule("ordinal from an end", _ordinal_from_an_end, (
    Example("put the bottle on the second from the bottom shelf", "second from the bottom", Tag.WORD),
    Example("put the book in the third from the left drawer", "third from the left", Tag.WORD),
), ORDINALS, "'the second from the bottom shelf': an ordinal counted from an end, one modifier of the noun")
SIDE_OF_REGION = Rule("side of a region", _side_of_region, (
    Example("put the pot on the front left of the stove", "left", Tag.WORD),
    Example("put the soap on the back right of the counter", "right", Tag.WORD),
    Example("put the pan on the lower right of the stove", "right", Tag.WORD),
), SIDES, "'left'/'right' before 'of' after a region word ('the front left of'): a noun, not 'left of'")
OF = Rule("of", _of, (Example("bring me a slice of apple", "of", Tag.OF),), frozenset(["of"]), "'of'")
DETERMINER_IN_NP = Rule("determiner inside a noun phrase", _determiner_in_np, (
    Example("bring me all the cups", "the", Tag.DET),
), NP_OPENERS, "a determiner or possessive after another, before a noun", after=IN_NP)
SEEN_OUT = ("out", "exit", "toward")
"""A person *seen out*: the word, the place it names (where a person leaves a building by), the way it is said
(where the motion goes: a goal)."""


_ENDING = frozenset([None, "", ".", "!", "?", ",", ";", "please", "and", "then", "now"])
"""What may follow a word that ends its clause ("see him *out* please", "... *out* and close the door")."""


def _seen_out(s: State, i: int) -> Match | None:
    """"see Helen *out*", "show the guest out", "walk him out", "guide the lady waving in the kitchen out": "out"
    ending a clause whose verb leads a person (a unit of a frame whose first element is a person) whose object is
    a person (a name, a pronoun of a person, a noun the taxonomy lists as a person) is where they are led: out of
    the building, its exit (a goal, as "home" is). A Guide with no goal would lead nowhere; the phrase is never
    dropped."""
    word, (low, place, prep) = s.words[i], SEEN_OUT
    if word.lower != low or s.verb_index < 0 or str(s.out[s.verb_index].info) not in s.lexicon.escorts or \
            s.in_np() or s.next_lower(i) not in _ENDING:
        return None
    led = next((w for w in s.out[s.verb_index + 1:] if w.tag in (Tag.NAME, Tag.PRON, Tag.WORD)), None)
    person = led is not None and (led.tag == Tag.NAME or led.lower in ("him", "her", "them", "us", "me") or
                                  led.tag == Tag.WORD and any(noun_lemma(w.lower) in s.lexicon.people
                                                              for w in _phrase_at(s, led)))
    return Match(1, (Word(word.text, word.start, word.end, Tag.HERE, prep, place),)) if person else None


def _phrase_at(s: State, first: Word) -> list[Word]:
    """The open words of the noun phrase that begins with ``first`` (its adjectives and its head), up to the first
    word of another kind: "the *old lady* waving in the kitchen"."""
    out = s.out
    k = next(j for j, w in enumerate(out) if w is first)
    end = k
    while end < len(out) and out[end].tag == Tag.WORD:
        end += 1
    return list(out[k:end])


PLACE_WORD_AFTER_FROM = Rule("a place word after from", _place_word_after_from, (
    Example("fetch my slippers from upstairs", "upstairs", Tag.WORD),
    Example("bring the laundry from downstairs", "downstairs", Tag.WORD),
), _PLACE_WORDS, "'from upstairs': the place word names where the motion starts, as a noun")
FROM_THERE = Rule("from there", _from_there, (
    Example("go to the shed and get a rake from there", "from there", Tag.HERE),
    Example("take the mug from here to the sink", "from here", Tag.HERE),
), _WHENCE, "'from there', 'from here': where the motion starts, a place pointed at or said before")
HERE = Rule("here and there", _here, (
    Example("bring it here", "here", Tag.HERE),
    Example("how many cups are there on the table", "there", Tag.THERE),
    Example("go to the pantry and count the cans in there", "in there", Tag.HERE),
    Example("meet alex at the station and bring him home", "home", Tag.HERE),
), _HERE_FIRST, "'here', 'there', 'upstairs' (a place); 'there' before or after 'is' (existential)")
OUT_OF_THE_HOUSE = Rule("a person seen out", _seen_out, (
    Example("see helen out", "out", Tag.HERE),
    Example("show the guest out please", "out", Tag.HERE),
    Example("guide the lady waving in the kitchen out", "out", Tag.HERE),
), frozenset([SEEN_OUT[0]]), "'out' after the person a verb of leading takes, ending the clause: to the exit")
PARTICLE_BEFORE_OBJECT = Rule("in before the object", _particle_before_object, (
    Example("bring in the washing", "in", Tag.PARTICLE),
    Example("could you hand in my form", "in", Tag.PARTICLE),
    Example("bring over a cola to Mia", "over", Tag.PARTICLE),          # words48: "over" as "bring a cola over"
), frozenset(["in", "over"]), "'bring in the washing', 'bring over a cola': the verb's particle before its object, the "
   "clause naming no place")
FORM_FOR_FROM = Rule("'form' typed for 'from'", _form_for_from, (
    Example("pick up the ladle form the drawer", "form", Tag.PREP),
    Example("bring me a pear form the bowl", "form", Tag.PREP),
), frozenset([_FROM_SLIP]), "'form' after a verb's object and before a phrase: 'from' typed with a slip")
PARTICLE_OF_NO_MOTION = Rule("a particle before the object of a verb of no motion", _particle_of_no_motion, (
    Example("dust off the bookcase", "off", Tag.PARTICLE),
    Example("please scrub out the roasting tin", "out", Tag.PARTICLE),
), OBJECT_PARTICLES, "'dust off the shelf': the particle of a verb that moves nothing, before its"
   " object")
PREPOSITION = Rule("preposition", _preposition, (
    Example("put the plates back in there", "back", Tag.PARTICLE),
    Example("put the cup on top of the fridge", "on top of", Tag.PREP),
    Example("take the trash bag outside", "outside", Tag.HERE),
), _PREP_FIRST, "a preposition with its object, else a particle")
BACK = Rule("back, where it was", _back, (
    Example("put the mug back", "back", Tag.HERE),
    Example("take the cup from the table and put it back", "back", Tag.HERE),
), frozenset(["back"]), "'back' after a verb of putting with no place said: back where the thing was taken from")
PARTICLE = Rule("particle", _particle, (Example("carry back the mug", "back", Tag.PARTICLE),), PARTICLES,
                "a particle with no verb of its own")
WH = Rule("wh-word", _wh, (Example("tell me what time it is", "what", Tag.WH),), WH_WORDS, "'what', 'which', ...")
BE = Rule("be", _be, (Example("tell me what time it is", "is", Tag.BE),), BE_WORDS, "'is', 'are', ...")
POSSESSIVE = Rule("possessive", _possessive, (
    Example("bring me my coat", "my", Tag.POSS),
    Example("take her coat there", "her", Tag.POSS),
), POSSESSIVES,
                  "'my', 'their', 'her' before a noun")
PARTITIVE = Rule("partitive pronoun", _partitive, (
    Example("pour some into the cup", "some", Tag.PRON),
    Example("I'm hungry, can you bring me some?", "some", Tag.PRON),
), PARTITIVES, "'some', 'all' right after the verb (or its person) with no noun: some of it")
ANOTHER_ALONE = Rule("another, its noun left out", _another_alone, (
    Example("move the vase from one shelf to another", "another", Tag.WORD),
    Example("carry the box from one room to another, then wait", "another", Tag.WORD),
), frozenset(["another"]), "'from one shelf to another': the noun phrase, its noun the one said before",
    after=frozenset([Tag.PREP]))
NEXT_ALONE = Rule("the next, its noun left out", _next_alone, (
    Example("move the box from one table to the next", "next", Tag.WORD),
    Example("move the box from this shelf to the next, then wait", "next", Tag.WORD),
), frozenset(["next"]), "'from one table to the next': the noun phrase, its noun the one said before",
    after=frozenset([Tag.DET]))
DETERMINER = Rule("determiner", _determiner, (Example("bring me the cup", "the", Tag.DET),), DETERMINERS,
                  "a determiner ('that' only before a noun)")
WHATEVER = Rule("whatever is", _whatever, (
    Example("go to the table and pick up whatever is there", "whatever", Tag.WORD),
    Example("take whatever's in the sink", "whatever", Tag.WORD),
    Example("tell me whatever she says", "whatever", Tag.WH),
), _WHATEVER, "'whatever is on the counter': the thing, its 'is' dropped as 'that is' is")
PRONOUN_QUANTIFIED = Rule("pronoun with its quantifier", _pronoun_quantified, (
    Example("put the apple in the bowl and put them both on the table", "them both", Tag.PRON),
    Example("put a spoon in a cup and move them both to the sink", "them both", Tag.PRON),
    Example("wash the cups and put them all away", "them all", Tag.PRON),
), frozenset(["them", "they", "these", "those", "it"]), "'them both', 'them all': one pronoun, the quantifier "
   "floated after it (not before a noun phrase: 'give them all the apples')")
PRONOUN = Rule("pronoun", _pronoun, (Example("put it there", "it", Tag.PRON),), PRONOUNS, "a pronoun")
