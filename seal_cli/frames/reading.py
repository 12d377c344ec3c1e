"""Reading frame libraries: files and folders of frame files → a :class:`~seal_cli.frames.library.Library`.

:func:`read_library` reads frame files (YAML or the ``.frame`` DSL) and folders of them and
returns the library together with every problem found; :func:`load_library` raises them
instead. Which files make up the standard library is :func:`seal_cli.resources.framelib_dir`.

:func:`load_library` keeps each library it read without a problem in seal's cross-process cache
(:mod:`seal_cli.cache`), stamped with the names and contents of the files it was read from and the
code that read it; a later process whose files and code are the same unpickles it (~2 ms) instead
of reading and checking them again (~100 ms, most of ``seal parse``'s start). Any change to a
file, a file added to or removed from a folder, or another version of seal reads the files anew.
"""

from __future__ import annotations

import dataclasses
import os
from collections.abc import Iterable, Mapping, Sequence
from functools import cache
from pathlib import Path
from typing import TYPE_CHECKING, Any

from seal_cli.errors import SealError, SealErrors, Where
from seal_cli.frames.library import Library
from seal_cli.frames.model import Frame, LexicalUnit
from seal_cli.resources import framelib_dir, grammar_path

if TYPE_CHECKING:
    from seal_cli.frames.formats import Contents, Reader

    READERS: Mapping[str, Reader]
    """The frame file formats, by file suffix (made when first asked for, see ``__getattr__``)."""

__all__ = ["FRAME_SUFFIXES", "READERS", "cache_entry_name", "frame_files", "load_library", "read_files", "read_library",
           "standard_library"]

FRAME_SUFFIXES = (".yaml", ".yml", ".frame")
"""The suffixes of frame files (the keys of :data:`READERS`)."""


@cache
def _readers() -> Mapping[str, Reader]:
    from seal_cli.frames.formats import dsl, yamlfile

    return {".yaml": yamlfile.read, ".yml": yamlfile.read, ".frame": dsl.read}


def __getattr__(name: str) -> Any:
    """``READERS``, the frame file formats by file suffix, made when first asked for: the formats'
    modules (PyYAML, the DSL's grammar) are imported only when a file is read, not from the cache."""
    if name == "READERS":
        return _readers()
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")


def _frame_files_under(folder: Path) -> list[Path]:
    """The frame files in a folder and its subfolders (links to folders not followed, as ``rglob``), sorted.
    What vanishes or cannot be listed during the walk is passed over (``seal validate /`` met a process of
    ``/proc`` that had ended: "error: /proc/20888: No such file or directory"). A name with a frame file's suffix
    that is no regular file (a FIFO, a device, a dangling link, a link loop) is kept, for its reading to refuse by
    its kind: it was passed over, and the frames a user put there silently missing (hostile30)."""
    import os

    found = []
    for root, _, names in os.walk(folder, onerror=lambda _error: None):
        for name in names:
            path = Path(root) / name
            if path.suffix in FRAME_SUFFIXES:
                try:
                    if path.is_file() or os.path.lexists(path) and not path.is_dir():
                        found.append(path)
                except OSError:
                    continue
    return sorted(found)


def frame_files(paths: Iterable[str | Path]) -> tuple[list[Path], list[SealError]]:
    """The frame files under the given files and folders, sorted within each folder."""
    files: list[Path] = []
    problems: list[SealError] = []
    for raw in paths:
        path = Path(raw)
        if path.is_dir():
            found = _frame_files_under(path)
            if not found:
                from seal_cli.fileio import gone_cwd_hint

                problems.append(SealError(f"no frame files (*.yaml, *.frame) in folder {path}{gone_cwd_hint(path)}",
                                          Where(str(path))))
            files.extend(found)
        elif path.exists():  # a file, or a device or pipe that reading refuses by its kind
            files.append(path)
        else:
            from seal_cli.fileio import gone_cwd_hint, stdin_hint

            problems.append(SealError(f"no such file or folder: {path}{stdin_hint(str(raw))}{gone_cwd_hint(path)}",
                                      Where(str(path))))
    return _each_once(files), problems


def _each_once(files: Iterable[Path]) -> list[Path]:
    """Each file once, where it was first given: the same file named twice (``seal validate lib lib``,
    ``--framelib +framelib`` of a checkout, a folder and a file in it, a link to it) was read twice, and every
    frame and category in it reported as defined twice (526 problems for the standard library)."""
    seen: set[object] = set()
    once = []
    for path in files:
        try:
            status = path.stat()
            identity: object = (status.st_dev, status.st_ino)
        except OSError:
            identity = str(path)
        if identity not in seen:
            seen.add(identity)
            once.append(path)
    return once


def read_files(files: Sequence[Path]) -> Contents:
    """Read each file with the reader its suffix names (YAML for any other); problems are collected, not raised."""
    from seal_cli.fileio import read_text
    from seal_cli.frames.formats import Contents

    readers = _readers()
    pieces = Contents()
    for path in files:
        try:
            text = read_text(path)
        except SealError as exc:
            pieces.problems.append(exc)
            continue
        reader = readers.get(path.suffix, readers[".yaml"])
        piece = reader(text, str(path))
        if not (piece.frames or piece.units or piece.problems or piece.taxonomy.categories or piece.taxonomy.world
                or piece.taxonomy.synonyms):  # empty, a BOM, comments: "ok" said nothing was wrong (hostile30)
            piece.problems.append(SealError("this file holds nothing: no frame, category, world fact or synonyms, "
                                            "nor a map (is it the file you meant?)", Where(str(path))))
        pieces.add(piece)
    return pieces


def read_library(paths: Iterable[str | Path]) -> tuple[Library, list[SealError]]:
    """The library in these files and folders, and every problem found in it."""
    return _read(*frame_files(paths))


def _read(files: Sequence[Path], problems: list[SealError]) -> tuple[Library, list[SealError]]:
    from seal_cli.frames.validation import check_library

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
            import difflib

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
                elif unit.object is not None and unit.object not in {e.role for e in frame.elements}:
                    problems.append(SealError(f"lexical unit {unit.text!r}: {frame.name} has no element "
                                              f"{unit.object!r} for its object", unit.where))
                else:
                    new.append(unit)
                    own.add(unit.text)
            frame = dataclasses.replace(frame, lexical_units=frame.lexical_units + tuple(new))
        out.append(frame)
    return out


def cache_entry_name(paths: Iterable[str | Path] | None = None) -> str | None:
    """The name of the cache entry (:mod:`seal_cli.cache`) of the library in these files and folders (default: the
    standard library), or None when it has none (a file that cannot be read)."""
    given = [framelib_dir()] if paths is None else list(paths)
    files, problems = frame_files(given)
    entry = None if problems else _Entry.of(given, files)
    return entry.name if entry else None


def load_library(paths: Iterable[str | Path] | None = None) -> Library:
    """The library in these files and folders (default: the standard library); raises on any problem.
    Served from the cache when the files and the code are those it was read from (see above)."""
    given = [framelib_dir()] if paths is None else list(paths)
    files, problems = frame_files(given)
    entry = None if problems else _Entry.of(given, files)
    if entry is not None:
        cached = entry.load()
        if cached is not None:
            return cached
    library, problems = _read(files, problems)
    if problems:
        raise problems[0] if len(problems) == 1 else SealErrors(problems)
    if not library.frames:  # every command then failed on its first word: "known verbs include " and nothing
        raise SealError(f"this frame library holds no frames ({len(files):,} file{'s' if len(files) != 1 else ''} "
                        "read): give files that define frames, or '+FILE' to add to the standard library",
                        Where(", ".join(str(p) for p in given)))
    if entry is not None:
        entry.store(library)
    return library


@dataclasses.dataclass(frozen=True)
class _Entry:
    """Where a library read from these paths is cached, and the stamp of what it was read from."""

    name: str
    stamp: str

    @classmethod
    def of(cls, given: Sequence[str | Path], files: Sequence[Path]) -> _Entry | None:
        """The entry of a library read from ``files`` (found under the paths ``given``), or None when a
        file cannot be read (reading it again reports why)."""
        from seal_cli import cache
        from seal_cli.fileio import read_bytes

        named = [str(p) for p in given]
        if not all(os.path.isabs(p) for p in named):
            named.append(os.getcwd())  # relative paths name other files elsewhere
        parts = [_code_stamp()]
        for path in files:
            try:
                parts += [str(path).encode(), read_bytes(path)]
            except SealError:
                return None
        return cls(f"library-{cache.digest(*(p.encode() for p in named))[:24]}.pickle", cache.digest(*parts))

    def load(self) -> Library | None:
        """The cached library, or None when there is none of this stamp or it cannot be unpickled."""
        import pickle

        from seal_cli import cache

        payload = cache.read(self.name, self.stamp)
        if payload is None:
            return None
        try:
            library = pickle.loads(payload)
        except Exception:  # a corrupt entry (any error unpickling it) is one to make again
            return None
        return library if isinstance(library, Library) else None

    def store(self, library: Library) -> None:
        import pickle

        from seal_cli import cache

        cache.write(self.name, self.stamp, pickle.dumps(library, protocol=pickle.HIGHEST_PROTOCOL))


def _code_stamp() -> bytes:
    """What identifies the code that reads libraries and defines their values: seal's version and the
    size and modification time of each of its source files that do (a changed reader or model
    makes a new entry; an installed seal changes them only with its version)."""
    from seal_cli import __version__

    package = Path(__file__).resolve().parents[1]
    sources = [package / name for name in ("errors.py", "fileio.py", "yamlnodes.py", "resources.py")]
    sources += sorted((package / "frames").rglob("*.py"))
    sources.append(grammar_path("frames.lark"))
    stamp = [__version__]
    for source in sources:
        try:
            info = source.stat()
        except OSError:
            continue
        stamp.append(f"{source.name} {info.st_size} {info.st_mtime_ns}")
    return "\n".join(stamp).encode()


@cache
def standard_library() -> Library:
    """The shipped standard library, read once per process (a library is a value: sharing it is safe)."""
    return load_library()
