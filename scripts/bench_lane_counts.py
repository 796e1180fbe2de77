"""The lane kernel against the one-trajectory kernel for small lane counts: where lanes start
to pay (``charts.analyses.lyapunov_members.MIN_LANES``).

    python scripts/bench_lane_counts.py              # N = 5, L = 2 3 4 5 6 8 16
    python scripts/bench_lane_counts.py --n 4 --lanes 3 4 8

Per L: L `TangentFlow` s of N = n (3 exponents, the settings of `lyapunov_spectrum`) advanced
20 000 steps one after the other, and the same L in one `LaneFlows`, taking turns, 5 paired
repetitions; CPU ns per step of one trajectory, their ratio, and whether every lane ended
with the bits of its single flow.
"""
from __future__ import annotations

import argparse
import time
from dataclasses import replace

import numpy as np

import charts
from charts.analyses.lyapunov import lyapunov_flow, lyapunov_settings
from charts.solvers.lanes import LaneFlows


def measure(n: int, L: int, steps: int = 20000, repeat: int = 5):
    system = charts.RotorSystem(n)
    cfg = lyapunov_settings(system, 100.0, seed=0, n_exponents=min(3, n - 1))

    def flows():
        return [lyapunov_flow(system, *system.random_state(seed=s), replace(cfg, seed=s))
                for s in range(L)]

    LaneFlows(flows()).advance(10)               # compile / load both kernels
    flows()[0].advance(10)
    single, lanes = [], []
    for _ in range(repeat):
        fs = flows()
        t = time.process_time()
        for f in fs:
            f.advance(steps)
        single.append((time.process_time() - t) / (steps * L) * 1e9)
        lf = LaneFlows(flows())
        t = time.process_time()
        lf.advance(steps)
        lanes.append((time.process_time() - t) / (steps * L) * 1e9)
    same = all(np.array_equal(fs[l].Z.reshape(-1), lf.lane(l).reshape(-1)) for l in range(L))
    ratios = np.array(single) / np.array(lanes)
    return np.median(single), np.median(lanes), np.median(ratios), ratios.min(), ratios.max(), same


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--n", type=int, default=5)
    ap.add_argument("--lanes", type=int, nargs="+", default=[2, 3, 4, 5, 6, 8, 16])
    a = ap.parse_args(argv)
    print("| lanes | single ns/step | lanes ns/lane-step | ratio (paired median, range) | identical |")
    print("|---:|---:|---:|---|---|")
    for L in a.lanes:
        s, l, r, lo, hi, same = measure(a.n, L)
        print(f"| {L} | {s:.0f} | {l:.0f} | {r:.2f} ({lo:.2f}–{hi:.2f}) | {'yes' if same else 'NO'} |")


if __name__ == "__main__":
    main()
