"""A cross-process cache of what seal derives from files: the read frame library, the word tables.

``seal parse`` starts many times a minute from scripts, and most of its start-up went into
work whose result only changes when a file does: reading and checking the frame library, and
decompressing and sorting lemminflect's word tables. Such a result is kept as one *entry*, a file
in the user's cache folder (``$XDG_CACHE_HOME/seal``, else ``~/.cache/seal``; ``SEAL_CACHE_DIR``
names another; ``SEAL_NO_CACHE=1`` turns the cache off):

    entry file:  ``seal-cache 2 <stamp> <payload length> <payload sha256>\\n`` then the payload's bytes

The *stamp* is a digest of everything the result was made from (the files' contents and names,
the package's version, the code that made it): an entry whose stamp differs is stale, and one
whose header, length or payload digest is wrong is corrupt (a byte flipped on disk keeps the
length: the digest catches it, for about 2 ms a megabyte when the entry is first read); either is
ignored and made again. Entries are written
whole or not at all (a temporary file renamed onto the entry), so concurrent processes only ever
see a complete one. The cache is never required: a folder that cannot be made or written, or an
entry that cannot be read, costs the time of making the result, never an error. Entries are read
only from the user's own cache folder (the same trust as the files they were made from).
"""

from __future__ import annotations

import contextlib
import mmap
import os
from pathlib import Path
from typing import TYPE_CHECKING

if TYPE_CHECKING:
    from collections.abc import Mapping
    from typing import BinaryIO

__all__ = ["digest", "folder", "read", "read_mapped", "write"]

MAGIC = b"seal-cache 2 "
"""The start of every entry's header (the number is the format's version)."""


def folder(environ: Mapping[str, str] = os.environ) -> Path | None:
    """The cache folder, or None when the cache is turned off (``SEAL_NO_CACHE`` set and not ``0``)."""
    if environ.get("SEAL_NO_CACHE", "0") not in ("", "0"):
        return None
    chosen = environ.get("SEAL_CACHE_DIR")
    if chosen:
        return Path(chosen)
    base = environ.get("XDG_CACHE_HOME") or os.path.join(os.path.expanduser("~"), ".cache")
    return Path(base) / "seal"


def digest(*parts: bytes) -> str:
    """A hex digest of the parts (each length-prefixed, so that no two sequences of parts collide)."""
    import hashlib

    h = hashlib.blake2b(digest_size=20)
    for part in parts:
        h.update(len(part).to_bytes(8, "little"))
        h.update(part)
    return h.hexdigest()


def _checksum(payload: bytes | memoryview) -> str:
    """The payload's SHA-256 (hex): what a whole entry's header holds, to catch a corrupted payload."""
    import hashlib

    return hashlib.sha256(payload).hexdigest()


def _header(stamp: str, payload: bytes) -> bytes:
    return MAGIC + f"{stamp} {len(payload)} {_checksum(payload)}\n".encode("ascii")


HEADER_MAX = 256
"""The longest header an entry may have (magic, stamp, length and digest take about 130 bytes)."""


def _payload_start(data: bytes | mmap.mmap, stamp: str) -> int | None:
    """Where the payload starts if ``data`` is a whole entry of this stamp (its length and digest those of
    the header), else None."""
    end = data.find(b"\n", 0, HEADER_MAX)
    if end < 0:
        return None
    head = bytes(data[:end + 1])
    if not head.startswith(MAGIC + stamp.encode("ascii") + b" "):
        return None
    fields = head[len(MAGIC) + len(stamp) + 1:-1].split(b" ")
    if len(fields) != 2 or not fields[0].isdigit() or len(data) - (end + 1) != int(fields[0]):
        return None
    with memoryview(data) as view:
        whole = _checksum(view[end + 1:]).encode("ascii") == fields[1]
    return end + 1 if whole else None


MAX_READ = 64 * 2**20
"""The largest entry :func:`read` reads whole (the library's is about 90 KB): a larger file at an entry's name is not
one seal wrote, and is made again (replaced)."""


def _open(path: Path) -> BinaryIO | None:
    """``path`` opened if it is a regular file, else None: a FIFO, a device or a folder at an entry's name (a careless
    ``mkfifo``, a link to ``/dev/zero`` in a shared cache) is no entry, and a FIFO cannot stop seal waiting for a
    writer (``seal parse`` hung on one: :func:`~seal_cli.fileio.open_regular` does not block)."""
    from seal_cli.fileio import open_regular

    try:
        return open_regular(path)
    except (OSError, ValueError):
        return None


def read(name: str, stamp: str) -> bytes | None:
    """The payload of the entry ``name`` if it is whole and of this stamp; None otherwise (none,
    stale, corrupt, unreadable, not a regular file, larger than :data:`MAX_READ`, or the cache off)."""
    where = folder()
    handle = None if where is None else _open(where / name)
    if handle is None:
        return None
    try:
        with handle:
            data = handle.read(MAX_READ + 1)
    except OSError:
        return None
    if len(data) > MAX_READ:
        return None
    start = _payload_start(data, stamp)
    return None if start is None else data[start:]


def read_mapped(name: str, stamp: str) -> tuple[mmap.mmap, int] | None:
    """The entry ``name`` mapped into memory (read only) and where its payload starts, if it is whole
    and of this stamp; None otherwise. For large payloads looked up in place, never read whole."""
    where = folder()
    handle = None if where is None else _open(where / name)
    if handle is None:
        return None
    try:
        with handle:
            mapped = mmap.mmap(handle.fileno(), 0, access=mmap.ACCESS_READ)
    except (OSError, ValueError):  # no such entry, or an empty file (mmap refuses length 0)
        return None
    start = _payload_start(mapped, stamp)
    if start is None:
        mapped.close()
        return None
    return mapped, start


def write(name: str, stamp: str, payload: bytes) -> bool:
    """Store ``payload`` as the entry ``name`` of this stamp, atomically; whether it was stored (a
    cache that is off, or a folder that cannot be written, is not an error)."""
    where = folder()
    if where is None:
        return False
    tmp = where / f".{name}.{os.getpid()}.tmp"
    try:
        where.mkdir(parents=True, exist_ok=True)
        with open(tmp, "wb") as handle:
            handle.write(_header(stamp, payload))
            handle.write(payload)
        os.replace(tmp, where / name)
    except OSError:
        with contextlib.suppress(OSError):
            tmp.unlink()
        return False
    return True
