"""pipeline: text → parse → ground → plan → SeFM (→ act), the same path the commands take."""

from __future__ import annotations

import numpy as np
import pytest

from seal_cli import pipeline
from seal_cli.errors import SealError
from seal_cli.frames.library import Library
from seal_cli.frames.reading import standard_library
from seal_cli.language.grounding import Vocabulary
from seal_cli.language.parser import parse_command
from seal_cli.maps.formats.map_server import load_map
from seal_cli.maps.model import Map
from seal_cli.planning import plan as planning
from seal_cli.planning.problem import problem_of_text
from seal_cli.sefm.filter import SeFM, SeFMConfig
from seal_cli.sim.policies import make_policy


@pytest.fixture(scope="module")
def apartment() -> Map:
    return load_map("apartment")


def steps(plan: planning.Plan) -> list[str]:
    return [str(step) for step in plan.steps]


def test_parse_uses_the_standard_library_unless_given_one(library: Library) -> None:
    text = "bring me a cup from the kitchen"
    assert pipeline.parse(text) == parse_command(text, standard_library()) == pipeline.parse(text, library)
    vocabulary = Vocabulary.of(["mug"], {"mug": ["cup"]})
    assert pipeline.parse(text, vocabulary=vocabulary).frames[0].elements["theme"].cls == "mug"


def test_an_empty_library_is_used_as_given_not_replaced() -> None:
    with pytest.raises(SealError):
        pipeline.parse("stir the cup", Library())


def test_plan_is_parse_ground_and_search(library: Library) -> None:
    result = pipeline.plan("stir the cup")
    problem = problem_of_text("stir the cup", library)
    assert result == planning.plan(problem.commanded, library, problem.state, text="stir the cup")
    assert steps(result) == ["Pick(theme=spoon)", "Stir(theme=cup, instrument=spoon)"]
    assert steps(pipeline.plan("stir the cup", holding="spoon")) == ["Stir(theme=cup, instrument=spoon)"]
    assert steps(pipeline.plan("stir the cup", done=["pick up the spoon"])) == ["Stir(theme=cup, instrument=spoon)"]
    with pytest.raises(SealError, match="1 node"):
        pipeline.plan("stir the cup", max_nodes=0)


def test_frames_to_localise_are_the_distinct_frames_of_every_task(library: Library, apartment: Map) -> None:
    bindings, state = pipeline.frames_to_localise(["stir the cup", "pick up the spoon"], library, apartment)
    assert [b.frame.name for b in bindings] == ["Pick", "Stir"]          # the second task's Pick is the first's
    assert any(f.predicate == "hand_empty" for f in state.facts)      # the apartment's robot holds nothing
    nothing, start = pipeline.frames_to_localise([], library, apartment, holding="spoon")
    assert nothing == [] and any(f.predicate == "holding" for f in start.facts)


def test_localise_builds_sefm_over_the_plans_frames(apartment: Map) -> None:
    sefm = pipeline.localise(apartment, ["stir the cup"], rng=np.random.default_rng(0),
                             config=SeFMConfig(particles=50))
    assert isinstance(sefm, SeFM) and [b.frame.name for b in sefm.bindings] == ["Pick", "Stir"]
    sefm.update(apartment.robot.pose)
    assert sefm.step == 1 and sum(sefm.frame_summary(1).rooms.values()) == pytest.approx(1.0)
    again = pipeline.localise(apartment, ["stir the cup"], rng=np.random.default_rng(0),
                              config=SeFMConfig(particles=50))
    again.update(apartment.robot.pose)
    assert np.array_equal(again.frames.X, sefm.frames.X)              # one generator: the same beliefs
    classes = pipeline.localise(apartment, [], rng=np.random.default_rng(0), config=SeFMConfig(particles=20))
    assert classes.bindings == () and set(classes.object_classes) >= {"spoon", "apple"}


def test_run_on_map_warns_of_a_condition_it_cannot_check(library: Library, apartment: Map) -> None:
    _, result = pipeline.run_on_map(apartment, "when the water boils, turn off the stove", library,
                                    make_policy("oracle"), rng=np.random.default_rng(0))
    assert result.completed and result.executed == ["ToggleOff(theme=stove_1)"]
    assert result.warnings == ["ToggleOff ('turn off') is said with the condition 'when the water boils', which "
                               "seal run cannot check: it carries the frame out now"]
    _, plain = pipeline.run_on_map(apartment, "turn off the stove", library, make_policy("oracle"),
                                   rng=np.random.default_rng(0))
    assert plain.warnings == []


def test_run_on_map_carries_out_the_command(library: Library, apartment: Map) -> None:
    agent, result = pipeline.run_on_map(apartment, "stir the cup", library, make_policy("oracle"),
                                        rng=np.random.default_rng(0))
    assert result.completed, result.reason
    assert result.executed[-1].startswith("Stir") and agent.held() is not None


def test_a_state_question_is_answered_by_looking_at_the_thing(library: Library, apartment: Map) -> None:
    """"is the fridge open?" / "could you check if the fridge is open": LookAt of the fridge with the
    state asked, not picked up, with no warning; whether it is open is what the map records, answered where the robot
    stands (e2e25, as "close the fridge" is); whether the stove is on, it goes and looks at."""
    for text in ("is the fridge open?", "could you check if the fridge is open"):
        agent, result = pipeline.run_on_map(apartment, text, library, make_policy("oracle"),
                                            rng=np.random.default_rng(0))
        assert result.completed and result.plan == ["LookAt(theme=fridge_1)"] and result.warnings == []
        assert result.answer == "no: fridge_1 is closed (as the map has it)" and result.path_m == 0.0
    _, on = pipeline.run_on_map(apartment, "is the stove still on?", library, make_policy("oracle"),
                                rng=np.random.default_rng(0))
    assert on.answer == "no: stove_1 is off"


def test_the_last_done_of_a_localization_without_a_task_is_named_when_refused(library: Library,
                                                                              apartment: Map) -> None:
    """``seal localize --done ...`` without ``--task`` reads its last ``--done`` as the command; a refusal there
    names the option all the same (hostile26: "column 1: control character U+0001 in the command")."""
    with pytest.raises(SealError, match=r"in --done '\\x01 go': control character U\+0001"):
        pipeline.frames_to_localise([], library, apartment, done=["go to the sofa", "\x01 go"])


def test_run_on_map_acts_in_the_house_the_done_commands_left(library: Library, apartment: Map) -> None:
    """e2e30: `seal run --done 'bring the cup to the table' 'put it back'` acted in the map as drawn, the cup on the
    coffee table: it found it "on coffee_table_1 already" and did nothing. Now the cup lies on the dining table, the
    robot fetches it from there and puts it back on the coffee table; a cup picked up is in its hand."""
    agent, result = pipeline.run_on_map(apartment, "put it back", library, make_policy("sefm", 100),
                                        rng=np.random.default_rng(0), done=["bring the cup to the table"])
    assert result.completed, result.reason
    assert result.executed == ["Pick(theme=cup, source=dining_table_1)", "Place(theme=cup, goal=coffee_table_1)"]
    assert agent.world.items["cup_1"].parent == "coffee_table_1"
    agent, result = pipeline.run_on_map(apartment, "give it to me", library, make_policy("sefm", 100),
                                        rng=np.random.default_rng(0), done=["pick up the cup"])
    assert result.completed and result.path_m == 0.0 and any("handed cup_1 to me" in r.text for r in agent.records)


def test_run_on_map_puts_back_a_thing_that_is_not_where_it_belongs(library: Library) -> None:
    """e2e30: "put the book back on the bookshelf" in the library: the robot saw a book on a bookshelf and said the
    frame needed no doing; "back" means one away from the bookshelves (the returns trolley's)."""
    agent, result = pipeline.run_on_map(load_map("library"), "put the book back on the bookshelf", library,
                                        make_policy("sefm", 100), rng=np.random.default_rng(0))
    assert result.completed, result.reason
    assert agent.world.items["book_1"].parent == "bookshelf_1" and result.executed[0] == "Pick(theme=book)"
    assert any("on a bookshelf already: takes a book that is not on one" in r.text for r in agent.records)


def test_run_on_map_says_the_source_a_thing_was_taken_from_when_not_the_one_said(library: Library) -> None:
    """e2e30: "fetch me a book from the study room", none there: the run said so and fetched one from a table, yet its
    step lines kept "source=study_room"; they name where it took the book from."""
    agent, result = pipeline.run_on_map(load_map("library"), "fetch me a book from the study room", library,
                                        make_policy("sefm", 100), rng=np.random.default_rng(0))
    assert result.completed, result.reason
    texts = [r.text for r in agent.records]
    assert any("no book in the study room, where the command said it was; looks elsewhere" in t for t in texts)
    done = [t for t in texts if t.startswith("done: ")]
    assert done and all("study_room" not in t for t in done) and "source=table_2" in done[0]


def test_a_done_command_s_pronoun_is_grounded_after_the_done_commands_before_it_in_the_run(library: Library,
                                                                                              apartment: Map) -> None:
    """e2e31: `seal run --done 'pick up the cup' --done 'put it on the table' 'bring it to me'` was refused ("cannot
    tell what 'it' refers to", column 5 of the second done command): the run grounded each done command alone, where
    the plan grounds each after the ones before it. Both now read "it" as the cup."""
    done = ["pick up the cup", "put it on the table"]
    assert [str(s) for s in pipeline.plan("bring it to me", library, map=apartment, done=done).steps] == [
        "Pick(theme=cup, source=dining_table_1)", "Bring(theme=cup, recipient=me)"]
    agent, result = pipeline.run_on_map(apartment, "bring it to me", library, make_policy("oracle"),
                                        rng=np.random.default_rng(0), done=done)
    assert result.completed, result.reason
    assert any(r.text == "handed cup_1 to me" for r in agent.records)


def test_the_things_done_commands_moved_are_known_where_they_were_left(library: Library) -> None:
    """e2e31: after `--done 'take the catalogue to Anna'` on the workshop, "where is the catalogue?" searched the
    showroom, the workshop, the finishing room and the kitchen by the prior (a counter, a table) and said none was
    found: the robot itself left it with Anna, in the office; it knows so, and goes there."""
    from seal_cli.sim.policies.sefm import SeFMPolicy

    m = load_map("workshop")
    world, _ = pipeline._after_done(m, [pipeline.parse_to_plan("take the catalogue to Anna", library)], library,
                                    None, m.known())
    assert pipeline.left_by_done(m, world) == ["catalogue_1"] and pipeline.left_by_done(m, m) == []
    agent, result = pipeline.run_on_map(m, "where is the catalogue?", library, SeFMPolicy(particles=50),
                                        rng=np.random.default_rng(0), done=["take the catalogue to Anna"])
    assert result.completed, result.reason
    assert "office" in (result.answer or "") and result.path_m < 10.0
