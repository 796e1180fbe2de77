"""numba's inliner without its quadratic copy, while numba compiles charts' functions.

Every ``inline="always"`` call is inlined by ``InlineWorker.inline_ir``, which first copies
the callee's IR block by block with a separate ``copy.deepcopy`` per block.  Every block
refers to the function's one ``Scope`` (all its variables), so each block's copy copies the
whole scope again: the cost grows as blocks × variables, and an inlined function is itself
the inlined body of everything below it.  It was a third to a half of the first compilation
of charts' kernels (docs/performance.md, First use).  This adaptation gives numba's inliner
a copy of all blocks in one ``deepcopy`` (one memo: the scope copied once, shared by the
copied blocks, as the inliner then requires anyway) for callees defined in this package;
other functions keep numba's own code.  The IR, and so the compiled code, is the same.

The new copy is numba's own source of ``inline_ir`` with those lines replaced; where numba's
source or signature differs from what is expected (another numba version), nothing changes
(`usable` is False, with one notice).  It is in numba's class only while numba compiles a
charts function (`charts.jit.adaptations.compile_scope`).
"""
from __future__ import annotations

import inspect
import textwrap

from . import adaptations

__all__ = ["usable", "install", "restore", "PER_BLOCK", "ONE_COPY"]

#: numba's lines that copy the callee's blocks one by one (in ``inline_ir``'s ``copy_ir``).
PER_BLOCK = """\
        for block_label, block in the_ir.blocks.items():
            new_block = copy.deepcopy(the_ir.blocks[block_label])
            kernel_copy.blocks[block_label] = new_block
"""
#: Their replacement: every block in one deepcopy (one memo, so the scope is copied once).
ONE_COPY = """\
        kernel_copy.blocks = copy.deepcopy(the_ir.blocks)
"""

#: numba's ``inline_ir``'s parameters, as this adaptation calls it.
PARAMETERS = ["self", "caller_ir", "block", "i", "callee_ir", "callee_freevars", "arg_typs"]

_original = None        # numba's InlineWorker.inline_ir
_wrapper = None         # the one that picks the one-copy version for charts' callees


def _one_copy_inline_ir(original):
    """numba's ``inline_ir`` with `PER_BLOCK` replaced by `ONE_COPY`, compiled in numba's
    module (its globals), or None where its source does not hold `PER_BLOCK` exactly once."""
    from numba.core import inline_closurecall

    source = textwrap.dedent(inspect.getsource(original))
    if source.count(PER_BLOCK) != 1:
        return None
    namespace = {}
    exec(compile(source.replace(PER_BLOCK, ONE_COPY), inline_closurecall.__file__, "exec"),
         inline_closurecall.__dict__, namespace)
    return namespace.get("inline_ir")


def _check():
    """None, or what differs in numba's inliner from what this adaptation expects; builds
    the wrapper on success."""
    global _original, _wrapper
    from numba.core.inline_closurecall import InlineWorker

    original = InlineWorker.__dict__.get("inline_ir")
    if original is None:
        return "InlineWorker.inline_ir is missing"
    if list(inspect.signature(original).parameters) != PARAMETERS:
        return f"inline_ir{inspect.signature(original)} has other parameters"
    fast = _one_copy_inline_ir(original)
    if fast is None:
        return "inline_ir no longer copies the callee's blocks one by one"

    def inline_ir(self, caller_ir, block, i, callee_ir, callee_freevars, arg_typs=None):
        func = getattr(getattr(callee_ir, "func_id", None), "func", None)
        impl = fast if adaptations.ours(getattr(func, "__module__", "")) else original
        return impl(self, caller_ir, block, i, callee_ir, callee_freevars, arg_typs=arg_typs)

    inline_ir._charts_one_copy = True
    inline_ir.__wrapped__ = original
    inline_ir.__doc__ = original.__doc__
    _original, _wrapper = original, inline_ir
    return None


def usable() -> bool:
    """Whether the one-copy inliner is used for charts' compilations in this process."""
    return adaptations.active("inliner", _check)


def install() -> None:
    """Put the one-copy ``inline_ir`` in numba's class (while a charts function compiles)."""
    from numba.core.inline_closurecall import InlineWorker

    if usable():
        InlineWorker.inline_ir = _wrapper


def restore() -> None:
    """numba's own ``inline_ir`` back in its class."""
    from numba.core.inline_closurecall import InlineWorker

    if _original is not None:
        InlineWorker.inline_ir = _original
