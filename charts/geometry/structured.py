"""Structured chart geometry for any N: the generated functions' formulas from the shape of
the geometry, compiled once for every N (numba, ``cache=True``; nothing depends on N).

Chart k embeds the local angles q (d = N − 1 of them, masses m in local order with the
eliminated rotor's mass mₖ last) as θ(q) with cos θₖ = −C, C = Σ cos q_α, sin²θₖ = 1 − C².
Its coordinate vectors are E_α = e_α + tₐ eₖ with t_α = ∂θₖ/∂q_α = −s_α / sin θₖ (s = sin q,
c = cos q).  With the ambient metric M = diag m, F = Σ cos θ, the flat Hessian
h = Hess F = −diag(cos θ) and G = |∇F|² = Σᵢ sin²θᵢ / mᵢ:

* metric (eq 13), diagonal plus rank one:  g_αβ = m_α δ_αβ + mₖ s_α s_β / sin²θₖ;
* its inverse (Sherman–Morrison):          g^αβ = δ_αβ / m_α − s_α s_β / (m_α m_β G);
* Christoffel symbols (eq 15): Γ_{α,βγ} = ⟨E_α, ∂_β∂_γ θ⟩_M = mₖ t_α ∂_β∂_γθₖ, and raising
  the index with g⁻¹ gives a vector times a symmetric matrix,
  Γ^α_βγ = −(s_α / (m_α G)) h_βγ,   h_βγ = h(E_β, E_γ) = −(c_β δ_βγ − C s_β s_γ / sin²θₖ),
  so that Γ^α_βγ vᵝ pᵞ = −(s_α / (m_α G)) h(V, P) costs O(N) (V, P the ambient vectors);
* Riemann tensor from the Gauss equation of the hypersurface F = 0 in (Rᴺ, M):
  R_αβγδ = ⟨R(∂_γ, ∂_δ)∂_β, ∂_α⟩ = (h_αγ h_βδ − h_αδ h_βγ) / G, and the sectional curvature
  of the plane of ambient tangent vectors v, w is [h(v,v)h(w,w) − h(v,w)²] / (G |v∧w|²).

The functions take and fill the same arguments as the generated ones
(``charts.generated.rotor_nN``), so either serves ``charts.geometry.kernels.geometry``.
"""
from __future__ import annotations

import math

import numpy as np
from numba import njit

from .atlas import eliminated_component as _eliminated_at

__all__ = ["metric", "metric_inverse", "christoffel", "riemann", "geodesic_acceleration",
           "transport_rate", "curvature_operator", "eliminated_component", "chart_hessian",
           "gauss_sectional", "gauss_frame_curvature", "FUNCTIONS"]

#: The functions shared with the generated modules (``charts.codegen.names.GENERATED_FUNCTIONS``).
FUNCTIONS = ("metric", "metric_inverse", "christoffel", "riemann", "geodesic_acceleration",
             "transport_rate", "curvature_operator", "eliminated_component")


@njit(cache=True, inline="always")
def _chart_scalars(q, m, s):
    """Fills s = sin q; returns (C, sin²θₖ, G) of chart coordinates q with local masses m."""
    d = q.size
    C = 0.0
    G = 0.0
    for a in range(d):
        s[a] = math.sin(q[a])
        C += math.cos(q[a])
        G += s[a] * s[a] / m[a]
    sk2 = 1.0 - C * C
    return C, sk2, G + sk2 / m[d]


@njit(cache=True, inline="always")
def _hess(q, s, C, sk2, x, y):
    """h(X, Y) = −Σᵢ cos θᵢ Xᵢ Yᵢ of the ambient vectors of local components x, y."""
    acc = 0.0
    sx = 0.0
    sy = 0.0
    for a in range(q.size):
        acc += math.cos(q[a]) * x[a] * y[a]
        sx += s[a] * x[a]
        sy += s[a] * y[a]
    return -(acc - C * sx * sy / sk2)


@njit(cache=True, inline="always")
def _diag_plus_rank_one(x, f, diag, out):
    """out = diag(diag) + f x xᵀ."""
    d = x.size
    for a in range(d):
        for b in range(d):
            out[a, b] = f * x[a] * x[b]
        out[a, a] += diag[a]
    return out


@njit(cache=True)
def metric(q, m, out):
    """g_αβ, eq (13): diag(m_α) + mₖ s sᵀ / sin²θₖ; out shape (d, d)."""
    d = q.size
    s = np.empty(d)
    C, sk2, G = _chart_scalars(q, m, s)
    return _diag_plus_rank_one(s, m[d] / sk2, m[:d], out)


@njit(cache=True)
def metric_inverse(q, m, out):
    """g^αβ = δ_αβ / m_α − s_α s_β / (m_α m_β G) (Sherman–Morrison); out shape (d, d)."""
    d = q.size
    s = np.empty(d)
    C, sk2, G = _chart_scalars(q, m, s)
    minv = 1.0 / m[:d]
    return _diag_plus_rank_one(s * minv, -1.0 / G, minv, out)


@njit(cache=True)
def chart_hessian(q, m, out):
    """h_αβ = h(E_α, E_β) = −(c_α δ_αβ − C s_α s_β / sin²θₖ); out shape (d, d).  Returns G."""
    d = q.size
    s = np.empty(d)
    C, sk2, G = _chart_scalars(q, m, s)
    for a in range(d):
        for b in range(d):
            out[a, b] = C * s[a] * s[b] / sk2
        out[a, a] -= math.cos(q[a])
    return G


@njit(cache=True)
def christoffel(q, m, out):
    """Γ^α_βγ = −(s_α / (m_α G)) h_βγ, upper index first, eq (15); out shape (d, d, d)."""
    d = q.size
    h = np.empty((d, d))
    G = chart_hessian(q, m, h)
    for a in range(d):
        f = -math.sin(q[a]) / (m[a] * G)
        for b in range(d):
            for c in range(d):
                out[a, b, c] = f * h[b, c]
    return out


@njit(cache=True)
def riemann(q, m, out):
    """R_αβγδ = ⟨R(∂_γ, ∂_δ)∂_β, ∂_α⟩ = (h_αγ h_βδ − h_αδ h_βγ) / G (Gauss equation);
    out shape (d, d, d, d)."""
    d = q.size
    h = np.empty((d, d))
    G = chart_hessian(q, m, h)
    for a in range(d):
        for b in range(d):
            for c in range(d):
                for e in range(d):
                    out[a, b, c, e] = (h[a, c] * h[b, e] - h[a, e] * h[b, c]) / G
    return out


@njit(cache=True)
def transport_rate(q, v, p, m, out):
    """dp^α/dt = −Γ^α_βγ vᵝ pᵞ = (s_α / (m_α G)) h(V, P), eq (16); O(d), out shape (d,)."""
    d = q.size
    C, sk2, G = _chart_scalars(q, m, out)  # out holds s until the last loop
    f = _hess(q, out, C, sk2, v, p) / G
    for a in range(d):
        out[a] = f * out[a] / m[a]
    return out


@njit(cache=True)
def geodesic_acceleration(q, v, m, out):
    """dv^α/dt = −Γ^α_βγ vᵝ vᵞ, eq (14) (`transport_rate` with p = v); out shape (d,)."""
    return transport_rate(q, v, v, m, out)


@njit(cache=True)
def curvature_operator(q, x, y, m, out):
    """(R(x, y) y)^α = g^αβ [h_β(x) h(y, y) − h_β(y) h(x, y)] / G, the operator of the Jacobi
    equation J'' + R(J, v) v = 0; O(d), out shape (d,)."""
    d = q.size
    s = np.empty(d)
    C, sk2, G = _chart_scalars(q, m, s)
    hyy = _hess(q, s, C, sk2, y, y)
    hxy = _hess(q, s, C, sk2, x, y)
    sx = 0.0
    sy = 0.0
    for a in range(d):
        sx += s[a] * x[a]
        sy += s[a] * y[a]
    acc = 0.0
    for a in range(d):  # lowered: L_α = h_α(x) h(y,y) − h_α(y) h(x,y), h_α(x) = Σ_β h_αβ xᵝ
        c = math.cos(q[a])
        hx = -(c * x[a] - C * s[a] * sx / sk2)
        hy = -(c * y[a] - C * s[a] * sy / sk2)
        out[a] = (hx * hyy - hy * hxy) / G
        acc += s[a] * out[a] / m[a]
    for a in range(d):  # raised with the Sherman–Morrison inverse
        out[a] = out[a] / m[a] - s[a] * acc / (m[a] * G)
    return out


@njit(cache=True)
def eliminated_component(q, x, sin_k):
    """Ambient component of the eliminated angle of the tangent vector x (tangency, eq 10)."""
    return _eliminated_at(q, x, 0, q.size, sin_k)


@njit(cache=True)
def gauss_sectional(theta, v, w, m, wts):
    """Sectional curvature of the plane of the ambient tangent vectors v, w at theta by the
    Gauss equation: [h(v,v)h(w,w) − h(v,w)²] / (G (|v|²|w|² − ⟨v,w⟩²)), all in (Rᴺ, diag m),
    for F = Σ aᵢ cos θᵢ (a = ``wts``): h = −diag(a cos θ), G = Σ a² sin²θ / m.
    O(N).  Returns (K, |v|²|w|² − ⟨v,w⟩²)."""
    hvv = 0.0
    hww = 0.0
    hvw = 0.0
    vv = 0.0
    ww = 0.0
    vw = 0.0
    G = 0.0
    for i in range(theta.size):
        c = wts[i] * math.cos(theta[i])
        s = wts[i] * math.sin(theta[i])
        hvv -= c * v[i] * v[i]
        hww -= c * w[i] * w[i]
        hvw -= c * v[i] * w[i]
        vv += m[i] * v[i] * v[i]
        ww += m[i] * w[i] * w[i]
        vw += m[i] * v[i] * w[i]
        G += s * s / m[i]
    area2 = vv * ww - vw * vw
    return (hvv * hww - hvw * hvw) / (G * area2), area2


@njit(cache=True)
def gauss_frame_curvature(theta, P, m, wts, K):
    """K_ij = ⟨R(p_j, p_0)p_0, p_i⟩ = [h(p_i,p_j)h(p_0,p_0) − h(p_i,p_0)h(p_j,p_0)] / G for the
    M-orthonormal ambient frame P, shape (k + 1, N) (row 0 = p_0), into K, shape (k, k);
    weights a = ``wts`` (h = −diag(a cos θ), G = Σ a² sin²θ / m); O(N k²)."""
    n = theta.size
    r = P.shape[0]
    c = np.empty(n)
    G = 0.0
    for i in range(n):
        c[i] = wts[i] * math.cos(theta[i])
        G += (wts[i] * math.sin(theta[i])) ** 2 / m[i]
    H = np.zeros((r, r))
    for a in range(r):
        for b in range(a + 1):
            acc = 0.0
            for i in range(n):
                acc -= c[i] * P[a, i] * P[b, i]
            H[a, b] = acc
            H[b, a] = acc
    for i in range(r - 1):
        for j in range(r - 1):
            K[i, j] = (H[i + 1, j + 1] * H[0, 0] - H[i + 1, 0] * H[j + 1, 0]) / G
    return K
