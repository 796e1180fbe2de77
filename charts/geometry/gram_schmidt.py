"""Modified Gram–Schmidt (eq 18) of tangent vectors in the weighted inner product
⟨a, b⟩ = Σ wᵢ aᵢ bᵢ (weights: ``charts.solvers.tangent.inner_weights``), one trajectory at a
time (`orthonormalize`) or for L trajectories at once (`orthonormalize_lanes`, the layout of
``charts.solvers.lanes``): the same operations per trajectory in the same order, so the
same bits (sqrt is correctly rounded in vector units too; the logs of the norms, libm, stay
the caller's, lane by lane).  It lives with the geometry so that every integrator uses it:
the rotors' tangent flows (``charts.solvers``) and a mechanism's (``charts.mechanism``)."""
from __future__ import annotations

from math import log, sqrt

from ..jit import njit

from .primitives import LANE_WIDTH

__all__ = ["inner_term", "orthonormalize", "orthonormal_rows", "orthonormalize_lanes"]


@njit(cache=True, inline="always")
def inner_term(w, a, b):
    """The i-th term wᵢ aᵢ bᵢ of the inner product ⟨a, b⟩ of eq (18)."""
    return w * a * b


@njit(cache=True, inline="always")
def _gram_schmidt_row(X, w, r, d):
    """Row r of X made orthogonal to rows 0 … r−1 (orthonormal) and normalised in
    ⟨a, b⟩ = Σ wᵢ aᵢ bᵢ; returns its norm before normalising."""
    for q in range(r):
        p = 0.0
        for i in range(d):
            p += inner_term(w[i], X[r, i], X[q, i])
        for i in range(d):
            X[r, i] -= p * X[q, i]
    nrm = 0.0
    for i in range(d):
        nrm += inner_term(w[i], X[r, i], X[r, i])
    nrm = sqrt(nrm)
    for i in range(d):
        X[r, i] /= nrm
    return nrm


@njit(cache=True)
def orthonormalize(X, w, logs):
    """Modified Gram–Schmidt (eq 18) of the rows of X in ⟨a, b⟩ = Σ wᵢ aᵢ bᵢ, in place;
    logs[r] += log of the r-th norm."""
    k, d = X.shape
    for r in range(k):
        logs[r] += log(_gram_schmidt_row(X, w, r, d))


@njit(cache=True)
def orthonormal_rows(X, w):
    """`orthonormalize` without the logarithms of the norms (a basis only)."""
    k, d = X.shape
    for r in range(k):
        _gram_schmidt_row(X, w, r, d)


@njit(cache=True, inline="always")
def orthonormalize_lanes(Z, o, k, d, L, w, p, nrm):
    """`orthonormalize` of L lanes at once, the same operations per lane in the same order:
    element i of row r of lane l at Z[o + (r·d + i)·L + l] (L a multiple of `LANE_WIDTH`);
    the r-th norm of lane l into nrm[r·L + l] (its log is the caller's: libm, lane by lane);
    p, shape (L,), is work space.  Sizes unsigned."""
    W = LANE_WIDTH
    dL = d * L
    for l0 in range(L - L, L, W):
        for r in range(k):
            ro = o + r * dL + l0
            for q in range(r):
                qo = o + q * dL + l0
                for t in range(W):
                    p[l0 + t] = 0.0
                for i in range(d):
                    for t in range(W):
                        p[l0 + t] += inner_term(w[i], Z[ro + i * L + t], Z[qo + i * L + t])
                for i in range(d):
                    for t in range(W):
                        Z[ro + i * L + t] -= p[l0 + t] * Z[qo + i * L + t]
            no = r * L + l0
            for t in range(W):
                nrm[no + t] = 0.0
            for i in range(d):
                for t in range(W):
                    nrm[no + t] += inner_term(w[i], Z[ro + i * L + t], Z[ro + i * L + t])
            for t in range(W):
                nrm[no + t] = sqrt(nrm[no + t])
            for i in range(d):
                for t in range(W):
                    Z[ro + i * L + t] /= nrm[no + t]
