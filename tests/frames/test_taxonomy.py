"""Categories, open categories, and how class names compare."""

from __future__ import annotations

from hypothesis import given
from hypothesis import strategies as st

from seal_cli.frames.taxonomy import Taxonomy, class_key, class_words


def test_class_names_compare_across_spellings() -> None:
    assert class_key("SinkBasin") == class_key("sink_basin") == class_key("sink basin") == class_key("Sink-Basin")
    assert class_words("AlarmClock") == ("alarm", "clock")
    assert class_words("TVStand") == ("tv", "stand")
    assert class_key("CD") == "cd"


@given(st.lists(st.sampled_from(["sink", "basin", "alarm", "clock", "x2"]), min_size=1, max_size=3))
def test_class_key_ignores_separators_and_case(words: list[str]) -> None:
    spellings = ["_".join(words), " ".join(words), "-".join(words), "".join(w.capitalize() for w in words)]
    assert len({class_key(s) for s in spellings}) == 1


TAXONOMY = Taxonomy.of({"thing": None, "utensil": ["spoon", "cutter"], "cutter": ["knife", "ButterKnife"],
                        "person": ["man", "woman"]})


def test_membership_follows_nested_categories() -> None:
    assert TAXONOMY.is_a("knife", "utensil") is True
    assert TAXONOMY.is_a("butter_knife", "utensil") is True
    assert TAXONOMY.members("utensil") == {"spoon", "knife", "butter_knife"}


def test_membership_is_three_valued() -> None:
    assert TAXONOMY.is_a("spoon", "person") is False       # listed elsewhere: known not to be one
    assert TAXONOMY.is_a("teapot", "person") is None       # nobody listed it: open vocabulary
    assert TAXONOMY.is_a("teapot", "thing") is True        # open categories hold everything
    assert TAXONOMY.is_a("utensil", "utensil") is True


def test_merging_takes_the_union_of_members() -> None:
    merged = TAXONOMY.merged(Taxonomy.of({"utensil": ["ladle"]}, world=["hand_empty"]))
    assert merged.members("utensil") == {"spoon", "knife", "butter_knife", "ladle"}
    assert merged.world == ("hand_empty",)
    assert "Utensil" in merged


def test_nested_cycles_do_not_loop() -> None:
    looped = Taxonomy.of({"a": ["b", "x"], "b": ["a", "y"]})
    assert looped.members("a") == {"x", "y"}


def test_synonyms_are_sets_of_names_merged_across_entries() -> None:
    from seal_cli.frames.taxonomy import Synonyms

    taxonomy = Taxonomy(synonyms=(Synonyms("Fridge", ("refrigerator", "ice box")),)).merged(
        Taxonomy(synonyms=(Synonyms("fridge", ("icebox",)), Synonyms("sofa", ("couch",)))))
    assert taxonomy.names["refrigerator"] == ("fridge", "ice_box", "icebox")    # any name gives the others
    assert taxonomy.names["fridge"] == ("refrigerator", "ice_box", "icebox")
    assert taxonomy.names["couch"] == ("sofa",)
    assert "chair" not in taxonomy.names


def test_bad_synonym_entries_are_refused() -> None:
    import pytest

    from seal_cli.errors import SealError
    from seal_cli.frames.taxonomy import Synonyms

    for name, names, words in [("rug", (), "no other name"), ("mat", ("Mat",), "its own synonyms"),
                               ("mat", ("rug", "rug"), "repeat rug"), ("", ("x",), "needs a class name"),
                               ("knife", ("chef's knife",), "is not a name")]:
        with pytest.raises(SealError, match=words):
            Synonyms(name, names)


def test_a_category_member_that_is_a_number_is_refused() -> None:
    import pytest

    from seal_cli.errors import SealError
    from seal_cli.frames.taxonomy import Category

    for odd in ("0x10", "1e309", "5"):
        with pytest.raises(SealError, match=f"category container: '{odd}' is not a class name"):
            Category("container", ("cup", odd))
    assert Category("container", ("cup", "café", "Sink Basin")).members == ("cup", "café", "sink_basin")


def test_a_class_name_longer_than_the_bound_is_refused() -> None:
    import pytest

    from seal_cli.errors import SealError
    from seal_cli.frames.taxonomy import MAX_CLASS_NAME, check_class_name

    assert check_class_name("x" * MAX_CLASS_NAME, "holding") == "x" * MAX_CLASS_NAME
    with pytest.raises(SealError, match=r"holding 'x{40}'… is 3,000 characters long; a class name has at most 100"):
        check_class_name("x" * 3_000, "holding")


def test_kin_is_the_smallest_closed_category_that_lists_the_class() -> None:
    taxonomy = Taxonomy.of({"thing": None, "container": ["cup", "mug", "bowl", "vessel"], "vessel": ["cup", "mug"],
                            "utensil": ["spoon"]})
    assert taxonomy.kin("cup") == ("vessel", frozenset({"mug"}))          # not container, which is larger
    assert taxonomy.kin("bowl") == ("container", frozenset({"cup", "mug"}))
    assert taxonomy.kin("spoon") is None                                   # alone in its category
    assert taxonomy.kin("remote") is None                                  # listed nowhere
