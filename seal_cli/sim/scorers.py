"""The language model of the SayCan baseline, behind one small interface: :class:`Scorer`.

``Scorer.score(prompt, options)`` returns one log-probability per option: how likely a language
model finds each option as the next line after the prompt. The SayCan runner
(:mod:`seal_cli.sim.skills`) writes the prompt as :func:`prompt_for` does — the instruction on the
first line, then one line per skill already carried out — so a hosted or local LLM plugs in by
scoring ``prompt + "\\n" + option`` and normalising over the options.

Two scorers ship, both offline and deterministic:

- :class:`BagOfWordsScorer`: hashed bag-of-words vectors; no dependency; what the tests use;
- :class:`WordLlamaScorer`: WordLlama's static embeddings (the ``llm`` extra, weights inside the
  wheel, nothing downloaded at run time).

Both are :class:`SimilarityScorer` s: an embedding model is not a language model, so the
conditional ``p(option | instruction, history)`` is approximated as the *progress* the option makes: how much
adding it to what has been done brings the sum of the history's line vectors closer (in cosine) to
the instruction. ``done`` adds nothing, so it scores zero less a small margin and wins once no
skill brings the history closer to the instruction; the skill just done (the same line) is
penalised, as an LLM conditioned on the history would not ask for it again. The scores are
softmaxed at a temperature.
"""

from __future__ import annotations

import re
import zlib
from collections.abc import Sequence
from typing import Protocol

import numpy as np

from seal_cli.errors import SealError

__all__ = ["DONE", "BagOfWordsScorer", "Scorer", "SimilarityScorer", "WordLlamaScorer", "prompt_for",
           "read_prompt"]

DONE = "done"
"""The option that ends a run."""


class Scorer(Protocol):
    """A language model's judgement of the next line."""

    def score(self, prompt: str, options: Sequence[str]) -> np.ndarray:
        """Log-probabilities (natural log, summing to one in probability) of each option after the prompt."""
        ...


def prompt_for(instruction: str, history: Sequence[str]) -> str:
    """The prompt the SayCan runner asks about: the instruction, then the skills done, one a line."""
    return "\n".join([instruction.strip(), *history])


def read_prompt(prompt: str) -> tuple[str, list[str]]:
    """The instruction and the history back from a :func:`prompt_for` prompt."""
    lines = prompt.split("\n")
    return lines[0], [line for line in lines[1:] if line]


def _log_softmax(x: np.ndarray) -> np.ndarray:
    x = x - x.max()
    return np.asarray(x - np.log(np.exp(x).sum()), dtype=float)


class SimilarityScorer:
    """A scorer from an embedding of text (``embed``: strings → unit rows); see the module docstring."""

    temperature: float = 0.1
    repeat_penalty: float = 1.0
    done_offset: float = -0.02

    def __init__(self) -> None:
        self._cache: dict[str, np.ndarray] = {}

    def embed(self, texts: Sequence[str]) -> np.ndarray:
        raise NotImplementedError

    def vectors(self, texts: Sequence[str]) -> np.ndarray:
        todo = [t for t in dict.fromkeys(texts) if t not in self._cache]
        if todo:
            rows = np.asarray(self.embed(todo), dtype=float)
            norms = np.linalg.norm(rows, axis=1, keepdims=True)
            rows = rows / np.where(norms > 0, norms, 1.0)
            self._cache.update(zip(todo, rows, strict=True))
        return np.stack([self._cache[t] for t in texts]) if texts else np.zeros((0, 1))

    def score(self, prompt: str, options: Sequence[str]) -> np.ndarray:
        if not options:
            raise SealError("nothing to score: no options")
        instruction, history = read_prompt(prompt)
        instr = self.vectors([instruction])[0]
        done_lines = [h for h in history if not h.startswith("failed to ")]
        summed = self.vectors(done_lines).sum(axis=0) if done_lines else np.zeros_like(instr)
        before = _cos(instr, summed)
        skills = [o for o in options if o != DONE]
        rows = self.vectors(skills) if skills else np.zeros((0, len(instr)))
        after = np.array([_cos(instr, summed + row) for row in rows])
        gain = after - before
        if done_lines and skills:   # the step just done is not asked for again
            repeat = rows @ self.vectors(done_lines[-1:])[0] > 0.999
            gain = gain - self.repeat_penalty * repeat
        it = iter(gain)
        scores = np.array([self.done_offset if o == DONE else next(it) for o in options])
        return _log_softmax(scores / self.temperature)


def _cos(a: np.ndarray, b: np.ndarray) -> float:
    n = float(np.linalg.norm(b))
    return float(a @ b) / n if n > 0 else 0.0


_WORD = re.compile(r"[a-z0-9]+")
_FUNCTION_WORDS = frozenset({"the", "and", "then", "with", "into", "onto", "from", "its", "it", "in", "on", "a", "an",
                             "to", "of"})


class BagOfWordsScorer(SimilarityScorer):
    """Hashed bag-of-words vectors (1024 buckets) of the content words (English function words
    left out), plurals folded; deterministic."""

    def __init__(self, dims: int = 1024) -> None:
        super().__init__()
        self.dims = dims

    def embed(self, texts: Sequence[str]) -> np.ndarray:
        rows = np.zeros((len(texts), self.dims))
        for r, text in enumerate(texts):
            for word in _WORD.findall(text.lower()):
                if word not in _FUNCTION_WORDS:
                    rows[r, zlib.crc32(word.rstrip("s").encode()) % self.dims] += 1.0
        return rows


class WordLlamaScorer(SimilarityScorer):
    """WordLlama (``pip install 'seal[llm]'``), loaded from the weights inside its own package."""

    def __init__(self) -> None:
        super().__init__()
        try:
            import wordllama
            from wordllama import WordLlama
        except ImportError as error:
            raise SealError("the saycan policy's language model needs the llm extra: "
                            "pip install 'seal[llm]' (wordllama)") from error
        from pathlib import Path

        self.model = WordLlama.load(cache_dir=Path(wordllama.__file__).parent, disable_download=True)

    @classmethod
    def shared(cls) -> WordLlamaScorer:
        """One model per process (loading it costs more than an episode's scoring)."""
        global _SHARED
        if _SHARED is None:
            _SHARED = cls()
        return _SHARED

    def embed(self, texts: Sequence[str]) -> np.ndarray:
        return np.asarray(self.model.embed(list(texts), norm=True), dtype=float)


_SHARED: WordLlamaScorer | None = None
