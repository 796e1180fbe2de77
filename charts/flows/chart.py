"""The intrinsic equations in a chart: the geodesic equation (14) and parallel transport
(16), with Γ from the chart kernels of ``charts.geometry.kernels.geometry`` (generated for the
shipped N, structured otherwise).

Chart k's state is y = (q, v, p¹, …, pᵏ), shape ((2 + k)·(N − 1),):

    q̇ᵃ = vᵃ,   v̇ᵃ = −Γᵃ_bc vᵇ vᶜ   (eq 14),   ṗᵃ = −Γᵃ_bc vᵇ pᶜ   (eq 16)

Chart k is the canonical chart with θₖ moved last (``charts.geometry.atlas``), so one
compiled function per N (per kernel source) serves every chart and every member of the family
Σ aᵢ cos θᵢ = c: ``par`` begins with (N, local masses (N), local weights (N), level c)
(`local_parameters`).  The equations are written once, in `rates`, which takes the two
kernel functions as arguments; the structured kernels need no N, so their right-hand side
(`structured_rates`) is one function for every N, compiled once and cached on disk.
"""
from __future__ import annotations

import math
from functools import cache

import numpy as np
from numba import njit

from ..geometry import structured
from ..geometry.atlas import eliminated_angle, local_masses, local_weights
from ..geometry.kernels import compiled, source

__all__ = ["rates", "chart_rates", "structured_rates", "local_parameters"]


def local_parameters(masses, weights, level, k: int) -> np.ndarray:
    """``par`` for `rates` in chart ``k``: (N, local masses, local weights, level)."""
    n = len(masses)
    return np.concatenate([[n], local_masses(masses, k), local_weights(weights, k), [level]])


@njit(cache=True, inline="always")
def rates(y, par, dy, ga, tr):
    """Eqs (14) + (16) at y into dy with the kernels ``ga`` (geodesic_acceleration) and ``tr``
    (transport_rate) of the chart whose local masses and weights are ``par[1:1+N]``,
    ``par[1+N:1+2N]``, level ``par[1+2N]``, N = ``par[0]``.
    Returns S = Σ aᵢ² sin²θᵢ (as the ambient formulation), or −1 outside the chart
    (|C| >= aₖ, ``charts.geometry.atlas.eliminated_angle``)."""
    n = int(par[0])
    d = n - 1
    nv = (y.size - 2 * d) // d
    m = par[1:1 + n]
    w = par[1 + n:1 + 2 * n]
    c = par[1 + 2 * n]
    _, _, s2 = eliminated_angle(y, d, w, c, 1.0)
    if s2 <= 0.0:
        for i in range(y.size):
            dy[i] = 0.0
        return -1.0
    S = 0.0
    for a in range(d):
        S += (w[a] * math.sin(y[a])) ** 2
    q = y[:d]
    v = y[d:2 * d]
    ga(q, v, m, w, c, dy[d:2 * d])
    for a in range(d):
        dy[a] = y[d + a]
    for r in range(nv):
        o = (2 + r) * d
        tr(q, v, y[o:o + d], m, w, c, dy[o:o + d])
    return S + s2


def structured_rates(y, par, dy):
    """`rates` with the structured kernels: any N, one compilation (the caller's signature)."""
    return rates(y, par, dy, structured.geodesic_acceleration, structured.transport_rate)


@cache
def chart_rates(n: int, paper: bool = False):
    """The right-hand side ``rhs(y, par, dy) -> health`` of eqs (14) + (16) for N = ``n``
    (any chart and member: ``par`` selects them), to be compiled by the caller with its
    signature: `structured_rates` unless N's kernels are generated (``paper``: the paper's
    generated module, ``charts.geometry.kernels.geometry``)."""
    if source(n) == "structured":
        return structured_rates
    kern = compiled(n, paper)
    ga = kern.geodesic_acceleration
    tr = kern.transport_rate

    def rhs(y, par, dy):
        return rates(y, par, dy, ga, tr)

    return rhs
