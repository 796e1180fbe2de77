"""Sectional curvatures along trajectories, section 3 (eqs 19-22), two routes.

Route (a), the paper's numerical algorithm.  At a sample point of the trajectory the
frame p⁽⁰⁾ = u/|u|, p⁽¹⁾…p⁽ᴺ⁻²⁾ is built from the θ-parts of the N−2 leading Lyapunov
vectors (kept in the constraint-preserving subspace, see `charts.lyapunov`): the
component along the flow is removed from each vector by subtracting a multiple of the
flow-direction perturbation (u, u̇) (itself a solution of eq 17, so the result is still a
Jacobi field), and the θ-parts are M-orthonormalised (metric Σ mᵢ aᵢ bᵢ).  One RK4 step
of ±Δt then moves the trajectory, the Jacobi fields J⁽ʲ⁾ (eq 17) and the frame (parallel
transport, eq 19) together, and the coefficients c_i⁽ʲ⁾ = ⟨J⁽ʲ⁾, p⁽ⁱ⁾⟩ give, from the
Jacobi equation c̈ + K c = 0 (eq 20 with the curvature operator of J'' + R(J, u)u = 0),

    K_ij = −[c_i⁽ʲ⁾(t−Δt) − 2δ_ij + c_i⁽ʲ⁾(t+Δt)] / (Δt² |u|²).

Eq (21) as printed lacks the minus sign: with it the N = 3 result matches eq (22),
which is negative.  Dividing by |u|² makes K independent of the speed.

Route (b), exact: K_ij = ⟨R(p⁽ʲ⁾, p⁽⁰⁾)p⁽⁰⁾, p⁽ⁱ⁾⟩ = R_abcd p_i^a p_0^b p_j^c p_0^d from the
generated Riemann tensor (`charts.chartfuncs.compiled(n).riemann`) in the best-
conditioned chart, evaluated at the same points and frames.

For N = 3 with equal masses, eq (22) gives the Gaussian curvature in closed form
(`gaussian_curvature_eq22`).
"""
from __future__ import annotations

from dataclasses import dataclass
from math import cos, sin, sqrt

import numpy as np
from numba import njit

from ..flows.ambient import project_state, project_tangent_sc, transport_rhs
from ..geometry.kernels import compiled
from .lyapunov import (_initial_state, _initial_vectors, _lyap_kernel, _rk4_step, _stage,
                       inner_weights, orthonormalize)

__all__ = ["CurvatureResult", "curvature_along_trajectory", "exact_curvature_matrix",
           "gaussian_curvature_eq22"]


def gaussian_curvature_eq22(theta):
    """Eq (22): Gaussian curvature of the N = 3 surface (equal masses), theta (..., 3)."""
    theta = np.asarray(theta, dtype=float)
    return -(np.cos(theta) ** 2).sum(-1) / (2.0 * ((np.sin(theta) ** 2).sum(-1)) ** 2)


@njit(cache=True)
def _rk4_frame_step(y, X, P, minv, h):
    """One RK4 step of eq (8), eq (17) for rows of X and eq (19) for rows of P, in place."""
    n = y.size // 2
    d = 2 * n
    k = X.shape[0]
    kp = P.shape[0]
    s = np.empty(n)
    c = np.empty(n)
    ky = np.empty((4, d))
    kX = np.empty((4, k, d))
    kP = np.empty((4, kp, n))
    yt = y.copy()
    Xt = X.copy()
    Pt = P.copy()
    for st in range(4):
        if st > 0:
            a = 0.5 * h if st < 3 else h
            for i in range(d):
                yt[i] = y[i] + a * ky[st - 1, i]
            for r in range(k):
                for i in range(d):
                    Xt[r, i] = X[r, i] + a * kX[st - 1, r, i]
            for r in range(kp):
                for i in range(n):
                    Pt[r, i] = P[r, i] + a * kP[st - 1, r, i]
        _stage(yt, Xt, minv, s, c, ky[st], kX[st])
        transport_rhs(yt, Pt, minv, s, c, kP[st])
    h6 = h / 6.0
    for i in range(d):
        y[i] += h6 * (ky[0, i] + 2.0 * ky[1, i] + 2.0 * ky[2, i] + ky[3, i])
    for r in range(k):
        for i in range(d):
            X[r, i] += h6 * (kX[0, r, i] + 2.0 * kX[1, r, i] + 2.0 * kX[2, r, i] + kX[3, r, i])
    for r in range(kp):
        for i in range(n):
            P[r, i] += h6 * (kP[0, r, i] + 2.0 * kP[1, r, i] + 2.0 * kP[2, r, i] + kP[3, r, i])


@njit(cache=True)
def _frame(y, X, minv, m, Xj, P):
    """Jacobi fields Xj, shape (N−2, 2N), and frame P, shape (N−1, N), at y from the
    Lyapunov vectors X (route a, see module docstring)."""
    n = y.size // 2
    k = X.shape[0]
    s = np.empty(n)
    c = np.empty(n)
    f = np.empty(2 * n)
    dummy = np.empty((0, 2 * n))
    _stage(y, dummy, minv, s, c, f, dummy)
    uu = 0.0
    for i in range(n):
        uu += m[i] * y[n + i] * y[n + i]
    for r in range(k):
        a = 0.0
        for i in range(n):
            a += m[i] * X[r, i] * y[n + i]
        a /= uu
        for i in range(2 * n):
            Xj[r, i] = X[r, i] - a * f[i]
    w = np.zeros(2 * n)
    for i in range(n):
        w[i] = m[i]
    orthonormalize(Xj, w, np.zeros(k))
    un = sqrt(uu)
    for i in range(n):
        P[0, i] = y[n + i] / un
    for r in range(k):
        for i in range(n):
            P[r + 1, i] = Xj[r, i]
    return uu


@njit(cache=True)
def _curvature_kernel(y, X, minv, m, speed, dt, sample_every, w, project_every, Ka, Ys, Ps):
    """Advance (y, X) with re-orthonormalisation and, every ``sample_every`` steps, store
    y in Ys[s], the frame in Ps[s] and the route-(a) matrix K in Ka[s]."""
    n = y.size // 2
    k = X.shape[0]
    s = np.empty(n)
    c = np.empty(n)
    ky = np.empty((4, 2 * n))
    kX = np.empty((4, k, 2 * n))
    yt = np.empty(2 * n)
    Xt = np.empty((k, 2 * n))
    logs = np.zeros(k)
    Xj = np.empty((k, 2 * n))
    P = np.empty((k + 1, n))
    cs = np.zeros((k, k))
    step = 0
    for smp in range(Ka.shape[0]):
        for _ in range(sample_every):
            _rk4_step(y, X, minv, dt, s, c, ky, kX, yt, Xt)
            step += 1
            if step % project_every == 0:
                project_state(y, m, speed)
            for j in range(n):
                s[j] = sin(y[j])
                c[j] = cos(y[j])
            project_tangent_sc(y, X, minv, s, c)
            orthonormalize(X, w, logs)
        uu = _frame(y, X, minv, m, Xj, P)
        Ys[smp] = y
        Ps[smp] = P
        for i in range(k):
            for j in range(k):
                cs[i, j] = 0.0
        for sign in (1.0, -1.0):
            y2 = y.copy()
            X2 = Xj.copy()
            P2 = P.copy()
            _rk4_frame_step(y2, X2, P2, minv, sign * dt)
            for i in range(k):
                for j in range(k):
                    acc = 0.0
                    for q in range(n):
                        acc += m[q] * X2[j, q] * P2[i + 1, q]
                    cs[i, j] += acc
        for i in range(k):
            for j in range(k):
                Ka[smp, i, j] = -(cs[i, j] - (2.0 if i == j else 0.0)) / (dt * dt * uu)


def exact_curvature_matrix(system, theta, P):
    """Route (b): K_ij = ⟨R(p_j, p_0)p_0, p_i⟩ for the M-orthonormal tangent frame P,
    shape (N−1, N) (row 0 = p_0), from the generated Riemann tensor in the best chart.
    Returns shape (N−2, N−2)."""
    fn = compiled(system.n).riemann
    k = system.best_chart(theta)
    idx = [i for i in range(system.n) if i != k]
    q = np.ascontiguousarray(theta[idx])
    mm = np.concatenate([system.masses[idx], system.masses[k:k + 1]])
    R = fn(q, mm, np.empty((system.dim,) * 4))
    Q = P[:, idx]
    # R_abcd p_i^a p0^b p_j^c p0^d
    Rp = np.einsum("abcd,b,d->ac", R, Q[0], Q[0])
    return Q[1:] @ Rp @ Q[1:].T


@dataclass
class CurvatureResult:
    """Curvature along a trajectory.

    t : (S,) sample times; theta, u : (S, N) states; frames : (S, N−1, N) the
    M-orthonormal frame (row 0 the unit velocity, rows 1.. from the Lyapunov vectors);
    K_numeric : (S, N−2, N−2) route (a); K_exact : (S, N−2, N−2) route (b) or None.
    """
    t: np.ndarray
    theta: np.ndarray
    u: np.ndarray
    frames: np.ndarray
    K_numeric: np.ndarray
    K_exact: np.ndarray | None
    params: dict

    def diagonal(self, route="numeric"):
        """K_ii, shape (S, N−2), of route 'numeric' (a) or 'exact' (b)."""
        K = self.K_numeric if route == "numeric" else self.K_exact
        return np.diagonal(K, axis1=1, axis2=2)

    def fraction_positive(self, route="numeric"):
        """Fraction of positive values of each K_ii, shape (N−2,)."""
        return (self.diagonal(route) > 0).mean(axis=0)


def curvature_along_trajectory(system, theta0, u0, t_final, *, dt=0.01, sample_every=10,
                               t_transient=50.0, exact=True, project_every=100, seed=0,
                               progress=False):
    """Sectional curvatures K_ij along the trajectory from (theta0, u0), routes (a) and (b).

    Parameters
    ----------
    system : RotorSystem
    theta0, u0 : ndarray, shape (N,)
    t_final : float
        Sampled time after the transient.
    dt : float
        RK4 step of the trajectory, the Lyapunov vectors and the ±Δt frame steps.
    sample_every : int
        Steps between sample points.
    t_transient : float
        Time for the Lyapunov vectors to converge before sampling.
    exact : bool
        Also evaluate route (b) at the same points and frames.

    Returns
    -------
    CurvatureResult
    """
    n = system.n
    if n < 3:
        raise ValueError("curvature needs N >= 3")
    y, speed = _initial_state(system, theta0, u0)
    k = n - 2
    w = inner_weights(system, "theta")
    X = _initial_vectors(system, y, k, seed, True, w)
    if t_transient > 0:
        _lyap_kernel(y, X, system.minv, system.masses, speed, float(dt),
                     int(round(t_transient / dt)), 1, w, True, int(project_every), 0,
                     np.zeros(k), np.empty((0, k)))
    S = int(round(t_final / dt)) // int(sample_every)
    if S < 1:
        raise ValueError(f"t_final={t_final} is shorter than one sample interval; increase it")
    Ka = np.empty((S, k, k))
    Ys = np.empty((S, 2 * n))
    Ps = np.empty((S, k + 1, n))
    chunks = np.array_split(np.arange(S), min(S, 50))
    bar = None
    if progress:
        from tqdm.auto import tqdm
        bar = tqdm(total=S, desc=f"curvature N={n}", leave=False)
    for ch in chunks:
        a, b = ch[0], ch[-1] + 1
        Kc = np.empty((b - a, k, k))
        Yc = np.empty((b - a, 2 * n))
        Pc = np.empty((b - a, k + 1, n))
        _curvature_kernel(y, X, system.minv, system.masses, speed, float(dt), int(sample_every),
                          w, int(project_every), Kc, Yc, Pc)
        Ka[a:b], Ys[a:b], Ps[a:b] = Kc, Yc, Pc
        if bar is not None:
            bar.update(b - a)
    if bar is not None:
        bar.close()
    Kb = None
    if exact:
        Kb = np.array([exact_curvature_matrix(system, Ys[i, :n], Ps[i]) for i in range(S)])
    t = (np.arange(1, S + 1) * sample_every) * dt
    params = dict(n=n, masses=system.masses.tolist(), dt=dt, sample_every=sample_every,
                  t_transient=t_transient, speed=speed, t_final=float(t[-1]))
    return CurvatureResult(t, Ys[:, :n], Ys[:, n:], Ps, Ka, Kb, params)
