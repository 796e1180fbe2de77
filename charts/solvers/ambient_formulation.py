"""Ambient formulation of the flow for the integration loop: eq (8) with masses, eq (19)
for transported vectors (both from ``charts.flows.ambient``).

State ``y = (θ₀…θ_{N−1}, u₀…u_{N−1}, p¹, …, pᵏ)``, shape ((2 + k)·N,), all ambient.  The
constraint Σcos θ = 0 (eq 9), the tangency Σ uᵢ sin θᵢ = 0 (eq 10) and the energy ½Σ mᵢuᵢ²
are first integrals; with ``project=True`` the state is put back on all three after every
step (``charts.geometry.projection.project_state``) and each pʲ is made tangent again.  The
loop monitors all three at every step.

RK4 steps as the tangent kernel's step (``charts.solvers.tangent``; :func:`_step`, from the
same stage point, sin/cos shift, state rate and step end): the stage sin/cos are the step
start's shifted by δ = cᵢ·h·K (no libm inside a step), the start's own are carried from step
to step and recomputed (libm) only after a projection.  So ``integrate(...,
formulation="ambient", method="rk4")`` and ``TangentFlow(..., k=0)`` give the same bits
(projection: ``project=True`` is the tangent kernel's ``project_every`` = 1 step, ``False``
its 0) wherever the step cap (``charts.solvers.status``) does not bind; where it binds, near
a singular point, the loop caps each step from its own start while the tangent kernel cuts
dt into equal sub-steps (through Σ sin²θ ≈ 2e-6: 1.1e-7 against 5.0e-5 from DOP853 at
rtol 1e-13, docs/integrators.md).  DOP853 evaluates libm at every stage (:func:`_rhs`).

Parameters: ``par = (N, 1/m (N), m (N), speed, project, cap fraction, work (3N), weights a
(N), level c, step area (9N))`` — the work area holds a sin θ, a cos θ and a sin θ/m of the
point being evaluated, the step area the step start's a sin θ, a cos θ (s₀, c₀: carried),
the step's work and the state last projected, so that no hook allocates; ``ipar = (N, k)``.
The constraint is Σ a cos θ = c.
"""
from __future__ import annotations

from functools import cache

import numpy as np
from numba import njit

from ..flows.ambient import multiplier, sincos, state_rate, transport_rate
from ..geometry.projection import invariants_of, project_state, project_velocity
from .loop import (CAP_SIG, INV_SIG, OUT_SIG, POST_CHANGED, POST_OK, POST_SIG, STEP_SIG,
                   Formulation)
from .rk import NO_REFCOUNT, RHS_SIG
from .status import step_cap, sum_squares
from .tangent import stacked_rk4_step

#: Landing steps within this relative distance of dt are the grid's step dt (the loop's time
#: is a sum of steps, so the last step to an output time on the grid is dt up to rounding).
LANDING_RTOL = 1e-9

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


@njit(cache=True, inline="always")
def transport_vectors_rate(Zt, n, minv, s, c, lam, iB, f, _w1, _w2, _w3, K, o, R, d):
    """Eq (19) for the R transported vectors (rows of d = N after the state's 2N) at the stage
    point Zt into K[o:] (the hook of ``charts.solvers.tangent.stacked_rk4_step``); returns
    the stage's S = Σ (a sin θ)² (the loop's health)."""
    if R > 0:
        for j in range(n):
            f[j] = s[j] * minv[j]
        for r in range(R):
            oo = n + n + r * d
            transport_rate(Zt, oo, n, Zt, 0, f, c, iB, K, o + oo)
    return sum_squares(s, 0, n)


def _step(rhs, y, h, dt, par, K, ytmp, ynew):
    """The RK4 step hook: `_rk4_step` of eqs (8) + (19) from y into ynew, s₀, c₀ in the step
    area advancing with it; returns the smallest S = Σ (a sin θ)² of its stages (rhs
    unused).  A landing step within rounding of dt is dt (`LANDING_RTOL`)."""
    n = int(par[0])
    a = 6 * n + 5                              # the step area
    if abs(h - dt) <= LANDING_RTOL * dt:
        h = dt
    for i in range(y.size):
        ynew[i] = y[i]
    f = par[a + 6 * n:a + 7 * n]
    return stacked_rk4_step(ynew, ytmp, K.reshape(K.size), par[a + 2 * n:a + 3 * n],
                            par[a + 3 * n:a + 4 * n], par[a + 4 * n:a + 5 * n],
                            par[a + 5 * n:a + 6 * n], f, f, f, f, par[a:a + n],
                            par[a + n:a + 2 * n], par[1:1 + n], par[5 * n + 4:6 * n + 4], h,
                            np.uint64(n), np.uint64((y.size - 2 * n) // n), np.uint64(n),
                            np.uint64(y.size), transport_vectors_rate)


def _rk4_cap(y, par, ipar):
    """RK4's step cap (``status.step_cap``) from the carried s₀ of the step area (no libm)."""
    n = ipar[0]
    a = 6 * n + 5
    return step_cap(sum_squares(par, a, n), sum_squares(y, n, n), par[2 * n + 3])


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
    n = ipar[0]
    if par[2 * n + 2] == 0.0:
        return POST_OK
    _project(y, par, ipar)
    w, a = 2 * n + 4, 6 * n + 5   # the projected point's libm sin/cos become the next s₀, c₀
    for j in range(2 * n):
        par[a + j] = par[w + j]
    for j in range(2 * n):        # and the projected state is remembered (`_to_ambient`)
        par[a + 7 * n + j] = y[j]
    return POST_CHANGED


def _to_ambient(y, par, ipar, row):
    n = ipar[0]
    for i in range(y.size):
        row[i] = y[i]
    if par[2 * n + 2] == 0.0:
        return 0.0
    same = True                   # the state that `_post` projected last is output as is
    for j in range(2 * n):
        same = same and y[j] == par[6 * n + 5 + 7 * n + j]
    if not same:                  # samples inside a step are projected as well
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


@cache
def _rk4_hooks():
    """RK4's own: the cap from the carried s₀ and the step hook (the tangent kernel's step)."""
    return (njit(CAP_SIG, cache=True, error_model="numpy", **NO_REFCOUNT)(_rk4_cap),
            njit(STEP_SIG, cache=True, error_model="numpy", **NO_REFCOUNT)(_step))


class AmbientFlow(Formulation):
    """Eq (8) + eq (19) in ambient angles; optional projection onto the invariants."""

    name = "ambient"

    def hooks(self, method):
        rhs, cap, post, out, inv = _hooks()
        if method == "rk4":
            cap, step = _rk4_hooks()
        else:
            step = None
        return rhs, step, cap, post, out, inv

    def initial(self, theta, u, P):
        n = self.n
        sys = self.system
        y = np.concatenate([theta, u, P.ravel()])
        speed = float(sys.speed(u))
        par = np.concatenate([[n], sys.minv, sys.masses,
                              [speed, float(self.project), self.cap_fraction], np.zeros(3 * n),
                              sys.weights, [sys.level], sys.weights * np.sin(theta),
                              sys.weights * np.cos(theta), np.zeros(5 * n),
                              np.full(2 * n, np.nan)])
        ipar = np.array([n, P.shape[0]], dtype=np.int64)
        return y, par, ipar
