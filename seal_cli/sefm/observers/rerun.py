"""A Rerun recording of a SeFM run: an observer that logs the map, the robot and every belief.

:class:`RerunRecorder` is passed to :class:`~seal_cli.sefm.filter.SeFM` like any observer. It opens an
explicit ``rr.RecordingStream``, saves it to the given file *before* logging anything, and logs on
the timeline ``step`` (0 is the prior, before any update):

=================================  ==========================================================
entity                             what
=================================  ==========================================================
``map/occupancy``                  free cells (light) and occupied cells (dark), as Points2D
``map/rooms``                      each room's outline, a labelled LineStrips2D
``map/places``                     places, labelled Points2D
``robot/pose``                     where the robot is
``robot/path``                     where it has been (LineStrips2D)
``objects/<class>/particles``      each object's particles, coloured by weight
``frames/<frame id>/particles``    each frame's particles, coloured by weight (γ, see below)
``frames/<frame id>/modes``        each frame's modes, sized by spread, labelled room and weight
``observations/<class>``           the detections of the step
``metrics/frames/<id>/ess``        effective sample size (Scalars); also ``.../top_room`` mass
``metrics/objects/<class>/ess``    effective sample size of each object belief
=================================  ==========================================================

A frame's particles are resampled at every update, so they all weigh 1/P; they are coloured by
the weight each would carry if it had not been (its normalised target γ), which is what a
weighted particle set of the same belief would show. Log time and log ticks are off, so the same
run gives the same content. Read a file back with ``rr.chunk.RrdReader(path).stream().collect()``.
"""

from __future__ import annotations

from collections.abc import Sequence
from pathlib import Path
from typing import TYPE_CHECKING, Any

import numpy as np

from seal_cli.frames.taxonomy import class_key
from seal_cli.sefm.observers.metrics import weight_colours

if TYPE_CHECKING:
    from seal_cli.sefm.filter import SeFM, Step

__all__ = ["RerunRecorder"]

ROBOT = (214, 39, 40)
DETECTION = (255, 127, 14)


class RerunRecorder:
    """Observer that writes a ``.rrd`` recording of a run to ``path`` (see the module docstring)."""

    def __init__(self, path: str | Path, application_id: str = "seal_localize", stamps: Sequence[float] = ()) -> None:
        self.path = Path(path)
        self.stamps = tuple(stamps)
        self.application_id = application_id
        self.stream: Any = None
        self.trail: list[tuple[float, float]] = []

    def start(self, sefm: SeFM) -> None:
        import rerun as rr

        self.stream = rr.RecordingStream(self.application_id, recording_id=f"{sefm.map.name}-seal")
        self.stream.save(str(self.path))
        self.stream.set_log_time_enabled(False)
        self.stream.set_log_tick_enabled(False)
        self._map(sefm)
        self.stream.set_time("step", sequence=0)
        self.trail = []
        self._beliefs(sefm)

    def update(self, sefm: SeFM, step: Step) -> None:
        import rerun as rr

        s = self.stream
        s.set_time("step", sequence=step.index)
        x, y, yaw = step.pose
        self.trail.append((x, y))
        s.log("robot/pose", rr.Points2D([[x, y]], radii=0.15, colors=[ROBOT], labels=["robot"]))
        s.log("robot/heading", rr.Arrows2D(origins=[[x, y]], vectors=[[0.5 * np.cos(yaw), 0.5 * np.sin(yaw)]],
                                           colors=[ROBOT]))
        if len(self.trail) > 1:
            s.log("robot/path", rr.LineStrips2D([self.trail], colors=[ROBOT]))
        seen: dict[str, list[tuple[float, float]]] = {}
        for cls, at in step.detections:
            seen.setdefault(class_key(cls), []).append(at)
        for cls in sorted(set(seen) | set(sefm.object_classes)):
            points = seen.get(cls, [])
            s.log(f"observations/{cls}", rr.Points2D(np.array(points).reshape(-1, 2), radii=0.12,
                                                     colors=[DETECTION], labels=[cls] * len(points)))
        self._beliefs(sefm)

    def finish(self, sefm: SeFM) -> None:
        if self.stream is not None:
            self.stream.flush()
            self.stream.disconnect()
            self.stream = None

    # -- what is logged -----------------------------------------------------------------------------
    def _map(self, sefm: SeFM) -> None:
        import rerun as rr

        m, s = sefm.map, self.stream
        grid = m.grid
        rows, cols = np.nonzero(grid.occupied_mask)
        walls = grid.cell_centres(rows, cols)
        free = m.free_centres
        points = np.concatenate([free, walls])
        colours = np.concatenate([np.tile([[235, 235, 235]], (len(free), 1)), np.tile([[60, 60, 60]], (len(walls), 1))])
        s.log("map/occupancy", rr.Points2D(points, radii=grid.resolution / 2, colors=colours.astype(np.uint8)),
              static=True)
        if m.rooms:
            s.log("map/rooms", rr.LineStrips2D([[*r.polygon, r.polygon[0]] for r in m.rooms],
                                               labels=list(m.room_names), show_labels=True), static=True)
        if m.places:
            s.log("map/places", rr.Points2D([p.at for p in m.places], labels=[p.name for p in m.places],
                                            radii=0.1, colors=[[31, 119, 180]] * len(m.places)), static=True)

    def _beliefs(self, sefm: SeFM) -> None:
        import rerun as rr

        s = self.stream
        for cls in sefm.object_classes:
            row = sefm.objects.row(cls)
            W = sefm.objects.W[row]
            s.log(f"objects/{cls}/particles", rr.Points2D(sefm.objects.X[row], radii=0.04, colors=weight_colours(W)))
            s.log(f"metrics/objects/{cls}/ess", rr.Scalars(float(sefm.objects.ess()[row])))
        for i, fid in enumerate(sefm.frame_ids):
            s.log(f"frames/{fid}/particles", rr.Points2D(sefm.frames.X[i], radii=0.05,
                                                         colors=weight_colours(sefm.frames.shown_weights(i))))
            summary = sefm.frame_summary(i)
            modes = summary.modes
            if modes:
                weights = np.array([mo.weight for mo in modes])
                s.log(f"frames/{fid}/modes", rr.Points2D(
                    [mo.mean for mo in modes], colors=weight_colours(weights),
                    radii=[float(np.sqrt(max(np.trace(np.array(mo.cov)) / 2, 0.01))) for mo in modes],
                    labels=[f"{mo.room} {mo.weight:.2f}" for mo in modes]))
            else:
                s.log(f"frames/{fid}/modes", rr.Clear(recursive=False))
            s.log(f"metrics/frames/{fid}/ess", rr.Scalars(float(sefm.frames.ess()[i])))
            s.log(f"metrics/frames/{fid}/top_room", rr.Scalars(float(max(summary.rooms.values()))))
