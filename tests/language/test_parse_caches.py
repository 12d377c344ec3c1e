"""The parser's quick machinery parses as the plain one did, on a sample of every corpus.

What was made quicker (docs/benchmarks.md, "Parsing speed: this round (speed1)") is checked against the
plain code it replaced, kept here as the reference: phrase tables read word by word
(``state.match_phrase``, ``state.longest_phrase``), the rules' gates asked afresh at every word, each
phrase grounded anew, the library's types asked without memory and no parse tree shared; and, since perf46,
the chooser's sums taken row by row (``chooser.logits``) and each word's text read afresh (``tokens.read_word``).
The outputs of both, parse or error, must be equal on GPSR dev, ALFRED valid_seen and train goals (with ALFRED's
classes), every set of people's wording in ``tests/data`` and the commands of the end-to-end suites.
"""

from __future__ import annotations

import csv
import json
import sys
from collections.abc import Iterable, Iterator, Mapping, Sequence
from pathlib import Path
from typing import Any

import pytest
import yaml

import seal_cli.language.english as english
from seal_cli.errors import SealError
from seal_cli.frames.library import Library
from seal_cli.language import chooser, lexicon, state, tokens
from seal_cli.language.element_types import Types
from seal_cli.language.english import SPELLINGS
from seal_cli.language.grounding import Vocabulary
from seal_cli.language.parser import CommandParser
from seal_cli.language.tokens import Word, tokenize

DATA = Path(__file__).parents[1] / "data"
SUITES = Path(__file__).parents[2] / "seal_cli" / "bench" / "suites"

_MULTIWORD: dict[str, list[str]] = {}
for _table in (english.PREPOSITIONS, english.POLITE, english.POLITE_FORMULAE, english.THANKS_AHEAD,
               english.SEPARATOR_WORDS,
               english.SEQUENCE_ADVERBS, english.NUMBERS, english.HERE_WORDS, english.TIME_WORDS,
               english.SUBORDINATORS, english.VOCATIVES):
    for _phrase in _table:
        if " " in _phrase:
            _MULTIWORD.setdefault(_phrase.split()[0], []).append(_phrase)


def plain_match_phrase(words: Sequence[Word], i: int, table: Iterable[str] | Mapping[str, object]) -> int:
    """``state.match_phrase`` as it was: every multiword phrase of the closed-class tables that starts with the
    word, split and compared word by word."""
    first = words[i].lower
    if first not in _MULTIWORD:
        return 1 if first in table else 0
    best = 0
    for phrase in _MULTIWORD[first]:
        if phrase in table:
            parts = phrase.split()
            n = len(parts)
            if n > best and i + n <= len(words) and all(words[i + k].lower == parts[k] for k in range(n)):
                best = n
    return 1 if best == 0 and first in table else best


def plain_longest_phrase(words: Sequence[Word], i: int, table: frozenset[str]) -> int:
    """``state.longest_phrase`` as the rules' ``_phrase`` was: every phrase of the table, split and compared."""
    best = 0
    for phrase in table:
        parts = phrase.split()
        n = len(parts)
        if n > best and i + n <= len(words) and all(words[i + k].lower == parts[k] for k in range(n)):
            best = n
    return best


class PlainGates(lexicon.Gates):
    """The rules' ``first`` gates asked at every word, nothing remembered, and no index by the last tag (each
    rule's ``after`` gate is left out: the rule is asked after any tag, as before perf30; nor its ``needs``, perf47)."""

    def rules(self, low: str, after: str, unsaid: int = 0) -> tuple[tuple[Any, ...], ...]:
        return tuple(tuple(r for r in table if r.admits(low)) for table in self.tables)


def plain_logits(weights: Mapping[str, Mapping[str, float]], keys: Iterable[str], feats: Iterable[str]
                 ) -> dict[str, float]:
    """``chooser.logits`` as it was: each feature's row added to every key in turn."""
    out = dict.fromkeys(keys, 0.0)
    for f in feats:
        row = weights.get(f)
        if row:
            for key in out:
                out[key] += row.get(key, 0.0)
    return out


def plain_read_word(text: str) -> str:
    """``tokens.read_word`` as ``Word`` did it, nothing remembered."""
    lower = text.lower()
    lower = lower.replace("’", "'") if "’" in lower else lower
    return SPELLINGS.get(lower, lower)


def _jsonl(path: Path) -> list[str]:
    return [json.loads(line)["text"] for line in path.read_text(encoding="utf-8").splitlines() if line.strip()]


def _goals(path: Path) -> list[str]:
    with path.open(encoding="utf-8", newline="") as rows:
        return [" ".join(str(row.get("goal_sentence") or "").split()) for row in csv.DictReader(rows, delimiter="\t")]


def corpora(shared: Path) -> Iterator[tuple[str, list[str], Vocabulary | None]]:
    """A sample of each corpus, with the vocabulary it is scored with."""
    constants = json.loads((shared / "alfred" / "alfred_constants.json").read_text(encoding="utf-8"))
    alfred = Vocabulary.of([str(c) for c in constants["OBJECTS"]])
    yield "gpsr dev", _jsonl(shared / "gpsr" / "dev.jsonl")[::6], None
    yield "alfred valid_seen", _goals(shared / "alfred" / "goals_valid_seen.tsv")[::4], alfred
    yield "alfred train", _goals(shared / "alfred" / "goals_train.tsv")[::150], alfred
    yield "people's wording", [t for path in sorted(DATA.glob("wording*.jsonl")) for t in _jsonl(path)][::2], None
    e2e = [case["text"] for path in sorted(SUITES.glob("e2e*.yaml"))
           for case in yaml.safe_load(path.read_text(encoding="utf-8"))["cases"] if "text" in case]
    yield "end-to-end suites", e2e[::3], None


def outputs(parser: CommandParser, texts: Sequence[str], vocabulary: Vocabulary | None,
            fresh: bool = False) -> list[object]:
    found: list[object] = []
    for text in texts:
        if fresh:                                 # nothing carried over from the commands before
            parser.trees.clear()
            parser.types = Types(parser.library)
        try:
            found.append(parser.parse(text, vocabulary).to_json())
        except SealError as error:
            found.append(str(error))
    return found


def _patch_everywhere(monkeypatch: pytest.MonkeyPatch, name: str, quick: object, plain: object) -> None:
    """Put ``plain`` wherever a module of the language imported ``quick`` under ``name``."""
    for module_name, module in list(sys.modules.items()):
        if module_name.startswith("seal_cli.language") and getattr(module, name, None) is quick:
            monkeypatch.setattr(module, name, plain)


def test_the_phrase_tables_read_as_before(shared_data: Path) -> None:
    tables = [t for name, t in vars(english).items() if name.isupper() and isinstance(t, (frozenset, dict))
              and all(isinstance(p, str) for p in t)]
    phrase_sets = [t for t in tables if isinstance(t, frozenset)]
    assert len(tables) > 40 and len(phrase_sets) > 30
    texts = [t for _, sample, _ in corpora(shared_data) for t in sample[::8]]
    positions = 0
    for text in texts:
        try:
            words = tokenize(text)
        except SealError:
            continue
        for i in range(len(words)):
            positions += 1
            for table in tables:
                assert state.match_phrase(words, i, table) == plain_match_phrase(words, i, table), (text, i)
            for phrase_set in phrase_sets:
                assert state.longest_phrase(words, i, phrase_set) == plain_longest_phrase(words, i, phrase_set)
    assert positions > 2000


def test_every_corpus_parses_as_with_the_plain_machinery(library: Library, shared_data: Path,
                                                          monkeypatch: pytest.MonkeyPatch) -> None:
    samples = list(corpora(shared_data))
    quick = CommandParser.of(library)
    expected_sizes = {"gpsr dev": 500, "alfred valid_seen": 205}
    found = {name: outputs(quick, texts, vocabulary) for name, texts, vocabulary in samples}
    for name, size in expected_sizes.items():
        assert len(found[name]) == size
    assert sum(isinstance(x, dict) for x in found["gpsr dev"]) == 500          # GPSR dev parses whole

    _patch_everywhere(monkeypatch, "match_phrase", state.match_phrase, plain_match_phrase)
    _patch_everywhere(monkeypatch, "longest_phrase", state.longest_phrase, plain_longest_phrase)
    _patch_everywhere(monkeypatch, "logits", chooser.logits, plain_logits)
    monkeypatch.setattr(tokens, "read_word", plain_read_word)
    monkeypatch.setattr(lexicon, "_GATES", PlainGates(lexicon._GATES.tables))
    monkeypatch.setattr(Vocabulary, "grounded", lambda self, words, of=(): self.ground_words(list(words), -1, list(of)))
    plain = CommandParser(library)
    for name, texts, vocabulary in samples:
        assert outputs(plain, texts, vocabulary, fresh=True) == found[name], name


def test_a_phrase_table_of_any_kind_reads_as_a_set_of_phrases() -> None:
    words = tokenize("would you mind showing me where the keys are")
    phrases = ["would you mind", "would you", "you mind showing", "where"]
    for table in (phrases, tuple(phrases), dict.fromkeys(phrases), frozenset(phrases)):
        found = [state.longest_phrase(words, i, table) for i in range(len(words))]
        assert found == [plain_longest_phrase(words, i, frozenset(phrases)) for i in range(len(words))]
        assert found == [3, 3, 0, 0, 0, 1, 0, 0, 0]
