"""seal: Semantic Frame Execution And Localization.

Commands are parsed into semantic frames from a declarative frame library, ordered by a
planner so that every precondition holds, and localised on a room-annotated map by SeFM, a
particle filter over where each frame can be executed.
"""

from __future__ import annotations

from seal_cli.errors import SealError, SealErrors, Where
from seal_cli.frames.library import Library
from seal_cli.frames.model import Action, Binding, Element, Fact, Frame, LexicalUnit
from seal_cli.frames.reading import load_library, read_library
from seal_cli.frames.taxonomy import Category, Taxonomy, class_key

__version__ = "0.1.0"

__all__ = ["Action", "Binding", "Category", "Element", "Fact", "Frame", "LexicalUnit", "Library", "SealError",
           "SealErrors", "Taxonomy", "Where", "__version__", "class_key", "load_library", "read_library"]
