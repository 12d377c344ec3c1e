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
