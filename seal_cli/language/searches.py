"""A search asked, then said again as a command: one search; a search said again as the condition of its success
(words25): one search.

"Whereabouts is the tea spoon? Look in the living room", "is anyone in the garage? find them": a question that
asks to find something (Find, said with "?") and, right after it, a command to search again for nothing else
(its theme unsaid, or a pronoun that stands for the question's theme) say one search, not two. The command's
elements fill what the question left unsaid (where to look), and what later frames refer to in either frame
is the one search. Two commands ("find the cup, then look in the kitchen") stay two frames: only a question
and the command that answers it are merged.

"Look for my keys in the living room, and *if you find them*, bring them here", "look for the cat and tell me *if
you find it*": finding, said after a subordinator and "you" with a pronoun for what an earlier search seeks, is
whether that search succeeds, not a second search: the Find is dropped (:func:`drop_found_again`); when it was
told ("tell me if you | find it"), the told message is the whole condition.
"""

from __future__ import annotations

from dataclasses import replace

from seal_cli.language.values import Evoked, Parse, Phrase

SEARCH = "Find"
"""The frame of searching, which a question asks and a command may say again."""


def merge_searches(parse: Parse) -> Parse:
    """The parse with each question of searching and the command to search again right after it made one."""
    frames = list(parse.frames)
    k = 0
    while k + 1 < len(frames):
        asked, again = frames[k], frames[k + 1]
        if _asked(parse.text, asked) and again.frame == SEARCH and asked.frame == SEARCH and \
                _same_theme(again, k) and not (set(asked.elements) & set(again.elements) - {"theme"}):
            merged = {**asked.elements, **{r: p for r, p in again.elements.items() if r != "theme"}}
            frames[k] = replace(asked, elements=merged)
            del frames[k + 1]
            frames = [renumbered(f, k + 1) for f in frames]
        k += 1
    return replace(parse, frames=tuple(frames)) if len(frames) != len(parse.frames) else parse


_ON_FINDING = ("if you", "when you", "once you", "as soon as you", "whether you", "if you can")
"""What is said right before finding when it is the condition of an earlier search's success."""


def drop_found_again(parse: Parse) -> Parse:
    """The parse without each Find said as the condition of an earlier search's success (module docstring)."""
    frames = list(parse.frames)
    text = parse.text
    k = 1
    while k < len(frames):
        again = frames[k]
        theme = again.elements.get("theme")
        before = " ".join(text[:again.span[0]].lower().replace(",", " ").split())
        ref = theme.refers_to if theme is not None else None
        if again.frame != SEARCH or ref is None or ref[1] != "theme" or ref[0] >= k or \
                frames[ref[0]].frame != SEARCH or set(again.elements) != {"theme"} or \
                not any(before.endswith(p) for p in _ON_FINDING):
            k += 1
            continue
        told = frames[k - 1]
        message = told.elements.get("message")
        said = message.span if message is not None else None
        if message is not None and message.text is not None and said is not None and \
                any(" ".join(message.text.lower().split()) == p for p in _ON_FINDING):
            whole = text[said[0]:again.span[1]]   # "tell me if you | find it": the message is the condition
            frames[k - 1] = replace(told, elements={**told.elements, "message": replace(
                message, text=whole, head=whole, span=(said[0], again.span[1]))},
                span=(told.span[0], max(told.span[1], again.span[1])))
        del frames[k]
        frames = [renumbered(f, k) for f in frames]
    return replace(parse, frames=tuple(frames)) if len(frames) != len(parse.frames) else parse


def _asked(text: str, frame: Evoked) -> bool:
    """Whether the frame was asked: its words end at a question mark."""
    return text[frame.span[1]:].lstrip().startswith("?")


def _same_theme(again: Evoked, index: int) -> bool:
    """Whether the command seeks nothing of its own: no theme, or a pronoun for the question's theme."""
    theme = again.elements.get("theme")
    return theme is None or theme.refers_to == (index, "theme")


def renumbered(frame: Evoked, gone: int) -> Evoked:
    """The frame with references to the merged frame ``gone`` made to the one before it, later ones one less."""
    def moved(p: Phrase) -> Phrase:
        if p.refers_to is None or p.refers_to[0] < gone:
            return p
        index = p.refers_to[0] - 1
        return replace(p, refers_to=(index, p.refers_to[1]))
    return replace(frame, elements={r: moved(p) for r, p in frame.elements.items()})
