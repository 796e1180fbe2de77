"""Long runs for the large-N laws (docs/large-n.md): for each N an ensemble of independent
trajectories at unit total speed (`lyapunov_ensemble`, each member T time units after its
transient), with errors across the members:

* λ₁, the sum of the positive exponents Σλ⁺ (the Kolmogorov–Sinai entropy by Pesin's
  formula), the smallest positive exponent and the whole positive half of the spectrum;
* the members' own batch-means errors of λ₁ against their spread (the ensemble's
  ``error_ratio``);
* energy localisation: the fraction of the averaging time in which one rotor holds at least
  ``--share`` of the kinetic energy (`EnsembleResult.localised_fractions`) and the time mean
  of the largest share, and across the members their correlations with λ₁ (Pearson r with a
  95 % interval from Fisher's z) and the slope dλ₁/d(fraction); the members' histograms of
  the largest share are kept in the JSON;
* weighted power-law fits λ₁ ∝ N^a, Σλ⁺ ∝ N^b over ``--fit-from`` and above; at a kinetic
  energy ½ per rotor (speed √N) every exponent is √N times the unit-speed one (a geodesic
  flow's time scaling, tested), so those laws follow with a + ½, b + ½.

Each finished N is written to ``--json`` at once, and a rerun with the same file skips the N
it holds (``--resume``), so a long study loses no finished N.

    python scripts/large_n_long.py [--n 8 12 16 24 32] [--members 8] [--t-final 20000]
                                   [--transient 500 | auto] [--workers 2] [--json FILE]
                                   [--resume] [--figures DIR]
"""
import argparse
import json
import os
import time

import numpy as np

import charts
from charts.geometry.energy_shares import largest_shares


def fit_power_law(n, y, se):
    """Weighted least squares of log y = c + slope·log N (weights from se/y); returns (slope,
    its standard error scaled by √(χ²/dof) when that exceeds 1, χ²/dof)."""
    x, ly, w = np.log(n), np.log(y), (y / se) ** 2
    A = np.vstack([np.ones_like(x), x]).T
    cov = np.linalg.inv(A.T @ (w[:, None] * A))
    coef = cov @ (A.T @ (w * ly))
    chi2 = float(np.sum(w * (ly - A @ coef) ** 2) / max(len(x) - 2, 1))
    return float(coef[1]), float(np.sqrt(cov[1, 1] * max(chi2, 1.0))), chi2


def correlation(x, y):
    """(Pearson r, its 95 % interval from Fisher's z, OLS slope of y on x, its standard
    error); NaNs where x does not vary."""
    x, y = np.asarray(x, float), np.asarray(y, float)
    k = len(x)
    if k < 4 or np.ptp(x) == 0:
        return dict(r=np.nan, r_low=np.nan, r_high=np.nan, slope=np.nan, slope_se=np.nan)
    r = float(np.corrcoef(x, y)[0, 1])
    z, dz = np.arctanh(np.clip(r, -0.999999, 0.999999)), 1.96 / np.sqrt(k - 3)
    A = np.vstack([np.ones(k), x]).T
    coef, *_ = np.linalg.lstsq(A, y, rcond=None)
    res = y - A @ coef
    cov = np.linalg.inv(A.T @ A) * (res @ res) / (k - 2)
    return dict(r=r, r_low=float(np.tanh(z - dz)), r_high=float(np.tanh(z + dz)),
                slope=float(coef[1]), slope_se=float(np.sqrt(cov[1, 1])))


def mean_se(a):
    a = np.asarray(a, float)
    return float(a.mean()), float(a.std(ddof=1) / np.sqrt(len(a)))


def run_n(n, a):
    """One N: the ensemble and its row."""
    t0, c0 = time.perf_counter(), time.process_time()
    s = charts.RotorSystem(n)
    transient = a.transient if a.transient == "auto" else float(a.transient)
    ens = charts.lyapunov_ensemble(s, a.members, a.t_final, seed=1, workers=a.workers,
                                   t_transient=transient)
    lam = np.array([m.exponents for m in ens.members])          # (members, N - 2)
    pos = np.where(lam > 0, lam, 0.0).sum(axis=1)
    frac = ens.localised_fractions(a.share)
    k = lam.shape[0]
    row = dict(n=n, members=k, t_final=a.t_final,
               transient=float(ens.members[0].params["t_transient"]),
               transient_rule=ens.members[0].params.get("transient_rule", "fixed"),
               spectrum=lam.mean(axis=0).tolist(),
               spectrum_se=(lam.std(ddof=1, axis=0) / np.sqrt(k)).tolist(),
               lambda1_members=lam[:, 0].tolist(), sum_pos_members=pos.tolist(),
               lambda1_spread=float(lam[:, 0].std(ddof=1)),
               error_ratio=float(ens.error_ratio[0]),
               share=a.share, localised_members=frac.tolist(),
               share_counts_members=[m.energy_shares.tolist() for m in ens.members],
               cpu_seconds=time.process_time() - c0, seconds=time.perf_counter() - t0)
    row["lambda1"], row["lambda1_se"] = mean_se(lam[:, 0])
    row["sum_pos"], row["sum_pos_se"] = mean_se(pos)
    row["smallest"], row["smallest_se"] = mean_se(lam[:, -1])
    row["localised"], row["localised_se"] = mean_se(frac)
    row["localised_range"] = [float(frac.min()), float(frac.max())]
    row["lambda1_vs_localised"] = correlation(frac, lam[:, 0])
    mean_top = np.array([_mean_share(m.energy_shares) for m in ens.members])
    row["mean_largest_share"], row["mean_largest_share_se"] = mean_se(mean_top)
    row["lambda1_vs_mean_largest_share"] = correlation(mean_top, lam[:, 0])
    return row


def _mean_share(hist):
    """The time mean of the largest share, from its histogram (bin centres)."""
    hist = np.asarray(hist, float)
    return float((hist * (np.arange(hist.size) + 0.5)).sum() / hist.sum() / hist.size)


def print_row(r):
    c = r["lambda1_vs_localised"]
    print(f"{r['n']} | {r['lambda1']:.4f} ± {r['lambda1_se']:.4f} | {r['sum_pos']:.4f} ± "
          f"{r['sum_pos_se']:.4f} | {r['smallest']:.4f} ± {r['smallest_se']:.4f} | "
          f"{r['error_ratio']:.2f} | {r['localised']:.3f} ± {r['localised_se']:.3f} "
          f"({r['localised_range'][0]:.3f}–{r['localised_range'][1]:.3f}) | r = {c['r']:.2f} "
          f"[{c['r_low']:.2f}, {c['r_high']:.2f}] | mean largest share "
          f"{r['mean_largest_share']:.3f} ± {r['mean_largest_share_se']:.3f}, r with lambda1 = "
          f"{r['lambda1_vs_mean_largest_share']['r']:.2f} | transient {r['transient']:g} "
          f"({r['seconds']:.0f} s wall)", flush=True)


def maxwell_shares(n, share, samples=200_000, seed=0):
    """(mean largest share, fraction of samples with a largest share ≥ ``share``) of N
    independent Gaussian velocities of unit mass (energy shared as in a Maxwell gas, the
    constraints neglected): the equilibrium reference of the localisation columns."""
    u = np.random.default_rng(seed).normal(size=(samples, n))
    top = largest_shares(u, np.ones(n))
    return float(top.mean()), float(np.mean(top >= share))


def markdown(rows, fits, fit_from):
    """The tables of docs/large-n.md from the rows (and the fits over N ≥ fit_from)."""
    print("| N | members × T | transient | λ₁ | Σλ⁺ (h_KS) | λ_{N−2} | λ₁ at speed √N | "
          "Σλ⁺ at speed √N | within-run / between-member error of λ₁ |")
    print("|---|---|---|---|---|---|---|---|---|")
    for r in rows:
        q = np.sqrt(r["n"])
        print(f"| {r['n']} | {r['members']} × {r['t_final']:g} | {r['transient']:.0f} | "
              f"{r['lambda1']:.4f} ± {r['lambda1_se']:.4f} | {r['sum_pos']:.4f} ± "
              f"{r['sum_pos_se']:.4f} | {r['smallest']:.4f} ± {r['smallest_se']:.4f} | "
              f"{q * r['lambda1']:.4f} ± {q * r['lambda1_se']:.4f} | {q * r['sum_pos']:.3f} ± "
              f"{q * r['sum_pos_se']:.3f} | {r['error_ratio']:.2f} |")
    print()
    print(f"| N | fraction of time one rotor holds ≥ {rows[0]['share']:g} of the energy: mean ± se "
          "(members' range) | Maxwell gas | r with λ₁ [95 %] | slope dλ₁/d(fraction) | time mean "
          "of the largest share | Maxwell gas | r with λ₁ [95 %] |")
    print("|---|---|---|---|---|---|---|---|")
    for r in rows:
        c, d = r["lambda1_vs_localised"], r["lambda1_vs_mean_largest_share"]
        rc = "—" if not np.isfinite(c["r"]) else f"{c['r']:.2f} [{c['r_low']:.2f}, {c['r_high']:.2f}]"
        sl = "—" if not np.isfinite(c["slope"]) else f"{c['slope']:.3f} ± {c['slope_se']:.3f}"
        top, frac = maxwell_shares(r["n"], r["share"])
        print(f"| {r['n']} | {r['localised']:.4f} ± {r['localised_se']:.4f} "
              f"({r['localised_range'][0]:.4f}–{r['localised_range'][1]:.4f}) | {frac:.4f} | "
              f"{rc} | {sl} | {r['mean_largest_share']:.3f} ± {r['mean_largest_share_se']:.3f} | "
              f"{top:.3f} | {d['r']:.2f} [{d['r_low']:.2f}, {d['r_high']:.2f}] |")
    print()
    print("| N | λᵢ/λ₁ at i/(N−2) = 0.25 | 0.5 | 0.8 | λ_{N−2}/λ₁ |")
    print("|---|---|---|---|---|")
    for r in rows:
        if r["n"] < 16:
            continue
        lam = np.array(r["spectrum"]) / r["lambda1"]
        x = np.arange(1, lam.size + 1) / (r["n"] - 2)
        cells = " | ".join(f"{np.interp(q, x, lam):.3f}" for q in (0.25, 0.5, 0.8))
        print(f"| {r['n']} | {cells} | {lam[-1]:.3f} |")
    if fits:
        print()
        print(f"fits over N ≥ {fit_from}: λ₁ ∝ N^a, a = {fits['lambda1'][0]:.3f} ± "
              f"{fits['lambda1'][1]:.3f} (χ²/dof {fits['lambda1'][2]:.2f}); Σλ⁺ ∝ N^b, b = "
              f"{fits['sum_pos'][0]:.3f} ± {fits['sum_pos'][1]:.3f} (χ²/dof "
              f"{fits['sum_pos'][2]:.2f})")


def figures(rows, folder):
    """The spectrum's shape against i/(N − 2), the laws against N, λ₁ against the localised
    fraction per member."""
    from matplotlib.ticker import LogLocator, NullFormatter, ScalarFormatter

    from charts.plotting.style import new_figure, save_png
    os.makedirs(folder, exist_ok=True)
    from matplotlib import colormaps

    colour = colormaps["viridis"]
    fig, ax = new_figure(figsize=(6.4, 4.4))
    for i, r in enumerate(rows):
        lam, se = np.array(r["spectrum"]), np.array(r["spectrum_se"])
        x = np.arange(1, lam.size + 1) / max(r["n"] - 2, 1)
        ax.errorbar(x, lam / r["lambda1"], yerr=se / r["lambda1"], marker="o", ms=2.5, lw=0.9,
                    color=colour(0.92 * i / max(len(rows) - 1, 1)), label=f"N = {r['n']}")
    ax.set_xlabel("i / (N − 2)")
    ax.set_ylabel("λᵢ / λ₁")
    ax.set_title(f"Spectrum shape, {rows[0]['members']} members × T = {rows[0]['t_final']:g} "
                 "per N", fontsize=10)
    ax.legend(fontsize=7, frameon=False, ncol=2)
    save_png(fig, os.path.join(folder, "long-spectrum-shape.png"))
    fig, axes = new_figure(1, 2, figsize=(10, 4))
    ns = np.array([r["n"] for r in rows], float)
    for ax, key, label in zip(axes, ("lambda1", "sum_pos"), ("λ₁", "Σλ⁺ (h_KS)")):
        y = np.array([r[key] for r in rows])
        se = np.array([r[f"{key}_se"] for r in rows])
        ax.errorbar(ns, y, yerr=se, marker="o", ms=3, lw=0.9, capsize=2, label="unit total speed")
        ax.errorbar(ns, y * np.sqrt(ns), yerr=se * np.sqrt(ns), marker="s", ms=3, lw=0.9,
                    capsize=2, label="speed √N (energy ½ per rotor)")
        ax.set_xscale("log")
        ax.set_yscale("log")
        ax.set_xticks(ns)
        for axis in (ax.xaxis, ax.yaxis):
            axis.set_major_formatter(ScalarFormatter())
            axis.set_minor_formatter(NullFormatter())
        ax.yaxis.set_major_locator(LogLocator(subs=(1.0, 2.0, 5.0)))
        ax.set_xlabel("N (rotors)")
        ax.set_ylabel(f"{label} (1 / time unit)")
        ax.set_title(f"{label} against N ± standard error across members", fontsize=10)
        ax.legend(fontsize=8, frameon=False)
    save_png(fig, os.path.join(folder, "long-laws.png"))
    big = [r for r in rows if r["n"] >= 8]
    if big:
        fig, axes = new_figure(1, 2, figsize=(11, 4.2))
        for i, r in enumerate(big):
            c = colour(0.92 * i / max(len(big) - 1, 1))
            rel = np.array(r["lambda1_members"]) / r["lambda1"]
            top = [_mean_share(h) for h in r["share_counts_members"]]
            if max(r["localised_members"]) > 0:
                axes[0].plot(r["localised_members"], rel, "o", ms=3.5, color=c, label=f"N = {r['n']}")
            axes[1].plot(top, rel, "o", ms=3.5, color=c, label=f"N = {r['n']}")
        axes[0].set_xlabel(f"fraction of time one rotor holds ≥ {big[0]['share']:g} of the energy")
        axes[1].set_xlabel("time mean of the largest share of the kinetic energy")
        axes[1].set_xscale("log")
        for ax in axes:
            ax.set_ylabel("λ₁ of the member / mean λ₁ of its N")
            ax.legend(fontsize=7, frameon=False, ncol=2)
        axes[0].set_title("Localised episodes and the leading exponent (one point per member)",
                          fontsize=9)
        axes[1].set_title("The largest share and the leading exponent (one point per member)",
                          fontsize=9)
        save_png(fig, os.path.join(folder, "long-localisation.png"))


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--n", type=int, nargs="+", default=[8, 12, 16, 24, 32])
    ap.add_argument("--members", type=int, default=8)
    ap.add_argument("--t-final", type=float, default=20000.0)
    ap.add_argument("--transient", default="500", help="time units, or 'auto'")
    ap.add_argument("--share", type=float, default=0.4)
    ap.add_argument("--workers", type=int, default=2)
    ap.add_argument("--fit-from", type=int, default=8)
    ap.add_argument("--json", default=None)
    ap.add_argument("--resume", action="store_true", help="skip the N the --json file holds")
    ap.add_argument("--figures", default=None)
    ap.add_argument("--markdown", action="store_true",
                    help="print the docs' tables from the --json file (no runs)")
    a = ap.parse_args()
    if a.markdown:
        with open(a.json, encoding="utf-8") as fh:
            rows = sorted(json.load(fh)["rows"], key=lambda r: r["n"])
        fit_rows = [r for r in rows if r["n"] >= a.fit_from]
        ns = np.array([r["n"] for r in fit_rows], float)
        fits = {key: fit_power_law(ns, np.array([r[key] for r in fit_rows]),
                                   np.array([r[f"{key}_se"] for r in fit_rows]))
                for key in ("lambda1", "sum_pos")} if len(fit_rows) >= 3 else {}
        markdown(rows, fits, a.fit_from)
        if a.figures:
            figures(rows, a.figures)
        return
    if a.transient != "auto":
        float(a.transient)
    rows = []
    if a.resume and a.json and os.path.exists(a.json):
        with open(a.json, encoding="utf-8") as fh:
            rows = [r for r in json.load(fh)["rows"] if r["n"] in a.n]
    print(f"unit total speed, {a.members} members x T = {a.t_final:g} after a transient of "
          f"{a.transient}, errors across the members (one standard error of the mean)")
    print("N | lambda1 | sum lambda+ | lambda_{N-2} | within/across error of lambda1 | "
          f"fraction of time a rotor holds >= {a.share:g} (range) | r(fraction, lambda1) [95 %]")
    for r in rows:
        print_row(r)
    for n in a.n:
        if any(r["n"] == n for r in rows):
            continue
        rows.append(run_n(n, a))
        rows.sort(key=lambda r: r["n"])
        print_row(next(r for r in rows if r["n"] == n))
        if a.json:
            with open(a.json, "w", encoding="utf-8") as fh:
                json.dump(dict(rows=rows, args=vars(a)), fh, indent=1)
    fit_rows = [r for r in rows if r["n"] >= a.fit_from]
    fits = {}
    if len(fit_rows) >= 3:
        ns = np.array([r["n"] for r in fit_rows], float)
        for key in ("lambda1", "sum_pos"):
            y = np.array([r[key] for r in fit_rows])
            se = np.array([r[f"{key}_se"] for r in fit_rows])
            fits[key] = fit_power_law(ns, y, se)
        print(f"fit over N = {[r['n'] for r in fit_rows]}: lambda1 ~ N^a, a = "
              f"{fits['lambda1'][0]:.3f} ± {fits['lambda1'][1]:.3f} (chi2/dof "
              f"{fits['lambda1'][2]:.2f}); sum lambda+ ~ N^b, b = {fits['sum_pos'][0]:.3f} ± "
              f"{fits['sum_pos'][1]:.3f} (chi2/dof {fits['sum_pos'][2]:.2f}); at speed √N: "
              f"a + 0.5, b + 0.5")
    if a.json:
        with open(a.json, "w", encoding="utf-8") as fh:
            json.dump(dict(rows=rows, fits=fits, args=vars(a)), fh, indent=1)
    if a.figures:
        figures(rows, a.figures)


if __name__ == "__main__":
    main()
