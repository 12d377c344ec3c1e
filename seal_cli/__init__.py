"""seal: Semantic Frame Execution And Localization.

Commands are parsed into semantic frames from a declarative frame library, ordered by a
planner so that every precondition holds, and localised on a room-annotated map by SeFM, a
particle filter over where each frame can be executed.

This module is the public API (see docs/api.md)::

    import numpy as np
    import seal_cli as seal

    the_map = seal.load_map("apartment")               # a path, or the name of a shipped map
    sefm = seal.localise(the_map, ["stir the cup"], rng=np.random.default_rng(0))
    sefm.update((1.0, 2.0, 0.0), [seal.Detection("cup", (1.5, 2.2))])
    sefm.frame_summary(0).rooms

Names are loaded when first used, so that ``import seal_cli`` (and ``seal --version``) stays cheap.
"""

from __future__ import annotations

import importlib
from typing import TYPE_CHECKING, Any

from seal_cli.errors import SealError, SealErrors, Where

__version__ = "0.1.0"

_HOMES = {
    "seal_cli.frames.model": ("Action", "Binding", "Element", "Fact", "Frame", "LexicalUnit"),
    "seal_cli.frames.taxonomy": ("Category", "Taxonomy", "class_key"),
    "seal_cli.frames.library": ("Library",),
    "seal_cli.frames.reading": ("load_library", "read_library", "standard_library"),
    "seal_cli.language.grounding": ("Vocabulary", "load_vocabulary"),
    "seal_cli.language.parser": ("Evoked", "Parse", "Phrase"),
    "seal_cli.planning.state": ("State",),
    "seal_cli.planning.plan": ("Plan", "Step"),
    "seal_cli.maps.model": ("Map",),
    "seal_cli.maps.formats.map_server": ("load_map",),
    "seal_cli.sensing.sensor": ("Detection",),
    "seal_cli.sensing.model": ("simulate_detections",),
    "seal_cli.sensing.observations": ("Observation",),
    "seal_cli.sefm.filter": ("Observer", "SeFM", "SeFMConfig"),
    "seal_cli.pipeline": ("localise", "parse", "plan"),
}
"""Where each lazily loaded public name lives."""

_WHERE = {name: module for module, names in _HOMES.items() for name in names}

__all__ = ["Action", "Binding", "Category", "Detection", "Element", "Evoked", "Fact", "Frame", "LexicalUnit",
           "Library", "Map", "Observation", "Observer", "Parse", "Phrase", "Plan", "SeFM", "SeFMConfig", "SealError",
           "SealErrors", "State", "Step", "Taxonomy", "Vocabulary", "Where", "__version__", "class_key",
           "load_library", "load_map", "load_vocabulary", "localise", "parse", "plan", "read_library",
           "simulate_detections", "standard_library"]

if TYPE_CHECKING:
    from seal_cli.frames.library import Library
    from seal_cli.frames.model import Action, Binding, Element, Fact, Frame, LexicalUnit
    from seal_cli.frames.reading import load_library, read_library, standard_library
    from seal_cli.frames.taxonomy import Category, Taxonomy, class_key
    from seal_cli.language.grounding import Vocabulary, load_vocabulary
    from seal_cli.language.parser import Evoked, Parse, Phrase
    from seal_cli.maps.formats.map_server import load_map
    from seal_cli.maps.model import Map
    from seal_cli.pipeline import localise, parse, plan
    from seal_cli.planning.plan import Plan, Step
    from seal_cli.planning.state import State
    from seal_cli.sefm.filter import Observer, SeFM, SeFMConfig
    from seal_cli.sensing.model import simulate_detections
    from seal_cli.sensing.observations import Observation
    from seal_cli.sensing.sensor import Detection


def __getattr__(name: str) -> Any:
    """Load a public name from its home module on first use (PEP 562)."""
    module = _WHERE.get(name)
    if module is None:
        raise AttributeError(f"module 'seal_cli' has no attribute {name!r}")
    value = getattr(importlib.import_module(module), name)
    globals()[name] = value
    return value


def __dir__() -> list[str]:
    return sorted(set(globals()) | set(__all__))
