"""The shipped word-class table is what ``scripts/build_word_classes.py`` gives on ALFRED's train split:
a change to the parser or the chooser that shifts a count must ship the rebuilt table with it."""

from __future__ import annotations

import json
import subprocess
import sys
from pathlib import Path
from types import ModuleType
from typing import Any

from seal_cli.language.wordusage import SHIPPED
from tests.conftest import check_on_a_sample, module_from_file

ROOT = Path(__file__).resolve().parents[2]
SCRIPT = ROOT / "scripts" / "build_word_classes.py"


def builder() -> ModuleType:
    return module_from_file("build_word_classes", SCRIPT)


def test_a_fitted_weight_may_move_in_its_third_decimal_but_no_count_may_change() -> None:
    diff = builder().differences
    assert diff({"weights": {"w:a": {"Cup": 0.221}}}, {"weights": {"w:a": {"Cup": 0.222, "Mug": -0.004}}}) == []
    assert diff({"weights": {"w:a": {"Cup": 0.221}}}, {"weights": {"w:a": {"Cup": 0.24}}}) != []
    assert diff({"words": {"cup": {"Cup": 3}}}, {"words": {"cup": {"Cup": 4}}}) == [
        "/words/cup/Cup: 3 shipped, 4 built"]
    assert diff({"words": {"cup": {"Cup": 3}}}, {"words": {}}) == ["/words/cup only in the shipped table"]
    assert diff({"scenery": ["a", "b"]}, {"scenery": ["a"]}) != []


def test_the_shipped_table_is_what_the_train_split_gives(rebuilt_word_classes: Path) -> None:
    shipped = (SHIPPED / "alfred_train.json").read_text()
    stale = builder().differences(json.loads(shipped), json.loads(rebuilt_word_classes.read_text()))
    assert not stale, f"the shipped table is stale ({stale[:3]}): run python scripts/build_word_classes.py"


def test_check_names_a_table_the_data_no_longer_gives_and_writes_nothing(shared_data: Path, tmp_path: Path) -> None:
    def stale(table: dict[str, Any]) -> str:
        wording, counts = next(iter(table["words"].items()))
        counts[next(iter(counts))] += 1
        return f"/words/{wording}/"
    check_on_a_sample(SCRIPT, shared_data, tmp_path, stale)


def test_a_missing_data_folder_is_named(tmp_path: Path) -> None:
    done = subprocess.run([sys.executable, str(SCRIPT), "--check", "--data", str(tmp_path)],
                          capture_output=True, text=True, timeout=60)
    assert done.returncode == 1
    assert str(tmp_path / "alfred" / "goals_train.tsv") in done.stderr and "Traceback" not in done.stderr


def test_train_trials_or_whole_floor_plans_are_held_out() -> None:
    held_out = builder().held_out
    rows = [{"task_id": f"trial_{k}", "floor_plan": f"FloorPlan{k % 30}"} for k in range(600)]
    trials = held_out(rows, 0.2)
    plans = held_out(rows, 0.2, "floor-plans")
    assert 60 < len(trials) < 180 and 0 < len(plans) < 600
    fitted = {r["floor_plan"] for r in rows if r["task_id"] not in plans}
    assert not fitted & {r["floor_plan"] for r in rows if r["task_id"] in plans}     # no room seen on both sides
    assert fitted & {r["floor_plan"] for r in rows if r["task_id"] in trials}       # held-out trials share rooms


def test_where_a_stack_s_container_went_is_learned_from_the_stacks_that_do_not_say_it() -> None:
    module = builder()
    from seal_cli.language.grounding import Vocabulary
    from seal_cli.language.wordusage import FORMAT

    classes = ["Tomato", "Apple", "Pan", "Bowl", "CounterTop", "DiningTable", "Fridge"]
    data = {"format": FORMAT, "source": "test", "classes": classes, "words": {}}
    stack = "pick_and_place_with_movable_recep"
    rows = [{"task_type": stack, "receptacle": "CounterTop", "goal_sentence": "put a tomato in a pan"},
            {"task_type": stack, "receptacle": "CounterTop", "goal_sentence": "put the apple in the pan"},
            {"task_type": stack, "receptacle": "DiningTable", "goal_sentence": "put an apple in a bowl"},
            {"task_type": stack, "receptacle": "DiningTable", "goal_sentence": "put a tomato in the bowl"},
            {"task_type": stack, "receptacle": "Fridge",                       # its place said: not counted
             "goal_sentence": "put an apple in a bowl and put the bowl in the fridge"},
            {"task_type": "pick_and_place_simple", "receptacle": "Fridge",    # no stack: not counted
             "goal_sentence": "put an apple in a bowl"},
            {"task_type": stack, "receptacle": "Fridge", "goal_sentence": "put an apple in the fridge"}]  # no container
    built = module.with_stack_goals(data, rows, Vocabulary.of(classes))
    assert built["stack_goal_prior"] == {"CounterTop": 2, "DiningTable": 2}
    weights = built["stack_goal_weights"]
    assert weights["o:bowl"]["DiningTable"] > weights["o:pan"]["DiningTable"]        # the container weighs


def test_scenery_is_the_floor_plans_classes_no_task_names_and_may_be_of_some_floor_plans_only(tmp_path: Path) -> None:
    plans = {"FloorPlan1": {"object_types": ["Apple", "Faucet"], "receptacles": [{"class": "Sink"}]},
             "FloorPlan2": {"object_types": ["Mug"], "receptacles": [{"class": "ShowerHead"}]}}
    (tmp_path / "alfred2d").mkdir()
    (tmp_path / "alfred2d" / "floorplans.json").write_text(json.dumps({"floor_plans": plans}))
    scenery = builder().scenery
    assert scenery(tmp_path, ["Apple", "Mug", "Sink"]) == ["Faucet", "ShowerHead"]
    assert scenery(tmp_path, ["Apple", "Mug", "Sink"], {"FloorPlan2"}) == ["ShowerHead"]
    assert scenery(tmp_path / "nowhere", ["Apple"]) == []
