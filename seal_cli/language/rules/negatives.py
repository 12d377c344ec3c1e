"""What a person takes back: a prohibition ("don't open the window, close it"), a request cancelled ("never
mind the lamp, ..."), and a phrase corrected as it is said ("bring the cup, no, the mug").

A prohibition asks the robot not to do something, which no frame of the library does: its clause is dropped
as a remark when another clause holds the command, and said alone it is an error that says so (never the
frame of its verb: "can you not slam the door" is no Close). A correction says the phrase meant instead of the
last phrase said: the earlier one is dropped and the new one read in its place.
"""

from __future__ import annotations

from collections.abc import Sequence

from seal_cli.language.english import (
    CANCELLATIONS,
    CORRECTION_MARKS,
    END_MARKS,
    HALTS,
    MODALS,
    NOT_FORGOTTEN,
    NP_OPENERS,
    OBJECT_PRONOUNS,
    PARTICLES,
    PREPOSITIONS,
    PROHIBITIVES,
    SUBJECTS,
)
from seal_cli.language.morphology import in_verb_tables, verb_lemma
from seal_cli.language.rule import Example, Match, Rule
from seal_cli.language.state import CLOSED, TIME_FIRST, State, first_words, longest_phrase, match_phrase, merge
from seal_cli.language.tags import Tag
from seal_cli.language.tokens import Word

_JOINS = frozenset(["and", "but", "then", "or"])
_CLAUSE_ENDS = frozenset([",", ";", ":"]) | END_MARKS
_NP_TAGS = frozenset([Tag.WORD, Tag.RESULT, Tag.NAME, Tag.LABEL, Tag.NUM, Tag.OF])
_NP_OPENING = frozenset([Tag.DET, Tag.POSS])


def _negation(s: State, i: int) -> int:
    """How many words of a prohibition's opening start at ``i`` (0: none): "don't", "do not", "never", or a
    cancellation ("never mind", "no need to"); "not" after a modal and "you" ("can you *not* slam the door") or
    after a lead-in that ends in a modal or "to" ("you should *not* open it", "the robot must *not* open it") when
    the sentence asks no question (no "?": "can you not find it?" asks whether the robot can find it)."""
    words = s.words
    n = longest_phrase(words, i, CANCELLATIONS)
    if n:
        return n
    if halted(words, i):
        return 1                                 # "stop!", "okay stop, wait there": halt, no ToggleOff
    n = longest_phrase(words, i, PROHIBITIVES)
    if n:
        nxt = words[i + n].lower if i + n < len(words) else ""
        if nxt in SUBJECTS or nxt == "you":
            return 0                             # "don't we have any bulbs?", "don't you see it?": a question
        return 0 if verb_lemma(nxt) in NOT_FORGOTTEN or nxt in NOT_FORGOTTEN else n   # "don't forget to ..."
    if words[i].lower == "not" and len(s.out) and s.out[-1].tag == Tag.POLITE and \
            s.out[-1].lower.split()[:1] and s.out[-1].lower.split()[0] in MODALS and \
            s.out[-1].lower.split()[-1] == "you" and i + 1 < len(words) and \
            _not_asked(s, i + 1):
        return 1
    if words[i].lower == "not" and len(s.out) and s.out[-1].tag == Tag.POLITE and \
            len(s.out[-1].lower.split()) > 1 and s.out[-1].lower.split()[-1] in (*MODALS, "to") and \
            i + 1 < len(words) and _not_asked(s, i + 1):
        return 1                                 # "you should *not* open it", "the robot must *not* ..." (alfred30)
    return 0


_NEGATIONS = PROHIBITIVES | CANCELLATIONS


def halted(words: Sequence[Word], k: int) -> bool:
    """Whether word ``k`` is a verb of halting said with no object ("*stop*", "*stop*, don't put that there",
    "*stop*! wait there"): the robot asked to stop what it does, no frame of the library ("stop *the music*"
    turns something off)."""
    return words[k].lower in HALTS and (k + 1 >= len(words) or words[k + 1].lower in _CLAUSE_ENDS)


def opens_prohibition(words: Sequence[Word], k: int) -> bool:
    """Whether the tagged word ``k`` opens a prohibition or a cancellation, as :func:`_negation` reads them: one of
    ``english.PROHIBITIVES`` or ``english.CANCELLATIONS`` (merged into one word by the rule that refuses it, "do
    not", "never mind", or said out: "*don't* open the window", "*no need to* wash it"), or "not" right after
    "... you" ("can you *not* slam the door") or after a lead-in that ends in a modal or "to" ("you should *not*
    open the window", "the robot must *not* open it", "you need to *not* touch it"; alfred30). The one source of the
    parser's message "asks the robot not to do something" (words29; the parser had its own word list)."""
    low = words[k].lower
    if low in _NEGATIONS or longest_phrase(words, k, _NEGATIONS) or halted(words, k):
        return True
    if low != "not" or k == 0:
        return False
    said = words[k - 1].lower.split()
    return said[-1:] == ["you"] or len(said) > 1 and (said[-1] in MODALS or said[-1] == "to")


def _not_asked(s: State, k: int) -> bool:
    """Whether the sentence going on at ``k`` ends without a question mark."""
    words = s.words
    while k < len(words) and words[k].lower not in END_MARKS:
        k += 1
    return k >= len(words) or words[k].lower != "?"


def _prohibition_end(s: State, k: int) -> int:
    """Where the clause of a prohibition starting at ``k`` ends: at a comma, a semicolon or an end mark, or
    at "and"/"but"/"then" before a verb (the next clause)."""
    words = s.words
    while k < len(words):
        low = words[k].lower
        if low in _CLAUSE_ENDS or low in _JOINS and s.verb_after(k + 1):
            return k
        k += 1
    return k


def _command_after(s: State, k: int) -> bool:
    """Whether a clause with a command starts at ``k``, after the prohibition's separator ("don't open the window,
    *close it*"): a verb of the library, maybe after "but", "and", "then", "just", "instead" or politeness."""
    words = s.words
    while k < len(words) and (words[k].lower in _CLAUSE_ENDS or words[k].lower in _JOINS or
                              words[k].lower in ("instead", "rather")):
        k += 1
    return k < len(words) and (s.verb_after(k) or s.asks_at(k) or _unknown_imperative(s, k))


def _unknown_imperative(s: State, k: int) -> bool:
    """Whether an imperative with a verb of English no frame has starts at ``k`` (maybe after "just"): its base form
    and then an object or a particle ("don't turn it off, just *turn it down*"): a command of its own, refused at its
    verb, not the prohibition refused for it (words36)."""
    words = s.words
    k += k < len(words) and words[k].lower in ("just", "please")
    if k + 1 >= len(words):
        return False
    low, nxt = words[k].lower, words[k + 1].lower
    return low.isalpha() and low not in CLOSED and verb_lemma(low) == low and in_verb_tables(low) and \
        (nxt in NP_OPENERS or nxt in OBJECT_PRONOUNS or nxt in PARTICLES)


def _prohibited_first(s: State, i: int) -> Match | None:
    n = _negation(s, i)
    if not n:
        return None
    words = s.words
    end = _prohibition_end(s, i + n)
    if end <= i + n and not halted(words, i):
        return None
    said = any(w.tag == Tag.VERB for w in s.out)
    if not said and not _command_after(s, end):
        return Match(n, (merge(words, i, n, Tag.WORD),), expect=False)
        # "can you not slam the door", "never leave the door open": refused at the negation, never a Close or an Open
    stop = end + 1 if end < len(words) and words[end].lower in (",", ";", ":") or \
        end < len(words) and words[end].lower in END_MARKS else end
    return Match(stop - i, remarks=((words[i].start, words[end - 1].end),), expect=True)


def _denied_first(s: State, i: int) -> Match | None:
    """"*not the blue cup,* bring me the red one": "not" and a noun phrase, a comma, then a command: which thing is
    not meant, a remark (the command's phrase says which is)."""
    words = s.words
    if s.out and s.prev_tag() not in (Tag.SEP, Tag.POLITE) or not s.np_starts(i + 1) or s.verb_after(i + 1):
        return None
    k = i + 1
    while k < len(words) and words[k].lower not in _CLAUSE_ENDS and words[k].lower not in _JOINS:
        k += 1
    if k >= len(words) or words[k].lower != "," or k == i + 1 or not _command_after(s, k + 1):
        return None
    return Match(k + 1 - i, remarks=((words[i].start, words[k - 1].end),), expect=True)


def _denied_after(s: State, i: int) -> Match | None:
    """"give me the big bowl*, not the small one*": a comma, "not" and a noun phrase ending the sentence (or before
    the next comma) after the command: which thing is not meant, a remark."""
    words = s.words
    if i + 2 >= len(words) or words[i + 1].lower != "not" or s.expect_verb or not s.np_starts(i + 2) or \
            s.verb_after(i + 2) or words[i + 2].lower in TIME_FIRST:
        return None                              # ", not now": when, not which (as before)
    k = i + 2
    while k < len(words) and words[k].lower not in _CLAUSE_ENDS and words[k].lower not in _JOINS:
        k += 1
    if k < len(words) and words[k].lower not in END_MARKS and words[k].lower != ",":
        return None
    return Match(k - i, remarks=((words[i + 1].start, words[k - 1].end),))


def _prohibited_after(s: State, i: int) -> Match | None:
    """", but don't wash it", "and never leave it open": a prohibition said after the command, with its joint."""
    words = s.words
    k = i
    while k < len(words) and (words[k].lower in (",", ";") or words[k].lower in _JOINS):
        k += 1
    if k == i or k >= len(words) or s.expect_verb:
        return None
    n = _negation(s, k)
    if not n or words[k].lower == "not":
        return None
    end = _prohibition_end(s, k + n)
    if end <= k + n:
        return None
    return Match(end - i, remarks=((words[k].start, words[end - 1].end),))


def _corrected(s: State, i: int) -> Match | None:
    """", no, the mug": the phrase after a correction's marks replaces the last noun phrase said. After "and" or
    "but" ("go to the kitchen *and no wait,* go to the office": issue #13, the marks were read into the goal) only
    with a comma after the marks ("and no sugar", "and actually clean it" correct nothing), and then the clause's
    verb again or a phrase with a determiner ("but actually, *the* fork")."""
    words = s.words
    if words[i].lower in _CORRECTION_JOINS and not _marks_then_comma(words, i + 1):
        return _correction(s, i, i + 1, bare=True) if _marks_said(words, i + 1) >= 2 else None
    return _correction(s, i, i + 1)


def _corrected_unjoined(s: State, i: int) -> Match | None:
    """"bring me the cup *no wait* the mug", "grab the salt *actually no* the pepper", "put it in the sink *sorry I
    mean* the dishwasher": a correction said with no comma before it (issue #13: refused, the marks lost). Only marks
    of two words or more ("no" alone is a determiner: "a coffee no sugar"; "wait" alone a verb: "... and wait"), then
    the phrase with a determiner or the clause's verb again, as after "and" (:func:`_corrected`)."""
    words = s.words
    if i == 0 or words[i - 1].lower == "," or words[i - 1].lower in _CORRECTION_JOINS:
        return None                              # with a comma or a joint: the rule of ", no, NP"
    return _correction(s, i, i, bare=True) if _marks_said(words, i) >= 2 else None


def _marks_said(words: Sequence[Word], k: int) -> int:
    """How many words of a correction's marks, with no comma between, start at ``k`` ("no wait": 2)."""
    start = k
    while (n := longest_phrase(words, k, CORRECTION_MARKS)) > 0:
        k += n
    return k - start if k < len(words) else 0


def _correction(s: State, i: int, k: int, *, bare: bool = False) -> Match | None:
    """The correction whose marks start at ``k``, its match consuming from ``i`` (the comma or joint before them,
    or the marks themselves: ``bare``)."""
    words = s.words
    marks, denied, said = 0, False, 0
    while k < len(words):
        if words[k].lower == ",":
            k += 1
            continue
        if words[k].lower == "or" and longest_phrase(words, k + 1, CORRECTION_MARKS):
            k += 1                               # ", *or* actually the white one": "or" before the marks
            continue
        n = longest_phrase(words, k, CORRECTION_MARKS)
        if not n:
            break
        denied = denied or any(w.lower == "no" for w in words[k:k + n])
        k, marks, said = k + n, marks + 1, said + n
    if not marks or k >= len(words) or not bare and words[k - 1].lower != "," and \
            words[k - 1].lower in ("no", "wait", "sorry"):
        return None                              # "coffee, no sugar": "no" is its determiner
    if words[k].lower == "not":                  # ", no, *not the salt,* the pepper": the phrase denied, said again
        j = k + 1
        while j < len(words) and words[j].lower not in _CLAUSE_ENDS:
            j += 1
        if j >= len(words) or words[j].lower != ",":
            return None
        k = j + 1
    again = _clause_again(s, i, k, other=denied and (said > 1 or words[k - 1].lower == ","))
    if again is not None:                        # ", no, close it": "no" set off by commas denies (words49)
        return again
    if words[k].lower in PREPOSITIONS:
        return _place_corrected(s, i, k)
    if (bare or words[i].lower in _CORRECTION_JOINS) and words[k].lower not in NP_OPENERS:
        return None                              # "and, I mean, *see* if Jane is there": a next step, no phrase
    if not s.np_starts(k) or s.verb_after(k) and words[k].lower not in ("the", "a", "an", "my", "your"):
        return None
    end = k
    while end < len(words) and words[end].lower not in _CLAUSE_ENDS and words[end].lower not in ("and", "then"):
        end += 1
    if end < len(words) and words[end].lower not in END_MARKS:
        return None                              # only a phrase ending its sentence
    out = s.out
    split = len(out) > 1 and out[-1].tag == Tag.PARTICLE and s.verb_index >= 0 and \
        (out[s.verb_index].lower,) not in s.lexicon.units.get(out[s.verb_index].lower, ())  # "turn the oven *on*,
    # sorry, the grill"; not "put": a verb alone, and the particle may say where the phrase goes
    m = len(out) - split
    while m > 0 and out[m - 1].tag in _NP_TAGS:
        m -= 1
    if m > 0 and out[m - 1].tag in _NP_OPENING:
        m -= 1
    elif m == len(out) and m > 0 and out[m - 1].tag == Tag.PRON:
        m -= 1                                   # "bring it, no, the mug"
    if m == len(out) - split or m == 0 or s.verb_index >= m:
        return None
    if split:                                    # the particle stays with its verb, before the phrase said again
        return Match(k - i, last=out[-1], replaces=len(out) - m)
    return Match(k - i, last=out[m - 1], replaces=len(out) - m + 1)


def _place_corrected(s: State, i: int, k: int) -> Match | None:
    """", I mean *on the hook*": after a correction's marks, a preposition and its phrase ending the sentence replace
    the last preposition and phrase said in the clause ("put the keys on the shelf, I mean on the hook": the hook is
    the goal; words49: the correction was a remark, the shelf kept)."""
    words, out = s.words, s.out
    n = match_phrase(words, k, PREPOSITIONS)
    if not n or not s.np_starts(k + n) or s.verb_after(k + n):
        return None
    end = k + n
    while end < len(words) and words[end].lower not in _CLAUSE_ENDS and words[end].lower not in ("and", "then"):
        end += 1
    if end < len(words) and words[end].lower not in END_MARKS:
        return None
    m = len(out)
    while m > 0 and out[m - 1].tag in _NP_TAGS:
        m -= 1
    if m > 0 and out[m - 1].tag in _NP_OPENING:
        m -= 1
    if m == len(out) or m < 2 or out[m - 1].tag != Tag.PREP or s.verb_index >= m - 1:
        return None
    return Match(k - i, last=out[m - 2], replaces=len(out) - m + 2)


_CORRECTION_JOINS = frozenset(["and", "but"])
"""Joints a correction's marks may follow in place of a comma ("go to the hall *and* no wait, the porch")."""


def _marks_then_comma(words: Sequence[Word], k: int) -> bool:
    """A correction's marks at ``k`` (commas before and between them allowed) whose last is followed by a comma."""
    while k < len(words) and words[k].lower == ",":
        k += 1
    n = longest_phrase(words, k, CORRECTION_MARKS)
    while n:
        k += n
        if k >= len(words) or words[k].lower != ",":
            return False
        while k < len(words) and words[k].lower == ",":
            k += 1
        n = longest_phrase(words, k, CORRECTION_MARKS)
        if not n:
            return True
    return False


def _clause_again(s: State, i: int, k: int, *, other: bool = False) -> Match | None:
    """"find Oscar, *actually find Nina*", "go to the hall, sorry, go to the porch": after a correction's marks, the
    clause's own verb said again starts it afresh — the clause said before the marks is taken back, a remark (it
    asks nothing; words31: both were done). Only the same verb, as said (its first word: "turn on the lamp, sorry,
    *turn* it off", words34): another verb may be a next step ("open the door, sorry, then close the window" is no
    correction of the opening). ``other``: marks that deny ("no", then "wait"/"sorry": "open the door, *no wait,*
    close it") take the clause back before any verb (words47: "no wait" was a phrase joined to "the door")."""
    out, words = s.out, s.words
    if s.verb_index < 0 or k >= len(words) or not out[s.verb_index].lower or not s.verb_after(k) or \
            words[k].lower != out[s.verb_index].lower.split()[0] and not (other and s.verb_at(k) is not None):
        return None
    first = out[s.verb_index]
    said = Word(s.text_of(first.start, words[k - 1].end) or first.text, first.start, words[k - 1].end, Tag.POLITE)
    return Match(k - i, last=said, replaces=len(out) - s.verb_index,
                 remarks=((first.start, out[-1].end),), expect=True)


PROHIBITED_FIRST = Rule("a prohibition, then the command", _prohibited_first, (
    Example("don't open the door, shut the window instead", "open", ""),
    Example("please do not go in the garage. wait in the hall", "garage", ""),
    Example("never mind the kettle, switch on the radio", "kettle", ""),
    Example("could you not bang the door, just shut it", "bang", ""),
    Example("can you not bang the door", "not", Tag.WORD),
    Example("you should not open the window, close it", "open", ""),
    Example("the robot must not touch the oven, wipe the counter", "touch", ""),
    Example("never leave the door open", "never", Tag.WORD),
    Example("okay stop, wait in the hall", "stop", ""),
    Example("stop!", "stop", Tag.WORD),
), first_words(_NEGATIONS) | HALTS | {"not"},
    "a clause said negatively before the command asks nothing: a remark; alone, an error")
DENIED_FIRST = Rule("a phrase denied, then the command", _denied_first, (
    Example("not the blue cup, bring me the red one", "blue", ""),
    Example("not the green towel, please take the white one to the bathroom", "green", ""),
), frozenset(["not"]), "'not NP, V ...': the phrase denied before the command is a remark (which one is not meant)")
PROHIBITED_AFTER = Rule("a prohibition after the command", _prohibited_after, (
    Example("take the plate but don't wash it", "wash", ""),
    Example("shut the window, and never open it again", "open", ""),
    Example("switch off the radio, but don't touch the tv", "tv", ""),
), frozenset([",", ";", "and", "but", "then", "or"]), "', but don't V ...' after the command asks nothing: a remark")
CORRECTED = Rule("a phrase corrected", _corrected, (
    Example("bring the plate, no, the bowl", "plate", ""),
    Example("put it on the shelf, sorry, I mean the desk", "shelf", ""),
    Example("give Ann the pen, or rather the pencil", "pen", ""),
    Example("switch on the lamp, no, the reading light", "lamp", ""),
    Example("bring me the sugar, no, not the sugar, the salt", "sugar", ""),
    Example("find Ola, actually find Tim", "Ola", ""),                    # the clause said again (words31)
    Example("switch on the fan, sorry, switch it off", "fan", ""),        # the verb's first word again (words34)
    Example("hand me the fork, or actually the spoon", "fork", ""),       # "or" before the marks (words36)
    Example("switch the fan off, no, the heater", "fan", ""),             # after a split particle (words36)
    Example("go to the kitchen and no wait, go to the office", "kitchen", ""),   # after "and" (issue #13)
    Example("take the cup but sorry, the mug", "cup", ""),
    Example("go to the kitchen and no wait go to the office", "kitchen", ""),   # no comma: two words of marks
    Example("open the door, no wait, close it", "door", ""),      # another verb after a denial (words47)
    Example("close the window, no, open it", "window", ""),       # "no" set off by commas (words49)
    Example("put the keys on the shelf, I mean on the hook", "shelf", ""),   # a place said again (words49)
    Example("take the towels to the bathroom, sorry, to the bedroom", "bathroom", ""),
), frozenset([","]) | _CORRECTION_JOINS, "', no, NP' after a phrase: the new phrase stands for the last one said")
CORRECTED_UNJOINED = Rule("a phrase corrected, no comma", _corrected_unjoined, (
    Example("bring me the plate no wait the bowl", "plate", ""),
    Example("open the door no sorry the window", "door", ""),
    Example("grab the salt actually no the pepper", "salt", ""),
    Example("put it in the sink sorry I mean the dishwasher", "sink", ""),
    Example("go to the hall no wait go to the porch", "hall", ""),
), first_words(CORRECTION_MARKS), "'V NP no wait NP': a correction said without a comma, of two words or more")
DENIED_AFTER = Rule("a phrase denied after the command", _denied_after, (
    Example("give me the big bowl, not the small one.", "small", ""),
    Example("bring the red mug, not the blue one, to the kitchen", "blue", ""),
), frozenset([","]), "', not NP' after the command: which thing is not meant, a remark")
