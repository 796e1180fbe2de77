"""Structured chart geometry for any N: the generated functions' formulas from the shape of
the geometry, compiled once for every N (numba, ``cache=True``; nothing depends on N).

The manifold is Σ aᵢ cos θᵢ = c (weights a > 0, level c; the paper's a = 1, c = 0).  Chart k
embeds the local angles q (d = N − 1 of them; masses m and weights a in local order with the
eliminated rotor's last) as θ(q) with aₖ cos θₖ = −C, C = Σ a_α cos q_α − c, and
(aₖ sin θₖ)² = D = aₖ² − C² (the chart's domain is |C| < aₖ).  With σ = a sin q, κ = a cos q,
its coordinate vectors are E_α = e_α + t_α eₖ, t_α = ∂θₖ/∂q_α = −σ_α / (aₖ sin θₖ).  With the
ambient metric M = diag m, F = Σ a cos θ, the flat Hessian h = Hess F = −diag(a cos θ) and
G = |∇F|² = Σᵢ aᵢ² sin²θᵢ / mᵢ = Σ_α σ_α²/m_α + D/mₖ:

* metric (eq 13), diagonal plus rank one:  g_αβ = m_α δ_αβ + mₖ σ_α σ_β / D;
* its inverse (Sherman–Morrison):          g^αβ = δ_αβ / m_α − σ_α σ_β / (m_α m_β G);
* Christoffel symbols (eq 15): the tangential part of ∂_β∂_γθ = (∂_β∂_γθₖ) eₖ, with
  ∇F·∂_β∂_γθ = −h(E_β, E_γ) from differentiating F(θ(q)) = c twice, is a vector times a
  symmetric matrix, Γ^α_βγ = −(σ_α / (m_α G)) h_βγ,  h_βγ = h(E_β, E_γ) = −(κ_β δ_βγ − C σ_β σ_γ / D),
  so that Γ^α_βγ vᵝ pᵞ = −(σ_α / (m_α G)) h(V, P) costs O(N) (V, P the ambient vectors);
* Riemann tensor from the Gauss equation of the hypersurface F = c in (Rᴺ, M):
  R_αβγδ = ⟨R(∂_γ, ∂_δ)∂_β, ∂_α⟩ = (h_αγ h_βδ − h_αδ h_βγ) / G, and the sectional curvature
  of the plane of ambient tangent vectors v, w is [h(v,v)h(w,w) − h(v,w)²] / (G |v∧w|²).

For a = 1, c = 0 every product with a weight is a product with 1 and the level is added as 0,
so these are the operations of the unweighted kernels (the same bits).  The functions take and
fill the same arguments as the generated ones (``charts.generated.rotor_nN``), so either
serves ``charts.geometry.kernels.geometry``.
"""
from __future__ import annotations

import math

import numpy as np
from ..jit import njit

from .atlas import eliminated_component as _eliminated_at

__all__ = ["metric", "metric_inverse", "christoffel", "riemann", "geodesic_acceleration",
           "transport_rate", "geodesic_acceleration_sc", "transport_rate_sc", "curvature_operator", "eliminated_component", "chart_hessian",
           "gauss_sectional", "gauss_frame_curvature", "FUNCTIONS"]

#: The functions shared with the generated modules (``charts.codegen.names.GENERATED_FUNCTIONS``).
FUNCTIONS = ("metric", "metric_inverse", "christoffel", "riemann", "geodesic_acceleration",
             "transport_rate", "curvature_operator", "eliminated_component",
             "geodesic_acceleration_sc", "transport_rate_sc")


@njit(cache=True, inline="always")
def _weighted_sincos(q, w, s, k):
    """Fills s = σ = w sin q and k = κ = w cos q (local weights w)."""
    for a in range(q.size):
        s[a] = w[a] * math.sin(q[a])
        k[a] = w[a] * math.cos(q[a])


@njit(cache=True, inline="always")
def _chart_scalars_sc(s, k, m, w, c):
    """(C, D, G) of the chart point with σ = s, κ = k, local masses m, local weights w and
    level c (see the module doc)."""
    d = s.size
    C = 0.0
    G = 0.0
    for a in range(d):
        C += k[a]
        G += s[a] * s[a] / m[a]
    C -= c
    sk2 = w[d] * w[d] - C * C
    return C, sk2, G + sk2 / m[d]


@njit(cache=True, inline="always")
def _chart_scalars(q, m, w, c, s):
    """Fills s = σ = w sin q; returns (C, D, G) of chart coordinates q (`_chart_scalars_sc`)."""
    k = np.empty(q.size)
    _weighted_sincos(q, w, s, k)
    return _chart_scalars_sc(s, k, m, w, c)


@njit(cache=True, inline="always")
def _hess(s, k, C, sk2, x, y):
    """h(X, Y) = −Σᵢ aᵢ cos θᵢ Xᵢ Yᵢ of the ambient vectors of local components x, y
    (σ = s, κ = k)."""
    acc = 0.0
    sx = 0.0
    sy = 0.0
    for a in range(s.size):
        acc += k[a] * x[a] * y[a]
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
def metric(q, m, a, c, out):
    """g_αβ, eq (13): diag(m_α) + mₖ σ σᵀ / D; out shape (d, d)."""
    d = q.size
    s = np.empty(d)
    C, sk2, G = _chart_scalars(q, m, a, c, s)
    return _diag_plus_rank_one(s, m[d] / sk2, m[:d], out)


@njit(cache=True)
def metric_inverse(q, m, a, c, out):
    """g^αβ = δ_αβ / m_α − σ_α σ_β / (m_α m_β G) (Sherman–Morrison); out shape (d, d)."""
    d = q.size
    s = np.empty(d)
    C, sk2, G = _chart_scalars(q, m, a, c, s)
    minv = 1.0 / m[:d]
    return _diag_plus_rank_one(s * minv, -1.0 / G, minv, out)


@njit(cache=True)
def chart_hessian(q, m, w, c, out):
    """h_αβ = h(E_α, E_β) = −(κ_α δ_αβ − C σ_α σ_β / D); out shape (d, d).  Returns G."""
    d = q.size
    s = np.empty(d)
    C, sk2, G = _chart_scalars(q, m, w, c, s)
    for a in range(d):
        for b in range(d):
            out[a, b] = C * s[a] * s[b] / sk2
        out[a, a] -= w[a] * math.cos(q[a])
    return G


@njit(cache=True)
def christoffel(q, m, w, c, out):
    """Γ^α_βγ = −(σ_α / (m_α G)) h_βγ, upper index first, eq (15); out shape (d, d, d)."""
    d = q.size
    h = np.empty((d, d))
    G = chart_hessian(q, m, w, c, h)
    for a in range(d):
        f = -(w[a] * math.sin(q[a])) / (m[a] * G)
        for b in range(d):
            for c in range(d):
                out[a, b, c] = f * h[b, c]
    return out


@njit(cache=True)
def riemann(q, m, w, c, out):
    """R_αβγδ = ⟨R(∂_γ, ∂_δ)∂_β, ∂_α⟩ = (h_αγ h_βδ − h_αδ h_βγ) / G (Gauss equation);
    out shape (d, d, d, d)."""
    d = q.size
    h = np.empty((d, d))
    G = chart_hessian(q, m, w, c, h)
    for a in range(d):
        for b in range(d):
            for g in range(d):
                for e in range(d):
                    out[a, b, g, e] = (h[a, g] * h[b, e] - h[a, e] * h[b, g]) / G
    return out


@njit(cache=True, error_model="numpy")
def transport_rate_sc(ws, wc, v, p, m, w, c, out):
    """dp^α/dt = −Γ^α_βγ vᵝ pᵞ = (σ_α / (m_α G)) h(V, P), eq (16), with σ = ws = w sin q and
    κ = wc = w cos q given; O(d), out shape (d,)."""
    d = ws.size
    C, sk2, G = _chart_scalars_sc(ws, wc, m, w, c)
    f = _hess(ws, wc, C, sk2, v, p) / G
    for a in range(d):
        out[a] = f * ws[a] / m[a]
    return out


@njit(cache=True, error_model="numpy")
def geodesic_acceleration_sc(ws, wc, v, m, a, c, out):
    """dv^α/dt = −Γ^α_βγ vᵝ vᵞ, eq (14) (`transport_rate_sc` with p = v); out shape (d,)."""
    return transport_rate_sc(ws, wc, v, v, m, a, c, out)


@njit(cache=True)
def transport_rate(q, v, p, m, w, c, out):
    """`transport_rate_sc` at the local angles q."""
    s = np.empty(q.size)
    k = np.empty(q.size)
    _weighted_sincos(q, w, s, k)
    return transport_rate_sc(s, k, v, p, m, w, c, out)


@njit(cache=True)
def geodesic_acceleration(q, v, m, a, c, out):
    """dv^α/dt = −Γ^α_βγ vᵝ vᵞ, eq (14) (`transport_rate` with p = v); out shape (d,)."""
    return transport_rate(q, v, v, m, a, c, out)


@njit(cache=True)
def curvature_operator(q, x, y, m, w, c, out):
    """(R(x, y) y)^α = g^αβ [h_β(x) h(y, y) − h_β(y) h(x, y)] / G, the operator of the Jacobi
    equation J'' + R(J, v) v = 0; O(d), out shape (d,)."""
    d = q.size
    s = np.empty(d)
    kk = np.empty(d)
    _weighted_sincos(q, w, s, kk)
    C, sk2, G = _chart_scalars_sc(s, kk, m, w, c)
    hyy = _hess(s, kk, C, sk2, y, y)
    hxy = _hess(s, kk, C, sk2, x, y)
    sx = 0.0
    sy = 0.0
    for a in range(d):
        sx += s[a] * x[a]
        sy += s[a] * y[a]
    acc = 0.0
    for a in range(d):  # lowered: L_α = h_α(x) h(y,y) − h_α(y) h(x,y), h_α(x) = Σ_β h_αβ xᵝ
        k = kk[a]
        hx = -(k * x[a] - C * s[a] * sx / sk2)
        hy = -(k * y[a] - C * s[a] * sy / sk2)
        out[a] = (hx * hyy - hy * hxy) / G
        acc += s[a] * out[a] / m[a]
    for a in range(d):  # raised with the Sherman–Morrison inverse
        out[a] = out[a] / m[a] - s[a] * acc / (m[a] * G)
    return out


@njit(cache=True)
def eliminated_component(q, x, a, sin_k):
    """Ambient component of the eliminated angle of the tangent vector x (tangency, eq 10)."""
    return _eliminated_at(q, x, 0, q.size, a, sin_k)


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
