"""An open ROS bag: its topics and its messages deserialised, every failure one SealError naming the bag.

:func:`open_bag` takes a ROS 1 ``.bag``, a ROS 2 bag folder (sqlite3 or MCAP), or a bare ``.db3`` /
``.mcap`` file, with rosbags' ``AnyReader``; the message definitions the bag embeds are used, and
:func:`~seal_cli.ros.messages.typestore` (vision_msgs included) for a bag that carries none.
"""

from __future__ import annotations

import contextlib
import itertools
from collections.abc import Iterator
from pathlib import Path
from typing import Any

from seal_cli.errors import SealError, Where
from seal_cli.fileio import read_yaml
from seal_cli.ros.messages import require_rosbags, typestore

__all__ = ["Bag", "bag_topics", "open_bag"]


class Bag:
    """An open bag: its topics, and its messages deserialised, every failure a SealError."""

    def __init__(self, reader: Any, path: Path) -> None:
        self.reader, self.path = reader, path
        self.notes: list[str] = []
        """What reading left out, for the user (:attr:`seal_cli.ros.bags.Run.notes`)."""

    @property
    def topics(self) -> dict[str, str]:
        return {c.topic: c.msgtype for c in self.reader.connections}

    def error(self, message: str) -> SealError:
        return SealError(message, Where(str(self.path)))

    def messages(self, topic: str) -> Iterator[tuple[int, float, Any]]:
        """``(index, log time s, message)`` of a topic, in log order."""
        from rosbags.highlevel import AnyReaderError
        from rosbags.serde import SerdeError

        connections = [c for c in self.reader.connections if c.topic == topic]
        try:
            for i, (connection, logged, raw) in enumerate(self.reader.messages(connections=connections)):
                try:
                    message = self.reader.deserialize(raw, connection.msgtype)
                except (AnyReaderError, SerdeError, ValueError, IndexError, KeyError) as exc:
                    raise self.error(f"message {i + 1} on {topic} ({connection.msgtype}) cannot be decoded: "
                                     f"{exc}") from None
                yield i, logged * 1e-9, message
        except SealError:
            raise
        except Exception as exc:  # rosbags' readers raise their own errors and sqlite's, lz4's, zstd's
            raise self.error(f"cannot read {topic} from the bag: {damage(exc)}") from None


    def last(self, topic: str) -> tuple[int, int, Any] | None:
        """``(count, index of the last, last message)`` of a topic (None if it has none): only the last is
        deserialised (a map being built is published hundreds of times, each a megabyte)."""
        from rosbags.highlevel import AnyReaderError
        from rosbags.serde import SerdeError

        connections = [c for c in self.reader.connections if c.topic == topic]
        found: tuple[int, Any, Any] | None = None
        count = 0
        try:
            for connection, _, raw in self.reader.messages(connections=connections):
                found = (count, connection, raw)
                count += 1
        except Exception as exc:  # rosbags' readers raise their own errors and sqlite's, lz4's, zstd's
            raise self.error(f"cannot read {topic} from the bag: {damage(exc)}") from None
        if found is None:
            return None
        i, connection, raw = found
        try:
            return count, i, self.reader.deserialize(raw, connection.msgtype)
        except (AnyReaderError, SerdeError, ValueError, IndexError, KeyError) as exc:
            raise self.error(f"message {i + 1} on {topic} ({connection.msgtype}) cannot be decoded: {exc}") from None


def damage(exc: BaseException) -> str:
    """What a reader's failure says, or, when it says nothing a person can use (a damaged index makes rosbags
    fail an ``assert`` or look up a connection id that is no key: ``''``, ``'60673'``), that the bag is damaged."""
    said = " ".join(str(a) for a in getattr(exc, "args", ())).strip()
    if isinstance(exc, EOFError) or isinstance(exc, TypeError) and "length 0" in said:
        # an MCAP of its magic alone: rosbags read a record's opcode past the end, "ord() expected a character, but
        # string of length 0 found" (hostile31)
        return "the bag is cut short: it ends where a record should begin (was it copied or recorded whole?)"
    if isinstance(exc, (AssertionError, KeyError, IndexError, MemoryError)) or not said:
        return (f"the bag is damaged: a record or its index does not hold what its header says "
                f"({type(exc).__name__}{': ' + said if said else ''}); a ROS 1 bag's index can be rebuilt with 'rosbag "
                "reindex'")
    return said


FORMATS = ((b"#ROSBAG V2.0\n", ".bag", "a ROS 1 bag"), (b"\x89MCAP0\r\n", ".mcap", "an MCAP bag"),
           (b"SQLite format 3\x00", ".db3", "a ROS 2 sqlite3 bag"))
"""Each bag file's first bytes (its format's magic), the suffix by which rosbags tells that format, and its name."""


def _check_suffix(path: Path) -> None:
    """Refuse a bag file whose first bytes say one format and whose name another (an MCAP saved as ``run.bag``, a
    ROS 1 bag without ``.bag``): rosbags picks its reader by the suffix, and the other reader's failure said nothing
    of it (``utf-8 b'\\x89MCAP0\\r\\n' 0 1 invalid start byte``)."""
    if path.is_dir() and not (path / "metadata.yaml").is_file():
        raise SealError("this folder is no ROS 2 bag: it has no metadata.yaml (a ROS 2 bag is a folder with one beside "
                        "its .db3 or .mcap files; a bare .db3 or .mcap file is read too)", Where(str(path)))
    if not path.is_file():
        return
    try:
        with open(path, "rb") as handle:
            head = handle.read(16)
    except OSError:
        return  # rosbags' reader says why
    for magic, suffix, kind in FORMATS:
        if head.startswith(magic) and path.suffix != suffix:
            named = next((k for _, s, k in FORMATS if s == path.suffix), None)
            said = f"its name ends in {path.suffix} ({named})" if named else "its name does not end in " + suffix
            raise SealError(f"this file is {kind}, but {said}: seal reads a bag by its name's suffix; rename it to "
                            f"end in {suffix}", Where(str(path)))


@contextlib.contextmanager
def open_bag(path: str | Path) -> Iterator[Bag]:
    require_rosbags()
    from rosbags.highlevel import AnyReader

    path = Path(path)
    try:
        path.stat()
    except FileNotFoundError:
        raise SealError("no such bag", Where(str(path))) from None
    except OSError as exc:  # a link loop, a name too long: Path.exists said "no such bag"
        raise SealError(f"cannot read this bag: {exc.strerror}", Where(str(path))) from None
    from seal_cli.fileio import _regular

    # a FIFO named .mcap, or a ROS 2 bag's out.db3 that is one: rosbags opened it and waited for ever (hostile30)
    for file in itertools.islice(path.iterdir(), 10_000) if path.is_dir() else [path]:
        if not file.is_dir():
            _regular(file, "bag" if file == path else "bag file")
    _check_suffix(path)
    if path.is_dir():  # its metadata read as seal reads YAML first: rosbags' own failures said no line (hostile29)
        read_yaml(path / "metadata.yaml", what="ROS 2 bag's metadata")
    ros1 = path.suffix == ".bag"
    try:
        reader = AnyReader([path], default_typestore=typestore(ros1))
        reader.open()
    except Exception as exc:  # a file that is not a bag fails in many ways inside rosbags
        raise SealError(f"cannot read this as a ROS bag (ROS 1 .bag, ROS 2 folder, .db3 or .mcap): {damage(exc)}",
                        Where(str(path))) from None
    try:
        yield Bag(reader, path)
    finally:
        with contextlib.suppress(Exception):
            reader.close()


def bag_topics(path: str | Path) -> dict[str, str]:
    """Topic → message type of every connection in the bag."""
    with open_bag(path) as bag:
        return bag.topics
