"""``object_only``: SLiM-style search (after Zeng et al.), the baseline for what frames add.

One belief per object class, from the same priors and observations as SeFM, searched for one at a
time in plan order: it looks where the *object* the current frame needs is believed to be, with
no frame relations and no precondition context.
"""

from __future__ import annotations

from seal_cli.sim.policies.sefm import SeFMPolicy

__all__ = ["ObjectOnlyPolicy"]


class ObjectOnlyPolicy(SeFMPolicy):
    """SLiM-style search: the belief of the object the current frame needs, and nothing else."""

    name = "object_only"
    use_frames = False
