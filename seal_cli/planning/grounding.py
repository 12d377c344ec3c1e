"""Map grounding: which room, place or person of a map a phrase of a command names.

The words of a command name things of the map as people say them, not as the map file spells
them. A map thing is called by (lemmatised words, articles and possessives dropped):

- a **room** by its name ("living_room": "the living room", "the living_room" as written);
- a **place** by its name without its number ("dining_table_1": "the dining table"), by its name
  with the number ("sofa 2"), by its class and the class's other names in the library's synonyms
  ("sofa": "the couch", "the settee"), and, less surely, by the last word of its name or class
  ("the table" for a dining table, not for a nightstand that is also a "night table") or by the
  first words of a compound name ("the tv" for a tv stand: what the stand is for stands on it);
- a **person** by their name ("Roger"), or by a role the map gives them ("the nurse": the map's
  ``role: nurse``; :meth:`MapNames.with_role`); the **speaker** by "me", "I", "us"
  (:data:`SPEAKER`), and by the speaker's roles ("the doctor" on the clinic).

A phrase is split at its first relational word ("the couch *in* the living room"): the words
before it are the thing, the words after it say where it is. Among the things its words call
best, a phrase names, in turn:

1. the ones where it says they are: in that room, or in the room of that place (none there is
   refused: "the table in the kitchen" when the kitchen has none);
2. the ones the frame element can take (an ``openable`` element wants a place that opens; a
   ``heater`` a place that heats, by the library's categories);
3. of several places of one class nothing said tells apart (four beds), the nearest the robot drives to from
   where it starts, said as a warning with the others and why (:meth:`MapNames._one_of`; "on my desk": the one
   nearest the speaker); else the first in the map's order (the map lists the usual one first: "the table" is
   the dining table before the coffee table).

A phrase whose words name no thing of the map is not grounded here (it is an object the robot
must find, or a word of no class); but a room word ("garage", anything called a "room") or a
fixed thing (the library's ``fixed`` category: furniture, appliances) that the map lacks is
refused before anything moves, listing what the map has (:class:`Refusal`).
"""

from __future__ import annotations

import math
import re
from collections.abc import Iterable, Mapping, Sequence
from dataclasses import dataclass
from functools import cached_property

from seal_cli.errors import SealError
from seal_cli.frames.taxonomy import Taxonomy, class_key, class_words
from seal_cli.language.english import NUMBERS, ROOM_WORDS, SOME_PERSON, VAGUE_NUMBERS, is_room_word
from seal_cli.language.lexicon import noun_lemma
from seal_cli.language.morphology import is_adjective
from seal_cli.maps.model import SPEAKER, Map
from seal_cli.maps.prepositions import located

__all__ = ["FIXED", "HERE", "PAIRED", "ROOM_WORDS", "SPEAKER_WORDS", "MapNames", "Referent", "Refusal", "kind_of",
           "spoken"]

OBJECT = "object"
"""The library category of what the robot handles (the theme of Pick, Bring, Place)."""

FIXED = "fixed"
"""The library category of what never moves: furniture, appliances, fixtures and rooms."""


PAIRED = frozenset({"glove", "mitten", "sock", "shoe", "boot", "slipper", "sandal", "sneaker", "trainer", "earring",
                    "chopstick", "skate", "ski", "earbud", "earphone", "headphone", "glass", "spectacle", "goggle",
                    "scissor", "scissors", "pliers", "tong", "tongs", "trouser", "pant", "jean", "short"})
"""English nouns of things that come in pairs (general knowledge, not any corpus): "the gloves", "a pair of
gloves", "my glasses" is one pair, one thing on a map; "two gloves" says a number of its own."""

SPEAKER_WORDS = frozenset({"me", "i", "us", "myself", "ourselves", "we"})
"""Who the speaker is called in a command."""

HERE = frozenset({"here", "over here"})
"""Where the speaker is ("come here", "bring the cup here"): a robot told "here" goes to the speaker."""

RELATIONS = ("next to", "close to", "in front of", "on top of", "in", "on", "at", "inside", "near", "by",
             "beside", "under", "behind", "within", "from", "of")
"""Words after which a phrase says where its thing is ("the couch in the living room")."""

DESCRIBING = frozenset({"other", "same", "next", "last", "bottom", "far", "near", "middle"})
"""English words before a thing's name that pick one of its kind ("the *other* table"), not a kind."""

DROPPED = frozenset({"the", "a", "an", "my", "our", "your", "his", "her", "their", "this", "that", "these",
                     "those", "some", "any", "all", "every", "each", "both"})


WHERE_TYPES = frozenset({"location", "place", "room"})
"""The element types that say where to be (Go's goal, Find's ground), not what to act on."""


class Refusal(SealError):
    """A command that names a room or a fixed thing the map does not have."""


def spoken(text: str) -> str:
    """A command with a map's own spellings said as words ("the family_room": "the family room");
    one character for one, so spans into the text stay right."""
    return re.sub(r"(?<=[A-Za-z])_(?=[A-Za-z0-9])", " ", text)


_FLOATING_EACH = re.compile(r"(?<=[A-Za-z])(\s+)each(?=\s*(?:$|[,.;:!?]|\b(?:and|then|please)\b))", re.IGNORECASE)


def without_floating_each(text: str) -> str:
    """A command without "each" said after its object ("give Edith and Walter a biscuit *each*": one biscuit to
    each, e2e23; "bring the children an apple each"), which the parser read as a determiner with no noun and
    refused: the conjoined people already get one each. "each" after a preposition is its pronoun ("put a spoon
    in each") and stays. Blanked, one space for one character, so spans into the text stay right."""
    from seal_cli.language.english import PREPOSITIONS

    def blank(match: re.Match[str]) -> str:
        before = text[:match.start()].split()
        if before and before[-1].lower() in PREPOSITIONS:
            return match.group(0)
        return " " * len(match.group(0))

    return _FLOATING_EACH.sub(blank, text)


def words_of(text: str) -> tuple[str, ...]:
    """The lemmatised words of a phrase, without articles and possessives."""
    tokens = re.findall(r"[^\W_]+", text.lower().replace("_", " "))
    return tuple(noun_lemma(t) for t in tokens if t not in DROPPED)


@dataclass(frozen=True)
class Referent:
    """A thing of the map a phrase may name: ``kind`` is room, place or person."""

    id: str
    kind: str
    cls: str
    room: str | None
    names: tuple[tuple[str, ...], ...]
    """The word sequences that call it surely, best first."""
    heads: frozenset[str]
    """The single words that call it less surely (the last word of a name)."""
    own: int = 0
    """How many of ``names`` are its own (its name and class); the rest are its class's synonyms,
    which call it less surely than another thing's own name ("the washbasin": washbasin_1, not the
    sink, whose synonym it is)."""


def _split(words: tuple[str, ...]) -> tuple[tuple[str, ...], tuple[str, ...]]:
    """The thing's words and the words that say where it is, at the first relational word."""
    for i in range(1, len(words)):
        for relation in RELATIONS:
            rel = tuple(relation.split())
            if words[i:i + len(rel)] == rel:
                return words[:i], words[i + len(rel):]
    return words, ()


def where_words(text: str) -> tuple[str, ...]:
    """The words of a phrase that say where its thing is ("the cup in the bedroom": ``("bedroom",)``)."""
    return _split(words_of(text))[1]


def _said_in_plural(text: str, size: int) -> bool:
    """Whether the last of the first ``size`` words of a phrase (its thing's, :func:`words_of` without the lemmas)
    is said in the plural ("the *guests* in the lounge")."""
    tokens = [t for t in re.findall(r"[^\W_]+", text.lower().replace("_", " ")) if t not in DROPPED]
    if not 0 < size <= len(tokens):
        return False
    last = tokens[size - 1]
    return noun_lemma(last) != last


class MapNames:
    """The rooms, places and people of a map, by the words that call them (see the module docstring)."""

    def __init__(self, map: Map, taxonomy: Taxonomy) -> None:
        self.map = map
        self.taxonomy = taxonomy
        self.chosen: dict[str, str] = {}
        """Each place chosen among several a phrase did not tell apart, by id: which they were and why this one."""
        self.nearest_of: dict[str, tuple[str, ...]] = {}
        """Each place of :attr:`chosen` chosen as the nearest by drive from where the robot will be, by id: the places
        it was chosen among (``seal run`` chooses again from where it takes the thing, :meth:`_nearest`)."""
        self._house = map.name.replace("_", " ")
        """The map's name as words, in messages ("the office floor has no kitchen")."""
        self.room_said: str | None = None
        """The room an earlier frame of the command named last ("go to the bedroom and put it on the bed"): of
        several places, the ones in it are meant."""
        self.carried: str | None = None
        """The class of the thing the frame being grounded carries to the place its words name ("put the book on the
        shelf"), or None: of the places the words may call, one the map's priors keep such a thing on
        (:meth:`_kept_there`)."""
        self.guessed = False
        """Whether :attr:`robot_at` is a guess: where the map's prior says the thing carried most likely lies (``seal
        run`` plans on the map without its objects); the nearest place from there is chosen for now, and the run
        chooses again from where it finds the thing (:attr:`~seal_cli.planning.problem.Problem.nearest`)."""
        self.robot_at: tuple[tuple[float, float], str] | None = None
        """Where the robot will be when it sets off for the phrase being grounded, and how to say it ("where it takes
        the guitar"); None: where it starts. Of several places, the nearest is measured from there."""

    @cached_property
    def referents(self) -> tuple[Referent, ...]:
        synonyms = self.taxonomy.names
        found: list[Referent] = []
        for room in self.map.rooms:        # a room by its name, then its kind's other names ("the lounge")
            said = (words_of(room.name), *map(words_of, synonyms.get(class_key(room.name), ())))
            found.append(Referent(class_key(room.name), "room", class_key(room.name), class_key(room.name),
                                  tuple(dict.fromkeys(w for w in said if w)), frozenset(), 1))
        for place in self.map.places:
            base = re.sub(r"[_ ]?\d+$", "", place.name)
            number = place.name[len(base):].strip("_ ")
            # its number said as a word too: "table two" is table_2, as "table 2" is
            spoken_number = [f"{base} {w}" for w, n in NUMBERS.items() if number.isdigit() and n == int(number)
                             and (w == "one" or w not in VAGUE_NUMBERS) and " " not in w]     # "table one" too
            spelled = [base, place.name, *spoken_number, place.cls, *synonyms.get(place.cls, ())]
            mine = 3 + len(spoken_number)
            names = tuple(dict.fromkeys(w for w in map(words_of, spelled) if w))
            own = len(dict.fromkeys(w for w in map(words_of, spelled[:mine]) if w))
            closed = {"".join(n) for n in map(words_of, spelled[:mine]) if n}
            heads = frozenset(n[-1] for n in map(words_of, spelled) if n and (     # not a synonym's: a "tv table";
                n in names[:own] or "".join(n) in closed)     # but "arm chair" is "armchair" spelt apart: a chair
                and not (n[-1].isdigit() or n[-1] in NUMBERS))  # a number alone calls no place: "table 2" (or
            #         "table two") on a map with sofa_2 and no table_2 is not the sofa (lead, stop 42: it was)
            found.append(Referent(class_key(place.name), "place", place.cls,
                                  class_key(place.room) if place.room else None, names, heads, own))
        for person in self.map.people:
            room_name = person.room or self.map._room_name(self.map.person_at(person))
            found.append(Referent(person.key, "person", "person", class_key(room_name) if room_name else None,
                                  (words_of(person.name),), frozenset()))
        return tuple(found)

    def _also_in(self, referent: Referent, room: str) -> bool:
        """Whether a place of the map stands in ``room`` too, not only in the room it is said to be in: where areas
        drawn without walls overlap (a map warned of), a sofa in both is "the sofa in" either (hostile25)."""
        place = self.map.place(referent.id) if referent.kind == "place" else None
        return place is not None and any(class_key(name) == room for name in self.map.rooms_at(place.at))

    def with_role(self, text: str) -> tuple[str, ...]:
        """Who a phrase calls by a role of the map ("the nurse", "the head nurse", "the cook in the
        kitchen"): the ids of the people (and :data:`SPEAKER`) whose role its thing's last words are,
        in the map's order; empty when it names no role of the map. Where the phrase says they are
        narrows them; nobody there is refused. Several left is refused too, naming them: a robot
        must not guess whom a thing is for; the role said in the plural ("tell the guests that ...") calls them
        all (e2e33)."""
        thing, where = _split(words_of(text))
        said = ["_".join(thing[k:]) for k in range(len(thing))]
        role = next((r for r in said if r in self.map.roles), None)
        if role is None:
            return ()
        found = self.map.with_role(role)
        what = role.replace("_", " ")
        if where and (room := self._room_of_words(where)) is not None:
            inside = tuple(p for p in found if self._room_of_person(p) == room)
            if not inside:
                raise Refusal(f"the {self._house} has no {what} {located(room, self.map)}; it has "
                              f"{self._who(found)}")
            found = inside
        if len(found) > 1 and not _said_in_plural(text, len(thing)):
            raise Refusal(f"'the {' '.join(thing)}' could be {self._who(found, ' or ')}: the {self._house} has "
                          f"{len(found)} people with the role {what}; say which one by name")
        return found

    def _room_of_person(self, id_: str) -> str | None:
        if id_ == SPEAKER:
            room = self.map._room_name(self.map.speaker_at)
        else:
            person = self.map.person(id_)
            room = None if person is None else person.room or self.map._room_name(self.map.person_at(person))
        return class_key(room) if room else None

    def _who(self, ids: Sequence[str], joint: str = ", ") -> str:
        """People as the refusals list things: ``nora (treatment_room)``, the speaker as ``me``."""
        return joint.join(f"{i} ({self._room_of_person(i) or 'in no room'})" for i in ids)

    def by_id(self, id_: str) -> Referent | None:
        return next((r for r in self.referents if r.id == class_key(id_)), None)

    @staticmethod
    def _score(referent: Referent, words: tuple[str, ...], prefix: bool = True) -> int:
        """How surely the words call the referent: twice (2 + the length of a name they end with),
        and 1 more for its own name than for a synonym's; 1 for a head word alone (or, with ``prefix``,
        the first words of a compound name); 0 for nothing."""
        best = 0
        for k, name in enumerate(referent.names):
            said = len(name) <= len(words) and words[len(words) - len(name):] == name
            joined = len(name) > 1 and words[-1:] == ("".join(name),)       # "washbasin": wash basin, one word
            if said or joined:
                best = max(best, 2 * (2 + (len(name) if said else 1)) + (k < referent.own or not referent.own))
        if not best and words and words[-1] in referent.heads:
            best = 1
        if not best and prefix and words and any(len(name) > len(words) and name[:len(words)] == words
                                      for name in referent.names[:3]):
            best = 1            # "the tv": the tv stand (what a compound name is for stands on it)
        return best

    def candidates(self, words: tuple[str, ...], kinds: Iterable[str] = ("room", "place", "person"),
                   prefix: bool = True) -> list[Referent]:
        """The referents the words call best, in the map's order (``prefix``: see :meth:`_score`)."""
        kinds = set(kinds)
        scored = [(0 if self._another_compound(r, words) else self._score(r, words, prefix), r)
                  for r in self.referents if r.kind in kinds]
        top = max((s for s, _ in scored), default=0)
        if top == 0:
            return self._of_general_noun(words, kinds)
        return [r for s, r in scored if s == top and s > 0]

    def _of_general_noun(self, words: tuple[str, ...], kinds: Iterable[str]) -> list[Referent]:
        """The places a general noun of their kinds calls when no name, class or synonym does: a word that is both
        a kind of thing and the library's category of its kinds ("light": a desk lamp, a floor lamp, a light
        switch), said alone ("turn off the light in the office": the office's desk lamp; "the ceiling light" is
        not this). A category that is no kind of thing itself ("furniture", "heater") calls nothing."""
        if len(words) != 1 or "place" not in set(kinds):
            return []
        category = self.taxonomy.by_name.get(class_key(words[0]))
        if category is None or not category.members or category.name not in category.members:
            return []
        return [r for r in self.referents if r.kind == "place" and self.taxonomy.is_a(r.cls, category.name) is True]

    @cached_property
    def _describing(self) -> frozenset[str]:
        """Words that say which of the map's things, not what kind: the words of its rooms' and places'
        names, classes and synonyms, and of English room names."""
        said = {w for r in self.referents for name in r.names for w in name}
        return frozenset(said | {w for room in ROOM_WORDS for w in room.split("_")} | DESCRIBING)

    def _another_compound(self, referent: Referent, words: tuple[str, ...]) -> bool:
        """Whether the words name a compound of another kind that shares the place's head: a noun
        before it that is no adjective and no word of the map ("the *hand* dryer" is no tumble dryer,
        while "the kitchen sink", "the red chair" and "the other table" are the map's)."""
        if referent.kind != "place" or len(words) < 2:
            return False
        ends = [len(n) for n in referent.names if len(n) <= len(words) and words[len(words) - len(n):] == n]
        left = words[:len(words) - max(ends, default=1)]
        if not left or (not ends and words[-1] not in referent.heads):
            return False
        word = left[-1]
        return not (is_adjective(word) or word in self._describing or word.isdigit() or word in NUMBERS)

    def ground(self, text: str, element_type: str, kinds: Iterable[str] = ("room", "place", "person")
               ) -> Referent | None:
        """The map thing a phrase names, for an element of this type; None if it names none."""
        words = words_of(text)
        if not words:
            return None
        thing, where = _split(words)
        # the first words of a compound name call it only where to go ("go to the tv": the tv stand);
        # a thing is named by its head ("a coffee" is no coffee machine, "turn off the tv" no tv stand)
        found = self._kept_there(thing, self.candidates(thing, kinds, prefix=element_type in WHERE_TYPES))
        if not found:
            return None
        if where and (room := self._room_of_words(where)) is not None:
            inside = [r for r in found if r.room == room or r.id == room or self._also_in(r, room)]
            if not inside:
                what, there = " ".join(thing), located(room, self.map)
                others = ", ".join(f"{r.id} ({r.room or 'in no room'})" for r in found)
                raise Refusal(f"the {self._house} has no {what} {there}; it has {others}")
            found = inside
        typed = [r for r in found if r.kind != "place" or kind_of(self.taxonomy, r.cls, element_type) is not False
                 or (element_type == "openable" and self._openable(r.id))]
        if element_type == "openable":
            typed = [r for r in typed if r.kind == "place" and self._openable(r.id)] or typed
        return self._one_of(text, typed or found)

    def _kept_there(self, words: tuple[str, ...], found: list[Referent]) -> list[Referent]:
        """The places a word calls, weighed by what is carried there (:attr:`carried`): when none of the places it
        names best is one the map's priors keep the thing on, but a place it names less surely is — a compound
        whose last part it is ("the shelf" for a bookshelf), or a kind of it by the library's categories — the
        places of the highest prior mass among those ("put the book back on the shelf" in a library with a
        storeroom shelf and three bookshelves: a bookshelf; the storeroom's shelf keeps boxes). The words' own
        best places stand when the priors keep the thing on any of them, or keep no such thing at all."""
        if self.carried is None or not words or any(r.kind != "place" for r in found):
            return found
        from seal_cli.maps.priors import prior_of

        prior = prior_of(self.map.priors, self.carried)

        def mass(r: Referent) -> float:
            return prior.get(r.id, 0.0) + prior.get(class_key(r.cls), 0.0)

        if not prior or any(mass(r) > 0 for r in found):
            return found
        loose = [r for r in self.referents if r.kind == "place" and r not in found and mass(r) > 0
                 and self._a_kind_of(r, words[-1])]
        best = max((mass(r) for r in loose), default=0.0)
        return [r for r in loose if mass(r) == best] or found

    def _a_kind_of(self, referent: Referent, word: str) -> bool:
        """Whether a place is a kind of what a word names: its name or class is one word ending in it ("bookshelf",
        "shelf"; a word of four letters or more), or the library's categories put its class under the word's."""
        if len(word) >= 4 and any(len(n) == 1 and n[0] != word and n[0].endswith(word) for n in referent.names):
            return True
        return class_key(referent.cls) != class_key(word) and self.taxonomy.is_a(referent.cls, class_key(word)) is True

    def _one_of(self, text: str, found: list[Referent]) -> Referent:
        """The one of several referents a phrase calls: the one nearest the speaker when the phrase says it is
        theirs and several places fit ("is there a stapler on my desk?": the desk the speaker stands by); else,
        of several places of one class nothing said tells apart, the nearest the robot drives to from where it will
        be (:attr:`robot_at`: "put the guitar on the bed" with four beds, from where it takes the guitar), the choice
        and its reason kept in :attr:`chosen`;
        else (places of several classes: "the table" for a dining table and a coffee table) the first in the map's
        order, which lists the usual one first."""
        places = [r for r in found if r.kind == "place" and self.map.place(r.id) is not None]
        if len(places) < 2 or len(places) < len(found):
            return found[0]
        if re.match(r"\s*(my|our)\b", text, flags=re.IGNORECASE) is not None:
            here = self.map.speaker_at
            return min(places, key=lambda r: math.dist(self.map.place(r.id).at, here))  # type: ignore[union-attr]
        if len({r.cls for r in places}) > 1:
            return found[0]             # "the table": a dining table before a coffee table, as the map lists them
        return self._nearest(text, places)

    def _nearest(self, text: str, places: list[Referent]) -> Referent:
        from seal_cli.maps.reach import drive_lengths

        listed = [f"{r.id} ({r.room or 'in no room'})" for r in places]
        said = f"'{' '.join(text.split())}' could be {', '.join(listed[:-1])} or {listed[-1]}: chose"
        inside = [r for r in places if self.room_said is not None and r.room == self.room_said]
        if len(inside) == 1:
            self.chosen.setdefault(inside[0].id, f"{said} {inside[0].id}, the one "
                                   f"{located(inside[0].room or '', self.map)}, the room said before it")
            return inside[0]
        among = inside or places
        start, there = self.robot_at or (self.map.robot.xy, "where it starts")
        lengths = drive_lengths(self.map, start, [r.id for r in among])
        best = min(range(len(among)), key=lambda k: (lengths[k], k))
        one = among[best]
        which = f" of those {located(one.room or '', self.map)} (the room said before it)," if inside else ""
        if math.isinf(lengths[best]):       # a house split in islands: no path to any ("inf m" said before)
            said = said.removesuffix(": chose")
            self.chosen.setdefault(one.id, f"{said}: the robot can reach none of them from {there}; chose "
                                   f"{one.id},{which} the first the map lists; say its room or its number "
                                   f"('{one.id}') to choose")
            return one
        again = " for now" if self.guessed else ""
        then = "; it chooses again from where it finds one (seal plan chooses from where the map draws it)" \
            if self.guessed else ""
        self.chosen.setdefault(one.id, f"{said} {one.id}{again},{which} the nearest the robot drives to from {there} "
                               f"({lengths[best]:.1f} m){then}; say its room or its number ('{one.id}') to choose")
        self.nearest_of.setdefault(one.id, tuple(r.id for r in among))
        return one

    def _room_of_words(self, words: tuple[str, ...]) -> str | None:
        thing, _ = _split(words)
        found = self.candidates(thing, ("room", "place"))
        if not found:
            return None
        return found[0].id if found[0].kind == "room" else found[0].room

    def _openable(self, id_: str) -> bool:
        place = self.map.place(id_)
        return place is not None and place.openable

    def is_room_word(self, text: str) -> bool:
        """Whether a phrase calls something a room ("the garage", "the games room")."""
        thing, _ = _split(words_of(text))
        if not thing:
            return False
        return is_room_word(thing)

    def is_fixed_word(self, text: str, cls: str | None) -> bool:
        """Whether a phrase calls something that never moves (furniture, an appliance)."""
        thing, _ = _split(words_of(text))
        names = [cls] if cls else []
        if thing:
            names += ["_".join(thing), thing[-1]]
        return any(kind_of(self.taxonomy, n, FIXED) is True for n in names if n)

    def refusal(self, text: str, cls: str | None) -> Refusal | None:
        """Why a phrase cannot be grounded on this map, when it names a room or fixed thing the map
        lacks; None when it may be an object to search for."""
        what = " ".join(_split(words_of(text))[0]) or text
        if self.is_room_word(text):
            rooms = ", ".join(r.name for r in self.map.rooms) or "none"
            return Refusal(f"the {self._house} has no {what}; its rooms are {rooms}")
        if self.is_fixed_word(text, cls):
            places = ", ".join(p.name for p in self.map.places) or "none"
            like = [p.name for p in self.map.places if cls and class_key(p.cls) == class_key(cls)
                    and set(class_words(cls)) & set(what.split())]   # "the tv": a tv stand, not a guess's table
            only = f" (only {' and '.join(like)}, a {spoken(cls)})" if like and cls and what != spoken(cls) else ""
            return Refusal(f"the {self._house} has no {what}{only}; its places are {places}")
        return None

    def where_said(self, text: str) -> str | None:
        """The room a phrase says its thing is in ("the cups in the family room": family_room)."""
        where = where_words(text)
        return self._room_of_words(where) if where else None

    def names_of_kind(self, kind: str) -> Sequence[str]:
        return [r.id for r in self.referents if r.kind == kind]


def kind_of(taxonomy: Taxonomy, cls: str, category: str) -> bool | None:
    """Whether a class is of a category, as the library's taxonomy says; for a compound class the
    taxonomy does not list, as its head (the last word) is: a ``bunk_bed`` is a bed (furniture: it
    does not switch on), a ``chest_freezer`` a freezer, a ``filing_cabinet`` a cabinet."""
    known = taxonomy.is_a(cls, category)
    words = class_words(cls)
    if known is None and len(words) > 1:
        return taxonomy.is_a(words[-1], category)
    return known


def person_name(m: Map | None, value: str, said: str) -> str:
    """How a person is said in what the robot tells: as the map writes them ("Raj"), else their name as the
    command says it, capitalised as names are ("tell anna hello": Anna)."""
    person = m.person(value) if m is not None else None
    if person is not None:
        return str(person.name)
    words = [w for w in said.split() if w.lower() not in DROPPED and not w.lower().endswith("'s")] or [value]
    return " ".join(w if any(c.isupper() for c in w) else w.capitalize() for w in words)


def person_value(text: str, head: str, people: Mapping[str, object] | None = None) -> str:
    """The id a phrase for a person takes: the speaker's for "me", else the name's key."""
    if head.lower() in SPEAKER_WORDS:
        return SPEAKER
    if head.lower() in SOME_PERSON:    # "is there anyone in the kitchen?": a person, as "a person" is
        return "person"
    words = [w for w in class_words(text) if w not in DROPPED]
    if people is not None:
        for word in (*words, head):
            if class_key(word) in people:
                return class_key(word)
    return class_key(head)
