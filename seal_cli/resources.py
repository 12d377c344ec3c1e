"""Where the shipped grammars, frame library and maps are.

In a wheel they live inside the package (``seal_cli/_data/...``, put there by hatchling's
``force-include``); in a checkout or an editable install they are the project's top-level
``grammars/``, ``framelib/`` and ``maps/`` folders.
"""

from __future__ import annotations

from pathlib import Path

from seal_cli.errors import SealError

__all__ = ["data_dir", "framelib_dir", "grammar_path", "map_path", "maps_dir"]

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


def map_path(name: str) -> Path:
    """A map file by path, or by the name of a shipped map (``apartment``)."""
    path = Path(name)
    if path.exists():
        return path
    shipped = maps_dir() / (name if name.endswith((".yaml", ".yml")) else f"{name}.yaml")
    return shipped if shipped.exists() else path
