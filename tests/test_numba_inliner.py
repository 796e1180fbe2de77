"""numba's inliner with one copy of the callee's blocks (``charts.jit.inliner``): usable on
this numba, in numba's class only while a charts function compiles, the same IR as numba's
block-by-block copies, only for charts' callees, and kernels that inline through it compute
what they computed."""
import copy
import io
import subprocess
import sys
from contextlib import redirect_stdout

import numpy as np
from numba import njit
from numba.core.compiler import run_frontend
from numba.core.inline_closurecall import InlineWorker

from charts.jit import inliner
from charts.solvers.status import sum_squares
from charts.solvers.tangent import substep_loop


def _dump(blocks) -> str:
    out = io.StringIO()
    with redirect_stdout(out):
        for label in sorted(blocks):
            print(label)
            blocks[label].dump()
    return out.getvalue()


def test_the_one_copy_is_usable_on_this_numba_and_restored():
    """install is idempotent and keeps numba's own function beside it; restore puts numba's
    back."""
    own = InlineWorker.inline_ir
    assert inliner.usable(), ("numba's inline_ir no longer holds the block-by-block copy that "
                              "charts.jit.inliner replaces: check numba's source")
    inliner.install()
    inliner.install()
    try:
        assert InlineWorker.inline_ir._charts_one_copy
        assert InlineWorker.inline_ir.__wrapped__ is own
    finally:
        inliner.restore()
    assert InlineWorker.inline_ir is own


#: Records, at each compile event of a charts function and of another, whether numba's
#: inliner was its own then; a script that never imports charts leaves numba's untouched.
_SCOPE_PROBE = """
import sys
from numba import njit
from numba.core import event
from numba.core.inline_closurecall import InlineWorker
own = InlineWorker.inline_ir
seen = []
class Probe(event.Listener):
    def on_start(self, ev):
        seen.append((ev.data["dispatcher"].py_func.__module__,
                     InlineWorker.inline_ir is own))
    def on_end(self, ev):
        pass
if sys.argv[1] == "charts":
    from charts.solvers.status import sum_squares      # (imports charts.jit)
event.register("numba:compile", Probe())
@njit
def users(x):
    return x + 1
users(1)
if sys.argv[1] == "charts":
    import numpy as np
    njit(sum_squares.py_func)(np.ones(3), 0, 3)        # a charts function, compiled afresh
print(seen, InlineWorker.inline_ir is own)
"""


def test_in_numbas_class_only_while_a_charts_function_compiles():
    """A user's function compiles with numba's own inliner, with or without charts in the
    process; a charts function with the one copy; afterwards numba's is back."""
    r = subprocess.run([sys.executable, "-c", _SCOPE_PROBE, "plain"], capture_output=True,
                       text=True, timeout=300)
    assert r.stdout.strip() == "[('__main__', True)] True", r.stderr
    r = subprocess.run([sys.executable, "-c", _SCOPE_PROBE, "charts"], capture_output=True,
                       text=True, timeout=300)
    assert r.stdout.strip() == ("[('__main__', True), ('charts.solvers.status', False)] True"), \
        r.stderr


def test_one_copy_is_the_same_ir_with_one_scope():
    """Copied in one deepcopy, a charts function's blocks dump exactly as numba's copies one
    by one do, and share one copied scope (numba's inliner asserts a single scope) instead of
    one copy of the whole scope per block."""
    the_ir = run_frontend(substep_loop.py_func)
    per_block = {label: copy.deepcopy(block) for label, block in the_ir.blocks.items()}
    one = copy.deepcopy(the_ir.blocks)
    assert len(the_ir.blocks) > 3
    assert _dump(one) == _dump(per_block) == _dump(the_ir.blocks)
    scopes = {id(block.scope) for block in one.values()}
    assert len(scopes) == 1 and id(the_ir.blocks[min(the_ir.blocks)].scope) not in scopes
    assert len({id(block.scope) for block in per_block.values()}) == len(per_block)


def test_only_charts_callees_take_the_new_copy():
    from charts.jit.adaptations import ours

    assert ours("charts.solvers.tangent")
    assert ours("charts_ondemand_7_3")
    assert ours("charts")
    assert not ours("chartsy")
    assert not ours("numba.np.arrayobj")
    assert not ours(None)


def test_a_function_inlining_charts_terms_computes_the_same():
    """A new function that inlines a charts term (inline="always") through the one-copy
    inliner gives what the term gives in Python."""
    def twice_sum_squares(x, n):
        return sum_squares(x, 0, n) + sum_squares(x, 0, n)

    twice_sum_squares.__module__ = "charts_ondemand_inline_probe"    # compiled as charts'
    twice_sum_squares = njit(twice_sum_squares)

    x = np.array([0.5, -1.25, 3.0, 7.0])
    assert twice_sum_squares(x, 3) == 2 * sum_squares.py_func(x, 0, 3)
