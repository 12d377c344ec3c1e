"""scripts/rebuilt.py: a build script's ``--check`` names a shipped data file that is missing, unreadable, not
JSON (at its line and column) or stale, exits 1 and writes nothing; without it the file is written whole."""

from __future__ import annotations

import json
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2]
sys.path.insert(0, str(ROOT / "scripts"))

from rebuilt import write_or_check  # noqa: E402


def weights(shipped: object, built: object) -> list[str]:
    """A compare of the build scripts' kind: each number may move by 0.01, every key must be on both sides."""
    assert isinstance(shipped, dict) and isinstance(built, dict)
    one_side = sorted(set(shipped) ^ set(built))
    out = [f"/{k} only in the {'built' if k not in shipped else 'shipped'} file" for k in one_side]
    return out + [f"/{k}: {shipped[k]} shipped, {built[k]} built" for k in sorted(set(shipped) & set(built))
                  if abs(shipped[k] - built[k]) > 0.01]


def check(out: Path, text: str, capsys: pytest.CaptureFixture[str], compare: object = None) -> tuple[int, str]:
    status = write_or_check(out, text, check=True, made_from="the test's data", summary="-",
                            compare=compare)  # type: ignore[arg-type]
    captured = capsys.readouterr()
    return status, captured.err if status else captured.out


def test_a_file_is_written_whole_and_then_checks_up_to_date(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    out = tmp_path / "new" / "folder" / "table.tsv"
    assert write_or_check(out, "a\t1\n", check=False, made_from="x", summary="1 row") == 0
    assert capsys.readouterr().out == f"wrote {out} (1 row)\n"
    assert out.read_text() == "a\t1\n" and [p.name for p in out.parent.iterdir()] == ["table.tsv"]  # no temporary
    assert check(out, "a\t1\n", capsys) == (0, f"{out}: up to date\n")


def test_a_missing_or_stale_file_is_named_and_left_as_it_was(tmp_path: Path,
                                                              capsys: pytest.CaptureFixture[str]) -> None:
    out = tmp_path / "table.tsv"
    assert check(out, "a\t1\n", capsys) == (1, f"{out}: no such file (build it from the test's data)\n")
    assert not out.exists()
    out.write_text("a\t2\n")
    assert check(out, "a\t1\n", capsys) == (1, f"{out}: differs from what the test's data gives (rebuild it)\n")
    assert out.read_text() == "a\t2\n"


def test_a_json_file_is_compared_by_its_values(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    out = tmp_path / "model.json"
    out.write_text(json.dumps({"x": 0.21, "y": 1.0}, indent=4))
    assert check(out, json.dumps({"x": 0.215, "y": 1.0}), capsys, weights) == (0, f"{out}: up to date\n")
    status, said = check(out, json.dumps({"x": 0.25, "z": 1.0}), capsys, weights)
    assert status == 1 and said == (f"{out}: differs from what the test's data gives (rebuild it): /y only in the "
                                    "shipped file; /z only in the built file; /x: 0.21 shipped, 0.25 built\n")
    many = {f"w{i}": float(i) for i in range(8)}
    out.write_text(json.dumps(many))
    status, said = check(out, json.dumps({k: v + 1 for k, v in many.items()}), capsys, weights)
    assert status == 1 and said.count("shipped,") == 5 and said.endswith(" ... (3 more)\n")
    assert json.loads(out.read_text()) == many


@pytest.mark.parametrize(("content", "where"), [(b'{\n "x": 0.21,\n}', ":3:1: not JSON: Expecting property name"),
                                                (b"", ":1:1: not JSON: Expecting value")])
def test_a_file_that_is_not_json_is_named_at_its_line_and_column(tmp_path: Path, capsys: pytest.CaptureFixture[str],
                                                                 content: bytes, where: str) -> None:
    out = tmp_path / "model.json"
    out.write_bytes(content)
    status, said = check(out, json.dumps({"x": 0.21}), capsys, weights)
    assert status == 1 and said.startswith(f"{out}{where}") and said.endswith("(rebuild it)\n")
    assert out.read_bytes() == content


def test_an_unreadable_file_is_named(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    out = tmp_path / "model.json"
    out.write_bytes(b'{"x": "\xff"}')
    assert check(out, "{}", capsys, weights) == (1, f"{out}: cannot be read: not UTF-8 (rebuild it)\n")
    folder = tmp_path / "folder.json"
    folder.mkdir()
    assert check(folder, "{}", capsys) == (1, f"{folder}: cannot be read: Is a directory (rebuild it)\n")


def test_a_file_that_cannot_be_written_is_named_and_nothing_is_left(tmp_path: Path,
                                                                    capsys: pytest.CaptureFixture[str]) -> None:
    folder = tmp_path / "table.tsv"
    folder.mkdir()
    assert write_or_check(folder, "a\t1\n", check=False, made_from="x", summary="-") == 1
    said = capsys.readouterr().err
    assert said.startswith(f"error: {folder}: cannot be written: ") and "Traceback" not in said
    assert folder.is_dir() and list(tmp_path.iterdir()) == [folder]  # the temporary is gone
