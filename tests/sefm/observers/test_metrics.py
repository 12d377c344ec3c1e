"""sefm.observers.metrics: the trace and the metrics gathered from a run, without changing it."""

from __future__ import annotations

import numpy as np
import pytest

from seal_cli.maps.formats.map_server import load_map
from seal_cli.pipeline import localise
from seal_cli.sefm.filter import SeFMConfig
from seal_cli.sefm.observers.metrics import Metrics, Trace, weight_colours


def test_weight_colours_run_from_dark_purple_to_yellow() -> None:
    colours = weight_colours(np.array([0.0, 0.5, 1.0]))
    assert colours.dtype == np.uint8 and colours.shape == (3, 3)
    assert colours[0].tolist() == [68, 1, 84] and colours[2].tolist() == [253, 231, 37]
    assert weight_colours(np.zeros(2)).tolist() == [[68, 1, 84]] * 2 and len(weight_colours(np.zeros(0))) == 0


def test_observers_record_every_update_and_change_nothing() -> None:
    apartment = load_map("apartment")
    config = SeFMConfig(particles=60)
    trace, metrics = Trace(), Metrics()
    watched = localise(apartment, ["stir the cup"], rng=np.random.default_rng(3), config=config,
                       observers=[trace, metrics])
    alone = localise(apartment, ["stir the cup"], rng=np.random.default_rng(3), config=config)
    poses = [(-6.0, -3.0, 0.0), (5.0, -3.0, 0.0)]
    for sefm in (watched, alone):
        for pose in poses:
            sefm.update(pose, [("spoon", (8.3, -4.1))] if pose[0] > 0 else [])
        sefm.close()
    assert np.array_equal(watched.frames.W, alone.frames.W) and np.array_equal(watched.objects.X, alone.objects.X)
    assert trace.poses == poses and trace.detections == [(), (("spoon", (8.3, -4.1)),)]
    assert [row["step"] for row in metrics.rows] == [0, 1, 2]
    last = metrics.rows[-1]
    assert set(last["frames"]) == set(watched.frame_ids) and "spoon" in last["objects"]
    for frame in last["frames"].values():
        assert sum(frame["rooms"].values()) == pytest.approx(1.0) and 0 < frame["ess"] <= 60
