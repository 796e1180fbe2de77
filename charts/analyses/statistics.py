"""Error bars: batch means along one trajectory, and the spread of independent ones."""
from __future__ import annotations

import numpy as np

__all__ = ["standard_error", "batch_ends", "batch_estimates"]


def standard_error(samples, axis=0):
    """Two-sided standard error of the mean of independent ``samples`` along ``axis``:
    std(ddof=1)/√count (NaN for fewer than two samples)."""
    samples = np.asarray(samples, dtype=float)
    m = samples.shape[axis]
    if m < 2:  # no spread to measure
        return np.full(np.delete(samples.shape, axis), np.nan)
    return samples.std(axis=axis, ddof=1) / np.sqrt(m)


def batch_ends(total, n_batches, grid):
    """Ends of ``n_batches`` nearly equal blocks of ``total`` units, each a multiple of
    ``grid`` (0 excluded, ``total`` included).  Used by every route that cuts a run into
    batches, so that they cut it at the same steps."""
    ends = [grid * int(round(total / grid * (b + 1) / n_batches)) for b in range(n_batches)]
    ends[-1] = total
    return ends


def batch_estimates(cumulative, times):
    """Per-block rates from cumulative sums at the block ends: ``cumulative`` (B, k) at
    ``times`` (B,) (block b spans times[b−1]..times[b], times[−1] = 0).  Returns
    (estimates (B, k), two-sided standard error (k,))."""
    L = np.asarray(cumulative, dtype=float)
    T = np.asarray(times, dtype=float)
    prev = np.vstack([np.zeros((1, L.shape[1])), L[:-1]])
    Tp = np.concatenate([[0.0], T[:-1]])
    est = (L - prev) / (T - Tp)[:, None]
    return est, standard_error(est)
