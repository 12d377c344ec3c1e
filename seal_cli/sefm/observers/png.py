"""A picture of a SeFM run (``seal localize --png``): the map with every belief on it.

:class:`PngDrawer` is an observer: it follows the robot during the run and draws when the run
ends. The picture has one panel for the objects (each class's particles in its own colour, the
detections as orange crosses) and one panel per frame: its particles coloured by weight (dark
purple light, yellow heavy; a frame's weights are its target γ, see
:meth:`~seal_cli.sefm.frame_beliefs.FrameBeliefs.shown_weights`), its modes as 2-σ ellipses labelled
with their weight, its best point as a white star. Every panel shows the occupancy map, the rooms
(tinted, named), the places, the ground-truth objects (red stars) and the robot's path (blue)
ending at its pose.

Made to be read: axes in metres, names above the clouds and moved apart
(:func:`~seal_cli.maps.drawing.declutter`), legends under the map, a colour bar for the weights,
ellipses clipped to their mode's room (a room's outline runs along its walls, so an ellipse
never reaches across one), and every number formatted as the table formats it
(:mod:`seal_cli.sefm.shown`).
"""

from __future__ import annotations

import math
from pathlib import Path
from typing import TYPE_CHECKING, Any

import numpy as np

from seal_cli.maps.drawing import text_as_written
from seal_cli.sefm.observers.metrics import Trace

if TYPE_CHECKING:
    from seal_cli.sefm.filter import SeFM, Step

__all__ = ["PngDrawer", "draw_beliefs"]

MAX_FRAME_PANELS = 11
OBJECT_COLOURS = ["#1f77b4", "#2ca02c", "#9467bd", "#8c564b", "#e377c2", "#17becf", "#bcbd22", "#7f7f7f"]


class PngDrawer:
    """Observer that draws the final beliefs to ``path`` (PNG) when the run finishes."""

    def __init__(self, path: str | Path, dpi: int = 110) -> None:
        self.path = Path(path)
        self.dpi = dpi
        self.trace = Trace()

    def start(self, sefm: SeFM) -> None:
        self.trace.start(sefm)

    def update(self, sefm: SeFM, step: Step) -> None:
        self.trace.update(sefm, step)

    def finish(self, sefm: SeFM) -> None:
        draw_beliefs(self.path, sefm, self.trace, dpi=self.dpi)


@text_as_written
def draw_beliefs(path: str | Path, sefm: SeFM, trace: Trace | None = None, dpi: int = 110) -> None:
    """Draw the beliefs of ``sefm`` (and the robot's ``trace``) into a PNG file at ``path``."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    trace = trace or Trace()
    frames = list(range(min(len(sefm.bindings), MAX_FRAME_PANELS)))
    panels = 1 + len(frames)
    columns = min(3, panels)
    rows = math.ceil(panels / columns)
    xmin, ymin, xmax, ymax = sefm.map.bounds
    width = 6.0
    height = max(2.5, width * (ymax - ymin) / (xmax - xmin)) + 1.4  # room for the title and the legend
    fig, axes = plt.subplots(rows, columns, figsize=(width * columns, height * rows), squeeze=False)
    _objects(axes.flat[0], sefm, trace)
    for ax, i in zip(list(axes.flat)[1:], frames, strict=False):
        _frame(ax, sefm, trace, i)
    for ax in list(axes.flat)[panels:]:
        ax.axis("off")
    hidden = len(sefm.bindings) - len(frames)
    title = f"SeFM on the {sefm.map.said} after {sefm.step} update{'s' if sefm.step != 1 else ''}"
    if hidden > 0:
        title += f" (first {len(frames)} of {len(sefm.bindings)} frames shown)"
    fig.suptitle(title, fontsize=12)
    fig.tight_layout()
    from seal_cli.maps.drawing import declutter

    declutter(fig)
    fig.savefig(path, dpi=dpi, format="png")
    plt.close(fig)


def _base(ax: Any, sefm: SeFM, trace: Trace) -> None:
    from seal_cli.maps.drawing import draw_map

    draw_map(ax, sefm.map, robot=False)
    if trace.poses:
        path = np.array([p[:2] for p in trace.poses])
        ax.plot(path[:, 0], path[:, 1], "-", color="#1f77b4", linewidth=1.5, alpha=0.8, zorder=6)
        x, y, yaw = trace.poses[-1]
    else:
        x, y, yaw = sefm.map.robot.pose
    ax.plot(x, y, marker="o", markersize=8, color="#1f77b4", markeredgecolor="black", zorder=7)
    ax.arrow(x, y, 0.6 * math.cos(yaw), 0.6 * math.sin(yaw), width=0.05, color="#1f77b4", zorder=7)


def _objects(ax: Any, sefm: SeFM, trace: Trace) -> None:
    from seal_cli.maps.drawing import legend_below

    _base(ax, sefm, trace)
    for k, cls in enumerate(sorted(sefm.object_classes)):
        row = sefm.objects.row(cls)
        X, W = sefm.objects.X[row], sefm.objects.W[row]
        size = 4 + 40 * W / max(W.max(), 1e-300)
        ax.scatter(X[:, 0], X[:, 1], s=size, color=OBJECT_COLOURS[k % len(OBJECT_COLOURS)], alpha=0.6,
                   linewidths=0, label=cls, zorder=8)
    seen = [at for step in trace.detections for _, at in step]
    if seen:
        points = np.array(seen)
        ax.scatter(points[:, 0], points[:, 1], marker="x", s=50, color="#ff7f0e", linewidths=2, zorder=9,
                   label="detections")
    if sefm.map.objects:
        ax.plot([], [], "*", color="#d62728", markeredgecolor="black", markersize=9, linestyle="none",
                label="true object")
    legend_below(ax, markerscale=1.5, title="particles (size: weight)" if sefm.object_classes else None,
                 title_fontsize=7)
    ax.set_title("objects", fontsize=10)


def _frame(ax: Any, sefm: SeFM, trace: Trace, i: int) -> None:
    from matplotlib.patches import Ellipse, Polygon, Rectangle

    from seal_cli.maps.drawing import cut_title, legend_below
    from seal_cli.sefm.shown import rooms_text, share

    _base(ax, sefm, trace)
    X, W = sefm.frames.X[i], sefm.frames.shown_weights(i)
    order = np.argsort(W)
    heaviest = max(float(W.max()), 1e-300) if len(W) else 1.0
    cloud = ax.scatter(X[order, 0], X[order, 1], c=W[order] / heaviest, cmap="viridis", s=10, linewidths=0,
                       zorder=8, vmin=0, vmax=1)
    bar = ax.figure.colorbar(cloud, ax=ax, fraction=0.03, pad=0.02)
    bar.set_label("particle weight / heaviest", fontsize=7)
    bar.ax.tick_params(labelsize=6)
    summary = sefm.frame_summary(i)
    written = summary.to_json()
    xmin, ymin, xmax, ymax = sefm.map.bounds
    for mode, shown in zip(summary.modes, written["modes"], strict=True):
        values, vectors = np.linalg.eigh(np.array(mode.cov))
        angle = math.degrees(math.atan2(vectors[1, -1], vectors[0, -1]))
        w, h = 4 * np.sqrt(np.maximum(values[::-1], 1e-6))
        ellipse = Ellipse(mode.mean, w, h, angle=angle, fill=False, edgecolor="#d62728", linewidth=1.5, zorder=9)
        room = sefm.map.room_id(mode.room)
        clip = Polygon(sefm.map.rooms[room].vertices, closed=True, transform=ax.transData) if room is not None \
            else Rectangle((xmin, ymin), xmax - xmin, ymax - ymin, transform=ax.transData)
        ax.add_patch(ellipse)
        ellipse.set_clip_path(clip)
        ax.annotate(share(shown["weight"]), mode.mean, xytext=(0, 0), textcoords="offset points", fontsize=7,
                    color="#d62728", ha="center", va="center", weight="bold", zorder=21,
                    bbox={"boxstyle": "round,pad=0.1", "facecolor": "white", "edgecolor": "none", "alpha": 0.7})
    ax.plot(*summary.best, marker="*", markersize=14, color="white", markeredgecolor="black", zorder=10,
            linestyle="none", label="best point")
    if summary.modes:
        ax.plot([], [], color="#d62728", linewidth=1.5, label="mode: 2σ ellipse (within its room), weight")
    legend_below(ax)
    ax.set_title(cut_title(f"{sefm.bindings[i]}\n{rooms_text(written['rooms'])}"), fontsize=9)
