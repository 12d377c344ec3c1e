"""The two ways to write a library, YAML and the .frame DSL, load to equal frames.

Every shipped frame is converted into the other form and back, and the results compared with
what was shipped; the DSL grammar is also built with ``strict=True`` to prove it conflict-free.
"""

from __future__ import annotations

from pathlib import Path

import pytest

from seal_cli.errors import Where
from seal_cli.frames.formats import dsl
from seal_cli.frames.formats import yamlfile as yamlformat
from seal_cli.frames.library import Library
from seal_cli.frames.reading import frame_files, read_files
from seal_cli.resources import framelib_dir

SPEC_YAML = """\
frame: Stir                       # one frame per mapping; a file may hold a list under `frames:`
description: Stir the contents of a container with a utensil.
framenet: Cause_to_amalgamate     # optional provenance
lexical_units: [stir, mix]        # verb lemmas (multiword allowed: "pick up") that evoke the frame
elements:                         # frame elements, FrameNet-style role names
  theme:      {type: container}
  instrument: {type: utensil, default: spoon}   # filled from the default when the command omits it
preconditions: [holding(instrument)]            # ORDERED facts that must hold before the actions
actions: [navigate(theme), stir(instrument, theme)]  # primitive robot actions, in order
postconditions: [stirred(theme)]                # facts that hold afterwards; `not f(x)` deletes
"""

SPEC_DSL = """\
frame Stir "stir" "mix" {
  theme: container
  instrument: utensil = spoon
  requires holding(instrument)
  do navigate(theme), stir(instrument, theme)
  ensures stirred(theme)
}
"""


def test_the_spec_examples_say_the_same_thing() -> None:
    from_yaml = yamlformat.read(SPEC_YAML, "spec.yaml")
    from_dsl = dsl.read(SPEC_DSL, "spec.frame")
    assert from_yaml.problems == [] and from_dsl.problems == []
    (stir_yaml,), (stir_dsl,) = from_yaml.frames, from_dsl.frames
    assert [str(a) for a in stir_yaml.actions] == ["navigate(theme)", "stir(instrument, theme)"]
    # The DSL example leaves out description and provenance; otherwise the frames are equal.
    assert stir_yaml == stir_dsl.__class__(**{**stir_dsl.__dict__, "description": stir_yaml.description,
                                              "framenet": stir_yaml.framenet})


def test_positions_point_at_the_source() -> None:
    (frame,) = yamlformat.read(SPEC_YAML, "spec.yaml").frames
    assert frame.where == Where("spec.yaml", 1, 8)
    assert frame.preconditions[0].where == Where("spec.yaml", 8, 17)
    assert frame.element("instrument").where == Where("spec.yaml", 7, 3)
    (frame,) = dsl.read(SPEC_DSL, "spec.frame").frames
    assert frame.where == Where("spec.frame", 1, 7)
    assert frame.actions[1].where == Where("spec.frame", 5, 23)


def shipped() -> Library:
    contents = read_files(frame_files([framelib_dir()])[0])
    assert contents.problems == []
    return Library(tuple(contents.frames), contents.taxonomy)


def test_every_shipped_frame_survives_yaml_to_dsl_and_back() -> None:
    library = shipped()
    assert len(library) == 25
    as_dsl = dsl.read(dsl.dump(library.frames, library.taxonomy), "converted.frame")
    assert as_dsl.problems == []
    assert tuple(as_dsl.frames) == library.frames
    assert as_dsl.taxonomy == library.taxonomy
    back = yamlformat.read(yamlformat.dump(as_dsl.frames, as_dsl.taxonomy), "back.yaml")
    assert back.problems == []
    assert tuple(back.frames) == library.frames
    assert back.taxonomy == library.taxonomy


@pytest.mark.parametrize("path", frame_files([framelib_dir()])[0], ids=lambda p: p.name)
def test_each_shipped_file_converts_both_ways(path: Path) -> None:
    text = path.read_text()
    original = (dsl.read if path.suffix == ".frame" else yamlformat.read)(text, str(path))
    assert original.problems == []
    for write, read in ((dsl.dump, dsl.read), (yamlformat.dump, yamlformat.read)):
        again = read(write(original.frames, original.taxonomy), "converted")
        assert again.problems == [] and again.frames == original.frames and again.taxonomy == original.taxonomy


def test_the_dsl_grammar_is_strict_lalr() -> None:
    parser = dsl.parser(strict=True)
    assert parser.options.parser == "lalr"
    assert parser.parse(SPEC_DSL)


def test_yaml_accepts_single_scalars_and_frame_lists() -> None:
    text = "frames:\n  - frame: Wave\n    lexical_units: wave\n    elements: {theme: person}\n"
    contents = yamlformat.read(text, "x.yaml")
    assert contents.problems == []
    assert contents.frames[0].lexical_units[0].text == "wave"
    assert contents.frames[0].element("theme").type == "person"


def test_yaml_strings_with_special_characters_round_trip() -> None:
    frame = yamlformat.read('frame: Odd\ndescription: "Says: hello, [world] # not a comment"\n', "o.yaml").frames[0]
    again = yamlformat.read(yamlformat.dump([frame]), "again.yaml").frames[0]
    assert again.description == "Says: hello, [world] # not a comment"
    again = dsl.read(dsl.dump([frame]), "again.frame").frames[0]
    assert again.description == frame.description


def test_open_categories_and_world_facts_in_both_forms() -> None:
    yaml_text = "categories:\n  thing: ~\n  utensil: [spoon, Fork]\nworld: [hand_empty]\n"
    dsl_text = "category thing = *\ncategory utensil = spoon, fork\nworld hand_empty\n"
    assert yamlformat.read(yaml_text).taxonomy == dsl.read(dsl_text).taxonomy


def test_synonyms_in_both_forms() -> None:
    yaml_text = "synonyms:\n  Fridge: [refrigerator, ice box]\n  sofa: couch\n"
    dsl_text = "synonyms fridge = refrigerator, ice_box\nsynonyms sofa = couch\n"
    from_yaml, from_dsl = yamlformat.read(yaml_text), dsl.read(dsl_text)
    assert from_yaml.problems == [] and from_dsl.problems == []
    assert from_yaml.taxonomy == from_dsl.taxonomy
    assert from_yaml.taxonomy.names["ice_box"] == (
        "fridge", "refrigerator")
    for write, read in ((yamlformat.dump, yamlformat.read), (dsl.dump, dsl.read)):
        again = read(write([], from_yaml.taxonomy), "again")
        assert again.problems == [] and again.taxonomy == from_yaml.taxonomy
