"""The task fields a whole sentence says: read off a parse as the scorer reads them, weighed by a model of the
sentence's words, combined with the parser's reading, and written back into the parse (a class changed, or the
frames written anew and marked inferred); only with the shipped statistics, where they know the vocabulary."""

from __future__ import annotations

import json
import math
from pathlib import Path

import pytest

from seal_cli.errors import SealError
from seal_cli.frames.library import Library
from seal_cli.language.grounding import Vocabulary
from seal_cli.language.parser import parse_command
from seal_cli.language.taskfields import (
    NOTHING,
    FieldModel,
    Reading,
    candidates,
    combine,
    fit_fields,
    fit_trust,
    fit_trust_count,
    load_field_model,
    model_json,
    read_fields,
    reread,
    score,
    sentence_grams,
    shipped_field_model,
    sliced_probability,
)
from seal_cli.language.wordusage import WordUsage

ROOM = ("Apple", "Fridge", "Microwave", "CounterTop", "DiningTable", "SideTable", "Mug", "Pan", "DeskLamp", "Knife",
        "ButterKnife", "Bread")
SIMPLE = "pick_and_place_simple"
COOL = "pick_cool_then_place_in_recep"
STACK = "pick_and_place_with_movable_recep"
LOOK = "look_at_obj_in_light"
PRIORS = {"type": {SIMPLE: 50, COOL: 20, STACK: 10, LOOK: 10},
          "object": {"apple": 30, "mug": 30, "knife": 10, "butter_knife": 10, "bread": 10},
          "receptacle": {"fridge": 10, "microwave": 10, "counter_top": 20, "dining_table": 20, "side_table": 10,
                         NOTHING: 10},
          "mrecep": {NOTHING: 80, "pan": 10, "mug": 10}}
MODEL = FieldModel(PRIORS, {"type": {"u:frosty": {COOL: 6.0}, "u:lamp": {LOOK: 6.0}},
                            "object": {"b:butter_knife": {"butter_knife": 8.0}},
                            "receptacle": {"u:bedroom": {"side_table": 6.0}, "u:couch": {"sofa": 9.0}},
                            "mrecep": {}},
                   {"type": 2.0, "object": 3.0, "receptacle": 2.0, "mrecep": 1.5})


def rules(classes: tuple[str, ...] = ROOM) -> Vocabulary:
    """The rules' grounding, with what people meant by "table" (no universe: the counts never override a class)."""
    return Vocabulary.of(classes, usage=WordUsage({"table": {"dining_table": 300, "side_table": 200, "sofa": 2},
                                                "glass": {"cup": 90, "butter_knife": 1}}))


def parsed(text: str, library: Library) -> tuple[Vocabulary, object]:
    vocabulary = rules()
    return vocabulary, parse_command(text, library, vocabulary, infer_steps=False)


def test_a_sentence_s_features_are_its_words_and_their_pairs() -> None:
    assert sentence_grams("Chill an apple.") == ("b:<s>_chill", "b:an_apple", "b:apple_</s>", "b:chill_an",
                                                 "u:an", "u:apple", "u:chill")


def test_the_fields_are_read_as_the_scorer_reads_them(library: Library) -> None:
    _, parse = parsed("put the mug in the microwave", library)
    reading = read_fields(parse)
    assert (reading.type, dict(reading.values)) == (SIMPLE, {"object": "mug", "receptacle": "microwave",
                                                             "mrecep": NOTHING})
    _, parse = parsed("chill the apple and put it on the counter", library)
    reading = read_fields(parse)
    assert reading.type == COOL and reading.values["object"] == "apple"
    assert reading.at["object"] is not None and parse.frames[reading.at["object"][0]].frame == "Cool"
    _, parse = parsed("put the apple in the pan and put the pan in the fridge", library)
    assert read_fields(parse).type == STACK and read_fields(parse).values["mrecep"] == "pan"


def test_the_parser_s_reading_stands_unless_the_words_outweigh_its_trust(library: Library) -> None:
    vocabulary, parse = parsed("put the apple in the fridge", library)
    reading = read_fields(parse)
    plain, _ = combine(MODEL, sentence_grams("put the apple in the fridge"), reading, vocabulary.by_key)
    assert plain == {"type": SIMPLE, "object": "apple", "receptacle": "fridge", "mrecep": NOTHING}
    chilled, p = combine(MODEL, sentence_grams("put the frosty apple in the fridge"), reading, vocabulary.by_key)
    assert chilled["type"] == COOL and p > 0.5
    blind = FieldModel(PRIORS, MODEL.weights, {"type": 0.0, "object": 0.0, "receptacle": 0.0, "mrecep": 0.0})
    assert combine(blind, (), reading, vocabulary.by_key)[0]["object"] == "apple"     # a tie (30, 30): the parser's
    assert combine(blind, (), reading, ("mug", "fridge"))[0]["object"] == "mug"       # only classes present


def test_a_class_the_words_say_replaces_the_parser_s_and_keeps_its_words(library: Library) -> None:
    text = "put the mug on the table in the bedroom"
    vocabulary, parse = parsed(text, library)
    before = read_fields(parse)
    assert before.type == SIMPLE and before.values["receptacle"] in ("dining_table", "side_table")
    after = reread(parse, library, vocabulary, MODEL, text)
    goal = after.frames[before.at["receptacle"][0]].elements["goal"]
    assert goal.cls == "SideTable" and goal.head == "table"
    assert [f.frame for f in after.frames] == [f.frame for f in parse.frames]
    assert all(f.inferred is None for f in after.frames)
    text = "put the mug on the table by the couch"       # the sofa is likelier, but "table" meant it twice in 502
    vocabulary, parse = parsed(text, library)
    assert reread(parse, library, vocabulary, MODEL, text) == parse


def test_a_phrase_the_rules_ground_to_nothing_takes_no_class_people_never_meant_by_its_word(library: Library) -> None:
    text = "put the glass in the fridge"             # people meant a cup, none here (a butter knife once in 91)
    vocabulary, parse = parsed(text, library)
    assert read_fields(parse).values["object"] == NOTHING
    assert reread(parse, library, vocabulary, MODEL, text) == parse


def test_another_type_writes_the_frames_anew_marked_inferred(library: Library) -> None:
    text = "put the frosty apple on the counter"
    vocabulary, parse = parsed(text, library)
    after = reread(parse, library, vocabulary, MODEL, text)
    assert [f.frame for f in after.frames] == ["Pick", "Cool", "Place"]
    assert all(f.inferred is not None and f.inferred > 0.5 for f in after.frames)
    reading = read_fields(after)
    assert (reading.type, reading.values["object"], reading.values["receptacle"]) == (COOL, "apple", "counter_top")
    assert after.resolve(after.frames[2].elements["theme"]).text == parse.resolve(
        parse.frames[-1].elements["theme"]).text


def test_a_look_drops_the_receptacle(library: Library) -> None:
    text = "put the apple by the lamp"
    vocabulary, parse = parsed(text, library)
    after = reread(parse, library, vocabulary, MODEL, text)
    assert [f.frame for f in after.frames] == ["Pick", "LookAt"]
    assert read_fields(after).type == LOOK


def test_an_empty_model_or_no_frames_changes_nothing(library: Library) -> None:
    vocabulary, parse = parsed("put the frosty apple on the counter", library)
    assert reread(parse, library, vocabulary, FieldModel(), "put the frosty apple on the counter") is parse
    text = "put the frosty apple on the counter and find the mug"      # a frame no task field holds: kept as said
    vocabulary, parse = parsed(text, library)
    assert reread(parse, library, vocabulary, MODEL, text) == parse
    assert not FieldModel() and MODEL


def test_the_model_is_learned_from_labelled_sentences() -> None:
    rows = [{"goal_sentence": s, "task_type": t, "object": "Apple", "receptacle": "Fridge", "mrecep": ""}
            for s, t in [("chill an apple", COOL), ("put a chilled apple away", COOL), ("cool the apple", COOL),
                         ("chill the apple now", COOL), ("put an apple in the fridge", SIMPLE),
                         ("move the apple to the fridge", SIMPLE), ("place an apple", SIMPLE)]]
    model = fit_fields(rows)
    assert model.priors["type"] == {COOL: 4, SIMPLE: 3} and model.priors["mrecep"] == {NOTHING: 7}
    p = model.probabilities("type", sentence_grams("chill it"))
    assert p[COOL] > 4 / 7
    assert load_field_model_of(model_json(model, "test")) == model


def test_a_room_that_had_one_value_in_many_tasks_counts_as_fewer_when_its_sentences_are_weighed() -> None:
    # one floor plan says "table" for its dining table in twelve tasks; two others say it for their side tables
    dining = [{"goal_sentence": f"put the apple on the table {k}", "task_type": SIMPLE, "object": "Apple",
               "receptacle": "DiningTable", "mrecep": "", "floor_plan": "FloorPlan1"} for k in range(12)]
    side = [{"goal_sentence": f"put the book on the table {k}", "task_type": SIMPLE, "object": "Book",
             "receptacle": "SideTable", "mrecep": "", "floor_plan": f"FloorPlan30{k % 3}"} for k in range(3)]
    pooled, weighed = fit_fields(dining + side), fit_fields(dining + side, spread=1.0)
    assert pooled.priors == weighed.priors                          # the prior stays the tasks' count
    grams = sentence_grams("put it on the table")

    def lean(model: FieldModel) -> float:
        p = model.probabilities("receptacle", grams)
        return p["dining_table"] / p["side_table"]

    assert lean(weighed) < lean(pooled)
    assert fit_fields(dining + side, spread=1e9) == pooled            # a spread that large: each sentence counts 1


def load_field_model_of(text: str) -> FieldModel:
    import tempfile

    with tempfile.TemporaryDirectory() as folder:
        path = Path(folder) / "m.json"
        path.write_text(text)
        return load_field_model(path)


def test_a_file_that_is_no_model_is_named(tmp_path: Path) -> None:
    bad = tmp_path / "bad.json"
    bad.write_text("{\n  oops")
    with pytest.raises(SealError) as err:
        load_field_model(bad)
    assert str(bad) in str(err.value) and ":2:" in str(err.value)
    bad.write_text(json.dumps({"format": "seal-task-fields-1", "priors": {}}))
    with pytest.raises(SealError, match="not a task-field model"):
        load_field_model(bad)


def test_only_the_shipped_statistics_on_alfred_s_classes_reread(library: Library) -> None:
    shipped = shipped_field_model()
    assert shipped and set(shipped.priors["type"]) >= {SIMPLE, COOL, STACK, LOOK}
    assert Vocabulary.of(ROOM).field_model is shipped
    assert not rules().field_model                                            # statistics given: off
    assert not Vocabulary.of(("Apple", "Fridge", "SpaceShuttle")).field_model    # a class ALFRED never had
    house = Vocabulary(Vocabulary.of(ROOM).classes, house=True)
    assert not house.field_model


def reading_of(kind: str | None, obj: str = NOTHING, unsaid: frozenset[str] = frozenset()) -> Reading:
    return Reading(kind, {"object": obj, "receptacle": NOTHING, "mrecep": NOTHING},
                   {"object": None, "receptacle": None, "mrecep": None}, False, unsaid)


def test_each_value_s_features_are_the_model_s_log_odds_the_parser_s_reading_and_the_other_fields() -> None:
    model = FieldModel(PRIORS, {**MODEL.weights, "mrecep": {"u:tray": {"pan": 5.0}}}, MODEL.trust)
    grams = sentence_grams("put the apple on a tray on the counter")
    options = candidates(model, "type", grams, reading_of(SIMPLE), None, ("pan", "counter_top"))
    assert set(options) == set(PRIORS["type"])
    p = model.probabilities("type", grams)
    assert options[SIMPLE]["scale:type"] == pytest.approx(math.log(p[SIMPLE]))
    assert options[SIMPLE]["type"] == options[SIMPLE][f"type:{SIMPLE}"] == 1.0 and "type" not in options[COOL]
    # the tray says a movable receptacle: the stack's joint feature is the likelier, a simple placing's the less
    assert options[STACK]["joint:mrecep"] > math.log(0.5) > options[SIMPLE]["joint:mrecep"]
    assert options[LOOK]["joint:receptacle"] < options[SIMPLE]["joint:receptacle"]
    unsaid = candidates(model, "object", grams, reading_of(SIMPLE, "apple", frozenset({"object"})), {"apple", "mug"})
    assert unsaid["apple"]["object:unsaid"] == 1.0 and "object" not in unsaid["mug"]
    assert candidates(model, "object", grams, reading_of(SIMPLE, "apple"), {"mug"}).keys() == {"mug"}
    assert score({"type": 2.0}, options[SIMPLE]) == pytest.approx(math.log(p[SIMPLE]) + 2.0)
    assert score({"scale:type": 0.0, "bias:type:" + SIMPLE: 1.5}, options[SIMPLE]) == pytest.approx(1.5)


def test_the_combination_is_learned_from_how_often_the_parser_is_right() -> None:
    """Out-of-fold sentences where the words' model leans to a cool task 60 : 40 but the parser's reading of a
    simple placing is right 9 times in 10 teach a bonus for it; where the parser is right only as often as the
    model, the bonus stays near nothing."""
    leaning = {COOL: {"scale:type": math.log(0.6), "bias:type:" + COOL: 1.0},
               SIMPLE: {"scale:type": math.log(0.4), "type": 1.0, f"type:{SIMPLE}": 1.0, "bias:type:" + SIMPLE: 1.0}}
    sure = fit_trust([(leaning, SIMPLE)] * 90 + [(leaning, COOL)] * 10)
    assert sure.get("type", 0.0) + sure.get(f"type:{SIMPLE}", 0.0) > 1.0
    blind = FieldModel(PRIORS, {}, sure)
    reading = reading_of(SIMPLE)
    assert score(sure, leaning[SIMPLE]) > score(sure, leaning[COOL])
    assert combine(blind, (), reading, ("apple",))[0]["type"] == SIMPLE
    even = fit_trust([(leaning, SIMPLE)] * 40 + [(leaning, COOL)] * 60)
    assert abs(even.get("type", 0.0) + even.get(f"type:{SIMPLE}", 0.0)) < 0.5
    assert fit_trust([(leaning, "pick_two_obj_and_place")]) == {}          # the right value is no candidate
    assert fit_trust([({SIMPLE: leaning[SIMPLE]}, SIMPLE)]) == {}           # one candidate: nothing to learn


def test_a_stack_whose_container_would_be_the_thing_itself_keeps_the_parser_s_type() -> None:
    """The words lean to a stack, but the container they choose is the mug being moved: no task puts a thing in its
    own class (0 of ALFRED's 21,025 train rows), so the parser's plain placing stands; a container of another class
    keeps the stack."""
    model = FieldModel(PRIORS, {"type": {"u:mug": {STACK: 8.0}}, "object": {},
                                "receptacle": {}, "mrecep": {"u:mug": {"mug": 6.0}, "u:pan": {"pan": 9.0}}},
                       MODEL.trust)
    reading = reading_of(SIMPLE, "mug")
    room = ("mug", "pan", "fridge")
    assert model.probabilities("type", sentence_grams("put the mug in the fridge"))[STACK] > 0.9
    assert combine(model, sentence_grams("put the mug in the fridge"), reading, room)[0]["type"] == SIMPLE
    stacked = combine(model, sentence_grams("put the mug in the pan in the fridge"), reading, room)[0]
    assert (stacked["type"], stacked["mrecep"]) == (STACK, "pan")

def test_the_combination_learned_for_the_count_keeps_the_parser_only_where_the_words_are_unsure() -> None:
    """Out-of-fold sentences: where the words' model leans 60 : 40 to a cool task the parser's simple placing is right
    (60 sentences), where it is sure (97 : 3) the words are (40). A bonus of 4 for the parser's type gets the sure
    ones wrong; the perceptron learns one that gets both right (between log(0.6/0.4) and log(0.97/0.03)), the same
    weights every time."""
    def leaning(cool: float) -> dict[str, dict[str, float]]:
        return {COOL: {"scale:type": math.log(cool)},
                SIMPLE: {"scale:type": math.log(1 - cool), "type": 1.0, f"type:{SIMPLE}": 1.0}}

    unsure, sure = leaning(0.6), leaning(0.97)
    start = {"type": 4.0}
    data = [(unsure, SIMPLE)] * 60 + [(sure, COOL)] * 40
    assert score(start, sure[SIMPLE]) > score(start, sure[COOL])                  # the sure ones wrong
    learned = fit_trust_count(data, start=start)
    assert score(learned, unsure[SIMPLE]) > score(learned, unsure[COOL])
    assert score(learned, sure[COOL]) > score(learned, sure[SIMPLE])
    assert fit_trust_count(data, start=start) == learned
    assert fit_trust_count([(unsure, "pick_two_obj_and_place")]) == {}     # the right value is no candidate
    assert fit_trust_count([({SIMPLE: unsure[SIMPLE]}, SIMPLE)]) == {}      # one candidate: nothing to learn

def test_a_learned_combination_is_read_back_from_the_model_file(tmp_path: Path) -> None:
    learned = FieldModel(PRIORS, MODEL.weights, {**MODEL.trust, "type:" + SIMPLE: 0.7, "scale:object": 1.2})
    assert load_field_model_of(model_json(learned, "test")) == learned
    bad = tmp_path / "bad.json"
    bad.write_text(model_json(learned, "test").replace('"scale:object":1.2', '"scale:object":"high"'))
    with pytest.raises(SealError, match="trust: expected a number"):
        load_field_model(bad)


def test_a_thing_taken_to_a_place_is_read_as_put_there(library: Library) -> None:
    """A Bring to a place said ends as a Place does: a stack said with "take the box to ..." is read as one, so
    the receptacle is the chair, not the box (the scorer reads Place only; the parse keeps its Bring)."""
    vocabulary = rules((*ROOM, "Box", "ArmChair", "RemoteControl", "Shelf"))
    parse = parse_command("put the remote into a box and take the box to the chair", library, vocabulary,
                          infer_steps=False)
    assert [f.frame for f in parse.frames] == ["Place", "Bring"]
    reading = read_fields(parse)
    assert (reading.type, dict(reading.values)) == (STACK, {"object": "remote_control", "receptacle": "arm_chair",
                                                            "mrecep": "box"})
    parse = parse_command("take the apple to the fridge", library, vocabulary, infer_steps=False)
    reading = read_fields(parse)
    assert (reading.type, reading.values["object"], reading.values["receptacle"]) == (SIMPLE, "apple", "fridge")
    parse = parse_command("bring me the apple", library, vocabulary, infer_steps=False)
    assert read_fields(parse).values["receptacle"] == NOTHING                    # to a person: no place


def test_a_look_whose_thing_is_only_found_or_carried_looks_at_it_in_the_lamp_s_light(library: Library) -> None:
    """"find the mug and switch on the lamp", "carry the bread over to the lamp and switch it on": the lamp makes it
    a look, but no frame the task's object is read from handles the thing; a LookAt of it in the light of the lamp
    switched on is added last, marked inferred, every said frame kept (holding it is the planner's)."""
    vocabulary = rules()
    for text, said in (("find the mug and switch on the lamp", ["Find", "ToggleOn"]),
                       ("carry the bread over to the lamp and switch it on", ["Bring", "ToggleOn"])):
        parse = parse_command(text, library, vocabulary, infer_steps=False)
        assert [f.frame for f in parse.frames] == said
        after = reread(parse, library, vocabulary, MODEL, text)
        assert [f.frame for f in after.frames] == [*said, "LookAt"]
        assert after.frames[:-1] == parse.frames
        look = after.frames[-1]
        assert look.inferred is not None and look.inferred > 0.5
        assert after.resolve(look.elements["theme"]).cls == ("Mug" if "mug" in text else "Bread")
        assert after.resolve(look.elements["instrument"]).cls == "DeskLamp"
        assert read_fields(after).type == LOOK
    text = "find the mug and switch on the microwave"          # no lamp: no look, nothing added
    parse = parse_command(text, library, vocabulary, infer_steps=False)
    assert "LookAt" not in [f.frame for f in reread(parse, library, vocabulary, MODEL, text).frames]
    text = "pick up the mug and switch on the lamp"            # the thing already handled: read as before
    parse = parse_command(text, library, vocabulary, infer_steps=False)
    assert [f.frame for f in reread(parse, library, vocabulary, MODEL, text).frames] == ["Pick", "ToggleOn"]


def test_a_place_said_back_with_nothing_placing_it_takes_the_class_the_words_say(library: Library) -> None:
    """"put the apple from the bedroom back": no source said before places "back" (the planner's, on a map: where
    the thing lay), so the receptacle is the words' guess of where that was (the bedroom's side table by the model),
    not nothing; the phrase stays an unplaced "back" for the planner."""
    from seal_cli.language.reference import back_unplaced

    text = "put the apple from the bedroom back"
    vocabulary, parse = parsed(text, library)
    assert parse.frames[0].elements["goal"].cls is None
    after = reread(parse, library, vocabulary, MODEL, text)
    goal = after.frames[0].elements["goal"]
    assert (goal.text, goal.cls) == ("back", "SideTable")
    assert back_unplaced(goal)
    assert read_fields(after).values["receptacle"] == "side_table"


def test_a_thing_said_beside_another_is_never_dropped_by_frames_written_anew(library: Library) -> None:
    """"put the frosty apple and the mug on the counter": the words say cool, which would write Pick, Cool and Place
    of one object anew and drop the mug; a coordination of things of two classes keeps the parser's frames (only
    classes may change)."""
    text = "put the frosty apple and the mug on the counter"
    vocabulary, parse = parsed(text, library)
    assert [f.frame for f in parse.frames] == ["Place"]
    assert [c.cls for c in parse.frames[0].elements["theme"].conjuncts] == ["Apple", "Mug"]
    after = reread(parse, library, vocabulary, MODEL, text)
    assert [f.frame for f in after.frames] == ["Place"]
    assert [c.cls for c in after.frames[0].elements["theme"].conjuncts] == ["Apple", "Mug"]
    text = "put the frosty apple on the counter"                # one thing: written anew as before
    vocabulary, parse = parsed(text, library)
    assert [f.frame for f in reread(parse, library, vocabulary, MODEL, text).frames] == ["Pick", "Cool", "Place"]


CUT = FieldModel(PRIORS | {"sliced": {"sliced": 10, "whole": 10}},
                 {**MODEL.weights, "sliced": {"to:pick_and_place_simple|apple": {"sliced": 4.0},
                                              "u:whole": {"whole": 9.0}}},
                 MODEL.trust, frozenset({"apple", "bread"}))


def test_a_slice_the_task_read_most_likely_had_is_added_before_the_thing_is_handled(library: Library) -> None:
    text = "put the apple on the counter"
    vocabulary, parse = parsed(text, library)
    assert not read_fields(parse).sliced
    after = reread(parse, library, vocabulary, CUT, text)
    assert [f.frame for f in after.frames] == ["Slice", *(f.frame for f in parse.frames)]
    assert after.frames[0].inferred is not None and after.frames[0].inferred > 0.9
    assert read_fields(after).sliced and read_fields(after).values["object"] == "apple"
    assert reread(parse, library, vocabulary, MODEL, text) == parse           # a model with no sliced field: none


def test_no_slice_is_added_to_a_thing_said_whole_or_of_a_class_never_sliced_or_one_said_sliced(
        library: Library) -> None:
    for text in ("put the whole apple on the counter", "put the mug on the counter",
                 "put the apple slice on the counter"):
        vocabulary, parse = parsed(text, library)
        after = reread(parse, library, vocabulary, CUT, text)
        assert [f.frame for f in after.frames].count("Slice") == [f.frame for f in parse.frames].count("Slice"), text


def test_the_sliced_field_is_learned_for_the_classes_train_sliced_and_read_back(tmp_path: Path) -> None:
    rows = [{"goal_sentence": s, "task_type": STACK, "object": o, "receptacle": "Fridge", "mrecep": "Pan",
             "sliced": c} for s, o, c in [("put a pan with apple in the fridge", "Apple", "1"),
                                          ("move a pan with an apple to the fridge", "Apple", "1"),
                                          ("put a whole apple in a pan in the fridge", "Apple", "0"),
                                          ("put a pan with a mug in the fridge", "Mug", "0")]]
    model = fit_fields(rows)
    assert model.sliceable == {"apple"} and model.priors["sliced"] == {"sliced": 2, "whole": 1}
    assert sliced_probability(model, sentence_grams("put a pan with an apple in the fridge"), STACK, "apple") > 2 / 3
    assert load_field_model_of(model_json(model, "test")) == model
    assert not fit_fields([{**r, "sliced": "0"} for r in rows]).sliceable        # nothing sliced: no field
