"""What the language asks of a frame library's lexical units: each is a verb, with any words that go with it.

The frame readers (:mod:`seal_cli.frames`) check a unit's spelling; what a word of English is they cannot know. A unit
opening with a function word ("the", "of", "it") is refused here, where the closed classes are
(:mod:`seal_cli.language.english`), by every parser made for a library (:class:`~seal_cli.language.parser.
CommandParser`) and by ``seal validate``. Light: the tables alone, not the tagger.
"""

from __future__ import annotations

from seal_cli.errors import SealError
from seal_cli.frames.library import Library
from seal_cli.language.english import function_word_class

__all__ = ["unit_problems"]


def unit_problems(library: Library) -> list[SealError]:
    """Each lexical unit of the library that opens with a function word of English (:data:`english.
    FUNCTION_WORD_CLASSES`: "the", "a", "of", "and", "it", "with", "must"), at the unit's line and column. The tagger
    reads a unit's first word as a verb wherever it stands: a unit "the" made "the cup" that frame, "bring it" went
    wrong with a unit "it" (hostile32). A question word may open a unit of more words, a question's ("how many",
    Count's); function words after the verb are the unit's own ("lead the way", "look for")."""
    problems = []
    for frame in library.frames:
        for unit in frame.lexical_units:
            first = unit.words[0]
            kind = function_word_class(first)
            if kind is None or kind == "a question word" and len(unit.words) > 1:
                continue
            said = f"is {kind}" if len(unit.words) == 1 else f"opens with '{first}', {kind}"
            problems.append(SealError(f"lexical unit {unit.text!r} of {frame.name} {said}, a function word of English: "
                                      f"a command saying '{first}' would be read as {frame.name} there; a lexical "
                                      "unit is a verb, with any words that go with it ('zap', 'pick up', 'look for')",
                                      unit.where))
    return problems
