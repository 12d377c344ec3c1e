"""What a command asks: the question each commanded frame answers, read from the words that evoked it.

The parser gives a question the frame that finds its answer — "where is the cup?" and "is there a
cup in the kitchen?" are both Find, "how many cups ..." is Count, "what is on the dining table?" is
Tell with the question as its message — but the *kind* of answer a person expects differs:

- ``where``: a Find said as a command or as "where is ..."; the answer says where the thing is. Asked of a kind
  in the plural ("where are the towels?", "where can I find cups?": :func:`asks_where_every`), the question is
  ``every``: one Find of the kind, whose answer says where each one the robot finds is (``seal run`` looks
  everywhere the map keeps the kind, docs/benchmarks.md, "e2e34");
- ``whether``: a Find said as "is there ...", "are there ...", "is Anna in ..."; the answer is yes
  (and where) or no, from what the robot saw where the question asks;
- ``how_many``: a Count; the answer is how many the robot saw there;
- ``what``: a Tell whose message asks what is on, in or at a place or in a room ("what's in the
  fridge?", "who is in the kitchen?"), or a Find of nothing in particular somewhere ("look in the
  fridge"); ``about`` is the map's place or room, ``relation`` the word that relates them. A message
  that names no place but asks what is where the robot has gone ("go to the bedroom and tell me *what
  you see*", "... *who is there*") asks it of the last Go's goal or Find's ground. The robot goes and
  looks, and the answer lists what it saw;
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
  found out, never the message's words. Any other message ("tell Jo hello") is said as it is;
- ``asked``: a Tell whose message is a question put to the person ("ask Raj *if he wants tea*", "find out if
  anna wants coffee"): the parser gives the question as the person hears it as the message's head ("do you
  want tea?", :mod:`seal_cli.language.asking`), and the robot asks it.

A question told to someone ("tell Ben *where the spoon is*", "tell Anna *how many cups are in the
kitchen*") is found out first: :func:`told_first` puts the frames that answer it (the Find or Count
the same words ask of the robot: "do you know where the spoon is?") before the Tell, which then
reports them. What and who questions need no frame of their own (``what``: the Tell looks).

A question is read from words only (the frame's span in the text, the message's words) and
grounded with :class:`~seal_cli.planning.grounding.MapNames`: never from the map's objects.
"""

from __future__ import annotations

from collections.abc import Callable, Sequence
from dataclasses import dataclass, replace

from seal_cli.errors import SealError, at_words
from seal_cli.frames.model import Action, Binding, Frame
from seal_cli.frames.taxonomy import Taxonomy
from seal_cli.language.english import CHECK_WHETHER, WH_WORDS
from seal_cli.language.values import Evoked, Parse, Phrase
from seal_cli.planning.grounding import MapNames, Referent, Refusal, words_of

__all__ = ["ANY_THING", "FACTS", "KINDS", "STATE_WORDS", "Question", "anything_there", "asks_where_every",
           "asks_whether", "fact_asked", "looking", "name_asked", "put_to_person", "read_questions", "reports",
           "told_first"]

KINDS = ("where", "whether", "how_many", "what", "state", "fact", "report", "asked")

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

ASKING_WHETHER_SHORT = frozenset({"any", "anyone", "anybody", "anything", "someone", "somebody", "something"})
"""A Find whose words start with one of these, its "is there" unsaid, asks whether too ("*anyone* in the
bathroom?", "*any* milk left in the fridge?"). English, not any corpus's."""

ANY_THING = frozenset({"anything", "something"})
"""The words by which a question of whether some thing is somewhere names no kind of thing ("is there *anything* in
the fridge?"): it asks what is there. English, not any corpus's (people: "anyone", "someone" are sought as people)."""

ASKING_WHAT = {"what": "thing", "whats": "thing", "who": "person", "whos": "person"}
"""The first word of a message that asks what (or who) is somewhere, and what it asks for."""

POINTING_BACK = frozenset({"it", "its", "they", "them", "their"})
"""The pronouns and possessives by which a message refers to a thing sought before ("report *its* location")."""

SEEN_HERE = frozenset({"you", "can", "could", "do", "see", "saw", "seen", "find", "found", "notice", "noticed",
                       "spot", "spotted", "is", "are", "s", "there", "here", "around", "now"})
"""The words with which a what (or who) question asks what is where the robot has just gone, naming no place
("go to the bedroom and tell me *what you see*", "... *who is there*"). English, not any corpus's."""

CONTAINING = ("on top of", "inside", "on", "in", "at")
"""The words after which a "what is ..." question names where to look."""

ASKED_OF_ROBOT = "do you know "
"""The lead-in by which a question told to someone ("where the spoon is") is asked of the robot instead
("*do you know* where the spoon is?"), so that the parser gives the frames that find its answer."""

FOUND_OUT_BY = frozenset({"Find", "Count", "LookAt"})
"""The frames that find out what a question told to someone asks (where a thing is, how many, a state)."""


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
    every: bool = False
    """``where``: the question asks where every one of a kind is ("where are the towels?"), not where one is."""

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
    return evoked.frame == "Find" and bool(first) and (first[0] in ASKING_WHETHER | ASKING_WHETHER_SHORT or any(
        first[k] in ifs and " ".join(first[:k]) in checks for k in range(1, len(first))))


def asks_where_every(text: str, evoked: Evoked) -> bool:
    """Whether a Find asks where the things of a kind are, in the plural ("*where* are the towels?", "*where* can I
    find cups?"): one question, answered with every one found, so the kind is sought once. Not a number said ("where
    are the two cups?": those two), nor one thing said in the plural: a pair ("where are my glasses?"), a noun with
    a plural form only ("where are the scissors?"), a thing of a person's the parser reads as one ("my keys")."""
    from seal_cli.language.morphology import plural_only
    from seal_cli.planning.grounding import PAIRED

    theme = evoked.elements.get("theme")
    first = text[evoked.span[0]:evoked.span[1]].lower().split()[:1]
    return (evoked.frame == "Find" and first == ["where"] and theme is not None and theme.plural
            and theme.quantity is None and not theme.conjuncts and theme.refers_to is None
            and theme.head.lower() not in PAIRED and not plural_only(theme.head.lower()))


def put_to_person(message: Phrase) -> bool:
    """Whether a Tell's message is a question put to the person told ("ask Raj *if he wants tea*"): the parser
    gives it as they hear it, a head other than the words said, ending in "?" ("do you want tea?")."""
    return message.head.endswith("?") and message.head != message.text


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


NAME_OF = frozenset({"name", "names"})
"""A message that asks for the name of someone somewhere ("tell me *the name of* the person in the office") asks who
is there: the robot goes, looks, and says whom it saw by name. English, not any corpus's."""


def _what(message: str, names: MapNames | None) -> Question | None:
    """The ``what`` question a message asks, if it asks what or who is on, in or at a map place or room."""
    words = message.lower().replace("'", "").replace("’", "").split()
    if names is not None and (named := _name_of(words, names)) is not None:
        return named
    if not words or words[0] not in ASKING_WHAT or names is None or (at := _relation_at(words, 1)) is None:
        return None
    i, n, said = at
    found = _longest_grounded(words[i + n:], names)
    return None if found is None else Question("what", found.id, said, ASKING_WHAT[words[0]])


def _relation_at(words: Sequence[str], start: int) -> tuple[int, int, str] | None:
    """The first word of :data:`CONTAINING` at or after ``start``: where it is, how many words it is, and the
    relation said (in, on or at); None when there is none."""
    for i in range(start, len(words)):
        for relation in CONTAINING:
            rel = relation.split()
            if list(words[i:i + len(rel)]) == rel:
                said = "in" if relation in ("inside", "in") else "on" if relation in ("on", "on top of") else "at"
                return i, len(rel), said
    return None


def name_asked(message: str, taxonomy: Taxonomy) -> str | None:
    """The question a message that asks for names asks, as it would be said ("the name of the person in the office":
    "who is in the office"; "the names of the people at the door": "who is at the door"; "the name of the book on the
    shelf": "what book is on the shelf"), else None. After "of", words that name a person ask who; any others ask
    what, with the words said ("book", "biggest thing"). Read from words only: the place is not grounded here."""
    words = message.lower().replace("'", "").replace("’", "").replace("?", " ").split()
    said = list(words[1:] if words[:1] == ["the"] else words)
    if len(said) < 4 or said[0] not in NAME_OF or said[1] != "of" or (at := _relation_at(said, 3)) is None:
        return None
    i = at[0]
    named = [w for w in said[2:i] if w not in WHOSE_WORDS]
    if not named:
        return None
    if any(taxonomy.is_a(w, "person") is True for w in words_of(" ".join(named))):
        return " ".join(["who", "is", *said[i:]])
    return " ".join(["what", *named, "are" if said[0] == "names" else "is", *said[i:]])


WHOSE_WORDS = frozenset({"the", "a", "an", "this", "that", "these", "those", "all"})
"""Words before the one a name is asked of that a question drops ("the name of *the* book": "what book")."""


def _name_of(words: Sequence[str], names: MapNames) -> Question | None:
    """"the name of the person in the office", "the names of the people at the door": who is there (lead, stop 42:
    the run said "name" to the speaker, the message's head, and drove nowhere); "the name of the book on the
    shelf": what is there (words43: the run said "name"), by the question :func:`name_asked` reads."""
    asked = name_asked(" ".join(words), names.taxonomy)
    return None if asked is None else _what(asked, names)


def _longest_grounded(words: Sequence[str], names: MapNames) -> Referent | None:
    """The map room or place the longest run of ``words`` from the first names ("the kitchen right now": the
    kitchen; "the table in the hall": that table, not any table); None when none does. Where no run names one but
    a run calls a room or a fixed thing the map lacks ("who is in the kitchen?" on a map without a kitchen), that is
    refused (:class:`Refusal`): a question the robot cannot look into is not said back as it was asked."""
    runs = [" ".join(words[:end]) for end in range(len(words), 0, -1) if words_of(" ".join(words[:end]))]
    for run in runs:
        if (found := names.ground(run, "location", ("room", "place"))) is not None:
            return found
    for run in runs:
        if (refused := names.refusal(run, None)) is not None:
            raise refused
    return None


def _what_here(message: str, here: str | None, names: MapNames | None) -> Question | None:
    """The ``what`` question a message asks of where the command's last Go or Find took the robot (``here``, a map
    room or place), when it asks what or who is there and names no place ("go to the bedroom and tell me *what
    you see*")."""
    words = message.lower().replace("'", " ").replace("’", " ").split()
    if len(words) < 2 or words[0] not in ASKING_WHAT or not all(w in SEEN_HERE for w in words[1:]):
        return None
    return _what_is_at(here, names, ASKING_WHAT[words[0]])


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
    return _what_is_at(bindings[0].elements.get("ground") if bindings else None, names)


def _what_is_at(where: str | None, names: MapNames | None, asks_for: str = "thing") -> Question | None:
    """The ``what`` question of a map room or place (``where``, its id): what is on a place one cannot open,
    in a room or a place one opens; None if ``where`` is neither."""
    referent = names.by_id(where) if names is not None and where is not None else None
    if names is None or referent is None or referent.kind not in ("room", "place"):
        return None
    place = names.map.place(referent.id) if referent.kind == "place" else None
    return Question("what", referent.id, "on" if place is not None and not place.openable else "in", asks_for)


def read_questions(parse: Parse, commanded: Sequence[Binding], names: MapNames | None) -> dict[Binding, Question]:
    """The question each commanded frame answers (frames that answer none are left out).

    The frames of one evoked verb phrase are consecutive in ``commanded`` and share its frame
    (:func:`seal_cli.planning.problem.commanded_frames`); each takes the question its words ask."""
    questions: dict[Binding, Question] = {}
    answered = False                  # an earlier frame of the command answers a question
    here: str | None = None           # where the command's last Go or Find took the robot
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
            question = Question("whether") if asks_whether(parse.text, evoked) else \
                Question("where", every=asks_where_every(parse.text, evoked))
        elif evoked.frame == "Count":
            question = Question("how_many")
        elif evoked.frame == "Tell" and (message := evoked.elements.get("message")) is not None:
            said = message.text or message.head
            fact = fact_asked(said)
            try:
                question = Question("fact", relation=fact) if fact else _what(said, names)
            except Refusal as refused:                                 # "who is in the kitchen?": no kitchen
                raise at_words(refused.message, message.span, parse.text) from None
            if put_to_person(message):                                  # "ask Raj if he wants tea"
                question = Question("asked")
            if question is None and answered and reports(said):           # "find the cup and tell me where it is"
                question = Question("report")
            if question is None and not answered:                       # "go to the bedroom and tell me what you see"
                question = _what_here(said, here, names)
        for b in commanded[start:k]:
            if (went := b.elements.get("goal") if b.frame.name == "Go" else
                    b.elements.get("ground") if b.frame.name == "Find" else None) is not None:
                here = went
        if question is not None:
            questions.update((b, question) for b in commanded[start:k])
            answered = answered or question.kind not in ("report", "asked")
    return questions


def anything_there(parse: Parse) -> Parse:
    """The parse with each question of whether any thing at all is somewhere ("is there *anything* in the fridge?",
    "is there something on the table?") read as what it asks: what is there, a Find with its ground and no theme,
    as "look in the fridge" is (``what``). A thing of no kind cannot be searched for; the place can be looked at."""
    def asked(evoked: Evoked) -> Evoked:
        theme = evoked.elements.get("theme")
        if theme is None or "ground" not in evoked.elements or theme.conjuncts or theme.head.lower() not in ANY_THING \
                or not asks_whether(parse.text, evoked):
            return evoked
        return replace(evoked, elements={r: p for r, p in evoked.elements.items() if r != "theme"})

    frames = tuple(asked(f) for f in parse.frames)
    return parse if frames == parse.frames else replace(parse, frames=frames)


def told_first(parse: Parse, parse_text: Callable[[str], Parse]) -> Parse:
    """The parse with each question told to someone found out first: before a Tell whose message asks where
    a thing is, how many there are or whether a thing is so ("tell Ben *where the spoon is*"), and that no
    earlier frame of the command answers, the frames that answer it, as the parser reads the same words
    asked of the robot (``parse_text``: "do you know where the spoon is?" is Find the spoon), their spans
    moved onto the message's words. The Tell then reports what they found (``report``). A message that
    asks what or who is somewhere, asks a fact, points back at something or cannot be asked of the robot
    is left to the Tell."""
    frames: list[Evoked] = []
    for evoked in parse.frames:
        asked = _found_out_by(evoked, parse.text, parse_text) \
            if not any(f.frame in FOUND_OUT_BY for f in frames) else None
        frames.extend(asked or ())
        frames.append(evoked)
    return parse if len(frames) == len(parse.frames) else replace(parse, frames=tuple(frames))


def _found_out_by(evoked: Evoked, text: str, parse_text: Callable[[str], Parse]) -> tuple[Evoked, ...] | None:
    """The frames that answer the question a Tell's message asks, placed on the message's words, or None."""
    message = evoked.elements.get("message") if evoked.frame == "Tell" else None
    said = (message.text or "") if message is not None and not put_to_person(message) else ""
    words = said.lower().replace("_", " ").replace("?", " ").split()
    if not words or words[0] not in WH_WORDS or words[0] in ASKING_WHAT or fact_asked(said) \
            or any(w in POINTING_BACK for w in words):
        return None
    start = text.find(said, evoked.span[0])
    if start < 0:
        return None
    try:
        found = parse_text(ASKED_OF_ROBOT + said).frames
    except SealError:
        return None
    if not found or any(f.frame not in FOUND_OUT_BY or "theme" not in f.elements
                        or f.frame == "LookAt" and not f.asked for f in found):
        return None
    shift = start - len(ASKED_OF_ROBOT)
    return tuple(_moved(f, shift, start, start + len(said)) for f in found)


def _moved(evoked: Evoked, shift: int, start: int, end: int) -> Evoked:
    """A frame parsed from the message asked of the robot, placed on the message's words in the command."""
    def at(span: tuple[int, int] | None) -> tuple[int, int] | None:
        return None if span is None else (max(start, span[0] + shift), min(end, span[1] + shift))

    def moved(phrase: Phrase) -> Phrase:
        return replace(phrase, span=at(phrase.span), conjuncts=tuple(moved(c) for c in phrase.conjuncts))

    return replace(evoked, span=at(evoked.span) or (start, end),
                   elements={role: moved(p) for role, p in evoked.elements.items()})
