"""The atlas: N charts × 2 branches, and the relabelling between a chart and the generated
canonical chart.

Chart k eliminates θₖ: its local coordinates are the other angles in increasing order, and
the sign of sin θₖ is its branch.  On the manifold Σ aᵢ cos θᵢ = c the eliminated angle is
θₖ = ±arccos(−C / aₖ), C = Σ_{α≠k} a_α cos θ_α − c, so chart k's domain is |C| < aₖ
(`eliminated_angle`).  The generated code (``charts.generated.rotor_nN``) is written for the
canonical chart k = N − 1; chart k is the same code with θₖ moved last, which is why it takes
the local masses and weights (m without mₖ, then mₖ; the same for a).
"""
from __future__ import annotations

import numpy as np
from ..jit import njit

__all__ = ["chart_coordinates", "local_masses", "local_weights", "ambient_index", "local_index",
           "eliminated_component", "eliminated_angle", "eliminated_component_sc",
           "eliminated_angle_sc", "best_sine", "best_charts"]


def chart_coordinates(n: int, k: int) -> list[int]:
    """Ambient indices of the local coordinates of chart k, in local order."""
    return [i for i in range(n) if i != k]


def local_masses(masses, k: int) -> np.ndarray:
    """Masses in the local order of chart k: (m without mₖ, mₖ)."""
    masses = np.asarray(masses, dtype=float)
    return np.concatenate([np.delete(masses, k), masses[k:k + 1]])


#: The weights in the local order of chart k: the same relabelling as the masses.
local_weights = local_masses


@njit(cache=True, inline="always")
def ambient_index(a, k):
    """Ambient index of local coordinate a of chart k."""
    return a if a < k else a + 1


@njit(cache=True, inline="always")
def local_index(i, k):
    """Local coordinate of ambient index i ≠ k in chart k (the inverse of `ambient_index`)."""
    return i if i < k else i - 1


@njit(cache=True, inline="always")
def best_sine(s_local, s_k, k):
    """(j, |s_j|): the ambient index j of the largest |aᵢ sin θᵢ| (ties: the lowest index)
    and that value, from the local values ``s_local`` of chart k (shape (N − 1,), local order)
    and the eliminated rotor's ``s_k``; signs are ignored.  The one argmax of the atlas:
    `best_charts`, ``RotorSystem.best_chart`` and the switching rule
    (``charts.solvers.chart_formulation.switch_rule``) all call it."""
    j = -1
    smax = -1.0
    for i in range(s_local.size + 1):
        s = abs(s_k) if i == k else abs(s_local[local_index(i, k)])
        if s > smax:
            smax = s
            j = i
    return j, smax


@njit(cache=True)
def best_charts(s):
    """`best_sine` of each row of ``s`` = |aᵢ sin θᵢ|, shape (M, N) (ambient order, read as
    chart 0: s_k = s[:, 0]): the best conditioned chart of each point, shape (M,), int64."""
    out = np.empty(s.shape[0], dtype=np.int64)
    for r in range(s.shape[0]):
        out[r] = best_sine(s[r, 1:], s[r, 0], 0)[0]
    return out


@njit(cache=True, inline="always")
def eliminated_component_sc(ws, x, o, d, w, sk):
    """The eliminated rotor's component of the tangent vector with local components
    x[o:o+d] of chart k, σ = ws = w sin q given (local weights w, wₖ last), where
    sin θₖ = sk: xₖ = −Σ_α x_α σ_α / (wₖ sin θₖ) (tangency, eq 10)."""
    acc = 0.0
    for a in range(d):
        acc += x[o + a] * ws[a]
    return -acc / (w[d] * sk)


@njit(cache=True, inline="always")
def eliminated_component(q, x, o, d, w, sk):
    """`eliminated_component_sc` at local angles q (the first d entries)."""
    ws = np.empty(d)
    for a in range(d):
        ws[a] = w[a] * np.sin(q[a])
    return eliminated_component_sc(ws, x, o, d, w, sk)


@njit(cache=True, inline="always")
def eliminated_angle_sc(wc, d, w, c, branch):
    """cos θₖ, sin θₖ and D = aₖ² − C² = (aₖ sin θₖ)² of chart k, κ = wc = w cos q of its
    local angles given (local weights w, wₖ last), level c, on the branch
    sign(sin θₖ) = ``branch``: aₖ cos θₖ = −C, C = Σ κ_α − c.  D <= 0: the point is outside
    the chart (|C| >= aₖ), and sin θₖ is returned as 0."""
    C = 0.0
    for a in range(d):
        C += wc[a]
    C -= c
    D = w[d] * w[d] - C * C
    return -C / w[d], np.copysign(np.sqrt(max(D, 0.0)) / w[d], branch), D


@njit(cache=True, inline="always")
def eliminated_angle(q, d, w, c, branch):
    """`eliminated_angle_sc` at local angles q (the first d entries)."""
    wc = np.empty(d)
    for a in range(d):
        wc[a] = w[a] * np.cos(q[a])
    return eliminated_angle_sc(wc, d, w, c, branch)
