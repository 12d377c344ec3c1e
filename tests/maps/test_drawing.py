"""maps/drawing: names are drawn as written (hostile16)."""

from __future__ import annotations

from pathlib import Path

import pytest

from seal_cli.maps.drawing import save_map_png
from seal_cli.maps.formats.map_server import load_map
from seal_cli.resources import map_path


@pytest.mark.parametrize("name", ["$x^$", "$\\\\frac{$", "cost $5 or $6"])
def test_a_name_with_dollars_is_drawn_not_read_as_mathematics(tmp_path: Path, name: str) -> None:
    # the map's own name, drawn as the title (a room's or a person's can hold no '$' since hostile22)
    text = map_path("apartment").read_text(encoding="utf-8").replace("name: apartment", f'name: "{name}"', 1)
    (tmp_path / "apartment.pgm").write_bytes(map_path("apartment").with_suffix(".pgm").read_bytes())
    (tmp_path / "m.yaml").write_text(text, encoding="utf-8")
    save_map_png(load_map(tmp_path / "m.yaml"), tmp_path / "m.png")   # matplotlib's ParseSyntaxException before
    assert (tmp_path / "m.png").read_bytes().endswith(b"IEND\xaeB`\x82")
    import matplotlib

    assert matplotlib.rcParams["text.parse_math"]      # the setting is the picture's own, not the process's


def test_long_names_are_cut_on_the_picture_only() -> None:
    from seal_cli.maps.drawing import LEGEND_CHARS, NAME_CHARS, TITLE_CHARS, cut, cut_title

    assert cut("kitchen") == "kitchen" and cut("a" * NAME_CHARS) == "a" * NAME_CHARS
    assert cut("a" * 100) == "a" * (NAME_CHARS - 1) + "…" and len(cut("b" * 100, LEGEND_CHARS)) == LEGEND_CHARS
    assert cut_title("Find(theme=cup)\n" + "w" * 99 + " 0.50") == "Find(theme=cup)\n" + "w" * (TITLE_CHARS - 1) + "…"


def test_a_map_of_100_character_names_draws_them_cut_within_the_figure(tmp_path: Path) -> None:
    # hostile28: drawn whole, the names ran off the picture and over each other
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    from seal_cli.maps.drawing import LABEL, ROOM_CHARS, draw_map

    room, thing = "w" * 99, "a" * 98
    (tmp_path / "m.yaml").write_text(
        f"name: m\nbounds: [0, 0, 10, 10]\nrooms:\n  - {{name: {room}, box: [0, 0, 5, 10]}}\n"
        f"  - {{name: b{room}, box: [5, 0, 10, 10]}}\nplaces:\n  - {{name: {thing}_1, class: {thing}, at: [2, 5]}}\n",
        encoding="utf-8")
    fig, ax = plt.subplots(figsize=(9, 9))
    try:
        draw_map(ax, load_map(tmp_path / "m.yaml"))
        names = [t.get_text() for t in ax.texts if t.get_gid() == LABEL]
        assert names[:2] == ["w" * (ROOM_CHARS - 1) + "…", "b" + "w" * (ROOM_CHARS - 2) + "…"]
        assert all(len(n) <= 32 for n in names) and all(t.get_clip_on() for t in ax.texts[:2])
    finally:
        plt.close(fig)


def test_pictures_are_drawn_on_matplotlibs_own_defaults(monkeypatch: pytest.MonkeyPatch) -> None:
    """A ``matplotlibrc`` of the working folder set ``text.usetex`` (a traceback without LaTeX) or ``savefig.dpi:
    100000`` (out of memory) for seal's pictures (rel33): they are drawn on matplotlib's defaults."""
    import matplotlib

    from seal_cli.maps.drawing import text_as_written

    monkeypatch.setitem(matplotlib.rcParams, "text.usetex", True)
    monkeypatch.setitem(matplotlib.rcParams, "savefig.dpi", 100000)
    seen = text_as_written(lambda: (matplotlib.rcParams["text.usetex"], matplotlib.rcParams["savefig.dpi"],
                                    matplotlib.rcParams["text.parse_math"]))()
    assert seen == (False, matplotlib.rcParamsDefault["savefig.dpi"], False)
    assert matplotlib.rcParams["text.usetex"] is True          # the process's own settings are left as they were


def test_the_renderers_switches_are_set_for_files() -> None:
    from seal_cli.cli.output import own_renderers

    environ = {"MPLBACKEND": "junk", "RERUN": "off", "HOME": "/h"}
    own_renderers(environ)
    assert environ == {"MPLBACKEND": "agg", "HOME": "/h"}
