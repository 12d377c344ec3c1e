"""Rigid transforms over time, as ROS's TF keeps them, and a TF tree to look them up in.

A :class:`Track` is one edge of the tree: the pose of a ``child`` frame in its ``parent`` frame at
a list of stamps (a static transform, ``fixed``, holds at every stamp), as translations ``t`` (N, 3) and unit
quaternions ``q`` (N, 4, ``x y z w`` as ROS writes them). Between two stamps it is interpolated
(linearly in translation, normalised-linearly in rotation, which for the small turns between
two TF messages is slerp to within 1e-4 rad); outside its span it holds its first or last value
(the caller decides how far that may go, see :mod:`seal_cli.ros.bags`).

:class:`TfTree` chains tracks: ``tree.lookup("map", "base_link", stamps)`` is the pose of
``base_link`` in ``map`` at each stamp (``map → odom → base_link`` composed), the transform that
takes points given in ``base_link`` into ``map``. Everything is vectorised over the stamps.
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np
from numpy.typing import NDArray

from seal_cli.errors import SealError

__all__ = ["Track", "TfTree", "apply", "compose", "invert", "quaternion_yaw", "yaw_quaternion"]

Array = NDArray[np.float64]


def _rotate(q: Array, v: Array) -> Array:
    """Rotate vectors v (N, 3) by unit quaternions q (N, 4)."""
    u, w = q[:, :3], q[:, 3:4]
    c = np.cross(u, v)
    return np.asarray(v + 2 * w * c + 2 * np.cross(u, c))


def _multiply(a: Array, b: Array) -> Array:
    ax, ay, az, aw = a.T
    bx, by, bz, bw = b.T
    return np.stack([aw * bx + ax * bw + ay * bz - az * by, aw * by - ax * bz + ay * bw + az * bx,
                     aw * bz + ax * by - ay * bx + az * bw, aw * bw - ax * bx - ay * by - az * bz], axis=1)


def compose(first: tuple[Array, Array], second: tuple[Array, Array]) -> tuple[Array, Array]:
    """``first ∘ second``: the pose of C in A from the pose of B in A and of C in B."""
    (t1, q1), (t2, q2) = first, second
    return t1 + _rotate(q1, t2), _multiply(q1, q2)


def invert(pose: tuple[Array, Array]) -> tuple[Array, Array]:
    """The pose of A in B from the pose of B in A."""
    t, q = pose
    conj = q * np.array([-1.0, -1.0, -1.0, 1.0])
    return -_rotate(conj, t), conj


def apply(pose: tuple[Array, Array], points: Array) -> Array:
    """Points (N, 3) given in the child frame, in the parent frame."""
    t, q = pose
    return t + _rotate(q, points)


def quaternion_yaw(q: Array) -> Array:
    """The heading (rad) of unit quaternions (N, 4): the rotation about z, as ``tf2::getYaw``."""
    x, y, z, w = np.asarray(q, float).T
    return np.asarray(np.arctan2(2 * (w * z + x * y), 1 - 2 * (y * y + z * z)))


def yaw_quaternion(yaw: float) -> tuple[float, float, float, float]:
    """The quaternion ``x y z w`` of a turn by ``yaw`` about z."""
    return (0.0, 0.0, float(np.sin(yaw / 2)), float(np.cos(yaw / 2)))


@dataclass(frozen=True)
class Track:
    """The pose of ``child`` in ``parent`` at sorted ``stamps`` (s)."""

    parent: str
    child: str
    stamps: Array
    t: Array
    q: Array
    fixed: bool = False
    """A static transform (``/tf_static``): it holds at every stamp. A moving one holds only over its span."""

    def __post_init__(self) -> None:
        q = np.asarray(self.q, float)
        q = q / np.maximum(np.linalg.norm(q, axis=1, keepdims=True), 1e-12)
        if len(q) > 1:  # one hemisphere along the track, so that interpolation takes the short way round
            flips = np.cumprod(np.where(np.einsum("ij,ij->i", q[1:], q[:-1]) < 0, -1.0, 1.0))
            q[1:] *= flips[:, None]
        object.__setattr__(self, "q", q)

    @property
    def static(self) -> bool:
        return self.fixed

    @property
    def span(self) -> tuple[float, float]:
        return float(self.stamps[0]), float(self.stamps[-1])

    def at(self, stamps: Array) -> tuple[Array, Array]:
        """The pose at each stamp, interpolated; held constant outside the track's span."""
        stamps = np.asarray(stamps, float)
        if len(self.stamps) == 1:
            return np.repeat(self.t, len(stamps), axis=0), np.repeat(self.q, len(stamps), axis=0)
        i = np.clip(np.searchsorted(self.stamps, stamps, side="right") - 1, 0, len(self.stamps) - 2)
        gap = self.stamps[i + 1] - self.stamps[i]
        f = np.clip(np.divide(stamps - self.stamps[i], gap, out=np.zeros_like(stamps), where=gap > 0), 0, 1)[:, None]
        t = self.t[i] * (1 - f) + self.t[i + 1] * f
        q = self.q[i] * (1 - f) + self.q[i + 1] * f
        return t, q / np.linalg.norm(q, axis=1, keepdims=True)


@dataclass
class TfTree:
    """Frames linked by tracks, each child with one parent (as TF requires)."""

    tracks: dict[str, Track] = field(default_factory=dict)
    """By child frame."""

    def add(self, track: Track) -> None:
        self.tracks[track.child] = track

    @property
    def frames(self) -> set[str]:
        return {f for tr in self.tracks.values() for f in (tr.parent, tr.child)}

    def _chain(self, frame: str) -> list[Track]:
        """The tracks from ``frame`` up to its root."""
        chain: list[Track] = []
        while frame in self.tracks and len(chain) <= len(self.tracks):
            chain.append(self.tracks[frame])
            frame = chain[-1].parent
        return chain

    def root(self, frame: str) -> str:
        """The frame at the top of ``frame``'s chain (itself if it has no parent)."""
        chain = self._chain(frame)
        return chain[-1].parent if chain else frame

    def connected(self, a: str, b: str) -> bool:
        try:
            self.path(a, b)
        except SealError:
            return False
        return True

    def path(self, target: str, source: str) -> tuple[list[Track], list[Track]]:
        """The tracks from ``source`` up to the common ancestor, and from ``target`` up to it."""
        if target == source:
            return [], []
        known = self.frames
        for frame in (target, source):
            if frame not in known:
                raise SealError(f"frame {frame!r} is not in the transforms"
                                f" (known frames: {', '.join(sorted(known)) or 'none'})")
        up_source, up_target = self._chain(source), self._chain(target)
        above_source = [source] + [t.parent for t in up_source]
        above_target = [target] + [t.parent for t in up_target]
        common = next((f for f in above_source if f in above_target), None)
        if common is None:
            raise SealError(f"frames {target!r} and {source!r} are not connected by the transforms "
                            f"(the root of {target!r} is {above_target[-1]!r}, of {source!r} is {above_source[-1]!r})")
        return up_source[:above_source.index(common)], up_target[:above_target.index(common)]

    def lookup(self, target: str, source: str, stamps: Array) -> tuple[Array, Array]:
        """The pose of ``source`` in ``target`` at each stamp: ``(t (N, 3), q (N, 4))``."""
        stamps = np.asarray(stamps, float)
        up_source, up_target = self.path(target, source)
        identity = (np.zeros((len(stamps), 3)), np.tile([0.0, 0.0, 0.0, 1.0], (len(stamps), 1)))
        from_source, from_target = identity, identity
        for track in up_source:
            from_source = compose(track.at(stamps), from_source)
        for track in up_target:
            from_target = compose(track.at(stamps), from_target)
        return compose(invert(from_target), from_source)

    def span(self, target: str, source: str) -> tuple[float, float]:
        """The stamps over which every moving track between the two frames has data (±inf if all are static)."""
        tracks = [t for part in self.path(target, source) for t in part if not t.static]
        if not tracks:
            return -np.inf, np.inf
        return max(t.span[0] for t in tracks), min(t.span[1] for t in tracks)
