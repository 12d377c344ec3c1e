"""Class labels for detectors that name classes by number (ROS 1's vision_msgs, COCO-style ids).

A labels file maps a detection's class id to a class name, either as a mapping or as a list
whose position is the id (from 0)::

    {1: spoon, 2: cup, 47: cup}          # or
    [background, spoon, cup]

An id the file does not list stays as it is (a class no belief is kept for).
"""

from __future__ import annotations

from pathlib import Path

import yaml

from seal_cli.errors import SealError, SealErrors
from seal_cli.fileio import compose_yaml, read_text
from seal_cli.names import check_shown
from seal_cli.yamlnodes import CORE, NodeReader, shape

__all__ = ["read_labels"]


def read_labels(path: str | Path) -> dict[str, str]:
    """Class id (as text) → class name; every problem at its line and column."""
    text = read_text(path)
    reader = NodeReader(text, str(path))
    root = compose_yaml(text, str(path))
    labels: dict[str, str] = {}

    def label(node: yaml.Node, what: str) -> str | None:
        """A class's name, as an observations file takes it: a number (``cup: 1``) or a name holding a control
        character (``"cu\\0p"``) was passed on as a class, into the observations written (hostile31)."""
        name = reader.string(node, what)
        if name is None:
            return None
        if node.tag != CORE + "str":
            read_as = node.tag.removeprefix(CORE)
            reader.problem(f"{what} must be a class's name, not {shape(node)} (YAML reads it as {read_as})", node)
            return None
        try:
            return check_shown(name.strip(), what)
        except SealError as exc:
            reader.problem(exc.message, node)
            return None

    if isinstance(root, yaml.SequenceNode):
        for i, node in enumerate(root.value):
            name = label(node, f"label {i}")
            if name is not None:
                labels[str(i)] = name
    elif isinstance(root, yaml.MappingNode):
        for key, _, node in reader.pairs(root, "the labels"):
            name = label(node, f"the label of {key}")
            if name is not None:
                labels[key.strip()] = name
    else:
        reader.problem(f"a labels file is a mapping {{id: class}} or a list of classes, not "
                       f"{'nothing' if root is None else shape(root)}", root)
    if reader.problems:
        raise reader.problems[0] if len(reader.problems) == 1 else SealErrors(reader.problems)
    return labels
