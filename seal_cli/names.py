"""How long a name may be: of a frame, element, predicate, action, category or class, of a map, room,
place or person.

Every name is shown whole somewhere: in a row of ``seal frames`` or ``seal map`` on a terminal, in a label
of a map's PNG, in a Rerun entity path (``world/rooms/<name>``), in a plan's step. A name of 100,000
letters validated, then filled every message and every picture that showed it. :data:`MAX_NAME` is the
longest name those show whole: 100 characters are one line of a 120-column terminal beside the
table's other column, and, at the PNG's room-label size (9 pt bold, 120 dpi), about 900 pixels, the
width of the apartment's picture; a longer name would run off it.
"""

from __future__ import annotations

from seal_cli.errors import SealError, Where

__all__ = ["MAX_NAME", "check_name_length", "check_plannable", "check_sayable", "check_shown", "name_too_long"]

MAX_NAME = 100
"""The most characters a name may hold (the class names' bound too: ``frames.taxonomy.MAX_CLASS_NAME``)."""


def name_too_long(name: str, what: str, where: Where | None = None) -> SealError | None:
    """The problem, at ``where``, of a name longer than :data:`MAX_NAME`, or None; ``what`` says which name
    it is ("room name", "frame name")."""
    if len(name) <= MAX_NAME:
        return None
    return SealError(f"{what} '{name[:40]}…' is {len(name):,} characters long; a name has at most {MAX_NAME} "
                     "(what a terminal line, a label on a map's picture and a Rerun path show whole)", where)


def check_name_length(name: str, what: str, where: Where | None = None) -> str:
    """``name`` itself, or :func:`name_too_long`'s problem raised."""
    problem = name_too_long(name, what, where)
    if problem is not None:
        raise problem
    return name


UNSHOWN = {"Cc": "a control character", "Zl": "a line separator", "Zp": "a paragraph separator",
           "Cs": "half of a character (a lone surrogate)"}
"""Unicode's categories of what a name cannot hold to be shown: on a terminal (a NUL ends a C string, an escape
starts a terminal's command), in a picture's title (no glyph) or on a line of its own."""

REORDERING = {"LRE", "RLE", "LRO", "RLO", "PDF", "LRI", "RLI", "FSI", "PDI"}
"""Unicode's bidirectional embeddings, overrides and isolates: invisible, they reorder what follows them on the line
(a right-to-left override turns the rest of a terminal's line around). Other invisible characters stay: a zero-width
non-joiner belongs in Persian words, a zero-width joiner in emoji."""


def check_shown(name: str, what: str, where: Where | None = None, *, allowed: str = "") -> str:
    """``name`` itself, or a problem at ``where`` if it holds a character no terminal line or picture shows as itself
    (:data:`UNSHOWN`, :data:`REORDERING`). A map's own name is never said in a command (so it may hold symbols and
    punctuation), but it is the first word of ``seal map``, a picture's title and the JSON's ``map``: a map named
    ``"m\\0x"`` or ``"m\\u202Eeman"`` (YAML's escapes) validated, its NUL drawn as a missing glyph, its override
    reversing the rest of the terminal's line (hostile27). ``allowed``: characters a longer text may hold all the same
    (a frame's description: its line breaks and tabs)."""
    import unicodedata

    for character in name:
        if character in allowed:
            continue
        kind = unicodedata.category(character)
        if kind in UNSHOWN or unicodedata.bidirectional(character) in REORDERING:
            called = unicodedata.name(character, "")
            raise SealError(f"{what} {name!r} holds {character!r} (U+{ord(character):04X}{' ' if called else ''}"
                            f"{called}), {UNSHOWN.get(kind, 'an invisible character that reorders the line')}, "
                            "which no terminal line or picture shows as itself: name it in printable characters", where)
    return name


def check_sayable(name: str, what: str, where: Where | None = None) -> str:
    """``name`` itself, or a problem at ``where`` if it holds what no command can say: an invisible character (a
    zero-width joiner, a right-to-left mark: Unicode's format characters, pasted with a name) or a symbol (an emoji).
    A room called "🛏" or "hall" + U+200D validated, then "go to the hall" never found it and "go to the 🛏" was
    refused at the emoji (hostile21). Rooms and people are named by commands; a map's own name is not."""
    import unicodedata

    for character in name:
        kind = unicodedata.category(character)
        if kind in ("Cf", "So"):
            said = "an invisible character" if kind == "Cf" else "a symbol"
            raise SealError(f"{what} {name!r} holds {character!r} (U+{ord(character):04X} "
                            f"{unicodedata.name(character, 'unnamed')}), {said} no command can say: name it in "
                            "letters, digits and spaces", where)
    return check_plannable(name, what, where)


def check_plannable(name: str, what: str, where: Where | None = None) -> str:
    """``name`` itself, or a problem at ``where`` if a plan cannot name it. A plan names a room or a person by
    its words joined by '_' (``"living room"`` is ``living_room``, a fact's argument: letters, digits and '_', not
    starting with a digit), so a name with other punctuation (``"kid's room"``, ``"Dr. Smith"``, ``"hall: 2"``,
    ``"R&D lab"``) or whose first word starts with a digit (``"2nd floor"``) validated, then failed every plan
    that went there with ``argument "kid's_room" is not a name``, said at a line of seal's own ``motion.yaml``
    (or, for ``&``, at the character of the command, hostile22). Spaces, '_' and '-' part words; the letters
    of any script and their accents (combining marks) stay. A tab, a line's end (U+0085, U+2028) and a name of marks
    alone (accents on nothing) validated (hostile24)."""
    import unicodedata

    for character in name:
        if not (character.isalnum() or character in "_-" or unicodedata.category(character).startswith("M")
                or character.isspace() and unicodedata.category(character) == "Zs"):  # not a tab, nor a line's end
            raise SealError(f"{what} {name!r} holds {character!r}, which a plan cannot name (it names a room or a "
                            "person by its words joined by '_'): name it in letters, digits and spaces ('-' and "
                            "'_' part words too)", where)
    first = next((c for c in name if c.isalnum()), "")
    if not first:
        raise SealError(f"{what} {name!r} holds no letter or digit, so no command can say it (a name is said by its "
                        "words): name it in letters, digits and spaces", where)
    if first.isdigit():
        raise SealError(f"{what} {name!r} starts with a digit, which a plan cannot name (it names a room or a person "
                        "by its words joined by '_', a name starting with a letter): put the number after a word, "
                        "as in 'floor 2'", where)
    return name
