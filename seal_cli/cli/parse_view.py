"""How a parse is shown: a rich tree of its frames and elements, one line of it, or JSON.

Imports no command-line framework: ``seal parse TEXT`` prints through :func:`print_parse` with typer
(:mod:`~seal_cli.cli.parse_cmd`) or without it (:func:`seal_cli.cli.main`), the same way.
"""

from __future__ import annotations

import sys
from collections.abc import Callable
from typing import TYPE_CHECKING, Any

from seal_cli.cli.output import PIPE_WIDTH, emit_json, out
from seal_cli.errors import SealError

if TYPE_CHECKING:
    from seal_cli.frames.library import Library
    from seal_cli.language.grounding import Vocabulary
    from seal_cli.language.parser import Parse

__all__ = ["plain_tree", "print_parse", "summary", "tree"]


def print_parse(text: str, library: Library | None, vocabulary: Vocabulary | None, as_json: bool) -> int:
    """Parse one command and print it (a tree, or JSON with ``as_json``); the exit code. A command that
    cannot be parsed is an error: with ``as_json`` a JSON object with its ``error`` on stdout and exit
    code 1, else raised (a message on stderr). ``library`` None is the standard library."""
    from seal_cli.frames.reading import load_library
    from seal_cli.language.parser import parse_command

    if library is None:
        library = load_library()
    try:
        parsed = parse_command(text, library, vocabulary)
    except SealError as error:
        if as_json:
            from seal_cli.language.parser import _error_json

            emit_json({"text": text, "error": _error_json(error)})
            return 1
        raise
    if as_json:
        emit_json(parsed.to_json())
    else:
        plain = plain_tree(parsed) if out.plain() else None
        if plain is None:
            out.print(tree(parsed))
        else:
            sys.stdout.write(plain)
    return 0


def _escape(text: str) -> str:
    from rich.markup import escape

    return escape(text)


def summary(result: dict[str, Any]) -> str:
    """``Bring(theme=coffee, recipient=Roger) Place(...)``: a parse on one line."""
    parts = []
    for frame in result["frames"]:
        inner = ", ".join(f"{role}={e.get('class') or e['head']}" for role, e in frame["elements"].items())
        parts.append(f"{frame['frame']}({inner})")
    return " ".join(parts)


def tree(parsed: Parse) -> Any:
    """The parse as a rich tree: frames, their elements, and what each element is."""
    from rich.markup import escape
    from rich.tree import Tree

    root_label, frames = _outline(parsed, escape, lambda style, text: f"[{style}]{text}[/{style}]")
    root = Tree(root_label)
    for label, elements in frames:
        branch = root.add(label)
        for element in elements:
            branch.add(element)
    return root


def plain_tree(parsed: Parse) -> str | None:
    """The lines rich prints for :func:`tree` on a console without colours (:meth:`LazyConsole.plain`),
    made without importing rich; None when rich could print them otherwise (a ':' of an emoji code, a
    tab or control character, a character beyond Latin whose width in columns rich decides, a line
    longer than the console is wide), which rich then prints."""
    said = [parsed.text]
    for frame in parsed.frames:
        said += [frame.frame, frame.lexical_unit]
        for role, phrase in frame.elements.items():
            said += [role, phrase.head, phrase.cls or "", phrase.kind, phrase.text or ""]
        said.append(frame.condition or "")
    if any(":" in text or not text.isprintable() or max(text, default=" ") >= "\u0300" for text in said):
        return None  # an emoji code, a tab or control character, a character maybe not one column wide
    root_label, frames = _outline(parsed, str, lambda style, text: text)
    lines = [root_label]
    for index, (label, elements) in enumerate(frames):
        last = index == len(frames) - 1
        lines.append(("└── " if last else "├── ") + label)
        for number, element in enumerate(elements):
            lines.append(("    " if last else "│   ") + ("└── " if number == len(elements) - 1 else "├── ") + element)
    if any(len(line) > PIPE_WIDTH for line in lines):
        return None  # rich crops a line to the console's width
    return "".join(line + "\n" for line in lines)


def _outline(parsed: Parse, escape: Callable[[str], str],
             tag: Callable[[str, str], str]) -> tuple[str, list[tuple[str, list[str]]]]:
    """The tree's labels: the root's, and each frame's with its elements'; ``escape`` and ``tag``
    (a style, text) make them rich markup or plain text."""
    frames = []
    for index, frame in enumerate(parsed.frames):
        a, b = frame.span
        label = (tag("bold cyan", f"{index}. {frame.frame}") + "  "
                 + tag("dim", f"'{escape(frame.lexical_unit)}' · {escape(parsed.text[a:b])!s}"))
        if frame.inferred is not None:
            label += "  " + tag("dim", f"(inferred, {frame.inferred:.2f}: not said)")
        elements = []
        for role, phrase in frame.elements.items():
            facts = ["head " + tag("green", escape(phrase.head))]
            if phrase.cls:
                facts.append("class " + tag("magenta", escape(phrase.cls)))
            if phrase.kind != "thing":
                facts.append(phrase.kind)
            if phrase.quantity is not None:
                facts.append(f"×{phrase.quantity}")
            if phrase.refers_to is not None:
                facts.append(f"→ frame {phrase.refers_to[0]} {phrase.refers_to[1]}")
            if phrase.default:
                facts.append("default")
            said = escape(phrase.text) if phrase.text else tag("dim", "(unsaid)")
            elements.append(tag("yellow", role) + f": {said}  " + tag("dim", " · ".join(facts)))
        if frame.condition:
            elements.append(tag("yellow", "condition") + f": {escape(frame.condition)}")
        if frame.asked:
            elements.append(tag("yellow", "asked") + f": {escape(frame.asked)}")   # "is the fridge open?"
        frames.append((label, elements))
    return tag("bold", escape(parsed.text)), frames
