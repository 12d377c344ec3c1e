"""The SayCan baseline: scorers, affordances, failure kinds, and its place in the task suite."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from seal_cli.errors import SealError
from seal_cli.frames.library import Library
from seal_cli.frames.reading import load_library
from seal_cli.sim.agent import Budget
from seal_cli.sim.policies import DEFAULT_POLICIES, make_policy
from seal_cli.sim.policies.saycan import SayCanPolicy
from seal_cli.sim.scorers import (
    DONE,
    BagOfWordsScorer,
    Example,
    ExampleScorer,
    example_slots,
    load_examples,
    next_step,
    prompt_for,
    read_examples,
    read_prompt,
)
from seal_cli.sim.skills import SkillResult, SkillRunner, failure_kinds, gold_instruction

DATA = Path(__file__).resolve().parents[3] / ".." / "shared" / "data" / "alfred2d"


@pytest.fixture(scope="module")
def library() -> Library:
    return load_library(None)


class Scripted:
    """A fake language model: the next step of a script when it is an option, else "explore"
    (or, with ``explore=False``, the script's step whether or not it is an option)."""

    def __init__(self, script: list[str], explore: bool = True) -> None:
        self.script = script
        self.explore = explore

    def score(self, prompt: str, options: list[str]) -> np.ndarray:
        _, history = read_prompt(prompt)
        done = [h for h in history if h in self.script]
        want = self.script[len(done)] if len(done) < len(self.script) else DONE
        if want not in options and self.explore:
            want = "explore"
        s = np.array([5.0 if o == want else 0.0 for o in options])
        return s - np.log(np.exp(s).sum())


def kitchen(library: Library):
    from seal_cli.maps.formats.map_server import load_map
    from seal_cli.sim.agent import scene_from_map

    return scene_from_map(load_map("apartment"), library)


def test_prompt_round_trips_and_the_scorer_returns_log_probabilities() -> None:
    prompt = prompt_for("heat the apple", ["go to the fridge", "pick up the apple"])
    assert read_prompt(prompt) == ("heat the apple", ["go to the fridge", "pick up the apple"])
    logp = BagOfWordsScorer().score(prompt, ["heat the apple with the microwave", "pick up the sofa", DONE])
    assert logp.shape == (3,) and np.isclose(np.exp(logp).sum(), 1.0)
    assert int(np.argmax(logp)) == 0   # the step that brings the history closer to the instruction
    again = BagOfWordsScorer().score(prompt, ["pick up the apple", "heat the apple with the microwave"])
    assert again[1] > again[0]         # what is done already is not asked for again
    with pytest.raises(SealError, match="no options"):
        BagOfWordsScorer().score(prompt, [])


def test_gold_instruction_reads_like_alfreds_templates() -> None:
    assert gold_instruction("pick_heat_then_place_in_recep", "Apple", "DiningTable") == \
        "heat the apple, then put it in the dining table"
    assert gold_instruction("pick_two_obj_and_place", "Book", "Desk", sliced=True).startswith("slice the book")


def test_runner_executes_the_language_models_choice_times_affordance(library: Library) -> None:
    scene = kitchen(library)
    cup = next(i for i in scene.world.items.values() if i.key == "cup")
    script = ["find the cup", "pick up the cup"]
    result = SkillRunner(scene, library, Scripted(script), rng=np.random.default_rng(0),
                         budget=Budget()).run("pick up the cup")
    assert result.completed and [h for h in result.history if not h.startswith("explored")] == script
    assert scene.world.robot.holding == cup.id
    assert result.never_seen == [] and failure_kinds(result, True) == []


def test_an_unafforded_first_choice_is_counted_and_not_executed(library: Library) -> None:
    scene = kitchen(library)
    runner = SkillRunner(scene, library, Scripted(["pick up the cup"], explore=False), rng=np.random.default_rng(0),
                         budget=Budget(steps=20))
    result = runner.run("pick up the cup")   # wanted before the cup is in view or in reach
    assert result.proposed_unafforded > 0    # counted ...
    assert result.failed_skills == 0         # ... but the affordance made it explore instead
    assert result.history[0] == "explored area 1"
    assert "unafforded action proposed" in failure_kinds(result, False)


def test_failure_kinds_name_what_went_wrong() -> None:
    early = SkillResult(True, "said done", 1.0, 3, ["go to the fridge"], proposed_unafforded=0,
                        never_seen=["apple"])
    assert failure_kinds(early, False) == ["done too early", "object never found"]
    spent = SkillResult(False, "out of steps", 1.0, 3, [], proposed_unafforded=2)
    assert failure_kinds(spent, False) == ["unafforded action proposed", "out of budget"]


def test_saycan_is_registered_but_not_run_by_default_and_refuses_the_agents_questions() -> None:
    assert "saycan" not in DEFAULT_POLICIES
    policy = SayCanPolicy(BagOfWordsScorer())
    assert policy.drives_itself
    with pytest.raises(SealError, match="instruction text"):
        policy.next_view(None, None, "cup")  # type: ignore[arg-type]


@pytest.mark.skipif(not DATA.is_dir(), reason="needs ../shared/data/alfred2d")
def test_the_task_suite_runs_saycan_on_the_same_episodes(library: Library, monkeypatch: pytest.MonkeyPatch) -> None:
    from seal_cli.bench import tasks
    from seal_cli.bench.alfred2d import load_suite

    suite = load_suite(DATA, "valid_seen", limit=1, types=["pick_and_place_simple"])
    monkeypatch.setattr("seal_cli.sim.policies.make_policy",
                        lambda name, particles=200: SayCanPolicy(BagOfWordsScorer()) if name == "saycan"
                        else make_policy(name, particles))
    first = tasks.run_episode(suite.episodes[0], suite, library, ["saycan", "oracle"], seed=3)
    again = tasks.run_episode(suite.episodes[0], suite, library, ["saycan"], seed=3)
    saycan = first[0]
    assert saycan.policy == "saycan" and saycan.commanded == ("put the book in the side table",)
    assert saycan.success or any(k in saycan.reason for k in ("done too early", "out of budget"))
    assert (saycan.success, saycan.steps, saycan.path_m) == (again[0].success, again[0].steps, again[0].path_m)
    assert first[1].policy == "oracle"


def test_wordllama_scores_offline() -> None:
    pytest.importorskip("wordllama")
    from seal_cli.sim.scorers import WordLlamaScorer

    logp = WordLlamaScorer.shared().score("put the apple in the fridge",
                                          ["put the apple in the fridge", "turn on the television", DONE])
    assert int(np.argmax(logp)) == 0 and np.isclose(np.exp(logp).sum(), 1.0)



BOX = Example("put the box in the dining table", ("find the box", "pick up the box", "go to the dining table",
                                                  "put the box in the dining table", DONE))
HEAT = Example("heat the egg, then put it in the fridge",
               ("find the egg", "pick up the egg", "go to the microwave", "heat the egg with the microwave",
                "go to the fridge", "open the fridge", "put the egg in the fridge", DONE))


def test_the_prompt_carries_worked_examples_in_saycans_shape() -> None:
    prompt = prompt_for("put the mug in the sink", ["find the mug"], [BOX])
    assert prompt.startswith("Human: put the box in the dining table\nRobot: find the box\n")
    assert prompt.endswith("\n\nHuman: put the mug in the sink\nRobot: find the mug")
    assert read_examples(prompt) == [BOX]
    assert read_prompt(prompt) == ("put the mug in the sink", ["find the mug"])
    assert example_slots(BOX) == ["box", "dining table"] and example_slots(HEAT) == ["egg", "fridge"]


def test_the_example_scorer_continues_the_examples_pattern_with_the_instructions_things() -> None:
    scorer = ExampleScorer(BagOfWordsScorer())
    options = ["find the mug", "find the sink", "go to the sink", "pick up the mug", "put the mug in the sink",
               "go to the microwave", DONE]
    best = []
    for history in ([], ["find the mug"], ["find the mug", "pick up the mug"],
                    ["find the mug", "pick up the mug", "go to the sink"],
                    ["find the mug", "pick up the mug", "go to the sink", "put the mug in the sink"]):
        logp = scorer.score(prompt_for("put the mug in the sink", history, [BOX, HEAT]), options)
        assert np.isclose(np.exp(logp).sum(), 1.0)
        best.append(options[int(np.argmax(logp))])
    assert best == ["find the mug", "pick up the mug", "go to the sink", "put the mug in the sink", DONE]
    heat = scorer.score(prompt_for("heat the mug, then put it in the sink", ["find the mug", "pick up the mug"],
                                   [BOX, HEAT]), options)
    assert options[int(np.argmax(heat))] == "go to the microwave"   # the example like it leads


def test_without_a_fitting_example_the_scorer_falls_back_to_progress() -> None:
    scorer = ExampleScorer(BagOfWordsScorer())
    prompt = prompt_for("put the mug in the sink", [], [])
    options = ["pick up the mug", "turn on the television", DONE]
    assert np.allclose(scorer.score(prompt, options), BagOfWordsScorer().score(prompt, options))


def test_next_step_skips_what_was_done_another_way_and_what_is_not_offered() -> None:
    steps = list(HEAT.steps)
    assert next_step(steps, []) == "find the egg"
    assert next_step(steps, ["pick up the egg"]) == "go to the microwave"          # found it on the way
    assert next_step(steps, ["find the egg", "pick up the egg", "go to the oven"]) == \
        "heat the egg with the microwave"                                            # same shape stands in
    assert next_step(steps, ["find the egg", "go to the sink"]) == "pick up the egg"   # not the next one's shape
    assert next_step(steps, ["find the egg", "go to the fridge"]) == "open the fridge"  # a later step: skipped to
    done = ["find the egg", "pick up the egg", "go to the microwave", "heat the egg with the microwave",
            "go to the fridge"]
    assert next_step(steps, done) == "open the fridge"
    assert next_step(steps, done, ["put the egg in the fridge", DONE]) == "put the egg in the fridge"


def test_mentions_are_word_for_word_longest_first_in_the_instructions_order() -> None:
    scorer = ExampleScorer(BagOfWordsScorer())
    names = ["knife", "butter knife", "apple", "dining table", "plate"]
    assert scorer.mentions("Put two apples on the plate, then slice them with the butter knife", names) == \
        ["apple", "plate", "butter knife"]
    assert scorer.mentions("put it on the table", names) == ["dining table"]   # the embedding's nearest name
    assert scorer.mentions("open the window", names) == []


def test_the_shipped_examples_come_from_train_and_end_with_done() -> None:
    examples = load_examples()
    assert len(examples) >= 20
    assert all(e.steps[-1] == DONE and example_slots(e) for e in examples)
    kinds = {e.instruction.split()[0] for e in examples}
    assert {"look", "put", "heat", "cool", "clean", "slice"} <= kinds


@pytest.mark.skipif(not DATA.is_dir(), reason="needs ../shared/data/alfred2d")
def test_the_shipped_examples_are_rebuilt_from_train_and_none_is_a_sampled_or_valid_episode() -> None:
    import json
    import subprocess
    import sys

    root = Path(__file__).resolve().parents[3]
    check = subprocess.run([sys.executable, str(root / "scripts" / "build_saycan_examples.py"), "--check",
                            "--data", str(DATA)], capture_output=True, text=True)
    assert check.returncode == 0, check.stdout + check.stderr
    from seal_cli.bench.alfred2d import load_suite

    trials = {e["trial"] for e in json.loads((root / "seal_cli" / "bench" / "suites" /
                                              "saycan_examples.json").read_text())["examples"]}
    sampled = {e.task_id for e in load_suite(DATA, "train", sample=3, with_priors=False).episodes}
    valid = {e.task_id for e in load_suite(DATA, "valid_seen", with_priors=False).episodes}
    assert trials and not trials & sampled and not trials & valid


def test_load_examples_names_a_bad_file(tmp_path: Path) -> None:
    with pytest.raises(SealError, match="no worked examples"):
        load_examples(tmp_path / "absent.json")
    bad = tmp_path / "bad.json"
    bad.write_text('{"examples": [{"instruction": "x"}]}')
    with pytest.raises(SealError, match="not a file of worked examples"):
        load_examples(bad)


def test_find_goes_to_a_seen_thing_or_searches_and_put_down_needs_somewhere_open(library: Library) -> None:
    scene = kitchen(library)
    runner = SkillRunner(scene, library, BagOfWordsScorer(), rng=np.random.default_rng(0), budget=Budget())
    runner.agent.policy.begin(runner.agent)
    runner._look()
    outcome = runner.find("cup")            # not in view at the start: it explores until one is seen
    assert outcome.ok and scene.world.items[runner.focus].key == "cup"
    assert scene.world.within_reach(runner.focus) and scene.world.robot.path_m > 0
    assert scene.world.act("pick", runner.focus).ok
    find = next(s for s in runner.candidates() if s.text == "find the cup")
    assert find.affordance < 1               # the hand holds one
    down = next(s for s in runner.candidates() if s.text == "put down the cup")
    if down.affordance == 1:
        assert runner.execute(down).ok and scene.world.robot.holding is None
        assert down.args[1] in runner.placed or scene.world.items[down.args[0]].parent == down.args[1]


@pytest.mark.skipif(not DATA.is_dir(), reason="needs ../shared/data/alfred2d")
def test_saycan_with_wordllama_and_the_examples_does_a_pick_and_place(library: Library) -> None:
    pytest.importorskip("wordllama")
    from seal_cli.bench import tasks
    from seal_cli.bench.alfred2d import load_suite

    suite = load_suite(DATA, "valid_seen", limit=1, types=["pick_heat_then_place_in_recep"])
    outcome = tasks.run_episode(suite.episodes[0], suite, library, ["saycan"], seed=0)[0]
    assert outcome.success, outcome.reason


def test_going_to_a_room_ends_inside_it_unless_a_thing_is_to_be_put_down_there(library: Library) -> None:
    """"go to the kitchen" with empty hands drives into the kitchen near its middle (as the agent's Go does),
    not to its nearest appliance; holding a thing, to where such a thing is put there, within reach of it."""
    scene = kitchen(library)
    runner = SkillRunner(scene, library, Scripted(["go to the kitchen"]), rng=np.random.default_rng(0),
                         budget=Budget())
    result = runner.run("go to the kitchen")
    assert "go to the kitchen" in result.history
    agent = runner.agent
    kitchen_room = agent.room("kitchen")
    x, y = scene.world.robot.pose[:2]
    assert bool(kitchen_room.contains([(x, y)])[0])
    cx, cy = kitchen_room.centroid
    assert np.hypot(x - cx, y - cy) < 1.5     # near the middle (5.5, -3.0), not by the sink or the fridge
    assert any("goes to the kitchen (near its middle)" in r.text for r in agent.records)
