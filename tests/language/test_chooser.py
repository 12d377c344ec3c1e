"""The discriminative chooser: features, fitting, and the weights grounding then uses."""

from __future__ import annotations

import math

import pytest

from seal_cli.frames.reading import Library
from seal_cli.language.chooser import Instance, features, fit, logits, room_weights
from seal_cli.language.grounding import Vocabulary
from seal_cli.language.parser import parse_command
from seal_cli.language.wordusage import WordUsage
from tests.language.test_parse_caches import plain_logits


def test_features_are_the_other_words_and_the_modifiers_but_no_candidate_s_name() -> None:
    said = features(("coffee", "cup"), {"put", "the", "coffee", "cup", "in", "pot", "machine"}, ("cup", "pot"))
    assert said == ("w:in", "w:machine", "w:put", "w:the", "m:coffee")


def _cups(n: int) -> list[Instance]:
    """Cups said beside "coffee" are mugs, beside "sink" cups; priors even (log 1 each)."""
    out = []
    for k in range(n):
        mug = k % 2 == 0
        said = features(("cup",), {"put", "coffee" if mug else "sink"})
        out.append(Instance(("cup", "mug"), (0.0, 0.0), int(mug), said))
    return out


def test_fit_learns_which_words_say_which_class() -> None:
    weights = fit(_cups(40), l2=1.0)
    z = logits(weights, ["cup", "mug"], features(("cup",), {"put", "coffee"}))
    assert z["mug"] > z["cup"] + 2
    z = logits(weights, ["cup", "mug"], features(("cup",), {"put", "sink"}))
    assert z["cup"] > z["mug"] + 2
    put = weights.get("w:put", {})                                # said with both: no evidence
    assert abs(put.get("cup", 0.0) - put.get("mug", 0.0)) < 0.01
    assert fit(_cups(40), l2=1.0) == weights                    # deterministic


def test_a_stronger_penalty_keeps_weights_smaller_and_rare_pairs_get_none() -> None:
    weak, strong = fit(_cups(40), l2=0.1), fit(_cups(40), l2=10.0)
    assert abs(strong["w:coffee"]["mug"]) < abs(weak["w:coffee"]["mug"])
    rare = [*_cups(10), Instance(("cup", "mug"), (0.0, 0.0), 0, ("w:once",))]
    assert "w:once" not in fit(rare, min_count=2)
    assert fit([Instance(("cup",), (0.0,), 0, ("w:a",))]) == {}   # one candidate: nothing to choose


def test_a_word_that_went_with_a_class_in_one_room_only_gets_no_weight() -> None:
    # every mug said beside "coffee" was said in its own room; the one room whose cups all stood in a "sink"
    # says more of that room than of the word "sink"
    cups = _cups(40)
    rooms = [f"kitchen{k}" if k % 2 == 0 else "the one kitchen" for k in range(len(cups))]
    spread = fit(cups, l2=1.0, groups=rooms, min_groups=2)
    assert "mug" in spread["w:coffee"]
    assert "cup" not in spread.get("w:sink", {})
    assert fit(cups, l2=1.0, groups=rooms, min_groups=0) == fit(cups, l2=1.0)    # 0: no room asked for
    with pytest.raises(ValueError, match="40 instances have 2 groups"):
        fit(cups, groups=["a", "b"], min_groups=2)


def test_a_room_that_said_a_word_many_times_counts_less_than_as_many_rooms() -> None:
    # one room said "island" four times (its dining table), two rooms once each (their counter tops)
    said = [("plan1", "island")] * 4 + [("plan2", "island"), ("plan3", "island"), ("plan1", "table")]
    w = room_weights(said, spread=2.0)
    assert w[0] == pytest.approx(3 / 6) and sum(w[:4]) == pytest.approx(2.0)    # (1 + 2) · 4 / (4 + 2)
    assert w[4] == w[5] == w[6] == pytest.approx(1.0)                           # said once: counts 1
    assert room_weights(said, spread=1e9) == pytest.approx([1.0] * 7)          # large spread: pooled
    with pytest.raises(ValueError, match="spread 0"):
        room_weights(said, spread=0)


def test_the_fit_weighs_each_instance_by_its_weight() -> None:
    # twenty "sink" cups from one room and one "sink" mug from another: weighed down to a few, the one room's
    # cups say less against the mug
    cups = [Instance(("cup", "mug"), (0.0, 0.0), 0, ("w:sink",)) for _ in range(20)]
    mug = Instance(("cup", "mug"), (0.0, 0.0), 1, ("w:sink",))
    pooled = fit([*cups, mug], l2=1.0)
    weighed = fit([*cups, mug], l2=1.0, weights=[0.1] * 20 + [1.0])
    lean = pooled["w:sink"]["cup"] - pooled["w:sink"].get("mug", 0.0)
    assert 0 < weighed["w:sink"]["cup"] - weighed["w:sink"].get("mug", 0.0) < lean
    assert fit([*cups, mug], l2=1.0, weights=[1.0] * 21) == pooled             # every weight 1: unweighed
    with pytest.raises(ValueError, match="as many weights"):
        fit([*cups, mug], weights=[1.0])
    with pytest.raises(ValueError, match="each above 0"):
        fit([*cups, mug], weights=[0.0] * 21)


def test_the_weights_decide_against_the_counts_prior(library: Library) -> None:
    usage = WordUsage({"cup": {"cup": 30, "mug": 20}}, frozenset({"cup", "mug", "coffee_machine", "sink"}),
                      weights={"w:coffee": {"mug": 1.5, "cup": -0.5}})
    vocab = Vocabulary.of(["Cup", "Mug", "CoffeeMachine", "Sink"]).with_usage(usage)
    coffee = parse_command("put the cup in the coffee machine", library, vocab)
    assert coffee.frames[-1].elements["theme"].cls == "Mug"          # 20 e^1.5 against 30 e^-0.5
    sink = parse_command("put the cup in the sink", library, vocab)
    assert sink.frames[-1].elements["theme"].cls == "Cup"
    factor = usage.sentence_factor("cup", ("cup",), ["cup", "mug"], {"coffee"})
    assert math.isclose(factor["mug"] / factor["cup"], math.exp(2.0))


def test_logits_are_the_same_sums_taken_key_by_key() -> None:
    import random

    rng = random.Random(46)
    classes = [f"c{k}" for k in range(30)]
    weights = {f"f{j}": {c: rng.uniform(-3, 3) for c in rng.sample(classes, rng.randint(0, 12))} for j in range(60)}
    for _ in range(300):
        keys = rng.sample(classes, rng.randint(0, 12))
        feats = [f"f{rng.randrange(80)}" for _ in range(rng.randint(0, 20))]       # some unknown, some twice
        found = logits(weights, keys, feats)
        assert found == plain_logits(weights, keys, feats)                      # equal floats, not close ones
        assert list(found) == list(dict.fromkeys(keys))
    assert logits(weights, ["c1", "c1"], []) == {"c1": 0.0}
