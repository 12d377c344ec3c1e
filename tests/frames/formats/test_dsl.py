"""frames.formats.dsl: the ``.frame`` DSL read with positions; syntax errors say what was expected."""

from __future__ import annotations

import pytest

from seal_cli.frames.formats import dsl
from seal_cli.frames.formats.dsl import dump, read
from seal_cli.frames.reading import standard_library

WAVE = ('frame Wave "wave" "wave at" {\n  theme: person\n  do navigate(theme), greet(theme)\n'
        '  ensures greeted(theme)\n}\n')


def test_a_frame_reads_with_its_position_and_units() -> None:
    (frame,) = read(WAVE, "w.frame").frames
    assert frame.name == "Wave" and [u.text for u in frame.lexical_units] == ["wave", "wave at"]
    assert [str(a) for a in frame.actions] == ["navigate(theme)", "greet(theme)"]
    assert frame.where is not None and (frame.where.file, frame.where.line) == ("w.frame", 1)


def test_a_syntax_error_is_located_and_says_what_to_write() -> None:
    (problem,) = read('frame Wave "wave" {\n  theme person\n}\n', "w.frame").problems
    assert (problem.file, problem.line, problem.column) == ("w.frame", 2, 9)
    assert problem.message.startswith("syntax error") and "'role: category'" in problem.message
    (cut,) = read(WAVE[: WAVE.index("}")], "w.frame").problems
    assert "end of file" in cut.message and "'}'" in cut.message and cut.file == "w.frame"



def test_a_file_of_cr_or_crlf_lines_reads_as_one_of_lf_lines() -> None:
    # with CR alone the file was one line, its first '//' comment all of it: "ok: 0 frames" (hostile22)
    commented = "// waving at people\n" + WAVE
    for end in ("\r", "\r\n"):
        (frame,) = read(commented.replace("\n", end), "w.frame").frames
        assert frame.name == "Wave" and frame.where is not None and frame.where.line == 2
        (problem,) = read('frame Wave "wave" {\n  theme person\n}\n'.replace("\n", end), "w.frame").problems
        assert (problem.line, problem.column) == (2, 9) and str(problem).endswith("  theme person\n        ^")


def test_a_caret_is_under_the_line_named_when_a_comment_holds_a_form_feed() -> None:
    (problem,) = read('// a\x0cb\u2028c\nframe Wave "wave" {\n  theme person\n}\n', "w.frame").problems
    assert problem.line == 3 and str(problem).endswith("  theme person\n        ^")

@pytest.mark.parametrize(("text", "line", "column", "code"), [
    ("// a NUL \x00 here\n" + WAVE, 1, 10, 0), ("# \x1b[31m\n" + WAVE, 1, 3, 0x1B), (WAVE + "\x7f", 6, 1, 0x7F),
    (WAVE.replace("theme: person", "theme: per\x00son"), 2, 13, 0), (WAVE.replace("{", "{\x85"), 1, 30, 0x85)])
def test_a_control_character_anywhere_is_refused_at_it_even_in_a_comment(text: str, line: int, column: int,
                                                                           code: int) -> None:
    """In a comment a NUL was read with the comment, silently; in a name it was "the frame is not closed" (hostile31).
    The line is shown with the character escaped, the caret under it."""
    (problem,) = read(text, "w.frame").problems
    assert (problem.file, problem.line, problem.column) == ("w.frame", line, column)
    assert f"U+{code:04X}" in problem.message and "not even in a comment" in problem.message
    shown = str(problem).split("\n")
    assert not any(ch in "".join(shown) for ch in "\x00\x1b\x7f\x85")
    assert shown[2].index("^") == shown[1].index("\\x")


def test_a_bad_name_is_refused_where_it_is() -> None:
    (problem,) = read("frame wave {}\n", "w.frame").problems
    assert problem.line == 1 and problem.column == 7 and "capital letter" in problem.message


def test_a_name_in_other_letters_says_so_not_that_a_comma_is_missing() -> None:
    # 'thème' was "a comma is missing between two facts or actions (found 'è')" (hostile16)
    (problem,) = read('frame Wave "wave" { thème: person\n do navigate(thème) }\n', "w.frame").problems
    assert (problem.line, problem.column) == (1, 23)
    assert problem.message.startswith("syntax error: a name in a .frame file is written in the letters A-Z and a-z")
    assert "(found 'è')" in problem.message and "comma" not in problem.message


def test_a_lexical_unit_in_other_letters_says_which_letters() -> None:
    (problem,) = read('frame Wave "zäp" { theme: person\n do navigate(theme) }\n', "w.frame").problems
    assert problem.message == "lexical unit 'zäp' must be one or more words of letters a-z (with ' or - inside)"


def test_dump_reads_back_to_the_same_frames() -> None:
    library = standard_library()
    text = dump(list(library.frames), library.taxonomy)
    again = read(text, "dumped.frame")
    assert again.problems == [] and tuple(again.frames) == library.frames
    assert dsl.parser() is dsl.parser()                         # built once per process


def test_a_file_of_more_words_than_the_bound_is_refused_before_it_is_parsed(monkeypatch: pytest.MonkeyPatch) -> None:
    """A category of a million members on a line of 10 MB took minutes to parse (hostile26): past
    :data:`dsl.MAX_WORDS` names and units (comments not counted) the file is refused at the first word past it."""
    monkeypatch.setattr(dsl, "MAX_WORDS", 5)
    found = read("// one two three four five six\ncategory c = a, b, d, e\n", "w.frame")
    [problem] = found.problems
    assert (problem.where.line, problem.where.column) == (2, 23) and "more than 5 names" in problem.message
    assert read("category c = a, b\n", "w.frame").problems == []
