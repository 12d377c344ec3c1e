"""Phrases a clause said that no frame element takes: when no frame of the verb takes every phrase of a
clause, :meth:`~seal_cli.language.evoking.Evoker.choose` falls back to the frame that takes the most, and the
rest would be lost ("hand Ben a cup and then Anna a cup" → a second object no frame of "hand" has room
for). A robot must never drop an instruction silently: such a phrase lands in a role of a frame that can take
it, becomes a clause of its own, or the command is refused at the phrase (:func:`unplaced_error`), and
`seal bench parse` counts the parses that still leave one (the target is zero on every corpus).

A phrase is placed when it fills an element, or (a prepositional phrase) describes the noun before it. Said
for whom ("find *me* a thermometer", "chop the carrots *for me*") is no element of most frames and never an
instruction: not counted.
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from typing import Any

from seal_cli.frames.model import Frame
from seal_cli.language.english import PERSON_PRONOUNS, ROUTE_NOUNS
from seal_cli.language.lexicon import CommandError
from seal_cli.language.syntax import NP, PP, Clause

__all__ = ["EXPECTED", "unplaced", "unplaced_error"]


EXPECTED = "a frame element for the phrase"
"""What the parser's error expects when it refuses a phrase no element takes."""


def unplaced(clause: Clause, frame: Frame, roles: Mapping[str, Any],
             attached: Sequence[tuple[NP, PP]]) -> list[NP | PP]:
    """The phrases of a clause (its objects, then its noun and prepositional phrases) that neither fill one of
    the ``frame``'s ``roles`` nor describe a noun (``attached``), in the order said; empty when every one is
    placed. A route noun of a frame with a goal ("show them *the way*", "follow him *all the way* to the door")
    is the path the motion takes: placed."""
    moves = any(e.role == "goal" for e in frame.elements)
    filled = [v for v in roles.values() if isinstance(v, NP)]
    described = [pp for _, pp in attached]
    left: list[NP | PP] = []
    objects = clause.objects
    for at, item in enumerate([*objects, *clause.items]):
        if isinstance(item, NP):
            if not _in(item, filled) and not (at == 0 and len(objects) >= 2 and item.pronoun in PERSON_PRONOUNS) \
                    and not (moves and item.head_text in ROUTE_NOUNS):
                left.append(item)
        elif isinstance(item, PP) and not _in(item.np, filled) and not _in(item, described) and \
                not (item.prep == "for" and item.np.pronoun in PERSON_PRONOUNS):
            left.append(item)
    return left


def unplaced_error(text: str, phrase: NP | PP, frame: str, verb: str) -> CommandError:
    """The refusal of a phrase no element of the chosen frame takes, at the phrase's column."""
    start = phrase.start
    end = phrase.np.end if isinstance(phrase, PP) else phrase.end
    said = text[start:end]
    return CommandError(f"{said!r}: no element of {frame} ({verb!r}) takes it, and it would be lost; say it as "
                        f"an instruction of its own, or leave it out", start + 1, text, [EXPECTED])


def _in(item: object, among: Sequence[object]) -> bool:
    return any(item is x for x in among)
