"""The peers of the Lyapunov benchmark, on the task of `charts.runs.benchmarks.performance`:
N = 5, equal masses, unit speed, leading 3 exponents from one fixed state.

* JiTCODE (optional, ``pip install 'charts[bench]'``): ``jitcode_lyap`` of eq (8) written in
  SymEngine, ``simplify=False``, dopri5 at rtol 1e-8, atol 1e-10, log-norms read every time
  unit (its own QR).
* SciPy: ``solve_ivp`` DOP853 (same tolerances) of eqs (8) + (17) in NumPy, QR every time unit.

`trajectory_errors` compares the integration error of charts' RK4 with JiTCODE's dopri5.
Each ``*_run`` returns (wall seconds, exponents, CPU seconds).
"""
from __future__ import annotations

import time

import numpy as np

from ...geometry.system import RotorSystem
from ...solvers.tangent import TangentFlow

__all__ = ["N", "K", "SEED", "TRANSIENT", "fixed_state", "jitcode_setup", "jitcode_run",
           "scipy_run", "trajectory_errors"]

N = 5
K = 3
SEED = 1
TRANSIENT = 50.0


def fixed_state():
    """(θ, u) of the task: ``RotorSystem(5).random_state(seed=1)`` (unit speed)."""
    return RotorSystem(N).random_state(seed=SEED)


# ----------------------------------------------------------------------------- JiTCODE
def jitcode_setup():
    """(code generation + compilation seconds, integrator) or None if JiTCODE is missing."""
    try:
        import symengine
        from jitcode import jitcode_lyap, y
    except ImportError:
        return None
    t0 = time.perf_counter()
    theta = [y(i) for i in range(N)]
    vel = [y(N + i) for i in range(N)]
    A = sum(vel[j] ** 2 * symengine.cos(theta[j]) for j in range(N))
    B = sum(symengine.sin(theta[j]) ** 2 for j in range(N))
    f = vel + [-A / B * symengine.sin(theta[i]) for i in range(N)]
    ode = jitcode_lyap(f, n_lyap=K, simplify=False, verbose=False)
    ode.compile_C(verbose=False)
    t_gen = time.perf_counter() - t0
    ode.set_integrator("dopri5", rtol=1e-8, atol=1e-10)
    return t_gen, ode


def jitcode_run(ode, t_final):
    """The task with JiTCODE: transient, then ``t_final`` time units averaged."""
    th, u = fixed_state()
    ode.set_initial_value(np.concatenate([th, u]), 0.0)
    t1, c1 = time.perf_counter(), time.process_time()
    sums = np.zeros(K)
    for t in np.arange(1.0, TRANSIENT + t_final + 0.5):
        _, lyaps, _ = ode.integrate(t)
        if t > TRANSIENT:
            sums += lyaps
    return time.perf_counter() - t1, sums / t_final, time.process_time() - c1


def _jitcode_state(ode, t):
    th, u = fixed_state()
    ode.set_initial_value(np.concatenate([th, u]), 0.0)
    for s in np.arange(1.0, t + 0.5):
        state, _, _ = ode.integrate(s)
    return np.asarray(state)[: 2 * N]


# ----------------------------------------------------------------------------- SciPy
def _rhs8(t, y):
    s, c, v = np.sin(y[:N]), np.cos(y[:N]), y[N:]
    return np.concatenate([v, -np.sum(v * v * c) / np.sum(s * s) * s])


def _rhs8_17(t, z):
    """Eq (8) for y = z[:2N] and eq (17) for the K tangent vectors z[2N:] (equal masses)."""
    y, X = z[:2 * N], z[2 * N:].reshape(K, 2 * N)
    s, c = np.sin(y[:N]), np.cos(y[:N])
    v = y[N:]
    A, B = np.sum(v * v * c), np.sum(s * s)
    lam = A / B
    dA = 2 * (X[:, N:] * v * c).sum(1) - (X[:, :N] * v * v * s).sum(1)
    dB = 2 * (X[:, :N] * s * c).sum(1)
    dlam = (dA - lam * dB) / B
    dX = np.concatenate([X[:, N:], -(dlam[:, None] * s + lam * c * X[:, :N])], axis=1)
    return np.concatenate([v, -lam * s, dX.ravel()])


def scipy_run(t_final):
    """The task with ``solve_ivp`` DOP853 and NumPy QR every time unit."""
    from scipy.integrate import solve_ivp

    th, u = fixed_state()
    X, _ = np.linalg.qr(np.random.default_rng(0).normal(size=(2 * N, K)))
    z = np.concatenate([th, u, X.T.ravel()])
    sums = np.zeros(K)
    t0, c0 = time.perf_counter(), time.process_time()
    for t in np.arange(0.0, TRANSIENT + t_final - 0.5):
        z = solve_ivp(_rhs8_17, (t, t + 1.0), z, method="DOP853", rtol=1e-8, atol=1e-10).y[:, -1]
        Q, R = np.linalg.qr(z[2 * N:].reshape(K, 2 * N).T)
        if t + 1.0 > TRANSIENT:
            sums += np.log(np.abs(np.diag(R)))
        z[2 * N:] = Q.T.ravel()
    return time.perf_counter() - t0, sums / t_final, time.process_time() - c0


# ----------------------------------------------------------------------------- accuracy
def trajectory_errors(ode, t=20.0):
    """Largest error of (θ, u) at time ``t`` from the fixed state, against SciPy DOP853 at
    rtol = atol = 1e-13: charts' tangent kernel (RK4, dt = 0.01, state projected every time
    unit, as in the Lyapunov run) and, if ``ode`` is given, JiTCODE's dopri5."""
    from scipy.integrate import solve_ivp

    th, u = fixed_state()
    ref = solve_ivp(_rhs8, (0.0, t), np.concatenate([th, u]), method="DOP853", rtol=1e-13,
                    atol=1e-13).y[:, -1]
    dt = 0.01
    flow = TangentFlow(RotorSystem(N), th, u, 0, dt=dt, project_every=round(1.0 / dt))
    flow.advance(round(t / dt))
    errs = {"charts RK4 dt=0.01": np.abs(flow.y - ref).max()}
    if ode is not None:
        errs["JiTCODE dopri5 1e-8/1e-10"] = np.abs(_jitcode_state(ode, t) - ref).max()
    return errs
