"""ros.reader: what a bag reader's failure says, in words a person can act on."""

from __future__ import annotations

from seal_cli.ros.reader import damage


def test_a_bag_that_ends_where_a_record_should_begin_is_said_cut_short() -> None:
    """An MCAP of its magic alone: rosbags' "ord() expected a character, but string of length 0 found" (hostile31)."""
    for failure in (TypeError("ord() expected a character, but string of length 0 found"), EOFError()):
        said = damage(failure)
        assert said.startswith("the bag is cut short") and "ord()" not in said
    assert damage(ValueError("File end magic is invalid.")) == "File end magic is invalid."
    assert damage(KeyError("60673")).startswith("the bag is damaged")
