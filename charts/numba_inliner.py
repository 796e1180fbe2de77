"""numba's inliner without its quadratic copy, for charts' functions.

Every ``inline="always"`` call is inlined by ``InlineWorker.inline_ir``, which first copies
the callee's IR block by block with a separate ``copy.deepcopy`` per block.  Every block
refers to the function's one ``Scope`` (all its variables), so each block's copy copies the
whole scope again: the cost grows as blocks × variables, and an inlined function is itself
the inlined body of everything below it.  It was a third to a half of the first compilation of
charts' kernels (the angle test at N = 3: 16.7 of 37 s CPU in ``deepcopy``, measured; see
docs/performance.md, First use).  `install` gives numba a copy of all blocks in one
``deepcopy`` (one memo: the scope copied once, shared by the copied blocks, as the inliner
then requires anyway), for callees defined in this package; other packages' functions keep
numba's own code.  The IR, and so the compiled code, is the same.

The new copy is numba's own source of ``inline_ir`` with those lines replaced; where numba's
source differs from the lines expected (another numba version), nothing is changed and
`ACTIVE` stays False.  numba calls `install` through its ``numba_extensions`` entry point
(``charts.numba_init``, pyproject.toml) before it compiles anything.  The environment
variable ``CHARTS_NUMBA_INLINER=0`` leaves numba's inliner as it is (for a comparison, or
should a numba version need it).
"""
from __future__ import annotations

import inspect
import os
import textwrap

__all__ = ["install", "ACTIVE", "PER_BLOCK", "ONE_COPY", "ours"]

#: Whether numba's inliner uses the one-copy version for charts' callees in this process.
ACTIVE = False

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


def ours(module) -> bool:
    """Whether ``module`` (a module name) is this package's or one of its on-demand modules."""
    module = module or ""
    return module == "charts" or module.startswith(("charts.", "charts_ondemand_"))


def _one_copy_inline_ir(original):
    """numba's ``inline_ir`` with `PER_BLOCK` replaced by `ONE_COPY`, compiled in numba's
    module (its globals), or None where its source does not hold `PER_BLOCK` exactly once."""
    from numba.core import inline_closurecall

    try:
        source = textwrap.dedent(inspect.getsource(original))
    except (OSError, TypeError):
        return None
    if source.count(PER_BLOCK) != 1:
        return None
    namespace = {}
    exec(compile(source.replace(PER_BLOCK, ONE_COPY), inline_closurecall.__file__, "exec"),
         inline_closurecall.__dict__, namespace)
    return namespace.get("inline_ir")


def install() -> None:
    """Give numba's inliner the one-copy ``inline_ir`` for charts' callees (idempotent)."""
    global ACTIVE
    if os.environ.get("CHARTS_NUMBA_INLINER", "1").strip() == "0":
        return
    from numba.core.inline_closurecall import InlineWorker

    if getattr(InlineWorker.inline_ir, "_charts_one_copy", False):
        return
    original = InlineWorker.inline_ir
    fast = _one_copy_inline_ir(original)
    if fast is None:
        return

    def inline_ir(self, caller_ir, block, i, callee_ir, callee_freevars, arg_typs=None):
        func = getattr(getattr(callee_ir, "func_id", None), "func", None)
        impl = fast if ours(getattr(func, "__module__", "")) else original
        return impl(self, caller_ir, block, i, callee_ir, callee_freevars, arg_typs=arg_typs)

    inline_ir._charts_one_copy = True
    inline_ir.__wrapped__ = original
    inline_ir.__doc__ = original.__doc__
    InlineWorker.inline_ir = inline_ir
    ACTIVE = True
