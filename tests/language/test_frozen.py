"""frozen.quick_init: the same frozen dataclass objects, made quicker."""

from __future__ import annotations

import dataclasses
from dataclasses import dataclass, field

import pytest

from seal_cli.language.frozen import quick_init
from seal_cli.language.values import Evoked, Parse, Phrase


@dataclass(frozen=True)
class _Plain:
    a: int
    b: str = "b"
    c: list[int] = field(default_factory=list)
    d: tuple[int, int] | None = field(default=None, compare=False)


@quick_init
@dataclass(frozen=True)
class _Quick:
    a: int
    b: str = "b"
    c: list[int] = field(default_factory=list)
    d: tuple[int, int] | None = field(default=None, compare=False)


@quick_init
@dataclass(frozen=True)
class _Checked:
    a: int

    def __post_init__(self) -> None:
        if self.a < 0:
            raise ValueError("negative")


def test_quick_objects_are_the_generated_init_s() -> None:
    for args, kwargs in [((1,), {}), ((1, "x"), {}), ((2,), {"c": [3], "d": (1, 2)}), ((), {"a": 4, "b": "y"})]:
        plain, quick = _Plain(*args, **kwargs), _Quick(*args, **kwargs)   # type: ignore[arg-type]
        assert vars(plain) == vars(quick)
        assert dataclasses.astuple(plain) == dataclasses.astuple(quick)
    assert _Quick(1).c == [] and _Quick(1).c is not _Quick(1).c          # a fresh list each time, as before
    assert _Quick(1, d=(1, 2)) == _Quick(1, d=(3, 4)) and _Quick(1) != _Quick(2)   # compare=False kept
    assert dataclasses.replace(_Quick(1, "x"), a=2) == _Quick(2, "x")
    with pytest.raises(dataclasses.FrozenInstanceError):
        _Quick(1).a = 2                                                     # type: ignore[misc]
    with pytest.raises(TypeError):
        _Quick()                                                            # type: ignore[call-arg]
    with pytest.raises(ValueError, match="negative"):
        _Checked(-1)                                                        # __post_init__ still runs


def test_only_frozen_dataclasses_of_plain_fields_are_taken() -> None:
    @dataclass
    class Mutable:
        a: int

    @dataclass(frozen=True, slots=True)
    class Slotted:
        a: int

    @dataclass(frozen=True)
    class KeywordOnly:
        a: int = field(kw_only=True)

    for cls in (Mutable, Slotted, KeywordOnly, int):
        with pytest.raises(TypeError, match="quick_init"):
            quick_init(cls)


def test_the_values_of_a_parse_are_made_quickly_and_stay_frozen() -> None:
    phrase = Phrase("the cup", "cup", "Cup", span=(4, 11))
    assert phrase == Phrase("the cup", "cup", "Cup") and phrase.kind == "thing" and phrase.conjuncts == ()
    assert hash(phrase) == hash(Phrase("the cup", "cup", "Cup"))
    assert dataclasses.replace(phrase, preposition="on").preposition == "on"
    evoked = Evoked("Pick", "pick up", (0, 7), {"theme": phrase})
    assert Parse("pick up the cup", (evoked,)).to_json()["frames"][0]["elements"]["theme"]["class"] == "Cup"
    with pytest.raises(dataclasses.FrozenInstanceError):
        evoked.frame = "Place"                                              # type: ignore[misc]
