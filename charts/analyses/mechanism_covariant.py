"""Covariant Lyapunov vectors of any Mechanism (Ginelli et al., PRL 99, 130601 (2007)), as
``charts.analyses.covariant`` computes them for the rotors, and the hyperbolicity test of
section 4 built on them.

1. forward: the mechanism's compiled tangent flow (``charts.mechanism.tangent_flow``)
   advances the state and D = 2d vectors (all of the tangent space of TC, where its
   projections keep them: the rotors' ``restricted`` variant); at every sample (and as often
   in the transient) they are projected onto it (as the rotors' onto T_r: the basis spans all
   of it, so a drift off it would enter the contracting directions) and orthonormalised in the kinetic product on (δq, δv) (the angle test's,
   ``charts.analyses.mechanism_angles``), X = Rᵀ Q with R upper-triangular (positive
   diagonal), and Q, R and the state are stored;
2. backward: Ginelli's iteration C_{j−1} = R_j⁻¹ C_j from a random upper-triangular C
   (``covariant.ginelli_start``, ``covariant.backward_coefficients``);
3. at each sample: the CLVs v^i = Σ_q C[q, i] Q[q], the angle between E_u = span(Q[:m]) and
   E_cs = span(v^{m+1} … v^D), and between the leading unstable and stable CLVs
   (``covariant.clv_samples``, on the isometric images (√M δq, √M δv) of the vectors, so that
   the angles are those of the kinetic product).

The result is the rotors' ``CovariantResult`` (variant "restricted"; ``states`` holds (q, v),
``vectors`` the CLVs (δq, δv), unit in the kinetic product).  Everything is kept in memory
(8·(2·D·2n + D² + 2n) bytes per sample, refused beyond half the machine's memory,
``charts.solvers.tangent.check_memory``): no disk streaming.
"""
from __future__ import annotations

import numpy as np

from ..geometry.checks import option
from ..mechanism.tangent_flow import MechanismTangentFlow
from ..solvers.tangent import check_memory
from .arguments import (Documented, flag, project_steps,
                        samples_of, seed_of, steps_of)
from .covariant import CovariantResult, backward_coefficients, clv_samples, ginelli_start
from .mechanism_angles import root_metric
from .mechanism_arguments import mechanism_state, unstable_of
from .mechanism_lyapunov import opening_checks, resolve_transient

__all__ = ["mechanism_clvs", "gram_schmidt_factor"]

def gram_schmidt_factor(mech, q, X):
    """(Q, Y, R) of the vectors X (D, 2n) at q: X = Rᵀ Q with Q orthonormal in the kinetic
    product on (δq, δv) and R upper-triangular with positive diagonal (Gram–Schmidt, by a QR
    factorisation of their isometric images); Y the isometric images of Q (√M δq, √M δv),
    orthonormal in the Euclidean product."""
    n = mech.n
    L = root_metric(mech.mass_matrix(q))
    Qt, R = np.linalg.qr(np.hstack([X[:, :n] @ L, X[:, n:] @ L]).T)
    s = np.sign(np.diag(R))
    R *= s[:, None]
    return np.linalg.solve(R.T, X), (Qt * s).T, R


def mechanism_clvs(mech, q0, v0, t_final, *, variant="restricted", dt=0.01, n_unstable=None,
                   t_transient=Documented(100.0), sample_every=Documented(0.1),
                   project_every=Documented(1.0), seed=0,
                   keep_vectors=False) -> CovariantResult:
    """CLVs by Ginelli's method along ``mech``'s trajectory from (q0, v0), and the angles and
    growth rates built on them (module docstring), as ``charts.covariant_lyapunov_vectors``
    for the rotors.

    Parameters
    ----------
    mech, q0, v0
        The mechanism and its state, as ``mechanism_angles`` takes them.
    t_final : float
        Length of the analysed window (a multiple of ``sample_every``).
    variant : {"restricted"}
        The tangent space of TC (D = 2d vectors), the only variant of a mechanism.
    dt : float
        RK4 step.  A time written below must be a whole number of steps; a default left is
        the nearest whole number of steps at other dt (README, "Conventions").
    n_unstable : int, optional
        m, the dimension of E_u (default d − 1, at most d − 1).
    t_transient : float or "auto"
        Convergence time of the forward vectors and of the backward iteration.  "auto": the
        pilot of ``charts.analyses.mechanism_lyapunov.auto_transient`` (this dt,
        project_every and seed), recorded in ``params`` (``transient_rule``); "scaled" is
        refused.
    sample_every : float
        Time between samples (re-orthonormalisations).
    project_every : float or None
        Time between projections onto TC (None: never).
    seed : int
        Seed of the random initial vectors and of Ginelli's random C.
    keep_vectors : bool
        Return the CLVs (S·D·2n·8 bytes).

    Returns
    -------
    CovariantResult

    Raises
    ------
    MechanismError, ValueError
        Naming the argument: ``opening_checks``, the variant, ``unstable_of``,
        ``mechanism_state`` and the time grid's checks.
    """
    rule, dt = opening_checks(mech, t_transient, dt)
    if option("variant", variant, ("restricted", "full")) == "full":
        raise ValueError("variant='full' does not exist for a mechanism: its tangent vectors "
                         "stay in the tangent space of TC (use 'restricted')")
    keep_vectors = flag("keep_vectors", keep_vectors)
    d, n = mech.dim, mech.n
    D = 2 * d
    m = unstable_of(mech, n_unstable)
    n_tr = 0 if rule else steps_of("t_transient", t_transient, dt, allow_zero=True)
    n_win = steps_of("t_final", t_final, dt)
    sample = steps_of("sample_every", sample_every, dt, divides=n_win)
    S = samples_of(n_win, sample, t_final, sample_every)
    project = project_steps(project_every, dt)
    seed = seed_of(seed)
    q0, v0 = mechanism_state(mech, q0, v0)

    def stored(n_tr):
        """Stored samples (as the rotors' route), their memory checked."""
        total = S + max(1, -(-n_tr // sample))
        check_memory(8 * total * (2 * D * 2 * n + D * D + 2 * n),
                     f"the factors of {total} samples (t_final={t_final:g}, t_transient="
                     f"{n_tr * dt:g})", "shorten t_final or t_transient, or raise sample_every")
        return total
    total = stored(n_tr)
    if rule:                  # every other setting and the state checked: the pilot runs
        t_transient, rule = resolve_transient(t_transient, mech, q0, v0, dt=dt,
                                              project_every=project_every, seed=seed)
        n_tr = steps_of("t_transient", t_transient, dt, allow_zero=True)
        total = stored(n_tr)

    flow = MechanismTangentFlow(mech, q0, v0, D, dt=dt, reorth=n_tr + total * sample + 1,
                                project=project, inner="full", seed=seed)
    Qx, Qy = np.empty((total, D, 2 * n)), np.empty((total, D, 2 * n))
    R, states = np.empty((total, D, D)), np.empty((total, 2 * n))

    def factor(j):
        """Sample j: the state, the vectors projected onto the tangent space of TC (D is its
        dimension: no drift off it may enter the basis), factored, orthonormal again."""
        states[j] = flow.y
        q, v = states[j, :n], states[j, n:]
        for r in range(D):
            flow.Z[1 + r] = np.concatenate(mech.project_phase_tangent(q, v,
                                                                      *np.split(flow.X[r], 2)))
        Qx[j], Qy[j], R[j] = gram_schmidt_factor(mech, q, flow.X)
        flow.Z[1:] = Qx[j]
    # the transient in steps of sample_every, orthonormalised as often (else the vectors
    # collapse onto E_u and the contracting directions are lost to rounding)
    for done in range(0, n_tr, sample):
        flow.advance(min(sample, n_tr - done))
        factor(0)
    for j in range(total):
        if j:
            flow.advance(sample)
        factor(j)
    tau = sample * dt
    gs = np.log(np.abs(np.diagonal(R, axis1=1, axis2=2))) / tau
    lost = np.zeros((total, D))
    Cs = np.empty((total, D, D))
    backward_coefficients(R, ginelli_start(seed, D), Cs, lost)
    # clv_samples's N: the rotors' N − 2 positive exponents are the d − 1 here
    _, phi, phi_v = clv_samples(Qy[:S], Cs[:S], m, d + 1)
    vectors = clv_samples(Qx[:S], Cs[:S], m, d + 1)[0] if keep_vectors else None
    t = (n_tr + np.arange(S) * sample) * dt
    params = dict(mechanism=mech.name, parameters=mech.parameter_values, variant="restricted",
                  dt=dt, D=D, t_final=n_win * dt, t_transient=n_tr * dt, sample_every=tau,
                  speed=float(np.sqrt(2 * mech.energy(q0, v0))),
                  project_every=project * dt or None, vectors_seed=seed, state_seed="given",
                  stored_samples=total, n_unstable=m, keep_vectors=keep_vectors,
                  q0=q0.tolist(), v0=v0.tolist())
    if rule:
        params["transient_rule"] = rule
    return CovariantResult(t, "restricted", phi, phi_v, -lost[1:S + 1] / tau, gs[1:S + 1],
                           states[:S], vectors, params)
