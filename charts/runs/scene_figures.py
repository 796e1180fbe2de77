"""The figures a scene run writes, one PNG per effect with a picture (in the figure style of
:mod:`charts.runs.plotting`).  Each function returns the PNG bytes; the caller writes them.

Units: time in time units of the flow (those of the scene: at speed 1 the paper's), angles
in rad, angular velocities and angular frequencies in rad per unit time.
"""
from __future__ import annotations

import numpy as np

from .plotting import new_figure, png_bytes

__all__ = ["waveforms_png", "spectrum_png", "drift_png", "lyapunov_png", "angles_png", "clv_png",
           "curvature_png", "CURVATURE_QUANTILES"]

TIME = "t (time units of the flow)"
#: Quantiles (in %) of the curvature samples that set the histogram limits; the tails beyond
#: are left out of the picture (not of the numbers in result.json).
CURVATURE_QUANTILES = (0.5, 99.5)


def _title(sc, what):
    return f"{sc.name}: {what}, N = {sc.system['n']}"


def waveforms_png(sc, t, U) -> bytes:
    """The angular velocities uᵢ(t) of the stored window, one panel per rotor."""
    rotors = sc.effects["waveforms"]["rotors"]
    fig, axes = new_figure(len(rotors), 1, figsize=(8, 1.3 * len(rotors) + 0.9), sharex=True,
                           squeeze=False)
    for ax, r, col in zip(axes[:, 0], rotors, U.T):
        ax.plot(t, col, lw=0.7)
        ax.set_ylabel(f"$u_{{{r}}}$ (rad/time)")
    axes[-1, 0].set_xlabel(TIME)
    fig.suptitle(_title(sc, "angular velocities (rad per unit time)"))
    return png_bytes(fig)


def spectrum_png(sc, omega, density, segment_time) -> bytes:
    """Power spectral density of one rotor's velocity against angular frequency ω."""
    rotor = sc.effects["spectrum"]["rotor"]
    fig, ax = new_figure(figsize=(6.5, 3.8))
    sel = omega > 0
    ax.semilogy(omega[sel], density[sel], lw=0.8)
    ax.set_xlabel("ω (rad per unit time)")
    ax.set_ylabel(f"$S_{{u_{{{rotor}}}}}(\\omega)$ ((rad/time)² per unit ω)")
    ax.set_title(_title(sc, f"power spectral density of $u_{{{rotor}}}$") +
                 f"\n(Welch: Hann segments of {segment_time:g} time units, 50 % overlap)",
                 fontsize=10)
    return png_bytes(fig)


def drift_png(sc, t, D) -> bytes:
    """|drift| of the three invariants on a log axis; exact zeros (which a log axis cannot
    show) are left out and counted in the legend."""
    fig, ax = new_figure(figsize=(7.5, 3.8))
    names = ("|Σ cos θᵢ| (constraint)", "|Σ uᵢ sin θᵢ| (tangency, rad/time)",
             "|E/E₀ − 1| (energy, relative)")
    drawn = False
    for col, lab in zip(D.T, names):
        a = np.abs(col)
        zero = a == 0
        if zero.any():
            lab += f"\n  = 0 exactly at {zero.sum()} of {a.size} samples (not drawn)"
        drawn |= not zero.all()
        ax.semilogy(t, np.where(zero, np.nan, a), lw=0.8, marker="." if a.size < 60 else None,
                    label=lab)
    if not drawn:
        ax.set_ylim(1e-17, 1.0)
        ax.set_xlim(t[0], t[-1] if t[-1] > t[0] else t[0] + 1.0)
        ax.text(0.5, 0.5, "every recorded drift is exactly 0", transform=ax.transAxes,
                ha="center", va="center")
    ax.set_xlabel(TIME)
    ax.set_ylabel("|drift of the invariant|")
    ax.set_title(_title(sc, "drift of the invariants"))
    fig.legend(loc="outside right upper", fontsize=8)
    return png_bytes(fig)


def lyapunov_png(sc, T, H, res) -> bytes:
    """Running estimates λᵢ(T) at the batch ends against the averaging time T, the final
    estimate ± its batch-means standard error, and the paper's values when they apply."""
    fig, ax = new_figure(figsize=(7, 4.8))
    exps = res["exponents"]
    stderr = res.get("stderr", [None] * len(exps))
    for i, (col, lam, se) in enumerate(zip(H.T, exps, stderr)):
        color = f"C{i}"
        if se is None:
            lab = f"λ{i + 1} = {lam:.4g} (one batch: no error bar)"
        else:
            lab = f"λ{i + 1} = {lam:.4g} ± {se:.2g}"
            ax.axhspan(lam - se, lam + se, color=color, alpha=0.15, lw=0)
            ax.errorbar([T[-1]], [lam], yerr=[se], color=color, capsize=4, lw=1.2)
        ax.plot(T, col, marker="o", ms=3, color=color, label=lab)
    for i, p in enumerate(res.get("paper", [])):
        ax.axhline(p, color="k", lw=0.8, ls=":",
                   label="paper, section 2 (scaled by the speed)" if i == 0 else None)
    if len(T) >= 3:
        from matplotlib.ticker import LogLocator, NullFormatter, ScalarFormatter

        ax.set_xscale("log")
        ax.xaxis.set_major_locator(LogLocator(subs=(1.0, 2.0, 5.0)))
        ax.xaxis.set_major_formatter(ScalarFormatter())
        ax.xaxis.set_minor_formatter(NullFormatter())
    ax.set_xlabel("averaging time T (time units of the flow)")
    ax.set_ylabel("λ (1 / time unit)")
    how = "running estimates at the batch ends"
    if len(T) >= 2:
        how += "; band and bar: final estimate ± batch-means standard error"
    fig.suptitle(_title(sc, "Lyapunov exponents") + f"\n({how})", fontsize=10)
    fig.legend(loc="outside lower center", ncol=2, fontsize=8)
    return png_bytes(fig)


def angles_png(sc, arr) -> bytes:
    """Histograms of the angle φ between the expanding and the contracting-neutral subspaces."""
    variants = [v for v in ("full", "restricted") if f"angles_{v}" in arr]
    fig, axes = new_figure(1, len(variants), figsize=(4.5 * len(variants), 3.4), squeeze=False)
    for ax, v in zip(axes[0], variants):
        phi = arr[f"angles_{v}"]
        ax.hist(phi, bins=60, range=(0, np.pi / 2), density=True)
        ax.set_xlabel("φ (rad)")
        ax.set_ylabel("probability density")
        ax.set_title(f"{v} tangent space (min φ = {phi.min():.2g})", fontsize=10)
    fig.suptitle(_title(sc, "angles between $E_u$ and $E_{cs}$"))
    return png_bytes(fig)


def clv_png(sc, arr, res) -> bytes:
    """Per variant: histograms of φ (CLV route) and of the angle between the leading
    unstable and stable CLVs; the domination fractions against the window length."""
    variants = [v for v in ("full", "restricted") if f"clv_phi_{v}" in arr]
    fig, axes = new_figure(1, len(variants) + 1, figsize=(4.2 * (len(variants) + 1), 3.4),
                           squeeze=False)
    for ax, v in zip(axes[0], variants):
        for key, label in ((f"clv_phi_{v}", "$E_u$ vs $E_{cs}$"),
                           (f"clv_phi_vectors_{v}", "$v_1$ vs leading stable $v_s$")):
            ax.hist(arr[key], bins=60, range=(0, np.pi / 2), density=True, histtype="step",
                    label=f"{label} (min {arr[key].min():.2g})")
        ax.set_xlabel("angle (rad)")
        ax.set_ylabel("probability density")
        ax.set_title(f"{v} tangent space", fontsize=10)
        ax.legend(fontsize=7)
    ax = axes[0, -1]
    for v in variants:
        d = res[v]["domination"]
        w = [float(k) for k in d]
        ax.plot(w, [d[k]["split"] for k in d], "o-", label=v)
    ax.set_xscale("log")
    ax.set_xlabel("window T (time units)")
    ax.set_ylabel("fraction of windows")
    ax.set_title("$E_u$ not dominating $E_{cs}$", fontsize=10)
    ax.legend(fontsize=7)
    fig.suptitle(_title(sc, "covariant Lyapunov vectors"))
    return png_bytes(fig)


def curvature_png(sc, arr) -> bytes:
    """Histograms of the sectional curvatures K_ii, one panel per direction, both routes
    when both were computed; limits from the robust quantiles, tails clipped."""
    routes = [r for r in ("numerical", "exact") if f"curvature_{r}" in arr]
    k = arr[f"curvature_{routes[0]}"].shape[1]
    fig, axes = new_figure(1, k, figsize=(4 * k + 1.5, 3.6), squeeze=False)
    for i in range(k):
        ax = axes[0, i]
        samples = np.concatenate([arr[f"curvature_{r}"][:, i] for r in routes])
        lo, hi = np.percentile(samples, CURVATURE_QUANTILES)
        lo, hi = min(lo, 0.0), max(hi, 0.0)
        pad = 0.03 * (hi - lo) or 0.05
        for r in routes[::-1]:   # the routes agree closely: thin dashed over wide solid
            ax.hist(arr[f"curvature_{r}"][:, i], bins=60, range=(lo - pad, hi + pad),
                    histtype="step", density=True, label=f"{r} route" if i == 0 else None,
                    **(dict(ls="--", lw=1.0, color="k") if r == "numerical" else
                       dict(lw=2.4, color="C1", alpha=0.7)))
        ax.axvline(0.0, color="k", lw=0.6)
        ax.set_xlim(lo - pad, hi + pad)
        ax.set_xlabel(f"$K_{{{i + 1}{i + 1}}}$ (1/rad²)")
        ax.set_ylabel("probability density")
        K = arr[f"curvature_{routes[-1]}"][:, i]
        ax.set_title(f"$K_{{{i + 1}{i + 1}}}$ > 0 in {100 * (K > 0).mean():.2f} % of "
                     f"{K.size} samples ({routes[-1]} route)", fontsize=9)
    q0, q1 = CURVATURE_QUANTILES
    fig.suptitle(_title(sc, "sectional curvatures") +
                 f"\n(tails beyond the {q0:g} %–{q1:g} % quantiles clipped)", fontsize=11)
    fig.legend(loc="outside lower center", ncol=len(routes), fontsize=8)
    return png_bytes(fig)
