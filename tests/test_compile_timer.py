"""Compile time is kept apart from integration time in a scene's result.json
(charts.runs.runner.compile_timer: numba's compile events, outermost only)."""
import time
from types import SimpleNamespace

from numba import njit

from charts.runs.runner import compile_timer


def test_compile_timer_measures_numba_compilation_only():
    st = SimpleNamespace(compile_s=0.0)

    def fresh():
        @njit(cache=False)
        def f(x):
            return x * 2.0 + 1.0
        return f

    f = fresh()
    with compile_timer(st):
        t0 = time.perf_counter()
        f(1.0)                       # compiles
        wall = time.perf_counter() - t0
        for _ in range(1000):
            f(2.0)                   # compiled: no more events
    # the first call's wall time is its compilation (a call costs microseconds)
    assert 0.5 * wall <= st.compile_s <= wall + 1e-3
    before = st.compile_s
    with compile_timer(st):
        f(3.0)
    assert st.compile_s == before
