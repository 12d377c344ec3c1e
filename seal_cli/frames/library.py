"""A frame library: frames indexed by name and by lexical unit, with the taxonomy of their types.

:func:`read_library` reads frame files (YAML or the ``.frame`` DSL) and folders of them and
returns the library together with every problem found; :func:`load_library` raises them
instead. Which files make up the standard library is :func:`seal_cli.resources.framelib_dir`.
"""

from __future__ import annotations

from collections.abc import Iterable, Iterator, Mapping, Sequence
from dataclasses import dataclass, field
from functools import cached_property
from pathlib import Path

from seal_cli.errors import SealError, SealErrors, Where
from seal_cli.fileio import read_text
from seal_cli.frames.model import Frame, normalize_unit
from seal_cli.frames.taxonomy import Taxonomy

__all__ = ["FRAME_SUFFIXES", "Contents", "Library", "frame_files", "load_library", "read_library"]

FRAME_SUFFIXES = (".yaml", ".yml", ".frame")


@dataclass(frozen=True)
class Library:
    """Frames and the categories their elements are typed with."""

    frames: tuple[Frame, ...] = ()
    taxonomy: Taxonomy = field(default_factory=Taxonomy)

    @cached_property
    def by_name(self) -> Mapping[str, Frame]:
        return {f.name: f for f in self.frames}

    @cached_property
    def by_unit(self) -> Mapping[str, tuple[Frame, ...]]:
        """Lexical unit ("pick up") → the frames it evokes, in library order."""
        index: dict[str, list[Frame]] = {}
        for frame in self.frames:
            for unit in frame.lexical_units:
                index.setdefault(unit.text, []).append(frame)
        return {unit: tuple(frames) for unit, frames in index.items()}

    @property
    def units(self) -> tuple[str, ...]:
        """Every lexical unit, longest first (so that "pick up" is tried before "pick")."""
        return tuple(sorted(self.by_unit, key=lambda u: (-len(u.split()), u)))

    def __iter__(self) -> Iterator[Frame]:
        return iter(self.frames)

    def __len__(self) -> int:
        return len(self.frames)

    def __contains__(self, name: object) -> bool:
        return name in self.by_name

    def frame(self, name: str) -> Frame:
        """The frame called ``name``; an unknown name is an error that lists the known ones."""
        try:
            return self.by_name[name]
        except KeyError:
            folded = {n.lower(): f for n, f in self.by_name.items()}
            if name.lower() in folded:
                return folded[name.lower()]
            raise SealError(f"unknown frame {name!r}; the library has {', '.join(sorted(self.by_name))}") from None

    def evoked_by(self, unit: str) -> tuple[Frame, ...]:
        """The frames a lexical unit evokes (empty when none does)."""
        return self.by_unit.get(normalize_unit(unit), ())

    def achievers(self, predicate: str) -> tuple[Frame, ...]:
        """Frames with a positive postcondition of this predicate."""
        return tuple(f for f in self.frames
                     if any(p.predicate == predicate and not p.negated for p in f.postconditions))


def frame_files(paths: Iterable[str | Path]) -> tuple[list[Path], list[SealError]]:
    """The frame files under the given files and folders, sorted within each folder."""
    files: list[Path] = []
    problems: list[SealError] = []
    for raw in paths:
        path = Path(raw)
        if path.is_dir():
            found = sorted(p for p in path.rglob("*") if p.suffix in FRAME_SUFFIXES and p.is_file())
            if not found:
                problems.append(SealError(f"no frame files (*.yaml, *.frame) in folder {path}", Where(str(path))))
            files.extend(found)
        elif path.is_file():
            files.append(path)
        else:
            problems.append(SealError(f"no such file or folder: {path}", Where(str(path))))
    return files, problems


@dataclass
class Contents:
    """What one or more frame files hold, before they are checked together."""

    frames: list[Frame] = field(default_factory=list)
    taxonomy: Taxonomy = field(default_factory=Taxonomy)
    problems: list[SealError] = field(default_factory=list)

    def add(self, other: Contents) -> None:
        self.frames.extend(other.frames)
        self.taxonomy = self.taxonomy.merged(other.taxonomy)
        self.problems.extend(other.problems)


def read_files(files: Sequence[Path]) -> Contents:
    """Read each file with the reader its suffix names; problems are collected, not raised."""
    from seal_cli.frames.formats import dsl
    from seal_cli.frames.formats import yamlfile as yamlformat

    pieces = Contents()
    for path in files:
        try:
            text = read_text(path)
        except SealError as exc:
            pieces.problems.append(exc)
            continue
        reader = dsl.read if path.suffix == ".frame" else yamlformat.read
        content = reader(text, str(path))
        pieces.add(content)
    return pieces


def read_library(paths: Iterable[str | Path]) -> tuple[Library, list[SealError]]:
    """The library in these files and folders, and every problem found in it."""
    from seal_cli.frames.validation import check_library

    files, problems = frame_files(paths)
    pieces = read_files(files)
    problems.extend(pieces.problems)
    names: set[str] = set()
    unique: list[Frame] = []
    for frame in pieces.frames:
        if frame.name not in names:
            unique.append(frame)
            names.add(frame.name)
    library = Library(tuple(unique), pieces.taxonomy)
    problems.extend(check_library(pieces.frames, pieces.taxonomy))
    return library, problems


def load_library(paths: Iterable[str | Path] | None = None) -> Library:
    """The library in these files and folders (default: the standard library); raises on any problem."""
    if paths is None:
        from seal_cli.resources import framelib_dir

        paths = [framelib_dir()]
    library, problems = read_library(paths)
    if problems:
        raise problems[0] if len(problems) == 1 else SealErrors(problems)
    return library
