"""``scripts/chooser_features.py``: the chooser's candidate features, read off a phrase as the experiment reads them,
and its instances built from a split's counts as the shipped chooser's are (the phrase left out of its prior)."""

from __future__ import annotations

import sys
from pathlib import Path
from types import ModuleType

from seal_cli.frames.taxonomy import class_key
from tests.conftest import module_from_file

ROOT = Path(__file__).resolve().parents[2]
SCRIPT = ROOT / "scripts" / "chooser_features.py"


def experiment() -> ModuleType:
    sys.path.insert(0, str(ROOT / "scripts"))
    return module_from_file("chooser_features", SCRIPT)


def said(label: str, dev: bool = False) -> dict[str, object]:
    return {"lemmas": ("knife",), "label": label, "words": frozenset({"put", "the", "knife", "in", "sink", "butter"}),
            "text": "put the knife in the big sink", "phrase": "the knife", "field": "object", "dev": dev,
            "frames": ["Place"], "classes": ["SinkBasin"], "plan": "FloorPlan1", "scene": "kitchen"}


def test_each_feature_set_adds_its_own_features_to_the_shipped_ones() -> None:
    sets = experiment().SETS
    candidates = (class_key("ButterKnife"), class_key("Knife"))
    shipped = sets["shipped"](said("Knife"), candidates)
    assert "w:sink" in shipped and "w:butter" not in shipped          # a word of a candidate's name is none
    assert set(sets["near"](said("Knife"), candidates)) - set(shipped) == {"n:put", "n:in", "n:the", "n:big"}
    assert "b:big_sink" in sets["pairs"](said("Knife"), candidates)
    assert "c:sink_basin" in sets["classes"](said("Knife"), candidates)
    assert "f:Place" in sets["frames"](said("Knife"), candidates)
    assert sets["field"](said("Knife"), candidates)[-1] == "e:object"
    assert sets["room"](said("Knife"), candidates)[-1] == "r:kitchen"


def test_instances_leave_the_phrase_out_of_its_prior_and_need_two_classes() -> None:
    module = experiment()
    from collections import Counter

    counts = {"knife": Counter({"ButterKnife": 3, "Knife": 1})}
    made = module.instances([said("ButterKnife")], counts, module.SETS["shipped"], True)
    assert len(made) == 1 and made[0][1].candidates == ("butter_knife", "knife")
    assert [round(o, 3) for o in made[0][1].offsets] == [0.693, 0.0]          # log 2, log 1: itself left out
    assert module.instances([said("Knife")], counts, module.SETS["shipped"], True) == []   # one class left
    assert module.instances([said("Knife")], counts, module.SETS["shipped"], False)[0][1].label == 1


def test_each_instance_is_weighed_by_its_room_and_the_wording_it_was_counted_under() -> None:
    module = experiment()
    from collections import Counter

    counts = {"knife": Counter({"ButterKnife": 3, "Knife": 2})}
    made = module.instances([said("ButterKnife"), said("Knife"), {**said("Knife"), "plan": "FloorPlan2"}], counts,
                            module.SETS["shipped"], True)
    assert module.rooms(made) == [("FloorPlan1", "knife"), ("FloorPlan1", "knife"), ("FloorPlan2", "knife")]
