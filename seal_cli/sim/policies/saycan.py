"""``saycan``: the paper's language-model baseline (SayCan, Ahn et al. 2022), offline.

It does not answer the agent's questions: it never sees seal's frames or plan. It *drives itself*
(:attr:`SayCanPolicy.drives_itself`): given the instruction text, a
:class:`~seal_cli.sim.skills.SkillRunner` picks primitive skills by language score × affordance
in the same world, perception and budget as every other policy. The language model is a
:class:`~seal_cli.sim.scorers.Scorer`: WordLlama (the ``llm`` extra) unless one is given.
"""

from __future__ import annotations

from collections.abc import Callable, Sequence
from typing import TYPE_CHECKING, ClassVar

import numpy as np

from seal_cli.sim.policies.base import Policy

if TYPE_CHECKING:
    from seal_cli.frames.library import Library
    from seal_cli.frames.model import Binding
    from seal_cli.sim.agent import Agent, Budget, Record, Scene, View
    from seal_cli.sim.scorers import Example, Scorer
    from seal_cli.sim.skills import SkillResult

__all__ = ["SayCanPolicy"]


class SayCanPolicy(Policy):
    """Language score × affordance over primitive skills, from the instruction text alone."""

    name = "saycan"
    drives_itself: ClassVar[bool] = True
    """Runs from the instruction text (:meth:`run`), not inside the agent's plan loop."""

    def __init__(self, scorer: Scorer | None = None, examples: Sequence[Example] | None = None) -> None:
        self._scorer = scorer
        self._examples = None if examples is None else tuple(examples)

    @property
    def scorer(self) -> Scorer:
        """The language model: WordLlama following the prompt's worked examples unless one was given."""
        if self._scorer is None:
            from seal_cli.sim.scorers import ExampleScorer, WordLlamaScorer

            self._scorer = ExampleScorer(WordLlamaScorer.shared())
        return self._scorer

    @property
    def examples(self) -> tuple[Example, ...]:
        """The prompt's worked examples: the shipped ones (ALFRED train) unless others were given."""
        if self._examples is None:
            from seal_cli.sim.scorers import load_examples

            self._examples = load_examples()
        return self._examples

    def next_view(self, agent: Agent, binding: Binding, target: str) -> View | None:
        from seal_cli.errors import SealError

        raise SealError("the saycan policy runs from the instruction text, not from seal's frames")

    def run(self, scene: Scene, library: Library, instruction: str, *, rng: np.random.Generator,
            budget: Budget | None = None, observers: Sequence[Callable[[Record], None]] = ()) -> SkillResult:
        from seal_cli.sim.skills import SkillRunner

        return SkillRunner(scene, library, self.scorer, rng=rng, budget=budget, observers=observers,
                           examples=self.examples).run(instruction)
