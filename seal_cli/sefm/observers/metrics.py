"""Observers that gather what happens in a SeFM run, for pictures, recordings and tests.

They follow :class:`seal_cli.sefm.filter.Observer` (``start``, ``update``, ``finish``) and never
change the beliefs. Pass them to :class:`~seal_cli.sefm.filter.SeFM` (``observers=[...]``).
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import TYPE_CHECKING, Any

import numpy as np

if TYPE_CHECKING:
    from seal_cli.sefm.filter import SeFM, Step

__all__ = ["Metrics", "Trace", "weight_colours"]

# viridis at five stops: light weights dark purple, heavy weights yellow
_STOPS = np.array([[68, 1, 84], [59, 82, 139], [33, 145, 140], [94, 201, 98], [253, 231, 37]], float)


def weight_colours(W: np.ndarray) -> np.ndarray:
    """RGB (N, 3) uint8 colours for weights: the heaviest particle yellow, the lightest dark purple."""
    W = np.asarray(W, float)
    top = W.max() if len(W) else 0.0
    t = W / top if top > 0 else np.zeros_like(W)
    x = t * (len(_STOPS) - 1)
    i = np.minimum(np.floor(x).astype(int), len(_STOPS) - 2)
    f = (x - i)[:, None]
    return np.asarray(np.rint(_STOPS[i] * (1 - f) + _STOPS[i + 1] * f), np.uint8)


@dataclass
class Trace:
    """The robot's path and what it detected at each update."""

    poses: list[tuple[float, float, float]] = field(default_factory=list)
    detections: list[tuple[tuple[str, tuple[float, float]], ...]] = field(default_factory=list)

    def start(self, sefm: SeFM) -> None:
        self.poses.clear()
        self.detections.clear()

    def update(self, sefm: SeFM, step: Step) -> None:
        self.poses.append(step.pose)
        self.detections.append(step.detections)

    def finish(self, sefm: SeFM) -> None:
        pass


@dataclass
class Metrics:
    """Per update: the effective sample size of every frame and object, and each frame's room masses."""

    rows: list[dict[str, Any]] = field(default_factory=list)

    def start(self, sefm: SeFM) -> None:
        self.rows.clear()
        self.rows.append(self._row(sefm, 0))

    def update(self, sefm: SeFM, step: Step) -> None:
        self.rows.append(self._row(sefm, step.index))

    def finish(self, sefm: SeFM) -> None:
        pass

    @staticmethod
    def _row(sefm: SeFM, index: int) -> dict[str, Any]:
        from seal_cli.sefm.filter import frame_id
        from seal_cli.sefm.modes import room_masses

        frames = {frame_id(b): {"ess": float(sefm.frames.ess()[i]),
                                "rooms": room_masses(sefm.map, sefm.frames.X[i], sefm.frames.W[i])}
                  for i, b in enumerate(sefm.bindings)}
        objects = {c: {"ess": float(sefm.objects.ess()[sefm.objects.row(c)])} for c in sefm.object_classes}
        return {"step": index, "frames": frames, "objects": objects}
