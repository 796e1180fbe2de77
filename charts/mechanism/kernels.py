"""The ambient equations of a Mechanism at one point, as compiled loops over its jets: the one
home of these formulas, called by ``dynamics`` (NumPy arrays, one point at a time) and by the
compiled tangent flow (``tangent_flow``).

The equations of motion are the saddle-point (KKT) system of ``dynamics``,

    K (q̈, λ) = b,   K = [[M, −Jᵀ], [J, 0]],   b = (−C(q, v), −∂²F(v, v)),
    C_i = Σ_jk (∂_j M_ik − ½ ∂_i M_jk) v^j v^k,

and their linearisation along a phase-space tangent vector (δq, δv) (eq (17)'s analogue) is
the same system differentiated, K δ(q̈, λ) = δb − δK (q̈, λ).  Index order as in ``symbolic``:
J[a, i], F2[a, i, j], F3[a, i, j, l], dM[i, j, l] = ∂_l M_ij, d2M[i, j, l, m] = ∂_l∂_m M_ij.

Where M is constant and definite the KKT system is solved through its Schur complement
J M⁻¹ Jᵀ (`schur_factor`, `schur_solve_columns`; M⁻¹ computed once by the caller).  The hot
loops skip the jets' exact zeros (the rotors' ∂²F and ∂³F are diagonal): a zero term adds
nothing, so the bits are the same with fewer dependent operations.  The kernels allocate
nothing and are compiled without reference counting (``NO_REFCOUNT``), as the flow's driver
(all but `tangent_motion_rhs`, which allocates its matrix).
"""
from __future__ import annotations

import numpy as np

from ..jit import njit
from ..solvers.rk import NO_REFCOUNT

__all__ = ["kkt_matrix", "motion_rhs", "tangent_motion_matrix", "apply_tangent_matrix",
           "tangent_motion_rhs", "lu_in_place", "lu_solve_columns", "schur_factor",
           "schur_solve_columns"]


@njit(cache=True, error_model="numpy", **NO_REFCOUNT)
def kkt_matrix(M, J, sign, K):
    """K = [[M, sign·Jᵀ], [J, 0]], shape (n + k, n + k), written in place: ``sign`` −1 for the
    equations of motion, +1 for the M-orthogonal projections of ``dynamics``."""
    n = M.shape[0]
    k = J.shape[0]
    for i in range(n):
        for j in range(n):
            K[i, j] = M[i, j]
        for c in range(k):
            K[i, n + c] = sign * J[c, i]
    for c in range(k):
        for i in range(n):
            K[n + c, i] = J[c, i]
        for e in range(k):
            K[n + c, n + e] = 0.0


@njit(cache=True, error_model="numpy", **NO_REFCOUNT)
def motion_rhs(dM, F2, v, b, flat=False):
    """b = (−C(q, v), −∂²F(v, v)), shape (n + k,), in place: the right-hand side of the KKT
    system for (q̈, λ) (module docstring).  ``flat``: M is constant, C = 0 not summed (its
    terms are zeros: no bit changes)."""
    n = v.shape[0]
    k = F2.shape[0]
    for i in range(n):
        s = 0.0
        if not flat:
            for j in range(n):
                for m in range(n):
                    s += (dM[i, m, j] - 0.5 * dM[j, m, i]) * v[j] * v[m]
        b[i] = -s
    for c in range(k):
        s = 0.0
        for i in range(n):
            for j in range(n):
                if F2[c, i, j] != 0.0:
                    s += F2[c, i, j] * v[i] * v[j]
        b[n + c] = -s


@njit(cache=True, error_model="numpy", **NO_REFCOUNT)
def tangent_motion_matrix(dM, d2M, F2, F3, v, x, T, flat):
    """T, shape (n + k, 2n), in place: the linearisation of the KKT system at (q, v) with its
    solution x = (q̈, λ) as a matrix, δb − δK x = T (δq, δv), so that K δx = T (δq, δv) gives
    δq̈ for every phase tangent vector (δq, δv) (exact, with ∂²M and ∂³F; built once per
    point for all the vectors).  Rows i < n (δC and δK x of the metric rows):

        T[i, l]     = −Σ_jm (∂_l∂_j M_im − ½ ∂_l∂_i M_jm) v^j v^m − Σ_j ∂_l M_ij q̈_j + Σ_c ∂_l J_ci λ_c
        T[i, n + a] = −Σ_m (∂_a M_im − ½ ∂_i M_am + ∂_m M_ia − ½ ∂_i M_ma) v^m

    rows n + c (the constraint differentiated twice): T[n + c, l] = −∂³F_c(v, v, ∂_l) −
    Σ_i ∂_l J_ci q̈_i and T[n + c, n + j] = −2 Σ_i ∂²F_c[i, j] v^i.  ``flat``: M is constant
    (``Mechanism.constant_metric``), its ∂M and ∂²M terms skipped (zeros: no bit changes)."""
    n = v.shape[0]
    k = F2.shape[0]
    for i in range(n):
        for l in range(n):
            s = 0.0
            for c in range(k):
                if F2[c, i, l] != 0.0:
                    s += F2[c, i, l] * x[n + c]
            if not flat:
                for j in range(n):
                    s -= dM[i, j, l] * x[j]
                    for m in range(n):
                        s -= (d2M[i, m, j, l] - 0.5 * d2M[j, m, i, l]) * v[j] * v[m]
            T[i, l] = s
        for a in range(n):
            s = 0.0
            if not flat:
                for m in range(n):
                    s -= (dM[i, m, a] - 0.5 * dM[a, m, i] + dM[i, a, m] - 0.5 * dM[m, a, i]) * v[m]
            T[i, n + a] = s
    for c in range(k):
        for l in range(n):
            s = 0.0
            for i in range(n):
                if F2[c, i, l] != 0.0:
                    s -= F2[c, i, l] * x[i]
                for j in range(n):
                    if F3[c, i, j, l] != 0.0:
                        s -= F3[c, i, j, l] * v[i] * v[j]
            T[n + c, l] = s
        for j in range(n):
            s = 0.0
            for i in range(n):
                if F2[c, i, j] != 0.0:
                    s -= 2.0 * F2[c, i, j] * v[i]
            T[n + c, n + j] = s


@njit(cache=True, error_model="numpy", **NO_REFCOUNT)
def apply_tangent_matrix(T, dq, dv, r):
    """r = T (δq, δv), shape (n + k,), in place (`tangent_motion_matrix`)."""
    n = dq.shape[0]
    for i in range(T.shape[0]):
        s = 0.0
        for l in range(n):
            if T[i, l] != 0.0 or T[i, n + l] != 0.0:
                s += T[i, l] * dq[l] + T[i, n + l] * dv[l]
        r[i] = s


@njit(cache=True)
def tangent_motion_rhs(dM, d2M, F2, F3, v, x, dq, dv, r):
    """r = δb − δK x, shape (n + k,), in place: the KKT system differentiated along the phase
    tangent vector (δq, δv) at its solution x = (q̈, λ), so that K δx = r gives δq̈ (exact,
    with ∂²M and ∂³F; `tangent_motion_matrix` applied to one vector)."""
    T = np.empty((r.shape[0], 2 * v.shape[0]))
    tangent_motion_matrix(dM, d2M, F2, F3, v, x, T, False)
    apply_tangent_matrix(T, dq, dv, r)


@njit(cache=True, error_model="numpy", **NO_REFCOUNT)
def lu_in_place(A, piv):
    """A = P·L·U in place by Gaussian elimination with partial pivoting (L unit lower, below
    the diagonal; U on and above it); ``piv[c]`` the row exchanged with row c at step c.
    Returns the smallest |pivot| over the largest (0.0 where a pivot is zero or not finite:
    A singular, or NaN in it).  For the small KKT systems of the compiled flow: in place,
    without the copies and checks of ``np.linalg.solve`` (LAPACK's ``gesv``), which took
    most of a step's time at n + k = 4."""
    m = A.shape[0]
    small, large = np.inf, 0.0
    for c in range(m):
        r = c
        best = abs(A[c, c])
        for i in range(c + 1, m):
            if abs(A[i, c]) > best:
                r, best = i, abs(A[i, c])
        piv[c] = r
        if not (0.0 < best < np.inf):
            return 0.0
        if r != c:
            for j in range(m):
                t = A[c, j]
                A[c, j] = A[r, j]
                A[r, j] = t
        small, large = min(small, best), max(large, best)
        inv = 1.0 / A[c, c]
        for i in range(c + 1, m):
            f = A[i, c] * inv
            A[i, c] = f
            if f != 0.0:
                for j in range(c + 1, m):
                    A[i, j] -= f * A[c, j]
    return small / large


@njit(cache=True, error_model="numpy", **NO_REFCOUNT)
def lu_solve_columns(A, piv, B, first, last):
    """Columns ``first`` … ``last − 1`` of B, shape (m, r), overwritten by the solutions of
    A x = B[:, col], with A's factors from `lu_in_place` (its pivots non-zero)."""
    m = A.shape[0]
    for col in range(first, last):
        for c in range(m):                      # the row exchanges, then L y = P b
            r = piv[c]
            if r != c:
                t = B[c, col]
                B[c, col] = B[r, col]
                B[r, col] = t
        for i in range(1, m):
            s = B[i, col]
            for j in range(i):
                s -= A[i, j] * B[j, col]
            B[i, col] = s
        for i in range(m - 1, -1, -1):          # U x = y
            s = B[i, col]
            for j in range(i + 1, m):
                s -= A[i, j] * B[j, col]
            B[i, col] = s / A[i, i]


@njit(cache=True, error_model="numpy", **NO_REFCOUNT)
def schur_factor(Minv, J, W, S, spiv):
    """W = M⁻¹Jᵀ, shape (n, k), and S = J W, shape (k, k), factored in place (`lu_in_place`,
    pivots in ``spiv``): the Schur complement of the KKT matrix [[M, −Jᵀ], [J, 0]] where M is
    invertible (``Minv`` = M⁻¹, a constant metric's, computed once).  Returns `lu_in_place`'s
    pivot ratio (0.0: J rank-deficient, or not finite)."""
    n = Minv.shape[0]
    k = J.shape[0]
    for i in range(n):
        for c in range(k):
            s = 0.0
            for j in range(n):
                s += Minv[i, j] * J[c, j]
            W[i, c] = s
    for a in range(k):
        for c in range(k):
            s = 0.0
            for i in range(n):
                s += J[a, i] * W[i, c]
            S[a, c] = s
    return lu_in_place(S, spiv)


@njit(cache=True, error_model="numpy", **NO_REFCOUNT)
def schur_solve_columns(Minv, J, W, S, spiv, B, first, last, u):
    """Columns ``first`` … ``last − 1`` of B = (b_q, b_c), shape (n + k, r), overwritten by
    the solutions (q̈, λ) of [[M, −Jᵀ], [J, 0]] (q̈, λ) = (b_q, b_c) through the Schur
    complement (`schur_factor`'s W and factored S): u = M⁻¹ b_q, S λ = b_c − J u,
    q̈ = u + W λ.  ``u``, shape (n,), is work space."""
    n = Minv.shape[0]
    k = J.shape[0]
    for col in range(first, last):
        for i in range(n):
            s = 0.0
            for j in range(n):
                if Minv[i, j] != 0.0:
                    s += Minv[i, j] * B[j, col]
            u[i] = s
        for c in range(k):
            s = B[n + c, col]
            for i in range(n):
                s -= J[c, i] * u[i]
            B[n + c, col] = s
        for i in range(n):
            B[i, col] = u[i]
    lu_solve_columns(S, spiv, B[n:], first, last)
    for col in range(first, last):
        for i in range(n):
            s = B[i, col]
            for c in range(k):
                s += W[i, c] * B[n + c, col]
            B[i, col] = s
