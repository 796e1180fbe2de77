"""What charts installs in numba before numba compiles anything: the healing of damaged cache
entries of charts' kernels (`charts.numba_cache`), the inliner without its quadratic copy
(`charts.numba_inliner`) and the typing of calls remembered (`charts.numba_typing`).  numba
calls `install` through its ``numba_extensions`` entry point named ``init`` (pyproject.toml;
numba runs only entry points of that name) in every process, before its first compilation."""
from __future__ import annotations

from . import numba_cache, numba_inliner, numba_typing

__all__ = ["install"]


def install() -> None:
    """Install all three (each is idempotent)."""
    numba_cache.install()
    numba_inliner.install()
    numba_typing.install()
