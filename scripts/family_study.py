"""The family study Σ aᵢ cos θᵢ = c (docs/families-study.md): long angle runs at a few points
(growing samples), then the tables and figures from the sweeps and those runs.

    charts sweep families-n4 -o runs/families-n4
    charts sweep families-n5 -o runs/families-n5
    python scripts/family_study.py growth -o runs/families-growth
    python scripts/family_study.py clv            # the angles by a second route (CLVs)
    python scripts/family_study.py report --n4 runs/families-n4 --n5 runs/families-n5 \\
        --growth runs/families-growth --figures docs/figures/families > tables.md

``growth`` runs `charts.hyperbolicity_angles` (restricted variant) on a few independent
trajectories at each point of :data:`GROWTH` and stores the angles (``<point>.npz``).
``report`` reads each sweep's ``sweep.csv`` (one row per seed) and ``summary.csv`` (means over
seeds, standard errors: the larger of the seed spread and the propagated batch-means errors)
and pools the law of the small angles over seeds (`charts.analyses.statistics.
pool_small_value_laws`); it prints markdown tables and writes the figures.
"""
from __future__ import annotations

import argparse
import csv
import json
import math
import time
import warnings
from pathlib import Path

import numpy as np

from charts import RotorSystem, hyperbolicity_angles
from charts.analyses.angle_tally import SMALL_ANGLE
from charts.analyses.statistics import block_minima, pool_small_value_laws, small_value_law
from charts.geometry.system import critical_levels
from charts.plotting.style import new_figure, save_png

#: The points of the growing-sample runs: name -> (N, weights, level).
GROWTH = {"n4-equal-c0": (4, [1, 1, 1, 1], 0.0),      # the paper's manifold (critical)
          "n4-equal-c1": (4, [1, 1, 1, 1], 1.0),      # smooth, halfway to the next critical value
          "n4-1112-c0": (4, [1, 1, 1, 2], 0.0),       # smooth, unequal weights
          "n5-equal-c0": (5, [1, 1, 1, 1, 1], 0.0)}   # smooth for N = 5
#: Sampling of the angles (time units), as in the sweeps.
SAMPLE_EVERY, TRANSIENT = 0.1, 50.0
#: Block sizes (samples) of the block minima.
SIZES = (10, 30, 100, 300, 1000, 3000, 10000, 30000)
#: Thresholds of the law of the small angles in the growth table (rad).
THRESHOLDS = (0.05, 0.02, 0.01)
#: Fewest samples below the threshold for a fitted exponent in the tables and figures (the
#: batch-means error of fewer is itself unreliable).
MIN_COUNT = 30
MARK = {"(1,1,1,1)": "o", "(1,1,1,2)": "s", "(1,2,1,2)": "^", "(1,1,2,3)": "D",
        "(1,1,1,1,1)": "o"}


# ------------------------------------------------------------------------------- growth
def growth(out: Path, t_final: float, trajectories: int, seed: int, points) -> None:
    out.mkdir(parents=True, exist_ok=True)
    for name in points:
        n, w, c = GROWTH[name]
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")            # the critical level is asked for
            system = RotorSystem(n, weights=w, level=c)
        phis, cpu = [], []
        for i in range(trajectories):
            th, u = system.random_state(seed=seed + i)
            t0 = time.process_time()
            r = hyperbolicity_angles(system, th, u, t_final, t_transient=TRANSIENT,
                                     sample_every=SAMPLE_EVERY, seed=seed + i)
            cpu.append(time.process_time() - t0)
            phis.append(r.phi_restricted)
            print(f"{name} trajectory {i}: {r.phi_restricted.size} angles, min "
                  f"{r.phi_restricted.min():.2e}, {cpu[-1]:.0f} s CPU", flush=True)
        meta = dict(n=n, weights=w, level=c, t_final=t_final, seeds=[seed + i for i in
                    range(trajectories)], sample_every=SAMPLE_EVERY, t_transient=TRANSIENT,
                    cpu_s=cpu)
        np.savez(out / f"{name}.npz", phi=np.array(phis), meta=json.dumps(meta))


def second_route(levels=(0.0, 0.1, 1.0), t_final=2000.0):
    """Restricted angles of N = 4, equal weights, by the adjoint route and by covariant
    Lyapunov vectors on the same trajectory (seed 1), at a few levels."""
    from charts import covariant_lyapunov_vectors
    print("| c | samples | φ < 0.05 (adjoint) | φ < 0.05 (CLV) | min φ (adjoint) | min φ (CLV) | "
          "median rel. diff |\n|---|---|---|---|---|---|---|")
    for c in levels:
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")
            s = RotorSystem(4, weights=[1, 1, 1, 1], level=c)
        th, u = s.random_state(seed=1)
        a = hyperbolicity_angles(s, th, u, t_final, t_transient=100.0, seed=1).phi_restricted
        v = covariant_lyapunov_vectors(s, th, u, t_final, t_transient=100.0, seed=1).phi
        k = min(a.size, v.size)
        print(f"| {c:g} | {k} | {np.mean(a < 0.05):.4f} | {np.mean(v < 0.05):.4f} | "
              f"{a.min():.2e} | {v.min():.2e} | "
              f"{np.median(np.abs(a[:k] - v[:k]) / a[:k]):.1e} |", flush=True)


# ------------------------------------------------------------------------------- report
def _f(s):
    return float(s) if s not in ("", None) else np.nan


def load_sweep_dir(folder: Path):
    """Rows of summary.csv keyed by (weights, level), each with the pooled law of the seeds
    of sweep.csv and the total sample count."""
    summ = {(r["weights"], float(r["level"])): r for r in csv.DictReader(open(folder / "summary.csv"))}
    seeds: dict = {}
    for r in csv.DictReader(open(folder / "sweep.csv")):
        if r["status"] == "complete":
            seeds.setdefault((r["weights"], float(r["level"])), []).append(r)
    out = {}
    for key, s in summ.items():
        rows = seeds[key]
        law = pool_small_value_laws(
            dict(count=int(r["phi_restricted_law_count"]), n=int(r["phi_restricted_n"]),
                 x0=SMALL_ANGLE, exponent=_f(r["phi_restricted_law_exponent"]),
                 exponent_se=_f(r["phi_restricted_law_exponent_se"]),
                 coef2=_f(r["phi_restricted_law_coef2"]),
                 coef2_se=_f(r["phi_restricted_law_coef2_se"])) for r in rows)
        w = json.loads(rows[0]["weight_vector"])
        crit = critical_levels(w)
        out[key] = dict(row=s, law=law, weights=w, n=int(rows[0]["n"]), seeds=len(rows),
                        t=float(rows[0]["t_final"]), gap=float(np.min(np.abs(crit - key[1]))))
    return out


def pm(v, e, d=4):
    return f"{v:.{d}f} ± {e:.{d}f}"


def sweep_tables(data, title):
    n = next(iter(data.values()))["n"]
    k = n - 2
    print(f"\n#### {title}: exponents and curvature\n")
    head = ["weights", "c", "distance to critical"] + [f"λ{i}" for i in range(1, k + 1)] + \
        ["K>0 (some K_ii)", "seeds × t"]
    print("| " + " | ".join(head) + " |\n|" + "---|" * len(head))
    for (w, c), d in sorted(data.items()):
        r = d["row"]
        lam = [pm(_f(r[f"lambda_{i}"]), _f(r[f"lambda_{i}_se"])) for i in range(1, k + 1)]
        gap = "**0 (critical)**" if d["gap"] < 1e-12 else f"{d['gap']:g}"
        print(f"| {w} | {c:g} | {gap} | " + " | ".join(lam) +
              f" | {pm(_f(r['Kpos_numerical_any']), _f(r['Kpos_numerical_any_se']), 3)} | "
              f"{d['seeds']} × {d['t']:g} |")
    print(f"\n#### {title}: restricted angles\n")
    head = ["weights", "c", "distance to critical", "min φ", "0.1 % quantile", "φ < 0.05",
            "count < 0.05", "β (P ∝ φ^β below 0.05)", "A (P = Aφ²)", "samples"]
    print("| " + " | ".join(head) + " |\n|" + "---|" * len(head))
    for (w, c), d in sorted(data.items()):
        r, law = d["row"], d["law"]
        gap = "**0 (critical)**" if d["gap"] < 1e-12 else f"{d['gap']:g}"
        beta = pm(law["exponent"], law["exponent_se"], 2) if law["count"] >= MIN_COUNT else \
            f"— ({law['count']} < {MIN_COUNT})"
        print(f"| {w} | {c:g} | {gap} | {_f(r['phi_restricted_min']):.1e} | "
              f"{pm(_f(r['phi_restricted_p001']), _f(r['phi_restricted_p001_se']), 3)} | "
              f"{pm(_f(r['phi_restricted_frac_small']), _f(r['phi_restricted_frac_small_se']))} | "
              f"{law['count']} | {beta} | "
              f"{pm(law['coef2'], law['coef2_se'], 2)} | {law['n']} |")


def _critical_marker(ax, xs, ys, crit):
    """Open markers on the critical levels."""
    xc = [x for x, cr in zip(xs, crit) if cr]
    yc = [y for y, cr in zip(ys, crit) if cr]
    if xc:
        ax.plot(xc, yc, "o", ms=11, mfc="none", mec="k", mew=1.0, zorder=5)


def sweep_figure(data, title, path):
    n = next(iter(data.values()))["n"]
    k = n - 2
    panels = [(f"lambda_{i}", f"λ{i} (1/time)") for i in range(1, k + 1)] + [
        ("Kpos_numerical_any", "fraction with some K_ii > 0"),
        ("phi_restricted_min", "min φ over seeds (rad)"),
        ("phi_restricted_p001", "0.1 % quantile of φ (rad)"),
        ("law", f"β: P(φ < x) ∝ x^β, x < 0.05 (≥ {MIN_COUNT} samples)")]
    ncol = 3
    nrow = -(-len(panels) // ncol)
    fig, axs = new_figure(nrow, ncol, figsize=(4.2 * ncol, 3.0 * nrow), squeeze=False)
    pats = sorted({w for w, _ in data})
    for ax, (stat, label) in zip(axs.flat, panels):
        for w in pats:
            keys = sorted(c for ww, c in data if ww == w)
            ds = [data[(w, c)] for c in keys]
            if stat == "law":
                ok = [d["law"]["count"] >= MIN_COUNT for d in ds]
                y = [d["law"]["exponent"] if k else np.nan for d, k in zip(ds, ok)]
                e = [d["law"]["exponent_se"] if k else np.nan for d, k in zip(ds, ok)]
            else:
                y = [_f(d["row"][stat]) for d in ds]
                e = [_f(d["row"].get(stat + "_se", "")) if not stat.endswith("_min") else 0.0
                     for d in ds]
            ax.errorbar(keys, y, yerr=np.nan_to_num(e), marker=MARK.get(w, "o"), ms=4,
                        capsize=2, label=f"a = {w}")
            _critical_marker(ax, keys, y, [d["gap"] < 1e-12 for d in ds])
        if stat.startswith("phi_"):
            ax.set_yscale("log")
        if stat == "law":
            ax.axhline(2.0, color="k", lw=0.8, ls="--", label="β = 2")
        ax.set_xlabel("level c")
        ax.set_ylabel(label, fontsize=8)
    for ax in list(axs.flat)[len(panels):]:
        ax.set_visible(False)
    axs.flat[0].legend(fontsize=7, title="open circle: critical level", title_fontsize=7)
    fig.suptitle(title, fontsize=10)
    save_png(fig, path)


def growth_table_and_figure(folder: Path, path):
    print("\n#### Growing samples: restricted angles of long runs\n")
    head = ["point", "trajectories × t", "samples", "min φ"] + \
        [f"β below {x:g}" for x in THRESHOLDS] + ["A (P = Aφ² below 0.05)",
                                                   "slope of log mean block minimum"]
    print("| " + " | ".join(head) + " |\n|" + "---|" * len(head))
    fig, axs = new_figure(1, 2, figsize=(11, 4.0))
    for name in GROWTH:
        f = folder / f"{name}.npz"
        if not f.exists():
            continue
        z = np.load(f)
        phi, meta = z["phi"], json.loads(str(z["meta"]))
        laws = {x: pool_small_value_laws(small_value_law(p, x, 10) for p in phi)
                for x in THRESHOLDS}
        bm = [b for b in block_minima(phi, [s for s in SIZES if s <= phi.shape[1] // 4])]
        big = [b for b in bm if b["size"] >= 1000]
        sl, sse = _slope([b["size"] for b in big], [b["mean"] for b in big],
                         [b["se"] for b in big])
        wname = "(" + ",".join(f"{w:g}" for w in meta["weights"]) + ")"
        label = f"N = {meta['n']}, a = {wname}, c = {meta['level']:g}" + \
            (" (critical)" if np.min(np.abs(critical_levels(meta["weights"]) - meta["level"]))
             < 1e-12 else "")
        betas = [pm(laws[x]["exponent"], laws[x]["exponent_se"], 2) + f" ({laws[x]['count']})"
                 if laws[x]["count"] >= MIN_COUNT else f"— ({laws[x]['count']})"
                 for x in THRESHOLDS]
        print(f"| {label} | {phi.shape[0]} × {meta['t_final']:g} | {phi.size} | "
              f"{phi.min():.1e} | " + " | ".join(betas) +
              f" | {pm(laws[0.05]['coef2'], laws[0.05]['coef2_se'], 2)} | {pm(sl, sse, 2)} |")
        s = np.array([b["size"] for b in bm]) * meta["sample_every"]
        line = axs[0].errorbar(s, [b["mean"] for b in bm], yerr=[b["se"] for b in bm],
                               marker="o", ms=4, capsize=2, label=label)
        # independent samples with the fitted law F = A_β x^β below 0.05:
        # E[min of k samples] ≈ Γ(1 + 1/β) (A_β k)^(−1/β)
        b, p0 = laws[0.05]["exponent"], laws[0.05]["count"] / phi.size
        k = s / meta["sample_every"]
        axs[0].plot(s, math.gamma(1 + 1 / b) * (p0 / 0.05 ** b * k) ** (-1 / b), ls=":",
                    color=line[0].get_color(), lw=1)
        x = np.sort(phi.ravel())
        F = np.arange(1, x.size + 1) / x.size
        keep = x < 0.2
        axs[1].loglog(x[keep], F[keep], color=line[0].get_color(), label=label)
    xs = np.array([1e-3, 0.2])
    axs[1].loglog(xs, 0.3 * xs ** 2, "k--", lw=0.8, label="∝ φ²")
    axs[1].loglog(xs, 0.5 * xs, "k:", lw=0.8, label="∝ φ")
    axs[0].set_xscale("log")
    axs[0].set_yscale("log")
    axs[0].set_xlabel("block length (time units; 10 samples per time unit)")
    axs[0].set_ylabel("mean minimum of φ over a block (rad)")
    axs[0].set_title("mean block minimum (dotted: independent samples of the fitted law)",
                     fontsize=9)
    axs[0].legend(fontsize=7, loc="lower left")
    axs[1].set_xlabel("φ (rad)")
    axs[1].set_ylabel("P(φ < x)")
    axs[1].set_title("cumulative distribution of the restricted angle", fontsize=9)
    axs[1].legend(fontsize=7, loc="upper left")
    fig.suptitle("Growing samples: is the restricted angle bounded away from zero?", fontsize=10)
    save_png(fig, path)


def _slope(x, y, e):
    """Weighted least-squares slope of log y against log x and its standard error (None
    with fewer than three points)."""
    if len(x) < 3:
        return np.nan, np.nan
    lx, ly = np.log(x), np.log(y)
    w = (np.asarray(y) / np.asarray(e)) ** 2                # 1/var of log y
    X = np.vstack([np.ones_like(lx), lx]).T
    cov = np.linalg.inv(X.T @ (w[:, None] * X))
    beta = cov @ X.T @ (w * ly)
    chi2 = float(np.sum(w * (ly - X @ beta) ** 2)) / (len(x) - 2)
    return float(beta[1]), float(np.sqrt(cov[1, 1] * max(chi2, 1.0)))


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    sub = ap.add_subparsers(dest="cmd", required=True)
    g = sub.add_parser("growth", help="long angle runs at the points of GROWTH")
    g.add_argument("-o", "--out", type=Path, required=True)
    g.add_argument("--t", type=float, default=50000.0, help="t_final per trajectory")
    g.add_argument("--trajectories", type=int, default=4)
    g.add_argument("--seed", type=int, default=100)
    g.add_argument("--points", nargs="+", default=list(GROWTH), choices=list(GROWTH))
    sub.add_parser("clv", help="the restricted angles by the CLV route too (N = 4, t = 2000)")
    r = sub.add_parser("report", help="tables (stdout) and figures")
    r.add_argument("--n4", type=Path)
    r.add_argument("--n5", type=Path)
    r.add_argument("--growth", type=Path)
    r.add_argument("--figures", type=Path, default=Path("docs/figures/families"))
    a = ap.parse_args(argv)
    if a.cmd == "growth":
        growth(a.out, a.t, a.trajectories, a.seed, a.points)
        return
    if a.cmd == "clv":
        second_route()
        return
    a.figures.mkdir(parents=True, exist_ok=True)
    for folder, title, fname in ((a.n4, "N = 4, Σ aᵢ cos θᵢ = c", "families-n4.png"),
                                 (a.n5, "N = 5, Σ cos θᵢ = c", "families-n5.png")):
        if folder:
            data = load_sweep_dir(folder)
            sweep_tables(data, title)
            sweep_figure(data, title + " (unit speed; error bars: s.e. over seeds and batches)",
                         a.figures / fname)
    if a.growth:
        growth_table_and_figure(a.growth, a.figures / "families-growth.png")


if __name__ == "__main__":
    main()
