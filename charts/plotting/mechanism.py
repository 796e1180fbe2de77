"""Figures of a mechanism's results (``charts.analyses.mechanism_lyapunov``): its Lyapunov
exponents with their error bars beside the batch estimates behind them.  Named by the
mechanism and its parameter values, as the rotors' figures are by N."""
from __future__ import annotations

import numpy as np

from .analyses import plot_ensemble_exponents, value_error

__all__ = ["plot_mechanism_exponents", "mechanism_label"]


def mechanism_label(params) -> str:
    """"triple_linkage(r=0.3, l=1, …)": a mechanism result's ``params`` in a few words (its
    name and parameter values, at most 6 of them)."""
    values = params.get("parameters") or {}
    shown = ", ".join(f"{k}={float(v):g}" for k, v in list(values.items())[:6])
    more = ", …" if len(values) > 6 else ""
    name = str(params.get("mechanism", "mechanism"))
    return name if not values or "(" in name else f"{name}({shown}{more})"


def plot_mechanism_exponents(exponents, stderr, batches, params, *, ax=None, title=None):
    """λᵢ ± standard error (square, black bars) for i = 1…k beside the batch estimates
    ``batches`` (n_batches, k; dots spread sideways), whose spread the bars come from; the
    mechanism (`mechanism_label`), averaging time and speed in the title."""
    lam = np.asarray(exponents, dtype=float)
    se = np.asarray(stderr, dtype=float)
    B = np.asarray(batches, dtype=float).reshape(-1, lam.size)
    k, m = lam.size, B.shape[0]
    T, speed = params.get("t_final"), params.get("speed")
    run = ", ".join(x for x in (f"T = {T:g}" if T is not None else "",
                                f"speed {speed:.4g}" if speed is not None else "",
                                f"{m} batches") if x)
    fig, ax = plot_ensemble_exponents(
        B, lam, se, ax=ax, dots="batch estimates", bars="λ ± standard error",
        title=title or f"Lyapunov exponents, {mechanism_label(params)}\n({run})")
    for i in range(k):
        ax.annotate(value_error(lam[i], se[i]), (i + 1.42, lam[i]), fontsize=8, va="center")
    ax.axhline(0.0, color="0.6", lw=0.8)
    ax.set_xlim(0.5, k + 1.1)
    return fig, ax
