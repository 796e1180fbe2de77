"""The ambient (Lagrange) equations, generalised to masses and to the family of constraints
F = Σ aᵢ cos θᵢ − c = 0 (weights a, level c): the only place they are written.

State y = (θ₀…θ_{N−1}, u₀…u_{N−1}), shape (2N,).  With the *weighted* sᵢ = aᵢ sin θᵢ,
cᵢ = aᵢ cos θᵢ (−∇F and −diag Hess F; `sincos`, ``charts.geometry.primitives``):

    θ̇ᵢ = uᵢ,   u̇ᵢ = −Λ sᵢ / mᵢ,   Λ = Σ u_j² c_j / B,   B = Σ s_j² / m_j          (eq 8)

Since ds/dθ = c and dc/dθ = −s hold for the weighted pair as for sin and cos, eqs (17),
(19) and the adjoint below keep their form; the level c enters only the constraint
(``charts.geometry.projection``).  With a = 1 the products aᵢ sin θᵢ are exact, so the
paper's case gives the same bits as the unweighted equations.

Tangent (perturbation) vectors ξ = (θ̃, ũ), shape (2N,), obey the linearisation (eq 17,
re-derived for masses; tested against finite differences of eq 8), written with the
per-rotor factors fᵢ = sᵢ/mᵢ, gᵢ = Λcᵢ/mᵢ, pᵢ = 2uᵢcᵢ, qᵢ = sᵢ(uᵢ² + 2gᵢ):

    θ̃̇ᵢ = ũᵢ,   ũ̇ᵢ = −(δΛ fᵢ + gᵢ θ̃ᵢ),   δΛ = Σ (p_j ũ_j − q_j θ̃_j) / B             (eq 17)

Parallel transport of an ambient tangent vector p, shape (N,) (eq 19):

    ṗᵢ = −(Σ p_j u_j c_j / B) fᵢ                                                  (eq 19)

and adjoint vectors w = (a, b), shape (2N,), obey ẇ = −J(y)ᵀ w, J the Jacobian of eq (8).

The equations are scalar-loop functions inlined into the compiled kernels
(``inline="always"``).  They read and write *flat* arrays at offsets (``o``, ``do``), so the
same code serves every layout: the stacked state [y; X] of the tangent kernel, the packed
state (θ, u, p¹…pᵏ) of the integration loop and plain (2N,) vectors.  No call allocates.
The wrappers at the end (`flow_rhs`, `flow_tangent_rhs`, `adjoint_rhs`, `transport_rhs`)
evaluate them on ordinary arrays for Python callers and tests.

Lanes.  Eqs (8) and (17) are written once per rotor, as the scalar *terms* below
(`a_term`, `b_term`, `multiplier_of`, `acceleration`, `factor_f` … `factor_q`,
`tangent_term`, `tangent_acceleration`); the flat-array loops call them, one trajectory at a time
(`multiplier` … `tangent_rate`) or for L independent trajectories at once (``*_lanes``:
structure of arrays, element i of lane l at ``i·L + l``, the lane innermost so that the
arithmetic vectorises across lanes).  Both loops do the same operations in the same order
for each lane, so a lane gives the bits of the one-trajectory route.  A block writes one
array at one offset: two interleaved streams of stores into the same array (the copy
θ̇ = u and the acceleration of one rotor in one block) at a distance LLVM cannot bound
keep its SLP vectoriser from packing either, and the block stays scalar code (measured:
eqs (8) and (17) in 150 against 124 ns per lane-step of the whole lane kernel).
"""
from __future__ import annotations

import numpy as np
from ..jit import njit

from ..geometry.primitives import LANE_WIDTH, SHIFT_MAX, shifted, sincos  # noqa: F401 - re-exported

__all__ = [
    "a_term", "b_term", "multiplier_of", "acceleration", "factor_f", "factor_g", "factor_p",
    "factor_q", "tangent_term",
    "tangent_acceleration", "multiplier_lanes", "state_rate_lanes", "tangent_factors_lanes",
    "tangent_rate_lanes", "LANE_WIDTH", "sincos", "shifted", "SHIFT_MAX", "multiplier", "state_rate", "tangent_factors", "tangent_rate", "transport_rate",
    "factor_dlam", "adjoint_factors", "adjoint_rate", "state_stage", "stage_work", "flow_rhs", "flow_tangent_rhs", "adjoint_rhs", "transport_rhs",
]


# ------------------------------------------------------------------ the terms, per rotor
@njit(cache=True, inline="always")
def a_term(u, c):
    """The j-th term u² c of A = Σ u² c (Λ = A/B, eq 8)."""
    return u * u * c


@njit(cache=True, inline="always")
def b_term(s, minv):
    """The j-th term s²/m of B = Σ s²/m (eq 8)."""
    return s * s * minv


@njit(cache=True, inline="always")
def multiplier_of(A, B):
    """(Λ, 1/B) of eq (8) from the sums A, B; both 0 where B = 0 (a singular point)."""
    if B > 0.0:
        return A / B, 1.0 / B
    return 0.0, 0.0


@njit(cache=True, inline="always")
def acceleration(lam, s, minv):
    """u̇ᵢ = −Λ sᵢ / mᵢ of eq (8)."""
    return -lam * s * minv


@njit(cache=True, inline="always")
def factor_f(s, minv):
    """fᵢ = sᵢ/mᵢ of eq (17)."""
    return s * minv


@njit(cache=True, inline="always")
def factor_g(lam, c, minv):
    """gᵢ = Λcᵢ/mᵢ of eq (17)."""
    return lam * c * minv


@njit(cache=True, inline="always")
def factor_p(u, c):
    """pᵢ = 2uᵢcᵢ of eq (17)."""
    return 2.0 * u * c


@njit(cache=True, inline="always")
def factor_q(s, u, g):
    """qᵢ = sᵢ(uᵢ² + 2gᵢ) of eq (17)."""
    return s * (u * u + 2.0 * g)


@njit(cache=True, inline="always")
def tangent_term(p, q, xu, xt):
    """The j-th term pⱼ ũⱼ − qⱼ θ̃ⱼ of B·δΛ in eq (17)."""
    return p * xu - q * xt


@njit(cache=True, inline="always")
def tangent_acceleration(dlam, f, g, xt):
    """ũ̇ᵢ = −(δΛ fᵢ + gᵢ θ̃ᵢ) of eq (17)."""
    return -(dlam * f + g * xt)


# ------------------------------------------------------------------ one trajectory
@njit(cache=True, inline="always")
def multiplier(y, o, n, minv, s, c):
    """(Λ, B) of eq (8) at the state y[o:o+2N] with sin/cos s, c of its angles.
    B = Σ sin²θ/m → 0 only at the singular points (N = 4); Λ is then returned as 0."""
    A = 0.0
    B = 0.0
    for j in range(n):
        A += a_term(y[o + n + j], c[j])
        B += b_term(s[j], minv[j])
    if B > 0.0:
        return A / B, B
    return 0.0, B


@njit(cache=True, inline="always")
def state_rate(y, o, n, minv, s, lam, dy, do):
    """Eq (8): dy[do:do+2N] = (u, −Λ sin θ / m) for the state y[o:o+2N]."""
    for i in range(n):
        dy[do + i] = y[o + n + i]
        dy[do + n + i] = acceleration(lam, s[i], minv[i])


@njit(cache=True, inline="always")
def tangent_factors(y, o, n, minv, s, c, lam, f, g, p, q):
    """The factors f, g, p, q of eq (17) at the state y[o:o+2N] (see the module doc)."""
    for j in range(n):
        u = y[o + n + j]
        f[j] = factor_f(s[j], minv[j])
        g[j] = factor_g(lam, c[j], minv[j])
        p[j] = factor_p(u, c[j])
        q[j] = factor_q(s[j], u, g[j])


@njit(cache=True, inline="always")
def tangent_rate(x, o, n, f, g, p, q, iB, dx, do):
    """Eq (17): dx[do:do+2N] = d/dt of the tangent vector x[o:o+2N]; iB = 1/B."""
    acc = 0.0
    for j in range(n):
        acc += tangent_term(p[j], q[j], x[o + n + j], x[o + j])
    dlam = acc * iB
    for i in range(n):
        dx[do + i] = x[o + n + i]
        dx[do + n + i] = tangent_acceleration(dlam, f[i], g[i], x[o + i])


@njit(cache=True, inline="always")
def transport_rate(x, o, n, y, yo, f, c, iB, dx, do):
    """Eq (19): dx[do:do+N] = d/dt of the transported vector x[o:o+N] along the state
    y[yo:yo+2N]; f = a sin θ / m, c = a cos θ, iB = 1/B."""
    a = 0.0
    for j in range(n):
        a += x[o + j] * y[yo + n + j] * c[j]
    a *= iB
    for i in range(n):
        dx[do + i] = -a * f[i]


@njit(cache=True, inline="always")
def factor_dlam(u, s, c, lam, minv, iB):
    """∂Λ/∂θᵢ = −(uᵢ² sᵢ + 2Λ sᵢcᵢ/mᵢ)/B, the per-rotor factor of ẇ = −J(y)ᵀ w."""
    return (-u * u * s - lam * 2.0 * s * c * minv) * iB


@njit(cache=True, inline="always")
def adjoint_factors(y, yo, n, minv, s, c, lam, iB, fa, fb, fp):
    """The per-rotor factors of ẇ = −J(y)ᵀ w at the state y[yo:yo+2N] (shared by all
    adjoint vectors): fa = ∂Λ/∂θ, fb = g = Λc/m and fp = p/B = 2uc/B (eq 17's factors)."""
    for j in range(n):
        u = y[yo + n + j]
        fa[j] = factor_dlam(u, s[j], c[j], lam, minv[j], iB)
        fb[j] = factor_g(lam, c[j], minv[j])
        fp[j] = factor_p(u, c[j]) * iB


@njit(cache=True, inline="always")
def adjoint_rate(x, o, n, minv, s, fa, fb, fp, dx, do):
    """ẇ = −J(y)ᵀ w for the adjoint vector w = x[o:o+2N], with the factors fa, fb, fp of
    `adjoint_factors` at y."""
    sb = 0.0  # Σ sᵢ bᵢ / mᵢ, b = velocity part of w
    for i in range(n):
        sb += s[i] * x[o + n + i] * minv[i]
    for j in range(n):
        dx[do + j] = fa[j] * sb + fb[j] * x[o + n + j]
        dx[do + n + j] = -(x[o + j] - fp[j] * sb)


# ------------------------------------------------------------------ L trajectories (lanes)
@njit(cache=True, inline="always")
def multiplier_lanes(y, o, n, L, minv, s, c, lam, iB):
    """Eq (8)'s (Λ, 1/B) of the L states y[o + i·L + l] (i < 2N) into lam, iB, shape (L,);
    s, c shape (N·L,) (element j·L + l); L a multiple of `LANE_WIDTH`."""
    W = LANE_WIDTH
    for l0 in range(L - L, L, W):
        for t in range(W):
            lam[l0 + t] = 0.0
            iB[l0 + t] = 0.0
        for j in range(n):
            a = o + (n + j) * L + l0
            b = j * L + l0
            for t in range(W):
                lam[l0 + t] += a_term(y[a + t], c[b + t])
                iB[l0 + t] += b_term(s[b + t], minv[j])
        for t in range(W):
            lam[l0 + t], iB[l0 + t] = multiplier_of(lam[l0 + t], iB[l0 + t])


@njit(cache=True, inline="always")
def state_rate_lanes(y, o, n, L, minv, s, lam, dy, do):
    """Eq (8) of the L states y[o + i·L + l] into dy[do + i·L + l]."""
    W = LANE_WIDTH
    for l0 in range(L - L, L, W):
        for i in range(n):
            a = i * L + l0
            b = (n + i) * L + l0
            for t in range(W):  # two blocks: one would not vectorise (module doc)
                dy[do + a + t] = y[o + b + t]
            for t in range(W):
                dy[do + b + t] = acceleration(lam[l0 + t], s[a + t], minv[i])


@njit(cache=True, inline="always")
def tangent_factors_lanes(y, o, n, L, minv, s, c, lam, f, g, p, q):
    """The factors of eq (17) of the L states y[o + i·L + l] into f, g, p, q, shape (N·L,)."""
    W = LANE_WIDTH
    for l0 in range(L - L, L, W):
        for j in range(n):
            a = o + (n + j) * L + l0
            b = j * L + l0
            for t in range(W):
                e = b + t
                u = y[a + t]
                f[e] = factor_f(s[e], minv[j])
                gj = factor_g(lam[l0 + t], c[e], minv[j])
                g[e] = gj
                p[e] = factor_p(u, c[e])
                q[e] = factor_q(s[e], u, gj)


@njit(cache=True, inline="always")
def tangent_rate_lanes(x, o, k, n, L, f, g, p, q, iB, dlam, dx, do):
    """Eq (17) of the k tangent vectors of L lanes, row r at x[o + (r·2N + i)·L + l], into
    dx[do + (r·2N + i)·L + l]; dlam, shape (k·L,), is work space (row r of the block at
    l0 at l0·k + r·`LANE_WIDTH`: constant offsets, which LLVM sees apart and keeps in
    registers).  The rows of a block in one pass over the rotors (each factor loaded once
    per block, not once per row); per row the operations of `tangent_rate` in its order."""
    W = LANE_WIDTH
    dL = (n + n) * L
    for l0 in range(L - L, L, W):
        for r in range(k):
            for t in range(W):
                dlam[l0 * k + r * W + t] = 0.0
        for j in range(n):
            b = j * L + l0
            for r in range(k):
                a = o + r * dL + (n + j) * L + l0
                e = l0 * k + r * W
                for t in range(W):
                    dlam[e + t] += tangent_term(p[b + t], q[b + t], x[a + t],
                                                x[o + r * dL + b + t])
        for r in range(k):
            for t in range(W):
                dlam[l0 * k + r * W + t] *= iB[l0 + t]
        for i in range(n):
            a = i * L + l0
            b = (n + i) * L + l0
            for r in range(k):
                ro = r * dL
                for t in range(W):  # two blocks: one would not vectorise (module doc)
                    dx[do + ro + a + t] = x[o + ro + b + t]
            for r in range(k):
                ro = r * dL
                e = l0 * k + r * W
                for t in range(W):
                    dx[do + ro + b + t] = tangent_acceleration(dlam[e + t], f[a + t], g[a + t],
                                                               x[o + ro + a + t])


# ------------------------------------------------------------------ stages
@njit(cache=True, inline="always")
def state_stage(y, o, n, minv, a, s, c, dy, do):
    """Eq (8) at the state y[o:o+2N] into dy[do:do+2N], filling s, c = a sin θ, a cos θ;
    returns (Λ, 1/B) for the tangent, transport or adjoint rates at the same point."""
    sincos(y, o, n, a, s, c)
    lam, B = multiplier(y, o, n, minv, s, c)
    state_rate(y, o, n, minv, s, lam, dy, do)
    return lam, (1.0 / B if B > 0.0 else 0.0)


@njit(cache=True)
def stage_work(n):
    """Work arrays (s, c, f, g, p, q), each shape (N,), for the rates above."""
    return (np.empty(n), np.empty(n), np.empty(n), np.empty(n), np.empty(n), np.empty(n))


# ------------------------------------------------------------------ wrappers for Python
@njit(cache=True)
def flow_rhs(y, minv, a, dy):
    """Eq (8): dy = f(y), y and dy shape (2N,), weights a.  Returns B = Σ a² sin²θ/m."""
    n = y.size // 2
    s = np.empty(n)
    c = np.empty(n)
    sincos(y, 0, n, a, s, c)
    lam, B = multiplier(y, 0, n, minv, s, c)
    state_rate(y, 0, n, minv, s, lam, dy, 0)
    return B


@njit(cache=True)
def flow_tangent_rhs(y, X, minv, a, dy, dX):
    """Eq (8) for y, shape (2N,), and eq (17) for each row of X, shape (k, 2N); weights a."""
    n = y.size // 2
    s, c, f, g, p, q = stage_work(n)
    lam, iB = state_stage(y, 0, n, minv, a, s, c, dy, 0)
    tangent_factors(y, 0, n, minv, s, c, lam, f, g, p, q)
    xf = X.reshape(X.size)
    dxf = dX.reshape(dX.size)
    for r in range(X.shape[0]):
        tangent_rate(xf, 2 * n * r, n, f, g, p, q, iB, dxf, 2 * n * r)
    return 1.0 / iB


@njit(cache=True)
def adjoint_rhs(y, W, minv, a, dW):
    """ẇ = −J(y)ᵀ w for each row of W, shape (k, 2N); weights a.  Returns B."""
    n = y.size // 2
    s = np.empty(n)
    c = np.empty(n)
    sincos(y, 0, n, a, s, c)
    lam, B = multiplier(y, 0, n, minv, s, c)
    fa = np.empty(n)
    fb = np.empty(n)
    fp = np.empty(n)
    adjoint_factors(y, 0, n, minv, s, c, lam, 1.0 / B, fa, fb, fp)
    wf = W.reshape(W.size)
    dwf = dW.reshape(dW.size)
    for r in range(W.shape[0]):
        adjoint_rate(wf, 2 * n * r, n, minv, s, fa, fb, fp, dwf, 2 * n * r)
    return B


@njit(cache=True)
def transport_rhs(y, P, minv, a, dP):
    """Eq (19) for each row of P, shape (k, N), along y, shape (2N,); weights a.  Returns B."""
    n = y.size // 2
    s = np.empty(n)
    c = np.empty(n)
    f = np.empty(n)
    sincos(y, 0, n, a, s, c)
    lam, B = multiplier(y, 0, n, minv, s, c)
    for j in range(n):
        f[j] = s[j] * minv[j]
    pf = P.reshape(P.size)
    dpf = dP.reshape(dP.size)
    for r in range(P.shape[0]):
        transport_rate(pf, n * r, n, y, 0, f, c, 1.0 / B, dpf, n * r)
    return B
