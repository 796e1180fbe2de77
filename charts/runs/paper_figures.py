"""Figures 2-5 of the paper in its panel layouts (PNG, in the figure style of
:mod:`charts.plotting`; the curvature histograms drawn by its ``plot_curvature``).

Each function takes the computed data keyed by N and a path, writes the figure and
returns the path.  Time is in units where the speed along the geodesic is 1 (the
paper's normalisation), angular velocities and angular frequencies in rad / time.
"""
from __future__ import annotations

import numpy as np

from ..io.result_words import ANGULAR_VELOCITY
from ..plotting import CURVATURE_QUANTILES, plot_curvature
from ..plotting.style import new_figure, save_png

__all__ = ["figure2", "figure3", "figure4", "figure5"]

_LETTERS = "abcdef"


def _panels(ns, height, width=6.0, **kw):
    """One panel per N, stacked: ``(fig, [(ax, n, letter), ...])``."""
    fig, axes = new_figure(len(ns), 1, figsize=(width, height * len(ns)), squeeze=False, **kw)
    return fig, list(zip(axes[:, 0], ns, _LETTERS))


def _save(fig, path):
    save_png(fig, path)
    return path


def figure2(waveforms, path, t_show=100.0):
    """Waveforms uᵢ(t), N = 3 (a), 4 (b), 5 (c); ``waveforms[n]`` a `Waveform`."""
    fig, panels = _panels(sorted(waveforms), 2.4, width=9.0, sharex=True)
    for ax, n, L in panels:
        w = waveforms[n]
        sel = w.t - w.t[0] <= t_show
        for i in range(n):
            ax.plot(w.t[sel] - w.t[0], w.u[sel, i], lw=0.8, label=f"$u_{i}$")
        ax.set_ylabel(f"$u_i$ ({ANGULAR_VELOCITY})")
        ax.set_title(f"({L}) N = {n}, unit speed along the geodesic")
        ax.legend(loc="upper left", bbox_to_anchor=(1.01, 1.0), fontsize=7)
    ax.set_xlabel("time t (time units, unit speed)")
    return _save(fig, path)


def figure3(spectra, path):
    """Power spectral density of u₀, N = 3 (a), 4 (b), 5 (c); ``spectra[n] = (ω, S)``."""
    fig, panels = _panels(sorted(spectra), 2.4, sharex=True)
    for ax, n, L in panels:
        om, p = spectra[n]
        sel = (om > 0) & (om <= 6.0)
        ax.semilogy(om[sel], p[sel], lw=0.8)
        ax.set_ylabel(r"$S_{u_0}(\omega)$" f"\n(({ANGULAR_VELOCITY})² per unit ω)")
        ax.set_title(f"({L}) N = {n}: Welch spectrum of $u_0$")
    ax.set_xlabel(rf"angular frequency $\omega$ ({ANGULAR_VELOCITY})")
    return _save(fig, path)


def figure4(curvatures, path, bins=100):
    """Histograms of K_ii: N = 3 (a), N = 4 (b, c), N = 5 (d, e, f);
    ``curvatures[n]`` = array (S, N−2) of diagonal sectional curvatures."""
    fig, _ = new_figure(0, figsize=(10, 8))
    gs = fig.add_gridspec(3, 3)
    L = iter(_LETTERS)
    for row, n in enumerate(sorted(curvatures)):
        K = curvatures[n]
        axes = [fig.add_subplot(gs[row, i]) for i in range(K.shape[1])]
        plot_curvature({"K": K}, axes=axes, bins=bins)
        for ax in axes:
            ax.set_title(f"({next(L)}) N = {n}: " + ax.get_title(), fontsize=8)
            if ax.get_legend() is not None:
                ax.get_legend().remove()
    q0, q1 = CURVATURE_QUANTILES
    fig.suptitle("Sectional curvatures along the geodesic (velocity × i-th Lyapunov vector); "
                 f"axes: the {q0:g} %–{q1:g} % quantiles (share beyond them in each panel)",
                 fontsize=10)
    return _save(fig, path)


def figure5(angles, path, bins=100):
    """Histograms of φ, N = 3 (a), 4 (b), 5 (c); ``angles[n] = (phi_full, phi_restricted)``."""
    fig, panels = _panels(sorted(angles), 2.6, width=8.0)
    for ax, n, L in panels:
        pf, pr = angles[n]
        rng = (0.0, np.pi / 2)
        ax.hist(pr, bins=bins, range=rng, density=True, alpha=0.7,
                label=f"restricted to $T_r$\n(min {pr.min():.1e})")
        ax.hist(pf, bins=bins, range=rng, density=True, histtype="step", color="k",
                label=f"full $R^{{2N}}$\n(min {pf.min():.1e})")
        ax.set_title(f"({L}) N = {n}: angle between $E_u$ and $E_{{cs}}$")
        ax.set_xlabel(r"$\varphi$ (rad)")
        ax.set_ylabel("probability density")
        ax.legend(loc="upper left", bbox_to_anchor=(1.01, 1.0), fontsize=7)
    return _save(fig, path)
