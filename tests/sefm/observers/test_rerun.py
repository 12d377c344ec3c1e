"""The Rerun recording of a SeFM run, read back from the file: the map as one image, class colours, the
default layout, beliefs logged when they change (and at the end), the metrics, and the time timeline."""

from __future__ import annotations

import io
from collections import defaultdict
from pathlib import Path
from typing import Any

import numpy as np
import pytest

from seal_cli.frames.library import Library
from seal_cli.maps.formats.map_server import load_map
from seal_cli.maps.geometry import FREE, OCCUPIED
from seal_cli.maps.model import Map
from seal_cli.planning.state import State, robot_facts
from seal_cli.resources import map_path
from seal_cli.sefm.filter import SeFM, SeFMConfig
from seal_cli.sefm.observers.metrics import Metrics, Trace
from seal_cli.sefm.observers.rerun import RerunRecorder, radii, spread
from seal_cli.sefm.observers.rerun_scene import Classes

rr = pytest.importorskip("rerun")

P = 120
LOOKS = [((5.0, -4.5, 0.0), [("spoon", (8.3, -4.1))]), ((7.0, -3.0, 0.0), [("spoon", (8.3, -4.1))]),
         ((0.5, 2.5, 1.5), []), ((0.5, 2.5, 1.5), []), ((0.5, 2.5, 1.5), [])]
STAMPS = [1.7e9 + 0.5 * k for k in range(len(LOOKS))]


@pytest.fixture(scope="module")
def apartment() -> Map:
    return load_map(map_path("apartment"))


@pytest.fixture(scope="module")
def recorded(tmp_path_factory: pytest.TempPathFactory, library: Library, apartment: Map) -> tuple[Path, SeFM, Any]:
    path = tmp_path_factory.mktemp("rrd") / "run.rrd"
    bindings = [library.frame("Pick").bind({"theme": "spoon"}), library.frame("Stir").bind({"theme": "cup"})]
    state = State.of(robot_facts(None), library.taxonomy)
    metrics, trace = Metrics(), Trace()
    sefm = SeFM(apartment, bindings, state, np.random.default_rng(0), SeFMConfig(particles=P),
                [RerunRecorder(path, stamps=STAMPS), metrics, trace])
    for pose, seen in LOOKS:
        sefm.update(pose, seen)
    sefm.close()
    return path, sefm, (metrics, trace)


def rows(path: Path, store: Any = None) -> dict[str, list[dict[str, Any]]]:
    """Every logged row, by entity path, as plain Python values (without the log-time columns), in step order."""
    out: dict[str, list[dict[str, Any]]] = defaultdict(list)
    for chunk in rr.chunk.RrdReader(str(path)).stream(store=store).to_chunks():
        batch = chunk.to_record_batch()
        names = [n for n in batch.schema.names if n not in ("log_time", "log_tick")]
        table = batch.select(names).to_pydict()
        for i in range(chunk.num_rows):
            out[str(chunk.entity_path)].append({k: v[i] for k, v in table.items()})
    for entity in out:
        out[entity].sort(key=lambda r: r.get("step", -1))
    return out


def test_collect_reads_the_recording_as_a_store(recorded: tuple[Path, SeFM, Any]) -> None:
    store = rr.chunk.RrdReader(str(recorded[0])).stream().collect()
    schema = str(store.schema())
    assert "step" in schema and "time" in schema


def test_every_spec_entity_is_logged(recorded: tuple[Path, SeFM, Any]) -> None:
    logged = rows(recorded[0])
    assert set(logged) == {"/", "/map/occupancy", "/map/rooms", "/map/places", "/robot/pose", "/robot/path",
                           "/objects/particles", "/frames/particles", "/frames/modes", "/frames/pick_spoon/density",
                           "/frames/stir_cup_spoon/density", "/observations", "/metrics/rooms", "/metrics/ess"}


def chunks_per_entity(path: Path, store: Any = None) -> dict[str, int]:
    found: dict[str, int] = defaultdict(int)
    for chunk in rr.chunk.RrdReader(str(path)).stream(store=store).to_chunks():
        found[str(chunk.entity_path)] += 1
    return dict(found)


def test_one_chunk_per_entity_and_no_footer(recorded: tuple[Path, SeFM, Any]) -> None:
    """Every entity is one chunk (one Arrow schema), the metrics' steps included; the file has no footer."""
    path = recorded[0]
    assert set(chunks_per_entity(path).values()) == {1}
    (blueprint,) = rr.chunk.RrdReader(str(path)).blueprints()
    assert set(chunks_per_entity(path, blueprint).values()) == {1}
    assert not path.read_bytes().endswith(b"RRF2FOOT\x01\x00\x00\x00")  # rerun's footer trailer


def test_no_rerun_warning_on_stderr(tmp_path: Path, library: Library, apartment: Map,
                                    capfd: pytest.CaptureFixture[str]) -> None:
    bindings = [library.frame("Pick").bind({"theme": "spoon"})]
    sefm = SeFM(apartment, bindings, State.of(robot_facts(None), library.taxonomy), np.random.default_rng(0),
                SeFMConfig(particles=20), [RerunRecorder(tmp_path / "quiet.rrd")])
    sefm.update((5.0, -4.5, 0.0), [])
    sefm.close()
    assert capfd.readouterr().err == ""
    assert "/frames/particles" in rows(tmp_path / "quiet.rrd")


def png_pixels(blob: Any) -> np.ndarray:
    from PIL import Image

    return np.asarray(Image.open(io.BytesIO(bytes(blob[0] if isinstance(blob[0], list) else blob))))


def test_the_occupancy_is_one_image_placed_in_metres(recorded: tuple[Path, SeFM, Any], apartment: Map) -> None:
    (occupancy,) = rows(recorded[0])["/map/occupancy"]
    assert "step" not in occupancy  # static
    assert occupancy["EncodedImage:media_type"] == ["image/png"]
    pixels = png_pixels(occupancy["EncodedImage:blob"])
    grid = apartment.grid
    assert pixels.shape == grid.cells.shape  # one pixel per cell, row 0 the lowest y
    assert (pixels[grid.cells == FREE] == 254).all() and (pixels[grid.cells == OCCUPIED] == 0).all()
    assert occupancy["Transform3D:translation"] == [pytest.approx([grid.origin[0], grid.origin[1], 0.0])]
    assert occupancy["Transform3D:scale"] == [pytest.approx([grid.resolution] * 3)]
    assert occupancy["EncodedImage:draw_order"] == [-10.0]


def test_rooms_are_labelled_closed_strips(recorded: tuple[Path, SeFM, Any], apartment: Map) -> None:
    (rooms,) = rows(recorded[0])["/map/rooms"]
    assert rooms["LineStrips2D:labels"] == list(apartment.room_names)
    strips = rooms["LineStrips2D:strips"]
    assert len(strips) == len(apartment.rooms) and all(s[0] == s[-1] for s in strips)


def test_one_colour_per_class_and_particles_carry_class_ids(recorded: tuple[Path, SeFM, Any]) -> None:
    path, sefm, _ = recorded
    logged = rows(path)
    (context,) = logged["/"]
    (described,) = context["AnnotationContext:context"]
    classes = {c["class_description"]["info"]["label"]: c["class_description"]["info"] for c in described}
    assert list(classes) == [*sefm.object_classes, *sefm.frame_ids]
    assert len({c["color"] for c in classes.values()}) == len(classes)  # distinct colours: a legend
    for names, entity in [(sefm.object_classes, "/objects/particles"), (sefm.frame_ids, "/frames/particles")]:
        for row in logged[entity]:  # every class's particles in one entity, told apart by their class ids
            assert row["Points2D:class_ids"] == [classes[n]["id"] for n in names for _ in range(P)]
            assert row.get("Points2D:colors") is None  # the colour comes from the class


def test_beliefs_are_logged_at_the_prior_when_they_change_and_at_the_end(recorded: tuple[Path, SeFM, Any]) -> None:
    path, sefm, _ = recorded
    frames = rows(path)["/frames/particles"]
    steps = [r["step"] for r in frames]
    assert steps[0] == 0 and steps[-1] == len(LOOKS) and 1 in steps  # the spoon seen at step 1 changes the frame
    last = frames[-1]
    np.testing.assert_allclose(np.array(last["Points2D:positions"]), np.concatenate(sefm.frames.X), atol=1e-5)
    assert last["Points2D:radii"] == [pytest.approx(radii(np.ones(1))[0])]  # resampled: one size for all
    objects = rows(path)["/objects/particles"]
    spoon = sefm.object_classes.index("spoon")
    np.testing.assert_allclose(np.array(objects[-1]["Points2D:positions"][spoon * P:(spoon + 1) * P]),
                               sefm.objects.X[sefm.objects.row("spoon")], atol=1e-5)
    np.testing.assert_allclose(objects[-1]["Points2D:radii"][spoon * P:(spoon + 1) * P],
                               radii(sefm.objects.W[sefm.objects.row("spoon")]), atol=1e-6)
    assert len(objects[0]["Points2D:positions"]) == P * len(sefm.object_classes)


def test_radii_grow_with_weight() -> None:
    sizes = radii(np.array([0.0, 0.25, 1.0]))
    assert sizes[0] == pytest.approx(0.03) and sizes[-1] == pytest.approx(0.12) and sizes[0] < sizes[1] < sizes[2]
    even = radii(np.full(4, 0.25))
    assert len(set(even.tolist())) == 1 and 0.05 < even[0] < 0.1  # even weights: one middle size


def test_densities_are_images_in_the_frames_colour(recorded: tuple[Path, SeFM, Any], apartment: Map) -> None:
    path, sefm, _ = recorded
    density = rows(path)["/frames/pick_spoon/density"][-1]
    pixels = png_pixels(density["EncodedImage:blob"])
    xmin, ymin, xmax, ymax = apartment.bounds
    assert pixels.shape == (round((ymax - ymin) / 0.2), round((xmax - xmin) / 0.2))
    assert density["Transform3D:translation"] == [pytest.approx([xmin, ymin, 0.0])]
    # the spoon was seen on the counter: Pick's density is highest around it
    row, col = np.unravel_index(np.argmax(pixels), pixels.shape)
    assert abs(xmin + (col + 0.5) * 0.2 - 8.3) < 1.0 and abs(ymin + (row + 0.5) * 0.2 + 4.1) < 1.0


def test_robot_path_and_observations(recorded: tuple[Path, SeFM, Any]) -> None:
    logged = rows(recorded[0])
    assert [r["step"] for r in logged["/robot/pose"]] == [1, 2, 3]  # logged when it moved
    np.testing.assert_allclose(logged["/robot/pose"][-1]["Points2D:positions"], [[0.5, 2.5]])
    np.testing.assert_allclose(logged["/robot/path"][-1]["LineStrips2D:strips"][0], [[5, -4.5], [7, -3], [0.5, 2.5]])
    seen = logged["/observations"]
    assert [(r["step"], r["Points2D:labels"] or []) for r in seen] == [(1, ["spoon"]), (2, ["spoon"]), (3, [])]
    np.testing.assert_allclose(seen[0]["Points2D:positions"], [[8.3, -4.1]], atol=1e-5)


def test_metrics_are_series_per_step(recorded: tuple[Path, SeFM, Any]) -> None:
    path, sefm, (metrics, trace) = recorded
    logged = rows(path)
    ess = logged["/metrics/ess"]
    assert [r["step"] for r in ess] == list(range(len(LOOKS) + 1))
    assert ess[0]["SeriesLines:names"] == [*sefm.frame_ids, *sefm.object_classes]
    assert all(r["SeriesLines:names"] is None for r in ess[1:])  # null: the names stand, not cleared
    assert ess[-1]["Scalars:scalars"][:2] == pytest.approx(list(sefm.frames.ess()))
    rooms = logged["/metrics/rooms"]
    names = [*sefm.map.room_names, "_outside"]
    assert rooms[0]["SeriesLines:names"] == [f"{fid}: {room}" for fid in sefm.frame_ids for room in names]
    k = len(names)
    assert all(sum(r["Scalars:scalars"][i * k:(i + 1) * k]) == pytest.approx(1.0, abs=1e-6)
               for r in rooms for i in range(len(sefm.frame_ids)))
    assert rooms[-1]["Scalars:scalars"][k:] == pytest.approx(list(sefm.frame_summary(1).rooms.values()))
    assert metrics.rows[-1]["frames"]["stir_cup_spoon"]["ess"] == pytest.approx(sefm.frames.ess()[1])
    assert trace.poses == [pose for pose, _ in LOOKS]


def test_the_frame_ess_never_exceeds_the_particles(recorded: tuple[Path, SeFM, Any]) -> None:
    """It is the reweighting's (carried and fresh particles together), in particles kept; the JSON reports it."""
    path, sefm, (metrics, _) = recorded
    assert [sefm.frame_json(i)["ess"] for i in range(2)] == [round(float(v), 1) for v in sefm.frames.ess()]
    for row in rows(path)["/metrics/ess"]:
        assert all(0 < v <= P + 1e-9 for v in row["Scalars:scalars"])
    assert all(f["ess"] <= P + 1e-9 for row in metrics.rows for f in row["frames"].values())


def test_the_time_timeline_follows_the_stamps(recorded: tuple[Path, SeFM, Any]) -> None:
    ess = rows(recorded[0])["/metrics/ess"]
    times = [r["time"] for r in ess]
    assert [t.timestamp() if hasattr(t, "timestamp") else t for t in times][1:] == pytest.approx(STAMPS)


def test_the_recording_opens_with_the_default_layout(recorded: tuple[Path, SeFM, Any]) -> None:
    reader = rr.chunk.RrdReader(str(recorded[0]))
    (blueprint,) = reader.blueprints()
    logged = rows(recorded[0], blueprint)
    views = {r["ViewBlueprint:display_name"][0]: (r["ViewBlueprint:class_identifier"][0],
                                                  r["ViewBlueprint:space_origin"][0])
             for entity, found in logged.items() for r in found if "ViewBlueprint:display_name" in r}
    assert views == {"map apartment": ("2D", "/"), "room mass per frame": ("TimeSeries", "/metrics/rooms"),
                     "effective sample size": ("TimeSeries", "/metrics/ess")}


def test_the_modes_of_every_frame_in_one_entity(recorded: tuple[Path, SeFM, Any]) -> None:
    path, sefm, _ = recorded
    classes = Classes(sefm.object_classes, sefm.frame_ids)
    last = rows(path)["/frames/modes"][-1]
    modes = [(fid, mo) for i, fid in enumerate(sefm.frame_ids) for mo in sefm.frame_summary(i).modes]
    assert modes and last["Boxes2D:class_ids"] == [classes.ids[fid] for fid, _ in modes]
    assert last["Boxes2D:labels"] == [f"{mo.room} {mo.weight:.2f}" for _, mo in modes]
    np.testing.assert_allclose(last["Boxes2D:centers"], [mo.mean for _, mo in modes], atol=1e-5)
    np.testing.assert_allclose(last["Boxes2D:half_sizes"], [spread(mo.cov) for _, mo in modes], atol=1e-5)
    assert all(min(half) >= 0.1 - 1e-6 for half in last["Boxes2D:half_sizes"])  # ±1 σ, at least 0.1 m


def test_spread_is_the_standard_deviations() -> None:
    assert spread([[0.25, 0.1], [0.1, 0.0001]]) == pytest.approx((0.5, 0.1))


@pytest.mark.parametrize(("raised", "said"), [
    ("Failed to encode LogMsg: Failed to write: No space left on device (os error 28)", "No space left on device"),
    ("File-writer thread shut down prematurely", "rerun's writer stopped before the recording was whole")])
def test_rerun_failing_to_write_is_the_oserror_of_the_recording(raised: str, said: str) -> None:
    # --rrd on a full disk: a RuntimeError traceback from rerun's log or flush (hostile17)
    from seal_cli.sefm.observers.rerun_scene import writing

    with pytest.raises(OSError, match=said) as caught, writing("r.rrd"):
        raise RuntimeError(raised)
    assert caught.value.filename == "r.rrd"
    with pytest.raises(RuntimeError, match="something else"), writing("r.rrd"):
        raise RuntimeError("something else")


def test_a_writer_stopped_on_a_full_disk_is_said_as_a_full_disk(monkeypatch: pytest.MonkeyPatch) -> None:
    """Rerun's "File-writer thread shut down prematurely" names no reason; on a disk with no space left it is said
    as "No space left on device" (hostile25, a 16 KiB tmpfs: it was "rerun's writer stopped"), and the stream is let
    go quietly, so that rerun does not print its failure again at the process's end."""
    import errno

    import seal_cli.sefm.observers.rerun_scene as scene

    class Stream:
        gone = False

        def disconnect(self) -> None:
            self.gone = True

    stream = Stream()
    monkeypatch.setattr(scene, "cause", lambda path: errno.ENOSPC)
    with pytest.raises(OSError, match="No space left on device") as caught, scene.writing("r.rrd", stream):
        raise RuntimeError("File-writer thread shut down prematurely")
    assert caught.value.filename == "r.rrd" and stream.gone


@pytest.mark.parametrize(("raised", "number"), [
    ("Failed to encode LogMsg: Failed to write: No space left on device (os error 28)", 28),
    ("Failed to create file: Permission denied (os error 13)", 13),
    ("Failed to write: No such file or directory (os error 2)", 2)])
def test_rerun_saying_the_system_error_is_that_error_of_the_recording(raised: str, number: int) -> None:
    """One reading of rerun's words (:func:`failure`) for the log, the flush and the writer: the system's number
    rerun gives is the ``OSError``'s, said of the recording asked for."""
    import os

    from seal_cli.sefm.observers.rerun_scene import failure

    error = failure(raised, "d/r.rrd")
    assert error is not None and (error.errno, error.strerror, error.filename) == (number, os.strerror(number),
                                                                                     "d/r.rrd")
    assert failure("flush timed out", "d/r.rrd") is None          # not a failure to write: rerun's own words stand


def test_a_writer_stopped_without_a_reason_is_said_by_what_the_file_system_shows(tmp_path: Path,
                                                                                 monkeypatch: pytest.MonkeyPatch
                                                                                 ) -> None:
    """"File-writer thread shut down prematurely" names no reason: it is read off the recording's folder, a full disk
    (no blocks left), a folder removed while the command ran (hostile26: ``--rrd d/o.rrd``, ``d`` deleted), a
    folder that no longer takes a file; else the writer stopped."""
    import errno
    import os
    from types import SimpleNamespace

    import seal_cli.sefm.observers.rerun_scene as scene

    stopped = "File-writer thread shut down prematurely"
    gone = tmp_path / "gone" / "r.rrd"
    assert scene.failure(stopped, gone).errno == errno.ENOENT                         # type: ignore[union-attr]
    shut = tmp_path / "shut"
    shut.mkdir()
    monkeypatch.setattr(os, "access", lambda path, mode: str(path) != str(shut))
    assert scene.failure(stopped, shut / "r.rrd").strerror == "Permission denied"     # type: ignore[union-attr]
    assert "rerun's writer stopped" in str(scene.failure(stopped, tmp_path / "r.rrd"))
    real = os.statvfs
    monkeypatch.setattr(os, "statvfs", lambda path: SimpleNamespace(f_bavail=0) if str(path) == str(tmp_path)
                        else real(path))
    assert scene.failure(stopped, tmp_path / "r.rrd").errno == errno.ENOSPC             # type: ignore[union-attr]


class _Slow:
    """A stream whose flush never ends within one wait (rerun's, its writer gone: it waited for ever by default)."""

    def __init__(self, rounds: int) -> None:
        self.rounds, self.waits = rounds, []

    def flush(self, timeout_sec: float = 1e38) -> None:
        self.waits.append(timeout_sec)
        if len(self.waits) <= self.rounds:
            raise RuntimeError("flush timed out")


def test_a_flush_waits_in_rounds_and_gives_up_on_a_writer_that_stopped(tmp_path: Path,
                                                                        monkeypatch: pytest.MonkeyPatch) -> None:
    """``seal localize --rrd`` onto a disk that filled up hung in rerun's flush, deaf to SIGTERM (hostile25): the
    flush now waits :data:`FLUSH_ROUND` at a time (an interrupt acts between), ends when rerun's does, says a full
    disk as one and gives up on a recording that no longer grows."""
    import errno

    import seal_cli.sefm.observers.rerun_scene as scene

    path = tmp_path / "r.rrd"
    path.write_bytes(b"x")
    slow = _Slow(2)
    scene.flush(slow, path)
    assert slow.waits == [scene.FLUSH_ROUND] * 3
    monkeypatch.setattr(scene, "FLUSH_STALL", 0.05)
    with pytest.raises(OSError, match="made no progress for 0.05 s"):
        scene.flush(_Slow(10**9), path)
    monkeypatch.setattr(scene, "cause", lambda _: errno.ENOSPC)
    with pytest.raises(OSError, match="No space left on device"):
        scene.flush(_Slow(10**9), path)
