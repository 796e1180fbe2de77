"""Tables and figures of the large-N study (docs/large-n.md) from a `large-n` sweep folder.

    charts sweep large-n -o runs/large-n
    python scripts/large_n_report.py runs/large-n --figures docs/figures/large-n > tables.md

Reads the sweep's summary.csv (means over seeds, standard errors: the larger of the seed
spread and the propagated batch-means errors, `charts.runs.sweep.statistics`) and its
table.csv (one row per point: the curvature and angle columns per trajectory).  The
exponents to quote come from the long ensembles of ``scripts/large_n_long.py``.  The two speed
normalisations are the rows with speed "1" (unit total speed, the paper's) and "n ** 0.5"
(kinetic energy ½ per rotor of unit mass).
"""
from __future__ import annotations

import argparse
import csv
from pathlib import Path

import numpy as np

from charts.plotting.style import new_figure, save_png

UNIT, PER_ROTOR = "1.0", "n ** 0.5"
LABEL = {UNIT: "unit total speed", PER_ROTOR: "speed √N (energy ½ per rotor)"}


def load(folder):
    rows = list(csv.DictReader(open(Path(folder) / "summary.csv")))
    out = {}
    for r in rows:
        n = int(float(r["n"]))
        lam = np.array([float(r[f"lambda_{i}"]) for i in range(1, n - 1)])
        se = np.array([float(r[f"lambda_{i}_se"]) for i in range(1, n - 1)])
        kpos = np.array([float(r[f"Kpos_exact_{i}"]) for i in range(1, n - 1)])
        out[(n, r["speed"].strip())] = dict(
            lam=lam, se=se, kpos=kpos, kany=float(r["Kpos_exact_any"]),
            phi_min=float(r["phi_restricted_min"]), phi_p001=float(r["phi_restricted_p001"]),
            phi_med=float(r["phi_restricted_median"]), phi_small=float(r["phi_restricted_frac_small"]),
            seeds=int(r["n_seeds"]))
    return out


def per_seed(folder):
    """{(N, speed): {column: [value of seed 1, seed 2, …]}} from the sweep's table.csv (one
    row per point): the spread between the trajectories, shown as it is."""
    out = {}
    for r in csv.DictReader(open(Path(folder) / "table.csv")):
        n = int(float(r["n"]))
        d = out.setdefault((n, r["speed"].strip()), {})
        kpos = [float(r[f"Kpos_exact_{i}"]) for i in range(1, n - 1)]
        for key, value in (("kpos", np.mean(kpos)), ("kany", float(r["Kpos_exact_any"])),
                           ("phi_min", float(r["phi_restricted_min"])),
                           ("phi_p001", float(r["phi_restricted_p001"])),
                           ("phi_med", float(r["phi_restricted_median"])),
                           ("phi_small", float(r["phi_restricted_frac_small"]))):
            d.setdefault(key, []).append(value)
    return out


def ks(d):
    """h_KS = Σ of the N − 2 positive exponents; error bar Σ se (the exponents' errors are
    correlated, so the quadrature sum would understate it)."""
    return d["lam"].sum(), d["se"].sum()


def fmt(x, e):
    return f"{x:.4f} ± {e:.4f}"


def tables(data, ns, seeds=None):
    if seeds:
        print("### Curvature and angles against N (each trajectory's value: seed 1 / seed 2)\n")
        print("| N | speed | frac K>0 (mean over i) | frac K>0 (any i) | φ_r min | φ_r 0.1 % | "
              "φ_r median | φ_r < 0.05 |")
        print("|---|---|---|---|---|---|---|---|")
        forms = (("kpos", "{:.3f}"), ("kany", "{:.3f}"), ("phi_min", "{:.1e}"),
                 ("phi_p001", "{:.1e}"), ("phi_med", "{:.3f}"), ("phi_small", "{:.4f}"))
        for sp in (UNIT, PER_ROTOR):
            for n in ns:
                d = seeds.get((n, sp))
                if d is None:
                    continue
                cells = [" / ".join(f.format(v) for v in d[key]) for key, f in forms]
                print(f"| {n} | {LABEL[sp]} | " + " | ".join(cells) + " |")
    print("\n### Scaling law: λ(√N)/λ(1) = √N for a geodesic flow\n")
    print("| N | √N | λ₁(√N)/λ₁(1) | h_KS(√N)/h_KS(1) |")
    print("|---|---|---|---|")
    for n in ns:
        a, b = data.get((n, PER_ROTOR)), data.get((n, UNIT))
        if a is None or b is None:
            continue
        r1 = a["lam"][0] / b["lam"][0]
        e1 = r1 * np.hypot(a["se"][0] / a["lam"][0], b["se"][0] / b["lam"][0])
        (ha, hae), (hb, hbe) = ks(a), ks(b)
        rh = ha / hb
        eh = rh * np.hypot(hae / ha, hbe / hb)
        print(f"| {n} | {np.sqrt(n):.3f} | {r1:.3f} ± {e1:.3f} | {rh:.3f} ± {eh:.3f} |")


def _n_axis(ax, ns):
    """Log N axis labelled at the swept N (no minor labels)."""
    from matplotlib.ticker import NullFormatter, ScalarFormatter

    ax.set_xscale("log")
    ax.set_xticks([n for n in ns if n in (3, 4, 6, 8, 12, 16, 24, 32, 48, 64)])
    ax.xaxis.set_major_formatter(ScalarFormatter())
    ax.xaxis.set_minor_formatter(NullFormatter())


def figures(data, ns, out):
    out = Path(out)
    out.mkdir(parents=True, exist_ok=True)
    # (the exponents' figures come from the long ensembles: scripts/large_n_long.py)
    # curvature and angles against N
    fig, axes = new_figure(1, 2, figsize=(10, 4))
    for sp, mk in ((UNIT, "o-"), (PER_ROTOR, "s--")):
        nn = [n for n in ns if (n, sp) in data]
        d = [data[(n, sp)] for n in nn]
        axes[0].plot(nn, [x["kpos"].mean() for x in d], mk, label=f"mean over i, {LABEL[sp]}")
        axes[0].plot(nn, [x["kany"] for x in d], mk, alpha=0.5, label=f"any i, {LABEL[sp]}")
        axes[1].semilogy(nn, [x["phi_p001"] for x in d], mk, label=f"0.1 % quantile, {LABEL[sp]}")
        axes[1].semilogy(nn, [x["phi_med"] for x in d], mk, alpha=0.5, label=f"median, {LABEL[sp]}")
    _n_axis(axes[0], ns)
    axes[0].set_xlabel("N (rotors)")
    axes[0].set_ylabel("fraction of samples with K > 0")
    axes[0].set_title("Sectional curvature of the planes (u, i-th Lyapunov vector)", fontsize=10)
    _n_axis(axes[1], ns)
    axes[1].set_xlabel("N (rotors)")
    axes[1].set_ylabel("φ (rad)")
    axes[1].set_title("Restricted angle between E_u and E_cs (Euclidean product)", fontsize=10)
    for ax in axes:
        ax.grid(alpha=0.3, which="both")
        ax.legend(fontsize=7)
    save_png(fig, out / "curvature-angles-vs-n.png")


def main(argv=None):
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("folder")
    p.add_argument("--figures", default=None)
    a = p.parse_args(argv)
    data = load(a.folder)
    ns = sorted({n for n, _ in data})
    table = Path(a.folder) / "table.csv"
    tables(data, ns, per_seed(a.folder) if table.exists() else None)
    if a.figures:
        figures(data, ns, a.figures)
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
