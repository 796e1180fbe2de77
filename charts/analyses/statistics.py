"""Error bars: batch means along one trajectory, and the spread of independent ones; the law
of the smallest values of a sample (hyperbolicity angles near zero) and block minima."""
from __future__ import annotations

import numpy as np

from ..geometry.checks import finite_array, number

__all__ = ["standard_error", "batch_ends", "batch_estimates", "small_value_law",
           "pool_small_value_laws", "block_minima", "law_from_batches", "jackknife_slopes"]


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


def _blocks(n, n_blocks):
    """Slices of ``n_blocks`` contiguous, nearly equal blocks of ``range(n)``."""
    edges = np.linspace(0, n, n_blocks + 1).round().astype(int)
    return [slice(a, b) for a, b in zip(edges[:-1], edges[1:])]


def small_value_law(samples, x0, n_batches=10):
    """The law of the smallest values, P(X < x) = A x^β for 0 < x ≤ ``x0``, fitted to the
    time-ordered ``samples`` (1-D, > 0; e.g. the hyperbolicity angles of one trajectory).

    Returns dict(count k below x0, n, x0, exponent β̂ and its standard error, coef2 =
    A for β = 2, i.e. P(X < x0)/x0², and its standard error).  β̂ = k / Σ ln(x0/xᵢ) over the
    k samples below x0 is the maximum-likelihood (Hill) estimate; both errors are batch
    means over ``n_batches`` contiguous blocks (β̂ as a ratio estimator, sums per block), so
    that correlated neighbours (one tangency passage gives several small samples) are not
    counted as independent.  For independent samples they tend to β/√k and
    √(p(1−p)/n)/x0².  NaN where undefined (no sample below x0, fewer than two batches
    holding samples below it: `law_from_batches`).
    """
    x = finite_array("samples", samples, ndim=1)
    if x.size == 0:
        raise ValueError(f"samples must be a non-empty 1-D array, got shape {x.shape}")
    if np.any(x <= 0):
        raise ValueError("samples must be finite and > 0 (a power law of small values)")
    x0 = number("x0", x0)
    if not x0 > 0:
        raise ValueError(f"x0 must be a finite number > 0, got {x0!r}")
    if isinstance(n_batches, bool) or not isinstance(n_batches, (int, np.integer)) \
            or n_batches < 1 or n_batches > x.size:
        raise ValueError(f"n_batches must be an integer from 1 to the sample count {x.size}, "
                         f"got {n_batches!r}")
    below = x < x0
    logs = np.where(below, np.log(x0 / np.where(below, x, x0)), 0.0)
    blocks = _blocks(x.size, int(n_batches))
    kb = np.array([below[b].sum() for b in blocks], dtype=float)
    Lb = np.array([logs[b].sum() for b in blocks])
    fb = np.array([below[b].mean() for b in blocks])
    return law_from_batches(int(below.sum()), float(logs.sum()), int(x.size), kb, Lb, fb, x0)


def law_from_batches(count, logsum, n, kb, Lb, fb, x0):
    """`small_value_law` from its sums: ``count`` samples of ``n`` below ``x0`` and their
    ``logsum`` Σ ln(x0/xᵢ); per batch (B,) the counts ``kb``, log sums ``Lb`` and fractions
    below ``fb`` (the batches: blocks of one series, or independent series such as the
    members of an ensemble).  β̂ = count / logsum; its error by the batch-means ratio
    estimator, A's by the spread of ``fb``.  Both errors are NaN (undefined) where fewer than
    two batches hold samples below ``x0``: the spread between batches is then unknown, not
    small (with one such batch the ratio estimator's residuals vanish by construction, and a
    zero error would claim an exact exponent)."""
    kb, Lb, fb = (np.asarray(a, dtype=float) for a in (kb, Lb, fb))
    k, L = int(count), float(logsum)
    beta = k / L if L > 0 else np.nan
    B = len(kb)
    spread = B >= 2 and np.count_nonzero(kb) >= 2
    if spread and L > 0:
        beta_se = float(np.sqrt(B / (B - 1) * np.sum((kb - beta * Lb) ** 2)) / L)
    else:
        beta_se = np.nan
    with np.errstate(over="ignore", under="ignore"):   # 0 for a tiny x0: A undefined (NaN)
        x02 = float(np.float64(x0) ** 2)
    return dict(count=k, n=int(n), x0=float(x0), exponent=float(beta),
                exponent_se=beta_se, coef2=k / n / x02 if x02 > 0 else np.nan,
                coef2_se=float(standard_error(fb)) / x02 if x02 > 0 and spread else np.nan)


def block_minima(samples, sizes):
    """Mean minimum of ``size`` consecutive samples, for each of ``sizes``: the minima of
    the disjoint consecutive blocks of ``size`` samples, their mean and its standard error
    (blocks taken as independent).  ``samples``: shape (S,), or (R, S) for R independent
    series (blocks never straddle two rows; each row's incomplete last block is dropped).
    Returns a list of dict(size, blocks, mean, se).  Values bounded away from zero give
    means that level off as the size grows; independent samples with P(X < x) = A x² near
    zero give means that fall like √(π / (4 A size))."""
    x = np.asarray(samples, dtype=float)
    if x.ndim == 1:
        x = x[None, :]
    if x.ndim != 2 or x.size == 0 or not np.all(np.isfinite(x)):
        raise ValueError("samples must be a non-empty array (S,) or (R, S) of finite numbers, "
                         f"got shape {np.shape(samples)}")
    out = []
    for s in sizes:
        if isinstance(s, bool) or not isinstance(s, (int, np.integer)) or not 1 <= s <= x.shape[1]:
            raise ValueError(f"sizes must be integers from 1 to the length of a series "
                             f"{x.shape[1]}, got {s!r}")
        m = x[:, : x.shape[1] // s * s].reshape(x.shape[0], -1, s).min(axis=2).ravel()
        out.append(dict(size=int(s), blocks=int(m.size), mean=float(m.mean()),
                        se=float(standard_error(m))))
    return out


def pool_small_value_laws(laws):
    """One :func:`small_value_law` from those of independent samples with the same ``x0``
    (e.g. the seeds of a sweep point): counts and log sums add, so the pooled exponent and
    coefficient equal those of the concatenated samples exactly; the errors add the
    per-sample batch-means variances of the same sums (a sample without values below x0
    adds none; one whose error is undefined makes the pooled error undefined).  Each law is
    a dict with count, n, x0, exponent, exponent_se, coef2, coef2_se (the errors, and the
    exponent where count is 0, may be NaN/None)."""
    laws = list(laws)
    if not laws:
        raise ValueError("laws must hold at least one small_value_law result")
    x0 = {float(d["x0"]) for d in laws}
    if len(x0) != 1:
        raise ValueError(f"the laws must share one x0, got {sorted(x0)}")
    x0 = x0.pop()
    k = np.array([d["count"] for d in laws], dtype=float)
    n = np.array([d["n"] for d in laws], dtype=float)
    beta = np.array([np.nan if d["exponent"] is None else d["exponent"] for d in laws], float)
    bse = np.array([np.nan if d["exponent_se"] is None else d["exponent_se"] for d in laws], float)
    L = np.where(k > 0, k / np.where(k > 0, beta, 1.0), 0.0)       # Σ ln(x0/x) per sample
    K, Lt, N = k.sum(), L.sum(), n.sum()
    beta_p = K / Lt if Lt > 0 else np.nan
    beta_se = float(np.sqrt(np.sum(np.where(k > 0, bse * L, 0.0) ** 2)) / Lt) if Lt > 0 \
        else np.nan
    # a part without samples below x0 adds to n, not to the spread (its own error is undefined)
    cse = np.where(k > 0, np.array([d["coef2_se"] for d in laws], dtype=float), 0.0)
    return dict(count=int(K), n=int(N), x0=x0, exponent=float(beta_p), exponent_se=beta_se,
                coef2=float(K / N / x0 ** 2), coef2_se=float(np.sqrt(np.sum((n * cse) ** 2)) / N))


def jackknife_slopes(means, groups):
    """[slope, jackknife se] of log10(mean of column i + 1 / mean of column i) for each pair
    of neighbouring columns of ``means`` (members, columns; NaN: a member without that
    column), over the members holding both, the jackknife over at most ``groups`` groups of
    members (se NaN with fewer than 2)."""
    out = []
    for i in range(means.shape[1] - 1):
        m = means[:, i:i + 2]
        m = m[~np.isnan(m).any(axis=1)]
        L = m.shape[0]
        parts = np.array_split(np.arange(L), min(groups, L))

        def slope(rows):
            with np.errstate(divide="ignore", invalid="ignore"):    # a mean of 0
                return np.log(m[rows, 1].mean() / m[rows, 0].mean()) / np.log(10.0)
        full = slope(slice(None))
        if len(parts) >= 2:
            jack = np.array([slope(np.setdiff1d(np.arange(L), g)) for g in parts])
            G = len(parts)
            se = float(np.sqrt((G - 1) / G * np.sum((jack - jack.mean()) ** 2)))
        else:
            se = float("nan")
        out.append([float(full), se])
    return out
