"""Cost per unit of simulated time of charts.solvers.integrate, against scipy.integrate.solve_ivp.

For N = 3, 4, 5 (unit masses, unit speed, seed 0) every formulation × method is timed on
the same geodesic over ``--t`` time units, in one run, and reported as seconds per unit time
and as a ratio to ``solve_ivp(method="DOP853")`` at the same rtol/atol on eq (8).  The SciPy
right-hand side calls the numba-compiled eq (8) kernel (``charts.flows.ambient.flow_rhs``), so the
ratio measures the integrator, not a slow Python right-hand side.  RK4 uses the paper's
dt = 0.01.  Each entry is the best of ``--repeat`` runs after a warm-up (compilation).
The last column is max|θ − θ_ref| at t = 20 (before the chaos erases the digits),
θ_ref from the ambient DOP853 at rtol 1e-13.

    python scripts/bench_integrators.py [--t 200] [--rtol 1e-10] [--repeat 3]
"""
from __future__ import annotations

import argparse
import time

import numpy as np
from scipy.integrate import solve_ivp

from charts import RotorSystem, integrate
from charts.flows.ambient import flow_rhs


def best_time(fn, repeat):
    fn()  # warm-up: compile / load caches
    best = np.inf
    out = None
    for _ in range(repeat):
        t0 = time.perf_counter()
        out = fn()
        best = min(best, time.perf_counter() - t0)
    return best, out


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--t", type=float, default=200.0, help="simulated time per run")
    ap.add_argument("--rtol", type=float, default=1e-10)
    ap.add_argument("--repeat", type=int, default=3)
    a = ap.parse_args(argv)
    T, rtol = a.t, a.rtol
    print(f"# cost per unit simulated time, t_final = {T:g}, rtol = atol = {rtol:g}, RK4 dt = 0.01")
    print(f"{'N':>2} {'route':<22} {'s/unit t':>10} {'vs scipy':>9} {'steps':>8} {'rhs evals':>10} "
          f"{'err(t=20)':>12}")
    for n in (3, 4, 5):
        s = RotorSystem(n)
        th, u = s.random_state(0)
        tc = min(20.0, T / 2)  # the error is measured at tc < T
        ref = integrate(s, th, u, tc, formulation="ambient", rtol=1e-13, t_eval=[0, tc]).theta[-1]
        minv = s.minv
        dy = np.empty(2 * n)

        def f(t, y):
            flow_rhs(y, minv, dy)
            return dy.copy()

        y0 = np.concatenate([th, u])
        t_sp, sol = best_time(lambda: solve_ivp(f, (0, T), y0, method="DOP853", rtol=rtol,
                                                atol=rtol, t_eval=[tc, T]), a.repeat)
        err = np.abs(sol.y[:n, 0] - ref).max()
        nsteps = sol.nfev // 12  # t_eval hides the step grid; DOP853 uses 12 evaluations per step
        print(f"{n:>2} {'scipy solve_ivp DOP853':<22} {t_sp / T:>10.3e} {1.0:>9.3f} "
              f"{nsteps:>8} {sol.nfev:>10} {err:>12.1e}")
        for form in ("ambient", "chart"):
            for method in ("dop853", "rk4"):
                kw = dict(rtol=rtol, atol=rtol) if method == "dop853" else dict(dt=0.01)
                t_us, r = best_time(lambda: integrate(s, th, u, T, formulation=form, method=method,
                                                      t_eval=[0, tc, T], **kw), a.repeat)
                err = np.abs(r.theta[1] - ref).max()
                print(f"{n:>2} {form + ' ' + method:<22} {t_us / T:>10.3e} {t_us / t_sp:>9.3f} "
                      f"{r.n_steps:>8} {r.n_rhs:>10} {err:>12.1e}")


if __name__ == "__main__":
    main()
