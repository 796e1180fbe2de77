"""Projections onto the manifold and its tangent spaces, the energy rescale and the
invariants: the only place they are written.

Invariants of eq (8), for the family of constraints Σ aᵢ cos θᵢ = c (weights a, level c;
the paper's case a = 1, c = 0): the constraint F = Σ a cos θ − c = 0 (eq 9), the tangency
G = Σ a u sin θ = 0 (eq 10) and the energy E = ½ Σ m u².  Ḟ = −G, so the subspace of
perturbations

    T_r = {ξ = (θ̃, ũ) : δF = −Σ a sin θ θ̃ = 0,  δG = Σ (a sin θ ũ + u a cos θ θ̃) = 0}

(dimension 2N − 2) is invariant under eq (17); the tangent-vector projections map onto it.
Arguments named ``s``, ``c`` are the weighted sin/cos a sin θ, a cos θ
(``charts.geometry.primitives.sincos``); with a = 1 every product by aᵢ is exact, so the paper's
case gives the same bits as before the weights existed.
"""
from __future__ import annotations

from math import cos, sin, sqrt

import numpy as np
from ..jit import njit

from .primitives import LANE_WIDTH, sincos

__all__ = ["project_state", "project_state_into", "project_constraint", "rescale_speed", "project_velocity", "tangent_part", "project_tangent", "project_tangent_sc", "project_tangent_lanes", "removed", "dg_term",
           "project_tangent_euclidean", "project_tangent_euclidean_sc", "constraint_normals",
           "normals_of", "invariants", "invariants_of", "invariant_terms"]


@njit(cache=True, inline="always")
def rescale_speed(y, o, n, m, speed):
    """Scale the velocities y[o:o+n] in place so that Σ mᵢuᵢ² = speed² (energy)."""
    E = 0.0
    for j in range(n):
        E += m[j] * y[o + j] * y[o + j]
    f = speed / sqrt(E)
    for j in range(n):
        y[o + j] *= f


@njit(cache=True, inline="always")
def project_velocity(x, o, n, s, minv):
    """Make the ambient vector x[o:o+N] tangent: remove its Σ xᵢ aᵢ sin θᵢ component
    M-orthogonally (along M⁻¹ a sin θ); s = a sin θ."""
    G = 0.0
    B = 0.0
    for j in range(n):
        G += x[o + j] * s[j]
        B += s[j] * s[j] * minv[j]
    a = G / B
    for j in range(n):
        x[o + j] -= a * s[j] * minv[j]


@njit(cache=True)
def project_constraint(theta, m, a, level, iterations):
    """Put the angles theta[0:N] on F = Σ a cos θ − level = 0 in place by Newton steps along
    M⁻¹∇F (at most ``iterations``, stopping once |F| < 1e-15).  Returns False at a critical
    point of F (all sin θ = 0), where there is no direction to move along."""
    n = m.size
    for _ in range(iterations):
        F = -level
        B = 0.0
        for j in range(n):
            s = a[j] * sin(theta[j])
            F += a[j] * cos(theta[j])
            B += s * s / m[j]
        if B < 1e-300:
            return False
        d = F / B
        for j in range(n):
            theta[j] += d * (a[j] * sin(theta[j])) / m[j]
        if abs(F) < 1e-15:
            break
    return True


@njit(cache=True)
def project_state(y, m, a, level, speed):
    """Project y = (θ, u) in place onto F = 0 (`project_constraint`, 3 Newton steps), G = 0
    (M-orthogonally) and, if ``speed`` > 0, Σ mᵢuᵢ² = speed² (`rescale_speed`)."""
    n = y.size // 2
    project_state_into(y, m, a, level, speed, np.empty(n), np.empty(n))


@njit(cache=True)
def project_state_into(y, m, a, level, speed, s, minv):
    """`project_state` with its work arrays s, minv (N each) given: allocates nothing."""
    n = y.size // 2
    project_constraint(y, m, a, level, 3)
    for j in range(n):
        s[j] = a[j] * sin(y[j])
        minv[j] = 1.0 / m[j]
    project_velocity(y, n, n, s, minv)
    if speed > 0.0:
        rescale_speed(y, n, n, m, speed)


@njit(cache=True, inline="always")
def removed(x, a, B, s, minv):
    """x − (a/B) sᵢ/mᵢ: the component a of x along ∇F or ∇G removed M-orthogonally."""
    return x - a / B * s * minv


@njit(cache=True, inline="always")
def dg_term(s, xu, u, c, xt):
    """The j-th term sⱼ ũⱼ + uⱼ cⱼ θ̃ⱼ of δG."""
    return s * xu + u * c * xt


@njit(cache=True)
def project_tangent_sc(y, X, minv, s, c):
    """Project each row of X, shape (k, 2N), onto T_r at y: remove its δF and δG
    components M-orthogonally; s, c = a sin θ, a cos θ of y."""
    n = y.size // 2
    B = 0.0
    for j in range(n):
        B += s[j] * s[j] * minv[j]
    for r in range(X.shape[0]):
        dF = 0.0
        for j in range(n):
            dF += s[j] * X[r, j]
        for j in range(n):
            X[r, j] = removed(X[r, j], dF, B, s[j], minv[j])
        dG = 0.0
        for j in range(n):
            dG += dg_term(s[j], X[r, n + j], y[n + j], c[j], X[r, j])
        for j in range(n):
            X[r, n + j] = removed(X[r, n + j], dG, B, s[j], minv[j])


@njit(cache=True, inline="always")
def project_tangent_lanes(Z, n, k, L, minv, s, c, B, dF, dG):
    """`project_tangent_sc` of L lanes at once, the same operations per lane in the same
    order: element i of row r of the stacked state [y; X] of lane l at Z[(r·2N + i)·L + l],
    s, c (weighted sin/cos of y's angles) at [j·L + l] (L a multiple of `LANE_WIDTH`);
    B, dF, dG, shape (L,), are work space.  Sizes unsigned."""
    W = LANE_WIDTH
    one = np.uint64(1)
    dL = (n + n) * L                    # (unsigned throughout: no negative-index checks)
    for l0 in range(L - L, L, W):
        for t in range(W):
            B[l0 + t] = 0.0
        for j in range(n):
            for t in range(W):
                e = j * L + l0 + t
                B[l0 + t] += s[e] * s[e] * minv[j]
        for r in range(k):
            ro = (r + one) * dL + l0
            for t in range(W):
                dF[l0 + t] = 0.0
                dG[l0 + t] = 0.0
            for j in range(n):
                for t in range(W):
                    dF[l0 + t] += s[j * L + l0 + t] * Z[ro + j * L + t]
            for j in range(n):
                for t in range(W):
                    e = j * L + l0 + t
                    Z[ro + j * L + t] = removed(Z[ro + j * L + t], dF[l0 + t], B[l0 + t], s[e],
                                                minv[j])
            for j in range(n):
                for t in range(W):
                    e = j * L + l0 + t
                    dG[l0 + t] += dg_term(s[e], Z[ro + (n + j) * L + t], Z[(n + j) * L + l0 + t],
                                          c[e], Z[ro + j * L + t])
            for j in range(n):
                for t in range(W):
                    e = j * L + l0 + t
                    Z[ro + (n + j) * L + t] = removed(Z[ro + (n + j) * L + t], dG[l0 + t],
                                                      B[l0 + t], s[e], minv[j])


@njit(cache=True)
def tangent_part(theta, u, minv, a):
    """The M-orthogonal projection of the ambient vector u, shape (N,), onto the tangent
    space at theta (a new array); a = weights."""
    n = theta.size
    s = np.empty(n)
    for j in range(n):
        s[j] = a[j] * sin(theta[j])
    x = u.copy()
    project_velocity(x, 0, n, s, minv)
    return x


@njit(cache=True)
def project_tangent(y, X, minv, a):
    """`project_tangent_sc` computing a sin θ and a cos θ itself (a = weights)."""
    n = y.size // 2
    s = np.empty(n)
    c = np.empty(n)
    sincos(y, 0, n, a, s, c)
    project_tangent_sc(y, X, minv, s, c)


@njit(cache=True)
def project_tangent_euclidean(y, W, wts):
    """Euclidean-orthogonal projection of the rows of W, shape (k, 2N), onto T_r at y
    (`project_tangent_euclidean_sc` with libm sin/cos of y's angles); wts = a."""
    n = y.size // 2
    s = np.empty(n)
    c = np.empty(n)
    sincos(y, 0, n, wts, s, c)
    project_tangent_euclidean_sc(y, W, s, c, np.empty(2 * n), np.empty(2 * n))


@njit(cache=True, inline="always")
def constraint_normals(y, s, c, a, b):
    """The normals of T_r at y into a, b (2N,): a = −∇F = (a sin θ, 0) and ∇G = (u a cos θ,
    a sin θ), the gradients of the constraint and of the tangency (s, c = a sin θ, a cos θ
    of y); T_r is their Euclidean-orthogonal complement."""
    n = y.size // 2
    for i in range(n):
        a[i] = s[i]
        a[n + i] = 0.0
        b[i] = y[n + i] * c[i]
        b[n + i] = s[i]


@njit(cache=True)
def normals_of(y, wts):
    """(a, b): `constraint_normals` of the state y (sin/cos from libm; wts = a)."""
    n = y.size // 2
    s = np.empty(n)
    c = np.empty(n)
    sincos(y, 0, n, wts, s, c)
    a = np.empty(2 * n)
    b = np.empty(2 * n)
    constraint_normals(y, s, c, a, b)
    return a, b


@njit(cache=True, inline="always")
def project_tangent_euclidean_sc(y, W, s, c, a, b):
    """Euclidean-orthogonal projection of the rows of W, shape (k, 2N), onto T_r at y
    (the complement of span(∇F, ∇G): `constraint_normals`); s, c = a sin θ, a cos θ of y;
    a, b (2N,) work space."""
    n = y.size // 2
    constraint_normals(y, s, c, a, b)
    aa = 0.0
    ab = 0.0
    bb = 0.0
    for i in range(2 * n):
        aa += a[i] * a[i]
        ab += a[i] * b[i]
        bb += b[i] * b[i]
    det = aa * bb - ab * ab
    for r in range(W.shape[0]):
        wa = 0.0
        wb = 0.0
        for i in range(2 * n):
            wa += W[r, i] * a[i]
            wb += W[r, i] * b[i]
        ca = (bb * wa - ab * wb) / det
        cb = (aa * wb - ab * wa) / det
        for i in range(2 * n):
            W[r, i] -= ca * a[i] + cb * b[i]


@njit(cache=True, inline="always")
def invariants_of(row, n, masses, a, level):
    """(F, G, E) = (Σ a cos θ − level, Σ u a sin θ, ½ Σ m u²) of the state row[0:2N]."""
    F = -level
    G = 0.0
    E = 0.0
    for i in range(n):
        f, g, e = invariant_terms(a[i] * sin(row[i]), a[i] * cos(row[i]), row[n + i], masses[i])
        F += f
        G += g
        E += e
    return F, G, E


@njit(cache=True, inline="always")
def invariant_terms(s, c, u, m):
    """Rotor i's terms of (F, G, E) (eqs 9, 10 and the energy): a cos θ, u a sin θ, ½ m u²,
    from s, c = a sin θ, a cos θ, its velocity u and mass m."""
    return c, u * s, 0.5 * m * u * u


def invariants(theta, u, masses, weights=None, level=0.0):
    """(constraint Σ a cos θ − level, tangency Σ u a sin θ, energy ½Σ m u²) along the last
    axis (weights a default all 1)."""
    theta = np.asarray(theta)
    u = np.asarray(u)
    a = np.ones(theta.shape[-1]) if weights is None else np.asarray(weights, dtype=float)
    return ((a * np.cos(theta)).sum(-1) - level, (u * (a * np.sin(theta))).sum(-1),
            0.5 * (np.asarray(masses) * u * u).sum(-1))
