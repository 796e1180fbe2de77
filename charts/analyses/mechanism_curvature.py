"""Sectional curvatures along a trajectory of any Mechanism, section 3 (eqs 19-21), two
routes at the same points and frames, as ``charts.analyses.curvature`` for the rotors.

The frame.  At each sample (q, v) of the trajectory, p⁽⁰⁾ = v/|v| and p⁽¹⁾ … p⁽ᵈ⁻¹⁾ from the
position parts of the d − 1 leading Lyapunov vectors (the mechanism's compiled tangent flow,
``charts.mechanism.tangent_flow``, kinetic product on δq): the component along the flow is
removed from each vector by subtracting a multiple of the flow-direction perturbation (v, q̈)
(itself a solution of the linearised flow, so the result is still a Jacobi field) and the
position parts are M-orthonormalised.  All vectors are ambient (shape (n,)), tangent to the
configuration manifold.

Route (a), the paper's numerical algorithm: the trajectory, the Jacobi fields (the linearised
flow, ``Mechanism.tangent_acceleration``) and the frame (parallel transport, eq (19) in
ambient form: ṗ = A(v, p), the symmetric bilinear form whose diagonal is the geodesic
acceleration A(v, v) = ``Mechanism.acceleration``, so that ṗ + Γ(v, p) is normal and p stays
tangent) move together by ±Δt (DOP853 at rtol 1e-12, so that the only error left is the
central difference's O(Δt²)); the coefficients c_i⁽ʲ⁾ = ⟨J⁽ʲ⁾, p⁽ⁱ⁾⟩ give, by the Jacobi
equation, K_ij = −[c_i⁽ʲ⁾(t−Δt) − 2δ_ij + c_i⁽ʲ⁾(t+Δt)] / (Δt² |v|²).

Route (b): K_ij = R_abcd p_i^a p_0^b p_j^c p_0^d from the Riemann tensor of the induced metric
in the best-conditioned chart (``Mechanism.riemann``, the intrinsic route).  For a constant
metric the Gauss equation of the embedding (``Mechanism.gauss_equation_curvature``) is a
third, chart-free route to the same numbers (tests/test_mechanism_analyses.py).

The result is the rotors' ``CurvatureResult``: its fields ``theta`` and ``u`` hold the
ambient coordinates q and velocities v of the samples (shape (S, n)), ``frames`` the frames
(S, d, n), ``K_numeric`` and ``K_exact`` the two routes (S, d − 1, d − 1); saved, they are
``q``, ``v`` and ``frames`` along the dimension ``coordinate`` named by the mechanism's
coordinates (``params["coordinates"]``), not the rotors' ``rotor``.
"""
from __future__ import annotations

import numpy as np
from scipy.integrate import solve_ivp

from ..mechanism.errors import MechanismError
from ..mechanism.tangent_flow import MechanismTangentFlow
from ..solvers.tangent import reorth_steps
from .arguments import (Documented, flag, samples_of,
                        steps_of)
from .curvature import CurvatureResult
from .mechanism_lyapunov import closing_checks, opening_checks

__all__ = ["mechanism_curvature", "jacobi_frame", "jacobi_curvature", "riemann_curvature"]

#: Relative tolerance of the ±Δt moves of route (a): c⁽ʲ⁾ to ~1e-12, so that rounding
#: contributes ~1e-12/Δt² = 1e-8 at Δt = 0.01, below the O(Δt²) ~ 1e-5 of the difference.
MOVE_RTOL = 1e-12


def jacobi_frame(mech, q, v, X):
    """(Jacobi fields (k, 2n), frame (k + 1, n)) at (q, v) from the Lyapunov vectors X
    (k, 2n) (module docstring): the flow component removed, the position parts
    M-orthonormalised (Gram–Schmidt, by the Cholesky factor of their Gram matrix)."""
    n = mech.n
    M = mech.mass_matrix(q)
    flow = np.concatenate([v, mech.acceleration(q, v)])
    uu = v @ M @ v
    J = X - np.outer(X[:, :n] @ M @ v / uu, flow)
    G = J[:, :n] @ M @ J[:, :n].T
    J = np.linalg.solve(np.linalg.cholesky(G), J)
    return J, np.vstack([v / np.sqrt(uu), J[:, :n]])


def _transport(mech, q, v, p):
    """ṗ = A(v, p) of parallel transport along the geodesic (module docstring): the
    polarisation of the quadratic A(v, v) = ``mech.acceleration(q, v)``."""
    return 0.25 * (mech.acceleration(q, v + p) - mech.acceleration(q, v - p))


def jacobi_curvature(mech, q, v, J, P, h):
    """Route (a): K (k, k) from the Jacobi fields J (k, 2n) and the frame P (k + 1, n) at
    (q, v), moved by ±h together with the trajectory."""
    n, k = mech.n, J.shape[0]

    def rate(_, z):
        q_, v_ = z[:n], z[n:2 * n]
        Jz = z[2 * n:2 * n + 2 * k * n].reshape(k, 2 * n)
        Pz = z[2 * n + 2 * k * n:].reshape(k, n)
        out = [v_, mech.acceleration(q_, v_)]
        for dq, dv in zip(Jz[:, :n], Jz[:, n:]):
            out += [dv, mech.tangent_acceleration(q_, v_, dq, dv)]
        out += [_transport(mech, q_, v_, p) for p in Pz]
        return np.concatenate(out)
    z0 = np.concatenate([q, v, J.ravel(), P[1:].ravel()])
    c = np.zeros((k, k))
    for sign in (1.0, -1.0):
        sol = solve_ivp(rate, (0.0, sign * h), z0, method="DOP853", rtol=MOVE_RTOL,
                        atol=MOVE_RTOL)
        if not sol.success:
            raise MechanismError(f"{mech.name}: the ±dt move of the curvature frame failed "
                                 f"({sol.message})")
        z = sol.y[:, -1]
        Jz = z[2 * n:2 * n + 2 * k * n].reshape(k, 2 * n)
        Pz = z[2 * n + 2 * k * n:].reshape(k, n)
        c += Pz @ mech.mass_matrix(z[:n]) @ Jz[:, :n].T        # c[i, j] = ⟨J⁽ʲ⁾, p⁽ⁱ⁾⟩
    return -(c - 2.0 * np.eye(k)) / (h * h * (v @ mech.mass_matrix(q) @ v))


def riemann_curvature(mech, q, P):
    """Route (b): K_ij = R_abcd p_i^a p_0^b p_j^c p_0^d (i, j ≥ 1) of the M-orthonormal frame
    P (k + 1, n) at q, the Riemann tensor in the best-conditioned chart."""
    chart = mech._chart_of(q, None)           # best_chart's, as a tuple (a RotorSystem's: k)
    x = P[:, list(chart)]
    return np.einsum("abcd,ia,b,jc,d->ij", mech.riemann(q, chart), x[1:], x[0], x[1:], x[0])


def mechanism_curvature(mech, q0, v0, t_final, *, dt=0.01, sample_every=Documented(0.1),
                        t_transient=Documented(50.0), exact=True,
                        project_every=Documented(1.0), seed=0) -> CurvatureResult:
    """Sectional curvatures K_ij along ``mech``'s trajectory from (q0, v0), routes (a) and
    (b) (module docstring), as ``charts.curvature_along_trajectory`` for the rotors.

    Parameters
    ----------
    mech, q0, v0 : charts.Mechanism, ndarray (n,), ndarray (n,)
        The mechanism and the state, as ``mechanism_angles`` takes them.
    t_final : float
        Sampled time after the transient (a multiple of ``sample_every``).
    dt : float
        RK4 step of the trajectory and the Lyapunov vectors, and Δt of route (a).
    sample_every : float
        Time between samples (default 0.1, the nearest whole number of steps at other dt
        that divides t_final: README, "Conventions").
    t_transient : float or "auto"
        Time for the Lyapunov vectors to converge before sampling (default 50, the nearest
        whole number of steps at other dt).  "auto": the pilot of
        ``charts.analyses.mechanism_lyapunov.auto_transient`` (this dt, project_every and
        seed), recorded in ``params`` (``transient_rule``); "scaled" is refused.
    exact : bool
        Also evaluate route (b).
    project_every : float or None
        Time between projections onto TC (default 1.0; None: never).
    seed : int
        Seed of the random initial tangent vectors.

    Returns
    -------
    CurvatureResult
        ``theta`` and ``u`` hold q and v (module docstring); ``t`` counts from the end of
        the transient, as the rotors'.

    Raises
    ------
    MechanismError, ValueError
        Naming the argument (``opening_checks``, ``mechanism_state``, the sampling grid).
    """
    rule, dt = opening_checks(mech, t_transient, dt)
    total = steps_of("t_final", t_final, dt)
    sample = steps_of("sample_every", sample_every, dt, divides=total)
    S = samples_of(total, sample, t_final, sample_every)
    transient = 0 if rule else steps_of("t_transient", t_transient, dt, allow_zero=True)
    exact = flag("exact", exact)
    project, seed, q0, v0, t_transient, rule = closing_checks(
        mech, q0, v0, rule, t_transient, dt, project_every, seed)
    if rule:
        transient = steps_of("t_transient", t_transient, dt, allow_zero=True)
    d, n = mech.dim, mech.n
    k = d - 1
    flow = MechanismTangentFlow(mech, q0, v0, k, dt=dt, project=project, inner="theta",
                                reorth=reorth_steps(dt, sample, transient), seed=seed)
    flow.advance(transient)
    Ka, Kb = np.empty((S, k, k)), np.empty((S, k, k)) if exact else None
    Ys, Ps = np.empty((S, 2 * n)), np.empty((S, d, n))
    for s in range(S):
        flow.advance(sample)
        # the sample on TC (between the flow's projections it drifts off F = 0 by up to
        # ~1e-8: the points where the curvature is evaluated are the manifold's; the
        # trajectory itself is left as it runs)
        q = mech.project_point(flow.y[:n])
        v = mech.project_velocity(q, flow.y[n:])
        X = [np.concatenate(mech.project_phase_tangent(q, v, *np.split(x, 2))) for x in flow.X]
        Ys[s] = np.concatenate([q, v])
        J, Ps[s] = jacobi_frame(mech, q, v, np.array(X))
        Ka[s] = jacobi_curvature(mech, q, v, J, Ps[s], dt)
        if exact:
            Kb[s] = riemann_curvature(mech, q, Ps[s])
    t = np.arange(1, S + 1) * sample * dt
    params = dict(mechanism=mech.name, parameters=mech.parameter_values,
                  coordinates=[c.name for c in mech.q], periodic=list(mech.periodic), dt=dt,
                  sample_every=sample * dt, t_transient=transient * dt,
                  project_every=project * dt or None,
                  speed=float(np.sqrt(2 * mech.energy(q0, v0))), t_final=float(t[-1]),
                  vectors_seed=seed, state_seed="given", exact=exact, q0=q0.tolist(),
                  v0=v0.tolist())
    if rule:
        params["transient_rule"] = rule
    return CurvatureResult(t, Ys[:, :n], Ys[:, n:], Ps, Ka, Kb, params)
