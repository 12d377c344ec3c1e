"""What a pronoun, a bare "there" or an object left unsaid refers to: an element of a frame built
before (``refers_to``, as (frame index, element)).

* **Pronouns** ("it", "them", "him", "one", ...) refer to the latest element of an earlier frame that
  can be them (:meth:`Reference.antecedent`): a thing for "it", a person or a plural for "them",
  preferring one that fits the element's type; a pronoun no frame's element can be stands for what a
  statement or condition said before named (:meth:`Reference.mentioned`).
* **A bare "there"** refers to the place named last in an earlier clause (:meth:`Reference.place_before`).
* **"Back"** ("put it back") refers to the place a thing was taken from, said last in an earlier clause
  (:meth:`Reference.source_before`).
* **An object left unsaid** refers to the object of the frame before (:meth:`Reference.implicit`), or
  to the container it was just put in (:meth:`Reference.carried`).
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import replace

from seal_cli.frames.library import Library
from seal_cli.frames.model import Frame
from seal_cli.language.element_types import Types
from seal_cli.language.english import (
    BESIDE,
    FOUND_STATED,
    LOCATED,
    MODALS,
    NP_OPENERS,
    PREPOSITIONS,
    PRONOUNS,
    is_room_word,
)
from seal_cli.language.lexicon import Mention, Word, mentions, noun_lemma
from seal_cli.language.morphology import is_plural, parts_of_speech, plural_only
from seal_cli.language.syntax import NP
from seal_cli.language.values import Evoked, Phrase

__all__ = ["PLACES", "Reference", "back_unplaced"]


PLACES = ("goal", "ground", "source")
_GOAL_PREPOSITIONS = ("to", "into", "onto")
_PATH_STARTS = ("from",)
"""Prepositions of where a path a statement gives starts: where the one who moves is now ("get *from* the hall")."""
_POINTING = frozenset(["that", "this"])
"""Demonstratives that point at a person said before ("find *that* person")."""
"""Prepositions of where a motion ends: a place a statement names after one is where a bare "there" goes."""
"""The roles that say where (FrameNet's names)."""


def back_unplaced(phrase: Phrase) -> bool:
    """Whether a phrase is a bare "back" no source said before it places ("put the mug back"): where the
    thing goes is where it was, which only the world can say (the planner's, on a map)."""
    return phrase.refers_to is None and phrase.kind == "place" and phrase.head.lower() == "back"


_SPEAKERS = frozenset(["me", "us", "myself", "ourselves"])
"""The speaker said as an object: a pronoun of the third person ("them", "him") never stands for them."""


_WANTING = frozenset(["wants", "wanted", "would", "'d"])
"""What a subject that wishes says next ("grace *wants* a drink", "grandpa *would* like his tea"): a person."""


_GENDERED = {"him": "he", "he": "he", "his": "he", "himself": "he", "her": "she", "she": "she", "hers": "she",
             "herself": "she"}
"""The pronouns of the third person that say a gender: "him" never stands for one said as "her" before."""


def _unknown_plural(word: str) -> bool:
    """A word English's tables lack ending in a plural's "-s" (not "-ss"): a plural, as a brand's name of a food
    usually is ("the pringles are on the table, bring *them* to me", "the oreos", words28)."""
    return len(word) > 3 and word.isalpha() and word.endswith("s") and not word.endswith("ss") and \
        not parts_of_speech(word)


class Reference:
    """Reference in one command: asked of the frames built so far (a list the builder appends to)."""

    def __init__(self, text: str, library: Library, types: Types, words: Sequence[Word],
                 remarks: Sequence[tuple[int, int]], frames: list[Evoked]) -> None:
        self.text = text
        self.library = library
        self.types = types
        self.words = words
        self.remarks = remarks
        self.frames = frames
        self._mentions: list[Mention] | None = None

    def antecedent(self, np: NP, frame: Frame | None, role: str | None) -> tuple[int, str, str] | None:
        """(frame index, element, kind) of what a pronoun refers to: the latest element of an
        earlier frame that can be it (a person for "him", a thing for "it"), fitting the role."""
        wanted_person: bool | None = None
        if frame is not None and role is not None:
            type_ = frame.element(role).type
            wanted_person = True if self.types.is_person(type_) else None if self.types.is_open(type_) else \
                bool(self.types.is_a("person", type_))
        part = np.head is not None and " of " in np.head.lower     # "one of them": of the things, not their container
        carried = self.carried(frame, role) if np.pronoun in ("it", "them", "they", "both") and not part else None
        if carried is not None:
            return carried
        best: tuple[float, int, str, str] | None = None
        for index in range(len(self.frames) - 1, -1, -1):
            evoked = self.frames[index]
            for rank, (name, phrase) in enumerate(evoked.elements.items()):
                if phrase.default:
                    continue
                target = (index, name)
                if phrase.refers_to is not None:     # "put it in the fridge, take it out": the apple again
                    target = phrase.refers_to
                    if not (0 <= target[0] < len(self.frames)) or target[1] not in self.frames[target[0]].elements:
                        continue
                    phrase = self.frames[target[0]].elements[target[1]]
                kind = phrase.kind
                if kind in ("message", "place") or self.other_gender(np.pronoun, target):
                    continue
                if (phrase.text or "").lower() in _SPEAKERS and np.pronoun not in _SPEAKERS:
                    continue                         # "tell me if you find *them*": never the speaker (words25)
                guessed = False
                if kind == "thing" and np.pronoun in ("him", "her", "he", "she") and \
                        self.person_by_role(target, phrase) and not self.beside_person(target):
                    kind = "person"                  # "meet the plumber ... and take him": a person there
                    guessed = not self.types.is_person(     # "find the bellhop": a thing that may be a person
                        self.library.frame(self.frames[target[0]].frame).element(target[1]).type)
                if np.pronoun in ("it", "one", "this", "that") and kind == "person":
                    continue
                if np.pronoun in ("him", "her") and kind != "person":
                    continue
                if np.pronoun in ("them", "they", "ones") and kind != "person" and not phrase.plural \
                        and wanted_person is not False:
                    pass
                score = -(len(self.frames) - index) * 2 - rank * 0.5
                if guessed:              # "bring the book to *Raj* and tell him ...": one said as a person first
                    score -= 2
                if self.types.is_location(self.library.frame(evoked.frame).element(name).type):
                    score -= 1
                if wanted_person is True:
                    score += 3 if kind == "person" else -3
                elif wanted_person is False and kind == "person":
                    score -= 3
                if np.pronoun in ("them", "they") and (kind == "person" or phrase.plural):
                    score += 1
                if wanted_person is False and kind == "thing" and frame is not None and role is not None:
                    fits = self.types.is_a(phrase.cls or phrase.head, frame.element(role).type)
                    if fits is None and phrase.cls and phrase.head:     # a compound class read by its head:
                        fits = self.types.is_a(phrase.head, frame.element(role).type)   # a shoe cabinet opens
                    score += 3.0 if fits else -3.0 if fits is False else 0.0   # "close it": the fridge
                if frame is not None and role is not None and self.undoes(frame, role, evoked.frame, name):
                    score += 3.0       # "open the shed, grab the trowel, then close it": the shed opened
                if best is None or score > best[0]:
                    best = (score, target[0], target[1], kind)
        if best is not None and wanted_person is True and best[3] != "person" and frame is not None and \
                role is not None and np.pronoun in ("them", "they", "him", "her", "he", "she") and \
                self.mentioned(np, frame, role) is not None:
            return None             # "wait at the door until *the guest* arrives, then greet them": no door greeted
        return None if best is None else best[1:]

    def beside_person(self, target: tuple[int, str]) -> bool:
        """Whether another element of the target's frame is a person said: the thing beside a recipient is what is
        handed over ("give him *the keys* and then her the coat": the keys are no "her")."""
        return any(name != target[1] and phrase.kind == "person" and not phrase.default
                   for name, phrase in self.frames[target[0]].elements.items())

    def other_gender(self, pronoun: str | None, target: tuple[int, str]) -> bool:
        """Whether a gendered pronoun ("her") cannot be ``target``: it, or an element that refers to it, was said
        with a pronoun of the other gender ("give *him* the keys and then *her* the coat": two people)."""
        gender = _GENDERED.get(pronoun or "")
        if gender is None:
            return False
        said = [phrase for index, evoked in enumerate(self.frames) for name, phrase in evoked.elements.items()
                if (index, name) == target or phrase.refers_to == target]
        return any(_GENDERED.get((phrase.text or "").lower(), gender) != gender for phrase in said)

    def owner_before(self, np: NP) -> str | None:
        """The person "him"/"her" stands for when no element or statement names one: the latest name said as an
        owner before it ("go to *Tom's* room and tell him to get up", "take *Anna's* coat to her"; words29)."""
        if np.pronoun not in ("him", "her", "he", "she"):
            return None
        owners = [w.info for w in self.words if w.tag == "POSS" and w.end <= np.start and isinstance(w.info, str)
                  and w.info[:1].isupper() and " " not in w.info]
        return owners[-1] if owners else None

    def noun_for_one(self, np: NP) -> str | None:
        """The noun "one"/"ones" stands for in a phrase that describes it ("not the blue cup, bring me *the red
        one*", "the big spoon is dirty, bring me *a clean one*", "put the old batteries in the bin and bring me
        *new ones*", "move it from the black table to *the white one*"; with its noun left out, "from one shelf to
        *another*", "*another one*", "to *the other*", "to *the next*", alfred30): the head of the latest phrase said
        before it, a plural one for "ones", governed by a preposition as the phrase is or not (the thing moved for an
        object, where for a place: "take the cup to the sink and bring me a clean one" is a cup); None when no
        phrase was said before. One-anaphora
        repeats the noun, not the thing: the phrase names another of the same kind, so it refers to no element."""
        if np.head is None or np.pronoun is not None:
            return None
        first = self.text[np.start:np.end].split(None, 1)[0].lower()
        if np.head.lower in ("one", "ones"):
            if not np.mods and first != "another":    # "to *another one*": another of the kind (alfred30)
                return None
        elif np.head.lower not in ("another", "other", "next") or np.mods:
            return None                       # "from one shelf to *another*", "to *the other*", "*the next*" (alfred30)
        verbs = [w.start for w in self.words if w.tag == "VERB"]
        said = [m for m in mentions(self.text, 0, np.start) if not m.name and
                m.head.lower() not in ("one", "ones") and m.head.lower() not in PRONOUNS and
                not any(m.start <= v < m.end for v in verbs)]     # "open the other one": no noun "open"
        if np.head.lower == "ones":
            said = [m for m in said if is_plural(m.head.lower()) or plural_only(m.head.lower())]
        before = self.text[:np.start].split()
        oblique = bool(before) and before[-1].lower() in PREPOSITIONS     # "from the black table to *the white one*"
        said = [m for m in said if m.oblique == oblique] or said
        return noun_lemma(said[-1].head) if said else None

    def undoes(self, frame: Frame, role: str, earlier: str, name: str) -> bool:
        """Whether ``frame`` ends, on its element ``role``, a state the ``earlier`` frame gave its element
        ``name`` (Close's ``not open(theme)`` undoes Open's ``open(theme)``)."""
        ended = {p.predicate for p in frame.postconditions if p.negated and p.args == (role,)}
        return bool(ended) and any(not p.negated and p.args == (name,) and p.predicate in ended
                                   for p in self.library.frame(earlier).postconditions)

    def mentioned(self, np: NP, frame: Frame, role: str) -> Mention | None:
        """What a pronoun no frame's element can be stands for in a statement or condition said before it
        ("*My son Declan* arrives at six; meet him", "*When Ana* arrives, ...", "*The printer*'s jammed, fix
        it"): him/her the latest person named, it the latest thing (one of the element's type first), them/they the
        latest plural, or where a person is wanted the latest person ("when the guest arrives, greet *them*")."""
        self._mentions = self._said()
        pronoun = np.pronoun or ""
        if pronoun in ("them", "they"):              # "*The plants on the balcony*, bring them inside": a plural
            plural = [m for m in self._mentions if m.end <= np.start and m.determined and not m.oblique and
                      not m.name and (is_plural(m.head.lower()) or plural_only(m.head.lower()) or
                                      _unknown_plural(m.head.lower()))]
            if plural:
                return plural[-1]
            type_ = frame.element(role).type
            people = [m for m in self._mentions if m.end <= np.start and not m.oblique and
                      (m.name or self.types.is_a(noun_lemma(m.head), "person") is True)]
            subjects = [m for m in self._mentions if m.end <= np.start and not m.oblique]
            if not self.types.is_person(type_) and not (self.types.is_open(type_) and people and
                                                         people[-1] is subjects[-1]):
                return None                          # "when *the guest* arrives, greet them": one person, "they"
            return people[-1] if people else None    # "there's *a man* at the door, find them": "find" takes any
        if pronoun not in ("him", "her", "he", "she", "it", "this", "that", "one"):
            return None
        person = pronoun not in ("it", "this", "that", "one")   # "X wants a cola, bring him *one*" (words48): a thing
        said = [m for m in self._mentions if m.end <= np.start and
                (m.name or self.types.is_a(noun_lemma(m.head), "person") is True) == person]
        if person and not said and self.types.is_person(frame.element(role).type):
            said = [m for m in self._mentions if m.end <= np.start and not m.oblique and not m.name and
                    " " not in self.text[m.start:m.end].strip() and
                    self.types.is_a(noun_lemma(m.head), "person") is None and
                    (self.path_end_said(m) is not None or self.wanting_said(m))]
            # "lily has to get to the garage, lead her there": a word the taxonomy does not know, said bare as the
            # subject of a statement that has it go somewhere, is the one a person's frame leads (words25), and so
            # is the subject of "wants" ("grace wants a drink, bring her some water": a thing wants nothing, words27)
        if not person:
            type_ = frame.element(role).type
            fitting = [m for m in said if noun_lemma(m.head) == type_ or not self.types.is_open(type_)
                       and self.types.is_a(noun_lemma(m.head), type_) is True]
            said = fitting or [m for m in said if m.determined and not m.oblique] or [m for m in said if m.determined]
        return said[-1] if said else None

    def with_its_place(self, said: Mention) -> tuple[int, int]:
        """The span of a phrase a statement or condition named, with the place said right after it in the same
        phrase ("if *the light in the office* is on": "in" and the office), where that says which one; the
        phrase's own span when none follows."""
        following = next((m for m in self._said() if m.start >= said.end), None)
        between = self.text[said.end:following.start].split() if following is not None else []
        if following is None or not following.oblique or len(between) != 1 or between[0].lower() not in LOCATED:
            return said.start, said.end
        return said.start, following.end

    def pointed_person(self, np: NP) -> NP | None:
        """"Find *that person*", "follow this man": a demonstrative and a noun of people, said after a statement or
        clause that introduced a person, points at that person, as "him" or "them" would (what it stands for is
        found as a pronoun's is): the phrase as such a pronoun, to look up; None when it is no such phrase. A
        thing ("that cup") or a phrase with no demonstrative ("the person") is read as said."""
        if np.pronoun is not None or np.head is None or np.kind != "person" or np.head.tag != "WORD" or \
                np.conjuncts or np.possessor is not None:
            return None
        first = self.text[np.start:np.end].split()[0].lower()
        if first not in _POINTING or self.types.is_a(noun_lemma(np.head.lower), "person") is not True:
            return None
        return replace(np, pronoun="him", kind="pronoun")

    def _said(self) -> list[Mention]:
        """The phrases the statements and conditions of the command name, in order (read once)."""
        if self._mentions is None:
            spans = [*self.remarks, *((w.start, w.end) for w in self.words if w.tag == "COND")]
            self._mentions = sorted((m for a, b in spans for m in mentions(self.text, a, b)), key=lambda m: m.start)
        return self._mentions

    def place_stated(self, before: int) -> Mention | None:
        """Where a bare "there" points when no earlier clause names a place: a place the latest statement
        said before it names ("Sam wants to go *to the kitchen*, lead him there", "the guest needs to get to
        the bedroom — take her there", "the cups are in the sink, go there"). The last phrase said after a
        preposition of where a motion ends (``to``, ``into``, ``onto``) wins ("from the hall to *the garage*"),
        else the last after one of where a thing is (``LOCATED``, ``BESIDE``); never a person or clothing. A
        condition's place is not taken ("when Ana gets to the door"): no statement said it."""
        span = max(((a, b) for a, b in self.remarks if b <= before), default=None)
        if span is None:
            return None
        goal: Mention | None = None
        located: Mention | None = None
        for m in self._said():
            if not (span[0] <= m.start and m.end <= span[1]) or not m.oblique or \
                    self.types.is_a(noun_lemma(m.head), "clothing") is True or \
                    self.types.is_a(noun_lemma(m.head), "person") is True or m.name:
                continue
            prep = " ".join(self.text[span[0]:m.start].lower().split()[-3:])
            if any(prep == p or prep.endswith(f" {p}") for p in _GOAL_PREPOSITIONS):
                goal = m
            elif any(prep == p or prep.endswith(f" {p}") for p in (*LOCATED, *BESIDE)):
                located = m
        return goal or located

    def place_said(self, said: Mention, start: bool = False) -> Mention | None:
        """Where the statement that introduced ``said`` puts it ("*Paris* is in *the bathroom*", "there's a cup
        somewhere in *the kitchen*", "someone in a grey jacket is at *the bed*"): the first phrase after it, in
        the same statement, said after a preposition of where a thing is (``LOCATED``, ``BESIDE``) and naming no
        clothing (nor, "in" right after a person, anything but a room: "the person in the orange t-shirt"); None
        when a phrase that is no preposition's object comes first ("Ana has *the cup* in the kitchen") or none is
        said. Not a condition's ("when Ana gets to the door": where she will be, not where she is). With ``start``
        (the frame takes a ``source``) where a path the statement gives the person starts is where they are too
        ("Jules has to get *from the hall* to the garage, lead him there": words24)."""
        span = next(((a, b) for a, b in self.remarks if a <= said.start < b), None)
        if span is None or self._mentions is None:
            return None
        person = said.name or self.types.is_a(noun_lemma(said.head), "person") is True
        fronted = self._place_fronted(said, span)
        if fronted is not None:
            return fronted                           # "*on the desk* there are a few toys" (words42)
        for m in self._mentions:
            if m.start < said.end or m.start == said.start:
                continue
            if m.end > span[1] or not m.oblique:
                return None
            before = self.text[span[0]:m.start].lower().split()
            prep = " ".join(before[-3:])
            words = [w for w in self.text[m.start:m.end].lower().split() if w not in NP_OPENERS]
            if self.text[said.end:m.start].split() == ["in"] and person and not is_room_word(words):
                continue                             # "the person *in the orange t-shirt*": what they wear
            if any(prep == p or prep.endswith(f" {p}") for p in (*LOCATED, *BESIDE, *(_PATH_STARTS if start else ())))\
                    and self.types.is_a(noun_lemma(m.head), "clothing") is not True and \
                    self.types.is_a(noun_lemma(m.head), "person") is not True:
                return m
        return None

    def _place_fronted(self, said: Mention, span: tuple[int, int]) -> Mention | None:
        """The place said first in an existential statement, before "there is" and ``said`` ("*on the desk* there are
        a few toys", "in the kitchen there's a cup"): the phrase the statement opens with, after a preposition of
        where a thing is, when "there" and a form of "be" come between it and ``said``; None otherwise."""
        assert self._mentions is not None
        before = [m for m in self._mentions if span[0] <= m.start and m.end <= said.start]
        if not before or not before[-1].oblique:
            return None
        m = before[-1]
        words = self.text[m.start:m.end].split()
        if len(words) > 2 and words[-1].lower() == "there":     # the phrase read on into "there": cut before it
            end = m.start + self.text[m.start:m.end].rstrip().rfind(" ")
            m = replace(m, end=end, head=words[-2])
        opening = self.text[span[0]:m.start].lower().split()
        between = self.text[m.end:said.start].lower().replace("'s", " 's").split()
        if between[1:2] and between[1] in MODALS and between[2:3] == ["be"]:
            between = between[:1] + between[2:]              # "in the garage there *should be* a ladder" (words46)
        found = " ".join(between).replace(" 's", "'s") in FOUND_STATED     # "... *you'll find* some crisps" (words47)
        there_is = between[:1] == ["there"] and between[1:2] != [] and \
            between[1] in ("is", "are", "'s", "was", "were", "be")
        if not opening or " ".join(opening) not in (*LOCATED, *BESIDE) or not found and not there_is:
            return None
        return m

    def wanting_said(self, said: Mention) -> bool:
        """Whether a statement says that ``said`` wants something ("grace *wants* a drink", "rose *wanted* to go
        to bed"): only a person wants (a thing may need, "the trousers need washing", but wishes nothing)."""
        span = next(((a, b) for a, b in self.remarks if a <= said.start < b), None)
        after = self.text[said.end:span[1]].split()[:1] if span is not None else []
        return bool(after) and after[0].lower() in _WANTING

    def path_end_said(self, said: Mention) -> Mention | None:
        """Where the statement that introduced ``said`` has them go ("Jules has to get from the bookshelf *to the
        trash bin*", "Sam wants to go *to the kitchen*"): the last phrase after it, in the same statement, said
        after a preposition of where a motion ends (``to``, ``into``, ``onto``), no person or clothing (words24).
        None when there is none, or the statement is no statement (a condition's "when Ana gets to the door" says
        where she will be, not where she is to be led)."""
        span = next(((a, b) for a, b in self.remarks if a <= said.start < b), None)
        if span is None or self._mentions is None:
            return None
        end: Mention | None = None
        for m in self._mentions:
            if m.start < said.end or m.end > span[1] or not m.oblique or m.name or \
                    self.types.is_a(noun_lemma(m.head), "clothing") is True or \
                    self.types.is_a(noun_lemma(m.head), "person") is True:
                continue
            prep = " ".join(self.text[span[0]:m.start].lower().split()[-3:])
            if any(prep == p or prep.endswith(f" {p}") for p in _GOAL_PREPOSITIONS):
                end = m
        return end

    def person_by_role(self, target: tuple[int, str], phrase: Phrase) -> bool:
        """Whether a noun the library does not know as a person is one by the element it fills: an
        element typed person ("meet *the plumber*", Meet's theme), unless its class is known to be no
        person; or a noun the taxonomy does not know at all that fills the first element, one a person may
        fill ("find *the bellhop*": Find's theme is any thing; not "in the kitchen", where it is). A room's name
        (``english.ROOM_WORDS``) is no person, whatever element it fills ("go to *the corridor* and look for him")."""
        evoked = self.library.frame(self.frames[target[0]].frame)
        type_ = evoked.element(target[1]).type
        known = self.types.is_a(phrase.cls or phrase.head, "person")
        if known is None and is_room_word(phrase.head.lower().replace("_", " ").split()):
            known = False                             # "go to the corridor and look for him": no room is him (words28)
        if known is None and phrase.head.lower() not in PRONOUNS and target[1] == evoked.elements[0].role and \
                self.types.is_a("person", type_) is True:
            return True                               # "find the bellhop and tell him ...": one that may be a person
        return self.types.is_person(type_) and known is not False

    def carried(self, frame: Frame | None, role: str | None) -> tuple[int, str, str] | None:
        """After "put the pen in a cup", the object of "and move it (them) to the desk" is the cup
        with the pen in it: moving the pen again would undo what was just done. (Only when both
        frames put their first element somewhere, and the place was a container.)"""
        if frame is None or not self.frames or role != (frame.elements[0].role if frame.elements else None):
            return None
        if self.types.relation(frame) is None:
            return None
        last = self.frames[-1]
        relation = self.types.relation(self.library.frame(last.frame))
        if relation is None or relation.args[1] not in last.elements:
            return None
        goal = last.elements[relation.args[1]]
        if goal.default or goal.kind != "thing" or goal.refers_to is not None and \
                self.types.object_role(last.lexical_unit) != relation.args[1] or \
                self.types.is_a(goal.cls or goal.head, "container") is not True:
            return None
        return len(self.frames) - 1, relation.args[1], "thing"
    def implicit(self, frame: Frame, role: str) -> Phrase | None:
        """An object left unsaid refers to the object of the frame before ("and put [it] away"),
        or to the container it was just put in (:meth:`carried`); never to a place nothing carries (a room, a
        thing the taxonomy knows as ``fixed``: "go to *the shower*, meet Hayden and take him"), but to the one
        before it ("pick up the cup, go to *the kitchen* and put [it] on the table")."""
        carried = self.carried(frame, role)
        if carried is not None:
            index, name, _ = carried
            root = self.frames[index].elements[name]
            return Phrase("", root.head, root.cls, root.kind, (index, name), root.quantity, root.plural)
        for index in range(len(self.frames) - 1, -1, -1):
            evoked = self.frames[index]
            if not evoked.elements:
                continue
            name, phrase = next(iter(evoked.elements.items()))
            if phrase.kind != "thing" or phrase.default:
                continue
            target = phrase.refers_to or (index, name)
            root = self.frames[target[0]].elements[target[1]]
            if self.types.is_a(root.cls or root.head, "fixed") is True or \
                    is_room_word((root.cls or root.head).lower().replace("_", " ").split()):
                continue        # "go to the shower, meet Hayden and take him": no shower in hand (words28)
            return Phrase("", root.head, root.cls, root.kind, target, root.quantity, root.plural)
        return None

    def place_before(self, before: int) -> tuple[int, str] | None:
        """The place named last in an earlier clause (a goal, ground or source said, not a default, and no
        person; through a "there" or pronoun that stood for one), as (frame index, element); None. A thing a
        clause opened (its frame's actions open it) is a place too: "open the wardrobe and put the coat in
        *there*" (in the wardrobe)."""
        best: tuple[int, tuple[int, str]] | None = None
        for index in range(before):
            opened = {arg for action in self.library.frame(self.frames[index].frame).actions
                      if action.name == "open" for arg in action.args}
            for role, phrase in self.frames[index].elements.items():
                if phrase.default or phrase.span is None or role not in PLACES and role not in opened:
                    continue
                target = phrase.refers_to or (index, role)
                if self.frames[target[0]].elements[target[1]].kind != "thing":
                    continue                                  # a person, "here": no place named
                if best is None or phrase.span[0] >= best[0]:
                    best = (phrase.span[0], target)
        return None if best is None else best[1]

    def source_before(self, before: int) -> tuple[int, str] | None:
        """Where "back" is: the source said last in an earlier clause ("take the cup *from the table* and put
        it back"; not a default, no person), as (frame index, element); None when no clause says one."""
        for index in range(before - 1, -1, -1):
            phrase = self.frames[index].elements.get("source")
            if phrase is None or phrase.default or phrase.span is None:
                continue
            target = phrase.refers_to or (index, "source")
            if self.frames[target[0]].elements[target[1]].kind == "thing":
                return target
        return None
