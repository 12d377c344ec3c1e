"""Reading composed YAML nodes with the position of every value.

Frame files, maps and observation files are all read the same way: YAML is *composed* (not
loaded), so every node still knows its line and column, and a reader walks the nodes, turning
each mistake into a :class:`~seal_cli.errors.SealError` at the node's position instead of
stopping at the first. :class:`NodeReader` holds that shared walk; the readers of each format
extend it with what their format means.
"""

from __future__ import annotations

import difflib
from collections.abc import Callable, Iterable, Iterator
from typing import TypeVar

import yaml

from seal_cli.errors import SealError, Where

__all__ = ["MAX_VALUES", "NodeReader", "check_size", "clipped", "count_values", "is_null", "shape", "suggest"]

T = TypeVar("T")

NULL = "tag:yaml.org,2002:null"


MAX_VALUES = 1_000_000
"""The most values a YAML file may hold once its aliases are expanded (``*anchor`` repeats the
whole anchored value): a file that expands beyond is refused before it is read."""


def check_size(root: yaml.Node | None, file: str, limit: int = MAX_VALUES) -> None:
    """Refuse a composed file whose values, aliases expanded, number more than ``limit``; linear
    in the distinct nodes (each anchored node's expanded size is counted once and reused)."""
    if root is None:
        return
    sizes: dict[int, int] = {}
    open_: set[int] = set()  # on the path from the root: met again, an alias holds itself
    stack: list[tuple[yaml.Node, bool]] = [(root, False)]
    while stack:  # children before parents, each distinct node once, without recursion
        node, finished = stack.pop()
        if finished:
            sizes[id(node)] = min(1 + sum(sizes[id(c)] for c in _children(node)), limit + 1)
            open_.discard(id(node))
            continue
        if id(node) in sizes:
            continue
        if id(node) in open_:
            raise SealError("an alias (*name) refers to a value that holds it: the value would be endless",
                            Where(file, node.start_mark.line + 1, node.start_mark.column + 1))
        open_.add(id(node))
        stack.append((node, True))
        stack.extend((child, False) for child in _children(node))
    if sizes[id(root)] > limit:
        raise SealError(f"this file holds more than {limit:,} values once its aliases (*name) are expanded; "
                        "seal reads at most that many", Where(file))


def count_values(text: str, loader: type[yaml.SafeLoader], file: str, limit: int, what: str = "file") -> None:
    """Refuse ``text`` if it holds more than ``limit`` values (scalars, aliases, lists and mappings), at the
    line and column of the first one past the bound: the parser's events are streamed and counted, nothing
    is built (about a third of the time of composing the file)."""
    parser = loader(text)
    try:
        count = 0
        while parser.check_event():
            event = parser.get_event()
            if isinstance(event, yaml.NodeEvent):
                count += 1
                if count > limit:
                    mark = event.start_mark
                    raise SealError(f"this {what} holds more than {limit:,} values; seal reads at most that many",
                                    Where(file, mark.line + 1, mark.column + 1) if mark else Where(file))
    finally:
        parser.dispose()


def _children(node: yaml.Node) -> list[yaml.Node]:
    if isinstance(node, yaml.SequenceNode):
        return list(node.value)
    if isinstance(node, yaml.MappingNode):
        return [n for pair in node.value for n in pair]
    return []


def is_null(node: yaml.Node) -> bool:
    """An empty value (``~``, ``null`` or nothing at all)."""
    return isinstance(node, yaml.ScalarNode) and node.tag == NULL


def shape(node: yaml.Node) -> str:
    """What a node is, for a message: "a mapping", "a list", "nothing" or the value itself."""
    if isinstance(node, yaml.MappingNode):
        return "a mapping"
    if isinstance(node, yaml.SequenceNode):
        return "a list"
    if is_null(node):
        return "nothing"
    return clipped(repr(node.value))


def clipped(text: str, most: int = 60) -> str:
    """``text`` cut to ``most`` characters with "…" (a value of 5,000 digits in a message reads as its start)."""
    return text if len(text) <= most else text[:most - 1] + "…"


def suggest(word: str, choices: Iterable[str]) -> str:
    """`` (did you mean 'x'?)`` for the closest choice, or nothing."""
    close = difflib.get_close_matches(word, [c for c in choices if c != word], n=1)
    return f" (did you mean {close[0]!r}?)" if close else ""


class NodeReader:
    """Positions, problems and the common shapes of values, for one YAML file."""

    def __init__(self, text: str, file: str) -> None:
        self.file = file
        self.lines = text.splitlines()
        self.problems: list[SealError] = []

    def where(self, node: yaml.Node) -> Where:
        return Where(self.file, node.start_mark.line + 1, node.start_mark.column + 1)

    def problem(self, message: str, node: yaml.Node | None = None, where: Where | None = None) -> None:
        """Record a problem at ``where``, else at the node, else at the file; with its source line."""
        where = where or (self.where(node) if node is not None else Where(self.file))
        line = self.lines[where.line - 1] if where.line and where.line <= len(self.lines) else None
        self.problems.append(SealError(message, where, source_line=line))

    def build(self, make: Callable[[], T], node: yaml.Node) -> T | None:
        """Build a value object; a SealError it raises becomes a problem (at its own position if it
        has one, else at ``node``)."""
        try:
            return make()
        except SealError as exc:
            for problem in getattr(exc, "problems", None) or [exc]:
                self.problem(problem.message, node, problem.where if problem.where.line else None)
            return None

    def string(self, node: yaml.Node, what: str) -> str | None:
        """A single non-empty value, as text."""
        if isinstance(node, yaml.ScalarNode) and not is_null(node) and str(node.value).strip():
            return str(node.value)
        self.problem(f"{what} must be a single value, not {shape(node)}", node)
        return None

    def items(self, node: yaml.Node, what: str, *, single: bool = False) -> list[yaml.Node]:
        """A list's items; nothing is an empty list, and with ``single`` one value is a list of one."""
        if isinstance(node, yaml.SequenceNode):
            return list(node.value)
        if is_null(node):
            return []
        if single and isinstance(node, yaml.ScalarNode):
            return [node]
        self.problem(f"{what} must be a list, not {shape(node)}", node)
        return []

    def pairs(self, node: yaml.Node, what: str, allowed: tuple[str, ...] | None = None, *,
              empty: bool = False) -> Iterator[tuple[str, yaml.Node, yaml.Node]]:
        """A mapping's (key, key node, value node); unknown and repeated keys are problems. With
        ``empty``, nothing at all is an empty mapping rather than a problem."""
        if empty and is_null(node):
            return
        if not isinstance(node, yaml.MappingNode):
            self.problem(f"{what} must be a mapping, not {shape(node)}", node)
            return
        seen: set[str] = set()
        for key_node, value_node in node.value:
            key = self.string(key_node, "a key")
            if key is None:
                continue
            if key in seen:
                self.problem(f"{what} repeats the key {key!r}", key_node)
                continue
            seen.add(key)
            if allowed is not None and key not in allowed:
                self.problem(f"unknown key {key!r} in {what}{suggest(key, allowed)}; "
                             f"known keys are {', '.join(allowed)}", key_node)
                continue
            yield key, key_node, value_node
