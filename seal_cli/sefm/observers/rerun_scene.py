"""What every seal recording shares: the map as one image, the classes' colours, and the default layout.

Both recordings (``seal localize --rrd``, :mod:`seal_cli.sefm.observers.rerun`, and ``seal run --rrd``,
:mod:`seal_cli.sim.record`) open with the same scene:

- ``map/occupancy``: the occupancy grid as **one** PNG image in map_server's greys (free 254,
  occupied 0, unknown 205), placed in metres by a ``Transform3D`` (translation = the grid's
  origin, scale = its resolution), drawn beneath everything (draw order −10);
- ``map/rooms``: each room's outline, a labelled closed ``LineStrips2D``; ``map/places``;
- an ``AnnotationContext`` at the root giving each object class and each frame one id, label and
  colour (a legend in the viewer), so that particle clouds carry class ids, not colours;
- a default blueprint: the map view beside time series of each frame's room masses and of the
  effective sample sizes.

The file is written without rerun's footer (:func:`save`): the footer is a manifest of every chunk
for random access into large recordings (remote stores, lazy loading), and on a run of a few
dozen chunks it was half the file (64 kB of the README run's 131 kB). The viewer, ``rerun rrd
print`` and ``rr.chunk.RrdReader`` read the file from the start as a stream, as they read any
stream; ``rerun rrd verify`` reports the missing footer unless given ``--check-footers false``.

The map view is Rerun's 2-D view, whose y axis points down: the map appears mirrored top to
bottom relative to RViz (north is at the bottom); positions are the map frame's metres as they are.
"""

from __future__ import annotations

import contextlib
import io
import os
import sys
from collections.abc import Iterator, Sequence
from contextlib import contextmanager
from pathlib import Path
from typing import Any

import numpy as np

from seal_cli.maps.geometry import FREE, OCCUPIED, OccupancyGrid
from seal_cli.maps.model import Map

__all__ = ["DRAW", "Classes", "batching", "blueprint", "cause", "failure", "flush", "log_grid_image", "log_map", "png",
           "save", "send_series", "series_colour"]

DRAW = {"occupancy": -10.0, "density": -5.0, "rooms": 1.0, "places": 2.0, "objects": 3.0, "frames": 4.0,
        "modes": 6.0, "observations": 7.0, "robot": 8.0}
"""Draw orders: the map beneath, the beliefs over it, the robot on top."""

PALETTE = np.array([[31, 119, 180], [255, 127, 14], [44, 160, 44], [214, 39, 40], [148, 103, 189], [140, 86, 75],
                    [227, 119, 194], [127, 127, 127], [188, 189, 34], [23, 190, 207]], np.uint8)
"""Matplotlib's tab10."""
GREYS = {FREE: 254, OCCUPIED: 0}
UNKNOWN_GREY = 205


def batching() -> Any:
    """Chunks of up to 8 MB per entity, never cut by time: every chunk carries a couple of kB of Arrow
    schema, so a short run's recording is one chunk per entity instead of one per 200 ms."""
    import datetime

    import rerun as rr

    return rr.ChunkBatcherConfig(flush_tick=datetime.timedelta(hours=24), flush_num_bytes=8 << 20,
                                 flush_num_rows=1 << 31)


@contextmanager
def _quiet_stderr() -> Iterator[None]:
    """File descriptor 2 to /dev/null for the duration: rerun's Rust side warns there, not through Python."""
    sys.stderr.flush()
    try:
        saved, null = os.dup(2), os.open(os.devnull, os.O_WRONLY)
    except OSError:  # no descriptor 2 to quiet (a daemon's): nothing would be shown anyway
        yield
        return
    os.dup2(null, 2)
    try:
        yield
    finally:
        os.dup2(saved, 2)
        os.close(saved)
        os.close(null)


@contextmanager
def writing(path: str | Path, stream: Any = None) -> Iterator[None]:
    """Rerun's failures to write a recording (a full disk, a file system that refuses) as the ``OSError`` of
    ``path`` every other writer raises (:func:`failure`): both rerun's "Failed to encode LogMsg: Failed to write: No
    space left on device (os error 28)" when it logs and its "File-writer thread shut down prematurely" from the
    flush after its writer died were tracebacks of ``--rrd`` on a full disk. ``stream``, the recording written, is
    then let go quietly: its sink's failure was printed again, after seal's own message, when the process ended."""
    try:
        yield
    except RuntimeError as exc:
        error = failure(str(exc), path)
        if error is None:
            raise
        if stream is not None:
            with _quiet_stderr(), contextlib.suppress(Exception):
                stream.disconnect()
        raise error from None


WRITER_GONE = ("File-writer thread", "Failed to write", "(os error")
"""What rerun says when it could not write a recording: its writer thread died (a full disk), a write failed, an
error of the system with its number."""


def failure(text: str, path: str | Path) -> OSError | None:
    """The one reading of rerun's error ``text`` as the ``OSError`` of the recording ``path`` (None: not a failure to
    write). The system's number when rerun gives one (``(os error 28)``); else the cause found at ``path``
    (:func:`cause`: a full disk, ``ulimit -f``, a folder gone, one not writable), since "File-writer thread shut down
    prematurely" names none (hostile25: it was "rerun's writer stopped" on a full tmpfs); else the writer stopped,
    as rerun said above."""
    import errno
    import re

    if not any(said in text for said in WRITER_GONE):
        return None
    code = re.search(r"\(os error (\d+)\)", text)
    number = int(code.group(1)) if code is not None else cause(path)
    if number:
        return OSError(number, os.strerror(number), str(path))
    return OSError(errno.EIO, "rerun's writer stopped before the recording was whole (rerun said why above)",
                   str(path))


FLUSH_ROUND = 1.0
"""Seconds one wait for rerun's flush lasts (:func:`flush`)."""
FLUSH_STALL = 60.0
"""Seconds a flush may go on while the recording does not grow before it is given up."""


def flush(stream: Any, path: str | Path) -> None:
    """Flush the recording streamed to ``path``, in waits of :data:`FLUSH_ROUND` seconds. Rerun's own flush waits
    for ever by default, and when its file writer had died on a full disk it never returned: ``seal localize --rrd``
    onto a disk that filled up hung, SIGTERM and SIGINT held off while it waited inside rerun (hostile25, on a
    16 KiB tmpfs; ``run --rrd`` happened to fail at once). Between waits an interrupt is acted on, a full disk is
    said as one, and a recording that has not grown for :data:`FLUSH_STALL` seconds is given up as a writer that
    stopped. Rerun's own failures (its writer gone) are left to :func:`writing`."""
    import errno
    import time

    size, since = -1, time.monotonic()
    while True:
        try:
            stream.flush(timeout_sec=FLUSH_ROUND)
            return
        except RuntimeError as exc:
            if failure(str(exc), path) is not None:
                raise
        number = cause(path)
        if number:
            raise OSError(number, os.strerror(number), str(path))
        try:
            grown = os.path.getsize(path)
        except OSError:
            grown = size
        if grown != size:
            size, since = grown, time.monotonic()
        elif time.monotonic() - since > FLUSH_STALL:
            raise OSError(errno.EIO, f"rerun's writer made no progress for {FLUSH_STALL:g} s", str(path))


def cause(path: str | Path) -> int:
    """Why a recording could not be written to ``path``, read off the file system, as an ``errno`` (0: none
    found): ``ENOSPC`` when the file system has no space left for this process, ``EFBIG`` when ``path`` has grown to
    the largest file this process may write (``ulimit -f``), ``ENOENT`` when its folder is gone (removed while the
    command ran), ``EACCES`` when the folder no longer takes a file."""
    import errno
    import resource

    folder = os.path.dirname(os.path.abspath(path))
    if not os.path.isdir(folder):
        return errno.ENOENT
    try:
        if os.statvfs(folder).f_bavail == 0:
            return errno.ENOSPC
        limit = resource.getrlimit(resource.RLIMIT_FSIZE)[0]
        if limit != resource.RLIM_INFINITY and os.path.exists(path) and os.path.getsize(path) >= limit:
            return errno.EFBIG
    except OSError:
        return 0
    return 0 if os.access(folder, os.W_OK) else errno.EACCES


def save(stream: Any, path: str | Path) -> None:
    """Stream the recording to ``path``, without the footer (see the module docstring). Rerun warns on
    stderr, at this call, that a file without a footer loses random access; the choice is made here on
    purpose, so the warning is not shown."""
    with _quiet_stderr():
        stream.save(str(path), write_footer=False)


def send_series(stream: Any, entity: str, indexes: Sequence[Any], values: np.ndarray, names: Sequence[str],
                colours: Sequence[tuple[int, int, int]]) -> None:
    """A metric's whole run as **one** chunk: ``values`` (one row per time in ``indexes``, one column per
    series) as ``Scalars``, and the series' names and colours (``SeriesLines``) in the first row only
    (null after it, which keeps them, where an empty list would clear them)."""
    import pyarrow as pa
    import rerun as rr

    rows, k = values.shape
    chunk = rr.chunk.Chunk.from_columns(entity, indexes, [
        *rr.Scalars.columns(scalars=np.asarray(values, float).ravel()).partition([k] * rows),
        *rr.SeriesLines.columns(names=list(names), colors=list(colours)).partition([k] + [0] * (rows - 1))])
    batch = chunk.to_record_batch()
    later = pa.array([row > 0 for row in range(rows)])
    columns = [pa.ListArray.from_arrays(column.offsets, column.values, mask=later)
               if field.name.startswith("SeriesLines:") else column
               for field, column in zip(batch.schema, batch.columns, strict=True)]
    stream.send_chunks(rr.chunk.Chunk.from_record_batch(pa.RecordBatch.from_arrays(columns, schema=batch.schema)))


def series_colour(i: int) -> tuple[int, int, int]:
    r, g, b = PALETTE[i % len(PALETTE)]
    return int(r), int(g), int(b)


def png(image: np.ndarray, colour: tuple[int, int, int] | None = None) -> bytes:
    """An (H, W) uint8 array as PNG bytes, row 0 first: grey levels, or — with ``colour`` — that colour
    at the array's opacity (a 16-level palette with transparency: a density image of a few kB).

    Written with Pillow, which matplotlib already depends on."""
    from PIL import Image

    buffer = io.BytesIO()
    array = np.asarray(image, np.uint8)
    if colour is None:
        Image.fromarray(array, mode="L").save(buffer, format="PNG", optimize=True)
        return buffer.getvalue()
    levels = np.asarray(np.rint(array / 255 * 15), np.uint8)
    picture = Image.fromarray(levels, mode="P")
    picture.putpalette(list(colour) * 16)
    picture.save(buffer, format="PNG", optimize=True, transparency=bytes(int(round(k * 255 / 15)) for k in range(16)))
    return buffer.getvalue()


class Classes:
    """One annotation id and colour per object class and per frame, in the order given."""

    def __init__(self, objects: Sequence[str], frames: Sequence[str]) -> None:
        self.names = [*objects, *frames]
        self.ids = {name: i + 1 for i, name in enumerate(self.names)}

    def colour(self, name: str) -> tuple[int, int, int]:
        return series_colour(self.ids[name] - 1)

    def log(self, stream: Any) -> None:
        import rerun as rr

        stream.log("/", rr.AnnotationContext([rr.ClassDescription(info=rr.AnnotationInfo(
            id=self.ids[n], label=n, color=self.colour(n))) for n in self.names]), static=True)


def log_grid_image(stream: Any, entity: str, image: np.ndarray, resolution: float, origin: Sequence[float],
                   draw_order: float, static: bool = True, colour: tuple[int, int, int] | None = None) -> None:
    """An image whose pixel (col, row) is the cell at ``origin + (col, row) · resolution`` (row 0 the lowest y):
    grey levels, or ``colour`` at the image's values as opacity."""
    import rerun as rr

    yaw = float(origin[2]) if len(origin) > 2 else 0.0
    rotation = rr.RotationAxisAngle(axis=[0, 0, 1], radians=yaw) if yaw else None
    stream.log(entity, rr.Transform3D(translation=[float(origin[0]), float(origin[1]), 0.0], scale=float(resolution),
                                      rotation_axis_angle=rotation),
               rr.EncodedImage(contents=png(image, colour), media_type="image/png", draw_order=draw_order),
               static=static)


def occupancy_image(grid: OccupancyGrid) -> np.ndarray:
    cells = np.asarray(grid.cells)
    out = np.full(cells.shape, UNKNOWN_GREY, np.uint8)
    for value, grey in GREYS.items():
        out[cells == value] = grey
    return out


def log_map(stream: Any, m: Map, places: Sequence[tuple[str, tuple[float, float]]] | None = None) -> None:
    """The static map: the occupancy image, the labelled rooms, and the places (name, position)."""
    import rerun as rr

    grid = m.grid
    log_grid_image(stream, "map/occupancy", occupancy_image(grid), grid.resolution, grid.origin, DRAW["occupancy"])
    if m.rooms:
        stream.log("map/rooms", rr.LineStrips2D([[*r.polygon, r.polygon[0]] for r in m.rooms],
                                                labels=list(m.room_names), show_labels=True,
                                                colors=[[90, 90, 200]], radii=rr.Radius.ui_points(1.5),
                                                draw_order=DRAW["rooms"]), static=True)
    shown = list(places) if places is not None else [(p.name, p.at) for p in m.places]
    if shown:
        stream.log("map/places", rr.Points2D([at for _, at in shown], labels=[name for name, _ in shown],
                                             radii=0.1, colors=[[90, 90, 90]], draw_order=DRAW["places"]),
                   static=True)


def blueprint(m: Map, frame_ids: Sequence[str], panels: Sequence[tuple[str, str, str]] | None = None) -> Any:
    """The default layout: the map view (left) and, on the right, time series.

    By default two: every frame's room masses (``/metrics/rooms``: one series per frame and room)
    and the effective sample sizes (``/metrics/ess``); ``panels`` gives others as (kind, name,
    origin), kind ``series`` (a time series) or ``log`` (a text log)."""
    import rerun.blueprint as rrb

    view = rrb.Spatial2DView(name=f"map {m.name}", origin="/")  # framed on its content: the occupancy image
    if panels is None:
        panels = ([("series", "room mass per frame", "/metrics/rooms")] if frame_ids else []) + \
            [("series", "effective sample size", "/metrics/ess")]
    kinds = {"series": rrb.TimeSeriesView, "log": rrb.TextLogView}
    shown = [kinds[kind](name=name, origin=origin) for kind, name, origin in panels]
    return rrb.Blueprint(rrb.Horizontal(view, rrb.Vertical(*shown), column_shares=[3, 2]) if shown else view)
