"""numba's inliner with one copy of the callee's blocks (``charts.numba_inliner``): active on
this numba, the same IR as numba's block-by-block copies, only for charts' callees, and
kernels that inline through it compute what they computed."""
import copy
import io
import os
import subprocess
import sys
from contextlib import redirect_stdout

import numpy as np
from numba import njit
from numba.core.compiler import run_frontend
from numba.core.inline_closurecall import InlineWorker

from charts import numba_inliner
from charts.solvers.status import sum_squares
from charts.solvers.tangent import stacked_rk4_step


def _dump(blocks) -> str:
    out = io.StringIO()
    with redirect_stdout(out):
        for label in sorted(blocks):
            print(label)
            blocks[label].dump()
    return out.getvalue()


def test_the_one_copy_is_active_on_this_numba():
    """Installed through numba's entry point (pyproject.toml) before the first compilation;
    install is idempotent and keeps numba's own function beside it."""
    numba_inliner.install()
    numba_inliner.install()
    assert numba_inliner.ACTIVE, ("numba's inline_ir no longer holds the block-by-block copy "
                                  "that charts.numba_inliner replaces: check numba's source")
    assert InlineWorker.inline_ir._charts_one_copy
    assert not getattr(InlineWorker.inline_ir.__wrapped__, "_charts_one_copy", False)


def test_numba_installs_it_itself_before_compiling():
    """A process that never imports charts gets it from numba's entry point (as every
    process that compiles charts' kernels does, workers included)."""
    code = ("import numba\n@numba.njit\ndef f(x): return x\nf(1)\n"
            "from numba.core.inline_closurecall import InlineWorker\n"
            "print(getattr(InlineWorker.inline_ir, '_charts_one_copy', False))")
    r = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, timeout=120)
    assert r.stdout.strip() == "True", r.stderr
    off = dict(os.environ, CHARTS_NUMBA_INLINER="0")     # numba's own inliner, when asked
    r = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, timeout=120,
                       env=off)
    assert r.stdout.strip() == "False", r.stderr


def test_one_copy_is_the_same_ir_with_one_scope():
    """Copied in one deepcopy, a charts function's blocks dump exactly as numba's copies one
    by one do, and share one copied scope (numba's inliner asserts a single scope) instead of
    one copy of the whole scope per block."""
    the_ir = run_frontend(stacked_rk4_step.py_func)
    per_block = {label: copy.deepcopy(block) for label, block in the_ir.blocks.items()}
    one = copy.deepcopy(the_ir.blocks)
    assert len(the_ir.blocks) > 3
    assert _dump(one) == _dump(per_block) == _dump(the_ir.blocks)
    scopes = {id(block.scope) for block in one.values()}
    assert len(scopes) == 1 and id(the_ir.blocks[min(the_ir.blocks)].scope) not in scopes
    assert len({id(block.scope) for block in per_block.values()}) == len(per_block)


def test_only_charts_callees_take_the_new_copy():
    assert numba_inliner.ours("charts.solvers.tangent")
    assert numba_inliner.ours("charts_ondemand_7_3")
    assert numba_inliner.ours("charts")
    assert not numba_inliner.ours("chartsy")
    assert not numba_inliner.ours("numba.np.arrayobj")
    assert not numba_inliner.ours(None)


def test_a_function_inlining_charts_terms_computes_the_same():
    """A new function that inlines a charts term (inline="always") through the one-copy
    inliner gives what the term gives in Python."""
    numba_inliner.install()

    @njit
    def twice_sum_squares(x, n):
        return sum_squares(x, 0, n) + sum_squares(x, 0, n)

    x = np.array([0.5, -1.25, 3.0, 7.0])
    assert twice_sum_squares(x, 3) == 2 * sum_squares.py_func(x, 0, 3)
