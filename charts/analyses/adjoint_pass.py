"""The backward pass of the angle test (section 4, ``charts.analyses.hyperbolicity``): eq (8)
integrated backward from each trajectory checkpoint jointly with m adjoint vectors
(ẇ = −J(x(t))ᵀ w), by RK4 with the forward kernel's step policy, and at the sample points
the sines of the angles (the smallest singular values of W Vᵀ)."""
from __future__ import annotations


import numpy as np
from numba import njit

from ..flows.ambient import adjoint_factors, adjoint_rate
from ..geometry.primitives import sincos
from ..geometry.projection import project_tangent_euclidean_sc
from ..solvers.status import (CAP_FRACTION, RUNNING, SINGULAR, SINGULAR_S, fixed_step_status,
                              substep_count, sum_squares)
from ..solvers.tangent import orthonormal_rows, orthonormalize, stacked_rk4_step
from .singular_values import smallest_singular_values

__all__ = ["adjoint_step", "backward_kernel", "adjoint_vectors_rate"]

_CAP = CAP_FRACTION["rk4"]


@njit(cache=True, inline="always")
def adjoint_vectors_rate(Zt, n, minv, s, c, lam, iB, fa, fb, fp, _unused, K, o, R, d):
    """ẇ = −J(x)ᵀ w for the R − 1 adjoint vectors after the state in Zt into K[o + d:], the
    per-rotor factors (``charts.flows.ambient.adjoint_factors``) once for all of them (the
    hook of ``charts.solvers.tangent.stacked_rk4_step``)."""
    zero = np.uint64(0)
    adjoint_factors(Zt, zero, n, minv, s, c, lam, iB, fa, fb, fp)
    for r in range(np.uint64(1), R):
        adjoint_rate(Zt, r * d, n, minv, s, fa, fb, fp, K, o + r * d)


@njit(cache=True, inline="always")
def _adjoint_rk4(Zf, Zt, K, s0, c0, th, dl, s, c, fa, fb, fp, minv, wts, h, n, R, d, L):
    """One RK4 step of size h (h < 0: backward), in place, of eq (8) for the state Zf[:2N]
    and of the adjoint flow ẇ = −Jᵀw for the R − 1 vectors after it: the one stacked step
    (``charts.solvers.tangent.stacked_rk4_step``) with the adjoint's hook."""
    stacked_rk4_step(Zf, Zt, K, th, dl, s, c, fa, fb, fp, fp, s0, c0, minv, wts, h, n, R, d, L,
                     adjoint_vectors_rate)


@njit(cache=True)
def adjoint_step(Z, minv, a, h):
    """One RK4 step of size h (h < 0: backward), in place, of eq (8) for Z[0] and of the
    adjoint flow ẇ = −Jᵀw for the rows Z[1:] (weights a), as in the backward pass."""
    R, d = Z.shape
    n = d // 2
    L = R * d
    s0 = np.empty(n)
    c0 = np.empty(n)
    sincos(Z[0], 0, n, a, s0, c0)
    _adjoint_rk4(Z.reshape(L), np.empty(L), np.empty(4 * L), s0, c0, np.empty(n), np.empty(n),
                 np.empty(n), np.empty(n), np.empty(n), np.empty(n), np.empty(n), minv, a, h,
                 np.uint64(n), np.uint64(R), np.uint64(d), np.uint64(L))


@njit(cache=True)
def backward_kernel(ck, W, minv, wts, dt, ck_every, first_sample, sample_every, reorth, V, w,
                    logs, sf, sr):
    """Backward pass over the segments (last first) down to step ``first_sample``, W
    re-orthonormalised at every step index that is a multiple of ``reorth`` (which divides
    the sample steps, logs of the norms added to ``logs``); at the k-th sample step the
    smallest singular values of W V_kᵀ into sf[k] (full) and of W_r V_kᵀ into sr[k]
    (restricted), V_k the m forward vectors after the state in V[k] (the forward pass's
    records, shape (S, (1 + m)·2N)).  Returns (status, step): RUNNING, or NONFINITE /
    SINGULAR (the forward kernel's tests) at that step."""
    d = ck.shape[1]
    n = d // 2
    kk = W.shape[0]
    Z = np.empty((1 + kk, d))
    Z[1:] = W
    Wv = Z[1:]
    y = Z[0]
    L = (1 + kk) * d
    Zf = Z.reshape(L)
    nu, Ru, du, Lu = np.uint64(n), np.uint64(1 + kk), np.uint64(d), np.uint64(L)
    zt = np.empty(L)
    K = np.empty(4 * L)
    s0 = np.empty(n)
    c0 = np.empty(n)
    th = np.empty(n)
    dl = np.empty(n)
    s = np.empty(n)
    c = np.empty(n)
    fa = np.empty(n)
    fb = np.empty(n)
    fp = np.empty(n)
    ga = np.empty(d)
    gb = np.empty(d)
    M = np.empty((2, kk, kk))
    sv = np.empty(2)
    Wr = np.empty((kk, d))
    nseg = ck.shape[0] - 1
    S = V.shape[0]
    for seg in range(nseg - 1, first_sample // ck_every - 1, -1):
        Z[0] = ck[seg + 1]
        sincos(Zf, 0, n, wts, s0, c0)
        step = (seg + 1) * ck_every
        to_reorth = step % reorth or reorth  # steps to the next multiple of reorth
        j = step - first_sample              # (> 0) and to the next sample, of index q − 1
        q = -(-j // sample_every)
        to_sample = j % sample_every or sample_every
        for jj in range(ck_every):
            # the forward kernel's step policy (charts.solvers.status): near an N = 4
            # singular point the step is cut into equal sub-steps within the cap
            code, hc = fixed_step_status(sum_squares(s0, 0, n), sum_squares(Zf, n, n), dt,
                                         _CAP)
            # (the exits, never taken after a forward pass that passed, also keep the loop
            # fast: without them Numba's code for this loop is twice as slow, measured)
            if code != RUNNING:
                return code, step
            # (the forward kernel's sub-steps: equal ones within the cap, each from a point
            # that passes the singular-point test)
            nsub = substep_count(dt, hc)
            h = -dt / nsub
            for sub in range(nsub):
                if nsub > 1 and sum_squares(s0, 0, n) < SINGULAR_S:
                    return SINGULAR, step
                _adjoint_rk4(Zf, zt, K, s0, c0, th, dl, s, c, fa, fb, fp, minv, wts, h, nu, Ru,
                             du, Lu)
            step -= 1
            to_reorth -= 1
            if to_reorth == 0:
                to_reorth = reorth
                orthonormalize(Wv, w, logs)
            to_sample -= 1
            if to_sample == 0:
                to_sample = sample_every
                q -= 1
                if q < S:
                    for r in range(kk):
                        for i in range(d):
                            Wr[r, i] = Wv[r, i]
                    project_tangent_euclidean_sc(y, Wr, s0, c0, ga, gb)
                    orthonormal_rows(Wr, w)
                    for r in range(kk):
                        for s_ in range(kk):
                            af = 0.0
                            ar = 0.0
                            for i in range(d):
                                af += Wv[r, i] * V[q, d + s_ * d + i]
                                ar += Wr[r, i] * V[q, d + s_ * d + i]
                            M[0, r, s_] = af
                            M[1, r, s_] = ar
                    smallest_singular_values(M, sv)
                    sf[q] = sv[0]
                    sr[q] = sv[1]
            if step == first_sample:
                return RUNNING, step
    return RUNNING, first_sample
