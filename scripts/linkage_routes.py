"""The linkage on the mechanism's route against the hand-written flow it replaced
(docs/linkage.md, "The generic route against the hand-written one").

    python scripts/linkage_routes.py cost         # one linkage_run's CPU time (≈ 15 s)
    python scripts/linkage_routes.py single       # one state: exponents, trajectory, angles, cones
    python scripts/linkage_routes.py seeds        # λ₁, λ₂ over seeds 1–8 at ε = 0.2, 0.05 (≈ 1 min)

Each prints this tree's numbers; the hand-written route's are the same command at the commit
before the move:

    git archive 1aa132a | tar -x -C /tmp/old && PYTHONPATH=/tmp/old python scripts/linkage_routes.py cost

``cost``: ε = 0.05, the state of seed 1, t_final 500 after the default transient of 50,
dt = 0.01, two exponents, with and without the curvature samples; compiled first, then the
best of three (``time.process_time``).  ``single``: linkage_run at ε = 0.05 and 0.2 from
seed 1 (t = 500), linkage_trajectory from seed 3 at ε = 0.1 (t = 1, 10), linkage_angles at
ε = 0.05 from seed 0 (t = 200, transient 50, every 0.5), cone_distance at ε = 0.01.
``seeds``: linkage_run from seeds 1–8, t = 1000, no curvature; mean ± standard error of the
mean over the seeds.
"""
from __future__ import annotations

import argparse
import time

import numpy as np

import charts
from charts.analyses.linkage import CONE_POINTS, cone_distance
from charts.analyses.linkage_angles import linkage_angles


def cost():
    L = charts.LinkageSystem(0.05)
    q, v = L.random_state(seed=1)
    charts.linkage_run(L, q, v, 2.0, t_transient=0.0, n_batches=2)        # compile
    for curvature in (True, False):
        best = []
        for _ in range(3):
            t0 = time.process_time()
            charts.linkage_run(L, q, v, 500.0, seed=0, curvature=curvature)
            best.append(time.process_time() - t0)
        print(f"curvature={curvature}: {min(best):.2f} s CPU (best of 3)")


def single():
    for eps in (0.05, 0.2):
        L = charts.LinkageSystem(eps)
        r = charts.linkage_run(L, *L.random_state(seed=1), 500.0, seed=0)
        print(f"linkage_run eps={eps}: λ = {r.exponents.round(4).tolist()} ± "
              f"{r.stderr.round(4).tolist()}, K > 0 {r.fraction_positive().round(3).tolist()}")
    L = charts.LinkageSystem(0.1)
    q, v = L.random_state(seed=3)
    for T in (1.0, 10.0):
        _, S = charts.linkage_trajectory(L, q, v, T, sample_every=T)
        print(f"linkage_trajectory t={T:g}: {S[-1].tolist()}")
    L = charts.LinkageSystem(0.05)
    a = linkage_angles(L, *L.random_state(seed=0), 200.0, t_transient=50.0, sample_every=0.5)
    s = a.statistics()
    print(f"linkage_angles: min {s['min']:.4f}, p01 {s['p01']:.4f}, median {s['median']:.4f}, "
          f"n {s['n']}; forward {a.forward_exponents.round(4).tolist()}, backward "
          f"{a.backward_exponents.round(4).tolist()}")
    L = charts.LinkageSystem(0.01)
    print("cone_distance:", [f"{cone_distance(L, p)[0]:.12g}" for p in CONE_POINTS])


def seeds():
    for eps in (0.2, 0.05):
        E = []
        for s in range(1, 9):
            L = charts.LinkageSystem(eps)
            E.append(charts.linkage_run(L, *L.random_state(seed=s), 1000.0, seed=s,
                                        curvature=False).exponents)
        E = np.array(E)
        print(f"eps={eps}: λ = {E.mean(0).round(4).tolist()} ± "
              f"{(E.std(0, ddof=1) / np.sqrt(len(E))).round(4).tolist()} (8 seeds, t = 1000)")


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("what", choices=("cost", "single", "seeds"))
    {"cost": cost, "single": single, "seeds": seeds}[ap.parse_args(argv).what]()


if __name__ == "__main__":
    main()
