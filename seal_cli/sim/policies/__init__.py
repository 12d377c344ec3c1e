"""Where a robot looks next: the search policies, an extension point.

Each policy is one module of this folder implementing :class:`~seal_cli.sim.policies.base.Policy`,
registered by name in :data:`POLICIES`; ``seal run --policy``, its help and every benchmark suite
read the registry, so a new policy is one module and one line here. The registry names modules and
classes rather than importing them, so that reading it (for the command line's help) costs nothing.
"""

from __future__ import annotations

import importlib
from dataclasses import dataclass
from typing import TYPE_CHECKING

from seal_cli.errors import SealError

if TYPE_CHECKING:
    from seal_cli.sim.policies.base import Policy

__all__ = ["DEFAULT_POLICIES", "POLICIES", "Registered", "make_policy"]


@dataclass(frozen=True)
class Registered:
    """A registered policy: where its class is, what it does in a few words, and whether the
    benchmark suites run it unless told otherwise."""

    module: str
    cls: str
    summary: str
    default: bool = True

    def load(self) -> type[Policy]:
        loaded: type[Policy] = getattr(importlib.import_module(self.module), self.cls)
        return loaded


POLICIES: dict[str, Registered] = {
    "sefm": Registered("seal_cli.sim.policies.sefm", "SeFMPolicy", "SeFM's frame beliefs"),
    "object_only": Registered("seal_cli.sim.policies.object_only", "ObjectOnlyPolicy",
                              "one belief per object, searched for one at a time"),
    "coverage": Registered("seal_cli.sim.policies.coverage", "CoveragePolicy",
                           "the nearest unseen frontier or unopened receptacle"),
    "oracle": Registered("seal_cli.sim.policies.oracle", "OraclePolicy", "knows where everything is"),
    "prior_optimal": Registered("seal_cli.sim.policies.prior_optimal", "PriorOptimalPolicy",
                                "the exact expected-path search for the whole plan under the priors"),
    "frame_dp": Registered("seal_cli.sim.policies.frame_bound", "FrameDPPolicy",
                           "the plan's next two stops searched for jointly, exactly over regions", default=False),
    "uniform": Registered("seal_cli.sim.policies.uniform", "UniformPolicy", "SeFM without priors", default=False),
    "saycan": Registered("seal_cli.sim.policies.saycan", "SayCanPolicy",
                         "SayCan: language score x affordance over skills (the llm extra)", default=False),
}
"""Every policy by name."""

DEFAULT_POLICIES = tuple(name for name, entry in POLICIES.items() if entry.default)
"""The policies a benchmark runs when none are named."""


def make_policy(name: str, particles: int = 200) -> Policy:
    """A fresh policy by its registered name; an unknown name is refused with the known ones."""
    entry = POLICIES.get(name)
    if entry is None:
        raise SealError(f"unknown policy {name!r}; known: {', '.join(POLICIES)}")
    return entry.load().make(particles=particles)
