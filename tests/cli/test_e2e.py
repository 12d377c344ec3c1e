"""Everyday commands end to end on the shipped apartment: people, answers, warnings, refusals, the e2e bench."""

from __future__ import annotations

import json
from pathlib import Path

from typer.testing import CliRunner

from seal_cli.cli import app

runner = CliRunner()
FAST = ["--particles", "50", "--json"]


def run_json(*args: str) -> dict:  # type: ignore[type-arg]
    result = runner.invoke(app, ["run", "--map", "apartment", *args, *FAST])
    return json.loads(result.stdout)


def test_bring_me_hands_the_thing_to_the_speaker() -> None:
    report = run_json("bring me the spoon")
    assert report["completed"] and report["why"] == "ok" and report["warnings"] == []
    assert any(r["text"] == "handed spoon_1 to me" for r in report["records"])
    hand_over = next(r for r in report["records"] if r["text"] == "handed spoon_1 to me")
    assert abs(hand_over["pose"][0] + 6.5) + abs(hand_over["pose"][1] + 4.0) < 2.0    # beside the speaker


def test_going_to_a_room_says_the_room_and_where_in_it() -> None:
    report = run_json("go to the dining room")
    assert report["completed"] and report["plan"] == ["Go(goal=dining_room)"]
    assert any(r["text"].startswith("goes to the dining room (near its middle) (") for r in report["records"])


def test_a_persons_wish_is_brought_to_them() -> None:
    report = run_json("Anna wants the cup")
    assert report["plan"][-1] == "Bring(theme=cup, recipient=anna)" and report["completed"]
    assert any(r["text"] == "handed cup_1 to Anna" for r in report["records"])


def test_how_many_with_nowhere_said_looks_over_the_whole_house() -> None:
    report = run_json("how many cups are there?")
    assert report["completed"] and report["answer"] == "1 cup in the house"
    looked = {r["text"] for r in report["records"]}
    assert {"looks all over the kitchen", "looks all over the bedroom"} <= looked
    short = run_json("how many spoons are there?", "--max-metres", "5")
    assert short["answer"].startswith("0 spoons in the house seen, but it could not look all over ")


def test_come_back_returns_to_the_speaker() -> None:
    report = run_json("go to the kitchen and then come back")
    assert report["plan"] == ["Go(goal=kitchen)", "Go(goal=me)"] and report["completed"]
    end = report["records"][-1]["pose"]
    assert abs(end[0] + 6.5) + abs(end[1] + 4.0) < 2.0      # beside the speaker, in the living room


def test_questions_are_answered() -> None:
    found = run_json("find Ben")
    assert found["completed"] and found["answer"] == "Ben is in the bedroom at (-7.00, 3.00)"
    counted = run_json("count the cups in the family room")
    assert counted["plan"] == ["Count(theme=cup, ground=family_room)"]
    assert counted["answer"] == "1 cup in the family room"
    there = run_json("is Anna in the kitchen?")
    assert there["completed"] and there["answer"].startswith("yes: Anna is in the kitchen")
    elsewhere = run_json("is Ben in the kitchen?")
    assert elsewhere["completed"] and elsewhere["answer"] == "no: Ben is in the bedroom at (-7.00, 3.00)"


def test_a_kind_the_map_knows_nothing_of_is_warned_about_and_said_absent_at_once() -> None:
    """The apartment names no bowl: the robot's perception knows the map's classes only, so the run says so before
    it moves (e2e20; it searched the whole house before, to the same end). As where to put a thing, it is refused
    before the run (reach27: it fetched the apple, 14.35 m, before giving up)."""
    put = runner.invoke(app, ["run", "--map", "apartment", "put the apple in the bowl"])
    assert put.exit_code == 1 and "Traceback" not in put.output
    assert "column 18: the apartment has no bowl (" in put.output
    fetched = runner.invoke(app, ["run", "--map", "apartment", "bring me the bowl"])   # e2e27: refused where it is said
    assert fetched.exit_code == 1 and "column 10: the apartment knows no bowl (" in fetched.output
    report = run_json("find the bowl", "--max-steps", "40")       # looked for: said absent at once
    assert not report["completed"] and report["path_m"] == 0 and report["warnings"] == [
        "the map apartment knows nothing of bowl (no prior, object or place names it): seal run will say so "
        "without searching the house"]
    assert report["why"] == "not_found" and report["reason"].startswith(
        "no bowl found: the apartment map names none (no prior, object or place of one)")
    assert not any("searches the whole house" in r["text"] for r in report["records"])


def test_what_the_map_lacks_is_refused_before_anything_moves() -> None:
    result = runner.invoke(app, ["run", "--map", "apartment", "bring the cup to the garage"])
    assert result.exit_code == 1 and "Traceback" not in result.output
    assert "the apartment has no garage; its rooms are bedroom, family_room, dining_room, kitchen, living_room" \
        in result.output
    plan = runner.invoke(app, ["plan", "--map", "apartment", "clean the bathroom"])
    assert plan.exit_code == 1 and "has no bathroom" in plan.output


def test_framelib_plus_adds_to_the_standard_library(tmp_path: Path) -> None:
    mine = tmp_path / "mine.yaml"
    mine.write_text("frames:\n  - frame: Tidy\n    description: Tidy a room up.\n    lexical_units: [tidy up]\n"
                    "    elements:\n      ground: {type: location}\n    preconditions: []\n"
                    "    actions: [navigate(ground)]\n    postconditions: [tidied(ground)]\n", encoding="utf-8")
    result = runner.invoke(app, ["plan", "--map", "apartment", "--framelib", f"+{mine}", "--json",
                                 "tidy up the bedroom, then bring me the cup"])
    assert result.exit_code == 0, result.output
    assert [s["frame"] for s in json.loads(result.stdout)["plan"]] == ["Tidy", "Pick", "Bring"]
    alone = runner.invoke(app, ["plan", "--framelib", str(mine), "bring me the cup"])
    assert alone.exit_code == 1             # without +, the file is the whole library: no Bring
    missing = runner.invoke(app, ["plan", "--framelib", f"+{tmp_path / 'nope.yaml'}", "go home"])
    assert missing.exit_code == 1 and "no such file" in missing.output and "Traceback" not in missing.output


def test_bench_e2e_counts_plans_and_runs(tmp_path: Path) -> None:
    suite = tmp_path / "cases.yaml"
    suite.write_text("cases:\n"
                     "  - {map: apartment, text: go to the couch in the living room, plan: [Go(goal=sofa_2)], "
                     "run: done}\n"
                     "  - {map: apartment, text: bring the cup to the garage, refused: has no garage}\n"
                     "  - {map: apartment, text: go to the couch, plan: [Go(goal=sofa_1)]}\n", encoding="utf-8")
    result = runner.invoke(app, ["bench", "e2e", "--file", str(suite), "--jobs", "1", "--json", "--particles", "50"])
    assert result.exit_code == 0, result.output
    report = json.loads(result.stdout)
    assert report["groups"]["all"] == {"n": 3, "plan_right": 2, "plan_rate": 0.667, "runs": 1, "run_completed": 1,
                                       "run_rate": 1.0}
    assert [m["text"] for m in report["misses"]] == ["go to the couch"]   # it is sofa_2, the nearer: a miss, reported
    table = runner.invoke(app, ["bench", "e2e", "--file", str(suite), "--jobs", "1", "--particles", "50"])
    assert "plan miss" in table.stdout and "2/3" in table.stdout
    bad = runner.invoke(app, ["bench", "e2e", "--map", "moon"])
    assert bad.exit_code == 1 and "unknown map 'moon'" in bad.output


def test_the_shipped_suite_is_large_and_its_plans_are_right(library: object) -> None:
    from seal_cli.bench.e2e import MAPS, load_cases, plan_steps
    from seal_cli.maps.formats.map_server import load_map

    cases = [c for c in load_cases() if c.map == "apartment"]
    houses = {*MAPS, "townhouse", "office_floor", "cafe", "clinic", "terrace", "farmhouse", "bungalow", "lodge",
              "flat", "carehome", "student_house", "guesthouse", "studio", "corner_shop", "houseboat", "library",
              "bakery", "workshop", "fitness_club"}
    assert len(load_cases()) >= 100 and {c.map for c in load_cases()} == houses
    the_map = load_map(Path(__file__).resolve().parents[2] / "maps" / "apartment.yaml")
    wrong = [(c.text, got) for c in cases for right, got in [plan_steps(c, the_map, library)] if not right]
    assert wrong == []


def test_the_aws_house_plans_are_right(library: object, shared_data: Path, tmp_path: Path) -> None:
    from seal_cli.bench.e2e import MAPS, load_cases, plan_steps
    from seal_cli.maps.formats.map_server import load_map

    the_map = load_map(MAPS["aws"](tmp_path, shared_data))
    assert {p.name for p in the_map.people} == {"Carla", "Dev"} and len(the_map.places) == 14
    wrong = [(c.text, got) for c in load_cases() if c.map == "aws"
             for right, got in [plan_steps(c, the_map, library)] if not right]
    assert wrong == []


def test_the_example_houses_plans_are_right(library: object) -> None:
    from seal_cli.bench.e2e import load_cases, plan_steps
    from seal_cli.maps.formats.map_server import load_map

    houses = ("townhouse", "office_floor", "cafe", "clinic", "terrace", "farmhouse", "bungalow", "lodge", "flat",
              "carehome", "student_house", "guesthouse", "studio", "corner_shop", "houseboat", "library", "bakery",
              "workshop", "fitness_club")
    cases = [c for c in load_cases() if c.map in houses]
    assert len(cases) >= 120 and all(c.file is not None and Path(c.file).is_file() for c in cases)
    maps = {c.map: load_map(c.file) for c in cases if c.file is not None}
    wrong = [(c.text, got) for c in cases for right, got in [plan_steps(c, maps[c.map], library)] if not right]
    assert wrong == []


def test_bench_e2e_runs_cases_on_a_users_own_map_file(tmp_path: Path) -> None:
    from seal_cli.resources import map_path

    house = tmp_path / "houses" / "mine.yaml"
    house.parent.mkdir()
    house.write_text(map_path("townhouse").read_text(encoding="utf-8").replace(
        "image: townhouse.pgm", f"image: {map_path('townhouse').with_suffix('.pgm')}"), encoding="utf-8")
    suite = tmp_path / "cases.yaml"
    suite.write_text("cases:\n"
                     "  - {map: houses/mine.yaml, text: go to the laundry room, plan: [Go(goal=laundry_room)], "
                     "run: done}\n"
                     "  - {map: office_floor, text: go to the garage, refused: has no garage}\n", encoding="utf-8")
    result = runner.invoke(app, ["bench", "e2e", "--file", str(suite), "--jobs", "1", "--json", "--particles", "50"])
    assert result.exit_code == 0, result.output
    report = json.loads(result.stdout)
    assert report["groups"]["houses/mine.yaml"]["run_completed"] == 1 and report["groups"]["office_floor"]["n"] == 1
    assert report["groups"]["all"]["plan_right"] == 2 and report["misses"] == []
    suite.write_text("cases:\n  - {map: attic.yaml, text: go to the attic, refused: no attic}\n", encoding="utf-8")
    bad = runner.invoke(app, ["bench", "e2e", "--file", str(suite)])
    assert bad.exit_code == 1 and "case 1: no map 'attic.yaml'" in bad.output and "Traceback" not in bad.output


def test_a_whole_house_search_reads_as_one_line_a_room_and_ends_in_one_sentence() -> None:
    """Someone nobody placed is searched for in the whole house ("find Sam"; a thing the map names none of, such
    as "my keys" on the apartment, is said absent at once since e2e20)."""
    from seal_cli.maps.formats.map_server import load_map
    from seal_cli.resources import map_path

    report = run_json("find Sam")
    rooms = [r.name for r in load_map(map_path("apartment")).rooms]
    said = [r for r in report["records"] if not r.get("detail")]     # what the narration prints
    lines = [r["text"] for r in report["records"] if r["kind"] == "search"]
    assert report["why"] == "not_found" and report["reason"].startswith(
        "searched the whole house: no Sam (looked all over 5 rooms")
    per_room = [t for t in lines if t.startswith("searches the whole house for Sam: looks all over the ")]
    assert sorted(t.rsplit("the ", 1)[1].replace(" ", "_") for t in per_room) == sorted(rooms)   # each room once
    assert len(said) < 40 and report["path_m"] < 60.0      # not the old 0.25 m frontier steps (~100 lines, 77 m)
    keys = run_json("find my keys")
    assert keys["why"] == "not_found" and keys["path_m"] == 0.0 and keys["answer"].startswith("no key found: the "
                                                                                             "apartment map names none")


def truth(map_file: str | Path = "apartment") -> list[tuple[str, tuple[float, float], str | None]]:
    """The map's hidden truth: each object's class, position and place (what answers are checked against)."""
    from seal_cli.maps.formats.map_server import load_map

    return [(o.cls, o.at, o.inside) for o in load_map(map_file).objects]


def in_room(room: str, at: tuple[float, float], map_file: str | Path = "apartment") -> bool:
    from seal_cli.maps.formats.map_server import load_map

    return load_map(map_file).room_of([at])[0] == room


def test_yes_no_questions_are_true_on_the_map_and_answered_after_looking() -> None:
    no = run_json("is there a cup in the kitchen?")
    assert not any(c == "cup" and in_room("kitchen", at) for c, at, _ in truth())        # the truth: none there
    assert no["completed"] and no["answer"] == "no cup in the kitchen (it looked all over it)"
    texts = [r["text"] for r in no["records"]]
    assert any(t.startswith("opened fridge_1") for t in texts) and any(t.startswith("opened microwave_1")
                                                                          for t in texts)
    assert "closed fridge_1" in texts             # it leaves the fridge as it found it
    looks = [r["pose"] for r in no["records"] if r["kind"] == "search"]
    assert looks and all(in_room("kitchen", (p[0], p[1])) or p == looks[0] for p in looks[1:])
    yes = run_json("is there a cup in the family room?")
    assert any(c == "cup" and in_room("family_room", at) for c, at, _ in truth())
    assert yes["completed"] and yes["answer"].startswith("yes: cup_1 is on coffee_table_1 in the family room")


def test_what_is_on_or_in_a_place_lists_what_the_robot_saw_there() -> None:
    table = run_json("what is on the dining table?")
    assert not any(place == "dining_table_1" for _, _, place in truth())
    assert table["completed"] and table["answer"] == "nothing on dining_table_1"
    fridge = run_json("what's in the fridge?")
    assert [c for c, _, place in truth() if place == "fridge_1"] == ["apple"]
    assert fridge["completed"] and fridge["answer"] == "in fridge_1: apple_1"
    assert any(r["text"].startswith("opened fridge_1") for r in fridge["records"])
    said = [r["text"] for r in fridge["records"] if r["kind"] == "act"][-1]
    assert said == "says: in fridge_1: apple_1"


def test_how_many_counts_what_it_saw_including_none() -> None:
    zero = run_json("how many spoons are in the bedroom?")
    assert not any(c == "spoon" and in_room("bedroom", at) for c, at, _ in truth())
    assert zero["completed"] and zero["answer"] == "0 spoons in the bedroom"
    inside = run_json("count the apples in the kitchen")        # the one apple is in the closed fridge
    assert inside["answer"] == "1 apple in the kitchen"


def test_an_answer_says_when_the_robot_could_not_look_everywhere() -> None:
    short = run_json("is there a cup in the kitchen?", "--max-metres", "12")
    assert short["answer"].startswith("no cup seen in the kitchen, but it could not look all over it")


def test_answers_come_from_what_it_saw_not_from_the_map(tmp_path: Path) -> None:
    """Priors say nothing of cups in the kitchen; the world has one there: it is seen, and so said."""
    from seal_cli.resources import map_path

    text = map_path("apartment").read_text(encoding="utf-8").replace(
        "image: apartment.pgm", f"image: {map_path('apartment').with_suffix('.pgm')}").replace(
        "  - {class: cup, at: [0.3, 3.6], in: coffee_table_1}", "  - {class: cup, at: [6.2, -5.5], in: sink_1}")
    moved = tmp_path / "moved.yaml"
    moved.write_text(text, encoding="utf-8")
    result = runner.invoke(app, ["run", "--map", str(moved), "is there a cup in the kitchen?", *FAST])
    report = json.loads(result.stdout)
    assert report["answer"].startswith("yes: cup_1 is on sink_1 in the kitchen")
    where = runner.invoke(app, ["run", "--map", str(moved), "what is on the coffee table?", *FAST])
    assert json.loads(where.stdout)["answer"] == "nothing on coffee_table_1"


def test_find_goes_back_to_where_it_saw_the_thing(library: object, shared_data: Path, tmp_path: Path) -> None:
    """On the AWS house the robot sees the cup from afar while it searches, then goes to it (issue 11)."""
    import numpy as np

    from seal_cli.bench.e2e import MAPS
    from seal_cli.maps.formats.map_server import load_map
    from seal_cli.pipeline import run_on_map
    from seal_cli.sim.policies import make_policy

    the_map = load_map(MAPS["aws"](tmp_path, shared_data))
    agent, result = run_on_map(the_map, "find the cup", library, make_policy("sefm", 100),   # type: ignore[arg-type]
                               rng=np.random.default_rng(0))
    assert result.completed and result.answer == "cup_1 is in the bedroom at (-7.50, 2.50)"
    assert agent.in_view("cup_1")


def test_look_in_a_place_says_what_is_there() -> None:
    report = run_json("look in the fridge")
    assert report["completed"] and report["answer"] == "in fridge_1: apple_1"


def test_a_thing_brought_to_a_room_is_put_on_a_surface_there_not_back_where_it_was() -> None:
    report = run_json("please bring the apple to the kitchen")     # the apple is in the fridge, in the kitchen
    texts = [r["text"] for r in report["records"]]
    assert report["completed"] and "picked up apple_1 from fridge_1" in texts
    assert "put apple_1 on counter_1" in texts and "put apple_1 in fridge_1" not in texts


def test_anyone_in_a_room_is_whoever_the_robot_sees_there() -> None:
    yes = run_json("is there anyone in the kitchen?")
    assert yes["completed"] and yes["warnings"] == [] and yes["plan"] == ["Find(theme=person, ground=kitchen)"]
    assert yes["answer"] == "yes: Anna is in the kitchen at (5.53, -3.02)"
    no = run_json("is there a person in the dining room?")
    assert no["completed"] and no["answer"] == "nobody in the dining room (it looked all over it)"
    found = run_json("find somebody in the bedroom")
    assert found["completed"] and found["answer"] == "Ben is in the bedroom at (-7.00, 3.00)"


def test_telling_the_time_says_the_robots_clock_not_the_word() -> None:
    report = run_json("tell anna the time", "--clock", "14:05")
    said = [r["text"] for r in report["records"] if r["text"].startswith("said ")]
    assert report["completed"] and said == ['said "the time is 14:05"']   # 11.8 m at 0.5 m/s: still 14:05
    asked = run_json("what time is it?", "--clock", "2026-12-02T09:30")
    assert asked["answer"] == "the time is 09:30"
    dated = run_json("tell me the date", "--clock", "2026-12-02T09:30")
    assert dated["answer"] == "the date is 2 December 2026"


def test_a_bad_clock_is_refused_naming_the_option() -> None:
    result = runner.invoke(app, ["run", "--map", "apartment", "tell me the time", "--clock", "25:00"])
    assert result.exit_code == 1 and "--clock" in result.stderr and "Traceback" not in result.stderr


def test_a_negated_state_question_keeps_its_not() -> None:
    assert run_json("is the fridge open?")["answer"] == "no: fridge_1 is closed (as the map has it)"
    assert run_json("is the fridge not open?")["answer"] == "yes: fridge_1 is closed (as the map has it)"
    assert run_json("isn't the microwave open?")["answer"] == "yes: microwave_1 is closed (as the map has it)"


def test_whether_a_place_is_open_is_answered_from_the_map_as_closing_it_is() -> None:
    """e2e25: "is the fridge open?" drove 14 m to look while "close the fridge" said at 0 m it was shut already. One
    rule: the map records whether each place is open and only the robot opens and closes things, so both answer
    where the robot stands; what the map does not record (a lamp on, a fridge empty) it goes and looks at."""
    asked, closed = run_json("is the fridge open?"), run_json("close the fridge")
    assert asked["path_m"] == closed["path_m"] == 0.0 and asked["completed"] and closed["completed"]
    opened = run_json("open the fridge, then tell me whether the fridge is open")
    assert opened["answer"] == "yes: fridge_1 is open (as it left it)" and opened["path_m"] > 0
    assert run_json("is the fridge empty?")["path_m"] > 0           # what is inside: it looks


def test_a_state_question_with_a_place_looks_there_and_says_when_there_is_none() -> None:
    report = run_json("Is the window open in the bedroom?")      # the apartment has no window
    assert report["completed"] and report["answer"] == "no window in the bedroom (it looked all over it)"
    assert report["path_m"] < 15.0                                 # the bedroom only, not the whole house
    assert run_json("is the spoon clean in the kitchen?")["answer"] == "no: spoon_1 is not clean"


def test_a_place_the_map_does_not_mark_openable_is_refused_as_opened() -> None:
    result = runner.invoke(app, ["plan", "--map", "clinic", "open the hand dryer"])
    assert result.exit_code == 1 and "hand_dryer_1) does not (the map does not mark it openable)" in result.stderr
    lacking = runner.invoke(app, ["plan", "--map", "office_floor", "open the dryer"])   # an appliance: refused
    assert lacking.exit_code == 1 and "the office floor has no dryer" in lacking.stderr


def test_a_pair_of_gloves_is_one_thing_to_fetch() -> None:
    result = runner.invoke(app, ["plan", "--map", "clinic", "--json", "get me a pair of gloves"])
    assert [s["frame"] for s in json.loads(result.stdout)["plan"]] == ["Open", "Pick", "Bring"]


def test_is_there_stops_looking_once_it_sees_one() -> None:
    report = run_json("is there a spoon in the kitchen?")     # the spoon is on the counter, in plain view
    assert report["completed"] and report["answer"].startswith("yes: spoon_1 is on counter_1")
    assert not any(r["text"].startswith("opened") for r in report["records"])   # no fridge, no microwave
    assert report["path_m"] < 15.0                                              # was 19.9 m
    assert run_json("is there a cup in the kitchen?")["answer"] == "no cup in the kitchen (it looked all over it)"


def test_asked_whether_a_thing_is_in_a_closed_place_the_robot_opens_it_once_and_shows_it() -> None:
    report = run_json("is there an apple in the fridge?")
    texts = [r["text"] for r in report["records"]]
    assert report["answer"].startswith("yes: apple_1 is in fridge_1")
    assert sum(t.startswith("opened fridge_1") for t in texts) == 1 and "closed fridge_1" not in texts
    report = run_json("is there a spoon in the fridge?")                 # nothing to show: closed as found
    texts = [r["text"] for r in report["records"]]
    assert report["answer"].startswith("no spoon in fridge_1") and texts.count("closed fridge_1") == 1


def test_telling_where_a_thing_found_is_says_what_was_found_not_the_words() -> None:
    report = run_json("find the cup and tell me where it is")
    said = [r["text"] for r in report["records"] if r["text"].startswith("said ")]
    assert report["completed"] and said == [f'said "{report["answer"]}"']
    assert report["answer"].startswith("cup_1 is on coffee_table_1 in the family room")
    told = run_json("look for the apple and report its location to ben")
    said = [r["text"] for r in told["records"] if r["text"].startswith("said ")]
    assert told["completed"] and said == ['said "the apple is in the fridge in the kitchen"']
    hello = run_json("find the cup and tell me hello")
    assert [r["text"] for r in hello["records"] if r["text"].startswith("said ")] == ['said "hello"']


def acts_of(command: str) -> tuple[dict, list[str]]:  # type: ignore[type-arg]
    result = runner.invoke(app, ["run", "--map", "bungalow", command, *FAST])
    report = json.loads(result.stdout)
    return report, [r["text"] for r in report["records"] if r["kind"] in ("act", "fail")]


def test_a_thing_put_on_a_closed_place_goes_on_top_and_one_put_in_it_opens_it() -> None:
    """The bungalow's sideboard opens: "on" it needs it shut or open, "in" it opens it (and closes it
    after); the teapot, kept inside it, is taken out (opened to look) and put on top of it."""
    on, acts = acts_of("put the mug on the sideboard")
    assert on["completed"] and acts == ["picked up mug_1 from coffee_table_1", "put mug_1 on sideboard_1"]
    on_top, acts = acts_of("put the mug on top of the sideboard")
    assert on_top["completed"] and acts[-1] == "put mug_1 on sideboard_1" and not any("opened" in a for a in acts)
    into, acts = acts_of("put the mug in the sideboard")
    assert into["completed"] and acts == ["picked up mug_1 from coffee_table_1", "opened sideboard_1; inside: teapot_1",
                                          "put mug_1 in sideboard_1", "closed sideboard_1"]
    teapot, acts = acts_of("put the teapot on the sideboard")
    assert teapot["completed"] and acts == ["opened sideboard_1; inside: teapot_1",
                                            "picked up teapot_1 from sideboard_1", "closed sideboard_1",
                                            "put teapot_1 on sideboard_1"]
    still, acts = acts_of("put the teapot in the sideboard")       # inside it already: nothing to do
    assert still["completed"] and not any(a.startswith("put ") for a in acts)


def test_each_thing_is_fetched_from_its_own_place_and_handed_over_once() -> None:
    """"the spoon from the kitchen and the cup from the family room" (e2e19): before, one source for both, the plan
    brought the spoon twice ("from the cup") and the run ended "done" after taking the spoon back."""
    report = run_json("bring me the spoon from the kitchen and the cup from the family room")
    assert report["completed"] and report["plan"] == [
        "Pick(theme=spoon, source=kitchen)", "Bring(theme=spoon, recipient=me, source=kitchen)",
        "Pick(theme=cup, source=family_room)", "Bring(theme=cup, recipient=me, source=family_room)"]
    acts = [r["text"] for r in report["records"] if r["kind"] == "act"]
    assert [a for a in acts if a.startswith(("picked up", "handed", "took"))] == [
        "picked up spoon_1 from counter_1", "handed spoon_1 to me", "picked up cup_1 from coffee_table_1",
        "handed cup_1 to me"]


def test_a_question_put_to_a_person_is_asked_of_them() -> None:
    """"find out if anna wants coffee" was Find() of nothing, 0 m; "ask Raj if he wants tea" said "if he wants tea"."""
    report = run_json("find out if anna wants coffee")
    assert report["completed"] and report["plan"] == ["Tell(message=do_you_want_coffee, recipient=anna)"]
    acts = [r["text"] for r in report["records"] if r["kind"] == "act"]
    # then back to the speaker with the (absent) answer (e2e21)
    assert acts[-2:] == ['asked Anna "do you want coffee?"',
                         'tells the speaker that Anna gave no answer to "do you want coffee?"']
    result = runner.invoke(app, ["run", "--map", "bungalow", "ask Raj if he wants tea", *FAST])
    acts = [r["text"] for r in json.loads(result.stdout)["records"] if r["kind"] == "act"]
    assert acts[-2] == 'asked Raj "do you want tea?"'


def test_a_thing_not_in_the_house_ends_naming_what_the_map_has_of_its_kind() -> None:
    """"bring me a cup" on the bungalow, which has a mug and no cup: the run says at once that the map names no
    cup, and names the mug and the kettle (the taxonomy's containers the map has), without taking either for a
    cup (e2e20; it searched the whole house before, 62.39 m, and named the mug it saw)."""
    refused = runner.invoke(app, ["run", "--map", "bungalow", "bring me a cup", *FAST])   # e2e27: before the run
    assert refused.exit_code == 1 and "of its kind (container) it has: kettle, mug" in refused.output
    result = runner.invoke(app, ["run", "--map", "bungalow", "find a cup", *FAST])
    report = json.loads(result.stdout)
    assert result.exit_code == 1 and report["why"] == "not_found" and report["path_m"] == 0.0
    assert report["reason"].startswith("no cup found: the bungalow map names none")
    assert report["reason"].endswith("; of its kind (container) the map has: kettle, mug")
    assert not any(r["text"].startswith("picked up") for r in report["records"])


def test_the_school_suite_plans_are_right_but_its_two_judged_misses(library: object) -> None:
    """e2e32's user trials on the held-out school (``e2e_users29.yaml``, not shipped): every plan is what its user
    expected but the two judged and left in docs/planning.md ("e2e32"): the brush in the sink, the mug in the sink."""
    from seal_cli.bench.e2e import load_cases, plan_steps
    from seal_cli.maps.formats.map_server import load_map
    from seal_cli.resources import map_path

    cases = load_cases(Path(__file__).resolve().parents[2] / "seal_cli" / "bench" / "suites" / "e2e_users29.yaml")
    assert len(cases) == 53 and sum(c.map == "school" for c in cases) == 48
    maps = {name: load_map(map_path(name)) for name in {c.map for c in cases}}
    wrong = [c.text for c in cases for right, _ in [plan_steps(c, maps[c.map], library)] if not right]
    assert wrong == ["put the brush in the sink", "put the mug in the sink"]
