"""The orientation of the splitting E_u ⊕ E_cs along orbits (docs/families-study.md): the sign of
the oriented volume V (``charts.analyses.tangency.oriented_volume``) at every sample of a
CLV run, its smallest |V| and the smallest angle; then the closest passage of each orbit
resolved at every step (`closest_passage`).

    python scripts/splitting_orientation.py [--t-final 3000] [--resolve]
"""
import argparse

import numpy as np

from charts import RotorSystem, covariant_lyapunov_vectors
from charts.analyses.tangency import closest_passage, oriented_volume

CASES = [("N = 4, c = 0.5", dict(n=4, level=0.5), 2),
         ("N = 4, c = 0 (the paper's)", dict(n=4), 1),
         ("N = 5, c = 0", dict(n=5), 1),
         ("N = 6, masses 1, 2, 1, 1.5, 1, 0.7", dict(n=6, masses=[1, 2, 1, 1.5, 1, 0.7]), 3)]


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--t-final", type=float, default=3000.0)
    ap.add_argument("--resolve", action="store_true", help="resolve each closest passage")
    a = ap.parse_args()
    print("| system | seed | samples | signs of V | min abs V | min phi (rad) | max abs V / sin phi |")
    print("|---|---|---|---|---|---|---|")
    for name, kw, seed in CASES:
        s = RotorSystem(**kw)
        th, u = s.random_state(seed=seed)
        c = covariant_lyapunov_vectors(s, th, u, a.t_final, keep_vectors=True)
        V = oriented_volume(c.vectors, c.params["n_unstable"], c.states, s.weights)
        print(f"| {name} | {seed} | {V.size} | {' '.join(f'{x:+.0f}' for x in np.unique(np.sign(V)))} "
              f"| {np.abs(V).min():.1e} | {np.nanmin(c.phi):.1e} | "
              f"{np.nanmax(np.abs(V) / np.sin(c.phi)):.3f} |", flush=True)
    if a.resolve:
        for name, kw, seed in CASES:
            s = RotorSystem(**kw)
            print(f"\n{name}, seed {seed}:")
            print(closest_passage(s, *s.random_state(seed=seed), a.t_final).summary(), flush=True)


if __name__ == "__main__":
    main()
