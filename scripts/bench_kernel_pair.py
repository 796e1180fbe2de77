"""CPU seconds of the warm Lyapunov kernel and of the angle test, for paired before/after
comparisons: run it alternately with two checkouts' interpreters (each with its own warm
numba cache) and compare the minima.

    python scripts/bench_kernel_pair.py LABEL [--repeats 5] [--more]

Task: N = 5, unit speed, ``RotorSystem(5).random_state(seed=1)``; ``lyapunov_spectrum`` over
T = 3000 without transient and ``hyperbolicity_angles`` over T = 1000 after 10 (both RK4,
dt = 0.01); each ``repeats`` times after a warm-up, CPU time (``time.process_time``).
``--more`` adds ``covariant_lyapunov_vectors`` at N = 5 over T = 500 after 10 and
``curvature_along_trajectory`` at N = 6 over T = 500 (both routes: the generated Riemann
tensor of the exact one)."""
import argparse
import time

import numpy as np

import charts


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("label", help="printed first (e.g. the commit)")
    ap.add_argument("--repeats", type=int, default=5)
    ap.add_argument("--more", action="store_true", help="also the CLVs and the curvature")
    a = ap.parse_args()
    s = charts.RotorSystem(5)
    th, u = s.random_state(seed=1)
    charts.lyapunov_spectrum(s, th, u, 10.0, t_transient=1.0)       # compile / load
    charts.hyperbolicity_angles(s, th, u, 10.0, t_transient=1.0)
    lyap, angles = [], []
    for _ in range(a.repeats):
        t = time.process_time()
        charts.lyapunov_spectrum(s, th, u, 3000.0, t_transient=0.0)
        lyap.append(time.process_time() - t)
        t = time.process_time()
        charts.hyperbolicity_angles(s, th, u, 1000.0, t_transient=10.0)
        angles.append(time.process_time() - t)
    print(f"{a.label}: lyapunov_spectrum min {min(lyap):.3f} median {np.median(lyap):.3f} s | "
          f"hyperbolicity_angles min {min(angles):.3f} median {np.median(angles):.3f} s")
    if a.more:
        s6 = charts.RotorSystem(6)
        th6, u6 = s6.random_state(seed=1)
        runs = {"covariant_lyapunov_vectors": lambda: charts.covariant_lyapunov_vectors(
                    s, th, u, 500.0, t_transient=10.0),
                "curvature_along_trajectory N=6": lambda: charts.curvature_along_trajectory(
                    s6, th6, u6, 500.0, t_transient=0.0)}
        for name, run in runs.items():
            run()                                                    # compile / load
            times = []
            for _ in range(a.repeats):
                t = time.process_time()
                run()
                times.append(time.process_time() - t)
            print(f"{a.label}: {name} min {min(times):.4f} median {np.median(times):.4f} s")


if __name__ == "__main__":
    main()
