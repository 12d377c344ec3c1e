"""ALFRED-2D: real ALFRED trials replayed in the 2-D household simulator.

The data (``../shared/data/alfred2d/``, described in its README) holds, for every labelled trial
of ALFRED's ``train`` and ``valid_seen`` splits, the floor plan's reachable grid (0.25 m cells)
and static receptacles (with the pose from which an agent can use each), the trial's movable
objects and where they start, the agent's start pose, the task's labels, the human goal
sentences and the expert's plan. This module reads it and builds, for one trial:

- the :class:`~seal_cli.sim.world.World` (ground truth): every receptacle as a place (openable ones
  start closed), every object in or on its receptacle — the receptacle the expert took it from
  where the expert picks it up (exact), else the data's ``parent_guess`` (a heuristic);
- what the robot is told: the free grid, the places, and **place-level priors** ("apples sit in
  the fridge or on the counter"), estimated from the ``train`` split only (:func:`estimate_priors`);
- the task: its **gold** frames built from ALFRED's labels (:func:`gold_commands`), its goal
  sentences, and its **goal conditions**, judged on the world at the end (:func:`judge`).

Class names are compared with :func:`seal_cli.frames.taxonomy.class_key` (``SinkBasin`` = ``sink_basin``).
"""

from __future__ import annotations

import json
import math
import zlib
from collections import Counter, defaultdict
from collections.abc import Iterable, Iterator, Mapping, Sequence
from dataclasses import dataclass, field
from pathlib import Path
from typing import TYPE_CHECKING, Any

import numpy as np

from seal_cli.errors import SealError, SealErrors, Where
from seal_cli.frames.library import Library
from seal_cli.frames.model import Binding
from seal_cli.frames.taxonomy import class_key
from seal_cli.maps.model import Sensor as MapSensor
from seal_cli.maps.navigation import Grid
from seal_cli.sensing.model import RangeSensor, SensorModel
from seal_cli.sim.world import HAND, Item, Robot, World

if TYPE_CHECKING:
    from seal_cli.jsonvalues import Value
    from seal_cli.sim.agent import Scene

__all__ = ["FOUR", "GRID", "MOVABLE_RECEPTACLES", "TASK_TYPES", "Condition", "Episode", "FloorPlan", "Placement",
           "Receptacle", "Suite", "Task", "build_scene", "build_world", "data_files", "estimate_priors",
           "gold_commands", "gold_classes", "goal_conditions", "judge", "load_suite", "open_floor", "read_floorplans",
           "read_trials", "scene_priors", "scene_vocabulary", "suite_vocabulary", "thor_yaw",
           "train_priors"]

GRID = 0.25
"""ALFRED's agent grid, metres."""

TASK_TYPES = ("look_at_obj_in_light", "pick_and_place_simple", "pick_and_place_with_movable_recep",
              "pick_heat_then_place_in_recep", "pick_clean_then_place_in_recep", "pick_cool_then_place_in_recep",
              "pick_two_obj_and_place")
"""ALFRED's seven task types; the paper's four (look at, pick-place, pick-stack-place, pick-heat-place) first."""
FOUR = TASK_TYPES[:4]

MOVABLE_RECEPTACLES = frozenset(class_key(c) for c in ("Bowl", "Box", "Cup", "Mug", "Plate", "Pan", "Pot"))
"""Movable objects that other objects can be put into (ALFRED's ``gen/constants.py``)."""

SENSOR = RangeSensor(MapSensor(range=1.5, fov_deg=360.0))
"""The robot's eyes in ALFRED's rooms: it turns on the spot (turning costs no path) and recognises
things within 1.5 m (AI2-THOR's interaction distance); closed receptacles hide what is inside.
The scenes carry no wall geometry, so nothing else occludes."""

BELIEF_RANGE = 0.75
"""The sensor range the beliefs are told. Their particles live on free space: they are the poses
from which the robot could take a thing, up to a place's reach from it. A pose counts as looked
at when the robot passes within this distance of it — from there the thing it serves, if it were
there, would be within the robot's 1.5 m of sight; farther, it might not."""

REACH = 1.5
"""ALFRED's interaction distance (AI2-THOR's ``visibilityDistance``), metres."""


VOCABULARY = Path(__file__).resolve().parent / "suites" / "alfred2d_vocabulary.yaml"
"""The suite's vocabulary file: AI2-THOR's classes and the names people use for them where THOR's
name is not what the thing is called (a property of the simulator, like a detector's label map).
General English synonyms are the frame library's; ALFRED's labelling conventions are left to the
scene (:func:`scene_vocabulary`)."""

_VOCABULARY: dict[str, Any] = {}


def suite_vocabulary() -> Any:
    """The suite's :class:`~seal_cli.language.grounding.Vocabulary`, read once per process from :data:`VOCABULARY`."""
    from seal_cli.language.grounding import load_vocabulary

    if "suite" not in _VOCABULARY:
        _VOCABULARY["suite"] = load_vocabulary(VOCABULARY)
    return _VOCABULARY["suite"]


def scene_vocabulary(classes: Iterable[str]) -> Any:
    """The grounding vocabulary of one scene: the classes present in it (its receptacles and its
    things), with the suite's names for them, in the suite's order (which settles ties). A word is
    grounded among these only: "the table" is the room's one table, "the sink" its basin."""
    return suite_vocabulary().restricted_to(classes)


# -- the data ------------------------------------------------------------------------------------

@dataclass(frozen=True)
class Receptacle:
    """A static object of a floor plan: furniture, an appliance, a lamp."""

    id: str
    cls: str
    at: tuple[float, float]
    height: float
    openable: bool
    receptacle: bool
    access: tuple[tuple[float, float], ...]


@dataclass(frozen=True)
class FloorPlan:
    name: str
    scene_type: str
    bounds: tuple[float, float, float, float]
    reachable: tuple[tuple[float, float], ...]
    receptacles: tuple[Receptacle, ...]
    object_types: tuple[str, ...]

    def by_id(self) -> dict[str, Receptacle]:
        return {r.id: r for r in self.receptacles}

    @property
    def classes(self) -> frozenset[str]:
        """Every class of the floor plan (as class keys)."""
        return frozenset(class_key(c) for c in self.object_types) | {class_key(r.cls) for r in self.receptacles}


@dataclass(frozen=True)
class Task:
    """ALFRED's task labels (``pddl_params``)."""

    type: str
    object: str
    receptacle: str | None = None
    mrecep: str | None = None
    toggle: str | None = None
    sliced: bool = False

    def __str__(self) -> str:
        parts = [self.type, self.object + ("(sliced)" if self.sliced else ""), self.mrecep, self.receptacle,
                 self.toggle]
        return " ".join(p for p in parts if p)


@dataclass(frozen=True)
class Placement:
    """A movable object where the trial puts it at the start."""

    id: str
    cls: str
    at: tuple[float, float]
    height: float
    parent: str | None


@dataclass(frozen=True)
class Episode:
    """One ALFRED trial, ready to be replayed."""

    task_id: str
    task_dir: str
    split: str
    floor_plan: str
    scene_type: str
    task: Task
    goals: tuple[str, ...]
    start: tuple[float, float, float]
    objects: tuple[Placement, ...]
    lights_on: frozenset[str]
    expert_path_m: float
    source: Where = Where()
    """Where the trial is (its file and line): a problem of the world it makes is reported there."""

    @property
    def group(self) -> str:
        return self.task.type


@dataclass
class Suite:
    """Floor plans and the episodes of one split."""

    floor_plans: dict[str, FloorPlan]
    episodes: list[Episode]
    data_dir: Path
    movable_classes: tuple[str, ...] = ()
    priors: dict[str, dict[str, float]] = field(default_factory=dict)


def thor_yaw(rotation_deg: float) -> float:
    """AI2-THOR's rotation (0 faces +z, 90 faces +x) as a heading in the (x, z) plane (radians from +x)."""
    return math.radians((90.0 - rotation_deg) % 360.0)


def _where(path: Path, line: int | None = None) -> Where:
    return Where(str(path), line)


def data_files(data_dir: str | Path) -> list[Path]:
    """The files of the data folder the suite reads (its floor plans and every split's trials): inputs, which no
    output may replace (``bench tasks --episodes d/floorplans.json`` wrote its JSON Lines over them)."""
    return [Path(data_dir) / "floorplans.json", *sorted(Path(data_dir).glob("trials_*.jsonl"))]


def read_floorplans(data_dir: str | Path) -> tuple[dict[str, FloorPlan], tuple[str, ...]]:
    """The floor plans of ``floorplans.json``, and the classes that may move; a value of the wrong type is a
    SealError naming the file and the value's path (``floor_plans.FloorPlan1.receptacles[3].position``)."""
    from seal_cli.fileio import read_json
    from seal_cli.jsonvalues import Value

    path = Path(data_dir) / "floorplans.json"
    if not path.exists() and not path.is_symlink():
        raise SealError(f"no ALFRED-2D data here: {path} does not exist", _where(path))
    raw = Value(read_json(path, "floor plans file"), "", _where(path))
    plans = {name: _floor_plan(name, fp) for name, fp in raw["floor_plans"].items()}
    movable = raw.get("movable_classes")
    return plans, movable.texts() if movable is not None else ()


def _floor_plan(name: str, fp: Value) -> FloorPlan:
    receptacles = []
    for r in fp["receptacles"].list():
        pose = r.get("interaction_pose")
        at = pose.numbers() if pose is not None else ()
        if pose is not None and len(at) < 2:
            raise pose.problem("must be a list of at least 2 finite numbers (x, z, ...)")
        x, y, z = r["position"].numbers(3)
        receptacles.append(Receptacle(r["id"].text(), r["class"].text(), (x, z), y, r["openable"].flag(),
                                      r["receptacle"].flag(), ((at[0], at[1]),) if at else ()))
    extra = fp.get("reachable_extra")
    cells = [c.numbers(2) for c in fp["reachable"].list() + (extra.list() if extra is not None else [])]
    types = fp.get("object_types")
    xmin, ymin, xmax, ymax = fp["bounds"].numbers(4)
    return FloorPlan(name, fp["scene_type"].text(), (xmin, ymin, xmax, ymax),
                     tuple(dict.fromkeys((x, y) for x, y in cells)), tuple(receptacles),
                     types.texts() if types is not None else ())


def read_trials(data_dir: str | Path, split: str, floor_plans: Mapping[str, FloorPlan]) -> Iterator[Episode]:
    """The episodes of ``trials_<split>.jsonl``, in file order; a trial with a value of the wrong type is a
    SealError at its line, naming the value's path (``trial.objects[2].position``)."""
    from seal_cli.fileio import json_value, stream_lines
    from seal_cli.jsonvalues import Value

    path = Path(data_dir) / f"trials_{split}.jsonl"
    if not path.exists() and not path.is_symlink():
        have = sorted(p.stem.removeprefix("trials_") for p in Path(data_dir).glob("trials_*.jsonl"))
        raise SealError(f"no split {split!r} in {data_dir}; it has {', '.join(have) or 'none'}", _where(path))
    for number, line in stream_lines(path, "trials file"):
        if not line.strip():
            continue
        try:
            trial = json_value(line, path, number)  # a lone surrogate (hostile28), 5,000 digits (hostile29)
        except json.JSONDecodeError as exc:
            raise SealError(f"trial is not JSON: {exc.msg}", Where(str(path), number, exc.colno),
                            source_line=line) from None
        yield _episode(Value(trial, "trial", _where(path, number)), floor_plans)


def _optional_text(v: Value | None) -> str | None:
    return v.text() if v is not None else None


def _episode(t: Value, floor_plans: Mapping[str, FloorPlan]) -> Episode:
    floor_plan = t["floor_plan"]
    plan = floor_plans.get(floor_plan.text())
    if plan is None:
        raise floor_plan.problem(f"names no floor plan of the floor plans file ({floor_plan.raw!r})")
    task = t["task"]
    expert_parent: dict[str, str] = {}
    receptacle_ids = {r.id for r in plan.receptacles}
    expert = t["expert"]
    for step in expert["high_pddl"].list():
        source = _optional_text(step.get("from_receptacle_id"))
        if step["action"].text() == "PickupObject" and source in receptacle_ids:
            assert source is not None
            # a slice ("Apple|...|AppleSliced_1") lies where its whole object was
            whole = step["object_id"].text().split("|")
            whole_id = "|".join(whole[:4]) if len(whole) > 4 and "Sliced" in whole[-1] else "|".join(whole)
            expert_parent.setdefault(whole_id, source)
    objects = []
    for o in t["objects"].list():
        guess = o.get("parent_guess")
        index = guess.integer() if guess is not None else None
        if index is not None and not 0 <= index < len(plan.receptacles):
            assert guess is not None
            raise guess.problem(f"must be the index of one of the floor plan's {len(plan.receptacles)} receptacles "
                                f"(0 to {len(plan.receptacles) - 1}), not {index}")
        oid = o["id"].text()
        parent = expert_parent.get(oid) or (plan.receptacles[index].id if index is not None else None)
        x, y, z = o["position"].numbers(3)
        objects.append(Placement(oid, o["class"].text(), (x, z), y, parent))
    toggles = t.get("object_toggles")
    lights = frozenset(class_key(s["objectType"].text()) for s in (toggles.list() if toggles is not None else ())
                       if (on := s.get("isOn")) is not None and on.flag())
    sx, sz, rot = t["agent_start"].numbers(3)
    goals = t.get("goals")
    sliced = task.get("sliced")
    length = expert.get("path_length_m")
    return Episode(t["task_id"].text(), t["task_dir"].text(), t["split"].text(), plan.name, t["scene_type"].text(),
                   Task(task["type"].text(), task["object"].text(), _optional_text(task.get("receptacle")),
                        _optional_text(task.get("mrecep")), _optional_text(task.get("toggle")),
                        sliced.flag() if sliced is not None else False),
                   goals.texts() if goals is not None else (), (sx, sz, thor_yaw(rot)), tuple(objects), lights,
                   length.number() if length is not None else math.nan, t.where)


def load_suite(data_dir: str | Path, split: str, *, limit: int | None = None,
               types: Sequence[str] | None = None, with_priors: bool = True, sample: int | None = None) -> Suite:
    """The split's episodes (the first ``limit`` of each task type, if given), with priors from ``train``.

    ``sample``: a stratified sample instead, ``sample`` episodes of each task type, those first in the
    order of a hash of their id (the same sample whatever the seed; kept in the file's order)."""
    plans, movable = read_floorplans(data_dir)
    unknown = [t for t in types or () if t not in TASK_TYPES]
    if unknown:
        raise SealError(f"unknown task type {unknown[0]!r}; ALFRED's are {', '.join(TASK_TYPES)}")
    counts: Counter[str] = Counter()
    episodes = []
    wanted = tuple(types or TASK_TYPES)
    for episode in read_trials(data_dir, split, plans):
        if types and episode.group not in types:
            continue
        if limit is not None and counts[episode.group] >= limit:
            continue
        counts[episode.group] += 1
        episodes.append(episode)
        if limit is not None and sample is None and all(counts[t] >= limit for t in wanted):
            break   # every type has its first ``limit``: the rest of the file (35 MB for train) is not read
    if sample is not None:
        episodes = _stratified(episodes, sample)
    suite = Suite(plans, episodes, Path(data_dir), movable)
    if with_priors:
        suite.priors = train_priors(data_dir)
    return suite


def _stratified(episodes: list[Episode], per_group: int) -> list[Episode]:
    by_group: dict[str, list[Episode]] = {}
    for episode in episodes:
        by_group.setdefault(episode.group, []).append(episode)
    chosen = {e.task_id for group in by_group.values()
              for e in sorted(group, key=lambda e: zlib.crc32(e.task_id.encode()))[:per_group]}
    return [e for e in episodes if e.task_id in chosen]


_TRAIN: dict[tuple[str, float], dict[str, dict[str, float]]] = {}


def train_priors(data_dir: str | Path) -> dict[str, dict[str, float]]:
    """:func:`estimate_priors` over the ``train`` split (one reading, kept per process: reading it takes a
    while)."""
    path = Path(data_dir) / "trials_train.jsonl"
    key = (str(path.resolve()), path.stat().st_mtime if path.exists() else 0.0)
    if key not in _TRAIN:
        plans, _ = read_floorplans(data_dir)
        _TRAIN[key] = estimate_priors(read_trials(data_dir, "train", plans), plans)
    return _TRAIN[key]


# -- priors -----------------------------------------------------------------------------------------

def estimate_priors(episodes: Iterable[Episode], floor_plans: Mapping[str, FloorPlan]) -> dict[str, dict[str, float]]:
    """P(receptacle class | object class) over the given episodes (the ``train`` split): how often an
    object of each class starts in or on a receptacle of each class, ``"_none"`` for none."""
    counts: dict[str, Counter[str]] = defaultdict(Counter)
    for episode in episodes:
        classes = {r.id: class_key(r.cls) for r in floor_plans[episode.floor_plan].receptacles}
        for obj in episode.objects:
            counts[class_key(obj.cls)][classes.get(obj.parent or "", "_none")] += 1
    return {obj: {rec: n / sum(c.values()) for rec, n in sorted(c.items())} for obj, c in sorted(counts.items())}


SPREAD_LEVELS = (0.125, 0.375, 0.625, 0.875)
"""The quantiles :func:`place_spread` reports: the midpoints of four equally likely bands."""


def place_spread(episodes: Iterable[Episode], floor_plans: Mapping[str, FloorPlan],
                 levels: Sequence[float] = SPREAD_LEVELS) -> tuple[float, ...]:
    """Where on a receptacle a thing lies, the shape SeFM's search takes for it
    (:attr:`~seal_cli.sim.policies.sefm.SeFMPolicy.ON_PLACE`): over the things that start on a receptacle that
    does not open, the distance from the receptacle's pivot as a share of the pivot's distance to the nearest
    reachable position, at the quantiles ``levels`` (rounded to three places). Scenes repeat across episodes,
    and each thing counts once per episode."""
    shares: list[float] = []
    nearest: dict[tuple[str, str], float] = {}
    for episode in episodes:
        plan = floor_plans[episode.floor_plan]
        receptacles = plan.by_id()
        reachable = np.asarray(plan.reachable, dtype=float).reshape(-1, 2)
        for obj in episode.objects:
            r = receptacles.get(obj.parent or "")
            if r is None or r.openable or not len(reachable):
                continue
            key = (plan.name, r.id)
            if key not in nearest:
                nearest[key] = float(np.min(np.hypot(reachable[:, 0] - r.at[0], reachable[:, 1] - r.at[1])))
            if nearest[key] > 0:
                shares.append(math.dist(obj.at, r.at) / nearest[key])
    if not shares:
        raise SealError("no thing starts on a receptacle that does not open: no spread to estimate")
    return tuple(round(float(q), 3) for q in np.quantile(np.asarray(shares), list(levels)))


def scene_priors(priors: Mapping[str, Mapping[str, float]], plan: FloorPlan, classes: Iterable[str],
                 floor: float = 0.02) -> dict[str, dict[str, float]]:
    """Place-class priors for one floor plan: the learnt distribution restricted to the receptacle
    classes this plan has, each present class given at least ``floor`` (nothing is impossible), and
    renormalised. A class never seen in training gets the same mass on every receptacle class."""
    present = sorted({class_key(r.cls) for r in plan.receptacles if r.receptacle})
    out: dict[str, dict[str, float]] = {}
    for cls in classes:
        learnt = priors.get(class_key(cls), {})
        mass = {rec: max(learnt.get(rec, 0.0), floor) for rec in present}
        total = sum(mass.values())
        out[class_key(cls)] = {rec: m / total for rec, m in mass.items()} if total else {}
    return out


def open_floor(priors: Mapping[str, Mapping[str, float]], plan: FloorPlan, classes: Iterable[str],
               floor: float = 0.02) -> dict[str, float]:
    """Per class, the learnt chance that a thing of it lies on no receptacle of this floor plan (``"_none"``
    of :func:`estimate_priors`: a baseball bat or a tennis racket on the floor), restricted to this plan
    as :func:`scene_priors` restricts the rest: the none share against it plus the present receptacle
    classes' (each at least ``floor``). The search of the open floor reads it
    (:attr:`~seal_cli.sim.agent.Scene.open_floor`); classes never on the floor are left out."""
    present = sorted({class_key(r.cls) for r in plan.receptacles if r.receptacle})
    out = {}
    for cls in classes:
        learnt = priors.get(class_key(cls), {})
        none = float(learnt.get("_none", 0.0))
        if none > 0:
            out[class_key(cls)] = none / (none + sum(max(learnt.get(rec, 0.0), floor) for rec in present))
    return out


# -- the world --------------------------------------------------------------------------------------

def build_scene(episode: Episode, plan: FloorPlan, library: Library, priors: Mapping[str, Mapping[str, float]],
                *, sensor: SensorModel | None = None) -> Scene:
    """The episode as a :class:`~seal_cli.sim.agent.Scene`: the world (ground truth) and the map the
    robot is given — the reachable grid, the receptacles as places (openable ones closed), and
    place-level priors for every movable class of the scene. Items get short names
    (``fridge_1``, ``apple_2``) in the data's order."""
    try:
        return _scene(episode, plan, library, priors, sensor)
    except SealError as error:  # the trial's data (a start outside the floor plan): said at the trial's line
        if error.file is not None:
            raise
        said = [p.message for p in error.problems] if isinstance(error, SealErrors) else [error.message]
        raise SealError(f"trial {episode.task_id}: {'; '.join(said)}", episode.source) from None


def _scene(episode: Episode, plan: FloorPlan, library: Library, priors: Mapping[str, Mapping[str, float]],
           sensor: SensorModel | None) -> Scene:
    from seal_cli.maps.geometry import OccupancyGrid
    from seal_cli.maps.model import Map, ObjectTruth, Place, Room
    from seal_cli.maps.model import Robot as MapRobot
    from seal_cli.sim.agent import Scene

    world, names = build_world(episode, plan, library, sensor=sensor)
    grid = Grid.from_points(plan.reachable, GRID, connectivity=4)
    occupancy = OccupancyGrid.from_cells(plan.reachable, GRID)
    gx0, gy0, gx1, gy1 = occupancy.bounds
    bx0, by0, bx1, by1 = plan.bounds
    bounds = (min(gx0, bx0) - 0.5, min(gy0, by0) - 0.5, max(gx1, bx1) + 0.5, max(gy1, by1) + 0.5)
    places = tuple(Place(i.id, i.key, i.at, openable=i.openable, reach=_place_reach(i, grid))
                   for i in world.items.values() if not i.movable)
    movable = sorted({i.key for i in world.items.values() if i.movable})
    objects = tuple(ObjectTruth(i.key, i.at, i.parent) for i in world.items.values() if i.movable)
    s = world.sensor
    the_map = Map(f"{episode.floor_plan}:{episode.task_id}", bounds,
                  rooms=(Room.box(episode.scene_type, *bounds),), places=places,
                  priors=scene_priors(priors, plan, movable), objects=objects,
                  robot=MapRobot(episode.start), sensor=MapSensor(range=BELIEF_RANGE, fov_deg=s.spec.fov_deg),
                  grid=occupancy)
    vocabulary = tuple(sorted({i.key for i in world.items.values()}))
    return Scene(world, the_map, grid, vocabulary, f"{episode.task_dir} ({episode.task_id})",
                 open_floor=open_floor(priors, plan, movable))


def _place_reach(item: Item, grid: Grid) -> float:
    """How far from a receptacle's pivot the robot stands to use it, as the map's ``reach``: the
    nearest free cell's distance plus one cell (never more than the arm's reach). A place's prior
    mass, and what a shut place may hide, is spread over those cells only."""
    pts = grid.free_points
    nearest = float(np.min(np.hypot(pts[:, 0] - item.at[0], pts[:, 1] - item.at[1])))
    for a in item.access:
        nearest = min(nearest, math.dist(a, item.at))
    return min(REACH, nearest + GRID + 0.05)


def build_world(episode: Episode, plan: FloorPlan, library: Library, *,
                sensor: SensorModel | None = None) -> tuple[World, dict[str, str]]:
    """The episode's ground truth: receptacles as places (openable ones closed), objects where the
    trial puts them, lamps on as the trial says, the robot at the start pose with an empty hand.
    Also returns each item's short name → ALFRED object id."""
    taxonomy = library.taxonomy
    counts: Counter[str] = Counter()
    names: dict[str, str] = {}

    def short(alfred_id: str, key: str) -> str:
        counts[key] += 1
        name = f"{key}_{counts[key]}"
        names[alfred_id] = name
        return name

    items = []
    for r in plan.receptacles:
        key = class_key(r.cls)
        item = Item(short(r.id, key), key, r.at, movable=False, receptacle=r.receptacle, openable=r.openable,
                    toggleable=taxonomy.is_a(key, "toggleable") is True, access=r.access)
        if key in episode.lights_on:
            item.states.add("on")
        items.append(item)
    for o in episode.objects:
        key = class_key(o.cls)
        items.append(Item(short(o.id, key), key, o.at, movable=True, receptacle=key in MOVABLE_RECEPTACLES,
                          parent=names.get(o.parent or "")))
    robot = Robot(pose=episode.start)
    world = World(items, robot, taxonomy=taxonomy, reach=REACH, sensor=sensor or SENSOR)
    return world, {v: k for k, v in names.items()}


# -- the task -------------------------------------------------------------------------------------

def _instrument(library: Library, category: str, preferred: str, classes: frozenset[str]) -> str:
    """The class of the scene that serves as the ``category`` (a knife: Knife, else ButterKnife)."""
    if preferred in classes:
        return preferred
    members = sorted(c for c in classes if library.taxonomy.is_a(c, category) is True)
    return members[0] if members else preferred


def gold_commands(task: Task, library: Library, classes: Iterable[str] = ()) -> list[Binding]:
    """The frames ALFRED's labels command, in order (the planner adds what they need first).

    ``pick_heat_then_place_in_recep`` Egg → Fridge is Heat(egg), Place(egg, fridge); a sliced
    object is sliced first; a movable receptacle is filled, then placed; "pick two" places twice.
    """
    have = frozenset(class_key(c) for c in classes)
    obj = class_key(task.object)
    recep = class_key(task.receptacle) if task.receptacle else None
    frames: list[Binding] = []

    def bind(name: str, **values: str | None) -> Binding:
        return library.frame(name).bind(values)

    if task.sliced:
        frames.append(bind("Slice", theme=obj, instrument=_instrument(library, "cutter", "knife", have)))
    kind = task.type
    if kind == "look_at_obj_in_light":
        frames.append(bind("LookAt", theme=obj, instrument=class_key(task.toggle or "desk_lamp")))
        return frames
    if recep is None:
        raise SealError(f"task {task} names no receptacle")
    if kind == "pick_and_place_simple":
        frames.append(bind("Place", theme=obj, goal=recep))
    elif kind == "pick_two_obj_and_place":  # two things of one class: obj and obj_2 (see gold_classes)
        frames += [bind("Place", theme=obj, goal=recep), bind("Place", theme=f"{obj}_2", goal=recep)]
    elif kind == "pick_and_place_with_movable_recep":
        mrecep = class_key(task.mrecep or "")
        frames += [bind("Place", theme=obj, goal=mrecep), bind("Place", theme=mrecep, goal=recep)]
    else:
        verb, category, preferred = {"pick_heat_then_place_in_recep": ("Heat", "heater", "microwave"),
                                     "pick_cool_then_place_in_recep": ("Cool", "cooler", "fridge"),
                                     "pick_clean_then_place_in_recep": ("Clean", "washer", "sink_basin")}[kind]
        frames += [bind(verb, theme=obj, instrument=_instrument(library, category, preferred, have)),
                   bind("Place", theme=obj, goal=recep)]
    return frames


def gold_classes(task: Task) -> dict[str, str]:
    """The class of each name :func:`gold_commands` uses that is not a class (``book_2``: a second book)."""
    obj = class_key(task.object)
    return {f"{obj}_2": obj} if task.type == "pick_two_obj_and_place" else {}


@dataclass(frozen=True)
class Condition:
    """One goal condition over item ids: ``kind`` is a state (``hot``), ``in`` (a, b), ``held`` (a)
    or ``lit_near`` (a lamp that is on, within the robot's reach)."""

    kind: str
    args: tuple[str, ...]

    def __str__(self) -> str:
        return f"{self.kind}({', '.join(self.args)})"


def goal_conditions(task: Task) -> list[tuple[str, tuple[str, ...]]]:
    """The task type's goal conditions over *classes*, in the order they must come true.

    Each is ``(kind, classes)``; :func:`judge` looks for objects of those classes that satisfy all
    of them at the end, each no earlier than the one before it."""
    obj = class_key(task.object)
    recep = class_key(task.receptacle) if task.receptacle else ""
    conds: list[tuple[str, tuple[str, ...]]] = [("sliced", (obj,))] if task.sliced else []
    kind = task.type
    if kind == "look_at_obj_in_light":
        return conds + [("held", (obj,)), ("lit_near", (class_key(task.toggle or ""),))]
    if kind == "pick_and_place_simple":
        return conds + [("in", (obj, recep))]
    if kind == "pick_two_obj_and_place":
        return conds + [("in", (obj, recep)), ("in2", (obj, recep))]
    if kind == "pick_and_place_with_movable_recep":
        return conds + [("in", (obj, class_key(task.mrecep or ""))), ("in", (class_key(task.mrecep or ""), recep))]
    state = {"pick_heat_then_place_in_recep": "hot", "pick_cool_then_place_in_recep": "cold",
             "pick_clean_then_place_in_recep": "clean"}.get(kind)
    if state is None:
        raise SealError(f"unknown task type {kind!r}; ALFRED's are {', '.join(TASK_TYPES)}")
    return conds + [(state, (obj,)), ("in", (obj, recep))]


@dataclass(frozen=True)
class Verdict:
    success: bool
    reason: str
    satisfied: tuple[str, ...] = ()


def judge(task: Task, world: World) -> Verdict:
    """Whether the world at the end satisfies every goal condition of the task, in order.

    Conditions name classes; some assignment of objects to them must make each condition true
    now, and the step at which each last became true must not precede the previous one's (the
    apple was heated and *then* put on the table; sliced before it was heated)."""
    conds = goal_conditions(task)
    obj_key = class_key(task.object)
    candidates = [i.id for i in world.of_class(obj_key)]
    mrecep_key = class_key(task.mrecep) if task.mrecep else None
    mreceps = [i.id for i in world.of_class(mrecep_key)] if mrecep_key else [None]
    best: tuple[int, list[str]] = (-1, [])
    for primary in candidates:
        for second in mreceps:
            ok, times, done = _check(conds, world, primary, second)
            if ok and _ordered(times):
                return Verdict(True, "all goal conditions hold, in order", tuple(done))
            if len(done) > best[0]:
                best = (len(done), done + (["out of order"] if ok else []))
    missing = [f"{k}({', '.join(a)})" for k, a in conds]
    met = best[1]
    return Verdict(False, f"not done: needs {', '.join(missing)}; best had {', '.join(met) or 'nothing'}", tuple(met))


def _check(conds: Sequence[tuple[str, tuple[str, ...]]], world: World, obj: str,
           mrecep: str | None) -> tuple[bool, list[int], list[str]]:
    """Evaluate the conditions with ``obj`` (and ``mrecep``) as the task's objects."""
    times: list[int] = []
    done: list[str] = []
    used = {obj}
    for kind, classes in conds:
        t = _holds(kind, classes, world, obj, mrecep, used)
        if t is None:
            return False, times, done
        times.append(t)
        done.append(f"{kind}({', '.join(classes)})")
    return True, times, done


def _holds(kind: str, classes: tuple[str, ...], world: World, obj: str, mrecep: str | None,
           used: set[str]) -> int | None:
    """The step at which the condition last came true, or None if it does not hold."""
    if kind in ("hot", "cold", "clean", "sliced"):
        return world.since(obj, kind) if world.has(obj, kind) else None
    if kind == "held":
        return world.since(obj, "parent") if world.items[obj].parent == HAND else None
    if kind == "lit_near":
        lamps = [i for i in world.of_class(classes[0]) if world.has(i.id, "on") and world.within_reach(i.id)]
        return min((world.since(i.id, "on") for i in lamps), default=None)
    if kind in ("in", "in2"):
        thing_cls, recep_cls = classes
        if kind == "in2":
            if world.has(obj, "sliced"):  # a sliced object is its slices: two of them went in together
                return world.since(obj, "parent")
            others = [i for i in world.of_class(thing_cls) if i.id not in used and _in(world, i.id, recep_cls)
                      and _same_state(world, obj, i.id)]
            if not others:
                return None
            used.add(others[0].id)
            return world.since(others[0].id, "parent")
        thing = obj if world.items[obj].key == thing_cls else mrecep
        if thing is None or not _in(world, thing, recep_cls):
            return None
        if thing == obj and mrecep is not None and world.items[mrecep].key == recep_cls \
                and world.items[obj].parent != mrecep:
            return None  # in *the* movable receptacle that goes on to the receptacle
        return world.since(thing, "parent")
    raise SealError(f"unknown goal condition {kind!r}")


def _in(world: World, thing: str, recep_cls: str) -> bool:
    parent = world.items[thing].parent
    return parent is not None and parent != HAND and world.items[parent].key == recep_cls


def _same_state(world: World, a: str, b: str) -> bool:
    """A second object counts when it has the first one's sliced state (two slices, or two wholes)."""
    return world.has(a, "sliced") == world.has(b, "sliced")


def _ordered(times: Sequence[int]) -> bool:
    return all(a <= b for a, b in zip(times, times[1:], strict=False))
