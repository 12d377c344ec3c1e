"""A verb inside an element's text is a clause of its own or an error at the verb, never dropped silently."""

from __future__ import annotations

import json

import pytest

from seal_cli.frames.library import Library
from seal_cli.language.lexicon import CommandError, tokenize
from seal_cli.language.parser import CommandParser, parse_command
from seal_cli.language.swallowed import swallowed
from seal_cli.language.unplaced import EXPECTED as UNPLACED
from seal_cli.language.values import Evoked, Parse, Phrase


def _one_element(text: str, frame: str, role: str, said: str) -> Parse:
    """A parse whose one element holds ``said`` (as a parser that swallowed a clause would make it)."""
    start = text.index(said)
    phrase = Phrase(said, said.split()[-1], span=(start, start + len(said)))
    return Parse(text, (Evoked(frame, frame.lower(), (0, len(text)), {role: phrase}),))


@pytest.mark.parametrize(("text", "said", "verb"), [
    ("go to the door to greet Maria", "the door to greet Maria", "greet"),     # an infinitive after the goal
    ("take the box to the hall to open", "the hall to open", "open"),          # a purpose, its object unsaid
    ("meet Ken by the desk escort him out", "the desk escort", "escort"),      # an imperative before its object
    ("grab a mug from the shelf bring it here", "the shelf bring it", "bring"),
    ("take a cup from the sink handing it to Ana", "the sink handing it", "handing"),   # a participle, its object
    ("go to the kitchen and wait there", "the kitchen and wait there", "wait"),   # mostly a verb, after "and"
    ("go to the hall and dance", "the hall and dance", "dance"),                 # ... before the end
])
def test_a_verb_in_an_element_is_found(library: Library, text: str, said: str, verb: str) -> None:
    parse = _one_element(text, "Go", "goal", said)
    (found,) = swallowed(parse, tokenize(text), CommandParser.of(library).lexicon)
    assert (found.frame, found.element, found.verb, found.start) == (0, "goal", verb, text.index(verb))


@pytest.mark.parametrize(("text", "said"), [
    ("put the hand soap on the sink", "the hand soap"),                   # a noun after a determiner
    ("put a tray holding two cups on the table", "a tray holding two cups"),   # a participle: what it holds
    ("put the keys back where you found them", "where you found them"),   # a verb with a subject says where
    ("bring me a washed sliced pear", "a washed sliced pear"),            # results said before the noun
    ("go to the light switch", "the light switch"),
    ("bring the cup and plate", "the cup and plate"),                    # mostly a noun after "and": a list
    ("bring the salt and pepper to me", "the salt and pepper"),
    ("go to the kitchen and Wait there", "the kitchen and Wait there"),  # a name, not a verb
])
def test_nouns_participles_and_subjects_verbs_are_no_swallowed_verbs(library: Library, text: str, said: str) -> None:
    parse = _one_element(text, "Place", "theme", said)
    assert swallowed(parse, tokenize(text), CommandParser.of(library).lexicon) == ()


def test_a_class_of_the_library_is_a_noun_after_to(library: Library) -> None:
    text = "put the pan behind the kettle next to microwave"
    parse = _one_element(text, "Place", "goal", "the kettle next to microwave")
    lexicon, things = CommandParser.of(library).lexicon, library.taxonomy.known_classes
    assert [x.verb for x in swallowed(parse, tokenize(text), lexicon)] == ["microwave"]   # "microwave" is a verb too
    assert swallowed(parse, tokenize(text), lexicon, things) == ()                    # but names a thing here


def test_a_word_the_tagger_joined_is_read_by_its_first(library: Library) -> None:
    from seal_cli.language.lexicon import Tagger

    text = "cut the bread to warm up slices"
    parser = CommandParser.of(library)
    words = Tagger(parser.lexicon, tokenize(text), text).run()
    parse = _one_element(text, "Slice", "theme", "the bread to warm up slices")
    assert [x.verb for x in swallowed(parse, words, parser.lexicon)] in (["warm up"], ["warm"])


@pytest.mark.parametrize(("text", "verb"), [
    ("go to the door to greet Maria", "greet"),
    ("take the box to the hall to open", "open"),
    ("take the lamp from the box handing it to Ana", "handing"),
    ("grab a torch to hold up to the window", "hold"),
    ("meet Ken by the desk escort him out", "escort"),
    ("grab the mug from the shelf bring it to me", "bring"),
    ("walk to the bench to find Omar", "find"),
])
def test_the_parser_makes_it_a_clause_or_refuses_it(library: Library, text: str, verb: str) -> None:
    try:
        parse = parse_command(text, library)
    except CommandError as error:
        if error.expected == [UNPLACED]:    # a clause of its own, and a phrase of it no element takes: refused at
            assert f"({verb!r})" in error.message and error.column > text.index(verb) + 1    # that (words31)
            return
        assert error.column == text.index(verb) + 1 and verb in error.message
        assert error.expected == ["a clause of its own"]
    else:
        assert verb in [f.lexical_unit for f in parse.frames]
        assert swallowed(parse, tokenize(text), CommandParser.of(library).lexicon) == ()


@pytest.mark.parametrize("text", ["go to the bedroom and find Ana", "tell Ken to open the door",
                                  "put a tray holding two cups on the table"])
def test_commands_without_a_hidden_clause_parse(library: Library, text: str) -> None:
    assert parse_command(text, library).frames


def test_no_gpsr_command_swallows_a_clause(library: Library, shared_data) -> None:
    texts = [json.loads(line)["text"] for line in (shared_data / "gpsr" / "dev.jsonl").open()][:600]
    lexicon = CommandParser.of(library).lexicon
    assert all(swallowed(parse_command(t, library), tokenize(t), lexicon) == () for t in texts)


def test_the_command_line_reports_a_refused_one_as_an_error_object(library: Library) -> None:
    from typer.testing import CliRunner

    from seal_cli.cli import app

    text = "take the lamp from the box handing it to Ana"        # a participle doing something, after a place
    try:
        parse_command(text, library)
    except CommandError:
        pass
    else:
        pytest.skip("the tagger now reads this participle as a clause of its own")
    result = CliRunner().invoke(app, ["parse", text, "--json"])
    assert result.exit_code == 1
    error = json.loads(result.stdout)["error"]
    assert error["column"] == text.index("handing") + 1 and "'handing' is a verb inside the source" in error["message"]


@pytest.mark.parametrize(("text", "verb", "says"), [
    # "sit" is a verb of the library (Place's "sit the vase on ..."), said with no object (hostile31's message)
    ("go to the kitchen and sit there", "sit", "'sit' is read here as a thing, not as the library's verb 'sit'"),
    ("take the cup and dance", "dance", "unknown verb 'dance'"),
    ("grab the towel, and kneel down", "kneel", "unknown verb 'kneel'"),
    ("go to the door and knock", "knock", "unknown verb 'knock'"),
])
def test_a_verb_after_and_is_a_clause_and_its_unknown_verb_an_error(
        library: Library, text: str, verb: str, says: str) -> None:
    with pytest.raises(CommandError) as raised:
        parse_command(text, library)
    assert says in raised.value.message and raised.value.column == text.index(verb) + 1


def test_wait_after_and_is_a_wait_there_the_place_before(library: Library) -> None:
    """words15: "wait" is a verb of the library now (Wait), its "there" the Go's goal."""
    parse = parse_command("go to the kitchen and wait there", library)
    assert [f.frame for f in parse.frames] == ["Go", "Wait"]
    assert parse.frames[1].elements["ground"].refers_to == (0, "goal")
    assert parse.frames[1].elements["ground"].head == "kitchen"


@pytest.mark.parametrize(("text", "theme"), [
    ("bring the cup and plate", ["cup", "plate"]),
    ("bring the salt and pepper", ["salt", "pepper"]),
    ("take a knife and fork", ["knife", "fork"]),
    ("bring me fish and chips", ["fish", "chip"]),
    ("bring the bread and butter", ["bread", "butter"]),
])
def test_nouns_after_and_stay_a_list(library: Library, text: str, theme: list[str]) -> None:
    (frame,) = parse_command(text, library).frames
    phrase = frame.elements["theme"]
    assert [c.head for c in phrase.conjuncts] == theme
