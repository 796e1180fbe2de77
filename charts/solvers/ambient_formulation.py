"""Ambient formulation of the flow: eq (8) with masses, eq (19) for transported vectors.

State ``y = (θ₀…θ_{N−1}, u₀…u_{N−1}, p¹, …, pᵏ)``, shape ((2 + k)·N,), all ambient:

    θ̇ᵢ = uᵢ,   mᵢ u̇ᵢ = −Λ sin θᵢ,   Λ = Σ u_j² cos θ_j / Σ sin²θ_j/m_j         (eq 8)
    mᵢ ṗᵢ = −(Σ p_j u_j cos θ_j / Σ sin²θ_j/m_j) sin θᵢ                        (eq 19)

The constraint Σcos θ = 0 (eq 9), the tangency Σ uᵢ sin θᵢ = 0 (eq 10) and the energy
½Σ mᵢuᵢ² are first integrals; with ``project=True`` the state is put back on all three
after every step (``charts.ambient.project_state``) and each pʲ is projected
M-orthogonally onto the tangent space.  The driver monitors all three at every step.

Parameters: ``par = (N, 1/m (N), m (N), speed, project)``, ``ipar = (N, k)``.
"""
from __future__ import annotations

import math
from functools import cache

import numpy as np
from numba import njit

from ..flows.ambient import project_state
from .loop import CAP_SIG, OUT_SIG, POST_CHANGED, POST_OK, POST_SIG, Formulation
from .rk import RHS_SIG

__all__ = ["AmbientFlow"]


def _rhs(y, par, dy):
    """Eq (8) and eq (19); returns S = Σ sin²θ (0 at a singular point: dy is then 0)."""
    n = int(par[0])
    nv = (y.size - 2 * n) // n
    A = 0.0
    Bm = 0.0
    S = 0.0
    for j in range(n):
        s = math.sin(y[j])
        A += y[n + j] * y[n + j] * math.cos(y[j])
        Bm += s * s * par[1 + j]
        S += s * s
    if Bm == 0.0:
        for i in range(y.size):
            dy[i] = 0.0
        return 0.0
    lam = A / Bm
    for i in range(n):
        dy[i] = y[n + i]
        dy[n + i] = -lam * math.sin(y[i]) * par[1 + i]
    for r in range(nv):
        o = (2 + r) * n
        a = 0.0
        for j in range(n):
            a += y[o + j] * y[n + j] * math.cos(y[j])
        a /= Bm
        for i in range(n):
            dy[o + i] = -a * math.sin(y[i]) * par[1 + i]
    return S


def _cap(y, par, ipar):
    n = ipar[0]
    S = 0.0
    U = 0.0
    for j in range(n):
        S += math.sin(y[j]) ** 2
        U += y[n + j] ** 2
    if U == 0.0:
        return np.inf
    return par[2 * n + 3] * math.sqrt(S / U)


@njit(cache=True)
def _project(y, par, ipar):
    """Project (θ, u) onto the invariants and each p onto the tangent space, in place."""
    n = ipar[0]
    nv = ipar[1]
    project_state(y[:2 * n], par[1 + n:1 + 2 * n], par[2 * n + 1])
    Bm = 0.0
    for j in range(n):
        Bm += math.sin(y[j]) ** 2 * par[1 + j]
    for r in range(nv):
        o = (2 + r) * n
        G = 0.0
        for j in range(n):
            G += y[o + j] * math.sin(y[j])
        for j in range(n):
            y[o + j] -= G / Bm * math.sin(y[j]) * par[1 + j]


def _post(y, par, ipar, t, log):
    if par[2 * ipar[0] + 2] == 0.0:
        return POST_OK
    _project(y, par, ipar)
    return POST_CHANGED


def _to_ambient(y, par, ipar, row):
    for i in range(y.size):
        row[i] = y[i]
    if par[2 * ipar[0] + 2] != 0.0:  # samples from the dense output are projected as well
        _project(row, par, ipar)
    return 0.0


@cache
def _hooks():
    return (njit(RHS_SIG, cache=True)(_rhs), njit(CAP_SIG, cache=True)(_cap),
            njit(POST_SIG, cache=True)(_post), njit(OUT_SIG, cache=True)(_to_ambient))


class AmbientFlow(Formulation):
    """Eq (8) + eq (19) in ambient angles; optional projection onto the invariants."""

    name = "ambient"

    def hooks(self):
        return _hooks()

    def initial(self, theta, u, P):
        n = self.n
        sys = self.system
        y = np.concatenate([theta, u, P.ravel()])
        speed = float(sys.speed(u))
        par = np.concatenate([[n], sys.minv, sys.masses,
                              [speed, float(self.project), self.cap_fraction]])
        ipar = np.array([n, P.shape[0]], dtype=np.int64)
        return y, par, ipar
