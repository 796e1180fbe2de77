"""Energy localisation: how much of the kinetic energy T = ½ Σ mᵢuᵢ² the most energetic
rotor holds.

At large N one rotor now and then carries a large share of the energy for a long stretch of
time (docs/large-n.md), and the exponents of a run depend on how long.  The drivers sample
the largest share max_i mᵢuᵢ² / Σ_j mⱼuⱼ² at every re-orthonormalisation of the vectors (a
fixed interval of the run, 0.1 time units by default) into a histogram of `SHARE_BINS` equal
bins over [0, 1] (`record_share`; the lanes: `energies_lanes`, `record_share_of`); `localised_fraction` reads from it the
fraction of the samples in which one rotor holds at least a given share.  The histogram
costs O(N) per sample and changes no other number of the run.
"""
from __future__ import annotations

import numpy as np
from ..jit import njit

from .checks import finite_array, number
from .primitives import LANE_WIDTH

__all__ = ["SHARE_BINS", "record_share", "energies_lanes", "record_share_of", "largest_shares",
           "localised_fraction", "share_bin", "share_edges", "LOCALISED_SHARE"]

#: Bins of the histogram of the largest share (width 0.01: thresholds at whole per cent are
#: read exactly).
SHARE_BINS = 100
#: The share above which a run counts as localised by default: one rotor holding over 40 % of
#: the kinetic energy (at N ≥ 16 the mean share of a rotor is at most 1/16).
LOCALISED_SHARE = 0.4


@njit(cache=True, inline="always")
def _bin(top, total, nbins):
    b = int(top * nbins / total)
    return b if b < nbins else nbins - 1


@njit(cache=True)
def record_share(y, n, m, hist):
    """Add the largest kinetic-energy share of the state y = (θ, u) (masses m) to the
    histogram ``hist`` (its size the number of bins; size 0: nothing recorded).  A called
    function, not inlined: once every re-orthonormalisation its call costs nothing, and the
    time loops that inline it compiled 0.6–3 s longer on first use (measured)."""
    nbins = hist.size
    if nbins == 0:
        return
    total = 0.0
    top = 0.0
    for j in range(n):
        e = m[j] * y[n + j] * y[n + j]
        total += e
        if e > top:
            top = e
    if total > 0.0:
        hist[_bin(top, total, nbins)] += 1


@njit(cache=True, inline="always")
def energies_lanes(Zf, n, m, Lp, total, top):
    """The kinetic energies 2T = Σ mⱼuⱼ² (``total``) and their largest term (``top``) of every
    lane of the lanes' layout (element i of lane l at i·Lp + l, Lp a multiple of
    `LANE_WIDTH`), in blocks of `LANE_WIDTH` lanes (one vector register)."""
    W = LANE_WIDTH
    for l0 in range(0, Lp, W):
        for t in range(W):
            total[l0 + t] = 0.0
            top[l0 + t] = 0.0
        for j in range(n):
            b = (n + j) * Lp + l0
            for t in range(W):
                e = m[j] * Zf[b + t] * Zf[b + t]
                total[l0 + t] += e
                top[l0 + t] = max(top[l0 + t], e)


@njit(cache=True, inline="always")
def record_share_of(top, total, hist, l):
    """Add the share top/total to row l of the histograms ``hist`` (lanes, bins)."""
    nbins = hist.shape[1]
    if total > 0.0:
        hist[l, _bin(top, total, nbins)] += 1


def largest_shares(u, masses):
    """The largest kinetic-energy share of each state, u shape (..., N) (NumPy; the
    reference of the compiled recorders)."""
    e = np.asarray(masses) * np.asarray(u, dtype=float) ** 2
    return e.max(axis=-1) / e.sum(axis=-1)


def share_edges(nbins=SHARE_BINS):
    """The lower edges of the histogram's bins (bin b holds shares in [b/B, (b+1)/B))."""
    return np.arange(nbins) / nbins


def share_bin(share, nbins=SHARE_BINS) -> int:
    """The first bin counted by ``share``: a real number in [0, 1] on a bin edge (a multiple
    of 1/``nbins``); ValueError naming ``share`` otherwise (a bool or a string is not a
    share, ``charts.geometry.checks.number``)."""
    share = number("share", share)
    x = share * nbins
    b = int(round(x))
    if not 0.0 <= share <= 1.0 or abs(x - b) >= 1e-9:
        raise ValueError(f"share must be a multiple of 1/{nbins} in [0, 1] (the histogram's bin "
                         f"edges), got {share!r}")
    return b


def localised_fraction(hist, share=LOCALISED_SHARE):
    """Fraction of the samples of the histogram ``hist`` (counts >= 0, last axis the bins) in
    which one rotor held at least ``share`` of the kinetic energy.  ``share`` must be a real
    number in [0, 1] on a bin edge (a multiple of 1/B: 0.01 for `SHARE_BINS`: `share_bin`);
    ValueError otherwise (``hist``: an array of real numbers >= 0, at least 1-D)."""
    hist = finite_array("hist", hist)
    if hist.ndim == 0:
        raise ValueError(f"hist must be an array of counts (last axis the bins), got "
                         f"{hist.tolist()!r}")
    nbins = hist.shape[-1]
    if nbins == 0:
        raise ValueError("no energy shares were recorded")
    b = share_bin(share, nbins)
    if np.any(hist < 0):
        raise ValueError(f"hist must hold counts >= 0, got {hist.min():g}")
    total = hist.sum(axis=-1)
    if np.any(total == 0):
        raise ValueError("the histogram holds no samples")
    return hist[..., b:].sum(axis=-1) / total
