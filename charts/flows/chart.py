"""The intrinsic equations in a chart: the geodesic equation (14) and parallel transport
(16), with Γ from the generated kernels (``charts.geometry.kernels``).

Chart k's state is y = (q, v, p¹, …, pᵏ), shape ((2 + k)·(N − 1),):

    q̇ᵃ = vᵃ,   v̇ᵃ = −Γᵃ_bc vᵇ vᶜ   (eq 14),   ṗᵃ = −Γᵃ_bc vᵇ pᶜ   (eq 16)

Chart k is the canonical generated chart with θₖ moved last (``charts.geometry.atlas``), so
one compiled function per N serves every chart: the local masses in ``par[1:1+N]`` select it.
"""
from __future__ import annotations

import math
from functools import cache

from ..geometry.kernels import compiled

__all__ = ["chart_rates"]


@cache
def chart_rates(n: int):
    """The right-hand side ``rhs(y, par, dy) -> health`` of eqs (14) + (16) for N = ``n``
    (any chart: the local masses in ``par[1:1+N]`` select it), to be compiled by the caller
    with its signature.  Returns S = Σ sin²θ, or −1 outside the chart."""
    kern = compiled(n)
    ga = kern.geodesic_acceleration
    tr = kern.transport_rate
    d = n - 1

    def rhs(y, par, dy):
        nv = (y.size - 2 * d) // d
        C = 0.0
        S = 0.0
        for a in range(d):
            C += math.cos(y[a])
            S += math.sin(y[a]) ** 2
        s2 = 1.0 - C * C
        if s2 <= 0.0:
            for i in range(y.size):
                dy[i] = 0.0
            return -1.0
        m = par[1:1 + n]
        q = y[:d]
        v = y[d:2 * d]
        ga(q, v, m, dy[d:2 * d])
        for a in range(d):
            dy[a] = y[d + a]
        for r in range(nv):
            o = (2 + r) * d
            tr(q, v, y[o:o + d], m, dy[o:o + d])
        return S + s2

    return rhs
