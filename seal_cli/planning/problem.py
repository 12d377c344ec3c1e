"""The planning problem: the commanded frames, the things that fill their elements, and the state
they start from — what :func:`seal_cli.planning.plan.plan` takes, built from a parsed command, the
robot's state and a map.

**Values.** An element's value is the phrase's grounded class (``Phrase.cls``, known when a
vocabulary or a map is), else its head noun as a class key ("the alarm clock" without a vocabulary
is ``clock``). A pronoun takes the value of its antecedent (``refers_to``); one with no antecedent
("put it in the fridge" alone) is an error. An element the command leaves out takes its default.

**Things.** Values name things. Without a map a thing is named by its class. A map names its
places and rooms (``fridge_1``), and a value that is the class of a place becomes the first place
of that class in the map's order ("the fridge" → ``fridge_1``). Several things of one class are
``<class>``, ``<class>_2``, ``<class>_3``, …: the map's objects of a class in the map's order, and
the things a counted phrase ("two apples") asks for, so that on a map "two apples" are its first
two apples. A frame whose element is counted is commanded once per thing, in order, and so is a
frame whose pronoun refers to them ("find two apples and put them in the fridge").

**On a map** (:mod:`seal_cli.planning.grounding`) a phrase names the map's room, place or person
its words call ("the couch in the living room" → ``sofa_2``), "me" the speaker; a room or a fixed
thing the map lacks is refused. A value of a class no prior, object or place of the map names is
a *warning* (``Problem.warnings``): ``seal run`` says it has none without searching the house (the
robot's perception knows the map's classes only), unless a class the map names is a kind of it. A frame
whose element is only counted (Count) takes the class once, however many things the phrase says.

**Fixed things.** A room, or a class of the library's ``fixed`` category (furniture, appliances),
never fills an element of type ``object`` (what the robot takes into its hand): "clean the
bathroom" is refused with the frame's own description.

**State.** The robot holds ``holding`` (else the map's ``robot.holding``), else its hand is empty.
The map's objects are ``in`` their places. A thing that opens and closes (a map place with
``openable: true``, else a class of the ``openable`` category) is closed unless the map says
``open: true``; every other thing is always open (:attr:`State.closable <seal_cli.planning.state.State.closable>`).
Then the frames of each ``done`` command, grounded the same way, are applied in order: they ran.
"""

from __future__ import annotations

import contextlib
import itertools
import math
import re
from collections.abc import Iterable, Iterator, Mapping, Sequence
from dataclasses import dataclass, field, replace
from typing import TYPE_CHECKING, Any

from seal_cli.errors import SealError, at_words
from seal_cli.frames.library import Library
from seal_cli.frames.model import Action, Binding, Fact, Frame
from seal_cli.frames.taxonomy import Taxonomy, check_class_name, class_key, class_words
from seal_cli.maps.model import SPEAKER
from seal_cli.maps.prepositions import located
from seal_cli.planning.grounding import FIXED, PAIRED, WHERE_TYPES, is_room_word, kind_of, where_words, words_of
from seal_cli.planning.questions import name_asked
from seal_cli.planning.state import State, robot_facts

OPENABLE = "openable"
OBJECT = "object"
"""The category of what a robot handles; a map's rooms and places (fixed furniture and receptacles,
as the SPEC says) are never one."""

if TYPE_CHECKING:
    from seal_cli.language.parser import Parse, Phrase
    from seal_cli.language.values import Evoked
    from seal_cli.maps.model import Map

__all__ = ["MAX_COMMANDED", "MAX_COUNT", "Problem", "Things", "build_problem", "commanded_frames", "instance_names",
           "parse_to_plan", "problem_of_text"]

INDEFINITE = frozenset({"something", "anything", "everything", "nothing"})
"""Pronouns that name a thing of their own rather than an antecedent."""


THERE = frozenset({"there", "over there", "in there", "yonder"})
"""Words that point at a place and name none: with no place before them in the command (the parser's
``refers_to``), where they point is unknown ("put the cup in there" alone), and the command is refused."""

HELD_PRONOUNS = frozenset({"it", "this", "that"})
"""Pronouns that, with nothing before them in the command, call what the robot holds."""

PLURAL_PRONOUNS = frozenset({"them", "these", "those"})
"""Pronouns that call what the robot holds, or what a done command handled last, when it is one thing said as a
plural: a pair ("the gloves") or a noun with a plural form only ("the scissors") (:func:`said_as_plural`)."""


def said_as_plural(name: str) -> bool:
    """Whether one thing of a class (or an instance's name, ``gloves_1``) is called "them": its last word names a
    pair in the plural (:data:`~seal_cli.planning.grounding.PAIRED`: "gloves", "goggles"; not "glass", a drinking
    glass, nor "glove"), has a plural form only ("scissors", "pliers"), or is the plural of a noun whose singular is
    another word: a thing the map itself names in the plural, one box of "tissues", one bag of "crayons" (e2e32:
    after `--done 'bring me the tissues'`, "take them to Priya" was refused). "hang them on the coat rack", holding
    the gloves, was refused: nothing before "them" fit (e2e31)."""
    from seal_cli.language.morphology import noun_lemma, plural_only

    words = [w for w in class_words(name) if not w.isdigit()]
    if not words:
        return False
    word = words[-1]        # a class named by the plural of a pair ("gloves", "glasses"; not a drinking "glass")
    return word != noun_lemma(word) or plural_only(word) or _ends_in_a_pair(word)


def _ends_in_a_pair(word: str) -> bool:
    """Whether a word written as one is a compound whose last part is the plural of a pair
    (:data:`~seal_cli.planning.grounding.PAIRED`): "sunglasses", "eyeglasses", "snowshoes" (e2e33: after `--done 'put
    the sunglasses on the reception desk'`, "give them to Jack" was refused: the tables know "glasses", not
    "sunglasses")."""
    from seal_cli.language.morphology import noun_lemma

    for k in range(1, len(word) - 3):
        part = word[k:]
        lemma = noun_lemma(part)
        if part.endswith("s") and lemma != part and lemma in PAIRED:
            return True
    return False


def instance_names(cls: str, n: int) -> tuple[str, ...]:
    """The names of ``n`` things of a class when nothing else is named: ``apple``, ``apple_2``, …"""
    key = class_key(cls)
    return tuple(key if i == 1 else f"{key}_{i}" for i in range(1, n + 1))


@dataclass(frozen=True)
class Problem:
    """A command ready to plan: its frames in the commanded order and the state they start from."""

    text: str
    commanded: tuple[Binding, ...]
    state: State
    warnings: tuple[str, ...] = ()
    """What the map does not know of the command: classes it has no prior or object of, people
    nobody placed."""
    put_away: tuple[Binding, ...] = ()
    """The commanded Place frames whose goal "put away" chose (:mod:`seal_cli.planning.keeping`): ``seal
    run`` chooses again once the robot knows where the thing lay."""
    put_back: tuple[Binding, ...] = ()
    """The commanded frames that put a thing "back" when the map did not say where it lay ("take the cup and
    put it back" in ``seal run``): their goal is where such a thing is kept until the robot has taken it, then
    where it took it from."""
    names: Mapping[str, str] = field(default_factory=dict)
    """How each person the command names is said, by id ("raj": Raj, as the map writes him)."""
    among: Mapping[Binding, tuple[str, ...]] = field(default_factory=dict)
    """The commanded frames whose goal was one of several places of a class the command did not tell apart ("the
    fridge", two on the map), with those places: where a thing of the kind lies in any of them, the frame is so
    already (:func:`seal_cli.planning.lying.goal_among`; ``seal run`` asks it of what the robot sees)."""
    one_away: tuple[Binding, ...] = ()
    """The commanded frames that put a thing "back" on or in a place they name ("put the book back on the bookshelf"):
    the thing is one on or in no place of the goal's class (:func:`the_ones_not_there`; ``seal run``'s robot asks it
    of what it sees, :meth:`seal_cli.sim.agent.Agent.already_so`)."""
    done: tuple[Binding, ...] = ()
    """The frames of the commands already done (``--done``), in order, each grounded after the ones before it ("pick
    up the cup", then "put it on the table": the cup): ``seal run`` starts from their postconditions (e2e31: it
    grounded each alone, and refused "it")."""
    nearest: Mapping[Binding, tuple[str, ...]] = field(default_factory=dict)
    """The commanded frames that carry a thing to the nearest of several places of a class the command did not tell
    apart, nearest from where the robot takes it, with those places: ``seal run`` plans before it knows where the thing
    lies (it guessed where one most likely lies), so it chooses again from where it took it, as ``seal plan`` chose
    (e2e31: "put the brush in the sink" planned the finishing room's sink beside the brush's table; the run washed it in
    the kitchen's, nearer the showroom's table it guessed)."""


class Things:
    """The things a command and a map talk about: their names and classes, which ones open and
    close, and what the map says about them (``in`` and ``open`` facts)."""

    def __init__(self, taxonomy: Taxonomy, map: Map | None = None) -> None:
        from seal_cli.planning.grounding import MapNames

        self.taxonomy = taxonomy
        self.map = map
        self.names = MapNames(map, taxonomy) if map is not None else None
        self.classes: dict[str, str] = {}
        self.closable: set[str] = set()
        self.fixed: set[str] = set()
        """The map's rooms and places: they stay where they are."""
        self.rooms: dict[str, str] = {}
        """The room of each of the map's places that lies in one, and of each of its things on no place."""
        self.facts: set[Fact] = set()
        self.robot_holding: str | None = None
        self.held: str | None = None
        self.named_before: list[str] = []
        """The people the commands already done (``--done``) named, in order: the last is whom a "him" or "her"
        the command does not name itself stands for."""
        self.handled_before: list[str] = []
        """The things the commands already done (``--done``) acted on (their frames' themes), in order: the last is
        what an "it" the command does not name itself stands for (--done 'pick up the cup' 'give it to me')."""
        """What the robot holds as the command starts (``--holding``, else the map's robot): what "it" calls
        when nothing before it in the command does ("put it in the sink")."""
        self.people: set[str] = set()
        """The people the command names."""
        self.done_said = False
        """Whether commands done before this one (``--done``) were given."""
        self.taken_from: dict[str, str] = {}
        """Where each thing the commands already done (``--done``) moved lay before the last of them moved it (its
        place, or its room when it lay on no place): where "put it back" takes it (:func:`_back_to`)."""
        self.changed: dict[Fact, str] = {}
        """Each fact a command already done made true or false → that command (:meth:`carry_out`)."""
        self.object_names: list[str] = []
        """The name of each of the map's objects, in the map's order (``cup``, ``cup_2``): what :meth:`carry_out` moved
        is read back onto the map by :func:`seal_cli.planning.aftermath.world_after`."""
        self.roles_said: set[str] = set()
        """The people the command calls by a noun ("the nurse"), not by a name."""
        self.called: dict[str, str] = {}
        """How each person the command names is said: as the map writes them ("Raj"), else as the command
        does, a name capitalised ("anna": Anna); by id."""
        self.synonyms: Mapping[str, tuple[str, ...]] = {}
        """More names of classes (a vocabulary file's), by class key."""
        self.put_away: list[Binding] = []
        """The commanded frames whose goal "put away" chose."""
        self.put_back: list[Binding] = []
        """The commanded frames that put a thing "back" where the robot will take it from."""
        self.one_away: list[Binding] = []
        """The commanded frames that put a thing "back" on or in a place they name ("put the book back on the
        bookshelf"), or "another" of a kind ("put another loaf on the counter"): the thing is one on or in no place of
        the goal's class now (:func:`the_ones_not_there`)."""
        self.one_more: list[Binding] = []
        """Those of :attr:`one_away` that say "another": their goal is the place of its class where one lies."""
        self.all_there: list[str] = []
        """What the map says against the command's words, said as warnings: every book on a bookshelf already for a
        thing put "back" (:func:`the_ones_not_there`), no book where the command says one is
        (:func:`_the_ones_said_where`)."""
        self.goal_back: list[Binding] = []
        """The commanded frames whose goal "back" chose (where the thing was taken from or lies: "put it back")."""
        self.points: dict[str, tuple[float, float]] = {}
        """Where the map puts each of its rooms (the middle), places, things and people, by id."""
        self.every: Mapping[str, int] = {}
        """How many things of a class "all the ..." asks for when the map does not place them (``seal run``'s
        robot, after looking all over the house for them), by class key."""
        self.kinds: set[str] = set()
        """The kinds of thing the map knows, by class key: its priors', objects' and places' classes, and those of
        the house's vocabulary (``seal run`` plans on the map without its objects, whose classes its perception
        knows all the same)."""
        self.all_kinds = False
        """Whether :attr:`kinds` are all the kinds of thing in the house: the map places its objects, or the house's
        vocabulary says their classes (a map without objects and no such vocabulary may hold anything)."""
        if map is not None:
            self._read_map(map)

    def is_place(self, name: str) -> bool:
        """Whether a value is one of the map's places (not a room, not a thing)."""
        return self.map is not None and any(class_key(p.name) == name for p in self.map.places)

    def _read_map(self, map: Map) -> None:
        self.kinds = {*map.kinds(), *(class_key(p.cls) for p in map.places)}
        self.all_kinds = bool(map.objects)
        for room in map.rooms:
            self.classes.setdefault(class_key(room.name), class_key(room.name))
            self.fixed.add(class_key(room.name))
            self.points[class_key(room.name)] = room.centroid
        for place in map.places:
            name = class_key(place.name)
            self.classes[name] = place.cls
            self.points[name] = place.at
            self.fixed.add(name)
            if place.room:
                self.rooms[name] = class_key(place.room)
            if place.openable:
                self.closable.add(name)
                if place.open:
                    self.facts.add(Fact("open", (name,)))
        counts: dict[str, int] = {}
        for obj in map.objects:
            counts[obj.cls] = counts.get(obj.cls, 0) + 1
            name = self._fresh(obj.cls, counts[obj.cls])
            self.object_names.append(name)
            self.points[name] = obj.at
            if obj.inside is not None:
                self.facts.add(Fact("in", (name, class_key(obj.inside))))
            elif (floor := map._room_name(obj.at)) is not None:
                self.rooms[name] = class_key(floor)     # on no place: on the room's floor
        self.robot_holding = map.robot.holding
        for person in map.people:
            self.classes[person.key] = "person"
            self.points[person.key] = map.person_at(person)
        self.classes.setdefault(SPEAKER, "person")
        self.points[SPEAKER] = map.speaker_at

    def _fresh(self, cls: str, n: int) -> str:
        """Register a new thing of a class, the n-th if that name is free (else the next free one)."""
        name = cls if n == 1 else f"{cls}_{n}"
        while name in self.classes:
            n += 1
            name = f"{cls}_{n}"
        self._add(name, cls)
        return name

    def _add(self, name: str, cls: str) -> None:
        if name not in self.classes:
            self.classes[name] = cls
            if self.taxonomy.is_a(cls, OPENABLE) is True:
                self.closable.add(name)

    def class_of(self, name: str) -> str:
        return self.classes.get(name, name)

    def name(self, value: str) -> str:
        """The thing a value names: the thing of that name, else the first of that class, else a new one."""
        key = class_key(value)
        if key in self.classes:
            return key
        for name, cls in self.classes.items():
            if cls == key:
                return name
        self._add(key, key)
        return key

    def instances(self, value: str, n: int) -> tuple[str, ...]:
        """``n`` distinct things of the class a value names, the known ones first (in map order)."""
        first = self.name(value)
        cls = self.classes[first]
        known = [first] + [name for name, c in self.classes.items() if c == cls and name != first]
        while len(known) < n:
            known.append(self._fresh(cls, len(known) + 1))
        return tuple(known[:n])

    def known(self, value: str) -> int:
        """How many things of the class a value names the map places (its objects; 0 without a map), or
        :attr:`every` says."""
        cls = class_key(value)
        if cls in self.every:
            return self.every[cls]
        if self.map is None:
            return 0
        return sum(1 for o in self.map.objects if class_key(o.cls) == cls)

    def lies_in(self, name: str, where: str) -> bool:
        """Whether the map has the thing ``name`` in or on the place ``where``, or in the room ``where`` (on a
        place of it, or on its floor)."""
        at = next((f.args[1] for f in self.facts if f.predicate == "in" and f.args[0] == name), None)
        if at is not None:
            return at == where or self.rooms.get(at) == where
        return self.rooms.get(name) == where

    def swap(self, one: str, other: str) -> None:
        """Let two things of one class trade names: what the map says of each (its ``in`` facts, its room, which of
        the map's objects it is) is said of the other."""
        def named(value: str) -> str:
            return other if value == one else one if value == other else value

        self.facts = {Fact(f.predicate, tuple(named(a) for a in f.args)) if f.predicate == "in" else f
                      for f in self.facts}
        self.taken_from = {named(k): v for k, v in self.taken_from.items()}
        rooms = {named(k): v for k, v in self.rooms.items() if k in (one, other)}
        self.rooms = {k: v for k, v in self.rooms.items() if k not in (one, other)} | rooms
        points = {named(k): v for k, v in self.points.items() if k in (one, other)}
        self.points = {k: v for k, v in self.points.items() if k not in (one, other)} | points
        self.object_names = [named(n) for n in self.object_names]   # each name stays with what the map says of it

    def hold(self, holding: str | None) -> None:
        """Keep what the robot holds as the command starts (:attr:`held`): ``holding`` (a class, refused if
        malformed or a room, place or person of the map), else the map's robot's."""
        if holding:
            check_class_name(holding, "--holding")  # named as typed (hostile30)
            if self.map is not None:
                self.map.check_holding(holding)
        self.held = holding or self.robot_holding

    def state(self) -> State:
        """The world's facts and the robot's hand (what :meth:`hold` and the commands already done left in it)."""
        name = self.name(self.held) if self.held else None
        facts = {f for f in self.facts if not (f.predicate == "in" and f.args[0] == name)}
        return State.of(facts | robot_facts(name), self.taxonomy, self.closable, self.classes, self.rooms)

    def carry_out(self, text: str, bindings: Sequence[Binding]) -> None:
        """What a command already done (``--done``, said as ``text``) left: its frames applied in order to the map's
        facts and the robot's hand, a thing in one place at a time — a frame that puts it somewhere, or takes it up,
        takes it from wherever it lay (e2e30: "bring the cup to the table" left the cup on the coffee table too,
        whence "put it back" was already so). Refused, naming both, when a frame needs a fact an earlier done
        command undid."""
        state = self.state()
        for binding in bindings:
            for fact in state.unmet(binding):
                if fact.positive in self.changed:
                    raise SealError(f"--done {text!r} cannot follow --done {self.changed[fact.positive]!r}: "
                                    f"{binding.frame.name} needs {fact}, which that command undid; say what happened "
                                    "in between (another --done) or drop one of them")
            after = state.apply(binding)
            for thing in moved_by(binding):
                self._moved(thing, state, after)
                after = State(frozenset(f for f in after.facts if not _elsewhere(f, thing, binding)), after.taxonomy,
                              after.closable, after.classes, after.rooms)
            state = after
            self.changed.update((f.positive, text) for f in binding.postconditions)
        self.facts = {f for f in state.facts if f.predicate not in ("holding", "hand_empty")}
        self.held = next((f.args[0] for f in state.facts if f.predicate == "holding"), None)

    def _moved(self, thing: str, before: State, after: State) -> None:
        """Keep where a thing lay before a frame moved it (:attr:`taken_from`), and where it lies now."""
        lay = next((f.args[1] for f in sorted(before.facts, key=str) if f.predicate == "in" and f.args[0] == thing),
                   None) or (self.rooms.get(thing) if not any(f.args[:1] == (thing,) for f in before.facts) else None)
        now = next((f.args[1] for f in sorted(after.facts, key=str) if f.predicate == "in" and f.args[0] == thing
                    and f.args[1] != lay), None)
        if lay is not None and Fact("holding", (thing,)) not in before.facts:
            self.taken_from[thing] = lay
        if now is not None and now in self.points:
            self.points[thing] = self.points[now]


MAX_COUNT = 100
"""The most things one phrase may ask for ("put 100 apples in the fridge"); more is refused."""

MAX_COMMANDED = 200

ON_TOP = ("on", "onto", "upon", "atop")
"""Prepositions that put a thing on top of the goal, not in it ("on top of" is tagged "on")."""


def on_top(frame: Frame, goal: Phrase | None) -> Frame:
    """The frame's reading for a goal said with a preposition of :data:`ON_TOP` ("put the teapot *on*
    the sideboard"): the thing goes on the goal's top, so the goal need not be open (its ``open(goal)``
    precondition is dropped) and it is put there with ``place_on``, which a closed place allows. Any
    other goal ("in", "into", "inside", or none said) keeps the frame as the library wrote it."""
    if goal is None or goal.preposition not in ON_TOP:
        return frame
    opened = Fact("open", ("goal",))
    if opened not in frame.preconditions:
        return frame
    return replace(frame, preconditions=tuple(p for p in frame.preconditions if p != opened),
                   actions=tuple(Action("place_on", a.args, a.where) if a.name == "place" and a.args[-1:] == ("goal",)
                                 else a for a in frame.actions))
"""The most grounded frames one command may command (counts and conjunctions multiply)."""


def _default(frame: Frame, element: Any, evoked: Any, things: Things, text: str) -> str:
    """What an element the command leaves out takes: its default, the map's thing of that class if it has
    one. A map without one that has a place of the element's type gives its first (the cafe's oven heats
    as a microwave would); a map with neither, for a default that is fixed (a sink, a fridge: furniture the
    map would list), refuses, naming the frame's verb: the robot would search the house for it in vain."""
    value = things.name(element.default)
    if things.map is None or value in things.fixed:
        return value
    fits = [class_key(p.name) for p in things.map.places if kind_of(things.taxonomy, p.cls, element.type) is True]
    if fits:
        return fits[0]
    if kind_of(things.taxonomy, element.default, FIXED) is not True:
        return value
    places = ", ".join(p.name for p in things.map.places) or "none"
    span = getattr(evoked, "span", None)
    raise at_words(f"{frame.name} needs a {element.type} as its {element.role} (a {element.default} unless one "
                   f"is said), and the {things.map.said} has none; its places are {places}", span, text)


def _goal_not_source(evoked: Evoked, values: Mapping[str, tuple[str, ...]], things: Things, text: str) -> None:
    """Refuse a frame that takes a thing to the very place the command says it is ("there's a cup in the family
    room, bring it *there*": there is the family room): what the user wants done is not said, and the robot does
    not guess ("here" is another command). Not "put it back" (where it was taken from, on purpose)."""
    goal, source = evoked.elements.get("goal"), evoked.elements.get("source")
    if (goal is None or source is None or goal.default or source.default or things.map is None
            or len(values.get("goal", ())) != 1 or values.get("goal") != values.get("source")):
        return
    theme = evoked.elements.get("theme")
    where = values["goal"][0]
    shown = f"the {where.replace('_', ' ')}" if things.map.room_id(where) is not None else where
    what = f"the {theme.head}" if theme is not None and theme.head else "the thing"
    told = (f"{goal.text!r} is {shown}, where the command says {what} is" if (goal.text or "").lower() in THERE
            else f"the command takes it from {shown} to {shown}")
    raise _located(f"{what} is already in {shown}: {told}; say where to take it (here, to someone, or another "
                   "place)", goal, text)


def _located(message: str, phrase: Phrase | Evoked | None, text: str) -> SealError:
    """An error about a phrase (or a frame's words), with a caret under it when its place in the text is known."""
    return at_words(message, phrase.span if phrase is not None else None, text)


def _said(phrase: Phrase | None, name: str) -> str:
    return f"{phrase.text!r} ({name})" if phrase is not None and phrase.text else name


def _unnamed_kind(phrase: Phrase, map: Map) -> str:
    """The refusal of "something", "anything" as the thing of a frame on a map: no kind to look for
    (a search for a class called "something" would sweep the house and say "no something")."""
    kinds = map.kinds()
    known = f" (the {map.said} knows of {', '.join(kinds)})" if kinds else ""
    return (f"{phrase.text!r} does not say what kind of thing: name it{known}, or ask what is on or in "
            "a place (\"what is in the fridge?\")")


def _values(phrase: Phrase, earlier: Sequence[Mapping[str, tuple[str, ...]]], things: Things,
            text: str, category: str = "thing", asked: bool = False, carried: bool = False,
            gone_to: bool = False, vessel: bool = False) -> tuple[str, ...]:
    """The things a phrase names: its antecedent's for a pronoun, else the map's thing it calls,
    else its class (counted if asked); every conjunct's for a coordination. ``asked``: the phrase is
    what a question asks about ("how many chairs ...?", "is there a chair ...?"), so a fixed thing
    the map lacks is no refusal but a class to look for (the answer may be none). ``carried``: the
    frame carries the thing (:func:`_carried`), so only its own words can make it furniture the map lacks.
    ``vessel``: no source is said, so a thing the map knows only in its container is the container
    (:func:`_kept_in`)."""
    from seal_cli.language.english import PERSON_PRONOUNS, PRONOUNS

    if phrase.conjuncts:        # "the apple and the pear": both ("the book and the other book": two books)
        each: list[tuple[str, ...]] = []
        for c in phrase.conjuncts:
            found = [v for values in each for v in values]
            before = [*earlier, {"": tuple(dict.fromkeys(found))}] if found else earlier
            each.append(_values(c, before, things, text, category, asked, carried, gone_to, vessel))
        return _conjoined(phrase, each, things, carried)
    if phrase.refers_to is not None:
        index, role = phrase.refers_to
        if 0 <= index < len(earlier) and role in earlier[index]:
            return earlier[index][role]
        raise _located(f"{phrase.text!r} refers to the {role} of frame {index + 1}, which the command lacks",
                       phrase, text)
    word = phrase.head.lower()
    if word in THERE and category in ("location", "place", "room"):
        where = f" (the {things.map.said}'s places are {', '.join(p.name for p in things.map.places)})" \
            if things.map is not None and things.map.places else ""
        raise _located(f"cannot tell where {phrase.text!r} is: no place before it in the command says; name the "
                       f"place{where}", phrase, text)
    if word in INDEFINITE and things.map is not None and category not in ("message", "question"):
        raise _located(_unnamed_kind(phrase, things.map), phrase, text)
    if word in PRONOUNS and word not in PERSON_PRONOUNS and word not in INDEFINITE:
        if things.handled_before and (word in HELD_PRONOUNS or (word in PLURAL_PRONOUNS and said_as_plural(
                things.handled_before[-1]))):   # what the commands done acted on last ("them": the gloves)
            return (things.handled_before[-1],)
        if things.held and (word in HELD_PRONOUNS or (word in PLURAL_PRONOUNS and said_as_plural(things.held))):
            return (things.name(things.held),)
        raise _located(f"cannot tell what {phrase.text!r} refers to: nothing before it in the command fits"
                       f"{', nor does a command done before it (--done)' if things.done_said else ''}", phrase, text)
    if things.names is not None and (on_map := _on_map(phrase, things, text, category, asked, carried,
                                                       gone_to)) is not None:
        return on_map
    value = phrase.cls or phrase.head
    if category == "message" and (question := name_asked(phrase.text or "", things.taxonomy)) is not None:
        value = question      # "the names of the people in the kitchen": who is in the kitchen, not "name" (words43)
    if category in ("message", "question"):    # what is said, as a name: "what's on it?" what_s_on_it
        value = " ".join(re.findall(r"[A-Za-z0-9]+", value))
    if things.names is not None and phrase.cls and not _names(phrase, phrase.cls, things):
        value = phrase.head     # on a map, a class the words do not name is a guess: the thing said is sought
    if not phrase.cls and category not in ("message", "question") and things.map is not None:
        value = _compound_said(phrase, value, things.map, things.taxonomy)
    if not class_key(value):
        raise _located(f"{phrase.text!r} names no thing", phrase, text)
    if vessel and carried and not asked and things.map is not None and (kept := _kept_in(value, things)):
        return things.instances(kept, 1)        # "some water" and the map's water bottle: the bottle, once
    if carried and not asked and things.map is not None and (sources := _comes_from(value, things)):
        m = things.map
        where = ", ".join(f"{p.name} ({located(p.room or '?', m)})" for p in sources)
        kinds = m.kinds()
        known = f"; the things it knows of are {', '.join(kinds)}" if kinds else ""
        word = " ".join(class_words(value))
        raise _located(f"the {_words(m.name)} has no {word} to carry, only {where}, which the robot cannot get {word} "
                       f"from{known}", phrase, text)
    if phrase.quantity == 0:   # "bring me zero apples", "0 cups" planned one (hostile22): a count of none is no task
        raise _located(f"{phrase.text!r} asks for no things (a count of zero): say how many, at least one", phrase,
                       text)
    count = 1 if category in ("message", "question") else _count(phrase, value, things)   # said once, "names" too
    if count == 1 and (other := _the_other(phrase, value, earlier, things)) is not None:
        return (other,)
    if count > MAX_COUNT:
        raise _located(f"{phrase.text!r} asks for {count:,} things; seal plans for at most {MAX_COUNT} "
                       "of a kind", phrase, text)
    return things.instances(value, count)


def _compound_said(phrase: Phrase, value: str, m: Map, taxonomy: Taxonomy) -> str:
    """The kind a phrase names on a map that knows nothing of its head (no prior, object or place of it, nor of a kind
    of it): the head with the words said right before it that are no adjectives ("the *rolling* pin", "a *tennis*
    ball", not "the *red* cup"), the compound the user said, so that the run says "no rolling pin found", not "no pin
    found" (words40). ``value`` as it was when the map knows the head or nothing comes before it."""
    from seal_cli.language.morphology import parts_of_speech

    known = set(m.priors) | {o.cls for o in m.objects} | {p.cls for p in m.places}
    key = class_key(value)
    if not key or key in known or any(taxonomy.is_a(k, key) is True for k in known):
        return value
    before: list[str] = []
    for word in reversed(phrase.modifiers):
        if not word.isalpha() or "adj" in parts_of_speech(word.lower()):
            break
        before.insert(0, word.lower())
    return " ".join([*before, value]) if before else value


def _another_said(evoked: Evoked, earlier: Sequence[Mapping[str, tuple[str, ...]]], things: Things) -> bool:
    """Whether the frame's theme is "another" of a kind no earlier frame of the command named ("put another loaf on the
    counter"): one more besides the one where it goes, so not one lying there (e2e30; after a thing of the kind
    named before, "another" is that one's other, :func:`_the_other`)."""
    phrase = evoked.elements.get("theme")
    if phrase is None or "another" not in {w.lower() for w in (phrase.text or "").split()}:
        return False
    value = class_key(phrase.cls or phrase.head or "")
    cls = things.class_of(things.name(value)) if value else ""
    return not any(things.class_of(v) == cls for values in earlier for vs in values.values() for v in vs)


def _the_other(phrase: Phrase, value: str, earlier: Sequence[Mapping[str, tuple[str, ...]]],
               things: Things) -> str | None:
    """"The other mug" (or "another mug") after a mug the command named before (e2e24: "put the mug from the sink on
    the kitchen table, then bring me the other mug"): English's "other" picks a thing of the kind that is not the
    one said, so
    the first of the kind no earlier frame names (a new one when the map has no more: the run looks for it and
    says there is none). None when the phrase says no "other" or nothing of the kind was named before it."""
    if not {"other", "another"} & {w.lower() for w in (phrase.text or "").split()}:
        return None
    cls = things.class_of(things.name(value))
    said = {v for values in earlier for vs in values.values() for v in vs if things.class_of(v) == cls}
    if not said:
        return None
    return next(n for n in things.instances(value, len(said) + 1) if n not in said)


def _conjoined(phrase: Phrase, each: Sequence[tuple[str, ...]], things: Things, carried: bool) -> tuple[str, ...]:
    """The things of a coordination: every conjunct's, in order. Two conjuncts are two things: where a
    carried thing's conjunct, said by its own noun, names a class an earlier conjunct already gave, it is the
    next thing of that class ("a salt and a pepper shaker", "the tube and the toilet paper roll", "an empty roll
    and a full roll of toilet paper": two shakers, two rolls; alfred23). Without a map only: a map's thing
    said twice ("the mug and the cup" of a map with one cup) is its one thing; a pronoun ("the apple and it")
    and a thing the frame does not carry (a place, a person) keep their value."""
    from seal_cli.language.english import PRONOUNS

    out: list[str] = []
    for conjunct, values in zip(phrase.conjuncts, each, strict=True):
        anew = (carried and things.map is None and conjunct.refers_to is None and not conjunct.conjuncts
                and bool(conjunct.head) and conjunct.head.lower() not in PRONOUNS)
        for value in values:
            if value in out and anew:
                cls = things.classes.get(value, class_key(value))
                taken = sum(1 for v in out if things.classes.get(v) == cls)
                value = things.instances(cls, taken + 1)[-1]
            if value not in out:
                out.append(value)
    return tuple(out)


def _comes_from(value: str, things: Things) -> list[Any]:
    """The map's places a thing to carry comes out of, when the map knows nothing else of its class: places
    (no furniture) whose class is the thing's class and a head ("coffee" and the ``coffee_machine``, "ice"
    and an ``ice_maker``; not the ``coffee_table``). The robot takes things from places and does not work
    machines to make them, so "bring a coffee" there is refused at once, naming the machine and what the map
    does know of, rather than searching the house for a cup of coffee lying about."""
    m = things.map
    assert m is not None
    key = class_key(value)
    said = class_words(key)
    known = {class_key(c) for c in (*m.priors, *(o.cls for o in m.objects), *(p.cls for p in m.places))}
    if not said or key in known:
        return []
    return [p for p in m.places if len(words := class_words(p.cls)) > len(said) and words[:len(said)] == said
            and kind_of(things.taxonomy, p.cls, "furniture") is not True]


def _taken_out_of_a_thing(evoked: Evoked, things: Things) -> bool:
    """Whether the command says a thing the theme is taken from, not a room or place of the map ("the biscuits
    out of the *tin*"): then the theme is what is inside it, never the container itself (:func:`_kept_in`)."""
    source = evoked.elements.get("source")
    if source is None or not source.text or things.names is None:
        return False
    try:
        return things.names.ground(source.text, "location", ("room", "place")) is None
    except SealError:
        return True


def _kept_in(value: str, things: Things) -> str | None:
    """The container a thing to carry comes in, when the map knows nothing of the thing's own class but knows
    one kind of thing (a prior's or an object's class, not a place's) named by the thing's words and then a
    container ("some water": the office's ``water_bottle``; "the biscuits": the bungalow's ``biscuit_tin``):
    the robot carries the container, as a person handed it would. None when the map knows the class, or
    knows no such container or several."""
    from seal_cli.language.lexicon import noun_lemma

    m = things.map
    assert m is not None
    said = [noun_lemma(w) for w in class_words(value)]
    if not said or class_key("_".join(said)) in m.kinds() or class_key(value) in m.kinds():
        return None
    found = [kind for kind in m.kinds() if len(words := class_words(kind)) > len(said)
             and [noun_lemma(w) for w in words[:len(said)]] == said
             and kind_of(things.taxonomy, words[-1], "container") is True]
    return found[0] if len(found) == 1 else None


APPLIANCE_KINDS = (FIXED, "furniture", "openable", "toggleable", "heater", "cooler", "washer")
"""The library's categories of what stands in a house rather than what the robot carries."""


def _may_be_fixed(phrase: Phrase, cls: str, things: Things) -> bool:
    """Whether the class the parse gave a phrase may say it is a fixed thing the map lacks: the words
    name it ("the couch"), share a word with it ("the tv": a tv stand), or name a kind of appliance or
    furniture themselves ("the microwave", which the learned table reads as the cafe's fridge). Not a
    learned guess that turns a thing to carry into furniture ("the apple" on the terrace, read as its
    dining table, is an apple to search for)."""
    if _names(phrase, cls, things) or set(class_words(cls)) & set(words_of(phrase.text or "")):
        return True
    return any(things.taxonomy.is_a(phrase.head, kind) is True for kind in APPLIANCE_KINDS)


def _names(phrase: Phrase, cls: str, things: Things) -> bool:
    """Whether the phrase's words name the class: its own words or one of its synonyms' ("the couch": a
    sofa), rather than a class a learned table guesses people meant ("the bowl": a cup). A name of
    several words is named by its head, the last ("the bottle": a water bottle; "a coffee" is no
    coffee machine)."""
    from seal_cli.language.lexicon import noun_lemma

    said = {noun_lemma(w) for w in class_words(phrase.text or phrase.head)} | {phrase.head}
    names = [cls, *things.taxonomy.names.get(class_key(cls), ()), *things.synonyms.get(class_key(cls), ())]
    return any(noun_lemma(class_words(n)[-1]) in said for n in names if class_words(n))


THIRD_PERSONS = frozenset({"him", "her", "them", "he", "she", "they"})
"""Pronouns that stand for a person said before them; with nobody said, no one the robot can find."""


def _a_person_pronoun(phrase: Phrase) -> bool:
    """Whether the phrase is "him", "her" or "them" standing for no one the command itself named."""
    said = (phrase.text or "").lower()
    return said in THIRD_PERSONS and phrase.refers_to is None and phrase.head.lower() in THIRD_PERSONS


def _someone_named(phrase: Phrase, text: str) -> None:
    """Refuse "him", "her" or "them" that stands for nobody the command (or what it says beside it, or a command
    already done) named ("get *him* a plate"): the robot cannot tell whom it means, and would look the house over
    for someone called Him."""
    if _a_person_pronoun(phrase):
        raise _located(f"cannot tell who {phrase.text!r} is: the command names nobody before it, nor does a --done; "
                       f"say their name (or their role: \"the cook\")", phrase, text)


def _on_map(phrase: Phrase, things: Things, text: str, category: str, asked: bool = False, carried: bool = False,
            gone_to: bool = False) -> tuple[str, ...] | None:
    """The map's person, room or place a phrase names (see :mod:`seal_cli.planning.grounding`);
    None for an object, which the robot must find. A thing to carry (``carried``) is refused as furniture
    or an appliance the map lacks only when its words name that class ("bring me the sofa"), never by a
    learned guess nor by the head's kind ("bring me the laptop": a laptop opens and switches on, and
    is carried)."""
    from seal_cli.planning.grounding import DROPPED, HERE, SPEAKER_WORDS, person_name, person_value

    names = things.names
    assert names is not None and things.map is not None
    if phrase.kind == "place" and phrase.head.lower() in HERE:    # "come here": where the speaker is
        things.people.add(SPEAKER)
        return (SPEAKER,)
    if category not in ("message", "question") and phrase.text:
        try:
            called = names.with_role(phrase.text)         # "the nurse": whoever the map says is the nurse
        except SealError as wrong:
            raise _located(wrong.message, phrase, text) from None
        if called:
            things.people.update(called)
            return called
    if phrase.head.lower() in SPEAKER_WORDS or phrase.kind == "person" \
            or things.taxonomy.is_a(category, "person") is True and category != "thing":
        if _a_person_pronoun(phrase) and things.named_before:   # --done 'find Ben' 'give him the remote'
            return (things.named_before[-1],)
        _someone_named(phrase, text)
        if phrase.text and phrase.text.split()[0].lower() in DROPPED:
            things.roles_said.add(class_key(phrase.head))     # "the nurse" on a map without one
        value = person_value(phrase.text or phrase.head, phrase.head, {p.key: p for p in things.map.people})
        things.people.add(value)    # only the map's people are of class person: another is searched for by name
        if value not in (SPEAKER, "person") and value not in things.roles_said:
            things.called.setdefault(value, person_name(things.map, value, _person_words(phrase)))
        return (value,)
    if category in ("message", "question") or not phrase.text:
        return None
    kinds = ("room", "place", "person") if category == "thing" else ("room", "place")
    try:
        found = names.ground(_place_words(phrase), category, kinds)
    except SealError as wrong:
        raise _located(wrong.message, phrase, text) from None
    if found is not None:
        return (found.id,)
    if things.taxonomy.is_a(phrase.cls or phrase.head, "person") is True:
        return None
    cls = phrase.cls
    fixed = cls is not None and (_names(phrase, cls, things) if carried else _may_be_fixed(phrase, cls, things))
    said = cls if fixed else None
    refused = None if asked else names.refusal(_place_words(phrase), said)
    if refused is not None:
        raise _located(refused.message, phrase, text)
    if gone_to and not asked and not _kinds_known_of(phrase, things, said=True):
        m = things.map
        what = phrase.head if where_words(phrase.text) else " ".join(words_of(_place_words(phrase))) or phrase.head
        kind = "no kind of thing it knows of" if _unheard_of(phrase, things) else \
            "no prior, object or place of it names the kind, so the robot has nowhere to search for one"
        raise _located(f"the {_words(m.name)} has no {what} (no room, place or person of the map is called so, and "
                       f"{kind}); its rooms are {', '.join(m.room_names) or 'none'}", phrase, text)
    if not asked and category in FIXTURE_TYPES and not _kinds_known_of(phrase, things):
        m = things.map                 # said in a room too ("leave the light on in the hall"): the map knows none
        tax = things.taxonomy

        def does(cls: str) -> bool:     # by the class or another name of it (a hob is a stove)
            return any(kind_of(tax, n, category) is True for n in (cls, *tax.names.get(class_key(cls), ())))

        places = [p.name for p in m.places if (p.openable if category == "openable" else does(p.cls))]
        places += [kind for kind in m.kinds() if does(kind)]
        what = phrase.head if where_words(phrase.text) else " ".join(words_of(phrase.text)) or phrase.head
        raise _located(f"the {_words(m.name)} has no {what} (no place, thing or prior of the map names one, and what "
                       f"opens or switches is not searched for); what it knows will {FIXTURE_TYPES[category]}: "
                       f"{', '.join(places) or 'nothing'}", phrase, text)
    return None


DESTINATIONS = frozenset({"navigate", "lead", "place", "pour"})
"""Actions whose place argument is where the robot sets out for (goes, leads someone, puts or pours a thing)."""


def _gone_to(frame: Frame, role: str) -> bool:
    """Whether the element says where the robot sets out for: it goes there, leads someone there, or puts or pours
    what it holds there (Go's, Guide's, Place's, Bring's and Pour's goal, Find's ground), never what it takes, finds
    or looks at (a theme) nor where it takes a thing from. Such a value must be one the robot can find before it
    drives: a room, place or person of the map, or a kind the map knows (:func:`_kinds_known_of`), else it is
    refused where it is said (reach27: "put the cup on the spaceship" fetched the cup, 11.25 m, then gave up)."""
    used = [a for a in frame.actions if role in a.args and a.name in DESTINATIONS]
    return role != "theme" and frame.element(role).type in (*WHERE_TYPES, "container") and bool(used)


def _unheard_of(phrase: Phrase, things: Things) -> bool:
    """Whether a phrase names nothing the robot could go to: no kind the map knows (:func:`_kinds_known_of`), no
    class the parse grounded, and no class the library's taxonomy lists ("the barn", "the pharmacy"; a bag or a
    box is a thing to search for and put into)."""
    head = class_key(phrase.head)
    return (phrase.cls is None and not _kinds_known_of(phrase, things) and head not in things.taxonomy.known_classes
            and head not in things.taxonomy.by_name and not things.taxonomy.names.get(head))


FIXTURE_TYPES = {"openable": "open and close", "toggleable": "switch on and off"}
"""Element types whose thing is a fixture or an appliance the map would name ("open the car", "turn on the
telly" on a map with neither): a kind the map knows nothing of is refused, not searched for in the whole house;
said in a room ("the radio in the kitchen", "leave the light on in the hall") too (words18: it was looked for there,
while "turn off all the lights" was refused; a map that names no such thing anywhere has none in any room)."""


def _kinds_known_of(phrase: Phrase, things: Things, said: bool = False) -> bool:
    """Whether the map knows the kind of thing a phrase names: a prior, an object or a place of its class (the
    parse's, or the head's; ``said``: the parse's only when the words name it, not a learned guess, so "the bowl"
    read as a cup is a bowl, as the run seeks it)."""
    m = things.map
    assert m is not None
    known = {*m.kinds(), *(class_key(p.cls) for p in m.places)}
    cls = phrase.cls if phrase.cls and not (said and not _names(phrase, phrase.cls, things)) else None
    return any(class_key(c) in known for c in (cls, phrase.head) if c)


UNIVERSAL = frozenset({"all", "every", "each"})
"""Words that ask for every thing of a kind there is ("*all* the cups", "*every* cup", "*each* plate")."""


def every_said(parse: Parse) -> list[Phrase]:
    """The phrases of a parse that ask for every thing of a kind ("*all the cups*", "*every* cup"), by
    :data:`UNIVERSAL`, each kind once: ``seal run`` looks all over the house for them first."""
    out: dict[str, Phrase] = {}
    for evoked in parse.frames:
        for phrase in evoked.elements.values():
            said = (phrase.text or "").lower().split()
            if said[:1] and said[0] in UNIVERSAL and phrase.quantity is None and phrase.head:
                out.setdefault(phrase.cls or phrase.head, phrase)
    return list(out.values())


def _count(phrase: Phrase, value: str, things: Things) -> int:
    """How many things a phrase asks for: the number said ("two apples"); every one the map places for
    "all", "every" or "each" first ("all the cups": the two on the table and the one in the cupboard, e2e23;
    at least one); at least two for a plural that names the class by its head or by the head of one of the
    library's names for it ("the books", "both books", "toilet paper rolls" by "toilet roll"; not "the keys" of a
    key chain; not "the gloves" or "a pair of gloves", one pair: :data:`~seal_cli.planning.grounding.PAIRED`);
    one whole for pieces cut from it ("two slices of apple": one apple, sliced; but "two sets of keys" are two
    key chains)."""
    from seal_cli.language.grounding import PIECES

    heads = {class_words(name)[-1] for name in (value, *things.taxonomy.names.get(class_key(value), ()))
             if class_words(name)}       # "toilet paper rolls": the library's "toilet roll" (alfred23)
    named = phrase.head in heads
    if phrase.head in PIECES and not named:
        return 1
    said = (phrase.text or "").lower().split()
    if named and phrase.quantity is None and said[:1] and said[0] in UNIVERSAL and (known := things.known(value)):
        return known
    a_pair = phrase.quantity == 2 and "pair" in words_of(phrase.text or "")
    if phrase.head in PAIRED and (phrase.quantity is None or a_pair):
        return 1                      # "the gloves", "a pair of gloves": one pair
    if phrase.quantity is not None:
        return max(1, phrase.quantity)
    return 2 if phrase.plural and named else 1


def _check_types(frame: Frame, values: Mapping[str, tuple[str, ...]], phrases: Mapping[str, Phrase],
                 things: Things, text: str) -> None:
    """A value known not to belong to its element's category is an error ("open the table"); so is
    a map's room or place where the element is an object the robot handles ("pick up the sofa")."""
    for role, names in values.items():
        element = frame.element(role)
        for name in names:
            if element.type == OPENABLE and name in things.closable:
                continue
            cls = things.class_of(name)
            if element.type == OPENABLE and things.is_place(name):     # the map says which of its places open
                raise _located(f"{frame.name} needs its {role} to open and close, and {_said(phrases.get(role), name)}"
                               " does not (the map does not mark it openable)", phrases.get(role), text)
            if element.type == OBJECT and (name in things.fixed or kind_of(things.taxonomy, cls, FIXED) is True
                                           or is_room_word(class_words(cls))):
                phrase = phrases.get(role)
                where = "fixed in the map" if name in things.fixed else \
                    "a room" if is_room_word(class_words(cls)) else "fixed: it never moves"
                what = frame.description.rstrip(".").lower() if frame.description else ""
                raise _located(f"{frame.name} needs its {role} to be an object the robot can handle, and "
                               f"{_said(phrase, name)} is {where}" + (f" (the library's {frame.name}: {what})"
                                                                      if what else ""), phrase, text)
            if frame.needs_held(role) and (name in things.fixed or kind_of(things.taxonomy, cls, FIXED) is True):
                phrase = phrases.get(role)
                raise _located(f"{frame.name} needs to hold its {role}, and {_said(phrase, name)} is "
                               f"{'fixed in the map' if name in things.fixed else 'fixed: it never moves'}",
                               phrase, text)
            if kind_of(things.taxonomy, cls, element.type) is False:
                phrase = phrases.get(role)
                raise _located(f"{frame.name} needs its {role} to be {element.type}, and "
                               f"{_said(phrase, name)} is not", phrase, text)


def _to_recipient(frame: Frame, values: dict[str, tuple[str, ...]], things: Things) -> None:
    """A person said where a place was expected ("bring the cup *here*", to the speaker) is who
    receives the thing, when the frame has an unfilled element for a person that one of its actions takes."""
    for element in frame.elements:
        if element.type != "location" or element.role not in values:
            continue
        if not all(v in things.people for v in values[element.role]):
            continue
        acted_on = {a for action in frame.actions for a in action.args}   # Wait's who: no one acted on, "here" stays
        person = next((e.role for e in frame.elements if e.type == "person" and e.role not in values
                       and e.role in acted_on), None)
        if person is not None:
            values[person] = values.pop(element.role)


RETURNING = frozenset({"come", "return"})
"""Verbs of motion toward the speaker: said with no goal ("come back", "return", and "go back"), on a map
the goal is the speaker, who gave the command (by default where the robot started)."""


def _returning(evoked: Evoked) -> bool:
    unit = evoked.lexical_unit.split()
    return bool(unit) and (unit[0] in RETURNING or unit[-1] == "back")


COUNTING = frozenset({"count"})
"""Primitives whose argument is a kind of thing, counted, not one thing."""


def _counted_roles(frame: Frame) -> set[str]:
    """The elements the frame's actions only count: they stand for a kind, not for things."""
    counted = {a for action in frame.actions if action.name in COUNTING for a in action.args}
    other = {a for action in frame.actions if action.name not in COUNTING for a in action.args}
    return counted - other


def commanded_frames(parse: Parse, library: Library, things: Things) -> list[Binding]:
    """The grounded frames a parse commands, in order; a counted element repeats its frame."""
    from seal_cli.language.reference import back_unplaced
    from seal_cli.planning.fetching import brought
    from seal_cli.planning.questions import asks_where_every, asks_whether, looking
    from seal_cli.planning.returning import returned, says_back

    parse = replace(parse, frames=returned(parse.frames, library, parse.text))   # "return it", "take it back"
    parse = replace(parse, frames=brought(parse.frames, library))     # "fetch the remote": bring it here
    earlier: list[dict[str, tuple[str, ...]]] = []
    bindings: list[Binding] = []
    for evoked in parse.frames:
        if _in_a_name(evoked, parse, things):
            continue
        frame = library.frame(evoked.frame)
        if getattr(evoked, "asked", None) and "theme" in frame.roles:     # "is the fridge open?": looked at
            frame = looking(frame)
            evoked = _where_asked(evoked)
        asked = _counted_roles(frame) | ({"theme"} if asks_whether(parse.text, evoked) else set())
        if things.names is not None:    # "go to the bedroom and put it on the bed": the bedroom's bed
            things.names.room_said = _room_said_last(earlier, things)
        grounded = [r for r, p in evoked.elements.items() if not back_unplaced(p) and not _the_house(r, p, things)]
        values: dict[str, tuple[str, ...]] = {}
        for role in sorted(grounded, key=lambda r: r in CARRIED_TO):     # where a thing goes, once the thing is known
            if things.names is not None:
                things.names.robot_at = _robot_at(frame, role, values, bindings, things)
                things.names.guessed = things.names.robot_at is not None and things.names.robot_at[1].endswith(LIKELY)
                things.names.carried = things.class_of(values["theme"][0]) \
                    if role in ("goal", "source") and values.get("theme") and _carried(frame, "theme") else None
            values[role] = _values(_sought_where(evoked, role, things, role in asked), earlier, things, parse.text,
                                   frame.element(role).type, role in asked, _carried(frame, role),
                                   _gone_to(frame, role), not _taken_out_of_a_thing(evoked, things))
        values = {r: values[r] for r in grounded}
        if things.names is not None:
            things.names.robot_at = None
            things.names.carried = None
            things.names.guessed = False
        back_later = False
        backs: dict[str, Phrase | None] = {r: p for r, p in evoked.elements.items() if back_unplaced(p)}
        goal = evoked.elements.get("goal")
        if "goal" in frame.roles and (goal is None or goal.default) and _puts_back(frame, evoked.lexical_unit):
            backs["goal"] = None        # "put back the mug", "put it back": the unit says "back"
        placed_back: set[str] = set()
        for role, phrase in backs.items():     # "put it back", no place taken from said
            if things.map is not None:      # with no map: unsaid, as it always was
                back = _back_to(phrase, values.get("theme", ()), bindings, things, parse.text)
                if back is not None:        # else not taken: back where such a thing is kept (_put_away)
                    values[role], back_later = back
                    placed_back.add(role)
        for role, phrase in evoked.elements.items():     # a default the parse filled: the map's own, if any
            if (phrase.default and things.map is not None and frame.element(role).default is not None
                    and role not in placed_back):
                values[role] = (_default(frame, frame.element(role), evoked, things, parse.text),)
        for role in _counted_roles(frame):      # "count the cups": one Count of the class
            if role in values:
                values[role] = (things.class_of(values[role][0]),)
        if "theme" in values and (asks_whether(parse.text, evoked) or asks_where_every(parse.text, evoked)
                                  and not set(values["theme"]) & things.people):
            # "are there any cups ...?": one is enough; "where are the cups?": one question of the kind (but "where
            # are the residents?" asks where each of the map's people the role names is: a Find each)
            values["theme"] = values["theme"][:1]
        storing = things.map is not None and stores(frame, evoked.lexical_unit)
        for element in frame.elements:      # (a storing unit's goal is where the thing is kept: _put_away)
            if element.role not in values and element.default is not None and not (storing and element.role == "goal"):
                values[element.role] = (_default(frame, element, evoked, things, parse.text),)
        if (things.map is not None and "goal" in frame.roles and "goal" not in values and _returning(evoked)
                and not stores(frame, evoked.lexical_unit) and "recipient" not in values):   # "return it to Nora"
            things.people.add(SPEAKER)          # "go to the kitchen and come back": back to whoever asked
            values["goal"] = (SPEAKER,)
        _to_recipient(frame, values, things)
        _not_one_given(evoked, values, bindings, things)
        if _looked_at_where_it_stands(frame, values, things):       # "check on Ben": no picking Ben up
            frame = looking(frame)
        _check_types(frame, values, evoked.elements, things, parse.text)
        if not placed_back:
            _goal_not_source(evoked, values, things, parse.text)
        kept = {} if placed_back else _put_away(frame, evoked, values, things, parse.text)
        if not kept and not placed_back:
            _unsaid_goal(frame, evoked, values, things, parse.text)
        _fetched_unheard_of(frame, evoked, values, things, parse.text)
        bindings.extend(_where_said_first(frame, evoked, values, library, things, parse.text))
        earlier.append(values)
        roles = [r for r in frame.roles if r in values]
        if len(bindings) + math.prod(len(values[r]) for r in roles) > MAX_COMMANDED:
            raise SealError(f"the command asks for more than {MAX_COMMANDED} frames (counted and joined things "
                            f"multiply: {evoked.frame} alone is {math.prod(len(values[r]) for r in roles):,}); "
                            "split it into smaller commands")
        reading = frame if kept or "goal" in placed_back else on_top(frame, evoked.elements.get("goal"))
        _one_thing_to_several(frame, evoked, values, roles, parse.text)
        for combination in _combinations(frame, evoked, values, roles, things, parse.text):
            said = dict(zip(roles, combination, strict=True))
            if kept:        # "put away the cup and the spoon": each where it is kept
                said["goal"] = kept[said["theme"]]
                things.put_away.append(frame.bind(said))
            if back_later:  # back where the robot will have taken it from
                things.put_back.append(frame.bind(said))
            if "goal" in placed_back:
                things.goal_back.append(frame.bind(said))
            elif "goal" in said and (says_back(evoked, parse.text) or _another_said(evoked, earlier[:-1], things)):
                things.one_away.append(reading.bind(said))      # "back on the bookshelf", "another loaf on it"
                if not says_back(evoked, parse.text):
                    things.one_more.append(reading.bind(said))
            bindings.append(reading.bind(said))
    return bindings


ONE_EACH = frozenset({"a", "an", "one", "another"})
"""Words that open a phrase of one thing of a kind, not a particular one ("*a* biscuit"): handed to several people,
one each."""


CARRIED_TO = frozenset({"goal", "recipient"})
"""The elements a frame carries its theme to ("put the guitar *on the bed*", "give *Ben* the cup")."""

MOVES = frozenset({"navigate", "approach", "lead"})
"""Actions that take the robot to their last argument."""


def _robot_at(frame: Frame, role: str, values: Mapping[str, tuple[str, ...]], bindings: Sequence[Binding],
              things: Things) -> tuple[tuple[float, float], str] | None:
    """Where the robot will be when it sets off for ``role``'s value, where the map says, and how to say it: where it
    takes the thing it carries there, when the robot does not hold it already (where the map places the thing, else
    the source the frame says); else where the frames before leave it (the value the last move of the last of them
    goes to); None: where it starts."""
    theme, source = values.get("theme", ()), values.get("source", ())
    key = class_key(things.held) if things.held else None
    held = key if key in things.classes else next((n for n, c in things.classes.items() if c == key), None)
    if (role in CARRIED_TO and len(theme) == 1 and theme[0] != held
            and any("theme" in a.args and role in a.args for a in frame.actions)):
        what = things.class_of(theme[0]).replace("_", " ")
        if theme[0] in things.points:
            return things.points[theme[0]], f"where it takes the {what}"
        if len(source) == 1 and source[0] in things.points:     # "bring the mug from the kitchen to the sofa"
            return things.points[source[0]], f"{_at(source[0], things)}, where it takes the {what} from"
        if not source and (likely := _likely_place(theme[0], things)) is not None:   # seal run: no thing placed
            return things.points[likely], f"{likely}, where a {what} {LIKELY}"
    for binding in reversed(bindings):
        for action in reversed(binding.frame.actions):
            value = binding.elements.get(action.args[-1]) if action.name in MOVES and action.args else None
            if value in things.points:
                return things.points[value], f"{_at(value, things)}, where the step before leaves it"
    return None


LIKELY = "most likely lies"
"""How :func:`_robot_at` says where it guessed the robot takes a thing from (the prior's likeliest place)."""


def _likely_place(value: str, things: Things) -> str | None:
    """Where the map's prior says a thing of the value's class most likely lies, for a thing the map does not place
    (``seal run`` plans on the map without its objects): the place with the most prior mass, the one the robot
    drives to soonest from where it starts among equals (as its search looks first); None without a prior (e2e27:
    "put the ice cream in the fridge" chose the kitchen's fridge, nearer the start, where ``seal plan`` chose the
    shop's, beside the freezer the ice cream is taken from)."""
    from seal_cli.maps.priors import prior_of
    from seal_cli.maps.reach import drive_lengths
    from seal_cli.planning.keeping import mass, spots_of

    m = things.map
    if m is None:
        return None
    prior = prior_of(m.priors, things.class_of(value))
    spots = [s for s in spots_of(m) if s.name in things.points and mass(prior, s) > 0]
    if not spots:
        return None
    top = max(mass(prior, s) for s in spots)
    best = [s.name for s in spots if mass(prior, s) >= top - 1e-9]
    if len(best) == 1:
        return best[0]
    lengths = drive_lengths(m, m.robot.xy, best)
    return best[min(range(len(best)), key=lambda k: (lengths[k], k))]


def _at(value: str, things: Things) -> str:
    """How a room ("the dining room"), place ("sofa_1") or person ("ben") the robot stands at is said."""
    return f"the {value.replace('_', ' ')}" if value in things.fixed and things.class_of(value) == value else value


def _room_said_last(earlier: Sequence[Mapping[str, tuple[str, ...]]], things: Things) -> str | None:
    """The room the frames before named last, as a value of any element ("go to the bedroom": ``bedroom``)."""
    names = things.names
    for values in reversed(earlier):
        for value in reversed([v for vs in values.values() for v in vs]):
            if names is not None and (referent := names.by_id(value)) is not None and referent.kind == "room":
                return referent.id
    return None


def _not_one_given(evoked: Evoked, values: dict[str, tuple[str, ...]], bindings: Sequence[Binding],
                   things: Things) -> None:
    """One of a kind ("*a* plate") in a frame after an earlier frame of the command handed a thing of that kind to
    someone ("get Ben a plate and Anna as well", "give Ben a cup, then give Anna a cup") is another of the kind:
    the one handed over is that person's now, not to be taken back."""
    phrase = evoked.elements.get("theme")
    said = (phrase.text or "").lower().split() if phrase is not None else []
    if not said or said[0] not in ONE_EACH or len(values.get("theme", ())) != 1:
        return
    given = {b.elements["theme"] for b in bindings if "recipient" in b.elements and "theme" in b.elements}
    theme = values["theme"][0]
    if theme in given and theme in things.classes:
        values["theme"] = (next(t for t in things.instances(theme, len(given) + 1) if t not in given),)


ONE_THING = frozenset({"the", "this", "that", "my", "your", "his", "her", "its", "our", "their", "it"})
"""Words that open a phrase of one particular thing ("*the* cup", "*my* mug", "*it*"): it cannot be handed to
several people at once."""


def _one_thing_to_several(frame: Frame, evoked: Evoked, values: Mapping[str, tuple[str, ...]],
                          roles: Sequence[str], text: str) -> None:
    """Refuse one particular thing handed to several people ("bring Anna and Ben *the cup*"): the robot would give
    it to Anna, take it back and give it to Ben, which nobody means; the command must say whom it goes to, or ask
    for one each ("a cup each", ``ONE_EACH``). A thing said with "'s" ("Sam's mug") is one thing too (words29)."""
    phrase = evoked.elements.get("theme")
    people = values.get("recipient", ())
    if (phrase is None or not phrase.text or phrase.plural or phrase.conjuncts or (phrase.quantity or 1) > 1
            or len(values.get("theme", ())) != 1 or len(people) < 2 or "recipient" not in roles
            or not frame.needs_held("theme")):
        return
    first = phrase.text.lower().split()[0]
    if first not in ONE_THING and not first.endswith("'s"):
        return
    to = evoked.elements["recipient"]
    raise _located(f"{phrase.text!r} is one thing, and {to.text or 'the recipient'!r} are {len(people)} people: the "
                   f"robot cannot hand it to each; say whom it goes to (\"{evoked.lexical_unit} "
                   f"{(to.conjuncts[0].text if to.conjuncts else None) or people[0]} {phrase.text}\"), or ask for "
                   f"one each (\"a {phrase.head} each\")", phrase, text)


def _combinations(frame: Frame, evoked: Evoked, values: Mapping[str, tuple[str, ...]], roles: Sequence[str],
                  things: Things, text: str) -> Iterator[tuple[str, ...]]:
    """Every combination of the frame's values, in role order; except that things handed to several people are
    shared out, each thing to one of them (:func:`_shared_out`), not given to one, taken back and given to the next."""
    people = values.get("recipient", ())
    if len(people) > 1 and "theme" in values and frame.needs_held("theme") and "recipient" in roles:
        for thing, person in _shared_out(evoked, values["theme"], people, things, text):
            yield from itertools.product(*((thing,) if r == "theme" else (person,) if r == "recipient"
                                           else values[r] for r in roles))
        return
    yield from itertools.product(*(values[r] for r in roles))


def _shared_out(evoked: Evoked, themes: Sequence[str], people: Sequence[str], things: Things, text: str
                ) -> list[tuple[str, str]]:
    """Which thing goes to whom when things are handed to several people: one of a kind ("give Edith and Walter *a*
    biscuit", e2e23) or a kind said without a number ("bring *the cups* to Anna and Ben") is one each; a number of
    them ("*four* cups to Anna and Ben") is dealt out in turn, the first to the first person said; things said one
    by one ("the milk and the juice to Anna and Ben") go in the order said, one to each, when there are as many as
    people. Anything else does not share out: refused, as one thing to several people is
    (:func:`_one_thing_to_several`)."""
    phrase = evoked.elements.get("theme")
    said = (phrase.text or "").lower().split() if phrase is not None else []
    if phrase is not None and not phrase.conjuncts and (said[:1] and said[0] in ONE_EACH or phrase.plural
                                                        and phrase.quantity is None):
        return list(zip(things.instances(themes[0], len(people)), people, strict=True))
    if phrase is not None and not phrase.conjuncts and phrase.quantity is not None and len(themes) >= len(people):
        return [(thing, people[k % len(people)]) for k, thing in enumerate(themes)]
    if len(themes) == len(people) and (phrase is None or phrase.conjuncts):
        return list(zip(themes, people, strict=True))
    if len(themes) == 1:
        return [(themes[0], person) for person in people]     # what _one_thing_to_several lets by (a name)
    what = phrase.text if phrase is not None and phrase.text else " and ".join(themes)
    raise _located(f"{what!r} are {len(themes)} things for {len(people)} people: the robot cannot tell who gets "
                   "which; say it thing by thing (\"bring Anna the milk and Ben the juice\")", phrase, text)


def _back_to(phrase: Phrase | None, themes: Sequence[str], bindings: Sequence[Binding], things: Things,
             text: str) -> tuple[tuple[str, ...], bool] | None:
    """Where "back" is when the command said no place the thing was taken from (the parser's ``refers_to``
    gives that one), on a map, if the robot holds the thing by then (it held it as the command started, or
    an earlier frame of the command took it: "take the cup and put it back"): the place the thing lies on,
    and False. When the map does not say where it lies (``seal run``'s robot knows no object until it sees
    it), where such a thing is kept stands in for it, and True: the robot puts it back where it took it
    from (:attr:`Problem.put_back`). None when the command neither took the thing nor holds it ("put the
    mug back"): back where such a thing is kept, as "put away" (:func:`_put_away`). Refused when no place
    stands in. (With no map the element is left unsaid, as before: ALFRED's episodes are planned so.)"""
    from seal_cli.planning.keeping import kept_place, spots_of

    places: dict[str, None] = {}
    later = False
    m = things.map
    for theme in themes:
        takers = [b for b in bindings if _takes(b.frame) and b.elements.get("theme") == theme]
        if not takers and theme in things.taken_from:   # where a command done took it from (e2e30)
            places[things.taken_from[theme]] = None
            continue
        if not takers and theme != (things.name(things.held) if things.held else None):
            return None
        source = next((b.elements["source"] for b in takers if "source" in b.elements), None)   # the first taking
        if phrase is None and source is not None:    # "take the cup from the table and put back": that table
            places[source] = None
            continue
        lay = next((f.args[1] for f in sorted(things.facts, key=str) if f.predicate == "in" and f.args[0] == theme),
                   None) if takers else None      # held from the start: no thing the map places (e2e27)
        if lay is None and m is not None and (not takers or not m.objects):
            # held from the start, or a map that places no thing: back where such a thing is kept
            spot = kept_place(things.taxonomy, m.priors, things.class_of(theme), spots_of(m), near=m.robot.xy)
            lay, later = (spot.name, later or not m.objects) if spot is not None else (None, later)
        if lay is None:
            why = "no place it was taken from is said before it in the command" + (
                "" if m is None else f", and the {_words(m.name)} does not say where {theme} lay")
            raise _located(f"cannot tell where {_back_said(phrase)} is: {why}; say where it was (\"take it from the "
                           "table and put it back\") or where to put it", phrase, text)
        places[lay] = None
    if not places:
        raise _located(f"cannot tell where {_back_said(phrase)} is: nothing is put back", phrase, text)
    return tuple(places), later


def _fetched_unheard_of(frame: Frame, evoked: Evoked, values: Mapping[str, tuple[str, ...]], things: Things,
                        text: str) -> None:
    """Refuse, on a map, a thing to take up (a frame that picks it up or needs it held: Pick, Bring, Give, Place) or to
    act on where it is (:func:`_goes_to_theme`: Stir, Open) of
    a kind the map knows nothing of — no prior, object or place of it, nor of a kind of it (:attr:`Things.kinds`),
    and not what the robot holds — where the command says it (e2e27: "bring me the hammer" on a house with none).
    ``seal run``'s robot would not search for it (its perception knows the map's classes only,
    :meth:`seal_cli.sim.agent.Agent.absent_from_map`), yet it drove to whatever the frames before asked first; the
    plan was made and warned about. Said with what the map has of its kind ("a cup" on a map with mugs), the user's
    next word. A thing looked for (Find, Count, a question) is still answered "not found" by the run; one said to be
    somewhere ("a beer from the fridge") is looked for there; one put away or back is refused by :func:`_put_away`."""
    m = things.map
    phrase = evoked.elements.get("theme")
    if (m is None or not things.all_kinds or phrase is None or phrase.default or "theme" not in values
            or not (_takes(frame) or _goes_to_theme(frame)) or evoked.asked or values.keys() & {"source", "ground"}
            or stores(frame, evoked.lexical_unit)):
        return
    held = class_key(things.held) if things.held else None
    taxonomy = things.taxonomy
    for value in values["theme"]:
        cls = things.class_of(value)
        if (value in things.fixed or value in things.people or cls in ("person", held) or cls in things.kinds
                or any(taxonomy.is_a(k, cls) is True for k in things.kinds)):
            continue
        kin = taxonomy.kin(cls)
        alike = sorted(k for k in things.kinds if kin is not None and k in kin[1])
        has = f"; of its kind ({kin[0]}) it has: {', '.join(_words(k) for k in alike)}" if kin and alike else ""
        has += m.spelt_like(cls, things.kinds, taxonomy.known_classes)
        raise _located(f"the {m.said} knows no {_words(cls)} (no prior, object or place of one), so the "
                       f"robot would not find one to {' '.join(words_of(evoked.lexical_unit))}{has}; say something "
                       "the house has", phrase, text)


def _goes_to_theme(frame: Frame) -> bool:
    """Whether the frame drives to its theme to act on it where it is (Stir, Slice, Open, ToggleOn: "stir my tea" on
    a house that knows no tea picked up the spoon, then gave up; lead, stop 39), unlike a frame that searches
    somewhere for it (Find, Count: their question is answered "not found")."""
    return any(a.name == "navigate" and a.args == ("theme",) for a in frame.actions)


def _takes(frame: Frame) -> bool:
    """Whether the frame takes its theme up: leaves it held (Pick), or needs it held to start (Bring: "take the key
    to the hall and then return it" took the key from where it lay, though the Bring puts it down in the hall)."""
    return frame.gets_held("theme") or frame.needs_held("theme")


def _back_said(phrase: Phrase | None) -> str:
    return repr(phrase.text) if phrase is not None else "'back'"


def _puts_back(frame: Frame, unit: str) -> bool:
    """Whether the evoked unit is a storing unit that says "back" ("put back"): the thing goes back where
    it was taken from, when the command took it, else where it is kept."""
    return stores(frame, unit) and words_of(unit)[-1:] == ("back",)


def stores(frame: Frame, unit: str) -> bool:
    """Whether the frame's lexical unit ``unit`` (as evoked) is one of its storing units (``stores: true``
    in the library: "put away", "store")."""
    said = " ".join(words_of(unit))
    return any(u.stores and u.text == said for u in frame.lexical_units)


def _put_away(frame: Frame, evoked: Evoked, values: Mapping[str, tuple[str, ...]], things: Things,
              text: str) -> dict[str, str]:
    """The goal of each theme of a Place said with a storing verb and no goal ("put away the cup",
    "store the apple"), or put "back" when the command neither took it nor holds it ("put the mug back"),
    on a map: where the map's prior says such a thing is kept, other than where it
    lies (:func:`seal_cli.planning.keeping.kept_place`); refused, naming what the map does know where to
    keep, when no place fits. A goal the parser guessed from its learned table (``default``: "put away"
    goes into a side table or a cabinet, whatever the thing) gives way to the map's prior of the thing's
    class, and stands when the map has none. Empty for any other frame."""
    from seal_cli.language.reference import back_unplaced
    from seal_cli.maps.priors import prior_of
    from seal_cli.planning.keeping import kept_place, spots_of

    m = things.map
    said = evoked.elements.get("goal")
    guessed = said is not None and bool(said.default)     # the parser's learned guess of a goal, not words
    if (m is None or "goal" not in frame.roles or ("goal" in values and not guessed) or "theme" not in values
            or not (stores(frame, evoked.lexical_unit) or said is not None and back_unplaced(said))):
        return {}
    back = said is not None and back_unplaced(said) or _puts_back(frame, evoked.lexical_unit)
    spots = spots_of(m)
    kept: dict[str, str] = {}
    for theme in values["theme"]:
        cls = things.class_of(theme)
        lies = next((f.args[1] for f in things.facts if f.predicate == "in" and f.args[0] == theme), None)
        spot = kept_place(things.taxonomy, m.priors, cls, spots, lies=lies, near=m.robot.xy)
        if spot is None and guessed and not back:    # no prior of the class: the guess stands (what "put away"
            return {}                                  # goes in), but it is not where the thing goes *back*
        if spot is None:
            known = sorted(class_key(c) for c in m.priors)
            targets = " or ".join(located(t, m) for t in prior_of(m.priors, cls))
            but = f" but {lies}, where it is" if lies else ""
            house = _words(m.name)
            why = (f"the {house} keeps a {cls} {targets}, and there is no table, shelf or cupboard there{but}"
                   if targets else f"the {house} has no prior of where a {cls} is kept")
            listed = f" (it knows where to keep {', '.join(known)})" if known else ""
            verb = "put back" if back else " ".join(words_of(evoked.lexical_unit))
            raise _located(f"cannot tell where to {verb} {_said(evoked.elements.get('theme'), theme)}: {why}"
                           f"{listed}; say where to put it", evoked.elements.get("theme"), text)
        kept[theme] = spot.name
    return kept


def _unsaid_goal(frame: Frame, evoked: Evoked, values: Mapping[str, tuple[str, ...]], things: Things,
                 text: str) -> None:
    """Refuse, on a map, a frame that puts its theme at a goal nobody said: the parser's guess from the verb's
    statistics alone ("put the hammer": people who leave out where mostly meant a side table, whatever the
    thing), which is no place the command or the thing says. "Put it where?", naming a place such a thing is
    kept (or one of the map's places) as an example. A storing verb ("put away") or "back" chooses its own goal
    (:func:`_put_away`, :func:`_back_to`); a goal the command or a previous clause says is never refused, nor a
    Place the parser adds as an inferred step (ALFRED's scope, said as such)."""
    from seal_cli.planning.keeping import kept_place, spots_of

    m = things.map
    goal = evoked.elements.get("goal")
    if (m is None or goal is None or not goal.default or goal.text is not None or evoked.inferred is not None
            or "theme" not in values or not any(a.name == "place" and "goal" in a.args for a in frame.actions)
            or stores(frame, evoked.lexical_unit)):
        return
    theme = values["theme"][0]
    lies = next((f.args[1] for f in things.facts if f.predicate == "in" and f.args[0] == theme), None)
    spots = [s for s in spots_of(m) if s.name != lies]       # an example of somewhere else to put it
    spot = kept_place(things.taxonomy, m.priors, things.class_of(theme), spots, near=m.robot.xy)
    example = spot.name if spot is not None else next((s.name for s in spots), None)
    verb = " ".join(words_of(evoked.lexical_unit))
    phrase = evoked.elements.get("theme")
    said = phrase.text if phrase is not None and phrase.text else f"the {_words(things.class_of(theme))}"
    where = m.place(example) if example else None
    on = "in" if where is not None and where.openable else "on"
    hint = f" (\"{verb} the {_words(things.class_of(theme))} {on} the {_words(where.cls)}\")" if where else ""
    raise _located(f"{verb} {said} where? the command says no place to {verb} it; say where{hint}",
                   evoked.elements.get("theme"), text)


def _words(cls: str) -> str:
    """A class as words ("side_table": side table)."""
    return " ".join(class_words(cls)) or cls


def _carried(frame: Frame, role: str) -> bool:
    """Whether the frame carries its ``role``: takes it into the hand (Pick) or puts it down out of the
    hand (Place, Bring, Give: ``holding`` needed, ``not holding`` after). A frame that needs the thing held
    only to work on it and keeps holding it (LookAt, Heat, Clean) does not carry it: what it acts on is
    refused as a fixed thing the map lacks as Find and ToggleOn refuse it ("look at the tv" on a map with
    only a tv stand, as "find the tv"), not searched for as something one carries ("bring me the tv")."""
    drops = any(f.predicate == "holding" and f.args == (role,) and f.negated for f in frame.postconditions)
    return frame.gets_held(role) or frame.needs_held(role) and drops


def _in_a_name(evoked: Evoked, parse: Parse, things: Things) -> bool:
    """Whether a frame was evoked by a word of a map thing's name, said inside another frame's
    element ("go to the *open* office" on a map with an ``open_office``): the word names the room,
    it asks for nothing to be opened."""
    if things.names is None:
        return False
    unit = words_of(evoked.lexical_unit)
    for other in parse.frames:
        for phrase in other.elements.values() if other is not evoked else ():
            span, text = phrase.span, phrase.text
            if span is None or text is None or not (span[0] <= evoked.span[0] and evoked.span[1] <= span[1]):
                continue
            try:
                referent = things.names.ground(text, "thing", ("room", "place"))
            except SealError:
                continue
            if referent is not None and any(_contains(name, unit) for name in referent.names):
                return True
    return False


HOUSE_WORDS = (("home",), ("the", "house"))
"""A ground that is the whole house ("is mum *home*?", "is anyone in the house?")."""


def _looked_at_where_it_stands(frame: Frame, values: Mapping[str, tuple[str, ...]], things: Things) -> bool:
    """Whether a frame that finds out about its theme (``questions.FOUND_OUT_BY``: LookAt) but needs it held
    (ALFRED's looking at a thing in a lamp's light) is to look at it where it stands instead: a person ("check
    on Ben" planned Pick(theme=ben)) or a thing fixed in the house ("check the fridge", "keep an eye on the
    stove"), which no robot picks up. A thing it can carry is still taken into the hand ("examine the cup")."""
    from seal_cli.planning.questions import FOUND_OUT_BY

    themes = values.get("theme", ())
    if frame.name not in FOUND_OUT_BY or not frame.needs_held("theme") or not themes:
        return False
    return all(v in things.people or v in things.fixed or kind_of(things.taxonomy, things.class_of(v), FIXED) is True
               or things.taxonomy.is_a(things.class_of(v), "person") is True for v in themes)


def _the_house(role: str, phrase: Phrase, things: Things) -> bool:
    """Whether an element says where to look and names the whole house (:data:`HOUSE_WORDS`): on a map it
    bounds nothing, so it is left unsaid and the search is the house's ("find out if mum is home": Find mum,
    whether, anywhere), rather than a place the map lacks ("the apartment has no home")."""
    return (role == "ground" and things.map is not None and not phrase.conjuncts and phrase.refers_to is None
            and tuple(w.lower() for w in (phrase.text or phrase.head).split()) in HOUSE_WORDS
            and (things.names is None or things.names.ground(phrase.text or phrase.head, "location",
                                                              ("room", "place")) is None))


def _sought_where(evoked: Evoked, role: str, things: Things, asked: bool = False) -> Phrase:
    """The phrase of a role, with the frame's ground said after a theme that says no room of its own:
    "find the sofa in the living room" seeks the living room's sofa (``sofa_2``), not the map's first;
    a movable thing is not a map referent, so its phrase grounds as before. A theme only ``asked`` of (counted,
    or a yes/no question's) is not refused where the room has none of it: "how many tables are in the foyer?"
    has the answer none, which the run gives by the map."""
    phrase = evoked.elements[role]
    ground = evoked.elements.get("ground")
    if (role != "theme" or ground is None or not ground.text or not phrase.text or phrase.conjuncts
            or phrase.refers_to is not None or things.names is None or things.names.where_said(phrase.text)):
        return phrase
    there = replace(phrase, text=f"{phrase.text} in {ground.text}")
    try:
        found = things.names.ground(there.text or "", "thing", ("place",))
    except SealError:
        return phrase if asked else there   # "find the sofa in the kitchen": refused, naming the sofas there are
    return there if found is not None else phrase


def _where_said_first(frame: Frame, evoked: Evoked, values: Mapping[str, tuple[str, ...]], library: Library,
                      things: Things, text: str) -> list[Binding]:
    """The frames that take a theme from where its phrase says it is, for a frame with no element to
    carry that: "wash the cup in the bedroom" picks the cup up there first (Pick with the room as its
    source; with the place, when a place is said: "put the mug from the sink on the table", e2e24), "switch on
    the lamp in the study" finds the lamp there first (Find with the room or place as its ground). A where the
    map lacks is refused ("the townhouse has no living room"), never dropped. Nothing for a frame with a source
    or a ground of its own, which the parser fills."""
    names = things.names
    phrase = evoked.elements.get("theme")
    if (names is None or phrase is None or not phrase.text or phrase.conjuncts or "theme" not in values
            or {"source", "ground"} & set(frame.roles)):
        return []
    where = where_words(phrase.text)
    if not where or any(words_of(other.text or "") == where for role, other in evoked.elements.items()
                        if role != "theme"):   # the where is the frame's own goal (a stack: "... in the cup in the X")
        return []
    said = " ".join(where)
    try:
        there = names.ground(said, "location", ("room", "place"))
    except SealError as wrong:
        raise _located(wrong.message, phrase, text) from None
    if there is None:
        refused = names.refusal(said, None)
        if refused is not None:
            raise _located(refused.message, phrase, text)
        return []                           # "the cup of tea", "the book with the red cover": no where
    room = there.id if there.kind == "room" else there.room
    held = frame.needs_held("theme")
    first: list[Binding] = []
    for value in values["theme"]:
        if names.by_id(value) is not None or value in things.people:     # a map thing: it stays where it is
            continue
        if held and room is not None:     # from the place said, when one is ("the mug from the sink", e2e24)
            first.append(library.frame("Pick").bind({"theme": value, "source": there.id}))
        elif not held:
            first.append(library.frame("Find").bind({"theme": value, "ground": there.id}))
    return first


def _contains(words: tuple[str, ...], part: tuple[str, ...]) -> bool:
    return bool(part) and any(words[i:i + len(part)] == part for i in range(len(words) - len(part) + 1))


def build_problem(parse: Parse, library: Library, *, holding: str | None = None, done: Iterable[Parse] = (),
                  map: Map | None = None, vocabulary: Any = None, every: Mapping[str, int] | None = None) -> Problem:
    """The commanded frames of a parse and the state they start from (see the module's docstring); ``every``:
    how many things of a class "all the ..." asks for, where the map does not place them (:attr:`Things.every`)."""
    from seal_cli.planning.same import told_too

    if map is not None:             # "tell Ben that breakfast is ready and Anna as well": Anna is told too
        parse = told_too(parse, {p.name.lower() for p in map.people})
    things = Things(library.taxonomy, map)
    things.every = dict(every or {})
    things.hold(holding)            # before the frames: "put it in the sink" calls what the robot holds
    if vocabulary is not None:      # the names a vocabulary gives its classes name them too
        things.synonyms = {class_key(c): tuple(n) for c, n in zip(vocabulary.classes, vocabulary.synonyms,
                                                                   strict=True)}
        if map is not None and getattr(vocabulary, "house", False):    # the map's classes, objects' too
            things.kinds |= {class_key(c) for c in vocabulary.classes}
            things.all_kinds = bool(vocabulary.classes)     # a bare map (no place, object or prior) may hold anything
    for frame in library:
        for element in frame.elements:
            if element.default is not None:
                things.name(element.default)
    done_frames = carry_out_done(done, library, things)
    commanded = commanded_frames(parse, library, things)
    _the_ones_said_where(commanded, things)
    the_ones_not_there(commanded, things)
    the_ones_from_elsewhere(commanded, things)
    the_nearest_ones(commanded, things)
    among = the_goals_said_among(commanded, things)
    state = things.state()
    _nothing_to_hand(parse, commanded, state)
    commanded = _the_thing_held(commanded, state)
    warnings = (*unknown_to_map(commanded, things), *fewer_than_asked(commanded, things),
                *chosen_among(commanded, things), *things.all_there) if map else ()
    return Problem(parse.text, tuple(commanded), state, warnings,
                   tuple(b for b in things.put_away if b in commanded),
                   tuple(b for b in things.put_back if b in commanded), dict(things.called),
                   {b: places for b, places in among.items() if b in commanded},
                   one_away=tuple(b for b in things.one_away if b in commanded),
                   nearest=_nearest_from_the_thing(commanded, things), done=tuple(done_frames))


def _nearest_from_the_thing(commanded: Sequence[Binding], things: Things) -> dict[Binding, tuple[str, ...]]:
    """The frames whose goal is the nearest of several places from where the robot takes the thing it carries there
    (:attr:`Problem.nearest`), with those places: not one put away or back (chosen again by their own rules)."""
    names = things.names
    if names is None:
        return {}
    own = {*things.put_away, *things.put_back, *things.one_away}
    return {b: names.nearest_of[goal] for b in commanded
            if (goal := b.elements.get("goal")) in names.nearest_of and b not in own and b.elements.get("theme")
            and any("theme" in a.args and "goal" in a.args for a in b.frame.actions)}


def carry_out_done(done: Iterable[Parse], library: Library, things: Things) -> list[Binding]:
    """The commands already done (``--done``), in order, grounded and carried out on ``things``: each is context for
    the ones after it ("find Ben" → "him", "pick up the cup" → "it") and leaves the world as it left it (what the
    next one, and the command, are grounded on: the book put on the table is fetched from the table). Their frames,
    in order (:attr:`Problem.done`)."""
    frames: list[Binding] = []
    for earlier in done:
        bindings = commanded_frames(earlier, library, things)
        _the_ones_said_where(bindings, things)  # "take the book from bookshelf 2 ...": that one, as a command takes it
        frames.extend(bindings)
        things.carry_out(earlier.text, bindings)
        things.named_before = [*things.named_before, *_people_named(bindings, things)]
        things.handled_before = [*things.handled_before, *_handled(bindings, things)]
        things.done_said = True
    return frames


def moved_by(binding: Binding) -> tuple[str, ...]:
    """The things a grounded frame moves: each its postconditions put in something, in the robot's hand or in
    someone's (``has(me, cup)``)."""
    moved = [f.args[0] for f in binding.postconditions if not f.negated and len(f.args) == 2 and f.predicate == "in"
             or f.predicate == "holding"]
    moved += [f.args[1] for f in binding.postconditions if not f.negated and f.predicate == "has" and len(f.args) == 2]
    return tuple(dict.fromkeys(moved))


def _elsewhere(fact: Fact, thing: str, binding: Binding) -> bool:
    """Whether a fact puts ``thing`` somewhere the frame did not: where it lay before the frame moved it."""
    return (fact.predicate in ("in", "on") and fact.args[:1] == (thing,) or fact.predicate == "has"
            and fact.args[1:] == (thing,)) and fact not in binding.postconditions


def _the_thing_held(commanded: Sequence[Binding], state: State) -> list[Binding]:
    """The frames with a frame that hands over or puts down a thing it does not name ("give me", "hand it over to
    Owen" said with no thing) given the thing the robot holds as the command starts (after ``--done``), when no frame
    before it takes another up: "give me" holding a mug gives the mug. Before, the Give had no theme, so nothing was
    handed over and the run put the mug down on the nearest table (lead, e2e29)."""
    held = next((f.args[0] for f in state.facts if f.predicate == "holding" and not f.negated and f.args), None)
    frames = list(commanded)
    if held is not None:
        for number, binding in _handing_over_unnamed(commanded):
            frames[number] = binding.frame.bind({**binding.elements, "theme": held})
    return frames


def _handing_over_unnamed(commanded: Sequence[Binding]) -> Iterator[tuple[int, Binding]]:
    """The frames (with their index) that hand over or put down a thing held without naming it ("give me"), before
    any frame takes a thing up: what :func:`_the_thing_held` gives the thing held and :func:`_nothing_to_hand` refuses
    when the hand is empty."""
    for number, binding in enumerate(commanded):
        if binding.frame.gets_held():
            return
        if binding.frame.needs_held("theme") and "theme" in binding.frame.roles and "theme" not in binding.elements:
            yield number, binding


def _nothing_to_hand(parse: Parse, commanded: Sequence[Binding], state: State) -> None:
    """Refuse a frame that hands over or puts down a thing it does not name ("give me", "gimme") when the robot holds
    nothing as the command starts (after ``--done``) and no frame before it takes anything up: there is nothing to
    give. Before, the plan was a Give of nothing and ``seal run`` drove to the speaker and said it was done (lead,
    stop 39). Holding something, the frame is left as it was."""
    if Fact("hand_empty") not in state:
        return
    for _, binding in _handing_over_unnamed(commanded):
        evoked = next((e for e in parse.frames if e.frame == binding.frame.name and "theme" not in e.elements), None)
        verb = " ".join(words_of(evoked.lexical_unit)) if evoked is not None else binding.frame.name.lower()
        raise _located(f"{verb} what? the command says no thing to {verb}, and the robot holds nothing; say what "
                       f"(\"{verb} me the cup\")", evoked, parse.text)


def _handled(bindings: Sequence[Binding], things: Things) -> list[str]:
    """The things the frames act on (their themes, not people), in order: what a later "it" can stand for."""
    return [v for b in bindings for r, v in b.values if r == "theme" and v not in things.people and v != SPEAKER]


def _people_named(bindings: Sequence[Binding], things: Things) -> list[str]:
    """The people the frames name, in order (not the speaker): whom a later "him" or "her" can stand for."""
    return [v for b in bindings for _, v in b.values if v in things.people and v != SPEAKER]


def _the_ones_said_where(commanded: list[Binding], things: Things) -> None:
    """A thing of a kind the map has several of, said with where it is ("the mug in the green room", "the cup in
    the cupboard": the frame's source), is the one there (e2e24): the command's name of it (``mug``, the map's
    first mug) trades names with the map's thing of that class in that room or place, when the first is not there
    and the other is named by no frame of the command. Without it the plan took the first mug, in the kitchen's
    sink, for the one to take to the kitchen and planned nothing ("already in the kitchen")."""
    if things.map is None:
        return
    used = {v for b in commanded for _, v in b.values}
    settled: set[str] = set()
    for binding in commanded:
        theme, source = binding.elements.get("theme"), binding.elements.get("source")
        if (theme is None or source is None or theme in settled or theme in things.fixed
                or theme not in things.classes or theme in things.people):
            continue
        settled.add(theme)
        if things.lies_in(theme, source):
            continue
        cls = things.classes[theme]
        if (holding := _source_among(binding, source, cls, used, things)) is not None:
            index = commanded.index(binding)
            commanded[index] = binding = binding.frame.bind({**binding.elements, "source": holding})
            source = holding
            if things.lies_in(theme, source):
                continue
        there = next((n for n, c in things.classes.items() if c == cls and n != theme and n not in used
                      and n not in things.fixed and things.lies_in(n, source)), None)
        if there is not None:
            things.swap(theme, there)
        elif (elsewhere := sorted({p for n, c in things.classes.items() if c == cls and n not in things.fixed
                                   and (p := _lies_on(n, things)) is not None})):
            words, m = cls.replace("_", " "), things.map
            said = located(source, m) if m.room_id(source) is not None else f"in or on {source}"
            things.all_there.append(f"the {_words(m.name)} places no {words} {said} (it has "
                                    f"one in or on {', '.join(elsewhere)}): seal run looks there first, as the command "
                                    f"says, says it found none, then takes the nearest other {words}")


def _source_among(binding: Binding, source: str, cls: str, used: set[str], things: Things) -> str | None:
    """Of several places of one class a source said did not tell apart ("take the towel *on the bench* to the
    changing room", three benches), the one where the map has a thing of the theme's class, when grounding chose one
    with none (:meth:`MapNames._one_of <seal_cli.planning.grounding.MapNames._one_of>`: the nearest, bench_1, with
    no towel): the nearest of those that hold one by drive from where the robot starts, its choice said (e2e33: the
    plan said the towel was in the changing room already, and the run looked on the empty bench first). None: the
    source chosen holds one, none does, or the source was told apart by the command."""
    from seal_cli.maps.reach import drive_lengths

    m, names = things.map, things.names
    if m is None or names is None or source not in names.chosen or not things.is_place(source):
        return None
    kind = things.class_of(source)
    among = [class_key(p.name) for p in m.places if class_key(p.cls) == kind]

    def holds(place: str) -> bool:
        return any(c == cls and n not in things.fixed and things.lies_in(n, place) for n, c in things.classes.items())

    if holds(source) or not (holders := [p for p in among if holds(p)]):
        return None
    lengths = drive_lengths(m, m.robot.xy, holders)
    one = holders[min(range(len(holders)), key=lambda k: (lengths[k], k))]
    said = names.chosen.pop(source).split(": chose", 1)[0]
    names.chosen[one] = (f"{said}: chose {one}, the one the map has a {cls.replace('_', ' ')} on or in; say its room "
                         f"or its number ('{one}') to choose")
    names.nearest_of.pop(source, None)
    return one


def the_goals_said_among(commanded: list[Binding], things: Things) -> dict[Binding, tuple[str, ...]]:
    """The frames whose goal grounding chose among several places of one class the command did not tell apart ("put the
    milk in the fridge", a fridge in the shop and one in the kitchen), with those places; where the map has a thing of
    the kind in one of them already, the frame's goal is that place and the command's name of the thing trades names
    with it, so the plan says it is so already (:func:`seal_cli.planning.lying.goal_among`, e2e28: the plan moved the
    kitchen's milk to the shop's fridge, each fridge holding a milk). Not for a thing a done command moved: "put it in
    the cupboard" after `--done 'take the ball to the classroom'` is that ball, not the one left in the hall's cupboard
    (e2e32: the plan said it was so already). A goal said "back" is the place the thing came from, of those
    (:func:`_came_from`). ``commanded`` is changed in place."""
    from seal_cli.planning.lying import goal_among

    m = things.map
    if m is None or things.names is None:
        return {}
    used = {v for b in commanded for _, v in b.values}
    key = class_key(things.held) if things.held else None
    found: dict[Binding, tuple[str, ...]] = {}
    settled: set[str] = set()
    for index, binding in enumerate(commanded):
        theme, goal = binding.elements.get("theme"), binding.elements.get("goal")
        if theme is None or theme in settled:
            continue
        settled.add(theme)
        if (goal is None or goal not in things.names.chosen or not things.is_place(goal) or theme in things.fixed
                or theme in things.people or theme not in things.classes):
            continue
        among = tuple(class_key(p.name) for p in m.places if class_key(p.cls) == things.class_of(goal))
        cls = things.classes[theme]
        ones = [theme, *(n for n, c in things.classes.items() if c == cls and n != theme and n not in used
                         and n not in things.fixed)]

        def lying(place: str, ones: list[str] = ones) -> str | None:
            return next((n for n in ones if things.lies_in(n, place)), None)

        back = binding in things.one_away and not any(things.lies_in(theme, p) for p in among)
        if back and (origin := _came_from(theme, among, commanded[:index], things)) not in (None, goal):
            again = binding.frame.bind({**binding.elements, "goal": origin})    # "back in the cupboard": its own
            commanded[index] = again
            things.one_away[things.one_away.index(binding)] = again
            continue
        moved = theme in things.taken_from      # the one a done command moved ("put it in the cupboard"): no other
        place = None if back or moved else goal_among(binding, theme, cls, held=key, among=among, lies_in=lying)

        if len(among) > 1 and not back:     # "back on the bookshelf": one not on any (the_ones_not_there)
            found[binding] = among
        if back and binding in things.one_more:     # "another loaf on the counter": the counter one lies on
            ones_there = [p for p in among if any(things.lies_in(n, p) for n, c in things.classes.items() if c == cls)]
            place = goal if goal in ones_there or not ones_there else ones_there[0]
            if place != goal:
                commanded[index] = binding.frame.bind({**binding.elements, "goal": place})
                things.one_away.append(commanded[index])
            continue
        if place is None:
            continue
        if (one := lying(place)) is not None and one != theme:
            things.swap(theme, one)
        if place != goal:
            again = binding.frame.bind({**binding.elements, "goal": place})
            commanded[index] = again
            found[again] = found.pop(binding)
    return found


def _came_from(theme: str, among: Sequence[str], before: Sequence[Binding], things: Things) -> str | None:
    """Of the ``among`` places a goal said "back" to did not tell apart ("put it back in the cupboard", four
    cupboards), the one the thing came from: the source of the last frame before that took it up, else where a
    command done took it from (:attr:`Things.taken_from`); None when it came from none of them (e2e32: after `--done
    'take the ball to the classroom'`, the ball went "back" into the classroom's cupboard, the nearest, not the hall's
    it was taken from)."""
    sources = [b.elements.get("source") for b in before if b.elements.get("theme") == theme and _takes(b.frame)]
    origin = next((s for s in reversed(sources) if s is not None), None) or things.taken_from.get(theme)
    return origin if origin in among else None


def the_ones_not_there(commanded: Sequence[Binding], things: Things) -> None:
    """A thing put on or in a place where one of its kind lies already, on a map with another of the kind elsewhere, is
    that other one (e2e27): "put the book back on the shelf", a book on the shelf and one on the nightstand, asks for
    the nightstand's; nobody asks for what is so already (a room said as the goal is left as it was: one may lie on
    its floor or any place of it, and "it is in the kitchen already" is the likelier reading). The command's name of
    it (``book``, the map's first book) trades names with the first other thing of its class that lies somewhere
    else, is named by no frame of the command and is not what the robot holds. Only for the first frame that names
    the thing, by :func:`seal_cli.planning.lying.another_meant`, the rule ``seal run``'s robot asks of what it sees
    (:meth:`seal_cli.sim.agent.Agent.already_so`): the frame takes the thing up, the robot holds none of its kind,
    the goal is the map's one place of its class (e2e28: the planner lacked this), the command names one thing of
    its kind. Without it the plan was empty ("Place(theme=book, goal=bookshelf_1) is not done: ... holds
    already")."""
    from seal_cli.planning.lying import another_meant, several_said

    m = things.map
    if m is None:
        return
    used = {v for b in commanded for _, v in b.values}
    key = class_key(things.held) if things.held else None
    several = several_said(commanded, things.class_of)
    settled: set[str] = set()
    for binding in commanded:
        theme, goal = binding.elements.get("theme"), binding.elements.get("goal")
        if theme is None or theme in settled:
            continue
        settled.add(theme)
        if goal is None or not things.is_place(goal) or theme in things.fixed or theme in things.people \
                or theme not in things.classes:
            continue
        cls = things.classes[theme]
        like_goal = [class_key(p.name) for p in m.places if class_key(p.cls) == things.class_of(goal)]
        back = binding in things.one_away and len(like_goal) > 1    # "back on the bookshelf": on none now (e2e30)
        among = like_goal if back else [goal]
        if not any(things.lies_in(theme, p) for p in among) and not back:
            continue
        if not another_meant(binding, theme, cls, held=key, places_like_goal=1 if back else len(like_goal),
                             several=several):
            continue
        kept = binding in things.put_away       # its goal: where it is kept, read off where it lies
        others = [n for n, c in things.classes.items() if c == cls and (n == theme or n not in used) and (
                  n != theme or back) and n not in things.fixed and n in things.points
                  and not any(things.lies_in(n, p) for p in among) and not (kept and _kept_already(n, things))]
        if back and len(others) > 1:        # one a command done moved first ("back"), else the nearest by drive
            others = _nearest_first(others, binding, commanded, things)
        if others:
            if others[0] != theme:
                things.swap(theme, others[0])
        elif back:
            things.all_there.append(f"every {cls.replace('_', ' ')} the {_words(m.name)} has lies on or in a "
                                    f"{things.class_of(goal).replace('_', ' ')} already: none to put back")


def the_ones_from_elsewhere(commanded: Sequence[Binding], things: Things) -> None:
    """A thing taken to a room where it lies shut away in a place ("take the mug to the galley", the command's mug in
    the galley's cupboard) is another of its kind from outside the room, when the map has one the command names no
    other way: moving a thing from a cupboard to the counter of its own room is no taking it there. None elsewhere,
    it is that one, taken out (lead, e2e29; ``seal run``'s robot reads it alike, :meth:`Agent._shut_in_goal_room
    <seal_cli.sim.agent.Agent._shut_in_goal_room>`)."""
    m = things.map
    if m is None:
        return
    used = {v for b in commanded for _, v in b.values}
    for binding in commanded:
        theme, goal = binding.elements.get("theme"), binding.elements.get("goal")
        if (theme is None or goal is None or m.room_id(goal) is None or theme not in things.classes
                or not binding.frame.needs_held("theme") or class_key(things.held or "") == things.classes[theme]):
            continue
        lies = _lies_on(theme, things)
        if lies is None or lies not in things.closable or things.rooms.get(lies) != goal:
            continue
        other = next((n for n, c in things.classes.items() if c == things.classes[theme] and n != theme
                      and n not in used and n not in things.fixed and (p := _lies_on(n, things)) is not None
                      and things.rooms.get(p) != goal), None)
        if other is not None:
            things.swap(theme, other)


def _kept_already(name: str, things: Things) -> bool:
    """Whether a thing lies where such a thing is kept (:func:`seal_cli.planning.keeping.kept_place` of where it
    lies is that place): put away or back already. "Put the milk back", a milk in each of the corner shop's fridges,
    asks for neither: the shop's milk is back already, and putting the kitchen's into the shop's fridge was no
    reading of it (hostile26; the run said "needs no doing")."""
    from seal_cli.planning.keeping import kept_place, spots_of

    lies = _lies_on(name, things)
    m = things.map
    if lies is None or m is None:
        return False
    spot = kept_place(things.taxonomy, m.priors, things.classes[name], spots_of(m), lies=lies, near=m.robot.xy)
    return spot is not None and spot.name == lies


def the_nearest_ones(commanded: Sequence[Binding], things: Things) -> None:
    """A thing to take of a kind the map has several of, lying in places of one class, that the command does not tell
    apart ("get me the milk", a fridge in the shop and one in the kitchen) is the one in the place the robot drives
    to soonest from where it will be (where the frames before leave it, else where it starts), as ``seal run``'s
    robot takes it: it knows no thing before it sees it, its prior is the same at places of one class, so it looks in
    the nearest first (e2e27: the plan took the shop's milk, the map's first, the run the kitchen's, 4 m nearer). The
    command's name trades names with that one. Left as the map lists them where the places differ in class: the
    run weighs a prior against a drive, which the plan cannot tell (docs/planning.md). Only the first frame naming
    the thing, when it takes it up and says no source, and the thing is not what the robot holds."""
    from seal_cli.maps.reach import drive_lengths

    m = things.map
    if m is None:
        return
    used = {v for b in commanded for _, v in b.values}
    key = class_key(things.held) if things.held else None
    settled: set[str] = set()
    for index, binding in enumerate(commanded):
        theme = binding.elements.get("theme")
        if theme is None or theme in settled:
            continue
        settled.add(theme)
        if ("source" in binding.elements or not _takes(binding.frame) or theme in things.fixed
                or theme in things.people or theme not in things.classes or things.classes[theme] == key):
            continue
        cls = things.classes[theme]
        lying = {n: _lies_on(n, things) for n, c in things.classes.items()
                 if c == cls and n not in things.fixed and (n == theme or n not in used)}
        places = {p for p in lying.values() if p is not None}
        if len(lying) < 2 or None in lying.values() or len(places) < 2 \
                or _put_where_it_lies(theme, lying[theme], commanded[index:], things):
            continue
        start = _robot_at(binding.frame, "source", {}, commanded[:index], things)
        order = sorted(places)
        lengths = dict(zip(order, drive_lengths(m, start[0] if start else m.robot.xy, order), strict=True))
        if len({things.class_of(p) for p in places}) != 1:
            goals = {things.class_of(g) for b in commanded if b.elements.get("theme") == theme
                     for g in (b.elements.get("goal"),) if g is not None}
            kept = _most_kept(cls, {n: p for n, p in lying.items() if things.class_of(p or "") not in goals},
                              m, things) if not any(p in things.closable for p in places) else None
            nearest = min(lying, key=lambda n: (lengths[lying[n] or ""], n != theme))
            if kept is not None and kept != theme and kept == nearest:    # the prior and the drive agree
                things.swap(theme, kept)
            elif (in_sight := _open_nearer(theme, lying, lengths, things)) is not None:
                things.swap(theme, in_sight)
            continue
        best = min(lying, key=lambda n: (lengths[lying[n] or ""], n != theme))
        if best != theme and lengths[lying[best] or ""] < lengths[lying[theme] or ""]:
            things.swap(theme, best)


def _open_nearer(theme: str, lying: Mapping[str, str | None], lengths: Mapping[str, float],
                 things: Things) -> str | None:
    """Of things of one kind in places of different classes, the one in an open place nearer by drive than the shut
    place the command's thing lies in (e2e30: "go to the office and then bring me a mug", a mug on the office desk and
    one in the bakehouse's shut cupboard): ``seal run``'s robot sees it first and takes it; None when the thing does not
    lie shut away or no open place is nearer."""
    def shut(place: str | None) -> bool:
        return place is not None and place in things.closable and Fact("open", (place,)) not in things.facts

    if not shut(lying[theme]):
        return None
    open_ones = [n for n, p in lying.items() if p is not None and not shut(p)]
    best = min(open_ones, key=lambda n: lengths[lying[n] or ""], default=None)
    return best if best is not None and lengths[lying[best] or ""] < lengths[lying[theme] or ""] else None


def _most_kept(cls: str, lying: Mapping[str, str | None], m: Map, things: Things) -> str | None:
    """Of things of one kind lying in places of different classes, the one in the place the map's prior keeps that
    kind at most (a towel on the towel rail, 0.8, not the one left on the deck's bench, 0.1), as ``seal run``'s robot
    looks there first (the plan takes it when it is also the nearest: the run weighs the prior against the drive);
    None when no one place's prior is the highest. Only among open places, and not at the goal (a shut cupboard's mug
    is not the one the robot sees first; one where the command puts it is not the one meant)."""
    if not lying:
        return None
    prior = m.priors.get(cls, {})
    weight = {n: prior.get(things.class_of(p or ""), 0.0) for n, p in lying.items()}
    best = max(weight.values())
    top = [n for n, w in weight.items() if w == best]
    return top[0] if best > 0 and len(top) == 1 else None


def _put_where_it_lies(theme: str, lies: str | None, commanded: Sequence[Binding], things: Things) -> bool:
    """Whether a frame of the command puts ``theme`` where it lies, its goal read off where that one lies (put
    back, put away where it is kept already: "put the milk back", "take the milk and put it back"), so that one is
    the thing meant. Trading its name for a nearer one's moved the other thing there (hostile26: on the corner shop,
    a milk in each fridge, "put the milk back" took the kitchen's milk and put it in the shop's fridge). A goal the
    command said is no such reading: "put the milk in the fridge in the shop" still takes the kitchen's milk there
    (lead, stop 39: with any goal counted, it said the shop's milk "holds already")."""
    return any(b.elements.get("theme") == theme and b.elements.get("goal") == lies
               and (b in things.put_away or b in things.goal_back) for b in commanded)


def _nearest_first(names: Sequence[str], binding: Binding, commanded: Sequence[Binding], things: Things) -> list[str]:
    """Things of a kind, those a command done moved first (:attr:`Things.taken_from`), then each by how far the robot
    drives to where it lies from where the frames before ``binding`` leave it (else where it starts)."""
    from seal_cli.maps.reach import drive_lengths

    m = things.map
    assert m is not None
    before = list(commanded[:commanded.index(binding)]) if binding in commanded else []
    start = _robot_at(binding.frame, "source", {}, before, things)
    places = {n: _lies_on(n, things) for n in names}
    said = sorted({p for p in places.values() if p is not None})
    lengths = dict(zip(said, drive_lengths(m, start[0] if start else m.robot.xy, said), strict=True))
    return sorted(names, key=lambda n: (n not in things.taken_from, lengths.get(places[n] or "", math.inf)))


def _lies_on(name: str, things: Things) -> str | None:
    """The place of the map a thing lies in or on, by the map (None: on a room's floor, or not placed)."""
    return next((f.args[1] for f in things.facts if f.predicate == "in" and f.args[0] == name
                 and things.is_place(f.args[1])), None)


def chosen_among(commanded: Sequence[Binding], things: Things) -> list[str]:
    """Which place the plan chose, and why, for each place it names that was one of several the command did not
    tell apart (:meth:`MapNames._one_of <seal_cli.planning.grounding.MapNames._one_of>`): said, not asked."""
    if things.names is None:
        return []
    named = dict.fromkeys(v for b in commanded for _, v in b.values)
    return [note for id_, note in things.names.chosen.items() if id_ in named]


def fewer_than_asked(commanded: Sequence[Binding], things: Things) -> list[str]:
    """A warning for each kind the frames take more things of than the map places ("bring me two books" where the map
    has one book): said before the run drives, which looks for the others only where the map's prior keeps that kind
    (lead, e2e29: the guesthouse's one book took 87 m to give up on the second)."""
    from seal_cli.language.morphology import plural_of

    m = things.map
    if m is None:
        return []
    asked: dict[str, set[str]] = {}
    for binding in commanded:
        value = binding.elements.get("theme")
        if value is not None and value not in things.people and things.names is not None \
                and things.names.by_id(value) is None:
            asked.setdefault(things.class_of(value), set()).add(value)
    held = things.class_of(things.name(things.held)) if things.held else None
    warnings = []
    for cls, values in asked.items():
        placed = [o for o in m.objects if class_key(o.cls) == cls]
        have = len(placed) + (held == cls)
        if not placed or len(values) <= have:
            continue
        where = ", ".join(dict.fromkeys(f"on {o.inside}" if o.inside else "on the floor" for o in placed))
        others = "the other" if len(values) - have == 1 else "the others"
        kept = ", ".join(m.priors.get(cls, {})) or "anywhere"
        name = cls.replace("_", " ") if have == 1 else plural_of(cls.replace("_", " "))
        warnings.append(f"the {m.said} places {have} {name} ({where}) and the command asks for "
                        f"{len(values)}: seal run looks for {others} where the map's prior keeps them ({kept}) "
                        "and says so if it finds none")
    return warnings


def unknown_to_map(commanded: Sequence[Binding], things: Things) -> list[str]:
    """The warnings of a plan on a map: each class a frame needs that no prior, object or place of
    the map names, and each person nobody placed (the robot will have to search for them)."""
    m = things.map
    if m is None:
        return []
    known = set(m.priors) | {o.cls for o in m.objects} | {p.cls for p in m.places}
    if things.held:                 # what the robot holds as it starts is not searched for ("give me", holding a mug)
        known.add(things.class_of(things.name(things.held)))
    placed = {p.key for p in m.people} | {SPEAKER}
    warnings: dict[str, None] = {}
    unknown: set[str] = set()
    for binding in commanded:
        for role, value in binding.values:
            category = binding.frame.element(role).type
            if category in ("message", "question") or value in things.fixed:
                continue
            cls = things.class_of(value)
            if value in things.people or cls == "person":
                if value not in placed and value != "person":     # "a person", "anyone": whoever is there
                    called = f"is the {value.replace('_', ' ')} (no person has that role)" \
                        if value in things.roles_said else f"is called {things.called.get(value, value)}"
                    warnings.setdefault(f"nobody on the map {m.said} {called}: seal run will search "
                                        "the whole house for them", None)
            elif cls not in known and cls not in unknown:    # said once, where it is first looked for
                # where the command says it is ("a mug from the kitchen"): looked for there, and only there
                ground = next((binding.elements[r] for r in ("ground", "source") if r != role and
                               binding.elements.get(r)), None)
                kinds = any(things.taxonomy.is_a(k, cls) is True for k in known)    # "a drink": a kind of it
                where = f"look for it in {ground}" if ground else \
                    "search the whole house for it" if kinds or m.robot.holding == cls else \
                    "say so without searching the house"
                unknown.add(cls)
                warnings.setdefault(f"the map {m.said} knows nothing of {cls} (no prior, object or place names "
                                    f"it): seal run will {where}", None)
    return list(warnings)


def problem_of_text(text: str, library: Library, *, holding: str | None = None, done: Sequence[str] = (),
                    map: Map | None = None, vocabulary: Any = None) -> Problem:
    """Parse the command and the ``done`` commands (with the map's vocabulary unless one is
    given), then :func:`build_problem`."""
    if vocabulary is None and map is not None:
        from seal_cli.language.grounding import vocabulary_of_map

        vocabulary = vocabulary_of_map(map)
    with naming_done(done, text):
        parses = [parse_to_plan(t, library, vocabulary) for t in (*done, text)]
        return build_problem(parses[-1], library, holding=holding, done=parses[:-1], map=map,
                             vocabulary=vocabulary if hasattr(vocabulary, "synonyms") else None)


@contextlib.contextmanager
def naming_done(done: Sequence[str], text: str, option: str = "--done") -> Iterator[None]:
    """Say which ``--done`` command a refusal is about: a SealError located in one of them (not in the
    command itself) gets ``in --done '...':`` before its message, so "column 7" points into that one. ``option``:
    the option the commands were given by (``localize --task``, hostile30: "column 1: unexpected character" named
    no option)."""
    from seal_cli.language.tokens import printable
    from seal_cli.planning.grounding import spoken

    def said(command: str, line: str) -> bool:    # as parsed, or as shown (control characters as spaces: hostile26)
        return any(form.startswith(line) for form in (spoken(command), printable(spoken(command)), command))

    try:
        yield
    except SealError as exc:
        line = exc.source_line      # the text, or its start (a command too long is shown cut)
        which = None if line is None or said(text, line) or exc.message.startswith("in --") else \
            next((t for t in done if said(t, line)), None)
        if which is None:
            raise
        shown = which if len(which) <= 60 else which[:57] + "..."
        raise SealError(f"in {option} {shown!r}: {exc.message}", exc.where, source_line=line,
                        hint=exc.hint) from None


def parse_to_plan(text: str, library: Library, vocabulary: Any = None) -> Parse:
    """A command as the planner reads it: parsed as said aloud (:func:`~seal_cli.planning.grounding.spoken`), where
    a statement beside it says the thing is made part of it (:func:`~seal_cli.planning.told.told_where`),
    each question told to someone found out first (:func:`~seal_cli.planning.questions.told_first`:
    "tell Ben where the spoon is" finds the spoon, then tells Ben where it is), and a question of whether any
    thing at all is somewhere asked as what is there (:func:`~seal_cli.planning.questions.anything_there`)."""
    from seal_cli.language.parser import parse_command
    from seal_cli.planning.grounding import spoken, without_floating_each
    from seal_cli.planning.questions import anything_there, told_first
    from seal_cli.planning.same import refuse_the_same
    from seal_cli.planning.told import told_where

    refuse_the_same(text)
    parsed = told_where(parse_command(without_floating_each(spoken(text)), library, vocabulary), library)
    return anything_there(told_first(parsed, lambda said: parse_command(said, library, vocabulary)))


def _person_words(phrase: Phrase) -> str:
    """The words a phrase names its person by: its text, or its head when the parser found the person said before
    ("Sam is in the kitchen, find *him*", "... find *that person*": Sam, not "Him")."""
    text = phrase.text or phrase.head
    return text if phrase.head.lower() in text.lower().split() else phrase.head


def _where_asked(evoked: Any) -> Any:
    """A state question whose place follows the state ("is the light on *in the office*?"): its theme grounded as
    the thing in that place ("the light in the office": the office's desk lamp, not the lounge's floor lamp), as
    when the place is said with it. Unchanged when no place follows, or the theme says its own."""
    from seal_cli.language.english import LOCATED
    from seal_cli.planning.questions import STATE_WORDS

    theme = evoked.elements.get("theme")
    words = str(evoked.asked).split()
    if theme is None or not theme.text or theme.refers_to is not None or where_words(theme.text):
        return evoked
    for i, word in enumerate(words[1:-1], 1):
        if word.lower() in LOCATED and words[i - 1].lower() in STATE_WORDS:
            said = f"{theme.text} {' '.join(words[i:])}"
            return replace(evoked, elements={**evoked.elements, "theme": replace(theme, stands_for=said)})
    return evoked


def _place_words(phrase: Phrase) -> str:
    """The words a phrase names its place by: its text, or its head when a word said names a place by another
    name (the parser's "see Helen *out*": the exit) or a bare "there" stands for a place a statement named ("Sam
    wants to go to the kitchen, lead him *there*": its head is the kitchen), or "it" stands for a thing a condition
    or statement named ("the coffee machine is on, turn *it* off": its words, with where they say it is)."""
    if phrase.kind == "place" and phrase.head and phrase.text and phrase.head.lower() not in phrase.text.lower():
        return phrase.head
    if phrase.text and phrase.text.lower() in THERE and phrase.head and phrase.head.lower() not in THERE:
        return phrase.head
    if phrase.stands_for:   # "if the coffee machine is on, turn *it* off": what the condition said
        return phrase.stands_for
    return phrase.text or ""
