"""Figures 2-5 of the paper in its panel layouts (matplotlib, Agg backend, PNG).

Each function takes the computed data keyed by N and a path, writes the figure and
returns the path.  Time is in units where the speed along the geodesic is 1 (the
paper's normalisation), angular velocities in rad per time unit.
"""
from __future__ import annotations

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

__all__ = ["figure2", "figure3", "figure4", "figure5"]

_LETTERS = "abcdef"


def _save(fig, path):
    fig.tight_layout()
    fig.savefig(path, dpi=120)
    plt.close(fig)
    return path


def figure2(waveforms, path, t_show=100.0):
    """Waveforms uᵢ(t), N = 3 (a), 4 (b), 5 (c); ``waveforms[n]`` a `Waveform`."""
    ns = sorted(waveforms)
    fig, axes = plt.subplots(len(ns), 1, figsize=(8, 2.4 * len(ns)), sharex=True)
    for ax, n, L in zip(np.atleast_1d(axes), ns, _LETTERS):
        w = waveforms[n]
        sel = w.t - w.t[0] <= t_show
        for i in range(n):
            ax.plot(w.t[sel] - w.t[0], w.u[sel, i], lw=0.8, label=f"$u_{i}$")
        ax.set_ylabel("angular velocity $u_i$ (rad/time)")
        ax.set_title(f"({L}) N = {n}, unit speed along the geodesic")
        ax.legend(loc="upper right", ncol=n, fontsize=7)
    ax.set_xlabel("time t")
    return _save(fig, path)


def figure3(spectra, path):
    """Power spectral density of u₀, N = 3 (a), 4 (b), 5 (c); ``spectra[n] = (ω, S)``."""
    ns = sorted(spectra)
    fig, axes = plt.subplots(len(ns), 1, figsize=(6, 2.4 * len(ns)), sharex=True)
    for ax, n, L in zip(np.atleast_1d(axes), ns, _LETTERS):
        om, p = spectra[n]
        sel = (om > 0) & (om <= 6.0)
        ax.semilogy(om[sel], p[sel], lw=0.8)
        ax.set_ylabel(r"$S_{u_0}(\omega)$ (rad²/time)")
        ax.set_title(f"({L}) N = {n}: Welch spectrum of $u_0$")
    ax.set_xlabel(r"angular frequency $\omega$ (rad/time)")
    return _save(fig, path)


def figure4(curvatures, path, bins=100):
    """Histograms of K_ii: N = 3 (a), N = 4 (b, c), N = 5 (d, e, f);
    ``curvatures[n]`` = array (S, N−2) of diagonal sectional curvatures."""
    fig = plt.figure(figsize=(10, 8))
    gs = fig.add_gridspec(3, 3)
    L = iter(_LETTERS)
    for row, n in enumerate(sorted(curvatures)):
        K = curvatures[n]
        for i in range(K.shape[1]):
            ax = fig.add_subplot(gs[row, i])
            k = K[:, i]
            lo, hi = np.percentile(k, [0.5, 99.5])
            ax.hist(k, bins=bins, range=(min(lo, -0.05), max(hi, 0.05)), density=True, color="C0")
            ax.axvline(0.0, color="k", lw=0.6)
            ax.set_title(f"({next(L)}) N = {n}: $K_{{{i + 1}{i + 1}}}$", fontsize=9)
            ax.set_xlabel("sectional curvature (1/rad²)", fontsize=8)
            ax.set_ylabel("probability density", fontsize=8)
            ax.text(0.03, 0.92, f"K>0: {100 * (k > 0).mean():.2f} %\nn = {k.size}",
                    transform=ax.transAxes, fontsize=7, va="top")
    return _save(fig, path)


def figure5(angles, path, bins=100):
    """Histograms of φ, N = 3 (a), 4 (b), 5 (c); ``angles[n] = (phi_full, phi_restricted)``."""
    ns = sorted(angles)
    fig, axes = plt.subplots(len(ns), 1, figsize=(6, 2.6 * len(ns)))
    for ax, n, L in zip(np.atleast_1d(axes), ns, _LETTERS):
        pf, pr = angles[n]
        rng = (0.0, np.pi / 2)
        ax.hist(pr, bins=bins, range=rng, density=True, alpha=0.7,
                label=f"restricted to $T_r$ (min {pr.min():.1e})")
        ax.hist(pf, bins=bins, range=rng, density=True, histtype="step", color="k",
                label=f"full $R^{{2N}}$ (min {pf.min():.1e})")
        ax.set_title(f"({L}) N = {n}: angle between $E_u$ and $E_{{cs}}$")
        ax.set_xlabel(r"$\varphi$ (rad)")
        ax.set_ylabel("probability density")
        ax.legend(fontsize=7)
    return _save(fig, path)
