"""One clause → the frames it evokes: which frame of the verb (:meth:`Evoker.clause`), the frames
that must come first (result words, contents, pieces to cut, things to hold: the implied frames),
the clause's own frame with its elements as :class:`~seal_cli.language.values.Phrase` values, and
what is put where after it. Role choice is :mod:`seal_cli.language.roles`, reference
:mod:`seal_cli.language.reference`.
"""

from __future__ import annotations

from collections.abc import Iterable, Mapping, Sequence
from dataclasses import replace
from typing import TYPE_CHECKING, Any

from seal_cli.frames.library import Library
from seal_cli.frames.model import Frame
from seal_cli.language.element_types import Types
from seal_cli.language.english import (
    BESIDE,
    DEGREE_PHRASES,
    LOCATED,
    LOCATIVE,
    NP_OPENERS,
    NUMBER_MEANS,
    PARTICLES,
    ROUTE_NOUNS,
    SOME_PERSON,
    SPEAKER_PRONOUNS,
    TIME_UNITS,
    WH_WORDS,
    is_room_word,
)
from seal_cli.language.grounding import PARTS, PIECES, PORTIONS
from seal_cli.language.lexicon import CommandError, Mention, Word, noun_lemma
from seal_cli.language.morphology import is_gradable
from seal_cli.language.reference import PLACES, Reference
from seal_cli.language.roles import FROM, PUT_IN, ROLE_PREPOSITIONS, TO, Roles
from seal_cli.language.syntax import NP, PP, Clause
from seal_cli.language.unplaced import unplaced
from seal_cli.language.values import Evoked, Parse, Phrase

if TYPE_CHECKING:
    from seal_cli.language.grounding import Vocabulary

__all__ = ["Evoker", "Fit"]


_ASKERS = frozenset(["he", "she", "they", "him", "her", "them"])
"""Pronouns of a person whose question is answered ("answer whatever *she* asks you", "the question *they* ask")."""


Fit = tuple[tuple[float, ...], Frame, dict[str, Any], list[tuple[NP, PP]]]
"""A frame chosen for a clause: its key (higher is better), the frame, its elements (role → phrase)
and the phrases that describe a noun instead (:data:`seal_cli.language.roles.Assignment`)."""


_IN_IT = frozenset((prep, pronoun) for prep in ("in", "on", "inside", "into", "onto") for pronoun in ("it", "them"))
"""After contents said with a thing ("a bowl with a knife *in it*"): said to be in or on the thing."""


class Evoker:
    """Builds the frames of one command's clauses, in order, into :attr:`frames`."""

    def __init__(self, text: str, library: Library, types: Types, vocabulary: Vocabulary | None,
                 words: Sequence[Word], remarks: Sequence[tuple[int, int]] = ()) -> None:
        self.text = text
        self.library = library
        self.types = types
        self.vocabulary = vocabulary
        self.frames: list[Evoked] = []
        self.reference = Reference(text, library, types, words, remarks, self.frames)
        self.roles = Roles(types, vocabulary, self.reference, self.frames)
        self.cut: set[int] = set()                     # noun phrases of pieces already seen to (cut_for)
        self.clause_frames = 0                         # frames of the clauses before the one being built
        self.unplaced: list[tuple[NP | PP, str, str]] = []   # phrases no element took, the frame, the verb
        self.beside: list[tuple[int, int]] = []        # said beside the command: a degree, a manner, "you"
        self.fell_back = False                         # no frame took every phrase of the clause (:meth:`choose`)

    def command(self, clauses: Iterable[Clause]) -> Parse:
        """The parse of the clauses (in the order they are to be done)."""
        for clause in clauses:
            self.clause(clause)
        return Parse(self.text, tuple(self.frames))

    # -- one clause → frames -----------------------------------------------------------------
    def clause(self, clause: Clause) -> None:
        """The clause's frames: what it implies first (things held), then its own (:meth:`choose`)."""
        self.clause_frames = len(self.frames)
        unit = clause.unit or str(clause.verb.info)
        self.stray_state(unit, clause)
        frames = self.types.evoked_by(unit)
        self.stranded(unit, frames, clause)
        role = self.types.object_role(unit)
        if role is not None:
            self.object_as(role, clause)
        used = [x for x in clause.items if isinstance(x, PP) and x.lead and x.prep == "with"]
        if used and not any("instrument" in self.types.roles(f) for f in frames):
            clause.held += [x.np for x in used]             # "use a card to turn on the lamp": hold it
            clause.items = [x for x in clause.items if not any(x is u for u in used)]
        for np in clause.held:
            self.hold(np)
        self.there_asked(frames, clause)
        if frames and all(self.makes_state(f) for f in frames):
            clause.result = [x for x in clause.items if isinstance(x, PP) and self.is_form(x)]
            clause.items = [x for x in clause.items if not any(x is r for r in clause.result)]
        unit, best = self.choose(unit, self.accompanying(frames, clause) or self.keeping_near(unit, clause) or frames,
                                 clause)
        best = self.moved_object(best, self.types.evoked_by(unit), clause)
        best = self.returning(self.moving(best, self.types.evoked_by(unit), clause), self.types.evoked_by(unit),
                              clause)
        best = self.escorting(self.caused_motion(self.cleared(unit, best, clause), clause), clause)
        best = self.examining_for(best, clause)
        _, frame, roles, attached = self.showing(best, clause)
        if self.fell_back:
            self.fell_back = False
            self.place_left(frame, clause, roles, attached)
        self.first_into(frame, roles, attached)
        self.beside_on(frame, clause, roles, attached)
        self.emit(frame, unit, clause, roles, attached)

    def stray_state(self, unit: str, clause: Clause) -> None:
        """"pop the telly *on*", "bring the cup *off*": "on" or "off" alone after the thing, a particle no unit of the
        verb takes, names a state the frame would drop ("switch it on" and "put it down" differ by it): refused at
        the particle, never dropped silently, when it comes right after the thing and ends the clause or is followed
        only by places ("pop the telly on *in the lounge*"; "with the lamp *on*", "the table it was *on*", "on on the
        table" are not). A unit that ends in it ("take the lid *off*") keeps it."""
        words = unit.split()
        self.particle_alone(words, clause)
        rest = clause.items[1:]               # "pop the telly on *in the lounge*": where, after the state
        placed = all(isinstance(x, PP) and not x.lead and x.prep != clause.items[0].lower for x in rest) \
            if clause.items and isinstance(clause.items[0], Word) else False
        stray = clause.items[0] if clause.items and placed else None
        if not isinstance(stray, Word) or stray.tag != "PARTICLE" or stray.lower not in _STRAY_STATES or \
                stray.lower in words[1:]:
            return
        verb = self.text[clause.verb.start:clause.verb.end].lower()
        if not clause.objects or self.text[clause.objects[-1].end:stray.start].strip():
            return                               # only right after the thing: "with the lamp *on*" describes
        head = clause.objects[0].head
        part = head is not None and noun_lemma(head.text.lower()) in PARTS     # "put the lid on": on what?
        said = f"{stray.lower!r} after {self.text[clause.objects[0].start:clause.objects[0].end]!r}"
        moves = "goes on" if stray.lower == "on" else "comes off"
        example = "put it on the pan" if stray.lower == "on" else "take it off the pan"
        raise CommandError(f"{said}: a {head.text.lower() if head else 'part'} is a part of a thing, no thing to "
                           f"switch {stray.lower}, and what it {moves} is not said; say it ('{example}')" if part else
                           f"{said}: '{verb} ... {stray.lower}' is no verb of the library, and the state it names "
                           f"would be lost; say what to do with it ('turn it {stray.lower}', 'put it down')",
                           stray.start + 1, self.text, ["a verb the robot knows"])

    def particle_alone(self, unit: Sequence[str], clause: Clause) -> None:
        """"hold on", "hold on for a moment", "hold on in the hall": "on"/"off" right after a verb said with no object,
        no particle of the unit, followed by nothing, a time ("on *a moment*" is no place) or where (not where to: "go
        on *to* the hall" goes), makes the verb another verb no frame has: refused at the verb (words34: a Pick of
        nothing, "on" dropped; "go on a moment" went to a moment). "turn on", "switch it off", "put the cup on the
        table", "come on in" are not."""
        if clause.objects or not clause.items or not clause.verb.text or \
                self.text[:clause.verb.start].lower().split()[-1:] == ["to"]:
            return                           # "a plate for an egg *to rest on*": the thing it rests on, said before
        first = clause.items[0]
        if isinstance(first, Word):
            particle = first.lower if first.tag == "PARTICLE" else None
        else:
            particle = first.prep if isinstance(first, PP) and not first.lead and \
                first.np.head_text in TIME_UNITS else None
        timed = all(isinstance(x, PP) and not x.lead and (x.np.head_text in TIME_UNITS or x.prep not in TO) or
                    isinstance(x, Word) and x.info == "time"   # "hold on *in the hall*"; "go on *to* the hall" goes,
                    for x in clause.items[1:])                 # "come on *in*": another particle
        if particle not in _STRAY_STATES or particle in unit[1:] or not timed or \
                self.text[clause.verb.end:first.start].strip():
            return
        verb = self.text[clause.verb.start:clause.verb.end].lower()
        raise CommandError(f"'{verb} {particle}' is no verb of the library: no frame of '{verb}' takes "
                           f"'{particle}' alone; say what to do ('wait here', 'turn it {particle}')",
                           clause.verb.start + 1, self.text, ["a verb the robot knows"])

    def stranded(self, unit: str, frames: Sequence[Frame], clause: Clause) -> None:
        """"go *to*", "bring the cup *to*", "take the book *from*", "put the cup *in*": a preposition ending the
        clause with nothing after it, no particle of the unit, leaves the place it leads to unsaid (issue #13: read
        as a particle, the goal was dropped silently): refused at the preposition. A preposition of a path to or
        from ("to", "into", "from", ...: :data:`~seal_cli.language.roles.TO`, :data:`FROM`) that is never a
        particle is always refused; "in", a particle too, only when the thing is said and where it goes is all the
        frames say of it beyond (a putting: "bring it *in*", "come *in*" go in) in the command's first frame; after
        a clause that opened a place it is "in there" ("open the microwave, put the cup *in* and close it": in the
        microwave; it was a Place with no goal), and after one that took the same thing to a place
        (:meth:`carried_before`). "turn it *on*", "pick it *up*" are their units'; "a plate for
        an egg *to rest on*", "which room should I go *to*" are said before."""
        last = clause.items[-1] if clause.items else None
        if not isinstance(last, Word) or last.tag != "PARTICLE" or last.lower in unit.split()[1:] or \
                last.end < clause.end or self.text[:clause.verb.start].lower().split()[-1:] == ["to"] or \
                any(w in WH_WORDS for w in self.text[:clause.verb.start].lower().split()):
            return
        path = last.lower in TO + FROM and last.lower not in PARTICLES
        putting = last.lower == "in" and bool(clause.objects) and bool(frames) and \
            all(self.types.roles(f) - {"theme", "source"} == {"goal"} for f in frames)   # where it was: no end
        if putting and (self.opened_before() or self.carried_before(clause)):
            clause.items[-1] = PP("in", NP(last.start, last.end, last, "place", there=True), last.start)
            return                           # "open the microwave, put the cup *in*": in there, the microwave
        if not path and not (putting and not self.frames):
            return
        said = self.text[clause.verb.start:last.end]
        to_whom = last.lower == "to" and bool(clause.objects) and any("recipient" in self.types.roles(f)
                                                                       for f in frames)
        where = "the table" if last.lower in FROM else "the box" if putting or last.lower != "to" else \
            "me" if to_whom else "the kitchen"
        ends = "ends the command" if not self.text[last.end:].strip(" .!?") else "has nothing after it"
        raise CommandError(f"{last.lower!r} {ends}: say {'to whom or where' if to_whom else 'where'} "
                           f"('{said} {where}')", last.start + 1, self.text, ["a place"])

    def opened_before(self) -> bool:
        """Whether the place said last before this clause (:meth:`~seal_cli.language.reference.Reference.place_before`)
        is one a clause opened ("open the microwave, put the cup in": the microwave; not "move the pan to the
        counter, put the tomato in", where "in" is the pan's)."""
        place = self.reference.place_before(self.clause_frames)
        return place is not None and any(
            action.name == "open" and place[1] in action.args
            for action in self.library.frame(self.frames[place[0]].frame).actions)

    def carried_before(self, clause: Clause) -> bool:
        """Whether the place said last before this clause is where the clause right before took the thing this
        clause puts in: "take the tomato to the microwave(,) put *it* in" is in the microwave (words47: no goal). Not
        "move the pan to the counter, put the tomato in" (another thing: in the pan), nor a place said earlier."""
        place = self.reference.place_before(self.clause_frames)
        if place is None or not self.clause_frames or not clause.objects:
            return False
        index = self.clause_frames - 1
        goal, theme = self.frames[index].elements.get("goal"), self.frames[index].elements.get("theme")
        if goal is None or theme is None or (goal.refers_to or (index, "goal")) != place or theme.kind != "thing":
            return False
        said = clause.objects[0]
        if said.pronoun is not None:
            return said.pronoun in ("it", "them")
        return said.head is not None and noun_lemma(said.head.lower) == theme.head

    def there_asked(self, frames: Sequence[Frame], clause: Clause) -> None:
        """"go to the bedroom and tell me how many books *are there*", "... find out how many people there are": an
        existential "there" with "is"/"are" ending a question whose frame has a ground, no place said in the clause,
        after a clause that named a place, asks of that place, as a bare "there" does ("count the books there"): the
        "there" becomes the ground (text "there", ``refers_to`` the place; words43: the whole house was counted).
        With no place before ("how many chairs are there?") it stays existential, no place; with nothing counted ("...
        and let me know how many there are") it reports the count before (:mod:`~seal_cli.language.reported`)."""
        items = list(clause.items)
        if not clause.objects:
            return                           # "count the dishes and let me know how many there are": a report
        while items and isinstance(items[-1], Word) and items[-1].info == "time":
            items.pop()                      # "... are there right now"
        last = items[-2:]
        if len(last) != 2 or not all(isinstance(w, Word) for w in last) or \
                sorted(str(w.tag) for w in last if isinstance(w, Word)) != ["BE", "THERE"] or \
                any(isinstance(x, PP) and x.prep in LOCATIVE for x in clause.items) or \
                not any("ground" in self.types.roles(f) for f in frames) or \
                self.reference.place_before(self.clause_frames) is None:
            return
        there = next(w for w in last if isinstance(w, Word) and w.tag == "THERE")
        at = next(k for k, x in enumerate(clause.items) if x is there)
        clause.items[at] = PP("at", NP(there.start, there.end, there, "place", there=True), there.start)

    @staticmethod
    def object_as(role: str, clause: Clause) -> None:
        """A unit whose direct object fills another element than the frame's first ("fill *the glass* with
        water": the goal, FrameNet's Filling): the object is said as that element's phrase ("into the
        glass"), and what comes with "with" — a phrase of the verb, or the object's content ("the glass
        with water") — as the object ("pour water into the glass")."""
        prep = ROLE_PREPOSITIONS.get(role)
        with_pp = next((x for x in clause.items if isinstance(x, PP) and x.prep == "with" and not x.lead), None)
        if prep is None or not clause.objects:
            if prep is not None and with_pp is not None:          # "fill with water": the goal left unsaid
                clause.items = [x for x in clause.items if x is not with_pp]
                clause.objects = [with_pp.np]
            return
        said = clause.objects[0]
        if with_pp is not None:
            clause.items = [x for x in clause.items if x is not with_pp]
            theme: NP | None = with_pp.np
        elif len(said.contents) == 1:
            theme, said.contents = said.contents[0], []
        else:
            theme = None
        clause.objects = [theme, *clause.objects[1:]] if theme is not None else clause.objects[1:]
        clause.items = [PP(prep, said, said.start), *clause.items]

    def choose(self, unit: str, frames: Sequence[Frame], clause: Clause) -> tuple[str, Fit]:
        """The frame of the verb that takes the clause best (:meth:`best_fit`), with the lexical unit
        said; when none takes every phrase, the one that takes the most."""
        best = self.best_fit(frames, clause)
        head = unit.split()[0]
        if best is None and head != unit and self.types.evoked_by(head):
            # "take the trash out to the garage": no frame of "take out" has a goal, one of "take" has
            best = self.best_fit(self.types.evoked_by(head), clause)
            if best is not None:
                unit, frames = head, self.types.evoked_by(head)
        if (best is None or "recipient" not in self.types.roles(best[1])) and self.recipient_said(clause):
            brings = self.bringing(frames)   # "grab me a beer", "grab a beer from the fridge for me": Bring
            found = self.best_fit(brings, clause) if brings else None
            if found is not None:
                best = found
        if best is None and frames and all("recipient" in self.types.roles(f) and "goal" not in self.types.roles(f)
                                           for f in frames) and \
                any(isinstance(x, PP) and x.prep in PUT_IN and not x.lead for x in clause.items):
            found = self.best_fit(self.putting(), clause)   # "serve it *on the table*": handed to no one, put there
            if found is not None:
                best = found
        if best is None and not clause.objects and not clause.message:
            best = self.object_said_late(frames, clause)
        if best is None:                     # no frame takes every phrase: the best that takes the most
            for order, frame in enumerate(frames):
                assigned = self.roles.assign(frame, clause, strict=False)
                assert assigned is not None
                roles, attached, score = assigned
                key = (score - 5 * len(clause.items), -self.unfilled(frame, roles), -order)
                if best is None or key > best[0]:
                    best = (key, frame, roles, attached)
            self.fell_back = True
        assert best is not None
        return unit, best

    def place_left(self, frame: Frame, clause: Clause, roles: dict[str, Any], attached: list[tuple[NP, PP]]) -> None:
        """The phrases no element of the frame took when none takes every phrase (:meth:`choose`,
        :mod:`~seal_cli.language.unplaced`): each lands where English puts it, is kept as said beside the command,
        or is recorded in :attr:`unplaced` (the parser refuses the command at it).

        * "*of* the people in the hall, how many ...": a partitive said before the question is what is counted
          (the frame's first element, when empty);
        * "how many cups are *empty*", "how many eggs are *left*": a bare word after "are" says which of them are
          counted (a modifier of the first element; a remark when that is unsaid: "how many are left");
        * "on the same shelf as *the clock*": what "the same" is compared with describes that phrase (its text);
        * "go round *the corner*": a phrase with a determiner right after an element of one bare word takes its
          place, the bare word said beside (a word of path or manner the grammar read as a noun);
        * "slice the bread, *two slices*": a number of portions after a frame that leaves its thing in a form is
          the form ("into two slices");
        * "open the window *a little*" (:data:`~seal_cli.language.english.DEGREE_PHRASES`), "cut it, not too
          *thick*" (a bare gradable adjective: how), "..., would *you*, and ..." (the one spoken to): said beside
          the command, a remark."""
        first = frame.elements[0].role if frame.elements else None
        fronted = next((x for x in clause.items if isinstance(x, PP) and x.prep == "of" and
                        x.start < clause.verb.start and x.np.kind in ("thing", "person")), None)
        if fronted is not None and first and first not in roles:
            roles[first] = fronted.np        # (also when read as describing a word after it: "how many are *empty*")
            attached[:] = [(host, pp) for host, pp in attached if pp is not fronted]
        for item in unplaced(clause, frame, roles, attached):
            np = item.np if isinstance(item, PP) else item
            at = clause.items.index(item) if any(item is x for x in clause.items) else -1
            before = clause.items[at - 1] if at > 0 else None
            said = self.text[item.start:np.end].lower()
            same = next((v for v in roles.values() if isinstance(v, NP) and v.end <= item.start and
                         any(m.lower == "same" for m in v.mods)), None)
            if isinstance(item, NP) and isinstance(before, Word) and before.lower == "as" and same is not None:
                same.end = max(same.end, np.end)     # "on the same cushion *as the laptop*": which cushion
            elif isinstance(item, NP) and isinstance(before, Word) and before.tag == "BE" and np.head is not None \
                    and not np.determined and not np.mods:
                counted = roles.get(first) if first is not None else None
                if isinstance(counted, NP):
                    counted.mods.append(np.head)
                else:                        # "tell me how many are left": of what the question counts, unsaid
                    self.beside.append((item.start, np.end))
            elif isinstance(item, NP) and np.determined and self._bare_before(roles, np) is not None:
                role, bare = self._bare_before(roles, np) or ("", np)
                roles[role] = np                 # "go *round* the corner": a bare word, then the phrase it leads to
                self.beside.append((bare.start, bare.end))
            elif isinstance(item, NP) and self.makes_state(frame) and np.quantity is not None and \
                    np.head is not None and noun_lemma(np.head.text) in PORTIONS and not clause.result:
                clause.result = [PP("into", np, np.start)]
            elif said in DEGREE_PHRASES or np.pronoun == "you" or (
                    isinstance(item, NP) and not np.determined and not np.mods and np.head is not None and
                    is_gradable(np.head.text)):
                self.beside.append((item.start, np.end))
            else:
                self.unplaced.append((item, frame.name, self.text[clause.verb.start:clause.verb.end] or
                                      str(clause.verb.info)))      # a verb said once for two clauses: its unit

    def _bare_before(self, roles: Mapping[str, Any], np: NP) -> tuple[str, NP] | None:
        """The element filled by one bare word (no determiner, no modifier) said right before ``np`` ("go *round*
        the corner"), with its role; None."""
        for role, value in roles.items():
            if isinstance(value, NP) and value.head is not None and not value.determined and not value.mods and \
                    value.pronoun is None and value.start == value.head.start and value.end <= np.start and \
                    not self.text[value.end:np.start].strip():
                return role, value
        return None

    def accompanying(self, frames: Sequence[Frame], clause: Clause) -> list[Frame] | None:
        """"go *with Sam*", "walk with the visitor to the door": a verb of going somewhere, no object,
        and "with" a person is moving together with them — the library's frames that move with a person
        (the first element a person, and a goal). With a goal said, the one that brings the person
        there (its result relates them to the goal: Guide's ``at(theme, goal)``); without, or with the
        speaker ("come with *me* to the garden": who speaks knows the way), one that does not (Follow:
        where they go). The person becomes the object; None when this is not it."""
        if clause.objects or clause.message or not any(f.elements and f.elements[0].role == "goal" for f in frames) \
                or any("instrument" in self.types.roles(f) for f in frames):
            return None
        company = next((x for x in clause.items if isinstance(x, PP) and x.prep == "with" and not x.lead and
                        (self.roles.kind(x.np, None, None) == "person" or
                         x.np.pronoun == "them" and self.roles.kind(x.np, None, None) == "pronoun")), None)
        #   "go with *them*": no thing said before that they could be, so the people (words30: "with them" was
        #   dropped, a bare Go)
        if company is None:
            return self.going_with_thing(clause)
        together = [f for f in self.library.frames if f.elements and self.types.is_person(f.elements[0].type)
                    and "goal" in self.types.roles(f)]
        leading = [f for f in together if _relates_to_goal(self.types.relation(f))]
        goal_said = any(isinstance(x, PP) and x.prep in TO for x in clause.items)
        if company.np.pronoun in SPEAKER_PRONOUNS:
            goal_said = False                # "come with me to the garden": the speaker leads, the robot follows
        chosen = leading if goal_said else [f for f in together if f not in leading]
        if not chosen:
            return None
        clause.items = [x for x in clause.items if x is not company]
        clause.objects = [company.np]
        return chosen

    def going_with_thing(self, clause: Clause) -> list[Frame] | None:
        """"go *with the trolley* to the garage", "pick up the boxes and go with *them* to the car": going somewhere
        with a thing (no person; a pronoun that takes up things) is taking it there — the frames that take a thing
        in hand to where it goes (:meth:`handing`, those with a goal: Bring); the thing becomes the object. Only
        with a goal said ("go with the flow" is none); None when this is not it (words31: the thing was dropped
        silently, a bare Go)."""
        with_thing = next((x for x in clause.items if isinstance(x, PP) and x.prep == "with" and not x.lead and
                           self.roles.kind(x.np, None, None) == "thing"), None)
        if with_thing is None or not any(isinstance(x, PP) and x.prep in TO for x in clause.items):
            return None
        carrying = [f for f in self.handing() if "goal" in self.types.roles(f)]
        if not carrying:
            return None
        clause.items = [x for x in clause.items if x is not with_thing]
        clause.objects = [with_thing.np]
        return carrying

    def keeping_near(self, unit: str, clause: Clause) -> list[Frame] | None:
        """"stay *close to* Morgan", "stay near me": a verb whose unit with "with" moves with a person ("stay with":
        Follow, FrameNet's Cotheme) says the same with "near" ("near", "close to", "next to") a person and no
        object: keeping near someone who moves is moving with them. The person becomes the object; None when this
        is not it ("stay near the door": a place, the verb's own frame; "go near Sam": "go with" is no unit)."""
        if clause.objects or clause.message:
            return None
        along = [f for f in self.types.evoked_by(f"{unit} with") if f.elements and
                 self.types.is_person(f.elements[0].type)]
        near = next((x for x in clause.items if isinstance(x, PP) and x.prep == "near" and not x.lead and
                     self.roles.kind(x.np, None, None) == "person"), None) if along else None
        if near is None:
            return None
        clause.items = [x for x in clause.items if x is not near]
        clause.objects = [near.np]
        return along

    def moved_object(self, best: Fit, frames: Sequence[Frame], clause: Clause) -> Fit:
        """"*move the bowl*", "return the mug", "push the cart": a verb both of going (a frame whose first
        element is the goal: Go) and of moving a thing (one whose first element is the theme: Place, Bring)
        said with one bare object, a thing that can be moved (no person, nothing ``fixed``), moves that
        thing: the best of the theme frames when one takes the clause; else the frame as chosen ("move
        to the kitchen" has no object, "reach the table" is of going only)."""
        _, frame, roles, _ = best
        if not frame.elements or frame.elements[0].role != "goal" or len(clause.objects) != 1 or clause.message:
            return best
        np = clause.objects[0]
        if roles.get("goal") is not np or self.roles.kind(np, None, None) != "thing" or \
                self.types.is_a(self.roles.class_or_head(np), "fixed") is True:
            return best
        handling = [f for f in frames if f.elements and f.elements[0].role == "theme"]
        return (self.best_fit(handling, clause) or best) if handling else best

    def moving(self, best: Fit, frames: Sequence[Frame], clause: Clause) -> Fit:
        """"*get to* the kitchen", "get into the bedroom": a verb of taking (one of its ``frames`` gets its
        theme in hand: Pick) said with no object, only where to, and nothing earlier to take along, is
        going there — the library's frames whose first element is the goal (Go), when one takes the
        clause; else the frame as chosen ("put in the cabinet" stays Place: "put" takes nothing)."""
        _, frame, roles, _ = best
        first = frame.elements[0].role if frame.elements else None
        if first is None or first in roles or clause.objects or clause.message or not roles or \
                any(role not in PLACES for role in roles) or not any(f.gets_held() for f in frames) or \
                any(isinstance(np, NP) and np.head_text in TIME_UNITS for np in roles.values()):
            return best                      # "hold on a moment": a time, no place to go (words34)
        if self.frames and frame.needs_held() and self.reference.implicit(frame, first) is not None:
            return best                      # "pick up the cup and get [it] to the kitchen"
        going = [f for f in self.library.frames if f.elements and f.elements[0].role == "goal"]
        return self.best_fit(going, clause) or best

    def returning(self, best: Fit, frames: Sequence[Frame], clause: Clause) -> Fit:
        """"then *return to me*": a verb both of going (one of its ``frames`` has the goal first: Go) and of handing a
        thing over (Bring: "return the cup to me"), said with no object, only the person it goes to, is going to
        them: the frames of the verb whose first element is the goal, when one takes the clause
        (words34: "return to me" was a Bring of nothing to me). Not while the frame before leaves a thing in hand
        for the verb to carry on with unsaid ("heat the mug, move [it] to the cabinet")."""
        _, frame, roles, _ = best
        first = frame.elements[0].role if frame.elements else None
        if first is None or first == "goal" or first in roles or clause.objects or clause.message or \
                set(roles) != {"recipient"}:
            return best                      # "move to the sink" after "put the knife on the plate": the plate
        if self.frames and frame.needs_held() and not self.let_go():
            return best                      # "heat the mug, move [it] to the cabinet": still in hand
        going = [f for f in frames if f.elements and f.elements[0].role == "goal"]
        return (self.best_fit(going, clause) or best) if going else best

    def let_go(self) -> bool:
        """Whether the frame said last leaves nothing in the robot's hand (its result: ``not holding(theme)``, as
        Place's and Bring's), so that nothing is there for a verb to carry on with unsaid."""
        last = self.library.frame(self.frames[-1].frame)
        return any(p.predicate == "holding" and p.negated for p in last.postconditions)

    def cleared(self, unit: str, best: Fit, clause: Clause) -> Fit:
        """"*clear off* the counter", "take off the table", "clear out the cupboard": a unit of taking in hand that ends
        in a particle of leaving a place ("off", "out"), said of one thing that never moves (the ``fixed`` category: a
        counter, a cupboard), takes things *from* it: the object is the frame's source, what is taken left unsaid
        (words34: the counter itself was picked up). "take off the lid" and "clear away the cups" are as chosen."""
        _, frame, roles, _ = best
        particle = unit.split()[-1] if " " in unit else None
        if particle not in _LEAVING or not frame.gets_held() or "source" not in self.types.roles(frame) or \
                len(clause.objects) != 1 or roles.get("theme") is not clause.objects[0] or clause.items:
            return best
        np = clause.objects[0]
        if np.kind != "thing" or np.pronoun is not None or \
                self.types.is_a(noun_lemma(self.roles.class_or_head(np)), "fixed") is not True:
            return best
        said = replace(clause, objects=[], items=[PP(_LEAVING[particle], np, np.start)])
        found = self.best_fit([frame], said)
        if found is None:
            return best
        clause.objects, clause.items = said.objects, said.items
        return found

    def caused_motion(self, best: Fit, clause: Clause) -> Fit:
        """"bung the jeans *in the washing machine*", "bung the towels *into* the basket": a frame that says nothing but
        the thing it changes, of a closed type (Close: no goal, no instrument), said of one thing and a phrase of
        putting right after it that the frame took as describing the thing, is English's
        caused motion (the verb says how the thing is moved, the phrase where to: putting it there, the library's
        frames of :meth:`putting`) when the phrase says a path ("into", "onto": no thing is described by where it
        goes), or the thing is not known to be a member of the frame's first element's type (a closed one) nor a
        container (a jar is opened) while the phrase names a thing things are put *in* (the ``hollow`` category: "bung
        the jeans in the washing machine"). "close the door in the kitchen", "open the jar in the fridge", "wash the
        cup in the sink" are as chosen
        (words34: "bung the jeans in the washing machine" was Close of "the jeans in the washing machine", put
        nowhere)."""
        _, frame, roles, attached = best
        first = frame.elements[0] if frame.elements else None
        if first is None or first.role != "theme" or len(frame.elements) != 1 or self.types.is_open(first.type) or \
                len(clause.objects) != 1 or roles.get("theme") is not clause.objects[0]:
            return best                      # only a frame that says nothing but the thing it changes (Close)
        np = clause.objects[0]
        pp = next((pp for host, pp in attached if host is np and pp.prep in PUT_IN and not pp.lead), None)
        if pp is None or np.kind != "thing" or np.pronoun is not None or self.is_form(pp):
            return best
        if pp.prep not in ("into", "onto") and not (
                pp.np.kind == "thing" and not any(self.types.is_a(name, kind) is True for name in self.names_of(np)
                                                  for kind in (first.type, "container"))
                and any(self.types.is_a(name, "hollow") is True for name in self.names_of(pp.np))):
            return best                      # "close the door in the kitchen", "open the jar in the fridge"
        return self.best_fit(self.putting(), clause) or best

    def names_of(self, np: NP) -> tuple[str, ...]:
        """The classes a phrase may name: the vocabulary's class, its head's singular, and that with the word before
        it ("washing machine")."""
        head = noun_lemma(np.head_text)
        said = (f"{np.mods[-1].lower} {head}", head) if np.mods else (head,)
        return (self.roles.class_or_head(np), *said)

    def escorting(self, best: Fit, clause: Clause) -> Fit:
        """"*get Jane to* the kitchen", "deliver the guest to the lobby": a frame that moves a thing to a goal,
        said of a person (one object, a person, where the frame wants no person) with the goal said, is
        bringing the person there — the library's frames whose first element is a person and whose result
        relates them to the goal (Guide's ``at(theme, goal)``), as "take" and "bring" are listed there. So is one
        said of a person and where they are fetched from, no thing ("*fetch Robin from* the garden", "go get Jane
        from the office": words33; was Bring with Robin its recipient and nothing brought)."""
        _, frame, roles, _ = best
        first = frame.elements[0] if frame.elements else None
        fetched = "source" in roles and any(isinstance(x, PP) and x.prep in FROM for x in clause.items)
        if first is None or self.types.is_person(first.type) or "goal" not in roles and not fetched or \
                len(clause.objects) != 1 or self.roles.kind(clause.objects[0], None, None) != "person":
            return best
        leading = [f for f in self.library.frames if f.elements and self.types.is_person(f.elements[0].type)
                   and "goal" in self.types.roles(f) and _relates_to_goal(self.types.relation(f))]
        return self.best_fit(leading, clause) or best

    def examining_for(self, best: Fit, clause: Clause) -> Fit:
        """"*check* the bedroom *for* my keys", "inspect the fridge for milk": a frame of examining a thing (its
        first element no person, no unit of it said with "for"), said of one place and then "for" a thing, is
        searching the place for the thing, as "search the kitchen for the spoon" is: the library's frames of
        searching (a unit said both bare and with "for": "search", "search for"; and a verb of this frame said
        with "for" as this frame says it with another preposition: "look for" beside "look at") take the thing,
        the object where it is sought. "check the oven for me" (for whom), "get a cup for cleaning" (no frame of
        looking) stay as they were. People said as anyone of a kind are sought too (:meth:`anyone_sought`: "check
        the bedroom *for people*", "scan the hall *for anyone wearing a hat*", words48); "for me", "for Sam", "for
        the boss" say for whom."""
        _, frame, roles, _ = best
        wanted = [x for x in clause.items if isinstance(x, PP) and x.prep == "for" and not x.lead]
        if len(clause.objects) != 1 or len(wanted) != 1 or clause.items[0] is not wanted[0] or \
                not self.anyone_sought(wanted[0].np) and (
                    self.roles.kind(wanted[0].np, None, None) == "person" or wanted[0].np.kind != "thing") or \
                any(u.text.endswith(" for") for u in frame.lexical_units) or \
                frame.elements and self.types.is_person(frame.elements[0].type):
            return best
        verbs = {u.text.split()[0] for u in frame.lexical_units if len(u.text.split()) == 2}   # "look at"
        searching = [f for f in self.library.frames if f is not frame and any(
            u.text.endswith(" for") and any(v.text == u.text[:-4] for v in f.lexical_units) for u in f.lexical_units)
            and any(u.text.endswith(" for") and u.text[:-4] in verbs for u in f.lexical_units)]     # "look for"
        place = clause.objects[0]
        said = replace(clause, objects=[wanted[0].np], items=[PP("in", place, place.start), *clause.items[1:]])
        found = self.best_fit(searching, said)
        if found is None:
            return best
        clause.objects, clause.items = said.objects, said.items
        return found

    def anyone_sought(self, np: NP) -> bool:
        """Whether a phrase names people as anyone of a kind, not someone known: "someone", "anybody", or a noun of
        people said bare or with "a"/"any"/"some" ("people", "a man in a red shirt", "any guests"); never a name, a
        personal pronoun or a definite phrase ("me", "Sam", "the boss": for whom)."""
        if np.pronoun is not None or np.head is None:
            return (np.pronoun or "") in SOME_PERSON
        first = self.text[np.start:np.end].split(None, 1)[0].lower()
        return np.head.tag != "NAME" and self.roles.kind(np, None, None) == "person" and (
            not np.determined or first in ("a", "an", "any", "some"))

    def showing(self, best: Fit, clause: Clause) -> Fit:
        """"*show me* the remote", "show the photo to Jo": a frame that moves a person (Guide: "show" is
        one of its units), said of a thing and someone to see it (an indirect object, or "to" a person), is
        bringing the thing to them — a thing cannot be led, and what the robot holds before someone they
        see (the library's frames that take a thing in hand to a recipient, :meth:`handing`). Said of a
        room ("show me the kitchen"), it is leading them there: the room becomes the goal; "the way"
        (:data:`~seal_cli.language.english.ROUTE_NOUNS`) is no thing either ("show them the way": Guide)."""
        _, frame, _, _ = best
        first = frame.elements[0] if frame.elements else None
        if first is None or not self.types.is_person(first.type) or not clause.objects or \
                self.roles.kind(clause.objects[-1], None, None) in ("person", "pronoun") or \
                not self.recipient_said(clause):
            return best                      # "greet *them* for me": no thing said they could be, so people (words46)
        thing = clause.objects[-1]
        if thing.head_text in ROUTE_NOUNS:
            return best                      # "show them the way (to the kitchen)": leading them, as chosen
        if len(clause.objects) == 2 and is_room_word([m.lower for m in thing.mods] + [thing.head_text]):
            clause.objects = clause.objects[:1]
            clause.items = [*clause.items, PP("to", thing, thing.start)]
            return self.best_fit([frame], clause) or best
        return self.best_fit(self.handing(), clause) or best

    def makes_state(self, frame: Frame) -> bool:
        """Whether the frame's result is a state of its first element and it puts it nowhere (Slice:
        ``sliced(theme)``, no goal)."""
        return self.types.makes_state(frame)

    @staticmethod
    def is_form(pp: PP) -> bool:
        """Whether a phrase says the form the action leaves its theme in: "*into slices*", "into eight
        pieces", "into cubes", "*in half*" (a portion, a number of things, or things said bare)."""
        np = pp.np
        if np.head is None or np.kind != "thing" or np.pronoun is not None or pp.prep not in ("into", "in"):
            return False
        head = noun_lemma(np.head.text)
        if head in PORTIONS or head == "half":
            return True
        first = np.mods[0] if np.mods else np.head
        bare_plural = np.plural and first.start == np.start and not np.of
        return pp.prep == "into" and (np.quantity is not None or bare_plural)

    def recipient_said(self, clause: Clause) -> bool:
        """Whether the clause names someone to receive: an indirect object, or "for"/"to" a person."""
        return len(clause.objects) >= 2 and self.roles.kind(clause.objects[0], None, None) == "person" or any(
            isinstance(x, PP) and x.prep in ("for", "to") and self.roles.kind(x.np, None, None) == "person"
            for x in clause.items)

    def bringing(self, frames: Sequence[Frame]) -> list[Frame]:
        """For a verb of taking (a frame of it gets its theme in hand: Pick), the frames that take a
        thing in hand to someone (a recipient, and ``holding(theme)`` before): taking a thing for a
        person is bringing it to them, so those that also say where it is taken from (a source) when
        any does. Empty for any other verb."""
        if not any(f.gets_held() for f in frames):
            return []
        return self.handing(frames)      # "grab me two eggs": taken from where they are, so Bring, not Give

    def object_said_late(self, frames: Sequence[Frame], clause: Clause) -> Fit | None:
        """"bring to the kitchen *the cups*", "put on the shelf *all the books you can find*": the object said after
        a phrase of place (a long object is said last in English) is the verb's object when a frame takes the
        clause so (one noun phrase after the phrases, none before); None otherwise (words31: it was dropped)."""
        late = [x for x in clause.items if isinstance(x, NP)]
        if len(late) != 1 or not clause.items or not isinstance(clause.items[0], PP) or \
                not all(isinstance(x, PP) for x in clause.items if x is not late[0]):
            return None
        np = late[0]
        items = clause.items
        clause.objects, clause.items = [np], [x for x in items if x is not np]
        found = self.best_fit(frames, clause)
        if found is None:
            clause.objects, clause.items = [], items
        return found

    def putting(self) -> list[Frame]:
        """The library's frames that put a held thing somewhere and hand it to no one (a theme first, a goal, no
        recipient, ``holding(theme)`` before and not after — the thing is let go of, as one served is: Place, not
        Pour): a verb of handing over said with only a place ("serve the
        soup *on the table*", words31) puts it there."""
        return [f for f in self.library.frames if f.elements and f.elements[0].role == "theme" and f.needs_held()
                and "goal" in self.types.roles(f) and "recipient" not in self.types.roles(f) and
                any(p.predicate == "holding" and p.args == ("theme",) and p.negated for p in f.postconditions)]

    def handing(self, besides: Sequence[Frame] = ()) -> list[Frame]:
        """The library's frames (other than ``besides``) that take a thing in hand to someone (a recipient,
        and ``holding(theme)`` before): those that also say where it is taken from (a source) when any does."""
        handing = [f for f in self.library.frames if f not in besides and "recipient" in self.types.roles(f)
                   and f.needs_held()]
        return [f for f in handing if "source" in self.types.roles(f)] or handing

    def best_fit(self, frames: Sequence[Frame], clause: Clause) -> Fit | None:
        """The frame that takes every phrase of the clause best (fewest elements left empty, then
        library order), or None when none takes them all."""
        best: Fit | None = None
        for order, frame in enumerate(frames):
            assigned = self.roles.assign(frame, clause, strict=True)
            if assigned is None:
                continue
            roles, attached, score = assigned
            key = (score, -self.unfilled(frame, roles), -order)
            if best is None or key > best[0]:
                best = (key, frame, roles, attached)
        return best

    def first_into(self, frame: Frame, roles: dict[str, Any], attached: list[tuple[NP, PP]]) -> None:
        """"Put a spoon *in a bowl* into the sink": the spoon goes into the bowl, and the bowl (a
        container) into the sink (:meth:`carry_on`)."""
        relation = self.types.relation(frame)
        if relation is None or not isinstance(roles.get(relation.args[1]), NP):
            return
        theme, goal = roles.get(relation.args[0]), roles[relation.args[1]]
        for k, (host, pp) in enumerate(attached):
            if host is theme and pp.prep in PUT_IN and pp.np.kind == "thing" and not pp.np.pronoun and \
                    not pp.describes and \
                    self.types.is_a(self.roles.class_or_head(pp.np), "container") is True:
                roles[relation.args[1]] = pp.np
                attached[k] = (pp.np, PP("into", goal, goal.start))
                return

    def beside_on(self, frame: Frame, clause: Clause, roles: dict[str, Any], attached: list[tuple[NP, PP]]) -> None:
        """"Put the newspaper *next to the remote on the sofa*": a thing put beside, in front of or behind
        another thing said to be on or in something ends on or in that something (the sofa holds it; the
        remote is where on the sofa). The goal is the place the landmark is said to be at, when the goal
        was said with such a preposition (:data:`~seal_cli.language.english.BESIDE`) and that place is a
        thing, not a room ("next to the sink in the kitchen" stays the sink)."""
        relation = self.types.relation(frame)
        if relation is None or not isinstance(roles.get(relation.args[1]), NP):
            return
        goal = roles[relation.args[1]]
        said = next((x for x in clause.items if isinstance(x, PP) and x.np is goal), None)
        if said is None or said.prep not in BESIDE or goal.kind != "thing" or goal.pronoun or goal.conjuncts:
            return
        for host, pp in attached:
            if host is goal and pp.prep in LOCATED and pp.np.kind == "thing" and not pp.np.pronoun \
                    and pp.np.head is not None and not is_room_word((*(w.lower for w in pp.np.mods), pp.np.head_text)):
                roles[relation.args[1]] = pp.np
                return

    def carried_in(self, frame: Frame, roles: dict[str, Any]) -> None:
        """"Put the spoon *with the mug* on the table", "move a knife with a bowl to the counter": the thing said with
        "with" is read as what the thing holds ("a bowl with a knife": the knife goes in the bowl), but a spoon holds
        nothing; when the frame puts its theme somewhere, the theme is known to hold nothing (no category the taxonomy
        says holds things: not ``hollow``, no ``furniture``, nothing ``fixed``) and the one thing said with it is a
        ``container``, the container holds the theme and is what is put: the spoon in the mug, the mug on the table.
        The theme's and the container's classes, else their heads, are asked."""
        first = frame.elements[0].role if frame.elements else None
        np = roles.get(first) if first is not None else None
        if first is None or not isinstance(np, NP) or len(np.contents) != 1 or np.pronoun or np.conjuncts \
                or np.head is None:
            return
        if not any(not p.negated and len(p.args) == 2 and p.args[0] == first and p.args[1] in roles
                   for p in frame.postconditions):
            return
        box = np.contents[0]
        if box.head is None or box.pronoun or box.conjuncts or box.kind != "thing" or box.contents:
            return
        thing = self.roles.class_or_head(np)
        if self.types.is_a(thing, "hollow") is not False or self.types.is_a(thing, "furniture") is True or \
                self.types.is_a(thing, "fixed") is True or \
                self.types.is_a(self.roles.class_or_head(box), "container") is not True:
            return
        np.contents = []
        box.contents.append(np)
        roles[first] = box

    def unfilled(self, frame: Frame, roles: Mapping[str, Any]) -> int:
        """Elements the clause leaves empty; an object left unsaid that the frame before has in hand
        is not empty ("heat the mug, move [it] to the cabinet": Place, not Go)."""
        first = frame.elements[0].role if frame.elements else None
        held = first is not None and first not in roles and bool(self.frames) and frame.needs_held() and \
            self.reference.implicit(frame, first) is not None
        return sum(1 for e in frame.elements if e.role not in roles) - int(held)

    # -- frames out ----------------------------------------------------------------------------
    @staticmethod
    def located_ground(frame: Frame, roles: dict[str, Any]) -> None:
        """"Look for a person *standing in the corridor*", "bring me the dice *that's on the sofa*": where a
        participle or a relative clause of being says the theme is, is where to seek it or take it from
        (the frame's ``ground`` or ``source``, when nothing else fills it)."""
        theme = roles.get(frame.elements[0].role) if frame.elements else None
        if not isinstance(theme, NP) or theme.located is None:
            return
        role = next((r for r in ("ground", "source") if r in frame.roles), None)
        if role is not None and roles.get(role) is None:
            roles[role] = theme.located

    def place_said_first(self, frame: Frame, roles: Mapping[str, Any], attached: Sequence[tuple[NP, PP]],
                         elements: dict[str, Phrase]) -> None:
        """"*In the shop,* open the fridge": a place said before the clause that no element takes describes the thing
        after it, as "open the fridge in the shop" does; its words reach the planner with the thing's
        (``stands_for``), which grounds "the fridge in the shop" on the map (the kitchen's fridge was opened, the
        place dropped silently). The parse's text of the element stays what the clause said."""
        for host, pp in attached:
            if pp.prep not in LOCATED or pp.np.end > host.start:
                continue
            role = next((r for r, np in roles.items() if np is host and r in elements), None)
            if role is None or elements[role].stands_for or not elements[role].text:
                continue
            said = f"{elements[role].text} {self.text[pp.start:pp.np.end]}"
            elements[role] = replace(elements[role], stands_for=said)

    def place_said(self, frame: Frame, roles: dict[str, Any], elements: dict[str, Phrase]) -> None:
        """"Paris is in the bathroom; meet her", "there's a cup somewhere in the kitchen, find it": a pronoun
        standing for what a statement before the command introduced, and the statement said where it is: that
        is where to seek it or take it from (the frame's ``ground`` or ``source``, when nothing fills it), as
        :meth:`located_ground` does for a place said in the phrase itself."""
        first = frame.elements[0].role if frame.elements else None
        np = roles.get(first) if first is not None else None
        if isinstance(np, NP):
            np = self.reference.pointed_person(np) or np     # "... Find that person": looked up as "him"
        role = next((r for r in ("ground", "source") if r in frame.roles), None)
        if not isinstance(np, NP) or np.pronoun is None or role is None or role in elements or \
                first not in elements or elements[first].refers_to is not None:
            return
        said = self.reference.mentioned(np, frame, first)
        place = self.reference.place_said(said, start=role == "source") if said is not None else None
        if place is not None:
            elements[role] = self.stated_phrase(place)
        if said is None or not (said.name or self.types.is_a(noun_lemma(said.head), "person") is True):
            return
        if role == "source" and "goal" in frame.roles and "goal" not in elements and \
                self.types.is_person(frame.elements[0].type):
            end = self.reference.path_end_said(said)      # "Jules has to get from A to B, please guide him": to B
            if end is not None:
                elements["goal"] = self.stated_phrase(end)

    def counted_as_stated(self, frame: Frame, unit: str, clause: Clause, elements: dict[str, Phrase]) -> None:
        """"On the desk there are a few toys, *tell me how many*": counting said with nothing after "how many"
        counts the things a statement before it named, where it said they are, as "count them" would (words42: it
        counted nothing, nowhere). Only the unit of counting (``NUMBER_MEANS``) with its first element unsaid."""
        if unit != NUMBER_MEANS or not frame.elements or frame.elements[0].role in elements:
            return
        first = frame.elements[0].role
        said = self.reference.mentioned(NP(clause.start, clause.start, None, "pronoun", pronoun="them"), frame, first)
        if said is None:
            return
        person = said.name or self.types.is_a(noun_lemma(said.head), "person") is True
        start, end = self.reference.with_its_place(said)
        elements[first] = Phrase("", said.head if said.name else noun_lemma(said.head),
                                 None if person else self.mentioned_class(said), "person" if person else "thing",
                                 stands_for=self.text[start:end])
        role = next((r for r in ("ground",) if r in frame.roles and r not in elements), None)
        place = self.reference.place_said(said) if role is not None else None
        if role is not None and place is not None:
            elements[role] = self.stated_phrase(place)

    def mentioned_class(self, said: Mention) -> str | None:
        """The class a thing a statement or condition named is, by all its words, as the phrase itself would be
        grounded ("if *the coffee machine* is on, turn it off": ``coffee_machine``, not the head's "machine");
        None without a vocabulary or when its words name no class of it."""
        words = [w for w in self.text[said.start:said.end].split() if w.lower() not in NP_OPENERS]
        return self.vocabulary.grounded(words, []) if self.vocabulary is not None and words else None

    def stated_phrase(self, place: Mention) -> Phrase:
        """A place a statement said, as an element (its head, grounded when a vocabulary is given)."""
        text = self.text[place.start:place.end]
        words = [w for w in text.split() if w.lower() not in NP_OPENERS]
        cls = self.vocabulary.grounded(words, []) if self.vocabulary is not None and words else None
        return Phrase(text, noun_lemma(place.head), cls, span=(place.start, place.end))

    def led_where_already(self, clause: Clause, elements: dict[str, Phrase]) -> None:
        """"Ben is in the bedroom. Guide him there": the statement's place is where Ben is, so it is the frame's
        source (:meth:`place_said`), and a bare "there" points at the same place (``Reference.place_stated``):
        leading a person to where they already are asks nothing, and where to is unsaid. A clear error naming
        both, not a frame from the bedroom to the bedroom (words24). "Jules has to get from the hall to the
        garage, lead him there" (the path's start and its end) and a "there" an earlier clause named stay."""
        source, goal = elements.get("source"), elements.get("goal")
        if source is None or goal is None or source.span is None or goal.span is None or goal.refers_to is not None \
                or (goal.text or "").lower() != "there" or source.head != goal.head or source.span[0] >= clause.start:
            return
        who = next((p for role, p in elements.items() if role not in ("source", "goal")), None)
        person = self.text[who.span[0]:who.span[1]] if who is not None and who.span is not None else "them"
        verb = self.text[clause.verb.start:clause.verb.end]
        raise CommandError(f"'there' is where {who.head if who is not None else 'they'} already is "
                           f"({source.text}, said before): say where to {verb.lower()} {person} "
                           f"('{verb.lower()} {person} to the kitchen')", goal.span[0] + 1, self.text,
                           ["a place to go to"])

    def emit(self, frame: Frame, unit: str, clause: Clause, roles: dict[str, Any],
             attached: list[tuple[NP, PP]]) -> None:
        theme = frame.elements[0].role if frame.elements else ""
        holds_nothing = "instrument" not in frame.roles and self.types.relation(frame) is None
        people = [roles.get(e.role) for e in frame.elements if self.types.is_person(e.type)]
        for host, pp in attached:
            if pp.describes and pp.prep in LOCATED and host.located is None:
                host.located = pp.np             # "the dice *that's on the sofa*": where it is
            elif host.located is None and pp.np.located is not None:
                host.located = pp.np.located     # "the man in the red shirt waiting *at the door*": the participle
                # read with the phrase that describes him says where he is
            if pp.after_relative and host.relative is not None:
                host.relative = self.text[host.relative_start:pp.np.end]
                continue
            again = pp.prep == "with" and _named_again(pp.np, roles.get(theme), host, attached)
            if not host.borrowed and not again:   # an object said in an earlier clause ends where it was said
                particle = _split_particle(unit, clause, host.end, pp.start) if host in clause.objects else None
                if particle is not None and host.end < pp.np.end:
                    host.cut = (particle.start, particle.end)   # "the light *on* in the hall": the unit's, cut out
                host.end = max(host.end, pp.np.end)
            if pp.prep == "with" and pp.np.head is not None and pp.np.kind == "thing" and not pp.np.conjuncts \
                    and noun_lemma(pp.np.head.text) in PARTS:
                continue                         # "a spoon with a blue handle": described by its part, nothing in it
            if pp.prep == "with" and not host.pronoun and any(host is p for p in people):
                continue                         # "follow the guy *with the beard*": a person described (words36)
            if pp.prep == "with" and pp.np.kind != "person" and (host.kind != "person" or host.pronoun):
                if holds_nothing and host is roles.get(theme) and pp.np.kind == "thing" and not pp.np.pronoun and \
                        not self.worn_by(frame, theme, pp.np):
                    self.hold(pp.np)     # "turn on the lamp with the remote": held while it is done
                elif again:
                    roles[theme].contents.append(pp.np)   # "a pan on the table with an apple on the pan"
                else:
                    host.contents.append(pp.np)
        self.carried_in(frame, roles)
        self.asker(frame, roles)
        self.located_ground(frame, roles)
        # frames evoked by result words and contents, in the order of the words
        for role in frame.roles:
            np = roles.get(role)
            if isinstance(np, NP):
                self.prepare(np, frame, role, roles)
        elements: dict[str, Phrase] = {}
        for element in frame.elements:
            np = roles.get(element.role)
            if np is not None:
                elements[element.role] = self.phrase(np, frame, element.role)
                prep = next((x.prep for x in clause.items if isinstance(x, PP) and x.np is np), None)
                if prep is not None:             # "put the teapot *on* the sideboard": on its top, not in it
                    elements[element.role] = replace(elements[element.role], preposition=prep)
        self.place_said(frame, roles, elements)
        self.counted_as_stated(frame, unit, clause, elements)
        self.place_said_first(frame, roles, attached, elements)
        self.led_where_already(clause, elements)
        first = frame.elements[0] if frame.elements else None
        said = self.types.object_role(unit)            # "fill [it] with water": the goal is what is unsaid
        if said is not None:
            first = next((e for e in frame.elements if e.role == said), first)
        if first is not None and first.role not in elements and self.frames and (frame.needs_held() or said):
            implicit = self.reference.implicit(frame, first.role)
            if implicit is not None:
                elements = {first.role: implicit, **elements}
        for element in frame.elements:
            if element.role not in elements and element.default is not None:
                elements[element.role] = Phrase(None, element.default, self.ground_name(element.default),
                                                default=True)
            elif element.role not in elements and self.vocabulary is not None:
                unsaid = self.vocabulary.ground_unsaid(frame.name, element.role, unit)
                if unsaid is not None:          # "throw away the towel": where people mean by it (learned)
                    elements[element.role] = Phrase(None, unsaid, unsaid, default=True)
        ordered = {e.role: elements[e.role] for e in frame.elements if e.role in elements}
        self.frames.append(Evoked(frame.name, unit, (clause.start, clause.end), ordered,
                                  "; ".join(clause.conditions) or None,
                                  " ".join(self.text[r.start:r.np.end] for r in clause.result) or None,
                                  " ".join(w.text for w in clause.items if isinstance(w, Word) and w.info == "time")
                                  or None, clause.asked))
        self.carry_on(frame, roles, attached)
        self.cut_where_it_lies(frame, roles, attached)

    def cut_where_it_lies(self, frame: Frame, roles: Mapping[str, Any], attached: list[tuple[NP, PP]]) -> None:
        """"Slice the apple *in the pan*", "cut an apple inside a pot": a thing cut where it lies in a container
        leaves its pieces there, so the pieces are put in it, after the cut (a Place; the planner skips what is
        there already). Only a container the taxonomy names one (a pan, a bowl, a plate; not a counter, where
        "slice the bread on the counter" says where it is cut, nothing more), only for the frame that cuts."""
        cutting = self.cutting("cut")
        first = frame.elements[0].role if frame.elements else None
        theme = roles.get(first) if first is not None else None
        if cutting is None or cutting[0].name != frame.name or not isinstance(theme, NP) or theme.conjuncts:
            return
        for host, pp in attached:
            if host is theme and pp.prep in PUT_IN and pp.np.kind == "thing" and not pp.np.pronoun and \
                    self.types.is_a(self.roles.class_or_head(pp.np), "container") is True:
                self.put(theme, pp.np, "in")
                return

    @staticmethod
    def asker(frame: Frame, roles: dict[str, Any]) -> None:
        """Whose question is answered gets the answer: "answer *Jorge*'s question", "answer the question *of
        the girl in the kitchen*" (the possessor, or the person of an "of" phrase with what describes them,
        is the recipient when none is said)."""
        first = frame.elements[0] if frame.elements else None
        theme = roles.get(first.role) if first is not None and first.type == "question" else None
        if not isinstance(theme, NP) or "recipient" not in frame.roles or "recipient" in roles:
            return
        if theme.possessor is not None and theme.possessor.kind == "person":
            roles["recipient"] = theme.possessor
        elif theme.of is not None and theme.of.kind == "person" and theme.of.pronoun is None:
            roles["recipient"] = replace(theme.of, end=max(theme.of.end, theme.end))
        elif theme.of is not None and theme.of.pronoun in _ASKERS:
            roles["recipient"] = theme.of      # "answer whatever *she* asks you" (words46): the asker, a pronoun

    def carry_on(self, frame: Frame, roles: Mapping[str, Any], attached: list[tuple[NP, PP]]) -> None:
        """"Put an apple in a pan *on the table*": a container the theme goes into, said to be in
        or on a place, is put there too, after (a pan already there stays: the planner skips it).
        Only when the frame's goal may be a place (a room is one): "pour water into the bowl *in
        kennel 2*" says where the bowl is (Pour's goal is a container; the water is poured, not put)."""
        first = frame.elements[0].role if frame.elements else None
        relation = next((p for p in frame.postconditions if not p.negated and len(p.args) == 2
                         and p.args[0] == first and isinstance(roles.get(p.args[1]), NP)), None)
        if relation is None or self.types.is_a("room", frame.element(relation.args[1]).type) is not True:
            return                                   # the goal may be no place: a container only
        goal = roles[relation.args[1]]
        for host, pp in attached:
            if host is goal and pp.prep in PUT_IN and not pp.np.pronoun and goal.kind == "thing" and not pp.describes \
                    and \
                    self.types.is_a(self.roles.class_or_head(goal), "container") is True:
                self.put(goal, pp.np, relation.predicate)
                return

    def prepare(self, np: NP, frame: Frame, role: str, roles: Mapping[str, Any]) -> None:
        """Frames that must come first: result words ("heated") and contents ("with a fork")."""
        cutting = self.cutting(noun_lemma(np.head.text)) if np.head is not None else None
        if cutting is not None and cutting[0].name == frame.name and frame.elements and \
                role == frame.elements[0].role:
            self.cut.update(id(c) for c in (np, *np.conjuncts))   # "cut a tomato slice": this frame cuts it
        if np.inner and not np.conjuncts:
            self.cut_for(np)             # "a slice of cooked bread": the slice is what is cooked, so cut first
        for inner in np.inner:
            self.results_of(inner)
        if np.results and role == "instrument":
            np.results = []              # "wipe the table with a clean cloth": the tool as it is, no Clean first
        if np.results and frame.elements and role == frame.elements[0].role:
            if "source" in roles or "ground" in self.types.roles(frame):
                np.results = []          # "take the clean mugs out of the dishwasher", "are there any clean towels
                #                          in the cupboard?", "count the clean plates": the thing as it is (sought)
            undone = {p.predicate for p in frame.postconditions if p.negated and p.args == (role,)}
            np.results = [w for w in np.results if not undone & self.result_states(w)]   # "heat the frozen peas"
        self.results_of(np)
        if np.contents and role == (frame.elements[0].role if frame.elements else None):
            relation = next((p for p in frame.postconditions if not p.negated and len(p.args) == 2
                             and p.args[0] == role and p.args[1] in frame.roles), None)
            unsaid = relation is not None and relation.args[1] not in roles
            if relation is not None:
                for content in np.contents:
                    if unsaid and tuple(self.text[content.end:].lower().split()[:2]) not in _IN_IT:
                        continue         # "place it with the coffee maker": beside it, not in it
                    self.results_of(content)
                    self.put(content, np, relation.predicate)
            # "Move a bowl with a knife *in it*": the knife is put in the bowl even where the bowl goes is unsaid (it
            # was dropped; words25), when the contents are said to be in or on it

    def result_states(self, word: Word) -> set[str]:
        """The states a result word's frame gives its theme (``cold`` for "frozen")."""
        frame = self.library.frame(word.info[0])  # type: ignore[index]
        first = frame.elements[0].role if frame.elements else None
        return {p.predicate for p in frame.postconditions if not p.negated and p.args == (first,)}

    def results_of(self, np: NP) -> None:
        if np.conjuncts:                 # "a heated apple and a chilled pear": each its own
            for conjunct in np.conjuncts:
                self.results_of(conjunct)
            np.results = []
            return
        self.cut_for(np)
        cutting = self.cutting("cut")
        cut_name = cutting[0].name if cutting is not None else None
        # "cold sliced lettuce", "a clean, sliced potato": the words' order says nothing of which came first, and
        # the thing they name is the pieces, which have the other states: the cut first
        for word in sorted(np.results, key=lambda w: w.info[0] != cut_name):  # type: ignore[index]
            info: tuple[str, str] = word.info  # type: ignore[assignment]
            frame_name, unit = info
            frame = self.library.frame(frame_name)
            first = frame.elements[0].role
            theme = self.phrase(np, frame, first)
            if any(e.frame == frame.name and first in e.elements and self.same_thing(e.elements[first], theme)
                   for e in self.frames):
                continue                 # "a chilled, cut slice": cut once
            self.frames.append(Evoked(frame.name, unit, (word.start, word.end),
                                      {first: theme} | self.defaults(frame, {first})))
        np.results = []

    def cutting(self, noun: str) -> tuple[Frame, str] | None:
        """The frame that cuts a thing into pieces, and its lexical unit: the one the piece's noun
        names ("slice"), else the one of "cut", whose result is a state of its theme (``sliced``); memoised by
        the library's :class:`~seal_cli.language.element_types.Types`."""
        return self.types.cutting(noun)

    def cut_for(self, np: NP) -> None:
        """A piece cut from a whole ("an apple *slice*", "a *piece* of bread", ``grounding.PIECES``)
        exists once the whole has been cut: the cutting frame comes first, on the whole, unless the
        command has cut it already ("slice the bread and take a slice")."""
        if np.head is None or np.head.tag != "WORD" or np.kind != "thing" or noun_lemma(np.head.text) not in PIECES \
                or id(np) in self.cut:
            return
        self.cut.add(id(np))
        found = self.cutting(noun_lemma(np.head.text))
        if found is None:
            return
        frame, unit = found
        first = frame.elements[0].role
        whole = self.phrase(np, frame, first)
        if whole.refers_to is not None or whole.cls is None and not (_whole_named(np) or np.of):
            return                                         # no whole named: "take a (little) slice" (see phrase)
        if any(e.frame == frame.name and first in e.elements and self.same_thing(e.elements[first], whole)
               for e in self.frames):
            return
        self.frames.append(Evoked(frame.name, unit, (np.start, np.end), {first: whole} | self.defaults(frame, {first})))

    def cut_from(self, np: NP) -> tuple[int, str] | None:
        """For a piece that names no whole ("take *a slice*"), the theme of the latest frame that cut
        something in this command: what the piece was cut from."""
        if np.head is None or np.head.tag != "WORD" or _whole_named(np) or np.of is not None or \
                noun_lemma(np.head.text) not in PIECES:
            return None
        found = self.cutting(noun_lemma(np.head.text))
        if found is None:
            return None
        frame = found[0]
        first = frame.elements[0].role
        for index in range(len(self.frames) - 1, -1, -1):
            if self.frames[index].frame == frame.name and first in self.frames[index].elements:
                return index, first
        return None

    def same_thing(self, a: Phrase, b: Phrase) -> bool:
        if a.refers_to is not None or b.refers_to is not None:
            ra = a.refers_to or ()
            rb = b.refers_to or ()
            return bool(ra and ra == rb)
        return (a.cls or a.head) == (b.cls or b.head)

    def hold(self, np: NP) -> None:
        """The frame that gets ``np`` in hand (``holding(theme)``: Pick), before the clause."""
        for frame in sorted(self.library.achievers("holding"), key=lambda f: len(f.elements)):
            first = frame.first_role
            if first is not None and frame.gets_held():
                self.results_of(np)
                elements = {first: self.phrase(np, frame, first)}
                last = (len(self.frames) - 1, first)
                if self.frames and elements[first].refers_to == last and self.frames[-1].frame == frame.name:
                    return                           # "pick up a card and use it to ...": in hand already
                self.frames.append(Evoked(frame.name, frame.lexical_units[0].text if frame.lexical_units else "",
                                          (np.start, np.end), elements | self.defaults(frame, elements)))
                return

    def worn_by(self, frame: Frame, theme: str, np: NP) -> bool:
        """Whether ``np``, said with "with" after the first element of a frame that takes a person first, is a
        garment that describes that person ("greet the guy *with the gray sweater*": worn, no thing to hold first;
        words37). "turn on the lamp with the remote" still holds the remote."""
        element = frame.elements[0] if frame.elements else None
        return element is not None and element.role == theme and element.type == "person" and \
            np.head is not None and self.types.is_a(noun_lemma(np.head_text.lower()), "clothing") is True

    def put(self, content: NP, container: NP, predicate: str) -> None:
        """The frame that makes ``predicate(content, container)`` true (Place for ``in``)."""
        for frame in sorted(self.library.achievers(predicate), key=lambda f: len(f.elements)):
            fact = next(p for p in frame.postconditions if p.predicate == predicate and not p.negated)
            if len(fact.args) == 2 and fact.args[0] == frame.elements[0].role:
                elements = {fact.args[0]: self.phrase(content, frame, fact.args[0]),
                            fact.args[1]: self.phrase(container, frame, fact.args[1])}
                self.frames.append(Evoked(frame.name, frame.lexical_units[0].text if frame.lexical_units else "",
                                          (content.start, content.end), elements | self.defaults(frame, elements)))
                return

    def series(self, ref: tuple[int, str]) -> list[tuple[int, str]]:
        """The same element of a run of frames of one kind ending at ``ref``, each a single thing said there ("get
        *the milk* from the fridge and *the mug* from the living room": Pick, Pick): what a plural pronoun after
        them gathers ("... and put *them* on the table": both), oldest first; ``[ref]`` when there is no run."""
        index, name = ref
        kind = self.frames[index].frame
        run = [ref]
        k = index - 1
        while k >= 0 and self.frames[k].frame == kind and name in self.frames[k].elements:
            phrase = self.frames[k].elements[name]
            if phrase.refers_to is not None or phrase.default or phrase.plural or phrase.conjuncts or \
                    phrase.kind != "thing" or self.frames[k].inferred is not None:
                break
            run.insert(0, (k, name))
            k -= 1
        return run

    def defaults(self, frame: Frame, have: Iterable[str]) -> dict[str, Phrase]:
        have = set(have)
        return {e.role: Phrase(None, e.default, self.ground_name(e.default), default=True)
                for e in frame.elements if e.default is not None and e.role not in have}


    def phrase(self, np: NP, frame: Frame, role: str) -> Phrase:
        pointed = self.reference.pointed_person(np)
        if pointed is not None:                     # "Sam is in the hall. Find *that person*": Sam
            found = self.reference.antecedent(pointed, frame, role)
            said = self.reference.mentioned(pointed, frame, role) if found is None else None
            if found is not None and found[2] == "person" or said is not None:
                return self.phrase(pointed, frame, role)
        if np.pronoun is not None and (np.kind in ("pronoun", "thing") or np.pronoun in ("him", "her", "he", "she")) \
                and np.pronoun not in ("something", "everything", "anything", "nothing"):
            found = self.reference.antecedent(np, frame, role)
            if found is not None:
                index, name, _ = found
                target = self.frames[index].elements[name]
                ref = target.refers_to or (index, name)
                root = self.frames[ref[0]].elements[ref[1]]
                owner = self.reference.owner_before(np)
                if owner is not None and f"{owner}'s" in (root.text or ""):     # "go to Priya's office and tell
                    return Phrase(self.text[np.start:np.end], owner, None, "person",     # her": Priya, no office
                                  span=(np.start, np.end))
                series = self.series(ref) if np.pronoun in ("them", "they", "both") and found[2] != "person" \
                    and not root.plural and not root.conjuncts else [ref]
                if len(series) > 1:                 # "get the milk from the fridge and the mug from the living
                    return Phrase(self.text[np.start:np.end], root.head, root.cls, found[2], ref, None, True,
                                  span=(np.start, np.end), conjuncts=tuple(     # room and put *them* ...": both
                                      replace(self.frames[i].elements[r], refers_to=(i, r), span=(np.start, np.end))
                                      for i, r in series))
                return Phrase(self.text[np.start:np.end], root.head, root.cls, found[2], ref, root.quantity,
                              root.plural, span=(np.start, np.end))
            said = self.reference.mentioned(np, frame, role)
            if said is not None:                    # "Bogdan has a question; answer it for him"
                person = said.name or self.types.is_a(noun_lemma(said.head), "person") is True
                if person:
                    return Phrase(self.text[np.start:np.end], said.head if said.name else noun_lemma(said.head),
                                  None, "person", span=(np.start, np.end))
                start, end = self.reference.with_its_place(said)
                return Phrase(self.text[np.start:np.end], noun_lemma(said.head), self.mentioned_class(said), "thing",
                              span=(np.start, np.end), stands_for=self.text[start:end])
            owner = self.reference.owner_before(np)
            if owner is not None:                   # "go to Tom's room and tell him ...": Tom
                return Phrase(self.text[np.start:np.end], owner, None, "person", span=(np.start, np.end))
            return Phrase(self.text[np.start:np.end], np.head_text, None,
                          "thing" if np.kind == "pronoun" and np.pronoun == "it" else
                          "person" if np.kind == "pronoun" else np.kind, span=(np.start, np.end))
        if np.kind == "place" and np.head is not None and np.head.info == "back":
            source = self.reference.source_before(self.clause_frames)
            if source is not None:                  # "take the cup from the table and put it back": the table
                root = self.frames[source[0]].elements[source[1]]
                return Phrase(self.text[np.start:np.end], root.head, root.cls, root.kind, source, root.quantity,
                              root.plural, span=(np.start, np.end))
        if np.there:
            place = self.reference.place_before(self.clause_frames)
            if place is not None:                   # "go to the garage and count the bikes there"
                root = self.frames[place[0]].elements[place[1]]
                return Phrase(self.text[np.start:np.end], root.head, root.cls, root.kind, place, root.quantity,
                              root.plural, span=(np.start, np.end))
            stated = self.reference.place_stated(np.start)
            if stated is not None:                  # "Sam wants to go to the kitchen, lead him there"
                words = [w for w in self.text[stated.start:stated.end].split() if w.lower() not in NP_OPENERS]
                cls = self.vocabulary.grounded(words, []) if self.vocabulary is not None and words else None
                head = " ".join([*words[:-1], noun_lemma(stated.head)]) if words else noun_lemma(stated.head)
                return Phrase(self.text[np.start:np.end], head, cls, span=(np.start, np.end))
        text = self.text[np.start:np.end]
        if np.cut is not None and np.start < np.cut[0] and np.cut[1] < np.end:
            text = f"{self.text[np.start:np.cut[0]].rstrip()} {self.text[np.cut[1]:np.end].lstrip()}"
        cls = None
        if self.vocabulary is not None and np.kind != "message":
            cls = np.ground(self.vocabulary)
            if cls is None and np.possessor is not None and np.possessor.kind == "thing":
                cls = np.possessor.ground(self.vocabulary)   # "the toilet's water tank": a part no class names
        whole = self.cut_from(np) if cls is None else None
        if whole is not None:                   # "slice the bread, take a slice": a slice of the bread
            index, name = whole
            root = self.frames[index].elements[name]
            ref = root.refers_to or (index, name)
            root = self.frames[ref[0]].elements[ref[1]]
            return Phrase(text, root.head, root.cls, root.kind, ref, None, np.plural, span=(np.start, np.end))
        modifiers = tuple(noun_lemma(w.text) if w.tag == "WORD" else w.lower for w in np.mods)
        conjuncts = tuple(self.phrase(c, frame, role) for c in np.conjuncts) if len(np.conjuncts) > 1 else ()
        plural = np.plural and np.kind != "message" and not (   # "the keys": one key chain, as people mean it
            np.quantity is None and not np.conjuncts and self.vocabulary is not None and np.head is not None
            and self.vocabulary.names_one([w.text for w in np.mods] + [np.head.text]))
        head = np.head_text if np.kind != "message" else np.question or text
        if np.kind == "thing":
            noun = self.reference.noun_for_one(np)              # "the red one": the noun said before (words29)
            if noun is not None:
                head = noun
                if cls is None and self.vocabulary is not None:
                    cls = self.vocabulary.grounded([noun], [])
        return Phrase(text, head, cls, np.kind, None,
                      np.quantity,
                      plural, modifiers, span=(np.start, np.end), conjuncts=conjuncts,
                      relative=np.relative)


    def ground_name(self, name: str) -> str | None:
        if self.vocabulary is None:
            return name
        return self.vocabulary.ground_name(name) or name   # a default: the rules alone (langdata)


def _whole_named(np: NP) -> bool:
    """Whether a piece's modifiers name what it is cut from ("an *apple* slice"): a modifier that is no
    gradable adjective ("the *little* piece", "a *thin* slice" say how it is, not of what)."""
    return any(not is_gradable(m.lower) for m in np.mods)


def _relates_to_goal(relation: Any) -> bool:
    """Whether a frame's result relates its first element to its goal (``at(theme, goal)``)."""
    return relation is not None and relation.args[1] == "goal"


def _named_again(content: NP, theme: Any, host: NP, attached: Sequence[tuple[NP, PP]]) -> bool:
    """Whether "with X" said after another phrase belongs to the theme because it names the theme
    again: "put a pan on the table with an apple *on the pan*" is "a pan with an apple on it" (the
    contents construction with the noun repeated instead of "it"), not a table with an apple."""
    if not isinstance(theme, NP) or host is theme or theme.head is None or theme.pronoun:
        return False
    head = noun_lemma(theme.head.text)
    return any(h is content and p.prep in PUT_IN and p.np.head is not None and not p.np.pronoun
               and noun_lemma(p.np.head.text) == head for h, p in attached)


_LEAVING = {"off": "off", "out": "out of"}
"""The particles of taking a thing from where it is, and the preposition each says that place with ("clear *off* the
counter": off the counter; "clear *out* the cupboard": out of it)."""

_STRAY_STATES = frozenset(["on", "off"])
"""The particles that name a state (on.a.01 ! off.a.01): said alone after a thing, they change what is done."""


def _split_particle(unit: str, clause: Clause, after: int, before: int) -> Word | None:
    """The particle of a split unit said between a noun phrase and a prepositional phrase after it ("leave the
    light *on* in the hall", "switch the lights *off* in the bedroom"): it ends the thing's words, so the phrase
    describes the thing without it ("the light in the hall": a toggle frame has no place of its own)."""
    words = unit.split()
    if len(words) < 2:
        return None
    return next((w for w in clause.items if isinstance(w, Word) and w.tag == "PARTICLE" and
                 w.lower.split()[-1] == words[-1] and after <= w.start and w.end <= before), None)   # "switched off"
