"""``seal run`` takes a thing from the room the command names, or says there is none there (issue #11)."""

from __future__ import annotations

import json
from typing import Any

from typer.testing import CliRunner

from seal_cli.cli import app

runner = CliRunner()


def run(text: str) -> tuple[int, dict[str, Any]]:
    result = runner.invoke(app, ["run", "--map", "apartment", text, "--json", "--particles", "50"])
    return result.exit_code, json.loads(result.stdout)


def acts(report: dict[str, Any]) -> list[str]:
    return [r["text"] for r in report["records"] if r["kind"] == "act"]


def test_no_cup_in_the_kitchen_is_said_not_fetched_from_elsewhere() -> None:
    code, report = run("bring me a cup from the kitchen")
    assert code == 1 and not report["completed"]
    assert report["plan"][0] == "Pick(theme=cup, source=kitchen)"
    assert report["reason"] == "no cup in the kitchen" and report["why"] == "not_found"
    assert not [a for a in acts(report) if a.startswith(("picked", "handed"))]
    assert "opened fridge_1; inside: apple_1" in acts(report)  # it looked into what is closed there


def test_the_apple_from_the_kitchen_is_found_in_its_fridge() -> None:
    code, report = run("bring me the apple from the kitchen")
    assert code == 0 and report["completed"]
    assert "picked up apple_1 from fridge_1" in acts(report) and "handed apple_1 to me" in acts(report)


def test_a_room_holding_the_thing_and_a_named_place_are_taken_from() -> None:
    code, report = run("bring me the cup from the family room")
    assert code == 0 and "picked up cup_1 from coffee_table_1" in acts(report)
    code, report = run("take the cup from the coffee table to the kitchen")
    assert code == 0 and report["plan"][0] == "Pick(theme=cup, source=coffee_table_1)"
    assert "picked up cup_1 from coffee_table_1" in acts(report)
