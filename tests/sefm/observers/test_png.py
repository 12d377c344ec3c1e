"""sefm.observers.png: the picture of a run, written when the run finishes."""

from __future__ import annotations

from pathlib import Path

import numpy as np

from seal_cli.maps.formats.map_server import load_map
from seal_cli.pipeline import localise
from seal_cli.sefm.filter import SeFMConfig
from seal_cli.sefm.observers.png import PngDrawer

PNG_SIGNATURE = b"\x89PNG\r\n\x1a\n"


def test_the_picture_is_written_at_the_end_of_the_run(tmp_path: Path) -> None:
    path = tmp_path / "beliefs.png"
    drawer = PngDrawer(path, dpi=40)
    sefm = localise(load_map("apartment"), ["stir the cup"], rng=np.random.default_rng(0),
                    config=SeFMConfig(particles=40), observers=[drawer])
    sefm.update((5.0, -3.0, 0.0))
    assert not path.exists()                        # nothing is drawn before the run ends
    sefm.close()
    data = path.read_bytes()
    assert data.startswith(PNG_SIGNATURE)
    width, height = int.from_bytes(data[16:20], "big"), int.from_bytes(data[20:24], "big")
    assert width > height > 50                      # three panels (objects, Pick, Stir) side by side
    assert drawer.trace.poses == [(5.0, -3.0, 0.0)]
