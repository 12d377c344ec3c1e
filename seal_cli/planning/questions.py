"""What a command asks: the question each commanded frame answers, read from the words that evoked it.

The parser gives a question the frame that finds its answer — "where is the cup?" and "is there a
cup in the kitchen?" are both Find, "how many cups ..." is Count, "what is on the dining table?" is
Tell with the question as its message — but the *kind* of answer a person expects differs:

- ``where``: a Find said as a command or as "where is ..."; the answer says where the thing is;
- ``whether``: a Find said as "is there ...", "are there ...", "is Anna in ..."; the answer is yes
  (and where) or no, from what the robot saw where the question asks;
- ``how_many``: a Count; the answer is how many the robot saw there;
- ``what``: a Tell whose message asks what is on, in or at a place or in a room ("what's in the
  fridge?", "who is in the kitchen?"), or a Find of nothing in particular somewhere ("look in the
  fridge"); ``about`` is the map's place or room, ``relation`` the word that relates them. The
  robot goes and looks, and the answer lists what it saw;
- ``state``: a yes/no question about a thing's state ("is the fridge open?", "check if the stove is
  on"), which the parser gives as LookAt with the state asked (``Evoked.asked``); ``relation`` is the
  state word. The thing is looked at where it is (:func:`looking`: not taken into the hand), and the
  answer is yes or no with what the robot saw (:data:`STATE_WORDS`);
- ``fact``: a Tell whose message asks for something the robot knows without looking — the time, the
  date, the day ("tell Anna the time", "what time is it?"); ``relation`` is the fact (:data:`FACTS`).
  The robot says it (its clock: ``seal run --clock``), never the message's name;
- ``report``: a Tell, after a frame of the same command that answers a question, whose message asks
  (begins with a question word: "tell me *where* it is", "... *what* you found", "... *how many*") or
  points back at what was sought ("report *its* location"): the robot says what the earlier frames
  found out, never the message's words. Any other message ("tell Jo hello") is said as it is.

A question is read from words only (the frame's span in the text, the message's words) and
grounded with :class:`~seal_cli.planning.grounding.MapNames`: never from the map's objects.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass, replace

from seal_cli.frames.model import Action, Binding, Frame
from seal_cli.language.english import CHECK_WHETHER, WH_WORDS
from seal_cli.language.values import Evoked, Parse
from seal_cli.planning.grounding import MapNames, words_of

__all__ = ["FACTS", "KINDS", "STATE_WORDS", "Question", "asks_whether", "fact_asked", "looking", "read_questions",
           "reports"]

KINDS = ("where", "whether", "how_many", "what", "state", "fact", "report")

FACTS = frozenset({"time", "date", "day"})
"""What a robot tells from its clock, not from looking: "the *time*", "what *day* it is"."""

FACT_FILLER = frozenset({"what", "the", "a", "is", "it", "its", "it's", "s", "'s", "current", "right", "now",
                         "today", "todays", "today's", "of", "week", "exact"})
"""Words around a fact asked for that ask nothing more ("what time is it right now", "today's date",
"the day of the week"). English, not any corpus's."""

STATE_WORDS = {"open": ("open", True), "opened": ("open", True), "closed": ("open", False),
               "shut": ("open", False), "on": ("on", True), "running": ("on", True), "off": ("on", False),
               "clean": ("clean", True), "washed": ("clean", True), "dirty": ("clean", False),
               "hot": ("hot", True), "warm": ("hot", True), "heated": ("hot", True), "cold": ("cold", True),
               "cool": ("cold", True), "chilled": ("cold", True), "sliced": ("sliced", True),
               "cut": ("sliced", True), "empty": ("empty", True), "full": ("empty", False)}
"""A state word a question asks → the simulator's state (:data:`seal_cli.sim.world.STATES`, or
``empty``: holds nothing) and whether the word says it holds. English, not any corpus's."""

ASKING_WHETHER = frozenset({"is", "are", "was", "were"})
"""A Find whose words start with one of these asks whether ("*is* there a cup in the kitchen?")."""

ASKING_WHAT = {"what": "thing", "whats": "thing", "who": "person", "whos": "person"}
"""The first word of a message that asks what (or who) is somewhere, and what it asks for."""

POINTING_BACK = frozenset({"it", "its", "they", "them", "their"})
"""The pronouns and possessives by which a message refers to a thing sought before ("report *its* location")."""

CONTAINING = ("on top of", "inside", "on", "in", "at")
"""The words after which a "what is ..." question names where to look."""


@dataclass(frozen=True)
class Question:
    """The question a commanded frame answers (see the module docstring)."""

    kind: str
    about: str | None = None
    """``what``: the map id of the place or room asked about; ``state``: where the thing is said to be."""
    relation: str = "on"
    """``what``: on, in or at (as the question says it); ``state``: the state word asked."""
    asks_for: str = "thing"
    """``what``: thing (what is there) or person (who is there)."""

    def __post_init__(self) -> None:
        if self.kind not in KINDS:
            raise ValueError(f"a question is one of {', '.join(KINDS)}, not {self.kind!r}")


def looking(frame: Frame) -> Frame:
    """A frame as a state question needs it: its theme looked at where it stands, driven up to first
    (LookAt's ``holding(theme)`` is ALFRED's looking at a thing in the light; "is the fridge open?"
    does not pick the fridge up)."""
    kept = tuple(f for f in frame.preconditions if "theme" not in f.args)
    actions = frame.actions if any(a.name == "navigate" and a.args == ("theme",) for a in frame.actions) \
        else (Action("navigate", ("theme",)), *frame.actions)
    return replace(frame, preconditions=kept, actions=actions)


def asks_whether(text: str, evoked: Evoked) -> bool:
    """Whether a Find asks whether ("*is* there a cup ...?", "*are* there any spoons ...?"): at least one
    is enough, so a plural asks for the kind once."""
    first = text[evoked.span[0]:evoked.span[1]].lower().split()[:4]
    checks, ifs, _ = CHECK_WHETHER                      # "*see if* anyone is in the kitchen"
    return evoked.frame == "Find" and bool(first) and (first[0] in ASKING_WHETHER or any(
        first[k] in ifs and " ".join(first[:k]) in checks for k in range(1, len(first))))


def fact_asked(message: str) -> str | None:
    """The fact a message asks for (:data:`FACTS`: "the time", "what time it is", "today's date"), else None."""
    said = message.lower().replace("_", " ").replace("?", " ").replace("’", "'").replace("'s", " 's")
    words = [w for w in said.split() if w not in FACT_FILLER]      # "what's today's date": what 's today 's date
    return words[0] if len(words) == 1 and words[0] in FACTS else None


def reports(message: str) -> bool:
    """Whether a message, said after a question of the same command was answered, asks for that answer:
    it begins with a question word ("*where* it is", "*what* you found") or refers back with a pronoun or a
    possessive ("*its* location", "where *they* are")."""
    words = message.lower().replace("_", " ").replace("?", " ").split()
    return bool(words) and (words[0] in WH_WORDS or any(w in POINTING_BACK for w in words))


def _what(message: str, names: MapNames | None) -> Question | None:
    """The ``what`` question a message asks, if it asks what or who is on, in or at a map place or room."""
    words = message.lower().replace("'", "").replace("’", "").split()
    if not words or words[0] not in ASKING_WHAT or names is None:
        return None
    for i in range(1, len(words)):
        for relation in CONTAINING:
            rel = relation.split()
            if words[i:i + len(rel)] == rel:
                phrase = " ".join(words[i + len(rel):])
                found = names.ground(phrase, "location", ("room", "place")) if words_of(phrase) else None
                if found is not None:
                    said = "in" if relation in ("inside", "in") else "on" if relation in ("on", "on top of") else "at"
                    return Question("what", found.id, said, ASKING_WHAT[words[0]])
                return None
    return None


def _state(asked: str, names: MapNames | None) -> Question:
    """A state question: the state asked, and where the thing is when a place follows it ("is the window open
    *in the bedroom*?": ``about`` the bedroom, where the robot looks for it)."""
    words = asked.split()
    for i, word in enumerate(words):
        after_state = 0 < i < len(words) - 1 and words[i - 1].lower() in STATE_WORDS
        if word.lower() in ("in", "on", "at", "inside") and after_state:
            phrase = " ".join(words[i + 1:])
            found = names.ground(phrase, "location", ("room", "place")) if names and words_of(phrase) else None
            return Question("state", found.id if found is not None else None, " ".join(words[:i]))
    return Question("state", relation=asked)


def _looked_at(bindings: Sequence[Binding], names: MapNames | None) -> Question | None:
    """A Find with a ground and no theme ("look in the fridge", "look around the kitchen") asks what
    is there."""
    ground = bindings[0].elements.get("ground") if bindings else None
    referent = names.by_id(ground) if names is not None and ground is not None else None
    if referent is None or referent.kind not in ("room", "place"):
        return None
    place = names.map.place(referent.id) if names is not None and referent.kind == "place" else None
    return Question("what", referent.id, "on" if place is not None and not place.openable else "in")


def read_questions(parse: Parse, commanded: Sequence[Binding], names: MapNames | None) -> dict[Binding, Question]:
    """The question each commanded frame answers (frames that answer none are left out).

    The frames of one evoked verb phrase are consecutive in ``commanded`` and share its frame
    (:func:`seal_cli.planning.problem.commanded_frames`); each takes the question its words ask."""
    questions: dict[Binding, Question] = {}
    answered = False                  # an earlier frame of the command answers a question
    k = 0
    for evoked in parse.frames:
        start = k
        while k < len(commanded) and commanded[k].frame.name == evoked.frame:
            k += 1
        question: Question | None = None
        if (asked := getattr(evoked, "asked", None)) and "theme" in evoked.elements:   # "is the fridge open?"
            question = _state(asked, names)
        elif evoked.frame == "Find" and "theme" not in evoked.elements:    # "look in the fridge": what is there
            question = _looked_at(commanded[start:k], names)
        elif evoked.frame == "Find":
            question = Question("whether" if asks_whether(parse.text, evoked) else "where")
        elif evoked.frame == "Count":
            question = Question("how_many")
        elif evoked.frame == "Tell" and (message := evoked.elements.get("message")) is not None:
            said = message.text or message.head
            fact = fact_asked(said)
            question = Question("fact", relation=fact) if fact else _what(said, names)
            if question is None and answered and reports(said):           # "find the cup and tell me where it is"
                question = Question("report")
        if question is not None:
            questions.update((b, question) for b in commanded[start:k])
            answered = answered or question.kind != "report"
    return questions
