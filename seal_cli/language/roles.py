"""Which frame element each phrase of a clause fills, and how well it fits.

The roles a preposition may name are data (:data:`PREPOSITION_ROLES`, FrameNet's names): *to/into/
onto* → recipient (a person) or goal; *for* → recipient (a person); *from/out of/off* → source;
*with* → instrument; a locative (*in/on/at/near/under...*) → ground, goal, instrument or source. The
first the frame has and the clause has not filled yet is taken, after the rules of
:meth:`Roles.role_for` that say when a phrase fills none (it describes the noun before it).
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass
from typing import TYPE_CHECKING, Any

from seal_cli.frames.model import Frame
from seal_cli.language.element_types import Types
from seal_cli.language.english import LOCATIVE, PERSON_PRONOUNS
from seal_cli.language.lexicon import noun_lemma
from seal_cli.language.syntax import NP, PP, Clause

if TYPE_CHECKING:
    from seal_cli.language.grounding import Vocabulary
    from seal_cli.language.reference import Reference
    from seal_cli.language.values import Evoked

__all__ = ["ATTACHABLE", "FROM", "LOCATIVE", "PREPOSITION_ROLES", "PUT_IN", "ROLE_PREPOSITIONS", "TO", "Assignment",
           "Roles", "Sense"]


TO = ("to", "into", "onto")
FROM = ("from", "out of", "off")
ATTACHABLE = LOCATIVE + ("with", "without", "about", "for", "via", "of")
"""Prepositions whose phrase may describe the noun before it when it fills no element."""
ROLE_PREPOSITIONS = {"goal": "into", "source": "from", "recipient": "to", "instrument": "with", "ground": "in"}
"""The preposition that says each role, for a phrase said as a verb's object whose unit gives it that role
("fill *the glass* with water" is said as "... *into* the glass")."""
PUT_IN = ("in", "on", "inside", "into", "onto")
"""Prepositions that say a thing is put in or on another."""


_SAID_INDEFINITE = frozenset(["a", "an", "some", "any", "something", "anything", "everything", "nothing"])
"""First words of a telling's object that say what is said, not to whom ("say *something* about yourself")."""


@dataclass(frozen=True)
class Sense:
    """The roles a preposition's phrase may fill, in the order they are tried."""

    person: tuple[str, ...]          # when its noun phrase is a person
    thing: tuple[str, ...]           # otherwise


_WHERE = ("ground", "goal", "instrument", "source")
_POINTED = frozenset(["here", "there", "over here", "over there"])
"""Place words that point: after the person a frame moves (Guide), where they are led ("take him *there*")."""

PREPOSITION_ROLES: Mapping[str, Sense] = {
    **{p: Sense(("recipient", "goal"), ("goal",)) for p in TO},
    "for": Sense(("recipient",), ()),           # "follow them *for me*": for whom, never where (words46)
    **{p: Sense(("source",), ("source",)) for p in FROM},
    "with": Sense(("instrument",), ("instrument",)),
    **{p: Sense(_WHERE, _WHERE) for p in LOCATIVE},
    "toward": Sense(("goal", "ground"), ("goal", "ground")),     # "upstairs", "outside": where a motion goes
}
"""Preposition → the roles it may name (a preposition not listed names none)."""


Assignment = tuple[dict[str, Any], list[tuple[NP, PP]], float]
"""The elements a clause fills in a frame (role → phrase), the phrases that describe a noun
instead (noun, phrase), and how well the elements fit (:meth:`Roles.fit`)."""


class Roles:
    """Role choice for the clauses of one command (pronouns are asked of its :class:`Reference`)."""

    def __init__(self, types: Types, vocabulary: Vocabulary | None, reference: Reference,
                 frames: list[Evoked]) -> None:
        self.types = types
        self.vocabulary = vocabulary
        self.reference = reference
        self.frames = frames             # the frames built so far (shared with the builder)

    def assign(self, frame: Frame, clause: Clause, strict: bool) -> Assignment | None:
        """Fill the frame's elements from the clause; None when a realised role does not fit."""
        roles: dict[str, Any] = {}
        attached: list[tuple[NP, PP]] = []
        first = frame.elements[0].role if frame.elements else None
        have = self.types.roles(frame)
        objects = list(clause.objects)
        seek = first == "theme" and "ground" in have and self.searches(frame, str(clause.verb.info)) and \
            any(isinstance(x, PP) and x.prep == "for" for x in clause.items)
        if seek and objects:                 # "search the kitchen for a can opener": the kitchen is searched
            roles["ground"] = objects.pop(0)
        topic = self.topic(clause) if first == "message" and clause.message is None and (
            not objects or len(objects) == 1 and self.told_whom(objects[0]) and
            not any(isinstance(x, PP) and x.prep in TO for x in clause.items)) else None
        if clause.message is not None and first is not None:
            roles[first] = clause.message
            if objects and "recipient" in have:
                roles["recipient"] = objects.pop(0)
        elif topic is not None:
            roles["message"] = topic.np             # "tell robin *about the weather*": what is told is about it
            if len(objects) == 1 and "recipient" in have:
                roles["recipient"] = objects.pop(0)   # the one told, whatever kind of word names them
        elif len(objects) >= 2:
            if "recipient" in have:
                roles["recipient"] = objects.pop(0)
            elif objects[0].pronoun in PERSON_PRONOUNS:
                objects.pop(0)                   # "find me a thermometer": for whom, no element of the frame
            elif strict:
                return None
        if objects and first is not None and first not in roles:
            only = objects.pop(0)
            if ("recipient" in have and only.kind == "person"
                    and not self.types.is_person(frame.elements[0].type) and frame.elements[0].role != "goal"
                    and not any(isinstance(x, PP) and x.prep == "to" for x in clause.items)):
                roles["recipient"] = only            # "tell Robin", "give Maria": the person receives
            else:
                roles[first] = only
        if objects and strict:
            return None
        previous: NP | None = clause.objects[-1] if clause.objects else None
        has_to = any(isinstance(x, PP) and x.prep in TO for x in clause.items)
        items = clause.items
        for at, item in enumerate(items):
            if isinstance(item, NP):
                if strict:
                    return None
                previous = item
                continue
            if not isinstance(item, PP):
                continue
            if item is topic:
                previous = item.np
                continue
            if seek and item.prep == "for" and "theme" not in roles:
                roles["theme"] = item.np          # "... for a can opener", "look in the closet for my scarf"
                previous = item.np
                continue
            nxt = items[at + 1] if at + 1 < len(items) else None
            place_next = isinstance(nxt, PP) and nxt.prep in LOCATIVE and not nxt.describes
            role = None if item.describes else self.role_for(frame, item, previous, roles, has_to, place_next)
            before = items[at - 1] if at else None
            if role == "goal" and item.prep in LOCATIVE and isinstance(before, PP) and before.prep in FROM and \
                    roles.get("source") is before.np and (has_to or "recipient" in self.types.roles(frame)):
                role = None                       # "take the umbrella from the shelf *in the hall*": where it is
                #                                   (a frame ending at a place only: "put two knives from the
                #                                   table *in the drawer*", its goal; words49)
            if role == "source" and item.prep in LOCATIVE and ("goal" in roles or self.puts_only(frame)):
                role = None                       # "put the cup on the table *by the sink*": where the goal is;
                #                                   a frame that only puts a held thing down starts "from" a place
            if role == "source" and item.prep in LOCATIVE and \
                    any(isinstance(x, PP) and x.prep in FROM for x in items[at + 1:]):
                role = None                       # "the object *at the left of* the mug from the desk": "from" says
            if item.after_relative and "recipient" in roles and item.prep not in FROM:
                role = None                       # "bring me the book I left on the sofa": where it was left
                #                                   ("something to eat *from the kitchen*": where to take it from)
            if role is None and previous is None and first == "theme" and first not in roles and \
                    item.prep in ("on", "at") and not item.lead and not item.describes and \
                    not (self.frames and frame.needs_held()):
                role = first                      # "check on the baby": the verb's object after its preposition
            unsaid = roles.get("recipient")
            if item.prep == "for" and isinstance(unsaid, NP) and unsaid.start == unsaid.end and \
                    item.np.kind in ("person", "pronoun") and (item.np.kind == "person" or
                                                              item.np.pronoun in PERSON_PRONOUNS):
                roles["recipient"] = item.np      # "a glass of water *for grandma*, please": hers, not the unsaid
                previous = item.np                # "me" of a thing asked for without a verb (words24)
                continue
            if role is None and item.prep == "for" and item.np.pronoun in PERSON_PRONOUNS and not item.describes:
                continue                          # "chop the carrots *for me* with the knife": for whom, no element
            if role is not None:
                roles[role] = item.np
            elif previous is not None and (item.prep in ATTACHABLE or not strict or item.describes):
                attached.append((previous, item))
            elif strict:
                return None
            previous = item.np
        score = sum(self.fit(frame, role, np) for role, np in roles.items())
        return roles, attached, score

    def puts_only(self, frame: Frame) -> bool:
        """Whether the frame puts a thing it holds somewhere, to no one (Place): its source, where the thing was, is
        said with "from" only ("move the sugar *from* the pantry to the table"); a locative phrase is where it goes
        or describes a noun ("put a knife *in a blue container* onto the table": the container is moved too)."""
        return frame.needs_held() and "recipient" not in self.types.roles(frame)

    def told_whom(self, np: NP) -> bool:
        """Whether a telling's one object may be the one told, with what it is about said after it ("tell *robin*
        about the weather"): not an indefinite thing said ("say *something* about yourself", "tell *a joke* about
        cats": what is said)."""
        said = self.reference.text[np.start:np.end].lower().split()
        return bool(said) and said[0] not in _SAID_INDEFINITE and np.pronoun not in _SAID_INDEFINITE

    @staticmethod
    def topic(clause: Clause) -> PP | None:
        """The phrase a telling is about ("tell Sam *about the party*", "speak to the guests about dinner"): the
        first "about" phrase of the clause that describes no noun. It is the message when no object but the one told
        is said (words46: "tell robin in the kitchen about the weather" told "robin in the kitchen" to nobody); "tell
        them *something* about yourself", "say something about yourself to Jo" keep it on the thing said."""
        return next((x for x in clause.items if isinstance(x, PP) and x.prep == "about" and not x.describes), None)

    @staticmethod
    def searches(frame: Frame, unit: str) -> bool:
        """Whether the unit's object is the place searched: the frame also has the unit with "for"
        ("search" beside "search for", "look" beside "look for"), so "search X for Y" is "search for Y
        in X"."""
        wanted = unit + " for"
        return any(u.text == wanted for u in frame.lexical_units)

    def role_for(self, frame: Frame, pp: PP, previous: NP | None, roles: Mapping[str, Any],
                 has_to: bool = False, place_next: bool = False) -> str | None:
        """The element a prepositional phrase fills in this frame, or None (it describes a noun): the
        first role of :data:`PREPOSITION_ROLES` the frame has and the clause has not filled, after the
        rules below. ``place_next``: another locative phrase follows this one."""
        sense = PREPOSITION_ROLES.get(pp.prep)
        if sense is None:
            return None
        have = self.types.roles(frame)
        np = pp.np
        person = self.kind(np, frame, "recipient" if "recipient" in have else None) == "person"
        options = sense.person if person else sense.thing
        if pp.prep == "to" and not person and "goal" not in have and np.kind == "thing":
            options = ("recipient",)     # "give the newspaper to grandpa": Give has no goal, only someone
        elif pp.prep == "with":
            if previous is not None and previous.kind == "person" and previous.pronoun is None and not (
                    "instrument" in have and
                    self.types.is_a(self.class_or_head(np), frame.element("instrument").type) is True):
                return None              # "follow the woman *with the umbrella*": it describes her
        elif pp.prep in LOCATIVE:
            theme_type = frame.elements[0].type if frame.elements else None
            if pp.prep == "at" and np.kind == "place" and np.head is not None and np.head.tag == "HERE" and \
                    np.head.lower in _POINTED and "goal" in have and "goal" not in roles and not has_to and \
                    theme_type is not None and self.types.is_person(theme_type) and \
                    frame.elements[0].role != "goal":
                return "goal"            # "lead him *there*", "take the guest here": where the person is led
            person_before = previous is not None and (previous.kind == "person" or (
                frame.elements and roles.get(frame.elements[0].role) is previous
                and self.types.is_person(frame.elements[0].type)))
            if person_before and "ground" not in have:
                return None              # "bring it to Adel *in the bathroom*": where she is
            if person_before and pp.prep == "in" and np.pronoun is None and np.head is not None and \
                    self.types.is_a(noun_lemma(np.head_text.lower()), "clothing") is True:
                return None              # "greet the man *in the black jacket*": what he wears, not where he is
            if previous is not None and previous.kind == "person" and place_next and "ground" not in roles and \
                    previous.head is not None and previous.head.tag != "NAME" and \
                    (np.head_text not in self.types.taxonomy.known_classes or
                     self.types.is_a(noun_lemma(np.head_text.lower()), "clothing") is True):
                return None              # "greet the person *in the white jacket* in the bedroom": the last is where
            if previous is not None and previous.contents and np.pronoun in ("it", "them"):
                return None              # "a pan with a spoon in it"
            theme_type = frame.elements[0].type if frame.elements else None
            if not ((theme_type is None or not self.types.is_person(theme_type) or frame.elements[0].role == "goal")
                    and not has_to):
                options = tuple(r for r in options if r != "goal")   # a person is no goal; nor, beside "to", a place
            elif roles.get("recipient") is not None and "goal" in options:
                options = tuple(r for r in options if r != "goal")   # "bring me the cup *on the sofa*": where it is
        for role in options:
            if role in have and role not in roles:
                if role == "instrument" and pp.prep != "with" and not self.made_for(np, frame) and \
                        self.types.is_a(self.class_or_head(np), frame.element(role).type) is not True:
                    continue
                return role
        return None

    def made_for(self, np: NP, frame: Frame) -> bool:
        """Whether the noun names a thing made for doing the frame: its head is the agent noun of one of
        the frame's verbs and the library knows no class of it ("in the blanket *warmer*": warm, Heat)."""
        if np.head is None or np.kind != "thing" or "instrument" not in frame.roles or \
                self.types.is_a(self.class_or_head(np), frame.element("instrument").type) is not None:
            return False
        head = noun_lemma(np.head.text.split()[-1].lower())
        if not head.endswith("er") or len(head) < 5:
            return False
        stems = {head[:-2], head[:-1], head[:-3]}     # warmer, cooler: warm, cool; freezer: freeze; cutter: cut
        return any(u.text in stems for u in frame.lexical_units)

    def class_or_head(self, np: NP) -> str:
        """The class the phrase denotes in the vocabulary, else its head."""
        if self.vocabulary is not None:
            found = np.ground(self.vocabulary)
            if found:
                return found
        return np.head_text

    def kind(self, np: NP, frame: Frame | None, role: str | None) -> str:
        """The phrase's kind; a pronoun's is its antecedent's ("pronoun" when it has none)."""
        if np.kind != "pronoun":
            return np.kind
        antecedent = self.reference.antecedent(np, frame, role)
        if antecedent:
            return antecedent[2]
        if np.pronoun in ("them", "they") and frame is not None and role is not None:
            said = self.reference.mentioned(np, frame, role)     # "*the plants*, bring them inside": things
            if said is not None:
                return "person" if self.types.is_a(noun_lemma(said.head), "person") is True else "thing"
        return "pronoun"

    def fit(self, frame: Frame, role: str, np: NP) -> float:
        """How well a phrase fits an element: +2 a person where a person is wanted, +1 a class of
        the element's type, 0 unknown, -2 what cannot be (a thing where a person is wanted)."""
        type_ = frame.element(role).type
        kind = self.kind(np, frame, role)
        person_type = self.types.is_person(type_)
        if kind == "person":     # a person is somewhere too: "bring her to me" (Guide's goal)
            return 2.0 if person_type else 0.0 if self.types.is_open(type_) or self.types.is_location(type_) \
                else -2.0
        if kind == "pronoun":
            return 0.0
        if person_type:          # a noun nobody called a thing may receive ("give the newspaper to grandpa"),
            return 1.0 if role == "recipient" and kind == "thing" and \
                self.types.is_a(self.class_or_head(np), type_) is None else -2.0   # as any noun may be a place
        if kind in ("message", "place"):
            return 0.5
        found = self.types.is_a(self.class_or_head(np), type_)
        return 1.0 if found else -2.0 if found is False else 0.0
