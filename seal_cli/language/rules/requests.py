"""Requests said without an imperative verb: a bare question ("What's on the table?", "Where is the
cup?"), the speaker's wish ("I'd like the red mug", "Can I have a plate?"), and "let me know ...".

Each is read as the plain command it means — "tell me ...", "find ...", "bring me ...", "tell me
..." (the paraphrases are English, in :mod:`seal_cli.language.english`; their verb must be a
lexical unit of the library). What the paraphrase adds and the command did not say (the verb of
"What is on the table?", the "me" of "I'd like a cup") is a word of no width: an element that was
left unsaid (its ``text`` is empty).
"""

from __future__ import annotations

from collections.abc import Sequence

from seal_cli.language.asking import person_subject
from seal_cli.language.english import (
    ASKED_ALONE,
    BE_WORDS,
    CHECK_WHETHER,
    CONTRACTED,
    DETERMINERS,
    DIRECTIONS,
    END_MARKS,
    ENSURED,
    FINITE,
    FOUND_OUT,
    HELP_MEANS,
    HELPED_MOVING,
    HERE_WORDS,
    IMPERSONAL_WISHES,
    INFORMATION,
    KEEPING,
    KNOW_WISHES,
    LEFT_ASKED,
    LET_KNOW,
    LOCATED,
    LOCATIVE,
    NP_OPENERS,
    NUMBER_MEANS,
    NUMBER_OF,
    NUMBERS,
    OBJECT_PRONOUNS,
    OBLIGED,
    OPERATING,
    PARTICLES,
    PATH_ALONE,
    PATH_MEANS,
    PLACE_MEANS,
    POLITE,
    POSSESSIVES,
    PREPOSITIONS,
    PRONOUNS,
    QUESTION_MEANS,
    QUESTION_WORDS,
    RELATIVES,
    REQUEST_MEANS,
    REQUESTS,
    SEEN_ASKED,
    STATE_ADVERBS,
    STATE_ASKERS,
    STATE_MEANS,
    STATE_PARTICLES,
    SWITCHED_MEANS,
    TIME_WORDS,
    TOPICS,
    TOTALS,
    WH_WORDS,
    WHERE_ASKERS,
    WHERE_BE,
    WHERE_DID,
    WHERE_MEANS,
    WHERE_QUESTIONS,
    WISHED_PLACED,
    WISHED_PLACES,
    is_room_word,
)
from seal_cli.language.morphology import (
    gerund_lemma,
    in_dictionary,
    in_verb_tables,
    is_adjective,
    is_adverb,
    is_plural,
    noun_lemma,
    participles,
    parts_of_speech,
    verb_lemma,
)
from seal_cli.language.rule import START, Example, Match, Rule
from seal_cli.language.rules.politeness import asked_again_at
from seal_cli.language.rules.verbs import left_in_state
from seal_cli.language.state import CLOSED, State, first_words, longest_phrase, lower_case_name, match_phrase, merge
from seal_cli.language.tags import Tag
from seal_cli.language.tokens import Word, capitalised

_WHERE_FIRST = first_words(WHERE_QUESTIONS)
_REQUEST_FIRST = first_words(REQUESTS)
_SPEAKER = "me"


def _unsaid(at: int, tag: str, info: object = None, lower: str = "") -> Word:
    """A word the command implies but did not say, at character ``at``."""
    return Word("", at, at, tag, info, lower)


def _phrase(s: State, i: int, table: frozenset[str]) -> int:
    """How many words of a phrase of ``table`` start at ``i`` (0: none), longest first."""
    return longest_phrase(s.words, i, table)


def _sentence_asks_nothing_else(s: State, i: int) -> bool:
    """Whether no clause with a verb of the library follows in the sentence from ``i`` ("I need a hand,
    *could you bring* the box" is a statement and a request)."""
    words = s.words
    for k in range(i, len(words)):
        low = words[k].lower
        if low in END_MARKS:
            return True
        if low in (",", ";", "and", "then", "so") and s.verb_after(k + 1):
            return False
    return True


def _question(s: State, i: int) -> Match | None:
    words = s.words
    if QUESTION_MEANS not in s.lexicon.units or i + 1 >= len(words) or words[i + 1].lower in END_MARKS:
        return None
    nxt = words[i + 1].lower
    if nxt not in ("is", "are", "'s", "was", "were") and not nxt.isalpha() and not nxt.isdigit() and \
            not _contracted_subject(nxt) or \
            _phrase(s, i, _PSEUDO_CLEFTS):      # "which *3* items on the table are the thinnest?" (words41)
        return None                               # "what I need is X": a wish (``WISHED_STATE``), no question
    end = _asked_again_cut(s, i, s.speech_end(i))  # the question, whatever its shape, is what to tell
    if end - i < 3 and words[end - 1].lower in ("is", "are", "'s", "was", "were"):
        return None                               # "what is": no question yet
    return Match(end - i, (_unsaid(words[i].start, Tag.VERB, QUESTION_MEANS), s.emit(i, end - i, Tag.SAID).words[0]),
                 expect=False, verb=QUESTION_MEANS, using=False)


def _contracted_subject(low: str) -> bool:
    """Whether a word is a subject pronoun contracted with its verb ("*they're*", "she's", "you've"): a question goes
    on with it as with "they are" ("... and what *they're* wearing", words48: was an unknown verb "what")."""
    subject, _, rest = low.partition("'")
    return bool(rest) and subject in _SUBJECT_PRONOUNS and "'" + rest in CONTRACTED


_SUBJECT_PRONOUNS = frozenset(["i", "you", "he", "she", "it", "we", "they", "there"])


def _asked_again_cut(s: State, i: int, end: int) -> int:
    """Where a question from ``i`` to ``end`` ends once the same question asked again after its last comma is left out
    ("who is at the door*, do you think*?": the hearer's opinion asked, not part of what to tell; words39)."""
    words = s.words
    for c in range(end - 1, i + 1, -1):
        if words[c].lower == ",":
            return c if asked_again_at(s, c + 1) >= end - c - 1 > 0 else end
    return end


def _where(s: State, i: int) -> Match | None:
    words = s.words
    n = _phrase(s, i, WHERE_QUESTIONS)
    if not n or WHERE_MEANS not in s.lexicon.units or not s.np_starts(i + n) or \
            words[i + n - 1].lower in WHERE_DID[1] and words[i + n].lower in WHERE_DID[2] or \
            words[i].lower in WHERE_DID[0] and _where_did(s, i) is not None or _phrase(s, i, REQUESTS):
        return None                         # "where did *I* leave my glasses", "where did *ben* put it": WHERE_DID's;
        #   "is there any chance I could have a cushion": a request (words30), no chance sought
    text = s.text_of(words[i].start, words[i + n - 1].end) or " ".join(w.text for w in words[i:i + n])
    return Match(n, (Word(text, words[i].start, words[i + n - 1].end, Tag.VERB, WHERE_MEANS),), expect=False,
                 verb=WHERE_MEANS, using=False)


def _person_word(s: State, k: int) -> bool:
    """Whether the one word at ``k`` names a person: a noun the taxonomy lists as one ("mum", "the *guest*"), "he" or
    "she", or a name (capitalised, or no word the dictionary lists, and no thing): "where did *ben* leave the
    remote?", "is *ben* waiting in the kitchen?"."""
    word = s.words[k]
    low = word.lower
    if low in s.lexicon.people or (noun_lemma(low) or low) in s.lexicon.people or low in _PEOPLE_PRONOUNS:
        return True
    return low.isalpha() and low not in s.lexicon.things and low not in CLOSED and (
        capitalised(word) or not parts_of_speech(low))


def _where_did(s: State, i: int) -> Match | None:
    words = s.words
    where, auxiliaries, subjects = WHERE_DID
    if i + 4 >= len(words) or WHERE_MEANS not in s.lexicon.units or words[i + 1].lower not in auxiliaries:
        return None
    v = i + 3 if words[i + 2].lower in subjects or _person_word(s, i + 2) else \
        _person_said(s, i + 2) or _subject_said(s, i + 2)
    if v is None or v + 1 >= len(words) or not s.np_starts(v + 1):
        return None
    said, lemma = words[v].lower, verb_lemma(words[v].lower)
    perfect = words[i + 1].lower in ("have", "has") and lemma is not None and said in participles(lemma)
    if lemma != said and not perfect:    # "where have the children *left* their shoes?": the perfect's participle
        return None
    end = words[v].end
    return Match(v + 1 - i, (Word(s.text_of(words[i].start, end), words[i].start, end, Tag.VERB, WHERE_MEANS),),
                 expect=False, verb=WHERE_MEANS, using=False)


def _past_openers(words: Sequence[Word], k: int) -> int | None:
    """Where the words after a noun phrase's determiners or possessives at ``k`` start ("where did *the* kids ...",
    "*our* dog"); None when no opener is said at ``k``."""
    j = k
    while j < len(words) and words[j].lower in NP_OPENERS:
        j += 1
    return j if j > k else None


def _person_said(s: State, k: int) -> int | None:
    """Where a noun phrase of people at ``k`` that opens with a determiner or a possessive ends ("where did *the kids*
    leave the ball?", "where does *my little brother* keep his shoes"): after a few words, a noun the taxonomy lists
    as a person; None when the phrase names no person ("where did the cat ...")."""
    words = s.words
    j = _past_openers(words, k)
    if j is None:
        return None
    for h in range(j, min(j + 3, len(words))):
        low = words[h].lower
        if not low.isalpha() or low in CLOSED:
            return None
        if (noun_lemma(low) or low) in s.lexicon.people:
            return h + 1
    return None


def _subject_said(s: State, k: int) -> int | None:
    """Where a noun phrase of no person at ``k`` that opens with a determiner or a possessive ends before a verb of
    English and its object ("where did *the cat* hide the ball?", "where did *our dog* bury its bone": words47, a
    Find of the cat and a Place of the ball, or refused at the verb): the verb's index, when the word after one to
    three words of the phrase is a verb's base form or participle with a phrase after it; None otherwise."""
    words = s.words
    j = _past_openers(words, k)
    if j is None:
        return None
    for h in range(j, min(j + 3, len(words) - 2)):
        low = words[h].lower
        if not low.isalpha() or low in CLOSED:
            return None
        verb = words[h + 1].lower
        if in_verb_tables(verb) and verb not in CLOSED and verb_lemma(verb) is not None and s.np_starts(h + 2):
            return h + 1
    return None


_CAN_YOU = frozenset(["can you", "could you", "can't you", "couldn't you", "you can", "you could"])
"""Politeness that may be the question whether the robot can see a thing ("*can you* see the cat anywhere?"; said
with the subject first and a tag, "*you can* see the cup, can't you?", words26)."""


def _asked_alone_last(s: State, i: int) -> bool:
    """Whether the sentence from ``i`` is a question ending the command (its "?" or the end of the text), with no
    particle "out" in it: "can you see the cat anywhere?" asks to find it; "can you see the man by the door? greet
    him" introduces him (a question of perception before the command, words24), "can you see the guest out" is
    Guide's."""
    words = s.words
    end = _sentence_end(s, i)
    return (end == len(words) or words[end].lower == "?" and all(w.lower in END_MARKS for w in words[end:])) and \
        not any(w.lower == "out" for w in words[i:end])          # words48: its "?" often left out ("can you see X")


_DO_SEEN = frozenset(["do", "does", "don't", "doesn't"])
"""The auxiliaries of the present before a verb of perceiving: a question of what is seen now, asked last ("*do
you see* anyone in the kitchen?": find them); said before a command it introduces what the command's pronoun
stands for ("do you see the man by the window? greet him", ``SEEN_QUESTIONS``)."""


def _seen_asked(s: State, i: int) -> Match | None:
    words = s.words
    auxiliaries, subjects, _ = SEEN_ASKED
    if WHERE_MEANS not in s.lexicon.units:
        return None
    if i + 3 < len(words) and words[i].lower in auxiliaries and words[i + 1].lower in subjects:
        v = i + 2
    elif i + 3 < len(words) and words[i].lower in _DO_SEEN and words[i + 1].lower in subjects and \
            _asked_alone_last(s, i):
        v = i + 2                                    # "do you see anyone in the kitchen?" ending the command (words33)
    elif s.out and s.out[-1].tag == Tag.POLITE and s.out[-1].lower in _CAN_YOU and s.verb_at(i) is None and \
            i + 1 < len(words) and _asked_alone_last(s, i):
        v = i                                        # "can you | see the cat anywhere?" (words25)
    else:
        return None
    return seen_asked_from(s, i, v)


def seen_asked_from(s: State, i: int, v: int) -> Match | None:
    """The words ``i`` to a verb of perceiving at ``v`` and a phrase after it ("*have you seen* my keys",
    "*has anyone come across* the cat") as the search they ask (``WHERE_MEANS``), else None."""
    words = s.words
    seeing = SEEN_ASKED[2]
    for n in (2, 1):                                 # "come across" before "see"
        if v + n > len(words):
            continue
        said = [verb_lemma(words[v].lower) or words[v].lower, *(w.lower for w in words[v + 1:v + n])]
        if " ".join(said) in seeing and v + n < len(words) and s.np_starts(v + n):
            end = words[v + n - 1].end
            return Match(v + n - i, (Word(s.text_of(words[i].start, end), words[i].start, end, Tag.VERB,
                                          WHERE_MEANS),), expect=False, verb=WHERE_MEANS, using=False)
    return None


def _where_asker(s: State, i: int) -> int:
    """How many words of a lead-in asking where start at ``i``: a phrase of ``WHERE_ASKERS``, or its verb
    as a gerund after "would you mind" ("*showing me* where the remote is")."""
    n = _phrase(s, i, WHERE_ASKERS)
    if n or i + 1 >= len(s.words):
        return n
    lemma = gerund_lemma(s.words[i].lower)
    return 2 if lemma and f"{lemma} {s.words[i + 1].lower}" in WHERE_ASKERS else 0


def _asked_where(s: State, i: int) -> Match | None:
    """"*Do you know where* the tea spoon is?", "*can you tell me where* the keys are?", "*would you know
    where I left* my phone?": a question about what the robot knows of where a thing is asks it to find
    the thing (``WHERE_MEANS``), as "where is the tea spoon?" does. The lead-in, "where" and, when a
    subject and its verb follow ("where *I left*"), those are the verb; a phrase must follow."""
    words = s.words
    n = _where_asker(s, i)
    k = i + n
    if not n or WHERE_MEANS not in s.lexicon.units or k >= len(words) or words[k].lower != "where":
        return None
    k += 1
    subjects, verb = WHERE_DID[2], k + 1
    if k < len(words) and words[k].lower in subjects and verb < len(words) and words[verb].lower.isalpha() and \
            words[verb].lower not in DETERMINERS and words[verb].lower not in WHERE_BE:
        k = verb + 1                              # "where *I left* my phone"
    if not s.np_starts(k) or words[k].lower in PRONOUNS:
        return None                               # "tell me where *it* is": what was found, told
    end = words[k - 1].end
    return Match(k - i, (Word(s.text_of(words[i].start, end), words[i].start, end, Tag.VERB, WHERE_MEANS),),
                 expect=False, verb=WHERE_MEANS, using=False)


def _where_be(s: State, i: int) -> Match | None:
    """The "is" of "do you know where the tea spoon *is*?": after the thing asked about, at the end of the
    sentence, dropped ("where" was read as "find")."""
    if s.verb_index < 0 or s.out[s.verb_index].info != WHERE_MEANS or \
            not any(w in ("where", "where's") for w in s.out[s.verb_index].lower.split()) or \
            s.prev_tag() not in (Tag.WORD, Tag.NAME) and not (s.prev_tag() == Tag.PARTICLE and
                                                            is_adverb(s.out[-1].lower)):
        return None
    n = _phrase(s, i, WHERE_BE) or _where_kept(s, i)
    if not n or i + n < len(s.words) and s.words[i + n].lower not in END_MARKS:
        return None
    return Match(n)


def _where_kept(s: State, i: int) -> int:
    """1 when the word at ``i`` is the past participle of a passive "where" question ("where is the ladle *kept*?",
    "where are the spoons usually *stored*?"; words37): where the thing is, asked; the participle says nothing more
    and was read as the thing's noun ("Find *kept*")."""
    where = s.out[s.verb_index].lower.split()
    low = s.words[i].lower
    lemma = verb_lemma(low)
    if not (where[-1:] and where[-1] in ("is", "are", "where's") or "'s" in where) or lemma is None or \
            low not in participles(lemma):
        return 0
    return 1


_WHETHER_IS = frozenset(["is", "are", "isn't", "aren't"])
_STATE_CONTRACTED = frozenset(["'s", "'re"])
""""is"/"are" said joined to the phrase ("the oven*'s* off, isn't it?": a state said, then its tag, words26)."""
_PEOPLE_PRONOUNS = frozenset(["he", "she"])
_WHETHER_WHERE = frozenset(["in", "on", "at", "inside", "near", "by", "under", "beside", "behind"])
_AT_HOME = DIRECTIONS
"""Being *home* is being in the house ("is mum home?", "see if anyone is home"): where someone is, asked as finding
them in the whole house, never a state of theirs to look at; so is being *upstairs*, *downstairs*, *outdoors*
(``english.DIRECTIONS``: "is anybody upstairs?" was "unknown verb 'is'", words30)."""
_WHETHER_THERE = _WHETHER_WHERE | _AT_HOME | frozenset(["there", "here"])
"""After "see if anyone is": a place said, or pointed at ("... is *there*", where the robot went)."""


def _whether_is(s: State, i: int) -> Match | None:
    """"*Is* Ben in the kitchen?", "*are* the apples in the fridge?": whether a thing or person is somewhere,
    asked as "find ..." (``WHERE_MEANS``); a phrase must follow, and a preposition of place after it in the
    same sentence, before any other verb."""
    words = s.words
    if WHERE_MEANS not in s.lexicon.units or not _place_asked(s, i + 1) or words[i + 1].lower in _WHETHER_IS:
        return None
    return Match(1, (words[i].tagged(Tag.VERB, WHERE_MEANS),), expect=False, verb=WHERE_MEANS, using=False)


_INDEFINITES = frozenset(["anyone", "anybody", "anything", "someone", "somebody", "something"])
_ANY_ASKED = _INDEFINITES | frozenset(["any"])
"""Words that open a question of whether some such thing is somewhere, said without "is there"."""


def _any_asked(s: State, i: int) -> Match | None:
    """"*Anyone* in the bathroom?", "any milk in the fridge?", "someone at the door?", "any biscuits left?": a
    sentence with no verb that asks whether a thing or person is somewhere or remains ("is there" left unsaid: a
    phrase opened by "any-"/"some-", then a preposition of place and its phrase, or "left") is "find ..."
    (``WHERE_MEANS``), as "is anyone in the bathroom?" is."""
    words = s.words
    if WHERE_MEANS not in s.lexicon.units or words[i].lower not in _ANY_ASKED or not s.np_starts(i):
        return None
    end = _sentence_end(s, i)
    left = [k for k in range(i + 2, end) if words[k].lower in _REMAINING and words[k - 1].lower.isalpha()]
    if not (left or _place_asked(s, i)) or any(
            k not in left and (s.verb_at(k) is not None and words[k - 1].lower not in NP_OPENERS and
                               not _progressive(s, i, k) and not _compound_head(s, i, k) or
                               words[k].lower in BE_WORDS or words[k].lower in (",", ";", "and", "then") or
                               words[k].lower in FINITE)
            for k in range(i + 1, end)):
        return None               # "any milk in the fridge *is* fine", "someone in the hall *has* a question"
    tag = Tag.DET if words[i].lower == "any" else Tag.PRON
    return Match(1, (_unsaid(words[i].start, Tag.VERB, WHERE_MEANS), words[i].tagged(tag)), expect=False,
                 verb=WHERE_MEANS, using=False)


def _compound_head(s: State, j: int, k: int) -> bool:
    """Whether the word at ``k`` ends a phrase opened by a determiner at ``j`` as the head of a compound, not a verb
    ("any cleaning *supplies* in the bathroom?", "any dish *towels* left?"; words37): a plural noun right after
    another word of the phrase, before a preposition of place, "left" or the sentence's end."""
    words = s.words
    if k < j + 2 or words[j].lower not in NP_OPENERS or not words[k - 1].lower.isalpha() or k + 1 >= len(words):
        return False
    after = words[k + 1].lower
    return (after in LOCATIVE or after in END_MARKS or after in _REMAINING) and is_plural(words[k].lower) and \
        "noun" in parts_of_speech(words[k].lower)


def _place_asked(s: State, j: int) -> bool:
    """Whether a phrase starts at ``j`` and a preposition of place and its phrase follow it in the same sentence,
    before any other verb ("Ben | in the kitchen", "my keys | in the car")."""
    words = s.words
    if not s.np_starts(j):
        return False
    for k in range(j + 1, len(words)):
        low = words[k].lower
        if low in END_MARKS and _place_fronted(s) and any(_progressive(s, j, m) for m in range(j + 1, k)):
            return True                           # "In the bedroom, is anyone lying down?" (words33)
        if low in END_MARKS or low in (",", ";", "and", "then") or s.verb_at(k) is not None and \
                words[k - 1].lower not in NP_OPENERS and not _progressive(s, j, k) and not _compound_head(s, j, k):
            return False                          # a verb ("the *pan*": a noun after a determiner)
        if low in _WHETHER_WHERE:
            return s.np_starts(k + 1)
        if low in _AT_HOME:                      # "is Ben home?": ending the sentence, the house is the place
            while k + 1 < len(words) and words[k + 1].lower in _AFTER_STATE:
                k += 1                            # "is mum home *yet*?"
            return k + 1 == len(words) or words[k + 1].lower in END_MARKS
    return False


def _place_fronted(s: State) -> bool:
    """Whether the words tagged so far end in a phrase of place said first and its comma ("*In the bedroom,* is
    anyone lying down?"): the place a question asks about, said before it (words33)."""
    out = s.out
    if not out or out[-1].lower != ",":
        return False
    k = len(out) - 2
    while k > 0 and out[k].tag in _PHRASE_TAGS and out[k].tag != Tag.PREP:
        k -= 1
    if k < 0 or out[k].tag != Tag.PREP or out[k].info not in LOCATIVE or k >= len(out) - 2 or \
            k > 0 and out[k - 1].tag not in (Tag.SEP, Tag.END, Tag.POLITE):
        return False
    last = out[-2].lower                          # a place: a thing the taxonomy knows, or a room ("the meantime": no)
    return noun_lemma(last) in s.lexicon.things or is_room_word([w.lower for w in out[k + 1:-1]])


def _progressive(s: State, j: int, k: int) -> bool:
    """Whether the word at ``k`` is the -ing form of a progressive said of the phrase at ``j`` after a verb of
    being ("is someone *waiting* at the door?", "is Ben *sitting* in the kitchen?"): what the one asked of is
    doing where they are, which no command says; the question is still whether they are there."""
    low = s.words[k].lower
    asked = j > 0 and s.words[j - 1].lower in BE_WORDS or k == j + 1 and s.words[j].lower in _INDEFINITES
    return asked and gerund_lemma(low) not in (None, low) and s.words[k - 1].lower not in BE_WORDS


def _person_somewhere(s: State, j: int) -> bool:
    """Whether the phrase at ``j``, after a verb of being, names a person said to be doing something somewhere ("is
    *ben* waiting in the kitchen?", "is *the man in the red shirt* waiting at the door?"): a progressive (the -ing
    form of a verb, :func:`_progressive`) right before a preposition of place and its phrase, and the phrase's head
    (its last word before a preposition) a person — a noun of the taxonomy's people, "he"/"she", or one word that
    is a name (capitalised, or no word the dictionary lists and no thing). Where a person is asked is finding them
    there, whatever they are doing; of a thing the -ing form stays its state ("is the dishwasher running?"). So is an
    adjective of state said of the person before the place ("is lucy still *asleep* in her room?", words25:
    :func:`_person_state`)."""
    words = s.words
    if not _place_asked(s, j):
        return False
    end = _sentence_end(s, j)
    k = next((k for k in range(j + 1, end - 1) if (_progressive(s, j, k) or _person_state(s, j, k)) and
              words[k + 1].lower in _WHETHER_WHERE and s.np_starts(k + 2)), None)
    if k is None:
        return False
    cut = next((m for m in range(j + 1, k) if words[m].lower in PREPOSITIONS), k)
    while cut - 1 > j and words[cut - 1].lower in STATE_ADVERBS:
        cut -= 1                                  # "is lucy *still* asleep in her room?": the adverb is no head
    low = words[cut - 1].lower
    return low in s.lexicon.people or (noun_lemma(low) or low) in s.lexicon.people or cut == j + 1 and \
        _person_word(s, j)


def _person_state(s: State, j: int, k: int) -> bool:
    """Whether the word at ``k`` is an adjective said of the phrase at ``j`` after a verb of being, maybe after
    adverbs ("is lucy *still asleep* in her room?", "is grandpa awake in the lounge?"): the state a person is in
    where they are, which, like a progressive, leaves the question whether they are there."""
    low = s.words[k].lower
    return j > 0 and s.words[j - 1].lower in BE_WORDS and k > j and low.isalpha() and low not in CLOSED and \
        is_adjective(low) and s.verb_at(k) is None


_AFTER_STATE = frozenset(["properly", "fully", "completely", "yet", "now", "already", "again"])
"""Adverbs said after a state or a place of being, ending the question ("is the door shut *properly*?", "is mum
home *yet*?"): how far or since when, no state or place of their own (words26)."""


ASKED = "asked"
"""The info of the ``COND`` word that keeps the state a yes/no question asks ("open" of "is the fridge open?")."""


def _is_state(s: State, low: str) -> bool:
    """Whether a word can be the state a yes/no question asks of a thing: an adjective ("open", "clean",
    "empty"), a particle of state ("on", "off"), a frame's result word, or a participle ("locked", "shut",
    "running"); never a place word ("upstairs") or a preposition."""
    if low in HERE_WORDS or low in PREPOSITIONS or low in DETERMINERS or low in BE_WORDS or low in _AT_HOME:
        return low in STATE_PARTICLES
    if low in STATE_PARTICLES or low in s.lexicon.results or is_adjective(low):
        return True
    lemma = verb_lemma(low)
    return lemma is not None and lemma != low and (low in participles(lemma) or gerund_lemma(low) == lemma)


def _state_from(s: State, k: int, end: int) -> int | None:
    """Where the state said from word ``k`` begins, when words ``k .. end`` are adverbs of degree or time
    ("still") and then one word of state ending the clause at ``end``, or two joined by "or" ("sitting *or*
    standing", "open or closed": the alternatives a "whether A or B" asks, one state asked), each maybe with its
    particle ("sitting down or standing up", "switched on or off": words24), or one and "or not" ("locked or
    not"); else None."""
    words = s.words
    last = end - 1
    while last > k and words[last].lower in _AFTER_STATE:
        last -= 1                                 # "is the fridge door shut *properly*?", "is the oven on *yet*?"
    if last - 1 >= k and words[last - 1].lower == "or" and words[last].lower == "not":
        last -= 2                                 # "whether the door is locked *or not*": the state, either way
    if last < k or words[last].lower in STATE_ADVERBS:
        return None                              # "is the cup *still* on the table": an adverb, no state of its own
    if _kinds_asked(s, k, last):
        return k                                 # "is the person at the bed *a man or a woman*?" (words41)
    for q in _state_starts(s, k, last):
        first = _state_starts(s, k, q - 2) if q - 2 >= k and words[q - 1].lower == "or" else []
        if q < last and not first and not _participle(s, q):
            continue                              # a particle only in alternatives: "is the light *on*" as before
        for p in first or [q]:                    # "sitting (down) or": the first alternative begins the state
            while first and p - 2 >= k and words[p - 1].lower == "," and _state_starts(s, k, p - 2):
                p = _state_starts(s, k, p - 2)[-1]  # "standing, sitting or lying": three alternatives (words41)
            while p > k and words[p - 1].lower in STATE_ADVERBS:
                p -= 1
            if p == k:
                return p
    return None


def _kinds_asked(s: State, k: int, last: int) -> bool:
    """Whether words ``k .. last`` are two kinds joined by "or", each a noun after "a" or "an" ("*a man or a
    woman*", "a boy or girl"), or one kind of person ("a woman"): which of them a thing or person is is asked, as
    "male or female" asks a state (words41: the alternatives were a phrase no element took, refused)."""
    words = s.words
    if words[k].lower in ("a", "an") and last == k + 1:
        return words[last].lower in s.lexicon.people      # "is the person at the door *a woman*?": one kind of person
    if words[k].lower not in ("a", "an") or last - k not in (3, 4) or words[k + 2].lower != "or":
        return False
    return (last - k == 3 or words[k + 3].lower in ("a", "an")) and \
        all(words[m].lower.isalpha() and words[m].lower not in CLOSED and s.verb_at(m) is None for m in (k + 1, last))


def _participle(s: State, q: int) -> bool:
    """Whether the word at ``q`` is a participle said after its phrase, before its particle ("is the light in the
    office *switched* on?", "are the lamps *turned* off?"): the state is the two words (words26: the participle
    was left in the phrase, "the light in the office switched"); an adjective before a particle ("is the *light*
    on?") stays the phrase's noun."""
    words = s.words
    low = words[q].lower
    lemma = verb_lemma(low)
    return q > 0 and words[q - 1].lower not in NP_OPENERS and lemma is not None and lemma != low and \
        low in participles(lemma)


def state_said(s: State, k: int, end: int) -> bool:
    """Whether words ``k .. end`` say a state as a yes/no question asks it (:func:`_state_from`): "locked", "still
    on", "open or closed"."""
    return _state_from(s, k, end) is not None


def _state_starts(s: State, k: int, last: int) -> list[int]:
    """Where a word of state ending at ``last`` may begin: the word itself, or the word before it when ``last`` is
    a particle after a state ("standing *up*", "sitting *down*"); none before ``k``."""
    words = s.words
    found = [last] if last >= k and _is_state(s, words[last].lower) and words[last].lower not in STATE_ADVERBS \
        else []
    if last - 1 >= k and words[last].lower in PARTICLES and _is_state(s, words[last - 1].lower) and \
            words[last - 1].lower not in STATE_ADVERBS:
        found.append(last - 1)
    return found


def _clause_stop(s: State, k: int) -> int:
    """Where a question said from ``k`` ends: the clause's end, or an "and"/"then" before it ("check if the door
    is closed *and* lock it": the next clause, whatever its verb)."""
    end = s.cond_end(k)
    end = next((j for j in range(k, end) if s.words[j].lower in ("and", "then")), end)
    return _listed_states_end(s, k, end)


def _listed_states_end(s: State, k: int, end: int) -> int:
    """Where a list of states a question asks ends when a comma at ``end`` joins a state before it to more ("is he
    *standing, sitting or lying down*?", words41: the comma ended the clause, the rest was refused); else ``end``.
    The list ends in "or" and a state, each state maybe with its particle."""
    words = s.words
    if end >= len(words) or words[end].lower != "," or end - 1 < k or not _state_starts(s, k, end - 1):
        return end
    j, joined = end, False
    while j < len(words) and words[j].lower in (",", "or"):
        joined = joined or words[j].lower == "or"
        m = j + 1
        if m >= len(words) or not _is_state(s, words[m].lower) or words[m].lower in STATE_ADVERBS:
            return end
        j = m + 1 + (m + 1 < len(words) and words[m + 1].lower in PARTICLES)
        if joined:
            return j if j >= len(words) or words[j].lower in END_MARKS or words[j].lower in (",", "?") else end
    return end


def _state_stop(s: State, k: int) -> int:
    """Where the state asked from ``k`` ends: the clause's end (:func:`_clause_stop`), or a place said after the
    state ("is the window open *in the bedroom*?"), which is where the thing is, not part of the state. A word of
    state right after a determiner is the phrase's noun, not a state said before the place ("is *the light* in the
    office on?": "light" is the thing, "on" the state asked; words26 — it was read as the state "light", the
    question became a search and "on" was dropped)."""
    end = _clause_stop(s, k)
    words = s.words
    timed = next((t for t in range(max(k + 1, end - 3), end) if match_phrase(words, t, TIME_WORDS) == end - t), None)
    if timed is not None:
        end = timed                              # "is Jane in the office *right now*?": a time, no state (words33)
    for p in range(k + 1, end - 1):
        if words[p].lower in _WHETHER_WHERE and s.np_starts(p + 1) and _state_from(s, k, end) is None and \
                any(_state_from(s, q, p) is not None and words[q - 1].lower not in NP_OPENERS
                    for q in range(k, p)) and \
                not any(s.verb_at(j) and words[j - 1].lower not in NP_OPENERS for j in range(p + 1, end)):
            return p
    return end


def _state_question_end(s: State, i: int) -> int | None:
    """The end of the clause from ``i`` when it is a phrase and then a state: "the fridge | open", "the cup on
    the table | clean", "the kitchen light | still on", "the window | open | in the bedroom"; the index where
    the state begins, else None."""
    words = s.words
    if not s.np_starts(i) or words[i].lower in ("there", "you", "i", "we"):
        return None
    end = _state_stop(s, i)
    for q in range(end - 1, i, -1):              # the state's first word: adverbs, then the state
        if _state_from(s, q, end) is None:
            continue
        before = words[q - 1].lower
        if before in NP_OPENERS or before in PREPOSITIONS or before in BE_WORDS or \
                before.isdigit() and not _numbered_name(s, q - 1, i):
            return None                          # "is the cup on *the counter*": a noun in a phrase
        if any(s.verb_at(k) and words[k - 1].lower not in NP_OPENERS
               and not s.np_starts(k - 1) for k in range(i + 1, q)):
            return None
        return q
    return None


def state_asked_at(s: State, k: int) -> bool:
    """Whether the words from ``k`` to the clause's end are the state a yes/no question of state asks ("is locker 2
    *open*?"), in a clause whose verb is that question's (``STATE_MEANS``): a number before them names the thing
    (a label), it counts nothing (e2e33)."""
    return s.verb_index >= 0 and s.out[s.verb_index].info == STATE_MEANS and k < len(s.words) and \
        _state_from(s, k, _state_stop(s, k)) == k


def _numbered_name(s: State, k: int, start: int) -> bool:
    """Whether the digits at ``k`` end a numbered name ("is *locker 2* open?", "is the light in *room 3* on?"): a
    noun before them, inside the phrase that starts at ``start`` (e2e33: the number made the state a noun's)."""
    if k - 1 < start:
        return False
    noun = s.words[k - 1].lower
    return noun.isalpha() and noun not in CLOSED and noun not in NP_OPENERS and noun not in PREPOSITIONS and \
        noun not in BE_WORDS


_ENSURED_BE = BE_WORDS | frozenset(["gets", "get", "stays", "stay", "remains", "remain"])


def _ensured_state(s: State, j: int) -> tuple[str, int] | None:
    """At the verb of being of "make sure the door *is closed*": the unit whose result the state is, and how
    many words (the verb of being, adverbs, the state) it takes to the clause's end; None when the state is no
    result of a lexical unit. "on"/"off" are switching (``SWITCHED_MEANS``), a participle its verb ("closed":
    "close"; "turned off": "turn off"), an adjective that is a verb's base form its verb ("open", "clean"), one a
    frame's postcondition says of its theme that frame's first unit ("hot": "heat")."""
    words = s.words
    if j >= len(words) or words[j].lower not in _ENSURED_BE:
        return None
    end = _clause_stop(s, j)
    while end > j and words[end - 1].lower in (",", "please"):
        end -= 1
    k = j + 1
    while k < end and words[k].lower in STATE_ADVERBS:
        k += 1
    state = [w.lower for w in words[k:end]]
    if state and state[-1] in ("now", "again"):
        state.pop()
    if len(state) == 1 and state[0] in SWITCHED_MEANS:
        unit = SWITCHED_MEANS[state[0]]
    elif len(state) in (1, 2) and (len(state) == 1 or state[1] in SWITCHED_MEANS):
        unit = " ".join([verb_lemma(state[0]) or state[0], *state[1:]])
    else:
        return None
    parts = tuple(unit.split())
    if parts not in s.lexicon.units.get(parts[0], ()):
        result = s.lexicon.results.get(state[0]) if len(state) == 1 and is_adjective(state[0]) else None
        return (result[1], end - j) if result is not None else None    # "make sure the soup is *hot*": heat it
    return unit, end - j


def _ensured(s: State, i: int) -> Match | None:
    """"*Make sure* the stove is off", "please ensure the door is closed": a state to bring about is the verb
    whose result it is (:func:`_ensured_state`), said of the phrase before the verb of being; "make sure" is
    that verb, and the state is dropped after the phrase (:data:`ENSURED_STATE`)."""
    words = s.words
    n = _phrase(s, i, ENSURED)
    k = i + n
    if n and k < len(words) and words[k].lower == "that":
        k += 1
    if not n or not s.np_starts(k) or words[k].lower in ("you", "i", "we", "there"):
        return None
    be = next((j for j in range(k + 1, _clause_stop(s, k)) if words[j].lower in _ENSURED_BE), None)
    found = None if be is None else _ensured_state(s, be)
    if found is None:
        return None
    end = words[k - 1].end
    return Match(k - i, (Word(s.text_of(words[i].start, end), words[i].start, end, Tag.VERB, found[0]),),
                 expect=False, verb=found[0], using=False)


def _ensured_dropped(s: State, i: int) -> Match | None:
    verb = s.out[s.verb_index] if s.verb_index >= 0 else None
    if verb is None or not any(verb.lower.startswith(p) for p in ENSURED) or s.prev_tag() not in (Tag.WORD, Tag.NAME):
        return None
    found = _ensured_state(s, i)
    return None if found is None or found[0] != verb.info else Match(found[1])


def _state_question(s: State, i: int) -> Match | None:
    """"*Is* the fridge open?", "are the windows in the bedroom shut", "is the kitchen light still on?": a
    yes/no question about a thing's state is checking the thing (``STATE_MEANS``, a unit of LookAt); the state
    is kept (``ASKED``, by :data:`STATE_ASKED`). Of an indefinite said with a place ("is *anyone* sitting at the
    table?", "are *any* of the guests waiting in the hallway?"), no thing to check is named: whether one is there
    is finding (``WHETHER_IS_RULE``); so is a person said to be doing something somewhere ("is *ben* waiting in the
    kitchen?", :func:`_person_somewhere`)."""
    if STATE_MEANS not in s.lexicon.units or _state_question_end(s, i + 1) is None or \
            s.words[i + 1].lower in _ANY_ASKED and _place_asked(s, i + 1) or _person_somewhere(s, i + 1):
        return None
    return Match(1, (s.words[i].tagged(Tag.VERB, STATE_MEANS),), expect=False, verb=STATE_MEANS, using=False)


def _left_asked(s: State, i: int) -> Match | None:
    """"*Did I leave* the stove on?", "*has anyone left* the back door open": whether someone left a thing in a
    state is whether it is in it (``LEFT_ASKED``): check the thing, the state kept (``STATE_ASKED``)."""
    words = s.words
    auxiliaries, subjects, left = LEFT_ASKED
    if i + 3 >= len(words) or STATE_MEANS not in s.lexicon.units or words[i].lower not in auxiliaries or \
            words[i + 1].lower not in subjects or words[i + 2].lower not in left:
        return None
    if _state_question_end(s, i + 3) is not None:
        means = STATE_MEANS
    elif WHERE_MEANS in s.lexicon.units and _place_asked(s, i + 3):
        means = WHERE_MEANS                       # "did I leave my keys in the car?": is it there, find it
    else:
        return None
    end = words[i + 2].end
    return Match(3, (Word(s.text_of(words[i].start, end), words[i].start, end, Tag.VERB, means),),
                 expect=False, verb=means, using=False)


_ASKERS = CHECK_WHETHER[0] | STATE_ASKERS
_ASKER_WORDS = max(len(p.split()) for p in _ASKERS)


def _asked_whether(s: State, i: int) -> Match | None:
    """"*Check if* the door is closed", "*tell me whether* the stove is on", "*let me know if* the keys are on the
    table", "*do you know if* the kettle is on": whether a thing is in a state is checking it (LookAt, the
    state kept); whether it is somewhere is finding it there (Find), as the question said alone is. The verb
    of saying or asking is no frame of its own: the question is the instruction."""
    words = s.words
    if not any(w.lower in CHECK_WHETHER[1] for w in words[i + 1:i + 2 + _ASKER_WORDS]):
        return None                               # no "if"/"whether" near: nothing asked (the common case)
    n = _phrase(s, i, _ASKERS)
    if not n or i + n + 1 >= len(words) or words[i + n].lower not in CHECK_WHETHER[1]:
        return None
    k = i + n + 1
    end = _clause_stop(s, k)
    be = next((j for j in range(k + 1, end) if words[j].lower in _WHETHER_IS), None)
    if be is not None and STATE_MEANS in s.lexicon.units and s.np_starts(k) and \
            _state_from(s, be + 1, end) is not None:
        last = words[k - 1].end
        return Match(k - i, (Word(s.text_of(words[i].start, last), words[i].start, last, Tag.VERB, STATE_MEANS),),
                     expect=False, verb=STATE_MEANS, using=False)
    return _check_whether(s, i, _ASKERS)


def _whether_unjoined(s: State, i: int) -> Match | None:
    """"go over to the table *see if* there are any fruits and bring me one": a question whether
    (:func:`_asked_whether`) said right after a clause's phrase with no joint starts a clause of its own (words42:
    "see" was read as a noun of the table, the question a condition, and nothing was sought)."""
    if s.verb_index < 0 or s.prev_tag() not in (Tag.WORD, Tag.NAME, Tag.PRON, Tag.LABEL):
        return None
    found = _asked_whether(s, i)
    if found is None or not found.consumed or not found.words or found.words[0].tag != Tag.VERB:
        return None
    w = s.words[i]
    return found._replace(words=(Word("", w.start, w.start, Tag.SEP), *found.words))


def _state_asked(s: State, i: int) -> Match | None:
    """The state a yes/no question asks ("open" of "is the fridge open?", "is closed" of "check if the door is
    closed"): one ``COND`` word of info ``ASKED``, the "is" dropped."""
    if s.verb_index < 0:
        return None
    verb = s.out[s.verb_index]
    if verb.info != STATE_MEANS or not (verb.lower in _WHETHER_IS or verb.lower.split()[-1] in CHECK_WHETHER[1]
                                        or verb.lower.split()[-1] in LEFT_ASKED[2]):
        return None
    words = s.words
    k = i + 1 if words[i].lower in _WHETHER_IS | _STATE_CONTRACTED and verb.lower not in _WHETHER_IS else i
    if words[k - 1].lower in NP_OPENERS:
        return None                               # "is the *light* in the office on?": the phrase's noun
    end = _state_stop(s, k)
    if k >= end or _state_from(s, k, end) is None:
        return None
    end = _clause_stop(s, k)                      # a place said after the state is kept with it ("open in the
    text = s.text_of(words[k].start, words[end - 1].end)   # bedroom"): where the thing is, for the question
    if verb.lower.split()[0].endswith("n't") or words[i].lower.endswith("n't"):
        text = f"not {text}"                      # "isn't the fridge open?": whether it is not
    return Match(end - i, (Word(text, words[k].start, words[end - 1].end, Tag.COND, ASKED),))


def _check_whether(s: State, i: int, checks: frozenset[str] | None = None) -> Match | None:
    """"*See if* anyone is in the kitchen", "*check whether there's* a book on the shelf": whether someone or
    something is somewhere, asked as "find ..." (``WHERE_MEANS``); "there is" is read with the words before,
    and the "is" after a phrase is dropped (``WHETHER_BE``)."""
    words = s.words
    default, ifs, there_is = CHECK_WHETHER
    n = _phrase(s, i, checks or default)
    if not n or i + n + 1 >= len(words) or words[i + n].lower not in ifs or WHERE_MEANS not in s.lexicon.units:
        return None
    k = i + n + 1
    m = _phrase(s, k, there_is)
    if m and s.np_starts(k + m):
        k += m                                    # "check if there's ...": "is there ..."
    elif not s.np_starts(k) or not any(words[j].lower in _WHETHER_IS and words[j + 1].lower in _WHETHER_THERE
                                       for j in range(k + 1, min(len(words) - 1, s.cond_end(k)))):
        return None                               # "see if the soup is hot": no place asked of
    end = words[k - 1].end
    return Match(k - i, (Word(s.text_of(words[i].start, end), words[i].start, end, Tag.VERB, WHERE_MEANS),),
                 expect=False, verb=WHERE_MEANS, using=False)


def _found_out(s: State, i: int) -> Match | None:
    """"*Find out who* is in the hall", "check what's in the fridge", "see who is at the door": a verb of checking
    and a question word asks the question: "tell me who is in the hall" (``QUESTION_MEANS``, the question said)."""
    words = s.words
    n = _phrase(s, i, CHECK_WHETHER[0])
    if not n or QUESTION_MEANS not in s.lexicon.units or i + n >= len(words) or words[i + n].lower not in FOUND_OUT:
        return None
    end = s.speech_end(i + n)
    if end - (i + n) < 2:
        return None
    last = words[i + n - 1].end
    return Match(end - i, (Word(s.text_of(words[i].start, last), words[i].start, last, Tag.VERB, QUESTION_MEANS),
                           _unsaid(last, Tag.PRON, None, _SPEAKER), s.emit(i + n, end - i - n, Tag.SAID).words[0]),
                 expect=False, verb=QUESTION_MEANS, using=False)


_LEARNED = frozenset(["find out", "figure out", "work out"])
"""Verbs of learning a fact, which never find a thing ("*find out* the time", words33)."""


def _found_out_thing(s: State, i: int) -> Match | None:
    """"*Find out* the name of the person at the door", "figure out the time": to find out a thing is to learn it,
    not to search for it (words33): what is learnt is told (``QUESTION_MEANS``), the phrase kept whole as what to
    tell, as "find out who is at the door" is. A question word, "if"/"whether" or "how" after the verb are the rules
    before this one's."""
    words = s.words
    n = _phrase(s, i, _LEARNED)
    if not n or QUESTION_MEANS not in s.lexicon.units or not s.np_starts(i + n) or \
            words[i + n].lower in FOUND_OUT or words[i + n].lower in WH_WORDS:
        return None
    end = s.speech_end(i + n)
    last = words[i + n - 1].end
    return Match(end - i, (Word(s.text_of(words[i].start, last), words[i].start, last, Tag.VERB, QUESTION_MEANS),
                           _unsaid(last, Tag.PRON, None, _SPEAKER), s.emit(i + n, end - i - n, Tag.SAID).words[0]),
                 expect=False, verb=QUESTION_MEANS, using=False)


_LEARNING = frozenset(["find", "get", "learn", "discover", "identify", "obtain", "determine", "ascertain",
                       "establish", "check"])
"""Verbs that, said of what the robot reports of a person (``INFORMATION``: "the name of X", "their pose"), learn
it as "find out" does (words48): a name is no thing to fetch or look for."""


def _information_learnt(s: State, i: int) -> Match | None:
    """"*Find the name of* the person at the door", "get the pose of the man by the sofa", "learn their name": a verb
    of finding or getting (``_LEARNING``) said of a person's information (``INFORMATION`` after "the" and before
    "of", or after a possessive) learns it, and what is learnt is told (``QUESTION_MEANS``, to the speaker), as
    "find out the name of ..." is (``_found_out_thing``): it was a Pick or a Find of "the name". "get me the name
    of X" is ``INFORMATION_GIVEN``'s; "find the person's keys" names no information."""
    words = s.words
    if words[i].lower not in _LEARNING or i + 2 >= len(words) or QUESTION_MEANS not in s.lexicon.units or \
            words[i + 2].lower not in INFORMATION:
        return None
    det = words[i + 1].lower
    if not (det == "the" and i + 3 < len(words) and words[i + 3].lower == "of" or
            det in _INFO_DETERMINERS and det != "the"):
        return None
    end = s.speech_end(i + 1)
    last = words[i].end
    return Match(end - i, (Word(s.text_of(words[i].start, last), words[i].start, last, Tag.VERB, QUESTION_MEANS),
                           _unsaid(last, Tag.PRON, None, _SPEAKER), s.emit(i + 1, end - i - 1, Tag.SAID).words[0]),
                 expect=False, verb=QUESTION_MEANS, using=False)


_WHERE_SAID = HERE_WORDS | frozenset(["home", "there", "around", "back", "out", "in", "upstairs", "downstairs",
                                      "inside", "outside", "away"])
ASK_MEANS = "ask"
"""The unit a question put to a person is said with ("*find out if* anna wants coffee" is "ask anna if she wants
coffee"): a verb of asking (:data:`~seal_cli.language.asking.ASKING`), Tell's in the standard library."""


def _asked_of_person(s: State, i: int) -> Match | None:
    """"*Find out if* anna wants coffee", "*check whether* the guest is staying": whether a person wants, can, is or
    does something (the subject of the question a person: :func:`~seal_cli.language.asking.person_subject`) is found
    out by asking them (``ASK_MEANS``, the question kept whole); a question of a thing or a place is the robot's to
    look at, and so is a state said with "be" (the rules before this one: "check if the door is closed", "see if
    anyone is in the kitchen", "see if the baby is asleep")."""
    words = s.words
    n = _phrase(s, i, CHECK_WHETHER[0])
    if not n or ASK_MEANS not in s.lexicon.units or i + n + 2 >= len(words) or \
            words[i + n].lower not in CHECK_WHETHER[1]:
        return None
    k = i + n + 1
    end = s.speech_end(k)
    size = person_subject([w.text for w in words[k:end]], s.lexicon.people, s.lexicon.things) if end - k >= 2 else 0
    if not size or k + size + 1 < end and words[k + size].lower in BE_WORDS and \
            (words[k + size + 1].lower in _WHERE_SAID or match_phrase(words, k + size + 1, PREPOSITIONS)):
        return None                               # "see if Ben is in the kitchen", "... is home": where, looked for
    last = words[k - 2].end
    return Match(end - i, (Word(s.text_of(words[i].start, last), words[i].start, last, Tag.VERB, ASK_MEANS),
                           words[k - 1].tagged(Tag.WH), s.emit(k, end - k, Tag.SAID).words[0]),
                 expect=False, verb=ASK_MEANS, using=False)


_REMAINING = frozenset(["left", "remaining"])
_ASKS_WHAT_IS = frozenset([WHERE_MEANS, NUMBER_MEANS, "how many"])


def _remaining(s: State, i: int) -> Match | None:
    """"Is there any bread *left*?", "are there any eggs left in the fridge": after the thing a question asks
    about, "left" says it remains — no head of the phrase (the bread is what to find); dropped."""
    if s.verb_index < 0 or s.out[s.verb_index].info not in _ASKS_WHAT_IS or s.prev_tag() != Tag.WORD or \
            s.out[-1].lower in _REMAINING:
        return None
    nxt = s.next_lower(i)
    if nxt and nxt not in END_MARKS and nxt not in (",", ";") and nxt not in PREPOSITIONS:
        return None
    return Match(1)


def _person_state_dropped(s: State, i: int) -> Match | None:
    """After the person of "is lucy *still asleep* in her room?" (read as finding her there, ``WHETHER_IS_RULE``):
    adverbs and an adjective of state before the place, or adverbs before a progressive ("is ben *still* waiting
    in the kitchen?"), are no head of the phrase (the person is what to find); dropped (words25)."""
    verb = s.out[s.verb_index] if s.verb_index >= 0 else None
    if verb is None or verb.info != WHERE_MEANS or verb.lower not in _WHETHER_IS or \
            s.prev_tag() not in (Tag.WORD, Tag.NAME) or s.verb_index != len(s.out) - 2:
        return None
    words = s.words
    k = i
    while k < len(words) and words[k].lower in STATE_ADVERBS:
        k += 1
    if k + 1 >= len(words) or words[k + 1].lower not in _WHETHER_WHERE or not s.np_starts(k + 2):
        return None
    if _person_state(s, i - 1, k):
        return Match(k + 1 - i)
    return Match(k - i) if k > i and _progressive(s, i - 1, k) else None


def _whether_be(s: State, i: int) -> Match | None:
    if s.verb_index < 0 or s.out[s.verb_index].info != WHERE_MEANS or \
            s.out[s.verb_index].lower.split()[-1] not in CHECK_WHETHER[1] or \
            s.prev_tag() not in (Tag.WORD, Tag.NAME, Tag.PRON) or s.next_lower(i) not in _WHETHER_THERE:
        return None
    return Match(1)                               # "see if anyone *is* in the kitchen": dropped


_TOLD_PEOPLE = frozenset(["me", "us", "to me", "to us"])


def _told_how_many(s: State, i: int) -> Match | None:
    """"*Report to me how many* cups are in the sink", "say how many people are in the hall": a verb of saying
    (a unit of a frame whose first element is what is said) and "how many" is the unit of counting that
    says it ("tell me how many", ``NUMBER_MEANS``), as "let me know how many" is; the people told (the
    speaker) are the unit's."""
    words = s.words
    found = s.verb_at(i)
    if found is None or found[0] not in s.lexicon.speech or found[2] is not None or \
            NUMBER_MEANS.split()[0] not in s.lexicon.units or \
            tuple(NUMBER_MEANS.split()) not in s.lexicon.units[NUMBER_MEANS.split()[0]]:
        return None
    k = i + found[1]
    m = _phrase(s, k, _TOLD_PEOPLE)
    k += m
    polite = 0
    while k + polite < len(words) and words[k + polite].lower in ("please", ","):
        polite += 1                               # "tell me *please,* how many ..." (words42: what was said)
    k += polite
    if k + 1 >= len(words) or words[k].lower != "how" or words[k + 1].lower != "many" or \
            found[0] == NUMBER_MEANS.split()[0] and m and words[k - m - polite].lower != "to" and not polite:
        return None                               # "tell me how many": the unit itself, read as it is; "tell *to*
        #   me how many", as learners of English say it, is the unit's too (words39)
    end = words[k + 1].end
    return Match(k + 2 - i, (Word(s.text_of(words[i].start, end), words[i].start, end, Tag.VERB, NUMBER_MEANS),),
                 expect=False, verb=NUMBER_MEANS, using=False)


def _how_many_said(s: State, i: int) -> Match | None:
    """"tell Anna *how many cups are left*", "tell the guests how many chairs are free": after a verb of saying
    and the person told, "how many ..." is what is said, kept whole (the message was lost)."""
    words = s.words
    if not s.speech or s.verb_index < 0 or s.prev_tag() not in (Tag.NAME, Tag.PRON, Tag.WORD) or \
            i + 2 >= len(words) or words[i + 1].lower != "many":
        return None
    end = s.speech_end(i)
    return s.emit(i, end - i, Tag.SAID)


_SEEN_AUXILIARIES = frozenset(["can", "could", "do", "did", "will", "would"])
_SEERS = frozenset(["you", "we", "i"])


def _how_many_seen(s: State, i: int) -> Match | None:
    """"How many dishes *can you see* on the dining table?", "how many cups do you find in the kitchen": after the
    things a "how many" question counts, an auxiliary, a subject and a verb (of seeing or finding) say who counts,
    no thing: dropped, as "are there" is."""
    words = s.words
    if s.verb_index < 0 or not s.out[s.verb_index].lower.startswith("how many") or \
            s.prev_tag() not in (Tag.WORD, Tag.NAME) or i + 2 >= len(words) or words[i + 1].lower not in _SEERS:
        return None
    verb = words[i + 2].lower
    if verb_lemma(verb) != verb or verb in s.lexicon.things or verb in CLOSED or not in_dictionary(verb):
        return None
    return Match(3)


def _how_many_doing(s: State, i: int) -> Match | None:
    """"How many people in the kitchen *wear* a hat?", "how many people in the bedroom *raise* their left arm": after
    the people or things a "how many" question counts (a plural), a verb's plain present says what they do, as "are
    wearing" does (words41: "wear" was refused as an unknown verb, and "hold a cup" was a Pick of its own, added
    silently). Read as an unsaid "are" and the verb's -ing form: transitive before a noun phrase, with its
    preposition before one, bare before the end or a particle. No noun the taxonomy knows ("how many tea *spoon*
    are ..."), no word of a closed class, and only while nothing but the counted phrase follows the question's unit."""
    words, low = s.words, s.words[i].lower
    if s.verb_index < 0 or not str(s.out[s.verb_index].info).endswith(_COUNTED) or s.prev_tag() != Tag.WORD or \
            verb_lemma(low) != low or not low.isalpha() or low in CLOSED or low in s.lexicon.things or \
            not in_dictionary(low):
        return None
    after = s.out[s.verb_index + 1:]
    counted = next((w for w in after if w.tag == Tag.WORD), None)
    if counted is None or not is_plural(counted.lower) or any(w.tag not in _COUNTED_PHRASE for w in after):
        return None
    nxt = s.next_lower(i)
    if s.np_starts(i + 1) and nxt not in PARTICLES:
        tag = Tag.VBG_T
    elif nxt in PREPOSITIONS and s.np_starts(i + 2):
        tag = Tag.VBG_P
    elif nxt in END_MARKS or nxt in PARTICLES or not nxt:
        tag = Tag.VBG_I
    else:
        return None
    return Match(1, (_unsaid(words[i].start, Tag.BE, None, "are"), words[i].tagged(tag, low)))


def _total_dropped(s: State, i: int) -> Match | None:
    """"how many people are in the office *in total*?", "how many people *in all* are in the house", "count the
    cups *altogether*": in a count, a word of totality (:data:`~seal_cli.language.english.TOTALS`) after the counted
    or a place, before the end, a comma, "are"/"is" or a preposition, adds nothing: dropped (words41)."""
    if s.verb_index < 0 or not (str(s.out[s.verb_index].info).endswith(_COUNTED) or
                                s.out[s.verb_index].info == _COUNTING) or \
            s.prev_tag() not in (Tag.WORD, Tag.BE, Tag.THERE, Tag.HERE, Tag.NAME):
        return None
    n = _phrase(s, i, TOTALS)
    nxt = s.next_lower(i + n - 1) if n else ""
    if not n or nxt and nxt not in END_MARKS and nxt not in (",", "are", "is", "there") and nxt not in PREPOSITIONS:
        return None
    return Match(n)


def _topic_first(s: State, i: int) -> Match | None:
    """"*As for* the cup on the table, bring it to me", "*regarding* the person at the door, greet her": a word
    naming what the sentence is about (:data:`~seal_cli.language.english.TOPICS`), before a noun phrase, a comma
    and a clause, is politeness: the phrase after it is said first, as a bare one is ("the cup on the table, bring
    it to me"; words41)."""
    words = s.words
    n = _phrase(s, i, TOPICS)
    if not n or any(w.tag != Tag.POLITE for w in s.out) or not s.np_starts(i + n):
        return None
    comma = next((k for k in range(i + n + 1, min(len(words), i + n + 12)) if words[k].lower in (",", ";", ":")
                  or words[k].lower in END_MARKS), None)
    if comma is None or words[comma].lower not in (",", ";", ":") or not (
            s.verb_after(comma + 1) or _clause_at(s, comma + 1)):
        return None
    return s.emit(i, n, Tag.POLITE)


def _which_of(s: State, i: int) -> Match | None:
    """"tell me *which of* the objects on the desk is the smallest", "let me know who of the guests is standing":
    "of" right after the question word of a question told is read as "which *one of*" is, a quantifier (words41:
    "of" after "which" was refused)."""
    if s.prev_tag() != Tag.WH or s.out[-1].lower not in ("which", "who") or not s.np_starts(i + 1):
        return None
    return Match(1, (s.words[i].tagged(Tag.NUM, 1),))


_COUNTING = "count"
"""Count's plain unit ("count the cups *in total*")."""


_COUNTED_PHRASE = frozenset([Tag.WORD, Tag.DET, Tag.PREP, Tag.NUM, Tag.POSS, Tag.OF])
"""Tags of the words of a counted phrase and the place it is in ("how many *people in the kitchen* wear ...")."""


def _request(s: State, i: int) -> Match | None:
    words = s.words
    n = _phrase(s, i, REQUESTS)
    if not n or REQUEST_MEANS not in s.lexicon.units or not s.np_starts(i + n) or \
            words[i + n].lower in ("you", "to") or s.verb_at(i + n) is not None or \
            not _sentence_asks_nothing_else(s, i + n) or _done_by_no_unit(s, i + n):
        return None
    end = words[i + n - 1].end
    text = s.text_of(words[i].start, end) or " ".join(w.text for w in words[i:i + n])
    return Match(n, (Word(text, words[i].start, end, Tag.VERB, REQUEST_MEANS),
                     _unsaid(end, Tag.PRON, None, _SPEAKER)), expect=False, verb=REQUEST_MEANS, using=False)


def _done_by_no_unit(s: State, k: int) -> bool:
    """Whether the phrase wished for at ``k`` ends its sentence with the past participle of a verb no frame lists ("I
    want the door *locked*", "I'd like the eggs *poached*"): a wish for a deed the robot cannot do, no thing to bring
    (words47: a Bring of "the door locked"); the request is not read, and the sentence is refused as a statement."""
    words = s.words
    end = _sentence_end(s, k)
    while end > k + 1 and words[end - 1].lower in (",", "please"):
        end -= 1
    low = words[end - 1].lower
    lemma = verb_lemma(low) if low.isalpha() and end - 1 > k else None
    return lemma is not None and lemma != low and low in participles(lemma) and in_verb_tables(lemma) and \
        lemma not in s.lexicon.units and words[end - 2].lower not in NP_OPENERS


_HELP = frozenset(["help", "some help", "a little help", "a bit of help", "your help", "a hand", "a little hand",
                   "some assistance", "your assistance"])
"""Help asked for as a thing ("I could use *some help* finding my keys"): what the help is for is the request."""


def _help_wished(s: State, i: int) -> Match | None:
    """"*I could use some help* finding my keys", "I need a hand carrying the groceries to the car", "I'd love some help
    putting the dishes away": a wish for help (``REQUESTS``, then :data:`_HELP`) with an -ing form of a verb of the
    library after it asks for that deed; the wish and the help are politeness, the -ing form the verb (words43: a
    Bring of "some help finding my keys"). "I need a hand" alone, "I need help with the box" stay wishes."""
    words = s.words
    n = _phrase(s, i, REQUESTS)
    m = _phrase(s, i + n, _HELP) if n else 0
    k = i + n + m
    if not m or k >= len(words) or gerund_lemma(words[k].lower) is None or s.verb_at(k) is None:
        return None
    return Match(n + m, (merge(s.words, i, n + m, Tag.POLITE),), expect=True)


def _help_alone(s: State, i: int) -> Match | None:
    """"*I need a hand*", "I could use some help, please", "we need a hand in the garage": a wish for help
    (``REQUESTS``, then :data:`_HELP`) with no deed said is coming to whoever asks (``HELP_MEANS``: "come to me"), or
    to the one place said after it ("in the garage"); what it is with ("I need help *with the box*") is a remark.
    Help for a deed ("... carrying the bags": :func:`_help_wished`) is another's."""
    words = s.words
    n = _phrase(s, i, REQUESTS)
    m = _phrase(s, i + n, _HELP) if n else 0
    k = i + n + m
    if not m or HELP_MEANS not in s.lexicon.units:
        return None
    end = _sentence_end(s, k)
    while end > k and words[end - 1].lower in (",", "please", "now"):
        end -= 1
    with_what = end > k and words[k].lower == "with" and s.np_starts(k + 1) and not any(
        s.verb_at(j) is not None or words[j].lower in (",", "and", "then") for j in range(k + 1, end))
    remarks = ((words[k].start, words[end - 1].end),) if with_what else ()
    if with_what:
        k = end                                  # "I need help *with the box*": what it is for, a remark
    verb = Word(s.text_of(words[i].start, words[k - 1].end), words[i].start, words[k - 1].end, Tag.VERB, HELP_MEANS)
    if end == k:                                 # "I need a hand": come to me
        at = words[k - 1].end
        return Match(k - i, (verb, _unsaid(at, Tag.PREP, PREPOSITIONS["to"], "to"), _unsaid(at, Tag.PRON, None,
                                                                                               _SPEAKER)),
                     remarks=remarks, expect=False, verb=HELP_MEANS, using=False)
    if match_phrase(words, k, HERE_WORDS) == end - k:
        return Match(n + m, (verb,), expect=False, verb=HELP_MEANS, using=False)   # "... help here": come here
    if PREPOSITIONS.get(words[k].lower) not in LOCATED or not s.np_starts(k + 1) or \
            any(s.verb_at(j) is not None or words[j].lower in (",", "and", "then") for j in range(k + 1, end)):
        return None
    return Match(n + m, (verb,), expect=False, verb=HELP_MEANS, using=False)


_ASKED_FOR = frozenset(["can", "could", "may", "might"])
_HAVING = frozenset(["have", "get"])


def _request_for(s: State, i: int) -> Match | None:
    """"*Can* Jane *have* the salt?", "could Robin get a towel from the bathroom?": asking whether another person may
    have a thing asks the robot to bring it to them (words33), as "can I have X" brings it to the speaker: a modal,
    one name or a person's noun the taxonomy knows (the person), "have"/"get" and a phrase. The modal is the verb
    (``REQUEST_MEANS``), the person its recipient, "have" dropped. "can you get ...", "can I have ..." are other
    rules'."""
    words = s.words
    if i + 3 >= len(words) or words[i].lower not in _ASKED_FOR or words[i + 2].lower not in _HAVING or \
            REQUEST_MEANS not in s.lexicon.units or not s.np_starts(i + 3) or s.verb_at(i + 3) is not None:
        return None
    person = words[i + 1]
    low = person.lower
    if low in CLOSED or not low.isalpha() or not (capitalised(person) or low in s.lexicon.people):
        return None
    return Match(3, (words[i].tagged(Tag.VERB, REQUEST_MEANS), person.tagged(Tag.NAME)), expect=False,
                 verb=REQUEST_MEANS, using=False)


_WISHED_BESIDE = frozenset(["by", "near", "behind", "in front of"])
"""Prepositions of where a thing is beside another, which a wish for where it is may say too ("I want my shoes *by*
the door": put them there; words49), though no "put" takes them as often as ``WISHED_PLACES``."""


def _timed(s: State, k: int) -> bool:
    """Whether the phrase at ``k`` says a time ("by *six*", "by *tomorrow*", "by the *evening*"), not a place."""
    words = s.words
    k += k < len(words) and words[k].lower in NP_OPENERS
    return k < len(words) and (words[k].lower in TIME_WORDS or words[k].lower in NUMBERS or words[k].lower.isdigit()
                               or words[k].lower in ("morning", "afternoon", "evening", "night", "noon", "midnight"))


def _wished_placed(s: State, i: int) -> Match | None:
    """"*I want* the mug on the shelf": a wish for a thing to be somewhere is putting it there (``PLACE_MEANS``):
    a phrase, then one preposition of place (``WISHED_PLACES``) whose phrase ends the sentence, no verb
    between; the wish is the verb."""
    words = s.words
    n = _phrase(s, i, WISHED_PLACED)
    k = i + n
    if not n or (PLACE_MEANS,) not in s.lexicon.units.get(PLACE_MEANS, ()) or not s.np_starts(k) or \
            words[k].lower in ("you", "to", "it", "them") or s.verb_at(k) is not None:
        return None
    end = _sentence_end(s, k)
    while end > k and words[end - 1].lower in (",", "please"):
        end -= 1
    at = [p for p in range(k + 1, end) if words[p].lower in PREPOSITIONS or words[p].lower in (",", "and", "then")
          or s.verb_at(p) is not None and words[p - 1].lower not in NP_OPENERS]
    if len(at) != 1 or PREPOSITIONS.get(words[at[0]].lower) not in WISHED_PLACES | _WISHED_BESIDE or \
            not s.np_starts(at[0] + 1) or _timed(s, at[0] + 1):
        return None
    if any(words[p].lower.split("'")[0] in RELATIVES for p in range(k + 1, at[0])):
        return None             # "I want the juice *that's on* the shelf": where it is, no place it goes (words46)
    start, stop = words[i].start, words[k - 1].end
    return Match(n, (Word(s.text_of(start, stop), start, stop, Tag.VERB, PLACE_MEANS),), expect=False,
                 verb=PLACE_MEANS, using=False)


def _thing_placed(s: State, i: int) -> Match | None:
    """"*mug in the sink*", "the dirty cups in the dishwasher": a sentence of nothing but a thing and where it goes
    asks to put it there (``PLACE_MEANS``, unsaid before the thing): the sentence starts at ``i``, the thing's
    head is a class the library knows, one preposition of place (``WISHED_PLACES``) and its phrase end the
    sentence, and no verb is said ("the mug sitting in the sink", "cups in the sink need washing" stay as
    they are). Asked, it is no request: "any spoons in the drawer?" (``ANY_ASKED``), "mug in the sink?"."""
    words = s.words
    if s.out and s.out[-1].tag not in (Tag.END, Tag.POLITE) or PLACE_MEANS not in s.lexicon.units or \
            s.verb_at(i) is not None or words[i].lower in _ANY_ASKED:
        return None
    end = _sentence_end(s, i)
    if end < len(words) and words[end].lower == "?":
        return None
    while end > i and words[end - 1].lower in (",", "please", "now"):
        end -= 1
    k = i + (1 if words[i].lower in NP_OPENERS else 0)
    start = k
    while k < end and words[k].lower.isalpha() and words[k].lower not in CLOSED:
        k += 1
    head = words[k - 1].lower if k > start else ""
    if k == start or k >= end or noun_lemma(head) not in s.lexicon.things or gerund_lemma(head) or \
            start == i and noun_lemma(words[i].lower) not in s.lexicon.things or \
            PREPOSITIONS.get(words[k].lower) not in WISHED_PLACES or not s.np_starts(k + 1):
        return None                               # bare, the first word a thing too: "*load* paper onto ..." is none
    rest = range(k + 1, end)
    if any(not words[p].lower.isalpha() or words[p].lower in PREPOSITIONS or words[p].lower in ("and", "or") or
           words[p].lower in _NEEDS or s.verb_at(p) is not None and words[p].lower not in s.lexicon.things and
           words[p - 1].lower not in NP_OPENERS or words[p].lower in FINITE for p in rest):
        return None                               # "a man in the hall *has* a question": a statement (words28)
    w = words[i]
    return Match(0, (_unsaid(w.start, Tag.VERB, PLACE_MEANS),), expect=False, verb=PLACE_MEANS, using=False)


def _state_unit(s: State, low: str) -> str | None:
    """The lexical unit whose result the one word of state ``low`` is: "on"/"off" are switching
    (``SWITCHED_MEANS``), a participle its verb ("closed": "close"), an adjective that is a verb's base form
    its verb ("open", "clean"), an adjective a frame's postcondition says of its theme that frame's first unit
    ("hot": ``hot(theme)`` of Heat, "heat"; :attr:`Lexicon.results`); None when it is no result of a unit of the
    library."""
    unit = SWITCHED_MEANS.get(OPERATING.get(low, low)) or verb_lemma(low) or low
    if unit == low and low not in SWITCHED_MEANS and low not in STATE_PARTICLES and not is_adjective(low):
        return None                              # a verb's base form that is no adjective ("move"): no state
    parts = tuple(unit.split())
    if parts in s.lexicon.units.get(parts[0], ()):
        return unit
    result = s.lexicon.results.get(low) if is_adjective(low) else None
    return result[1] if result is not None else None        # "I'd like my tea *hot*": heat it


_WISHES = WISHED_PLACED | IMPERSONAL_WISHES | frozenset(["i need", "we need"])
_PSEUDO_CLEFTS = frozenset(f"what {wish} is" for wish in _WISHES)
"""A wish said as "*what I need is* the dishes counted" (a pseudo-cleft, words35): what follows "is" is the wish's
object, as after "I need"; no question of what something is (``QUESTION`` leaves it)."""
_WISHED_STATES = _WISHES | _PSEUDO_CLEFTS


def _wished_state(s: State, i: int) -> Match | None:
    """"*I'd like* the blinds closed", "I want the lights off", "we'd like the door open": a wish for a thing to
    be in a state, a phrase and then one word of state ending the sentence, is the verb whose result the state
    is (:func:`_state_unit`), as "make sure the door is closed" is; the wish is the verb, the state its split
    particle. A state said before "and"/"then" ends the wish there: "I'd like the blinds closed *and* the lights
    off" is two wishes, the second said without its verb (close the blinds, turn the lights off)."""
    n = _phrase(s, i, _WISHED_STATES)
    stop = _clause_stop(s, i + n) if n else len(s.words)
    if n and stop < _sentence_end(s, i + n):
        found = _state_after(s, i, n, stop)
        end = stop
        while end > i + n and s.words[end - 1].lower in (",", "please"):
            end -= 1
        if found is not None and found.particle and found.particle[0] == end - 1:
            return found
    return _state_after(s, i, n)


def _wished_done(s: State, i: int) -> Match | None:
    """"*I want* the apple *brought* to me", "I'd like the plate *put* on the table", "I need the towel *taken* to the
    bathroom": a wish for a verb of the library to be done to a thing (a phrase, then the verb's past participle
    and where the thing goes) is that verb (words33), as "I'd like the blinds closed" is closing them: the wish is
    the verb, the participle its split particle. A participle that opens the phrase ("I'd like the *baked* potato")
    or follows a verb of being is none."""
    words = s.words
    n = _phrase(s, i, _WISHED_STATES)
    k = i + n
    if not n or not s.np_starts(k) or words[k].lower in ("you", "to") or s.verb_at(k) is not None:
        return None
    for q in range(k + 1, _sentence_end(s, k) - 1):
        low = words[q].lower
        if low in (",", ";", "and", "then") or low in BE_WORDS or low in FINITE:
            return None
        unit = verb_lemma(low)
        two = None if s.np_starts(q + 2) else _done_with_particle(s, q + 1)   # "the cup *picked up* from the
        # table": "pick up"; "the plate put *on the table*": a preposition and its phrase, "put"
        if unit is None or low not in participles(unit) or \
                (unit,) not in s.lexicon.units.get(unit, ()) and two is None or \
                words[q - 1].lower in NP_OPENERS or words[q - 1].lower in PREPOSITIONS:
            continue
        after = q + 2 if two is not None else q + 1
        if after >= len(words) or words[after].lower not in PREPOSITIONS or \
                not s.np_starts(after + match_phrase(words, after, PREPOSITIONS)):
            return None
        unit = two or unit
        start, stop = words[i].start, words[k - 1].end
        return Match(n, (Word(s.text_of(start, stop), start, stop, Tag.VERB, unit),), expect=False, verb=unit,
                     using=False, particle=(q, unit))
    return None


def _resultative(s: State, i: int) -> Match | None:
    """"*leave* the door open", "*get* the soup hot", "*leave* the window shut": a verb that puts a thing in a state
    (the verb of a ``split`` unit, :attr:`Lexicon.split`: "put the kettle *on*" is ToggleOn) with a thing and one
    word of state ending the clause is the verb whose result the state is, as "I'd like the door open" is. "on" and
    "off" are the split units' own ("leave the light on": "leave on")."""
    words = s.words
    low = words[i].lower
    verbs = s.lexicon.state_verbs
    keeps = (verb_lemma(low) or low) in KEEPING and not (i and words[i - 1].lower == "to")
    # "keep the door shut": a verb of no unit, "on"/"off" its state; not a purpose ("... *to keep* it cold")
    if not keeps and (not verbs or low not in verbs and (verb_lemma(low) or low) not in verbs):
        return None
    stop = s.cond_end(i + 1)                     # "leave the door and window open": "and" between nouns
    stop = next((j for j in range(i + 1, stop) if s.words[j].lower in ("and", "then") and not _nouns_joined(s, j)),
                stop)
    end = stop
    while end > i + 1 and words[end - 1].lower in (",", "please", ".", "!"):
        end -= 1
    if keeps:                                    # "keep the fan running *in the bedroom*": where the thing is
        end = next((p for p in range(end - 2, i + 2, -1) if PREPOSITIONS.get(words[p].lower) in LOCATED and
                    s.np_starts(p + 1) and _state_unit(s, words[p - 1].lower) is not None), end)
    last = words[end - 1].lower if end > i + 2 else ""
    if not last or last in SWITCHED_MEANS and not keeps or \
            not (is_adjective(last) or last in STATE_PARTICLES or last in OPERATING) or \
            words[end - 2].lower in PARTICLES:
        return None                              # "put two lettuce *plants* in the sink", "put one *back* clean"
    found = _state_after(s, i, 1, stop)
    said = end - 2 if _done_with_particle(s, end - 1) is not None else end - 1   # "switched *on*": both words
    return found if found is not None and found.particle and found.particle[0] == said else None


def _state_after(s: State, i: int, n: int, stop: int | None = None) -> Match | None:
    """The state said after the ``n`` words at ``i`` and a phrase (:func:`_wished_state`, :func:`_resultative`),
    before ``stop`` (default: the sentence's end)."""
    words = s.words
    k = i + n
    if not n or not s.np_starts(k) or words[k].lower in ("you", "to") or s.verb_at(k) is not None:
        return None
    end = _sentence_end(s, k) if stop is None else stop
    while end > k and words[end - 1].lower in (",", "please"):
        end -= 1
    places = [p - 1 for p in range(k + 2, end - 1) if PREPOSITIONS.get(words[p].lower) in LOCATED and
              s.np_starts(p + 1) and not any(s.verb_at(j) for j in range(p + 1, end))]
    q = next((q for q in (*places, end - 1) if _state_unit(s, words[q].lower) is not None), end - 1)
    if q <= k:                                   # the state ends the sentence, or a place follows it ("the
        return None                              # lights on in the living room": where they are)
    unit = _state_unit(s, words[q].lower)
    done = _done_with_particle(s, q)
    if done is not None:                         # "I'd like the heater *turned on*": the particle's unit, said whole
        unit, q = done, q - 1
    elif q - 1 > k and left_in_state(s, q - 1):
        q -= 1                                   # "I want the door *left open*": the state, kept (words47)
    before = words[q - 1].lower
    if unit is None or before in NP_OPENERS or before in PREPOSITIONS or \
            any(words[p].lower in BE_WORDS or words[p].lower in (",", "and", "then") and not _nouns_joined(s, p) or
                s.verb_at(p) is not None and words[p - 1].lower not in NP_OPENERS for p in range(k + 1, q)):
        return None
    start, stop = words[i].start, words[k - 1].end
    return Match(n, (Word(s.text_of(start, stop), start, stop, Tag.VERB, unit),), expect=False, verb=unit,
                 using=False, particle=(q, unit))


def _done_with_particle(s: State, q: int) -> str | None:
    """The unit of two words a past participle and the particle at ``q`` say ("turned *on*": "turn on", "switched
    off", "picked up"), when the library has it; None otherwise ("closed": one word, "left on": no unit "leave on").
    The participle and the particle are then one split particle (:func:`~seal_cli.language.rules.verbs.split_unit`)."""
    if not 1 <= q < len(s.words):
        return None
    return s.lexicon.done_unit(s.words[q - 1].lower, s.words[q].lower, base=True)


def _switched_by_unknown(s: State, i: int) -> Match | None:
    """"*flick* the light *on* in the bedroom", "knock the telly off": a verb of English no frame lists, said in its
    base form with a thing and "on"/"off" ending the clause (or before where the thing is), puts the thing in that
    state as "put the kettle on" does: switching it (``SWITCHED_MEANS``), the particle split. Not of a thing the
    split units refuse (a kind the taxonomy says cannot be switched, a part: "kick your shoes off", "pry the lid
    off" stay unknown verbs), nor of a person ("it", "them" may be switched: "flick it on")."""
    words, low = s.words, s.words[i].lower
    if not low.isalpha() or low in CLOSED or s.verb_at(i) is not None or verb_lemma(low) != low or \
            not in_verb_tables(low) or not s.np_starts(i + 1) or words[i + 1].lower in PRONOUNS and \
            words[i + 1].lower not in ("it", "them"):
        return None
    stop = _clause_stop(s, i + 1)
    q = next((q for q in range(i + 2, stop) if words[q].lower in SWITCHED_MEANS), None)
    if q is None or words[q - 1].lower in NP_OPENERS or words[q - 1].lower in PREPOSITIONS:
        return None
    rest = [w.lower for w in words[q + 1:stop] if w.lower not in (",", "please", ".", "!")]
    if rest and not (PREPOSITIONS.get(rest[0]) in LOCATED and s.np_starts(q + 2)):
        return None                              # "knock the cup off the table": where it falls, no switching
    unit = SWITCHED_MEANS[words[q].lower]
    refused = frozenset().union(*(v for u, v in s.lexicon.split.items() if u.endswith(" " + words[q].lower)))
    thing = [w.lower for w in words[i + 1:q] if w.lower not in NP_OPENERS or w.lower in ("it", "them")]
    if not thing or any(not w.isalpha() or w in CLOSED and w not in ("it", "them") for w in thing) or \
            noun_lemma(thing[-1]) in refused or noun_lemma(thing[-1]) in s.lexicon.people or \
            tuple(unit.split()) not in s.lexicon.units.get(unit.split()[0], ()):
        return None
    return Match(1, (words[i].tagged(Tag.VERB, unit),), expect=False, verb=unit, using=False, particle=(q, unit))


def _nouns_joined(s: State, p: int) -> bool:
    """Whether the "and" at ``p`` joins two nouns of one phrase ("the bread *and* butter warm"), not two things each
    with its state ("the blinds closed *and* the lights off": a determiner after it, a state before it)."""
    words = s.words
    return words[p].lower == "and" and p + 1 < len(words) and words[p + 1].lower not in NP_OPENERS and \
        _state_unit(s, words[p - 1].lower) is None and s.verb_at(p + 1) is None


_OBLIGED_SUBJECTS = frozenset(["it", "this", "these", "those", "that"])
_SUPPOSED = frozenset(["should be", "must be", "ought to be"])
"""Said of where a thing is, these suppose ("locate the spoon? It *should be* in the dining room"), they ask no
putting; of a state they ask it ("the door should be closed")."""
_NEEDS = frozenset(["needs", "need", "wants", "want"])
"""Obligations said with a verb's -ing form after them ("the cup *needs* washing", "the shirt wants ironing")."""
_OBLIGED_WORDS = 14
"""The most words the thing's noun phrase may have before what it should do ("the knife, the fork and the spoon all":
words42 let its things be listed)."""
_FLOATING = frozenset(["all", "both", "each"])
"""A quantifier said after the things, before what they should do ("the cups *all* go in the cupboard")."""


def _obliged_phrase(s: State, i: int) -> tuple[int, int] | None:
    """Where the obligation of "the bowl *should go* in the dishwasher" starts after the phrase at ``i``, and how
    many words it has; None when no such phrase and obligation start here."""
    words = s.words
    first = words[i].lower
    if not (first in NP_OPENERS or first in _OBLIGED_SUBJECTS) or s.verb_at(i) is not None:
        return None
    for k in range(i + 1, min(len(words), i + _OBLIGED_WORDS)):
        n = _phrase(s, k, OBLIGED)
        if n:
            before = words[k - 1].lower
            alone = k - 1 == i and first in _OBLIGED_SUBJECTS             # "*this* needs to go in the bin"
            if before in _FLOATING and k - 2 > i and words[k - 2].lower not in NP_OPENERS:
                return k - 1, n + 1                 # "the cups *all go* in the cupboard": the quantifier dropped too
            return (k, n) if alone or before not in NP_OPENERS else None
        low = words[k].lower
        if low in (",", "and") and k + 1 < len(words) and words[k + 1].lower in NP_OPENERS and \
                words[k - 1].lower.isalpha() and words[k - 1].lower not in NP_OPENERS:
            continue                              # "the knife, the fork and the spoon go ...": things listed (words42)
        if not low.isalpha() or low in BE_WORDS or low in QUESTION_WORDS or low in s.lexicon.people or \
                noun_lemma(low) in s.lexicon.people or \
                s.verb_at(k) is not None and words[k - 1].lower not in DETERMINERS:
            return None                           # "the guest should go to ...": a person, no thing put
    return None


def _obliged_unit(s: State, k: int, n: int) -> tuple[str, int | None] | None:
    """What the obligation at ``k`` (``n`` words) asks: (``PLACE_MEANS``, None) for a place the phrase ending the
    clause names ("in the dishwasher"), (the unit, the state's index) for one word of state after "be" ("closed",
    "off"); None for anything else ("the bus goes at six")."""
    words = s.words
    m = k + n
    end = _clause_stop(s, m)
    while end > m and words[end - 1].lower in (",", "please"):
        end -= 1
    if m >= end:
        return None
    prep = PREPOSITIONS.get(words[m].lower)
    to_place = prep in WISHED_PLACES or prep == "to" and m + 1 < end and not capitalised(words[m + 1])
    if " ".join(w.lower for w in words[k + (words[k].lower in _FLOATING):m]) in _SUPPOSED:
        to_place = False                          # "it should be in the dining room": where to look, no command
    if to_place and m + 1 < end and s.np_starts(m + 1) and words[m + 1].lower not in PRONOUNS and \
            noun_lemma(words[end - 1].lower) not in s.lexicon.people and \
            not any(s.verb_at(j) is not None and words[j - 1].lower not in NP_OPENERS
                    or words[j].lower in (",", "and", "then") for j in range(m + 1, end)) and \
            (PLACE_MEANS,) in s.lexicon.units.get(PLACE_MEANS, ()):
        return PLACE_MEANS, None
    if words[k + n - 1].lower in _NEEDS:
        lemma = gerund_lemma(words[m].lower)    # "the cup needs *washing*", "the oven needs turning off"
        unit = " ".join([lemma, *(w.lower for w in words[m + 1:end])]) if lemma and end - m <= 2 else None
        return (unit, m) if unit is not None and lemma and tuple(unit.split()) in s.lexicon.units.get(lemma, ()) \
            else None
    if words[k + n - 1].lower != "be":
        return None
    q = m
    while q < end - 1 and words[q].lower in STATE_ADVERBS:
        q += 1
    unit = _state_unit(s, words[q].lower) if q == end - 1 else None
    return (unit, q) if unit is not None else None


def _obliged(s: State, i: int) -> Match | None:
    """"*The bowl should go* in the dishwasher", "the milk belongs in the fridge", "it needs to go on the table",
    "the front door should be closed": a thing said to belong somewhere, or to be in a state, is a command to
    put it there (``PLACE_MEANS``) or to bring the state about (its verb, :func:`_state_unit`): the verb is
    unsaid before the phrase, the obligation dropped after it (``OBLIGED_DROPPED``), a state word its particle."""
    found = _obliged_phrase(s, i)
    if found is None:
        return None
    asked = _obliged_unit(s, *found)
    if asked is None:
        return None
    unit, state = asked
    w = s.words[i]
    alone = found[0] == i + 1 and w.lower in _OBLIGED_SUBJECTS             # "*this* needs to go in the bin"
    tag = Tag.PRON if alone else Tag.DET if w.lower in DETERMINERS else Tag.POSS if w.lower in POSSESSIVES else \
        Tag.PRON
    return Match(1, (_unsaid(w.start, Tag.VERB, unit), w.tagged(tag)), expect=False, verb=unit, using=False,
                 particle=(state, unit) if state is not None else None)


def _obliged_after_comma(s: State, i: int) -> Match | None:
    """"put the dirty cups in the dishwasher*,* the clean ones go in the cupboard": a comma before a thing said to
    belong somewhere (:func:`_obliged`) joins a clause of its own, not a noun of a list ("the dishwasher, the clean
    ones" was a list, and "go" a Go of the cupboard, the cups' place lost; words30)."""
    if s.expect_verb or i + 1 >= len(s.words) or s.things_listed() or _obliged(s, i + 1) is None:
        return None                               # "the knife, the fork ... go in ...": things listed (words42)
    return Match(1, (s.words[i].tagged(Tag.SEP),), expect=True)


def _obliged_dropped(s: State, i: int) -> Match | None:
    at = next((k for k in range(len(s.out) - 1, -1, -1) if s.out[k].tag == Tag.VERB), -1)
    if at < 0 or at + 1 >= len(s.out) or s.out[at].text or \
            s.prev_tag() not in (Tag.WORD, Tag.NAME, Tag.PRON, Tag.LABEL):
        return None
    first = next((k for k, w in enumerate(s.words) if w.start == s.out[at + 1].start), -1)
    found = _obliged_phrase(s, first) if first >= 0 else None
    if found is None or found[0] != i or _obliged_unit(s, *found) is None:
        return None                               # only the obligation of the unsaid verb's own phrase
    return Match(found[1])                        # "the bowl *should go* in ...": dropped, "put" was unsaid before


_AGENTS = frozenset(["by you", "by yourself", "by the robot"])
"""The robot named as the doer of a command said in the passive ("the cups must be counted *by you*": words39)."""


def _agent_dropped(s: State, i: int) -> Match | None:
    """"the cups must be counted *by you*", "Ana should be taken to the exit by you": in a clause said in the passive
    (its verb unsaid before the thing, :func:`_obliged`, :func:`_person_needing`), "by you" at the clause's end names
    the robot as who does it: nothing more to do, no place ("by" was read as "near you": the ground "you")."""
    words = s.words
    at = next((k for k in range(len(s.out) - 1, -1, -1) if s.out[k].tag == Tag.VERB), -1)
    n = _phrase(s, i, _AGENTS)
    if at < 0 or s.out[at].text or not n or i + n < len(words) and words[i + n].lower not in END_MARKS and \
            words[i + n].lower not in (",", ";", "and", "then", "please"):
        return None
    return Match(n)


_NEEDS_DONE = frozenset(["needs", "need", "wants", "has to be", "have to be", "needs to be", "need to be",
                         "wants to be", "should be", "must be", "is to be", "are to be"])
"""What a person said to need a verb done to them is said with ("Ana *needs* guiding to the door", "Ben *has to be*
taken to the exit"): the -ing form after "needs"/"wants", a past participle after the others."""
_PERSON_WORDS = 16
"""The most words the person's noun phrase may have before what they need ("the person at the coat rack raising
their right arm")."""


def _person_needs(s: State, i: int) -> tuple[int, int, str] | None:
    """Where "needs V-ing" / "needs to be V-ed" starts after a person's phrase at ``i``, how many words it has,
    and the verb (a one-word unit of the library); None when no such phrase and need start here."""
    words = s.words
    first = words[i]
    guide = HELPED_MOVING[0]
    if i + 1 < len(words) and first.lower.isalpha() and first.lower not in CLOSED and s.verb_at(i) is None and \
            (helped := _help_moving_needed(s, i + 1)) and (guide,) in s.lexicon.units.get(guide, ()):
        return i + 1, helped, guide    # "robin needs help getting to the exit": one word, a name (words49)
    named = (capitalised(first) or lower_case_name(words, i)) and first.lower not in CLOSED and s.verb_at(i) is None
    if not (first.lower in NP_OPENERS or named):                  # "noah needs to be taken ...": a name (words24)
        return None
    person = named
    for k in range(i + 1, min(len(words) - 1, i + _PERSON_WORDS)):
        helped = _help_moving_needed(s, k) if person else 0
        if helped and (HELPED_MOVING[0],) in s.lexicon.units.get(HELPED_MOVING[0], ()):
            return k, helped, HELPED_MOVING[0]    # "robin needs some help getting to the exit": guide her (words49)
        n = _phrase(s, k, _NEEDS_DONE)
        gerund = n and words[k + n - 1].lower in ("needs", "need", "wants")
        if n and (person or not gerund and first.lower in DETERMINERS) and k + n < len(words):
            low = words[k + n].lower    # a thing too, with its passive: "the apple *should be taken* to ..." (words35)
            lemma = gerund_lemma(low) if gerund else \
                next((v for v in (verb_lemma(low),) if v is not None and low in participles(v)), None)
            return (k, n + 1, lemma) if lemma is not None and (lemma,) in s.lexicon.units.get(lemma, ()) \
                else None
        low = words[k].lower
        if not low.isalpha() or low in BE_WORDS or low in QUESTION_WORDS or low in ("and", "then", "or"):
            return None                           # "Angel is at the bin and needs ...": no phrase alone
        if named and k == i + 1 and capitalised(words[k]) is False and low not in NP_OPENERS:
            return None                           # "Morgan *likes* ...": a name is one word here
        person = person or low in s.lexicon.people or noun_lemma(low) in s.lexicon.people
    return None


_HELP_NEEDED = frozenset(["help", "some help", "a little help", "a bit of help", "a hand", "a helping hand"])
"""What a person needs to move somewhere, said after "needs" ("Ana needs *a hand* getting to the door")."""


def _help_moving_needed(s: State, k: int) -> int:
    """How many words "needs (some) help (with) getting/to get" and the verb of moving take at ``k`` when where to
    follows them ("needs help getting *to* the exit", ``HELPED_MOVING``), as "help her get to the exit" asks; else 0.
    Not "needs help getting dressed" (no where: no leading)."""
    words = s.words
    if words[k].lower not in ("needs", "need", "wants"):
        return 0
    m = k + 1 + _phrase(s, k + 1, _HELP_NEEDED)
    if m == k + 1:
        return 0
    m += m < len(words) and words[m].lower == "with"
    if m < len(words) and words[m].lower == "to":
        m += 1
        lemma = verb_lemma(words[m].lower) if m < len(words) else None
    else:
        lemma = gerund_lemma(words[m].lower) if m < len(words) else None
    _, moving, where = HELPED_MOVING
    if lemma not in moving or m + 1 >= len(words) or words[m + 1].lower not in where:
        return 0
    return m + 1 - k


def _person_needing(s: State, i: int) -> Match | None:
    """"*Morgan needs to be led* from the storage rack to the bookshelf", "the person at the coat rack needs guiding
    to the living room": a person said to need a verb done to them asks the robot to do it; the verb is unsaid
    before the phrase (the person its object), the need dropped after it (``PERSON_NEED_DROPPED``)."""
    found = _person_needs(s, i)
    if found is None:
        return None
    w = s.words[i]
    tag = Tag.DET if w.lower in DETERMINERS else Tag.POSS if w.lower in POSSESSIVES else Tag.NAME \
        if w.lower not in NP_OPENERS else Tag.PRON
    return Match(1, (_unsaid(w.start, Tag.VERB, found[2]), w.tagged(tag)), expect=False, verb=found[2], using=False)


def _person_need_dropped(s: State, i: int) -> Match | None:
    at = next((k for k in range(len(s.out) - 1, -1, -1) if s.out[k].tag == Tag.VERB), -1)
    if at < 0 or at + 1 >= len(s.out) or s.out[at].text:
        return None
    first = next((k for k, w in enumerate(s.words) if w.start == s.out[at + 1].start), -1)
    found = _person_needs(s, first) if first >= 0 else None
    if found is None or found[0] != i or found[2] != s.out[at].info:
        return None                               # only the need of the unsaid verb's own phrase
    return Match(found[1])                        # "Morgan *needs to be led* to ...": dropped, "lead" unsaid before


def _sentence_end(s: State, i: int) -> int:
    words = s.words
    return next((k for k in range(i, len(words)) if words[k].lower in END_MARKS), len(words))


def _path_alone(s: State, i: int) -> Match | None:
    """"*To* the bathroom", "back to the kitchen, please", "into the garden and then find the dog": a clause
    that is only a path to somewhere, with no verb in it, is going there (``PATH_MEANS``); after a clause
    whose verb has a goal, it is that verb again ("put it in the fridge and *into* the microwave")."""
    words = s.words
    n = match_phrase(words, i, PREPOSITIONS)
    if not n or PREPOSITIONS[" ".join(w.lower for w in words[i:i + n])] not in PATH_ALONE or \
            PATH_MEANS not in s.lexicon.units or not s.np_starts(i + n) or \
            not all(t.tag in (Tag.POLITE, Tag.SEP) for t in s.out[-1:]):
        return None
    first = words[i + n]
    if first.lower not in NP_OPENERS and not capitalised(first) and \
            verb_lemma(first.lower) == first.lower:
        return None                               # "To fill a bowl with water ...": an infinitive
    end = s.cond_end(i + n)
    if any(s.verb_at(k) and words[k - 1].lower not in NP_OPENERS
           for k in range(i + n, end)):
        return None                               # a verb in it ("the shed" is a noun)
    k = end
    while k < len(words) and words[k].lower in ASKED_ALONE | {","}:
        k += 1
    if not (k >= len(words) or words[k].lower in END_MARKS or words[k].lower in ("and", "then", ";") and
            s.verb_after(k + 1) or words[k - 1].lower in ASKED_ALONE and s.verb_after(k) and not _takes_goal(s, k)):
        return None                               # "To the kitchen, bring the cup": a phrase said first
    w = words[i]
    prep = PREPOSITIONS[" ".join(x.lower for x in words[i:i + n])]
    before = next((t for t in reversed(s.out) if t.tag == Tag.VERB), None)
    verb = str(before.info) if before is not None and str(before.info) in s.lexicon.goals else PATH_MEANS
    return Match(n, (_unsaid(w.start, Tag.VERB, verb), merge(words, i, n, Tag.PREP, prep)), expect=False,
                 verb=verb, using=False)    # "put it in the fridge, and *into* the microwave": the verb again


def _takes_goal(s: State, k: int) -> bool:
    """Whether the verb at ``k`` is a unit with a goal ("to the exit, please *guide* the woman": the path said first
    is its goal, words33), not a clause of its own after a path alone ("to the kitchen, please; find the cup")."""
    found = s.verb_at(k)
    return found is not None and found[0] in s.lexicon.goals


def _asked_for(s: State, i: int, end: int) -> bool:
    """Whether the sentence from ``i`` to ``end`` is a noun phrase and "for" with what it is for ("coffee *for Ruth*",
    "a glass of water *for grandad*", "another cushion *for the sofa*", "tea *for two* in the lounge"): a request, as
    "please" makes one (words32), the thing brought to the speaker, or to the person "for" names. The first word is
    no verb of English ("nip into the garage for me" stays an unknown verb)."""
    words = s.words
    if in_verb_tables(words[i].lower) and words[i].lower not in NP_OPENERS:
        return False
    k = next((k for k in range(i + 1, end) if words[k].lower == "for"), None)
    if k is None or words[k - 1].lower in NP_OPENERS or k + 1 >= end:
        return False
    return s.np_starts(k + 1) or s.person_at(k + 1) or words[k + 1].lower in NUMBERS


def _asked_alone(s: State, i: int) -> Match | None:
    """"Milk from the fridge, please", "the remote please": a noun phrase and "please" (``ASKED_ALONE``), no
    verb anywhere in the sentence, is a request for the thing: "bring me ..." (``REQUEST_MEANS``). The capital of
    the sentence's first word makes no name of a word the dictionary lists ("*Orange* juice, from the sofa, for me
    please", "*Milk* from the fridge, please": the thing, not a person called Orange or Milk; words24); a name the
    dictionary does not list ("Anna"), or one of two capitalised words ("Rose Tyler"), stays one."""
    words = s.words
    if any(t.tag != Tag.POLITE for t in s.out) or REQUEST_MEANS not in s.lexicon.units or \
            words[i].lower in PRONOUNS or not s.np_starts(i):
        return None
    particle = i + 1 < len(words) and words[i + 1].lower in PARTICLES and words[i + 1].lower not in PREPOSITIONS
    if verb_lemma(words[i].lower) == words[i].lower and (particle or i + 1 < len(words) and
                                                         (words[i + 1].lower in NP_OPENERS or
                                                          words[i + 1].lower in PRONOUNS)):
        return None                               # "please *list the* things", "please list *everything*", "please
        #                                           tidy *up the* room": an imperative, its verb unknown (a noun takes
        #                                           no pronoun after it, nor a particle and a phrase)
    end = _sentence_end(s, i)
    if not (any(words[k].lower in ASKED_ALONE for k in range(end)) or _asked_for(s, i, end)) or \
            any(s.verb_at(k) or words[k].lower in BE_WORDS or words[k].lower in QUESTION_WORDS
                for k in range(i, end)):
        return None
    asked = (_unsaid(words[i].start, Tag.VERB, REQUEST_MEANS), _unsaid(words[i].start, Tag.PRON, None, _SPEAKER))
    first = words[i]
    if capitalised(first) and (i == 0 or words[i - 1].lower in END_MARKS) and in_dictionary(first.lower) and \
            not (i + 1 < len(words) and capitalised(words[i + 1])):
        return Match(1, (*asked, first.tagged(Tag.WORD)), expect=False, verb=REQUEST_MEANS, using=False)
    return Match(0, asked, expect=False, verb=REQUEST_MEANS, using=False)


_SWITCHED_WORDS = 4


_ONWARD = frozenset(["over", "down", "up", "out", "back", "round", "around", "along", "through"])
"""Adverbs of direction after "on" said of going on ("head *on over* to the kitchen", "go on down"): no switching."""


def _switched_alone(s: State, i: int) -> Match | None:
    """"*Lights off* in the hall", "the TV on, please", "kitchen lights off": a short noun phrase (no verb's base
    form first) and "on"/"off", then only where (a preposition and a phrase) or "please" to the sentence's end,
    is switching the thing so (``SWITCHED_MEANS``: "turn the lights off"), the particle read as the verb's."""
    words = s.words
    if not any(w.lower in SWITCHED_MEANS for w in words[i + 1:i + 1 + _SWITCHED_WORDS]):
        return None                               # no "on"/"off" near (the common case)
    first = words[i].lower
    nxt = s.next_lower(i)
    if not s.np_starts(i) or first in PRONOUNS or first in QUESTION_WORDS or gerund_lemma(first) is not None or \
            verb_lemma(first) == first and (nxt in NP_OPENERS or nxt in PRONOUNS
                                            or nxt in NUMBERS or nxt.isdigit()):
        return None                               # "flip the lamp off", "put two phones on the bed": a verb first
    found = s.verb_at(i)
    if found is not None and found[2] is not None:
        return None                               # "switch the radio on": the verb and its split particle
    end = _sentence_end(s, i)
    k = next((k for k in range(i + 1, min(end, i + 1 + _SWITCHED_WORDS)) if words[k].lower in SWITCHED_MEANS), None)
    if k is None or words[k - 1].lower in NP_OPENERS or \
            any(words[j].lower in BE_WORDS or words[j].lower in PREPOSITIONS for j in range(i, k)):
        return None
    if k == i + 1 and (words[k].lower in s.lexicon.apart.get(verb_lemma(first) or first, ()) or
                       verb_lemma(first) == first and found is not None and (
                           first not in s.lexicon.things or k + 1 < len(words) and words[k + 1].lower in _ONWARD)):
        return None                               # "hang on", "hold on": a verb and its particle, no thing switched;
        #                                           "head on over to the kitchen": "on" onward, a way (words48)
    unit = SWITCHED_MEANS[words[k].lower]
    parts = tuple(unit.split())
    if parts not in s.lexicon.units.get(parts[0], ()):
        return None
    rest = k + 1
    if rest < end and words[rest].lower not in ASKED_ALONE | {","}:
        n = match_phrase(words, rest, PREPOSITIONS)
        if not n or not s.np_starts(rest + n) or any(
                s.verb_at(j) and words[j - 1].lower not in NP_OPENERS
                for j in range(rest + n, end)):
            return None                           # "lights off in the hall": only where may follow
    tag = Tag.DET if first in DETERMINERS else Tag.POSS if first in POSSESSIVES else Tag.WORD
    return Match(1, (_unsaid(words[i].start, Tag.VERB, unit), words[i].tagged(tag)), expect=False, verb=unit,
                 using=False, particle=(k, unit))    # its first word tagged here: "Lights" is no verb


_MODALS = frozenset(["could", "would", "will", "can", "might", "may"])
_WISHES_OF = (("wants",), ("needs",), *sorted({tuple(p.split()[1:]) for p in REQUESTS if p.split()[0] == "i" and
                                              p.split()[1] in _MODALS}, key=lambda w: (-len(w), w)))
"""A named person's wish for a thing ("*Anna wants* the cup"): bring it to them (``REQUEST_MEANS``). Besides "wants"
and "needs", each of the speaker's wishes made with a modal (``REQUESTS``: "I *could use*", "I *would like*", "I
*could do with*"), which says the same of anyone: a modal does not agree with its subject ("anna could use a
spoon")."""


def _wish_of(s: State, i: int) -> Match | None:
    """"*Anna wants* the cup", "*dad needs* his glasses", "*ellie wants* a drink": a wish said of a name, of a noun
    the taxonomy lists as a person said bare (a name to the family: "dad", "grandma"), or of a word no dictionary
    lists (a name written in lower case), first in the sentence or as a name is, brings the thing to them. First in
    the sentence, a word the dictionary lists only as a noun, said bare and singular and no thing the taxonomy knows,
    is a name too ("*morgan needs* a glass of water": a breed of horse; no one brings water to a bare noun), as after
    "to" (``LOWER_CASE_NAME``); "coffee needs sugar" stays an error."""
    words = s.words
    low = words[i].lower
    if REQUEST_MEANS not in s.lexicon.units or s.verb_at(i) is not None or not (
            capitalised(words[i]) or low in s.lexicon.people or
            low.isalpha() and words[i].text == low and low not in CLOSED and (
                not in_dictionary(low) or _bare_noun_first(s, i))):
        return None
    for wish in _WISHES_OF:
        n = 1 + len(wish)
        if i + n < len(words) and all(words[i + 1 + k].lower == w for k, w in enumerate(wish)) and \
                s.np_starts(i + n) and words[i + n].lower not in ("you", "to") and s.verb_at(i + n) is None and \
                _sentence_asks_nothing_else(s, i + n):
            end = words[i + n - 1].end
            return Match(n, (Word(s.text_of(words[i].start, end), words[i].start, end, Tag.VERB, REQUEST_MEANS),
                             words[i].tagged(Tag.NAME)), expect=False, verb=REQUEST_MEANS, using=False)
    return None


_RELATIVE_WORDS = frozenset(["who", "whom", "which", "that"])
_DESCRIBED_WORDS = 10
"""The most words between a person and their wish said of them ("Robin*, who is in the garage,* needs ...")."""


def _wish_after(s: State, head: int) -> int | None:
    """Where a wish starts ("needs", "would like") after the person ending at ``head`` and what describes them: a
    phrase of place ("Robin *in the garage* needs"), a relative clause ("the lady *who's waiting at the door*
    needs"), or one set off by commas ("Robin*, who is in the garage,* needs": the closing comma is the wish's
    first word). None when something else comes first (a verb, "is": a statement, not a wish)."""
    words = s.words
    relative = False
    k = head + 1
    while k < min(len(words), head + _DESCRIBED_WORDS) and not _wish_at(s, k):
        low = words[k].lower
        if low == "," and not relative and s.next_lower(k) in _RELATIVE_WORDS:
            k += 1                                    # "Robin*,* who ...": the clause set off
            continue
        if low == "," and relative:
            return k if k > head + 2 and _wish_at(s, k + 1) else None     # "..., needs": the closing comma
        if low in _RELATIVE_WORDS:
            relative = True
        elif not (low.isalpha() or relative and low == "'s") or low in BE_WORDS and not relative or \
                s.verb_at(k) is not None and words[k - 1].lower not in DETERMINERS and not relative:
            return None
        k += 1
    if k < len(words) and words[k - 1].lower in PREPOSITIONS:
        return None                                   # "I'm in *need* of a towel": a noun, no wish (words41: it was
        #                                               Bring to "I'm" and Guide, silently)
    return k if k < len(words) and _wish_at(s, k) and k > head + 1 else None


def _wished_by(s: State, k: int) -> bool:
    """Whether the wish at ``k`` (maybe its closing comma first) asks for a thing: a noun phrase after it, no
    "you"/"to" (a wish of an action: "needs to be led"), no verb, and nothing else asked in the sentence."""
    words = s.words
    if words[k].lower == ",":
        k += 1
    n = _wish_at(s, k)
    return bool(n) and k + n < len(words) and s.np_starts(k + n) and words[k + n].lower not in ("you", "to") and \
        s.verb_at(k + n) is None and _sentence_asks_nothing_else(s, k + n)


def _wish_of_described(s: State, i: int) -> Match | None:
    """"Robin, who is in the garage, needs a wrench", "Sam in the study wants a coffee": a wish said of a name (as
    :func:`_wish_of` takes it) and what describes them, a phrase of place or a relative clause, brings the thing to
    them: the verb is unsaid before the name, the wish dropped after what describes them (``WISH_DROPPED``; was the
    question "who is in the garage" told to Robin, words34)."""
    words = s.words
    low = words[i].lower
    if REQUEST_MEANS not in s.lexicon.units or s.verb_at(i) is not None or i + 2 >= len(words) or \
            words[i + 1].lower not in PREPOSITIONS and words[i + 1].lower != "," or not (
                capitalised(words[i]) or low in s.lexicon.people or
                low.isalpha() and words[i].text == low and low not in CLOSED and (
                    not in_dictionary(low) or _bare_noun_first(s, i))):
        return None
    k = _wish_after(s, i)
    if k is None or not _wished_by(s, k):
        return None
    return Match(1, (_unsaid(words[i].start, Tag.VERB, REQUEST_MEANS), words[i].tagged(Tag.NAME)), expect=False,
                 verb=REQUEST_MEANS, using=False)


def _bare_noun_first(s: State, i: int) -> bool:
    """Whether the word at ``i`` starts the sentence and is listed only as a noun, singular, and no thing the
    taxonomy knows ("morgan", "robin": a name written in lower case where a person is the subject)."""
    low = s.words[i].lower
    return (not s.out or s.out[-1].tag == Tag.END) and parts_of_speech(low) == {"noun"} and not is_plural(low) and \
        low not in s.lexicon.things


_WISHED = frozenset(w for wish in _WISHES_OF for w in wish[:1]) | frozenset(["want", "need"])


def _wish_at(s: State, k: int) -> int:
    """How many words of a wish ("wants", "needs", "would like"; "want", "need" after a plural) start at ``k``."""
    words = s.words
    for wish in (*_WISHES_OF, ("want",), ("need",)):
        if all(k + m < len(words) and words[k + m].lower == w for m, w in enumerate(wish)):
            return len(wish)
    return 0


def _wish_of_phrase(s: State, i: int) -> Match | None:
    """"*The person at the armchair needs* a towel", "my son wants a glass of water": a wish said of a
    person named by a noun phrase (its head a person of the taxonomy, a phrase of place after it) is
    bringing them the thing, as "Anna wants the cup" is; the verb is unsaid before the phrase, and the
    wish is dropped after it (``WISH_DROPPED``)."""
    words = s.words
    if REQUEST_MEANS not in s.lexicon.units or words[i].lower not in NP_OPENERS or \
            s.verb_at(i) is not None:
        return None
    head = next((k for k in range(i + 1, min(len(words), i + 4))
                 if noun_lemma(words[k].lower) in s.lexicon.people or words[k].lower in s.lexicon.people), None)
    if head is None or any(not words[j].lower.isalpha() for j in range(i + 1, head)):
        return None
    k = head if _wish_at(s, head + 1) else _wish_after(s, head)
    if k is None or not _wished_by(s, k + 1 if k == head else k):
        return None
    tag = Tag.DET if words[i].lower in DETERMINERS else Tag.POSS
    return Match(1, (_unsaid(words[i].start, Tag.VERB, REQUEST_MEANS), words[i].tagged(tag)), expect=False,
                 verb=REQUEST_MEANS, using=False)


def _wish_dropped(s: State, i: int) -> Match | None:
    verb = next((t for t in reversed(s.out) if t.tag == Tag.VERB), None)
    comma = int(s.words[i].lower == ",")             # "Robin, who is in the garage*,* needs": the closing comma
    n = _wish_at(s, i + comma)
    if comma and n:
        n += 1
    if verb is None or verb.info != REQUEST_MEANS or verb.text or \
            s.prev_tag() not in ((Tag.WORD, Tag.NAME, Tag.REL) if comma else (Tag.WORD, Tag.NAME)) or \
            not n or not s.np_starts(i + n):
        return None
    if s.words[i + n].lower in NP_OPENERS:
        return Match(n)                           # "the guest *wants* a tea": dropped, "bring" was unsaid before
    return Match(n, (_unsaid(s.words[i + n].start, Tag.DET),))   # "wants *tea*": a phrase of its own, not "guest tea"


def _know_wish(s: State, i: int) -> Match | None:
    words = s.words
    n = _phrase(s, i, KNOW_WISHES)
    if not n or QUESTION_MEANS not in s.lexicon.units or i + n >= len(words) or words[i + n].lower in END_MARKS:
        return None
    k = i + n
    end = words[k - 1].end
    for unit in s.lexicon.units.get(QUESTION_MEANS, ()):         # "do you know how many": "tell me how many"
        rest = unit[2:]
        if len(unit) > 2 and unit[1] == _SPEAKER and all(k + m < len(words) and words[k + m].lower == rest[m]
                                                          for m in range(len(rest))):
            last = words[k + len(rest) - 1].end
            return Match(n + len(rest), (Word(s.text_of(words[i].start, last), words[i].start, last, Tag.VERB,
                                              " ".join(unit)),), expect=False, verb=" ".join(unit), using=False)
    text = s.text_of(words[i].start, end) or " ".join(w.text for w in words[i:k])
    return Match(n, (Word(text, words[i].start, end, Tag.VERB, QUESTION_MEANS), _unsaid(end, Tag.PRON, None, _SPEAKER)),
                 expect=False, verb=QUESTION_MEANS, using=False)


_COUNTED = "how many"
"""The unit of counting a question of number opens with."""


def _how_much_counted(s: State, i: int) -> Match | None:
    """"*How much* plates are on the table?": "how much" before a plural noun (a learner's "much" for "many", the
    noun's plural saying things are counted) asks how many (words25); before a noun with no plural ("how much milk
    is left?") it stays an amount, no count."""
    words = s.words
    unit = tuple(_COUNTED.split())
    if i + 2 >= len(words) or words[i + 1].lower != "much" or unit not in s.lexicon.units.get(unit[0], ()):
        return None
    k = i + 2
    while k < len(words) and words[k].lower.isalpha() and words[k].lower not in CLOSED and not is_plural(
            words[k].lower) and s.verb_at(k) is None:
        k += 1                                       # "how much *dirty* plates"
    if k >= len(words) or not is_plural(words[k].lower) or words[k].lower in CLOSED or \
            verb_lemma(words[k].lower) in _AUXILIARY_LEMMAS:
        return None                                  # "how much *does* the box weigh?": a weight, no count (words41)
    end = words[i + 1].end
    return Match(2, (Word(s.text_of(words[i].start, end), words[i].start, end, Tag.VERB, _COUNTED),),
                 expect=False, verb=_COUNTED, using=False)


_AUXILIARY_LEMMAS = frozenset(["do", "be", "have"])
"""Verbs whose forms ("does", "is", "has") open the question after "how much", no noun counted."""
_PLACE_NOUNS = frozenset(["room", "place", "part", "floor"])
_STRANDED = frozenset(["in", "at", "on"])


def _which_place(s: State, i: int) -> Match | None:
    """"*Which room is* grandma in?", "what room are the kids in", "which floor is the laundry on?": which place a
    thing or person is in asks where it is: find it (``WHERE_MEANS``, as "where is grandma?"); the preposition left
    at the end is dropped (``STRANDED_WHERE``, words25)."""
    words = s.words
    if WHERE_MEANS not in s.lexicon.units or i + 4 >= len(words) or \
            noun_lemma(words[i + 1].lower) not in _PLACE_NOUNS or words[i + 2].lower not in ("is", "are", "'s") or \
            not s.np_starts(i + 3):
        return None
    end = _sentence_end(s, i)
    if words[end - 1].lower not in _STRANDED or end - 1 <= i + 3:
        return None
    last = words[i + 2].end
    return Match(3, (Word(s.text_of(words[i].start, last), words[i].start, last, Tag.VERB, WHERE_MEANS),),
                 expect=False, verb=WHERE_MEANS, using=False)


def _stranded_where(s: State, i: int) -> Match | None:
    verb = s.out[s.verb_index] if s.verb_index >= 0 else None
    if verb is None or verb.info != WHERE_MEANS or verb.lower.split()[:1] not in (["which"], ["what"]) or \
            s.words[i].lower not in _STRANDED or s.prev_tag() not in (Tag.WORD, Tag.NAME):
        return None
    nxt = s.next_lower(i)
    return Match(1) if not nxt or nxt in END_MARKS else None


def _number_of(s: State, i: int) -> Match | None:
    words = s.words
    n = _phrase(s, i, NUMBER_OF)
    unit = tuple(NUMBER_MEANS.split())
    if not n or unit not in s.lexicon.units.get(unit[0], ()) or not s.np_starts(i + n):
        return None
    end = words[i + n - 1].end
    return Match(n, (Word(s.text_of(words[i].start, end), words[i].start, end, Tag.VERB, NUMBER_MEANS),),
                 expect=False, verb=NUMBER_MEANS, using=False)


def _information_given(s: State, i: int) -> Match | None:
    """"*Give* me the name of the person at the door", "bring us the names of the three biggest objects on the shelf":
    a verb of giving or bringing (a unit with a recipient, no verb of saying), "me" or "us", and a piece of
    information of something (:data:`~seal_cli.language.english.INFORMATION`, then "of") is telling it (words41: a
    Bring of "the name", silently). The verb is read as "tell"; what follows is what "tell me ..." takes."""
    words = s.words
    if i + 4 >= len(words) or words[i + 1].lower not in ("me", "us") or words[i + 2].lower not in _INFO_DETERMINERS \
            or words[i + 3].lower not in INFORMATION or words[i + 4].lower != "of" or QUESTION_MEANS not in \
            s.lexicon.units:
        return None
    found = s.verb_at(i)
    if found is None or found[1] != 1 or found[0] not in s.lexicon.recipients or found[0] in s.lexicon.speech:
        return None
    return Match(1, (words[i].tagged(Tag.VERB, QUESTION_MEANS),), expect=False, verb=QUESTION_MEANS, using=False)


_INFO_DETERMINERS = frozenset(["the", "their", "his", "her", "its"])


def _let_know(s: State, i: int) -> Match | None:
    words = s.words
    if QUESTION_MEANS not in s.lexicon.units or i + 2 >= len(words):
        return None
    told = words[i + 1]
    if told.lower in NP_OPENERS or told.lower in _EVERYONE or \
            words[i + 2].lower != LET_KNOW[1] and _one_told(told):      # "let mum and dad know"
        return _let_phrase_know(s, i)
    pronoun = told.lower in OBJECT_PRONOUNS and told.lower not in ("it", "this", "that")
    if words[i + 2].lower != LET_KNOW[1] or not (pronoun or capitalised(told) or _one_told(told)):
        return None
    k = i + 3                                     # "let me know how many": "tell me how many", a unit of its own
    for unit in s.lexicon.units.get(QUESTION_MEANS, ()):
        rest = unit[2:]
        speaker = _SPEAKER if told.lower == "us" else told.lower          # "let us know how many": the speakers
        if len(unit) > 2 and unit[1] == speaker and all(k + m < len(words) and words[k + m].lower == rest[m]
                                                        for m in range(len(rest))):
            end = words[k + len(rest) - 1].end
            text = s.text_of(words[i].start, end)
            return Match(k + len(rest) - i, (Word(text, words[i].start, end, Tag.VERB, " ".join(unit)),),
                         expect=False, verb=" ".join(unit), using=False)
    tag = Tag.PRON if told.lower in OBJECT_PRONOUNS else Tag.NAME
    return Match(3, (words[i].tagged(Tag.VERB, QUESTION_MEANS), told.tagged(tag)), expect=False,
                 verb=QUESTION_MEANS, using=False)


_LET_PHRASE_WORDS = 12


_EVERYONE = _INDEFINITES - {"anything", "something"} | {"everyone", "everybody"}
"""Indefinite pronouns of people that may be told ("let *everyone* in the hall know ...", words37)."""


def _one_told(word: Word) -> bool:
    """One word of letters, of no closed class, alone between "let" and "know" is who is told, whatever its
    case: a name written in lower case ("let *maria* know"), a bare noun of kin ("let *grandpa* know")."""
    return word.lower.isalpha() and word.lower not in CLOSED


def _let_phrase_know(s: State, i: int) -> Match | None:
    """"*let* the person at the chairs *know* ...": "let" is "tell" when "know" ends a noun phrase after it (a few
    words of no verb, in the sentence); the "know" is dropped where it comes (``KNOW_AFTER_LET``)."""
    words = s.words
    for k in range(i + 2, min(len(words), i + 2 + _LET_PHRASE_WORDS)):
        low = words[k].lower
        if low == LET_KNOW[1]:
            return Match(1, (words[i].tagged(Tag.VERB, QUESTION_MEANS),), expect=False, verb=QUESTION_MEANS,
                         using=False)
        joined = low == "and" and k + 1 < len(words) and s.verb_at(k + 1) is None      # "mum *and* dad"
        if low in END_MARKS or low in (",", ";", "and", "then") and not joined or s.verb_at(k) is not None and \
                words[k - 1].lower not in DETERMINERS:
            return None
    return None


def _know_after_let(s: State, i: int) -> Match | None:
    if s.verb_index < 0 or s.out[s.verb_index].lower != LET_KNOW[0] or \
            s.prev_tag() not in (Tag.WORD, Tag.NAME, Tag.LABEL) and \
            not (s.prev_tag() == Tag.PRON and s.out[-1].lower in _EVERYONE):
        return None
    k = i + 1                                     # "let mum and dad know *dinner is ready*": what is told
    if s.speech and k < len(s.words) and s.words[k].lower not in _TOLD_LEADS and s.words[k].lower not in END_MARKS \
            and s.verb_at(k) is None and (any(w.lower in BE_WORDS or w.lower in FINITE for w in s.words[k:k + 4]) or
                                          any(_finite_s(s, m) for m in range(k + 1, min(k + 4, len(s.words))))):
        said = s.emit(k, s.speech_end(k) - k, Tag.SAID)
        return Match(1 + said.consumed, said.words)
    return Match(1)                               # "let the person at the chairs *know* what ...": dropped


def _finite_s(s: State, m: int) -> bool:
    """Whether the word at ``m`` is a verb's -s form said of the noun before it ("let him know the meeting *starts*
    soon", "the bus *leaves* at six"; words37): no noun of a phrase its determiner opens ("the *cups*")."""
    low = s.words[m].lower
    lemma = verb_lemma(low)
    return low.endswith("s") and lemma is not None and lemma != low and \
        s.words[m - 1].lower not in NP_OPENERS and s.words[m - 1].lower.isalpha()


_TOLD_LEADS = WH_WORDS | {"that", ",", "about"}       # WH_WORDS holds "if", "whether", "how"
"""Words that begin what "let X know" tells in a way other rules read (a question, "that", whether ...)."""


QUESTION = Rule("bare question", _question, (
    Example("What's the biggest thing on the shelf?", "What's the biggest thing on the shelf", Tag.SAID),
    Example("which of the bottles in the pantry is the biggest?", "", Tag.VERB),
    Example("who is in the kitchen?", "", Tag.VERB),
    Example("who is knocking on the gate, would you say?", "who is knocking on the gate", Tag.SAID),
    Example("tell me how many guests are in the hall and what they're eating", "what they're eating", Tag.SAID),
), QUESTION_WORDS, "a question where a command starts: 'tell me' and the question")
WHERE = Rule("where is", _where, (
    Example("where is the cup?", "where is", Tag.VERB),
    Example("Is there a cup in the kitchen?", "Is there", Tag.VERB),
    Example("Do we have any eggs?", "Do we have any", Tag.VERB),
    Example("whereabouts is the remote?", "whereabouts is", Tag.VERB),
), _WHERE_FIRST, "'where is X', 'is there X': find X")
WHERE_DID_RULE = Rule("where did I leave", _where_did, (
    Example("Where did I leave my glasses?", "Where did I leave", Tag.VERB),
    Example("where do we keep the batteries", "where do we keep", Tag.VERB),
    Example("Where can I find the sponge?", "Where can I find", Tag.VERB),
    Example("where did dad put the scissors?", "where did dad put", Tag.VERB),
    Example("where does Priya keep her tea", "where does Priya keep", Tag.VERB),
    Example("Where did the kids leave the football?", "Where did the kids leave", Tag.VERB),
    Example("where have you put my glasses", "where have you put", Tag.VERB),
    Example("Where has Tom left the keys?", "Where has Tom left", Tag.VERB),
    Example("where does my little brother keep his shoes", "where does my little brother keep", Tag.VERB),
    Example("where did the cat hide the ball", "where did the cat hide", Tag.VERB),        # no person (words47)
    Example("where did our dog bury its bone", "where did our dog bury", Tag.VERB),
), WHERE_DID[0], "'where did I leave X', 'where do we keep X': find X")
SEEN_ASKED_RULE = Rule("have you seen", _seen_asked, (
    Example("can you see my phone anywhere?", "see", Tag.VERB),
    Example("you can see the blue mug, can't you?", "see", Tag.VERB),
    Example("have you seen my phone anywhere", "have you seen", Tag.VERB),
    Example("Did you notice the keys in the hall?", "Did you notice", Tag.VERB),
    Example("has anyone come across my glasses", "has anyone come across", Tag.VERB),
    Example("Do you see anyone in the kitchen?", "Do you see", Tag.VERB),
    Example("can you see anyone in the garden", "see", Tag.VERB),                  # words48: no "?"
), SEEN_ASKED[0] | _DO_SEEN | first_words(SEEN_ASKED[2]),
    "'have you seen X', 'did you notice X', 'can you see X?': find X")
LEFT_ASKED_RULE = Rule("did someone leave X in a state", _left_asked, (
    Example("did I leave the stove on", "did I leave", Tag.VERB),
    Example("Has anyone left the back door open?", "open", Tag.COND),
    Example("did I leave my keys in the car?", "did I leave", Tag.VERB),
), LEFT_ASKED[0], "'did I leave X on?': check X (LookAt), the state asked kept; 'did I leave X in Y?': find X in Y",
   needs=LEFT_ASKED[2])
WHETHER_IS_RULE = Rule("is X somewhere", _whether_is, (
    Example("Is Ben in the kitchen?", "Is", Tag.VERB),
    Example("is anybody upstairs?", "is", Tag.VERB),
    Example("are the apples in the fridge?", "are", Tag.VERB),
    Example("is anyone sitting at the table?", "is", Tag.VERB),
    Example("is someone waiting at the door?", "is", Tag.VERB),
    Example("is grandpa sleeping in the bedroom?", "is", Tag.VERB),
    Example("is the girl with the red bag standing by the sofa?", "is", Tag.VERB),
), _WHETHER_IS, "'is X in Y?': find X in Y, and answer whether it is there")
ANY_ASKED = Rule("any X somewhere, asked", _any_asked, (
    Example("anyone in the bathroom?", "anyone", Tag.PRON),
    Example("any milk left in the fridge?", "any", Tag.DET),
    Example("any biscuits left?", "any", Tag.DET),
    Example("any spoons in the drawer?", "any", Tag.DET),
    Example("someone waiting at the door?", "someone", Tag.PRON),
), _ANY_ASKED, "'anyone in the bathroom?', 'any milk in the fridge?': find them there ('is there' unsaid)")
WISHED_DONE = Rule("a wish for a thing done", _wished_done, (
    Example("I want the apple brought to me", "I want", Tag.VERB),
    Example("I'd like the plate put on the table", "put", Tag.PARTICLE),
    Example("we need the chairs moved to the porch", "we need", Tag.VERB),
    Example("I'd like the cup picked up from the table", "picked up", Tag.PARTICLE),
    Example("we want the lights switched off in the hall", "switched off", Tag.PARTICLE),
    Example("what I want is the towels taken to the bathroom", "what I want is", Tag.VERB),
), first_words(_WISHED_STATES), "'I want X brought to me', 'I'd like X put on Y': bring X to me, put X on Y")
WISHED_STATE = Rule("a wish for a thing's state", _wished_state, (
    Example("I'd like the blinds closed", "I'd like", Tag.VERB),
    Example("I want the lights off, please", "off", Tag.PARTICLE),
    Example("I need the door open", "I need", Tag.VERB),
    Example("I'd like the heater turned on", "turned on", Tag.PARTICLE),
    Example("I want the door left open", "left open", Tag.PARTICLE),
    Example("we'd like the lights on in the living room", "on", Tag.PARTICLE),
    Example("I'd like my tea hot", "hot", Tag.PARTICLE),
    Example("I want the door open and the radio on", "open", Tag.PARTICLE),
    Example("I'd like the bread and butter warm", "warm", Tag.PARTICLE),
    Example("what we need is the plates on the shelf counted", "what we need is", Tag.VERB),
), first_words(_WISHED_STATES), "'I'd like X closed', 'I want X off': close X, turn X off")
RESULTATIVE = Rule("a thing left in a state", _resultative, (
    Example("leave the door open", "leave", Tag.VERB),
    Example("get the soup hot, please", "hot", Tag.PARTICLE),
    Example("leave the window in the bedroom shut", "shut", Tag.PARTICLE),
    Example("leave the door and window open", "open", Tag.PARTICLE),
    Example("keep the door shut", "keep", Tag.VERB),
    Example("keep the heater switched on", "switched on", Tag.PARTICLE),
    Example("please keep the gate closed", "closed", Tag.PARTICLE),
    Example("keep the fan running", "running", Tag.PARTICLE),
    Example("keep the lamp on in the hallway", "on", Tag.PARTICLE),
    Example("leave the dishwasher going", "going", Tag.PARTICLE),
), None, "'leave X open', 'get X hot': open X, heat X (a verb that puts a thing in a state, and the state)")
SWITCHED_BY_UNKNOWN = Rule("an unknown verb of a thing and on/off", _switched_by_unknown, (
    Example("flick the light on in the bedroom", "flick", Tag.VERB),
    Example("knock the telly off", "knock", Tag.VERB),
), lambda low: low.isalpha(), "'flick the light on': a verb no frame lists, a thing and 'on'/'off': switch it so",
   needs=frozenset(SWITCHED_MEANS))
OBLIGED_AFTER_COMMA = Rule("a comma before where a thing should go", _obliged_after_comma, (
    Example("put the mugs in the sink, the clean ones go in the cupboard", ",", Tag.SEP),
), frozenset([",", ";"]), "', the plates go in the dishwasher': a clause of its own after the comma")
OBLIGED_RULE = Rule("where a thing should go", _obliged, (
    Example("the bowl should go in the dishwasher", "", Tag.VERB),
    Example("The milk belongs in the fridge.", "The", Tag.DET),
    Example("the strawberry jello needs to go to the pantry", "", Tag.VERB),
    Example("the saucers all go in the cupboard", "", Tag.VERB),                   # words42
    Example("the jug, the mugs and the teapot belong on the tray", "", Tag.VERB),  # words42
    Example("the front door should be closed", "closed", Tag.PARTICLE),
    Example("the cup on the coffee table needs washing", "washing", Tag.PARTICLE),
), lambda low: low in NP_OPENERS or low in _OBLIGED_SUBJECTS,
    "'X should go in Y', 'X belongs in Y': put X in Y; 'X should be closed': close X")
PERSON_NEEDING = Rule("a person who needs leading", _person_needing, (
    Example("Morgan needs to be led to the bookshelf", "Morgan", Tag.NAME),
    Example("the man at the door needs showing to the kitchen", "the", Tag.DET),
    Example("noah needs to be taken to the garage", "noah", Tag.NAME),
    Example("robin needs some help getting to the exit", "robin", Tag.NAME),     # words49
    Example("the old man needs a hand to get back to his room", "the", Tag.DET),
), lambda low: low in NP_OPENERS or low.isalpha(),
    "'Ana needs guiding to the door', 'the guest has to be taken to the exit': guide/take the person there",
   needs=first_words(_NEEDS_DONE))
PERSON_NEED_DROPPED = Rule("the need after the person", _person_need_dropped, (
    Example("Morgan needs to be led to the bookshelf", "needs to be led", ""),
), first_words(_NEEDS_DONE), "the 'needs to be led' of 'Morgan needs to be led to X', dropped: 'lead' was unsaid")
AGENT_DROPPED = Rule("'by you' after a command said in the passive", _agent_dropped, (
    Example("the jars must be counted by you", "by you", ""),
    Example("Ada needs to be taken to the gate by you.", "you", ""),
), frozenset(["by"]), "'by you' ending a clause said in the passive: the robot does it, no place")
OBLIGED_DROPPED = Rule("the obligation after the thing", _obliged_dropped, (
    Example("the bowl should go in the dishwasher", "should go", ""),
    Example("the saucers all go in the cupboard", "all go", ""),                     # words42
), first_words(OBLIGED) | _FLOATING, "the 'should go' of 'the bowl should go in Y', dropped: 'put' was unsaid before")
WISHED_PLACED_RULE = Rule("a wish for where a thing is", _wished_placed, (
    Example("I want the mug on the shelf", "I want", Tag.VERB),
    Example("I'd like the books in the box, please", "I'd like", Tag.VERB),
    Example("I want my shoes by the door", "I want", Tag.VERB),             # words49
    Example("we'd like the plant near the window", "we'd like", Tag.VERB),
), first_words(WISHED_PLACED), "'I want X on Y': put X on Y")
THING_PLACED = Rule("a thing and where it goes, no verb", _thing_placed, (
    Example("mug in the sink", "", Tag.VERB),
    Example("the dirty cups in the dishwasher.", "", Tag.VERB),
), None, "'mug in the sink': a sentence of only a thing and a place of putting is putting it there",
   after=frozenset([START, Tag.END, Tag.POLITE]))
REQUEST = Rule("wish for a thing", _request, (
    Example("I'd like the red mug", "I'd like", Tag.VERB),
    Example("Can I have the big plate?", "Can I have", Tag.VERB),
    Example("I need a pen.", "I need", Tag.VERB),
    Example("I wouldn't mind a biscuit", "I wouldn't mind", Tag.VERB),
    Example("is there any chance of a blanket?", "is there any chance of", Tag.VERB),
    Example("any chance I could have a cushion", "any chance I could have", Tag.VERB),
), _REQUEST_FIRST, "'I'd like X', 'can I have X', 'I need X': bring X to the speaker")
HELP_WISHED = Rule("a wish for help doing", _help_wished, (
    Example("I could use some help finding my keys.", "I could use some help", Tag.POLITE),
    Example("I need a hand carrying the groceries to the car", "I need a hand", Tag.POLITE),
), _REQUEST_FIRST, "'I could use some help V-ing X': V X")
HELP_ALONE = Rule("help wished for, no deed said", _help_alone, (
    Example("I need a hand", "I need a hand", Tag.VERB),
    Example("we could use some help in the garage", "we could use some help", Tag.VERB),
    Example("I need some help here, please", "I need some help", Tag.VERB),
    Example("I could use a hand", "I could use a hand", Tag.VERB),
    Example("I need help with the box", "I need help with the box", Tag.VERB),
), _REQUEST_FIRST, "'I need a hand (in the garage)': come to me (to the garage)")
REQUEST_FOR = Rule("may a person have a thing", _request_for, (
    Example("Can Jane have the salt?", "Jane", Tag.NAME),
    Example("could Robin get a towel from the bathroom?", "could", Tag.VERB),
), _ASKED_FOR, "'can Jane have X?', 'could Robin get X?': bring X to the person")
SWITCHED_ALONE = Rule("a thing switched on or off", _switched_alone, (
    Example("Lights off in the hall.", "Lights", Tag.WORD),
    Example("the porch lamp on, please", "on", Tag.PARTICLE),
), None, "'lights off (in the hall)': turn the lights off", needs=frozenset(SWITCHED_MEANS))
WISH_OF = Rule("a person's wish for a thing", _wish_of, (
    Example("Anna wants the cup", "Anna wants", Tag.VERB),
    Example("Ben needs a towel.", "Ben needs", Tag.VERB),
    Example("Anna would like the red mug", "Anna would like", Tag.VERB),
    Example("dad wants his reading glasses", "dad wants", Tag.VERB),
    Example("morgan needs a glass of water", "morgan needs", Tag.VERB),
    Example("grandpa could use a blanket", "grandpa could use", Tag.VERB),
    Example("Sara could do with a cup of tea", "Sara could do with", Tag.VERB),
), None, "'Anna wants X', 'Ben needs X', 'Sara could use X': bring X to the person",
   needs=frozenset(wish[0] for wish in _WISHES_OF))
WISH_OF_PHRASE = Rule("a wish said of a person's phrase", _wish_of_phrase, (
    Example("the person at the armchair needs a towel", "the", Tag.DET),
    Example("my son wants a glass of water", "my", Tag.POSS),
    Example("the guests in the hall would like some coffee", "the", Tag.DET),
), NP_OPENERS, "'the person at the armchair needs X': bring X to the person")
WISH_OF_DESCRIBED = Rule("a wish said of a person described", _wish_of_described, (
    Example("Robin, who is in the garage, needs a wrench", "Robin", Tag.NAME),
    Example("Sam in the study would like a coffee", "Sam", Tag.NAME),
    Example("dad, who's in the shed, wants his gloves", "dad", Tag.NAME),
), None, "'Robin, who is in the garage, needs X', 'Sam in the study wants X': bring X to the person",
   needs=frozenset(wish[0] for wish in (*_WISHES_OF, ("want",), ("need",))))     # the words _wish_at reads
WISH_DROPPED = Rule("the wish after a person's phrase", _wish_dropped, (
    Example("the person at the armchair needs a towel", "needs", ""),
    Example("Robin, who is in the garage, needs a wrench", ", needs", ""),
), _WISHED | frozenset(["would", ","]),
   "the 'needs' of 'the guest needs X' (and the comma closing what describes them), dropped: 'bring' was read before")
PATH_ALONE_RULE = Rule("a path alone", _path_alone, (
    Example("to the bathroom", "to", Tag.PREP),
    Example("back to the kitchen, please", "back to", Tag.PREP),
    Example("into the garden and then find the dog", "", Tag.VERB),
), first_words(p for p, canonical in PREPOSITIONS.items() if canonical in PATH_ALONE), "'to X' with no verb: go to X")
ASKED_ALONE_RULE = Rule("a thing asked for alone", _asked_alone, (
    Example("milk from the fridge, please", "", Tag.VERB),
    Example("the spoon back, please", "", Tag.VERB),
    Example("The remote please.", "", Tag.PRON),
    Example("Orange juice, from the sofa, for me please", "Orange", Tag.WORD),
    Example("cocoa for Priya", "", Tag.VERB),                              # words32: "for" and a person last
    Example("a blanket for grandma", "", Tag.PRON),
), None, "a noun phrase and 'please' with no verb: bring it to the speaker (or to whom 'for' names)",
   after=frozenset([START, Tag.POLITE]))
STATE_QUESTION = Rule("is X in a state", _state_question, (
    Example("Is the fridge open?", "Is", Tag.VERB),
    Example("is the kitchen light still on?", "still on", Tag.COND),
    Example("Is the cup on the table clean?", "clean", Tag.COND),
    Example("is the washing machine running?", "running", Tag.COND),
    Example("is grandpa sitting down or standing up?", "sitting down or standing up", Tag.COND),
), _WHETHER_IS, "'is X open?': check X (LookAt), the state asked kept")
WHETHER_UNJOINED = Rule("asked whether, no joint", _whether_unjoined, (
    Example("go over to the shelf see if there are any cups and bring me one", "see if there are", Tag.VERB),
), first_words(_ASKERS), "'see if ...' right after a phrase: a clause of its own, said without 'and'",
   after=frozenset([Tag.WORD, Tag.NAME, Tag.PRON, Tag.LABEL]))
ASKED_WHETHER = Rule("asked whether", _asked_whether, (
    Example("Could you check if the door is closed?", "check if", Tag.VERB),
    Example("tell me whether the stove is still on", "tell me whether", Tag.VERB),
    Example("Let me know if there is a pen on the desk.", "Let me know if there is", Tag.VERB),
    Example("Tell me if the keys are on the table.", "Tell me if", Tag.VERB),
    Example("Can you see if anyone is in the kitchen?", "see if", Tag.VERB),
    Example("check whether there's a book on the shelf", "check whether there's", Tag.VERB),
    Example("go to the kitchen and see if anyone is there", "see if", Tag.VERB),
), first_words(_ASKERS), "'tell me / check / do you know if X is open' (LookAt), '... if X is in Y' (Find)")
STATE_ASKED = Rule("the state asked", _state_asked, (
    Example("do you know if the kettle is on", "on", Tag.COND),
    Example("are the windows in the bedroom shut", "shut", Tag.COND),
    Example("is the fridge not open?", "not open", Tag.COND),
    Example("isn't the oven on?", "not on", Tag.COND),
    Example("Is the window open in the bedroom?", "open in the bedroom", Tag.COND),
), None, "the state of 'is X open?', 'check if X is closed': kept beside the frame, the 'is' dropped")
FOUND_OUT_RULE = Rule("find out who", _found_out, (
    Example("Find out who is in the hall.", "who is in the hall", Tag.SAID),
    Example("go to the hall and see who is there", "see", Tag.VERB),
), first_words(CHECK_WHETHER[0]), "'find out who ...', 'check what ...': tell me who ...")
FOUND_OUT_THING = Rule("find out a thing", _found_out_thing, (
    Example("find out the name of the person at the door", "the name of the person at the door", Tag.SAID),
    Example("figure out the time and tell Jo", "the time", Tag.SAID),
), first_words(_LEARNED), "'find out the name of X': tell the name of X (what is learnt is told, not searched for)")
INFORMATION_LEARNT = Rule("a person's information learnt", _information_learnt, (
    Example("find the name of the woman at the gate", "the name of the woman at the gate", Tag.SAID),
    Example("go to the porch, get the pose of the man there and tell me", "the pose of the man there", Tag.SAID),
    Example("learn their name", "learn", Tag.VERB),
), _LEARNING, "'get the name of X', 'learn their name': tell the name of X (learnt, not fetched)",
   needs=INFORMATION)
ASKED_OF_PERSON = Rule("found out by asking", _asked_of_person, (
    Example("find out if anna wants coffee", "find out", Tag.VERB),
    Example("check whether the guest is staying for dinner", "the guest is staying for dinner", Tag.SAID),
), first_words(CHECK_WHETHER[0]), "'find out if Anna wants coffee': ask Anna whether she wants coffee")
def _pointing_asked(s: State, i: int) -> Match | None:
    """"is *that* my phone on the sofa?", "is this the right key?": a demonstrative right after the "is" of a
    question whether a thing is somewhere, before a phrase of its own, is the subject pointing at it; the phrase
    names the thing (it was the theme "that", the phone lost)."""
    words = s.words
    if len(s.out) != 1 or s.out[0].tag != Tag.VERB or s.out[0].lower not in ("is", "are") or \
            i + 1 >= len(words) or words[i + 1].lower not in NP_OPENERS:
        return None
    return Match(1)


POINTING_ASKED = Rule("a demonstrative pointing at what is asked", _pointing_asked, (
    Example("is that my hat on the chair?", "that", ""),
    Example("are those your keys in the bowl?", "those", ""),
), frozenset(["this", "that", "these", "those"]), "'is that my X on Y?': the demonstrative points at X, dropped")
REMAINING = Rule("what is left", _remaining, (
    Example("is there any bread left?", "left", ""),
    Example("are there any eggs left in the fridge", "left", ""),
), _REMAINING, "'left' after the thing a question asks about: it remains, dropped")
PERSON_STATE_DROPPED = Rule("the state of a person asked where", _person_state_dropped, (
    Example("is lucy still asleep in her room?", "asleep", ""),
    Example("is ben still waiting in the kitchen?", "still", ""),
), None, "'is lucy still asleep in her room?': find her there; the state said of her is no head, dropped",
   after=frozenset([Tag.WORD, Tag.NAME]))
WHETHER_BE = Rule("is, after see if X", _whether_be, (
    Example("see if the cat is in the garden", "is", ""),
), _WHETHER_IS, "the 'is' of 'see if X is in Y', dropped: 'see if' was read as 'find'")
TOLD_HOW_MANY = Rule("said how many", _told_how_many, (
    Example("Report to me how many cups are in the sink.", "Report to me how many", Tag.VERB),
    Example("say how many people are in the hall", "say how many", Tag.VERB),
    Example("tell to me how many jars are in the shed", "tell to me how many", Tag.VERB),
    Example("tell me please how many jars are in the shed", "tell me please how many", Tag.VERB),   # words42
), None, "a verb of saying and 'how many': tell me how many (Count)", needs=frozenset(["many"]))
HOW_MANY_SEEN = Rule("how many X can you see", _how_many_seen, (
    Example("How many dishes can you see on the dining table?", "can", ""),
    Example("how many cups do you find in the kitchen", "do", ""),
), _SEEN_AUXILIARIES, "'how many X can you see': who counts, dropped (the things are X)")
TOPIC_FIRST = Rule("what the sentence is about, first", _topic_first, (
    Example("As for the cup on the table, bring it to me", "As for", Tag.POLITE),
    Example("regarding the person at the door, greet her", "regarding", Tag.POLITE),
), first_words(TOPICS), "'as for X, ...', 'regarding X, ...': politeness; X is said first",
    after=frozenset([START, Tag.POLITE]))
WHICH_OF = Rule("which of, told", _which_of, (
    Example("tell me which of the objects on the desk is the smallest", "of", Tag.NUM),
    Example("let me know who of the guests is standing", "of", Tag.NUM),
), frozenset(["of"]), "'which of the X' in a question told: 'which one of the X'", after=frozenset([Tag.WH]))
TOTAL_DROPPED = Rule("in total, of a count", _total_dropped, (
    Example("how many people are in the office in total?", "in total", ""),
    Example("how many people in all are in the house", "in all", ""),
    Example("how many people are there total in the office", "total", ""),
), first_words(TOTALS), "'in total', 'altogether' in a count: dropped (a count counts all)",
    after=frozenset([Tag.WORD, Tag.BE, Tag.THERE, Tag.HERE, Tag.NAME]))
HOW_MANY_DOING = Rule("how many X do", _how_many_doing, (
    Example("How many people in the kitchen wear a hat?", "wear", Tag.VBG_T),
    Example("how many people in the bedroom raise their left arm", "raise", Tag.VBG_T),
    Example("how many people in the office point to the left", "point", Tag.VBG_P),
    Example("how many men in the hall sit?", "sit", Tag.VBG_I),
), None, "'how many X V': what the counted do, read as 'are V-ing'", after=frozenset([Tag.WORD]))
HOW_MANY_SAID = Rule("how many, said", _how_many_said, (
    Example("tell Anna how many cups are left", "how many cups are left", Tag.SAID),
), frozenset(["how"]), "'how many ...' after a verb of saying and the person told: what is said")
_WHERE_ASKER_FIRST = first_words(WHERE_ASKERS)


def _asks_where_first(low: str) -> bool:
    """Where a lead-in asking where can start (:func:`_where_asker`; its rule's gate)."""
    return low in _WHERE_ASKER_FIRST or gerund_lemma(low) in _WHERE_ASKER_FIRST


ASKED_WHERE = Rule("asked where", _asked_where, (
    Example("Do you know where the tea spoon is?", "Do you know where", Tag.VERB),
    Example("can you tell me where the keys are?", "tell me where", Tag.VERB),
    Example("Would you know where I left my phone?", "know where I left", Tag.VERB),
    Example("did you see where I put my wallet", "did you see where I put", Tag.VERB),
    Example("would you mind showing me where the remote is", "showing me where", Tag.VERB),
), _asks_where_first, "'do you know / tell me where X is': find X")
WHERE_BE_DROPPED = Rule("is, after asked where", _where_be, (
    Example("do you know where the tea spoon is", "is", ""),
    Example("do u know where the remote went", "went", ""),
    Example("where's the remote gone?", "gone", ""),
    Example("where is the ladle kept?", "kept", ""),
    Example("where are the jars usually stored?", "stored", ""),
), None, "the 'is' of 'do you know where X is', dropped: 'do you know where' was read as 'find'",
   after=frozenset([Tag.WORD, Tag.NAME, Tag.PARTICLE]))
ENSURED_RULE = Rule("make sure of a state", _ensured, (
    Example("please make sure the stove is off", "make sure", Tag.VERB),
    Example("Please make sure the door is closed", "make sure", Tag.VERB),
    Example("ensure that the lights are turned off", "ensure that", Tag.VERB),
    Example("make sure the soup is hot", "make sure", Tag.VERB),
), first_words(ENSURED), "'make sure X is off / closed': turn X off, close X")
ENSURED_STATE = Rule("the state made sure of", _ensured_dropped, (
    Example("make sure the lamp is on", "is on", ""),
), _ENSURED_BE, "the 'is closed' of 'make sure the door is closed', dropped: it was read as the verb")
KNOW_WISH = Rule("wish to know", _know_wish, (
    Example("I'd like to know the heaviest object on the bookshelf.", "I'd like to know", Tag.VERB),
    Example("Do you know how many people in the bedroom are wearing white jackets?", "Do you know how many",
            Tag.VERB),
    Example("Any idea how many drinks are in the fridge?", "Any idea how many", Tag.VERB),
), first_words(KNOW_WISHES), "'I'd like to know X', 'do you know X', 'any idea X': tell me X")
HOW_MUCH_COUNTED = Rule("how much of a plural", _how_much_counted, (
    Example("how much cups are in the sink?", "how much", Tag.VERB),
    Example("how much dirty towels are there in the basket", "how much", Tag.VERB),
), frozenset(["how"]), "'how much plates': how many (a plural counts)")
WHICH_PLACE = Rule("which room is X in", _which_place, (
    Example("which room is grandpa in?", "which room is", Tag.VERB),
    Example("what floor is the laundry on", "what floor is", Tag.VERB),
), frozenset(["which", "what"]), "'which room is X in?': find X (where is X)")
STRANDED_WHERE = Rule("the preposition left at the end of which room", _stranded_where, (
    Example("which room is grandpa in?", "in", ""),
), _STRANDED, "the 'in' of 'which room is X in?': dropped")
INFORMATION_GIVEN = Rule("give me the name of", _information_given, (
    Example("give me the name of the person at the door", "give", Tag.VERB),
    Example("Bring me the names of the three biggest objects on the shelf", "Bring", Tag.VERB),
), None, "'give me the name of X': tell me the name of X", after=frozenset([START, Tag.POLITE, Tag.SEP]),
   needs=INFORMATION)
NUMBER_OF_RULE = Rule("the number of", _number_of, (
    Example("Tell me the total number of snacks on the desk.", "Tell me the total number of", Tag.VERB),
    Example("What number of people in the bedroom wear white jackets?", "What number of", Tag.VERB),
    Example("Count the number of people wearing glasses in the kitchen", "Count the number of", Tag.VERB),
), first_words(NUMBER_OF), "'tell me the number of X', 'what number of X': tell me how many X",
   needs=frozenset(p.split()[-2] for p in NUMBER_OF))     # "number", "count": each phrase's noun
LET_KNOW_RULE = Rule("let me know", _let_know, (
    Example("let me know when the laundry is done", "let", Tag.VERB),
    Example("let me know how many bottles are in the fridge", "let me know how many", Tag.VERB),
    Example("let Amara know that her package arrived", "Amara", Tag.NAME),
    Example("let maria know dinner is ready", "maria", Tag.NAME),
    Example("let grandpa know that his taxi is here", "grandpa", Tag.NAME),
    Example("let mum and dad know dinner is ready", "let", Tag.VERB),
    Example("let the person at the chairs know what gesture the person at the sofa is making", "let", Tag.VERB),
    Example("let everyone in the den know that the film is starting", "let", Tag.VERB),
    Example("let everybody know lunch is served", "let", Tag.VERB),
    Example("let Jo know the bus leaves at six", "the bus leaves at six", Tag.SAID),
), frozenset([LET_KNOW[0]]), "'let X know': tell X")
KNOW_AFTER_LET = Rule("know after let X", _know_after_let, (
    Example("let the people in the hall know that dinner is ready", "know", ""),
    Example("let mum and dad know dinner is ready", "dinner is ready", Tag.SAID),
), frozenset([LET_KNOW[1]]), "the 'know' of 'let the guests know ...', dropped: 'let' was read as 'tell'")


_PHRASE_TAGS = frozenset({Tag.PREP, Tag.OF, Tag.DET, Tag.NUM, Tag.POSS, Tag.WORD, Tag.NAME, Tag.RESULT, Tag.LABEL,
                          Tag.AND_NP, Tag.PRON})


def _fronted_of(s: State, i: int) -> Match | None:
    n = 2 if s.words[i].lower == "out" else 1     # "*out of* the people in the hall, how many ...": "of"
    if n == 2 and s.next_lower(i) != "of" or not s.np_starts(i + n) or not _fronted_ends(s, i + n):
        return None
    if s.words[i].lower != "of":                  # "out of the fridge, take the milk": where from, as said
        comma = next(k for k in range(i + n, len(s.words)) if s.words[k].lower == ",")
        if comma + 1 >= len(s.words) or s.words[comma + 1].lower not in WH_WORDS:
            return None
    return s.emit(i, n, Tag.PREP, "of")


def _fronted_ends(s: State, i: int) -> bool:
    """Whether a phrase from ``i`` ends at a comma before a clause in the same sentence."""
    words = s.words
    for k in range(i, len(words)):
        if words[k].lower in END_MARKS or words[k].lower == ";":
            return False
        if words[k].lower == ",":
            return _clause_at(s, k + 1)
    return False


def _clause_at(s: State, k: int) -> bool:
    return k < len(s.words) and (s.verb_after(k) or s.words[k].lower in QUESTION_WORDS and _question(s, k) is not None
                                 or _where(s, k) is not None)


def _fronted_question(s: State, i: int) -> Match | None:
    """A phrase said before a question ("*On the table,* which object is lightest?"): the phrase is part
    of what to tell."""
    words = s.words
    if QUESTION_MEANS not in s.lexicon.units or not match_phrase(words, i, PREPOSITIONS) and words[i].lower != "of" \
            and not match_phrase(words, i, TOPICS):   # "*regarding* the jars on the shelf, which is the oldest?"
        return None
    k = i + 1
    while k < len(words) and words[k].lower not in END_MARKS and words[k].lower not in (",", ";") and \
            not (k > i + 2 and words[k].lower in QUESTION_WORDS and _asked_to_the_end(s, k)):
        k += 1
    asked = k + (words[k].lower == ",") if k < len(words) else k      # the comma may be left out (words33)
    if asked >= len(words) or words[asked].lower not in QUESTION_WORDS or _question(s, asked) is None:
        return None
    end = s.speech_end(asked)
    return Match(end - i, (_unsaid(words[i].start, Tag.VERB, QUESTION_MEANS), s.emit(i, end - i, Tag.SAID).words[0]),
                 expect=False, verb=QUESTION_MEANS, using=False)


_TAKEN_UP = frozenset(["it", "they", "them", "he", "she", "him", "her", "that", "this", "those", "these", "one",
                       "its", "their", "his"])
"""Pronouns with which a question takes up the phrase said before it ("the heaviest jar, what is *it*?"; a
possessive too, "the man at the door, what's *his* name?": words41)."""
_PHRASE_BREAKS = frozenset([",", ";", ":"])
"""What ends a phrase said first before the question that takes it up: a comma, a dash (read as ";") or a colon
("the person by the shelf *-* what are they wearing?", words41)."""


def _phrase_said_first(s: State, i: int) -> int | None:
    """Where the noun phrase from ``i`` ends (the index of the comma, semicolon or end mark after it) when it is a
    phrase said first for a question to take up (:func:`_phrase_asked`, :func:`_phrase_counted`); None when a verb of
    the library in its base form stands in it ("the cup, bring it": a command takes it up, ``DISLOCATED``)."""
    words = s.words
    k = i + 1
    while k < len(words) and words[k].lower not in END_MARKS and words[k].lower not in _PHRASE_BREAKS:
        if s.verb_at(k) is not None and verb_lemma(words[k].lower) == words[k].lower and \
                words[k - 1].lower not in NP_OPENERS:
            return None
        k += 1
    return k


def _phrase_asked(s: State, i: int) -> Match | None:
    """A noun phrase said first and taken up by a pronoun of the question after its comma ("*the heaviest jar on the
    shelf*, what is it?", "the man by the door, who is he?"; words37): the phrase is part of what to tell, as a
    phrase of place before a question is (:func:`_fronted_question`)."""
    words = s.words
    if QUESTION_MEANS not in s.lexicon.units or s.out and s.out[-1].tag != Tag.POLITE or \
            words[i].lower not in NP_OPENERS:
        return None
    k = _phrase_said_first(s, i)
    if k is None or k + 2 >= len(words) or words[k].lower not in _PHRASE_BREAKS or \
            words[k + 1].lower not in QUESTION_WORDS or \
            not _asked_to_the_end(s, k + 1) or _question(s, k + 1) is None:
        return None
    end = s.speech_end(k + 1)
    if not any(w.lower in _TAKEN_UP for w in words[k + 2:end]):
        return None                               # "the cup, what about the plate?": nothing taken up
    return Match(end - i, (_unsaid(words[i].start, Tag.VERB, QUESTION_MEANS), s.emit(i, end - i, Tag.SAID).words[0]),
                 expect=False, verb=QUESTION_MEANS, using=False)


_COUNTED_TAKEN_UP = frozenset(["that", "those", "these", "they"])
"""Pronouns after "how many is/are" that take up the phrase said before the comma (words39)."""


def _count_tail(s: State, k: int) -> int:
    """How many words from the comma at ``k`` to the sentence's end ask how many of the phrase before it there are
    (", how many are there?", ", how many of them are left", ", how many is there": words37; ", how many is that?",
    ", how many are they": words39); 0 if they do not."""
    words = s.words
    if k + 3 >= len(words) or words[k].lower != "," or words[k + 1].lower != "how" or words[k + 2].lower != "many":
        return 0
    m = k + 3
    if m + 1 < len(words) and words[m].lower == "of" and words[m + 1].lower in ("them", "those", "these"):
        m += 2
    if m < len(words) and words[m].lower in ("are", "is"):
        m += 1
    else:
        return 0
    if m < len(words) and words[m].lower in _COUNTED_TAKEN_UP:
        m += 1                  # ", how many *is that*?", ", how many are *they*?": a pronoun takes up the phrase
    while m < len(words) and words[m].lower in ("there", "left", "remaining", "in", "here", "now"):
        if words[m].lower == "in" and not (m + 1 < len(words) and words[m + 1].lower == "there"):
            return 0
        m += 1
    return m - k if m == len(words) or words[m].lower in END_MARKS else 0


def _phrase_counted(s: State, i: int) -> Match | None:
    """A noun phrase said first and counted by the question after its comma ("*the mugs on the counter*, how many are
    there?"; words37): count them (the unit "how many"), the question after the comma dropped
    (:data:`COUNT_TAIL_DROPPED`), as "how many mugs are on the counter?" does."""
    words = s.words
    unit = tuple(_COUNTED.split())
    if unit not in s.lexicon.units.get(unit[0], ()) or s.out and s.out[-1].tag != Tag.POLITE or \
            words[i].lower not in NP_OPENERS:
        return None
    k = _phrase_said_first(s, i)
    if k is None or k == i + 1 or not _count_tail(s, k):
        return None
    return Match(1, (_unsaid(words[i].start, Tag.VERB, _COUNTED), words[i].tagged(Tag.DET)), expect=False,
                 verb=_COUNTED, using=False)


def _count_tail_dropped(s: State, i: int) -> Match | None:
    verb = s.out[s.verb_index] if s.verb_index >= 0 else None
    if verb is None or verb.info != _COUNTED or verb.text:
        return None
    n = _count_tail(s, i)
    return Match(n) if n else None


def _asked_to_the_end(s: State, k: int) -> bool:
    """Whether a question that starts at ``k`` is all the rest of its sentence and asks ("in the hall *which person
    is standing?*"): a question mark ends it, and no verb of the library in its base form is said in it (a command
    the question word only opened a relative clause before: "in the box which is red put the cup"). Crowd workers
    often leave the mark out or write a stop ("on the shelf what is the biggest object", words41): the command's
    end does as well, when nothing follows it."""
    words = s.words
    m = k + 1
    while m < len(words) and words[m].lower not in END_MARKS:
        low = words[m].lower
        if low in (",", ";") or s.verb_at(m) is not None and verb_lemma(low) == low and \
                words[m - 1].lower not in NP_OPENERS:
            return False                          # "what is her *name*": a noun after a possessive (words48)
        m += 1
    return m >= len(words) or words[m].lower == "?" or m == len(words) - 1


_FRONTED_FIRST = frozenset([*LOCATIVE, "from", "to", "into", "onto", "out of", "off"])
"""Prepositions that may open a phrase said before the verb with no comma after it (words33)."""


def _fronted_unmarked(s: State, i: int) -> Match | None:
    """A phrase of place said first with no comma after it ("*From the dresser* take the hairbrush", "*In the
    kitchen* how many people are standing?", words33): all the clause holds so far is that phrase (a preposition
    of place, then a noun phrase ending in a noun), and a verb of the library in its base form starts here (or a
    question's unit: "how many"). The clause starts at the verb, as after the comma ("From the dresser, take ...")."""
    out, words = s.out, s.words
    if not out or out[-1].tag not in (Tag.WORD, Tag.NAME):
        return None
    k = len(out) - 1
    while k >= 0 and out[k].tag in _PHRASE_TAGS and out[k].tag != Tag.PREP:
        k -= 1
    if k < 0 or out[k].tag != Tag.PREP or out[k].info not in _FRONTED_FIRST or \
            k > 0 and out[k - 1].tag not in (Tag.SEP, Tag.END, Tag.POLITE) or \
            any(w.tag == Tag.PREP for w in out[k + 1:]):
        return None
    found = s.verb_at(i)
    low = words[i].lower
    polite = match_phrase(words, i, POLITE) if found is None and low not in ("to", "and", "then") else 0
    if polite and s.verb_after(i + polite):     # "From the shelf *could you* get me the book"
        return Match(polite, (_unsaid(words[i].start, Tag.SEP), merge(words, i, polite, Tag.POLITE)), expect=True)
    if found is None or not (verb_lemma(low) == low or found[1] > 1 and low == "how") or \
            out[k].info in ("to", "into", "onto") and found[0] not in s.lexicon.goals:
        return None                             # "to the lamp turn on the light": no goal of it, refused as before
    unit, n, split = found
    return Match(n, (_unsaid(words[i].start, Tag.SEP), merge(words, i, n, Tag.VERB, unit)), expect=False, verb=unit,
                 using=False, particle=(split, unit) if split is not None else None)


def _fronted_end(s: State, i: int) -> Match | None:
    """A comma ending a phrase said before the clause's verb ("*From the cupboard,* give me the bowl", "*On
    the table,* which object is lightest?"): the clause starts after it."""
    out = s.out
    k = len(out) - 1
    while k >= 0 and out[k].tag in _PHRASE_TAGS:
        k -= 1
    if k == len(out) - 1 and not (out and out[-1].tag == Tag.HERE and (k == 0 or out[k - 1].tag == Tag.SEP)):
        return None                               # "*in there,* find the sponge": a place pointed at, said first
    if k < len(out) - 1 and out[k + 1].tag != Tag.PREP or not _clause_at(s, i + 1):
        return None
    if 0 <= k < len(out) - 1 and out[k].tag not in _BEFORE_FRONTED:
        return None                               # "answer the man standing *in the hall*, who ...": no phrase said
    return Match(1, (s.words[i].tagged(Tag.SEP),), expect=True)     # first, the clause's own (words35)


_BEFORE_FRONTED = frozenset([Tag.SEP, Tag.POLITE, Tag.END])
"""Tags a phrase said before the verb may follow: it opens its clause."""


FRONTED_OF = Rule("of-phrase first", _fronted_of, (
    Example("Of the people in the hall, how many are sitting?", "Of", Tag.PREP),
    Example("Among the people in the kitchen, how many are standing?", "Among", Tag.PREP),
    Example("out of the people in the office, how many are waving?", "out of", Tag.PREP),
), frozenset(["of", "among", "amongst", "out"]),
    "'of' ('among', 'out of') and a noun phrase before the clause ('Of the people in the hall, how many ...')")
FRONTED_QUESTION = Rule("phrase said before a question", _fronted_question, (
    Example("On the table, which object is lightest?", "On the table, which object is lightest", Tag.SAID),
    Example("in the garage which car is the oldest?", "in the garage which car is the oldest", Tag.SAID),
    Example("Regarding the jars on the shelf, which is the oldest?", "Regarding the jars on the shelf, which is the "
            "oldest", Tag.SAID),
), first_words(PREPOSITIONS) | {"of"} | first_words(TOPICS),
    "a phrase and a comma before a question: all of it is what to tell")
PHRASE_ASKED = Rule("phrase said before a question that takes it up", _phrase_asked, (
    Example("The heaviest jar on the shelf, what is it?", "The heaviest jar on the shelf, what is it", Tag.SAID),
    Example("the man by the gate, who is he?", "the man by the gate, who is he", Tag.SAID),
), first_words(NP_OPENERS), "a noun phrase and a comma before a question with a pronoun: all of it is what to tell")
PHRASE_COUNTED = Rule("phrase said before how many", _phrase_counted, (
    Example("the jars on the shelf, how many are there?", "the", Tag.DET),
    Example("those mugs in the sink, how many of them are left", "those", Tag.DET),
    Example("the spoons in the drawer, how many is that?", "the", Tag.DET),
), first_words(NP_OPENERS), "a noun phrase and a comma before 'how many are there': count what it names")
COUNT_TAIL_DROPPED = Rule("how many are there, after the phrase counted", _count_tail_dropped, (
    Example("the jars on the shelf, how many are there?", "how", ""),
), frozenset([","]), "the ', how many are there' of a phrase said first and counted, dropped")
FRONTED_UNMARKED = Rule("phrase said first, no comma", _fronted_unmarked, (
    Example("From the dresser take the hairbrush", "take", Tag.VERB),
    Example("In the kitchen how many people are standing?", "how many", Tag.VERB),
    Example("in the garage you'll find a ladder and bring it here", "you'll", Tag.POLITE),      # words46
), lambda low: low.isalpha() or low in POLITE, "a phrase of place said before the verb with no comma: the clause "
   "starts at the verb (or at politeness before it)",
   after=frozenset([Tag.WORD, Tag.NAME]))
FRONTED_END = Rule("phrase said first", _fronted_end, (
    Example("From the cupboard, give me the bowl", ",", Tag.SEP),
    Example("go to the kitchen. In there, find the sponge", ",", Tag.SEP),
), frozenset([","]), "the comma after a phrase said before the verb: the clause starts after it")
