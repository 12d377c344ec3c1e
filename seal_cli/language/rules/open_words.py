"""Open-class words: participles after a noun, result words before one, adverbs, names, and every
other word (a noun or an adjective). Nothing here lists a word."""

from __future__ import annotations

from seal_cli.language.english import (
    FREQUENCY_ADVERBS,
    LOCATIVE,
    NP_OPENERS,
    NUMBERS,
    PARTICLES,
    PREPOSITIONS,
    STATE_ADVERBS,
    TITLES_ONLY,
)
from seal_cli.language.morphology import (
    adverb_no_noun,
    gerund_lemma,
    in_dictionary,
    is_adverb,
    is_gradable,
    is_plural,
    noun_lemma,
    parts_of_speech,
    verb_lemma,
)
from seal_cli.language.rule import Example, Match, Rule, after_all_but
from seal_cli.language.state import CLOSED, IN_NP, State, match_phrase
from seal_cli.language.tags import Tag
from seal_cli.language.tokens import Word, capitalised
from seal_cli.language.verb_objects import takes_object


def where_said(s: State, k: int) -> bool:
    """Whether a preposition of two words or more that says where a thing is ("next to", "in front of", "close to",
    "on top of") and its noun phrase start at ``k``: a participle before it takes that phrase ("standing *next to*
    the door"; words39). Not one of motion ("back to", "up to": "going *back to* the table")."""
    words = s.words
    n = match_phrase(words, k, PREPOSITIONS) if k + 1 < len(words) else 0
    return n > 1 and words[k].lower not in ("back", "to") and \
        PREPOSITIONS[" ".join(w.lower for w in words[k:k + n])] in LOCATIVE and s.np_starts(k + n)


def _participle(s: State, i: int) -> Match | None:
    low, nxt = s.words[i].lower, s.next_lower(i)
    gerund = gerund_lemma(low)
    if not gerund or s.prev_tag() not in (Tag.WORD, Tag.NAME, Tag.PRON, Tag.BE, Tag.AND_VBG):
        return None
    if where_said(s, i + 1):
        return s.emit(i, 1, Tag.VBG_P, gerund)  # "the person standing *next to* the door" (words39): not "next" an NP
    words = s.words
    if nxt in PARTICLES and nxt not in PREPOSITIONS and i + 3 < len(words) and \
            words[i + 2].lower in PREPOSITIONS and s.np_starts(i + 3) and _a_person(s, s.out[-1]):
        return s.emit(i, 2, Tag.VBG_P, gerund)  # "the person *lying down* in the living room": one participle
        #   and its place (words42: "down" was a particle, the place lost); of a person only ("the cup on the
        #   microwave going back to the coffee maker", "a spoon standing up on it" are read as before)
    tag = Tag.VBG_T if s.np_starts(i + 1) and nxt not in PARTICLES and not _second_object(s, gerund) else \
        Tag.VBG_P if nxt in PREPOSITIONS and s.np_starts(i + 2) else Tag.VBG_I
    return s.emit(i, 1, tag, gerund)


def _a_person(s: State, word: Word) -> bool:
    """Whether a tagged word names a person: a name, or a noun of people (``Lexicon.people``)."""
    low = word.lower
    return word.tag == Tag.NAME or low in s.lexicon.people or noun_lemma(low) in s.lexicon.people


def _second_object(s: State, gerund: str) -> bool:
    """Whether the noun phrase after a participle is the clause verb's second object, not the participle's: "bring
    the kid who's *crying* his teddy", "give the boy *waiting* his coat" (words38: the teddy was the kid's crying and
    Guide took the kid). The clause's verb takes a recipient and a thing (not a verb of saying), the participle
    describes its first object, and its verb is mostly said with no object (:func:`~seal_cli.language.verb_objects.
    takes_object`: people cry and wait, they wear and hold things)."""
    verb = s.out[s.verb_index] if s.verb_index >= 0 else None
    if verb is None or verb.start == verb.end or str(verb.info) not in s.lexicon.recipients or \
            str(verb.info) in s.lexicon.speech or takes_object(gerund):
        return False                   # "the boy who is crying wants his teddy": an implied verb, the wish's
    return all(w.tag in (Tag.DET, Tag.POSS, Tag.NUM, Tag.WORD) for w in s.out[s.verb_index + 1:])


def _and_participle(s: State, i: int) -> Match | None:
    """"the people sitting *and* wearing red shirts", "the man standing *and* waving": "and" between two
    participles of one noun (words38: the second was read as a clause of its own and refused). The first is a
    bare participle (after an object, "and" could join the object's own: the grammar stays LALR(1)), and an -ing
    form follows."""
    nxt = s.next_lower(i)
    if not nxt or gerund_lemma(nxt) in (None, nxt):
        return None                                               # "sitting and *bring* me ...": a verb's base form
    return s.emit(i, 1, Tag.AND_VBG) if s.prev_tag() == Tag.VBG_I else None


def _noun_modifier(s: State, i: int) -> bool:
    """Whether the -ing form at ``i`` says what kind of thing the noun after it is, in a phrase whose words
    before it are adjectives ("the blue *recycling* bin", "a small black *shelving* unit", "the wooden
    *dining* table"): a determiner, a number or a possessive, then adjectives (each gradable, or nothing
    else: no noun such as "patient" or "the elderly"), then a noun. After a noun it stays a participle ("the
    person *wearing* glasses")."""
    out = s.out
    if not gerund_lemma(s.words[i].lower) or not s.noun_follows(i + 1):
        return False
    k = len(out) - 1
    while k >= 0 and out[k].tag == Tag.WORD and _adjective_only(s, out[k].lower):
        k -= 1
    return k < len(out) - 1 and k >= 0 and out[k].tag in (Tag.DET, Tag.NUM, Tag.POSS)


def _adjective_only(s: State, low: str) -> bool:
    kinds = parts_of_speech(low)
    return "adj" in kinds and (is_gradable(low) or kinds == {"adj"}) and low not in s.lexicon.things


def _filled_with(s: State, i: int) -> Match | None:
    """A past participle between a noun and "with" and a noun phrase says what the thing holds, as "with"
    alone does ("a bowl *filled* with water", "a plate *covered* with foil": "a bowl with water"): it is
    dropped, the noun before stays the head."""
    low = s.words[i].lower
    if s.prev_tag() not in (Tag.WORD, Tag.NAME) or not low.endswith("ed") or s.next_lower(i) != "with" or \
            not s.np_starts(i + 2):
        return None
    lemma = verb_lemma(low)
    return Match(1) if lemma and lemma != low else None


def _kind_gerund(s: State, i: int) -> Match | None:
    return s.emit(i, 1, Tag.WORD) if _noun_modifier(s, i) else None


def _result(s: State, i: int) -> Match | None:
    words, low, nxt = s.words, s.words[i].lower, s.next_lower(i)
    result = s.lexicon.results.get(low)
    if not result:
        return None
    if s.noun_follows(i + 1):
        return s.emit(i, 1, Tag.RESULT, result)
    if nxt in PARTICLES and s.noun_follows(i + 2):
        return s.emit(i, 2, Tag.RESULT, s.lexicon.results.get(f"{low} {nxt}", result))  # "a heated up potato"
    if nxt == "," and i + 2 < len(words) and words[i + 2].lower in s.lexicon.results and s.noun_follows(i + 3):
        return Match(2, s.emit(i, 1, Tag.RESULT, result).words)   # "a cooked, rinsed egg"
    if nxt == "and" and s.prev_tag() == Tag.DET and i + 2 < len(words) and words[i + 2].lower in s.lexicon.results \
            and s.noun_follows(i + 3):
        return Match(2, s.emit(i, 1, Tag.RESULT, result).words)   # "the sliced and washed lettuce": one noun's two
    if nxt == "," and s.prev_tag() == Tag.DET and s.noun_follows(i + 2) and \
            (words[i + 2].lower not in s.lexicon.verb_set or s.next_lower(i + 2) == "of"):
        return Match(2, s.emit(i, 1, Tag.RESULT, result).words)   # "the rinsed, tea kettle": the comma a slip
    return None


def _adverb(s: State, i: int) -> Match | None:
    low = s.words[i].lower
    if not s.in_np() and low.isalpha() and is_adverb(low) and s.prev_tag() != Tag.DET:
        return s.emit(i, 1, Tag.PARTICLE)                         # "gather together", "put it carefully on ..."
    return None


_BEFORE_OBJECT = (STATE_ADVERBS | FREQUENCY_ADVERBS) - {"not", "all", "now"}


def _adverb_before_object(s: State, i: int) -> Match | None:
    """An adverb of time or degree between the verb and its object's first word ("is there *still* some juice in
    the carton?", "is there *even* any milk?", "bring *just* the red cup"): how or since when, no part of the
    thing (it was the theme "still", the juice dropped; words30)."""
    if s.prev_tag() != Tag.VERB or i + 1 >= len(s.words):
        return None
    nxt = s.words[i + 1].lower
    if nxt not in NP_OPENERS and nxt not in NUMBERS and not nxt.isdigit():
        return None
    return s.emit(i, 1, Tag.PARTICLE)


def _adverb_of_place(s: State, i: int) -> Match | None:
    """A word that may be an adverb and is no noun, between a noun and a phrase of where: it says how near,
    not what ("the shelf *just* below the keys", "a cabinet *directly* under the sink"); the noun before stays
    the head ("a cleaning *supply* in the kitchen": "supply" is a noun too, the head)."""
    low = s.words[i].lower
    if s.prev_tag() not in (Tag.WORD, Tag.NAME) or not _of_place(low) or low in s.lexicon.things or \
            low in CLOSED and low not in STATE_ADVERBS:
        return None
    n = match_phrase(s.words, i + 1, PREPOSITIONS) if i + 1 < len(s.words) else 0
    if not n or PREPOSITIONS[" ".join(w.lower for w in s.words[i + 1:i + 1 + n])] not in LOCATIVE or \
            not s.np_starts(i + 1 + n):
        return None
    return s.emit(i, 1, Tag.PARTICLE)


def _of_place(low: str) -> bool:
    """Whether a word may say how near or since when a thing is where it is: an adverb that is no noun ("just"),
    or one of time said before a state ("*still* on the table", "*already* in the fridge")."""
    return low in STATE_ADVERBS and low not in ("not", "all") or low.isalpha() and adverb_no_noun(low)


def _name(s: State, i: int) -> Match | None:
    w, low, nxt, prev = s.words[i], s.words[i].lower, s.next_lower(i), s.prev_tag()
    if not capitalised(w) or s.in_np() or prev == Tag.WORD or low in CLOSED:
        return None
    if prev == Tag.PREP and low.endswith("s") and len(low) > 2 and s.noun_follows(i + 1) and \
            not capitalised(s.words[i + 1]) and not gerund_lemma(nxt):
        return s.emit(i, 1, Tag.POSS, w.text[:-1])                # "in *Emmas* room": a possessive lacking its '
    if prev == Tag.NAME:                                          # "Mary Ann": one name
        last = s.out[-1]
        return Match(1, last=Word(s.text_of(last.start, w.end), last.start, w.end, Tag.NAME))
    return s.emit(i, 1, Tag.NAME)


def _title_in_lower_case(s: State, i: int) -> Match | None:
    """A title that is no other word ("mr", "dr.": :data:`~seal_cli.language.english.TITLES_ONLY`) where a noun
    phrase starts, and a word of letters after it, are one name, as "Mr Smith" is: "take *mr smith* to the
    kitchen" (a person taken somewhere: Guide), "greet dr. ahmed"."""
    words, w = s.words, s.words[i]
    if w.lower.rstrip(".") not in TITLES_ONLY or s.in_np() or s.prev_tag() == Tag.WORD or i + 1 >= len(words) or \
            not words[i + 1].lower.isalpha() or words[i + 1].lower in CLOSED:
        return None
    return Match(2, (Word(s.text_of(w.start, words[i + 1].end), w.start, words[i + 1].end, Tag.NAME),))


_NO_PLURAL_ENDINGS = ("is", "us", "ss")
"""Endings of a word no dictionary lists that make no English plural (words42): "paris", "chris", "marcus", "ross" end
in "s" and are no more than one, as "cheezits" and "oreos" are."""


_NO_NOUNS = frozenset(["wherever", "whenever"])
"""Open-class words after a name that start no noun phrase of it ("go with adel *wherever* she goes": words46)."""


def _lower_case_name(s: State, i: int) -> Match | None:
    """A word neither an English dictionary nor the library's taxonomy lists, alone after "to" or "for" in a
    clause whose verb may have a recipient ("deliver the knife to *jamie*", "fetch a towel for *jo*"), or
    after "with" in one whose verb has a goal ("go with *sam*": who goes along), or after "near" ("close to", "next
    to") in one whose verb with "with" is a unit of a frame of people ("stay close to *morgan*": "stay with" is
    Follow's, keeping near someone who moves is moving with them); after any of these prepositions even a word
    the dictionary lists only as a noun, said bare and singular before the clause's end or a preposition
    ("deliver the cup to *robin* in the kitchen", "go with *angel* to the kitchen": a bird, a spirit; right after
    a verb only frames of people have too: "meet *morgan* at the door", a horse; not "home",
    an adverb too, nor a thing the taxonomy knows: "bring it to bed"; "with" right after the verb: "put the plate
    with *apple* in the fridge" says what the plate holds), or right after a verb whose
    frame's first element is a person ("take *jordan* to the bedroom", unless it ends in "s" as plurals do, not in
    "is", "us", "ss" ("take *paris* to the desk"), which none does:
    "take cheezits to the kitchen" stays a thing): a name written in lower case. A word the map or the
    vocabulary names as a person is a name wherever it is (the parser writes it capitalised for the
    tagger)."""
    w, low = s.words[i], s.words[i].lower
    told = s.prev_tag() == Tag.VERB and str(s.out[-1].info) in s.lexicon.speech and not in_dictionary(low) and \
        s.clause_end(i + 1) == i + 1     # "go tell *ben*": the person told, said alone (no message is a name)
    if s.verb_index < 0 or s.prev_tag() != Tag.PREP and not (
            s.verb_index == len(s.out) - 1 and s.prev_tag() == Tag.VERB and
            (str(s.out[-1].info) in s.lexicon.escorts or told)):
        return None                      # "take *jordan* to the bedroom": right after a verb whose object is a person
    verb = str(s.out[s.verb_index].info)
    if s.prev_tag() == Tag.VERB and low.endswith("s") and not low.endswith(_NO_PLURAL_ENDINGS):
        return None
    near = s.prev_tag() == Tag.PREP and s.out[-1].info == "near" and f"{verb} with" in s.lexicon.escorts
    if s.prev_tag() == Tag.PREP and not (s.out[-1].info in ("to", "for") and verb in s.lexicon.recipients or
                                         s.out[-1].info == "with" and verb in s.lexicon.goals or near) or \
            not low.isalpha() or w.text != low or low in CLOSED or low in s.lexicon.things or \
            s.noun_follows(i + 1) and s.next_lower(i) not in _NO_NOUNS:
        return None
    if in_dictionary(low) and not ((s.prev_tag() == Tag.PREP or verb in s.lexicon.people_only) and
                                   parts_of_speech(low) == {"noun"} and not is_plural(low) and
                                   (s.out[-1].info != "with" or s.out[-2].tag in (Tag.VERB, Tag.PARTICLE)) and (
            s.clause_end(i + 1) == i + 1 or s.next_lower(i) in PREPOSITIONS)):
        return None                      # "stay close to *morgan*" (a breed of horse): no one stays close to a noun
    return s.emit(i, 1, Tag.NAME)        # said bare, singular, at the clause's end: who it is kept near


def _word(s: State, i: int) -> Match | None:
    return s.emit(i, 1, Tag.WORD)


PARTICIPLE = Rule("participle after a noun", _participle, (
    Example("find the person wearing a red blouse", "wearing", Tag.VBG_T),
    Example("find the person pointing to the left", "pointing", Tag.VBG_P),
    Example("find the person sitting", "sitting", Tag.VBG_I),
    Example("count the men standing and holding umbrellas", "holding", Tag.VBG_T),
    Example("hand the man snoozing his paper", "snoozing", Tag.VBG_I),     # the paper is handed (words38)
    Example("find the person standing next to the door", "standing", Tag.VBG_P),
), lambda low: bool(gerund_lemma(low)),
    "an -ing form after a noun, a pronoun or 'is': transitive, with a preposition, or bare",
    after=frozenset([Tag.WORD, Tag.NAME, Tag.PRON, Tag.BE, Tag.AND_VBG]))
AND_PARTICIPLE = Rule("and between participles", _and_participle, (
    Example("count the people sitting and wearing hats", "and", Tag.AND_VBG),
    Example("find the girl standing and talking on the phone", "and", Tag.AND_VBG),
    Example("find the girls that are standing and wearing hats", "and", Tag.AND_VBG),
    Example("count the people sitting and waving in the kitchen", "and", Tag.AND_VBG),
), frozenset(["and"]), "'and' between two participles that describe one noun: the second describes it too")
FILLED_WITH = Rule("participle before with", _filled_with, (
    Example("put a bowl filled with water in the cabinet", "filled", ""),
), lambda low: low.endswith("ed"), "a past participle between a noun and 'with': what the thing holds, as 'with'",
   after=frozenset([Tag.WORD, Tag.NAME]))
KIND_GERUND = Rule("-ing form of a kind of thing", _kind_gerund, (
    Example("put the bottle in the blue recycling bin", "recycling", Tag.WORD),
    Example("put the mug on a small black shelving unit", "shelving", Tag.WORD),
), lambda low: bool(gerund_lemma(low)),
    "an -ing form after an adjective that follows a determiner, before a noun: what kind of thing, no participle")
RESULT = Rule("result word", _result, (
    Example("put a heated egg in the fridge", "heated", Tag.RESULT),
    Example("put the heated up egg in the fridge", "heated up", Tag.RESULT),
    Example("put a cooked, rinsed egg in the fridge", "cooked", Tag.RESULT),
    Example("put the sliced and washed lettuce in the fridge", "sliced", Tag.RESULT),   # after a determiner only:
    Example("put the cut and washed lettuce in the fridge", "washed", Tag.RESULT),      # "cut and wash the apple"
    Example("put the rinsed, tea kettle under the sink", "rinsed", Tag.RESULT),   # a comma after a determiner's
    Example("put a chilled, head of lettuce in the sink", "chilled", Tag.RESULT),  # adjective: the noun follows
), None, "a participle of a lexical unit, or a frame's result adjective, before a noun")
ADVERB = Rule("adverb", _adverb, (
    Example("put it carefully on the shelf", "carefully", Tag.PARTICLE),
), lambda low: low.isalpha() and is_adverb(low), "an adverb inside the clause")
ADVERB_BEFORE_OBJECT = Rule("adverb before the object", _adverb_before_object, (
    Example("is there still some juice in the carton?", "still", Tag.PARTICLE),
    Example("bring just the red cup", "just", Tag.PARTICLE),
), _BEFORE_OBJECT, "'still', 'even', 'just' between the verb and its object's determiner: an adverb")
ADVERB_OF_PLACE = Rule("adverb of place", _adverb_of_place, (
    Example("place the pen on the shelf just below the keys", "just", Tag.PARTICLE),
    Example("put the mug in the cabinet just above the sink", "just", Tag.PARTICLE),
    Example("is the cup still on the coffee table?", "still", Tag.PARTICLE),
), _of_place,
    "a word that may be an adverb and is no noun (or 'still', 'already'), after a noun and before a phrase of where: "
    "how near, not the head", after=frozenset([Tag.WORD, Tag.NAME]))
NAME = Rule("name", _name, (
    Example("greet Mary Ann", "Mary Ann", Tag.NAME),
    Example("go to Emmas room", "Emmas", Tag.POSS),
), None, "a capitalised word where a noun phrase starts; two in a row are one name",
   after=after_all_but(Tag.WORD, *IN_NP))
TITLE_IN_LOWER_CASE = Rule("title in lower case", _title_in_lower_case, (
    Example("take mr smith to the kitchen", "mr smith", Tag.NAME),
    Example("greet dr. ahmed in the hall", "dr. ahmed", Tag.NAME),
), lambda low: low.rstrip(".") in TITLES_ONLY, "a title that is no other word, and the word after it: one name")
LOWER_CASE_NAME = Rule("name in lower case", _lower_case_name, (
    Example("deliver the parcel to jamie", "jamie", Tag.NAME),
    Example("give the keys to priya in the hallway", "priya", Tag.NAME),
    Example("fetch a towel for jo", "jo", Tag.NAME),
    Example("go with sam to the bedroom", "sam", Tag.NAME),
    Example("take jordan to the bedroom", "jordan", Tag.NAME),
    Example("take doris from the porch to the car", "doris", Tag.NAME),          # words42: no plural's ending
    Example("stay close to morgan", "morgan", Tag.NAME),
    Example("deliver the cup to robin in the kitchen", "robin", Tag.NAME),
    Example("go with angel to the kitchen", "angel", Tag.NAME),
    Example("go with adel wherever she goes", "adel", Tag.NAME),
    Example("meet morgan at the door", "morgan", Tag.NAME),
    Example("dinner's ready, go tell ben", "ben", Tag.NAME),
), None, "a word no dictionary lists, alone after 'to' or 'for' (a clause that may have a recipient) or "
         "'with' (one that has a goal): a name", after=frozenset([Tag.PREP, Tag.VERB]))
WORD = Rule("open word", _word, (
    Example("bring me the cup", "cup", Tag.WORD),
), None, "every other word: a noun or an adjective")
