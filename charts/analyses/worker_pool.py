"""The process pools of the package: `worker_pool`, a ``concurrent.futures`` executor whose
worker processes the package can name, so that an interrupt stops them and nothing else.

The pool launches its workers through a multiprocessing context (the executor's documented
``mp_context``) that keeps each worker ``Process`` it creates: `pool_workers` gives the
live workers of every pool made here, `workers_of` those of one pool.  The context is the
default one of the process (``multiprocessing.get_context()``); every other method of it is
the default context's own.
"""
from __future__ import annotations

import multiprocessing
import weakref
from concurrent.futures import ProcessPoolExecutor

__all__ = ["worker_pool", "pool_workers", "workers_of", "WorkerContext"]

#: Every worker process started by a pool of `worker_pool` (dead ones drop out on their own).
_WORKERS: "weakref.WeakSet" = weakref.WeakSet()


class WorkerContext:
    """A multiprocessing context that records the processes it starts (in ``processes`` and
    in the module's set of all pool workers) and is otherwise the context ``base``."""

    def __init__(self, base=None):
        self._base = base if base is not None else multiprocessing.get_context()
        self.processes = weakref.WeakSet()

    def Process(self, *args, **kwargs):  # noqa: N802 - the name of the context's method
        proc = self._base.Process(*args, **kwargs)
        self.processes.add(proc)
        _WORKERS.add(proc)
        return proc

    def __getattr__(self, name):
        return getattr(self._base, name)


def worker_pool(max_workers, initializer=None, initargs=()) -> ProcessPoolExecutor:
    """A ``ProcessPoolExecutor`` of ``max_workers`` processes whose workers `pool_workers`
    and `workers_of` name."""
    ctx = WorkerContext()
    pool = ProcessPoolExecutor(max_workers=max_workers, mp_context=ctx, initializer=initializer,
                               initargs=initargs)
    _CONTEXTS[pool] = ctx
    return pool


_CONTEXTS: "weakref.WeakKeyDictionary" = weakref.WeakKeyDictionary()


def _alive(processes) -> list:
    out = []
    for proc in list(processes):
        try:
            if proc.is_alive():
                out.append(proc)
        except (ValueError, AssertionError):   # closed, or not a child of this process
            continue
    return out


def pool_workers() -> list:
    """The live worker processes of every pool of `worker_pool` started by this process."""
    return _alive(_WORKERS)


def workers_of(pool) -> list:
    """The live worker processes of ``pool`` (made by `worker_pool`; another executor: [])."""
    try:
        ctx = _CONTEXTS.get(pool)
    except TypeError:                   # not weakly referable: no pool of `worker_pool`
        return []
    return [] if ctx is None else _alive(ctx.processes)
