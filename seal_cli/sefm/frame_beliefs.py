"""Frame beliefs: a weighted particle set per grounded frame over where it can be executed.

Notation: ``X`` (F, P, 2) particles of F frames, ``W`` (F, P) normalised weights, ``γ`` the
unnormalised target, ``K_s(x)`` the kernel sum of source ``s`` (:mod:`seal_cli.sefm.potentials`),
``B`` element and ``C`` context relation beliefs (:mod:`seal_cli.sefm.relations`).

**Target.** Frame ``i``'s belief at step t is ``π_t(x) ∝ γ_t(x)`` over free space, with::

    γ_t(x) = [ Σ_k B_ik · K_k(x) + ε_i ] × [ c₀ + Σ_j C_ij · K_j(x) ]

the measurement potential (a *sum* over the frame's elements of the object beliefs smoothed by
a Gaussian of constant Σ = σ²I) times the context potential (the same over the frames that
achieve its unmet preconditions). A potential whose relations are all Disjoint is the factor 1.
``ε_i`` is a floor worth ``floor_share`` of the frame's mass spread over all free space (the
frame is never impossible anywhere); ``c₀`` (``context_floor``, 1 by default) keeps the context
from vetoing: it raises a frame's weight by at most ``1 + Σ C`` where its preconditions' frames
are, like the authors' sums floored at 1. With ``c₀ = 0`` the context is the bare product;
then two beliefs that are each uniform over a room multiply to one proportional to 1/area², and
which room wins depends on room sizes (docs/sefm.md shows the numbers).

**Update** (the paper's Algorithm 1 — resample, move, reweight — as a resample-move
sequential Monte Carlo sampler; written from the reweighting, so that the move can keep the
target it has just been weighted for):

1. reweight each particle by ``γ_t(x) / γ_{t−1}(x)`` at the point where it is (``γ_{t−1}`` is
   remembered from the last update);
2. reinvigorate: a share of particles is drawn afresh from ``g = u·U + (1 − u)·M``, uniform free
   space ``U`` mixed with the frame's elements' beliefs ``M`` (their particles chosen by ``B·W``,
   plus N(0, Σ)), and weighted ``γ_t(x) / g(x)``. Both groups' weights estimate ``Z_t = ∫ γ_t``
   (the old ones through the running estimate ``Ẑ``), so they are on one scale and the fresh
   group takes over exactly when the old particles stop explaining the target (an object just
   seen);
3. resample P particles by weight (systematic, over the particles listed room by room and along a
   Hilbert curve within a room, :mod:`seal_cli.sefm.cell_order`, so that each room keeps its share of
   the belief to within one particle);
4. move the copies that resampling made by the prediction potential, a Gaussian of the frame's
   own spread (static frames barely move, frames on movable objects move more), each move
   accepted or not by a Metropolis–Hastings test against ``γ_t``: the move explores without
   changing the belief. A particle drawn once is already a draw from ``π_t``; its copies are
   not independent of it, and moving them restores the diversity that resampling took (the
   first copy stays where it is). Where the target has not changed, the weights are even,
   resampling copies almost nothing and almost nothing moves; where it has (an object just
   seen), many particles are copied and all the copies move.

The particles thus track ``π_t``, the frame's location given the *current* object and frame
beliefs. Weighting by ``γ_t`` alone after a resampling would multiply the same object evidence
in again at every update (the belief after T updates ∝ γ^T) and collapse every frame onto its
single densest room. After an update every particle weighs 1/P; :meth:`FrameBeliefs.ess` is the
effective sample size of the reweighting.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass, field
from functools import cached_property

import numpy as np
from numpy.typing import NDArray

from seal_cli.maps.model import Map
from seal_cli.sefm import cell_order, compiled
from seal_cli.sefm.potentials import KernelSums
from seal_cli.sefm.resampling import ess, grouped_systematic, normalise, systematic

__all__ = ["FrameBeliefs", "FrameModel", "Terms"]

Array = NDArray[np.float64]
Index = NDArray[np.intp]
Change = tuple[Index, Array, Index, Array]
"""Particles gone and come in an update: the frame of each and where it was (gone) or is (come)."""


@dataclass(frozen=True)
class FrameModel:
    """Parameters of the frame filter."""

    floor_share: float = 0.01
    context_floor: float = 1.0
    fresh_share: float = 0.1
    uniform_share: float = 0.05
    static_noise: float = 0.02
    movable_noise: float = 0.1


@dataclass(frozen=True)
class Terms:
    """Every frame's potentials in one state, as flat index arrays (one entry per non-Disjoint relation).

    ``source`` entries are rows of the kernel's sources: object rows for the measurement,
    frame rows for the context.
    """

    frames: int
    meas_frame: Index
    meas_source: Index
    meas_weight: Array
    ctx_frame: Index
    ctx_source: Index
    ctx_weight: Array

    @classmethod
    def build(cls, frames: int, measurement: Sequence[Sequence[tuple[int, float]]],
              context: Sequence[Sequence[tuple[int, float]]]) -> Terms:
        """From, per frame, ``(source row, belief)`` pairs of its elements and of its context frames."""
        def flat(per_frame: Sequence[Sequence[tuple[int, float]]]) -> tuple[Index, Index, Array]:
            rows = [(f, s, b) for f, pairs in enumerate(per_frame) for s, b in pairs if b > 0]
            if not rows:
                return np.zeros(0, np.intp), np.zeros(0, np.intp), np.zeros(0)
            f, s, b = zip(*rows, strict=True)
            return np.array(f, np.intp), np.array(s, np.intp), np.array(b, float)

        return cls(frames, *flat(measurement), *flat(context))

    @cached_property
    def measurement(self) -> tuple[Index, Array]:
        """The measurement terms as (F, S) source rows (−1: none) and beliefs: frame i's terms in row i."""
        return _slots(self.meas_frame, self.meas_source, self.meas_weight, np.arange(self.frames))

    @cached_property
    def context(self) -> tuple[Index, Array]:
        """The context terms as (F, S) source rows (−1: none) and beliefs: frame i's terms in row i."""
        return _slots(self.ctx_frame, self.ctx_source, self.ctx_weight, np.arange(self.frames))

    @cached_property
    def belief_total(self) -> Array:
        """Σ_k B_ik per frame."""
        return np.asarray(np.bincount(self.meas_frame, self.meas_weight, minlength=self.frames), float)

    @cached_property
    def has_context(self) -> NDArray[np.bool_]:
        return np.bincount(self.ctx_frame, minlength=self.frames) > 0


@dataclass
class FrameBeliefs:
    """The particle sets of every frame (rows), with what the update needs to remember."""

    map: Map
    X: Array
    W: Array
    gamma: Array
    """γ of each particle where it is, from the update that weighted it."""
    Z: Array
    """Ẑ per frame: the estimate of ∫γ."""
    noise: Array
    """The prediction potential's spread per frame (m)."""
    sigma: float
    model: FrameModel = field(default_factory=FrameModel)
    last_ess: Array = field(default_factory=lambda: np.zeros(0))
    cell: Index = field(default_factory=lambda: np.zeros((0, 0), np.intp))
    """The free cell of each particle (an index into the map's free cells)."""
    _moved: tuple[Array, Index, NDArray[np.bool_], int] | None = None
    """What :attr:`change` is read from: the particles before the last update, each new particle's
    ancestor among them and the fresh draws (a column), which new particles are copies, how many were carried."""
    _seen: tuple[Terms, Index | None] | None = None
    """The terms and the kernel's row versions γ was last evaluated with."""

    @classmethod
    def start(cls, m: Map, noise: Sequence[float], particles: int, terms: Terms, kernel: KernelSums,
              sources: tuple[Array, Array], rng: np.random.Generator, model: FrameModel | None = None) -> FrameBeliefs:
        """Draw every particle from the proposal, weight it by ``γ/g``, resample and move."""
        F = terms.frames
        beliefs = cls(m, np.zeros((F, particles, 2)), np.full((F, particles), 1.0 / max(particles, 1)),
                      np.zeros((F, particles)), np.ones(F), np.asarray(noise, float), kernel.sigma,
                      model or FrameModel())
        beliefs.cell = np.zeros((F, particles), np.intp)
        if F:
            beliefs._resample_move(*beliefs._fresh(terms, kernel, sources, particles, rng), terms, kernel, rng)
            beliefs._moved = None  # drawn afresh: nothing to compare with
        return beliefs

    @property
    def particles(self) -> int:
        return int(self.X.shape[1])

    @property
    def change(self) -> Change | None:
        """What the last update changed: the particles gone (carried ones no draw chose) and come (every other
        new particle: fresh draws and copies, moved or not), each with its frame; the first draw of a
        carried particle is that particle, where it was. None before the first update."""
        if self._moved is None:
            return None
        before, ancestor, copies, carried = self._moved
        F, width = ancestor.shape[0], before.shape[1]
        chosen = np.zeros(F * width, bool)
        chosen[(ancestor + np.arange(F)[:, None] * width).ravel()] = True
        gone_f, gone_k = np.nonzero(~chosen.reshape(F, width)[:, :carried])
        come_f, come_k = np.nonzero(copies | (ancestor >= carried))
        return (gone_f, np.take(before.reshape(-1, 2), gone_f * width + gone_k, axis=0),
                come_f, np.take(self.X.reshape(-1, 2), come_f * self.particles + come_k, axis=0))

    def changed(self) -> Index | None:
        """How many particles of each frame the last update changed (gone plus come), None before the first."""
        if self._moved is None:
            return None
        _, ancestor, copies, carried = self._moved
        return np.asarray(2 * (copies | (ancestor >= carried)).sum(axis=1))

    def ess(self) -> Array:
        """The effective sample size of the last reweighting (before it was resampled), in particles kept.

        The reweighted set holds the P carried particles and the n fresh draws; its Kish ESS
        ``1 / Σ W²`` counts all P + n, so it is scaled by ``P / (P + n)``: between P / (P + n) and
        P, and P exactly when all weights are even."""
        return self.last_ess

    def shown_weights(self, i: int) -> Array:
        """Frame i's particles' weights for pictures: each particle's γ, normalised. After the resampling
        every particle weighs 1/P; γ is the weight it would carry in a weighted set of the same belief."""
        gamma = self.gamma[i]
        total = gamma.sum()
        return gamma / total if total > 0 else self.W[i]

    # -- one update ---------------------------------------------------------------------------
    def update(self, terms: Terms, kernel: KernelSums, sources: tuple[Array, Array],
               rng: np.random.Generator) -> None:
        """Reweight, reinvigorate, resample, move (see the module docstring)."""
        F, P = self.W.shape
        if F == 0:
            return
        gamma = self._gamma_now(terms, kernel)
        X, cells, fresh_gamma, fresh_weights = self._fresh(terms, kernel, sources,
                                                           max(1, int(round(self.model.fresh_share * P))), rng)
        jit = compiled.kernels()
        arrays = (self.X, X, gamma, self.gamma, fresh_gamma, self.Z, self.W, fresh_weights)
        if jit is not None and all(a.dtype == np.float64 and a.flags.c_contiguous for a in arrays) \
                and self.cell.dtype == cells.dtype:  # the same arrays as below, in one pass
            width = P + X.shape[1]
            both = (np.empty((F, width, 2)), np.empty((F, width), cells.dtype), np.empty((F, width)),
                    np.empty((F, width)))
            jit.assemble(self.X, X, self.cell, cells, gamma, self.gamma, fresh_gamma, self.Z, self.W, P, fresh_weights,
                         *both)
            self._resample_move(*both, terms, kernel, rng, carried=P)
            return
        ratio = np.divide(gamma, self.gamma, out=np.zeros((F, P)), where=self.gamma > 0)
        self._resample_move(np.concatenate([self.X, X], axis=1), np.concatenate([self.cell, cells], axis=1),
                            np.concatenate([gamma, fresh_gamma], axis=1),
                            np.concatenate([self.Z[:, None] * self.W * P * ratio, fresh_weights], axis=1),
                            terms, kernel, rng, carried=P)

    def _gamma_now(self, terms: Terms, kernel: KernelSums) -> Array:
        """γ of the current target at every particle. A frame without context whose sources' K are all as
        they were at the last update (the same relations, no row of them set or reweighted since) has the
        same γ where its particles are: it is kept, not evaluated again (the same numbers, bit for bit)."""
        versions = kernel.versions()
        seen, self._seen = self._seen, (terms, versions)
        if versions is None or seen is None or seen[0] is not terms or seen[1] is None:
            return self.gamma_at(terms, kernel, self.X, free=self.cell >= 0)
        sources = terms.measurement[0]
        changed = versions != seen[1]
        stale = terms.has_context | ((sources >= 0) & changed[np.maximum(sources, 0)]).any(axis=1)
        rows = np.flatnonzero(stale)
        if len(rows) == len(stale):
            return self.gamma_at(terms, kernel, self.X, free=self.cell >= 0)
        gamma = self.gamma.copy()
        if len(rows):
            gamma[rows] = self.gamma_at(terms, kernel, np.take(self.X, rows, axis=0), rows,
                                        free=np.take(self.cell, rows, axis=0) >= 0)
        return gamma

    def _fresh(self, terms: Terms, kernel: KernelSums, sources: tuple[Array, Array], n: int,
               rng: np.random.Generator) -> tuple[Array, Index, Array, Array]:
        """``n`` fresh points per frame from the proposal g: where they are, their free cells, their γ,
        and their importance weights γ/g."""
        X = self._draw(terms, sources, n, rng)
        cells = self.map.free_index(X.reshape(-1, 2)).reshape(X.shape[:2]).astype(np.intp)
        measurement, context = self.potentials(terms, kernel, X)
        gamma = self.gamma_of(terms, measurement, context, free=cells >= 0)
        return X, cells, gamma, self._importance(terms, gamma, measurement, cells >= 0)

    def _importance(self, terms: Terms, gamma: Array, measurement: Array, free: NDArray[np.bool_]) -> Array:
        """``γ / g`` of fresh draws, g being the proposal's density (uniform share plus the elements' share)."""
        total = terms.belief_total[:, None]
        u = np.where(total > 0, self.model.uniform_share, 1.0)
        g = u * free / self.free_area + (1 - u) * measurement / (np.where(total > 0, total, 1.0)
                                                                 * 2 * np.pi * self.sigma ** 2)
        return np.where(g > 0, gamma / np.where(g > 0, g, 1.0), 0.0)

    def _resample_move(self, X: Array, cells: Index, gamma: Array, weights: Array, terms: Terms,
                       kernel: KernelSums, rng: np.random.Generator, carried: int = 0) -> None:
        """Keep P of the weighted particles by systematic resampling in cell order, then move the copies.

        The first ``carried`` of each row are the particles of the previous update (each weighing 1/P):
        :attr:`change` then tells which of them are gone and which particles are new."""
        F, P = self.W.shape
        np.copyto(weights, 0.0, where=~((weights > 0) & (weights < np.inf)))  # no NaN, infinite or negative weight
        self.Z = np.maximum(weights.mean(axis=1), np.finfo(float).tiny)
        W = normalise(weights)
        width = W.shape[1]
        self.last_ess = ess(W) * (P / width)  # of P + n weighted particles, P are kept: at most P, even weights give P
        order = cell_order.order_of_cells(self.map, cells)
        jit = compiled.kernels()
        if jit is not None and X.dtype == W.dtype == gamma.dtype == np.float64:  # the same gathers, in one pass
            listed = np.empty((F, width))
            jit.gather_rows(W, order, listed)
            chosen = systematic(listed, rng, P)
            self.X, self.cell, self.gamma = np.empty((F, P, 2)), np.empty((F, P), cells.dtype), np.empty((F, P))
            ancestors, copies = np.empty((F, P), np.intp), np.empty((F, P), bool)
            jit.gather_resampled(order, chosen, X, cells, gamma, self.X, self.cell, self.gamma, ancestors, copies)
        else:
            flat = (order + np.arange(F)[:, None] * width).ravel()  # flat indices
            chosen = systematic(W.ravel()[flat].reshape(F, width), rng, P)
            listed = flat[chosen + np.arange(F)[:, None] * width]
            self.X = np.take(X.reshape(-1, 2), listed, axis=0)  # np.take: a row gather ``[listed]`` is ~10× slower
            self.cell = cells.ravel()[listed]
            self.gamma = gamma.ravel()[listed]
            ancestors = listed - np.arange(F)[:, None] * width
            copies = np.zeros((F, P), bool)
            copies[:, 1:] = chosen[:, 1:] == chosen[:, :-1]  # the draws are sorted: a copy follows its original
        self.W = np.full((F, P), 1.0 / P)
        f, k = np.nonzero(copies)
        self._move(f, k, terms, kernel, rng)
        self._moved = (X, ancestors, copies, carried) if carried else None

    def _move(self, f: Index, k: Index, terms: Terms, kernel: KernelSums, rng: np.random.Generator) -> None:
        """Move particles ``k`` of frames ``f`` by the prediction potential, each move accepted by a
        Metropolis–Hastings test against γ (so the belief stays what it is)."""
        if len(f) == 0:
            return
        flat = f * self.particles + k
        X = self.X.reshape(-1, 2)
        proposal = np.take(X, flat, axis=0) + rng.standard_normal((len(f), 2)) * self.noise[f, None]
        moved = self.map.free_index(proposal).astype(np.intp)
        proposed = self.gamma_at(terms, kernel, proposal[:, None], f, free=moved[:, None] >= 0)[:, 0]
        accept = np.flatnonzero(rng.random(len(f)) * np.take(self.gamma, flat) < proposed)
        flat = flat[accept]
        X[flat] = np.take(proposal, accept, axis=0)
        self.cell.reshape(-1)[flat], self.gamma.reshape(-1)[flat] = moved[accept], proposed[accept]

    @property
    def free_area(self) -> float:
        return max(self.map.free_area, 1e-9)

    # -- the target and the proposal ----------------------------------------------------------
    def potentials(self, terms: Terms, kernel: KernelSums, X: Array,
                   frames: Index | None = None) -> tuple[Array, Array]:
        """Σ_k B_ik K_k(x) and Σ_j C_ij K_j(x) at points X (R, Q, 2) of the frames ``frames`` (R,) — by
        default every frame, R = F: two (R, Q) arrays."""
        rows = np.arange(terms.frames) if frames is None else frames
        sources, beliefs = terms.measurement
        measurement = kernel.combine(sources[rows], beliefs[rows], X)
        context = np.zeros_like(measurement)
        live = np.flatnonzero(terms.has_context[rows])
        if len(live):
            sources, beliefs = terms.context
            # a run of rows is read and written through a slice (no copies)
            some = slice(live[0], live[-1] + 1) if live[-1] - live[0] + 1 == len(live) else live
            at = rows[some]
            context[some] = kernel.combine(sources[at], beliefs[at], X[some])
        return measurement, context

    def gamma_of(self, terms: Terms, measurement: Array, context: Array, frames: Index | None = None,
                 free: NDArray[np.bool_] | None = None) -> Array:
        """γ from the two potentials of the frames ``frames`` (default: every frame); zero where not
        ``free`` when it is given."""
        rows = np.arange(terms.frames) if frames is None else frames
        total = terms.belief_total[rows, None]
        floor = self.model.floor_share * total * 2 * np.pi * self.sigma ** 2 / self.free_area
        jit = compiled.kernels()
        if jit is not None and free is not None and measurement.dtype == context.dtype == np.float32 \
                and measurement.ndim == 2:  # the same numbers, in one pass
            out = np.empty(measurement.shape)
            jit.gamma(np.ascontiguousarray(measurement), np.ascontiguousarray(context),
                      np.ascontiguousarray(floor[:, 0]), total[:, 0] > 0, terms.has_context[rows],
                      np.float32(max(self.model.context_floor, 1e-12)),
                      np.ascontiguousarray(np.broadcast_to(free, measurement.shape)), out)
            return out
        if free is not None:
            return np.where(free, self.gamma_of(terms, measurement, context, frames), 0.0)
        meas = measurement.astype(float) + floor
        if not (total > 0).all():
            meas = np.where(total > 0, meas, 1.0)
        has = terms.has_context[rows, None]
        if not has.any():
            return np.asarray(meas)
        c0 = max(self.model.context_floor, 1e-12)
        meas *= np.where(has, c0 + context, 1.0)
        return np.asarray(meas)

    def gamma_at(self, terms: Terms, kernel: KernelSums, X: Array, frames: Index | None = None,
                 free: NDArray[np.bool_] | None = None) -> Array:
        """γ at points X (R, Q, 2) of the frames ``frames`` (default: every frame), zero off free space
        (``free``, when the points' free cells are known)."""
        if free is None:
            free = self.map.is_free(X.reshape(-1, 2)).reshape(X.shape[:2])
        return self.gamma_of(terms, *self.potentials(terms, kernel, X, frames), frames, free=free)

    def _draw(self, terms: Terms, sources: tuple[Array, Array], n: int, rng: np.random.Generator) -> Array:
        """``n`` points per frame from the proposal g.

        The split between the two parts is exact (``u·n`` uniform draws), and the element draws are
        systematic over the mixture ``Σ_k B_k W_k``: each element and each of its rooms gets its
        share of the fresh particles to within one.
        """
        F = terms.frames
        total = terms.belief_total
        n_uniform = np.where(total > 0, int(np.ceil(self.model.uniform_share * n)), n)
        uniform = np.arange(n)[None, :] < n_uniform[:, None]
        X = np.zeros((F, n, 2))
        count = int(uniform.sum())
        if count:  # uniform over free space (``Map.sample_free``, without listing every free cell)
            X[uniform] = self.map.jitter_in_cells(rng, rng.integers(0, len(self.map.free_centres), size=count))
        if count < F * n:
            X[~uniform] = self._near_elements(terms, sources, n - n_uniform, rng)
        return X

    def _near_elements(self, terms: Terms, sources: tuple[Array, Array], counts: Index,
                       rng: np.random.Generator) -> Array:
        """``counts[i]`` points for frame i: an element chosen by B, then one of its particles by weight —
        both systematically (each element, and each room of it, gets its share to within one) — plus N(0, Σ)."""
        positions, weights = sources
        S, P = weights.shape
        order = np.argsort(terms.meas_frame, kind="stable")
        frame_of, source_of = terms.meas_frame[order], terms.meas_source[order]
        per_term = np.bincount(grouped_systematic(terms.meas_weight[order], frame_of, counts, rng),
                               minlength=len(order))
        owner = np.repeat(np.arange(len(order)), per_term)
        rank = np.arange(len(owner)) - np.repeat(np.cumsum(per_term) - per_term, per_term)
        row = source_of[owner]
        points = row + (rank + rng.random(len(order))[owner]) / np.maximum(per_term[owner], 1)
        jit = compiled.kernels()
        if jit is not None and weights.dtype == np.float64 and np.isfinite(points).all():
            particle = np.empty(len(row), np.intp)
            jit.draw_in_rows(np.ascontiguousarray(weights), row, points, particle)  # the same, summing only these rows
        else:
            cdf = np.cumsum(weights, axis=1)
            cdf = (cdf / cdf[:, -1:] + np.arange(S)[:, None]).ravel()
            particle = np.clip(np.searchsorted(cdf, points, side="right") - row * P, 0, P - 1)
        drawn = np.take(positions.reshape(-1, 2), row * P + particle, axis=0)
        return np.asarray(drawn + rng.normal(0.0, self.sigma, drawn.shape))


def _slots(frame: Index, source: Index, weight: Array, rows: Index) -> tuple[Index, Array]:
    """Terms listed by frame (``frame`` sorted) as a dense (len(rows), S) layout: the terms of frame
    ``rows[r]`` fill row r from the left, −1 and 0 pad the rest."""
    row = np.searchsorted(rows, frame)
    rank = np.arange(len(frame)) - np.searchsorted(frame, frame)
    width = int(rank.max()) + 1 if len(frame) else 0
    sources, weights = np.full((len(rows), width), -1, np.intp), np.zeros((len(rows), width))
    sources[row, rank], weights[row, rank] = source, weight
    return sources, weights
