"""Words of a command and the part each plays: the lexicon behind ``grammars/command.lark``.

The command grammar is written over *tags*, not words. This module splits a command into
words and tags each one, so that the grammar never lists a verb or a noun:

- **verbs** are the lexical units of the frame library (``Library.by_unit``), multiword ones
  included ("pick up", "tell me how many"); a particle verb may be split around its object
  ("pick the cup up", "turn the lamp on"). A frame with new lexical units makes new verbs;
- **function words** (determiners, prepositions, pronouns, conjunctions, politeness) are the
  closed classes of English, listed in :mod:`seal_cli.language.english`;
- **every other word is open-class**: a noun, an adjective or a name (``NAME``: a capitalised
  word where a noun phrase starts). A word nobody has listed is never an error;
- **result words** (``RESULT``): a participle of a lexical unit, or an adjective equal to the
  predicate of a frame's result (``hot``, ``clean``), before a noun: "a *heated* egg" evokes
  Heat. Which words these are is derived from the library's postconditions;
- **participles after a noun** (``VBG_T``, ``VBG_P``, ``VBG_I``: transitive, with a
  prepositional complement, bare) describe people and things: "the person *wearing* a hat".

Lemmas and singulars come from lemminflect, which ships its data. The tagger decides what the
grammar cannot: whether "and" joins clauses or noun phrases, whether "light" is a verb or a
noun, by looking one or two words ahead.
"""

from __future__ import annotations

from collections.abc import Iterable, Mapping, Sequence
from dataclasses import dataclass, field
from functools import cached_property, lru_cache

from seal_cli.frames.library import Library
from seal_cli.language.asides import set_aside
from seal_cli.language.english import (
    BE_WORDS,
    BECAUSE,
    DEGREE_PHRASES,
    DIRECTIONS,
    END_MARKS,
    FINITE,
    NOMINATIVE,
    NP_OPENERS,
    NUMBERS,
    OBJECT_PARTICLES,
    OBJECT_PRONOUNS,
    PARTICLES,
    PARTS,
    POLITE,
    PREPOSITIONS,
    RELAYING,
    SEPARATOR_WORDS,
    STATE_PARTICLES,
    SUBJECTS,
    SUBORDINATORS,
    TIME_WORDS,
)
from seal_cli.language.morphology import (
    gerund_lemma,
    in_dictionary,
    is_adjective,
    is_gradable,
    is_plural,
    noun_lemma,
    participles,
    parts_of_speech,
    verb_lemma,
)
from seal_cli.language.rule import AFTER_SEP, START, Match, Rule
from seal_cli.language.rules import ANYWHERE, CLAUSE_START, INSIDE, WORDS
from seal_cli.language.slips import one_slip
from seal_cli.language.state import (
    CLOSED,
    SUB_FIRST,
    State,
    inflected,
    longest_phrase,
    lower_case_name,
    match_phrase,
    subject_contracted,
)
from seal_cli.language.tags import NP_START, Tag
from seal_cli.language.tokens import MAX_LENGTH, CommandError, Word, capitalised, tokenize

__all__ = ["AGAIN_LEAST", "MAX_LENGTH", "NP_START", "CommandError", "Lexicon", "Mention", "Tagger", "Word", "is_plural",
           "mentions", "noun_lemma", "tag", "tokenize", "verb_lemma"]


# ---------------------------------------------------------------------------------------------
# The lexicon of one library


@dataclass(frozen=True)
class Lexicon:
    """Verbs and result words of a library, indexed for the tagger.

    ``units``: first word → the library's lexical units starting with it, longest first.
    ``results``: a participle or result adjective → (frame name, lexical unit).
    ``speech``: units of frames whose first element is a ``message`` or a ``question`` ("tell", "say",
    "answer"): after them a clause is what is said ("tell him *that dinner is ready*"), not a relative
    clause or a condition. ``goals``: units of frames with a ``goal`` element ("follow", "go");
    ``recipients``: units of frames with a ``recipient`` ("bring", "give", "tell"); ``things``: the
    words of the classes and synonyms the library's taxonomy knows ("fridge", "ice", "box").
    """

    units: Mapping[str, tuple[tuple[str, ...], ...]]
    results: Mapping[str, tuple[str, str]]
    verbs: tuple[str, ...]
    speech: frozenset[str] = frozenset()
    goals: frozenset[str] = frozenset()
    recipients: frozenset[str] = frozenset()
    things: frozenset[str] = frozenset()
    people: frozenset[str] = frozenset()
    """The nouns the taxonomy lists as people ("guest", "son", "person"): "the guest wants tea"."""
    escorts: frozenset[str] = frozenset()
    """Units of frames whose first element is a person ("take", "follow", "meet"): "take *jordan* there"."""
    apart: Mapping[str, frozenset[str]] = field(default_factory=dict)
    """A unit → the particles with which its verb is another verb, which no frame has ("hang" → up: end a phone
    call; :mod:`seal_cli.language.phrasal`)."""
    can: tuple[str, ...] = ()
    """What the robot can do: each frame's first lexical unit, in the library's order ("go", "find", "pick up"),
    named by the error for a verb no frame lists."""
    puts: frozenset[str] = frozenset()
    """Units of frames that put their first element in their goal (``in(theme, goal)``: "put", "bring"): "put
    the pan in the fridge, then *on the stove*" says the verb again with the same thing."""
    stores: frozenset[str] = frozenset()
    """Storing units ("put away", "put back": ``stores: true`` in the library): said split around the object,
    "back" is the BACK rule's place ("put it *back*": where it was taken from), not the unit's particle."""
    split: Mapping[str, frozenset[str]] = field(default_factory=dict)
    """Units said only split around their object (``split: true``: "put the kettle *on*", ToggleOn) → the known
    classes their frame's first element cannot be, and the parts things are made with (``english.PARTS``: "put
    the lid on", "put your coat on": no such unit)."""
    state_verbs: frozenset[str] = frozenset()
    """The verbs of the split units ("put", "leave", "get"): they put a thing in a state ("leave the door *open*")."""
    people_only: frozenset[str] = frozenset()
    """Units of ``escorts`` that no frame with another first element has ("meet", "greet", "follow"; not "take",
    "bring"): what they take first is a person, whatever the word."""
    opening: frozenset[str] = frozenset()
    """Verbs that are mostly nouns (``opening: true`` in the library: "dust", "vacuum", "ladle"): a unit only
    opening an imperative clause before its object (:func:`opens_before_object`), a noun anywhere else."""
    motionless: frozenset[str] = frozenset()
    """Units none of whose frames has a goal or a source ("wipe", "dust", "heat"; not "take", "clear off"): a
    particle right after them, before their object, moves nothing ("dust *off* the shelf", words36)."""
    undoable: frozenset[str] = frozenset()
    """Units of frames that leave their theme in a state another frame of the library undoes (a one-place fact on
    the theme that two frames' postconditions say, one way or the other: open/closed, on/off, hot/cold; what the
    robot holds is its hands' state, not the thing's: frames that empty or fill its hands are left out): "did you
    *close* the door?" is answered by looking at it, since it may have been opened again (words25)."""
    puts_only: frozenset[str] = frozenset()
    """Units of ``puts`` that no other frame lists ("leave", "put"; not "return", "move", also Go's): said alone,
    with no object, "leave" is going away (rule ``leave with nothing after it``, words40)."""

    @classmethod
    def of(cls, library: Library) -> Lexicon:
        units: dict[str, list[tuple[str, ...]]] = {}
        for unit in library.units:           # longest first
            words = tuple(unit.split())
            units.setdefault(words[0], []).append(words)
        speech = frozenset(unit.text for frame in library.frames if frame.elements
                           and frame.elements[0].type in ("message", "question") for unit in frame.lexical_units)
        goals = frozenset(unit.text for frame in library.frames if any(e.role == "goal" for e in frame.elements)
                          for unit in frame.lexical_units)
        recipients = frozenset(unit.text for frame in library.frames
                               if any(e.role == "recipient" for e in frame.elements) for unit in frame.lexical_units)
        taxonomy = library.taxonomy
        things = frozenset(word for name in (*taxonomy.known_classes, *taxonomy.names) for word in name.split("_"))
        people = frozenset({"person", *taxonomy.members("person")}) if "person" in taxonomy else frozenset()
        escorts = frozenset(unit.text for frame in library.frames if frame.elements and
                            frame.elements[0].type == "person" for unit in frame.lexical_units)
        people_only = escorts - frozenset(unit.text for frame in library.frames if frame.elements and
                                          frame.elements[0].type != "person" for unit in frame.lexical_units)
        can = tuple(dict.fromkeys(frame.lexical_units[0].text for frame in library.frames if frame.lexical_units))
        apart = {unit.text: frozenset(unit.apart) for frame in library.frames for unit in frame.lexical_units
                 if unit.apart}
        putting = [frame for frame in library.frames if frame.elements and any(
            not p.negated and p.predicate == "in" and p.args == (frame.elements[0].role, "goal")
            for p in frame.postconditions)]
        puts = frozenset(unit.text for frame in putting for unit in frame.lexical_units)
        puts_only = puts - frozenset(unit.text for frame in library.frames if frame not in putting
                                     for unit in frame.lexical_units)
        stores = frozenset(unit.text for frame in library.frames for unit in frame.lexical_units if unit.stores)
        split = {unit.text: frozenset(c for c in taxonomy.known_classes if frame.elements and
                                      taxonomy.is_a(c, frame.elements[0].type) is False) | PARTS
                 for frame in library.frames for unit in frame.lexical_units if unit.split}
        # "put the lid on": a part fitted to the thing it is made with ("lid", "cover", "door"), not switched on
        said = {frame.name: {p.predicate for p in frame.postconditions if frame.elements and
                             p.args == (frame.elements[0].role,) and frame.elements[0].role == "theme"}
                for frame in library.frames if not any(p.predicate == "hand_empty" for p in frame.postconditions)}
        undone = {p for name, preds in said.items() for p in preds
                  if any(p in other for n, other in said.items() if n != name)}
        undoable = frozenset(unit.text for frame in library.frames if said.get(frame.name, set()) & undone
                             for unit in frame.lexical_units)
        moving = frozenset(unit.text for frame in library.frames if any(e.role in ("goal", "source")
                                                                       for e in frame.elements)
                           for unit in frame.lexical_units)
        motionless = frozenset(library.by_unit) - moving
        return cls({w: tuple(us) for w, us in units.items()}, _result_words(library),
                   tuple(sorted(library.by_unit)), speech, goals, recipients, things, people, escorts, apart, can, puts,
                   stores, split, frozenset(unit.split()[0] for unit in split), people_only,
                   frozenset(unit.text for frame in library.frames for unit in frame.lexical_units if unit.opening),
                   motionless, undoable, puts_only)

    @cached_property
    def verb_set(self) -> frozenset[str]:
        """The verbs, to ask whether a word is one (``in`` the tuple of 667 took 2 ms a refusal)."""
        return frozenset(self.verbs)

    def verb_at(self, words: Sequence[Word], i: int, stop: int) -> tuple[str, int, int | None] | None:
        """The lexical unit that starts at word ``i``: (unit, words it covers contiguously,
        index of a split particle or None). Contiguous matches are preferred, longest first;
        "pick the cup up" splits "pick up" when "up" stands alone before the clause ends."""
        first = words[i].lower
        candidates = self.units.get(first)
        if not candidates:                       # "putting", "placed": a form of a lexical unit
            base = verb_lemma(first) if first.isalpha() else None
            base = base or self.regular_past(first)
            candidates = self.units.get(base) if base and base != first else None
            if not candidates:
                return self.again(words, i) or self.mistyped(words, i, stop) or self.written_together(words, i)
        if i + 2 < len(words) and words[i + 1].lower == "of" and (words[i + 2].lower in NP_OPENERS or
                                                                 words[i + 2].lower in OBJECT_PRONOUNS):
            off = self.typed_of(candidates)
            if off and off.split()[0] == first:  # the base form, said to the robot ("left of the sink": where)
                return off, 2, None              # "turn *of* the kettle": "off" typed with one "f" (words30)
        for unit in candidates:
            n = len(unit)
            if i + n <= len(words) and all(words[i + k].lower == unit[k] for k in range(1, n)):
                if i + n < len(words) and words[i + n].lower in ("of", "'s") and unit[-1] not in ("many", "much"):
                    return None                  # "slice of apple", "the light's": a noun ("how many of": a part)
                if n > 1 and " ".join(unit) in self.split:
                    continue                     # "put on the table", "put on your coat": no unit said joined
                if n == 1 and unit[0] in self.opening and not (first == unit[0] and opens_before_object(words, i)) \
                        and not _perfect(words, i):
                    continue                     # "put the dust in the bin": a noun; "dust the shelf": the verb
                if n > 1 or not self._split(words, i, stop, candidates):
                    return " ".join(unit), n, None
                break
        split = self._split(words, i, stop, candidates)
        if split:
            return split
        if all(len(unit) == 1 and unit[0] in self.opening for unit in candidates):
            return self.again(words, i)          # "reposition two clocks": no object opener, so "re" + "position"
        return None

    def regular_past(self, word: str) -> str | None:
        """The unit whose regular past form a word lemminflect does not know is ("hoovered": "hoover", "hoovered"
        was no verb at all; words36): "-ed" or "-d" taken off leaves a one-word unit of the library; else None."""
        if len(word) < 5 or not word.endswith("ed") or not word.isalpha():
            return None
        return next((stem for stem in (word[:-2], word[:-1]) if (stem,) in self.units.get(stem, ())), None)

    def written_together(self, words: Sequence[Word], i: int) -> tuple[str, int, None] | None:
        """A unit of a verb and its particle written as one word ("*turnoff* the lights", "*pickup* the toys":
        "turn off", "pick up"), where only a verb can stand (:func:`opens_before_object`: a clause's start, before
        its object); elsewhere the word is the noun it also is ("a *pickup*", "what a *turnoff*"). words30."""
        unit = self._joined.get(words[i].lower)
        return (unit, 1, None) if unit is not None and opens_before_object(words, i) else None

    @cached_property
    def _joined(self) -> dict[str, str]:
        """Each unit of two words (a verb and its particle) written together → the unit."""
        return {"".join(unit): " ".join(unit) for units in self.units.values() for unit in units
                if len(unit) == 2 and unit[1] in PARTICLES}

    @staticmethod
    def typed_of(candidates: Iterable[tuple[str, ...]]) -> str | None:
        """The unit "V off" a verb said with "of" before its object stands for ("turn *of* the kettle", "switch
        *of* the lights": "off" typed with one "f"): no verb of the library takes "of" right after it, so "V of"
        and a noun phrase is no English but the slip; None when the verb has no such unit or one with "of"."""
        units = tuple(candidates)
        if any(len(unit) == 2 and unit[1] == "of" for unit in units):
            return None
        return next((" ".join(unit) for unit in units if len(unit) == 2 and unit[1] == "off"), None)

    def again(self, words: Sequence[Word], i: int) -> tuple[str, int, None] | None:
        """A verb said with the prefix *re-* ("again") that the library lacks is the verb it repeats: "re
        arranging" (two words), "re-arrange", "rearranging" (one; the verb after "re" of at least
        :data:`AGAIN_LEAST` letters, so "reset" and "recall" stay unknown) are "arrange". Only a one-word unit,
        and only where the word itself is no unit ("reheat", "return", "remove" are theirs)."""
        first = words[i].lower
        if first == "re" and i + 1 < len(words):
            rest, n, least = words[i + 1].lower, 2, 1
        elif first.startswith("re-"):
            rest, n, least = first[3:], 1, 1
        elif first.startswith("re"):
            rest, n, least = first[2:], 1, AGAIN_LEAST
        else:
            return None
        if not rest.isalpha():
            return None
        for form in (rest, verb_lemma(rest) or rest):
            if len(form) >= least and (form,) in self.units.get(form, ()):
                return form, n, None
        return None

    def mistyped(self, words: Sequence[Word], i: int, stop: int | None = None) -> tuple[str, int, int | None] | None:
        """A one-word unit typed with one slip of the fingers: two neighbouring letters swapped ("*brign* me the cup",
        "*tkae* it"), one letter left out ("*brng* it", "*plae* the cup": "place") or one letter typed twice or
        between ("*bringg*", "*opent* it"): a word of at least :data:`TYPO_LEAST` letters that no dictionary lists,
        written in lower case (a capital only first in the sentence), no thing of the taxonomy, one slip from exactly
        one unit, and no unit that is mostly a noun ("laddle" is no slip of the verb "ladle"). "ben", "jamie" (names)
        are no slip of a unit; a word the dictionary lists ("form" beside "from") is never read so. The first word
        of a unit of several words slips too (words24): "*tunr* on the lamp" is "turn on", "*swithc* the light
        off" "switch off", read as the verb the slip stands for (the unit's other words as :meth:`verb_at` finds
        them)."""
        word = words[i]
        low = word.lower
        if len(low) < TYPO_LEAST or not low.isalpha() or low in self.things or \
                word.text != low and not (i == 0 and word.text[1:] == low[1:]):
            return None
        found = self._slips.get(low)
        if found is None:
            if len(self._slips) >= SLIPS_KEPT:
                self._slips.clear()              # a long-running parser meets words without end
            found = self._slips[low] = "" if in_dictionary(low) else self._slipped(low)
        if not found:
            return None
        fixed = list(words)
        fixed[i] = Word(word.text, word.start, word.end, word.tag, word.info, lower=found)
        return self.verb_at(fixed, i, len(words) if stop is None else stop)

    @cached_property
    def _slips(self) -> dict[str, str]:
        """A typed word → the unit it slips from ("" none): the tagger asks of each word more than once."""
        return {}

    def _slipped(self, low: str) -> str:
        found = {w for w in one_slip(low) if w in self.units and w not in self.opening}   # "laddle": a noun
        return found.pop() if len(found) == 1 else ""

    def _split(self, words: Sequence[Word], i: int, stop: int,
               candidates: Iterable[tuple[str, ...]]) -> tuple[str, int, int | None] | None:
        """The split unit whose particle stands alone nearest after the verb: "switch the light *off* that I left
        on" is "switch off" (the last "on" is the relative clause's). One pass over the words."""
        candidates = tuple(candidates)
        by_particle = _by_particle(candidates, self.stores)
        if not by_particle:
            return None
        for j in range(i + 2, stop):
            low = words[j].lower
            if low == "to" and j + 1 < stop and (words[j + 1].lower in self.units or
                                                 verb_lemma(words[j + 1].lower) in self.units):
                return None                      # "wash a teapot *to put it away*", "*to rinsed off*": the next verb's
            for unit in by_particle.get(low, ()):
                if _stands_alone(words, j) and match_phrase(words, j - 1, TIME_WORDS) < 2 and \
                        self._split_fits(unit, words, i, j):  # not "right away"
                    done = j - 1 > i + 1 and self.done_unit(words[j - 1].lower, low) is not None
                    return unit, 1, j - 1 if done else j   # "leave the heater *turned on*": both the particle
        if any(len(unit) == 1 for unit in candidates):
            return None                          # "take the lid off the pot": "take" is a unit alone
        return _particle_as_source(words, i, stop, by_particle)

    def done_unit(self, done: str, particle: str, *, base: bool = False) -> str | None:
        """The unit of two words a past participle and a particle say ("turned" "on": "turn on", "switched off"),
        when the library has it; else None. Said after the thing of a split unit with that particle ("leave the
        heater *turned on*"), it is the unit's particle said with a verb of the same state, no word of the thing
        (issue #13: the theme was "the heater turned"). ``base``: a participle spelt as its verb ("put", "shut")
        counts too (a wish for a thing done, "I'd like the coat put on": ``requests._done_with_particle``)."""
        verb = verb_lemma(done) if done.isalpha() else None
        if verb is None or done == verb and not base or done not in participles(verb):
            return None
        return f"{verb} {particle}" if (verb, particle) in self.units.get(verb, ()) else None

    def _split_fits(self, unit: str, words: Sequence[Word], i: int, j: int) -> bool:
        """A split-only unit ("put on") holds around a thing its frame takes, with no place said between: "put the
        kettle *on*", "put the telly *on*" (a thing nobody listed), not "put the lid *on*" nor "put the cup in the
        sink *on*"."""
        refused = self.split.get(unit)
        if refused is None:
            return True
        if any(w.lower in PREPOSITIONS for w in words[i + 1:j]):
            return False
        after = words[j + 1].lower if j + 1 < len(words) else "."
        if not (after in (",", ".", "!", "?", ";", "please") or after in PREPOSITIONS or after in SEPARATOR_WORDS or
                match_phrase(words, j + 1, TIME_WORDS) > 0):     # "put the kettle on *right now*"
            return False                         # "put the kettle on *its* base": a possessive, not "it's"
        return noun_lemma(words[j - 1].lower) not in refused and words[j - 1].lower not in refused


OPENERS = frozenset(w for w in (*SEPARATOR_WORDS, "to") if " " not in w) | {".", "!", "?"}
"""The words after which an imperative clause opens ("and", "then", ",", "to": "I need you *to* dust the shelf"),
besides the sentence's start and politeness ("please", "could you")."""


def _perfect(words: Sequence[Word], i: int) -> bool:
    """Whether the word at ``i`` is a past form ending in "-ed" after "have" ("once you've *hoovered* the rug"): a
    verb, never a noun (words36)."""
    return i > 0 and words[i].lower.endswith("ed") and words[i - 1].lower in ("have", "has", "had", "'ve", "you've")


def opens_before_object(words: Sequence[Word], i: int) -> bool:
    """Whether the word at ``i`` stands where only a verb can: opening an imperative clause (the sentence's start,
    after a joint, "to" or politeness) and right before a noun phrase's opener or an object pronoun ("dust *the*
    shelf", "please vacuum *my* room", "ladle *it* into the bowl"), maybe with a particle between ("dust *off* the
    shelf", "hoover *up* the crumbs", words36). A noun is never followed by "the" there."""
    k = i + 2 if i + 2 < len(words) and words[i + 1].lower in OBJECT_PARTICLES else i + 1
    if k >= len(words) or not (words[k].lower in NP_OPENERS or words[k].lower in OBJECT_PRONOUNS):
        return False
    if i == 0 or words[i - 1].lower in OPENERS:
        return True
    return any(tuple(w.lower for w in words[max(0, i - len(p)):i]) == p for p in POLITE_WORDS)


POLITE_WORDS = tuple(tuple(phrase.split()) for phrase in POLITE)


_SOURCE_PARTICLES = frozenset(["off"])
"""Particles of leaving that are also the preposition of a source ("the plates *off* the table")."""


def _particle_as_source(words: Sequence[Word], i: int, stop: int,
                        by_particle: dict[str, tuple[str, ...]]) -> tuple[str, int, None] | None:
    """"*clear* the plates *off* the table": a verb that is a unit only with a particle of leaving ("clear off";
    "clear" alone is none), its particle after the object and before a noun phrase, is that unit, and the particle
    is also the preposition of where from (words38: refused at "clear"). The particle stays a preposition: the
    place is the frame's source."""
    for j in range(i + 2, min(stop, len(words) - 1)):
        low = words[j].lower
        if low in SEPARATOR_WORDS or low in END_MARKS or low == ",":
            return None
        if low in _SOURCE_PARTICLES and low in by_particle and words[j + 1].lower in NP_OPENERS:
            return by_particle[low][0], 1, None
    return None


@lru_cache(maxsize=4096)
def _by_particle(candidates: tuple[tuple[str, ...], ...], stores: frozenset[str]) -> dict[str, tuple[str, ...]]:
    """A verb's two-word particle units by their particle ("turn" → on: "turn on", off: "turn off"), in the
    candidates' order; not "back" of a storing unit (the BACK rule's place)."""
    found: dict[str, list[str]] = {}
    for unit in candidates:
        if len(unit) == 2 and unit[1] in PARTICLES and not (unit[1] == "back" and " ".join(unit) in stores):
            found.setdefault(unit[1], []).append(" ".join(unit))
    return {particle: tuple(units) for particle, units in found.items()}


TYPO_LEAST = 4
"""The fewest letters of a word read as a unit typed with one slip (:meth:`Lexicon.mistyped`): "tkae" is "take";
three letters leave too few words apart ("og" is no "go", "pu" no "put")."""
SLIPS_KEPT = 65536
"""How many typed words :meth:`Lexicon.mistyped` remembers before it starts afresh."""

AGAIN_LEAST = 5
"""The fewest letters of the verb after a joined "re" (:meth:`Lexicon.again`): "rearrange" is "arrange", "reset"
is no "set"."""


def _stands_alone(words: Sequence[Word], j: int) -> bool:
    """A particle stands alone when no noun phrase follows it (it is not a preposition there)."""
    if j + 1 >= len(words):
        return True
    after = words[j + 1].lower
    if after in ("that", "which") and j + 2 < len(words) and (words[j + 2].lower in BE_WORDS or
                                                              words[j + 2].lower in NOMINATIVE):
        return True            # "turn the lamp on *that is* on the table", "the light off *that I* left on": a
        # relative clause of the noun before
    return after in (",", ".", "!", "?", ";", "please") or after in PREPOSITIONS or after in SEPARATOR_WORDS or \
        after in DIRECTIONS or after in BECAUSE or "'" in after and after.split("'")[0] in SUBJECTS or \
        after == "so" and j + 2 < len(words) and words[j + 2].lower in SUBJECTS | {"that"} or \
        subject_contracted(words, j + 1) or \
        match_phrase(words, j + 1, SUBORDINATORS) > 0 or \
        match_phrase(words, j + 1, TIME_WORDS) > 0 or \
        longest_phrase(words, j + 1, DEGREE_PHRASES) > 0   # "turn it off *it's* too loud", "... *when*", "... *right
    #                                                         away*"; "turn the heating on *a little*" (words31);
    #                                                         "switch the fan on *so I* can sleep": a purpose


def _result_words(library: Library) -> dict[str, tuple[str, str]]:
    """Words before a noun that name a frame's result: participles of its lexical units and the
    predicate of a positive one-place postcondition on its first element (``hot(theme)``)."""
    results: dict[str, tuple[str, str]] = {}
    for frame in library.frames:
        if not frame.elements or not frame.lexical_units:
            continue
        first = frame.elements[0]
        if first.role != "theme" or library.taxonomy.is_a("person", first.type) and \
                not library.taxonomy.is_open(first.type):
            continue    # only a theme's state is a result ("the moved cup" does not mean Go)
        effects = [f for f in frame.postconditions if not f.negated and f.args == (first.role,)]
        if not effects:
            continue
        for fact in effects:
            if fact.predicate.isalpha() and is_adjective(fact.predicate):
                results.setdefault(fact.predicate, (frame.name, frame.lexical_units[0].text))
                for unit in frame.lexical_units:     # "a warm apple", "a cool tomato": the same state
                    if len(unit.words) == 1 and is_gradable(unit.text):
                        results.setdefault(unit.text, (frame.name, unit.text))
        for unit in frame.lexical_units:
            words = unit.words
            if unit.split:
                continue                          # "left" is no result of "leave the light on": "their left arm"
            if len(words) == 1 or all(w in PARTICLES for w in words[1:]):
                for form in participles(words[0]):
                    if form not in CLOSED:
                        results.setdefault(form, (frame.name, unit.text))
                        if len(words) > 1:          # "turned off": ToggleOff, whatever "turned" alone is
                            results.setdefault(" ".join((form, *words[1:])), (frame.name, unit.text))
    return results



# ---------------------------------------------------------------------------------------------
# The tagger: a short loop over the tables of rules


class Tagger(State):
    """Tags the words of one command (see the module docstring) by the tables of
    :mod:`seal_cli.language.rules`. Not thread-safe; cheap to make. ``trace``: when a list, the
    names of the rules that matched, in order, are appended to it."""

    def __init__(self, lexicon: Lexicon, words: list[Word], text: str = "",
                 trace: list[str] | None = None, sift: bool = True) -> None:
        words, aside = set_aside(lexicon, words)     # "(any drink is fine)": a remark, before any rule reads on
        super().__init__(lexicon, words, text)
        self.remarks.extend(aside)
        self.trace = trace
        self.unsaid = _GATES.unsaid(self.words) if sift else 0
        """The rules whose ``needs`` this command does not say (:meth:`Gates.unsaid`), never asked here; ``sift``
        False asks them (a test: the same rules fire either way)."""

    def run(self) -> list[Word]:
        words = self.words
        i = 0
        while i < len(words):
            low = words[i].lower
            found = self.first_match(_ANYWHERE, low, i)
            if found is None and self.expect_verb:
                found = self.first_match(_CLAUSE_START, low, i)
                if found is None:
                    self.expect_verb = False    # not a verb: tag it as what it is; the grammar reports it
            if found is None:
                found = self.first_match(_INSIDE, low, i)
            if found is None:
                found = self.first_match(_WORDS, low, i)
                assert found is not None        # the last rule of WORDS always matches
                last = self.out[-1]
                if last.lower in ("hand", "hands") and len(self.out) > 1 and \
                        self.out[-2].tag in (Tag.PREP, Tag.POSS) and self.verb_after(i + found.consumed):
                    self.expect_verb = True     # "with a clock in hand turn the lamp on"
            i += found.consumed
        return self.out

    def first_match(self, table: int, low: str, i: int) -> Match | None:
        """The first rule of table ``table`` (of those its gates admit at word ``i``, read as ``low``) that consumes
        words at ``i``, applied; rules that only retag the last word are applied on the way."""
        out = self.out
        after = out[-1].tag if out else START
        gated = _KNOWN.get((low, after, self.unsaid))
        if gated is None:
            gated = _GATES.rules(low, after, self.unsaid)
        return self.first_of(gated[table], table, low, i, after)

    def first_of(self, rules: tuple[Rule, ...], table: int, low: str, i: int, after: str) -> Match | None:
        """:meth:`first_match` over ``rules``, gated after a word tagged ``after``: where a rule retags the last
        word ("tell *her* we're moving": a pronoun, not a possessive), the rules after it are those the gates admit
        after its new tag."""
        out = self.out
        for rule in rules:
            found = rule.match(self, i)
            if found is None:
                continue
            self.apply(found, i)
            if self.trace is not None:
                self.trace.append(rule.name)
            if found.consumed:
                return found
            retagged = out[-1].tag if out else START
            if retagged != after:
                return self.first_of(_GATES.rest(table, low, retagged, rule, self.unsaid), table, low, i, retagged)
        return None

    def apply(self, found: Match, i: int) -> None:
        """Make what a rule matched at word ``i`` part of the state."""
        if found.last is not None:
            self.out[len(self.out) - found.replaces:] = [found.last]
        self.out.extend(found.words)
        if found.remarks:
            self.remarks.extend(found.remarks)
        if found.using is not None:
            self.using = found.using
        if found.verb is not None:
            self.speech = found.verb in self.lexicon.speech     # a clause after it is what is said
            self.verb_index = next(k for k in range(len(self.out) - 1, len(self.out) - len(found.words) - 1, -1)
                                   if self.out[k].tag == Tag.VERB) if found.words[-1].tag != Tag.VERB and any(
                w.tag == Tag.VERB for w in found.words) else len(self.out) - 1   # "Anna wants": the verb, not Anna
        if found.particle is not None:
            self.particles[found.particle[0]] = found.particle[1]
        if found.expect is AFTER_SEP:
            self.expect_verb = self.prev_tag() == Tag.SEP
        elif found.expect is not None:
            self.expect_verb = bool(found.expect)
        if i in self.particles and found.consumed:
            del self.particles[i]


class Gates:
    """The rules of each table that may match a word, by the word's lower-case form, the tag of the last tagged word
    and the rules the command leaves out (each rule's ``first`` and ``after`` gates, asked once per form and tag, and
    its ``needs``, asked once per command; the answer kept here): an index derived from the rules themselves, so a
    new rule is in it as soon as it is in its table."""

    FORMS = 100_000
    """How many (word form, tag, rules left out) keys are kept before the cache starts again."""

    def __init__(self, tables: tuple[tuple[Rule, ...], ...]) -> None:
        self.tables = tables
        self.known: dict[tuple[str, str, int], tuple[tuple[Rule, ...], ...]] = {}
        """What :meth:`rules` has answered, by (word form, tag, :meth:`unsaid`): the tagger reads it first."""
        self._position = [{id(rule): k for k, rule in enumerate(table)} for table in tables]
        needs = list(dict.fromkeys(rule.needs for table in tables for rule in table if rule.needs is not None))
        self._needs = tuple((1 << k, words) for k, words in enumerate(needs))
        """Each distinct ``needs`` of the rules, and its bit in :meth:`unsaid`'s mask."""
        self._bit = {id(rule): 1 << needs.index(rule.needs) for table in tables for rule in table
                     if rule.needs is not None}

    def unsaid(self, words: Sequence[Word]) -> int:
        """The rules a command of ``words`` leaves out, as a mask of the bits of their ``needs``: those none of whose
        needed words it says (0: none left out)."""
        said = {w.lower for w in words}
        mask = 0
        for bit, needed in self._needs:
            if needed.isdisjoint(said):
                mask |= bit
        return mask

    def rules(self, low: str, after: str, unsaid: int = 0) -> tuple[tuple[Rule, ...], ...]:
        """For each table, its rules, in order, that may match a word read as ``low`` after a word tagged
        ``after`` (``START``: the first) in a command that leaves out the rules of mask ``unsaid``."""
        key = (low, after, unsaid)
        rules = self.known.get(key)
        if rules is None:
            if unsaid:
                bit = self._bit
                rules = tuple(tuple(r for r in table if not unsaid & bit.get(id(r), 0))
                              for table in self.rules(low, after))
            else:
                rules = tuple(tuple(r for r in table if r.admits(low) and r.follows(after)) for table in self.tables)
            if len(self.known) >= self.FORMS:
                self.known.clear()
            self.known[key] = rules
        return rules

    def rest(self, table: int, low: str, after: str, rule: Rule, unsaid: int = 0) -> tuple[Rule, ...]:
        """The rules of table ``table`` after ``rule`` that may match a word read as ``low`` after a word tagged
        ``after`` (where a rule has just retagged the last word), the rules of mask ``unsaid`` left out."""
        position = self._position[table]
        here = position[id(rule)]
        return tuple(r for r in self.rules(low, after, unsaid)[table] if position[id(r)] > here)


_GATES = Gates((ANYWHERE, CLAUSE_START, INSIDE, WORDS))
"""The tagger's tables in the order :meth:`Tagger.run` tries them."""
_KNOWN = _GATES.known
_ANYWHERE, _CLAUSE_START, _INSIDE, _WORDS = range(4)
"""The tables' places in ``_GATES``."""


@dataclass(frozen=True)
class Mention:
    """A noun phrase said in a statement or condition beside the command ("*my son Declan* arrives"):
    what a pronoun of the command may stand for. ``head`` is its last word (a name as written)."""

    start: int
    end: int
    head: str
    name: bool
    determined: bool
    oblique: bool = False            # the object of a preposition ("a question about *the computer*")


def mentions(text: str, start: int, end: int) -> list[Mention]:
    """The noun phrases of ``text[start:end]``, a statement or condition that is no command: a determiner, a
    possessive or a capitalised word, then open-class words; a name ends its phrase ("my friend *Ana* arrives"), a
    subject pronoun too ("the book *I* was reading": a relative clause without "that", words38)."""
    try:
        words = tokenize(text[start:end])
    except CommandError:
        return []
    found: list[Mention] = []
    opened = (match_phrase(words, 0, SUBORDINATORS) or 1) if words and words[0].lower in SUB_FIRST else -1
    k = 0
    while k < len(words):
        low = words[k].lower
        determined = low in NP_OPENERS or _counted(words, k)
        existential = _after_there_is(words, k) and low.isalpha() and low not in CLOSED
        someone = low in _SOMEONE
        subject = k == 0 or k == opened           # "*ben* is in ...", "when *sam* gets home", "as soon as *dad* ..."
        named = capitalised(words[k]) or subject and lower_case_name(words, k)
        bare = subject and not named and (_bare_subject(words, k) or k == 0 and _bare_phrase(words))
        # "*grandpa* is in the garden" (words25); "*door*", a remark of a bare phrase alone (words26)
        if not (determined or existential or someone or bare or named and low not in CLOSED and
                low not in NOMINATIVE and low not in _EXISTENTIAL):
            k += 1
            continue
        first, k = k, k + 1 if determined or someone else k
        while k < len(words) and words[k].lower.replace("-", "").isalpha() and words[k].lower not in CLOSED and \
                words[k].lower not in NOMINATIVE and \
                words[k].lower not in FINITE and words[k].lower not in SEPARATOR_WORDS and \
                words[k].lower not in RELAYING and \
                words[k].lower not in SUB_FIRST and words[k].lower not in _SOMEWHERE and \
                not (gerund_lemma(words[k].lower) and not _gerund_modifier(words, k, first + int(determined))) and \
                not (k > first + int(determined) and _present_verb(words[k].lower)) and \
                not (k > first + int(determined) and words[k].lower in STATE_PARTICLES):   # "left the fridge *open*"
            k += 1
            if capitalised(words[k - 1]) and not (k < len(words) and capitalised(words[k])):
                break                                         # "my son Declan | arrives"
        if k > first + int(determined):
            head = words[k - 1]
            oblique = first > 0 and words[first - 1].lower in PREPOSITIONS
            found.append(Mention(start + words[first].start, start + head.end, head.text,
                                 capitalised(head) or head is words[first] and named,
                                 determined or existential or someone or bare, oblique))
        else:
            k = max(k, first + 1)
    return found


_EXISTENTIAL = frozenset(["there", "here"])
"""Capitalised first in a statement, these name nothing ("*There*'s a cup on the table")."""
_SOMEONE = frozenset(["someone", "somebody"])
"""An indefinite person a statement may introduce ("*Someone*'s at the door, let them in")."""
_SOMEWHERE = frozenset(["somewhere", "anywhere", "everywhere", "nowhere"])
"""Adverbs of place that end the phrase before them ("the dish *somewhere* in the dining room")."""


def _bare_subject(words: Sequence[Word], k: int) -> bool:
    """Whether word ``k``, a word the dictionary lists, in lower case and with no determiner, is the subject of a
    finite verb ("*grandpa* is in the garden", "as soon as *dad* arrives", "*milk* is in the fridge"): a phrase of
    its own, introduced as one said with a determiner is, no name: a pronoun takes it up where its head fits (a
    person of the taxonomy for "him": grandpa, dad; "dinner is ready, tell him" leaves "him" unresolved)."""
    low = words[k].lower
    if not low.isalpha() or low in CLOSED or low.endswith("ever") or k + 1 >= len(words):
        return False
    nxt = words[k + 1].lower
    return nxt in FINITE or nxt == "'s" or nxt.isalpha() and nxt not in CLOSED and inflected(nxt)


def _bare_phrase(words: Sequence[Word]) -> bool:
    """Whether the words are a bare phrase alone, open-class words with no verb of being ("door", "kitchen
    table"): a thing said telegraphically before a command that takes it up ("door - open it", words26)."""
    return bool(words) and all(w.lower.isalpha() and w.lower not in CLOSED and w.lower not in FINITE for w in words)


def _counted(words: Sequence[Word], k: int) -> bool:
    """Whether word ``k`` is a number before an open-class word ("there are *two* cups in the sink", "*3* plates"):
    it opens a phrase as a determiner does (words25)."""
    low = words[k].lower
    if not (low in NUMBERS or low.isdigit()) or k + 1 >= len(words):
        return False
    nxt = words[k + 1].lower
    return nxt.isalpha() and nxt not in CLOSED


def _after_there_is(words: Sequence[Word], k: int) -> bool:
    """Whether word ``k`` follows "there is/'s/are" (a modal between: "there should be"): a bare noun there is
    introduced as a determiner would ("there's *mustard* in the kitchen")."""
    return k >= 2 and words[k - 1].lower in BE_WORDS and \
        any(w.lower == "there" for w in words[max(0, k - 3):k - 1])


def _gerund_modifier(words: Sequence[Word], k: int, opening: int) -> bool:
    """Whether the -ing form at ``k`` opens its phrase and a noun follows it ("a *cleaning* supply"): a modifier,
    not the verb that ends the phrase ("the man *waiting* at the door")."""
    return k == opening and k + 1 < len(words) and words[k + 1].lower.isalpha() and \
        words[k + 1].lower not in CLOSED and not gerund_lemma(words[k + 1].lower)


def _present_verb(low: str) -> bool:
    """Whether a word after a noun is a verb's present tense and no noun ("the guest *arrives*", "when the guests
    *arrive*"; "the *dishes*", "the coffee *maker*" stay nouns): it ends the phrase a statement names."""
    lemma = verb_lemma(low)
    return bool(lemma) and (lemma == low or low == f"{lemma}s" or low == f"{lemma}es") and \
        "noun" not in parts_of_speech(lemma) and "adj" not in parts_of_speech(lemma)


def tag(lexicon: Lexicon, text: str) -> list[Word]:
    """The tagged words of a command."""
    return Tagger(lexicon, tokenize(text), text).run()
