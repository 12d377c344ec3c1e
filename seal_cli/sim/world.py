"""A 2-D household simulator: things in and on places, a robot that drives, looks and handles them.

The world is the ground truth a robot acts in; the robot itself only ever learns about it through
:meth:`World.observe`. It holds

- **items**: static places (furniture, appliances, receptacles; ``movable=False``) and movable
  things (an apple, a pan). An item may sit in or on another (``parent``); an openable item that
  is closed hides what is inside it, from sight and from the hand. Items carry the states that
  ALFRED's tasks change: hot, cold, clean, sliced, toggled on, open.
- **the robot**: its pose, the item in its hand, the metres it has driven.

Every primitive of :data:`seal_cli.frames.actions.PRIMITIVES` that concerns things is executed by
:meth:`World.act`, which checks the physical preconditions (the item is within reach, the hand is
empty to pick, a receptacle is open to put inside, a knife is held to slice, ...). An action that
is not afforded changes nothing and returns an :class:`Outcome` that says why. The semantic
state (facts, :mod:`seal_cli.planning.state`) is the agent's business; the world only knows physics.

What happened and when is kept: :attr:`World.log` lists every action, and :meth:`World.since`
gives the step at which an item's property last took its current value, so a task can be judged
"done, and in the right order" from the world itself.
"""

from __future__ import annotations

import enum
import math
from collections.abc import Iterable, Iterator, Sequence
from dataclasses import dataclass, field

import numpy as np

from seal_cli.errors import SealError
from seal_cli.frames.actions import PRIMITIVES
from seal_cli.frames.taxonomy import Taxonomy, class_key
from seal_cli.planning.grounding import kind_of
from seal_cli.sensing.model import RangeSensor, SensorModel

__all__ = ["HAND", "PERSON", "Detection", "Event", "Item", "Outcome", "Reason", "Robot", "World"]

HAND = "@hand"
"""The parent of the item the robot holds."""

PERSON = "person"
"""The class of the people in the world: they stand where they are, take what is handed to them,
and follow the robot when it leads them."""

STATES = ("hot", "cold", "clean", "sliced", "on", "open")

REACH_MARGIN = 0.3
"""How close to a thing a wall may stand without cutting the robot's reach to it: the sight line
from the robot is tested to the point this far short of the thing (for a place with its own
reach, that reach less 0.5 m if more: :meth:`World.margin`), so the thing's own furniture (a
counter a laser map marks occupied) does not hide it from the hand."""


@dataclass
class Item:
    """A place or a thing in the world."""

    id: str
    cls: str
    at: tuple[float, float]
    movable: bool = True
    receptacle: bool = False
    openable: bool = False
    toggleable: bool = False
    parent: str | None = None
    access: tuple[tuple[float, float], ...] = ()
    """Poses (x, y) from which a robot can reach a place that is larger than its arm's reach."""
    states: set[str] = field(default_factory=set)
    reach: float | None = None
    """How far from it the robot can act on it (m); None: the world's reach (a thing in or on a
    place: the place's)."""
    on_top: bool = False
    """Put on top of its parent (``place_on``), which is hollow (a sideboard), not in it: a closed parent
    does not hide it."""

    def __post_init__(self) -> None:
        self.key = class_key(self.cls)
        if self.openable and not self.receptacle:
            self.receptacle = True

    @property
    def is_open(self) -> bool:
        return not self.openable or "open" in self.states


@dataclass
class Robot:
    pose: tuple[float, float, float] = (0.0, 0.0, 0.0)
    holding: str | None = None
    path_m: float = 0.0
    trajectory: list[tuple[float, float]] = field(default_factory=list)


class Reason(enum.Enum):
    """Why an action did not happen, for the robot to act on (the message is for people)."""

    OK = "ok"
    UNKNOWN_ITEM = "unknown_item"
    OUT_OF_REACH = "out_of_reach"
    BEHIND_WALL = "behind_wall"
    INSIDE_CLOSED = "inside_closed"
    CLOSED = "closed"
    OPEN = "open"
    NOT_RECEPTACLE = "not_receptacle"
    FIXED = "fixed"
    HAND_FULL = "hand_full"
    NOT_HELD = "not_held"
    WRONG_KIND = "wrong_kind"
    NOT_SEEN = "not_seen"
    NOT_FOUND = "not_found"
    UNREACHABLE = "unreachable"
    BUDGET = "budget"
    CANNOT = "cannot"
    ALREADY = "already"
    """What the frame is for holds already (the thing is where the command wants it): not a failure."""


@dataclass(frozen=True)
class Outcome:
    """What an action did: ``ok``, a sentence that says what happened or why it could not, the
    :class:`Reason` when it could not, and the item the reason is about (the closed fridge)."""

    ok: bool
    message: str
    reason: Reason = Reason.OK
    about: str | None = None

    def __bool__(self) -> bool:
        return self.ok


@dataclass(frozen=True)
class Event:
    step: int
    action: str
    args: tuple[str, ...]
    ok: bool
    message: str


@dataclass(frozen=True)
class Detection:
    """A thing seen: its class, where, and the world's id for it (a tracker's identity)."""

    cls: str
    at: tuple[float, float]
    id: str


class World:
    """The simulated household: items, the robot, and the log of what was done."""

    def __init__(self, items: Iterable[Item], robot: Robot | None = None, *, taxonomy: Taxonomy | None = None,
                 reach: float = 1.5, sensor: SensorModel | None = None, access_tolerance: float = 0.2) -> None:
        self.items: dict[str, Item] = {}
        for item in items:
            if item.id in self.items or item.id == HAND:
                raise SealError(f"two items in the world are called {item.id!r}")
            self.items[item.id] = item
        for item in self.items.values():
            if item.parent is not None and item.parent not in self.items and item.parent != HAND:
                raise SealError(f"{item.id} is in {item.parent!r}, which is not in the world")
        self.robot = robot or Robot()
        if not self.robot.trajectory:
            self.robot.trajectory.append(self.robot.pose[:2])
        held = [i.id for i in self.items.values() if i.parent == HAND]
        if self.robot.holding and self.robot.holding not in self.items:
            raise SealError(f"the robot holds {self.robot.holding!r}, which is not in the world")
        if self.robot.holding and not held:
            self.items[self.robot.holding].parent = HAND
        elif held and not self.robot.holding:
            self.robot.holding = held[0]
        self.taxonomy = taxonomy or Taxonomy()
        self.reach = reach
        self.sensor: SensorModel = sensor or RangeSensor()
        self.access_tolerance = access_tolerance
        self.following: str | None = None
        """A person who walks with the robot (being led): where the robot drives, they go."""
        self.step = 0
        self.log: list[Event] = []
        self._since: dict[tuple[str, str], int] = {}

    # -- what is where -----------------------------------------------------------------------

    def item(self, item_id: str) -> Item:
        try:
            return self.items[item_id]
        except KeyError:
            raise SealError(f"nothing in the world is called {item_id!r}") from None

    def of_class(self, cls: str) -> list[Item]:
        key = class_key(cls)
        return [i for i in self.items.values() if i.key == key]

    def ancestors(self, item_id: str) -> Iterator[Item]:
        """The items this one is in or on, innermost first."""
        seen = {item_id}
        parent = self.items[item_id].parent
        while parent is not None and parent != HAND and parent not in seen:
            seen.add(parent)
            yield self.items[parent]
            parent = self.items[parent].parent

    def held_chain(self, item_id: str) -> bool:
        """Whether the item is in the hand, or in something in the hand."""
        item = self.items[item_id]
        return item.parent == HAND or any(a.parent == HAND for a in self.ancestors(item_id))

    def position(self, item_id: str) -> tuple[float, float]:
        """Where an item is now: the robot's position for what it carries."""
        if self.held_chain(item_id):
            return (self.robot.pose[0], self.robot.pose[1])
        return self.items[item_id].at

    def enclosure(self, item_id: str) -> Item | None:
        """The closed item that hides this one, if any (not the one it lies on top of)."""
        inner = self.items[item_id]
        for outer in self.ancestors(item_id):
            if not outer.is_open and not inner.on_top:
                return outer
            inner = outer
        return None

    def contents(self, item_id: str) -> list[Item]:
        return [i for i in self.items.values() if i.parent == item_id]

    def since(self, item_id: str, prop: str) -> int:
        """The step at which the item's property (a state, or ``parent``) last took its value (0: always)."""
        return self._since.get((item_id, prop), 0)

    def has(self, item_id: str, state: str) -> bool:
        return state in self.items[item_id].states

    # -- reach and sight ---------------------------------------------------------------------

    def within_reach(self, item_id: str, pose: Sequence[float] | None = None) -> bool:
        """Whether the robot (at ``pose``, default where it is) can touch the item."""
        pose = pose or self.robot.pose
        if self.held_chain(item_id):
            return True
        item = self.items[item_id]
        if math.dist(pose[:2], item.at) <= self.reach_of(item_id) + 1e-9:
            return not self.walled(item_id, pose)
        stands = list(item.access)
        parent = self.items.get(item.parent) if item.parent else None
        if parent is not None and not parent.movable:
            stands.extend(parent.access)
        return any(math.dist(pose[:2], a) <= self.access_tolerance for a in stands)

    def reach_of(self, item_id: str) -> float:
        """How far from the item the robot can act on it: its own reach, else its place's, else the world's."""
        item = self.items[item_id]
        parent = self.items.get(item.parent) if item.parent else None
        for owner in (item, parent):
            if owner is not None and owner.reach is not None:
                return owner.reach
        return self.reach

    def walled(self, item_id: str, pose: Sequence[float] | None = None) -> bool:
        """Whether a wall stands between the robot and the item: the sight line from the robot to
        the point :data:`REACH_MARGIN` short of the item is blocked."""
        pose = pose or self.robot.pose
        at = self.items[item_id].at
        d = math.dist(pose[:2], at)
        margin = self.margin(item_id)
        if d <= margin:
            return False
        f = (d - margin) / d
        short = (pose[0] + (at[0] - pose[0]) * f, pose[1] + (at[1] - pose[1]) * f)
        return not bool(np.asarray(self.sensor.line_of_sight(pose[:2], np.asarray([short], dtype=float)))[0])

    def margin(self, item_id: str) -> float:
        """How far short of the item the sight line for reach is tested: :data:`REACH_MARGIN` for a
        thing, more for a place whose own reach is larger (a bed, a fridge drawn as a box: its
        outline must not hide it from the hand), its reach less half a metre."""
        item = self.items[item_id]
        parent = self.items.get(item.parent) if item.parent else None
        owner = item if item.reach is not None else parent if parent is not None and parent.reach is not None \
            else None
        return REACH_MARGIN if owner is None else max(REACH_MARGIN, float(owner.reach or 0.0) - 0.5)

    p_detect = 1.0
    """The chance that :meth:`observe` reports a thing in the sensor's view: 1, the simulated detector never misses
    (whatever ``p_detect`` the map's sensor declares, which describes a real robot's detector: ``seal localize``,
    ROS). A policy that models its detector's misses reads it here in the simulator (SeFM's object filter,
    :attr:`~seal_cli.sim.policies.sefm.SeFMPolicy.world_detector`)."""

    def observe(self, pose: Sequence[float] | None = None) -> list[Detection]:
        """The movable things the robot sees: not shut inside anything, and in its sensor's view or in
        or on a place within its reach (it looks at what it stands at)."""
        pose = pose or self.robot.pose
        things = [i for i in self.items.values() if i.movable and not self.held_chain(i.id)
                  and self.enclosure(i.id) is None]
        if not things:
            return []
        mask = self.sensor.visible(pose, np.asarray([t.at for t in things], dtype=float))
        at_hand = {i.id for i in self.items.values() if not i.movable and i.is_open and self.within_reach(i.id, pose)}
        return [Detection(t.cls, t.at, t.id) for t, ok in zip(things, mask, strict=True)
                if ok or t.parent in at_hand]

    # -- moving ------------------------------------------------------------------------------

    def drive(self, waypoints: Sequence[Sequence[float]], heading: float | None = None) -> float:
        """Drive through the waypoints (a path found on free space); returns the metres driven."""
        metres = 0.0
        x, y = self.robot.pose[0], self.robot.pose[1]
        yaw = self.robot.pose[2]
        for wp in waypoints:
            step = math.dist((x, y), wp[:2])
            if step > 1e-9:
                yaw = math.atan2(wp[1] - y, wp[0] - x)
                metres += step
                x, y = float(wp[0]), float(wp[1])
                self.robot.trajectory.append((x, y))
        self.robot.pose = (x, y, yaw if heading is None else heading)
        self.robot.path_m += metres
        if self.following is not None:
            self.items[self.following].at = (x, y)
        self.step += 1
        return metres

    def face(self, point: Sequence[float]) -> None:
        """Turn on the spot towards a point (turning costs no path)."""
        x, y = self.robot.pose[0], self.robot.pose[1]
        if math.dist((x, y), point[:2]) > 1e-9:
            self.robot.pose = (x, y, math.atan2(point[1] - y, point[0] - x))

    # -- acting ------------------------------------------------------------------------------

    def act(self, name: str, *args: str) -> Outcome:
        """Execute the primitive ``name`` on items named by id; log it and say what happened."""
        if name not in PRIMITIVES:
            raise SealError(f"unknown primitive {name!r}; known: {', '.join(sorted(PRIMITIVES))}")
        if len(args) != PRIMITIVES[name].arity:
            raise SealError(f"{name} takes {PRIMITIVES[name].arity} argument(s), not {len(args)}")
        handler = getattr(self, f"_do_{name}", None)
        if handler is None:
            outcome = Outcome(False, f"this world cannot {name.replace('_', ' ')}")
        else:
            missing = [a for a in args if a not in self.items]
            if missing and name not in _TEXT_ARGS:
                outcome = Outcome(False, f"there is no {missing[0]!r} here", Reason.UNKNOWN_ITEM, missing[0])
            else:
                outcome = handler(*args)
        self.step += 1
        self.log.append(Event(self.step, name, tuple(args), outcome.ok, outcome.message))
        return outcome

    def _set(self, item: Item, state: str, value: bool = True) -> None:
        if (state in item.states) != value:
            (item.states.add if value else item.states.discard)(state)
            self._since[(item.id, state)] = self.step + 1

    def _move(self, item: Item, parent: str | None, at: tuple[float, float] | None = None,
              on_top: bool = False) -> None:
        item.parent = parent
        item.on_top = on_top
        if at is not None:
            item.at = at
        self._since[(item.id, "parent")] = self.step + 1

    def _reachable(self, item_id: str) -> Outcome | None:
        """None if the robot can touch the item, else why not."""
        item = self.items[item_id]
        if not self.within_reach(item_id):
            d = math.dist(self.robot.pose[:2], self.position(item_id))
            if d <= self.reach_of(item_id) + 1e-9 and self.walled(item_id):
                return Outcome(False, f"{item.id} is {d:.1f} m away behind a wall: the robot cannot reach "
                                      "through it", Reason.BEHIND_WALL, item.id)
            return Outcome(False, f"{item.id} is {d:.1f} m away, out of reach ({self.reach_of(item_id):g} m)",
                           Reason.OUT_OF_REACH, item.id)
        shut = self.enclosure(item_id)
        if shut is not None:
            return Outcome(False, f"{item.id} is inside {shut.id}, which is closed", Reason.INSIDE_CLOSED, shut.id)
        return None

    def _is(self, item: Item, category: str) -> bool:
        return self.taxonomy.is_a(item.cls, category) is True

    def _do_pick(self, obj: str) -> Outcome:
        item = self.items[obj]
        if not item.movable:
            return Outcome(False, f"{obj} cannot be picked up: it is fixed", Reason.FIXED, obj)
        if self.robot.holding is not None:
            return Outcome(False, f"the hand is not empty: it holds {self.robot.holding}", Reason.HAND_FULL,
                           self.robot.holding)
        if (why := self._reachable(obj)) is not None:
            return why
        source = item.parent
        self._move(item, HAND)
        self.robot.holding = obj
        if source is not None and self.items[source].key == PERSON:     # handed to them before
            return Outcome(True, f"took {obj} back from {source}")
        return Outcome(True, f"picked up {obj}" + (f" from {source}" if source else ""))

    def _do_place(self, obj: str, receptacle: str, on_top: bool = False) -> Outcome:
        item, target = self.items[obj], self.items[receptacle]
        if self.robot.holding != obj:
            return Outcome(False, f"the robot does not hold {obj}", Reason.NOT_HELD, obj)
        if not target.receptacle:
            return Outcome(False, f"nothing can be put in or on {receptacle}", Reason.NOT_RECEPTACLE, receptacle)
        if receptacle == obj or self.held_chain(receptacle):
            return Outcome(False, f"{obj} cannot be put into something the robot is carrying", Reason.CANNOT,
                           receptacle)
        if (why := self._reachable(receptacle)) is not None:
            return why
        if not target.is_open and not on_top:
            return Outcome(False, f"{receptacle} is closed", Reason.CLOSED, receptacle)
        self._move(item, receptacle, self._drop_point(target), on_top and self.hollow(target))
        self.robot.holding = None
        return Outcome(True, f"put {obj} {'in' if self.hollow(target) and not on_top else 'on'} {receptacle}")

    def _do_place_on(self, obj: str, receptacle: str) -> Outcome:
        """Put the held thing on top of the receptacle: a closed one too (a sideboard's top), and what
        lies there stays in sight and reach while it is closed."""
        return self._do_place(obj, receptacle, on_top=True)

    def hollow(self, target: Item) -> bool:
        """Whether a thing is put *in* the target (a fridge, a sink, a cup, a laundry basket) or *on* it
        (a table, a shelf): openable, or of the taxonomy's ``hollow`` kinds (a compound by its head)."""
        return target.openable or kind_of(self.taxonomy, target.cls, "hollow") is True

    def _drop_point(self, target: Item) -> tuple[float, float]:
        """Where a thing put on a place ends up: the place's centre, or the edge nearest the robot."""
        x, y = self.robot.pose[0], self.robot.pose[1]
        d = math.dist((x, y), target.at)
        if target.movable or d <= self.reach * 0.8:
            return target.at
        f = self.reach * 0.8 / d
        return (x + (target.at[0] - x) * f, y + (target.at[1] - y) * f)

    def _open_close(self, thing: str, opening: bool) -> Outcome:
        item = self.items[thing]
        if not item.openable:
            return Outcome(False, f"{thing} cannot be {'opened' if opening else 'closed'}")
        if (why := self._reachable(thing)) is not None:
            return why
        if item.is_open == opening:
            return Outcome(True, f"{thing} is already {'open' if opening else 'closed'}")
        self._set(item, "open", opening)
        inside = [c.id for c in self.contents(thing)]
        seen = f"; inside: {', '.join(inside)}" if opening and inside else ("; it is empty" if opening else "")
        return Outcome(True, f"{'opened' if opening else 'closed'} {thing}{seen}")

    def _do_open(self, thing: str) -> Outcome:
        return self._open_close(thing, True)

    def _do_close(self, thing: str) -> Outcome:
        return self._open_close(thing, False)

    def _toggle(self, thing: str, on: bool) -> Outcome:
        item = self.items[thing]
        if not item.toggleable:
            return Outcome(False, f"{thing} cannot be switched {'on' if on else 'off'}")
        if (why := self._reachable(thing)) is not None:
            return why
        if item.openable and on and item.is_open and self._is(item, "heater"):
            return Outcome(False, f"{thing} must be closed before it is switched on", Reason.OPEN, thing)
        if ("on" in item.states) == on:     # as Open and Close say (e2e23: "switch off the radio" when it is off)
            return Outcome(True, f"{thing} is already {'on' if on else 'off'}")
        self._set(item, "on", on)
        return Outcome(True, f"switched {thing} {'on' if on else 'off'}")

    def _do_toggle_on(self, thing: str) -> Outcome:
        return self._toggle(thing, True)

    def _do_toggle_off(self, thing: str) -> Outcome:
        return self._toggle(thing, False)

    def _treat(self, obj: str, appliance: str, category: str, state: str, clears: str | None) -> Outcome:
        item, tool = self.items[obj], self.items[appliance]
        if self.robot.holding != obj:
            return Outcome(False, f"the robot does not hold {obj}", Reason.NOT_HELD, obj)
        if not self._is(tool, category):
            return Outcome(False, f"{appliance} is a {tool.cls}, not a {category}", Reason.WRONG_KIND, appliance)
        if (why := self._reachable(appliance)) is not None:
            return why
        self._set(item, state)
        if clears:
            self._set(item, clears, False)
        return Outcome(True, f"{obj} is {state} now ({appliance})")

    def _do_heat(self, obj: str, appliance: str) -> Outcome:
        return self._treat(obj, appliance, "heater", "hot", "cold")

    def _do_cool(self, obj: str, appliance: str) -> Outcome:
        return self._treat(obj, appliance, "cooler", "cold", "hot")

    def _do_clean(self, obj: str, appliance: str) -> Outcome:
        return self._treat(obj, appliance, "washer", "clean", None)

    def _do_slice(self, obj: str, tool: str) -> Outcome:
        item, knife = self.items[obj], self.items[tool]
        if self.robot.holding != tool:
            return Outcome(False, f"the robot must hold {tool} to slice with it")
        if not self._is(knife, "cutter"):
            return Outcome(False, f"{tool} is a {knife.cls}, which does not cut")
        if self.held_chain(obj):
            return Outcome(False, f"{obj} must be put down to be sliced")
        if (why := self._reachable(obj)) is not None:
            return why
        if "sliced" in item.states:
            return Outcome(True, f"{obj} is already sliced")
        self._set(item, "sliced")
        return Outcome(True, f"sliced {obj} with {tool}")

    def _do_look_at(self, obj: str) -> Outcome:
        if not self.held_chain(obj) and (why := self._reachable(obj)) is not None:
            return why
        lit = [i.id for i in self.items.values() if "on" in i.states and self._is(i, "light")
               and self.within_reach(i.id)]
        return Outcome(True, f"looked at {obj}" + (f" in the light of {lit[0]}" if lit else ""))

    def _do_stir(self, tool: str, container: str) -> Outcome:
        if self.robot.holding != tool:
            return Outcome(False, f"the robot must hold {tool} to stir with it")
        if (why := self._reachable(container)) is not None:
            return why
        self._set(self.items[container], "stirred")
        return Outcome(True, f"stirred {container} with {tool}")

    def _do_pour(self, obj: str, container: str) -> Outcome:
        if self.robot.holding != obj:
            return Outcome(False, f"the robot does not hold {obj}")
        if (why := self._reachable(container)) is not None:
            return why
        return Outcome(True, f"poured {obj} into {container}")

    def _do_search(self, thing: str) -> Outcome:
        key = class_key(thing)
        seen = [d.id for d in self.observe() if class_key(d.cls) == key]
        if not seen and key in self.items and self.within_reach(key):      # a person or a place, by name
            seen = [key]
        if not seen:                                                        # a place of the class, at hand
            seen = [i.id for i in self.items.values()
                    if not i.movable and class_key(i.cls) == key and self.within_reach(i.id)]
        return Outcome(bool(seen), f"sees {', '.join(seen)}" if seen else f"sees no {thing} from here",
                       Reason.OK if seen else Reason.NOT_SEEN, thing)

    def _do_count(self, thing: str) -> Outcome:
        key = class_key(thing)
        n = sum(class_key(d.cls) == key for d in self.observe())
        return Outcome(True, f"counted {n} {thing}")

    def _person(self, person: str) -> Outcome | None:
        """None if the item is a person within reach, else why not."""
        if self.items[person].key != PERSON:
            return Outcome(False, f"{person} is not a person", Reason.WRONG_KIND, person)
        return self._reachable(person)

    def _do_approach(self, person: str) -> Outcome:
        why = self._person(person)
        return why if why is not None else Outcome(True, f"is with {'the speaker' if person == 'me' else person}")

    def _do_hand_over(self, obj: str, person: str) -> Outcome:
        if self.robot.holding != obj:
            return Outcome(False, f"the robot does not hold {obj}", Reason.NOT_HELD, obj)
        if (why := self._person(person)) is not None:
            return why
        self._move(self.items[obj], person, self.items[person].at)
        self.robot.holding = None
        return Outcome(True, f"handed {obj} to {person}")

    def _do_follow(self, person: str) -> Outcome:
        why = self._person(person)
        return why if why is not None else Outcome(True, f"followed {person}")

    def _do_lead(self, person: str, target: str) -> Outcome:
        """The person, within reach, walks with the robot from now on (:attr:`following`)."""
        if (why := self._person(person)) is not None:
            return why
        self.following = person
        self._since[(person, "at")] = self.step + 1
        return Outcome(True, f"{person} follows the robot to {target}")

    def _do_meet(self, person: str) -> Outcome:
        why = self._person(person)
        return why if why is not None else Outcome(True, f"met {person}")

    def _do_greet(self, person: str) -> Outcome:
        why = self._person(person)
        return why if why is not None else Outcome(True, f"greeted {person}")

    def _do_answer(self, question: str) -> Outcome:
        return Outcome(True, f"answered \"{question.replace('_', ' ')}\"")

    def _do_wait(self) -> Outcome:
        return Outcome(True, "waits")

    def _do_say(self, message: str) -> Outcome:
        from seal_cli.frames.said import said_words

        return Outcome(True, f"said \"{said_words(message)}\"")     # the message's name, as words ("it's ready")


_TEXT_ARGS = {"search", "count", "say", "answer", "lead"}
