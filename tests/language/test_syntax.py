"""The tree → typed values: every rule of the grammar has its method, and the values say what was said."""

from __future__ import annotations

from seal_cli.frames.library import Library
from seal_cli.language.lexicon import Tagger, tokenize
from seal_cli.language.parser import CommandParser, command_parser
from seal_cli.language.syntax import _RULES, NP, PP, Clause, Syntax


def test_every_rule_of_the_grammar_has_a_method() -> None:
    rules = {r.origin.name for r in command_parser().rules if not r.origin.name.startswith("_")
             and not r.options.expand1}
    assert rules == set(_RULES)


def _command(text: str, library: Library) -> tuple[Clause, ...]:
    parser = CommandParser.of(library)
    words = Tagger(parser.lexicon, tokenize(text), text).run()
    return Syntax(text, words, parser.types).transform(parser.tree(text, words)).clauses


def test_a_clause_holds_its_phrases_in_order(library: Library) -> None:
    (clause,) = _command("take the two red cups from the kitchen table", library)
    assert clause.verb.text == "take" and clause.objects == []
    np, pp = clause.items
    assert isinstance(np, NP) and isinstance(pp, PP)
    assert (np.quantity, np.plural, np.head_text, [m.text for m in np.mods]) == (2, True, "cup", ["red"])
    assert pp.prep == "from" and pp.np.head_text == "table" and [m.text for m in pp.np.mods] == ["kitchen"]


def test_clauses_carry_their_separator_and_what_is_said_before_the_verb(library: Library) -> None:
    text = "with a clock in hand, turn on the lamp and then go to the kitchen"
    parser = CommandParser.of(library)
    words = Tagger(parser.lexicon, tokenize(text), text).run()
    command = Syntax(text, words, parser.types).transform(parser.tree(text, words))
    assert command.joins == ("", "and then")
    lead = [x for x in command.clauses[0].items if isinstance(x, PP) and x.lead]
    assert [pp.np.head_text for pp in lead] == ["clock", "hand"]


def test_a_person_a_name_and_a_pronoun(library: Library) -> None:
    (clause,) = _command("bring Roger the woman's coat and it", library)
    kinds = [(x.kind, x.head_text) for x in clause.items if isinstance(x, NP)]
    assert kinds[0] == ("person", "Roger")
    coat = next(x for x in clause.items if isinstance(x, NP) and x.head_text == "coat")
    assert coat.possessor is not None and coat.possessor.kind == "person"
