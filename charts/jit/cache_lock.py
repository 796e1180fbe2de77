"""numba's on-disk cache of charts' kernels, safe for processes that share it and healed: its
index and object files are read and written under a lock, and a damaged entry is removed and
compiled again, once, with a notice.

numba saves a new entry by reading the function's index (``.nbi``: key -> object file),
choosing the first free file number, writing the index, then the object file (``.nbc``).
Two processes that add entries to one index at once (`charts warmup`'s pool compiling the
chart kernels of N = 4, 5 and 6, ``pytest -n 2``, a sweep's workers) can both choose the same
number: the index then names one entry's key and the file holds the other's code, and every
later process loads the wrong kernel — a chart right-hand side of another N — without an
error.  And a process that reads the index between another's two writes can load an old
file under a new key.  Each of charts' own dispatchers with ``cache=True`` (made by
`charts.jit.njit`) therefore gets a `LockedCache`, numba's ``FunctionCache`` whose saving
holds an exclusive lock on a file beside the index (``<index>.lock``, ``fcntl.flock``) from
reading the index to writing the object file, and whose loading a shared one from reading
the index to reading the object file.  numba's classes are not touched: other functions'
caches are numba's own.  Where the platform has no ``fcntl`` (Windows), the lock file
cannot be opened (a read-only cache) or the file system refuses locks (a notice, once), the
cache works without it.  An entry keyed on a compiled function passed as an argument, which
no other process could find, is neither saved nor looked up (`_per_process`).

numba reads a cached kernel with ``pickle`` and rebuilds it; an index or object file that
was truncated by a full disk, overwritten or left by another version of the source raises
from deep inside numba (``UnpicklingError``, ``EOFError``, a ``KeyError`` while rebuilding)
on every call.  `LockedCache.load_overload` removes that function's index and object files
on such a failure, says so on stderr and lets numba compile and cache it anew.
"""
from __future__ import annotations

import glob
import inspect
import os
import sys
from contextlib import contextmanager

try:
    import fcntl
except ImportError:                         # Windows: no advisory locks here
    fcntl = None

from . import adaptations

__all__ = ["usable", "adopt", "index_lock", "HEALED", "UNLOCKED"]

#: Functions healed in this process: qualified name -> the error that was read.
HEALED: dict = {}

#: The cache folders where locks were refused, and why (said on stderr for the first).
UNLOCKED: dict = {}

_LockedCache = None     # the class, made once numba's FunctionCache passed the check


def _check():
    """None, or what differs in numba's cache from what `LockedCache` expects; makes the
    class on success."""
    global _LockedCache
    from numba.core import caching

    base = getattr(caching, "FunctionCache", None)
    if base is None:
        return "numba.core.caching.FunctionCache is missing"
    for name, params in (("load_overload", ["self", "sig", "target_context"]),
                         ("save_overload", ["self", "sig", "data"])):
        method = getattr(base, name, None)
        if method is None or list(inspect.signature(method).parameters) != params:
            return f"FunctionCache.{name} has another signature"

    class LockedCache(base):
        """numba's ``FunctionCache`` read and written under the index's lock, healed."""

        def load_overload(self, sig, target_context):
            if _per_process(sig):
                return None                     # never saved (`_per_process`): a miss
            with index_lock(self, fcntl and fcntl.LOCK_SH):
                try:
                    return super().load_overload(sig, target_context)
                except Exception as exc:        # noqa: BLE001 - any failure to read the entry
                    failure = exc
            with index_lock(self, fcntl and fcntl.LOCK_EX):
                _heal(self, failure)
            return None                         # a miss: numba compiles and saves it again

        def save_overload(self, sig, data):
            if _per_process(sig):
                return None
            with index_lock(self, fcntl and fcntl.LOCK_EX):
                return super().save_overload(sig, data)

    _LockedCache = LockedCache
    return None


def usable() -> bool:
    """Whether charts' dispatchers get a `LockedCache` in this process."""
    return adaptations.active("cache_lock", _check)


def adopt(dispatcher):
    """Give the numba dispatcher ``dispatcher`` (cache=True) a locked cache in place of
    numba's own, where the adaptation is in use; returns the dispatcher."""
    from numba.core.caching import FunctionCache

    cache = getattr(dispatcher, "_cache", None)
    if usable() and type(cache) is FunctionCache:
        index = getattr(getattr(cache, "_cache_file", None), "_index_path", None)
        if not (isinstance(index, str) and index.endswith(".nbi")) or \
                getattr(cache, "_py_func", None) is not dispatcher.py_func:
            adaptations.step_aside("cache_lock", "a FunctionCache keeps no "
                                   "_cache_file._index_path or _py_func")
        else:
            cache.__class__ = _LockedCache  # numba's cache made already; only its methods differ
    return dispatcher


@contextmanager
def index_lock(cache, mode):
    """Hold the lock ``mode`` (``fcntl.LOCK_SH`` or ``LOCK_EX``) on the file beside numba's
    index of ``cache`` while the block runs.  The file is opened read-only where it cannot be
    opened for writing (another user's, in a shared cache: ``flock`` needs no write access);
    without a lock where there is no ``fcntl`` or the file cannot be opened at all (a
    read-only cache), silently, and where the lock is refused (NFS without its lock daemon,
    some FUSE mounts), with one notice (`UNLOCKED`)."""
    fd = _lock_file(cache) if fcntl is not None else None
    if fd is not None:
        try:
            fcntl.flock(fd, mode)
        except OSError as exc:
            os.close(fd)
            fd = None
            _unlocked(cache, exc)
    try:
        yield
    finally:
        if fd is not None:
            os.close(fd)                    # (closing releases the lock)


def _lock_file(cache):
    """A descriptor of the lock file beside the index of ``cache``, or None."""
    path = cache._cache_file._index_path + ".lock"
    try:
        os.makedirs(os.path.dirname(path), exist_ok=True)
        return os.open(path, os.O_RDWR | os.O_CREAT, 0o666)
    except OSError:
        pass
    try:
        return os.open(path, os.O_RDONLY)
    except OSError:
        return None


def _unlocked(cache, exc) -> None:
    folder = os.path.dirname(cache._cache_file._index_path)
    if folder in UNLOCKED:
        return
    UNLOCKED[folder] = f"{type(exc).__name__}: {exc}"
    if len(UNLOCKED) == 1:
        print(f"charts: numba's cache ({folder}) could not be locked ({UNLOCKED[folder]}); "
              "kernels are cached there without the lock (processes that compile at once may "
              "then mix entries: give each its own NUMBA_CACHE_DIR)",
              file=sys.stderr, flush=True)


def _per_process(sig) -> bool:
    """Whether a signature holds a compiled function as an argument (a kernel called from
    Python with a right-hand side of the caller's: ``rk4_step(f, …)``).  numba keys such an
    entry on the function object of the process that compiled it, so no other process ever
    finds it: each would add one more to the index, and numba rebuilds every entry's function
    to save the next (a ReferenceError once one of them has been collected).  Such entries are
    neither saved nor looked up."""
    from numba.core import types

    return any(isinstance(t, types.Dispatcher) for t in getattr(sig, "args", sig))


def _heal(cache, exc) -> None:
    """Remove the function's index and object files and say so."""
    func = cache._py_func
    name = f"{func.__module__}.{func.__qualname__}"
    index = cache._cache_file._index_path
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
