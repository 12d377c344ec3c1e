"""What a parse says: the frames a command evokes (:class:`Evoked`), the phrases that fill their
elements (:class:`Phrase`), and the whole (:class:`Parse`), with the SPEC's JSON."""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass, field
from typing import Any

from seal_cli.language.frozen import quick_init

__all__ = ["Evoked", "Parse", "Phrase"]


@quick_init
@dataclass(frozen=True)
class Phrase:
    """What fills a frame element: the words, their head (lemma), the class they denote.

    ``kind`` is "person", "thing", "place" (here, there) or "message"; ``refers_to`` names the
    antecedent of a pronoun as (frame index, element); ``quantity`` a number said ("two
    apples"); ``default`` marks an element filled from the frame's default, not said;
    ``conjuncts`` are the phrases of a coordination ("the apple and the pear"), each grounded
    (the phrase itself stands for the first); ``preposition`` the one it was said with.
    """

    text: str | None
    head: str
    cls: str | None = None
    kind: str = "thing"
    refers_to: tuple[int, str] | None = None
    quantity: int | None = None
    plural: bool = False
    modifiers: tuple[str, ...] = ()
    default: bool = False
    span: tuple[int, int] | None = field(default=None, compare=False)
    conjuncts: tuple[Phrase, ...] = ()
    relative: str | None = None
    preposition: str | None = field(default=None, compare=False)
    """The preposition it was said with ("on" of "put the teapot *on* the sideboard"), None for an object;
    read by the planner (:func:`seal_cli.planning.problem.on_top`), not part of the SPEC's JSON (as ``span``)."""
    stands_for: str | None = field(default=None, compare=False)
    """For a pronoun that stands for a thing a statement or condition named, those words with where they say it is
    ("if *the light in the office* is on, switch it off"): what the planner grounds on the map in its stead; not
    part of the SPEC's JSON (the element's text is the pronoun said)."""

    def to_json(self) -> dict[str, Any]:
        data: dict[str, Any] = {"text": self.text, "head": self.head, "class": self.cls}
        if self.kind != "thing":
            data["kind"] = self.kind
        if self.refers_to is not None:
            data["refers_to"] = list(self.refers_to)
        if self.quantity is not None:
            data["quantity"] = self.quantity
        if self.plural:
            data["number"] = "plural"
        if self.modifiers:
            data["modifiers"] = list(self.modifiers)
        if self.default:
            data["default"] = True
        if self.conjuncts:
            data["conjuncts"] = [c.to_json() for c in self.conjuncts]
        if self.relative:
            data["relative"] = self.relative
        return data


@quick_init
@dataclass(frozen=True)
class Evoked:
    """A frame evoked by a verb phrase (or by a result word), with its elements."""

    frame: str
    lexical_unit: str
    span: tuple[int, int]
    elements: Mapping[str, Phrase]
    condition: str | None = None
    result: str | None = None
    time: str | None = None
    asked: str | None = None
    """The state a yes/no question asks of the frame's theme ("open" of "is the fridge open?")."""
    inferred: float | None = None
    """Not said but inferred, with this probability: the step a sentence most likely leaves unsaid
    (:mod:`~seal_cli.language.steps`: "put an apple in the fridge" → Cool it first). None: said."""

    def to_json(self) -> dict[str, Any]:
        data: dict[str, Any] = {"frame": self.frame, "lexical_unit": self.lexical_unit, "span": list(self.span),
                                "elements": {role: p.to_json() for role, p in self.elements.items()}}
        for key in ("condition", "result", "time", "asked"):
            if getattr(self, key):
                data[key] = getattr(self, key)
        if self.inferred is not None:
            data["inferred"] = True
            data["probability"] = self.inferred
        return data


@quick_init
@dataclass(frozen=True)
class Parse:
    """A parsed command: the frames it evokes, in the order they are to be done."""

    text: str
    frames: tuple[Evoked, ...]
    remarks: tuple[str, ...] = ()
    """What was said beside the command and dropped: statements, greetings ("*The grandchildren are
    here.*", "..., *she's been waiting a while*")."""
    unplaced: tuple[tuple[int, int], ...] = field(default=(), compare=False)
    """Where the phrases are that no frame element took (:mod:`~seal_cli.language.unplaced`), for a parse made
    without the parser's refusal: :class:`~seal_cli.language.parser.CommandParser` refuses a command that leaves
    one, so a parse it returns has none (`seal bench parse` counts any that would); not part of the SPEC's JSON."""

    def to_json(self) -> dict[str, Any]:
        data: dict[str, Any] = {"text": self.text, "frames": [f.to_json() for f in self.frames]}
        if self.remarks:
            data["remarks"] = list(self.remarks)
        return data

    def resolve(self, phrase: Phrase) -> Phrase:
        """The phrase a pronoun stands for (the phrase itself when it is not one)."""
        seen = 0
        while phrase.refers_to is not None and seen < len(self.frames):
            index, role = phrase.refers_to
            phrase = self.frames[index].elements[role]
            seen += 1
        return phrase
