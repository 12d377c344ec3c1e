"""Reading frame libraries: files and folders of frame files → a :class:`~seal_cli.frames.library.Library`.

:func:`read_library` reads frame files (YAML or the ``.frame`` DSL) and folders of them and
returns the library together with every problem found; :func:`load_library` raises them
instead. Which files make up the standard library is :func:`seal_cli.resources.framelib_dir`.
"""

from __future__ import annotations

import dataclasses
import difflib
from collections.abc import Iterable, Mapping, Sequence
from functools import cache
from pathlib import Path

from seal_cli.errors import SealError, SealErrors, Where
from seal_cli.fileio import read_text
from seal_cli.frames.formats import Contents, Reader, dsl, yamlfile
from seal_cli.frames.library import Library
from seal_cli.frames.model import Frame, LexicalUnit
from seal_cli.frames.validation import check_library
from seal_cli.resources import framelib_dir

__all__ = ["FRAME_SUFFIXES", "READERS", "frame_files", "load_library", "read_files", "read_library", "standard_library"]

READERS: Mapping[str, Reader] = {".yaml": yamlfile.read, ".yml": yamlfile.read, ".frame": dsl.read}
"""The frame file formats, by file suffix."""

FRAME_SUFFIXES = tuple(READERS)


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


def read_files(files: Sequence[Path]) -> Contents:
    """Read each file with the reader its suffix names (YAML for any other); problems are collected, not raised."""
    pieces = Contents()
    for path in files:
        try:
            text = read_text(path)
        except SealError as exc:
            pieces.problems.append(exc)
            continue
        reader = READERS.get(path.suffix, yamlfile.read)
        pieces.add(reader(text, str(path)))
    return pieces


def read_library(paths: Iterable[str | Path]) -> tuple[Library, list[SealError]]:
    """The library in these files and folders, and every problem found in it."""
    files, problems = frame_files(paths)
    pieces = read_files(files)
    problems.extend(pieces.problems)
    pieces.frames = _with_units(pieces.frames, pieces.units, problems)
    names: set[str] = set()
    unique: list[Frame] = []
    for frame in pieces.frames:
        if frame.name not in names:
            unique.append(frame)
            names.add(frame.name)
    library = Library(tuple(unique), pieces.taxonomy)
    problems.extend(check_library(pieces.frames, pieces.taxonomy))
    return library, problems


def _with_units(frames: list[Frame], units: Sequence[tuple[str, LexicalUnit]],
                problems: list[SealError]) -> list[Frame]:
    """The frames with the lexical units other files add to them (``lexical_units:`` in a frame
    file, as ``framelib/derived_units.yaml`` does); a unit for no frame, or one the frame lists
    already, is a problem."""
    added: dict[str, list[LexicalUnit]] = {}
    names = {f.name for f in frames}
    for name, unit in units:
        if name not in names:
            close = difflib.get_close_matches(name, sorted(names), n=1)
            hint = f" (did you mean {close[0]!r}?)" if close else ""
            problems.append(SealError(f"lexical unit {unit.text!r} is for frame {name!r}, which no file defines{hint}",
                                      unit.where))
            continue
        added.setdefault(name, []).append(unit)
    out = []
    for frame in frames:
        extra = added.pop(frame.name, None)
        if extra:
            own = {u.text for u in frame.lexical_units}
            new: list[LexicalUnit] = []
            for unit in extra:
                if unit.text in own:
                    problems.append(SealError(f"lexical unit {unit.text!r} is already one of {frame.name}'s",
                                              unit.where))
                else:
                    new.append(unit)
                    own.add(unit.text)
            frame = dataclasses.replace(frame, lexical_units=frame.lexical_units + tuple(new))
        out.append(frame)
    return out


def load_library(paths: Iterable[str | Path] | None = None) -> Library:
    """The library in these files and folders (default: the standard library); raises on any problem."""
    library, problems = read_library([framelib_dir()] if paths is None else paths)
    if problems:
        raise problems[0] if len(problems) == 1 else SealErrors(problems)
    return library


@cache
def standard_library() -> Library:
    """The shipped standard library, read once per process (a library is a value: sharing it is safe)."""
    return load_library()
