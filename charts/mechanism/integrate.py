"""Geodesic flows of a Mechanism, two ways, for cross-checks: the ambient constrained
equations (``Mechanism.acceleration``) with DOP853 or RK4 and a projection back onto the
constraint and its tangent space at every sample; and the geodesic equation of the induced
metric in charts (RK4), switching to the best conditioned chart (``Mechanism.best_chart``)
after every step."""
from __future__ import annotations

import numpy as np
from scipy.integrate import solve_ivp

from ..geometry.checks import number
from ..solvers.rk import RK4_NODES, rk4_combine, rk4_point
from .model import MechanismError

__all__ = ["integrate_ambient", "integrate_chart"]


def _times(t_final, samples):
    t_final = float(t_final)
    if not (np.isfinite(t_final) and t_final > 0):
        raise MechanismError(f"t_final must be positive and finite, got {t_final}")
    if int(samples) < 1:
        raise MechanismError(f"samples must be >= 1, got {samples}")
    return np.linspace(0.0, t_final, int(samples) + 1)


def _positive(name, x) -> float:
    """``x`` as a finite float > 0; MechanismError naming ``name`` otherwise (a step dt ≤ 0
    was taken as one step per sample, and NaN failed deep inside)."""
    try:
        x = number(name, x)
    except ValueError as exc:
        raise MechanismError(str(exc)) from None
    if not x > 0:
        raise MechanismError(f"{name} must be positive, got {x!r}")
    return x


def _rk4(f, y, h):
    """One classical RK4 step of y' = f(y), y of shape (n,): the one tableau of
    ``charts.solvers.rk`` (`RK4_NODES`, `rk4_point`, `rk4_combine`) on the rates of the NumPy
    ``f``."""
    n = y.size
    K = np.empty((4, n))                            # the stages' rates, flat in Kf
    Kf, point, out = K.reshape(-1), np.empty(n), np.empty(n)
    K[0] = f(y)
    for st in (1, 2, 3):
        rk4_point(y, Kf, (st - 1) * n, RK4_NODES[st] * h, n, point)
        K[st] = f(point)
    rk4_combine(y, Kf, h, n, out)
    return out


def integrate_ambient(mech, q0, v0, t_final, *, samples=100, method="dop853", dt=0.01,
                      rtol=1e-11, atol=1e-12, project=True):
    """(t, q, v) at ``samples + 1`` equally spaced times of the ambient flow from (q0, v0):
    DOP853 (``rtol``, ``atol``) or RK4 (step ``dt``) between samples; with ``project`` the
    state is projected onto F = 0 and ker J at every sample (no energy rescaling)."""
    q0 = mech.check_point(q0)
    v0 = mech.check_tangent(q0, v0, "v0")
    t = _times(t_final, samples)
    if method == "rk4":
        dt = _positive("dt", dt)
    elif method == "dop853":
        rtol, atol = _positive("rtol", rtol), _positive("atol", atol)
    n = mech.n
    Y = np.empty((t.size, 2 * n))
    Y[0] = np.concatenate([q0, v0])
    f = lambda y: mech.rhs(0.0, y)
    for i in range(1, t.size):
        y = Y[i - 1]
        if method == "dop853":
            sol = solve_ivp(mech.rhs, (t[i - 1], t[i]), y, method="DOP853", rtol=rtol, atol=atol)
            if not sol.success:
                raise MechanismError(f"DOP853 failed: {sol.message}")
            y = sol.y[:, -1]
        elif method == "rk4":
            steps = max(1, int(np.ceil((t[i] - t[i - 1]) / dt)))
            h = (t[i] - t[i - 1]) / steps
            for _ in range(steps):
                y = _rk4(f, y, h)
        else:
            raise MechanismError(f"method must be 'dop853' or 'rk4', got {method!r}")
        if project:
            q = mech.project_point(y[:n])
            y = np.concatenate([q, mech.project_velocity(q, y[n:])])
        Y[i] = y
    return t, Y[:, :n], Y[:, n:]


def integrate_chart(mech, q0, v0, t_final, *, samples=100, dt=0.01):
    """(t, q, v, charts) at ``samples + 1`` equally spaced times of the geodesic equation
    s̈ᵃ = −Γᵃ_bc ṡᵇ ṡᶜ of the induced metric, RK4 of step ≤ ``dt``, in the chart chosen by
    ``best_chart`` (re-chosen after every step; the dependent coordinates by Newton from the
    previous point, the local branch).  ``charts``: the chart in use at each sample."""
    q = mech.check_point(q0).copy()
    v = mech.check_tangent(q, v0, "v0").copy()
    t = _times(t_final, samples)
    dt = _positive("dt", dt)
    d = mech.dim
    Q = np.empty((t.size, mech.n))
    V = np.empty((t.size, mech.n))
    Q[0], V[0] = q, v
    chart = mech._chart_of(q, None)        # the tuple form (a RotorSystem: int)
    used = [chart]
    for i in range(1, t.size):
        steps = max(1, int(np.ceil((t[i] - t[i - 1]) / dt)))
        h = (t[i] - t[i - 1]) / steps
        for _ in range(steps):
            ind = list(chart)
            ref = q

            def f(z):
                p = mech.lift(z[:d], chart, ref)
                G = mech._gamma(p, chart)
                return np.concatenate([z[d:], -np.einsum("abc,b,c->a", G, z[d:], z[d:])])
            z = _rk4(f, np.concatenate([q[ind], v[ind]]), h)
            q = mech.lift(z[:d], chart, ref)
            v = mech.embedding_jets(q, chart)[0] @ z[d:]
            chart = mech._chart_of(q, None)
        Q[i], V[i] = q, v
        used.append(chart)
    return t, Q, V, used
