"""Ambient formulation of the flow for the integration loop: eq (8) with masses, eq (19)
for transported vectors (both from ``charts.flows.ambient``).

State ``y = (θ₀…θ_{N−1}, u₀…u_{N−1}, p¹, …, pᵏ)``, shape ((2 + k)·N,), all ambient.  The
constraint Σcos θ = 0 (eq 9), the tangency Σ uᵢ sin θᵢ = 0 (eq 10) and the energy ½Σ mᵢuᵢ²
are first integrals; with ``project=True`` the state is put back on all three after every
step (``charts.geometry.projection.project_state``) and each pʲ is made tangent again.  The
loop monitors all three at every step.

Parameters: ``par = (N, 1/m (N), m (N), speed, project, cap fraction, work (3N), weights a
(N), level c)`` — the work area holds a sin θ, a cos θ and a sin θ/m of the point being
evaluated, so that no hook allocates; ``ipar = (N, k)``.  The constraint is Σ a cos θ = c.
"""
from __future__ import annotations

from functools import cache

import numpy as np
from numba import njit

from ..flows.ambient import multiplier, sincos, state_rate, transport_rate
from ..geometry.projection import invariants_of, project_state, project_velocity
from .loop import CAP_SIG, INV_SIG, OUT_SIG, POST_CHANGED, POST_OK, POST_SIG, Formulation
from .rk import RHS_SIG
from .status import step_cap

__all__ = ["AmbientFlow"]


@njit(cache=True, inline="always")
def _point(y, par, n):
    """Views of the work area: (1/m, a sin θ, a cos θ, a sin θ/m) with sin/cos of y filled in."""
    w = 2 * n + 4
    minv = par[1:1 + n]
    s = par[w:w + n]
    c = par[w + n:w + 2 * n]
    f = par[w + 2 * n:w + 3 * n]
    sincos(y, 0, n, par[w + 3 * n:w + 4 * n], s, c)
    for j in range(n):
        f[j] = s[j] * minv[j]
    return minv, s, c, f


def _rhs(y, par, dy):
    """Eq (8) and eq (19); returns S = Σ a² sin²θ (0 at a singular point: dy is then 0)."""
    n = int(par[0])
    nv = (y.size - 2 * n) // n
    minv, s, c, f = _point(y, par, n)
    lam, B = multiplier(y, 0, n, minv, s, c)
    if B == 0.0:
        for i in range(y.size):
            dy[i] = 0.0
        return 0.0
    state_rate(y, 0, n, minv, s, lam, dy, 0)
    for r in range(nv):
        o = (2 + r) * n
        transport_rate(y, o, n, y, 0, f, c, 1.0 / B, dy, o)
    S = 0.0
    for j in range(n):
        S += s[j] * s[j]
    return S


def _cap(y, par, ipar):
    n = ipar[0]
    S = 0.0
    U = 0.0
    for j in range(n):
        S += (par[5 * n + 4 + j] * np.sin(y[j])) ** 2
        U += y[n + j] ** 2
    return step_cap(S, U, par[2 * n + 3])


@njit(cache=True)
def _project(y, par, ipar):
    """Project (θ, u) onto the invariants and each p onto the tangent space, in place."""
    n = ipar[0]
    project_state(y[:2 * n], par[1 + n:1 + 2 * n], par[5 * n + 4:6 * n + 4], par[6 * n + 4],
                  par[2 * n + 1])
    minv, s, c, f = _point(y, par, n)
    for r in range(ipar[1]):
        project_velocity(y, (2 + r) * n, n, s, minv)


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


def _invariants(y, par, ipar, inv):
    n = ipar[0]
    inv[0], inv[1], inv[2] = invariants_of(y, n, par[1 + n:1 + 2 * n], par[5 * n + 4:6 * n + 4],
                                           par[6 * n + 4])
    return 0.0


@cache
def _hooks():
    return (njit(RHS_SIG, cache=True)(_rhs), njit(CAP_SIG, cache=True)(_cap),
            njit(POST_SIG, cache=True)(_post), njit(OUT_SIG, cache=True)(_to_ambient),
            njit(INV_SIG, cache=True)(_invariants))


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
                              [speed, float(self.project), self.cap_fraction], np.zeros(3 * n),
                              sys.weights, [sys.level]])
        ipar = np.array([n, P.shape[0]], dtype=np.int64)
        return y, par, ipar
