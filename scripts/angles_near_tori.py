"""Do the small restricted angles of the paper's N = 4 manifold come from passages near its
flat, totally geodesic antipodal tori (docs/hyperbolicity.md)?  For one trajectory: the
angle test, the state at every sample (the forward pass's own state: `TangentFlow` without
vectors, same steps and projections), the distance to the nearest of the three tori
{θ_j = θ_i + π, θ_l = θ_k + π} over the three pairings, and the angles binned by it.

    python scripts/angles_near_tori.py [--seed 1] [--t-final 2000]
"""
import argparse

import numpy as np

import charts
from charts.solvers.tangent import TangentFlow

PAIRINGS = [((0, 1), (2, 3)), ((0, 2), (1, 3)), ((0, 3), (1, 2))]


def wrap(x):
    return np.angle(np.exp(1j * x))


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--seed", type=int, default=1)
    ap.add_argument("--t-final", type=float, default=2000.0)
    a = ap.parse_args()
    s = charts.RotorSystem(4)
    th, u = s.random_state(seed=a.seed)
    tr, dt = 50.0, 0.01
    res = charts.hyperbolicity_angles(s, th, u, a.t_final, t_transient=tr, dt=dt)
    sample = int(round(res.params["sample_every"] / dt))
    f = TangentFlow(s, th, u, 0, dt=dt, project_every=int(round(res.params["project_every"] / dt)))
    f.advance(int(round(tr / dt)))
    Y = np.empty((res.t.size, 8))
    Y[0] = f.y
    for q in range(1, res.t.size):
        f.advance(sample)
        Y[q] = f.y
    d = np.min([np.hypot(wrap(Y[:, j] - Y[:, i] - np.pi), wrap(Y[:, m] - Y[:, k] - np.pi))
                for (i, j), (k, m) in PAIRINGS], axis=0)
    phi = res.phi_restricted
    print(f"N = 4, seed {a.seed}, T = {a.t_final:g}: {phi.size} samples, min angle {phi.min():.3g}")
    print("distance to the nearest torus | samples | fraction of angles < 0.05 | median angle")
    for lo, hi in [(0, 0.05), (0.05, 0.1), (0.1, 0.2), (0.2, 0.5), (0.5, 1), (1, 5)]:
        m = (d >= lo) & (d < hi)
        print(f"[{lo}, {hi}) | {m.sum()} | {np.mean(phi[m] < 0.05):.4f} | {np.median(phi[m]):.3f}")
    small = phi < 0.05
    near = f"{np.median(d[small]):.3f}" if small.any() else "— (none)"
    print(f"median distance: all samples {np.median(d):.3f}, angles < 0.05 {near}")


if __name__ == "__main__":
    main()
