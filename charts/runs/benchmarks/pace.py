"""Every analysis at the Lyapunov kernel's pace: CPU time per simulated time unit of each
analysis and of ``integrate``, as a ratio to ``lyapunov_spectrum``'s, measured in one run.

    python scripts/bench_analysis_pace.py [--t 500] [--n 5]

Task: N rotors (default 5), equal masses, unit speed, RK4 dt = 0.01, the state
``RotorSystem(n).random_state(seed=1)``; the Lyapunov kernel with N − 2 vectors (3 for
N = 5, the number of vectors of the angle test and of the curvature frames), transients of
10 inside every other row.  Each row: a warm-up run (compilation, cache load), then the
median of ``repeats`` runs of T time units, CPU time (``time.process_time``: the machine is
shared, wall time would measure the other jobs).  The rows take turns, so a change of load
touches every row alike.
"""
from __future__ import annotations

import time

import numpy as np

from ...analyses.covariant import covariant_lyapunov_vectors
from ...analyses.curvature import curvature_along_trajectory
from ...analyses.hyperbolicity import hyperbolicity_angles
from ...analyses.lyapunov import lyapunov_spectrum
from ...geometry.system import RotorSystem
from ...solvers.integrate import integrate

__all__ = ["analysis_pace", "pace_rows", "format_rows", "TRANSIENT"]

#: Transient of every analysis row (time units, inside the cost per time unit).
TRANSIENT = 10.0
#: The row every ratio is taken against.
BASE = "lyapunov_spectrum"


def pace_rows(n: int = 5):
    """``{name: run(T)}`` for the rows of the table (the first is the base)."""
    s = RotorSystem(n)
    th, u = s.random_state(seed=1)
    tr = TRANSIENT
    return {
        f"{BASE}, {n - 2} exponents": lambda t: lyapunov_spectrum(s, th, u, t, n_exponents=n - 2),
        "hyperbolicity_angles (forward + backward)":
            lambda t: hyperbolicity_angles(s, th, u, t, t_transient=tr),
        "covariant_lyapunov_vectors (restricted)":
            lambda t: covariant_lyapunov_vectors(s, th, u, t, t_transient=tr),
        "curvature_along_trajectory, numerical route":
            lambda t: curvature_along_trajectory(s, th, u, t, exact=False, t_transient=tr),
        "curvature_along_trajectory, both routes":
            lambda t: curvature_along_trajectory(s, th, u, t, exact=True, t_transient=tr),
        "integrate, ambient RK4": lambda t: integrate(s, th, u, t, formulation="ambient",
                                                      method="rk4"),
        "integrate, chart RK4": lambda t: integrate(s, th, u, t, formulation="chart", method="rk4"),
        "integrate, chart DOP853 (rtol 1e-10)": lambda t: integrate(s, th, u, t, formulation="chart"),
    }


def analysis_pace(t: float = 500.0, *, n: int = 5, repeats: int = 3, progress=None):
    """Rows ``(name, CPU µs per time unit, ratio to the Lyapunov kernel)``, measured in one
    run (see the module doc); ``progress(name)`` is called before each row's warm-up."""
    rows = pace_rows(n)
    times = {name: [] for name in rows}
    for name, run in rows.items():
        if progress is not None:
            progress(name)
        run(20.0)                                         # compile / load the kernels
    for _ in range(repeats):                              # the rows take turns
        for name, run in rows.items():
            c0 = time.process_time()
            run(t)
            times[name].append(time.process_time() - c0)
    cost = {name: float(np.median(v)) / t for name, v in times.items()}
    base = next(iter(cost.values()))
    return [(name, c * 1e6, c / base) for name, c in cost.items()]


def format_rows(rows, t: float, n: int = 5) -> str:
    """The rows as the Markdown table of docs/performance.md."""
    lines = [f"| N = {n}, T = {t:g} (the transients of {TRANSIENT:g} included) "
             "| CPU µs per time unit | ratio |", "|---|---:|---:|"]
    lines += [f"| {name} | {us:.1f} | {ratio:.2f} |" for name, us, ratio in rows]
    return "\n".join(lines)
