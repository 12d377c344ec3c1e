"""A robot that is told what to do, searches for what it needs, and does it: the SeFM agent.

An :class:`Agent` runs one command in a :class:`Scene` (the simulated :class:`~seal_cli.sim.world.World`,
and the map the robot is given: free space, places, priors, sensor). The loop is the paper's:

1. **plan**: the commanded frames and the robot's state give an ordered list of grounded frames
   (:mod:`seal_cli.planning.plan`); the semantic state (:class:`~seal_cli.planning.state.State`) is the
   planner's, and executing a frame applies its postconditions to it;
2. for each frame, run its primitive actions in the world. ``navigate(x)`` needs an *instance*
   of ``x`` the robot knows: places are on the map; things must have been seen. While none is
   known, the **search policy** proposes a :class:`View` — a pose from which to look at where
   the frame is believed to be (or a closed receptacle to open and look into) — the robot drives
   there, looking as it goes, and the beliefs are updated with what it sees;
3. when an action fails (a receptacle is closed, a thing out of reach) the robot deals with
   what the world told it, and **replans** from the state it is in; it **gives up** after a
   budget of steps or metres.

The policies differ only in where they look (:class:`~seal_cli.sim.policies.base.Policy`): the SeFM
agent (:class:`~seal_cli.sim.policies.sefm.SeFMPolicy`) looks where its frame beliefs say; the others are
registered beside it in :data:`seal_cli.sim.policies.POLICIES`.
Everything else — execution, perception, bookkeeping of path
length — is shared, so that the comparison measures the search and nothing else.

What happened is reported to observers (``observe=callable(Record)``) and kept in
:attr:`Agent.records`: the narration of ``seal run`` and the Rerun recording hang off it.
"""

from __future__ import annotations

import itertools
import math
import re
from collections.abc import Callable, Iterable, Mapping, Sequence
from dataclasses import dataclass, field, replace
from datetime import datetime, timedelta
from typing import Any

import numpy as np

from seal_cli.errors import SealError
from seal_cli.frames.library import Library
from seal_cli.frames.model import Action, Binding, Fact
from seal_cli.frames.said import said_words, shown
from seal_cli.frames.taxonomy import class_key
from seal_cli.language.morphology import counted, plural_of
from seal_cli.maps.model import SPEAKER, Map
from seal_cli.maps.navigation import ROBOT_RADIUS, Cell, Grid
from seal_cli.maps.prepositions import located
from seal_cli.planning.grounding import kind_of, spoken
from seal_cli.planning.lying import another_meant, goal_among, several_said
from seal_cli.planning.plan import already_so, open_already
from seal_cli.planning.questions import STATE_WORDS, Question
from seal_cli.planning.state import State
from seal_cli.sim.policies.base import Policy
from seal_cli.sim.relaying import SENDER, asked_for, relayed
from seal_cli.sim.unsearched import Unsearched
from seal_cli.sim.world import HAND, PERSON, Detection, Item, Outcome, Reason, World

__all__ = ["Agent", "Budget", "Known", "Policy", "Record", "Result", "Scene", "View", "scene_from_map"]


@dataclass
class Scene:
    """A world to act in, and what the robot is told about it."""

    world: World
    map: Map
    grid: Grid
    vocabulary: tuple[str, ...] = ()
    """The classes present, which the robot's perception knows (empty: any)."""
    title: str = ""
    open_floor: Mapping[str, float] = field(default_factory=dict)
    """Per class, the share of its prior that lies on no place at all: anywhere on the open floor
    (ALFRED-2D: a baseball bat 0.65, a box 0.19, learnt on the train split). The map's priors name
    places only; this share is what a search of the floor may find (empty: none)."""


@dataclass(frozen=True)
class Budget:
    """When the robot gives up: after ``steps`` world steps (drives and actions) or ``metres`` driven."""

    steps: int = 400
    metres: float = 200.0
    replans: int = 8


@dataclass(frozen=True)
class View:
    """A pose to go to and look from; ``open`` names a closed receptacle to open there first."""

    cell: Cell
    look_at: tuple[float, float]
    open: str | None = None
    why: str = ""


@dataclass(frozen=True)
class Record:
    """One line of what the robot did: ``kind`` is warn, plan, frame, search, go, look, see, act,
    answer, fail, replan, done or give_up."""

    kind: str
    text: str
    step: int
    path_m: float
    pose: tuple[float, float, float]
    data: dict[str, Any] = field(default_factory=dict, compare=False)


@dataclass
class Result:
    """How a run ended."""

    completed: bool
    """Every frame of the plan was executed (whether the *task* is done is the judge's business)."""
    reason: str
    path_m: float
    steps: int
    plan: list[str]
    executed: list[str]
    records: list[Record]
    answer: str | None = None
    """What a question asked, found out: where a thing is, how many there are."""
    warnings: list[str] = field(default_factory=list)
    """What the map did not know of the command (classes it has no prior of, people nobody placed)."""
    why: Reason = Reason.OK
    """Why the run stopped short, for a program (``reason`` says it for people)."""


@dataclass
class Known:
    """What the robot knows about one item: a place from the map, or a thing it has seen."""

    id: str
    cls: str
    at: tuple[float, float]
    movable: bool
    openable: bool = False
    receptacle: bool = True
    access: tuple[tuple[float, float], ...] = ()
    parent: str | None = None
    """The place a thing was seen in or on."""


class Agent:
    """One robot, one command, one policy; see the module docstring."""

    def __init__(self, scene: Scene, library: Library, policy: Policy, *, rng: np.random.Generator,
                 budget: Budget | None = None, planner: Callable[..., list[Binding]] | None = None,
                 observers: Sequence[Callable[[Record], None]] = (), look_every: float = 1.0,
                 classes: Mapping[str, str] | None = None, sweeper: Callable[[], Any] | None = None,
                 questions: Mapping[Binding, Question] | None = None, clock: datetime | None = None,
                 search_end: float | None = None,
                 put_away: Mapping[Binding, Callable[[str | None], str | None]] | None = None,
                 put_back: Iterable[Binding] = (), told: Mapping[str, Sequence[str]] | None = None,
                 names: Mapping[str, str] | None = None, heed_sources: bool = False,
                 absent_said: bool = False, among: Mapping[Binding, Sequence[str]] | None = None,
                 one_away: Iterable[Binding] = (), nearest: Mapping[Binding, Sequence[str]] | None = None) -> None:
        self.scene = scene
        self.world = scene.world
        self.grid = scene.grid
        self.library = library
        self.policy = policy
        self.rng = rng
        self.budget = budget or Budget()
        self.planner = planner or default_planner
        self.observers = list(observers)
        self.look_every = look_every
        self.sweeper = sweeper
        """Makes the search that looks all over the house (a coverage policy), for a kind of thing the
        robot's perception does not know (``seal run``: the map names what it knows, a command may
        name more) and to look all over a room before counting; None (a benchmark whose scene lists
        every class there is): such a thing is refused at once, and counting counts what is in view."""
        self.records: list[Record] = []
        self.put_away: dict[Binding, Callable[[str | None], str | None]] = dict(put_away or {})
        """Each commanded frame whose goal "put away" chose, and where it would put the thing, as a function
        of where the thing lay (:func:`seal_cli.planning.keeping.where_kept`): the command was grounded
        before the robot saw the thing, so it chooses again once it knows."""
        self.put_back: set[Binding] = set(put_back)
        """Those of :attr:`put_away` that put the thing back where the robot took it from ("take the cup and
        put it back"), not where such a thing is kept."""
        self.picked_from: dict[str, str | None] = {}
        """Where each thing the robot picked up lay (the last time it picked it up)."""
        self.framed: dict[str, Binding] = {}
        """Each step the run began, by its plan's name (a record's ``frame`` data): :meth:`said_at_end` names it."""
        self.taken_from: dict[str, str | None] = {}
        """Where each thing lay when the robot first picked it up: where "put it back" puts it ("take the key to the
        hall and then return it": the table, not the hall it was picked up from again)."""
        self.started = {i.id: i.at for i in self.world.items.values() if i.movable or i.key == "person"}
        """Where each thing and each person was as the run began (the picture draws what moved from there)."""
        """Where each thing was as the run started (the picture shows where the moved ones came from)."""
        self.known: dict[str, Known] = {}
        self.unreachable: set[str] = set()
        self.opened: set[str] = set()
        """Receptacles the robot has opened (and so looked into)."""
        self.ajar: set[str] = set()
        """Receptacles the robot opened itself to look into, take from or put into, not yet closed again."""
        self.left_open: set[str] = {i.id for i in self.world.items.values() if i.openable and i.is_open}
        """Receptacles open as the command found them or as a frame opened them, not only to look in: what is
        in them is where it lies (an apple in a fridge the robot opened to look for it is still to be brought
        out, as the planner says)."""
        self.placed: set[str] = set()
        """Things the robot has put where a frame wanted them: not to be taken away again."""
        self.chosen: dict[str, str] = {}
        """The instance chosen for each name a frame uses, across frames (open *this* cabinet, put into it)."""
        self.there_already: dict[Binding, str] = {}
        """Frames that put a thing where the robot saw one of its kind lying already, before the command took one
        ("put the book back on the shelf", a book on the shelf): another one is meant, so the robot looks for it;
        what it would have said ("book_1 is on bookshelf_1 already") is said only if it finds no other (e2e27)."""
        self.among: dict[Binding, tuple[str, ...]] = {b: tuple(p) for b, p in (among or {}).items()}
        """The commanded frames whose goal was one of several places of a class the command did not tell apart, with
        those places (:attr:`seal_cli.planning.problem.Problem.among`): one of the kind seen lying in any of them makes
        the frame so already ("put the milk in the fridge", two fridges, a milk in each), as the planner says."""
        self.one_away: set[Binding] = set(one_away)
        """The commanded frames that put a thing "back" on or in a place they name (:attr:`seal_cli.planning.problem.
        Problem.one_away`): one of the kind seen on or in any place of the goal's class is not the one meant (e2e30)."""
        self.nearest_of: dict[Binding, tuple[str, ...]] = {b: tuple(p) for b, p in (nearest or {}).items()}
        """The commanded frames whose goal is the nearest of several places from where the thing is taken, with those
        places (:attr:`seal_cli.planning.problem.Problem.nearest`): chosen again once the robot has taken it
        (:meth:`_nearest_again`)."""
        self.not_meant: dict[str, set[str]] = {}
        """The instances a name does not stand for, by name: the one seen where a frame puts its kind already."""
        self.shut_there: dict[Binding, tuple[str, set[str]]] = {}
        """Frames that take a thing to a room where the robot saw one of its kind shut away in a place (a mug in the
        galley's cupboard, for "take the mug to the galley"), with the thing's name and those seen there: one from
        elsewhere is meant, as the planner reads it; found none, the robot takes one of those out (lead, e2e29)."""
        self.several: set[str] = set()
        """The classes the command names several things of ("all the cups", "two plates"): each is one of them."""
        self.looks: list[tuple[float, float, float]] = []
        self.inspected: set[str] = set()
        """Places the robot has looked into or onto from within reach: it has seen all they hold."""
        self.told: dict[str, tuple[str, ...]] = {class_key(k): tuple(v) for k, v in (told or {}).items()}
        """Where the command's words say each thing is, by class ("a beer from the fridge": beer → fridge_1;
        :func:`~seal_cli.sefm.relations.said_where`): looked at first (the search's beliefs are conditioned on
        it; the whole-house search for what nothing else places starts there)."""
        self.heed_sources = heed_sources
        self.absent_said = absent_said
        """Whether a kind of thing the map names none of is said absent at once (:meth:`absent_from_map`; ``seal
        run``) rather than searched for in the whole house (the sweep, which a scene built by hand exercises)."""
        """Whether to read :attr:`told` off the first plan it makes (``seal run``: the robot knows no object, so a
        frame's source can only be the speaker's word); off where a frame's source is the grounded truth (the
        benchmarks' scenes), and where :attr:`told` is given."""
        self.missed: set[str] = set()
        """Places the command said a thing was in, looked into without finding it (said once)."""
        self.unfound: set[str] = set()
        """Kinds of thing the command said the one sought is in or on, searched for without finding one."""
        self.missed_rooms: set[tuple[str, str]] = set()
        """(class, room) for each room the command said a thing was to be taken from, looked all over without
        finding one: the search widens to the rest of the house (:meth:`source_room` no longer bounds it)."""
        self.names: dict[str, str] = {class_key(p.name): p.name for p in getattr(scene.map, "people", ())}
        self.names |= {class_key(k): v for k, v in (names or {}).items() if class_key(k) != SPEAKER}
        """How each person is said, by id: as the map writes them, or the command names them ("goes to Raj")."""
        keys = sorted({f for k in self.names for f in (k, k.replace("_", " "))}, key=len, reverse=True)
        self._names_re = re.compile(r"(?<![\w=])(?:" + "|".join(map(re.escape, keys)) + r")(?![\w=(])") \
            if keys else None
        self.classes = {class_key(k): class_key(v) for k, v in (classes or {}).items()}
        """The class of each thing a command names that is not a class itself (``apple_2``)."""
        self.state = State()
        self.steps: list[Binding] = []
        """The plan being executed; ``steps[index]`` is the frame at hand."""
        self.index = 0
        self.todo: list[Binding] = []
        """The commanded frames not yet executed."""
        self.answers: list[str] = []
        """What the robot found out for a question (Find: where; Count: how many)."""
        self.sweep: Any = None
        """What is left of the whole-house search (rooms, then the rest of the house); None before it."""
        self.swept: list[tuple[str, Outcome]] = []
        self.detail = False
        """Whether what the robot does now is a detail of a line already said (a survey's drives and looks)."""
        """The whole-house search for what no prior or detector knows of, started when needed."""
        self.questions: dict[Binding, Question] = dict(questions or {})
        self.kept: set[str] = set()
        """The classes whose house-wide count looks only where the map's priors keep them ("all the plates":
        :meth:`_count_where_kept`, e2e24); a count asked ("how many plates are there?") looks all over."""
        """What each commanded frame asks (:mod:`seal_cli.planning.questions`); a Find, Count or Tell
        that asks nothing is a plain command."""
        self.clock = clock
        """The time the run starts at (what "tell Anna the time" tells, plus the driving since, at
        :data:`ROBOT_SPEED`); None: the computer's clock when the robot tells it."""
        self.search_end = search_end
        """End a search for a thing of a kind the map has a prior of once less than this share of the
        prior is left unsearched (:mod:`seal_cli.sim.unsearched`); None: search within the budget only."""
        self.unsearched: dict[str, Unsearched] = {}
        """Per class the robot searches for, the prior mass it has not searched yet (with ``search_end``)."""
        self._learn_places(policy.oracle)

    # -- knowledge ---------------------------------------------------------------------------

    def _learn_places(self, oracle: bool) -> None:
        """Places are on the map; an oracle also knows where every thing is."""
        for item in self.world.items.values():
            if not item.movable or oracle:
                self.known[item.id] = self._known(item)

    def remember(self, ids: Iterable[str]) -> None:
        """Know where these things of the world lie as the run starts, as though seen: the ones the commands already
        done moved (``seal run --done``), where the robot itself left them."""
        for i in ids:
            if i in self.world.items:
                self.known[i] = self._known(self.world.items[i])

    def _known(self, item: Item) -> Known:
        parent = item.parent if item.parent in self.world.items and not self.world.items[item.parent].movable else None
        return Known(item.id, item.key, item.at, item.movable, item.openable, item.receptacle, item.access, parent)

    def instances(self, cls: str) -> list[Known]:
        key = class_key(cls)
        return [k for k in self.known.values() if k.cls == key]

    def present(self, key: str) -> list[str]:
        """The things of a class key the robot knows of that are still in the world (none it gave away or used up)."""
        return [k.id for k in self.known.values() if k.cls == key and k.id in self.world.items]

    def held(self) -> Item | None:
        return self.world.items[self.world.robot.holding] if self.world.robot.holding else None

    # -- records -----------------------------------------------------------------------------

    def named(self, text: str) -> str:
        """Text with each person said as :attr:`names` says ("handed drill_1 to Raj"); a frame's element value
        (``recipient=raj``) stays an id."""
        if self._names_re is None:
            return text
        return self._names_re.sub(lambda m: self.names[class_key(m.group(0))], text)

    def say(self, kind: str, text: str, **data: Any) -> None:
        if kind not in ("plan", "frame"):
            text = self.named(text)
        if self.detail and kind in DETAIL_KINDS:
            data["detail"] = True       # a step of a survey said a line for: kept, not narrated
        if kind in WORDED_KINDS:
            text = as_words(text)
        robot = self.world.robot
        record = Record(kind, text, self.world.step, robot.path_m, robot.pose, data)
        self.records.append(record)
        for observer in self.observers:
            observer(record)

    # -- budget ------------------------------------------------------------------------------

    def exhausted(self) -> str | None:
        robot = self.world.robot
        if self.world.step >= self.budget.steps:
            return f"out of steps ({self.budget.steps})"
        if robot.path_m >= self.budget.metres - 1e-6:  # a leg cut at the budget ends on it, to rounding
            return f"out of path budget ({self.budget.metres:g} m)"
        return None

    # -- the run -----------------------------------------------------------------------------

    @property
    def remaining(self) -> list[Binding]:
        return self.steps[self.index:]

    def initial_state(self) -> State:
        """The semantic state the robot starts from: its hand, and which receptacles are open."""
        held = self.held()
        facts = {Fact("holding", (held.key,))} if held else {Fact("hand_empty")}
        closable = {i.key for i in self.world.items.values() if i.openable}
        facts |= {Fact("open", (i.key,)) for i in self.world.items.values() if i.openable and i.is_open}
        return State.of(facts, self.library.taxonomy, closable=closable, classes=self.classes)

    def already_so(self, binding: Binding) -> str | None:
        """What the robot sees that makes a frame pointless, by the planner's rule
        (:func:`seal_cli.planning.plan.already_so`) asked of what it has seen: "umbrella_1 is in the
        hallway already" when the frame would only bring a thing into a room where one it knows of lies
        free (not held, not shut in), or put it in or on a place where one it knows of is; None otherwise."""
        if binding in self.put_back:        # back where it was taken from: the robot puts it there
            return None
        if (shut := self._open_already(binding)) is not None:     # "close the fridge", shut (e2e23)
            return shut
        if binding in self.put_away:        # put away: already so only where such a thing is kept
            return self._kept_already(binding)
        if binding in self.one_away and self._back_from_elsewhere(binding):     # one on no bookshelf (e2e30)
            return None
        results = [f for f in binding.postconditions if not f.negated and f.predicate == "in" and len(f.args) == 2]
        on = any(a.name == "place_on" for a in binding.actions)
        rooms = {class_key(p.name): class_key(p.room) for p in self.scene.map.places if p.room}
        facts = set(self.state.facts)
        seen: dict[str, str] = {}
        source = binding.elements.get("source")
        for fact in results:
            thing, where = fact.args
            room, place = self.room(where), self._place_of(where)
            free = [k.id for k in self.known.values() if k.cls == self.class_of(thing) and k.movable
                    and k.id in self.world.items and not self.world.held_chain(k.id)
                    and not self._chosen_as_other(k.id, thing) and k.id not in self.not_meant.get(thing, ())]
            if source is not None and thing == binding.elements.get("theme"):   # "the towel from the dining table"
                elsewhere = [i for i in free if not self._from(i, source)]
                free = [i for i in free if i not in elsewhere]
                # one lying where it is to go already is not the one to take there (it would move nothing)
                if at_goal := [i for i in elsewhere if self._from(i, where)]:
                    self.not_meant.setdefault(thing, set()).update(at_goal)
            if room is not None:      # on no place there (the room's floor), or in or on a place there
                there = [i for i in free if bool(room.contains([self.world.position(i)])[0])]
                loose = [i for i in there if self._place_of(self.world.items[i].parent or "") is None]
                if loose:
                    rooms[thing], there = class_key(room.name), loose
                else:                 # in a place only if the state says the place is open (as seal plan)
                    away = [i for i in there if self._parent(i).id not in self.left_open and self._parent(i).openable]
                    there = [i for i in there if i not in away]
                    facts |= {Fact("in", (thing, class_key(self._parent(i).id))) for i in there}
                    if not there and away:
                        self._shut_in_goal_room(binding, thing, room, away)
            elif place is not None:       # on top of a hollow place ("put it on the sideboard") is not in it
                places = self._goals_among(binding, thing, where, free, on)
                there = [i for i in free if self.world.items[i].parent in places and
                         (self.world.items[i].on_top == on or not self.world.hollow(self._parent(i)))]
                if there:
                    facts.add(Fact("in", (thing, where)))
            else:
                continue
            if there:
                seen[thing] = there[0]
            else:
                rooms.pop(thing, None)
        made = already_so(binding, replace(self.state, facts=frozenset(facts), rooms=rooms))
        if made is None or made.args[0] not in seen:
            return None
        thing, where = made.args
        room = self.room(where)
        if room is not None:
            said = f"{seen[thing]} is {located(room.name, self.scene.map)} already"
        else:
            place = self.world.items[seen[thing]].parent or where
            said = f"{seen[thing]} is {'in' if self.world.hollow(self.world.items[place]) else 'on'} {place} already"
        if room is None and self._another_meant(binding, thing, where):    # one lies there: another is meant
            self.there_already[binding] = said
            self.not_meant.setdefault(thing, set()).add(seen[thing])
            self.say("search", f"{said}: looks for another {spoken(self.class_of(thing))} to put there",
                     target=thing)
            return None
        self.chosen.setdefault(class_key(thing), seen[thing])   # that one is this name's: not cup_2's too (e2e23)
        return said

    def _from(self, thing: str, source: str) -> bool:
        """Whether a thing lies where a frame says it is taken from (on or in the place, or in the room): "take the
        towel from the dining table to the bathroom" means the dining table's towel, so the one on the bathroom's
        rail does not make it so already (lead, stop 42: the guesthouse's run said "towel_1 is in the bathroom
        already, so Bring(..., source=dining_table_1) needs no doing" and did nothing)."""
        parent = self.world.items[thing].parent
        return (parent is not None and self._lies_within(parent, source)) or self._lies_within(thing, source)

    def _back_from_elsewhere(self, binding: Binding) -> bool:
        """A frame puts a thing "back" on or in a place it names ("put the book back on the bookshelf"), or "another"
        ("put another loaf on the counter"): the things of its kind the robot sees on or in a place of the goal's class
        are not the one meant; it says so and looks on (as :func:`seal_cli.planning.problem.the_ones_not_there` reads
        the map). False where the goal is the one place of its class (the other-one rule holds there, e2e27)."""
        thing, goal = binding.elements.get("theme"), self.world.items.get(binding.elements.get("goal") or "")
        if thing is None or goal is None or sum(1 for k in self.instances(goal.key) if not k.movable) < 2:
            return False        # one place of its class: the other-one rule (:meth:`_another_meant`)
        if class_key(thing) in self.chosen:
            return True
        kind = self.class_of(thing)
        there = {k.id for k in self.known.values() if k.cls == kind and k.movable and k.id in self.world.items
                 and (parent := self.world.items[k.id].parent) in self.world.items
                 and self.world.items[parent].cls == goal.cls}
        new = sorted(there - self.not_meant.get(thing, set()))
        if new:
            self.not_meant.setdefault(thing, set()).update(new)
            self.say("search", f"{', '.join(new)} {'is' if len(new) == 1 else 'are'} on a {spoken(goal.cls)} already: "
                     f"takes a {spoken(kind)} that is not on one", target=thing)
        return True

    def _shut_in_goal_room(self, binding: Binding, thing: str, room: Any, shut: Sequence[str]) -> None:
        """A frame takes ``thing`` to ``room``, where the robot sees things of its kind shut away in a place (``shut``):
        those are not the one meant while another may lie elsewhere ("take the mug to the galley", a mug in the
        galley's cupboard: the saloon's mug, as ``seal plan`` reads it); the robot looks for another where such
        things are kept (:meth:`_kept_elsewhere`), and takes one of those out if it finds none."""
        if binding in self.shut_there or class_key(thing) in self.chosen or not binding.frame.needs_held("theme"):
            return
        held = self.held()
        if held is not None and held.key == self.class_of(thing):
            return
        self.shut_there[binding] = (thing, set(shut))
        self.not_meant.setdefault(thing, set()).update(shut)
        where = self._parent(shut[0]).id
        self.say("search", f"{shut[0]} is in {where} {located(room.name, self.scene.map)} already: looks for another "
                 f"{spoken(self.class_of(thing))} to take there", target=thing)

    def _take_out_after_all(self, binding: Binding) -> str | None:
        """Found no other thing to take to the room (:attr:`shut_there`): the ones shut away there are meant after
        all, and the robot takes one out; what it says, or None when the frame is no such frame."""
        if binding not in self.shut_there:
            return None
        thing, shut = self.shut_there[binding]
        self.not_meant[thing] = self.not_meant.get(thing, set()) - shut
        self.there_already.pop(binding, None)
        return f"found no other {spoken(self.class_of(thing))}, so takes {', '.join(sorted(shut))} out"

    def _goals_among(self, binding: Binding, thing: str, where: str, free: Sequence[str], on: bool) -> tuple[str, ...]:
        """The places where one of the kind seen lying makes a frame so already: its goal, or, where the goal was one
        of several places the command did not tell apart, the one of those a thing of the kind lies in
        (:func:`seal_cli.planning.lying.goal_among`, as the planner asks it of the map)."""
        among = self.among.get(binding, ())
        held = self.held()

        def lying(place: str) -> str | None:
            item = self.world.items.get(place)
            return None if item is None else next((i for i in free if self.world.items[i].parent == place and (
                self.world.items[i].on_top == on or not self.world.hollow(item))), None)

        found = goal_among(binding, thing, self.class_of(thing), held=held.key if held else None, among=among,
                           lies_in=lying) if among else None
        return (where,) if found is None else (found,)

    def _another_meant(self, binding: Binding, thing: str, where: str) -> bool:
        """Whether a frame that would put ``thing`` where the robot sees one of its kind already means another one, by
        the planner's rule (:func:`seal_cli.planning.lying.another_meant`, e2e27, e2e28: one rule in one place): the
        frame takes the thing up, the robot holds none of its kind, the goal is the one place of its class the robot
        knows (the map's), the command names one thing of its kind; asked once a frame, before the command chose one
        for the name."""
        held = self.held()
        goal = self.world.items.get(where)
        return (binding not in self.there_already and class_key(thing) not in self.chosen and goal is not None
                and another_meant(binding, thing, self.class_of(thing), held=held.key if held else None,
                                  places_like_goal=sum(1 for k in self.instances(goal.key) if not k.movable),
                                  several=self.several))

    def _open_already(self, binding: Binding) -> str | None:
        """"fridge_1 is already closed (as the map has it)", for an Open or a Close of a place of the map that is
        so already, by :func:`seal_cli.planning.plan.open_already` (e2e23). The robot knows whether a place is
        open: the map says so (``open:``) and only the robot opens and closes things in the simulator, so this
        is its own knowledge, not the hidden truth (a thing inside stays unseen)."""
        places = {f.args[0] for f in binding.postconditions if len(f.args) == 1}
        if len(places) != 1 or (place := next(iter(places))) not in self.world.items or not self._is_place(place):
            return None
        item = self.world.items[place]
        state = State.of({Fact("open", (place,))} if item.is_open else set(), self.library.taxonomy,
                         closable={place} if item.openable else set())
        made = open_already(binding, state)
        if made is None:
            return None
        how = "it closed it again after looking in" if place in self.opened else "as the map has it"
        return f"{place} is already {'closed' if made.negated else 'open'} ({how})"

    def _kept_already(self, binding: Binding) -> str | None:
        """"pen_1 is on desk_1 already", for a frame "put away" chose the goal of, when the robot sees a
        thing of its kind lying free where such a thing is kept (a place its prior names); None otherwise."""
        choose = self.put_away.get(binding)
        theme = binding.elements.get("theme")
        if choose is None or theme is None:
            return None
        for k in self.known.values():
            if (k.movable and k.cls == self.class_of(theme) and k.id in self.world.items
                    and not self.world.held_chain(k.id) and not self._chosen_as_other(k.id, theme)
                    and (place := self.world.items[k.id].parent) is not None
                    and place in self.known and choose(place) == class_key(place)):
                on = "in" if self.world.hollow(self.world.items[place]) else "on"
                return f"{k.id} is {on} {place} already, where a {spoken(k.cls)} is kept"
        return None

    def _chosen_as_other(self, item: str, value: str) -> bool:
        """Whether an instance was chosen for another name of its class (the sock put on the bed for
        "sock" is not "sock_2" lying there already)."""
        name = class_key(value)
        return any(i == item and n != name for n, i in self.chosen.items())

    def _put_away_again(self, todo: list[Binding]) -> str | None:
        """Choose again where the next commanded frame puts away the thing just picked up, now that the
        robot knows where it lay ("put away the cup": not back on the table it was on); the reason to
        replan, or None when the goal stands."""
        if not todo or (choose := self.put_away.get(todo[0])) is None or (held := self.held()) is None:
            return None
        if held.key != self.class_of(todo[0].elements.get("theme", "")):
            return None
        lay = (self.taken_from if todo[0] in self.put_back else self.picked_from).get(held.id)
        goal = choose(lay)
        if goal is None or goal == todo[0].elements.get("goal"):
            return None
        again = todo[0].frame.bind({**todo[0].elements, "goal": goal})
        self.put_away[again] = self.put_away.pop(todo[0])
        if todo[0] in self.put_back:
            self.put_back.discard(todo[0])
            self.put_back.add(again)
            todo[0] = again
            return f"{held.id} lay on {lay}: puts it back there"
        todo[0] = again
        return f"{held.id} lay on {lay}: puts it away on {goal}"

    def _nearest_again(self, todo: list[Binding]) -> str | None:
        """Choose again the goal of the next commanded frame, the nearest of several places the command did not tell
        apart, now that the robot has taken the thing it carries there: the nearest by drive from where it lay, as
        ``seal plan`` chooses it from where the map places the thing (the run planned from where one most likely
        lies); the reason to replan, or None when the goal stands."""
        from seal_cli.maps.reach import drive_lengths

        if not todo or (among := self.nearest_of.get(todo[0])) is None or (held := self.held()) is None:
            return None
        if held.key != self.class_of(todo[0].elements.get("theme", "")) or len(among) < 2:
            return None
        lay = self.picked_from.get(held.id)
        at = self.world.items[lay].at if lay in self.world.items else \
            self.started.get(held.id, self.world.robot.pose[:2])
        lengths = drive_lengths(self.scene.map, at, list(among))
        best = min(range(len(among)), key=lambda k: (lengths[k], k))
        goal = todo[0].elements.get("goal")
        if among[best] == goal or math.isinf(lengths[best]):
            return None
        again = todo[0].frame.bind({**todo[0].elements, "goal": among[best]})
        self.nearest_of[again] = self.nearest_of.pop(todo[0])
        if todo[0] in self.among:
            self.among[again] = self.among.pop(todo[0])
        todo[0] = again
        return (f"{held.id} lay {'on ' + lay if lay else 'there'}: takes it to {among[best]}, the nearest from there "
                f"({lengths[best]:.1f} m), not {goal}")

    def _parent(self, item_id: str) -> Item:
        return self.world.items[self.world.items[item_id].parent or ""]

    def _place_of(self, value: str) -> str | None:
        """The map's place a value names (``coffee_table_1``), if it names one."""
        item = self.world.items.get(value)
        return value if item is not None and not item.movable and item.key != PERSON else None

    def _track_searches(self, commanded: Sequence[Binding]) -> None:
        """Keep the unsearched prior of each kind of thing a commanded frame names that the map has a
        prior of (and its perception knows), from the first look on."""
        m = self.scene.map
        shut = [i.id for i in self.world.items.values() if i.openable and not i.is_open]
        priors = {class_key(c) for c in m.priors}
        for binding in commanded:
            for _, value in binding.values:
                key = self.class_of(value)
                if key in priors and key not in self.unsearched and self.recognises(value):
                    self.unsearched[key] = Unsearched.of(m, key, shut)

    def search_ended(self, value: str) -> Outcome | None:
        """Not found, when less than ``search_end`` of the prior of the thing's kind is left unsearched:
        "no sandwich found: searched the staff room, ..., looked into fridge_1 (...)"; for a further one of a kind
        it has one of ("bring me three towels", ``towel_2``), "no other towel found: ..."."""
        left = self.unsearched.get(self.class_of(value))
        if self.search_end is None or left is None:
            return None
        if (elsewhere := self._kept_elsewhere(value)) is not None:    # another one: where such things are kept
            if left.left_at(elsewhere) >= self.search_end:
                return None
        elif left.left >= self.search_end:
            return None
        rooms = [r.replace("_", " ") for r in left.searched_rooms()]
        opened = sorted(p for p in self.opened if p in left.inside)
        said = ", ".join(f"the {r}" for r in rooms) or "where it looked"
        into = f"; looked into {', '.join(opened)}" if opened else ""
        cls = self.class_of(value)
        other = class_key(value) != cls and any(k.cls == cls for k in self.known.values() if k.movable)
        what, one = (f"other {self.said(value)}", "another") if other else (self.said(value), "one")
        return Fatal(False, f"no {what} found: searched {said}{into} (had the {self.scene.map.said} {one}, it "
                     f"would have been seen with probability {1 - left.left:.2f})", Reason.NOT_FOUND, value)

    def _kept_elsewhere(self, value: str) -> list[str] | None:
        """Where to look for another thing of a kind than the one seen lying where the next frame puts it (the
        other-one rule, :attr:`there_already`): the prior's own targets (its places, place classes and rooms, not the
        floor share it spreads everywhere), less the goal, where one lies already. The reading that another is meant
        is the command's guess, and one lying there says "it is so already" is likelier; so the robot looks where
        such a thing is kept, not all over the house (e2e28: "put the milk in the fridge" on the houseboat, its milk
        in its one fridge, searched 77.25 m before "it found no other"). None when the search is no such search."""
        if not self.todo or ((binding := self.todo[0]) not in self.there_already and binding not in self.shut_there):
            return None
        theme, goal = binding.elements.get("theme"), binding.elements.get("goal")
        if theme is None or goal is None or self.class_of(theme) != self.class_of(value):
            return None
        m = self.scene.map
        if binding in self.shut_there:         # not in the goal room, where the ones seen lie shut away
            return [t for t in m.prior(self.class_of(value)).masses if t != "_rest" and (r := m.prior_target(t))
                    and not ({class_key(m.rooms[i].name) for i in r[1]} if r[0] == "room" else
                             {class_key(m.places[i].room or "") for i in r[1]}) <= {class_key(goal)}]
        targets = []
        for target in m.prior(self.class_of(value)).masses:
            resolved = m.prior_target(target) if target != "_rest" else None
            if resolved is None:
                continue
            if resolved[0] != "room" and {class_key(m.places[i].name) for i in resolved[1]} <= {class_key(goal)}:
                continue          # the goal itself: one lies there already
            if resolved[0] == "room" and (place := m.place(goal)) is not None and place.room is not None \
                    and class_key(place.room) in {class_key(m.rooms[i].name) for i in resolved[1]}:
                continue          # the goal's room: its prior is the goal's own (lead, stop 39: the houseboat's
                #                   "put the blanket on the sofa" circled the saloon, where the seen one kept the
                #                   belief, 211 m before "it found no other")
            targets.append(target)
        return targets

    def class_of(self, value: str) -> str:
        key = class_key(value)
        return self.classes.get(key, key)

    def shown_now(self, binding: Binding) -> str:
        """A step as the run says it (:func:`~seal_cli.frames.said.shown`), naming what the robot handles: a thing
        the plan names (``cup``, ``cup_2``: a second cup, a name the plan made up, no cup of the house) is said as
        the instance the robot chose for it once it has ("Bring(theme=cup_3, ...)" after "picked up cup_3"), and a
        made-up name not yet chosen as "another cup" (e2e26: the plan said Pick(theme=cup_2), then "picked up
        cup_1"). Places, rooms and people keep their names; the records' ``frame`` data keeps the plan's, and so
        does a step skipped as so already ("umbrella_1 is in the waiting room already, so Bring(theme=umbrella,
        ...) needs no doing": the plan's step, quoted, after the thing it found)."""
        said = {role: self.handled(value) for role, value in binding.values}
        lay = self.picked_from.get(said.get("theme", ""))
        if "source" in said and lay is not None and not self._lies_within(lay, said["source"]):
            said["source"] = lay        # taken from elsewhere than the command said (e2e30: no book in the study room)
        if all(said[r] == v for r, v in binding.values):
            return shown(binding)
        return shown(binding.frame.bind(said))

    def _lies_within(self, place: str, where: str) -> bool:
        """Whether a place is ``where`` or lies in the room ``where`` names."""
        room = self.room(where)
        item = self.world.items.get(place)
        return place == where or (room is not None and item is not None and bool(room.contains([item.at])[0]))

    def said_at_end(self, record: Record) -> str:
        """A step's record as the run would say it now, naming what it handled in it (the run's picture, drawn after
        the run: "step 1: Pick(theme=spoon_1)", not the "Pick(theme=spoon)" said before it chose the spoon)."""
        binding = self.framed.get(record.data.get("frame", ""))
        return self.shown_now(binding) if binding is not None else record.text

    def handled(self, value: str) -> str:
        """The name the run says for a thing a step names (see :meth:`shown_now`)."""
        name = class_key(value)
        item = self.world.items.get(value)
        if (item is not None and not item.movable) or self.is_person(value) or self.room(value) is not None:
            return value
        chosen = self.chosen.get(name)
        instance = self.world.items.get(chosen) if chosen is not None else None
        if instance is not None and instance.movable and instance.key == self.class_of(value):
            return instance.id
        if name in self.classes and self.classes[name] != name:
            return f"another {self.said(value)}"
        return value

    def run(self, commanded: Sequence[Binding], done: Sequence[Binding] = ()) -> Result:
        """Plan the commanded frames, then search and execute until done or out of budget.
        ``done``: frames already carried out, whose postconditions hold at the start."""
        self.state = self.initial_state()
        for binding in done:
            self.state = self.state.apply(binding)
        if self.search_end is not None:
            self._track_searches(commanded)
        self.policy.begin(self)
        self.look_round(self.world.robot.pose[:2])  # where it starts, all round (a narrow sensor turns)
        todo = list(commanded)
        self.several = several_said(todo, self.class_of)
        while todo and (already := self.already_so(todo[0])) is not None:
            skipped = todo.pop(0)
            self.say("done", f"{already}, so {shown(skipped)} needs no doing", frame=str(skipped))
        self.todo = todo
        try:
            steps = self.planner(todo, self.library, self.state)
        except SealError as error:
            self.say("fail", f"cannot plan: {error.message}")
            return self._result(False, f"cannot plan: {error.message}", [], why=Reason.CANNOT)
        self.steps, self.index = steps, 0
        if self.heed_sources and not self.told:
            from seal_cli.sefm.relations import said_where

            self.told = {self.class_of(k): v for k, v in said_where(steps).items()}
        plan = [str(b) for b in steps]
        self.say("plan", "plan: " + ", ".join(self.shown_now(b) for b in steps) if plan else "nothing to do", plan=plan)
        for binding in todo:        # a goal chosen before the robot has seen the thing: said as such
            theme, goal = binding.elements.get("theme"), binding.elements.get("goal")
            if binding in self.put_back:
                self.say("plan", f"({goal} stands in for where {theme} lies: it puts {theme} back where it "
                         "takes it from)")
            elif binding in self.put_away:
                kind = spoken(self.class_of(theme or ""))
                self.say("plan", f"({goal}: where it would keep a {kind}, not yet knowing where the {kind} lies; "
                         "it chooses again once it sees it)")
        executed: list[str] = []
        replans = 0
        while self.index < len(self.steps):
            binding = self.steps[self.index]
            self.framed[str(binding)] = binding
            self.say("frame", self.shown_now(binding), frame=str(binding))
            outcome = self.execute(binding)
            if outcome.ok:
                self.state = self.state.apply(binding)
                executed.append(str(binding))
                self.index += 1
                passed = False
                if todo and binding == todo[0]:
                    todo.pop(0)
                    self.say("done", f"done: {self.shown_now(binding)}", frame=str(binding))
                    while todo and (already := self.already_so(todo[0])) is not None:   # so by its turn
                        skipped, passed = todo.pop(0), True
                        self.say("done", f"{already}, so {shown(skipped)} needs no doing", frame=str(skipped))
                else:
                    self.say("done", f"done: {self.shown_now(binding)}", frame=str(binding))
                if passed:
                    if (failed := self._replan(todo, self.resync(self.state))) is not None:
                        return self._result(False, failed, plan, executed, Reason.CANNOT)
                    continue
                if (again := self._put_away_again(todo) or self._nearest_again(todo)) is not None:
                    if (failed := self._replan(todo, self.resync(self.state))) is not None:
                        return self._result(False, failed, plan, executed, Reason.CANNOT)
                    self.say("replan", f"{again}; replans: " + ", ".join(self.shown_now(b) for b in self.steps))
                continue
            if outcome.reason is Reason.ALREADY:     # what the next commanded frame would do is so already
                skipped = todo.pop(0)
                self.say("done", f"{outcome.message}, so {shown(skipped)} needs no doing", frame=str(skipped))
                if (failed := self._replan(todo, self.resync(self.state))) is not None:
                    return self._result(False, failed, plan, executed, Reason.CANNOT)
                continue
            stop = self.exhausted()
            if not stop and outcome.reason is Reason.NOT_FOUND and todo and (out := self._take_out_after_all(todo[0])):
                self.say("search", out)
                if (failed := self._replan(todo, self.resync(self.state))) is not None:
                    return self._result(False, failed, plan, executed, Reason.CANNOT)
                continue
            if not stop and outcome.reason is Reason.NOT_FOUND and todo and todo[0] in self.there_already:
                skipped = todo.pop(0)       # no other one anywhere: the one seen there was meant after all
                self.say("done", f"{self.there_already[skipped]} and it found no other, so {shown(skipped)} needs "
                         "no doing", frame=str(skipped))
                if (failed := self._replan(todo, self.resync(self.state))) is not None:
                    return self._result(False, failed, plan, executed, Reason.CANNOT)
                continue
            if stop or isinstance(outcome, Fatal):
                reason = stop or outcome.message
                self.say("give_up", f"gives up: {reason}")
                if not stop and outcome.reason is Reason.NOT_FOUND:
                    self.report_unfound(outcome, binding)
                return self._result(False, reason, plan, executed, Reason.BUDGET if stop else outcome.reason)
            replans += 1
            if replans > self.budget.replans:
                self.say("give_up", f"gives up after {self.budget.replans} replans: {outcome.message}")
                return self._result(False, outcome.message, plan, executed, outcome.reason)
            self.state = self.resync(self.state)
            if (failed := self._replan(todo, self.state)) is not None:
                return self._result(False, failed, plan, executed, Reason.CANNOT)
            self.say("replan", f"{outcome.message}; replans: " + ", ".join(self.shown_now(b) for b in self.steps))
        return self._result(True, "done", plan, executed)

    def _replan(self, todo: Sequence[Binding], state: State) -> str | None:
        """Plan what is left to do from ``state`` and start on it; the reason to give up (said) if no plan is found."""
        try:
            self.steps, self.index = self.planner(todo, self.library, state), 0
        except SealError as error:
            self.say("give_up", f"cannot replan: {error.message}")
            return f"cannot replan: {error.message}"
        return None

    def _result(self, completed: bool, reason: str, plan: list[str], executed: list[str] | None = None,
                why: Reason = Reason.OK) -> Result:
        answer = "; ".join(self.answers) if self.answers else None
        reason = self.named(reason)
        return Result(completed, reason, self.world.robot.path_m, self.world.step, plan, executed or [],
                      self.records, answer, why=why if not completed else Reason.OK)

    def resync(self, state: State) -> State:
        """The semantic state corrected by what the robot knows of its own hand."""
        held = self.held()
        facts = {f for f in state.facts if f.predicate not in ("holding", "hand_empty")}
        facts |= {Fact("holding", (held.key,))} if held else {Fact("hand_empty")}
        return State.of(facts, state.taxonomy, closable=state.closable, classes=state.classes)

    # -- executing a frame -----------------------------------------------------------------------

    def execute(self, binding: Binding) -> Outcome:
        """Run the grounded frame's primitive actions in the world."""
        acted = False
        question = self.questions.get(binding)
        if question is not None and question.kind == "state" and (known := self.state_known(binding, question)):
            return known
        if question is not None and question.kind == "state" and (absent := self.state_absent(binding, question)):
            return absent
        for action in binding.actions:
            if action.name == "approach" and question is not None and question.kind == "what":
                continue            # "tell Ben what is on the table": looked first, then told (answer_what)
            if action.name == "navigate" and self._counted_by_the_map(action.args[0], binding):
                continue            # "how many sofas are in the kitchen?": the map says, no drive there first
            if action.name == "navigate":
                outcome = self.go_to(action.args[0], binding)
                if not outcome.ok and outcome.reason is Reason.NOT_FOUND and question is not None \
                        and question.kind == "state":         # "is the window open?" with no window: the answer
                    self.answer(outcome.message)
                    return Outcome(True, outcome.message)
            else:
                outcome = Outcome(True, "ok")
                if action.name in GO_FIRST:      # drive up to the person, to where the person is led
                    outcome = self.go_to(action.args[GO_FIRST[action.name]], binding)
                if outcome.ok:
                    outcome = self.do(action, binding)
                acted = True
            if not outcome.ok:
                return outcome
        question = self.questions.get(binding)
        if question is not None and question.kind == "what" and not any(a.name == "say" for a in binding.actions):
            answered = self.answer_what(question, binding)     # "look in the fridge": says what it saw
            if not answered.ok:
                return answered
        hand_empty = any(f.predicate == "hand_empty" and not f.negated for f in binding.postconditions)
        if hand_empty and self.world.robot.holding is not None and not any(
                a.name in (*PUTS, "hand_over") for a in binding.actions):
            return self.put_down(binding)  # "put it down": a Place without a goal
        if not acted and not binding.actions:
            return Outcome(True, "nothing to do")
        return Outcome(True, "ok")

    def resolve(self, value: str, binding: Binding, role: str | None = None) -> str | None:
        """The instance that an element's value (a class, or an item's name) denotes now."""
        name = class_key(value)
        if value in self.world.items and value in self.known and (
                name not in self.classes or not self.world.items[value].movable):
            # an item named by itself (a place, a person of the map), not a name the command made up
            return None if value in self.unreachable else value
        key = self.class_of(value)
        room = self.room(value)
        if room is not None and not self.instances(key):
            theme = binding.elements.get("theme") if role != "theme" else None
            return self.surface_in(room, self.class_of(theme) if theme else None)
        others = {i for n, i in self.chosen.items() if n != name and self.class_of(n) == key}
        held = self.held()
        if held is not None and held.key == key and held.id not in others:
            return held.id
        candidates = [k for k in self.instances(key) if k.id not in self.unreachable and k.id not in others
                      and not self.world.held_chain(k.id) and k.id not in self.not_meant.get(value, ())]
        previous = self.chosen.get(name)
        taking = role == "theme" and any(a.name == "pick" for a in binding.actions)
        if taking:   # a thing put in place is not taken again, unless the command names it again
            candidates = [k for k in candidates if k.id not in self.placed or k.id == previous]
        if (source := self.source_room(binding, role)) is not None:  # "a cup from the kitchen": one there
            candidates = [k for k in candidates if bool(source.contains([self.world.position(k.id)])[0])]
        if not candidates:
            return None
        place = self._place_of(binding.elements.get("source") or "") if taking else None
        there = [k for k in candidates if place is not None and self.world.items[k.id].parent == place]
        if there:          # "the mug on the coffee table": one seen there, not the nearest mug elsewhere (e2e23)
            candidates = there
        elif place is not None and self.known[place].openable and place not in self.inspected | self.unreachable \
                and place in self.said_places(value):
            return None    # "the cup in the cupboard": not one seen on the way before it looked in (e2e24)
        if previous is not None and any(k.id == previous for k in candidates):
            return previous
        return self.policy.choose(self, key, candidates) or self.nearest(candidates)

    def source_room(self, binding: Binding, role: str | None) -> Any:
        """The room a frame that picks its theme up takes it from, when its source names a room
        ("bring me a cup from the kitchen": Pick(cup, source=kitchen)), until the robot has looked all over
        it without finding one (:attr:`missed_rooms`: then any will do, as for a place said); else None."""
        if role != "theme" or not any(a.name == "pick" for a in binding.actions):
            return None
        source = binding.elements.get("source")
        room = self.room(source) if source else None
        theme = binding.elements.get("theme")
        if room is None or theme is None or (self.class_of(theme), room.name) in self.missed_rooms:
            return None
        return room

    def look_into(self, place: str, value: str, binding: Binding, role: str | None, why: str) -> None:
        """Go within reach of a place, open it if it is shut, and look; closed again when what was sought
        is not in it. A place it cannot reach is marked so."""
        cell = self.policy.stand(self, self.known[place])
        if cell is None:
            self.unreachable.add(place)
            return
        self.drive_to(cell, why)
        self.world.face(self.known[place].at)
        if self.known[place].openable and not self.world.items[place].is_open:
            self.open_to_look(place)
        self.look()
        if self.resolve(value, binding, role) is None:
            self.shut_after(place)

    def said_places(self, value: str) -> list[str]:
        """The places of the map the command says a thing of this kind is in or on (:attr:`told`: "a beer from
        the fridge": fridge_1; a place class: every place of it), where it is looked for first. A room said
        so is :meth:`source_room`'s."""
        out = []
        for where in self.told.get(self.class_of(value), ()):
            if self._is_place(where):
                out.append(where)
            elif self.room(where) is None:      # a kind of place, or of thing ("the lid off the pan"): those seen
                out += sorted(k.id for k in self.known.values() if k.cls == where and k.id in self.world.items
                              and (self._is_place(k.id) or k.movable and not self.world.held_chain(k.id)))
        return [p for p in out if p in self.known]

    def said_things(self, value: str) -> list[str]:
        """The kinds of thing (not place) the command says a thing of this kind is in or on ("take the lid off the
        frying pan": frying_pan), that the robot's perception knows, has seen none of and has not given up on."""
        return [w for w in self.told.get(self.class_of(value), ()) if self.room(w) is None and not self._is_place(w)
                and w not in self.unfound and self.recognises(w) and not self.instances(w)
                and not any(k.cls == w and not k.movable for k in self.known.values())]

    def look_where_said(self, value: str, binding: Binding) -> Outcome | None:
        """Before searching on its own: into a thing the command said the one sought is in or on, once seen
        (:meth:`said_places`), or a search for such a thing first, while none is seen (it then looks into it).
        An Outcome (None: looked) when it did something; False-y when there is nothing said to look at."""
        role = next((r for r, v in binding.values if v == value), None)
        things = [p for p in self.said_places(value) if (self.world.items[p].movable or self._shut_said(p, value))
                  and p not in self.inspected and p not in self.unreachable]
        if things:
            self.look_where_said_at(things[0], value, binding, role)
            return Outcome(True, "looked")
        for kind in self.said_things(value):
            self.say("search", f"looks for the {spoken(kind)} first, where the command said the {self.said(value)} "
                     "is", target=kind)
            while not self.instances(kind):
                ended = self.look_once(kind, binding)
                if ended is not None or self.exhausted() is not None:
                    self.unfound.add(kind)
                    break
            return Outcome(True, "looked")
        return None

    def _shut_said(self, place: str, value: str) -> bool:
        """Whether a place the command says the thing is in is shut and holds no thing of its kind the robot knows
        of: what is inside is seen only by opening it, so the robot goes there first ("the cup in the cupboard",
        e2e24: the cups seen on the way are not the one meant, :meth:`resolve`)."""
        item = self.world.items[place]
        return self.known[place].openable and not item.is_open and not any(
            k.parent == place and k.cls == self.class_of(value) for k in self.known.values() if k.movable)

    def look_where_said_at(self, where: str, value: str, binding: Binding, role: str | None) -> None:
        """Look into a place or thing the command said a thing of this kind is in or on, saying so; not tried again
        if the robot could not look into it."""
        self.say("search", f"looks for {self.said(value)} where the command said: {where}", target=value)
        self.look_into(where, value, binding, role, f"goes to {where}")
        if where not in self.inspected:
            self.unreachable.add(where)

    def missed_where_said(self, value: str) -> None:
        """Say once, per place, that the thing sought is not where the command said it was, once the robot
        has looked into that place (it searches on elsewhere)."""
        for place in self.said_places(value):
            if place in self.inspected and place not in self.missed:
                self.missed.add(place)
                item = self.world.items[place]
                on = "in" if self.world.hollow(item) else "on"
                self.say("search", f"no {self.said(value)} {on} {place}, where the command said it was"
                         f"{self.elsewhere(value)}", target=value)
                self.withdraw(value, place)

    def elsewhere(self, value: str) -> str:
        """What a miss where the command said adds: "; looks elsewhere", unless the map names no such thing and the
        run says so next (:meth:`absent_from_map`), rather than look anywhere else."""
        return "" if self.absent_said and self.absent_from_map(value) is not None else "; looks elsewhere"

    def withdraw(self, value: str, where: str) -> None:
        """Take back the command's word that a thing of this kind is at ``where`` (a room, a place, a thing), once
        the robot has looked there without finding it: the search goes on from the map's own prior and what the
        robot has seen (a policy that conditions its beliefs on :attr:`told` rebuilds them)."""
        key = self.class_of(value)
        item = self.world.items.get(where)
        dropped = {where, class_key(where)} | ({item.key} if item is not None and item.movable else set())
        left = tuple(w for w in self.told.get(key, ()) if w not in dropped)
        if key in self.told:
            self.told = {**{k: v for k, v in self.told.items() if k != key}, **({key: left} if left else {})}

    def _not_where_said(self, thing: str, lay: str | None) -> str:
        """" (not in tool_chest_1, where the command said it was)" when the robot takes a thing from elsewhere than
        the places the command said it was in (seen on the way, before it looked there), and had not said so."""
        said = self.said_places(self.world.items[thing].key)
        if lay is None or not said or lay in said or all(p in self.missed for p in said):
            return ""
        self.missed.update(said)
        on = "in" if self.world.hollow(self.world.items[said[0]]) else "on"
        return f" (not {on} {' or '.join(said)}, where the command said it was)"

    def look_in(self, room: Any, value: str, binding: Binding, role: str | None) -> Outcome | None:
        """Look for a thing in the room it is to be taken from, until one of its kind is known there:
        all over the room a view at a time (:meth:`survey`, at most :data:`SURVEY_VIEWS` views), then
        into its closed receptacles, the nearest first. An Outcome when none is there."""
        views = 0
        start = len(self.looks)
        while self.resolve(value, binding, role) is None:
            if (stop := self.exhausted()) is not None:
                return Fatal(False, stop, Reason.BUDGET)
            looked = len(self.looks)
            if views < SURVEY_VIEWS:
                self.survey(room, views=1, announced=len(self.looks) > start)   # "looks all over" said once
                views += 1
            if len(self.looks) > looked:
                continue
            closed = [k for k in self.known.values() if not k.movable and k.openable and k.id not in self.opened
                      and k.id not in self.unreachable and not self.world.items[k.id].is_open
                      and bool(room.contains([k.at])[0]) and self.may_hold(k, value)]
            named = [k for k in closed if self.prior_names(k, value)]
            place = self.nearest(named or closed) if closed else None
            if place is None:
                seen = " (it sees all of it from where it is)" if len(self.looks) == start else ""
                shut = sorted(k.id for k in self.known.values() if not k.movable and k.openable
                              and k.id not in self.opened and not self.world.items[k.id].is_open
                              and bool(room.contains([k.at])[0]) and not self.may_hold(k, value))
                if shut:    # appliances it did not open: the search goes on, and may yet look into them
                    kind = spoken(self.class_of(value))
                    return Fatal(False, f"no {self.said(value)} in sight {located(room.name, self.scene.map)}, where "
                                 f"the command said it was ({', '.join(shut)} left shut: the map keeps no {kind} "
                                 f"there){seen}; searches on", Reason.NOT_FOUND, value)
                return Fatal(False, f"no {self.said(value)} {located(room.name, self.scene.map)}, where the command "
                             f"said it was{seen}{self.elsewhere(value)}", Reason.NOT_FOUND, value)
            self.look_into(place, value, binding, role, f"goes to {place}")
            if place not in self.opened:  # out of reach, or it would not open: not tried again
                self.unreachable.add(place)
        return None

    def prior_names(self, place: Known, value: str) -> bool:
        """Whether the map's prior of the thing's class names this place or its class ("milk: {fridge: 0.9}")."""
        from seal_cli.planning.keeping import Spot, prior_of, tier

        prior = prior_of(self.scene.map.priors, self.class_of(value))
        return tier(self.library.taxonomy, prior, Spot(place.id, place.cls, None, place.at)) == 0

    def may_hold(self, place: Known, value: str) -> bool:
        """Whether a room said as where a thing is makes the robot look into this closed place of it: a place
        for keeping things (a cupboard, a larder, a drawer), or an appliance (a fridge, an oven, a dishwasher:
        :data:`~seal_cli.planning.keeping.APPLIANCES`) the map's prior of the thing's class names. "The mug from
        the kitchen" does not open the fridge and the oven; "the milk from the kitchen" opens the fridge where
        milk is kept. A thing that is nowhere else in the room is then searched for as any thing is. Of a class the
        map has no prior of, the map says nothing of where it is kept: every closed place may hold it."""
        from seal_cli.planning.keeping import APPLIANCES, prior_of

        if not prior_of(self.scene.map.priors, self.class_of(value)):
            return True
        appliance = any(kind_of(self.library.taxonomy, place.cls, kind) is True for kind in APPLIANCES)
        return not appliance or self.prior_names(place, value)

    def room(self, value: str) -> Any:
        """The map's room a value names, if it names one."""
        index = self.scene.map.room_id(value)
        return self.scene.map.rooms[index] if index is not None else None

    def surface_in(self, room: Any, cls: str | None = None) -> str | None:
        """Where to go in a room, or to put a thing down there: the nearest surface in it (a place
        that does not open, such as a counter), else the nearest open receptacle in it (a fridge the
        robot left open is no place to put down what it was asked to bring to the kitchen). For a thing
        of class ``cls`` brought there, the room's place where such a thing is put, open or not
        (:func:`seal_cli.planning.keeping.put_in_room`: a counter, not the sink), the nearest among equals, other
        than the place the thing in hand was taken from (the apple brought from the fridge to the kitchen goes on the
        counter, not back in), and one that does not shut while the room has one where such a thing can be left (its
        prior's place, or furniture: :func:`~seal_cli.planning.keeping.tier` 0 or 1): a thing taken to a room is left
        out in it, not shut away (lead, e2e29: "bring the towel up to the double room" went into its closed wardrobe,
        where towels are kept too; the townhouse bathroom's towel still goes in the medicine cabinet, not the bath).
        In the room the speaker is in, the nearest the speaker among equals: a thing taken to where the speaker is is
        put down by them (e2e28: "take the laptop to the shop", the speaker behind the till, went on the shelf
        nearest the robot's way in, not the till's counter)."""
        if cls is not None:
            from seal_cli.planning.keeping import Spot, prior_of, put_in_room, tier

            field_ = self.distances()
            spots, distance = [], {}
            for k in self.known.values():
                if k.movable or not k.receptacle or not bool(room.contains([k.at])[0]) or k.id in self.unreachable:
                    continue
                spots.append(Spot(k.id, k.cls, room.name, k.at))
                if (cell := self.stand_cell(k, field_)) is not None and math.isfinite(field_[cell]):
                    distance[k.id] = float(field_[cell])
            held = self.held()
            lay = self.picked_from.get(held.id) if held is not None else None
            if any(s.name != lay for s in spots if s.name in distance):     # not back where it was taken from
                spots = [s for s in spots if s.name != lay]
            out = [s for s in spots if not self.world.items[s.name].openable]
            prior = prior_of(self.scene.map.priors, cls)
            if any(s.name in distance and tier(self.library.taxonomy, prior, s) <= 1 for s in out):   # not shut away
                spots = out
            speaker = self.scene.map.speaker         # where the map says they stand (none: not said)
            if speaker is not None and bool(room.contains([speaker])[0]):     # by the speaker, where they can reach
                distance = {s.name: math.dist(s.at, speaker) for s in spots if s.name in distance}
            best = put_in_room(self.library.taxonomy, self.scene.map.priors, cls, spots, distance)
            if best is not None:
                return best.name
        places = [k for k in self.known.values() if not k.movable and k.receptacle
                  and self.world.items[k.id].is_open and bool(room.contains([k.at])[0])]
        surfaces = [k for k in places if not k.openable]
        return self.nearest(surfaces or places) if places else None

    def spent(self, item: str, value: str) -> bool:
        """Whether a known instance cannot serve as ``value`` (put in place already, out of reach,
        or chosen for another name of its class)."""
        name = class_key(value)
        return item in self.placed or item in self.unreachable or any(
            i == item and n != name for n, i in self.chosen.items())

    def nearest(self, candidates: Sequence[Known]) -> str | None:
        """The candidate the robot can reach by the shortest drive."""
        field_ = self.distances()
        best: tuple[float, str] | None = None
        for k in candidates:
            cell = self.stand_cell(k, field_)
            if cell is None:
                continue
            cost = field_[cell]
            if best is None or cost < best[0]:
                best = (cost, k.id)
        return best[1] if best else None

    def robot_cell(self) -> Cell:
        cell = self.grid.cell(self.world.robot.pose)
        return cell if self.grid.is_free(cell) else self.grid.nearest_free(self.world.robot.pose)

    def distances(self) -> np.ndarray:
        return self.grid.distances(self.robot_cell())

    def stand_cells(self, known: Known) -> np.ndarray:
        """Free cells (rows of i, j) from which the robot can reach the item."""
        pts = self.grid.free_points
        at = np.asarray(known.at)
        reach = self.world.reach_of(known.id) if known.id in self.world.items else self.world.reach
        near = np.hypot(pts[:, 0] - at[0], pts[:, 1] - at[1]) <= reach - 1e-6
        stands = list(known.access)
        if known.parent is not None and known.parent in self.known:
            stands += list(self.known[known.parent].access)
        for a in stands:
            near |= np.hypot(pts[:, 0] - a[0], pts[:, 1] - a[1]) <= self.world.access_tolerance
        box = self.known.get(known.parent) if known.parent else None
        if box is not None and box.openable:  # stand where the receptacle can be opened too
            both = near & self._reach_mask(box)
            if both.any():
                near = both
        return self.grid.free_cells[near]

    def _reach_mask(self, known: Known) -> np.ndarray:
        pts = self.grid.free_points
        reach = self.world.reach_of(known.id) if known.id in self.world.items else self.world.reach
        mask = np.hypot(pts[:, 0] - known.at[0], pts[:, 1] - known.at[1]) <= reach - 1e-6
        for a in known.access:
            mask |= np.hypot(pts[:, 0] - a[0], pts[:, 1] - a[1]) <= self.world.access_tolerance
        return mask

    def stand_cell(self, known: Known, field_: np.ndarray | None = None) -> Cell | None:
        """The stand cell nearest the robot by path, or None if none can be driven to."""
        cells = self.stand_cells(known)
        if not len(cells):
            return None
        field_ = self.distances() if field_ is None else field_
        costs = field_[cells[:, 0], cells[:, 1]]
        if known.id in self.world.items:      # not behind a wall, seen from the thing
            points = np.column_stack([self.grid.origin[0] + cells[:, 1] * self.grid.resolution,
                                      self.grid.origin[1] + cells[:, 0] * self.grid.resolution])
            clear = np.asarray(self.world.sensor.line_of_sight(known.at, points), dtype=bool)
            if clear.any():
                cells, costs = cells[clear], costs[clear]
        for k in np.argsort(costs, kind="stable")[:STAND_TRIES]:
            if not np.isfinite(costs[k]):
                return None
            cell = (int(cells[k, 0]), int(cells[k, 1]))
            if known.id not in self.world.items or not self.world.walled(known.id, self.grid.point(cell)):
                return cell
        return None

    def go_to(self, value: str, binding: Binding) -> Outcome:
        """``navigate(value)``: find an instance (searching while none is known), drive within reach of
        it; a room the robot is in already needs no drive (unless a thing is to be put down there:
        then to a surface in it)."""
        role = next((r for r, v in binding.values if v == value), None)
        room = self.room(value)
        puts = any(a.name in PUTS and role in a.args for a in binding.frame.actions)   # onto a surface there
        if room is not None and not puts and bool(room.contains([self.world.robot.pose[:2]])[0]):
            self.say("go", f"is {located(room.name, self.scene.map)} already", to=self.world.robot.pose[:2], metres=0.0)
            return Outcome(True, f"in {value}")
        if room is not None and not puts:      # into the room, not to an appliance of it
            return self.into_room(room, value)
        while True:
            target = self.resolve(value, binding, role)
            if target is not None:
                if self.world.held_chain(target):
                    return Outcome(True, f"holds {target}")
                if (holder := self.world.items[target].parent) is not None and self.is_person(holder):
                    return self.go_to(holder, binding)      # handed to someone before: taken back from them
                if self.todo and binding != self.todo[0] and (already := self.already_so(self.todo[0])):
                    return Outcome(False, already, Reason.ALREADY)   # seen where the command wants it
                if target in self.not_meant.get(value, ()):     # seen where it is to go: another one is meant
                    continue
                cell = self.policy.stand(self, self.known[target])
                if cell is None:
                    self.unreachable.add(target)
                    said = f"{target} cannot be reached from anywhere the robot can drive"
                    self.say("fail", said)
                    if target == value and self.scene.map.place(value) is not None:
                        return Fatal(False, said)   # the one place the plan names: no other to search for
                    continue
                self.chosen[class_key(value)] = target
                said = "the speaker" if target == SPEAKER else \
                    f"the {spoken(value)} (by {target})" if target != value and self.room(value) is not None else target
                self.drive_to(cell, f"goes to {said}")
                self.world.face(self.known[target].at)
                return Outcome(True, f"at {target}")
            if (stop := self.exhausted()) is not None:
                return Fatal(False, stop)
            room = self.room(value)
            if room is not None:  # a room with no open place in it: drive into it
                return self.into_room(room, value)
            if (source := self.source_room(binding, role)) is not None and self.sweeper is not None:
                if (ended := self.look_in(source, value, binding, role)) is not None:
                    if ended.reason is not Reason.NOT_FOUND:
                        return ended
                    self.missed_rooms.add((self.class_of(value), source.name))   # the speaker was wrong: widen
                    self.withdraw(value, source.name)
                    self.say("search", ended.message, target=value)
                continue
            self.missed_where_said(value)
            if (ended := self.look_once(value, binding)) is not None:
                return ended

    def room_spot(self, room: Any) -> Cell | None:
        """Where "go to the kitchen" ends: the free cell of the room the robot can drive to that lies
        nearest the room's centre (the point "where is the kitchen?" answers with), the shorter drive
        among equals, not within :data:`ROOM_SPOT_CLEARANCE` of a person; None when the robot can
        drive to no cell of the room."""
        inside = np.flatnonzero(room.contains(self.grid.free_points))
        if not len(inside):
            return None
        cells = self.grid.free_cells[inside]
        field_ = self.distances()
        costs = field_[cells[:, 0], cells[:, 1]]
        reach = np.isfinite(costs)
        if not reach.any():
            return None
        points, cells, costs = self.grid.free_points[inside][reach], cells[reach], costs[reach]
        people = [self.world.position(i.id) for i in self.world.items.values() if i.key == PERSON]
        clear = np.ones(len(points), dtype=bool)      # not where someone stands (the robot would see them)
        for at in people:
            clear &= np.hypot(points[:, 0] - at[0], points[:, 1] - at[1]) > ROOM_SPOT_CLEARANCE
        if clear.any():
            points, cells, costs = points[clear], cells[clear], costs[clear]
        x, y = room.centroid
        off = np.round(np.hypot(points[:, 0] - x, points[:, 1] - y) / self.grid.resolution)   # in cells
        k = int(np.lexsort((costs, off))[0])
        return int(cells[k, 0]), int(cells[k, 1])

    def into_room(self, room: Any, value: str) -> Outcome:
        """Drive into a room, to :meth:`room_spot`: "goes to the kitchen (near its middle)"."""
        cell = self.room_spot(room)
        if cell is None:
            return Fatal(False, f"cannot drive into {value}")
        self.drive_to(cell, f"goes to the {spoken(value)} (near its middle)")
        return Outcome(True, f"in {value}")

    def look_once(self, value: str, binding: Binding) -> Outcome | None:
        """One look for a thing of kind ``value``: go to the view the policy chooses, open what it
        says to open, and look. An Outcome when the search must stop instead."""
        if self.told and self.look_where_said(value, binding) is not None:
            return None
        if not self.recognises(value):
            if self.sweeper is None:
                return Fatal(False, f"cannot recognise {value!r}: no class it knows is called that",
                             Reason.NOT_FOUND, value)
            return self.sweep_once(value, binding)
        if (ended := self.search_ended(value)) is not None:
            return ended
        view = self.policy.next_view(self, binding, value)
        if view is None:
            return Fatal(False, f"searched everywhere it could and found no {value}", Reason.NOT_FOUND, value)
        self.say("search", f"looks for {value}: {view.why}".rstrip(": "), target=value, view=view.cell)
        role = next((r for r, v in binding.values if v == value), None)
        if self.drive_to(view.cell, "goes to look", until=lambda: self.resolve(value, binding, role) is not None,
                         rethink=lambda: self.policy.reconsider(self, binding, value, view)):
            return None
        if view.open is not None:
            self.world.face(view.look_at)
            self.open_to_look(view.open)
        self.look_round(view.look_at)               # a narrow sensor turns round: a view sees all round
        if view.open is not None and self.resolve(value, binding, role) is None:
            self.shut_after(view.open)              # nothing sought in it: closed again, as a peek
        return None

    def is_person(self, value: str) -> bool:
        """Whether a value names a person of the world (by their own name)."""
        item = self.world.items.get(value)
        return item is not None and item.key == PERSON

    def _sought_person(self, value: str) -> bool:
        """Whether a value sought is someone: a person of the world, of the library's class person ("mum",
        whom the map does not name), or named as a person by the command ("tell Sophie ...", whom the map does not
        place: :attr:`names`). Nobody is looked for inside a fridge: the house search for them does not peek into
        closed places."""
        return self.is_person(value) or self.library.taxonomy.is_a(self.class_of(value), PERSON) is True or \
            class_key(value) in self.names

    def sweep_once(self, value: str, binding: Binding) -> Outcome | None:
        """One room of the whole-house search for a kind of thing nothing tells the robot where to
        look for (no prior, no class its perception knows): the nearest room not yet looked over
        (by the drive to it), surveyed with next-best views and into its closed receptacles
        (:meth:`survey`), then the rest of the house outside every room the same way, within the
        run's budget. One line a room; the drives and looks of the survey are details. An Outcome
        once the house has been searched."""
        role = next((r for r, v in binding.values if v == value), None)
        said = [p for p in self.said_places(value) if p not in self.inspected and p not in self.unreachable]
        if said and not self.world.items[said[0]].movable and self.sweep is None:   # the command's place first
            self.look_where_said_at(said[0], value, binding, role)
            return None
        if self.sweep is None and self.absent_said and (absent := self.absent_from_map(value)) is not None:
            return Fatal(False, absent, Reason.NOT_FOUND, value)
        if self.sweep is None:      # a room said and looked all over already is not looked over again
            done = [r for r in self.scene.map.rooms if (self.class_of(value), r.name) in self.missed_rooms]
            rooms = [r for r in self.scene.map.rooms if r not in done]
            self.sweep = [*self.room_tour(rooms), _Rest(self.scene.map.rooms)]
            self.swept = [(r.name.replace("_", " "), Outcome(True, "looked all over")) for r in done]
        if not self.sweep:
            return Fatal(False, self._swept_house(value), Reason.NOT_FOUND, value)
        region = self.sweep.pop(0)
        if not np.isfinite(self._drive_into(region, self.distances())):
            return None
        self.say("search", f"searches the whole house for {self.said(value)}: looks all over the "
                 f"{region.name.replace('_', ' ')}", target=value, room=region.name)
        self.detail = True
        try:
            looked = self.survey(region, peek=not self._sought_person(value))
        finally:
            self.detail = False
        self.swept.append((region.name.replace("_", " "), looked))
        if looked.reason is Reason.BUDGET:
            return Fatal(False, looked.message, Reason.BUDGET)
        return None

    def absent_from_map(self, value: str) -> str | None:
        """Why a thing need not be searched for at all: the map names no such thing — no prior, object or place
        of it, nor of a kind of it — and the robot's perception knows the map's classes only
        (:attr:`Scene.vocabulary`, the classes present), so a whole-house search could not end otherwise. Said
        at once, with what the map has of its kind (:meth:`Taxonomy.kin <seal_cli.frames.taxonomy.Taxonomy.kin>`:
        "bring me a cup" on a map with mugs), the user's next word. None when it may be there: the map names
        it or a kind of it, the scene knows no classes, or it is someone (a person is searched for by name)."""
        known = [class_key(c) for c in self.scene.vocabulary]
        cls = self.class_of(value)
        taxonomy = self.library.taxonomy
        if not known or cls in known or self._sought_person(value) or class_key(value) in self.names or \
                any(taxonomy.is_a(k, cls) is True for k in known):
            return None
        m = self.scene.map
        looked = [located(r, m) for c, r in sorted(self.missed_rooms) if c == cls] + \
            [f"in the {p}" for p in self.said_places(value) if p in self.missed]
        if looked:      # "bring me a mug from the kitchen": it looked there, as the command said, and nowhere else
            said = f"no {self.said(value)} found: none {' or '.join(looked)}, where the command said, and " \
                   f"the {m.name.replace('_', ' ')} map names none elsewhere (no prior, object or place of one), so " \
                   "the robot did not search the rest of the house"
        else:
            said = f"no {self.said(value)} found: the {m.name.replace('_', ' ')} map names none (no prior, object " \
                   "or place of one), so the robot did not search the house"
        kin = taxonomy.kin(cls)
        alike = [k for k in m.kinds() if kin is not None and k in kin[1]]
        if kin is not None and alike:
            said += f"; of its kind ({kin[0]}) the map has: {', '.join(k.replace('_', ' ') for k in alike)}"
        return said + m.spelt_like(cls, words=taxonomy.known_classes)

    def _drive_into(self, region: Any, field_: np.ndarray) -> float:
        """Metres to the nearest free cell of a region (inf when none can be reached)."""
        cells, points = self.grid.free_cells, self.grid.free_points
        inside = np.asarray(region.contains(points), dtype=bool)
        costs = field_[cells[inside, 0], cells[inside, 1]]
        return float(costs.min()) if len(costs) else math.inf

    def room_tour(self, rooms: Sequence[Any]) -> list[Any]:
        """The rooms in the order that drives least from where the robot is to each room's middle
        (its free cell nearest its centroid) in turn: every order when there are at most
        :data:`TOUR_EXACT` rooms, else the nearest room next. Rooms it cannot drive into go last."""
        cells, points = self.grid.free_cells, self.grid.free_points
        middles: list[Cell] = []
        for room in rooms:
            inside = np.flatnonzero(np.asarray(room.contains(points), dtype=bool))
            if not len(inside):
                middles.append(self.robot_cell())
                continue
            k = inside[int(np.argmin(np.hypot(*(points[inside] - np.asarray(room.centroid)).T)))]
            middles.append((int(cells[k, 0]), int(cells[k, 1])))
        start = self.distances()
        fields = [self.grid.distances(c) for c in middles]
        first = np.array([start[c] for c in middles])
        between = np.array([[f[c] for c in middles] for f in fields])
        reachable = [i for i in range(len(rooms)) if np.isfinite(first[i])]
        if len(reachable) <= TOUR_EXACT:
            order = min(itertools.permutations(reachable), default=(), key=lambda o: first[o[0]] + sum(
                between[a, b] for a, b in itertools.pairwise(o)))
        else:
            order, left = (), set(reachable)
            while left:
                here = first if not order else between[order[-1]]
                order += (min(left, key=lambda i: here[i]),)
                left.discard(order[-1])
            order = _two_opt(order, first, between)
        return [rooms[i] for i in order] + [r for i, r in enumerate(rooms) if i not in order]

    def _swept_house(self, value: str) -> str:
        """The one sentence that ends a whole-house search that found nothing."""
        rooms = [name for name, _ in self.swept if name != _Rest.name]
        partly = [name for name, looked in self.swept if not looked.ok]
        opened = sorted(self.opened)
        said = f"searched the whole house: no {self.said(value)}"
        detail = []
        if rooms:
            detail.append(f"looked all over {len(rooms)} room{'' if len(rooms) == 1 else 's'}")
        if opened:
            detail.append(f"into {', '.join(opened)}")
        if partly:
            detail.append(f"could not see all of {', '.join(partly)}")
        said = f"{said} ({'; '.join(detail)})" if detail else said
        kin = self.library.taxonomy.kin(self.class_of(value))
        alike = [k.id for k in self.known.values() if k.movable and kin is not None and k.cls in kin[1]] \
            if kin is not None else []
        if alike:                # "bring me a cup" where there is a mug: what the user may have meant, not taken
            said += f"; of its kind ({kin[0] if kin else ''}) it saw: {'; '.join(self.where_is(i) for i in alike[:3])}"
        return said

    def wait(self, binding: Binding) -> Outcome:
        """``wait()``: stay put, doing nothing; said as where it waits (its room) and for whom (the theme)."""
        outcome = self.world.act("wait")
        if not outcome.ok:
            return outcome
        x, y = self.world.robot.pose[:2]
        where = self._in_room_at(x, y) or " where it is"
        who = binding.elements.get("theme")
        whom = "" if who is None else " for the speaker" if who == "me" else f" for {self.said(who)}"
        self.say("act", f"waits{where}{whom}", action="wait", args=[])
        return outcome

    def said(self, value: str) -> str:
        """A value as a person would say it: its class, with spaces (``apple_2``: apple)."""
        return self.class_of(value).replace("_", " ")

    def search_for(self, value: str, binding: Binding) -> Outcome:
        """``search(value)``: look (as ``navigate`` would) until a thing of that kind is known, go back
        to where it was seen if it is out of sight now, and see it. With a ``ground`` (a room or a
        place: "is there a cup in the kitchen?") only there (:meth:`search_in`)."""
        role = next((r for r, v in binding.values if v == value), None)
        ground = binding.elements.get("ground")
        question = self.questions.get(binding)
        if ground is not None and not self.is_person(value) and not self._is_place(value) \
                and (self.room(ground) is not None or self._is_place(ground)):     # a map place: known
            return self.search_in(value, binding, ground, question)
        if ground is None and (room := self.room(value)) is not None:      # "where is the kitchen?": the map's
            went = self.go_to(value, binding)                                # room, driven into, not searched for
            if not went.ok:
                return went
            x, y = room.centroid
            self.answer(f"the {spoken(value)} is the room around ({x:.2f}, {y:.2f})")
            return Outcome(True, f"is {located(room.name, self.scene.map)}")
        if self.is_person(value) and not self.world.within_reach(value):    # told where: goes to see them
            went = self.go_to(value, binding)
            if not went.ok:
                return went
        every = question is not None and question.every and not self.is_person(value)
        short = self.look_where_kept(self.said(value), spots, self.class_of(value)) \
            if every and (spots := self.kept_spots(value)) else []
        while self.resolve(value, binding, role) is None:
            if (stop := self.exhausted()) is not None:
                return Fatal(False, stop, Reason.BUDGET)
            if (ended := self.look_once(value, binding)) is not None:
                if ended.reason is Reason.NOT_FOUND:
                    said = ended.message.startswith(("searched the whole house", f"no {self.said(value)} found"))
                    no = ended.message if said else f"no {self.said(value)} found: {ended.message}"
                    if question is not None and question.kind == "whether":     # "is mum home?": no is an answer
                        self.answer(f"no: {no}")
                        return Outcome(True, no)
                    self.answer(no)
                return ended
        target = self.resolve(value, binding, role)
        if every and target is not None and not (target in self.known and self.in_view(target)):
            n = self.answer_every(value, short)     # it knows where each one is: no drive back to see one again
            knows = f"knows where {counted(n, self.said(value))} {'is' if n == 1 else 'are'}"
            self.say("act", knows, action="search", args=[value], detail=True)
            return Outcome(True, knows)
        if target is not None and target in self.known and not self.in_view(target):
            went = self.go_to(value, binding)     # seen before, from elsewhere: back to where it was seen
            if not went.ok:
                return went
        if target is not None and target in self.known:
            self.world.face(self.known[target].at)
            if every:                   # found where the map keeps them, shut in again after the look: shown once more
                self._show_inside(target)
            answer = self.where_is(target)
            if question is not None and question.kind == "whether":
                answer = self._whether_person(target, ground, answer)
            if every:
                self.answer_every(value, short)
            else:
                self.answer(answer)
        return self._act_words("search", [value])

    def _show_inside(self, item_id: str) -> None:
        """Open again the closed place within reach that a thing the robot found inside it lies in, to show it."""
        parent = self.world.items.get(self.world.items[item_id].parent or "")
        if parent is not None and parent.openable and not parent.is_open and self.world.within_reach(parent.id):
            self.open_to_look(parent.id)
            self.look(quiet=True)

    def answer_every(self, value: str, short: Sequence[str]) -> int:
        """"Where are the towels?": where each thing of the kind the robot knows is (the one in its hand, those it
        saw where the map keeps them, on the way, or where it left them), in the map's order; and where it could not
        look. How many it said."""
        key = self.class_of(value)
        held = self.held()
        ids = set(self.present(key))
        ids |= {held.id} if held is not None and held.key == key else set()
        order = list(self.world.items)
        for item_id in sorted(ids, key=order.index):
            self.answer(self.where_is(item_id))
        if short:
            self.answer(f"it could not look at {', '.join(short)}")
        return len(ids)

    def _search_people(self, value: str, binding: Binding, ground: str, question: Question | None) -> Outcome:
        """Anyone in a room: look all over it, and go to the nearest person seen there (yes, and
        where), or say nobody is there (the answer to a question, not found for a command)."""
        where, _, complete = self.look_over(ground, peek=False)
        people = self.people_seen_in(self.room(ground))
        if people:
            target = self.nearest([self.known[p] for p in people if p in self.known]) or people[0]
            self.chosen[class_key(value)] = target
            went = self.go_to(target, binding)
            if not went.ok:
                return went
            answer = self.where_is(target)
            self.answer(f"yes: {answer}" if question is not None and question.kind == "whether" else answer)
            return Outcome(True, answer)
        but = self.but_you(self.room(ground))
        no = f"nobody {where}{but} (it looked all over it)" if complete else \
            f"nobody seen {where}{but}, but it could not look all over it ({complete.message})"
        self.answer(no)
        if question is not None and question.kind == "whether":
            return Outcome(True, no)
        return Fatal(False, no, Reason.NOT_FOUND, value)

    def but_you(self, room: Any) -> str:
        """" but you" when the speaker stands in the room asked about ("is anyone in the living room?" said
        there: "nobody in the living room but you"), else ""."""
        speaker = self.world.items.get(SPEAKER)
        return " but you" if speaker is not None and room is not None and bool(room.contains([speaker.at])[0]) \
            else ""

    def people_seen_in(self, room: Any) -> list[str]:
        """The people (not the speaker) the robot's last looks saw in a room."""
        return [i.id for i in self.world.items.values() if i.key == PERSON and i.id != SPEAKER
                and room is not None and bool(room.contains([i.at])[0]) and self._seen_person(i.id)]

    def _is_place(self, value: str) -> bool:
        item = self.world.items.get(value)
        return item is not None and not item.movable and item.key != PERSON

    def _whether_person(self, person: str, ground: str | None, where: str) -> str:
        """Yes or no to "is Anna in the kitchen?", from where the robot found her."""
        room = self.room(ground) if ground else None
        if room is None:
            return f"yes: {where}"
        inside = bool(room.contains([self.world.position(person)])[0])
        return f"yes: {where}" if inside else f"no: {where}"

    def in_view(self, item_id: str) -> bool:
        """Whether the robot sees the thing from where it stands (a person: has them within reach)."""
        if self.is_person(item_id):
            return self.world.within_reach(item_id)
        return self.world.held_chain(item_id) or any(d.id == item_id for d in self.world.observe())

    def search_in(self, value: str, binding: Binding, ground: str, question: Question | None) -> Outcome:
        """Look for a thing where the command says, and only there: all over a room (and into its
        closed receptacles), or at a place (into it if it opens). Yes and where, or no; a "no" is
        the answer to a question ("is there ..."), and not found for a command ("find the cup in the
        kitchen"). Things the robot saw elsewhere are mentioned, never the map's hidden truth."""
        key = self.class_of(value)
        if key == PERSON and self.room(ground) is not None:      # "is there anyone in the kitchen?"
            return self._search_people(value, binding, ground, question)
        where, found, complete = self.look_over(ground, sought=key)
        found = [k for k in found if k.cls == key]
        if found:
            target = self.nearest(found) or found[0].id
            self.chosen[class_key(value)] = target
            if not self.in_view(target):         # seen earlier in the survey: back to it
                went = self.go_to(value, binding)
                if not went.ok:
                    return went
            shut = self.world.enclosure(target)
            if shut is not None and self.world.within_reach(shut.id):     # seen inside: open it to show it
                self.open_to_look(shut.id)
            self.world.face(self.known[target].at)
            answer = self.where_is(target)
            self.answer(f"yes: {answer}" if question is not None and question.kind == "whether" else answer)
            return self._act_words("search", [value])
        said = self.said(value)
        elsewhere = [k.id for k in self.known.values() if k.cls == key and k.movable and k.id in self.world.items]
        also = f"; elsewhere it saw: {'; '.join(self.where_is(i) for i in elsewhere[:3])}" if elsewhere else ""
        if complete:
            no = f"no {said} {where} (it looked all over it){also}"
        else:
            no = f"no {said} seen {where}, but it could not look all over it ({complete.message}){also}"
        self.answer(no)
        if question is not None and question.kind == "whether":
            return Outcome(True, no)
        return Fatal(False, no, Reason.NOT_FOUND, value)

    def look_over(self, ground: str, peek: bool = True, sought: str | None = None) -> tuple[str, list[Known], Outcome]:
        """Look all over a room (with ``peek``, into its closed receptacles too) or at a place: how to
        say where (``in the kitchen``, ``on desk_1``), the movable things the robot knows to be there,
        and whether it could look at all of it. ``sought``: a class whose first sight in the room ends
        the survey ("is there a spoon in the kitchen?" needs one spoon, not the rest of the room)."""
        room = self.room(ground)
        if room is not None:
            def seen() -> bool:
                return any(k.cls == sought and k.movable and k.id in self.world.items
                           and bool(room.contains([self.world.position(k.id)])[0]) for k in self.known.values())

            until = seen if sought is not None else None
            complete = self.survey(room, peek=peek, until=until) if self.sweeper is not None else Outcome(
                False, "it cannot survey a room in this world")
            inside = [k for k in self.known.values() if k.movable and k.id in self.world.items
                      and not self.world.held_chain(k.id)
                      and bool(room.contains([self.world.position(k.id)])[0])]
            return located(room.name, self.scene.map), inside, complete
        place = self.world.items[ground]
        complete = Outcome(True, "looked")
        if not self.world.within_reach(ground):
            cell = self.stand_cell(self.known[ground])
            if cell is None:
                complete = Outcome(False, f"{ground} cannot be reached")
            else:
                self.drive_to(cell, f"goes to {ground}")
        if complete.ok:
            self.world.face(place.at)

            def found_inside() -> bool:                # what it looks for is inside: kept open to show it
                return sought is not None and any(k.cls == sought and k.movable and k.parent == ground
                                                  for k in self.known.values())

            complete = self.peek(ground, found_inside) if place.openable and not place.is_open else \
                Outcome(True, "looked")
            self.look()
        on = [k for k in self.known.values() if k.movable and k.parent == ground and k.id in self.world.items
              and self.world.items[k.id].parent == ground]
        return f"{'in' if place.openable else 'on'} {ground}", on, complete

    def peek(self, place: str, keep_open: Callable[[], bool] | None = None) -> Outcome:
        """Open a closed place within reach, look inside, and close it again (as it was found), unless
        ``keep_open()`` says what it saw is to be shown there."""
        opened = self.world.act("open", place)
        self.say("act" if opened.ok else "fail", opened.message, action="open", args=[place])
        if not opened.ok:
            return Outcome(False, f"could not open {place}: {opened.message}")
        self.opened.add(place)
        self.look()
        if keep_open is not None and keep_open():
            return Outcome(True, f"looked into {place}")
        closed = self.world.act("close", place)
        self.say("act" if closed.ok else "fail", closed.message, action="close", args=[place],
                 **({"detail": True} if self.detail and closed.ok else {}))
        return Outcome(True, f"looked into {place}")

    def answer(self, text: str) -> None:
        """Keep what the robot found out for the question (said once)."""
        text = self.named(text)
        if text not in self.answers:
            self.answers.append(text)
            self.say("answer", f"answer: {text}", answer=text)

    def _act_words(self, name: str, args: list[str], said: str | None = None) -> Outcome:
        """A primitive on words (a kind of thing, a message); ``said``: what the record says the robot
        did instead of the world's own words (the answer it gives, not the message's name)."""
        outcome = self.world.act(name, *(a if self.is_person(a) else self.class_of(a) for a in args))
        text = said if said is not None and outcome.ok else outcome.message
        text = self.named(text)
        again = text in {r.text for r in self.records[-3:]} or any(text.endswith(f": {a}") for a in self.answers) \
            or name == "search" and outcome.ok and bool(self.answers)     # the answer said where it is
        # "sees spoon_1" said by the look just now, "says: <the answer>": kept, not narrated twice
        self.say("act" if outcome.ok else "fail", text, action=name, args=list(args),
                 **({"detail": True} if again else {}))
        return outcome

    def answer_what(self, question: Question, binding: Binding) -> Outcome:
        """"What is on the dining table?", "who is in the kitchen?": go and look, then say what
        the robot saw there (and that it could not look at all of it, if so)."""
        assert question.about is not None
        where, found, complete = self.look_over(question.about, peek=question.asks_for != "person")
        if question.asks_for == "person":
            names = self.people_seen_in(self.room(question.about))
            nothing = f"nobody {where}{self.but_you(self.room(question.about))}"
        else:
            names = [k.id for k in found]
            nothing = f"nothing {where}"
        said = f"{where}: {', '.join(names)}" if names else nothing
        if not complete:
            said += f" (it could not look all over it: {complete.message})"
        self.answer(said)
        recipient = binding.elements.get("recipient")
        if recipient is not None and recipient in self.world.items:
            went = self.go_to(recipient, binding)
            if not went.ok:
                return went
        if "message" not in binding.elements:
            return Outcome(True, said)
        told = f'said "{self.in_words(said)}"' if recipient is not None and recipient != SPEAKER else f"says: {said}"
        return self._act_words("say", [binding.elements["message"]], told)   # to another: narrated

    def _seen_person(self, person: str) -> bool:
        at = np.asarray([self.world.items[person].at], dtype=float)
        return any(bool(np.asarray(self.world.sensor.visible(pose, at))[0]) for pose in self.looks[-SURVEY_VIEWS * 4:])

    def _in_room_at(self, x: float, y: float) -> str:
        """" in the family room" (" on the balcony") for a point in a room of the map; "" outside every room (or with
        none)."""
        rooms = self.scene.map.room_of([(x, y)]) if self.scene.map.rooms else []
        return f" {located(rooms[0], self.scene.map)}" if rooms and not rooms[0].startswith("_") else ""

    def where_is(self, item_id: str) -> str:
        """Where a thing is, as the answer to "where is it?": on or in its place, in its room, at x, y."""
        item = self.world.items[item_id]
        x, y = self.world.position(item_id)
        room = self._in_room_at(x, y)
        parent = self.world.items.get(item.parent) if item.parent and item.parent != HAND else None
        if self.world.held_chain(item_id):
            return f"{item_id} is in the robot's hand"
        on = f" {'in' if parent.openable else 'on'} {parent.id}" if parent is not None else ""
        return f"{item_id} is{on}{room} at ({x:.2f}, {y:.2f})"

    def recognises(self, value: str) -> bool:
        """Whether the robot could see a thing of this kind: its class is one of the scene's (the
        classes its perception knows). A word the command grounded to no class is never seen, so
        it is not searched for."""
        known = self.scene.vocabulary
        return not known or self.class_of(value) in {class_key(c) for c in known}

    def open_to_look(self, place: str) -> None:
        if self._open_or_close(place, True):
            self.opened.add(place)
            self.ajar.add(place)

    def needs_open(self, place: str) -> bool:
        """Whether a frame still to come in the plan needs the place open (``open`` among its preconditions)."""
        names = {place, self.world.items[place].key}
        return any(f.predicate == "open" and not f.negated and f.args and f.args[0] in names
                   for b in self.steps[self.index + 1:] for f in b.preconditions)

    def shut_after(self, place: str | None) -> None:
        """Close again a receptacle the robot opened only to look into, take from or put into (as it closes
        the fridge it peeked into), before it goes on, unless the plan still needs it open."""
        if place is None or place not in self.ajar or self.needs_open(place):
            return
        self.ajar.discard(place)
        if self.world.items[place].is_open and self.world.within_reach(place) and self._open_or_close(place, False):
            self.left_open.discard(place)

    def commanded(self, binding: Binding) -> bool:
        """Whether the frame at hand is one the command said, not one the planner put in for it."""
        return bool(self.todo) and binding == self.todo[0]

    def close_to_use(self, place: str) -> None:
        """Close what must be shut for the action (a microwave before it is switched on)."""
        if self._open_or_close(place, False):
            self.left_open.discard(place)

    def _open_or_close(self, place: str, opening: bool) -> bool:
        """Open or close a place, say so, and keep the planning state's ``open`` fact in step; whether it did."""
        name = "open" if opening else "close"
        outcome = self.world.act(name, place)
        self.say("act" if outcome.ok else "fail", outcome.message, action=name, args=[place])
        if outcome.ok:
            fact = Fact("open", (self.world.items[place].key,))
            facts = set(self.state.facts) | {fact} if opening else set(self.state.facts) - {fact}
            self.state = State.of(facts, self.state.taxonomy, closable=self.state.closable, classes=self.state.classes)
        return outcome.ok

    def drive_to(self, cell: Cell, why: str, until: Callable[[], bool] | None = None,
                 rethink: Callable[[], str | None] | None = None) -> bool:
        """Drive the shortest path to the cell, looking every ``look_every`` metres and at the end. A drive
        to look for something stops at the look that finds it (``until()`` true), or where what it saw on
        the way makes another view better (``rethink()`` says why): returns whether it stopped short."""
        start = self.robot_cell()
        if cell == start:
            return False
        path = self.grid.path(start, cell)
        points = [self.grid.point(c) for c in path[1:]]
        metres = 0.0
        since_look = 0.0
        chunk: list[tuple[float, float]] = []
        prev = self.world.robot.pose[:2]
        for p in points:
            chunk.append(p)
            step = math.dist(prev, p)
            prev = p
            since_look += step
            if since_look >= self.look_every and p != points[-1]:
                metres += self.world.drive(self._affordable(chunk))
                chunk, since_look = [], 0.0
                if self.exhausted():  # the budget is checked inside a leg, not only between legs
                    break
                self.look(quiet=True)
                if until is not None and until():
                    self.say("go", f"{why} ({metres:.2f} m): stops, what it looks for is in sight",
                             to=self.world.robot.pose[:2], metres=metres)
                    return True
                if rethink is not None and (reason := rethink()) is not None:
                    self.say("go", f"{why} ({metres:.2f} m): stops, {reason}", to=self.world.robot.pose[:2],
                             metres=metres)
                    return True
        else:
            metres += self.world.drive(self._affordable(chunk))
        self.say("go", f"{why} ({metres:.2f} m)", to=self.world.robot.pose[:2], metres=metres)
        return False

    def _affordable(self, waypoints: list[tuple[float, float]]) -> list[tuple[float, float]]:
        """The waypoints cut where the path budget runs out (the last one moved back along its segment)."""
        left = self.budget.metres - self.world.robot.path_m
        out: list[tuple[float, float]] = []
        prev = self.world.robot.pose[:2]
        for wp in waypoints:
            step = math.dist(prev, wp)
            if step >= left:
                if left > 1e-9:
                    f = left / step
                    out.append((prev[0] + f * (wp[0] - prev[0]), prev[1] + f * (wp[1] - prev[1])))
                return out
            left -= step
            out.append(wp)
            prev = wp
        return out

    def look(self, quiet: bool = False) -> list[Detection]:
        """Sense from where the robot is; remember what it sees; update the beliefs."""
        pose = self.world.robot.pose
        detections = self.world.observe()
        self.looks.append(pose)
        open_near = {k.id: k.movable for k in self.known.values() if k.id in self.world.items
                     and self.world.items[k.id].is_open and self.world.within_reach(k.id, pose)}
        self.inspected |= open_near.keys()          # places, and things looked into ("the lid off the pan")
        at_hand = {i for i, movable in open_near.items() if not movable}
        if self.unsearched:
            region = self.world.sensor.region(pose)
            seen = region.contains(self.scene.map.free_centres)
            for left in self.unsearched.values():
                left.saw(seen, at_hand)
        new = []
        for d in detections:
            item = self.world.items[d.id]
            if d.id not in self.known:
                new.append(d.id)
            self.known[d.id] = self._known(item)
        self.policy.observe(self, detections)
        if new:
            self.say("see", f"sees {', '.join(new)}", seen=new)
        elif not quiet:
            self.say("look", "looks around: nothing new", seen=[])
        return detections

    def do(self, action: Action, binding: Binding) -> Outcome:
        """A primitive other than navigate, on the instances its arguments denote; a closed
        receptacle in the way is opened, and the action tried once more."""
        if action.name in WORDS:  # a message to say, a kind of thing to count: words, not items
            if action.name == "search":
                return self.search_for(action.args[0], binding)
            question = self.questions.get(binding)
            if action.name == "say" and question is not None and question.kind == "what":
                return self.answer_what(question, binding)
            if action.name == "say" and question is not None and question.kind == "fact":
                return self.tell_fact(question.relation, binding)
            if action.name == "say" and question is not None and question.kind == "report":
                return self.report(binding)
            if action.name == "say" and question is not None and question.kind == "asked":
                return self.ask(binding)
            if action.name == "count":
                counted = self.how_many(action.args[0], binding)
                self.answer(counted)
                return self._act_words(action.name, list(action.args), f"counted: {counted}")
            if action.name == "say" and binding.elements.get("recipient") not in (None, SPEAKER):
                return self._act_words("say", list(action.args), f'said "{self.passed_on(action.args[0])}"')
            return self._act_words(action.name, list(action.args))
        if action.name == "wait":
            return self.wait(binding)
        roles = {v: r for r, v in binding.values}
        args: list[str] = []
        for value in action.args:
            if action.name == "lead" and args:       # where to: driven to after, by go_to
                args.append(value)
                continue
            target = self.resolve(value, binding, roles.get(value))
            if target is None:
                return Outcome(False, f"knows no {value} to {action.name.replace('_', ' ')}", Reason.NOT_FOUND, value)
            args.append(target)
        lay = self.world.items[args[0]].parent if action.name == "pick" and args[0] in self.world.items else None
        if action.name == "open" and self.commanded(binding):     # "open the larder": left open, even if the
            self.ajar.discard(args[0])                              # robot had opened it to look in already
        outcome = self.world.act(action.name, *args)
        if outcome.ok and action.name == "pick":
            self.picked_from[args[0]] = lay
            self.taken_from.setdefault(args[0], lay)
            outcome = replace(outcome, message=outcome.message + self._not_where_said(args[0], lay))
        if outcome.reason is Reason.INSIDE_CLOSED and outcome.about is not None:
            self.open_to_look(outcome.about)
            outcome = self.world.act(action.name, *args)
        if outcome.reason is Reason.CLOSED and action.name == "place":
            self.open_to_look(args[1])
            outcome = self.world.act(action.name, *args)
        if outcome.reason is Reason.OPEN and outcome.about is not None:   # a microwave left open: shut it first
            self.close_to_use(outcome.about)
            outcome = self.world.act(action.name, *args)
        if outcome.reason is Reason.NOT_RECEPTACLE and action.name in PUTS:
            outcome, args = self.put_beside(args[0], args[1], outcome)
        if outcome.ok and action.name == "lead":     # the person follows the robot there
            self.say("act", f"asks {args[0]} to follow", action="lead", args=args)
            arrived = self.go_to(action.args[1], binding)
            self.world.following = None
            if args[0] in self.known:       # the robot knows where the one it led now stands: beside it
                self.known[args[0]] = replace(self.known[args[0]], at=self.world.items[args[0]].at)
            if not arrived.ok:
                return arrived
            where = action.args[1]
            outcome = Outcome(True, f"led {args[0]} to " + (f"the {spoken(where)}" if self.room(where) is not None
                                                           else where))
        self.say("act" if outcome.ok else "fail", outcome.message, action=action.name, args=args)
        if outcome.ok:
            self._after(action.name, args, binding)
            if action.name in ("pick", *PUTS):         # taken out of it, or put into it: shut it again
                self.shut_after(lay if action.name == "pick" else args[1])
            question = self.questions.get(binding)
            if action.name == "look_at" and question is not None and question.kind == "state":
                self.answer(self.state_answer(args[0], question.relation))
        elif outcome.reason in (Reason.OUT_OF_REACH, Reason.BEHIND_WALL):
            self.look()
        return outcome

    def now(self) -> datetime:
        """The robot's clock: the run's start and the time its driving has taken, or the computer's."""
        if self.clock is None:
            return datetime.now()
        return self.clock + timedelta(seconds=self.world.robot.path_m / ROBOT_SPEED)

    def report(self, binding: Binding) -> Outcome:
        """Say what the command's earlier frames found out ("find the cup and tell me where it is"), not the
        message's words; said to someone else, it is not the speaker's answer again."""
        said = "; ".join(self.answers) if self.answers else "it found out nothing to tell"
        if binding.elements.get("recipient") not in (None, SPEAKER):
            said = self.in_words(said)
        return self._act_words("say", [binding.elements.get("message", "report")], f'said "{said}"')

    def ask(self, binding: Binding) -> Outcome:
        """Put a question to the person (``recipient``; "ask Raj if he wants tea"): the message's name as the question
        the parser made of it ("do you want tea?"), narrated as asked of them. The simulator's people do not speak,
        so what the robot brings back to the speaker (the run's answer) says plainly that the person gave none
        ("Raj gave no answer (...)"), rather than leaving the speaker to wonder what was said."""
        asked = said_words(str(binding.elements.get("message", ""))).strip()
        person = binding.elements.get("recipient")
        put = asked     # to another, "ask Sam if I can ...": the speaker's "I" (back to the speaker: as said)
        if person not in (None, SPEAKER):
            put = asked_for(asked, self.sender())
        whom = f" {person}" if person is not None and person != SPEAKER else ""
        outcome = self._act_words("say", [binding.elements.get("message", asked)], f'asked{whom} "{put}?"')
        if outcome.ok and whom:
            self.answer(f'{person} gave no answer to "{asked}?" (the simulator\'s people do not speak)')
            if self.index + 1 >= len(self.steps) and SPEAKER in self.world.items:
                return self.report_back(f'{person} gave no answer to "{asked}?"', binding)
        return outcome

    def report_back(self, said: str, binding: Binding) -> Outcome:
        """Bring what a person answered back to whoever asked (the question the command's last step): drive to the
        speaker and say it there ("tells the speaker that Raj gave no answer ..."). A later step of the command
        takes the robot on instead (the run's answer line says it all the same)."""
        went = self.go_to(SPEAKER, binding)
        if not went.ok:
            return went
        return self._act_words("say", ["report"], f"tells the speaker that {said}")

    def report_unfound(self, outcome: Outcome, binding: Binding) -> None:
        """Someone the command was for who is nowhere to be found ("ask Raj if he wants tea", no Raj in the house):
        the robot comes back to whoever asked and says so there (e2e22), as it brings back a person's answer, rather
        than stopping where the search ended. The run still ends not done (the person was not asked); a thing not
        found is said as before, where the search ended (what the speaker asked for is not with them either way)."""
        who = outcome.about
        if who is None or who == SPEAKER or SPEAKER not in self.world.items or not self._sought_person(who) \
                or self.exhausted():
            return
        if self.go_to(SPEAKER, binding).ok:
            name = self.said(who)
            how = without_not_found(self.in_words(outcome.message), name)
            self._act_words("say", ["report"], f"tells the speaker that it did not find {name}"
                            + (f" ({how})" if how else ""))

    def passed_on(self, message: str) -> str:
        """A message told to someone other than the speaker, as the robot passes it on: the speaker's "I" said as
        the speaker, a "he"/"she" that can only be the hearer said as "you" (:mod:`seal_cli.sim.relaying`)."""
        return relayed(said_words(message), self.sender(), hearer=True)

    def sender(self) -> str:
        """Who the robot passes a message or a question on from: "the doctor" where the map calls the speaker so,
        else :data:`~seal_cli.sim.relaying.SENDER`."""
        roles = self.scene.map.speaker_roles
        return f"the {spoken(roles[0])}" if roles else SENDER

    def in_words(self, text: str) -> str:
        """An answer as said to a person, not printed for the speaker's record: a thing's or place's id as its
        kind ("mug_1 is on dining_table_1 in the dining room": "the mug is on the dining table in the dining
        room"), and no coordinates."""
        def kind(match: re.Match[str]) -> str:
            item = self.world.items.get(match.group(0))
            return f"the {spoken(item.cls)}" if item is not None and item.key != PERSON else match.group(0)

        text = re.sub(r" at \(-?\d+(?:\.\d+)?, -?\d+(?:\.\d+)?\)", "", text)
        return re.sub(r"\b[A-Za-z][A-Za-z0-9_]*_\d+\b", kind, text)

    def tell_fact(self, fact: str, binding: Binding) -> Outcome:
        """Say what the robot knows without looking ("the time is 14:05", "the date is 2 December 2026");
        to the speaker (no recipient, or "me") it is also the answer."""
        now = self.now()
        said = {"time": f"the time is {now:%H:%M}", "date": f"the date is {now.day} {now:%B %Y}",
                "day": f"today is {now:%A}"}[fact]
        recipient = binding.elements.get("recipient")
        if recipient is None or recipient == SPEAKER:
            self.answer(said)
        return self._act_words("say", [binding.elements.get("message", fact)], f'said "{said}"')

    def state_absent(self, binding: Binding, question: Question) -> Outcome | None:
        """A state question about a thing said to be somewhere ("is the window open in the bedroom?"): the
        robot looks there first; a thing it does not find there is the answer ("no window in the bedroom
        (it looked all over it)"), else None and the thing is looked at as found."""
        theme = binding.elements.get("theme")
        if question.about is None or theme is None or self._is_place(theme) or theme in self.world.items:
            return None
        where, found, complete = self.look_over(question.about)
        found = [k for k in found if k.cls == self.class_of(theme)]
        if found:
            self.chosen[class_key(theme)] = self.nearest(found) or found[0].id
            return None
        no = f"no {self.said(theme)} {where}" + (" (it looked all over it)" if complete else
                                                f", but it could not look all over it ({complete.message})")
        self.answer(no)
        return Outcome(True, no)

    def state_known(self, binding: Binding, question: Question) -> Outcome | None:
        """A question of whether a place of the map is open or closed ("is the fridge open?"), answered where the
        robot stands, as "close the fridge" is when it is shut (:meth:`_open_already`): the map records whether
        each place is open (``open:``) and only the robot opens and closes things, so this is what it knows, and
        driving over to look would tell it nothing new. A state the map does not record (a lamp on, a cup clean,
        a fridge empty) it goes and looks at; None then."""
        theme = binding.elements.get("theme")
        words = question.relation.lower().split() or [""]
        if (theme is None or STATE_WORDS.get(words[-1], (None, True))[0] != "open" or theme not in self.world.items
                or not self._is_place(theme) or not self.world.items[theme].openable):
            return None
        place = self.scene.map.place(theme)
        as_mapped = place is not None and place.open == self.world.items[theme].is_open
        how = "as the map has it" if as_mapped else "as it left it"
        said = f"{self.state_answer(theme, question.relation)} ({how})"
        self.answer(said)
        return Outcome(True, said)

    def state_answer(self, item_id: str, word: str) -> str:
        """Whether a thing the robot is looking at is in the state a question asks ("is the fridge
        open?": "no: fridge_1 is closed"), from what it sees (:data:`STATE_WORDS`); what it cannot
        sense, or a state the thing never has, is said as such."""
        item = self.world.items[item_id]
        words = word.lower().split() or [""]         # "still on": on; "not open": whether it is closed
        state, holds = STATE_WORDS.get(words[-1], (None, True))
        holds = holds != ("not" in words[:-1] or "n't" in words[:-1])
        if state is None:
            return (f"it cannot tell whether {item_id} is {word}: it sees whether a thing is "
                    "open, on, clean, hot, cold, sliced or empty")
        if state == "open" and not item.openable or state == "on" and not item.toggleable:
            return f"{item_id} does not {'open or close' if state == 'open' else 'switch on or off'}"
        if state == "empty":
            if item.openable and not item.is_open:
                self.peek(item_id)            # looks inside, and closes it again
            inside = sorted(i.id for i in self.world.items.values() if i.parent == item_id and i.id in self.known)
            yes = not inside if holds else bool(inside)
            return f"{'yes' if yes else 'no'}: " + (f"{item_id} holds {', '.join(inside)}" if inside
                                                     else f"{item_id} is empty")
        now = item.is_open if state == "open" else state in item.states
        yes_no = {"open": ("open", "closed"), "on": ("on", "off")}.get(state, (state, f"not {state}"))
        return f"{'yes' if now == holds else 'no'}: {item_id} is {yes_no[0] if now else yes_no[1]}"

    def how_many(self, value: str, binding: Binding) -> str:
        """How many things of a kind there are where the command says: in a room, every one the
        robot has seen there once it has looked all over the room and into its closed receptacles
        (:meth:`look_over`); at a place, those on or in it; elsewhere, those it sees from where it
        counts. Said with how far it could look, when it could not look at all of it."""
        key = self.class_of(value)
        ground = binding.elements.get("ground")
        noun = key.replace("_", " ")
        if self._is_place_class(key) and (ground is None or self.room(ground) is not None):
            return self._count_places(key, noun, ground)      # the map says where its furniture stands
        if ground is not None and (self._is_place(ground) or self.room(ground) is not None and self.sweeper):
            where, found, complete = self.look_over(ground)
            n = sum(1 for k in found if k.cls == key) + len(self._fixed_in(key, ground))
            note = "" if complete else f" seen, but it could not look all over it ({complete.message})"
            return f"{counted(n, noun)} {where}{note}{self._none_known(key, noun, n)}"
        if ground is None and key in self.kept and (spots := self.kept_spots(value)):
            return self._count_where_kept(key, noun, spots)
        if ground is None and self.sweeper is not None and self.scene.map.rooms:
            return self._count_in_house(key, noun)
        n = sum(class_key(d.cls) == key for d in self.world.observe())
        where = f" {located(ground, self.scene.map)}" if ground else " in view"
        return f"{counted(n, noun)}{where}"

    def _count_in_house(self, key: str, noun: str) -> str:
        """"How many cups are there?": every room looked all over (nearest room first, as the crow
        flies), then the things of the kind the robot knows, wherever it saw them."""
        left = list(self.scene.map.rooms)
        unseen: list[str] = []
        while left:
            here = np.asarray(self.world.robot.pose[:2], dtype=float)
            room = min(left, key=lambda r: float(np.hypot(r.centroid[0] - here[0], r.centroid[1] - here[1])))
            left.remove(room)
            _, _, complete = self.look_over(room.name)
            if not complete.ok:
                unseen.append(room.name.replace("_", " "))
            if self.exhausted() is not None:
                unseen.extend(r.name.replace("_", " ") for r in left)
                break
        n = len(self.present(key))
        note = f" seen, but it could not look all over {', '.join(unseen)}" if unseen else ""
        return f"{counted(n, noun)} in the house{note}{self._none_known(key, noun, n)}"

    def kept_spots(self, value: str) -> list[str]:
        """Where the map's priors keep a thing of this kind: every place the prior names (by its name or its
        class: "plate: {cupboard: 0.6}" names each cupboard) and every room it names; empty for a kind the map
        has no prior of."""
        from seal_cli.planning.keeping import prior_of

        prior = prior_of(self.scene.map.priors, self.class_of(value))
        if not prior:
            return []
        places = [k.id for k in self.known.values() if not k.movable and k.receptacle and self.prior_names(k, value)]
        rooms = [r.name for r in self.scene.map.rooms if class_key(r.name) in prior]
        return [*rooms, *places]

    def _count_where_kept(self, key: str, noun: str, spots: list[str]) -> str:
        """"All the plates" (e2e24): every room and place the priors keep the kind in is looked all over or into
        (the nearest next, as the crow flies), not the whole house; then the things of the kind the robot knows,
        wherever it saw them (those it saw on the way count too)."""
        short = self.look_where_kept(noun, spots)
        n = len(self.present(key))
        note = f" seen, but it could not look at {', '.join(short)}" if short else ""
        return f"{counted(n, noun)} where the map keeps them{note}"

    def look_where_kept(self, noun: str, spots: list[str], shown: str | None = None) -> list[str]:
        """Look all over or into every room and place of ``spots`` (where the priors keep a kind), the nearest next
        as the crow flies; the ones it could not look at (out of reach, out of time). ``shown``: a class whose
        thing found in the last place looked into keeps it open, to be shown there ("where are the cups?")."""
        left = list(spots)
        short: list[str] = []
        said = ", ".join(f"the {s.replace('_', ' ')}" if self.room(s) is not None else s for s in spots)
        self.say("search", f"looks where the map keeps {plural_of(noun)}: {said}")
        def at(spot: str) -> tuple[float, float]:
            room = self.room(spot)
            return tuple(room.centroid) if room is not None else self.known[spot].at

        while left:
            x, y = self.world.robot.pose[:2]
            spot = min(left, key=lambda s: math.dist(at(s), (x, y)))
            left.remove(spot)
            _, _, complete = self.look_over(spot, sought=shown if not left and self.room(spot) is None else None)
            if not complete.ok:
                short.append(spot.replace("_", " "))
            if self.exhausted() is not None:
                short.extend(s.replace("_", " ") for s in left)
                break
        return short

    def _counted_by_the_map(self, where: str, binding: Binding) -> bool:
        """Whether driving to ``where`` only leads up to a count the map answers: the frame counts a class of the
        map's places (furniture) in that room, which :meth:`how_many` reads off the map without a look (lead, stop
        41: "how many sofas are in the kitchen?" drove 11.95 m, then said "0 sofas in the kitchen, by the map")."""
        ground = binding.elements.get("ground")
        return ground == where and self.room(where) is not None and any(
            a.name == "count" and self._is_place_class(self.class_of(a.args[0])) for a in binding.actions)

    def _is_place_class(self, key: str) -> bool:
        """Whether a class is one of the map's places' (a sofa, a bed): known from the map, not sought."""
        return any(not k.movable and k.cls == key for k in self.known.values())

    def _count_places(self, key: str, noun: str, ground: str | None) -> str:
        """How many places of a class the map has, in a room or in the house, without a look."""
        if ground is None:
            n = sum(1 for k in self.known.values() if not k.movable and k.cls == key and k.id in self.world.items)
            return f"{counted(n, noun)} in the house, by the map"
        n = len(self._fixed_in(key, ground))
        return f"{counted(n, noun)} {located(ground, self.scene.map)}, by the map"

    def _fixed_in(self, key: str, ground: str) -> list[str]:
        """The places of a class in a room ("how many beds are in the bedroom?"): the map says where
        furniture stands, so they are counted without being seen; none at a place."""
        room = self.room(ground)
        if room is None:
            return []
        return [k.id for k in self.known.values() if not k.movable and k.cls == key and k.id in self.world.items
                and bool(room.contains([k.at])[0])]

    def _none_known(self, key: str, noun: str, n: int) -> str:
        """What a count of none adds when the robot knows of no such thing anywhere (the map has no
        chair, and it saw none): said, so a 0 is not taken for a room that merely lacks one."""
        if n or any(k.cls == key for k in self.known.values()) or key in {class_key(c) for c in self.scene.map.priors}:
            return ""
        return f"; it knows of no {plural_of(noun)} anywhere"

    def survey(self, room: Any, views: int | None = None, peek: bool = False,
               until: Callable[[], bool] | None = None, announced: bool = False) -> Outcome:
        """Look all over a room: to the nearest part of it not yet seen, until all of it is (at
        most ``views`` views, default :data:`SURVEY_VIEWS`, within the budget); with ``peek``, then
        into each closed receptacle in it not yet looked into. Ok when there was nothing more to
        see; else why it stopped. ``until``: stop as soon as it holds (what was sought is seen).
        ``announced``: "looks all over the room" was said already (a survey a view at a time)."""
        assert self.sweeper is not None
        limit = SURVEY_VIEWS if views is None else views
        sweep = self.sweeper()
        sweep.begin(self)
        from scipy.spatial import cKDTree

        near, _ = cKDTree(self.grid.free_points).query(sweep.lattice, distance_upper_bound=SURVEY_NEAR)
        points = sweep.lattice[room.contains(sweep.lattice) & np.isfinite(near)]   # where things stand
        seen = np.zeros(len(points), dtype=bool)
        for pose in self.looks:
            seen |= self.world.sensor.visible(pose, points)
        cells = self.grid.free_cells
        field_ = self.distances()
        candidates, sees = self._views(room, points, field_[cells[:, 0], cells[:, 1]])
        seeable = seen | sees.any(axis=0)
        name = room.name.replace("_", " ")

        def share() -> float:
            return float(seen[seeable].mean()) if seeable.any() else 1.0

        ended = Outcome(False, f"it saw {100 * share():.0f} % of it in {limit} views")
        said = announced
        for _ in range(limit):
            if until is not None and until():
                return Outcome(True, "saw what it looked for")
            if (stop := self.exhausted()) is not None:
                return Outcome(False, f"{stop}; it saw {100 * share():.0f} % of it", Reason.BUDGET)
            if share() >= SURVEY_SHARE:
                ended = Outcome(True, "looked all over it")
                break
            field_ = self.distances()
            best = self._best_view(candidates, sees, points, ~seen & seeable, field_[cells[:, 0], cells[:, 1]])
            if best is None:        # what is left, no view in the room sees enough of
                ok = share() >= SURVEY_SEEABLE
                ended = Outcome(ok, "looked all over it" if ok else
                                f"it saw {100 * share():.0f} % of it: no place it can drive to sees the rest")
                break
            k, goal = best
            if not said:        # once a room: its further views are each a "goes to look"
                self.say("search", f"looks all over the {name}", target=room.name)
                said = True
            before = len(self.looks)
            self.drive_to((int(cells[k, 0]), int(cells[k, 1])), "goes to look")
            self.look_round(goal)
            for pose in self.looks[before:]:
                seen |= self.world.sensor.visible(pose, points)
        else:
            ended = Outcome(share() >= SURVEY_SHARE, f"it saw {100 * share():.0f} % of it in {limit} views")
        if not peek:
            return ended
        shut = [k for k in self.known.values() if not k.movable and k.openable and k.id not in self.opened
                and not self.world.items[k.id].is_open and bool(room.contains([k.at])[0])]
        while shut:
            if until is not None and until():
                return Outcome(True, "saw what it looked for")
            if (stop := self.exhausted()) is not None:
                return Outcome(False, stop, Reason.BUDGET)
            field_ = self.distances()
            box = min(shut, key=lambda s: field_[c] if (c := self.stand_cell(s, field_)) is not None else np.inf)
            shut.remove(box)
            cell = self.stand_cell(box, field_)
            if cell is None:
                ended = Outcome(False, f"{box.id} cannot be reached to look inside")
                continue
            self.say("search", f"looks into {box.id}", target=room.name)
            self.drive_to(cell, f"goes to {box.id}")
            self.world.face(box.at)
            peeked = self.peek(box.id, until)       # what was sought is inside: kept open to show it
            if not peeked.ok:
                ended = peeked
        return ended

    def _views(self, room: Any, points: np.ndarray, costs: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """Where a room can be looked over from: its free cells about a metre apart that the robot
        can drive to, and which of the points each sees all round (in range and in line of sight;
        a robot with a narrower field of view turns on the spot to look round, :meth:`look_round`)."""
        cells, free = self.grid.free_cells, self.grid.free_points
        stride = max(1, round(1.0 / self.grid.resolution))
        pick = np.flatnonzero((cells[:, 0] % stride == 0) & (cells[:, 1] % stride == 0) & np.isfinite(costs)
                              & np.asarray(room.contains(free), dtype=bool))
        sensor = self.world.sensor
        sees = np.zeros((len(pick), len(points)), dtype=bool)
        for row, k in enumerate(pick):
            near = np.flatnonzero(np.hypot(*(points - free[k]).T) <= sensor.range)
            if len(near):
                sees[row, near] = sensor.line_of_sight(free[k], points[near])
        return pick, sees

    def _best_view(self, candidates: np.ndarray, sees: np.ndarray, points: np.ndarray, unseen: np.ndarray,
                   costs: np.ndarray) -> tuple[int, tuple[float, float]] | None:
        """The next view to look all over a room from (next best view): the candidate view that
        sees the most of what is still unseen per metre driven (plus :data:`VIEW_COST` for the
        look), with the point to face, the middle of what it will see; None when no view sees 3 of
        the unseen points. ``unseen`` holds only points some view can see, so the survey never
        drives to chase what no place in the room shows (the inside of a sofa on a laser map)."""
        here = self.robot_cell()
        cells = self.grid.free_cells
        away = ~((cells[candidates, 0] == here[0]) & (cells[candidates, 1] == here[1]))
        gains = (sees & unseen).sum(axis=1)
        useful = np.flatnonzero(away & (gains >= 3))
        if not len(useful):
            return None
        j = int(max(useful, key=lambda c: gains[c] / (float(costs[candidates[c]]) + VIEW_COST)))
        seen = points[sees[j] & unseen]
        centre = seen.mean(axis=0)
        look = seen[int(np.argmin(np.hypot(*(seen - centre).T)))]
        return int(candidates[j]), (float(look[0]), float(look[1]))

    def look_round(self, goal: tuple[float, float]) -> None:
        """Face a point and look; a sensor that does not see all round then turns on the spot and
        looks again until it has looked all round (turning costs no path). Every policy's view, the
        start of a run and a survey's views look round alike (docs/sefm.md: narrow sensors)."""
        self.world.face(goal)
        self.look()
        fov = self.world.sensor.spec.fov_deg
        if fov >= 360:
            return
        x, y, yaw = self.world.robot.pose
        for turn in range(1, math.ceil(360 / fov)):
            heading = yaw + math.radians(fov) * turn
            self.world.face((x + math.cos(heading), y + math.sin(heading)))
            self.look(quiet=True)

    def _after(self, name: str, args: list[str], binding: Binding) -> None:
        """Keep the robot's own knowledge in step with what it just did."""
        if name in PUTS:               # it knows where it put the thing, and on what
            self.known[args[0]] = self._known(self.world.items[args[0]])
            if binding.frame.name != "Place" or binding.elements.get("goal") is not None:
                self.placed.add(args[0])
        elif name == "pick":
            self.placed.discard(args[0])
        elif name == "open":           # what the opening shows is seen, as when it peeks
            self.opened.add(args[0])
            self.left_open.add(args[0])
            if not self.commanded(binding):      # opened only for the frames after it: closed again after them
                self.ajar.add(args[0])
            self.look(quiet=True)

    def put_beside(self, thing: str, target: str, refused: Outcome) -> tuple[Outcome, list[str]]:
        """"Put the keys on the laptop", "to the right of the knife", "take the bowl to the lamp":
        nothing goes on that, so the thing goes where the target is — on the place it was seen on,
        else on the open place nearest it."""
        known = self.known.get(target)
        under = known.parent if known is not None else None
        places = [k for k in self.known.values() if not k.movable and k.receptacle and k.id != target
                  and self.world.items[k.id].is_open]
        if under is None or under not in self.known or not any(k.id == under for k in places):
            at = self.world.position(target)
            under = min(places, key=lambda k: math.dist(k.at, at)).id if places else None
        if under is None:
            return refused, [thing, target]
        self.say("fail", f"{refused.message}; puts {thing} where {target} is, on {under}")
        if not self.world.within_reach(under):
            cell = self.stand_cell(self.known[under])
            if cell is not None:
                self.drive_to(cell, f"goes to {under}")
        return self.world.act("place", thing, under), [thing, under]

    def put_down(self, binding: Binding) -> Outcome:
        """Set the held thing down on the nearest open surface (a Place without a goal)."""
        held = self.held()
        assert held is not None
        surfaces = [k for k in self.known.values() if not k.movable and k.receptacle and not k.openable]
        target = self.nearest(surfaces) if surfaces else None
        if target is None:
            return Outcome(False, f"finds nowhere to put {held.id} down")
        cell = self.stand_cell(self.known[target])
        if cell is not None:
            self.drive_to(cell, f"goes to put {held.id} down on {target}")
        outcome = self.world.act("place", held.id, target)
        self.say("act" if outcome.ok else "fail", outcome.message, action="place", args=[held.id, target])
        if outcome.ok:
            self._after("place", [held.id, target], binding)
        return outcome


PUTS = ("place", "place_on")
"""The primitives that put the held thing down in or on a receptacle."""
WORDS = frozenset({"search", "count", "say", "answer"})
"""Primitives whose argument is a word (a kind of thing, a message), not an item of the world."""

GO_FIRST = {"approach": 0, "follow": 0}
"""Primitives the robot drives for first: up to the person (approach, follow)."""

ROBOT_SPEED = 0.5
"""Metres a second the robot's clock counts for its driving (a household robot's cruising speed)."""

TOUR_EXACT = 7
"""Up to this many rooms, the whole-house search tries every order of them (7! = 5,040)."""

DETAIL_KINDS = frozenset({"go", "look", "search"})
WORDED_KINDS = frozenset({"search"})
"""Narration whose class names are said as words ("looks for frying pan"), its ids kept (``frying_pan_1``)."""
CLASS_NAME = re.compile(r"\b[A-Za-z]+(?:_[A-Za-z]+)+\b")


def as_words(text: str) -> str:
    """Class and room names said as words ("frying_pan 0.73 there": "frying pan 0.73 there"), an item's id
    (``frying_pan_1``, ``fridge_1``) as it is."""
    return CLASS_NAME.sub(lambda m: m.group().replace("_", " "), text)
"""The kinds of record that are details of a survey's line (not narrated, kept in the records)."""

SURVEY_VIEWS = 30
"""At most this many views to look all over a room (Count, "is there ... in the kitchen?")."""

VIEW_COST = 2.0
"""Metres a look is worth in :meth:`Agent._best_view` (so a view next door that sees a little does not
beat one across the room that sees much)."""

SURVEY_NEAR = 0.6
"""What of a room there is to look at: the points within this many metres of free space (things
stand on the floor or on furniture beside it, not inside walls or deep in a bed's blob)."""

SURVEY_SEEABLE = 0.8
"""When no view inside a room sees 3 more of its points, the room was looked all over if the robot
saw this share of it (the rest is wall faces and the backs of furniture); else it says how much it saw."""

SURVEY_SHARE = 0.95
"""A room is looked all over when the robot has seen this share of it (a lattice of 0.25 m over the
room, :class:`~seal_cli.sim.policies.coverage.CoveragePolicy`): the last corners behind furniture
cost many short drives and hide nothing a camera at table height would miss."""

STAND_TRIES = 400
"""Stand cells tried, nearest first, for one that no wall cuts off from the thing."""


class _Rest:
    """The part of the house outside every room (all of it, on a map without rooms): what the
    whole-house search looks over after the rooms."""

    name = "rest of the house"

    def __init__(self, rooms: Sequence[Any]) -> None:
        self.rooms = tuple(rooms)

    def contains(self, points: Any) -> np.ndarray:
        points = np.asarray(points, dtype=float).reshape(-1, 2)
        inside = np.zeros(len(points), dtype=bool)
        for room in self.rooms:
            inside |= np.asarray(room.contains(points), dtype=bool)
        return ~inside


class Fatal(Outcome):
    """A failure that replanning cannot mend (the search is exhausted, the budget spent)."""


def default_planner(commanded: Sequence[Binding], library: Library, state: State) -> list[Binding]:
    """The project's planner (:func:`seal_cli.planning.plan.plan`) as a list of grounded frames."""
    from seal_cli.planning import plan as planning

    result = planning.plan(list(commanded), library, state)
    return [step.binding for step in result.steps]


def _two_opt(order: tuple[int, ...], first: np.ndarray, between: np.ndarray) -> tuple[int, ...]:
    """A tour from the robot improved by reversing stretches of it while that drives less (2-opt): the nearest
    room next leaves the far end of a long corridor to come back across the house."""
    def cost(o: Sequence[int]) -> float:
        return float(first[o[0]] + sum(between[a, b] for a, b in itertools.pairwise(o))) if o else 0.0

    best, best_cost = tuple(order), cost(order)
    improved = True
    while improved:
        improved = False
        for i in range(len(best) - 1):
            for j in range(i + 1, len(best)):
                tried = best[:i] + best[i:j + 1][::-1] + best[j + 1:]
                if (c := cost(tried)) < best_cost - 1e-9:
                    best, best_cost, improved = tried, c, True
    return best


def scene_from_map(m: Map, library: Library, *, robot_radius: float = ROBOT_RADIUS) -> Scene:
    """A world built from a seal map's places, ground-truth objects and people (the speaker, "me",
    stands at ``speaker.at`` or where the robot starts), on its free space. A place's ``reach`` is
    how far the robot can act on it and on what is in or on it. A place switches on and off unless
    the library knows its class does not (a table; a dryer nobody lists does, as the planner allows); a
    thing only when the library knows its class does (a kettle standing on the worktop)."""
    from seal_cli.sensing.model import RangeSensor
    from seal_cli.sim.world import Item, Robot

    taxonomy = library.taxonomy
    items = [Item(p.name, p.cls, p.at, movable=False, receptacle=True, openable=p.openable,
                  toggleable=kind_of(taxonomy, p.cls, "toggleable") is not False, reach=p.reach) for p in m.places]
    for item, place in zip(items, m.places, strict=True):
        if place.openable and place.open:
            item.states.add("open")
    counts: dict[str, int] = {}
    names = {class_key(p.name): p.name for p in m.places}
    for o in m.objects:
        counts[o.cls] = counts.get(o.cls, 0) + 1
        parent = names.get(class_key(o.inside)) if o.inside else None
        items.append(Item(f"{o.cls}_{counts[o.cls]}", o.cls, o.at, movable=True, parent=parent,
                          receptacle=taxonomy.is_a(o.cls, "container") is True,
                          toggleable=kind_of(taxonomy, o.cls, "toggleable") is True))   # a kettle, a lamp
    people = [(p.key, m.person_at(p)) for p in m.people]
    items += [Item(key, PERSON, at, movable=False) for key, at in [*people, (SPEAKER, m.speaker_at)]]
    holding = None
    if m.robot.holding:
        holding = f"{m.robot.holding}_{counts.get(m.robot.holding, 0) + 1}"   # the next of its class: "cup_2"
        items.append(Item(holding, m.robot.holding, m.robot.xy, movable=True, parent=HAND))
    grid = Grid.from_map(m, robot_radius)
    world = World(items, Robot(pose=m.robot.pose, holding=holding), taxonomy=taxonomy,
                  sensor=RangeSensor.on_map(m))
    known = {i.key for i in items} | {class_key(c) for c in m.priors}   # what the map has priors of, it knows
    return Scene(world, m, grid, tuple(sorted(known)), m.name)

ROOM_SPOT_CLEARANCE = 0.6
"""Metres from anyone standing in a room that :meth:`Agent.room_spot` keeps ("go to the kitchen" does not
end on Anna's toes at the kitchen's middle)."""


def without_not_found(message: str, who: str) -> str:
    """The search's sentence without its clauses that only say ``who`` was not found (e2e23), for a report that says
    so already: "searched the whole house: no Raj (looked all over 9 rooms)" is "searched the whole house; looked all
    over 9 rooms" after "it did not find Raj"; a parenthesis of such a clause is kept as a clause of its own."""
    kept: list[str] = []
    for clause in message.split(": "):
        match = re.fullmatch(rf"no (?:other )?{re.escape(who)}(?: found)?(?: \((.*)\))?", clause.strip(), re.IGNORECASE)
        if match is None:
            kept.append(clause.strip())
        elif match.group(1):
            kept.append(match.group(1))
    return "; ".join(c for c in kept if c)
