"""The backward pass of the angle test (section 4, ``charts.analyses.hyperbolicity``): eq (8)
integrated backward from each trajectory checkpoint jointly with m adjoint vectors
(ẇ = −J(x(t))ᵀ w): a formulation of the stacked flows' one time loop
(``charts.solvers.tangent.stacked_loop``, the adjoint hook `adjoint_vectors_rate`, step −dt,
the forward kernel's step policy), and at the sample points the sines of the angles (the
smallest singular values of W Vᵀ)."""
from __future__ import annotations


import numpy as np
from numba import types
from ..jit import njit

from ..flows.ambient import adjoint_factors, adjoint_rate
from ..jit.kernel_calls import CallsKernel
from ..geometry.primitives import sincos
from ..geometry.projection import project_tangent_euclidean_sc
from ..solvers.status import RUNNING
from ..solvers.driver import Phases
from ..solvers.tangent import (Records, Stack, Stepping, orthonormal_rows, stacked_loop,
                               stacked_rk4_step, stacked_work)
from .singular_values import smallest_singular_values_into

__all__ = ["adjoint_step", "backward_kernel", "backward_loop", "adjoint_vectors_rate", "sample_sines"]


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
def sample_sines(rec, row, V, q, w, y, sc, Wr, ga, gb, M, sv, A):
    """At one sample point: the smallest singular values of W Vᵀ into sv[0] (full) and of
    W_r Vᵀ into sv[1] (restricted), W the rows after the state in rec[row] (the backward
    pass's record: the state, the m rows, then the weighted sin and cos of the state's angles
    as the pass kept them), W_r those rows projected Euclidean-orthogonally onto
    T_r at the state and re-orthonormalised, V the m forward vectors after the state in
    V[q] (the forward pass's record).  y (2N,), sc (2, N), Wr (m, 2N), ga, gb (2N,),
    M (2, m, m), A (m, m): work space."""
    kk, d = Wr.shape
    n = d // 2
    for i in range(d):
        y[i] = rec[row, i]
    for r in range(kk):
        for i in range(d):
            Wr[r, i] = rec[row, d + r * d + i]
    o = (1 + kk) * d
    for j in range(n):
        sc[0, j] = rec[row, o + j]
        sc[1, j] = rec[row, o + n + j]
    project_tangent_euclidean_sc(y, Wr, sc[0], sc[1], ga, gb)
    orthonormal_rows(Wr, w)
    for r in range(kk):
        for s_ in range(kk):
            af = 0.0
            ar = 0.0
            for i in range(d):
                af += rec[row, d + r * d + i] * V[q, d + s_ * d + i]
                ar += Wr[r, i] * V[q, d + s_ * d + i]
            M[0, r, s_] = af
            M[1, r, s_] = ar
    smallest_singular_values_into(M, sv, A)


def _backward_pass(sines, ck, W, rotors, stepping, ck_every, first_sample, sample_every, reorth,
                   V, logs, sf, sr):
    """Backward pass over the segments (last first) down to step ``first_sample``: each
    segment from its checkpoint ck[seg + 1] by the stacked flows' one time loop
    (``charts.solvers.tangent.stacked_loop``, with the adjoint hook and step −dt of the
    forward flow's ``stepping``; the state is not projected), W re-orthonormalised at every step index that is a multiple of
    ``reorth`` (which divides the segment and sample steps; logs of the norms added to
    ``logs``) and recorded at the sample steps; at the k-th sample step the sines of
    `sample_sines` into sf[k] (full) and sr[k] (restricted), V_k the forward pass's record
    V[k] (shape (S, (1 + m)·2N)).  Returns (status, step): RUNNING, or NONFINITE / SINGULAR
    (the forward kernel's tests) at that step.  The work of `backward_loop`, allocated;
    ``sines``: `sample_sines`, called by address (`backward_kernel`)."""
    d = ck.shape[1]
    n = d // 2
    kk = W.shape[0]
    Z = np.empty((1 + kk, d))
    # copies by loops, not slices: a slice copy compiles numba's shape-mismatch message
    # (string formatting, ~1 s of every first compile: docs/performance.md, First use)
    for r in range(kk):
        for i in range(d):
            Z[1 + r, i] = W[r, i]
    rec = np.empty((ck_every // sample_every + 1, (1 + kk) * d + d))  # Z, then sin, cos
    samples = (np.empty(d), np.empty((2, n)), np.empty((kk, d)), np.empty(d), np.empty(d),
               np.empty((2, kk, kk)), np.empty(2), np.empty((kk, kk)))
    return backward_loop(ck, Z, np.empty((2, n)), np.zeros(1, dtype=np.int64), rec, rotors,
                         stepping, ck_every, first_sample, sample_every, reorth, V, logs, sf, sr,
                         np.empty(0, dtype=np.int64), np.empty((0, 0)), stacked_work(1 + kk, d),
                         samples, sines)


def sample_sines_types(ck, W, rotors, stepping, ck_every, first_sample, sample_every, reorth, V,
                       logs, sf, sr):
    """The argument types with which `backward_loop` calls `sample_sines` in `backward_kernel`
    (from the numba types of its arguments): its record, row and sample indices, the forward
    record V, the weights of ``stepping`` and the work arrays `_backward_pass` allocates."""
    f8 = types.float64
    vector, matrix = f8[::1], f8[:, ::1]
    return (matrix, types.int64, V, types.int64, stepping.types[2], vector, matrix, matrix,
            vector, vector, f8[:, :, ::1], vector, matrix)


#: `_backward_pass` compiled with the sines called by address (their code, with the singular
#: values', not compiled into the backward pass a second time: ``charts.jit.kernel_calls``)
backward_kernel = CallsKernel(_backward_pass, (sample_sines, sample_sines_types))


@njit(cache=True, inline="always")
def backward_loop(ck, Z, sc, counter, rec, rotors, stepping, ck_every, first_sample,
                  sample_every, reorth, V, logs, sf, sr, no_events, none, work, samples, sines):
    """`backward_kernel` on arrays given by the caller, allocating nothing (it also runs in
    a GPU thread: ``charts.analyses.angle_blocks``): Z (1 + m, 2N) holds W in its rows
    after the first; sc (2, N), counter (1,) and rec (segment samples + 1, (2 + m)·2N)
    are work space, as are ``work`` (``charts.solvers.tangent.stacked_work``) and
    ``samples`` (the work arrays of `sample_sines`); no_events (0,), none (0, 0); ``sines``:
    `sample_sines` (or its address)."""
    d = ck.shape[1]
    n = d // 2
    ys, scs, Wr, ga, gb, M, sv, A = samples
    S = V.shape[0]
    w = stepping.w
    adjoint = Stack(Z, sc, counter, logs, no_events)
    backward = Stepping(stepping.speed, -stepping.dt, w, False)
    records = Records(rec, no_events, none)
    for seg in range(ck.shape[0] - 2, first_sample // ck_every - 1, -1):
        for i in range(d):
            Z[0, i] = ck[seg + 1, i]
        sincos(ck[seg + 1], 0, n, rotors.wts, sc[0], sc[1])
        top = (seg + 1) * ck_every
        low = seg * ck_every
        nsteps = top - (low if low > first_sample else first_sample)
        counter[0] = 0                   # steps down from top (a multiple of reorth)
        rec_start = (top - first_sample) % sample_every
        status, done = stacked_loop(adjoint, rotors, backward,
                                    Phases(0, reorth, rec_start, sample_every), records, nsteps,
                                    adjoint_vectors_rate, work)
        if status != RUNNING:
            return status, top - done
        for i in range(rec_start if rec_start > 0 else sample_every, nsteps + 1, sample_every):
            q = (top - i - first_sample) // sample_every
            if q < S:
                sines(rec, (i - rec_start) // sample_every, V, q, w, ys, scs, Wr, ga, gb, M,
                      sv, A)
                sf[q] = sv[0]
                sr[q] = sv[1]
    return RUNNING, first_sample
