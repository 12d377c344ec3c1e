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


def test_the_picture_reads_as_the_table_does(tmp_path: Path, monkeypatch) -> None:  # type: ignore[no-untyped-def]
    """Axes in metres, a colour bar per frame, legends under the maps, ellipses clipped to their
    room, names that do not overlap, and the numbers of the table (issue 14)."""
    import matplotlib

    matplotlib.use("Agg")
    from matplotlib.figure import Figure
    from matplotlib.patches import Ellipse
    from matplotlib.text import Annotation

    from seal_cli.maps.drawing import LABEL
    from seal_cli.sefm.shown import rooms_text, share

    figures: list[Figure] = []
    real = Figure.savefig

    def keep(self: Figure, *args: object, **kwargs: object) -> None:
        figures.append(self)
        real(self, *args, **kwargs)

    monkeypatch.setattr(Figure, "savefig", keep)
    monkeypatch.setattr("matplotlib.pyplot.close", lambda *a: None)
    sefm = localise(load_map("apartment"), ["stir the cup"], rng=np.random.default_rng(0),
                    config=SeFMConfig(particles=300), observers=[PngDrawer(tmp_path / "b.png", dpi=60)])
    sefm.update((5.0, -3.0, 0.0))
    sefm.close()
    (fig,) = figures
    maps = [ax for ax in fig.axes if ax.get_xlabel() == "x (m)"]
    bars = [ax for ax in fig.axes if ax.get_ylabel() == "particle weight / heaviest"]
    assert len(maps) == 3 and len(bars) == 2  # objects, Pick, Stir; a colour bar for each frame
    renderer = fig.canvas.get_renderer()
    for ax in maps:
        assert any(t.get_text() for t in ax.get_xticklabels()) and any(t.get_text() for t in ax.get_yticklabels())
        legend = ax.get_legend()
        assert legend is not None and legend.get_window_extent(renderer).y1 <= ax.get_window_extent(renderer).y0
        names = [t for t in ax.texts if isinstance(t, Annotation) and t.get_gid() == LABEL]
        boxes = [t.get_window_extent(renderer) for t in names]
        clashes = sum(a.overlaps(b) for i, a in enumerate(boxes) for b in boxes[i + 1:])
        assert names and clashes <= len(names) // 10  # a few may touch on a crowded wall; most stand apart
    for i, ax in enumerate(maps[1:]):
        ellipses = [p for p in ax.patches if isinstance(p, Ellipse)]
        assert ellipses and all(e.get_clip_path() is not None for e in ellipses)
        written = sefm.frame_json(i)
        assert ax.get_title().split("\n")[1] == rooms_text(written["rooms"])
        weights = {t.get_text() for t in ax.texts if t.get_gid() != LABEL}
        assert {share(m["weight"]) for m in written["modes"]} <= weights
