"""Annotated 2-D maps: an occupancy grid with rooms, places, object priors and ground truth.

A :class:`Map` is what SeFM, the planner and the simulator read about a building:

- ``grid``: an :class:`~seal_cli.maps.geometry.OccupancyGrid` (from a ROS map_server image, from a
  reachability grid, or, when neither is given, all free over ``bounds``);
- ``bounds``: ``(xmin, ymin, xmax, ymax)``, the part of the world the map is about;
- ``rooms``: named simple polygons that do not overlap (a point in none is ``"_outside"``);
- ``places``: fixed furniture and receptacles (``fridge_1``, class ``fridge``), some openable;
- ``priors``: per object class, probability mass per room, place name or place class;
- ``objects``: the ground-truth objects, used only to simulate what a robot would see;
- ``people``: who is where (:class:`Person`: a name and a point or a room), and the ``speaker``
  ("me", "I", "us"), by default standing at the robot's start;
- ``robot``: its pose ``(x, y, yaw)`` (yaw in radians) and what it holds;
- ``sensor``: range (m), field of view (degrees) and the detection model.

*Free space* is where the robot and the particles live: grid cells that are FREE and whose
centre lies within ``bounds``. Class names compare by :func:`~seal_cli.frames.taxonomy.class_key`;
room and place names are looked up the same way.

Maps check themselves when built: a :class:`Map` that exists is valid, otherwise building it
raised :class:`~seal_cli.errors.SealErrors` listing every problem. Maps read from files
(:func:`load_map`) locate each problem at its file, line and column.
"""

from __future__ import annotations

import difflib
import math
from collections.abc import Container, Iterable, Iterator, Mapping, Sequence
from dataclasses import InitVar, dataclass, field, replace
from functools import cached_property
from typing import TYPE_CHECKING, Any

import numpy as np
from numpy.typing import ArrayLike, NDArray

from seal_cli.errors import SealError, SealErrors, Where
from seal_cli.frames.taxonomy import check_class_name, class_key
from seal_cli.maps.geometry import (
    MAX_GRID_CELLS,
    OUTSIDE,
    OccupancyGrid,
    as_points,
    box_polygon,
    clipped_area,
    line_of_sight,
    overlap_area,
    point_in_polygon,
    polygon_area,
    self_intersections,
)
from seal_cli.maps.prepositions import ROOM_PREPOSITIONS
from seal_cli.names import check_name_length, check_sayable

if TYPE_CHECKING:
    from seal_cli.maps.priors import Prior

__all__ = ["FOV_RANGE", "MIN_FOV", "OUTSIDE", "SPEAKER", "Map", "MapWarning", "ObjectTruth", "Person", "Place", "Robot",
           "Room", "Sensor", "fov_ok", "prior_density", "prior_sampler", "sample_prior"]

SPEAKER = "me"
"""The name the person who gives the command goes by ("me", "I", "us")."""

OVERLAP_TOLERANCE = 0.01
"""Square metres two rooms may share before they count as overlapping (drawing slack)."""
MAX_IMPLICIT_CELLS = MAX_GRID_CELLS
"""Largest implicit all-free grid built from bounds alone (its resolution grows to fit): the bound of every map's
grid (4,000,000 before hostile14: a run on it took 2.3 GB)."""
MAX_LISTED = 10_000
"""The most rooms, places, objects or people a map may list (a real building has tens to hundreds): checking a map
grows with them, and 40,000 rooms of 1 m² took over a minute to validate, 100,000 places two minutes to run
(hostile26); a longer list is refused at its first item past the bound."""
MAX_PRIOR_CLASSES = 2_000
"""The most classes a map's ``priors:`` may name (a building's things are of tens or hundreds of classes): each is a
belief of its own in ``seal localize`` and a prior summed over the free cells (about 3 ms and 0.3 MB a class); a map
of 100,000 prior classes (2.3 MB) took 30 s of CPU to ``seal map`` and ``seal localize`` ran past 300 s and 6 GB
(rel33). Refused at the first class past the bound."""
MAX_ROOM_VERTICES = 10_000
"""The most points a room's polygon may have (real outlines have tens): a map's checks and each cell's room
grow with them (a room of 62,831 points took 15 GB before the edges' crossing test swept by x)."""

Bounds = tuple[float, float, float, float]
XY = tuple[float, float]


def _xy(value: ArrayLike, what: str, where: Where | None = None) -> XY:
    try:
        array = np.asarray(value, dtype=float).ravel()
    except (TypeError, ValueError):
        raise SealError(f"{what} must be two numbers [x, y], not {value!r}", where) from None
    if array.shape != (2,) or not np.all(np.isfinite(array)):
        raise SealError(f"{what} must be two finite numbers [x, y], not {value!r}", where)
    return (float(array[0]), float(array[1]))


class MapWarning(SealError):
    """A problem that ``seal validate`` reports but that does not stop the map from being used.

    Rooms that overlap (the room listed first wins), and objects, people or the robot on an
    occupied cell (a laser map marks furniture occupied: a cup on a coffee table may well stand
    on one). Such a map loads, with the problems in :attr:`Map.warnings`. Anything outside the
    bounds is an error, not a warning.
    """


# -- value objects ------------------------------------------------------------------------------
@dataclass(frozen=True)
class Room:
    """A named room: a simple polygon (vertices in order, either orientation, not closed).

    ``preposition`` is how English says something is there ("in", "on" or "at": *on* the balcony), when the map
    gives one; None lets :func:`~seal_cli.maps.prepositions.located` take English's default for the name."""

    name: str
    polygon: tuple[XY, ...]
    where: Where | None = field(default=None, compare=False, repr=False)
    preposition: str | None = None

    def __post_init__(self) -> None:
        if not isinstance(self.name, str) or not class_key(self.name):
            raise SealError(f"a room needs a name, not {self.name!r}", self.where)
        check_name_length(self.name, "room name", self.where)
        check_sayable(self.name, "room name", self.where)
        if self.preposition is not None and self.preposition not in ROOM_PREPOSITIONS:
            raise SealError(f"room {self.name}: preposition must be one of {', '.join(ROOM_PREPOSITIONS)}, not "
                            f"{self.preposition!r}", self.where)
        if self.name.strip().casefold() == OUTSIDE:
            raise SealError(f"a room cannot be called {self.name!r}: seal's outputs give that name to the mass in no "
                            "room; call the room another name", self.where)
        try:
            vertices = np.asarray(self.polygon, dtype=float)
        except (TypeError, ValueError):
            raise SealError(f"room {self.name}: polygon must be a list of [x, y] points", self.where) from None
        if vertices.ndim != 2 or vertices.shape[1:] != (2,) or not np.all(np.isfinite(vertices)):
            raise SealError(f"room {self.name}: polygon must be a list of [x, y] points of finite numbers",
                            self.where)
        if len(vertices) > 1 and np.array_equal(vertices[0], vertices[-1]):
            vertices = vertices[:-1]  # a closed ring: drop the repeated first point
        if len(vertices) < 3:
            raise SealError(f"room {self.name}: a polygon needs at least 3 points, not {len(vertices)}", self.where)
        if len(vertices) > MAX_ROOM_VERTICES:
            raise SealError(f"room {self.name}: its polygon has {len(vertices):,} points; seal reads rooms of at most "
                            f"{MAX_ROOM_VERTICES:,}: simplify the outline", self.where)
        object.__setattr__(self, "polygon", tuple((float(x), float(y)) for x, y in vertices))

    @classmethod
    def box(cls, name: str, xmin: float, ymin: float, xmax: float, ymax: float, where: Where | None = None,
            preposition: str | None = None) -> Room:
        """An axis-aligned room (the ``box: [xmin, ymin, xmax, ymax]`` shorthand)."""
        if not (xmin < xmax and ymin < ymax):
            raise SealError(f"room {name}: box must be [xmin, ymin, xmax, ymax] with xmin < xmax and ymin < ymax, "
                            f"not {[xmin, ymin, xmax, ymax]}", where)
        corners = box_polygon(xmin, ymin, xmax, ymax)
        return cls(name, tuple((float(x), float(y)) for x, y in corners), where, preposition)

    @cached_property
    def vertices(self) -> NDArray[np.float64]:
        v = np.array(self.polygon, dtype=float)
        v.setflags(write=False)
        return v

    @cached_property
    def area(self) -> float:
        return abs(polygon_area(self.vertices))

    @cached_property
    def bbox(self) -> Bounds:
        lo, hi = self.vertices.min(axis=0), self.vertices.max(axis=0)
        return (float(lo[0]), float(lo[1]), float(hi[0]), float(hi[1]))

    @cached_property
    def centroid(self) -> XY:
        """The area centroid (may fall outside a non-convex room)."""
        v = self.vertices
        x, y = v[:, 0], v[:, 1]
        xn, yn = np.roll(x, -1), np.roll(y, -1)
        cross = x * yn - xn * y
        a = cross.sum() / 2
        if abs(a) < 1e-12:
            return (float(x.mean()), float(y.mean()))
        return (float(((x + xn) * cross).sum() / (6 * a)), float(((y + yn) * cross).sum() / (6 * a)))

    def contains(self, points: ArrayLike) -> NDArray[np.bool_]:
        """Whether each point is in the room (half-open boundary: adjacent rooms share no point)."""
        p = as_points(points)
        xmin, ymin, xmax, ymax = self.bbox
        near = (p[:, 0] >= xmin) & (p[:, 0] <= xmax) & (p[:, 1] >= ymin) & (p[:, 1] <= ymax)
        out = np.zeros(len(p), dtype=bool)
        if near.any():
            out[near] = point_in_polygon(p[near], self.vertices)
        return out


@dataclass(frozen=True)
class Place:
    """Fixed furniture or a receptacle. ``open`` defaults to True unless ``openable`` (then closed).

    ``reach`` (m) is how far from ``at`` a robot can act on it: a prior on a place spreads its
    mass over the free space within reach. ``room`` is filled in by the map when not given.
    """

    name: str
    cls: str
    at: XY
    openable: bool = False
    open: bool | None = None
    room: str | None = None
    reach: float = 1.0
    where: Where | None = field(default=None, compare=False, repr=False)

    def __post_init__(self) -> None:
        if not isinstance(self.name, str) or not class_key(self.name):
            raise SealError(f"a place needs a name, not {self.name!r}", self.where)
        # a fact's argument: 'fridge[/]' validated, then failed every plan on the map without saying where
        check_class_name(self.name, "place name", self.where)
        if not isinstance(self.cls, str) or not class_key(self.cls):
            raise SealError(f"place {self.name} needs a class", self.where)
        object.__setattr__(self, "cls", check_class_name(self.cls, f"place {self.name}: class", self.where))
        object.__setattr__(self, "at", _xy(self.at, f"place {self.name}: at", self.where))
        object.__setattr__(self, "openable", bool(self.openable))
        object.__setattr__(self, "open", (not self.openable) if self.open is None else bool(self.open))
        if not (math.isfinite(self.reach) and self.reach > 0):
            raise SealError(f"place {self.name}: reach must be a positive number of metres, not {self.reach}",
                            self.where)
        if self.open is False and not self.openable:
            raise SealError(f"place {self.name} says open: false but is not openable (add openable: true)",
                            self.where)

    @property
    def closed(self) -> bool:
        return not self.open


@dataclass(frozen=True)
class ObjectTruth:
    """A ground-truth object: its class, where it is, and the place it is in or on (if any)."""

    cls: str
    at: XY
    inside: str | None = None
    where: Where | None = field(default=None, compare=False, repr=False)

    def __post_init__(self) -> None:
        if not isinstance(self.cls, str) or not class_key(self.cls):
            raise SealError(f"an object needs a class, not {self.cls!r}", self.where)
        object.__setattr__(self, "cls", check_class_name(self.cls, "object class", self.where))
        object.__setattr__(self, "at", _xy(self.at, f"object {self.cls}: at", self.where))


def role_keys(roles: str | Sequence[str], what: str, where: Where | None = None) -> tuple[str, ...]:
    """Roles as class keys, each once, in the order given: a noun or a list of nouns ("nurse",
    ["cook", "chef"], "head nurse")."""
    listed = [roles] if isinstance(roles, str) else list(roles)
    if not all(isinstance(r, str) and class_key(r) for r in listed):
        raise SealError(f"{what} must be a noun or a list of nouns, not {roles!r}", where)
    for role in listed:
        check_name_length(role, what, where)
    return tuple(dict.fromkeys(class_key(r) for r in listed))


@dataclass(frozen=True)
class Person:
    """Someone in the building: a name, and where they are, at a point (``at``) or in a ``room``
    (then :meth:`Map.person_at` stands them at the room's free cell nearest its centre); ``roles``
    are the nouns they are also called by ("the nurse"), as class keys (``head_nurse``)."""

    name: str
    at: XY | None = None
    room: str | None = None
    where: Where | None = field(default=None, compare=False, repr=False)
    roles: tuple[str, ...] = ()

    def __post_init__(self) -> None:
        if not isinstance(self.name, str) or not class_key(self.name):
            raise SealError(f"a person needs a name, not {self.name!r}", self.where)
        check_name_length(self.name, "person name", self.where)
        check_sayable(self.name, "person name", self.where)
        if (self.at is None) == (self.room is None):
            raise SealError(f"person {self.name} needs exactly one of at: [x, y] or room: <room>", self.where)
        if self.at is not None:
            object.__setattr__(self, "at", _xy(self.at, f"person {self.name}: at", self.where))
        object.__setattr__(self, "roles", role_keys(self.roles, f"person {self.name}: role", self.where))

    @property
    def key(self) -> str:
        return class_key(self.name)


@dataclass(frozen=True)
class Robot:
    """The robot's pose ``(x, y, yaw)`` (yaw in radians, counter-clockwise from +x) and what it holds.

    A robot built without a pose is placed by the map: at the free cell nearest the middle of
    its bounds, facing +x.
    """

    pose: tuple[float, float, float] = None  # type: ignore[assignment]  # None: placed by the map
    holding: str | None = None
    where: Where | None = field(default=None, compare=False, repr=False)

    def __post_init__(self) -> None:
        if self.holding is not None:
            held = str(self.holding)
            object.__setattr__(self, "holding", check_class_name(held, "holding", self.where) if class_key(held)
                               else None)
        if self.pose is None:
            return
        try:
            pose = [float(v) for v in self.pose]
        except (TypeError, ValueError):
            raise SealError(f"robot pose must be [x, y] or [x, y, yaw], not {self.pose!r}", self.where) from None
        if len(pose) == 2:
            pose.append(0.0)
        if len(pose) != 3 or not all(math.isfinite(v) for v in pose):
            raise SealError(f"robot pose must be [x, y] or [x, y, yaw] of finite numbers, not {self.pose!r}",
                            self.where)
        object.__setattr__(self, "pose", (pose[0], pose[1], pose[2]))

    @property
    def placed(self) -> bool:
        return self.pose is not None

    @property
    def xy(self) -> XY:
        return (self.pose[0], self.pose[1])


MIN_FOV = 1.0
"""The narrowest field of view a sensor may have, in degrees. A robot that does not see all round looks round by
turning 360 / fov times on the spot (``sim.agent.Agent.look_round``): ``fov: 0.001`` was 360,000 looks at every
stop, and ``seal run`` did not end (hostile31); at 1° it is 360, as narrow as a camera is."""

FOV_RANGE = f"degrees in [{MIN_FOV:g}, 360]"
"""How a message says the field of view a sensor may have."""


def fov_ok(value: float) -> bool:
    """Whether ``value`` is a field of view a sensor may have (:data:`MIN_FOV` to 360 degrees; NaN is not)."""
    return MIN_FOV <= value <= 360


@dataclass(frozen=True)
class Sensor:
    """What the robot perceives.

    ``range`` (m) and ``fov_deg`` (degrees, centred on the robot's yaw; 360 sees all round)
    bound the visible region, line of sight through occupied cells cuts it. ``p_detect`` is the
    probability that a visible object is detected and ``sigma`` (m) the spread of a detection
    around the object: the filter's observation model. ``noise`` (m) is the standard deviation
    of the position error of *simulated* detections.
    """

    range: float = 5.0
    fov_deg: float = 360.0
    p_detect: float = 0.9
    sigma: float = 0.3
    noise: float = 0.05
    where: Where | None = field(default=None, compare=False, repr=False)

    def __post_init__(self) -> None:
        checks = (("range", self.range, lambda v: v > 0, "a positive number of metres"),
                  ("fov", self.fov_deg, fov_ok, FOV_RANGE),
                  ("p_detect", self.p_detect, lambda v: 0 <= v <= 1, "a probability in [0, 1]"),
                  ("sigma", self.sigma, lambda v: v > 0, "a positive number of metres"),
                  ("noise", self.noise, lambda v: v >= 0, "a number of metres, 0 or more"))
        for name, value, ok, what in checks:
            if not isinstance(value, int | float) or isinstance(value, bool) or not math.isfinite(value) \
                    or not ok(value):
                raise SealError(f"sensor {name} must be {what}, not {value!r}", self.where)
            object.__setattr__(self, "fov_deg" if name == "fov" else name, float(value))


# -- the map ------------------------------------------------------------------------------------
@dataclass(frozen=True, eq=False)
class Map:
    """An annotated map (see the module docstring). Build it in code or with :func:`load_map`.

    ``bounds`` may be omitted when a ``grid`` is given (then it is the box around the grid, the
    places, the objects and the robot); ``grid`` may be omitted when ``bounds`` are given (then
    all of ``bounds`` is free). ``priors`` maps an object class to ``{room | place name | place
    class: mass}``. A robot without a pose is placed at the free cell nearest the middle. ``positions`` locates parts of
    the map in its source file by YAML path (``("rooms", 2, "polygon")``) for error messages.
    ``check=False`` builds without checking; call :meth:`problems` yourself.
    """

    name: str
    bounds: Bounds = None  # type: ignore[assignment]  # None: around the grid and what is on it
    rooms: tuple[Room, ...] = ()
    places: tuple[Place, ...] = ()
    priors: Mapping[str, Mapping[str, float]] = field(default_factory=dict)
    objects: tuple[ObjectTruth, ...] = ()
    robot: Robot = field(default_factory=Robot)  # a robot without a pose is placed by the map
    sensor: Sensor = field(default_factory=Sensor)
    grid: OccupancyGrid = None  # type: ignore[assignment]  # None: all of bounds free
    file: str | None = field(default=None, compare=False)
    positions: Mapping[tuple[str | int, ...], Where] = field(default_factory=dict, compare=False, repr=False)
    people: tuple[Person, ...] = ()
    speaker: XY | None = None
    """Where the person giving the command stands; None: at the robot's start."""
    speaker_roles: tuple[str, ...] = ()
    """The nouns the speaker is also called by (the clinic's speaker is "the doctor"), as class keys."""
    check: InitVar[bool] = True
    warnings: tuple[SealError, ...] = field(default=(), init=False, compare=False, repr=False)
    """What is odd about the map but does not stop it from being used (:class:`MapWarning`)."""

    def __post_init__(self, check: bool) -> None:
        set_ = object.__setattr__
        if self.bounds is None and self.grid is None:
            raise SealError("a map needs bounds [xmin, ymin, xmax, ymax] or an occupancy image", self.where())
        if self.bounds is None:
            set_(self, "bounds", self._grid_and_contents_bounds())
        set_(self, "bounds", self._checked_bounds(self.bounds))
        if self.grid is None:
            xmin, ymin, xmax, ymax = self.bounds
            resolution = max(0.05, math.sqrt((xmax - xmin) * (ymax - ymin) / MAX_IMPLICIT_CELLS))
            if not math.isfinite(resolution) or resolution > 1e5:
                raise SealError(f"bounds {list(self.bounds)} are too large to map without an image",
                                self.where("bounds"))
            set_(self, "grid", OccupancyGrid.filled(self.bounds, resolution))
        set_(self, "rooms", tuple(self.rooms))
        set_(self, "objects", tuple(self.objects))
        set_(self, "people", tuple(self.people))
        if self.speaker is not None:
            set_(self, "speaker", _xy(self.speaker, "speaker: at", self.where("speaker")))
        set_(self, "speaker_roles", role_keys(self.speaker_roles, "speaker: role", self.where("speaker", "role")))
        set_(self, "priors", self._checked_priors(self.priors))
        set_(self, "places", tuple(p if p.room is not None else replace(p, room=self._room_name(p.at))
                                   for p in self.places))
        if self.robot is None:
            set_(self, "robot", Robot())
        if not self.robot.placed:
            set_(self, "robot", replace(self.robot, pose=self._default_pose()))
        if check:
            problems = self.problems()
            fatal = [p for p in problems if not isinstance(p, MapWarning)]
            if fatal:
                raise SealErrors(fatal)
            set_(self, "warnings", tuple(problems))

    def _checked_priors(self, priors: Any) -> dict[str, dict[str, float]]:
        out: dict[str, dict[str, float]] = {}
        for cls, masses in dict(priors).items():
            if not isinstance(masses, Mapping):
                raise SealError(f"the prior of {cls} must map rooms, places or place classes to masses, "
                                f"not {masses!r}", self.where("priors", class_key(str(cls))))
            try:
                out[class_key(str(cls))] = {str(t): float(m) for t, m in masses.items()}
            except (TypeError, ValueError):
                raise SealError(f"the prior of {cls} has a mass that is not a number: {dict(masses)!r}",
                                self.where("priors", class_key(str(cls)))) from None
        return out

    def _grid_and_contents_bounds(self) -> Bounds:
        """The box around the grid and every place, object and placed robot (receptacles often lie
        just off a reachability grid)."""
        xmin, ymin, xmax, ymax = self.grid.bounds
        points = [p.at for p in self.places] + [o.at for o in self.objects]
        if self.robot is not None and self.robot.placed:
            points.append(self.robot.xy)
        for x, y in points:
            xmin, ymin, xmax, ymax = min(xmin, x), min(ymin, y), max(xmax, x), max(ymax, y)
        return (xmin, ymin, xmax, ymax)

    def _checked_bounds(self, bounds: Any) -> Bounds:
        try:
            values = tuple(float(v) for v in bounds)
        except (TypeError, ValueError):
            values = ()
        if len(values) != 4 or not all(math.isfinite(v) for v in values) or not (
                values[0] < values[2] and values[1] < values[3]):
            raise SealError(f"bounds must be [xmin, ymin, xmax, ymax] with xmin < xmax and ymin < ymax, "
                            f"not {bounds!r}", self.where("bounds"))
        return values

    def _default_pose(self) -> tuple[float, float, float]:
        xmin, ymin, xmax, ymax = self.bounds
        middle = np.array([(xmin + xmax) / 2, (ymin + ymax) / 2])
        if len(self.free_centres) == 0:
            return (float(middle[0]), float(middle[1]), 0.0)
        nearest = self.free_centres[np.argmin(((self.free_centres - middle) ** 2).sum(axis=1))]
        return (float(nearest[0]), float(nearest[1]), 0.0)

    def _room_name(self, xy: XY) -> str | None:
        index = int(self.room_index(np.array([xy]))[0])
        return self.rooms[index].name if index >= 0 else None

    def known(self) -> Map:
        """What a robot knows of this map before it looks: everything but the ground-truth objects,
        which only simulate what it would see. Plans made for localising and searching use this."""
        return replace(self, objects=()) if self.objects else self

    def person(self, name: str) -> Person | None:
        """The person of that name, or None."""
        key = class_key(name)
        return next((p for p in self.people if p.key == key), None)

    def person_at(self, person: Person) -> XY:
        """Where a person stands: their point, else the free cell of their room nearest its centre."""
        if person.at is not None:
            return person.at
        room = self.room(person.room or "")
        centres = self.free_centres[room.contains(self.free_centres)] if len(self.free_centres) else np.zeros((0, 2))
        if not len(centres):
            return room.centroid
        c = np.asarray(room.centroid)
        best = centres[int(np.argmin(((centres - c) ** 2).sum(axis=1)))]
        return (float(best[0]), float(best[1]))

    def with_role(self, role: str) -> tuple[str, ...]:
        """Who has this role, by id (a person's key, :data:`SPEAKER` for the speaker), in the map's order."""
        key = class_key(role)
        found = tuple(p.key for p in self.people if key in p.roles)
        return found + ((SPEAKER,) if key in self.speaker_roles else ())

    @property
    def roles(self) -> frozenset[str]:
        """Every role someone of the map has."""
        return frozenset(r for p in self.people for r in p.roles) | frozenset(self.speaker_roles)

    @property
    def speaker_at(self) -> XY:
        """Where the speaker stands: ``speaker.at``, else the robot's start."""
        return self.speaker if self.speaker is not None else self.robot.xy

    def where(self, *path: str | int) -> Where:
        """Where a part of the map (by YAML path) was written; the longest known prefix, else the file."""
        for end in range(len(path), 0, -1):
            found = self.positions.get(tuple(path[:end]))
            if found is not None:
                return found
        return Where(self.file)

    # -- names ---------------------------------------------------------------------------------
    @property
    def room_names(self) -> tuple[str, ...]:
        return tuple(r.name for r in self.rooms)

    @cached_property
    def _room_by_key(self) -> Mapping[str, int]:
        return {class_key(r.name): i for i, r in reversed(list(enumerate(self.rooms)))}

    @cached_property
    def _place_by_key(self) -> Mapping[str, Place]:
        return {class_key(p.name): p for p in reversed(self.places)}

    def room(self, name: str) -> Room:
        """The room of that name; a SealError listing the rooms if there is none."""
        index = self.room_id(name)
        if index is None:
            raise SealError(f"map {self.name} has no room {name!r}{_suggest(class_key(name), self._room_by_key)}; "
                            f"its rooms: {', '.join(self.room_names) or 'none'}")
        return self.rooms[index]

    def room_id(self, name: str) -> int | None:
        """The index of the room of that name, or None."""
        return self._room_by_key.get(class_key(name))

    def place(self, name: str) -> Place | None:
        """The place of that name, or None."""
        return self._place_by_key.get(class_key(name))

    @property
    def said(self) -> str:
        """The map's name as words, as messages say it ("corner_shop": corner shop): "the corner shop knows no
        hammer", not "the corner_shop" (e2e28: one place for every message that names a map)."""
        return " ".join(self.name.replace("_", " ").split()) or self.name

    def kinds(self) -> list[str]:
        """The kinds of thing the map knows of, by class key, sorted: its priors' classes and its objects'."""
        return sorted({class_key(c) for c in (*self.priors, *(o.cls for o in self.objects))})

    def spelt_like(self, cls: str, kinds: Iterable[str] = (), words: Container[str] = frozenset()) -> str:
        """``; the map names a mgu, spelt like it (a typo in the map?)`` when a kind of thing the map knows of
        (:meth:`kinds`, and ``kinds``) is spelt like ``cls``, which it does not know; else nothing. A refusal of a
        thing the map lacks then says what the user can fix: the map's ``{class: mgu}`` (hostile26: "the m knows no
        mug" said nothing of it). A kind among ``words`` (the classes the library knows) is spelt as meant, no typo:
        "slice the bread" on a map with beds said "the map names a bed, spelt like it" (lead, stop 39). A kind whose
        name holds every word of ``cls`` and more is said as a kind of its own ("coffee" on a map of coffee beans: "the
        map names 'coffee beans', a kind of its own ...", e2e33: it said "a coffee beans, spelt like it (a typo in the
        map?)")."""
        import difflib

        key = class_key(cls)
        known = sorted(k for k in {*self.kinds(), *(class_key(k) for k in kinds)} - {key} if k not in words)
        parts = set(key.split("_"))
        compound = next((k for k in known if parts < set(k.split("_"))), None)
        if compound is not None:        # "coffee" on a map of coffee beans: a kind of its own, no typo (e2e33)
            return f"; the map names '{compound.replace('_', ' ')}', a kind of its own: say that if it is what is meant"
        close = difflib.get_close_matches(key, known, n=1, cutoff=0.6)
        return f"; the map names a {close[0].replace('_', ' ')}, spelt like it (a typo in the map?)" if close else ""

    def unholdable(self, name: str) -> str | None:
        """Why the robot cannot hold a thing of this name on this map, or None: it names a room, a place,
        a person (or the speaker), or the class of a place (a fixed thing: "fridge" where fridge_1 stands)."""
        key = class_key(name)
        if key in self._room_by_key:
            return "a room of this map"
        if key in self._place_by_key:
            return "a place of this map (fixed)"
        if key == SPEAKER or self.person(name) is not None:
            return "a person of this map"
        fixed = next((p.name for p in self.places if p.cls == key), None)
        return None if fixed is None else f"the class of the place {fixed} (fixed)"

    def check_holding(self, holding: str) -> None:
        """Refuse ``--holding`` naming what the robot cannot hold on this map (:meth:`unholdable`)."""
        why = self.unholdable(holding)
        if why is not None:
            raise SealError(f"--holding {holding!r} is {why}; the robot can hold only a thing it picks up")

    def places_of_class(self, cls: str) -> tuple[Place, ...]:
        key = class_key(cls)
        return tuple(p for p in self.places if p.cls == key)

    def objects_of_class(self, cls: str) -> tuple[ObjectTruth, ...]:
        key = class_key(cls)
        return tuple(o for o in self.objects if o.cls == key)

    @property
    def classes(self) -> tuple[str, ...]:
        """Every object class the map mentions (priors and ground truth), sorted."""
        return tuple(sorted(set(self.priors) | {o.cls for o in self.objects}))

    # -- space ---------------------------------------------------------------------------------
    def in_bounds(self, points: ArrayLike) -> NDArray[np.bool_]:
        p = as_points(points)
        xmin, ymin, xmax, ymax = self.bounds
        return np.asarray((p[:, 0] >= xmin) & (p[:, 0] <= xmax) & (p[:, 1] >= ymin) & (p[:, 1] <= ymax))

    def is_free(self, points: ArrayLike) -> NDArray[np.bool_]:
        """Whether each point is in free space (a FREE cell whose centre is within bounds)."""
        return np.asarray(self.free_index(points) >= 0)

    def is_occupied(self, points: ArrayLike) -> NDArray[np.bool_]:
        """Whether each point is on an occupied cell (a wall or an obstacle)."""
        return self.grid.is_occupied(points)

    def room_index(self, points: ArrayLike) -> NDArray[np.intp]:
        """The index into :attr:`rooms` of the room holding each point; -1 outside every room.

        Exact (the rooms' polygons decide). Points in grid cells that no room edge comes near are
        answered from a cached raster of the rooms; the rest are tested against the polygons.
        """
        p = as_points(points)
        if len(p) < 2000 and "_room_raster" not in self.__dict__:
            return self._room_index_exact(p)  # a few points: not worth building the raster
        raster = self._room_raster
        if raster is None:
            return self._room_index_exact(p)
        labels, near_edge = raster
        rows, cols, inside = self.grid.cell_index(p)
        out = np.full(len(p), -1, dtype=np.intp)
        out[inside] = labels[rows[inside], cols[inside]]
        exact = ~inside
        exact[inside] = near_edge[rows[inside], cols[inside]]
        if exact.any():
            out[exact] = self._room_index_exact(p[exact])
        return out

    def _room_index_exact(self, p: NDArray[np.float64]) -> NDArray[np.intp]:
        """Room of each point by the polygons alone, first room first.

        Each room tests only the points within its bounding box (:func:`_box_members`), so the
        cost grows with points plus rooms, not with their product (10,000 rooms on a 4-million-cell
        grid)."""
        out = np.full(len(p), -1, dtype=np.intp)
        for index, members in _box_members(p, self._room_boxes):
            todo = members[out[members] < 0]
            if len(todo):
                out[todo[point_in_polygon(p[todo], self.rooms[index].vertices)]] = index
        return out

    @cached_property
    def _room_boxes(self) -> NDArray[np.float64]:
        """The rooms' bounding boxes, shape (R, 4): xmin, ymin, xmax, ymax."""
        return np.array([r.bbox for r in self.rooms], dtype=float).reshape(-1, 4)

    @cached_property
    def _room_raster(self) -> tuple[NDArray[np.int16], NDArray[np.bool_]] | None:
        """Per grid cell: the room of its centre, and whether a room edge passes within one cell of it
        (there the cell's points may lie in different rooms). None for no rooms or a huge grid."""
        h, w = self.grid.shape
        if not self.rooms or h * w > MAX_IMPLICIT_CELLS:
            return None
        from seal_cli.maps.geometry import segment_cells

        near = np.zeros((h, w), dtype=bool)
        for room in self.rooms:
            v = room.vertices
            for a, b in zip(v, np.roll(v, -1, axis=0), strict=True):
                rows, cols, _, valid = segment_cells(self.grid, a, b[None, :])
                keep = valid & (rows >= 0) & (rows < h) & (cols >= 0) & (cols < w)
                near[rows[keep], cols[keep]] = True
        # one cell of slack on every side, diagonals included (a 3 x 3 box, rows then columns): a
        # vertex on a grid corner touches four cells, and its edges may run through only one of them
        tall = near.copy()
        tall[1:, :] |= near[:-1, :]
        tall[:-1, :] |= near[1:, :]
        grown = tall.copy()
        grown[:, 1:] |= tall[:, :-1]
        grown[:, :-1] |= tall[:, 1:]
        rr, cc = np.mgrid[0:h, 0:w]
        labels = self._room_index_exact(self.grid.cell_centres(rr.ravel(), cc.ravel())).reshape(h, w)
        return labels.astype(np.int16), grown

    def room_of(self, points: ArrayLike) -> list[str]:
        """The name of the room of each point (:data:`OUTSIDE` for none)."""
        names = self.room_names + (OUTSIDE,)
        return [names[i] for i in self.room_index(points)]

    def rooms_at(self, xy: ArrayLike) -> tuple[str, ...]:
        """The name of every room whose polygon holds the point, in the map's order: one room where rooms do not
        overlap; more where areas drawn without walls do (a map that :meth:`problems` warns of), where
        :meth:`room_of` gives the first only."""
        point = as_points(xy)[:1]
        return tuple(room.name for room in self.rooms if point_in_polygon(point, room.vertices)[0])

    def line_of_sight(self, origin_xy: ArrayLike, points: ArrayLike) -> NDArray[np.bool_]:
        """Whether each point can be seen from ``origin_xy``: no occupied cell between them.

        Unknown cells do not block (sensors see over tables and beds that a laser map marks
        unknown); the cells of the two end points never block.
        """
        return line_of_sight(self.grid, origin_xy, points)

    # -- free cells ----------------------------------------------------------------------------
    @cached_property
    def _free_cells(self) -> tuple[NDArray[np.intp], NDArray[np.intp]]:
        rows, cols = np.nonzero(self.grid.free_mask)
        inside = self.in_bounds(self.grid.cell_centres(rows, cols))
        return rows[inside], cols[inside]

    @cached_property
    def free_centres(self) -> NDArray[np.float64]:
        """The centre of every free cell, shape (F, 2); free cells are indexed in this order."""
        centres = self.grid.cell_centres(*self._free_cells)
        centres.setflags(write=False)
        return centres

    @cached_property
    def _free_lookup(self) -> NDArray[np.int32]:
        lookup = np.full(self.grid.shape, -1, dtype=np.int32)
        rows, cols = self._free_cells
        lookup[rows, cols] = np.arange(len(rows), dtype=np.int32)
        return lookup

    def free_index(self, points: ArrayLike) -> NDArray[np.int32]:
        """The index of each point's free cell (into :attr:`free_centres`), -1 where not free."""
        p = as_points(points)
        rows, cols, inside = self.grid.cell_index(p)
        out = np.full(len(p), -1, dtype=np.int32)
        inside &= self.in_bounds(p)
        out[inside] = self._free_lookup[rows[inside], cols[inside]]
        return out

    @property
    def cell_area(self) -> float:
        return self.grid.resolution ** 2

    @property
    def free_area(self) -> float:
        """Square metres of free space."""
        return len(self.free_centres) * self.cell_area

    @cached_property
    def free_cell_room(self) -> NDArray[np.intp]:
        """The room index of each free cell's centre (-1 for none)."""
        return self._room_index_exact(self.free_centres)

    def room_free_area(self) -> dict[str, float]:
        """Square metres of free space per room, and :data:`OUTSIDE`."""
        counts = np.bincount(self.free_cell_room + 1, minlength=len(self.rooms) + 1)
        areas = {name: float(counts[i + 1]) * self.cell_area for i, name in enumerate(self.room_names)}
        areas[OUTSIDE] = float(counts[0]) * self.cell_area
        return areas

    def sample_free(self, rng: np.random.Generator, n: int, region: str | int | None = None) -> NDArray[np.float64]:
        """``n`` points uniform over free space (or over a room's free space, by name or index)."""
        cells = np.arange(len(self.free_centres))
        if region is not None:
            index = region if isinstance(region, int) else self.room_id(region)
            if index is None:
                self.room(str(region))  # raises with the list of rooms
            cells = np.flatnonzero(self.free_cell_room == index)
        if len(cells) == 0:
            raise SealError(f"map {self.name} has no free space{'' if region is None else f' in {region}'} "
                            "to sample from", self.where())
        return self.jitter_in_cells(rng, cells[rng.integers(0, len(cells), size=n)])

    def jitter_in_cells(self, rng: np.random.Generator, cells: NDArray[np.intp]) -> NDArray[np.float64]:
        """A point uniform within each given free cell (indices into :attr:`free_centres`), kept in bounds."""
        centres = self.free_centres[cells]
        res = self.grid.resolution
        points = centres + rng.uniform(-0.5, 0.5, size=(len(cells), 2)) * res
        if self.grid.yaw:
            offsets = points - centres
            c, s = math.cos(self.grid.yaw), math.sin(self.grid.yaw)
            points = centres + offsets @ np.array([[c, s], [-s, c]])
        xmin, ymin, xmax, ymax = self.bounds
        return np.column_stack([np.clip(points[:, 0], xmin, xmax), np.clip(points[:, 1], ymin, ymax)])

    # -- priors ------------------------------------------------------------------------------------
    def prior(self, cls: str, said: Sequence[str] = ()) -> Prior:
        """The prior over where objects of ``cls`` are (see :mod:`seal_cli.maps.priors`); cached per class.
        ``said``: rooms, places or place classes a command names as where the thing is ("the milk from the
        larder"), which take :data:`~seal_cli.maps.priors.SAID` of the mass."""
        from seal_cli.maps.priors import build_prior

        key = class_key(cls)
        told = tuple(sorted(set(said)))
        cache = self._prior_cache
        if (key, told) not in cache:
            cache[key, told] = build_prior(self, key, said=told)
        return cache[key, told]

    @cached_property
    def _prior_cache(self) -> dict[tuple[str, tuple[str, ...]], Prior]:
        return {}

    def target_cells(self, target: str) -> NDArray[np.intp]:
        """The free cells a prior target (a room, a place or a place class) spreads its mass over,
        sorted; computed once per target and shared by every class's prior."""
        from seal_cli.maps.priors import target_cells

        cache = self._target_cells_cache
        if target not in cache:
            cells = target_cells(self, target)
            cells.setflags(write=False)
            cache[target] = cells
        return cache[target]

    @cached_property
    def _target_cells_cache(self) -> dict[str, NDArray[np.intp]]:
        return {}

    def prior_target(self, name: str) -> tuple[str, tuple[int, ...]] | None:
        """What a prior's key names: ``("room", (index,))``, ``("place", indices)`` for a place name
        or ``("class", indices)`` for every place of a class; None if nothing. Rooms come first."""
        room = self.room_id(name)
        if room is not None:
            return ("room", (room,))
        place = self.place(name)
        if place is not None:
            return ("place", (self.places.index(place),))
        members = tuple(i for i, p in enumerate(self.places) if p.cls == class_key(name))
        return ("class", members) if members else None

    # -- checking --------------------------------------------------------------------------------
    def noting(self, warnings: Iterable[SealError]) -> Map:
        """This map, with these warnings recorded in :attr:`warnings` (for readers that check themselves)."""
        object.__setattr__(self, "warnings", tuple(warnings))
        return self

    def problems(self, known: Iterable[str] = ()) -> list[SealError]:
        """Every problem of this map, located by :attr:`positions`. ``known``: names of rooms and
        places that exist but could not be built (so that priors naming them are not blamed)."""
        return list(_problems(self, {class_key(k) for k in known}))


def _suggest(word: str, choices: Iterable[str]) -> str:
    close = difflib.get_close_matches(word, sorted(choices), n=1)
    return f" (did you mean {close[0]!r}?)" if close else ""


def _problems(m: Map, known: set[str]) -> Iterator[SealError]:
    yield from _duplicates(m)
    yield from _room_shapes(m)
    yield from _room_overlaps(m)
    yield from _places(m)
    yield from _priors(m, known)
    yield from _objects(m, known)
    yield from _robot(m)
    yield from _people(m)
    if len(m.free_centres) == 0:
        yield SealError(f"map {m.name} has no free space inside its bounds", m.where("bounds"))


def _duplicates(m: Map) -> Iterator[SealError]:
    seen: dict[str, tuple[str, int]] = {}
    named: tuple[tuple[str, Sequence[Room | Place]], ...] = (("rooms", m.rooms), ("places", m.places))
    for kind, items in named:
        for i, item in enumerate(items):
            key = class_key(item.name)
            if key in seen:
                other_kind, j = seen[key]
                first = m.where(other_kind, j)
                at = f" (first at line {first.line})" if first.line else ""
                what = "room" if other_kind == "rooms" else "place"
                yield SealError(f"{kind[:-1]} name {item.name!r} is already the name of a {what}{at}; "
                                "room and place names must be unique", m.where(kind, i, "name"))
            else:
                seen[key] = (kind, i)


def _room_shapes(m: Map) -> Iterator[SealError]:
    for i, room in enumerate(m.rooms):
        where = m.where("rooms", i, "polygon")
        crossings = self_intersections(room.vertices)
        if crossings:
            a, b = crossings[0]
            n = len(room.polygon)
            yield SealError(f"room {room.name} intersects itself: edge {a + 1} ({_edge(room, a)}) meets edge "
                            f"{b + 1} ({_edge(room, b)}) of {n}; list the vertices in order around the room", where)
        elif room.area < 1e-9:
            yield SealError(f"room {room.name} has no area", where)
        xmin, ymin, xmax, ymax = m._room_boxes[i]
        if xmax <= m.bounds[0] or xmin >= m.bounds[2] or ymax <= m.bounds[1] or ymin >= m.bounds[3]:
            yield SealError(f"room {room.name} ({_pt((xmin, ymin))}–{_pt((xmax, ymax))}) is wholly {_off(m)}: "
                            "nothing in it can be reached or seen", where)
        elif not crossings and room.area >= 1e-9 and (xmin < m.bounds[0] or ymin < m.bounds[1] or
                                                        xmax > m.bounds[2] or ymax > m.bounds[3]):
            outside = 1.0 - clipped_area(room.vertices, m.bounds) / room.area
            if outside > MAX_OUTSIDE:
                yield MapWarning(f"room {room.name} ({_pt((xmin, ymin))}–{_pt((xmax, ymax))}) lies {outside:.0%} "
                                 f"{_off(m)}: what is there can be neither reached nor seen (do the image's "
                                 "resolution and origin match the rooms?)", where)


MAX_OUTSIDE = 0.5
"""The share of a room's area that may lie outside the map's bounds without a warning. A room partly outside is
usable, but mostly outside means the image and the rooms disagree: a resolution of 0.005 for 0.05 draws the image
a tenth of its size, and a room of 50 m × 50 m on an image of 0.1 m validated without a word (hostile21). A room
whose outline follows the outer walls may stand a little past the image's last pixel: well within half."""


def _edge(room: Room, i: int) -> str:
    a, b = room.polygon[i], room.polygon[(i + 1) % len(room.polygon)]
    return f"{_pt(a)}–{_pt(b)}"


def _pt(p: Sequence[float]) -> str:
    return f"[{p[0]:g}, {p[1]:g}]"


def _box_pairs(boxes: NDArray[np.float64]) -> Iterator[tuple[int, int]]:
    """Every pair ``i < j`` of boxes whose interiors meet: a sweep over the boxes sorted by ``xmin``, so the cost
    follows the boxes and the pairs, not all pairs; the pairs of each box in turn, as they are found (a reader may
    stop early: n boxes one over another are n²/2 pairs)."""
    order = np.argsort(boxes[:, 0], kind="stable")
    xmin = boxes[order, 0]
    for k, i in enumerate(order):
        end = int(np.searchsorted(xmin, boxes[i, 2], side="left"))
        others = order[k + 1:end]
        b = boxes[others]
        meet = (b[:, 2] > boxes[i, 0]) & (b[:, 1] < boxes[i, 3]) & (b[:, 3] > boxes[i, 1])
        yield from sorted((min(int(i), int(j)), max(int(i), int(j))) for j in others[meet])


def _box_members(points: NDArray[np.float64], boxes: NDArray[np.float64]) -> Iterator[tuple[int, NDArray[np.intp]]]:
    """For each box in order that holds any, the indices of the points inside it (edges included).

    Few points or few boxes: one comparison of all against all. Otherwise the points are sorted
    into a grid of about four buckets per box and each box looks only at the buckets it covers."""
    finite = np.flatnonzero(np.isfinite(points).all(axis=1))
    if not len(finite) or not len(boxes):
        return
    q = points[finite]
    if len(q) * len(boxes) <= 2_000_000:
        inside = ((q[None, :, 0] >= boxes[:, None, 0]) & (q[None, :, 0] <= boxes[:, None, 2])
                  & (q[None, :, 1] >= boxes[:, None, 1]) & (q[None, :, 1] <= boxes[:, None, 3]))
        rooms, members = np.nonzero(inside)
        if not len(rooms):
            return
        cuts = np.flatnonzero(np.diff(rooms)) + 1
        for room, part in zip(rooms[np.r_[0, cuts]], np.split(members, cuts), strict=True):
            yield int(room), finite[part]
        return
    lo, hi = q.min(axis=0), q.max(axis=0)
    side = int(min(2048, max(1, math.isqrt(4 * min(len(boxes), len(q))))))
    size = np.where(hi > lo, (hi - lo) / side, 1.0)

    def bucket(value: float, axis: int) -> int:
        return int(min(side - 1, max(0, math.floor((value - lo[axis]) / size[axis]))))

    cells = np.clip(np.floor((q - lo) / size).astype(np.int64), 0, side - 1)
    ids = cells[:, 1] * side + cells[:, 0]
    order = np.argsort(ids, kind="stable")
    starts = np.searchsorted(ids[order], np.arange(side * side + 1))
    for room, (x0, y0, x1, y1) in enumerate(boxes):
        if x1 < lo[0] or x0 > hi[0] or y1 < lo[1] or y0 > hi[1]:
            continue
        c0, c1 = bucket(x0, 0), bucket(x1, 0)
        candidates = np.concatenate([order[starts[row * side + c0]:starts[row * side + c1 + 1]]
                                     for row in range(bucket(y0, 1), bucket(y1, 1) + 1)])
        c = q[candidates]
        keep = (c[:, 0] >= x0) & (c[:, 0] <= x1) & (c[:, 1] >= y0) & (c[:, 1] <= y1)
        if keep.any():
            yield room, finite[np.sort(candidates[keep])]


MAX_OVERLAPS = 50
"""The most overlapping pairs of rooms a map's check says: the pairs are found by a sweep, linear in rooms that do
not overlap, but n rooms drawn one over another are n²/2 pairs (hostile30: 10,000 identical rooms, a list within
:data:`MAX_LISTED`, ran for hours)."""


def _room_overlaps(m: Map) -> Iterator[SealError]:
    said = 0
    for i, j in _box_pairs(m._room_boxes):
        a, b = m.rooms[i], m.rooms[j]
        area = overlap_area(a.vertices, b.vertices)
        if area > OVERLAP_TOLERANCE and said == MAX_OVERLAPS:
            yield MapWarning(f"more rooms overlap than the {MAX_OVERLAPS} pairs said above (room {b.name} overlaps "
                             f"room {a.name} too): fix those first", m.where("rooms", j, "polygon"))
            return
        if area > OVERLAP_TOLERANCE:
            said += 1
            first = m.where("rooms", i)
            at = f" (line {first.line})" if first.line else ""
            yield MapWarning(f"room {b.name} overlaps room {a.name}{at} by about {area:.2f} m²; rooms must not "
                             "overlap (they may share walls)", m.where("rooms", j, "polygon"))


def _off(m: Map) -> str:
    """What to say of a point outside the bounds (an error: nothing there can be reached, seen or
    searched; the bounds never grow to take it in)."""
    return f"outside the map's bounds {_pt(m.bounds[:2])}–{_pt(m.bounds[2:])}"


def _outside(m: Map, xy: XY) -> bool:
    return not bool(m.in_bounds(np.array([xy]))[0])


def _places(m: Map) -> Iterator[SealError]:
    rooms = m.room_of([p.at for p in m.places]) if m.rooms and m.places else [OUTSIDE] * len(m.places)
    for i, (place, room) in enumerate(zip(m.places, rooms, strict=True)):
        if _outside(m, place.at):
            yield SealError(f"place {place.name} at {_pt(place.at)} is {_off(m)}", m.where("places", i, "at"))
        elif m.rooms and room == OUTSIDE:  # a map with rooms: each place belongs to one
            yield MapWarning(f"place {place.name} at {_pt(place.at)} is in no room of this map, so a command naming "
                             "its room never finds it; draw the room around it", m.where("places", i, "at"))


def _priors(m: Map, known: set[str]) -> Iterator[SealError]:
    names = set(m._room_by_key) | set(m._place_by_key) | {p.cls for p in m.places}
    free_rooms = np.bincount(m.free_cell_room + 1, minlength=len(m.rooms) + 1)[1:] if m.rooms else np.zeros(0)
    for cls, masses in m.priors.items():
        total = 0.0
        for target, mass in masses.items():
            where = m.where("priors", cls, target)
            resolved = m.prior_target(target)
            if resolved is None and class_key(target) not in known:
                yield SealError(f"prior of {cls} names {target!r}, which is no room, place or place class of this "
                                f"map{_suggest(class_key(target), names)}; rooms: {', '.join(m.room_names) or 'none'}",
                                where)
            if not math.isfinite(mass) or mass < 0:
                yield SealError(f"prior of {cls} gives {target} the mass {mass:g}; a mass is a number from 0 to 1",
                                where)
                continue
            total += mass
            if resolved is not None and resolved[0] == "room" and mass > 0 and free_rooms[resolved[1][0]] == 0:
                yield SealError(f"prior of {cls} puts mass on room {target}, which has no free space", where)
        if total > 1 + 1e-6:
            yield SealError(f"prior masses of {cls} sum to {total:g}, more than 1; the rest of 1 is spread over all "
                            "free space, so the masses must not exceed 1", m.where("priors", cls))


def _objects(m: Map, known: set[str]) -> Iterator[SealError]:
    taken = {class_key(p.name): "place" for p in m.places} | {p.key: "person" for p in m.people}
    counts: dict[str, int] = {}
    for i, obj in enumerate(m.objects):
        counts[obj.cls] = counts.get(obj.cls, 0) + 1      # the world calls it cls_N (sim.agent.scene_from_map)
        called = f"{obj.cls}_{counts[obj.cls]}"
        if class_key(called) in taken:
            yield SealError(f"object {obj.cls} is called {called} in a run, which is already the name of a "
                            f"{taken[class_key(called)]}; rename the {taken[class_key(called)]} or give the object "
                            "another class", m.where("objects", i, "class"))
        point = np.array([obj.at])
        if _outside(m, obj.at):
            yield SealError(f"object {obj.cls} at {_pt(obj.at)} is {_off(m)}", m.where("objects", i, "at"))
        elif m.is_occupied(point)[0] and (obj.inside is None or m.place(obj.inside) is None):
            yield MapWarning(f"object {obj.cls} at {_pt(obj.at)} is inside a wall or an obstacle (an occupied cell "
                             "of the map); if it stands on furniture, say which place it is in: in: <place>",
                            m.where("objects", i, "at"))
        if obj.inside is not None and m.place(obj.inside) is None and class_key(obj.inside) not in known:
            places = [p.name for p in m.places]
            yield SealError(f"object {obj.cls} is in {obj.inside!r}, which is no place of this map"
                            f"{_suggest(class_key(obj.inside), [class_key(p) for p in places])}; "
                            f"places: {', '.join(places) or 'none'}", m.where("objects", i, "in"))


def _robot(m: Map) -> Iterator[SealError]:
    xy = m.robot.xy
    why = m.unholdable(m.robot.holding) if m.robot.holding else None
    if why is not None:
        yield SealError(f"the robot holds {m.robot.holding!r}, which is {why}; it can hold only a thing it picks up",
                        m.where("robot", "holding"))
    if _outside(m, xy):
        yield SealError(f"robot pose {_pt(xy)} is {_off(m)}", m.where("robot", "pose"))
    elif m.is_occupied(np.array([xy]))[0]:
        yield MapWarning(f"robot pose {_pt(xy)} is inside a wall or an obstacle (an occupied cell of the map)",
                        m.where("robot", "pose"))


def _people(m: Map) -> Iterator[SealError]:
    seen: dict[str, int] = {}
    names = set(m._room_by_key) | set(m._place_by_key)
    for i, person in enumerate(m.people):
        if person.key in seen or person.key == SPEAKER:
            why = "is the speaker's name (\"me\")" if person.key == SPEAKER else \
                f"is already the name of person {seen[person.key] + 1}"
            yield SealError(f"person name {person.name!r} {why}; people's names must be unique",
                            m.where("people", i, "name"))
        elif person.key in names:
            yield SealError(f"person name {person.name!r} is already the name of a room or place",
                            m.where("people", i, "name"))
        seen.setdefault(person.key, i)
        if person.room is not None and m.room_id(person.room) is None:
            yield SealError(f"person {person.name} is in room {person.room!r}, which is no room of this map"
                            f"{_suggest(class_key(person.room), m._room_by_key)}; rooms: "
                            f"{', '.join(m.room_names) or 'none'}", m.where("people", i, "room"))
        elif person.at is not None and _outside(m, person.at):
            yield SealError(f"person {person.name} at {_pt(person.at)} is {_off(m)}",
                             m.where("people", i, "at"))
        elif person.at is not None and not m.is_free(np.array([person.at]))[0]:
            yield MapWarning(f"person {person.name} at {_pt(person.at)} stands where the robot cannot drive "
                             "(not free space)", m.where("people", i, "at"))
    if m.speaker is not None and _outside(m, m.speaker):
        yield SealError(f"speaker at {_pt(m.speaker)} is {_off(m)}", m.where("speaker", "at"))
    yield from _roles(m, names, seen)


def _roles(m: Map, names: set[str], people: Mapping[str, int]) -> Iterator[SealError]:
    """A role must call only people: not be a room's, a place's or another person's name, nor "me"."""
    holders: list[tuple[str, tuple[str, ...], tuple[str | int, ...]]] = [
        (f"person {p.name}", p.roles, ("people", i, "role")) for i, p in enumerate(m.people)]
    holders.append(("the speaker", m.speaker_roles, ("speaker", "role")))
    for who, roles, path in holders:
        for role in roles:
            clash = ("the speaker's name (\"me\")" if role == SPEAKER else
                     f"the name of person {m.people[people[role]].name}" if role in people else
                     "the name of a room or place of this map" if role in names else None)
            if clash is not None:
                yield SealError(f"{who} has the role {role!r}, which is {clash}; a role must call only people",
                                m.where(*path))


# -- priors (implemented beside, in seal_cli.maps.priors) ----------------------------------------
def prior_sampler(m: Map, cls: str) -> Prior:
    """The prior of ``cls`` on map ``m`` (``.sample(n, rng)``, ``.density(points)``)."""
    return m.prior(cls)


def sample_prior(m: Map, cls: str, n: int, rng: np.random.Generator) -> NDArray[np.float64]:
    """``n`` points drawn from the prior of ``cls``; shape (n, 2)."""
    return m.prior(cls).sample(n, rng)


def prior_density(m: Map, cls: str, points: ArrayLike) -> NDArray[np.float64]:
    """The prior density of ``cls`` at each point (per m², integrating to 1 over free space; 0 off it)."""
    return m.prior(cls).density(points)
