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


def test_the_candidates_are_the_same_for_a_seed_and_numbered_as_drawn() -> None:
    from seal_cli.bench.context import House, drawn_starts
    from seal_cli.bench.headroom import candidates
    from seal_cli.bench.houses import mews

    house, library = House(mews(), ()), load_library(None)
    once = list(candidates([house], library, commands=("stir the cup",), starts=2, seed=5))
    assert once == list(candidates([house], library, commands=("stir the cup",), starts=2, seed=5))
    assert [c.pose for c in once] == list(drawn_starts(house.map, 2, 5)) and [c.start for c in once] == [1, 2]
    other = list(candidates([house], library, commands=("stir the cup",), starts=2, seed=6))
    assert [c.pose for c in other] != [c.pose for c in once]


def test_the_committed_cases_are_what_the_criterion_gives_on_a_slice() -> None:
    # the whole file takes ~15 min to recompute (scripts/context_cases.py --check); here: the file's own consistency,
    # and the mews (built in code) recomputed for its first case that fits and its first that does not
    import json

    from seal_cli.bench.context import CASES_FILE, drawn_starts
    from seal_cli.bench.headroom import CANDIDATE_COMMANDS, CANDIDATE_SEED, CANDIDATE_STARTS
    from seal_cli.bench.houses import mews

    doc = json.loads(CASES_FILE.read_text(encoding="utf-8"))
    assert (doc["fits_share"], doc["starts"], doc["seed"]) == (FITS_SHARE, CANDIDATE_STARTS, CANDIDATE_SEED)
    assert doc["commands"] == list(CANDIDATE_COMMANDS)
    assert doc["cases"] == [c for c in doc["candidates"] if c["fits"]]
    assert len(doc["candidates"]) == len(doc["houses"]) * CANDIDATE_STARTS * len(CANDIDATE_COMMANDS)
    assert all(c["fits"] == (c["joint_region"] != c["one_at_a_time_region"] and c["saving"] >= FITS_SHARE)
               for c in doc["candidates"])
    m = mews()
    poses = drawn_starts(m, CANDIDATE_STARTS, CANDIDATE_SEED)
    mine = [c for c in doc["candidates"] if c["house"] == "mews"]
    picked = [next(c for c in mine if c["fits"]), next(c for c in mine if not c["fits"] and c["second"])]
    library = load_library(None)
    for case in picked:
        assert case["pose"] == list(poses[case["start"] - 1])
        again = headroom(m, poses[case["start"] - 1], case["command"], library, case["start"])
        assert again is not None and again.to_json() == case


def test_the_held_out_cases_are_the_criterions_on_the_drawn_houses() -> None:
    # search27: the held-out houses' cases (context.HELD_OUT_CASES_FILE), chosen by the same criterion before any policy
    # ran on them; the file's own consistency, and its first case that fits recomputed from the drawn house
    import json

    from seal_cli.bench.context import HELD_OUT_CASES_FILE, drawn_starts, held_out_houses
    from seal_cli.bench.headroom import CANDIDATE_COMMANDS, CANDIDATE_SEED, CANDIDATE_STARTS

    doc = json.loads(HELD_OUT_CASES_FILE.read_text(encoding="utf-8"))
    built = held_out_houses()
    assert doc["houses"] == [h.map.name for h in built]
    assert (doc["fits_share"], doc["starts"], doc["seed"]) == (FITS_SHARE, CANDIDATE_STARTS, CANDIDATE_SEED)
    assert doc["commands"] == list(CANDIDATE_COMMANDS)
    assert doc["cases"] == [c for c in doc["candidates"] if c["fits"]] and doc["cases"]
    assert len(doc["candidates"]) == len(built) * CANDIDATE_STARTS * len(CANDIDATE_COMMANDS)
    m = built[0].map
    case = next(c for c in doc["candidates"] if c["house"] == m.name and c["fits"])
    pose = drawn_starts(m, CANDIDATE_STARTS, CANDIDATE_SEED)[case["start"] - 1]
    assert case["pose"] == list(pose)
    again = headroom(m, pose, case["command"], load_library(None), case["start"])
    assert again is not None and again.to_json() == case
