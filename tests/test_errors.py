"""errors: where a problem is, printed as compilers print it, and several problems sorted."""

from __future__ import annotations

from seal_cli.errors import SealError, SealErrors, Where, caret


def test_where_prints_file_line_column_or_the_place_in_a_typed_command() -> None:
    assert str(Where("lib.yaml", 3, 7)) == "lib.yaml:3:7"
    assert str(Where("lib.yaml", 3)) == "lib.yaml:3" and str(Where("lib.yaml")) == "lib.yaml"
    assert str(Where(None, None, 5)) == "column 5" and str(Where(None, 2, 5)) == "line 2, column 5"
    assert str(Where()) == "<input>" and str(Where(None, 4)) == "line 4"


def test_an_error_shows_its_source_line_with_a_caret_and_its_hint() -> None:
    error = SealError("unexpected '}'", Where("a.frame", 2, 5), source_line="  x }\n", hint="close the frame")
    assert str(error) == "a.frame:2:5: unexpected '}'\n  x }\n    ^\nclose the frame"
    assert error.to_json() == {"file": "a.frame", "line": 2, "column": 5, "message": "unexpected '}'"}
    assert str(SealError("no position")) == "no position" and SealError("x").where == Where()


def test_the_caret_keeps_tabs_so_it_lines_up() -> None:
    assert caret("\tab c", 4) == "\tab c\n\t  ^"


def test_control_characters_are_shown_escaped_and_the_caret_still_lines_up() -> None:
    """A NUL, an escape sequence or a carriage return in a source line, a message or a file name acted on the terminal
    (hostile31); the JSON of the error keeps them as they are."""
    assert caret("a\x00b\x1b[2Jc", 3) == "a\\x00b\\x1b[2Jc\n     ^"
    error = SealError("name 'x\ry' is odd", Where("f\x1b.yaml", 1, 2))
    assert str(error) == "f\\x1b.yaml:1:2: name 'x\\ry' is odd" and error.to_json()["message"] == "name 'x\ry' is odd"
    assert str(SealError("two\n\tlines")) == "two\n\tlines"


def test_several_errors_are_sorted_by_file_line_and_column() -> None:
    errors = SealErrors([SealError("c", Where("b", 1, 1)), SealError("b", Where("a", 2, 1)),
                         SealError("a", Where("a", 1, 9))])
    assert [p.message for p in errors.problems] == ["a", "b", "c"]
    assert errors.message == "3 problems" and errors.where == Where("a", 1, 9)
    assert str(errors) == "a:1:9: a\na:2:1: b\nb:1:1: c"
    assert errors.to_json() == {"problems": [p.to_json() for p in errors.problems]}
    assert SealErrors([SealError("one")]).message == "1 problem"
    assert isinstance(errors, SealError)


def test_a_long_source_line_is_cut_around_the_column() -> None:
    """20,000 brackets on one line: the message shows a window around the column, the caret under it."""
    from seal_cli.errors import EXCERPT

    line = "[" * 10_000 + "x" + "]" * 10_000
    shown, mark = caret(line, 10_001).split("\n")
    assert shown.startswith("…") and shown.endswith("…") and len(shown) == EXCERPT + 2
    assert shown[len(mark) - 1] == "x" and mark.strip() == "^"
    start, _ = caret("y" + "a" * 500, 1).split("\n")
    assert start.startswith("y") and start.endswith("…") and caret("short", 3) == "short\n  ^"


def test_a_printed_message_cuts_overlong_words_and_length_but_json_keeps_it_whole() -> None:
    from seal_cli.errors import MESSAGE, WORD, readable

    name = "b" + "e" * 20_000 + "droom"
    error = SealError(f"prior of spoon names 'bedroom'; rooms: {name}, kitchen", Where("m.yaml", 3, 4))
    shown = str(error)
    assert shown.startswith("m.yaml:3:4: prior of spoon names 'bedroom'; rooms: beee") and shown.endswith(" kitchen")
    assert max(len(word) for word in shown.split()) == WORD
    assert error.to_json()["message"] == error.message  # whole, for a program
    assert len(readable("x " * 10_000)) == MESSAGE and readable("short words stay") == "short words stay"


def test_a_commands_error_is_placed_at_its_line_of_the_file_it_came_from() -> None:
    from seal_cli.errors import at_line

    typed = SealError("unknown verb 'flibber'", Where(None, None, 1), source_line="flibber the garage")
    moved = at_line(typed, "c.txt", 3, "  flibber the garage\r\n")   # the line as read: indented, CRLF
    assert str(moved) == "c.txt:3:3: unknown verb 'flibber'\n  flibber the garage\n  ^"
    other = SealError("no room", Where("m.yaml", 4, 2))              # the map's own problem stays at the map
    assert at_line(other, "c.txt", 3, "x") is other
    assert str(at_line(SealError("too many"), "c.txt", 7, "x")) == "c.txt:7: too many"
