"""The Rerun recording of a SeFM run, read back from the file."""

from __future__ import annotations

from collections import defaultdict
from pathlib import Path
from typing import Any

import numpy as np
import pytest

from seal_cli.frames.library import Library
from seal_cli.maps.formats.map_server import load_map
from seal_cli.maps.model import Map
from seal_cli.planning.state import State, robot_facts
from seal_cli.resources import map_path
from seal_cli.sefm.filter import SeFM, SeFMConfig
from seal_cli.sefm.observers.metrics import Metrics, Trace, weight_colours
from seal_cli.sefm.observers.rerun import RerunRecorder

rr = pytest.importorskip("rerun")


@pytest.fixture(scope="module")
def apartment() -> Map:
    return load_map(map_path("apartment"))


@pytest.fixture(scope="module")
def recorded(tmp_path_factory: pytest.TempPathFactory, library: Library, apartment: Map) -> tuple[Path, SeFM, Any]:
    path = tmp_path_factory.mktemp("rrd") / "run.rrd"
    bindings = [library.frame("Pick").bind({"theme": "spoon"}), library.frame("Stir").bind({"theme": "cup"})]
    state = State.of(robot_facts(None), library.taxonomy)
    metrics, trace = Metrics(), Trace()
    sefm = SeFM(apartment, bindings, state, np.random.default_rng(0), SeFMConfig(particles=120),
                [RerunRecorder(path), metrics, trace])
    sefm.update((5.0, -4.5, 0.0), [("spoon", (8.3, -4.1))])
    sefm.update((7.0, -3.0, 0.0), [("spoon", (8.3, -4.1))])
    sefm.update((0.5, 2.5, 1.5), [])
    sefm.close()
    return path, sefm, (metrics, trace)


def rows(path: Path) -> dict[str, list[dict[str, Any]]]:
    """Every logged row, by entity path, as plain Python values (without the log-time columns)."""
    out: dict[str, list[dict[str, Any]]] = defaultdict(list)
    for chunk in rr.chunk.RrdReader(str(path)).stream().to_chunks():
        batch = chunk.to_record_batch()
        names = [n for n in batch.schema.names if n not in ("log_time", "log_tick")]
        table = batch.select(names).to_pydict()
        for i in range(chunk.num_rows):
            out[str(chunk.entity_path)].append({k: v[i] for k, v in table.items()})
    return out


def test_collect_reads_the_recording_as_a_store(recorded: tuple[Path, SeFM, Any]) -> None:
    store = rr.chunk.RrdReader(str(recorded[0])).stream().collect()
    assert "step" in str(store.schema())


def test_every_spec_entity_is_logged(recorded: tuple[Path, SeFM, Any]) -> None:
    logged = rows(recorded[0])
    for entity in ("/map/occupancy", "/map/rooms", "/map/places", "/robot/pose", "/robot/path",
                   "/objects/spoon/particles", "/objects/cup/particles", "/frames/pick_spoon/particles",
                   "/frames/stir_cup_spoon/particles", "/frames/stir_cup_spoon/modes", "/observations/spoon",
                   "/metrics/frames/stir_cup_spoon/ess", "/metrics/objects/spoon/ess"):
        assert entity in logged, entity


def test_the_map_is_static_and_the_rooms_are_labelled(recorded: tuple[Path, SeFM, Any], apartment: Map) -> None:
    logged = rows(recorded[0])
    (rooms,) = logged["/map/rooms"]
    assert "step" not in rooms
    assert rooms["LineStrips2D:labels"] == list(apartment.room_names)
    assert len(rooms["LineStrips2D:strips"]) == len(apartment.rooms)
    (occupancy,) = logged["/map/occupancy"]
    assert len(occupancy["Points2D:positions"]) == len(apartment.free_centres) + int(apartment.grid.occupied_mask.sum())


def test_particles_are_logged_at_every_step_with_weight_colours(recorded: tuple[Path, SeFM, Any]) -> None:
    path, sefm, _ = recorded
    logged = rows(path)
    frames = logged["/frames/stir_cup_spoon/particles"]
    assert [r["step"] for r in frames] == [0, 1, 2, 3]
    last = frames[-1]
    np.testing.assert_allclose(np.array(last["Points2D:positions"]), sefm.frames.X[1], atol=1e-5)
    colours = np.array(last["Points2D:colors"], dtype=np.uint32)
    expected = weight_colours(sefm.frames.shown_weights(1)).astype(np.uint32)
    packed = (expected[:, 0] << 24) | (expected[:, 1] << 16) | (expected[:, 2] << 8) | 255
    np.testing.assert_array_equal(colours, packed)
    assert len(logged["/objects/cup/particles"][0]["Points2D:positions"]) == 120


def test_robot_path_and_observations(recorded: tuple[Path, SeFM, Any]) -> None:
    logged = rows(recorded[0])
    assert [r["step"] for r in logged["/robot/pose"]] == [1, 2, 3]
    np.testing.assert_allclose(logged["/robot/pose"][-1]["Points2D:positions"], [[0.5, 2.5]])
    np.testing.assert_allclose(logged["/robot/path"][-1]["LineStrips2D:strips"][0], [[5, -4.5], [7, -3], [0.5, 2.5]])
    spoon = logged["/observations/spoon"]
    assert [len(r["Points2D:positions"] or []) for r in spoon] == [1, 1, 0]


def test_metrics_are_scalars_per_step(recorded: tuple[Path, SeFM, Any]) -> None:
    path, sefm, (metrics, trace) = recorded
    ess = rows(path)["/metrics/frames/stir_cup_spoon/ess"]
    assert [r["step"] for r in ess] == [0, 1, 2, 3]
    assert ess[-1]["Scalars:scalars"] == pytest.approx([sefm.frames.ess()[1]])
    assert [row["step"] for row in metrics.rows] == [0, 1, 2, 3]
    assert metrics.rows[-1]["frames"]["stir_cup_spoon"]["ess"] == pytest.approx(sefm.frames.ess()[1])
    assert trace.poses == [(5.0, -4.5, 0.0), (7.0, -3.0, 0.0), (0.5, 2.5, 1.5)]


def test_modes_carry_room_and_weight_labels(recorded: tuple[Path, SeFM, Any]) -> None:
    path, sefm, _ = recorded
    last = rows(path)["/frames/pick_spoon/modes"][-1]
    summary = sefm.frame_summary(0)
    assert last["Points2D:labels"] == [f"{m.room} {m.weight:.2f}" for m in summary.modes]
