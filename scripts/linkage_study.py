#!/usr/bin/env python
"""The linkage of the Appendix against its first-order limit Σ cos θ = 0, for a range of ε
(ρ = 2ε, massless disk): Lyapunov exponents, fraction of positive sectional curvature, the
distance of the manifold from the six cone points and the curvature at the two that stay on
it.  Writes a Markdown table to stdout and figures into docs/figures/linkage/.

    python scripts/linkage_study.py                     # the study of docs/linkage.md
    python scripts/linkage_study.py --quick             # a smoke run (short times)
    python scripts/linkage_study.py --angles            # only the angle (tangency) study, added
                                                        # to study.json
"""
from __future__ import annotations

import argparse
import json
import sys
import time
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parent.parent


def cone_table(eps_list):
    from charts.analyses.linkage import CONE_POINTS, cone_distance, gauss_curvature
    from charts.mechanism.linkage import LinkageSystem

    rows = []
    for eps in eps_list:
        L = LinkageSystem(eps)
        d = [cone_distance(L, p, 1) for p in CONE_POINTS]
        on = [i for i, (di, _) in enumerate(d) if di < 1e-6]
        q = d[on[0]][1] if on else None
        Kmin = np.nan
        if q is not None:  # sectional curvatures of the coordinate planes of an orthonormal basis
            V = np.linalg.svd(L.jacobian(q))[2][4:]
            B = []
            for x in V:
                x = x - sum(np.dot(x[:4], e[:4]) * e for e in B)
                B.append(x / np.linalg.norm(x[:4]))
            Kmin = min(gauss_curvature(L, q, B[i], B[j]) for i in range(3) for j in range(i + 1, 3))
        rows.append(dict(eps=eps, distances=[di for di, _ in d], on=on, K_min_on_cone=Kmin))
    return rows


def dynamics(eps_list, seeds, t_final, t_transient):
    import charts
    from charts.analyses.linkage import linkage_run
    from charts.analyses.statistics import standard_error
    from charts.mechanism.linkage import LinkageSystem

    out = []
    R4 = charts.RotorSystem(4)
    for eps in [None] + list(eps_list):
        E, P, S2 = [], [], []
        t0 = time.perf_counter()
        for s in seeds:
            if eps is None:  # the first-order limit: the library's RotorSystem(4)
                th, u = R4.random_state(seed=s, speed=1.0)
                ly = charts.lyapunov_spectrum(R4, th, u, t_final, t_transient=t_transient, seed=s)
                cu = charts.curvature_along_trajectory(R4, th, u, t_final, sample_every=1.0,
                                                       t_transient=t_transient, seed=s)
                E.append(ly.exponents)
                P.append(cu.fraction_positive("exact"))
                S2.append(np.min(np.sum(np.sin(cu.theta) ** 2, axis=1)))
            else:
                L = LinkageSystem(eps)
                q, v = L.random_state(seed=s, speed=1.0)
                r = linkage_run(L, q, v, t_final, t_transient=t_transient, seed=s)
                E.append(r.exponents)
                P.append(r.fraction_positive())
                S2.append(r.min_sin2)
        E, P = np.array(E), np.array(P)
        out.append(dict(eps=eps, exponents=E.mean(0).tolist(), stderr=standard_error(E).tolist(),
                        positive=P.mean(0).tolist(), positive_se=standard_error(P).tolist(),
                        min_sin2=float(min(S2)), seconds=time.perf_counter() - t0))
        print(json.dumps(out[-1]), file=sys.stderr, flush=True)
    return out


def angles(eps_list, seeds, t_final):
    """Angles between E_u and E_cs (section 4), restricted variant, against RotorSystem(4)."""
    import charts
    from charts.analyses.linkage_angles import linkage_angles
    from charts.mechanism.linkage import LinkageSystem

    out = []
    R4 = charts.RotorSystem(4)
    for eps in [None] + list(eps_list):
        phi = []
        for s in seeds:
            if eps is None:
                th, u = R4.random_state(seed=s, speed=1.0)
                phi.append(charts.hyperbolicity_angles(R4, th, u, t_final, t_transient=50.0,
                                                       seed=s).phi_restricted)
            else:
                L = LinkageSystem(eps)
                q, v = L.random_state(seed=s, speed=1.0)
                phi.append(linkage_angles(L, q, v, t_final, seed=s).phi)
        st = charts.angle_statistics(np.concatenate(phi))
        out.append(dict(eps=eps, **st))
        print(json.dumps(out[-1]), file=sys.stderr, flush=True)
    return out


def figure(dyn, cones, path):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    ref = dyn[0]
    rows = dyn[1:]
    eps = np.array([r["eps"] for r in rows])
    fig, ax = plt.subplots(1, 3, figsize=(13, 4))
    for i, c in enumerate(["C0", "C1"]):
        e = np.array([r["exponents"][i] for r in rows])
        s = np.array([r["stderr"][i] for r in rows])
        ax[0].errorbar(eps, e, 2 * s, fmt="o-", color=c, capsize=3, label=f"linkage λ{i + 1}")
        ax[0].axhspan(ref["exponents"][i] - 2 * ref["stderr"][i], ref["exponents"][i] + 2 * ref["stderr"][i],
                      color=c, alpha=0.2, label=f"Σcos θ = 0: λ{i + 1} ± 2se")
        p = np.array([r["positive"][i] for r in rows])
        ps = np.array([r["positive_se"][i] for r in rows])
        ax[1].errorbar(eps, p, 2 * ps, fmt="o-", color=c, capsize=3, label=f"K(v, e{i + 1}) > 0")
        ax[1].axhline(ref["positive"][i], color=c, ls="--", label=f"Σcos θ = 0, K(v, e{i + 1})")
    ax[0].set(xscale="log", xlabel="ε (ρ = 2ε)", ylabel="Lyapunov exponent (1/time, unit speed)",
              title="Lyapunov exponents vs ε")
    ax[1].set(xscale="log", xlabel="ε (ρ = 2ε)", ylabel="fraction of samples",
              title="Positive sectional curvature")
    ce = np.array([c["eps"] for c in cones])
    dmin = np.array([min(d for d in c["distances"] if d > 1e-6) for c in cones])
    Kc = -np.array([c["K_min_on_cone"] for c in cones])
    ax[2].loglog(ce, dmin, "o-", label="distance to the 4 avoided cone points")
    ax[2].loglog(ce, Kc, "s-", label="−min K at the 2 cone points on M")
    ax[2].loglog(ce, 2 * ce, "k:", label="2ε")
    ax[2].set(xlabel="ε (ρ = 2ε)", ylabel="distance (rad) / |K| (1/rad²)", title="Cone points")
    for a in ax:
        a.legend(fontsize=7)
        a.grid(alpha=0.3)
    fig.tight_layout()
    fig.savefig(path, dpi=120)


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--quick", action="store_true")
    ap.add_argument("--angles", action="store_true", help="run only the angle study")
    ap.add_argument("--out", type=Path, default=ROOT / "docs" / "figures" / "linkage")
    args = ap.parse_args(argv)
    eps_list = [0.2, 0.1, 0.05, 0.02, 0.01]
    seeds = range(2) if args.quick else range(8)
    t_final = 200.0 if args.quick else 4000.0
    if args.angles:
        seeds = seeds[:4]
        ang = angles([0.2, 0.05, 0.01], seeds, 100.0 if args.quick else 1000.0)
        path = args.out / "study.json"
        data = json.loads(path.read_text()) if path.exists() else {}
        data["angles"] = dict(rows=ang, seeds=len(seeds), t_final=100.0 if args.quick else 1000.0)
        args.out.mkdir(parents=True, exist_ok=True)
        path.write_text(json.dumps(data, indent=1))
        print("| ε | min φ | 0.1 % quantile | 1 % quantile | median | fraction φ < 0.05 | samples |")
        print("|---|---|---|---|---|---|---|")
        for r in ang:
            name = "Σcos θ = 0 (RotorSystem(4))" if r["eps"] is None else f"{r['eps']:g}"
            print(f"| {name} | {r['min']:.4f} | {r['p001']:.4f} | {r['p01']:.4f} | "
                  f"{r['median']:.4f} | {r['frac_small']:.4f} | {r['n']} |")
        return 0
    cones = cone_table([0.2, 0.1, 0.05, 0.02, 0.01, 0.005, 0.002])
    dyn = dynamics(eps_list, seeds, t_final, 50.0)
    args.out.mkdir(parents=True, exist_ok=True)
    (args.out / "study.json").write_text(json.dumps(dict(cones=cones, dynamics=dyn,
                                                         seeds=len(seeds), t_final=t_final), indent=1))
    figure(dyn, cones, args.out / "linkage_eps.png")
    print(f"| ε | λ₁ | λ₂ | K(v,e₁) > 0 | K(v,e₂) > 0 | min Σ sin²θ |")
    print("|---|---|---|---|---|---|")
    for r in dyn:
        name = "Σcos θ = 0 (RotorSystem(4))" if r["eps"] is None else f"{r['eps']:g}"
        e, s, p, ps = r["exponents"], r["stderr"], r["positive"], r["positive_se"]
        print(f"| {name} | {e[0]:.4f} ± {s[0]:.4f} | {e[1]:.4f} ± {s[1]:.4f} | "
              f"{p[0]:.3f} ± {ps[0]:.3f} | {p[1]:.3f} ± {ps[1]:.3f} | {r['min_sin2']:.2e} |")
    print()
    print("| ε | distance to the four avoided cone points | on M | min K at a cone point on M |")
    print("|---|---|---|---|")
    for c in cones:
        d = [x for x in c["distances"] if x > 1e-6]
        print(f"| {c['eps']:g} | {min(d):.5f} … {max(d):.5f} | {c['on']} | {c['K_min_on_cone']:.4g} |")
    return 0


if __name__ == "__main__":
    sys.path.insert(0, str(ROOT))
    sys.exit(main())
