"""``seal bench parse``, in process: how fast commands are parsed, and whether any clause is swallowed.

:func:`measure` parses every command of a corpus with :func:`~seal_cli.language.parser.parse_command`
in this process (after one warm-up pass over the first commands, so the figure is the parser's, not
the grammar's loading) and reports commands per CPU-second (``time.process_time``: on a shared
machine, the CPU time is what compares), with:

* ``refused_swallowed``: commands refused because a verb of the library was said inside an element's
  text (the parser's error "... is a verb inside the goal ..."): instructions that would have been
  swallowed and are refused instead;
* ``silent_swallowed``: parses that still hold such a verb in an element's text, found by
  :func:`~seal_cli.language.swallowed.swallowed` on the output (over the command's own tokens, not
  the tagger's): the target is zero on every corpus;
* ``silent_dropped``: parses that drop a word of state ending a sentence ("is the light in the office *on*?"
  read as a search, words26), found by :func:`~seal_cli.language.dropped.dropped_states`: the target is zero too;
* ``refused_unplaced``: commands refused because a phrase of a clause reached no frame element (the parser's
  error "... no element of Bring takes it ...", :mod:`~seal_cli.language.unplaced`);
* ``silent_unplaced``: parses that still leave such a phrase (``Parse.unplaced``): the target is zero (words31).
  Since the parser refuses every command that leaves one, this is zero by construction; it was the figure of the
  corpora before that refusal (GPSR dev 0, ALFRED valid_seen 9, ``tests/data`` 26), and ``refused_unplaced`` is the
  one that moves now.
"""

from __future__ import annotations

import contextlib
import csv
import time
from collections.abc import Sequence
from dataclasses import asdict, dataclass
from pathlib import Path
from typing import TYPE_CHECKING

from seal_cli.errors import SealError, Where
from seal_cli.fileio import read_json_lines
from seal_cli.frames.library import Library
from seal_cli.language.dropped import dropped_states
from seal_cli.language.lexicon import CommandError, tokenize
from seal_cli.language.parser import CommandParser
from seal_cli.language.swallowed import swallowed
from seal_cli.language.unplaced import EXPECTED as UNPLACED
from seal_cli.language.values import Parse

if TYPE_CHECKING:
    from seal_cli.language.grounding import Vocabulary

__all__ = ["ParsingFigures", "commands_of", "measure"]


SWALLOWED = "a clause of its own"
"""What the parser's error expects when it refuses a verb inside an element."""


@dataclass(frozen=True)
class ParsingFigures:
    """What :func:`measure` found on one corpus."""

    commands: int
    parsed: int
    errors: int
    refused_swallowed: int
    silent_swallowed: int
    commands_per_cpu_s: float
    silent_dropped: int = 0
    refused_unplaced: int = 0
    silent_unplaced: int = 0

    def to_json(self) -> dict[str, float | int]:
        return asdict(self)


def commands_of(path: Path) -> list[str]:
    """The commands of a corpus: the ``text`` of each JSON line (a line without one is skipped: the
    scorer says what is wrong with it), or the ``goal_sentence`` of each row of an ALFRED goals table
    (``.tsv``), its runs of white space made single, as the scorer does."""
    if path.suffix != ".tsv":
        return [item["text"] for item in read_json_lines(path)
                if isinstance(item, dict) and isinstance(item.get("text"), str)]
    try:
        with path.open(encoding="utf-8", newline="") as rows:
            return [" ".join(str(row.get("goal_sentence") or "").split())
                    for row in csv.DictReader(rows, delimiter="\t")]
    except (OSError, UnicodeDecodeError, csv.Error) as error:
        raise SealError(f"cannot read the corpus: {error}", Where(str(path))) from None


def measure(texts: Sequence[str], library: Library, vocabulary: Vocabulary | None = None,
            warmup: int = 200) -> ParsingFigures:
    """Parse every command in this process (see the module docstring)."""
    parser = CommandParser.of(library)
    for text in texts[:warmup]:
        with contextlib.suppress(SealError):
            parser.parse(text, vocabulary)
    parses: list[Parse] = []
    errors = refused = refused_unplaced = 0
    start = time.process_time()
    for text in texts:
        try:
            parses.append(parser.parse(text, vocabulary))
        except CommandError as error:
            errors += 1
            refused += error.expected == [SWALLOWED]
            refused_unplaced += error.expected == [UNPLACED]
        except SealError:
            errors += 1
    seconds = time.process_time() - start
    things = library.taxonomy.known_classes
    silent = dropped = 0
    for parse in parses:
        tokens = tokenize(parse.text)
        silent += bool(swallowed(parse, tokens, parser.lexicon, things))
        dropped += bool(dropped_states(parse, tokens))
    return ParsingFigures(len(texts), len(parses), errors, refused, silent,
                          round(len(texts) / seconds, 1) if seconds > 0 else float("inf"), dropped,
                          refused_unplaced, sum(bool(parse.unplaced) for parse in parses))
