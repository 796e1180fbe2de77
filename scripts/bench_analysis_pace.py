"""CPU time per simulated time unit of each analysis and of `integrate`, as a ratio to the
Lyapunov kernel's (N = 5, unit speed, RK4 dt = 0.01, 3 vectors; median of 3 after a warm-up).

    python scripts/bench_analysis_pace.py [--t 500]
"""
import argparse
import time

import numpy as np

from charts import (RotorSystem, covariant_lyapunov_vectors, curvature_along_trajectory,
                    hyperbolicity_angles, integrate, lyapunov_spectrum)


def cpu_per_time_unit(run, T):
    run(20.0)                                            # compile / load the kernels
    times = []
    for _ in range(3):
        t0 = time.process_time()
        run(T)
        times.append(time.process_time() - t0)
    return float(np.median(times)) / T


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--t", type=float, default=500.0, help="simulated time per repetition")
    T = ap.parse_args().t
    s = RotorSystem(5)
    th, u = s.random_state(seed=1)
    rows = {
        "lyapunov_spectrum, 3 exponents": lambda t: lyapunov_spectrum(s, th, u, t, n_exponents=3),
        "hyperbolicity_angles (forward + backward)":
            lambda t: hyperbolicity_angles(s, th, u, t, t_transient=10.0),
        "covariant_lyapunov_vectors (restricted)":
            lambda t: covariant_lyapunov_vectors(s, th, u, t, t_transient=10.0),
        "curvature_along_trajectory, numerical route":
            lambda t: curvature_along_trajectory(s, th, u, t, exact=False, t_transient=10.0),
        "curvature_along_trajectory, both routes":
            lambda t: curvature_along_trajectory(s, th, u, t, exact=True, t_transient=10.0),
        "integrate, ambient RK4": lambda t: integrate(s, th, u, t, formulation="ambient", method="rk4"),
        "integrate, chart RK4": lambda t: integrate(s, th, u, t, formulation="chart", method="rk4"),
        "integrate, chart DOP853 (rtol 1e-10)": lambda t: integrate(s, th, u, t, formulation="chart"),
    }
    base = None
    print(f"| N = 5, T = {T:g} (the transients of 10 included) | CPU µs per time unit | ratio |")
    print("|---|---:|---:|")
    for name, run in rows.items():
        c = cpu_per_time_unit(run, T)
        base = c if base is None else base
        print(f"| {name} | {c * 1e6:.1f} | {c / base:.2f} |", flush=True)


if __name__ == "__main__":
    main()
