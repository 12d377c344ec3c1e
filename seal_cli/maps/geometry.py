"""Plane geometry for maps: polygons, occupancy grids and line of sight, vectorised with numpy.

Points are float arrays of shape ``(N, 2)`` in metres (a single ``(2,)`` point is accepted
wherever points are). Nothing here loops in Python over points; loops run over polygon edges,
rooms, or fixed-size chunks of points that bound memory.

Occupancy grids follow ROS ``nav_msgs/OccupancyGrid``: ``cells[row, col]`` with row 0 at the
*lowest* y (the map image flipped upside down), cell ``(0, 0)``'s lower-left corner at
``origin``, and values ``FREE = 0``, ``OCCUPIED = 100``, ``UNKNOWN = -1``. A cell covers
``[origin + col·res, origin + (col+1)·res)`` in x (and likewise in y), so a point on a cell
edge belongs to the cell above/right of it.

Line of sight is exact on the grid: a segment is followed through every cell its interior
passes (:func:`segment_cells`), and it is blocked by an occupied cell other than the cell it
starts in and the cell it ends in (a robot sees the surface of the obstacle it looks at).
Unknown cells and space outside the grid do not block.
"""

from __future__ import annotations

import math
from collections.abc import Iterator, Sequence
from dataclasses import dataclass
from functools import cached_property

import numpy as np
from numpy.typing import ArrayLike, NDArray

__all__ = ["FREE", "MAX_GRID_CELLS", "MAX_IMAGE_CELLS", "OCCUPIED", "OUTSIDE", "UNKNOWN", "OccupancyGrid", "as_points",
           "box_polygon", "cast_rays", "clipped_area", "coarsened", "fit_cells", "line_of_sight", "lines_of_sight",
           "overlap_area",
           "point_in_polygon", "polygon_area", "segment_cells", "segments_intersect", "self_intersections",
           "shrink_factor"]

FREE, OCCUPIED, UNKNOWN = 0, 100, -1
OUTSIDE = "_outside"
"""The name reported for points in no room (no polygon of a map's rooms)."""
MAX_IMAGE_CELLS = 4096 * 4096
"""The most pixels of a map image decoded whole (a PNG, a text PGM): a larger one is refused from its header
(a binary PGM is read a band of rows at a time instead, see :data:`MAX_GRID_CELLS`)."""
MAX_GRID_CELLS = 1024 * 1024
"""The most cells of the occupancy grid a map holds (from an image, a bag's grid, or its bounds alone): a larger
image or bag grid is cropped to what it knows, then coarsened to fit (with a warning); bounds alone get coarser
cells. A run holds about 550 bytes a free cell (the navigation graph and its distances, the coverage lattice, the
beliefs): a fully known 8,200 × 8,200 image, 2,734 × 2,734 cells under the bound before (4096 × 4096), took 64 s
and 3.9 GB to `seal run`; 4 million implicit cells 30 s and 2.3 GB. Under this bound a run stays under 1 GB."""
_CHUNK = 1 << 21
"""Largest number of (point × edge) or (segment × crossing) entries handled in one numpy step."""

Points = NDArray[np.float64]


def as_points(points: ArrayLike) -> Points:
    """``points`` as a float array of shape (N, 2); one point ``(x, y)`` becomes shape (1, 2)."""
    array = np.asarray(points, dtype=float)
    if array.ndim == 1 and array.shape[0] == 2:
        return array.reshape(1, 2)
    if array.ndim == 1 and array.size == 0:
        return array.reshape(0, 2)
    if array.ndim != 2 or array.shape[1] != 2:
        raise ValueError(f"points must have shape (N, 2), not {array.shape}")
    return array


def _chunks(n: int, width: int) -> Iterator[slice]:
    step = max(1, _CHUNK // max(width, 1))
    for start in range(0, n, step):
        yield slice(start, min(n, start + step))


# -- polygons ---------------------------------------------------------------------------------
def box_polygon(xmin: float, ymin: float, xmax: float, ymax: float) -> Points:
    """The axis-aligned rectangle as a counter-clockwise polygon."""
    return np.array([[xmin, ymin], [xmax, ymin], [xmax, ymax], [xmin, ymax]], dtype=float)


def polygon_area(vertices: ArrayLike) -> float:
    """Signed area (shoelace): positive for counter-clockwise vertices."""
    v = as_points(vertices)
    x, y = v[:, 0], v[:, 1]
    return float(0.5 * (np.dot(x, np.roll(y, -1)) - np.dot(y, np.roll(x, -1))))


def clipped_area(vertices: ArrayLike, box: Sequence[float]) -> float:
    """The area of a simple polygon's part inside the box ``(xmin, ymin, xmax, ymax)``: the polygon clipped by each
    of the box's four sides in turn (Sutherland–Hodgman, exact for a convex clip region), linear in its vertices."""
    points = [tuple(p) for p in as_points(vertices).tolist()]
    for axis, limit, keep_below in ((0, box[0], False), (0, box[2], True), (1, box[1], False), (1, box[3], True)):
        if not points:
            return 0.0

        def inside(p: tuple[float, ...], axis: int = axis, limit: float = limit, below: bool = keep_below) -> bool:
            return p[axis] <= limit if below else p[axis] >= limit

        kept: list[tuple[float, ...]] = []
        for k, current in enumerate(points):
            previous = points[k - 1]
            if inside(current) != inside(previous):     # the edge crosses the side: where it does
                t = (limit - previous[axis]) / (current[axis] - previous[axis])
                kept.append(tuple(a + t * (b - a) for a, b in zip(previous, current, strict=True)))
            if inside(current):
                kept.append(current)
        points = kept
    return abs(polygon_area(points)) if len(points) >= 3 else 0.0


def point_in_polygon(points: ArrayLike, vertices: ArrayLike) -> NDArray[np.bool_]:
    """Whether each point is inside the polygon (crossing number, even-odd rule).

    Half-open on the boundary: of two polygons sharing an edge, a point on that edge is in
    exactly one of them, so adjacent rooms partition the plane without double counting.
    """
    p = as_points(points)
    v = as_points(vertices)
    out = np.zeros(len(p), dtype=bool)
    if len(v) < 3 or len(p) == 0:
        return out
    xi, yi = v[:, 0], v[:, 1]
    xj, yj = np.roll(xi, 1), np.roll(yi, 1)
    spans = (yi > yj) | (yi < yj)
    xi, yi, xj, yj = xi[spans], yi[spans], xj[spans], yj[spans]
    slope = (xj - xi) / (yj - yi)
    for part in _chunks(len(p), len(xi)):
        px, py = p[part, 0:1], p[part, 1:2]
        straddles = (yi > py) != (yj > py)
        crossing_x = xi + (py - yi) * slope
        out[part] = np.count_nonzero(straddles & (px < crossing_x), axis=1) % 2 == 1
    return out


def shrink_factor(height: int, width: int, limit: int) -> int:
    """The smallest whole factor by which a ``height`` × ``width`` grid, coarsened, has at most ``limit`` cells."""
    factor = max(1, math.ceil(math.sqrt(height * width / limit)))
    while math.ceil(height / factor) * math.ceil(width / factor) > limit:
        factor += 1
    return factor


def coarsened(cells: NDArray[np.int8], factor: int) -> NDArray[np.int8]:
    """Cells merged ``factor`` × ``factor`` into one: OCCUPIED if any was (a wall stays closed), else FREE if
    any was, else UNKNOWN. Rows and columns past a whole block count as unknown (row 0 stays row 0)."""
    if factor == 1:
        return cells
    h, w = cells.shape
    rows, cols = -(-h // factor), -(-w // factor)
    padded = np.full((rows * factor, cols * factor), UNKNOWN, dtype=np.int8)
    padded[:h, :w] = cells
    blocks = padded.reshape(rows, factor, cols, factor)
    out = np.where((blocks == FREE).any(axis=(1, 3)), FREE, UNKNOWN).astype(np.int8)
    out[(blocks == OCCUPIED).any(axis=(1, 3))] = OCCUPIED
    return out


def fit_cells(cells: NDArray[np.int8], limit: int) -> tuple[NDArray[np.int8], tuple[int, int], int]:
    """Cells (row 0 at the lowest y) of at most ``limit``: cropped to the rows and columns holding a known cell,
    then :func:`coarsened` if still too many; with the (column, row) of the kept corner and the factor."""
    if cells.size <= limit:
        return cells, (0, 0), 1
    known = cells != UNKNOWN
    rows, cols = np.flatnonzero(known.any(axis=1)), np.flatnonzero(known.any(axis=0))
    if len(rows):
        cells = cells[rows[0]:rows[-1] + 1, cols[0]:cols[-1] + 1]
    corner = (int(cols[0]), int(rows[0])) if len(rows) else (0, 0)
    factor = shrink_factor(cells.shape[0], cells.shape[1], limit)
    return np.ascontiguousarray(coarsened(cells, factor)), corner, factor


def _orientation(a: Points, b: Points, c: Points) -> NDArray[np.float64]:
    """Twice the signed area of triangles (a, b, c), broadcasting over leading axes."""
    return (b[..., 0] - a[..., 0]) * (c[..., 1] - a[..., 1]) - (b[..., 1] - a[..., 1]) * (c[..., 0] - a[..., 0])


def _on_segment(a: Points, b: Points, p: Points, eps: float) -> NDArray[np.bool_]:
    """For collinear p: whether p lies within the bounding box of segment a-b."""
    lo, hi = np.minimum(a, b) - eps, np.maximum(a, b) + eps
    return np.all((p >= lo) & (p <= hi), axis=-1)


def segments_intersect(p1: ArrayLike, p2: ArrayLike, q1: ArrayLike, q2: ArrayLike,
                       eps: float = 1e-12) -> NDArray[np.bool_]:
    """Whether closed segments p1-p2 and q1-q2 meet (touching and collinear overlap count).

    Arguments are arrays of shape (..., 2) that broadcast against each other.
    """
    p1, p2, q1, q2 = (np.asarray(a, dtype=float) for a in (p1, p2, q1, q2))
    d1, d2 = _orientation(q1, q2, p1), _orientation(q1, q2, p2)
    d3, d4 = _orientation(p1, p2, q1), _orientation(p1, p2, q2)
    scale = eps * (1.0 + np.abs(d1) + np.abs(d2) + np.abs(d3) + np.abs(d4))
    s1, s2, s3, s4 = (np.where(np.abs(d) <= scale, 0, np.sign(d)) for d in (d1, d2, d3, d4))
    proper = (s1 * s2 < 0) & (s3 * s4 < 0)
    touch = ((s1 == 0) & _on_segment(q1, q2, p1, eps)) | ((s2 == 0) & _on_segment(q1, q2, p2, eps)) \
        | ((s3 == 0) & _on_segment(p1, p2, q1, eps)) | ((s4 == 0) & _on_segment(p1, p2, q2, eps))
    return np.asarray(proper | touch)


def self_intersections(vertices: ArrayLike) -> list[tuple[int, int]]:
    """The pairs ``(i, j)`` of edges (edge i runs from vertex i to i+1) that meet although they are
    not neighbours; neighbours that fold back onto each other count too. Empty for a simple polygon.

    Only edges whose x-extents overlap are tested (sorted by their left end, each edge meets the ones
    starting before its right end), and those a block at a time: a room's outline of thousands of points
    is checked in time and memory near its size, not its square."""
    v = as_points(vertices)
    n = len(v)
    if n < 3:
        return []
    a, b = v, np.roll(v, -1, axis=0)
    slack = 1e-9 * (1.0 + np.abs(v).max())
    left, right = np.minimum(a[:, 0], b[:, 0]) - slack, np.maximum(a[:, 0], b[:, 0]) + slack
    low, high = np.minimum(a[:, 1], b[:, 1]) - slack, np.maximum(a[:, 1], b[:, 1]) + slack
    order = np.argsort(left, kind="stable")
    ends = np.searchsorted(left[order], right[order], side="right")  # sorted edges p+1 .. ends[p]-1 overlap p in x
    counts = np.maximum(ends - np.arange(n) - 1, 0)
    out: list[tuple[int, int]] = []
    first = 0
    while first < n:
        last = first + 1  # a block of sorted edges whose candidate pairs number about PAIRS_AT_ONCE
        total = counts[first]
        while last < n and total + counts[last] <= PAIRS_AT_ONCE:
            total += counts[last]
            last += 1
        block = np.arange(first, last)
        p = np.repeat(block, counts[block])
        q = p + 1 + (np.arange(len(p)) - np.repeat(np.cumsum(counts[block]) - counts[block], counts[block]))
        x, y = order[p], order[q]
        i, j = np.minimum(x, y), np.maximum(x, y)
        near = (low[i] <= high[j]) & (low[j] <= high[i])
        i, j = i[near], j[near]
        hits = segments_intersect(a[i], b[i], a[j], b[j])
        neighbours = (j == i + 1) | ((i == 0) & (j == n - 1))
        # neighbours always share a vertex; they are a problem only when they overlap along a stretch
        along = neighbours & _folds_back(a[i], b[i], a[j], b[j])
        found = (hits & ~neighbours) | along
        out.extend((int(s), int(t)) for s, t in zip(i[found], j[found], strict=True))
        first = last
    return sorted(out)


PAIRS_AT_ONCE = 1_000_000
"""Candidate edge pairs :func:`self_intersections` tests at once (some 200 MB of temporaries)."""



def _folds_back(a1: Points, b1: Points, a2: Points, b2: Points) -> NDArray[np.bool_]:
    """For neighbouring edges (they share a vertex): whether they run back over each other."""
    d1, d2 = b1 - a1, b2 - a2
    cross = d1[:, 0] * d2[:, 1] - d1[:, 1] * d2[:, 0]
    scale = 1e-12 * (np.hypot(d1[:, 0], d1[:, 1]) * np.hypot(d2[:, 0], d2[:, 1]))
    return np.asarray((np.abs(cross) <= scale) & (np.einsum("ij,ij->i", d1, d2) < 0))


def overlap_area(a: ArrayLike, b: ArrayLike, step: float = 0.02) -> float:
    """The area shared by two polygons, measured on a lattice of ``step`` metres.

    Exact up to the lattice: each lattice cell counts when its centre is inside both polygons
    (half-open boundaries, so two polygons that only share edges overlap by 0).
    """
    va, vb = as_points(a), as_points(b)
    lo = np.maximum(va.min(axis=0), vb.min(axis=0))
    hi = np.minimum(va.max(axis=0), vb.max(axis=0))
    if np.any(hi <= lo):
        return 0.0
    nx, ny = (np.ceil((hi - lo) / step).astype(int) + 1).tolist()
    # an irrational offset keeps lattice points off the axis-aligned edges maps are drawn with
    xs = lo[0] + (np.arange(nx) + 0.5 - 0.0123456789) * step
    ys = lo[1] + (np.arange(ny) + 0.5 - 0.0123456789) * step
    total = 0
    for rows in _chunks(ny, nx * max(len(va), len(vb))):
        gx, gy = np.meshgrid(xs, ys[rows])
        pts = np.column_stack([gx.ravel(), gy.ravel()])
        total += int(np.count_nonzero(point_in_polygon(pts, va) & point_in_polygon(pts, vb)))
    return total * step * step


# -- occupancy grids ----------------------------------------------------------------------------
@dataclass(frozen=True, eq=False)
class OccupancyGrid:
    """A 2-D occupancy grid: ``cells[row, col]`` in {FREE, OCCUPIED, UNKNOWN}, row 0 at the lowest y.

    ``origin`` is ``(x, y, yaw)``: the world pose of cell (0, 0)'s lower-left corner, as in ROS
    (yaw in radians, counter-clockwise; almost always 0).
    """

    cells: NDArray[np.int8]
    resolution: float
    origin: tuple[float, float, float] = (0.0, 0.0, 0.0)

    def __post_init__(self) -> None:
        cells = np.asarray(self.cells)
        if cells.ndim != 2 or cells.size == 0:
            raise ValueError(f"an occupancy grid needs a non-empty 2-D array of cells, not shape {cells.shape}")
        if not np.isfinite(self.resolution) or self.resolution <= 0:
            raise ValueError(f"resolution must be positive, not {self.resolution}")
        values = np.asarray(cells, dtype=np.int16)
        if not np.all((values == FREE) | (values == OCCUPIED) | (values == UNKNOWN)):
            raise ValueError("grid cells must be FREE (0), OCCUPIED (100) or UNKNOWN (-1)")
        origin = tuple(float(c) for c in self.origin)
        if len(origin) == 2:
            origin = (*origin, 0.0)
        if len(origin) != 3 or not all(np.isfinite(origin)):
            raise ValueError(f"origin must be (x, y) or (x, y, yaw), not {self.origin}")
        cells = cells.astype(np.int8)
        cells.setflags(write=False)
        object.__setattr__(self, "cells", cells)
        object.__setattr__(self, "resolution", float(self.resolution))
        object.__setattr__(self, "origin", origin)

    # -- building ---------------------------------------------------------------------------
    @classmethod
    def from_masks(cls, free: ArrayLike, resolution: float, origin: ArrayLike = (0.0, 0.0, 0.0),
                   occupied: ArrayLike | None = None) -> OccupancyGrid:
        """From boolean masks indexed ``[row, col]`` with row 0 at the lowest y.

        Cells neither free nor occupied are UNKNOWN: they hold no free space but do not block
        sight (the right reading of a reachability grid: counters and tables are not walls).
        """
        free_mask = np.asarray(free, dtype=bool)
        occ_mask = np.zeros_like(free_mask) if occupied is None else np.asarray(occupied, dtype=bool)
        if occ_mask.shape != free_mask.shape:
            raise ValueError(f"free and occupied masks differ in shape: {free_mask.shape} vs {occ_mask.shape}")
        cells = np.full(free_mask.shape, UNKNOWN, dtype=np.int8)
        cells[free_mask] = FREE
        cells[occ_mask] = OCCUPIED
        return cls(cells, resolution, tuple(np.asarray(origin, dtype=float).tolist()))

    @classmethod
    def from_cells(cls, centres: ArrayLike, resolution: float, margin: int = 1,
                   occupied: ArrayLike | None = None) -> OccupancyGrid:
        """A grid whose free cells are centred on the given points (e.g. ALFRED's reachable
        positions on its 0.25 m lattice); everything else UNKNOWN, and the cells holding any of
        the ``occupied`` points OCCUPIED. ``margin`` unknown cells surround the free ones."""
        c = as_points(centres)
        if len(c) == 0:
            raise ValueError("from_cells needs at least one free cell centre")
        occ = as_points(occupied) if occupied is not None else np.zeros((0, 2))
        low = c.min(axis=0) - (margin + 0.5) * resolution
        high = c.max(axis=0) + (margin + 0.5) * resolution
        shape = np.ceil((high - low) / resolution - 1e-9).astype(int)[::-1]
        cols, rows = np.floor((c - low) / resolution).astype(int).T
        free = np.zeros(shape, dtype=bool)
        free[rows, cols] = True
        occ_mask = np.zeros(shape, dtype=bool)
        if len(occ):
            ocols, orows = np.floor((occ - low) / resolution).astype(int).T
            keep = (orows >= 0) & (orows < shape[0]) & (ocols >= 0) & (ocols < shape[1])
            occ_mask[orows[keep], ocols[keep]] = True
        occ_mask &= ~free
        return cls.from_masks(free, resolution, (low[0], low[1], 0.0), occ_mask)

    @classmethod
    def placed(cls, cells: ArrayLike, resolution: float, origin: tuple[float, float, float],
               corner: tuple[int, int] = (0, 0), factor: int = 1) -> OccupancyGrid:
        """Cells kept from a larger grid of ``resolution`` at ``origin``: their lower-left cell was at (column, row)
        ``corner`` of it (the origin moves there along its yaw), each merges ``factor`` × ``factor`` of its cells."""
        x, y, yaw = origin
        dx, dy = corner[0] * resolution, corner[1] * resolution
        moved = (x + math.cos(yaw) * dx - math.sin(yaw) * dy, y + math.sin(yaw) * dx + math.cos(yaw) * dy, yaw)
        return cls(np.asarray(cells, dtype=np.int8), resolution * factor, moved)

    @classmethod
    def filled(cls, bounds: tuple[float, float, float, float], resolution: float,
               value: int = FREE) -> OccupancyGrid:
        """A grid of one value covering ``bounds`` (xmin, ymin, xmax, ymax)."""
        xmin, ymin, xmax, ymax = bounds
        shape = (max(1, int(np.ceil((ymax - ymin) / resolution - 1e-9))),
                 max(1, int(np.ceil((xmax - xmin) / resolution - 1e-9))))
        return cls(np.full(shape, value, dtype=np.int8), resolution, (xmin, ymin, 0.0))

    # -- shape ------------------------------------------------------------------------------
    @property
    def shape(self) -> tuple[int, int]:
        return (int(self.cells.shape[0]), int(self.cells.shape[1]))

    @property
    def yaw(self) -> float:
        return self.origin[2]

    @cached_property
    def free_mask(self) -> NDArray[np.bool_]:
        return np.asarray(self.cells == FREE)

    @cached_property
    def occupied_mask(self) -> NDArray[np.bool_]:
        return np.asarray(self.cells == OCCUPIED)

    @cached_property
    def has_obstacles(self) -> bool:
        return bool(self.occupied_mask.any())

    @property
    def extent(self) -> tuple[float, float, float, float]:
        """``(left, right, bottom, top)`` of the unrotated grid, for ``imshow(cells, origin="lower")``."""
        h, w = self.shape
        x0, y0 = self.origin[0], self.origin[1]
        return (x0, x0 + w * self.resolution, y0, y0 + h * self.resolution)

    @cached_property
    def bounds(self) -> tuple[float, float, float, float]:
        """``(xmin, ymin, xmax, ymax)`` of the grid in the world (the box around it if rotated)."""
        h, w = self.shape
        corners = self.grid_to_world(np.array([[0, 0], [w, 0], [w, h], [0, h]], dtype=float) * self.resolution)
        lo, hi = corners.min(axis=0), corners.max(axis=0)
        return (float(lo[0]), float(lo[1]), float(hi[0]), float(hi[1]))

    # -- coordinates ------------------------------------------------------------------------
    def world_to_grid(self, points: ArrayLike) -> Points:
        """World points in the grid's own frame (metres from cell (0, 0)'s corner, along its axes)."""
        p = as_points(points) - np.array(self.origin[:2])
        if self.yaw:
            c, s = np.cos(self.yaw), np.sin(self.yaw)
            p = p @ np.array([[c, -s], [s, c]])
        return p

    def grid_to_world(self, local: ArrayLike) -> Points:
        q = as_points(local)
        if self.yaw:
            c, s = np.cos(self.yaw), np.sin(self.yaw)
            q = q @ np.array([[c, s], [-s, c]])
        return q + np.array(self.origin[:2])

    def cell_index(self, points: ArrayLike) -> tuple[NDArray[np.intp], NDArray[np.intp], NDArray[np.bool_]]:
        """``(rows, cols, inside)``: the cell of each point and whether it lies on the grid."""
        local = self.world_to_grid(points) / self.resolution
        cols = np.floor(local[:, 0]).astype(np.intp)
        rows = np.floor(local[:, 1]).astype(np.intp)
        h, w = self.shape
        inside = (rows >= 0) & (rows < h) & (cols >= 0) & (cols < w)
        return rows, cols, inside

    def cell_centres(self, rows: ArrayLike, cols: ArrayLike) -> Points:
        local = (np.column_stack([np.asarray(cols, dtype=float), np.asarray(rows, dtype=float)]) + 0.5)
        return self.grid_to_world(local * self.resolution)

    def values(self, points: ArrayLike) -> NDArray[np.int8]:
        """The cell value under each point; UNKNOWN off the grid."""
        rows, cols, inside = self.cell_index(points)
        out = np.full(len(rows), UNKNOWN, dtype=np.int8)
        out[inside] = self.cells[rows[inside], cols[inside]]
        return out

    def is_free(self, points: ArrayLike) -> NDArray[np.bool_]:
        return np.asarray(self.values(points) == FREE)

    def is_occupied(self, points: ArrayLike) -> NDArray[np.bool_]:
        return np.asarray(self.values(points) == OCCUPIED)


# -- line of sight ------------------------------------------------------------------------------
def _crossings(a: NDArray[np.float64], b: NDArray[np.float64]) -> NDArray[np.float64]:
    """Parameters t in (0, 1) where segments a→b (1-D, in cell units) cross integer lines; inf-padded."""
    fa, fb = np.floor(a), np.floor(b)
    count = np.abs(fb - fa).astype(np.intp)
    width = int(count.max()) if len(count) else 0
    if width == 0:
        return np.full((len(a), 0), np.inf)
    k = np.arange(1, width + 1)
    forward = (b >= a)[:, None]
    lines = np.where(forward, fa[:, None] + k, fa[:, None] - k + 1)
    with np.errstate(divide="ignore", invalid="ignore"):
        t = (lines - a[:, None]) / (b - a)[:, None]
    return np.where(k[None, :] <= count[:, None], t, np.inf)


def segment_cells(grid: OccupancyGrid, start: ArrayLike, ends: ArrayLike
                  ) -> tuple[NDArray[np.intp], NDArray[np.intp], NDArray[np.float64], NDArray[np.bool_]]:
    """The cells each segment ``start → ends[i]`` passes through, in order.

    Returns ``(rows, cols, t_exit, valid)``, each of shape (N, K): the k-th cell entered by
    segment i, the segment parameter in [0, 1] at which it leaves that cell, and whether entry k
    is real (rows are padded to the longest segment). Touching a corner enters no cell.
    """
    a = as_points(start)
    e = as_points(ends)
    ga = np.broadcast_to(grid.world_to_grid(a) / grid.resolution, e.shape)
    gb = grid.world_to_grid(e) / grid.resolution
    t = np.concatenate([np.zeros((len(e), 1)), _crossings(ga[:, 0], gb[:, 0]), _crossings(ga[:, 1], gb[:, 1]),
                        np.ones((len(e), 1))], axis=1)
    t.sort(axis=1)
    t0, t1 = t[:, :-1], t[:, 1:]
    with np.errstate(invalid="ignore"):
        valid = np.isfinite(t1) & (t1 - t0 > 1e-12)
    mid = np.where(valid, 0.5 * (t0 + np.where(valid, t1, 0.0)), 0.0)
    u = ga[:, 0:1] + mid * (gb[:, 0:1] - ga[:, 0:1])
    v = ga[:, 1:2] + mid * (gb[:, 1:2] - ga[:, 1:2])
    return np.floor(v).astype(np.intp), np.floor(u).astype(np.intp), np.where(valid, t1, np.inf), valid


_BLOCK = 16
"""Grid-line crossings examined per step of :func:`line_of_sight` before blocked segments are dropped."""


def line_of_sight(grid: OccupancyGrid, origin: ArrayLike, points: ArrayLike) -> NDArray[np.bool_]:
    """Whether the segment from ``origin`` to each point passes no occupied cell.

    The cell the segment starts in and the cell it ends in never block; unknown cells and
    space off the grid never block. The crossings of each segment with the grid's lines are
    examined a block at a time, near ones first, and a segment leaves the work as soon as it is
    blocked (walls are usually near), so the cost follows the distance to the first wall.
    """
    p = as_points(points)
    out = np.ones(len(p), dtype=bool)
    if not grid.has_obstacles or len(p) == 0:
        return out
    t_rows, t_cols, _ = grid.cell_index(p)
    ga = grid.world_to_grid(as_points(origin)[:1])[0] / grid.resolution
    gb = grid.world_to_grid(p) / grid.resolution
    for axis in (0, 1):
        lines = _Crossings(grid, ga, gb, axis)
        todo = np.flatnonzero(out & (lines.count > 0))
        k0 = 1
        while len(todo):
            _, rows, cols, hit = lines.block(todo, k0)
            hit &= ~((rows == t_rows[todo, None]) & (cols == t_cols[todo, None]))
            blocked = hit.any(axis=1)
            out[todo[blocked]] = False
            k0 += _BLOCK
            todo = todo[~blocked & (lines.count[todo] >= k0)]
    return out


class _Crossings:
    """Where segments from the grid point ``ga`` to the grid points ``gb`` (in cells) cross the grid lines of one
    axis (0: the lines of constant x, 1: of constant y), the k-th of segment i (k ≥ 1) at ``t`` along it (0 at
    ``ga``, 1 at its end), and the cell it enters there: one walk for :func:`line_of_sight` and :func:`cast_rays`."""

    def __init__(self, grid: OccupancyGrid, ga: NDArray[np.float64], gb: NDArray[np.float64], axis: int) -> None:
        self.grid, self.ga, self.d = grid, ga, gb - ga
        self.nudge = np.sign(self.d) * 1e-9
        self.a, self.b = ga[axis], gb[:, axis]
        self.fa = np.floor(self.a)
        self.count = np.abs(np.floor(self.b) - self.fa).astype(np.intp)
        """How many lines of the axis each segment crosses."""
        self.forward = self.b >= self.a

    def t(self, todo: NDArray[np.intp], k: NDArray[np.intp]) -> NDArray[np.float64]:
        """Where along each segment of ``todo`` its crossings ``k`` lie (one row a segment)."""
        lines = np.where(self.forward[todo, None], self.fa + k, self.fa - k + 1)
        return np.asarray((lines - self.a) / (self.b[todo] - self.a)[:, None], dtype=float)

    def block(self, todo: NDArray[np.intp], k0: int) -> tuple[NDArray[np.float64], NDArray[np.intp],
                                                               NDArray[np.intp], NDArray[np.bool_]]:
        """The :data:`_BLOCK` crossings from the ``k0``-th on of each segment of ``todo``: where they lie, the rows and
        columns of the cells they enter, and whether each is a crossing of the segment into an occupied cell."""
        k = np.arange(k0, k0 + _BLOCK)
        t = self.t(todo, k)
        d, nudge, ga = self.d, self.nudge, self.ga
        cols = np.floor(ga[0] + t * d[todo, 0:1] + nudge[todo, 0:1]).astype(np.intp)
        rows = np.floor(ga[1] + t * d[todo, 1:2] + nudge[todo, 1:2]).astype(np.intp)
        h, w = self.grid.shape
        hit = (k <= self.count[todo][:, None]) & (rows >= 0) & (rows < h) & (cols >= 0) & (cols < w)
        hit[hit] = self.grid.occupied_mask[rows[hit], cols[hit]]
        return t, rows, cols, hit


FAN_FROM = 64
"""From this many points, :func:`lines_of_sight` settles most of them by one fan of rays."""


def lines_of_sight(grid: OccupancyGrid, origin: ArrayLike, points: ArrayLike) -> NDArray[np.bool_]:
    """:func:`line_of_sight` for many points from one origin — the same answer, most of it found by one fan of rays.

    The fan (:func:`cast_rays`) has its neighbouring rays ``res / (2 (R + diag))`` radians apart (R: the farthest
    point, diag: a cell's diagonal), reaching ``R + 2 diag``. A point whose distance plus ``2 diag`` is within the
    reach of *both* rays either side of its bearing is in sight, and is settled; every other point is followed
    exactly. Why a settled point is in sight: were the segment to it blocked by an occupied cell C (not the point's
    own), C — a square of side ``res`` no farther than the point plus ``diag`` — spans at least ``res / (R + diag)``
    radians, twice the gap between rays, so its angular span holds one of the two rays, which (C being convex and
    not holding the origin, whose own cell never blocks either) passes through C and stops there, no farther than
    the point plus ``diag``. Tested against :func:`line_of_sight` on every shipped house."""
    p = as_points(points)
    if len(p) < FAN_FROM or not grid.has_obstacles:
        return line_of_sight(grid, origin, p)
    o = as_points(origin)[0]
    d = p - o
    dist = np.hypot(d[:, 0], d[:, 1])
    diag = grid.resolution * np.sqrt(2.0)
    far = float(dist.max()) + diag
    rays = int(np.ceil(2 * np.pi * 2 * far / grid.resolution))
    gap = 2 * np.pi / rays
    reach = cast_rays(grid, o, -np.pi + gap * np.arange(rays), far + diag)
    below = np.floor((np.arctan2(d[:, 1], d[:, 0]) + np.pi) / gap).astype(np.intp) % rays
    sure = dist + 2 * diag <= np.minimum(reach[below], reach[(below + 1) % rays])
    out = sure.copy()
    rest = np.flatnonzero(~sure)
    if len(rest):
        out[rest] = line_of_sight(grid, o, p[rest])
    return out


def cast_rays(grid: OccupancyGrid, origin: ArrayLike, angles: ArrayLike, max_range: float) -> NDArray[np.float64]:
    """For rays from ``origin`` at ``angles`` (radians, world frame): how far each one sees.

    A ray sees up to and *including* the first occupied cell it enters (other than the cell it
    starts in), so a point is visible along the ray when its distance is at most this reach —
    the same rule as :func:`line_of_sight`. Rays that meet nothing reach ``max_range``. Like
    :func:`line_of_sight`, crossings are examined a block at a time and a ray stops once the
    rest of its crossings lie beyond its first hit.
    """
    theta = np.asarray(angles, dtype=float).ravel()
    reach = np.full(len(theta), float(max_range))
    if not grid.has_obstacles or len(theta) == 0:
        return reach
    o = as_points(origin)[:1]
    ends = o + max_range * np.column_stack([np.cos(theta), np.sin(theta)])
    ga = grid.world_to_grid(o)[0] / grid.resolution
    gb = grid.world_to_grid(ends) / grid.resolution
    d = gb - ga
    hit_t = np.full(len(theta), np.inf)
    hit_cell = np.zeros((len(theta), 2), dtype=np.intp)
    for axis in (0, 1):
        lines = _Crossings(grid, ga, gb, axis)
        todo = np.flatnonzero(lines.count > 0)
        k0 = 1
        while len(todo):
            t, rows, cols, hit = lines.block(todo, k0)
            first = np.argmax(hit, axis=1)
            found = hit[np.arange(len(todo)), first]
            t_found = np.where(found, t[np.arange(len(todo)), first], np.inf)
            better = t_found < hit_t[todo]
            rays = todo[better]
            hit_t[rays] = t_found[better]
            hit_cell[rays, 0] = rows[better, first[better]]
            hit_cell[rays, 1] = cols[better, first[better]]
            k0 += _BLOCK
            next_t = lines.t(todo, np.array([k0]))[:, 0]
            todo = todo[~found & (lines.count[todo] >= k0) & (next_t < hit_t[todo])]
    stopped = np.isfinite(hit_t)
    if stopped.any():
        # the ray leaves its hit cell where it crosses the cell's far side in x or in y
        row, col = hit_cell[stopped, 0], hit_cell[stopped, 1]
        ds, starts = d[stopped], ga
        exits = []
        for axis, cell in ((0, col), (1, row)):
            far = np.where(ds[:, axis] > 0, cell + 1, cell)
            with np.errstate(divide="ignore", invalid="ignore"):
                exits.append(np.where(ds[:, axis] != 0, (far - starts[axis]) / ds[:, axis], np.inf))
        reach[stopped] = np.minimum(np.minimum(exits[0], exits[1]), 1.0) * max_range
    return reach
