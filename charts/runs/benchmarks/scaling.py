"""Cost per simulated time unit against N (``python scripts/bench_scaling.py``).

For each N: the tangent kernel of the Lyapunov analyses (eqs 8 + 17, RK4 dt = 0.01, eq 18
every 0.1, ``charts.solvers.tangent.TangentFlow``) with k = N − 2 and with k = 3 vectors, and
the chart formulation (eq 14 on the kernels of ``charts.geometry.kernels.geometry``, RK4
dt = 0.01, through ``integrate``).  CPU time (``time.process_time``) of a warm run, the
median of ``--repeat`` runs, each long enough to take ``--min-cpu`` seconds.  Slopes of
log(cost) against log(N) are least-squares fits over N >= ``--fit-from``.
"""
from __future__ import annotations

import argparse
import time

import numpy as np
from ...jit import njit

from ...geometry.kernels import source
from ...geometry.system import RotorSystem
from ...solvers.rk import RHS_SIG
from ...solvers.integrate import integrate
from ...solvers.tangent import TangentFlow
from ...plotting.style import new_figure, save_png

__all__ = ["measure", "fit_slope", "rhs_cost", "main", "DEFAULT_N"]

DEFAULT_N = (3, 4, 6, 8, 12, 16, 24, 32, 48, 64, 96, 128, 192, 256)
DT = 0.01
REORTH = 10          # steps: eq (18) every 0.1 time units, the Lyapunov default


def _cpu_per_step(run, steps, min_cpu, repeat):
    run(steps)  # warm: compiled, caches hot
    t0 = time.process_time()
    run(steps)
    once = max(time.process_time() - t0, 1e-6)
    steps = max(steps, int(steps * min_cpu / once))
    out = []
    for _ in range(repeat):
        t0 = time.process_time()
        run(steps)
        out.append((time.process_time() - t0) / steps)
    return float(np.median(out))


def measure(n, kind, *, min_cpu=0.3, repeat=3):
    """CPU seconds per simulated time unit for N = ``n``; ``kind`` is 'k=N-2', 'k=3' or
    'chart'.  None when the kind does not apply (k = 3 needs N >= 5)."""
    system = RotorSystem(n)
    theta, u = system.random_state(seed=1)
    if kind == "chart":
        state = {"theta": theta, "u": u}

        def run(steps):
            r = integrate(system, state["theta"], state["u"], steps * DT, formulation="chart",
                          method="rk4", dt=DT, t_eval=np.array([steps * DT]))
            state["theta"], state["u"] = r.theta[-1], r.u[-1]
    else:
        k = n - 2 if kind == "k=N-2" else 3
        if k > n - 2:
            return None
        flow = TangentFlow(system, theta, u, k, dt=DT, reorth_every=REORTH, project_every=100)

        def run(steps):
            flow.advance(steps)
    return _cpu_per_step(run, 200, min_cpu, repeat) / DT


@njit
def _repeat_rhs(f, y, par, dy, reps):
    acc = 0.0
    for _ in range(reps):
        acc += f(y, par, dy)
    return acc


def rhs_cost(n, which, reps=100_000, repeat=3):
    """CPU seconds per evaluation of the chart right-hand side (eqs 14 + 16, one transported
    vector) for N = ``n`` with the ``which`` = 'generated' or 'structured' kernels."""
    from ...flows.chart import local_parameters, structured_rates
    from ...solvers.chart_formulation import chart_rhs

    if which == "structured":
        rhs = njit(RHS_SIG)(structured_rates)
    elif source(n) == "generated":
        rhs = chart_rhs(n, paper=True)
    else:
        return None
    system = RotorSystem(n)
    theta, u = system.random_state(seed=1)
    k = system.best_chart(theta)
    y = np.concatenate([np.delete(theta, k), np.delete(u, k), np.delete(u, k)])
    par = local_parameters(system.masses, system.weights, system.level, k)
    dy = np.empty_like(y)
    _repeat_rhs(rhs, y, par, dy, 10)
    out = []
    for _ in range(repeat):
        t0 = time.process_time()
        _repeat_rhs(rhs, y, par, dy, reps)
        out.append((time.process_time() - t0) / reps)
    return float(np.median(out))


def fit_slope(ns, costs, fit_from):
    """Least-squares slope and intercept of log(cost) against log(N) over N >= fit_from."""
    pts = [(np.log(n), np.log(c)) for n, c in zip(ns, costs) if c is not None and n >= fit_from]
    x, y = np.array(pts).T
    slope, icpt = np.polyfit(x, y, 1)
    return float(slope), float(icpt)


KINDS = {"k=N-2": "tangent kernel, k = N−2 vectors (full positive spectrum)",
         "k=3": "tangent kernel, k = 3 vectors",
         "chart": "chart formulation (eq 14), state only"}


def main(argv=None):
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("--n", type=int, nargs="+", default=list(DEFAULT_N))
    p.add_argument("--min-cpu", type=float, default=0.3, help="CPU seconds per timed run")
    p.add_argument("--repeat", type=int, default=3)
    p.add_argument("--fit-from", type=int, default=16)
    p.add_argument("--figure", default=None, help="write the log–log figure here (PNG)")
    p.add_argument("--kernels", action="store_true",
                   help="only compare the generated and structured chart right-hand sides")
    a = p.parse_args(argv)
    if a.kernels:
        print(f"{'N':>5} {'generated':>12} {'structured':>12}   (CPU µs per evaluation of eqs "
              "14 + 16 with one transported vector)")
        for n in a.n:
            g, st = rhs_cost(n, "generated"), rhs_cost(n, "structured")
            print(f"{n:>5} " + ("-".rjust(12) if g is None else f"{g * 1e6:12.3f}")
                  + f" {st * 1e6:12.3f}", flush=True)
        return 0
    res = {kind: [] for kind in KINDS}
    print(f"{'N':>5} " + " ".join(f"{k:>14}" for k in KINDS) + "   (CPU s per time unit)")
    for n in a.n:
        row = [measure(n, kind, min_cpu=a.min_cpu, repeat=a.repeat) for kind in KINDS]
        for kind, c in zip(KINDS, row):
            res[kind].append(c)
        print(f"{n:>5} " + " ".join(f"{'-':>14}" if c is None else f"{c:14.3e}" for c in row),
              flush=True)
    fits = {kind: fit_slope(a.n, res[kind], a.fit_from) for kind in KINDS}
    for kind, (slope, _) in fits.items():
        print(f"slope of log cost vs log N over N >= {a.fit_from}, {KINDS[kind]}: {slope:.2f}")
    if a.figure:
        fig, ax = new_figure(figsize=(6.4, 4.2))
        for (kind, label), mk in zip(KINDS.items(), "os^"):
            ns = [n for n, c in zip(a.n, res[kind]) if c is not None]
            cs = [c for c in res[kind] if c is not None]
            slope, icpt = fits[kind]
            line = ax.loglog(ns, cs, mk, label=f"{label}: slope {slope:.2f}")[0]
            xs = np.array([a.fit_from, max(ns)], float)
            ax.loglog(xs, np.exp(icpt) * xs ** slope, "-", color=line.get_color(), lw=1)
        ax.set_xlabel("N (rotors)")
        ax.set_ylabel("CPU seconds per simulated time unit")
        ax.set_title(f"Cost per time unit, RK4 dt = {DT}, eq (18) every 0.1\n"
                     f"(lines: least-squares fits over N ≥ {a.fit_from})", fontsize=10)
        ax.legend(fontsize=8)
        ax.grid(True, which="both", alpha=0.3)
        save_png(fig, a.figure)
        print(f"figure: {a.figure}")
    return 0
