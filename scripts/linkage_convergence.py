"""The linkage's trajectories against those of Σ cos θ = 0 as ε → 0 (docs/linkage.md): from
the same states of `RotorSystem(4)` (`LinkageSystem.from_rotor_state`, ρ = 2ε, massless
disk), max over t ∈ [0, T] of |θ_linkage − θ_RotorSystem(4)| divided by ε, per state and ε.

    python scripts/linkage_convergence.py [--seeds 0 1 ... 9] [--t-final 3]
"""
import argparse

import numpy as np

import charts
from charts import LinkageSystem, linkage_trajectory


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--seeds", type=int, nargs="+", default=list(range(10)))
    ap.add_argument("--t-final", type=float, default=3.0)
    ap.add_argument("--eps", type=float, nargs="+", default=[0.02, 0.01, 0.005])
    a = ap.parse_args()
    R4 = charts.RotorSystem(4)
    T = a.t_final
    print("seed | " + " | ".join(f"error / eps at eps = {e:g}" for e in a.eps))
    worst = []
    for seed in a.seeds:
        th, u = R4.random_state(seed=seed)
        ref = charts.integrate(R4, th, u, T, method="rk4", dt=0.001,
                               t_eval=np.linspace(0, T, int(10 * T) + 1))
        row = []
        for eps in a.eps:
            L = LinkageSystem(eps)
            q, v = L.from_rotor_state(th, u)
            _, S = linkage_trajectory(L, q, v, T, dt=0.001)
            err = np.max(np.abs(np.angle(np.exp(1j * (S[:, :4] - ref.theta)))))
            row.append(err / eps)
        worst.append(row[-1])
        print(f"{seed} | " + " | ".join(f"{x:.2f}" for x in row), flush=True)
    print(f"range at eps = {a.eps[-1]:g} over {len(worst)} states: {min(worst):.2f} eps to "
          f"{max(worst):.2f} eps (median {np.median(worst):.2f} eps)")


if __name__ == "__main__":
    main()
