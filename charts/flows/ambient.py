"""Ambient (Lagrange) formulation, eqs (8), (17), (19), generalised to masses.

State y = (θ₀…θ_{N−1}, u₀…u_{N−1}), shape (2N,).  With minv = 1/m:

    θ̇ᵢ = uᵢ,   u̇ᵢ = −Λ sin θᵢ / mᵢ,   Λ = Σ u_j² cos θ_j / Σ sin²θ_j / m_j     (eq 8)

Tangent (perturbation) vectors ξ = (θ̃, ũ), shape (2N,), obey the linearisation
(eq 17, re-derived here for masses; tested against finite differences of eq 8):

    θ̃̇ᵢ = ũᵢ,   ũ̇ᵢ = −(δΛ sin θᵢ + Λ cos θᵢ θ̃ᵢ) / mᵢ,
    δΛ = [Σ(2u_j ũ_j cos θ_j − u_j² sin θ_j θ̃_j) − Λ Σ 2 sin θ_j cos θ_j θ̃_j / m_j] / B

and the adjoint vectors obey ẇ = −Jᵀ w.  All kernels are numba-compiled, write
into caller-given arrays and allocate nothing.
"""
from __future__ import annotations

from math import cos, sin, sqrt

import numpy as np
from numba import njit

__all__ = [
    "flow_rhs", "flow_tangent_rhs", "adjoint_rhs", "transport_rhs", "project_state",
    "project_tangent", "project_tangent_sc", "invariants",
]


@njit(cache=True)
def flow_rhs(y, minv, dy):
    """Eq (8): dy = f(y).  Returns B = Σ sin²θ/m (→ 0 at singular points)."""
    n = y.size // 2
    A = 0.0
    B = 0.0
    for j in range(n):
        s = sin(y[j])
        A += y[n + j] * y[n + j] * cos(y[j])
        B += s * s * minv[j]
    lam = A / B
    for i in range(n):
        dy[i] = y[n + i]
        dy[n + i] = -lam * sin(y[i]) * minv[i]
    return B


@njit(cache=True)
def flow_tangent_rhs(y, X, minv, dy, dX):
    """Eq (8) for y and eq (17) for each row of X, shape (k, 2N), sharing sin/cos."""
    n = y.size // 2
    A = 0.0
    B = 0.0
    for j in range(n):
        s = sin(y[j])
        A += y[n + j] * y[n + j] * cos(y[j])
        B += s * s * minv[j]
    lam = A / B
    for i in range(n):
        dy[i] = y[n + i]
        dy[n + i] = -lam * sin(y[i]) * minv[i]
    for r in range(X.shape[0]):
        dA = 0.0
        dB = 0.0
        for j in range(n):
            s = sin(y[j])
            c = cos(y[j])
            u = y[n + j]
            dA += 2.0 * u * X[r, n + j] * c - u * u * s * X[r, j]
            dB += 2.0 * s * c * X[r, j] * minv[j]
        dlam = (dA - lam * dB) / B
        for i in range(n):
            dX[r, i] = X[r, n + i]
            dX[r, n + i] = -(dlam * sin(y[i]) + lam * cos(y[i]) * X[r, i]) * minv[i]
    return B


@njit(cache=True)
def adjoint_rhs(y, W, minv, dW):
    """ẇ = −J(y)ᵀ w for each row of W, shape (k, 2N), J the Jacobian of eq (8)."""
    n = y.size // 2
    A = 0.0
    B = 0.0
    for j in range(n):
        s = sin(y[j])
        A += y[n + j] * y[n + j] * cos(y[j])
        B += s * s * minv[j]
    lam = A / B
    for r in range(W.shape[0]):
        sb = 0.0  # Σ_i sin θ_i b_i / m_i, b = velocity part of w
        for i in range(n):
            sb += sin(y[i]) * W[r, n + i] * minv[i]
        for j in range(n):
            s = sin(y[j])
            c = cos(y[j])
            u = y[n + j]
            dlam_dtheta = (-u * u * s - lam * 2.0 * s * c * minv[j]) / B
            jt_theta = -dlam_dtheta * sb - lam * c * minv[j] * W[r, n + j]
            jt_u = W[r, j] - 2.0 * u * c / B * sb
            dW[r, j] = -jt_theta
            dW[r, n + j] = -jt_u
    return B


@njit(cache=True)
def transport_rhs(y, P, minv, s, c, dP):
    """Eq (19), parallel transport of the rows of P, shape (k, N), along the flow, given
    s, c = sin θ, cos θ of y (shared with the caller's other right-hand sides):
    ṗᵢ = −(Σ p_j u_j cos θ_j / B) sin θᵢ / mᵢ."""
    n = y.size // 2
    B = 0.0
    for j in range(n):
        B += s[j] * s[j] * minv[j]
    for r in range(P.shape[0]):
        a = 0.0
        for j in range(n):
            a += P[r, j] * y[n + j] * c[j]
        a /= B
        for i in range(n):
            dP[r, i] = -a * s[i] * minv[i]


@njit(cache=True)
def project_state(y, m, speed):
    """Project y in place onto Σcos θ = 0 (Newton along M⁻¹∇F), Σ uᵢ sin θᵢ = 0
    (M-orthogonal) and Σ mᵢuᵢ² = speed² (rescaling u)."""
    n = y.size // 2
    for _ in range(3):
        F = 0.0
        B = 0.0
        for j in range(n):
            s = sin(y[j])
            F += cos(y[j])
            B += s * s / m[j]
        d = F / B
        for j in range(n):
            y[j] += d * sin(y[j]) / m[j]
        if abs(F) < 1e-15:
            break
    G = 0.0
    B = 0.0
    for j in range(n):
        s = sin(y[j])
        G += y[n + j] * s
        B += s * s / m[j]
    for j in range(n):
        y[n + j] -= G / B * sin(y[j]) / m[j]
    if speed > 0.0:
        E = 0.0
        for j in range(n):
            E += m[j] * y[n + j] * y[n + j]
        f = speed / sqrt(E)
        for j in range(n):
            y[n + j] *= f


@njit(cache=True)
def project_tangent_sc(y, X, minv, s, c):
    """Remove from each row of X, shape (k, 2N), its components that change the
    constraint F = Σcos θ and the tangency G = Σ u sin θ to first order, i.e.
    make δF = −Σ sin θ θ̃ = 0 and δG = Σ(sin θ ũ + u cos θ θ̃) = 0 (M-orthogonally),
    given s, c = sin θ, cos θ of y."""
    n = y.size // 2
    B = 0.0
    for j in range(n):
        B += s[j] * s[j] * minv[j]
    for r in range(X.shape[0]):
        dF = 0.0
        for j in range(n):
            dF += s[j] * X[r, j]
        for j in range(n):
            X[r, j] -= dF / B * s[j] * minv[j]
        dG = 0.0
        for j in range(n):
            dG += s[j] * X[r, n + j] + y[n + j] * c[j] * X[r, j]
        for j in range(n):
            X[r, n + j] -= dG / B * s[j] * minv[j]


@njit(cache=True)
def project_tangent(y, X, minv):
    """`project_tangent_sc` computing sin θ and cos θ itself (allocates two (N,) arrays)."""
    n = y.size // 2
    s = np.empty(n)
    c = np.empty(n)
    for j in range(n):
        s[j] = sin(y[j])
        c[j] = cos(y[j])
    project_tangent_sc(y, X, minv, s, c)


def invariants(theta, u, masses):
    """(constraint Σcos θ, tangency Σ u sin θ, energy ½Σ m u²) along the last axis."""
    theta = np.asarray(theta)
    u = np.asarray(u)
    return (np.cos(theta).sum(-1), (u * np.sin(theta)).sum(-1),
            0.5 * (np.asarray(masses) * u * u).sum(-1))
