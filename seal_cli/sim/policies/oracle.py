"""``oracle``: knows where everything is, including what closed receptacles hold: a lower bound on the path."""

from __future__ import annotations

import itertools
import math
from collections.abc import Sequence

import numpy as np

from seal_cli.frames.model import Binding
from seal_cli.frames.taxonomy import class_key
from seal_cli.maps.navigation import Cell
from seal_cli.sim.agent import Agent, Known, View
from seal_cli.sim.policies.base import Policy
from seal_cli.sim.policies.coverage import one_per_quarter_metre
from seal_cli.sim.world import Detection

__all__ = ["OraclePolicy", "navigation_targets"]


class OraclePolicy(Policy):
    """Knows the world; picks the instances, and the poses to act from, that make the remaining plan
    shortest (exhaustively over the nearest few instances of each class, and exactly over poses by
    dynamic programming): the lower bound on the path."""

    name = "oracle"
    oracle = True
    max_assignments = 2000
    per_class = 6

    def begin(self, agent: Agent) -> None:
        self.plan: list[Known] = []
        self._pairs: dict[tuple[str, str], np.ndarray] = {}
        self._cells: dict[str, np.ndarray] = {}

    def observe(self, agent: Agent, detections: Sequence[Detection]) -> None:
        pass

    def next_view(self, agent: Agent, binding: Binding, target: str) -> View | None:
        return None  # it knows every instance there is; if none will do, there is none

    def choose(self, agent: Agent, cls: str, candidates: Sequence[Known]) -> str | None:
        targets = [agent.class_of(t) for t in navigation_targets(agent)]
        if not targets or targets[0] != cls:
            targets = [cls, *targets]
        held = agent.held()
        options: dict[str, list[Known]] = {}
        field_ = agent.distances()
        for t in dict.fromkeys(targets):
            if held is not None and held.key == t and t != cls:
                continue
            pool = list(candidates) if t == cls else [k for k in agent.instances(t) if k.id not in agent.unreachable]
            costed = [(float(field_[c]), k) for k in pool if (c := agent.stand_cell(k, field_)) is not None]
            costed.sort(key=lambda ck: ck[0])
            if costed:
                options[t] = [k for _, k in costed[: self.per_class]]
        if cls not in options:
            return None
        classes = list(options)
        best: tuple[float, list[Known]] | None = None
        for n, combo in enumerate(itertools.product(*(options[c] for c in classes))):
            if n >= self.max_assignments:
                break
            chosen = dict(zip(classes, combo, strict=True))
            stops = [chosen[t] for t in targets if t in chosen]
            cost = self.tour(agent, stops)[0]
            if best is None or cost < best[0]:
                best = (cost, stops)
        if best is None:
            return None
        self.plan = best[1]
        return best[1][0].id

    def stand(self, agent: Agent, known: Known) -> Cell | None:
        """The pose to act on ``known`` from that makes the rest of the chosen tour shortest."""
        stops = self.plan if self.plan and self.plan[0].id == known.id else [known]
        cost, cell = self.tour(agent, stops)
        return cell if np.isfinite(cost) else None

    def _stand_cells(self, agent: Agent, known: Known) -> np.ndarray:
        """The cells to act on ``known`` from; on a grid finer than 0.25 m, one per 0.25 m (a
        shortest-path field is computed from each, so a 5 cm grid would cost 25 times as many for
        a few centimetres of path)."""
        if known.id not in self._cells:
            cells = agent.stand_cells(known)
            if known.id in agent.world.items and len(cells):   # not where a wall stands between (as Agent.stand_cell)
                clear = np.array([not agent.world.walled(known.id, agent.grid.point((int(i), int(j))))
                                  for i, j in cells], dtype=bool)
                cells = cells[clear] if clear.any() else cells
            thin = cells[one_per_quarter_metre(cells, agent.grid.resolution)]
            self._cells[known.id] = thin if len(thin) else cells
        return self._cells[known.id]

    def _between(self, agent: Agent, a: Known, b: Known) -> np.ndarray:
        """Metres from each stand cell of ``a`` to each stand cell of ``b``."""
        key = (a.id, b.id)
        if key not in self._pairs:
            ca, cb = self._stand_cells(agent, a), self._stand_cells(agent, b)
            rows = [agent.grid.distances((int(i), int(j)))[cb[:, 0], cb[:, 1]] for i, j in ca]
            self._pairs[key] = np.asarray(rows).reshape(len(ca), len(cb))
        return self._pairs[key]

    def tour(self, agent: Agent, stops: Sequence[Known]) -> tuple[float, Cell | None]:
        """The shortest drive through the stops in order (each from any of its stand cells), and the
        cell to stand at for the first stop."""
        if not stops:
            return 0.0, None
        after = np.zeros(len(self._stand_cells(agent, stops[-1])))  # metres still to go from each cell
        for a, b in zip(stops[-2::-1], stops[:0:-1], strict=True):
            between = self._between(agent, a, b)
            after = (between + after[None, :]).min(axis=1) if between.size else np.full(len(between), np.inf)
        first = self._stand_cells(agent, stops[0])
        if not len(first):
            return math.inf, None
        here = agent.distances()[first[:, 0], first[:, 1]]
        total = here + after
        k = int(np.argmin(total))
        return float(total[k]), (int(first[k, 0]), int(first[k, 1]))


def navigation_targets(agent: Agent) -> list[str]:
    """The names the remaining plan will drive to, in order."""
    out: list[str] = []
    for binding in agent.remaining:
        for action in binding.actions:
            if action.name == "navigate":
                out.append(class_key(action.args[0]))
    return out
