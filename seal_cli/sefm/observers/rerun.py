"""A Rerun recording of a SeFM run: an observer that logs the map, the robot and every belief.

:class:`RerunRecorder` is passed to :class:`~seal_cli.sefm.filter.SeFM` like any observer. It opens an
explicit ``rr.RecordingStream``, saves it to the given file *before* logging anything, sends the
default blueprint (:func:`~seal_cli.sefm.observers.rerun_scene.blueprint`: the map view beside the
room masses and effective sample sizes) and logs on the timeline ``step`` (0 is the prior, before
any update) and, when the run came from a bag, on the timeline ``time`` too (the detection
messages' stamps):

=====================================  ======================================================
entity                                 what
=====================================  ======================================================
``map/occupancy``                      the occupancy grid, one image (static; see rerun_scene)
``map/rooms``, ``map/places``          labelled outlines and places (static)
``/`` (AnnotationContext)              one id, label and colour per object class and frame
``robot/pose``                         where the robot is (a point) and which way it faces (an arrow)
``robot/path``                         where it has been (LineStrips2D, a point every 0.25 m)
``objects/<class>/particles``          each object's particles: its class id, radius by weight
``frames/<frame id>/particles``        each frame's particles: its class id, radius by weight γ
``frames/<frame id>/density``          the frame's target density γ as an image in its colour
``frames/<frame id>/modes``            the modes, coloured by weight, labelled room and weight
``observations/<class>``               the detections of the step
``metrics/rooms/<frame id>``           the frame's probability mass per room (Scalars, one series a room)
``metrics/ess``                        effective sample size of every belief (one series each: the
                                       frames' last reweighting, the objects' weights)
=====================================  ======================================================

The metrics are logged at every step. A belief's particles, density and modes are logged when
the belief has changed since they were last logged — by more than ``CHANGE`` in total variation
over 0.5 m cells, between the particles' masses for an object and between the target densities
γ for a frame (its particles are redrawn at every update, so their masses carry sampling noise
even when the belief stands still) — and at the last step: between two such logs the latest
logged cloud *is* a sample of the belief shown (Rerun shows the latest value at the time
cursor), and the recording of a run that has settled stays small. Positions are re-sent only
when they moved (an object cloud that is only reweighted sends its radii). A frame's particles
are resampled at every update, so they all weigh 1/P; they are sized by the weight each would
carry if it had not been (its normalised γ), which is what a weighted particle set of the same
belief would show. Log time and log ticks are off, so the same run gives the same content. Read
a file back with ``rr.chunk.RrdReader(path).stream().collect()``.
"""

from __future__ import annotations

from collections.abc import Sequence
from pathlib import Path
from typing import TYPE_CHECKING, Any

import numpy as np
from numpy.typing import NDArray

from seal_cli.frames.taxonomy import class_key
from seal_cli.sefm.observers.metrics import weight_colours
from seal_cli.sefm.observers.rerun_scene import DRAW, Classes, batching, blueprint, log_grid_image, log_map

if TYPE_CHECKING:
    from seal_cli.sefm.filter import SeFM, Step

__all__ = ["CHANGE", "RerunRecorder", "cell_masses", "radii", "total_variation"]

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
        self._seen: dict[str, int] = {}
        self._pending: set[str] = set()
        self._coarse: NDArray[np.float64] | None = None
        self._series_lines: dict[str, Any] = {}
        self._pose: tuple[float, float, float] | None = None

    def start(self, sefm: SeFM) -> None:
        import rerun as rr

        self.stream = rr.RecordingStream(self.application_id, recording_id=f"{sefm.map.name}-seal",
                                         batcher_config=batching(), send_properties=False)
        self.stream.save(str(self.path))
        self.stream.set_log_time_enabled(False)
        self.stream.set_log_tick_enabled(False)
        self.classes = Classes(sefm.object_classes, sefm.frame_ids)
        self.stream.send_blueprint(blueprint(sefm.map, sefm.frame_ids))
        self.classes.log(self.stream)
        log_map(self.stream, sefm.map)
        self._at(0)
        self._series(sefm)
        self.trail, self._shown, self._seen = [], {}, {}
        self._beliefs(sefm, force=True)

    def update(self, sefm: SeFM, step: Step) -> None:
        self._at(step.index)
        self._robot(step)
        self._observations(sefm, step)
        self._beliefs(sefm)

    def finish(self, sefm: SeFM) -> None:
        if self.stream is not None:
            self._beliefs(sefm, force=True, only_pending=True, metrics=False)
            self.stream.flush()
            self.stream.disconnect()
            self.stream = None

    # -- timelines -----------------------------------------------------------------------------------
    def _at(self, index: int) -> None:
        self.stream.set_time("step", sequence=index)
        if self.stamps:
            t = self.stamps[min(max(index - 1, 0), len(self.stamps) - 1)]
            if t > 1e8:  # after 1973: a wall-clock stamp
                self.stream.set_time("time", timestamp=t)
            else:  # simulated time from zero
                self.stream.set_time("time", duration=t)

    # -- what is logged ------------------------------------------------------------------------------
    def _series(self, sefm: SeFM) -> None:
        """Names and colours of the metrics' series, logged with their first values (one chunk per entity)."""
        import rerun as rr

        from seal_cli.sefm.observers.rerun_scene import series_colour

        rooms = [*sefm.map.room_names, "_outside"]
        colours = [series_colour(k) for k in range(len(rooms))]
        self._series_lines = {f"metrics/rooms/{fid}": rr.SeriesLines(names=rooms, colors=colours)
                              for fid in sefm.frame_ids}
        names = [*sefm.frame_ids, *sefm.object_classes]
        self._series_lines["metrics/ess"] = rr.SeriesLines(names=names, colors=[self.classes.colour(n) for n in names])

    def _scalars(self, entity: str, values: Sequence[float]) -> None:
        """Values of a metric's series; its names and colours go with the first (one chunk per entity)."""
        import rerun as rr

        lines = self._series_lines.pop(entity, None)
        extra = [lines] if lines is not None else []
        self.stream.log(entity, rr.Scalars([float(v) for v in values]), *extra)

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

    def _observations(self, sefm: SeFM, step: Step) -> None:
        import rerun as rr

        seen: dict[str, list[tuple[float, float]]] = {}
        for cls, at in step.detections:
            seen.setdefault(class_key(cls), []).append(at)
        for cls in sorted(set(seen) | set(sefm.object_classes)):
            points = seen.get(cls, [])
            if not points and not self._seen.get(cls):
                continue  # nothing seen now, nothing shown: nothing to clear
            self._seen[cls] = len(points)
            self.stream.log(f"observations/{cls}", rr.Points2D(np.array(points).reshape(-1, 2), radii=0.12,
                                                               colors=[DETECTION], labels=[cls] * len(points),
                                                               draw_order=DRAW["observations"]))

    def _beliefs(self, sefm: SeFM, force: bool = False, only_pending: bool = False, metrics: bool = True) -> None:
        import rerun as rr

        s = self.stream
        ess = [*(float(v) for v in sefm.frames.ess()), *(float(sefm.objects.ess()[sefm.objects.row(c)])
                                                        for c in sefm.object_classes)]
        if ess and metrics:
            self._scalars("metrics/ess", ess)
        for cls in sefm.object_classes:
            row = sefm.objects.row(cls)
            X, W = sefm.objects.X[row], sefm.objects.W[row]
            if self._changed(f"objects/{cls}", X, W, sefm, force, only_pending):
                self._cloud(f"objects/{cls}/particles", X, W, self.classes.ids[cls], DRAW["objects"])
        for i, fid in enumerate(sefm.frame_ids):
            summary = sefm.frame_summary(i)
            if metrics:
                self._scalars(f"metrics/rooms/{fid}", list(summary.rooms.values()))
            if not self._changed(f"frames/{fid}", *self._target(sefm, i), sefm, force, only_pending):
                continue
            self._cloud(f"frames/{fid}/particles", sefm.frames.X[i], sefm.frames.shown_weights(i),
                        self.classes.ids[fid], DRAW["frames"])
            self._density(sefm, i, fid)
            modes = summary.modes
            if modes:
                weights = np.array([mo.weight for mo in modes])
                s.log(f"frames/{fid}/modes", rr.Points2D(
                    [mo.mean for mo in modes], colors=weight_colours(weights), draw_order=DRAW["modes"],
                    radii=[float(np.sqrt(max(np.trace(np.array(mo.cov)) / 2, 0.01))) for mo in modes],
                    labels=[f"{mo.room} {mo.weight:.2f}" for mo in modes], show_labels=True))
            else:
                s.log(f"frames/{fid}/modes", rr.Clear(recursive=False))

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

    def _cloud(self, entity: str, X: NDArray[np.float64], W: NDArray[np.float64], class_id: int,
               draw_order: float) -> None:
        import rerun as rr

        self.stream.log(entity, rr.Points2D(X, radii=radii(W), class_ids=[class_id], draw_order=draw_order))

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
