"""A Rerun recording of a SeFM run: an observer that logs the map, the robot and every belief.

:class:`RerunRecorder` is passed to :class:`~seal_cli.sefm.filter.SeFM` like any observer. It opens an
explicit ``rr.RecordingStream``, saves it to the given file *before* logging anything (without
rerun's footer: :func:`~seal_cli.sefm.observers.rerun_scene.save`), sends the default blueprint
(:func:`~seal_cli.sefm.observers.rerun_scene.blueprint`: the map view beside the room masses and
effective sample sizes) and logs on the timeline ``step`` (0 is the prior, before any update) and,
when the run came from a bag, on the timeline ``time`` too (the detection messages' stamps):

=====================================  ======================================================
entity                                 what
=====================================  ======================================================
``map/occupancy``                      the occupancy grid, one image (static; see rerun_scene)
``map/rooms``, ``map/places``          labelled outlines and places (static)
``/`` (AnnotationContext)              one id, label and colour per object class and frame
``robot/pose``                         where the robot is (a point) and which way it faces (an arrow)
``robot/path``                         where it has been (LineStrips2D, a point every 0.25 m)
``objects/particles``                  every object's particles: its class id, radius by weight
``frames/particles``                   every frame's particles: its class id (one radius: they are
                                       resampled at every update, so all weigh 1/P)
``frames/<frame id>/density``          the frame's target density γ as an image in its colour
``frames/modes``                       every frame's modes: outlined boxes of ±1 standard deviation
                                       (at least 0.1 m) about each mean, its class id, labelled room
                                       and weight (outlines, so the cloud beneath stays visible)
``observations``                       the detections of the step: class ids, labelled
``metrics/rooms``                      every frame's probability mass per room (Scalars, one
                                       series ``<frame id>: <room>`` each)
``metrics/ess``                        effective sample size of every belief (one series each: the
                                       frames' last reweighting, the objects' weights)
=====================================  ======================================================

One entity holds every class (told apart by their class ids and the annotation context's legend)
rather than one entity per class: each entity costs a chunk and its Arrow schema, a kB or two,
more than the data of a cloud. The metrics are kept while the run goes and sent at its end as one
chunk per metric, all steps in columns (``send_columns``). A belief's particles, density and modes
are logged when it has changed since they were last logged — by more than ``CHANGE`` in total
variation over 0.5 m cells, between the particles' masses for an object and between the target
densities γ for a frame (its particles are redrawn at every update, so their masses carry sampling
noise even when the belief stands still) — and at the last step; a change of one class logs the
clouds of all the classes of its entity. Between two such logs the latest logged cloud *is* a
sample of the belief shown (Rerun shows the latest value at the time cursor), and the recording of
a run that has settled stays small. Log time and log ticks are off, so the same run gives the same
content. Read a file back with ``rr.chunk.RrdReader(path).stream().collect()``.
"""

from __future__ import annotations

from collections.abc import Sequence
from pathlib import Path
from typing import TYPE_CHECKING, Any

import numpy as np
from numpy.typing import NDArray

from seal_cli.frames.taxonomy import class_key
from seal_cli.sefm.observers.rerun_scene import (
    DRAW,
    Classes,
    batching,
    blueprint,
    flush,
    log_grid_image,
    log_map,
    save,
    send_series,
    series_colour,
    writing,
)

if TYPE_CHECKING:
    from seal_cli.sefm.filter import SeFM, Step

__all__ = ["CHANGE", "TRAIL_STEP", "RerunRecorder", "cell_masses", "log_clouds", "log_detections", "radii", "spread",
           "total_variation"]

ROBOT = (214, 39, 40)
DETECTION = (255, 127, 14)
CHANGE = 0.05
"""Total variation (over 0.5 m cells) by which a belief must change before its cloud is logged again."""
CELL = 0.5
TRAIL_STEP = 0.25
"""The path gains a point when the robot has moved this far (m) from the last one: a long bag's path
stays a few hundred points, logged a few hundred times, not one point and one log per update."""
DENSITY_CELL = 0.2
"""The density images' cell (m)."""


def radii(W: NDArray[np.float64], smallest: float = 0.03, largest: float = 0.12) -> NDArray[np.float32]:
    """A radius per particle growing with the square root of its weight (area ∝ weight), in 0.01 m steps; even
    weights all get the middle radius."""
    W = np.asarray(W, float)
    top = W.max() if len(W) else 0.0
    if top <= 0 or np.ptp(W) <= 1e-9 * top:  # even weights (a resampled set) say nothing: a middle size
        return np.full(len(W), round((smallest + largest) / 2, 2), np.float32)
    share = np.sqrt(W / top)
    return np.asarray(np.round((smallest + (largest - smallest) * share) * 100) / 100, np.float32)


def spread(cov: Sequence[Sequence[float]], smallest: float = 0.1) -> tuple[float, float]:
    """A mode's half sizes along x and y: its standard deviations, at least ``smallest`` (m)."""
    c = np.asarray(cov, float)
    return float(max(np.sqrt(max(c[0, 0], 0.0)), smallest)), float(max(np.sqrt(max(c[1, 1], 0.0)), smallest))


def cell_masses(X: NDArray[np.float64], W: NDArray[np.float64], bounds: Sequence[float]) -> dict[int, float]:
    """A cloud's (or a density's, sampled at points X) mass per 0.5 m cell, by flat cell index."""
    xmin, ymin, xmax, _ = bounds
    cols = int(np.ceil((xmax - xmin) / CELL)) + 1
    ij = np.floor((np.asarray(X) - (xmin, ymin)) / CELL).astype(np.int64)
    keys = ij[:, 1] * cols + ij[:, 0]
    unique, inverse = np.unique(keys, return_inverse=True)
    sums = np.bincount(inverse, weights=np.asarray(W, float), minlength=len(unique))
    total = sums.sum()
    return {int(k): float(s / total) if total > 0 else 0.0 for k, s in zip(unique, sums, strict=True)}


def total_variation(a: dict[int, float], b: dict[int, float]) -> float:
    """½ Σ |a − b| over the cells of two :func:`cell_masses`."""
    return 0.5 * sum(abs(a.get(k, 0.0) - b.get(k, 0.0)) for k in set(a) | set(b))


def log_clouds(stream: Any, entity: str, clouds: Sequence[NDArray[np.float64]], sizes: Sequence[NDArray[np.float32]],
               class_ids: Sequence[int], draw_order: float) -> None:
    """Several classes' particles as one ``Points2D``: positions, a class id per point, and radii (one
    per point, or a single one for all: given when every point's is the same)."""
    import rerun as rr

    every = np.concatenate(sizes) if sizes else np.zeros(0, np.float32)
    if len(every) and np.all(every == every[0]):
        sizes = [every[:1]]
    stream.log(entity, rr.Points2D(
        np.concatenate([np.asarray(X, float).reshape(-1, 2) for X in clouds]) if clouds else np.zeros((0, 2)),
        radii=np.concatenate(sizes) if sizes else [],
        class_ids=np.repeat(np.asarray(class_ids, np.uint16), [len(X) for X in clouds]),
        draw_order=draw_order))


def log_detections(stream: Any, seen: Sequence[tuple[str, Sequence[float]]], classes: Classes,
                   colour: tuple[int, int, int]) -> None:
    """What was seen at a step (class, position), as the one entity ``observations``: labelled with the
    class and carrying its id (0 for a class without one); nothing seen clears what was shown."""
    import rerun as rr

    names = [name for name, _ in seen]
    stream.log("observations", rr.Points2D(
        np.array([at for _, at in seen], float).reshape(-1, 2), radii=0.12, colors=[colour], labels=names,
        class_ids=[classes.ids.get(n, 0) for n in names], draw_order=DRAW["observations"]))


class RerunRecorder:
    """Observer that writes a ``.rrd`` recording of a run to ``path`` (see the module docstring).

    ``stamps``: the time (s) of each update in order, when the run has one (a bag's stamps); the
    updates after the last stamp (the extra steps at the last pose) keep the last time."""

    def __init__(self, path: str | Path, application_id: str = "seal_localize", stamps: Sequence[float] = ()) -> None:
        self.path = Path(path)
        self.application_id = application_id
        self.stamps = tuple(float(s) for s in stamps)
        self.stream: Any = None
        self.trail: list[tuple[float, float]] = []
        self.classes = Classes((), ())
        self._shown: dict[str, dict[int, float]] = {}
        self._seen = 0
        self._pending: set[str] = set()
        self._coarse: NDArray[np.float64] | None = None
        self._pose: tuple[float, float, float] | None = None
        self._index = 0
        self._metrics: dict[str, list[tuple[int, list[float]]]] = {}
        self._series_lines: dict[str, tuple[list[str], list[tuple[int, int, int]]]] = {}

    def start(self, sefm: SeFM) -> None:
        with writing(self.path, self.stream):
            self._start(sefm)

    def update(self, sefm: SeFM, step: Step) -> None:
        with writing(self.path, self.stream):
            self._update(step, sefm)

    def finish(self, sefm: SeFM) -> None:
        with writing(self.path, self.stream):
            self._finish(sefm)

    def _start(self, sefm: SeFM) -> None:
        import rerun as rr

        self.stream = rr.RecordingStream(self.application_id, recording_id=f"{sefm.map.name}-seal",
                                         batcher_config=batching(), send_properties=False)
        save(self.stream, self.path)
        self.stream.set_log_time_enabled(False)
        self.stream.set_log_tick_enabled(False)
        self.classes = Classes(sefm.object_classes, sefm.frame_ids)
        self.stream.send_blueprint(blueprint(sefm.map, sefm.frame_ids))
        self.classes.log(self.stream)
        log_map(self.stream, sefm.map)
        self._at(0)
        self._series(sefm)
        self.trail, self._shown, self._seen, self._metrics = [], {}, 0, {}
        self._beliefs(sefm, force=True)

    def _update(self, step: Step, sefm: SeFM) -> None:
        self._at(step.index)
        self._robot(step)
        self._observations(step)
        self._beliefs(sefm)

    def _finish(self, sefm: SeFM) -> None:
        if self.stream is not None:
            self._beliefs(sefm, force=True, only_pending=True, metrics=False)
            self._send_metrics()
            flush(self.stream, self.path)
            self.stream.disconnect()
            self.stream = None

    # -- timelines -----------------------------------------------------------------------------------
    def _time(self, index: int) -> tuple[str, float] | None:
        """The ``time`` timeline's kind and value (s) at an update's index, when the run has stamps."""
        if not self.stamps:
            return None
        t = self.stamps[min(max(index - 1, 0), len(self.stamps) - 1)]
        return ("timestamp" if t > 1e8 else "duration"), t  # after 1973: a wall-clock stamp; else from zero

    def _at(self, index: int) -> None:
        self._index = index
        self.stream.set_time("step", sequence=index)
        time = self._time(index)
        if time is not None:
            self.stream.set_time("time", **{time[0]: time[1]})

    # -- what is logged ------------------------------------------------------------------------------
    def _series(self, sefm: SeFM) -> None:
        """Names and colours of the metrics' series: ``<frame id>: <room>`` coloured by room, and one
        series per frame and object for the ESS, in its class's colour."""
        rooms = [*sefm.map.room_names, "_outside"]
        self._series_lines = {}
        if sefm.frame_ids:
            self._series_lines["metrics/rooms"] = ([f"{fid}: {room}" for fid in sefm.frame_ids for room in rooms],
                                                   [series_colour(k) for _ in sefm.frame_ids
                                                    for k in range(len(rooms))])
        names = [*sefm.frame_ids, *sefm.object_classes]
        if names:
            self._series_lines["metrics/ess"] = (names, [self.classes.colour(n) for n in names])

    def _send_metrics(self) -> None:
        """Every metric kept during the run, as one chunk each (all steps in columns)."""
        import rerun as rr

        for entity, found in self._metrics.items():
            steps = [index for index, _ in found]
            indexes = [rr.TimeColumn("step", sequence=steps)]
            times = [self._time(index) for index in steps]
            if times and times[0] is not None:
                kind = times[0][0]
                indexes.append(rr.TimeColumn("time", **{kind: [t[1] for t in times if t is not None]}))
            names, colours = self._series_lines[entity]
            send_series(self.stream, entity, indexes, np.array([values for _, values in found], float), names,
                        colours)

    def _scalars(self, entity: str, values: Sequence[float]) -> None:
        """A metric's values at this step, kept until the end (:meth:`_send_metrics`)."""
        self._metrics.setdefault(entity, []).append((self._index, [float(v) for v in values]))

    def _robot(self, step: Step) -> None:
        import rerun as rr

        s = self.stream
        x, y, yaw = step.pose
        if self.trail and step.pose == self._pose:
            return  # still there: the latest pose logged stands
        self._pose = step.pose
        s.log("robot/pose", rr.Points2D([[x, y]], radii=0.15, colors=[ROBOT], draw_order=DRAW["robot"]),
              rr.Arrows2D(origins=[[x, y]], vectors=[[0.5 * np.cos(yaw), 0.5 * np.sin(yaw)]], colors=[ROBOT],
                          draw_order=DRAW["robot"]))
        if not self.trail or np.hypot(x - self.trail[-1][0], y - self.trail[-1][1]) >= TRAIL_STEP:
            self.trail.append((x, y))
            if len(self.trail) > 1:
                s.log("robot/path", rr.LineStrips2D([self.trail], colors=[ROBOT], draw_order=DRAW["robot"]))

    def _observations(self, step: Step) -> None:
        """The step's detections, one entity for all classes (class ids, labelled); an empty log clears
        the last step's."""
        if not step.detections and not self._seen:
            return  # nothing seen now, nothing shown: nothing to clear
        self._seen = len(step.detections)
        log_detections(self.stream, [(class_key(cls), at) for cls, at in step.detections], self.classes, DETECTION)

    def _beliefs(self, sefm: SeFM, force: bool = False, only_pending: bool = False, metrics: bool = True) -> None:
        ess = [*(float(v) for v in sefm.frames.ess()), *(float(sefm.objects.ess()[sefm.objects.row(c)])
                                                        for c in sefm.object_classes)]
        if ess and metrics:
            self._scalars("metrics/ess", ess)
        changed = [self._changed(f"objects/{cls}", *self._object(sefm, cls), sefm, force, only_pending)
                   for cls in sefm.object_classes]
        if any(changed):
            self._objects(sefm)
        summaries = [sefm.frame_summary(i) for i in range(len(sefm.frame_ids))]
        if summaries and metrics:
            self._scalars("metrics/rooms", [v for summary in summaries for v in summary.rooms.values()])
        changed = [self._changed(f"frames/{fid}", *self._target(sefm, i), sefm, force, only_pending)
                   for i, fid in enumerate(sefm.frame_ids)]
        if any(changed):
            self._frames(sefm, summaries)
        for i, fid in enumerate(sefm.frame_ids):
            if changed[i]:
                self._density(sefm, i, fid)

    @staticmethod
    def _object(sefm: SeFM, cls: str) -> tuple[NDArray[np.float64], NDArray[np.float64]]:
        row = sefm.objects.row(cls)
        return sefm.objects.X[row], sefm.objects.W[row]

    def _objects(self, sefm: SeFM) -> None:
        """Every object's particles, one entity: the class id of each, a radius by its weight in its class."""
        clouds = [self._object(sefm, cls) for cls in sefm.object_classes]
        self._cloud("objects/particles", [X for X, _ in clouds], [radii(W) for _, W in clouds],
                    [self.classes.ids[cls] for cls in sefm.object_classes], DRAW["objects"])

    def _frames(self, sefm: SeFM, summaries: Sequence[Any]) -> None:
        """Every frame's particles (one middle radius: resampled, they weigh the same) and modes."""
        import rerun as rr

        ids = [self.classes.ids[fid] for fid in sefm.frame_ids]
        clouds = [sefm.frames.X[i] for i in range(len(ids))]
        self._cloud("frames/particles", clouds, [radii(np.ones(1))], ids, DRAW["frames"])  # one radius for all
        modes = [(class_id, mo) for class_id, summary in zip(ids, summaries, strict=True) for mo in summary.modes]
        self.stream.log("frames/modes", rr.Boxes2D(
            centers=np.array([mo.mean for _, mo in modes], float).reshape(-1, 2), class_ids=[c for c, _ in modes],
            half_sizes=np.array([spread(mo.cov) for _, mo in modes], float).reshape(-1, 2),
            labels=[f"{mo.room} {mo.weight:.2f}" for _, mo in modes], show_labels=True,
            radii=rr.Radius.ui_points(2.0), draw_order=DRAW["modes"]))

    def _changed(self, key: str, X: NDArray[np.float64], W: NDArray[np.float64], sefm: SeFM, force: bool,
                 only_pending: bool) -> bool:
        """Whether a belief is to be logged now; remembers what was."""
        if only_pending and key not in self._pending:
            return False
        masses = cell_masses(X, W, sefm.map.bounds)
        if force or key not in self._shown or total_variation(masses, self._shown[key]) > CHANGE:
            self._shown[key] = masses
            self._pending.discard(key)
            return True
        self._pending.add(key)  # changed a little since: logged at the end if nothing else logs it
        return False

    def _target(self, sefm: SeFM, i: int) -> tuple[NDArray[np.float64], NDArray[np.float64]]:
        """Frame i's target density γ at the free cells' centres, thinned to about one per 0.5 m cell."""
        if self._coarse is None:
            free = sefm.map.free_centres
            stride = max(1, int(round(CELL / sefm.map.grid.resolution)))
            cells = np.floor(free / (stride * sefm.map.grid.resolution)).astype(np.int64)
            self._coarse = free[np.unique(cells, axis=0, return_index=True)[1]]
        return self._coarse, sefm.frame_density(i, self._coarse)

    def _cloud(self, entity: str, clouds: Sequence[NDArray[np.float64]], sizes: Sequence[NDArray[np.float32]],
               class_ids: Sequence[int], draw_order: float) -> None:
        log_clouds(self.stream, entity, clouds, sizes, class_ids, draw_order)

    def _density(self, sefm: SeFM, i: int, fid: str) -> None:
        """Frame i's target density γ on a 0.2 m grid over the map's bounds, as an RGBA image in its colour."""
        xmin, ymin, xmax, ymax = sefm.map.bounds
        cols, rows = int(np.ceil((xmax - xmin) / DENSITY_CELL)), int(np.ceil((ymax - ymin) / DENSITY_CELL))
        xs = xmin + (np.arange(cols) + 0.5) * DENSITY_CELL
        ys = ymin + (np.arange(rows) + 0.5) * DENSITY_CELL
        points = np.stack(np.meshgrid(xs, ys), axis=-1).reshape(-1, 2)
        density = np.where(sefm.map.is_free(points), sefm.frame_density(i, points), 0.0).reshape(rows, cols)
        top = density.max()
        alpha = np.asarray(np.rint(200 * np.sqrt(density / top)), np.uint8) if top > 0 else np.zeros_like(density,
                                                                                                          np.uint8)
        log_grid_image(self.stream, f"frames/{fid}/density", alpha, DENSITY_CELL, (xmin, ymin, 0.0),
                       DRAW["density"], static=False, colour=self.classes.colour(fid))
