"""Long runs for the large-N laws at unit total speed (docs/large-n.md): for each N an ensemble
of independent trajectories (`lyapunov_ensemble`, each member T time units after a long
transient), λ₁ and the sum of the positive exponents Σλ⁺ (the Kolmogorov–Sinai entropy by
Pesin's formula) with standard errors across the members, the members' own batch-means errors
against that spread (their ratio), and weighted power-law fits λ₁ ∝ N^a, Σλ⁺ ∝ N^b.

    python scripts/large_n_long.py [--n 8 12 16 24 32] [--members 8] [--t-final 20000]
                                   [--transient 500] [--workers 2] [--json FILE]
"""
import argparse
import json
import time

import numpy as np

import charts


def fit_power_law(n, y, se):
    """Weighted least squares of log y = c + slope·log N (weights from se/y); returns (slope,
    its standard error scaled by √(χ²/dof) when that exceeds 1, χ²/dof)."""
    x, ly, w = np.log(n), np.log(y), (y / se) ** 2
    A = np.vstack([np.ones_like(x), x]).T
    cov = np.linalg.inv(A.T @ (w[:, None] * A))
    coef = cov @ (A.T @ (w * ly))
    chi2 = float(np.sum(w * (ly - A @ coef) ** 2) / max(len(x) - 2, 1))
    return float(coef[1]), float(np.sqrt(cov[1, 1] * max(chi2, 1.0))), chi2


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--n", type=int, nargs="+", default=[8, 12, 16, 24, 32])
    ap.add_argument("--members", type=int, default=8)
    ap.add_argument("--t-final", type=float, default=20000.0)
    ap.add_argument("--transient", type=float, default=500.0)
    ap.add_argument("--workers", type=int, default=2)
    ap.add_argument("--json", default=None)
    a = ap.parse_args()
    rows = []
    print(f"unit total speed, {a.members} members x T = {a.t_final:g} after {a.transient:g}, "
          "errors across the members (one standard error of the mean)")
    print("N | lambda1 | sum lambda+ | lambda_{N-2} | within-run / across-member error of lambda1")
    for n in a.n:
        t0 = time.perf_counter()
        s = charts.RotorSystem(n)
        ens = charts.lyapunov_ensemble(s, a.members, a.t_final, seed=1, workers=a.workers,
                                       t_transient=a.transient)
        lam = np.array([m.exponents for m in ens.members])          # (members, N - 2)
        pos = np.where(lam > 0, lam, 0.0).sum(axis=1)
        k = lam.shape[0]
        row = dict(n=n, members=k, t_final=a.t_final, transient=a.transient,
                   lambda1=float(lam[:, 0].mean()), lambda1_se=float(lam[:, 0].std(ddof=1) / np.sqrt(k)),
                   sum_pos=float(pos.mean()), sum_pos_se=float(pos.std(ddof=1) / np.sqrt(k)),
                   smallest=float(lam[:, -1].mean()), smallest_se=float(lam[:, -1].std(ddof=1) / np.sqrt(k)),
                   lambda1_spread=float(lam[:, 0].std(ddof=1)),
                   error_ratio=float(ens.error_ratio[0]),      # the ensemble's own (EnsembleResult)
                   seconds=time.perf_counter() - t0)
        rows.append(row)
        print(f"{n} | {row['lambda1']:.4f} ± {row['lambda1_se']:.4f} | {row['sum_pos']:.4f} ± "
              f"{row['sum_pos_se']:.4f} | {row['smallest']:.4f} ± {row['smallest_se']:.4f} | "
              f"{row['error_ratio']:.2f} ({row['seconds']:.0f} s)", flush=True)
    ns = np.array([r["n"] for r in rows], float)
    fits = {}
    for key in ("lambda1", "sum_pos"):
        y = np.array([r[key] for r in rows])
        se = np.array([r[f"{key}_se"] for r in rows])
        fits[key] = fit_power_law(ns, y, se)
    print(f"fit over N = {a.n}: lambda1 ~ N^a, a = {fits['lambda1'][0]:.3f} ± "
          f"{fits['lambda1'][1]:.3f} (chi2/dof {fits['lambda1'][2]:.2f}); sum lambda+ ~ N^b, "
          f"b = {fits['sum_pos'][0]:.3f} ± {fits['sum_pos'][1]:.3f} (chi2/dof "
          f"{fits['sum_pos'][2]:.2f})")
    if a.json:
        with open(a.json, "w", encoding="utf-8") as fh:
            json.dump(dict(rows=rows, fits=fits, args=vars(a)), fh, indent=1)


if __name__ == "__main__":
    main()
