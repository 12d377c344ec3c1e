"""Where the shipped grammars, frame library and maps are.

In a wheel they live inside the package (``seal_cli/_data/...``, put there by hatchling's
``force-include``); in a checkout or an editable install they are the project's top-level
``grammars/``, ``framelib/`` and ``maps/`` folders.
"""

from __future__ import annotations

from pathlib import Path

from seal_cli.errors import SealError

__all__ = ["data_dir", "framelib_dir", "grammar_path", "map_path", "maps_dir", "shipped_maps"]

_PACKAGE = Path(__file__).resolve().parent


def data_dir(name: str) -> Path:
    """The shipped folder ``name`` (``grammars``, ``framelib`` or ``maps``)."""
    for candidate in (_PACKAGE / "_data" / name, _PACKAGE.parent / name):
        if candidate.is_dir():
            return candidate
    raise SealError(f"the shipped folder {name!r} is missing from this installation "
                    f"(looked in {_PACKAGE / '_data'} and {_PACKAGE.parent}); reinstall seal")


def grammar_path(name: str) -> Path:
    return data_dir("grammars") / name


def framelib_dir() -> Path:
    return data_dir("framelib")


def maps_dir() -> Path:
    return data_dir("maps")


def shipped_maps() -> list[str]:
    """The names of the maps shipped with seal."""
    return sorted(p.stem for p in maps_dir().glob("*.yaml"))


def map_path(name: str) -> Path:
    """A map file by path, or by the name of a shipped map (``apartment``: a plain name, no folder).
    A name that is neither is a SealError listing the shipped maps (the closest first)."""
    import difflib
    import os

    if not name.strip():
        raise SealError(f"the map's name is empty: give a map file or a shipped map ({', '.join(shipped_maps())})")
    path = Path(name)
    try:
        if os.path.lexists(path) or os.sep in name or (os.altsep or os.sep) in name:
            return path  # a path: the reader says what is wrong with it
    except (OSError, ValueError):
        return path
    shipped = maps_dir() / (name if name.endswith((".yaml", ".yml")) else f"{name}.yaml")
    try:
        if shipped.exists():
            return shipped
    except (OSError, ValueError):  # a name too long for the file system is no shipped map (nor seal's folder's)
        pass
    names = shipped_maps()
    close = difflib.get_close_matches(name.lower().removesuffix(".yaml"), names, n=1)
    if name == "-":
        from seal_cli.fileio import stdin_hint

        raise SealError(f"-: no such map file{stdin_hint(name)}")
    from seal_cli.fileio import gone_cwd_hint

    raise SealError(f"{name}: no such map file{gone_cwd_hint(name)}, nor a map shipped with seal"
                    f"{f' (did you mean {close[0]!r}?)' if close else ''}; shipped maps: {', '.join(names)}")
