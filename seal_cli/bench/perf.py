"""``seal bench perf``: how fast SeFM updates its beliefs, against the exact O(P²) evaluation.

Three scales (SPEC, "seal bench"):

``paper``
    the paper's Gazebo study: the shipped apartment, the frames Pick(cup), Pick(spoon),
    Stir(cup, spoon) (3 frames) over 2 object classes, 200 particles each.
``building``
    a 30 m × 20 m floor of 24 walled rooms (:func:`building`), 60 object classes with priors
    on one to three rooms each and one ground-truth instance each, and 60 frames — 20 Pick, 20
    Stir (utensil core, container other, context the utensil's Pick) and 20 Place into a room —,
    1,000 particles per object and per frame.
``large``
    a 120 m × 80 m floor of 384 walled rooms (the same :func:`building`, 0.1 m cells: 0.96 M cells),
    200 object classes and 200 frames (70 Pick, 70 Stir, 60 Place), 1,000 particles each.

Each scale runs in a process of its own (``spawn``), so that ``peak_rss_mb`` — the peak resident memory
of that process, from ``getrusage``, when the engine's updates are done and before the exact reference
runs — is the scale's engine alone and not the largest seen so far.

In all, the robot drives a loop through the map, one update per pose, with detections simulated
from the ground truth. ``updates_per_s`` times :meth:`SeFM.update <seal_cli.sefm.filter.SeFM.update>`
with the grid kernel sums (the engine), ``exact_updates_per_s`` the same updates with the exact
ones. ``tv_distance`` compares the two on the same particles: after the timed engine updates,
both kernels are given the same object and frame particle sets, every frame's target γ is
evaluated at its particles by each, and the total variation distance between the normalised
weights is taken; the largest over the frames is reported. ``compiled`` says whether the engine's inner
loops ran compiled (numba, :mod:`seal_cli.sefm.compiled`) or as numpy: the same numbers, not the same speed.
"""

from __future__ import annotations

import time
from collections.abc import Callable, Sequence
from dataclasses import dataclass
from typing import Any

import numpy as np

from seal_cli.frames.library import Library
from seal_cli.frames.model import Binding
from seal_cli.maps.model import Map, ObjectTruth, Robot, Room, Sensor
from seal_cli.planning.state import State, robot_facts
from seal_cli.sefm import compiled
from seal_cli.sefm.filter import SeFM, SeFMConfig
from seal_cli.sefm.potentials import make_kernel_sums
from seal_cli.sensing.model import simulate_detections

__all__ = ["SCALES", "Scale", "building", "measure", "measure_apart", "peak_rss_mb", "scale", "scales"]


@dataclass(frozen=True)
class Scale:
    name: str
    map: Map
    bindings: tuple[Binding, ...]
    state: State
    particles: int
    path: tuple[tuple[float, float, float], ...]
    updates: int
    exact_updates: int

    @property
    def objects(self) -> int:
        return len({v for b in self.bindings for v in b.elements.values() if self.map.room_id(v) is None})


def building(rng: np.random.Generator, classes: int = 60, columns: int = 6, rows: int = 4, room: float = 5.0,
             resolution: float = 0.1) -> Map:
    """A floor of ``columns × rows`` walled rooms of ``room`` metres with doorways between neighbours,
    ``classes`` object classes with priors on one to three rooms, and one instance of each."""
    from seal_cli.maps.geometry import OccupancyGrid

    width, height = columns * room, rows * room
    nx, ny = int(round(width / resolution)), int(round(height / resolution))
    ys, xs = (np.mgrid[0:ny, 0:nx] + 0.5) * resolution

    def on_wall(v: np.ndarray) -> np.ndarray:
        return np.abs((v + room / 2) % room - room / 2) < 0.06

    def mid_wall(v: np.ndarray) -> np.ndarray:  # a 1 m doorway in the middle of each wall
        return np.abs(v % room - room / 2) < 0.5

    outside = (xs < 0.1) | (ys < 0.1) | (xs > width - 0.1) | (ys > height - 0.1)
    walls = ((on_wall(xs) & ~mid_wall(ys)) | (on_wall(ys) & ~mid_wall(xs))) | outside
    grid = OccupancyGrid.from_masks(~walls, resolution, (0.0, 0.0, 0.0), walls)
    names = [f"room_{i}_{j}" for j in range(rows) for i in range(columns)]
    rooms = tuple(Room.box(f"room_{i}_{j}", i * room, j * room, (i + 1) * room, (j + 1) * room)
                  for j in range(rows) for i in range(columns))
    priors: dict[str, dict[str, float]] = {}
    objects = []
    for k in range(classes):
        chosen = rng.choice(len(names), size=int(rng.integers(1, 4)), replace=False)
        priors[f"thing_{k:02d}"] = {names[c]: 0.95 / len(chosen) for c in chosen}
        home = rooms[int(rng.choice(chosen))]
        xmin, ymin, xmax, ymax = home.bbox
        objects.append(ObjectTruth(f"thing_{k:02d}", (float(rng.uniform(xmin + 0.5, xmax - 0.5)),
                                                      float(rng.uniform(ymin + 0.5, ymax - 0.5)))))
    return Map("building", (0.0, 0.0, width, height), rooms, (), priors, tuple(objects),
               Robot((room / 2, room / 2, 0.0)), Sensor(), grid)


def _loop(m: Map, room: float = 5.0) -> tuple[tuple[float, float, float], ...]:
    """Room centres in a snake through the floor, with a stop in each doorway on the way."""
    xmin, ymin, xmax, ymax = m.bounds
    columns, rows = int(round((xmax - xmin) / room)), int(round((ymax - ymin) / room))
    centres = []
    for j in range(rows):
        order = range(columns) if j % 2 == 0 else reversed(range(columns))
        centres += [((i + 0.5) * room, (j + 0.5) * room) for i in order]
    path: list[tuple[float, float, float]] = []
    for a, b in zip(centres, centres[1:], strict=False):
        path += [(a[0], a[1], 0.0), ((a[0] + b[0]) / 2, (a[1] + b[1]) / 2, 0.0)]
    return (*path, (*centres[-1], 0.0))


SCALES = ("paper", "building", "large")
"""The names of the scales, smallest first."""


def scales(library: Library, load_apartment: Callable[[], Map], which: Sequence[str] = SCALES[:2],
           seed: int = 0) -> list[Scale]:
    """The benchmark's scales (see the module docstring)."""
    return [scale(name, library, load_apartment, seed) for name in SCALES if name in which]


def scale(name: str, library: Library, load_apartment: Callable[[], Map], seed: int = 0) -> Scale:
    """One of :data:`SCALES`."""
    hand_empty = State.of(robot_facts(None), library.taxonomy)
    if name == "paper":
        m = load_apartment()
        bindings: tuple[Binding, ...] = (library.frame("Pick").bind({"theme": "cup"}),
                                         library.frame("Pick").bind({"theme": "spoon"}),
                                         library.frame("Stir").bind({"theme": "cup"}))
        path = tuple((x, y, 0.0) for x, y in [(-6, -3), (-3.5, -0.2), (-1, -2.5), (1, -2.5), (2.5, -4.7), (5, -4.5),
                                              (7, -3), (5, -4.5), (2.5, -4.7), (1, -2), (0.5, 0.5), (0.5, 2.5)])
        return Scale("paper", m, bindings, hand_empty, 200, path, 200, 40)
    if name == "building":
        m = building(np.random.default_rng(seed))
        return Scale("building", m, _frames(library, m, 20, 20, 20), hand_empty, 1000, _loop(m), 30, 2)
    if name == "large":
        m = building(np.random.default_rng(seed), classes=200, columns=24, rows=16)
        return Scale("large", m, _frames(library, m, 70, 70, 60), hand_empty, 1000, _loop(m), 10, 1)
    raise KeyError(name)


def _frames(library: Library, m: Map, picks: int, stirs: int, places: int) -> tuple[Binding, ...]:
    """``picks`` Pick frames, ``stirs`` Stir frames (instrument: one of the picked things) and ``places``
    Place frames into a room, over the map's classes in order."""
    things = sorted(m.priors)
    pick, stir, place = (library.frame(n) for n in ("Pick", "Stir", "Place"))
    return tuple([pick.bind({"theme": t}) for t in things[:picks]]
                 + [stir.bind({"theme": things[picks + k], "instrument": things[k % picks]}) for k in range(stirs)]
                 + [place.bind({"theme": things[picks + stirs + k], "goal": m.rooms[k % len(m.rooms)].name})
                    for k in range(places)])


def _run(scale: Scale, kernel: str, updates: int, seed: int) -> tuple[SeFM, float]:
    """Build SeFM and make ``updates`` updates along the path; the CPU seconds the updates took (the
    process's own time, so that other work on the machine does not count)."""
    rng = np.random.default_rng(seed)
    sefm = SeFM(scale.map, scale.bindings, scale.state, rng, SeFMConfig(particles=scale.particles, kernel=kernel))
    poses = [scale.path[k % len(scale.path)] for k in range(updates)]
    seen = [simulate_detections(scale.map, pose, sefm.open_places(), rng) for pose in poses]
    start = time.process_time()
    for pose, detections in zip(poses, seen, strict=True):
        sefm.update(pose, detections, scale.state)
    return sefm, time.process_time() - start


def tv_distance(sefm: SeFM) -> float:
    """The largest total variation distance, over the frames, between the weights γ/Σγ of the engine's
    grid kernel sums and of the exact ones, evaluated on the same particles."""
    terms = sefm.terms()
    C, F, P = len(sefm.sources), len(sefm.bindings), sefm.config.particles
    gammas = []
    for kind in ("grid", "exact"):
        kernel = make_kernel_sums(kind, C + F, P, sefm.map.bounds, sefm.config.sigma, split=C)
        kernel.set(range(C), sefm.objects.X, sefm.objects.W)
        kernel.set(range(C, C + F), sefm.frames.X, sefm.frames.W)
        gammas.append(sefm.frames.gamma_at(terms, kernel, sefm.frames.X))
    grid, exact = (g / g.sum(axis=1, keepdims=True) for g in gammas)
    return float(0.5 * np.abs(grid - exact).sum(axis=1).max())


def measure(scale: Scale, seed: int = 0, progress: Callable[[str], None] | None = None) -> dict[str, Any]:
    """The SPEC's figures for one scale. ``peak_rss_mb`` is the process's peak once SeFM is built and its
    engine updates are done, before the exact reference runs (so, in a process of its own, the engine's)."""
    say = progress or (lambda _: None)
    say(f"{scale.name}: {scale.updates} engine updates")
    engine, seconds = _run(scale, "grid", scale.updates, seed)
    peak = peak_rss_mb()  # the engine's: building SeFM and its updates (the reference below needs more)
    say(f"{scale.name}: {scale.exact_updates} exact updates")
    _, exact_seconds = _run(scale, "exact", scale.exact_updates, seed)
    say(f"{scale.name}: total variation")
    return {"name": scale.name, "frames": len(scale.bindings), "objects": scale.objects,
            "particles": scale.particles, "updates_per_s": round(scale.updates / max(seconds, 1e-9), 2),
            "exact_updates_per_s": round(scale.exact_updates / max(exact_seconds, 1e-9), 3),
            "tv_distance": round(tv_distance(engine), 5), "peak_rss_mb": round(peak, 1),
            "compiled": compiled.kernels() is not None}


def peak_rss_mb(children: bool = False) -> float:
    """The peak resident memory of this process, in MB (``ru_maxrss`` is in KiB on Linux, bytes on macOS); with
    ``children``, the largest of it and of every child process it has waited for (the workers of a pool)."""
    import resource
    import sys

    peak = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss
    if children:
        peak = max(peak, resource.getrusage(resource.RUSAGE_CHILDREN).ru_maxrss)
    return peak / (1 << 20) if sys.platform == "darwin" else peak / 1024


def measure_apart(name: str, seed: int = 0, framelib: Sequence[str] = ()) -> dict[str, Any]:
    """:func:`measure` of the scale ``name`` in a fresh process of its own, so that its ``peak_rss_mb``
    counts that scale alone. The library is the shipped one unless ``framelib`` paths are given."""
    from seal_cli.bench.workers import ordered

    return next(ordered(_measure_named, [(name, seed, tuple(framelib))], 1, method="spawn"))


def _measure_named(task: tuple[str, int, tuple[str, ...]]) -> dict[str, Any]:
    name, seed, framelib = task
    from pathlib import Path

    from seal_cli.frames.reading import load_library
    from seal_cli.maps.formats.map_server import load_map
    from seal_cli.resources import map_path

    library = load_library([Path(p) for p in framelib] or None)
    return measure(scale(name, library, lambda: load_map(map_path("apartment")), seed), seed)
