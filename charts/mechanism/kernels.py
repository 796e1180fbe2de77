"""The ambient equations of a Mechanism at one point, as compiled loops over its jets: the one
home of these formulas, called by ``dynamics`` (NumPy arrays, one point at a time) and by the
compiled tangent flow (``tangent_flow``).

The equations of motion are the saddle-point (KKT) system of ``dynamics``,

    K (q̈, λ) = b,   K = [[M, −Jᵀ], [J, 0]],   b = (−C(q, v), −∂²F(v, v)),
    C_i = Σ_jk (∂_j M_ik − ½ ∂_i M_jk) v^j v^k,

and their linearisation along a phase-space tangent vector (δq, δv) (eq (17)'s analogue) is
the same system differentiated, K δ(q̈, λ) = δb − δK (q̈, λ).  Index order as in ``symbolic``:
J[a, i], F2[a, i, j], F3[a, i, j, l], dM[i, j, l] = ∂_l M_ij, d2M[i, j, l, m] = ∂_l∂_m M_ij.
"""
from __future__ import annotations

from ..jit import njit

__all__ = ["kkt_matrix", "motion_rhs", "tangent_motion_rhs"]


@njit(cache=True)
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


@njit(cache=True)
def motion_rhs(dM, F2, v, b):
    """b = (−C(q, v), −∂²F(v, v)), shape (n + k,), in place: the right-hand side of the KKT
    system for (q̈, λ) (module docstring)."""
    n = v.shape[0]
    k = F2.shape[0]
    for i in range(n):
        s = 0.0
        for j in range(n):
            for m in range(n):
                s += (dM[i, m, j] - 0.5 * dM[j, m, i]) * v[j] * v[m]
        b[i] = -s
    for c in range(k):
        s = 0.0
        for i in range(n):
            for j in range(n):
                s += F2[c, i, j] * v[i] * v[j]
        b[n + c] = -s


@njit(cache=True)
def tangent_motion_rhs(dM, d2M, F2, F3, v, x, dq, dv, r):
    """r = δb − δK x, shape (n + k,), in place: the KKT system differentiated along the phase
    tangent vector (δq, δv) at its solution x = (q̈, λ), so that K δx = r gives δq̈ (exact,
    with ∂²M and ∂³F)."""
    n = v.shape[0]
    k = F2.shape[0]
    for i in range(n):
        dc = 0.0                                    # δC_i
        for j in range(n):
            for m in range(n):
                vv = v[j] * v[m]
                for l in range(n):
                    dc += (d2M[i, m, j, l] - 0.5 * d2M[j, m, i, l]) * vv * dq[l]
                dc += (dM[i, m, j] - 0.5 * dM[j, m, i]) * (dv[j] * v[m] + v[j] * dv[m])
        dkx = 0.0                                   # (δK x)_i = Σ_j δM_ij q̈_j − Σ_c δJ_ci λ_c
        for j in range(n):
            dm = 0.0
            for l in range(n):
                dm += dM[i, j, l] * dq[l]
            dkx += dm * x[j]
        for c in range(k):
            dj = 0.0
            for l in range(n):
                dj += F2[c, i, l] * dq[l]
            dkx -= dj * x[n + c]
        r[i] = -dc - dkx
    for c in range(k):
        d3 = 0.0                                    # ∂³F(v, v, δq)
        d2 = 0.0                                    # ∂²F(v, δv)
        dkx = 0.0                                   # (δK x)_{n+c} = Σ_i δJ_ci q̈_i
        for i in range(n):
            dj = 0.0
            for j in range(n):
                d2 += F2[c, i, j] * v[i] * dv[j]
                dj += F2[c, i, j] * dq[j]
                for l in range(n):
                    d3 += F3[c, i, j, l] * v[i] * v[j] * dq[l]
            dkx += dj * x[i]
        r[n + c] = -d3 - 2.0 * d2 - dkx

