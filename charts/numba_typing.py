"""numba's typing of a call, remembered: each function type answers once per argument types.

numba types every call in a function it compiles — each ``*`` and ``+``, ``math.sin``, an
``@overload`` — by asking the callee's function type for a signature
(``types.BaseFunction.get_call_type``), which orders the callee's templates and tries them
one by one; type inference asks again each time it revisits the call, and numba keeps no
memo.  The generated chart kernels are long straight-line code (thousands of arithmetic
operations): `integrate` in a chart at N = 6, after N = 3, took 5.2 s CPU, 3.1 s with this
memo (docs/performance.md, First use).

`install` gives each function type a memo: (typing context, target, the calling function's
compiler flags but those of its own wrapper, `OWN_FLAGS`, argument types, keyword types) →
the signature found and the implementation key numba recorded with it.  The flags belong in
the key because an ``@overload``'s implementation inherits the caller's (its error model,
fastmath, NRT: numba builds one implementation per set, ``_OverloadFunctionTemplate._get_impl``).
Only found signatures are kept (a failure is asked again, as numba does), and a hit records
the implementation key again, as numba's own call does.  A call answered by an
``@overload(inline=...)`` other than "never" is not kept: numba rebuilds the callee's IR for
the inliner at each typing (``_inline_overloads``), which a hit would skip.  The memo is held
beside the function type object (dropped with it; a function type augmented by a new
``@overload`` is a new object), not in it: numba pickles types with their attributes.  It
serves the typing of charts' own functions (``charts.numba_inliner.ours``: the package, its
generated and on-demand modules), on the CPU; every other compilation in the process, and
the GPU's (not measured there), is left to numba as it is.  numba calls `install` through
its ``numba_extensions`` entry point (``charts.numba_init``, pyproject.toml) before it
compiles anything; ``CHARTS_NUMBA_TYPING=0`` leaves numba as it is (for a comparison, or
should a numba version need it).
"""
from __future__ import annotations

import os
import weakref

from .numba_inliner import ours

__all__ = ["install", "ACTIVE", "memo_size"]

#: Whether numba's function types remember their signatures in this process.
ACTIVE = False

#: function type -> (its memo, its inlined @overload templates); held beside the type, not
#: in it: numba pickles a type with its ``__dict__`` (its disk cache's index does, for a
#: function-pointer argument), and the memo holds typing contexts.
_HELD = weakref.WeakKeyDictionary()


def _inlining(fnty) -> tuple:
    """The function type's templates that are ``@overload``s inlined at numba-IR level (their
    ``_inline`` option other than "never")."""
    out = []
    for template in getattr(fnty, "templates", ()):
        inline = getattr(template, "_inline", None)
        if inline is not None and not inline.is_never_inline:
            out.append(template)
    return tuple(out)


#: The calling function's compiler flags that concern only its own wrapper, its own inlining
#: or object mode: left out of the key (they differ between functions, and no callee's
#: implementation depends on them).  Every other flag is in it, by value.
OWN_FLAGS = frozenset({"no_compile", "no_cpython_wrapper", "no_cfunc_wrapper", "inline",
                       "enable_looplift", "enable_pyobject_looplift"})


def _caller_flags(flags):
    """The calling function's compiler flags as a key (None outside a compilation), or False
    where one's text is not stable (an object's address)."""
    if flags is None:
        return None
    key = tuple(sorted((name, repr(value)) for name, value in flags.values().items()
                       if name not in OWN_FLAGS))
    return False if any(" at 0x" in text for _, text in key) else key


def _remembering(original):
    """``BaseFunction.get_call_type`` with the memo (see the module's docstring)."""
    from numba.core.target_extension import CPU, get_local_target
    from numba.core.targetconfig import ConfigStack

    def get_call_type(self, context, args, kws):
        frames = context.callstack             # [0]: the function being typed
        if len(frames) == 0 or not ours(frames[0].func_id.modname):
            return original(self, context, args, kws)     # not charts' own: numba's way
        held = _HELD.get(self)
        if held is None:
            held = _HELD[self] = ({}, _inlining(self))
        memo, inlining = held
        target = get_local_target(context)
        flags = _caller_flags(ConfigStack.top_or_none())
        if flags is False or not issubclass(target, CPU):   # numba's own way: flags without
            return original(self, context, args, kws)       # a stable text, other targets
        try:
            key = (context, target, flags, tuple(args),
                   tuple(sorted(kws.items())) if kws else ())
            hash(key)
        except TypeError:                      # an unhashable argument type: numba's own way
            return original(self, context, args, kws)
        hit = memo.get(key)
        if hit is not None:
            sig, impl_key = hit
            self._impl_keys[sig.args] = impl_key
            return sig
        sig = original(self, context, args, kws)
        if sig is not None and sig.args in self._impl_keys and not any(
                sig.args in t._inline_overloads for t in inlining):
            memo[key] = (sig, self._impl_keys[sig.args])
        return sig

    get_call_type._charts_memo = True
    get_call_type.__wrapped__ = original
    get_call_type.__doc__ = original.__doc__
    return get_call_type


def memo_size(fnty) -> int:
    """The number of argument-type combinations the function type ``fnty`` remembers."""
    held = _HELD.get(fnty)
    return 0 if held is None else len(held[0])


def install() -> None:
    """Give numba's function types the memo (idempotent)."""
    global ACTIVE
    if os.environ.get("CHARTS_NUMBA_TYPING", "1").strip() == "0":
        return
    from numba.core.types.functions import BaseFunction

    if getattr(BaseFunction.get_call_type, "_charts_memo", False):
        ACTIVE = True
        return
    BaseFunction.get_call_type = _remembering(BaseFunction.get_call_type)
    ACTIVE = True
