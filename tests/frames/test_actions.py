"""frames.actions: the registry of primitive actions that frames and the simulator share."""

from __future__ import annotations

from seal_cli.frames.actions import PRIMITIVES, Primitive
from seal_cli.frames.reading import standard_library


def test_each_primitive_is_registered_under_its_name_with_its_meaning() -> None:
    assert all(isinstance(p, Primitive) and p.name == name and p.meaning for name, p in PRIMITIVES.items())
    assert PRIMITIVES["place"].params == ("object", "receptacle") and PRIMITIVES["place"].arity == 2
    assert PRIMITIVES["navigate"].arity == 1


def test_the_standard_library_uses_only_primitives_with_their_arity() -> None:
    used = {(a.name, len(a.args)) for frame in standard_library() for a in frame.actions}
    assert used and all(PRIMITIVES[name].arity == arity for name, arity in used)
    assert {name for name, _ in used} >= {"navigate", "pick", "place", "open", "stir"}
