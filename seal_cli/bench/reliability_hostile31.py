"""Round hostile31's hostile inputs of ``seal bench reliability`` (an attacker's, as
:mod:`seal_cli.bench.reliability_attacker`'s, kept apart from that long list): what hostile30 left (a NUL or another
control character in a ``.frame`` file's comment was read as part of the comment, silently), then the kinds older
rounds held fewest of."""

from __future__ import annotations

from collections.abc import Iterator

from seal_cli.bench.reliability import Case

__all__ = ["hostile31_cases", "hostile31_leftover_cases"]

WHISK = b'category object = cup, bowl\nframe Whisk "whisk" {\n  theme: object\n  do navigate(theme)\n}\n'
"""A frame file of one category and one frame that validates alone."""

RAW = r"[\x00-\x08\x0b-\x1f\x7f]"
"""A control character other than a tab or a line break: what must never reach the terminal as it is."""


def hostile31_leftover_cases() -> Iterator[Case]:
    """Round hostile31's first batch, what hostile30 left: a ``.frame`` file holding a NUL (or an escape, a
    backspace, a DEL) in a comment was read, the character passed over with the comment; one in a name or between
    two facts was "the frame is not closed", its line printed with the character as it is."""
    def frame_case(name: str, data: bytes, says: str, argv: tuple[str, ...] = ("validate", "f.frame")) -> Case:
        return Case(f"A {argv[0]} of a .frame file {name}", argv, (("f.frame", data),), codes=(1,),
                    keep=("f.frame",), says=says, unsaid=RAW)
    yield frame_case("with a NUL in a '#' comment", WHISK.replace(b"{\n", b"{\n  # a NUL \x00 here\n"),
                     r"f\.frame:3:11: .*U\+0000")
    yield frame_case("with a NUL in a '//' comment", WHISK.replace(b"{\n", b"{\n  // \x00\n"),
                     r"f\.frame:3:6: .*U\+0000", ("plan", "whisk the cup", "--framelib", "+f.frame"))
    yield frame_case("with an escape sequence in a comment", b"# \x1b[2J\x1b[31mred\n" + WHISK,
                     r"f\.frame:1:3: .*U\+001B")
    yield frame_case("with a NUL inside a name", WHISK.replace(b"theme: object", b"theme: obj\x00ect"),
                     r"f\.frame:3:13: .*U\+0000")
    yield frame_case("with a backspace between two frames", WHISK + b"\x08\n" + WHISK.replace(b"Whisk", b"Beat"),
                     r"f\.frame:6:1: .*U\+0008")
    yield frame_case("with a DEL at the end of a comment at the end", WHISK + b"// end\x7f",
                     r"f\.frame:6:7: .*U\+007F")


def hostile31_cases() -> Iterator[Case]:
    """Round hostile31's later batches (none yet)."""
    yield from ()
