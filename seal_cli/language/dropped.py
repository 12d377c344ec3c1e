"""States dropped from a question: a word of state ending a sentence ("is the light in the office *on*?") that
nothing of the parse holds. A robot must never drop an instruction silently; a state asked and then lost turns
"is the light in the office on?" into "is the light in the office?" (a search, words25's parse), so `seal bench
parse` counts such parses on every corpus beside the clauses swallowed into an element
(:mod:`~seal_cli.language.swallowed`).

A word of state here is a particle of state (``STATE_PARTICLES``: "on", "off", "open", "shut") ending its
sentence (before ".", "!", "?" or the command's end). It is held when it lies in the span of an element, or in
the text of a frame's asked state, condition, result or time, or of a remark, or is a word of the lexical unit of
a frame said before it ("turn it *off*": the unit "turn off"; "make sure the lamp is *on*": the unit "turn on",
the state brought about).
"""

from __future__ import annotations

from collections.abc import Iterator, Sequence
from dataclasses import dataclass

from seal_cli.language.english import END_MARKS, STATE_PARTICLES
from seal_cli.language.tokens import Word
from seal_cli.language.values import Parse, Phrase

__all__ = ["Dropped", "dropped_states"]


@dataclass(frozen=True)
class Dropped:
    """A word of state that ends a sentence and that no part of the parse holds: the word, where it is."""

    word: str
    start: int                 # in characters of the command

    def to_json(self) -> dict[str, object]:
        return {"word": self.word, "start": self.start}


def dropped_states(parse: Parse, words: Sequence[Word]) -> tuple[Dropped, ...]:
    """The words of state that end a sentence of the command and that the parse drops (the module docstring),
    given the command's words (:func:`~seal_cli.language.tokens.tokenize`'s); empty when none, the usual case."""
    last = [w for k, w in enumerate(words) if w.lower in STATE_PARTICLES and
            (k + 1 == len(words) or words[k + 1].lower in END_MARKS)]
    if not last:
        return ()
    held = list(_held(parse))
    units = [(f.span, set(f.lexical_unit.lower().split())) for f in parse.frames]
    return tuple(Dropped(w.text, w.start) for w in last
                 if not any(a <= w.start and w.end <= b for a, b in held) and
                 not any(a <= w.start and w.lower in unit for (a, _), unit in units))


def _held(parse: Parse) -> Iterator[tuple[int, int]]:
    """The spans of the command that an element, an asked state, a condition, a result, a time or a remark
    holds."""
    for frame in parse.frames:
        for phrase in frame.elements.values():
            yield from _spans(phrase)
        for said in (frame.asked, frame.condition, frame.result, frame.time):
            if said:
                yield from _found(parse.text, said.removeprefix("not "))
    for remark in parse.remarks:
        yield from _found(parse.text, remark)


def _spans(phrase: Phrase) -> Iterator[tuple[int, int]]:
    if phrase.span is not None:
        yield phrase.span
    for conjunct in phrase.conjuncts:
        yield from _spans(conjunct)


def _found(text: str, said: str) -> Iterator[tuple[int, int]]:
    """Every place of ``said`` in ``text``, ignoring case (a text the parser kept is a piece of the command)."""
    low, said = text.lower(), said.lower()
    at = low.find(said)
    while said and at >= 0:
        yield at, at + len(said)
        at = low.find(said, at + 1)
