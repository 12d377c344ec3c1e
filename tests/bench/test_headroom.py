"""The context suite's headroom from the priors and the map alone, on a house built in code (no shared data)."""

from __future__ import annotations

import pytest

from seal_cli.bench.context import unseen_houses
from seal_cli.bench.headroom import FITS_SHARE, Headroom, headroom
from seal_cli.frames.reading import load_library


@pytest.fixture(scope="module")
def bungalow():  # type: ignore[no-untyped-def]
    return next(h for h in unseen_houses() if h.map.name == "bungalow")


def test_a_two_thing_command_is_never_longer_searched_jointly(bungalow) -> None:  # type: ignore[no-untyped-def]
    case = headroom(bungalow.map, bungalow.starts[1], "stir the cup", load_library(None), 2)
    assert case is not None
    assert (case.house, case.command, case.start, case.first, case.second) == ("bungalow", "stir the cup", 2,
                                                                                 "spoon", "cup")
    assert 0 < case.joint_m <= case.one_at_a_time_m + 1e-9
    assert 0.0 <= case.saving < 1.0 and 0.9 <= case.covered <= 1.0 + 1e-9


def test_one_thing_has_nothing_for_context_to_save(bungalow) -> None:  # type: ignore[no-untyped-def]
    case = headroom(bungalow.map, bungalow.starts[0], "pick up the spoon", load_library(None))
    assert case is not None and case.second is None
    assert case.joint_m == pytest.approx(case.one_at_a_time_m)
    assert case.joint_region == case.one_at_a_time_region and not case.fits


def test_a_case_fits_when_context_changes_the_first_look_by_enough() -> None:
    def case(joint: float, first: str) -> Headroom:
        return Headroom("h", "c", 1, "spoon", "cup", joint, 20.0, first, "kitchen", 1.0)

    assert case(20.0 * (1 - FITS_SHARE), "bedroom").fits
    assert not case(20.0 * (1 - FITS_SHARE) + 0.01, "bedroom").fits   # the order changes, by too little
    assert not case(10.0, "kitchen").fits                                # the same first look
