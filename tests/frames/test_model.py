"""The frame model: facts, actions, elements, lexical units, frames and their grounding."""

from __future__ import annotations

import pytest

from seal_cli.errors import SealError, SealErrors
from seal_cli.frames.model import Action, Element, Fact, Frame, LexicalUnit, parse_atom


def stir() -> Frame:
    return Frame("Stir", (LexicalUnit("stir"),),
                 (Element("theme", "container"), Element("instrument", "utensil", "spoon")),
                 (Fact.parse("holding(instrument)"),),
                 (Action.parse("navigate(theme)"), Action.parse("stir(instrument, theme)")),
                 (Fact.parse("stirred(theme)"),))


def test_parse_atom_reads_negation_and_arguments() -> None:
    assert parse_atom("not in(theme, goal)") == (True, "in", ("theme", "goal"))
    assert parse_atom("hand_empty") == (False, "hand_empty", ())
    assert parse_atom(" open( goal ) ") == (False, "open", ("goal",))


@pytest.mark.parametrize("text", ["in(theme, ", "holding(x))", "not", "2cups(x)", "a b", "in(theme,,goal)", ""])
def test_malformed_atoms_are_errors(text: str) -> None:
    with pytest.raises(SealError):
        Fact.parse(text)


def test_fact_text_round_trips() -> None:
    for text in ("hand_empty", "not holding(theme)", "in(theme, goal)"):
        assert str(Fact.parse(text)) == text


def test_where_does_not_take_part_in_equality() -> None:
    from seal_cli.errors import Where

    assert Fact.parse("open(x)", Where("a.yaml", 1, 2)) == Fact.parse("open(x)", Where("b.frame", 9, 9))
    assert hash(Fact("open", ("x",), where=Where("a", 1, 1))) == hash(Fact("open", ("x",)))


def test_actions_cannot_be_negated() -> None:
    with pytest.raises(SealError, match="cannot be negated"):
        Action.parse("not navigate(x)")


def test_lexical_units_are_normalised_and_checked() -> None:
    assert LexicalUnit("  Pick   Up ").text == "pick up"
    assert LexicalUnit("pick up").words == ("pick", "up")
    for bad in ("", "pick_up", "go!", "3d print"):
        with pytest.raises(SealError):
            LexicalUnit(bad)


def test_frame_refuses_facts_naming_missing_elements_and_lists_them_all() -> None:
    with pytest.raises(SealErrors) as caught:
        Frame("Stir", elements=(Element("theme", "container"),),
              preconditions=(Fact.parse("holding(instrumnet)"),), actions=(Action.parse("stir(tool, theme)"),))
    messages = [p.message for p in caught.value.problems]
    assert len(messages) == 2
    assert "'instrumnet', which Stir lacks" in messages[0] and "its elements are theme" in messages[0]
    assert "'tool'" in messages[1]


def test_frame_refuses_bad_names_and_repeated_elements() -> None:
    with pytest.raises(SealError, match="capital letter"):
        Frame("stir")
    with pytest.raises(SealError, match="two elements named 'theme'"):
        Frame("Stir", elements=(Element("theme", "a"), Element("theme", "b")))


def test_bind_fills_defaults_and_drops_what_names_unfilled_elements() -> None:
    frame = stir()
    binding = frame.bind({"theme": "cup"})
    assert binding.elements == {"theme": "cup", "instrument": "spoon"}
    assert binding.preconditions == (Fact("holding", ("spoon",)),)
    assert [str(a) for a in binding.actions] == ["navigate(cup)", "stir(spoon, cup)"]
    assert str(binding) == "Stir(theme=cup, instrument=spoon)"

    pick = Frame("Pick", elements=(Element("theme", "object"), Element("source", "location")),
                 preconditions=(Fact("hand_empty"), Fact.parse("open(source)")),
                 postconditions=(Fact.parse("holding(theme)"),))
    assert pick.bind({"theme": "cup"}).preconditions == (Fact("hand_empty"),)
    assert pick.bind({"theme": "cup", "source": "fridge"}).preconditions[1] == Fact("open", ("fridge",))


def test_bind_refuses_unknown_elements() -> None:
    with pytest.raises(SealError, match="no element goal"):
        stir().bind({"goal": "table"})


def test_element_lookup_names_the_known_roles() -> None:
    assert stir().element("instrument").default == "spoon"
    with pytest.raises(KeyError, match="theme, instrument"):
        stir().element("goal")


def pick() -> Frame:
    return Frame("Pick", (LexicalUnit("pick up"),), (Element("theme", "object"), Element("source", "place")),
                 (Fact.parse("hand_empty"),), (Action.parse("grasp(theme)"),),
                 (Fact.parse("holding(theme)"), Fact.parse("not hand_empty")))


def test_needs_held_and_gets_held_read_holding_before_and_after() -> None:
    assert stir().needs_held("instrument") and not stir().needs_held() and not stir().needs_held("theme")
    assert pick().gets_held() and pick().gets_held("theme") and not pick().needs_held()
    assert not stir().gets_held("instrument") and not pick().gets_held("source")
    dropping = Frame("Drop", (LexicalUnit("drop"),), (Element("theme", "object"),),
                     (Fact.parse("not holding(theme)"),), (), (Fact.parse("not holding(theme)"),))
    assert not dropping.needs_held() and not dropping.gets_held()     # a negation is not holding
    assert Frame("Wait", (LexicalUnit("wait"),), (), (), (), ()).first_role is None
    assert not Frame("Wait", (LexicalUnit("wait"),), (), (), (), ()).needs_held()


def test_a_lexical_unit_longer_than_any_command_is_refused() -> None:
    from seal_cli.frames.model import MAX_UNIT_LENGTH
    from seal_cli.language.tokens import MAX_LENGTH

    assert MAX_UNIT_LENGTH == MAX_LENGTH  # a unit is said inside a command
    LexicalUnit(" ".join(["zap"] * 250))  # 999 characters
    with pytest.raises(SealError, match=r"1,003 characters long, longer than any command seal takes"):
        LexicalUnit(" ".join(["zap"] * 251))


@pytest.mark.parametrize(("description", "framenet", "said"), [
    ("a \udc80 b", None, r"Stir's description 'a \\udc80 b' holds '\\udc80' \(U\+DC80\), half of a character"),
    ("a \x1b[31m red", None, r"Stir's description .* a control character"),
    ("a \u202e b", None, r"Stir's description .* reorders the line"),
    ("", "Apply\x00heat", r"Stir's FrameNet name .* a control character"),
])
def test_a_description_no_terminal_shows_is_refused(description: str, framenet: str | None, said: str) -> None:
    # hostile28: `seal frames` printed them (its JSON with a lone surrogate no strict reader takes)
    with pytest.raises(SealError, match=said):
        Frame("Stir", (LexicalUnit("stir"),), description=description, framenet=framenet)


def test_a_description_keeps_its_line_breaks() -> None:
    assert Frame("Stir", (LexicalUnit("stir"),), description="Stir.\n\tWith a spoon.").description.endswith("spoon.")



def test_a_lexical_unit_is_spaced_as_a_command_is() -> None:
    """hostile30: a line separator (YAML's ``\\L``) between a unit's words is a space, as in a command's line."""
    assert LexicalUnit("whisk\u2028it").text == "whisk it" and LexicalUnit("whisk\u2029").text == "whisk"
