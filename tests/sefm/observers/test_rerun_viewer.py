"""A recording opened in Rerun's own viewer, headless: the layout is the blueprint's, the timeline is there,
and it paints. Needs a graphics adapter (a GPU, or Mesa's lavapipe: ``apt install mesa-vulkan-drivers``);
skipped cleanly without one (or with one it cannot render with), or without the ``rerun`` executable of the
rerun-sdk wheel."""

from __future__ import annotations

import io
import os
import shutil
import signal
import socket
import subprocess
import sys
import time
from collections.abc import Iterator
from pathlib import Path
from typing import Any

import numpy as np
import pytest

from seal_cli.frames.library import Library
from seal_cli.maps.formats.map_server import load_map
from seal_cli.planning.state import State, robot_facts
from seal_cli.resources import map_path
from seal_cli.sefm.filter import SeFM, SeFMConfig
from seal_cli.sefm.observers.rerun import RerunRecorder

rr = pytest.importorskip("rerun")
pytest.importorskip("rerun.experimental")

STARTUP_S = 90.0


def _rerun() -> str:
    found = Path(sys.executable).with_name("rerun")
    exe = str(found) if found.exists() else shutil.which("rerun")
    if exe is None:
        pytest.skip("no rerun executable")
    return exe


def _free_port() -> int:
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return int(s.getsockname()[1])


@pytest.fixture(scope="module")
def recording(tmp_path_factory: pytest.TempPathFactory, library: Library) -> Path:
    path = tmp_path_factory.mktemp("viewer") / "run.rrd"
    bindings = [library.frame("Pick").bind({"theme": "spoon"}), library.frame("Stir").bind({"theme": "cup"})]
    sefm = SeFM(load_map(map_path("apartment")), bindings, State.of(robot_facts(None), library.taxonomy),
                np.random.default_rng(0), SeFMConfig(particles=60), [RerunRecorder(path, stamps=[1.7e9, 1.7e9 + 0.5])])
    for pose in [(5.0, -4.5, 0.0), (7.0, -3.0, 0.0)]:
        sefm.update(pose, [("spoon", (8.3, -4.1))])
    sefm.close()
    return path


@pytest.fixture(scope="module")
def viewer(recording: Path) -> Iterator[tuple[Any, Any]]:
    from rerun.experimental import ViewerClient

    port = _free_port()
    process = subprocess.Popen([_rerun(), "--headless", "--port", str(port), "--window-size", "1280x720",
                                str(recording)], stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                               start_new_session=True)  # its own group: the wheel's launcher starts the viewer
    try:
        client, state, deadline = None, None, time.monotonic() + STARTUP_S
        while time.monotonic() < deadline:
            if process.poll() is not None:
                said = process.stdout.read().decode(errors="replace") if process.stdout else ""
                if "graphics adapter" in said or "DISPLAY" in said:
                    pytest.skip("the viewer needs a graphics adapter (none here)")
                if "Failed to get render context" in said:  # an adapter, but one it cannot paint with (GL llvmpipe)
                    pytest.skip("the viewer found no graphics adapter it can render with")
                pytest.fail(f"the viewer stopped ({process.returncode}): {said[-2000:]}")
            try:
                client = client or ViewerClient.connect(f"rerun+http://127.0.0.1:{port}/proxy")
                state = client.get_state()
                if state.views and state.recordings and not state.loading and _loaded(state):
                    break
            except Exception:  # not listening yet
                pass
            time.sleep(0.5)
        if state is None or not state.views or not _loaded(state):
            pytest.fail(f"the viewer had not shown the recording within {STARTUP_S:.0f} s: {state}")
        yield client, state
    finally:
        _stop(process)
        if process.stdout:
            process.stdout.close()


def _loaded(state: Any) -> bool:
    """Whether the recording has been read to its end (its last step is on the timeline)."""
    timelines = {t.name: t for r in state.recordings for t in r.timelines}
    return "step" in timelines and timelines["step"].end == 2 and "time" in timelines


def _stop(process: subprocess.Popen[bytes]) -> None:
    """The launcher and the viewer it started (the process group this test made)."""
    for sig, wait in ((signal.SIGTERM, 10), (signal.SIGKILL, 10)):
        try:
            os.killpg(process.pid, sig)
        except ProcessLookupError:
            break
        try:
            process.wait(timeout=wait)
            break
        except subprocess.TimeoutExpired:
            continue


def test_the_viewer_opens_the_default_layout(viewer: tuple[Any, Any]) -> None:
    _, state = viewer
    views = {v.name: (v.view_class, v.origin) for v in state.views}
    assert views == {"map apartment": ("2D", "/"), "room mass per frame": ("TimeSeries", "/metrics/rooms"),
                     "effective sample size": ("TimeSeries", "/metrics/ess")}
    (recording,) = state.recordings
    timelines = {t.name: t for t in recording.timelines}
    assert (timelines["step"].start, timelines["step"].end) == (0, 2)  # the prior and the two updates
    assert "time" in timelines  # the stamps (a bag's)


def test_the_viewer_paints_the_map(viewer: tuple[Any, Any]) -> None:
    """The occupancy image's free cells (254 grey) fill a good part of the map view once it has painted
    (a software rasteriser may take a few frames to upload the textures: asked again for up to 30 s)."""
    from PIL import Image

    client, _ = viewer
    share, deadline = 0.0, time.monotonic() + 30.0
    while time.monotonic() < deadline:
        picture = np.asarray(Image.open(io.BytesIO(client.take_screenshot())).convert("RGB"))
        assert picture.shape[0] > 100 and picture.shape[1] > 100
        share = float((picture == 254).all(axis=-1).mean())
        if share > 0.01:
            break
        time.sleep(1.0)
    assert share > 0.01
