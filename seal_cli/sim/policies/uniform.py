"""``uniform``: the ablation of SeFM without priors (every place equally likely before anything is seen)."""

from __future__ import annotations

from seal_cli.sim.policies.base import Policy
from seal_cli.sim.policies.sefm import SeFMPolicy

__all__ = ["UniformPolicy"]


class UniformPolicy(SeFMPolicy):
    """SeFM with the map's priors removed."""

    name = "uniform"

    @classmethod
    def make(cls, *, particles: int = 200) -> Policy:
        return cls(particles=particles, priors=False)
