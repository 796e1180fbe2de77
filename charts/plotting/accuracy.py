"""The figure of ``charts bench accuracy`` (``charts.runs.accuracy``): what accuracy costs in
CPU time, four work–precision panels."""
from __future__ import annotations

import numpy as np

__all__ = ["work_precision_figure"]


#: The trajectory panels' series of one formulation: (suffix, colour, line, marker).
_SERIES = (("RK4", "C0", "-", "s"), ("RK4 + projection", "C0", "--", "s"),
           ("DOP853", "C3", "-", "o"), ("DOP853 + projection", "C3", "--", "o"))
#: Errors below this (exact zeros) are drawn at it on the log axes.
_FLOOR = 1e-16


def _right(ax):
    """The legend right of the axes, off the data (the project's figures' place)."""
    ax.legend(loc="upper left", bbox_to_anchor=(1.01, 1.0), fontsize=8, frameon=False)


def _trajectory_panel(ax, study, form, letter, scipy_method, mark=None):
    pts = [q for q in study["points"] if q["study"] == "trajectory"]
    info = study["trajectory"]
    for suffix, color, line, marker in _SERIES:
        qs = [q for q in pts if q["method"] == f"{form} {suffix}"]
        if qs:
            ax.loglog([1e3 * q["cpu"] for q in qs], [max(q["error"], _FLOOR) for q in qs],
                      line, color=color, marker=marker, ms=4,
                      mfc="none" if "projection" in suffix else color, label=suffix)
    qs = [q for q in pts if q["method"] == scipy_method]
    if qs:
        ax.loglog([1e3 * q["cpu"] for q in qs], [max(q["error"], _FLOOR) for q in qs], ":",
                  color="0.45", marker="x", ms=5, label="SciPy solve_ivp DOP853\n(baseline)")
    if mark:
        for q, dy in zip(mark, (6, -14)):    # RK4's label above, DOP853's below its ring
            ax.loglog([1e3 * q["cpu"]], [max(q["error"], _FLOOR)], "o", ms=11, mfc="none",
                      mec="k", mew=1.0)
            ax.annotate(q["setting"].replace("=", " = "), (1e3 * q["cpu"], q["error"]),
                        xytext=(8, dy), textcoords="offset points", fontsize=7)
        ax.plot([], [], "o", ms=9, mfc="none", mec="k", label="headline pair")
    ax.axhline(max(info["reference_error"], _FLOOR), color="k", lw=0.7, ls="-.",
               label="reference floor")
    ax.set_xlabel(f"CPU time of one run to t = {info['T']:g} (ms)")
    ax.set_ylabel(f"max error of (θ, u) at t = {info['T']:g} (rad, rad / time unit)")
    ax.set_title(f"({letter}) trajectory, {form} formulation, N = {info['n']}")
    _right(ax)


def work_precision_figure(study: dict, pair, scipy_method: str):
    """The four work–precision panels of ``charts bench accuracy``'s study (a matplotlib
    Figure; ``pair``: the headline's two points, ringed; ``scipy_method``: the baseline's
    method name in the points): the trajectory
    study split by formulation (ambient | chart, the same axes, SciPy's solve_ivp and the
    reference floor in both), the Lyapunov and the curvature studies."""
    from matplotlib.ticker import FuncFormatter, LogLocator, MaxNLocator, NullFormatter

    from .style import new_figure

    pts = study["points"]
    fig, grid = new_figure(2, 2, figsize=(13, 9.5))
    axes = list(grid.ravel())
    _trajectory_panel(axes[0], study, "ambient", "a", scipy_method, mark=pair)
    _trajectory_panel(axes[1], study, "chart", "b", scipy_method)
    axes[1].sharex(axes[0])
    axes[1].sharey(axes[0])
    ax = axes[2]
    qs = [q for q in pts if q["study"] == "lyapunov"]
    L = study["lyapunov"]
    lam = [float(q["note"].split("=")[1].split("+-")[0]) for q in qs]
    ax.errorbar([1e3 * q["cpu"] for q in qs], [x - L["lambda1_reference"] for x in lam],
                yerr=[q["stderr"] for q in qs], fmt="-o", ms=4, capsize=3,
                label="λ̄₁(dt) − λ̄₁(dt_ref)\n± standard error")
    for i, (q, x) in enumerate(zip(qs, lam)):    # labels above and below in turn: apart
        ax.annotate(q["setting"], (1e3 * q["cpu"], x - L["lambda1_reference"]), fontsize=7,
                    xytext=(4, 4 if i % 2 == 0 else -11), textcoords="offset points")
    ax.axhline(0.0, color="k", lw=0.6)
    ax.axhline(L["paper"] - L["lambda1_reference"], color="g", ls=":", lw=0.8,
               label=f"paper ({L['paper']:.3f})")
    ax.set_xscale("log")
    ax.set_xlabel(f"CPU time of {L['members']} trajectories × T = {L['T']:g} (ms)")
    ax.set_ylabel(f"λ̄₁ − λ̄₁(dt = {L['reference_dt']:g}) (1 / time unit)")
    ax.set_title(f"(c) leading Lyapunov exponent, N = 3 "
                 f"(λ̄₁(dt_ref) = {L['lambda1_reference']:.4f})")
    _right(ax)
    ax = axes[3]
    qs = [q for q in pts if q["study"] == "curvature" and "numerical" in q["method"]]
    ax.loglog([1e3 * q["cpu"] for q in qs], [q["error"] for q in qs], "-o", ms=4,
              label="numerical route\n(eqs 19–21)")
    for q in qs:
        ax.annotate(q["setting"], (1e3 * q["cpu"], q["error"]), fontsize=7, xytext=(3, 3),
                    textcoords="offset points")
    ex = [q for q in pts if q["study"] == "curvature" and "exact" in q["method"]]
    if ex:
        ax.loglog([1e3 * ex[0]["cpu"]], [max(ex[0]["error"], _FLOOR)], "k*", ms=9,
                  label="exact route\n(added cost)")
    ax.set_xlabel("CPU time (ms)")
    ax.set_ylabel("median |K − K_eq22| / |K_eq22| (relative)")
    ax.set_title("(d) N = 3 curvature against eq (22)")
    _right(ax)
    for ax in axes:   # x labels readable at any span: two or more powers of 10 inside the
        lo, hi = ax.get_xlim()      # axis: those only; else 1-2-5 labels; narrower than 4x: plain
        decades = np.floor(np.log10(hi)) - np.ceil(np.log10(lo)) + 1
        if hi < 4 * lo:
            ax.xaxis.set_major_locator(MaxNLocator(4))
        elif decades < 2:
            ax.xaxis.set_major_locator(LogLocator(subs=(1.0, 2.0, 5.0)))
        if decades < 2:
            ax.xaxis.set_major_formatter(FuncFormatter(lambda x, _: f"{x:.2g}".replace(
                "e+0", "e").replace("e-0", "e-") if not 1e-3 <= x < 1e4 else f"{x:g}"))
        ax.xaxis.set_minor_formatter(NullFormatter())
    return fig
