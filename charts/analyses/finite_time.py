"""Finite-time Lyapunov exponents and the domination test of the Oseledets splitting.

Input: local growth rates ``rates`` (S, D) (1/time) over S consecutive intervals of length
``sample_every`` — the Gram–Schmidt rates log R_ii/τ of eq (18) or the rates along the
covariant Lyapunov vectors (``charts.analyses.covariant``).  A finite-time exponent over a
window of length T = k·sample_every is the mean of k consecutive rates; windows do not
overlap, so the S // k windows of one length are as independent as the trajectory allows.

Domination (a third view of hyperbolicity besides the angles): the splitting E_u ⊕ E_cs is
dominated if for some window length T every finite-time exponent along the unstable CLVs
exceeds every one along the centre-stable CLVs, at every time.  `domination` reports the
fraction of windows where that order fails, for several T: for a dominated splitting it
vanishes beyond some T, for a non-dominated one it decays without vanishing.
"""
from __future__ import annotations

import numpy as np

from ..geometry.checks import finite_array, integer
from .arguments import positive_time, steps_of

__all__ = ["window_means", "finite_time_statistics", "domination"]


def window_means(rates, sample_every, window, name="window", rates_name="rates"):
    """Finite-time exponents (W, D): means of ``rates`` (S, D) over the W = S // k
    non-overlapping windows of ``window`` = k·sample_every (a whole multiple; ValueError
    naming ``name`` and sample_every otherwise, or ``name`` and ``rates_name`` if no window
    fits)."""
    rates = finite_array(rates_name, rates, ndim=2)
    tau = positive_time("sample_every", sample_every)
    try:
        k = steps_of(name, window, tau)
    except ValueError as exc:
        raise ValueError(f"{exc} (the step here is sample_every={tau:g})") from None
    W = rates.shape[0] // k
    if W < 1:
        raise ValueError(f"{name}={float(window):g} is longer than the {rates.shape[0] * tau:g} "
                         f"time units of {rates_name} ({rates.shape[0]} samples of "
                         f"sample_every={tau:g}); use a shorter window")
    return rates[:W * k].reshape(W, k, rates.shape[1]).mean(axis=1)


def finite_time_statistics(rates, sample_every, windows):
    """Distribution of the finite-time exponents for each window length in ``windows``:
    {window: dict(count, mean (D,), std (D,), p01, p50, p99 (D,) percentiles 1/50/99,
    frac_nonpositive_leading: fraction of windows whose leading exponent is <= 0)}."""
    out = {}
    for i, w in enumerate(window_lengths(windows)):
        L = window_means(rates, sample_every, w, f"windows[{i}]")
        p01, p50, p99 = np.percentile(L, [1, 50, 99], axis=0)
        out[float(w)] = dict(count=int(L.shape[0]), mean=L.mean(0), std=L.std(0), p01=p01,
                             p50=p50, p99=p99,
                             frac_nonpositive_leading=float((L[:, 0] <= 0).mean()))
    return out


def domination(growth, m, sample_every, windows):
    """Order of the finite-time exponents along the CLVs, ``growth`` (S, D) (index 0 the
    largest exponent), for each window length: {window: dict(count, split: fraction of
    windows where min over the m unstable CLVs <= max over the others (E_u does not dominate
    E_cs), pairs (D−1,): fraction where CLV i grows slower than CLV i+1)}."""
    growth = finite_array("growth", growth, ndim=2)
    m = integer("m", m, 1, max(1, growth.shape[1] - 1))
    out = {}
    for i, w in enumerate(window_lengths(windows)):
        L = window_means(growth, sample_every, w, f"windows[{i}]", "growth")
        split = L[:, :m].min(axis=1) <= L[:, m:].max(axis=1)
        out[float(w)] = dict(count=int(L.shape[0]), split=float(split.mean()),
                             pairs=(L[:, :-1] < L[:, 1:]).mean(axis=0))
    return out


def window_lengths(windows) -> list:
    """``windows`` as a list of floats: a non-empty 1-D sequence of positive finite window
    lengths (time units); ValueError naming ``windows`` otherwise."""
    w = finite_array("windows", windows, ndim=1)
    if w.size == 0 or not np.all(w > 0):
        raise ValueError(f"windows must be a non-empty list of positive window lengths "
                         f"(time units), got {w.tolist()}")
    return w.tolist()
