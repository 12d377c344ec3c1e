"""Reading composed YAML nodes with the position of every value.

Frame files, maps and observation files are all read the same way: YAML is *composed* (not
loaded), so every node still knows its line and column, and a reader walks the nodes, turning
each mistake into a :class:`~seal_cli.errors.SealError` at the node's position instead of
stopping at the first. :class:`NodeReader` holds that shared walk; the readers of each format
extend it with what their format means.
"""

from __future__ import annotations

import copy
import difflib
from collections.abc import Callable, Iterable, Iterator, Sequence
from typing import Any, TypeVar

import yaml

from seal_cli.errors import SealError, Where

__all__ = ["MAX_VALUES", "NodeReader", "check_size", "clipped", "count_values", "is_null", "merge_keys",
           "place_aliases", "shape", "suggest"]

T = TypeVar("T")

NULL = "tag:yaml.org,2002:null"
MERGE = "tag:yaml.org,2002:merge"


CORE = "tag:yaml.org,2002:"
READ_TAGS = frozenset(CORE + name for name in ("null", "bool", "int", "float", "str", "timestamp", "merge", "seq",
                                               "map"))
"""The tags a composed file's nodes may carry: the ones YAML gives a plain value itself. Any other was written in the
file (``!!binary``, ``!!set``, ``!!python/object/apply:...``, a local ``!mine``) and asks for a reading seal's
readers do not give: refused at its node (hostile29: each was passed over, ``name: !!binary bGFi`` read as the text
``bGFi``)."""

MAX_VALUES = 1_000_000
"""The most values a YAML file may hold once its aliases are expanded (``*anchor`` repeats the
whole anchored value): a file that expands beyond is refused before it is read."""


TAG_SAYS = {CORE + "int": "an integer", CORE + "float": "a number", CORE + "bool": "true or false",
            CORE + "null": "nothing (null, ~ or no value at all)", CORE + "timestamp": "a date",
            CORE + "merge": "a merge key (<<)", CORE + "seq": "a list", CORE + "map": "a mapping"}
"""What each of YAML's own tags says its value is, for a value written with a tag that does not fit it."""


def check_size(root: yaml.Node | None, file: str, limit: int = MAX_VALUES, lines: Sequence[str] = ()) -> None:
    """Refuse a composed file whose values, aliases expanded, number more than ``limit``, or that holds a tag of
    none of :data:`READ_TAGS`; linear in the distinct nodes (each anchored node's expanded size is counted once and
    reused). With the file's ``lines`` (split at YAML's line breaks), a tag of YAML's own written in the file is read
    as YAML defines it (:func:`_written_tag`)."""
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
        if node.tag not in READ_TAGS:
            raise SealError(f"the tag {_tag(node.tag)} asks for a value seal does not read: leave the tag out",
                            Where(file, node.start_mark.line + 1, node.start_mark.column + 1))
        if lines and _tagged(node, lines):
            _written_tag(node, file)
        open_.add(id(node))
        stack.append((node, True))
        stack.extend((child, False) for child in _children(node))
    if sizes[id(root)] > limit:
        past = _past_bound(root, sizes, limit)
        raise SealError(f"this file holds more than {limit:,} values once its aliases (*name) are expanded; "
                        "seal reads at most that many",
                        Where(file, past.start_mark.line + 1, past.start_mark.column + 1))


def _tagged(node: yaml.Node, lines: Sequence[str]) -> bool:
    """Whether the node's tag is written in the file (``!!str 5``, ``&a !!int 7``), not the one YAML gives a plain
    value: a node starts at its anchor or its tag (the composed node keeps no other trace of it)."""
    mark = node.start_mark
    rest = lines[mark.line][mark.column:] if mark.line < len(lines) else ""
    if rest.startswith("&"):
        rest = rest.split(None, 1)[1] if len(rest.split(None, 1)) == 2 else ""
    return rest.startswith("!")


def _written_tag(node: yaml.Node, file: str) -> None:
    """A value tagged with one of YAML's own tags (hostile30), read as YAML defines the tag: ``!!str`` makes a plain
    value text, as quotes do (``resolution: !!str 0.05`` is the text "0.05", refused where a number goes; it was read
    as the number); every other tag must fit what it tags (``!!float 1`` is the number 1.0, ``!!int lab``,
    ``!!bool 0`` or ``!!seq {a: 1}`` are refused at the value: the name was read as "lab", and ``!!bool 0`` was a
    KeyError traceback)."""
    tag, says = node.tag, TAG_SAYS.get(node.tag)
    if tag == CORE + "str" and isinstance(node, yaml.ScalarNode):
        if not node.style:
            node.style = "'"  # as if quoted: text, never a number read from it
        return
    if says is None or _fits(node):
        return
    raise SealError(f"the tag {_tag(tag)} says the value is {says}, but it is {shape(node)}: "
                    f"leave the tag out, or write {says}",
                    Where(file, node.start_mark.line + 1, node.start_mark.column + 1))


def _fits(node: yaml.Node) -> bool:
    """Whether a node is what its tag (one of :data:`TAG_SAYS`) says: a list for ``!!seq``, a mapping for ``!!map``,
    else a value YAML would read as that tag's kind by itself (a float also from an integer, or from what Python
    reads as one: ``!!float 1e-3``)."""
    if node.tag == CORE + "seq":
        return isinstance(node, yaml.SequenceNode)
    if node.tag == CORE + "map":
        return isinstance(node, yaml.MappingNode)
    if not isinstance(node, yaml.ScalarNode):
        return False
    plain = yaml.resolver.Resolver().resolve(yaml.ScalarNode, node.value, (True, False))
    if node.tag == CORE + "float" and plain != CORE + "float":
        try:
            float(node.value.replace("_", ""))
        except ValueError:
            return plain == CORE + "int"
        return True
    return bool(plain == node.tag)


def _tag(tag: str) -> str:
    """A tag as it is written: ``!!binary`` for YAML's own, ``!mine`` for a local one, clipped."""
    return clipped("!!" + tag.removeprefix(CORE) if tag.startswith(CORE) else tag if tag.startswith("!") else
                   f"!<{tag}>")


def _past_bound(root: yaml.Node, sizes: dict[int, int], limit: int) -> yaml.Node:
    """Where the values of a file too large once expanded pass ``limit``: from the root, the child (in the order
    written) that brings the count past it, down to a value made of aliases (a child met twice: a "billion laughs"
    line ``&l8 [*l7, *l7, ...]``) or of none (hostile26: the refusal named the file only)."""
    node, budget = root, limit
    while True:
        children = list(_children(node))
        if not children or len({id(c) for c in children}) < len(children):
            return node
        count = 1
        for child in children:
            if count + sizes[id(child)] > budget:
                break
            count += sizes[id(child)]
        else:
            return node
        node, budget = child, budget - count


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


def place_aliases(roots: Sequence[yaml.Node | None], text: str, loader: type[yaml.SafeLoader]) -> None:
    """Give each alias (``*name``) of the composed ``roots`` a node of its own, at the alias's line and column.

    PyYAML's composer puts the anchored node itself where an alias stands, so a problem with what the alias
    brings (``people: [*r]`` with ``robot: &r {pose: ...}``: "a person needs a name") was said at the anchor's
    line, not where the value is used. The aliases' marks come from the parser's events, in the order the
    composer met them: the nodes are walked depth first in the same order, and the n-th node met a second time
    is the n-th alias. Its replacement is a shallow copy (the same tag, value and children) with the alias's
    marks. Run after :func:`check_size` (which relies on shared nodes to count an alias once)."""
    if "*" not in text:
        return
    marks: list[tuple[Any, Any]] = []
    parser = loader(text)
    try:
        while parser.check_event():
            event = parser.get_event()
            if isinstance(event, yaml.AliasEvent):
                marks.append((event.start_mark, event.end_mark))
    finally:
        parser.dispose()
    if not marks:
        return
    aliases = iter(marks)
    seen: set[int] = set()

    def placed(node: yaml.Node) -> yaml.Node:
        marks = next(aliases, None)
        if marks is None:  # never, if the composer shares a node only for an alias: then the node as it was
            return node
        alias = copy.copy(node)
        start, end = marks
        alias.start_mark, alias.end_mark = start, end
        return alias

    for root in roots:
        if root is None:
            continue
        # (the list holding the node, its index there, which of a pair it is or -1, the node), popped in the order
        # written: a node's children are pushed last first
        stack: list[tuple[list, int, int, yaml.Node]] = [([root], 0, -1, root)]
        while stack:
            holder, index, side, node = stack.pop()
            if id(node) in seen:
                if side < 0:
                    holder[index] = placed(node)
                else:
                    pair = list(holder[index])
                    pair[side] = placed(node)
                    holder[index] = (pair[0], pair[1])
                continue
            seen.add(id(node))
            if isinstance(node, yaml.SequenceNode):
                items = node.value
                stack.extend((items, i, -1, items[i]) for i in range(len(items) - 1, -1, -1))
            elif isinstance(node, yaml.MappingNode):
                pairs = node.value
                for i in range(len(pairs) - 1, -1, -1):
                    stack.append((pairs, i, 1, pairs[i][1]))
                    stack.append((pairs, i, 0, pairs[i][0]))


def merge_keys(root: yaml.Node | None, file: str) -> None:
    """Merge each ``<<: *base`` (YAML's merge key, as ROS users write it) into its mapping, in place.

    As PyYAML's loader does: ``<<`` takes a mapping or a list of mappings; a key the mapping itself holds wins
    over a merged one, and among merged mappings the first listed wins; merged pairs come first. A merged pair
    stands at the merge that brought it (the ``*base`` after ``<<:``: a frame name repeated by merging a frame
    is said there), what is inside its value where it is written. Each mapping is merged once, children
    before parents, so a merged mapping's own ``<<`` is already merged; nothing grows past what
    :func:`check_size` counted (an alias counts the whole value it repeats). Anything but a mapping after ``<<``
    is a SealError at its line and column."""
    if root is None:
        return
    done: set[int] = set()  # the value lists merged: an alias's node shares its anchor's list
    stack: list[tuple[yaml.Node, bool]] = [(root, False)]
    while stack:
        node, finished = stack.pop()
        if not isinstance(node, yaml.CollectionNode) or id(node.value) in done:
            continue
        if not finished:
            stack.append((node, True))
            stack.extend((child, False) for child in reversed(_children(node)))
            continue
        done.add(id(node.value))
        if isinstance(node, yaml.MappingNode) and any(key.tag == MERGE for key, _ in node.value):
            node.value[:] = _merged(node, file)


def _merged(node: yaml.MappingNode, file: str) -> list[tuple[yaml.Node, yaml.Node]]:
    own = [(key, value) for key, value in node.value if key.tag != MERGE]
    sources: list[yaml.MappingNode] = []
    for key, value in node.value:
        if key.tag != MERGE:
            continue
        for source in value.value if isinstance(value, yaml.SequenceNode) else [value]:
            if not isinstance(source, yaml.MappingNode):
                mark = source.start_mark
                raise SealError(f"a merge key (<<) takes a mapping or a list of mappings (such as *base or [*a, *b]), "
                                f"not {shape(source)}", Where(file, mark.line + 1, mark.column + 1))
            sources.append(source)
    taken = {key.value for key, _ in own if isinstance(key, yaml.ScalarNode)}
    merged: list[tuple[yaml.Node, yaml.Node]] = []
    for source in sources:
        for key, value in source.value:
            if isinstance(key, yaml.ScalarNode):
                if key.value in taken:
                    continue
                taken.add(key.value)
            merged.append((_at(key, source), _at(value, source)))
    return merged + own


def _at(node: yaml.Node, source: yaml.Node) -> yaml.Node:
    """``node`` (a pair merged in) at ``source``'s marks: the merge that brought it (``*base`` after ``<<:``)."""
    moved = copy.copy(node)
    moved.start_mark, moved.end_mark = source.start_mark, source.end_mark
    return moved


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
    if node.tag == CORE + "str" and getattr(node, "style", None) and _number_text(node.value):
        return f"the text {clipped(repr(node.value))} (a number is written without quotes or !!str)"
    return clipped(repr(node.value))


def _number_text(text: str) -> bool:
    try:
        float(text)
    except ValueError:
        return False
    return True


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
