"""The frame file formats: YAML (:mod:`.yamlfile`) and the ``.frame`` DSL (:mod:`.dsl`), read with
positions and written back.

A format is a module with ``read(text, file) -> Contents``: it never raises, and collects every
problem with its position. :data:`seal_cli.frames.reading.READERS` maps file suffixes to readers;
a new format is one module here and one entry there.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Protocol

from seal_cli.errors import SealError
from seal_cli.frames.model import Frame, LexicalUnit
from seal_cli.frames.taxonomy import Taxonomy

__all__ = ["Contents", "Reader"]


@dataclass
class Contents:
    """What one or more frame files hold, before they are checked together."""

    frames: list[Frame] = field(default_factory=list)
    taxonomy: Taxonomy = field(default_factory=Taxonomy)
    problems: list[SealError] = field(default_factory=list)
    units: list[tuple[str, LexicalUnit]] = field(default_factory=list)
    """Lexical units a file adds to a frame defined elsewhere (frame name, unit)."""

    def add(self, other: Contents) -> None:
        self.frames.extend(other.frames)
        self.units.extend(other.units)
        self.taxonomy = self.taxonomy.merged(other.taxonomy)
        self.problems.extend(other.problems)


class Reader(Protocol):
    """How a format reads the text of one file (``file`` names it in problems)."""

    def __call__(self, text: str, file: str = ...) -> Contents: ...
