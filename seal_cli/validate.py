"""What ``seal validate`` checks: frame files, folders of them and maps, every problem at once.

Frame files are read by :mod:`seal_cli.frames.reading` and checked together (with the standard
library, on request); a YAML file whose top-level keys are a map's (:data:`seal_cli.maps.formats.
map_server.KEYS`) and none a frame file's is checked as a map.
"""

from __future__ import annotations

import os
from collections.abc import Iterable
from dataclasses import dataclass, field
from pathlib import Path

import yaml

from seal_cli.errors import SealError
from seal_cli.fileio import read_text
from seal_cli.frames.reading import frame_files, read_library
from seal_cli.maps.formats.map_server import KEYS, check_map_file
from seal_cli.resources import framelib_dir

__all__ = ["FRAME_FILE_KEYS", "Report", "is_map_file", "validate_paths"]

FRAME_FILE_KEYS = frozenset({"frame", "frames", "categories", "world", "synonyms"})
"""Top-level keys of frame files (:mod:`seal_cli.frames.formats.yamlfile`)."""

_MAP_ONLY_KEYS = frozenset(KEYS) - {"name", "mode"}
"""The map keys that say "map": a frame file may have a ``name`` too."""


def is_map_file(path: Path) -> bool:
    """Whether a YAML file is a map (top-level map keys and no frame keys) rather than frames, whatever its name
    says but ``.frame`` (the DSL): ``seal validate my_map`` (or ``/dev/stdin``, ``map.txt``) was read as a frame
    file, and every key of a good map listed as "unknown key in a frame file"."""
    if path.suffix == ".frame" or path.is_dir():
        return False
    try:
        keys = top_level_keys(read_text(path))
    except (SealError, yaml.YAMLError):
        return False
    return keys is not None and bool(keys & _MAP_ONLY_KEYS) and not keys & FRAME_FILE_KEYS


def top_level_keys(text: str) -> set[str] | None:
    """The keys of a YAML text's top-level mapping (None: its first document is no mapping), read off the parser's
    events: nothing is composed, so a map of 40,000 rooms is not composed twice (hostile26: once to tell it is a
    map, once to read it; over a minute to validate)."""
    from seal_cli import fileio

    parser = fileio.LOADER(text)
    keys: set[str] = set()
    depth = position = 0     # how deep the parser is; how many keys and values of the top mapping it has passed
    try:
        while parser.check_event():
            event = parser.get_event()
            if isinstance(event, yaml.DocumentEndEvent):
                break
            if isinstance(event, yaml.NodeEvent):
                if depth == 0 and not isinstance(event, yaml.MappingStartEvent):
                    return None
                if depth == 1:
                    if position % 2 == 0 and isinstance(event, yaml.ScalarEvent):
                        keys.add(event.value)
                    position += 1
                if isinstance(event, yaml.CollectionStartEvent):
                    depth += 1
            elif isinstance(event, yaml.CollectionEndEvent):
                depth -= 1
    finally:
        parser.dispose()
    return keys


@dataclass
class Report:
    """What ``seal validate`` found."""

    files: list[Path] = field(default_factory=list)
    frames: int = 0
    categories: int = 0
    maps: int = 0
    problems: list[SealError] = field(default_factory=list)

    def summary(self) -> str:
        found = (f"{_count(self.frames, 'frame')}, {_count(self.categories, 'category', 'categories')}, "
                 f"{_count(self.maps, 'map')} in {_count(len(self.files), 'file')}")
        if not self.problems:
            return f"ok: {found}"
        return f"{_count(len(self.problems), 'problem')} in {found}"

    def to_json(self) -> dict[str, object]:
        return {"ok": not self.problems, "files": [str(f) for f in self.files], "frames": self.frames,
                "categories": self.categories, "maps": self.maps,
                "problems": [p.to_json() for p in self.problems]}


def _count(n: int, one: str, many: str | None = None) -> str:
    return f"{n} {one if n == 1 else many or one + 's'}"


def validate_paths(paths: Iterable[str | Path], with_stdlib: bool = False) -> Report:
    """Check frame files, folders and maps; every problem, sorted by file, line and column."""
    files, problems = frame_files(paths)
    maps = [f for f in files if is_map_file(f)]
    frame_paths = [f for f in files if f not in maps]
    report = Report(files=files, maps=len(maps), problems=problems)
    if frame_paths:
        extra: list[Path] = []
        if with_stdlib:
            extra = [p for p in frame_files([framelib_dir()])[0] if os.path.realpath(p) not in
                     {os.path.realpath(f) for f in frame_paths}]
        library, found = read_library(extra + frame_paths)
        report.frames = len(library) - (len(read_library(extra)[0]) if extra else 0)
        report.categories = len(library.taxonomy.categories)
        report.problems.extend(found)
        from seal_cli.language.units import unit_problems  # what a word of English is: the language's to say

        report.problems.extend(unit_problems(library))
    for path in maps:
        report.problems.extend(check_map_file(path))
    report.problems.sort(key=lambda p: (p.file or "", p.line or 0, p.column or 0))
    return report
