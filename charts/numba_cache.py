"""numba's on-disk cache of charts' kernels, healed: a damaged entry is removed and compiled
again, once, with a notice.

numba reads a cached kernel with ``pickle`` and rebuilds it; an index (``.nbi``) or object
file (``.nbc``) that was truncated by a full disk, overwritten or left by another version of
the source raises from deep inside numba (``UnpicklingError``, ``EOFError``, a ``KeyError``
while rebuilding) on every call.  `install` wraps numba's ``Cache.load_overload``: for a
function of this package such a failure removes that function's index and object files,
says so on stderr and lets numba compile and cache it anew.  Other packages' caches are left
to numba.  numba calls `install` through its ``numba_extensions`` entry point
(``charts.numba_init``, pyproject.toml) before it creates its first kernel, so it covers every
process that uses charts.
"""
from __future__ import annotations

import glob
import os
import sys

from .numba_inliner import ours

__all__ = ["install", "HEALED"]

#: Functions healed in this process: qualified name -> the error that was read.
HEALED: dict = {}


def install() -> None:
    """Wrap numba's cache loading once (idempotent)."""
    from numba.core.caching import Cache

    if getattr(Cache.load_overload, "_charts_heals", False):
        return
    original = Cache.load_overload

    def load_overload(self, sig, target_context):
        try:
            return original(self, sig, target_context)
        except Exception as exc:            # noqa: BLE001 - any failure to read the entry
            if not _ours(self):
                raise
            _heal(self, exc)
            return None                     # a miss: numba compiles and saves it again

    load_overload._charts_heals = True
    load_overload.__wrapped__ = original
    Cache.load_overload = load_overload


def _ours(cache) -> bool:
    return ours(getattr(getattr(cache, "_py_func", None), "__module__", ""))


def _heal(cache, exc) -> None:
    """Remove the function's index and object files and say so."""
    func = cache._py_func
    name = f"{func.__module__}.{func.__qualname__}"
    cache_file = cache._cache_file
    index = cache_file._index_path
    base = index[: -len(".nbi")]
    for path in [index, *glob.glob(glob.escape(base) + ".*.nbc")]:
        try:
            os.unlink(path)
        except FileNotFoundError:
            pass
        except OSError as err:              # read-only cache: numba then keeps it in memory
            print(f"charts: could not remove {path}: {err}", file=sys.stderr, flush=True)
    reason = " ".join(f"{type(exc).__name__}: {exc}".split())[:200]
    HEALED[name] = reason
    print(f"charts: numba's cached {name} in {os.path.dirname(index)} was damaged ({reason}); "
          "removed it, compiling again (once)", file=sys.stderr, flush=True)
