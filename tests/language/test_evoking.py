"""Which frame a clause evokes, where the verb alone would mislead: going with someone, getting somewhere."""

from __future__ import annotations

import pytest

from seal_cli.frames.library import Library
from seal_cli.language.lexicon import CommandError
from seal_cli.language.parser import parse_command


def _frames(text: str, library: Library) -> list[tuple[str, dict[str, str | None]]]:
    return [(f.frame, {role: p.text for role, p in f.elements.items()}) for f in parse_command(text, library).frames]


@pytest.mark.parametrize(("text", "expected"), [
    ("go with Sam", [("Follow", {"theme": "Sam"})]),                   # where Sam goes: follow
    ("go with him", [("Follow", {"theme": "him"})]),
    ("please drive with the nurse", [("Follow", {"theme": "the nurse"})]),
    ("go with the visitor to the door", [("Guide", {"theme": "the visitor", "goal": "the door"})]),   # bring there
    ("head with Lena to the car", [("Guide", {"theme": "Lena", "goal": "the car"})]),
])
def test_going_with_a_person_is_moving_together(library: Library, text: str, expected: list[object]) -> None:
    assert _frames(text, library) == expected


def test_going_with_a_thing_is_no_company(library: Library) -> None:
    """A thing gone with is taken there (words31: "go with the cart to the kitchen" was a bare Go, "with the cart"
    dropped silently)."""
    assert _frames("go to the kitchen", library) == [("Go", {"goal": "the kitchen"})]
    assert _frames("go with the cart to the kitchen", library) == [
        ("Bring", {"theme": "the cart", "goal": "the kitchen"})]


@pytest.mark.parametrize(("text", "expected"), [
    # nouns WordNet names only people (framelib/wordnet_people.yaml), beside the household ones of types.yaml
    ("go with the plumber", [("Follow", {"theme": "the plumber"})]),
    ("walk with the courier to the gate", [("Guide", {"theme": "the courier", "goal": "the gate"})]),
    ("go along with the janitor", [("Follow", {"theme": "the janitor"})]),
    ("go with my friend", [("Follow", {"theme": "my friend"})]),
    ("go with the woman to the lobby", [("Guide", {"theme": "the woman", "goal": "the lobby"})]),
])
def test_going_with_a_person_noun_is_moving_together(library: Library, text: str, expected: list[object]) -> None:
    assert _frames(text, library) == expected


@pytest.mark.parametrize("text", ["go with the trolley to the garage", "go with the pitcher to the sink",
                                  "go with the controller to the couch"])
def test_a_noun_that_is_also_a_thing_keeps_going_with_it_a_go(library: Library, text: str) -> None:
    assert [f for f, _ in _frames(text, library)] == ["Bring"]   # a pitcher is a jug too: no company, a thing
    #                                                              taken there (words31; a bare Go dropped it)


@pytest.mark.parametrize(("text", "expected"), [
    ("get to the kitchen", [("Go", {"goal": "the kitchen"})]),
    ("get into the bedroom", [("Go", {"goal": "the bedroom"})]),
    ("get over to the garage", [("Go", {"goal": "the garage"})]),
])
def test_getting_somewhere_with_nothing_to_take_is_going(library: Library, text: str, expected: list[object]) -> None:
    assert _frames(text, library) == expected


def test_getting_a_thing_somewhere_is_still_bringing(library: Library) -> None:
    assert _frames("get the mug to the office", library) == [("Bring", {"theme": "the mug", "goal": "the office"})]
    for text in ("pick up the mug and take to the office", "pick up the mug and get to the office"):
        picked, brought = parse_command(text, library).frames
        assert (picked.frame, brought.frame) == ("Pick", "Bring")   # "take [it] to the office": the mug
        assert brought.elements["theme"].refers_to == (0, "theme")
    assert [f for f, _ in _frames("put in the cabinet", library)] == ["Place"]    # "put" takes nothing


@pytest.mark.parametrize("text", ["take Sam", "take the visitor", "take her", "take Omar along"])
def test_taking_a_person_with_no_goal_is_guiding(library: Library, text: str) -> None:
    assert [f for f, _ in _frames(text, library)] == ["Guide"]


@pytest.mark.parametrize(("text", "expected"), [
    ("move the bowl", [("Place", {"theme": "the bowl"})]),            # the thing moved, not a place gone to
    ("relocate a cup", [("Place", {"theme": "a cup"})]),
    ("return the mug", [("Bring", {"theme": "the mug"})]),
    ("return it", [("Bring", {"theme": "it"})]),
])
def test_a_verb_of_going_and_of_moving_moves_its_bare_object(library: Library, text: str,
                                                           expected: list[object]) -> None:
    assert _frames(text, library) == expected


@pytest.mark.parametrize(("text", "expected"), [
    ("move to the kitchen", [("Go", {"goal": "the kitchen"})]),       # no object: going
    ("return to the kitchen", [("Go", {"goal": "the kitchen"})]),
    ("move the chair", [("Go", {"goal": "the chair"})]),              # furniture is fixed: a place
    ("reach the table", [("Go", {"goal": "the table"})]),             # a verb of going only
    ("move the bowl to the sink", [("Place", {"theme": "the bowl", "goal": "the sink"})]),
])
def test_going_stays_going_without_a_movable_object(library: Library, text: str, expected: list[object]) -> None:
    assert _frames(text, library) == expected


@pytest.mark.parametrize(("text", "expected"), [
    # a thing cannot be led: shown to someone, it is brought to them
    ("show me the remote", [("Bring", {"theme": "the remote", "recipient": "me"})]),
    ("show grandma the photos", [("Bring", {"theme": "the photos", "recipient": "grandma"})]),
    ("show the letter to Jo", [("Bring", {"theme": "the letter", "recipient": "Jo"})]),
    # a room is where they are led; the way there is no thing; a person is led as before
    ("show me the kitchen", [("Guide", {"theme": "me", "goal": "the kitchen"})]),
    ("show the visitor the laundry room", [("Guide", {"theme": "the visitor", "goal": "the laundry room"})]),
    ("show them the way to the garage", [("Guide", {"theme": "them", "goal": "the garage"})]),
    ("show the guest to the living room", [("Guide", {"theme": "the guest", "goal": "the living room"})]),
])
def test_showing_a_thing_brings_it_and_showing_a_room_leads_there(library: Library, text: str,
                                                                  expected: list[object]) -> None:
    assert _frames(text, library) == expected


@pytest.mark.parametrize(("text", "goal"), [
    ("put the newspaper next to the remote on the sofa", "the sofa"),      # the sofa holds it
    ("place two clocks in front of the phone on the desk", "the desk"),
    ("put the mug to the left of the bread on the counter", "the counter"),
    ("put the book under the pillow on the bed", "the bed"),
    ("put the newspaper next to the remote", "the remote"),                # nothing said to hold it: as said
    ("put the cup next to the sink in the kitchen", "the sink in the kitchen"),   # a room says where, not on what
    ("put the cup on the plate on the table", "the plate on the table"),   # on it: the plate holds it (then the table)
])
def test_a_thing_put_beside_another_ends_where_the_other_is(library: Library, text: str, goal: str) -> None:
    assert [(f, e.get("goal")) for f, e in _frames(text, library)][0] == ("Place", goal)


@pytest.mark.parametrize(("text", "frames"), [
    ("put a spoon with a blue handle in the drawer", ["Place"]),           # its part: nothing in it
    ("put the box with a lid on the shelf", ["Place"]),
    ("put the box with a pen in it on the shelf", ["Place", "Place"]),     # contents: put in first
])
def test_a_thing_said_with_its_part_has_no_contents(library: Library, text: str, frames: list[str]) -> None:
    assert [f for f, _ in _frames(text, library)] == frames


def _placed(text: str, library: Library) -> list[tuple[str, str | None, str | None]]:
    parse = parse_command(text, library)
    return [(f.frame, parse.resolve(f.elements["theme"]).head if "theme" in f.elements else None,
             parse.resolve(f.elements["goal"]).head if "goal" in f.elements else None) for f in parse.frames]


@pytest.mark.parametrize(("text", "expected"), [
    # a spoon holds nothing: the mug said with it holds the spoon, and the mug is what is put on the table
    ("put the spoon with the mug on the table", [("Place", "spoon", "mug"), ("Place", "mug", "table")]),
    ("move a knife with a bowl to the counter", [("Place", "knife", "bowl"), ("Place", "bowl", "counter")]),
    ("put the ladle with the plate in the cabinet", [("Place", "ladle", "plate"), ("Place", "plate", "cabinet")]),
    # a bowl holds things: as said
    ("put a bowl with a fork on the table", [("Place", "fork", "bowl"), ("Place", "bowl", "table")]),
    # neither holds (a book is in no category): as said; a frame that puts nothing anywhere: nothing carried
    ("put the book with the pen on the desk", [("Place", "pen", "book"), ("Place", "book", "desk")]),
    ("wash the spoon with the sponge", [("Clean", "spoon", None)]),
])
def test_a_thing_that_holds_nothing_said_with_a_container_goes_in_it(library: Library, text: str,
                                                                     expected: list[object]) -> None:
    assert _placed(text, library) == expected


@pytest.mark.parametrize(("text", "frames"), [
    ("put a slice of cooked bread on the table", ["Slice", "Heat", "Place"]),      # the slice is what was cooked
    ("put a heated slice of bread on the table", ["Slice", "Heat", "Place"]),
    ("put cold sliced lettuce on the table", ["Slice", "Cool", "Place"]),           # the adjectives' order: none
    ("put a clean, sliced potato in the fridge", ["Slice", "Clean", "Place"]),
    ("heat the bread, then slice it", ["Heat", "Slice"]),                           # said in order: kept
    ("put the heated bread on the table", ["Heat", "Place"]),
])
def test_pieces_are_cut_before_the_states_their_phrase_gives_them(library: Library, text: str,
                                                                  frames: list[str]) -> None:
    assert [f for f, _ in _frames(text, library)] == frames


@pytest.mark.parametrize(("text", "expected"), [
    ("move the towel from next to the mirror to the bathtub",
     [("Place", {"theme": "the towel from next to the mirror", "goal": "the bathtub"})]),
    ("move the towel from the mirror to the bathtub",
     [("Place", {"theme": "the towel from the mirror", "goal": "the bathtub"})]),
    ("move the bottle from behind the toilet to the sink",
     [("Place", {"theme": "the bottle from behind the toilet", "goal": "the sink"})]),
])
def test_from_a_place_said_by_another_preposition_is_where_it_was(library: Library, text: str,
                                                                   expected: list[object]) -> None:
    assert _frames(text, library) == expected


def test_them_after_a_run_of_like_frames_is_each_of_their_things(library: Library) -> None:
    """"get the milk from the fridge and the mug from the living room and put them on the dining table" (e2e19): the
    gapped second clause made two Picks, and "them" was the mug alone; it gathers the run's themes."""
    frames = parse_command("get the milk from the fridge and the mug from the living room and put them on the table",
                           library).frames
    them = frames[2].elements["theme"]
    assert [c.refers_to for c in them.conjuncts] == [(0, "theme"), (1, "theme")] and them.plural
    frames = parse_command("pick up the apple and the pear and put them in the fridge", library).frames
    assert frames[1].elements["theme"].refers_to == (0, "theme") and not frames[1].elements["theme"].conjuncts
    frames = parse_command("open the fridge, take the milk and put it on the table", library).frames
    assert frames[2].elements["theme"].refers_to == (1, "theme") and not frames[2].elements["theme"].conjuncts


@pytest.mark.parametrize(("text", "place", "ref"), [
    ("go to the bedroom and tell me how many books are there", "bedroom", (0, "goal")),
    ("walk into the garage, then count how many bikes there are", "garage", (0, "goal")),
    ("head to the den and find out how many people are there right now", "den", (0, "goal")),
    ("look in the pantry and let me know how many jars are there", "pantry", (0, "ground")),
])
def test_how_many_are_there_after_a_place_asks_of_that_place(library: Library, text: str, place: str,
                                                             ref: tuple[int, str]) -> None:
    """words43: the existential "there" was dropped and the whole house counted; it is where the clause before went,
    as "count the books there" is."""
    count = parse_command(text, library).frames[-1]
    ground = count.elements["ground"]
    assert count.frame == "Count" and (ground.text, ground.head, ground.refers_to) == ("there", place, ref)


@pytest.mark.parametrize("text", [
    "how many chairs are there?",                                        # no place before: existential, no place
    "go to the kitchen and tell me how many cups are there on the table",  # a place said in the clause
    "how many cups are there? then go to the kitchen",                   # the place comes after
])
def test_how_many_are_there_without_a_place_before_names_none(library: Library, text: str) -> None:
    count = next(f for f in parse_command(text, library).frames if f.frame == "Count")
    assert count.elements.get("ground") is None or count.elements["ground"].text == "the table"


def test_how_many_there_are_of_nothing_said_reports_the_count_before(library: Library) -> None:
    """"there" names no place where nothing is counted: the telling reports the count before (words41's merge)."""
    assert _frames("count the cups in the sink and let me know how many there are", library) == [
        ("Count", {"theme": "the cups", "ground": "the sink"})]


@pytest.mark.parametrize(("text", "prep", "column"), [
    ("go to", "to", 4),
    ("bring the cup to", "to", 15),
    ("put the cup in", "in", 13),
    ("take the book from", "from", 15),
    ("drop the keys into.", "into", 15),
    ("walk to and wait there", "to", 6),                           # ends its clause, not the command
])
def test_a_preposition_with_nothing_after_it_is_refused_at_it(library: Library, text: str, prep: str,
                                                              column: int) -> None:
    """Issue #13: read as a particle, it left the place unsaid and the command went nowhere, silently."""
    with pytest.raises(CommandError) as refused:
        parse_command(text, library)
    assert refused.value.column == column and refused.value.message.startswith(f"{prep!r} ")
    assert "say where" in refused.value.message or "say to whom" in refused.value.message


@pytest.mark.parametrize(("text", "frame"), [
    ("bring it in", "Bring"), ("come in", "Go"), ("turn it on", "ToggleOn"), ("pick it up", "Pick"),
    ("put it down", "Place"), ("which room should I go to", "Tell"), ("put the cup in the box", "Place"),
])
def test_a_particle_of_the_unit_or_a_fronted_object_is_no_stranded_preposition(library: Library, text: str,
                                                                              frame: str) -> None:
    assert [f for f, _ in _frames(text, library)] == [frame]


def test_a_putting_in_said_last_after_a_place_opened_is_in_there(library: Library) -> None:
    """"open the oven, put the tray in and shut it": "in" is in the oven opened before (it was a Place with no goal,
    the place dropped silently). A place only named ("move the pan to the shelf, put the egg in": in the pan, not
    the shelf) is not taken for it: as before, no goal."""
    parse = parse_command("open the oven, put the tray in and shut it", library)
    assert [f.frame for f in parse.frames] == ["Open", "Place", "Close"]
    assert parse.frames[1].elements["goal"].refers_to == (0, "theme")
    assert parse.frames[1].elements["theme"].head == "tray"
    parse = parse_command("move the pan to the shelf, put the egg in", library)
    assert [f.frame for f in parse.frames] == ["Place", "Place"]
    assert "goal" not in parse.frames[1].elements


@pytest.mark.parametrize(("text", "frame", "theme"), [
    ("leave the heater turned on", "ToggleOn", "the heater"),
    ("leave the lamp switched off", "ToggleOff", "the lamp"),
    ("leave the kitchen light turned on in the hall", "ToggleOn", "the kitchen light in the hall"),
    ("leave the heater on", "ToggleOn", "the heater"),
])
def test_a_participle_of_the_state_before_the_particle_is_no_word_of_the_thing(
        library: Library, text: str, frame: str, theme: str) -> None:
    """Issue #13: "leave the heater turned on" had the theme "the heater turned" (head "turned")."""
    assert _frames(text, library) == [(frame, {"theme": theme})]


@pytest.mark.parametrize(("text", "place"), [
    ("take the pear to the fridge put it in", "fridge"),               # run on, no comma
    ("carry the pots to the cupboard, then put them in", "cupboard"),
    ("bring the bread to the oven and put the bread in", "oven"),
])
def test_a_putting_in_said_last_after_the_thing_was_taken_to_a_place_is_in_there(
        library: Library, text: str, place: str) -> None:
    """words47: "take the tomato to the microwave put it in" had no goal; the place the clause before took the same
    thing to is where "in" puts it (the goal refers to it). Another thing put in stays without a goal (it may go in
    the thing moved: "move the pan to the shelf, put the egg in")."""
    parse = parse_command(text, library)
    assert [f.frame for f in parse.frames] == ["Bring", "Place"]
    goal = parse.frames[1].elements["goal"]
    assert goal.refers_to == (0, "goal") and goal.head == place
    other = parse_command("take the pear to the fridge, put the plum in", library)
    assert "goal" not in other.frames[1].elements


@pytest.mark.parametrize(("text", "theme", "ground"), [
    ("check the attic for people", "people", "the attic"),
    ("scan the hall for anyone wearing a hat", "anyone wearing a hat", "the hall"),
    ("search the porch for a woman in a green coat", "a woman in a green coat", "the porch"),
    ("look around the garden for any guests", "any guests", "the garden"),
])
def test_a_place_examined_for_anyone_of_a_kind_is_searched_for_them(
        library: Library, text: str, theme: str, ground: str) -> None:
    """words48: "check the bedroom for people" was a LookAt of "the bedroom for people" (a person after "for" says
    for whom); people said as anyone of a kind are sought, as a thing is."""
    assert _frames(text, library) == [("Find", {"theme": theme, "ground": ground})]


@pytest.mark.parametrize("text", ["check the oven for me", "check the hall for the boss"])
def test_a_place_examined_for_someone_known_is_looked_at_for_them(library: Library, text: str) -> None:
    assert [f.frame for f in parse_command(text, library).frames] == ["LookAt"]


@pytest.mark.parametrize(("text", "goal"), [
    ("stop by the garage and grab the drill", "the garage"),
    ("drop by the study", "the study"),
    ("come by the porch", "the porch"),
])
def test_a_visit_said_with_by_is_going(library: Library, text: str, goal: str) -> None:
    """words48: "stop by the kitchen" was a ToggleOff refused for its "by" phrase, "drop by the office" a Place with
    no theme; "stop by", "drop by", "come by" are Go's units (framelib/motion.yaml)."""
    assert _frames(text, library)[0] == ("Go", {"goal": goal})
    assert _frames("drop the keys by the door", library)[0][0] == "Place"
