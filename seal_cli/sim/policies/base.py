"""What the agent asks a search policy: the :class:`Policy` interface, every question with its default.

The :class:`~seal_cli.sim.agent.Agent` executes a plan and is the same for every policy; a policy
only answers these questions, and a new one overrides the ones it has an answer to:

- :meth:`Policy.next_view`: from where to look next for what the current frame needs (the only
  question every policy must answer);
- :meth:`Policy.choose`: which of several known instances of a class to use (default: the agent's
  nearest);
- :meth:`Policy.stand`: from which pose to act on an instance (default: the nearest by path);
- :attr:`Policy.oracle`: whether the robot is told where every thing is before it starts.

Policies are registered by name in :data:`seal_cli.sim.policies.POLICIES`.
"""

from __future__ import annotations

from collections.abc import Sequence
from typing import TYPE_CHECKING, Any, ClassVar

if TYPE_CHECKING:
    from seal_cli.frames.model import Binding
    from seal_cli.maps.navigation import Cell
    from seal_cli.sim.agent import Agent, Known, View
    from seal_cli.sim.world import Detection

__all__ = ["Policy"]


class Policy:
    """A searcher: ``begin`` once per run, ``observe`` after every look, ``next_view`` while what the
    frame at hand needs is unknown. The defaults are those of a policy with no view on the matter."""

    name: ClassVar[str] = "policy"
    oracle: ClassVar[bool] = False
    """The robot knows where every thing is from the start (the world's items are given to it)."""
    keeps_particles: ClassVar[bool] = False
    """Its beliefs are particles, as many as :meth:`make`'s ``particles`` (``seal run --particles`` is for it alone:
    given to a policy that keeps none, it is refused, not passed over; hostile32)."""
    keep_clouds: bool = False
    """Keep the belief clouds after every update, for pictures and recordings (``seal run --png/--rrd``)."""

    @classmethod
    def make(cls, *, particles: int = 200) -> Policy:
        """A fresh policy; ``particles`` is for those that keep particle beliefs."""
        return cls()

    @property
    def clouds(self) -> list[dict[str, Any]]:
        """The belief clouds kept (:attr:`keep_clouds`): dicts with ``step``, ``frame``,
        ``frame_particles`` (X, W) or None, ``objects`` {class: (X, W)}; empty if none."""
        return []

    def begin(self, agent: Agent) -> None:
        """A new run starts (the agent knows the places, nothing is seen yet)."""

    def observe(self, agent: Agent, detections: Sequence[Detection]) -> None:
        """The robot has looked from where it is and seen ``detections``."""

    def next_view(self, agent: Agent, binding: Binding, target: str) -> View | None:
        """Where to look next for a thing of kind ``target`` that ``binding`` needs; None: nowhere left."""
        raise NotImplementedError(f"policy {self.name!r} does not say where to look")

    def reconsider(self, agent: Agent, binding: Binding, target: str, view: View) -> str | None:
        """On the drive to ``view`` (chosen by :meth:`next_view`), after a look on the way: why to stop and
        choose again (what it saw makes another view better), or None to drive on."""
        return None

    def choose(self, agent: Agent, cls: str, candidates: Sequence[Known]) -> str | None:
        """Which of the known candidates of ``cls`` to use; None leaves it to the agent (the nearest)."""
        return None

    def stand(self, agent: Agent, known: Known) -> Cell | None:
        """The cell to act on ``known`` from; None if it cannot be reached."""
        return agent.stand_cell(known)
