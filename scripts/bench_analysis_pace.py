"""CPU time per simulated time unit of each analysis and of `integrate`, as a ratio to the
Lyapunov kernel's (``charts.runs.benchmarks.pace``; N = 5, unit speed, RK4 dt = 0.01,
3 vectors; median of 3 after a warm-up, the rows taking turns).

    python scripts/bench_analysis_pace.py [--t 500] [--n 5] [--repeats 3]
"""
import argparse
import os
import sys

from charts.runs.benchmarks.pace import analysis_pace, format_rows


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--t", type=float, default=500.0, help="simulated time per repetition")
    ap.add_argument("--n", type=int, default=5, help="number of rotors")
    ap.add_argument("--repeats", type=int, default=3, help="repetitions per row (median)")
    a = ap.parse_args()
    rows = analysis_pace(a.t, n=a.n, repeats=a.repeats,
                         progress=lambda name: print(f"warm-up: {name}", file=sys.stderr))
    print(format_rows(rows, a.t, a.n))
    print(f"load average: {' '.join(f'{x:.2f}' for x in os.getloadavg())}")


if __name__ == "__main__":
    main()
