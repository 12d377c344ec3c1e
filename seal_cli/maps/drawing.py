"""Pictures of maps with matplotlib: occupancy, rooms, places, objects, the robot and what it sees.

:func:`draw_map` draws onto a matplotlib ``Axes`` so that other pictures (particle clouds,
modes) can be layered on top; :func:`save_map_png` writes a whole picture. matplotlib is
imported inside the functions (it costs half a second).
"""

from __future__ import annotations

import functools
from collections.abc import Callable
from pathlib import Path
from typing import Any, TypeVar, cast

import numpy as np

from seal_cli.maps.geometry import FREE, OCCUPIED
from seal_cli.maps.model import Map

__all__ = ["LABEL", "LEGEND_CHARS", "MARGIN", "NAME_CHARS", "ROOM_CHARS", "TITLE_CHARS", "cut", "cut_title",
           "declutter", "draw_map", "legend_below", "room_colour", "save_map_png", "shown_extent", "text_as_written"]

_Drawing = TypeVar("_Drawing", bound=Callable[..., Any])


UNSET = ("backend", "backend_fallback", "interactive")
"""Settings of matplotlib's own that :func:`text_as_written` leaves as they are (the backend is Agg: ``__main__``)."""


def text_as_written(draw: _Drawing) -> _Drawing:
    """``draw`` (a function that makes a picture) with every text of its figures written as it is, on matplotlib's
    own defaults: matplotlib reads a text with two ``$`` in it as mathematics, so a room, place, class or map called
    ``$x^$`` (any name a file gives) failed the picture with a ``ParseSyntaxException`` traceback, and ``cost $5 or
    $6`` was drawn as italics. A ``matplotlibrc`` in the working folder (or ``MATPLOTLIBRC``, ``MPLCONFIGDIR``'s)
    is not read for seal's pictures (rel33): ``text.usetex: True`` without LaTeX was a ``RuntimeError`` traceback,
    ``savefig.dpi: 100000`` ran out of memory, and the same map drew another picture in another folder."""
    @functools.wraps(draw)
    def drawn(*args: Any, **kwargs: Any) -> Any:
        import matplotlib

        own = {k: v for k, v in matplotlib.rcParamsDefault.items() if k not in UNSET}
        with matplotlib.rc_context({**own, "text.parse_math": False}):
            return draw(*args, **kwargs)

    return cast(_Drawing, drawn)

NAME_CHARS = 32
"""A name written beside its point (a room, place, class or person) is cut to this many characters, with "…": a
name may have 100 (``names.MAX_NAME``), and drawn whole it ran off the picture and over its neighbours' names
(hostile28). The tables and the JSON keep every name whole."""
ROOM_CHARS = 20
"""A room's name, in bold inside its room, is cut to this many characters, and clipped to the axes: cut to
:data:`NAME_CHARS`, two rooms side by side on a small panel still wrote their names over each other."""
LEGEND_CHARS = 48
"""A legend's entry is cut to this many characters: longer, the legend under the map was wider than the figure, and
matplotlib warned "Tight layout not applied" on stderr (hostile28)."""
TITLE_CHARS = 56
"""Each line of a picture's title is cut to this many characters (a map's name of 100, three rooms' names)."""


def cut(text: str, limit: int = NAME_CHARS) -> str:
    """``text``, or its first ``limit - 1`` characters and "…"."""
    return text if len(text) <= limit else text[:limit - 1] + "…"


def cut_title(text: str) -> str:
    """A title, each of its lines cut to :data:`TITLE_CHARS`."""
    return "\n".join(cut(line, TITLE_CHARS) for line in text.split("\n"))


LABEL = "seal-label"
"""The ``gid`` of the names written on a map; :func:`declutter` moves those that are annotations."""
LABEL_Z = 20
"""Labels are drawn above everything else (particles, ellipses): a cloud never hides a name."""
_HALO: dict[str, Any] = {"boxstyle": "round,pad=0.1", "facecolor": "white", "edgecolor": "none", "alpha": 0.7}
_OFFSETS = ((3, 3), (3, -9), (-3, 3), (-3, -9), (6, -3), (-6, -3), (0, 9), (0, -15), (10, 10), (-10, 10),
            (10, -16), (-10, -16))
"""Where a name may stand beside its point, in points, nearest first."""

_PALETTE = ("#4e79a7", "#f28e2b", "#59a14f", "#e15759", "#b07aa1", "#76b7b2", "#edc948", "#ff9da7", "#9c755f",
            "#bab0ac")


def room_colour(index: int) -> str:
    """The colour of the index-th room (a 10-colour palette, repeating)."""
    return _PALETTE[index % len(_PALETTE)]


MARGIN = 0.5
"""Metres of the picture around what the map shows (its known cells, rooms, places, things and people)."""


def shown_extent(m: Map) -> tuple[float, float, float, float]:
    """What a picture of the map shows: the part of its bounds that holds known cells (free or occupied),
    rooms, places, things, people and the robot, plus :data:`MARGIN` — not the wide unknown border a
    laser map is saved with (the AWS house's 25 m square holds a 16 m × 9 m house)."""
    grid = m.grid
    known = np.argwhere((grid.cells == FREE) | (grid.cells == OCCUPIED))
    points = [grid.cell_centres(known[:, 0], known[:, 1])] if len(known) else []
    points += [room.vertices for room in m.rooms if not room.name.startswith("_")]
    points += [np.asarray([p.at for p in m.places] + [o.at for o in m.objects] + [m.robot.xy], float)]
    points += [np.asarray([m.person_at(p) for p in m.people], float).reshape(-1, 2)]
    xy = np.vstack([np.asarray(p, float).reshape(-1, 2) for p in points])
    xmin, ymin, xmax, ymax = m.bounds
    lo = np.maximum(xy.min(axis=0) - MARGIN, (xmin, ymin))
    hi = np.minimum(xy.max(axis=0) + MARGIN, (xmax, ymax))
    return (float(lo[0]), float(lo[1]), float(hi[0]), float(hi[1]))


def occupancy_image(m: Map) -> np.ndarray:
    """Grey levels for the grid (white free, black occupied, light grey unknown), row 0 at the lowest y."""
    image = np.full(m.grid.shape, 0.85)
    image[m.grid.cells == FREE] = 1.0
    image[m.grid.cells == OCCUPIED] = 0.0
    return image


def draw_map(ax: Any, m: Map, *, rooms: bool = True, places: bool = True, objects: bool = True,
             robot: bool = True, visible: bool = False) -> None:
    """Draw the map on ``ax`` in world coordinates (metres), clipped to the map's bounds."""
    from matplotlib.patches import Polygon
    from matplotlib.transforms import Affine2D

    grid = m.grid
    shown = ax.imshow(occupancy_image(m), cmap="gray", vmin=0, vmax=1, origin="lower", extent=grid.extent,
                      interpolation="nearest", zorder=0)
    if grid.yaw:
        x0, y0 = grid.origin[0], grid.origin[1]
        shown.set_transform(Affine2D().rotate_around(x0, y0, grid.yaw) + ax.transData)
    if rooms:
        for i, room in enumerate(m.rooms):
            colour = room_colour(i)
            ax.add_patch(Polygon(room.vertices, closed=True, facecolor=colour, alpha=0.12, edgecolor=colour,
                                 linewidth=1.5, zorder=1))
            x, y, ha, va = _label_point(m, i)
            ax.text(x, y, cut(room.name, ROOM_CHARS), clip_on=True, ha=ha, va=va, fontsize=9, color=colour,
                    weight="bold", zorder=LABEL_Z,
                    gid=LABEL, bbox=_HALO)
    if places:
        for place in m.places:
            marker = "s" if place.openable else "o"
            ax.plot(*place.at, marker=marker, markersize=5, markerfacecolor="white" if place.closed else "#555",
                    markeredgecolor="#555", zorder=3)
            ax.annotate(cut(place.name), place.at, xytext=(3, 3), textcoords="offset points", fontsize=6, color="#555",
                        zorder=LABEL_Z, gid=LABEL, bbox=_HALO)
    if objects:
        for obj in m.objects:
            ax.plot(*obj.at, marker="*", markersize=11, color="#d62728", markeredgecolor="black", zorder=4)
            ax.annotate(cut(obj.cls), obj.at, xytext=(4, -9), textcoords="offset points", fontsize=7, color="#d62728",
                        zorder=LABEL_Z, gid=LABEL, bbox=_HALO)
    if robot:
        x, y, yaw = m.robot.pose
        if visible:
            from seal_cli.sensing.sensor import visible_region

            outline = visible_region(m, m.robot.pose).polygon()
            ax.add_patch(Polygon(outline, closed=True, facecolor="#ffd700", alpha=0.25, edgecolor="none", zorder=2))
        ax.plot(x, y, marker="o", markersize=8, color="#1f77b4", markeredgecolor="black", zorder=4)
        ax.arrow(x, y, 0.6 * np.cos(yaw), 0.6 * np.sin(yaw), width=0.05, color="#1f77b4", zorder=4)
    xmin, ymin, xmax, ymax = shown_extent(m)
    pad = 0.02 * max(xmax - xmin, ymax - ymin)
    ax.set_xlim(xmin - pad, xmax + pad)
    ax.set_ylim(ymin - pad, ymax + pad)
    ax.set_aspect("equal")
    ax.set_xlabel("x (m)")
    ax.set_ylabel("y (m)")
    ax.tick_params(labelsize=7)


def legend_below(ax: Any, columns: int = 4, **options: Any) -> None:
    """The axes' legend under the map, outside it, so no cloud of particles covers it; at most ``columns`` wide
    (fewer where panels stand side by side, so that their legends do not run into each other)."""
    handles, labels = ax.get_legend_handles_labels()
    if handles:
        ax.legend(handles, [cut(label, LEGEND_CHARS) for label in labels], loc="upper center",
                  bbox_to_anchor=(0.5, -0.1), ncol=min(len(handles), columns),
                  fontsize=7, frameon=False, **options)


def declutter(fig: Any) -> None:
    """Move the names beside points (annotations with ``gid=LABEL``) so that no two overlap and none
    leaves its axes: each, in order, takes the first of a few offsets that meets no name already
    placed (room names stay where they are), else the one that overlaps least. Call it after the
    layout is final (after ``tight_layout``), just before saving."""
    from matplotlib.text import Annotation

    renderer = fig.canvas.get_renderer()
    for ax in fig.axes:
        names = [t for t in ax.texts if t.get_gid() == LABEL]
        taken = [t.get_window_extent(renderer) for t in names if not isinstance(t, Annotation)]
        frame = ax.get_window_extent(renderer)
        for label in (t for t in names if isinstance(t, Annotation)):
            best: tuple[float, tuple[int, int]] | None = None
            for offset in _OFFSETS:
                label.xyann = offset
                label.set_horizontalalignment("left" if offset[0] >= 0 else "right")
                box = label.get_window_extent(renderer)
                clash = sum(_overlap(box, other) for other in taken) + box.width * box.height - _overlap(box, frame)
                if best is None or clash < best[0]:
                    best = (clash, offset)
                if clash == 0:
                    break
            assert best is not None
            label.xyann = best[1]
            label.set_horizontalalignment("left" if best[1][0] >= 0 else "right")
            taken.append(label.get_window_extent(renderer))


def _overlap(a: Any, b: Any) -> float:
    """The area two display boxes share."""
    w = min(a.x1, b.x1) - max(a.x0, b.x0)
    h = min(a.y1, b.y1) - max(a.y0, b.y0)
    return max(w, 0.0) * max(h, 0.0)


def _label_point(m: Map, index: int) -> tuple[float, float, str, str]:
    """Where to write a room's name, and its alignment: inside its top-left corner (as on a floor
    plan), else at its centroid, else at its free cell nearest the centroid."""
    room = m.rooms[index]
    xmin, _, _, ymax = room.bbox
    inset = 0.3 + 0.02 * max(m.bounds[2] - m.bounds[0], m.bounds[3] - m.bounds[1])
    corner = (xmin + inset, ymax - inset)
    if room.contains([corner])[0]:
        return (corner[0], corner[1], "left", "top")
    cx, cy = room.centroid
    if room.contains([(cx, cy)])[0]:
        return (cx, cy, "center", "center")
    cells = m.free_centres[m.free_cell_room == index]
    if len(cells) == 0:
        return (float(room.vertices[:, 0].mean()), float(room.vertices[:, 1].mean()), "center", "center")
    best = cells[np.argmin(np.hypot(cells[:, 0] - cx, cells[:, 1] - cy))]
    return (float(best[0]), float(best[1]), "center", "center")


@text_as_written
def save_map_png(m: Map, path: str | Path, *, visible: bool = True, dpi: int = 120) -> None:
    """Write a picture of the map (with the robot's visible region) to ``path`` (whole or not at all)."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    from seal_cli.fileio import atomic_output

    xmin, ymin, xmax, ymax = shown_extent(m)
    width = 9.0
    height = max(3.0, width * (ymax - ymin) / (xmax - xmin) + 0.6)
    fig, ax = plt.subplots(figsize=(width, height))
    try:
        draw_map(ax, m, visible=visible)
        ax.set_title(cut_title(m.name))
        fig.tight_layout()
        declutter(fig)
        with atomic_output(path) as tmp:
            fig.savefig(tmp, dpi=dpi, format="png")
    finally:
        plt.close(fig)
