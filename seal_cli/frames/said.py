"""What is said, as words: a message's or question's name in a plan turned back into what a user reads.

A plan grounds what is said ("ask Anna what's in the fridge") to a name like every other element
(``what_s_in_the_fridge``: the words' letters and digits joined by ``_``), because facts (``told(x)``)
take names. A plan line shown to a user should say the words, not the name (e2e22):
``Tell(message="what's in the fridge?", recipient=anna)``. The name keeps no punctuation, so two
general rules of English bring it back:

- a clitic split off at its apostrophe is joined again: ``what s`` is "what's", ``don t`` "don't"
  (``n't``: the ``n`` stays with its verb), ``you re`` "you're", ``we ll``, ``they ve``, ``i d``,
  ``i m`` — a lone ``s``, ``t``, ``re``, ``ll``, ``ve``, ``d`` or ``m`` after a word is no word of its
  own in a sentence a user says to a robot (``vitamin d`` would read "vitamin'd": a known limit);
- a sentence opened by a wh-word or by an auxiliary verb in front of its subject is a question
  ("do you want tea?", "where is the stapler?"), and is shown with its question mark; "dinner is
  ready" stays a statement.

``str(binding)`` keeps the names (``--json``, the suites and every test compare them): only what is
printed for a user (``seal plan``'s table, ``seal run``'s narration) shows :func:`shown`.
"""

from __future__ import annotations

from collections.abc import Collection, Iterable

from seal_cli.frames.model import Binding, Fact

__all__ = ["SAID_TYPES", "is_question", "quoted", "said_names", "said_words", "shown", "shown_elements", "shown_fact"]

SAID_TYPES = frozenset({"message", "question"})
"""The element types whose values are what is said, not things."""

CLITICS = frozenset({"s", "t", "re", "ll", "ve", "d", "m"})
"""What English writes after an apostrophe, split off from its word by the name: "what's", "don't", "we'll"."""

WH_WORDS = frozenset({"what", "where", "when", "who", "whom", "whose", "which", "why", "how"})
AUXILIARIES = frozenset({"do", "does", "did", "is", "are", "was", "were", "am", "can", "could", "will", "would",
                         "shall", "should", "may", "might", "must", "have", "has", "had", "isn", "aren", "don",
                         "doesn", "didn", "won", "wouldn", "couldn", "shouldn", "hasn", "haven"})
"""The words that open a question: wh-words, and auxiliaries put in front of the subject ("do you ...?",
"isn't it ...?": ``isn`` is the auxiliary's part before its ``'t``)."""


def said_words(name: str) -> str:
    """The words of a said name: ``what_s_in_the_fridge`` "what's in the fridge", ``don_t_wait`` "don't
    wait", ``dinner_is_ready`` "dinner is ready"; a name with no word (``_``) is given back as it is."""
    words = [w for w in name.split("_") if w]
    if not words:
        return name
    out: list[str] = [words[0]]
    for word in words[1:]:
        if word.lower() in CLITICS:
            out[-1] = f"{out[-1]}'{word}"
        else:
            out.append(word)
    return " ".join("I" + w[1:] if w.lower() == "i" or w.lower().startswith("i'") else w for w in out)


def is_question(words: str) -> bool:
    """Whether words said open as a question does: a wh-word, or an auxiliary before its subject."""
    first = words.split()[0].split("'")[0].lower() if words.split() else ""
    return first in WH_WORDS or first in AUXILIARIES


def quoted(name: str) -> str:
    """A said name as a user reads it: its words quoted, with the question mark of a question
    (``do_you_want_tea``: ``"do you want tea?"``)."""
    words = said_words(name)
    return '"' + words + ("?" if is_question(words) else "") + '"'


def shown_elements(binding: Binding) -> list[tuple[str, str]]:
    """The filled elements in the frame's role order, what is said quoted as words (``message``,
    ``"do you want tea?"``); every other value its name."""
    parts = []
    for role, value in sorted(binding.values, key=lambda kv: binding.frame.roles.index(kv[0])):
        if binding.frame.element(role).type in SAID_TYPES:
            value = quoted(value)
        parts.append((role, value))
    return parts


def said_names(bindings: Iterable[Binding]) -> frozenset[str]:
    """The names that are what is said in these steps (the values of their message and question elements)."""
    return frozenset(value for b in bindings for role, value in b.values
                     if b.frame.element(role).type in SAID_TYPES)


def shown_fact(fact: Fact, said: Collection[str]) -> str:
    """A fact as a user reads it: an argument that is what a step says (one of ``said``, from
    :func:`said_names`) quoted as words — ``told("what's in the fridge?")``, not ``told(what_s_in_the_fridge)``
    (e2e23: ``seal plan``'s ``goal:`` line); every other argument its name."""
    if not any(a in said for a in fact.args):
        return str(fact)
    atom = f"{fact.predicate}({', '.join(quoted(a) if a in said else a for a in fact.args)})"
    return f"not {atom}" if fact.negated else atom


def shown(binding: Binding) -> str:
    """A step as a user reads it: ``str(binding)`` with what is said quoted as words
    (``Tell(message="do you want tea?", recipient=raj)``)."""
    return f"{binding.frame.name}({', '.join(f'{role}={value}' for role, value in shown_elements(binding))})"
