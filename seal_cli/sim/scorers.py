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

import itertools
import math
import re
import zlib
from collections.abc import Sequence
from dataclasses import dataclass
from pathlib import Path
from typing import Protocol

import numpy as np

from seal_cli.errors import SealError

__all__ = ["DONE", "BagOfWordsScorer", "Example", "ExampleScorer", "Scorer", "SimilarityScorer", "WordLlamaScorer",
           "load_examples", "prompt_for", "read_examples", "read_prompt"]

DONE = "done"
"""The option that ends a run."""


class Scorer(Protocol):
    """A language model's judgement of the next line."""

    def score(self, prompt: str, options: Sequence[str]) -> np.ndarray:
        """Log-probabilities (natural log, summing to one in probability) of each option after the prompt."""
        ...


def prompt_for(instruction: str, history: Sequence[str], examples: Sequence[Example] = ()) -> str:
    """The prompt the SayCan runner asks about, in SayCan's shape: the worked examples first, each
    a ``Human:`` line (the instruction) and one ``Robot:`` line per skill, ending with ``done``; a
    blank line after each; then the instruction and the skills done so far. The next line a
    language model writes is ``Robot: <option>``."""
    blocks = [_block(e.instruction, e.steps) for e in examples]
    return "\n\n".join([*blocks, _block(instruction, history)])


def _block(instruction: str, steps: Sequence[str]) -> str:
    return "\n".join([f"Human: {' '.join(instruction.split())}", *(f"Robot: {s}" for s in steps)])


def _blocks(prompt: str) -> list[tuple[str, list[str]]]:
    out = []
    for block in prompt.split("\n\n"):
        lines = block.split("\n")
        head = lines[0].removeprefix("Human: ")
        out.append((head, [line.removeprefix("Robot: ") for line in lines[1:] if line.strip()]))
    return out


def read_prompt(prompt: str) -> tuple[str, list[str]]:
    """The instruction and the history back from a :func:`prompt_for` prompt."""
    return _blocks(prompt)[-1]


def read_examples(prompt: str) -> list[Example]:
    """The worked examples back from a :func:`prompt_for` prompt."""
    return [Example(i, tuple(steps)) for i, steps in _blocks(prompt)[:-1]]


@dataclass(frozen=True)
class Example:
    """One worked example of the prompt: an instruction and the skills that carry it out."""

    instruction: str
    steps: tuple[str, ...]


def load_examples(path: str | Path | None = None) -> tuple[Example, ...]:
    """The worked examples shipped with seal (``seal_cli/bench/suites/saycan_examples.json``, rebuilt
    from ALFRED's train split by ``scripts/build_saycan_examples.py``), or another such file."""
    from seal_cli.fileio import read_json

    where = Path(path) if path is not None else EXAMPLES
    if not where.exists() and not where.is_symlink():
        raise SealError(f"no worked examples at {where}")
    raw = read_json(where, "file of worked examples")
    try:
        return tuple(Example(str(e["instruction"]), tuple(str(s) for s in e["steps"])) for e in raw["examples"])
    except (ValueError, KeyError, TypeError) as error:
        raise SealError(f"{where} is not a file of worked examples: {error}") from None


EXAMPLES = Path(__file__).resolve().parents[1] / "bench" / "suites" / "saycan_examples.json"


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


class ExampleScorer:
    """The worked examples of the prompt, followed by analogy; see :ref:`the analogy <analogy>` below.

    An LLM given SayCan's prompt continues the pattern of the examples like the instruction: after
    "put the box in the dining table" came "find the box", "pick up the box", "go to the dining
    table", ... so after "put the mug in the sink basin" it writes the same with mug and sink basin.
    This scorer does that by analogy, with an embedding ``base`` (a :class:`SimilarityScorer`):

    - *the names*: an example's slots are the things its instruction names that its skills act on
      (in the order the instruction names them); the instruction's are the things the options act
      on that it names — word for word (plurals folded), else the option's name nearest in the
      embedding to one or two of its words, if at least :attr:`synonym` in cosine;
    - *which examples*: the example's slots are bound, in order, to as many of the instruction's
      names (in order; the choice that makes the two most alike), and the example counts with weight
      ``exp(cos(instruction', example') / weight_temperature)``, where ' has the bound names replaced
      by "something" (an instruction with fewer names than the example's slots: left out);
    - *where it is*: the example's skills with its slots renamed to the bound names; the skills done
      so far (those that succeeded) are matched against them in order (a later step done skips
      those between), and the one after the last matched is what the example says comes next;
    - *the option*: each example gives ``softmax(sim(option, next) / temperature)`` (sim 1 for the
      same words, else the embedding's cosine); the options' probability is the weighted mixture,
      with the line just done made :attr:`repeat` times as likely (no example repeats a line).

    With no example that fits, it falls back to ``base`` (the progress score). It cannot reorder
    what the examples do not show, read word order (the embedding is a bag of words: "the apple in
    the bowl" and "the bowl in the apple" are one vector; the names are bound by their order), or
    know a name the embedding does not put near the thing's."""

    temperature: float = 0.05
    weight_temperature: float = 0.05
    synonym: float = 0.5
    repeat: float = 0.01
    """The factor on the option that repeats the last line."""

    def __init__(self, base: SimilarityScorer) -> None:
        self.base = base

    def score(self, prompt: str, options: Sequence[str]) -> np.ndarray:
        if not options:
            raise SealError("nothing to score: no options")
        instruction, history = read_prompt(prompt)
        names = sorted({n for o in options for n in phrases(o)})
        mentioned = self.mentions(instruction, names)
        done = [h for h in history if not h.startswith(("failed to ", "explored "))]
        mixture = np.zeros(len(options))
        total = 0.0
        for example in read_examples(prompt):
            slots = example_slots(example)
            if not slots or len(mentioned) < len(slots):
                continue
            shape = self.base.vectors([delexicalise(example.instruction, slots)])[0]
            fits = [(_cos(shape, self.base.vectors([delexicalise(instruction, chosen)])[0]), chosen)
                    for chosen in itertools.combinations(mentioned, len(slots))]
            fit, chosen = max(fits, key=lambda f: f[0])
            weight = math.exp(fit / self.weight_temperature)
            want = next_step(rename(example.steps, dict(zip(slots, chosen, strict=True))), done, options)
            mixture += weight * np.exp(_log_softmax(self.similarity(want, options) / self.temperature))
            total += weight
        if total == 0.0:
            return self.base.score(prompt, options)
        if history:   # no example does the same thing twice running
            mixture = mixture * np.where(np.array([o == history[-1] for o in options]), self.repeat, 1.0)
        mixture = np.maximum(mixture, 1e-300)
        return np.asarray(np.log(mixture / mixture.sum()), dtype=float)

    def similarity(self, want: str, options: Sequence[str]) -> np.ndarray:
        rows = self.base.vectors(list(options))
        cos = np.minimum(rows @ self.base.vectors([want])[0], 0.99)
        return np.where(np.array([o == want for o in options]), 1.0, cos)

    def mentions(self, instruction: str, names: Sequence[str]) -> list[str]:
        """The names the instruction names, in its order (see the class docstring)."""
        names = sorted(dict.fromkeys(names), key=lambda n: (-len(n.split()), n))
        tokens = _WORD.findall(instruction.lower())
        taken = [False] * len(tokens)
        found: list[tuple[int, str]] = []
        for name in names:   # longest first: "butter knife" before "knife"
            parts = name.split()
            for i in range(len(tokens) - len(parts) + 1):
                if _same(tokens[i:i + len(parts)], parts) and not any(taken[i:i + len(parts)]):
                    taken[i:i + len(parts)] = [True] * len(parts)
                    found.append((i, name))
        if names:
            vectors = self.base.vectors(list(names))
            for width in (2, 1):
                for i in range(len(tokens) - width + 1):
                    span = tokens[i:i + width]
                    if any(taken[i:i + width]) or any(t in _FUNCTION_WORDS for t in span):
                        continue
                    cos = vectors @ self.base.vectors([" ".join(span)])[0]
                    best = int(np.argmax(cos))
                    if cos[best] >= self.synonym:
                        taken[i:i + width] = [True] * width
                        found.append((i, names[best]))
        return list(dict.fromkeys(name for _, name in sorted(found)))


_PHRASE = re.compile(r"\bthe ([a-z0-9 ]+?)(?= with the | in the |$)")


def phrases(skill: str) -> list[str]:
    """The names a skill line acts on: "put the apple in the fridge" → apple, fridge."""
    return _PHRASE.findall(skill)


def _same(tokens: Sequence[str], parts: Sequence[str]) -> bool:
    """The words are the name's, the last perhaps in the plural."""
    return len(tokens) == len(parts) and all(t == p for t, p in zip(tokens[:-1], parts[:-1], strict=True)) and \
        tokens[-1] in (parts[-1], parts[-1] + "s", parts[-1] + "es")


def _named(text: str, name: str) -> int | None:
    """Where the text names ``name`` (whole words, plurals folded), or None."""
    tokens, parts = _WORD.findall(text.lower()), name.split()
    return next((i for i in range(len(tokens) - len(parts) + 1) if _same(tokens[i:i + len(parts)], parts)), None)


def example_slots(example: Example) -> list[str]:
    """The things the example's instruction names that its skills act on, in the instruction's order."""
    names = {n for s in example.steps for n in phrases(s)}
    where = {n: _named(example.instruction, n) for n in names}
    named = [n for n in names if where[n] is not None]
    named = [n for n in named if not any(n != m and n in m.split() for m in named)]  # "knife" inside "butter knife"
    return sorted(named, key=lambda n: (where[n], -len(n)))


def delexicalise(text: str, names: Sequence[str]) -> str:
    """The text with the names it names replaced by "something"."""
    out = " " + " ".join(_WORD.findall(text.lower())) + " "
    for name in sorted(names, key=len, reverse=True):
        out = re.sub(rf" {re.escape(name)}(s|es)? ", " something ", out)
    return out.strip()


def rename(steps: Sequence[str], mapping: dict[str, str]) -> list[str]:
    """The steps with each of their names renamed (all at once)."""
    def swap(m: re.Match[str]) -> str:
        return "the " + mapping.get(m.group(1), m.group(1))

    return [_PHRASE.sub(swap, s) for s in steps]


def next_step(steps: Sequence[str], done: Sequence[str], options: Sequence[str] | None = None) -> str:
    """The step after the last one matched by what was done, matching in order; given the
    options, a step they do not offer is passed over for the one after it if that is offered
    ("open the counter top", from an example whose receptacle was a fridge).

    A line matches a step with the same words; a line done that is a later step than the next
    skips the steps between (done another way, or not needed). A line also stands for the next
    step if it has the same shape ("go to the _"): what an example does with a thing this scene
    lacks ("go to the cabinet") is done with another ("go to the dining table")."""
    k = 0
    for line in done:
        j = next((j for j in range(k, len(steps)) if steps[j] == line), None)
        if j is None and k < len(steps) and _shape(steps[k]) == _shape(line):
            j = k
        if j is not None:
            k = j + 1
    want = steps[k] if k < len(steps) else DONE
    if options is not None and want not in options and k < len(steps):
        after = steps[k + 1] if k + 1 < len(steps) else DONE
        if after in options:
            return after
    return want


def _shape(step: str) -> str:
    return _PHRASE.sub("the _", step)


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
