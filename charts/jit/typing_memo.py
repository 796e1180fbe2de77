"""numba's typing of a call remembered, while numba compiles charts' functions.

numba types every call in a function it compiles — each ``*`` and ``+``, ``math.sin``, an
``@overload`` — by asking the callee's function type for a signature
(``types.BaseFunction.get_call_type``), which orders the callee's templates and tries them
one by one; type inference asks again each time it revisits the call, and numba keeps no
memo.  The generated chart kernels are long straight-line code (thousands of arithmetic
operations), so typing is much of their first compilation (docs/performance.md, First use).

This adaptation gives each function type a memo: (typing context, target, the calling
function's compiler flags but those of its own wrapper, `OWN_FLAGS`, argument types, keyword
types) → the signature found and the implementation key numba recorded with it.  The flags
belong in the key because an ``@overload``'s implementation inherits the caller's (its error
model, fastmath, NRT: numba builds one implementation per set).  Only found signatures are
kept (a failure is asked again, as numba does), and a hit records the implementation key
again, as numba's own call does.  A call answered by an ``@overload(inline=...)`` other than
"never" is not kept: numba rebuilds the callee's IR for the inliner at each typing, which a
hit would skip.  The memo is held beside the function type object (dropped with it), not in
it: numba pickles types with their attributes.  It serves the typing of charts' own
functions (`charts.jit.adaptations.ours`) on the CPU; every other typing goes to numba's
own function.  It is in numba's class only while numba compiles a charts function
(`charts.jit.adaptations.compile_scope`); where numba's internals differ from what it
expects, it stays out with one notice (`usable`).
"""
from __future__ import annotations

import weakref

from . import adaptations

__all__ = ["usable", "install", "restore", "memo_size", "OWN_FLAGS"]

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
        if len(frames) == 0 or not adaptations.ours(frames[0].func_id.modname):
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


#: numba's ``get_call_type``'s parameters, as this adaptation calls it.
PARAMETERS = ["self", "context", "args", "kws"]

_original = None        # numba's BaseFunction.get_call_type
_wrapper = None         # the remembering one


def _check():
    """None, or what differs in numba's typing from what this adaptation expects; builds the
    wrapper on success."""
    global _original, _wrapper
    import inspect

    from numba.core.target_extension import CPU, get_local_target  # noqa: F401 - the memo's
    from numba.core.typing import context as typing_context
    from numba.core.targetconfig import ConfigStack
    from numba.core.types.functions import BaseFunction
    from numba.core.typing import templates

    original = BaseFunction.__dict__.get("get_call_type")
    if original is None:
        return "BaseFunction.get_call_type is missing"
    if list(inspect.signature(original).parameters) != PARAMETERS:
        return f"get_call_type{inspect.signature(original)} has other parameters"
    if "_impl_keys" not in inspect.getsource(BaseFunction):
        return "function types keep no _impl_keys"
    if "_inline_overloads" not in inspect.getsource(templates):
        return "overload templates keep no _inline_overloads"
    if not hasattr(ConfigStack, "top_or_none"):
        return "ConfigStack.top_or_none is missing"
    if not hasattr(getattr(typing_context, "CallStack", None), "__getitem__"):
        return "the typing context's call stack is not indexable"
    _original, _wrapper = original, _remembering(original)
    return None


def usable() -> bool:
    """Whether the memo serves charts' compilations in this process."""
    return adaptations.active("typing_memo", _check)


def install() -> None:
    """Put the remembering ``get_call_type`` in numba's class (while a charts function
    compiles)."""
    from numba.core.types.functions import BaseFunction

    if usable():
        BaseFunction.get_call_type = _wrapper


def restore() -> None:
    """numba's own ``get_call_type`` back in its class."""
    from numba.core.types.functions import BaseFunction

    if _original is not None:
        BaseFunction.get_call_type = _original
