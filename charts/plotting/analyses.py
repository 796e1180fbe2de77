"""Figures of the analyses: Lyapunov convergence, curvature and angle histograms, power
spectra, drift of the invariants.  The one home of these pictures: the result classes'
``plot()`` and the figures scenes write both draw with them.  Each returns ``(fig, ax)``
(or ``(fig, axes)``) on a pyplot-free figure or the axes given.

Robust axes: nothing at or below :data:`LOG_FLOOR` goes on a log axis (those samples are
counted in the legend instead), histogram tails beyond :data:`CURVATURE_QUANTILES` are
clipped and the clipped share stated, reference values are drawn only where they exist."""
from __future__ import annotations

import numpy as np

from ..io.result_words import ANGULAR_VELOCITY, RATE
from .style import MAX_POINTS, TIME, figure_axes, line_colors, new_figure, time_window

__all__ = ["plot_lyapunov", "plot_ensemble_exponents", "plot_curvature", "plot_angles",
           "plot_angle_law", "plot_spectrum", "plot_drift",
           "CURVATURE_QUANTILES", "LOG_FLOOR"]

#: Quantiles (in %) of the curvature samples that set the histogram limits; the share of
#: samples beyond them is written in each panel (the numbers elsewhere use every sample).
CURVATURE_QUANTILES = (2.0, 99.5)
#: Values at or below this are not drawn on a log axis (exact zeros, subnormal numbers and
#: values far below double rounding of O(1) quantities, ~1e-16).
LOG_FLOOR = 1e-18


def value_error(value, error) -> str:
    """"value ± error" with the error to two significant digits and the value to the same
    decimal place (0.1269 ± 0.0080, 0.022 ± 0.011)."""
    if not (np.isfinite(error) and error > 0):
        return f"{value:.4g} ± {error:.2g}"
    places = max(0, 1 - int(np.floor(np.log10(error))))
    return f"{value:.{places}f} ± {error:.{places}f}"


def plot_lyapunov(T, H, exponents, stderr=None, *, paper=None, paper_label="paper (dotted)",
                  ax=None, title=None, system=None):
    """Running estimates ``H`` (m, k) of the exponents against the averaging time ``T`` (m,)
    on a log axis; the final ``exponents`` ± ``stderr`` as bands and error bars (when there
    are standard errors); ``paper`` values as dotted lines (only when given); ``system`` (e.g.
    `system_label`'s words) in the title."""
    T = np.asarray(T, dtype=float)
    H = np.asarray(H, dtype=float).reshape(len(T), -1)
    fig, ax = figure_axes(ax, figsize=(7, 4.6))
    keep = T > 0
    colors = line_colors(H.shape[1])
    for i in range(H.shape[1]):
        color = colors[i]
        lam = exponents[i]
        se = None if stderr is None else stderr[i]
        if se is None:
            lab = f"λ{i + 1} = {lam:.4g} (one batch: no error bar)"
        else:
            lab = f"λ{i + 1} = {value_error(lam, se)}"
            ax.axhspan(lam - se, lam + se, color=color, alpha=0.18, lw=0)
            if keep.any():
                ax.errorbar([T[keep][-1]], [lam], yerr=[se], color=color, capsize=4, lw=1.4)
        ax.plot(T[keep], H[keep, i], marker="o" if keep.sum() < 60 else None, ms=3, lw=1.0,
                color=color, label=lab)
    for i, p in enumerate(paper if paper is not None else []):
        ax.axhline(p, color="k", lw=1.0, ls=":", label=paper_label if i == 0 else None)
    if keep.sum() >= 2 and T[keep][-1] > T[keep][0]:
        from matplotlib.ticker import FuncFormatter, LogLocator, NullFormatter

        ax.set_xscale("log")
        decades = np.log10(T[keep][-1] / T[keep][0])
        ax.xaxis.set_major_locator(LogLocator(subs=(1.0,) if decades > 3 else (1.0, 2.0, 5.0)))
        ax.xaxis.set_major_formatter(FuncFormatter(lambda x, _: f"{x:g}"))
        ax.xaxis.set_minor_formatter(NullFormatter())
    ax.set_xlabel("averaging time T (time units of the flow)")
    ax.set_ylabel(f"λ ({RATE})")
    how = "running estimates"
    if stderr is not None:
        how += "; band and bar: final estimate ± standard error"
    # the title in two lines: one line of this length was clipped at the figure's edge
    what = f"Lyapunov exponents, {system}" if system else "Lyapunov exponents"
    ax.set_title(title or f"{what}\n({how})", fontsize=10)
    ax.legend(loc="upper left", bbox_to_anchor=(1.01, 1.0), fontsize=8, frameon=False,
              ncol=1 if H.shape[1] <= 12 else 2)
    return fig, ax


def plot_lyapunov_spectrum(exponents, stderr, n, *, ax=None, label=None, title=None):
    """Exponents λᵢ ± ``stderr`` against i/(N − 2), i = 1…k (the positive half of a geodesic
    flow's spectrum fills (0, 1]), so that spectra of several N can be drawn on one ``ax``
    and compared; ``label`` defaults to "N = n"."""
    lam = np.asarray(exponents, dtype=float)
    x = np.arange(1, lam.size + 1) / max(n - 2, 1)
    fig, ax = figure_axes(ax, figsize=(6.4, 4.4))
    yerr = None if stderr is None else np.asarray(stderr, dtype=float)
    ax.errorbar(x, lam, yerr=yerr, marker="o", ms=3.5, lw=1.0, capsize=3,
                label=label or f"N = {n}")
    ax.axhline(0.0, color="0.6", lw=0.8)
    ax.set_xlabel("i / (N − 2)")
    ax.set_ylabel(f"λᵢ ({RATE})")
    ax.set_title(title or "Lyapunov spectrum (positive half) ± standard error", fontsize=10)
    ax.legend(fontsize=8, frameon=False)
    return fig, ax


def plot_ensemble_exponents(members, exponents, stderr, *, ax=None, title=None,
                            dots="members", bars="mean ± standard error"):
    """Each member's exponents (``members`` (m, k), one dot per member and exponent, spread
    sideways so that equal values stay visible) beside the ensemble's mean ± its standard
    error (the members' spread), exponent i = 1…k on the horizontal axis; ``dots`` and
    ``bars`` name them in the legend (a run's batch estimates and its exponents, too)."""
    members = np.asarray(members, dtype=float)
    m, k = members.shape
    fig, ax = figure_axes(ax, figsize=(max(4.0, 1.1 * k + 2.5), 4.2))
    colors = line_colors(k)
    spread = np.linspace(-0.18, 0.18, m) if m > 1 else np.zeros(1)
    for i in range(k):
        ax.plot(i + 1 + spread, members[:, i], "o", ms=3, alpha=0.55, color=colors[i],
                label=dots if i == 0 else None)
        ax.errorbar([i + 1.32], [exponents[i]], yerr=None if stderr is None else [stderr[i]],
                    fmt="s", ms=5, capsize=4, color="k", label=bars if i == 0 else None)
    ax.set_xticks(np.arange(1, k + 1), [f"λ{i + 1}" for i in range(k)])
    ax.set_xlim(0.5, k + 0.7)
    ax.set_xlabel("exponent")
    ax.set_ylabel(f"λ ({RATE})")
    ax.set_title(title or f"Lyapunov exponents\n{m} members", fontsize=10)
    ax.legend(fontsize=8, frameon=False)
    return fig, ax


def plot_curvature(samples, *, quantiles=CURVATURE_QUANTILES, axes=None, ax=None, title=None,
                   bins=60):
    """Histograms of sectional curvatures, one panel per direction: ``samples`` maps a route
    name to an array (S, k) (or (S,)).  Limits from the robust ``quantiles`` of all samples
    (widened to include K = 0, drawn as a line); the share of samples beyond them is stated."""
    from matplotlib.ticker import MaxNLocator

    samples = {r: np.asarray(v, dtype=float).reshape(len(v), -1) for r, v in samples.items()}
    routes = list(samples)
    k = samples[routes[0]].shape[1]
    if ax is not None:
        axes = [ax]
    if axes is None:
        fig, grid = new_figure(1, k, figsize=(4 * k + 1.0, 3.6), squeeze=False)
        axes = list(grid[0])
    fig = axes[0].figure
    for i in range(k):
        a = axes[i]
        allv = np.concatenate([samples[r][:, i] for r in routes])
        lo, hi = np.percentile(allv, quantiles)
        lo, hi = min(lo, 0.0), max(hi, 0.0)
        pad = 0.03 * (hi - lo) or 0.05
        lo, hi = lo - pad, hi + pad
        for j, r in enumerate(routes[::-1]):   # thin dashed over wide solid
            style = (dict(ls="--", lw=1.0, color="k") if j == len(routes) - 1 and len(routes) > 1
                     else dict(lw=2.0, color=f"C{j}", alpha=0.8))
            a.hist(samples[r][:, i], bins=bins, range=(lo, hi), histtype="step", density=True,
                   label=f"{r} route" if i == 0 else None, **style)
        a.axvline(0.0, color="k", lw=0.8, label="K = 0" if i == 0 else None)
        a.set_xlim(lo, hi)
        a.xaxis.set_major_locator(MaxNLocator(5))
        a.set_xlabel(f"$K_{{{i + 1}{i + 1}}}$ (1/rad²)")
        a.set_ylabel("probability density")
        v = samples[routes[-1]][:, i]
        clipped = float(np.mean((v < lo) | (v > hi)))
        a.set_title(f"$K_{{{i + 1}{i + 1}}}$ > 0: {100 * (v > 0).mean():.2f} % of {v.size}\n"
                    f"beyond the axis (clipped): {100 * clipped:.2f} %", fontsize=9)
    q0, q1 = quantiles
    fig.suptitle(title or f"sectional curvatures (axis: {q0:g} %–{q1:g} % quantiles)", fontsize=10)
    axes[0].legend(loc="upper left", fontsize=7)
    return fig, axes


def plot_angles(phis, *, axes=None, title=None, bins=60):
    """Histograms of the angles φ ∈ [0, π/2] (rad) between the expanding and the
    contracting-neutral subspaces, one panel per variant (``phis``: name → array)."""
    names = list(phis)
    if axes is None:
        fig, grid = new_figure(1, len(names), figsize=(4.5 * len(names), 3.4), squeeze=False)
        axes = list(grid[0])
    fig = axes[0].figure
    for a, v in zip(axes, names):
        phi = np.asarray(phis[v], dtype=float)
        a.hist(phi, bins=bins, range=(0, np.pi / 2), density=True)
        a.set_xlim(0, np.pi / 2)
        a.set_xlabel("φ (rad)")
        a.set_ylabel("probability density")
        a.set_title(f"{v} tangent space (min φ = {phi.min():.2g}, {phi.size} samples)", fontsize=9)
    fig.suptitle(title or "angles between $E_u$ and $E_{cs}$", fontsize=10)
    return fig, axes


def plot_angle_law(statistics, *, axes=None, title=None, sample_every=0.1):
    """The law of the small angles from `AngleTally.statistics` dicts (``statistics``: label
    → dict, one curve each): (a) P(φ < x) against x on log axes with the members' standard
    errors (where P exceeds two of them: the last few angles of the tail are left out), and
    the line of slope 1 (β = 1) for reference; (b) the members' mean minimum of
    consecutive samples against the block's length in time units (``sample_every`` per
    sample): flat for angles bounded away from zero, falling as length^(−1/β) for a law
    A x^β.  ``(fig, axes)``."""
    if axes is None:
        fig, grid = new_figure(1, 2, figsize=(10, 3.8), squeeze=False)
        axes = list(grid[0])
    fig = axes[0].figure
    colors = line_colors(len(statistics))
    xs = []
    for color, (label, st) in zip(colors, statistics.items()):
        if st["cdf"]:
            x, p, se = (np.array(c, dtype=float) for c in zip(*st["cdf"]))
            ok = p > 2 * se                         # the tail of a few angles left out
            x, p, se = x[ok], p[ok], se[ok]
            axes[0].errorbar(x, p, yerr=se, color=color, lw=1, capsize=0,
                             label=f"{label}: min {st['min']:.2g} rad, {st['n']:.2g} angles")
            xs.append(x)
        else:
            axes[0].plot([], [], color=color,
                         label=f"{label}: none below {st['small']:g} (min {st['min']:.2g} rad)")
        if st["block_minima"]:
            size, mean, se = (np.array(c, dtype=float) for c in zip(*st["block_minima"]))
            axes[1].errorbar(size * sample_every, mean, yerr=se, color=color, marker="o",
                             ms=3, lw=1, capsize=0, label=label)
    if xs:
        x = np.concatenate(xs)
        ref = np.array([x.min(), x.max()])
        axes[0].plot(ref, ref / ref[-1] * 1e-2, "k:", lw=0.8, label="slope 1 (β = 1)")
    for ax, x, y, t in ((axes[0], "x (rad)", "P(φ < x)", "(a) the law of the small angles"),
                        (axes[1], "block of consecutive samples (time units)",
                         "mean minimum of φ (rad)", "(b) block minima")):
        ax.set_xscale("log")
        ax.set_yscale("log")
        ax.set(xlabel=x, ylabel=y)
        ax.set_title(t, fontsize=9)
        ax.legend(fontsize=7, frameon=False)
    fig.suptitle(title or "smallest angles between $E_u$ and $E_{cs}$ (restricted)", fontsize=10)
    return fig, axes


def plot_angles_series(t, phis, *, window=None, max_points=MAX_POINTS, ax=None, title=None):
    """φ(t) (rad, log axis) of each variant (``phis``: name → array at the times ``t``);
    ``window`` = (t0, t1): only that span, at most ``max_points`` samples per line
    (`time_window`: the title says when thinned).  Non-finite angles (a lost sample) are
    left out."""
    fig, ax = figure_axes(ax, figsize=(7.5, 3.6))
    stride = 1
    for name, phi in phis.items():
        tt, ph, stride = time_window(t, phi, window, max_points)
        ok = np.isfinite(ph) & (ph > 0)
        ax.semilogy(tt[ok], ph[ok], lw=0.8, label=f"{name} (min {np.nanmin(ph):.2g} rad)")
    ax.set_xlabel(TIME)
    ax.set_ylabel("φ (rad)")
    every = f", every {stride}th sample" if stride > 1 else ""
    ax.set_title(title or f"angle between $E_u$ and $E_{{cs}}$ against time{every}", fontsize=10)
    ax.legend(fontsize=8, frameon=False)
    return fig, ax


def plot_spectrum(omega, density, *, ax=None, label=None, title=None):
    """Power spectral density against angular frequency ω (rad per unit time), log scale;
    ω = 0 and non-positive densities are left out."""
    omega = np.asarray(omega, dtype=float)
    density = np.asarray(density, dtype=float)
    fig, ax = figure_axes(ax, figsize=(6.5, 3.8))
    sel = (omega > 0) & (density > LOG_FLOOR)
    ax.semilogy(omega[sel], density[sel], lw=0.8, label=label)
    ax.set_xlabel(f"ω ({ANGULAR_VELOCITY})")
    ax.set_ylabel("power spectral density (per unit ω)")
    ax.set_title(title or "power spectrum", fontsize=10)
    return fig, ax


def plot_drift(t, columns, names, *, ax=None, title=None):
    """|drift| of invariants against time on a log axis.  Samples at or below
    :data:`LOG_FLOOR` (exact zeros, rounding) are not drawn and are counted in the legend;
    the y axis spans the drawn values only."""
    fig, ax = figure_axes(ax, figsize=(7.5, 3.8))
    t = np.asarray(t, dtype=float)
    drawn = []
    for col, lab in zip(columns, names):
        a = np.abs(np.asarray(col, dtype=float))
        low = a <= LOG_FLOOR
        if low.any():
            lab += f"\n  ≤ {LOG_FLOOR:.0e} at {low.sum()} of {a.size} samples (not drawn)"
        ax.plot(t, np.where(low, np.nan, a), lw=0.8, marker="." if a.size < 60 else None,
                label=lab)
        drawn.append(a[~low])
    ax.set_yscale("log")
    vals = np.concatenate(drawn) if drawn else np.zeros(0)
    if vals.size:
        ax.set_ylim(vals.min() / 3, vals.max() * 3)
    else:
        ax.set_ylim(LOG_FLOOR, 1.0)
        ax.text(0.5, 0.5, f"every recorded drift is ≤ {LOG_FLOOR:.0e}", transform=ax.transAxes,
                ha="center", va="center")
    if t.size:
        ax.set_xlim(t[0], t[-1] if t[-1] > t[0] else t[0] + 1.0)
    ax.set_xlabel(TIME)
    ax.set_ylabel("|drift of the invariant|")
    ax.set_title(title or "drift of the invariants", fontsize=10)
    ax.legend(loc="upper left", bbox_to_anchor=(1.01, 1.0), fontsize=8, frameon=False)
    return fig, ax
