"""A verb with a particle that makes it another verb: "hang *up* the phone" is no hanging of the phone.

A lexical unit may name the particles with which its verb is a verb of its own (``apart`` in the
unit's entry, derived from PropBank's phrasal rolesets by ``scripts/build_lexical_units.py``:
``hang_up.03`` "terminate a phone call", ``tuck_in.03`` "put your shirt in your pants", none of them
linked to the frame's FrameNet frame). Said right after the verb ("hang up the phone", "tuck in the
kids") or ending its clause ("hang the phone up"), with no place said in the clause, the particle
makes the verb that other verb, which no frame of the library has: the command is refused at the
verb, never read as the unit's frame. With a place said ("hang up the coat *on the hook*") the verb
is the unit's own: the phrasal senses say where nothing goes.
"""

from __future__ import annotations

from collections.abc import Sequence

from seal_cli.language.english import NOT_PLACES
from seal_cli.language.lexicon import Lexicon
from seal_cli.language.tags import Tag
from seal_cli.language.tokens import Word

__all__ = ["phrasal_verb"]

_CLAUSE_ENDS = frozenset({Tag.SEP, Tag.END, Tag.VERB})


def phrasal_verb(words: Sequence[Word], lexicon: Lexicon) -> tuple[Word, Word] | None:
    """The first verb (a tagged word) whose particle makes it a verb no frame has, with that particle; None when
    there is none."""
    if not lexicon.apart:
        return None
    for i, verb in enumerate(words):
        particles = lexicon.apart.get(str(verb.info)) if verb.tag == Tag.VERB else None
        if not particles:
            continue
        end = next((k for k in range(i + 1, len(words)) if words[k].tag in _CLAUSE_ENDS), len(words))
        clause = words[i + 1:end]
        if not clause:
            continue
        first, last = clause[0], clause[-1]
        if first.tag in (Tag.PARTICLE, Tag.PREP) and first.lower in particles:
            particle = first
        elif last.tag == Tag.PARTICLE and last.lower in particles:
            particle = last
        else:
            continue
        if any(w.tag == Tag.PREP and w is not particle and str(w.info) not in NOT_PLACES for w in clause) and \
                not (particle is first and len(clause) > 1 and clause[1].tag == Tag.PREP):
            continue                              # "hang up the coat on the hook": where it goes, the unit's own
            # (not with no thing said: "hang on in the hall" is waiting there, no hanging, words34)
        return verb, particle
    return None
