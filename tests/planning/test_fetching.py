"""A fetch said alone is brought to the speaker; a later frame that does anything with the thing keeps it a Pick."""

from __future__ import annotations

import subprocess
import sys
from pathlib import Path

import pytest

from seal_cli import pipeline
from seal_cli.frames.library import Library
from seal_cli.maps.formats.map_server import load_map
from seal_cli.planning.fetching import fetching_units

ROOT = Path(__file__).resolve().parents[2]


def steps(text: str, library: Library, map_name: str = "bungalow") -> list[str]:
    return [str(s.binding) for s in pipeline.plan(text, library, map=load_map(map_name)).steps]


def test_fetch_said_alone_brings_the_thing_to_the_speaker(library: Library) -> None:
    assert steps("fetch the remote", library) == ["Pick(theme=remote, source=sofa_1)",
                                                  "Bring(theme=remote, recipient=me)"]
    assert steps("fetch the remote from the sofa", library)[-1] == "Bring(theme=remote, recipient=me, source=sofa_1)"
    assert steps("fetch the mug for raj", library)[-1] == "Bring(theme=mug, recipient=raj)"


def test_a_bringing_said_with_no_one_and_nowhere_to_bring_to_brings_it_to_the_speaker(library: Library) -> None:
    """"Bring the remote (from the kitchen)": before e2e16 the robot picked it up and put it down where it stood."""
    assert steps("bring the remote", library) == ["Pick(theme=remote, source=sofa_1)",
                                                  "Bring(theme=remote, recipient=me)"]
    assert steps("bring the remote from the kitchen", library)[-1] == \
        "Bring(theme=remote, recipient=me, source=kitchen)"
    assert steps("bring the remote to the kitchen", library)[-1] == "Bring(theme=remote, goal=kitchen)"
    assert steps("bring the remote to raj", library)[-1] == "Bring(theme=remote, recipient=raj)"
    assert steps("bring the mug and put it in the sink", library)[-1] == "Place(theme=mug, goal=sink_1)"


def test_a_later_frame_that_does_anything_with_the_thing_keeps_the_fetch_a_pick(library: Library) -> None:
    put = steps("fetch the mug and put it in the sink", library)
    assert put == ["Pick(theme=mug)", "Place(theme=mug, goal=sink_1)"]
    assert steps("fetch a mug and give it to raj", library) == ["Pick(theme=mug)", "Give(theme=mug, recipient=raj)"]


def test_a_take_verb_that_also_means_other_things_stays_a_pick(library: Library) -> None:
    """take.01 links Taking as well as Bringing, get.01 Getting: "take the remote" is a Pick, as it was."""
    assert steps("take the remote", library) == ["Pick(theme=remote)"]
    assert set(fetching_units()) == {("fetch", "Pick")}


def test_the_shipped_table_is_what_the_verb_data_gives(shared_data: Path) -> None:
    done = subprocess.run([sys.executable, str(ROOT / "scripts" / "build_fetching_units.py"), "--check",
                           "--data", str(shared_data)], capture_output=True, text=True, check=False)
    assert done.returncode == 0, done.stderr
    with pytest.raises(KeyError):
        fetching_units()[("take", "Pick")]
