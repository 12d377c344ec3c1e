"""``scripts/alfred_goal_errors.py``: a held-out goal sentence read wrong, classified by its first wrong field and
the cause the read-back, the labels and the word-class table show; a bad errors file or table named with its line."""

from __future__ import annotations

import json
import subprocess
import sys
from pathlib import Path
from types import ModuleType

from tests.conftest import module_from_file

ROOT = Path(__file__).resolve().parents[2]
SCRIPT = ROOT / "scripts" / "alfred_goal_errors.py"


def script() -> ModuleType:
    return module_from_file("alfred_goal_errors", SCRIPT)


WANT = {"type": "pick_cool_then_place_in_recep", "object": "butterknife", "receptacle": "sidetable", "mrecep": "",
        "sliced": False}
WORDS = {"knife": {"ButterKnife": 40, "Knife": 30, "Spoon": 1}, "table": {"DiningTable": 90, "SideTable": 60}}


def test_shared_wordings_need_both_classes_meant_often() -> None:
    shared = script().shared_words(WORDS)
    assert shared[frozenset(("butterknife", "knife"))] == "knife"
    assert frozenset(("knife", "spoon")) not in shared          # one slip of a label is no second meaning
    assert shared[frozenset(("diningtable", "sidetable"))] == "table"


def test_the_first_wrong_field_and_its_cause() -> None:
    m = script()
    shared = m.shared_words(WORDS)
    empty = {f: None for f in m.FIELDS}
    assert m.classify(["type", "object"], empty, WANT, shared) == ("any", "no parse", "")
    got = {**WANT, "type": "pick_and_place_simple", "object": "knife"}
    assert m.classify(["type", "object"], got, WANT, shared)[:2] == ("type", "step not read")
    got = {**WANT, "type": "pick_heat_then_place_in_recep"}
    assert m.classify(["type"], got, WANT, shared)[:2] == ("type", "another step read")
    got = {**WANT, "object": "knife"}
    assert m.classify(["object"], got, WANT, shared) == ("object", "one word, two classes",
                                                         "knife for butterknife ('knife')")
    assert m.classify(["receptacle"], {**WANT, "receptacle": ""}, WANT, shared) == (
        "receptacle", "nothing read", "sidetable")
    assert m.classify(["receptacle"], {**WANT, "receptacle": "fridge"}, WANT, shared)[1] == "another class"
    two = {**WANT, "type": "pick_two_obj_and_place"}
    assert m.classify(["type"], {**two, "type": "pick_and_place_simple"}, two, shared)[1] == "second thing not read"
    stack = {**WANT, "type": "pick_and_place_with_movable_recep", "mrecep": "pan"}
    assert m.classify(["type"], {**stack, "type": "pick_two_obj_and_place"}, stack, shared)[1] == \
        "stack read as two things"
    assert m.classify(["sliced"], {**WANT, "sliced": True}, WANT, shared)[1] == "slice read"


def test_the_table_of_causes_and_bad_files(tmp_path: Path) -> None:
    table = tmp_path / "t.json"
    table.write_text(json.dumps({"words": WORDS}))
    errors = tmp_path / "e.tsv"
    rows = [("object", "Put a knife on the side table.", {**WANT, "object": "knife"}),
            ("receptacle", "Cool a knife.", {**WANT, "receptacle": ""})]
    errors.write_text("".join(f"{f}\t{s}\t{json.dumps(g)}\t{json.dumps(WANT)}\n" for f, s, g in rows))
    run = subprocess.run([sys.executable, str(SCRIPT), str(errors), "--table", str(table), "--markdown"],
                         capture_output=True, text=True, check=True)
    assert "| object | one word, two classes | 1 | knife for butterknife ('knife') 1 |" in run.stdout
    assert "| all |  | 2 |" in run.stdout
    errors.write_text("object\tPut a knife.\tnot json\t{}\n")
    bad = subprocess.run([sys.executable, str(SCRIPT), str(errors), "--table", str(table)],
                         capture_output=True, text=True)
    assert bad.returncode == 1 and f"{errors}:1: not a line of --errors" in bad.stderr and "Traceback" not in bad.stderr
    table.write_text("{\n  \"words\": [\n")
    errors.write_text("")
    bad = subprocess.run([sys.executable, str(SCRIPT), str(errors), "--table", str(table)],
                         capture_output=True, text=True)
    assert bad.returncode == 1 and f"{table}:3:1: not JSON" in bad.stderr
