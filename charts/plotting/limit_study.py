"""A sweep toward a limit in one figure: a mechanism's exponents against the parameter that
tends to a system the paper measured (the linkage's crank length ε → 0, docs/linkage.md; the
triple linkage's rim radius r → 0, docs/triple-linkage.md), the limit's values as dashed
lines; where the sweep has them, the positive curvature and the approach to the cone points
of Σ cos θ = 0 (the linkage's columns).  From the rows of a sweep summary (one dict per
parameter value: statistic → mean over seeds, ``<statistic>_se`` its standard error)."""
from __future__ import annotations

from ..io.result_words import RATE
from .style import new_figure

__all__ = ["plot_limit_study", "ERROR_BARS"]

#: Error bars and bands are ± this many standard errors.
ERROR_BARS = 2.0


def _series(rows, x, stat):
    rs = sorted((r for r in rows if r.get(stat) is not None), key=lambda r: r[x])
    return ([r[x] for r in rs], [r[stat] for r in rs],
            [ERROR_BARS * (r.get(stat + "_se") or 0.0) for r in rs])


def plot_limit_study(rows, x="eps", *, paper=(), system="linkage", symbol="ε",
                     xlabel="ε (crank length; rods R = 1)", title="the linkage against ε"):
    """``(fig, axes)``: panels against ``x`` (log scale) — the Lyapunov exponents
    ``lambda_i`` of the ``system`` with the paper's values ``paper`` (its limit
    ``symbol`` → 0) as dashed lines; where the rows have them, the fractions
    ``Kpos_exact_i`` of samples with K(v̂, eᵢ) > 0, and the distance of M from the avoided
    cone points (``cone_distance_min``), the smallest Σ sin²θᵢ met (``sin2_min``) and the
    smallest angle φ (``phi_restricted_min``).  ``xlabel``: the parameter's axis."""
    stats = sorted({k for r in rows for k in r})
    more = [any(s.startswith("Kpos_exact") for s in stats),
            any(s in stats for s in ("cone_distance_min", "sin2_min", "phi_restricted_min"))]
    fig, ax = new_figure(1, 1 + sum(more), figsize=(4.4 * (1 + sum(more)), 4), squeeze=False)
    ax = list(ax[0]) + [None] * (2 - sum(more))
    if not more[0] and more[1]:
        ax[1], ax[2] = None, ax[1]
    colors = ("C0", "C1", "C2")
    for i, c in enumerate(colors, 1):
        if f"lambda_{i}" in stats:
            ax[0].errorbar(*_series(rows, x, f"lambda_{i}"), fmt="o-", color=c, capsize=3,
                           label=f"{system} λ{i}")
        if i <= len(paper):
            ax[0].axhline(paper[i - 1], color=c, ls="--", lw=1,
                          label=f"paper λ{i} = {paper[i - 1]:.3f} ({symbol} → 0)")
        if f"Kpos_exact_{i}" in stats and ax[1] is not None:
            ax[1].errorbar(*_series(rows, x, f"Kpos_exact_{i}"), fmt="o-", color=c, capsize=3,
                           label=f"K(v̂, e{i}) > 0")
    if "Kpos_exact_any" in stats and ax[1] is not None:
        ax[1].errorbar(*_series(rows, x, "Kpos_exact_any"), fmt="s:", color="k", capsize=3,
                       label="either > 0")
    for stat, label, fmt in (("cone_distance_min", "distance of M from the avoided cone "
                              "points (rad)", "o-"),
                             ("sin2_min", "smallest Σ sin²θᵢ met", "s-"),
                             ("phi_restricted_min", "smallest angle φ (rad)", "^-")):
        if stat in stats and ax[2] is not None:
            xs, ys, _ = _series(rows, x, stat)
            ax[2].plot(xs, ys, fmt, label=label)
    if "cone_distance_min" in stats and ax[2] is not None:
        xs = sorted(r[x] for r in rows)
        ax[2].plot(xs, [2 * e for e in xs], "k:", label="2ε")
    ax[0].set(ylabel=f"Lyapunov exponent ({RATE})", title="Lyapunov exponents")
    if ax[1] is not None:
        ax[1].set(ylabel="fraction of samples", title="Positive sectional curvature")
    if ax[2] is not None:
        ax[2].set(yscale="log", ylabel="rad, or dimensionless",
                  title="Cone points and tangencies")
    ax = [a for a in ax if a is not None]
    ticks = sorted({r[x] for r in rows})
    for a in ax:
        a.set_xscale("log")
        a.set_xticks(ticks, [f"{t:g}" for t in ticks])
        a.minorticks_off()
        a.set_xlabel(xlabel)
        a.legend(fontsize=7)
        a.grid(alpha=0.3)
    fig.suptitle(f"{title} (error bars ± {ERROR_BARS:g} s.e.)", fontsize=10)
    return fig, ax
