"""The compile machinery: how charts has numba compile, cache and call its kernels.

* `njit`: numba's ``njit`` for charts' own kernels (each with cache=True gets the locked,
  healing disk cache of `charts.jit.cache_lock`);
* `charts.jit.adaptations`: what charts adapts in numba, for its own compilations only, each
  fail-safe, all off with ``CHARTS_NUMBA_PLAIN=1``;
* `charts.jit.kernel_calls`: a large kernel called by address from compiled drivers;
* `charts.jit.vector_lowering`: the lanes' vectorising pipeline;
* `charts.jit.borrowed`: arrays read from a loop state without reference counts;
* `charts.jit.compilation`: the one-time compilation timed and announced;
* `charts.jit.packed`: named fields of a packed parameter array.

Importing this package imports numba and has numba's compile events scope the class-level
adaptations (`charts.jit.adaptations.compile_scope`); nothing else of numba changes.
"""
from __future__ import annotations

import inspect

import numba as _numba

from . import adaptations as _adaptations

__all__ = ["njit", "report"]


def njit(*args, **options):
    """numba's ``njit`` (the same arguments: a function, or signatures, and numba's options)
    for a function of charts: with ``cache=True``, its dispatcher reads and writes numba's
    disk cache under a lock and heals damaged entries (`charts.jit.cache_lock`), given
    signatures included: they are compiled (or loaded) after the cache is in place, and the
    dispatcher then closed to compilation, as numba does."""
    from .cache_lock import adopt

    if not options.get("cache"):
        return _numba.njit(*args, **options)
    function = args[0] if args and inspect.isfunction(args[0]) else None
    sigs = None if function is not None or not args else args[0]

    def decorate(fn):
        dispatcher = adopt(_numba.njit(**options)(fn))
        if sigs is not None and hasattr(dispatcher, "disable_compile"):
            for sig in sigs if isinstance(sigs, list) else [sigs]:
                dispatcher.compile(sig)
            dispatcher.disable_compile()
        return dispatcher

    return decorate if function is None else decorate(function)


def report() -> dict:
    """name -> state of every adaptation of numba (`charts.jit.adaptations.STATE`: "on",
    "plain" or "off: <why>"), each one's check run where it has not yet been."""
    from . import borrowed, cache_lock, inliner, kernel_calls, typing_memo, vector_lowering

    for module in (cache_lock, inliner, typing_memo, kernel_calls, vector_lowering, borrowed):
        module.usable()
    return {name: _adaptations.STATE[name] for name in _adaptations.ADAPTATIONS}


def _scope_adaptations() -> None:
    """Register the class-level adaptations with numba's compile events."""
    from . import inliner, typing_memo

    _adaptations.scoped(inliner.install, inliner.restore)
    _adaptations.scoped(typing_memo.install, typing_memo.restore)


_scope_adaptations()
