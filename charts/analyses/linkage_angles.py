"""Hyperbolicity test of section 4 for the linkage of the Appendix: the angle φ between the
expanding subspace E_u and the centre-stable subspace E_cs = E_0 ⊕ E_s, in the invariant
subspace T_r (``charts.geometry.linkage``).

1. forward, two tangent vectors (``charts.solvers.linkage.LinkageFlow``) converge to E_u; the
   state and the vectors are stored at the sample points;
2. backward (the same flow with step −dt), two tangent vectors converge to the subspace that
   grows in reverse time, E_s.  The backward base point is put back on the stored forward
   state at every sample point, so it never drifts from the forward trajectory;
3. E_0 = span{(v, a), (0, v)} (the flow direction and the change of speed, invariant: the flow
   at speed (1 + s)|v| is the reparametrised one), a = q̈;
4. sin φ = σ_min of the part of an orthonormal basis of E_u orthogonal to E_cs.

Inner product: Σ Mⱼⱼ (δqⱼ² + δvⱼ²) — for a massless disk Σ δθ² + Σ δθ̇², the Euclidean
product of the rotors' (θ, u) of the restricted variant of ``charts.analyses.hyperbolicity``
(the disk's parts are determined by the rotors' in T_r).
"""
from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from ..flows.linkage import NY, acceleration
from ..geometry.linkage import NQ
from ..solvers.linkage import LinkageFlow
from ..solvers.tangent import orthonormalize
from .arguments import (Documented, inner_steps, linkage_system, positive_time, project_steps, seed_of,
                        steps_of)
from .hyperbolicity import angle_statistics

__all__ = ["LinkageAngles", "linkage_angles", "angle_steps", "sin_angle"]


@dataclass
class LinkageAngles:
    """t (S,) sample times; phi (S,) angles between E_u and E_cs (rad); forward_exponents,
    backward_exponents (2,) growth rates of the two passes (both ≈ λ₁, λ₂ when converged)."""
    t: np.ndarray
    phi: np.ndarray
    forward_exponents: np.ndarray
    backward_exponents: np.ndarray
    params: dict = field(default_factory=dict)

    def statistics(self, small=0.05):
        return angle_statistics(self.phi, small)


def angle_steps(dt, t_final, t_transient, sample_every):
    """(t_final, t_transient, sample_every) of `linkage_angles` in steps dt: a written time
    a whole number of steps or ValueError; a `Documented` default placed as the signature's
    docstring says (as ``lyapunov_spectrum`` places reorth_every and record_every)."""
    total = steps_of("t_final", t_final, dt)
    transient = steps_of("t_transient", t_transient, dt, allow_zero=True)
    sample = inner_steps("sample_every", sample_every, dt, total, t_transient, transient)
    if isinstance(t_transient, Documented) and transient:
        transient = sample * steps_of("t_transient", t_transient, sample * dt)
    return total, transient, sample


def sin_angle(y, U, S, system, w):
    """sin φ between span U (2, 14) and span(S (2, 14), E_0 at y) in the product w."""
    a = np.empty(NQ)
    acceleration(y[:NQ], y[NQ:], system.par, a)
    C = np.vstack([S, np.concatenate([y[NQ:], a]), np.concatenate([np.zeros(NQ), y[NQ:]])])
    orthonormalize(C, w, np.zeros(len(C)))
    B = U.copy()
    orthonormalize(B, w, np.zeros(len(B)))
    R = B - (B * w) @ C.T @ C
    G = (R * w) @ R.T
    return np.sqrt(max(np.linalg.eigvalsh(G)[0], 0.0))


def linkage_angles(system, q0, v0, t_final, *, dt=0.01, t_transient=Documented(50.0),
                   sample_every=Documented(0.1), project_every=Documented(1.0),
                   seed=0) -> LinkageAngles:
    """Angles φ between E_u and E_cs along the linkage's trajectory from (q0, v0) at every
    ``sample_every`` (default 0.1) over ``t_final`` (module doc); the trajectory runs
    t_transient + t_final + t_transient (default 50) so that both passes converge; the
    state is projected onto the invariants every ``project_every`` (default 1.0, None:
    never).  t_final and t_transient are multiples of sample_every.  A time written must be
    a whole number of steps dt; a default left is the nearest whole number of steps at
    other dt (README, "Conventions"): a default ``sample_every`` the largest count at most
    that which divides t_final (and a written t_transient), a default ``t_transient`` the
    nearest multiple of ``sample_every``."""
    linkage_system(system)
    q0, v0 = system.check_state(q0, v0, ("q0", "v0"))
    dt = positive_time("dt", dt)
    total, transient, sample = angle_steps(dt, t_final, t_transient, sample_every)
    if total % sample or transient % sample:
        raise ValueError(f"t_final={t_final:g} and t_transient={t_transient:g} must be "
                         f"multiples of sample_every={sample_every:g}")
    S, Sb = total // sample, transient // sample
    project = project_steps(project_every, dt)
    seed = seed_of(seed)
    fw = LinkageFlow(system, q0, v0, 2, dt=dt, reorth_every=1, project_every=project, seed=seed)
    fw.advance(transient)
    fw.logsum[:] = 0.0
    ys = np.empty((S + Sb + 1, NY))
    Us = np.empty((S + 1, 2, NY))
    ys[0], Us[0] = fw.Z[0], fw.Z[1:]
    for j in range(1, S + Sb + 1):
        fw.advance(sample)
        ys[j] = fw.Z[0]
        if j <= S:
            Us[j] = fw.Z[1:]
    fexp = fw.logsum / (fw.steps * dt - transient * dt)
    bw = LinkageFlow(system, ys[-1, :NQ], ys[-1, NQ:], 2, dt=-dt, reorth_every=1,
                     project_every=project, seed=seed + 1)
    w = np.concatenate([system.mass, system.mass])
    phi = np.empty(S + 1)
    for j in range(S + Sb, 0, -1):
        bw.Z[0] = ys[j]
        bw.advance(sample, where="linkage_angles (backward RK4)")
        if j - 1 == S:
            bw.logsum[:] = 0.0
        if j - 1 <= S:
            phi[j - 1] = np.arcsin(min(1.0, sin_angle(ys[j - 1], Us[j - 1], bw.Z[1:], system, w)))
    bexp = bw.logsum / (total * dt)
    params = dict(eps=system.eps, rho=system.rho, dt=dt, t_final=total * dt,
                  t_transient=transient * dt, sample_every=sample * dt, vectors_seed=seed,
                  state_seed="given")
    return LinkageAngles(np.arange(S + 1) * sample * dt, phi, fexp, bexp, params)
