"""The geodesic flow of the linkage of the Appendix and its variational equations: the only
place they are written.

State y = (q, v), q = (θ₀…θ₃, x, y, α), shape (14,).  Lagrange's equations with the four
constraints F(q) = 0 (``charts.geometry.linkage``), mass matrix M = diag(1, 1, 1, 1, m_d, m_d,
I_d), J = ∂F/∂q and h(q, v) = vᵀ∇²F v (shape (4,)), in the saddle-point (KKT) form

    [ M  Jᵀ ] [ a ]   [  0 ]
    [ J  0  ] [ λ ] = [ −h ],      q̇ = v,  v̇ = a.

The KKT matrix is invertible exactly where M is positive definite on ker J, i.e. for a
massless disk where C = ∂F/∂(x, y, α) has rank 3 (the pull-back of Σ dθ² is a metric), so
the Appendix's massless disk needs no regularisation away from the degenerate set.  For m_d
= I_d = 0 the θ-part a_θ = −Aλ is normal to the θ-projection of M: this is eq (8) with the
single normal Σ cos θᵢ replaced by the exact one.

Variational equations (tangent vectors ξ = (δq, δv)): differentiating the KKT system,

    [ M  Jᵀ ] [ δa ]   [ −H(δq)ᵀ λ                          ]
    [ J  0  ] [ δλ ] = [ −H(δq) a − T(v, v, δq) − 2 H(v) δv   ],

with H(w) = Σₖ ∂²F/∂q∂qₖ wₖ and T from the generated third derivatives; the same
factorisation serves every vector.  ``linkage_rates(Z, par, dZ)`` evaluates both for the flat
stacked state Z = [y; ξ¹; …; ξᵏ] (``charts.solvers.linkage.linkage_rhs`` compiles it with the
steppers' signature), with ``par = (ε, ρ, R, m_d, I_d)``; it returns the health `disk_gram`: det(C̃ᵀC̃), C̃ = ∂F/∂(x, y,
ρα) (→ 0 where the massless disk's metric degenerates; 0 if the KKT matrix is singular).
"""
from __future__ import annotations

import numpy as np
from ..jit import njit

from ..geometry.linkage import (NC, NQ, gen_hessian_vector, gen_jacobian, gen_third_form,
                                kkt_matrix, lu_factor, lu_solve)

__all__ = ["linkage_rates", "acceleration", "disk_gram", "NY", "NK"]

#: Length of the state (q, v) and of the KKT system.
NY = 2 * NQ
NK = NQ + NC


@njit(cache=True, inline="always")
def _state_solve(q, v, par, J, Hv, K, piv, b):
    """Factorise the KKT matrix at q into (K, piv) and solve it for (a, λ) of the velocity v
    into b, shape (11,), with J and Hv = H(v) filled in.  Returns the smallest |pivot|."""
    gen_jacobian(q, par, J)
    gen_hessian_vector(q, v, par, Hv)
    kkt_matrix(J, par, K)
    pmin = lu_factor(K, piv)
    if pmin == 0.0:
        return 0.0
    for j in range(NQ):
        b[j] = 0.0
    for i in range(NC):
        b[NQ + i] = -(Hv[i] @ v)
    lu_solve(K, piv, b)
    return pmin


@njit(cache=True)
def acceleration(q, v, par, a):
    """a = q̈ of the geodesic with velocity v at q (the KKT solve above), shape (7,); returns
    the smallest |pivot|.  a is a quadratic form in v (the second fundamental form)."""
    b = np.empty(NK)
    pmin = _state_solve(q, v, par, np.empty((NC, NQ)), np.empty((NC, NQ)), np.empty((NK, NK)),
                        np.empty(NK, dtype=np.int64), b)
    for j in range(NQ):
        a[j] = b[j]
    return pmin


@njit(cache=True, inline="always")
def disk_gram(J, rho):
    """det(C̃ᵀC̃) for C̃ = J[:, 4:7] with its α column divided by ρ: the squared product of the
    singular values of ∂F/∂(x, y, ρα), dimensionless, 0 exactly where C loses rank."""
    G = np.empty((3, 3))
    for a in range(3):
        for b in range(3):
            acc = 0.0
            for i in range(NC):
                acc += J[i, 4 + a] * J[i, 4 + b]
            G[a, b] = acc / ((rho if a == 2 else 1.0) * (rho if b == 2 else 1.0))
    return (G[0, 0] * (G[1, 1] * G[2, 2] - G[1, 2] * G[2, 1])
            - G[0, 1] * (G[1, 0] * G[2, 2] - G[1, 2] * G[2, 0])
            + G[0, 2] * (G[1, 0] * G[2, 1] - G[1, 1] * G[2, 0]))


def linkage_rates(Z, par, dZ):
    nvec = Z.size // NY - 1
    q = Z[:NQ]
    v = Z[NQ:NY]
    J = np.empty((NC, NQ))
    Hv = np.empty((NC, NQ))
    Hd = np.empty((NC, NQ))
    T = np.empty(NC)
    K = np.empty((NK, NK))
    piv = np.empty(NK, dtype=np.int64)
    b = np.empty(NK)
    if _state_solve(q, v, par, J, Hv, K, piv, b) == 0.0:
        dZ[:] = 0.0
        return 0.0
    a = b[:NQ].copy()
    lam = b[NQ:].copy()
    for j in range(NQ):
        dZ[j] = v[j]
        dZ[NQ + j] = a[j]
    for r in range(nvec):
        o = NY * (r + 1)
        dq = Z[o:o + NQ]
        dv = Z[o + NQ:o + NY]
        gen_hessian_vector(q, dq, par, Hd)
        gen_third_form(q, v, dq, par, T)
        for j in range(NQ):
            acc = 0.0
            for i in range(NC):
                acc += Hd[i, j] * lam[i]
            b[j] = -acc
        for i in range(NC):
            b[NQ + i] = -(Hd[i] @ a) - T[i] - 2.0 * (Hv[i] @ dv)
        lu_solve(K, piv, b)
        for j in range(NQ):
            dZ[o + j] = dv[j]
            dZ[o + NQ + j] = b[j]
    return disk_gram(J, par[1])
