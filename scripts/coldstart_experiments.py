"""The cold-start experiments of docs/changelog.md ("Cold start", "What was tried"), for whichever copy of
the package is imported (point PYTHONPATH at a modified copy, and NUMBA_CACHE_DIR at a new empty
folder, to measure a variant from cold).

    NUMBA_CACHE_DIR=$(mktemp -d) PYTHONPATH=COPY python scripts/coldstart_experiments.py variant LABEL
    python scripts/coldstart_experiments.py interpreted     # the kernels' own Python vs compiled
    python scripts/coldstart_experiments.py aot DIR         # numba.pycc build into DIR, then compare

``variant``: CPU seconds of the first ``lyapunov_spectrum`` (t = 2) of a new process, the part
spent under numba's LLVM lock, and the warm rate (CPU µs per time unit, median of 3 × t = 300).
``interpreted``: 300 steps of the tangent kernel by its Python source with every numba function
replaced by its ``py_func``, against the compiled kernel: bit-identical?  and the cost per step.
``aot``: the tangent kernel compiled ahead of time by ``numba.pycc`` (pending deprecation), then
its warm rate against the JIT kernel's in one process and whether the exponents are identical.
"""
import statistics
import sys
import time
import types

import numpy as np

S_ARGS = dict(dt=0.01, n_exponents=3, t_transient=0.0)
AOT_SIG = ("UniTuple(int64, 2)(float64[:, ::1], float64[:, ::1], int64[::1], float64[::1], "
           "float64[::1], float64[::1], float64, float64, float64, int64, int64, float64[::1], "
           "boolean, int64, float64[::1], int64, int64, float64[:, ::1], int64[::1], "
           "float64[:, ::1], int64[::1], UniTuple(float64[::1], 10))")   # shares, work arrays


def warm_rate(charts, S, th, u):
    """CPU µs per simulated time unit of the Lyapunov task, median of 3 × t = 300."""
    w = []
    for _ in range(3):
        c = time.process_time()
        r = charts.lyapunov_spectrum(S, th, u, 300.0, **S_ARGS)
        w.append((time.process_time() - c) / 300 * 1e6)
    return statistics.median(w), r.exponents


def variant(label):
    from numba.core import event

    import charts

    llvm = [0.0]

    class LLVMTime(event.Listener):                   # CPU seconds under numba's LLVM lock
        def on_start(self, e):
            self.t0 = time.process_time()

        def on_end(self, e):
            llvm[0] += time.process_time() - self.t0

    event.register("numba:llvm_lock", LLVMTime())
    S = charts.RotorSystem(5)
    th, u = S.random_state(seed=1)
    c = time.process_time()
    charts.lyapunov_spectrum(S, th, u, 2.0, n_batches=2, **S_ARGS)
    first = time.process_time() - c
    rate, exps = warm_rate(charts, S, th, u)
    print(f"{label}: first call {first:.2f} CPU s (LLVM {llvm[0]:.2f}), warm "
          f"{rate:.1f} µs per time unit, λ1 = {exps[0]!r}")


def _interpreted(disp, memo):
    """The Python source of a numba function, its numba callees replaced likewise."""
    from numba.core.registry import CPUDispatcher

    if disp not in memo:
        f = disp.py_func
        g = dict(f.__globals__)
        memo[disp] = types.FunctionType(f.__code__, g, f.__name__, f.__defaults__, f.__closure__)
        for name in f.__code__.co_names:
            if isinstance(g.get(name), CPUDispatcher):
                g[name] = _interpreted(g[name], memo)
    return memo[disp]


def interpreted():
    import charts
    from charts.analyses.lyapunov import lyapunov_flow, lyapunov_settings
    from charts.solvers import tangent

    S = charts.RotorSystem(5)
    th, u = S.random_state(seed=1)
    cfg = lyapunov_settings(S, 2.0, n_exponents=3, t_transient=0.0, n_batches=2)
    a, b = lyapunov_flow(S, th, u, cfg), lyapunov_flow(S, th, u, cfg)
    a.advance(1)                                       # compile, and one step ahead
    slow = _interpreted(tangent.tangent_kernel, {})
    n = 300
    c = time.process_time()
    a.advance(n)
    fast = (time.process_time() - c) / n
    none = np.empty((0, 0))
    c = time.process_time()
    slow(b.Z, b.sc, b.counter, S.minv, S.masses, S.weights, S.level, b.speed, b.dt, n + 1,
         b.reorth_every, b.w, b.restricted, b.project_every, b.logsum, 0, 0, none,
         np.empty(0, dtype=np.int64), none, b.shares, tangent.stacked_work(*b.Z.shape))
    py = (time.process_time() - c) / (n + 1)
    print(f"{n + 1} steps: Z identical {np.array_equal(a.Z, b.Z)}, log sums identical "
          f"{np.array_equal(a.logsum, b.logsum)}; compiled {fast * 1e6:.2f} µs per step, "
          f"interpreted {py * 1e6:.0f} µs ({py / fast:.0f}×)")


def aot(folder):
    from numba.pycc import CC

    import charts
    from charts.solvers import tangent

    cc = CC("aot_tangent")
    cc.output_dir = folder
    cc.target_cpu = "host"
    cc.export("tangent_kernel", AOT_SIG)(tangent.tangent_kernel.py_func)
    c = time.process_time()
    cc.compile()
    print(f"AOT build: {time.process_time() - c:.1f} CPU s")
    sys.path.insert(0, folder)
    import aot_tangent

    S = charts.RotorSystem(5)
    th, u = S.random_state(seed=1)
    jit = tangent.tangent_kernel
    rates = {}
    for name, kernel in (("AOT", aot_tangent.tangent_kernel), ("JIT", jit)):
        tangent.tangent_kernel = kernel                # TangentFlow looks it up in its module
        rates[name] = warm_rate(charts, S, th, u)
    tangent.tangent_kernel = jit
    print(f"warm µs per time unit: AOT {rates['AOT'][0]:.1f}, JIT {rates['JIT'][0]:.1f}; "
          f"exponents identical {np.array_equal(rates['AOT'][1], rates['JIT'][1])}")


if __name__ == "__main__":
    what, *rest = sys.argv[1:] or ["variant"]
    {"variant": lambda: variant(rest[0] if rest else "this copy"), "interpreted": interpreted,
     "aot": lambda: aot(rest[0])}[what]()
