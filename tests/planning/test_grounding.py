"""Map grounding: the rooms, places and people a command's words name on a map, and what is refused."""

from __future__ import annotations

import json
from pathlib import Path

import pytest

from seal_cli.errors import SealError
from seal_cli.frames.library import Library
from seal_cli.maps.formats.map_server import load_map
from seal_cli.pipeline import plan as plan_text
from seal_cli.planning.grounding import MapNames, spoken, words_of

APARTMENT = Path(__file__).resolve().parents[2] / "maps" / "apartment.yaml"


def steps(text: str, library: Library) -> list[str]:
    return [str(s) for s in plan_text(text, library, map=load_map(APARTMENT)).steps]


@pytest.mark.parametrize(("text", "expected"), [
    ("go to the living room", ["Go(goal=living_room)"]),               # two words, as people say it
    ("go to the family_room", ["Go(goal=family_room)"]),               # the map's own spelling
    ("go to the couch in the living room", ["Go(goal=sofa_2)"]),       # a synonym, placed by its room
    ("go to the sofa in the family room", ["Go(goal=sofa_1)"]),
    ("go to the couch", ["Go(goal=sofa_2)"]),                          # of two sofas, the nearest the robot drives to
    ("go to sofa 2", ["Go(goal=sofa_2)"]),                             # a place's name with its number
    ("go to the dining table", ["Go(goal=dining_table_1)"]),
    ("go to the tv stand", ["Go(goal=tv_stand_1)"]),
    ("count the cups in the family room", ["Count(theme=cup, ground=family_room)"]),   # one Count of the class
    ("bring me the cup", ["Pick(theme=cup, source=coffee_table_1)", "Bring(theme=cup, recipient=me)"]),
    ("give the apple to Ben", ["Open(theme=fridge_1)", "Pick(theme=apple, source=fridge_1)",
                               "Give(theme=apple, recipient=ben)"]),
    ("guide Anna to the living room", ["Guide(theme=anna, goal=living_room)"]),
    ("go to the lounge", ["Go(goal=living_room)"]),                   # a room by another name of its kind
    ("take the cup to the sitting room", ["Pick(theme=cup, source=coffee_table_1)",
                                          "Bring(theme=cup, goal=living_room)"]),
    ("go to the den", ["Go(goal=family_room)"]),
])
def test_words_ground_to_the_maps_ids(library: Library, text: str, expected: list[str]) -> None:
    assert steps(text, library) == expected


@pytest.mark.parametrize(("text", "message", "column"), [
    ("bring the cup to the garage", "the apartment has no garage; its rooms are bedroom, family_room, "
                                    "dining_room, kitchen, living_room", 18),
    ("go to the table in the kitchen", "the apartment has no table in the kitchen; it has dining_table_1 "
                                       "(dining_room), coffee_table_1 (family_room)", 7),
    ("put the cup on the shelf", "the apartment has no shelf; its places are fridge_1", 16),
    ("pick up the sofa", "'the sofa' (sofa_2) is fixed in the map", 9),
    ("clean the bathroom", "the apartment has no bathroom", 7),
    ("go to the washroom", "the apartment has no washroom", 7),       # another name of a room it lacks
    ("go upstairs", "the apartment has no upstairs; its rooms are", 4),   # not a thing to search the house for
    ("bring me something to drink from", "'something' does not say what kind of thing: name it (the apartment "
                                         "knows of apple, cup, spoon)", 10),
    ("find something in the kitchen", "'something' does not say what kind of thing", 6),   # no question: no answer
    # where the robot sets out for must be found before it drives (reach27): put, poured, gone to, searched in
    ("put the teapot on the spaceship", "the apartment has no spaceship (no room, place or person of the map is "
                                        "called so, and no kind of thing it knows of)", 19),
    ("put the cup on the spaceship in the kitchen", "the apartment has no spaceship (", 16),   # said where: no help
    ("put the apple in the bowl", "the apartment has no bowl (no room, place or person of the map is called so, and "
                                  "no prior, object or place of it names the kind, so the robot has nowhere to "
                                  "search for one)", 18),
    ("pour the milk into a jug", "the apartment has no jug (", 20),
    ("go to the bucket", "the apartment has no bucket (", 7),
    ("look for the spoon in the hamper", "the apartment has no hamper (", 23),
])
def test_what_the_map_lacks_is_refused_where_it_is_said(library: Library, text: str, message: str,
                                                         column: int) -> None:
    with pytest.raises(SealError, match=message.replace("(", r"\(").replace(")", r"\)")) as caught:
        steps(text, library)
    assert caught.value.column == column


def test_what_the_map_knows_nothing_of_is_a_warning(library: Library) -> None:
    # a thing to find is sought, never refused at plan time (where it goes must be known: the test above)
    plan = plan_text("find the bowl", library, map=load_map(APARTMENT))
    assert plan.warnings == ("the map apartment knows nothing of bowl (no prior, object or place names it): "
                             "seal run will say so without searching the house",)     # (e2e20: it searched)
    assert plan.to_json()["warnings"] == list(plan.warnings)
    roger = plan_text("give the cup to Roger", library, map=load_map(APARTMENT))
    assert roger.warnings and "nobody on the map apartment is called Roger" in roger.warnings[0]
    assert not plan_text("bring me the cup", library, map=load_map(APARTMENT)).warnings


def test_names_and_spellings(library: Library) -> None:
    names = MapNames(load_map(APARTMENT), library.taxonomy)
    assert spoken("go to the family_room") == "go to the family room"
    assert names.ground("the settee in the living room", "location").id == "sofa_2"   # type: ignore[union-attr]
    assert names.ground("the fridge", "openable").id == "fridge_1"                   # type: ignore[union-attr]
    assert names.ground("Anna", "thing").kind == "person"                             # type: ignore[union-attr]
    assert names.ground("the bowl", "location") is None                  # an object to find, not a place
    assert names.where_said("the cups in the family room") == "family_room"


def test_here_is_the_speaker_and_a_person_where_a_place_was_said_receives(library: object) -> None:
    from seal_cli.maps.formats.map_server import load_map
    from seal_cli.pipeline import plan

    m = load_map("apartment").known()
    assert [str(s) for s in plan("come here", library, map=m).steps] == ["Go(goal=me)"]   # type: ignore[arg-type]
    assert [str(s) for s in plan("bring the cup here", library, map=m).steps] == [    # type: ignore[arg-type]
        "Pick(theme=cup)", "Bring(theme=cup, recipient=me)"]
    # Wait's theme (whom it waits for) is acted on by no primitive: "here" stays where it waits
    assert [str(s) for s in plan("wait here", library, map=m).steps] == ["Wait(ground=me)"]   # type: ignore[arg-type]
    assert [str(s) for s in plan("wait for me in the kitchen", library, map=m).steps] == [  # type: ignore[arg-type]
        "Wait(theme=me, ground=kitchen)"]


def test_the_first_words_of_a_compound_name_call_it_weakly(library: object) -> None:
    from seal_cli.maps.formats.map_server import load_map
    from seal_cli.pipeline import plan

    m = load_map("apartment").known()
    assert [str(s) for s in plan("go to the tv", library, map=m).steps] == ["Go(goal=tv_stand_1)"]  # type: ignore[arg-type]
    assert [str(s) for s in plan("go to the table", library, map=m).steps] == ["Go(goal=dining_table_1)"]  # type: ignore[arg-type]


def test_a_thing_acted_on_is_named_by_its_head_not_by_the_first_words_of_a_place(library: Library) -> None:
    """"turn off the tv": the apartment's tv stand is a stand, not a tv, so the tv is refused (not
    the stand switched); where to go ("go to the tv") the stand is still meant."""
    with pytest.raises(SealError, match="the apartment has no tv") as caught:
        steps("turn off the tv", library)
    assert caught.value.column == 10
    assert "the apartment has no tv (only tv_stand_1, a tv stand); its places are" in caught.value.message
    with pytest.raises(SealError, match=r"no tv \(only tv_stand_1"):    # said in its room: the same (e2e16)
        steps("turn off the tv in the living room", library)
    assert steps("go to the tv", library) == ["Go(goal=tv_stand_1)"]


def test_a_numbered_place_is_its_number_said_as_a_word_too(library: Library) -> None:
    """"bring a mug to table two" on the cafe (table_1 to table_3) was refused: "the cafe has no table two (only
    table_1 and table_2 and table_3, a table)" while "table 2" was table_2 (lead, stop 42). A number the map has
    not is still refused, naming the tables it has."""
    cafe = load_map("cafe")
    for said, table in (("table two", "table_2"), ("table 2", "table_2"), ("table three", "table_3")):
        assert [str(s) for s in plan_text(f"go to {said}", library, map=cafe).steps] == [f"Go(goal={table})"]
    with pytest.raises(SealError, match=r"no table four \(only table_1 and table_2 and table_3"):
        plan_text("go to table four", library, map=cafe)
    apartment = load_map("apartment")       # sofa_2 and no table_2: a number alone calls no place (it was the sofa)
    for said in ("table 2", "table two"):
        with pytest.raises(SealError, match=f"the apartment has no {said}"):
            plan_text(f"go to {said}", library, map=apartment)
    assert [str(s) for s in plan_text("go to sofa two", library, map=apartment).steps] == ["Go(goal=sofa_2)"]


def test_a_question_about_what_the_map_lacks_is_asked_not_refused(library: Library) -> None:
    """"how many chairs ...?", "is there a chair ...?" on a map without chairs: a class to look for
    in the room (the warning says where), while "go to the chair" is still refused."""
    counted = plan_text("how many chairs are in the dining room", library, map=load_map(APARTMENT))
    assert [str(s) for s in counted.steps] == ["Count(theme=chair, ground=dining_room)"]
    assert counted.warnings == ("the map apartment knows nothing of chair (no prior, object or place names it): "
                                "seal run will look for it in dining_room",)
    assert steps("is there a chair in the kitchen?", library) == ["Find(theme=chair, ground=kitchen)"]
    with pytest.raises(SealError, match="the apartment has no chair"):
        steps("go to the chair", library)


def test_a_frame_that_must_hold_a_fixed_thing_is_refused(library: object) -> None:
    import pytest

    from seal_cli.errors import SealError
    from seal_cli.maps.formats.map_server import load_map
    from seal_cli.pipeline import plan

    with pytest.raises(SealError, match=r"Clean needs its theme to be an object the robot can handle, and 'the sofa' "
                                        r"\(sofa_2\) is fixed"):
        plan("clean the sofa", library, map=load_map("apartment").known())  # type: ignore[arg-type]


@pytest.mark.parametrize(("text", "plan"), [
    ("check the fridge", ["LookAt(theme=fridge_1)"]),            # was refused: "LookAt needs to hold its theme"
    ("check on Ben", ["LookAt(theme=ben)"]),                      # was Pick(theme=ben), LookAt
    ("keep an eye on the stove", ["LookAt(theme=stove_1)"]),
    ("examine the cup", ["Pick(theme=cup, source=coffee_table_1)", "LookAt(theme=cup)"]),   # a thing: in the hand
])
def test_a_person_or_a_fixed_thing_is_looked_at_where_it_stands(library: Library, text: str, plan: list[str]) -> None:
    """LookAt holds its theme (ALFRED's looking at a thing in a lamp's light): never a person or a fixture."""
    assert steps(text, library) == plan


def test_a_places_own_name_calls_it_before_another_places_synonym(library: Library) -> None:
    """The cafe has a kitchen sink and a restroom washbasin, and "washbasin" is a synonym of sink:
    "the washbasin" is the washbasin, "the sink" the sink; on a map with only a sink, the synonym
    still calls the sink."""
    cafe = load_map("cafe")
    assert [str(s) for s in plan_text("go to the washbasin", library, map=cafe).steps] == ["Go(goal=washbasin_1)"]
    assert [str(s) for s in plan_text("go to the sink", library, map=cafe).steps] == ["Go(goal=sink_1)"]
    assert steps("go to the washbasin", library) == ["Go(goal=sink_1)"]


def test_a_compound_spelt_apart_in_the_synonyms_gives_the_place_its_head(library: Library) -> None:
    """The library spells "armchair" also "arm chair": the armchair is called "the chair" (the
    townhouse's only chair), while a synonym that is another word ("tv table") still gives no head."""
    townhouse = load_map(APARTMENT.parent / "townhouse.yaml")
    assert [str(s) for s in plan_text("go to the chair", library, map=townhouse).steps] == ["Go(goal=armchair_1)"]
    names = MapNames(load_map(APARTMENT), library.taxonomy)
    assert "table" not in names.by_id("tv_stand_1").heads


def test_a_compound_of_another_kind_is_not_the_place_sharing_its_head(library: Library) -> None:
    """"the hand dryer" on the townhouse is not its (tumble) dryer: refused, naming what was said; a
    describing word ("the red dryer") or a word of the map ("the bathroom sink") still finds the place."""
    townhouse = load_map(APARTMENT.parent / "townhouse.yaml")
    with pytest.raises(SealError, match="the townhouse has no hand dryer"):
        plan_text("open the hand dryer", library, map=townhouse)
    for text, step in [("open the dryer", "Open(theme=dryer_1)"), ("open the red dryer", "Open(theme=dryer_1)"),
                       ("go to the bathroom sink", "Go(goal=bathroom_sink_1)")]:
        assert [str(s) for s in plan_text(text, library, map=townhouse).steps] == [step]


def test_a_thing_already_in_the_room_it_is_taken_to_is_left_there_with_a_warning(library: Library) -> None:
    townhouse = load_map(APARTMENT.parent / "townhouse.yaml")
    found = plan_text("take the umbrella to the hallway", library, map=townhouse)
    assert found.steps == () and found.warnings == (
        "Bring(theme=umbrella, goal=hallway) is not done: in(umbrella, hallway), hand_empty holds already",)
    assert len(plan_text("take the umbrella to the garage", library, map=townhouse).steps) == 2
    apple = plan_text("bring the apple to the kitchen", library, map=load_map(APARTMENT))   # shut in the fridge
    assert [s.binding.frame.name for s in apple.steps] == ["Open", "Pick", "Bring"]


# -- people called by their roles ("the nurse") ----------------------------------------------------
CLINIC = APARTMENT.parent / "clinic.yaml"
TWO_NURSES = """\
bounds: [0, 0, 10, 5]
rooms:
  - {name: ward, box: [0, 0, 5, 5]}
  - {name: office, box: [5, 0, 10, 5]}
priors: {cup: {ward: 0.5}}
people:
  - {name: Nora, room: ward, role: nurse}
  - {name: Ida, room: office, role: [nurse, head nurse]}
  - {name: Ben, room: office, role: cook}
speaker: {role: [doctor, boss]}
"""


def two_nurses(tmp_path: Path) -> Path:
    path = tmp_path / "ward.yaml"
    path.write_text(TWO_NURSES)
    return path


@pytest.mark.parametrize(("text", "expected"), [
    ("bring the mug to the nurse", ["Pick(theme=mug, source=table_1)", "Bring(theme=mug, recipient=nora)"]),
    ("give the nurse the pen", ["Pick(theme=pen, source=desk_1)", "Give(theme=pen, recipient=nora)"]),
    ("bring the pen to the receptionist", ["Pick(theme=pen, source=desk_1)", "Bring(theme=pen, recipient=victor)"]),
    ("guide the nurse to the staff room", ["Guide(theme=nora, goal=staff_room)"]),
    ("find the nurse", ["Find(theme=nora)"]),
    # the speaker is the clinic's doctor: "the doctor" is "me"
    ("bring the stethoscope to the doctor", ["Pick(theme=stethoscope, source=exam_table_1)",
                                             "Bring(theme=stethoscope, recipient=me)"]),
])
def test_a_person_is_called_by_the_role_the_map_gives_them(library: Library, text: str, expected: list[str]) -> None:
    assert [str(s) for s in plan_text(text, library, map=load_map(CLINIC)).steps] == expected


def test_a_role_several_people_have_is_refused_naming_them_and_a_room_said_narrows_it(
        library: Library, tmp_path: Path) -> None:
    ward = load_map(two_nurses(tmp_path))
    with pytest.raises(SealError, match=r"'the nurse' could be nora \(ward\) or ida \(office\): the ward has 2 "
                                        r"people with the role nurse; say which one by name") as caught:
        plan_text("bring the cup to the nurse", library, map=ward)
    assert caught.value.column == 18
    said = plan_text("bring the cup to the nurse in the office", library, map=ward)
    assert str(said.steps[-1]) == "Bring(theme=cup, recipient=ida)"
    assert str(plan_text("bring the cup to the head nurse", library, map=ward).steps[-1]) == \
        "Bring(theme=cup, recipient=ida)"
    # a role the parser reads as a place ("to the cook") is still the person, and receives
    assert str(plan_text("take the cup to the cook", library, map=ward).steps[-1]) == "Bring(theme=cup, recipient=ben)"
    assert str(plan_text("bring the cup to the boss", library, map=ward).steps[-1]) == "Bring(theme=cup, recipient=me)"
    with pytest.raises(SealError, match=r"the ward has no cook in the ward; it has ben \(office\)"):
        plan_text("follow the cook in the ward", library, map=ward)


def test_a_role_said_in_the_plural_calls_everyone_with_it(library: Library, tmp_path: Path) -> None:
    """e2e33: "tell the guests that breakfast is ready" on the guesthouse (two guests) was refused as "the guest"
    is; said in the plural, the role calls them all, as "Anna and Ben" does; a room said narrows them."""
    ward = load_map(two_nurses(tmp_path))
    told = plan_text("tell the nurses that the doctor is here", library, map=ward)
    assert [str(s) for s in told.steps] == ["Tell(message=the_doctor_is_here, recipient=nora)",
                                            "Tell(message=the_doctor_is_here, recipient=ida)"]
    assert [str(s) for s in plan_text("find the nurses", library, map=ward).steps] == ["Find(theme=nora)",
                                                                                         "Find(theme=ida)"]
    narrowed = plan_text("bring the nurses in the office a cup", library, map=ward)
    assert str(narrowed.steps[-1]) == "Bring(theme=cup, recipient=ida)"
    with pytest.raises(SealError, match=r"'the nurse' could be nora \(ward\) or ida \(office\)"):
        plan_text("find the nurse", library, map=ward)


def test_a_role_nobody_has_is_warned_about_like_a_name_nobody_has(library: Library) -> None:
    plan = plan_text("bring the cup to the nurse", library, map=load_map(APARTMENT))
    assert str(plan.steps[-1]) == "Bring(theme=cup, recipient=nurse)"
    assert plan.warnings == ("nobody on the map apartment is the nurse (no person has that role): seal run will "
                             "search the whole house for them",)
    named = plan_text("bring the cup to Roger", library, map=load_map(APARTMENT))
    assert named.warnings == ("nobody on the map apartment is called Roger: seal run will search the whole house "
                              "for them",)


def test_a_person_or_place_the_parser_found_said_before_is_grounded_by_what_it_stands_for(library: Library) -> None:
    """"him" and a bare "there" standing for a person and a place a statement named (words22, words23) are
    grounded by their heads: the plan leads Sam to the kitchen and warns of no one "called Him"."""
    plan = plan_text("Sam wants to go to the kitchen, lead him there", library, map=load_map(APARTMENT))
    assert str(plan.steps[-1]) == "Guide(theme=sam, goal=kitchen)"
    assert plan.warnings == ("nobody on the map apartment is called Sam: seal run will search the whole house "
                             "for them",)
    found = plan_text("Sam is in the kitchen, find him", library, map=load_map(APARTMENT))
    assert str(found.steps[-1]) == "Find(theme=sam, ground=kitchen)"
    assert "called Sam" in found.warnings[0]


def test_a_thing_on_no_place_in_the_room_is_there_already_for_plan_and_run_alike(library: Library) -> None:
    """One rule (``planning.plan.already_so``) for ``seal plan`` (the map's state) and ``seal run`` (what the
    robot sees): the clinic's umbrella lies on the waiting room's floor, on no place."""
    from typer.testing import CliRunner

    from seal_cli.cli import app
    from seal_cli.frames.model import Fact
    from seal_cli.planning.plan import already_so
    from seal_cli.planning.problem import problem_of_text

    clinic = load_map(CLINIC)
    plan = plan_text("take the umbrella to the waiting room", library, map=clinic)
    assert plan.steps == () and plan.warnings == ("Bring(theme=umbrella, goal=waiting_room) is not done: "
                                                  "in(umbrella, waiting_room), hand_empty holds already",)
    problem = problem_of_text("take the umbrella to the staff room", library, map=clinic)
    bring = problem.commanded[0]
    assert already_so(bring, problem.state) is None       # another room: it is brought
    assert problem.state.holds(Fact("in", ("umbrella", "waiting_room")))
    held = problem.state.apply(library.frame("Pick").bind({"theme": "umbrella"}))
    assert not held.holds(Fact("in", ("umbrella", "waiting_room")))   # once picked up, it is in the hand
    run = CliRunner().invoke(app, ["run", "--map", str(CLINIC), "take the umbrella to the waiting room",
                                   "--particles", "50", "--json"])
    report = json.loads(run.stdout)
    assert report["completed"] and report["executed"] == []
    assert any(r["text"] == "umbrella_1 is in the waiting room already, so Bring(theme=umbrella, goal=waiting_room) "
               "needs no doing" for r in report["records"])
    assert not any("picked up" in r["text"] for r in report["records"])


def test_a_person_is_said_as_the_map_writes_them_else_as_a_name() -> None:
    from seal_cli.planning.grounding import person_name

    m = load_map(APARTMENT)
    assert person_name(m, "anna", "anna") == "Anna"              # the map's spelling, whatever was typed
    assert person_name(m, "roger", "roger") == "Roger"            # nobody on the map: a name, capitalised
    assert person_name(m, "mcdonald", "McDonald") == "McDonald"   # as typed when it has capitals
    assert person_name(None, "roger", "Roger's") == "Roger"     # a possessive alone: the id, capitalised


def test_my_place_is_the_one_nearest_the_speaker(library: Library) -> None:
    """The office floor has desks 1-4; its speaker stands by desk_2. "My desk" is that one (e2e18; before, desk_1,
    the first in the map's order); "the desk" is still the first."""
    names = MapNames(load_map("office_floor"), library.taxonomy)
    assert names.ground("my desk", "place").id == "desk_2"      # type: ignore[union-attr]
    assert names.ground("our desk", "place").id == "desk_2"     # type: ignore[union-attr]
    assert names.ground("the desk", "place").id == "desk_1"     # type: ignore[union-attr]


def test_there_stands_for_a_compound_place_a_statement_named(library: Library) -> None:
    """"there's a cup in the family room, bring it there" was refused "the apartment has no room" (there's head was
    "room"): there is the family room, where the command says the cup already is, which the refusal says."""
    with pytest.raises(SealError) as error:
        plan_text("there's a cup in the family room, bring it there", library, map=load_map(APARTMENT))
    assert error.value.message.startswith("the cup is already in the family room: 'there' is the family room")
    with pytest.raises(SealError, match="the command takes it from the family room to the family room"):
        plan_text("take the cup from the family room to the family room", library, map=load_map(APARTMENT))
    here = plan_text("there's a cup in the family room, bring it here", library, map=load_map(APARTMENT))
    assert str(here.steps[-1]) == "Bring(theme=cup, recipient=me, source=family_room)"
    lead = plan_text("Sam wants to go to the dining room, lead him there", library, map=load_map(APARTMENT))
    assert str(lead.steps[-1]) == "Guide(theme=sam, goal=dining_room)"


@pytest.mark.parametrize(("room", "said"), [("кухня", "кухня"), ("σαλόνι", "Σαλόνι"), ("café", "café")])
def test_a_room_named_in_any_script_is_reached_by_its_name(library: Library, tmp_path: Path, room: str,
                                                           said: str) -> None:
    """A room's name is a proper name, written as its owner writes it: "go to the кухня" was "the m has no кухня
    ... its rooms are кухня, hall" (a phrase's words were ASCII letters only; "café" was "caf" on both sides)."""
    (tmp_path / "m.yaml").write_text(f'name: m\nbounds: [0, 0, 10, 10]\nrooms:\n  - {{name: "{room}", box: [0, 0, 5, '
                                     '10]}\n  - {name: hall, box: [5, 0, 10, 10]}\n', encoding="utf-8")
    assert words_of(f"the {said}") == (room,)
    plan = plan_text(f"go to the {said}", library, map=load_map(tmp_path / "m.yaml"))
    assert [str(s) for s in plan.steps] == [f"Go(goal={room})"]


def test_a_place_of_several_none_reachable_is_said_so_not_inf_metres(library: Library, tmp_path: Path) -> None:
    """Two beds beyond a wall with no door: "chose bed_1, the nearest the robot drives to ... (inf m)" (hostile24)."""
    from seal_cli.bench.reliability_attacker import split_house

    image, head = split_house()
    (tmp_path / "s.pgm").write_bytes(image)
    (tmp_path / "m.yaml").write_text(head + "places:\n  - {name: bed_1, class: bed, at: [8, 2]}\n"
                                     "  - {name: bed_2, class: bed, at: [7, 8]}\n", encoding="utf-8")
    plan = plan_text("go to the bed", library, map=load_map(tmp_path / "m.yaml"))
    assert [str(s) for s in plan.steps] == ["Go(goal=bed_1)"]
    said = " ".join(plan.warnings)
    assert "the robot can reach none of them from where it starts; chose bed_1, the first the map lists" in said
    assert "inf m" not in said


def test_a_place_where_two_areas_overlap_is_in_either(library: Library, tmp_path: Path) -> None:
    """Areas drawn without walls may overlap (a map warned of): a sofa standing where both reach is "the sofa in"
    either; it was refused in the second, "the m has no sofa in the east; it has sofa_1 (west)" (hostile25). A room
    that does not hold it is still refused."""
    text = ("name: m\nbounds: [0, 0, 10, 10]\nrooms:\n  - {name: west, box: [0, 0, 6, 10]}\n"
            "  - {name: east, box: [4, 0, 10, 10]}\n  - {name: loft, box: [0, 10, 10, 12]}\n"
            "places:\n  - {name: sofa_1, class: sofa, at: [5, 5]}\n")
    (tmp_path / "m.yaml").write_text(text.replace("bounds: [0, 0, 10, 10]", "bounds: [0, 0, 10, 12]"))
    world = load_map(tmp_path / "m.yaml")
    for room in ("west", "east"):
        assert [str(s) for s in plan_text(f"go to the sofa in the {room}", library, map=world).steps] == \
            ["Go(goal=sofa_1)"]
    with pytest.raises(SealError, match="has no sofa in the loft; it has sofa_1 \\(west\\)"):
        plan_text("go to the sofa in the loft", library, map=world)
