"""Resampling and weight bookkeeping for stacks of particle sets (one row per belief).

Every function works on all rows at once: ``W`` is an (R, P) array of normalised weights, one
row per object class or frame; no Python loop runs over particles.
"""

from __future__ import annotations

import numpy as np
from numpy.typing import NDArray

from seal_cli.sefm import compiled

__all__ = ["ess", "grouped_systematic", "normalise", "stratified", "systematic"]


def normalise(weights: NDArray[np.float64]) -> NDArray[np.float64]:
    """Each row divided by its sum; a row whose sum is not a positive finite number becomes uniform."""
    total = weights.sum(axis=-1, keepdims=True)
    good = np.isfinite(total) & (total > 0)
    if good.all():
        return np.asarray(weights / total)
    return np.where(good, weights / np.where(good, total, 1.0), 1.0 / weights.shape[-1])


def ess(weights: NDArray[np.float64]) -> NDArray[np.float64]:
    """Effective sample size of each row of normalised weights: ``1 / Σ W²`` (P for uniform weights)."""
    return np.asarray(1.0 / np.square(weights).sum(axis=-1))


def systematic(weights: NDArray[np.float64], rng: np.random.Generator, count: int | None = None) -> NDArray[np.intp]:
    """Systematic resampling of each row: ``count`` (default P) ancestor indices per row, one uniform draw per row.

    The draws are at ``(u + k) / count`` on the row's cumulative weights, k = 0 … count − 1; particle
    i is drawn once for each such point in ``[C_{i−1}, C_i)``, that is ``⌈count·C_i − u⌉ − ⌈count·C_{i−1} − u⌉``
    times, so the ancestors are each index repeated that often (linear time, no search). In the
    order the particles are listed, each contiguous run of them gets its share of the draws to
    within one. A row whose sum is not positive is drawn as if uniform.
    """
    rows, size = weights.shape
    count = size if count is None else count
    u = rng.random((rows, 1))
    jit = compiled.kernels()
    if jit is not None and size and weights.dtype == np.float64:
        ancestors = np.empty((rows, count), np.intp)
        if jit.systematic(np.ascontiguousarray(weights), u[:, 0], count, ancestors):  # every row's sum is positive
            return ancestors
    cumulative = np.cumsum(weights, axis=1)
    total = cumulative[:, -1:]
    good = np.isfinite(total) & (total > 0)
    if good.all():  # (in place: these passes over every particle are most of the work)
        cumulative *= count / total
    else:
        cumulative = np.where(good, cumulative * (count / np.where(good, total, 1.0)),
                              np.arange(1, size + 1) * (count / size))
    cumulative[:, -1] = count  # exactly: rounding must not make count + 1 draws
    cumulative -= u
    drawn_below = np.ceil(cumulative, out=cumulative).astype(np.intp)  # draws at or below each particle's upper edge
    copies = np.empty_like(drawn_below)
    copies[:, 0] = drawn_below[:, 0]
    np.subtract(drawn_below[:, 1:], drawn_below[:, :-1], out=copies[:, 1:])
    ancestors = np.repeat(np.arange(rows * size), copies.ravel()).reshape(rows, count)
    ancestors -= np.arange(rows)[:, None] * size
    return ancestors


def grouped_systematic(weights: NDArray[np.float64], group: NDArray[np.intp], counts: NDArray[np.intp],
                       rng: np.random.Generator, systematic: bool = True) -> NDArray[np.intp]:
    """Draws within groups: ``counts[g]`` indices into ``weights`` from the entries of group ``g``.

    ``group`` (N,) must be sorted; each group's weights need not sum to 1 (each is normalised on its
    own) but must have a positive sum when its count is positive. Returns the indices, group by group.
    Draws are systematic (one uniform per group) or, with ``systematic=False``, independent.
    """
    counts = np.asarray(counts, np.intp)
    groups = len(counts)
    total = np.bincount(group, weights, minlength=groups)
    share = weights / np.where(total > 0, total, 1.0)[group]
    cumulative = np.cumsum(share)
    start = np.searchsorted(group, np.arange(groups))
    before = np.concatenate([[0.0], cumulative])[start]
    cumulative = cumulative - before[group] + group
    owner = np.repeat(np.arange(groups), counts)
    rank = np.arange(len(owner)) - np.repeat(np.cumsum(counts) - counts, counts)
    if systematic:
        points = owner + (rank + rng.random(groups)[owner]) / np.maximum(counts[owner], 1)
    else:
        points = owner + rng.random(len(owner))
    index = np.searchsorted(cumulative, points, side="right")
    end = np.searchsorted(group, np.arange(groups), side="right")
    return np.asarray(np.clip(index, start[owner], np.maximum(end[owner] - 1, start[owner])))


def stratified(weights: NDArray[np.float64], n: int, rng: np.random.Generator) -> NDArray[np.intp]:
    """``n`` systematic draws of indices by ``weights`` (any positive scale), in random order."""
    index = grouped_systematic(np.asarray(weights, float), np.zeros(len(weights), np.intp),
                               np.array([n]), rng)
    return np.asarray(rng.permutation(index))
