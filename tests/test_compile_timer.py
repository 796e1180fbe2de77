"""Compile time is kept apart from integration time in a scene's result.json
(charts.jit.compilation.compile_timer, used by the runner: numba's compile events, outermost only)."""
import time

from numba import njit

from charts.jit.compilation import compile_timer


def test_compile_timer_measures_numba_compilation_only():
    spent = []

    def fresh():
        @njit(cache=False)
        def f(x):
            return x * 2.0 + 1.0
        return f

    f = fresh()
    with compile_timer(spent.append):
        t0 = time.perf_counter()
        f(1.0)                       # compiles
        wall = time.perf_counter() - t0
        for _ in range(1000):
            f(2.0)                   # compiled: no more events
    # the first call's wall time is its compilation (a call costs microseconds)
    assert 0.5 * wall <= sum(spent) <= wall + 1e-3
    before = sum(spent)
    with compile_timer(spent.append):
        f(3.0)
    assert sum(spent) == before
