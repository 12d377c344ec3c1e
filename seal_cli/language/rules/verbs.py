"""Verbs: a lexical unit of the library starting a clause, its split particle, "use X to V", and
"to" starting a clause of purpose or what is told."""

from __future__ import annotations

from seal_cli.language.english import (
    DEPARTURE_MEANS,
    END_MARKS,
    FOLLOW_ASKED,
    KEEPING,
    PARTICLES,
    PATH_ALONE,
    PATH_MEANS,
    PERSON_PRONOUNS,
    PREPOSITIONS,
    TITLES,
)
from seal_cli.language.morphology import in_dictionary, in_verb_tables, noun_lemma, participles, verb_lemma
from seal_cli.language.rule import Example, Match, Rule
from seal_cli.language.state import CLOSED, State, longest_phrase, match_phrase, merge
from seal_cli.language.tags import Tag
from seal_cli.language.tokens import Word, capitalised
from seal_cli.language.verb_objects import object_share


def _split_particle(s: State, i: int) -> Match | None:
    unit = s.particles.get(i)
    if unit is None:
        return None
    w = s.words[i]
    n = split_unit(s, i, unit)
    if n == 2:                                  # "I'd like the heater *turned on*": one particle of two words
        end = s.words[i + 1].end
        said = f"{w.lower} {s.words[i + 1].lower}"
        return Match(2, (Word(s.text_of(w.start, end), w.start, end, Tag.PARTICLE, unit, said),))
    return Match(1, (Word(w.text, w.start, w.end, Tag.PARTICLE, unit, w.lower),))


def left_in_state(s: State, j: int) -> bool:
    """Whether the word at ``j`` is the participle of a verb that leaves or keeps a thing in a state ("left", "kept":
    :attr:`Lexicon.state_verbs`, ``english.KEEPING``) said before the state ("I want the door *left* open", "I'd like
    the lamp *kept* on"): with the state, one split particle (:func:`split_unit`)."""
    low = s.words[j].lower
    lemma = verb_lemma(low) if low.isalpha() else None
    return lemma is not None and low != lemma and low in participles(lemma) and \
        (lemma in s.lexicon.state_verbs or lemma in KEEPING)


def split_unit(s: State, i: int, unit: str) -> int:
    """How many words the split particle of ``unit`` at ``i`` is: two when they are the unit's verb in a past form and
    its particle ("the heater *turned on*", a wish for a state: ``requests._done_with_particle``), else one."""
    parts = unit.split()
    if i + 1 < len(s.words) and s.words[i + 1].lower.isalpha() and left_in_state(s, i) and \
            not s.np_starts(i + 2):
        return 2                                # "I want the door *left open*" (words47); not "left *in the sink*"
    if len(parts) != 2 or i + 1 >= len(s.words) or s.words[i + 1].lower != parts[1]:
        return 1
    done = s.words[i].lower                     # "leave the heater *turned on*": another verb of the state
    return 2 if done in participles(parts[0]) or s.lexicon.done_unit(done, parts[1]) is not None else 1


DEPARTURE_OBJECT_SHARE = 0.9
"""A unit that puts its object somewhere is going away when said alone only if WordNet says its verb is said with no
object in more than a tenth of its uses (:mod:`seal_cli.language.verb_objects`): "leave" 0.638, "move" 0.419 are;
"put" 1.000, "place" 0.974, "set" 0.958 are not."""


def _left_alone(s: State, i: int) -> Match | None:
    words = s.words
    found = s.verb_at(i)
    if found is None or found[1] != 1 or found[2] is not None or words[i].lower != found[0] or \
            found[0] not in s.lexicon.puts_only or DEPARTURE_MEANS not in s.lexicon.units or \
            (object_share(found[0]) or 1.0) >= DEPARTURE_OBJECT_SHARE:
        return None                                   # "heat the soup and put": "put" has an object always
    k = i + 1
    while k < len(words) and words[k].lower in ("now", "please"):
        k += 1
    if k < len(words) and words[k].lower not in END_MARKS:
        return None                                   # "leave the cup", "leave it on the desk": what is put
    return Match(1, (merge(words, i, 1, Tag.VERB, DEPARTURE_MEANS),), expect=False, verb=DEPARTURE_MEANS, using=False)


def _use(s: State, i: int) -> Match | None:
    if not s.use_at(i):
        return None
    return Match(1, (s.words[i].tagged(Tag.PREP, "with"),), expect=False, using=True)


def _verb(s: State, i: int) -> Match | None:
    found = s.verb_at(i)
    if not found:
        return None
    unit, n, split = found
    return Match(n, (merge(s.words, i, n, Tag.VERB, unit),), expect=False, verb=unit, using=False,
                 particle=(split, unit) if split is not None else None)


SEEN_TO = ("see", "escort", frozenset(["to", "out", "home", "in", "into", "back", "upstairs", "downstairs"]))
"""*See* someone *to* a place, *out*, *home*: to escort them (WordNet's escort.v.01 "accompany or escort",
a sense of "see" far below its first), read as the library's unit "escort" (Guide)."""
_TITLE_WORDS = 3
"""The most words of a person's name after "see" ("mr jones", "the new guest", "doctor anna smith")."""


def _seen_to(s: State, i: int) -> Match | None:
    """"*See* mr jones to the front door", "see her out", "see the guest in": "see" with a person (a name, a
    title, an object pronoun, or a noun the taxonomy lists as a person) and then where to or a particle of
    going is escorting them ("see the guest off" stays refused: "off" names no place). "see if ...", "see what
    is ...", "see the cup on the table" are not."""
    words = s.words
    verb, unit, afters = SEEN_TO
    if unit not in s.lexicon.units or i + 2 >= len(words) or words[i].lower != verb:
        return None
    k = i + 1
    if words[k].lower in ("him", "her", "them", "us", "me"):
        k += 1
    else:
        determined = words[k].lower in ("the", "our", "my", "your", "a", "this", "that")
        k += determined
        start = k
        while k < min(len(words), start + _TITLE_WORDS) and words[k].lower.rstrip(".").isalpha() and \
                words[k].lower not in afters and words[k].lower not in CLOSED:
            k += 1
        said = [w.lower for w in words[start:k]]
        named = any(capitalised(w) for w in words[start:k]) or bool(said and said[0].rstrip(".") in TITLES) or \
            len(said) == 1 and not determined and not in_dictionary(said[0])    # "see *helen* out": a name
        if not said or not (named or noun_lemma(said[-1]) in s.lexicon.people):
            return None
    if k >= len(words) or words[k].lower not in afters:
        return None
    return Match(1, (words[i].tagged(Tag.VERB, unit),), expect=False, verb=unit, using=False)


def _tell_to(s: State, i: int) -> Match | None:
    if s.speech and s.prev_tag() in (Tag.WORD, Tag.NAME, Tag.PRON) and i + 1 < len(s.words) and s.verb_at(i + 1):
        return s.emit(i, 1, Tag.WH)                               # "tell Maria *to* come downstairs"
    return None


def _told_to_do(s: State, i: int) -> Match | None:
    words = s.words
    if not (s.speech and s.prev_tag() in (Tag.WORD, Tag.NAME, Tag.PRON) and i + 1 < len(words)):
        return None
    low = words[i + 1].lower
    if capitalised(words[i + 1]) or low in CLOSED or verb_lemma(low) != low or not in_verb_tables(low) or \
            s.verb_at(i + 1):
        return None
    end = s.speech_end(i + 1)                                     # "remind Anna to *call her mother*"
    return Match(end - i, (words[i].tagged(Tag.WH), s.emit(i + 1, end - i - 1, Tag.SAID).words[0]))


_ASKED_PERSON_WORDS = 8
"""The most words the person asked to follow may have ("the man in the red hat by the door")."""


def _follow_asked_at(s: State, i: int) -> int:
    """Where "to follow you" starts after the person asked at ``i`` ("ask *Anna* to follow you"; 0: none): the words
    between name a person (a name, a pronoun of a person, or a noun of people) and hold no verb or punctuation."""
    words = s.words
    unit, _, asked = FOLLOW_ASKED
    person = False
    for k in range(i, min(len(words), i + _ASKED_PERSON_WORDS)):
        low = words[k].lower
        if k > i and person and low == "to" and longest_phrase(words, k, asked):
            return k
        if low == "to":
            return 0                                              # "ask Anna to bring ...": something else asked
        if not low.isalpha() and "'" not in low or low in END_MARKS or k == i and s.verb_at(k) is not None:
            return 0                                              # (a verb only where the person would start)
        person = person or capitalised(words[k]) or low in PERSON_PRONOUNS or low == "them" or \
            low in s.lexicon.people or noun_lemma(low) in s.lexicon.people
    return 0


def _follow_asked(s: State, i: int) -> Match | None:
    unit, asking, _ = FOLLOW_ASKED
    if s.words[i].lower not in asking or unit not in s.lexicon.units or not _follow_asked_at(s, i + 1):
        return None
    return Match(1, (merge(s.words, i, 1, Tag.VERB, unit),), expect=False, verb=unit, using=False)


def _follow_asked_dropped(s: State, i: int) -> Match | None:
    unit, asking, asked = FOLLOW_ASKED
    if s.verb_index < 0 or s.out[s.verb_index].info != unit or s.out[s.verb_index].lower not in asking:
        return None
    n = longest_phrase(s.words, i, asked)
    return Match(n) if n else None                               # "ask Anna *to follow you* to the kitchen"


def _purpose(s: State, i: int) -> Match | None:
    if s.purpose(i):
        return Match(1, (s.words[i].tagged(Tag.SEP),), expect=True)   # "take the remote to turn on the lamp"
    return None


def _path_at(words: list[Word], k: int) -> bool:
    """Whether a preposition of a path ("to", "into", "onto") starts at ``k``."""
    n = match_phrase(words, k, PREPOSITIONS) if k < len(words) else 0
    return bool(n) and PREPOSITIONS[" ".join(w.lower for w in words[k:k + n])] in PATH_ALONE


def _moved_yourself(s: State, i: int) -> Match | None:
    """"get *yourself* to the bedroom", "bring yourself over to the sofa": a verb that moves what it takes to a
    goal, said of the robot itself ("yourself", right after the verb) and then a path ("to", "into", "onto",
    after a particle or not), is going there (``PATH_MEANS``): the verb is read as going, "yourself" with it."""
    words, out = s.words, s.out
    if PATH_MEANS not in s.lexicon.units or s.verb_index != len(out) - 1 or out[-1].tag != Tag.VERB or \
            str(out[-1].info) not in s.lexicon.goals or str(out[-1].info) == PATH_MEANS:
        return None
    if not _path_at(words, i + 1) and not (i + 1 < len(words) and words[i + 1].lower in PARTICLES and
                                          _path_at(words, i + 2)):
        return None                                               # "bring yourself *over* to the sofa"
    verb = out[-1]
    return Match(1, last=Word(s.text_of(verb.start, words[i].end), verb.start, words[i].end, Tag.VERB, PATH_MEANS))


SPLIT_PARTICLE = Rule("split particle", _split_particle, (
    Example("pick the cup up", "up", Tag.PARTICLE),
    Example("turn the lamp on", "on", Tag.PARTICLE),
    Example("I'd like the heater turned on", "turned on", Tag.PARTICLE),
), None, "the particle of a verb split around its object, found when the verb was")
USE = Rule("use X to V", _use, (
    Example("use a knife to slice the apple", "use", Tag.PREP),
), frozenset(["use", "using"]), "'use X to V': X is what V is done with")
LEFT_ALONE = Rule("leave with nothing after it", _left_alone, (
    Example("grab the cup and leave", "leave", Tag.VERB),
    Example("put the mug away, then leave now.", "leave", Tag.VERB),
), None, "a unit that puts its object somewhere, said with nothing after it: going away (english.DEPARTURE_MEANS)")
VERB = Rule("verb", _verb, (
    Example("tell me how many cups are on the table", "tell me how many", Tag.VERB),
    Example("putting the cup on the table", "putting", Tag.VERB),
), None, "the longest lexical unit of the library starting at the word, in any inflection")
SEEN_TO_RULE = Rule("see someone to a place", _seen_to, (
    Example("see mr jones to the front door", "see", Tag.VERB),
    Example("please see the guest out", "see", Tag.VERB),
    Example("see her to the exit", "see", Tag.VERB),
    Example("see helen out", "see", Tag.VERB),
    Example("see mr. jones to the door", "see", Tag.VERB),
), frozenset([SEEN_TO[0]]), "'see X to Y', 'see X out': escort X (Guide), a person said after 'see'")
TELL_TO = Rule("told to", _tell_to, (
    Example("tell Maria to come downstairs", "to", Tag.WH),
), frozenset(["to"]), "'to' after the person a verb of saying tells")
TOLD_TO_DO = Rule("told to do what the robot cannot", _told_to_do, (
    Example("remind Anna to call her mother", "call her mother", Tag.SAID),
    Example("tell the guest to sit", "sit", Tag.SAID),
), frozenset(["to"]), "'to' and a verb of English no frame has, after the person a verb of saying tells: what is "
   "said (what Anna is to do, not the robot)")
FOLLOW_ASKED_RULE = Rule("asked to follow", _follow_asked, (
    Example("ask Anna to follow you to the kitchen", "ask", Tag.VERB),
    Example("tell the man in the red hat to come with you", "tell", Tag.VERB),
), FOLLOW_ASKED[1], "'ask X to follow you (to Y)': guide X (to Y)",
   needs=frozenset(p.split()[1] for p in FOLLOW_ASKED[2]))       # "follow", "come", ...: a word of each phrase
FOLLOW_ASKED_DROPPED = Rule("asked to follow: what is asked", _follow_asked_dropped, (
    Example("ask Anna to follow you to the kitchen", "to follow you", ""),
), frozenset(["to"]), "the 'to follow you' of 'ask X to follow you': dropped, the verb is the guiding")
PURPOSE = Rule("clause of purpose", _purpose, (
    Example("take the remote to turn on the lamp", "to", Tag.SEP),
), frozenset(["to"]), "'to' and a verb of the library with its object: a clause of its own")
MOVED_YOURSELF = Rule("a verb of moving said of yourself", _moved_yourself, (
    Example("get yourself to the bedroom", "get yourself", Tag.VERB),
    Example("bring yourself over to the sofa", "bring yourself", Tag.VERB),
), frozenset(["yourself"]), "'get yourself to X', 'take yourself to X': the robot moves itself there: go to X")
