"""``seal bench plan``: how long parse + ground + plan take for commands of up to six clauses."""

from __future__ import annotations

import statistics
import time
from collections.abc import Sequence
from dataclasses import dataclass

from seal_cli.errors import SealError, at_line
from seal_cli.frames.library import Library
from seal_cli.language.grounding import Vocabulary
from seal_cli.maps.model import Map
from seal_cli.planning.plan import plan
from seal_cli.planning.problem import problem_of_text


@dataclass(frozen=True)
class Timing:
    """One command's plan: commanded and total frames, search nodes expanded, median milliseconds
    for parse + ground + plan, and for the plan alone."""

    text: str
    commanded: int
    steps: int
    nodes: int
    ms: float
    plan_ms: float
    """Of ``ms``, the search alone (the rest is parsing and grounding)."""


BENCH_COMMANDS = (
    "stir the cup",
    "heat the egg and put it in the fridge",
    "slice the apple and put it in the fridge",
    "put two apples in the fridge, put three eggs in the microwave and put two cups on the table",
    "go to the kitchen, pick up the cup, bring it to me",
    "find the cup, bring it to me, find the spoon, give it to Roger, open the fridge and put the apple in the fridge",
    "pick up the cup, put it in the fridge, pick up the apple, put it in the microwave, pick up the spoon "
    "and stir the cup",
    "look at the clock under the lamp, turn off the lamp, slice the bread, heat it, put it on the table "
    "and close the microwave",
    "heat the egg, cool the apple, clean the plate, put the egg on the plate, put the apple in the microwave "
    "and stir the cup",
    "stir the cup, slice the apple, put the apple in the cup, heat the cup, put the cup in the fridge "
    "and close the fridge",
    "slice the apple, slice the bread, slice the tomato, put the apple in the fridge, put the bread in the fridge "
    "and put the tomato in the fridge",
)
"""Commands of one to six clauses that ``seal bench plan`` times by default."""


def time_plans(texts: Sequence[str], library: Library, *, map: Map | None = None,
               vocabulary: Vocabulary | None = None, repeat: int = 5,
               source: tuple[str, Sequence[tuple[int, str]]] | None = None) -> list[Timing]:
    """Each command's :class:`Timing`: the median of ``repeat`` runs, after one warm-up run of each (the first
    builds the grammar and the lexicon, so the first command does not pay for them). ``source``: the file the
    commands were read from and each one's line there (its number and text); a command that cannot be planned
    is refused at its line and column of that file, before any is timed."""
    if not texts:
        return []
    for k, text in enumerate(texts):  # every command plans, or the first that does not is said where it is
        try:
            problem = problem_of_text(text, library, map=map, vocabulary=vocabulary)
            plan(problem.commanded, library, problem.state, text=text)
        except SealError as error:
            if source is None:
                raise
            raise at_line(error, source[0], *source[1][k]) from None
    rows = []
    for text in texts:
        times, searches = [], []
        for _ in range(repeat):
            begin = time.perf_counter()
            problem = problem_of_text(text, library, map=map, vocabulary=vocabulary)
            middle = time.perf_counter()
            result = plan(problem.commanded, library, problem.state, text=text)
            times.append(time.perf_counter() - begin)
            searches.append(time.perf_counter() - middle)
        rows.append(Timing(text, sum(s.commanded for s in result.steps), len(result.steps), result.expanded,
                           round(1000 * statistics.median(times), 2), round(1000 * statistics.median(searches), 2)))
    return rows
