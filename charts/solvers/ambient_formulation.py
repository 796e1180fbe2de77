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
dt into sub-steps (``status.next_substep``; through Σ sin²θ ≈ 2e-6: 1.1e-7 against 1.4e-6
from DOP853 at rtol 1e-13, docs/integrators.md).  DOP853 evaluates libm at every stage (:func:`_rhs`).

Parameters: ``par``, the fields of `PAR` (``charts.jit.packed``): N, 1/m, m, the speed,
the project flag, the cap fraction, the point's work (a sin θ, a cos θ, a sin θ/m of the point
being evaluated), the weights a, the level c, and the step's: the start's a sin θ, a cos θ
(s₀, c₀: carried), its work and the state last projected, so that no hook allocates;
``ipar = (N, k)``.  The constraint is Σ a cos θ = c.
"""
from __future__ import annotations

from functools import cache

import numpy as np
from ..jit import njit

from ..flows.ambient import multiplier, sincos, state_rate, transport_rate
from ..geometry.projection import invariants_of, project_state, project_velocity
from .loop import (CAP_SIG, INV_SIG, OUT_SIG, POST_CHANGED, POST_OK, POST_SIG, STEP_SIG,
                   Formulation)
from .rk import NO_REFCOUNT, RHS_SIG
from .status import SINGULAR_S, singular_floor, step_cap, sum_squares
from ..jit.packed import layout, pack, value, view
from .tangent import stacked_rk4_step

#: Landing steps within this relative distance of dt are the grid's step dt (the loop's time
#: is a sum of steps, so the last step to an output time on the grid is dt up to rounding).
LANDING_RTOL = 1e-9

__all__ = ["AmbientFlow", "PAR"]

#: The layout of ``par`` (``charts.jit.packed.layout``: name, length a·N + b).
PAR = layout(("n", 0, 1), ("minv", 1, 0), ("masses", 1, 0), ("speed", 0, 1), ("project", 0, 1),
             ("cap", 0, 1), ("point_s", 1, 0), ("point_c", 1, 0), ("point_f", 1, 0),
             ("weights", 1, 0), ("level", 0, 1), ("s0", 1, 0), ("c0", 1, 0), ("th", 1, 0),
             ("dl", 1, 0), ("s", 1, 0), ("c", 1, 0), ("f", 1, 0), ("projected", 2, 0),
             ("health", 0, 1))
_N, _MINV, _MASSES, _SPEED, _PROJECT, _CAP = (PAR[k] for k in ("n", "minv", "masses", "speed",
                                                               "project", "cap"))
_PS, _PC, _PF, _WTS, _LEVEL = (PAR[k] for k in ("point_s", "point_c", "point_f", "weights",
                                                "level"))
_S0, _C0, _TH, _DL, _SS, _SC, _SF, _PROJECTED = (PAR[k] for k in ("s0", "c0", "th", "dl", "s",
                                                                  "c", "f", "projected"))
_HEALTH = PAR["health"]
#: ``ipar``: N and the number of transported vectors.
I_N, I_VECTORS = range(2)


@njit(cache=True, inline="always")
def _point(y, par, n):
    """Views of the point's work: (1/m, a sin θ, a cos θ, a sin θ/m) with sin/cos of y filled in."""
    minv = view(par, n, _MINV)
    s = view(par, n, _PS)
    c = view(par, n, _PC)
    f = view(par, n, _PF)
    sincos(y, 0, n, view(par, n, _WTS), s, c)
    for j in range(n):
        f[j] = s[j] * minv[j]
    return minv, s, c, f


def _rhs(y, par, dy):
    """Eq (8) and eq (19); returns the health S = Σ a² sin²θ (`_health`; 0 at a singular
    point: dy is then 0)."""
    n = int(value(par, 0, _N))   # (N comes first: its offset is 0)
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
    return _health(S, c, n, par)


@njit(cache=True, inline="always")
def _health(S, c, n, par):
    """The loop's health of a point with S = Σ (a sin θ)² and weighted cosines c: S, scaled
    by SINGULAR_S / `singular_floor` where the drift from the constraint raises the floor, so
    that the loop's one test (health < SINGULAR_S) reads S < singular_floor
    (``charts.solvers.status``: a drifted trajectory stops at a cone point as the chart
    route does)."""
    floor = singular_floor(c, view(par, n, _WTS), n, value(par, n, _LEVEL))
    return S if floor == SINGULAR_S else S * (SINGULAR_S / floor)


@njit(cache=True, inline="always")
def transport_vectors_rate(Zt, n, minv, s, c, lam, iB, f, health, _w2, _w3, K, o, R, d):
    """Eq (19) for the R transported vectors (rows of d = N after the state's 2N) at the stage
    point Zt into K[o:] (the hook of ``charts.solvers.tangent.stacked_rk4_step``); health[0]
    keeps the smallest S = Σ (a sin θ)² of the stages (the loop's health)."""
    health[0] = min(health[0], sum_squares(s, 0, n))
    if R > 0:
        for j in range(n):
            f[j] = s[j] * minv[j]
        for r in range(R):
            oo = n + n + r * d
            transport_rate(Zt, oo, n, Zt, 0, f, c, iB, K, o + oo)


def _step(rhs, y, h, dt, par, K, ytmp, ynew):
    """The RK4 step hook: ``stacked_rk4_step`` of eqs (8) + (19) from y into ynew, s₀, c₀ in
    the step's fields advancing with it; returns the smallest S = Σ (a sin θ)² of its stages
    (rhs unused).  A landing step within rounding of dt is dt (`LANDING_RTOL`)."""
    n = int(value(par, 0, _N))   # (N comes first: its offset is 0)
    if abs(h - dt) <= LANDING_RTOL * dt:
        h = dt
    for i in range(y.size):
        ynew[i] = y[i]
    f = view(par, n, _SF)
    health = view(par, n, _HEALTH)
    health[0] = np.inf
    stacked_rk4_step(ynew, ytmp, K.reshape(K.size), view(par, n, _TH), view(par, n, _DL),
                     view(par, n, _SS), view(par, n, _SC), f, health, f, f, view(par, n, _S0),
                     view(par, n, _C0), view(par, n, _MINV), view(par, n, _WTS), h,
                     np.uint64(n), np.uint64((y.size - 2 * n) // n), np.uint64(n),
                     np.uint64(y.size), transport_vectors_rate)
    return _health(health[0], view(par, n, _C0), n, par)


def _rk4_cap(y, par, ipar):
    """RK4's step cap (``status.step_cap``) from the carried s₀ (no libm)."""
    n = ipar[I_N]
    return step_cap(sum_squares(view(par, n, _S0), 0, n), sum_squares(y, n, n),
                    value(par, n, _CAP))


def _cap(y, par, ipar):
    n = ipar[I_N]
    a = view(par, n, _WTS)
    S = 0.0
    U = 0.0
    for j in range(n):
        S += (a[j] * np.sin(y[j])) ** 2
        U += y[n + j] ** 2
    return step_cap(S, U, value(par, n, _CAP))


@njit(cache=True)
def _project(y, par, ipar):
    """Project (θ, u) onto the invariants and each p onto the tangent space, in place."""
    n = ipar[I_N]
    project_state(y[:2 * n], view(par, n, _MASSES), view(par, n, _WTS), value(par, n, _LEVEL),
                  value(par, n, _SPEED))
    minv, s, c, f = _point(y, par, n)
    for r in range(ipar[I_VECTORS]):
        project_velocity(y, (2 + r) * n, n, s, minv)


def _post(y, par, ipar, t, log):
    n = ipar[I_N]
    if value(par, n, _PROJECT) == 0.0:
        return POST_OK
    _project(y, par, ipar)
    s0, c0, ps, pc = view(par, n, _S0), view(par, n, _C0), view(par, n, _PS), view(par, n, _PC)
    for j in range(n):            # the projected point's libm sin/cos become the next s₀, c₀
        s0[j] = ps[j]
        c0[j] = pc[j]
    last = view(par, n, _PROJECTED)
    for j in range(2 * n):        # and the projected state is remembered (`_to_ambient`)
        last[j] = y[j]
    return POST_CHANGED


def _to_ambient(y, par, ipar, row):
    n = ipar[I_N]
    for i in range(y.size):
        row[i] = y[i]
    if value(par, n, _PROJECT) == 0.0:
        return 0.0
    same = True                   # the state that `_post` projected last is output as is
    last = view(par, n, _PROJECTED)
    for j in range(2 * n):
        same = same and y[j] == last[j]
    if not same:                  # samples inside a step are projected as well
        _project(row, par, ipar)
    return 0.0


def _invariants(y, par, ipar, inv):
    n = ipar[I_N]
    inv[0], inv[1], inv[2] = invariants_of(y, n, view(par, n, _MASSES), view(par, n, _WTS),
                                           value(par, n, _LEVEL))
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

    def hooks(self, method, vectors):
        rhs, cap, post, out, inv = _hooks()   # (N-generic: eq (19) for any number of vectors)
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
        par = pack(PAR, n, n=n, minv=sys.minv, masses=sys.masses, speed=speed,
                   project=float(self.project), cap=self.cap_fraction, weights=sys.weights,
                   level=sys.level, s0=sys.weights * np.sin(theta),
                   c0=sys.weights * np.cos(theta), projected=np.nan)
        ipar = np.array([n, P.shape[0]], dtype=np.int64)
        return y, par, ipar
