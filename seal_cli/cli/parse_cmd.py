"""``seal parse`` and ``seal bench parse``: commands in words → the frames they evoke."""

from __future__ import annotations

import json
import subprocess
import sys
import tempfile
from pathlib import Path
from typing import TYPE_CHECKING, Any

import typer

from seal_cli.cli import FramelibOption, JsonOption, bench_app, command, emit_json, err, framelib_paths, out
from seal_cli.cli.output import dump_json, plain
from seal_cli.cli.parse_view import _escape, print_parse, summary
from seal_cli.errors import SealError, Where

if TYPE_CHECKING:
    from seal_cli.frames.library import Library
    from seal_cli.language.grounding import Vocabulary

VocabularyOption = typer.Option(None, "--vocabulary", help="YAML list of object classes (each a name or "
                                "{class: NAME, synonyms: [...]}) to ground elements in.", show_default=False)
MapOption = typer.Option(None, "--map", help="Ground elements in the classes of this map (its places, objects "
                         "and priors); a path or a shipped map's name.", show_default=False)


def vocabulary_from(vocabulary: Path | None, map_name: str | None) -> Vocabulary | None:
    """The vocabulary named by ``--vocabulary`` and/or ``--map`` (both: their union)."""
    from dataclasses import replace

    from seal_cli.language.grounding import Vocabulary, load_vocabulary, vocabulary_of_map

    found: list[Vocabulary] = []
    if vocabulary is not None:
        found.append(load_vocabulary(vocabulary))
    if map_name is not None:
        from seal_cli.maps.formats.map_server import load_map
        from seal_cli.resources import map_path

        found.append(vocabulary_of_map(load_map(map_path(map_name))))
    if not found:
        return None
    if len(found) == 1:
        return found[0]
    names = [c for v in found for c in v.classes]
    synonyms: dict[str, list[str]] = {}
    for v in found:
        for name, extra in zip(v.classes, v.synonyms, strict=True):
            synonyms.setdefault(name, []).extend(extra)
    return replace(Vocabulary.of(names, synonyms), people=frozenset(p for v in found for p in v.people),
                   house=any(v.house for v in found))


def _read_lines(source: str) -> list[str]:
    """The lines of a file or of standard input ('-'): one command per ``\\n``-separated line."""
    from seal_cli.fileio import MAX_INPUT_BYTES, decode, read_text, split_lines

    if source != "-":
        return split_lines(read_text(source))
    if sys.stdin is None:  # started with its standard input closed
        raise SealError("--file -: standard input is closed; pipe the commands in, or give a file")
    data = sys.stdin.buffer.read(MAX_INPUT_BYTES + 1)
    if len(data) > MAX_INPUT_BYTES:
        raise SealError(f"standard input holds more than {MAX_INPUT_BYTES // 2**20} MiB; seal reads at most that")
    return split_lines(decode(data, "<stdin>"))


@command("parse")
def parse(
    text: str | None = typer.Argument(None, help="The command, e.g. \"bring Roger a coffee from the kitchen\"."),
    file: str | None = typer.Option(None, "--file", "-f", help="Parse one command per line of this file "
                                    "('-': standard input); with --json, one JSON object per line.",
                                    show_default=False),
    vocabulary: Path | None = VocabularyOption,
    map_name: str | None = MapOption,
    framelib: list[Path] | None = FramelibOption,
    as_json: bool = JsonOption,
) -> None:
    """Parse a command into the frames it evokes, with their elements."""
    from seal_cli.frames.reading import load_library
    from seal_cli.language.parser import parse_lines

    if (text is None) == (file is None):
        raise typer.BadParameter("give either a command or --file FILE (one command per line; '-' reads standard "
                                 "input)", param_hint="TEXT / --file")
    library = load_library(framelib_paths(framelib))
    vocab = vocabulary_from(vocabulary, map_name)
    if file is not None:
        lines = _read_lines(file)
        if as_json:
            sys.stdout.write("".join(dump_json(result) + "\n"
                                     for result in parse_lines(lines, library, vocab)))
            sys.stdout.flush()
            return
        for number, result in enumerate(parse_lines(lines, library, vocab), 1):
            if "error" in result:
                out.print(f"{number}: [red]error[/red] {_escape(result['error']['message'])} "
                          f"(column {result['error']['column']})")
            else:
                out.print(f"{number}: {_escape(summary(result))}")
        return
    assert text is not None
    code = print_parse(text, library, vocab, as_json)
    if code:
        raise typer.Exit(code)


# ---------------------------------------------------------------------------------------------
# seal bench parse


def _alfred_classes(constants: Path) -> list[str]:
    """The classes of ALFRED's constants (what the scorer grounds in)."""
    from seal_cli.fileio import read_json

    raw = read_json(constants, "ALFRED constants file")
    try:
        classes = raw["OBJECTS"]
        if not isinstance(classes, list):
            raise TypeError(f"OBJECTS is {type(classes).__name__}, not a list")
    except (KeyError, TypeError) as error:
        raise SealError(f"cannot read the ALFRED constants' OBJECTS: {error}", Where(str(constants))) from None
    wrong = next((c for c in classes if not isinstance(c, str) or not c.strip()), None)
    if wrong is not None or not classes:  # the scorer writes each as a YAML list item: 5 was read as a number
        raise SealError("the ALFRED constants' OBJECTS " + ("is empty" if not classes else f"holds {wrong!r}, not "
                        "a class name") + ": it lists ALFRED's object classes as strings", Where(str(constants)))
    return classes


def _shared() -> Path:
    """``../shared`` beside the checkout (where the corpora and scorers are)."""
    return Path(__file__).resolve().parents[2] / ".." / "shared"


@command("parse", on=bench_app)
def bench_parse(
    corpus: list[Path] | None = typer.Option(None, "--corpus", help="Corpus to score (repeatable): GPSR-style "
                                             "JSON Lines, or ALFRED goals (.tsv). Default: the shipped GPSR dev "
                                             "set and ALFRED valid_seen goals.", show_default=False),
    constants: Path | None = typer.Option(None, "--constants", help="ALFRED constants (classes) for .tsv goals; "
                                          "default: the shipped alfred_constants.json.", show_default=False),
    scorers: Path | None = typer.Option(None, "--scorers", help="Folder of the scorers (default: ../shared/eval).",
                                        show_default=False),
    as_json: bool = JsonOption,
) -> None:
    """Score `seal parse` on parsing corpora with the shared scorers, and print their figures; then
    parse each corpus in process: commands per CPU-second, clauses swallowed into an element
    (refused by the parser, or left silently), states a question asks dropped silently, and phrases of a
    clause no frame element takes (refused, or left silently; the target of each is zero)."""
    from seal_cli.frames.reading import load_library

    library = load_library()
    shared = _shared()
    folder = scorers or shared / "eval"
    corpora = list(corpus or [shared / "data" / "gpsr" / "dev.jsonl", shared / "data" / "alfred" /
                              "goals_valid_seen.tsv"])
    if constants is not None and not any(path.suffix == ".tsv" for path in corpora):  # passed over before (hostile20)
        raise SealError(f"--constants {constants}: the ALFRED constants are read for ALFRED goals (a .tsv --corpus), "
                        "and no --corpus given is one")
    with tempfile.TemporaryDirectory(prefix="seal-bench-parse-") as work:
        _score(corpora, folder, constants or shared / "data" / "alfred" / "alfred_constants.json", Path(work),
               library, as_json, shipped=not corpus)


def _score(corpora: list[Path], folder: Path, constants: Path, work: Path, library: Library, as_json: bool, *,
           shipped: bool) -> None:
    """Check every corpus, scorer and constants file, then score each: the scorers read seal's plain copies of
    the corpora and constants (:mod:`seal_cli.bench.corpora`), never the user's files."""
    from seal_cli.bench.corpora import Corpus, read_corpus, write_plain
    from seal_cli.bench.parsing import commands_of, measure
    from seal_cli.fileio import shown_path
    from seal_cli.language.grounding import Vocabulary

    seal = f"{sys.executable} -m seal_cli"
    results: dict[str, Any] = {}
    runs: list[tuple[Corpus, list[str], Vocabulary | None]] = []
    for path in corpora:  # every corpus, scorer and constants file checked before any is scored (no half output)
        if not path.exists():
            where = "" if not shipped else (" (the default corpora are in ../shared/data beside a checkout of seal, "
                                            "which an installed seal does not have: give --corpus FILE and --scorers "
                                            "DIR)")
            raise SealError(f"no such corpus: {path}{where}", Where(str(path)))
        read = read_corpus(path)  # every field the scorer reads, at its line (hostile28: a KeyError in the scorer)
        vocab = None
        if read.table:  # the constants checked before the scorer reads them (a FIFO there hung it), then copied
            classes = _alfred_classes(constants)
            vocab = Vocabulary.of(classes)
            plain_constants = work / "constants.json"
            plain_constants.write_text(json.dumps({"OBJECTS": classes}), encoding="utf-8")
            argv = [str(folder / "score_alfred_goals.py"), str(write_plain(read, work)), str(plain_constants)]
        else:
            argv = [str(folder / "score_parse.py"), str(write_plain(read, work))]
        if not Path(argv[0]).is_file():  # a FIFO or a folder of that name was "not found" (hostile30)
            import os

            from seal_cli.fileio import _kind

            what = f"is {_kind(os.stat(argv[0]).st_mode)}, not a scorer" if os.path.exists(argv[0]) else "not found"
            raise SealError(f"scorer {argv[0]} {what} (give --scorers DIR, the folder of the shared scorers)",
                            Where(argv[0]))
        runs.append((read, argv, vocab))
    for read, _, _ in runs:  # then what each holds: the scorer divided by zero on a corpus of no commands
        if not any(commands_of(read.path)):
            raise SealError("this corpus holds no commands: a corpus is JSON Lines with a 'text' in each line, or an "
                            "ALFRED goals table (.tsv) with a 'goal_sentence' column", Where(str(read.path)))
    for read, argv, vocab in runs:
        path = read.path
        err.print(f"scoring {path} ...", markup=False)
        run = subprocess.run([sys.executable, *argv, "--seal", seal, *(["--json"] if as_json else [])],
                             capture_output=True, text=True)
        if run.returncode and "Traceback (most recent call last)" in run.stderr:  # it crashed (exit 1 is a low score)
            last = run.stderr.strip().splitlines()[-1]
            if last.startswith("ZeroDivisionError") and not read.expects:
                raise SealError("the scorer scored none of this corpus's commands: it passes over a GPSR command "
                                "whose command_types it has no template for (or whose fills do not match them), "
                                "and no line gives its frames as 'expect'", Where(str(path)))
            raise SealError(f"the scorer failed on {path}: {last}", Where(str(path)))
        figures = measure(commands_of(path), library, vocab)
        if as_json:
            lines = run.stdout.strip().splitlines()
            try:
                results[str(path)] = json.loads("\n".join(lines[:-1]))
            except json.JSONDecodeError:
                raise SealError(f"the scorer failed on {path}: {run.stderr[-500:]}") from None
            results[str(path)]["in_process"] = figures.to_json()
        else:
            out.print(f"[bold]{plain(shown_path(path))}[/bold]")
            out.print(plain(run.stdout.rstrip()))  # the scorer prints each command as it is: an escape sequence too
            if run.returncode and run.stderr:
                err.print(plain(run.stderr.rstrip()[-1000:]))
            out.print(f"in process: {figures.commands_per_cpu_s:,.0f} commands/CPU-s; clauses swallowed into an "
                      f"element: {figures.silent_swallowed} silently, {figures.refused_swallowed} refused; states "
                      f"dropped: {figures.silent_dropped}; phrases no element takes: {figures.silent_unplaced} "
                      f"silently, {figures.refused_unplaced} refused (n={figures.commands}, errors {figures.errors})")
    if as_json:
        emit_json({"corpora": results})
