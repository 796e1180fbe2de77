"""Cost per unit of simulated time of ``charts.integrate``, against ``scipy.integrate.solve_ivp``.

    charts bench integrators [--t 200] [--rtol 1e-10] [--repeat 5]

For N = 3, 4, 5 (unit masses, unit speed, seed 0) every formulation × method is timed on the
same geodesic over ``--t`` time units and reported as CPU seconds per unit time and as a ratio
to ``solve_ivp(method="DOP853")`` at the same rtol/atol on eq (8).  The SciPy right-hand side
calls the numba-compiled eq (8) (``charts.flows.ambient.flow_rhs``), so the ratio measures the
integrator, not a slow Python right-hand side.  RK4 uses the paper's dt = 0.01.  After a
warm-up (compilation) the routes take turns ``--repeat`` times; each entry is the median CPU
time (``time.process_time``), with the range over the repetitions.  The last column is
max|θ − θ_ref| at t = 20 (before the chaos erases the digits), θ_ref from the ambient DOP853
at rtol 1e-13.
"""
from __future__ import annotations

import argparse
import datetime
import sys
import time

import numpy as np
from scipy.integrate import solve_ivp

from ...flows.ambient import flow_rhs
from ...geometry.system import RotorSystem
from ...solvers.integrate import integrate
from .environment import load, machine, spread
from ..cli_parser import OneLineParser

__all__ = ["routes", "main"]


def cpu_time(fn):
    """(CPU seconds, result) of one call."""
    c0 = time.process_time()
    out = fn()
    return time.process_time() - c0, out


def routes(system, theta, u, T, tc, rtol):
    """{name: callable} for one N: SciPy's DOP853 on eq (8) and charts' formulations × methods;
    each callable returns (steps, rhs evaluations, θ at tc)."""
    n = system.n
    minv = system.minv
    wts = system.weights
    dy = np.empty(2 * n)

    def f(t, y):
        flow_rhs(y, minv, wts, dy)
        return dy.copy()

    y0 = np.concatenate([theta, u])

    def scipy_route():
        sol = solve_ivp(f, (0, T), y0, method="DOP853", rtol=rtol, atol=rtol, t_eval=[tc, T])
        # t_eval hides the step grid; DOP853 uses 12 evaluations per step
        return sol.nfev // 12, sol.nfev, sol.y[:n, 0]

    out = {"scipy solve_ivp DOP853": scipy_route}
    for form in ("ambient", "chart"):
        for method in ("dop853", "rk4"):
            kw = dict(rtol=rtol, atol=rtol) if method == "dop853" else dict(dt=0.01)

            def ours(form=form, method=method, kw=kw):
                r = integrate(system, theta, u, T, formulation=form, method=method,
                              t_eval=[0, tc, T], **kw)
                return r.n_steps, r.n_rhs, r.theta[1]

            out[f"{form} {method}"] = ours
    return out


def main(argv=None) -> int:
    ap = OneLineParser(prog="charts bench integrators", description=__doc__,
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--t", type=float, default=200.0, help="simulated time per run (default 200)")
    ap.add_argument("--rtol", type=float, default=1e-10,
                    help="rtol = atol of DOP853 (default 1e-10)")
    ap.add_argument("--repeat", type=int, default=5, help="repetitions per route (default 5)")
    a = ap.parse_args(argv)
    T, rtol = a.t, a.rtol
    print(f"date: {datetime.date.today().isoformat()}\nmachine: {machine()}")
    print("command: charts bench integrators " + " ".join(sys.argv[1:] if argv is None else argv))
    print(f"# CPU seconds per unit simulated time, t_final = {T:g}, rtol = atol = {rtol:g}, "
          f"RK4 dt = 0.01; median (range) of {a.repeat}; {load()}")
    print(f"{'N':>2} {'route':<22} {'s/unit t':>10} {'range':>21} {'vs scipy':>9} {'steps':>8} "
          f"{'rhs evals':>10} {'err(t=20)':>10}")
    for n in (3, 4, 5):
        s = RotorSystem(n)
        th, u = s.random_state(0)
        tc = min(20.0, T / 2)  # the error is measured at tc < T
        ref = integrate(s, th, u, tc, formulation="ambient", rtol=1e-13, t_eval=[0, tc]).theta[-1]
        rs = routes(s, th, u, T, tc, rtol)
        last = {name: fn() for name, fn in rs.items()}  # warm-up: compile / load caches
        times = {name: [] for name in rs}
        for _ in range(a.repeat):
            for name, fn in rs.items():
                t, last[name] = cpu_time(fn)
                times[name].append(t)
        t_sp = spread(times["scipy solve_ivp DOP853"])[0]
        for name in rs:
            med, lo, hi = spread(times[name])
            steps, nrhs, theta = last[name]
            err = np.abs(theta - ref).max()
            print(f"{n:>2} {name:<22} {med / T:>10.3e} {lo / T:>10.3e}–{hi / T:<10.3e} "
                  f"{med / t_sp:>9.3f} {steps:>8} {nrhs:>10} {err:>10.1e}", flush=True)
    print(load())
    return 0


if __name__ == "__main__":
    sys.exit(main())
