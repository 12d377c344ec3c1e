"""sefm.frame_beliefs: the potentials' terms, and frame beliefs that follow what is seen."""

from __future__ import annotations

import numpy as np
import pytest

from seal_cli.maps.formats.map_server import load_map
from seal_cli.pipeline import localise
from seal_cli.sefm.filter import SeFMConfig
from seal_cli.sefm.frame_beliefs import Terms


def test_terms_are_flat_per_relation_and_drop_disjoint_ones() -> None:
    terms = Terms.build(3, [[(0, 1.0), (1, 0.0)], [], [(1, 0.5)]], [[], [(3, 0.25)], []])
    assert terms.meas_frame.tolist() == [0, 2] and terms.meas_source.tolist() == [0, 1]
    assert terms.belief_total.tolist() == [1.0, 0.0, 0.5]
    assert terms.has_context.tolist() == [False, True, False]
    rows, beliefs = terms.measurement
    assert rows.shape[0] == 3 and rows[1].max() == -1 and beliefs[0][rows[0] == 0].tolist() == [1.0]
    empty = Terms.build(2, [[], []], [[], []])
    assert empty.belief_total.tolist() == [0.0, 0.0] and not empty.has_context.any()


def test_a_frames_belief_goes_where_its_object_is_seen() -> None:
    apartment = load_map("apartment")
    sefm = localise(apartment, ["pick up the apple"], rng=np.random.default_rng(0), config=SeFMConfig(particles=150))
    (pick,) = [i for i, b in enumerate(sefm.bindings) if b.frame.name == "Pick"]
    seen_at = np.array([0.2, 3.6])                     # on the coffee table, in the family room
    for _ in range(5):
        sefm.update((0.0, 2.5, 0.0), [("apple", tuple(seen_at))])
    X, W = sefm.frames.X[pick], sefm.frames.W[pick]
    assert np.isclose(W.sum(), 1.0) and np.all(W >= 0)
    near = np.linalg.norm(X - seen_at, axis=1) < 1.0
    assert float(W[near].sum()) > 0.6
    assert sefm.frame_summary(pick).top_room == apartment.room_of(seen_at)[0] == "family_room"
    assert 0 < sefm.frames.ess()[pick] <= 150


def test_the_same_seed_gives_the_same_frame_beliefs() -> None:
    apartment = load_map("apartment")
    runs = []
    for _ in range(2):
        sefm = localise(apartment, ["stir the cup"], rng=np.random.default_rng(7), config=SeFMConfig(particles=40))
        sefm.update((5.0, -3.0, 0.0), [("spoon", (8.3, -4.1))])
        runs.append((sefm.frames.X.copy(), sefm.frames.W.copy()))
    assert np.array_equal(runs[0][0], runs[1][0]) and np.array_equal(runs[0][1], runs[1][1])
    assert runs[0][0].shape == (2, 40, 2) and pytest.approx(runs[0][1].sum(axis=1)) == [1.0, 1.0]


def _multiset(points: np.ndarray) -> list[tuple[float, float]]:
    return sorted(map(tuple, points.tolist()))


def test_an_update_says_which_particles_went_and_which_came() -> None:
    """Before − gone + come is after, particle for particle, in every frame (what a kernel that follows the
    beliefs by their differences relies on); nothing is said after the first draw."""
    apartment = load_map("apartment")
    sefm = localise(apartment, ["stir the cup"], rng=np.random.default_rng(3), config=SeFMConfig(particles=120))
    assert sefm.frames.change is None
    for pose, seen in [((5.0, -3.0, 0.0), [("spoon", (8.3, -4.1))]), ((0.0, 2.5, 0.0), [])]:
        before = sefm.frames.X.copy()
        sefm.update(pose, seen)
        assert sefm.frames.change is not None
        gone_f, gone_x, come_f, come_x = sefm.frames.change
        assert 0 < len(come_f) < 2 * 120 * len(before)
        for i in range(len(before)):
            kept = _multiset(before[i])
            for x in gone_x[gone_f == i].tolist():
                kept.remove(tuple(x))                   # each gone particle was there
            assert sorted(kept + _multiset(come_x[come_f == i])) == _multiset(sefm.frames.X[i])


def test_frames_whose_sources_did_not_change_keep_their_gamma_bit_for_bit(monkeypatch: pytest.MonkeyPatch) -> None:
    """A frame without context whose sources' grids are as they were keeps its γ rather than evaluating it
    again: the beliefs are the very same as when every frame is evaluated at every update."""
    from seal_cli.sefm.frame_beliefs import FrameBeliefs
    from seal_cli.sefm.potentials import SplitKernelSums

    apartment = load_map("apartment")
    texts = ["pick up the apple", "grasp the spoon", "stir the cup"]
    looks = [((0.0, 2.5, 0.0), [("apple", (0.2, 3.6))]), ((0.0, 2.6, 0.0), []), ((-6.0, -3.0, 0.0), []),
             ((-6.0, -3.0, 0.0), [])]
    evaluated: list[int] = []
    gamma_at = FrameBeliefs.gamma_at

    def counted(self: FrameBeliefs, *args: object, **kwargs: object) -> np.ndarray:
        points = np.asarray(args[2])
        if points.shape[1] > 1:                          # the reweighting (a move asks about one point per copy)
            evaluated.append(len(points))
        return gamma_at(self, *args, **kwargs)  # type: ignore[arg-type]

    runs = []
    for versions in (True, False):
        if not versions:
            monkeypatch.setattr(SplitKernelSums, "versions", lambda self: None)
        monkeypatch.setattr(FrameBeliefs, "gamma_at", counted)
        evaluated.clear()
        sefm = localise(apartment, texts, rng=np.random.default_rng(5), config=SeFMConfig(particles=60))
        frames = len(sefm.bindings)
        for pose, seen in looks:
            sefm.update(pose, seen)
        runs.append((sefm.frames.X.copy(), sefm.frames.gamma.copy(), list(evaluated), frames))
    (X, gamma, kept, frames), (X_all, gamma_all, every, _) = runs
    assert np.array_equal(X, X_all) and np.array_equal(gamma, gamma_all)
    assert min(kept) < frames <= min(every)               # some update evaluated fewer frames than all
