"""The second route of ``charts reproduce``: covariant Lyapunov vectors on the trajectories
of the angle test (same seeds, t, t_transient, dt, samples), the point-by-point comparison
of the two routes to φ, the domination test and the finite-time exponents, with their
report section and figures (``clv.png``, ``ftle.png``)."""
from __future__ import annotations

import numpy as np
from matplotlib.ticker import NullFormatter

from ..analyses.hyperbolicity import angle_statistics
from ..io.result_words import RATE
from ..plotting.style import new_figure, save_png

__all__ = ["task_clv", "summarise", "report_lines", "figure_clv", "figure_ftle",
           "DOMINATION_WINDOWS", "FTLE_WINDOWS"]

VARIANTS = ("full", "restricted")
#: window lengths (time units) of the domination test and of the finite-time exponents.
DOMINATION_WINDOWS = (0.1, 1.0, 10.0)
FTLE_WINDOWS = (1.0, 10.0, 100.0)


def task_clv(n, seed, t, t_transient):
    """Both variants from ``random_state(seed)``, as the angle task; returns the angles, the
    domination fractions, the leading finite-time exponents (restricted) and the mean and
    spread of the growth rates along the CLVs."""
    from ..analyses.covariant import covariant_lyapunov_vectors
    from ..analyses.finite_time import window_means
    from ..geometry.system import RotorSystem
    s = RotorSystem(n)
    th, u = s.random_state(seed=seed)
    out = {}
    for variant in VARIANTS:
        r = covariant_lyapunov_vectors(s, th, u, t, variant=variant, t_transient=t_transient,
                                       seed=seed)
        dom = r.domination(DOMINATION_WINDOWS)
        out[variant] = dict(phi=r.phi, phi_vectors=r.phi_vectors, exponents=r.exponents,
                            growth_std=r.growth.std(axis=0),
                            split={w: (d["split"], d["count"]) for w, d in dom.items()})
        if variant == "restricted":
            tau = r.params["sample_every"]
            out["ftle"] = {w: window_means(r.gs_rates, tau, w)[:, 0] for w in FTLE_WINDOWS}
    return out


def summarise(members, angle_members):
    """Pool the members of one N (``task_clv`` outputs and the angle task's outputs of the
    same trajectories, in the same order) into the numbers of the report."""
    out = {}
    for v in VARIANTS:
        clv = np.concatenate([m[v]["phi"] for m in members])
        adj = np.concatenate([a[f"phi_{v}"] for a in angle_members])
        rel = np.abs(clv - adj) / adj
        split = {}
        for w in DOMINATION_WINDOWS:
            f = np.array([m[v]["split"][w] for m in members])
            split[w] = float((f[:, 0] * f[:, 1]).sum() / f[:, 1].sum())
        out[v] = dict(median_rel=float(np.median(rel)), max_rel=float(rel.max()),
                      clv=angle_statistics(clv), adjoint=angle_statistics(adj),
                      min_phi_vectors=float(min(m[v]["phi_vectors"].min() for m in members)),
                      exponents=np.mean([m[v]["exponents"] for m in members], axis=0).tolist(),
                      growth_std=np.mean([m[v]["growth_std"] for m in members], axis=0).tolist(),
                      split=split)
    ftle = {}
    for w in FTLE_WINDOWS:
        L = np.concatenate([m["ftle"][w] for m in members])
        p01, p99 = np.percentile(L, [1, 99])
        ftle[w] = dict(count=int(L.size), mean=float(L.mean()), std=float(L.std()),
                       p01=float(p01), p99=float(p99), nonpositive=float((L <= 0).mean()))
    out["ftle"] = ftle
    return out


def report_lines(clv, ns, t_transient):
    """The report section (markdown lines) from ``summarise`` outputs keyed by N."""
    L = ["## Hyperbolicity by a second route: covariant Lyapunov vectors", "",
         "Covariant Lyapunov vectors (Ginelli's method: forward Gram–Schmidt with stored R "
         "factors, backward iteration of the triangular coefficients) on the trajectories of "
         f"the angle test (same seeds, samples, dt; transients {t_transient:g} forward and "
         "backward in both routes).  φ from the CLVs: the angle between span(Q₁…Q_m) and the "
         "span of the CLVs m+1…D; from the adjoint route: section 4's algorithm above.", "",
         "| N | variant | min φ adjoint | min φ CLV | median rel. diff | max rel. diff | "
         "min ∠(v₁, v_s) | samples |",
         "|---|---------|---------------|-----------|------------------|---------------|"
         "----------------|---------|"]
    for n in ns:
        for v in VARIANTS:
            c = clv[n][v]
            L.append(f"| {n} | {v} | {c['adjoint']['min']:.3e} | {c['clv']['min']:.3e} | "
                     f"{c['median_rel']:.1e} | {c['max_rel']:.1e} | {c['min_phi_vectors']:.3f} | "
                     f"{c['clv']['n']} |")
    L += ["", "∠(v₁, v_s): the smallest angle between the leading unstable CLV and the leading "
          "stable one (the first negative exponent).", "",
          "Domination of E_u over E_cs: fraction of non-overlapping windows of length T in "
          "which some unstable CLV grows no faster than some centre-stable one (0 at some T "
          "for a dominated splitting).", "",
          "| N | variant | " + " | ".join(f"T = {w:g}" for w in DOMINATION_WINDOWS) +
          " | mean growth along the CLVs |",
          "|---|---------|" + "|".join("-------" for _ in DOMINATION_WINDOWS) + "|----|"]
    for n in ns:
        for v in VARIANTS:
            c = clv[n][v]
            ex = ", ".join(f"{e:+.3f}" for e in c["exponents"])
            L.append(f"| {n} | {v} | " + " | ".join(f"{c['split'][w]:.4f}"
                                                    for w in DOMINATION_WINDOWS) + f" | {ex} |")
    L += ["", "Finite-time leading Lyapunov exponent λ₁(T) (Gram–Schmidt, restricted, "
          "non-overlapping windows of length T):", "",
          "| N | T | windows | mean | std | 1 % | 99 % | fraction λ₁(T) ≤ 0 |",
          "|---|---|---------|------|-----|-----|------|--------------------|"]
    for n in ns:
        for w, f in clv[n]["ftle"].items():
            L.append(f"| {n} | {w:g} | {f['count']} | {f['mean']:.4f} | {f['std']:.4f} | "
                     f"{f['p01']:.4f} | {f['p99']:.4f} | {f['nonpositive']:.4f} |")
    return L + [""]


def figure_clv(pairs, path, max_points=20000):
    """φ from the CLVs against φ from the adjoint route, one row per N, full and restricted
    side by side; ``pairs[n][variant] = (phi_adjoint, phi_clv)``."""
    ns = sorted(pairs)
    fig, axes = new_figure(len(ns), 2, figsize=(8.0, 2.8 * len(ns)), squeeze=False)
    for row, n in enumerate(ns):
        for ax, v in zip(axes[row], VARIANTS):
            a, c = pairs[n][v]
            step = max(1, a.size // max_points)
            rel = np.abs(c - a) / a
            ax.loglog(a[::step], rel[::step] + 1e-17, ".", ms=1.5, alpha=0.5)
            ax.xaxis.set_minor_formatter(NullFormatter())
            ax.set_title(f"N = {n}, {v}: median {np.median(rel):.1e}, max {rel.max():.1e}",
                         fontsize=9)
            ax.set_xlabel(r"$\varphi$ adjoint route (rad)")
            ax.set_ylabel("|φ_CLV − φ_adj| / φ_adj")
    fig.suptitle("Angle between $E_u$ and $E_{cs}$: relative difference of the two routes "
                 "at each sample", fontsize=10)
    save_png(fig, path)
    return path


def figure_ftle(ftle, path):
    """Histograms of the leading finite-time exponent λ₁(T), one panel per N, one curve
    per window length T (√count bins, 10..80, over the 0.1–99.9 % range of the shortest
    window); ``ftle[n][T]`` = array of λ₁(T)."""
    ns = sorted(ftle)
    fig, axes = new_figure(len(ns), 1, figsize=(6.5, 2.6 * len(ns)), squeeze=False)
    for ax, n in zip(axes[:, 0], ns):
        windows = sorted(ftle[n])
        lo, hi = np.percentile(ftle[n][windows[0]], [0.1, 99.9])
        for w in windows:
            L = ftle[n][w]
            bins = int(np.clip(np.sqrt(L.size), 10, 80))
            ax.hist(L, bins=bins, range=(min(lo, -0.02), hi), density=True, histtype="step",
                    label=f"T = {w:g} (≤ 0: {100 * (L <= 0).mean():.2f} %)")
        ax.axvline(0.0, color="k", lw=0.6)
        ax.set_title(f"N = {n}: leading finite-time Lyapunov exponent", fontsize=9)
        ax.set_xlabel(rf"$\lambda_1(T)$ ({RATE})")
        ax.set_ylabel("probability density")
        ax.legend(fontsize=7)
    save_png(fig, path)
    return path
