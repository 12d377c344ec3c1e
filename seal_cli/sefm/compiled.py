"""Whether the grid engine's inner loops run compiled (numba, the ``fast`` extra) or as numpy passes.

Three loops of an update are many whole-array numpy passes each, with a temporary per pass: the
bilinear reads of the kernel sums at the frames' particles (``GridKernelSums.combine``), the linear
binning of particles onto the grids (``GridKernelSums._bin``) and systematic resampling
(:func:`seal_cli.sefm.resampling.systematic`). With numba installed they run as one compiled loop each
(:mod:`seal_cli.sefm._jit`), giving the same numbers bit for bit; without it, as numpy. Setting the
environment variable ``SEAL_NUMPY_ONLY=1`` keeps numpy even when numba is there (to compare the two).

numba is imported on first use, not with the package: ``seal --version`` and ``seal parse`` never pay
for it, a run that builds SeFM pays ~0.3 s once. The loops are compiled when first asked for (all at
once, :func:`seal_cli.sefm._jit.warm`: never inside an update) and cached on disk by numba, so later
processes read them back instead (the first run after installing compiles them: a few seconds).
"""

from __future__ import annotations

import os
from functools import lru_cache
from types import ModuleType

__all__ = ["kernels"]


@lru_cache(maxsize=1)
def kernels() -> ModuleType | None:
    """The compiled loops (:mod:`seal_cli.sefm._jit`), or None: numba is not installed or
    ``SEAL_NUMPY_ONLY`` is set. (``kernels.cache_clear()`` reads the environment again.)"""
    if os.environ.get("SEAL_NUMPY_ONLY", "") not in ("", "0"):
        return None
    from seal_cli.fileio import interrupted

    try:
        from seal_cli.sefm import _jit
    except Exception:   # not installed, or refused by its environment (NUMBA_NUM_THREADS=0 is a ValueError, rel33)
        if interrupted():  # a SIGINT inside numba's import comes out as "ImportError: initialization failed"
            raise KeyboardInterrupt from None
        return None     # numpy's passes: the same numbers bit for bit
    _jit.warm()
    if interrupted():  # one inside LLVM's callbacks while compiling was dropped there (fileio.note_interrupts)
        raise KeyboardInterrupt
    return _jit
