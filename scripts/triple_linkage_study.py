"""The triple linkage's configuration surface along r/R (l = R), a few δ = (l − R)/r and the
joint's mass: χ, area, the curvature's range and the share of area where K > 0, next to the
rotor surface Σ cos θ = 3δ it tends to as r → 0 (docs/triple-linkage.md).

    python scripts/triple_linkage_study.py [--grid 192] [--share-grid 96] [--json FILE]
    python scripts/triple_linkage_study.py --limit      # the r → 0 limit's table only
    python scripts/triple_linkage_study.py --lyapunov [--t-final 10000] [--seed 0]

Each row: ``charts.mechanism.surface_integrals`` on grid² nodes per angle chart (the Gauss
route; the chart route for the rods' configuration-dependent metric), χ the integer nearest
∫K dA / 2π with the residual; K's range from the nodes, each end refined by Nelder–Mead in the
best chart of its node (the node values bound the range from inside); the share of area with
K > 0 on two grids (the indicator converges only at first order in the grid step: the two
values say how far).  Katok's bound √(2π|χ|/A) (χ < 0) bounds the Liouville entropy at unit
speed, not λ₁ itself.

``--lyapunov``: λ₁ at unit speed (``charts.analyses.mechanism_lyapunov.lyapunov_spectrum``,
the mechanism's compiled tangent flow, RK4 dt = 0.01, 20 batches) from one random state per
case, next to mean √(−K) and Katok's bound from the surface integrals (grid 96²).
"""
from __future__ import annotations

import argparse
import json
import time

import numpy as np
from scipy.optimize import minimize

from charts.geometry.surface_quadrature import integrals_from_nodes
from charts.mechanism import rotors, surface_integrals, triple_linkage
from charts.mechanism.surface import curvatures, surface_nodes

#: (label, keyword arguments of triple_linkage, or None for the rotor limit at level 3δ, δ)
ROWS = [("r → 0 (rotors, Σcos θ = 0)", None, 0.0)]
ROWS += [(f"r = {r:g}", dict(r=r), 0.0) for r in (0.025, 0.05, 0.1, 0.2, 0.3, 0.4)]
ROWS += [(f"r → 0 (rotors, Σcos θ = {3 * d:g})", None, d) for d in (-0.2, 0.1, 0.2, 0.5)]
ROWS += [(f"r = 0.1, δ = {d:g}", dict(r=0.1, l=1.0 + 0.1 * d), d) for d in (-0.2, 0.1, 0.2, 0.5)]
ROWS += [(f"r = 0.2, joint mass {m:g}", dict(r=0.2, joint_mass=m), 0.0) for m in (0.1, 0.3, 1.0)]
ROWS += [("r = 0.2, rod mass 0.3", dict(r=0.2, rod_mass=0.3), 0.0)]


def refine(mech, q, sign):
    """The local extreme of sign·K near the node q (Nelder–Mead in q's best chart)."""
    chart = mech.best_chart(q)
    res = minimize(lambda s: -sign * mech.gaussian_curvature(s, chart, near=q), q[list(chart)],
                   method="Nelder-Mead", options=dict(xatol=1e-7, fatol=1e-13))
    return sign * -res.fun


def row(label, params, delta, grid, share_grid):
    t0 = time.perf_counter()
    mech = rotors(3, level=3 * delta) if params is None else triple_linkage(**params)
    route = "gauss" if mech.constant_metric else "chart"
    q, dA = surface_nodes(mech, grid)
    K = curvatures(mech, q, route)
    chi = int(round(np.sum(K * dA) / (2 * np.pi)))     # as surface_integrals reads it
    s = integrals_from_nodes(K, dA, chi, grid, route, mech.parameter_values)
    kmin, kmax = refine(mech, q[np.argmin(K)], -1.0), refine(mech, q[np.argmax(K)], 1.0)
    coarse = surface_integrals(mech, share_grid, route=route)
    return dict(label=label, params=s.params, delta=delta, route=route, grid=grid,
                chi=chi, gauss_bonnet_residual=s.total_curvature / (2 * np.pi) - chi,
                area=s.area, k_min=min(kmin, float(K.min())), k_max=max(kmax, float(K.max())),
                k_min_nodes=float(K.min()), k_max_nodes=float(K.max()),
                positive_share=s.positive_area, positive_share_coarse=coarse.positive_area,
                share_grid=share_grid, mean_sqrt_neg_k=s.mean_sqrt_neg_curvature,
                katok_bound=(float(np.sqrt(2 * np.pi * abs(chi) / s.area)) if chi < 0 else None),
                seconds=time.perf_counter() - t0)


def table(rows) -> str:
    head = ("| case | χ | ∫K dA/2π − χ | area | K min | K max | share K > 0 (grid, coarse) "
            "| √(2π\\|χ\\|/A) |\n|---|---|---|---|---|---|---|---|")
    lines = [head]
    for r in rows:
        kb = "—" if r["katok_bound"] is None else f"{r['katok_bound']:.4f}"
        lines.append(f"| {r['label']} | {r['chi']} | {r['gauss_bonnet_residual']:.1e} | "
                     f"{r['area']:.4f} | {r['k_min']:.4f} | {r['k_max']:.3e} | "
                     f"{100 * r['positive_share']:.3f} % ({100 * r['positive_share_coarse']:.3f} %) "
                     f"| {kb} |")
    return "\n".join(lines)


def limit(grid=64, radii=(0.2, 0.1, 0.05, 0.025), deltas=(0.0, 0.1)) -> str:
    """The r → 0 limit, l = R + rδ: the linkage's area minus the rotor surface's (Σ cos θ =
    3δ), ∫K dA / 2π, and the local log-log slope of |ΔA| between successive r."""
    lines = ["| δ | r | area | area − rotor area | ∫K dA/2π | slope |", "|---|---|---|---|---|---|"]
    for delta in deltas:
        ref = surface_integrals(rotors(3, level=3 * delta), grid)
        lines.append(f"| {delta:g} | 0 (rotors) | {ref.area:.5f} | — | "
                     f"{ref.total_curvature / (2 * np.pi):.6f} | |")
        prev = None
        for r in radii:
            s = surface_integrals(triple_linkage(r, l=1.0 + r * delta), grid, route="gauss")
            d = s.area - ref.area
            slope = "" if prev is None else f"{np.log(abs(prev[1] / d)) / np.log(prev[0] / r):.3f}"
            lines.append(f"| {delta:g} | {r:g} | {s.area:.5f} | {d:+.5f} | "
                         f"{s.total_curvature / (2 * np.pi):.6f} | {slope} |")
            prev = (r, d)
    return "\n".join(lines)


#: (label, keyword arguments of triple_linkage, or None for the rotor limit Σ cos θ = 0)
LYAPUNOV_ROWS = [("r → 0 (rotors, Σcos θ = 0)", None)]
LYAPUNOV_ROWS += [(f"r = {r:g}", dict(r=r)) for r in (0.05, 0.1, 0.2, 0.3, 0.4)]


def lyapunov_rows(t_final=10000.0, seed=0, grid=96, dt=0.01, n_batches=20):
    """λ₁ ± its standard error per case of `LYAPUNOV_ROWS` (unit speed, t_transient 50), with
    the surface's mean √(−K) and Katok's bound √(2π|χ|/A) on grid² nodes per chart."""
    from charts.analyses.mechanism_lyapunov import lyapunov_spectrum

    out = []
    for label, params in LYAPUNOV_ROWS:
        t0 = time.perf_counter()
        mech = rotors(3) if params is None else triple_linkage(**params)
        q, v = mech.random_state(seed)
        res = lyapunov_spectrum(mech, q, v, t_final, dt=dt, n_batches=n_batches, seed=seed)
        s = surface_integrals(mech, grid, route="gauss")
        chi = int(round(s.total_curvature / (2 * np.pi)))
        out.append(dict(label=label, params=mech.parameter_values, lambda1=float(res.exponents[0]),
                        stderr=float(res.stderr[0]), n_batches=n_batches, t_final=t_final, dt=dt,
                        seed=seed, energy_error=res.energy_error, chi=chi,
                        max_curvature=s.max_curvature, mean_sqrt_neg_k=s.mean_sqrt_neg_curvature,
                        katok_bound=float(np.sqrt(2 * np.pi * abs(chi) / s.area)),
                        seconds=time.perf_counter() - t0))
        print(f"{label}: {out[-1]['seconds']:.1f} s", flush=True)
    return out


def lyapunov_table(rows) -> str:
    from scipy.stats import t as student

    lines = ["| case | λ₁ ± s.e. | 95 % interval | mean √(−K) | √(2π\\|χ\\|/A) | max K "
             "| \\|T/T₀ − 1\\| |", "|---|---|---|---|---|---|---|"]
    for r in rows:
        lam, se = r["lambda1"], r["stderr"]
        w = student.ppf(0.975, r["n_batches"] - 1) * se      # batch means: Student's t
        lines.append(f"| {r['label']} | {lam:.4f} ± {se:.4f} | [{lam - w:.4f}, "
                     f"{lam + w:.4f}] | {r['mean_sqrt_neg_k']:.4f} | {r['katok_bound']:.4f} "
                     f"| {r['max_curvature']:.2e} | {r['energy_error']:.0e} |")
    return "\n".join(lines)


def main(argv=None):
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("--grid", type=int, default=192, help="nodes per chart axis (default 192)")
    p.add_argument("--share-grid", type=int, default=96,
                   help="the coarser grid of the share of K > 0 (default 96)")
    p.add_argument("--json", help="also write every number as JSON")
    p.add_argument("--limit", action="store_true",
                   help="only the r → 0 limit's table (area and ∫K against the rotors', 64² "
                   "nodes per chart)")
    p.add_argument("--lyapunov", action="store_true",
                   help="only λ₁ at unit speed for the rotor limit and r = 0.05 … 0.4")
    p.add_argument("--t-final", type=float, default=10000.0,
                   help="--lyapunov's averaging time (default 10000)")
    p.add_argument("--seed", type=int, default=0, help="--lyapunov's random state (default 0)")
    args = p.parse_args(argv)
    if args.lyapunov:
        rows = lyapunov_rows(args.t_final, args.seed)
        print(f"\nλ₁ at unit speed, t = {args.t_final:g} after a transient of 50, dt = 0.01, "
              f"20 batches, seed {args.seed}; surface integrals on 96² nodes per chart\n")
        print(lyapunov_table(rows))
        if args.json:
            with open(args.json, "w", encoding="utf-8") as f:
                json.dump(rows, f, indent=1)
        return
    if args.limit:
        print(limit())
        return
    rows = []
    for label, params, delta in ROWS:
        rows.append(row(label, params, delta, args.grid, args.share_grid))
        print(f"{label}: {rows[-1]['seconds']:.1f} s", flush=True)
    print(f"\ngrid {args.grid}² per angle chart (share of K > 0 also on {args.share_grid}²); "
          "I = R = 1, massless joint and rods unless stated\n")
    print(table(rows))
    if args.json:
        with open(args.json, "w", encoding="utf-8") as f:
            json.dump(rows, f, indent=1)


if __name__ == "__main__":
    main()
