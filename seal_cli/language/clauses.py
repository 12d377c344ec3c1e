"""Clause-to-clause passes: from the clauses as the grammar read them (:mod:`seal_cli.language.syntax`)
to the clauses the frames are built from, in the order they are to be done.

Each pass is a method that takes clauses (or a clause's items) and returns or edits them, in the
order :meth:`Clauses.passes` lists them:

1. **reading a clause** (:meth:`Clauses.read`): relative clauses join their noun
   (:meth:`~Clauses.relatives`), a clause of purpose read as a "to" phrase is split off
   (:meth:`~Clauses.purpose`: "take the box to the hall *to open*"), and so is a gapped second
   clause (:meth:`~Clauses.gapping`: "put the plates on the table *and the glasses next to them*");
   things held are taken out ("with X in hand"), coordinated noun phrases join
   (:meth:`~Clauses.coordinate`), contents join their container, the objects are read (an indirect
   object first, a second object after what describes a person) and what a verb of saying says
   (:meth:`~Clauses.message`);
2. **subordinate clauses** ordered (:meth:`~Clauses.subordinate`: "*before you go*, turn off ...");
3. **coordinated verbs** sharing one object (:meth:`~Clauses.share_objects`: "slice and chill an apple");
4. **clauses of purpose** leaving their object unsaid (:meth:`~Clauses.purposes`: "... *to open* [it]");
5. **order words** (:meth:`~Clauses.order`: "A while B", "A after B", "A when done B");
6. **light verbs** (:meth:`~Clauses.light_verb`: "give the sauce *a stir*" is stirring it).
"""

from __future__ import annotations

import re
from collections.abc import Sequence
from dataclasses import replace

from seal_cli.frames.library import Library
from seal_cli.frames.taxonomy import class_key
from seal_cli.language.asking import ASKING, IFS, WH_ASKED, contracted_wh, direct_question, person_subject
from seal_cli.language.element_types import Types
from seal_cli.language.english import DONE_BEFORE, FIRST_LATER
from seal_cli.language.lexicon import CommandError, Word
from seal_cli.language.morphology import in_dictionary, is_adjective, noun_lemma, verb_lemma
from seal_cli.language.roles import FROM, LOCATIVE
from seal_cli.language.syntax import NP, PP, Clause, Command, Item, end_of
from seal_cli.language.verb_usage import mostly_verb

__all__ = ["LIGHT_VERBS", "Clauses"]


LIGHT_VERBS = ("give",)
"""Verbs that lend their clause to an action noun: "give the sauce a stir" is stirring it."""


_ALSO = frozenset(["too", "as well", "also"])
"""Words that say a clause holds again for one more ("and Ben *too*"; words29)."""
_OBJECT_PERSONS = frozenset(["me", "him", "her", "them", "us"])
"""Object pronouns that can be the person a thing is given to ("give *him* the keys and *her* the coat")."""


_SOME_THING = frozenset(["something", "anything", "everything"])
"""Indefinite pronouns of a thing that may be the second object ("tell Jo in the hall *something* about yourself")."""


class Clauses:
    """The clause passes for one command (its text) and one library."""

    def __init__(self, text: str, library: Library, types: Types, speech: frozenset[str]) -> None:
        self.text = text
        self.library = library
        self.types = types
        self.speech = speech               # units of verbs of saying (``Lexicon.speech``)

    def passes(self, command: Command) -> list[Clause]:
        """The command's clauses, read and ordered (the passes of the module docstring)."""
        clauses: list[Clause] = []
        joins: list[str] = []
        for raw, join in zip(command.clauses, command.joins, strict=True):
            read = self.read(raw)             # the clause, and the ones said inside it (gapped, of purpose)
            clauses.extend(read)
            joins.append(join)
            joins.extend("and" if extra is read[0].gap else "to" for extra in read[1:])
        self.subordinate(clauses)
        self.one_more(clauses)
        self.share_objects(clauses, joins)
        self.purposes(clauses, joins)
        ordered = self.order(clauses, joins)
        for clause in ordered:
            self.light_verb(clause)
        return ordered

    # -- one clause ----------------------------------------------------------------------------
    def read(self, raw: Clause) -> list[Clause]:
        """A clause from the grammar's (all its phrases in ``items``): objects, message; then the
        clause of purpose said inside it (:meth:`purpose`) and the gapped clause after it."""
        items = self.relatives(list(raw.items))
        purpose = self.purpose(items)
        gap: Clause | None = None
        split = self.gapping(items)
        if split is not None:
            gapped = items[split + 1:]
            raw_and = items[split]
            items = items[:split]
            said_end = end_of(items[-1])
            # "bring *me* the spoon from the kitchen and the cup from ...": the person told is the second's too
            told = items[0] if len(items) > 1 and isinstance(items[0], NP) and items[0].kind == "person" and \
                isinstance(items[1], NP) and not self.to_each([*items, raw_and, *gapped]) else None
            if any(isinstance(x, PP) and x.prep in FROM for x in gapped):   # "... from the sink *on the table*"
                items += [replace(x, np=_copy(x.np)) for x in gapped if isinstance(x, PP) and x.prep not in FROM
                          and not any(isinstance(y, PP) and y.prep == x.prep for y in items)]
            gap = self.make_clause(raw.verb, [*([replace(told)] if told is not None else []), *gapped], [], None)
            gap.start = gapped[0].start
        echo = self.echoed(items) if split is None else None
        if echo is not None:              # "bring Anna a towel and Ben too": the same for Ben (words29)
            other = items[echo + 1]
            said_end = end_of(items[echo - 1])
            gap = self.make_clause(raw.verb, [other, *(replace(x) for x in items[1:echo])], [], None)
            gap.start = other.start
            items = items[:echo]
        clause = self.make_clause(raw.verb, items, raw.conditions, raw.sub)
        if gap is not None:
            clause.end = min(clause.end, max(said_end, clause.message.end if clause.message else 0))
        clause.gap = gap
        clause.asked = raw.asked
        return [clause, *([gap] if gap is not None else []), *([purpose] if purpose is not None else [])]

    def purpose(self, items: list[Item]) -> Clause | None:
        """A clause of purpose the grammar read as a "to" phrase: "to" and a bare noun phrase that begins
        with the base form of a verb of the library that is no class of its taxonomy ("take the box to the
        hall *to open*", "take a dish to the table *to put tissue box on it*"; not "to *microwave*"), and
        no state after it ("to get *chilled*", "to get *cold*": what happens to it, no instruction). It
        becomes a clause of its own, with the rest of its words as its object and the phrases after it
        (taken out of ``items``); None when there is none."""
        for k, item in enumerate(items):
            if not isinstance(item, PP) or item.prep != "to" or item.lead:
                continue
            np = item.np
            if np.determined or np.kind != "thing" or np.head is None or np.head.tag != "WORD" or np.of or \
                    np.results or np.quantity is not None:
                continue
            words = [*np.mods, np.head]
            verb = words[0]
            if verb.start != np.start or verb_lemma(verb.lower) != verb.lower or not self.types.evoked_by(verb.lower) \
                    or class_key(verb.lower) in self.types.taxonomy.known_classes or \
                    self.types.opening_only(verb.lower):
                continue                      # "move the mug to *microwave*": a thing the library knows; "to *trash*
                #                               can", "to *dust* pan": a word that is mostly a noun, a verb only before
                #                               its object (alfred29)
            after = words[1].lower if len(words) > 1 else None
            if after is not None and (is_adjective(after) or verb_lemma(after) not in (None, after)):
                continue                      # "to get chilled": a state the thing gets into
            rest: list[Item] = []
            if len(words) > 1:                # "to put *tissue box*": the rest is its object
                rest.append(NP(words[1].start, np.end, np.head, mods=words[1:-1], plural=np.plural))
            rest += items[k + 1:]
            del items[k:]
            return self.make_clause(Word(verb.text, verb.start, verb.end, "VERB", verb.lower), rest, [], None)
        return None

    def make_clause(self, verb: Word, items: list[Item], conditions: list[str], sub: str | None) -> Clause:
        """A clause from its verb and the phrases after it."""
        held = self.in_hand(items)
        items = self.coordinate(items)
        items = self.containing(items)
        objects: list[NP] = []
        if len(items) > 1 and isinstance(items[0], Word) and items[0].lower == "how" and \
                isinstance(items[1], NP) and items[1].quantity is not None:
            counted = items[1]
            counted.quantity = None             # "count how many books are on the shelf": the books
            items.pop(0)
        while items and (isinstance(items[0], NP) or isinstance(items[0], Word) and items[0].tag == "PARTICLE"
                         and objects == [] and len(items) > 1 and isinstance(items[1], NP)):
            first = items.pop(0)
            if isinstance(first, NP):
                objects.append(first)
        self.recipient_first(verb, objects, items)
        self.second_object(verb, objects, items)
        message = self.message(items) or self.said(verb, objects, items)
        if message is not None and str(verb.info) in ASKING:
            self.asked(objects, message)
        end = max([verb.end] + [end_of(x) for x in (*objects, *items)] + ([message.end] if message else []))
        return Clause(verb, objects, items, message, verb.start, end, held, sub, conditions)

    def asked(self, objects: list[NP], message: NP) -> None:
        """A yes/no question a verb of asking puts to a person ("ask Raj *if he wants tea*"): the message is the
        question as the person hears it (``question``: "do you want tea?", :func:`~seal_cli.language.asking.
        direct_question`); with nobody said to ask ("find out if *anna* wants coffee"), the person the question is
        about is the one asked."""
        spans = [(m.start() + message.start, m.end() + message.start)
                 for m in re.finditer(r"[^\s,;:?!.]+", self.text[message.start:message.end])]
        words = [self.text[a:b] for a, b in spans]
        wh = bool(words) and (words[0].lower() in WH_ASKED or contracted_wh(words[0]))     # "what's in it"
        if not words or words[0].lower() not in IFS and not wh or wh and not objects:
            return                      # a wh-question is put to a person said ("ask Maria where the stapler is")
        if not objects:
            size = person_subject(words[1:], self.types.taxonomy.members("person") | {"person"}, ())
            if size:
                start, end = spans[1][0], spans[size][1]
                head = words[size]
                name = size == 1 and (head[:1].isupper() or not in_dictionary(head))
                objects.append(NP(start, end, Word(head, spans[size][0], end, "NAME" if name else "WORD",
                                                   None, head.lower()), "person", determined=size > 1,
                                  mods=[]))
        person = objects[0] if objects and objects[0].kind == "person" and objects[0].pronoun is None else None
        message.question = direct_question(words, self.text[person.start:person.end].split() if person else ())

    def receives(self, verb: Word) -> bool:
        """Whether a frame of the verb has someone to receive (a recipient)."""
        return any("recipient" in self.types.roles(f) for f in self.types.evoked_by(str(verb.info)))

    def recipient_first(self, verb: Word, objects: list[NP], items: list[Item]) -> None:
        """"give *to me* the remote", "bring to my son his coat", "describe *for me* the things on the table": a
        "to" or "for" phrase naming a person right after a verb whose frames have someone to receive, and then a
        noun phrase: that noun phrase is the object (the order of many other languages; "bring for me the cup"
        had dropped the cup)."""
        if objects or len(items) < 2 or not isinstance(items[0], PP) or items[0].prep not in ("to", "for") or \
                items[0].np.kind != "person" or not isinstance(items[1], NP) or items[1].kind == "person" or \
                not self.receives(verb):
            return
        second = items.pop(1)
        assert isinstance(second, NP)
        objects.append(second)
        items.append(items.pop(0))      # the phrases said after the object describe it, not the person

    def second_object(self, verb: Word, objects: list[NP], items: list[Item]) -> None:
        """"give the man *in the gray suit* his coat": after a person and the phrases that describe them
        (where they are, what they have), a noun phrase with a determiner is the second object of a verb
        whose frames have someone to receive; the phrases join the person's noun phrase."""
        if len(objects) != 1 or objects[0].kind != "person" or objects[0].pronoun is not None or \
                not items or not isinstance(items[0], PP):
            return
        k = 0
        while k < len(items):
            item = items[k]
            if not (isinstance(item, PP) and item.prep in LOCATIVE + ("with",) and not item.lead):
                break
            k += 1
        second = items[k] if k < len(items) else None
        if not isinstance(second, NP) or not (second.determined or second.pronoun in _SOME_THING) or \
                second.kind == "person" or not self.receives(verb):
            return                      # "tell the man in the hall *something* about yourself" (words41)
        person = objects[0]
        for pp in items[:k]:
            assert isinstance(pp, PP)
            person.inner.append(pp.np)
            person.end = max(person.end, pp.np.end)
        objects.append(second)
        del items[:k + 1]

    def relatives(self, items: list[Item]) -> list[Item]:
        """A relative clause (``REL``) belongs to the noun before it: kept whole as its ``relative``,
        with the frames its result words evoke ("a lamp that is turned on"); "that is" before a
        prepositional phrase makes the phrase describe the noun ("the pan that is on the stove"),
        never fill an element of the frame."""
        if not any(isinstance(item, Word) and item.tag == "REL" for item in items):
            return items
        out: list[Item] = []
        describe = False
        for item in items:
            last = out[-1] if out else None
            if isinstance(last, Word) and last.tag == "PARTICLE" and last.info != last.lower and len(out) > 1:
                last = out[-2]                   # "switch the light off *that I left on*": the split unit's particle
            if isinstance(item, Word) and item.tag == "REL" and isinstance(last, NP | PP):
                host = last.np if isinstance(last, PP) else last
                if item.info == "be":
                    describe = True
                    continue
                host.relative = self.text[item.start:item.end]
                host.relative_start, host.relative_end = item.start, item.end
                for frame_unit in item.info if isinstance(item.info, tuple) else ():
                    host.results.append(Word(item.text, item.start, item.end, "RESULT", frame_unit))
                continue
            if describe and isinstance(item, PP):
                item.describes = True
            elif isinstance(item, PP) and isinstance(last, NP | PP) and \
                    (last.np if isinstance(last, PP) else last).relative_end == item.start - 1:
                item.after_relative = True
            describe = False
            out.append(item)
        return out

    @staticmethod
    def gapping(items: list[Item]) -> int | None:
        """Where a second clause with the verb left out starts: "put the plates *on the table* and the
        glasses *next to them*" (an object and a place, "and", another object and place); None.

        A source in each ("bring me the spoon *from the kitchen* and the cup *from the family room*") is
        a gap too: each thing is fetched from its own place, and a phrase said once after the second source
        ("... *on the table*") is said of both (:meth:`read` copies it back). A second noun phrase after a
        source with no source of its own stays a place joined to the first ("take the cup from the table and
        the shelf to the sink")."""
        if len(items) < 5 or not isinstance(items[0], NP):
            return None
        if Clauses.to_each(items):
            return 2
        for k in range(2, len(items) - 2):
            word, before = items[k], items[k - 1]
            rest = items[k + 2:]
            if isinstance(word, Word) and word.tag == "AND_NP" and word.lower == "and" and \
                    isinstance(before, PP) and isinstance(items[k + 1], NP) and \
                    all(isinstance(x, PP) for x in rest) and not before.lead and \
                    before.prep not in ("with", "without", "of", "for", "about", "between") and \
                    (before.prep not in FROM or isinstance(rest[0], PP) and rest[0].prep in FROM) and \
                    before.np.pronoun is None:     # "a bowl with a spoon in it and a knife ...": contents
                return k
        return None

    @staticmethod
    def echoed(items: list[Item]) -> int | None:
        """Where "and", another person and "too" (or "as well", "also") start after a clause that gives a thing to a
        person: "bring Anna a towel *and Ben too*", "get Sam a plate and Jo as well": the clause again for the other
        person, with the same things (the coordination pass had joined "a towel and Ben", and the robot would have
        carried Ben). A thing after "and" ("bring me the cup and the spoon too") stays one clause of two things."""
        if not items or not isinstance(items[-1], Word) or items[-1].lower not in _ALSO:
            return None
        k = next((j for j, x in enumerate(items) if isinstance(x, Word) and x.tag == "AND_NP" and
                  x.lower in ("and", ", and")), None)         # ", and Ben too" (words31)
        if k is None or k < 2 or k + 2 >= len(items):
            return None
        rest = items[k + 2:]
        if not all(isinstance(x, Word) and x.info == "time" and x.lower in _ALSO for x in rest):
            return None

        def person(x: Item) -> bool:
            return isinstance(x, NP) and (x.kind == "person" or x.kind == "pronoun" and
                                          (x.pronoun or "").lower() in _OBJECT_PERSONS)

        if not (person(items[0]) and person(items[k + 1]) and
                all(isinstance(x, NP) and x.kind == "thing" for x in items[1:k])):
            return None
        return k

    @staticmethod
    def to_each(items: list[Item]) -> bool:
        """Whether the phrases are a person and a thing, "and", another person and thing: "bring *Anna the cup*
        and *Ben the spoon*", "give him the keys and her the coat" — each thing to its own person, the second
        clause's verb left out (the coordination pass had joined "the cup and Ben" and lost the spoon)."""
        def person(x: Item) -> bool:
            return isinstance(x, NP) and (x.kind == "person" or x.kind == "pronoun" and
                                          (x.pronoun or "").lower() in _OBJECT_PERSONS)

        def thing(x: Item) -> bool:
            return isinstance(x, NP) and x.kind == "thing"

        return len(items) >= 5 and person(items[0]) and thing(items[1]) and isinstance(items[2], Word) and \
            items[2].tag == "AND_NP" and items[2].lower == "and" and person(items[3]) and thing(items[4])

    def said(self, verb: Word, objects: list[NP], items: list[Item]) -> NP | None:
        """What a verb of saying says when it is a clause without a wh-word: "tell him *dinner is
        ready*" (a noun phrase, then "is"), from the object after the person told."""
        if not objects or not items or not (isinstance(items[0], Word) and items[0].tag == "BE") or \
                str(verb.info) not in self.speech:
            return None
        first = objects[1] if len(objects) >= 2 else objects[0]
        stop = next((j for j, x in enumerate(items) if isinstance(x, PP) and x.prep in ("to", "for")
                     and x.np.kind in ("person", "pronoun")), len(items))
        end = max(end_of(x) for x in items[:stop])
        del objects[objects.index(first):]
        del items[:stop]
        head = Word(self.text[first.start:end], first.start, end, "WORD")
        return NP(first.start, end, head, "message")

    @staticmethod
    def in_hand(items: list[Item]) -> list[NP]:
        """Take out "with X in hand" ("in his hands"): X is held while the clause is done."""
        held = []
        k = 0
        while k + 1 < len(items):
            first, second = items[k], items[k + 1]
            if isinstance(first, PP) and first.prep == "with" and isinstance(second, PP) and second.prep == "in" \
                    and second.np.head is not None and second.np.head_text == "hand" and not second.np.of:
                held.append(first.np)
                del items[k:k + 2]
                continue
            k += 1
        return held

    @staticmethod
    def coordinate(items: list[Item]) -> list[Item]:
        """Join "NP and NP" into one phrase with conjuncts."""
        out: list[Item] = []
        i = 0
        while i < len(items):
            item = items[i]
            last = out[-1] if out else None
            if (isinstance(item, Word) and item.tag == "AND_NP" and item.lower == "or" and isinstance(last, PP)
                    and i + 1 < len(items)):
                alternative = items[i + 1]
                if isinstance(alternative, PP):     # "on the desk or in the bedroom"
                    items = [*items[:i + 1], alternative.np, *items[i + 2:]]
            other = items[i + 1] if i + 1 < len(items) else None
            if isinstance(item, Word) and item.tag == "AND_NP" and isinstance(last, NP | PP) and \
                    isinstance(other, NP):
                host = last.np if isinstance(last, PP) else last
                if item.lower == "or":               # "an apple or a pear": either will do, the first
                    host.end = other.end
                    i += 2
                    continue
                if host.contents and host.contents[-1].end == host.end:   # "a pot containing a knife and
                    content = host.contents[-1]                             # a slice": both in the pot
                    if not content.conjuncts:
                        content.conjuncts.append(_copy(content))
                    content.conjuncts.append(other)
                    content.end = host.end = other.end
                    content.plural = True
                    i += 2
                    continue
                if not host.conjuncts:
                    host.conjuncts.append(_copy(host))
                host.conjuncts.append(other)
                host.end = other.end
                host.plural = True
                i += 2
                continue
            out.append(item)
            i += 1
        return out

    def containing(self, items: list[Item]) -> list[Item]:
        """Read "a pan with a spoon in it": the spoon is a content of the pan (and "in it" no goal). Said after
        the place the thing goes to, the contents are the thing's when the place holds nothing and the thing does
        (:meth:`carrier`: "drop the pan on the table with a knife in it")."""
        out: list[Item] = []
        i = 0
        while i < len(items):
            item = items[i]
            nxt = items[i + 1] if i + 1 < len(items) else None
            last = out[-1] if out else None
            host = last.np if isinstance(last, PP) else last if isinstance(last, NP) else None
            if (host is not None and isinstance(item, PP) and item.prep == "with" and isinstance(nxt, PP)
                    and nxt.prep in ("in", "on", "inside") and nxt.np.pronoun in ("it", "them")):
                carrier = self.carrier(out) if isinstance(last, PP) else None
                if carrier is not None:
                    carrier.contents.append(item.np)        # the thing's, its span as said
                else:
                    host.contents.append(item.np)
                    host.end = max(host.end, nxt.np.end)
                i += 2
                continue
            out.append(item)
            i += 1
        return out

    def carrier(self, out: list[Item]) -> NP | None:
        """The thing before the place just said (``out`` ends with its phrase) when the place is no container and
        the thing is one ("the pan" of "drop the pan on the table with a knife in it"; not "bring the paper to the
        table with a lamp on it": a paper holds nothing); else None. A particle between them is the verb's ("place
        a pan *down* on the table with a potato inside of it")."""
        place = out[-1]
        before = [x for x in out[:-1] if not (isinstance(x, Word) and x.tag == "PARTICLE")]
        thing = before[-1] if before else None
        if not isinstance(place, PP) or not isinstance(thing, NP) or thing.head is None or place.np.head is None \
                or thing.pronoun or thing.conjuncts:
            return None
        if self.types.is_a(noun_lemma(place.np.head.lower), "container") is not False:
            return None
        return thing if self.types.is_a(noun_lemma(thing.head.lower), "container") is True else None

    def message(self, items: list[Item]) -> NP | None:
        """A question said as the message ("tell me *what day is today*"): from the wh-word on,
        up to a final "to <person>" phrase. "how many" is no message (it asks to count)."""
        for k, item in enumerate(items):
            if isinstance(item, Word) and item.tag == "SAID":   # "tell him we need a cart": said without "that"
                del items[k]
                return NP(item.start, item.end, Word(item.text, item.start, item.end, "WORD"), "message")
            if isinstance(item, Word) and item.tag == "WH":
                nxt = items[k + 1] if k + 1 < len(items) else None
                if item.lower == "how" and isinstance(nxt, NP) and nxt.quantity is not None:
                    items.pop(k)
                    return None
                stop = next((j for j in range(k + 1, len(items)) if _to_person(items[j])), len(items))
                end = max(end_of(x) for x in items[k:stop]) if stop > k else item.end
                start = item.start
                if item.lower in ("that", "to") and stop > k + 1:   # "tell him that ...", "tell her to ..."
                    start = items[k + 1].start
                head = Word(self.text[start:end], start, end, "WORD")
                del items[k:stop]
                return NP(start, end, head, "message")
        return None

    # -- clause to clause ----------------------------------------------------------------------
    @staticmethod
    def subordinate(clauses: list[Clause]) -> None:
        """Order the clauses of subordinate clauses said with a subordinator before their verb: one
        that a clause follows is subordinate to it ("*before you go* to the garage, turn off the
        lights": the lights first; "*when you reach* the kitchen, open the fridge": in order); the
        last one is subordinate to the clause before it ("put them away, *after you wash* them")."""
        k = 0
        while k < len(clauses):
            sub = clauses[k].sub
            if sub is not None and k + 1 < len(clauses) and sub == "before":
                clauses[k], clauses[k + 1] = clauses[k + 1], clauses[k]
                k += 2
                continue
            if sub is not None and k + 1 == len(clauses) and k > 0 and sub in FIRST_LATER:
                clauses[k - 1], clauses[k] = clauses[k], clauses[k - 1]
            k += 1

    @staticmethod
    def one_more(clauses: list[Clause]) -> None:
        """"bring the milk to the table *and the cereal too*", "grab me a coke, and a juice as well": the verb said
        again with one more object (the tagger's ``english.ADDITIVES``, an unsaid verb of the clause before) takes
        the rest of that clause too — its other objects ("me") and its phrases ("to the table"), borrowed —
        with the new object in place of the last one. One said with a place of its own ("bring me the cup, *and a
        knife from the kitchen*") borrows the other objects only."""
        for k in range(1, len(clauses)):
            clause, before = clauses[k], clauses[k - 1]
            if clause.verb.text or clause.verb.info != before.verb.info or len(clause.objects) != 1 or \
                    clause.message or not before.objects:
                continue
            placed = any(isinstance(x, PP) for x in clause.items)     # "..., and a knife from the kitchen"
            if placed and any(isinstance(x, NP) for x in clause.items):
                continue
            clause.objects = [*(replace(o, borrowed=True) for o in before.objects[:-1]), clause.objects[0]]
            if not placed:                                  # only the additive ("too": a particle) after it
                clause.items = [*(replace(item, np=replace(item.np, borrowed=True)) for item in before.items
                                  if isinstance(item, PP)), *clause.items]

    @staticmethod
    def share_objects(clauses: list[Clause], joins: Sequence[str]) -> None:
        """"slice and chill an apple": a verb said bare before "and" shares the next clause's object."""
        for k in range(len(clauses) - 1):
            bare, nxt = clauses[k], clauses[k + 1]
            if not (bare.objects or bare.items or bare.message or bare.held) and nxt.objects and \
                    not set(joins[k + 1].split()) - {"and", "then", ",", "plus", "as", "well"}:
                bare.objects = [nxt.objects[0]]

    def purposes(self, clauses: list[Clause], joins: Sequence[str]) -> None:
        """"carry the box to the porch *to open*": a clause of purpose said with nothing after its verb
        acts on the object of the clause before, when that object is known to be what the verb's frames
        take (a box is ``openable``; a credit card is not known to be ``toggleable``: "take the card *to
        light*" stays as said) and nothing else would fill it (a frame that needs its object in hand takes
        the object of the frame before anyway, :meth:`Reference.implicit`); never for a verb of going
        ("grab the torch *to go*"). The object is borrowed: a copy that ends where it was said."""
        for k in range(1, len(clauses)):
            clause, before = clauses[k], clauses[k - 1]
            if joins[k] != "to" or clause.objects or clause.message or clause.items or not before.objects:
                continue
            thing = before.objects[0]
            frames = self.types.evoked_by(clause.unit or str(clause.verb.info))
            if not frames or any(not f.elements or f.elements[0].role == "goal" or f.needs_held() or
                                 self.types.is_a(thing.head_text, f.elements[0].type) is not True for f in frames):
                continue
            clause.objects = [replace(thing, borrowed=True)]

    def order(self, clauses: list[Clause], joins: Sequence[str]) -> list[Clause]:
        """The clauses in the order they are to be done: "turn on the lamp while holding a clock" holds
        it first, but "carry a clock while turning on a lamp" is already holding it (the one that takes
        a thing in hand comes first); "A after B", "A when done B" do B first, and a clause of B that
        leaves its object unsaid takes A's; "A; before that, B and C" (``english.DONE_BEFORE``) does B and C
        first, in their order."""
        ordered: list[Clause] = []
        first: int | None = None             # where the clauses said after "before that" go (words28)
        for clause, join in zip(clauses, joins, strict=True):
            if join in DONE_BEFORE and ordered:
                first = len(ordered) - 1     # "give me the cereal; before that, go to the table": Go first
            elif first is not None and join not in ("and", ","):
                first = None                 # "...; before that, rinse it. Then ...": in order again
            if first is not None:
                later = ordered[-1]          # the clause said before the joint, now done after
                if clause.objects and clause.objects[-1].pronoun in ("it", "them") and later.objects and \
                        not later.objects[-1].pronoun:
                    clause.objects[-1] = later.objects[-1]   # "give me the cereal; before that, find *it*"
                ordered.insert(first, clause)
                first += 1
                continue
            together = "while" in join.split() or join.split()[:1] == ["as"] and join != "as well as"
            if together and ordered and not (self.takes(ordered[-1]) and not self.takes(clause)) \
                    or (join in ("when done", "once done") or join in FIRST_LATER) and ordered:  # "A after B": B first
                if not (clause.objects or clause.message) and ordered[-1].objects and not self.goes(clause):
                    clause.objects = [ordered[-1].objects[0]]     # "put it away when done heating": it
                elif clause.objects and clause.objects[0].pronoun in ("it", "them") and ordered[-1].objects and \
                        not ordered[-1].objects[0].pronoun:
                    clause.objects[0] = ordered[-1].objects[0]    # "put the dishes away after you wash them"
                ordered.insert(len(ordered) - 1, clause)
            else:
                ordered.append(clause)
        return ordered

    def goes(self, clause: Clause) -> bool:
        """Whether the clause says only where to ("to", "into") and its verb may go there with no object (a frame of it
        has the goal first, or takes a thing in hand: "get to", :meth:`Evoker.moving`): "open the door when you *get to
        the kitchen*" (words39) — the robot goes; the object of the clause said before is not borrowed (it was "Bring
        the door to the kitchen", silently)."""
        frames = self.types.evoked_by(clause.unit or str(clause.verb.info))
        only_where = bool(clause.items) and all(isinstance(x, PP) and x.prep in ("to", "into", "onto")
                                                for x in clause.items)
        return only_where and any(f.elements and f.elements[0].role == "goal" or f.gets_held() for f in frames)

    def takes(self, clause: Clause) -> bool:
        """Whether the clause's verb takes a thing in hand (a frame of it has ``holding(theme)`` as a
        result: "hold", "carry", "pick up")."""
        return any(frame.gets_held() for frame in self.types.evoked_by(str(clause.verb.info)))

    def light_verb(self, clause: Clause) -> None:
        """"give the sauce *a quick stir*": "give" with a thing and "a" (adjectives) and a noun that is a lexical
        unit of the library is that unit's frame, done to the thing (the construction of "take a look at"):
        the clause's ``unit`` becomes the noun. A person keeps "give" ("give me a hand"). A noun used mostly as a
        verb (WordNet's counts, :func:`~seal_cli.language.verb_usage.mostly_verb`) that no frame has is refused
        at the noun ("give the floor a quick *sweep*"): an action asked, not a floor given a thing."""
        if str(clause.verb.info) not in LIGHT_VERBS:
            return
        places = [item for item in clause.items[:-1] if isinstance(item, PP) and item.prep in LOCATIVE]
        if len(clause.objects) == 1 and clause.items and isinstance(clause.items[-1], NP) and \
                len(places) == len(clause.items) - 1:          # "give the plants *on the sill* a rinse"
            thing, act, after = clause.objects[0], clause.items[-1], clause.items[:-1]
        elif len(clause.objects) == 2:
            thing, act, after = *clause.objects, clause.items
        else:
            return
        if thing.kind == "person" or act.head is None or act.head.tag != "WORD" or act.of is not None or \
                act.plural or act.quantity is not None or act.relative or \
                self.text[act.start:act.end].split(None, 1)[0].lower() not in ("a", "an", "another"):
            return
        unit = act.head.lower
        frames = self.types.evoked_by(unit)
        if not frames and mostly_verb(unit) and unit not in self.library.taxonomy.known_classes:
            can = list(dict.fromkeys(f.lexical_units[0].text for f in self.library.frames if f.lexical_units))
            said = self.text[clause.verb.start:act.end]
            raise CommandError(f"{said!r} asks to {unit} {self.text[thing.start:thing.end]!r}, and no frame of the "
                               f"library does '{unit}'; the robot can {', '.join(can[:-1])} or {can[-1]}",
                               act.head.start + 1, self.text, ["an action the robot can do"])
        if not frames or not all(f.elements and not self.types.is_person(f.elements[0].type) for f in frames):
            return
        clause.objects = [thing]
        clause.items = after
        clause.unit = unit


def _copy(np: NP) -> NP:
    """The first conjunct of a coordination: the phrase as it was, without the others."""
    return replace(np, conjuncts=[])


def _to_person(item: Item) -> bool:
    """A "to"/"for" phrase naming a person (or a pronoun): whom a message is for."""
    return isinstance(item, PP) and item.prep in ("to", "for") and item.np.kind in ("person", "pronoun")
