"""`seal frames` on a library of one frame: the table's title counts it right."""

from __future__ import annotations

from pathlib import Path

from typer.testing import CliRunner

from seal_cli.cli import app

runner = CliRunner()

STIR = """frame Stir "stir" "mix" {
  theme: container
  instrument: utensil = spoon
  requires holding(instrument)
  do navigate(theme), stir(instrument, theme)
  ensures stirred(theme)
}
category utensil = spoon, fork, ladle
category container = cup, mug, bowl
world hand_empty, holding
"""


def test_a_library_of_one_frame_is_titled_one_frame(tmp_path: Path) -> None:
    library = tmp_path / "stir.frame"
    library.write_text(STIR, encoding="utf-8")
    result = runner.invoke(app, ["frames", "--framelib", str(library)])
    assert result.exit_code == 0, result.output
    assert result.stdout.splitlines()[0].strip() == "1 frame"
    assert runner.invoke(app, ["frames"]).stdout.splitlines()[0].strip() == "25 frames"
