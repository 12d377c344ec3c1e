"""Reading the files users hand to seal, and writing output files whole or not at all.

Every reader turns an unreadable or malformed file into a :class:`~seal_cli.errors.SealError`
naming the file, line and column. Readers refuse what is not a regular file by its kind (a FIFO,
``/dev/zero``, a socket) before opening it, and a file larger than :data:`MAX_INPUT_BYTES`, so
that no input can hang seal or fill its memory.

Every writer goes through :class:`Outputs` (or :func:`atomic_output`, one file): each output is
written to a temporary file of our own naming beside it and renamed onto it only when the whole
command succeeded. An :class:`Outputs` plan is checked before any work: each output is resolved
and compared by path and inode with every input and every other output, its folder must exist and
take a file (a temporary is created there at once), and its suffix must be the format's. A device
such as ``/dev/null`` is written in place, not replaced by a rename. On SIGTERM, SIGINT or SIGHUP
(see :func:`clean_up_on_signals`) and at exit, our temporaries are removed; temporaries left by a
killed seal (``SIGKILL``) are swept on the next write of the same file.
"""

from __future__ import annotations

import atexit
import contextlib
import errno
import itertools
import os
import re
import shutil
import signal
import stat
import sys
from collections.abc import Iterable, Iterator, Mapping, Sequence
from dataclasses import dataclass
from pathlib import Path
from types import TracebackType
from typing import TYPE_CHECKING, Any, BinaryIO

from seal_cli.errors import SealError, Where

if TYPE_CHECKING:
    import yaml

__all__ = ["LOADER", "MAX_IMAGE_BYTES", "MAX_INPUT_BYTES", "YAML_BREAKS", "Outputs", "atomic_output",
           "atomic_write_text", "clean_up_on_signals", "compose_documents", "compose_yaml", "decode", "interrupted",
           "is_live_temporary",
           "json_value", "note_interrupts", "open_regular", "read_bytes", "read_json", "read_json_lines", "read_text",
           "read_yaml", "remove_temporaries", "shown_path", "signals_wait", "split_lines", "stdin_hint", "stream_lines",
           "typed", "work_folder", "yaml_problem"]

if TYPE_CHECKING:
    LOADER: type[yaml.SafeLoader]
    """PyYAML's safe loader, in C (libyaml) when PyYAML has it: about 14 times faster at reading
    frame libraries and maps, with the same nodes and marks."""


MAX_INT_DIGITS = 4300
"""The longest integer YAML may hold, in digits: Python converts at most this many (more is a ValueError,
which PyYAML's constructor lets through), and converting is quadratic in the digits."""


def _bounded_int(constructor: yaml.constructor.SafeConstructor, node: yaml.ScalarNode) -> int:
    """PyYAML's safe integer, with an integer of more than :data:`MAX_INT_DIGITS` digits a YAML error at
    its node (every reader turns that into its file, line and column)."""
    import yaml

    digits = sum(c.isdigit() for c in str(node.value))
    if digits > MAX_INT_DIGITS:
        raise yaml.constructor.ConstructorError(
            None, None, f"an integer of {digits:,} digits is more than seal reads ({MAX_INT_DIGITS:,} digits at most)",
            node.start_mark)
    _one_reading(node)
    return yaml.constructor.SafeConstructor.construct_yaml_int(constructor, node)


def _one_reading_float(constructor: yaml.constructor.SafeConstructor, node: yaml.ScalarNode) -> float:
    """PyYAML's safe float, but for one YAML 1.2 reads otherwise (:func:`_one_reading`)."""
    import yaml

    _one_reading(node)
    return yaml.constructor.SafeConstructor.construct_yaml_float(constructor, node)


_LEADING_ZERO = re.compile(r"[-+]?0[0-7_]+")
_BASE_60 = re.compile(r"[-+]?[0-9][0-9_]*(?::[0-5]?[0-9])+(?:\.[0-9_]*)?")


def _one_reading(node: yaml.ScalarNode) -> None:
    """Refuse a number YAML 1.1 (PyYAML's, seal's) and YAML 1.2 (ROS's own map_server reads with yaml-cpp) read as
    two different values, at its node: a plain ``010`` is octal to YAML 1.1 (8) and ten to YAML 1.2, and ``10:30``
    is 630 to YAML 1.1 (base 60) and text to YAML 1.2 (hostile21: ``bounds: [0, 0, 10:00, 10]`` made a map 600 m
    wide and ``012`` 10 m, silently). A leading zero that changes nothing (``07``, ``-05``) is read."""
    import yaml

    text = str(node.value)
    if _LEADING_ZERO.fullmatch(text):
        digits = text.replace("_", "")
        if int(digits, 8) == int(digits, 10):
            return
        problem = (f"'{text}' has a leading zero: YAML 1.1, which seal reads, takes it as octal ({int(digits, 8)}), "
                   f"YAML 1.2, which ROS reads, as {int(digits, 10)}: write it without the zero")
    elif _BASE_60.fullmatch(text):
        problem = (f"'{text}' is a number in base 60 to YAML 1.1, which seal reads, and text to YAML 1.2, which ROS "
                   "reads: write the number itself (quote it if it is a name)")
    else:
        return
    raise yaml.constructor.ConstructorError(None, None, problem, node.start_mark)


def _loader() -> type[yaml.SafeLoader]:
    import yaml

    # every safe loader (C or Python, PyYAML's own safe_load too) reads integers through the bound
    yaml.constructor.SafeConstructor.add_constructor("tag:yaml.org,2002:int", _bounded_int)  # type: ignore[type-var]
    yaml.constructor.SafeConstructor.add_constructor("tag:yaml.org,2002:float",  # type: ignore[type-var]
                                                     _one_reading_float)
    loader: type[yaml.SafeLoader] = getattr(yaml, "CSafeLoader", yaml.SafeLoader)
    globals()["LOADER"] = loader
    return loader


def __getattr__(name: str) -> Any:
    """``LOADER``, imported with PyYAML when first asked for: what reads no YAML (``seal parse`` with
    its library from the cache) does not pay for PyYAML (~8 ms)."""
    if name == "LOADER":
        return _loader()
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")

MAX_INPUT_BYTES = 16 * 2**20
"""The largest text file seal reads (frame files, maps, observations, command files): 16 MiB."""

MAX_IMAGE_BYTES = 256 * 2**20
"""The largest map image seal reads: 256 MiB (a 16,000 × 16,000 PGM)."""

_READ: dict[tuple[int, int], str] = {}
"""(device, inode) → path of every file read through this module: no output may be written over one."""


# -- reading ------------------------------------------------------------------------------------
def _kind(mode: int) -> str:
    for test, name in ((stat.S_ISFIFO, "a FIFO (named pipe)"), (stat.S_ISCHR, "a character device"),
                       (stat.S_ISBLK, "a block device"), (stat.S_ISSOCK, "a socket"), (stat.S_ISDIR, "a folder")):
        if test(mode):
            return name
    return "not a regular file"


def stdin_hint(name: str) -> str:
    """What to add to "no such file" when the name is ``-``: standard input, which only ``seal parse --file``
    reads (``bench plan --file -`` said only "-: no such file", hostile21; ``seal validate -`` and ``seal map -``
    said "no such file or folder" and "no such map file", hostile22)."""
    return (" ('-' is standard input only to seal parse --file: save the text to a file and give its name)"
            if name == "-" else "")


def cwd_gone() -> bool:
    """Whether the working folder has been deleted (``os.getcwd`` fails): a relative name then names nothing."""
    try:
        os.getcwd()
    except FileNotFoundError:
        return True
    return False


def gone_cwd_hint(path: str | Path) -> str:
    """What to add to a failure to find or write ``path`` when it is relative and the working folder has been
    deleted under seal's caller (``cd d; rm -r ../d; seal map m --png o.png`` said only "cannot write the output:
    No such file or directory", hostile28)."""
    if Path(path).is_absolute() or not cwd_gone():
        return ""
    return (" (the working folder has been deleted, and a relative name is read from it: give an absolute path, or "
            "run seal from a folder that exists)")


def _regular(path: Path, what: str) -> os.stat_result:
    """The file's status if it is a regular file; else a SealError saying what it is (missing, a folder, a
    FIFO, ...), which :func:`read_bytes` and :func:`stream_lines` both refuse."""
    where = Where(str(path))
    try:
        info = path.stat()
    except FileNotFoundError:
        raise SealError(f"no such {what}{stdin_hint(str(path))}{gone_cwd_hint(path)}", where) from None
    except OSError as exc:
        raise SealError(f"cannot read this {what}: {exc.strerror}", where) from None
    if stat.S_ISDIR(info.st_mode):
        raise SealError(f"this is a folder, not a {what}", where)
    if not stat.S_ISREG(info.st_mode):
        handed = ""
        if str(path) in ("/dev/stdin", "/dev/tty") or re.fullmatch(r"/(dev|proc/self)/fd/\d+", str(path)):
            handed = (" (a stream this command was handed: standard input or a shell's <(...)); save it to a file "
                      "first, or give '-' where seal reads standard input (seal parse --file -)")
        raise SealError(f"cannot read this {what}: it is {_kind(info.st_mode)}, not a regular file{handed}", where)
    return info


def open_regular(path: str | Path) -> BinaryIO | None:
    """``path`` opened for reading if it is a regular file, else None (a FIFO, a device, a folder); opened without
    blocking, so that a FIFO or a "regular" file that waits for data (/proc/kmsg) cannot hang seal. An OSError if
    it cannot be opened at all."""
    fd = os.open(path, os.O_RDONLY | os.O_NONBLOCK)
    if stat.S_ISREG(os.fstat(fd).st_mode):
        return os.fdopen(fd, "rb")
    os.close(fd)
    return None


def read_bytes(path: str | Path, limit: int = MAX_INPUT_BYTES, what: str = "file") -> bytes:
    """A regular file's bytes, at most ``limit`` of them; anything else is a SealError naming it."""
    path = Path(path)
    where = Where(str(path))
    info = _regular(path, what)
    if info.st_size > limit:
        size, most = _sizes(info.st_size, limit)
        raise SealError(f"this {what} is {size}; seal reads {what}s of at most {most}", where)
    try:
        handle = open_regular(path)
        if handle is None:  # swapped for a FIFO since the stat
            raise SealError(f"cannot read this {what}: it is not a regular file", where)
        with handle:
            data = handle.read(limit + 1)
    except BlockingIOError:
        raise SealError(f"cannot read this {what}: it has nothing to read yet (a file that waits for data, "
                        "such as /proc/kmsg)", where) from None
    except OSError as exc:
        raise SealError(f"cannot read this {what}: {exc.strerror}", where) from None
    if data is None:  # a non-blocking read with nothing there
        raise SealError(f"cannot read this {what}: it has nothing to read yet", where)
    if len(data) > limit:  # it grew while we read it
        raise SealError(f"this {what} is larger than {_size(limit)}, the most seal reads", where)
    _READ[(info.st_dev, info.st_ino)] = str(path)
    return data


def _sizes(size: int, limit: int) -> tuple[str, str]:
    """A size past a limit and the limit, in bytes when the rounded sizes would read the same ("this file is 16 MiB;
    seal reads files of at most 16 MiB" was said of a file 23 KB past the bound)."""
    if _size(size) != _size(limit):
        return _size(size), _size(limit)
    return f"{size:,} bytes", f"{limit:,} bytes ({_size(limit)})"


def _size(count: int) -> str:
    for scale, unit in ((2**30, "GiB"), (2**20, "MiB"), (2**10, "KiB")):
        if count >= scale:
            return f"{count / scale:.1f} {unit}".replace(".0 ", " ")
    return f"{count} bytes"


_WIDE = ((b"\xff\xfe\x00\x00", "UTF-32"), (b"\x00\x00\xfe\xff", "UTF-32"), (b"\xff\xfe", "UTF-16"),
         (b"\xfe\xff", "UTF-16"))
"""The byte-order marks of the encodings Windows tools save text in ("Unicode" in Notepad, PowerShell's ``>``)."""


def wide_encoding(head: bytes) -> str | None:
    """"UTF-16" or "UTF-32" when a text's first bytes show it (a byte-order mark, or UTF-16 without one: every other
    byte of the first 64 zero, which UTF-8 text never is), else None."""
    wide = next((name for mark, name in _WIDE if head.startswith(mark)), None)
    pairs = head[:64]
    if wide is None and len(pairs) >= 4 and pairs.count(0) * 2 >= len(pairs) - 1:
        wide = "UTF-16"
    return wide


def not_utf8(wide: str, what: str = "file") -> str:
    """The refusal of a text in a wide encoding: "byte 0xff cannot be decoded" said nothing a person could act on."""
    return (f"this {what} is {wide} text, not UTF-8: seal reads UTF-8; save it as UTF-8 (iconv -f {wide} -t UTF-8, or "
            "'UTF-8' in the editor's Save As)")


def decode(data: bytes, file: str) -> str:
    """UTF-8 text (a leading byte-order mark dropped), composed (NFC: an "é" written as "e" and a combining accent,
    as macOS writes it, is the one letter the same name elsewhere is); invalid UTF-8 is a SealError at its line and
    column."""
    if data.startswith(b"\xef\xbb\xbf"):
        data = data[3:]
    wide = wide_encoding(data)
    if wide is not None:
        raise SealError(not_utf8(wide), Where(file, 1, 1))
    try:
        return composed(data.decode("utf-8"))
    except UnicodeDecodeError as exc:
        line = data.count(b"\n", 0, exc.start) + 1
        column = exc.start - (data.rfind(b"\n", 0, exc.start) + 1) + 1
        raise SealError(f"this file is not UTF-8 text: byte 0x{data[exc.start]:02x} cannot be decoded",
                        Where(file, line, column)) from None


def composed(text: str) -> str:
    """``text`` in Unicode's composed form (NFC), where a letter and its accent are one character: a command or a
    name typed decomposed ("cafe" + U+0301) reads as the composed one ("café") a map or a library names."""
    import unicodedata

    return text if text.isascii() or unicodedata.is_normalized("NFC", text) else unicodedata.normalize("NFC", text)


_UNDECODED = re.compile("[\udc80-\udcff]")


def typed(text: str) -> str:
    """A text of the command line (a command, ``--task``, ``--holding``) as its user typed it: composed
    (:func:`composed`), and, where the locale could not decode its bytes (Python's ``surrogateescape``: an ASCII
    locale, ``LANG=C`` with Python's UTF-8 mode off), read as UTF-8 if they are UTF-8: "stir the café" was refused
    there at a "byte 0xc3" (hostile21). Bytes that are no UTF-8 stay as Python gave them: the parser names the first
    (:mod:`seal_cli.language.tokens`)."""
    if not text.isascii() and _UNDECODED.search(text):
        with contextlib.suppress(UnicodeError):
            text = os.fsencode(text).decode("utf-8")
    return composed(text)


def read_text(path: str | Path, limit: int = MAX_INPUT_BYTES) -> str:
    """A text file's contents; a missing, unreadable, special, oversized or non-UTF-8 file is a
    SealError naming it."""
    return decode(read_bytes(path, limit), str(path))


def split_lines(text: str) -> list[str]:
    """Lines separated by ``\\n`` (or ``\\r\\n``) and nothing else: unlike :meth:`str.splitlines`,
    U+2028, form feeds, a lone ``\\r`` and the other Unicode breaks stay inside their line, so one
    line in is one line out."""
    lines = text.split("\n")
    if lines and lines[-1] == "":
        lines.pop()
    return [line[:-1] if line.endswith("\r") else line for line in lines]


YAML_BREAKS = re.compile("\r\n|[\n\r\x85\u2028\u2029]")
"""What YAML counts as a line break (its marks count lines by these)."""


def yaml_problem(exc: Exception, text: str, file: str) -> SealError:
    """One YAML reader's failure as a SealError at its line and column, with the line and a caret:
    a syntax error at its mark, a character YAML refuses (a NUL, a control character) at its
    position, anything else at the file. Every YAML reader of seal words its failures here."""
    import yaml

    lines = YAML_BREAKS.split(text)
    if isinstance(exc, yaml.MarkedYAMLError):
        mark = exc.problem_mark or exc.context_mark
        what = (f"cannot read this value: {exc.problem or exc.context}"  # a value its constructor refused
                if isinstance(exc, yaml.constructor.ConstructorError) else
                f"YAML syntax error: {exc.problem or exc.context}")
        if mark is None:
            return SealError(what, Where(file))
        source = lines[mark.line] if mark.line < len(lines) else None
        return SealError(what, Where(file, mark.line + 1, mark.column + 1), source_line=source)
    if isinstance(exc, yaml.reader.ReaderError) and isinstance(exc.character, (int, str)):
        code = exc.character if isinstance(exc.character, int) else ord(exc.character)
        before = YAML_BREAKS.split(text[:exc.position])
        line, column = len(before), len(before[-1]) + 1
        return SealError(f"YAML does not allow the control character {chr(code)!r} (U+{code:04X}) in a file",
                         Where(file, line, column), source_line=lines[line - 1].replace(chr(code), " "))
    return SealError(f"YAML error: {exc}", Where(file))


def compose_yaml(text: str, file: str) -> Any:
    """A YAML text's node tree (``yaml.Node``, or None for an empty text), aliases not expanded and its size
    checked (:func:`~seal_cli.yamlnodes.check_size`); a syntax error as :func:`yaml_problem` words it. For the
    readers that report each problem at its node (:class:`~seal_cli.yamlnodes.NodeReader`)."""
    return compose_documents(text, file, single=True)[0]


def compose_documents(text: str, file: str, *, single: bool = False) -> list[Any]:
    """The node trees of a YAML text's documents (``single``: the one document ``yaml.compose`` allows), bounded as
    :func:`read_yaml` bounds a file: more than :data:`~seal_cli.yamlnodes.MAX_VALUES` values is refused at the value
    past the bound by streaming the parser's events before any node is built (composing is ~4 s and ~300 MB a
    million values: a 14 MB map of seven million numbers took over a minute and 2 GB before it was refused), and the
    values the aliases expand to are counted per document. Each alias then stands as a node of its own at its own
    line and column (:func:`~seal_cli.yamlnodes.place_aliases`: a problem with what it brings is said where it is
    used), and merge keys (``<<: *base``) are merged (:func:`~seal_cli.yamlnodes.merge_keys`)."""
    import yaml

    from seal_cli.yamlnodes import MAX_VALUES, check_size, count_values, merge_keys, place_aliases

    loader = _loader()
    try:
        if len(text) > MAX_VALUES:  # a value takes at least one character: a shorter text cannot hold more
            count_values(text, loader, file, MAX_VALUES)
        documents = [yaml.compose(text, Loader=loader)] if single else list(yaml.compose_all(text, Loader=loader))
    except yaml.YAMLError as exc:
        raise yaml_problem(exc, text, file) from None
    lines = _tag_lines(text)
    for root in documents:
        check_size(root, file, MAX_VALUES, lines)
    place_aliases(documents, text, loader)
    if "<<" in text:
        for root in documents:
            merge_keys(root, file)
    return documents


def _tag_lines(text: str) -> list[str]:
    """A YAML text's lines for :func:`~seal_cli.yamlnodes.check_size` to read a tag written in the file as YAML reads
    it; none when the text writes no tag (no "!")."""
    return YAML_BREAKS.split(text) if "!" in text else []


def read_yaml(path: str | Path, max_values: int | None = None, what: str = "file") -> Any:
    """A YAML file's data; syntax errors carry the line and column, with the line and a caret.

    ``max_values``: the most values (scalars, lists and mappings, aliases expanded) the file may hold
    (default :data:`~seal_cli.yamlnodes.MAX_VALUES`); a file holding more is refused at the value past the
    bound, found by streaming the parser's events before anything is built (a vocabulary of 300,000 words
    is refused in a fraction of a second, not after it has been read and used)."""
    import yaml

    from seal_cli.yamlnodes import MAX_VALUES, check_size, count_values

    text = read_text(path)
    loader = _loader()
    limit = MAX_VALUES if max_values is None else max_values
    try:
        if len(text) > limit:  # a value takes at least one character: a shorter file cannot hold more
            count_values(text, loader, str(path), limit, what)
        check_size(yaml.compose(text, Loader=loader), str(path), limit, _tag_lines(text))  # no alias bomb expanded
        return yaml.load(text, Loader=loader)  # noqa: S506 (a safe loader)
    except yaml.YAMLError as exc:
        raise yaml_problem(exc, text, str(path)) from None


_LONE_SURROGATE = re.compile(r"\\u[dD][89abAB][0-9a-fA-F]{2}(?!\\u[dD][c-fC-F])"
                             r"|(?<!\\u[dD][89abAB][0-9a-fA-F]{2})\\u[dD][c-fC-F][0-9a-fA-F]{2}")
"""A JSON escape of half a character: a high surrogate not followed by a low one, or a low one alone."""


def _halves(value: Any) -> bool:
    """Whether a decoded JSON value holds a string with a lone surrogate (JSON's ``"\\ud800"``)."""
    if isinstance(value, str):
        return any("\ud800" <= c <= "\udfff" for c in value)
    if isinstance(value, dict):
        return any(_halves(k) or _halves(v) for k, v in value.items())
    if isinstance(value, list):
        return any(_halves(v) for v in value)
    return False


_LONG_NUMBER = re.compile(rf"-?\d{{{MAX_INT_DIGITS + 1},}}")
DEEPEST_SHOWN = 500
"""How deep a JSON value's nesting is where :func:`json_value` points, once Python's reader found it too deep."""


def json_value(text: str, path: str | Path, line: int = 1) -> Any:
    """The JSON value of ``text`` (a file's, or its line ``line``'s) with no half characters
    (:func:`check_whole_characters`); an integer of more than :data:`MAX_INT_DIGITS` digits (Python's reader
    raised a bare ValueError: a traceback from ``bench parse --corpus`` and every JSON reader, hostile29) or nesting
    deeper than Python's reader goes is a SealError at its line and column. Not JSON at all: ``json.JSONDecodeError``,
    which each reader words as its own."""
    import json

    try:
        return check_whole_characters(json.loads(text, object_pairs_hook=_each_key_once), text, path, line)
    except json.JSONDecodeError:
        raise
    except _RepeatedKey:
        at, key = _repeated_key(text)
        shown = key if len(key) <= 60 else key[:59] + "…"
        message = (f"this object says the key {shown!r} twice: JSON readers differ on which one counts (Python's "
                   "takes the last, others the first or refuse), so say it once")
    except RecursionError:
        at = _depth_reached(text, DEEPEST_SHOWN)
        message = f"this value is nested too deeply for seal to read ({DEEPEST_SHOWN} levels deep here, and deeper)"
    except ValueError:
        found = _LONG_NUMBER.search(text)
        at = found.start() if found else 0
        digits = len(found.group().lstrip("-")) if found else 0
        message = f"an integer of {digits:,} digits is more than seal reads ({MAX_INT_DIGITS:,} digits at most)"
    before = text.rfind("\n", 0, at)
    shown = text[before + 1:].split("\n", 1)[0]
    raise SealError(message, Where(str(path), line + text.count("\n", 0, at), at - before),
                    source_line=shown if len(shown) <= 200 else None) from None


class _RepeatedKey(Exception):
    """An object of a JSON text says a key twice (found by :func:`_each_key_once`, placed by :func:`_repeated_key`)."""


def _each_key_once(pairs: list[tuple[str, Any]]) -> dict[str, Any]:
    """The object of JSON ``pairs``, as Python's reader makes it, but refusing a key said twice (hostile30: the last
    was taken silently, ``{"text": "a", "text": "b"}`` scored as "b")."""
    value = dict(pairs)
    if len(value) != len(pairs):
        raise _RepeatedKey
    return value


_JSON_TOKEN = re.compile(r'"(?:[^"\\]|\\.)*"|[{}\[\],:]')
"""A JSON string, or one of JSON's structural characters (what else a JSON text holds has neither)."""


def _repeated_key(text: str) -> tuple[int, str]:
    """Where the first key said twice in one object of a JSON text is (its second saying), and the key; the text
    is JSON (Python's reader read it), walked without recursion."""
    import json

    objects: list[set[str] | None] = []  # the keys of each open object; None for an open array
    last = ""
    for token in _JSON_TOKEN.finditer(text):
        word = token.group()
        if word[0] == '"':
            if objects and objects[-1] is not None and last in ("{", ","):
                key = json.loads(word)
                if key in objects[-1]:
                    return token.start(), key
                objects[-1].add(key)
        elif word in "{[":
            objects.append(set() if word == "{" else None)
        elif word in "}]" and objects:
            objects.pop()
        last = word[0]
    return 0, ""


def _depth_reached(text: str, depth: int) -> int:
    """Where the nesting of a JSON text's arrays and objects first reaches ``depth`` (strings skipped)."""
    level, inside, escaped = 0, False, False
    for at, c in enumerate(text):
        if inside:
            escaped, inside = (False, True) if escaped else (c == "\\", c != '"')
        elif c == '"':
            inside = True
        elif c in "[{":
            level += 1
            if level >= depth:
                return at
        elif c in "]}":
            level -= 1
    return 0


def check_whole_characters(value: Any, text: str, path: str | Path, line: int = 1) -> Any:
    """``value``, decoded from the JSON ``text``, or a SealError at the escape that is half a character: Python's
    ``json`` decodes ``"\\ud800"`` to a lone surrogate, which no UTF-8 can hold, so the first write of it (a
    scorer handing it to ``seal parse``, a JSON output) failed with a UnicodeEncodeError (hostile28)."""
    if "\\u" not in text or not _halves(value):
        return value
    found = _LONE_SURROGATE.search(text)
    start = found.start() if found else 0
    before = text.rfind("\n", 0, start)
    number = line + text.count("\n", 0, start)
    shown = text[before + 1:].split("\n", 1)[0]
    raise SealError(f"{found.group() if found else 'an escape'} is half a character (a lone surrogate, which UTF-8 "
                    "cannot hold): write the character itself, or both halves of its pair",
                    Where(str(path), number, start - before), source_line=shown)


def read_json(path: str | Path, what: str = "JSON file") -> Any:
    """A JSON file's value; a file that is not JSON is a SealError at its line and column."""
    import json

    text = read_text(path)
    try:
        return json_value(text, path)
    except json.JSONDecodeError as exc:
        lines = text.split("\n")
        source = lines[exc.lineno - 1] if exc.lineno <= len(lines) else None
        raise SealError(f"this {what} is not JSON: {exc.msg}", Where(str(path), exc.lineno, exc.colno),
                        source_line=source) from None


def stream_lines(path: str | Path, what: str = "file") -> Iterator[tuple[int, str]]:
    """``(line number, line)`` of a text file too large to read whole (the ALFRED trials: 35 MB), one at
    a time: refused by kind as :func:`read_bytes` refuses, each line at most :data:`MAX_INPUT_BYTES`
    long and UTF-8 (else a SealError at its line and column)."""
    path = Path(path)
    where = Where(str(path))
    info = _regular(path, what)
    _READ[(info.st_dev, info.st_ino)] = str(path)
    try:
        with os.fdopen(os.open(path, os.O_RDONLY | os.O_NONBLOCK), "rb") as handle:
            for number, raw in enumerate(iter(lambda: handle.readline(MAX_INPUT_BYTES + 1), b""), 1):
                if len(raw) > MAX_INPUT_BYTES:
                    raise SealError(f"line {number} of this {what} is longer than {_size(MAX_INPUT_BYTES)}, the "
                                    "most seal reads", Where(str(path), number))
                wide = wide_encoding(raw) if number == 1 else None
                if wide is not None:
                    raise SealError(not_utf8(wide, what), Where(str(path), 1, 1))
                try:
                    line = raw.decode("utf-8")
                except UnicodeDecodeError as exc:
                    raise SealError(f"this {what} is not UTF-8 text: byte 0x{raw[exc.start]:02x} cannot be decoded",
                                    Where(str(path), number, exc.start + 1)) from None
                yield number, line.removeprefix("\ufeff") if number == 1 else line
    except BlockingIOError:
        raise SealError(f"cannot read this {what}: it has nothing to read yet", where) from None
    except OSError as exc:
        raise SealError(f"cannot read this {what}: {exc.strerror}", where) from None


def read_json_lines(path: str | Path) -> list[Any]:
    """The JSON values of a JSON Lines file (blank lines skipped); a line that is not JSON is a
    SealError at its line and column."""
    import json

    values = []
    for number, line in enumerate(split_lines(read_text(path)), 1):
        if not line.strip():
            continue
        try:
            values.append(json_value(line, path, number))
        except json.JSONDecodeError as exc:
            raise SealError(f"not JSON: {exc.msg}", Where(str(path), number, exc.colno), source_line=line) from None
    return values


# -- writing ------------------------------------------------------------------------------------
_LIVE: set[Path] = set()
"""Our temporaries not yet renamed or removed: removed at exit and on a signal."""

_TEMP = re.compile(r"\.seal(\d+)-[0-9a-f]{8}\.tmp")


def is_live_temporary(path: str | Path) -> bool:
    """Whether ``path`` is the temporary of an output being written (a writer handed it says its failures as the
    system's errors of it, for the output to name its option)."""
    return Path(path) in _LIVE


def remove_temporaries() -> None:
    """Remove every temporary of ours not yet moved onto its target (a command that failed half-way)."""
    for tmp in list(_LIVE):
        with contextlib.suppress(OSError):
            tmp.unlink()
        _LIVE.discard(tmp)


atexit.register(remove_temporaries)


_INTERRUPTED: list[bool] = [False]


def note_interrupts() -> None:
    """SIGINT raises KeyboardInterrupt as ever, and is remembered: an interrupt that lands inside a C
    extension's import (matplotlib's ``ft2font``) comes out as an ``ImportError: initialization failed``,
    which :func:`interrupted` then tells apart from a real failure."""

    def handler(number: int, frame: Any) -> None:
        _INTERRUPTED[0] = True
        signal.default_int_handler(number, frame)

    _INTERRUPTED[0] = False  # a command run before in this process (the API, tests) was interrupted: not this one
    with contextlib.suppress(ValueError, OSError):  # not the main thread
        if signal.getsignal(signal.SIGINT) is signal.default_int_handler:
            signal.signal(signal.SIGINT, handler)
    if not getattr(sys.unraisablehook, "seal", False):
        previous = sys.unraisablehook

        def unraisable(info: Any) -> None:
            """A KeyboardInterrupt raised where Python cannot raise it (a ctypes callback of LLVM's while numba
            compiles, a ``__del__``) is printed as "Exception ignored" and dropped, and the command ran on
            (``localize --steps 100000`` for minutes, or to its end, its outputs written): silently here, the
            signal is sent again a moment later (from a thread: sent from here it would be raised in this hook,
            and dropped), to be raised where Python runs then (the command's own code, or the next such callback,
            which sends it again). Once an interrupt has come, another error Python cannot raise is its echo and is
            dropped too: an object the interrupt left half built fails in its ``__del__`` (llvmlite's
            ``PassBuilder`` without its ``_as_parameter_``, interrupted while numba compiled), which printed an
            "Exception ignored" traceback before the command's "interrupted"."""
            if not isinstance(info.exc_value, KeyboardInterrupt):
                if not _INTERRUPTED[0]:
                    previous(info)
                return
            import threading

            again = threading.Timer(0.01, lambda: os.kill(os.getpid(), signal.SIGINT))
            again.daemon = True
            again.start()

        unraisable.seal = True  # type: ignore[attr-defined]
        sys.unraisablehook = unraisable


def interrupted() -> bool:
    """Whether SIGINT has arrived (since :func:`note_interrupts`)."""
    return _INTERRUPTED[0]


_COMMITTED: list[bool] = [False]
_HELD = {signal.SIGINT, signal.SIGTERM, signal.SIGHUP}


def committed() -> bool:
    """Whether a command's outputs have been moved into place (since :func:`forget_commits`): an interrupt
    after that leaves the command's work done."""
    return _COMMITTED[0]


def forget_commits() -> None:
    """A new command starts: none of its outputs is in place yet."""
    _COMMITTED[0] = False


_Held = tuple[dict[int, Any], list[int]]


def _hold_signals() -> _Held | None:
    """Make SIGINT, SIGTERM and SIGHUP wait: each is noted by a handler of ours, not acted on (Python runs
    handlers in the main thread whichever thread the system hands a signal to); the handlers before and the
    signals noted, None where handlers cannot be set (not the main thread)."""
    noted: list[int] = []
    before: dict[int, Any] = {}
    try:
        for number in _HELD:
            before[number] = signal.signal(number, lambda n, _frame: noted.append(n))
    except (ValueError, OSError):
        for held, handler in before.items():
            signal.signal(held, handler)
        return None
    return before, noted


def _release_signals(held: _Held | None) -> None:
    """Put back the handlers :func:`_hold_signals` replaced, then act on the signals that waited, as they
    would have been (a KeyboardInterrupt, a SystemExit)."""
    if held is None:
        return
    before, noted = held
    for number, handler in before.items():
        signal.signal(number, handler)
    for number in dict.fromkeys(noted):
        handler = before[number]
        if callable(handler):
            handler(number, None)
        elif handler == signal.SIG_DFL:
            os.kill(os.getpid(), number)


@contextlib.contextmanager
def signals_wait() -> Iterator[None]:
    """SIGINT, SIGTERM and SIGHUP arriving inside the block are noted, and acted on as they would have been (a
    KeyboardInterrupt, a SystemExit) when it ends: for a step no interrupt may cut in two, such as starting a
    process and recording it."""
    held = _hold_signals()
    try:
        yield
    finally:
        _release_signals(held)


_STOPPED: list[int] = [0]
"""The signal (SIGTERM, SIGHUP) that asked this command to stop before its outputs were in place, 0 if none."""


def clean_up_on_signals() -> None:
    """Make SIGTERM and SIGHUP end this process as SIGINT does, by an exception, so that every
    ``with`` block unwinds and our temporaries are removed (``timeout`` and CI send SIGTERM).
    Processes forked from this one (worker pools) keep the default behaviour. A signal this process was started
    with ignored stays ignored: ``nohup seal run ...`` ignores SIGHUP, so that the run outlives its terminal (it
    ended with exit code 129 when the terminal closed, its outputs unwritten: hostile25), as Python leaves SIGINT
    ignored in a shell's background job."""
    main = os.getpid()
    _STOPPED[0] = 0  # a command run before in this process (the API, tests) was stopped: not this one

    def stop(number: int, _frame: Any) -> None:
        if os.getpid() != main:
            signal.signal(number, signal.SIG_DFL)
            os.kill(os.getpid(), number)
            return
        if not committed():
            _STOPPED[0] = number  # noted: a SystemExit raised where a library swallows it still ends the command
        remove_temporaries()
        raise SystemExit(0 if committed() else 128 + number)  # after the outputs are in place: the work is done

    for number in (signal.SIGTERM, signal.SIGHUP):
        with contextlib.suppress(ValueError, OSError):  # not the main thread, or no such signal here
            if signal.getsignal(number) != signal.SIG_IGN:
                signal.signal(number, stop)


def _alive(pid: int) -> bool:
    try:
        os.kill(pid, 0)
    except ProcessLookupError:
        return False
    except OSError:
        return True
    return True


def _sweep(target: Path) -> None:
    """Remove temporaries of ``target`` left by seal processes that no longer run."""
    folder = target.parent
    prefix = f".{target.name}.seal"
    with contextlib.suppress(OSError):
        for entry in os.scandir(folder):
            if not entry.name.startswith(prefix):
                continue
            found = _TEMP.match(entry.name[len(target.name) + 1:])
            if found and int(found.group(1)) != os.getpid() and not _alive(int(found.group(1))):
                with contextlib.suppress(OSError):
                    if entry.is_dir(follow_symlinks=False):     # a bag writer's work folder (work_folder)
                        shutil.rmtree(entry.path)
                    else:
                        os.unlink(entry.path)


def work_folder(target: Path) -> Path:
    """A new folder beside ``target`` to build it in (a bag's writer makes a folder of files), named as a temporary
    of ``target`` with this process's id: the next write of ``target`` removes it if its process was killed (hostile27:
    ``localize --goals g.mcap`` killed left ``.g.mcap.2x8f_k1/`` for ever, named by ``tempfile.mkdtemp``). The caller
    removes it."""
    import secrets

    _sweep(target)
    folder = target.parent / f".{target.name}.seal{os.getpid()}-{secrets.token_hex(4)}.tmp"
    folder.mkdir()
    return folder


def _check_not_stdout(path: Path, option: str) -> None:
    """Refuse an output file that is the command's standard output (``--png /dev/stdout``, ``/dev/fd/1``, or the
    file stdout is redirected to): the SPEC puts the command's results on stdout, and a picture or a recording
    written onto the same stream is mixed with its lines (e2e22). ``/dev/null`` as both is no mix: allowed."""
    target = _identity(path)
    if target is None:
        return
    try:
        info = os.fstat(1)
    except OSError:     # no standard output at all: nothing to mix with
        return
    if target == (info.st_dev, info.st_ino) and target != _identity(Path(os.devnull)):
        raise SealError(f"{option} {str(path)!r} is standard output, where seal prints its results; the output "
                        "would be mixed with them: give a file name")


def _identity(path: Path) -> tuple[int, int] | None:
    try:
        info = path.stat()
    except OSError:
        return None
    return (info.st_dev, info.st_ino)


@dataclass
class _Output:
    option: str
    target: Path
    tmp: Path
    device: bool  # written in place (a character device or a pipe), not renamed onto


class Outputs:
    """The output files of one command, checked before any work and written whole or not at all.

    ``outputs`` maps each option (``--png``) to its path (None: not asked for); ``inputs`` are the
    files the command reads (files read through this module count as well); ``suffixes`` gives
    the suffixes an option's format may carry (``{"--png": (".png",)}``); an option whose value
    is a folder is named in ``folders`` with the file names written into it. Building the plan
    refuses an output that is an input, two outputs that are one file, a missing or unwritable
    folder, a wrong suffix and a target that is a folder, a block device or a socket; it creates
    every temporary at once (``guard_read=False``: files read earlier may be overwritten).
    ``plan[option]`` is the path to write; leaving the ``with`` block
    without an exception moves every temporary onto its target, otherwise removes them all."""

    def __init__(self, outputs: Mapping[str, str | Path | None], inputs: Iterable[str | Path | None] = (), *,
                 suffixes: Mapping[str, Sequence[str]] | None = None,
                 folders: Mapping[str, Sequence[str]] | None = None, guard_read: bool = True,
                 by_option: bool = True) -> None:
        self._by_option = by_option  # a failure to write is said of the option; else an OSError of the target
        self._outputs: dict[str, _Output] = {}
        self._folders: dict[str, Path] = {}
        planned: list[tuple[str, Path]] = []
        for option, value in outputs.items():
            if value is None:
                continue
            if str(value).strip() in ("", "-"):     # "-" would be a file called "-", not standard output
                kind = "folder" if folders and option in folders else "file"
                raise SealError(f"{option} {str(value)!r}: seal writes this output into a {kind}, not to standard "
                                f"output; give a {kind} name")
            if gone_cwd_hint(value):
                raise SealError(f"cannot write {option} {shown_path(value)}: the working folder has been deleted, and "
                                "a relative name is read from it: give an absolute path, or run seal from a folder "
                                "that exists")
            if folders and option in folders:
                folder = _folder(Path(value), option)
                self._folders[option] = folder
                planned.extend((f"{option} {name}", folder / name) for name in folders[option])
            else:
                _check_suffix(Path(value), option, (suffixes or {}).get(option, ()))
                _check_not_stdout(Path(value), option)
                planned.append((option, Path(value)))
        _check_distinct(planned, [Path(p) for p in inputs if p is not None], guard_read)
        self._guard_read = guard_read
        try:
            for option, target in planned:
                self._outputs[option] = _reserve(option, target, by_option)
        except BaseException:
            self.discard()
            raise

    def __getitem__(self, option: str) -> Path:
        """The path a writer writes the output of ``option`` to (a folder for a folder option)."""
        if option in self._folders:
            raise KeyError(f"{option} is a folder: use plan.file({option!r}, name)")
        return self._outputs[option].tmp

    def file(self, option: str, name: str) -> Path:
        """The path to write the file ``name`` of the folder option ``option`` to."""
        return self._outputs[f"{option} {name}"].tmp

    def get(self, option: str) -> Path | None:
        return self._outputs[option].tmp if option in self._outputs else None

    def __enter__(self) -> Outputs:
        return self

    def __exit__(self, kind: type[BaseException] | None, value: BaseException | None,
                 trace: TracebackType | None) -> None:
        if kind is None:
            self.commit()
            return
        written = self._written_by(value) if isinstance(value, OSError) else None  # before its temporary goes
        self.discard()
        if isinstance(value, OSError):
            if written is not None and not self._by_option:  # nested in another's output: it names the option
                raise OSError(value.errno, value.strerror, str(written.target)) from None
            if written is not None:  # said of the file asked for, not of its temporary or of "the output"
                option = written.option.split(" ")[0]  # "--pddl domain.pddl": a file of a folder's option
                raise SealError(f"cannot write {option} {shown_path(written.target)}: "
                                f"{_reason(value, written.target)}") from None

    def _written_by(self, error: OSError) -> _Output | None:
        """The output whose writing failed with ``error``: the one whose temporary it names, or, for a full disk
        reported without a name (a file object's write or close), the one whose folder has no space left, or, for
        a file grown past what the process may write (``ulimit -f``: "File too large", reported without a name
        too), the one whose temporary has reached that size (hostile20: it was "cannot write the output", as if
        standard output had failed)."""
        for output in self._outputs.values():
            if error.filename is not None and os.path.abspath(error.filename) == os.path.abspath(output.tmp):
                return output
        if error.filename is not None or error.errno not in (errno.ENOSPC, errno.EDQUOT, errno.EFBIG):
            return None
        for output in self._outputs.values():
            with contextlib.suppress(OSError):
                if output.device:
                    continue
                if error.errno == errno.EFBIG and os.stat(output.tmp).st_size >= _largest_file():
                    return output
                if error.errno != errno.EFBIG and os.statvfs(output.tmp.parent).f_bavail == 0:
                    return output
        return None

    def commit(self) -> None:
        """Move every temporary onto its target (devices are written in place). SIGINT, SIGTERM and SIGHUP wait
        while the outputs move and until that is recorded (:func:`committed`): one arriving then ends the command
        with the outputs whole and in place, never with them written by a command that says it failed. An
        interrupt noted before but never raised (dropped where Python could not raise it) stops it here, and so does
        a SIGTERM or SIGHUP whose ``SystemExit`` was dropped: the outputs of an interrupted command are not written."""
        if interrupted():
            self.discard()
            raise KeyboardInterrupt
        if _STOPPED[0]:  # SIGTERM's SystemExit dropped on its way (the whole bench, hostile28: exit 0, outputs written)
            self.discard()
            raise SystemExit(128 + _STOPPED[0])
        self._check_unread()
        held = _hold_signals()
        try:  # devices first: a write onto one can fail (/dev/full), a rename in place hardly; a device that failed
            # left the other outputs unwritten (hostile25: --rrd o.rrd was in place when --png /dev/full failed)
            for output in sorted(self._outputs.values(), key=lambda o: not o.device):
                _move(output)
            _COMMITTED[0] = True
        finally:
            self.discard()
            _release_signals(held)

    def _check_unread(self) -> None:
        """No output replaces a file the command read after its outputs were planned (the data of a suite, read as
        the episodes run): checked again before anything moves, so the input is kept and nothing is written."""
        for output in self._outputs.values():
            identity = _identity(output.target)
            if self._guard_read and not output.device and identity in _READ:
                self.discard()
                raise SealError(f"{output.option} {shown_path(output.target)} would overwrite the input "
                                f"{_READ[identity]}, which the command read; give another file name")

    def discard(self) -> None:
        """Remove every temporary not yet moved."""
        for output in self._outputs.values():
            with contextlib.suppress(OSError):
                output.tmp.unlink()
            _LIVE.discard(output.tmp)


def _largest_file() -> float:
    """The size of the largest file this process may write (``ulimit -f``, ``RLIMIT_FSIZE``): infinite if none."""
    import resource

    limit = resource.getrlimit(resource.RLIMIT_FSIZE)[0]
    return float("inf") if limit == resource.RLIM_INFINITY else limit


def _folder(folder: Path, option: str) -> Path:
    if not folder.is_dir():
        what = "is a file, not a folder" if folder.exists() else "does not exist"
        raise SealError(f"cannot write into {option} {folder}: it {what}")
    return folder


def _check_suffix(target: Path, option: str, allowed: Sequence[str]) -> None:
    suffix = target.suffix.lower()
    if allowed and suffix and suffix not in allowed and not _is_device(target):
        formats = " or ".join(allowed)
        kinds = " or ".join(s[1:].upper() for s in allowed)  # "JSONL or JSON" (it read "JSONL OR .JSON")
        raise SealError(f"{option} {shown_path(target)}: seal writes {kinds} files here; give a name ending in "
                        f"{formats}, not {target.suffix}")


def _is_device(path: Path) -> bool:
    try:
        mode = path.stat().st_mode
    except OSError:
        return False
    return stat.S_ISCHR(mode) or stat.S_ISFIFO(mode)


def _check_distinct(planned: list[tuple[str, Path]], inputs: list[Path], guard_read: bool) -> None:
    """No output is an input, and no two outputs are one file (by resolved path or by inode). An input that is a
    folder (a ROS 2 bag, a frame library's folder) has its files for inputs too (:func:`_with_files`)."""
    inputs = list(_with_files(inputs))
    read = {identity: str(path) for path in inputs if (identity := _identity(path)) is not None}
    resolved_inputs = {os.path.realpath(p): str(p) for p in inputs}
    seen: dict[str, str] = {}
    seen_ids: dict[tuple[int, int], str] = {}
    for option, target in planned:
        real = os.path.realpath(target)
        identity = _identity(target)
        device = _is_device(target)
        source = resolved_inputs.get(real) or (read.get(identity) if identity else None)
        if source is None and guard_read and identity in _READ:
            source = _READ[identity]
        if source is not None and not device:
            raise SealError(f"{option} {shown_path(target)} would overwrite the input {source}; give another file "
                            "name")
        other = seen.get(real) or (seen_ids.get(identity) if identity else None)
        if other is not None and not device:
            raise SealError(f"{option} and {other} name the same file ({shown_path(target)}); give each its own "
                            "file")
        seen[real] = option
        if identity:
            seen_ids[identity] = option


FOLDER_FILES = 10_000
"""The most files of an input folder :func:`_with_files` guards (a bag folder holds a few)."""


def _with_files(inputs: list[Path]) -> Iterator[Path]:
    """``inputs``, and the files directly in each that is a folder: ``import-bag x -o x/metadata.yaml`` replaced the
    ROS 2 bag's own metadata (hostile29), read by rosbags, not by seal, so never guarded as a file seal read."""
    for path in inputs:
        yield path
        with contextlib.suppress(OSError):
            if path.is_dir():
                with os.scandir(path) as entries:
                    for entry in itertools.islice(entries, FOLDER_FILES):
                        if entry.is_file():
                            yield Path(entry.path)


def _reserve(option: str, target: Path, by_option: bool = True) -> _Output:
    """Create the temporary for ``target`` (which proves its folder takes a file). A failure of the system is said
    of ``option``; but a writer nested in another's output (``atomic_output`` of the temporary that ``run --png``
    handed it: ``by_option`` False, ``target`` a live temporary) raises the ``OSError`` of ``target``, so that the
    outer one names its option (hostile26: a folder removed while ``run --png d/o.png`` ran was "cannot write output
    d/.o.png.seal…tmp.png")."""
    try:
        return _reserved(option, target)
    except OSError as exc:
        if not by_option and target in _LIVE:
            raise OSError(exc.errno, exc.strerror, str(target)) from None
        raise SealError(f"cannot write {option} {shown_path(target)}: {_reason(exc, target, in_folder=True)}") \
            from None


_NO_NEW_FILES = frozenset({errno.ENOENT, errno.EACCES, errno.EPERM, errno.EROFS})
"""What the system says when a folder that exists takes no new file: ``/proc`` says "No such file or directory" (its
files are the kernel's), ``/sys`` "Permission denied" even to root, a read-only mount EROFS (hostile30: "No such file
or directory (in folder /proc)" named a folder that exists)."""


def _root() -> bool:
    return hasattr(os, "geteuid") and os.geteuid() == 0


def _reason(error: OSError, target: Path, *, in_folder: bool = False) -> str:
    """Why writing ``target`` failed, in words: a folder that does not exist (or was removed while the command ran)
    is named, and with ``in_folder`` the folder of any other failure."""
    folder = target.parent
    if error.errno == errno.ENOENT and not folder.is_dir():
        return f"folder {shown_path(folder)} does not exist"
    if in_folder and error.errno in _NO_NEW_FILES and folder.is_dir():  # the temporary is the folder's first new file
        return (f"folder {shown_path(folder)} does not take new files ({error.strerror}"
                f"{'; seal runs as root here, so it is the file system that refuses' if _root() else ''})")
    return f"{error.strerror}" + (f" (in folder {shown_path(folder)})" if in_folder else "")


def shown_path(path: str | Path) -> str:
    """A path as a message shows it: a character that is not printable (a newline, an escape, a byte that was not
    UTF-8) as its escape, ``\\n``, ``\\x1b``, ``\\xff``, so that a name cannot break the message's line or talk
    to the terminal (hostile26: ``--rrd $'x\\ny.png'`` was said over two lines)."""
    text = str(path)
    return text if text.isprintable() else "".join(map(_shown_char, text))


def _shown_char(c: str) -> str:
    if c.isprintable():
        return c
    if 0xDC80 <= ord(c) <= 0xDCFF:        # a byte that was not UTF-8, as the file system's decoding keeps it
        return f"\\x{ord(c) - 0xDC00:02x}"
    return repr(c)[1:-1]


def _reserved(option: str, target: Path) -> _Output:
    try:
        mode = target.stat().st_mode
    except FileNotFoundError:
        mode = None
    except OSError as exc:
        raise SealError(f"cannot write {option} {shown_path(target)}: {exc.strerror}") from None
    if mode is not None and stat.S_ISDIR(mode):
        raise SealError(f"cannot write {option} {shown_path(target)}: it is a folder; give a file name")
    if mode is not None and not (stat.S_ISREG(mode) or stat.S_ISCHR(mode) or stat.S_ISFIFO(mode)):
        raise SealError(f"cannot write {option} {shown_path(target)}: it is {_kind(mode)}")
    device = mode is not None and not stat.S_ISREG(mode)
    if device and stat.S_ISFIFO(mode or 0):
        _check_reader(option, target)
    folder = target.parent
    if not device and not folder.is_dir():
        raise FileNotFoundError(errno.ENOENT, os.strerror(errno.ENOENT))
    if not device:
        _sweep(target)
    import secrets
    import tempfile

    name = f".{target.name}.seal{os.getpid()}-{secrets.token_hex(4)}.tmp{target.suffix}"
    tmp = Path(tempfile.gettempdir() if device else folder) / name
    with signals_wait():    # made and recorded as one step: a signal between them left the temporary behind
        fd = os.open(tmp, os.O_WRONLY | os.O_CREAT | os.O_EXCL, 0o666)  # the mode a plain open() gives
        os.close(fd)
        _LIVE.add(tmp)
    return _Output(option, target, tmp, device)


def _check_reader(option: str, target: Path) -> None:
    """A named pipe is written only if some process reads it (else opening it would wait forever)."""
    try:
        fd = os.open(target, os.O_WRONLY | os.O_NONBLOCK)
    except OSError:
        raise SealError(f"cannot write {option} {shown_path(target)}: it is a named pipe that no process reads") \
            from None
    os.close(fd)


def _move(output: _Output) -> None:
    try:
        if output.device:
            with output.tmp.open("rb") as source, output.target.open("wb") as sink:
                while chunk := source.read(2**20):
                    sink.write(chunk)
        else:
            os.replace(output.tmp, output.target)
    except OSError as exc:
        raise SealError(f"cannot write {output.option} {shown_path(output.target)}: {_reason(exc, output.target)}") \
            from None
    _LIVE.discard(output.tmp)


@contextlib.contextmanager
def atomic_output(path: str | Path) -> Iterator[Path]:
    """A temporary path for ``path``; moved onto it only if the block ends without error."""
    with Outputs({"output": path}, guard_read=False, by_option=False) as plan:
        yield plan["output"]


def atomic_write_text(path: str | Path, text: str) -> None:
    with atomic_output(path) as tmp:
        tmp.write_text(text, encoding="utf-8")
