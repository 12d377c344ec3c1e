"""Where the user says a thing is, in a statement beside the command: "Locate the towel, *it's in the dining room*".

The parser keeps a statement said beside the command as a remark (:attr:`Parse.remarks
<seal_cli.language.values.Parse.remarks>`); a remark must never lose what it tells. English tells where a thing
is with a copular sentence whose subject is the thing — a pronoun ("it", "they", "that", "she") or the thing's own
noun ("the towel") — a form of "be" (``'s``, ``'re``, is, are), maybe a hedge ("probably", "usually", "still")
and a place said with a preposition of being in or on it (:data:`~seal_cli.language.english.LOCATED`): "it's in
the dining room", "they are probably in the kitchen", "the remote is on the sofa". Such a statement about the
theme of the frame said before it tells where that thing is: the frame's ``ground`` when it has one unsaid
(Find, Count: where to look), else its ``source`` (Pick, Bring: where it is taken from), as if said with the
thing ("find the towel in the dining room"). A statement about another thing, or a frame with where already
said, is left as a remark.
"""

from __future__ import annotations

import re
from dataclasses import replace

from seal_cli.frames.library import Library
from seal_cli.language.english import LOCATED
from seal_cli.language.values import Evoked, Parse, Phrase

__all__ = ["told_where"]

PRONOUNS = frozenset({"it", "they", "that", "those", "these", "this", "he", "she"})
"""Subjects that stand for the thing said before."""

HEDGES = r"(?:(?:probably|maybe|perhaps|usually|still|now|already|just)\s+)?"

STATEMENT = re.compile(
    r"^\s*(?:(?P<contracted>it|they|that|he|she)\s*['’](?:s|re)|(?P<subject>[a-z' ]+?)\s+(?:is|are))\s+" + HEDGES
    + r"(?P<preposition>" + "|".join(LOCATED) + r")\s+(?P<place>[a-z][a-z' ]*?)\s*[.!]?\s*$", re.IGNORECASE)
"""A statement of where a thing is: its subject, the preposition and the place."""

ARTICLES = frozenset({"the", "a", "an", "my", "our", "your", "his", "her", "their"})


def told_where(parse: Parse, library: Library) -> Parse:
    """The parse with each remark that tells where the thing of the frame before it is made that frame's
    ``ground`` or ``source`` (the module docstring); unchanged when no remark does."""
    frames, remarks = list(parse.frames), []
    for remark in parse.remarks:
        said = STATEMENT.match(remark)
        at = parse.text.find(remark)
        before = [k for k, f in enumerate(frames) if f.span is not None and f.span[1] <= at]
        role = None if said is None or not before else _role(frames[before[-1]], said, library)
        if role is None or said is None:
            remarks.append(remark)
            continue
        k = before[-1]
        place = said.group("place")
        start = at + said.start("place")
        words = place.split()
        phrase = Phrase(place, words[-1].lower(), modifiers=tuple(w.lower() for w in words[:-1]
                                                                  if w.lower() not in ARTICLES),
                        span=(start, start + len(place)), preposition=said.group("preposition").lower())
        frames[k] = replace(frames[k], elements={**frames[k].elements, role: phrase})
    if len(remarks) == len(parse.remarks):
        return parse
    return replace(parse, frames=tuple(frames), remarks=tuple(remarks))


def _role(evoked: Evoked, said: re.Match[str], library: Library) -> str | None:
    """The element a statement fills on the frame before it: ``ground``, else ``source``, unsaid; None when the
    statement is about another thing or where is said already."""
    theme = evoked.elements.get("theme")
    if theme is None or not theme.text:
        return None
    subject = (said.group("contracted") or said.group("subject") or "").lower().split()
    if not (subject and (subject == [subject[0]] and subject[0] in PRONOUNS or subject[-1] in
                         {w.lower() for w in theme.text.split()} | {theme.head.lower()})):
        return None
    roles = library.frame(evoked.frame).roles
    for role in ("ground", "source"):
        if role in roles:
            return None if role in evoked.elements else role
    return None
