"""A frame library: frames indexed by name and by lexical unit, with the taxonomy of their types.

A value: it reads no file. Reading frame files into a library is :mod:`seal_cli.frames.reading`.
"""

from __future__ import annotations

from collections.abc import Iterator, Mapping
from dataclasses import dataclass, field
from functools import cached_property

from seal_cli.errors import SealError
from seal_cli.frames.model import Frame, normalize_unit
from seal_cli.frames.taxonomy import Taxonomy

__all__ = ["Library"]


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
            import difflib

            close = difflib.get_close_matches(name.lower(), list(folded), n=1, cutoff=0.5)
            hint = f" (did you mean {folded[close[0]].name!r}?)" if close else ""
            raise SealError(f"unknown frame {name!r}{hint}; the library has {', '.join(sorted(self.by_name))}"
                            ) from None

    def evoked_by(self, unit: str) -> tuple[Frame, ...]:
        """The frames a lexical unit evokes (empty when none does)."""
        return self.by_unit.get(normalize_unit(unit), ())

    def achievers(self, predicate: str) -> tuple[Frame, ...]:
        """Frames with a positive postcondition of this predicate."""
        return tuple(f for f in self.frames
                     if any(p.predicate == predicate and not p.negated for p in f.postconditions))
