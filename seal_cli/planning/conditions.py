"""A condition on the world that ``seal run`` can check before it acts: "*if Tom is in the garage*, give him
the hammer", "*if there is milk in the fridge*, bring it to Lucia", "*if the fridge is open*, close it".

The parser keeps a frame's condition as the words said (``Evoked.condition``). One that says where someone or
something is — "if" and a clause "X is/are in/on/at Y" or "there is/are X in/on/at Y" — is the yes/no question
"is X in Y?" / "is there X in Y?" (turned by English's rules, :func:`seal_cli.language.asking.direct_question`),
which the robot answers as it answers that question asked directly: it looks (a Find of X with Y as its ground).
One that says a state the robot sees — "if the fridge is open", "if the light is on", "if the oven is still on"
(the state words of a question, :data:`seal_cli.planning.questions.STATE_WORDS`) — is the question "is the fridge
open?", answered by looking at the thing where it stands (a LookAt with the state asked), from the simulator's
state as the robot sees it.
The frames are carried out when the answer is yes, and not when it is no, which the run says. Other conditions
("when the water boils", "if it rains") are no question the robot can answer by looking: they are carried out at
once, with the warning they always had (:func:`seal_cli.pipeline.unchecked_conditions`).
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass

from seal_cli.language.asking import direct_question

__all__ = ["Condition", "as_question", "checked_condition", "may_be_checked"]

_IF = ("if",)
"""Subordinators of a condition that holds or not now (not "when"/"once", which wait for it to come true)."""
_WHERE = ("in", "on", "at", "inside", "under", "by", "near")
"""Prepositions of where a thing is: a condition that says one is about where something is."""
_BE = ("is", "are", "'s")
_STATE_ADVERBS = ("not", "still", "already", "left")
"""Words between "is" and a state word that leave it a state seen ("if the oven is *still* on", "is *not* empty")."""


@dataclass(frozen=True)
class Condition:
    """A condition the run checks first: its words as said, and the question that checks it."""

    said: str
    question: str
    looks: tuple[str, ...] = ()
    """The steps that check it, as planned on a map ("Find(theme=tom, ground=garage)"): what ``seal plan`` shows
    before the steps that are carried out only when it holds."""

    def to_json(self) -> dict[str, object]:
        """The ``check`` of ``seal plan --json``: the condition as said, its question, the steps that check it."""
        return {"condition": self.said, "question": self.question, "plan": list(self.looks)}


def as_question(condition: str) -> str | None:
    """The yes/no question a condition about where something is, or a state it is in, asks ("if Tom is in the
    garage": "is Tom in the garage?", "if there's milk in the fridge": "is there milk in the fridge?", "if the fridge
    is open": "is the fridge open?"); None for any other condition."""
    words = condition.replace("'s ", " is ").replace(",", " ").split()
    if len(words) < 4 or words[0].lower() not in _IF:
        return None
    rest = words[1:]
    be = next((k for k, w in enumerate(rest) if w.lower() in _BE), None)
    if be is None or be == 0 or be + 1 >= len(rest):
        return None
    if rest[0].lower() == "there":          # "there is milk in the fridge": a place said after the thing
        if be != 1 or not any(w.lower() in _WHERE for w in rest[be + 2:]):
            return None
    elif _state_said(rest[be + 1:]):       # "the fridge is open", "the light is on" ("on" with nothing after it)
        at = next((k for k, w in enumerate(rest[1:be], 1) if w.lower() in _WHERE), None)
        if at is not None:    # "the light in the office is on": "is the light on in the office?", the state asked
            rest = [*rest[:at], *rest[be:], *rest[at:be]]     # of the thing there, as a question says it
    elif rest[be + 1].lower() not in _WHERE:
        return None
    return direct_question(["if", *rest])


def _state_said(after: Sequence[str]) -> bool:
    """Whether the words after "is"/"are" say a state the robot sees ("open", "still on", "not empty": the
    question's state words, :data:`seal_cli.planning.questions.STATE_WORDS`) and nothing more."""
    from seal_cli.planning.questions import STATE_WORDS

    words = [w.lower() for w in after]
    while len(words) > 1 and words[0] in _STATE_ADVERBS:
        words = words[1:]
    return len(words) == 1 and words[0] in STATE_WORDS


def may_be_checked(text: str) -> bool:
    """Whether a command may hold a condition the robot checks: one of its words opens one ("if"). A cheap test
    before parsing the command again (``pipeline.plan``)."""
    return any(w.strip(",.;:!?").lower() in _IF for w in text.split())


def checked_condition(frames: Sequence[object]) -> Condition | None:
    """The condition every frame of a command is said under, when it is one the robot checks by looking
    (:func:`as_question`); None when a frame has none, the frames' conditions differ, or it is no such condition."""
    said = {getattr(f, "condition", None) for f in frames}
    if len(said) != 1:
        return None
    condition = said.pop()
    if not condition:
        return None
    question = as_question(condition)
    return Condition(condition, question) if question is not None else None
