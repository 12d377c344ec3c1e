"""sefm.shown: one way to write a share, for the table and the picture alike."""

from __future__ import annotations

import io
import json

import pytest
from typer.testing import CliRunner

from seal_cli.cli import app
from seal_cli.sefm.shown import modes_text, point, rooms_text, share


@pytest.mark.parametrize(("value", "text"), [(0.845, "0.85"), (0.8444, "0.84"), (0.8449, "0.85"),
                                             (0.125, "0.13"), (0.0044, "0.00"), (1.0, "1.00"), (0.995, "1.00")])
def test_a_share_is_rounded_half_up_from_what_json_writes(value: float, text: str) -> None:
    assert share(value) == text
    assert share(round(value, 3)) == text  # the raw number and the JSON's number read the same


def test_rooms_modes_and_points() -> None:
    assert rooms_text({"kitchen": 0.845, "hall": 0.15, "bath": 0.004, "attic": 0.001}) == "kitchen 0.85, hall 0.15"
    assert modes_text([{"weight": 0.605, "room": "bedroom"}]) == "0.61 bedroom"
    assert point([-6.025, 3.5]) == "(-6.03, 3.50)"


def test_the_localize_table_writes_the_json_numbers_by_the_same_formatter(monkeypatch) -> None:  # type: ignore[no-untyped-def]
    from rich.console import Console

    from seal_cli.cli import localize_cmd

    args = ["localize", "--map", "apartment", "--task", "stir the cup", "--steps", "3", "--particles", "200"]
    data = json.loads(CliRunner().invoke(app, [*args, "--json"]).output)
    wide = Console(width=400, record=True, file=io.StringIO())
    monkeypatch.setattr(localize_cmd, "out", wide)
    localize_cmd.show(data)
    table = wide.export_text()
    assert data["frames"]
    for frame in data["frames"]:
        assert rooms_text(frame["rooms"]) in table and modes_text(frame["modes"]) in table
