"""A question asked, and the telling of its answer said as a clause of its own: one frame (words33), or a telling of
that answer (words32's answer left unsaid; one pass since words34).

People wrap a question in a request to report it, before or after: "find out what is on the bench *and tell me*",
"check who's in the hall *and let me know*", "how many cups are on the table? *Tell me, please.*", "count the
plates *and report back*", "*Tell me,* who is at the door?". The telling says nothing of its own (no message, or
"it": "find out his name and tell *it* to Jo"): it is the answer of the question beside it, not a second thing to
tell. :func:`merge_reported` makes the two one frame: the question's, with the person told when the question's
frame tells someone (Tell) and said no one ("find out who's in the hall and tell Jo": Tell, recipient Jo).

A question is a frame that asks: Tell with a message, Count, a state asked (LookAt with ``asked``), or a search
asked rather than commanded (Find whose words do not start with its verb: "is there milk in the fridge", "check
whether ..."). "Find the cat and tell me" stays two frames (a search commanded, then a report of its own), and so
does a telling with a message ("count the cups and tell me the number") or to another person after a frame that
tells no one ("count the cups and tell Jo"), or two people told ("tell me X and tell it to Jo").

A telling that stays a frame of its own and leaves its message unsaid right after a frame that answers a question
tells that answer (:func:`told_answers`): "find the keys and let me know" says where they are, "count the cups and
tell Jo" how many there are (the question the earlier frame answers: a unit of it that asks, "how many", or "where"
for a search). Its message has no text (nothing said) and the question as its head, which the planner reads as a
report. Both are one idea, the telling of a question's answer, and :func:`merge_reported` does both: first the
answers told, then the frames merged (a telling whose message is an answer left unsaid merges as one with none).
"""

from __future__ import annotations

import re
from dataclasses import replace

from seal_cli.frames.library import Library
from seal_cli.language.english import SPEAKER_PRONOUNS, WH_WORDS
from seal_cli.language.searches import SEARCH, renumbered
from seal_cli.language.values import Evoked, Parse, Phrase

__all__ = ["COUNTING", "TELLING", "merge_reported", "told_answers"]

TELLING = "Tell"
"""The frame that reports to a person; a telling with no message is the one merged."""

COUNTING = "Count"
"""The frame that counts: a count of nothing said after one reports it."""

_ANSWER_AGAIN = frozenset(["it", "that", "this", "the answer"])
"""A telling's message that is the answer of the question before it ("find out his name and tell *it* to Jo")."""

_JOINT_AFTER = re.compile(r"^(?:\s|[,.;!?]|\band\b|\bthen\b|\bplease\b|\bjust\b|\bso\b|\balso\b)*$", re.IGNORECASE)
"""What may stand between a question and the telling after it: the joints of clauses and sentences, and politeness
("... ? Tell me, please", "... and then let me know")."""

_JOINT_BEFORE = re.compile(r"^\s*[,:;\-\u2013\u2014]\s*$")
"""What stands between a telling said first and its question: a comma, a colon or a dash ("Tell me, who is at the
door?", "tell me - which fruit is the biggest?": words41)."""


def merge_reported(parse: Parse, library: Library) -> Parse:
    """The parse with each telling of an answer left unsaid telling it (:func:`told_answers`), and each question and
    the telling of its answer beside it made one frame (module docstring)."""
    parse = told_answers(parse, library)
    frames = list(parse.frames)
    k = 0
    while k + 1 < len(frames):
        first, second = frames[k], frames[k + 1]
        between = _between(parse.text, first, second)
        if _asks(parse.text, first) and _reports(second, first) and _JOINT_AFTER.match(between):
            frames[k] = _told(first, second)
        elif _reports(first, second) and _asks(parse.text, second) and _JOINT_BEFORE.match(between):
            frames[k] = _told(second, first)
        else:
            k += 1
            continue
        del frames[k + 1]
        frames = [renumbered(f, k + 1) for f in frames]
    return replace(parse, frames=tuple(frames)) if len(frames) != len(parse.frames) else parse


def told_answers(parse: Parse, library: Library) -> Parse:
    """The parse with each frame that tells a message it leaves unsaid (no element of its says one), said right after
    a frame that answers a question, telling that answer: a message with no text whose head is the question
    (:func:`answer_of`; module docstring)."""
    frames = list(parse.frames)
    for k in range(1, len(frames)):
        evoked = frames[k]
        frame = library.frame(evoked.frame)
        role = next((e.role for e in frame.elements if e.type == "message" and e.role not in evoked.elements), None)
        if role is None or any(p.kind == "message" for p in evoked.elements.values()):
            continue
        question = answer_of(library, frames[k - 1].frame)
        if question is None:
            continue
        elements = {**evoked.elements, role: Phrase("", question, None, "message")}
        frames[k] = replace(evoked, elements={e.role: elements[e.role] for e in frame.elements if e.role in elements})
    return replace(parse, frames=tuple(frames)) if frames != list(parse.frames) else parse


def answer_of(library: Library, name: str) -> str | None:
    """The question the frame ``name`` answers: a unit of it that starts with a question word (Count's "how many"),
    "where" for a search; None for a frame that answers none."""
    frame = library.frame(name)
    asks = next((u.text for u in frame.lexical_units if u.text.split()[0] in WH_WORDS), None)
    return asks or ("where" if frame.name == SEARCH else None)


def _between(text: str, first: Evoked, second: Evoked) -> str:
    """What is said between two frames, without the end of the first one's own words its span leaves out: the
    state a question asks ("is the door *closed*? let me know") and the "know" of "let me *know*"."""
    between = text[first.span[1]:second.span[0]]
    for own in (first.asked, "know" if first.frame == TELLING else None):
        if own and between.lower().lstrip().startswith(own.lower()):
            between = between.lstrip()[len(own):]
    return between


def _asks(text: str, frame: Evoked) -> bool:
    """Whether the frame is a question: a telling of a message to the speaker or no one, a count, a state asked,
    or a search asked (its words do not start with its verb)."""
    if frame.frame == TELLING:
        return "message" in frame.elements and _to_speaker(frame.elements.get("recipient"))
    if frame.frame == "Count" or frame.asked:
        return True
    said = text[frame.span[0]:frame.span[1]].lower()
    return frame.frame == "Find" and not said.startswith(frame.lexical_unit)


def _reports(telling: Evoked, question: Evoked) -> bool:
    """Whether ``telling`` only reports the answer of ``question``: a Tell with no message and no element but the
    person told, who is the speaker unless the question's own frame tells someone; or a count that names nothing
    after a count ("count the dishes *and let me know how many there are*", words41: a second Count of nothing)."""
    if telling.frame == COUNTING and question.frame == COUNTING and not telling.elements:
        return True
    if telling.frame != TELLING or set(telling.elements) - {"recipient", "message"}:
        return False
    asked_of, told_to = question.elements.get("recipient"), telling.elements.get("recipient")
    if asked_of is not None and asked_of.text and told_to is not None and told_to.text and \
            asked_of.head.lower() != told_to.head.lower():
        return False                  # "tell me what is in the box and tell it to Jo": two people told
    message = telling.elements.get("message")
    if message is not None and message.text:    # "find out his name and tell *it* to Jo": the answer, said again
        return question.frame == TELLING and message.text.lower() in _ANSWER_AGAIN
    # a message left unsaid ("count the cups and let me know": told_answers's, head "how many") is no message
    return question.frame == TELLING or _to_speaker(telling.elements.get("recipient"))


def _to_speaker(recipient: Phrase | None) -> bool:
    """Whether a recipient is the speaker, or unsaid."""
    return recipient is None or not recipient.text or recipient.head.lower() in SPEAKER_PRONOUNS


def _told(question: Evoked, telling: Evoked) -> Evoked:
    """The question's frame, telling the person the telling names when the question is itself a telling."""
    recipient = telling.elements.get("recipient")
    elements = dict(question.elements)
    if question.frame == TELLING and recipient is not None and recipient.text:
        elements["recipient"] = recipient
    span = (min(question.span[0], telling.span[0]), max(question.span[1], telling.span[1]))
    return replace(question, elements=elements, span=span)
