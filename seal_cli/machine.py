"""What the machine seal runs on has to give: the memory a command may still take.

Read from the system, never from a file a user names: ``MemAvailable`` of ``/proc/meminfo`` (what Linux can hand
out without swapping), lowered by the process's own address-space limit (``ulimit -v``) when one is set. None
when neither says (another system): a command then takes what it asks for, as before.
"""

from __future__ import annotations

import resource
from pathlib import Path

__all__ = ["available_memory"]

MEMINFO = Path("/proc/meminfo")


def available_memory() -> int | None:
    """Bytes the command may still allocate, or None if the system does not say."""
    found: list[int] = []
    try:
        for line in MEMINFO.read_text(encoding="ascii", errors="replace").splitlines():
            if line.startswith("MemAvailable:"):
                found.append(int(line.split()[1]) * 1024)
                break
    except (OSError, ValueError, IndexError):
        pass
    limit, _ = resource.getrlimit(resource.RLIMIT_AS)
    if limit != resource.RLIM_INFINITY and limit > 0:
        found.append(int(limit))
    return min(found) if found else None
