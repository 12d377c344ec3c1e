"""How a parse is shown: a rich tree of its frames and elements, one line of it, or JSON.

Imports no command-line framework: ``seal parse TEXT`` prints through :func:`print_parse` with typer
(:mod:`~seal_cli.cli.parse_cmd`) or without it (:func:`seal_cli.cli.main`), the same way.
"""

from __future__ import annotations

from typing import TYPE_CHECKING, Any

from seal_cli.cli.output import emit_json, out
from seal_cli.errors import SealError

if TYPE_CHECKING:
    from seal_cli.frames.library import Library
    from seal_cli.language.grounding import Vocabulary
    from seal_cli.language.parser import Parse

__all__ = ["print_parse", "summary", "tree"]


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
        out.print(tree(parsed))
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

    root = Tree(f"[bold]{escape(parsed.text)}[/bold]")
    for index, frame in enumerate(parsed.frames):
        a, b = frame.span
        branch = root.add(f"[bold cyan]{index}. {frame.frame}[/bold cyan]  [dim]'{escape(frame.lexical_unit)}' "
                          f"· {escape(parsed.text[a:b])!s}[/dim]")
        for role, phrase in frame.elements.items():
            facts = [f"head [green]{escape(phrase.head)}[/green]"]
            if phrase.cls:
                facts.append(f"class [magenta]{escape(phrase.cls)}[/magenta]")
            if phrase.kind != "thing":
                facts.append(phrase.kind)
            if phrase.quantity is not None:
                facts.append(f"×{phrase.quantity}")
            if phrase.refers_to is not None:
                facts.append(f"→ frame {phrase.refers_to[0]} {phrase.refers_to[1]}")
            if phrase.default:
                facts.append("default")
            said = escape(phrase.text) if phrase.text else "[dim](unsaid)[/dim]"
            branch.add(f"[yellow]{role}[/yellow]: {said}  [dim]{' · '.join(facts)}[/dim]")
    return root
