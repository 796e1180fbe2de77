"""The smallest crank ε the linkage computes with: rotor angles at t = 5 against the ε → 0 limit.

    python scripts/linkage_eps_floor.py            # ε = 1e-3 … 1e-7, about 30 s

The linkage of the Appendix tends to Σ cos θᵢ = 0 as ε → 0 (ρ = 2ε, massless disk), so the
rotor angles of a linkage trajectory started at `LinkageSystem.from_rotor_state` of a rotor
state differ from the rotor system's trajectory by O(ε).  The table prints that difference
at t = 5 and its ratio to ε: constant while the computation holds its digits, then a jump
where the kinetic projection's KKT matrix (entries of order ε²) drops under its pivot
threshold.  `charts.mechanism.linkage.LENGTH_MIN` keeps a factor four above the jump; ε
below it is refused, so the last rows are computed by building the system past the check.
"""
from __future__ import annotations

import argparse

import numpy as np

import charts
from charts.mechanism import linkage as geometry


def unchecked(eps):
    """A `LinkageSystem` at ε below the floor (the measurement's own business only)."""
    L = charts.LinkageSystem(0.01)
    L.eps, L.rho = eps, 2.0 * eps
    L.par = L.param_values = np.array([eps, 2.0 * eps, 1.0, L.disk_mass, L.disk_inertia])
    return L


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--eps", type=float, nargs="+",
                    default=[1e-3, 1e-4, 1e-5, 1e-6, 5e-7, 3e-7, 2e-7, 1e-7])
    ap.add_argument("--seed", type=int, default=3)
    ap.add_argument("--dt", type=float, default=1e-3)
    a = ap.parse_args(argv)
    S = charts.RotorSystem(4)
    theta, u = S.random_state(seed=a.seed)
    rotor = charts.integrate(S, theta, u, 5.0, dt=a.dt, method="rk4", formulation="ambient")
    print(f"floor LENGTH_MIN = {geometry.LENGTH_MIN:g}; N = 4 rotor state seed {a.seed}, "
          f"RK4 dt = {a.dt:g}, t = 5")
    print(f"{'eps':>8} {'max|Δθ(5)|':>12} {'/ eps':>10}")
    for eps in a.eps:
        L = charts.LinkageSystem(eps) if eps >= geometry.LENGTH_MIN else unchecked(eps)
        q, v = L.from_rotor_state(theta, u)
        _, states = charts.linkage_trajectory(L, q, v, 5.0, dt=a.dt, sample_every=5.0)
        d = float(np.max(np.abs(np.angle(np.exp(1j * (states[-1, :4] - rotor.theta[-1]))))))
        print(f"{eps:8.0e} {d:12.2e} {d / eps:10.2f}" + ("   (below the floor)"
                                                         if eps < geometry.LENGTH_MIN else ""))


if __name__ == "__main__":
    main()
