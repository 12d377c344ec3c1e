"""Frame libraries written in YAML, read with the position of every value.

A document is either one frame (a mapping with ``frame:``) or a mapping with any of
``frames:`` (a list of frames), ``categories:`` (category → members, ``~`` for an open
category), ``world:`` (predicates the world may make true without a frame) and ``synonyms:``
(class → its other English names, ``fridge: [refrigerator, icebox]``). A file may
hold several documents separated by ``---``::

    frame: Stir
    lexical_units: [stir, mix]
    elements:
      theme: {type: container}
      instrument: {type: utensil, default: spoon}
    preconditions: [holding(instrument)]
    actions: [navigate(theme), stir(instrument, theme)]
    postconditions: [stirred(theme)]

Reading never raises: problems are collected with their file, line and column.
"""

from __future__ import annotations

import functools
from collections.abc import Callable, Iterator
from typing import TypeVar

import yaml

from seal_cli.errors import SealError, Where
from seal_cli.fileio import compose_documents
from seal_cli.frames.formats import Contents
from seal_cli.frames.model import IDENTIFIER, Action, Element, Fact, Frame, LexicalUnit
from seal_cli.frames.taxonomy import Category, Synonyms, Taxonomy
from seal_cli.yamlnodes import NodeReader, is_null

__all__ = ["FRAME_KEYS", "dump", "read"]

FRAME_KEYS = ("frame", "description", "framenet", "lexical_units", "elements", "preconditions", "actions",
              "postconditions")
ELEMENT_KEYS = ("type", "default")
TOP_KEYS = ("frames", "categories", "world", "synonyms", "lexical_units")
UNIT_KEYS = ("frame", "unit", "source")
UNIT_OPTIONAL = ("object", "apart", "stores", "split", "opening")
"""An added unit may say which element its direct object fills (``object: goal``), the particles with which
its verb is another verb (``apart: "on out up"``, words separated by spaces), and whether, said with no goal,
it puts its thing where such a thing is kept (``stores: true``: "put away", "store"), and whether it is said only with
its particle alone after the object (``split: true``: "put the kettle *on*"), and whether it is a verb that is mostly a
noun, read only opening an imperative before its object (``opening: true``: "dust the shelf")."""

T = TypeVar("T")


class _Reader(NodeReader):
    """Turns composed YAML nodes into model objects, recording problems as it goes."""

    def __init__(self, text: str, file: str) -> None:
        super().__init__(text, file)
        self.contents = Contents(problems=self.problems)

    def items(self, node: yaml.Node, what: str, *, single: bool = True) -> list[yaml.Node]:
        """A list's items; in a frame file one value is a list of one (``lexical_units: stir``)."""
        return super().items(node, what, single=single)

    # -- documents ------------------------------------------------------------------------
    def document(self, node: yaml.Node) -> None:
        if is_null(node):
            return
        if isinstance(node, yaml.SequenceNode):
            for item in node.value:
                self.frame(item)
            return
        if isinstance(node, yaml.MappingNode) and any(k.value == "frame" for k, _ in node.value):
            self.frame(node)
            return
        for key, _, value in self.pairs(node, "a frame file", TOP_KEYS + ("frame",)):
            if key == "frames":
                for item in self.items(value, "frames"):
                    self.frame(item)
            elif key == "categories":
                self.categories(value)
            elif key == "synonyms":
                self.synonyms(value)
            elif key == "lexical_units":
                self.units(value)
            elif key == "world":
                world = tuple(w for w in (self.predicate(n) for n in self.items(value, "world")) if w)
                self.contents.taxonomy = self.contents.taxonomy.merged(Taxonomy((), world))

    def predicate(self, node: yaml.Node) -> str | None:
        """A world predicate: a name."""
        name = self.string(node, "a world predicate")
        if name is not None and not IDENTIFIER.match(name):
            self.problem(f"world predicate {name!r} is not a name (letters, digits and '_', not starting with a "
                         "digit)", node)
            return None
        return name

    def categories(self, node: yaml.Node) -> None:
        found = []
        for name, key_node, value in self.pairs(node, "categories"):
            if is_null(value):
                members = None
            else:
                members = tuple(m for m in (self.string(n, f"a member of {name}")
                                            for n in self.items(value, f"category {name}")) if m)
            category = self.build(functools.partial(Category, name, members, self.where(key_node)), key_node)
            if category:
                found.append(category)
        self.contents.taxonomy = self.contents.taxonomy.merged(Taxonomy(tuple(found)))

    def synonyms(self, node: yaml.Node) -> None:
        found = []
        for name, key_node, value in self.pairs(node, "synonyms"):
            names = tuple(n for n in (self.string(item, f"a synonym of {name}")
                                      for item in self.items(value, f"synonyms of {name}")) if n)
            entry = self.build(functools.partial(Synonyms, name, names, self.where(key_node)), key_node)
            if entry:
                found.append(entry)
        self.contents.taxonomy = self.contents.taxonomy.merged(Taxonomy(synonyms=tuple(found)))

    def units(self, node: yaml.Node) -> None:
        """Lexical units added to frames defined elsewhere, each with where it comes from
        (``framelib/derived_units.yaml``: ``{frame: Place, unit: relocate, source: ...}``)."""
        for item in self.items(node, "lexical_units"):
            found: dict[str, object] = {}
            for key, _, value in self.pairs(item, "a lexical unit", UNIT_KEYS + UNIT_OPTIONAL):
                found[key] = self.flag(value, key) if key in ("stores", "split", "opening") else self.string(value, key)
            if not isinstance(item, yaml.MappingNode):
                continue
            missing = [key for key in UNIT_KEYS if not found.get(key)]
            if missing:
                self.problem(f"a lexical unit needs {', '.join(repr(k) for k in missing)}: "
                             "{frame: Name, unit: words, source: where it comes from}", item)
                continue
            said = found.get("object")
            apart = tuple(str(found.get("apart") or "").split())
            unit = self.build(functools.partial(LexicalUnit, str(found["unit"]), self.where(item),
                                                str(said) if said else None, apart, bool(found.get("stores")),
                                                bool(found.get("split")), bool(found.get("opening"))), item)
            if unit is not None:
                self.contents.units.append((str(found["frame"]), unit))

    def flag(self, node: yaml.Node, what: str) -> bool | None:
        """A yes/no value (``true`` or ``false``)."""
        if isinstance(node, yaml.ScalarNode) and node.tag == "tag:yaml.org,2002:bool":
            return node.value.lower() in ("true", "yes", "on")
        self.problem(f"{what} must be true or false", node)
        return None

    def frame(self, node: yaml.Node) -> None:
        fields: dict[str, object] = {}
        name_node = node
        for key, _, value in self.pairs(node, "a frame", FRAME_KEYS):
            if key in ("frame", "description", "framenet"):
                fields[key] = self.string(value, key)
                name_node = value if key == "frame" else name_node
            elif key == "lexical_units":
                fields[key] = self.many(value, key, lambda t, w: LexicalUnit(t, w))
            elif key == "elements":
                fields[key] = tuple(self.elements(value))
            elif key == "actions":
                fields[key] = self.many(value, key, Action.parse)
            else:
                fields[key] = self.many(value, key, Fact.parse)
        if not isinstance(node, yaml.MappingNode):
            return
        if "frame" not in fields:
            self.problem("a frame needs a name: add 'frame: Name'", node)
            return
        name = fields.pop("frame")
        if not name:
            return
        args = {k: v for k, v in fields.items() if v is not None}
        description = args.pop("description", "")
        built = self.build(lambda: Frame(str(name), description=str(description), where=self.where(name_node),
                                         **args),  # type: ignore[arg-type]
                           name_node)
        if built is None:  # still checked with the others, without the parts refused above
            built = Frame.salvage(str(name), description=str(description), where=self.where(name_node),
                                  **args)
        if built:
            self.contents.frames.append(built)

    def many(self, node: yaml.Node, what: str, make: Callable[[str, Where], T]) -> tuple[T, ...]:
        out = []
        for text, item in self.atoms(node, what):
            built = self.build(functools.partial(make, text, self.where(item)), item)
            if built is not None:
                out.append(built)
        return tuple(out)

    def atoms(self, node: yaml.Node, what: str) -> Iterator[tuple[str, yaml.Node]]:
        """The list's strings, with ``in(theme, goal)`` whole again.

        In a YAML flow list, ``[in(theme, goal)]`` reads as the two items ``in(theme`` and
        ``goal)``; an item whose parentheses are left open takes the items after it until they close.
        """
        pending: tuple[str, yaml.Node] | None = None
        for item in self.items(node, what):
            text = self.string(item, f"each of {what}")
            if text is None:
                continue
            if pending is not None:
                text, item = f"{pending[0]}, {text}", pending[1]
            if text.count("(") > text.count(")"):
                pending = (text, item)
                continue
            pending = None
            yield text, item
        if pending is not None:
            yield pending

    def elements(self, node: yaml.Node) -> Iterator[Element]:
        for role, key_node, value in self.pairs(node, "elements"):
            fields: dict[str, str | None] = {}
            before = len(self.problems)
            if isinstance(value, yaml.ScalarNode):
                fields["type"] = self.string(value, f"the type of {role}")
            else:
                for key, _, inner in self.pairs(value, f"element {role!r}", ELEMENT_KEYS):
                    fields[key] = self.string(inner, f"{key} of {role}")
            if not fields.get("type"):
                if "type" not in fields and len(self.problems) == before:
                    self.problem(f"element {role!r} needs a type", key_node)
                continue
            element = self.build(functools.partial(Element, role, str(fields["type"]), fields.get("default"),
                                                   self.where(key_node)), key_node)
            if element:
                yield element


def read(text: str, file: str = "<yaml>") -> Contents:
    """The frames, categories and problems in a YAML frame file's text."""
    reader = _Reader(text, file)
    try:
        documents = compose_documents(text, file)
    except SealError as problem:
        reader.problem(problem.message, where=problem.where)
        return reader.contents
    for document in documents:
        if document is not None:
            reader.document(document)
    return reader.contents


# -- writing --------------------------------------------------------------------------------
def _flow(items: object) -> str:
    return "[" + ", ".join(_scalar(str(i)) for i in items) + "]"  # type: ignore[attr-defined]


def _scalar(text: str) -> str:
    """A YAML scalar that reads back as this exact string."""
    dumped = yaml.safe_dump(text, default_style=None, width=10_000).strip()
    dumped = dumped.removesuffix("\n...").removesuffix("...").strip()
    if dumped.startswith(("'", '"')) or any(c in text for c in ",[]{}#") or text != text.strip():
        return yaml.safe_dump(text, default_style='"', width=10_000).strip().removesuffix("...").strip()
    return dumped


def dump_frame(frame: Frame) -> str:
    """One frame as a YAML document in the SPEC's layout."""
    lines = [f"frame: {frame.name}"]
    if frame.description:
        lines.append(f"description: {_scalar(frame.description)}")
    if frame.framenet:
        lines.append(f"framenet: {frame.framenet}")
    lines.append(f"lexical_units: {_flow(u.text for u in frame.lexical_units)}")
    lines.append("elements:" if frame.elements else "elements: {}")
    for e in frame.elements:
        default = f", default: {e.default}" if e.default is not None else ""
        lines.append(f"  {e.role}: {{type: {e.type}{default}}}")
    lines.append(f"preconditions: {_flow(frame.preconditions)}")
    lines.append(f"actions: {_flow(frame.actions)}")
    lines.append(f"postconditions: {_flow(frame.postconditions)}")
    return "\n".join(lines) + "\n"


def dump(frames: tuple[Frame, ...] | list[Frame], taxonomy: Taxonomy | None = None) -> str:
    """Frames (and categories) as a multi-document YAML frame file."""
    docs = [dump_frame(f) for f in frames]
    if taxonomy and (taxonomy.categories or taxonomy.world or taxonomy.synonyms):
        lines = []
        if taxonomy.categories:
            lines.append("categories:")
            for c in taxonomy.categories:
                lines.append(f"  {c.name}: {'~' if c.members is None else _flow(c.members)}")
        if taxonomy.world:
            lines.append(f"world: {_flow(taxonomy.world)}")
        if taxonomy.synonyms:
            lines.append("synonyms:")
            lines.extend(f"  {s.name}: {_flow(s.names)}" for s in taxonomy.synonyms)
        docs.append("\n".join(lines) + "\n")
    return "---\n".join(docs)
