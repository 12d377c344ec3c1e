"""Grounding noun phrases in a vocabulary of object classes; vocabulary files."""

from __future__ import annotations

from pathlib import Path

import pytest

from seal_cli.errors import SealError
from seal_cli.frames.library import Library
from seal_cli.language.grounding import Vocabulary, load_vocabulary, vocabulary_of_map
from seal_cli.language.parser import parse_command
from seal_cli.language.wordusage import WordUsage


@pytest.fixture(autouse=True)
def rules_alone(monkeypatch: pytest.MonkeyPatch) -> None:
    """These tests are of the rules: the statistics learned from ALFRED's train split (which would
    call a sink a SinkBasin) are off here and tested in test_wordusage.py."""
    monkeypatch.setattr("seal_cli.language.grounding.shipped_word_usage", WordUsage)


ALFRED_LIKE = Vocabulary.of(["AlarmClock", "Apple", "CounterTop", "DiningTable", "SideTable", "ToiletPaper",
                             "ToiletPaperRoll", "WineBottle", "SoapBottle", "KeyChain", "SoapBar", "Sink",
                             "SinkBasin", "tomato soup", "Laptop", "Bathtub", "Chair", "Tomato", "Dresser",
                             "Fridge", "Sofa", "GarbageCan", "Toilet"])


def theme_class(text: str, library: Library, vocabulary: Vocabulary = ALFRED_LIKE) -> str | None:
    return parse_command(f"find {text}", library, vocabulary).frames[0].elements["theme"].cls


@pytest.mark.parametrize(("phrase", "cls"), [
    ("the alarm clock", "AlarmClock"),        # exact, CamelCase split
    ("two red alarm clocks", "AlarmClock"),   # plural, modifiers
    ("the clock", "AlarmClock"),              # head word
    ("the counter", "CounterTop"),            # another word of the class name
    ("an apple slice", "Apple"),              # a modifier when the head is nothing known
    ("a slice of apple", "Apple"),            # the "of" phrase
    ("two rolls of toilet paper", "ToiletPaper"),   # an exact name beats a head word
    ("a bottle of wine", "WineBottle"),       # head word helped by the other words
    ("a set of keys", "KeyChain"),
    ("a bar of soap", "SoapBar"),
    ("the table", "DiningTable"),             # a tie: the class listed first
    ("the sink", "Sink"),
    ("some tomato soup", "tomato soup"),      # multiword class names
    ("the zorblax", None),                    # open vocabulary: no class, no error
    ("the lap top", "Laptop"),                # written apart: compared without separators
    ("a bath tub", "Bathtub"),
    ("the chair cushion", None),              # a compound is its head: a cushion, not a chair
    ("the table top", "DiningTable"),         # a region of the modifier's thing
    ("a tomato piece", "Tomato"),             # a portion of it
    ("a set of keys", "KeyChain"),            # a group of what "of" names
    ("the toilet tank", "Toilet"),            # a part of the modifier's thing
    ("the fridge door", "Fridge"),
    ("a chest of drawers", "Dresser"),        # a name with "of" in it (the library's synonyms)
    ("the refrigerator", "Fridge"),           # the library's synonyms
    ("the couch", "Sofa"),
    ("a waste bin", "GarbageCan"),
    ("the bin", "GarbageCan"),                # the head of a synonym ("trash bin"), like a class name's head
    ("the front left of the counter", "CounterTop"),   # a side of a region ("left of" is no preposition there)
    ("the lower right of the sink", "Sink"),
    ("the far left of the dresser", "Dresser"),
])
def test_noun_phrases_ground_to_classes(library: Library, phrase: str, cls: str | None) -> None:
    assert theme_class(phrase, library) == cls


def test_a_head_word_shared_by_several_classes_goes_to_the_first_listed(library: Library) -> None:
    tables = ["DiningTable", "SideTable", "CoffeeTable"]
    assert theme_class("the table", library, Vocabulary.of(tables)) == "DiningTable"
    assert theme_class("the table", library, Vocabulary.of(tables[::-1])) == "CoffeeTable"
    assert theme_class("the coffee table", library, Vocabulary.of(tables)) == "CoffeeTable"   # exact first
    assert theme_class("the cushion", library, Vocabulary.of(["Chair", "Pillow"])) == "Pillow"   # a synonym


def test_a_class_own_name_wins_over_another_class_synonym(library: Library) -> None:
    vocab = Vocabulary.of(["SideTable", "nightstand", "Towel", "HandTowel"])
    assert theme_class("the nightstand", library, vocab) == "nightstand"
    assert theme_class("the bedside table", library, vocab) == "SideTable"   # the set's first class listed
    assert theme_class("the towel", library, vocab) == "Towel"
    own = Vocabulary.of(["fridge"], {"fridge": ["cold box"]})               # a file's synonyms add to the library's
    assert theme_class("the cold box", library, own) == theme_class("the icebox", library, own) == "fridge"


def test_the_library_synonyms_join_a_vocabulary_by_any_name_of_their_set() -> None:
    vocab = Vocabulary.of(["refrigerator", "Couch"]).with_synonyms({"refrigerator": ("fridge",), "couch": ("sofa",)})
    assert vocab.ground_words(["fridge"]) == "refrigerator"
    assert vocab.ground_words(["sofas"]) == "Couch"
    assert Vocabulary.of(["cup"]).with_synonyms({}).ground_words(["mug"]) is None


def test_synonyms_and_names_compare_like_class_names() -> None:
    vocab = Vocabulary.of(["Fridge", "coffee_machine"], {"Fridge": ["refrigerator", "ice box"]})
    assert vocab.ground_words(["refrigerators"]) == "Fridge"
    assert vocab.ground_words(["ice", "box"]) == "Fridge"
    assert vocab.ground_words(["coffee", "machine"]) == "coffee_machine"
    assert vocab.ground_words(["the"]) is None
    assert Vocabulary.of(["cheezit"]).ground_words(["cheezits"]) == "cheezit"   # a plural nobody listed
    assert len(Vocabulary.of(["cup", "cup", "Cup"])) == 2      # exact duplicates dropped, spelling kept


def test_vocabulary_files(tmp_path: Path, library: Library) -> None:
    path = tmp_path / "vocab.yaml"
    path.write_text("- AlarmClock\n- {class: Fridge, synonyms: [refrigerator]}\n- counter top\n", encoding="utf-8")
    vocab = load_vocabulary(path)
    assert vocab.classes == ("AlarmClock", "Fridge", "counter top")
    parse = parse_command("put the clock from the counter in the refrigerator", library, vocab)
    place = parse.frames[0].elements
    assert (place["theme"].cls, place["goal"].cls) == ("AlarmClock", "Fridge")
    mapping = tmp_path / "mapping.yaml"
    mapping.write_text("classes: [cup, plate]\n", encoding="utf-8")
    assert load_vocabulary(mapping).classes == ("cup", "plate")


ARENA = ('{"names": ["Robin", "Jules"], "objects": ["knife", "orange juice"], "locations": ["sink", "desk"],'
         ' "rooms": ["kitchen"], "verb_dict": {"take": ["take"]}}')


def _recipient_or_goal(text: str, library: Library, vocab: Vocabulary | None) -> tuple[str, str, str | None]:
    (bring,) = parse_command(text, library, vocab).frames
    role = "recipient" if "recipient" in bring.elements else "goal"
    return role, bring.elements[role].head, bring.elements[role].kind


def test_an_arena_vocabulary_names_its_people_whatever_their_case(tmp_path: Path, library: Library) -> None:
    path = tmp_path / "arena.json"               # RoboCup@Home's own vocabulary file, as the generator reads it
    path.write_text(ARENA, encoding="utf-8")
    vocab = load_vocabulary(path)
    assert vocab.classes == ("knife", "orange juice", "sink", "desk", "kitchen")
    assert vocab.people == {"robin", "jules"}
    assert _recipient_or_goal("deliver the knife to robin", library, vocab) == ("recipient", "Robin", "person")
    assert _recipient_or_goal("take the orange juice to jules", library, vocab)[0] == "recipient"
    assert _recipient_or_goal("deliver the knife to the sink", library, vocab)[0] == "goal"
    # without a vocabulary naming them, a word of the dictionary is a name only said bare and singular where a
    # person goes (words19: a bird is delivered nothing)
    assert _recipient_or_goal("deliver the knife to robin", library, None)[0] == "recipient"
    assert _recipient_or_goal("deliver the knife to the robin", library, None) == ("goal", "robin", "thing")


def test_a_maps_people_are_recipients_whatever_their_case(library: Library) -> None:
    from seal_cli.maps.formats.map_server import load_map

    vocab = vocabulary_of_map(load_map(Path(__file__).resolve().parents[2] / "maps" / "apartment.yaml"))
    assert _recipient_or_goal("deliver the cup to anna", library, vocab) == ("recipient", "Anna", "person")
    assert vocab.house and not Vocabulary.of(["cup"]).house       # a map's classes are a house's


@pytest.mark.parametrize(("content", "words", "at"), [
    ("cup: 1\n", "YAML list", "1:1"),
    ("[]\n", "no class", "1:1"),
    ("- {synonyms: [a]}\n", "entry 1", "1:3"),
    ("- cup\n- {class: Fridge, synonyms: refrigerator}\n", "entry 2: synonyms must be a list", "2:29"),
    ("classes:\n  - cup\n  - [x]\n", "entry 2 is neither", "3:5"),
    ("classes: [cup]\npeople: [5]\n", "people: must be", "2:9"),
    ("- [a, b\n", "YAML syntax error", "2:1"),
])
def test_bad_vocabulary_files_are_clear_errors(tmp_path: Path, content: str, words: str, at: str) -> None:
    """Each at its line and column (they named the file alone, and printed the entry's repr)."""
    path = tmp_path / "bad.yaml"
    path.write_text(content, encoding="utf-8")
    with pytest.raises(SealError) as caught:
        load_vocabulary(path)
    assert words in str(caught.value) and str(caught.value).startswith(f"{path}:{at}: ")


def test_a_missing_vocabulary_file_is_an_error(tmp_path: Path) -> None:
    with pytest.raises(SealError, match="no such file"):
        load_vocabulary(tmp_path / "nope.yaml")


def test_a_maps_classes_make_a_vocabulary() -> None:
    class Thing:
        def __init__(self, cls: str) -> None:
            self.cls = cls

    class FakeMap:
        places = (Thing("fridge"), Thing("kitchen_table"))
        objects = (Thing("cup"),)
        priors = {"spoon": {}, "cup": {}}

    vocab = vocabulary_of_map(FakeMap())
    assert vocab.classes == ("fridge", "kitchen_table", "cup", "spoon")
    assert vocab.ground_words(["kitchen", "tables"]) == "kitchen_table"


SCENE = Vocabulary.of(["DiningTable", "CoffeeTable", "SideTable", "SinkBasin", "Sink", "BathtubBasin", "Bathtub",
                       "DeskLamp", "FloorLamp", "HandTowel", "Towel", "Knife", "ButterKnife", "CounterTop", "CD"],
                      {"CD": ["disc"]})


@pytest.mark.parametrize(("present", "phrase", "cls"), [
    (["SideTable", "SinkBasin"], "the table", "SideTable"),        # the one table the room has
    (["CoffeeTable", "SideTable"], "the table", "CoffeeTable"),    # a tie: the vocabulary's order
    (["SinkBasin", "Toilet"], "the sink", "SinkBasin"),            # only the basin: "sink" is the basin
    (["Sink", "SinkBasin"], "the sink", "Sink"),                   # both: the exact name
    (["BathtubBasin"], "the tub", "BathtubBasin"),                 # the whole's synonyms too
    (["BathtubBasin"], "the bath", "BathtubBasin"),
    (["FloorLamp", "SideTable"], "the lamp", "FloorLamp"),         # whichever lamp is there
    (["DeskLamp", "SideTable"], "the lamp", "DeskLamp"),
    (["HandTowel"], "a towel", "HandTowel"),                       # no exact class: the one whose head it is
    (["HandTowel", "Towel"], "a towel", "Towel"),                  # an exact name first
    (["ButterKnife", "Apple"], "a knife", "ButterKnife"),
    (["CounterTop"], "the counter", "CounterTop"),                 # the whole of a part
    (["CD"], "two CDs", "CD"),                                     # a short plural the dictionary lacks
    (["CD"], "the discs", "CD"),                                   # the vocabulary's own synonyms survive
    (["Apple"], "the table", None),                                # nothing present: no class
])
def test_a_scene_grounds_words_in_the_classes_it_has(library: Library, present: list[str], phrase: str,
                                                     cls: str | None) -> None:
    assert theme_class(phrase, library, SCENE.restricted_to(present)) == cls


def test_restricted_keeps_the_vocabulary_order_and_the_given_spelling() -> None:
    scene = SCENE.restricted_to(["side_table", "cd", "dining_table", "pineapple"])
    assert scene.classes == ("dining_table", "side_table", "cd", "pineapple")   # unlisted classes last
    assert scene.ground_words(["disc"]) == "cd" and scene.ground_words(["pineapple"]) == "pineapple"
    assert SCENE.restricted_to([]).classes == ()


def test_another_class_synonym_names_a_thing_only_by_its_head(library: Library) -> None:
    # DeskLamp is also a "table lamp": that makes it a lamp, not a table
    vocab = Vocabulary.of(["DeskLamp", "Desk"])
    assert theme_class("the table", library, vocab) is None
    assert theme_class("the table lamp", library, vocab) == "DeskLamp"
    assert theme_class("the light", library, vocab) == "DeskLamp"                # "desk light": its head
    assert theme_class("a lettuce head", library, Vocabulary.of(["Lettuce"])) == "Lettuce"   # "head of lettuce"


def test_a_part_is_called_by_its_whole_only_when_the_whole_is_no_class(library: Library) -> None:
    assert theme_class("the sink", library, Vocabulary.of(["SinkBasin"])) == "SinkBasin"
    assert theme_class("the sink", library, Vocabulary.of(["SinkBasin", "Sink"])) == "Sink"
    assert theme_class("the fridge", library, Vocabulary.of(["FridgeDoor", "Fridge"])) == "Fridge"
    assert theme_class("the roll", library, Vocabulary.of(["PaperTowelRoll"])) == "PaperTowelRoll"
    assert theme_class("the kitchen roll", library, Vocabulary.of(["PaperTowelRoll"])) == "PaperTowelRoll"


def test_a_map_vocabulary_follows_the_same_rules(library: Library) -> None:
    class Thing:
        def __init__(self, cls: str) -> None:
            self.cls = cls

    class Kitchen:
        places = (Thing("sink_basin"), Thing("side_table"))
        objects = (Thing("butter_knife"), Thing("floor_lamp"))
        priors: dict[str, dict[str, float]] = {}

    parse = parse_command("put the knife on the table by the lamp", library, vocabulary_of_map(Kitchen()))
    place = parse.frames[0].elements
    assert (place["theme"].cls, place["goal"].cls) == ("butter_knife", "side_table")
    assert theme_class("the sink", library, vocabulary_of_map(Kitchen())) == "sink_basin"


def test_pieces_are_portions() -> None:
    from seal_cli.language.grounding import PIECES, PORTIONS

    assert PIECES <= PORTIONS
    assert Vocabulary.of(["Apple"]).ground_words(["apple", "section"]) == "Apple"


def test_the_people_of_a_map_or_a_vocabulary_are_names_however_written(library: Library, tmp_path: Path) -> None:
    from seal_cli.maps.formats.map_server import load_map
    from seal_cli.resources import map_path

    world = vocabulary_of_map(load_map(map_path("apartment")))          # Anna and Ben live there
    assert world.people == frozenset({"anna", "ben"})
    parse = parse_command("take anna to the kitchen", library, world)
    assert [(f.frame, {r: e.text for r, e in f.elements.items()}) for f in parse.frames] == [
        ("Guide", {"theme": "anna", "goal": "the kitchen"})]             # the text as said
    assert parse_command("take anna", library, world).frames[0].frame == "Guide"
    assert parse_command("take anna", library).frames[0].frame == "Guide"  # no world: a word no dictionary has
    assert parse_command("take apples", library).frames[0].frame == "Pick"  # a word of English: a thing
    path = tmp_path / "v.yaml"
    path.write_text("classes: [knife]\npeople: [Robin]\n")
    vocab = load_vocabulary(path)
    (bring,) = parse_command("deliver the knife to robin", library, vocab).frames
    assert bring.elements["recipient"].text == "robin"                     # a bird to the dictionary, a name here
    assert parse_command("take robin to the kitchen", library, vocab).frames[0].frame == "Guide"
    assert parse_command("take robin to the kitchen", library).frames[0].frame == "Bring"   # no world: a bird
    path.write_text("classes: [knife]\npeople: [Robin, 3]\n")
    with pytest.raises(SealError, match="people: must be a list of names") as err:
        load_vocabulary(path)
    assert err.value.file == str(path)


@pytest.mark.parametrize("where", ["to the bottom left of the sink", "to bottom left of the sink",
                                   "to left of the sink", "to the left of the sink"])
def test_to_a_region_and_side_of_a_thing_is_beside_it(library: Library, where: str) -> None:
    frames = parse_command(f"put the soap in the cabinet {where}", library, ALFRED_LIKE).frames
    assert [f.frame for f in frames] == ["Place"]
    goal = frames[0].elements["goal"]
    assert (goal.head, goal.text) == ("cabinet", f"the cabinet {where}")   # said where it is


def test_a_vocabulary_past_its_bound_is_refused_while_it_is_read(tmp_path: Path) -> None:
    import time

    from seal_cli.language.grounding import MAX_VOCABULARY_VALUES

    path = tmp_path / "v.yaml"
    path.write_text("".join(f"- w{k}\n" for k in range(300_000)))
    start = time.perf_counter()
    with pytest.raises(SealError, match=rf"v\.yaml:{MAX_VOCABULARY_VALUES}:3: this vocabulary holds more than "):
        load_vocabulary(path)
    assert time.perf_counter() - start < 10  # it was read, used and accepted in 25 s


def test_a_part_no_class_names_is_its_possessor_s(library: Library) -> None:
    assert theme_class("the toilet's water tank", library) == "Toilet"       # a part of the toilet: the toilet
    assert theme_class("the fridge's door", library) == "Fridge"
    assert theme_class("the water tank", library) is None                   # no whole said: nothing
    assert theme_class("the toilet's soap bar", library) == "SoapBar"       # a class of its own: itself
    assert theme_class("the man's laptop", library) == "Laptop"
    assert theme_class("the man's shirt", library) is None                  # a person's: never the person


@pytest.mark.parametrize(("text", "where"), [
    ("- cup\n- " + "c" * 101 + "\n", (2, 3)),
    ("- cup\n- {class: spoon, synonyms: [" + "s" * 500 + "]}\n", (2, 3)),
])
def test_a_vocabulary_name_longer_than_any_name_is_refused_at_its_entry(tmp_path: Path, text: str,
                                                                       where: tuple[int, int]) -> None:
    """hostile19: a vocabulary class of 1,000 letters was taken (names.MAX_NAME bounds every other name)."""
    (tmp_path / "v.yaml").write_text(text)
    with pytest.raises(SealError, match=r"name '.*' is \d+ characters long; a name has at most 100") as caught:
        load_vocabulary(tmp_path / "v.yaml")
    assert (caught.value.where.line, caught.value.where.column) == where
    (tmp_path / "v.yaml").write_text("- " + "c" * 100 + "\n")
    assert load_vocabulary(tmp_path / "v.yaml").classes == ("c" * 100,)


def test_the_form_said_tells_apart_classes_one_by_their_lemmas() -> None:
    """A house with a drinking ``glass`` and reading ``glasses`` (both "glass" by lemma, e2e22): "a glass" is the
    glass, "my glasses" the glasses, in either order of the classes; with only one of them, either form names it."""
    for classes in (["glasses", "glass", "cup"], ["glass", "glasses", "cup"]):
        both = Vocabulary.of(classes)
        assert both.ground_words(["a", "glass"]) == "glass" and both.ground_words(["glass"]) == "glass"
        assert both.ground_words(["my", "glasses"]) == "glasses"
        assert both.ground_words(["wine", "glass"]) == "glass"
        assert both.ground_words(["a", "glass"], -1, ["water"]) == "glass"     # its own words before its "of"
        assert both.ground_words(["a", "pair"], -1, ["glasses"]) == "glasses"  # its "of" phrase's form
    assert Vocabulary.of(["glasses", "cup"]).ground_words(["glass"]) == "glasses"
    assert Vocabulary.of(["glass", "cup"]).ground_words(["glasses"]) == "glass"


@pytest.mark.parametrize(("text", "said"), [
    ('- "cu\\e[31mp"\n- mug\n', r"v\.yaml:1:3: entry 1: name 'cu\\x1b\[31mp' holds '\\x1b' \(U\+001B\), a control"),
    ('- cup\n- {class: mug, synonyms: ["be\\u202eaker"]}\n', r"v\.yaml:2:3: entry 2: name 'be\\u202eaker' holds"),
])
def test_a_vocabulary_name_no_terminal_shows_is_refused_at_its_entry(tmp_path: Path, text: str, said: str) -> None:
    # hostile28: the escape sequence reached the terminal in every table naming the class
    (tmp_path / "v.yaml").write_text(text, encoding="utf-8")
    with pytest.raises(SealError, match=said):
        load_vocabulary(tmp_path / "v.yaml")


@pytest.mark.parametrize(("text", "theme"), [
    ("take robin the cup", "the cup"),
    ("bring morgan a coffee", "a coffee"),
    ("could you take grace her glasses", "her glasses"),
])
def test_a_lower_case_name_of_the_world_before_a_second_object_is_the_recipient(
        library: Library, tmp_path: Path, text: str, theme: str) -> None:
    """words47 (issue #13): a lower-case word the world names as a person ("robin", "grace": nouns to the dictionary)
    said after "take"/"bring" and before a second phrase is the person the thing is for."""
    path = tmp_path / "v.yaml"
    path.write_text("classes: [cup]\npeople: [Robin, Morgan, Grace]\n")
    (bring,) = parse_command(text, library, load_vocabulary(path)).frames
    assert bring.frame == "Bring"
    assert (bring.elements["theme"].text, bring.elements["recipient"].kind) == (theme, "person")
