"""How far a seed's linkage state lies from the rotor state of the same seed (docs/linkage.md):
``LinkageSystem(ε).random_state(seed=s)`` against ``RotorSystem(4).random_state(seed=s)``,
max over the four angles of |Δθᵢ| divided by ε (per seed and ε, and its range over the seeds),
the part of Δθ along the normal of Σ cos θ = 0, and max |Δθ̇ᵢ| of the velocities (speed 1).

    python scripts/linkage_seeds.py [--seeds 0 1 ... 19] [--eps 0.1 0.01 0.001 0.0001]
"""
import argparse

import numpy as np

import charts
from charts import LinkageSystem


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--seeds", type=int, nargs="+", default=list(range(20)))
    ap.add_argument("--eps", type=float, nargs="+", default=[0.1, 0.01, 0.001, 0.0001])
    a = ap.parse_args()
    R4 = charts.RotorSystem(4)
    rotor = [R4.random_state(seed=s, speed=1.0) for s in a.seeds]
    table = {}
    print("eps | max|Δθ|/ε: min (seed) | mean | max (seed) | |Δθ·n|/|Δθ| min | max|Δθ̇|: min | max")
    for eps in a.eps:
        L = LinkageSystem(eps)
        c, normal, dv = [], [], []
        for (th, u), s in zip(rotor, a.seeds):
            q, v = L.random_state(seed=s, speed=1.0)
            d = np.angle(np.exp(1j * (q[:4] - th)))
            n = np.sin(th) / np.linalg.norm(np.sin(th))      # normal of Σ cos θ = 0
            c.append(np.max(np.abs(d)) / eps)
            normal.append(abs(d @ n) / np.linalg.norm(d))
            dv.append(np.max(np.abs(v[:4] - u)))
        c = np.array(c)
        table[eps] = c
        lo, hi = int(np.argmin(c)), int(np.argmax(c))
        print(f"{eps:g} | {c[lo]:.3f} ({a.seeds[lo]}) | {c.mean():.3f} | {c[hi]:.3f} "
              f"({a.seeds[hi]}) | {min(normal):.3f} | {min(dv):.3f} | {max(dv):.3f}", flush=True)
    print("\nmax|Δθ|/ε per seed:")
    print("seed | " + " | ".join(f"ε = {e:g}" for e in a.eps))
    for i, s in enumerate(a.seeds):
        print(f"{s} | " + " | ".join(f"{table[e][i]:.3f}" for e in a.eps))


if __name__ == "__main__":
    main()
